//! Triangle meshes of trimmed surfaces by constrained Delaunay triangulation (spade) in
//! the unit parameter square: the trimming loops are constraint edges, interior points
//! (a regular grid, or the vertices of an adaptive quad-tree) fill the region, and
//! triangles outside the trim are dropped. The mesh boundary therefore follows the trimming
//! curves instead of a staircase of cells. Points on the sides of the domain are glued
//! like those of untrimmed meshes ([`crate::boundary_gluing`]).

use std::collections::BTreeMap;

use foldhash::{HashMap, HashMapExt};

use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use splinekit::surface::{Surface, TrimLoops, unit_normal};
use splinekit::{Error, Point, Result};

use crate::boundary_gluing::{Gluing, Node};
use crate::mesh_options::{AdaptiveTolerance, MeshOptions, lattice_param, to3};
use crate::triangle_mesh::{TriangleMesh, v3};

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// A point of the unit parameter square.
type Unit = [f64; 2];

/// The mesh of a trimmed surface with grid spacing 1/`n` of the domain in each direction;
/// the loops are resampled to half that spacing.
pub fn trimmed<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    loops: &TrimLoops<'_>,
    n: usize,
    options: MeshOptions,
) -> Result<TriangleMesh> {
    let spacing = 1.0 / n as f64;
    let to_unit = unit_of(surface);
    let resample = |poly: &[Point<2>]| by_spacing(&poly.iter().map(&to_unit).collect::<Vec<_>>(), 0.5 * spacing);
    let outer = match loops.outer {
        Some(o) => resample(o),
        None => {
            let side = |k: usize| k as f64 * spacing;
            let mut r: Vec<Unit> = (0..n).map(|k| [side(k), 0.0]).collect();
            r.extend((0..n).map(|k| [1.0, side(k)]));
            r.extend((0..n).map(|k| [1.0 - side(k), 1.0]));
            r.extend((0..n).map(|k| [0.0, 1.0 - side(k)]));
            r
        }
    };
    let mut rings = vec![outer];
    rings.extend(loops.holes.iter().map(|h| resample(h)));
    let grid = (1..n).flat_map(|i| (1..n).map(move |j| ([i as f64 * spacing, j as f64 * spacing], 0.4 * spacing)));
    triangulate(surface, Gluing::detect(surface), &rings, grid.collect(), (n as i64, n as i64), options, "density")
}

/// The mesh of a trimmed surface through the corners of an adaptive quad-tree's leaves
/// (`corners`: lattice point → size of the smallest leaf at it, on a `size` lattice, in
/// lattice order, which fixes the order of insertion and so the mesh), with the loops
/// sampled so that no chord is farther than the chord height from the surface.
pub(crate) fn trimmed_adaptive<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    loops: &TrimLoops<'_>,
    size: (i64, i64),
    corners: &BTreeMap<(i64, i64), i64>,
    tolerance: AdaptiveTolerance,
    options: MeshOptions,
) -> Result<TriangleMesh> {
    let to_unit = unit_of(surface);
    let resample = |poly: &[Point<2>]| {
        by_chord_height(surface, &poly.iter().map(&to_unit).collect::<Vec<_>>(), tolerance.chord_height)
    };
    let unit = |(i, j): (i64, i64)| [i as f64 / size.0 as f64, j as f64 / size.1 as f64];
    let on_boundary = |&(i, j): &(i64, i64)| i == 0 || j == 0 || i == size.0 || j == size.1;
    let gluing = Gluing::detect(surface);
    let outer = match loops.outer {
        Some(o) => resample(o),
        None => {
            // Both sides of a seam get the points of either, so they glue without T-junctions.
            let sides = corners.keys().filter(|p| on_boundary(p)).flat_map(|&(i, j)| gluing.seam_partners(i, j, size));
            boundary_ring(sides, size).into_iter().map(unit).collect()
        }
    };
    let mut rings = vec![outer];
    rings.extend(loops.holes.iter().map(|h| resample(h)));
    let cell = |s: i64| s as f64 / size.0.max(size.1) as f64;
    let interior = corners.iter().filter(|(p, _)| !on_boundary(p)).map(|(&p, &s)| (unit(p), 0.4 * cell(s))).collect();
    triangulate(surface, gluing, &rings, interior, size, options, "tolerance")
}

/// Maps parameters to the unit square.
fn unit_of<const D: usize, S: Surface<D> + ?Sized>(surface: &S) -> impl Fn(&Point<2>) -> Unit {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    move |p| [(p[0] - du.start) / du.length(), (p[1] - dv.start) / dv.length()]
}

