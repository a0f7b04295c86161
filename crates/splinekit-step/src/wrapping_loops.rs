//! Face bounds that wrap around a periodic surface, closed in the parameter plane.
//!
//! ISO 10303-42 bounds a face by loops of edges in 3-D; it does not ask for seam edges. A
//! cylinder's band between two circles is one face with two loops, each a circle, and a
//! cone's tip or a sphere's cap is one face with one circle (the apex or pole is not an
//! edge). In the surface's (u, v) each such loop runs once around the period, from (a, v₀)
//! to (a ± P, v₀): it is closed in 3-D but not in the plane, and no region of the plane is
//! inside it. OpenCASCADE's files add a seam edge and never show this; most other CAD
//! systems' files do.
//!
//! Before the pieces of a loop are compared, each is moved by whole periods to start where
//! the one before it ends (pcurves computed from 3-D edges each start in [0, P)). A loop
//! whose end is its start moved by ±P along one periodic parameter (and by whole periods,
//! or not at all, along the other) wraps around it. Then:
//!
//! * **Two loops wrapping in opposite senses** (a band) become one: A from (a, v₀) to
//!   (a + P, v₀), a segment to the start of B moved by whole periods into (a, a + P], B to
//!   its end (one period back), and the same segment one period back to A's start. The
//!   region inside is a fundamental domain of the band, cut along a slanted line; a
//!   periodic surface evaluates it the same for any u.
//! * **One loop wrapping** (a cap or tip) is closed through the surface's pole or apex on
//!   the side where the face lies: up along u = a + P to the pole's line v = v_p, back
//!   along it to u = a, and down. The face lies on the left of its outer loop in the
//!   surface's (u, v) when the face's sense agrees with the surface's normal (on the right
//!   otherwise), so a loop running towards +u has the face at larger v. The pole's line
//!   is v = ±π/2 on a sphere, the apex height −r / tan α on a cone, and the end of a
//!   revolved profile that lies on the axis.
//!
//! Loops that use seam edges (OpenCASCADE's) are left to the seam logic of
//! `documents::import`.

use splinekit::Point;
use std::f64::consts::FRAC_PI_2;

use crate::evaluate::{CurveEval, SurfaceEval};
use crate::geometry::{Curve, Surface};
use crate::import::{Face, Role};

/// Relative gap (to the period) below which a piece's start is its predecessor's end moved
/// by whole periods.
const PERIOD_TOLERANCE: f64 = 1e-7;

/// A 2-D curve of a loop at its parameter t.
fn at(c: &Curve, t: f64) -> Option<Point<2>> {
    let p = CurveEval::new(c).ok()?.point(t);
    Some(Point::<2>::new(p[0], p[1]))
}

/// The start and end of a loop piece (a trimmed curve).
fn ends(c: &Curve) -> Option<(Point<2>, Point<2>)> {
    match c {
        Curve::Trimmed { basis, start, end } => Some((at(basis, *start)?, at(basis, *end)?)),
        _ => None,
    }
}

/// The curve moved by `d` in the parameter plane.
fn shifted(c: &Curve, d: Point<2>) -> Curve {
    match c {
        Curve::Line { origin, direction } => {
            Curve::Line { origin: vec![origin[0] + d[0], origin[1] + d[1]], direction: direction.clone() }
        }
        Curve::Circle { axes, radius } => {
            let mut a = *axes;
            a.origin += Point::<3>::new(d[0], d[1], 0.0);
            Curve::Circle { axes: a, radius: *radius }
        }
        Curve::Ellipse { axes, a, b } => {
            let mut placed = *axes;
            placed.origin += Point::<3>::new(d[0], d[1], 0.0);
            Curve::Ellipse { axes: placed, a: *a, b: *b }
        }
        Curve::Spline(s) => {
            let mut s = s.clone();
            s.points.iter_mut().for_each(|p| {
                p[0] += d[0];
                p[1] += d[1];
            });
            Curve::Spline(s)
        }
        Curve::Trimmed { basis, start, end } => {
            Curve::Trimmed { basis: Box::new(shifted(basis, d)), start: *start, end: *end }
        }
    }
}

/// The segment from `a` to `b` as a trimmed line over [0, 1].
fn segment(a: Point<2>, b: Point<2>) -> Curve {
    let d = b - a;
    Curve::Trimmed {
        basis: Box::new(Curve::Line { origin: vec![a[0], a[1]], direction: vec![d[0], d[1]] }),
        start: 0.0,
        end: 1.0,
    }
}

/// The whole number of periods nearest to `x / period`, if `x` is within the tolerance of
/// it (0 for a parameter that is not periodic, when `x` is small).
fn turns(x: f64, period: Option<f64>, scale: f64) -> Option<f64> {
    match period {
        Some(p) => {
            let k = (x / p).round();
            ((x - k * p).abs() <= PERIOD_TOLERANCE * p).then_some(k)
        }
        None => (x.abs() <= PERIOD_TOLERANCE * scale).then_some(0.0),
    }
}

/// How a loop wraps: whole periods along u and v from its start to its end.
fn wraps(pieces: &[Curve], periods: (Option<f64>, Option<f64>)) -> Option<(f64, f64)> {
    let (first, _) = ends(pieces.first()?)?;
    let (_, last) = ends(pieces.last()?)?;
    let net = last - first;
    let scale = 1.0 + first.amax();
    Some((turns(net[0], periods.0, scale)?, turns(net[1], periods.1, scale)?))
}

