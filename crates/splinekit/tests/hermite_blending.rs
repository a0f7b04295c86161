//! Blending splines from Hermite data (GMlib's `PERBSCurve(DVector<DVector<Vector>>, t)` and
//! `PERBSSurf(DMatrix<DMatrix<Vector>>, u, v)`): the data reproduced at every knot to 1e-12,
//! derivatives included, as far as the B-function's smoothness allows; polynomials of the
//! locals' degree reproduced everywhere; the closed seam; the errors.

use splinekit::Point;
use splinekit::basis::{BFunction, Side};
use splinekit::blend::{BlendKnots, BlendingSplineCurve, BlendingSplineSurface};
use splinekit::curve::Curve;
use splinekit::curve::model::Helix;
use splinekit::surface::Surface;
use splinekit::surface::model::Torus;

/// A small deterministic generator (xorshift) for data that no formula relates.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
    fn point(&mut self, scale: f64) -> Point<3> {
        Point::<3>::new(self.next(), self.next(), self.next()) * scale
    }
}

fn derivatives(c: &dyn Curve<3>, t: f64, side: Side, n: usize) -> Vec<Point<3>> {
    let mut out = vec![Point::<3>::zeros(); n];
    c.eval_side(t, side, &mut out);
    out
}

/// |got − want| ≤ 1e-12 · max(1, |want|) for every order.
fn assert_data(got: &[Point<3>], want: &[Point<3>], what: &str) {
    assert_within(got, want, 1e-12, what);
}

/// |got − want| ≤ tol · max(1, |want|) for every order.
fn assert_within(got: &[Point<3>], want: &[Point<3>], tol: f64, what: &str) {
    for (j, (g, w)) in got.iter().zip(want).enumerate() {
        let err = (g - w).norm();
        assert!(err <= tol * w.norm().max(1.0), "{what}, order {j}: {g} vs {w} (error {err:e})");
    }
}

#[test]
fn random_hermite_data_is_reproduced_at_every_knot_with_every_derivative() {
    let mut rng = Rng(0x9e3779b97f4a7c15);
    for closed in [false, true] {
        for d in 1..=5 {
            // Uneven knots; closed curves have one more knot (the first plus the period).
            let n = 7;
            let mut knots = vec![0.0];
            for _ in 1..n + usize::from(closed) {
                knots.push(knots.last().unwrap() + 0.5 + rng.next().abs());
            }
            let data: Vec<Vec<Point<3>>> = (0..n).map(|_| (0..=d).map(|_| rng.point(3.0)).collect()).collect();
            let kv = BlendKnots::new(knots.clone(), closed).unwrap();
            let c = BlendingSplineCurve::from_hermite(kv, data.clone(), BFunction::erbs_default()).unwrap();
            assert_eq!((c.local_count(), c.is_closed()), (n, closed));
            for (k, want) in data.iter().enumerate() {
                for side in [Side::Left, Side::Right] {
                    let got = derivatives(&c, knots[k], side, d + 1);
                    assert_data(&got, want, &format!("closed {closed}, d = {d}, knot {k}, {side:?}"));
                }
                // The local frame's origin is the datum's position.
                assert_eq!(c.origin(k), want[0]);
            }
            if closed {
                // The end of the period is knot 0 again, from both sides.
                let got = derivatives(&c, *knots.last().unwrap(), Side::Left, d + 1);
                assert_data(&got, &data[0], &format!("seam, d = {d}"));
            }
        }
    }
}

#[test]
fn hermite_data_of_a_helix_gives_its_derivatives_at_the_knots_and_stays_close_between() {
    let helix = Helix::new(2.0, 0.5, 2.0).unwrap();
    let dom = helix.domain();
    let n = 25;
    let knots: Vec<f64> = (0..n).map(|i| dom.lerp(i as f64 / (n - 1) as f64)).collect();
    let data: Vec<Vec<Point<3>>> = knots.iter().map(|&t| derivatives(&helix, t, Side::Right, 5)).collect();
    let c = BlendingSplineCurve::from_hermite(
        BlendKnots::new(knots.clone(), false).unwrap(),
        data.clone(),
        BFunction::erbs_default(),
    )
    .unwrap();
    for (k, &t) in knots.iter().enumerate() {
        assert_data(&derivatives(&c, t, Side::Right, 5), &data[k], &format!("knot {k}"));
        // Orders past the data's: the quartic locals have no fifth derivative, and ERBS adds none at a knot.
        assert!(derivatives(&c, t, Side::Right, 6)[5].norm() < 1e-9);
    }
    // Between the knots the quartic Taylor pieces are within their remainder of the helix.
    let h = knots[1] - knots[0];
    let mut worst: f64 = 0.0;
    for i in 0..=1000 {
        let t = dom.lerp(i as f64 / 1000.0);
        worst = worst.max((c.point(t) - helix.point(t)).norm());
    }
    assert!(worst < 2.0 * h.powi(5) && worst > 0.0, "{worst:e} vs h⁵ = {:e}", h.powi(5));
}

