//! The memory budget of the solver ladders: how many bytes a level may
//! take, what a level of dense matrices needs, and the refusal when it
//! does not fit. Owns the rule and the size syntax of `--max-memory`; the
//! ladders ask it before they build a level, so the process never aborts
//! on an allocation.
//!
//! **The rule.** The default budget is [`DEFAULT_FRACTION`] of the memory
//! the machine has free (`MemAvailable`, else `MemTotal`, in
//! `/proc/meminfo`), and no more than that fraction of the process's
//! address-space limit (`ulimit -v`, `prlimit --as`, read from
//! `/proc/self/limits`); where neither file can be read it is
//! [`FALLBACK_BYTES`]. `--max-memory SIZE` (`SolveOptions::max_memory`)
//! replaces it.
//!
//! **The estimate.** A level of `dim` coefficients per basis holding
//! `matrices` dense `dim × dim` matrices of `f64` needs `8·dim²·matrices`
//! bytes ([`dense_bytes`]); the ladders count their matrices and add the
//! level they still hold while building the next.

/// The fraction of free memory (and of the address-space limit) a solve
/// may use by default.
pub const DEFAULT_FRACTION: f64 = 0.5;

/// The budget where the machine's memory cannot be read: 4 GiB.
pub const FALLBACK_BYTES: u64 = 4 << 30;

/// A level that does not fit the budget.
#[derive(Debug, Clone, PartialEq)]
pub struct OverBudget {
    /// What needed the memory (e.g. "level 3 (12000 coefficients per basis)").
    pub what: String,
    /// Bytes it would need.
    pub needed: f64,
    /// The budget in bytes.
    pub budget: u64,
}

impl std::fmt::Display for OverBudget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} would need about {} of memory, over the memory budget of {} (by default {}% of the free memory; set it with --max-memory SIZE, e.g. --max-memory {})",
            self.what,
            format_bytes(self.needed),
            format_bytes(self.budget as f64),
            (DEFAULT_FRACTION * 100.0).round(),
            suggest(self.needed)
        )
    }
}

/// Bytes of `matrices` dense `dim × dim` matrices of `f64` (a float, so
/// an absurd level is measured rather than overflowing).
pub fn dense_bytes(dim: f64, matrices: f64) -> f64 {
    8.0 * dim * dim * matrices
}

/// Checks `needed` bytes against `budget`.
pub fn check(what: impl FnOnce() -> String, needed: f64, budget: u64) -> Result<(), OverBudget> {
    if needed <= budget as f64 {
        Ok(())
    } else {
        Err(OverBudget {
            what: what(),
            needed,
            budget,
        })
    }
}

/// The default budget (the module's rule).
pub fn default_budget() -> u64 {
    let free = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|t| meminfo_bytes(&t));
    let limit = std::fs::read_to_string("/proc/self/limits")
        .ok()
        .and_then(|t| address_limit(&t));
    let bytes = match (free, limit) {
        (Some(f), Some(l)) => f.min(l),
        (Some(f), None) => f,
        (None, Some(l)) => l.min(FALLBACK_BYTES as f64 / DEFAULT_FRACTION),
        (None, None) => return FALLBACK_BYTES,
    };
    (bytes * DEFAULT_FRACTION) as u64
}

/// `MemAvailable` (else `MemTotal`) of a `/proc/meminfo` text, in bytes.
fn meminfo_bytes(text: &str) -> Option<f64> {
    let field = |name: &str| {
        text.lines().find_map(|l| {
            let rest = l.strip_prefix(name)?.trim();
            let kb: f64 = rest.trim_end_matches("kB").trim().parse().ok()?;
            Some(kb * 1024.0)
        })
    };
    field("MemAvailable:").or_else(|| field("MemTotal:"))
}

/// The soft address-space limit of a `/proc/self/limits` text, in bytes
/// (`None` when unlimited).
fn address_limit(text: &str) -> Option<f64> {
    let line = text.lines().find(|l| l.starts_with("Max address space"))?;
    let soft = line["Max address space".len()..]
        .split_whitespace()
        .next()?;
    soft.parse().ok()
}

