//! The reduction of an operator system to one equation for one unknown:
//! it takes a lowered [`Program`], asks [`crate::algebra::eliminate`] for
//! the commutative eliminant (with its Smith cross-check and commuted
//! pairs) and [`crate::algebra::ordered`] for the ordered elimination, and
//! expands the eliminant into iterated integrals from the operator table
//! ([`expand`]). It returns printable strings and structure; it must not
//! parse, print to a stream or evaluate anything numerically.
//!
//! * [`expand`]: operator words → iterated integrals (text, LaTeX);
//! * [`split`]: the subintervals of a split-domain program as systems.

pub mod expand;
pub mod split;

use crate::algebra::derivation::{Derivation, MAX_ELIMINANT_TERMS};
use crate::algebra::eliminate::EliminateError;
use crate::algebra::matrix::Matrix;
use crate::algebra::mpoly::MPoly;
use crate::algebra::polyring::PolyRing;
use crate::algebra::print::{Node, PrintOptions, print};
use crate::algebra::rational::fmt_q;
use crate::algebra::smith::certify::Check;
use crate::system::{Expr, Program};
use expand::{Argument, ExpandError, ExpandedTerm, expand_word};
use num_traits::One;

/// Why a reduction could not be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ReduceError {
    /// The file has no operator system.
    #[error("the file has no equations, so there is nothing to reduce")]
    NoSystem,
    /// The unknown named on the command line does not exist.
    #[error("no unknown named `{name}` (declared: {declared})")]
    NoSuchUnknown {
        /// The name asked for.
        name: String,
        /// The declared unknowns.
        declared: String,
    },
    /// The λ-matrix has no eliminant (singular or not square).
    #[error("no eliminant for {unknown}: {source}")]
    Eliminate {
        /// The unknown.
        unknown: String,
        /// The algebra's reason.
        source: EliminateError,
    },
}

/// One term `operator[value]` of the eliminant's right side.
#[derive(Clone, Debug, PartialEq)]
pub struct RhsTerm {
    /// The operator polynomial (commutative form), e.g. `-k2`.
    pub operator: String,
    /// The equation it multiplies (numbered from 1).
    pub equation: usize,
    /// The equation's right side, e.g. `0`.
    pub value: String,
    /// LaTeX of the operator.
    pub operator_latex: String,
    /// The operator's print tree: signs and grouping of the eliminant's
    /// display are read off it, never off the printed strings.
    pub operator_node: Node,
}

/// A symbol pair the eliminant commuted, with names.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedPair {
    /// The two symbols (table order).
    pub pair: [String; 2],
    /// The unknowns whose dropped coefficient needs the pair.
    pub on: Vec<String>,
}

/// The expanded form of the eliminant.
#[derive(Clone, Debug, PartialEq)]
pub struct Expanded {
    /// Terms of the left side (operator on the unknown).
    pub lhs: Vec<ExpandedTerm>,
    /// Terms of the right side.
    pub rhs: Vec<ExpandedTerm>,
}

/// The ordered elimination, printable.
#[derive(Clone, Debug, PartialEq)]
pub struct OrderedForm {
    /// E.g. `(k1 - k2 k4^-1 k3) p = g1 - k2 k4^-1 g2`.
    pub text: String,
    /// LaTeX form.
    pub latex: String,
    /// The language's syntax: `(k1 - k2*k4^(-1)*k3) p = g1 - k2*k4^(-1)*g2`.
    pub lmx: String,
    /// `g1 = 1, g2 = 0`.
    pub right_sides: Vec<(String, String)>,
    /// The inverses the result needs (`k4^-1`).
    pub inverses: Vec<String>,
    /// The same inverses in the language's syntax (`k4^(-1)`).
    pub inverses_lmx: Vec<String>,
    /// Pivot steps, e.g. `q from equation 2 (pivot k4)`.
    pub pivots: Vec<String>,
    /// Whether the commutative image agrees with Cramer's rule.
    pub agrees_with_cramer: bool,
}

/// One formula in the three notations of `crate::algebra::print`.
#[derive(Clone, Debug, PartialEq)]
pub struct Printed {
    /// Plain text (`k3 k7^-1 k5`).
    pub text: String,
    /// LaTeX.
    pub latex: String,
    /// The language's syntax (`k3*k7^(-1)*k5`), which parses back.
    pub lmx: String,
}

