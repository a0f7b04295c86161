//! Surfaces: tensor products against an independent row-by-row de Boor, partials against
//! finite differences, grids, closed forms, seams.

mod common;
use common::*;
use proptest::prelude::*;
use splinekit::curve::Curve;
use splinekit::surface::TrimmedSurface;
use splinekit::surface::model::*;
use splinekit::surface::surface_ops::BezierPatch;
use splinekit::surface::*;
use splinekit::{Interval, Point};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

fn net(nu: usize, nv: usize) -> Vec<Vec<Point<3>>> {
    (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| p3(i as f64, j as f64, ((i * 7 + j * 3) % 5) as f64 * 0.3 - (i as f64 * 0.4).sin()))
                .collect()
        })
        .collect()
}

fn sample_surface() -> BSplineSurface<3> {
    let ku = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
    let kv = vec![0.0, 0.0, 0.0, 1.0, 2.5, 3.0, 3.0, 3.0];
    BSplineSurface::new((3, 2), ku, kv, net(7, 5), (false, false)).unwrap()
}

/// ∂^{i+j} by central differences of the (i−1, j) or (i, j−1) partial.
fn fd<S: Surface<3> + ?Sized>(s: &S, u: f64, v: f64, i: usize, j: usize, h: f64) -> Point<3> {
    if i > 0 {
        let f = |x: f64| s.partial(x, v, i - 1, j);
        (f(u - 2.0 * h) - f(u + 2.0 * h) + (f(u + h) - f(u - h)) * 8.0) / (12.0 * h)
    } else {
        let f = |y: f64| s.partial(u, y, i, j - 1);
        (f(v - 2.0 * h) - f(v + 2.0 * h) + (f(v + h) - f(v - h)) * 8.0) / (12.0 * h)
    }
}

fn check_partials<S: Surface<3> + ?Sized>(s: &S, name: &str) {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let h = 1e-5 * du.length().min(dv.length()).max(1e-3);
    for a in 1..5 {
        for b in 1..5 {
            let (u, v) = (du.lerp(a as f64 / 5.0 + 0.017), dv.lerp(b as f64 / 5.0 + 0.013));
            let mut out = [Point::<3>::zeros(); 9];
            s.eval_partials(u, v, 2, 2, &mut out);
            for i in 0..=2 {
                for j in 0..=2 {
                    if i + j == 0 {
                        continue;
                    }
                    let f = fd(s, u, v, i, j, h);
                    let scale = out[i * 3 + j].norm().max(1.0);
                    assert!(
                        (out[i * 3 + j] - f).norm() < 1e-5 * scale,
                        "{name}: ∂({i},{j}) at ({u}, {v}): {} vs {}",
                        out[i * 3 + j],
                        f
                    );
                }
            }
        }
    }
}

#[test]
fn bspline_surface_matches_row_by_row_de_boor() {
    let s = sample_surface();
    let (ku, kv) = s.knots();
    for a in 0..=20 {
        for b in 0..=20 {
            let (u, v) = (a as f64 / 20.0, 3.0 * b as f64 / 20.0);
            let rows: Vec<Point<3>> = s.control_points().iter().map(|r| de_boor(2, kv, r, v)).collect();
            let expected = de_boor(3, ku, &rows, u);
            assert!((s.point(u, v) - expected).norm() < 1e-13, "({u}, {v})");
        }
    }
    check_partials(&s, "bspline surface");
}

#[test]
fn grid_evaluation_equals_pointwise() {
    let s = sample_surface();
    let us: Vec<f64> = (0..17).map(|i| i as f64 / 16.0).collect();
    let vs: Vec<f64> = (0..13).map(|j| 3.0 * ((j * 5) % 13) as f64 / 12.0).collect();
    let mut grid = vec![Point::<3>::zeros(); us.len() * vs.len() * 6];
    s.eval_grid(&us, &vs, 1, 2, &mut grid);
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            let mut single = [Point::<3>::zeros(); 6];
            s.eval_partials(u, v, 1, 2, &mut single);
            for k in 0..6 {
                let g = grid[(a * vs.len() + b) * 6 + k];
                assert!((g - single[k]).norm() < 1e-12 * single[k].norm().max(1.0), "({u}, {v}) partial {k}");
            }
        }
    }
}

#[test]
fn periodic_directions_close_smoothly() {
    let n = 6;
    let ring: Vec<Vec<Point<3>>> = (0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            (0..4)
                .map(|j| {
                    p3(
                        (2.0 + 0.3 * j as f64) * a.cos(),
                        (2.0 + 0.3 * j as f64) * a.sin(),
                        j as f64 + 0.2 * (i % 2) as f64,
                    )
                })
                .collect()
        })
        .collect();
    let ku: Vec<f64> = (0..n + 4).map(|i| i as f64).collect();
    let kv = vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
    let s = BSplineSurface::new((3, 2), ku, kv, ring, (true, false)).unwrap();
    assert!(s.is_closed_u() && !s.is_closed_v());
    let d = s.domain_u();
    for b in 0..=10 {
        let v = 0.2 * b as f64;
        let mut a = [Point::<3>::zeros(); 9];
        let mut c = [Point::<3>::zeros(); 9];
        s.eval_partials(d.start, v, 2, 2, &mut a);
        s.eval_partials(d.end - 1e-13, v, 2, 2, &mut c);
        for k in 0..9 {
            assert!((a[k] - c[k]).norm() < 1e-9 * a[k].norm().max(1.0), "partial {k} at the seam, v = {v}");
        }
    }
    check_partials(&s, "periodic bspline surface");
}

