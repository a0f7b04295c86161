//! Bicubic Hermite patches: the bicubic on [0, 1]² with given positions, first partials
//! and twists at its four corners (Ferguson's patch; Farin, *Curves and Surfaces for
//! CAGD*, §16.3), written as a Bézier surface.
//!
//! In one variable the cubic with p(0), p′(0), p(1), p′(1) has the Bézier points
//! b₀ = p(0), b₁ = p(0) + p′(0)/3, b₂ = p(1) − p′(1)/3, b₃ = p(1). The tensor product of
//! this map in u and in v takes the corner data (S, S_u, S_v, S_uv) to the 4 × 4 net: at
//! the corner (a, b) ∈ {0, 1}², with σ = +1 at 0 and −1 at 1,
//! b_{3a, 3b} = S, b_{3a+σ_a, 3b} = S + σ_a S_u/3, b_{3a, 3b+σ_b} = S + σ_b S_v/3,
//! b_{3a+σ_a, 3b+σ_b} = S + σ_a S_u/3 + σ_b S_v/3 + σ_a σ_b S_uv/9.

use crate::Point;
use crate::error::{Error, Result};
use crate::surface::BezierSurface;

/// What a bicubic Hermite patch is given at one corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HermiteCorner<const D: usize> {
    /// S.
    pub point: Point<D>,
    /// ∂S/∂u.
    pub du: Point<D>,
    /// ∂S/∂v.
    pub dv: Point<D>,
    /// The twist ∂²S/∂u∂v.
    pub duv: Point<D>,
}

impl<const D: usize> BezierSurface<D> {
    /// The bicubic on [0, 1]² whose position, first partials and twist at the corner
    /// (u, v) = (a, b) are `corners[a][b]` (the module documentation gives the net). Every
    /// value must be finite (errors name `points`, `du`, `dv` or `duv`).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::surface::{BezierSurface, HermiteCorner, Surface};
    /// // The saddle (u, v, uv) from its corner data: reproduced exactly, being bicubic.
    /// let corner = |u: f64, v: f64| HermiteCorner {
    ///     point: Point::<3>::new(u, v, u * v),
    ///     du: Point::<3>::new(1.0, 0.0, v),
    ///     dv: Point::<3>::new(0.0, 1.0, u),
    ///     duv: Point::<3>::new(0.0, 0.0, 1.0),
    /// };
    /// let s = BezierSurface::bicubic_hermite([[corner(0.0, 0.0), corner(0.0, 1.0)], [corner(1.0, 0.0), corner(1.0, 1.0)]]).unwrap();
    /// assert!((s.point(0.3, 0.6) - Point::<3>::new(0.3, 0.6, 0.18)).norm() < 1e-15);
    /// ```
    pub fn bicubic_hermite(corners: [[HermiteCorner<D>; 2]; 2]) -> Result<Self> {
        for (a, row) in corners.iter().enumerate() {
            for (b, c) in row.iter().enumerate() {
                for (field, p) in [("points", c.point), ("du", c.du), ("dv", c.dv), ("duv", c.duv)] {
                    if let Some(x) = p.iter().find(|x| !x.is_finite()) {
                        return Err(Error::invalid(
                            format!("{field}[{a}][{b}]"),
                            format!("coordinate is not finite ({x})"),
                        ));
                    }
                }
            }
        }
        let mut net = vec![vec![Point::<D>::zeros(); 4]; 4];
        for (a, row) in corners.iter().enumerate() {
            for (b, c) in row.iter().enumerate() {
                let (su, sv) = (if a == 0 { 1.0 } else { -1.0 }, if b == 0 { 1.0 } else { -1.0 });
                let (i, j) = (3 * a, 3 * b);
                let (i1, j1) = (if a == 0 { 1 } else { 2 }, if b == 0 { 1 } else { 2 });
                net[i][j] = c.point;
                net[i1][j] = c.point + c.du * (su / 3.0);
                net[i][j1] = c.point + c.dv * (sv / 3.0);
                net[i1][j1] = c.point + c.du * (su / 3.0) + c.dv * (sv / 3.0) + c.duv * (su * sv / 9.0);
            }
        }
        BezierSurface::new(net)
    }
}
