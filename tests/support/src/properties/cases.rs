//! Random physical bodies, states and loads for the property tests, each over many decades,
//! with the extremes mixed in: inertia ratios up to 10⁶ (the thin rod), rates up to 10³ rad/s,
//! pitch from 1e-12 to 1e-6 rad from ±90°.

use eom::{InertiaTensor, PendulumParameters};
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// Which products of inertia a random tensor has (all three: principal axes rotated at
/// random; only I_xz: rotated about y; none), and how the attitude is carried: the catalog's
/// own enums.
pub use eom::models::{Kinematics, Symmetry};

/// Where the pitch of a random Euler attitude lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pitch {
    /// Uniform with |θ| below 90° − 1e-3 rad.
    Random,
    /// ±90° ± δ, δ from 1e-12 to 1e-6 rad on a log scale, on either side of +90° and of −90°,
    /// never at it: |cos θ| ≈ δ, so sec θ and tan θ from 10⁶ to 10¹².
    NearVertical,
}

/// sign · 10^e with e uniform in [lo, hi]: every decade in the range equally often.
pub fn signed_log(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..=hi, any::<bool>()).prop_map(|(e, negative)| {
        let magnitude = 10f64.powf(e);
        if negative { -magnitude } else { magnitude }
    })
}

/// A vector with each component from [`signed_log`].
pub fn signed_log_vector(lo: f64, hi: f64) -> impl Strategy<Value = Vector3<f64>> {
    prop::array::uniform3(signed_log(lo, hi)).prop_map(Vector3::from)
}

/// Body rates: random over six decades up to 10³ rad/s, or every component at ±10³ rad/s.
pub fn body_rates() -> impl Strategy<Value = Vector3<f64>> {
    let extreme = prop::array::uniform3(prop_oneof![Just(1e3), Just(-1e3)]).prop_map(Vector3::from);
    prop_oneof![3 => signed_log_vector(-3.0, 3.0), 1 => extreme]
}

/// A uniformly distributed unit quaternion (four components from a ball, normalised).
pub fn unit_quaternion() -> impl Strategy<Value = UnitQuaternion<f64>> {
    prop::array::uniform4(-1.0..1.0f64)
        .prop_filter("a point well inside the unit ball", |c| {
            let n = c.iter().map(|x| x * x).sum::<f64>();
            (0.01..=1.0).contains(&n)
        })
        .prop_map(|[w, i, j, k]| UnitQuaternion::new_normalize(Quaternion::new(w, i, j, k)))
}

/// Principal moments a ≤ b ≤ c with c ≤ a + b (the triangle inequality of 4.13), the ratio
/// b/a up to 10⁶, the smallest moment over four decades, in a random order. One case in eight
/// is the thin rod (1, 10⁶, 10⁶), scaled.
pub fn principal_moments() -> impl Strategy<Value = [f64; 3]> {
    let random = (0.0..=6.0f64, 0.0..0.99f64).prop_map(|(ratio, t)| {
        let b = 10f64.powf(ratio);
        [1.0, b, b + t]
    });
    let rod = Just([1.0, 1e6, 1e6]);
    (prop_oneof![7 => random, 1 => rod], -2.0..2.0f64, 0..6usize).prop_map(
        |(moments, scale, order)| {
            let s = 10f64.powf(scale);
            let [a, b, c] = moments.map(|m| m * s);
            [
                [a, b, c],
                [a, c, b],
                [b, a, c],
                [b, c, a],
                [c, a, b],
                [c, b, a],
            ][order]
        },
    )
}

