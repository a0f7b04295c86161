//! What a style reads off a shape besides its points: colour maps (a quantity per vertex
//! turned into a colour by a ramp) and arrows of vector fields (normals, tangents,
//! derivatives, partials) at regular parameters.

use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::surface::{Surface, unit_normal};
use splinekit_mesh::surface_mesh::to3;
use splinekit_scene::scenes::{ArrowFieldDoc, ArrowPlacementDoc, ArrowsDoc, ColorMapDoc};

use crate::scene::LineItem;

/// How a map's values become colours.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Ramp {
    /// From the least value (dark blue) to the most (yellow).
    Range,
    /// From 0 (dark blue) to the most (yellow): speeds, a curve's curvature.
    FromZero,
    /// Blue (negative), white (0), red (positive), at ± the 95th percentile of |value|.
    Signed,
}

fn ramp_of(map: ColorMapDoc) -> Ramp {
    match map {
        ColorMapDoc::Gaussian
        | ColorMapDoc::Mean
        | ColorMapDoc::PrincipalMax
        | ColorMapDoc::PrincipalMin
        | ColorMapDoc::Torsion => Ramp::Signed,
        ColorMapDoc::SpeedU | ColorMapDoc::SpeedV | ColorMapDoc::Curvature => Ramp::FromZero,
        _ => Ramp::Range,
    }
}

/// The colours of `values` of a map by its ramp (NaN and infinities at the ramp's middle
/// or start).
pub fn ramp_colors(map: ColorMapDoc, values: &[f64]) -> Vec<[f32; 4]> {
    let finite = || values.iter().copied().filter(|x| x.is_finite());
    match ramp_of(map) {
        Ramp::Range => {
            let (lo, hi) = finite().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
            let span = if hi > lo { hi - lo } else { 1.0 };
            values.iter().map(|&x| sequential(if x.is_finite() { ((x - lo) / span) as f32 } else { 0.0 })).collect()
        }
        Ramp::FromZero => {
            let hi = finite().fold(0.0f64, f64::max);
            let top = robust_top(values).min(hi).max(1e-300);
            values.iter().map(|&x| sequential(if x.is_finite() { (x / top) as f32 } else { 0.0 })).collect()
        }
        Ramp::Signed => {
            let scale = robust_top(values).max(1e-12);
            values.iter().map(|&x| diverging(if x.is_finite() { (x / scale) as f32 } else { 0.0 })).collect()
        }
    }
}

/// The 95th percentile of |value| over the finite values (1 when there are none).
fn robust_top(values: &[f64]) -> f64 {
    let mut mags: Vec<f64> = values.iter().map(|x| x.abs()).filter(|x| x.is_finite()).collect();
    mags.sort_by(f64::total_cmp);
    mags.get(mags.len() * 95 / 100).copied().unwrap_or(1.0)
}

/// The value of a surface map at (u, v) (normalised parameters `t`, position `p`, unit
/// normal `n`); zebra and isophotes give the angle and N·L their ramps read.
pub fn surface_value<const D: usize>(
    s: &dyn Surface<D>,
    map: ColorMapDoc,
    (u, v): (f64, f64),
    t: [f64; 2],
    p: [f64; 3],
    n: [f64; 3],
) -> f64 {
    let speed = |i: usize, j: usize| {
        let mut out = [Point::<D>::zeros(); 4];
        s.eval_partials(u, v, 1, 1, &mut out);
        out[i * 2 + j].norm()
    };
    let curvatures = || s.curvatures(u, v);
    match map {
        ColorMapDoc::U => t[0],
        ColorMapDoc::V => t[1],
        ColorMapDoc::X => p[0],
        ColorMapDoc::Y => p[1],
        ColorMapDoc::Z => p[2],
        ColorMapDoc::SpeedU => speed(1, 0),
        ColorMapDoc::SpeedV => speed(0, 1),
        ColorMapDoc::Gaussian => curvatures().map_or(0.0, |c| c.gaussian),
        ColorMapDoc::Mean => curvatures().map_or(0.0, |c| c.mean),
        ColorMapDoc::PrincipalMax => curvatures().map_or(0.0, |c| c.principal.0),
        ColorMapDoc::PrincipalMin => curvatures().map_or(0.0, |c| c.principal.1),
        ColorMapDoc::Zebra => n[0].clamp(-1.0, 1.0).asin(),
        ColorMapDoc::Isophotes => {
            let l = [1.0, 1.0, 2.0].map(|x: f64| x / 6f64.sqrt());
            n[0] * l[0] + n[1] * l[1] + n[2] * l[2]
        }
        // Curve maps; `compose` refuses them on surfaces.
        ColorMapDoc::Curvature | ColorMapDoc::Torsion => 0.0,
    }
}

