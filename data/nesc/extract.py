#!/usr/bin/env python3
"""Regenerate data/nesc/cases.json from a checkout of github.com/nasa/simupy-flight.

    python3 extract.py /path/to/simupy-flight            # writes cases.json beside this script
    python3 extract.py /path/to/simupy-flight --check    # compares with the existing file, byte for byte

Only the Python standard library is used. Trajectory numbers are copied as the strings the
CSV files print (never parsed and re-printed); the medians and spreads at t = 30 s are the
only computed numbers (IEEE doubles, written with Python's shortest round-trip repr).
The case descriptions are taken from the files verbatim (docstring tables, setup lines, DAVE-ML
initialValue attributes); the plain-language interpretation beside them is written below by
hand and says so.
"""

import argparse
import csv
import glob
import hashlib
import io
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

SOURCE_COMMIT = "70754e6916afc206e8c0abb386d1a9c98bf8f561"
CASES = range(1, 11)
CHECKPOINTS = [0.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0]
ATMOS = "NESC_data/Atmospheric_checkcases"
MODELS = "NESC_data/All_models"
DML_FILES = ["brick_inertia.dml", "brick_aero.dml", "cannonball_inertia.dml", "cannonball_aero.dml"]

# CSV column -> (plain name, unit as in the column name, meaning). Meanings are the NESC/AIAA
# S-119 variable names read plainly; the ones marked "(inferred)" are not stated in any file read.
COLUMNS = {
    "time": ("t", "s", "simulation time"),
    "gePosition_ft_X": ("x_ecef", "ft", "position in the Earth-centred Earth-fixed frame, X (equator/prime meridian)"),
    "gePosition_ft_Y": ("y_ecef", "ft", "ECEF position, Y (equator/90 deg E)"),
    "gePosition_ft_Z": ("z_ecef", "ft", "ECEF position, Z (north pole)"),
    "eiPosition_ft_X": ("x_eci", "ft", "position in the Earth-centred inertial frame, X (coincides with ECEF at t = 0)"),
    "eiPosition_ft_Y": ("y_eci", "ft", "ECI position, Y"),
    "eiPosition_ft_Z": ("z_eci", "ft", "ECI position, Z"),
    "eiVelocity_ft_s_X": ("vx_eci", "ft/s", "inertial velocity in ECI axes, X"),
    "eiVelocity_ft_s_Y": ("vy_eci", "ft/s", "inertial velocity in ECI axes, Y"),
    "eiVelocity_ft_s_Z": ("vz_eci", "ft/s", "inertial velocity in ECI axes, Z"),
    "feVelocity_ft_s_X": ("v_north", "ft/s", "Earth-relative velocity in local NED axes, North (simupy maps it to V_N)"),
    "feVelocity_ft_s_Y": ("v_east", "ft/s", "Earth-relative velocity, East (V_E)"),
    "feVelocity_ft_s_Z": ("v_down", "ft/s", "Earth-relative velocity, Down (V_D)"),
    "altitudeMsl_ft": ("altitude", "ft", "height above the reference ellipsoid / sphere (named 'Msl'; simupy compares it with its geodetic height h_D)"),
    "longitude_deg": ("longitude", "deg", "longitude"),
    "latitude_deg": ("latitude", "deg", "geodetic latitude (inferred; SIM02 in case 10 looks geocentric, see notes)"),
    "localGravity_ft_s2": ("gravity", "ft/s^2", "magnitude of the gravitation model's acceleration, without the centrifugal term (inferred: 32.1065 ft/s^2 at 30000 ft on the equator matches J2 gravitation, not gravity)"),
    "eulerAngle_deg_Yaw": ("psi", "deg", "Euler yaw of body w.r.t. local NED"),
    "eulerAngle_deg_Pitch": ("theta", "deg", "Euler pitch"),
    "eulerAngle_deg_Roll": ("phi", "deg", "Euler roll"),
    "bodyAngularRateWrtEi_deg_s_Roll": ("p", "deg/s", "body angular rate w.r.t. inertial space, body x"),
    "bodyAngularRateWrtEi_deg_s_Pitch": ("q", "deg/s", "body angular rate w.r.t. inertial space, body y"),
    "bodyAngularRateWrtEi_deg_s_Yaw": ("r", "deg/s", "body angular rate w.r.t. inertial space, body z"),
    "altitudeRateWrtMsl_ft_min": ("altitude_rate", "ft/min", "rate of change of altitude"),
    "speedOfSound_ft_s": ("speed_of_sound", "ft/s", "atmosphere model"),
    "airDensity_slug_ft3": ("density", "slug/ft^3", "atmosphere model"),
    "ambientPressure_lbf_ft2": ("pressure", "lbf/ft^2", "atmosphere model"),
    "ambientTemperature_dgR": ("temperature", "degR", "atmosphere model"),
    "aero_bodyForce_lbf_X": ("fx_aero", "lbf", "aerodynamic force, body x"),
    "aero_bodyForce_lbf_Y": ("fy_aero", "lbf", "aerodynamic force, body y"),
    "aero_bodyForce_lbf_Z": ("fz_aero", "lbf", "aerodynamic force, body z"),
    "aero_bodyMoment_ftlbf_L": ("l_aero", "ft*lbf", "aerodynamic moment, body x"),
    "aero_bodyMoment_ftlbf_M": ("m_aero", "ft*lbf", "aerodynamic moment, body y"),
    "aero_bodyMoment_ftlbf_N": ("n_aero", "ft*lbf", "aerodynamic moment, body z"),
    "mach": ("mach", "1", "Mach number"),
    "dynamicPressure_lbf_ft2": ("qbar", "lbf/ft^2", "dynamic pressure"),
    "trueAirspeed_nmi_h": ("tas", "kt", "true airspeed, nautical miles per hour"),
}
COLUMN_ORDER = list(COLUMNS)

