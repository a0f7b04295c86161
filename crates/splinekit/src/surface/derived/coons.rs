//! Coons patches: the surface on [0, 1]² spanned by four boundary curves
//! S(u, 0) = c₀(u), S(u, 1) = c₁(u), S(0, v) = d₀(v), S(1, v) = d₁(v):
//!
//! S = F₀(v)c₀(u) + F₁(v)c₁(u) + F₀(u)d₀(v) + F₁(u)d₁(v) − Σ_{a,b} F_a(u)F_b(v)P_ab,
//!
//! with F₀ = 1 − t, F₁ = t (bilinearly blended) or F₀ = 1 − 3t² + 2t³, F₁ = 3t² − 2t³
//! (bicubically blended, cross-boundary derivatives taken from the boundary curves only).

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::curve::{Curve, Reparametrized};
use crate::error::{Error, Result};
use crate::surface::Surface;
use crate::tolerance::JOIN_RELATIVE;

/// The blending functions of a Coons patch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoonsBlend {
    /// F₀ = 1 − t, F₁ = t.
    Linear,
    /// F₀ = 1 − 3t² + 2t³, F₁ = 3t² − 2t³.
    Cubic,
}

impl CoonsBlend {
    /// F_which^{(k)}(t).
    fn value(self, which: usize, t: f64, k: usize) -> f64 {
        let f1 = match (self, k) {
            (CoonsBlend::Linear, 0) => t,
            (CoonsBlend::Linear, 1) => 1.0,
            (CoonsBlend::Linear, _) => 0.0,
            (CoonsBlend::Cubic, 0) => t * t * (3.0 - 2.0 * t),
            (CoonsBlend::Cubic, 1) => 6.0 * t * (1.0 - t),
            (CoonsBlend::Cubic, 2) => 6.0 - 12.0 * t,
            (CoonsBlend::Cubic, 3) => -12.0,
            (CoonsBlend::Cubic, _) => 0.0,
        };
        if which == 1 {
            f1
        } else if k == 0 {
            1.0 - f1
        } else {
            -f1
        }
    }
}

/// A boundary curve reparametrised to [0, 1].
type UnitCurve<const D: usize> = Reparametrized<Box<dyn Curve<D>>>;

/// A Coons patch from four boundary curves (each reparametrised to [0, 1]).
pub struct CoonsPatch<const D: usize> {
    bottom: UnitCurve<D>,
    top: UnitCurve<D>,
    left: UnitCurve<D>,
    right: UnitCurve<D>,
    corners: [[Point<D>; 2]; 2],
    blend: CoonsBlend,
}

impl<const D: usize> CoonsPatch<D> {
    /// The patch with boundaries bottom (v = 0), top (v = 1), left (u = 0), right
    /// (u = 1). Their ends must meet at the four corners.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Line;
    /// use splinekit::surface::Surface;
    /// use splinekit::surface::derived::{CoonsBlend, CoonsPatch};
    /// // Four straight boundaries of the saddle z = uv: the bilinear Coons patch is the saddle.
    /// let corner = |u: f64, v: f64| Point::<3>::new(u, v, u * v);
    /// let line = |a, b| -> Box<dyn Curve<3>> { Box::new(Line::new(a, b).unwrap()) };
    /// let s = CoonsPatch::new(
    ///     line(corner(0.0, 0.0), corner(1.0, 0.0)),
    ///     line(corner(0.0, 1.0), corner(1.0, 1.0)),
    ///     line(corner(0.0, 0.0), corner(0.0, 1.0)),
    ///     line(corner(1.0, 0.0), corner(1.0, 1.0)),
    ///     CoonsBlend::Linear,
    /// )
    /// .unwrap();
    /// assert!((s.point(0.3, 0.6) - corner(0.3, 0.6)).norm() < 1e-15);
    /// ```
    pub fn new(
        bottom: Box<dyn Curve<D>>,
        top: Box<dyn Curve<D>>,
        left: Box<dyn Curve<D>>,
        right: Box<dyn Curve<D>>,
        blend: CoonsBlend,
    ) -> Result<Self> {
        let [bottom, top, left, right] = [bottom, top, left, right].map(Reparametrized::unit);
        let (bottom, top, left, right) = (bottom?, top?, left?, right?);
        let pairs = [
            ("bottom start and left start", bottom.point(0.0), left.point(0.0)),
            ("bottom end and right start", bottom.point(1.0), right.point(0.0)),
            ("top start and left end", top.point(0.0), left.point(1.0)),
            ("top end and right end", top.point(1.0), right.point(1.0)),
        ];
        let scale = pairs.iter().map(|p| p.1.norm()).fold(1.0, f64::max);
        for (name, a, b) in &pairs {
            if (a - b).norm() > JOIN_RELATIVE * scale {
                return Err(Error::invalid("corners", format!("{name} must meet, but are {} apart", (a - b).norm())));
            }
        }
        let corners = [[pairs[0].1, pairs[2].1], [pairs[1].1, pairs[3].1]];
        Ok(CoonsPatch { bottom, top, left, right, corners, blend })
    }
}

impl<const D: usize> Surface<D> for CoonsPatch<D> {
    crate::surface::unit_square::unit_square_domains!();
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = (u.clamp(0.0, 1.0), v.clamp(0.0, 1.0));
        let jet = |c: &UnitCurve<D>, t: f64, order: usize| {
            let mut out: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); order + 1];
            c.eval(t, &mut out);
            out
        };
        let (c0, c1) = (jet(&self.bottom, u, du), jet(&self.top, u, du));
        let (d0, d1) = (jet(&self.left, v, dv), jet(&self.right, v, dv));
        let f = |w: usize, t: f64, k: usize| self.blend.value(w, t, k);
        for i in 0..=du {
            for j in 0..=dv {
                let mut s = c0[i] * f(0, v, j) + c1[i] * f(1, v, j) + d0[j] * f(0, u, i) + d1[j] * f(1, u, i);
                for a in 0..2 {
                    for b in 0..2 {
                        s -= self.corners[a][b] * (f(a, u, i) * f(b, v, j));
                    }
                }
                out[i * (dv + 1) + j] = s;
            }
        }
    }
}
