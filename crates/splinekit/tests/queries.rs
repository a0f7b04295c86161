//! Geometric queries against closed forms and brute force: projection onto curves and
//! surfaces.

mod common;
use common::*;
use splinekit::Point;
use splinekit::curve::model::{Circle, Ellipse, Rose};
use splinekit::curve::{BSplineCurve, CircleFrame, Curve, CurveNearest, NurbsCurve};
use splinekit::query::CurveProjector;
use std::f64::consts::{PI, TAU};

fn spline() -> BSplineCurve<2> {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 2.0), p2(2.0, -1.0), p2(3.0, 1.5), p2(4.0, 0.0), p2(5.0, 2.0), p2(6.0, -0.5)];
    BSplineCurve::clamped_uniform(3, pts).unwrap()
}

/// The smallest distance over 20 000 samples, refined by golden-section search around the
/// best sample: an independent upper bound on the global minimum.
fn brute_force_distance<const D: usize, C: Curve<D>>(c: &C, q: &Point<D>) -> f64 {
    let d = c.domain();
    let n = 20_000;
    let f = |t: f64| (c.point(t) - q).norm();
    let best = (0..=n).map(|i| d.lerp(i as f64 / n as f64)).min_by(|a, b| f(*a).total_cmp(&f(*b))).unwrap();
    let h = d.length() / n as f64;
    let (mut lo, mut hi) = (d.clamp(best - h), d.clamp(best + h));
    for _ in 0..100 {
        let (m1, m2) = (lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo));
        if f(m1) < f(m2) { hi = m2 } else { lo = m1 }
    }
    f(0.5 * (lo + hi)).min(f(best))
}

#[test]
fn nearest_point_on_a_cubic_spline_agrees_with_brute_force() {
    let c = spline();
    let projector = CurveProjector::new(&c);
    for i in 0..40 {
        let q = p2(-1.0 + 8.0 * ((i * 37) % 40) as f64 / 40.0, -2.0 + 5.0 * ((i * 13) % 40) as f64 / 40.0);
        let near = projector.nearest(&q, 0.0).unwrap();
        let brute = brute_force_distance(&c, &q);
        assert!(near.distance <= brute + 1e-12, "q = {q:?}: {} vs brute force {brute}", near.distance);
        assert!((c.point(near.t) - near.point).norm() < 1e-15);
        // The answer is a stationary point of the distance or an end of the domain.
        let d1 = c.derivative(near.t, 1);
        let at_end = near.t == 0.0 || near.t == 1.0;
        assert!(at_end || (near.point - q).dot(&d1).abs() < 1e-12 * d1.norm() * (1.0 + near.distance));
        assert!((near.distance - (near.point - q).norm()).abs() < 1e-15);
    }
}

#[test]
fn accuracy_bounds_the_distance_error() {
    let c = spline();
    let projector = CurveProjector::new(&c);
    for i in 0..20 {
        let q = p2(0.3 * i as f64, 2.5 - 0.2 * i as f64);
        let exact = projector.nearest(&q, 0.0).unwrap().distance;
        for accuracy in [1e-3, 1e-1] {
            let rough = projector.nearest(&q, accuracy).unwrap().distance;
            assert!(rough >= exact && rough <= exact + accuracy, "{rough} vs {exact} at accuracy {accuracy}");
        }
    }
}

#[test]
fn ellipse_from_inside_has_the_closed_form_local_minima() {
    // (a cos t, b sin t) from q = (x, 0): f′ = 2 sin t (a x − (a² − b²) cos t), so the
    // minima are at cos t = a x/(a² − b²) and the maxima at t = 0 and t = π.
    let (a, b, x) = (3.0, 2.0, 0.8);
    let e = Ellipse::new(a, b).unwrap();
    let q = p3(x, 0.0, 0.0);
    let minima = CurveProjector::new(&e).local_minima(&q, 0.0).unwrap();
    let t = (a * x / (a * a - b * b)).acos();
    assert_eq!(minima.len(), 2, "{minima:?}");
    assert!((minima[0].t - t).abs() < 1e-13, "{} vs {t}", minima[0].t);
    assert!((minima[1].t - (TAU - t)).abs() < 1e-13);
}

