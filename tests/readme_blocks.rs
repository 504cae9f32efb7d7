//! Every command-and-output block of README.md and docs/*.md runs here
//! through trycmd and is compared with what the command prints.
//!
//! A ```` ```console ```` block is `$ lambdamat ARGS`, optionally `? CODE`
//! (the expected exit code, 0 when absent), then the expected output:
//! standard output and standard error together, as a terminal shows them.
//! In the expected text `[..]` matches any text within a line and a line
//! `...` matches any number of lines, so numbers are compared to the digits
//! that are stable. A ```` ```sh ```` block is a command the test cannot
//! run (an install, the whole suite); it must follow a
//! `<!-- not run: WHY -->` marker, which this file checks, as it checks
//! that blocks read only `examples/`, `tests/data/` and write only under
//! `/tmp`. To refresh a block after an output change, run the command and
//! paste its output, keeping `[..]` where digits are not stable
//! (`cargo test --release --test readme_blocks` prints the difference).

use std::path::PathBuf;

/// README.md and every docs/*.md file.
fn documents() -> Vec<PathBuf> {
    let mut out = vec![PathBuf::from("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir("docs")
        .expect("docs/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    out.extend(docs);
    out
}

/// The command lines of the console blocks of `text` (with their line
/// numbers), and the lines of `sh` blocks that lack a `not run` marker.
fn commands(text: &str) -> (Vec<(usize, String)>, Vec<usize>) {
    let lines: Vec<&str> = text.lines().collect();
    let (mut cmds, mut unmarked) = (Vec::new(), Vec::new());
    let mut in_console = false;
    for (i, l) in lines.iter().enumerate() {
        if in_console {
            if l.starts_with("```") {
                in_console = false;
            } else if let Some(cmd) = l.strip_prefix("$ ") {
                cmds.push((i + 1, cmd.to_string()));
            }
        } else if *l == "```console" {
            in_console = true;
        } else if *l == "```sh" && !(i > 0 && lines[i - 1].starts_with("<!-- not run: ")) {
            unmarked.push(i + 1);
        }
    }
    (cmds, unmarked)
}

#[test]
fn blocks_run_only_lambdamat_on_shipped_inputs_and_shell_blocks_say_why_not() {
    let mut total = 0;
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).expect("document");
        let (cmds, unmarked) = commands(&text);
        assert!(
            unmarked.is_empty(),
            "{} lines {unmarked:?}: a sh block without a `<!-- not run: WHY -->` marker",
            doc.display()
        );
        for (line, cmd) in &cmds {
            let args: Vec<&str> = cmd.split_whitespace().collect();
            assert_eq!(
                args.first(),
                Some(&"lambdamat"),
                "{}:{line}: a console block runs `lambdamat …`",
                doc.display()
            );
            assert!(
                args.iter().all(|a| !a.contains('/')
                    || a.starts_with("examples/")
                    || a.starts_with("tests/data/")
                    || a.starts_with("/tmp/")),
                "{}:{line}: a block reads examples/ or tests/data/ and writes only under /tmp",
                doc.display()
            );
        }
        total += cmds.len();
    }
    assert!(total >= 12, "only {total} console commands found");
}

#[test]
fn every_console_block_prints_what_it_shows() {
    let cases = trycmd::TestCases::new();
    cases.register_bin("lambdamat", PathBuf::from(env!("CARGO_BIN_EXE_lambdamat")));
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).expect("document");
        if text.contains("```console") {
            cases.case(doc);
        }
    }
}
