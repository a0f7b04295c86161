//! `splinekit eval` on surfaces: points, partials up to a total order, unit normals.

use anyhow::{Result, bail};
use splinekit::Point;
use splinekit::curve::Interval;
use splinekit::surface::{Surface, normal_or_limit};
use splinekit_scene::budget::{Cost, ShapeCost};
use splinekit_scene::{DimensionVisitor, Surfaces};

use crate::output::JsonOut;

/// The points of a surface evaluation: `--at` pairs or a `--grid`, with partials up to
/// total order `order`.
pub struct EvalSurface<'a> {
    pub at: Option<&'a [(f64, f64)]>,
    /// Points (triangle, u, v) of a triangle document.
    pub triangles: Option<&'a [(usize, f64, f64)]>,
    pub grid: Option<(usize, usize)>,
    pub order: usize,
}

fn spread(n: usize, d: Interval) -> Vec<f64> {
    (0..n).map(|i| super::spread::spread(i, n, d)).collect()
}

/// Parameter pairs and the partials at each.
type Samples<const D: usize> = (Vec<(f64, f64)>, Vec<Point<D>>);

impl EvalSurface<'_> {
    fn count(&self) -> usize {
        if let Some(t) = self.triangles {
            return t.len();
        }
        match (self.at, self.grid) {
            (Some(list), _) => list.len(),
            (None, Some((nu, nv))) => nu * nv,
            (None, None) => 0,
        }
    }

    /// Refuses a request that would not fit the budget: the partials held in memory (up to
    /// order max(K, 1) in each direction, for the normals), their evaluation (and a few
    /// more near singular points) and formatting.
    pub fn check_budget(&self, dimension: usize, cost: &ShapeCost) -> Result<()> {
        let k = self.order.max(1);
        let n = self.count() as f64;
        let block = ((k + 1) * (k + 1)) as f64;
        let written = n * (2.0 + (1.0 + ((self.order + 1) * (self.order + 2) / 2) as f64) * dimension as f64);
        let request = Cost::new(n * (block * dimension as f64 + 2.0) * 8.0, cost.evaluations(n, (k + 1) * (k + 1) - 1))
            + crate::budget::output(written);
        let flag = if self.grid.is_some() { "--grid" } else { "--at" };
        let what = format!(
            "{} points with partials up to order {k} ({:.1e} operations each, driven by {})",
            self.count(),
            cost.eval * block,
            cost.field
        );
        crate::budget::check_request(flag, &what, cost, request)
    }

    /// The parameters asked for (`--at` pairs, checked against open directions, or a
    /// `--grid`) and the partials up to order k in each direction at each of them, in
    /// blocks of (k + 1)² (i-th u- and j-th v-derivative at i·(k + 1) + j).
    fn sample<const D: usize>(&self, s: &dyn Surface<D>, k: usize) -> Result<Samples<D>> {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let w = (k + 1) * (k + 1);
        if s.subdivision().is_some() && self.order > 2 {
            bail!(
                "--derivatives: the limit of a subdivision surface has partials up to order 2 here, got {}",
                self.order
            );
        }
        if let Some(points) = self.triangles {
            return self.sample_triangles(s, points, k);
        }
        let samples = match (self.at, self.grid) {
            (Some(list), _) => {
                for &(u, v) in list {
                    let slack = |d: &Interval| 1e-12 * d.length().max(d.start.abs()).max(d.end.abs());
                    if !s.is_closed_u() && (u < du.start - slack(&du) || u > du.end + slack(&du)) {
                        bail!("--at: u = {u} is outside the domain [{}, {}] of this surface", du.start, du.end);
                    }
                    if !s.is_closed_v() && (v < dv.start - slack(&dv) || v > dv.end + slack(&dv)) {
                        bail!("--at: v = {v} is outside the domain [{}, {}] of this surface", dv.start, dv.end);
                    }
                }
                let mut values = vec![Point::<D>::zeros(); list.len() * w];
                for (i, &(u, v)) in list.iter().enumerate() {
                    s.eval_partials(u, v, k, k, &mut values[i * w..(i + 1) * w]);
                }
                (list.to_vec(), values)
            }
            (None, Some((nu, nv))) => {
                let us = spread(nu, du);
                let vs = spread(nv, dv);
                let mut values = vec![Point::<D>::zeros(); nu * nv * w];
                s.eval_grid(&us, &vs, k, k, &mut values);
                let params = us.iter().flat_map(|&u| vs.iter().map(move |&v| (u, v))).collect();
                (params, values)
            }
            (None, None) => bail!("give --at U:V,... or --grid NU,NV"),
        };
        if s.subdivision().is_some() {
            let (params, values) = &samples;
            for (n, &(u, v)) in params.iter().enumerate() {
                let printed = (0..=k)
                    .flat_map(|i| (0..=k).map(move |j| (i, j)))
                    .filter(|&(i, j)| i + j >= 1 && i + j <= self.order);
                if printed.into_iter().any(|(i, j)| !values[n * w + i * (k + 1) + j].iter().all(|x| x.is_finite())) {
                    bail!(
                        "--derivatives: the limit surface has no partials at ({u}, {v}), an extraordinary vertex (its point and normal are given without --derivatives)"
                    );
                }
            }
        }
        Ok(samples)
    }
}