#[test]
fn circle_centre_is_one_minimum_at_the_start() {
    for r in [0.5, 1.0, 7.0] {
        let c = Circle::new(r).unwrap();
        let q = p3(0.0, 0.0, 0.0);
        let minima = CurveProjector::new(&c).local_minima(&q, 0.0).unwrap();
        assert_eq!(minima.len(), 1, "{minima:?}");
        assert_eq!(minima[0].t, 0.0);
        let near = c.closest_point(&q, 0.0).unwrap();
        assert!((near.distance - r).abs() < 1e-13 * r);
        // Off the plane, above the centre: still every point is nearest.
        let near = c.closest_point(&p3(0.0, 0.0, 2.0), 0.0).unwrap();
        assert!((near.distance - (r * r + 4.0f64).sqrt()).abs() < 1e-13);
    }
    let nurbs = NurbsCurve::circle(&CircleFrame::in_xy_plane(p2(1.0, 1.0), 2.0)).unwrap();
    let minima = CurveProjector::new(&nurbs).local_minima(&p2(1.0, 1.0), 0.0).unwrap();
    // Stored as an open curve: the whole domain is one flat stretch from its start.
    assert_eq!(minima.len(), 1, "{minima:?}");
}

#[test]
fn minima_at_kinks_ends_and_seams() {
    // A polyline: the corner (2, 2) is the nearest point of q above it, at the knot ½.
    let poly =
        BSplineCurve::new(1, vec![0.0, 0.0, 0.5, 1.0, 1.0], vec![p2(0.0, 0.0), p2(2.0, 2.0), p2(4.0, 0.0)]).unwrap();
    let near = poly.closest_point(&p2(2.0, 3.0), 0.0).unwrap();
    assert_eq!(near.t, 0.5);
    let minima = CurveProjector::new(&poly).local_minima(&p2(2.0, 3.0), 0.0).unwrap();
    assert_eq!(minima.len(), 1, "{minima:?}");
    // Both ends are local minima of a point below the middle; the kink is a maximum.
    let minima = CurveProjector::new(&poly).local_minima(&p2(2.0, -10.0), 0.0).unwrap();
    let ts: Vec<f64> = minima.iter().map(|m| m.t).collect();
    assert_eq!(ts, vec![0.0, 1.0]);
    // Closed curve: the nearest point lies across the seam at 2π.
    let c = Circle::new(1.0).unwrap();
    for a in [-1e-9, 0.0, 1e-9, -0.05, 0.05] {
        let q = p3(2.0 * f64::cos(a), 2.0 * f64::sin(a), 0.0);
        let minima = CurveProjector::new(&c).local_minima(&q, 0.0).unwrap();
        assert_eq!(minima.len(), 1, "a = {a}: {minima:?}");
        let expected = if a < 0.0 { TAU + a } else { a };
        let dt = (minima[0].t - expected).abs();
        assert!(dt < 1e-12 || (a == 0.0 && (minima[0].t - TAU).abs() < 1e-12), "a = {a}: {}", minima[0].t);
    }
}

#[test]
fn every_local_minimum_of_a_rose_from_its_centre() {
    // r = cos(3θ) has 3 petals; from the centre the distance |cos 3θ| has minima 0 at the
    // six parameters where the curve passes through the origin, θ = π/6 + kπ/3 on [0, 2π)
    // (the curve traces each petal twice over [0, 2π]).
    let rose = Rose::new(1.0, 3.0, true).unwrap();
    let minima = CurveProjector::new(&rose).local_minima(&p3(0.0, 0.0, 0.0), 1e-12).unwrap();
    let mut expected: Vec<f64> = (0..6).map(|k| PI / 6.0 + k as f64 * PI / 3.0).collect();
    expected.sort_by(f64::total_cmp);
    let got: Vec<f64> = minima.iter().map(|m| m.t).collect();
    assert_eq!(got.len(), 6, "{got:?}");
    for (g, e) in got.iter().zip(&expected) {
        assert!((g - e).abs() < 1e-12, "{got:?} vs {expected:?}");
    }
}

