//! Lofting (skinning): a B-spline surface through a sequence of section curves
//! (NURBS Book §10.3). The sections are made compatible — clamped, knots mapped to
//! [0, 1], raised to a common degree, refined to a common knot vector — and then every
//! column of corresponding control points is interpolated across the sections.

use crate::Point;
use crate::curve::BSplineCurve;
use crate::error::{Error, Result};
use crate::fit::lsq::{FitWithKnotsOptions, fit_with_knots};
use crate::fit::parametrize::{Parametrization, parametrize};
use crate::surface::BSplineSurface;

/// Knots of `c` (clamped) mapped affinely to [0, 1].
fn unit_knots<const D: usize>(c: &BSplineCurve<D>) -> Result<BSplineCurve<D>> {
    let c = c.clamped()?;
    let k = c.knots();
    let (a, b) = (k[0], k[k.len() - 1]);
    BSplineCurve::new(c.degree(), k.iter().map(|x| (x - a) / (b - a)).collect(), c.control_points().to_vec())
}

impl<const D: usize> BSplineSurface<D> {
    /// The surface through the `sections` (u runs along each section, v across them):
    /// S(u, v_k) = section_k(u) at parameters v_k from the section control polygons
    /// (`params`, averaged over the columns), with interpolation of degree `degree_v` in v.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::BSplineCurve;
    /// use splinekit::fit::Parametrization;
    /// use splinekit::surface::{BSplineSurface, Surface};
    /// // Two straight sections, lofted linearly in v: the ruled surface between them.
    /// let p = |x, y, z| Point::<3>::new(x, y, z);
    /// let bottom = BSplineCurve::clamped_uniform(1, vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)]).unwrap();
    /// let top = BSplineCurve::clamped_uniform(1, vec![p(0.0, 1.0, 1.0), p(1.0, 1.0, 1.0)]).unwrap();
    /// let s = BSplineSurface::loft(&[bottom, top], 1, Parametrization::ChordLength).unwrap();
    /// assert!((s.point(0.5, 0.5) - p(0.5, 0.5, 0.5)).norm() < 1e-15);
    /// ```
    pub fn loft(sections: &[BSplineCurve<D>], degree_v: usize, params: Parametrization) -> Result<Self> {
        let k = sections.len();
        if k < 2 {
            return Err(Error::count("sections", "at least 2 curves", k));
        }
        if degree_v == 0 || degree_v >= k {
            return Err(Error::invalid(
                "degree_v",
                format!("must be between 1 and {} for {k} sections, got {degree_v}", k - 1),
            ));
        }
        let mut curves: Vec<BSplineCurve<D>> = sections.iter().map(unit_knots).collect::<Result<_>>()?;
        let p = curves.iter().map(|c| c.degree()).max().unwrap();
        for c in curves.iter_mut() {
            if c.degree() < p {
                *c = c.elevate_degree(p - c.degree())?;
            }
        }
        // Common knots: every interior value with its largest multiplicity.
        let mut merged: Vec<f64> = Vec::new();
        for c in &curves {
            let kn = c.knots();
            let mut i = p + 1;
            while i < kn.len() - p - 1 {
                let x = kn[i];
                let m = kn.iter().filter(|&&y| y == x).count();
                let have = merged.iter().filter(|&&y| y == x).count();
                merged.extend(std::iter::repeat_n(x, m.saturating_sub(have)));
                i += m;
            }
        }
        merged.sort_by(f64::total_cmp);
        for c in curves.iter_mut() {
            let kn = c.knots();
            let mut missing = Vec::new();
            let mut i = 0;
            while i < merged.len() {
                let x = merged[i];
                let want = merged.iter().filter(|&&y| y == x).count();
                let have = kn.iter().filter(|&&y| y == x).count();
                missing.extend(std::iter::repeat_n(x, want.saturating_sub(have)));
                i += want;
            }
            if !missing.is_empty() {
                *c = c.refine(&missing)?;
            }
        }
        let n = curves[0].control_points().len();
        let columns: Vec<Vec<Point<D>>> =
            (0..n).map(|j| curves.iter().map(|c| c.control_points()[j]).collect()).collect();
        // Shared v-parameters: the mean over all columns; knots by averaging.
        let mut v = vec![0.0; k];
        for col in &columns {
            for (s, t) in v.iter_mut().zip(parametrize(col, params, false)?) {
                *s += t / n as f64;
            }
        }
        let q = degree_v;
        let mut kv = vec![0.0; q + 1];
        for j in 1..k - q {
            kv.push(v[j..j + q].iter().sum::<f64>() / q as f64);
        }
        kv.extend(vec![1.0; q + 1]);
        let mut net = vec![Vec::with_capacity(k); n];
        for (j, col) in columns.iter().enumerate() {
            net[j] = fit_with_knots(col, &v, &FitWithKnotsOptions::new(q, kv.clone()))?.curve.control_points().to_vec();
        }
        BSplineSurface::new((p, q), curves[0].knots().to_vec(), kv, net, (false, false))
    }
}