impl EvalSurface<'_> {
    /// The partials in (u, v) of triangle t at each (t, u, v) of a triangle document; the
    /// parameters are returned as (t + u, v) only to name them in messages.
    fn sample_triangles<const D: usize>(
        &self,
        s: &dyn Surface<D>,
        points: &[(usize, f64, f64)],
        k: usize,
    ) -> Result<Samples<D>> {
        let Some(atlas) = s.triangle_atlas() else {
            bail!("--at: T:U:V points are for triangle documents; this surface takes U:V pairs");
        };
        let w = (k + 1) * (k + 1);
        let mut values = vec![Point::<D>::zeros(); points.len() * w];
        for (n, &(t, u, v)) in points.iter().enumerate() {
            let Some(chart) = atlas.charts().get(t) else {
                bail!("--at: triangle {t} does not exist (there are {})", atlas.charts().len());
            };
            chart.eval_partials(u, v, k, k, &mut values[n * w..(n + 1) * w]);
            let printed =
                (0..=k).flat_map(|i| (0..=k).map(move |j| (i, j))).filter(|&(i, j)| i + j >= 1 && i + j <= self.order);
            if printed.into_iter().any(|(i, j)| !values[n * w + i * (k + 1) + j].iter().all(|x| x.is_finite())) {
                bail!(
                    "--derivatives: triangle {t} has no partials in (u, v) at ({u}, {v}), a corner where its parametrisation is singular (a vertex of valence other than 6 of a blending triangulation); its point and normal are given without --derivatives"
                );
            }
        }
        Ok((points.iter().map(|&(t, u, v)| (t as f64 + u, v)).collect(), values))
    }
}

/// Streams a surface evaluation as `{"params", "points", "partials", "inside", "normals"}`.
pub struct SurfaceOutput<'a> {
    pub request: EvalSurface<'a>,
    pub out: &'a mut JsonOut,
}

impl DimensionVisitor<Surfaces> for SurfaceOutput<'_> {
    type Output = Result<()>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Result<()> {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let order = self.request.order;
        let k = order.max(1);
        let w = (k + 1) * (k + 1);
        let (params, values) = self.request.sample(s, k)?;
        let out = self.out;
        let list =
            |out: &mut JsonOut, key: &str, item: &mut dyn FnMut(&mut JsonOut, usize) -> Result<()>| -> Result<()> {
                out.raw(format!("\"{key}\":[").as_bytes())?;
                for n in 0..params.len() {
                    if n > 0 {
                        out.raw(b",")?;
                    }
                    item(out, n)?;
                }
                out.raw(b"]")
            };
        out.raw(b"{")?;
        let triangles = self.request.triangles;
        list(out, "params", &mut |out, n| match triangles {
            Some(t) => {
                let (t, u, v) = t[n];
                out.point(&[t as f64, u, v, 1.0 - u - v], || format!("params[{n}]"))
            }
            None => out.point(&[params[n].0, params[n].1], || format!("params[{n}]")),
        })?;
        out.raw(b",")?;
        list(out, "points", &mut |out, n| {
            let (u, v) = params[n];
            out.point(values[n * w].as_slice(), || format!("points[{n}] (at ({u}, {v}))"))
        })?;
        out.raw(b",\"partials\":{")?;
        let mut first = true;
        for total in 1..=order {
            for i in (0..=total).rev() {
                let j = total - i;
                let key = "u".repeat(i) + &"v".repeat(j);
                if !first {
                    out.raw(b",")?;
                }
                first = false;
                list(out, &key, &mut |out, n| {
                    let (u, v) = params[n];
                    out.point(values[n * w + i * (k + 1) + j].as_slice(), || {
                        format!("partials.{key}[{n}] (at ({u}, {v}))")
                    })
                })?;
            }
        }
        out.raw(b"}")?;
        if s.trim_contains(du.start, dv.start).is_some() {
            out.raw(b",")?;
            list(out, "inside", &mut |out, n| {
                let (u, v) = params[n];
                out.raw(if s.trim_contains(u, v).unwrap_or(true) { b"true" } else { b"false" })
            })?;
        }
        if D == 3 {
            out.raw(b",")?;
            list(out, "normals", &mut |out, n| {
                let (u, v) = params[n];
                let o = &values[n * w..(n + 1) * w];
                let normal = match (triangles, s.triangle_atlas()) {
                    (Some(t), Some(atlas)) => {
                        let (t, a, b) = t[n];
                        atlas.charts()[t].normal(a, b, 1.0 - a - b)
                    }
                    _ => normal_or_limit(s, u, v, &o[k + 1], &o[1]),
                };
                match normal {
                    Some(nrm) => out.point(nrm.as_slice(), || format!("normals[{n}] (at ({u}, {v}))")),
                    None => {
                        out.abandon();
                        bail!("normals: the surface has no normal at ({u}, {v}): S_u × S_v vanishes there and nearby")
                    }
                }
            })?;
        }
        out.raw(b"}")
    }
}
