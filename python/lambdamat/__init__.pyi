import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

class LambdamatError(Exception):
    exit_code: int
    file: Optional[str]
    line: Optional[int]
    column: Optional[int]
    locations: List[Tuple[str, int, int]]

class InvalidInput(LambdamatError): ...
class ComputationFailed(LambdamatError): ...

class Field:
    @property
    def x(self) -> npt.NDArray[np.float64]: ...
    @property
    def values(self) -> npt.NDArray[np.float64]: ...
    @property
    def weight(self) -> str: ...
    @property
    def error_estimate(self) -> float: ...

class Solution:
    converged: bool
    scalars: Dict[str, float]
    outputs: Dict[str, float]
    error_estimates: Dict[str, float]
    unknowns: Dict[str, Field]
    warnings: List[str]
    def to_json(self) -> str: ...

class SmithForm:
    name: str
    ring: str
    A: List[List[str]]
    D: List[List[str]]
    U: Optional[List[List[str]]]
    V: Optional[List[List[str]]]
    invariant_factors: List[str]
    verified: bool
    certificate: List[Tuple[str, bool, str]]
    def text(self) -> str: ...
    def latex(self) -> str: ...
    def to_json(self) -> str: ...
    def _repr_latex_(self) -> str: ...

class Reduction:
    unknown: str
    eliminant: str
    eliminant_latex: str
    ordered: Optional[str]
    ordered_latex: Optional[str]
    commuted_pairs: List[Tuple[str, str]]
    pieces: List[Optional[str]]
    def text(self) -> str: ...
    def latex(self) -> str: ...
    def to_json(self) -> str: ...
    def _repr_latex_(self) -> str: ...

class Problem:
    @staticmethod
    def from_file(path: Union[str, os.PathLike[str]]) -> Problem: ...
    @staticmethod
    def from_source(text: str, name: str = "<source>") -> Problem: ...
    @property
    def params(self) -> List[Tuple[str, str]]: ...
    @property
    def name(self) -> str: ...
    @property
    def source(self) -> str: ...
    def solve(
        self,
        set: Optional[Mapping[str, Union[str, int, float]]] = None,
        tol: float = 1e-10,
        method: Optional[str] = None,
        max_level: Optional[int] = None,
    ) -> Solution: ...
    def smith(self, principal: Optional[str] = None, matrix: Optional[str] = None) -> SmithForm: ...
    def reduce(self, target: Optional[str] = None) -> Reduction: ...
    def codegen(self, target: Optional[str] = None) -> str: ...

def hertz(nu: float, mu: Optional[float] = None, c: Optional[float] = None, tol: float = 1e-10) -> Solution: ...
def sweep(
    problem_or_path: Union[Problem, str, os.PathLike[str]],
    grid: Mapping[str, Iterable[Any]],
    client: Any = None,
    tol: float = 1e-10,
) -> List[Dict[str, Any]]: ...
