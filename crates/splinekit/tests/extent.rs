//! `extent()`: exact boxes for closed forms (the circle, the ellipse, the unit square
//! patch, the sphere, the torus), the control-point box of splines, and the sampled
//! extent of the default method against dense sampling.

use splinekit::Point;
use splinekit::curve::model::{Butterfly, Circle, Ellipse, Lissajous};
use splinekit::curve::{BSplineCurve, Curve, CurveExtent};
use splinekit::query::Aabb;
use splinekit::query::extent::{curve_extent, surface_extent};
use splinekit::surface::model::{Plane, Sphere, Torus};
use splinekit::surface::{BezierSurface, PlacedSurface, SurfaceExtent};

fn p3(x: f64, y: f64, z: f64) -> Point<3> {
    Point::<3>::new(x, y, z)
}

fn assert_box(b: &Aabb<3>, min: Point<3>, max: Point<3>, tol: f64) {
    assert!((b.min - min).amax() <= tol && (b.max - max).amax() <= tol, "{b:?} against {min:?} … {max:?}");
}

/// The box of `n` + 1 regular samples of a curve: an inner approximation of its box.
fn dense_curve_box<C: Curve<3>>(c: &C, n: usize) -> Aabb<3> {
    let d = c.domain();
    let pts: Vec<Point<3>> = (0..=n).map(|i| c.point(d.lerp(i as f64 / n as f64))).collect();
    Aabb::around(&pts, 0.0)
}

#[test]
fn a_circle_and_an_ellipse_have_their_exact_boxes() {
    let b = Circle::new(2.0).unwrap().extent();
    assert_box(&b, p3(-2.0, -2.0, 0.0), p3(2.0, 2.0, 0.0), 1e-15);
    // (a cos t, b sin t): [−a, a] × [−b, b].
    let b = Ellipse::new(3.0, 0.5).unwrap().extent();
    assert_box(&b, p3(-3.0, -0.5, 0.0), p3(3.0, 0.5, 0.0), 4e-16);
}

#[test]
fn the_unit_square_patch_has_the_unit_square() {
    let plane = Plane::new(p3(0.0, 0.0, 0.0), p3(1.0, 0.0, 0.0), p3(0.0, 1.0, 0.0)).unwrap();
    assert_box(&plane.extent(), p3(0.0, 0.0, 0.0), p3(1.0, 1.0, 0.0), 0.0);
    let net = vec![vec![p3(0.0, 0.0, 0.0), p3(0.0, 1.0, 0.0)], vec![p3(1.0, 0.0, 0.0), p3(1.0, 1.0, 0.0)]];
    let bezier = BezierSurface::new(net).unwrap();
    assert_box(&bezier.extent(), p3(0.0, 0.0, 0.0), p3(1.0, 1.0, 0.0), 0.0);
    // The sampled method agrees with the control net here (a bilinear patch).
    assert_box(&surface_extent(&bezier), p3(0.0, 0.0, 0.0), p3(1.0, 1.0, 0.0), 0.0);
}

#[test]
fn a_sphere_and_a_torus_have_their_exact_boxes() {
    // Sphere of radius 2: [−2, 2]³ (x, y extremes on the equator, z at the poles).
    assert_box(&Sphere::new(2.0).unwrap().extent(), p3(-2.0, -2.0, -2.0), p3(2.0, 2.0, 2.0), 1e-15);
    // Torus R = 3, r = 1: [−4, 4]² × [−1, 1].
    assert_box(&Torus::new(3.0, 1.0).unwrap().extent(), p3(-4.0, -4.0, -1.0), p3(4.0, 4.0, 1.0), 1e-15);
}

