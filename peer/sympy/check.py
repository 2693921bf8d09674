#!/usr/bin/env python3
"""Checks the emitted C of every variant before its counts are compared with eom's.

Compiles c/*.c with the system C compiler, calls each function through ctypes and compares
it with
  1. an independent reference in plain Python floats (no SymPy): v' = F/M - w x v,
     w' = [I]^-1 (M - w x [I] w) by Gaussian elimination, E = Rz Ry Rx, the rates of 4.60,
     R(q/|q|) v and 1/2 q (x) (0, w), at random parameters and states (quaternions not of
     unit norm for the normalised contract);
  2. eom's own generated model through `eom eval` (Euler angles, and their unit quaternion),
     when an eom binary is found (--eom, or target/release/eom of this workspace);
and checks derive.py's operation counter on hand-counted expressions.

Prints 'N passed, N failed' and exits non-zero on any failure.
"""

from __future__ import annotations

import argparse
import ctypes
import json
import math
import pathlib
import random
import shutil
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
SYMMETRIES = ["full", "xz", "principal"]
KINEMATICS = ["euler", "quaternion"]
TOLERANCE = 1e-12


# ----------------------------------------------------------------------------------------------
# Reference, in plain floats
# ----------------------------------------------------------------------------------------------


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def matvec(m, x):
    return [sum(m[i][j] * x[j] for j in range(3)) for i in range(3)]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def solve(m, b):
    """Gaussian elimination with partial pivoting, 3x3."""
    a = [row[:] + [b[i]] for i, row in enumerate(m)]
    for c in range(3):
        pivot = max(range(c, 3), key=lambda i: abs(a[i][c]))
        a[c], a[pivot] = a[pivot], a[c]
        for i in range(c + 1, 3):
            f = a[i][c] / a[c][c]
            for j in range(c, 4):
                a[i][j] -= f * a[c][j]
    x = [0.0] * 3
    for i in reversed(range(3)):
        x[i] = (a[i][3] - sum(a[i][j] * x[j] for j in range(i + 1, 3))) / a[i][i]
    return x


def tensor(parameters):
    _, ixx, iyy, izz, ixy, iyz, ixz = parameters
    return [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]


def dynamics(parameters, state, inputs):
    mass = parameters[0]
    velocity, omega = state[0:3], state[3:6]
    force, moment = inputs[0:3], inputs[3:6]
    spin = cross(omega, velocity)
    translational = [force[i] / mass - spin[i] for i in range(3)]
    I = tensor(parameters)
    gyroscopic = cross(omega, matvec(I, omega))
    angular = solve(I, [moment[i] - gyroscopic[i] for i in range(3)])
    return translational + angular


def euler_matrix(phi, theta, psi):
    c, s = math.cos, math.sin
    rz = [[c(psi), -s(psi), 0], [s(psi), c(psi), 0], [0, 0, 1]]
    ry = [[c(theta), 0, s(theta)], [0, 1, 0], [-s(theta), 0, c(theta)]]
    rx = [[1, 0, 0], [0, c(phi), -s(phi)], [0, s(phi), c(phi)]]
    return matmul(rz, matmul(ry, rx))


def quaternion_matrix(a, b, c, d):
    """The rotation matrix of a unit quaternion (a, b, c, d)."""
    return [
        [1 - 2 * (c * c + d * d), 2 * (b * c - a * d), 2 * (b * d + a * c)],
        [2 * (b * c + a * d), 1 - 2 * (b * b + d * d), 2 * (c * d - a * b)],
        [2 * (b * d - a * c), 2 * (c * d + a * b), 1 - 2 * (b * b + c * c)],
    ]


def hamilton(x, y):
    a0, a = x[0], x[1:]
    b0, b = y[0], y[1:]
    vector = [a0 * b[i] + b0 * a[i] + cross(a, b)[i] for i in range(3)]
    return [a0 * b0 - sum(a[i] * b[i] for i in range(3)), *vector]


def reference(kinematics, contract, parameters, state, inputs):
    velocity = state[0:3]
    p, q, r = state[3:6]
    out = dynamics(parameters, state, inputs)
    if kinematics == "euler":
        phi, theta, psi = state[9:12]
        out += matvec(euler_matrix(phi, theta, psi), velocity)
        rolled = q * math.sin(phi) + r * math.cos(phi)
        out += [p + rolled * math.tan(theta), q * math.cos(phi) - r * math.sin(phi), rolled / math.cos(theta)]
        return out
    attitude = state[9:13]
    norm = math.sqrt(sum(x * x for x in attitude))
    R = quaternion_matrix(*[x / norm for x in attitude])
    if contract == "unit":
        R = [[x * norm * norm for x in row] for row in R]
    out += matvec(R, velocity)
    out += [x / 2 for x in hamilton(attitude, [0.0, p, q, r])]
    return out


