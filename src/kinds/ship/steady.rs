//! The steady turns: at a fixed rudder angle δ, the states (u, v, r) of the ship whose rates
//! vanish, the heading and the position set aside (they only integrate the rest). They make a
//! curve in (u, v, r, δ), the r–δ curve that the spiral tests ([`super::spiral`]) measure
//! point by point with a procedure and a settling criterion; here it is traced directly, free
//! of both.
//!
//! Where the curve turns back in δ (a **fold**) two steady turns meet and vanish: between two
//! folds a course-unstable ship has three steady turns at each δ, the middle one unstable, and
//! the folds are the true ends of the loop the spiral tests look for. A course-stable ship's
//! curve has no fold: one steady turn at each δ.
//!
//! **The method: pseudo-arclength continuation.** In scaled variables x = (u/U₀, v/U₀,
//! r L/U₀, δ) and with the rates scaled alike, F(x) = (u̇ L/U₀², v̇ L/U₀², ṙ L²/U₀²) = 0 is
//! three equations in four unknowns, the propeller (if any) at its approach rate n₀ and the
//! rudder held. The curve's tangent is the null vector of F's 3 × 4 Jacobian J, taken as
//! the vector of J's signed 3 × 3 minors, t_j = (−1)^j det J₍without column j₎: it exists
//! wherever J has full rank, folds included, and its δ-component is −det ∂F/∂(u, v, r), which
//! changes sign exactly at a fold. Each step predicts x + h t/|t| and corrects it by Newton's
//! method on F(x) = 0 and t·(x − prediction) = 0, whose Jacobian is J bordered by t: it stays
//! regular through a fold, where Newton at fixed δ would fail. J is the model's own proved
//! Jacobian program ([`Model::state_jacobian`]), its columns u, v, r and δ. The step grows
//! where Newton converges at once and halves where it does not or where the tangent turns by
//! more than [`MAX_TURN`]. A fold is located between two points whose det ∂F/∂(u, v, r)
//! differ in sign by bisection along their chord, each trial point corrected onto the curve
//! in the plane normal to the chord.
//!
//! The curve starts on the straight course: r = 0, with u, v and δ found by Newton (the trim
//! of a ship whose bias terms need a rudder to hold it straight). From there it is traced both
//! ways until δ leaves the range asked for (the last point is put on the range's end), the
//! speed falls below [`LEAST_SPEED`] of U₀ (the prime system's forces lose their meaning as U
//! goes to zero), or [`MAX_POINTS`] points.

use super::model::ShipModel;
use crate::models::Model;
use nalgebra::{Matrix3, Matrix3x4, Matrix4, Vector3, Vector4};

/// The least speed, as a fraction of U₀, the curve is traced to.
pub const LEAST_SPEED: f64 = 0.05;
/// The most points traced each way from the straight course.
pub const MAX_POINTS: usize = 4000;
/// The largest angle between two consecutive tangents, rad: the step halves beyond it.
pub const MAX_TURN: f64 = 0.1;
/// Newton has converged when its step is below this, in the scaled variables (each of order
/// one): some thousand roundings of the rates, whose terms are of order 10⁻².
const CONVERGED: f64 = 1e-12;
/// The most Newton steps per point.
const MAX_NEWTON: usize = 12;
/// The first, largest and least continuation steps, in the scaled variables.
const STEPS: (f64, f64, f64) = (0.01, 0.05, 1e-9);

/// One steady turn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyTurn {
    /// δ, rad.
    pub rudder: f64,
    /// u, m/s.
    pub u: f64,
    /// v, m/s.
    pub v: f64,
    /// r, rad/s.
    pub r: f64,
    /// Whether it is stable with the rudder held: every eigenvalue of ∂(u̇, v̇, ṙ)/∂(u, v, r)
    /// has a negative real part (Routh–Hurwitz on its characteristic polynomial).
    pub stable: bool,
}

/// The curve of steady turns over a range of rudder angles.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyTurns {
    /// The turns in order along the curve.
    pub turns: Vec<SteadyTurn>,
    /// Its folds, in the same order: where it turns back in δ.
    pub folds: Vec<SteadyTurn>,
    /// The range of δ asked for, rad.
    pub range: (f64, f64),
    /// Why each end of the traced curve is where it is (the rudder range's end, or why the
    /// curve stopped short of it).
    pub ends: [String; 2],
    /// The Newton steps taken, every point and fold together.
    pub newton_steps: usize,
}

