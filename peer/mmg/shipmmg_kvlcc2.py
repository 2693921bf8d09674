"""The KVLCC2 at L = 7 m under shipmmg (PyPI 0.0.11), run as eom runs scenes/kvlcc2_l7.toml,
and each way shipmmg's model differs from eom's switched to eom's reading one at a time, so that
every figure's difference is traced to a named modelling choice.

    pip install shipmmg==0.0.11             # brings numpy and scipy
    python3 peer/mmg/shipmmg_kvlcc2.py      # writes peer/mmg/shipmmg_kvlcc2.json, prints the tables
    python3 peer/mmg/shipmmg_kvlcc2.py --check

`--check` runs every trial again and exits 1 if a figure differs from the JSON's by more than
CHECK_RELATIVE of its value (CHECK_ABSOLUTE near zero); timings are not checked and not re-run.
Where target/release/eom exists (or the binary EOM_BIN names), the script runs the scene with it (eom's column, and its wall
time); without it, eom's figures are those the JSON holds.

The setup is the scene's (read from scenes/kvlcc2_l7.toml and data/kvlcc2_mmg.json): the approach
at u = 1.179 m/s, v = r = 0, the propeller held at the rate n0 that balances the approach (solved
here as eom solves it), the steering gear's rate limit of 15.68 deg/s acting on a first-order lag
of 0.05 s (eom's gear: the rudder moves at the limit to within 0.784 deg of its command, then
settles exponentially), the 35 deg turning circle for 300 s and the 10/10 and 20/20 zig-zags for
120 s, each to port and to starboard. delta > 0 turns the ship to starboard in shipmmg as in eom.

The figures are eom's (src/kinds/ship/manoeuvre/figures.rs), read at events located on the
integrator's dense output: advance and transfer of midship at 90 deg of heading change from the
execute, the tactical diameter at 180 deg, t_90 and t_180; the steady turn at the end of the run
(U of midship over |r|); a zig-zag's reversal where the heading change reaches +-psi_a, its k-th
overshoot where r = 0 after the k-th reversal, the period from the first reversal to the third,
the initial turning distance run by midship to the first reversal.

Three ways to run shipmmg's model are compared:
- shipmmg itself: shipmmg.mmg_3dof.simulate_mmg_3dof (scipy's solve_ivp; here DOP853 at
  rtol = atol = 1e-12 through its **options), the rudder angle given as samples of eom's gear law
  on a grid with a knot where the rate limit ends, which shipmmg interpolates with a natural
  cubic spline; a zig-zag is run stage by stage, each stage one call from the reversal, ended by
  a terminal event where the heading passes the next +-psi_a.
- shipmmg's own zig-zag function, zigzag_test_mmg_3dof, as published: it does not pass its
  tolerances on (RK45 at scipy's defaults, rtol 1e-3, atol 1e-6), reverses the rudder at the
  first sample of its time grid past +-psi_a, and ramps the rudder without a lag; its figures are
  read off its samples.
- a copy of shipmmg's right-hand side (mmg_3dof.py lines 866-954) written here, whose differences
  from eom's model are switches (all eight combinations of the three differences are run): as
  published it reproduces shipmmg's own runs (to the spline's interpolation of the rudder,
  residuals.copy_against_shipmmg_published in the JSON), and with every switch at eom's reading
  it reproduces eom's figures (to eom's tolerances, residuals.eom_reading_against_eom).

What it finds: shipmmg's right-hand side (mmg_3dof.py:862-955) is the paper's model as eom
implements it, the equations of motion about midship, the mass and inertia, the hull, propeller
and rudder, but for three choices: x_P (-0.69 in its test fixture where eom's table has -0.48),
U and beta taken from v - x_G r (where v' takes v), and the older wake law w_P0 exp(-4 beta_P^2).
The three account for every figure's difference; the attribution gives each its share. At n0
shipmmg's X on the straight course is zero to rounding: both wake laws give w_P0 there, so the
approach is an equilibrium of its model too.
"""
import argparse
import importlib.metadata
from itertools import combinations
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
import tomllib

import numpy as np
import scipy
from scipy.integrate import solve_ivp

from shipmmg import mmg_3dof

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, '..', '..'))
SCENE = os.path.join(ROOT, 'scenes', 'kvlcc2_l7.toml')
TABLE = os.path.join(ROOT, 'data', 'kvlcc2_mmg.json')
# The eom binary: EOM_BIN where it is set (CI's debug build), else the release build.
EOM = os.environ.get('EOM_BIN') or os.path.join(ROOT, 'target', 'release', 'eom')
OUT = os.path.join(HERE, 'shipmmg_kvlcc2.json')

SHIPMMG_VERSION = '0.0.11'
RTOL = ATOL = 1e-12          # every integration here but shipmmg's own zig-zag function
LOOSE = 1e-10                # the same runs again, for the integrator's share of each figure
EOM_TOL = 1e-8               # the scene's: shipmmg with RK45 (Dormand-Prince 5(4), eom's dopri5) at it
ZIGZAG_GRID_S = 0.01         # the time grid of shipmmg's own zig-zag function
CHECK_RELATIVE = 1e-6
CHECK_ABSOLUTE = 1e-9
TIMING_RUNS = 5

# The turning circle's and the zig-zag's figures, in eom's keys and order.
TURNING = ['advance_90_m', 'transfer_90_m', 'tactical_diameter_m', 'steady_turning_radius_m',
           'steady_speed_m_s', 't_90_s', 't_180_s']
ZIGZAG = ['first_overshoot_deg', 'second_overshoot_deg', 'reach_time_s', 'period_s',
          'initial_turning_distance_m']

# shipmmg's KVLCC2 L7 as its test fixture gives it (tests/test_mmg_3dof.py, ship_KVLCC2_L7_model,
# lines 28-104 at ShipMMG/shipmmg b004dab, the commit of 0.0.11's code): the package's own
# parameter file for this ship, in data/kvlcc2_mmg.json's names. Its example notebook
# (shipmmg_example.ipynb, code cell 14) is the same but x_P = -0.48.
SHIPMMG_TESTS = {
    'L': 7.00, 'B': 1.27, 'd': 0.46, 'nabla': 3.27, 'x_G': 0.25, 'D_P': 0.216, 'H_R': 0.345,
    'A_R': 0.0539,
    't_P': 0.220, 'w_P0': 0.40, 'm_x_p': 0.022, 'm_y_p': 0.223, 'J_z_p': 0.011, 't_R': 0.387,
    'x_R_p': -0.500, 'a_H': 0.312, 'x_H_p': -0.464, 'gamma_R_minus': 0.395,
    'gamma_R_plus': 0.640, 'l_R_p': -0.710, 'x_P_p': -0.690, 'epsilon': 1.09, 'kappa': 0.50,
    'f_alpha': 2.747,
    'k_0': 0.2931, 'k_1': -0.2753, 'k_2': -0.1385, 'R_0_p': 0.022, 'X_vv_p': -0.040,
    'X_vr_p': 0.002, 'X_rr_p': 0.011, 'X_vvvv_p': 0.771, 'Y_v_p': -0.315, 'Y_r_p': 0.083,
    'Y_vvv_p': -1.607, 'Y_vvr_p': 0.379, 'Y_vrr_p': -0.391, 'Y_rrr_p': 0.008, 'N_v_p': -0.137,
    'N_r_p': -0.049, 'N_vvv_p': -0.030, 'N_vvr_p': -0.294, 'N_vrr_p': 0.055, 'N_rrr_p': -0.013,
}
# shipmmg's examples' propeller rate and approach (tests lines 137, 152; notebook cell 15, 17).
SHIPMMG_EXAMPLE_RATE = 17.95
SHIPMMG_EXAMPLE_SPEED = 2.29 * 0.512