#[test]
fn bad_queries_are_errors() {
    let c = spline();
    let err = c.closest_point(&p2(f64::NAN, 0.0), 0.0).unwrap_err();
    assert!(err.to_string().starts_with("point"), "{err}");
    let err = c.closest_point(&p2(0.0, 0.0), -1.0).unwrap_err();
    assert!(err.to_string().starts_with("accuracy:"), "{err}");
}

mod surfaces {
    use super::*;
    use splinekit::query::{NearestOnSurface, SurfaceProjector};
    use splinekit::surface::model::{Cone, Plane, Sphere, Torus};
    use splinekit::surface::{BSplineSurface, Surface, SurfaceNearest};
    use std::f64::consts::FRAC_PI_2;

    fn bicubic() -> BSplineSurface<3> {
        let net: Vec<Vec<Point<3>>> = (0..7)
            .map(|i| (0..6).map(|j| p3(i as f64, j as f64, ((i * 3 + j * 5) % 7) as f64 * 0.4 - 1.0)).collect())
            .collect();
        BSplineSurface::clamped_uniform((3, 3), net).unwrap()
    }

    /// The smallest distance over a 120 × 120 grid, refined by coordinate-wise golden
    /// sections around the best sample: an independent upper bound on the minimum.
    fn brute_force<S: Surface<3>>(s: &S, q: &Point<3>) -> f64 {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let n = 120;
        let f = |u: f64, v: f64| (s.point(du.clamp(u), dv.clamp(v)) - q).norm();
        let mut best = (f64::INFINITY, 0.0, 0.0);
        for i in 0..=n {
            for j in 0..=n {
                let (u, v) = (du.lerp(i as f64 / n as f64), dv.lerp(j as f64 / n as f64));
                let d = f(u, v);
                if d < best.0 {
                    best = (d, u, v);
                }
            }
        }
        let (mut u, mut v) = (best.1, best.2);
        let (mut hu, mut hv) = (du.length() / n as f64, dv.length() / n as f64);
        for _ in 0..60 {
            let cands = [(u + hu, v), (u - hu, v), (u, v + hv), (u, v - hv)];
            let (d, cu, cv) =
                cands.iter().map(|&(a, b)| (f(a, b), a, b)).fold(best, |m, c| if c.0 < m.0 { c } else { m });
            if d < best.0 {
                best = (d, cu, cv);
                u = du.clamp(cu);
                v = dv.clamp(cv);
            } else {
                hu *= 0.5;
                hv *= 0.5;
            }
        }
        best.0
    }

    fn check_on_surface<S: Surface<3>>(s: &S, m: &NearestOnSurface<3>, q: &Point<3>) {
        assert!((s.point(m.u, m.v) - m.point).norm() < 1e-14 * (1.0 + m.point.norm()));
        assert!((m.distance - (m.point - q).norm()).abs() < 1e-15 * (1.0 + m.distance));
    }

    #[test]
    fn nearest_point_on_a_bicubic_agrees_with_brute_force() {
        let s = bicubic();
        let projector = SurfaceProjector::new(&s);
        for i in 0..12 {
            let q = p3(-1.0 + 0.7 * i as f64, 5.5 - 0.54 * i as f64, ((i * 7) % 5) as f64 - 2.0);
            let near = projector.nearest(&q, 0.0).unwrap();
            check_on_surface(&s, &near, &q);
            let brute = brute_force(&s, &q);
            assert!(near.distance <= brute + 1e-12, "q = {q:?}: {} vs brute force {brute}", near.distance);
            // Every local minimum is a point of the surface no nearer than the global one.
            let minima = projector.local_minima(&q, 0.0).unwrap();
            assert!(!minima.is_empty());
            for m in &minima {
                check_on_surface(&s, m, &q);
                assert!(m.distance >= near.distance - 1e-12);
            }
            let least = minima.iter().map(|m| m.distance).fold(f64::INFINITY, f64::min);
            assert!((least - near.distance).abs() < 1e-12, "q = {q:?}: nearest {near:?}, minima {minima:?}");
        }
    }