#[test]
fn data_of_a_polynomial_of_the_local_degree_is_that_polynomial_everywhere() {
    // p(t) = (t³ − t, 2t² + 1, 1 − t³/3): every local is p itself, so their blend is p.
    let p = |t: f64| {
        [
            Point::<3>::new(t * t * t - t, 2.0 * t * t + 1.0, 1.0 - t * t * t / 3.0),
            Point::<3>::new(3.0 * t * t - 1.0, 4.0 * t, -t * t),
            Point::<3>::new(6.0 * t, 4.0, -2.0 * t),
            Point::<3>::new(6.0, 0.0, -2.0),
        ]
    };
    let knots = vec![-1.0, -0.2, 0.5, 0.7, 2.0];
    let data: Vec<Vec<Point<3>>> = knots.iter().map(|&t| p(t).to_vec()).collect();
    for b in [BFunction::erbs_default(), BFunction::polynomial(1).unwrap(), BFunction::Linear] {
        let c =
            BlendingSplineCurve::from_hermite(BlendKnots::new(knots.clone(), false).unwrap(), data.clone(), b).unwrap();
        for i in 0..=300 {
            let t = -1.0 + 3.0 * i as f64 / 300.0;
            // Between knots B‴/Δ³ multiplies the locals' rounding differences (Δ = 0.2 here).
            assert_within(&derivatives(&c, t, Side::Right, 4), &p(t), 1e-10, &format!("t = {t}"));
        }
    }
}

#[test]
fn a_polynomial_bfunction_reproduces_the_data_up_to_its_smoothness_only() {
    let mut rng = Rng(7);
    let knots = vec![0.0, 1.0, 2.5, 3.0];
    let data: Vec<Vec<Point<3>>> = (0..4).map(|_| (0..4).map(|_| rng.point(2.0)).collect()).collect();
    for smoothness in 1..=2 {
        let b = BFunction::polynomial(smoothness).unwrap();
        let c =
            BlendingSplineCurve::from_hermite(BlendKnots::new(knots.clone(), false).unwrap(), data.clone(), b).unwrap();
        let got = derivatives(&c, knots[1], Side::Right, 4);
        assert_data(&got[..=smoothness], &data[1][..=smoothness], &format!("smoothness {smoothness}"));
        // B^{(s+1)}(0) ≠ 0 mixes the neighbour in: the next derivative is not the datum.
        assert!((got[smoothness + 1] - data[1][smoothness + 1]).norm() > 1e-3, "smoothness {smoothness}");
    }
}

#[test]
fn bad_hermite_data_is_refused_naming_the_entry() {
    let k = || BlendKnots::new(vec![0.0, 1.0, 2.0], false).unwrap();
    let b = BFunction::erbs_default;
    let pt = |x| Point::<2>::new(x, 0.0);
    let e = BlendingSplineCurve::from_hermite(k(), vec![vec![pt(0.0), pt(1.0)]; 2], b()).err().unwrap().to_string();
    assert!(e.contains("hermite") && e.contains("expected 3 entries") && e.contains("got 2"), "{e}");
    let e = BlendingSplineCurve::from_hermite(k(), vec![vec![pt(0.0)]; 3], b()).err().unwrap().to_string();
    assert!(e.contains("hermite[0]") && e.contains("got 1 values"), "{e}");
    let mut ragged = vec![vec![pt(0.0), pt(1.0)]; 3];
    ragged[2].push(pt(2.0));
    let e = BlendingSplineCurve::from_hermite(k(), ragged, b()).err().unwrap().to_string();
    assert!(e.contains("hermite[2]") && e.contains("expected 2 values"), "{e}");
    let mut nan = vec![vec![pt(0.0), pt(1.0)]; 3];
    nan[1][1] = pt(f64::NAN);
    let e = BlendingSplineCurve::from_hermite(k(), nan, b()).err().unwrap().to_string();
    assert!(e.contains("hermite[1][1]") && e.contains("finite"), "{e}");
}

/// All partials ∂^{i,j}, i ≤ du, j ≤ dv, of a surface at (u, v), row-major.
fn partials(s: &dyn Surface<3>, u: f64, v: f64, du: usize, dv: usize) -> Vec<Point<3>> {
    let mut out = vec![Point::<3>::zeros(); (du + 1) * (dv + 1)];
    s.eval_partials(u, v, du, dv, &mut out);
    out
}

