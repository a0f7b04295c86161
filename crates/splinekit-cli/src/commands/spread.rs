//! Parameters spread evenly over a domain, ends included: tᵢ = start + (end − start)·i/(n − 1)
//! for 0 < i < n − 1, with t₀ and tₙ₋₁ the domain's ends exactly. Shared by `splinekit eval` on curves
//! (`--samples`) and on surfaces (`--grid`).

use splinekit::curve::Interval;

/// Sample i of n spread evenly over `dom`, ends included.
pub(crate) fn spread(i: usize, n: usize, dom: Interval) -> f64 {
    if n == 1 || i == 0 {
        dom.start
    } else if i + 1 == n {
        dom.end
    } else {
        dom.lerp(i as f64 / (n - 1) as f64)
    }
}
