//! The triangle family against independent truth (Farin, *Curves and Surfaces for CAGD*,
//! ch. 17): de Casteljau against the Bernstein form, derivatives against finite
//! differences, degree elevation and subdivision leaving the surface unchanged, the exact
//! degenerate tensor patch, the sphere octant, triangular B-functions (partition of unity,
//! flat corners, edges) and GERBS triangles (corner interpolation, affine invariance).

use std::sync::Arc;

use proptest::prelude::*;
use splinekit::Point;
use splinekit::basis::{BFunction, binomial};
use splinekit::frame::Affine;
use splinekit::surface::Surface;
use splinekit::surface::model::{Sphere, Torus};
use splinekit::triangle::{
    BezierTriangle, GerbsTriangle, RationalBezierTriangle, SubTriangle, Triangle, TriangularBFunction, TriangularForm,
    degenerate_patch_parameters, hermite_local, multi_indices, net_len,
};

/// A small deterministic generator (xorshift64*), uniform in [0, 1).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
    fn point3(&mut self) -> Point<3> {
        Point::<3>::new(self.range(-1.0, 1.0), self.range(-1.0, 1.0), self.range(-1.0, 1.0))
    }
    /// A point of the triangle at least `margin` inside every edge.
    fn inside(&mut self, margin: f64) -> (f64, f64, f64) {
        loop {
            let (u, v) = (self.next(), self.next());
            let w = 1.0 - u - v;
            if u >= margin && v >= margin && w >= margin {
                return (u, v, w);
            }
        }
    }
}

fn random_net(rng: &mut Rng, degree: usize) -> Vec<Point<3>> {
    (0..net_len(degree)).map(|_| rng.point3()).collect()
}
fn random_weights(rng: &mut Rng, degree: usize) -> Vec<f64> {
    (0..net_len(degree)).map(|_| rng.range(0.5, 2.0)).collect()
}

/// Barycentric sample points: a grid with the corners and edges, plus random ones.
fn samples(rng: &mut Rng) -> Vec<(f64, f64, f64)> {
    let mut s = Vec::new();
    let m = 8;
    for i in 0..=m {
        for j in 0..=m - i {
            let (u, v) = (i as f64 / m as f64, j as f64 / m as f64);
            s.push((u, v, 1.0 - u - v));
        }
    }
    s.extend((0..40).map(|_| rng.inside(0.0)));
    s
}

fn partials<const D: usize, T: Triangle<D> + ?Sized>(t: &T, u: f64, v: f64, du: usize, dv: usize) -> Vec<Point<D>> {
    let mut out = vec![Point::<D>::zeros(); (du + 1) * (dv + 1)];
    t.eval_partials(u, v, du, dv, &mut out);
    out
}

/// ∂^{i,j}T at (u, v) by a fourth-order central difference of the exact ∂^{i−1,j} (or
/// ∂^{i,j−1}) with step h. The error is h⁴|f⁽⁵⁾|/30 from truncation plus about
/// 1.5 ε max|f| / h from rounding; with h = 10⁻³ and the smooth, O(1)-sized nets and
/// weights used here the truncation term is ~10⁻¹² times the fifth derivative's size (at
/// most a few thousand for degree ≤ 7 nets in [−1, 1]³) and rounding ~10⁻¹³, so a
/// relative tolerance of 10⁻⁷ leaves a wide margin and still catches any wrong factor.
fn finite_difference<const D: usize, T: Triangle<D> + ?Sized>(
    t: &T,
    u: f64,
    v: f64,
    i: usize,
    j: usize,
    h: f64,
) -> Point<D> {
    let (lower, du, dv) = if i > 0 { ((i - 1, j), 1.0, 0.0) } else { ((i, j - 1), 0.0, 1.0) };
    let f = |s: f64| {
        let p = partials(t, u + s * du, v + s * dv, lower.0, lower.1);
        p[lower.0 * (lower.1 + 1) + lower.1]
    };
    (f(-2.0 * h) - f(2.0 * h) + (f(h) - f(-h)) * 8.0) / (12.0 * h)
}

fn assert_close<const D: usize>(a: &Point<D>, b: &Point<D>, tol: f64, what: &str) {
    assert!((a - b).norm() <= tol * b.norm().max(1.0), "{what}: {a:?} vs {b:?} (diff {:e})", (a - b).norm());
}

