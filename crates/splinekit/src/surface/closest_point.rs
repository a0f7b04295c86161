//! Closest point on a surface: a coarse grid search, then Newton's method on
//! (S − q)·S_u = 0, (S − q)·S_v = 0 with the 2×2 Hessian
//! [[S_u·S_u + (S−q)·S_uu, S_u·S_v + (S−q)·S_uv], [·, S_v·S_v + (S−q)·S_vv]],
//! clamped to the domain or wrapped in closed directions.

use crate::Point;
use crate::surface::Surface;

/// The parameters (u, v) and point nearest to `query`.
pub fn closest_point<const D: usize, S: Surface<D> + ?Sized>(surface: &S, query: &Point<D>) -> (f64, f64, Point<D>) {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let n = 24;
    let mut seeds: Vec<(f64, f64, f64)> = Vec::with_capacity((n + 1) * (n + 1));
    for a in 0..=n {
        for b in 0..=n {
            let (u, v) = (du.lerp(a as f64 / n as f64), dv.lerp(b as f64 / n as f64));
            seeds.push(((surface.point(u, v) - query).norm_squared(), u, v));
        }
    }
    seeds.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut best = seeds[0];
    let fix_u = |u: f64| if surface.is_closed_u() { du.wrap(u) } else { du.clamp(u) };
    let fix_v = |v: f64| if surface.is_closed_v() { dv.wrap(v) } else { dv.clamp(v) };
    for &(_, u0, v0) in seeds.iter().take(4) {
        let (mut u, mut v) = (u0, v0);
        let mut o = [Point::<D>::zeros(); 9];
        for _ in 0..50 {
            surface.eval_partials(u, v, 2, 2, &mut o);
            let r = o[0] - query;
            let (su, sv, suu, suv, svv) = (o[3], o[1], o[6], o[4], o[2]);
            let (gu, gv) = (r.dot(&su), r.dot(&sv));
            let (a, b, c) = (su.dot(&su) + r.dot(&suu), su.dot(&sv) + r.dot(&suv), sv.dot(&sv) + r.dot(&svv));
            let det = a * c - b * b;
            if !(det > 0.0 && det.is_finite() && a > 0.0) {
                break;
            }
            let (step_u, step_v) = ((c * gu - b * gv) / det, (a * gv - b * gu) / det);
            let (nu, nv) = (fix_u(u - step_u), fix_v(v - step_v));
            let moved = (nu - u).abs() + (nv - v).abs();
            u = nu;
            v = nv;
            if moved <= 1e-15 * (du.length() + dv.length()) {
                break;
            }
        }
        let d = (surface.point(u, v) - query).norm_squared();
        if d < best.0 {
            best = (d, u, v);
        }
    }
    (best.1, best.2, surface.point(best.1, best.2))
}
