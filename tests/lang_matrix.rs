//! End-to-end tests of the matrix part of the language: valid files lower to
//! the expected polynomials, and every kind of bad input is reported with its
//! message and its line:column.

mod common;

use common::{errs, ok, single, summary};
use lambdamat::lang::{Directive, ErrorKind, Program};

fn entries(p: &Program, m: usize) -> Vec<String> {
    p.matrices[m]
        .entries
        .iter()
        .map(|e| e.to_string_with(&p.symbols))
        .collect()
}

#[test]
fn issue_example_parses_and_lowers() {
    let p = ok(
        "# comment\nvar x\nmatrix A = [\n  (-5)+(9)*x, x^2 - 1/3*x;\n  3/4, (x+1)^2\n]\nsmith A\n",
    );
    assert_eq!(p.symbols, ["x"]);
    assert_eq!(p.principal, None);
    assert_eq!((p.matrices[0].rows, p.matrices[0].cols), (2, 2));
    assert_eq!(p.matrices[0].name, "A");
    assert_eq!(
        entries(&p, 0),
        ["9*x - 5", "x^2 - 1/3*x", "3/4", "x^2 + 2*x + 1"]
    );
    assert_eq!(p.directives, [Directive::Smith { matrix: 0 }]);
}

#[test]
fn smith_peers_output_parses() {
    let src = include_str!("data/peers_3x3.lmx");
    let p = ok(src);
    assert_eq!((p.matrices[0].rows, p.matrices[0].cols), (3, 3));
    assert_eq!(entries(&p, 0)[0], "-7*x^2 + 9*x - 5");
    assert_eq!(entries(&p, 0)[8], "-9*x^2 + 8*x - 9");
}

#[test]
fn several_symbols_principal_and_check() {
    let p = ok("var k1, k2, k3, k4\nprincipal k4\n\
                matrix A = [k1, k2; k3, k4]\n\
                matrix U = [1, 0; -k3, k1]\n\
                matrix D = [1, 0; 0, k1*k4 - k2*k3]\n\
                matrix V = [1, -k2; 0, 1]\n\
                smith A\ncheck smith A with U, D, V\n");
    assert_eq!(p.symbols, ["k1", "k2", "k3", "k4"]);
    assert_eq!(p.principal, Some(3));
    assert_eq!(entries(&p, 2)[3], "k1*k4 - k2*k3");
    assert_eq!(
        p.directives,
        [
            Directive::Smith { matrix: 0 },
            Directive::CheckSmith {
                matrix: 0,
                u: 1,
                d: 2,
                v: 3
            }
        ]
    );
}

#[test]
fn shapes_trailing_semicolon_and_empty_matrix() {
    let p = ok("var x\nmatrix E = []\nmatrix R = [1, x, x^2;]\nmatrix C = [1; x; x^2]\n");
    let shape = |i: usize| {
        (
            p.matrices[i].rows,
            p.matrices[i].cols,
            p.matrices[i].entries.len(),
        )
    };
    assert_eq!(shape(0), (0, 0, 0));
    assert_eq!(shape(1), (1, 3, 3));
    assert_eq!(shape(2), (3, 1, 3));
}

#[test]
fn numbers_are_exact_and_precedence_is_usual() {
    let p = ok(
        "var x, y\nmatrix A = [0.25, 1.50*x, -x^2, 2^10, 2*-x, (x-y)*(x+y), 6/4/3, x - 1 - 1, -(x)^2]",
    );
    assert_eq!(
        entries(&p, 0),
        [
            "1/4",
            "3/2*x",
            "-x^2",
            "1024",
            "-2*x",
            "x^2 - y^2",
            "1/2",
            "x - 2",
            "-x^2"
        ]
    );
}

#[test]
fn division_by_constant_expression_and_parameters() {
    let p = ok("param h = 1/2\nvar x\nmatrix A = [x/(1+1), x/h, h*x^2]");
    assert_eq!(entries(&p, 0), ["1/2*x", "2*x", "1/2*x^2"]);
}

#[test]
fn unicode_names_are_allowed() {
    let p = ok("var κ1, κ2\nmatrix A = [κ1*κ2]");
    assert_eq!(entries(&p, 0), ["κ1*κ2"]);
}