/// A physical inertia tensor of the class: principal moments turned by a random rotation
/// when the class keeps every product, about the one axis that leaves exactly the kept
/// product when it keeps one (about y for the xz class), not at all when it keeps none. The
/// class is read from what it prunes, so a new class needs no edit here.
pub fn inertia_tensor(class: Symmetry) -> impl Strategy<Value = InertiaTensor> {
    (principal_moments(), unit_quaternion(), -3.2..3.2f64).prop_map(move |(m, q, angle)| {
        let kept: Vec<&str> = ["Ixy", "Iyz", "Ixz"]
            .into_iter()
            .filter(|p| !class.pruned().contains(p))
            .collect();
        let rotation = match kept.as_slice() {
            [] => Rotation3::identity(),
            ["Ixy"] => Rotation3::from_axis_angle(&Vector3::z_axis(), angle),
            ["Iyz"] => Rotation3::from_axis_angle(&Vector3::x_axis(), angle),
            ["Ixz"] => Rotation3::from_axis_angle(&Vector3::y_axis(), angle),
            _ => q.to_rotation_matrix(),
        };
        let r = rotation.matrix();
        let i = r * Matrix3::from_diagonal(&Vector3::from(m)) * r.transpose();
        let keep = |name: &str, value: f64| if kept.contains(&name) { value } else { 0.0 };
        let (ixy, iyz, izx) = (
            keep("Ixy", i[(0, 1)]),
            keep("Iyz", i[(1, 2)]),
            keep("Ixz", i[(2, 0)]),
        );
        InertiaTensor::new(i[(0, 0)], i[(1, 1)], i[(2, 2)], ixy, iyz, izx)
            .expect("principal moments satisfying the triangle inequality, rotated")
    })
}

/// One random evaluation point of a spatial model.
#[derive(Debug, Clone)]
pub struct SpatialCase {
    /// The mass M.
    pub mass: f64,
    /// The tensor about G.
    pub tensor: InertiaTensor,
    /// Body velocity of G, (u, v, w).
    pub velocity: Vector3<f64>,
    /// Body rates, (p, q, r).
    pub omega: Vector3<f64>,
    /// Position of G, (x, y, z).
    pub position: Vector3<f64>,
    /// Euler angles (φ, θ, ψ).
    pub euler: Vector3<f64>,
    /// An independent attitude for the quaternion variants.
    pub quaternion: UnitQuaternion<f64>,
    /// Force, body axes.
    pub force: Vector3<f64>,
    /// Moment about G, body axes.
    pub moment: Vector3<f64>,
}

impl SpatialCase {
    /// The state of the variant's layout.
    pub fn state(&self, kinematics: Kinematics) -> Vec<f64> {
        let mut state: Vec<f64> = self.velocity.iter().copied().collect();
        state.extend(self.omega.iter().chain(self.position.iter()));
        match kinematics {
            Kinematics::Euler => state.extend(self.euler.iter()),
            Kinematics::Quaternion => state.extend(self.quaternion.coords.iter()),
        }
        if kinematics == Kinematics::Quaternion {
            // nalgebra stores (i, j, k, w); the state is scalar first.
            state[9..].rotate_right(1);
        }
        state
    }

    /// The same case with zero force and moment.
    pub fn torque_free(&self) -> Self {
        Self {
            force: Vector3::zeros(),
            moment: Vector3::zeros(),
            ..self.clone()
        }
    }
}

/// Random spatial cases for a tensor class and a pitch range. The force and the moment are
/// M·a and I_max·α with a and α over several decades, so that no term always dominates.
pub fn spatial_case(class: Symmetry, pitch: Pitch) -> impl Strategy<Value = SpatialCase> {
    let theta = match pitch {
        Pitch::Random => {
            let limit = std::f64::consts::FRAC_PI_2 - 1e-3;
            (-limit..limit).boxed()
        }
        // The offset's sign puts θ below or above the vertical; the double nearest ±π/2 + δ
        // carries δ to at least 2e-4 of itself (the spacing there is 2.2e-16).
        Pitch::NearVertical => (prop_oneof![Just(1.0), Just(-1.0)], signed_log(-12.0, -6.0))
            .prop_map(|(vertical, offset)| vertical * std::f64::consts::FRAC_PI_2 + offset)
            .boxed(),
    };
    let angle = -std::f64::consts::PI..std::f64::consts::PI;
    let kinematic = (
        signed_log_vector(-3.0, 2.0),
        body_rates(),
        prop::array::uniform3(-1e3..1e3f64),
        (angle.clone(), theta, angle),
        unit_quaternion(),
    );
    let dynamic = (
        -2.0..6.0f64,
        inertia_tensor(class),
        signed_log_vector(-2.0, 3.0),
        signed_log_vector(-2.0, 3.0),
    );
    (kinematic, dynamic).prop_map(|((v, w, x, (phi, theta, psi), q), (m, tensor, a, alpha))| {
        let mass = 10f64.powf(m);
        let largest = tensor.ixx().max(tensor.iyy()).max(tensor.izz());
        SpatialCase {
            mass,
            tensor,
            velocity: v,
            omega: w,
            position: Vector3::from(x),
            euler: Vector3::new(phi, theta, psi),
            quaternion: q,
            force: a * mass,
            moment: alpha * largest,
        }
    })
}

