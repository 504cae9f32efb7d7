//! Code generation (`lambdamat codegen`): a standalone Rust module that
//! solves one language system. Kernels, multipliers, right sides and
//! output weights become plain Rust functions; `system()` puts them into a
//! [`CompiledSystem`] (the operator system), `input()` adds the file's
//! breakpoints, scalars, relations and singular terms, and `main()` solves
//! it through `lambdamat::standalone::split_solver_main` (the library's
//! one solver: assembly, refinement and solves) and prints the same report
//! as `lambdamat solve`.
//!
//! The generated code and the in-process solver are built from the same
//! decisions ([`plan_operator`]'s term plans, the compiled system's
//! interval and target) and the printed expressions perform the same
//! floating-point operations as the closures (see [`rust`]), so the two
//! agree to rounding. This module owns the layout of the generated file;
//! it must not parse (it takes a [`Program`]) or solve.
pub mod rust;
mod split;

use std::collections::HashSet;
use std::fmt::Write;

use crate::numeric::Limits;
use crate::numeric::Singularity;
use crate::plan::PlanError;
use crate::plan::compiled::{CompiledSystem, OutputTerm};
use crate::plan::operators::{KernelPlan, TermPlan, plan_operator};
use crate::system::{Expr, FunctionalTerm, Program};

use rust::{Body, literal};

/// Where the generated code came from, for its header.
#[derive(Debug, Clone)]
pub struct Provenance {
    /// The source file as given on the command line.
    pub source: String,
    /// The command that regenerates the file.
    pub command: String,
}

/// Rust source of a solver for `prog`, solving for `target` (an unknown's
/// name; default the file's `solve for`, else the first unknown). Fails
/// exactly where `lambdamat solve` would refuse the system before any
/// numerics (unsupported kernels, `var` symbols, shape).
pub fn solver_source(
    prog: &Program,
    target: Option<&str>,
    from: &Provenance,
) -> Result<String, PlanError> {
    split::split_solver_source(prog, target, from)
}