    #[test]
    fn sphere_radial_points_poles_and_centre() {
        let r = 2.0;
        let sphere = Sphere::new(r).unwrap();
        let projector = SurfaceProjector::new(&sphere);
        for q in [p3(3.0, 1.0, -0.5), p3(-0.1, -4.0, 2.0), p3(0.5, 0.25, 0.1)] {
            let minima = projector.local_minima(&q, 0.0).unwrap();
            assert_eq!(minima.len(), 1, "{q:?}: {minima:?}");
            let expected = q.normalize() * r;
            assert!((minima[0].point - expected).norm() < 1e-12, "{:?} vs {expected:?}", minima[0].point);
            let near = projector.nearest(&q, 0.0).unwrap();
            assert!((near.point - expected).norm() < 1e-12);
        }
        // Above a pole: the pole itself, reported once, with v at the end of the domain.
        for z in [5.0, -5.0, 0.5] {
            let q = p3(0.0, 0.0, z);
            let minima = projector.local_minima(&q, 0.0).unwrap();
            assert_eq!(minima.len(), 1, "z = {z}: {minima:?}");
            assert!((minima[0].v.abs() - FRAC_PI_2).abs() < 1e-12);
            assert!((minima[0].distance - (z.abs() - r).abs()).abs() < 1e-12);
        }
        // At the centre every point is nearest: one minimum at distance r.
        let minima = projector.local_minima(&p3(0.0, 0.0, 0.0), 0.0).unwrap();
        assert_eq!(minima.len(), 1, "{minima:?}");
        assert!((minima[0].distance - r).abs() < 1e-12);
        assert!((projector.nearest(&p3(0.0, 0.0, 0.0), 0.0).unwrap().distance - r).abs() < 1e-12);
    }

    #[test]
    fn torus_across_the_seam_and_from_its_centre() {
        let torus = Torus::new(3.0, 1.0).unwrap();
        let projector = SurfaceProjector::new(&torus);
        for a in [-0.2f64, 0.0, 1e-10, 2.0] {
            let q = p3(4.5 * a.cos(), 4.5 * a.sin(), 0.3);
            let centre = p3(3.0 * a.cos(), 3.0 * a.sin(), 0.0);
            let expected = centre + (q - centre).normalize();
            let minima = projector.local_minima(&q, 0.0).unwrap();
            assert_eq!(minima.len(), 1, "a = {a}: {minima:?}");
            assert!((minima[0].point - expected).norm() < 1e-12);
        }
        // From a point in the hole off the centre: one minimum on the inner equator.
        let minima = projector.local_minima(&p3(0.5, 0.0, 0.0), 0.0).unwrap();
        assert_eq!(minima.len(), 1, "{minima:?}");
        assert!((minima[0].point - p3(2.0, 0.0, 0.0)).norm() < 1e-12);
        // From the centre the whole inner equator is nearest: reported once.
        let minima = projector.local_minima(&p3(0.0, 0.0, 0.0), 0.0).unwrap();
        assert_eq!(minima.len(), 1, "{minima:?}");
        assert!((minima[0].distance - 2.0).abs() < 1e-12);
    }

