//! A small deterministic generator (xorshift64*), shared by tests and
//! benchmarks that need fixed pseudo-random inputs.

/// xorshift64*: a fixed, dependency-free sequence.
pub struct Rng(pub u64);

impl Rng {
    /// The next 64 bits.
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// Uniform in `0..n` (slightly biased for huge `n`; fine for tests).
    #[allow(dead_code)]
    pub fn below(&mut self, n: u64) -> i64 {
        (self.next() % n) as i64
    }

    /// Uniform in `[0, 1)`.
    #[allow(dead_code)]
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}
