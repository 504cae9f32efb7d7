//! A solver written by `lambdamat codegen` builds in a crate of its own that
//! depends on lambdamat with `default-features = false` (no clap, miette's
//! fancy output, plotters or indicatif), and runs with the exit codes of
//! `lambdamat solve`. Ignored by default: it compiles lambdamat and its
//! dependencies afresh (minutes) and needs them in the local registry
//! (`--offline`, falling back to the network). Run it with
//! `cargo test --release --test generated_build -- --ignored --nocapture`.

use std::process::Command;

#[test]
#[ignore = "compiles lambdamat afresh in a temporary crate (minutes)"]
fn a_generated_solver_builds_without_the_command_line() {
    let dir = tempfile::tempdir().expect("temp dir");
    let root = env!("CARGO_MANIFEST_DIR");
    std::fs::create_dir(dir.path().join("src")).expect("src");
    std::fs::write(
        dir.path().join("Cargo.toml"),
        format!(
            "[package]\nname = \"mms_solver\"\nversion = \"0.1.0\"\nedition = \"2024\"\n\n\
             [dependencies]\nlambdamat = {{ path = {root:?}, default-features = false }}\n\n[workspace]\n"
        ),
    )
    .expect("Cargo.toml");
    let status = Command::new(env!("CARGO_BIN_EXE_lambdamat"))
        .args(["codegen", "examples/mms.lmx", "-o"])
        .arg(dir.path().join("src/main.rs"))
        .status()
        .expect("codegen");
    assert!(status.success());
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let tree = Command::new(&cargo)
        .args(["tree", "-e", "normal,build", "--prefix", "none"])
        .current_dir(dir.path())
        .output()
        .expect("cargo tree");
    let tree = String::from_utf8_lossy(&tree.stdout);
    for heavy in ["clap ", "plotters ", "indicatif "] {
        assert!(!tree.contains(heavy), "{heavy}in the tree:\n{tree}");
    }
    let mut crates: Vec<&str> = tree
        .lines()
        .map(|l| l.split(" (").next().unwrap_or(l))
        .collect();
    crates.sort_unstable();
    crates.dedup();
    println!("{} crates in the generated solver's build", crates.len());
    let build = Command::new(&cargo)
        .args(["build", "--release", "--offline"])
        .current_dir(dir.path())
        .status()
        .expect("cargo build");
    assert!(build.success());
    let bin = dir.path().join("target/release/mms_solver");
    let out = Command::new(&bin).output().expect("runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("output P = 0.785398163"), "{text}");
    assert_eq!(
        Command::new(&bin)
            .arg("--bogus")
            .status()
            .expect("runs")
            .code(),
        Some(1)
    );
    assert_eq!(
        Command::new(&bin)
            .args(["--tol", "-1e-3"])
            .status()
            .expect("runs")
            .code(),
        Some(2)
    );
}
