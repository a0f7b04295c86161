//! Watertight triangle meshes of boundary representations ([`splinekit::brep::Brep`]).
//!
//! Each edge is flattened once, to the chord tolerance ([`Polyline::adaptive`]), its ends
//! put exactly on its vertices; every face that uses the edge takes those same points as
//! the boundary of its mesh. A face is then filled inside its loops by constrained Delaunay
//! triangulation (spade) in its surface's (u, v):
//!
//! * the boundary points' (u, v) are the surface parameters of the edge points, found by
//!   Gauss–Newton from the face's pcurve at the same fraction of the use (the pcurve says
//!   which side of a seam a use runs along; the edge point stays the mesh vertex, so a
//!   face off its edges by the file's gap still meets its neighbours exactly);
//! * uses without an edge (a pole's line, the two sides of a cut across a periodic
//!   surface) are flattened on the surface: a cut once, its twin taking the same points
//!   one period over; a pole's line is one vertex;
//! * interior points lie on a grid of the loops' box whose spacing keeps the chord height
//!   h²|S''|/8 within the tolerance in each direction (none on planes); the triangulation
//!   runs in (u |S_u|, v |S_v|) so that its triangles are about as well shaped in space as
//!   in the plane; triangles whose centre is outside the loops (even–odd rule) are dropped,
//!   and so are those that collapse at a pole.
//!
//! Triangles turn counter-clockwise about S_u × S_v, or about its opposite on reversed
//! faces, so a closed shell's mesh is consistently oriented. Each face has its own vertices
//! (their normals are the face's), but vertices on an edge have the same position, bit for
//! bit, in every face: welded by position, the mesh of a closed shell is a closed
//! 2-manifold, and [`TriangleMesh::signed_volume`] is the solid's volume to within the
//! tolerance.

use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use splinekit::brep::{Brep, BrepFace, EdgeUse};
use splinekit::curve::{Curve, Interval};
use splinekit::query::newton::{Settle, cap, polish_on_surface};
use splinekit::surface::{Surface, unit_normal};
use splinekit::{Error, Point, Result};

use crate::polyline::Polyline;
use crate::triangle_mesh::TriangleMesh;

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// Most interior grid points of one face.
pub const MAX_FACE_POINTS: usize = 1 << 20;
/// Samples per direction where a face's second derivatives are estimated.
const CURVATURE_SAMPLES: usize = 9;
/// Points a use without an edge is flattened to at least.
const MIN_CUT_POINTS: usize = 2;

/// A surface whose closed directions continue past their domain (a periodic surface
/// evaluated at u + P is itself at u): loops that cross a seam have parameters beyond it.
struct Periodic<'a>(&'a dyn Surface<3>);

fn wrap(x: f64, d: Interval, closed: bool) -> f64 {
    if closed && x.is_finite() && (x < d.start || x > d.end) {
        d.start + (x - d.start).rem_euclid(d.length())
    } else {
        x
    }
}

impl Surface<3> for Periodic<'_> {
    fn domain_u(&self) -> Interval {
        let d = self.0.domain_u();
        if self.0.is_closed_u() { Interval::new(f64::NEG_INFINITY, f64::INFINITY) } else { d }
    }
    fn domain_v(&self) -> Interval {
        let d = self.0.domain_v();
        if self.0.is_closed_v() { Interval::new(f64::NEG_INFINITY, f64::INFINITY) } else { d }
    }
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let (u, v) =
            (wrap(u, self.0.domain_u(), self.0.is_closed_u()), wrap(v, self.0.domain_v(), self.0.is_closed_v()));
        self.0.eval_partials(u, v, du, dv, out);
    }
}

/// A point of a face's boundary: its (u, v), its position, and whether it is a pole's
/// (one vertex for the whole line).
#[derive(Debug, Clone, Copy)]
struct Boundary {
    uv: Point<2>,
    position: Point<3>,
}

/// The flattened edges: parameters and points, ends on the edge's vertices.
struct Edges {
    points: Vec<Vec<Point<3>>>,
}

fn flatten_edges(brep: &Brep, tolerance: f64) -> Result<Edges> {
    let mut points = Vec::with_capacity(brep.edges().len());
    for (k, e) in brep.edges().iter().enumerate() {
        let line = Polyline::adaptive(e.curve.as_ref(), tolerance)
            .map_err(|err| Error::invalid(format!("edges[{k}]"), err.to_string()))?;
        let mut pts = line.points;
        if line.closed {
            let first = pts[0];
            pts.push(first);
        }
        if pts.len() < 2 {
            return Err(Error::invalid(format!("edges[{k}]"), "an edge flattens to fewer than two points"));
        }
        // The ends are the vertices, bit for bit, so that edges meet exactly.
        let n = pts.len();
        pts[0] = brep.vertices()[e.vertices[0]];
        pts[n - 1] = brep.vertices()[e.vertices[1]];
        points.push(pts);
    }
    Ok(Edges { points })
}

