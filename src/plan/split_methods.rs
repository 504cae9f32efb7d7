//! The solution methods of the split-domain discretisation (`split.rs`)
//! other than `coupled`: `ordered` (exact block elimination toward the
//! target unknown in the pivot order of the system's [`Derivation`], the
//! recipe of [`super::method`] executed on the split system's blocks) and
//! `commutative` (on files without relations or exact singular terms: the
//! derivation's eliminant `D_i u_i = Σ_j c_j g_j` evaluated with the split
//! operator matrices, the seed's single-equation model, with the other
//! unknowns solved from the ordered elimination's pivot equations given
//! `u_i`, and the commuted pairs' measured defects). Block `A_ij` of the split system is made
//! of the rows of equation `i` (its collocation rows and the one-sided
//! limit rows of the singular terms it is paired with) and the columns of
//! unknown `j` (its basis on its free support, its exact singular terms'
//! coefficients, and the columns through which a relation substitutes
//! another unknown). This is a square block system when every equation is
//! collocated for one and the same unknown on every subinterval where it
//! holds; a file where it is not, or whose side conditions add rows to no
//! block, is refused with the feature named. Owns the applicability checks
//! and these two recipes; the assembly is `split.rs`'s, the elimination
//! itself `method.rs`'s and `numeric::elimination`'s; it executes the
//! derivation and never re-derives.
use std::sync::Mutex;

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::error::PlanError;
use super::method::{Method, ordered as ordered_blocks};
use super::split::SplitProblem;
use super::split_input::SplitKind;
use crate::algebra::derivation::Derivation;
use crate::numeric::elimination::{apply_to_values, commutator_defect_on, solve_blocks};
use crate::numeric::solve::DEFAULT_MAX_COND;
use crate::numeric::{Assembler, NumericError, Operator, PanelBasis};
use crate::system::NcPoly;

/// Commutator defects above this are reported as warnings.
pub const DEFECT_WARNING: f64 = 1e-8;

/// A method other than `coupled`, ready to run on every discretisation of
/// one problem: the method, the derivation it executes, and the record of
/// its last solve.
pub struct MethodPlan {
    method: Method,
    derivation: Option<Derivation>,
    last: Mutex<MethodRecord>,
}

/// What a method did on its last solve, for the report.
#[derive(Debug, Clone, Default, Serialize, PartialEq)]
pub struct MethodRecord {
    /// The pivots the ordered elimination executed, as (equation,
    /// unknown), numbered from 1.
    pub pivots: Vec<(usize, usize)>,
    /// Where the method departed from the derivation, named.
    pub warnings: Vec<String>,
    /// For the commutative model: the symbol pairs it commuted, each with
    /// its measured defects.
    pub commuted: Vec<Commuted>,
}

/// A pair of symbols the commutative model commuted, with its measured
/// defect `‖KaKb f - KbKa f‖/‖KaKb f‖` (max norm at the target's nodes;
/// `None` if `KaKb f` vanishes) for `f = 1 + x` and for `f` the model's
/// solution for the target.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Commuted {
    /// The two symbols.
    pub pair: [String; 2],
    /// The defect for `f = 1 + x`.
    pub defect: Option<f64>,
    /// The defect for the model's solution.
    pub on_solution: Option<f64>,
}

/// The assembled split system with the ownership of its rows and columns
/// (`split.rs` builds it at the point where `coupled` solves).
pub(super) struct Assembled<'a> {
    /// The square collocation matrix.
    pub mat: &'a DMatrix<f64>,
    /// Its right side.
    pub rhs: &'a DVector<f64>,
    /// Collocation rows per equation, in equation order (the singular
    /// terms' limit rows follow all of them).
    pub eq_rows: Vec<usize>,
    /// Per singular term: the unknown it belongs to and the equation its
    /// limit row is taken from.
    pub terms: Vec<(usize, usize)>,
    /// Column offsets of the unknowns' bases (then one column per term).
    pub offsets: &'a [usize],
    /// `paired[u][k]`: the equation collocated at unknown `u`'s nodes on
    /// subinterval `k` (`None` where `u` is not free).
    pub paired: &'a [Vec<Option<usize>>],
    /// Subinterval ends.
    pub breaks: &'a [f64],
    /// Per unknown, its basis on its free support.
    pub bases: &'a [Option<PanelBasis>],
}

