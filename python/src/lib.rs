//! The native half of the Python package `lambdamat`: thin wrappers over
//! the crate's API ([`lambdamat::Problem`] and its values) that convert at
//! the boundary (maps to dicts, unknowns to NumPy arrays, [`lambdamat::Error`]
//! to the package's exceptions) and release the GIL while the library
//! works. The Python classes and `sweep` live in `lambdamat/__init__.py`.
use std::collections::BTreeMap;

use numpy::PyArray1;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyInt, PyString};

use lambdamat::{ErrorKind, Method, SmithOptions, SolveOptions};

pyo3::create_exception!(
    lambdamat,
    LambdamatError,
    PyException,
    "Base class of lambdamat's errors."
);
pyo3::create_exception!(
    lambdamat,
    InvalidInput,
    LambdamatError,
    "Invalid input (exit code 2): `file`, `line`, `column` name the first place, when there is one."
);
pyo3::create_exception!(
    lambdamat,
    ComputationFailed,
    LambdamatError,
    "A computation refused or failed, naming the cause (exit code 3)."
);

/// The Python exception for `e`: its message is the CLI's.
fn to_py(py: Python<'_>, e: lambdamat::Error) -> PyErr {
    let msg = e.to_string();
    let err = match e.kind() {
        // A file that cannot be read is invalid input, as its exit code says.
        ErrorKind::InvalidInput | ErrorKind::Io => InvalidInput::new_err(msg),
        ErrorKind::ComputationFailed => ComputationFailed::new_err(msg),
        _ if e.exit_code() == 3 => ComputationFailed::new_err(msg),
        _ => InvalidInput::new_err(msg),
    };
    let first = e.locations().into_iter().next();
    let value = err.value(py);
    let _ = value.setattr("exit_code", e.exit_code());
    let _ = value.setattr("file", first.as_ref().map(|l| l.file.clone()));
    let _ = value.setattr("line", first.as_ref().map(|l| l.line));
    let _ = value.setattr("column", first.as_ref().map(|l| l.column));
    let all: Vec<(String, usize, usize)> = e
        .locations()
        .into_iter()
        .map(|l| (l.file, l.line, l.column))
        .collect();
    let _ = value.setattr("locations", all);
    err
}

/// A `set` value as `--set` reads it: a string as written, an integer in
/// full, a float as its shortest decimal.
fn set_text(v: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(s) = v.cast::<PyString>() {
        return s.extract::<String>();
    }
    if v.is_instance_of::<PyInt>() {
        return Ok(v.str()?.extract::<String>()?);
    }
    if v.is_instance_of::<PyFloat>() {
        return Ok(lambdamat::api::float_text(v.extract::<f64>()?));
    }
    Err(pyo3::exceptions::PyTypeError::new_err(format!(
        "a parameter value must be a str, int or float, not {}",
        v.get_type().name()?
    )))
}

fn parse_method(name: Option<&str>) -> PyResult<Option<Method>> {
    name.map(|m| {
        m.parse::<Method>()
            .map_err(|e| InvalidInput::new_err(format!("error: method={m}: {e}")))
    })
    .transpose()
}

/// One parsed, validated source file.
#[pyclass(frozen, module = "lambdamat._native")]
struct Problem(lambdamat::Problem);

