//! Lofting (skinning): a surface through a sequence of section curves.
//!
//! [`BSplineSurface::loft`] (NURBS Book §10.3) takes B-spline sections: they are made
//! compatible — clamped, knots mapped to [0, 1], raised to a common degree, refined to a
//! common knot vector — and then every column of corresponding control points is
//! interpolated across the sections. [`CurveLoft`] takes any curves: with the cardinal
//! functions L_k of the same interpolation in v (the B-spline of degree q on the averaged
//! knots with L_k(v_l) = δ_kl), S(u, v) = Σ_k L_k(v) c_k(u). For B-spline sections at the
//! same parameters the two are one surface (interpolation is linear in the data), which
//! is how a loft of B-splines is exported exactly. With q = n − 1 the knots in v are those
//! of a Bézier curve: the loft is a polynomial (a Bézier) of degree n − 1 in the cross
//! direction, the Lagrange interpolant of the sections written in the Bernstein basis.

use smallvec::{SmallVec, smallvec};

use crate::curve::{BSplineCurve, Curve, Reparametrized};
use crate::error::{Error, Result};
use crate::fit::lsq::{FitWithKnotsOptions, fit_with_knots};
use crate::fit::parametrize::{Parametrization, parametrize};
use crate::surface::{BSplineSurface, Surface};
use crate::{Interval, Point};

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
        check_degree_v(k, degree_v)?;
        let curves = compatible(sections)?;
        let n = curves[0].control_points().len();
        let columns: Vec<Vec<Point<D>>> =
            (0..n).map(|j| curves.iter().map(|c| c.control_points()[j]).collect()).collect();
        // Shared v-parameters: the mean over all columns.
        let mut v = vec![0.0; k];
        for col in &columns {
            for (s, t) in v.iter_mut().zip(parametrize(col, params, false)?) {
                *s += t / n as f64;
            }
        }
        // The ends exactly (the means of 0s and 1s may round).
        v[0] = 0.0;
        v[k - 1] = 1.0;
        interpolate_columns(&curves, degree_v, &v)
    }

    /// [`BSplineSurface::loft`] at given parameters `v` across the sections (strictly
    /// increasing, one per section; the v-domain is [v₀, v_{n−1}]): S(u, v_k) =
    /// section_k(u), u mapped to [0, 1] on every section. This is the surface a
    /// [`CurveLoft`] of the same sections, degree and parameters is.
    pub fn loft_at(sections: &[BSplineCurve<D>], degree_v: usize, v: &[f64]) -> Result<Self> {
        check_degree_v(sections.len(), degree_v)?;
        check_parameters(v, sections.len())?;
        interpolate_columns(&compatible(sections)?, degree_v, v)
    }
}

/// At least 2 sections and 1 ≤ `degree_v` < their number.
fn check_degree_v(k: usize, degree_v: usize) -> Result<()> {
    if k < 2 {
        return Err(Error::count("sections", "at least 2 curves", k));
    }
    if degree_v == 0 || degree_v >= k {
        return Err(Error::invalid(
            "degree_v",
            format!("must be between 1 and {} for {k} sections, got {degree_v}", k - 1),
        ));
    }
    Ok(())
}

/// One finite parameter per section, strictly increasing.
fn check_parameters(v: &[f64], k: usize) -> Result<()> {
    if v.len() != k {
        return Err(Error::count("parameters", format!("one per section ({k})"), v.len()));
    }
    for (i, x) in v.iter().enumerate() {
        if !x.is_finite() {
            return Err(Error::invalid(format!("parameters[{i}]"), format!("must be finite, got {x}")));
        }
        if i > 0 && *x <= v[i - 1] {
            return Err(Error::invalid(
                format!("parameters[{i}]"),
                format!("parameters must increase strictly: {x} follows {}", v[i - 1]),
            ));
        }
    }
    Ok(())
}

/// The knots of interpolation of degree q at the parameters v (NURBS Book eq. 9.8): q + 1
/// copies of v₀, the means of q consecutive inner parameters, q + 1 copies of v_{n−1}.
fn averaged_knots(v: &[f64], q: usize) -> Vec<f64> {
    let k = v.len();
    let mut kv = vec![v[0]; q + 1];
    for j in 1..k - q {
        kv.push(v[j..j + q].iter().sum::<f64>() / q as f64);
    }
    kv.extend(vec![v[k - 1]; q + 1]);
    kv
}