/// The pcurve at fraction `f` of its domain.
fn pcurve_at(u: &EdgeUse, f: f64) -> Point<2> {
    let d = u.pcurve.domain();
    u.pcurve.point(d.start + d.length() * f)
}

/// The parameters of `p` on the surface, from `hint`.
fn parameters(surface: &Periodic, p: &Point<3>, hint: Point<2>) -> Point<2> {
    let ((u, v), _) = polish_on_surface(
        surface,
        p,
        (hint[0], hint[1]),
        (surface.domain_u(), surface.domain_v()),
        cap::POINT_PARAMETERS,
        Settle::Rounding,
    );
    let found = Point::<2>::new(u, v);
    // A singular or wandering polish (at a pole) keeps the pcurve's point.
    if found.iter().all(|x| x.is_finite())
        && (surface.point(u, v) - p).norm() <= (surface.point(hint[0], hint[1]) - p).norm()
    {
        found
    } else {
        hint
    }
}

/// One face's boundary rings: per loop its points in order (the last not repeating the
/// first).
fn rings(face: &BrepFace, surface: &Periodic, edges: &Edges, tolerance: f64, f: usize) -> Result<Vec<Vec<Boundary>>> {
    let mut out = Vec::with_capacity(face.loops.len());
    for lp in &face.loops {
        let mut pieces: Vec<Option<Vec<Boundary>>> = vec![None; lp.len()];
        for (k, us) in lp.iter().enumerate() {
            if pieces[k].is_some() {
                continue;
            }
            let piece: Vec<Boundary> = match us.edge {
                Some(e) => {
                    let pts = &edges.points[e];
                    let n = pts.len();
                    (0..n)
                        .map(|i| {
                            let p = if us.forward { pts[i] } else { pts[n - 1 - i] };
                            let hint = pcurve_at(us, i as f64 / (n - 1) as f64);
                            Boundary { uv: parameters(surface, &p, hint), position: p }
                        })
                        .collect()
                }
                None => {
                    let piece = flatten_on_surface(us, surface, tolerance)?;
                    if let Some(t) = us.twin {
                        // The other side: the same points, run back, at its own (u, v).
                        let twin = &lp[t];
                        let n = piece.len();
                        pieces[t] = Some(
                            (0..n)
                                .map(|i| {
                                    let b = piece[n - 1 - i];
                                    Boundary { uv: pcurve_at(twin, i as f64 / (n - 1) as f64), position: b.position }
                                })
                                .collect(),
                        );
                    }
                    piece
                }
            };
            pieces[k] = Some(piece);
        }
        let mut pieces: Vec<Vec<Boundary>> = pieces.into_iter().flatten().collect();
        // The ends of a piece without an edge are the vertices of the edges beside it, bit
        // for bit (a pole's line is all that vertex), so that the faces across those edges
        // meet it exactly.
        let n = pieces.len();
        for k in 0..n {
            if lp[k].edge.is_some() {
                continue;
            }
            let (before, after) = ((k + n - 1) % n, (k + 1) % n);
            let pole = pieces[k].iter().all(|b| b.position == pieces[k][0].position);
            if lp[before].edge.is_some() {
                let p = pieces[before][pieces[before].len() - 1].position;
                if pole {
                    pieces[k].iter_mut().for_each(|b| b.position = p);
                }
                pieces[k][0].position = p;
            }
            if lp[after].edge.is_some() {
                let p = pieces[after][0].position;
                if pole {
                    pieces[k].iter_mut().for_each(|b| b.position = p);
                }
                let last = pieces[k].len() - 1;
                pieces[k][last].position = p;
            }
        }
        let mut ring: Vec<Boundary> = Vec::new();
        for piece in pieces {
            // Each piece starts where the one before it ends: keep its end only.
            let skip = usize::from(!ring.is_empty());
            ring.extend(piece.into_iter().skip(skip));
        }
        if ring.len() > 1 {
            ring.pop(); // the loop's end is its start
        }
        if ring.len() < 3 {
            return Err(Error::invalid(format!("faces[{f}].loops"), "a loop of fewer than three points"));
        }
        out.push(ring);
    }
    Ok(out)
}