#[pymethods]
impl Problem {
    #[staticmethod]
    fn from_file(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Problem> {
        lambdamat::Problem::from_file(&path)
            .map(Problem)
            .map_err(|e| to_py(py, e))
    }

    #[staticmethod]
    #[pyo3(signature = (text, name = "<source>"))]
    fn from_source(py: Python<'_>, text: &str, name: &str) -> PyResult<Problem> {
        lambdamat::Problem::from_source(text, name)
            .map(Problem)
            .map_err(|e| to_py(py, e))
    }

    #[getter]
    fn params(&self) -> Vec<(String, String)> {
        self.0.params()
    }

    #[getter]
    fn name(&self) -> String {
        self.0.name().to_string()
    }

    #[getter]
    fn source(&self) -> String {
        self.0.source().to_string()
    }

    #[pyo3(signature = (set = None, tol = 1e-10, method = None, max_level = None))]
    fn solve(
        &self,
        py: Python<'_>,
        set: Option<Vec<(String, Bound<'_, PyAny>)>>,
        tol: f64,
        method: Option<&str>,
        max_level: Option<usize>,
    ) -> PyResult<Solution> {
        let set = set
            .unwrap_or_default()
            .iter()
            .map(|(n, v)| Ok((n.clone(), set_text(v)?)))
            .collect::<PyResult<Vec<_>>>()?;
        let opts = SolveOptions {
            set,
            tol,
            method: parse_method(method)?,
            max_level,
            ..SolveOptions::default()
        };
        let problem = &self.0;
        py.detach(|| problem.solve(&opts))
            .map(Solution)
            .map_err(|e| to_py(py, e))
    }

    #[pyo3(signature = (principal = None, matrix = None))]
    fn smith(
        &self,
        py: Python<'_>,
        principal: Option<String>,
        matrix: Option<String>,
    ) -> PyResult<SmithForm> {
        let opts = SmithOptions { principal, matrix };
        let problem = &self.0;
        py.detach(|| problem.smith(&opts))
            .map(SmithForm)
            .map_err(|e| to_py(py, e))
    }

    #[pyo3(signature = (target = None))]
    fn reduce(&self, py: Python<'_>, target: Option<String>) -> PyResult<Reduction> {
        let problem = &self.0;
        py.detach(|| problem.reduce(target.as_deref()))
            .map(Reduction)
            .map_err(|e| to_py(py, e))
    }

    #[pyo3(signature = (target = None))]
    fn codegen(&self, py: Python<'_>, target: Option<String>) -> PyResult<String> {
        let problem = &self.0;
        py.detach(|| problem.codegen(target.as_deref()))
            .map_err(|e| to_py(py, e))
    }
}

/// A solved problem.
#[pyclass(frozen, module = "lambdamat._native")]
struct Solution(lambdamat::Solution);

#[pymethods]
impl Solution {
    #[getter]
    fn converged(&self) -> bool {
        self.0.converged
    }
    #[getter]
    fn scalars(&self) -> BTreeMap<String, f64> {
        self.0.scalars.clone()
    }
    #[getter]
    fn outputs(&self) -> BTreeMap<String, f64> {
        self.0.outputs.clone()
    }
    #[getter]
    fn error_estimates(&self) -> BTreeMap<String, f64> {
        self.0.error_estimates.clone()
    }
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.0.warnings.clone()
    }
    #[getter]
    fn unknowns(&self) -> BTreeMap<String, Field> {
        self.0
            .unknowns
            .iter()
            .map(|(n, f)| (n.clone(), Field(f.clone())))
            .collect()
    }
    fn to_json(&self) -> String {
        serde_json::to_string_pretty(&self.0.to_json()).unwrap_or_default()
    }
}

/// One unknown on the output grid.
#[pyclass(frozen, module = "lambdamat._native")]
struct Field(lambdamat::Field);

#[pymethods]
impl Field {
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.0.x)
    }
    #[getter]
    fn values<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.0.values)
    }
    #[getter]
    fn weight(&self) -> String {
        self.0.weight.clone()
    }
    #[getter]
    fn error_estimate(&self) -> f64 {
        self.0.error_estimate
    }
}

/// A certified Smith form.
#[pyclass(frozen, module = "lambdamat._native")]
struct SmithForm(lambdamat::SmithForm);

fn rows(r: &[Vec<String>]) -> Vec<Vec<String>> {
    r.to_vec()
}