#[test]
fn bezier_surface_is_the_clamped_bspline_surface() {
    let n = net(4, 3);
    let b = BezierSurface::new(n.clone()).unwrap();
    let s = BSplineSurface::clamped_uniform((3, 2), n).unwrap();
    for a in 0..=10 {
        for c in 0..=10 {
            let (u, v) = (a as f64 / 10.0, c as f64 / 10.0);
            let mut x = [Point::<3>::zeros(); 9];
            let mut y = [Point::<3>::zeros(); 9];
            b.eval_partials(u, v, 2, 2, &mut x);
            s.eval_partials(u, v, 2, 2, &mut y);
            for k in 0..9 {
                assert!((x[k] - y[k]).norm() < 1e-12 * y[k].norm().max(1.0));
            }
        }
    }
    check_partials(&b, "bezier surface");
}

#[test]
fn nurbs_sphere_cylinder_torus_are_exact() {
    let s = NurbsSurface::sphere(2.5).unwrap();
    let t = NurbsSurface::torus(3.0, 1.0).unwrap();
    let c = NurbsSurface::cylinder(1.5, 2.0).unwrap();
    for a in 0..=40 {
        for b in 0..=40 {
            let (u, v) = (a as f64 / 40.0, b as f64 / 40.0);
            assert!((s.point(u, v).norm() - 2.5).abs() < 1e-14 * 2.5 * 4.0);
            let p = t.point(u, v);
            let ring = p3(p[0], p[1], 0.0).normalize() * 3.0;
            assert!(((p - ring).norm() - 1.0).abs() < 1e-14 * 8.0);
            let q = c.point(u, v);
            assert!((q[0].hypot(q[1]) - 1.5).abs() < 1e-14 * 4.0);
        }
    }
    // Gaussian curvature of the sphere: 1/r² everywhere (away from the poles).
    for (u, v) in [(0.1, 0.3), (0.6, 0.5), (0.9, 0.8)] {
        let k = s.curvatures(u, v).unwrap();
        assert!((k.gaussian - 1.0 / 6.25).abs() < 1e-9, "K = {}", k.gaussian);
        assert!((k.mean.abs() - 0.4).abs() < 1e-9);
    }
    check_partials(&s, "nurbs sphere");
}

#[test]
fn model_surfaces_have_correct_partials_curvature_and_seams() {
    let surfaces: Vec<(&str, Box<dyn Surface<3>>)> = vec![
        ("plane", Box::new(Plane::new(p3(1.0, 2.0, 3.0), p3(1.0, 0.0, 0.5), p3(0.0, 2.0, 0.0)).unwrap())),
        ("cylinder", Box::new(Cylinder::new(1.0, 2.0).unwrap())),
        ("cone", Box::new(Cone::new(1.0, 2.0).unwrap())),
        ("sphere", Box::new(Sphere::new(2.0).unwrap())),
        ("torus", Box::new(Torus::new(3.0, 1.0).unwrap())),
        ("mobius", Box::new(MobiusStrip::new(1.0, 0.4).unwrap())),
        ("klein", Box::new(KleinBottle::new(3.0).unwrap())),
        ("enneper", Box::new(Enneper::new(1.5).unwrap())),
        ("helicoid", Box::new(Helicoid::new(1.0, 1.0, 2.0).unwrap())),
        ("seashell", Box::new(Seashell::new(1.0, 2.0, 0.1, 2.0).unwrap())),
        ("apple", Box::new(Apple::new(1.0).unwrap())),
        ("heart", Box::new(HeartSurface::new(1.0).unwrap())),
    ];
    for (name, s) in &surfaces {
        check_partials(s.as_ref(), name);
        let (du, dv) = (s.domain_u(), s.domain_v());
        for k in 0..=8 {
            let t = k as f64 / 8.0;
            if s.is_closed_u() {
                let (a, b) = (s.point(du.start, dv.lerp(t)), s.point(du.end, dv.lerp(t)));
                assert!((a - b).norm() < 1e-12 * a.norm().max(1.0), "{name}: u-seam");
                let (a, b) = (s.partial(du.start, dv.lerp(t), 1, 0), s.partial(du.end - 1e-14, dv.lerp(t), 1, 0));
                assert!((a - b).norm() < 1e-9 * a.norm().max(1.0), "{name}: u-seam tangent");
            }
            if s.is_closed_v() {
                let (a, b) = (s.point(du.lerp(t), dv.start), s.point(du.lerp(t), dv.end));
                assert!((a - b).norm() < 1e-12 * a.norm().max(1.0), "{name}: v-seam");
            }
        }
    }
    // Closed forms: torus K = cos v / (r (R + r cos v)), sphere H = −1/r with outward normals… sign aside.
    let torus = Torus::new(3.0, 1.0).unwrap();
    for v in [0.0, 0.7, PI / 2.0, 2.0, PI] {
        let k = torus.curvatures(0.4, v).unwrap();
        assert!((k.gaussian - v.cos() / (3.0 + v.cos())).abs() < 1e-12, "torus K at v = {v}");
    }
    let sphere = Sphere::new(2.0).unwrap();
    let c = sphere.curvatures(1.0, 0.3).unwrap();
    assert!((c.gaussian - 0.25).abs() < 1e-13 && (c.mean.abs() - 0.5).abs() < 1e-13);
    assert!((c.principal.0 - c.principal.1).abs() < 1e-7);
    // Enneper is minimal: H = 0.
    let e = Enneper::new(1.5).unwrap();
    assert!(e.curvatures(0.3, -0.7).unwrap().mean.abs() < 1e-12);
    // Normals are unit and orthogonal to both partials.
    let n = torus.normal(0.3, 1.1).unwrap();
    assert!((n.norm() - 1.0).abs() < 1e-15);
    assert!(n.dot(&torus.partial(0.3, 1.1, 1, 0)).abs() < 1e-13 && n.dot(&torus.partial(0.3, 1.1, 0, 1)).abs() < 1e-13);
    // At the poles of the sphere the normal is undefined.
    assert!(sphere.normal(0.3, FRAC_PI_2).is_none() || sphere.normal(0.3, FRAC_PI_2).unwrap().norm() > 0.99);
}

