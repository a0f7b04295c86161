//! Knot insertion on B-spline, NURBS and Bézier surfaces from the window: a click on the
//! selected surface inserts a u-knot there (the isocurve u = u₀ through the clicked point
//! becomes a knot line), Shift + click a v-knot; the surface does not change. One undoable
//! edit of the object's whole `shape`, made by the scene's
//! [`insert_net_knots`](splinekit_scene::refine_net::insert_net_knots) (Boehm on every
//! column or row of the net, in the kernel).
//!
//! The clicked parameters (u₀, v₀) come from a [`GRID`] × [`GRID`] grid of surface samples:
//! each grid cell is two triangles in screen space; among the triangles that contain the
//! cursor, the nearest the eye (smallest normalised depth, so a hidden sheet is not
//! picked) gives (u, v) by barycentric interpolation of its corners' parameters.

use splinekit::surface::Surface;
use splinekit::surface::iso_curve::Direction;
use splinekit_scene::refine_net::insert_net_knots;
use splinekit_scene::{DimensionVisitor, ShapeDocument, Surfaces};

use crate::edit::Edit;
use crate::error::StudioError;
use crate::view_camera::Projector;

/// Samples per direction of the grid searched for the clicked parameters (cells: one less).
pub const GRID: usize = 64;

/// One surface sample: its parameters (u, v) and world point (z = 0 for plane nets).
type Sample = ((f64, f64), [f64; 3]);

/// A sample's pixel position and normalised depth; `None` behind the eye.
type OnScreen = Option<([f64; 2], f64)>;

/// `n` + 1 × `n` + 1 samples over the surface's domain, `grid[i][j]` at the i-th u and j-th v.
pub fn surface_samples(shape: &ShapeDocument, n: usize) -> Result<Vec<Vec<Sample>>, StudioError> {
    struct Grid(usize);
    impl DimensionVisitor<Surfaces> for Grid {
        type Output = Vec<Vec<Sample>>;
        fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
            let (du, dv) = (s.domain_u(), s.domain_v());
            (0..=self.0)
                .map(|i| {
                    let u = du.lerp(i as f64 / self.0 as f64);
                    (0..=self.0)
                        .map(|j| {
                            let v = dv.lerp(j as f64 / self.0 as f64);
                            let p = s.point(u, v);
                            ((u, v), [0, 1, 2].map(|k| if k < D { p[k] } else { 0.0 }))
                        })
                        .collect()
                })
                .collect()
        }
    }
    match shape {
        ShapeDocument::Surface(s) => Ok(s.build()?.visit(Grid(n))),
        ShapeDocument::Curve(_) => Err("not a surface".into()),
    }
}

/// Barycentric coordinates (λ₀, λ₁, λ₂) of `m` in the screen triangle `p`; `None` for a
/// degenerate (edge-on) triangle.
fn barycentric(p: [[f64; 2]; 3], m: [f64; 2]) -> Option<[f64; 3]> {
    let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
    let sub = |a: [f64; 2], b: [f64; 2]| [a[0] - b[0], a[1] - b[1]];
    let (e1, e2, r) = (sub(p[1], p[0]), sub(p[2], p[0]), sub(m, p[0]));
    let d = cross(e1, e2);
    if d.abs() < 1e-12 {
        return None;
    }
    let (l1, l2) = (cross(r, e2) / d, cross(e1, r) / d);
    Some([1.0 - l1 - l2, l1, l2])
}

/// The parameters (u, v) of the front-most point of the sampled surface under `mouse`
/// (view pixels); `None` off the surface.
pub fn parameters_at(grid: &[Vec<Sample>], projector: &Projector, mouse: [f64; 2]) -> Option<(f64, f64)> {
    let projected: Vec<Vec<OnScreen>> =
        grid.iter().map(|row| row.iter().map(|&(_, p)| projector.project(p)).collect()).collect();
    let mut best: Option<(f64, (f64, f64))> = None;
    for i in 0..grid.len().saturating_sub(1) {
        for j in 0..grid[i].len().saturating_sub(1) {
            let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            for tri in [[0, 1, 2], [0, 2, 3]] {
                let c = tri.map(|k| corners[k]);
                let Some(proj) = c.iter().map(|&(a, b)| projected[a][b]).collect::<Option<Vec<_>>>() else {
                    continue;
                };
                let Some(l) = barycentric([proj[0].0, proj[1].0, proj[2].0], mouse) else { continue };
                if l.iter().any(|&x| x < -1e-9) {
                    continue;
                }
                let depth: f64 = (0..3).map(|k| l[k] * proj[k].1).sum();
                if best.is_some_and(|(d, _)| d <= depth) {
                    continue;
                }
                let uv = |k: usize| grid[c[k].0][c[k].1].0;
                let u = (0..3).map(|k| l[k] * uv(k).0).sum();
                let v = (0..3).map(|k| l[k] * uv(k).1).sum();
                best = Some((depth, (u, v)));
            }
        }
    }
    best.map(|(_, uv)| uv)
}

