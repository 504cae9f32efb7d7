//! End-to-end tests of the operator-system part of the language: the Hertz
//! example lowers to the seed's λ-matrix (2.7), operator table (2.6), right
//! sides and output; every validation error is reported with its message and
//! line:column.

mod common;

use common::{errs, ok, single, summary};
use lambdamat::lang::{Directive, ErrorKind};
use lambdamat::system::{Expr, FunctionalTerm, Limit, Term};
use num_bigint::BigInt;
use num_rational::BigRational;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

const HERTZ: &str = include_str!("../examples/hertz_stick.lmx");

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-14 * (1.0 + b.abs())
}

#[test]
fn hertz_lambda_matrix_is_the_seeds_2_7() {
    let p = ok(HERTZ);
    assert_eq!(p.symbols, ["k1", "k2", "k3", "k4"]);
    assert_eq!(p.unknowns, ["p", "q"]);
    assert_eq!(p.principal, Some(3));
    assert_eq!(p.directives, [Directive::Solve { unknown: 0 }]);
    let a = p.lambda_matrix();
    assert_eq!((a.rows, a.cols), (2, 2));
    let shown: Vec<String> = a
        .entries
        .iter()
        .map(|e| e.to_string_with(&p.symbols))
        .collect();
    assert_eq!(shown, ["k1", "k2", "k3", "k4"]);
    assert_eq!(p.equations[0].rhs, Expr::Const(q(1, 1)));
    assert_eq!(p.equations[1].rhs, Expr::Const(q(0, 1)));
    let params: Vec<_> = p
        .params
        .iter()
        .map(|x| (x.name.as_str(), x.value.clone()))
        .collect();
    assert_eq!(params, [("nu", q(1, 4)), ("gamma", q(1, 3))]);
}

#[test]
fn hertz_operator_table_is_the_seeds_2_6() {
    let p = ok(HERTZ);
    let gamma = 1.0 / 3.0;
    let (x, t): (f64, f64) = (0.6, 0.8);
    let root_tx = (t * t - x * x).sqrt();
    let root_xt = (x * x - t * t).abs().sqrt();
    // κ1: one integral over x..1 with kernel t/√(t²-x²).
    let k1 = &p.operator(0).expect("k1 defined").terms;
    match k1.as_slice() {
        [
            Term::Integral {
                lower: Limit::X,
                upper: Limit::Const(one),
                kernel,
                ..
            },
        ] => {
            assert_eq!(one, &q(1, 1));
            assert!(close(kernel.eval(x, t), t / root_tx));
        }
        other => panic!("k1 = {other:?}"),
    }
    // κ2: -γ ∫_0^1 + γ ∫_0^x x/√(x²-t²).
    let k2 = &p.operator(1).expect("k2 defined").terms;
    match k2.as_slice() {
        [
            Term::Integral {
                lower: Limit::Const(a),
                upper: Limit::Const(b),
                kernel: k_a,
                ..
            },
            Term::Integral {
                lower: Limit::Const(c),
                upper: Limit::X,
                kernel: k_b,
                ..
            },
        ] => {
            assert_eq!((a, b, c), (&q(0, 1), &q(1, 1), &q(0, 1)));
            assert_eq!(k_a, &Expr::Const(q(-1, 3)));
            let (x, t) = (0.8, 0.6);
            assert!(close(k_b.eval(x, t), gamma * x / root_xt));
        }
        other => panic!("k2 = {other:?}"),
    }
    // κ4: -∫_x^1 x/√(t²-x²).
    let k4 = &p.operator(3).expect("k4 defined").terms;
    match k4.as_slice() {
        [
            Term::Integral {
                lower: Limit::X,
                upper: Limit::Const(_),
                kernel,
                ..
            },
        ] => {
            assert!(close(kernel.eval(x, t), -x / root_tx));
        }
        other => panic!("k4 = {other:?}"),
    }
}

#[test]
fn hertz_output_is_the_compliance_factor() {
    let p = ok(HERTZ);
    assert_eq!(p.outputs.len(), 1);
    assert_eq!(p.outputs[0].name, "P");
    match p.outputs[0].terms.as_slice() {
        [
            FunctionalTerm::Integral {
                coeff,
                lower,
                upper,
                weight,
                unknown: 0,
            },
        ] => {
            assert!(close(coeff.eval(0.0, 0.0), std::f64::consts::FRAC_PI_2));
            assert_eq!((lower, upper), (&q(0, 1), &q(1, 1)));
            assert_eq!(weight, &Expr::X);
        }
        other => panic!("P = {other:?}"),
    }
}