#[test]
fn isocurves_and_closest_points() {
    let s = sample_surface();
    let iso = s.iso_curve_u(0.37).unwrap();
    let generic = IsoCurve::new(&s, Direction::U, 0.37);
    for k in 0..=30 {
        let v = 3.0 * k as f64 / 30.0;
        assert!((iso.point(v) - s.point(0.37, v)).norm() < 1e-13);
        assert!((generic.derivative(v, 1) - s.partial(0.37, v, 0, 1)).norm() < 1e-12);
    }
    let torus = Torus::new(3.0, 1.0).unwrap();
    // A point off the tube: the nearest point is along the tube's radius, across the seam.
    let q = p3(4.5 * (-0.2f64).cos(), 4.5 * (-0.2f64).sin(), 0.3);
    let near = torus.closest_point(&q, 0.0).unwrap();
    let (u, v, p) = (near.u, near.v, near.point);
    let centre = p3(3.0 * (-0.2f64).cos(), 3.0 * (-0.2f64).sin(), 0.0);
    let expected = centre + (q - centre).normalize();
    assert!((p - expected).norm() < 1e-10, "{p} vs {expected} at ({u}, {v})");
    assert!((u - (TAU - 0.2)).abs() < 1e-9);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn affine_invariance_of_bspline_surfaces(
        a in prop::array::uniform9(-2.0f64..2.0),
        b in prop::array::uniform3(-5.0f64..5.0),
        u in 0.0f64..1.0,
        v in 0.0f64..3.0,
    ) {
        let s = sample_surface();
        let m = nalgebra::Matrix3::from_row_slice(&a);
        let t = Point::<3>::from(b);
        let mapped = s.map_points(|p| m * p + t);
        let lhs = mapped.point(u, v);
        let rhs = m * s.point(u, v) + t;
        prop_assert!((lhs - rhs).norm() < 1e-12 * (1.0 + rhs.norm()));
    }
}

#[test]
fn model_surfaces_match_their_formulas_written_directly() {
    let klein = KleinBottle::new(3.0).unwrap();
    let mobius = MobiusStrip::new(1.0, 0.4).unwrap();
    let apple = Apple::new(1.0).unwrap();
    let shell = Seashell::new(1.0, 2.0, 0.1, 2.0).unwrap();
    let heart = HeartSurface::new(1.0).unwrap();
    let cone = Cone::new(1.5, 2.0).unwrap();
    let helicoid = Helicoid::new(1.0, 1.0, 2.0).unwrap();
    let enneper = Enneper::new(1.5).unwrap();
    for a in 0..=12 {
        for b in 0..=12 {
            let (s, t) = (a as f64 / 12.0, b as f64 / 12.0);
            let (u, v) = (TAU * s, TAU * t);
            let r = 3.0 + (u / 2.0).cos() * v.sin() - (u / 2.0).sin() * (2.0 * v).sin();
            let k = p3(r * u.cos(), r * u.sin(), (u / 2.0).sin() * v.sin() + (u / 2.0).cos() * (2.0 * v).sin());
            assert!((klein.point(u, v) - k).norm() < 1e-13);
            let w = -0.4 + 0.8 * t;
            let m =
                p3((1.0 + w * (u / 2.0).cos()) * u.cos(), (1.0 + w * (u / 2.0).cos()) * u.sin(), w * (u / 2.0).sin());
            assert!((mobius.point(u, w) - m).norm() < 1e-14);
            let va = -PI + TAU * t;
            let ap = p3(
                u.cos() * (4.0 + 3.8 * va.cos()),
                u.sin() * (4.0 + 3.8 * va.cos()),
                (va.cos() + va.sin() - 1.0) * (1.0 + va.sin()) * (1.0 - PI * va / 10.0).ln() + 7.5 * va.sin(),
            );
            assert!((apple.point(u, va) - ap).norm() < 1e-12, "apple at ({u}, {va})");
            let sv = 1.0 - v / TAU;
            let ring = sv * (1.0 + u.cos()) + 0.1;
            let sh = p3(ring * (2.0 * v).cos(), ring * (2.0 * v).sin(), 2.0 * v / TAU + sv * u.sin());
            assert!((shell.point(u, v) - sh).norm() < 1e-13);
            let hu = PI * s;
            let hx = 16.0 * hu.sin().powi(3);
            let hy = 13.0 * hu.cos() - 5.0 * (2.0 * hu).cos() - 2.0 * (3.0 * hu).cos() - (4.0 * hu).cos();
            assert!((heart.point(hu, v) - p3(hx * v.cos(), hx * v.sin(), hy)).norm() < 1e-12);
            assert!(
                (cone.point(u, t) - p3(1.5 * (1.0 - t) * u.cos(), 1.5 * (1.0 - t) * u.sin(), 2.0 * t)).norm() < 1e-14
            );
            let hv = -1.0 + 2.0 * t;
            assert!(
                (helicoid.point(2.0 * u, hv) - p3(hv * (2.0 * u).cos(), hv * (2.0 * u).sin(), 2.0 * u / TAU)).norm()
                    < 1e-14
            );
            let (x, y) = (-1.5 + 3.0 * s, -1.5 + 3.0 * t);
            let en = p3(x - x * x * x / 3.0 + x * y * y, y - y * y * y / 3.0 + y * x * x, x * x - y * y);
            assert!((enneper.point(x, y) - en).norm() < 1e-13);
        }
    }
}