/// Each piece after the first moved by whole periods to start where the one before it ends.
fn align(pieces: &mut [Curve], periods: (Option<f64>, Option<f64>)) {
    for k in 1..pieces.len() {
        let (Some((_, end)), Some((start, _))) = (ends(&pieces[k - 1]), ends(&pieces[k])) else { return };
        let gap = start - end;
        let shift = |x: f64, p: Option<f64>| p.and_then(|p| turns(x, Some(p), 1.0).map(|k| -k * p)).unwrap_or(0.0);
        let d = Point::<2>::new(shift(gap[0], periods.0), shift(gap[1], periods.1));
        if d != Point::<2>::zeros() {
            pieces[k] = shifted(&pieces[k], d);
        }
    }
}

/// The parameter v of the surface's pole or apex line above (`upper`) or below the face,
/// where it has one.
fn pole(surface: &SurfaceEval, step: &Surface, upper: bool) -> Option<f64> {
    match step {
        Surface::Sphere { .. } => Some(if upper { FRAC_PI_2 } else { -FRAC_PI_2 }),
        Surface::Cone { radius, semi_angle, .. } => Some(-radius / semi_angle.tan()),
        Surface::Revolution { axis_origin, axis, .. } => {
            use splinekit::surface::Surface as _;
            let d = surface.domain_v();
            let v = if upper { d.end } else { d.start };
            let p = surface.point(0.0, v);
            let w = p - axis_origin;
            let off_axis = (w - axis * w.dot(axis) / axis.norm_squared()).norm();
            (v.is_finite() && off_axis <= 1e-9 * (1.0 + w.norm())).then_some(v)
        }
        Surface::Trimmed { basis, .. } => pole(surface, basis, upper),
        _ => None,
    }
}

/// Closes the face's loops that wrap around its surface (see the module). Faces whose
/// loops use seam edges, and loops that do not wrap, are left as they are.
pub fn close_wrapping_loops(face: &mut Face) {
    let same_sense = face.same_sense;
    let Ok(surface) = SurfaceEval::new(&face.surface) else { return };
    let periods = surface.periods();
    if periods == (None, None) || face.seam_twins.iter().flatten().any(Option::is_some) {
        return;
    }
    for pieces in &mut face.loops {
        align(pieces, periods);
    }
    let wrapping: Vec<(usize, (f64, f64))> = face
        .loops
        .iter()
        .enumerate()
        .filter_map(|(i, l)| wraps(l, periods).filter(|w| *w != (0.0, 0.0)).map(|w| (i, w)))
        .collect();
    match wrapping.as_slice() {
        [(a, wa), (b, wb)] if wa.0 == -wb.0 && wa.1 == -wb.1 => {
            let (a, b) = if wa.0 + wa.1 > 0.0 { (*a, *b) } else { (*b, *a) };
            let Some(band) = band(&face.loops[a], &face.loops[b], periods) else { return };
            // A, the cut up, B, the cut down (the same cut one period back).
            let (na, nb) = (face.loops[a].len(), face.loops[b].len());
            let (up, down) = (na, na + 1 + nb);
            let mut roles = face.roles[a].clone();
            roles.push(Role::Cut { twin: down });
            roles.extend(face.roles[b].iter().copied());
            roles.push(Role::Cut { twin: up });
            face.roles[a] = roles;
            face.roles.remove(b);
            face.seam_twins[a] = vec![None; band.len()];
            face.loops[a] = band;
            face.loops.remove(b);
            face.seam_twins.remove(b);
            face.outer = Some(if a > b { a - 1 } else { a });
        }
        [(a, (wu, 0.0))] => {
            // Along +u with the face on the left (or −u with it on the right): the face lies
            // at larger v.
            let upper = (*wu > 0.0) == same_sense;
            let Some(v_pole) = pole(&surface, &face.surface, upper) else { return };
            let pieces = &mut face.loops[*a];
            let (Some((start, _)), Some((_, end))) = (ends(&pieces[0]), ends(&pieces[pieces.len() - 1])) else {
                return;
            };
            let (top_end, top_start) = (Point::<2>::new(end[0], v_pole), Point::<2>::new(start[0], v_pole));
            let n = pieces.len();
            pieces.extend([segment(end, top_end), segment(top_end, top_start), segment(top_start, start)]);
            // Up along u = a + P and down along u = a: one cut, one period apart.
            face.roles[*a].extend([Role::Cut { twin: n + 2 }, Role::Pole, Role::Cut { twin: n }]);
            face.seam_twins[*a] = vec![None; pieces.len()];
            face.outer = Some(*a);
        }
        _ => {}
    }
}

/// Two loops wrapping in opposite senses as one loop around the band between them (see
/// the module): `a` runs forward one period, `b` back.
fn band(a: &[Curve], b: &[Curve], periods: (Option<f64>, Option<f64>)) -> Option<Vec<Curve>> {
    let (a_start, _) = ends(a.first()?)?;
    let (_, a_end) = ends(a.last()?)?;
    let (b_start, _) = ends(b.first()?)?;
    // B's start moved by whole periods into (a_start, a_end] along each wrapping parameter.
    let mut d = Point::<2>::zeros();
    for k in 0..2 {
        let p = [periods.0, periods.1][k];
        if let Some(p) = p
            && (a_end[k] - a_start[k]).abs() > 0.5 * p
        {
            let lo = a_start[k].min(a_end[k]);
            d[k] = ((lo + p - b_start[k]) / p).floor() * p;
        }
    }
    let b: Vec<Curve> = b.iter().map(|c| shifted(c, d)).collect();
    let (b_start, _) = ends(b.first()?)?;
    let (_, b_end) = ends(b.last()?)?;
    let mut out = a.to_vec();
    out.push(segment(a_end, b_start));
    out.extend(b);
    out.push(segment(b_end, a_start));
    Some(out)
}
