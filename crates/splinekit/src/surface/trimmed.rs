//! Trimmed surfaces: a surface restricted to the region of its parameter domain inside an
//! outer trimming loop and outside any holes. Loops are closed 2-D curves in (u, v).
//!
//! Evaluation is the underlying surface's (trimming changes the region, not the shape);
//! [`TrimmedSurface::contains`] tests a parameter pair with the non-zero winding rule
//! against each loop, flattened to 64 segments per piece between breakpoints (and at
//! least 512 per loop).

use crate::Point;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result};
use crate::surface::Surface;
use crate::tolerance::JOIN_RELATIVE;

/// A surface with trimming loops in its parameter domain.
pub struct TrimmedSurface<const D: usize> {
    surface: Box<dyn Surface<D>>,
    outer: Option<Vec<Point<2>>>,
    holes: Vec<Vec<Point<2>>>,
}

fn flatten(curve: &dyn Curve<2>, field: &str) -> Result<Vec<Point<2>>> {
    let d = curve.domain();
    let (a, b) = (curve.point(d.start), curve.point(d.end));
    let scale = a.norm().max(b.norm()).max(1.0);
    if !curve.is_closed() && (a - b).norm() > JOIN_RELATIVE * scale {
        return Err(Error::invalid(
            field,
            format!("a trimming loop must be closed, but its ends are {} apart", (a - b).norm()),
        ));
    }
    let bps = curve.breakpoints();
    let per = (512 / (bps.len() - 1).max(1)).max(64);
    let mut pts = Vec::new();
    for w in bps.windows(2) {
        for k in 0..per {
            pts.push(curve.point(w[0] + (w[1] - w[0]) * k as f64 / per as f64));
        }
    }
    Ok(pts)
}

/// Winding number of the closed polygon around p.
fn winding(poly: &[Point<2>], p: &Point<2>) -> i32 {
    let mut w = 0;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let cross = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
        if a[1] <= p[1] {
            if b[1] > p[1] && cross > 0.0 {
                w += 1;
            }
        } else if b[1] <= p[1] && cross < 0.0 {
            w -= 1;
        }
    }
    w
}

impl<const D: usize> TrimmedSurface<D> {
    /// Trims `surface` to the inside of `outer` (whole domain if `None`) minus the holes.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{CircleFrame, NurbsCurve};
    /// use splinekit::surface::TrimmedSurface;
    /// use splinekit::surface::model::Plane;
    /// // The unit square of a plane with a round hole of radius 0.2 in the middle.
    /// let plane = Plane::new(Point::<3>::zeros(), Point::<3>::x(), Point::<3>::y()).unwrap();
    /// let hole = NurbsCurve::circle(&CircleFrame::in_xy_plane(Point::<2>::new(0.5, 0.5), 0.2)).unwrap();
    /// let s = TrimmedSurface::new(Box::new(plane), None, &[&hole]).unwrap();
    /// assert!(!s.contains(0.5, 0.5) && !s.contains(0.6, 0.5));
    /// assert!(s.contains(0.1, 0.1) && s.contains(0.75, 0.5));
    /// ```
    pub fn new(surface: Box<dyn Surface<D>>, outer: Option<&dyn Curve<2>>, holes: &[&dyn Curve<2>]) -> Result<Self> {
        let outer = outer.map(|c| flatten(c, "outer")).transpose()?;
        let holes =
            holes.iter().enumerate().map(|(i, c)| flatten(*c, &format!("holes[{i}]"))).collect::<Result<_>>()?;
        Ok(TrimmedSurface { surface, outer, holes })
    }

    /// Whether (u, v) lies in the trimmed region. Where the surface is closed, a loop may
    /// cross the seam (run past the domain's end, e.g. around a torus' tube through v = 0):
    /// the point counts as inside a loop when it, or its copy one period to either side,
    /// is.
    pub fn contains(&self, u: f64, v: f64) -> bool {
        let (du, dv) = (self.surface.domain_u(), self.surface.domain_v());
        if u < du.start || u > du.end || v < dv.start || v > dv.end {
            return false;
        }
        let shifts = |closed: bool, d: Interval| if closed { vec![0.0, -d.length(), d.length()] } else { vec![0.0] };
        let (su, sv) = (shifts(self.surface.is_closed_u(), du), shifts(self.surface.is_closed_v(), dv));
        let within = |poly: &[Point<2>]| {
            su.iter().any(|a| sv.iter().any(|b| winding(poly, &Point::<2>::new(u + a, v + b)) != 0))
        };
        if let Some(o) = &self.outer {
            if !within(o) {
                return false;
            }
        }
        self.holes.iter().all(|h| !within(h))
    }