#[test]
fn grid_points_and_normals_match_pointwise_evaluation() {
    let s = sample_surface();
    let t = NurbsSurface::torus(3.0, 1.0).unwrap();
    let us: Vec<f64> = (0..9).map(|i| i as f64 / 8.0).collect();
    let vs: Vec<f64> = (0..7).map(|j| j as f64 / 6.0).collect();
    let vs3: Vec<f64> = vs.iter().map(|v| 3.0 * v).collect();
    for (surface, vs) in [(&s as &dyn Surface<3>, &vs3), (&t as &dyn Surface<3>, &vs)] {
        let mut pts = vec![Point::<3>::zeros(); us.len() * vs.len()];
        let mut nrm = pts.clone();
        surface.eval_grid_with_normals(&us, vs, &mut pts, &mut nrm);
        for (a, &u) in us.iter().enumerate() {
            for (b, &v) in vs.iter().enumerate() {
                let k = a * vs.len() + b;
                assert!((pts[k] - surface.point(u, v)).norm() < 1e-13);
                match surface.normal(u, v) {
                    Some(n) => assert!((nrm[k] - n).norm() < 1e-12, "normal at ({u}, {v})"),
                    None => assert_eq!(nrm[k], Point::<3>::zeros()),
                }
            }
        }
    }
}

#[test]
fn normals_of_tiny_and_huge_surfaces() {
    for scale in [1e-170, 1e170] {
        let p = Plane::new(p3(0.0, 0.0, 0.0), p3(scale, 0.0, 0.0), p3(0.0, scale, 0.0)).unwrap();
        let n = p.normal(0.5, 0.5).expect("a normal exists at any scale");
        assert!((n - p3(0.0, 0.0, 1.0)).norm() < 1e-15, "scale {scale}: {n}");
    }
}

fn max_surface_distance(a: &dyn Surface<3>, b: &dyn Surface<3>) -> f64 {
    let (du, dv) = (a.domain_u(), a.domain_v());
    let mut m: f64 = 0.0;
    for i in 0..=25 {
        for j in 0..=25 {
            let (u, v) = (du.lerp(i as f64 / 25.0), dv.lerp(j as f64 / 25.0));
            m = m.max((a.point(u, v) - b.point(u, v)).norm());
        }
    }
    m
}

#[test]
fn surface_refinement_elevation_and_bezier_patches_keep_the_shape() {
    let s = sample_surface();
    let r = s.refine(Direction::U, &[0.1, 0.5, 0.77]).unwrap().refine(Direction::V, &[1.5, 2.2]).unwrap();
    assert_eq!(r.control_points().len(), 10);
    assert_eq!(r.control_points()[0].len(), 7);
    assert!(max_surface_distance(&s, &r) < 1e-12);
    let e = s.elevate_degree(Direction::U, 1).unwrap().elevate_degree(Direction::V, 2).unwrap();
    assert_eq!(e.degrees(), (4, 4));
    assert!(max_surface_distance(&s, &e) < 1e-12);
    let patches = s.bezier_patches().unwrap();
    assert_eq!((patches.len(), patches[0].len()), (3, 3));
    for row in &patches {
        for BezierPatch {
            u_range: Interval { start: u0, end: u1 },
            v_range: Interval { start: v0, end: v1 },
            surface: patch,
        } in row
        {
            for k in 0..=6 {
                let (a, b) = (k as f64 / 6.0, (6 - k) as f64 / 6.0);
                let p = patch.point(a, b);
                let q = s.point(u0 + (u1 - u0) * a, v0 + (v1 - v0) * b);
                assert!((p - q).norm() < 1e-12);
            }
        }
    }
    // NURBS: the torus refined and elevated stays on the torus.
    let t = NurbsSurface::torus(3.0, 1.0).unwrap();
    let t2 = t.refine(Direction::V, &[0.1, 0.6]).unwrap().elevate_degree(Direction::U, 1).unwrap();
    assert!(max_surface_distance(&t, &t2) < 1e-12);
    // Periodic directions stay periodic.
    let n = 6;
    let ring: Vec<Vec<Point<3>>> = (0..n)
        .map(|i| {
            (0..3)
                .map(|j| {
                    p3(
                        (TAU * i as f64 / n as f64).cos() * (2.0 + j as f64),
                        (TAU * i as f64 / n as f64).sin(),
                        j as f64,
                    )
                })
                .collect()
        })
        .collect();
    let ps = BSplineSurface::new(
        (3, 2),
        (0..n + 4).map(|i| i as f64).collect(),
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        ring,
        (true, false),
    )
    .unwrap();
    let pr = ps.refine(Direction::U, &[3.5]).unwrap();
    assert!(pr.is_closed_u());
    assert!(max_surface_distance(&ps, &pr) < 1e-12);
    // Bézier surfaces split and elevate.
    let b = BezierSurface::new(net(4, 3)).unwrap();
    let (l, rr) = b.split(Direction::V, 0.3).unwrap();
    assert!((l.point(0.4, 1.0) - b.point(0.4, 0.3)).norm() < 1e-13);
    assert!((rr.point(0.4, 0.0) - b.point(0.4, 0.3)).norm() < 1e-13);
    let be = b.elevate(Direction::U).unwrap();
    assert_eq!(be.degrees(), (4, 2));
    assert!(max_surface_distance(&b, &be) < 1e-13);
}

