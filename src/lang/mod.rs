//! The front end: source text → pest parse tree → spanned AST → validated
//! program → lowered algebraic objects. This is the only layer that knows
//! about source positions (line:column) and user-facing names; it hands the
//! algebra plain polynomials indexed by a symbol table and must not do any
//! algebra beyond building those polynomials.
//!
//! * `grammar/lambdamat.pest`: the syntax, the single reference;
//! * [`parser`]: text → spanned [`ast`] (pest + a Pratt parser);
//! * [`validate`], [`validate_system`]: every meaning error at once, each
//!   with a span, and the [`scope`] (name table, parameter values);
//! * [`diagnostics`]: [`LangErrors`], the only place that formats line:column;
//! * [`lower`]: validated AST → span-free [`Program`] (see [`crate::system`]);
//! * [`pretty`]: [`Program`] → source text that parses back to it;
//! * [`formula`]: one printed formula → the exact value it stands for
//!   (polynomial, rational function, ordered operator expression).
//!
//! # The language
//!
//! A file is a sequence of statements, each led by a keyword; newlines are
//! ordinary blanks and `#` comments run to the end of the line.
//!
//! ```text
//! var x                      # polynomial symbols, in order
//! var k1, k2, k3, k4
//! principal k4               # the symbol playing λ in the Smith form
//! matrix A = [ k1, k2;       # rows end with `;` (a trailing one is fine),
//!              k3, k4 ]      # entries are separated by `,`; `[]` is 0×0
//! smith A                    # Smith normal form of A
//! check smith A with U, D, V # check a given decomposition U·A·V = D
//!
//! param nu = 1/4             # exact rationals, from earlier parameters
//! param gamma = (1 - 2*nu)/(2 - 2*nu)
//! operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt      # ∫ₓ¹ t f(t)/√(t²−x²) dt
//! operator k2 = -gamma*int(0..1) dt + gamma*int(0..x) x/sqrt(x^2 - t^2) dt
//! operator m  = 2*id + x^2*id                       # 2f(x) + x² f(x)
//! unknown p, q               # unknown functions of x
//! equation k1 p + k2 q = 1   # operator polynomial applied to each unknown
//! equation k4*k1 p - (k2 + 1/2*k3) q = x*sqrt(1 - x^2)
//! solve for p
//! output P = pi/2 * int(0..1) x*p(x) dx             # a number from the solution
//! ```
//!
//! * Numbers are integers or exact decimals (`0.25` is 1/4); `a/b` is a
//!   rational. Operators `+ - * / ^` and unary minus have the usual
//!   precedence, `^` binding tightest and grouping to the right.
//! * In matrix entries and in the operator part of equations, names are
//!   symbols (`var`, `operator`) or parameters; division only by nonzero
//!   constants, exponents non-negative integer literals (so every entry is a
//!   polynomial).
//! * `int(a..b) K dt` integrates over `t`; the integrand `K` may use `x`
//!   and `t`, the function the operator is applied to is implied, and `K`
//!   may be left out when it is 1. Limits are constants or `x`. Outside
//!   integrals an operator may multiply its terms by functions of `x`; `id`
//!   is the identity. Functions: `sqrt`, `ln`, `abs`, `exp`; constant `pi`.
//! * In an equation a term is an operator product followed by the unknown it
//!   is applied to (`k4*k1 p`, or `k4*k1*p`); the right side is a function of
//!   `x`. There must be as many equations as unknowns.
//! * An output is a constant plus constant multiples of `int(a..b) w*p(x) dx`
//!   (or `… p(t) dt`) and of point values `p(1/2)`, linear in the unknowns,
//!   with constant limits and points; a side condition
//!   `condition int(-1..1) f(t) dt = 1` fixes such a functional.
//! * Reserved words: see [`keywords::KEYWORDS`];
//!   `x` and `t` cannot name parameters, unknowns, operators or outputs.
//! * Limits that keep every pass safe: brackets nest at most
//!   [`parser::MAX_NESTING`] deep, expression trees at most
//!   [`parser::MAX_DEPTH`] deep (a sum of that many terms in one entry),
//!   exponents at most [`validate::MAX_EXPONENT`], entries of degree at most
//!   [`validate::MAX_DEGREE`].

