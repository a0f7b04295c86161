//! Axis-aligned bounding boxes in ℝᴰ, the bounding volumes of the query covers.

use std::borrow::Borrow;

use crate::Point;

/// The box [min₀, max₀] × … × [min_{D−1}, max_{D−1}].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb<const D: usize> {
    /// Lower corner.
    pub min: Point<D>,
    /// Upper corner.
    pub max: Point<D>,
}

impl<const D: usize> Aabb<D> {
    /// The empty box (min = +∞, max = −∞), which [`Aabb::include`] grows.
    pub fn empty() -> Self {
        Aabb { min: Point::<D>::repeat(f64::INFINITY), max: Point::<D>::repeat(f64::NEG_INFINITY) }
    }

    /// Whether the box holds no point: min ≤ max fails in some coordinate (an empty box,
    /// or a NaN corner).
    pub fn is_empty(&self) -> bool {
        !(0..D).all(|k| self.min[k] <= self.max[k])
    }

    /// Grows the box to hold `p`.
    #[inline]
    pub fn include(&mut self, p: &Point<D>) {
        self.min = self.min.inf(p);
        self.max = self.max.sup(p);
    }

    /// Whether `p` lies in the box grown by `margin` on every side.
    #[inline]
    pub fn contains(&self, p: &Point<D>, margin: f64) -> bool {
        (0..D).all(|k| self.min[k] - margin <= p[k] && p[k] <= self.max[k] + margin)
    }

    /// The smallest box holding every point, grown by `margin` on every side.
    pub fn around<'a>(points: impl IntoIterator<Item = &'a Point<D>>, margin: f64) -> Self {
        let mut min = Point::<D>::repeat(f64::INFINITY);
        let mut max = Point::<D>::repeat(f64::NEG_INFINITY);
        for p in points {
            min = min.inf(p);
            max = max.sup(p);
        }
        Aabb { min: min.add_scalar(-margin), max: max.add_scalar(margin) }
    }

    /// The box of the points' coordinates that are numbers, `None` for no points: per
    /// coordinate the least and greatest value by `f64::min`/`f64::max`, starting from the
    /// first point, so a NaN coordinate is passed over (where every point has NaN there,
    /// that coordinate of the box is NaN). [`Aabb::around`] compares instead, and a NaN
    /// coordinate can enter its box; meshes and samples that may hold NaN use this one.
    pub fn spanning<P: Borrow<Point<D>>>(points: impl IntoIterator<Item = P>) -> Option<Self> {
        let mut points = points.into_iter();
        let first = *points.next()?.borrow();
        Some(points.fold(Aabb { min: first, max: first }, |b, p| Aabb {
            min: b.min.zip_map(p.borrow(), f64::min),
            max: b.max.zip_map(p.borrow(), f64::max),
        }))
    }

    /// The length of the diagonal, |max − min|.
    #[inline]
    pub fn diagonal(&self) -> f64 {
        (self.max - self.min).norm()
    }

    /// The Euclidean distance from `q` to the box (0 inside): a lower bound on the
    /// distance from `q` to anything the box holds.
    #[inline]
    pub fn distance_to(&self, q: &Point<D>) -> f64 {
        let mut s = 0.0;
        for k in 0..D {
            let d = (self.min[k] - q[k]).max(q[k] - self.max[k]).max(0.0);
            s += d * d;
        }
        s.sqrt()
    }

    /// Whether the two boxes, each grown by `margin`, share a point.
    #[inline]
    pub fn overlaps(&self, other: &Aabb<D>, margin: f64) -> bool {
        (0..D).all(|k| self.min[k] <= other.max[k] + margin && other.min[k] <= self.max[k] + margin)
    }

    /// The smallest box holding both.
    #[inline]
    pub fn union(&self, other: &Aabb<D>) -> Self {
        Aabb { min: self.min.inf(&other.min), max: self.max.sup(&other.max) }
    }
}
