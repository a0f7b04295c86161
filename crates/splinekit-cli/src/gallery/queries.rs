//! The gallery's figures of geometric queries: crossings of two curves, the offsets of the
//! heart, and contours (plane sections) of a surface.

use anyhow::{Result, anyhow};
use splinekit::Point;
use splinekit::curve::model::Line;
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::query::{intersect_curves, intersect_surfaces, offset_curve};
use splinekit::surface::BSplineSurface;
use splinekit::surface::derived::RevolvedSurface;
use splinekit::surface::model::Plane;
use splinekit::surface::model::Torus;
use splinekit_mesh::export::{GltfGeometry, GltfObject, GltfScene};
use splinekit_mesh::surface_mesh::regular;
use splinekit_mesh::{MeshOptions, Polyline, Projection, SvgFigure};
use splinekit_render::{Camera, Image, LineItem, MeshItem, RenderScene, Renderer};
use splinekit_scene::ShapeDocument;
use std::f64::consts::TAU;

use super::figures::Figure;

const W: f64 = 640.0;
const H: f64 = 480.0;
const PALETTE: [&str; 6] = ["#1f5fbf", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"];

fn draw<const D: usize>(fig: &mut SvgFigure, c: &dyn Curve<D>, colour: &str, width: f64) -> Result<()> {
    let poly = Polyline::adaptive(c, 1e-3)?;
    fig.path(&poly.points, poly.closed, colour, width);
    Ok(())
}

/// Two wavy cubic B-splines and every crossing of them.
pub fn crossings() -> Result<Figure> {
    let a: Vec<Point<2>> = (0..40).map(|i| Point::<2>::new(0.25 * i as f64, (0.7 * i as f64).sin())).collect();
    let b: Vec<Point<2>> = (0..40).map(|i| Point::<2>::new(0.25 * i as f64, 0.8 * (0.45 * i as f64).cos())).collect();
    let (a, b) = (BSplineCurve::clamped_uniform(3, a)?, BSplineCurve::clamped_uniform(3, b)?);
    let found = intersect_curves(&a, &b, 1e-9)?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Crossings of two cubic B-splines");
    draw(&mut fig, &a, PALETTE[0], 2.0)?;
    draw(&mut fig, &b, PALETTE[2], 2.0)?;
    let points: Vec<Point<2>> = found.points.iter().map(|p| p.point).collect();
    fig.dots(&points, 4.0, PALETTE[1]);
    Ok(Figure {
        file: "crossings.svg",
        caption: format!(
            "Every crossing of two cubic B-splines with 40 control points each ({} points, red): subdivision of their \
             Hermite covers with box and tangent-cone tests, then Newton's method to full precision.",
            points.len()
        ),
        svg: fig.render()?,
    })
}

/// The blending-spline heart of examples/ and its offsets at ±0.4, ±0.8, ±1.2.
pub fn heart_offsets() -> Result<Figure> {
    let text = include_str!("../../../../examples/shapes/beating_heart.json");
    let ShapeDocument::Curve(doc) = ShapeDocument::from_json(text)? else {
        return Err(anyhow!("beating_heart.json: expected a curve"));
    };
    let heart = doc.build_in::<3>()?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Offsets of the heart");
    let mut worst = 0.0f64;
    for (k, d) in [-1.2, -0.8, -0.4, 0.4, 0.8, 1.2].iter().enumerate() {
        let off = offset_curve(heart.as_ref(), *d, Some(Point::<3>::z()), 1e-4)?;
        worst = worst.max(off.max_error);
        for piece in &off.pieces {
            draw(&mut fig, &piece.curve, PALETTE[if *d < 0.0 { 0 } else { 2 }], 1.2 + 0.1 * k as f64)?;
        }
    }
    draw(&mut fig, heart.as_ref(), PALETTE[1], 2.5)?;
    Ok(Figure {
        file: "heart_offsets.svg",
        caption: format!(
            "The blending-spline heart (red) and its offsets at distances 0.4, 0.8, 1.2 outside (blue) and inside (green): \
             cubic B-splines within 10⁻⁴ of c + d·n (largest error {worst:.1e}), the swallowtails behind the cusps of the \
             raw offset and its self-intersections trimmed; the pieces end on the normals at the heart's two corners."
        ),
        svg: fig.render()?,
    })
}

/// Contours of a wavy bicubic patch: its sections with planes z = const.
pub fn contours() -> Result<Figure> {
    let net: Vec<Vec<Point<3>>> = (0..8)
        .map(|i| (0..8).map(|j| Point::<3>::new(i as f64, j as f64, (i as f64).sin() * (j as f64).cos())).collect())
        .collect();
    let s = BSplineSurface::clamped_uniform((3, 3), net)?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Contours of a bicubic patch");
    let levels = [-0.45, -0.3, -0.15, 0.0, 0.15, 0.3, 0.45];
    let mut branches = 0;
    for (k, z) in levels.iter().enumerate() {
        let plane = Plane::new(
            Point::<3>::new(-10.0, -10.0, *z),
            Point::<3>::new(30.0, 0.0, 0.0),
            Point::<3>::new(0.0, 30.0, 0.0),
        )?;
        for b in intersect_surfaces(&s, &plane, 1e-9, 1e-3)? {
            fig.path(&b.points, b.closed, PALETTE[k % PALETTE.len()], 1.8);
            branches += 1;
        }
    }
    let outline: Vec<Point<3>> =
        [(0.0, 0.0), (7.0, 0.0), (7.0, 7.0), (0.0, 7.0)].iter().map(|&(x, y)| Point::<3>::new(x, y, 0.0)).collect();
    fig.dashed(&outline, true, "#999999", 1.0);
    Ok(Figure {
        file: "contours.svg",
        caption: format!(
            "Contours of the bicubic patch z ≈ sin i cos j (8 × 8 control points) at seven heights from −0.45 to 0.45, seen from \
             above: {branches} branches of its intersections with planes, by seeded marching (what `splinekit section --levels` prints)."
        ),
        svg: fig.render()?,
    })
}

/// A rendered figure: file stem, caption, picture, glb bytes.
pub type Rendered = (String, String, Image, Vec<u8>);

/// A torus (R 3, r 1) pierced by a cylinder of radius 0.5 about x = 3 through its tube, with
/// the two loops of their intersection curve drawn over both (shaded offscreen).
pub fn torus_cylinder(renderer: &Renderer) -> Result<Rendered> {
    let torus = Torus::new(3.0, 1.0)?;
    let line = Line::new(Point::<3>::new(3.5, 0.0, -1.6), Point::<3>::new(3.5, 0.0, 1.6))?;
    let cylinder =
        RevolvedSurface::new(Box::new(line), Point::<3>::new(3.0, 0.0, 0.0), Point::<3>::new(0.0, 0.0, 1.0), TAU)?;
    let branches = intersect_surfaces(&torus, &cylinder, 1e-9, 1e-5)?;
    let f = |v: &[[f64; 3]]| v.iter().map(|p| p.map(|x| x as f32)).collect::<Vec<_>>();
    let mut scene = RenderScene::default();
    let mut gltf = GltfScene::default();
    for (name, mut mesh, color, cut) in [
        ("torus", regular(&torus, 240, 120, MeshOptions::default())?, [0.86, 0.72, 0.4, 1.0], true),
        ("cylinder", regular(&cylinder, 48, 96, MeshOptions::default())?, [0.3, 0.55, 0.85, 1.0], false),
    ] {
        if cut {
            // The ring of the torus is cut open along the meridians u = π and u = −0.22
            // (the camera's side, in front of the cylinder at u = 0): the open tube shows
            // the cylinder inside it and both loops, the upper one where the cylinder
            // leaves the tube and the lower one where it enters.
            let uv = &mesh.uvs;
            mesh.triangles
                .retain(|t| t.iter().all(|&i| uv[i as usize][0] <= 0.5 || uv[i as usize][0] >= 1.0 - 0.22 / TAU));
        }
        scene.meshes.push(MeshItem {
            positions: f(&mesh.positions),
            normals: f(&mesh.normals),
            color,
            triangles: mesh.triangles.clone(),
            ..Default::default()
        });
        gltf.objects.push(GltfObject {
            name: name.to_string(),
            geometry: GltfGeometry::Mesh(mesh),
            color,
            frames: vec![],
        });
    }
    let mut points = 0;
    for b in &branches {
        let pts = b.points.iter().map(|p| [p.x as f32, p.y as f32, p.z as f32]).collect();
        let red = [0.8, 0.05, 0.05, 1.0];
        scene.lines.push(LineItem { points: pts, closed: b.closed, color: red, width: 5.0 });
        let strip = b.points.iter().map(|p| [p.x, p.y, p.z]).collect();
        gltf.objects.push(GltfObject {
            name: "loop".to_string(),
            geometry: GltfGeometry::LineStrip(strip),
            color: red,
            frames: vec![],
        });
        points += b.points.len();
    }
    // Framed on the cylinder and the tube around it.
    scene.camera = Some(Camera::fit(([0.6, -1.5, -1.7], [5.4, 1.5, 1.7]), -1.2, 0.35, 4.0 / 3.0));
    let img = renderer.render(&scene, 800, 600)?;
    let closed = branches.iter().filter(|b| b.closed).count();
    let caption = format!(
        "A torus (R = 3, r = 1, cut open in front) pierced through its tube by a cylinder of radius 0.5, and the {} \
         loops of their intersection curve (red; {closed} closed, {points} points within 10⁻⁵ of the curve): seeds by \
         subdividing pairs of patches until their normals cannot be parallel, then marching (what `splinekit \
         intersect` prints for two surfaces).",
        branches.len()
    );
    Ok(("torus_cylinder".to_string(), caption, img, gltf.to_glb()?))
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_query_figures_draw_their_answers() {
        for f in [super::crossings().unwrap(), super::heart_offsets().unwrap(), super::contours().unwrap()] {
            assert!(f.svg.contains("<path") && f.svg.len() > 1000, "{}", f.file);
        }
    }
}
