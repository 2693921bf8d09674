//! The feature `platform-trig`: `sin_cos` is each scalar's own `simd_sin_cos`, bit for bit.
#![cfg(feature = "platform-trig")]

use num_dual::Dual64;
use simba::simd::{SimdComplexField, WideF64x4};

#[test]
fn every_scalar_gets_its_own_sine_and_cosine() {
    let angles: [f64; 5] = [0.3, -2.5, 1e7, -1e-12, 700.0];
    for (x, pair) in angles.into_iter().zip(eom_kernel::sin_cos(angles)) {
        assert_eq!(pair, x.sin_cos(), "x = {x:e}");
        let x32 = x as f32;
        assert_eq!(eom_kernel::sin_cos([x32]), [x32.sin_cos()], "x = {x32:e}");
    }
    let dual = Dual64::new(0.7, 1.0);
    assert_eq!(eom_kernel::sin_cos([dual]), [dual.simd_sin_cos()]);
    let lanes = WideF64x4::from([0.1, -2.0, 40.0, 1e3]);
    assert_eq!(eom_kernel::sin_cos([lanes]), [lanes.simd_sin_cos()]);
}
