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
/// moves with the scalar: with `int(x..a)` the unknown beyond `a` enters
/// no equation, so setting it to 3 there (through a second unknown `q = 1`)
/// leaves the contact radius, the depth and the loads at their closed
/// forms (were the range not moved, the pressure beyond `a` would push
/// and `a` would be off by far more than 1e-9); an output's integral
/// `int(0..a/2)` ends at half the solved radius.
#[test]
fn a_scalar_ends_an_operator_range_and_an_output() {
    let src = "param P0 = 1\n\
     unknown p, q on [0, 2]\n\
     scalar a in (0, 2)\n\
     scalar delta in (0, 4)\n\
     operator k1 = int(x..a) t/sqrt(t^2 - x^2) dt\n\
     equation k1 p = delta - x^2 on [0, a)\n\
     equation q = 1 on [0, 2]\n\
     relation p = 3*q on [a, 2]\n\
     singular p at a- ~ B*x/sqrt(a^2 - x^2)\n\
     condition B = 0\n\
     condition int(0..a) 2*pi*x*p(x) dx = P0\n\
     output P_half = int(0..a/2) 2*pi*x*p(x) dx\n";
    let f = lmx_file(src);
    let j = json(&["solve", f.path().to_str().expect("utf-8")]);
    assert_eq!(j["converged"], true, "{j}");
    let a = (3.0f64 / 8.0).cbrt();
    for (name, exact) in [
        ("a", a),
        ("delta", a * a),
        ("P_half", 1.0 - 0.75f64.powf(1.5)),
    ] {
        let v = j["scalars"][name]
            .as_f64()
            .or_else(|| j["outputs"][name].as_f64())
            .expect("value");
        let e = j["error_estimates"][name].as_f64().expect("estimate");
        assert!(
            (v - exact).abs() <= 1e-9,
            "{name} = {v}, closed form {exact}"
        );
        assert!(
            (v - exact).abs() <= e,
            "{name} = {v} ± {e}, closed form {exact}"
        );
    }
}

/// A limit with a scalar needs the unknowns' interval declared. A point
/// value may be taken at a scalar (`p(a/2)`, an output or a side
/// condition), and it moves with the scalar as a limit does: on the
/// sphere at a given load it is Hertz's `(4/π)·√(a² − a²/4) = 2√3·a/π`.
#[test]
fn a_scalar_limit_without_a_declared_interval_is_an_input_error() {
    let sphere = std::fs::read_to_string("examples/contact/sphere_load_range.lmx").expect("source");
    let (from, to) = ("unknown p on [0, 2]", "unknown p");
    assert!(sphere.contains(from), "{from}");
    let out = run(&sphere.replace(from, to));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains(
            "an integration limit that uses an unknown scalar needs the unknowns' interval declared"
        ) && err.contains(":24:22"),
        "{err}"
    );
    let from = "output P = int(0..a) 2*pi*x*p(x) dx";
    assert!(sphere.contains(from), "{from}");
    let f = lmx_file(&sphere.replace(from, &format!("{from}\noutput p_mid = p(a/2)")));
    // `a/2` is also the limit of `P_half`, so it cuts the mesh, and a
    // point value at a cut converges as the field does there, more slowly
    // than the integrals: the default 1e-10 takes more than 9 levels.
    let j = json(&["solve", f.path().to_str().expect("utf-8"), "--tol", "1e-8"]);
    assert_eq!(j["converged"], true);
    let a = (3.0f64 / 8.0).cbrt();
    let exact = 2.0 * 3f64.sqrt() * a / std::f64::consts::PI;
    let v = j["outputs"]["p_mid"].as_f64().expect("p_mid");
    let e = j["error_estimates"]["p_mid"].as_f64().expect("estimate");
    assert!(
        (v - exact).abs() <= e,
        "p(a/2) = {v} ± {e}, closed form {exact}"
    );
    assert!(
        (v - exact).abs() <= 1e-8,
        "p(a/2) = {v}, closed form {exact}"
    );
    // A side condition on such a point value is refused at the position.
    let from = "condition B = 0";
    assert!(sphere.contains(from), "{from}");
    let out = run(&sphere.replace(from, &format!("{from}\ncondition p(a/2) = 1")));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains(
            "a condition cannot take a point value at a position that uses an unknown scalar"
        ),
        "{err}"
    );
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