impl Printed {
    /// `node` in the three notations.
    pub(crate) fn of(node: &Node) -> Printed {
        Printed {
            text: print(node, PrintOptions::TEXT),
            latex: print(node, PrintOptions::LATEX),
            lmx: print(node, PrintOptions::LMX),
        }
    }
}

/// One named intermediate of the steps form: `S1 = k20 - k3 k7^-1 k5`.
#[derive(Clone, Debug, PartialEq)]
pub struct StepUpdate {
    /// Its name (`S1`, `R1`).
    pub name: String,
    /// The equation it updates (numbered from 1).
    pub equation: usize,
    /// The unknown whose coefficient it is; `None` for the right side.
    pub unknown: Option<String>,
    /// Its definition (the right-hand side of `S1 = …`).
    pub value: Printed,
    /// The definition expands to zero (the entry is zero afterwards).
    pub vanishes: bool,
}

/// One pivot of the steps form and the updates it makes.
#[derive(Clone, Debug, PartialEq)]
pub struct StepForm {
    /// The pivot equation (numbered from 1).
    pub equation: usize,
    /// The unknown solved from it.
    pub unknown: String,
    /// The pivot.
    pub pivot: Printed,
    /// The inverse it needs (a number for a constant pivot).
    pub inverse: Printed,
    /// The pivot is a constant (its inverse is a number, no operator).
    pub constant: bool,
    /// The intermediates it defines.
    pub updates: Vec<StepUpdate>,
}

/// The ordered elimination as steps ([`crate::algebra::ordered::EliminationSteps`]).
#[derive(Clone, Debug, PartialEq)]
pub struct StepsForm {
    /// The symbols its formulas are written in: the operators, `g1..gn`,
    /// then the intermediates.
    pub symbols: Vec<String>,
    /// The steps in order.
    pub steps: Vec<StepForm>,
    /// The equation left over (numbered from 1).
    pub equation: usize,
    /// The operator left on the unknown.
    pub lhs: Printed,
    /// The right side left over.
    pub rhs: Printed,
    /// The result `lhs u = rhs`.
    pub result: Printed,
    /// Every distinct inverse the steps need.
    pub inverses: Vec<Printed>,
    /// `(g1, its value)` for every equation.
    pub right_sides: Vec<(String, String)>,
}

/// The steps form of `d`, printable.
fn steps_form(p: &Program, d: &Derivation, uname: &str) -> Result<StepsForm, String> {
    let st = d.steps.as_ref().map_err(|e| e.to_string())?;
    let names = st.names(&p.symbols);
    let base = st.symbols + st.equations;
    let steps = st
        .steps
        .iter()
        .map(|s| StepForm {
            equation: s.equation + 1,
            unknown: p.unknowns[s.unknown].clone(),
            pivot: Printed::of(&s.pivot.to_node(&names)),
            inverse: Printed::of(&s.inverse.to_node(&names)),
            constant: s.pivot.as_constant().is_some(),
            updates: s
                .updates
                .iter()
                .map(|&k| {
                    let i = &st.intermediates[k];
                    StepUpdate {
                        name: names[base + k].clone(),
                        equation: i.equation + 1,
                        unknown: i.column.map(|c| p.unknowns[c].clone()),
                        value: Printed::of(&i.value.to_node(&names)),
                        vanishes: i.vanishes,
                    }
                })
                .collect(),
        })
        .collect();
    Ok(StepsForm {
        steps,
        equation: st.equation + 1,
        lhs: Printed::of(&st.lhs.to_node(&names)),
        rhs: Printed::of(&st.rhs.to_node(&names)),
        result: Printed::of(&st.result_node(&names, uname)),
        inverses: st
            .inverses()
            .iter()
            .map(|e| Printed::of(&Node::pow_i(e.to_node(&names), -1)))
            .collect(),
        symbols: names,
        right_sides: p
            .equations
            .iter()
            .enumerate()
            .map(|(j, eq)| (format!("g{}", j + 1), eq.rhs_text()))
            .collect(),
    })
}

