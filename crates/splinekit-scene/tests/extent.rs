//! `extent()` of every registry kind: built from its example document, the box holds dense
//! samples of the shape (a new kind is covered by walking the registry).

use splinekit::Point;
use splinekit::curve::{Curve, CurveExtent};
use splinekit::query::Aabb;
use splinekit::surface::{Surface, SurfaceExtent};
use splinekit_scene::{CurveDocument, Curves, DimensionVisitor, SurfaceDocument, Surfaces};

/// Dense samples per direction (on top of every breakpoint).
const DENSE: usize = 2000;
const DENSE_SURFACE: usize = 100;

/// The parameters: `n` regular steps over the domain, and every breakpoint.
fn dense(domain: splinekit::Interval, breakpoints: Vec<f64>, n: usize) -> Vec<f64> {
    let mut ts: Vec<f64> = (0..=n).map(|i| domain.lerp(i as f64 / n as f64)).collect();
    ts.extend(breakpoints.into_iter().filter(|t| domain.start <= *t && *t <= domain.end));
    ts
}

/// The worst amount by which a point lies outside the box, relative to its diagonal
/// (0 inside); and whether the box is finite and not empty.
fn outside<const D: usize>(b: &Aabb<D>, points: impl Iterator<Item = Point<D>>) -> (f64, bool) {
    let ok = !b.is_empty() && b.min.iter().chain(b.max.iter()).all(|x| x.is_finite());
    let size = b.diagonal().max(1e-300);
    let worst = points
        .filter(|p| p.iter().all(|x| x.is_finite()))
        .map(|p| (0..D).map(|k| (b.min[k] - p[k]).max(p[k] - b.max[k]).max(0.0)).fold(0.0, f64::max))
        .fold(0.0, f64::max);
    (worst / size, ok)
}

struct CurveCheck;

impl DimensionVisitor<Curves> for CurveCheck {
    type Output = (f64, bool);
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> (f64, bool) {
        let ts = dense(c.domain(), c.breakpoints(), DENSE);
        outside(&c.extent(), ts.into_iter().map(|t| c.point(t)))
    }
}

struct SurfaceCheck;

impl DimensionVisitor<Surfaces> for SurfaceCheck {
    type Output = (f64, bool);
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> (f64, bool) {
        let us = dense(s.domain_u(), s.breakpoints_u(), DENSE_SURFACE);
        let vs = dense(s.domain_v(), s.breakpoints_v(), DENSE_SURFACE);
        let points = us.iter().flat_map(|&u| vs.iter().map(move |&v| (u, v))).map(|(u, v)| s.point(u, v));
        outside(&s.extent(), points)
    }
}

/// Rounding of the Newton steps' extremes, relative to the diagonal.
const ROUNDING: f64 = 1e-12;

/// Each kind's (name, (worst relative excess, finite and non-empty)) passes.
fn check_kinds(results: impl Iterator<Item = (&'static str, (f64, bool))>) {
    for (name, (worst, ok)) in results {
        assert!(ok, "{name}: empty or infinite extent");
        assert!(worst <= ROUNDING, "{name}: a sample lies {worst:e} (relative) outside the extent");
    }
}

#[test]
fn every_curve_kind_lies_in_its_extent() {
    check_kinds(CurveDocument::examples().into_iter().map(|doc| {
        let name = doc.type_name();
        (name, doc.build().unwrap_or_else(|e| panic!("{name}: {e}")).visit(CurveCheck))
    }));
}

#[test]
fn every_surface_kind_lies_in_its_extent() {
    check_kinds(SurfaceDocument::examples().into_iter().map(|doc| {
        let name = doc.type_name();
        (name, doc.build().unwrap_or_else(|e| panic!("{name}: {e}")).visit(SurfaceCheck))
    }));
}
