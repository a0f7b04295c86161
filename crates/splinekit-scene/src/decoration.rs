//! What a scene draws besides a shape when its style asks for control nets (`control_net`)
//! or local pieces (`local_pieces`): one enum over both families, made of what each kind
//! declares in its family's terms ([`CurveDecoration`], [`SurfaceDecoration`]), so that a
//! scene, the renderer and editors handle curves and surfaces alike.

use crate::curves::{BlendingSplineDoc, CurveDecoration, CurveDocument};
use crate::surfaces::{BlendingSplineSurfaceDoc, LocalPieces, SurfaceDecoration, SurfaceDocument};

/// What a scene draws besides a shape (see the [module](self)).
#[derive(Debug, Clone, Copy)]
pub enum Decoration<'a> {
    /// Nothing besides the shape.
    None,
    /// A control polygon (curves from control points or interpolated points).
    ControlPolygon {
        /// The points, each of 1 to 4 coordinates.
        points: &'a [Vec<f64>],
        /// The document field that holds them (`control_points`, or `points` of
        /// interpolating kinds), for editors that move them.
        field: &'static str,
        /// Whether the last point joins the first.
        closed: bool,
    },
    /// A control net, rows along u.
    ControlNet(&'a [Vec<Vec<f64>>]),
    /// The local curves of a blending-spline curve.
    LocalCurves(&'a BlendingSplineDoc),
    /// The local patches of a blending-spline surface.
    LocalPatches(&'a BlendingSplineSurfaceDoc),
    /// The polygon cage of a subdivision surface: its vertices and faces (vertex indices).
    Cage {
        /// The vertices, 3-D.
        vertices: &'a [Vec<f64>],
        /// The faces.
        faces: &'a [Vec<u32>],
    },
    /// The triangular control net of a Bézier triangle (b_n00 first, then rows of falling i,
    /// each by falling j: row r holds r + 1 points).
    TriangularNet {
        /// The points in storage order.
        points: &'a [Vec<f64>],
        /// The document field that holds them, for editors that move them.
        field: &'static str,
    },
    /// The local pieces of a GERBS triangle or a blending triangulation.
    LocalPieces(&'a dyn LocalPieces),
}

impl<'a> From<CurveDecoration<'a>> for Decoration<'a> {
    fn from(d: CurveDecoration<'a>) -> Self {
        match d {
            CurveDecoration::None => Decoration::None,
            CurveDecoration::ControlPolygon { points, field, closed } => {
                Decoration::ControlPolygon { points, field, closed }
            }
            CurveDecoration::LocalCurves(doc) => Decoration::LocalCurves(doc),
        }
    }
}

impl<'a> From<SurfaceDecoration<'a>> for Decoration<'a> {
    fn from(d: SurfaceDecoration<'a>) -> Self {
        match d {
            SurfaceDecoration::None => Decoration::None,
            SurfaceDecoration::ControlNet(net) => Decoration::ControlNet(net),
            SurfaceDecoration::LocalPatches(doc) => Decoration::LocalPatches(doc),
            SurfaceDecoration::Cage { vertices, faces } => Decoration::Cage { vertices, faces },
            SurfaceDecoration::TriangularNet { points, field } => Decoration::TriangularNet { points, field },
            SurfaceDecoration::LocalPieces(d) => Decoration::LocalPieces(d),
        }
    }
}

impl CurveDocument {
    /// What a scene may draw besides the curve.
    pub fn decoration(&self) -> Decoration<'_> {
        self.family_decoration().into()
    }
}

impl SurfaceDocument {
    /// What a scene may draw besides the surface.
    pub fn decoration(&self) -> Decoration<'_> {
        self.family_decoration().into()
    }
}