# How shipmmg's model differs from eom's, each with where it is said (shipmmg: mmg_3dof.py of the
# 0.0.11 wheel, the same bytes as ShipMMG/shipmmg b004dab; eom: this repository).
DIFFERENCES = [
    {
        'key': 'x_P',
        'what': "x'_P, the propeller's effective position in beta_P = beta - x'_P r'",
        'shipmmg': '-0.69 in the test fixture (tests/test_mmg_3dof.py:52), -0.48 in the example '
                   'notebook (shipmmg_example.ipynb, code cell 14), -0.65 in the docstrings '
                   '(mmg_3dof.py:357, 776)',
        'eom': "-0.48 (data/kvlcc2_mmg.json x_P_p; scenes/kvlcc2_l7.toml)",
        'kind': 'parameter',
        'eom_to_run_shipmmgs': 'nothing new: x_P_p = -0.69 in the scene\'s '
                               '[hydrodynamics.coefficients]',
    },
    {
        'key': 'kinematics',
        'what': 'U and beta from the sway of midship',
        'shipmmg': 'U = sqrt(u^2 + (v - x_G r)^2) (mmg_3dof.py:866), beta = arcsin(-(v - x_G r)/U) '
                   '(868), while v\' = v/U and r\' = rL/U (869-870) take the state\'s v, which its '
                   'equations of motion (943-949) treat as the sway of midship v_m; the same in '
                   'get_sub_values_from_simulation_result (1028, 1038)',
        'eom': 'U = sqrt(u^2 + v_m^2), beta = atan2(-v_m, u), v\' = v_m/U '
               '(src/kinds/ship/mmg/forces.rs:390-409; src/kinds/ship/mmg.rs:22)',
        'kind': 'model',
        'eom_to_run_shipmmgs': 'an option of the forces\' kinematics (forces.rs, kinematics) to '
                               'take U and beta, not v\', from v_m - x_G r: the sway of a point '
                               'x_G aft of midship, which is neither midship\'s nor G\'s '
                               '(v_G = v_m + x_G r), so a reading no other term of the model '
                               'shares; no parameter gives it',
    },
    {
        'key': 'wake',
        'what': 'the wake fraction in manoeuvres',
        'shipmmg': 'w_P = w_P0 exp(-4 beta_P^2) (mmg_3dof.py:873; 1057), symmetric in beta_P, '
                   'C_1, C_2+ and C_2- unused',
        'eom': "1 - w_P = (1 - w_P0)(1 + (1 - exp(-C_1|beta_P|))(C_2 - 1)), C_2 = C_2+ for "
               "beta_P >= 0, C_2- below (src/kinds/ship/mmg/forces.rs:256-268; "
               "src/kinds/ship/mmg.rs:27)",
        'kind': 'model',
        'eom_to_run_shipmmgs': 'an option for the older wake law w_P0 exp(-k beta_P^2) with its '
                               'constant (4; not in the paper\'s table) in propeller_forces '
                               '(forces.rs), and in balancing_rate none (both laws give w_P0 on '
                               'the straight course); no values of C_1, C_2+- give it',
    },
]
# What is the same in both, checked line by line (the equations of motion, the inertia, the
# rudder), and what differs only in numerics or outside these runs; for the JSON and the report.
SAME = [
    'equations of motion about midship: (m + m_x) du = X + (m + m_y) v r + x_G m r^2, and the '
    'sway and yaw pair with (I_zG + J_z + x_G^2 m) solved together (mmg_3dof.py:943-949), which '
    "is eom's 4.46 with the MMG added masses (codegen/src/model/ship.rs:50-54); the docstrings' "
    'equations (mmg_3dof.py:9-13, 196-200, 531-535) drop the x_G terms, the code does not',
    'mass m = rho nabla and I_zG = rho nabla (0.25 L)^2 about G (tests/test_mmg_3dof.py:63-64), '
    "eom's body.mass and body.izz; m_x, m_y on 1/2 rho L^2 d and J_z on 1/2 rho L^4 d (67-69) as "
    "eom's; the docstring examples' m = 3.27*1.025 (mmg_3dof.py:338, 758) is in tonnes beside "
    'added masses in kg, and no test runs it',
    "rudder: u_R, v_R = U gamma_R beta_R, alpha_R = delta - atan2(v_R, u_R), F_N, X_R = -(1 - t_R) "
    "F_N sin(delta), Y_R = -(1 + a_H) F_N cos(delta), N_R = -(x_R + a_H x_H) F_N cos(delta) "
    "(mmg_3dof.py:877-893, 909, 926, 942) with x_R = -0.5 L, x_H = -0.464 L in metres "
    "(tests/test_mmg_3dof.py:73, 75), gamma_R- for beta_R < 0 (878) as eom's; only through U "
    "and beta (the kinematics difference) do they differ",
    'hull X_H, Y_H, N_H on 1/2 rho L d U^2 and 1/2 rho L^2 d U^2 (mmg_3dof.py:895-941); '
    'propeller J, K_T, X_P (875-876, 910)',
    'track: dx = u cos(psi) - v sin(psi), dy = u sin(psi) + v cos(psi), of midship (950-951); '
    'delta > 0 turns to starboard (F_N > 0, N_R > 0)',
    'outside these runs: u_R at J = 0 is sqrt(eta) kappa epsilon 8 k_0 n^2 D_P^4/pi (881), not a '
    "speed (eom takes the limit as u -> 0); get_sub_values_from_simulation_result's Y_R uses "
    '(1 - t_R) for (1 + a_H) (1205), a post-processing slip that the simulation (926) does not share',
    "numerics: the rudder is an input list that simulate_mmg_3dof interpolates with a natural "
    "cubic spline and integrates as a state (856-860, 953); solve_ivp's method defaults to RK45 "
    "(519) at scipy's rtol 1e-3, atol 1e-6; zigzag_test_mmg_3dof does not pass method or "
    'tolerances on (1453-1467), reverses at the first grid sample past +-psi_a (1479-1490), '
    'restarts u, v, r, x, y from the sample before it but psi from that sample (1433-1438, '
    '1489), and ramps the rudder without a lag (1440-1451)',
]

# The variants: every combination of the three differences switched to eom's reading (x_P a
# parameter, kinematics and wake the copied right-hand side's switches), named by those switched.
DIFFERENCE_KEYS = ['x_P', 'kinematics', 'wake']