/// Everything `lambdamat reduce` shows.
#[derive(Clone, Debug, PartialEq)]
pub struct Reduction {
    /// The unknown solved for.
    pub unknown: String,
    /// The unknowns (columns of the λ-matrix).
    pub unknowns: Vec<String>,
    /// The λ-matrix, rows of entries.
    pub lambda_matrix: Vec<Vec<String>>,
    /// The λ-matrix in LaTeX.
    pub lambda_matrix_latex: Vec<Vec<String>>,
    /// The ring, e.g. `Q[k1, k2, k3, k4]`.
    pub ring: String,
    /// Invariant factors over Q\[all\] (empty if not computed).
    pub invariant_factors: Vec<String>,
    /// LaTeX of the invariant factors.
    pub invariant_factors_latex: Vec<String>,
    /// Cross-checks of the eliminant against the Smith data.
    pub smith_checks: Vec<Check>,
    /// `det(A)`.
    pub det: String,
    /// The removed common factor (`None` if it is one).
    pub removed_factor: Option<String>,
    /// Left side operator (commutative form), e.g. `k1*k4 - k2*k3`.
    pub lhs: String,
    /// LaTeX of the left side operator.
    pub lhs_latex: String,
    /// The print tree of the operator on the unknown (zero when refused).
    pub lhs_node: Node,
    /// The left side operator in the derivation's order (`k4 k1 - k2 k3`).
    pub lhs_ordered: String,
    /// The same in the language's syntax (`k4*k1 - k2*k3`).
    pub lhs_ordered_lmx: String,
    /// Right side terms (nonzero operators only).
    pub rhs: Vec<RhsTerm>,
    /// Dropped terms: `(ordered coefficient, unknown)`.
    pub dropped: Vec<(String, String)>,
    /// The dropped coefficients in the language's syntax, in the same order.
    pub dropped_lmx: Vec<String>,
    /// The expanded form, or why there is none.
    pub expanded: Result<Expanded, String>,
    /// The ordered elimination, or why there is none.
    pub ordered: Result<OrderedForm, String>,
    /// The same ordered elimination as steps with named intermediates
    /// (never expanded; shown when the Schur form is too large to write
    /// out), or why there is none. Same pivots as [`Reduction::ordered`].
    pub ordered_steps: Result<StepsForm, String>,
    /// Why the commutative eliminant was not expanded (its size bound);
    /// `None` if it was. When set, the eliminant fields above are empty.
    pub eliminant_refused: Option<String>,
    /// The commuted pairs.
    pub commuted_pairs: Vec<NamedPair>,
    /// Parameters substituted in the kernels.
    pub params: Vec<(String, String)>,
    /// Caveats, e.g. products of distinct operators inside the λ-matrix,
    /// which the lowering stores commutatively (read here in table order).
    pub notes: Vec<String>,
}

/// The unknown to reduce for: `--for NAME`, else the file's first
/// `solve for`, else the first unknown.
pub fn choose_unknown(p: &Program, name: Option<&str>) -> Result<usize, ReduceError> {
    if p.equations.is_empty() || p.unknowns.is_empty() {
        return Err(ReduceError::NoSystem);
    }
    match name {
        Some(n) => {
            p.unknowns
                .iter()
                .position(|u| u == n)
                .ok_or_else(|| ReduceError::NoSuchUnknown {
                    name: n.to_string(),
                    declared: p.unknowns.join(", "),
                })
        }
        None => Ok(p
            .directives
            .iter()
            .find_map(|d| match d {
                crate::system::Directive::Solve { unknown } => Some(*unknown),
                _ => None,
            })
            .unwrap_or(0)),
    }
}

/// The λ-matrix of the program's operator system over Q\[symbols\].
pub fn lambda_matrix(p: &Program) -> Matrix<PolyRing> {
    let m = p.lambda_matrix();
    Matrix::new(PolyRing::new(p.symbols.clone()), m.rows, m.cols, m.entries)
}

/// The one [`Derivation`] of the program's system for unknown `unknown`
/// (0-based): what `reduce` prints, `solve` runs and `codegen` writes.
pub fn derive(p: &Program, unknown: usize) -> Result<Derivation, ReduceError> {
    if p.equations.is_empty() {
        return Err(ReduceError::NoSystem);
    }
    let uname = p
        .unknowns
        .get(unknown)
        .cloned()
        .ok_or(ReduceError::NoSystem)?;
    Derivation::new(&lambda_matrix(p), &p.ordered_matrix(), unknown, p.principal).map_err(
        |source| ReduceError::Eliminate {
            unknown: uname,
            source,
        },
    )
}

