"""The Python package against the command line and the physics: every
function of the package, its errors, and a sweep on a Dask LocalCluster
matching the serial sweep."""
import json
import pathlib
import shutil
import subprocess
import threading

import numpy as np
import pytest

import lambdamat
from lambdamat import ComputationFailed, InvalidInput, LambdamatError, Problem

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cli(*args):
    """The `lambdamat` command's output: the binary `cargo build --release`
    makes (or one on PATH); the comparisons with it never skip."""
    exe = ROOT / "target" / "release" / "lambdamat"
    path = str(exe) if exe.exists() else shutil.which("lambdamat")
    assert path, "build the command line first: cargo build --release"
    return subprocess.run([path, *args], capture_output=True, text=True)


def test_from_file_and_params(examples):
    p = Problem.from_file(examples / "hertz.lmx")
    assert p.params[:2] == [("nu", "1/4"), ("mu", "0.1801")]
    assert p.params[2] == ("gamma", "(1 - 2*nu)/(2 - 2*nu)")
    assert p.name.endswith("hertz.lmx")


def test_from_source_errors_name_file_line_column():
    with pytest.raises(InvalidInput) as e:
        Problem.from_source("var x\nmatrix A = [x, y]")
    err = e.value
    assert isinstance(err, LambdamatError)
    assert (err.file, err.line, err.column) == ("<source>", 2, 16)
    assert err.exit_code == 2
    assert "<source>:2:16" in str(err)
    with pytest.raises(InvalidInput) as e:
        Problem.from_source("var x\nmatrix A = [y]", name="m.lmx")
    assert e.value.file == "m.lmx"
    with pytest.raises(InvalidInput):
        Problem.from_file("/nonexistent/file.lmx")


def test_solve_values_arrays_and_json(examples):
    p = Problem.from_file(examples / "mms.lmx")
    s = p.solve()
    assert s.converged
    assert set(s.outputs) == {"P", "Q"}
    assert all(isinstance(v, float) for v in s.outputs.values())
    assert all(s.error_estimates[k] <= 1e-10 for k in s.outputs)
    for f in s.unknowns.values():
        assert f.x.dtype == np.float64 and f.values.dtype == np.float64
        assert f.x.shape == f.values.shape and f.x.size > 10
    doc = json.loads(s.to_json())
    assert doc["outputs"]["P"] == s.outputs["P"]
    out = cli("solve", str(examples / "mms.lmx"), "--json")
    assert json.loads(out.stdout) == doc
    c = p.solve(method="coupled")
    assert abs(c.outputs["P"] - s.outputs["P"]) <= c.error_estimates["P"] + s.error_estimates["P"]
    with pytest.raises(InvalidInput):
        p.solve(method="fastest")
    with pytest.raises(InvalidInput):
        p.solve(tol=-1.0)


def test_solve_set_reads_values_as_set_does(examples):
    p = Problem.from_file(examples / "hertz.lmx")
    a = p.solve(set={"nu": 0.3, "mu": "1/2"}, tol=1e-8)
    b = p.solve(set={"nu": "0.3", "mu": 0.5}, tol=1e-8)
    assert a.scalars == b.scalars and a.outputs == b.outputs
    assert a.converged and 0 < a.scalars["c"] < 1
    assert a.error_estimates["c"] <= 1e-8
    with pytest.raises(InvalidInput) as e:
        p.solve(set={"rho": 1})
    assert "defines no parameter `rho`" in str(e.value)
    with pytest.raises(TypeError):
        p.solve(set={"nu": [1]})


def test_unconverged_is_a_result_and_failure_an_exception():
    p = Problem.from_source("operator k = int(0..1) dt\nunknown p\nequation p + k p = 1/x\n")
    s = p.solve(max_level=3)
    assert s.converged is False
    ill = Problem.from_source(
        "operator k = int(0..1) 100000000000000000000*(x + t) dt\nunknown p\nequation p + k p = 1\n"
    )
    with pytest.raises(ComputationFailed) as e:
        ill.solve()
    assert e.value.exit_code == 3 and isinstance(e.value, LambdamatError)