#[test]
fn surface_fitting_equals_the_dense_least_squares_solution() {
    use splinekit::basis::basis_function;
    use splinekit::fit::{KnotPlacement, Parametrization, SurfaceFitOptions, fit_surface, interpolate_surface};
    let (mu, mv) = (14, 11);
    let f = |u: f64, v: f64| p3(u, v, (3.0 * u).sin() * (2.0 * v).cos() + 0.1 * u * v);
    let grid: Vec<Vec<Point<3>>> =
        (0..mu).map(|a| (0..mv).map(|b| f(a as f64 / (mu - 1) as f64, b as f64 / (mv - 1) as f64)).collect()).collect();
    let opts = SurfaceFitOptions {
        degrees: (3, 2),
        control_points: (7, 5),
        params: Parametrization::Uniform,
        knots: KnotPlacement::Uniform,
    };
    let s = fit_surface(&grid, &opts).unwrap();
    // Dense least squares over all mu·mv equations with (A_u ⊗ A_v).
    let (ku, kv) = s.knots();
    let (nu, nv) = (7, 5);
    let mut a = nalgebra::DMatrix::<f64>::zeros(mu * mv, nu * nv);
    let mut rhs = nalgebra::DMatrix::<f64>::zeros(mu * mv, 3);
    for i in 0..mu {
        for j in 0..mv {
            let (u, v) = (i as f64 / (mu - 1) as f64, j as f64 / (mv - 1) as f64);
            for r in 0..nu {
                for c in 0..nv {
                    a[(i * mv + j, r * nv + c)] = basis_function(ku, 3, r, u) * basis_function(kv, 2, c, v);
                }
            }
            for k in 0..3 {
                rhs[(i * mv + j, k)] = grid[i][j][k];
            }
        }
    }
    let x = a.svd(true, true).solve(&rhs, 1e-14).unwrap();
    for r in 0..nu {
        for c in 0..nv {
            for k in 0..3 {
                let got = s.control_points()[r][c][k];
                assert!((got - x[(r * nv + c, k)]).abs() < 1e-11, "P[{r}][{c}][{k}]: {got} vs {}", x[(r * nv + c, k)]);
            }
        }
    }
    // A bicubic-by-quadratic polynomial surface is reproduced exactly.
    let poly = |u: f64, v: f64| p3(u * u * u - u, v * v + u * v, 1.0 + u * u * v * v);
    let pg: Vec<Vec<Point<3>>> = (0..mu)
        .map(|a| (0..mv).map(|b| poly(a as f64 / (mu - 1) as f64, b as f64 / (mv - 1) as f64)).collect())
        .collect();
    let ps = fit_surface(&pg, &opts).unwrap();
    for (a, row) in pg.iter().enumerate() {
        for (b, q) in row.iter().enumerate() {
            assert!((ps.point(a as f64 / (mu - 1) as f64, b as f64 / (mv - 1) as f64) - q).norm() < 1e-12);
        }
    }
    // Interpolation passes through every grid point.
    let is = interpolate_surface(&grid, (3, 3), Parametrization::Uniform).unwrap();
    for (a, row) in grid.iter().enumerate() {
        for (b, q) in row.iter().enumerate() {
            assert!((is.point(a as f64 / (mu - 1) as f64, b as f64 / (mv - 1) as f64) - q).norm() < 1e-12);
        }
    }
    let bad = SurfaceFitOptions {
        degrees: (3, 2),
        control_points: (20, 5),
        params: Parametrization::Uniform,
        knots: KnotPlacement::Uniform,
    };
    assert!(fit_surface(&grid, &bad).unwrap_err().to_string().contains("control_points"));
}

#[test]
fn revolved_surfaces_turn_profiles_about_any_axis() {
    use splinekit::curve::BSplineCurve;
    use splinekit::curve::model::{Circle, Line};
    use splinekit::surface::derived::RevolvedSurface;
    // A circle of radius 1 about (3, 0, 0) in the xz-plane, revolved about z: the torus.
    let tube = BSplineCurve::new_periodic(
        3,
        (0..12).map(|i| i as f64).collect(),
        (0..8)
            .map(|i| {
                let a = TAU * i as f64 / 8.0;
                p3(3.0 + a.cos(), 0.0, a.sin())
            })
            .collect(),
    )
    .unwrap();
    let rev = RevolvedSurface::new(Box::new(tube), p3(0.0, 0.0, 0.0), p3(0.0, 0.0, 2.0), TAU).unwrap();
    assert!(rev.is_closed_u() && rev.is_closed_v());
    check_partials(&rev, "revolved b-spline");
    let circle_profile = splinekit::curve::NurbsCurve::circle(&splinekit::curve::CircleFrame {
        center: p3(3.0, 0.0, 0.0),
        x_axis: p3(1.0, 0.0, 0.0),
        y_axis: p3(0.0, 0.0, 1.0),
        radius: 1.0,
    })
    .unwrap();
    let exact = RevolvedSurface::new(Box::new(circle_profile), p3(0.0, 0.0, 0.0), p3(0.0, 0.0, 1.0), TAU).unwrap();
    for a in 0..=8 {
        for b in 0..=8 {
            let p = exact.point(TAU * a as f64 / 8.0, b as f64 / 8.0);
            let ring = p3(p[0], p[1], 0.0).normalize() * 3.0;
            assert!(((p - ring).norm() - 1.0).abs() < 1e-14);
        }
    }
    // A partial revolution about a tilted axis through a point keeps distances to the axis.
    let seg = Line::new(p3(1.0, 0.0, 0.0), p3(2.0, 1.0, 1.0)).unwrap();
    let part = RevolvedSurface::new(Box::new(seg), p3(0.5, 0.5, 0.0), p3(1.0, 1.0, 1.0), 1.0).unwrap();
    assert!(!part.is_closed_u());
    check_partials(&part, "partial revolution");
    let k = p3(1.0, 1.0, 1.0).normalize();
    let dist = |p: Point<3>| {
        let x = p - p3(0.5, 0.5, 0.0);
        (x - k * k.dot(&x)).norm()
    };
    for a in 0..=4 {
        assert!((dist(part.point(a as f64 / 4.0, 0.3)) - dist(part.point(0.0, 0.3))).abs() < 1e-14);
    }
    assert!(
        RevolvedSurface::new(Box::new(Circle::new(1.0).unwrap()), p3(0.0, 0.0, 0.0), p3(0.0, 0.0, 0.0), 1.0).is_err()
    );
}

