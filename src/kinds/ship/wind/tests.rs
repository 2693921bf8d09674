use super::*;
use std::f64::consts::PI;

/// A merchant ship's above-water geometry, the example Fossen's MSS gives Isherwood's
/// regression (L_oa 100 m, B 30 m, A_L 900 m², A_F 300 m²).
fn example() -> Isherwood {
    Isherwood {
        length_overall: 100.0,
        beam: 30.0,
        lateral_area: 900.0,
        frontal_area: 300.0,
        superstructure_area: 100.0,
        perimeter: 100.0,
        centroid_from_bow: 50.0,
        masts: 2.0,
    }
}

fn ship_in(speed: f64, from_deg: f64, current: [f64; 2]) -> ShipWind {
    let geometry = example();
    ShipWind {
        windage: Windage {
            coefficients: geometry.coefficients().unwrap(),
            frontal_area: geometry.frontal_area,
            lateral_area: geometry.lateral_area,
            length_overall: geometry.length_overall,
            air_density: 1.225,
            isherwood: Some(geometry),
        },
        wind: Wind {
            speed,
            from: from_deg.to_radians(),
            gust: None,
        },
        current,
    }
}

/// Isherwood's C_X at 0° by hand from the file's first row: −(2.152 − 5.00·2A_L/L² +
/// 0.243·2A_F/B² − 0.164·L/B), the other ratios' coefficients zero at 0°.
#[test]
fn isherwood_at_a_head_wind_is_the_regression_by_hand() {
    let table = example().coefficients().unwrap();
    let by_hand =
        -(2.152 - 5.00 * 2.0 * 900.0 / 1e4 + 0.243 * 2.0 * 300.0 / 900.0 - 0.164 * 100.0 / 30.0);
    let [(x, _), (y, _), (n, _)] = table.at(0.0);
    assert!((x - by_hand).abs() < 1e-15, "{x} {by_hand}");
    assert_eq!((y, n), (0.0, 0.0));
}

/// A ship at rest: a head wind pushes it astern and nothing else; a wind from port pushes it
/// to starboard, one from starboard to port, mirrored exactly.
#[test]
fn the_wind_pushes_a_ship_at_rest_downwind() {
    let head = ship_in(20.0, 0.0, [0.0; 2]).loads([0.0, 0.0, 0.0], 0.0);
    assert!(head.loads[0] < 0.0, "{:?}", head.loads);
    assert_eq!([head.loads[1], head.loads[2]], [0.0, 0.0]);
    assert_eq!(head.relative_angle, 0.0);
    assert!((head.relative_speed - 20.0).abs() < 1e-14);
    // Heading north, a wind from the west (270°) comes from port.
    let from_port = ship_in(20.0, 270.0, [0.0; 2]).loads([0.0, 0.0, 0.0], 0.0);
    let from_starboard = ship_in(20.0, 90.0, [0.0; 2]).loads([0.0, 0.0, 0.0], 0.0);
    assert!(from_port.loads[1] > 0.0, "{:?}", from_port.loads);
    assert!(from_starboard.loads[1] < 0.0, "{:?}", from_starboard.loads);
    for k in 0..3 {
        let sign = if k == 0 { 1.0 } else { -1.0 };
        let mirrored = sign * from_starboard.loads[k];
        assert!(
            (from_port.loads[k] - mirrored).abs() <= 1e-9 * from_port.loads[k].abs().max(1.0),
            "{k}: {} {}",
            from_port.loads[k],
            mirrored
        );
    }
}

/// Moving ahead at 8 m/s in an 8 m/s following wind the ship feels no air; in still air it
/// feels a head wind of its own speed; a current that carries it with the wind's velocity
/// leaves it in still air too.
#[test]
fn the_loads_are_on_the_air_relative_to_the_ship() {
    let following = ship_in(8.0, 180.0, [0.0; 2]).loads([8.0, 0.0, 0.0], 0.0);
    // sin 180° is 1.2e-16, not 0: the air left is of that order, its loads of its square.
    assert!(following.relative_speed < 1e-14, "{following:?}");
    assert!(
        following.loads.iter().all(|l| l.abs() < 1e-20),
        "{following:?}"
    );
    assert!(following.by.iter().flatten().all(|d| d.is_finite()));
    let still = ship_in(0.0, 0.0, [0.0; 2]).loads([8.0, 0.0, 0.0], 0.0);
    let head = ship_in(8.0, 0.0, [0.0; 2]).loads([0.0, 0.0, 0.0], 0.0);
    assert_eq!(still.loads, head.loads);
    // Drifting east at 3 m/s with the current, in a 3 m/s wind from the west.
    let carried = ship_in(3.0, 270.0, [0.0, 3.0]).loads([0.0, 0.0, 0.7], 0.0);
    assert!(carried.relative_speed < 1e-14, "{carried:?}");
}

/// The derivatives by (u, v, ψ, g) are the loads' central differences, to 1e-6 of the loads'
/// scale (the differences' own error at a step of 1e-5 is far below), at states whose angles
/// are not on the table's breakpoints, with a current.
#[test]
fn the_derivatives_are_the_loads_slopes() {
    let wind = ship_in(15.0, 40.0, [0.3, -0.4]);
    let states = [
        [7.0, 0.3, 0.2, 0.0],
        [5.0, -1.0, 2.0, 1.5],
        [-1.0, 2.0, 4.0, -2.0],
        [3.0, 0.0, -2.5, 0.5],
    ];
    for [u, v, psi, gust] in states {
        let at = wind.loads([u, v, psi], gust);
        let scale = at.loads.iter().fold(1.0f64, |m, l| m.max(l.abs()));
        for variable in 0..4 {
            let h = 1e-5;
            let shifted = |step: f64| {
                let mut x = [u, v, psi, gust];
                x[variable] += step;
                wind.loads([x[0], x[1], x[2]], x[3]).loads
            };
            let (up, down) = (shifted(h), shifted(-h));
            for k in 0..3 {
                let difference = (up[k] - down[k]) / (2.0 * h);
                let error = (difference - at.by[k][variable]).abs();
                assert!(
                    error < 1e-6 * scale,
                    "load {k} by {variable} at {:?}: {} against {difference}",
                    [u, v, psi, gust],
                    at.by[k][variable]
                );
            }
        }
    }
}

