//! The fuzz targets' `Rng`: libFuzzer's input read as the choices of
//! `tests/common/fuzz_cases.rs` (the generator `tests/fuzz.rs` seeds), so
//! that a mutation of the bytes is a mutation of the shapes. Each choice
//! takes as few bytes as its range needs; past the input's end every value
//! is zero.

pub struct Rng {
    bytes: Vec<u8>,
    at: usize,
}

impl Rng {
    pub fn new(bytes: &[u8]) -> Self {
        Self {
            bytes: bytes.to_vec(),
            at: 0,
        }
    }

    /// The next `n` bytes (zeros past the end), little-endian.
    fn take(&mut self, n: usize) -> u64 {
        let mut v = 0u64;
        for k in 0..n {
            let byte = self.bytes.get(self.at + k).copied().unwrap_or(0);
            v |= u64::from(byte) << (8 * k);
        }
        self.at = self.at.saturating_add(n);
        v
    }

    /// The next 64 bits. Named as the seeded generator's method, which
    /// the shared checks call: not an iterator.
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> u64 {
        self.take(8)
    }

    /// A value in `0..n` (`n > 0`), from the fewest bytes that reach `n`.
    pub fn below(&mut self, n: u64) -> i64 {
        let bytes = (64 - (n - 1).leading_zeros()).div_ceil(8).max(1) as usize;
        (self.take(bytes) % n) as i64
    }
}