/// The compiled system of `prog` and the Rust code that builds it: one
/// function per kernel, multiplier, right side and output weight, and
/// `system()`.
fn system_code(
    prog: &Program,
    target: Option<&str>,
) -> Result<(CompiledSystem, String), PlanError> {
    let sys = CompiledSystem::from_program(prog, target)?;
    let mut names = Names::default();
    let mut fns = String::new();
    let mut setup = String::new();

    // Operators: one function per kernel and multiplier.
    let mut op_vars = Vec::new();
    for (s, sym) in prog.symbols.iter().enumerate() {
        if sys.operators[s].is_none() {
            op_vars.push(None);
            continue;
        }
        let def = prog
            .operator(s)
            .ok_or_else(|| PlanError::Invalid(format!("operator {sym} has no definition")))?;
        let plans = plan_operator(def, sym, sys.domain)?;
        let var = names.fresh(&format!("op_{sym}"));
        let mut pieces = Vec::new();
        let multiple = plans.len() > 1;
        for (k, plan) in plans.iter().enumerate() {
            let suffix = if multiple {
                format!("_{}", k + 1)
            } else {
                String::new()
            };
            pieces.push(match plan {
                TermPlan::Identity => "Operator::identity()".to_string(),
                TermPlan::Scalar(c) => format!("Operator::identity().scaled({})", literal(*c)),
                TermPlan::Multiply(m) => {
                    let f = names.fresh(&format!("multiplier_{sym}{suffix}"));
                    let doc = format!("Multiplier of operator `{sym}`: `{m}`.");
                    function_x(&mut fns, &f, &doc, m);
                    format!("Operator::multiply({f})")
                }
                TermPlan::Integral {
                    limits,
                    sign,
                    kernel,
                    written,
                } => {
                    let f = names.fresh(&format!("kernel_{sym}{suffix}"));
                    kernel_fn(&mut fns, &f, sym, written, kernel);
                    let singularity = match kernel {
                        KernelPlan::Abel(_) => "AbelSqrt".to_string(),
                        KernelPlan::Smooth(_) => "Smooth".to_string(),
                        KernelPlan::Diagonal(s, _) | KernelPlan::Peaked(s, _) => {
                            format!("lambdamat::standalone::Singularity::{s:?}")
                        }
                    };
                    let lim = match limits {
                        Limits::Upper { b } => struct_lit("Upper", &[("b", literal(*b))], 4),
                        Limits::Lower { a } => struct_lit("Lower", &[("a", literal(*a))], 4),
                        Limits::Fixed { a, b } => struct_lit(
                            "Fixed",
                            &[("a", literal(*a)), ("b", literal(*b))],
                            4,
                        ),
                    };
                    let scaled = if *sign == 1.0 {
                        String::new()
                    } else {
                        format!(".scaled({})", literal(*sign))
                    };
                    let args = format!("{lim}, {singularity}, {f}");
                    let one = format!("    {var} = {var} + Operator::integral({args});");
                    if scaled.is_empty() && !lim.contains('\n') && args.len() <= 60 && one.len() <= 100 {
                        format!("Operator::integral({args})")
                    } else {
                        let args = format!("limits, {singularity}, {f}");
                        let call = format!("Operator::integral({args})");
                        // rustfmt puts the arguments one per line beyond 60
                        // columns of arguments or 100 of line.
                        let long = "    let term = ".len() + call.len() + 1 > 100;
                        let call = if args.len() > 60 || long {
                            format!(
                                "Operator::integral(\n        limits,\n        {singularity},\n        {f},\n    )"
                            )
                        } else {
                            call
                        };
                        format!("let limits = {lim};\n    let term = {call};\n    {var} = {var} + term{scaled};")
                    }
                }
            });
        }
        // The library sums the terms onto the zero operator in order.
        let _ = writeln!(setup, "    let mut {var} = Operator::zero();");
        for p in pieces {
            if p.starts_with("let limits") {
                let _ = writeln!(setup, "    {p}");
            } else {
                statement(&mut setup, &format!("{var} = {var} + "), &p, ";");
            }
        }
        op_vars.push(Some(var));
    }

    // Right sides.
    let mut rhs_fns = Vec::new();
    for (i, eq) in prog.equations.iter().enumerate() {
        let f = names.fresh(&format!("rhs_{}", i + 1));
        let doc = match &eq.written {
            Some(w) => format!(
                "Right side of equation {}: `{w}`; it uses an unknown scalar, so the operator system holds 0 here and the split input evaluates it.",
                i + 1
            ),
            None => format!("Right side of equation {}: `{}`.", i + 1, eq.rhs),
        };
        function_x(&mut fns, &f, &doc, &eq.rhs);
        rhs_fns.push(f);
    }

    // Output weights.
    let mut output_terms: Vec<Vec<String>> = Vec::new();
    for (o, compiled) in prog.outputs.iter().zip(&sys.outputs) {
        output_terms.push(functional_code(
            &mut names,
            &mut fns,
            &format!("output `{}`", o.name),
            &format!("weight_{}", o.name),
            &o.terms,
            &compiled.terms,
        )?);
    }
    // Side conditions: their weights, like outputs'.
    let mut condition_terms: Vec<Vec<String>> = Vec::new();
    for (k, (c, compiled)) in prog.side_conditions.iter().zip(&sys.conditions).enumerate() {
        condition_terms.push(functional_code(
            &mut names,
            &mut fns,
            &format!("side condition {}", k + 1),
            &format!("condition_weight_{}", k + 1),
            &c.terms,
            &compiled.terms,
        )?);
    }

    let mut code = fns;
    system_fn(
        &mut code,
        prog,
        &sys,
        &setup,
        &op_vars,
        &rhs_fns,
        (&output_terms, &condition_terms),
    );
    Ok((sys, code))
}

