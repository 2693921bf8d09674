"""eom from Python: rigid bodies, ships, underwater vehicles and aircraft, their equations of motion
derived and proved, run from scene files.

>>> import eom
>>> scene = eom.Scene.load("scenes/mariner.toml")
>>> scene.kind, scene.runs
('ship', ['turning_circle_35', 'zigzag_10_10', 'zigzag_20_20'])
>>> result = scene.run("turning_circle_35")          # the same bits as `eom run` writes
>>> track = result.trajectories["turning_circle_35/port"]
>>> track["x"], track.units["x"]                       # numpy arrays, column names, units
>>> result.summary["manoeuvre"]["turning_circle_35"]["tactical_diameter_m"]
>>> model = scene.model()                                # rhs(x, u) and its Jacobians
>>> model.rhs(states, inputs)                            # (n, N) in, (n, N) out, one call
>>> linear = eom.Scene.load("scenes/remus100.toml").linearise()
>>> linear.A, linear.x_names, linear.state_space()       # python-control, if installed

Everything calls the library (the crate ``eom``), not the ``eom`` binary. Errors are
:class:`EomError`'s subclasses with eom's message and the key path (``err.key``); a run
releases the GIL and stops on Ctrl-C (raising :class:`KeyboardInterrupt`).
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, Iterable, Mapping, Sequence

import numpy as np

from . import _eom
from ._errors import (
    EomError,
    FileError,
    InternalError,
    InvalidValue,
    OutputError,
    RunError,
    SceneError,
    ShapeError,
)

__all__ = [
    "Scene",
    "RunResult",
    "MonteCarloResult",
    "Trajectory",
    "Model",
    "Linear",
    "Case",
    "Derivation",
    "Equation",
    "derive",
    "mass",
    "EomError",
    "SceneError",
    "FileError",
    "RunError",
    "OutputError",
    "InternalError",
    "ShapeError",
    "InvalidValue",
]

__version__ = "0.1.0"

#: The file a scene that is one run writes its rows into, among :attr:`Scene.folders`.
TRAJECTORY = "trajectory.csv"


def _split_header(column: str) -> tuple[str, str]:
    """``u[m/s]`` → (``u``, ``m/s``): trajectory.csv's header names each column with its unit."""
    if column.endswith("]") and "[" in column:
        name, unit = column[:-1].split("[", 1)
        return name, unit
    return column, ""


class Trajectory:
    """One run's rows: the numbers trajectory.csv holds, as one float64 array.

    Attributes:
        path: the run's path under the output folder (``turning_circle_35/port``; empty for
            a scene that is one run).
        columns: trajectory.csv's header, each name with its unit (``t[s]``, ``u[m/s]``).
        names: the columns' names (``t``, ``u``, …).
        units: each name's unit, by name (``{"t": "s", "u": "m/s"}``).
        data: the rows, shape (rows, columns), float64; ``data[:, j]`` is column j.

    ``trajectory["x"]`` is a column by name (a view of ``data``), ``trajectory.t`` the times.
    """

    def __init__(self, path: str, columns: Sequence[str], data: np.ndarray):
        self.path = path
        self.columns = list(columns)
        self.names = [_split_header(c)[0] for c in self.columns]
        self.units = dict(_split_header(c) for c in self.columns)
        self.data = data

    def __getitem__(self, name: str) -> np.ndarray:
        """The column ``name`` (``x``, or with its unit, ``x[m]``)."""
        for index, (short, full) in enumerate(zip(self.names, self.columns)):
            if name in (short, full):
                return self.data[:, index]
        raise KeyError(f"{name!r}: the run {self.path!r} has the columns {', '.join(self.names)}")

    def __contains__(self, name: object) -> bool:
        return name in self.names or name in self.columns

    def __len__(self) -> int:
        return self.data.shape[0]

    @property
    def t(self) -> np.ndarray:
        """The times, s."""
        return self.data[:, 0]

    def as_dict(self) -> dict[str, np.ndarray]:
        """Every column by name (a pandas ``DataFrame(trajectory.as_dict())`` takes it)."""
        return {name: self.data[:, j] for j, name in enumerate(self.names)}

    def __repr__(self) -> str:
        return f"<eom.Trajectory {self.path!r}: {len(self)} rows × {', '.join(self.names)}>"


