//! The library API (`lambdamat::Problem` and its values) against the
//! command line it serves: every value printed through the API is what
//! the `lambdamat` command prints for the same file, and the errors carry
//! the CLI's exit code, message and source location.
use assert_cmd::Command;
use lambdamat::{ErrorKind, Method, Problem, SmithOptions, SolveOptions};

fn lambdamat(args: &[&str]) -> (i32, String, String) {
    let out = Command::cargo_bin("lambdamat")
        .expect("binary")
        .args(args)
        .output()
        .expect("runs");
    (
        out.status.code().expect("exit code"),
        String::from_utf8(out.stdout).expect("utf-8"),
        String::from_utf8(out.stderr).expect("utf-8"),
    )
}

fn json(s: &str) -> serde_json::Value {
    serde_json::from_str(s).expect("JSON")
}

#[test]
fn smith_of_an_operator_system_is_its_lambda_matrix_and_the_cli_prints_it() {
    let p = Problem::from_file("examples/hertz.lmx").expect("valid");
    let s = p.smith(&SmithOptions::default()).expect("smith");
    assert_eq!(s.ring(), "Q(k1, k2, k3)[k4]");
    assert_eq!(s.a(), &[vec!["k1", "k2"], vec!["k3", "k4"]]);
    assert_eq!(s.invariant_factors(), &["1", "k4 - k2*k3/k1"]);
    assert!(s.verified() && s.certificate().iter().all(|c| c.ok));
    assert!(s.u().is_some() && s.v().is_some());
    let (code, out, _) = lambdamat(&["smith", "examples/hertz.lmx"]);
    assert_eq!(code, 0);
    assert_eq!(out, s.text());
    let (code, out, _) = lambdamat(&["smith", "examples/hertz.lmx", "--latex"]);
    assert_eq!(code, 0);
    assert_eq!(out, s.latex());
}

#[test]
fn smith_of_a_matrix_with_options() {
    let src = "var x, y\nmatrix A = [x, y; 0, x]\nmatrix B = [x*y]";
    let p = Problem::from_source(src, "m.lmx").expect("valid");
    let b = p
        .smith(&SmithOptions {
            matrix: Some("B".into()),
            principal: Some("y".into()),
        })
        .expect("smith");
    assert_eq!(b.name(), "B");
    assert_eq!(b.invariant_factors(), &["y"]);
    let a = p.smith(&SmithOptions::default()).expect("smith");
    assert_eq!(a.name(), "A");
    // two symbols, no principal: invariant factors from determinantal
    // divisors, without U and V
    assert_eq!(a.invariant_factors(), &["1", "x^2"]);
    assert!(a.u().is_none());
    assert_eq!(json(&a.to_json())["invariant_factors"][1], "x^2");
    for (opts, needle) in [
        (
            SmithOptions {
                matrix: Some("C".into()),
                ..SmithOptions::default()
            },
            "--matrix C: no such matrix in the file (defined: A, B)",
        ),
        (
            SmithOptions {
                principal: Some("z".into()),
                ..SmithOptions::default()
            },
            "--principal z: no such symbol in the file (declared: x, y)",
        ),
    ] {
        let e = p.smith(&opts).expect_err("refused");
        assert_eq!(e.kind(), ErrorKind::InvalidInput);
        assert_eq!(e.to_string(), format!("error: {needle}"));
    }
}

#[test]
fn params_are_shown_as_written_and_as_set() {
    let p = Problem::from_file("examples/hertz.lmx").expect("valid");
    let params = p.params();
    assert_eq!(params[0], ("nu".into(), "1/4".into()));
    assert_eq!(params[1], ("mu".into(), "0.1801".into()));
    assert_eq!(params[2], ("gamma".into(), "(1 - 2*nu)/(2 - 2*nu)".into()));
    let q = p.with_set(&[("nu".into(), "0.3".into())]).expect("set");
    assert_eq!(q.params()[0], ("nu".into(), "3/10".into()));
    let e = p
        .with_set(&[("rho".into(), "1".into())])
        .expect_err("no rho");
    assert_eq!(e.exit_code(), 2);
    assert!(e.to_string().contains("defines no parameter `rho`"), "{e}");
    let e = p.with_set(&[("nu".into(), "abc".into())]).expect_err("bad");
    assert!(e.to_string().contains("is not an exact number"), "{e}");
}