def variant_name(switched):
    return '+'.join(k for k in DIFFERENCE_KEYS if k in switched) or 'published'


VARIANTS = [(variant_name(sw), {k: ('eom' if k in sw else 'shipmmg') for k in DIFFERENCE_KEYS})
            for sw in ([], ['x_P'], ['kinematics'], ['wake'], ['x_P', 'kinematics'],
                       ['x_P', 'wake'], ['kinematics', 'wake'], ['x_P', 'kinematics', 'wake'])]
CHAIN = ['published', 'x_P', 'x_P+kinematics', 'x_P+kinematics+wake']


# ----------------------------------------------------------------------------------------------
# The setup

def read_setup():
    scene = tomllib.load(open(SCENE, 'rb'))
    table = json.load(open(TABLE))
    c, ship = table['coefficients'], table['particulars']['L7']
    body, hydro, rudder = scene['body'], scene['hydrodynamics'], scene['rudder']
    for key, value in hydro['coefficients'].items():
        assert value == c[key], f'the scene and the table differ on {key}'
    trials = []
    # The turning circles and zig-zags (the scene's spiral is eom's alone).
    for m in scene['manoeuvre']:
        if m['kind'] not in ('turning_circle', 'zigzag'):
            continue
        for side in ('port', 'starboard'):
            trials.append({
                'name': m['name'], 'kind': m['kind'], 'side': side,
                'rudder_deg': m['rudder_deg'], **({'heading_deg': m['heading_deg']}
                                                  if 'heading_deg' in m else {}),
                'rudder': math.radians(m['rudder_deg']),
                'heading': math.radians(m.get('heading_deg', 0.0)),
                'duration': m['duration_s'],
            })
    return {
        'density': hydro['density'], 'speed': hydro['design_speed'],
        'mass': body['mass'], 'izz': body['izz'], 'x_G': body['x_g'],
        'max_rate': math.radians(rudder['max_rate_deg_s']),
        'max_angle': math.radians(rudder['max_deg']),
        'lag': rudder['time_constant_s'],
        'rudder_table': rudder,
        'eom': {**c, **ship},
        'trials': trials,
        'scene_integrator': scene['integrator'],
    }


def balancing_rate(p, rho, speed):
    """n0 at which (1 - t_P) T balances the resistance on the straight course at U0 (the larger
    root of the quadratic in n that eom's balancing_rate solves)."""
    a_adv = speed * (1 - p['w_P0']) / p['D_P']
    thrust = (1 - p['t_P']) * rho * p['D_P'] ** 4
    resistance = 0.5 * rho * p['L'] * p['d'] * speed ** 2 * p['R_0_p']
    a, b, cc = thrust * p['k_0'], thrust * p['k_1'] * a_adv, thrust * p['k_2'] * a_adv ** 2 - resistance
    q = -0.5 * (b + math.copysign(math.sqrt(b * b - 4 * a * cc), b))
    return q / a if b <= 0 else cc / q


def parameters(setup, x_P):
    """The L7 ship in eom's values (data/kvlcc2_mmg.json) with x_P; the dimensional set that
    shipmmg's Mmg3DofBasicParams takes, as its fixture builds it."""
    p = dict(setup['eom'])
    p['x_P_p'] = x_P
    return p


def shipmmg_params(p, setup):
    rho, L, d = setup['density'], p['L'], p['d']
    basic = mmg_3dof.Mmg3DofBasicParams(
        L_pp=L, B=p['B'], d=d, x_G=setup['x_G'], D_p=p['D_P'],
        m=setup['mass'], I_zG=setup['izz'], A_R=p['A_R'], η=p['D_P'] / p['H_R'],
        m_x=0.5 * rho * L ** 2 * d * p['m_x_p'], m_y=0.5 * rho * L ** 2 * d * p['m_y_p'],
        J_z=0.5 * rho * L ** 4 * d * p['J_z_p'], f_α=p['f_alpha'], ϵ=p['epsilon'], t_R=p['t_R'],
        x_R=p['x_R_p'] * L, a_H=p['a_H'], x_H=p['x_H_p'] * L, γ_R_minus=p['gamma_R_minus'],
        γ_R_plus=p['gamma_R_plus'], l_R=p['l_R_p'], κ=p['kappa'], t_P=p['t_P'], w_P0=p['w_P0'],
        x_P=p['x_P_p'])
    manoeuvring = mmg_3dof.Mmg3DofManeuveringParams(
        k_0=p['k_0'], k_1=p['k_1'], k_2=p['k_2'], R_0_dash=p['R_0_p'], X_vv_dash=p['X_vv_p'],
        X_vr_dash=p['X_vr_p'], X_rr_dash=p['X_rr_p'], X_vvvv_dash=p['X_vvvv_p'],
        Y_v_dash=p['Y_v_p'], Y_r_dash=p['Y_r_p'], Y_vvv_dash=p['Y_vvv_p'],
        Y_vvr_dash=p['Y_vvr_p'], Y_vrr_dash=p['Y_vrr_p'], Y_rrr_dash=p['Y_rrr_p'],
        N_v_dash=p['N_v_p'], N_r_dash=p['N_r_p'], N_vvv_dash=p['N_vvv_p'],
        N_vvr_dash=p['N_vvr_p'], N_vrr_dash=p['N_vrr_p'], N_rrr_dash=p['N_rrr_p'])
    return basic, manoeuvring


def fixture_against_table(setup):
    """Every value of shipmmg's fixture that is not data/kvlcc2_mmg.json's, and the mass and
    inertia it builds against the scene's."""
    eom = setup['eom']
    differ = {k: {'shipmmg_tests': v, 'eom': eom[k]} for k, v in SHIPMMG_TESTS.items()
              if eom.get(k) != v}
    rho, f = setup['density'], SHIPMMG_TESTS
    mass = rho * f['nabla']
    izz = mass * (0.25 * f['L']) ** 2
    assert mass == setup['mass'] and izz == setup['izz'], 'the fixture builds another body'
    return differ


# ----------------------------------------------------------------------------------------------
# eom's steering gear: the rate limit on a first-order lag

class Gear:
    """delta(t) from delta0 at t0 toward the command c: at the rate limit R until |c - delta| = R T,
    then c - (c - delta) e^{-(t - t1)/T}; the solution of eom's d delta/dt = clamp((c - delta)/T)."""

    def __init__(self, t0, delta0, command, rate, lag):
        self.t0, self.delta0, self.c, self.R, self.T = t0, delta0, command, rate, lag
        gap = command - delta0
        self.sign = math.copysign(1.0, gap)
        self.ramp = max(0.0, (abs(gap) - rate * lag) / rate)   # how long it moves at the limit
        self.t1 = t0 + self.ramp
        self.gap1 = gap - self.sign * rate * self.ramp              # c - delta at t1

    def angle(self, t):
        if t <= self.t1:
            return self.delta0 + self.sign * self.R * (t - self.t0)
        return self.c - self.gap1 * math.exp(-(t - self.t1) / self.T)

    def grid(self, end):
        """Knots for shipmmg's spline: fine on the ramp and the lag, a knot at t1, coarse after."""
        settle = min(end, self.t1 + 30 * self.T)
        parts = [np.linspace(self.t0, self.t1, max(2, int(self.ramp / 0.005) + 1)),
                 np.linspace(self.t1, settle, 1200),
                 np.linspace(settle, end, max(2, int((end - settle) / 0.5) + 1))]
        return np.unique(np.concatenate(parts))