@dataclass
class RunResult:
    """What a scene's run gave: the same as ``eom run`` writes, in memory.

    Attributes:
        summary: summary.json as ``json.load`` reads it (``wall_seconds`` is this run's).
        report: what ``eom run`` prints.
        warnings: what the run did not stop for but a reader should know.
        stopped: whether the run stopped before every run the scene asks for had run.
        trajectories: each run's rows, by its path (``""`` for a scene that is one run,
            ``turning_circle_35/port`` for a ship's manoeuvre to port).
    """

    summary: dict[str, Any]
    report: str
    warnings: list[str]
    stopped: bool
    trajectories: dict[str, Trajectory] = field(default_factory=dict)

    @property
    def trajectory(self) -> Trajectory:
        """The one run of a scene that is one run (a body's), or the first run's."""
        return next(iter(self.trajectories.values()))


@dataclass
class MonteCarloResult:
    """What a scene's Monte Carlo gave: what ``eom run`` writes of it, in memory.

    Attributes:
        report: uncertainty.json as ``json.load`` reads it: each figure's spread, each
            verdict's pass rate, the failed cases and their reasons.
        table: uncertainty.csv's text, a line per case (its values, figures, verdicts and
            error), the same bytes as the file.
    """

    report: dict[str, Any]
    table: str


@dataclass
class Case:
    """One case of a scene's ``[sweep]``, as ``eom run`` makes it.

    Attributes:
        index: its number, from 0 (``case-0003`` is index 3).
        values: the swept keys and this case's values.
        scene: the scene with those values set.
    """

    index: int
    values: dict[str, Any]
    scene: "Scene"


