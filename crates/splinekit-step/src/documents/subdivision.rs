//! `subdivision_surface` documents in STEP: the Catmull–Clark or Loop limit surface as one
//! Bézier surface per patch ([`limit_patches_within`]): exact bicubic patches on regular
//! quads, exact (4, 4) patches with one collapsed edge on regular Loop triangles, and
//! around extraordinary vertices (and creases, and Loop boundaries) faces refined locally
//! until regular, the last face at each extraordinary vertex a bilinear patch through limit
//! points (a flat triangle, one edge collapsed, for Loop). The bilinear scheme's limit is
//! its faces, written as bilinear patches. Each irregular face takes the fewest levels (1 to [`MAX_DEPTH`]) whose stand-in
//! is within the tolerance (relative to the cage's bounding-box diagonal) of the exact limit
//! on a 9 × 9 grid of its parameters; a tolerance that 30 levels do not reach is refused
//! with the one they do.

use splinekit::Point;
use splinekit::query::Aabb;
use splinekit::subdivision::surface::SubdivisionSurface;
use splinekit::subdivision::surface::bezier_patches::{LimitPatches, limit_patches_within};
use splinekit_scene::surfaces::{BezierSurfaceDoc, SubdivisionSurfaceDoc};
use splinekit_scene::{SceneDocument, SceneObject, SceneOrShape, ShapeDocument, SurfaceDocument};

use crate::error::{Result, StepError};

/// Most levels of local refinement at extraordinary vertices (each adds three exact
/// patches per stand-in and multiplies its deviation by about the subdominant eigenvalue,
/// 0.41 at valence 3).
pub use splinekit::subdivision::surface::bezier_patches::MAX_DEPTH;

/// The patches as `bezier_surface` documents (bicubic, quartic, then the bilinear stand-ins).
pub fn patch_shapes(p: &LimitPatches) -> Vec<ShapeDocument> {
    let a = |q: &Point<3>| vec![q.x, q.y, q.z];
    let bezier =
        |control_points| ShapeDocument::Surface(SurfaceDocument::BezierSurface(BezierSurfaceDoc { control_points }));
    let mut shapes = Vec::with_capacity(p.bicubic.len() + p.quartic.len() + p.bilinear.len());
    for b in &p.bicubic {
        shapes.push(bezier(b.iter().map(|row| row.iter().map(a).collect()).collect()));
    }
    for b in &p.quartic {
        shapes.push(bezier(b.iter().map(|row| row.iter().map(a).collect()).collect()));
    }
    for q in &p.bilinear {
        shapes.push(bezier(vec![vec![a(&q[0]), a(&q[3])], vec![a(&q[1]), a(&q[2])]]));
    }
    shapes
}

/// The patches as a scene of `bezier_surface` objects.
pub fn patches_scene(p: &LimitPatches) -> Option<SceneDocument> {
    let shapes = patch_shapes(p);
    let mut scene = SceneDocument::of_shape(shapes.first()?.clone());
    let style = scene.objects[0].clone();
    scene.objects = shapes.into_iter().map(|shape| SceneObject { shape, instance_of: None, ..style.clone() }).collect();
    Some(scene)
}

/// The patches of a document's limit surface within `relative_tolerance`, and the depth
/// (the deepest level of a stand-in).
pub fn subdivision_patches(doc: &SubdivisionSurfaceDoc, relative_tolerance: f64) -> Result<(LimitPatches, usize)> {
    let s = doc.subdivision_surface().map_err(|e| StepError::plain(e.to_string()))?;
    surface_patches(&s, relative_tolerance)
}

/// The patches of a Catmull–Clark or Loop surface within `relative_tolerance` of its
/// cage's bounding-box diagonal (the bilinear scheme: its faces, exactly), and the depth
/// (the deepest level of a stand-in); refuses a tolerance that [`MAX_DEPTH`] levels do
/// not reach, naming the one they do.
pub fn surface_patches(s: &SubdivisionSurface, relative_tolerance: f64) -> Result<(LimitPatches, usize)> {
    if !(relative_tolerance > 0.0 && relative_tolerance.is_finite()) {
        return Err(StepError::plain(format!("tolerance: must be finite and > 0, got {relative_tolerance}")));
    }
    let size = Aabb::around(&s.cage().vertices, 0.0).diagonal();
    if size == 0.0 {
        return Err(StepError::plain("vertices: the cage has no extent (all its vertices coincide)"));
    }
    let tolerance = relative_tolerance * size;
    let patches = limit_patches_within(s, tolerance).map_err(|e| StepError::plain(e.to_string()))?;
    if patches.max_deviation > tolerance {
        let (reached, relative) = (patches.max_deviation, patches.max_deviation / size);
        // Rounded up to two digits, so that asking for it succeeds.
        let unit = 10f64.powf(relative.log10().floor() - 1.0);
        let reachable = (relative / unit).ceil() * unit;
        return Err(StepError::plain(format!(
            "tolerance: the patches at extraordinary vertices come within {reached:.3e} of the limit after {MAX_DEPTH} levels ({relative:.2e} of the cage's size), not {tolerance:.3e} (relative {relative_tolerance:.1e}): ask for a relative tolerance of at least {reachable:.1e}"
        )));
    }
    let depth = patches.depth();
    Ok((patches, depth))
}

/// The document with every `subdivision_surface` (a shape, or a scene's object) replaced by
/// its patches (objects keeping the style of theirs); other documents as they are.
pub fn expand_subdivision_surfaces(doc: &SceneOrShape, relative_tolerance: f64) -> Result<SceneOrShape> {
    let patches = |d: &SubdivisionSurfaceDoc| -> Result<Vec<ShapeDocument>> {
        Ok(patch_shapes(&subdivision_patches(d, relative_tolerance)?.0))
    };
    Ok(match doc {
        SceneOrShape::Shape(ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(d))) => {
            let mut scene =
                SceneDocument::of_shape(ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(d.clone())));
            scene.objects = patches(d)?
                .into_iter()
                .map(|shape| SceneObject { shape, instance_of: None, ..scene.objects[0].clone() })
                .collect();
            SceneOrShape::Scene(scene)
        }
        SceneOrShape::Scene(scene) => {
            let mut out = scene.clone();
            out.objects.clear();
            for (i, o) in scene.objects.iter().enumerate() {
                match &o.shape {
                    ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(d)) => {
                        let pieces =
                            patches(d).map_err(|e| StepError::plain(format!("objects[{i}]: {}", e.message)))?;
                        out.objects.extend(pieces.into_iter().map(|shape| SceneObject {
                            shape,
                            instance_of: None,
                            ..o.clone()
                        }));
                    }
                    _ => out.objects.push(o.clone()),
                }
            }
            SceneOrShape::Scene(out)
        }
        other => other.clone(),
    })
}
