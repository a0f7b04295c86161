//! Sub-surfaces over a quadrilateral of the domain (GMlib's `PSubSurf`, not bound to the
//! axes): points against direct evaluation of the host at the bilinear map, partials
//! against the chain rule in closed form (axis-aligned rectangles, planar hosts) and
//! against central differences of the order below (skew quadrilaterals on a torus),
//! refusals naming the field, and use as the model of a blending-spline surface.

use std::sync::Arc;

use splinekit::Point;
use splinekit::blend::{BlendingSplineSurface, BlendingSurfaceOptions};
use splinekit::surface::model::{Plane, Torus};
use splinekit::surface::{QuadSubSurface, Surface};

const SKEW: [[f64; 2]; 4] = [[0.4, 0.3], [2.9, 0.8], [2.5, 3.6], [0.7, 2.4]];

fn partials(s: &dyn Surface<3>, u: f64, v: f64, du: usize, dv: usize) -> Vec<Point<3>> {
    let mut out = vec![Point::<3>::zeros(); (du + 1) * (dv + 1)];
    s.eval_partials(u, v, du, dv, &mut out);
    out
}

fn bilinear(c: [[f64; 2]; 4], s: f64, t: f64) -> (f64, f64) {
    let w = [(1.0 - s) * (1.0 - t), s * (1.0 - t), s * t, (1.0 - s) * t];
    ((0..4).map(|i| w[i] * c[i][0]).sum(), (0..4).map(|i| w[i] * c[i][1]).sum())
}

#[test]
fn points_are_the_host_at_the_bilinear_map() {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let q = QuadSubSurface::new(torus.clone(), SKEW).unwrap();
    for i in 0..=20 {
        for j in 0..=20 {
            let (s, t) = (i as f64 / 20.0, j as f64 / 20.0);
            let (u, v) = bilinear(SKEW, s, t);
            assert!((q.point(s, t) - torus.point(u, v)).norm() < 1e-14, "({s}, {t})");
        }
    }
    // The corners in order.
    for (k, (s, t)) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].into_iter().enumerate() {
        assert!((q.point(s, t) - torus.point(SKEW[k][0], SKEW[k][1])).norm() < 1e-14);
    }
}

#[test]
fn an_axis_aligned_rectangle_has_the_hosts_partials_scaled_by_the_side_lengths() {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let (u0, u1, v0, v1) = (0.5, 2.0, 1.0, 4.5);
    let q = QuadSubSurface::new(torus.clone(), [[u0, v0], [u1, v0], [u1, v1], [u0, v1]]).unwrap();
    let (a, b) = (u1 - u0, v1 - v0);
    for (s, t) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.35)] {
        let got = partials(&q, s, t, 3, 3);
        let want = partials(&torus, u0 + a * s, v0 + b * t, 3, 3);
        for i in 0..=3 {
            for j in 0..=3 {
                let w = want[i * 4 + j] * a.powi(i as i32) * b.powi(j as i32);
                let g = got[i * 4 + j];
                assert!((g - w).norm() < 1e-12 * w.norm().max(1.0), "({i}, {j}) at ({s}, {t}): {g} vs {w}");
            }
        }
    }
}

