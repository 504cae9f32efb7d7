//! Round trip: pretty-printing a parsed program and parsing the text again
//! gives the same program, for the shipped examples and for randomly
//! generated valid systems (matrices, parameters, operators, equations,
//! outputs, directives).

use lambdamat::lang::pretty::pretty;
use lambdamat::lang::{Program, parse_program};
use proptest::prelude::*;

fn parse(src: &str) -> Program {
    match parse_program(src, "gen.lmx") {
        Ok(p) => p,
        Err(e) => panic!("{}\n--- source ---\n{src}", e.render()),
    }
}

/// Parses `src`, prints it, parses the print: both programs must be equal,
/// and printing is idempotent.
fn round_trip(src: &str) {
    let p1 = parse(src);
    let text = pretty(&p1);
    let p2 = parse(&text);
    assert_eq!(p1, p2, "\n--- source ---\n{src}\n--- printed ---\n{text}");
    assert_eq!(pretty(&p2), text);
}

#[test]
fn examples_round_trip() {
    round_trip(include_str!("../examples/hertz_stick.lmx"));
    round_trip(include_str!("data/peers_3x3.lmx"));
    round_trip(include_str!("../examples/seed_lambda.lmx"));
    round_trip(include_str!("../examples/matrix_qx.lmx"));
    round_trip(include_str!("../examples/generic3.lmx"));
    round_trip(include_str!("../examples/singular.lmx"));
    round_trip(
        "var k1, k2, k3, k4\nprincipal k4\nmatrix A = [k1, k2; k3, k4]\nmatrix E = []\nsmith A\ncheck smith A with A, A, A\n",
    );
}

#[test]
fn printed_hertz_is_golden() {
    let p = parse(include_str!("../examples/hertz_stick.lmx"));
    assert_eq!(
        pretty(&p),
        "param nu = 1/4\n\
         param gamma = 1/3\n\
         operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\n\
         operator k2 = int(0..1) -1/3 dt + int(0..x) 1/3*(x/sqrt(x^2 - t^2)) dt\n\
         operator k3 = int(0..x) 1/3*(t/sqrt(x^2 - t^2)) dt\n\
         operator k4 = int(x..1) -(x/sqrt(t^2 - x^2)) dt\n\
         principal k4\n\
         unknown p, q\n\
         equation k1 p + k2 q = 1\n\
         equation k3 p + k4 q = 0\n\
         output P = pi/2*int(0..1) x*p(x) dx\n\
         solve for p\n"
    );
}

#[test]
fn awkward_shapes_round_trip() {
    round_trip(
        "operator a = -(2*id - (x + 1)*id) + pi*id\nunknown u, v\n\
         equation (a - a) u + 0 v = -(1)\nequation a*a v - u = x\n\
         output P = 1 + (pi + 2*int(0..1) u(x) dx) - (int(-1/2..1) -t*v(t) dt)/3 - -2\n",
    );
}

#[test]
fn side_conditions_point_values_and_functions_round_trip() {
    round_trip(
        "operator h = 1/pi*pv int(-1..1) sin(t)*cosh(x)/(t - x) dt\nunknown f on [-1, 1]\n\
         equation h f = tanh(x) + acot(x)\n\
         condition int(-1..1) f(t) dt - 2*f(1/2) + 1 = asin(1/2)\ncondition f(0) = 0\n\
         output V = f(1/2) - 3*int(0..1) x*f(x) dx\n",
    );
}

// ───────────────────────────── generators ─────────────────────────────

/// A small rational literal, possibly a fraction or a decimal.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        (0u32..20).prop_map(|n| n.to_string()),
        (1u32..20, 1u32..9).prop_map(|(a, b)| format!("{a}/{b}")),
        (0u32..100).prop_map(|n| format!("0.{n:02}")),
    ]
}