/// Reduces the program's system for unknown `unknown` (0-based).
pub fn reduce(p: &Program, unknown: usize) -> Result<Reduction, ReduceError> {
    reduce_with(p, &derive(p, unknown)?)
}

/// The printable reduction of a derivation of the program's system.
pub fn reduce_with(p: &Program, d: &Derivation) -> Result<Reduction, ReduceError> {
    let a = lambda_matrix(p);
    let names = &p.symbols;
    let unknown = d.target;
    let uname = p
        .unknowns
        .get(unknown)
        .cloned()
        .ok_or(ReduceError::NoSystem)?;
    let ordered = ordered_form(p, d, &a, &uname);
    let Some(e) = &d.eliminant else {
        return Ok(refused(p, d, &a, uname, ordered));
    };
    let ordered_steps = steps_form(p, d, &uname);
    let fmt = |m: &MPoly| m.to_string_with(names);
    let rhs: Vec<RhsTerm> = e
        .multipliers
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.is_zero())
        .map(|(j, c)| RhsTerm {
            operator: fmt(c),
            equation: j + 1,
            value: p.equations[j].rhs_text(),
            operator_latex: c.to_latex_with(names),
            operator_node: c.to_node(names),
        })
        .collect();
    let (invariant_factors, invariant_factors_latex, smith_checks) = match &e.smith {
        Some(s) => (
            s.invariant_factors.iter().map(fmt).collect(),
            s.invariant_factors
                .iter()
                .map(|f| f.to_latex_with(names))
                .collect(),
            s.checks.clone(),
        ),
        None => (Vec::new(), Vec::new(), Vec::new()),
    };
    let expanded = expand_all(p, e, unknown).map_err(|x| x.to_string());
    Ok(Reduction {
        unknown: uname,
        unknowns: p.unknowns.clone(),
        lambda_matrix: a.format_rows(),
        lambda_matrix_latex: a.latex_rows(),
        // No symbols: the entries are constants, the ring is Q itself.
        ring: if names.is_empty() {
            "Q".to_string()
        } else {
            format!("Q[{}]", names.join(", "))
        },
        invariant_factors,
        invariant_factors_latex,
        smith_checks,
        det: fmt(&e.det),
        removed_factor: (!e.removed_factor.is_nonzero_constant()).then(|| fmt(&e.removed_factor)),
        lhs: fmt(&e.lhs),
        lhs_latex: e.lhs.to_latex_with(names),
        lhs_node: e.lhs.to_node(names),
        lhs_ordered: e.lhs_ordered.to_string_with(names),
        lhs_ordered_lmx: e.lhs_ordered.to_lmx_with(names),
        rhs,
        dropped: e
            .dropped
            .iter()
            .map(|(k, c)| (c.to_string_with(names), p.unknowns[*k].clone()))
            .collect(),
        dropped_lmx: e
            .dropped
            .iter()
            .map(|(_, c)| c.to_lmx_with(names))
            .collect(),
        expanded,
        ordered,
        ordered_steps,
        eliminant_refused: None,
        commuted_pairs: e
            .commuted_pairs
            .iter()
            .map(|c| NamedPair {
                pair: [names[c.a].clone(), names[c.b].clone()],
                on: c
                    .on_unknowns
                    .iter()
                    .map(|k| p.unknowns[*k].clone())
                    .collect(),
            })
            .collect(),
        params: p
            .params
            .iter()
            .map(|q| (q.name.clone(), fmt_q(&q.value)))
            .collect(),
        notes: product_notes(p),
    })
}