/// The header's first two lines, shared by both generators: what the file
/// solves and how to regenerate it.
pub(crate) fn provenance_lines(out: &mut String, from: &Provenance) {
    let _ = writeln!(
        out,
        "//! A solver for `{}`, written by lambdamat {} (`lambdamat codegen`).",
        from.source,
        env!("CARGO_PKG_VERSION")
    );
    let _ = writeln!(out, "//! Do not edit: regenerate with `{}`.", from.command);
}

/// The derivation of a file on one interval, for the reader of its
/// generated solver: the unknowns' interval, the target, the ordered
/// elimination with its pivots and the commutative eliminant, as
/// `lambdamat reduce` prints them (`--method ordered` and `commutative`
/// run exactly these pivots: `system()` embeds them).
pub(crate) fn one_interval_derivation(out: &mut String, prog: &Program, sys: &CompiledSystem) {
    let _ = writeln!(
        out,
        "//! Unknowns on [{}, {}]; eliminations solve for `{}`.",
        sys.domain.0, sys.domain.1, sys.unknowns[sys.target]
    );
    // The derivation the solver runs (`lambdamat reduce` prints the same
    // value), for the reader. Its eliminant is bounded before it is
    // expanded, so this never waits for a large one.
    let derived = sys
        .derivation()
        .ok()
        .and_then(|d| crate::reduce::reduce_with(prog, &d).ok());
    if let Some(r) = derived {
        let _ = writeln!(
            out,
            "//!\n//! Derived equations for `{}` (`lambdamat reduce`):\n//!",
            r.unknown
        );
        match &r.ordered {
            Ok(o) => {
                let _ = writeln!(
                    out,
                    "//! - ordered elimination, exact (`--method ordered`; gj is\n//!   the right side of equation j):\n//!   `{}`\n//!   pivots: {}",
                    o.text,
                    if o.pivots.is_empty() {
                        "none (one equation)".to_string()
                    } else {
                        o.pivots.join("; ")
                    }
                );
            }
            Err(e) => match &r.ordered_steps {
                Ok(st) => {
                    let pivots: Vec<String> = st
                        .steps
                        .iter()
                        .map(|s| format!("{} from equation {}", s.unknown, s.equation))
                        .collect();
                    let _ = writeln!(
                        out,
                        "//! - ordered elimination (`--method ordered`), in steps\n//!   with named intermediates ({e}; `lambdamat reduce` prints the\n//!   steps):\n//!   pivots: {}\n//!   result, equation {}: `{}`",
                        pivots.join("; "),
                        st.equation,
                        st.result.text
                    );
                }
                Err(_) => {
                    let _ = writeln!(out, "//! - ordered elimination: {e}");
                }
            },
        }
        match &r.eliminant_refused {
            None => {
                let pairs: Vec<String> = r
                    .commuted_pairs
                    .iter()
                    .map(|c| format!("({}, {})", c.pair[0], c.pair[1]))
                    .collect();
                let _ = writeln!(
                    out,
                    "//! - commutative eliminant, the seed's model (`--method commutative`):\n//!   `{}`\n//!   commuted pairs: {}",
                    r.eliminant_text(),
                    if pairs.is_empty() {
                        "none".to_string()
                    } else {
                        pairs.join(", ")
                    }
                );
            }
            Some(why) => {
                let _ = writeln!(out, "//! - commutative eliminant: {why}");
            }
        }
    }
    if !sys.conditions.is_empty() {
        let _ = writeln!(
            out,
            "//! - with its {} side condition(s) the system is solved as one least-squares\n//!   system of equations and conditions (`--method coupled`; the eliminations\n//!   refuse them).",
            sys.conditions.len()
        );
    }
}

/// The header's closing part, shared by both generators: `prog`
/// pretty-printed (parameters substituted) under "The {noun}", and the
/// lint allowance for bit-exact literals.
pub(crate) fn source_block(out: &mut String, prog: &Program, noun: &str) {
    let _ = write!(
        out,
        "//!\n//! The {noun} (parameters substituted):\n//!\n//! ```text\n"
    );
    for line in crate::lang::pretty::pretty(prog).lines() {
        if line.is_empty() {
            out.push_str("//!\n");
        } else {
            let _ = writeln!(out, "//! {line}");
        }
    }
    out.push_str("//! ```\n");
    out.push_str(
        "\n// Literals are printed to read back bit for bit; some may look like\n\
         // named constants without being them.\n\
         #![allow(clippy::approx_constant)]\n",
    );
}