/// The solution, condition estimate and least-squares residual (0: the
/// methods here solve square systems) of one level.
pub(super) type Solved = (DVector<f64>, f64, f64);

impl SplitProblem {
    /// Runs `method` on every discretisation from now on, or refuses it
    /// with the feature of the file that keeps it from applying.
    pub fn set_method(&mut self, method: Method) -> Result<(), PlanError> {
        if method == Method::Coupled {
            self.method = None;
            return Ok(());
        }
        let refuse = |why: &str| {
            Err(PlanError::Invalid(format!(
                "--method {method}: {why}; use --method coupled"
            )))
        };
        if !self.sys.conditions.is_empty() && self.contact.scalars.is_empty() {
            return refuse(
                "side conditions add rows outside every (equation, unknown) block (the system is solved by least squares)",
            );
        }
        let derivation = match self.sys.derivation() {
            Ok(d) => Some(d),
            Err(e @ PlanError::Invalid(_)) => return Err(e),
            Err(_) => None,
        };
        if method == Method::Commutative {
            if !self.contact.relations.is_empty() {
                return refuse(
                    "relations substitute an unknown on a subinterval, where the eliminant D u = Σ c_j g_j (one equation on the whole interval, every equation and unknown in it) does not hold",
                );
            }
            if self
                .contact
                .singulars
                .iter()
                .any(|s| matches!(s.kind, SplitKind::Term { .. }))
            {
                return refuse(
                    "exact singular terms (`singular q at c- ~ B*g(x)`) add coefficients and limit rows the eliminant D u = Σ c_j g_j does not have",
                );
            }
            let Some(d) = &derivation else {
                return refuse(
                    "the λ-matrix is singular (det(A) = 0 over Q[symbols]), so there is no single equation",
                );
            };
            if d.eliminant.is_none() {
                return refuse(&format!(
                    "the eliminant was not derived: det(A) may have up to {:.3e} terms (limit {:.0})",
                    d.bound.terms,
                    crate::algebra::derivation::MAX_ELIMINANT_TERMS
                ));
            }
        }
        self.method = Some(MethodPlan {
            method,
            derivation,
            last: Mutex::new(MethodRecord::default()),
        });
        Ok(())
    }

    /// The method every discretisation runs.
    pub fn method(&self) -> Method {
        self.method.as_ref().map_or(Method::Coupled, |m| m.method)
    }

    /// What the method did on its last solve (`None` for `coupled`).
    pub fn method_record(&self) -> Option<MethodRecord> {
        let plan = self.method.as_ref()?;
        plan.last.lock().ok().map(|r| r.clone())
    }
}

