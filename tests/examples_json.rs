//! Every example through `lambdamat solve --json`: one report shape for
//! every file (`method`, `converged`, `levels`, `tol`, `unknowns` with
//! `x`, `values`, `weight` and `error_estimate`, `outputs`, `scalars`,
//! `coefficients`, `error_estimates` with one absolute estimate per
//! output, scalar, coefficient and unknown, `warnings`), and on every
//! example that states its closed form's values (`# exact: NAME = VALUE`)
//! each value within its estimate. At least ten files are compared; a
//! file may be refused (exit 2 or 3, with its reason) only if it states
//! no values.
use std::path::PathBuf;
use std::process::Command;

use serde_json::Value;

/// The `# exact:` lines of a file.
fn exact_values(text: &str) -> Vec<(String, f64)> {
    text.lines()
        .filter_map(|l| l.strip_prefix("# exact:"))
        .map(|rest| {
            let (name, value) = rest.split_once('=').expect("NAME = VALUE");
            (
                name.trim().to_string(),
                value.trim().parse().expect("a number"),
            )
        })
        .collect()
}

fn examples() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for dir in ["examples", "examples/contact"] {
        for entry in std::fs::read_dir(dir).expect("examples") {
            let path = entry.expect("entry").path();
            if path.extension().is_some_and(|e| e == "lmx") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

#[test]
fn every_example_reports_one_shape_and_its_closed_form_within_the_estimates() {
    let (mut solved, mut compared, mut values) = (0, 0, 0);
    for path in examples() {
        let text = std::fs::read_to_string(&path).expect("reads");
        // Matrix files (no equations) are `smith`'s, and systems of `var`
        // symbols (no kernels) `reduce`'s, not `solve`'s.
        let starts = |w: &str| text.lines().any(|l| l.trim_start().starts_with(w));
        if !starts("equation") || starts("var ") {
            continue;
        }
        let out = Command::new(assert_cmd::cargo::cargo_bin("lambdamat"))
            .args(["solve", "--json"])
            .arg(&path)
            .output()
            .expect("runs");
        let code = out.status.code();
        let name = path.display();
        // A refusal is an answer too (examples/singular.lmx is there to be
        // refused), with its reason, on a file that claims no values.
        if matches!(code, Some(2) | Some(3)) {
            let err = String::from_utf8_lossy(&out.stderr);
            eprintln!("{name}: refused (exit {code:?}): {}", err.trim());
            assert!(!err.trim().is_empty(), "{name}: refused without a reason");
            assert!(exact_values(&text).is_empty(), "{name}: refused: {err}");
            continue;
        }
        assert!(
            matches!(code, Some(0) | Some(4)),
            "{name}: exit {code:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let j: Value = serde_json::from_slice(&out.stdout).expect("JSON");
        for key in [
            "method",
            "converged",
            "levels",
            "tol",
            "unknowns",
            "outputs",
            "scalars",
            "coefficients",
            "error_estimates",
            "warnings",
        ] {
            assert!(j.get(key).is_some(), "{name}: no `{key}`");
        }
        assert_eq!(j["converged"].as_bool(), Some(code == Some(0)), "{name}");
        let estimates = j["error_estimates"].as_object().expect("estimates");
        let unknowns = j["unknowns"].as_object().expect("unknowns");
        assert!(!unknowns.is_empty(), "{name}: no unknowns");
        for (u, field) in unknowns {
            let (x, v) = (field["x"].as_array(), field["values"].as_array());
            assert!(
                x.zip(v)
                    .is_some_and(|(x, v)| !x.is_empty() && x.len() == v.len()),
                "{name}: {u} has no values"
            );
            assert!(field["weight"].is_string(), "{name}: {u} has no weight");
            assert_eq!(
                field["error_estimate"].as_f64(),
                estimates.get(u).and_then(Value::as_f64),
                "{name}: {u}'s estimate"
            );
        }
        for group in ["outputs", "scalars", "coefficients"] {
            for (q, _) in j[group].as_object().expect(group) {
                let e = estimates.get(q).and_then(Value::as_f64);
                assert!(
                    e.is_some_and(|e| e >= 0.0),
                    "{name}: {q} has no absolute estimate"
                );
            }
        }
        solved += 1;
        let exact = exact_values(&text);
        if exact.is_empty() {
            continue;
        }
        for (q, want) in &exact {
            let got = j["outputs"]
                .get(q)
                .or_else(|| j["scalars"].get(q))
                .or_else(|| j["coefficients"].get(q))
                .and_then(Value::as_f64)
                .unwrap_or_else(|| panic!("{name}: no value {q}"));
            let e = estimates[q].as_f64().expect("estimate");
            let err = (got - want).abs();
            eprintln!("{name}: {q} = {got} (exact {want}), error {err:.1e}, estimate {e:.1e}");
            assert!(err <= e, "{name}: {q} off by {err:.2e}, estimate {e:.2e}");
            values += 1;
        }
        compared += 1;
    }
    eprintln!("{solved} examples solved, {compared} compared ({values} values)");
    assert!(solved >= 15, "only {solved} examples solved");
    assert!(compared >= 10, "only {compared} examples compared");
}
