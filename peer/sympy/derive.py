#!/usr/bin/env python3
"""The SymPy peer of eom's six spatial 6-DOF variants.

A user who does not use eom derives the right-hand side with SymPy from vectors and matrices,
runs `sympy.cse` over all outputs together and prints C99 with `ccode` (the PyDy route). This
script does exactly that for the same equations and the same state, input and parameter
contract as eom's generated `spatial_{full,xz,principal}_{euler,quaternion}`:

    state  [u, v, w, p, q, r, x, y, z, phi, theta, psi]   (Euler kinematics)
           [u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]    (quaternion kinematics)
    input  [F_x, F_y, F_z, M_x, M_y, M_z]                 (force and moment at G, body axes)

    4.49  v' = F/M - w x v
    4.51  [I] w' + w x ([I] w) = M, [I] with I_xy = -int xy dm (4.14), as eom's Parameters
    4.57  position rate = E v, E = Rz(psi) Ry(theta) Rx(phi)
    4.60  Euler-angle rates with tan(theta) and 1/cos(theta)
    q     position rate = R(q) v / |q|^2 ("normalised", eom's contract) or R(q) v ("unit",
          valid only for |q| = 1), q' = 1/2 q (x) (0, w)

Two routes are counted for the dynamics (the kinematics have no parameters):

    built    what the Matrix algebra gives: 1/M and the entries of [I]^-1 (computed once per
             parameter set, like eom's coefficients) are parameters beside the inertia entries;
             w' = [I]^-1 (M - w x ([I] w)).
    hoisted  every parameter-only coefficient of the expanded dynamics is a parameter, as eom
             hoists them into its `Coefficients` struct; w' = sum k_i * monomial.

Run `python3 derive.py` for the Markdown table; `--emit` also rewrites c/<variant>.c, each
with the route that has the fewer additions plus multiplications for that variant.
The counting rules are in README.md and in `Counter` below.
"""

from __future__ import annotations

import argparse
import dataclasses
import functools
import pathlib
import re
import sys

import sympy as sp
from sympy.algebras.quaternion import Quaternion
from sympy.codegen.rewriting import create_expand_pow_optimization, optimize

HERE = pathlib.Path(__file__).resolve().parent

# ----------------------------------------------------------------------------------------------
# Symbols
# ----------------------------------------------------------------------------------------------

u, v, w, p, q, r = sp.symbols("u v w p q r", real=True)
X, Y, Z = sp.symbols("x y z", real=True)
phi, theta, psi = sp.symbols("phi theta psi", real=True)
q0, q1, q2, q3 = sp.symbols("q0 q1 q2 q3", real=True)
F_x, F_y, F_z, M_x, M_y, M_z = sp.symbols("F_x F_y F_z M_x M_y M_z", real=True)
INPUTS = [F_x, F_y, F_z, M_x, M_y, M_z]

# The physical parameters, in the order of eom's `Parameters` struct.
M = sp.Symbol("M", positive=True)
Ixx, Iyy, Izz, Ixy, Iyz, Ixz = sp.symbols("Ixx Iyy Izz Ixy Iyz Ixz", real=True)
PARAMETERS = [M, Ixx, Iyy, Izz, Ixy, Iyz, Ixz]
PARAMETER_NAMES = ["mass", "ixx", "iyy", "izz", "ixy", "iyz", "ixz"]

# The inertia products each symmetry keeps.
INERTIA = {
    "full": {},
    "xz": {Ixy: 0, Iyz: 0},
    "principal": {Ixy: 0, Iyz: 0, Ixz: 0},
}
KINEMATICS = ["euler", "quaternion"]


def state_of(kinematics: str) -> list[sp.Symbol]:
    attitude = [phi, theta, psi] if kinematics == "euler" else [q0, q1, q2, q3]
    return [u, v, w, p, q, r, X, Y, Z, *attitude]


def inertia_tensor(symmetry: str) -> sp.Matrix:
    """[I] of 4.12 with the minus sign inside the products (4.14), as eom's `Parameters`."""
    tensor = sp.Matrix([[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]])
    return tensor.subs(INERTIA[symmetry])


# ----------------------------------------------------------------------------------------------
# The model, from vectors and matrices
# ----------------------------------------------------------------------------------------------


@dataclasses.dataclass
class Model:
    """Right-hand side in runtime symbols plus the parameters it reads.

    `coefficients` maps each parameter symbol the outputs read to its value in terms of
    PARAMETERS (what the companion C function computes once per parameter set)."""

    outputs: list[sp.Expr]
    coefficients: dict[sp.Symbol, sp.Expr]