#[test]
fn source_errors_carry_locations_and_the_cli_message() {
    let dir = tempfile::tempdir().expect("dir");
    let path = dir.path().join("bad.lmx");
    std::fs::write(&path, "var x\nmatrix A = [x, y]\nmatrix B = [z]\n").expect("write");
    let e = Problem::from_file(&path).expect_err("invalid");
    assert_eq!(e.kind(), ErrorKind::InvalidInput);
    let locs = e.locations();
    assert_eq!(locs.len(), 2);
    assert_eq!((locs[0].line, locs[0].column), (2, 16));
    assert_eq!((locs[1].line, locs[1].column), (3, 13));
    assert_eq!(locs[0].file, path.display().to_string());
    let (code, _, err) = lambdamat(&["smith", path.to_str().expect("utf-8")]);
    assert_eq!(code, e.exit_code());
    assert_eq!(err, format!("{e}\n"));
    let missing = Problem::from_file(dir.path().join("none.lmx")).expect_err("missing");
    assert_eq!(missing.kind(), ErrorKind::Io);
    assert_eq!(missing.exit_code(), 2);
    assert!(missing.locations().is_empty());
    assert!(missing.to_string().starts_with("error: cannot read"));
}

#[test]
fn solve_gives_the_cli_json_and_values() {
    let p = Problem::from_file("examples/mms.lmx").expect("valid");
    let s = p.solve(&SolveOptions::default()).expect("solves");
    let (code, out, _) = lambdamat(&["solve", "examples/mms.lmx", "--json"]);
    assert_eq!(code, 0);
    assert_eq!(
        format!(
            "{}\n",
            serde_json::to_string_pretty(&s.to_json()).expect("JSON")
        ),
        out
    );
    assert!(s.converged);
    let v = json(&out);
    for (name, value) in &s.outputs {
        assert_eq!(v["outputs"][name].as_f64(), Some(*value));
        assert!(s.error_estimates[name] <= 1e-10);
    }
    assert_eq!(s.outputs.len(), 2);
    for (name, f) in &s.unknowns {
        assert_eq!(f.x.len(), f.values.len());
        assert_eq!(
            v["unknowns"][name]["values"]
                .as_array()
                .expect("values")
                .len(),
            f.values.len()
        );
    }
    let coupled = p
        .solve(&SolveOptions {
            method: Some(Method::Coupled),
            ..SolveOptions::default()
        })
        .expect("solves");
    for (name, value) in &s.outputs {
        let d = (coupled.outputs[name] - value).abs();
        assert!(d <= s.error_estimates[name] + coupled.error_estimates[name]);
    }
}

#[test]
fn split_solve_with_set_matches_the_cli() {
    let p = Problem::from_file("examples/hertz.lmx").expect("valid");
    let opts = SolveOptions {
        set: vec![("nu".into(), "0.3".into()), ("mu".into(), "0.5".into())],
        tol: 1e-8,
        ..SolveOptions::default()
    };
    let s = p.solve(&opts).expect("solves");
    let (code, out, _) = lambdamat(&[
        "solve",
        "examples/hertz.lmx",
        "--set",
        "nu=0.3",
        "--set",
        "mu=0.5",
        "--tol",
        "1e-8",
        "--json",
    ]);
    assert_eq!(code, 0);
    assert_eq!(
        format!(
            "{}\n",
            serde_json::to_string_pretty(&s.to_json()).expect("JSON")
        ),
        out
    );
    assert!(s.converged);
    assert!(s.scalars["c"] > 0.0 && s.scalars["c"] < 1.0);
    assert!(s.error_estimates["c"] <= 1e-8);
    assert!(s.outputs.contains_key("P"));
    assert_eq!(s.unknowns.len(), 2);
}