/// Keeps polygon points at least `step` apart along the polygon (at least 8 points).
fn by_spacing(pts: &[Unit], step: f64) -> Vec<Unit> {
    let mut out = vec![pts[0]];
    let mut run = 0.0;
    for w in pts.windows(2) {
        run += ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt();
        if run >= step {
            out.push(w[1]);
            run = 0.0;
        }
    }
    if out.len() < 8 {
        let stride = (pts.len() / 8).max(1);
        out = pts.iter().step_by(stride).copied().collect();
    }
    out
}

/// Keeps as few points of the closed polygon as possible (at least 8) such that each
/// skipped point's image lies within `height` of the chord between the images of the kept
/// points around it (greedy, at most 256 points skipped per chord).
fn by_chord_height<const D: usize, S: Surface<D> + ?Sized>(surface: &S, pts: &[Unit], height: f64) -> Vec<Unit> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let images: Vec<[f64; 3]> = pts.iter().map(|p| to3(&surface.point(du.lerp(p[0]), dv.lerp(p[1])))).collect();
    let n = pts.len();
    let most = (n / 8).clamp(1, 256);
    let chord_ok = |a: usize, b: usize| {
        let (p, q) = (v3(images[a]), v3(images[b % n]));
        let d = q - p;
        let len = d.norm();
        (a + 1..b).all(|k| {
            let r = v3(images[k % n]) - p;
            let off = if len > 0.0 { d.cross(&r).norm() / len } else { r.norm() };
            off <= height
        })
    };
    let mut out = vec![pts[0]];
    let mut a = 0;
    while a < n {
        let mut b = a + 1;
        while b < n && b - a < most && chord_ok(a, b + 1) {
            b += 1;
        }
        if b < n {
            out.push(pts[b]);
        }
        a = b;
    }
    if out.len() < 8 {
        let stride = (n / 8).max(1);
        out = pts.iter().step_by(stride).copied().collect();
    }
    out
}

/// Lattice points on the boundary of the `size` lattice, in order around it (counter-
/// clockwise from (0, 0)).
fn boundary_ring(points: impl Iterator<Item = (i64, i64)>, size: (i64, i64)) -> Vec<(i64, i64)> {
    // Position along the boundary: bottom, right, top (backwards), left (backwards).
    let key = |&(i, j): &(i64, i64)| {
        if j == 0 && i < size.0 {
            i
        } else if i == size.0 && j < size.1 {
            size.0 + j
        } else if j == size.1 && i > 0 {
            size.0 + size.1 + (size.0 - i)
        } else {
            2 * size.0 + size.1 + (size.1 - j)
        }
    };
    let mut ring: Vec<(i64, i64)> = points.collect();
    ring.sort_by_key(key);
    ring.dedup();
    ring
}

/// Interior points farther than their radius from every loop point, found through a grid of
/// buckets as wide as the largest radius.
fn away_from_loops(rings: &[Vec<Unit>], points: Vec<(Unit, f64)>) -> Vec<Unit> {
    let width = points.iter().map(|p| p.1).fold(0.0, f64::max);
    if width <= 0.0 {
        return points.into_iter().map(|p| p.0).collect();
    }
    let bucket = |p: Unit| ((p[0] / width).floor() as i64, (p[1] / width).floor() as i64);
    let mut buckets: HashMap<(i64, i64), Vec<Unit>> = HashMap::new();
    for q in rings.iter().flatten() {
        buckets.entry(bucket(*q)).or_default().push(*q);
    }
    let near = |p: Unit, r: f64| {
        let (bx, by) = bucket(p);
        (bx - 1..=bx + 1).any(|x| {
            (by - 1..=by + 1).any(|y| {
                buckets
                    .get(&(x, y))
                    .is_some_and(|qs| qs.iter().any(|q| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) < r * r))
            })
        })
    };
    points.into_iter().filter(|&(p, r)| !near(p, r)).map(|p| p.0).collect()
}