#[test]
fn de_casteljau_equals_the_bernstein_form() {
    let mut rng = Rng(7);
    let mut worst: f64 = 0.0;
    for degree in 0..=9 {
        let net = random_net(&mut rng, degree);
        let weights = random_weights(&mut rng, degree);
        let poly = BezierTriangle::new(net.clone()).unwrap();
        let rat = RationalBezierTriangle::new(net, weights).unwrap();
        for (u, v, w) in samples(&mut rng) {
            let (a, b) = (poly.point_de_casteljau(u, v, w), poly.point_bernstein(u, v, w));
            worst = worst.max((a - b).norm());
            assert_close(&a, &b, 1e-14, &format!("degree {degree} at ({u}, {v}, {w})"));
            assert_eq!(poly.point(u, v, w), a, "the trait's point is de Casteljau's");
            let (a, b) = (rat.point_de_casteljau(u, v, w), rat.point_bernstein(u, v, w));
            assert_close(&a, &b, 1e-14, &format!("rational degree {degree} at ({u}, {v}, {w})"));
            // Partials: de Casteljau (blossom) against the Bernstein form of the difference nets.
            let (du, dv) = (3, 2);
            let exact = partials(&poly, u, v, du, dv);
            let mut bern = vec![Point::<3>::zeros(); exact.len()];
            poly.eval_partials_bernstein(u, v, du, dv, &mut bern);
            for k in 0..exact.len() {
                assert_close(&exact[k], &bern[k], 1e-12, &format!("degree {degree} partial {k}"));
            }
            let exact = partials(&rat, u, v, du, dv);
            rat.eval_partials_bernstein(u, v, du, dv, &mut bern);
            for k in 0..exact.len() {
                assert_close(&exact[k], &bern[k], 1e-11, &format!("rational degree {degree} partial {k}"));
            }
        }
    }
    eprintln!("de Casteljau vs Bernstein, largest difference: {worst:e}");
}

#[test]
fn the_bernstein_form_is_the_textbook_sum() {
    // Σ n!/(i! j! k!) uⁱ vʲ wᵏ P_ijk written out with factorials, independent of the kernel.
    let fact = |n: usize| (1..=n).map(|x| x as f64).product::<f64>();
    let mut rng = Rng(11);
    for degree in 1..=7 {
        let net = random_net(&mut rng, degree);
        let t = BezierTriangle::new(net.clone()).unwrap();
        let (u, v, w) = rng.inside(0.0);
        let mut want = Point::<3>::zeros();
        for ((i, j, k), p) in multi_indices(degree).zip(&net) {
            want += p
                * (fact(degree) / (fact(i) * fact(j) * fact(k))
                    * u.powi(i as i32)
                    * v.powi(j as i32)
                    * w.powi(k as i32));
            assert_eq!(t.control_point(i, j, k), Some(p));
        }
        assert_close(&t.point(u, v, w), &want, 1e-14, &format!("degree {degree}"));
    }
}

#[test]
fn partials_match_finite_differences() {
    let mut rng = Rng(3);
    for degree in 1..=7 {
        let poly = BezierTriangle::new(random_net(&mut rng, degree)).unwrap();
        let rat = RationalBezierTriangle::new(random_net(&mut rng, degree), random_weights(&mut rng, degree)).unwrap();
        for _ in 0..10 {
            let (u, v, _) = rng.inside(0.05);
            for (name, t) in [("polynomial", &poly as &dyn Triangle<3>), ("rational", &rat as &dyn Triangle<3>)] {
                let exact = partials(t, u, v, 3, 3);
                for i in 0..=3 {
                    for j in 0..=3 {
                        if i + j == 0 || i + j > 4 {
                            continue;
                        }
                        let fd = finite_difference(t, u, v, i, j, 1e-3);
                        assert_close(&exact[i * 4 + j], &fd, 1e-7, &format!("{name} degree {degree} ∂({i},{j})"));
                    }
                }
            }
        }
    }
}

#[test]
fn directional_and_barycentric_derivatives() {
    let mut rng = Rng(5);
    for degree in 1..=7 {
        let t = BezierTriangle::new(random_net(&mut rng, degree)).unwrap();
        let rat = RationalBezierTriangle::new(random_net(&mut rng, degree), random_weights(&mut rng, degree)).unwrap();
        let (u, v, w) = rng.inside(0.05);
        let d = [0.3, -0.7, 0.4];
        let p = partials(&t, u, v, 3, 3);
        // Blossom path (Bézier override) against the chain rule on the partials.
        let mut blossom = [Point::<3>::zeros(); 4];
        t.directional_derivatives(u, v, w, d, &mut blossom);
        for r in 0..=3 {
            let mut want = Point::<3>::zeros();
            for i in 0..=r {
                // d already sums to zero, so (d_u, d_v) are its chart components.
                want += p[i * 4 + (r - i)] * (binomial(r, i) * d[0].powi(i as i32) * d[1].powi((r - i) as i32));
            }
            assert_close(&blossom[r], &want, 1e-12, &format!("degree {degree} D_d^{r}"));
        }
        // The generic (partials) path of the trait on a rational triangle against a finite
        // difference along the line λ + s d.
        let mut dd = [Point::<3>::zeros(); 2];
        rat.directional_derivatives(u, v, w, d, &mut dd);
        let h = 1e-4;
        let f = |s: f64| rat.point(u + s * d[0], v + s * d[1], w + s * d[2]);
        let fd = (f(-2.0 * h) - f(2.0 * h) + (f(h) - f(-h)) * 8.0) / (12.0 * h);
        assert_close(&dd[1], &fd, 1e-8, &format!("rational degree {degree} D_d"));
        // Barycentric derivatives: D_u − D_w = T_u, D_v − D_w = T_v, u D_u + v D_v + w D_w = 0,
        // and GMlib's homogeneous-degree-n D_u = n Σ B^{n−1}_I P_{I+e₁} is D_u + n T.
        let [bu, bv, bw] = t.barycentric_derivatives(u, v, w);
        assert_close(&(bu - bw), &p[4], 1e-13, "D_u − D_w = T_u");
        assert_close(&(bv - bw), &p[1], 1e-13, "D_v − D_w = T_v");
        assert!((bu * u + bv * v + bw * w).norm() < 1e-13 * p[4].norm().max(1.0), "Euler, degree 0");
        if degree >= 1 {
            let lower =
                BezierTriangle::from_fn(degree - 1, |(i, j, k)| *t.control_point(i + 1, j, k).unwrap()).unwrap();
            let gmlib = lower.point(u, v, w) * degree as f64;
            assert_close(&(bu + t.point(u, v, w) * degree as f64), &gmlib, 1e-13, "GMlib's D_u");
        }
    }
}