impl SteadyTurns {
    /// The range of δ between the outermost folds, rad: the loop's width; zero for a curve
    /// without folds that spans the range asked for (one steady turn at each δ); `None` for a
    /// single fold (the loop runs past the range traced) or a curve without folds that
    /// stopped short of the range (a fold may lie beyond).
    pub fn loop_width(&self) -> Option<f64> {
        let rudders = self.folds.iter().map(|f| f.rudder);
        match self.folds.len() {
            0 => self.spans_range().then_some(0.0),
            1 => None,
            _ => {
                let low = rudders.clone().fold(f64::INFINITY, f64::min);
                Some(rudders.fold(f64::NEG_INFINITY, f64::max) - low)
            }
        }
    }

    /// Whether the curve reached both ends of the range asked for.
    pub fn spans_range(&self) -> bool {
        self.ends.iter().all(|e| e == RANGE_END)
    }
}

/// Why a traced branch ends where the range does.
const RANGE_END: &str = "the end of the rudder range";

/// The steady turns of `model` at rudder angles in `range` (rad), for a ship of `length` (m)
/// approached at `speed` U₀ (m/s), the propeller (if any) at its approach rate; `Err` with
/// why where the straight course itself cannot be found.
pub fn steady_turns(
    model: &ShipModel,
    (speed, length): (f64, f64),
    range: (f64, f64),
) -> Result<SteadyTurns, String> {
    let ship = Scaled {
        model,
        speed,
        length,
        rate: model.approach_rate(),
    };
    let mut newton = 0;
    let start = ship.straight_course(&mut newton)?;
    let mut ends = [String::new(), String::new()];
    let mut folds = [Vec::new(), Vec::new()];
    let mut branches = [Vec::new(), Vec::new()];
    for (k, direction) in [-1.0, 1.0].into_iter().enumerate() {
        let branch = ship.trace(start, direction, range, &mut newton);
        ends[k] = branch.end;
        folds[k] = branch.folds;
        branches[k] = branch.points;
    }
    let [mut back, ahead] = branches;
    back.reverse();
    back.push(start);
    back.extend(ahead);
    let [mut back_folds, ahead_folds] = folds;
    back_folds.reverse();
    back_folds.extend(ahead_folds);
    Ok(SteadyTurns {
        turns: back.iter().map(|x| ship.turn(x)).collect(),
        folds: back_folds.iter().map(|x| ship.turn(x)).collect(),
        range,
        ends,
        newton_steps: newton,
    })
}

/// What a steady turn is found at: a rudder angle, or a yaw rate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Held {
    /// δ, rad.
    Rudder(f64),
    /// r, rad/s.
    YawRate(f64),
}

/// The steady turn of `model` with δ or r held at `held`, found by Newton from `near` (a turn
/// of the curve nearby), for a ship of `length` approached at `speed` as in
/// [`steady_turns`]; `None` where Newton does not converge.
pub fn steady_turn(
    model: &ShipModel,
    (speed, length): (f64, f64),
    held: Held,
    near: &SteadyTurn,
) -> Option<SteadyTurn> {
    let ship = Scaled {
        model,
        speed,
        length,
        rate: model.approach_rate(),
    };
    let mut x = Vector4::new(
        near.u / speed,
        near.v / speed,
        near.r * length / speed,
        near.rudder,
    );
    let normal = match held {
        Held::Rudder(rudder) => {
            x[3] = rudder;
            Vector4::w()
        }
        Held::YawRate(r) => {
            x[2] = r * length / speed;
            Vector4::z()
        }
    };
    let (found, _) = ship.correct(x, &normal)?;
    Some(ship.turn(&found))
}

/// One way along the curve from the straight course.
struct Branch {
    points: Vec<Vector4<f64>>,
    folds: Vec<Vector4<f64>>,
    end: String,
}

/// The ship in the scaled variables of the module's documentation.
struct Scaled<'a> {
    model: &'a ShipModel,
    speed: f64,
    length: f64,
    /// The propeller rate n₀, rev/s.
    rate: f64,
}

