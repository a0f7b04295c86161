//! `brep` documents: solids, shells and faces that share their edges and vertices (a
//! boundary representation, as CAD systems exchange parts; see `splinekit::brep`).
//!
//! ```json
//! {"type": "brep",
//!  "source_unit": "inch",
//!  "vertices": [[0, 0, 0], …],
//!  "edges": [{"curve": {"type": "line", "from": [0, 0, 0], "to": [1, 0, 0]}, "vertices": [0, 1]}, …],
//!  "faces": [{"surface": {"type": "plane", …}, "reversed": false,
//!             "loops": [[{"pcurve": {…2-D…}, "edge": 0, "forward": true}, …]]}, …],
//!  "shells": [{"faces": [0, 1, 2, 3, 4, 5], "closed": true}],
//!  "solids": [{"shells": [0], "name": "cube"}]}
//! ```
//!
//! Lengths are in millimetres; `source_unit` records the unit the geometry was read in (a
//! STEP file's), converted. An edge's curve runs over its whole domain from its first
//! vertex to its second. A face's loops (outer first) are uses of 2-D curves in its
//! surface's (u, v), each in the loop's direction, along an edge (`edge`, `forward`) or,
//! without one, along a pole's line or one side of a cut across a periodic surface whose
//! other side is its `twin` (index in the same loop).

use serde::{Deserialize, Serialize};
use splinekit::Point;
use splinekit::brep::{Brep, BrepEdge, BrepFace, EdgeUse, Shell, Solid};
use splinekit::surface::Surface;

use super::{PlaneDoc, SurfaceDecoration, SurfaceDocument, SurfaceForm, Surfaces};
use crate::budget::ShapeCost;
use crate::curves::{CurveDocument, LineDoc};
use crate::dimension::same_type;
use crate::error::{DocumentError, Result};
use crate::registry::DocumentKind;

fn yes() -> bool {
    true
}

fn is_true(b: &bool) -> bool {
    *b
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// An edge: a 3-D curve from `vertices[0]` to `vertices[1]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BrepEdgeDoc {
    /// The curve over its whole domain.
    pub curve: CurveDocument,
    /// Its first and last vertex.
    pub vertices: [usize; 2],
}

/// One piece of a face's loop.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BrepUseDoc {
    /// The piece as a 2-D curve in the face surface's (u, v), in the loop's direction.
    pub pcurve: CurveDocument,
    /// The edge it runs along, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub edge: Option<usize>,
    /// Whether it runs from the edge's first vertex to its second.
    #[serde(default = "yes", skip_serializing_if = "is_true")]
    pub forward: bool,
    /// The other side of a cut (index in the same loop).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub twin: Option<usize>,
}

/// A face: a surface bounded by loops.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BrepFaceDoc {
    /// Its name.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub name: String,
    /// The surface.
    pub surface: SurfaceDocument,
    /// Whether the face's normal is −(S_u × S_v).
    #[serde(default, skip_serializing_if = "is_false")]
    pub reversed: bool,
    /// The loops, outer first (none: the whole surface).
    #[serde(default)]
    pub loops: Vec<Vec<BrepUseDoc>>,
    /// Its colour, linear RGBA in [0, 1].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<[f32; 4]>,
}

/// A shell.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BrepShellDoc {
    /// Its faces.
    pub faces: Vec<usize>,
    /// Whether it bounds a volume.
    #[serde(default, skip_serializing_if = "is_false")]
    pub closed: bool,
}

/// A solid.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BrepSolidDoc {
    /// Its name.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub name: String,
    /// Its shells, the outer one first.
    pub shells: Vec<usize>,
    /// Its colour, linear RGBA in [0, 1] (faces' own colours take precedence).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<[f32; 4]>,
}

