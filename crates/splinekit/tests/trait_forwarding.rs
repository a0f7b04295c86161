//! `Curve` and `Surface` behind `&`, `Box`, `Arc` (and as trait objects) forward every
//! method: a kind that overrides a provided method (a fast `eval_many`, a trimmed surface's
//! loops) keeps its override behind any pointer. The sentinel kinds below override every
//! method with an answer the default could not give, so a pointer impl that fell back to
//! a default anywhere fails here.

use std::sync::Arc;

use splinekit::basis::Side;
use splinekit::curve::{Curve, FrenetFrame};
use splinekit::query::Aabb;
use splinekit::surface::{Curvatures, FundamentalForms, Surface, TrimLoops};
use splinekit::{Interval, Point};

fn p2(x: f64) -> Point<2> {
    Point::<2>::new(x, -x)
}

fn p3(x: f64) -> Point<3> {
    Point::<3>::new(x, -x, 2.0 * x)
}

/// A curve that answers every method with its own number.
struct SentinelCurve;

impl Curve<2> for SentinelCurve {
    fn domain(&self) -> Interval {
        Interval::new(-1.0, 3.0)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn eval_side(&self, _t: f64, side: Side, out: &mut [Point<2>]) {
        out.fill(p2(if side == Side::Left { 1.0 } else { 2.0 }));
    }
    fn eval(&self, _t: f64, out: &mut [Point<2>]) {
        out.fill(p2(3.0));
    }
    fn eval_many(&self, _params: &[f64], _order: usize, out: &mut [Point<2>]) {
        out.fill(p2(4.0));
    }
    fn breakpoints(&self) -> Vec<f64> {
        vec![-1.0, 0.5, 3.0]
    }
    fn point(&self, _t: f64) -> Point<2> {
        p2(5.0)
    }
    fn derivative(&self, _t: f64, order: usize) -> Point<2> {
        p2(6.0 + order as f64)
    }
    fn tangent(&self, _t: f64) -> Point<2> {
        p2(8.0)
    }
    fn curvature(&self, _t: f64) -> f64 {
        9.0
    }
    fn frame(&self, _t: f64) -> Option<FrenetFrame<2>> {
        Some(FrenetFrame { tangent: p2(10.0), normal: None, binormal: None, curvature: 10.0 })
    }
    fn enclosing_box(&self) -> Option<Aabb<2>> {
        Some(Aabb { min: p2(13.0), max: p2(14.0) })
    }
}

/// Every method of `c` gives the sentinel's answer.
fn check_curve(name: &str, c: &impl Curve<2>) {
    assert_eq!(c.domain(), Interval::new(-1.0, 3.0), "{name}: domain");
    assert!(c.is_closed(), "{name}: is_closed");
    let mut out = [Point::<2>::zeros(); 2];
    c.eval_side(0.0, Side::Left, &mut out);
    assert_eq!(out, [p2(1.0); 2], "{name}: eval_side");
    c.eval(0.0, &mut out);
    assert_eq!(out, [p2(3.0); 2], "{name}: eval");
    c.eval_many(&[0.0, 1.0], 0, &mut out);
    assert_eq!(out, [p2(4.0); 2], "{name}: eval_many");
    assert_eq!(c.breakpoints(), vec![-1.0, 0.5, 3.0], "{name}: breakpoints");
    assert_eq!(c.point(0.0), p2(5.0), "{name}: point");
    assert_eq!(c.derivative(0.0, 1), p2(7.0), "{name}: derivative");
    assert_eq!(c.tangent(0.0), p2(8.0), "{name}: tangent");
    assert_eq!(c.curvature(0.0), 9.0, "{name}: curvature");
    assert_eq!(c.frame(0.0).map(|f| f.curvature), Some(10.0), "{name}: frame");
    assert_eq!(c.enclosing_box(), Some(Aabb { min: p2(13.0), max: p2(14.0) }), "{name}: enclosing_box");
}

#[test]
fn curves_behind_every_pointer_forward_every_method() {
    check_curve("value", &SentinelCurve);
    check_curve("&C", &&SentinelCurve);
    check_curve("Box<C>", &Box::new(SentinelCurve));
    check_curve("Arc<C>", &Arc::new(SentinelCurve));
    let boxed: Box<dyn Curve<2>> = Box::new(SentinelCurve);
    check_curve("Box<dyn Curve>", &boxed);
    let shared: Arc<dyn Curve<2>> = Arc::new(SentinelCurve);
    check_curve("Arc<dyn Curve>", &shared);
    check_curve("&dyn Curve", &(&SentinelCurve as &dyn Curve<2>));
    check_curve("Arc<Box<dyn Curve>>", &Arc::new(boxed));
}

/// A surface that answers every method with its own number.
struct SentinelSurface {
    outer: Vec<Point<2>>,
}

impl Surface<3> for SentinelSurface {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, 2.0)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(-2.0, 0.0)
    }
    fn is_closed_u(&self) -> bool {
        true
    }
    fn is_closed_v(&self) -> bool {
        true
    }
    fn eval_partials(&self, _u: f64, _v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        out[..(du + 1) * (dv + 1)].fill(p3(1.0));
    }
    fn eval_grid(&self, _us: &[f64], _vs: &[f64], _du: usize, _dv: usize, out: &mut [Point<3>]) {
        out.fill(p3(2.0));
    }
    fn eval_grid_with_normals(&self, _us: &[f64], _vs: &[f64], points: &mut [Point<3>], normals: &mut [Point<3>]) {
        points.fill(p3(3.0));
        normals.fill(p3(4.0));
    }
    fn trim_contains(&self, _u: f64, _v: f64) -> Option<bool> {
        Some(false)
    }
    fn trim_loops(&self) -> Option<TrimLoops<'_>> {
        Some(TrimLoops { outer: Some(&self.outer), holes: vec![] })
    }
    fn point(&self, _u: f64, _v: f64) -> Point<3> {
        p3(5.0)
    }
    fn partial(&self, _u: f64, _v: f64, i: usize, j: usize) -> Point<3> {
        p3(6.0 + (i + 2 * j) as f64)
    }
    fn normal(&self, _u: f64, _v: f64) -> Option<Point<3>> {
        Some(p3(10.0))
    }
    fn fundamental_forms(&self, _u: f64, _v: f64) -> Option<FundamentalForms> {
        Some(FundamentalForms { e: 11.0, f: 0.0, g: 0.0, l: 0.0, m: 0.0, n: 0.0 })
    }
    fn curvatures(&self, _u: f64, _v: f64) -> Option<Curvatures> {
        Some(Curvatures { gaussian: 12.0, mean: 0.0, principal: (0.0, 0.0) })
    }
    fn breakpoints_u(&self) -> Vec<f64> {
        vec![0.0, 0.5, 2.0]
    }
    fn breakpoints_v(&self) -> Vec<f64> {
        vec![-2.0, -0.5, 0.0]
    }
    fn enclosing_box(&self) -> Option<Aabb<3>> {
        Some(Aabb { min: p3(15.0), max: p3(16.0) })
    }
}