/// The sections clamped on [0, 1], raised to their highest degree and refined to one knot
/// vector.
fn compatible<const D: usize>(sections: &[BSplineCurve<D>]) -> Result<Vec<BSplineCurve<D>>> {
    let mut curves: Vec<BSplineCurve<D>> = sections.iter().map(unit_knots).collect::<Result<_>>()?;
    let p = curves.iter().map(|c| c.degree()).max().unwrap_or(0);
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
    Ok(curves)
}

/// Every column of the compatible sections' control points interpolated at `v` by degree
/// `q` on the averaged knots.
fn interpolate_columns<const D: usize>(curves: &[BSplineCurve<D>], q: usize, v: &[f64]) -> Result<BSplineSurface<D>> {
    let n = curves[0].control_points().len();
    let kv = averaged_knots(v, q);
    let mut net = vec![Vec::with_capacity(curves.len()); n];
    for (j, row) in net.iter_mut().enumerate() {
        let col: Vec<Point<D>> = curves.iter().map(|c| c.control_points()[j]).collect();
        *row = fit_with_knots(&col, v, &FitWithKnotsOptions::new(q, kv.clone()))?.curve.control_points().to_vec();
    }
    BSplineSurface::new((curves[0].degree(), q), curves[0].knots().to_vec(), kv, net, (false, false))
}

/// How a [`CurveLoft`] places its sections in v.
#[derive(Debug, Clone, PartialEq)]
pub enum LoftParameters {
    /// On [0, 1], spaced by the sections' mean distance apart (sampled at 33 common
    /// parameters of their unit domains): equal gaps (`Uniform`), the distance
    /// (`ChordLength`) or its square root (`Centripetal`).
    Spacing(Parametrization),
    /// These parameters, strictly increasing, one per section.
    Given(Vec<f64>),
}

/// Samples per section for the mean distance between neighbouring sections.
const SPACING_SAMPLES: usize = 33;

/// A loft of any curves: S(u, v) = Σ_k L_k(v) c_k(u), u ∈ [0, 1] (every section
/// reparametrised there), v ∈ [v₀, v_{n−1}], L_k the cardinal B-splines of degree q on the
/// averaged knots (module documentation). S(u, v_k) = c_k(u) exactly up to rounding of the
/// cardinal functions; partials ∂^{i,j}S = Σ_k L_k^{(j)}(v) c_k^{(i)}(u), exact given the
/// sections'.
pub struct CurveLoft<const D: usize> {
    sections: Vec<Reparametrized<Box<dyn Curve<D>>>>,
    parameters: Vec<f64>,
    knots_v: Vec<f64>,
    cardinal: Vec<BSplineCurve<1>>,
}

impl<const D: usize> CurveLoft<D> {
    /// The loft through `sections` with interpolation of degree `degree_v` across them
    /// (`sections.len() − 1` for the Bézier), placed by `parameters`. The sections must
    /// have finite domains and be all closed or all open (errors name `sections[k]`);
    /// chord-length spacing needs neighbouring sections apart.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{Curve, model::Line};
    /// use splinekit::fit::Parametrization;
    /// use splinekit::surface::Surface;
    /// use splinekit::surface::loft::{CurveLoft, LoftParameters};
    /// // Three parallel segments at heights 0, 1, 4: the quadratic (Bézier) loft through them.
    /// let line = |z: f64, y: f64| -> Box<dyn Curve<3>> {
    ///     Box::new(Line::new(Point::<3>::new(0.0, y, z), Point::<3>::new(1.0, y, z)).unwrap())
    /// };
    /// let sections = vec![line(0.0, 0.0), line(1.0, 1.0), line(4.0, 2.0)];
    /// let s = CurveLoft::new(sections, 2, &LoftParameters::Spacing(Parametrization::Uniform)).unwrap();
    /// assert!((s.point(0.5, 0.5) - Point::<3>::new(0.5, 1.0, 1.0)).norm() < 1e-14);
    /// ```
    pub fn new(sections: Vec<Box<dyn Curve<D>>>, degree_v: usize, parameters: &LoftParameters) -> Result<Self> {
        check_degree_v(sections.len(), degree_v)?;
        let closed = sections[0].is_closed();
        let mut unit = Vec::with_capacity(sections.len());
        for (k, c) in sections.into_iter().enumerate() {
            let d = c.domain();
            if !(d.start.is_finite() && d.end.is_finite() && d.start < d.end) {
                return Err(Error::invalid(
                    format!("sections[{k}]"),
                    format!("the domain [{}, {}] must be finite and non-empty", d.start, d.end),
                ));
            }
            if c.is_closed() != closed {
                return Err(Error::invalid(
                    format!("sections[{k}]"),
                    "the sections must be all closed or all open (sections[0] is not like this one)",
                ));
            }
            unit.push(Reparametrized::unit(c)?);
        }
        let v = match parameters {
            LoftParameters::Given(v) => {
                check_parameters(v, unit.len())?;
                v.clone()
            }
            LoftParameters::Spacing(method) => spacing(&unit, *method)?,
        };
        let knots_v = averaged_knots(&v, degree_v);
        let cardinal = (0..unit.len())
            .map(|k| {
                let data: Vec<Point<1>> =
                    (0..unit.len()).map(|l| Point::<1>::new(if l == k { 1.0 } else { 0.0 })).collect();
                Ok(fit_with_knots(&data, &v, &FitWithKnotsOptions::new(degree_v, knots_v.clone()))?.curve)
            })
            .collect::<Result<_>>()?;
        Ok(CurveLoft { sections: unit, parameters: v, knots_v, cardinal })
    }

