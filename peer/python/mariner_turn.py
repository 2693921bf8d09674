"""The Mariner's 35° turning circle as a careful Python user writes it: numpy and scipy, no eom.

The model is the one `eom run scenes/mariner.toml` integrates, written out by hand from the
scene: Fossen's 4.46 for a ship whose origin is midship, with the Chislett & Strøm-Tejsen
table in the prime system (forces over ½ρU²L², moments over ½ρU²L³; u′ = (u − U₀)/U,
v′ = v/U, r′ = rL/U, U = √(u² + v²)). The published table folds rigid-body terms into six
coefficients; they are taken back out (as eom's summary, `model.conversion`, says it does) and
4.46 writes them itself: M(vr + x_G r²), −Mur, −M x_G ur. The steering gear is the scene's:
the command saturated at δ_max = 40°, a first-order lag δ̇ = (δ_c − δ)/T with T = 1 s, its
rate clamped to ±δ̇_max = 5°/s. The state is eom's, (u, v, r, X, Y, ψ, δ) of midship, starting
from the approach (u = U₀, everything else zero), the rudder put over at t = 0.

Two ways to integrate it:

- ``--method rk4``: fixed-step classical RK4 (1 s by default), numpy-vectorised over the cases
  (the state is an array of shape (7, N)); one grid for all cases, which steps onto the instant
  the steering gear's rate limit lets go (a kink in δ̇, the same for every case) and onto each
  whole second (the rows the steady-turn check reads).
- ``--method solve_ivp``: ``scipy.integrate.solve_ivp`` once per case, RK45 (Dormand–Prince,
  eom's DOPRI5) at rtol = atol = 1e-8 by default (README.md says why), events for the 90° and
  180° heading changes, a terminal event where the rate limit lets go (the integration restarts
  there, so no step straddles the kink).

The cases: case 0 is the published table; case k ≥ 1 multiplies every hydrodynamic
coefficient (the 40 force-polynomial terms after the rigid-body terms are taken out, one of
which, X_vr, is then zero, and the 5 added masses) by 1 + σz, z standard normal truncated to
|z| ≤ 3 (redrawn beyond), drawn from case k's own stream (``numpy.random.default_rng([seed,
k])``), so a case is the same in any batch. eom's ``examples/monte_carlo.rs`` draws the same
distribution from its own generator: the cases are not eom's, case by case.

The figures, as eom defines them (``src/kinds/ship/manoeuvre.rs``, ``src/manoeuvring/course.rs``),
from the execute (t = 0, ψ₀ = 0, midship at the origin):

- ``advance_90_m``, ``transfer_90_m``: midship's displacement along and (its magnitude) across
  the approach heading where |ψ − ψ₀| first reaches 90°;
- ``tactical_diameter_m``: the magnitude of the displacement across it where |ψ − ψ₀| first
  reaches 180°;
- ``t_90_s``, ``t_180_s``: those instants;
- ``steady_turning_radius_m`` = U/|r|, ``steady_speed_m_s`` = U at the end of the run (1500 s),
  given only if the heading has changed by 540° or more by then and, over the last 360° of
  heading change, U and r each stay within 1 % of their final values (checked on the rows, one
  a second);
- each crossing is the integrated solution's, not the nearest step's: g = (ψ − ψ₀)² − angle²
  changes sign within a step, and the crossing is found on that step taken again from its start
  with a shorter length (RK4), or on the dense output (solve_ivp's events);
- a figure is not given if the ship went astern (u < 0) or stopped (U below 5 % of the approach
  speed) before it was read, nor a steady turn if the yaw rate changed sign against the turn once
  the heading had changed by 10° (none of which happens to the Mariner).

    python peer/python/mariner_turn.py --method rk4 --cases 1000 --reference /tmp/ref/summary.json
    python peer/python/mariner_turn.py --method solve_ivp --cases 100

See peer/python/README.md for the numbers measured.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import scipy
from scipy.integrate import solve_ivp

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "mariner.toml"

# The force polynomial's terms as this file writes them; the scene must give exactly these.
X_TERMS = ("Xu", "Xuu", "Xuuu", "Xvv", "Xrr", "Xdd", "Xudd", "Xrv", "Xvd", "Xuvd")
SIDE_TERMS = ("v", "r", "vvv", "vvr", "vu", "ru", "d", "ddd", "ud", "uud", "vdd", "vvd", "0", "0u", "0uu")
Y_TERMS = tuple("Y" + t for t in SIDE_TERMS)
N_TERMS = tuple("N" + t for t in SIDE_TERMS)
TERMS = X_TERMS + Y_TERMS + N_TERMS
ADDED_MASS = ("Xudot", "Yvdot", "Yrdot", "Nvdot", "Nrdot")
COEFFICIENTS = TERMS + ADDED_MASS

# The figures' conditions (src/manoeuvring/course.rs).
STEADY_TOLERANCE = 0.01
STOPPED_FRACTION = 0.05
TURN_ESTABLISHED = math.pi / 18.0
STEADY_AFTER = 3.0 * math.pi

FIGURES = (
    "advance_90_m",
    "transfer_90_m",
    "tactical_diameter_m",
    "steady_turning_radius_m",
    "steady_speed_m_s",
    "t_90_s",
    "t_180_s",
)


@dataclass
class Ship:
    """What the scene gives: the body, the published (folded) table, the rudder, the turn."""

    length: float
    density: float
    u0: float
    mass_prime: float
    x_g_prime: float
    izz_prime: float
    table: dict[str, float]
    max_angle: float
    max_rate: float
    time_constant: float
    rudder: float
    duration: float
    every: float

    @classmethod
    def load(cls, scene: Path = SCENE) -> "Ship":
        text = tomllib.loads(Path(scene).read_text())
        body, hydro, rudder = text["body"], text["hydrodynamics"], text["rudder"]
        assert hydro["units"] == "prime" and hydro["rigid_body_terms"] == "folded"
        table = dict(hydro["coefficients"])
        if set(table) != set(COEFFICIENTS):
            raise ValueError(f"the scene's table is not the Mariner's: {sorted(set(table) ^ set(COEFFICIENTS))}")
        turn = next(m for m in text["manoeuvre"] if m["kind"] == "turning_circle")
        return cls(
            length=body["length"],
            density=hydro["density"],
            u0=hydro["design_speed"],
            mass_prime=body["mass_prime"],
            x_g_prime=body["x_g_prime"],
            izz_prime=body["izz_midship_prime"],
            table=table,
            max_angle=math.radians(rudder["max_deg"]),
            max_rate=math.radians(rudder["max_rate_deg_s"]),
            time_constant=rudder["time_constant_s"],
            rudder=math.radians(turn["rudder_deg"]),
            duration=turn["duration_s"],
            every=text.get("output", {}).get("every", 1.0),
        )

    def hydrodynamic(self) -> dict[str, float]:
        """The table with the folded rigid-body terms taken out (hydrodynamic = folded − rigid):
        X_vr holds m′, X_rr m′x_G′; Y_r and Y_ur hold −m′; N_r and N_ur hold −m′x_G′."""
        c = dict(self.table)
        m, mx = self.mass_prime, self.mass_prime * self.x_g_prime
        c["Xrv"] -= m
        c["Xrr"] -= mx
        c["Yr"] += m
        c["Yru"] += m
        c["Nr"] += mx
        c["Nru"] += mx
        return c

    def command(self, side: str) -> float:
        """The saturated command: positive δ turns the Mariner to port (the scene says so)."""
        angle = self.rudder if side == "port" else -self.rudder
        return min(max(angle, -self.max_angle), self.max_angle)

    def rate_limit_releases(self, side: str) -> float | None:
        """When the lag's rate (δ_c − δ)/T, clamped at δ̇_max from δ = 0, falls within the
        clamp: δ̇ has a kink there."""
        excess = abs(self.command(side)) - self.time_constant * self.max_rate
        return excess / self.max_rate if excess > 0 else None


@dataclass
class Cases:
    """N tables: each coefficient an array over the cases (or a float, for one case)."""

    c: dict[str, np.ndarray]
    count: int

    def take(self, index) -> "Cases":
        return Cases({k: v[index] for k, v in self.c.items()}, len(np.atleast_1d(index)))

    def one(self, k: int) -> "Cases":
        """Case k alone, its coefficients as Python floats (for solve_ivp)."""
        return Cases({name: float(v[k]) for name, v in self.c.items()}, 1)


def draw_cases(ship: Ship, count: int, sigma: float = 0.10, seed: int = 2026, first: int = 0) -> Cases:
    """Cases first … first + count − 1: case 0 the published table, case k ≥ 1 every
    hydrodynamic coefficient times 1 + σz, z ~ N(0, 1) truncated to |z| ≤ 3, from its own stream."""
    base = ship.hydrodynamic()
    factors = np.ones((len(COEFFICIENTS), count))
    for i, k in enumerate(range(first, first + count)):
        if k == 0 or sigma == 0.0:
            continue
        rng = np.random.default_rng([seed, k])
        z = rng.standard_normal(len(COEFFICIENTS))
        while np.any(far := np.abs(z) > 3.0):
            z[far] = rng.standard_normal(int(far.sum()))
        factors[:, i] = 1.0 + sigma * z
    return Cases({name: base[name] * factors[j] for j, name in enumerate(COEFFICIENTS)}, count)


class Mariner:
    """4.46 with the Mariner's table: ``rates(x, cases, command)`` for x of shape (7, N) with
    N cases, or of shape (7,) with one case's floats."""

    def __init__(self, ship: Ship, cases: Cases):
        self.ship = ship
        L, half_rho = ship.length, 0.5 * ship.density
        self.L, self.u0 = L, ship.u0
        self.mass = ship.mass_prime * half_rho * L**3
        self.xg = ship.x_g_prime * L
        c = cases.c
        self.c = c
        # The mass matrix [[m11, 0, 0], [0, m22, m23], [0, m32, m33]] per case, inverted by hand.
        m11 = self.mass - c["Xudot"] * half_rho * L**3
        m22 = self.mass - c["Yvdot"] * half_rho * L**3
        m23 = self.mass * self.xg - c["Yrdot"] * half_rho * L**4
        m32 = self.mass * self.xg - c["Nvdot"] * half_rho * L**4
        m33 = (ship.izz_prime - c["Nrdot"]) * half_rho * L**5
        det = m22 * m33 - m23 * m32
        self.i11 = 1.0 / m11
        self.i22, self.i23 = m33 / det, -m23 / det
        self.i32, self.i33 = -m32 / det, m22 / det
        # ½ρL² and ½ρL³: the prime forces and moment to newtons over U².
        self.force_scale, self.moment_scale = half_rho * L**2, half_rho * L**3
        self.max_rate, self.time_constant = ship.max_rate, ship.time_constant

    def rates(self, x, command: float):
        c = self.c
        u, v, r, _, _, psi, delta = x
        speed2 = u * u + v * v
        over = 1.0 / np.sqrt(speed2)
        up, vp, rp, d = (u - self.u0) * over, v * over, r * self.L * over, delta
        up2, vp2, d2 = up * up, vp * vp, d * d
        # The prime forces, the scene's terms each once (Horner in u′ where they share it).
        X = (
            (c["Xu"] + (c["Xuu"] + c["Xuuu"] * up) * up) * up
            + c["Xvv"] * vp2
            + (c["Xrr"] * rp + c["Xrv"] * vp) * rp
            + (c["Xdd"] + c["Xudd"] * up) * d2
            + (c["Xvd"] + c["Xuvd"] * up) * vp * d
        )

        def side(f):
            return (
                c[f + "0"] + (c[f + "0u"] + c[f + "0uu"] * up) * up
                + (c[f + "v"] + c[f + "vu"] * up + c[f + "vvv"] * vp2 + c[f + "vvr"] * vp * rp) * vp
                + (c[f + "r"] + c[f + "ru"] * up) * rp
                + (c[f + "d"] + (c[f + "ud"] + c[f + "uud"] * up) * up + c[f + "ddd"] * d2 + c[f + "vdd"] * vp * d
                   + c[f + "vvd"] * vp2) * d
            )

        Y, N = side("Y"), side("N")
        m, xg = self.mass, self.xg
        mr = m * r
        fx = X * self.force_scale * speed2 + mr * (v + xg * r)
        fy = Y * self.force_scale * speed2 - mr * u
        fn = N * self.moment_scale * speed2 - mr * xg * u
        du = fx * self.i11
        dv = self.i22 * fy + self.i23 * fn
        dr = self.i32 * fy + self.i33 * fn
        cos, sin = np.cos(psi), np.sin(psi)
        lag = (command - delta) * (1.0 / self.time_constant)
        dd = np.minimum(np.maximum(lag, -self.max_rate), self.max_rate)
        return np.array([du, dv, dr, u * cos - v * sin, u * sin + v * cos, r, dd])