    #[test]
    fn cone_apex_and_circles_of_nearest_points() {
        let (r, h) = (1.0, 2.0);
        let cone = Cone::new(r, h).unwrap();
        let projector = SurfaceProjector::new(&cone);
        // Above the apex: the apex.
        let near = projector.nearest(&p3(0.0, 0.0, 3.0), 0.0).unwrap();
        assert!((near.point - p3(0.0, 0.0, h)).norm() < 1e-12 && (near.v - 1.0).abs() < 1e-12);
        let minima = projector.local_minima(&p3(0.0, 0.0, 3.0), 0.0).unwrap();
        assert_eq!(minima.len(), 1, "{minima:?}");
        // Inside on the axis: a circle at v = (r² + h z)/(r² + h²), reported once.
        let z = 0.5;
        let v = (r * r + h * z) / (r * r + h * h);
        let d = (r * r * (1.0 - v) * (1.0 - v) + (h * v - z) * (h * v - z)).sqrt();
        let minima = projector.local_minima(&p3(0.0, 0.0, z), 0.0).unwrap();
        assert_eq!(minima.len(), 1, "{minima:?}");
        assert!((minima[0].distance - d).abs() < 1e-12 && (minima[0].v - v).abs() < 1e-9);
        assert!((projector.nearest(&p3(0.0, 0.0, z), 0.0).unwrap().distance - d).abs() < 1e-12);
    }

    #[test]
    fn plane_feet_edges_and_corners() {
        let plane = Plane::new(p3(0.0, 0.0, 0.0), p3(2.0, 0.0, 0.0), p3(0.0, 1.0, 0.0)).unwrap();
        let projector = SurfaceProjector::new(&plane);
        let cases = [
            (p3(1.0, 0.5, 3.0), (0.5, 0.5)),
            (p3(5.0, 0.5, 1.0), (1.0, 0.5)),
            (p3(-1.0, -1.0, 0.0), (0.0, 0.0)),
            (p3(1.5, 2.0, -1.0), (0.75, 1.0)),
        ];
        for (q, (u, v)) in cases {
            let minima = projector.local_minima(&q, 0.0).unwrap();
            assert_eq!(minima.len(), 1, "{q:?}: {minima:?}");
            assert!((minima[0].u - u).abs() < 1e-14 && (minima[0].v - v).abs() < 1e-14, "{q:?}: {minima:?}");
            let near = plane.closest_point(&q, 0.0).unwrap();
            assert!((near.u - u).abs() < 1e-14 && (near.v - v).abs() < 1e-14);
        }
    }
}

mod intersections {
    use super::*;
    use splinekit::curve::BezierCurve;
    use splinekit::curve::model::{Helix, Line};
    use splinekit::query::{IntersectionKind, intersect_curves, self_intersections};

    fn unit_circle(cx: f64, cy: f64) -> NurbsCurve<2> {
        NurbsCurve::circle(&CircleFrame::in_xy_plane(p2(cx, cy), 1.0)).unwrap()
    }