# A difference below this is treated as numerical noise when flagging outliers (by column unit).
NOISE_FLOOR = [
    ("_ft_s2", 1e-6), ("_ft_s", 1e-5), ("_ft_min", 1e-3), ("_ft", 1e-3),
    ("_deg_s", 1e-7), ("_deg", 1e-7), ("_slug_ft3", 1e-9), ("_lbf_ft2", 1e-4),
    ("_dgR", 1e-4), ("_ftlbf", 1e-9), ("_lbf", 1e-6), ("_nmi_h", 1e-4), ("mach", 1e-7),
]
OUTLIER_K = 10.0

WGS84_J2 = {
    "shape": "WGS-84 ellipsoid",
    "equatorial_radius_m": "6378137.0",
    "flattening": "1 / 298.257223563",
    "rotating": True,
    "rotation_rate_deg_s": "0.004178073",
    "gravity": "J2 (gravitation only; simupy_flight.earth_J2_gravity)",
    "GM_ft3_s2": "14076443110000000",
    "J2": "0.00108262982",
    "source": "simupy_flight/__init__.py constants (earth_equitorial_radius, earth_f, earth_rotation_rate_deg, earth_spherical_gravity_constant = 14076443110000000 / (3.28084**3) m^3/s^2, earth_J2_constant)",
}
ROUND = {
    "shape": "sphere",
    "radius_ft": "20902255.199",
    "gravity": "inverse square 1/R^2, GM = 14076443110000000 ft^3/s^2 (simupy_flight.get_spherical_gravity(earth_spherical_gravity_constant))",
    "source": "nesc_caseNN.py: Planetodetic(a=20902255.199 / ft_per_m, omega_p=..., f=0.0)",
}
EARTH = {
    "wgs84_rotating_j2": WGS84_J2,
    "round_nonrotating": dict(ROUND, rotating=False, rotation_rate_deg_s="0.0"),
    "round_rotating": dict(ROUND, rotating=True, rotation_rate_deg_s="0.004178073"),
}

