//! Which states are set aside: those that may grow along a steady motion without any other
//! state depending on them.
//!
//! The rule works on the dependency graph of the rates (row i depends on state j where ∂fᵢ/∂xⱼ
//! is not identically zero: the emitted pattern, plus what the loads add) and its strongly
//! connected components. A component that no other remaining state depends on (a *source*)
//! is set aside, while something else remains, when
//! - it is one state whose rate reads others but not itself: a position or a heading, which
//!   only integrates the rest (X, Y and ψ of a planar body, x, y, z of a spatial one, the
//!   heading ψ of a top under a vertical weight), or
//! - one of its states grows at the point (its rate is not zero): the attitude of a body
//!   spinning about an axis, whose angles turn steadily.
//!
//! This repeats until nothing changes. What remains depends only on itself, so its A is the
//! whole linear model of the motion; a component that is the whole of what remains is kept
//! even if it grows (a pendulum away from its equilibrium), which the caller reports as a
//! point that is not an equilibrium.

use super::{EQUILIBRIUM_TOLERANCE, rate_scale};

/// The indices set aside, ascending, given `depends[i][j]` (row i reads state j), the rates
/// at the point, the point itself and which entries are coordinates (positions, angles, a
/// quaternion's parts) rather than velocities: only coordinates are set aside for growing,
/// because a velocity that changes is a point that is not steady, which the caller reports.
///
/// ```
/// use eom::linear::set_aside;
/// // ẋ = v, v̇ = 0: the position integrates the velocity and is set aside.
/// let depends = vec![vec![false, true], vec![false, false]];
/// assert_eq!(set_aside(&depends, &[1.0, 0.0], &[0.0, 1.0], &[true, false]), vec![0]);
/// ```
pub fn set_aside(
    depends: &[Vec<bool>],
    rates: &[f64],
    state: &[f64],
    coordinate: &[bool],
) -> Vec<usize> {
    set_aside_why(depends, rates, state, coordinate)
        .into_iter()
        .map(|(i, _)| i)
        .collect()
}

/// Why a state entry was set aside.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SetAsideReason {
    /// Its rate reads other states but not itself, and nothing left reads it: a position or a
    /// heading, which only integrates the rest.
    Integrates,
    /// It is a coordinate that grows at the point (its rate is not zero), with the states it
    /// reads among themselves, and nothing left reads them: the attitude of a spinning body.
    Grows,
}

impl SetAsideReason {
    /// The reason in words, as the outputs give it.
    pub fn describe(self) -> &'static str {
        match self {
            SetAsideReason::Integrates => "only integrates the rest",
            SetAsideReason::Grows => "grows at the point",
        }
    }
}

/// [`set_aside`] with the reason for each index, ascending.
///
/// ```
/// use eom::linear::{SetAsideReason, set_aside_why};
/// // ẋ = v, v̇ = 0: the position integrates the velocity.
/// let depends = vec![vec![false, true], vec![false, false]];
/// assert_eq!(
///     set_aside_why(&depends, &[1.0, 0.0], &[0.0, 1.0], &[true, false]),
///     vec![(0, SetAsideReason::Integrates)]
/// );
/// ```
pub fn set_aside_why(
    depends: &[Vec<bool>],
    rates: &[f64],
    state: &[f64],
    coordinate: &[bool],
) -> Vec<(usize, SetAsideReason)> {
    let n = depends.len();
    let tolerance = EQUILIBRIUM_TOLERANCE * rate_scale(state);
    let mut remaining = vec![true; n];
    let mut why = vec![None; n];
    let growing: Vec<bool> = (0..n)
        .map(|i| coordinate[i] && rates[i].abs() > tolerance)
        .collect();
    while let Some((component, reason)) =
        next_to_set_aside(depends, &growing, coordinate, &remaining)
    {
        for i in component {
            remaining[i] = false;
            why[i] = Some(reason);
        }
    }
    (why.into_iter().enumerate())
        .filter_map(|(i, reason)| Some((i, reason?)))
        .collect()
}

