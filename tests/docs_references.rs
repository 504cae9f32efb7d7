//! The documents stay true to the repository: every file path that the
//! README, the docs, the help texts and comments in `src/`, the examples,
//! the grammar and the benches mention exists, and every ```lmx block in
//! the README and `docs/` is a complete file that parses.

use std::path::{Path, PathBuf};

const ROOTS: &[&str] = &["docs", "examples", "tests", "src", "grammar", "benches"];

/// Every `root/...` path written in `text`.
fn references(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let bytes = text.as_bytes();
    for root in ROOTS {
        let pat = format!("{root}/");
        let mut from = 0;
        while let Some(i) = text[from..].find(&pat) {
            let start = from + i;
            from = start + pat.len();
            // Only at the start of a word (not `shared/docs/…`, `../src`).
            if start > 0 {
                let b = bytes[start - 1];
                if b.is_ascii_alphanumeric() || b == b'/' || b == b'.' || b == b'_' || b == b'-' {
                    continue;
                }
            }
            let end = text[start..]
                .find(|c: char| !(c.is_ascii_alphanumeric() || "_./-*".contains(c)))
                .map_or(text.len(), |j| start + j);
            let r = text[start..end].trim_end_matches(['.', '/']);
            // A path built at run time (`peers_{n}.lmx`) is not a file name.
            let built = text[end..].starts_with(['{', '$']);
            if r.len() > pat.len() && !r.contains('*') && !built {
                out.push(r.to_string());
            }
        }
    }
    out
}

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            if !p.ends_with("data") {
                files(&p, out);
            }
        } else if p.extension().is_some_and(|x| {
            ["rs", "md", "lmx", "pest", "sh", "py"]
                .iter()
                .any(|e| x == *e)
        }) {
            out.push(p);
        }
    }
}

#[test]
fn every_referenced_file_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sources = vec![root.join("README.md")];
    for d in ["docs", "src", "examples", "grammar", "benches"] {
        files(&root.join(d), &mut sources);
    }
    let mut missing = Vec::new();
    let mut checked = 0;
    for f in &sources {
        let text = std::fs::read_to_string(f).unwrap_or_default();
        for r in references(&text) {
            checked += 1;
            if !root.join(&r).exists() {
                missing.push(format!("{}: {r}", f.display()));
            }
        }
    }
    assert!(
        checked > 20,
        "only {checked} references found: is the scanner broken?"
    );
    assert!(missing.is_empty(), "missing files:\n{}", missing.join("\n"));
}

#[test]
fn the_scanner_finds_paths_and_skips_others() {
    let r = references(
        "see docs/hertz.md. Also shared/docs/x.md and `examples/a.lmx`, tests/hertz_*.rs",
    );
    assert_eq!(r, ["docs/hertz.md", "examples/a.lmx"]);
}

#[test]
fn every_lmx_block_in_the_docs_parses() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut blocks = 0;
    for f in ["README.md", "docs/language.md", "docs/hertz.md"] {
        let text = std::fs::read_to_string(root.join(f)).expect("document exists");
        let mut rest = text.as_str();
        while let Some(i) = rest.find("```lmx\n") {
            let body = &rest[i + 7..];
            let end = body.find("```").expect("closed block");
            if let Err(e) = lambdamat::lang::parse_program(&body[..end], f) {
                panic!("a block in {f} does not parse:\n{}", e.render());
            }
            blocks += 1;
            rest = &body[end..];
        }
    }
    assert!(blocks >= 3, "only {blocks} lmx blocks");
}
