//! The Mariner's turning circles in lanes, as the lanes' bench, test and `calls` run them: the
//! rudder orders and the steering gear, written branch-free so that each lane clamps its own.

/// The rudder orders of the lanes' turning circles, degrees to port: case `i` takes the
/// `i % 4`th, so that each lane of a group of four has its own.
pub const RUDDER_ORDERS_DEG: [f64; 4] = [20.0, 25.0, 30.0, 35.0];

/// The inputs `[δ̇, U]` of the compiled Mariner: `scenes/mariner.toml`'s steering gear
/// δ̇ = clamp((δ_c − δ)/T_δ, ±δ̇_max), T_δ = 1 s, δ̇_max = 5°/s, towards `order`, written
/// branch-free so that each lane clamps its own, and the speed U = √(u² + v²) as `eom`'s ship
/// model computes it.
pub fn steering_gear<T: simba::simd::SimdRealField + Copy>(
    order: T,
) -> impl Fn(T, &[T; 7]) -> [T; 2] {
    let lag = T::from_subset(&1.0);
    let max = T::from_subset(&(5.0 * std::f64::consts::PI / 180.0));
    move |_, y| {
        let rate = ((order - y[6]) / lag).simd_clamp(-max, max);
        [rate, (y[0] * y[0] + y[1] * y[1]).simd_sqrt()]
    }
}