    fn segment(a: Point<2>, b: Point<2>) -> BSplineCurve<2> {
        BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![a, b]).unwrap()
    }

    fn assert_on_both<const D: usize, A: Curve<D>, B: Curve<D>>(
        a: &A,
        b: &B,
        r: &splinekit::query::CurveIntersections<D>,
        tol: f64,
    ) {
        for p in &r.points {
            assert!((a.point(p.t_a) - p.point).norm() <= tol && (b.point(p.t_b) - p.point).norm() <= tol, "{p:?}");
        }
    }

    #[test]
    fn line_and_circle() {
        let circle = unit_circle(0.0, 0.0);
        let line = segment(p2(-3.0, 0.5), p2(3.0, 0.5));
        let r = intersect_curves(&line, &circle, 1e-12).unwrap();
        assert_on_both(&line, &circle, &r, 1e-12);
        let xs: Vec<f64> = r.points.iter().map(|p| p.point[0]).collect();
        let x = 0.75f64.sqrt();
        assert_eq!(xs.len(), 2, "{r:?}");
        assert!((xs[0] + x).abs() < 1e-14 && (xs[1] - x).abs() < 1e-14, "{xs:?}");
        assert!(r.points.iter().all(|p| p.kind == IntersectionKind::Crossing && (p.point[1] - 0.5).abs() < 1e-14));
        // Touching at the top: one tangent contact.
        let line = segment(p2(-3.0, 1.0), p2(3.0, 1.0));
        let r = intersect_curves(&line, &circle, 1e-9).unwrap();
        assert_eq!(r.points.len(), 1, "{r:?}");
        assert_eq!(r.points[0].kind, IntersectionKind::Tangent);
        assert!((r.points[0].point - p2(0.0, 1.0)).norm() < 1e-4);
        // Passing above: nothing.
        let line = segment(p2(-3.0, 1.001), p2(3.0, 1.001));
        assert!(intersect_curves(&line, &circle, 1e-9).unwrap().points.is_empty());
    }

    #[test]
    fn circle_and_circle() {
        for d in [1.0, 0.3, 1.9] {
            let (a, b) = (unit_circle(0.0, 0.0), unit_circle(d, 0.0));
            let r = intersect_curves(&a, &b, 1e-12).unwrap();
            assert_on_both(&a, &b, &r, 1e-12);
            let (x, y) = (d / 2.0, (1.0 - d * d / 4.0).sqrt());
            let mut pts: Vec<Point<2>> = r.points.iter().map(|p| p.point).collect();
            pts.sort_by(|p, q| p[1].total_cmp(&q[1]));
            assert_eq!(pts.len(), 2, "d = {d}: {r:?}");
            assert!((pts[0] - p2(x, -y)).norm() < 1e-13 && (pts[1] - p2(x, y)).norm() < 1e-13, "{pts:?}");
        }
        // The same circle twice: one overlap over the whole domain.
        let r = intersect_curves(&unit_circle(0.0, 0.0), &unit_circle(0.0, 0.0), 1e-9).unwrap();
        assert_eq!(r.overlaps.len(), 1, "{r:?}");
        assert!(r.overlaps[0].a.start <= 1e-12 && r.overlaps[0].a.end >= 1.0 - 1e-12);
        assert!(r.points.is_empty(), "{r:?}");
    }

    #[test]
    fn collinear_segments_overlap_as_intervals() {
        let a = segment(p2(0.0, 0.0), p2(4.0, 0.0));
        let b = segment(p2(6.0, 0.0), p2(1.0, 0.0));
        let r = intersect_curves(&a, &b, 1e-9).unwrap();
        assert_eq!(r.overlaps.len(), 1, "{r:?}");
        let o = r.overlaps[0];
        assert!((o.a.start - 0.25).abs() < 1e-12 && (o.a.end - 1.0).abs() < 1e-12, "{o:?}");
        assert!((o.b.0 - 1.0).abs() < 1e-12 && (o.b.1 - 0.4).abs() < 1e-12, "{o:?}");
    }

    #[test]
    fn parabola_and_cubic_against_the_roots_of_the_implicit_equation() {
        // The parabola y = x² as a quadratic Bézier curve; substituting the cubic's x(t),
        // y(t) into y − x² gives a degree-6 polynomial whose roots in [0, 1] are the
        // intersections (the resultant of the two parametric curves).
        let parabola = BezierCurve::new(vec![p2(-2.0, 4.0), p2(0.0, -4.0), p2(2.0, 4.0)]).unwrap();
        let cubic = BezierCurve::new(vec![p2(-2.0, 5.0), p2(-1.0, -5.0), p2(1.0, 8.0), p2(2.0, 2.0)]).unwrap();
        let f = |t: f64| {
            let p = cubic.point(t);
            p[1] - p[0] * p[0]
        };
        let n = 100_000;
        let mut roots = Vec::new();
        for i in 0..n {
            let (mut lo, mut hi) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
            if f(lo) == 0.0 || f(lo).signum() != f(hi).signum() {
                for _ in 0..100 {
                    let m = 0.5 * (lo + hi);
                    if f(lo).signum() == f(m).signum() && f(m) != 0.0 { lo = m } else { hi = m }
                }
                roots.push(0.5 * (lo + hi));
            }
        }
        let r = intersect_curves(&cubic, &parabola, 1e-12).unwrap();
        assert_on_both(&cubic, &parabola, &r, 1e-12);
        let got: Vec<f64> = r.points.iter().map(|p| p.t_a).collect();
        assert_eq!(got.len(), roots.len(), "{got:?} vs {roots:?}");
        assert_eq!(roots.len(), 3);
        for (g, e) in got.iter().zip(&roots) {
            assert!((g - e).abs() < 1e-12, "{got:?} vs {roots:?}");
        }
    }

    #[test]
    fn helix_and_a_line_in_space() {
        let helix = Helix::new(1.0, 1.0, 3.0).unwrap();
        let line = Line::new(p3(1.0, 0.0, -1.0), p3(1.0, 0.0, 5.0)).unwrap();
        let r = intersect_curves(&helix, &line, 1e-12).unwrap();
        // (cos t, sin t, t/2π) meets x = 1, y = 0 at t = 2πk: z = 0, 1, 2, 3.
        let zs: Vec<f64> = r.points.iter().map(|p| p.point[2]).collect();
        assert_eq!(zs.len(), 4, "{r:?}");
        for (k, z) in zs.iter().enumerate() {
            assert!((z - k as f64).abs() < 1e-12, "{zs:?}");
        }
    }

    #[test]
    fn a_looped_cubic_crosses_itself_once() {
        let c = BezierCurve::new(vec![p2(0.0, 0.0), p2(3.0, 2.0), p2(-1.0, 2.0), p2(2.0, 0.0)]).unwrap();
        let r = self_intersections(&c, 1e-12).unwrap();
        assert_eq!(r.points.len(), 1, "{r:?}");
        let p = r.points[0];
        assert!(p.t_b - p.t_a > 0.1 && (c.point(p.t_a) - c.point(p.t_b)).norm() < 1e-12, "{p:?}");
        // A simple arc does not.
        let arc = BezierCurve::new(vec![p2(0.0, 0.0), p2(1.0, 2.0), p2(2.0, 2.0), p2(3.0, 0.0)]).unwrap();
        assert!(self_intersections(&arc, 1e-12).unwrap().points.is_empty());
        // Nor does a closed circle at its seam.
        assert!(self_intersections(&Circle::new(1.0).unwrap(), 1e-12).unwrap().points.is_empty());
    }
}