# ----------------------------------------------------------------------------------------------
# shipmmg's right-hand side, copied (mmg_3dof.py:862-955) with each difference a switch

def local_rhs(p, setup, switches, gear, n):
    rho, L_pp, d, x_G = setup['density'], p['L'], p['d'], setup['x_G']
    D_p, A_R, η = p['D_P'], p['A_R'], p['D_P'] / p['H_R']
    m, I_zG = setup['mass'], setup['izz']
    m_x = 0.5 * rho * L_pp ** 2 * d * p['m_x_p']
    m_y = 0.5 * rho * L_pp ** 2 * d * p['m_y_p']
    J_z = 0.5 * rho * L_pp ** 4 * d * p['J_z_p']
    x_R, x_H = p['x_R_p'] * L_pp, p['x_H_p'] * L_pp
    x_P, w_P0, l_R = p['x_P_p'], p['w_P0'], p['l_R_p']
    k_0, k_1, k_2 = p['k_0'], p['k_1'], p['k_2']
    t_P, t_R, a_H, ϵ, κ, f_α = p['t_P'], p['t_R'], p['a_H'], p['epsilon'], p['kappa'], p['f_alpha']
    γ_R_minus, γ_R_plus = p['gamma_R_minus'], p['gamma_R_plus']
    C_1, C_2_plus, C_2_minus = p['C_1'], p['C_2_plus'], p['C_2_minus']
    X_c = [p[k] for k in ('R_0_p', 'X_vv_p', 'X_vr_p', 'X_rr_p', 'X_vvvv_p')]
    Y_c = [p[k] for k in ('Y_v_p', 'Y_r_p', 'Y_vvv_p', 'Y_vvr_p', 'Y_vrr_p', 'Y_rrr_p')]
    N_c = [p[k] for k in ('N_v_p', 'N_r_p', 'N_vvv_p', 'N_vvr_p', 'N_vrr_p', 'N_rrr_p')]
    midship = switches['kinematics'] == 'eom'
    paper_wake = switches['wake'] == 'eom'
    nps = n
    I = I_zG + J_z + (x_G ** 2) * m

    def rhs(t, X):
        u, v, r, x, y, ψ, s = X
        δ = gear.angle(t)
        v_flow = v if midship else v - r * x_G          # mmg_3dof.py:866, 868
        U = math.sqrt(u ** 2 + v_flow ** 2)
        β = math.asin(-v_flow / U)
        v_dash = v / U
        r_dash = r * L_pp / U
        β_P = β - x_P * r_dash
        if paper_wake:
            C_2 = C_2_plus if β_P >= 0.0 else C_2_minus
            w_P = 1.0 - (1.0 - w_P0) * (1.0 + (1.0 - math.exp(-C_1 * abs(β_P))) * (C_2 - 1.0))
        else:
            w_P = w_P0 * math.exp(-4.0 * β_P ** 2)       # mmg_3dof.py:873
        J = (1 - w_P) * u / (nps * D_p)
        K_T = k_0 + k_1 * J + k_2 * J ** 2
        β_R = β - l_R * r_dash
        γ_R = γ_R_minus if β_R < 0.0 else γ_R_plus
        v_R = U * γ_R * β_R
        u_R = u * (1 - w_P) * ϵ * math.sqrt(
            η * (1.0 + κ * (math.sqrt(1.0 + 8.0 * K_T / (math.pi * J ** 2)) - 1)) ** 2 + (1 - η))
        U_R = math.sqrt(u_R ** 2 + v_R ** 2)
        α_R = δ - math.atan2(v_R, u_R)
        F_N = 0.5 * A_R * rho * f_α * (U_R ** 2) * math.sin(α_R)
        q = 0.5 * rho * L_pp * d * (U ** 2)
        X_H = q * (-X_c[0] + X_c[1] * v_dash ** 2 + X_c[2] * v_dash * r_dash
                   + X_c[3] * r_dash ** 2 + X_c[4] * v_dash ** 4)
        X_R = -(1 - t_R) * F_N * math.sin(δ)
        X_P = (1 - t_P) * rho * K_T * nps ** 2 * D_p ** 4
        Y_H = q * (Y_c[0] * v_dash + Y_c[1] * r_dash + Y_c[2] * v_dash ** 3
                   + Y_c[3] * v_dash ** 2 * r_dash + Y_c[4] * v_dash * r_dash ** 2
                   + Y_c[5] * r_dash ** 3)
        Y_R = -(1 + a_H) * F_N * math.cos(δ)
        N_H = q * L_pp * (N_c[0] * v_dash + N_c[1] * r_dash + N_c[2] * v_dash ** 3
                          + N_c[3] * v_dash ** 2 * r_dash + N_c[4] * v_dash * r_dash ** 2
                          + N_c[5] * r_dash ** 3)
        N_R = -(x_R + a_H * x_H) * F_N * math.cos(δ)
        d_u = ((X_H + X_R + X_P) + (m + m_y) * v * r + x_G * m * (r ** 2)) / (m + m_x)
        d_v = ((x_G ** 2) * (m ** 2) * u * r - (N_H + N_R) * x_G * m
               + ((Y_H + Y_R) - (m + m_x) * u * r) * I) / (I * (m + m_y) - (x_G ** 2) * (m ** 2))
        d_r = (N_H + N_R - x_G * m * (d_v + u * r)) / I
        return [d_u, d_v, d_r, u * math.cos(ψ) - v * math.sin(ψ),
                u * math.sin(ψ) + v * math.cos(ψ), r, math.sqrt(u * u + v * v)]

    return rhs


# ----------------------------------------------------------------------------------------------
# Running a trial: stages between rudder reversals, events on the dense output

class Record:
    """What a run met: the state (u, v, r, x, y, psi, s) at each event, in eom's terms."""

    def __init__(self):
        self.heading = {}       # 90, 180 -> (t, state)
        self.switches = []      # (t, state) at each reversal
        self.peaks = []         # (k, t, state): r = 0 after the k-th reversal
        self.end = None


def heading_event(side, angle):
    def g(t, y):
        return side * y[5] - angle
    g.direction = 1.0
    return g


def yaw_zero(t, y):
    return y[2]


def distance(sol, t0, t1):
    """The distance run by midship from t0 to t1 on shipmmg's dense output (10-point
    Gauss-Legendre on each of its steps)."""
    nodes, weights = np.polynomial.legendre.leggauss(10)
    cuts = np.concatenate([[t0], sol.t[(sol.t > t0) & (sol.t < t1)], [t1]])
    total = 0.0
    for a, b in zip(cuts[:-1], cuts[1:]):
        ts = 0.5 * (b - a) * nodes + 0.5 * (a + b)
        state = sol.sol(ts)
        total += 0.5 * (b - a) * float(np.dot(weights, np.hypot(state[0], state[1])))
    return total


