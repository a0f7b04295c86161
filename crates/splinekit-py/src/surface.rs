//! `splinekit.Surface`: any surface of a shape document, evaluated from numpy on grids
//! (as scipy's ``RectBivariateSpline``) or at paired parameters.

use numpy::PyArrayDyn;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use splinekit::Interval;
use splinekit::surface::{Surface, SurfaceNearest, unit_normal};
use splinekit_scene::budget::{Cost, F64};
use splinekit_scene::{AnySurface, DimensionVisitor, SurfaceDocument, Surfaces};

use crate::arrays::{Numbers, as_points_mut, check_params, filled};
use crate::budget;
use crate::errors::{OrValueError, value_error};
use crate::row_writer::{RowWriter, unfilled_rows};

/// Highest total order of partials one call may ask for (as ``splinekit eval``).
pub const MAX_SURFACE_DERIVATIVES: usize = 16;

/// A parametric surface S: [a, b] × [c, d] → ℝᴰ of any kind a shape document describes.
///
/// ``s(u, v)`` evaluates on the grid u × v: u of shape (Nu,) and v (Nv,) give (Nu, Nv, D);
/// ``s(u, v, grid=False)`` pairs u[i] with v[i] and gives (N, D). Open directions refuse
/// parameters outside the domain; closed ones wrap them around.
#[pyclass(subclass, module = "splinekit", name = "Surface")]
pub struct PySurface {
    pub(crate) doc: SurfaceDocument,
    pub(crate) surface: AnySurface,
    domain: [Interval; 2],
    closed: [bool; 2],
}

/// Domains and closedness of a surface of any dimension.
struct Shape;

impl DimensionVisitor<Surfaces> for Shape {
    type Output = ([Interval; 2], [bool; 2]);
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        ([s.domain_u(), s.domain_v()], [s.is_closed_u(), s.is_closed_v()])
    }
}

/// The partials ∂^{i+j}S/∂uⁱ∂vʲ, i, j ≤ k, on a grid (`eval_grid`'s layout) or at pairs.
struct Partials<'a> {
    us: &'a [f64],
    vs: &'a [f64],
    grid: bool,
    k: usize,
    out: &'a mut [f64],
}

impl DimensionVisitor<Surfaces> for Partials<'_> {
    type Output = ();
    fn visit<const D: usize>(self, s: &dyn Surface<D>) {
        let out = as_points_mut::<D>(self.out);
        if self.grid {
            return s.eval_grid(self.us, self.vs, self.k, self.k, out);
        }
        let w = (self.k + 1) * (self.k + 1);
        for (i, (&u, &v)) in self.us.iter().zip(self.vs).enumerate() {
            s.eval_partials(u, v, self.k, self.k, &mut out[i * w..(i + 1) * w]);
        }
    }
}

/// Points and unit normals N = S_u × S_v / |S_u × S_v| (zero where the surface is not
/// regular, and outside 3-D) on a grid or at pairs.
struct WithNormals<'a> {
    us: &'a [f64],
    vs: &'a [f64],
    grid: bool,
    out: &'a mut [f64],
}

impl DimensionVisitor<Surfaces> for WithNormals<'_> {
    type Output = ();
    fn visit<const D: usize>(self, s: &dyn Surface<D>) {
        let sites = if self.grid { self.us.len() * self.vs.len() } else { self.us.len() };
        let (points, normals) = as_points_mut::<D>(self.out).split_at_mut(sites);
        if self.grid {
            return s.eval_grid_with_normals(self.us, self.vs, points, normals);
        }
        let mut o = [splinekit::Point::<D>::zeros(); 4];
        for (i, (&u, &v)) in self.us.iter().zip(self.vs).enumerate() {
            s.eval_partials(u, v, 1, 1, &mut o);
            points[i] = o[0];
            normals[i] = unit_normal(&o[2], &o[1]).unwrap_or_else(splinekit::Point::<D>::zeros);
        }
    }
}

/// The parameters of one call: u and v values, their output shape, grid or paired.
pub struct Request<'py> {
    u: Numbers<'py>,
    v: Numbers<'py>,
    grid: bool,
}

impl<'py> Request<'py> {
    /// The u parameters.
    pub fn us(&self) -> &[f64] {
        self.u.values()
    }
    /// The v parameters.
    pub fn vs(&self) -> &[f64] {
        self.v.values()
    }
    /// Evaluation sites: Nu·Nv on a grid, N paired.
    fn count(&self) -> usize {
        if self.grid { self.us().len() * self.vs().len() } else { self.us().len() }
    }
    /// The leading output shape: (Nu, Nv) on a grid of arrays, (N,) paired, () for two
    /// numbers.
    fn shape(&self) -> Vec<usize> {
        match (self.u.is_scalar() && self.v.is_scalar(), self.grid) {
            (true, _) => vec![],
            (false, true) => vec![self.us().len(), self.vs().len()],
            (false, false) => vec![self.us().len()],
        }
    }
}

