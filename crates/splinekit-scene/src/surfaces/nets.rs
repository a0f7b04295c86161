//! Documents of tensor-product surfaces given by control nets: Bézier, B-spline and NURBS,
//! in any dimension 1 … 4. `control_points[i][j]` is P_ij, rows along u.

use serde::{Deserialize, Serialize};
use splinekit::Point;
use splinekit::surface::{BSplineSurface, BezierSurface, NurbsSurface, Surface};

use super::{SurfaceDecoration, SurfaceForm, Surfaces};
use crate::budget::{F64, ShapeCost, check_degree};
use crate::defaults::is_false;
use crate::error::{DocumentError, Result};
use crate::points::{check_finite_list, dimension_of, to_points};
use crate::registry::{DocumentKind, spline_kind_items};
use crate::views::NetView;

/// `{"type":"bezier_surface","control_points":[[...row...],...]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierSurfaceDoc {
    /// Rows of control points (rows along u).
    pub control_points: Vec<Vec<Vec<f64>>>,
}

impl DocumentKind for BezierSurfaceDoc {
    type Family = Surfaces;
    fn spline(&self) -> Option<NetView<'_>> {
        Some(NetView::bezier(&self.control_points))
    }
    spline_kind_items!(SurfaceForm, net_dimension, control_net);
    /// De Casteljau along every row, then once across: n_u·n_v² + n_u² interpolations.
    fn cost(&self) -> ShapeCost {
        let (nu, nv, d) = net_size(&self.control_points);
        let cap = |n: f64| n.min(crate::budget::MAX_DEGREE as f64 + 1.0);
        ShapeCost::new(
            "control_points",
            nu * nv * d * F64,
            nu * nv * d,
            (cap(nu) * cap(nv).powi(2) + cap(nu).powi(2)) * d,
        )
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let (nu, nv, _) = net_size(&self.control_points);
        check_degree("control_points", nu as usize - 1)?;
        check_degree("control_points[0]", nv as usize - 1)?;
        Ok(Box::new(BezierSurface::new(net_points::<D>(&self.control_points))?))
    }
    /// A biquadratic bump over [0, 2]².
    fn example() -> Self {
        BezierSurfaceDoc { control_points: bump() }
    }
}

/// `{"type":"bspline_surface", ...}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BSplineSurfaceDoc {
    /// Degree in u.
    pub degree_u: usize,
    /// Degree in v.
    pub degree_v: usize,
    /// n_u + degree_u + 1 knots.
    pub knots_u: Vec<f64>,
    /// n_v + degree_v + 1 knots.
    pub knots_v: Vec<f64>,
    /// n_u rows of n_v points.
    pub control_points: Vec<Vec<Vec<f64>>>,
    /// Closed in u with cyclic rows.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_u: bool,
    /// Closed in v with cyclic columns.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_v: bool,
}

impl DocumentKind for BSplineSurfaceDoc {
    type Family = Surfaces;
    fn spline(&self) -> Option<NetView<'_>> {
        let knots = Some((self.knots_u.as_slice(), self.knots_v.as_slice()));
        let periodic = (self.periodic_u, self.periodic_v);
        Some(NetView::borrowed((self.degree_u, self.degree_v), &self.control_points, knots, None, periodic))
    }
    spline_kind_items!(SurfaceForm, net_dimension, control_net);
    fn cost(&self) -> ShapeCost {
        tensor_spline_cost(self.degree_u, self.degree_v, &self.control_points, 0.0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        knotted_surface(&self.spline().expect("a spline kind"))
    }
    /// The biquadratic bump as one clamped B-spline patch.
    fn example() -> Self {
        BSplineSurfaceDoc {
            degree_u: 2,
            degree_v: 2,
            knots_u: vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            knots_v: vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            control_points: bump(),
            periodic_u: false,
            periodic_v: false,
        }
    }
}

/// `{"type":"nurbs_surface", ...bspline_surface fields..., "weights":[[...]]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NurbsSurfaceDoc {
    /// Degree in u.
    pub degree_u: usize,
    /// Degree in v.
    pub degree_v: usize,
    /// n_u + degree_u + 1 knots.
    pub knots_u: Vec<f64>,
    /// n_v + degree_v + 1 knots.
    pub knots_v: Vec<f64>,
    /// n_u rows of n_v points.
    pub control_points: Vec<Vec<Vec<f64>>>,
    /// n_u rows of n_v positive weights.
    pub weights: Vec<Vec<f64>>,
    /// Closed in u.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_u: bool,
    /// Closed in v.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_v: bool,
}

