//! The split-domain statements of the language (`on`, `relation`,
//! `scalar`, `singular`, `condition`, real parameters): what they lower
//! to, and their errors with line:column (exit code 2 through the CLI).
mod common;

use common::cli::{lambdamat, lmx_file};
use common::{ok, summary};
use lambdamat::lang::ErrorKind;
use lambdamat::system::contact::SingularKind;

const HEAD: &str = "param mu = 0.2\nunknown p, q on [0, 1]\nscalar c in (0, 1)\n\
operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\noperator k4 = -int(x..1) x/sqrt(t^2 - x^2) dt\n";

#[test]
fn hertz_file_lowers_to_its_declarations() {
    let src = std::fs::read_to_string("examples/hertz.lmx").expect("example");
    let p = ok(&src);
    let c = &p.contact;
    assert!(c.is_split());
    assert_eq!(c.slots(), ["c", "alpha"]);
    assert_eq!(c.equation_domains.len(), 2);
    assert!(c.equation_domains[0].is_some());
    let e2 = c.equation_domains[1].as_ref().expect("E2 on [0, c)");
    assert!(e2.lo_closed && !e2.hi_closed);
    assert_eq!(c.relations.len(), 1);
    assert_eq!((c.relations[0].unknown, c.relations[0].other), (1, 0));
    assert_eq!(c.coefficients, ["B"]);
    assert_eq!(c.conditions.len(), 1);
    assert!(matches!(c.singulars[0].kind, SingularKind::Weight { .. }));
    assert!(matches!(
        c.singulars[1].kind,
        SingularKind::Term { coefficient: 0, .. }
    ));
    assert_eq!(c.singulars[1].side, -1);
    // alpha = acot(gamma*mu)/pi at c = 0.3 (alpha does not depend on c).
    let v = c.values(&[0.3]);
    let (g, mu) = (1.0 / 3.0, 0.1801);
    assert!((v[1] - (1.0f64 / (g * mu)).atan() / std::f64::consts::PI).abs() < 1e-15);
    // Real parameters are not listed among the exact ones.
    assert!(p.params.iter().all(|q| q.name != "alpha"));
}

#[test]
fn errors_point_at_the_statement_parts() {
    let cases: [(&str, ErrorKind, usize, usize); 6] = [
        (
            "equation k1 p + k4 q = 1 on [0, d)\n",
            ErrorKind::Undeclared,
            6,
            33,
        ),
        (
            "relation q = mu*p*p on [c, 1]\n",
            ErrorKind::WrongSort,
            6,
            17,
        ),
        ("relation q = 2 on [c, 1]\n", ErrorKind::WrongSort, 6, 14),
        ("singular p at 1 ~ sin(x)\n", ErrorKind::WrongSort, 6, 19),
        ("condition C = 0\n", ErrorKind::WrongSort, 6, 11),
        (
            "param a = acot(mu)\noperator k2 = a*int(0..x) dt\n",
            ErrorKind::WrongSort,
            7,
            15,
        ),
    ];
    for (tail, kind, line, col) in cases {
        let src = format!("{HEAD}{tail}");
        let errs = summary(&src);
        assert!(
            errs.iter()
                .any(|e| e.0 == kind && e.2 == line && e.3 == col),
            "{tail}: {errs:?}"
        );
    }
}

#[test]
fn cli_reports_split_errors_with_exit_2() {
    // Syntax: a missing interval after `on`.
    let f = lmx_file(&format!("{HEAD}equation k1 p = 1 on\n"));
    let out = lambdamat()
        .args(["solve"])
        .arg(f.path())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains(":7:1"));
    // Meaning, found by the solver: two equations hold on (c, 1) but only p is free there.
    let f = lmx_file(&format!(
        "{HEAD}equation k1 p + k4 q = 1 on [0, 1]\nequation k4 p + k1 q = 0 on [0, 1]\n\
         relation q = mu*p on [c, 1]\nsingular q at c- ~ B*x/sqrt(c^2 - x^2)\ncondition B = 0\n"
    ));
    let out = lambdamat()
        .args(["solve"])
        .arg(f.path())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("2 equations hold for 1 free unknowns"));
}

#[test]
fn reduce_shows_each_subinterval() {
    let v = common::cli::json(&["reduce", "examples/hertz_given_c.lmx"]);
    let pieces = v["pieces"].as_array().expect("pieces");
    assert_eq!(pieces.len(), 2);
    assert_eq!(pieces[0]["interval"], "[0, 1/2)");
    assert_eq!(pieces[1]["interval"], "[1/2, 1]");
    assert_eq!(pieces[1]["substituted"][0], "q = mu*p");
    // Stick zone: the seed's (3.3) as the eliminant, k4·E1 - k2·E2.
    let stick = &pieces[0]["reduction"];
    assert_eq!(stick["eliminant"]["lhs"], "k1*k4 - k2*k3");
    // Slip zone: the seed's (2.4), (k1 + μ k2) p = 1, with μ a symbol.
    let slip = &pieces[1]["reduction"];
    assert_eq!(slip["eliminant"]["lhs"], "k1 + k2*mu");
    assert!(pieces[1]["note"].as_str().expect("note").contains("(2.4)"));
    // A rational μ is substituted exactly.
    let t = common::cli::stdout(&["reduce", "examples/hertz.lmx", "--set", "mu=1/5"]);
    assert!(t.contains("on [c, 1] with q = 1/5*p substituted"), "{t}");
    assert!(t.contains("A = [ k1 + 1/5*k2 ]"), "{t}");
}

#[test]
fn run_uses_the_split_solver() {
    let v = common::cli::json(&["run", "examples/hertz_split_mms.lmx"]);
    let results = v["results"].as_array().expect("results");
    let solve = results
        .iter()
        .find(|r| r["kind"] == "solve")
        .expect("a solve result");
    let c = solve["result"]["scalars"]["c"].as_f64().expect("c");
    assert!((c - 0.5).abs() <= 1e-10);
    // `codegen` writes solvers for split files: tests/codegen_split.rs.
}

#[test]
fn split_files_print_back_to_the_same_program() {
    for path in [
        "examples/hertz.lmx",
        "examples/hertz_given_c.lmx",
        "examples/hertz_split_mms.lmx",
    ] {
        let src = std::fs::read_to_string(path).expect("example");
        let p = ok(&src);
        let text = lambdamat::lang::pretty::pretty(&p);
        assert_eq!(ok(&text), p, "{path} printed as:\n{text}");
    }
}
