//! The gallery's figures of geometric queries: crossings of two curves, the offsets of the
//! heart, and contours (plane sections) of a surface.

use anyhow::{Result, anyhow};
use splinekit::Point;
use splinekit::curve::model::Line;
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::query::{IntersectionBranch, intersect_curves, intersect_surfaces, offset_curve};
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

/// The two wavy cubic B-splines (40 control points each) of [`crossings`].
fn wavy_pair() -> Result<(BSplineCurve<2>, BSplineCurve<2>)> {
    let a: Vec<Point<2>> = (0..40).map(|i| Point::<2>::new(0.25 * i as f64, (0.7 * i as f64).sin())).collect();
    let b: Vec<Point<2>> = (0..40).map(|i| Point::<2>::new(0.25 * i as f64, 0.8 * (0.45 * i as f64).cos())).collect();
    Ok((BSplineCurve::clamped_uniform(3, a)?, BSplineCurve::clamped_uniform(3, b)?))
}

/// Two wavy cubic B-splines and every crossing of them.
pub fn crossings() -> Result<Figure> {
    let (a, b) = wavy_pair()?;
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

/// The distances of the heart's offsets, drawn with stroke width 1.2 + 0.1·(index).
const HEART_DISTANCES: [f64; 6] = [-1.2, -0.8, -0.4, 0.4, 0.8, 1.2];

/// The blending-spline heart of examples/ and its offsets at ±0.4, ±0.8, ±1.2.
pub fn heart_offsets() -> Result<Figure> {
    let text = include_str!("../../../../examples/shapes/beating_heart.json");
    let ShapeDocument::Curve(doc) = ShapeDocument::from_json(text)? else {
        return Err(anyhow!("beating_heart.json: expected a curve"));
    };
    let heart = doc.build_in::<3>()?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Offsets of the heart");
    let mut worst = 0.0f64;
    for (k, d) in HEART_DISTANCES.iter().enumerate() {
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

/// The heights of the contours of [`contours`].
const CONTOUR_LEVELS: [f64; 7] = [-0.45, -0.3, -0.15, 0.0, 0.15, 0.3, 0.45];

/// The contours' patch z ≈ sin i cos j (8 × 8 control points).
fn contour_patch() -> Result<BSplineSurface<3>> {
    let net: Vec<Vec<Point<3>>> = (0..8)
        .map(|i| (0..8).map(|j| Point::<3>::new(i as f64, j as f64, (i as f64).sin() * (j as f64).cos())).collect())
        .collect();
    Ok(BSplineSurface::clamped_uniform((3, 3), net)?)
}

/// The patch's section with the plane at height z.
fn section(s: &BSplineSurface<3>, z: f64) -> Result<Vec<IntersectionBranch>> {
    let o = Point::<3>::new(-10.0, -10.0, z);
    let plane = Plane::new(o, Point::<3>::new(30.0, 0.0, 0.0), Point::<3>::new(0.0, 30.0, 0.0))?;
    Ok(intersect_surfaces(s, &plane, 1e-9, 1e-3)?)
}

/// Contours of a wavy bicubic patch: its sections with planes z = const.
pub fn contours() -> Result<Figure> {
    let s = contour_patch()?;
    let mut fig = SvgFigure::new(W, H, Projection::TOP).title("Contours of a bicubic patch");
    let mut branches = 0;
    for (k, z) in CONTOUR_LEVELS.iter().enumerate() {
        for b in section(&s, *z)? {
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

/// A rendered figure: file stem, caption, picture, glb bytes, the picture's camera.
pub type Rendered = (String, String, Image, Vec<u8>, Camera);

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
        scene.lines.push(LineItem { points: pts, closed: b.closed, color: red, width: 5.0, colors: Vec::new() });
        let strip = b.points.iter().map(|p| [p.x, p.y, p.z]).collect();
        gltf.objects.push(GltfObject {
            name: "loop".to_string(),
            geometry: GltfGeometry::LineStrip(strip),
            color: red,
            frames: vec![],
        });
        points += b.points.len();
    }
    // Framed on what is drawn: the half of the ring left (u from −0.22 to π: x from −4 to
    // 4, y from −0.9 to 4) and the cylinder, seen from the front right and above.
    let camera = Camera::fit(([-4.0, -0.9, -1.6], [4.0, 4.0, 1.6]), -1.0, 0.4, 4.0 / 3.0);
    scene.camera = Some(camera);
    let img = renderer.render(&scene, 800, 600)?;
    let closed = branches.iter().filter(|b| b.closed).count();
    let caption = format!(
        "A torus (R = 3, r = 1, cut open in front) pierced through its tube by a cylinder of radius 0.5, and the {} \
         loops of their intersection curve (red; {closed} closed, {points} points within 10⁻⁵ of the curve): seeds by \
         subdividing pairs of patches until their normals cannot be parallel, then marching (what `splinekit \
         intersect` prints for two surfaces).",
        branches.len()
    );
    Ok(("torus_cylinder".to_string(), caption, img, gltf.to_glb()?, camera))
}

#[cfg(test)]
mod tests {
    use super::*;
    use splinekit::query::Aabb;

    /// A drawn polyline: its points in picture coordinates, stroke and width.
    struct Drawn {
        points: Vec<[f64; 2]>,
        stroke: String,
        width: f64,
        dashed: bool,
    }

    fn attribute<'a>(element: &'a str, name: &str) -> &'a str {
        let start =
            element.find(&format!(" {name}=\"")).unwrap_or_else(|| panic!("no {name} in {element}")) + name.len() + 3;
        &element[start..start + element[start..].find('"').unwrap()]
    }

    /// The paths and the dots (circle centres) of an SVG written by `SvgFigure`.
    fn parse(svg: &str) -> (Vec<Drawn>, Vec<[f64; 2]>) {
        let (mut paths, mut dots) = (Vec::new(), Vec::new());
        for line in svg.lines() {
            if line.starts_with("<path") {
                let points = attribute(line, "d")
                    .split_whitespace()
                    .filter(|t| *t != "Z")
                    .map(|t| {
                        let (x, y) = t[1..].split_once(',').unwrap();
                        [x.parse().unwrap(), y.parse().unwrap()]
                    })
                    .collect();
                let (stroke, width) =
                    (attribute(line, "stroke").to_string(), attribute(line, "stroke-width").parse().unwrap());
                paths.push(Drawn { points, stroke, width, dashed: line.contains("stroke-dasharray") });
            } else if line.starts_with("<circle") {
                dots.push([attribute(line, "cx").parse().unwrap(), attribute(line, "cy").parse().unwrap()]);
            }
        }
        (paths, dots)
    }

    /// The distance from q to the polyline (picture coordinates).
    fn distance(q: &[f64; 2], line: &[[f64; 2]]) -> f64 {
        line.windows(2)
            .map(|w| {
                let (d, r) = ([w[1][0] - w[0][0], w[1][1] - w[0][1]], [q[0] - w[0][0], q[1] - w[0][1]]);
                let dd = d[0] * d[0] + d[1] * d[1];
                let s = if dd > 0.0 { ((r[0] * d[0] + r[1] * d[1]) / dd).clamp(0.0, 1.0) } else { 0.0 };
                (r[0] - s * d[0]).hypot(r[1] - s * d[1])
            })
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn every_crossing_is_marked_on_both_drawn_curves() {
        let (a, b) = wavy_pair().unwrap();
        let expected = intersect_curves(&a, &b, 1e-9).unwrap().points.len();
        let (paths, dots) = parse(&crossings().unwrap().svg);
        assert!(expected > 5 && dots.len() == expected, "{} dots for {expected} crossings", dots.len());
        assert_eq!(paths.len(), 2);
        for q in &dots {
            // Picture coordinates have two decimals; the drawn polylines are within 10⁻³
            // of the curves, a fraction of a pixel at this scale.
            for p in &paths {
                assert!(distance(q, &p.points) < 0.5, "the dot at {q:?} is {} px off a curve", distance(q, &p.points));
            }
        }
    }

    #[test]
    fn each_drawn_offset_of_the_heart_keeps_its_distance_from_the_drawn_heart() {
        let (paths, _) = parse(&heart_offsets().unwrap().svg);
        let heart = paths.iter().find(|p| p.stroke == PALETTE[1]).expect("the heart is drawn in red");
        // Per distance: the pixel distances of the offset's points from the heart, which
        // must all be |d| at one scale (trimmed offsets are exactly |d| from the curve).
        let mut scales = Vec::new();
        for (k, d) in HEART_DISTANCES.iter().enumerate() {
            let width = 1.2 + 0.1 * k as f64;
            let pieces: Vec<&Drawn> =
                paths.iter().filter(|p| (p.width - width).abs() < 1e-9 && p.stroke != PALETTE[1]).collect();
            assert!(!pieces.is_empty(), "no offset drawn at d = {d}");
            assert!(pieces.iter().all(|p| p.stroke == PALETTE[if *d < 0.0 { 0 } else { 2 }]), "d = {d}: colour");
            let gaps: Vec<f64> =
                pieces.iter().flat_map(|p| p.points.iter().map(|q| distance(q, &heart.points))).collect();
            let (lo, hi) = gaps.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), g| (lo.min(*g), hi.max(*g)));
            assert!(hi - lo < 1.5, "d = {d}: the offset is {lo} to {hi} px from the heart");
            scales.push(0.5 * (lo + hi) / d.abs());
        }
        let (lo, hi) = scales.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), s| (lo.min(*s), hi.max(*s)));
        assert!(hi / lo < 1.03, "pixels per unit differ between the offsets: {scales:?}");
    }

    #[test]
    fn every_contour_is_drawn_inside_the_patch_outline() {
        let s = contour_patch().unwrap();
        let expected: usize = CONTOUR_LEVELS.iter().map(|z| section(&s, *z).unwrap().len()).sum();
        let (paths, _) = parse(&contours().unwrap().svg);
        let outline: Vec<&Drawn> = paths.iter().filter(|p| p.dashed).collect();
        assert_eq!(outline.len(), 1);
        let outline_box = Aabb::spanning(outline[0].points.iter().map(|q| Point::<2>::from(*q))).expect("an outline");
        let contours: Vec<&Drawn> = paths.iter().filter(|p| !p.dashed).collect();
        assert!(
            expected > CONTOUR_LEVELS.len() && contours.len() == expected,
            "{} paths, {expected} branches",
            contours.len()
        );
        for q in contours.iter().flat_map(|p| &p.points) {
            assert!(outline_box.contains(&Point::<2>::from(*q), 0.01), "{q:?} is outside the patch");
        }
    }
}