/// A use without an edge flattened on the surface: S(pcurve) to the tolerance; a pole's
/// line (whose points all lie within the tolerance of its first) is that one point, at
/// the line's (u, v) samples.
fn flatten_on_surface(us: &EdgeUse, surface: &Periodic, tolerance: f64) -> Result<Vec<Boundary>> {
    let image = OnSurface { surface, pcurve: us.pcurve.as_ref() };
    let line = Polyline::adaptive(&image, tolerance)?;
    let mut params = line.params;
    if params.len() < MIN_CUT_POINTS {
        let d = us.pcurve.domain();
        params = vec![d.start, d.end];
    }
    let d = us.pcurve.domain();
    if params[params.len() - 1] < d.end {
        params.push(d.end);
    }
    let uvs: Vec<Point<2>> = params.iter().map(|&t| us.pcurve.point(t)).collect();
    let positions: Vec<Point<3>> = uvs.iter().map(|q| surface.point(q[0], q[1])).collect();
    let pole = positions.iter().all(|p| (p - positions[0]).norm() <= tolerance);
    Ok(uvs
        .into_iter()
        .zip(positions.iter())
        .map(|(uv, p)| Boundary { uv, position: if pole { positions[0] } else { *p } })
        .collect())
}

/// S(c(t)) of a pcurve c, for flattening (position only).
struct OnSurface<'a> {
    surface: &'a Periodic<'a>,
    pcurve: &'a dyn Curve<2>,
}

impl Curve<3> for OnSurface<'_> {
    fn domain(&self) -> Interval {
        self.pcurve.domain()
    }
    fn eval_side(&self, t: f64, side: splinekit::basis::Side, out: &mut [Point<3>]) {
        let mut c = [Point::<2>::zeros(); 2];
        let n = out.len().min(2);
        self.pcurve.eval_side(t, side, &mut c[..n]);
        let mut s = [Point::<3>::zeros(); 4];
        self.surface.eval_partials(c[0][0], c[0][1], 1, 1, &mut s);
        out[0] = s[0];
        if n > 1 {
            out[1] = s[2] * c[1][0] + s[1] * c[1][1];
        }
        out[n..].iter_mut().for_each(|o| *o = Point::<3>::zeros());
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.pcurve.breakpoints()
    }
}

/// Even–odd: whether `p` lies inside the rings.
fn inside(rings: &[Vec<Boundary>], p: Point<2>) -> bool {
    let mut odd = false;
    for ring in rings {
        let n = ring.len();
        for k in 0..n {
            let (a, b) = (ring[k].uv, ring[(k + 1) % n].uv);
            if (a[1] > p[1]) != (b[1] > p[1]) {
                let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if x > p[0] {
                    odd = !odd;
                }
            }
        }
    }
    odd
}