// ───────────────────────────── errors ─────────────────────────────

#[test]
fn syntax_error_missing_row_separator() {
    let (k, m, l, c) = single("var x\nmatrix A = [1, 2\n  3, 4]\n");
    assert_eq!(k, ErrorKind::Syntax);
    assert_eq!(
        m,
        "expected an operator (`+`, `-`, `*`, `/`, `^`), `,`, `;` or `]`, found the number `3`"
    );
    assert_eq!((l, c), (3, 3));
}

#[test]
fn syntax_error_unknown_statement() {
    let (k, m, l, c) = single("var x\nfoo\n");
    assert_eq!(k, ErrorKind::Syntax);
    assert!(m.starts_with("expected a statement (`var`"), "{m}");
    assert!(m.ends_with("found `foo`"), "{m}");
    assert_eq!((l, c), (2, 1));
}

#[test]
fn syntax_error_missing_operand() {
    let (k, m, l, c) = single("var x\nmatrix A = [x + ]\n");
    assert_eq!(k, ErrorKind::Syntax);
    assert_eq!(m, "expected an expression, found `]`");
    assert_eq!((l, c), (2, 17));
}

#[test]
fn syntax_error_unclosed_bracket_at_end_of_file() {
    let (k, m, l, c) = single("var x\nmatrix A = [x, 1\n");
    assert_eq!(k, ErrorKind::Syntax);
    assert!(m.ends_with("found the end of the file"), "{m}");
    assert!(m.contains("`]`"), "{m}");
    assert_eq!((l, c), (3, 1));
}

#[test]
fn syntax_error_labels_are_short() {
    let r = errs("var x y\n").render();
    assert!(r.contains("found `y`\n --> t.lmx:1:7\n"), "{r}");
    assert!(
        r.contains("  |       ^ expected a statement or `,`\n"),
        "{r}"
    );
}

#[test]
fn syntax_error_check_without_with() {
    let (k, m, l, c) = single("check smith A U, D, V");
    assert_eq!(k, ErrorKind::Syntax);
    assert_eq!(m, "expected `with`, found `U`");
    assert_eq!((l, c), (1, 15));
}

#[test]
fn undeclared_symbol() {
    let (k, m, l, c) = single("var x\nmatrix A = [x, y^2]\n");
    assert_eq!(k, ErrorKind::Undeclared);
    assert_eq!(m, "undeclared symbol `y`");
    assert_eq!((l, c), (2, 16));
}

#[test]
fn division_by_zero() {
    let (k, m, l, c) = single("var x\nmatrix A = [1, x/(2-2)]\n");
    assert_eq!(k, ErrorKind::DivisionByZero);
    assert_eq!(m, "division by zero");
    assert_eq!((l, c), (2, 18));
}

#[test]
fn division_by_non_constant() {
    let (k, m, l, c) = single("var x\nmatrix A = [1/(x+1)]\n");
    assert_eq!(k, ErrorKind::NonPolynomial);
    assert_eq!(
        m,
        "division by a non-constant: matrix entries must be polynomials"
    );
    assert_eq!((l, c), (2, 15));
}

#[test]
fn negative_and_fractional_exponents() {
    let all = summary("var x\nmatrix A = [x^-1, x^0.5, x^(1/2), x^x]\n");
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::BadExponent,
                "negative exponent: the result would not be a polynomial",
                2,
                15
            ),
            (
                ErrorKind::BadExponent,
                "fractional exponent 1/2: the result would not be a polynomial",
                2,
                21
            ),
            (
                ErrorKind::BadExponent,
                "fractional exponent: the result would not be a polynomial",
                2,
                28
            ),
            (
                ErrorKind::BadExponent,
                "the exponent must be a non-negative integer literal",
                2,
                37
            ),
        ]
    );
}

#[test]
fn huge_exponent_is_refused_not_computed() {
    let (k, m, _, _) = single("var x\nmatrix A = [(x+1)^100000]\n");
    assert_eq!(k, ErrorKind::BadExponent);
    assert!(m.contains("too large"), "{m}");
    let (k, m, _, _) = single("var x\nmatrix A = [((x+1)^1000)^1000]\n");
    assert_eq!(k, ErrorKind::BadExponent);
    assert!(m.contains("degree"), "{m}");
}

