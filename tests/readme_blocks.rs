//! Every command-and-output block of README.md runs here and is compared
//! with what the command prints.
//!
//! A ```` ```console ```` block is `$ lambdamat ARGS`, optionally `? CODE`
//! (the expected exit code, 0 when absent), then the expected output:
//! standard output when the code is 0, standard error otherwise. In the
//! expected text `[..]` matches any text within a line and a line `...`
//! matches any number of lines, so numbers are compared to the digits that
//! are stable. A ```` ```sh ```` block is a command the test cannot run
//! (an install, the whole suite); it must follow a `<!-- not run: WHY -->`
//! marker, which this test checks. Commands write only under /tmp.
//!
//! The syntax is trycmd's (`[..]`, `...`); trycmd itself is not used
//! because this machine builds offline from a vendored registry that lacks
//! it. To refresh a block after an output change, run the command and paste
//! its output, keeping `[..]` where digits are not stable:
//! `cargo test --release --test readme_blocks -- --nocapture` prints the
//! actual output of every block that differs.

use std::process::Command;

struct Block {
    line: usize,
    args: Vec<String>,
    code: i32,
    expected: Vec<String>,
}

/// The console blocks of `text`, and the `sh` blocks without a marker.
fn blocks(text: &str) -> (Vec<Block>, Vec<usize>) {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut unmarked = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let l = lines[i];
        if l == "```sh" {
            let marked = i > 0 && lines[i - 1].starts_with("<!-- not run: ");
            if !marked {
                unmarked.push(i + 1);
            }
        }
        if l == "```console" {
            let start = i + 1;
            let mut body = Vec::new();
            i += 1;
            while i < lines.len() && lines[i] != "```" {
                body.push(lines[i].to_string());
                i += 1;
            }
            let cmd = body.first().cloned().unwrap_or_default();
            let cmd = cmd.strip_prefix("$ lambdamat ").unwrap_or_else(|| {
                panic!("README.md:{start}: a console block starts with `$ lambdamat `")
            });
            let mut rest = &body[1..];
            let mut code = 0;
            if let Some(c) = rest.first().and_then(|l| l.strip_prefix("? ")) {
                code = c.parse().expect("? CODE");
                rest = &rest[1..];
            }
            out.push(Block {
                line: start,
                args: cmd.split_whitespace().map(String::from).collect(),
                code,
                expected: rest.to_vec(),
            });
        }
        i += 1;
    }
    (out, unmarked)
}

/// Whether `line` matches `pattern`, where `[..]` matches any text.
fn line_matches(pattern: &str, line: &str) -> bool {
    let parts: Vec<&str> = pattern.split("[..]").collect();
    if parts.len() == 1 {
        return pattern == line;
    }
    let Some(mut rest) = line.strip_prefix(parts[0]) else {
        return false;
    };
    let last = parts.len() - 1;
    for (k, part) in parts.iter().enumerate().skip(1) {
        if k == last {
            return rest.ends_with(part);
        }
        match rest.find(part) {
            Some(at) => rest = &rest[at + part.len()..],
            None => return false,
        }
    }
    true
}

/// Whether `actual` matches `expected` (`...` lines match any lines).
fn matches(expected: &[String], actual: &[&str]) -> bool {
    match expected.split_first() {
        None => actual.is_empty(),
        Some((e, rest)) if e == "..." => {
            (0..=actual.len()).any(|skip| matches(rest, &actual[skip..]))
        }
        Some((e, rest)) => actual
            .split_first()
            .is_some_and(|(a, more)| line_matches(e, a) && matches(rest, more)),
    }
}

#[test]
fn patterns_match_as_documented() {
    assert!(line_matches("c = 0.49[..] ± [..]", "c = 0.4956 ± 7.7e-11"));
    assert!(!line_matches("c = 0.49[..]", "c = 0.50"));
    let e: Vec<String> = ["a", "...", "z"].iter().map(|s| s.to_string()).collect();
    assert!(matches(&e, &["a", "b", "c", "z"]));
    assert!(matches(&e, &["a", "z"]));
    assert!(!matches(&e, &["a", "b"]));
}

#[test]
fn every_readme_block_runs_and_prints_what_it_shows() {
    let text = std::fs::read_to_string("README.md").expect("README.md");
    let (blocks, unmarked) = blocks(&text);
    assert!(
        unmarked.is_empty(),
        "README.md lines {unmarked:?}: a sh block without a `<!-- not run: WHY -->` marker"
    );
    assert!(
        blocks.len() >= 8,
        "only {} console blocks found",
        blocks.len()
    );
    let mut failures = Vec::new();
    for b in &blocks {
        assert!(
            b.args.iter().all(|a| !a.contains('/')
                || a.starts_with("examples/")
                || a.starts_with("tests/data/")
                || a.starts_with("/tmp/")),
            "README.md:{}: a block reads examples/ or tests/data/ and writes only under /tmp",
            b.line
        );
        let out = Command::new(env!("CARGO_BIN_EXE_lambdamat"))
            .args(&b.args)
            .output()
            .expect("runs");
        let shown = if b.code == 0 {
            &out.stdout
        } else {
            &out.stderr
        };
        let shown = String::from_utf8_lossy(shown);
        let actual: Vec<&str> = shown.lines().collect();
        if out.status.code() != Some(b.code) || !matches(&b.expected, &actual) {
            println!(
                "README.md:{}: lambdamat {} (exit {:?}, expected {}):\n{shown}",
                b.line,
                b.args.join(" "),
                out.status.code(),
                b.code
            );
            failures.push(b.line);
        }
    }
    assert!(
        failures.is_empty(),
        "README.md blocks at lines {failures:?} differ (run with --nocapture)"
    );
}
