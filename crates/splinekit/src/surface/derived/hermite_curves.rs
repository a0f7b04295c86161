//! Hermite surfaces from curves (GMlib's `PHermiteCurveSurf`): two boundary curves and
//! two cross-derivative curves, joined by cubic Hermite interpolation across them,
//!
//! S(u, v) = H₀(v) c₀(u) + H₁(v) c₁(u) + H₂(v) d₀(u) + H₃(v) d₁(u),  v ∈ [0, 1],
//!
//! with H₀ = 1 − 3v² + 2v³, H₁ = 3v² − 2v³, H₂ = v − 2v² + v³, H₃ = v³ − v², so that
//! S(u, 0) = c₀(u), S(u, 1) = c₁(u), S_v(u, 0) = d₀(u), S_v(u, 1) = d₁(u). Partials of
//! every order, ∂^{i,j}S = Σ H_k^{(j)}(v) (curve k)^{(i)}(u), exact given the curves'.

use smallvec::{SmallVec, smallvec};

use crate::basis::Side;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::surface::Surface;
use crate::{Interval, Point};

/// Two domains are one when their ends differ by at most this fraction of their size
/// (rounding of a domain computed from knots or turns, nothing more).
const SAME_DOMAIN_RELATIVE: f64 = 1e-12;

/// The cubic Hermite functions H₀ … H₃ and their derivatives of order `k` at v.
pub(crate) fn hermite_basis(v: f64, k: usize) -> [f64; 4] {
    let (v2, v3) = (v * v, v * v * v);
    match k {
        0 => [1.0 - 3.0 * v2 + 2.0 * v3, 3.0 * v2 - 2.0 * v3, v - 2.0 * v2 + v3, v3 - v2],
        1 => [6.0 * v2 - 6.0 * v, 6.0 * v - 6.0 * v2, 1.0 - 4.0 * v + 3.0 * v2, 3.0 * v2 - 2.0 * v],
        2 => [12.0 * v - 6.0, 6.0 - 12.0 * v, 6.0 * v - 4.0, 6.0 * v - 2.0],
        3 => [12.0, -12.0, 6.0, 6.0],
        _ => [0.0; 4],
    }
}

/// The Hermite surface of two boundary curves and two cross-derivative curves.
pub struct HermiteCurveSurface<const D: usize> {
    /// c₀, c₁, d₀, d₁.
    curves: [Box<dyn Curve<D>>; 4],
}

impl<const D: usize> HermiteCurveSurface<D> {
    /// The surface with S(u, 0) = `bottom`(u), S(u, 1) = `top`(u), S_v(u, 0) =
    /// `bottom_derivative`(u) and S_v(u, 1) = `top_derivative`(u), on the curves' common
    /// domain × [0, 1].
    ///
    /// The check (what makes the data a surface): the four domains are one (finite,
    /// non-empty, their ends equal to 10⁻¹² of their size), because the curves are
    /// evaluated at the same u; and the four curves are all closed or all open, because
    /// the surface is closed in u exactly when each of its v-rows is. Errors name the
    /// field that differs from `bottom`. There are no corner conditions: the surface
    /// interpolates in v only, so any four curves on one domain are consistent (the
    /// corner twist S_uv(u₀, 0) is d₀′(u₀), whatever it is).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{Curve, model::Line};
    /// use splinekit::surface::Surface;
    /// use splinekit::surface::derived::HermiteCurveSurface;
    /// let line = |a: [f64; 3], b: [f64; 3]| -> Box<dyn Curve<3>> { Box::new(Line::new(a.into(), b.into()).unwrap()) };
    /// // From z = 0 to z = 0 with slopes +1 and −1 across: the cylinder-like arch z = v − v².
    /// let s = HermiteCurveSurface::new(
    ///     line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
    ///     line([0.0, 1.0, 0.0], [1.0, 1.0, 0.0]),
    ///     line([0.0, 1.0, 1.0], [0.0, 1.0, 1.0]),
    ///     line([0.0, 1.0, -1.0], [0.0, 1.0, -1.0]),
    /// ).unwrap();
    /// assert!((s.point(0.25, 0.5) - Point::<3>::new(0.25, 0.5, 0.25)).norm() < 1e-15);
    /// ```
    pub fn new(
        bottom: Box<dyn Curve<D>>,
        top: Box<dyn Curve<D>>,
        bottom_derivative: Box<dyn Curve<D>>,
        top_derivative: Box<dyn Curve<D>>,
    ) -> Result<Self> {
        let d = bottom.domain();
        if !(d.start.is_finite() && d.end.is_finite() && d.start < d.end) {
            return Err(Error::invalid(
                "bottom",
                format!("the domain [{}, {}] must be finite and non-empty", d.start, d.end),
            ));
        }
        let slack = SAME_DOMAIN_RELATIVE * d.length().max(d.start.abs()).max(d.end.abs());
        for (name, c) in [("top", &top), ("bottom_derivative", &bottom_derivative), ("top_derivative", &top_derivative)]
        {
            let e = c.domain();
            if !((e.start - d.start).abs() <= slack && (e.end - d.end).abs() <= slack) {
                return Err(Error::invalid(
                    name,
                    format!(
                        "the curve's domain [{}, {}] differs from bottom's [{}, {}]: the four curves are evaluated at the same u, so their domains must be one",
                        e.start, e.end, d.start, d.end
                    ),
                ));
            }
            if c.is_closed() != bottom.is_closed() {
                let says = |b: bool| if b { "closed" } else { "open" };
                return Err(Error::invalid(
                    name,
                    format!(
                        "the curve is {} but bottom is {}: all four curves must be closed or all open",
                        says(c.is_closed()),
                        says(bottom.is_closed())
                    ),
                ));
            }
        }
        Ok(HermiteCurveSurface { curves: [bottom, top, bottom_derivative, top_derivative] })
    }
}

impl<const D: usize> Surface<D> for HermiteCurveSurface<D> {
    fn domain_u(&self) -> Interval {
        self.curves[0].domain()
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn is_closed_u(&self) -> bool {
        self.curves[0].is_closed()
    }
    /// The curves' breakpoints, merged.
    fn breakpoints_u(&self) -> Vec<f64> {
        let mut b: Vec<f64> = self.curves.iter().flat_map(|c| c.breakpoints()).collect();
        b.sort_by(f64::total_cmp);
        b.dedup();
        b
    }
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let v = v.clamp(0.0, 1.0);
        let mut c: SmallVec<[Point<D>; 16]> = smallvec![Point::<D>::zeros(); 4 * (du + 1)];
        for (k, curve) in self.curves.iter().enumerate() {
            curve.eval_side(u, Side::Right, &mut c[k * (du + 1)..(k + 1) * (du + 1)]);
        }
        for j in 0..=dv {
            let h = hermite_basis(v, j);
            for i in 0..=du {
                out[i * (dv + 1) + j] = (0..4).map(|k| c[k * (du + 1) + i] * h[k]).sum();
            }
        }
    }
}