VEHICLES = {
    "sphere": {
        "what": "the NESC 'cannonball': 1 slug, 6 in diameter sphere (DAVE-ML cannonball_*.dml)",
        "dml": ["cannonball_inertia.dml", "cannonball_aero.dml"],
        "interpretation": "m = 1.0 slug; Ixx = Iyy = Izz = 3.6 slug*ft^2, products 0; CG at the reference point; "
                          "S = 0.1963495 ft^2; CD = 0.1 constant; CL = CY = Cl = Cm = Cn = 0",
    },
    "brick": {
        "what": "the NESC brick: US face brick 8 x 4 x 2.25 in, 5 lbm (DAVE-ML brick_*.dml)",
        "dml": ["brick_inertia.dml", "brick_aero.dml"],
        "interpretation": "m = 0.155404754 slug; Ixx = 0.00189422, Iyy = 0.006211019, Izz = 0.007194665 slug*ft^2, products 0; "
                          "S = 0.22222 ft^2, b = 0.33333 ft, cbar = 0.66667 ft; Cl = Clp*p*b/(2V) + Clr*r*b/(2V), "
                          "Cm = Cmq*q*cbar/(2V), Cn = Cnp*p*b/(2V) + Cnr*r*b/(2V) with Clp = Cmq = Cnr = -1.0 /rad, "
                          "Clr = Cnp = 0; the DAVE-ML gives CD = 0.01, but cases 2 and 3 set drag to zero",
    },
}

# Hand-written reading of each case (units: ft, deg, ft/s, deg/s, s). 'ic' is what the setup gives.
CASE_INFO = {
    1: dict(vehicle="sphere", earth="wgs84_rotating_j2",
            vehicle_note="CD set to 0 (no aerodynamic force); simupy builds no vehicle block for this case",
            atmosphere="US 1976 standard (irrelevant: no aero forces; simupy uses a zero-density constant atmosphere)",
            winds="still air",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[0.0, 0.0, 0.0], body_rates_frame="inertial (simupy sets the inertial rate state)")),
    2: dict(vehicle="brick", earth="wgs84_rotating_j2",
            vehicle_note="damping and drag coefficients set to 0 (simupy: get_constant_aero() all zero, S_A = 0.0)",
            atmosphere="US 1976 standard (irrelevant: no aero; simupy uses a zero-density constant atmosphere)",
            winds="still air",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[10.0, 20.0, 30.0], body_rates_frame="inertial ('The specification is for inertial angular rate, not relative')")),
    3: dict(vehicle="brick", earth="wgs84_rotating_j2",
            vehicle_note="rate damping Clp = Cmq = Cnr = -1.0 per rad; drag set to 0 (simupy: Cp_b = Cq_b = Cr_b = -1.0, CD 0, "
                         "S_A = 0.22222 ft^2, b_l = 1/3 ft, c_l = 2/3 ft; DAVE-ML: BSPAN 0.33333, CBAR 0.66667, CD 0.01)",
            atmosphere="US 1976 standard", winds="still air",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[10.0, 20.0, 30.0], body_rates_frame="inertial")),
    4: dict(vehicle="sphere", earth="round_nonrotating", vehicle_note="CD = 0.1",
            atmosphere="US 1976 standard", winds="still air",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[10.0, 20.0, 30.0], body_rates_frame="inertial (simupy setup; the CSVs start at 10/20/30 deg/s too)")),
    5: dict(vehicle="sphere", earth="round_rotating", vehicle_note="CD = 0.1",
            atmosphere="US 1976 standard", winds="still air",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[10.0, 20.0, 30.0], body_rates_frame="inertial (simupy setup; the CSVs start at 10/20/30 deg/s too)")),
    6: dict(vehicle="sphere", earth="wgs84_rotating_j2", vehicle_note="CD = 0.1",
            atmosphere="US 1976 standard", winds="still air",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[0.0, 0.0, 0.0], body_rates_frame="inertial")),
    7: dict(vehicle="sphere", earth="wgs84_rotating_j2", vehicle_note="CD = 0.1",
            atmosphere="US 1976 standard",
            winds="steady 20 ft/s from due west, i.e. wind velocity +20 ft/s East in NED (simupy: get_constant_winds(wy=20 / ft_per_m))",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[0.0, 0.0, 0.0], body_rates_frame="inertial")),
    8: dict(vehicle="sphere", earth="wgs84_rotating_j2", vehicle_note="CD = 0.1",
            atmosphere="US 1976 standard",
            winds="wind velocity East = 70 ft/s at 30000 ft, -20 ft/s at 0 ft, linear in (geodetic) altitude in between: "
                  "W_E(h) = 70 + (-20 - 70) * (h - 30000) / (0 - 30000) ft/s; W_N = W_D = 0",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=30000.0, v_ned_ft_s=[0.0, 0.0, 0.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                    body_rates_deg_s=[0.0, 0.0, 0.0], body_rates_frame="inertial")),
    9: dict(vehicle="sphere", earth="wgs84_rotating_j2", vehicle_note="CD = 0.1",
            atmosphere="US 1976 standard", winds="still air",
            ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=0.0, v_ned_ft_s=[0.0, 1000.0, -1000.0], euler_psi_theta_phi_deg=[90.0, 0.0, 0.0],
                    body_rates_deg_s=[0.0, -0.004178073, 0.0],
                    body_rates_frame="inertial; equals zero rate relative to the Earth (launch platform). The docstring's "
                                     "'sqrt{2000} ft/s' speed is a slip: the setup gives V_E = 1000, V_D = -1000 ft/s, |V| = 1000*sqrt(2)")),
    10: dict(vehicle="sphere", earth="wgs84_rotating_j2", vehicle_note="CD = 0.1",
             atmosphere="US 1976 standard", winds="still air",
             ic=dict(lat_deg=0.0, lon_deg=0.0, alt_ft=0.0, v_ned_ft_s=[1000.0, 0.0, -1000.0], euler_psi_theta_phi_deg=[0.0, 0.0, 0.0],
                     body_rates_deg_s=[0.0, 0.0, 0.0],
                     body_rates_frame="Earth-relative (p_B, q_B, r_B passed to ic_from_planetodetic), i.e. inertial "
                                      "[0.004178073, 0, 0] deg/s as the CSVs show; simupy then sets initial_condition[-2] = 0.0")),
}

