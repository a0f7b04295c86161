//! Surface shape documents: the surface family — the registry of its kinds, its marker
//! [`Surfaces`], and what its kinds declare of themselves, [`SurfaceForm`] and
//! [`SurfaceDecoration`]. Those name kinds (a revolution's form is the document) while the
//! kinds, declared in this module's files, produce them: the family is one module. The
//! first index of a control net runs along u.
//!
//! Adding a surface kind is a document struct with its
//! [`DocumentKind`](crate::registry::DocumentKind) (for a model surface, one
//! `model_document!` declaration in `models.rs`) and one line in the list (see
//! CONTRIBUTING.md); the compiler asks for everything else.

mod blending;
mod brep;
mod from_curves;
mod hermite;
mod models;
mod nets;
mod placed;
mod sub_surface;
mod subdivision;
mod triangles;
mod trimmed;

use serde_json::Value;
use splinekit::surface::Surface;

pub use blending::{BlendingSplineSurfaceDoc, LocalPatchDoc};
pub use brep::{BrepDoc, BrepEdgeDoc, BrepFaceDoc, BrepShellDoc, BrepSolidDoc, BrepUseDoc};
pub use from_curves::{
    CoonsBlendDoc, CoonsDoc, ExtrusionDoc, HermiteCurveSurfaceDoc, LoftCrossDoc, LoftDoc, LoftParametersDoc,
    RevolutionDoc, RuledDoc, SweepDoc,
};
pub use hermite::BicubicHermiteDoc;
// Every document that `models.rs` declares, so that a model kind is its declaration and
// its line in the list below.
pub use models::*;
pub use nets::{BSplineSurfaceDoc, BezierSurfaceDoc, NurbsSurfaceDoc};
pub use placed::PlacedDoc;
pub use sub_surface::SubSurfaceDoc;
pub use subdivision::{BoundaryDoc, CreaseDoc, SchemeDoc, SubdivisionSurfaceDoc};
pub use triangles::{
    BezierTriangleDoc, BlendingTriangulationDoc, GerbsTriangleDoc, InterpolantDoc, LocalOrigin, LocalPieces, MeshDoc,
    SubTriangleDoc, TriangularFormDoc, TriangulationDoc, triangle_of,
};
pub use trimmed::TrimmedDoc;

use crate::dimension::{AnyDimension, ShapeFamily};
use crate::error::{DocumentError, Result};
use crate::json::split_type;
use crate::registry::ModelFamily;
use crate::views::NetView;