/// Triangulates the region inside the first ring and outside the others, through the
/// interior points (each with the radius around loop points where it is left out).
fn triangulate<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    gluing: Gluing,
    rings: &[Vec<Unit>],
    interior: Vec<(Unit, f64)>,
    lattice: (i64, i64),
    options: MeshOptions,
    field: &str,
) -> Result<TriangleMesh> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let mut cdt = Cdt::new();
    let insert = |cdt: &mut Cdt, p: Unit| {
        cdt.insert(Point2::new(p[0], p[1])).map_err(|e| {
            Error::invalid("trim", format!("the point ({}, {}) cannot be triangulated: {e:?}", p[0], p[1]))
        })
    };
    for (r, ring) in rings.iter().enumerate() {
        let handles = ring.iter().map(|&p| insert(&mut cdt, p)).collect::<Result<Vec<_>>>()?;
        for k in 0..handles.len() {
            let (a, b) = (handles[k], handles[(k + 1) % handles.len()]);
            if a == b {
                continue;
            }
            if !cdt.can_add_constraint(a, b) {
                return Err(Error::invalid(
                    if r == 0 { "outer".to_string() } else { format!("holes[{}]", r - 1) },
                    "trimming loops must not cross themselves or each other",
                ));
            }
            cdt.add_constraint(a, b);
        }
    }
    let inside = |p: Unit| surface.trim_contains(du.lerp(p[0]), dv.lerp(p[1])) != Some(false);
    let interior: Vec<(Unit, f64)> = interior.into_iter().filter(|(p, _)| inside(*p)).collect();
    for p in away_from_loops(rings, interior) {
        insert(&mut cdt, p)?;
    }
    let mut vertices = GluedVertices { surface, gluing, lattice, options, ids: HashMap::new() };
    let mut mesh = TriangleMesh::default();
    for face in cdt.inner_faces() {
        let vs = face.vertices();
        let c = vs.iter().fold([0.0, 0.0], |acc, v| [acc[0] + v.position().x / 3.0, acc[1] + v.position().y / 3.0]);
        if !inside(c) {
            continue;
        }
        let tri = vs.map(|v| vertices.id(&mut mesh, v.fix().index(), [v.position().x, v.position().y]));
        mesh.triangles.push(tri);
    }
    if mesh.triangles.is_empty() {
        return Err(Error::invalid(
            "holes",
            "the trim leaves nothing of the surface: its holes cover the whole region inside the outer loop",
        ));
    }
    crate::mesh_cleanup::finish(&mut mesh, field)?;
    Ok(mesh)
}

/// Mesh vertices of triangulation vertices: those on a side of the domain at a lattice
/// point are glued like lattice points of untrimmed meshes; the others are their own.
struct GluedVertices<'a, const D: usize, S: Surface<D> + ?Sized> {
    surface: &'a S,
    gluing: Gluing,
    lattice: (i64, i64),
    options: MeshOptions,
    ids: HashMap<Key, u32>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Glued(Node),
    Own(usize),
}

impl<'a, const D: usize, S: Surface<D> + ?Sized> GluedVertices<'a, D, S> {
    /// The lattice point at `p` if it lies on a side of the square at a lattice point.
    fn side_lattice_point(&self, p: Unit) -> Option<(i64, i64)> {
        let on_side = p[0] == 0.0 || p[0] == 1.0 || p[1] == 0.0 || p[1] == 1.0;
        let snap = |x: f64, n: i64| {
            let k = (x * n as f64).round();
            ((x * n as f64 - k).abs() < 1e-6).then_some(k as i64)
        };
        if !on_side {
            return None;
        }
        Some((snap(p[0], self.lattice.0)?, snap(p[1], self.lattice.1)?))
    }
    fn id(&mut self, mesh: &mut TriangleMesh, own: usize, p: Unit) -> u32 {
        let lattice_point = self.side_lattice_point(p);
        let key = match lattice_point {
            Some((i, j)) => Key::Glued(self.gluing.node(i, j, self.lattice, !self.options.uv)),
            None => Key::Own(own),
        };
        if let Some(&id) = self.ids.get(&key) {
            return id;
        }
        let (du, dv) = (self.surface.domain_u(), self.surface.domain_v());
        let (position, normal) = match lattice_point.map(|(i, j)| self.gluing.node(i, j, self.lattice, true)) {
            Some(Node::Pole(c)) => {
                let pole = self.gluing.pole(c);
                (pole.position, pole.normal.unwrap_or([0.0; 3]))
            }
            Some(Node::Grid(a, b)) => {
                self.eval(lattice_param(du, a, self.lattice.0), lattice_param(dv, b, self.lattice.1))
            }
            None => self.eval(du.lerp(p[0]), dv.lerp(p[1])),
        };
        let id = mesh.positions.len() as u32;
        mesh.positions.push(position);
        mesh.normals.push(normal);
        if self.options.uv {
            mesh.uvs.push(p);
        }
        self.ids.insert(key, id);
        id
    }
    fn eval(&self, u: f64, v: f64) -> ([f64; 3], [f64; 3]) {
        let mut partials = [Point::<D>::zeros(); 4];
        self.surface.eval_partials(u, v, 1, 1, &mut partials);
        (to3(&partials[0]), unit_normal(&partials[2], &partials[1]).map(|n| to3(&n)).unwrap_or([0.0; 3]))
    }
}