pub mod ast;
pub mod diagnostics;
pub mod error;
pub mod formula;
pub mod keywords;
pub mod lower;
pub mod lower_contact;
pub mod parser;
pub mod pretty;
pub mod scope;
mod scalar_ends;
pub mod validate;
pub mod validate_contact;
pub mod validate_system;

pub use crate::system::{Directive, MatrixDef, Program};
pub use diagnostics::LangErrors;
pub use error::{ErrorKind, LangError};

/// Parses, validates and lowers a whole file.
///
/// On failure, returns the syntax error, or every validation error, each
/// with its position in `filename`.
///
/// ```
/// let src = "var x\nmatrix A = [x, 1/2; 0.25, (x+1)^2]\nsmith A\n";
/// let p = lambdamat::lang::parse_program(src, "a.lmx").expect("valid");
/// assert_eq!(p.symbols, ["x"]);
/// assert_eq!((p.matrices[0].rows, p.matrices[0].cols), (2, 2));
/// assert_eq!(p.matrices[0].entries[3].to_string_with(&p.symbols), "x^2 + 2*x + 1");
///
/// let err = lambdamat::lang::parse_program("var x\nmatrix A = [y]", "a.lmx").unwrap_err();
/// assert!(err.render().contains("a.lmx:2:13"));
/// ```
///
/// Input deeper than [`HERE_MAX_LEVELS`] by [`depth_bound`], or a caller's
/// thread without room for its levels, is handed to a helper thread with a
/// [`STACK_SIZE`] stack (as rustc does), so that the recursive passes over
/// deeply nested input stay far from the end of the caller's stack,
/// whatever thread the caller is on. Small shallow files (every example and
/// benchmark matrix of degree up to 3) are done on the caller's thread:
/// starting the helper thread cost more than parsing them.
#[cfg(any(test, feature = "internals"))]
pub fn parse_program(src: &str, filename: &str) -> Result<Program, LangErrors> {
    parse_program_with(src, filename, &[])
}

/// `src` without a leading UTF-8 byte-order mark (editors on some systems
/// write one); spans are offsets into the text after it.
pub fn strip_bom(src: &str) -> &str {
    src.strip_prefix('\u{feff}').unwrap_or(src)
}

/// Stack size of the front end's worker thread: ample for
/// [`parser::MAX_NESTING`] brackets and [`parser::MAX_DEPTH`] levels even in
/// unoptimised builds (the memory is reserved, not used, until needed).
pub const STACK_SIZE: usize = 256 << 20;

/// [`parse_program`] with parameter overrides (`--set nu=1/4`): each named
/// parameter's definition is replaced by the exact value before
/// validation, so everything computed from it follows. Names that are not
/// parameters of the file are ignored here (the caller checks them with
/// [`param_names`]).
///
/// ```
/// use num_rational::BigRational;
/// let src = "param a = 1\nparam b = 2*a\nvar k\nmatrix A = [b*k]";
/// let set = [("a".to_string(), BigRational::new(3.into(), 2.into()))];
/// let p = lambdamat::lang::parse_program_with(src, "a.lmx", &set).expect("valid");
/// assert_eq!(p.params[1].value.to_string(), "3");
/// ```
pub fn parse_program_with(
    src: &str,
    filename: &str,
    sets: &[(String, num_rational::BigRational)],
) -> Result<Program, LangErrors> {
    let src = strip_bom(src);
    if fits_here(src) {
        return parse_program_here(src, filename, sets);
    }
    std::thread::scope(|s| {
        let worker = std::thread::Builder::new()
            .name("lambdamat-front-end".into())
            .stack_size(STACK_SIZE)
            .spawn_scoped(s, || parse_program_here(src, filename, sets));
        match worker {
            Ok(handle) => handle.join().unwrap_or_else(|_| {
                Err(LangErrors::new(
                    filename,
                    src,
                    vec![LangError::new(
                        ErrorKind::Syntax,
                        "internal error in the front end",
                        ast::Span::default(),
                        "while reading this file",
                    )],
                ))
            }),
            // No thread available: do the work here.
            Err(_) => parse_program_here(src, filename, sets),
        }
    })
}

/// Most levels ([`depth_bound`]) an input may have for the front end to run
/// on the caller's thread (deeper input goes to the [`STACK_SIZE`] thread).
pub const HERE_MAX_LEVELS: usize = 128;

