//! The plane a curve is offset in, and the curve in that plane's coordinates.
//!
//! A 2-D curve is its own plane (x, y), with the normal direction V = z. A 3-D curve is
//! offset in a plane through its start point o perpendicular to a given direction V: with
//! an orthonormal pair e₁, e₂ such that e₁ × e₂ = V/|V|, a point p has plane coordinates
//! ((p − o)·e₁, (p − o)·e₂) and the plane point (x, y) is o + x e₁ + y e₂. The curve must lie
//! in that plane (within the tolerance of the offset); derivatives map by the linear part.
//! With this orientation the 2-D right-hand normal (T_y, −T_x) of a unit tangent T is
//! T × V/|V| in space, the convention of OpenCASCADE's offset curves.

use crate::Point;
use crate::basis::Side;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result};

/// Samples per breakpoint interval at which planarity is checked.
const PLANARITY_SAMPLES: usize = 32;

/// An orthonormal frame of the offset plane in ℝᴰ (D = 2 or 3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarFrame<const D: usize> {
    origin: Point<D>,
    e1: Point<D>,
    e2: Point<D>,
}

impl<const D: usize> PlanarFrame<D> {
    /// The plane of `curve` with normal direction `normal` (3-D: required, non-zero and
    /// finite; 2-D: absent or along z); an error names `normal` when the curve leaves the
    /// plane by more than `tolerance`.
    pub fn of<C: Curve<D> + ?Sized>(curve: &C, normal: Option<Point<3>>, tolerance: f64) -> Result<Self> {
        let origin = curve.point(curve.domain().start);
        match (D, normal) {
            (2, None) => Ok(PlanarFrame { origin, e1: axis(0), e2: axis(1) }),
            (2, Some(n)) if n.x == 0.0 && n.y == 0.0 && n.z > 0.0 && n.z.is_finite() => {
                Ok(PlanarFrame { origin, e1: axis(0), e2: axis(1) })
            }
            (2, Some(n)) => Err(Error::invalid(
                "normal",
                format!("a 2-D curve is offset in its plane (normal 0,0,1), got {},{},{}", n.x, n.y, n.z),
            )),
            (3, None) => Err(Error::invalid("normal", "a 3-D curve needs the normal direction of its plane")),
            (3, Some(n)) => {
                let len = n.norm();
                if !(len > 0.0 && len.is_finite()) {
                    return Err(Error::invalid(
                        "normal",
                        format!("must be a non-zero finite vector, got {},{},{}", n.x, n.y, n.z),
                    ));
                }
                let v = n / len;
                let helper = if v.x.abs() < 0.9 { Point::<3>::x() } else { Point::<3>::y() };
                let e1 = helper.cross(&v).normalize();
                let e2 = v.cross(&e1);
                let frame = PlanarFrame { origin, e1: lift(&e1), e2: lift(&e2) };
                frame.check_planar(curve, &lift(&v), tolerance)?;
                Ok(frame)
            }
            _ => Err(Error::invalid("dimension", format!("offsets are of 2-D and 3-D curves, this one is {D}-D"))),
        }
    }

    /// The largest distance of sampled points from the plane must be within `tolerance`.
    fn check_planar<C: Curve<D> + ?Sized>(&self, curve: &C, v: &Point<D>, tolerance: f64) -> Result<()> {
        let breaks = curve.breakpoints();
        let mut worst = (0.0f64, curve.domain().start);
        for w in breaks.windows(2) {
            let span = Interval::new(w[0], w[1]);
            for k in 0..=PLANARITY_SAMPLES {
                let t = span.lerp(k as f64 / PLANARITY_SAMPLES as f64);
                let h = (curve.point(t) - self.origin).dot(v).abs();
                if h > worst.0 {
                    worst = (h, t);
                }
            }
        }
        if worst.0 > tolerance {
            return Err(Error::invalid(
                "normal",
                format!(
                    "the curve is not in a plane perpendicular to the normal: at t = {} it is {:e} from the plane through its start (tolerance {tolerance:e})",
                    worst.1, worst.0
                ),
            ));
        }
        Ok(())
    }

    /// Plane coordinates of a point.
    pub fn to_plane(&self, p: &Point<D>) -> Point<2> {
        let r = p - self.origin;
        Point::<2>::new(r.dot(&self.e1), r.dot(&self.e2))
    }

    /// Plane coordinates of a vector (a derivative).
    pub fn vector_to_plane(&self, v: &Point<D>) -> Point<2> {
        Point::<2>::new(v.dot(&self.e1), v.dot(&self.e2))
    }

    /// The point of ℝᴰ with plane coordinates q.
    pub fn from_plane(&self, q: &Point<2>) -> Point<D> {
        self.origin + self.e1 * q.x + self.e2 * q.y
    }
}

/// The k-th unit vector of ℝᴰ.
fn axis<const D: usize>(k: usize) -> Point<D> {
    let mut e = Point::<D>::zeros();
    e[k] = 1.0;
    e
}

/// A 3-vector as a point of ℝᴰ (D = 3 here; the other entries are dropped or zero).
fn lift<const D: usize>(v: &Point<3>) -> Point<D> {
    let mut p = Point::<D>::zeros();
    for k in 0..D.min(3) {
        p[k] = v[k];
    }
    p
}

/// A curve of ℝᴰ seen in the plane coordinates of a [`PlanarFrame`], on its domain or a
/// part of it (then open).
pub struct InPlane<'c, const D: usize, C: ?Sized> {
    /// The curve.
    pub curve: &'c C,
    /// The plane.
    pub frame: PlanarFrame<D>,
    /// The parameters used.
    pub domain: Interval,
    /// Whether the curve is used as closed (its whole domain, periodic).
    pub closed: bool,
}

impl<'c, const D: usize, C: Curve<D> + ?Sized> InPlane<'c, D, C> {
    /// The whole curve in the plane of `frame`.
    pub fn new(curve: &'c C, frame: PlanarFrame<D>) -> Self {
        InPlane { curve, frame, domain: curve.domain(), closed: curve.is_closed() }
    }
}

impl<const D: usize, C: Curve<D> + ?Sized> Curve<2> for InPlane<'_, D, C> {
    fn domain(&self) -> Interval {
        self.domain
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn breakpoints(&self) -> Vec<f64> {
        let d = self.domain;
        let mut b: Vec<f64> = self.curve.breakpoints().into_iter().filter(|&t| t > d.start && t < d.end).collect();
        b.insert(0, d.start);
        b.push(d.end);
        b
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<2>]) {
        let mut full: smallvec::SmallVec<[Point<D>; 4]> = smallvec::smallvec![Point::<D>::zeros(); out.len()];
        self.curve.eval_side(t, side, &mut full);
        for (k, (o, f)) in out.iter_mut().zip(&full).enumerate() {
            *o = if k == 0 { self.frame.to_plane(f) } else { self.frame.vector_to_plane(f) };
        }
    }
}