/// The `use` lines for the names `code` mentions (outside comments), laid
/// out as `rustfmt` lays them out.
fn imports(code: &str) -> String {
    let lines: Vec<&str> = code
        .lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect();
    let mentions = |name: &str| {
        lines.iter().any(|l| {
            l.match_indices(name).any(|(i, _)| {
                let before = l[..i].chars().next_back();
                let after = l[i + name.len()..].chars().next();
                let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
                !ident(before) && !ident(after)
            })
        })
    };
    // Every name comes from `lambdamat::standalone`, which re-exports them.
    let groups: [(&str, &[&str]); 3] = [
        ("lambdamat::standalone::Limits", &["Fixed", "Lower", "Upper"]),
        ("lambdamat::standalone::Singularity", &["AbelSqrt", "Smooth"]),
        (
            "lambdamat::standalone",
            &[
                "CompiledCondition",
                "CompiledEquation",
                "CompiledOutput",
                "CompiledSystem",
                "EndSite",
                "Operator",
                "OutputTerm",
                "PlanError",
                "RFunc",
                "RealFn",
                "Scalar",
                "SplitCondition",
                "SplitContact",
                "SplitEnd",
                "SplitInequality",
                "SplitInput",
                "SplitInterval",
                "SplitKind",
                "SplitLinTerm",
                "SplitRelation",
                "SplitSingular",
                "real_pow",
                "words",
            ],
        ),
    ];
    let mut out = String::from("\nuse std::sync::Arc;\n\n");
    for (path, names) in groups {
        let used: Vec<&str> = names.iter().copied().filter(|n| mentions(n)).collect();
        match used.as_slice() {
            [] => {}
            [one] => {
                let _ = writeln!(out, "use {path}::{one};");
            }
            many => {
                let list = many.join(", ");
                let line = format!("use {path}::{{{list}}};");
                if line.len() < 100 {
                    let _ = writeln!(out, "{line}");
                } else {
                    // rustfmt fills the rows of a nested import list to
                    // at most 99 columns.
                    let _ = writeln!(out, "use {path}::{{");
                    let mut row = String::from("   ");
                    for n in many {
                        if row.len() + 1 + n.len() + 1 > 99 {
                            let _ = writeln!(out, "{row}");
                            row = String::from("   ");
                        }
                        row.push(' ');
                        row.push_str(n);
                        row.push(',');
                    }
                    let _ = writeln!(out, "{row}\n}};");
                }
            }
        }
    }
    out
}

#[allow(clippy::too_many_arguments)]
/// The generated terms of one functional (an output or a side
/// condition): `OutputTerm` literals, with a Rust function for each weight
/// (named from `weight_name`).
fn functional_code(
    names: &mut Names,
    fns: &mut String,
    label: &str,
    weight_name: &str,
    terms: &[FunctionalTerm],
    compiled: &[OutputTerm],
) -> Result<Vec<String>, PlanError> {
    let mut out = Vec::new();
    let multiple = terms.len() > 1;
    for (k, (t, ct)) in terms.iter().zip(compiled).enumerate() {
        match (t, ct) {
            (FunctionalTerm::Constant(_), OutputTerm::Constant(c)) => {
                out.push(format!("OutputTerm::Constant({})", literal(*c)));
            }
            (
                FunctionalTerm::Integral { weight, .. },
                OutputTerm::Integral {
                    coeff,
                    lower,
                    upper,
                    unknown,
                    ..
                },
            ) => {
                let suffix = if multiple {
                    format!("_{}", k + 1)
                } else {
                    String::new()
                };
                let f = names.fresh(&format!("{weight_name}{suffix}"));
                let doc = format!("Weight of {label}: `{weight}`.");
                function_x(fns, &f, &doc, weight);
                out.push(struct_lit(
                    "OutputTerm::Integral",
                    &[
                        ("coeff", literal(*coeff)),
                        ("lower", literal(*lower)),
                        ("upper", literal(*upper)),
                        ("weight", format!("Arc::new({f})")),
                        ("unknown", unknown.to_string()),
                    ],
                    4,
                ));
            }
            (FunctionalTerm::Point { .. }, OutputTerm::Point { coeff, at, unknown }) => {
                out.push(struct_lit(
                    "OutputTerm::Point",
                    &[
                        ("coeff", literal(*coeff)),
                        ("at", literal(*at)),
                        ("unknown", unknown.to_string()),
                    ],
                    4,
                ));
            }
            _ => {
                return Err(PlanError::Invalid(format!(
                    "internal: {label} compiled out of order"
                )));
            }
        }
    }
    Ok(out)
}

