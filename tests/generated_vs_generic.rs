//! The generated models against the independent nalgebra forms (`eom::generic`), variant by
//! variant: at random states, at the extremes (pitch 1e-12 to 1e-6 rad from ±90°, rates up to
//! 10³ rad/s, inertia ratios up to 10⁶), a pruned variant against the full one for a body
//! whose pruned products are zero, f32 against f64, and SIMD lanes (f64×4, f32×8) against
//! the scalar model, bit for bit.
//!
//! Every comparison is relative to the size of the terms of each output (see `eom_test_support::properties`), not
//! to the output itself, because the two forms add the same terms in different orders and an
//! output may cancel.

use eom::generic::{self, ModelError};
use eom::models::{
    Model, Pendulum, PlanarAtG, PlanarMidship, PlanarSpaceFixed, SpatialFullEuler,
    SpatialFullQuaternion, SpatialPrincipalQuaternion, SpatialXzEuler, SpatialXzQuaternion,
};
use eom::{InertiaTensor, PendulumParameters};
use eom_test_support::properties;
use eom_test_support::properties::{
    Kinematics, PendulumCase, Pitch, PlanarCase, Spatial, SpatialCase, Symmetry, at_g_scale,
    generated, generic, inverse_scale, midship_scale, pendulum_case, pendulum_scale, planar_case,
    relative_gap, space_fixed_scale, spatial_case, spatial_scale,
};
use nalgebra::{Quaternion, UnitQuaternion, Vector3, Vector6};
use simba::scalar::SupersetOf;
use simba::simd::{SimdRealField, WideF32x8, WideF64x4};

/// Relative 1e-12 of the size of the terms: two f64 forms of one formula. Each evaluates an
/// output through at most ~16 roundings, so each is within 16·(ε/2)·scale of the exact value
/// and the two within 16ε·scale ≈ 3.6e-15·scale to first order. The scale includes the
/// conditioning of the f64 inverse of [I] (and of the midship mass matrix): the generator
/// inverts by cofactors over an expanded determinant, nalgebra by its own cofactor order, and
/// for a rotated thin rod (1, 10⁶, 10⁶) the determinant is 10⁶ times smaller than its terms,
/// so the two inverses differ by ~10⁶ε relative to [I]⁻¹ itself (2e-12 seen when the scale
/// leaves this out); relative to the terms they agree to a few ε.
///
/// Pitch 1e-12 to 1e-6 rad from ±90° (`Pitch::NearVertical`) keeps the same relative
/// tolerance because the scale grows with the terms: the terms of φ̇ and ψ̇ are
/// (|q sin φ| + |r cos φ|)/|cos θ|, 10⁶ to 10¹² times the rates, and both forms compute sin θ
/// and cos θ of the same double with relative accuracy (the kernel's `sin_cos` is tested
/// relative next to every multiple of π/2), so sec θ is a few ε off in each and the gap a
/// few ε of the terms, as at any other pitch. What no tolerance here absorbs is a pitch that
/// differs by an ulp between the two: that changes sec θ by ε/|cos θ| of itself, up to
/// 2e-4 at 1e-12 rad, which is why every input is read to the nearest double
/// (`app/tests/exact_inputs.rs`).
///
/// Near the vertical the Euler rates are also held to [`EULER_RATES_TOLERANCE`], without the
/// inverse of [I] that the 1e-12 is made for.
const F64_TOLERANCE: f64 = 1e-12;

/// φ̇, θ̇, ψ̇ (4.60) generated against generic next to ±90°, in units of f64::EPSILON times the
/// term size. Each form evaluates φ̇ = p + (q sin φ + r cos φ) tan θ with at most seven
/// roundings of ε/2 of the terms (q sin φ, r cos φ, their sum, 1/cos θ, two products, the sum
/// with p): 3.5ε each, 7ε for the two. Their sines and cosines differ too: the kernel's
/// `sin_cos` is within one ulp of the platform's for everyday angles (φ) and within two next
/// to a multiple of π/2 (θ), and an ulp is at most ε relative, so 1 + 1 + 2 + 2 = 6ε of the
/// terms. 13ε in all, at worst; 16ε. θ̇ and ψ̇ have fewer operations.
const EULER_RATES_TOLERANCE: f64 = 16.0;