/// Stack bytes budgeted per level for the front end on the caller's thread,
/// and on top of them. At [`HERE_MAX_LEVELS`] levels of brackets (the
/// deepest shape) the whole front end ran in a 0.66 MiB stack when
/// optimised and in 1.6 MiB unoptimised (pest's own guard included: it
/// refuses to go on with less than 64 KiB left); the budget is 3.3 MiB. The
/// test `the_stack_budget_covers_the_deepest_input_run_here` runs every deep
/// shape within it.
const HERE_STACK_PER_LEVEL: usize = 24 << 10;
const HERE_STACK_BASE: usize = 256 << 10;

/// Whether [`parse_program_with`] can do its work on the caller's thread:
/// the input is at most [`HERE_MAX_LEVELS`] deep by [`depth_bound`] and the
/// thread has room for that many levels. Spawning the big-stack thread
/// costs more than parsing a small file.
fn fits_here(src: &str) -> bool {
    let levels = depth_bound(src);
    levels <= HERE_MAX_LEVELS
        && stacker::remaining_stack()
            .is_some_and(|room| room >= HERE_STACK_BASE + levels * HERE_STACK_PER_LEVEL)
}

/// An upper bound on how deep any pass of the front end recurses for `src`,
/// in levels: the most `(`, `+`, `-`, `*`, `/` and `^` between two
/// characters that never occur inside an expression (`;` `=` `[` `]` `~`,
/// and `,` outside brackets; a `,` inside brackets, which may separate a
/// call's arguments, counts three levels), comments left out. Every node of an expression tree that has
/// children (a sum, product, power, negation, call or integral) and every
/// bracket the parser descends into is one of those characters, so an
/// expression's tree depth and bracket nesting are both at most the count of
/// the stretch it lies in.
pub fn depth_bound(src: &str) -> usize {
    let (mut most, mut here, mut in_comment) = (0usize, 0usize, false);
    let mut open = 0usize;
    for b in src.bytes() {
        match b {
            b'\n' => in_comment = false,
            _ if in_comment => {}
            b'#' => in_comment = true,
            b'(' | b'+' | b'-' | b'*' | b'/' | b'^' => {
                open += usize::from(b == b'(');
                here += 1;
                most = most.max(here);
            }
            b')' => open = open.saturating_sub(1),
            // A `,` inside brackets may separate a call's arguments
            // (`beta(a, b)`, written out three levels deeper): no reset.
            b',' if open > 0 => {
                here += 3;
                most = most.max(here);
            }
            b',' | b';' | b'=' | b'[' | b']' | b'~' => here = 0,
            _ => {}
        }
    }
    most
}

/// The names of the parameters a file defines (for checking `--set`).
pub fn param_names(file: &ast::File) -> Vec<String> {
    file.statements
        .iter()
        .filter_map(|s| match &s.kind {
            ast::Stmt::Param { name, .. } => Some(name.name.clone()),
            _ => None,
        })
        .collect()
}

/// [`parse_program_with`] on the current thread.
fn parse_program_here(
    src: &str,
    filename: &str,
    sets: &[(String, num_rational::BigRational)],
) -> Result<Program, LangErrors> {
    let mut file = parser::parse_file(src).map_err(|e| LangErrors::new(filename, src, vec![e]))?;
    for st in &mut file.statements {
        if let ast::Stmt::Param { name, value } = &mut st.kind
            && let Some((_, v)) = sets.iter().rev().find(|(n, _)| *n == name.name)
        {
            let span = value.span;
            *value = ast::Expr {
                kind: ast::ExprKind::Number(v.clone()),
                span,
            };
        }
    }
    scalar_ends::rewrite(&mut file);
    let checked = validate::validate(&file).map_err(|errs| LangErrors::new(filename, src, errs))?;
    lower::lower(&file, &checked).map_err(|e| LangErrors::new(filename, src, vec![e]))
}

