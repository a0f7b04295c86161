//! Knot insertion, refinement, degree elevation and Bézier patch decomposition of
//! B-spline and NURBS surfaces. An operation in u acts on every column of the net as on a
//! curve (all columns share the u-knots, so they end with the same new knots); an
//! operation in v acts on every row. The surface is unchanged.

use crate::curve::{BSplineCurve, NurbsCurve};
use crate::error::Result;
use crate::surface::iso_curve::Direction;
use crate::surface::{BSplineSurface, BezierSurface, NurbsSurface};
use crate::{Interval, Point};

/// One Bézier patch of a B-spline surface and the parameter rectangle it covers.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPatch<const D: usize> {
    /// [u₀, u₁] of the patch in the spline's parameters.
    pub u_range: Interval,
    /// [v₀, v₁] of the patch.
    pub v_range: Interval,
    /// The patch as a Bézier surface on [0, 1]².
    pub surface: BezierSurface<D>,
}

fn transpose<T: Clone>(net: &[Vec<T>]) -> Vec<Vec<T>> {
    (0..net[0].len()).map(|j| net.iter().map(|r| r[j].clone()).collect()).collect()
}

/// A spline curve that one line of a tensor-product net makes (a row or a column of the
/// control points, with the weights for NURBS), and what [`map_net_lines`] reads back.
trait LineCurve: Sized {
    /// One coefficient of the net: a control point, or a control point and its weight.
    type Coefficient;
    /// The curve of one line, periodic when `closed`.
    fn of_line(degree: usize, knots: Vec<f64>, line: Vec<Self::Coefficient>, closed: bool) -> Result<Self>;
    /// The line of the curve's coefficients.
    fn line(&self) -> Vec<Self::Coefficient>;
    /// Degree, knots and periodicity.
    fn spline(&self) -> (usize, &[f64], bool);
}

impl<const D: usize> LineCurve for BSplineCurve<D> {
    type Coefficient = Point<D>;
    fn of_line(degree: usize, knots: Vec<f64>, line: Vec<Point<D>>, closed: bool) -> Result<Self> {
        if closed { BSplineCurve::new_periodic(degree, knots, line) } else { BSplineCurve::new(degree, knots, line) }
    }
    fn line(&self) -> Vec<Point<D>> {
        self.control_points().to_vec()
    }
    fn spline(&self) -> (usize, &[f64], bool) {
        (self.degree(), self.knots(), self.is_periodic())
    }
}

impl<const D: usize> LineCurve for NurbsCurve<D> {
    type Coefficient = (Point<D>, f64);
    fn of_line(degree: usize, knots: Vec<f64>, line: Vec<(Point<D>, f64)>, closed: bool) -> Result<Self> {
        let (points, weights) = line.into_iter().unzip();
        if closed {
            NurbsCurve::new_periodic(degree, knots, points, weights)
        } else {
            NurbsCurve::new(degree, knots, points, weights)
        }
    }
    fn line(&self) -> Vec<(Point<D>, f64)> {
        self.control_points().iter().copied().zip(self.weights().iter().copied()).collect()
    }
    fn spline(&self) -> (usize, &[f64], bool) {
        (self.degree(), self.knots(), self.is_periodic())
    }
}

/// A tensor-product net with its degrees, knots and periodic flags in u and v.
struct NetSpline<T> {
    degrees: (usize, usize),
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    net: Vec<Vec<T>>,
    periodic: (bool, bool),
}

/// A surface's degrees, knots and periodic flags, each as (u, v).
type NetAxes<'a> = ((usize, usize), (&'a [f64], &'a [f64]), (bool, bool));

/// Applies `op` to the curve of every column (`Direction::U`) or row (`Direction::V`) of
/// `net`, given the surface's degrees, knots and periodic flags. The lines share their
/// knots, so they end with the same new degree, knots and closedness (read from the last
/// line); the other direction is unchanged.
fn map_net_lines<C: LineCurve>(
    direction: Direction,
    (degrees, (ku, kv), periodic): NetAxes<'_>,
    net: Vec<Vec<C::Coefficient>>,
    op: impl Fn(C) -> Result<C>,
) -> Result<NetSpline<C::Coefficient>>
where
    C::Coefficient: Clone,
{
    let (lines, degree, knots, closed) = match direction {
        Direction::U => (transpose(&net), degrees.0, ku, periodic.0),
        Direction::V => (net, degrees.1, kv, periodic.1),
    };
    let mut out_lines = Vec::with_capacity(lines.len());
    let mut last = None;
    for line in lines {
        let r = op(C::of_line(degree, knots.to_vec(), line, closed)?)?;
        out_lines.push(r.line());
        last = Some(r);
    }
    // Every line comes out with the same degree, knots and periodicity: the last one's.
    let (new_degree, new_knots, still_closed) = match &last {
        Some(r) => {
            let (d, k, p) = r.spline();
            (d, k.to_vec(), p)
        }
        None => (degree, Vec::new(), closed),
    };
    Ok(match direction {
        Direction::U => NetSpline {
            degrees: (new_degree, degrees.1),
            knots_u: new_knots,
            knots_v: kv.to_vec(),
            net: transpose(&out_lines),
            periodic: (still_closed, periodic.1),
        },
        Direction::V => NetSpline {
            degrees: (degrees.0, new_degree),
            knots_u: ku.to_vec(),
            knots_v: new_knots,
            net: out_lines,
            periodic: (periodic.0, still_closed),
        },
    })
}

