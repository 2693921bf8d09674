//! The f32 kernel's error in ulps of the correctly rounded sine and cosine, shared by
//! `tests/sin_cos_f32.rs` (a sample of angles) and `examples/f32_exhaustive.rs` (all of them),
//! which include this file by path.

/// The kernel on one angle.
pub fn sin_cos(x: f32) -> (f32, f32) {
    let [pair] = eom_kernel::sin_cos([x]);
    pair
}

/// How many f32 lie between `a` and `b` (0 if equal, ±0 counted as one, NaN as equal to NaN).
pub fn ulps_apart(a: f32, b: f32) -> u32 {
    if a.is_nan() && b.is_nan() {
        return 0;
    }
    let ordered = |v: f32| {
        let bits = v.to_bits() as i32;
        i64::from(if bits < 0 { i32::MIN - bits } else { bits })
    };
    (ordered(a) - ordered(b)).unsigned_abs() as u32
}

/// The larger of the two errors of the kernel at `x`, in f32 ulps of the correctly rounded
/// pair.
pub fn error_in_ulps(x: f32) -> u32 {
    let (s, c) = sin_cos(x);
    let (s0, c0) = f64::from(x).sin_cos();
    ulps_apart(s, s0 as f32).max(ulps_apart(c, c0 as f32))
}
