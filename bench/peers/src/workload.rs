//! The curve workload every binary here shares: a clamped uniform cubic 3-D B-spline
//! (`knots`, `control`) with N or N_LARGE control points, and M parameters in random order
//! (xorshift) and sorted (`params`).

/// Control points of the curve.
pub const N: usize = 1000;
/// Parameters per run.
pub const M: usize = 1_000_000;
/// Control points of the large curve.
pub const N_LARGE: usize = 100_000;

/// Control point i.
pub fn control(i: usize) -> [f64; 3] {
    let x = i as f64;
    [x, (x * 0.37).sin(), (x * 0.11).cos()]
}

/// The clamped uniform cubic knots of n control points on [0, 1].
pub fn knots(n: usize) -> Vec<f64> {
    let p = 3;
    let mut k = vec![0.0; p + 1];
    for i in 1..n - p {
        k.push(i as f64 / (n - p) as f64);
    }
    k.extend([1.0; 4]);
    k
}

/// M parameters in [0, 1): random (xorshift from a fixed seed) and sorted.
pub fn params() -> (Vec<f64>, Vec<f64>) {
    let mut s = 0x9E3779B97F4A7C15u64;
    let random = (0..M)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect();
    let sorted = (0..M).map(|i| i as f64 / (M - 1) as f64).collect();
    (random, sorted)
}