impl DocumentKind for NurbsSurfaceDoc {
    type Family = Surfaces;
    fn spline(&self) -> Option<NetView<'_>> {
        let knots = Some((self.knots_u.as_slice(), self.knots_v.as_slice()));
        let periodic = (self.periodic_u, self.periodic_v);
        Some(NetView::borrowed(
            (self.degree_u, self.degree_v),
            &self.control_points,
            knots,
            Some(&self.weights),
            periodic,
        ))
    }
    spline_kind_items!(SurfaceForm, net_dimension, control_net);
    fn cost(&self) -> ShapeCost {
        tensor_spline_cost(self.degree_u, self.degree_v, &self.control_points, 1.0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        knotted_surface(&self.spline().expect("a spline kind"))
    }
    /// A bilinear patch pulled towards its raised corner by the weight 3.
    fn example() -> Self {
        NurbsSurfaceDoc {
            degree_u: 1,
            degree_v: 1,
            knots_u: vec![0.0, 0.0, 1.0, 1.0],
            knots_v: vec![0.0, 0.0, 1.0, 1.0],
            control_points: vec![
                vec![vec![0.0, 0.0, 0.0], vec![0.0, 1.0, 0.0]],
                vec![vec![1.0, 0.0, 0.0], vec![1.0, 1.0, 1.0]],
            ],
            weights: vec![vec![1.0, 1.0], vec![1.0, 3.0]],
            periodic_u: false,
            periodic_v: false,
        }
    }
}

/// A 3 × 3 net over [0, 2]² with its middle point raised.
fn bump() -> Vec<Vec<Vec<f64>>> {
    (0..3)
        .map(|i| (0..3).map(|j| vec![i as f64, j as f64, if (i, j) == (1, 1) { 2.0 } else { 0.0 }]).collect())
        .collect()
}

/// The common dimension of a control net's points; rows must agree.
fn net_dimension(field: &str, net: &[Vec<Vec<f64>>]) -> Result<usize> {
    let first = net.first().ok_or_else(|| DocumentError::new(field, "expected at least 1 row, got 0"))?;
    let d = dimension_of(&format!("{field}[0]"), first)?;
    for (i, row) in net.iter().enumerate() {
        let di = dimension_of(&format!("{field}[{i}]"), row)?;
        if di != d {
            return Err(DocumentError::new(
                format!("{field}[{i}]"),
                format!("expected points of {d} coordinates like the first row, got {di}"),
            ));
        }
    }
    Ok(d)
}

/// The kernel surface of a knotted net kind's view: the B-spline surface, or with weights
/// the NURBS surface. Its degrees above the budget's and numbers that are not finite are
/// refused first, naming the fields (`degree_u`, `degree_v`, `knots_u`, `knots_v`, then
/// `weights[i]`, in that order).
fn knotted_surface<const D: usize>(view: &NetView<'_>) -> Result<Box<dyn Surface<D>>> {
    let (knots_u, knots_v) = view.knots.as_ref().expect("a knotted net");
    check_degree("degree_u", view.degrees.0)?;
    check_degree("degree_v", view.degrees.1)?;
    check_finite_list("knots_u", knots_u)?;
    check_finite_list("knots_v", knots_v)?;
    for (i, row) in view.weights.iter().flat_map(|w| w.iter()).enumerate() {
        check_finite_list(&format!("weights[{i}]"), row)?;
    }
    let (knots_u, knots_v, points) = (knots_u.to_vec(), knots_v.to_vec(), net_points::<D>(&view.control_points));
    Ok(match &view.weights {
        None => Box::new(BSplineSurface::new(view.degrees, knots_u, knots_v, points, view.periodic)?),
        Some(w) => Box::new(NurbsSurface::new(view.degrees, knots_u, knots_v, points, w.to_vec(), view.periodic)?),
    })
}

/// What a scene draws besides a net kind: its control net (`control_points`).
fn control_net<'a>(net: &'a [Vec<Vec<f64>>], _spline: &NetView<'_>) -> SurfaceDecoration<'a> {
    SurfaceDecoration::ControlNet(net)
}

fn net_points<const D: usize>(net: &[Vec<Vec<f64>>]) -> Vec<Vec<Point<D>>> {
    net.iter().map(|r| to_points::<D>(r)).collect()
}

/// Rows, points per row (of the first row) and coordinates per point of a net, as numbers
/// for estimates (at least 1 each).
fn net_size(net: &[Vec<Vec<f64>>]) -> (f64, f64, f64) {
    let row = net.first().map(Vec::as_slice).unwrap_or_default();
    let d = row.first().map_or(1, Vec::len);
    (net.len().max(1) as f64, row.len().max(1) as f64, d.max(1) as f64)
}

/// A tensor-product B-spline surface (with `extra` = 1 for NURBS weights): the net and
/// knots stored; per point two span searches, the two bases and the (p_u + 1)(p_v + 1)
/// combination.
fn tensor_spline_cost(pu: usize, pv: usize, net: &[Vec<Vec<f64>>], extra: f64) -> ShapeCost {
    let (nu, nv, d) = net_size(net);
    let cap = |p: usize| p.min(crate::budget::MAX_DEGREE + 1) as f64 + 1.0;
    let (pu, pv, d) = (cap(pu), cap(pv), d + extra);
    let stored = nu * nv * d + nu + nv + pu + pv;
    let eval = pu * pu + pv * pv + pu * pv * d + (nu * nv).max(2.0).log2();
    let field = if pu > nu {
        "degree_u"
    } else if pv > nv {
        "degree_v"
    } else {
        "control_points"
    };
    ShapeCost::new(field, stored * F64, stored, eval)
}