def rotation_x(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def rotation_y(a):
    return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])


def rotation_z(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def kinematics_rows(kinematics: str, contract: str) -> list[sp.Expr]:
    """Position and attitude rates (no parameters)."""
    velocity = sp.Matrix([u, v, w])
    omega = sp.Matrix([p, q, r])
    if kinematics == "euler":
        E = rotation_z(psi) * rotation_y(theta) * rotation_x(phi)  # 4.56-4.57
        T = sp.Matrix(  # 4.60
            [
                [1, sp.sin(phi) * sp.tan(theta), sp.cos(phi) * sp.tan(theta)],
                [0, sp.cos(phi), -sp.sin(phi)],
                [0, sp.sin(phi) / sp.cos(theta), sp.cos(phi) / sp.cos(theta)],
            ]
        )
        return list(E * velocity) + list(T * omega)
    attitude = Quaternion(q0, q1, q2, q3)
    # SymPy's own rotation matrix of a quaternion is the normalised one: R(q) / |q|^2.
    R = attitude.to_rotation_matrix()
    if contract == "unit":
        # R(q) without the division: correct only for |q| = 1.
        norm2 = q0**2 + q1**2 + q2**2 + q3**2
        R = (R * norm2).applyfunc(sp.cancel)
    elif contract != "normalised":
        raise ValueError(contract)
    rate = attitude * Quaternion(0, p, q, r) / 2
    return list(R * velocity) + [rate.a, rate.b, rate.c, rate.d]


def dynamics_built(symmetry: str) -> Model:
    """4.49 and 4.51 as Matrix algebra, [I]^-1 and 1/M as parameters."""
    velocity = sp.Matrix([u, v, w])
    omega = sp.Matrix([p, q, r])
    force = sp.Matrix([F_x, F_y, F_z])
    moment = sp.Matrix([M_x, M_y, M_z])
    tensor = inertia_tensor(symmetry)
    inverse = tensor.inv()
    inv_M = sp.Symbol("inv_M")
    coefficients = {inv_M: 1 / M}
    # The parameter symbols of [I]^-1 with the zero pattern the inverse has.
    names = "xyz"
    J = sp.zeros(3, 3)
    for i in range(3):
        for j in range(3):
            a, b = min(i, j), max(i, j)
            value = sp.factor(sp.cancel(inverse[a, b]))
            if value != 0:
                symbol = sp.Symbol(f"J{names[a]}{names[b]}")
                J[i, j] = symbol
                coefficients[symbol] = value
    for symbol in tensor.free_symbols:
        coefficients[symbol] = symbol
    translational = inv_M * force - omega.cross(velocity)
    angular = J * (moment - omega.cross(tensor * omega))
    return Model(list(translational) + list(angular), coefficients)


def dynamics_hoisted(symmetry: str) -> Model:
    """The same dynamics expanded, each parameter-only coefficient one parameter k_i.

    As eom hoists: coefficients equal up to sign share one k_i, and a unit coefficient is
    no parameter at all."""
    built = dynamics_built(symmetry)
    value_of = {s: e for s, e in built.coefficients.items()}
    runtime = [u, v, w, p, q, r, *INPUTS]
    coefficients: dict[sp.Symbol, sp.Expr] = {}
    index: dict[sp.Expr, sp.Symbol] = {}
    outputs = []
    for row in built.outputs:
        poly = sp.Poly(sp.expand(row.subs(value_of)), *runtime)
        terms = []
        for monomial, coefficient in poly.terms():
            coefficient = sp.factor(sp.cancel(coefficient))
            if coefficient == 0:
                continue
            sign = -1 if coefficient.could_extract_minus_sign() else 1
            magnitude = sign * coefficient
            if magnitude == 1:
                factor = 1
            else:
                if magnitude not in index:
                    index[magnitude] = sp.Symbol(f"k{len(index)}")
                    coefficients[index[magnitude]] = magnitude
                factor = index[magnitude]
            terms.append(sign * factor * sp.Mul(*[s**e for s, e in zip(runtime, monomial)]))
        outputs.append(sp.Add(*terms))
    return Model(outputs, coefficients)


def model(symmetry: str, kinematics: str, route: str, contract: str = "normalised") -> Model:
    dynamics = {"built": dynamics_built, "hoisted": dynamics_hoisted}[route](symmetry)
    return Model(dynamics.outputs + kinematics_rows(kinematics, contract), dynamics.coefficients)


# ----------------------------------------------------------------------------------------------
# Counting
# ----------------------------------------------------------------------------------------------


@dataclasses.dataclass
class Counter:
    """Operations of a cse result, one node of each expression tree at a time.

    - Add of n terms: n-1 additions. A term with a negative numeric coefficient is
      subtracted (its sign absorbed); only when every term of the Add is negative does the
      Add pay one more addition, for the negation.
    - Mul: numeric coefficient c (if |c| != 1) is one factor; the factors with a negative
      integer exponent form a denominator. n numerator factors: n-1 multiplications; d
      denominator factors: d-1 multiplications and one division (a lone 1/x is one
      division). A coefficient of exactly -1 outside an Add is one negation (an addition);
      any other negative coefficient is a negative literal, free.
    - Pow x**k, k >= 2 integer: k-1 multiplications (x**2 is one); x**-k: one division and
      k-1 multiplications; x**(1/2): one sqrt; x**(-1/2): one sqrt and one division.
    - sin and cos: one trigonometric call per distinct angle, whether sin, cos or both are
      used (like eom's sin_cos); tan(a) = sin/cos and sec(a) = 1/cos: the pair of that
      angle plus one division.
    """

    add: int = 0
    negations: int = 0  # how many of `add` are negations
    mul: int = 0
    div: int = 0
    sqrt: int = 0
    angles: set = dataclasses.field(default_factory=set)

    @property
    def trig(self) -> int:
        return len(self.angles)

    def expression(self, e: sp.Expr, in_add: bool = False) -> None:
        if e.is_Atom:
            return
        if isinstance(e, sp.Add):
            terms = e.args
            self.add += len(terms) - 1
            if all(self.negative(t) for t in terms):
                self.add += 1
                self.negations += 1
            for t in terms:
                self.expression(t, in_add=True)
        elif isinstance(e, sp.Mul):
            self.product(e, in_add)
        elif isinstance(e, sp.Pow):
            self.power(e, standalone=True)
        elif isinstance(e, (sp.sin, sp.cos)):
            self.angles.add(e.args[0])
            self.expression(e.args[0])
        elif isinstance(e, (sp.tan, sp.sec)):
            self.angles.add(e.args[0])
            self.div += 1
            self.expression(e.args[0])
        else:
            raise TypeError(f"no counting rule for {type(e).__name__}: {e}")

    @staticmethod
    def negative(e: sp.Expr) -> bool:
        coefficient, _ = e.as_coeff_Mul()
        return bool(coefficient.is_negative)

    def product(self, e: sp.Mul, in_add: bool) -> None:
        coefficient, factors = e.as_coeff_mul()
        numerator, denominator = [], []
        for f in factors:
            if f.is_Pow and f.exp.is_Integer and f.exp < 0:
                denominator.append(f.base ** (-f.exp))
            else:
                numerator.append(f)
        if abs(coefficient) != 1:
            numerator_count = len(numerator) + 1
        else:
            numerator_count = len(numerator)
            if coefficient == -1 and not in_add:
                self.add += 1
                self.negations += 1
        self.mul += max(numerator_count - 1, 0)
        if denominator:
            self.mul += len(denominator) - 1
            self.div += 1
        for f in numerator + denominator:
            if f.is_Pow:
                self.power(f, standalone=False)
            else:
                self.expression(f)

    def power(self, e: sp.Pow, standalone: bool) -> None:
        base, exponent = e.args
        if exponent.is_Integer and exponent >= 2:
            self.mul += int(exponent) - 1
        elif exponent.is_Integer and exponent <= -1:
            # inside a Mul the division is the Mul's; a lone x**-k is 1/x**k
            self.mul += int(-exponent) - 1
            self.div += 1 if standalone else 0
        elif exponent == sp.Rational(1, 2):
            self.sqrt += 1
        elif exponent == sp.Rational(-1, 2):
            self.sqrt += 1
            self.div += 1
        else:
            raise TypeError(f"no counting rule for the power {e}")
        self.expression(base)


def count(replacements, reduced) -> Counter:
    counter = Counter()
    for _, e in replacements:
        counter.expression(e)
    for e in reduced:
        counter.expression(e)
    return counter


def cse(outputs):
    return sp.cse(outputs)


# ----------------------------------------------------------------------------------------------
# C99
# ----------------------------------------------------------------------------------------------

EXPAND_POW = [create_expand_pow_optimization(3)]


def c_statements(replacements, reduced, target: str) -> list[str]:
    lines = []
    for symbol, e in replacements:
        lines.append(f"    const double {symbol} = {sp.ccode(optimize(e, EXPAND_POW))};")
    for i, e in enumerate(reduced):
        lines.append(f"    {target}[{i}] = {sp.ccode(optimize(e, EXPAND_POW))};")
    return lines


def natural(symbol: sp.Symbol):
    """k2 before k10; Ixx before Jxx before inv_M."""
    name = str(symbol)
    stem = name.rstrip("0123456789")
    return (stem, int(name[len(stem):] or -1))


def c_function(name: str, m: Model, ks: list[sp.Symbol], state: list[sp.Symbol], what: str) -> list[str]:
    replacements, reduced = cse(m.outputs)
    used = set().union(*(e.free_symbols for _, e in replacements), *(e.free_symbols for e in reduced))
    lines = [f"/* {what} */", f"void {name}(const double *k, const double *state, const double *input, double *out)", "{"]
    for i, s in enumerate(ks):
        if s in used:
            lines.append(f"    const double {s} = k[{i}];")
    for i, s in enumerate(state):
        if s in used:
            lines.append(f"    const double {s} = state[{i}];")
    for i, s in enumerate(INPUTS):
        if s in used:
            lines.append(f"    const double {s} = input[{i}];")
    lines += c_statements(replacements, reduced, "out")
    lines.append("}")
    return lines


def c_coefficients(name: str, m: Model, ks: list[sp.Symbol]) -> list[str]:
    replacements, reduced = sp.cse([m.coefficients[s] for s in ks], symbols=sp.numbered_symbols("t"))
    lines = [
        f"/* k = [{', '.join(map(str, ks))}], computed once per parameter set from",
        f"   parameters = [{', '.join(PARAMETER_NAMES)}] (eom's Parameters, I_xy = -int xy dm). */",
        f"void {name}_coefficients(const double *parameters, double *k)",
        "{",
    ]
    used = set().union(*(e.free_symbols for _, e in replacements), *(e.free_symbols for e in reduced))
    for i, s in enumerate(PARAMETERS):
        if s in used:
            lines.append(f"    const double {s} = parameters[{i}];")
    lines += c_statements(replacements, reduced, "k")
    lines.append("}")
    return lines


def emit(symmetry: str, kinematics: str, route: str) -> str:
    variant = f"spatial_{symmetry}_{kinematics}"
    state = state_of(kinematics)
    models = {c: model(symmetry, kinematics, route, c) for c in contracts_of(kinematics)}
    # Both contracts share the dynamics, hence the coefficients.
    coefficients = models["normalised"].coefficients
    ks = sorted(coefficients, key=natural)
    out = [
        f"/* {variant}: the 6-DOF right-hand side derived with SymPy {sp.__version__} from vectors and",
        "   matrices, sympy.cse over all outputs, printed with sympy.ccode. Generated by",
        "   peer/sympy/derive.py --emit; do not edit.",
        f"   state = [{', '.join(map(str, state))}]",
        f"   input = [{', '.join(map(str, INPUTS))}]",
        f"   k     = the parameter-only coefficients of the {route} route (see derive.py), computed",
        f"           once by {variant}_coefficients; of the two routes this one has the fewer",
        "           additions plus multiplications for this variant. */",
        "",
        "#include <math.h>",
        "",
    ]
    out += c_coefficients(variant, models["normalised"], ks) + [""]
    for contract, m in models.items():
        assert m.coefficients == coefficients
        name = variant if contract == "normalised" else f"{variant}_unit"
        if kinematics == "quaternion":
            what = (
                "position rate R(q) v / |q|^2 (eom's normalised contract)"
                if contract == "normalised"
                else f"position rate R(q) v, valid only for |q| = 1; k as for {variant}"
            )
        else:
            what = "Euler angles; singular at theta = +-90 deg (4.60)"
        out += c_function(name, m, ks, state, what) + [""]
    return "\n".join(out)


# ----------------------------------------------------------------------------------------------
# Main
# ----------------------------------------------------------------------------------------------

ROUTES = ["built", "hoisted"]
GOLDEN = HERE.parent.parent / "codegen" / "tests" / "golden"


def variants():
    for symmetry in INERTIA:
        for kinematics in KINEMATICS:
            yield symmetry, kinematics


def contracts_of(kinematics: str) -> list[str]:
    return ["normalised", "unit"] if kinematics == "quaternion" else ["normalised"]


@functools.lru_cache(maxsize=None)
def counts(symmetry: str, kinematics: str, route: str, contract: str) -> Counter:
    replacements, reduced = cse(model(symmetry, kinematics, route, contract).outputs)
    return count(replacements, reduced)


def cheaper_route(symmetry: str, kinematics: str) -> str:
    """The route with fewer additions plus multiplications (eom's contract; ties: built)."""
    def cost(route):
        c = counts(symmetry, kinematics, route, "normalised")
        return c.add + c.mul

    return min(ROUTES, key=cost)


def eom_operations(variant: str) -> dict[str, int] | None:
    """eom's own counts, read from the OPERATIONS constant of its generated golden file."""
    path = GOLDEN / f"{variant}.rs"
    if not path.exists():
        return None
    block = path.read_text().split("pub const OPERATIONS", 1)[1].split("];", 1)[0]
    return {name: int(n) for name, n in re.findall(r'\("(\w+)", (\d+)\)', block)}


def cell(c) -> list[str]:
    return [str(c.add), str(c.mul), f"{c.div} / {c.sqrt} / {c.trig}"]


def table() -> str:
    lines = [
        "| variant | eom add | eom mul | eom div / sqrt / trig | SymPy route "
        "| SymPy add | SymPy mul | SymPy div / sqrt / trig "
        "| unit-q add | unit-q mul | unit-q div / sqrt / trig |",
        "|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|",
    ]
    for symmetry, kinematics in variants():
        variant = f"spatial_{symmetry}_{kinematics}"
        eom = eom_operations(variant)
        for i, route in enumerate(ROUTES):
            if eom is None or i > 0:
                eom_cells = ["", "", ""] if i > 0 else ["?", "?", "?"]
            else:
                eom_cells = [str(eom["add"]), str(eom["mul"]),
                             f"{eom['div']} / {eom['sqrt']} / {eom['trig']}"]
            sympy_cells = cell(counts(symmetry, kinematics, route, "normalised"))
            if kinematics == "quaternion":
                unit_cells = cell(counts(symmetry, kinematics, route, "unit"))
            else:
                unit_cells = ["-", "-", "-"]
            name = variant if i == 0 else ""
            lines.append("| " + " | ".join([name, *eom_cells, route, *sympy_cells, *unit_cells]) + " |")
    return "\n".join(lines)


def eom_negations(variant: str) -> tuple[int, int] | None:
    """eom's negations: sums whose first term is negative, each one addition in its count;
    and how many of them have a positive term that could have led instead."""
    path = GOLDEN / f"{variant}.rs"
    if not path.exists():
        return None
    sums = re.findall(r"^\s+let \w+ = (-[^;]*);", path.read_text(), flags=re.M)
    return len(sums), sum(1 for s in sums if "+" in s)


def negation_table() -> str:
    lines = [
        "| variant | eom negations (avoidable by reordering) | SymPy built | SymPy hoisted "
        "| unit-q built | unit-q hoisted |",
        "|---|---:|---:|---:|---:|---:|",
    ]
    for symmetry, kinematics in variants():
        variant = f"spatial_{symmetry}_{kinematics}"
        eom = eom_negations(variant)
        eom_cell = "?" if eom is None else f"{eom[0]} ({eom[1]})"
        cells = [str(counts(symmetry, kinematics, route, "normalised").negations) for route in ROUTES]
        if kinematics == "quaternion":
            cells += [str(counts(symmetry, kinematics, route, "unit").negations) for route in ROUTES]
        else:
            cells += ["-", "-"]
        lines.append("| " + " | ".join([variant, eom_cell, *cells]) + " |")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--emit", action="store_true", help="rewrite c/<variant>.c")
    args = parser.parse_args(argv)

    print(f"SymPy {sp.__version__}, Python {sys.version.split()[0]}\n")
    print(table())
    print("\nNegations, each counted as one addition above:\n")
    print(negation_table())
    if args.emit:
        (HERE / "c").mkdir(exist_ok=True)
        for symmetry, kinematics in variants():
            path = HERE / "c" / f"spatial_{symmetry}_{kinematics}.c"
            path.write_text(emit(symmetry, kinematics, cheaper_route(symmetry, kinematics)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
