//! The contact statements as users write them: singular weights in any
//! equivalent spelling, `relation u = 0`, and `inequality`, which rejects
//! roots and answers that break it and says where and by how much.

mod common;

use common::cli::{json, lambdamat, lmx_file};

/// The flat punch `k1 p = 1/3` on [0, 1] with the edge weight spelled `w`.
fn punch(weight: &str, extra: &str) -> String {
    format!(
        "unknown p on [0, 1]\noperator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\n\
         equation k1 p = 1/3 on [0, 1]\nsingular p at 1 ~ {weight}\n{extra}\
         output P = 2*pi*int(0..1) x*p(x) dx\n"
    )
}

fn run(src: &str) -> std::process::Output {
    let f = lmx_file(src);
    lambdamat()
        .args(["solve", f.path().to_str().expect("utf-8")])
        .output()
        .expect("runs")
}

#[test]
fn equivalent_weights_give_the_same_answer_bit_for_bit() {
    let spellings = [
        "(1 - x)^(-1/2)",
        "(x - 1)^(-1/2)",
        "1/sqrt(1 - x)",
        "(-x + 1)^(-1/2)",
        "3*(2 - 2*x)^(-1/2)",
        "abs(x - 1)^(-1/2)",
    ];
    let mut values = Vec::new();
    for w in spellings {
        let f = lmx_file(&punch(w, ""));
        let j = json(&["solve", f.path().to_str().expect("utf-8")]);
        let p = j["outputs"]["P"].as_f64().expect("P");
        assert!((p - 4.0 / 3.0).abs() < 1e-9, "{w}: P = {p}");
        values.push(p.to_bits());
    }
    assert!(values.windows(2).all(|w| w[0] == w[1]), "{values:?}");
}

#[test]
fn a_weight_at_another_point_is_an_input_error() {
    let out = run(&punch("(1 + x)^(-1/2)", ""));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("singular at x = -1, not at the declared point 1"),
        "{err}"
    );
}

#[test]
fn a_broken_inequality_is_refused_with_where_and_how_much() {
    // The punch pressure is positive: p <= 0 cannot hold.
    let out = run(&punch("(1 - x)^(-1/2)", "inequality p <= 0 on [0, 1]\n"));
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("violates the inequality `p <= 0`") && err.contains("at x = "),
        "{err}"
    );
    assert!(err.contains(" by "), "{err}");
    // The true one passes.
    let ok = run(&punch("(1 - x)^(-1/2)", "inequality p >= 0 on [0, 1]\n"));
    assert_eq!(
        ok.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
}

#[test]
fn a_relation_to_zero_is_a_substitution() {
    // The sphere at given indentation: p = 0 beyond the contact.
    let j = json(&["solve", "examples/contact/sphere_indentation.lmx"]);
    let a = j["scalars"]["a"].as_f64().expect("a");
    assert!((a - 0.5f64.sqrt()).abs() < 1e-9, "a = {a}");
    // A nonzero constant is not a substitution.
    let src = std::fs::read_to_string("examples/contact/sphere_indentation.lmx")
        .expect("example")
        .replace("relation p = 0 on [a, 2]", "relation p = 1 on [a, 2]");
    let out = run(&src);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("must be 0 or a constant times an unknown"),
        "{err}"
    );
}

