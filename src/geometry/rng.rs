//! A seeded pseudo-random number generator: the test data, the mesh sampler and the planner all
//! draw from it, so a seed names one run on every platform.

/// A small, fast, seeded pseudo-random number generator: xoshiro256\*\* seeded through SplitMix64.
///
/// Hand-written on purpose rather than taken from `rand`: the integer stream (and so
/// [`Rng::uniform`] and every generator that only uses it) is bit-for-bit identical on every
/// platform and for every future version of this crate, which an external crate does not promise
/// across its own releases, and it costs no dependency. Seeds recorded in tests, benchmark reports
/// and bug reports therefore stay meaningful.
///
/// [`Rng::normal`] uses `ln`, `sin` and `cos` from the platform's maths library, which may differ in
/// the last bit between platforms; what is built on it (the sphere, shell and lens point families)
/// is deterministic on one platform and agrees to
/// rounding across platforms.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rng {
    state: [u64; 4],
    /// The second normal deviate of the last Box–Muller pair, stored as bits to keep `Eq`.
    spare_normal: Option<u64>,
}

impl Rng {
    /// A generator whose whole stream is determined by `seed`.
    pub fn new(seed: u64) -> Self {
        // SplitMix64 spreads any seed (0 included) over the 256-bit state, as the xoshiro authors
        // recommend; the state can never be all zeros.
        let mut sm = seed;
        let mut next = || {
            sm = sm.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = sm;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        };
        Self {
            state: [next(), next(), next(), next()],
            spare_normal: None,
        }
    }

    /// The next 64 random bits (xoshiro256\*\*).
    pub fn next_u64(&mut self) -> u64 {
        let s = &mut self.state;
        let result = s[1].wrapping_mul(5).rotate_left(7).wrapping_mul(9);
        let t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = s[3].rotate_left(45);
        result
    }

    /// Uniform in `[0, 1)`, a multiple of `2^−53`.
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in `[lo, hi)` (up to rounding of `lo + (hi − lo)·u`).
    pub fn uniform_in(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }

    /// Uniform integer in `0..bound` (Lemire's multiply-shift; the bias, below `bound / 2^64`, is
    /// irrelevant here). Returns 0 when `bound` is 0.
    pub fn below(&mut self, bound: u64) -> u64 {
        ((u128::from(self.next_u64()) * u128::from(bound)) >> 64) as u64
    }

    /// Uniform index in `0..len`. Returns 0 when `len` is 0.
    pub fn index(&mut self, len: usize) -> usize {
        self.below(len as u64) as usize
    }

    /// A standard normal deviate (Box–Muller; the second value of each pair is kept for the next
    /// call).
    pub fn normal(&mut self) -> f64 {
        if let Some(bits) = self.spare_normal.take() {
            return f64::from_bits(bits);
        }
        let u1 = 1.0 - self.uniform(); // (0, 1]: ln is finite
        let u2 = self.uniform();
        let r = (-2.0 * u1.ln()).sqrt();
        let theta = std::f64::consts::TAU * u2;
        self.spare_normal = Some((r * theta.sin()).to_bits());
        r * theta.cos()
    }

    /// A uniformly distributed unit vector in `dimension` dimensions (a normalised Gaussian
    /// vector). For `dimension == 1` it is `[±1]`.
    pub fn unit_vector(&mut self, dimension: usize) -> Vec<f64> {
        loop {
            let v: Vec<f64> = (0..dimension).map(|_| self.normal()).collect();
            let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt();
            if norm > 1e-100 {
                return v.into_iter().map(|x| x / norm).collect();
            }
            if dimension == 0 {
                return v;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Rng;

    #[test]
    fn seeding_is_pinned() {
        // SplitMix64's published first output for seed 0 is 0xE220A8397B1DCDAF; the state seeding
        // must never change, or every recorded seed in the project changes meaning.
        assert_eq!(Rng::new(0).state[0], 0xE220_A839_7B1D_CDAF);
    }
}
