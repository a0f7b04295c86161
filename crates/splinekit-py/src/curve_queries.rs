//! Geometric queries of curves: arc length, nearest point, curvature, Frenet frame.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use splinekit::Point;
use splinekit::curve::{Curve, CurveArcLength, CurveNearest, curvature_from};
use splinekit_scene::{Curves, DimensionVisitor};

use crate::arrays::Numbers;
use crate::curve::PyCurve;
use crate::errors::{OrValueError, value_error};

/// Arc length ∫ₐᵇ |c'(t)| dt to an absolute tolerance.
struct Length(f64);

impl DimensionVisitor<Curves> for Length {
    type Output = f64;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> f64 {
        c.length(self.0)
    }
}

/// The nearest point to a query point: (t, c(t), distance).
struct Nearest<'a> {
    query: &'a [f64],
    accuracy: f64,
}

impl DimensionVisitor<Curves> for Nearest<'_> {
    type Output = splinekit::Result<(f64, Vec<f64>, f64)>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
        let near = c.closest_point(&Point::<D>::from_column_slice(self.query), self.accuracy)?;
        Ok((near.t, near.point.iter().copied().collect(), near.distance))
    }
}

/// Curvature κ at every parameter, from one batch of c' and c''.
struct Curvatures<'a>(&'a [f64]);

impl DimensionVisitor<Curves> for Curvatures<'_> {
    type Output = Vec<f64>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Vec<f64> {
        let mut d = vec![Point::<D>::zeros(); self.0.len() * 3];
        c.eval_many(self.0, 2, &mut d);
        d.chunks_exact(3).map(|v| curvature_from(&v[1], &v[2])).collect()
    }
}

/// The Frenet frame at one parameter, as coordinate lists.
struct Frame(f64);

/// Tangent, normal, binormal (as available) and curvature.
type FrameLists = Option<(Vec<f64>, Option<Vec<f64>>, Option<Vec<f64>>, f64)>;

impl DimensionVisitor<Curves> for Frame {
    type Output = FrameLists;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> FrameLists {
        let list = |p: Point<D>| p.iter().copied().collect::<Vec<f64>>();
        c.frame(self.0).map(|f| (list(f.tangent), f.normal.map(list), f.binormal.map(list), f.curvature))
    }
}

/// Refuses a tolerance that is not finite and positive.
fn check_tolerance(field: &str, value: f64) -> PyResult<()> {
    if !(value.is_finite() && value > 0.0) {
        return Err(value_error(format!("{field}: must be finite and > 0, got {value}")));
    }
    Ok(())
}

#[pymethods]
impl PyCurve {
    /// Arc length L = ∫ₐᵇ |c'(t)| dt of the whole curve, to the absolute `tolerance`
    /// (adaptive Gauss–Legendre quadrature between the curve's breakpoints).
    #[pyo3(signature = (tolerance = 1e-10))]
    fn length(&self, py: Python<'_>, tolerance: f64) -> PyResult<f64> {
        check_tolerance("tolerance", tolerance)?;
        let curve = &self.curve;
        Ok(py.detach(|| curve.visit(Length(tolerance))))
    }

    /// The point of the curve nearest to `p`: ``(t, c(t), |c(t) − p|)``, the distance
    /// within `accuracy` of the true minimum (global: the curve is covered by bounding
    /// boxes, the best candidates refined by Newton steps on (c(t) − p)·c'(t) = 0).
    #[pyo3(signature = (p, accuracy = 1e-12))]
    fn closest_point<'py>(&self, p: &Bound<'py, PyAny>, accuracy: f64) -> PyResult<(f64, Bound<'py, PyAny>, f64)> {
        let (py, numbers) = (p.py(), Numbers::new(p)?);
        let query = numbers.point("p", self.dimension(), "curve")?;
        let curve = &self.curve;
        let (t, point, distance) = py.detach(|| curve.visit(Nearest { query, accuracy })).or_value_error()?;
        Ok((t, numpy::PyArray1::from_vec(py, point).into_any(), distance))
    }

    /// Curvature κ = √(|c'|²|c''|² − (c'·c'')²) / |c'|³ (in 3-D |c' × c''| / |c'|³) at t:
    /// a number for a number, an array of shape (N,) for N parameters; 0 where c' = 0.
    fn curvature<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let numbers = Numbers::new(t)?;
        let params = numbers.list("t")?;
        self.check_params("t", params)?;
        let curve = &self.curve;
        let k = py.detach(|| curve.visit(Curvatures(params)));
        if numbers.is_scalar() {
            return Ok(k[0].into_pyobject(py)?.into_any());
        }
        Ok(numpy::PyArray1::from_vec(py, k).into_any())
    }

    /// The Frenet frame at a parameter t: a dict with the unit ``tangent`` T = c'/|c'|,
    /// the principal ``normal`` N (None where κ = 0), the ``binormal`` B = T × N (3-D
    /// only, else None) and the ``curvature`` κ; None where c'(t) = 0.
    fn frame<'py>(&self, py: Python<'py>, t: f64) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.check_params("t", &[t])?;
        let Some((tangent, normal, binormal, curvature)) = self.curve.visit(Frame(t)) else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        let array = |v: Vec<f64>| numpy::PyArray1::from_vec(py, v);
        d.set_item("tangent", array(tangent))?;
        d.set_item("normal", normal.map(array))?;
        d.set_item("binormal", binormal.map(array))?;
        d.set_item("curvature", curvature)?;
        Ok(Some(d))
    }
}
