//! Adaptive triangle meshes of surfaces: a quad-tree over the parameter rectangle, each cell
//! split in four while it is farther than a chord height from flat or its normals turn more
//! than an angle. Poles and seams are glued as in the regular mesh
//! ([`crate::boundary_gluing`]); trimmed surfaces hand the quad-tree's vertices to the
//! constrained triangulation that follows their trimming loops ([`crate::trimmed_mesh`]).

use std::collections::BTreeMap;

use foldhash::{HashMap, HashMapExt, HashSet};

use splinekit::surface::{Surface, unit_normal};
use splinekit::{Error, Point, Result};

use crate::boundary_gluing::{Gluing, Node};
pub use crate::mesh_options::AdaptiveTolerance;
use crate::mesh_options::{MAX_VERTICES, MeshOptions, lattice_param, to3};
use crate::triangle_mesh::{TriangleMesh, v3};

/// Levels below the initial grid at which [`adaptive_with_limit`] probes the surface to
/// estimate the size of the mesh before refining (8 × 8 base cells make a 32 × 32 probe).
const PROBE_LEVELS: u32 = 2;

/// An adaptive mesh: an initial grid of `base` = (n_u, n_v) cells, each split in four while
/// it is farther than the chord height from flat or its normals turn more than the angle
/// (down to `max_depth` levels). Cells are triangulated as a fan from their centre whenever a
/// finer neighbour put vertices on their edges, so neighbouring levels stitch without cracks.
/// Trimmed surfaces are triangulated through the quad-tree's vertices with the trimming
/// loops (sampled to the chord height) as constraints.
pub fn adaptive<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    base: (usize, usize),
    tolerance: AdaptiveTolerance,
    options: MeshOptions,
) -> Result<TriangleMesh> {
    adaptive_with_limit(surface, base, tolerance, options, MAX_VERTICES)
}

/// [`adaptive`], refusing (with an error on `tolerance`) a quad-tree of more than
/// `max_leaves` cells, the budget of the mesh (about two triangles and one vertex each).
pub fn adaptive_with_limit<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    base: (usize, usize),
    tolerance: AdaptiveTolerance,
    options: MeshOptions,
    max_leaves: usize,
) -> Result<TriangleMesh> {
    if !(tolerance.chord_height > 0.0 && tolerance.chord_height.is_finite()) {
        return Err(Error::invalid(
            "tolerance",
            format!("must be positive and finite, got {}", tolerance.chord_height),
        ));
    }
    if let Some(atlas) = surface.triangle_atlas() {
        let most = max_leaves.saturating_mul(2);
        return crate::triangle_atlas_mesh::within_tolerance(atlas, tolerance.chord_height, most, options);
    }
    if let Some(s) = surface.subdivision() {
        return Ok(crate::subdivision_mesh::within_tolerance(s, tolerance.chord_height, max_leaves)?.0);
    }
    if let Some(b) = surface.brep() {
        return crate::brep_mesh::brep_mesh(b, tolerance.chord_height);
    }
    if tolerance.normal_angle.is_nan()
        || tolerance.normal_angle <= 0.0
        || tolerance.max_depth > 16
        || base.0 == 0
        || base.1 == 0
        || base.0.saturating_mul(base.1) > 1 << 20
    {
        return Err(Error::invalid(
            "tolerance",
            format!(
                "need a positive normal angle, depth ≤ 16 and a base grid of 1 to 2²⁰ cells, got {}, {}, {}×{}",
                tolerance.normal_angle, tolerance.max_depth, base.0, base.1
            ),
        ));
    }
    let mut tree = QuadTree::new(surface, base, tolerance);
    tree.max_leaves = max_leaves.min(MAX_VERTICES);
    let estimate = tree.estimated_leaves(base);
    if estimate > tree.max_leaves as f64 {
        return Err(Error::invalid(
            "tolerance",
            format!(
                "{:?} needs about {estimate:.2e} cells (estimated from the surface's flatness on a coarse grid), more than the budget of {} cells of this mesh",
                tolerance.chord_height, tree.max_leaves
            ),
        ));
    }
    let scale = 1i64 << tolerance.max_depth;
    for i in 0..base.0 as i64 {
        for j in 0..base.1 as i64 {
            tree.refine(i * scale, j * scale, scale)?;
        }
    }
    if let Some(loops) = surface.trim_loops() {
        let points = tree.leaf_corners();
        return crate::trimmed_mesh::trimmed_adaptive(surface, &loops, tree.size, &points, tolerance, options);
    }
    let mut mesh = Stitcher::new(&mut tree, options).triangulate()?;
    crate::mesh_cleanup::finish(&mut mesh, "tolerance")?;
    Ok(mesh)
}

/// The refined quad-tree: its leaves and the surface samples it took.
struct QuadTree<'a, const D: usize, S: Surface<D> + ?Sized> {
    surface: &'a S,
    tolerance: AdaptiveTolerance,
    /// Lattice size in each direction (base cells × 2^depth).
    size: (i64, i64),
    /// Leaves as (i, j, size) in lattice units.
    leaves: Vec<(i64, i64, i64)>,
    /// Evaluations: lattice point → (position, unit normal or zero).
    cache: HashMap<(i64, i64), ([f64; 3], [f64; 3])>,
    /// Most leaves the tree may grow.
    max_leaves: usize,
}