def rk4_step(model: Mariner, x, h, command):
    k1 = model.rates(x, command)
    k2 = model.rates(x + (0.5 * h) * k1, command)
    k3 = model.rates(x + (0.5 * h) * k2, command)
    k4 = model.rates(x + h * k3, command)
    return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)


def heading_g(x, angle):
    """g = (ψ − ψ₀)² − angle², ψ₀ = 0: negative until |ψ − ψ₀| reaches `angle`."""
    return x[5] * x[5] - angle * angle


def locate(model: Mariner, cases: Cases, x0, h, angle, command):
    """θ ∈ (0, 1] per case where g(RK4 step of θh from x0) = 0, and the state there: the
    Illinois method, each case iterated until its bracket is within 1e-12 s, then frozen, so a
    case's answer does not depend on the others in the batch."""
    n = x0.shape[1]
    lo, hi = np.zeros(n), np.ones(n)
    g_lo = heading_g(x0, angle)
    x_hi = rk4_step(model, x0, h, command)
    g_hi = heading_g(x_hi, angle)
    last = np.zeros(n)  # which end was kept last time: −1 lo, +1 hi
    active = np.arange(n)
    for _ in range(200):
        active = active[(hi[active] - lo[active]) * h[active] > 1e-12]
        active = active[g_hi[active] != 0.0]
        if active.size == 0:
            break
        sub = Mariner(model.ship, cases.take(active))
        a, b, ga, gb = lo[active], hi[active], g_lo[active], g_hi[active]
        theta = (a * gb - b * ga) / (gb - ga)
        theta = np.where((theta > a) & (theta < b), theta, 0.5 * (a + b))
        x = rk4_step(sub, x0[:, active], theta * h[active], command)
        g = heading_g(x, angle)
        up = g >= 0.0
        # The crossing lies in [a, θ] where g(θ) ≥ 0, else in [θ, b]; Illinois halves the
        # value kept at the end that stays twice in a row.
        keep_lo = up & (last[active] == -1)
        keep_hi = ~up & (last[active] == 1)
        new_lo = np.where(up, a, theta)
        new_hi = np.where(up, theta, b)
        new_glo = np.where(up, np.where(keep_lo, 0.5 * ga, ga), g)
        new_ghi = np.where(up, g, np.where(keep_hi, 0.5 * gb, gb))
        lo[active], hi[active] = new_lo, new_hi
        g_lo[active], g_hi[active] = new_glo, new_ghi
        x_hi[:, active] = np.where(up, x, x_hi[:, active])
        last[active] = np.where(up, -1, 1)
    # The crossing: the first θ found where g ≥ 0 (x_hi there), re-evaluated exactly.
    x_hi = rk4_step(model, x0, hi * h, command)
    return hi, x_hi


