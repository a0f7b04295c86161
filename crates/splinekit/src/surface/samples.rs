//! Stored points and unit normals of a surface on a parameter grid, refreshable on
//! parameter rectangles only (after an edit that reports what it changed, such as moving a
//! patch of a blending-spline surface).

pub use crate::ParamRect;
use crate::error::{Error, Result};
use crate::surface::Surface;
use crate::{Interval, Point};

/// Points and normals at `us × vs` (`points[a·vs.len() + b]` at (`us[a]`, `vs[b]`)).
#[derive(Debug, Clone)]
pub struct SurfaceGridSamples<const D: usize> {
    us: Vec<f64>,
    vs: Vec<f64>,
    points: Vec<Point<D>>,
    normals: Vec<Point<D>>,
}

impl<const D: usize> SurfaceGridSamples<D> {
    /// An nu × nv grid evenly over the domain (nu, nv ≥ 2).
    pub fn uniform<S: Surface<D> + ?Sized>(surface: &S, nu: usize, nv: usize) -> Result<Self> {
        if nu < 2 || nv < 2 || nu.saturating_mul(nv) > 100_000_000 {
            return Err(Error::invalid(
                "grid",
                format!("need 2 to 10⁸ samples with at least 2 each way, got {nu}×{nv}"),
            ));
        }
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let us = (0..nu).map(|i| du.lerp(i as f64 / (nu - 1) as f64)).collect();
        let vs = (0..nv).map(|i| dv.lerp(i as f64 / (nv - 1) as f64)).collect();
        let mut s = SurfaceGridSamples {
            us,
            vs,
            points: vec![Point::<D>::zeros(); nu * nv],
            normals: vec![Point::<D>::zeros(); nu * nv],
        };
        surface.eval_grid_with_normals(&s.us, &s.vs, &mut s.points, &mut s.normals);
        Ok(s)
    }
    /// Re-evaluates the samples inside any of the closed rectangles; returns how many.
    pub fn refresh<S: Surface<D> + ?Sized>(&mut self, surface: &S, rects: &[ParamRect]) -> usize {
        let mut done = 0;
        let range = |xs: &[f64], i: Interval| xs.partition_point(|&x| x < i.start)..xs.partition_point(|&x| x <= i.end);
        let (mut pts, mut nrm) = (Vec::new(), Vec::new());
        for rect in rects {
            let (iu, iv) = (range(&self.us, rect.u), range(&self.vs, rect.v));
            let (n_u, n_v) = (iu.len(), iv.len());
            if n_u == 0 || n_v == 0 {
                continue;
            }
            pts.resize(n_u * n_v, Point::<D>::zeros());
            nrm.resize(n_u * n_v, Point::<D>::zeros());
            surface.eval_grid_with_normals(&self.us[iu.clone()], &self.vs[iv.clone()], &mut pts, &mut nrm);
            let nv = self.vs.len();
            for (a, ia) in iu.clone().enumerate() {
                let dst = ia * nv + iv.start;
                self.points[dst..dst + n_v].copy_from_slice(&pts[a * n_v..(a + 1) * n_v]);
                self.normals[dst..dst + n_v].copy_from_slice(&nrm[a * n_v..(a + 1) * n_v]);
            }
            done += n_u * n_v;
        }
        done
    }
    /// The u parameters of the grid rows.
    pub fn us(&self) -> &[f64] {
        &self.us
    }
    /// The v parameters of the grid columns.
    pub fn vs(&self) -> &[f64] {
        &self.vs
    }
    /// The points.
    pub fn points(&self) -> &[Point<D>] {
        &self.points
    }
    /// The unit normals (zero where the surface is not regular).
    pub fn normals(&self) -> &[Point<D>] {
        &self.normals
    }
}