/// A pruned variant against the full one, for a body whose pruned products are zero: two f64
/// evaluations of the same formula with the zero terms dropped, each within 16·(ε/2)·scale,
/// so 16ε apart at most; 64ε leaves a factor of four for the second-order terms.
const PRUNED_TOLERANCE: f64 = 64.0 * f64::EPSILON;

/// f32 against f64 at the same (f32-rounded) state and inputs, in units of f32::EPSILON times
/// the term size. The f32 coefficients are the f64 ones rounded once, the trigonometry is
/// within an ulp, and the longest path from a rounded input to an output (the full tensor's
/// ṗ: H = [I]ω, ω × H, the bracket, [I]⁻¹ times it; or φ̇ through sin, cos, 1/cos θ) has at
/// most ~12 roundings of ε/2: 6ε. The f64 reference is 10⁹ times more accurate. 16ε allows
/// a factor of 2.5 over the count.
const F32_TOLERANCE: f64 = 16.0;

/// Generated against generic for one spatial variant, relative to the f64 term sizes.
fn spatial_gap<S: Spatial<f64>>(case: &SpatialCase) -> f64 {
    let inverse = inverse_scale(&case.tensor.matrix()).terms;
    let scale = spatial_scale(case, S::KINEMATICS, &inverse);
    relative_gap(&generated::<S>(case), &generic(case, S::KINEMATICS), &scale)
}

/// The Euler rates φ̇, θ̇, ψ̇ (entries 9 to 11) generated against generic, in units of
/// f64::EPSILON times their term sizes.
fn euler_rates_gap<S: Spatial<f64>>(case: &SpatialCase) -> f64 {
    assert_eq!(
        S::KINEMATICS,
        Kinematics::Euler,
        "{} has no Euler rates",
        S::NAME
    );
    let inverse = inverse_scale(&case.tensor.matrix()).terms;
    let scale = spatial_scale(case, S::KINEMATICS, &inverse);
    let (ours, theirs) = (generated::<S>(case), generic(case, S::KINEMATICS));
    relative_gap(&ours[9..12], &theirs[9..12], &scale[9..12]) / f64::EPSILON
}

/// A pruned variant `P` against the full variant `F` on a body of `P`'s class.
fn pruned_gap<P: Spatial<f64>, F: Spatial<f64>>(case: &SpatialCase) -> f64 {
    let inverse = inverse_scale(&case.tensor.matrix()).terms;
    let scale = spatial_scale(case, P::KINEMATICS, &inverse);
    relative_gap(&generated::<P>(case), &generated::<F>(case), &scale)
}

/// The case with its state and inputs rounded to f32 (and read back as f64).
fn rounded(case: &SpatialCase) -> SpatialCase {
    let round = |v: &Vector3<f64>| v.map(|x| f64::from(x as f32));
    let q = case.quaternion.coords.map(|x| f64::from(x as f32));
    SpatialCase {
        velocity: round(&case.velocity),
        omega: round(&case.omega),
        position: round(&case.position),
        euler: round(&case.euler),
        quaternion: UnitQuaternion::new_unchecked(Quaternion::from(q)),
        force: round(&case.force),
        moment: round(&case.moment),
        ..case.clone()
    }
}

/// The f32 model `S32` against the f64 model `S64` of the same variant at the f32-rounded
/// case, in units of f32::EPSILON times the term size with exact coefficients.
fn f32_gap<S32: Spatial<f32>, S64: Spatial<f64>>(case: &SpatialCase) -> f64 {
    let case = rounded(case);
    let state = case.state(S64::KINEMATICS);
    let narrow = |v: &Vector3<f64>| v.map(|x| x as f32).into();
    let model = S32::build(case.mass, &case.tensor).expect("a valid body");
    let state32: Vec<f32> = state.iter().map(|&x| x as f32).collect();
    let single = model.eval(&state32, &narrow(&case.force), &narrow(&case.moment));
    let single: Vec<f64> = single.into_iter().map(f64::from).collect();
    let inverse = inverse_scale(&case.tensor.matrix()).value;
    let scale = spatial_scale(&case, S64::KINEMATICS, &inverse);
    relative_gap(&single, &generated::<S64>(&case), &scale) / f64::from(f32::EPSILON)
}