#[test]
fn surface_hermite_data_is_reproduced_at_every_knot_pair_with_every_mixed_partial() {
    let mut rng = Rng(0x2545f4914f6cdd1d);
    for (closed_u, closed_v) in [(false, false), (true, false), (true, true)] {
        for (du, dv) in [(1, 1), (2, 3), (3, 3)] {
            let (nu, nv) = (5, 4);
            let knots = |n: usize, closed: bool, rng: &mut Rng| {
                let mut k = vec![0.0];
                for _ in 1..n + usize::from(closed) {
                    k.push(k.last().unwrap() + 0.4 + rng.next().abs());
                }
                k
            };
            let (ku, kv) = (knots(nu, closed_u, &mut rng), knots(nv, closed_v, &mut rng));
            let data: Vec<Vec<Point<3>>> =
                (0..nu * nv).map(|_| (0..(du + 1) * (dv + 1)).map(|_| rng.point(2.0)).collect()).collect();
            let s = BlendingSplineSurface::from_hermite(
                (BlendKnots::new(ku.clone(), closed_u).unwrap(), BlendKnots::new(kv.clone(), closed_v).unwrap()),
                data.clone(),
                (du, dv),
                BFunction::erbs_default(),
            )
            .unwrap();
            assert_eq!((s.is_closed_u(), s.is_closed_v()), (closed_u, closed_v));
            for k in 0..nu {
                for l in 0..nv {
                    let got = partials(&s, ku[k], kv[l], du, dv);
                    assert_data(
                        &got,
                        &data[k * nv + l],
                        &format!("[{closed_u}, {closed_v}] ({du}, {dv}) at ({k}, {l})"),
                    );
                    assert_eq!(s.origin(k, l), data[k * nv + l][0]);
                }
            }
        }
    }
}

#[test]
fn torus_partials_as_surface_data_give_the_torus_at_the_knots() {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let (nu, nv) = (12, 8);
    let ku: Vec<f64> = (0..=nu).map(|i| torus.domain_u().lerp(i as f64 / nu as f64)).collect();
    let kv: Vec<f64> = (0..=nv).map(|i| torus.domain_v().lerp(i as f64 / nv as f64)).collect();
    let data: Vec<Vec<Point<3>>> = (0..nu * nv).map(|i| partials(&torus, ku[i / nv], kv[i % nv], 3, 3)).collect();
    let s = BlendingSplineSurface::from_hermite(
        (BlendKnots::new(ku.clone(), true).unwrap(), BlendKnots::new(kv.clone(), true).unwrap()),
        data,
        (3, 3),
        BFunction::erbs_default(),
    )
    .unwrap();
    for (k, &u) in ku.iter().enumerate() {
        for (l, &v) in kv.iter().enumerate() {
            assert_data(&partials(&s, u, v, 3, 3), &partials(&torus, u, v, 3, 3), &format!("({k}, {l})"));
        }
    }
    // Between knots, within the bicubic Taylor remainder of the torus.
    let worst = (0..=40)
        .flat_map(|i| (0..=40).map(move |j| (i as f64 / 40.0, j as f64 / 40.0)))
        .map(|(a, b)| {
            let (u, v) = (torus.domain_u().lerp(a), torus.domain_v().lerp(b));
            (s.point(u, v) - torus.point(u, v)).norm()
        })
        .fold(0.0, f64::max);
    assert!(worst < 0.05 && worst > 1e-6, "{worst:e}");
}

#[test]
fn bad_surface_data_is_refused_naming_the_entry() {
    let k = || (BlendKnots::new(vec![0.0, 1.0], false).unwrap(), BlendKnots::new(vec![0.0, 1.0, 2.0], false).unwrap());
    let b = BFunction::erbs_default;
    let four = vec![Point::<3>::zeros(); 4];
    let e = BlendingSplineSurface::from_hermite(k(), vec![four.clone(); 5], (1, 1), b()).err().unwrap().to_string();
    assert!(e.contains("hermite") && e.contains("2×3 entries") && e.contains("got 5"), "{e}");
    let mut short = vec![four.clone(); 6];
    short[4].pop();
    let e = BlendingSplineSurface::from_hermite(k(), short, (1, 1), b()).err().unwrap().to_string();
    assert!(e.contains("hermite[1][1]") && e.contains("expected 2×2 partials, got 3"), "{e}");
    let mut nan = vec![four.clone(); 6];
    nan[5][3].x = f64::INFINITY;
    let e = BlendingSplineSurface::from_hermite(k(), nan, (1, 1), b()).err().unwrap().to_string();
    assert!(e.contains("hermite[1][2][1][1]") && e.contains("finite"), "{e}");
    let e = BlendingSplineSurface::from_hermite(k(), vec![four; 6], (0, 3), b()).err().unwrap().to_string();
    assert!(e.contains("between 1 and 12") && e.contains("[0, 3]"), "{e}");
}