#[test]
fn ragged_rows() {
    let (k, m, l, c) = single("var x\nmatrix A = [\n  1, 2;\n  3, 4, 5\n]\n");
    assert_eq!(k, ErrorKind::RaggedRows);
    assert_eq!(m, "row 2 has 3 entries, but row 1 has 2 entries");
    let (_, m, _, _) = single("matrix A = [1, 2; 3]");
    assert_eq!(m, "row 2 has 1 entry, but row 1 has 2 entries");
    assert_eq!((l, c), (4, 3));
}

#[test]
fn duplicate_names_point_at_both() {
    let e = errs("var x, y\nmatrix x = [1]\nvar y\n");
    assert_eq!(e.len(), 2);
    let r = e.render();
    assert!(
        r.contains("error: `x` is defined more than once\n --> t.lmx:2:8"),
        "{r}"
    );
    assert!(r.contains("first defined here as a symbol"), "{r}");
    assert!(r.contains(" --> t.lmx:1:5"), "{r}");
    assert!(
        r.contains("error: `y` is defined more than once\n --> t.lmx:3:5"),
        "{r}"
    );
}

#[test]
fn unknown_matrix_in_smith_and_check() {
    let all = summary("var x\nmatrix A = [x]\nsmith B\ncheck smith A with U, A, x\n");
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (ErrorKind::UnknownMatrix, "unknown matrix `B`", 3, 7),
            (ErrorKind::UnknownMatrix, "unknown matrix `U`", 4, 20),
            (
                ErrorKind::UnknownMatrix,
                "`x` is a symbol, not a matrix",
                4,
                26
            ),
        ]
    );
}

#[test]
fn undeclared_principal() {
    let (k, m, l, c) = single("var k1, k2\nprincipal k4\n");
    assert_eq!(k, ErrorKind::BadPrincipal);
    assert_eq!(m, "the principal symbol `k4` is not declared");
    assert_eq!((l, c), (2, 11));
}

#[test]
fn keyword_used_as_a_name() {
    let (k, m, l, c) = single("var k1, smith\n");
    assert_eq!(k, ErrorKind::KeywordAsName);
    assert_eq!(
        m,
        "`smith` is a reserved keyword and cannot be used as a name"
    );
    assert_eq!((l, c), (1, 9));
    let (k, _, l, c) = single("var x\nmatrix var = [x]\n");
    assert_eq!(k, ErrorKind::KeywordAsName);
    assert_eq!((l, c), (2, 8));
    let (k, m, l, c) = single("var x\nmatrix A = [x*pi + int]\n");
    assert_eq!(k, ErrorKind::KeywordAsName);
    assert_eq!(
        m,
        "expected an expression, found the keyword `int` (keywords cannot be used as names)"
    );
    assert_eq!((l, c), (2, 20));
    // A missing operand before the next statement is caught at its keyword.
    let (k, _, l, c) = single("param a = 1 +\nvar x\n");
    assert_eq!((k, l, c), (ErrorKind::KeywordAsName, 2, 1));
}

#[test]
fn non_polynomial_entries() {
    let all = summary("var x\nmatrix A = [sqrt(x), pi*x]\n");
    let kinds: Vec<_> = all.iter().map(|(k, _, l, c)| (*k, *l, *c)).collect();
    assert_eq!(
        kinds,
        [
            (ErrorKind::NonPolynomial, 2, 13),
            (ErrorKind::NonPolynomial, 2, 22)
        ]
    );
}

#[test]
fn every_error_is_reported_at_once() {
    let src = "var x, x\nprincipal z\nmatrix A = [y, 1/0; 1]\nsmith B\n";
    let all = summary(src);
    let got: Vec<_> = all.iter().map(|(k, _, l, c)| (*k, *l, *c)).collect();
    assert_eq!(
        got,
        [
            (ErrorKind::Duplicate, 1, 8),
            (ErrorKind::BadPrincipal, 2, 11),
            (ErrorKind::Undeclared, 3, 13),
            (ErrorKind::DivisionByZero, 3, 18),
            (ErrorKind::RaggedRows, 3, 21),
            (ErrorKind::UnknownMatrix, 4, 7),
        ]
    );
}

