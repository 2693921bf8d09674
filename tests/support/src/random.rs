//! splitmix64 (Sebastiano Vigna): a small, fast stream of draws that is the same on every
//! machine, for the tests that want many fixed random inputs without a dependency.

/// A splitmix64 stream from its seed.
pub struct Random(pub u64);

impl Random {
    /// The next 64 random bits.
    // A stream that never ends, drawn from by hand: not an iterator.
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1), from the top 53 bits.
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// In 0..n, as the remainder of the next 64 bits.
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    /// +1 or −1, evenly.
    pub fn sign(&mut self) -> f64 {
        if self.next() & 1 == 0 { 1.0 } else { -1.0 }
    }
}