    /// The flattened outer loop and holes (for tessellation).
    pub fn loops(&self) -> (Option<&[Point<2>]>, Vec<&[Point<2>]>) {
        (self.outer.as_deref(), self.holes.iter().map(|h| h.as_slice()).collect())
    }
}

/// The base surface's geometry, every method forwarded (its fast grids, its closed-form
/// normals and curvatures, its breakpoints and its enclosing box: the box of the whole
/// surface holds the trimmed part); the trim is the trimmed surface's own. `subdivision` is
/// not forwarded: a subdivision limit drawn from its cage would lose the trim.
impl<const D: usize> Surface<D> for TrimmedSurface<D> {
    crate::wrapped_surface_domains!(surface);
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        self.surface.eval_partials(u, v, du, dv, out)
    }
    fn eval_grid(&self, us: &[f64], vs: &[f64], du: usize, dv: usize, out: &mut [Point<D>]) {
        self.surface.eval_grid(us, vs, du, dv, out)
    }
    fn eval_grid_with_normals(&self, us: &[f64], vs: &[f64], points: &mut [Point<D>], normals: &mut [Point<D>]) {
        self.surface.eval_grid_with_normals(us, vs, points, normals)
    }
    fn point(&self, u: f64, v: f64) -> Point<D> {
        self.surface.point(u, v)
    }
    fn partial(&self, u: f64, v: f64, i: usize, j: usize) -> Point<D> {
        self.surface.partial(u, v, i, j)
    }
    fn normal(&self, u: f64, v: f64) -> Option<Point<D>> {
        self.surface.normal(u, v)
    }
    fn fundamental_forms(&self, u: f64, v: f64) -> Option<crate::surface::FundamentalForms> {
        self.surface.fundamental_forms(u, v)
    }
    fn curvatures(&self, u: f64, v: f64) -> Option<crate::surface::Curvatures> {
        self.surface.curvatures(u, v)
    }
    fn breakpoints_u(&self) -> Vec<f64> {
        self.surface.breakpoints_u()
    }
    fn breakpoints_v(&self) -> Vec<f64> {
        self.surface.breakpoints_v()
    }
    fn enclosing_box(&self) -> Option<crate::query::Aabb<D>> {
        self.surface.enclosing_box()
    }
    fn trim_contains(&self, u: f64, v: f64) -> Option<bool> {
        Some(self.contains(u, v))
    }
    fn trim_loops(&self) -> Option<crate::surface::traits::TrimLoops<'_>> {
        let (outer, holes) = self.loops();
        Some(crate::surface::traits::TrimLoops { outer, holes })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::{CircleFrame, NurbsCurve};
    use crate::surface::model::{Plane, Torus};
    use std::f64::consts::TAU;

    #[test]
    fn loops_across_a_seam_trim_both_sides_of_it() {
        // A disc of radius 0.5 about (1, 0) on the torus: it crosses the tube's seam
        // v = 0, so it holds (1, 0.3) and (1, 2π − 0.3) but not (1, 0.6) or (1, 2π − 0.6).
        let disc = NurbsCurve::circle(&CircleFrame::in_xy_plane(Point::<2>::new(1.0, 0.0), 0.5)).unwrap();
        let torus = || Box::new(Torus::new(3.0, 1.0).unwrap());
        let face = TrimmedSurface::new(torus(), Some(&disc), &[]).unwrap();
        for (v, inside) in [(0.3, true), (TAU - 0.3, true), (0.0, true), (TAU, true), (0.6, false), (TAU - 0.6, false)]
        {
            assert_eq!(face.contains(1.0, v), inside, "v = {v}");
        }
        // As a hole, the same disc takes both sides away.
        let holed = TrimmedSurface::new(torus(), None, &[&disc]).unwrap();
        for (v, inside) in [(0.3, false), (TAU - 0.3, false), (0.6, true), (3.0, true)] {
            assert_eq!(holed.contains(1.0, v), inside, "v = {v}");
        }
        // A surface open in v has no seam: only the part inside the domain counts.
        let plane = Plane::new(Point::<3>::zeros(), Point::<3>::x(), Point::<3>::y()).unwrap();
        let flat = TrimmedSurface::new(Box::new(plane), Some(&disc), &[]).unwrap();
        assert!(flat.contains(0.9, 0.3) && !flat.contains(0.9, 0.95));
    }
}
