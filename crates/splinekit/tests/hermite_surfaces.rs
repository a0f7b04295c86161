//! Hermite surfaces and lofts (GMlib's bicubic Hermite patch, `PHermiteCurveSurf` and
//! skinning): each reproduces its data to 1e-12 — the corner data of the bicubic, the
//! boundary and cross-derivative curves of the curve surface, the sections of the lofts —
//! with partials against central differences of the partial one order lower; the loft of
//! B-spline sections is the B-spline loft at the same parameters, and the Bézier loft is a
//! polynomial of degree n − 1 across.

use splinekit::Point;
use splinekit::curve::model::{Circle, Helix, Line};
use splinekit::curve::{BSplineCurve, BezierCurve, Curve};
use splinekit::fit::Parametrization;
use splinekit::surface::derived::HermiteCurveSurface;
use splinekit::surface::loft::{CurveLoft, LoftParameters};
use splinekit::surface::{BSplineSurface, BezierSurface, HermiteCorner, Surface};
use splinekit::{Error, Result};

/// A fixed pseudo-random sequence in (−1, 1).
fn randoms() -> impl FnMut() -> f64 {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        2.0 * ((state >> 11) as f64 / (1u64 << 53) as f64) - 1.0
    }
}

fn partials<S: Surface<3> + ?Sized>(s: &S, u: f64, v: f64, du: usize, dv: usize) -> Vec<Point<3>> {
    let mut out = vec![Point::<3>::zeros(); (du + 1) * (dv + 1)];
    s.eval_partials(u, v, du, dv, &mut out);
    out
}

/// ∂^{i+j} by the fourth-order central difference of the exact (i−1, j) or (i, j−1) partial.
fn fd<S: Surface<3> + ?Sized>(s: &S, u: f64, v: f64, i: usize, j: usize, h: f64) -> Point<3> {
    let f = |d: f64| if i > 0 { s.partial(u + d, v, i - 1, j) } else { s.partial(u, v + d, i, j - 1) };
    (f(-2.0 * h) - f(2.0 * h) + (f(h) - f(-h)) * 8.0) / (12.0 * h)
}

/// Every partial with 1 ≤ i + j, i, j ≤ 3 against [`fd`] inside the domain.
fn check_partials<S: Surface<3> + ?Sized>(s: &S, name: &str) {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let h = 1e-4 * du.length().min(dv.length());
    for (a, b) in [(0.13, 0.21), (0.52, 0.46), (0.77, 0.31), (0.35, 0.88)] {
        let (u, v) = (du.lerp(a), dv.lerp(b));
        for i in 0..=3 {
            for j in 0..=3 {
                if i + j == 0 {
                    continue;
                }
                let (got, want) = (s.partial(u, v, i, j), fd(s, u, v, i, j, h));
                assert!(
                    (got - want).norm() < 1e-6 * want.norm().max(1.0),
                    "{name}: ({i}, {j}) at ({u}, {v}): {got} vs {want}"
                );
            }
        }
    }
}

fn random_point(r: &mut impl FnMut() -> f64) -> Point<3> {
    Point::<3>::new(3.0 * r(), 3.0 * r(), 3.0 * r())
}