impl MethodPlan {
    /// Solves the assembled system `a` of `problem` by this method.
    pub(super) fn solve(
        &self,
        problem: &SplitProblem,
        a: &Assembled<'_>,
    ) -> Result<Solved, PlanError> {
        let names = &problem.sys.unknowns;
        let owner = equation_of_unknown(a, names, self.method)?;
        let n = names.len();
        // Rows of each equation, columns of each unknown.
        let mut rows: Vec<Vec<usize>> = vec![Vec::new(); n];
        let mut r0 = 0;
        for (e, &len) in a.eq_rows.iter().enumerate() {
            rows[e].extend(r0..r0 + len);
            r0 += len;
        }
        let dim = a.offsets[a.offsets.len() - 1];
        let mut cols: Vec<Vec<usize>> = (0..n)
            .map(|u| (a.offsets[u]..a.offsets[u + 1]).collect())
            .collect();
        for (ti, &(u, e)) in a.terms.iter().enumerate() {
            rows[e].push(r0 + ti);
            cols[u].push(dim + ti);
        }
        for (u, e) in owner.iter().enumerate() {
            if rows[*e].len() != cols[u].len() {
                return Err(PlanError::Invalid(format!(
                    "--method {}: equation {} has {} rows for the {} coefficients of {}: its block is not square; use --method coupled",
                    self.method,
                    e + 1,
                    rows[*e].len(),
                    cols[u].len(),
                    names[u]
                )));
            }
        }
        let blocks: Vec<Vec<DMatrix<f64>>> = rows
            .iter()
            .map(|r| {
                cols.iter()
                    .map(|c| DMatrix::from_fn(r.len(), c.len(), |i, j| a.mat[(r[i], c[j])]))
                    .collect()
            })
            .collect();
        let g: Vec<DVector<f64>> = rows
            .iter()
            .map(|r| DVector::from_iterator(r.len(), r.iter().map(|&i| a.rhs[i])))
            .collect();
        let pivots = self
            .derivation
            .as_ref()
            .map(Derivation::pivot_order)
            .unwrap_or_default();
        if self.method == Method::Commutative {
            return self.commutative(problem, a, &owner, &blocks, &g, &cols, &pivots);
        }
        let sol = ordered_blocks(
            blocks,
            g,
            problem.sys.target,
            &pivots,
            names,
            DEFAULT_MAX_COND,
        )?;
        let mut x = DVector::zeros(a.mat.ncols());
        for (u, c) in cols.iter().enumerate() {
            let Some(v) = &sol.coefs[u] else {
                return Err(PlanError::Invalid(format!(
                    "--method {}: {} was not computed",
                    self.method, names[u]
                )));
            };
            for (q, &col) in c.iter().enumerate() {
                x[col] = v[q];
            }
        }
        if let Ok(mut last) = self.last.lock() {
            *last = MethodRecord {
                pivots: sol.pivots.iter().map(|&(e, u)| (e + 1, u + 1)).collect(),
                warnings: sol.warnings,
                commuted: Vec::new(),
            };
        }
        Ok((x, sol.cond, 0.0))
    }
}

/// The equation collocated for each unknown on every subinterval where it
/// is free, when that is one equation per unknown and one unknown per
/// equation (the split system is then a square block system); else the
/// refusal, naming the subintervals where the pairing changes.
fn equation_of_unknown(
    a: &Assembled<'_>,
    names: &[String],
    method: Method,
) -> Result<Vec<usize>, PlanError> {
    let piece = |k: usize| format!("({}, {})", a.breaks[k], a.breaks[k + 1]);
    let mut owner = Vec::with_capacity(names.len());
    for (u, name) in names.iter().enumerate() {
        let mut found: Option<(usize, usize)> = None;
        for (k, e) in a.paired[u].iter().enumerate() {
            let Some(e) = *e else { continue };
            match found {
                None => found = Some((e, k)),
                Some((e0, k0)) if e0 != e => {
                    return Err(PlanError::Invalid(format!(
                        "--method {method}: {name} is collocated with equation {} on {} but with equation {} on {} (the equations holding there change with the subinterval), so no equation's rows form one block for it; use --method coupled",
                        e0 + 1,
                        piece(k0),
                        e + 1,
                        piece(k)
                    )));
                }
                Some(_) => {}
            }
        }
        let Some((e, _)) = found else {
            return Err(PlanError::Invalid(format!(
                "--method {method}: {name} is nowhere free (a relation substitutes it everywhere), so it has no block; use --method coupled"
            )));
        };
        if let Some(v) = owner.iter().position(|&o| o == e) {
            return Err(PlanError::Invalid(format!(
                "--method {method}: equation {} is collocated for {} on some subintervals and for {name} on others (a relation substitutes one of them), so its rows form no block of one unknown; use --method coupled",
                e + 1,
                names[v]
            )));
        }
        owner.push(e);
    }
    if owner.len() != a.eq_rows.len() {
        return Err(PlanError::Invalid(format!(
            "--method {method}: {} equations for {} unknowns: the blocks are not square; use --method coupled",
            a.eq_rows.len(),
            owner.len()
        )));
    }
    Ok(owner)
}