/// What a singular declaration cannot say is refused at its line and
/// column (exit 2): a logarithm at another point than the declared one,
/// and a logarithm of something other than a linear expression. A second
/// exact term of one unknown at one point and side with the same power as
/// the first is refused too (exit 2, naming both coefficients): their
/// difference is bounded, so they are not determined apart.
#[test]
fn logarithmic_and_same_power_singular_terms_are_refused() {
    let cone = std::fs::read_to_string("examples/contact/cone.lmx").expect("source");
    let line = cone
        .lines()
        .position(|l| l.starts_with("singular p at a-"))
        .expect("the cone's edge term")
        + 1;
    for (extra, want) in [
        (
            "singular p at 0 ~ ln(x - 1)",
            "this logarithm is singular at x = 1, not at the declared point 0",
        ),
        (
            "singular p at 0 ~ ln(x^2)",
            "logarithmic singular behaviour must be the logarithm of an expression linear in x",
        ),
        (
            "singular p at a- ~ D*(a^2 - x^2)^(-1/2)",
            "the singular terms D and B of p at",
        ),
    ] {
        let src = cone.replace("singular p at a-", &format!("{extra}\nsingular p at a-"));
        let out = run(&src);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra}: {err}");
        assert!(err.contains(want), "{extra}: {err}");
        if extra.contains("ln(") {
            // The new declaration sits on the edge term's old line.
            assert!(err.contains(&format!(":{line}:")), "{extra}: {err}");
        } else {
            assert!(err.contains("have the same power"), "{extra}: {err}");
        }
    }
}

/// Two weights or logarithms of one unknown at one point are refused at
/// the second one's line and column (exit 2), whatever side it names: a
/// weight holds on both sides of its point, and two of them would multiply
/// where a sum is meant. The one power with the exponents added solves.
#[test]
fn a_second_weight_or_logarithm_at_one_point_is_refused_at_its_place() {
    for (first, second, col, what) in [
        (
            "(1 - x)^(-1/2)",
            "singular p at 1 ~ (1 - x)^(1/2)",
            19,
            "a weight",
        ),
        (
            "ln(1 - x)",
            "singular p at 1 ~ log(1 - x)/2",
            19,
            "a logarithm",
        ),
        (
            "(1 - x)^(-1/2)",
            "singular p at 1 ~ ln(1 - x)",
            19,
            "a weight",
        ),
        (
            "ln(1 - x)",
            "singular p at 1- ~ 1/sqrt(1 - x)",
            20,
            "a logarithm",
        ),
    ] {
        // `punch` puts its declaration on line 4 and the extra one on line 5.
        let out = run(&punch(first, &format!("{second}\n")));
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{second}: {err}");
        assert!(
            err.contains(&format!("`p` already has {what} at this point"))
                && err.contains("one unknown has one of them per point"),
            "{second}: {err}"
        );
        assert!(err.contains(&format!(":5:{col}]")), "{second}: {err}");
    }
    // Weights of one unknown at two points are two declarations: the
    // punch's load P = 4/3 with a plain weight at the other end.
    let f = lmx_file(&punch("(1 - x)^(-1/2)", "singular p at 0 ~ x^0\n"));
    let j = json(&["solve", f.path().to_str().expect("utf-8")]);
    let p = j["outputs"]["P"].as_f64().expect("P");
    assert!((p - 4.0 / 3.0).abs() < 1e-9, "P = {p}");
}

/// `reduce` shows a side condition in the unknowns of each subinterval's
/// model: on the stick zone of the Cattaneo–Mindlin force file the shear
/// `q` itself, on the slip zone `q = mu*p` substituted (never `?(x)`).
#[test]
fn reduce_prints_side_conditions_in_each_pieces_unknowns() {
    let out = lambdamat()
        .args(["reduce", "examples/contact/cattaneo_mindlin_force.lmx"])
        .output()
        .expect("runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(
        text.contains("(condition 2*pi*int(0..1) x*q(x) dx = 7/6)")
            && text.contains("(condition 1/2*(2*pi)*int(0..1) x*p(x) dx = 7/6)")
            && !text.contains("?(x)"),
        "{text}"
    );
}

