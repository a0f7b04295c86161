//! The gallery's figures: each function builds one SVG drawing with splinekit.

use anyhow::Result;
use splinekit::Point;
use splinekit::basis::{basis_function, bernstein};
use splinekit::curve::model::{Butterfly, Circle, Heart, Helix, Lissajous, Trefoil};
use splinekit::curve::{BSplineCurve, BezierCurve, CatmullRomCurve, CircleFrame, Curve, HermiteCurve, NurbsCurve};
use splinekit::fit::{FitOptions, KnotPlacement, fit_curve};
use splinekit::query::Aabb;
use splinekit::subdivision::{ChaikinOptions, FourPointOptions, chaikin, four_point, lane_riesenfeld};
use splinekit_mesh::{Polyline, Projection, SvgFigure};
use std::f64::consts::TAU;

/// One finished figure.
pub struct Figure {
    /// File name (no directory).
    pub file: &'static str,
    /// Caption for the index page.
    pub caption: String,
    /// The SVG text.
    pub svg: String,
}

const W: f64 = 640.0;
const H: f64 = 480.0;
const CURVE: &str = "#1f5fbf";
const POLYGON: &str = "#999999";
const POINTS: &str = "#d62728";
const MODEL: &str = "#bbbbbb";
const PALETTE: [&str; 6] = ["#1f5fbf", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"];

fn p2(x: f64, y: f64) -> Point<2> {
    Point::<2>::new(x, y)
}

fn curve_points<const D: usize>(c: &dyn Curve<D>) -> Result<(Vec<Point<D>>, bool)> {
    let poly = Polyline::adaptive(c, 1e-3 * extent(c))?;
    Ok((poly.points, poly.closed))
}

/// The figure's size: the diagonal of the box of 65 regular samples (the figures are
/// defined by that sample set).
fn extent<const D: usize>(c: &dyn Curve<D>) -> f64 {
    let p = Polyline::regular(c, 64).map(|p| p.points).unwrap_or_default();
    Aabb::around(&p, 0.0).diagonal().max(1e-9)
}

fn draw<const D: usize>(fig: &mut SvgFigure, c: &dyn Curve<D>, colour: &str, width: f64) -> Result<()> {
    let (pts, closed) = curve_points(c)?;
    fig.path(&pts, closed, colour, width);
    Ok(())
}

/// The seed's cubic B-spline with 8 control points and knots 0,0,0,0,1,2,3,4,5,5,5,5.
pub fn bspline_from_control_points() -> Result<Figure> {
    let pts = vec![
        p2(0.0, 0.0),
        p2(1.0, 2.0),
        p2(2.5, 2.5),
        p2(3.5, 0.5),
        p2(5.0, 0.0),
        p2(6.0, 2.0),
        p2(7.5, 2.5),
        p2(8.0, 0.5),
    ];
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0];
    let c = BSplineCurve::new(3, knots, pts.clone())?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Cubic B-spline from 8 control points");
    fig.dashed(&pts, false, POLYGON, 1.5);
    draw(&mut fig, &c, CURVE, 3.0)?;
    fig.dots(&pts, 4.0, POINTS);
    let joins: Vec<Point<2>> = (0..=5).map(|k| c.point(k as f64)).collect();
    fig.dots(&joins, 3.0, "#000000");
    Ok(Figure {
        file: "bspline_control_points.svg",
        caption:
            "Cubic B-spline c(t) = Σ N<sub>i,3</sub>(t) P<sub>i</sub> with clamped knots 0,0,0,0,1,2,3,4,5,5,5,5: \
                  control polygon dashed, control points red, the curve at the knots black."
                .into(),
        svg: fig.render()?,
    })
}

/// Least-squares B-spline of a sampled circle, as in the seeds.
pub fn least_squares_circle() -> Result<Figure> {
    let circle = Circle::new(1.0)?;
    let mut o = FitOptions::new(3, 8);
    o.knots = KnotPlacement::Uniform;
    let f = fit_curve(&circle, 100, &o)?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Least-squares B-spline of a circle (8 control points)");
    draw(&mut fig, &circle, MODEL, 6.0)?;
    fig.dashed(f.curve.control_points(), false, POLYGON, 1.5);
    draw(&mut fig, &f.curve, CURVE, 2.0)?;
    fig.dots(f.curve.control_points(), 4.0, POINTS);
    Ok(Figure {
        file: "least_squares_circle.svg",
        caption: format!(
            "Open cubic B-spline fitted by least squares (banded QR) to 100 samples of the unit circle (grey): \
             RMS error {:.2e}, max error {:.2e}.",
            f.rms_error, f.max_error
        ),
        svg: fig.render()?,
    })
}

