//! One discretisation level of a language system: a mesh on the unknowns'
//! interval graded geometrically toward its right end (and toward interior
//! constant limits), one weighted trial basis per unknown and one
//! unweighted intermediate basis (`mid`) on the same mesh, so every matrix
//! is square with rows at the common collocation nodes. Operator symbols
//! are assembled once per basis and cached; an ordered operator (an
//! [`NcPoly`] over the symbols) becomes a sum of products of these matrices
//! through `mid`, every word in its written order. This file owns the level and its matrices; it must not
//! choose methods or refine.
use std::collections::HashMap;

use nalgebra::{DMatrix, DVector};

use crate::numeric::elimination::product;
use crate::numeric::{Assembler, Factor, Grading, Mesh, Operator, PanelBasis, Side};
use crate::system::NcPoly;

use super::compiled::Fn1;
use super::error::PlanError;

/// Which trial basis a matrix acts on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BasisId {
    /// The unweighted intermediate basis.
    Mid,
    /// The basis of unknown `j`.
    Unknown(usize),
}

/// Mesh and degree parameters of refinement level `level` (1, 2, ...).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelSpec {
    /// Geometric layers toward the right end and interior points.
    pub layers: usize,
    /// Geometric layers toward the left end.
    pub layers_lo: usize,
    /// Longest panel, as a fraction of the interval.
    pub max_panel: f64,
    /// Grading ratio.
    pub sigma: f64,
    /// Nodes on the panels touching a graded point.
    pub n_min: usize,
    /// Most nodes on any panel.
    pub n_max: usize,
}

impl LevelSpec {
    /// The ladder used by the solver: layers and degrees both grow. The
    /// left end is not graded (the Abel kernels `|t²-x²|^(-1/2)` are even
    /// in `x`, and tiny panels there only amplify the first-kind
    /// ill-posedness: measured on the punch, grading it cost three digits);
    /// panels stay below a quarter of the interval, and the panels farthest
    /// from the graded points carry the most nodes.
    pub fn level(level: usize) -> LevelSpec {
        LevelSpec {
            layers: level + 1,
            layers_lo: 0,
            max_panel: 0.25,
            sigma: 0.15,
            n_min: level + 2,
            n_max: 2 * level + 6,
        }
    }
}

/// The matrices of one level.
pub struct Discretisation {
    /// The unweighted intermediate basis.
    pub mid: PanelBasis,
    /// One basis per unknown (same mesh and nodes, own weight).
    pub bases: Vec<PanelBasis>,
    /// The common collocation points (nodes of the mesh).
    pub nodes: Vec<f64>,
    ops: Vec<Option<(String, Operator)>>,
    cache: HashMap<(usize, BasisId), DMatrix<f64>>,
}