/// JKR adhesion at a given tensile load between the pull-off load and 0
/// has two equilibria (P = (8/3)a³ − 2πC a^(3/2) falls, then rises): the
/// joint solve of `a` and `delta` finds both, admissible alike (no
/// inequality tells them apart), and refuses with exit 3 naming both.
#[test]
fn two_admissible_roots_of_the_conditions_are_refused_naming_both() {
    let src = "param C = 1/4\n\
               param P0 = -1/10\n\
               unknown p on [0, 2]\n\
               scalar a in (0, 2)\n\
               scalar delta in (-2, 4)\n\
               operator k1 = int(x..2) t/sqrt(t^2 - x^2) dt\n\
               equation k1 p = delta - x^2 on [0, a)\n\
               relation p = 0 on [a, 2]\n\
               singular p at a- ~ B*x/sqrt(a^2 - x^2)\n\
               condition B = -C/sqrt(a)\n\
               condition 2*pi*int(0..2) x*p(x) dx = P0\n\
               output P = 2*pi*int(0..2) x*p(x) dx\n";
    let out = run(src);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(
        out.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(
        err.contains("the 2 conditions for a, delta have 2 admissible roots"),
        "{err}"
    );
    // The closed-form roots: (8/3)a^3 - 2 pi C a^(3/2) = P0 on each side
    // of the minimum at a^(3/2) = 3 pi C/8, by bisection.
    let (c, p0) = (0.25f64, -0.1f64);
    let load = |a: f64| 8.0 / 3.0 * a.powi(3) - 2.0 * std::f64::consts::PI * c * a.powf(1.5) - p0;
    let root = |mut lo: f64, mut hi: f64| {
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if (load(m) > 0.0) == (load(lo) > 0.0) {
                lo = m;
            } else {
                hi = m;
            }
        }
        lo
    };
    let turn = (3.0 * std::f64::consts::PI * c / 8.0).powf(2.0 / 3.0);
    for a in [root(1e-9, turn), root(turn, 2.0)] {
        assert!(
            err.contains(&format!("a = {:.6e}", a)[..12]),
            "root a = {a} not named: {err}"
        );
    }
}

/// JKR adhesion at a given tensile depth, `delta = -1/10`, has two
/// equilibria with one unknown scalar: `delta = a^2 - (pi/2) C sqrt(a)`
/// falls and then rises in `a`. The single-scalar search refuses with
/// exit 3 naming both; a range narrowed to either one returns it, equal
/// to the closed form to 1e-9 and within its estimate.
#[test]
fn two_admissible_roots_of_one_scalar_are_refused_and_each_can_be_selected() {
    let file = "examples/contact/jkr_indentation.lmx";
    let (c, delta) = (0.25f64, -0.1f64);
    let depth = |a: f64| a * a - std::f64::consts::PI / 2.0 * c * a.sqrt() - delta;
    let root = |mut lo: f64, mut hi: f64| {
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if (depth(m) > 0.0) == (depth(lo) > 0.0) {
                lo = m;
            } else {
                hi = m;
            }
        }
        lo
    };
    // The minimum of the depth: sqrt(a)^3 = pi C/8.
    let turn = (std::f64::consts::PI * c / 8.0).powf(2.0 / 3.0);
    let roots = [root(1e-12, turn), root(turn, 2.0)];
    assert!(roots[0] < 0.2 && roots[1] > 0.2, "{roots:?}");

    let out = lambdamat()
        .args(["solve", file, "--set", "delta=-1/10"])
        .output()
        .expect("runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(out.stdout.is_empty());
    assert!(
        err.contains("the condition for a has 2 admissible roots in (0, 2)")
            && err.contains("narrow the range in `scalar a in (lo, hi)`"),
        "{err}"
    );
    // Each root is named, to the accuracy of the first level.
    let named: Vec<f64> = err
        .split("a = ")
        .skip(1)
        .filter_map(|t| t.split([',', ';']).next()?.trim().parse().ok())
        .collect();
    assert_eq!(named.len(), 2, "{err}");
    for (n, r) in named.iter().zip(roots) {
        assert!((n - r).abs() < 1e-9, "named {n}, closed form {r}");
    }

    // The range, with parameter ends, narrowed to each root in turn.
    let text = std::fs::read_to_string(file).expect("reads");
    let line = "scalar a in (0, 2)";
    assert!(text.contains(line));
    let src = text.replace(
        line,
        "param amin = 0\nparam amax = 2\nscalar a in (amin, amax)",
    );
    let f = lmx_file(&src);
    let path = f.path().to_str().expect("utf-8");
    for (range, exact) in [
        (["amax=1/5", "amin=0"], roots[0]),
        (["amin=1/5", "amax=2"], roots[1]),
    ] {
        let j = json(&[
            "solve",
            path,
            "--set",
            "delta=-1/10",
            "--set",
            range[0],
            "--set",
            range[1],
        ]);
        assert_eq!(j["converged"], true, "{range:?}");
        let a = j["scalars"]["a"].as_f64().expect("a");
        let e = j["error_estimates"]["a"].as_f64().expect("estimate");
        let error = (a - exact).abs();
        assert!(
            error <= 1e-9 && error <= e + 8.0 * f64::EPSILON,
            "{range:?}: a = {a} ± {e}, closed form {exact}"
        );
    }
}