def run_trial(trial, setup, p, n, *, engine, switches=None, tol=RTOL, method='DOP853'):
    """One trial of eom's scene: engine 'shipmmg' (simulate_mmg_3dof, stage by stage) or 'local'
    (the copied right-hand side with `switches`)."""
    side = 1.0 if trial['side'] == 'starboard' else -1.0
    zigzag = trial['kind'] == 'zigzag'
    end, R, T = trial['duration'], setup['max_rate'], setup['lag']
    basic, man = shipmmg_params(p, setup)
    rec = Record()
    t, delta, command = 0.0, 0.0, side * trial['rudder']
    state = [setup['speed'], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]   # u, v, r, x, y, psi, s
    stage = 0
    options = {'rtol': tol, 'atol': tol} if tol else {}
    while t < end:
        gear = Gear(t, delta, command, R, T)
        if zigzag:
            next_side = side if stage % 2 == 0 else -side
            events = [heading_event(next_side, trial['heading'])]
            events[0].terminal = True
            if stage > 0:
                events.append(yaw_zero)
        else:
            events = [heading_event(side, math.pi / 2), heading_event(side, math.pi)]
        if engine == 'shipmmg':
            grid = gear.grid(end)
            angles = [gear.angle(s) for s in grid]
            sol = mmg_3dof.simulate_mmg_3dof(
                basic, man, grid, angles, np.full(len(grid), n),
                u0=state[0], v0=state[1], r0=state[2], x0=state[3], y0=state[4], ψ0=state[5],
                ρ=setup['density'], method=method, events=events, **options)
            at = lambda ev: [*ev[:6], None]
        else:
            rhs = local_rhs(p, setup, switches, gear, n)
            # Split where the gear leaves its rate limit: the rudder's second derivative jumps.
            sol = None
            pieces = [(t, gear.t1), (gear.t1, end)] if t < gear.t1 < end else [(t, end)]
            t_events = [[] for _ in events]
            y_events = [[] for _ in events]
            for a, b in pieces:
                piece = solve_ivp(rhs, (a, b), state, method=method, events=events,
                                  dense_output=False, **options)
                for i in range(len(events)):
                    t_events[i].extend(piece.t_events[i])
                    y_events[i].extend(piece.y_events[i])
                state = list(piece.y[:, -1])
                sol = piece
                if piece.status == 1:
                    break
            sol.t_events, sol.y_events = t_events, y_events
            at = lambda ev: list(ev)
        assert sol.success, sol.message
        if zigzag:
            if stage > 0 and len(sol.t_events[1]):
                rec.peaks.append((stage - 1, sol.t_events[1][0], at(sol.y_events[1][0])))
            if len(sol.t_events[0]):
                t_sw = float(sol.t_events[0][0])
                y_sw = at(sol.y_events[0][0])
                if engine == 'shipmmg':
                    y_sw[6] = state[6] + distance(sol, t, t_sw)
                rec.switches.append((t_sw, y_sw))
                delta = gear.angle(t_sw)
                command = -command
                state, t = y_sw, t_sw
                stage += 1
                continue
        else:
            for i, key in enumerate((90, 180)):
                if len(sol.t_events[i]):
                    rec.heading[key] = (float(sol.t_events[i][0]), at(sol.y_events[i][0]))
        y_end = at(sol.y[:, -1])
        rec.end = (float(sol.t[-1]), y_end)
        t = end
    return figures(trial, rec)


def figures(trial, rec):
    """eom's figures (src/kinds/ship/manoeuvre/figures.rs) from the events met."""
    side = 1.0 if trial['side'] == 'starboard' else -1.0
    out = {}
    if trial['kind'] == 'turning_circle':
        t90, y90 = rec.heading[90]
        t180, y180 = rec.heading[180]
        out['advance_90_m'] = y90[3]
        out['transfer_90_m'] = abs(y90[4])
        out['tactical_diameter_m'] = abs(y180[4])
        u, v, r = rec.end[1][:3]
        speed = math.hypot(u, v)
        out['steady_turning_radius_m'] = speed / abs(r)
        out['steady_speed_m_s'] = speed
        out['t_90_s'] = t90
        out['t_180_s'] = t180
        return {k: out[k] for k in TURNING}
    psi_a = trial['heading']
    sw = rec.switches
    # The first reversal's side is the side of the rudder put over: this ship turns to it.
    for k in (0, 1):
        peak = next(y for (j, _, y) in rec.peaks if j == k)
        sk = side if k == 0 else -side
        out[('first_overshoot_deg', 'second_overshoot_deg')[k]] = math.degrees(sk * peak[5] - psi_a)
    out['reach_time_s'] = sw[0][0]
    out['period_s'] = sw[2][0] - sw[0][0]
    out['initial_turning_distance_m'] = sw[0][1][6]
    return {k: out[k] for k in ZIGZAG}


def steady_settled(trial, setup, p, n):
    """Whether the turn had settled by the end as eom's Course::steady asks: over the last 360 deg
    of heading, U and r within 1 % of their final values (read on shipmmg's own run)."""
    basic, man = shipmmg_params(p, setup)
    side = 1.0 if trial['side'] == 'starboard' else -1.0
    gear = Gear(0.0, 0.0, side * trial['rudder'], setup['max_rate'], setup['lag'])
    grid = gear.grid(trial['duration'])
    sol = mmg_3dof.simulate_mmg_3dof(basic, man, grid, [gear.angle(s) for s in grid],
                                     np.full(len(grid), n), u0=setup['speed'],
                                     ρ=setup['density'], method='DOP853', rtol=RTOL, atol=ATOL)
    ts = np.linspace(0, trial['duration'], 30001)
    y = sol.sol(ts)
    psi_end = y[5, -1]
    window = np.abs(psi_end - y[5]) <= 2 * math.pi
    speed = np.hypot(y[0], y[1])
    vary = lambda a: float(np.max(np.abs(a[window] - a[-1])) / abs(a[-1]))
    return {'turned_deg': math.degrees(abs(psi_end)), 'speed_variation': vary(speed),
            'yaw_rate_variation': vary(y[2])}


# ----------------------------------------------------------------------------------------------
# shipmmg's own zig-zag function