const HEAD: &str = "operator a = int(0..x) dt\noperator b = 2*id - x^2*id + int(x..1) (t - x) dt/3\nunknown p, q\n";

#[test]
fn equation_terms_products_and_signs() {
    let p = ok(&format!(
        "{HEAD}equation b*a p - 2*a*q + p = x\nequation -a p + a^2 q - b q = sqrt(x)\n"
    ));
    let a = p.lambda_matrix();
    let shown: Vec<String> = a
        .entries
        .iter()
        .map(|e| e.to_string_with(&p.symbols))
        .collect();
    assert_eq!(shown, ["a*b + 1", "-2*a", "-a", "a^2 - b"]);
    assert_eq!(p.equations[0].rhs, Expr::X);
    assert!(close(p.equations[1].rhs.eval(0.25, f64::NAN), 0.5));
}

#[test]
fn operator_terms_identity_scalar_multiplier_integral() {
    let p = ok(&format!("{HEAD}equation a p = 0\nequation b q = 0\n"));
    let b = &p.operator(1).expect("b").terms;
    match b.as_slice() {
        [
            Term::Scalar(two),
            Term::Multiply(m),
            Term::Integral {
                lower: Limit::X,
                kernel,
                ..
            },
        ] => {
            assert_eq!(two, &q(2, 1));
            assert!(close(m.eval(0.5, f64::NAN), -0.25));
            assert!(close(kernel.eval(0.25, 1.0), 0.25));
        }
        other => panic!("b = {other:?}"),
    }
    let a = &p.operator(0).expect("a").terms;
    assert_eq!(
        a,
        &[Term::Integral {
            lower: Limit::Const(q(0, 1)),
            upper: Limit::X,
            kernel: Expr::Const(q(1, 1)),
            pv: false,
        }]
    );
    let p = ok("operator i = id\noperator h = id/2\nunknown u\nequation (i + h) u = 1\n");
    assert_eq!(p.operator(0).expect("i").terms, [Term::Identity]);
    assert_eq!(p.operator(1).expect("h").terms, [Term::Scalar(q(1, 2))]);
}

#[test]
fn outputs_with_constants_and_dt() {
    let p = ok(&format!(
        "{HEAD}param g = 1/3\nequation a p = 0\nequation b q = 0\n\
         output S = 1 + g*int(0..1) q(t)*(1 - sqrt(1 - t^2)) dt - int(0..1/2) p(x) dx\n"
    ));
    match p.outputs[0].terms.as_slice() {
        [
            FunctionalTerm::Constant(one),
            FunctionalTerm::Integral {
                coeff: c1,
                weight: w1,
                unknown: 1,
                ..
            },
            FunctionalTerm::Integral {
                coeff: c2,
                upper,
                weight: w2,
                unknown: 0,
                ..
            },
        ] => {
            assert_eq!(one, &Expr::Const(q(1, 1)));
            assert_eq!(c1, &Expr::Const(q(1, 3)));
            assert!(!w1.uses_t(), "weights are stored in x");
            assert!(close(w1.eval(0.6, f64::NAN), 0.2));
            assert_eq!(c2, &Expr::Const(q(-1, 1)));
            assert_eq!(upper, &q(1, 2));
            assert_eq!(w2, &Expr::Const(q(1, 1)));
        }
        other => panic!("S = {other:?}"),
    }
}

#[test]
fn var_symbols_are_abstract_operators() {
    let p = ok("var k1, k2\nunknown u\nequation (k1 + k2) u = 1\nsolve for u\n");
    assert!(p.operators.is_empty());
    assert_eq!(
        p.lambda_matrix().entries[0].to_string_with(&p.symbols),
        "k1 + k2"
    );
}

// ───────────────────────────── errors ─────────────────────────────

#[test]
fn undeclared_names_in_every_place() {
    let all =
        summary("operator a = int(0..x) w dt\nunknown p\nequation a p + b q = f\nsolve for r\n");
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (ErrorKind::Undeclared, "undeclared name `w`", 1, 24),
            (ErrorKind::Undeclared, "undeclared operator `b`", 3, 16),
            (ErrorKind::Undeclared, "undeclared unknown `q`", 3, 18),
            (ErrorKind::Undeclared, "undeclared name `f`", 3, 22),
            (ErrorKind::Undeclared, "undeclared unknown `r`", 4, 11),
        ]
    );
}