def test_smith_of_matrix_and_of_operator_system(examples):
    m = Problem.from_source("var x\nmatrix A = [x, 1; 0, x]")
    s = m.smith()
    assert s.invariant_factors == ["1", "x^2"]
    assert s.D == [["1", "0"], ["0", "x^2"]]
    assert s.U is not None and s.V is not None and s.verified
    latex = s._repr_latex_()
    assert latex.startswith("$$") and r"\begin{pmatrix}" in latex
    h = Problem.from_file(examples / "hertz.lmx").smith()
    assert h.ring == "Q(k1, k2, k3)[k4]"
    assert h.invariant_factors == ["1", "k4 - k2*k3/k1"]
    out = cli("smith", str(examples / "hertz.lmx"))
    assert out.stdout == h.text()
    two = Problem.from_source("var x, y\nmatrix A = [x, y; 0, x]")
    assert two.smith(principal="y").invariant_factors == ["1", "1"]  # det = x^2, a unit of Q(x)
    assert two.smith().U is None
    with pytest.raises(InvalidInput):
        two.smith(principal="z")


def test_reduce_and_codegen(examples):
    p = Problem.from_file(examples / "generic3.lmx")
    r = p.reduce()
    assert r.eliminant and r.unknown
    assert r._repr_latex_().startswith("$")
    assert json.loads(r.to_json())
    out = cli("reduce", str(examples / "generic3.lmx"))
    assert out.stdout == r.text()
    h = Problem.from_file(examples / "hertz.lmx").reduce("q")
    assert h.unknown == "q" and len(h.pieces) == 2
    with pytest.raises(InvalidInput):
        p.reduce("nosuch")
    code = Problem.from_file(examples / "mms.lmx").codegen()
    assert "fn main" in code


def test_hertz_matches_the_file_and_known_values(examples):
    s = lambdamat.hertz(0.25, mu=0.1801, tol=1e-9)
    assert s.converged
    # docs/hertz.md tabulates (ν, μ) = (0.25, 0.1801) at c = 0.50 (two digits)
    assert abs(s.scalars["c"] - 0.5) < 0.005
    f = Problem.from_file(examples / "hertz.lmx").solve(set={"nu": 0.25, "mu": 0.1801}, tol=1e-9)
    assert f.scalars == s.scalars
    g = lambdamat.hertz(0.25, c=s.scalars["c"], tol=1e-9)
    assert abs(g.scalars["mu"] - 0.1801) <= 1e-6
    frictionless = lambdamat.hertz(0.3, mu=0.0)
    assert frictionless.converged
    with pytest.raises(InvalidInput):
        lambdamat.hertz(0.7, mu=0.1)
    with pytest.raises(InvalidInput):
        lambdamat.hertz(0.25, mu=0.1, c=0.5)


GRID = {"nu": [0.2, 1], "mu": [0.3, "1/2"]}


def check_rows(rows):
    assert [(r["nu"], r["mu"]) for r in rows] == [(0.2, 0.3), (0.2, "1/2"), (1, 0.3), (1, "1/2")]
    good, bad = rows[:2], rows[2:]
    for r in good:
        assert r["error"] is None and r["converged"] is True
        assert 0 < r["c"] < 1 and r["c_err"] <= 1e-8 and "P" in r and "P_err" in r
    for r in bad:  # ν = 1: γ = (1 - 2ν)/(2 - 2ν) divides by zero
        assert r["converged"] is False and "division by zero" in r["error"].lower()


def test_sweep_serial_with_a_failed_point(examples):
    rows = lambdamat.sweep(examples / "hertz.lmx", GRID, tol=1e-8)
    check_rows(rows)
    again = lambdamat.sweep(Problem.from_file(examples / "hertz.lmx"), GRID, tol=1e-8)
    assert again == rows


def test_sweep_on_a_local_cluster_equals_the_serial_sweep(examples):
    import distributed

    serial = lambdamat.sweep(examples / "hertz.lmx", GRID, tol=1e-8)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == 2
            rows = lambdamat.sweep(examples / "hertz.lmx", GRID, client=client, tol=1e-8)
    check_rows(rows)
    assert rows == serial


def test_the_gil_is_released_during_solves(examples):
    """Two threads in one solve each: while one runs, the other thread's
    Python code runs too (a counter advances during the solve)."""
    p = Problem.from_file(examples / "hertz.lmx")
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)

    t = threading.Thread(target=count)
    t.start()
    try:
        before = len(ticks)
        p.solve(set={"nu": 0.3, "mu": 0.5}, tol=1e-9)
        during = len(ticks) - before
    finally:
        done.set()
        t.join()
    assert during > 1000


def test_the_notebook_runs_headless(examples):
    import nbclient
    import nbformat

    path = examples / "notebooks" / "hertz.ipynb"
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=900, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    assert any("text/latex" in o.get("data", {}) for o in outputs)
    assert any("image/png" in o.get("data", {}) for o in outputs)