impl PySurface {
    /// Builds the kernel surface of `doc`; its errors are the command line's.
    pub fn new(doc: SurfaceDocument) -> PyResult<Self> {
        let surface = doc.build().or_value_error()?;
        let (domain, closed) = surface.visit(Shape);
        Ok(PySurface { doc, surface, domain, closed })
    }

    /// The dimension D of the points.
    pub(crate) fn dimension(&self) -> usize {
        self.surface.dimension()
    }

    fn request<'py>(&self, u: &Bound<'py, PyAny>, v: &Bound<'py, PyAny>, grid: bool) -> PyResult<Request<'py>> {
        let r = Request { u: Numbers::new(u)?, v: Numbers::new(v)?, grid };
        for (field, values, axis) in [("u", r.u.list("u")?, 0), ("v", r.v.list("v")?, 1)] {
            check_params(field, values, (!self.closed[axis]).then_some(self.domain[axis]), "direction")?;
        }
        if !grid && r.us().len() != r.vs().len() {
            return Err(value_error(format!(
                "v: with grid=False u and v are paired and need the same length, got {} and {}",
                r.us().len(),
                r.vs().len()
            )));
        }
        Ok(r)
    }

    /// Refuses a request over the budget: the partials up to order k in each direction
    /// evaluated at every site and `values` points per site held (the budget of
    /// `splinekit eval --grid`, without the formatting).
    fn check_budget(&self, r: &Request<'_>, k: usize, values: usize) -> PyResult<()> {
        let cost = self.doc.cost();
        let (n, block) = (r.count() as f64, ((k + 1) * (k + 1)) as f64);
        let held = n * values as f64 * self.dimension() as f64 * F64;
        let request = Cost::new(held, cost.evaluations(n, (k + 1) * (k + 1) - 1));
        let (field, sites) = match r.grid {
            true => ("grid", format!("a grid of {}×{} points", r.us().len(), r.vs().len())),
            false => ("u", format!("{} points", r.count())),
        };
        let what = format!(
            "{sites} with partials up to order {k} ({:.1e} operations each, driven by {})",
            cost.eval * block,
            cost.field
        );
        budget::check_request(field, &what, &cost, request)
    }

    /// All partials with i, j ≤ k, shaped (sites…, (k+1)², D).
    fn partial_block<'py>(&self, py: Python<'py>, r: &Request<'py>, k: usize) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.check_budget(r, k, (k + 1) * (k + 1))?;
        let (us, vs, grid) = (r.us(), r.vs(), r.grid);
        let shape = [r.count(), (k + 1) * (k + 1), self.dimension()];
        let surface = &self.surface;
        filled(py, &shape, |out| surface.visit(Partials { us, vs, grid, k, out }))
    }

    /// The grid evaluation S(u × v) of `__call__`, checked, as its request and a new
    /// (sites, 1, D) array not yet written: `fill_grid` writes it (from any thread) and
    /// `shaped` gives the result of `__call__`.
    pub fn grid_evaluation<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<(Request<'py>, Bound<'py, PyArrayDyn<f64>>, RowWriter)> {
        let r = self.request(u, v, true)?;
        self.check_budget(&r, 0, 1)?;
        let (array, writer) = unfilled_rows(py, &[r.count(), 1, self.dimension()], 1, r.count() * self.dimension());
        Ok((r, array, writer))
    }

    /// Writes S on the grid `us` × `vs` into `out` (as `__call__` does).
    pub fn fill_grid(&self, us: &[f64], vs: &[f64], out: &mut [f64]) {
        self.surface.visit(Partials { us, vs, grid: true, k: 0, out })
    }

    /// Reshapes (sites, D) blocks to the request's leading shape.
    pub fn shaped<'py>(&self, r: &Request<'py>, a: Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let mut shape = r.shape();
        shape.push(self.dimension());
        let np = a.py().import("numpy")?;
        np.call_method1("ascontiguousarray", (a.call_method1("reshape", (shape,))?,))
    }
}

#[pymethods]
impl PySurface {
    /// S(u, v): on the grid u × v (Nu, Nv, D), or paired (N, D) with ``grid=False``; two
    /// numbers give (D,). Tensor-product splines evaluate each u- and v-basis once.
    #[pyo3(signature = (u, v, grid = true))]
    fn __call__<'py>(&self, u: &Bound<'py, PyAny>, v: &Bound<'py, PyAny>, grid: bool) -> PyResult<Bound<'py, PyAny>> {
        let r = self.request(u, v, grid)?;
        let block = self.partial_block(u.py(), &r, 0)?;
        self.shaped(&r, block.into_any())
    }