/// Closed Lane–Riesenfeld subdivision with its initial points.
pub fn lane_riesenfeld_closed() -> Result<Figure> {
    let pts = vec![p2(0.0, 0.0), p2(3.0, -1.0), p2(5.0, 1.5), p2(3.5, 4.0), p2(1.0, 3.0), p2(-1.5, 4.5), p2(-2.0, 1.5)];
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Closed Lane–Riesenfeld subdivision, degree 3");
    fig.dashed(&pts, true, POLYGON, 1.5);
    for (k, steps) in [1usize, 2, 5].iter().enumerate() {
        let q = lane_riesenfeld(&pts, 3, *steps, true)?;
        fig.path(&q, true, PALETTE[k], if *steps == 5 { 2.5 } else { 1.2 });
    }
    fig.dots(&pts, 4.0, POINTS);
    Ok(Figure {
        file: "lane_riesenfeld.svg",
        caption:
            "Lane–Riesenfeld subdivision (double, then 3 averaging passes) of a closed polygon: 1, 2 and 5 steps. \
                  The limit is the periodic uniform cubic B-spline on the initial points (red)."
                .into(),
        svg: fig.render()?,
    })
}

/// Bézier curve with the de Casteljau construction at t = 0.4.
pub fn de_casteljau() -> Result<Figure> {
    let b = BezierCurve::new(vec![p2(0.0, 0.0), p2(1.0, 3.0), p2(4.0, 3.5), p2(6.0, 0.5)])?;
    let t = 0.4;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Cubic Bézier curve and de Casteljau at t = 0.4");
    draw(&mut fig, &b, CURVE, 3.0)?;
    for (level, pts) in b.de_casteljau_levels(t).iter().enumerate() {
        let colour = PALETTE[(level + 1) % PALETTE.len()];
        if pts.len() > 1 {
            fig.path(pts, false, colour, 1.3);
        }
        fig.dots(pts, if pts.len() == 1 { 6.0 } else { 3.5 }, colour);
    }
    Ok(Figure {
        file: "de_casteljau.svg",
        caption: "De Casteljau's algorithm: repeated linear interpolation at t = 0.4 of the control polygon, \
                  then of each new polygon, ends at the curve point c(0.4)."
            .into(),
        svg: fig.render()?,
    })
}

fn plot(fig: &mut SvgFigure, f: impl Fn(f64) -> f64, a: f64, b: f64, colour: &str) {
    let pts: Vec<Point<2>> = (0..=400).map(|i| a + (b - a) * i as f64 / 400.0).map(|x| p2(x, f(x))).collect();
    fig.path(&pts, false, colour, 2.0);
}

/// Bernstein polynomials of degree 3.
pub fn bernstein_basis() -> Result<Figure> {
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Cubic Bernstein polynomials on [0, 1]");
    for i in 0..=3 {
        plot(&mut fig, |t| bernstein(i, 3, t), 0.0, 1.0, PALETTE[i]);
    }
    fig.path(&[p2(0.0, 0.0), p2(1.0, 0.0)], false, "#000", 1.0);
    Ok(Figure {
        file: "bernstein_basis.svg",
        caption:
            "The cubic Bernstein basis C(3,i) t<sup>i</sup> (1−t)<sup>3−i</sup> on [0, 1]: non-negative, summing to 1."
                .into(),
        svg: fig.render()?,
    })
}

/// Cubic B-spline basis functions on a non-uniform knot vector with a double knot.
pub fn bspline_basis() -> Result<Figure> {
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 4.0, 4.0, 4.0, 4.0];
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Cubic B-spline basis on 0,0,0,0,1,2,2,3,4,4,4,4");
    for i in 0..8 {
        plot(&mut fig, |t| basis_function(&knots, 3, i, t), 0.0, 4.0, PALETTE[i % PALETTE.len()]);
    }
    fig.path(&[p2(0.0, 0.0), p2(4.0, 0.0)], false, "#000", 1.0);
    Ok(Figure {
        file: "bspline_basis.svg",
        caption: "Cox–de Boor basis functions N<sub>i,3</sub>: each is non-zero on 4 spans; the double knot at 2 lowers the continuity there to C¹.".into(),
        svg: fig.render()?,
    })
}