#[test]
fn degree_elevation_leaves_the_surface_unchanged() {
    let mut rng = Rng(13);
    for degree in 1..=7 {
        let poly = BezierTriangle::new(random_net(&mut rng, degree)).unwrap();
        let rat = RationalBezierTriangle::new(random_net(&mut rng, degree), random_weights(&mut rng, degree)).unwrap();
        let (mut pe, mut re) = (poly.clone(), rat.clone());
        for step in 1..=3 {
            pe = pe.elevate().unwrap();
            re = re.elevate().unwrap();
            assert_eq!((pe.degree(), re.degree()), (degree + step, degree + step));
            for (u, v, w) in samples(&mut rng) {
                assert_close(&pe.point(u, v, w), &poly.point(u, v, w), 1e-14, &format!("degree {degree} + {step}"));
                assert_close(&re.point(u, v, w), &rat.point(u, v, w), 1e-14, &format!("rational {degree} + {step}"));
            }
        }
    }
}

/// A child of the polynomial split, the rational one's, and their corners in the parent.
type Child<'a> = (&'a dyn Triangle<3>, &'a dyn Triangle<3>, [[f64; 3]; 3]);

#[test]
fn subdivision_reproduces_the_surface() {
    let mut rng = Rng(17);
    for degree in 1..=7 {
        let poly = BezierTriangle::new(random_net(&mut rng, degree)).unwrap();
        let rat = RationalBezierTriangle::new(random_net(&mut rng, degree), random_weights(&mut rng, degree)).unwrap();
        let p = [0.2, 0.45, 0.35];
        let e = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let three = [[p, e[1], e[2]], [e[0], p, e[2]], [e[0], e[1], p]];
        let m = |a: usize, b: usize| [(e[a][0] + e[b][0]) / 2.0, (e[a][1] + e[b][1]) / 2.0, (e[a][2] + e[b][2]) / 2.0];
        let four =
            [[e[0], m(0, 1), m(0, 2)], [m(0, 1), e[1], m(1, 2)], [m(0, 2), m(1, 2), e[2]], [m(1, 2), m(0, 2), m(0, 1)]];
        let pc = poly.split_at(p).unwrap();
        let rc = rat.split_at(p).unwrap();
        let pm = poly.split_midpoints();
        let rm = rat.split_midpoints();
        let children: Vec<Child> = (0..3)
            .map(|c| (&pc[c] as &dyn Triangle<3>, &rc[c] as &dyn Triangle<3>, three[c]))
            .chain((0..4).map(|c| (&pm[c] as &dyn Triangle<3>, &rm[c] as &dyn Triangle<3>, four[c])))
            .collect();
        for (child, rchild, q) in children {
            for (u, v, w) in samples(&mut rng) {
                let at = |k: usize| u * q[0][k] + v * q[1][k] + w * q[2][k];
                assert_close(
                    &child.point(u, v, w),
                    &poly.point(at(0), at(1), at(2)),
                    1e-13,
                    &format!("degree {degree}"),
                );
                assert_close(
                    &rchild.point(u, v, w),
                    &rat.point(at(0), at(1), at(2)),
                    1e-13,
                    &format!("rational {degree}"),
                );
            }
        }
        // Children share the parent's orientation: normals agree.
        let (u, v, w) = (0.3, 0.3, 0.4);
        let q = four[3];
        let at = |k: usize| u * q[0][k] + v * q[1][k] + w * q[2][k];
        if let (Some(a), Some(b)) = (pm[3].normal(u, v, w), poly.normal(at(0), at(1), at(2))) {
            assert!((a - b).norm() < 1e-10, "middle child's orientation");
        }
    }
}