/// A table that would have the loads jump as the wind crosses the bow, or that is not a table,
/// is refused naming the key.
#[test]
fn bad_tables_are_refused_by_key() {
    let angles = [0.0, 90.0, 180.0];
    let ok = || {
        [
            vec![-0.5, 0.0, 0.4],
            vec![0.0, 0.8, 0.0],
            vec![0.0, 0.1, 0.0],
        ]
    };
    assert!(WindCoefficients::new(&angles, ok()).is_ok());
    let key = |e: WindTableError| match e {
        WindTableError::Invalid { key, .. } => key,
    };
    let mut jumping = ok();
    jumping[1][0] = 0.2;
    assert_eq!(
        key(WindCoefficients::new(&angles, jumping).unwrap_err()),
        "windage.C_Y"
    );
    let mut short = ok();
    short[2].pop();
    assert_eq!(
        key(WindCoefficients::new(&angles, short).unwrap_err()),
        "windage.C_N"
    );
    let mut nan = ok();
    nan[0][1] = f64::NAN;
    assert_eq!(
        key(WindCoefficients::new(&angles, nan).unwrap_err()),
        "windage.C_X"
    );
    for bad in [[0.0, 90.0, 170.0], [10.0, 90.0, 180.0], [0.0, 0.0, 180.0]] {
        let error = WindCoefficients::new(&bad, ok()).unwrap_err();
        assert_eq!(key(error), "windage.angles_deg", "{bad:?}");
    }
    let negative = Isherwood {
        beam: -3.0,
        ..example()
    };
    assert_eq!(key(negative.coefficients().unwrap_err()), "windage.beam_m");
}

/// The table's two sides meet at the bow and the stern: C at ±γ mirrored, and continuous
/// through 0 and ±π.
#[test]
fn the_coefficients_are_mirrored_across_the_bow() {
    let table = example().coefficients().unwrap();
    for angle in [0.1, 0.7, 1.6, 2.9] {
        let (plus, minus) = (table.at(angle), table.at(-angle));
        assert_eq!(plus[0].0, minus[0].0);
        assert_eq!(plus[1].0, -minus[1].0);
        assert_eq!(plus[2].0, -minus[2].0);
    }
    for end in [0.0, PI] {
        let (a, b) = (table.at(end + 1e-12), table.at(-(end + 1e-12)));
        assert!((a[1].0 - b[1].0).abs() < 1e-9 && (a[2].0 - b[2].0).abs() < 1e-9);
    }
}

/// NORSOK's whole variance is B(1/n, 2/(3n))/n times S(0)/(172 …): at U₀ = 20 m/s, z = 10 m,
/// 7.099163464875378 m²/s² by Python's math.gamma, Γ(1/n)Γ(2/(3n))/Γ(5/(3n)); and at 10 m/s,
/// 30 m, 0.8317607381748576. The quadrature's error is below 1e-6 of it.
#[test]
fn the_spectrum_s_variance_is_its_closed_form() {
    for (speed, height, closed) in [
        (20.0, 10.0, 7.099163464875378),
        (10.0, 30.0, 0.8317607381748576),
    ] {
        let spectrum = Spectrum::named("norsok", speed, height).unwrap();
        let variance = spectrum.variance();
        assert!(
            ((variance - closed) / closed).abs() < 1e-6,
            "{variance} {closed}"
        );
    }
}

/// A seed gives one series, another seed another; the series' variance over a long record is
/// the sum of its harmonics' (the spectrum's below 0.5 Hz, 86 % of the whole at 20 m/s), to
/// 2 % over 20 000 s (the cross terms of harmonics 0.002 Hz apart average out over it).
#[test]
fn a_seed_draws_one_series_with_the_spectrum_s_variance() {
    let spectrum = Spectrum::named("norsok", 20.0, 10.0).unwrap();
    let (a, b, c) = (
        Gust::new(spectrum, 7),
        Gust::new(spectrum, 7),
        Gust::new(spectrum, 8),
    );
    assert_eq!(a, b);
    assert_ne!(a.at(100.0), c.at(100.0));
    let below = a.variance() / spectrum.variance();
    assert!((0.85..0.87).contains(&below), "{below}");
    let samples: Vec<f64> = (0..40_000).map(|k| a.at(0.5 * k as f64)).collect();
    let mean = samples.iter().sum::<f64>() / samples.len() as f64;
    let variance = samples.iter().map(|g| (g - mean).powi(2)).sum::<f64>() / samples.len() as f64;
    assert!(
        ((variance - a.variance()) / a.variance()).abs() < 0.02,
        "{variance} {}",
        a.variance()
    );
    let refused = |name, speed, height| Spectrum::named(name, speed, height).unwrap_err();
    assert!(matches!(
        refused("harris", 20.0, 10.0),
        GustError::Invalid {
            key: "environment.wind_spectrum",
            ..
        }
    ));
    assert!(matches!(
        refused("norsok", 0.0, 10.0),
        GustError::Invalid {
            key: "environment.wind_m_s",
            ..
        }
    ));
    assert!(matches!(
        refused("norsok", 20.0, f64::NAN),
        GustError::Invalid {
            key: "environment.wind_height_m",
            ..
        }
    ));
}