# Hand-written findings (the numbers quoted are in this file's checkpoints/at_30s blocks).
NOTES = {
    1: ["SIM01's atmosphere is ~0.1 % denser at 15600 ft (pressure 1167.836 vs 1166.29 lbf/ft^2), so its dynamic pressure "
        "is 0.56 lbf/ft^2 high; SIM01 ends 0.0016 ft higher and 1.2e-4 ft/s slower than SIM03-06.",
        "SIM02's east velocity (2.1003 vs 2.1010 ft/s) and gravity (32.15075 vs 32.15078 ft/s^2) are slightly off."],
    2: ["SIM02's Euler angles drift away from the others (roll -59.857 vs -56.151 deg, pitch -3.506 vs -3.820 deg at 30 s) "
        "while its body rates agree to ~1e-3 deg/s; SIM06 differs from SIM01/04/05 by ~1e-3 deg (angles) and ~3e-3 deg/s (rates).",
        "Translation is the same as case 1 (the brick has no aerodynamic force)."],
    3: ["At 30 s the damped rates split: SIM01/SIM02/SIM04 are ~0 inertially (|w| <= 2e-5 deg/s) while SIM05/SIM06 keep "
        "|w| = 0.00418 deg/s, the Earth's rotation rate (0.004178073 deg/s): their damping acts on rates relative to the "
        "rotating Earth/air mass, the others' on inertial rates (inferred from the numbers; the DAVE-ML input "
        "'bodyAngularRate_Roll' does not say relative to what). SIM05/SIM06 also report non-zero L and M moments.",
        "Euler angles at 30 s spread 0.31 deg (yaw, SIM01 lowest) and 0.65 deg (pitch, SIM02 lowest)."],
    4: ["SIM02 falls ~18 ft less than the others (altitude 16249.4161 vs 16231.31 ft at 30 s; down velocity 866.04 vs "
        "867.10 ft/s), starts with feVelocity_ft_s_X = 0.01 ft/s, reports localGravity_ft_s2 = 0.0, a latitude of 7.83E-7 deg, "
        "Euler angles 0.8-4.3 deg away from the others and a different aero force split. Only 4 tools ran this case."],
    5: ["Same SIM02 behaviour as in case 4 (altitude 16294.5521 vs 16276.39 ft at 30 s, 18.2 ft high)."],
    6: ["SIM03 falls ~0.6 ft further than SIM04/05/06 (down velocity 864.11 vs 864.01 ft/s at 30 s); its body-y aero force "
        "is 0.0235 lbf vs 5.8E-4 lbf (about the drag times sin of the 0.125 deg roll, as if the Earth-relative east "
        "velocity were ignored; inferred).",
        "SIM01 is 0.28 ft higher than SIM04/05/06 at 30 s (its atmosphere is slightly denser, Mach 5.7e-5 low).",
        "SIM06's ECI X position is 0.010 ft from SIM04/05 (also in cases 5 and 8)."],
    7: ["All tools that report air data include the wind after t = 0: TAS, Mach*a and sqrt(2*qbar/rho) match "
        "|V_NED - W| with W_E = +20 ft/s. At t = 0 SIM06 prints trueAirspeed, mach and dynamicPressure = 0.0 (the others "
        "print the 20 ft/s wind, e.g. mach 0.0201).",
        "SIM03 as in case 6 (0.6 ft low, body-y force 0.2315 vs 0.2091 lbf)."],
    8: ["As in case 7 (SIM06 air data 0.0 at t = 0 with a 70 ft/s wind); in addition SIM03's aero force is 0.0 at t = 0."],
    9: ["Altitude at 30 s spreads 4.3 ft (SIM01/SIM03 ~10156.8, SIM02 10159.5, SIM06 10160.66, SIM04/SIM05 10160.98-10160.99); "
        "no single outlier by the rule. SIM06's ECI position is 0.32 ft from SIM04/SIM05 (and its ECEF X too).",
        "SIM02's inertial pitch rate is -0.0041768623 deg/s vs -0.004178074 for the others (a different Earth rate?)."],
    10: ["SIM02's latitude at 30 s (0.061715205 deg) is (1 - e^2) times the others' 0.06213 deg: it looks geocentric.",
         "Pitch at 30 s splits: SIM04/SIM05 print theta equal to their geodetic latitude (0.0621356 deg), "
         "SIM01/SIM02/SIM06 print ~0.06171-0.06173 deg (about (1 - e^2) x latitude). For a body fixed relative to the Earth "
         "(as here) theta should equal the geodetic latitude change, which supports SIM04/SIM05 (our reading, not the report's).",
         "Altitude spreads 4.3 ft and SIM06's ECI position is 0.33 ft off, as in case 9."],
}
COMMON_NOTES = [
    "Columns differ by tool: SIM03 gives no Euler angles, body rates, Mach, dynamic pressure or airspeed; SIM02 no ECEF/ECI "
    "position or dynamic pressure; SIM04 no airspeed or altitude rate; only SIM04/05/06 give ECI position and velocity; "
    "only SIM01/03/05/06 give ECEF position. SIM03 is absent from cases 2-5, SIM01 and SIM03 from cases 4-5.",
    "SIM03's atmosphere columns (speedOfSound, airDensity, ambientPressure, ambientTemperature) on its last row (t = 30.0) "
    "repeat the t = 29.9 row in every case: its t = 30 atmosphere 'outliers' are this stale row, not a different model.",
    "SIM05 writes its air data (mach, dynamicPressure_lbf_ft2, trueAirspeed_nmi_h) in single precision "
    "(e.g. 0.8212794065475464, 535.5581665039062): ~1e-7 relative. SIM05 repeats the column feVelocity_ft_s_Z at the end "
    "of its files (identical values; dropped here).",
    "SIM06's trueAirspeed_nmi_h is 1.2e-5 (relative) below its own Mach * speed of sound in every case: a different "
    "knot conversion, not a different airspeed.",
    "SIM02 prints ~10 significant digits or fewer (e.g. longitude 5.74E-5); small differences of SIM02 are often print rounding.",
    "SIM02's aero force magnitudes are ~0.08 % below what its own density, airspeed, S = 0.1963495 ft^2 and CD = 0.1 give.",
    "SIM06's time stamps drift (30.00000000001368 for 30): the nearest row is used.",
    "The outlier rule is mechanical and flags sub-ppm differences where the other tools agree to many digits; the notes "
    "say which differences matter.",
]


