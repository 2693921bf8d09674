"""The MMG standard method's forces on the KVLCC2, worked by hand from the paper, at six states:
the checkpoint table eom's MMG force module is held to (tests/mmg_forces.rs).

    python3 peer/mmg/checkpoint.py          # writes peer/mmg/checkpoints.json
    python3 peer/mmg/checkpoint.py --check  # exits 1 if the file is not what it would write

The model is H. Yasukawa and Y. Yoshimura (2015), "Introduction of MMG standard method for ship
maneuvering predictions", J. Mar. Sci. Technol. 20:37-52, doi:10.1007/s00773-014-0293-y: the
forces about midship split into the hull's (H), the propeller's (P) and the rudder's (R), at a
state (u, v_m, r) of the midship and the inputs (delta, n_P). The parameters are the paper's
KVLCC2 table as public codes transcribe it, data/kvlcc2_mmg.json. Written from the paper's
equations on its own, in the order a naval architect works them by hand, with the standard
library only; it shares no code with eom. Each value is written with Python's repr (the shortest
decimal that reads back to the same double).
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, '..', '..')
TABLE = os.path.join(ROOT, 'data', 'kvlcc2_mmg.json')
OUT = os.path.join(HERE, 'checkpoints.json')

# Every quantity of a state, in the order it is worked out, with its unit.
UNITS = {
    'U': 'm/s', 'beta': 'rad', 'v_prime': '1', 'r_prime': '1',
    'X_H': 'N', 'Y_H': 'N', 'N_H': 'N m',
    'beta_P': 'rad', 'w_P': '1', 'J': '1', 'K_T': '1', 'T': 'N', 'X_P': 'N',
    'beta_R': 'rad', 'gamma_R': '1', 'u_R': 'm/s', 'v_R': 'm/s', 'alpha_R': 'rad', 'U_R': 'm/s',
    'F_N': 'N', 'X_R': 'N', 'Y_R': 'N', 'N_R': 'N m',
    'X': 'N', 'Y': 'N', 'N': 'N m',
}

DENSITY = 1025.0  # kg/m^3, the SIMMAN 2020 setup's

# (name, what it shows, scale, u m/s, v_m m/s, r rad/s, delta deg, n_P rev/s)
STATES = [
    ('straight_ahead', 'on course at the approach speed, rudder amidships', 'L7',
     1.179, 0.0, 0.0, 0.0, 10.0),
    ('drifting', 'sideslip alone (v_m < 0, beta about 9.8 deg), no yaw, rudder amidships', 'L7',
     1.16, -0.2, 0.0, 0.0, 10.0),
    ('turning_starboard', 'hard to starboard (delta = +35 deg), yawing to starboard, drifting out', 'L7',
     0.9, -0.2, 0.06, 35.0, 10.0),
    ('turning_port', 'the mirror: hard to port (delta = -35 deg), yawing to port', 'L7',
     0.9, 0.2, -0.06, -35.0, 10.0),
    ('yaw_against_drift', 'r > 0 with beta_R < 0 (and beta_P < 0): gamma_R- and C_2- while yawing to starboard', 'L7',
     1.1, 0.15, 0.02, 10.0, 10.0),
    ('full_scale_turn', 'the 320 m ship turning to starboard at 20 deg of rudder', 'full',
     7.0, -1.0, 0.005, 20.0, 1.5),
]


def forces(c, ship, rho, u, vm, r, delta, n):
    """Every quantity of the paper's model at one state, in SI units, as a dict in UNITS' order."""
    L, d, Dp = ship['L'], ship['d'], ship['D_P']
    assert u > 0 and n > 0, 'the checkpoints are ahead, with the propeller turning ahead'
    q = {}

    # Hull. The speed and drift at midship, the non-dimensional sway and yaw.
    U = math.sqrt(u * u + vm * vm)
    beta = math.atan(-vm / u)
    vp = vm / U
    rp = r * L / U
    q['U'], q['beta'], q['v_prime'], q['r_prime'] = U, beta, vp, rp
    X_H_nd = -c['R_0_p'] + c['X_vv_p'] * vp**2 + c['X_vr_p'] * vp * rp + c['X_rr_p'] * rp**2 \
        + c['X_vvvv_p'] * vp**4
    Y_H_nd = c['Y_v_p'] * vp + c['Y_r_p'] * rp + c['Y_vvv_p'] * vp**3 + c['Y_vvr_p'] * vp**2 * rp \
        + c['Y_vrr_p'] * vp * rp**2 + c['Y_rrr_p'] * rp**3
    N_H_nd = c['N_v_p'] * vp + c['N_r_p'] * rp + c['N_vvv_p'] * vp**3 + c['N_vvr_p'] * vp**2 * rp \
        + c['N_vrr_p'] * vp * rp**2 + c['N_rrr_p'] * rp**3
    half_rho_U2 = 0.5 * rho * U**2
    q['X_H'] = half_rho_U2 * L * d * X_H_nd
    q['Y_H'] = half_rho_U2 * L * d * Y_H_nd
    q['N_H'] = half_rho_U2 * L**2 * d * N_H_nd

    # Propeller. The inflow angle at the propeller sets the wake in the manoeuvre: C_2 by the
    # side the flow comes from (at beta_P = 0 it multiplies zero; + is taken there).
    beta_P = beta - c['x_P_p'] * rp
    C_2 = c['C_2_plus'] if beta_P >= 0 else c['C_2_minus']
    one_minus_wP = (1 - c['w_P0']) * (1 + (1 - math.exp(-c['C_1'] * abs(beta_P))) * (C_2 - 1))
    w_P = 1 - one_minus_wP
    J = u * one_minus_wP / (n * Dp)
    K_T = c['k_0'] + c['k_1'] * J + c['k_2'] * J**2
    T = rho * n**2 * Dp**4 * K_T
    q['beta_P'], q['w_P'], q['J'], q['K_T'], q['T'] = beta_P, w_P, J, K_T, T
    q['X_P'] = (1 - c['t_P']) * T

    # Rudder. Its inflow: ahead, the wake speed accelerated by the propeller's race over the
    # share eta of the span in it; across, the flow straightened by the hull and propeller
    # (gamma_R by the side of beta_R; at beta_R = 0 it multiplies zero, and + is taken there,
    # the convention eom's module states, so that the table can name it).
    eta = Dp / ship['H_R']
    beta_R = beta - c['l_R_p'] * rp
    gamma_R = c['gamma_R_plus'] if beta_R >= 0 else c['gamma_R_minus']
    race = 1 + c['kappa'] * (math.sqrt(1 + 8 * K_T / (math.pi * J**2)) - 1)
    u_R = c['epsilon'] * u * one_minus_wP * math.sqrt(eta * race**2 + (1 - eta))
    v_R = U * gamma_R * beta_R
    alpha_R = delta - math.atan(v_R / u_R)
    U_R = math.sqrt(u_R**2 + v_R**2)
    F_N = 0.5 * rho * ship['A_R'] * U_R**2 * c['f_alpha'] * math.sin(alpha_R)
    q['beta_R'], q['gamma_R'], q['u_R'], q['v_R'] = beta_R, gamma_R, u_R, v_R
    q['alpha_R'], q['U_R'], q['F_N'] = alpha_R, U_R, F_N
    q['X_R'] = -(1 - c['t_R']) * F_N * math.sin(delta)
    q['Y_R'] = -(1 + c['a_H']) * F_N * math.cos(delta)
    x_R, x_H = c['x_R_p'] * L, c['x_H_p'] * L
    q['N_R'] = -(x_R + c['a_H'] * x_H) * F_N * math.cos(delta)

    # The whole ship, about midship.
    q['X'] = q['X_H'] + q['X_P'] + q['X_R']
    q['Y'] = q['Y_H'] + q['Y_R']
    q['N'] = q['N_H'] + q['N_R']
    assert list(q) == list(UNITS)
    return q


def table():
    data = json.load(open(TABLE))
    c = data['coefficients']
    states = []
    for name, about, scale, u, vm, r, delta_deg, n in STATES:
        delta = math.radians(delta_deg)
        states.append({
            'name': name, 'about': about, 'scale': scale, 'density': DENSITY,
            'u': u, 'v_m': vm, 'r': r, 'delta': delta, 'n_P': n,
            'values': forces(c, data['particulars'][scale], DENSITY, u, vm, r, delta, n),
        })
    return {
        'about': 'The MMG standard method (Yasukawa & Yoshimura 2015) on the KVLCC2 of '
                 'data/kvlcc2_mmg.json at six states, every intermediate quantity in SI units about '
                 'midship; delta in rad, positive turning the ship to starboard (the paper\'s sign). Written by '
                 'peer/mmg/checkpoint.py, which works the paper\'s equations on its own; '
                 'tests/mmg_forces.rs holds eom\'s module to it.',
        'units': UNITS,
        'states': states,
    }


def main():
    text = json.dumps(table(), indent=1, ensure_ascii=False) + '\n'
    if '--check' in sys.argv[1:]:
        if open(OUT, encoding='utf-8').read() != text:
            sys.exit(f'{OUT} is not what peer/mmg/checkpoint.py writes: run it')
        return
    with open(OUT, 'w', encoding='utf-8') as f:
        f.write(text)


if __name__ == '__main__':
    main()