/// The cone's pressure `arccosh(a/x)` is logarithmically infinite at the
/// centre; `singular p at 0 ~ ln(x)` says so. Every spelling gives the same
/// answer bit for bit, within 1e-9 and its estimate of Sneddon's
/// `a = 2 delta/pi`, `P = pi a^2`; the report says what the declaration
/// does, and `p(0)` is not among the values.
#[test]
fn a_logarithmic_end_is_declared_in_any_spelling() {
    let cone = std::fs::read_to_string("examples/contact/cone.lmx").expect("source");
    let a = 2.0 / std::f64::consts::PI;
    let exact = [("a", a), ("P", std::f64::consts::PI * a * a)];
    let mut bits = Vec::new();
    for body in [
        "ln(x)",
        "log(x)",
        "-ln(abs(x - 0))",
        "ln(2*x)/2",
        "ln(0 - x)",
    ] {
        let src = cone.replace(
            "singular p at a-",
            &format!("singular p at 0 ~ {body}\nsingular p at a-"),
        );
        let f = lmx_file(&src);
        let j = json(&["solve", f.path().to_str().expect("utf-8")]);
        assert_eq!(j["converged"], true, "{body}");
        let mut these = Vec::new();
        for (name, want) in exact {
            let v = j["scalars"][name]
                .as_f64()
                .or_else(|| j["outputs"][name].as_f64())
                .expect("value");
            let e = j["error_estimates"][name].as_f64().expect("estimate");
            let err = (v - want).abs();
            assert!(
                err <= 1e-9 && err <= e,
                "{body}: {name} = {v} ± {e}, closed form {want}"
            );
            these.push(v.to_bits());
        }
        bits.push(these);
        let notes = j["notes"].to_string();
        assert!(
            notes.contains("p is declared logarithmic at 0")
                && !notes.contains("graded toward the end"),
            "{body}: {notes}"
        );
        let xs = j["unknowns"]["p"]["x"].as_array().expect("grid");
        assert!(
            !xs.is_empty() && xs.iter().all(|x| x.as_f64() != Some(0.0)),
            "{xs:?}"
        );
    }
    assert!(bits.windows(2).all(|w| w[0] == w[1]), "{bits:?}");
}

/// An unknown on an interval that ends at an unknown scalar lives on the
/// scalar's range and is zero beyond the scalar: `unknown p on [0, a]`
/// with an equation written without a domain solves bit for bit as the
/// shipped file with `[0, 2]`, `relation p = 0 on [a, 2]` and the equation
/// `on [0, a)`. A scalar whose range has no finite end there is still
/// refused at the scalar (exit 2), saying how to write it.
#[test]
fn an_unknown_interval_ending_at_a_scalar_is_zero_beyond_it() {
    let sphere =
        std::fs::read_to_string("examples/contact/sphere_indentation.lmx").expect("source");
    let at_scalar = sphere
        .replace("unknown p on [0, 2]", "unknown p on [0, a]")
        .replace(
            "equation k1 p = delta - x^2 on [0, a)",
            "equation k1 p = delta - x^2",
        )
        .lines()
        .filter(|l| !l.starts_with("relation p = 0"))
        .collect::<Vec<_>>()
        .join("\n");
    assert!(
        !at_scalar.contains("relation p") && at_scalar.contains("equation k1 p = delta - x^2\n")
    );
    let f = lmx_file(&at_scalar);
    let ours = json(&["solve", f.path().to_str().expect("utf-8")]);
    let shipped = json(&["solve", "examples/contact/sphere_indentation.lmx"]);
    for key in ["scalars", "outputs", "error_estimates", "levels"] {
        assert_eq!(ours[key], shipped[key], "{key}");
    }
    assert!(ours["converged"].as_bool().expect("bool"));
    // a = 1/√2 for delta = 1/2 (δ = a²).
    let a = ours["scalars"]["a"].as_f64().expect("a");
    assert!((a - 0.5f64.sqrt()).abs() <= 1e-9, "{a}");

    let unbounded = at_scalar.replace("scalar a in (0, 2)", "scalar a in (0, inf)");
    let line = unbounded
        .lines()
        .position(|l| l.starts_with("unknown p on [0, a]"))
        .expect("the unknown's declaration")
        + 1;
    let out = run(&unbounded);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("an unknown's interval cannot end at an unknown scalar")
            && err.contains(&format!(":{line}:18]"))
            && err.contains("`relation p = 0 on [a, 2]`"),
        "{err}"
    );
}