def quaternion_of(phi, theta, psi):
    """q = q_z(psi) (x) q_y(theta) (x) q_x(phi), as eom builds it."""
    qz = [math.cos(psi / 2), 0.0, 0.0, math.sin(psi / 2)]
    qy = [math.cos(theta / 2), 0.0, math.sin(theta / 2), 0.0]
    qx = [math.cos(phi / 2), math.sin(phi / 2), 0.0, 0.0]
    return hamilton(hamilton(qz, qy), qx)


# ----------------------------------------------------------------------------------------------
# The emitted C
# ----------------------------------------------------------------------------------------------


def build(directory: pathlib.Path) -> ctypes.CDLL:
    compiler = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    if compiler is None:
        sys.exit("no C compiler (cc, gcc or clang) found")
    library = directory / "libpeer.so"
    sources = sorted(str(p) for p in (HERE / "c").glob("*.c"))
    command = [compiler, "-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-pedantic",
               "-shared", "-fPIC", "-o", str(library), *sources, "-lm"]
    subprocess.run(command, check=True)
    return ctypes.CDLL(str(library))


Array = ctypes.c_double * 32


def call_c(lib, name, parameters, state, inputs, n):
    k, out = Array(), Array()
    getattr(lib, f"{name.removesuffix('_unit')}_coefficients")(Array(*parameters), k)
    getattr(lib, name)(k, Array(*state), Array(*inputs), out)
    return list(out[:n])


def random_parameters(rng, symmetry):
    """Mass and inertia of a cloud of point masses about the origin, so that the tensor is
    that of a body; mirrored about the xz-plane (xz) and also the xy-plane (principal)."""
    points = [(rng.uniform(0.1, 1.0), [rng.uniform(-1.0, 1.0) for _ in range(3)]) for _ in range(4)]
    if symmetry in ("xz", "principal"):
        points += [(m, [x, -y, z]) for m, (x, y, z) in points]
    if symmetry == "principal":
        points += [(m, [x, y, -z]) for m, (x, y, z) in points]
    mass = sum(m for m, _ in points)
    ixx = sum(m * (y * y + z * z) for m, (x, y, z) in points)
    iyy = sum(m * (z * z + x * x) for m, (x, y, z) in points)
    izz = sum(m * (x * x + y * y) for m, (x, y, z) in points)
    ixy = -sum(m * x * y for m, (x, y, z) in points)  # 4.14: the minus sign inside
    iyz = -sum(m * y * z for m, (x, y, z) in points)
    ixz = -sum(m * z * x for m, (x, y, z) in points)
    if symmetry in ("xz", "principal"):
        ixy = iyz = 0.0  # zero already, up to rounding
    if symmetry == "principal":
        ixz = 0.0
    return [mass, ixx, iyy, izz, ixy, iyz, ixz]


def random_state(rng, kinematics, contract):
    state = [rng.uniform(-2.0, 2.0) for _ in range(9)]
    if kinematics == "euler":
        return state + [rng.uniform(-3.0, 3.0), rng.uniform(-1.3, 1.3), rng.uniform(-3.0, 3.0)]
    attitude = [rng.uniform(-1.0, 1.0) for _ in range(4)]
    norm = math.sqrt(sum(x * x for x in attitude))
    scale = rng.uniform(0.5, 2.0) if contract == "normalised" else 1.0
    return state + [x / norm * scale for x in attitude]


def close(a, b):
    return all(abs(x - y) <= TOLERANCE * max(1.0, abs(y)) for x, y in zip(a, b))


def eom_eval(eom, symmetry, kinematics, parameters, state, inputs):
    mass = parameters[0]
    phi, theta, psi = state[9:12]
    request = {
        "mass": mass,
        "inertia": tensor(parameters),
        "state": dict(zip(["u", "v", "w", "p", "q", "r"], state[0:6]), phi=phi, theta=theta, psi=psi),
        "force": inputs[0:3],
        "moment": inputs[3:6],
    }
    command = [eom, "eval", "--model", "spatial", "--symmetry", symmetry, "--kinematics", kinematics, "--input", "-"]
    run = subprocess.run(command, input=json.dumps(request), capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"eom eval failed on {request}: {run.stderr}")
    return json.loads(run.stdout)["generated"]


