//! Fixed pseudo-random angles for the kernel tests, included by path.

/// A fixed sequence of uniform numbers in [0, 1) (xorshift64), so every run checks the same
/// points.
pub fn uniform(count: usize, seed: u64) -> impl Iterator<Item = f64> {
    let mut state = seed;
    (0..count).map(move |_| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    })
}
