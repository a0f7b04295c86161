//! Homogeneous coordinates (w·P, w) so that rational curves reuse the polynomial
//! algorithms (knot insertion, elevation, splitting) unchanged.

use crate::{Coefficient, Point};

/// The homogeneous point (w P, w).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Homogeneous<const D: usize> {
    /// w · P.
    pub weighted: Point<D>,
    /// w.
    pub weight: f64,
}

impl<const D: usize> Homogeneous<D> {
    /// Lifts P with weight w to (w P, w).
    pub fn lift(p: &Point<D>, w: f64) -> Self {
        Homogeneous { weighted: p * w, weight: w }
    }
    /// Projects back to P = (w P)/w.
    pub fn project(&self) -> Point<D> {
        self.weighted / self.weight
    }
}

impl<const D: usize> std::ops::Add for Homogeneous<D> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Homogeneous { weighted: self.weighted + o.weighted, weight: self.weight + o.weight }
    }
}
impl<const D: usize> std::ops::Sub for Homogeneous<D> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Homogeneous { weighted: self.weighted - o.weighted, weight: self.weight - o.weight }
    }
}
impl<const D: usize> std::ops::Mul<f64> for Homogeneous<D> {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        Homogeneous { weighted: self.weighted * s, weight: self.weight * s }
    }
}
impl<const D: usize> std::ops::AddAssign for Homogeneous<D> {
    fn add_assign(&mut self, o: Self) {
        self.weighted += o.weighted;
        self.weight += o.weight;
    }
}
impl<const D: usize> Coefficient for Homogeneous<D> {
    fn zero() -> Self {
        Homogeneous { weighted: Point::<D>::zeros(), weight: 0.0 }
    }
}

/// A norm for tolerance checks on coefficients.
pub trait CoefficientNorm: Coefficient {
    /// Euclidean norm (of the homogeneous vector for rational coefficients).
    fn norm(&self) -> f64;
}
impl<const D: usize> CoefficientNorm for Point<D> {
    fn norm(&self) -> f64 {
        nalgebra::Matrix::norm(self)
    }
}
impl<const D: usize> CoefficientNorm for Homogeneous<D> {
    fn norm(&self) -> f64 {
        (self.weighted.norm_squared() + self.weight * self.weight).sqrt()
    }
}
impl CoefficientNorm for f64 {
    fn norm(&self) -> f64 {
        self.abs()
    }
}
