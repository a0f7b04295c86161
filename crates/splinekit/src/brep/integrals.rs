//! Areas of B-rep faces and volumes of closed shells, integrated over the exact trimmed
//! faces (no mesh).
//!
//! Over a face's region R of its (u, v), with S_u × S_v the surface's normal vector,
//!
//! * area = ∬_R |S_u × S_v| du dv;
//! * volume (divergence theorem, div x = 3) = ⅓ Σ_faces ∬_R S · (±S_u × S_v) du dv, the sign
//!   that of the face's outward normal.
//!
//! Each double integral ∬_R h du dv becomes a line integral by Green's theorem,
//! ∮_∂R H(u, v) dv with H(u, v) = ∫_{u₀}^{u} h(s, v) ds: the loops' pcurves are integrated
//! by adaptive Gauss–Legendre rules (panels at their breakpoints, bisected until a panel's
//! halves agree with it, [`RELATIVE`]), and H at every node by the same rule along u from the
//! face's lowest u (panels at the surface's breakpoints). The loops run counter-clockwise in (u, v) about the face
//! when its normal is S_u × S_v and clockwise on reversed faces, so ∮ H dv over the loops
//! as they run is the signed integral: the volume's sum takes it as it comes, the area its
//! magnitude. Both integrands are smooth on each panel, so the rules converge
//! exponentially; the result is as exact as the pcurves (a computed pcurve is within its
//! tolerance of the edge).

use crate::brep::{Brep, BrepFace};
use crate::curve::{Curve, Interval};
use crate::quadrature::GaussLegendre;
use crate::surface::Surface;
use crate::{Point, Result};

/// Samples of each pcurve for the face's lowest u, where the inner integrals start.
pub const LOWEST_U_SAMPLES: usize = 8;
/// Nodes of the Gauss–Legendre rule on each panel.
pub const NODES: usize = 12;
/// A panel is bisected until its halves agree with it to this fraction of ∫|integrand| (or,
/// along the loops, of the face's whole integral)
/// ([`GaussLegendre::integrate_adaptive`]). Both integrands are smooth on each panel, so the
/// halves are far more accurate than their difference from the whole (by about 2^(2·NODES));
/// a bound near the rounding of the sums would never be met and bisect to [`MAX_DEPTH`].
pub const RELATIVE: f64 = 1e-12;
/// Bisections of a panel at most (2¹² pieces of a span).
pub const MAX_DEPTH: u32 = 12;

/// A face's surface evaluated past the domain of its closed directions (cuts across a
/// seam run beyond it).
fn partials(s: &dyn Surface<3>, u: f64, v: f64, out: &mut [Point<3>; 4]) {
    let wrap = |x: f64, d: Interval, closed: bool| {
        if closed && x.is_finite() && (x < d.start || x > d.end) {
            d.start + (x - d.start).rem_euclid(d.length())
        } else {
            x
        }
    };
    let (u, v) = (wrap(u, s.domain_u(), s.is_closed_u()), wrap(v, s.domain_v(), s.is_closed_v()));
    s.eval_partials(u, v, 1, 1, out);
}

/// ∮ H dv over the face's loops for the integrand `h(S, S_u × S_v)`.
fn boundary_integral(face: &BrepFace, h: &dyn Fn(&Point<3>, &Point<3>) -> f64) -> f64 {
    let rule = GaussLegendre::new(NODES);
    let surface = face.surface.as_ref();
    let u0 = face
        .loops
        .iter()
        .flatten()
        .flat_map(|us| {
            let d = us.pcurve.domain();
            (0..=LOWEST_U_SAMPLES)
                .map(move |k| us.pcurve.point(d.start + d.length() * k as f64 / LOWEST_U_SAMPLES as f64)[0])
        })
        .fold(f64::INFINITY, f64::min);
    let knots = [
        (surface.breakpoints_u(), surface.domain_u(), surface.is_closed_u()),
        (surface.breakpoints_v(), surface.domain_v(), surface.is_closed_v()),
    ];
    let mut o = [Point::<3>::zeros(); 4];
    let mut inner = |u: f64, v: f64| -> f64 {
        if u == u0 {
            return 0.0;
        }
        let (a, b) = (u0.min(u), u0.max(u));
        let mut cuts: Vec<f64> = vec![a];
        let (breaks, domain, closed) = &knots[0];
        cuts.extend(lines_within(breaks, *domain, *closed, a, b));
        cuts.push(b);
        let mut sum = 0.0;
        for w in cuts.windows(2) {
            sum += rule.integrate_adaptive(w[0], w[1], RELATIVE, 0.0, MAX_DEPTH, |s| {
                partials(surface, s, v, &mut o);
                h(&o[0], &o[2].cross(&o[1]))
            });
        }
        if u < u0 { -sum } else { sum }
    };
    // The face's integral is of the size of max |H| times the loops' extent in v; panels
    // whose share of it is settled below RELATIVE of that are not bisected further (a
    // pcurve that runs nearly along u, v′ ≈ 0, would otherwise chase its own rounding).
    let (mut h_max, mut v_lo, mut v_hi) = (0.0_f64, f64::INFINITY, f64::NEG_INFINITY);
    for us in face.loops.iter().flatten() {
        let d = us.pcurve.domain();
        for k in 0..=LOWEST_U_SAMPLES {
            let p = us.pcurve.point(d.start + d.length() * k as f64 / LOWEST_U_SAMPLES as f64);
            h_max = h_max.max(inner(p[0], p[1]).abs());
            (v_lo, v_hi) = (v_lo.min(p[1]), v_hi.max(p[1]));
        }
    }
    let floor = RELATIVE * h_max * (v_hi - v_lo);
    let floor = if floor.is_finite() { floor } else { 0.0 };
    let mut total = 0.0;
    let mut c = [Point::<2>::zeros(); 2];
    for us in face.loops.iter().flatten() {
        let d = us.pcurve.domain();
        let mut spans: Vec<f64> = us.pcurve.breakpoints().into_iter().filter(|&t| t >= d.start && t <= d.end).collect();
        if spans.first() != Some(&d.start) {
            spans.insert(0, d.start);
        }
        if spans.last() != Some(&d.end) {
            spans.push(d.end);
        }
        // H is only as smooth as the surface across its knot lines: the pcurve's crossings
        // of them end panels too.
        let crossings: Vec<f64> =
            spans.windows(2).flat_map(|w| knot_line_crossings(us.pcurve.as_ref(), w[0], w[1], &knots)).collect();
        spans.extend(crossings);
        spans.sort_by(f64::total_cmp);
        spans.dedup();
        for w in spans.windows(2) {
            total += rule.integrate_adaptive(w[0], w[1], RELATIVE, floor, MAX_DEPTH, |t| {
                us.pcurve.eval(t, &mut c);
                if c[1][1] == 0.0 { 0.0 } else { inner(c[0][0], c[0][1]) * c[1][1] }
            });
        }
    }
    total
}