#[test]
fn unknown_used_non_linearly() {
    let all = summary("operator a = id\nunknown p, q\nequation a*p*q = 1\nequation p*a + q = 0\n");
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::NonLinear,
                "the unknown `p` is used non-linearly: each term applies operators to one unknown, written last",
                3,
                12
            ),
            (
                ErrorKind::NonLinear,
                "the unknown `p` must come last in its term, after the operators applied to it",
                4,
                10
            ),
        ]
    );
}

#[test]
fn unknown_inside_a_kernel_or_on_the_right() {
    let all = summary("unknown p\noperator a = int(0..x) p(t) dt\nequation a p = p\n");
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::NonLinear,
                "the unknown `p` cannot appear inside a kernel",
                2,
                24
            ),
            (
                ErrorKind::NonLinear,
                "the unknown `p` cannot appear on the right side",
                3,
                16
            ),
        ]
    );
}

#[test]
fn variables_where_they_cannot_be() {
    let all = summary(
        "operator a = t*id + int(0..t) dx\nunknown p\nequation a p = t\n\
         output P = x + int(0..1) x*p(t) dt\n",
    );
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::BadVariable,
                "`t` is the integration variable and may only appear inside `int(…) … dt`",
                1,
                14
            ),
            (
                ErrorKind::BadVariable,
                "an integration limit must be `x` or a constant",
                1,
                28
            ),
            (
                ErrorKind::BadVariable,
                "an operator integrates over t: close the integral with `dt`",
                1,
                31
            ),
            (
                ErrorKind::BadVariable,
                "`t` is the integration variable and may only appear inside `int(…) … dt`",
                3,
                16
            ),
            (
                ErrorKind::BadVariable,
                "an output is a number: `x` may only appear inside an integral",
                4,
                12
            ),
            (
                ErrorKind::BadVariable,
                "this integral runs over t (`dt`), so `x` cannot appear in it",
                4,
                26
            ),
        ]
    );
}

#[test]
fn non_square_system() {
    let (k, m, l, c) = single("operator a = id\nunknown p, q\nequation a p = 1\n");
    assert_eq!(k, ErrorKind::NotSquare);
    assert_eq!(m, "the system is not square: 1 equation for 2 unknowns");
    assert_eq!((l, c), (2, 1));
    let e = errs("operator a = id\nunknown p\nequation a p = 1\nequation p = 2\n");
    assert_eq!(
        e.errors()[0].message,
        "the system is not square: 2 equations for 1 unknown"
    );
    assert!(e.render().contains("extra equation"), "{}", e.render());
    assert!(e.render().contains("t.lmx:4:1"), "{}", e.render());
}

#[test]
fn duplicate_definitions() {
    let all = summary(
        "operator a = id\nparam a = 1\nunknown p, p\noperator k = id\noutput k = 1\nequation a p = 0\n",
    );
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (ErrorKind::Duplicate, "`a` is defined more than once", 2, 7),
            (ErrorKind::Duplicate, "`p` is defined more than once", 3, 12),
            (ErrorKind::Duplicate, "`k` is defined more than once", 5, 8),
        ]
    );
}

#[test]
fn division_by_zero_in_params_kernels_and_outputs() {
    let all = summary(
        "param nu = 1/2\nparam g = 1/(1 - 2*nu)\noperator a = int(0..1) t/(nu - 1/2) dt\n\
         unknown p\nequation a p = x/0\noutput P = int(0..1) p(x) dx / (1 - 1)\n",
    );
    let got: Vec<_> = all.iter().map(|(k, _, l, c)| (*k, *l, *c)).collect();
    assert_eq!(
        got,
        [
            (ErrorKind::DivisionByZero, 2, 13),
            (ErrorKind::DivisionByZero, 3, 26),
            (ErrorKind::DivisionByZero, 5, 18),
            (ErrorKind::DivisionByZero, 6, 32),
        ]
    );
}

#[test]
fn parameters_must_be_defined_first_and_real_ones_stay_out_of_exact_places() {
    // `pi` and `sqrt(2)` make real parameters (numerics only); using one
    // where an exact rational is needed (a matrix entry) is an error.
    let all = summary(
        "param a = b + 1\nparam b = 2\nparam c = pi\nparam d = sqrt(2)\nvar x\nmatrix M = [d*x]\n",
    );
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::Undeclared,
                "parameter `b` is used before its definition",
                1,
                11
            ),
            (
                ErrorKind::WrongSort,
                "`d` is a real (not exactly rational) parameter, but an exact rational is needed here",
                6,
                13
            ),
        ]
    );
}