impl<'a, const D: usize, S: Surface<D> + ?Sized> QuadTree<'a, D, S> {
    fn new(surface: &'a S, base: (usize, usize), tolerance: AdaptiveTolerance) -> Self {
        let scale = 1i64 << tolerance.max_depth;
        QuadTree {
            surface,
            tolerance,
            size: (base.0 as i64 * scale, base.1 as i64 * scale),
            leaves: Vec::new(),
            cache: HashMap::new(),
            max_leaves: MAX_VERTICES,
        }
    }
    fn sample(&mut self, i: i64, j: i64) -> ([f64; 3], [f64; 3]) {
        if let Some(s) = self.cache.get(&(i, j)) {
            return *s;
        }
        let (du, dv) = (self.surface.domain_u(), self.surface.domain_v());
        let (u, v) = (lattice_param(du, i, self.size.0), lattice_param(dv, j, self.size.1));
        let mut out = [Point::<D>::zeros(); 4];
        self.surface.eval_partials(u, v, 1, 1, &mut out);
        let n = unit_normal(&out[2], &out[1]).map(|n| to3(&n)).unwrap_or([0.0; 3]);
        let s = (to3(&out[0]), n);
        self.cache.insert((i, j), s);
        s
    }
    /// How far the cell is from flat: the largest distance of its centre and edge midpoints
    /// from the bilinear patch and the straight edges through its corners, and the largest
    /// turn of the normal from its centre to its corners and midpoints, as the smallest cosine.
    fn flatness(&mut self, i: i64, j: i64, size: i64) -> (f64, f64) {
        let corners = [(i, j), (i + size, j), (i + size, j + size), (i, j + size)];
        let c: Vec<_> = corners.iter().map(|&(a, b)| self.sample(a, b)).collect();
        let h = size / 2;
        let centre = self.sample(i + h, j + h);
        let mid =
            [self.sample(i + h, j), self.sample(i + size, j + h), self.sample(i + h, j + size), self.sample(i, j + h)];
        let bilinear: [f64; 3] = std::array::from_fn(|k| 0.25 * (c[0].0[k] + c[1].0[k] + c[2].0[k] + c[3].0[k]));
        let mut chord = (v3(centre.0) - v3(bilinear)).norm();
        for k in 0..4 {
            let (a, b) = (c[k].0, c[(k + 1) % 4].0);
            let m: [f64; 3] = std::array::from_fn(|x| 0.5 * (a[x] + b[x]));
            chord = chord.max((v3(mid[k].0) - v3(m)).norm());
        }
        let mut cos: f64 = 1.0;
        for s in c.iter().chain(mid.iter()) {
            if v3(s.1).norm() > 0.5 && v3(centre.1).norm() > 0.5 {
                cos = cos.min(v3(s.1).dot(&v3(centre.1)));
            }
        }
        (chord, cos)
    }
    /// Whether the cell is farther than the chord height from flat or its normals turn.
    fn needs_split(&mut self, i: i64, j: i64, size: i64) -> bool {
        let (chord, cos) = self.flatness(i, j, size);
        chord > self.tolerance.chord_height || cos < self.tolerance.normal_angle.cos()
    }
    /// An estimate of the leaves the refinement will make, from the cells `PROBE_LEVELS`
    /// below the initial grid: a smooth surface's chord height falls as h² and its normals'
    /// turn as h in a cell of size h, so a probe cell of chord height e and turn θ becomes
    /// about max(e / chord_height, (θ / normal_angle)²) leaves (at least one, at most
    /// 4^(levels left)). Its samples stay in the cache for the refinement.
    fn estimated_leaves(&mut self, base: (usize, usize)) -> f64 {
        let probe = PROBE_LEVELS.min(self.tolerance.max_depth);
        let size = 1i64 << (self.tolerance.max_depth - probe);
        let most = 4f64.powi((self.tolerance.max_depth - probe) as i32);
        let cells = (base.0 as i64) << probe;
        let rows = (base.1 as i64) << probe;
        let mut total = 0.0;
        for a in 0..cells {
            for b in 0..rows {
                let (chord, cos) = self.flatness(a * size, b * size, size);
                let by_chord = chord / self.tolerance.chord_height;
                let by_angle = (cos.clamp(-1.0, 1.0).acos() / self.tolerance.normal_angle).powi(2);
                total += by_chord.max(by_angle).clamp(1.0, most);
            }
        }
        total
    }
    fn refine(&mut self, i: i64, j: i64, size: i64) -> Result<()> {
        if size > 1 && self.needs_split(i, j, size) {
            let h = size / 2;
            self.refine(i, j, h)?;
            self.refine(i + h, j, h)?;
            self.refine(i, j + h, h)?;
            self.refine(i + h, j + h, h)?;
        } else {
            self.leaves.push((i, j, size));
            if self.leaves.len() > self.max_leaves {
                return Err(Error::invalid(
                    "tolerance",
                    format!(
                        "{:?} needs more than {} cells, the budget of this mesh",
                        self.tolerance.chord_height, self.max_leaves
                    ),
                ));
            }
        }
        Ok(())
    }
    /// Every corner of a leaf, with the size of the smallest leaf it is a corner of, in
    /// lattice order (the trimmed mesh inserts them in this order, so it fixes the mesh).
    fn leaf_corners(&self) -> BTreeMap<(i64, i64), i64> {
        let mut out: BTreeMap<(i64, i64), i64> = BTreeMap::new();
        for &(i, j, size) in &self.leaves {
            for corner in [(i, j), (i + size, j), (i + size, j + size), (i, j + size)] {
                let s = out.entry(corner).or_insert(size);
                *s = (*s).min(size);
            }
        }
        out
    }
}