/// The edit inserting knot `t` in `direction` (u-knot for [`Direction::U`]) into object
/// `object`'s spline net.
pub fn insert(shape: &ShapeDocument, object: usize, direction: Direction, t: f64) -> Result<Edit, StudioError> {
    let ShapeDocument::Surface(doc) = shape else {
        return Err("knot insertion on a surface: the object is a curve".into());
    };
    let out = insert_net_knots(doc, direction, &[t])?;
    Ok(Edit::Set { object, pointer: "/shape".into(), value: Some(out.to_value()) })
}

#[cfg(test)]
mod tests {
    use super::*;
    use splinekit_render::{Camera, RenderScene};

    fn bump() -> ShapeDocument {
        ShapeDocument::from_value(serde_json::json!({"type": "nurbs_surface", "degree_u": 2, "degree_v": 2,
            "knots_u": [0, 0, 0, 1, 1, 1], "knots_v": [0, 0, 0, 0.5, 1, 1, 1],
            "control_points": [[[0, 0, 0], [0, 1, 0], [0, 2, 0], [0, 3, 0]],
                               [[1, 0, 0], [1, 1, 1.5], [1, 2, 1], [1, 3, 0]],
                               [[2, 0, 0], [2, 1, 0], [2, 2, 0], [2, 3, 0]]],
            "weights": [[1, 1, 1, 1], [1, 2, 0.5, 1], [1, 1, 1, 1]]}))
        .expect("valid")
    }

    fn value(s: &ShapeDocument) -> serde_json::Value {
        match s {
            ShapeDocument::Curve(c) => c.to_value(),
            ShapeDocument::Surface(s) => s.to_value(),
        }
    }

    #[test]
    fn a_click_finds_the_parameters_of_the_front_sheet() {
        let shape = bump();
        let grid = surface_samples(&shape, GRID).expect("samples");
        let scene = RenderScene {
            camera: Some(Camera::fit(([0.0, 0.0, 0.0], [2.0, 3.0, 1.0]), 0.7, 0.6, 1.5)),
            ..Default::default()
        };
        let projector = Projector::new(&scene, (800, 600));
        // The point S(0.3, 0.62) of a finer grid, off the search grid's own samples.
        let fine = surface_samples(&shape, 50).expect("fine");
        let ((u, v), p) = fine[15][31]; // u = 0.3, v = 0.62
        let (px, _) = projector.project(p).expect("in front");
        let (pu, pv) = parameters_at(&grid, &projector, px).expect("on the surface");
        assert!((pu - u).abs() < 5e-3 && (pv - v).abs() < 5e-3, "({pu}, {pv}) for ({u}, {v})");
        assert!(parameters_at(&grid, &projector, [-50.0, -50.0]).is_none());
    }

    #[test]
    fn inserting_a_u_or_v_knot_keeps_the_surface() {
        let before = bump();
        for (direction, field, rows, cols) in [(Direction::U, "knots_u", 4, 4), (Direction::V, "knots_v", 3, 5)] {
            let Edit::Set { value: Some(v), .. } = insert(&before, 0, direction, 0.3).expect("inserts") else {
                panic!("a set")
            };
            let after = ShapeDocument::from_value(v).expect("valid");
            let (a, b) = (value(&before), value(&after));
            assert_eq!(b[field].as_array().map(Vec::len), a[field].as_array().map(|k| k.len() + 1), "{field}");
            assert_eq!(b["control_points"].as_array().map(Vec::len), Some(rows));
            assert_eq!(b["control_points"][0].as_array().map(Vec::len), Some(cols));
            let (sa, sb) = (surface_samples(&before, 20).expect("a"), surface_samples(&after, 20).expect("b"));
            for (ra, rb) in sa.iter().zip(&sb) {
                for ((ta, pa), (tb, pb)) in ra.iter().zip(rb) {
                    assert_eq!(ta, tb);
                    assert!((0..3).all(|k| (pa[k] - pb[k]).abs() <= 1e-12), "{pa:?} vs {pb:?} at {ta:?}");
                }
            }
        }
        let curve =
            ShapeDocument::from_value(serde_json::json!({"type": "bezier", "control_points": [[0, 0], [1, 1]]}))
                .expect("valid");
        assert!(insert(&curve, 0, Direction::U, 0.5).is_err());
    }
}