fn pendulum_gap(case: &PendulumCase) -> f64 {
    let parameters = case.parameters();
    let ours = Pendulum::<f64>::new(&parameters).rhs(&case.state, &[case.moment]);
    let theirs = generic::Pendulum::<f64>::new(&parameters);
    let theirs = theirs.rhs(&case.state.into(), case.moment);
    relative_gap(&ours, theirs.as_slice(), &pendulum_scale(case))
}

fn at_g_gap(case: &PlanarCase) -> f64 {
    let ours = PlanarAtG::<f64>::new(case.mass, case.izz).unwrap();
    let theirs = generic::PlanarBody::<f64>::new(case.mass, case.izz).unwrap();
    let theirs = theirs.rhs_body_at_g(&Vector6::from(case.state), &case.load.into());
    let ours = ours.rhs(&case.state, &case.load);
    relative_gap(&ours, theirs.as_slice(), &at_g_scale(case))
}

fn midship_gap(case: &PlanarCase) -> f64 {
    let ours = PlanarMidship::<f64>::new(case.mass, case.izz, case.x_g).unwrap();
    let theirs = generic::PlanarMidship::<f64>::new(case.mass, case.izz, case.x_g).unwrap();
    let theirs = theirs.rhs_body_at_midship(&Vector6::from(case.state), &case.load.into());
    let ours = ours.rhs(&case.state, &case.load);
    relative_gap(&ours, theirs.as_slice(), &midship_scale(case, true))
}

fn space_fixed_gap(case: &PlanarCase) -> f64 {
    let state = case.space_fixed_state();
    let ours = PlanarSpaceFixed::<f64>::new(case.mass, case.izz).unwrap();
    let theirs = generic::PlanarBody::<f64>::new(case.mass, case.izz).unwrap();
    let theirs = theirs.rhs_space_fixed(&Vector6::from(state), &case.load.into());
    let ours = ours.rhs(&state, &case.load);
    relative_gap(&ours, theirs.as_slice(), &space_fixed_scale(case))
}

/// The planar models and the pendulum in f32 against f64 at the f32-rounded state, in units
/// of f32::EPSILON times the term size with exact coefficients.
fn planar_f32_gap(case: &PlanarCase) -> f64 {
    let state = case.state.map(|x| x as f32);
    let load = case.load.map(|x| x as f32);
    let widen = |a: [f32; 6]| a.map(f64::from);
    let rounded = PlanarCase {
        state: state.map(f64::from),
        load: load.map(f64::from),
        ..case.clone()
    };
    let (m, izz, x_g) = (case.mass, case.izz, case.x_g);
    let at_g = PlanarAtG::<f32>::new(m, izz).unwrap().rhs(&state, &load);
    let at_g64 = PlanarAtG::<f64>::new(m, izz).unwrap();
    let at_g64 = at_g64.rhs(&rounded.state, &rounded.load);
    let midship = PlanarMidship::<f32>::new(m, izz, x_g)
        .unwrap()
        .rhs(&state, &load);
    let midship64 = PlanarMidship::<f64>::new(m, izz, x_g).unwrap();
    let midship64 = midship64.rhs(&rounded.state, &rounded.load);
    let fixed_state = rounded.space_fixed_state().map(|x| x as f32);
    let fixed = PlanarSpaceFixed::<f32>::new(m, izz)
        .unwrap()
        .rhs(&fixed_state, &load);
    let fixed64 = PlanarSpaceFixed::<f64>::new(m, izz).unwrap();
    let fixed64 = fixed64.rhs(&rounded.space_fixed_state(), &rounded.load);
    let gaps = [
        relative_gap(&widen(at_g), &at_g64, &at_g_scale(&rounded)),
        relative_gap(&widen(midship), &midship64, &midship_scale(&rounded, false)),
        relative_gap(&widen(fixed), &fixed64, &space_fixed_scale(&rounded)),
    ];
    gaps.into_iter().fold(0.0, f64::max) / f64::from(f32::EPSILON)
}

