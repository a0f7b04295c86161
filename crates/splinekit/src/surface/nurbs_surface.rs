//! NURBS surfaces S = Σ N_i M_j w_ij P_ij / Σ N_i M_j w_ij, with rational partials of any
//! order (NURBS Book eq. 4.20):
//! S^{(k,l)} = (A^{(k,l)} − Σ_{(i,j)≠(0,0)} C(k,i) C(l,j) w^{(i,j)} S^{(k−i,l−j)}) / w.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::binomial;
use crate::curve::nurbs::check_weights;
use crate::error::Result;
use crate::ops::homogeneous::Homogeneous;
use crate::surface::tensor::{TensorSpline, net_axes, net_shape, tensor_surface_accessors, tensor_surface_domains};
use crate::surface::{Surface, unit_normal};

/// A tensor-product NURBS surface with positive weights beside the control points.
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSurface<const D: usize> {
    net: Vec<Vec<Point<D>>>,
    weights: Vec<Vec<f64>>,
    spline: TensorSpline<Homogeneous<D>>,
}

impl<const D: usize> NurbsSurface<D> {
    /// A surface from degrees, knots, net, weights (same shape, all > 0) and periodic flags.
    pub fn new(
        degrees: (usize, usize),
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        net: Vec<Vec<Point<D>>>,
        weights: Vec<Vec<f64>>,
        periodic: (bool, bool),
    ) -> Result<Self> {
        let (u, v) = net_axes(degrees, knots_u, knots_v, &net, periodic)?;
        let (nu, nv) = (net.len(), net[0].len());
        if weights.len() != nu {
            return Err(crate::Error::count("weights", format!("{nu} rows like the control points"), weights.len()));
        }
        for (i, row) in weights.iter().enumerate() {
            check_weights(row, nv).map_err(|e| match e {
                crate::Error::Count { expected, got, .. } => {
                    crate::Error::Count { field: format!("weights[{i}]"), expected, got }
                }
                crate::Error::Invalid { message, .. } => {
                    crate::Error::Invalid { field: format!("weights[{i}]"), message }
                }
                other => other,
            })?;
        }
        let rows: Vec<Vec<Homogeneous<D>>> = net
            .iter()
            .zip(&weights)
            .map(|(r, w)| r.iter().zip(w).map(|(p, w)| Homogeneous::lift(p, *w)).collect())
            .collect();
        let spline = TensorSpline::new(u, v, &rows);
        Ok(NurbsSurface { net, weights, spline })
    }

    /// The rational Bézier surface Σ B_{i,m}(u) B_{j,n}(v) w_ij P_ij / Σ B B w on [0, 1]²
    /// (a NURBS surface with a single span in each direction).
    pub fn rational_bezier(net: Vec<Vec<Point<D>>>, weights: Vec<Vec<f64>>) -> Result<Self> {
        let (nu, nv) = net_shape(&net, "control_points")?;
        let bezier_knots = |n: usize| {
            let mut k = vec![0.0; n];
            k.extend(vec![1.0; n]);
            k
        };
        Self::new((nu - 1, nv - 1), bezier_knots(nu), bezier_knots(nv), net, weights, (false, false))
    }

    tensor_surface_accessors!();
    /// The weights.
    pub fn weights(&self) -> &[Vec<f64>] {
        &self.weights
    }
}

/// Turns homogeneous partials h[i·(dv+1)+j] into the rational surface's partials.
pub(crate) fn rational_partials<const D: usize>(h: &[Homogeneous<D>], du: usize, dv: usize, out: &mut [Point<D>]) {
    let w = dv + 1;
    let w0 = h[0].weight;
    for k in 0..=du {
        for l in 0..=dv {
            let mut v = h[k * w + l].weighted;
            for i in 0..=k {
                for j in 0..=l {
                    if i == 0 && j == 0 {
                        continue;
                    }
                    v -= out[(k - i) * w + (l - j)] * (binomial(k, i) * binomial(l, j) * h[i * w + j].weight);
                }
            }
            out[k * w + l] = v / w0;
        }
    }
}

impl<const D: usize> Surface<D> for NurbsSurface<D> {
    crate::curve::control_box::control_point_box!(net "a NURBS surface (weights > 0)");
    tensor_surface_domains!();
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let n = (du + 1) * (dv + 1);
        let mut h: SmallVec<[Homogeneous<D>; 9]> = smallvec![Homogeneous::lift(&Point::<D>::zeros(), 0.0); n];
        self.spline.eval_partials(u, v, du, dv, &mut h);
        rational_partials(&h, du, dv, out);
    }
    fn eval_grid_with_normals(&self, us: &[f64], vs: &[f64], points: &mut [Point<D>], normals: &mut [Point<D>]) {
        // S = A/w, S_u = (A_u − w_u S)/w, S_v = (A_v − w_v S)/w.
        self.spline.eval_grid_first(us, vs, |k, h, hu, hv| {
            let inv = 1.0 / h.weight;
            let s = h.weighted * inv;
            let su = (hu.weighted - s * hu.weight) * inv;
            let sv = (hv.weighted - s * hv.weight) * inv;
            points[k] = s;
            normals[k] = unit_normal(&su, &sv).unwrap_or_else(Point::<D>::zeros);
        });
    }
    fn eval_grid(&self, us: &[f64], vs: &[f64], du: usize, dv: usize, out: &mut [Point<D>]) {
        let n = (du + 1) * (dv + 1);
        let mut h = vec![Homogeneous::lift(&Point::<D>::zeros(), 0.0); us.len() * vs.len() * n];
        self.spline.eval_grid(us, vs, du, dv, &mut h);
        for (hc, oc) in h.chunks_exact(n).zip(out.chunks_exact_mut(n)) {
            rational_partials(hc, du, dv, oc);
        }
    }
}