/// A real expression over the given variables and parameters (never a
/// division by something that can be zero).
fn real(vars: Vec<&'static str>, params: Vec<String>) -> impl Strategy<Value = String> {
    let divisor = if vars.contains(&"x") { "x^2" } else { "pi" };
    let mut leaves: Vec<BoxedStrategy<String>> =
        vec![number().boxed(), Just("pi".to_string()).boxed()];
    for v in vars {
        leaves.push(Just(v.to_string()).boxed());
    }
    if !params.is_empty() {
        leaves.push(prop::sample::select(params).boxed());
    }
    let leaf = prop::strategy::Union::new(leaves);
    leaf.prop_recursive(4, 24, 2, move |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("{a} + {b}")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a}) - ({b})")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a})*({b})")),
            (inner.clone(), 1u32..9).prop_map(move |(a, b)| format!("({a})/(1 + {b}*{divisor})")),
            inner.clone().prop_map(|a| format!("-({a})")),
            (inner.clone(), 0u32..4).prop_map(|(a, n)| format!("({a})^{n}")),
            inner.clone().prop_map(|a| format!("({a})^(-1/2)")),
            (
                prop::sample::select(vec!["sqrt", "ln", "abs", "exp"]),
                inner
            )
                .prop_map(|(f, a)| format!("{f}({a})")),
        ]
    })
}

/// A polynomial over the given symbols.
fn poly(symbols: Vec<String>) -> impl Strategy<Value = String> {
    let leaf = prop_oneof![number(), prop::sample::select(symbols)];
    leaf.prop_recursive(3, 12, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("{a} + {b}")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a}) - ({b})")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a})*({b})")),
            (inner.clone(), 0u32..3).prop_map(|(a, n)| format!("({a})^{n}")),
            (inner, 1u32..5).prop_map(|(a, n)| format!("({a})/{n}")),
        ]
    })
}

fn limit() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("x".to_string()),
        number(),
        number().prop_map(|n| format!("-{n}"))
    ]
}

/// One operator term.
fn op_term(params: Vec<String>) -> impl Strategy<Value = String> {
    prop_oneof![
        Just("id".to_string()),
        number().prop_map(|c| format!("{c}*id")),
        real(vec!["x"], params.clone()).prop_map(|f| format!("({f})*id")),
        (limit(), limit(), real(vec!["x", "t"], params.clone()))
            .prop_map(|(a, b, k)| format!("int({a}..{b}) {k} dt")),
        (real(vec!["x"], params.clone()), limit(), limit())
            .prop_map(|(f, a, b)| format!("({f})*int({a}..{b}) dt")),
        (limit(), limit(), real(vec!["x", "t"], params))
            .prop_map(|(a, b, k)| format!("-int({a}..{b}) {k} dt/3")),
    ]
}