#[test]
fn ruled_surfaces_are_bilinear_and_extrusions_translate() {
    use splinekit::curve::BezierCurve;
    use splinekit::curve::model::Line;
    use splinekit::surface::derived::{Extrusion, RuledSurface};
    // Ruled surface between two lines is bilinear; extrusion is a translation.
    let ruled = RuledSurface::new(
        Box::new(Line::new(p2(0.0, 0.0), p2(2.0, 0.0)).unwrap()),
        Box::new(Line::new(p2(0.0, 1.0), p2(2.0, 3.0)).unwrap()),
    )
    .unwrap();
    assert!((ruled.point(0.5, 0.5) - p2(1.0, 1.0)).norm() < 1e-15);
    let bez = BezierCurve::new(vec![p3(0.0, 0.0, 0.0), p3(1.0, 2.0, 0.0), p3(2.0, 0.0, 1.0)]).unwrap();
    let ext = Extrusion::new(Box::new(bez.clone()), p3(0.0, 0.0, 2.0)).unwrap();
    assert!((ext.point(0.3, 0.25) - (bez.point(0.3) + p3(0.0, 0.0, 0.5))).norm() < 1e-15);
    check_partials(&ext, "extrusion");
}

#[test]
fn coons_patches_interpolate_their_boundaries() {
    use splinekit::curve::BezierCurve;
    use splinekit::curve::model::Line;
    use splinekit::surface::derived::{CoonsBlend, CoonsPatch};
    // Coons patches interpolate their boundaries and reproduce bilinear surfaces.
    let corner = |u: f64, v: f64| p3(u, v, u * v);
    let line = |a: Point<3>, b: Point<3>| -> Box<dyn Curve<3>> { Box::new(Line::new(a, b).unwrap()) };
    for blend in [CoonsBlend::Linear, CoonsBlend::Cubic] {
        let coons = CoonsPatch::new(
            line(corner(0.0, 0.0), corner(1.0, 0.0)),
            line(corner(0.0, 1.0), corner(1.0, 1.0)),
            line(corner(0.0, 0.0), corner(0.0, 1.0)),
            line(corner(1.0, 0.0), corner(1.0, 1.0)),
            blend,
        )
        .unwrap();
        for a in 0..=6 {
            for b in 0..=6 {
                let (u, v) = (a as f64 / 6.0, b as f64 / 6.0);
                let (p, q) = (coons.point(u, v), corner(u, v));
                // Bilinear blending reproduces bilinear surfaces; cubic blending (positions
                // only) reproduces the ruled x and y but not z = uv.
                if blend == CoonsBlend::Linear {
                    assert!((p - q).norm() < 1e-14, "{blend:?} at ({u}, {v})");
                } else {
                    assert!((p[0] - u).abs() < 1e-14 && (p[1] - v).abs() < 1e-14);
                    let f1 = |t: f64| t * t * (3.0 - 2.0 * t);
                    assert!((p[2] - (f1(v) * u + f1(u) * v - f1(u) * f1(v))).abs() < 1e-14);
                }
            }
        }
        let curved = CoonsPatch::new(
            Box::new(BezierCurve::new(vec![p3(0.0, 0.0, 0.0), p3(0.5, -0.3, 0.4), p3(1.0, 0.0, 0.0)]).unwrap()),
            Box::new(BezierCurve::new(vec![p3(0.0, 1.0, 0.0), p3(0.5, 1.2, 0.8), p3(1.0, 1.0, 0.2)]).unwrap()),
            Box::new(BezierCurve::new(vec![p3(0.0, 0.0, 0.0), p3(-0.2, 0.5, 0.1), p3(0.0, 1.0, 0.0)]).unwrap()),
            line(p3(1.0, 0.0, 0.0), p3(1.0, 1.0, 0.2)),
            blend,
        )
        .unwrap();
        check_partials(&curved, "coons");
        for a in 0..=8 {
            let t = a as f64 / 8.0;
            let bottom = BezierCurve::new(vec![p3(0.0, 0.0, 0.0), p3(0.5, -0.3, 0.4), p3(1.0, 0.0, 0.0)]).unwrap();
            assert!((curved.point(t, 0.0) - bottom.point(t)).norm() < 1e-15);
            assert!((curved.point(1.0, t) - p3(1.0, t, 0.2 * t)).norm() < 1e-15);
        }
    }
    let bad = CoonsPatch::new(
        line(p3(0.0, 0.0, 0.0), p3(1.0, 0.0, 0.0)),
        line(p3(0.0, 1.0, 0.0), p3(1.0, 1.0, 0.0)),
        line(p3(0.0, 0.0, 0.0), p3(0.0, 1.0, 0.0)),
        line(p3(1.0, 0.5, 0.0), p3(1.0, 1.0, 0.0)),
        CoonsBlend::Linear,
    );
    assert!(bad.err().unwrap().to_string().contains("bottom end and right start"));
}