#[test]
fn a_tilted_sphere_has_its_exact_box_from_interior_extremes() {
    // Rotating the sphere about x by 0.3 moves the y and z extremes off the iso-lines
    // through the samples: the Newton steps on the gradient must find them.
    let s = Box::new(Sphere::new(1.5).unwrap());
    let tilted = PlacedSurface::new(s, [0.0; 3], [0.0, -0.3f64.sin(), 0.3f64.cos()], [1.0, 0.0, 0.0]);
    assert_box(&tilted.unwrap().extent(), p3(-1.5, -1.5, -1.5), p3(1.5, 1.5, 1.5), 1e-14);
}

#[test]
fn a_bspline_gives_its_control_box_and_the_sampled_method_its_tight_box() {
    let pts = vec![p3(0.0, 0.0, 0.0), p3(1.0, 2.0, -1.0), p3(3.0, -1.0, 0.5), p3(4.0, 1.0, 2.0), p3(5.0, 0.0, 0.0)];
    let c = BSplineCurve::<3>::clamped_uniform(3, pts.clone()).unwrap();
    assert_eq!(c.extent(), Aabb::around(&pts, 0.0));
    let dense = dense_curve_box(&c, 100_000);
    let sampled = curve_extent(&c);
    // The dense box lies inside the true one and within h²·|c″|/8 ≈ 1e-9 of it.
    assert!((sampled.min - dense.min).amax() < 1e-9 && (sampled.max - dense.max).amax() < 1e-9);
    assert!((0..3).all(|k| sampled.min[k] <= dense.min[k] + 1e-15 && sampled.max[k] >= dense.max[k] - 1e-15));
}

/// The curve's extent holds `n` + 1 dense samples (to 10⁻¹²) and falls short of their box
/// by less than `gap` (what samples that far apart can miss of an extreme).
fn assert_holds_dense_samples<C: Curve<3>>(c: &C, n: usize, gap: f64) {
    let (b, dense) = (c.extent(), dense_curve_box(c, n));
    assert!((0..3).all(|k| b.min[k] <= dense.min[k] + 1e-12 && b.max[k] >= dense.max[k] - 1e-12), "{b:?} {dense:?}");
    assert!((b.min - dense.min).amax() < gap && (b.max - dense.max).amax() < gap, "{b:?} {dense:?}");
}

#[test]
fn a_lissajous_figure_holds_its_dense_samples() {
    assert_holds_dense_samples(&Lissajous::new([1.0, 2.0, 0.5], [3.0, 5.0, 2.0], 0.5).unwrap(), 200_000, 1e-8);
}

#[test]
fn the_butterfly_holds_its_dense_samples() {
    // r = e^{cos t} − 2 cos 4t − sin⁵(t/12) over [0, 24π]: 96 periods of cos 4t, far more
    // than the regular samples, so the halving where the tangent turns has to find them.
    // Samples 1.9·10⁻⁴ apart fall short of the extremes by up to h²|c″|/8 ≈ 10⁻⁶.
    assert_holds_dense_samples(&Butterfly::new(1.0).unwrap(), 400_000, 1e-6);
}

#[test]
fn spanning_passes_over_nan_coordinates_and_around_grows_by_its_margin() {
    let pts = [p3(1.0, f64::NAN, 0.0), p3(-1.0, 2.0, 0.5), p3(0.0, -3.0, f64::NAN)];
    let b = Aabb::spanning(pts).unwrap();
    assert_eq!((b.min, b.max), (p3(-1.0, -3.0, 0.0), p3(1.0, 2.0, 0.5)));
    assert!(Aabb::<3>::spanning(std::iter::empty::<Point<3>>()).is_none());
    let mut e = Aabb::<3>::empty();
    assert!(e.is_empty());
    e.include(&p3(1.0, 2.0, 3.0));
    assert!(!e.is_empty() && e.contains(&p3(1.0, 2.0, 3.0), 0.0) && !e.contains(&p3(1.0, 2.0, 3.1), 0.05));
    let a = Aabb::around(&[p3(1.0, 0.0, 0.0), p3(-1.0, 2.0, 0.5)], 0.5);
    assert_eq!((a.min, a.max), (p3(-1.5, -0.5, -0.5), p3(1.5, 2.5, 1.0)));
}