impl<const D: usize> BSplineSurface<D> {
    /// Applies a curve operation to every column (u) or row (v) of the net.
    fn map_lines(&self, direction: Direction, op: impl Fn(BSplineCurve<D>) -> Result<BSplineCurve<D>>) -> Result<Self> {
        let net = self.control_points().to_vec();
        let m = map_net_lines(direction, (self.degrees(), self.knots(), self.periodic()), net, op)?;
        BSplineSurface::new(m.degrees, m.knots_u, m.knots_v, m.net, m.periodic)
    }

    /// Inserts the knots (u-knots for `Direction::U`, v-knots for `Direction::V`).
    pub fn refine(&self, direction: Direction, knots: &[f64]) -> Result<Self> {
        self.map_lines(direction, |c| c.refine(knots))
    }
    /// Raises the degree in one direction by `t`.
    pub fn elevate_degree(&self, direction: Direction, t: usize) -> Result<Self> {
        self.map_lines(direction, |c| c.elevate_degree(t))
    }
    /// The same surface with clamped knots in both directions (periodic directions are
    /// cut open at the start of their domain).
    pub fn clamped(&self) -> Result<Self> {
        self.map_lines(Direction::U, |c| c.clamped())?.map_lines(Direction::V, |c| c.clamped())
    }

    /// The Bézier patches: `patches[a][b]` covers the a-th u-span and b-th v-span.
    pub fn bezier_patches(&self) -> Result<Vec<Vec<BezierPatch<D>>>> {
        let clamped = self.clamped()?;
        let (p, q) = clamped.degrees();
        let (ku, kv) = clamped.knots();
        let breaks = |k: &[f64], deg: usize| -> Vec<f64> {
            let mut b: Vec<f64> = k[deg..k.len() - deg].to_vec();
            b.dedup();
            b
        };
        let (bu, bv) = (breaks(ku, p), breaks(kv, q));
        let interior = |b: &[f64], times: &dyn Fn(f64) -> usize| -> Vec<f64> {
            b[1..b.len() - 1].iter().flat_map(|&x| std::iter::repeat_n(x, times(x))).collect()
        };
        let mult = |k: &[f64], x: f64| k.iter().filter(|&&y| y == x).count();
        let iu = interior(&bu, &|x| p - mult(ku, x).min(p));
        let iv = interior(&bv, &|x| q - mult(kv, x).min(q));
        let full = clamped.refine(Direction::U, &iu)?.refine(Direction::V, &iv)?;
        let net = full.control_points();
        let mut out = Vec::with_capacity(bu.len() - 1);
        for a in 0..bu.len() - 1 {
            let mut row = Vec::with_capacity(bv.len() - 1);
            for b in 0..bv.len() - 1 {
                let patch: Vec<Vec<Point<D>>> = (0..=p).map(|i| net[a * p + i][b * q..=b * q + q].to_vec()).collect();
                row.push(BezierPatch {
                    u_range: Interval::new(bu[a], bu[a + 1]),
                    v_range: Interval::new(bv[b], bv[b + 1]),
                    surface: BezierSurface::new(patch)?,
                });
            }
            out.push(row);
        }
        Ok(out)
    }
}

impl<const D: usize> NurbsSurface<D> {
    fn map_lines(&self, direction: Direction, op: impl Fn(NurbsCurve<D>) -> Result<NurbsCurve<D>>) -> Result<Self> {
        let net = self
            .control_points()
            .iter()
            .zip(self.weights())
            .map(|(row, w)| row.iter().copied().zip(w.iter().copied()).collect())
            .collect();
        let m = map_net_lines(direction, (self.degrees(), self.knots(), self.periodic()), net, op)?;
        let (points, weights) = m.net.into_iter().map(|row| row.into_iter().unzip()).unzip();
        NurbsSurface::new(m.degrees, m.knots_u, m.knots_v, points, weights, m.periodic)
    }
    /// Inserts the knots in one direction.
    pub fn refine(&self, direction: Direction, knots: &[f64]) -> Result<Self> {
        self.map_lines(direction, |c| c.refine(knots))
    }
    /// Raises the degree in one direction by `t`.
    pub fn elevate_degree(&self, direction: Direction, t: usize) -> Result<Self> {
        self.map_lines(direction, |c| c.elevate_degree(t))
    }
}

impl<const D: usize> BezierSurface<D> {
    /// Splits at u = t (`Direction::U`) or v = t into two Bézier surfaces, each
    /// reparametrised to [0, 1]².
    pub fn split(&self, direction: Direction, t: f64) -> Result<(Self, Self)> {
        let lines = match direction {
            Direction::U => transpose(self.control_points()),
            Direction::V => self.control_points().to_vec(),
        };
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for line in lines {
            let (l, r) = crate::curve::BezierCurve::new(line)?.split(t);
            a.push(l.control_points().to_vec());
            b.push(r.control_points().to_vec());
        }
        Ok(match direction {
            Direction::U => (BezierSurface::new(transpose(&a))?, BezierSurface::new(transpose(&b))?),
            Direction::V => (BezierSurface::new(a)?, BezierSurface::new(b)?),
        })
    }
    /// Raises the degree in one direction by one.
    pub fn elevate(&self, direction: Direction) -> Result<Self> {
        let lines = match direction {
            Direction::U => transpose(self.control_points()),
            Direction::V => self.control_points().to_vec(),
        };
        let mut out = Vec::new();
        for line in lines {
            out.push(crate::curve::BezierCurve::new(line)?.elevate().control_points().to_vec());
        }
        BezierSurface::new(match direction {
            Direction::U => transpose(&out),
            Direction::V => out,
        })
    }
}