/// The registry of surface kinds: `surface_kinds!(callback)` calls the macro `callback` with the
/// list, in the syntax of `document_kinds!` (see [`crate::registry`]). This crate makes
/// the document enum of it; front ends make their per-kind code of it (the Python
/// classes), so that every kind appears in each of them.
///
/// Each line is `Variant(Doc) = "type", python(CLASS),` where CLASS is the kind's Python
/// class: `base` (the plain `Surface`), `own` (splinekit-py's hand-written class named
/// after the variant) or `fields "Name"` (a class `Name` whose constructor takes the
/// document's fields as keyword arguments).
#[macro_export]
macro_rules! surface_kinds {
    ($callback:path) => {
        $callback! {
            /// A surface shape document: `{"type": "…", …fields…}`.
            pub enum SurfaceDocument of Surfaces {
                /// Tensor-product Bézier surface.
                BezierSurface(BezierSurfaceDoc) = "bezier_surface", python(own),
                /// Tensor-product B-spline surface.
                BsplineSurface(BSplineSurfaceDoc) = "bspline_surface", python(own),
                /// NURBS surface.
                NurbsSurface(NurbsSurfaceDoc) = "nurbs_surface", python(own),
                /// Plane.
                Plane(PlaneDoc) = "plane", python(base),
                /// Cylinder.
                Cylinder(CylinderDoc) = "cylinder", python(base),
                /// Cone.
                Cone(ConeDoc) = "cone", python(base),
                /// Sphere.
                Sphere(SphereDoc) = "sphere", python(base),
                /// Torus.
                Torus(TorusDoc) = "torus", python(base),
                /// Möbius strip.
                Mobius(MobiusDoc) = "mobius", python(base),
                /// Figure-8 Klein bottle.
                KleinBottle(KleinBottleDoc) = "klein_bottle", python(base),
                /// Enneper's minimal surface.
                Enneper(EnneperDoc) = "enneper", python(base),
                /// Helicoid.
                Helicoid(HelicoidDoc) = "helicoid", python(base),
                /// Seashell.
                Seashell(SeashellDoc) = "seashell", python(base),
                /// Apple.
                Apple(AppleDoc) = "apple", python(base),
                /// The heart curve turned about its axis.
                HeartSurface(HeartSurfaceDoc) = "heart_surface", python(base),
                /// Dupin cyclide.
                DupinCyclide(DupinCyclideDoc) = "dupin_cyclide", python(fields "DupinCyclide"),
                /// Asteroidal sphere (the sphere cubed).
                AsteroidalSphere(AsteroidalSphereDoc) = "asteroidal_sphere", python(fields "AsteroidalSphere"),
                /// Bent horns.
                BentHorns(BentHornsDoc) = "bent_horns", python(fields "BentHorns"),
                /// Bohemian dome.
                BohemianDome(BohemianDomeDoc) = "bohemian_dome", python(fields "BohemianDome"),
                /// Boy's surface.
                BoySurface(BoySurfaceDoc) = "boy_surface", python(fields "BoySurface"),
                /// Cross-cap.
                CrossCap(CrossCapDoc) = "cross_cap", python(fields "CrossCap"),
                /// Dini's surface.
                DiniSurface(DiniSurfaceDoc) = "dini_surface", python(fields "DiniSurface"),
                /// Eight surface.
                EightSurface(EightSurfaceDoc) = "eight_surface", python(fields "EightSurface"),
                /// Inside-out (elliptic-tube) torus.
                InsideOutTorus(InsideOutTorusDoc) = "inside_out_torus", python(fields "InsideOutTorus"),
                /// Kuen's surface.
                KuenSurface(KuenSurfaceDoc) = "kuen_surface", python(fields "KuenSurface"),
                /// Sine surface.
                SineSurface(SineSurfaceDoc) = "sine_surface", python(fields "SineSurface"),
                /// Slippers surface.
                SlippersSurface(SlippersSurfaceDoc) = "slippers_surface", python(fields "SlippersSurface"),
                /// Steiner's Roman surface.
                RomanSurface(RomanSurfaceDoc) = "roman_surface", python(fields "RomanSurface"),
                /// Swallowtail.
                Swallowtail(SwallowtailDoc) = "swallowtail", python(fields "Swallowtail"),
                /// Trianguloid trefoil.
                TrianguloidTrefoil(TrianguloidTrefoilDoc) = "trianguloid_trefoil", python(fields "TrianguloidTrefoil"),
                /// Whitney umbrella.
                WhitneyUmbrella(WhitneyUmbrellaDoc) = "whitney_umbrella", python(fields "WhitneyUmbrella"),
                /// Surface of revolution.
                Revolution(RevolutionDoc) = "revolution", python(base),
                /// Ruled surface between two curves.
                Ruled(RuledDoc) = "ruled", python(base),
                /// Extrusion of a curve.
                Extrusion(ExtrusionDoc) = "extrusion", python(base),
                /// Coons patch of four boundary curves.
                Coons(CoonsDoc) = "coons", python(base),
                /// Sweep of a profile along a path.
                Sweep(SweepDoc) = "sweep", python(base),
                /// Bicubic patch of corner positions, partials and twists.
                BicubicHermite(BicubicHermiteDoc) = "bicubic_hermite", python(base),
                /// Hermite surface of two boundary and two cross-derivative curves.
                HermiteCurveSurface(HermiteCurveSurfaceDoc) = "hermite_curve_surface", python(base),
                /// Loft (skinning) through section curves.
                Loft(LoftDoc) = "loft", python(base),
                /// Trimmed surface.
                Trimmed(TrimmedDoc) = "trimmed", python(base),
                /// A surface moved rigidly into a frame.
                Placed(PlacedDoc) = "placed", python(base),
                /// A surface over a quadrilateral of another's domain.
                SubSurface(SubSurfaceDoc) = "sub_surface", python(base),
                /// Blending-spline surface.
                BlendingSplineSurface(BlendingSplineSurfaceDoc) = "blending_spline_surface", python(base),
                /// The limit surface of a subdivision cage.
                SubdivisionSurface(SubdivisionSurfaceDoc) = "subdivision_surface", python(base),
                /// Solids, shells and faces sharing their edges (a boundary representation).
                Brep(BrepDoc) = "brep", python(base),
                /// Bézier triangle (rational with weights).
                BezierTriangle(BezierTriangleDoc) = "bezier_triangle", python(fields "BezierTriangle"),
                /// The triangle S(u a + v b + w c) of a surface.
                SubTriangle(SubTriangleDoc) = "sub_triangle", python(fields "SubTriangle"),
                /// GERBS triangle: three framed local triangles blended by a triangular B-function.
                GerbsTriangle(GerbsTriangleDoc) = "gerbs_triangle", python(fields "GerbsTriangle"),
                /// Height field over a constrained Delaunay triangulation.
                Triangulation(TriangulationDoc) = "triangulation", python(fields "Triangulation"),
                /// Blending surface over a triangulated surface, one local per vertex.
                BlendingTriangulation(BlendingTriangulationDoc) = "blending_triangulation", python(fields "BlendingTriangulation"),
            }
        }
    };
}
crate::surface_kinds!(crate::registry::document_kinds);

/// The surface `type` names, for messages.
pub const SURFACE_TYPES: &[&str] = SurfaceDocument::TYPES;