/// `{"type":"brep", …}`: see the module.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BrepDoc {
    /// The length unit the geometry was read in and converted from (e.g. `inch`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source_unit: Option<String>,
    /// The vertices.
    pub vertices: Vec<Vec<f64>>,
    /// The edges.
    #[serde(default)]
    pub edges: Vec<BrepEdgeDoc>,
    /// The faces.
    pub faces: Vec<BrepFaceDoc>,
    /// The shells.
    #[serde(default)]
    pub shells: Vec<BrepShellDoc>,
    /// The solids.
    #[serde(default)]
    pub solids: Vec<BrepSolidDoc>,
}

impl BrepDoc {
    /// The kernel B-rep, its parts built and its indices checked (errors name the field).
    pub fn build(&self) -> Result<Brep> {
        let vertices = self
            .vertices
            .iter()
            .enumerate()
            .map(|(k, v)| match v.as_slice() {
                [x, y, z] => Ok(Point::<3>::new(*x, *y, *z)),
                _ => Err(DocumentError::new(
                    format!("vertices[{k}]"),
                    format!("expected 3 coordinates, got {}", v.len()),
                )),
            })
            .collect::<Result<Vec<_>>>()?;
        let edges = self
            .edges
            .iter()
            .enumerate()
            .map(|(k, e)| {
                let field = format!("edges[{k}].curve");
                if e.curve.dimension().map_err(|err| err.within(&field))? != 3 {
                    return Err(DocumentError::new(field, "an edge is a 3-D curve"));
                }
                Ok(BrepEdge { curve: e.curve.build_in::<3>().map_err(|err| err.within(&field))?, vertices: e.vertices })
            })
            .collect::<Result<Vec<_>>>()?;
        let mut faces = Vec::with_capacity(self.faces.len());
        for (f, face) in self.faces.iter().enumerate() {
            let field = format!("faces[{f}]");
            let surface = face.surface.build_in::<3>().map_err(|e| e.within(&format!("{field}.surface")))?;
            let mut loops = Vec::with_capacity(face.loops.len());
            for (l, lp) in face.loops.iter().enumerate() {
                let mut uses = Vec::with_capacity(lp.len());
                for (u, us) in lp.iter().enumerate() {
                    let pfield = format!("{field}.loops[{l}][{u}].pcurve");
                    if us.pcurve.dimension().map_err(|e| e.within(&pfield))? != 2 {
                        return Err(DocumentError::new(pfield, "a pcurve is a 2-D curve in the surface's (u, v)"));
                    }
                    uses.push(EdgeUse {
                        pcurve: us.pcurve.build_in::<2>().map_err(|e| e.within(&pfield))?,
                        edge: us.edge,
                        forward: us.forward,
                        twin: us.twin,
                    });
                }
                loops.push(uses);
            }
            faces.push(BrepFace { surface, reversed: face.reversed, loops, color: face.color });
        }
        let shells = self.shells.iter().map(|s| Shell { faces: s.faces.clone(), closed: s.closed }).collect();
        let solids = self.solids.iter().map(|s| Solid { shells: s.shells.clone() }).collect();
        Ok(Brep::new(vertices, edges, faces, shells, solids)?)
    }

