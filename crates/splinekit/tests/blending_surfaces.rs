//! Blending-spline surfaces: the Hermite property at every knot pair, exact reproduction
//! with sub-surface patches, seams, locality, affine invariance, derivatives against
//! finite differences, the fast grid path against the general one, refresh, convergence.

use splinekit::Point;
use splinekit::basis::BFunction;
use splinekit::blend::{BlendingSplineSurface, BlendingSurfaceOptions, PatchKind};
use splinekit::frame::Affine;
use splinekit::surface::Surface;
use splinekit::surface::SurfaceGridSamples;
use splinekit::surface::model::{Cylinder, Plane, Sphere, Torus};
use std::f64::consts::TAU;
use std::sync::Arc;

fn torus() -> Arc<dyn Surface<3>> {
    Arc::new(Torus::new(3.0, 1.0).unwrap())
}
fn models() -> Vec<(&'static str, Arc<dyn Surface<3>>)> {
    vec![
        ("torus", torus()),
        ("cylinder", Arc::new(Cylinder::new(1.0, 2.0).unwrap())),
        (
            "plane",
            Arc::new(
                Plane::new(Point::<3>::zeros(), Point::<3>::new(2.0, 0.0, 0.5), Point::<3>::new(0.0, 1.0, 0.0))
                    .unwrap(),
            ),
        ),
        ("sphere", Arc::new(Sphere::new(1.5).unwrap())),
    ]
}
fn build(model: &Arc<dyn Surface<3>>, n: (usize, usize), kind: PatchKind) -> BlendingSplineSurface<3> {
    let closed = (model.is_closed_u(), model.is_closed_v());
    BlendingSplineSurface::from_model(
        model.clone(),
        n,
        &BlendingSurfaceOptions {
            local: kind,
            bfunction: BFunction::erbs_default(),
            closed_u: Some(closed.0),
            closed_v: Some(closed.1),
        },
    )
    .unwrap()
}
fn close(a: &Point<3>, b: &Point<3>, tol: f64) -> bool {
    (a - b).norm() <= tol * b.norm().max(1.0)
}

#[test]
fn bezier_patches_reproduce_every_mixed_partial_at_every_knot_pair() {
    for (name, model) in models() {
        for (du, dv) in [(1, 1), (2, 3), (3, 3)] {
            let s = build(&model, (5, 4), PatchKind::Bezier(du, dv));
            let (ku, kv) = s.knots();
            for k in 0..5 {
                for l in 0..4 {
                    let (u, v) = (ku.centre(k), kv.centre(l));
                    let w = (du + 1) * (dv + 1);
                    let (mut got, mut want) = (vec![Point::<3>::zeros(); w], vec![Point::<3>::zeros(); w]);
                    s.eval_partials(u, v, du, dv, &mut got);
                    model.eval_partials(u, v, du, dv, &mut want);
                    for i in 0..w {
                        assert!(close(&got[i], &want[i], 1e-10), "{name} ({du},{dv}) knot ({k},{l}) partial {i}");
                    }
                }
            }
        }
    }
}

#[test]
fn sub_surface_patches_give_the_model_back_and_closed_seams_meet() {
    for (name, model) in models() {
        let s = build(&model, (4, 5), PatchKind::SubSurface);
        for i in 0..=20 {
            for j in 0..=20 {
                let u = model.domain_u().lerp(i as f64 / 20.0);
                let v = model.domain_v().lerp(j as f64 / 20.0);
                assert!(close(&s.point(u, v), &model.point(u, v), 1e-13), "{name} at ({u}, {v})");
            }
        }
    }
    // Seams of the Bézier torus: equal points, and partials continuous across u = 0 ≡ 2π and v = 0 ≡ 2π.
    let s = build(&torus(), (6, 5), PatchKind::Bezier(3, 3));
    let eps = 1e-7;
    for j in 0..=10 {
        let x = TAU * j as f64 / 10.0;
        assert_eq!(s.point(0.0, x), s.point(TAU, x));
        assert_eq!(s.point(x, 0.0), s.point(x, TAU));
        let (mut a, mut b) = ([Point::<3>::zeros(); 9], [Point::<3>::zeros(); 9]);
        s.eval_partials(TAU - eps, x, 2, 2, &mut a);
        s.eval_partials(eps, x, 2, 2, &mut b);
        for i in 0..9 {
            assert!((a[i] - b[i]).norm() < 1e-4 * b[i].norm().max(1.0), "u seam, partial {i}");
        }
        s.eval_partials(x, TAU - eps, 2, 2, &mut a);
        s.eval_partials(x, eps, 2, 2, &mut b);
        for i in 0..9 {
            assert!((a[i] - b[i]).norm() < 1e-4 * b[i].norm().max(1.0), "v seam, partial {i}");
        }
    }
}