#[test]
fn the_degenerate_tensor_patch_is_exact() {
    let mut rng = Rng(19);
    let mut worst: f64 = 0.0;
    for degree in 1..=7 {
        let poly = BezierTriangle::new(random_net(&mut rng, degree)).unwrap();
        let rat = RationalBezierTriangle::new(random_net(&mut rng, degree), random_weights(&mut rng, degree)).unwrap();
        let (ps, rs) = (poly.to_tensor_patch(), rat.to_tensor_patch());
        assert_eq!(ps.degrees(), (degree, degree));
        assert_eq!(rs.degrees(), (degree, degree));
        for a in 0..=16 {
            for b in 0..=16 {
                let (s, t) = (a as f64 / 16.0, b as f64 / 16.0);
                let [u, v, w] = degenerate_patch_parameters(s, t);
                let d = (ps.point(s, t) - poly.point(u, v, w)).norm();
                worst = worst.max(d);
                assert!(d <= 1e-14 * poly.point(u, v, w).norm().max(1.0), "degree {degree} at ({s}, {t}): {d:e}");
                let d = (rs.point(s, t) - rat.point(u, v, w)).norm();
                worst = worst.max(d);
                assert!(
                    d <= 1e-14 * rat.point(u, v, w).norm().max(1.0),
                    "rational degree {degree} at ({s}, {t}): {d:e}"
                );
            }
        }
    }
    eprintln!("tensor conversion, largest difference: {worst:e}");
}

#[test]
fn the_sphere_octant_is_exact() {
    let t = RationalBezierTriangle::sphere_octant();
    let tensor = t.to_tensor_patch();
    let mut rng = Rng(23);
    let mut worst: f64 = 0.0;
    for (u, v, w) in samples(&mut rng) {
        let p = t.point(u, v, w);
        worst = worst.max((p.norm() - 1.0).abs());
        assert!((p.norm() - 1.0).abs() < 1e-14, "|T| = {} at ({u}, {v}, {w})", p.norm());
        assert!(p.iter().all(|x| *x >= -1e-15), "in the octant");
        let [s, tt] = [1.0 - w, if u + v > 0.0 { v / (u + v) } else { 0.0 }];
        assert!((tensor.point(s, tt).norm() - 1.0).abs() < 1e-14, "tensor form");
    }
    for (u, v, w) in [(0.3, 0.3, 0.4), (0.6, 0.2, 0.2), (0.1, 0.1, 0.8)] {
        // Outward unit normal = position; K = 1, H = −1 (the normal points away from the centre).
        let p = t.point(u, v, w);
        assert!((t.normal(u, v, w).unwrap() - p).norm() < 1e-12);
        let k = t.curvatures(u, v, w).unwrap();
        assert!((k.gaussian - 1.0).abs() < 1e-11 && (k.mean.abs() - 1.0).abs() < 1e-11, "{k:?}");
    }
    assert_eq!(t.point(1.0, 0.0, 0.0), Point::<3>::x());
    for child in t.split_midpoints() {
        for (u, v, w) in samples(&mut rng) {
            assert!((child.point(u, v, w).norm() - 1.0).abs() < 1e-14);
        }
    }
    eprintln!("sphere octant, largest | |T| − 1 |: {worst:e}");
}

#[test]
fn constructors_name_the_field() {
    let p = Point::<3>::zeros();
    let e = BezierTriangle::new(vec![p; 5]).unwrap_err().to_string();
    assert!(e.starts_with("control_points:") && e.contains("got 5"), "{e}");
    let e = BezierTriangle::new(vec![p, Point::<3>::new(f64::NAN, 0.0, 0.0), p]).unwrap_err().to_string();
    assert!(e.starts_with("control_points[1][0]"), "{e}");
    let e = RationalBezierTriangle::new(vec![p; 3], vec![1.0, -1.0, 1.0]).unwrap_err().to_string();
    assert!(e.starts_with("weights:") && e.contains("-1"), "{e}");
    let t = BezierTriangle::new(vec![p; 3]).unwrap();
    let e = t.split_at([0.5, 0.5, 0.0]).unwrap_err().to_string();
    assert!(e.starts_with("point:"), "{e}");
    assert!(t.split_at([f64::NAN, 0.5, 0.0]).is_err());
    assert!(BezierTriangle::<3>::from_fn(31, |_| p).is_err());
    let sphere = Sphere::new(1.0).unwrap();
    let (a, b) = (Point::<2>::new(0.1, 0.1), Point::<2>::new(0.5, 0.2));
    let e = SubTriangle::new(sphere.clone(), [a, b, Point::<2>::new(0.3, 9.0)]).unwrap_err().to_string();
    assert!(e.starts_with("corners[2]") && e.contains("v = 9"), "{e}");
    let e = SubTriangle::new(sphere, [a, b, a * 2.0 - b]).unwrap_err().to_string();
    assert!(e.starts_with("corners:") && e.contains("collinear"), "{e}");
    // Evaluation outside the triangle clamps; NaN does not panic.
    assert_eq!(t.point(-1.0, 2.0, 0.0), t.point(0.0, 1.0, 0.0));
    assert!(t.point(f64::NAN, 0.5, 0.5).iter().all(|x| x.is_finite()));
}

// ---------------------------------------------------------------------------------------
// Sub-triangles

