"""lambdamat from Python: systems of linear integral-operator equations as
exact algebra (certified Smith forms, eliminations) and as error-controlled
numerical solvers.

A thin layer over the Rust crate's API (``lambdamat::Problem``): every
value comes from the library, and every error is the command line's
message, raised as :class:`InvalidInput` (exit code 2) or
:class:`ComputationFailed` (exit code 3), both :class:`LambdamatError`.
The GIL is released while a solve, a Smith form or a reduction runs.
"""
from __future__ import annotations

import itertools
import json
import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Union

from . import _native
from ._native import ComputationFailed, InvalidInput, LambdamatError

__all__ = [
    "Problem",
    "Solution",
    "Field",
    "SmithForm",
    "Reduction",
    "hertz",
    "sweep",
    "LambdamatError",
    "InvalidInput",
    "ComputationFailed",
]

Field = _native.Field


def _matrix_latex(rows: Sequence[Sequence[str]]) -> str:
    body = r" \\ ".join(" & ".join(r) for r in rows)
    return r"\begin{pmatrix} " + body + r" \end{pmatrix}"


class Solution:
    """A solved problem: what ``lambdamat solve --json`` prints, as values.

    ``scalars``, ``outputs`` and ``error_estimates`` (absolute) are dicts of
    floats; ``unknowns[name].x`` and ``.values`` are NumPy float64 arrays;
    ``converged`` is False when the tolerance was not reached (the values
    are still there, with their honest estimates)."""

    def __init__(self, native: "_native.Solution"):
        self._native = native
        self.converged: bool = native.converged
        self.scalars: Dict[str, float] = native.scalars
        self.outputs: Dict[str, float] = native.outputs
        self.error_estimates: Dict[str, float] = native.error_estimates
        self.unknowns: Dict[str, Field] = native.unknowns
        self.warnings: List[str] = native.warnings

    def to_json(self) -> str:
        """The JSON object ``lambdamat solve --json`` prints."""
        return self._native.to_json()

    def __repr__(self) -> str:
        vals = {**self.scalars, **self.outputs}
        shown = ", ".join(
            f"{k}={v:.12g}±{self.error_estimates.get(k, float('nan')):.1e}"
            for k, v in vals.items()
        )
        return f"Solution(converged={self.converged}, {shown})"


class _Printed:
    """What the command line prints for a value, through the one printer:
    ``text()``, ``latex()`` (``--latex``) and ``to_json()`` (``--json``)."""

    _native: Any

    def text(self) -> str:
        return self._native.text()

    def latex(self) -> str:
        return self._native.latex()

    def to_json(self) -> str:
        return self._native.to_json()


class SmithForm(_Printed):
    """A certified Smith decomposition U·A·V = D; entries are exact, in the
    language's syntax (they parse back). ``U`` and ``V`` are None in the
    determinantal-divisor mode (several symbols, no principal one)."""

    def __init__(self, native: "_native.SmithForm"):
        self._native = native
        self.name: str = native.name
        self.ring: str = native.ring
        self.A: List[List[str]] = native.A
        self.D: List[List[str]] = native.D
        self.U: Optional[List[List[str]]] = native.U
        self.V: Optional[List[List[str]]] = native.V
        self.invariant_factors: List[str] = native.invariant_factors
        self.verified: bool = native.verified
        self.certificate = native.certificate

    def _repr_latex_(self) -> str:
        # Jupyter renders one math block: the LaTeX lines of the printer.
        lines = [
            l[3:-3].strip()
            for l in self.latex().splitlines()
            if l.startswith(r"\[") and l.endswith(r"\]")
        ]
        return "$$\\begin{aligned}" + r" \\ ".join(
            l.replace(" = ", " &= ", 1) if " = " in l else "& " + l for l in lines
        ) + "\\end{aligned}$$"

    def __repr__(self) -> str:
        return f"SmithForm({self.name} over {self.ring}: invariant factors {', '.join(self.invariant_factors)})"


class Reduction(_Printed):
    """One equation for one unknown of an operator system: the commutative
    eliminant (``eliminant``: its operator in the language's syntax), the
    ordered elimination (``ordered``, or None) and the commuted pairs."""

    def __init__(self, native: "_native.Reduction"):
        self._native = native
        self.unknown: str = native.unknown
        text, latex, lmx = native.eliminant
        self.eliminant: str = lmx
        self.eliminant_latex: str = latex
        ordered = native.ordered
        self.ordered: Optional[str] = None if ordered is None else ordered[2]
        self.ordered_latex: Optional[str] = None if ordered is None else ordered[1]
        self.commuted_pairs = native.commuted_pairs
        self.pieces = native.pieces

    def _repr_latex_(self) -> str:
        ordered = f"\\quad\\text{{ordered: }} {self.ordered_latex}" if self.ordered_latex else ""
        return f"$\\left({self.eliminant_latex}\\right) {self.unknown}{ordered}$"

    def __repr__(self) -> str:
        return f"Reduction(for {self.unknown}: ({self.eliminant}) {self.unknown})"