#[pymethods]
impl SmithForm {
    #[getter]
    fn name(&self) -> String {
        self.0.name().to_string()
    }
    #[getter]
    fn ring(&self) -> String {
        self.0.ring().to_string()
    }
    #[getter]
    fn invariant_factors(&self) -> Vec<String> {
        self.0.invariant_factors().to_vec()
    }
    #[getter(A)]
    fn a(&self) -> Vec<Vec<String>> {
        rows(self.0.a())
    }
    #[getter(D)]
    fn d(&self) -> Vec<Vec<String>> {
        rows(self.0.d())
    }
    #[getter(U)]
    fn u(&self) -> Option<Vec<Vec<String>>> {
        self.0.u().map(rows)
    }
    #[getter(V)]
    fn v(&self) -> Option<Vec<Vec<String>>> {
        self.0.v().map(rows)
    }
    #[getter]
    fn verified(&self) -> bool {
        self.0.verified()
    }
    #[getter]
    fn certificate(&self) -> Vec<(String, bool, String)> {
        self.0
            .certificate()
            .iter()
            .map(|c| (c.property.clone(), c.ok, c.detail.clone()))
            .collect()
    }
    fn text(&self) -> String {
        self.0.text()
    }
    fn latex(&self) -> String {
        self.0.latex()
    }
    fn to_json(&self) -> String {
        self.0.to_json()
    }
}

/// The reduction of an operator system for one unknown.
#[pyclass(frozen, module = "lambdamat._native")]
struct Reduction(lambdamat::Reduction);

#[pymethods]
impl Reduction {
    #[getter]
    fn unknown(&self) -> String {
        self.0.unknown().to_string()
    }
    /// (text, LaTeX, language syntax) of the eliminant's operator.
    #[getter]
    fn eliminant(&self) -> (String, String, String) {
        let p = self.0.eliminant();
        (p.text, p.latex, p.lmx)
    }
    /// (text, LaTeX, language syntax) of the ordered form, or None.
    #[getter]
    fn ordered(&self) -> Option<(String, String, String)> {
        self.0
            .ordered()
            .ok()
            .map(|o| (o.text.clone(), o.latex.clone(), o.lmx.clone()))
    }
    #[getter]
    fn commuted_pairs(&self) -> Vec<(String, String)> {
        self.0
            .commuted_pairs()
            .into_iter()
            .map(|[a, b]| (a, b))
            .collect()
    }
    #[getter]
    fn pieces(&self) -> Vec<Option<String>> {
        self.0
            .pieces()
            .into_iter()
            .map(|(l, _)| l.map(str::to_string))
            .collect()
    }
    fn text(&self) -> String {
        self.0.text()
    }
    fn latex(&self) -> String {
        self.0.latex()
    }
    fn to_json(&self) -> String {
        self.0.to_json()
    }
}

/// The Hertz problem for ν and exactly one of μ, c.
#[pyfunction]
#[pyo3(signature = (nu, mu = None, c = None, tol = 1e-10))]
fn hertz(
    py: Python<'_>,
    nu: f64,
    mu: Option<f64>,
    c: Option<f64>,
    tol: f64,
) -> PyResult<Solution> {
    let given = match (mu, c) {
        (Some(mu), None) => lambdamat::api::Given::Mu(mu),
        (None, Some(c)) => lambdamat::api::Given::C(c),
        _ => {
            return Err(InvalidInput::new_err(
                "error: give exactly one of mu and c",
            ));
        }
    };
    py.detach(|| lambdamat::api::hertz(nu, given, tol))
        .map(Solution)
        .map_err(|e| to_py(py, e))
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("LambdamatError", py.get_type::<LambdamatError>())?;
    m.add("InvalidInput", py.get_type::<InvalidInput>())?;
    m.add("ComputationFailed", py.get_type::<ComputationFailed>())?;
    m.add_class::<Problem>()?;
    m.add_class::<Solution>()?;
    m.add_class::<Field>()?;
    m.add_class::<SmithForm>()?;
    m.add_class::<Reduction>()?;
    m.add_function(wrap_pyfunction!(hertz, m)?)?;
    Ok(())
}