/// The colours of a surface map over a mesh's vertices.
pub fn surface_colors<const D: usize>(
    s: &dyn Surface<D>,
    map: ColorMapDoc,
    uvs: &[[f64; 2]],
    positions: &[[f64; 3]],
    normals: &[[f64; 3]],
    base: [f32; 4],
) -> Vec<[f32; 4]> {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let values: Vec<f64> = uvs
        .iter()
        .zip(positions)
        .zip(normals)
        .map(|((t, p), n)| surface_value(s, map, (du.lerp(t[0]), dv.lerp(t[1])), *t, *p, *n))
        .collect();
    match map {
        ColorMapDoc::U | ColorMapDoc::V => values.iter().map(|&x| sequential(x as f32)).collect(),
        ColorMapDoc::Zebra => values.iter().map(|&a| zebra(a)).collect(),
        ColorMapDoc::Isophotes => values.iter().map(|&x| isophote(x, base)).collect(),
        _ => ramp_colors(map, &values),
    }
}

/// The colours of a curve map at a polyline's parameters.
pub fn curve_colors<const D: usize>(c: &dyn Curve<D>, map: ColorMapDoc, params: &[f64]) -> Vec<[f32; 4]> {
    let d = c.domain();
    let values: Vec<f64> = params
        .iter()
        .map(|&t| {
            let mut out = [Point::<D>::zeros(); 4];
            c.eval(t, &mut out);
            let p = to3(&out[0]);
            match map {
                ColorMapDoc::X => p[0],
                ColorMapDoc::Y => p[1],
                ColorMapDoc::Z => p[2],
                ColorMapDoc::U => (t - d.start) / d.length(),
                ColorMapDoc::SpeedU => out[1].norm(),
                ColorMapDoc::Curvature => splinekit::curve::curvature_from(&out[1], &out[2]),
                ColorMapDoc::Torsion => torsion(&to3(&out[1]), &to3(&out[2]), &to3(&out[3])),
                // Surface maps; `compose` refuses them on curves.
                _ => 0.0,
            }
        })
        .collect();
    match map {
        ColorMapDoc::U => values.iter().map(|&x| sequential(x as f32)).collect(),
        _ => ramp_colors(map, &values),
    }
}

/// τ = (c′ × c″)·c‴ / |c′ × c″|² (0 where the curve is straight; 2-D curves have none).
fn torsion(d1: &[f64; 3], d2: &[f64; 3], d3: &[f64; 3]) -> f64 {
    let x = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]];
    let n2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    if n2 <= 1e-300 { 0.0 } else { (x[0] * d3[0] + x[1] * d3[1] + x[2] * d3[2]) / n2 }
}

/// The diagonal of the box around the points (the size arrows are measured by).
pub fn box_diagonal(points: impl Iterator<Item = [f64; 3]>) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in points.filter(|p| p.iter().all(|x| x.is_finite())) {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let d = (0..3).map(|k| (hi[k] - lo[k]).max(0.0).powi(2)).sum::<f64>().sqrt();
    if d.is_finite() { d } else { 0.0 }
}