fn next_to_set_aside(
    depends: &[Vec<bool>],
    growing: &[bool],
    coordinate: &[bool],
    remaining: &[bool],
) -> Option<(Vec<usize>, SetAsideReason)> {
    let reach = reachability(depends, remaining);
    let alive: Vec<usize> = (0..depends.len()).filter(|&i| remaining[i]).collect();
    for &i in &alive {
        let component: Vec<usize> = alive
            .iter()
            .copied()
            .filter(|&j| j == i || (reach[i][j] && reach[j][i]))
            .collect();
        let read_from_outside = alive
            .iter()
            .filter(|k| !component.contains(k))
            .any(|&k| component.iter().any(|&c| depends[k][c]));
        if read_from_outside || component.len() == alive.len() {
            continue;
        }
        let integrates_others = component.len() == 1
            && !depends[i][i]
            && alive.iter().any(|&j| j != i && depends[i][j]);
        let grows =
            component.iter().all(|&c| coordinate[c]) && component.iter().any(|&c| growing[c]);
        if integrates_others {
            return Some((component, SetAsideReason::Integrates));
        }
        if grows {
            return Some((component, SetAsideReason::Grows));
        }
    }
    None
}

/// `reach[i][j]`: the rate of i depends, through the remaining states, on state j.
fn reachability(depends: &[Vec<bool>], remaining: &[bool]) -> Vec<Vec<bool>> {
    let n = depends.len();
    let mut reach: Vec<Vec<bool>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| remaining[i] && remaining[j] && depends[i][j])
                .collect()
        })
        .collect();
    // Warshall: after step k, reach[i][j] holds for paths through the first k states.
    for k in 0..n {
        let through = reach[k].clone();
        for row in reach.iter_mut().filter(|row| row[k]) {
            for (reached, via) in row.iter_mut().zip(&through) {
                *reached |= *via;
            }
        }
    }
    reach
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `depends` from a list of (row, column).
    fn graph(n: usize, edges: &[(usize, usize)]) -> Vec<Vec<bool>> {
        let mut depends = vec![vec![false; n]; n];
        for &(i, j) in edges {
            depends[i][j] = true;
        }
        depends
    }

    #[test]
    fn a_pendulum_away_from_equilibrium_keeps_both_states() {
        let depends = graph(2, &[(0, 1), (1, 0)]);
        let coordinate = [true, false];
        assert!(set_aside(&depends, &[0.0, -3.0], &[0.5, 0.0], &coordinate).is_empty());
    }

    #[test]
    fn a_planar_body_sets_aside_its_track_and_heading() {
        // u, v, r, X, Y, ψ with u̇ = vr, v̇ = −ur, ṙ = 0, the track reads u, v, ψ, ψ̇ = r.
        let depends = graph(
            6,
            &[
                (0, 1),
                (0, 2),
                (1, 0),
                (1, 2),
                (3, 0),
                (3, 1),
                (3, 5),
                (4, 0),
                (4, 1),
                (4, 5),
                (5, 2),
            ],
        );
        let coordinate = [false, false, false, true, true, true];
        let state = [2.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let at_speed = [0.0, 0.0, 0.0, 2.0, 0.0, 0.0];
        assert_eq!(
            set_aside(&depends, &at_speed, &state, &coordinate),
            vec![3, 4, 5]
        );
        // The track and the heading each only integrate the rest, though X grows at speed.
        let integrates = SetAsideReason::Integrates;
        assert_eq!(
            set_aside_why(&depends, &at_speed, &state, &coordinate),
            vec![(3, integrates), (4, integrates), (5, integrates)]
        );
        // Slowing down, the velocities are kept: the point is not steady, which is reported.
        let slowing = [-0.2, 0.0, 0.0, 2.0, 0.0, 0.0];
        assert_eq!(
            set_aside(&depends, &slowing, &state, &coordinate),
            vec![3, 4, 5]
        );
    }

    #[test]
    fn a_growing_attitude_is_set_aside_with_what_only_it_feeds() {
        // ω (0) feeds the angle pair (1, 2), which reads itself; the pair grows.
        let depends = graph(3, &[(1, 0), (1, 2), (2, 1), (2, 0)]);
        let coordinate = [false, true, true];
        let state = [5.0, 0.0, 0.0];
        assert_eq!(
            set_aside(&depends, &[0.0, 5.0, 0.0], &state, &coordinate),
            vec![1, 2]
        );
        assert_eq!(
            set_aside_why(&depends, &[0.0, 5.0, 0.0], &state, &coordinate),
            vec![(1, SetAsideReason::Grows), (2, SetAsideReason::Grows)]
        );
        // Not growing, the pair is kept.
        assert!(set_aside(&depends, &[0.0; 3], &state, &coordinate).is_empty());
    }
}