/// Several exact terms of one unknown at one point and side, in one
/// declaration (`A*g(x) + B*h(x)`) or in several, solve to the same bits,
/// and each coefficient and the output lie within their estimates of the
/// closed form of `examples/two_terms.lmx` (A = 1/2, B = 1/3, P = 22/9),
/// with the coupled and the ordered method alike (the ordered one
/// reports the normwise floor where it keeps no factors, so it may fall
/// short of the tolerance, but never claims more than it has).
#[test]
fn several_singular_terms_at_one_point_are_each_fixed_within_their_estimates() {
    let sum = std::fs::read_to_string("examples/two_terms.lmx").expect("source");
    let decl = "singular p at 1- ~ A/sqrt(1 - x) + B*(1 - x)^(-1/4)";
    assert!(sum.contains(decl), "the example declares a sum");
    let split = sum.replace(
        decl,
        "singular p at 1- ~ A/sqrt(1 - x)\nsingular p at 1- ~ B*(1 - x)^(-1/4)",
    );
    let difference = sum.replace(decl, "singular p at 1- ~ A/sqrt(1 - x) - B*(1 - x)^(-1/4)");
    let want = [("P", 22.0 / 9.0), ("A", 0.5), ("B", 1.0 / 3.0)];
    let mut compared = 0;
    let mut first: Option<serde_json::Value> = None;
    for (what, src, args, sign) in [
        ("sum", &sum, &[][..], 1.0),
        ("two declarations", &split, &[][..], 1.0),
        ("difference", &difference, &[][..], -1.0),
        ("ordered", &sum, &["--method", "ordered"][..], 1.0),
    ] {
        let f = lmx_file(src);
        let mut a = vec!["solve", f.path().to_str().expect("utf-8")];
        a.extend_from_slice(args);
        let out = lambdamat().args(&a).arg("--json").output().expect("runs");
        let j: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
        let converged = j["converged"].as_bool().expect("converged");
        assert_eq!(out.status.code() == Some(0), converged, "{what}");
        for (q, exact) in want {
            let group = if q == "P" { "outputs" } else { "coefficients" };
            let exact = if q == "B" { sign * exact } else { exact };
            let got = j[group][q].as_f64().expect("value");
            let e = j["error_estimates"][q].as_f64().expect("estimate");
            assert!(
                (got - exact).abs() <= e,
                "{what}: {q} = {got}, exact {exact}, estimate {e}"
            );
            compared += 1;
        }
        if args.is_empty() && sign > 0.0 {
            assert!(converged, "{what}");
            match &first {
                None => first = Some(j),
                Some(f) => assert_eq!(f["coefficients"], j["coefficients"], "{what}"),
            }
        }
    }
    assert_eq!(compared, 12);
}

/// Every term of a sum of singular terms names its own new coefficient:
/// a repeated one is refused at its line and column (exit 2).
#[test]
fn a_sum_of_singular_terms_needs_a_coefficient_per_term() {
    let src = std::fs::read_to_string("examples/two_terms.lmx")
        .expect("source")
        .replace("+ B*(1 - x)^(-1/4)", "+ A*(1 - x)^(-1/4)");
    let line = src
        .lines()
        .position(|l| l.starts_with("singular p at 1-"))
        .expect("the declaration")
        + 1;
    let out = run(&src);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("needs its own new coefficient name"), "{err}");
    assert!(err.contains(&format!(":{line}:36]")), "{err}");
}