/// Self-intersections of a cubic B-spline that winds `windings` times about a centre that
/// drifts around a circle of radius 0.3 (every winding crosses the others; the drift stops
/// short of a full turn so that the ends do not meet), against
/// an independent count: proper crossings of non-adjacent segments of a dense polyline.
#[test]
fn a_many_times_winding_bspline_crosses_itself_where_its_polyline_does() {
    use splinekit::query::self_intersections;
    let windings = 8;
    let n = 16 * windings;
    let pts: Vec<Point<2>> = (0..n)
        .map(|i| {
            let t = i as f64 / (n - 1) as f64 * 0.97 * TAU;
            let w = windings as f64 * t;
            p2(w.cos() + 0.3 * t.cos(), w.sin() + 0.3 * t.sin())
        })
        .collect();
    let c = BSplineCurve::clamped_uniform(3, pts).unwrap();
    let r = self_intersections(&c, 1e-10).unwrap();
    assert!(r.overlaps.is_empty());
    for p in &r.points {
        assert!(p.t_b - p.t_a > 1e-3 && (c.point(p.t_a) - c.point(p.t_b)).norm() < 1e-9, "{p:?}");
    }
    // The polyline's crossings, found through a grid of cells.
    let m = 40_000;
    let poly: Vec<Point<2>> = (0..=m).map(|k| c.point(k as f64 / m as f64)).collect();
    let cell = 0.02;
    let key = |p: &Point<2>| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: std::collections::HashMap<(i64, i64), Vec<usize>> = std::collections::HashMap::new();
    for i in 0..m {
        let (a, b) = (key(&poly[i]), key(&poly[i + 1]));
        for x in a.0.min(b.0)..=a.0.max(b.0) {
            for y in a.1.min(b.1)..=a.1.max(b.1) {
                grid.entry((x, y)).or_default().push(i);
            }
        }
    }
    let cross = |i: usize, j: usize| {
        let (p, q, r, s) = (poly[i], poly[i + 1], poly[j], poly[j + 1]);
        let side = |a: &Point<2>, b: &Point<2>, c: &Point<2>| (b - a).perp(&(c - a));
        side(&p, &q, &r) * side(&p, &q, &s) < 0.0 && side(&r, &s, &p) * side(&r, &s, &q) < 0.0
    };
    let mut found = std::collections::HashSet::new();
    for segs in grid.values() {
        for (k, &i) in segs.iter().enumerate() {
            for &j in &segs[k + 1..] {
                let (i, j) = (i.min(j), i.max(j));
                if j > i + 1 && cross(i, j) {
                    found.insert((i, j));
                }
            }
        }
    }
    assert_eq!(r.points.len(), found.len(), "splinekit {} crossings, the polyline {}", r.points.len(), found.len());
    for &(i, j) in &found {
        let (ti, tj) = (i as f64 / m as f64, j as f64 / m as f64);
        assert!(
            r.points.iter().any(|p| (p.t_a - ti).abs() < 2.0 / m as f64 && (p.t_b - tj).abs() < 2.0 / m as f64),
            "the polyline crosses itself near t = {ti}, {tj}"
        );
    }
}

