"""The compiled module under ``eom`` (PyO3). Use the package ``eom``; these are its parts."""

from os import PathLike
from typing import Any

import numpy as np
import numpy.typing as npt

class Scene:
    """A scene read and checked by the library's reader."""

    @staticmethod
    def load(path: str | PathLike[str], name: str | None = None) -> Scene:
        """Reads and checks the scene file at ``path``; ``name`` names it in errors and the
        summary (default: the path as given)."""
    @staticmethod
    def from_text(text: str, name: str = "<scene>", base: str | PathLike[str] = ".") -> Scene:
        """Reads and checks scene text; ``base`` is where a file it names is found."""
    @staticmethod
    def from_table_json(table: str, name: str = "<scene>", base: str | PathLike[str] = ".") -> Scene:
        """Reads and checks a scene's tables given as JSON text."""
    def with_values(self, values: dict[str, Any]) -> Scene:
        """The scene with each dotted key of ``values`` (a JSON object) set, checked again."""
    def cases(self) -> list[tuple[int, str, Scene]]:
        """The ``[sweep]``'s cases: (index, the swept values as JSON, the case's scene)."""
    @property
    def kind(self) -> str:
        """``body``, ``ship``, ``vehicle``."""
    @property
    def title(self) -> str:
        """The title."""
    @property
    def name(self) -> str:
        """How errors and the summary name the file."""
    @property
    def base(self) -> str:
        """Where a file the scene names is found."""
    @property
    def folders(self) -> list[str]:
        """What ``eom run`` writes at the top of its folder besides summary.json."""
    @property
    def table_json(self) -> str:
        """The scene's tables as JSON text."""
    def run(
        self,
    ) -> tuple[
        bytes,
        str,
        list[str],
        bool,
        list[tuple[str, list[str], npt.NDArray[np.float64]]],
        BaseException | None,
    ]:
        """Runs every run: (summary.json's bytes, the report, the warnings, stopped early,
        each run's (path, header, rows), the exception of a run that failed keeping its
        rows). Releases the GIL; Ctrl-C raises KeyboardInterrupt."""
    def monte_carlo(self) -> tuple[bytes, str]:
        """Runs the scene's ``[uncertainty]``, every case: (uncertainty.json's bytes,
        uncertainty.csv's text). Releases the GIL; Ctrl-C raises KeyboardInterrupt."""
    def model(self) -> Model:
        """The scene's model."""
    def linear(self) -> tuple[str, str]:
        """(linear.json's object as JSON text, the text report)."""

class Model:
    """A scene's model over many states at once."""

    @property
    def name(self) -> str: ...
    @property
    def state_names(self) -> list[str]: ...
    @property
    def input_names(self) -> list[str]: ...
    def rhs(
        self, x: npt.NDArray[np.float64], u: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.float64]:
        """f(x, u) at each column: x (n, N), u (m, N) → (n, N)."""
    def jacobian(
        self,
        x: npt.NDArray[np.float64],
        u: npt.NDArray[np.float64],
        by_inputs: bool = False,
    ) -> npt.NDArray[np.float64]:
        """∂f/∂x at each column, (n, n, N); with ``by_inputs``, ∂f/∂u, (n, m, N)."""

def derive() -> tuple[str, list[tuple[str, str, int, str | None]]]:
    """``eom derive``: (the Markdown report, each equation's (number, description,
    components, why it is not proved or None))."""

def mass(path: str | PathLike[str], about: list[float] | None = None) -> str:
    """``eom mass --json`` of a body file, as JSON text."""

