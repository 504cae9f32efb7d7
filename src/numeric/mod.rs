//! The numeric layer: `f64` and nalgebra only (never exact rationals).
//!
//! * [`gauss`]: Gauss–Legendre / Gauss–Jacobi rules by Golub–Welsch;
//! * [`gamma`]: `ln Γ` for the Jacobi moments;
//! * [`mesh`]: panel meshes graded geometrically toward chosen points;
//! * [`basis`]: weighted, discontinuous piecewise-polynomial trial spaces;
//! * [`product`]: product-integration rules exact for endpoint and diagonal
//!   power singularities, with geometric sub-grading near them;
//! * [`kernels`]: product rules for `ln|t-x|`, Cauchy principal values and
//!   sharply peaked smooth kernels;
//! * [`operator`]: operators as data (Abel-type and smooth integral terms,
//!   multipliers, identity) with kernels as closures;
//! * [`assemble`]: collocation matrices of operators;
//! * [`lu`]: blocked LU with partial pivoting (and transposed solves);
//! * [`roots`]: bracketing, Brent and warm-started secant iterations;
//! * [`solve`]: dense solves that refuse singular or ill-conditioned
//!   systems;
//! * [`elimination`]: the coupled block solve, operator products through
//!   an intermediate basis and commutator defects;
//! * [`budget`]: the memory budget of the solver ladders;
//! * [`error`]: the layer's error enum.
//!
//! Problem-specific code (the Hertz problem, solvers for systems from the
//! language) builds on this layer and must not copy its quadrature.
pub mod assemble;
pub mod basis;
pub mod budget;
pub mod elimination;
pub mod error;
pub mod gamma;
pub mod gauss;
pub mod kernels;
pub mod lu;
pub mod mesh;
pub mod operator;
pub mod product;
pub mod roots;
pub mod solve;

pub use assemble::Assembler;
pub use basis::{Factor, PanelBasis};
pub use error::NumericError;
pub use mesh::{Grading, Mesh, Side};
pub use operator::{Limits, Operator, Singularity};