/// Parameters `count` + 1 regular ones over [a, b] (`count` on a closed domain, whose end
/// is its start).
fn regular(a: f64, b: f64, count: usize, closed: bool) -> Vec<f64> {
    let n = if closed { count } else { count + 1 };
    (0..n).map(|i| a + (b - a) * i as f64 / count as f64).collect()
}

/// An arrow from `foot` along `vector`: the shaft and a head of two short strokes at 25 %
/// of its length, 25° off the shaft in the plane of the shaft and `side`.
fn arrow(foot: [f64; 3], vector: [f64; 3], side: [f64; 3], color: [f32; 4], width: f32) -> [LineItem; 2] {
    let tip = [foot[0] + vector[0], foot[1] + vector[1], foot[2] + vector[2]];
    let len = (vector[0] * vector[0] + vector[1] * vector[1] + vector[2] * vector[2]).sqrt();
    let unit = vector.map(|x| x / len.max(1e-300));
    // The part of `side` across the shaft (any perpendicular when they are parallel).
    let dot = side[0] * unit[0] + side[1] * unit[1] + side[2] * unit[2];
    let mut across = [side[0] - dot * unit[0], side[1] - dot * unit[1], side[2] - dot * unit[2]];
    let mut n = (across[0] * across[0] + across[1] * across[1] + across[2] * across[2]).sqrt();
    if n < 1e-9 {
        across = if unit[0].abs() < 0.9 { [0.0, -unit[2], unit[1]] } else { [-unit[2], 0.0, unit[0]] };
        n = (across[0] * across[0] + across[1] * across[1] + across[2] * across[2]).sqrt();
    }
    let across = across.map(|x| x / n);
    let (back, wide) = (0.25 * len * 25f64.to_radians().cos(), 0.25 * len * 25f64.to_radians().sin());
    let head =
        |sign: f64| -> [f32; 3] { [0, 1, 2].map(|k| (tip[k] - back * unit[k] + sign * wide * across[k]) as f32) };
    let f = |p: [f64; 3]| p.map(|x| x as f32);
    [
        LineItem { points: vec![f(foot), f(tip)], closed: false, color, width, colors: Vec::new() },
        LineItem { points: vec![head(1.0), f(tip), head(-1.0)], closed: false, color, width, colors: Vec::new() },
    ]
}

/// Feet and vectors scaled so the longest is `length` (unit fields: each `length`), with
/// each arrow's head in the plane of its vector and `side`.
fn arrows_of(samples: Vec<([f64; 3], [f64; 3], [f64; 3])>, unit: bool, length: f64, color: [f32; 4]) -> Vec<LineItem> {
    let norm = |v: &[f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let longest = samples.iter().map(|(_, v, _)| norm(v)).filter(|x| x.is_finite()).fold(0.0, f64::max);
    let mut out = Vec::new();
    for (foot, v, side) in samples {
        let n = norm(&v);
        if !(n.is_finite() && n > 1e-12 * longest.max(1e-300) && foot.iter().all(|x| x.is_finite())) {
            continue;
        }
        let scale = if unit { length / n } else { length / longest };
        out.extend(arrow(foot, v.map(|x| x * scale), side, color, 1.5));
    }
    out
}

/// The arrows of a curve: its field at `count` + 1 regular parameters (only the ends with
/// `"boundary"`), the longest `length` of the curve's size `size` long.
pub fn curve_arrows<const D: usize>(c: &dyn Curve<D>, a: &ArrowsDoc, size: f64, color: [f32; 4]) -> Vec<LineItem> {
    let d = c.domain();
    let params = match a.on {
        ArrowPlacementDoc::All => regular(d.start, d.end, a.count.unwrap_or(32), c.is_closed()),
        ArrowPlacementDoc::Boundary if c.is_closed() => vec![d.start],
        ArrowPlacementDoc::Boundary => vec![d.start, d.end],
    };
    let samples = params
        .iter()
        .map(|&t| {
            let mut out = [Point::<D>::zeros(); 3];
            c.eval(t, &mut out);
            let (p, d1, d2) = (to3(&out[0]), to3(&out[1]), to3(&out[2]));
            let n1 = (d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]).sqrt().max(1e-300);
            let tangent = d1.map(|x| x / n1);
            let v = match a.field {
                ArrowFieldDoc::Tangent | ArrowFieldDoc::Derivative => d1,
                ArrowFieldDoc::Second => d2,
                // The part of c″ across the tangent.
                _ => {
                    let k = d2[0] * tangent[0] + d2[1] * tangent[1] + d2[2] * tangent[2];
                    [d2[0] - k * tangent[0], d2[1] - k * tangent[1], d2[2] - k * tangent[2]]
                }
            };
            // Heads in the osculating plane, or the xy-plane for straight pieces.
            let side = if a.field == ArrowFieldDoc::Tangent || a.field == ArrowFieldDoc::Derivative { d2 } else { d1 };
            (p, v, side)
        })
        .collect();
    arrows_of(samples, a.field.is_unit(), a.length * size, color)
}