/// Parses a size: a number with an optional unit `K`, `M`, `G` or `T`
/// (powers of 1024; `B`, `iB` and lower case accepted), e.g. `2G`, `500M`,
/// `1.5GiB`, `1000000`.
pub fn parse_size(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let value: f64 = num
        .parse()
        .map_err(|_| format!("{text:?}: expected a size such as 2G, 500M or 1000000 (bytes)"))?;
    let unit = unit.trim().to_ascii_uppercase();
    let unit = unit.trim_end_matches('B').trim_end_matches('I');
    let scale = match unit {
        "" => 1.0,
        "K" => 1024.0,
        "M" => 1024.0 * 1024.0,
        "G" => 1024.0 * 1024.0 * 1024.0,
        "T" => 1024.0 * 1024.0 * 1024.0 * 1024.0,
        _ => {
            return Err(format!(
                "{text:?}: unknown unit (use K, M, G or T, e.g. 2G or 500M)"
            ));
        }
    };
    let bytes = value * scale;
    if !(1.0..1.8e19).contains(&bytes) {
        return Err(format!("{text:?}: a memory size must be at least 1 byte"));
    }
    Ok(bytes as u64)
}

/// A byte count for people: `1.5 GiB`, `300 MiB`.
pub fn format_bytes(b: f64) -> String {
    const UNITS: [&str; 5] = ["B", "KiB", "MiB", "GiB", "TiB"];
    let mut v = b;
    let mut u = 0;
    while v >= 1024.0 && u + 1 < UNITS.len() {
        v /= 1024.0;
        u += 1;
    }
    if !v.is_finite() {
        return "more than any machine has".into();
    }
    if u == 0 {
        format!("{v:.0} {}", UNITS[0])
    } else {
        format!("{v:.1} {}", UNITS[u])
    }
}

/// A `--max-memory` value that would cover `needed` bytes.
fn suggest(needed: f64) -> String {
    let gib = needed / (1u64 << 30) as f64;
    if gib < 1.0 {
        format!("{}M", (needed / (1u64 << 20) as f64).ceil().max(1.0))
    } else if gib.is_finite() && gib < 1e6 {
        format!("{}G", gib.ceil())
    } else {
        "<more than any machine has>".into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_in_binary_units() {
        assert_eq!(parse_size("2G"), Ok(2 << 30));
        assert_eq!(parse_size("500M"), Ok(500 << 20));
        assert_eq!(parse_size("1.5GiB"), Ok(3 << 29));
        assert_eq!(parse_size("64kb"), Ok(64 << 10));
        assert_eq!(parse_size("1000000"), Ok(1_000_000));
        for bad in ["", "G", "2X", "-1G", "0", "1e3"] {
            assert!(parse_size(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn the_default_reads_free_memory_and_the_address_limit() {
        let meminfo = "MemTotal:       24684092 kB\nMemFree: 1 kB\nMemAvailable:   21766788 kB\n";
        assert_eq!(meminfo_bytes(meminfo), Some(21766788.0 * 1024.0));
        assert_eq!(meminfo_bytes("MemTotal: 1000 kB\n"), Some(1000.0 * 1024.0));
        let limits = "Limit                     Soft Limit           Hard Limit           Units\nMax address space         3221225472           unlimited            bytes\n";
        assert_eq!(address_limit(limits), Some(3221225472.0));
        let unlimited =
            "Max address space         unlimited            unlimited            bytes\n";
        assert_eq!(address_limit(unlimited), None);
        assert!(default_budget() > 0);
    }

    #[test]
    fn an_over_budget_level_names_its_size_and_the_flag() {
        let e = check(|| "level 3".into(), 3.0 * (1u64 << 30) as f64, 1 << 30).unwrap_err();
        let m = e.to_string();
        assert!(m.contains("level 3 would need about 3.0 GiB"), "{m}");
        assert!(m.contains("--max-memory 3G"), "{m}");
        assert!(check(|| "x".into(), 10.0, 10).is_ok());
    }
}