/// The ordered elimination of `d`, printable.
fn ordered_form(
    p: &Program,
    d: &Derivation,
    a: &Matrix<PolyRing>,
    uname: &str,
) -> Result<OrderedForm, String> {
    let names = &p.symbols;
    match &d.ordered {
        Ok(o) => Ok(OrderedForm {
            text: o.to_string_with(names, uname),
            latex: o.to_latex_with(names, uname),
            lmx: o.to_lmx_with(names, uname),
            right_sides: p
                .equations
                .iter()
                .enumerate()
                .map(|(j, eq)| (format!("g{}", j + 1), eq.rhs_text()))
                .collect(),
            inverses: o.required_inverses(names),
            inverses_lmx: o.required_inverses_lmx(names),
            pivots: o
                .pivots
                .iter()
                .map(|pv| {
                    format!(
                        "{} from equation {} (pivot {})",
                        p.unknowns[pv.unknown],
                        pv.equation + 1,
                        pv.entry.to_string_with(names)
                    )
                })
                .collect(),
            // Cramer's rule needs det and adj: checked only where the
            // eliminant may be expanded.
            agrees_with_cramer: d.bound.allows_expansion() && o.agrees_with_cramer(a),
        }),
        Err(e) => Err(e.to_string()),
    }
}

/// The reduction when the eliminant's size bound forbids expanding it: the
/// λ-matrix, the bound and the ordered elimination (if it fits).
fn refused(
    p: &Program,
    d: &Derivation,
    a: &Matrix<PolyRing>,
    uname: String,
    ordered: Result<OrderedForm, String>,
) -> Reduction {
    let ordered_steps = steps_form(p, d, &uname);
    let why = format!(
        "not expanded: det(A) may have up to {:.3e} terms of degree up to {} (limit {:.0} terms)",
        d.bound.terms, d.bound.degree, MAX_ELIMINANT_TERMS
    );
    Reduction {
        unknown: uname,
        unknowns: p.unknowns.clone(),
        lambda_matrix: a.format_rows(),
        lambda_matrix_latex: a.latex_rows(),
        ring: format!("Q[{}]", p.symbols.join(", ")),
        invariant_factors: Vec::new(),
        invariant_factors_latex: Vec::new(),
        smith_checks: Vec::new(),
        det: String::new(),
        removed_factor: None,
        lhs: String::new(),
        lhs_latex: String::new(),
        lhs_node: Node::Terms(Vec::new()),
        lhs_ordered: String::new(),
        lhs_ordered_lmx: String::new(),
        rhs: Vec::new(),
        dropped: Vec::new(),
        dropped_lmx: Vec::new(),
        expanded: Err(why.clone()),
        ordered,
        ordered_steps,
        eliminant_refused: Some(why),
        commuted_pairs: Vec::new(),
        params: p
            .params
            .iter()
            .map(|q| (q.name.clone(), fmt_q(&q.value)))
            .collect(),
        notes: product_notes(p),
    }
}

/// A note for every equation operator whose written order is not the
/// symbol-table order: the λ-matrix holds its commutative image, the
/// ordered form keeps the order written.
fn product_notes(p: &Program) -> Vec<String> {
    let mut out = Vec::new();
    let n = p.symbols.len();
    for (i, eq) in p.equations.iter().enumerate() {
        for (j, w) in eq.lhs.iter().enumerate() {
            if !w.is_table_ordered() {
                out.push(format!(
                    "equation {} applies {} to {} in this order; the λ-matrix holds its commutative image {}",
                    i + 1,
                    w.to_string_with(&p.symbols),
                    p.unknowns[j],
                    w.commutative_image(n).to_string_with(&p.symbols)
                ));
            }
        }
    }
    if !p.side_conditions.is_empty() {
        out.push(format!(
            "{} side condition{} ({}): `solve` adds {} to the discrete system, not by the eliminations shown here ({} solved with the equations by least squares; in a file with unknown scalars, as conditions that fix the scalars)",
            p.side_conditions.len(),
            if p.side_conditions.len() == 1 { "" } else { "s" },
            p.side_conditions
                .iter()
                .map(|c| crate::lang::pretty::side_condition(c, &p.unknowns))
                .collect::<Vec<_>>()
                .join("; "),
            if p.side_conditions.len() == 1 { "it" } else { "them" },
            if p.side_conditions.len() == 1 { "as a row" } else { "as rows" },
        ));
    }
    out
}