def counter_cases() -> list[str]:
    """The counting rules of derive.Counter on hand-counted expressions; the failures."""
    import sympy as sp

    from derive import Counter

    a, b, c, d, x = sp.symbols("a b c d x")
    cases = [  # expression, (add, mul, div, sqrt, trig)
        (a * b * c, (0, 2, 0, 0, 0)),
        (a - b, (1, 0, 0, 0, 0)),
        (-a - b, (2, 0, 0, 0, 0)),  # one subtraction, one negation
        (-a, (1, 0, 0, 0, 0)),
        (-2 * a, (0, 1, 0, 0, 0)),  # a negative literal
        (a * b - 2 * c * d, (1, 3, 0, 0, 0)),
        (a**2, (0, 1, 0, 0, 0)),
        (a**3, (0, 2, 0, 0, 0)),
        (a / b, (0, 0, 1, 0, 0)),
        (1 / b, (0, 0, 1, 0, 0)),
        (b**-2, (0, 1, 1, 0, 0)),
        (a * b / (c * d**2), (0, 3, 1, 0, 0)),
        (sp.Rational(1, 2) * a, (0, 1, 0, 0, 0)),
        (sp.sin(x) * sp.cos(x) + sp.tan(x), (1, 1, 1, 0, 1)),
        (sp.cos(x) / sp.cos(2 * x), (0, 1, 1, 0, 2)),
        (sp.sqrt(a), (0, 0, 0, 1, 0)),
        (1 / sp.sqrt(a + b), (1, 0, 1, 1, 0)),
    ]
    failures = []
    for expression, expected in cases:
        counter = Counter()
        counter.expression(expression)
        got = (counter.add, counter.mul, counter.div, counter.sqrt, counter.trig)
        if got != expected:
            failures.append(f"{expression}: counted {got}, expected {expected}")
    return failures


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--eom", help="path of the eom binary (default: target/release/eom, if built)")
    parser.add_argument("--samples", type=int, default=200)
    args = parser.parse_args(argv)
    eom = args.eom or str(HERE.parent.parent / "target" / "release" / "eom")
    if not pathlib.Path(eom).exists():
        print(f"(no eom binary at {eom}: the comparison with eom eval is skipped)")
        eom = None

    rng = random.Random(20240601)
    failures = counter_cases()
    for failure in failures:
        print(f"FAIL counting rule: {failure}")
    print(f"{'ok  ' if not failures else 'FAIL'} the counting rules on hand-counted expressions")
    passed, failed = int(not failures), int(bool(failures))
    with tempfile.TemporaryDirectory() as directory:
        lib = build(pathlib.Path(directory))
        for symmetry in SYMMETRIES:
            for kinematics in KINEMATICS:
                variant = f"spatial_{symmetry}_{kinematics}"
                n = 12 if kinematics == "euler" else 13
                contracts = ["normalised", "unit"] if kinematics == "quaternion" else ["normalised"]
                for contract in contracts:
                    name = variant if contract == "normalised" else f"{variant}_unit"
                    worst = 0
                    for _ in range(args.samples):
                        parameters = random_parameters(rng, symmetry)
                        state = random_state(rng, kinematics, contract)
                        inputs = [rng.uniform(-5.0, 5.0) for _ in range(6)]
                        got = call_c(lib, name, parameters, state, inputs, n)
                        want = reference(kinematics, contract, parameters, state, inputs)
                        if not close(got, want):
                            worst += 1
                    ok = worst == 0
                    passed, failed = passed + ok, failed + (not ok)
                    print(f"{'ok  ' if ok else 'FAIL'} {name} against the plain-float reference ({args.samples} samples)")
                if eom is None:
                    continue
                mismatches = 0
                for _ in range(20):
                    parameters = random_parameters(rng, symmetry)
                    euler = random_state(rng, "euler", "normalised")
                    inputs = [rng.uniform(-5.0, 5.0) for _ in range(6)]
                    generated = eom_eval(eom, symmetry, kinematics, parameters, euler, inputs)
                    keys = ["u_dot", "v_dot", "w_dot", "p_dot", "q_dot", "r_dot", "x_dot", "y_dot", "z_dot"]
                    if kinematics == "euler":
                        state = euler
                        keys += ["phi_dot", "theta_dot", "psi_dot"]
                    else:
                        state = euler[:9] + quaternion_of(*euler[9:12])
                        keys += ["q0_dot", "q1_dot", "q2_dot", "q3_dot"]
                    want = [generated[key] for key in keys]
                    for name in [variant] + ([f"{variant}_unit"] if kinematics == "quaternion" else []):
                        if not close(call_c(lib, name, parameters, state, inputs, n), want):
                            mismatches += 1
                ok = mismatches == 0
                passed, failed = passed + ok, failed + (not ok)
                print(f"{'ok  ' if ok else 'FAIL'} {variant} against eom eval's generated model (20 states)")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