class Scene:
    """A scene file read and checked: its kind, title, runs and keys; its run, its model and
    its linearisation.

    Read one with :meth:`load` (a file) or :meth:`from_text` (TOML text). Every value is
    checked as ``eom run`` checks it; an error raises :class:`SceneError` with ``key``.
    """

    def __init__(self, native: _eom.Scene):
        self._native = native

    @staticmethod
    def load(path: str | os.PathLike[str], name: str | None = None) -> "Scene":
        """Reads and checks the scene file at ``path``.

        ``name`` is how errors and the summary name the file (by default the path as given,
        as ``eom run PATH`` names it). A file a scene names (``body.file``) is found relative
        to the scene's folder.
        """
        return Scene(_eom.Scene.load(os.fspath(path), name))

    @staticmethod
    def from_text(
        text: str, name: str = "<scene>", base: str | os.PathLike[str] = "."
    ) -> "Scene":
        """Reads and checks scene text (TOML); ``base`` is where a file it names is found."""
        return Scene(_eom.Scene.from_text(text, name, os.fspath(base)))

    @staticmethod
    def from_table(
        table: Mapping[str, Any], name: str = "<scene>", base: str | os.PathLike[str] = "."
    ) -> "Scene":
        """Reads and checks a scene given as its tables (a dict as :attr:`table` gives it)."""
        return Scene(_eom.Scene.from_table_json(json.dumps(table), name, os.fspath(base)))

    @property
    def kind(self) -> str:
        """The kind of scene (``body``, ``ship``, ``vehicle``, ``aircraft``)."""
        return self._native.kind

    @property
    def title(self) -> str:
        """The scene's title."""
        return self._native.title

    @property
    def name(self) -> str:
        """How errors and the summary name the file."""
        return self._native.name

    @property
    def folders(self) -> list[str]:
        """What ``eom run`` writes at the top of its folder besides summary.json: each
        manoeuvre's folder, or ``trajectory.csv`` for a scene that is one run."""
        return list(self._native.folders)

    @property
    def runs(self) -> list[str]:
        """The scene's manoeuvres by name (each a folder of ``eom run``; a ship's runs each
        to port and starboard beneath it), or ``[]`` for a scene that is one run."""
        return [f for f in self._native.folders if f != TRAJECTORY]

    @property
    def table(self) -> dict[str, Any]:
        """The scene's tables as read (a fresh dict: change it and pass it to
        :meth:`from_table`)."""
        return json.loads(self._native.table_json)

    @property
    def keys(self) -> list[str]:
        """Every value's key path in the scene (``integrator.step``,
        ``manoeuvre[0].rudder_deg``), as errors and :meth:`with_values` name them."""
        return list(_key_paths(self.table, ""))

    def with_values(self, values: Mapping[str, Any]) -> "Scene":
        """The scene with each key path of ``values`` set (``{"hydrodynamics.Nr": -0.0017}``,
        ``{"manoeuvre[0].rudder_deg": 20.0}``), read and checked again: what one case of a
        ``[sweep]`` is."""
        return Scene(self._native.with_values(dict(values)))

    def cases(self) -> list[Case]:
        """The cases of the scene's ``[sweep]``, as ``eom run`` runs them (``[]`` without
        one)."""
        return [
            Case(index, json.loads(values), Scene(native))
            for index, values, native in self._native.cases()
        ]

    def run(self, manoeuvre: str | None = None) -> RunResult:
        """Runs the scene, or only its manoeuvre ``manoeuvre`` (one of :attr:`runs`), and
        returns its rows and summary: the numbers ``eom run`` writes into trajectory.csv and
        summary.json, bit for bit (the summary's ``wall_seconds`` aside).

        A scene with a ``[sweep]`` runs as written, its sweep aside: its cases are
        :meth:`cases`, each a scene to run. A scene with an ``[uncertainty]`` raises
        :class:`SceneError` (key ``uncertainty``): :meth:`monte_carlo` runs it.

        The GIL is released while it runs; Ctrl-C stops it at its next row and raises
        :class:`KeyboardInterrupt`. A run that fails where it fails (gimbal lock) raises
        :class:`RunError` with what it kept in ``error.result``.
        """
        scene = self if manoeuvre is None else self._only(manoeuvre)
        summary, report, warnings, stopped, runs, failure = scene._native.run()
        result = RunResult(
            summary=json.loads(summary),
            report=report,
            warnings=list(warnings),
            stopped=stopped,
            trajectories={path: Trajectory(path, header, data) for path, header, data in runs},
        )
        if failure is not None:
            failure.result = result
            raise failure
        return result

    def monte_carlo(self) -> MonteCarloResult:
        """Runs the scene's ``[uncertainty]`` as ``eom run`` does, every case on every core:
        its report and table are the bytes of the command's uncertainty.json and
        uncertainty.csv. A scene without one raises :class:`SceneError`, as does a law the
        scene refuses at one spread from its value (a mass varied against a fixed weight).

        Cases that fail are in the report (``failed``, ``failure_reasons``) and raise
        nothing. The GIL is released while the cases run; Ctrl-C raises
        :class:`KeyboardInterrupt`.
        """
        report, table = self._native.monte_carlo()
        return MonteCarloResult(report=json.loads(report), table=table)

    def _only(self, manoeuvre: str) -> "Scene":
        """The scene with its one manoeuvre ``manoeuvre``."""
        table = self.table
        entries = table.get("manoeuvre")
        runs = self.runs
        if not isinstance(entries, list) or len(entries) != len(runs):
            raise SceneError(
                f"{self.name} has no manoeuvres to choose from: it is one run",
                key="manoeuvre",
                file=self.name,
            )
        if manoeuvre not in runs:
            raise SceneError(
                f"{manoeuvre!r} is not one of the scene's manoeuvres: {', '.join(runs)}",
                key="manoeuvre",
                file=self.name,
            )
        entry = dict(entries[runs.index(manoeuvre)])
        entry["name"] = manoeuvre
        table["manoeuvre"] = [entry]
        return Scene(_eom.Scene.from_table_json(json.dumps(table), self.name, self._base()))

    def _base(self) -> str:
        return os.fspath(self._native.base)

    def model(self) -> "Model":
        """The scene's model as it stands (no loads, schedules or steering gear): its names,
        ``rhs(x, u)`` and its proved Jacobians, over many states at once."""
        return Model(self._native.model())

    def linearise(self) -> "Linear":
        """The scene linearised at its operating point (its ``[linear]`` table, trimmed
        where it names free variables; a ship's straight course, a vehicle's cruise): what
        ``eom linear`` reports, with A, B, C, D as numpy arrays."""
        report, text = self._native.linear()
        return Linear(json.loads(report), text)

    def __repr__(self) -> str:
        return f"<eom.Scene {self.name!r} ({self.kind}): {self.title!r}>"