#[test]
fn operator_definitions_must_be_operators() {
    let all = summary(
        "operator a = x^2\noperator b = id + 1\noperator c = int(0..1) dt * int(0..x) dt\noperator d = a\n\
         unknown p, q, r, s\nequation a p = 0\nequation b q = 0\nequation c r = 0\nequation d s = 0\n",
    );
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::WrongSort,
                "an operator must be built from `id` and integrals `int(a..b) … dt`",
                1,
                14
            ),
            (
                ErrorKind::WrongSort,
                "this is a function, not an operator term",
                2,
                19
            ),
            (
                ErrorKind::NonLinear,
                "a product of two operators cannot be defined directly",
                3,
                14
            ),
            (
                ErrorKind::WrongSort,
                "an operator definition cannot refer to another operator (`a`)",
                4,
                14
            ),
        ]
    );
}

#[test]
fn reserved_variables_cannot_be_names_and_keywords_neither() {
    let all = summary("unknown x\nparam t = 1\n");
    let got: Vec<_> = all.iter().map(|(k, _, l, c)| (*k, *l, *c)).collect();
    assert_eq!(
        got,
        [
            (ErrorKind::NotSquare, 1, 1),
            (ErrorKind::BadVariable, 1, 9),
            (ErrorKind::BadVariable, 2, 7)
        ]
    );
    let (k, m, l, c) = single("unknown p, output\n");
    assert_eq!(k, ErrorKind::KeywordAsName);
    assert_eq!(
        m,
        "`output` is a reserved keyword and cannot be used as a name"
    );
    assert_eq!((l, c), (1, 12));
}

#[test]
fn outputs_must_be_linear() {
    let all = summary(
        "operator a = id\nunknown p\nequation a p = 1\n\
         output A = int(0..1) p(x)^2 dx\noutput B = int(0..1) x dx\noutput C = p(1/2)^2\n\
         output D = p(1/2) + 2*int(0..1) p(x) dx\n",
    );
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::NonLinear,
                "the unknown `p` is used non-linearly",
                4,
                22
            ),
            (
                ErrorKind::NonLinear,
                "this part of the integrand contains no unknown",
                5,
                22
            ),
            (
                ErrorKind::NonLinear,
                "the unknown `p` is used non-linearly",
                6,
                12
            ),
        ]
    );
}

#[test]
fn system_syntax_errors_say_what_was_expected() {
    let (k, m, l, c) = single("operator k1 = int(x..1) t/sqrt(t^2 - x^2)\nunknown p\n");
    assert_eq!(k, ErrorKind::Syntax);
    assert_eq!(
        m,
        "expected an operator (`+`, `-`, `*`, `/`, `^`) or `dt`/`dx` to close the integral, found the keyword `unknown`"
    );
    assert_eq!((l, c), (2, 1));
    let (k, m, l, c) = single("unknown p\nequation k1 p + = 1\n");
    assert_eq!(k, ErrorKind::Syntax);
    assert_eq!(m, "expected a term such as `k1 p`, found `=`");
    assert_eq!((l, c), (2, 17));
}

#[test]
fn generic_and_singular_examples() {
    let p = ok(include_str!("../examples/generic3.lmx"));
    assert_eq!(p.symbols.len(), 9);
    assert!(p.operators.is_empty());
    let a = p.lambda_matrix();
    let shown: Vec<String> = a
        .entries
        .iter()
        .map(|e| e.to_string_with(&p.symbols))
        .collect();
    assert_eq!(
        shown,
        ["k1", "k2", "k3", "k4", "k5", "k6", "k7", "k8", "k9"]
    );
    assert_eq!(p.directives, [Directive::Solve { unknown: 0 }]);
    let p = ok(include_str!("../examples/singular.lmx"));
    let a = p.lambda_matrix();
    let shown: Vec<String> = a
        .entries
        .iter()
        .map(|e| e.to_string_with(&p.symbols))
        .collect();
    assert_eq!(shown, ["k1", "k2", "k1*k2", "k2^2"]);
}