#[test]
fn sub_triangles_follow_the_chain_rule() {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let corners = [Point::<2>::new(0.3, 0.2), Point::<2>::new(1.4, 0.9), Point::<2>::new(0.5, 2.0)];
    let t = SubTriangle::new(torus.clone(), corners).unwrap();
    let mut rng = Rng(29);
    for _ in 0..10 {
        let (u, v, w) = rng.inside(0.05);
        let q = t.surface_parameter(u, v);
        assert_eq!(t.point(u, v, w), torus.point(q.x, q.y));
        let exact = partials(&t, u, v, 2, 2);
        for i in 0..=2 {
            for j in 0..=2 {
                if i + j > 0 {
                    let fd = finite_difference(&t, u, v, i, j, 1e-3);
                    assert_close(&exact[i * 3 + j], &fd, 1e-7, &format!("torus sub-triangle ∂({i},{j})"));
                }
            }
        }
        // Curvatures do not depend on the parametrisation.
        let (kt, ks) = (t.curvatures(u, v, w).unwrap(), torus.curvatures(q.x, q.y).unwrap());
        assert!((kt.gaussian - ks.gaussian).abs() < 1e-12 && (kt.mean.abs() - ks.mean.abs()).abs() < 1e-12);
    }
}

// ---------------------------------------------------------------------------------------
// Triangular B-functions

/// The six variants: (name, B, form).
fn variants() -> Vec<(String, TriangularBFunction)> {
    let kinds = [
        ("ERBS", BFunction::erbs_default()),
        ("Beta(2,2)", BFunction::beta(2, 2).unwrap()),
        ("polynomial(1)", BFunction::polynomial(1).unwrap()),
    ];
    let mut v = Vec::new();
    for (name, b) in kinds {
        for form in [TriangularForm::Rational, TriangularForm::NonRational] {
            v.push((format!("{name} {form:?}"), TriangularBFunction::new(b.clone(), form).unwrap()));
        }
    }
    v
}

fn beta_partials(b: &TriangularBFunction, u: f64, v: f64, du: usize, dv: usize) -> Vec<[f64; 3]> {
    let mut out = vec![[0.0; 3]; (du + 1) * (dv + 1)];
    b.eval_partials(u, v, du, dv, &mut out);
    out
}

#[test]
fn triangular_bfunctions_are_a_partition_of_unity() {
    let mut rng = Rng(31);
    for (name, b) in variants() {
        let mut worst: f64 = 0.0;
        for (u, v, w) in samples(&mut rng).into_iter().chain((0..500).map(|_| rng.inside(0.0))) {
            let x = b.values(u, v, w);
            worst = worst.max((x[0] + x[1] + x[2] - 1.0).abs());
            assert!(
                (x[0] + x[1] + x[2] - 1.0).abs() <= 1e-14,
                "{name}: Σβ = {} at ({u}, {v}, {w})",
                x[0] + x[1] + x[2]
            );
            assert!(x.iter().all(|y| *y >= 0.0 && *y <= 1.0 + 1e-15), "{name}: {x:?} at ({u}, {v}, {w})");
            // Derivatives of the sum vanish too.
            let d = beta_partials(&b, u, v, 2, 2);
            for (k, dk) in d.iter().enumerate().skip(1) {
                assert!(
                    (dk[0] + dk[1] + dk[2]).abs() < 1e-9 * (dk[0].abs() + dk[1].abs() + 1.0),
                    "{name}: Σ∂β, partial {k}"
                );
            }
        }
        eprintln!("{name}: largest |Σβ − 1| = {worst:e}");
        // Corners: β_i = 1 at corner i exactly.
        assert_eq!(b.values(1.0, 0.0, 0.0), [1.0, 0.0, 0.0], "{name}");
        assert_eq!(b.values(0.0, 1.0, 0.0), [0.0, 1.0, 0.0], "{name}");
        assert_eq!(b.values(0.0, 0.0, 1.0), [0.0, 0.0, 1.0], "{name}");
    }
}