mod arc_length {
    use super::*;
    use splinekit::curve::model::Helix;
    use splinekit::ops::length::arc_length;
    use splinekit::query::{ArcLengthCurve, ArcLengthTable};

    #[test]
    fn circle_and_helix_invert_in_closed_form() {
        let r = 2.5;
        let circle = Circle::new(r).unwrap();
        let table = ArcLengthTable::new(&circle, 1e-12).unwrap();
        assert!((table.total() - TAU * r).abs() < 1e-11);
        for s in [0.0, 0.1, 3.0, 10.0, TAU * r] {
            assert!((table.parameter_at(s).unwrap() - s / r).abs() < 1e-11, "s = {s}");
        }
        // (cos t, sin t, t/2π) has speed √(1 + 1/4π²).
        let helix = Helix::new(1.0, 1.0, 2.0).unwrap();
        let speed = (1.0 + 1.0 / (4.0 * PI * PI)).sqrt();
        let table = ArcLengthTable::new(&helix, 1e-12).unwrap();
        for s in [0.5, 4.0, 12.0] {
            assert!((table.parameter_at(s).unwrap() - s / speed).abs() < 1e-11);
        }
        assert!(table.parameter_at(-1.0).is_err() && table.parameter_at(100.0).is_err());
        assert!(ArcLengthTable::new(&helix, 0.0).is_err());
    }

    #[test]
    fn equal_length_samples_of_a_spline() {
        let c = spline();
        let table = ArcLengthTable::new(&c, 1e-10).unwrap();
        let ts = table.equal_length_parameters(25).unwrap();
        let step = table.total() / 24.0;
        for w in ts.windows(2) {
            assert!((arc_length(&c, splinekit::Interval::new(w[0], w[1]), 1e-12) - step).abs() < 1e-9, "{w:?}");
        }
    }

    #[test]
    fn arc_length_curve_has_unit_speed_and_the_curvature_vector() {
        let c = spline();
        let b = ArcLengthCurve::new(&c, 1e-12).unwrap();
        let total = b.domain().end;
        for k in 1..20 {
            let s = total * k as f64 / 20.0;
            let mut o = [Point::<2>::zeros(); 4];
            b.eval(s, &mut o);
            let t = b.table().parameter_at(s).unwrap();
            assert!((o[0] - c.point(t)).norm() < 1e-14);
            assert!((o[1].norm() - 1.0).abs() < 1e-12, "|b′| = {}", o[1].norm());
            // b″ is the curvature vector: perpendicular to b′, of length κ.
            assert!(o[1].dot(&o[2]).abs() < 1e-10);
            assert!((o[2].norm() - c.curvature(t)).abs() < 1e-9 * (1.0 + c.curvature(t)));
            // b‴ against central differences of b″.
            let h = 1e-4;
            let fd = (b.derivative(s + h, 2) - b.derivative(s - h, 2)) / (2.0 * h);
            assert!((fd - o[3]).norm() < 1e-5 * (1.0 + o[3].norm()), "{fd:?} vs {:?}", o[3]);
        }
    }
}