#[test]
fn unconverged_is_ok_and_failures_are_errors() {
    let p = Problem::from_source(
        "operator k = int(0..1) dt\nunknown p\nequation p + k p = 1/x\n",
        "nc.lmx",
    )
    .expect("valid");
    let s = p
        .solve(&SolveOptions {
            max_level: Some(3),
            ..SolveOptions::default()
        })
        .expect("a result");
    assert!(!s.converged);
    let p = Problem::from_source(
        "operator k = int(0..1) 100000000000000000000*(x + t) dt\nunknown p\nequation p + k p = 1\n",
        "ill.lmx",
    )
    .expect("valid");
    let e = p.solve(&SolveOptions::default()).expect_err("fails");
    assert_eq!(e.kind(), ErrorKind::ComputationFailed);
    assert_eq!(e.exit_code(), 3);
    for bad in [
        SolveOptions {
            tol: f64::NAN,
            ..SolveOptions::default()
        },
        SolveOptions {
            max_level: Some(15),
            ..SolveOptions::default()
        },
        SolveOptions {
            set: vec![("k".into(), "1".into())],
            ..SolveOptions::default()
        },
    ] {
        let e = p.solve(&bad).expect_err("refused");
        assert_eq!(e.kind(), ErrorKind::InvalidInput, "{e}");
    }
    // A memory budget no level fits: the size it would need (exit 3).
    let e = p
        .solve(&SolveOptions {
            max_memory: Some(64),
            ..SolveOptions::default()
        })
        .expect_err("over the budget");
    assert_eq!(e.exit_code(), 3, "{e}");
    assert!(e.to_string().contains("would need about"), "{e}");
}

#[test]
fn reduce_and_codegen_print_what_the_cli_prints() {
    let p = Problem::from_file("examples/generic3.lmx").expect("valid");
    let r = p.reduce(None).expect("reduces");
    let (code, out, _) = lambdamat(&["reduce", "examples/generic3.lmx"]);
    assert_eq!(code, 0);
    assert_eq!(out, r.text());
    let (_, out, _) = lambdamat(&["reduce", "examples/generic3.lmx", "--json"]);
    assert_eq!(json(&r.to_json()), json(&out));
    assert!(!r.eliminant().lmx.is_empty());
    let h = Problem::from_file("examples/hertz.lmx").expect("valid");
    let r = h.reduce(Some("q")).expect("reduces");
    assert_eq!(r.unknown(), "q");
    assert_eq!(r.pieces().len(), 2);
    let (_, out, _) = lambdamat(&["reduce", "examples/hertz.lmx", "--for", "q", "--latex"]);
    assert_eq!(out, r.latex());
    let e = h.reduce(Some("w")).expect_err("no w");
    assert_eq!(e.kind(), ErrorKind::InvalidInput);
    let m = Problem::from_file("examples/mms.lmx").expect("valid");
    let (code, out, _) = lambdamat(&["codegen", "examples/mms.lmx"]);
    assert_eq!(code, 0);
    assert_eq!(out, m.codegen(None).expect("code"));
}

#[test]
fn the_hertz_entry_prints_what_lambdamat_hertz_prints_and_its_solution_is_the_files() {
    use lambdamat::api::{Given, HertzOptions, hertz, hertz_report};
    let opts = HertzOptions {
        tol: 1e-8,
        grid: 2,
        ..HertzOptions::default()
    };
    let h = hertz_report(0.25, Given::Mu(0.1801), &opts).expect("solves");
    let args = ["hertz", "--nu", "0.25", "--mu", "0.1801", "--tol", "1e-8"];
    let (code, out, _) = lambdamat(&args);
    assert_eq!((code, out), (0, h.text()));
    let (code, out, _) = lambdamat(&[&args[..], &["--json"]].concat());
    assert_eq!((code, json(&out)), (0, json(&h.to_json())));
    // `api::hertz` (Python's `lambdamat.hertz`) is the same solve, and its
    // solution is the file's as `lambdamat solve` gives it.
    let s = hertz(0.25, Given::Mu(0.1801), 1e-8).expect("solves");
    assert_eq!(s.scalars["c"], h.c());
    let f = Problem::from_file("examples/hertz.lmx")
        .expect("valid")
        .solve(&SolveOptions {
            set: vec![("nu".into(), "0.25".into()), ("mu".into(), "0.1801".into())],
            tol: 1e-8,
            ..SolveOptions::default()
        })
        .expect("solves");
    assert_eq!(s.to_json(), f.to_json());
    // A given c below the smallest the front resolves is its refusal, with the CLI's
    // message and exit code, through both entries.
    let (code, _, err) = lambdamat(&["hertz", "--nu", "0.25", "--c", "1e-7"]);
    let refused = hertz_report(0.25, Given::C(1e-7), &HertzOptions::default()).unwrap_err();
    assert_eq!(code, refused.error().exit_code());
    assert_eq!(err.trim_end(), refused.error().to_string());
    let e = hertz(0.25, Given::C(1e-7), 1e-10).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::ComputationFailed);
}
