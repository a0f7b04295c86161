//! The `subdivision_surface` document: a polygon cage (inline, or read from an OBJ file by
//! the loaders, see [`crate::cage_file`]), a scheme, creases and the boundary rule; the shape
//! is the exact limit surface over its atlas of unit charts
//! ([`LimitAtlas`]: chart c over u ∈ [c, c + 1], v ∈ [0, 1]; for a cage of quads chart c is
//! face c).

use serde::{Deserialize, Serialize};
use splinekit::Point;
use splinekit::subdivision::surface::{
    BoundaryRule, Cage, Crease, INFINITE_SHARPNESS, LimitAtlas, Scheme, SubdivisionSurface,
};
use splinekit::surface::Surface;

use super::{SurfaceDecoration, SurfaceForm, Surfaces};
use crate::budget::{F64, ShapeCost};
use crate::defaults::is_false;
use crate::dimension::same_type;
use crate::error::{DocumentError, Result};
use crate::points::dimension_of;
use crate::registry::DocumentKind;

/// The subdivision scheme of a document.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SchemeDoc {
    /// Catmull–Clark (any polygons).
    #[default]
    CatmullClark,
    /// Loop (triangles, or polygons with `triangulate`).
    Loop,
    /// Bilinear.
    Bilinear,
}

/// The boundary rule of a document.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BoundaryDoc {
    /// Boundary vertices take the crease rule.
    #[default]
    EdgeOnly,
    /// Boundary vertices of a single face are corners.
    EdgeAndCorner,
}

/// One creased edge: `{"edge": [a, b], "sharpness": s}` (s ≥ 10 infinitely sharp, the default).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CreaseDoc {
    /// The edge's two vertices (0-based).
    pub edge: [u32; 2],
    /// Sharpness s ≥ 0 (default 10: infinitely sharp).
    #[serde(default = "infinite")]
    pub sharpness: f64,
}

fn infinite() -> f64 {
    INFINITE_SHARPNESS
}

fn is_default<T: Default + PartialEq>(x: &T) -> bool {
    *x == T::default()
}

/// `{"type":"subdivision_surface","vertices":[[x,y,z],…],"faces":[[i,j,k,l],…],
/// "scheme":"catmull-clark","creases":[{"edge":[a,b],"sharpness":s}],"boundary":"edge-only"}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubdivisionSurfaceDoc {
    /// The cage's vertices (3-D); empty when `obj` names the cage file.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub vertices: Vec<Vec<f64>>,
    /// The faces, each 3 or more 0-based vertex indices, counter-clockwise seen from outside.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub faces: Vec<Vec<u32>>,
    /// An OBJ file holding the cage (`v`, `f` and `t crease` lines), relative to the
    /// document's folder; read by the loaders in place of `vertices` and `faces`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub obj: Option<String>,
    /// The scheme (default Catmull–Clark).
    #[serde(default, skip_serializing_if = "is_default")]
    pub scheme: SchemeDoc,
    /// Creased edges (default none).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub creases: Vec<CreaseDoc>,
    /// The boundary rule (default edge-only).
    #[serde(default, skip_serializing_if = "is_default")]
    pub boundary: BoundaryDoc,
    /// Loop only: split polygons into triangle fans first (default false).
    #[serde(default, skip_serializing_if = "is_false")]
    pub triangulate: bool,
}

impl SubdivisionSurfaceDoc {
    /// The kernel's subdivision surface, its cage checked (errors name `vertices[i]`,
    /// `faces[f]`, `creases[k]`).
    pub fn subdivision_surface(&self) -> Result<SubdivisionSurface> {
        self.dimension()?;
        let vertices: Vec<Point<3>> = self.vertices.iter().map(|p| Point::<3>::from_column_slice(p)).collect();
        let creases =
            self.creases.iter().map(|c| Crease { a: c.edge[0], b: c.edge[1], sharpness: c.sharpness }).collect();
        let boundary = match self.boundary {
            BoundaryDoc::EdgeOnly => BoundaryRule::EdgeOnly,
            BoundaryDoc::EdgeAndCorner => BoundaryRule::EdgeAndCorner,
        };
        let scheme = match self.scheme {
            SchemeDoc::CatmullClark => Scheme::CatmullClark,
            SchemeDoc::Loop => Scheme::Loop,
            SchemeDoc::Bilinear => Scheme::Bilinear,
        };
        let cage = Cage::new(vertices, &self.faces).with_creases(creases).with_boundary(boundary);
        Ok(SubdivisionSurface::new(cage, scheme, self.triangulate)?)
    }

    /// The limit surface over its atlas.
    pub fn atlas(&self) -> Result<LimitAtlas> {
        Ok(LimitAtlas::new(self.subdivision_surface()?))
    }

    /// The unit cube [−1, 1]³, faces counter-clockwise seen from outside.
    pub fn cube() -> Self {
        let cage = Cage::cube();
        let vertices = cage.vertices.iter().map(|p| vec![p.x, p.y, p.z]).collect();
        let faces = (0..cage.face_count()).map(|f| cage.face(f).to_vec()).collect();
        SubdivisionSurfaceDoc {
            vertices,
            faces,
            obj: None,
            scheme: SchemeDoc::CatmullClark,
            creases: Vec::new(),
            boundary: BoundaryDoc::EdgeOnly,
            triangulate: false,
        }
    }
}

impl DocumentKind for SubdivisionSurfaceDoc {
    type Family = Surfaces;
    fn dimension(&self) -> Result<usize> {
        if self.vertices.is_empty()
            && let Some(path) = &self.obj
        {
            return Err(DocumentError::new(
                "obj",
                format!(
                    "the cage file '{path}' is read only when the document is read from a file (or give \"vertices\" and \"faces\")"
                ),
            ));
        }
        let d = dimension_of("vertices", &self.vertices)?;
        if d != 3 {
            return Err(DocumentError::new("vertices[0]", format!("a cage's vertices are 3-D, got {d} coordinates")));
        }
        Ok(3)
    }
    /// Building: the half-edge adjacency, linear in the cage. An evaluation: the 1-ring of
    /// a face, subdivided locally near extraordinary vertices (a few thousand operations).
    fn cost(&self) -> ShapeCost {
        let corners: f64 = self.faces.iter().map(|f| f.len() as f64).sum();
        let n = self.vertices.len() as f64;
        ShapeCost::new("faces", n * 3.0 * F64 + corners * 64.0, corners * 200.0 + n * 50.0, 5000.0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let atlas: Box<dyn Surface<3>> = Box::new(self.atlas()?);
        same_type(atlas).ok_or_else(|| DocumentError::new("vertices", "a subdivision surface is 3-D"))
    }
    /// The cube [−1, 1]³ under Catmull–Clark (corners' limit at (±½, ±½, ±½)).
    fn example() -> Self {
        Self::cube()
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::Cage { vertices: &self.vertices, faces: &self.faces }
    }
    fn set_time(&mut self, _time: f64) {}
    /// A cage holds vertices and faces, not a control net.
    fn spline(&self) -> Option<crate::views::NetView<'_>> {
        None
    }
    /// The limit is piecewise bicubic only on regular faces; exporters write its patches
    /// (STEP: `export_document`) or approximate it.
    fn exact_form(&self) -> Result<SurfaceForm<'_>> {
        Ok(SurfaceForm::Approximate)
    }
    const BLENDING_MODEL: bool = false;
}