/// One random evaluation point of the planar models: a body, a planar state and a load.
#[derive(Debug, Clone)]
pub struct PlanarCase {
    /// The mass M.
    pub mass: f64,
    /// The yaw moment of inertia about G.
    pub izz: f64,
    /// G's distance ahead of midship (used by the midship model only).
    pub x_g: f64,
    /// `[u, v, r, X, Y, ψ]`; for the space-fixed model, read as `[Ẋ, Ẏ, ψ̇, X, Y, ψ]`.
    pub state: [f64; 6],
    /// `[F_x, F_y, M_z]` (or `[X, Y, N]` at midship, or space axes).
    pub load: [f64; 3],
}

impl PlanarCase {
    /// The state `[X, Y, ψ, Ẋ, Ẏ, ψ̇]` of the space-fixed model.
    pub fn space_fixed_state(&self) -> [f64; 6] {
        let [u, v, r, x, y, psi] = self.state;
        [x, y, psi, u, v, r]
    }
}

/// Random planar cases: M over eight decades, radius of gyration over three, x_G up to 100,
/// velocities up to 100, yaw rates up to 10³ rad/s, loads M·a and I_zz·α over several decades.
pub fn planar_case() -> impl Strategy<Value = PlanarCase> {
    let angle = -std::f64::consts::PI..std::f64::consts::PI;
    (
        (-2.0..6.0f64, -1.0..2.0f64, signed_log(-3.0, 2.0)),
        (
            signed_log(-3.0, 2.0),
            signed_log(-3.0, 2.0),
            signed_log(-3.0, 3.0),
        ),
        (-1e3..1e3f64, -1e3..1e3f64, angle),
        (
            signed_log(-2.0, 3.0),
            signed_log(-2.0, 3.0),
            signed_log(-2.0, 3.0),
        ),
    )
        .prop_map(|((m, k, x_g), (u, v, r), (x, y, psi), (ax, ay, alpha))| {
            let mass = 10f64.powf(m);
            let izz = mass * 10f64.powf(2.0 * k);
            PlanarCase {
                mass,
                izz,
                x_g,
                state: [u, v, r, x, y, psi],
                load: [mass * ax, mass * ay, izz * alpha],
            }
        })
}

/// One random evaluation point of the compound pendulum.
#[derive(Debug, Clone)]
pub struct PendulumCase {
    /// I₀ = M(κ_G² + h²) > M h², as 4.29 requires.
    pub i0: f64,
    /// The mass M.
    pub mass: f64,
    /// Gravity g.
    pub g: f64,
    /// Pivot to G, h.
    pub h: f64,
    /// `[θ, θ̇]`, θ over several turns.
    pub state: [f64; 2],
    /// The applied moment about the pivot.
    pub moment: f64,
}

impl PendulumCase {
    /// The validated parameter set that every pendulum form is built from.
    pub fn parameters(&self) -> PendulumParameters {
        PendulumParameters::new(self.i0, self.mass, self.g, self.h)
            .expect("I₀ > M h² by construction")
    }
}

/// Random pendulums and states.
pub fn pendulum_case() -> impl Strategy<Value = PendulumCase> {
    (
        (-2.0..6.0f64, -2.0..1.0f64, 0.0..10.0f64, 0.1..30.0f64),
        (-20.0..20.0f64, signed_log(-3.0, 3.0), signed_log(-2.0, 3.0)),
    )
        .prop_map(|((m, k, h, g), (theta, rate, alpha))| {
            let mass = 10f64.powf(m);
            let i0 = mass * (10f64.powf(2.0 * k) + h * h);
            PendulumCase {
                i0,
                mass,
                g,
                h,
                state: [theta, rate],
                moment: i0 * alpha,
            }
        })
}