def own_zigzag(trial, setup, p, n, tolerances=None):
    """zigzag_test_mmg_3dof as published, on a grid of ZIGZAG_GRID_S; with `tolerances`, its calls
    to simulate_mmg_3dof are given them (the function does not pass them on itself). Figures off
    its samples: the reversal at the first sample past +-psi_a (its own rule), the overshoot the
    largest sampled excursion, the distance by the trapezoid rule."""
    basic, man = shipmmg_params(p, setup)
    side = 1.0 if trial['side'] == 'starboard' else -1.0
    times = np.linspace(0.0, trial['duration'], int(round(trial['duration'] / ZIGZAG_GRID_S)) + 1)
    original = mmg_3dof.simulate_mmg_3dof
    if tolerances:
        def tight(*args, **kwargs):
            kwargs.update(method='DOP853', rtol=tolerances, atol=tolerances)
            return original(*args, **kwargs)
        mmg_3dof.simulate_mmg_3dof = tight
    try:
        δ, u, v, r, x, y, ψ = mmg_3dof.zigzag_test_mmg_3dof(
            basic, man, side * trial['rudder'], trial['heading'], times,
            np.full(len(times), n), δ_rad_rate=setup['max_rate'], u0=setup['speed'],
            ρ=setup['density'])
    finally:
        mmg_3dof.simulate_mmg_3dof = original
    ψ, psi_a = np.asarray(ψ), trial['heading']
    switches, k, s = [], 0, side
    for i in range(len(times)):
        if s * ψ[i] >= psi_a and (not switches or i > switches[-1]):
            switches.append(i)
            s = -s
    peaks = []
    for k in (0, 1):
        sk = side if k == 0 else -side
        seg = slice(switches[k], switches[k + 1])
        peaks.append(math.degrees(float(np.max(sk * ψ[seg])) - psi_a))
    speed = np.hypot(np.asarray(u), np.asarray(v))
    i0 = switches[0]
    dist = float(np.trapezoid(speed[:i0 + 1], times[:i0 + 1]))
    out = {'first_overshoot_deg': peaks[0], 'second_overshoot_deg': peaks[1],
           'reach_time_s': float(times[switches[0]]),
           'period_s': float(times[switches[2]] - times[switches[0]]),
           'initial_turning_distance_m': dist}
    return {k: out[k] for k in ZIGZAG}


# ----------------------------------------------------------------------------------------------
# eom

def run_eom(setup, timing):
    """eom's figures from `eom run` on scenes/kvlcc2_l7.toml with its turning circles and
    zig-zags alone, and its wall times: those six trials in one command (TIMING_RUNS runs, as
    `time` reads them) and each trial alone (the scene with that manoeuvre and side alone)."""
    if not os.access(EOM, os.X_OK):
        return None
    version = subprocess.run([EOM, '--version'], capture_output=True, text=True).stdout.strip()
    work = tempfile.mkdtemp(prefix='eom_kvlcc2_')

    def run(scene, out):
        start = time.perf_counter()
        done = subprocess.run([EOM, 'run', scene, '--out', out, '--force'],
                              capture_output=True, text=True, cwd=ROOT)
        elapsed = time.perf_counter() - start
        if done.returncode != 0:
            raise SystemExit(f'eom run {scene} failed:\n{done.stderr}')
        return elapsed, json.load(open(os.path.join(out, 'summary.json')))

    # The scene's turning circles and zig-zags, the trials compared (its spiral is eom's alone).
    text = open(SCENE).read()
    head, *blocks = text.split('[[manoeuvre]]')
    by_name = {}
    for block in blocks:
        manoeuvre = tomllib.loads('[[manoeuvre]]' + block)['manoeuvre'][0]
        if manoeuvre['kind'] in ('turning_circle', 'zigzag'):
            by_name[manoeuvre['name']] = block
    trials_scene = os.path.join(work, 'trials.toml')
    with open(trials_scene, 'w') as f:
        f.write(head + ''.join('[[manoeuvre]]' + block for block in by_name.values()))
    wall, summary = run(trials_scene, os.path.join(work, 'scene'))
    result = {'version': version,
              'command': 'eom run on scenes/kvlcc2_l7.toml with its turning circles and zig-zags '
                         'alone --out DIR --force',
              'approach_rate_rps': summary['model']['mmg']['approach_rate_rps'],
              'integrator': {k: summary['integrator'][k] for k in ('method', 'rtol', 'atol')},
              'figures': {}}
    for trial in setup['trials']:
        figs = summary['manoeuvre'][trial['name']]['sides'][trial['side']]
        keys = TURNING if trial['kind'] == 'turning_circle' else ZIGZAG
        result['figures'][label(trial)] = {k: figs[k] for k in keys}
    if timing:
        walls, inner = [wall], [summary['wall_seconds']]
        for i in range(TIMING_RUNS - 1):
            w, s = run(trials_scene, os.path.join(work, 'scene'))
            walls.append(w)
            inner.append(s['wall_seconds'])
        result['timing'] = {'scene_wall_s': walls, 'scene_wall_median_s': statistics.median(walls),
                            'scene_summary_wall_seconds': inner,
                            'scene_summary_wall_median_s': statistics.median(inner),
                            'per_trial': {}}
        for trial in setup['trials']:
            stem = f"{trial['name']}_{trial['side']}"
            scene = os.path.join(work, f'{stem}.toml')
            with open(scene, 'w') as f:
                f.write(head + '[[manoeuvre]]' + by_name[trial['name']].rstrip()
                        + f'\nside = "{trial["side"]}"\n')
            walls, inner = [], []
            for i in range(TIMING_RUNS):
                w, s = run(scene, os.path.join(work, stem))
                walls.append(w)
                inner.append(s['wall_seconds'])
            result['timing']['per_trial'][label(trial)] = {
                'wall_median_s': statistics.median(walls),
                'summary_wall_median_s': statistics.median(inner),
                'steps': s['integrator']['steps'], 'rhs_evals': s['integrator']['rhs_evals']}
    return result


# ----------------------------------------------------------------------------------------------

def label(trial):
    return f"{trial['name']}/{trial['side']}"


def surge_at_approach(setup, p, n, speed):
    """shipmmg's own X = X_H + X_P + X_R on the straight course (get_sub_values_from_simulation_
    result, its force function), rudder amidships."""
    basic, man = shipmmg_params(p, setup)
    X_H, X_R, X_P, *_ = mmg_3dof.get_sub_values_from_simulation_result(
        [speed], [0.0], [0.0], [0.0], [n], basic, man, ρ=setup['density'])
    total = X_H[0] + X_R[0] + X_P[0]
    m_x = 0.5 * setup['density'] * p['L'] ** 2 * p['d'] * p['m_x_p']
    return {'rate_rps': n, 'speed_m_s': speed, 'X_H_N': float(X_H[0]), 'X_P_N': float(X_P[0]),
            'X_R_N': float(X_R[0]), 'X_N': float(total),
            'X_over_thrust': float(total * (1 - p['t_P']) / X_P[0]),
            'du_dt_m_s2': float(total / (setup['mass'] + m_x))}


def median_time(fn, runs=TIMING_RUNS):
    walls = []
    for _ in range(runs):
        start = time.perf_counter()
        fn()
        walls.append(time.perf_counter() - start)
    return statistics.median(walls)