@dataclass
class Course:
    """What the figures' conditions need, per case: when the ship first went astern, stopped,
    turned against its turn (NaN: never); the rows (one a second) of U, r and ψ − ψ₀."""

    astern: np.ndarray
    stopped: np.ndarray
    reversed: np.ndarray
    rows_speed: list = field(default_factory=list)
    rows_r: list = field(default_factory=list)
    rows_turned: list = field(default_factory=list)

    @classmethod
    def new(cls, n: int) -> "Course":
        return cls(np.full(n, np.nan), np.full(n, np.nan), np.full(n, np.nan))

    def record(self, t, x, u0):
        u, v, r, turned = x[0], x[1], x[2], x[5]
        speed = np.sqrt(u * u + v * v)
        self.astern = np.where(np.isnan(self.astern) & (u < 0.0), t, self.astern)
        self.stopped = np.where(np.isnan(self.stopped) & (speed < STOPPED_FRACTION * u0), t, self.stopped)
        against = (np.abs(turned) >= TURN_ESTABLISHED) & (r * turned < 0.0)
        self.reversed = np.where(np.isnan(self.reversed) & against, t, self.reversed)
        return speed

    def row(self, t, x, u0):
        speed = self.record(t, x, u0)
        self.rows_speed.append(np.asarray(speed, dtype=np.float32))
        self.rows_r.append(np.asarray(x[2], dtype=np.float32))
        self.rows_turned.append(np.asarray(x[5], dtype=np.float32))

    def broken_by(self, t):
        """Whether a figure read at t (per case) is not given: the ship went astern or stopped
        by then."""
        return (self.astern <= t) | (self.stopped <= t)