fn system_fn(
    out: &mut String,
    prog: &Program,
    sys: &CompiledSystem,
    setup: &str,
    op_vars: &[Option<String>],
    rhs_fns: &[String],
    (output_terms, condition_terms): (&[Vec<String>], &[Vec<String>]),
) {
    out.push_str("\n/// The operator system, which `input()` completes.\n");
    out.push_str("pub fn system() -> Result<CompiledSystem, PlanError> {\n");
    out.push_str(setup);
    let mut eq_vars = Vec::new();
    for (i, eq) in prog.equations.iter().enumerate() {
        let lhs: Vec<String> = eq
            .lhs
            .iter()
            .map(|p| {
                let terms: Vec<String> = p
                    .terms()
                    .iter()
                    .map(|(w, c)| {
                        let letters: Vec<String> = w.iter().map(usize::to_string).collect();
                        format!("(&[{}], \"{c}\")", letters.join(", "))
                    })
                    .collect();
                format!("words(&[{}])?", terms.join(", "))
            })
            .collect();
        let lhs_var = format!("lhs_{}", i + 1);
        let_vec(out, &lhs_var, &lhs);
        let var = format!("equation_{}", i + 1);
        let lit = struct_lit(
            "CompiledEquation",
            &[
                ("lhs", lhs_var),
                ("rhs", format!("Arc::new({})", rhs_fns[i])),
                (
                    "rhs_text",
                    format!("{:?}.into()", sys.equations[i].rhs_text),
                ),
            ],
            4,
        );
        let _ = writeln!(out, "    let {var} = {lit};");
        eq_vars.push(var);
    }
    let mut out_vars = Vec::new();
    for (k, (o, terms)) in sys.outputs.iter().zip(output_terms).enumerate() {
        let mut term_vars = Vec::new();
        for (j, t) in terms.iter().enumerate() {
            let var = format!("output_{}_term_{}", k + 1, j + 1);
            let _ = writeln!(out, "    let {var} = {t};");
            term_vars.push(var);
        }
        let var = format!("output_{}", k + 1);
        let lit = struct_lit(
            "CompiledOutput",
            &[
                ("name", format!("{:?}.into()", o.name)),
                ("terms", vec_expr(&term_vars, 8)),
            ],
            4,
        );
        let _ = writeln!(out, "    let {var} = {lit};");
        out_vars.push(var);
    }
    let mut cond_vars = Vec::new();
    for (k, (c, terms)) in sys.conditions.iter().zip(condition_terms).enumerate() {
        let mut term_vars = Vec::new();
        for (j, t) in terms.iter().enumerate() {
            let var = format!("condition_{}_term_{}", k + 1, j + 1);
            let _ = writeln!(out, "    let {var} = {t};");
            term_vars.push(var);
        }
        let var = format!("condition_{}", k + 1);
        let lit = struct_lit(
            "CompiledCondition",
            &[
                ("terms", vec_expr(&term_vars, 8)),
                ("value", literal(c.value)),
                ("text", format!("{:?}.into()", c.text)),
            ],
            4,
        );
        let _ = writeln!(out, "    let {var} = {lit};");
        cond_vars.push(var);
    }
    let _ = writeln!(out, "    let sys = CompiledSystem {{");
    let symbols: Vec<String> = prog
        .symbols
        .iter()
        .map(|s| format!("{s:?}.into()"))
        .collect();
    list_field(out, "symbols", &symbols);
    let ops: Vec<String> = op_vars
        .iter()
        .map(|v| match v {
            Some(v) => format!("Some({v})"),
            None => "None".into(),
        })
        .collect();
    list_field(out, "operators", &ops);
    let unknowns: Vec<String> = prog
        .unknowns
        .iter()
        .map(|s| format!("{s:?}.into()"))
        .collect();
    list_field(out, "unknowns", &unknowns);
    list_field(out, "equations", &eq_vars);
    list_field(out, "outputs", &out_vars);
    list_field(out, "conditions", &cond_vars);
    let _ = writeln!(out, "        target: {},", sys.target);
    let _ = writeln!(out, "        principal: {:?},", sys.principal);
    // The derivation's pivot sequence, embedded: the solver refuses to run
    // another (see `CompiledSystem::derived_pivots`).
    match sys.derivation().ok().map(|d| d.pivot_order()) {
        Some(p) => {
            let items: Vec<String> = p.iter().map(|(e, u)| format!("({e}, {u})")).collect();
            let v = vec_expr(&items, 8);
            let _ = writeln!(out, "        derived_pivots: Some({v}),");
        }
        None => {
            let _ = writeln!(out, "        derived_pivots: None,");
        }
    }
    let _ = writeln!(
        out,
        "        domain: ({}, {}),",
        literal(sys.domain.0),
        literal(sys.domain.1)
    );
    let interior: Vec<String> = sys.interior.iter().map(|&z| literal(z)).collect();
    list_field(out, "interior", &interior);
    let features: Vec<String> = sys
        .features
        .iter()
        .map(|&(at, w)| format!("({}, {})", literal(at), literal(w)))
        .collect();
    list_field(out, "features", &features);
    let _ = writeln!(out, "    }};");
    let _ = writeln!(out, "    sys.check()?;");
    let _ = writeln!(out, "    Ok(sys)");
    out.push_str("}\n");
}

