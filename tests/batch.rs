//! A batch of bodies in SIMD lanes steps each body as the scalar RK4 does, bit for bit: the
//! same tableau, the same arithmetic in each lane, the kernel's sines and cosines the scalar
//! kernel's. Seven bodies, so that the last group of four has an empty lane and the last of
//! eight is short.

use eom::batch::Batch;
use eom::models::{Model, SpatialFullEuler, SpatialXzQuaternion};
use eom::{Constant, InertiaTensor, Integrator, Rk4};
use simba::scalar::SupersetOf;
use simba::simd::{SimdRealField, WideF32x8, WideF64x4};

fn tensor() -> InertiaTensor {
    InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.2).unwrap()
}

/// Seven bodies: the velocities, rates and attitudes differ from body to body; N = 13 with a
/// quaternion, 12 with Euler angles.
fn starts<const N: usize>() -> Vec<[f64; N]> {
    let quaternion = N == 13;
    (0..7)
        .map(|i| {
            let f = f64::from(i);
            let mut y = [0.0; 13];
            y[..6].copy_from_slice(&[1.0 + f, -0.2 * f, 0.1, 0.3 - 0.1 * f, 1.5, -0.7 + 0.2 * f]);
            let attitude = nalgebra::UnitQuaternion::from_euler_angles(0.3 * f, -0.2, 1.0 - f);
            if quaternion {
                y[9..13].copy_from_slice(&[attitude.w, attitude.i, attitude.j, attitude.k]);
            } else {
                let (roll, pitch, yaw) = attitude.euler_angles();
                y[9..12].copy_from_slice(&[roll, pitch, yaw]);
            }
            std::array::from_fn(|i| y[i])
        })
        .collect()
}

const INPUT: [f64; 6] = [3.0, -1.0, 0.5, 0.2, -0.1, 0.4];

/// The batch in lanes of `T` against scalar RK4 on each body in `E`, 200 steps of 0.01 s.
fn lanes_match_scalar<Mo, Ms, T, const N: usize>(
    lanes: &Mo,
    scalar: &Ms,
    starts: &[[T::Element; N]],
) where
    T: SimdRealField + Copy,
    T::Element: nalgebra::RealField + Copy,
    Mo: Model<T, N, 6>,
    Ms: Model<T::Element, N, 6>,
{
    let h = 0.01;
    let input = INPUT.map(|x| T::Element::from_subset(&x));
    let mut batch = Batch::<T, N>::new(starts);
    for step in 0..200 {
        batch.step_rk4(
            lanes,
            &Constant(input.map(T::splat)),
            f64::from(step) * h,
            h,
        );
    }
    for (body, start) in starts.iter().enumerate() {
        let mut rk4 = Rk4::new(h);
        let end_time = T::Element::from_subset(&(200.0 * h));
        let driven = scalar.driven_by(Constant(input));
        let zero = T::Element::from_subset(&0.0);
        let end = rk4
            .integrate(&driven, zero, (*start).into(), end_time)
            .unwrap();
        assert_eq!(batch.state(body), end.data.0[0], "body {body}");
    }
}

#[test]
fn f64_lanes_step_each_body_as_scalar_rk4() {
    let tensor = tensor();
    let lanes = SpatialXzQuaternion::<WideF64x4>::new(5.0, &tensor).unwrap();
    let scalar = SpatialXzQuaternion::<f64>::new(5.0, &tensor).unwrap();
    lanes_match_scalar(&lanes, &scalar, &starts());
    let lanes = SpatialFullEuler::<WideF64x4>::new(5.0, &tensor).unwrap();
    let scalar = SpatialFullEuler::<f64>::new(5.0, &tensor).unwrap();
    lanes_match_scalar(&lanes, &scalar, &starts());
}

#[test]
fn f32_lanes_step_each_body_as_scalar_rk4() {
    let tensor = tensor();
    fn narrow<const N: usize>(starts: Vec<[f64; N]>) -> Vec<[f32; N]> {
        starts.iter().map(|y| y.map(|x| x as f32)).collect()
    }
    let lanes = SpatialXzQuaternion::<WideF32x8>::new(5.0, &tensor).unwrap();
    let scalar = SpatialXzQuaternion::<f32>::new(5.0, &tensor).unwrap();
    lanes_match_scalar(&lanes, &scalar, &narrow(starts()));
    let lanes = SpatialFullEuler::<WideF32x8>::new(5.0, &tensor).unwrap();
    let scalar = SpatialFullEuler::<f32>::new(5.0, &tensor).unwrap();
    lanes_match_scalar(&lanes, &scalar, &narrow(starts()));
}

#[test]
fn a_batch_gives_back_its_bodies_in_order() {
    let starts = starts::<13>();
    let batch = Batch::<WideF64x4, 13>::new(&starts);
    assert_eq!(batch.bodies(), 7);
    assert_eq!(batch.states(), starts);
}