def figures(course: Course, at_90, at_180, end) -> dict[str, np.ndarray]:
    """eom's turning-circle figures from the crossings (t, x) and the end (t, x), per case."""
    (t90, x90), (t180, x180), (t_end, x_end) = at_90, at_180, end
    ok90 = ~np.isnan(t90) & ~course.broken_by(t90)
    ok180 = ~np.isnan(t180) & ~course.broken_by(t180)
    nan = np.nan
    out = {
        "advance_90_m": np.where(ok90, x90[3], nan),
        "transfer_90_m": np.where(ok90, np.abs(x90[4]), nan),
        "tactical_diameter_m": np.where(ok180, np.abs(x180[4]), nan),
        "t_90_s": np.where(ok90, t90, nan),
        "t_180_s": np.where(ok180, t180, nan),
    }
    speed_end = np.sqrt(x_end[0] ** 2 + x_end[1] ** 2)
    r_end, turned_end = x_end[2], x_end[5]
    steady = ~course.broken_by(t_end) & np.isnan(course.reversed) & (np.abs(turned_end) >= STEADY_AFTER)
    if course.rows_speed:
        speed = np.array(course.rows_speed, dtype=np.float64)
        r = np.array(course.rows_r, dtype=np.float64)
        turned = np.array(course.rows_turned, dtype=np.float64)
        window = np.abs(turned_end - turned) <= 2.0 * math.pi
        vary_speed = np.max(np.where(window, np.abs(speed - speed_end), 0.0), axis=0) / speed_end
        vary_r = np.max(np.where(window, np.abs(r - r_end), 0.0), axis=0) / np.abs(r_end)
        steady &= (vary_speed <= STEADY_TOLERANCE) & (vary_r <= STEADY_TOLERANCE)
    out["steady_turning_radius_m"] = np.where(steady, speed_end / np.abs(r_end), nan)
    out["steady_speed_m_s"] = np.where(steady, speed_end, nan)
    out["side"] = np.where(turned_end > 0.0, "starboard", "port")
    return out