/// Expands the derivation-ordered left side and each `c_j[g_j]`.
fn expand_all(
    p: &Program,
    e: &crate::algebra::eliminate::Eliminant,
    unknown: usize,
) -> Result<Expanded, ExpandError> {
    let u = Argument::Unknown(p.unknowns[unknown].clone());
    let mut lhs = Vec::new();
    for (w, c) in e.lhs_ordered.terms() {
        lhs.extend(expand_word(p, w, c, &u)?);
        if lhs.len() > expand::MAX_TERMS {
            return Err(ExpandError::TooManyTerms);
        }
    }
    let mut rhs = Vec::new();
    for (j, c) in e.multipliers.iter().enumerate() {
        if let Some(w) = p.equations[j].written.as_ref().filter(|_| !c.is_zero()) {
            return Err(ExpandError::ScalarRhs(w.clone()));
        }
        let g = &p.equations[j].rhs;
        if matches!(g, Expr::Const(z) if num_traits::Zero::is_zero(z)) {
            continue;
        }
        let arg = Argument::Value(Some(g.clone()));
        for (w, k) in crate::algebra::ncpoly::NcPoly::from_mpoly(c).terms() {
            let tag = format!(
                "{} g{}",
                crate::algebra::ncpoly::word_text(w, &p.symbols),
                j + 1
            );
            rhs.extend(expand_word(p, w, k, &arg)?.into_iter().map(|mut t| {
                t.source = tag.trim_start().to_string();
                t
            }));
            if rhs.len() > expand::MAX_TERMS {
                return Err(ExpandError::TooManyTerms);
            }
        }
    }
    Ok(Expanded { lhs, rhs })
}

impl Reduction {
    /// `(k1*k4 - k2*k3) p = k4[1] - k2[0]`.
    pub fn eliminant_text(&self) -> String {
        self.eliminant_with(PrintOptions::TEXT)
    }

    /// How the eliminant was derived from the equations E1, E2, …:
    /// `k4·E1 - k2·E2`.
    pub fn derivation_text(&self) -> String {
        let mut out = String::new();
        for t in &self.rhs {
            let (neg, body) = coefficient(&t.operator_node, PrintOptions::TEXT);
            let term = match body {
                None => format!("E{}", t.equation),
                Some(b) => format!("{b}·E{}", t.equation),
            };
            push_signed(&mut out, neg, &term);
        }
        out
    }

    /// LaTeX of [`Reduction::eliminant_text`].
    pub fn eliminant_latex(&self) -> String {
        self.eliminant_with(PrintOptions::LATEX)
    }

    /// `lhs u = ±op[g] ± …` in text or LaTeX.
    fn eliminant_with(&self, opts: PrintOptions) -> String {
        let unknown = print(&Node::sym(self.unknown.as_str()), opts);
        let lhs = match coefficient(&self.lhs_node, opts) {
            (neg, None) => format!("{}{unknown}", if neg { "-" } else { "" }),
            (neg, Some(b)) => format!("{}{b} {unknown}", if neg { "-" } else { "" }),
        };
        let mut rhs = String::new();
        for t in &self.rhs {
            let (neg, body) = coefficient(&t.operator_node, opts);
            let term = format!("{}[{}]", body.unwrap_or_default(), t.value);
            push_signed(&mut rhs, neg, &term);
        }
        if rhs.is_empty() {
            rhs.push('0');
        }
        format!("{lhs} = {rhs}")
    }
}

/// A coefficient laid out before what it acts on, decided on its print
/// tree: the sign is taken out of a single term (`-k2` → `-`, `k2`), a sum
/// keeps its signs and is grouped (`(k1*k4 - k2*k3)`), and the body is
/// `None` when it is 1.
fn coefficient(node: &Node, opts: PrintOptions) -> (bool, Option<String>) {
    if let Node::Terms(ts) = node
        && ts.len() > 1
    {
        return (
            false,
            Some(print(&Node::Group(Box::new(node.clone())), opts)),
        );
    }
    let (neg, body) = match node {
        Node::Terms(ts) if ts.len() == 1 => (ts[0].0, ts[0].1.clone()),
        other => other.clone().split_sign(),
    };
    let one = matches!(&body, Node::Num(q) if q.is_one());
    (neg, (!one).then(|| print(&body, opts)))
}

fn push_signed(out: &mut String, neg: bool, term: &str) {
    out.push_str(match (out.is_empty(), neg) {
        (true, true) => "-",
        (true, false) => "",
        (false, true) => " - ",
        (false, false) => " + ",
    });
    out.push_str(term);
}