#[test]
fn the_bicubic_reproduces_random_corner_data() -> Result<()> {
    let mut r = randoms();
    for _ in 0..20 {
        let mut corner = || HermiteCorner {
            point: random_point(&mut r),
            du: random_point(&mut r),
            dv: random_point(&mut r),
            duv: random_point(&mut r),
        };
        let corners = [[corner(), corner()], [corner(), corner()]];
        let s = BezierSurface::bicubic_hermite(corners)?;
        assert_eq!(s.degrees(), (3, 3));
        for (a, row) in corners.iter().enumerate() {
            for (b, c) in row.iter().enumerate() {
                let p = partials(&s, a as f64, b as f64, 1, 1);
                for (got, want, what) in
                    [(p[0], c.point, "S"), (p[2], c.du, "S_u"), (p[1], c.dv, "S_v"), (p[3], c.duv, "S_uv")]
                {
                    assert!(
                        (got - want).norm() < 1e-12 * want.norm().max(1.0),
                        "{what} at ({a}, {b}): {got} vs {want}"
                    );
                }
            }
        }
        check_partials(&s, "bicubic");
    }
    // A bicubic is reproduced from its own corner data: (u², v³ − u v, u²v²).
    let f = |u: f64, v: f64| HermiteCorner {
        point: Point::<3>::new(u * u, v * v * v - u * v, u * u * v * v),
        du: Point::<3>::new(2.0 * u, -v, 2.0 * u * v * v),
        dv: Point::<3>::new(0.0, 3.0 * v * v - u, 2.0 * u * u * v),
        duv: Point::<3>::new(0.0, -1.0, 4.0 * u * v),
    };
    let s = BezierSurface::bicubic_hermite([[f(0.0, 0.0), f(0.0, 1.0)], [f(1.0, 0.0), f(1.0, 1.0)]])?;
    for (u, v) in [(0.3, 0.6), (0.9, 0.1), (0.5, 0.5)] {
        assert!((s.point(u, v) - f(u, v).point).norm() < 1e-14);
    }
    let mut bad = [[f(0.0, 0.0), f(0.0, 1.0)], [f(1.0, 0.0), f(1.0, 1.0)]];
    bad[1][0].duv[2] = f64::NAN;
    match BezierSurface::bicubic_hermite(bad) {
        Err(Error::Invalid { field, .. }) => assert_eq!(field, "duv[1][0]"),
        other => panic!("{other:?}"),
    }
    Ok(())
}

fn bezier3(r: &mut impl FnMut() -> f64, n: usize) -> Box<dyn Curve<3>> {
    Box::new(BezierCurve::new((0..n).map(|_| random_point(r)).collect()).unwrap())
}

#[test]
fn the_curve_surface_reproduces_its_boundaries_and_cross_derivatives() -> Result<()> {
    let mut r = randoms();
    for _ in 0..10 {
        let curves: Vec<Box<dyn Curve<3>>> = (0..4).map(|k| bezier3(&mut r, 3 + k)).collect();
        let [c0, c1, d0, d1]: [Box<dyn Curve<3>>; 4] = curves.try_into().ok().unwrap();
        let keep: Vec<Vec<Point<3>>> = [&c0, &c1, &d0, &d1]
            .iter()
            .map(|c| {
                (0..=10)
                    .flat_map(|i| {
                        let mut o = [Point::<3>::zeros(); 3];
                        c.eval(i as f64 / 10.0, &mut o);
                        o
                    })
                    .collect()
            })
            .collect();
        let s = HermiteCurveSurface::new(c0, c1, d0, d1)?;
        for i in 0..=10 {
            let u = i as f64 / 10.0;
            let at0 = partials(&s, u, 0.0, 2, 1);
            let at1 = partials(&s, u, 1.0, 2, 1);
            // at[i_u·2 + j_v]: (i, 0) positions along u, (i, 1) cross derivatives.
            for iu in 0..=2 {
                let want = [keep[0][3 * i + iu], keep[2][3 * i + iu], keep[1][3 * i + iu], keep[3][3 * i + iu]];
                let got = [at0[iu * 2], at0[iu * 2 + 1], at1[iu * 2], at1[iu * 2 + 1]];
                for (g, w) in got.iter().zip(want) {
                    assert!((g - w).norm() < 1e-12 * w.norm().max(1.0), "u-order {iu} at {u}: {g} vs {w}");
                }
            }
        }
        check_partials(&s, "hermite curve surface");
    }
    Ok(())
}