    /// The partials ∂^{i+j}S/∂uⁱ∂vʲ of total order 1 … ``order``, as a dict keyed by ``"u"``,
    /// ``"v"``, ``"uu"``, ``"uv"``, ``"vv"``, … (the keys of ``splinekit eval``), each shaped
    /// like ``s(u, v, grid)``.
    #[pyo3(signature = (u, v, order = 1, grid = true))]
    fn partials<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        order: usize,
        grid: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        if order > MAX_SURFACE_DERIVATIVES {
            return Err(value_error(format!(
                "order: {order} is more than the limit of {MAX_SURFACE_DERIVATIVES} for surfaces"
            )));
        }
        let r = self.request(u, v, grid)?;
        let block = self.partial_block(py, &r, order)?;
        let dict = PyDict::new(py);
        for total in 1..=order {
            for i in (0..=total).rev() {
                let j = total - i;
                let key = format!("{}{}", "u".repeat(i), "v".repeat(j));
                let slice = (pyo3::types::PySlice::full(py), i * (order + 1) + j);
                dict.set_item(key, self.shaped(&r, block.get_item(slice)?)?)?;
            }
        }
        Ok(dict)
    }

    /// Unit normals N = S_u × S_v / |S_u × S_v|, shaped like ``s(u, v, grid)`` (3-D
    /// surfaces; zero where S_u × S_v = 0, e.g. at poles).
    #[pyo3(signature = (u, v, grid = true))]
    fn normals<'py>(&self, u: &Bound<'py, PyAny>, v: &Bound<'py, PyAny>, grid: bool) -> PyResult<Bound<'py, PyAny>> {
        Ok(self.points_and_normals(u, v, grid)?.1)
    }

    /// ``(points, normals)`` in one pass (S, S_u and S_v per site, the basis once per row
    /// and column on grids): what shading needs.
    #[pyo3(signature = (u, v, grid = true))]
    fn points_and_normals<'py>(
        &self,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        grid: bool,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
        let py = u.py();
        let r = self.request(u, v, grid)?;
        self.check_budget(&r, 1, 2)?;
        let (us, vs) = (r.us(), r.vs());
        let surface = &self.surface;
        let both =
            filled(py, &[2, r.count(), self.dimension()], |out| surface.visit(WithNormals { us, vs, grid, out }))?;
        Ok((self.shaped(&r, both.get_item(0)?)?, self.shaped(&r, both.get_item(1)?)?))
    }

    /// The point of the surface nearest to `p`: ``(u, v, S(u, v), distance)``, the distance
    /// within `accuracy` of the true minimum.
    #[pyo3(signature = (p, accuracy = 1e-12))]
    fn closest_point<'py>(&self, p: &Bound<'py, PyAny>, accuracy: f64) -> PyResult<(f64, f64, Bound<'py, PyAny>, f64)> {
        let (py, numbers) = (p.py(), Numbers::new(p)?);
        let query = numbers.point("p", self.dimension(), "surface")?;
        let surface = &self.surface;
        let (u, v, point, distance) =
            py.detach(|| surface.visit(NearestOnSurface { query, accuracy })).or_value_error()?;
        Ok((u, v, numpy::PyArray1::from_vec(py, point).into_any(), distance))
    }

    /// The u domain (a, b).
    #[getter]
    fn domain_u(&self) -> (f64, f64) {
        (self.domain[0].start, self.domain[0].end)
    }
    /// The v domain (c, d).
    #[getter]
    fn domain_v(&self) -> (f64, f64) {
        (self.domain[1].start, self.domain[1].end)
    }
    /// Whether the surface closes up (periodically) in u.
    #[getter]
    fn closed_u(&self) -> bool {
        self.closed[0]
    }
    /// Whether the surface closes up (periodically) in v.
    #[getter]
    fn closed_v(&self) -> bool {
        self.closed[1]
    }
    fn __repr__(&self) -> String {
        let [u, v] = self.domain;
        format!(
            "<splinekit {} surface in {}-D on [{}, {}] × [{}, {}]>",
            self.doc.type_name(),
            self.dimension(),
            u.start,
            u.end,
            v.start,
            v.end
        )
    }
}

/// The nearest point to a query point: (u, v, S(u, v), distance).
struct NearestOnSurface<'a> {
    query: &'a [f64],
    accuracy: f64,
}

impl DimensionVisitor<Surfaces> for NearestOnSurface<'_> {
    type Output = splinekit::Result<(f64, f64, Vec<f64>, f64)>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        let near = s.closest_point(&splinekit::Point::<D>::from_column_slice(self.query), self.accuracy)?;
        Ok((near.u, near.v, near.point.iter().copied().collect(), near.distance))
    }
}