/// Applies one operator of the lowered Hertz system to `f` at `x` by
/// quadrature, with substitutions that remove the 1/√ singularity of the
/// Abel kernels: `t = x sin θ` on `0..x`, `t = √(x² + s²)` on `x..1`.
fn apply(terms: &[Term], f: &dyn Fn(f64) -> f64, x: f64) -> f64 {
    /// Composite midpoint rule: never evaluates the endpoints, where the
    /// transformed integrands are 0/0.
    fn midpoint(g: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
        let n = 20000;
        let h = (b - a) / n as f64;
        (0..n).map(|i| g(a + (i as f64 + 0.5) * h)).sum::<f64>() * h
    }
    let val = |l: &Limit| match l {
        Limit::X => None,
        Limit::Const(q) => Some(num_traits::ToPrimitive::to_f64(q).unwrap_or(f64::NAN)),
    };
    terms
        .iter()
        .map(|term| match term {
            Term::Integral {
                lower,
                upper,
                kernel,
                ..
            } => match (val(lower), val(upper)) {
                (Some(0.0), None) => midpoint(
                    &|th: f64| {
                        let t = x * th.sin();
                        kernel.eval(x, t) * f(t) * x * th.cos()
                    },
                    0.0,
                    std::f64::consts::FRAC_PI_2,
                ),
                (None, Some(1.0)) => midpoint(
                    &|s: f64| {
                        let t = (x * x + s * s).sqrt();
                        kernel.eval(x, t) * f(t) * s / t
                    },
                    0.0,
                    (1.0 - x * x).sqrt(),
                ),
                (Some(a), Some(b)) => midpoint(&|t: f64| kernel.eval(x, t) * f(t), a, b),
                other => panic!("limits {other:?} not used by the Hertz operators"),
            },
            Term::Identity => f(x),
            Term::Scalar(c) => num_traits::ToPrimitive::to_f64(c).unwrap_or(f64::NAN) * f(x),
            Term::Multiply(m) => m.eval(x, f64::NAN) * f(x),
        })
        .sum()
}

#[test]
fn hertz_operators_satisfy_the_abel_identities() {
    let p = ok(HERTZ);
    let gamma = 1.0 / 3.0;
    let k = |i: usize| p.operator(i).expect("defined").terms.clone();
    let one = |_: f64| 1.0;
    let id = |t: f64| t;
    for x in [0.1f64, 0.35, 0.5, 0.8, 0.95] {
        let r = (1.0 - x * x).sqrt();
        let checks = [
            ("k1[1]", apply(&k(0), &one, x), r),
            (
                "k4[1]",
                apply(&k(3), &one, x),
                x * f64::ln(x) - x * f64::ln(1.0 + r),
            ),
            ("k3[1]", apply(&k(2), &one, x), gamma * x),
            ("k4[x]", apply(&k(3), &id, x), -x * r),
            ("k2[x]", apply(&k(1), &id, x), gamma * (x * x - 0.5)),
        ];
        for (what, got, want) in checks {
            assert!(
                (got - want).abs() < 1e-9,
                "{what} at x={x}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn manufactured_system_has_residual_zero_at_the_exact_solution() {
    let p = ok(include_str!("../examples/hertz_manufactured.lmx"));
    let exact: [&dyn Fn(f64) -> f64; 2] = [&|_| 1.0, &|t| t];
    for x in [0.2f64, 0.5, 0.9] {
        for (i, eq) in p.equations.iter().enumerate() {
            let mut lhs = 0.0;
            for (j, poly) in eq.lhs.iter().enumerate() {
                // Here every entry is a single operator symbol or zero.
                for (word, coeff) in poly.terms() {
                    let [sym] = word.as_slice() else {
                        panic!("one symbol per term")
                    };
                    let sym = *sym;
                    let c = num_traits::ToPrimitive::to_f64(coeff).unwrap_or(f64::NAN);
                    let terms = &p.operator(sym).expect("defined").terms;
                    lhs += c * apply(terms, exact[j], x);
                }
            }
            let rhs = eq.rhs.eval(x, f64::NAN);
            assert!(
                (lhs - rhs).abs() < 1e-9,
                "equation {i} at x={x}: {lhs} vs {rhs}"
            );
        }
    }
    let names: Vec<&str> = p.outputs.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["P", "Q"]);
}

#[test]
fn products_keep_the_order_written_and_the_lambda_matrix_is_their_image() {
    let p = ok("var a, b\nunknown u, v\n\
         equation b*a u - a*b u + 2*b^2*a v = x\nequation a u + v = 1\n");
    let e = &p.equations[0];
    // The commutator b a - a b is kept, not cancelled.
    assert_eq!(e.lhs[0].to_string_with(&p.symbols), "-a b + b a");
    assert_eq!(e.lhs[1].to_string_with(&p.symbols), "2*b^2 a");
    let a = p.lambda_matrix();
    assert!(
        a.entries[0].is_zero(),
        "commutative image of the commutator"
    );
    assert_eq!(a.entries[1].to_string_with(&p.symbols), "2*a*b^2");
    // The printed program reads back as the same ordered system.
    let again = ok(&lambdamat::lang::pretty::pretty(&p));
    assert_eq!(again, p);
}