impl SurfaceDocument {
    /// Parses a surface document, taking the JSON value.
    pub fn from_value(value: Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        Self::parse_fields(&ty, rest)
            .unwrap_or_else(|| Err(DocumentError::new("type", format!("expected a surface type, got \"{ty}\""))))
    }
}

/// Surfaces: `dyn Surface<D>`.
#[derive(Debug)]
pub enum Surfaces {}

impl ShapeFamily for Surfaces {
    type Shape<const D: usize> = dyn Surface<D>;
    type Spline<'a> = NetView<'a>;
    type Form<'a> = SurfaceForm<'a>;
    type Decoration<'a> = SurfaceDecoration<'a>;
}

/// A surface of a dimension known only at run time.
pub type AnySurface = AnyDimension<Surfaces>;

impl ModelFamily for Surfaces {
    fn not_3d(_name: &str) -> DocumentError {
        DocumentError::new("type", "model surfaces are 3-D")
    }
}

/// The exact form of a surface document: what it is in the classical vocabulary of
/// geometry (a spline, a plane, a quadric, a swept surface), declared by its kind in
/// [`DocumentKind::exact_form`](crate::registry::DocumentKind::exact_form).
///
/// Exporters write the form's own entity (STEP: `B_SPLINE_CURVE_WITH_KNOTS`, `CIRCLE`,
/// `TOROIDAL_SURFACE`, …) and approximate only `Approximate`; a new kind chooses among
/// these forms, so an exporter needs no edit for it. Every form has the document's
/// parametrisation up to the affine maps the exporter names.
#[derive(Debug, Clone)]
pub enum SurfaceForm<'a> {
    /// A B-spline, NURBS or Bézier net.
    Spline(NetView<'a>),
    /// origin + u U + v V, (u, v) ∈ [0, 1]².
    Plane {
        /// S(0, 0).
        origin: &'a [f64],
        /// U.
        u_axis: &'a [f64],
        /// V.
        v_axis: &'a [f64],
    },
    /// (r cos u, r sin u, h v), u ∈ [0, 2π], v ∈ [0, 1].
    Cylinder {
        /// r.
        radius: f64,
        /// h.
        height: f64,
    },
    /// (r (1 − v) cos u, r (1 − v) sin u, h v), u ∈ [0, 2π], v ∈ [0, 1].
    Cone {
        /// r.
        radius: f64,
        /// h.
        height: f64,
    },
    /// The sphere of radius r about the origin, u the longitude, v ∈ [−π/2, π/2] the latitude.
    Sphere {
        /// r.
        radius: f64,
    },
    /// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), (u, v) ∈ [0, 2π]².
    Torus {
        /// R.
        major_radius: f64,
        /// r.
        minor_radius: f64,
    },
    /// A curve turned about an axis.
    Revolution(&'a RevolutionDoc),
    /// A curve moved along a direction.
    Extrusion(&'a ExtrusionDoc),
    /// A surface cut by loops of curves.
    Trimmed(&'a TrimmedDoc),
    /// A surface moved rigidly into a frame.
    Placed(&'a PlacedDoc),
    /// A blending-spline surface: a B-spline when its locals are Bézier patches and its
    /// B-function a polynomial, else approximated.
    BlendingSpline(&'a BlendingSplineSurfaceDoc),
    /// A boundary representation: exporters write its faces with their shared edges.
    Brep(&'a BrepDoc),
    /// Several triangles (an atlas of them, see
    /// [`TriangleAtlas`](splinekit::triangle::TriangleAtlas)): exporters write one item
    /// per triangle, a Bézier triangle exactly as its degenerate tensor patch, others within
    /// a tolerance.
    Triangles,
    /// No exact form: exporters approximate the surface within a tolerance.
    Approximate,
}

/// What a scene draws besides a surface when its style asks for control nets
/// (`control_net`) or local pieces (`local_pieces`); scenes read it as a
/// [`Decoration`](crate::Decoration).
#[derive(Debug, Clone, Copy, Default)]
pub enum SurfaceDecoration<'a> {
    /// Nothing besides the surface.
    #[default]
    None,
    /// A control net, rows along u.
    ControlNet(&'a [Vec<Vec<f64>>]),
    /// The local patches of a blending-spline surface.
    LocalPatches(&'a BlendingSplineSurfaceDoc),
    /// The polygon cage of a subdivision surface: its vertices and faces (vertex indices).
    Cage {
        /// The vertices, 3-D.
        vertices: &'a [Vec<f64>],
        /// The faces.
        faces: &'a [Vec<u32>],
    },
    /// The triangular control net of a Bézier triangle, b_n00 first, then rows of falling i.
    TriangularNet {
        /// The points in storage order.
        points: &'a [Vec<f64>],
        /// The document field that holds them, for editors that move them.
        field: &'static str,
    },
    /// The local pieces of a blending kind of the triangle family (a `triangulation`'s
    /// Voronoi cells).
    LocalPieces(&'a dyn LocalPieces),
}