/// Parses `src` into its spanned AST (syntax only, no validation), on the
/// caller's thread.
pub fn parse_ast(src: &str, filename: &str) -> Result<ast::File, LangErrors> {
    let src = strip_bom(src);
    parser::parse_file(src).map_err(|e| LangErrors::new(filename, src, vec![e]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Inputs of exactly `levels` levels, one of each shape that makes a
    /// pass recurse: brackets, calls, negations, long sums, powers,
    /// integrals, equation sides.
    fn deep_shapes(n: usize) -> Vec<String> {
        vec![
            format!("var x\nmatrix A = [{}x{}]", "(".repeat(n), ")".repeat(n)),
            format!("var x\nmatrix A = [{}x]", "-".repeat(n)),
            format!(
                "var x\nmatrix A = [{}x{}]",
                "-(".repeat(n / 2),
                ")".repeat(n / 2)
            ),
            format!("var x\nmatrix A = [{}]", vec!["x"; n + 1].join("+")),
            format!("var x\nmatrix A = [x{}]", "^1".repeat(n)),
            format!("param a = {}1{}", "abs(".repeat(n), ")".repeat(n)),
            format!("param a = {}1{}", "(".repeat(n), ")".repeat(n)),
            format!(
                "operator k = id\nunknown p\nequation {}k{} p = {}x{}",
                "(".repeat(n),
                ")".repeat(n),
                "sqrt(".repeat(n),
                ")".repeat(n)
            ),
            format!(
                "var x\nmatrix A = [{}x{} +]",
                "(".repeat(n - 1),
                ")".repeat(n - 1)
            ),
            format!(
                "operator k = {}1{}\nunknown p\nequation k p = 1",
                "int(0..1) ".repeat(n),
                " dt".repeat(n)
            ),
        ]
    }

    #[test]
    fn the_stack_budget_covers_the_deepest_input_run_here() {
        let n = HERE_MAX_LEVELS;
        let budget = HERE_STACK_BASE + n * HERE_STACK_PER_LEVEL;
        for src in deep_shapes(n) {
            assert_eq!(depth_bound(&src), n, "{src}");
            // A stack overflow here aborts the test binary: the budget is short.
            let worker = std::thread::Builder::new()
                .stack_size(budget)
                .spawn(move || {
                    let r = parse_program_here(&src, "t.lmx", &[]);
                    // Valid or refused for its meaning, never for the stack.
                    if let Err(e) = &r {
                        let text = e.render();
                        assert!(!text.contains("stack limit"), "{text}");
                        assert!(!text.contains("too deeply"), "{text}");
                    }
                })
                .expect("spawn");
            assert!(worker.join().is_ok());
        }
    }

    #[test]
    fn only_shallow_input_on_a_roomy_thread_runs_here() {
        let worker = std::thread::Builder::new()
            .stack_size(8 << 20)
            .spawn(|| {
                let small = "var x\nmatrix A = [(-5)+(9)*x, 1; x^2, 0]\nsmith A\n";
                assert!(fits_here(small));
                for src in deep_shapes(HERE_MAX_LEVELS + 2) {
                    assert!(depth_bound(&src) > HERE_MAX_LEVELS, "{src}");
                    assert!(!fits_here(&src), "{src}");
                }
            })
            .expect("spawn");
        assert!(worker.join().is_ok());
        // A thread without room for the levels hands the work on.
        let worker = std::thread::Builder::new()
            .stack_size(64 << 10)
            .spawn(|| {
                let src = "var x\nmatrix A = [x + 1]\n";
                assert!(!fits_here(src));
                assert!(parse_program(src, "t.lmx").is_ok());
            })
            .expect("spawn");
        assert!(worker.join().is_ok());
    }

    #[test]
    fn the_depth_bound_counts_within_expressions_only() {
        assert_eq!(
            depth_bound("var x\nmatrix A = [x+1, -(x); x^2*3-1, 1/2]"),
            3
        );
        // Separators reset the count; comments are left out, separators in
        // them included.
        assert_eq!(depth_bound("param a = 1+1+1 # ,;=\n +1"), 3);
        assert_eq!(depth_bound("param a = 1 # ((((((\n"), 0);
        // A `,` inside brackets may separate a call's arguments (`beta(a, b)`
        // is written out three levels deeper): it counts 3, also in an
        // interval that opens with `(` (an over-count, which is safe).
        assert_eq!(depth_bound("unknown p on (0, 1]\n"), 4);
        assert_eq!(depth_bound("param b = beta(1/2, 3/2)"), 6);
        assert_eq!(depth_bound("param κ = (1)"), 1);
    }
}
