//! A deterministic stream of numbers for the unit tests' random cases.

/// xorshift64 (Marsaglia): a deterministic stream in [0, 1) from a nonzero `seed`; the
/// top 53 bits of each state as the mantissa of a uniform double.
pub fn stream(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    }
}