/// A negative load has no admissible root: the conditions' roots (if any)
/// pull the sphere out of the half-space, so the solve refuses with exit 3
/// and says how many starting points it tried, never exit 0.
#[test]
fn a_load_without_an_admissible_root_is_refused() {
    let out = lambdamat()
        .args([
            "solve",
            "examples/contact/sphere_load.lmx",
            "--set",
            "P0=-1",
        ])
        .output()
        .expect("runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(
        err.contains("no admissible root of the 2 conditions for a, delta found from")
            && err.contains("starting points in their declared ranges"),
        "{err}"
    );
    assert!(
        out.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

/// A scalar as the end of an operator's range or of an output's integral
/// is not supported yet: refused with exit 2 at its line and column.
#[test]
fn a_scalar_in_an_operator_range_or_an_output_is_an_input_error() {
    let sphere = std::fs::read_to_string("examples/contact/sphere_load.lmx").expect("source");
    for (from, to, at) in [
        (
            "output P = 2*pi*int(0..2) x*p(x) dx",
            "output P = 2*pi*int(0..a) x*p(x) dx",
            ":31:24",
        ),
        (
            "operator k1 = int(x..2) t/sqrt",
            "operator k1 = int(x..a) t/sqrt",
            ":21:22",
        ),
    ] {
        assert!(sphere.contains(from));
        let out = run(&sphere.replace(from, to));
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains("`a` is an unknown scalar, but a constant is needed here")
                && err.contains(at),
            "{err}"
        );
    }
}

/// JKR with an auxiliary unknown `z = 2p` that carries a singular term of
/// its own at the contact edge: the identity (or an integral from 0)
/// keeps the term's singularity there, so no limit fixes its coefficient.
/// Refused in the user's terms (exit 2), not with an assembly error; with
/// Abel equations for both unknowns the same file solves.
#[test]
fn a_singular_term_whose_equation_keeps_the_singularity_is_refused_in_words() {
    let jkr = std::fs::read_to_string("examples/contact/jkr_indentation.lmx").expect("source");
    let base = jkr
        .replace("unknown p on [0, 2]", "unknown p, z on [0, 2]")
        .replace(
            "operator k1 = int(x..2) t/sqrt(t^2 - x^2) dt",
            "operator k1 = int(x..2) t/sqrt(t^2 - x^2) dt\n\
             operator k2 = int(0..x) t/sqrt(x^2 - t^2) dt",
        )
        .replace(
            "relation p = 0 on [a, 2]",
            "relation p = 1*z on [a, 2]\nsingular z at a- ~ D*x/sqrt(a^2 - x^2)",
        );
    assert!(base.contains("unknown p, z") && base.contains("singular z at a-"));
    for eq in ["z - 2*p = 0", "k2 z - 2*k2 p = 0"] {
        let src = base.replace(
            "equation k1 p = delta - x^2 on [0, a)",
            &format!("equation k1 p = delta - x^2 on [0, a)\nequation {eq}"),
        );
        let out = run(&src);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{eq}: {err}");
        assert!(
            err.contains("is not finite at the point on the singular term of p")
                && !err.contains("assembly")
                && !err.contains("Jacobi"),
            "{eq}: {err}"
        );
    }
    let src = base.replace(
        "equation k1 p = delta - x^2 on [0, a)",
        "equation k1 p = delta - x^2 on [0, a)\nequation k1 z - 2*k1 p = 0",
    );
    let j = {
        let f = lmx_file(&src);
        json(&["solve", f.path().to_str().expect("utf-8")])
    };
    assert_eq!(j["converged"], true);
    let (b, d) = (
        j["coefficients"]["B"].as_f64().expect("B"),
        j["coefficients"]["D"].as_f64().expect("D"),
    );
    assert!((d - 2.0 * b).abs() < 1e-9, "B = {b}, D = {d}");
}

/// Gauss's airfoil-type log equation on [-1, 1] with the weight at -1
/// spelled every equivalent way: the same answer bit for bit.
#[test]
fn equivalent_weights_at_a_negative_point_give_the_same_answer() {
    let file = |w: &str| {
        format!(
            "operator k = 1/pi*int(-1..1) ln(abs(x - t)) dt\nunknown f on [-1, 1]\n\
             equation k f = 1\nsingular f at -1 ~ {w}\nsingular f at 1 ~ (1 - x)^(-1/2)\n\
             output V = int(-1..1) f(x) dx\n"
        )
    };
    let mut values = Vec::new();
    for w in [
        "(1 + x)^(-1/2)",
        "(x + 1)^(-1/2)",
        "(x - (-1))^(-1/2)",
        "1/sqrt(x + 1)",
        "2/sqrt(1 + x)",
        "(1 + x)^(-1/2)*3",
        "sqrt(2 + 2*x)^(-1)",
    ] {
        let f = lmx_file(&file(w));
        let j = json(&["solve", f.path().to_str().expect("utf-8")]);
        assert_eq!(j["converged"], true, "{w}");
        // ∫ f = -π/ln 2 (the capacity of [-1, 1] is 1/2).
        let v = j["outputs"]["V"].as_f64().expect("V");
        let exact = -std::f64::consts::PI / std::f64::consts::LN_2;
        assert!((v - exact).abs() < 1e-9, "{w}: V = {v}, exact {exact}");
        values.push(v.to_bits());
    }
    assert!(values.windows(2).all(|w| w[0] == w[1]), "{values:?}");
}

/// What a singular declaration cannot say yet is refused at its line and
/// column (exit 2): a logarithm, and a second exact term of one unknown
/// at one point and side.
#[test]
fn logarithmic_and_second_singular_terms_are_refused_at_their_place() {
    let cone = std::fs::read_to_string("examples/contact/cone.lmx").expect("source");
    let line = cone
        .lines()
        .position(|l| l.starts_with("singular p at a-"))
        .expect("the cone's edge term")
        + 1;
    for (extra, want) in [
        (
            "singular p at 0 ~ ln(x)",
            "logarithmic singular behaviour cannot be declared",
        ),
        (
            "singular p at a- ~ D*(a^2 - x^2)^(-1/2)",
            "already has a singular term `B*g(x)` at this point and side",
        ),
    ] {
        let src = cone.replace("singular p at a-", &format!("{extra}\nsingular p at a-"));
        let out = run(&src);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra}: {err}");
        assert!(err.contains(want), "{extra}: {err}");
        // The new declaration sits on the edge term's old line, which
        // moves down by one.
        let at_line = if extra.contains("ln(") {
            line
        } else {
            line + 1
        };
        assert!(err.contains(&format!(":{at_line}:")), "{extra}: {err}");
    }
}