/// The arrows of a surface: its field on a (`count` + 1)² grid of regular parameters, or on
/// the four sides only with `"boundary"`, the longest `length` of the surface's size `size`
/// long.
pub fn surface_arrows<const D: usize>(s: &dyn Surface<D>, a: &ArrowsDoc, size: f64, color: [f32; 4]) -> Vec<LineItem> {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let n = a.count.unwrap_or(12);
    let us = regular(du.start, du.end, n, s.is_closed_u());
    let vs = regular(dv.start, dv.end, n, s.is_closed_v());
    let mut params = Vec::new();
    match a.on {
        ArrowPlacementDoc::All => {
            for &u in &us {
                params.extend(vs.iter().map(|&v| (u, v)));
            }
        }
        ArrowPlacementDoc::Boundary => {
            if !s.is_closed_v() {
                params.extend(us.iter().flat_map(|&u| [(u, dv.start), (u, dv.end)]));
            }
            if !s.is_closed_u() {
                params.extend(vs.iter().flat_map(|&v| [(du.start, v), (du.end, v)]));
            }
        }
    }
    let samples = params
        .iter()
        .map(|&(u, v)| {
            let mut out = [Point::<D>::zeros(); 4];
            s.eval_partials(u, v, 1, 1, &mut out);
            let (p, su, sv, suv) = (to3(&out[0]), to3(&out[2]), to3(&out[1]), to3(&out[3]));
            let normal = unit_normal(&out[2], &out[1]).map_or([0.0; 3], |n| to3(&n));
            match a.field {
                ArrowFieldDoc::Du => (p, su, sv),
                ArrowFieldDoc::Dv => (p, sv, su),
                ArrowFieldDoc::Duv => (p, suv, su),
                _ => (p, normal, su),
            }
        })
        .collect();
    arrows_of(samples, a.field.is_unit(), a.length * size, color)
}

/// Zebra stripes of the normal's angle `a` (radians) from the yz-plane: white and black,
/// 15° each (white from 0° to 15°), a clipped sine so that colours interpolated between
/// vertices keep the stripes' edges smooth.
pub fn zebra(a: f64) -> [f32; 4] {
    let s = (std::f64::consts::PI * a / 15f64.to_radians()).sin();
    let g = (0.5 + 0.5 * (2.5 * s).clamp(-1.0, 1.0)) as f32;
    let g = 0.05 + 0.9 * g;
    [g, g, g, 1.0]
}

/// The shape's colour with a dark line where N·L (`x`) is within 0.012 of a multiple of 0.1.
pub fn isophote(x: f64, color: [f32; 4]) -> [f32; 4] {
    let step = 0.1;
    let off = (x / step - (x / step).round()).abs() * step;
    if off < 0.012 { [0.05, 0.05, 0.05, 1.0] } else { color }
}