impl MethodPlan {
    /// The commutative model on the split system: the target `i` solves
    /// the derivation's eliminant `D_i u_i = Σ_j c_j g_j` (`D_i` in written
    /// order, `c_j`'s monomials in symbol-table order, as `reduce`
    /// prints it) collocated at its nodes, products through its basis
    /// without weight; the other unknowns then solve the equations the
    /// ordered elimination pivots on, with `u_i` given (so every unknown
    /// is the model's, consistent with its `u_i`). Records the commuted
    /// pairs with their measured defects.
    #[allow(clippy::too_many_arguments)]
    fn commutative(
        &self,
        problem: &SplitProblem,
        a: &Assembled<'_>,
        owner: &[usize],
        blocks: &[Vec<DMatrix<f64>>],
        g: &[DVector<f64>],
        cols: &[Vec<usize>],
        pivots: &[(usize, usize)],
    ) -> Result<Solved, PlanError> {
        let sys = &problem.sys;
        let n = sys.unknowns.len();
        let der = self
            .derivation
            .as_ref()
            .ok_or_else(|| PlanError::Invalid("commutative model: no derivation".into()))?;
        let e = der
            .eliminant
            .as_ref()
            .ok_or_else(|| PlanError::Invalid("commutative model: no eliminant".into()))?;
        let i = der.target;
        let basis = a.bases[i].as_ref().ok_or_else(|| {
            PlanError::Invalid("commutative model: the target has no basis".into())
        })?;
        // Every unknown is free on the whole interval on the same mesh
        // (no relations, no terms), so all share the target's nodes.
        let mut mid = basis.clone();
        mid.weight.clear();
        let (asm, mid_asm) = (
            Assembler::new(basis).map_err(num())?,
            Assembler::new(&mid).map_err(num())?,
        );
        let nodes = basis.nodes();
        let ctx = || PlanError::numeric("commutative model");
        let op = |s: usize| -> Result<&Operator, PlanError> {
            sys.operators[s]
                .as_ref()
                .ok_or_else(|| PlanError::Invalid(format!("operator #{s} has no definition")))
        };
        // The matrix of `p` (written order) on `inner`'s coefficients,
        // collocated at the nodes.
        let poly = |p: &NcPoly, inner: &Assembler| -> Result<DMatrix<f64>, PlanError> {
            let (sup, mid_sup) = (inner.basis().support(), mid.support());
            let mut out = DMatrix::zeros(nodes.len(), inner.basis().dim());
            for (word, c) in p.terms() {
                let c = super::compile::rational(c);
                let m = match word.as_slice() {
                    [] => inner
                        .matrix_on(&Operator::identity(), &nodes, sup)
                        .map_err(ctx())?,
                    [s] => inner.matrix_on(op(*s)?, &nodes, sup).map_err(ctx())?,
                    [first, middle @ .., inner_s] => {
                        let mut m = inner.matrix_on(op(*inner_s)?, &nodes, sup).map_err(ctx())?;
                        for s in middle.iter().rev() {
                            m = mid_asm.matrix_on(op(*s)?, &nodes, mid_sup).map_err(ctx())? * m;
                        }
                        mid_asm
                            .matrix_on(op(*first)?, &nodes, mid_sup)
                            .map_err(ctx())?
                            * m
                    }
                };
                out += m * c;
            }
            Ok(out)
        };
        let l = poly(&e.lhs_ordered, &asm)?;
        let mut rhs = DVector::zeros(nodes.len());
        for (c, gk) in e.multipliers.iter().zip(g).take(n) {
            if c.is_zero() {
                continue;
            }
            let cm = poly(&NcPoly::from_mpoly(c), &mid_asm)?;
            rhs += apply_to_values(&cm, &mid, gk).map_err(ctx())?;
        }
        let lu = crate::numeric::solve::CheckedLu::new(&l, DEFAULT_MAX_COND).map_err(
            PlanError::numeric(format!("commutative model det(A) {} = …", sys.unknowns[i])),
        )?;
        let ui = lu.solve(&rhs).map_err(ctx())?;
        let mut cond = lu.cond();
        // The other unknowns from the pivot equations, u_i given.
        let others: Vec<usize> = (0..n).filter(|&j| j != i).collect();
        let eqs: Vec<usize> = if pivots.len() + 1 == n {
            pivots.iter().map(|&(eq, _)| eq).collect()
        } else {
            others.iter().map(|&j| owner[j]).collect()
        };
        let mut coefs: Vec<Option<DVector<f64>>> = vec![None; n];
        if !others.is_empty() {
            let sub: Vec<Vec<&DMatrix<f64>>> = eqs
                .iter()
                .map(|&r| others.iter().map(|&j| &blocks[r][j]).collect())
                .collect();
            let rhs: Vec<DVector<f64>> = eqs.iter().map(|&r| &g[r] - &blocks[r][i] * &ui).collect();
            let rrefs: Vec<&DVector<f64>> = rhs.iter().collect();
            let (us, c2) =
                solve_blocks(&sub, &rrefs, DEFAULT_MAX_COND).map_err(PlanError::numeric(
                    "commutative model: the other unknowns from the pivot equations",
                ))?;
            cond = cond.max(c2);
            for (&j, u) in others.iter().zip(us) {
                coefs[j] = Some(u);
            }
        }
        coefs[i] = Some(ui);
        let mut x = DVector::zeros(a.mat.ncols());
        for (u, c) in cols.iter().enumerate() {
            let v = coefs[u].as_ref().ok_or_else(ctx_missing)?;
            for (q, &col) in c.iter().enumerate() {
                x[col] = v[q];
            }
        }
        // The commuted pairs and their defects on f = 1 + x and on the
        // model's solution (its values at the nodes, the coefficients of
        // the unweighted `mid`).
        let f = DVector::from_vec(mid.interpolate(|t| 1.0 + t));
        let on_solution = DVector::from_iterator(
            nodes.len(),
            nodes.iter().zip(coefs[i].iter().flatten()).map(|(&t, v)| basis.weight_at(t) * v),
        );
        let mut commuted = Vec::new();
        for p in der.commuted_pairs() {
            let ka = mid_asm
                .matrix_on(op(p.a)?, &nodes, mid.support())
                .map_err(ctx())?;
            let kb = mid_asm
                .matrix_on(op(p.b)?, &nodes, mid.support())
                .map_err(ctx())?;
            let defect = |f: &DVector<f64>| match commutator_defect_on(&ka, &kb, &ka, &kb, &mid, f) {
                Ok(v) => Ok(v.is_finite().then_some(v)),
                Err(NumericError::InvalidArgument(_)) => Ok(None),
                Err(e) => Err(PlanError::numeric("commutator defect")(e)),
            };
            commuted.push(Commuted {
                pair: [sys.symbols[p.a].clone(), sys.symbols[p.b].clone()],
                defect: defect(&f)?,
                on_solution: defect(&on_solution)?,
            });
        }
        if let Ok(mut last) = self.last.lock() {
            *last = MethodRecord {
                pivots: Vec::new(),
                warnings: Vec::new(),
                commuted,
            };
        }
        Ok((x, cond, 0.0))
    }
}

fn num() -> impl FnOnce(NumericError) -> PlanError {
    PlanError::numeric("commutative model")
}

fn ctx_missing() -> PlanError {
    PlanError::Invalid("commutative model: an unknown was not computed".into())
}