#[test]
fn on_a_plane_the_partials_are_the_bilinear_maps() {
    let plane =
        Plane::new(Point::<3>::new(1.0, 2.0, 3.0), Point::<3>::new(1.0, 0.0, 1.0), Point::<3>::new(0.0, 2.0, 0.0))
            .unwrap();
    let c = [[0.1, 0.0], [0.9, 0.2], [0.8, 1.0], [0.0, 0.7]];
    let q = QuadSubSurface::new(plane.clone(), c).unwrap();
    let (s, t) = (0.3, 0.6);
    let g = partials(&q, s, t, 2, 2);
    let lift = |du: f64, dv: f64| Point::<3>::new(1.0, 0.0, 1.0) * du + Point::<3>::new(0.0, 2.0, 0.0) * dv;
    let phi_s = |k: usize| (1.0 - t) * (c[1][k] - c[0][k]) + t * (c[2][k] - c[3][k]);
    let phi_t = |k: usize| (1.0 - s) * (c[3][k] - c[0][k]) + s * (c[2][k] - c[1][k]);
    let twist = |k: usize| c[2][k] - c[1][k] - c[3][k] + c[0][k];
    assert!((g[3] - lift(phi_s(0), phi_s(1))).norm() < 1e-14, "P_s");
    assert!((g[1] - lift(phi_t(0), phi_t(1))).norm() < 1e-14, "P_t");
    assert!((g[4] - lift(twist(0), twist(1))).norm() < 1e-14, "P_st");
    for zero in [g[6], g[2], g[5], g[7], g[8]] {
        assert!(zero.norm() < 1e-14, "second and higher pure partials vanish: {zero}");
    }
}

#[test]
fn partials_on_a_skew_quadrilateral_match_central_differences_of_the_order_below() {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let q = QuadSubSurface::new(torus, SKEW).unwrap();
    let h = 1e-5;
    for (s, t) in [(0.2, 0.3), (0.55, 0.45), (0.8, 0.7)] {
        let at = partials(&q, s, t, 3, 3);
        for i in 0..=3usize {
            for j in 0..=3usize {
                if i + j == 0 {
                    continue;
                }
                // Differentiate the (i − 1, j) partial in s, or the (i, j − 1) one in t.
                let (fd, what) = if i > 0 {
                    let (a, b) = (partials(&q, s + h, t, 3, 3), partials(&q, s - h, t, 3, 3));
                    ((a[(i - 1) * 4 + j] - b[(i - 1) * 4 + j]) / (2.0 * h), "s")
                } else {
                    let (a, b) = (partials(&q, s, t + h, 3, 3), partials(&q, s, t - h, 3, 3));
                    ((a[i * 4 + j - 1] - b[i * 4 + j - 1]) / (2.0 * h), "t")
                };
                let got = at[i * 4 + j];
                assert!(
                    (got - fd).norm() < 1e-5 * got.norm().max(1.0),
                    "({i}, {j}) by {what} at ({s}, {t}): {got} vs {fd}"
                );
            }
        }
    }
}

#[test]
fn bad_quadrilaterals_are_refused_naming_the_field() {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let e = |c| QuadSubSurface::new(torus.clone(), c).err().unwrap().to_string();
    let m = e([[0.0, 0.0], [7.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    assert!(m.contains("corners[1]") && m.contains("outside the surface's domain"), "{m}");
    let m = e([[0.0, 0.0], [1.0, f64::NAN], [1.0, 1.0], [0.0, 1.0]]);
    assert!(m.contains("corners[1]") && m.contains("finite"), "{m}");
    // A bow tie (corners out of order) folds.
    let m = e([[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]);
    assert!(m.contains("corners") && m.contains("folds"), "{m}");
    // Three corners on a line: degenerate at one corner.
    let m = e([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [0.0, 1.0]]);
    assert!(m.contains("folds or is degenerate"), "{m}");
    // Clockwise is fine.
    assert!(QuadSubSurface::new(torus, [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]).is_ok());
}

#[test]
fn a_skew_sub_surface_serves_as_a_blending_spline_model() {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let q: Arc<dyn Surface<3>> = Arc::new(QuadSubSurface::new(torus, SKEW).unwrap());
    let s = BlendingSplineSurface::from_model(q.clone(), (5, 5), &BlendingSurfaceOptions::default()).unwrap();
    let (ku, kv) = s.knots();
    for k in 0..5 {
        for l in 0..5 {
            let (u, v) = (ku.centre(k), kv.centre(l));
            let (a, b) = (partials(&s, u, v, 3, 3), partials(q.as_ref(), u, v, 3, 3));
            for (x, y) in a.iter().zip(&b) {
                assert!((x - y).norm() < 1e-10 * y.norm().max(1.0), "({k}, {l})");
            }
        }
    }
}