    /// The sections' parameters v_k.
    pub fn parameters(&self) -> &[f64] {
        &self.parameters
    }

    /// The knots in v (clamped; a Bézier's when the degree is the number of sections less
    /// one).
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }
}

/// v_k on [0, 1] from the mean distances between neighbouring sections.
fn spacing<const D: usize>(
    sections: &[Reparametrized<Box<dyn Curve<D>>>],
    method: Parametrization,
) -> Result<Vec<f64>> {
    let samples: Vec<Vec<Point<D>>> = sections
        .iter()
        .map(|c| (0..SPACING_SAMPLES).map(|m| c.point(m as f64 / (SPACING_SAMPLES - 1) as f64)).collect())
        .collect();
    let mut v = vec![0.0; sections.len()];
    for k in 1..sections.len() {
        let d =
            samples[k].iter().zip(&samples[k - 1]).map(|(a, b)| (a - b).norm()).sum::<f64>() / SPACING_SAMPLES as f64;
        let gap = match method {
            Parametrization::Uniform => 1.0,
            Parametrization::ChordLength => d,
            Parametrization::Centripetal => d.sqrt(),
        };
        if !(gap > 0.0 && gap.is_finite()) {
            return Err(Error::invalid(
                format!("sections[{k}]"),
                format!(
                    "the section lies on sections[{}] (mean distance {d}): chord-length spacing needs them apart",
                    k - 1
                ),
            ));
        }
        v[k] = v[k - 1] + gap;
    }
    let total = v[sections.len() - 1];
    if !total.is_finite() {
        return Err(Error::invalid("sections", "the sections are too far apart for their distances to be finite"));
    }
    for x in v.iter_mut() {
        *x /= total;
    }
    let last = v.len() - 1;
    v[last] = 1.0;
    Ok(v)
}

impl<const D: usize> Surface<D> for CurveLoft<D> {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(self.parameters[0], self.parameters[self.parameters.len() - 1])
    }
    fn is_closed_u(&self) -> bool {
        self.sections[0].is_closed()
    }
    /// The sections' breakpoints, merged.
    fn breakpoints_u(&self) -> Vec<f64> {
        let mut b: Vec<f64> = self.sections.iter().flat_map(|c| c.breakpoints()).collect();
        b.sort_by(f64::total_cmp);
        b.dedup();
        b
    }
    /// The knots in v.
    fn breakpoints_v(&self) -> Vec<f64> {
        let mut b = self.knots_v.clone();
        b.dedup();
        b
    }
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let dom = self.domain_v();
        let v = v.clamp(dom.start, dom.end);
        out[..(du + 1) * (dv + 1)].iter_mut().for_each(|p| *p = Point::<D>::zeros());
        let mut c: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); du + 1];
        let mut l: SmallVec<[Point<1>; 8]> = smallvec![Point::<1>::zeros(); dv + 1];
        for (section, cardinal) in self.sections.iter().zip(&self.cardinal) {
            cardinal.eval(v, &mut l);
            if l.iter().all(|x| x[0] == 0.0) {
                continue;
            }
            section.eval(u, &mut c);
            for i in 0..=du {
                for j in 0..=dv {
                    out[i * (dv + 1) + j] += c[i] * l[j][0];
                }
            }
        }
    }
}
