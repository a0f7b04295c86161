//! Points in documents: arrays of numbers, all of one dimension.

use splinekit::Point;

use crate::error::{DocumentError, Result};

/// The common dimension of a list of points (≥ 1 point, all the same length, finite).
pub fn dimension_of(field: &str, points: &[Vec<f64>]) -> Result<usize> {
    let first = points.first().ok_or_else(|| DocumentError::new(field, "expected at least 1 point, got 0"))?;
    let d = first.len();
    if d == 0 {
        return Err(DocumentError::new(format!("{field}[0]"), "a point needs at least 1 coordinate, got 0"));
    }
    for (i, p) in points.iter().enumerate() {
        if p.len() != d {
            return Err(DocumentError::new(
                format!("{field}[{i}]"),
                format!("expected {d} coordinates like the first point, got {}", p.len()),
            ));
        }
        for (j, v) in p.iter().enumerate() {
            if !v.is_finite() {
                return Err(DocumentError::new(
                    format!("{field}[{i}][{j}]"),
                    format!("coordinate is not finite ({v})"),
                ));
            }
            check_magnitude(format_args!("{field}[{i}][{j}]"), *v)?;
        }
    }
    Ok(d)
}

/// Converts to fixed-dimension points (dimension already checked).
pub fn to_points<const D: usize>(points: &[Vec<f64>]) -> Vec<Point<D>> {
    points.iter().map(|p| Point::<D>::from_column_slice(p)).collect()
}

/// A single point of dimension D, named `field` in errors.
pub fn to_point<const D: usize>(field: &str, p: &[f64]) -> Result<Point<D>> {
    if p.len() != D {
        return Err(DocumentError::new(field, format!("expected {D} coordinates, got {}", p.len())));
    }
    if let Some((j, v)) = p.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(DocumentError::new(format!("{field}[{j}]"), format!("coordinate is not finite ({v})")));
    }
    for (j, v) in p.iter().enumerate() {
        check_magnitude(format_args!("{field}[{j}]"), *v)?;
    }
    Ok(Point::<D>::from_column_slice(p))
}

/// Back to plain arrays.
pub fn from_points<const D: usize>(points: &[Point<D>]) -> Vec<Vec<f64>> {
    points.iter().map(|p| p.iter().copied().collect()).collect()
}

/// Checks that every number of a list is finite.
pub fn check_finite_list(field: &str, values: &[f64]) -> Result<()> {
    match values.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        Some((i, v)) => Err(DocumentError::new(format!("{field}[{i}]"), format!("value is not finite ({v})"))),
        None => values.iter().enumerate().try_for_each(|(i, v)| check_magnitude(format_args!("{field}[{i}]"), *v)),
    }
}

/// Refuses a number beyond ±[`MAX_MAGNITUDE`](crate::budget::MAX_MAGNITUDE), where
/// evaluation would overflow.
pub fn check_magnitude(field: impl std::fmt::Display, v: f64) -> Result<()> {
    if v.abs() > crate::budget::MAX_MAGNITUDE {
        return Err(DocumentError::new(
            field.to_string(),
            format!(
                "{v:e} is beyond ±{:e}, where evaluating the shape would overflow double precision",
                crate::budget::MAX_MAGNITUDE
            ),
        ));
    }
    Ok(())
}