def compute(setup, timing):
    n0 = balancing_rate(setup['eom'], setup['density'], setup['speed'])
    fixture_diff = fixture_against_table(setup)
    x_P = {'shipmmg': SHIPMMG_TESTS['x_P_p'], 'eom': setup['eom']['x_P_p']}
    p_of = lambda which: parameters(setup, x_P[which])
    result = {'n0_rps': n0, 'fixture_differs_from_table': fixture_diff, 'variants': {},
              'shipmmg_runs': {}, 'timing': {}}
    result['surge_at_approach'] = {
        'at_n0': surge_at_approach(setup, p_of('shipmmg'), n0, setup['speed']),
        'at_shipmmg_example': surge_at_approach(setup, p_of('shipmmg'), SHIPMMG_EXAMPLE_RATE,
                                                SHIPMMG_EXAMPLE_SPEED),
    }
    trials = setup['trials']
    # shipmmg itself, as published and with eom's x_P (a parameter: shipmmg's own function).
    for key, which in (('published', 'shipmmg'), ('x_P', 'eom')):
        runs = {}
        for trial in trials:
            runs[label(trial)] = run_trial(trial, setup, p_of(which), n0, engine='shipmmg')
        result['shipmmg_runs'][key] = runs
    # The integrator's share: shipmmg as published at LOOSE, and at its own defaults.
    result['shipmmg_runs']['published_rtol_1e-10'] = {
        label(tr): run_trial(tr, setup, p_of('shipmmg'), n0, engine='shipmmg', tol=LOOSE)
        for tr in trials}
    result['shipmmg_runs']['published_rk45_1e-8'] = {
        label(tr): run_trial(tr, setup, p_of('shipmmg'), n0, engine='shipmmg', tol=EOM_TOL,
                             method='RK45') for tr in trials}
    result['shipmmg_runs']['published_defaults_rk45'] = {
        label(tr): run_trial(tr, setup, p_of('shipmmg'), n0, engine='shipmmg', tol=None,
                             method='RK45') for tr in trials}
    # shipmmg's own zig-zag function, as published and with tight tolerances given to it.
    zz = [tr for tr in trials if tr['kind'] == 'zigzag']
    result['shipmmg_runs']['own_zigzag_function'] = {
        label(tr): own_zigzag(tr, setup, p_of('shipmmg'), n0) for tr in zz}
    result['shipmmg_runs']['own_zigzag_function_tight'] = {
        label(tr): own_zigzag(tr, setup, p_of('shipmmg'), n0, tolerances=RTOL) for tr in zz}
    # The copied right-hand side, each switch.
    for key, sw in VARIANTS:
        result['variants'][key] = {
            'switches': sw,
            'figures': {label(tr): run_trial(tr, setup, p_of(sw['x_P']), n0, engine='local',
                                             switches=sw) for tr in trials}}
    result['steady'] = {label(tr): steady_settled(tr, setup, p_of('shipmmg'), n0)
                        for tr in trials if tr['kind'] == 'turning_circle'}
    if timing:
        per = {}
        for tr in trials:
            entry = {
                'simulate_mmg_3dof_dop853_1e-12_s': median_time(
                    lambda: run_trial(tr, setup, p_of('shipmmg'), n0, engine='shipmmg')),
                'simulate_mmg_3dof_rk45_1e-8_s': median_time(
                    lambda: run_trial(tr, setup, p_of('shipmmg'), n0, engine='shipmmg',
                                      tol=EOM_TOL, method='RK45')),
                'simulate_mmg_3dof_rk45_defaults_s': median_time(
                    lambda: run_trial(tr, setup, p_of('shipmmg'), n0, engine='shipmmg', tol=None,
                                      method='RK45')),
            }
            if tr['kind'] == 'zigzag':
                entry['zigzag_test_mmg_3dof_s'] = median_time(
                    lambda: own_zigzag(tr, setup, p_of('shipmmg'), n0))
            per[label(tr)] = entry
        result['timing'] = {'runs': TIMING_RUNS, 'statistic': 'median wall seconds',
                            'per_trial': per,
                            'scene_total_s': {k: sum(e[k] for e in per.values())
                                              for k in ('simulate_mmg_3dof_dop853_1e-12_s',
                                                        'simulate_mmg_3dof_rk45_1e-8_s',
                                                        'simulate_mmg_3dof_rk45_defaults_s')}}
    return result


def largest_relative(a, b):
    worst = 0.0
    for trial, figs in a.items():
        for k, v in figs.items():
            w = b[trial][k]
            worst = max(worst, abs(v - w) / max(abs(w), CHECK_ABSOLUTE))
    return worst


def attribution(variants, shipmmg_published, eom):
    """For each figure, what each difference moves it by alone (switched from shipmmg as
    published) and its share of the whole move: the Shapley value, each difference's move
    averaged over the orders in which the three can be switched, so that the shares add up to
    the move with all three switched whatever their interaction."""
    n = len(DIFFERENCE_KEYS)
    f = lambda switched, trial, key: variants[variant_name(switched)]['figures'][trial][key]
    out = {}
    for trial, figs in variants['published']['figures'].items():
        out[trial] = {}
        for key, base in figs.items():
            entry = {'alone': {}, 'share': {}}
            for i in DIFFERENCE_KEYS:
                others = [k for k in DIFFERENCE_KEYS if k != i]
                entry['alone'][i] = f([i], trial, key) - base
                share = 0.0
                for size in range(n):
                    weight = math.factorial(size) * math.factorial(n - size - 1) / math.factorial(n)
                    for subset in combinations(others, size):
                        share += weight * (f([*subset, i], trial, key) - f(list(subset), trial, key))
                entry['share'][i] = share
            entry['all'] = f(DIFFERENCE_KEYS, trial, key) - base
            if eom:
                entry['eom_minus_shipmmg'] = eom[trial][key] - shipmmg_published[trial][key]
                entry['not_attributed'] = entry['eom_minus_shipmmg'] - entry['all']
            out[trial][key] = entry
    return out