/// Every method of `s` gives the sentinel's answer.
fn check_surface(name: &str, s: &impl Surface<3>) {
    check_geometry(name, s);
    assert_eq!(s.trim_contains(0.5, 0.5), Some(false), "{name}: trim_contains");
    let loops = s.trim_loops().expect("trim_loops forwarded");
    assert_eq!(loops.outer.map(|o| o.len()), Some(3), "{name}: trim_loops");
}

/// Every method of `s` but the trim gives the sentinel's answer.
fn check_geometry(name: &str, s: &impl Surface<3>) {
    assert_eq!((s.domain_u(), s.domain_v()), (Interval::new(0.0, 2.0), Interval::new(-2.0, 0.0)), "{name}: domains");
    assert!(s.is_closed_u() && s.is_closed_v(), "{name}: is_closed_u/v");
    let mut out = [Point::<3>::zeros(); 4];
    s.eval_partials(0.0, 0.0, 1, 1, &mut out);
    assert_eq!(out, [p3(1.0); 4], "{name}: eval_partials");
    s.eval_grid(&[0.0, 1.0], &[0.0, 1.0], 0, 0, &mut out);
    assert_eq!(out, [p3(2.0); 4], "{name}: eval_grid");
    let (mut points, mut normals) = ([Point::<3>::zeros(); 1], [Point::<3>::zeros(); 1]);
    s.eval_grid_with_normals(&[0.0], &[0.0], &mut points, &mut normals);
    assert_eq!((points[0], normals[0]), (p3(3.0), p3(4.0)), "{name}: eval_grid_with_normals");
    assert_eq!(s.point(0.0, 0.0), p3(5.0), "{name}: point");
    assert_eq!(s.partial(0.0, 0.0, 1, 1), p3(9.0), "{name}: partial");
    assert_eq!(s.normal(0.0, 0.0), Some(p3(10.0)), "{name}: normal");
    assert_eq!(s.fundamental_forms(0.0, 0.0).map(|f| f.e), Some(11.0), "{name}: fundamental_forms");
    assert_eq!(s.curvatures(0.0, 0.0).map(|c| c.gaussian), Some(12.0), "{name}: curvatures");
    assert_eq!(s.breakpoints_u(), vec![0.0, 0.5, 2.0], "{name}: breakpoints_u");
    assert_eq!(s.breakpoints_v(), vec![-2.0, -0.5, 0.0], "{name}: breakpoints_v");
    assert_eq!(s.enclosing_box(), Some(Aabb { min: p3(15.0), max: p3(16.0) }), "{name}: enclosing_box");
}

#[test]
fn surfaces_behind_every_pointer_forward_every_method() {
    let sentinel = || SentinelSurface { outer: vec![Point::<2>::new(0.0, 0.0); 3] };
    check_surface("value", &sentinel());
    check_surface("&S", &&sentinel());
    check_surface("Box<S>", &Box::new(sentinel()));
    check_surface("Arc<S>", &Arc::new(sentinel()));
    let boxed: Box<dyn Surface<3>> = Box::new(sentinel());
    check_surface("Box<dyn Surface>", &boxed);
    let shared: Arc<dyn Surface<3>> = Arc::new(sentinel());
    check_surface("Arc<dyn Surface>", &shared);
    check_surface("Arc<Box<dyn Surface>>", &Arc::new(boxed));
}

/// A trimmed surface answers with its base for every method but the trim: the base's grids,
/// normals, curvatures, breakpoints and box (which holds the trimmed part), its own
/// `trim_contains` and `trim_loops`.
#[test]
fn a_trimmed_surface_forwards_all_but_its_trim_to_its_base() {
    use splinekit::surface::TrimmedSurface;
    let base = Box::new(SentinelSurface { outer: vec![Point::<2>::new(0.0, 0.0); 3] });
    let s = TrimmedSurface::new(base, None, &[]).unwrap();
    check_geometry("TrimmedSurface", &s);
    // The trim is its own: no outer loop and no hole keep the whole domain, where the base
    // would say "outside" and give its own triangle.
    assert_eq!(s.trim_contains(0.5, -0.5), Some(true), "trim_contains");
    let loops = s.trim_loops().expect("a trimmed surface has loops");
    assert!(loops.outer.is_none() && loops.holes.is_empty(), "trim_loops");
    assert!(s.subdivision().is_none(), "subdivision");
}