    /// The unit cube [0, 1]³ as one solid: 8 vertices, 12 line edges, 6 planes whose loops
    /// run counter-clockwise seen from outside.
    pub fn cube() -> Self {
        let corner = |k: usize| vec![(k & 1) as f64, (k >> 1 & 1) as f64, (k >> 2 & 1) as f64];
        let vertices: Vec<Vec<f64>> = (0..8).map(corner).collect();
        // Edges along x, y and z between corners differing in one bit.
        let mut edges = Vec::new();
        for a in 0..8usize {
            for bit in [1usize, 2, 4] {
                if a & bit == 0 {
                    let b = a | bit;
                    let curve = CurveDocument::Line(LineDoc { from: corner(a), to: corner(b) });
                    edges.push(BrepEdgeDoc { curve, vertices: [a, b] });
                }
            }
        }
        let edge_between = |a: usize, b: usize| edges.iter().position(|e| e.vertices == [a.min(b), a.max(b)]);
        // Each face: the plane through corner `o` spanned by axes `u` and `v` (bits), its
        // outward normal ±(u × v) by `reversed`.
        let face = |o: usize, u: usize, v: usize, reversed: bool| {
            let origin = corner(o);
            let axis = |bit: usize| (0..3).map(|k| if 1 << k == bit { 1.0 } else { 0.0 }).collect::<Vec<f64>>();
            let surface = SurfaceDocument::Plane(PlaneDoc { origin, u_axis: axis(u), v_axis: axis(v) });
            let ring = [o, o | u, o | u | v, o | v];
            let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
            let mut uses: Vec<BrepUseDoc> = (0..4)
                .map(|k| {
                    let (a, b) = (ring[k], ring[(k + 1) % 4]);
                    let pcurve =
                        CurveDocument::Line(LineDoc { from: square[k].to_vec(), to: square[(k + 1) % 4].to_vec() });
                    BrepUseDoc { pcurve, edge: edge_between(a, b), forward: a < b, twin: None }
                })
                .collect();
            if reversed {
                // The loop runs clockwise in (u, v): counter-clockwise seen along −(S_u × S_v).
                uses.reverse();
                for u in &mut uses {
                    u.forward = !u.forward;
                    if let CurveDocument::Line(l) = &mut u.pcurve {
                        std::mem::swap(&mut l.from, &mut l.to);
                    }
                }
            }
            BrepFaceDoc { name: String::new(), surface, reversed, loops: vec![uses], color: None }
        };
        let faces = vec![
            face(0, 1, 2, true),  // z = 0, normal −z
            face(4, 1, 2, false), // z = 1, normal +z
            face(0, 1, 4, false), // y = 0: x × z = −y
            face(2, 1, 4, true),  // y = 1
            face(0, 2, 4, true),  // x = 0: y × z = +x, reversed for −x
            face(1, 2, 4, false), // x = 1
        ];
        BrepDoc {
            source_unit: None,
            vertices,
            edges,
            faces,
            shells: vec![BrepShellDoc { faces: (0..6).collect(), closed: true }],
            solids: vec![BrepSolidDoc { name: "cube".into(), shells: vec![0], color: None }],
        }
    }
}

impl DocumentKind for BrepDoc {
    type Family = Surfaces;

    fn dimension(&self) -> Result<usize> {
        Ok(3)
    }

    /// Its curves and surfaces.
    fn cost(&self) -> ShapeCost {
        let edges = self.edges.iter().enumerate().map(|(k, e)| e.curve.cost().within(&format!("edges[{k}].curve")));
        let faces = self.faces.iter().enumerate().flat_map(|(f, face)| {
            let surface = std::iter::once(face.surface.cost().within(&format!("faces[{f}].surface")));
            let pcurves = face.loops.iter().enumerate().flat_map(move |(l, lp)| {
                lp.iter()
                    .enumerate()
                    .map(move |(u, us)| us.pcurve.cost().within(&format!("faces[{f}].loops[{l}][{u}].pcurve")))
            });
            surface.chain(pcurves)
        });
        let base = ShapeCost::new("vertices", 24.0 * self.vertices.len() as f64, self.vertices.len() as f64, 0.0);
        edges.chain(faces).fold(base, |acc, c| acc.and(c))
    }

    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let brep: Box<dyn Surface<3>> = Box::new(self.build()?);
        same_type(brep).ok_or_else(|| DocumentError::new("vertices", "a B-rep is 3-D"))
    }

    /// The unit cube.
    fn example() -> Self {
        Self::cube()
    }

    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::None
    }

    fn set_time(&mut self, time: f64) {
        for f in &mut self.faces {
            f.surface.set_time(time);
        }
    }

    /// A B-rep holds faces, not one control net.
    fn spline(&self) -> Option<crate::views::NetView<'_>> {
        None
    }

    fn exact_form(&self) -> Result<SurfaceForm<'_>> {
        Ok(SurfaceForm::Brep(self))
    }

    const BLENDING_MODEL: bool = false;
}