/// A whole valid file.
fn system() -> impl Strategy<Value = String> {
    (0usize..3, 1usize..4, 0usize..3, 1usize..4).prop_flat_map(|(np, nops, nvars, nunk)| {
        let params: Vec<String> = (0..np).map(|i| format!("g{i}")).collect();
        let ops: Vec<String> = (0..nops).map(|i| format!("k{i}")).collect();
        let vars: Vec<String> = (0..nvars).map(|i| format!("s{i}")).collect();
        let unknowns: Vec<String> = (0..nunk).map(|i| format!("u{i}")).collect();
        let mut symbols = ops.clone();
        symbols.extend(vars.iter().cloned());
        let param_defs = prop::collection::vec(number(), np);
        let op_defs =
            prop::collection::vec(prop::collection::vec(op_term(params.clone()), 1..4), nops);
        let equations = prop::collection::vec(
            (
                prop::collection::vec(
                    (
                        poly(symbols.clone()),
                        prop::sample::select(unknowns.clone()),
                    ),
                    1..4,
                ),
                real(vec!["x"], params.clone()),
            ),
            nunk,
        );
        let matrix = prop::option::of((1usize..3, 1usize..3).prop_flat_map({
            let symbols = symbols.clone();
            move |(r, c)| {
                prop::collection::vec(poly(symbols.clone()), r * c).prop_map(move |e| (r, c, e))
            }
        }));
        let output = prop::option::of((
            real(vec![], params.clone()),
            real(vec!["x"], params.clone()),
            prop::sample::select(unknowns.clone()),
        ));
        let principal = prop::option::of(prop::sample::select(symbols.clone()));
        (
            param_defs,
            op_defs,
            equations,
            matrix,
            output,
            principal,
            0usize..nunk,
        )
            .prop_map(move |(pv, od, eqs, mat, out, principal, solve)| {
                let mut s = String::new();
                for (name, v) in params.iter().zip(&pv) {
                    s += &format!("param {name} = {v}\n");
                }
                for (name, terms) in ops.iter().zip(&od) {
                    s += &format!("operator {name} = {}\n", terms.join(" + "));
                }
                if !vars.is_empty() {
                    s += &format!("var {}\n", vars.join(", "));
                }
                s += &format!("unknown {}\n", unknowns.join(", "));
                for (terms, rhs) in &eqs {
                    let lhs: Vec<String> =
                        terms.iter().map(|(p, u)| format!("({p}) {u}")).collect();
                    s += &format!("equation {} = {rhs}\n", lhs.join(" - "));
                }
                if let Some((r, c, e)) = &mat {
                    let rows: Vec<String> = e.chunks(*c).map(|row| row.join(", ")).collect();
                    s += &format!("matrix M = [{}]\nsmith M\n", rows.join(";\n"));
                    let _ = r;
                }
                if let Some((c, w, u)) = &out {
                    s += &format!(
                        "output P = {c} + ({c})*int(0..1) ({w})*{u}(x) dx - int(0..1/2) {u}(t) dt\n"
                    );
                }
                if let Some(p) = &principal {
                    s += &format!("principal {p}\n");
                }
                s += &format!("solve for {}\n", unknowns[solve]);
                s
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// A generated output whose constant or weight is not a finite double
    /// (`sqrt` or `ln` of a negative value) is refused by the language, not
    /// printed: such draws are rejected, and proptest fails the test if it
    /// rejects too many of them to reach its 300 cases.
    #[test]
    fn generated_systems_round_trip(src in system()) {
        let refused = parse_program(&src, "gen.lmx")
            .err()
            .is_some_and(|e| e.render().contains("not a finite number"));
        prop_assume!(!refused);
        round_trip(&src);
    }
}

const SEEDS: &[&str] = &[
    include_str!("../examples/hertz_stick.lmx"),
    include_str!("../examples/hertz_manufactured.lmx"),
    include_str!("../examples/seed_lambda.lmx"),
    include_str!("../examples/generic3.lmx"),
];

const PIECES: &[&str] = &[
    "(", ")", "+", "-", "*", "/", "^2", "x", "t", "k1", "0", "1", "1/3", "0.5", "id", "pi",
    "sqrt(x)", "p(x)", "\n", "-1/2", "^(-1/2)", "2*", "k2 ", "q ",
];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    /// Randomly edited examples: whenever the edit is still a valid file,
    /// it must round-trip too.
    #[test]
    fn edited_examples_round_trip_when_valid(
        which in 0..SEEDS.len(),
        edits in prop::collection::vec((any::<usize>(), prop::sample::select(PIECES), any::<bool>()), 1..4),
    ) {
        let mut s: Vec<char> = SEEDS[which].chars().collect();
        for (at, piece, replace) in edits {
            let at = at % s.len().max(1);
            let end = if replace { (at + 1).min(s.len()) } else { at };
            s.splice(at..end, piece.chars());
        }
        let src: String = s.into_iter().collect();
        if parse_program(&src, "edit.lmx").is_ok() {
            round_trip(&src);
        }
    }
}