def _key_paths(value: Any, prefix: str) -> Iterable[str]:
    if isinstance(value, dict):
        for key, inner in value.items():
            yield from _key_paths(inner, f"{prefix}.{key}" if prefix else key)
    elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
        for index, inner in enumerate(value):
            yield from _key_paths(inner, f"{prefix}[{index}]")
    else:
        yield prefix


def _real(name: str, value: Any) -> np.ndarray:
    """``value`` as an array of doubles; complex numbers are refused rather than cast, which
    would drop their imaginary parts."""
    array = np.asarray(value)
    if np.iscomplexobj(array):
        raise InvalidValue(
            f"{name} is complex ({array.dtype}): the model takes real states and inputs "
            f"(pass {name}.real where the imaginary parts are zero)"
        )
    return np.asarray(array, dtype=np.float64)


class Model:
    """A scene's model: f(x, u), ∂f/∂x and ∂f/∂u, evaluated by the compiled (proved) program
    over many states in one call, with the GIL released.

    States are columns: ``x`` is (n, N), ``u`` is (m, N), or (m,) for the same inputs at
    every state, or None for zero inputs; a single state (n,) gives a single answer.
    """

    def __init__(self, native: _eom.Model):
        self._native = native

    @property
    def name(self) -> str:
        """The model's name (``ship``, ``spatial_principal_quaternion``)."""
        return self._native.name

    @property
    def state_names(self) -> list[str]:
        """Every state entry's name, in the model's layout: the rows of ``x``."""
        return list(self._native.state_names)

    @property
    def input_names(self) -> list[str]:
        """Every input's name: the rows of ``u``."""
        return list(self._native.input_names)

    def _arrays(self, x: Any, u: Any) -> tuple[np.ndarray, np.ndarray, bool]:
        x = _real("x", x)
        single = x.ndim == 1
        if single:
            x = x[:, None]
        if x.ndim != 2:
            raise ShapeError(
                f"x has shape {x.shape}; the model {self.name} takes "
                f"({len(self.state_names)}, N) or ({len(self.state_names)},)"
            )
        m, count = len(self.input_names), x.shape[1]
        if u is None:
            u = np.zeros((m, count))
        else:
            u = _real("u", u)
            if u.ndim == 1:
                if u.shape[0] != m:
                    raise ShapeError(
                        f"u has shape {u.shape}; the model {self.name} takes ({m},) or ({m}, N)"
                    )
                u = np.broadcast_to(u[:, None], (m, count))
            if u.ndim != 2:
                raise ShapeError(f"u has shape {u.shape}; the model {self.name} takes ({m}, N)")
        return np.ascontiguousarray(x), np.ascontiguousarray(u), single

    def rhs(self, x: Any, u: Any = None) -> np.ndarray:
        """f(x, u): the rates, (n, N) for x (n, N); (n,) for a single state."""
        x, u, single = self._arrays(x, u)
        rates = self._native.rhs(x, u)
        return rates[:, 0] if single else rates

    def state_jacobian(self, x: Any, u: Any = None) -> np.ndarray:
        """∂f/∂x, the proved Jacobian: (n, n, N), entry [i, j, k] the derivative of the rate
        of state i by state j at column k; (n, n) for a single state."""
        x, u, single = self._arrays(x, u)
        a = self._native.jacobian(x, u)
        return a[:, :, 0] if single else a

    def input_jacobian(self, x: Any, u: Any = None) -> np.ndarray:
        """∂f/∂u, the proved Jacobian: (n, m, N); (n, m) for a single state."""
        x, u, single = self._arrays(x, u)
        b = self._native.jacobian(x, u, by_inputs=True)
        return b[:, :, 0] if single else b

    def __repr__(self) -> str:
        return repr(self._native)