#[test]
fn triangular_bfunctions_are_flat_at_the_corners() {
    for (name, b) in variants() {
        // Test orders up to the flatness (up to 4 for ERBS, flat to every order).
        let k = b.flatness().unwrap_or(4);
        for corner in [(1.0, 0.0), (0.0, 1.0), (0.0, 0.0)] {
            let d = beta_partials(&b, corner.0, corner.1, k, k);
            for p in 0..=k {
                for q in 0..=k - p {
                    if p + q == 0 {
                        continue;
                    }
                    for i in 0..3 {
                        assert!(
                            d[p * (k + 1) + q][i].abs() < 1e-12,
                            "{name}: ∂({p},{q})β_{i} = {} at {corner:?}",
                            d[p * (k + 1) + q][i]
                        );
                    }
                }
            }
            // And order k + 1 does not vanish for the polynomial kinds (the flatness is exact).
            if let Some(k) = b.flatness() {
                let d = beta_partials(&b, corner.0, corner.1, k + 1, 0);
                let e = beta_partials(&b, corner.0, corner.1, 0, k + 1);
                let top = d[k + 1].iter().chain(e[k + 1].iter()).fold(0.0f64, |m, x| m.max(x.abs()));
                assert!(top > 1e-3, "{name}: order {} vanishes too at {corner:?}", k + 1);
            }
        }
        // Independently of the exact derivatives: along any ray into the triangle from a
        // corner, |β(corner + h d) − β(corner)| = O(h^{k+1}): halving h divides it by about
        // 2^{k+1} (ERBS: faster than any power).
        let order = b.flatness().map_or(10, |k| k + 1) as i32;
        for (c, d) in [
            ([1.0, 0.0, 0.0], [-0.6, 0.25, 0.35]),
            ([0.0, 1.0, 0.0], [0.5, -0.7, 0.2]),
            ([0.0, 0.0, 1.0], [0.3, 0.4, -0.7]),
        ] {
            let at = |h: f64| b.values(c[0] + h * d[0], c[1] + h * d[1], c[2] + h * d[2]);
            let (h1, h2) = if b.flatness().is_none() { (0.04, 0.02) } else { (2e-3, 1e-3) };
            let base = b.values(c[0], c[1], c[2]);
            for i in 0..3 {
                let (a1, a2) = ((at(h1)[i] - base[i]).abs(), (at(h2)[i] - base[i]).abs());
                if a1 > 1e-300 {
                    let ratio = a1 / a2.max(1e-300);
                    assert!(
                        ratio > 0.8 * 2f64.powi(order),
                        "{name}: β_{i} near corner {c:?}: ratio {ratio} for order {order}"
                    );
                }
            }
        }
    }
}

#[test]
fn triangular_bfunction_partials_match_finite_differences() {
    let mut rng = Rng(37);
    for (name, b) in variants() {
        for _ in 0..20 {
            let (u, v, _) = rng.inside(0.05);
            let exact = beta_partials(&b, u, v, 3, 3);
            let h = 1e-4;
            for pq in [(1usize, 0usize), (0, 1), (2, 0), (1, 1), (0, 2), (2, 1), (1, 2), (3, 0)] {
                let (lower, du, dv) =
                    if pq.0 > 0 { ((pq.0 - 1, pq.1), 1.0, 0.0) } else { ((pq.0, pq.1 - 1), 0.0, 1.0) };
                let f = |s: f64| {
                    beta_partials(&b, u + s * du, v + s * dv, lower.0, lower.1)[lower.0 * (lower.1 + 1) + lower.1]
                };
                for i in 0..3 {
                    let fd = (f(-2.0 * h)[i] - f(2.0 * h)[i] + 8.0 * (f(h)[i] - f(-h)[i])) / (12.0 * h);
                    let e = exact[pq.0 * 4 + pq.1][i];
                    // ERBS derivatives grow fast near the edges (φ's essential singularity);
                    // 10⁻⁶ of the size plus 10⁻⁶ absolute covers the h⁴ term there.
                    assert!((e - fd).abs() < 1e-6 * e.abs().max(1.0), "{name}: ∂{pq:?}β_{i} = {e} vs {fd}");
                }
            }
        }
    }
}

#[test]
fn triangular_bfunctions_reduce_to_the_bfunction_on_edges() {
    for (name, b) in variants() {
        let bf = b.bfunction().clone();
        for s in [0.1, 0.3, 0.5, 0.77] {
            // Edge w = 0 from v (s = 0) to u (s = 1): β_w = 0, β_u = B(s), β_v = 1 − B(s).
            let x = b.values(s, 1.0 - s, 0.0);
            assert!(x[2].abs() < 1e-15, "{name}: β_w = {} on its opposite edge", x[2]);
            assert!((x[0] - bf.value(s)).abs() < 1e-14 && (x[1] - bf.value(1.0 - s)).abs() < 1e-14, "{name}: {x:?}");
        }
    }
    // The cubic's non-rational form is the Bernstein–Bézier cubic u³ + 3u²(v + w) + 2uvw.
    let b = TriangularBFunction::non_rational(BFunction::polynomial(1).unwrap()).unwrap();
    let mut rng = Rng(41);
    for _ in 0..50 {
        let (u, v, w) = rng.inside(0.0);
        let bb = |a: f64, b: f64, c: f64| a.powi(3) + 3.0 * a * a * (b + c) + 2.0 * a * b * c;
        let x = b.values(u, v, w);
        assert!(
            (x[0] - bb(u, v, w)).abs() < 1e-15
                && (x[1] - bb(v, w, u)).abs() < 1e-15
                && (x[2] - bb(w, u, v)).abs() < 1e-15
        );
    }
    // Asymmetric B-functions have only the rational form.
    assert!(TriangularBFunction::non_rational(BFunction::erbs(1.0, 1.0, 1.0, 0.3).unwrap()).is_err());
    let e = TriangularBFunction::non_rational(BFunction::beta(1, 2).unwrap()).unwrap_err().to_string();
    assert!(e.starts_with("bfunction:"), "{e}");
}

// ---------------------------------------------------------------------------------------
// GERBS triangles

fn local_bezier(rng: &mut Rng, degree: usize, shift: Point<3>) -> Arc<dyn Triangle<3>> {
    let net: Vec<Point<3>> = random_net(rng, degree).into_iter().map(|p| p * 0.3 + shift).collect();
    Arc::new(BezierTriangle::new(net).unwrap())
}