impl Discretisation {
    /// A level on `domain` graded toward its ends and the `interior`
    /// points marked `true` (the others are plain breakpoints);
    /// `ops[s]` is the operator of symbol `s` (with its name) or `None`,
    /// `weights[j]` the weight factors of unknown `j`.
    pub fn new(
        domain: (f64, f64),
        interior: &[(f64, bool)],
        spec: LevelSpec,
        ops: Vec<Option<(String, Operator)>>,
        weights: &[Vec<Factor>],
    ) -> Result<Discretisation, PlanError> {
        let (lo, hi) = domain;
        let ctx = PlanError::numeric("building the mesh");
        let mesh = split_long(
            Mesh::graded(lo, hi, &gradings(domain, interior, spec), spec.sigma).map_err(ctx)?,
            spec.max_panel * (hi - lo),
        );
        let basis = |w: Vec<Factor>| {
            PanelBasis::hp(&mesh, spec.n_min, 1.0, spec.n_max, w)
                .map_err(PlanError::numeric("building a trial basis"))
        };
        let mid = basis(Vec::new())?;
        let bases = weights
            .iter()
            .map(|w| basis(w.clone()))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Discretisation {
            nodes: mid.nodes(),
            mid,
            bases,
            ops,
            cache: HashMap::new(),
        })
    }

    /// Number of coefficients of every basis.
    pub fn dim(&self) -> usize {
        self.mid.dim()
    }

    /// The basis with this id.
    pub fn basis(&self, id: BasisId) -> &PanelBasis {
        match id {
            BasisId::Mid => &self.mid,
            BasisId::Unknown(j) => &self.bases[j],
        }
    }

    /// The collocation matrix of `op` on basis `id`.
    pub fn assemble(&self, op: &Operator, id: BasisId) -> Result<DMatrix<f64>, PlanError> {
        let asm = Assembler::new(self.basis(id)).map_err(PlanError::numeric("assembly"))?;
        asm.matrix(op, &self.nodes)
            .map_err(PlanError::numeric("assembling an operator matrix"))
    }

    /// The matrix of operator symbol `s` on basis `id` (assembled once).
    pub fn symbol(&mut self, s: usize, id: BasisId) -> Result<DMatrix<f64>, PlanError> {
        if let Some(m) = self.cache.get(&(s, id)) {
            return Ok(m.clone());
        }
        let Some(Some((name, op))) = self.ops.get(s) else {
            return Err(PlanError::Invalid(format!(
                "symbol #{s} has no operator definition"
            )));
        };
        let m = self.assemble(op, id).map_err(|e| match e {
            PlanError::Numeric { source, .. } => PlanError::Numeric {
                context: format!("assembling operator {name}"),
                source,
            },
            other => other,
        })?;
        self.cache.insert((s, id), m.clone());
        Ok(m)
    }

    /// The matrix of the operator product `s_1 s_2 … s_k` (symbols in the
    /// order given, `s_k` applied first) on basis `id`, through `mid`.
    pub fn word(&mut self, word: &[usize], id: BasisId) -> Result<DMatrix<f64>, PlanError> {
        let Some((&inner, outer)) = word.split_last() else {
            return self.assemble(&Operator::identity(), id);
        };
        let mut m = self.symbol(inner, id)?;
        for &s in outer.iter().rev() {
            let k = self.symbol(s, BasisId::Mid)?;
            m = product(&k, &self.mid, &m).map_err(PlanError::numeric("operator product"))?;
        }
        Ok(m)
    }

    /// The matrix of an ordered operator on basis `id`: every word is
    /// applied as written (its last symbol first).
    pub fn poly(&mut self, p: &NcPoly, id: BasisId) -> Result<DMatrix<f64>, PlanError> {
        let n = self.dim();
        let mut out = DMatrix::zeros(n, n);
        for (word, c) in p.terms() {
            let m = self.word(word, id)?;
            out += m * super::compile::rational(c);
        }
        Ok(out)
    }

    /// Values of a function of `x` at the collocation nodes.
    pub fn values(&self, f: &Fn1, what: &str) -> Result<DVector<f64>, PlanError> {
        let v = DVector::from_iterator(self.nodes.len(), self.nodes.iter().map(|&x| f(x)));
        if let Some(i) = v.iter().position(|v| !v.is_finite()) {
            return Err(PlanError::Invalid(format!(
                "{what} is not finite at x = {}",
                self.nodes[i]
            )));
        }
        Ok(v)
    }
}

/// The graded points of a level: both ends and the interior points.
fn gradings(domain: (f64, f64), interior: &[(f64, bool)], spec: LevelSpec) -> Vec<Grading> {
    let (lo, hi) = domain;
    let mut gradings = vec![
        Grading {
            at: lo,
            side: Side::Right,
            layers: spec.layers_lo,
        },
        Grading {
            at: hi,
            side: Side::Left,
            layers: spec.layers,
        },
    ];
    for &(z, graded) in interior.iter().filter(|&&(z, _)| z > lo && z < hi) {
        gradings.push(Grading {
            at: z,
            side: Side::Both,
            layers: if graded { spec.layers } else { 0 },
        });
    }
    gradings
}

/// The coefficients per basis of the level [`Discretisation::new`] would
/// build on `domain`, counted without building it (a float: the memory
/// budget must measure a level too large to allocate).
pub fn level_dim(
    domain: (f64, f64),
    interior: &[(f64, bool)],
    spec: LevelSpec,
) -> Result<f64, PlanError> {
    let (lo, hi) = domain;
    let mesh = Mesh::graded(lo, hi, &gradings(domain, interior, spec), spec.sigma)
        .map_err(PlanError::numeric("building the mesh"))?;
    let h = spec.max_panel * (hi - lo);
    Ok(mesh
        .levels
        .iter()
        .enumerate()
        .map(|(k, &l)| {
            let (a, b) = mesh.panel(k);
            let nodes =
                ((spec.n_min as f64 + l as f64).round()).clamp(1.0, spec.n_max.max(1) as f64);
            ((b - a) / h).ceil().max(1.0) * nodes
        })
        .sum())
}

/// Splits panels longer than `h` into equal pieces of the same layer.
fn split_long(m: Mesh, h: f64) -> Mesh {
    let mut breaks = vec![m.breaks[0]];
    let mut levels = Vec::new();
    for (k, &level) in m.levels.iter().enumerate() {
        let (a, b) = m.panel(k);
        let pieces = ((b - a) / h).ceil().max(1.0) as usize;
        for i in 1..=pieces {
            breaks.push(if i == pieces {
                b
            } else {
                a + (b - a) * i as f64 / pieces as f64
            });
            levels.push(level);
        }
    }
    Mesh { breaks, levels }
}