#[test]
fn rational_bezier_surfaces_and_v_isocurves() {
    // A quarter cylinder: the rational quadratic arc in u, straight in v.
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let net = vec![
        vec![p3(1.0, 0.0, 0.0), p3(1.0, 0.0, 2.0)],
        vec![p3(1.0, 1.0, 0.0), p3(1.0, 1.0, 2.0)],
        vec![p3(0.0, 1.0, 0.0), p3(0.0, 1.0, 2.0)],
    ];
    let s = NurbsSurface::rational_bezier(net, vec![vec![1.0, 1.0], vec![w, w], vec![1.0, 1.0]]).unwrap();
    for a in 0..=10 {
        let p = s.point(a as f64 / 10.0, 0.37);
        assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15 && (p[2] - 0.74).abs() < 1e-15);
    }
    check_partials(&s, "rational bezier surface");
    let b = sample_surface();
    let iso = b.iso_curve_v(1.7).unwrap();
    for k in 0..=20 {
        let u = k as f64 / 20.0;
        assert!((iso.point(u) - b.point(u, 1.7)).norm() < 1e-13);
    }
}

#[test]
fn sweeps_with_rotation_minimising_frames() {
    use splinekit::curve::model::{Circle, Helix, Line};
    use splinekit::surface::derived::SweepSurface;
    let tube = || -> Box<dyn Curve<3>> { Box::new(Circle::new(0.3).unwrap()) };
    // Along a line: a cylinder of radius 0.3 about the line.
    let line = SweepSurface::new(tube(), Box::new(Line::new(p3(0.0, 0.0, 0.0), p3(1.0, 2.0, 2.0)).unwrap())).unwrap();
    let axis = p3(1.0, 2.0, 2.0) / 3.0;
    for a in 0..=8 {
        for b in 0..=8 {
            let p = line.point(TAU * a as f64 / 8.0, b as f64 / 8.0);
            assert!(((p - axis * axis.dot(&p)).norm() - 0.3).abs() < 1e-14);
        }
    }
    // Along a helix: every point is 0.3 from the path point, in its normal plane.
    let helix = Helix::new(2.0, 3.0, 2.0).unwrap();
    let s = SweepSurface::new(tube(), Box::new(helix.clone())).unwrap();
    for b in 0..=40 {
        let v = helix.domain().lerp(b as f64 / 40.0);
        let (c, t) = (helix.point(v), helix.tangent(v));
        for a in 0..8 {
            let p = s.point(TAU * a as f64 / 8.0, v);
            assert!(((p - c).norm() - 0.3).abs() < 1e-13);
            assert!((p - c).dot(&t).abs() < 1e-13);
        }
        // Rotation-minimising: the numerical frame does not turn about the tangent.
        let h = 1e-5;
        let r = |x: f64| (s.point(0.0, x) - helix.point(x)) / 0.3;
        let rv = (r(v + h) - r(v - h)) / (2.0 * h);
        let sn = t.cross(&r(v));
        if b > 0 && b < 40 {
            assert!(rv.dot(&sn).abs() < 1e-7, "frame twists at v = {v}: {}", rv.dot(&sn));
        }
    }
    check_partials(&s, "sweep along helix");
    // Along a closed planar circle: the RMF has no holonomy; the sweep is the torus.
    let ring = SweepSurface::new(tube(), Box::new(Circle::new(3.0).unwrap())).unwrap();
    assert!(ring.is_closed_u() && ring.is_closed_v());
    for a in 0..=8 {
        for b in 0..=8 {
            let p = ring.point(TAU * a as f64 / 8.0, TAU * b as f64 / 8.0);
            let centre = p3(p[0], p[1], 0.0).normalize() * 3.0;
            assert!(((p - centre).norm() - 0.3).abs() < 1e-12);
        }
        let (start, end) = (ring.point(TAU * a as f64 / 8.0, 0.0), ring.point(TAU * a as f64 / 8.0, TAU));
        assert!((start - end).norm() < 1e-12);
    }
    // A closed non-planar path (trefoil): the twist is spread, and the surface closes.
    let knot = SweepSurface::new(tube(), Box::new(splinekit::curve::model::Trefoil::new(1.0).unwrap())).unwrap();
    for a in 0..8 {
        let u = TAU * a as f64 / 8.0;
        assert!((knot.point(u, 0.0) - knot.point(u, TAU - 1e-9)).norm() < 1e-7, "trefoil tube closes at u = {u}");
    }
}