#[test]
fn the_curve_surface_checks_its_curves() {
    let line = |a: [f64; 3], b: [f64; 3]| -> Box<dyn Curve<3>> { Box::new(Line::new(a.into(), b.into()).unwrap()) };
    let circle = || -> Box<dyn Curve<3>> { Box::new(Circle::new(1.0).unwrap()) };
    let helix = || -> Box<dyn Curve<3>> { Box::new(Helix::new(1.0, 1.0, 1.0).unwrap()) };
    let field = |r: splinekit::Result<HermiteCurveSurface<3>>| match r {
        Err(Error::Invalid { field, message }) => (field, message),
        Err(e) => panic!("{e}"),
        Ok(_) => panic!("accepted"),
    };
    // A line on [0, 1] beside curves on [0, 2π].
    let (f, m) = field(HermiteCurveSurface::new(circle(), circle(), line([0.0; 3], [1.0; 3]), circle()));
    assert_eq!(f, "bottom_derivative");
    assert!(m.contains("differs from bottom's"), "{m}");
    // A helix on [0, 2π] is open, the circles closed.
    let (f, m) = field(HermiteCurveSurface::new(circle(), circle(), circle(), helix()));
    assert_eq!(f, "top_derivative");
    assert!(m.contains("open but bottom is closed"), "{m}");
    // Four circles: a closed tube-like band.
    let s = HermiteCurveSurface::new(circle(), circle(), circle(), circle()).unwrap();
    assert!(s.is_closed_u());
}

/// n random Bézier sections of degrees 1 to 3, the same for the same n.
fn random_sections(n: usize) -> Vec<Box<dyn Curve<3>>> {
    let mut r = randoms();
    (0..n).map(|k| bezier3(&mut r, 2 + k % 3)).collect()
}

#[test]
fn lofts_interpolate_their_sections() -> Result<()> {
    for n in [2, 3, 5] {
        for (degree, params) in [
            (n - 1, LoftParameters::Spacing(Parametrization::ChordLength)),
            (1, LoftParameters::Spacing(Parametrization::Uniform)),
            ((n - 1).min(3), LoftParameters::Spacing(Parametrization::Centripetal)),
            (n - 1, LoftParameters::Given((0..n).map(|k| 2.0 + (k * k) as f64).collect())),
        ] {
            let loft = CurveLoft::new(random_sections(n), degree, &params)?;
            let v = loft.parameters().to_vec();
            assert_eq!(v.len(), n);
            for (k, c) in random_sections(n).iter().enumerate() {
                for i in 0..=10 {
                    let u = i as f64 / 10.0;
                    let got = partials(&loft, u, v[k], 2, 0);
                    let mut w = [Point::<3>::zeros(); 3];
                    c.eval(u, &mut w);
                    for o in 0..=2 {
                        assert!(
                            (got[o] - w[o]).norm() < 1e-12 * w[o].norm().max(1.0),
                            "n {n}, degree {degree}, section {k}, u-order {o} at {u}: {} vs {}",
                            got[o],
                            w[o]
                        );
                    }
                }
            }
            check_partials(&loft, "loft");
        }
    }
    Ok(())
}

