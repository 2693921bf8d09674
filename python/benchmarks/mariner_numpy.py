"""4.46 for the Mariner in numpy, written by hand from scenes/mariner.toml: the same equations
eom derives and proves when it reads the scene (docs/ships.md), vectorised over states.

The state is eom's, (u, v, r, X, Y, psi, delta) of the midship origin, the inputs
(delta_rate, n); the table is in the prime system (forces over ½ρU²L², moments over ½ρU²L³,
u′ = (u − U₀)/U, v′ = v/U, r′ = rL/U, U = √(u² + v²)) with its rigid-body terms folded in,
taken back out as eom's summary says it converts them (``model.conversion``). The mass matrix

    [[M − X_u̇, 0, 0], [0, M − Y_v̇, M x_G − Y_ṙ], [0, M x_G − N_v̇, I_O − N_ṙ]]

(I_O, the yaw inertia about midship, as the scene gives it) is inverted once.

    python python/benchmarks/mariner_numpy.py

checks it against eom's compiled model on 10⁵ random states and times both over 10⁶.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "mariner.toml"
POWERS = "uvrd"


class Mariner:
    """The Mariner's 4.46, vectorised: ``rhs(x, u)`` with x (7, N), u (2, N)."""

    def __init__(self, scene: Path = SCENE):
        table = tomllib.loads(scene.read_text())
        body, hydro = table["body"], table["hydrodynamics"]
        c = dict(hydro["coefficients"])
        m, xg, iz = body["mass_prime"], body["x_g_prime"], body["izz_midship_prime"]
        # The folded rigid-body terms taken out (the summary's model.conversion).
        c["Xrv"] -= m
        c["Xrr"] -= m * xg
        c["Yr"] += m
        c["Yru"] += m
        c["Nr"] += m * xg
        c["Nru"] += m * xg
        self.length = L = body["length"]
        self.u0 = hydro["design_speed"]
        half_rho = 0.5 * hydro["density"]
        self.terms = {"X": [], "Y": [], "N": []}
        for name, value in c.items():
            if name.endswith("dot"):
                continue
            letters = name[1:].replace("0", "")
            powers = tuple(letters.count(p) for p in POWERS)
            self.terms[name[0]].append((value, powers))
        self.mass = m * half_rho * L**3
        self.xg = xg * L
        mass_matrix = np.array(
            [
                [self.mass - c["Xudot"] * half_rho * L**3, 0.0, 0.0],
                [0.0, self.mass - c["Yvdot"] * half_rho * L**3, self.mass * self.xg - c["Yrdot"] * half_rho * L**4],
                [0.0, self.mass * self.xg - c["Nvdot"] * half_rho * L**4, (iz - c["Nrdot"]) * half_rho * L**5],
            ]
        )
        self.inverse = np.linalg.inv(mass_matrix)
        self.force_scale = {"X": half_rho * L**2, "Y": half_rho * L**2, "N": half_rho * L**3}

    def rhs(self, x: np.ndarray, inputs: np.ndarray) -> np.ndarray:
        u, v, r, _, _, psi, delta = x
        speed = np.sqrt(u * u + v * v)
        variables = {"u": (u - self.u0) / speed, "v": v / speed, "r": r * self.length / speed, "d": delta}
        powers_of = {
            name: [np.ones_like(u), value, value * value, value * value * value]
            for name, value in variables.items()
        }
        loads = {}
        for force, terms in self.terms.items():
            total = np.zeros_like(u)
            for coefficient, powers in terms:
                term = coefficient
                for name, power in zip(POWERS, powers):
                    if power:
                        term = term * powers_of[name][power]
                total = total + term
            loads[force] = total * self.force_scale[force] * speed * speed
        mass, xg = self.mass, self.xg
        right = np.stack(
            [
                loads["X"] + mass * (v * r + xg * r * r),
                loads["Y"] - mass * u * r,
                loads["N"] - mass * xg * u * r,
            ]
        )
        du, dv, dr = self.inverse @ right
        cos, sin = np.cos(psi), np.sin(psi)
        return np.stack([du, dv, dr, u * cos - v * sin, u * sin + v * cos, r, inputs[0]])


def random_states(count: int, seed: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """States and inputs about the Mariner's approach: u within ±30 % of U₀, v and r of a
    tight turn, any heading, δ within ±40°."""
    rng = np.random.default_rng(seed)
    u0 = 7.7175
    x = np.stack(
        [
            rng.uniform(0.7 * u0, 1.3 * u0, count),
            rng.uniform(-1.5, 1.5, count),
            rng.uniform(-0.02, 0.02, count),
            rng.uniform(-1e3, 1e3, count),
            rng.uniform(-1e3, 1e3, count),
            rng.uniform(-np.pi, np.pi, count),
            rng.uniform(-0.7, 0.7, count),
        ]
    )
    u = np.stack([rng.uniform(-0.09, 0.09, count), np.zeros(count), np.zeros(count)])
    return x, u


if __name__ == "__main__":
    import time

    import eom

    model = eom.Scene.load(SCENE).model()
    numpy_form = Mariner()
    x, u = random_states(10**5)
    ours, theirs = model.rhs(x, u), numpy_form.rhs(x, u)
    scale = np.abs(ours).max(axis=1, keepdims=True)
    print("largest difference over 1e5 states, relative to each rate's largest:",
          float(np.max(np.abs(ours - theirs) / scale)))
    x, u = random_states(10**6)
    for name, call in [("eom (compiled, one call)", model.rhs), ("numpy 4.46", numpy_form.rhs)]:
        times = []
        for _ in range(5):
            start = time.perf_counter()
            call(x, u)
            times.append(time.perf_counter() - start)
        print(f"{name}: best of 5 over 10^6 states {min(times):.3f} s, {min(times) / 1e6 * 1e9:.1f} ns per state")