#[test]
fn lofting_through_sections() {
    use splinekit::curve::BSplineCurve;
    use splinekit::fit::Parametrization;
    // Sections of a surface that is cubic in v: lofting with uniform parameters gives it back.
    let net: Vec<Vec<Point<3>>> =
        (0..4).map(|i| (0..3).map(|j| p3(j as f64, i as f64, ((i * 3 + j) % 4) as f64 * 0.5)).collect()).collect();
    let s = BSplineSurface::clamped_uniform((3, 2), net).unwrap();
    // Sections v_k are u-isocurves of the transposed roles: take curves along the 2nd index.
    let sections: Vec<BSplineCurve<3>> = (0..5).map(|k| s.iso_curve_u(k as f64 / 4.0).unwrap()).collect();
    let loft = BSplineSurface::loft(&sections, 3, Parametrization::Uniform).unwrap();
    for a in 0..=10 {
        for b in 0..=10 {
            let (u, v) = (a as f64 / 10.0, b as f64 / 10.0);
            // loft(u = section parameter, v = across sections) = s(v, u).
            assert!((loft.point(u, v) - s.point(v, u)).norm() < 1e-12, "({u}, {v})");
        }
    }
    // Sections of different degrees and knots are made compatible and interpolated.
    let line = BSplineCurve::new(1, vec![0.0, 0.0, 2.0, 2.0], vec![p3(0.0, 0.0, 0.0), p3(2.0, 0.0, 0.0)]).unwrap();
    let quad = BSplineCurve::clamped_uniform(2, vec![p3(0.0, 1.0, 0.5), p3(1.0, 1.0, 1.5), p3(2.0, 1.0, 0.5)]).unwrap();
    let cubic = BSplineCurve::new(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.6, 1.0, 1.0, 1.0, 1.0],
        vec![
            p3(0.0, 2.0, 0.0),
            p3(0.5, 2.2, 0.3),
            p3(1.0, 2.0, -0.4),
            p3(1.5, 1.8, 0.2),
            p3(1.8, 2.1, 0.0),
            p3(2.0, 2.0, 0.0),
        ],
    )
    .unwrap();
    let loft = BSplineSurface::loft(&[line.clone(), quad.clone(), cubic.clone()], 2, Parametrization::Uniform).unwrap();
    assert_eq!(loft.degrees(), (3, 2));
    for a in 0..=20 {
        let t = a as f64 / 20.0;
        assert!((loft.point(t, 0.0) - line.point(2.0 * t)).norm() < 1e-13);
        assert!((loft.point(t, 0.5) - quad.point(t)).norm() < 1e-13);
        assert!((loft.point(t, 1.0) - cubic.point(t)).norm() < 1e-13);
    }
    assert!(BSplineSurface::loft(std::slice::from_ref(&line), 1, Parametrization::Uniform).is_err());
    assert!(BSplineSurface::loft(&[line, quad], 2, Parametrization::Uniform).is_err());
}

#[cfg(feature = "parallel")]
#[test]
fn parallel_grids_equal_serial_grids() {
    let s = sample_surface();
    let us: Vec<f64> = (0..101).map(|i| i as f64 / 100.0).collect();
    let vs: Vec<f64> = (0..57).map(|j| 3.0 * j as f64 / 56.0).collect();
    let (mut p1, mut n1) = (vec![Point::<3>::zeros(); 101 * 57], vec![Point::<3>::zeros(); 101 * 57]);
    let (mut p2, mut n2) = (p1.clone(), n1.clone());
    s.eval_grid_with_normals(&us, &vs, &mut p1, &mut n1);
    splinekit::surface::parallel::eval_grid_with_normals(&s, &us, &vs, &mut p2, &mut n2);
    assert_eq!(p1, p2);
    assert_eq!(n1, n2);
    let mut g1 = vec![Point::<3>::zeros(); 101 * 57 * 9];
    let mut g2 = g1.clone();
    s.eval_grid(&us, &vs, 2, 2, &mut g1);
    splinekit::surface::parallel::eval_grid(&s, &us, &vs, 2, 2, &mut g2);
    assert_eq!(g1, g2);
}

#[test]
fn trimmed_surfaces_test_containment_by_winding() {
    use splinekit::curve::{BSplineCurve, CatmullRomCurve, Curve};
    let plane = Plane::new(p3(0.0, 0.0, 0.0), p3(2.0, 0.0, 0.0), p3(0.0, 2.0, 0.0)).unwrap();
    // Outer loop: a periodic B-spline approximating the circle of radius 0.45 about (½, ½).
    let ring: Vec<Point<2>> = (0..12)
        .map(|i| {
            let a = TAU * i as f64 / 12.0;
            p2(0.5 + 0.47 * a.cos(), 0.5 + 0.47 * a.sin())
        })
        .collect();
    let outer = BSplineCurve::periodic_uniform(3, ring).unwrap();
    let hole =
        CatmullRomCurve::new(vec![p2(0.45, 0.45), p2(0.55, 0.45), p2(0.55, 0.55), p2(0.45, 0.55)], 0.0, true).unwrap();
    let t = TrimmedSurface::new(Box::new(plane), Some(&outer as &dyn Curve<2>), &[&hole as &dyn Curve<2>]).unwrap();
    assert!(!t.contains(0.5, 0.5), "inside the hole");
    assert!(t.contains(0.3, 0.5) && t.contains(0.5, 0.75));
    assert!(!t.contains(0.02, 0.02), "outside the outer loop");
    assert!(!t.contains(1.5, 0.5), "outside the domain");
    assert_eq!(t.trim_contains(0.3, 0.5), Some(true));
    assert!((t.point(0.25, 0.5) - p3(0.5, 1.0, 0.0)).norm() < 1e-15, "trimming keeps the shape");
    let open = splinekit::curve::model::Line::new(p2(0.0, 0.0), p2(1.0, 1.0)).unwrap();
    let e = TrimmedSurface::new(Box::new(Sphere::new(1.0).unwrap()), Some(&open as &dyn Curve<2>), &[])
        .err()
        .unwrap()
        .to_string();
    assert!(e.starts_with("outer:") && e.contains("closed"), "{e}");
}