fn gerbs(rng: &mut Rng, basis: TriangularBFunction) -> GerbsTriangle<3> {
    let sphere: Arc<dyn Surface<3>> = Arc::new(Sphere::new(2.0).unwrap());
    let sub: Arc<dyn Triangle<3>> = Arc::new(
        SubTriangle::new(sphere, [Point::<2>::new(0.2, 0.1), Point::<2>::new(1.1, 0.3), Point::<2>::new(0.5, 1.2)])
            .unwrap(),
    );
    let rat: Arc<dyn Triangle<3>> =
        Arc::new(RationalBezierTriangle::new(random_net(rng, 3), random_weights(rng, 3)).unwrap());
    GerbsTriangle::new([local_bezier(rng, 4, Point::<3>::new(1.0, 0.0, 0.0)), sub, rat], basis).unwrap()
}

#[test]
fn gerbs_triangles_interpolate_their_locals_at_the_corners() {
    let mut rng = Rng(43);
    for (name, basis) in variants() {
        let mut t = gerbs(&mut rng, basis.clone());
        // Frames: turn, scale and move each local about its origin.
        t.set_frame(0, Affine::rotation(Point::<3>::new(1.0, 2.0, 0.5), 0.7).unwrap()).unwrap();
        t.set_frame(1, Affine::uniform_scale(1.5).after(&Affine::translation(Point::<3>::new(0.1, -0.2, 0.3))))
            .unwrap();
        t.set_frame(2, Affine::scale(Point::<3>::new(1.0, 2.0, 0.5))).unwrap();
        let k = basis.flatness().unwrap_or(4);
        let mut worst: f64 = 0.0;
        for (i, (u, v)) in [(1.0, 0.0), (0.0, 1.0), (0.0, 0.0)].into_iter().enumerate() {
            let got = partials(&t, u, v, k, k);
            let mut want = vec![Point::<3>::zeros(); (k + 1) * (k + 1)];
            t.local_partials(i, u, v, k, k, &mut want).unwrap();
            for p in 0..=k {
                for q in 0..=k - p {
                    let (g, w) = (got[p * (k + 1) + q], want[p * (k + 1) + q]);
                    worst = worst.max((g - w).norm() / w.norm().max(1.0));
                    assert!(
                        (g - w).norm() <= 1e-12 * w.norm().max(1.0),
                        "{name}: corner {i}, ∂({p},{q}): {g:?} vs {w:?}"
                    );
                }
            }
            assert_eq!(t.origin(i).map(|o| (o - want[0]).norm() < 1e-15 || i == 1), Some(true));
        }
        eprintln!("{name}: corner interpolation up to order {k}, largest relative error {worst:e}");
    }
}

#[test]
fn gerbs_triangles_are_affine_invariant() {
    let mut rng = Rng(47);
    let g = Affine::rotation(Point::<3>::new(0.3, -1.0, 2.0), 1.1)
        .unwrap()
        .after(&Affine::scale(Point::<3>::new(2.0, 0.5, 1.5)));
    let g = Affine { translation: Point::<3>::new(3.0, -1.0, 0.5), ..g };
    for (name, basis) in variants() {
        let nets: Vec<Vec<Point<3>>> = (0..3).map(|_| random_net(&mut rng, 3)).collect();
        let make = |f: &dyn Fn(&Point<3>) -> Point<3>| -> GerbsTriangle<3> {
            let locals = [0, 1, 2].map(|i| {
                Arc::new(BezierTriangle::new(nets[i].iter().map(f).collect()).unwrap()) as Arc<dyn Triangle<3>>
            });
            GerbsTriangle::new(locals, basis.clone()).unwrap()
        };
        let plain = make(&|p| *p);
        let mapped = make(&|p| g.apply_point(p));
        for (u, v, w) in samples(&mut rng) {
            assert_close(&mapped.point(u, v, w), &g.apply_point(&plain.point(u, v, w)), 1e-13, &name);
            let (a, b) = (partials(&mapped, u, v, 1, 1), partials(&plain, u, v, 1, 1));
            for k in 1..4 {
                assert_close(&a[k], &g.apply_vector(&b[k]), 1e-12, &format!("{name} partial {k}"));
            }
        }
        // A frame about local i's origin is the same as mapping local i's net by it.
        let mut framed = plain.clone();
        let turn = Affine::rotation(Point::<3>::z(), 0.4).unwrap();
        framed.set_frame(1, turn).unwrap();
        let o = plain.origin(1).unwrap();
        let moved = {
            let locals = [0, 1, 2].map(|i| {
                let f = |p: &Point<3>| if i == 1 { turn.apply_point_about(&o, p) } else { *p };
                Arc::new(BezierTriangle::new(nets[i].iter().map(f).collect()).unwrap()) as Arc<dyn Triangle<3>>
            });
            GerbsTriangle::new(locals, basis.clone()).unwrap()
        };
        for (u, v, w) in samples(&mut rng) {
            assert_close(&framed.point(u, v, w), &moved.point(u, v, w), 1e-13, &format!("{name} frame"));
        }
        // Outside local 1's corner neighbourhood... the frame changes nothing at the other corners.
        assert_close(&framed.point(1.0, 0.0, 0.0), &plain.point(1.0, 0.0, 0.0), 1e-15, "corner u stays");
    }
}