/// Triangulates the leaves of an untrimmed quad-tree into one crack-free mesh.
struct Stitcher<'t, 'a, const D: usize, S: Surface<D> + ?Sized> {
    tree: &'t mut QuadTree<'a, D, S>,
    gluing: Gluing,
    options: MeshOptions,
    /// Lattice points that are leaf corners, by their fully glued node.
    present: HashSet<Node>,
    /// Vertex of each node (seams glued unless (u, v) is stored).
    vertices: HashMap<Node, u32>,
    mesh: TriangleMesh,
}

impl<'t, 'a, const D: usize, S: Surface<D> + ?Sized> Stitcher<'t, 'a, D, S> {
    fn new(tree: &'t mut QuadTree<'a, D, S>, options: MeshOptions) -> Self {
        let gluing = Gluing::detect(tree.surface);
        let size = tree.size;
        let present = tree
            .leaves
            .iter()
            .flat_map(|&(i, j, s)| [(i, j), (i + s, j), (i + s, j + s), (i, j + s)])
            .map(|(i, j)| gluing.node(i, j, size, true))
            .collect();
        Stitcher { tree, gluing, options, present, vertices: HashMap::new(), mesh: TriangleMesh::default() }
    }
    fn vertex(&mut self, i: i64, j: i64) -> Result<u32> {
        let size = self.tree.size;
        let node = self.gluing.node(i, j, size, !self.options.uv);
        if let Some(&v) = self.vertices.get(&node) {
            return Ok(v);
        }
        if self.mesh.positions.len() >= MAX_VERTICES {
            return Err(Error::invalid("tolerance", format!("needs more than {MAX_VERTICES} vertices")));
        }
        let (p, n, uv) = match self.gluing.node(i, j, size, true) {
            Node::Pole(c) => {
                let pole = self.gluing.pole(c);
                (pole.position, pole.normal.unwrap_or([0.0; 3]), pole.uv)
            }
            Node::Grid(a, b) => {
                let (p, n) = self.tree.sample(a, b);
                (p, n, [i as f64 / size.0 as f64, j as f64 / size.1 as f64])
            }
        };
        let idx = self.mesh.positions.len() as u32;
        self.mesh.positions.push(p);
        self.mesh.normals.push(n);
        if self.options.uv {
            self.mesh.uvs.push(uv);
        }
        self.vertices.insert(node, idx);
        Ok(idx)
    }
    /// Lattice points strictly inside the axis-aligned lattice edge from `a` to `b` (length
    /// a power of two) that are corners of some leaf, in order: found by looking for
    /// midpoints recursively. Edges along a pole have none.
    fn edge_points(&self, a: (i64, i64), b: (i64, i64), out: &mut Vec<(i64, i64)>) {
        let len = (b.0 - a.0).abs().max((b.1 - a.1).abs());
        let size = self.tree.size;
        let node = |p: (i64, i64)| self.gluing.node(p.0, p.1, size, true);
        if len < 2 || (matches!(node(a), Node::Pole(_)) && node(a) == node(b)) {
            return;
        }
        let m = ((a.0 + b.0) / 2, (a.1 + b.1) / 2);
        if self.present.contains(&node(m)) {
            self.edge_points(a, m, out);
            out.push(m);
            self.edge_points(m, b, out);
        }
    }
    fn triangulate(mut self) -> Result<TriangleMesh> {
        let leaves = std::mem::take(&mut self.tree.leaves);
        let mut ring_points = Vec::new();
        for (i, j, size) in leaves {
            let corners = [(i, j), (i + size, j), (i + size, j + size), (i, j + size)];
            ring_points.clear();
            for k in 0..4 {
                ring_points.push(corners[k]);
                self.edge_points(corners[k], corners[(k + 1) % 4], &mut ring_points);
            }
            let ring = ring_points.iter().map(|&(a, b)| self.vertex(a, b)).collect::<Result<Vec<u32>>>()?;
            if ring.len() == 4 {
                self.mesh.triangles.push([ring[0], ring[1], ring[2]]);
                self.mesh.triangles.push([ring[0], ring[2], ring[3]]);
            } else {
                let h = size / 2;
                let c = self.vertex(i + h, j + h)?;
                for k in 0..ring.len() {
                    self.mesh.triangles.push([c, ring[k], ring[(k + 1) % ring.len()]]);
                }
            }
        }
        Ok(self.mesh)
    }
}