fn pendulum_f32_gap(case: &PendulumCase) -> f64 {
    let parameters = case.parameters();
    let state = case.state.map(|x| x as f32);
    let moment = case.moment as f32;
    let rounded = PendulumCase {
        state: state.map(f64::from),
        moment: f64::from(moment),
        ..case.clone()
    };
    let single = Pendulum::<f32>::new(&parameters).rhs(&state, &[moment]);
    let double = Pendulum::<f64>::new(&parameters).rhs(&rounded.state, &[rounded.moment]);
    let gap = relative_gap(&single.map(f64::from), &double, &pendulum_scale(&rounded));
    gap / f64::from(f32::EPSILON)
}

properties! {
    pendulum_matches_generic: pendulum_case(), pendulum_gap, F64_TOLERANCE;
    planar_at_g_matches_generic: planar_case(), at_g_gap, F64_TOLERANCE;
    planar_midship_matches_generic: planar_case(), midship_gap, F64_TOLERANCE;
    planar_space_fixed_matches_generic: planar_case(), space_fixed_gap, F64_TOLERANCE;
    planar_f32_matches_f64: planar_case(), planar_f32_gap, F32_TOLERANCE;
    pendulum_f32_matches_f64: pendulum_case(), pendulum_f32_gap, F32_TOLERANCE;
}

/// SIMD lanes against the scalar model of the same variant, lane by lane: 0 when every output
/// of every lane has the scalar's bits (the same arithmetic in each lane, and the kernel's
/// sines and cosines the scalar kernel's), else the largest relative difference. Lane k holds
/// the case's state with every entry times 1 + k/16, so that no two lanes are alike.
fn lanes_gap<L, S, T>(case: &SpatialCase) -> f64
where
    T: SimdRealField + Copy,
    T::Element: SimdRealField + Copy,
    L: Spatial<T>,
    S: Spatial<T::Element>,
{
    let element = |x: f64| T::Element::from_subset(&x);
    let state = case.state(S::KINEMATICS);
    let lane_state = |k: usize| -> Vec<T::Element> {
        let factor = 1.0 + k as f64 / 16.0;
        state.iter().map(|&x| element(x * factor)).collect()
    };
    let states: Vec<Vec<T::Element>> = (0..T::LANES).map(lane_state).collect();
    let packed: Vec<T> = (0..state.len())
        .map(|i| {
            let mut lanes = T::splat(states[0][i]);
            for (k, lane) in states.iter().enumerate() {
                lanes.replace(k, lane[i]);
            }
            lanes
        })
        .collect();
    let load = |v: &Vector3<f64>| [0, 1, 2].map(|i| element(v[i]));
    let (force, moment) = (load(&case.force), load(&case.moment));
    let lanes = L::build(case.mass, &case.tensor).expect("a valid body");
    let scalar = S::build(case.mass, &case.tensor).expect("a valid body");
    let out = lanes.eval(&packed, &force.map(T::splat), &moment.map(T::splat));
    let mut worst = 0.0f64;
    for (k, lane) in states.iter().enumerate() {
        let expected = scalar.eval(lane, &force, &moment);
        for (got, want) in out.iter().zip(&expected) {
            let (got, want) = (got.extract(k), *want);
            if got != want {
                let (a, b): (f64, f64) = (got.to_subset().unwrap(), want.to_subset().unwrap());
                worst = worst.max((a - b).abs() / a.abs().max(b.abs()));
            }
        }
    }
    worst
}