/// The ERBS B-function with its first three derivatives, each scaled to at most 1 (its
/// scale in the legend): B rises from 0 to 1 with every derivative 0 at both ends.
pub fn bfunction_derivatives() -> Result<Figure> {
    let b = splinekit::basis::BFunction::erbs_default();
    let mut fig =
        SvgFigure::new(W, H, Projection::TOP).title("ERBS B-function and its derivatives B′, B″, B‴ (scaled)");
    let at = |t: f64, k: usize| {
        let mut out = [0.0; 4];
        b.eval(t, &mut out);
        out[k]
    };
    let mut legend = Vec::new();
    for k in 0..4 {
        let peak = (0..=400).map(|i| at(i as f64 / 400.0, k).abs()).fold(0.0, f64::max).max(1e-300);
        let scale = if k == 0 { 1.0 } else { 1.0 / peak };
        plot(&mut fig, |t| at(t, k) * scale, 0.0, 1.0, PALETTE[k]);
        let name = ["B", "B′", "B″", "B‴"][k];
        fig.label(&p2(1.04, 0.9 - 0.14 * k as f64), &format!("{name} ×{scale:.3}"), PALETTE[k]);
        legend.push(format!("{name} ×{scale:.3}"));
    }
    fig.path(&[p2(0.0, 0.0), p2(1.0, 0.0)], false, "#000", 1.0);
    Ok(Figure {
        file: "bfunction_derivatives.svg",
        caption: format!(
            "The ERBS B-function (α = β = γ = 1, λ = ½) and its derivatives, each scaled to a peak of 1 ({}): every derivative vanishes at 0 and 1, so blending splines reproduce their locals' derivatives at the knots.",
            legend.join(", ")
        ),
        svg: fig.render()?,
    })
}

/// The blending basis of a knot vector: on [t_{k−1}, t_{k+1}] the weight of local k,
/// B((t − t_{k−1})/(t_k − t_{k−1})) rising, then 1 − B((t − t_k)/(t_{k+1} − t_k)) falling
/// (ERBS): each non-zero on two spans, summing to 1, flat at every knot.
pub fn blending_basis() -> Result<Figure> {
    let knots = [0.0, 1.0, 1.5, 3.0, 4.0];
    let b = splinekit::basis::BFunction::erbs_default();
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("ERBS blending basis on the knots 0, 1, 1.5, 3, 4");
    let n = knots.len();
    for k in 0..n {
        let weight = |t: f64| {
            if k > 0 && t >= knots[k - 1] && t <= knots[k] {
                b.value((t - knots[k - 1]) / (knots[k] - knots[k - 1]))
            } else if k + 1 < n && t >= knots[k] && t <= knots[k + 1] {
                1.0 - b.value((t - knots[k]) / (knots[k + 1] - knots[k]))
            } else {
                0.0
            }
        };
        plot(&mut fig, weight, knots[0], knots[n - 1], PALETTE[k % PALETTE.len()]);
    }
    fig.path(&[p2(knots[0], 0.0), p2(knots[n - 1], 0.0)], false, "#000", 1.0);
    let ticks: Vec<Point<2>> = knots.iter().map(|&t| p2(t, 0.0)).collect();
    fig.dots(&ticks, 4.0, "#000");
    Ok(Figure {
        file: "blending_basis.svg",
        caption: "The blending basis of a knot vector: local k weighs B∘w on its two spans (ERBS), so the weights sum to 1 and each is flat at every knot.".into(),
        svg: fig.render()?,
    })
}

/// The exact NURBS circle.
pub fn nurbs_circle() -> Result<Figure> {
    let c = NurbsCurve::circle(&CircleFrame {
        center: Point::<2>::zeros(),
        x_axis: p2(1.0, 0.0),
        y_axis: p2(0.0, 1.0),
        radius: 1.0,
    })?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("NURBS circle: degree 2, 9 control points");
    fig.dashed(c.control_points(), false, POLYGON, 1.5);
    draw(&mut fig, &c, CURVE, 3.0)?;
    fig.dots(c.control_points(), 4.0, POINTS);
    for (p, w) in c.control_points().iter().zip(c.weights()).skip(1).step_by(2) {
        fig.label(p, &format!("w = {w:.4}"), "#555");
    }
    let err = (0..=10000).map(|i| (c.point(i as f64 / 10000.0).norm() - 1.0).abs()).fold(0.0, f64::max);
    Ok(Figure {
        file: "nurbs_circle.svg",
        caption: format!(
            "The rational quadratic circle: corner weights √2/2 make it exact (max radius error over 10001 points: {err:.1e})."
        ),
        svg: fig.render()?,
    })
}