def grid(ship: Ship, side: str, step: float, duration: float) -> tuple[np.ndarray, np.ndarray]:
    """The RK4 grid: k·step, the rows (each `every`, the scene's second, or each step if the
    step is longer), the instant the rate limit lets go and the end, within [0, duration]; and
    which points are rows."""
    points = np.arange(round(duration / step) + 1) * step
    points = points[points <= duration * (1 + 1e-15)]
    every = max(ship.every, step)
    # Points within a nanosecond of a row are put onto it.
    nearest = np.round(points / every) * every
    points = np.where(np.abs(points - nearest) < 1e-9, nearest, points)
    rows = np.arange(round(duration / every) + 1) * every
    rows = rows[rows <= duration]
    special = [duration]
    kink = ship.rate_limit_releases(side)
    if kink is not None and kink < duration:
        special.append(kink)
    for s in special:
        points = np.where(np.abs(points - s) < 1e-9, s, points)
    points = np.unique(np.concatenate([points, rows, special]))
    return points, np.isin(points, rows)


def turn_rk4(ship: Ship, cases: Cases, step: float, side: str = "port", duration: float | None = None):
    """The turning circle of every case at once, fixed-step RK4 on (7, N): the figures per case."""
    duration = ship.duration if duration is None else duration
    model = Mariner(ship, cases)
    command = ship.command(side)
    n = cases.count
    x = np.zeros((7, n))
    x[0] = ship.u0
    times, is_row = grid(ship, side, step, duration)
    course = Course.new(n)
    course.row(0.0, x, ship.u0)
    angles = (math.pi / 2.0, math.pi)
    # Per event: the step's start (t, x, h) where g first changed sign.
    found = [dict(t=np.full(n, np.nan), x=np.zeros((7, n)), h=np.zeros(n)) for _ in angles]
    pending = [np.ones(n, dtype=bool) for _ in angles]
    for i in range(len(times) - 1):
        t, h = times[i], times[i + 1] - times[i]
        new = rk4_step(model, x, h, command)
        for e, angle in enumerate(angles):
            if not pending[e].any():
                continue
            crossed = pending[e] & (heading_g(new, angle) >= 0.0)
            if crossed.any():
                found[e]["t"][crossed] = t
                found[e]["x"][:, crossed] = x[:, crossed]
                found[e]["h"][crossed] = h
                pending[e] &= ~crossed
        x = new
        if is_row[i + 1]:
            course.row(times[i + 1], x, ship.u0)
        else:
            course.record(times[i + 1], x, ship.u0)
    crossings = []
    for e, angle in enumerate(angles):
        t_at, x_at = np.full(n, np.nan), np.full((7, n), np.nan)
        hit = np.flatnonzero(~np.isnan(found[e]["t"]))
        if hit.size:
            sub = Mariner(ship, cases.take(hit))
            theta, xs = locate(sub, cases.take(hit), found[e]["x"][:, hit], found[e]["h"][hit], angle, command)
            t_at[hit] = found[e]["t"][hit] + theta * found[e]["h"][hit]
            x_at[:, hit] = xs
        crossings.append((t_at, x_at))
    return figures(course, crossings[0], crossings[1], (times[-1], x))


