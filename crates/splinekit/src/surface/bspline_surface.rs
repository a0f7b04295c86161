//! B-spline surfaces S(u, v) = Σ_i Σ_j N_{i,p}(u) M_{j,q}(v) P_ij.

use crate::basis::{KnotVector, SplineAxis};
use crate::curve::BSplineCurve;
use crate::error::Result;
use crate::ops::spline_data::{SplineData, to_bspline};
use crate::surface::Surface;
use crate::surface::tensor::{TensorSpline, net_axes, net_shape, tensor_surface_accessors, tensor_surface_domains};
use crate::{Interval, Point};

/// A tensor-product B-spline surface of degrees (p, q). The net's first index runs along
/// u. Each direction may be clamped, unclamped or periodic (closed), with the knot rules
/// of [`BSplineCurve`].
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface<const D: usize> {
    net: Vec<Vec<Point<D>>>,
    spline: TensorSpline<Point<D>>,
}

impl<const D: usize> BSplineSurface<D> {
    /// A surface from degrees, knot vectors (n_u + p + 1 and n_v + q + 1 values), the
    /// control net (n_u rows of n_v points) and the periodic flags.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::surface::{BSplineSurface, Surface};
    /// // The bilinear patch S(u, v) = (u, v, uv) on [0, 1]²: degrees (1, 1), one span each way.
    /// let p = |x, y, z| Point::<3>::new(x, y, z);
    /// let net = vec![vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)], vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)]];
    /// let s = BSplineSurface::new((1, 1), vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 0.0, 1.0, 1.0], net, (false, false)).unwrap();
    /// assert_eq!(s.point(0.5, 0.25), p(0.5, 0.25, 0.125));
    /// assert_eq!(s.partial(0.3, 0.7, 1, 1), p(0.0, 0.0, 1.0));
    /// ```
    pub fn new(
        degrees: (usize, usize),
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        net: Vec<Vec<Point<D>>>,
        periodic: (bool, bool),
    ) -> Result<Self> {
        let (u, v) = net_axes(degrees, knots_u, knots_v, &net, periodic)?;
        let spline = TensorSpline::new(u, v, &net);
        Ok(BSplineSurface { net, spline })
    }

    /// Clamped uniform knots on [0, 1]² for the given net.
    pub fn clamped_uniform(degrees: (usize, usize), net: Vec<Vec<Point<D>>>) -> Result<Self> {
        let (nu, nv) = net_shape(&net, "control_points")?;
        let unit = Interval::new(0.0, 1.0);
        let ku = KnotVector::clamped_uniform(degrees.0, nu, unit)?.into_vec();
        let kv = KnotVector::clamped_uniform(degrees.1, nv, unit)?.into_vec();
        Self::new(degrees, ku, kv, net, (false, false))
    }

    tensor_surface_accessors!();

    /// The isocurve u = u₀ as a B-spline in v (exact: its control points are
    /// Σ_i N_i(u₀) P_ij).
    pub fn iso_curve_u(&self, u0: f64) -> Result<BSplineCurve<D>> {
        let (su, nb) = basis_at(&self.spline.u, u0);
        let (pu, nu) = (nb.len() - 1, self.net.len());
        let pts: Vec<Point<D>> = (0..self.net[0].len())
            .map(|j| (0..=pu).fold(Point::<D>::zeros(), |acc, r| acc + self.net[(su - pu + r) % nu][j] * nb[r]))
            .collect();
        curve_along(&self.spline.v, pts)
    }

    /// The isocurve v = v₀ as a B-spline in u (exact: control points Σ_j M_j(v₀) P_ij).
    pub fn iso_curve_v(&self, v0: f64) -> Result<BSplineCurve<D>> {
        let (sv, nb) = basis_at(&self.spline.v, v0);
        let (pv, nv) = (nb.len() - 1, self.net[0].len());
        let pts: Vec<Point<D>> = self
            .net
            .iter()
            .map(|row| (0..=pv).fold(Point::<D>::zeros(), |acc, r| acc + row[(sv - pv + r) % nv] * nb[r]))
            .collect();
        curve_along(&self.spline.u, pts)
    }

    /// The same surface with every control point mapped by `f` (exact for affine maps).
    pub fn map_points(&self, f: impl Fn(&Point<D>) -> Point<D>) -> Self {
        let net = self.net.iter().map(|r| r.iter().map(&f).collect()).collect();
        let (ku, kv) = self.knots();
        Self::new(self.degrees(), ku.to_vec(), kv.to_vec(), net, self.periodic()).expect("same knots")
    }
}

impl<const D: usize> Surface<D> for BSplineSurface<D> {
    crate::curve::control_box::control_point_box!(net "a B-spline surface");
    tensor_surface_domains!();
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        self.spline.eval_partials(u, v, du, dv, out)
    }
    fn eval_grid(&self, us: &[f64], vs: &[f64], du: usize, dv: usize, out: &mut [Point<D>]) {
        self.spline.eval_grid(us, vs, du, dv, out)
    }
    fn eval_grid_with_normals(&self, us: &[f64], vs: &[f64], points: &mut [Point<D>], normals: &mut [Point<D>]) {
        self.spline.eval_grid_points_normals(us, vs, points, normals);
    }
}

/// The span s of x on `axis` (x clamped or wrapped into its domain) and the p + 1 basis
/// functions N_{s−p}(x), …, N_s(x) there: the weights of an isocurve's control points.
fn basis_at(axis: &SplineAxis, x: f64) -> (usize, Vec<f64>) {
    let (p, x) = (axis.degree(), axis.normalise(x));
    let s = axis.span(x);
    let mut nb = vec![0.0; p + 1];
    crate::basis::basis_functions(axis.eval_knots(), p, s, x, &mut nb);
    (s, nb)
}

/// The B-spline curve with these control points along `axis`: its degree, its knots as
/// given and its periodicity (an isocurve runs along the other direction's axis).
fn curve_along<const D: usize>(axis: &SplineAxis, points: Vec<Point<D>>) -> Result<BSplineCurve<D>> {
    let data = SplineData { degree: axis.degree(), knots: axis.knots().to_vec(), coefficients: points };
    to_bspline(data, axis.is_periodic())
}