impl Scaled<'_> {
    /// The model's state at x: (u, v, r), the heading and position zero, δ.
    fn state(&self, x: &Vector4<f64>) -> [f64; 7] {
        let (u, l) = (self.speed, self.length);
        [u * x[0], u * x[1], u / l * x[2], 0.0, 0.0, 0.0, x[3]]
    }

    /// What each rate is scaled by: L/U₀² for u̇ and v̇, L²/U₀² for ṙ.
    fn rate_scales(&self) -> [f64; 3] {
        let (u, l) = (self.speed, self.length);
        [l / (u * u), l / (u * u), l * l / (u * u)]
    }

    /// F(x).
    fn residual(&self, x: &Vector4<f64>) -> Vector3<f64> {
        let rates = self.model.rhs(&self.state(x), &[0.0, self.rate, 0.0]);
        let scales = self.rate_scales();
        Vector3::from_fn(|i, _| rates[i] * scales[i])
    }

    /// J = ∂F/∂x: the proved Jacobian's rows u̇, v̇, ṙ and columns u, v, r, δ, scaled.
    fn jacobian(&self, x: &Vector4<f64>) -> Matrix3x4<f64> {
        let jacobian = self
            .model
            .state_jacobian(&self.state(x), &[0.0, self.rate, 0.0]);
        let (u, l) = (self.speed, self.length);
        let columns = [(0, u), (1, u), (2, u / l), (6, 1.0)];
        let scales = self.rate_scales();
        Matrix3x4::from_fn(|i, j| jacobian[i][columns[j].0] * columns[j].1 * scales[i])
    }

    /// The tangent: J's signed 3 × 3 minors, t_j = (−1)^j det J₍without column j₎.
    fn tangent(&self, x: &Vector4<f64>) -> Vector4<f64> {
        let j = self.jacobian(x);
        Vector4::from_fn(|k, _| {
            let minor = Matrix3::from_fn(|r, c| j[(r, if c < k { c } else { c + 1 })]);
            if k % 2 == 0 {
                minor.determinant()
            } else {
                -minor.determinant()
            }
        })
    }

    /// det ∂F/∂(u, v, r): zero at a fold.
    fn fold_function(&self, x: &Vector4<f64>) -> f64 {
        self.jacobian(x)
            .fixed_columns::<3>(0)
            .into_owned()
            .determinant()
    }

    /// The point of the curve nearest `through` in the plane normal to `normal` through it:
    /// Newton on F = 0 and normal·(x − through) = 0, and the steps it took; `None` where it
    /// does not converge.
    fn correct(
        &self,
        through: Vector4<f64>,
        normal: &Vector4<f64>,
    ) -> Option<(Vector4<f64>, usize)> {
        let mut x = through;
        for step in 1..=MAX_NEWTON {
            let (f, j) = (self.residual(&x), self.jacobian(&x));
            let bordered = Matrix4::from_fn(|r, c| if r < 3 { j[(r, c)] } else { normal[c] });
            let rhs = Vector4::new(-f[0], -f[1], -f[2], -normal.dot(&(x - through)));
            let dx = bordered.lu().solve(&rhs)?;
            x += dx;
            if !x.iter().all(|v| v.is_finite()) {
                return None;
            }
            if dx.norm() <= CONVERGED {
                return Some((x, step));
            }
        }
        None
    }

    /// The straight course: r = 0, Newton on (u, v, δ) from the approach.
    fn straight_course(&self, newton: &mut usize) -> Result<Vector4<f64>, String> {
        let approach = Vector4::new(1.0, 0.0, 0.0, 0.0);
        let (x, steps) = self.correct(approach, &Vector4::z()).ok_or_else(|| {
            "Newton found no straight course (r = 0) near the approach: the steady turns \
             are traced from there"
                .to_owned()
        })?;
        *newton += steps;
        Ok(x)
    }

    /// The curve from `start` one way (`direction` ±1 along the minors' tangent) until δ
    /// leaves `range`, the speed falls below the least, or the most points.
    fn trace(
        &self,
        start: Vector4<f64>,
        direction: f64,
        (low, high): (f64, f64),
        newton: &mut usize,
    ) -> Branch {
        let (first, largest, least) = STEPS;
        let mut branch = Branch {
            points: Vec::new(),
            folds: Vec::new(),
            end: String::new(),
        };
        let (mut x, mut t) = (start, self.tangent(&start).normalize() * direction);
        let mut h = first;
        while branch.points.len() < MAX_POINTS {
            let prediction = x + t * h;
            let Some((next, steps)) = self.correct(prediction, &t) else {
                h /= 2.0;
                if h < least {
                    branch.end = format!(
                        "Newton did not converge on the curve past δ = {:.4}°",
                        x[3].to_degrees()
                    );
                    return branch;
                }
                continue;
            };
            *newton += steps;
            let mut tangent = self.tangent(&next).normalize();
            if tangent.dot(&t) < 0.0 {
                tangent = -tangent;
            }
            if tangent.dot(&t) < MAX_TURN.cos() && h > least {
                h /= 2.0;
                continue;
            }
            if self.fold_function(&x).signum() != self.fold_function(&next).signum()
                && let Some(fold) = self.fold(x, next, newton)
            {
                branch.folds.push(fold);
            }
            if next[3] < low || next[3] > high {
                let bound = if next[3] < low { low } else { high };
                let mut on_bound = next;
                on_bound[3] = bound;
                if let Some((end, steps)) = self.correct(on_bound, &Vector4::w()) {
                    *newton += steps;
                    branch.points.push(end);
                }
                branch.end = RANGE_END.to_owned();
                return branch;
            }
            branch.points.push(next);
            if next[0].hypot(next[1]) < LEAST_SPEED {
                branch.end = format!(
                    "the speed fell below {:.0} % of U₀ at δ = {:.4}°",
                    LEAST_SPEED * 100.0,
                    next[3].to_degrees()
                );
                return branch;
            }
            (x, t) = (next, tangent);
            if steps <= 3 {
                h = (h * 1.5).min(largest);
            }
        }
        branch.end = format!("the most points ({MAX_POINTS}) were traced");
        branch
    }

    /// The fold between two points of the curve whose fold functions differ in sign, by
    /// bisection along their chord, to adjacent floating-point fractions of it.
    fn fold(&self, a: Vector4<f64>, b: Vector4<f64>, newton: &mut usize) -> Option<Vector4<f64>> {
        let chord = b - a;
        let sign_a = self.fold_function(&a).signum();
        let (mut low, mut high) = (0.0_f64, 1.0_f64);
        let mut found = a;
        while high - low > f64::EPSILON {
            let middle = 0.5 * (low + high);
            if middle <= low || middle >= high {
                break;
            }
            let (x, steps) = self.correct(a + chord * middle, &chord)?;
            *newton += steps;
            if self.fold_function(&x).signum() == sign_a {
                low = middle;
            } else {
                high = middle;
            }
            found = x;
        }
        Some(found)
    }

    /// The steady turn at x, in SI, with its stability.
    fn turn(&self, x: &Vector4<f64>) -> SteadyTurn {
        let state = self.state(x);
        let jacobian = self.model.state_jacobian(&state, &[0.0, self.rate, 0.0]);
        let a = Matrix3::from_fn(|i, j| jacobian[i][j]);
        SteadyTurn {
            rudder: x[3],
            u: state[0],
            v: state[1],
            r: state[2],
            stable: hurwitz_stable(&a),
        }
    }
}