class Problem:
    """One parsed, validated lambdamat source file."""

    def __init__(self, native: "_native.Problem"):
        self._native = native

    @staticmethod
    def from_file(path: Union[str, "os.PathLike[str]"]) -> "Problem":
        return Problem(_native.Problem.from_file(os.fspath(path)))

    @staticmethod
    def from_source(text: str, name: str = "<source>") -> "Problem":
        return Problem(_native.Problem.from_source(text, name))

    @property
    def params(self) -> List[tuple]:
        """``[(name, value as written), ...]`` in definition order."""
        return self._native.params

    @property
    def name(self) -> str:
        return self._native.name

    @property
    def source(self) -> str:
        return self._native.source

    def solve(
        self,
        set: Optional[Mapping[str, Union[str, int, float]]] = None,
        tol: float = 1e-10,
        method: Optional[str] = None,
        max_level: Optional[int] = None,
    ) -> Solution:
        """Solves the system with parameters ``set`` (strings as written,
        ints in full, floats as their shortest decimal: exactly as
        ``--set`` reads them)."""
        items = None if set is None else list(set.items())
        return Solution(self._native.solve(items, tol, method, max_level))

    def smith(self, principal: Optional[str] = None, matrix: Optional[str] = None) -> SmithForm:
        """The certified Smith form of the file's matrix or, when it has
        none, of its operator system's λ-matrix."""
        return SmithForm(self._native.smith(principal, matrix))

    def reduce(self, target: Optional[str] = None) -> Reduction:
        return Reduction(self._native.reduce(target))

    def codegen(self, target: Optional[str] = None) -> str:
        """The Rust source ``lambdamat codegen`` writes."""
        return self._native.codegen(target)

    def __repr__(self) -> str:
        return f"Problem({self.name!r})"


def hertz(nu: float, mu: Optional[float] = None, c: Optional[float] = None, tol: float = 1e-10) -> Solution:
    """The Hertz contact problem with finite friction for Poisson's ratio
    ``nu`` and exactly one of the friction coefficient ``mu`` (find the
    stick radius ``scalars['c']``) or the stick radius ``c`` (find
    ``scalars['mu']``); the same computation as ``lambdamat hertz``."""
    return Solution(_native.hertz(nu, mu, c, tol))


def _point(source: str, name: str, params: Dict[str, Any], tol: float) -> Dict[str, Any]:
    """One sweep row (runs on a worker: only plain values cross)."""
    row: Dict[str, Any] = dict(params)
    # NumPy scalars become the Python numbers they hold.
    items = [(k, v.item() if hasattr(v, "item") else v) for k, v in params.items()]
    try:
        s = _native.Problem.from_source(source, name).solve(items, tol, None, None)
    except (LambdamatError, TypeError) as e:
        row.update(converged=False, error=str(e))
        return row
    row.update(s.scalars)
    row.update(s.outputs)
    row.update({f"{k}_err": v for k, v in s.error_estimates.items()})
    row.update(converged=s.converged, error=None)
    return row


def sweep(
    problem_or_path: Union[Problem, str, "os.PathLike[str]"],
    grid: Mapping[str, Iterable[Any]],
    client: Any = None,
    tol: float = 1e-10,
) -> List[Dict[str, Any]]:
    """Solves at every point of the Cartesian product of ``grid`` (in the
    dict's key order, the last key varying fastest) and returns one row per
    point: the parameters, the scalars and outputs, each estimate as
    ``<name>_err``, ``converged`` and ``error`` (the message, or None). A
    failed point is a row with its error; the sweep goes on.

    With a ``dask.distributed.Client`` the points run on its workers (one
    task per point); the rows equal the serial ones."""
    problem = problem_or_path if isinstance(problem_or_path, Problem) else Problem.from_file(problem_or_path)
    keys = list(grid.keys())
    points = [dict(zip(keys, values)) for values in itertools.product(*(list(grid[k]) for k in keys))]
    source, name = problem.source, problem.name
    if client is None:
        return [_point(source, name, p, tol) for p in points]
    futures = client.map(_point, [source] * len(points), [name] * len(points), points, [tol] * len(points), pure=False)
    return client.gather(futures)
