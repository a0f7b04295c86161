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
//! by composite Gauss–Legendre rules (panels at their breakpoints, each split in
//! [`PANELS`]), and H at every node by the same rule along u from the face's lowest u (panels
//! at the surface's breakpoints). The loops run counter-clockwise in (u, v) about the face
//! when its normal is S_u × S_v and clockwise on reversed faces, so ∮ H dv over the loops
//! as they run is the signed integral: the volume's sum takes it as it comes, the area its
//! magnitude. Both integrands are smooth on each panel, so the rules converge
//! exponentially; the result is as exact as the pcurves (a computed pcurve is within its
//! tolerance of the edge).

use crate::brep::{Brep, BrepFace};
use crate::curve::Interval;
use crate::quadrature::GaussLegendre;
use crate::surface::Surface;
use crate::{Point, Result};

/// Panels each pcurve span and each inner range is divided into.
pub const PANELS: usize = 8;
/// Nodes of the Gauss–Legendre rule on each panel.
pub const NODES: usize = 12;

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
            (0..=PANELS).map(move |k| us.pcurve.point(d.start + d.length() * k as f64 / PANELS as f64)[0])
        })
        .fold(f64::INFINITY, f64::min);
    let breaks_u = surface.breakpoints_u();
    let mut o = [Point::<3>::zeros(); 4];
    let mut inner = |u: f64, v: f64| -> f64 {
        if u == u0 {
            return 0.0;
        }
        let (a, b) = (u0.min(u), u0.max(u));
        let mut cuts: Vec<f64> = vec![a];
        cuts.extend(breaks_u.iter().copied().filter(|&t| t > a && t < b));
        cuts.push(b);
        let mut sum = 0.0;
        for w in cuts.windows(2) {
            for k in 0..PANELS {
                let (p, q) = (
                    w[0] + (w[1] - w[0]) * k as f64 / PANELS as f64,
                    w[0] + (w[1] - w[0]) * (k + 1) as f64 / PANELS as f64,
                );
                sum += rule.integrate(p, q, |s| {
                    partials(surface, s, v, &mut o);
                    h(&o[0], &o[2].cross(&o[1]))
                });
            }
        }
        if u < u0 { -sum } else { sum }
    };
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
        for w in spans.windows(2) {
            for k in 0..PANELS {
                let (p, q) = (
                    w[0] + (w[1] - w[0]) * k as f64 / PANELS as f64,
                    w[0] + (w[1] - w[0]) * (k + 1) as f64 / PANELS as f64,
                );
                total += rule.integrate(p, q, |t| {
                    us.pcurve.eval(t, &mut c);
                    if c[1][1] == 0.0 { 0.0 } else { inner(c[0][0], c[0][1]) * c[1][1] }
                });
            }
        }
    }
    total
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