#[test]
fn partials_agree_with_finite_differences() {
    let mut s = build(&torus(), (5, 4), PatchKind::Bezier(3, 2));
    s.set_transform(2, 1, Affine::rotation(Point::<3>::new(1.0, 1.0, 0.0), 0.4).unwrap());
    let h = 1e-6;
    for &(u, v) in &[(0.3, 0.2), (2.9, 4.1), (5.5, 6.0), (1.0, 3.3)] {
        let mut m = [Point::<3>::zeros(); 9];
        s.eval_partials(u, v, 2, 2, &mut m);
        let (mut up, mut um, mut vp, mut vm) =
            ([Point::<3>::zeros(); 9], [Point::<3>::zeros(); 9], [Point::<3>::zeros(); 9], [Point::<3>::zeros(); 9]);
        s.eval_partials(u + h, v, 2, 2, &mut up);
        s.eval_partials(u - h, v, 2, 2, &mut um);
        s.eval_partials(u, v + h, 2, 2, &mut vp);
        s.eval_partials(u, v - h, 2, 2, &mut vm);
        for i in 0..2 {
            for j in 0..3 {
                // ∂/∂u of the (i, j) partial is the (i+1, j) partial.
                let fd = (up[i * 3 + j] - um[i * 3 + j]) / (2.0 * h);
                assert!(close(&fd, &m[(i + 1) * 3 + j], 1e-6), "u of ({i},{j}) at ({u},{v})");
            }
        }
        for i in 0..3 {
            for j in 0..2 {
                let fd = (vp[i * 3 + j] - vm[i * 3 + j]) / (2.0 * h);
                assert!(close(&fd, &m[i * 3 + j + 1], 1e-6), "v of ({i},{j}) at ({u},{v})");
            }
        }
    }
}

#[test]
fn moving_a_patch_is_local_and_frames_are_affine() {
    let base = build(&torus(), (6, 6), PatchKind::Bezier(3, 3));
    let mut s = base.clone();
    let rects = s.set_transform(0, 3, Affine::translation(Point::<3>::new(0.0, 0.0, 1.0)));
    assert_eq!(rects.len(), 2, "patch 0 in u straddles the u seam");
    let inside =
        |u: f64, v: f64| rects.iter().any(|r| u >= r.u.start && u <= r.u.end && v >= r.v.start && v <= r.v.end);
    let mut moved = 0;
    for i in 0..=60 {
        for j in 0..=60 {
            let (u, v) = (TAU * i as f64 / 60.0, TAU * j as f64 / 60.0);
            if inside(u, v) {
                moved += (s.point(u, v) != base.point(u, v)) as usize;
            } else {
                assert_eq!(s.point(u, v), base.point(u, v), "changed outside at ({u}, {v})");
            }
        }
    }
    assert!(moved > 50);
    // One affine map applied to every frame = the map applied to the surface.
    let map = Affine::rotation(Point::<3>::new(0.2, 1.0, 0.3), 0.9).unwrap().after(&Affine::uniform_scale(1.3));
    let mut all = base.clone();
    for k in 0..6 {
        for l in 0..6 {
            let o = all.origin(k, l);
            // A frame about o that maps the local exactly as `map` maps the world.
            let about = Affine { linear: map.linear, translation: map.apply_point(&o) - o };
            all.set_transform(k, l, about);
        }
    }
    for (u, v) in [(0.1, 0.2), (1.7, 5.0), (4.4, 2.2)] {
        let want = map.apply_point(&base.point(u, v));
        assert!(close(&all.point(u, v), &want, 1e-13), "({u}, {v})");
    }
}