/// Blue (−1) – white (0) – red (+1).
pub fn diverging(x: f32) -> [f32; 4] {
    let x = x.clamp(-1.0, 1.0);
    if x < 0.0 {
        [1.0 + 0.8 * x, 1.0 + 0.55 * x, 1.0 + 0.1 * x, 1.0]
    } else {
        [1.0 - 0.1 * x, 1.0 - 0.75 * x, 1.0 - 0.8 * x, 1.0]
    }
}

/// Dark blue (0) – teal – yellow (1), roughly viridis.
pub fn sequential(x: f32) -> [f32; 4] {
    let x = x.clamp(0.0, 1.0);
    let stops = [[0.27, 0.0, 0.33], [0.23, 0.32, 0.55], [0.13, 0.57, 0.55], [0.37, 0.79, 0.38], [0.99, 0.91, 0.14]];
    let f = x * 4.0;
    let i = (f as usize).min(3);
    let t = f - i as f32;
    let (a, b) = (stops[i], stops[i + 1]);
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t, 1.0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use splinekit::curve::model::Helix;
    use splinekit::surface::model::Sphere;

    #[test]
    fn a_helix_has_constant_curvature_and_torsion_and_its_maps_are_flat() {
        // r = 1, pitch 2π: κ = τ = 1/2.
        let h = Helix::new(1.0, std::f64::consts::TAU, 2.0).unwrap();
        let params: Vec<f64> = (0..10).map(|i| i as f64 * 0.9).collect();
        let mut out = [Point::<3>::zeros(); 4];
        h.eval(0.4, &mut out);
        assert!((torsion(&to3(&out[1]), &to3(&out[2]), &to3(&out[3])) - 0.5).abs() < 1e-14);
        let c = curve_colors(&h, ColorMapDoc::Torsion, &params);
        assert!(c.iter().all(|x| *x == c[0]), "constant torsion, one colour");
        let z = curve_colors(&h, ColorMapDoc::Z, &params);
        assert_eq!(z[0], sequential(0.0));
        assert_eq!(z[9], sequential(1.0));
    }

    #[test]
    fn sphere_maps_read_the_right_quantities() {
        let s = Sphere::new(2.0).unwrap();
        let (u, v) = (0.7, 0.4);
        let p = to3(&s.point(u, v));
        let n = s.normal(u, v).map_or([0.0; 3], |n| to3(&n));
        let k = |m| surface_value(&s, m, (u, v), [0.0, 0.0], p, n);
        assert!((k(ColorMapDoc::PrincipalMax).abs() - 0.5).abs() < 1e-12);
        assert!((k(ColorMapDoc::PrincipalMin).abs() - 0.5).abs() < 1e-12);
        assert!((k(ColorMapDoc::Gaussian) - 0.25).abs() < 1e-12);
        assert_eq!(k(ColorMapDoc::Z), p[2]);
        assert!((k(ColorMapDoc::SpeedU) - s.partial(u, v, 1, 0).norm()).abs() < 1e-15);
    }

    #[test]
    fn arrows_have_a_shaft_and_a_head_and_scale_to_the_longest() {
        let s = Sphere::new(1.0).unwrap();
        let a = ArrowsDoc { field: ArrowFieldDoc::Normal, on: ArrowPlacementDoc::All, count: Some(4), length: 0.1 };
        let lines = surface_arrows(&s, &a, 2.0, [0.0, 0.0, 0.0, 1.0]);
        assert!(!lines.is_empty() && lines.len() % 2 == 0);
        for shaft in lines.iter().step_by(2) {
            let (f, t) = (shaft.points[0], shaft.points[1]);
            let len = ((t[0] - f[0]).powi(2) + (t[1] - f[1]).powi(2) + (t[2] - f[2]).powi(2)).sqrt();
            assert!((len - 0.2).abs() < 1e-6, "unit normals 0.1 of size 2 long: {len}");
        }
        let b = ArrowsDoc { on: ArrowPlacementDoc::Boundary, ..a.clone() };
        // The sphere is closed in u: its boundary is the two poles' rows in v.
        assert!(surface_arrows(&s, &b, 2.0, [0.0; 4]).len() < lines.len());
    }
}