/// The mesh of one face, appended to `mesh`.
fn mesh_face(face: &BrepFace, f: usize, edges: &Edges, tolerance: f64, mesh: &mut TriangleMesh) -> Result<()> {
    let surface = Periodic(face.surface.as_ref());
    let rings = if face.loops.is_empty() {
        return Err(Error::invalid(format!("faces[{f}].loops"), "a face without loops is not meshed as a B-rep face"));
    } else {
        rings(face, &surface, edges, tolerance, f)?
    };
    let (mut lo, mut hi) = (Point::<2>::from([f64::INFINITY; 2]), Point::<2>::from([f64::NEG_INFINITY; 2]));
    for b in rings.iter().flatten() {
        lo = lo.inf(&b.uv);
        hi = hi.sup(&b.uv);
    }
    // Speeds and second derivatives over the loops' box.
    let (mut speed, mut bend) = ([0.0f64; 2], [0.0f64; 2]);
    let mut o = [Point::<3>::zeros(); 9];
    let samples = CURVATURE_SAMPLES;
    for i in 0..samples {
        for j in 0..samples {
            let u = lo[0] + (hi[0] - lo[0]) * i as f64 / (samples - 1) as f64;
            let v = lo[1] + (hi[1] - lo[1]) * j as f64 / (samples - 1) as f64;
            surface.eval_partials(u, v, 2, 2, &mut o);
            if !o.iter().all(|p| p.iter().all(|x| x.is_finite())) {
                continue;
            }
            speed = [speed[0].max(o[3].norm()), speed[1].max(o[1].norm())];
            bend = [bend[0].max(o[6].norm()), bend[1].max(o[2].norm())];
        }
    }
    let scale = [speed[0].max(f64::MIN_POSITIVE), speed[1].max(f64::MIN_POSITIVE)];
    let to_plane = |uv: Point<2>| Point2::new(uv[0] * scale[0], uv[1] * scale[1]);
    let mut cdt = Cdt::new();
    let mut vertex_of: Vec<Option<(Point<2>, Option<Point<3>>)>> = Vec::new();
    let mut note = |cdt: &Cdt, h: spade::handles::FixedVertexHandle, uv: Point<2>, p: Option<Point<3>>| {
        let k = h.index();
        if vertex_of.len() <= k {
            vertex_of.resize(k + 1, None);
        }
        // A boundary position wins over an interior one at the same place.
        if vertex_of[k].is_none_or(|(_, q)| q.is_none()) {
            vertex_of[k] = Some((uv, p));
        }
        let _ = cdt;
    };
    let field = format!("faces[{f}]");
    let mut every_side_constrained = true;
    for ring in &rings {
        let mut handles = Vec::with_capacity(ring.len());
        for b in ring {
            let h = cdt.insert(to_plane(b.uv)).map_err(|e| {
                Error::invalid(field.clone(), format!("a boundary point cannot be triangulated: {e:?}"))
            })?;
            note(&cdt, h, b.uv, Some(b.position));
            handles.push(h);
        }
        for k in 0..handles.len() {
            let (a, b) = (handles[k], handles[(k + 1) % handles.len()]);
            if a != b {
                if cdt.can_add_constraint(a, b) {
                    cdt.add_constraint(a, b);
                } else {
                    every_side_constrained = false;
                }
            }
        }
    }
    // Interior grid: spacing h with h²|S''|/8 within the tolerance in each direction.
    let step = |k: usize| {
        if bend[k] > 0.0 { (8.0 * tolerance / bend[k]).sqrt() } else { f64::INFINITY }
    };
    let counts = [0, 1].map(|k| {
        let n = ((hi[k] - lo[k]) / step(k)).ceil();
        if n.is_finite() { (n as usize).max(1) } else { 1 }
    });
    if counts[0].saturating_mul(counts[1]) > MAX_FACE_POINTS {
        return Err(Error::invalid(
            "tolerance",
            format!("face {f} needs {}×{} interior points at {tolerance:e}", counts[0], counts[1]),
        ));
    }
    let spacing = [0, 1].map(|k| (hi[k] - lo[k]) / counts[k] as f64);
    let clearance = 0.3 * (spacing[0] * scale[0]).min(spacing[1] * scale[1]);
    for i in 1..counts[0] {
        for j in 1..counts[1] {
            let uv = Point::<2>::new(lo[0] + spacing[0] * i as f64, lo[1] + spacing[1] * j as f64);
            if !inside(&rings, uv) || near_boundary(&rings, uv, &to_plane, clearance) {
                continue;
            }
            if let Ok(h) = cdt.insert(to_plane(uv)) {
                note(&cdt, h, uv, None);
            }
        }
    }
    let first = mesh.positions.len();
    let mut ids = vec![u32::MAX; vertex_of.len()];
    let enclosed = every_side_constrained.then(|| faces_within_constraints(&cdt));
    for t in cdt.inner_faces() {
        let vs = t.vertices();
        let within = match &enclosed {
            Some(within) => within[t.fix().index()],
            None => {
                let centre = vs.iter().fold(Point::<2>::zeros(), |acc, v| {
                    let (uv, _) = vertex_of[v.fix().index()].expect("every vertex was noted");
                    acc + uv / 3.0
                });
                inside(&rings, centre)
            }
        };
        if !within {
            continue;
        }
        let corners = vs.map(|v| v.fix().index());
        let positions = corners.map(|k| {
            let (uv, p) = vertex_of[k].expect("noted");
            p.unwrap_or_else(|| surface.point(uv[0], uv[1]))
        });
        if positions[0] == positions[1] || positions[1] == positions[2] || positions[0] == positions[2] {
            continue; // collapsed at a pole
        }
        let mut tri = [0u32; 3];
        for (c, &k) in corners.iter().enumerate() {
            if ids[k] == u32::MAX {
                let (uv, p) = vertex_of[k].expect("noted");
                let mut d = [Point::<3>::zeros(); 4];
                surface.eval_partials(uv[0], uv[1], 1, 1, &mut d);
                let n = unit_normal(&d[2], &d[1]).map(|n| if face.reversed { -n } else { n });
                let p = p.unwrap_or(d[0]);
                ids[k] = mesh.positions.len() as u32;
                mesh.positions.push([p[0], p[1], p[2]]);
                mesh.normals.push(n.map_or([0.0; 3], |n| [n[0], n[1], n[2]]));
                if let Some(c) = face.color {
                    mesh.colors.push(c);
                }
            }
            tri[c] = ids[k];
        }
        if face.reversed {
            tri.swap(1, 2);
        }
        mesh.triangles.push(tri);
    }
    if mesh.positions.len() == first {
        return Err(Error::invalid(field, "the face's loops enclose no triangle"));
    }
    Ok(())
}