/// The full-tensor variant of a kinematics, which a pruned variant is compared with.
macro_rules! full_variant {
    (Euler) => {
        SpatialFullEuler<f64>
    };
    (Quaternion) => {
        SpatialFullQuaternion<f64>
    };
}

/// The Euler rates near pitch ±90° for a variant with Euler kinematics; nothing for a
/// quaternion variant, whose attitude has no singularity there.
macro_rules! euler_rates_near_vertical {
    (Euler) => {
        properties! {
            euler_rates_match_generic_near_vertical: spatial_case(CLASS, Pitch::NearVertical), euler_rates_gap::<Model64>, EULER_RATES_TOLERANCE;
        }
    };
    (Quaternion) => {};
}

/// For every spatial variant of the catalog, a module of properties: generated against
/// generic at random attitudes and 1e-12 to 1e-6 rad from pitch ±90° (and there the Euler
/// rates alone, to a few ε), f32 against f64 likewise, the variant
/// against the full one on a body of its class, and the refusal of a tensor whose
/// determinant leaves f64.
macro_rules! spatial_properties {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        $(spatial_properties!(@item $module $type $family $(($($option),+))?);)*
    };
    (@item $module:ident $type:ident Spatial($symmetry:ident, $kinematics:ident)) => {
        mod $module {
            use super::*;
            type Model64 = eom::models::$type<f64>;
            type Model32 = eom::models::$type<f32>;
            const CLASS: Symmetry = Symmetry::$symmetry;

            properties! {
                matches_generic: spatial_case(CLASS, Pitch::Random), spatial_gap::<Model64>, F64_TOLERANCE;
                matches_generic_near_vertical: spatial_case(CLASS, Pitch::NearVertical), spatial_gap::<Model64>, F64_TOLERANCE;
                f32_matches_f64: spatial_case(CLASS, Pitch::Random), f32_gap::<Model32, Model64>, F32_TOLERANCE;
                f32_matches_f64_near_vertical: spatial_case(CLASS, Pitch::NearVertical), f32_gap::<Model32, Model64>, F32_TOLERANCE;
                equals_the_full_variant_on_a_body_of_its_class: spatial_case(CLASS, Pitch::Random), pruned_gap::<Model64, full_variant!($kinematics)>, PRUNED_TOLERANCE;
                f64x4_lanes_equal_f64_bit_for_bit: spatial_case(CLASS, Pitch::Random), lanes_gap::<eom::models::$type<WideF64x4>, Model64, WideF64x4>, 0.0;
                f32x8_lanes_equal_f32_bit_for_bit: spatial_case(CLASS, Pitch::Random), lanes_gap::<eom::models::$type<WideF32x8>, Model32, WideF32x8>, 0.0;
            }
            euler_rates_near_vertical!($kinematics);

            #[test]
            fn refuses_a_tensor_whose_determinant_leaves_f64_as_the_generic_form_does() {
                // Valid tensors (1, 1.5, 2)·s of the class whose determinant underflows
                // (s = 1e-110) or overflows (s = 1e110): 1/det would make every rate NaN.
                for s in [1e-110, 1e110] {
                    // 0.1·s in every product the class keeps.
                    let keep = |name| if CLASS.pruned().contains(&name) { 0.0 } else { 0.1 * s };
                    let (ixy, iyz, izx) = (keep("Ixy"), keep("Iyz"), keep("Ixz"));
                    let tensor = InertiaTensor::new(s, 1.5 * s, 2.0 * s, ixy, iyz, izx).unwrap();
                    assert!(generic::RigidBody::<f64>::new(1.0, &tensor).is_err(), "s = {s:e}");
                    assert!(refuses_singular::<Model64>(&tensor), "s = {s:e}");
                }
            }
        }
    };
    (@item $($other:tt)*) => {};
}

eom::for_each_model!(spatial_properties);