class Linear:
    """A scene linearised at its operating point: what ``eom linear --json`` prints (and
    ``--out`` writes as linear.json), with the matrices as numpy arrays.

    Attributes:
        A, B, C, D: ẋ = A x + B u, y = C x + D u about the point (deviations from x0, u0).
        x_names, u_names, y_names: the names of the reduced state, the inputs, the outputs.
        x_units, u_units, y_units: their units (None where a name has none).
        x0, u0: the point.
        eigenvalues: A's eigenvalues (complex), largest real part first.
        modes: each mode (eigenvalue, period, damping ratio, times to double and to half,
            dominant states, name) as a dict.
        trim: the free variables solved for and the Newton steps, or None.
        json: the whole report as a dict (linear.json's keys).
        report: the text report, as ``eom linear`` prints it.
    """

    def __init__(self, report: dict[str, Any], text: str):
        self.json = report
        self.report = text
        self.A = np.array(report["A"], dtype=np.float64).reshape(len(report["x_names"]), -1)
        self.B = np.array(report["B"], dtype=np.float64).reshape(len(report["x_names"]), -1)
        self.C = np.array(report["C"], dtype=np.float64).reshape(len(report["y_names"]), -1)
        self.D = np.array(report["D"], dtype=np.float64).reshape(len(report["y_names"]), -1)
        self.x_names: list[str] = report["x_names"]
        self.u_names: list[str] = report["u_names"]
        self.y_names: list[str] = report["y_names"]
        self.x_units: list[str | None] = report["x_units"]
        self.u_units: list[str | None] = report["u_units"]
        self.y_units: list[str | None] = report["y_units"]
        self.x0 = np.array(report["x0"], dtype=np.float64)
        self.u0 = np.array(report["u0"], dtype=np.float64)
        self.eigenvalues = np.array([complex(e["re"], e["im"]) for e in report["eigenvalues"]])
        self.modes: list[dict[str, Any]] = report["modes"]
        self.trim: dict[str, Any] | None = report.get("trim")
        self.stable: bool | None = report.get("stable")

    def state_space(self) -> Any:
        """The model as a python-control ``StateSpace`` with the names of x, u and y
        (``pip install control``; ImportError without it)."""
        import control

        return control.ss(
            self.A,
            self.B,
            self.C,
            self.D,
            inputs=self.u_names,
            outputs=self.y_names,
            states=self.x_names,
        )

    def __repr__(self) -> str:
        return (
            f"<eom.Linear {self.json.get('model')}: x = [{', '.join(self.x_names)}], "
            f"u = [{', '.join(self.u_names)}], {self.json.get('verdict')}>"
        )


@dataclass
class Equation:
    """One equation of the chapter as ``eom derive`` derives it.

    Attributes:
        number: the chapter's number (``4.51``).
        description: what it is, in one line.
        components: how many scalar components were proved.
        proved: whether the derived form equals the book's.
        why: why not, where it is not proved.
    """

    number: str
    description: str
    components: int
    proved: bool
    why: str | None = None


@dataclass
class Derivation:
    """The derivation report: every equation derived from its vector definitions and proved
    equal to the chapter's form, as ``eom derive`` prints it.

    Attributes:
        markdown: the report, as ``eom derive`` prints it.
        equations: each equation, with whether it is proved.
    """

    markdown: str
    equations: list[Equation]

    @property
    def all_proved(self) -> bool:
        """Whether every equation is proved."""
        return all(e.proved for e in self.equations)


def derive() -> Derivation:
    """Derives every equation afresh and proves it (the GIL released): ``eom derive``."""
    markdown, equations = _eom.derive()
    return Derivation(
        markdown,
        [Equation(n, d, c, why is None, why) for n, d, c, why in equations],
    )


def mass(path: str | os.PathLike[str], about: Sequence[float] | None = None) -> dict[str, Any]:
    """The mass properties of a body file, as ``eom mass --json`` prints them: ``mass``,
    ``centre_of_gravity``, ``inertia_about_g``, ``radii_of_gyration``, the principal moments,
    axes and radii, each part, and with ``about`` (a point in body axes) the tensor about it
    (4.23)."""
    point = None if about is None else [float(v) for v in about]
    if point is not None and len(point) != 3:
        raise ShapeError(f"about has {len(point)} numbers; a point has 3 (x, y, z)")
    return json.loads(_eom.mass(os.fspath(path), point))