#[test]
fn the_bezier_loft_is_a_polynomial_of_degree_n_minus_1_across() -> Result<()> {
    // Four sections: the cubic in v through them; its fourth v-derivative vanishes, and on
    // sections taken from a surface cubic in v the loft is that surface.
    let f = |u: f64, v: f64| Point::<3>::new(u + v, u * v * v * v - v, (u * 3.0).sin() * (1.0 + v * v));
    let params = [0.0, 0.2, 0.7, 1.0];
    let sections: Vec<Box<dyn Curve<3>>> = params
        .iter()
        .map(|&v| -> Box<dyn Curve<3>> {
            let pts: Vec<Point<3>> = (0..=8).map(|i| f(i as f64 / 8.0, v)).collect();
            Box::new(BezierCurve::new(pts).unwrap())
        })
        .collect();
    let loft = CurveLoft::new(sections, 3, &LoftParameters::Given(params.to_vec()))?;
    assert_eq!(loft.knots_v(), &[0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
    for (u, v) in [(0.1, 0.5), (0.6, 0.33), (0.9, 0.95)] {
        assert!(loft.partial(u, v, 0, 4).norm() < 1e-12);
        // f's first two coordinates are polynomials of degree ≤ 8 in u (exact in the
        // degree-8 sections), cubic in v: the loft is f there.
        let (got, want) = (loft.point(u, v), f(u, v));
        assert!((got[0] - want[0]).abs() < 1e-13 && (got[1] - want[1]).abs() < 1e-13, "{got} vs {want}");
    }
    Ok(())
}

#[test]
fn a_loft_of_bsplines_is_the_bspline_loft_at_its_parameters() -> Result<()> {
    let p = |x: f64, y: f64, z: f64| Point::<3>::new(x, y, z);
    let a =
        BSplineCurve::clamped_uniform(2, vec![p(0.0, 0.0, 0.0), p(1.0, 0.5, 0.0), p(2.0, 0.0, 0.0), p(3.0, 0.2, 0.0)])?;
    let b = BSplineCurve::new(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.3, 2.0, 2.0, 2.0, 2.0],
        vec![p(0.0, 0.0, 1.0), p(1.0, 1.0, 1.2), p(2.0, -1.0, 1.0), p(2.5, 0.0, 0.8), p(3.0, 0.0, 1.0)],
    )?;
    let c = BSplineCurve::clamped_uniform(1, vec![p(0.0, 0.0, 2.0), p(3.0, 0.0, 2.5)])?;
    let d =
        BSplineCurve::clamped_uniform(3, vec![p(0.0, 1.0, 3.0), p(1.0, 2.0, 3.0), p(2.0, 0.0, 3.0), p(3.0, 1.0, 3.0)])?;
    let all = [a, b, c, d];
    for degree in [1, 2, 3] {
        let boxed: Vec<Box<dyn Curve<3>>> = all.iter().map(|c| Box::new(c.clone()) as Box<dyn Curve<3>>).collect();
        let loft = CurveLoft::new(boxed, degree, &LoftParameters::Spacing(Parametrization::ChordLength))?;
        let spline = BSplineSurface::loft_at(&all, degree, loft.parameters())?;
        for i in 0..=12 {
            for j in 0..=12 {
                let (u, v) = (i as f64 / 12.0, j as f64 / 12.0);
                let (g, w) = (partials(&loft, u, v, 1, 1), partials(&spline, u, v, 1, 1));
                for k in 0..4 {
                    assert!((g[k] - w[k]).norm() < 1e-11 * w[k].norm().max(1.0), "degree {degree}, {k} at ({u}, {v})");
                }
            }
        }
    }
    Ok(())
}

#[test]
fn lofts_refuse_what_they_cannot_make_naming_the_field() {
    let line = |z: f64| -> Box<dyn Curve<3>> {
        Box::new(Line::new(Point::<3>::new(0.0, 0.0, z), Point::<3>::new(1.0, 0.0, z)).unwrap())
    };
    let circle = || -> Box<dyn Curve<3>> { Box::new(Circle::new(1.0).unwrap()) };
    let field = |r: splinekit::Result<CurveLoft<3>>| match r {
        Err(Error::Invalid { field, .. }) | Err(Error::Count { field, .. }) => field,
        Err(e) => panic!("{e}"),
        Ok(_) => panic!("accepted"),
    };
    let chord = LoftParameters::Spacing(Parametrization::ChordLength);
    assert_eq!(field(CurveLoft::new(vec![line(0.0)], 1, &chord)), "sections");
    assert_eq!(field(CurveLoft::new(vec![line(0.0), line(1.0)], 2, &chord)), "degree_v");
    assert_eq!(field(CurveLoft::new(vec![line(0.0), circle()], 1, &chord)), "sections[1]");
    assert_eq!(field(CurveLoft::new(vec![line(0.0), line(0.0), line(1.0)], 1, &chord)), "sections[1]");
    assert_eq!(
        field(CurveLoft::new(vec![line(0.0), line(1.0)], 1, &LoftParameters::Given(vec![1.0, 1.0]))),
        "parameters[1]"
    );
    assert_eq!(field(CurveLoft::new(vec![line(0.0), line(1.0)], 1, &LoftParameters::Given(vec![1.0]))), "parameters");
}