def die(msg):
    sys.exit("extract.py: " + msg)


def git_blob_sha1(data):
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def noise_floor(col):
    base = re.sub(r"_(X|Y|Z|Roll|Pitch|Yaw|L|M|N)$", "", col)
    for suffix, floor in NOISE_FLOOR:
        if base.endswith(suffix):
            return floor
    die("no noise floor for column " + col)


def median(xs):
    s = sorted(xs)
    n = len(s)
    return s[n // 2] if n % 2 else (s[n // 2 - 1] + s[n // 2]) / 2


def read_csv(path):
    data = open(path, "rb").read()
    rows = list(csv.reader(io.StringIO(data.decode("ascii"), newline="")))
    header, body = rows[0], rows[1:]
    if any(len(r) != len(header) for r in body):
        die(path + ": ragged rows")
    return data, header, body


def extract_tool(repo, rel):
    data, header, body = read_csv(os.path.join(repo, rel))
    # Drop repeated columns (SIM05 repeats feVelocity_ft_s_Z at the end) after checking they are identical.
    keep, seen, dropped = [], {}, []
    for i, col in enumerate(header):
        if col in seen:
            j = seen[col]
            if any(r[i] != r[j] for r in body):
                die(rel + ": repeated column %s differs" % col)
            dropped.append(col)
            continue
        if col not in COLUMNS:
            die(rel + ": unknown column " + col)
        seen[col] = i
        keep.append(col)
    times = [float(r[0]) for r in body]
    picks = []
    for T in CHECKPOINTS:
        k = min(range(len(body)), key=lambda i: (abs(times[i] - T), i))
        if abs(times[k] - T) > 1e-6:
            die(rel + ": no row near t = %g" % T)
        picks.append(k)
    info = {
        "path": rel,
        "git_blob_sha1": git_blob_sha1(data),  # as `git ls-tree` lists it at the source commit
        "data_rows": len(body),
        "first_times": [body[0][0], body[1][0]],
        "last_time": body[-1][0],
        "checkpoint_rows": [k + 2 for k in picks],  # 1-based line numbers in the file (line 1 = header)
    }
    if dropped:
        info["repeated_columns_dropped"] = dropped
    values = {col: [body[k][seen[col]] for k in picks] for col in keep}
    return info, values


def stats_at_30(case_values, tools):
    out = {}
    for col in COLUMN_ORDER:
        if col == "time" or col not in case_values:
            continue
        have = [t for t in tools if t in case_values[col]]
        strs = {t: case_values[col][t][-1] for t in have}
        x = {t: float(s) for t, s in strs.items()}
        wrapped = False
        if col in ("eulerAngle_deg_Yaw", "eulerAngle_deg_Roll"):
            ref = x[have[0]]
            for t in have:
                if abs(x[t] - ref) > 180.0:
                    wrapped = True
                    x[t] = ref + (x[t] - ref + 180.0) % 360.0 - 180.0
        vals = [x[t] for t in have]
        entry = {"n": len(have), "median": median(vals), "spread": max(vals) - min(vals)}
        if wrapped:
            entry["angles_unwrapped"] = True
        if len(have) >= 3:
            med = entry["median"]
            mad = median([abs(v - med) for v in vals])
            thresh = max(OUTLIER_K * mad, noise_floor(col))
            flagged = [t for t in have if abs(x[t] - med) > thresh]
            rest = [t for t in have if t not in flagged]
            if flagged and rest:
                rmed = median([x[t] for t in rest])
                rspread = max(x[t] for t in rest) - min(x[t] for t in rest)
                entry["outliers"] = [[t, strs[t], x[t] - rmed, rspread] for t in flagged]
        out[col] = entry
    return out


def docstring_table(text):
    m = re.search(r'^"""(.*?)"""', text, re.S | re.M)
    lines = m.group(1).strip("\n").splitlines()
    title = lines[1].strip()
    table, key = {}, None
    for ln in lines[3:]:
        if not ln.strip() or ln.startswith("==="):
            continue
        if ln[:16].strip():
            key = ln[:16].strip()
            table[key] = ln[16:].strip()
        elif key:
            table[key] += " " + ln.strip()
    return title, table


SETUP_LINE = re.compile(
    r"^\s*(?:(?:lat_ic|long_ic|h_ic|V_[NED]_ic|psi_ic|theta_ic|phi_ic|omega_[XYZ]_ic|[pqr]_b_ic|"
    r"Ixx|Iyy|Izz|Ixy|Iyz|Izx|m|S_A|a_l|b_l|c_l|wy_1|x_1|wy_2|x_2|aero_model)\s*=.*|"
    r"(?:gravity|winds|atmosphere|a|omega_p|f|base_aero_coeffs|S_A|a_l|b_l|c_l|d_l)=.*|"
    r"winds_out\[1\].*|planet\.initial_condition\[.*|.*BD\.simulate\(.*|# The specification.*)$")


def setup_lines(text):
    body = text.split('"""', 2)[2]
    return [ln.strip() for ln in body.splitlines() if SETUP_LINE.match(ln)]


def dml_values(path):
    root = ET.parse(path).getroot()
    ns = {"d": "http://daveml.org/2010/DAVEML"}
    out = []
    for v in root.findall("d:variableDef", ns):
        if "initialValue" in v.attrib:
            out.append({"varID": v.attrib["varID"], "name": v.attrib["name"], "units": v.attrib.get("units", ""),
                        "initialValue": v.attrib["initialValue"]})
    return out


def dumps(obj, indent=0):
    """JSON with one item per line down to lists/small objects, which stay on one line."""
    flat = json.dumps(obj, ensure_ascii=False)
    if not isinstance(obj, (dict, list)) or len(flat) + indent <= 110 or (
            isinstance(obj, list) and all(not isinstance(v, (dict, list)) for v in obj)):
        return flat
    pad = " " * (indent + 1)
    if isinstance(obj, list):
        return "[\n" + ",\n".join(pad + dumps(v, indent + 1) for v in obj) + "\n" + " " * indent + "]"
    return "{\n" + ",\n".join(pad + json.dumps(k) + ": " + dumps(v, indent + 1) for k, v in obj.items()) + "\n" + " " * indent + "}"


def build(repo):
    read = []
    cases = []
    for n in CASES:
        nn = "%02d" % n
        py_rel = "nesc_test_cases/nesc_case%s.py" % nn
        py = open(os.path.join(repo, py_rel), encoding="utf-8").read()
        read.append(py_rel)
        title, table = docstring_table(py)
        files = sorted(glob.glob(os.path.join(repo, ATMOS, "Atmos_%s_*" % nn, "Atmos_%s_sim_*.csv" % nn)))
        if not files:
            die("no CSV for case %d" % n)
        folder = os.path.basename(os.path.dirname(files[0]))
        tools, values = {}, {}
        for f in files:
            rel = os.path.relpath(f, repo).replace(os.sep, "/")
            read.append(rel)
            tool = "SIM" + re.search(r"_sim_(\d+)\.csv$", rel).group(1)
            info, vals = extract_tool(repo, rel)
            tools[tool] = info
            for col, v in vals.items():
                values.setdefault(col, {})[tool] = v
        names = list(tools)
        values = {c: values[c] for c in COLUMN_ORDER if c in values}
        ci = CASE_INFO[n]
        cases.append({
            "number": n,
            "folder": ATMOS + "/" + folder,
            "title": title,
            "simupy_table": table,
            "vehicle": ci["vehicle"],
            "vehicle_note": ci["vehicle_note"],
            "earth": ci["earth"],
            "atmosphere": ci["atmosphere"],
            "winds": ci["winds"],
            "initial_conditions": ci["ic"],
            "duration_s": 30,
            "output_step_s": {t: ("0.01" if tools[t]["data_rows"] == 3001 else "0.1") for t in names},
            "simupy_setup_lines": setup_lines(py),
            "tools": names,
            "files": tools,
            "checkpoints": values,
            "at_30s": stats_at_30(values, names),
            "notes": NOTES.get(n, []),
        })
    dml = {}
    for name in DML_FILES:
        rel = MODELS + "/" + name
        read.append(rel)
        dml[name] = dml_values(os.path.join(repo, rel))
    read += ["simupy_flight/__init__.py", "nesc_test_cases/nesc_testcase_helper.py", "NESC_data/README.rst"]
    init = open(os.path.join(repo, "simupy_flight/__init__.py"), encoding="utf-8").read()
    helper = open(os.path.join(repo, "nesc_test_cases/nesc_testcase_helper.py"), encoding="utf-8").read()
    constants = [ln for ln in init.splitlines() if re.match(r"^earth_\w+ = ", ln)]
    constants += [ln for ln in helper.splitlines() if re.match(r"^(ft_per_m|kg_per_slug|N_per_lbf) = ", ln)]
    return {
        "about": "Subset of the NESC atmospheric check cases 1-10 (NASA/TM-2015-218675) as published in nasa/simupy-flight; "
                 "see README.md. Trajectory values are the CSV strings verbatim.",
        "source": {
            "repository": "https://github.com/nasa/simupy-flight",
            "commit": SOURCE_COMMIT,
            "report": "E. B. Jackson et al., Check-cases for Verification of 6-Degree-of-Freedom Flight Vehicle "
                      "Simulations, NASA/TM-2015-218675, Vol. I and II, 2015",
            "files_read": read,
        },
        "number_format": "checkpoint values: JSON strings, byte-identical to the CSV fields; at_30s median, spread and the two numbers of each outlier: "
                         "JSON numbers computed from float() of those strings",
        "checkpoint_times_s": CHECKPOINTS,
        "checkpoint_rule": "per file, the row whose time is nearest each checkpoint (all within 1.4e-11 s); "
                           "files[tool].checkpoint_rows gives the line numbers",
        "at_30s_format": "per column: n (tools reporting it), median, spread (max - min), and outliers as "
                         "[tool, its value (CSV string), its value minus the median of the unflagged tools, "
                         "spread (max - min) of the unflagged tools]",
        "outlier_rule": "at t = 30 s, with n >= 3 tools: flag a tool when |value - median| > max(%g * MAD, noise floor of "
                        "the column's unit); MAD = median absolute deviation from the median. Euler yaw/roll are "
                        "unwrapped to within 180 deg of the first tool before statistics." % OUTLIER_K,
        "noise_floors": dict(NOISE_FLOOR),
        "columns": {c: {"name": v[0], "unit": v[1], "meaning": v[2]} for c, v in COLUMNS.items()},
        "simupy_constants_lines": constants,
        "earth_models": EARTH,
        "vehicles": VEHICLES,
        "dml_initial_values": dml,
        "common_notes": COMMON_NOTES,
        "cases": cases,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("repo", help="checkout of github.com/nasa/simupy-flight (commit %s)" % SOURCE_COMMIT)
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "cases.json"))
    ap.add_argument("--check", action="store_true", help="compare with --out instead of writing it")
    a = ap.parse_args()
    text = dumps(build(a.repo)) + "\n"
    if a.check:
        old = open(a.out, encoding="utf-8").read()
        if old != text:
            die("%s differs from what the source gives" % a.out)
        print("identical:", a.out)
    else:
        with open(a.out, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
        print("wrote", a.out, len(text.encode()), "bytes")


if __name__ == "__main__":
    main()