def markdown(doc):
    out = []
    eom = doc['eom']['figures'] if doc.get('eom') else None
    var = doc['variants']
    cols = [('shipmmg', doc['shipmmg_runs']['published'])]
    cols += [(f"+ {k}" if i else 'copy, as published', var[k]['figures'])
             for i, k in enumerate(CHAIN)]
    head = ['trial', 'figure', 'shipmmg 0.0.11', 'copy as published', '+ x_P = -0.48',
            '+ U, β at midship', "+ paper's wake", 'eom']
    out.append('| ' + ' | '.join(head) + ' |')
    out.append('|' + '---|' * 2 + '---:|' * (len(head) - 2))
    for trial, figs in doc['shipmmg_runs']['published'].items():
        for key in figs:
            row = [trial, key] + [f"{c[trial][key]:.4f}" for _, c in cols]
            row.append(f"{eom[trial][key]:.4f}" if eom else '-')
            out.append('| ' + ' | '.join(row) + ' |')
    out.append('')
    out.append('Each difference from shipmmg as published to eom: what it moves the figure by '
               'switched alone, and its share of the whole move (the Shapley value over the orders '
               'of switching; the shares add up to eom − shipmmg but for the last column):')
    out.append('')
    head = ['trial', 'figure', 'x_P alone', 'x_P share', 'U, β alone', 'U, β share',
            'wake alone', 'wake share', 'eom − shipmmg', 'not attributed']
    out.append('| ' + ' | '.join(head) + ' |')
    out.append('|' + '---|' * 2 + '---:|' * (len(head) - 2))
    for trial, figs in doc['attribution'].items():
        for key, e in figs.items():
            row = [trial, key]
            for i in DIFFERENCE_KEYS:
                row += [f"{e['alone'][i]:+.4f}", f"{e['share'][i]:+.4f}"]
            row += [f"{e.get('eom_minus_shipmmg', float('nan')):+.4f}",
                    f"{e.get('not_attributed', float('nan')):+.1e}"]
            out.append('| ' + ' | '.join(row) + ' |')
    out.append('')
    out.append("shipmmg as published under other integrations (the model's figures are the first "
               'column):')
    out.append('')
    runs = doc['shipmmg_runs']
    names = [('published', 'DOP853 1e-12'), ('published_rk45_1e-8', 'RK45 1e-8'),
             ('published_defaults_rk45', 'RK45 defaults'),
             ('own_zigzag_function', 'zigzag_test_mmg_3dof'),
             ('own_zigzag_function_tight', 'zigzag_test_mmg_3dof, DOP853 1e-12')]
    out.append('| trial | figure | ' + ' | '.join(n for _, n in names) + ' |')
    out.append('|' + '---|' * 2 + '---:|' * len(names))
    for trial, figs in runs['published'].items():
        for key in figs:
            row = [trial, key] + [f"{runs[k][trial][key]:.4f}" if trial in runs[k] else '-'
                                  for k, _ in names]
            out.append('| ' + ' | '.join(row) + ' |')
    return '\n'.join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--check', action='store_true')
    args = parser.parse_args()
    installed = importlib.metadata.version('shipmmg')
    if installed != SHIPMMG_VERSION:
        sys.exit(f'shipmmg {installed} is installed; this comparison is of {SHIPMMG_VERSION}: '
                 f'pip install shipmmg=={SHIPMMG_VERSION}')
    setup = read_setup()
    result = compute(setup, timing=not args.check)
    eom = run_eom(setup, timing=not args.check)
    if args.check:
        stored = json.load(open(OUT, encoding='utf-8'))
        failures = []

        def compare(where, new, old):
            for trial, figs in new.items():
                for k, v in figs.items():
                    w = old[trial][k]
                    if abs(v - w) > max(CHECK_RELATIVE * abs(w), CHECK_ABSOLUTE):
                        failures.append(f'{where} {trial} {k}: {v!r} against {w!r}')
        for key, runs in result['shipmmg_runs'].items():
            compare(f'shipmmg_runs.{key}', runs, stored['shipmmg_runs'][key])
        for key, v in result['variants'].items():
            compare(f'variants.{key}', v['figures'], stored['variants'][key]['figures'])
        if eom:
            compare('eom', eom['figures'], stored['eom']['figures'])
        else:
            print(f'{EOM} is not built: eom\'s figures not checked')
        if failures:
            sys.exit('\n'.join(['figures differ from ' + OUT + ':'] + failures))
        print(f'every figure within {CHECK_RELATIVE:g} of {os.path.relpath(OUT, ROOT)}')
        return
    if eom is None:
        if os.path.exists(OUT):
            eom = json.load(open(OUT, encoding='utf-8')).get('eom')
            print(f'{EOM} is not built: eom\'s figures are those of the JSON as it stood')
    pub = result['shipmmg_runs']['published']
    chain_end = result['variants']['x_P+kinematics+wake']['figures']
    doc = {
        'about': "The KVLCC2 at L = 7 m under shipmmg 0.0.11 (PyPI) in the setup of "
                 "scenes/kvlcc2_l7.toml, with each way its model differs from eom's switched to "
                 "eom's reading; written by peer/mmg/shipmmg_kvlcc2.py. Figures as eom defines "
                 "them (src/kinds/ship/manoeuvre/figures.rs); delta > 0 turns to starboard in both.",
        'versions': {'python': platform.python_version(), 'numpy': np.__version__,
                     'scipy': scipy.__version__, 'shipmmg': SHIPMMG_VERSION,
                     'eom': eom['version'] if eom else None},
        'setup': {
            'scene': 'scenes/kvlcc2_l7.toml', 'table': 'data/kvlcc2_mmg.json',
            'density_kg_m3': setup['density'], 'approach_speed_m_s': setup['speed'],
            'mass_kg': setup['mass'], 'izz_kg_m2': setup['izz'], 'x_G_m': setup['x_G'],
            'propeller_rate_rps': result['n0_rps'],
            'propeller_rate_eom_rps': eom['approach_rate_rps'] if eom else None,
            'rudder': setup['rudder_table'],
            'trials': [{k: v for k, v in tr.items() if k not in ('rudder', 'heading')}
                       for tr in setup['trials']],
            'integration': {
                'shipmmg': f'simulate_mmg_3dof (solve_ivp) with method DOP853, rtol = atol = '
                           f'{RTOL:g}; the rudder as samples of the gear law on a grid with a knot '
                           'where its rate limit ends (shipmmg interpolates them by a natural cubic '
                           'spline); events on the dense output (scipy\'s root finding)',
                'copy': f'solve_ivp DOP853 at rtol = atol = {RTOL:g} on the copied right-hand '
                        'side, the gear law exact, split where the rate limit ends',
                'eom': 'dopri5 at rtol = atol = 1e-8 (the scene), events to adjacent doubles',
                'loose': f'shipmmg again at {LOOSE:g}: published_rtol_1e-10',
            },
        },
        'differences': DIFFERENCES,
        'the_same': SAME,
        'fixture_differs_from_table': result['fixture_differs_from_table'],
        'surge_at_approach': result['surge_at_approach'],
        'shipmmg_runs': result['shipmmg_runs'],
        'variants': result['variants'],
        'attribution': attribution(result['variants'], pub, eom['figures'] if eom else None),
        'steady_turn_settled': result['steady'],
        'residuals': {
            'copy_against_shipmmg_published': largest_relative(
                result['variants']['published']['figures'], pub),
            'copy_against_shipmmg_x_P': largest_relative(
                result['variants']['x_P']['figures'], result['shipmmg_runs']['x_P']),
            'shipmmg_1e-12_against_1e-10': largest_relative(
                result['shipmmg_runs']['published_rtol_1e-10'], pub),
            'eom_reading_against_eom': largest_relative(chain_end, eom['figures']) if eom else None,
        },
        'eom': eom,
        'timing': {'shipmmg': result['timing'], 'eom': eom.get('timing') if eom else None,
                   'machine': f'{platform.machine()}, {os.cpu_count()} cores',
                   'load_average_1_5_15_min_after': list(os.getloadavg()),
                   'note': 'wall times on a shared machine; eom\'s include reading the scene '
                           '(the model derived and proved), each trial run twice (the second at '
                           'tolerances a hundred times tighter, for summary.json\'s '
                           'tolerance_difference) and writing its outputs'},
        'check': {'relative': CHECK_RELATIVE, 'absolute': CHECK_ABSOLUTE},
    }
    with open(OUT, 'w', encoding='utf-8') as f:
        f.write(json.dumps(doc, indent=1, ensure_ascii=False) + '\n')
    print(markdown(doc))
    print()
    print('residuals (largest relative):', json.dumps(doc['residuals']))


if __name__ == '__main__':
    main()
