//! `splinekit eval` on surfaces: points, partials up to a total order, unit normals.

use anyhow::{Result, bail};
use serde_json::{Map, Value, json};
use splinekit::Point;
use splinekit::surface::{Surface, unit_normal};
use splinekit_scene::{DimensionVisitor, Surfaces};

use super::eval::MAX_SAMPLES;
use crate::output::number;

pub struct EvalSurface<'a> {
    pub at: Option<&'a [(f64, f64)]>,
    pub grid: Option<(usize, usize)>,
    pub order: usize,
}

fn spread(n: usize, a: f64, b: f64) -> Vec<f64> {
    (0..n)
        .map(|i| {
            if n == 1 {
                a
            } else if i + 1 == n {
                b
            } else {
                a + (b - a) * i as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// The unit normal at (u, v), or its limit from just inside the domain where S_u × S_v
/// vanishes (poles, apexes); `None` if the surface is degenerate around the point.
fn normal_or_limit<const D: usize>(
    s: &dyn Surface<D>,
    u: f64,
    v: f64,
    su: &Point<D>,
    sv: &Point<D>,
) -> Option<Point<D>> {
    if let Some(n) = unit_normal(su, sv) {
        return Some(n);
    }
    let (du, dv) = (s.domain_u(), s.domain_v());
    let (hu, hv) = (1e-7 * du.length(), 1e-7 * dv.length());
    let inside = |x: f64, d: &splinekit::curve::Interval| x >= d.start && x <= d.end;
    for (a, b) in [(0.0, hv), (0.0, -hv), (hu, 0.0), (-hu, 0.0), (hu, hv), (-hu, -hv), (hu, -hv), (-hu, hv)] {
        let (x, y) = (u + a, v + b);
        if inside(x, &du) && inside(y, &dv) {
            let mut o = [Point::<D>::zeros(); 4];
            s.eval_partials(x, y, 1, 1, &mut o);
            if let Some(n) = unit_normal(&o[2], &o[1]) {
                return Some(n);
            }
        }
    }
    None
}

/// Parameter pairs and the partials at each.
type Samples<const D: usize> = (Vec<(f64, f64)>, Vec<Point<D>>);

impl EvalSurface<'_> {
    /// The parameters asked for (`--at` pairs, checked against open directions, or a
    /// `--grid`) and the partials up to order k in each direction at each of them, in
    /// blocks of (k + 1)² (i-th u- and j-th v-derivative at i·(k + 1) + j).
    fn sample<const D: usize>(&self, s: &dyn Surface<D>, k: usize) -> Result<Samples<D>> {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let w = (k + 1) * (k + 1);
        Ok(match (self.at, self.grid) {
            (Some(list), _) => {
                for &(u, v) in list {
                    let slack = |d: &splinekit::curve::Interval| 1e-12 * d.length().max(d.start.abs()).max(d.end.abs());
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
                if (nu * nv).saturating_mul(w * D) > 100_000_000 || nu * nv > MAX_SAMPLES {
                    bail!(
                        "request too large: {nu} × {nv} points with partials up to order {k} exceeds 100000000 numbers"
                    );
                }
                let us = spread(nu, du.start, du.end);
                let vs = spread(nv, dv.start, dv.end);
                let mut values = vec![Point::<D>::zeros(); nu * nv * w];
                s.eval_grid(&us, &vs, k, k, &mut values);
                let params = us.iter().flat_map(|&u| vs.iter().map(move |&v| (u, v))).collect();
                (params, values)
            }
            (None, None) => bail!("give --at U:V,... or --grid NU,NV"),
        })
    }
}

impl DimensionVisitor<Surfaces> for EvalSurface<'_> {
    type Output = Result<Value>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Result<Value> {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let k = self.order.max(1);
        let w = (k + 1) * (k + 1);
        let (params, values) = self.sample(s, k)?;
        let coords = |p: &Point<D>, what: &dyn Fn() -> String| -> Result<Value> {
            Ok(Value::Array(p.iter().map(|&c| number(c, &what())).collect::<Result<_>>()?))
        };
        let mut points = Vec::with_capacity(params.len());
        let mut normals = Vec::with_capacity(params.len());
        let mut partials: Vec<(String, Vec<Value>)> = Vec::new();
        for total in 1..=self.order {
            for i in (0..=total).rev() {
                partials.push(("u".repeat(i) + &"v".repeat(total - i), Vec::with_capacity(params.len())));
            }
        }
        for (n, &(u, v)) in params.iter().enumerate() {
            let o = &values[n * w..(n + 1) * w];
            points.push(coords(&o[0], &|| format!("the point at ({u}, {v})"))?);
            let mut slot = 0;
            for total in 1..=self.order {
                for i in (0..=total).rev() {
                    let j = total - i;
                    let key = partials[slot].0.clone();
                    partials[slot].1.push(coords(&o[i * (k + 1) + j], &|| format!("partial {key} at ({u}, {v})"))?);
                    slot += 1;
                }
            }
            if D == 3 {
                let (su, sv) = (o[k + 1], o[1]);
                match normal_or_limit(s, u, v, &su, &sv) {
                    Some(nrm) => normals.push(coords(&nrm, &|| format!("the normal at ({u}, {v})"))?),
                    None => {
                        bail!("normals: the surface has no normal at ({u}, {v}): S_u × S_v vanishes there and nearby")
                    }
                }
            }
        }
        let mut map = Map::new();
        for (key, vals) in partials {
            map.insert(key, Value::Array(vals));
        }
        let params_uv = params;
        let params: Vec<Value> = params_uv.iter().map(|&(u, v)| json!([u, v])).collect();
        let inside: Option<Vec<bool>> = (s.trim_contains(du.start, dv.start).is_some())
            .then(|| params_uv.iter().map(|&(u, v)| s.trim_contains(u, v).unwrap_or(true)).collect());
        let mut out = json!({ "params": params, "points": points, "partials": Value::Object(map) });
        if let Some(inside) = inside {
            out["inside"] = json!(inside);
        }
        if D == 3 {
            out["normals"] = Value::Array(normals);
        }
        Ok(out)
    }
}