#[test]
fn render_is_plain_text_with_caret() {
    let e = errs("var x\nmatrix A = [x, 1/(x-1)]\n");
    assert_eq!(
        e.render(),
        "error: division by a non-constant: matrix entries must be polynomials\n --> t.lmx:2:18\n  |\n2 | matrix A = [x, 1/(x-1)]\n  |                  ^^^^^ not a constant\n  = help: divide only by nonzero numbers or parameters, e.g. `x/3`\n"
    );
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    let open = "(".repeat(50_000);
    let close = ")".repeat(50_000);
    let (k, _, l, _) = single(&format!("var x\nmatrix A = [{open}x{close}]"));
    assert_eq!((k, l), (ErrorKind::TooDeep, 2));
    let src = format!("var x\nmatrix A = [{}x]", "-".repeat(100_000));
    assert_eq!(single(&src).0, ErrorKind::TooDeep);
    let src = format!("var x\nmatrix A = [x{}]", "^1".repeat(100_000));
    assert_eq!(single(&src).0, ErrorKind::TooDeep);
    let long_sum = vec!["x"; 50_000].join("+");
    let src = format!("var x\nmatrix A = [{long_sum}]");
    assert_eq!(single(&src).0, ErrorKind::TooDeep);
}

#[test]
fn deep_but_allowed_input_is_fine_on_any_thread() {
    // Run on a small stack: the front end must not depend on the caller's.
    let worker = std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(|| {
            let long_sum = vec!["x"; 15_000].join("+");
            let p = ok(&format!("var x\nmatrix A = [{long_sum}]"));
            assert_eq!(entries(&p, 0), ["15000*x"]);
            let nested = format!("{}x{}", "(".repeat(450), ")".repeat(450));
            let p = ok(&format!("var x\nmatrix A = [{nested}^2]"));
            assert_eq!(entries(&p, 0), ["x^2"]);
            let negs = format!("{}x", "-".repeat(4000));
            let p = ok(&format!("var x\nmatrix A = [{negs}]"));
            assert_eq!(entries(&p, 0), ["x"]);
        })
        .expect("spawn");
    assert!(worker.join().is_ok());
}

#[test]
fn seed_example_checks_the_papers_decomposition() {
    let p = ok(include_str!("../examples/seed_lambda.lmx"));
    let names: Vec<&str> = p.matrices.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names, ["A", "U", "D", "V"]);
    assert_eq!(entries(&p, 2), ["k4^2", "0", "0", "k1*k4^2 - k2*k3*k4"]);
    assert_eq!(
        p.directives,
        [
            Directive::Smith { matrix: 0 },
            Directive::CheckSmith {
                matrix: 0,
                u: 1,
                d: 2,
                v: 3
            }
        ]
    );
    let p = ok(include_str!("../examples/matrix_qx.lmx"));
    assert_eq!(
        entries(&p, 0),
        ["9*x - 5", "x^2 - 1/3*x", "3/4", "x^2 + 2*x + 1"]
    );
}

#[test]
fn check_smith_shapes_must_fit() {
    let all = summary(
        "matrix A = [1, 2, 3; 4, 5, 6]\nmatrix U = [1, 0; 0, 1]\nmatrix D = [1, 0; 0, 1]\n\
         matrix V = [1, 0; 0, 1]\ncheck smith A with U, D, V\n",
    );
    let got: Vec<_> = all
        .iter()
        .map(|(k, m, l, c)| (*k, m.as_str(), *l, *c))
        .collect();
    assert_eq!(
        got,
        [
            (
                ErrorKind::Shape,
                "`D` is 2×2, but it must be 2×3: D = U·A·V has the shape of A and A is 2×3",
                5,
                23
            ),
            (
                ErrorKind::Shape,
                "`V` is 2×2, but it must be 3×3: V multiplies A on the right and A is 2×3",
                5,
                26
            ),
        ]
    );
}
