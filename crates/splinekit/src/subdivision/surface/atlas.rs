//! The limit surface of a subdivision surface as one parametric [`Surface`]: an atlas of
//! unit charts laid side by side along u.
//!
//! Chart c covers u ∈ [c, c + 1], v ∈ [0, 1]; at (c + s, t) the surface is the exact limit
//! ([`SubdivisionSurface::evaluate`]) at local (s, t) of the chart's face:
//!
//! - Catmull–Clark and bilinear: a quad is one chart, (s, t) its own (u, v) (c₀ at (0, 0),
//!   c₁ at (1, 0), c₂ at (1, 1)); an n-gon (n ≠ 4) is n charts, one per corner in order,
//!   each the quad that corner becomes after one step
//!   ([`SubdivisionSurface::evaluate_subface`]).
//! - Loop: a triangle is one chart, the unit square collapsed onto the triangle by
//!   (u, v) = (s(1 − t), t), so t = 1 is the corner c₂. By the chain rule
//!   P_s = (1 − t)L_u, P_t = L_v − s L_u, P_ss = (1 − t)²L_uu,
//!   P_st = (1 − t)(L_uv − s L_uu) − L_u, P_tt = L_vv − 2s L_uv + s²L_uu.
//!
//! So for a cage of quads chart c is face c, and (c + u, v) is `--at c,u,v`. Partials of
//! total order up to 2 are exact; higher ones, and the partials at an extraordinary vertex
//! (where they do not exist), are NaN. The normal is the limit normal everywhere, the
//! extraordinary vertices included.

use super::{Scheme, SubdivisionSurface};
use crate::surface::Surface;
use crate::{Error, Interval, Point, Result};

/// One chart: a face, and for an n-gon of Catmull–Clark or bilinear the corner whose quad it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Chart {
    /// The cage face.
    pub face: u32,
    /// The corner of an n-gon (n ≠ 4), `None` for a quad or a Loop triangle.
    pub corner: Option<u32>,
}

/// The limit surface over its atlas of charts (see the module's documentation).
#[derive(Debug, Clone)]
pub struct LimitAtlas {
    surface: SubdivisionSurface,
    charts: Vec<Chart>,
}

impl LimitAtlas {
    /// The atlas of `surface`'s cage.
    pub fn new(surface: SubdivisionSurface) -> Self {
        let cage = surface.cage();
        let mut charts = Vec::with_capacity(cage.face_count());
        for f in 0..cage.face_count() {
            let n = cage.face(f).len();
            if surface.scheme() == Scheme::Loop || n == 4 {
                charts.push(Chart { face: f as u32, corner: None });
            } else {
                charts.extend((0..n as u32).map(|k| Chart { face: f as u32, corner: Some(k) }));
            }
        }
        LimitAtlas { surface, charts }
    }

    /// The subdivision surface.
    pub fn surface(&self) -> &SubdivisionSurface {
        &self.surface
    }

    /// The charts, chart c over u ∈ [c, c + 1].
    pub fn charts(&self) -> &[Chart] {
        &self.charts
    }

    /// The chart and local (s, t) ∈ [0, 1]² of the atlas parameter (u, v), clamped to the domain.
    pub fn locate(&self, u: f64, v: f64) -> (usize, f64, f64) {
        let last = self.charts.len().saturating_sub(1);
        let u = if u.is_nan() { 0.0 } else { u.clamp(0.0, self.charts.len() as f64) };
        let c = (u.floor() as usize).min(last);
        let t = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        (c, (u - c as f64).clamp(0.0, 1.0), t)
    }

    /// The limit point, normal and partials (with respect to the atlas parameters) at (u, v).
    pub fn sample(&self, u: f64, v: f64) -> Result<super::LimitSample> {
        let (c, s, t) = self.locate(u, v);
        let chart = self.charts.get(c).ok_or_else(|| Error::invalid("faces", "the cage has no faces"))?;
        let face = chart.face as usize;
        match (self.surface.scheme(), chart.corner) {
            (Scheme::Loop, _) => {
                let mut sample = self.surface.evaluate(face, s * (1.0 - t), t)?;
                if let Some(p) = sample.partials.as_mut() {
                    let (lu, lv, luu, luv, lvv) = (p.du, p.dv, p.duu, p.duv, p.dvv);
                    p.du = lu * (1.0 - t);
                    p.dv = lv - lu * s;
                    p.duu = luu * ((1.0 - t) * (1.0 - t));
                    p.duv = (luv - luu * s) * (1.0 - t) - lu;
                    p.dvv = lvv - luv * (2.0 * s) + luu * (s * s);
                }
                Ok(sample)
            }
            (_, None) => self.surface.evaluate(face, s, t),
            (_, Some(k)) => self.surface.evaluate_subface(face, k as usize, s, t),
        }
    }
}

impl Surface<3> for LimitAtlas {
    /// The box of the cage's vertices: it holds the limit surface, since every rule of the
    /// three schemes (boundaries and creases included) makes each new point a convex
    /// combination of old ones; not tight in general.
    fn enclosing_box(&self) -> Option<crate::query::Aabb<3>> {
        Some(crate::query::Aabb::around(&self.surface.cage().vertices, 0.0))
    }
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, self.charts.len() as f64)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }

    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let nan = Point::<3>::from([f64::NAN; 3]);
        out.iter_mut().take((du + 1) * (dv + 1)).for_each(|o| *o = nan);
        let Ok(sample) = self.sample(u, v) else { return };
        out[0] = sample.position;
        let Some(p) = sample.partials else { return };
        let mut put = |i: usize, j: usize, x: Point<3>| {
            if i <= du && j <= dv {
                out[i * (dv + 1) + j] = x;
            }
        };
        put(1, 0, p.du);
        put(0, 1, p.dv);
        put(2, 0, p.duu);
        put(1, 1, p.duv);
        put(0, 2, p.dvv);
    }

    fn breakpoints_u(&self) -> Vec<f64> {
        (0..=self.charts.len()).map(|c| c as f64).collect()
    }

    fn normal(&self, u: f64, v: f64) -> Option<Point<3>> {
        let n = self.sample(u, v).ok()?.normal;
        (n.norm() > 0.0).then_some(n)
    }

    fn subdivision(&self) -> Option<&SubdivisionSurface> {
        Some(&self.surface)
    }
}