#[test]
fn xz_variants_refuse_a_tensor_with_ixy_and_name_it() {
    let tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.1, 0.0, 0.2).unwrap();
    for result in [
        SpatialXzEuler::<f64>::new(1.0, &tensor).map(|_| ()),
        SpatialXzQuaternion::<f64>::new(1.0, &tensor).map(|_| ()),
    ] {
        let error = result.unwrap_err();
        assert!(matches!(
            error,
            ModelError::SymmetryClass {
                field: "Ixy",
                value: 0.1,
                class: "xz"
            }
        ));
        assert!(error.to_string().contains("Ixy"), "{error}");
    }
}

#[test]
fn pruned_variants_name_the_product_they_cannot_carry() {
    let iyz = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, -0.1, 0.2).unwrap();
    let error = SpatialXzEuler::<f64>::new(1.0, &iyz).unwrap_err();
    assert!(matches!(
        error,
        ModelError::SymmetryClass { field: "Iyz", .. }
    ));
    let izx = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.2).unwrap();
    let error = SpatialPrincipalQuaternion::<f64>::new(1.0, &izx).unwrap_err();
    assert!(matches!(
        error,
        ModelError::SymmetryClass {
            field: "Ixz",
            class: "principal",
            ..
        }
    ));
    // The full class carries every product, and the xz class carries I_xz.
    assert!(SpatialFullEuler::<f64>::new(1.0, &iyz).is_ok());
    assert!(SpatialXzQuaternion::<f64>::new(1.0, &izx).is_ok());
}

#[test]
fn both_pendulum_forms_take_one_parameter_set_which_refuses_a_pivot_inertia_below_m_h_squared() {
    // I₀ = 1 < M h² = 4: I_G = I₀ − M h² would be negative (4.29).
    let err = PendulumParameters::new(1.0, 1.0, 9.81, 2.0).unwrap_err();
    assert_eq!(err.field, "i0");
    // A simple pendulum, I₀ = M h² exactly, is accepted, and both forms are built from it.
    let simple = PendulumParameters::new(4.0, 1.0, 9.81, 2.0).unwrap();
    let ours = Pendulum::<f64>::new(&simple).rhs(&[1.0, 0.0], &[0.0]);
    let theirs = generic::Pendulum::<f64>::new(&simple).rhs(&[1.0, 0.0].into(), 0.0);
    // g/h sin 1, one rounding apart.
    assert!((ours[1] - theirs[1]).abs() <= 4.0 * f64::EPSILON * theirs[1].abs());
}

/// `S::new` on `tensor` must fail as the generic form does, with `SingularInertia`.
fn refuses_singular<S: Spatial<f64>>(tensor: &InertiaTensor) -> bool {
    matches!(
        S::build(1.0, tensor),
        Err(ModelError::SingularInertia { .. })
    )
}

/// A quaternion that has drifted off the unit sphere (as integrators let it) still gives the
/// track of the attitude it represents: the generated position rate is the sandwich
/// q v q* / |q|², the generic one normalises first.
#[test]
fn quaternion_track_is_independent_of_the_quaternion_length() {
    let tensor = eom::InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, -0.3).unwrap();
    let model = eom::models::SpatialXzQuaternion::<f64>::new(5.0, &tensor).unwrap();
    let q = nalgebra::UnitQuaternion::from_euler_angles(0.4, -1.2, 2.0);
    let unit = [
        1.0, -0.5, 0.3, 0.2, 0.1, -0.4, 0.0, 0.0, 0.0, q.w, q.i, q.j, q.k,
    ];
    let mut drifted = unit;
    for c in &mut drifted[9..] {
        *c *= 1.0 + 1e-3;
    }
    let (f, m) = ([1.0, 2.0, 3.0], [0.1, 0.2, 0.3]);
    let input = [f[0], f[1], f[2], m[0], m[1], m[2]];
    let (a, b) = (model.rhs(&unit, &input), model.rhs(&drifted, &input));
    // Both are f64 evaluations of one rotation of |v| ≈ 1.2: a few ulps.
    for i in 6..9 {
        assert!(
            (a[i] - b[i]).abs() < 1e-14,
            "component {i}: {} vs {}",
            a[i],
            b[i]
        );
    }
}