def turn_ivp(ship: Ship, case: Cases, side: str = "port", method: str = "RK45", rtol: float = 1e-8,
             atol: float = 1e-8, duration: float | None = None):
    """One case's turning circle with scipy's solve_ivp: the figures, and the right-hand sides
    it took."""
    duration = ship.duration if duration is None else duration
    model = Mariner(ship, case)
    command = ship.command(side)

    def rates(t, y):
        return model.rates(y, command)

    def at_90(t, y):
        return y[5] * y[5] - (math.pi / 2.0) ** 2

    def at_180(t, y):
        return y[5] * y[5] - math.pi**2

    def rate_limit(t, y):
        rate = (command - y[6]) / ship.time_constant
        return rate * rate - ship.max_rate**2

    rate_limit.terminal = True
    at_90.direction = at_180.direction = 1.0
    x0 = np.array([ship.u0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    rows = np.arange(0.0, duration + 1e-9, ship.every)
    course = Course.new(1)
    events = {90: (np.nan, np.full(7, np.nan)), 180: (np.nan, np.full(7, np.nan))}
    t, x, evaluations = 0.0, x0, 0
    watch = [at_90, at_180, rate_limit]
    while True:
        sol = solve_ivp(rates, (t, duration), x, method=method, rtol=rtol, atol=atol, events=watch,
                        t_eval=rows[rows >= t])
        evaluations += sol.nfev
        if sol.status < 0:
            raise RuntimeError(sol.message)
        # The rows and the events of this stretch, in time order, into the course.
        points = [(tr, xr, True) for tr, xr in zip(sol.t, sol.y.T)]
        for key, te, ye in zip((90, 180), sol.t_events[:2], sol.y_events[:2]):
            if len(te) and np.isnan(events[key][0]):
                events[key] = (te[0], ye[0])
                points.append((te[0], ye[0], False))
        for tr, xr, is_row in sorted(points, key=lambda p: p[0]):
            (course.row if is_row else course.record)(tr, xr, ship.u0)
        if sol.status == 1:  # the rate limit let go: start again from there, without its watch
            t, x = sol.t_events[2][0], sol.y_events[2][0]
            watch = [at_90, at_180]
            continue
        break
    end = (sol.t[-1], sol.y[:, -1])
    out = figures(course, events[90], events[180], end)
    return {k: v.item() if isinstance(v, np.ndarray) else v for k, v in out.items()}, evaluations


def reference(path: Path | None, side: str) -> dict | None:
    if path is None:
        return None
    summary = json.loads(Path(path).read_text())
    return summary["manoeuvre"]["turning_circle_35"]["sides"][side]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--method", choices=("rk4", "solve_ivp"), default="rk4")
    parser.add_argument("--cases", type=int, help="default 1000 for rk4, 100 for solve_ivp")
    parser.add_argument("--sigma", type=float, default=0.10, help="relative spread of every coefficient (case 0 is always the published table)")
    parser.add_argument("--nominal", action="store_true", help="every case the published table (sigma 0)")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--step", type=float, default=1.0, help="RK4 step, s (1 s: advance, transfer, tactical diameter within 0.0025 m of eom's reference)")
    parser.add_argument("--ivp-method", choices=("RK45", "DOP853"), default="RK45")
    parser.add_argument("--rtol", type=float, default=1e-8)
    parser.add_argument("--atol", type=float, default=1e-8)
    parser.add_argument("--side", choices=("port", "starboard"), default="port", help="port: δ = +35° (eom's first side)")
    parser.add_argument("--duration", type=float, help="s; default the scene's 1500 (the steady turn needs it)")
    parser.add_argument("--scene", type=Path, default=SCENE)
    parser.add_argument("--reference", type=Path, help="eom's summary.json of `eom run scenes/mariner.toml`")
    args = parser.parse_args(argv)

    total = time.perf_counter()
    ship = Ship.load(args.scene)
    count = args.cases or (1000 if args.method == "rk4" else 100)
    sigma = 0.0 if args.nominal else args.sigma
    cases = draw_cases(ship, count, sigma, args.seed)
    if args.method == "rk4":
        start = time.perf_counter()
        result = turn_rk4(ship, cases, args.step, args.side, args.duration)
        integration = time.perf_counter() - start
        setting = f"RK4 at {args.step} s, numpy-vectorised over the {count} cases"
        evaluations = None
    else:
        per_case, evaluations, integration = [], 0, 0.0
        for k in range(count):
            case = cases.one(k)
            start = time.perf_counter()
            figs, nfev = turn_ivp(ship, case, args.side, args.ivp_method, args.rtol, args.atol, args.duration)
            integration += time.perf_counter() - start
            per_case.append(figs)
            evaluations += nfev
        result = {key: np.array([f[key] for f in per_case]) for key in per_case[0]}
        setting = f"solve_ivp {args.ivp_method} at rtol {args.rtol:g}, atol {args.atol:g}, one case at a time"
    total = time.perf_counter() - total

    print(f"Mariner 35° turning circle to {args.side}, {count} cases (case 0 the published table, "
          f"σ = {sigma}, seed {args.seed}); {setting}")
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"  numpy {np.__version__}, scipy {scipy.__version__}; load average {load}")
    print(f"  integration {integration:.3f} s: {count / integration:.1f} turning circles/s; "
          f"total {total:.3f} s: {count / total:.1f} turning circles/s")
    if evaluations is not None:
        print(f"  right-hand sides: {evaluations} ({evaluations / count:.0f} per case)")
    given = ~np.isnan(result["tactical_diameter_m"])
    sides = ", ".join(f"{s} {int((result['side'] == s).sum())}" for s in ("port", "starboard"))
    steady = int((~np.isnan(result["steady_turning_radius_m"])).sum())
    print(f"  tactical diameter given for {int(given.sum())} of {count} cases, the steady turn for {steady}; "
          f"sides: {sides}")
    ref = reference(args.reference, args.side)
    print("  case 0 (the published table):")
    for key in FIGURES:
        value = float(result[key][0])
        line = f"    {key:<24} {value:14.6f}"
        if ref is not None and ref.get(key) is not None:
            line += f"   eom {ref[key]:14.6f}   difference {value - ref[key]:+.2e}"
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