#[test]
fn gerbs_partials_match_finite_differences() {
    let mut rng = Rng(53);
    for (name, basis) in variants() {
        let mut t = gerbs(&mut rng, basis);
        t.set_frame(2, Affine::rotation(Point::<3>::x(), 0.3).unwrap()).unwrap();
        for _ in 0..8 {
            let (u, v, _) = rng.inside(0.08);
            let exact = partials(&t, u, v, 2, 2);
            for i in 0..=2 {
                for j in 0..=2 {
                    if i + j == 0 || i + j > 3 {
                        continue;
                    }
                    let fd = finite_difference(&t, u, v, i, j, 1e-4);
                    assert_close(&exact[i * 3 + j], &fd, 1e-6, &format!("{name} ∂({i},{j}) at ({u}, {v})"));
                }
            }
        }
    }
}

#[test]
fn hermite_gerbs_triangles_reproduce_the_model_at_the_corners() {
    let torus: Arc<dyn Surface<3>> = Arc::new(Torus::new(3.0, 1.0).unwrap());
    let model =
        SubTriangle::new(torus, [Point::<2>::new(0.2, 0.1), Point::<2>::new(0.9, 0.4), Point::<2>::new(0.3, 1.0)])
            .unwrap();
    let degree = 3;
    let t = GerbsTriangle::hermite(&model, degree, TriangularBFunction::rational(BFunction::erbs_default()).unwrap())
        .unwrap();
    for corner in 0..3 {
        let local = hermite_local(&model, corner, degree).unwrap();
        assert_eq!(local.degree(), degree);
        let (u, v) = [(1.0, 0.0), (0.0, 1.0), (0.0, 0.0)][corner];
        let (got, want) = (partials(&t, u, v, degree, degree), partials(&model, u, v, degree, degree));
        for p in 0..=degree {
            for q in 0..=degree - p {
                assert_close(
                    &got[p * (degree + 1) + q],
                    &want[p * (degree + 1) + q],
                    1e-11,
                    &format!("corner {corner} ∂({p},{q})"),
                );
            }
        }
    }
    // In between it approximates the torus (three cubics over a patch of about one unit).
    let (u, v, w) = (1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
    assert!((t.point(u, v, w) - model.point(u, v, w)).norm() < 0.05);
}

// ---------------------------------------------------------------------------------------
// Property tests over degrees 1..=7 and random nets

fn net_strategy() -> impl Strategy<Value = (usize, Vec<f64>, Vec<f64>, (f64, f64))> {
    (1usize..=7).prop_flat_map(|n| {
        let len = net_len(n);
        (
            Just(n),
            prop::collection::vec(-10.0f64..10.0, 3 * len),
            prop::collection::vec(0.1f64..10.0, len),
            (0.0f64..1.0, 0.0f64..1.0),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_nets_keep_farins_identities((n, coords, weights, (a, b)) in net_strategy()) {
        let net: Vec<Point<3>> = coords.chunks(3).map(|c| Point::<3>::new(c[0], c[1], c[2])).collect();
        let poly = BezierTriangle::new(net.clone()).unwrap();
        let rat = RationalBezierTriangle::new(net, weights).unwrap();
        prop_assert_eq!(poly.degree(), n);
        // A point of the triangle from the unit square.
        let [u, v, w] = degenerate_patch_parameters(a, b);
        let scale = 10.0;
        prop_assert!((poly.point_de_casteljau(u, v, w) - poly.point_bernstein(u, v, w)).norm() <= 1e-13 * scale);
        prop_assert!((rat.point_de_casteljau(u, v, w) - rat.point_bernstein(u, v, w)).norm() <= 1e-13 * scale);
        prop_assert!((poly.elevate().unwrap().point(u, v, w) - poly.point(u, v, w)).norm() <= 1e-13 * scale);
        prop_assert!((rat.elevate().unwrap().point(u, v, w) - rat.point(u, v, w)).norm() <= 1e-12 * scale);
        prop_assert!((poly.to_tensor_patch().point(a, b) - poly.point(u, v, w)).norm() <= 1e-13 * scale);
        prop_assert!((rat.to_tensor_patch().point(a, b) - rat.point(u, v, w)).norm() <= 1e-12 * scale);
        // The middle child of the midpoint split at (u, v, w) is the parent at its image.
        let [_, _, _, mid] = poly.split_midpoints();
        let q = [[0.0, 0.5, 0.5], [0.5, 0.0, 0.5], [0.5, 0.5, 0.0]];
        let at = |k: usize| u * q[0][k] + v * q[1][k] + w * q[2][k];
        prop_assert!((mid.point(u, v, w) - poly.point(at(0), at(1), at(2))).norm() <= 1e-12 * scale);
    }
}