/// `name: vec![a, b, c],` as a field at indentation 8.
fn list_field(out: &mut String, name: &str, items: &[String]) {
    let _ = writeln!(out, "        {name}: {},", vec_expr(items, 8));
}

/// `let name = vec![a, b, c];` at indentation 4.
fn let_vec(out: &mut String, name: &str, items: &[String]) {
    let _ = writeln!(out, "    let {name} = {};", vec_expr(items, 4));
}

/// `vec![a, b, c]` on one line if the items fit in 60 columns (rustfmt's
/// limit for arrays), else one item per line; `Vec::new()` if empty.
fn vec_expr(items: &[String], indent: usize) -> String {
    let inline = items.join(", ");
    if items.is_empty() {
        "Vec::new()".into()
    } else if inline.len() <= 60 && !inline.contains('\n') {
        format!("vec![{inline}]")
    } else {
        let pad = " ".repeat(indent + 4);
        let mut s = "vec![\n".to_string();
        for it in items {
            let _ = writeln!(s, "{pad}{it},");
        }
        s.push_str(&" ".repeat(indent));
        s.push(']');
        s
    }
}

/// One statement `open` `expr` `close` at indentation 4, kept within 100
/// columns by putting a long `expr` on its own line(s).
fn statement(out: &mut String, open: &str, expr: &str, close: &str) {
    let one = format!("    {open}{expr}{close}");
    if one.len() <= 100 {
        let _ = writeln!(out, "{one}");
    } else {
        // Long lines are bound to a name first; rustfmt keeps both lines.
        let _ = writeln!(out, "    let item = {expr};");
        let _ = writeln!(out, "    {open}item{close}");
    }
}