/// The knot lines `breaks` of one direction strictly inside (lo, hi), repeated every period
/// where the direction is closed, in increasing order.
fn lines_within(breaks: &[f64], domain: Interval, closed: bool, lo: f64, hi: f64) -> Vec<f64> {
    let period = domain.length();
    if !closed || period.is_nan() || period <= 0.0 || !lo.is_finite() || !hi.is_finite() {
        return breaks.iter().copied().filter(|&t| t > lo && t < hi).collect();
    }
    let first = ((lo - domain.end) / period).floor() as i64;
    let last = ((hi - domain.start) / period).ceil() as i64;
    let mut out: Vec<f64> = (first..=last)
        .flat_map(|k| breaks.iter().map(move |&t| t + k as f64 * period))
        .filter(|&t| t > lo && t < hi)
        .collect();
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}

/// Samples of a pcurve span searched for crossings of knot lines.
const CROSSING_SAMPLES: usize = 16;

/// The parameters in (a, b) where the pcurve crosses a knot line of the surface (`knots`:
/// the breakpoints, domain and closedness of u, then v), each found by bisection between
/// samples on either side of it; a line touched without a crossing between two samples is
/// not found, and only costs the adaptive rule some bisections there.
fn knot_line_crossings(pcurve: &dyn Curve<2>, a: f64, b: f64, knots: &[(Vec<f64>, Interval, bool); 2]) -> Vec<f64> {
    let at = |k: usize| a + (b - a) * k as f64 / CROSSING_SAMPLES as f64;
    let samples: Vec<(f64, Point<2>)> = (0..=CROSSING_SAMPLES).map(|k| (at(k), pcurve.point(at(k)))).collect();
    let mut found = Vec::new();
    for (i, (breaks, domain, closed)) in knots.iter().enumerate() {
        if breaks.is_empty() {
            continue;
        }
        let (lo, hi) =
            samples.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), (_, p)| (l.min(p[i]), h.max(p[i])));
        for line in lines_within(breaks, *domain, *closed, lo - f64::EPSILON * lo.abs(), hi + f64::EPSILON * hi.abs()) {
            for w in samples.windows(2) {
                let (fa, fb) = (w[0].1[i] - line, w[1].1[i] - line);
                if fa == 0.0 && w[0].0 > a {
                    found.push(w[0].0);
                } else if fa * fb < 0.0 {
                    let (mut s, mut t, mut fs) = (w[0].0, w[1].0, fa);
                    while t - s > f64::EPSILON * (s.abs() + t.abs()) {
                        let m = 0.5 * (s + t);
                        if m <= s || m >= t {
                            break;
                        }
                        let fm = pcurve.point(m)[i] - line;
                        if (fm < 0.0) == (fs < 0.0) {
                            (s, fs) = (m, fm);
                        } else {
                            t = m;
                        }
                    }
                    found.push(0.5 * (s + t));
                }
            }
        }
    }
    found.retain(|&t| t > a && t < b);
    found
}

/// The area of face `k`, over its trimmed region.
pub fn face_area(brep: &Brep, k: usize) -> f64 {
    boundary_integral(&brep.faces()[k], &|_, n| n.norm()).abs()
}

/// The total area of the faces.
pub fn area(brep: &Brep) -> f64 {
    (0..brep.faces().len()).map(|k| face_area(brep, k)).sum()
}

/// The volume the faces of `shells` enclose: ⅓ Σ ∬ S·n dA over their faces (see the
/// module); meaningful for closed shells, which is checked.
pub fn volume(brep: &Brep, shells: &[usize]) -> Result<f64> {
    let mut sum = 0.0;
    for &s in shells {
        let shell = brep.shells().get(s).ok_or_else(|| crate::Error::invalid("shells", format!("no shell {s}")))?;
        if !shell.closed {
            return Err(crate::Error::invalid(format!("shells[{s}]"), "an open shell encloses no volume"));
        }
        for &f in &shell.faces {
            sum += boundary_integral(&brep.faces()[f], &|p, n| p.dot(n));
        }
    }
    Ok(sum / 3.0)
}