/// Whether every eigenvalue of `a` has a negative real part: Routh–Hurwitz on
/// λ³ + a₂λ² + a₁λ + a₀ (a₂ = −tr A, a₁ the sum of the principal 2 × 2 minors, a₀ = −det A):
/// a₂ > 0, a₀ > 0 and a₂a₁ > a₀.
fn hurwitz_stable(a: &Matrix3<f64>) -> bool {
    let minor = |i: usize, j: usize| a[(i, i)] * a[(j, j)] - a[(i, j)] * a[(j, i)];
    let a2 = -a.trace();
    let a1 = minor(0, 1) + minor(0, 2) + minor(1, 2);
    let a0 = -a.determinant();
    a2 > 0.0 && a0 > 0.0 && a2 * a1 > a0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn routh_hurwitz_tells_stable_from_unstable() {
        let stable = Matrix3::from_diagonal(&Vector3::new(-1.0, -2.0, -3.0));
        assert!(hurwitz_stable(&stable));
        let growing = Matrix3::from_diagonal(&Vector3::new(-1.0, 0.5, -3.0));
        assert!(!hurwitz_stable(&growing));
        // A pair at ±2i and −1: marginal, not stable.
        let oscillating = Matrix3::new(0.0, 2.0, 0.0, -2.0, 0.0, 0.0, 0.0, 0.0, -1.0);
        assert!(!hurwitz_stable(&oscillating));
    }
}