/// A struct literal `Name { a: 1.0, b: 2.0 }` at indentation `indent`,
/// on one line if its fields fit in 18 columns (rustfmt's limit), else
/// one field per line.
fn struct_lit(name: &str, fields: &[(&str, String)], indent: usize) -> String {
    let inline: Vec<String> = fields.iter().map(|(k, v)| format!("{k}: {v}")).collect();
    let inline = inline.join(", ");
    if inline.len() <= 18 {
        return format!("{name} {{ {inline} }}");
    }
    let pad = " ".repeat(indent + 4);
    let mut s = format!("{name} {{\n");
    for (k, v) in fields {
        let _ = writeln!(s, "{pad}{k}: {v},");
    }
    s.push_str(&" ".repeat(indent));
    s.push('}');
    s
}

/// A function of `x` (multipliers, right sides, weights).
fn function_x(out: &mut String, name: &str, doc: &str, e: &Expr) {
    let x = if e.uses_x() { "x" } else { "_x" };
    let _ = writeln!(out, "\n/// {doc}");
    let _ = writeln!(out, "fn {name}({x}: f64) -> f64 {{");
    if e.uses_t() {
        // Functions of x are evaluated at t = 0 (as the closures are).
        let _ = writeln!(out, "    let t = 0.0;");
    }
    for line in Body::new().expr(e) {
        let _ = writeln!(out, "    {line}");
    }
    out.push_str("}\n");
}

/// A kernel function of `(x, t)`: the smooth factor of an Abel kernel, or
/// a smooth kernel.
fn kernel_fn(out: &mut String, name: &str, sym: &str, written: &Expr, k: &KernelPlan) {
    let (uses_x, uses_t, lines, what) = match k {
        KernelPlan::Abel(parts) => (
            parts.factors.iter().any(|(f, _)| f.uses_x()),
            parts.factors.iter().any(|(f, _)| f.uses_t()),
            Body::new().abel(parts),
            "its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|",
        ),
        KernelPlan::Smooth(e) | KernelPlan::Peaked(_, e) => (
            e.uses_x(),
            e.uses_t(),
            Body::new().expr(e),
            "a smooth kernel",
        ),
        KernelPlan::Diagonal(s, parts) => (
            parts.factors.iter().any(|(f, _)| f.uses_x()),
            parts.factors.iter().any(|(f, _)| f.uses_t()),
            Body::new().abel(parts),
            match s {
                Singularity::Log => "its smooth factor a(x, t) with kernel = a(x, t) ln|x - t|",
                Singularity::Cauchy => "its smooth factor a(x, t) with kernel = a(x, t)/(t - x)",
                Singularity::Smooth => {
                    "its smooth part a(x, t) ln|c| with kernel = a(x, t) ln|c (x - t)|"
                }
                _ => "its smooth factor a(x, t) with kernel = a(x, t) |x - t|^(-β)",
            },
        ),
    };
    let x = if uses_x { "x" } else { "_x" };
    let t = if uses_t { "t" } else { "_t" };
    let _ = writeln!(out, "\n/// Operator `{sym}`, kernel `{written}`: {what}.");
    let _ = writeln!(out, "fn {name}({x}: f64, {t}: f64) -> f64 {{");
    for line in lines {
        let _ = writeln!(out, "    {line}");
    }
    out.push_str("}\n");
}

/// Distinct snake-case Rust identifiers.
#[derive(Default)]
struct Names {
    used: HashSet<String>,
}

impl Names {
    fn fresh(&mut self, want: &str) -> String {
        let mut base: String = want
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() {
                    c.to_ascii_lowercase()
                } else {
                    '_'
                }
            })
            .collect();
        // One underscore per run of other characters (`__` is not snake case).
        while base.contains("__") {
            base = base.replace("__", "_");
        }
        if base.is_empty() || base.starts_with(|c: char| c.is_ascii_digit()) {
            base.insert(0, 'f');
        }
        let mut name = base.clone();
        let mut k = 2;
        while !self.used.insert(name.clone()) {
            name = format!("{base}_{k}");
            k += 1;
        }
        name
    }
}