/// Hermite and Catmull–Rom through the same points.
pub fn hermite_and_catmull_rom() -> Result<Figure> {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 2.0), p2(1.3, 2.1), p2(3.0, 0.5), p2(5.0, 1.5), p2(5.2, -0.5)];
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Hermite and Catmull–Rom through the same points");
    let labels = ["uniform α = 0", "centripetal α = ½", "chordal α = 1"];
    for (k, alpha) in [0.0, 0.5, 1.0].iter().enumerate() {
        let c = CatmullRomCurve::new(pts.clone(), *alpha, false)?;
        draw(&mut fig, &c, PALETTE[k], 2.0)?;
        fig.label(&p2(-0.2, -0.6 - 0.35 * k as f64), labels[k], PALETTE[k]);
    }
    let tangents = vec![p2(1.0, 1.0); pts.len()];
    let h = HermiteCurve::new(pts.clone(), tangents, None)?;
    draw(&mut fig, &h, PALETTE[3], 1.2)?;
    fig.label(&p2(-0.2, -1.65), "Hermite, all tangents (1, 1)", PALETTE[3]);
    fig.dots(&pts, 4.5, "#000");
    Ok(Figure {
        file: "hermite_catmull_rom.svg",
        caption: "Catmull–Rom splines with uniform (blue), centripetal (red) and chordal (green) knots, and a \
                  piecewise cubic Hermite curve with fixed tangents (purple). Centripetal avoids the cusp and loop near the close pair."
            .into(),
        svg: fig.render()?,
    })
}

/// Chaikin, 4-point and Lane–Riesenfeld on one open polygon.
pub fn subdivision_schemes() -> Result<Figure> {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 3.0), p2(3.0, 3.5), p2(4.0, 0.5), p2(6.0, 0.0), p2(7.0, 3.0)];
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Subdivision curves after 5 steps");
    fig.dashed(&pts, false, POLYGON, 1.5);
    fig.path(&chaikin(&pts, 5, ChaikinOptions { closed: false, keep_ends: true })?, false, PALETTE[0], 2.0);
    fig.path(&four_point(&pts, 5, FourPointOptions { closed: false, tension: 1.0 / 16.0 })?, false, PALETTE[1], 2.0);
    fig.path(&lane_riesenfeld(&pts, 4, 5, false)?, false, PALETTE[2], 2.0);
    fig.dots(&pts, 4.0, "#000");
    Ok(Figure {
        file: "subdivision.svg",
        caption: "Chaikin corner cutting keeping the ends (blue), the interpolating 4-point scheme (red) and \
                  Lane–Riesenfeld of degree 4 (green) on the same polygon."
            .into(),
        svg: fig.render()?,
    })
}

/// Knot insertion and degree elevation leave the curve unchanged.
pub fn refinement() -> Result<Figure> {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 3.0), p2(3.0, 3.5), p2(4.0, 0.5), p2(6.0, 0.0), p2(7.0, 3.0)];
    let c = BSplineCurve::clamped_uniform(3, pts.clone())?;
    let refined = c.refine(&[0.1, 0.2, 0.4, 0.6, 0.8, 0.9])?;
    let elevated = c.elevate_degree(2)?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Knot insertion and degree elevation");
    fig.dashed(&pts, false, POLYGON, 1.5);
    fig.path(refined.control_points(), false, PALETTE[1], 1.0);
    fig.dots(refined.control_points(), 3.0, PALETTE[1]);
    fig.path(elevated.control_points(), false, PALETTE[2], 1.0);
    fig.dots(elevated.control_points(), 3.0, PALETTE[2]);
    draw(&mut fig, &c, CURVE, 3.0)?;
    fig.dots(&pts, 4.0, "#000");
    Ok(Figure {
        file: "refinement.svg",
        caption:
            "One cubic B-spline (blue) with three control polygons: the original (dashed), after inserting six knots \
                  (red) and after raising the degree to 5 (green). The curve is the same for all three."
                .into(),
        svg: fig.render()?,
    })
}