/// Which faces of the triangulation lie inside the loops, by the parity of the constraint
/// edges crossed on the way in from the convex hull (a walk over neighbouring triangles).
/// Unlike a test of each triangle's centre against the loops, this cannot mistake a sliver
/// along a loop (three consecutive boundary points where the loop bends outwards by a
/// rounding error) for an inside triangle, which left the shared edge used three times.
fn faces_within_constraints(cdt: &Cdt) -> Vec<bool> {
    let mut crossings: Vec<Option<u32>> = vec![None; cdt.num_all_faces()];
    let mut queue = std::collections::VecDeque::new();
    for hull_edge in cdt.convex_hull() {
        for side in [hull_edge, hull_edge.rev()] {
            if let Some(inner) = side.face().as_inner() {
                let k = inner.fix().index();
                if crossings[k].is_none() {
                    crossings[k] = Some(u32::from(side.is_constraint_edge()));
                    queue.push_back(inner.fix());
                }
            }
        }
    }
    while let Some(face) = queue.pop_front() {
        let here = crossings[face.index()].expect("queued faces are numbered");
        for edge in cdt.face(face).adjacent_edges() {
            if let Some(next) = edge.rev().face().as_inner() {
                let k = next.fix().index();
                if crossings[k].is_none() {
                    crossings[k] = Some(here + u32::from(edge.is_constraint_edge()));
                    queue.push_back(next.fix());
                }
            }
        }
    }
    crossings.iter().map(|c| c.is_some_and(|c| c % 2 == 1)).collect()
}

/// Whether `uv` lies within `clearance` (in the triangulation's plane) of a boundary
/// point.
fn near_boundary(
    rings: &[Vec<Boundary>],
    uv: Point<2>,
    to_plane: &impl Fn(Point<2>) -> Point2<f64>,
    clearance: f64,
) -> bool {
    let p = to_plane(uv);
    rings.iter().flatten().any(|b| {
        let q = to_plane(b.uv);
        (p.x - q.x).powi(2) + (p.y - q.y).powi(2) < clearance * clearance
    })
}

/// The chord tolerance that a regular mesh of `n` cells a direction stands for: the
/// chord height of a circle the size of the B-rep's vertex box drawn with `n` segments,
/// r(1 − cos(π/n)).
pub fn tolerance_for_density(brep: &Brep, n: usize) -> f64 {
    let (mut lo, mut hi) = (Point::<3>::from([f64::INFINITY; 3]), Point::<3>::from([f64::NEG_INFINITY; 3]));
    for p in brep.vertices() {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    let r = if brep.vertices().is_empty() { 1.0 } else { 0.5 * (hi - lo).norm().max(f64::MIN_POSITIVE) };
    r * (1.0 - (std::f64::consts::PI / n.max(3) as f64).cos())
}

/// The watertight mesh of a B-rep within the chord `tolerance` (see the module): faces in
/// order, each with its own vertices, colours where every face has one.
pub fn brep_mesh(brep: &Brep, tolerance: f64) -> Result<TriangleMesh> {
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::invalid("tolerance", format!("must be positive and finite, got {tolerance}")));
    }
    let edges = flatten_edges(brep, tolerance)?;
    let mut mesh = TriangleMesh::default();
    for (f, face) in brep.faces().iter().enumerate() {
        mesh_face(face, f, &edges, tolerance, &mut mesh)?;
    }
    if mesh.colors.len() != mesh.positions.len() {
        mesh.colors.clear();
    }
    Ok(mesh)
}

/// The edges of a mesh, welded by exact position, that are not used once each way by two
/// triangles: 0 for a closed, consistently oriented 2-manifold (triangles that collapse
/// when welded are left out).
pub fn open_edges(mesh: &TriangleMesh) -> usize {
    use std::collections::HashMap;
    let mut ids: HashMap<[u64; 3], u32> = HashMap::new();
    let welded: Vec<u32> = mesh
        .positions
        .iter()
        .map(|p| {
            let n = ids.len() as u32;
            *ids.entry(p.map(f64::to_bits)).or_insert(n)
        })
        .collect();
    let mut uses: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| welded[i as usize]);
        if a == b || b == c || a == c {
            continue;
        }
        for e in [(a, b), (b, c), (c, a)] {
            *uses.entry(e).or_default() += 1;
        }
    }
    uses.iter().filter(|(e, n)| **n != 1 || uses.get(&(e.1, e.0)) != Some(&1)).count()
}