#[test]
fn the_fast_grid_path_matches_pointwise_evaluation_and_refresh_matches_a_full_pass() {
    for (name, model) in models() {
        let mut s = build(&model, (5, 4), PatchKind::Bezier(3, 2));
        s.set_transform(1, 2, Affine::uniform_scale(1.4));
        let g = SurfaceGridSamples::uniform(&s, 37, 29).unwrap();
        for (a, &u) in g.us().iter().enumerate() {
            for (b, &v) in g.vs().iter().enumerate() {
                let i = a * 29 + b;
                assert!(close(&g.points()[i], &s.point(u, v), 1e-13), "{name} point at ({u}, {v})");
                if let Some(n) = s.normal(u, v) {
                    assert!((g.normals()[i] - n).norm() < 1e-10, "{name} normal at ({u}, {v})");
                }
            }
        }
    }
    let mut s = build(&torus(), (8, 8), PatchKind::Bezier(3, 3));
    let mut g = SurfaceGridSamples::uniform(&s, 256, 256).unwrap();
    let rects = s.set_transform(7, 0, Affine::uniform_scale(0.5));
    let n = g.refresh(&s, &rects);
    assert!(n < 256 * 256 / 10, "{n} points re-evaluated");
    let fresh = SurfaceGridSamples::uniform(&s, 256, 256).unwrap();
    assert_eq!(g.points(), fresh.points());
    assert_eq!(g.normals(), fresh.normals());
}

#[test]
fn bicubic_patches_converge_to_the_torus() {
    let model = torus();
    let mut errors = Vec::new();
    for n in [4, 8, 16, 32] {
        let s = build(&model, (n, n), PatchKind::Bezier(3, 3));
        let mut worst: f64 = 0.0;
        for i in 0..=97 {
            for j in 0..=89 {
                let (u, v) = (TAU * i as f64 / 97.0, TAU * j as f64 / 89.0);
                worst = worst.max((s.point(u, v) - model.point(u, v)).norm());
            }
        }
        errors.push(worst);
    }
    let rates: Vec<f64> = errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
    eprintln!("torus errors {errors:?} rates {rates:?}");
    assert!(rates.iter().skip(1).all(|&r| r > 3.5), "rates {rates:?}");
}

#[test]
fn bad_counts_and_degrees_are_refused_with_the_field() {
    let e = BlendingSplineSurface::from_model(
        torus(),
        (2, 5),
        &BlendingSurfaceOptions {
            local: PatchKind::SubSurface,
            bfunction: BFunction::erbs_default(),
            closed_u: Some(true),
            closed_v: Some(true),
        },
    );
    assert!(e.err().unwrap().to_string().contains("local_surfaces[0]"));
    let e = BlendingSplineSurface::from_model(
        torus(),
        (4, 4),
        &BlendingSurfaceOptions {
            local: PatchKind::Bezier(0, 3),
            bfunction: BFunction::erbs_default(),
            closed_u: Some(true),
            closed_v: Some(true),
        },
    );
    assert!(e.err().unwrap().to_string().contains("local"));
}

/// The breakpoints (where queries cut patches) are the knots: increasing, from the start
/// of the domain to its end, every local's knot among them and nothing between knots.
#[test]
fn breakpoints_are_the_knots() {
    for (name, model) in models() {
        let s = build(&model, (5, 4), PatchKind::Bezier(3, 3));
        let (ku, kv) = s.knots();
        for (breaks, knots, domain, count) in
            [(s.breakpoints_u(), ku, s.domain_u(), 5), (s.breakpoints_v(), kv, s.domain_v(), 4)]
        {
            assert_eq!((breaks[0], *breaks.last().unwrap()), (domain.start, domain.end), "{name}");
            assert!(breaks.windows(2).all(|w| w[0] < w[1]), "{name}: {breaks:?}");
            for k in 0..count {
                assert!(breaks.contains(&knots.centre(k)), "{name}: knot {k} missing from {breaks:?}");
            }
            assert!(breaks.len() <= count + 1, "{name}: {breaks:?} has points that are not knots");
        }
    }
}
