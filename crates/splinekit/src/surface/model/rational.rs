//! Surfaces whose coordinates are quotients of separable sums, plus a separable sum:
//! x_c = P_c + N_c / D_c with P_c, N_c, D_c each Σ a·f(u)·g(v) (Kuen's surface, the Boy
//! surface, the trianguloid trefoil).
//!
//! The partials of every order come from Taylor mode in two variables: the coefficients
//! f⁽ⁱ⁾(u) g⁽ʲ⁾(v) / (i! j!) of N and D (exact, [`super::separable::Factor`]), divided as
//! truncated series ([`crate::taylor::div2`]), times i! j!.

use super::separable::{SeparableTerm, in_domain};
use crate::Point;
use crate::curve::Interval;
use crate::curve::model::trig::SinCosCache;
use smallvec::SmallVec;

/// One coordinate: Σ `plus` + (Σ `numerator`) / (Σ `denominator`); an empty denominator
/// leaves the separable part alone.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RationalCoordinate {
    /// The separable part P.
    pub plus: Vec<SeparableTerm>,
    /// The numerator N.
    pub numerator: Vec<SeparableTerm>,
    /// The denominator D, which must not vanish on the domain.
    pub denominator: Vec<SeparableTerm>,
}

/// A 3-D surface with rational-separable coordinates over a domain.
#[derive(Debug, Clone, PartialEq)]
pub struct RationalSurface {
    /// x, y and z.
    pub coordinates: [RationalCoordinate; 3],
    /// u-domain.
    pub domain_u: Interval,
    /// v-domain.
    pub domain_v: Interval,
    /// Closed (periodic) in u.
    pub closed_u: bool,
    /// Closed (periodic) in v.
    pub closed_v: bool,
}

type Coefficients = SmallVec<[f64; 16]>;

/// Adds the normalised coefficients f⁽ⁱ⁾(u) g⁽ʲ⁾(v) / (i! j!) of `terms` to `out`
/// ((du + 1) × (dv + 1), row-major).
fn add_coefficients(
    terms: &[SeparableTerm],
    (u, v): (f64, f64),
    (du, dv): (usize, usize),
    out: &mut [f64],
    cache: &mut SinCosCache,
) {
    let (mut fu, mut gv) = (SmallVec::<[f64; 8]>::from_elem(0.0, du + 1), SmallVec::<[f64; 8]>::from_elem(0.0, dv + 1));
    for t in terms {
        t.u.derivatives_cached(u, &mut fu, cache);
        t.v.derivatives_cached(v, &mut gv, cache);
        let mut fact_i = 1.0;
        for i in 0..=du {
            if i > 0 {
                fact_i *= i as f64;
            }
            let mut fact_j = 1.0;
            for j in 0..=dv {
                if j > 0 {
                    fact_j *= j as f64;
                }
                out[i * (dv + 1) + j] += t.coefficient * fu[i] * gv[j] / (fact_i * fact_j);
            }
        }
    }
}

impl RationalSurface {
    /// Writes the partials (layout of [`crate::surface::Surface::eval_partials`]).
    pub fn eval_into(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let (u, v) = (in_domain(self.domain_u, self.closed_u, u), in_domain(self.domain_v, self.closed_v, v));
        let count = (du + 1) * (dv + 1);
        let mut cache = SinCosCache::default();
        for (c, coordinate) in self.coordinates.iter().enumerate() {
            let mut value = Coefficients::from_elem(0.0, count);
            add_coefficients(&coordinate.plus, (u, v), (du, dv), &mut value, &mut cache);
            if !coordinate.denominator.is_empty() {
                let (mut n, mut d) = (Coefficients::from_elem(0.0, count), Coefficients::from_elem(0.0, count));
                add_coefficients(&coordinate.numerator, (u, v), (du, dv), &mut n, &mut cache);
                add_coefficients(&coordinate.denominator, (u, v), (du, dv), &mut d, &mut cache);
                let mut q = Coefficients::from_elem(0.0, count);
                crate::taylor::div2(&n, &d, dv + 1, &mut q);
                for (s, q) in value.iter_mut().zip(&q) {
                    *s += q;
                }
            }
            let mut fact_i = 1.0;
            for i in 0..=du {
                if i > 0 {
                    fact_i *= i as f64;
                }
                let mut fact_j = 1.0;
                for j in 0..=dv {
                    if j > 0 {
                        fact_j *= j as f64;
                    }
                    out[i * (dv + 1) + j][c] = value[i * (dv + 1) + j] * fact_i * fact_j;
                }
            }
        }
    }
}