/// The model curves side by side.
pub fn model_curves() -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    let items: Vec<(&'static str, &str, Box<dyn Curve<3>>, Projection)> = vec![
        (
            "heart.svg",
            "Heart (16 sin³t, 13 cos t − 5 cos 2t − 2 cos 3t − cos 4t)",
            Box::new(Heart::new(1.0)?),
            Projection::TOP,
        ),
        (
            "butterfly.svg",
            "Butterfly r = e^{cos t} − 2 cos 4t − sin⁵(t/12), t ∈ [0, 24π]",
            Box::new(Butterfly::new(1.0)?),
            Projection::TOP,
        ),
        (
            "trefoil.svg",
            "Trefoil knot (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t)",
            Box::new(Trefoil::new(1.0)?),
            Projection::view(0.0, 1.35),
        ),
        (
            "lissajous.svg",
            "Lissajous (sin(3t + π/2), sin 2t, 0.5 sin 5t)",
            Box::new(Lissajous::new([1.0, 1.0, 0.5], [3.0, 2.0, 5.0], std::f64::consts::FRAC_PI_2)?),
            Projection::view(0.5, 0.4),
        ),
        ("helix.svg", "Helix, 3 turns", Box::new(Helix::new(1.0, 1.0, 3.0)?), Projection::view(0.4, 0.35)),
    ];
    for (file, caption, curve, proj) in items {
        let mut fig = SvgFigure::new(W, H, proj).title(caption);
        draw(&mut fig, curve.as_ref(), CURVE, 2.0)?;
        out.push(Figure {
            file,
            caption: format!("Model curve: {caption}; analytic derivatives of every order."),
            svg: fig.render()?,
        });
    }
    Ok(out)
}

/// The B-functions side by side, and two curves blended at 80, 50 and 20 % overlap.
pub fn blending() -> Result<Vec<Figure>> {
    use splinekit::basis::BFunction;
    use splinekit::blend::TwoCurveBlend;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("B-functions on [0, 1]");
    let kinds = [
        ("linear", BFunction::Linear),
        ("polynomial k = 1 (3t² − 2t³)", BFunction::polynomial(1)?),
        ("polynomial k = 3", BFunction::polynomial(3)?),
        ("trigonometric", BFunction::Trigonometric),
        ("rational", BFunction::Rational),
        ("ERBS", BFunction::erbs_default()),
    ];
    for (k, (name, b)) in kinds.iter().enumerate() {
        plot(&mut fig, |t| b.value(t), 0.0, 1.0, PALETTE[k % PALETTE.len()]);
        fig.label(&p2(0.0, 0.95 - 0.09 * k as f64), name, PALETTE[k % PALETTE.len()]);
    }
    let bfunctions = Figure {
        file: "bfunctions.svg",
        caption:
            "B-functions B: [0, 1] → [0, 1]. The smoother their ends, the smoother the blend: 3t² − 2t³ gives C¹, \
                  the trigonometric one C², ERBS C^∞ (all derivatives vanish at 0 and 1)."
                .into(),
        svg: fig.render()?,
    };
    // c₁(t) = (4t, ½ sin 2πt) and, for overlap x, c₂(s) = (4(s + x), 1.5 + ½ cos 2πs): over
    // the overlap c₁(t) and c₂(t − x) share their abscissa, so the blend visibly crosses.
    let wave = |f: &dyn Fn(f64) -> Point<2>| -> Result<Box<dyn Curve<2>>> {
        Ok(Box::new(CatmullRomCurve::new((0..=32).map(|k| f(k as f64 / 32.0)).collect(), 0.5, false)?))
    };
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Two curves blended at 80, 50 and 20 %");
    for (k, x) in [0.8, 0.5, 0.2].iter().enumerate() {
        let dy = -3.0 * k as f64;
        let first = || wave(&|t: f64| p2(4.0 * t, 0.5 * (TAU * t).sin()));
        let second = || wave(&|s: f64| p2(4.0 * (s + x), 1.5 + 0.5 * (TAU * s).cos()));
        let blend = TwoCurveBlend::new(first()?, second()?, *x, BFunction::polynomial(1)?)?;
        for c in [first()?, second()?] {
            let pts: Vec<Point<2>> =
                Polyline::regular(c.as_ref(), 96)?.points.iter().map(|p| p + p2(0.0, dy)).collect();
            fig.dashed(&pts, false, MODEL, 1.0);
        }
        let pts: Vec<Point<2>> = Polyline::adaptive(&blend, 1e-3)?.points.iter().map(|p| p + p2(0.0, dy)).collect();
        fig.path(&pts, false, PALETTE[k], 2.5);
        fig.label(&p2(-0.8, 0.6 + dy), &format!("x = {x}"), PALETTE[k]);
    }
    let blends = Figure {
        file: "blends.svg",
        caption: "The seeds' two-curve blend on [0, 1 + x]: the lower wave c₁ until x, then c₁ + B((t−x)/(1−x))(c₂(t−x) − c₁) \
                  with B = 3t² − 2t³ across the overlap, then the upper wave c₂ (both dashed grey), for overlaps x = 0.8, 0.5, 0.2."
            .into(),
        svg: fig.render()?,
    };
    Ok(vec![bfunctions, blends])
}
