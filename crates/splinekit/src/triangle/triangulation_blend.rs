//! A blending-spline surface over a whole triangulated surface: one local patch per vertex,
//! blended over each triangle by weights of its three vertices (GERBS beyond one triangle).
//!
//! # The parametrisation: an equilateral flat structure
//!
//! Every triangle τ of the triangulation is taken as a unit *equilateral* triangle and
//! neighbours are glued isometrically along their edges. Across an edge a–b the barycentric
//! coordinates of the two triangles τ = (a, b, c) and τ' (with fourth vertex d = a + b − c in
//! the rhombus they make) are related by the *affine* map λ_a = λ'_a + λ'_d,
//! λ_b = λ'_b + λ'_d, λ_c = −λ'_d. This gives the triangulated surface, minus its vertices, a
//! smooth (indeed flat) structure in which "smooth across an edge" has a meaning; every
//! vertex of valence n ≠ 6 is a cone point of angle n·60°.
//!
//! # The locals and their charts
//!
//! Vertex i of valence n has the chart ζ_i = z^{α} of its star (Ying and Zorin's
//! construction, *A simple manifold-based construction of surfaces of arbitrary
//! smoothness*, 2004): z is the complex coordinate of the star unfolded flat about i (the
//! k-th triangle of its fan between the angles k·60° and (k + 1)·60°; in triangle (i, a, b)
//! z = λ_a + λ_b e^{iπ/3} turned by k·60°), and α = 6/n for an interior vertex (the cone
//! opened to a full disc) or min(1, 3/n) on the boundary (a fan of more than three
//! triangles opened to a half-disc). z^α is
//! analytic away from z = 0, so the chart is smooth in the flat structure everywhere in
//! the star except at i itself, where it *defines* the smooth structure. The neighbours
//! lie on the unit circle, |ζ| ≤ 1 on the star.
//!
//! Local i is a polynomial patch L_i: ζ ↦ ℝ³ (a Bézier patch of degree (d, d) over
//! ζ ∈ [−1, 1]², which users may edit). Fitted to Hermite data (position p_i, unit normal
//! n_i: given, or the area-weighted mean of the face normals), it is the quadratic
//! L_i(ζ) = p_i + J ζ + Q(ζ), ζ = X + iY, with J: ℝ² → the tangent plane ⊥ n_i (so the
//! surface has the normal n_i at the vertex) and Q quadratic (degree 1 drops it): the
//! least-squares fit, L_i(ζ_i(λ)) ≈ R(λ), to samples of a reference surface R over the disc
//! r_i < ρ where local i's weight lives (a lattice of 45 points per triangle). R is the
//! mesh's PN triangles (cubic Bézier triangles from the corners' positions and normals,
//! continuous across edges): fitting every local to one surface parametrised over the flat
//! structure makes neighbouring locals agree in the tangential direction too, so that
//! blending them averages nearly the same points (fitting each local to its ring of
//! neighbours alone lets them disagree by a good part of an edge, which the blend turns
//! into an error of curvature × that², off the surface). Each local carries an affine frame
//! F_i acting about its origin L_i(0) = p_i.
//!
//! # The weights: radial B-functions of the flat distance
//!
//! With r_i the flat distance from vertex i (in triangle (i, a, b):
//! r_i² = λ_a² + λ_a λ_b + λ_b², the law of cosines with the 60° corner) and ρ = √3/2 (the
//! distance from a vertex to the opposite edge),
//!
//! b_i = B(1 − r_i/ρ) for r_i < ρ, else 0;   β_i = b_i / Σ_j b_j,
//!
//! where B is the 1-D B-function. b_i is supported in the disc of radius ρ about i, which lies
//! in i's star; it is as smooth as B in the flat structure (r_i is analytic away from i, B is
//! flat at 0 where the disc ends and at 1 at the vertex). At most three discs meet in a
//! triangle, and their sum never vanishes (every point is within 1/√3 < ρ of a corner).
//! Within 1 − ρ ≈ 0.13 of vertex i only b_i is non-zero: β_i ≡ 1 there.
//!
//! *Why not the triangular B-functions B(λ_i) of a GERBS triangle*: λ_i is the
//! piecewise-linear hat of i's star; it has a kink across every edge i–j, where B′(λ_i) ≠ 0,
//! so weights made from it are only C⁰ across the triangulation's edges. The radial form
//! replaces the hat by the flat distance, which has no kink there.
//!
//! # The surface
//!
//! On triangle τ with corners c₀, c₁, c₂ and (u, v, w) = (λ_{c₀}, λ_{c₁}, λ_{c₂}),
//!
//! S_τ(u, v) = Σ_m β_{c_m}(u, v) F_{c_m}(L_{c_m}(ζ_{c_m}(u, v))),
//!
//! with partials of every order by the Leibniz rule and the chain rule carried in jets
//! ([`crate::triangle::jet`]). Properties:
//!
//! * **Interpolation**: within 1 − ρ of vertex i, S = F_i ∘ L_i ∘ ζ_i exactly (value and
//!   every derivative): the surface passes through F_i(p_i) with the local's tangent plane
//!   and curvature.
//! * **Smoothness**: every β_i and every L_i ∘ ζ_i is as smooth as B in the flat structure
//!   away from the vertices, so S is C^k across every edge (k the B-function's flatness;
//!   C^∞ for ERBS) in the sense that S_τ and S_τ' composed with the affine transition above
//!   have equal derivatives on their common edge. At vertex i, S is F_i ∘ L_i in the chart
//!   ζ_i. In a triangle's own (u, v) the parametrisation is singular at a corner of valence
//!   n ≠ 6 (ζ = z^α there): its first partials vanish (n < 6) or blow up (n > 6), so partials
//!   of order ≥ 1 at exactly such a corner are NaN while the point and normal are the local's.
//! * **Locality**: moving local i (its frame) changes S only on the triangles of i's star;
//!   elsewhere the evaluation does not read local i at all.
//! * **Partition of unity**: Σ β = 1, so an affine map applied to every local maps S.

use std::collections::HashMap;
use std::f64::consts::PI;
use std::sync::Arc;

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::{BFunction, binomial};
use crate::error::{Error, Result};
use crate::frame::Affine;
use crate::surface::{BezierSurface, Surface, unit_normal};
use crate::triangle::atlas::TriangleAtlas;
use crate::triangle::jet::{ComplexJet, Jet, compose_point};
use crate::triangle::traits::{Triangle, clamp_to_triangle, clamp_uv};

/// ρ = √3/2: the support radius of the radial weights in the flat structure.
pub const SUPPORT_RADIUS: f64 = 0.866_025_403_784_438_6;

/// A triangulated surface: positions, counter-clockwise triangles (seen from the side the
/// normals point to) and optionally unit normals.
#[derive(Debug, Clone, PartialEq)]
pub struct TriangulatedSurface {
    /// Vertex positions.
    pub positions: Vec<Point<3>>,
    /// Vertex normals (one per vertex), or empty to estimate them.
    pub normals: Vec<Point<3>>,
    /// Triangles as vertex numbers.
    pub triangles: Vec<[u32; 3]>,
}

impl TriangulatedSurface {
    /// The sphere of `radius` about the origin triangulated over the icosahedron, each
    /// triangle split into four `subdivisions` times (new vertices projected onto the
    /// sphere); exact normals. 12 vertices of valence 5, the others of valence 6.
    pub fn icosphere(radius: f64, subdivisions: usize) -> Result<Self> {
        if !(radius.is_finite() && radius > 0.0) {
            return Err(Error::invalid("radius", format!("must be positive and finite, got {radius}")));
        }
        if subdivisions > 6 {
            return Err(Error::invalid("subdivisions", format!("must be at most 6, got {subdivisions}")));
        }
        let g = (1.0 + 5f64.sqrt()) / 2.0;
        let mut p: Vec<Point<3>> = [
            (-1.0, g, 0.0),
            (1.0, g, 0.0),
            (-1.0, -g, 0.0),
            (1.0, -g, 0.0),
            (0.0, -1.0, g),
            (0.0, 1.0, g),
            (0.0, -1.0, -g),
            (0.0, 1.0, -g),
            (g, 0.0, -1.0),
            (g, 0.0, 1.0),
            (-g, 0.0, -1.0),
            (-g, 0.0, 1.0),
        ]
        .iter()
        .map(|&(x, y, z)| Point::<3>::new(x, y, z).normalize())
        .collect();
        let mut t: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..subdivisions {
            let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
            let mut next = Vec::with_capacity(t.len() * 4);
            let mut m = |a: u32, b: u32, p: &mut Vec<Point<3>>| {
                *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    p.push(((p[a as usize] + p[b as usize]) / 2.0).normalize());
                    (p.len() - 1) as u32
                })
            };
            for &[a, b, c] in &t {
                let (ab, bc, ca) = (m(a, b, &mut p), m(b, c, &mut p), m(c, a, &mut p));
                next.extend_from_slice(&[[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
            }
            t = next;
        }
        Ok(TriangulatedSurface { positions: p.iter().map(|q| q * radius).collect(), normals: p, triangles: t })
    }

    /// The torus ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) sampled on an n_u × n_v
    /// grid of (u, v) ∈ [0, 2π)², each cell split along its diagonal (every vertex of
    /// valence 6); exact normals.
    pub fn torus(major_radius: f64, minor_radius: f64, nu: usize, nv: usize) -> Result<Self> {
        for (name, x) in [("major_radius", major_radius), ("minor_radius", minor_radius)] {
            if !(x.is_finite() && x > 0.0) {
                return Err(Error::invalid(name, format!("must be positive and finite, got {x}")));
            }
        }
        if !(3..=1000).contains(&nu) || !(3..=1000).contains(&nv) {
            return Err(Error::invalid("segments", format!("need 3 to 1000 each way, got [{nu}, {nv}]")));
        }
        let mut positions = Vec::with_capacity(nu * nv);
        let mut normals = Vec::with_capacity(nu * nv);
        for i in 0..nu {
            let u = 2.0 * PI * i as f64 / nu as f64;
            for j in 0..nv {
                let v = 2.0 * PI * j as f64 / nv as f64;
                let n = Point::<3>::new(v.cos() * u.cos(), v.cos() * u.sin(), v.sin());
                let c = Point::<3>::new(major_radius * u.cos(), major_radius * u.sin(), 0.0);
                positions.push(c + n * minor_radius);
                normals.push(n);
            }
        }
        let id = |i: usize, j: usize| ((i % nu) * nv + j % nv) as u32;
        let mut triangles = Vec::with_capacity(2 * nu * nv);
        for i in 0..nu {
            for j in 0..nv {
                triangles.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                triangles.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
        Ok(TriangulatedSurface { positions, normals, triangles })
    }
}

#[derive(Debug, Clone)]
struct Local {
    patch: BezierSurface<3>,
    origin: Point<3>,
    frame: Affine<3>,
}

#[derive(Debug)]
struct BlendData {
    positions: Vec<Point<3>>,
    triangles: Vec<[u32; 3]>,
    /// Per triangle, per corner: the triangle's place k in that vertex's fan.
    fan: Vec<[u32; 3]>,
    /// Per vertex: its triangles and its corner in each.
    incident: Vec<Vec<(usize, usize)>>,
    /// Per vertex: α (6/n inside, 3/n on the boundary) and the valence n.
    alpha: Vec<f64>,
    valence: Vec<u32>,
    boundary: Vec<bool>,
    normals: Vec<Point<3>>,
    locals: Vec<Local>,
    bfunction: BFunction,
}

/// The blending-spline surface over a triangulated surface (see the module documentation).
#[derive(Debug, Clone)]
pub struct TriangulationBlend {
    data: Arc<BlendData>,
}

/// Solves the symmetric system A x = b (n ≤ 3) with a little Tikhonov damping, so that
/// rings too small to fix every coefficient give the smallest ones that fit.
fn solve_damped<const N: usize>(a: [[f64; N]; N], b: [f64; N]) -> [f64; N] {
    let trace: f64 = (0..N).map(|i| a[i][i]).sum();
    let m = nalgebra::SMatrix::<f64, N, N>::from_fn(|i, j| a[i][j] + if i == j { 1e-12 * trace } else { 0.0 });
    let v = nalgebra::SVector::<f64, N>::from_fn(|i, _| b[i]);
    match m.cholesky() {
        Some(c) => {
            let x = c.solve(&v);
            std::array::from_fn(|i| x[i])
        }
        None => [0.0; N],
    }
}

/// The Bézier patch of degree (d, d) over ζ ∈ [−1, 1]² (s = (X + 1)/2, t = (Y + 1)/2) of the
/// polynomial Σ c[a][b] X^a Y^b (a + b ≤ d).
fn monomial_patch(d: usize, c: &[Vec<Point<3>>]) -> Result<BezierSurface<3>> {
    // X^a = Σ_k C(a, k) 2^k (−1)^{a−k} s^k; s^k = Σ_{i≥k} C(i, k)/C(d, k) B_i^d(s).
    let expand = |a: usize, k: usize| -> f64 {
        if k > a { 0.0 } else { binomial(a, k) * 2f64.powi(k as i32) * if (a - k) % 2 == 0 { 1.0 } else { -1.0 } }
    };
    let mut net = vec![vec![Point::<3>::zeros(); d + 1]; d + 1];
    for (a, row) in c.iter().enumerate() {
        for (b, coef) in row.iter().enumerate() {
            for k in 0..=a {
                for l in 0..=b {
                    let power = expand(a, k) * expand(b, l);
                    if power == 0.0 {
                        continue;
                    }
                    for (i, net_row) in net.iter_mut().enumerate().skip(k) {
                        for (j, q) in net_row.iter_mut().enumerate().skip(l) {
                            *q += coef * (power * binomial(i, k) / binomial(d, k) * binomial(j, l) / binomial(d, l));
                        }
                    }
                }
            }
        }
    }
    BezierSurface::new(net)
}

impl TriangulationBlend {
    /// The blending surface of `surface` with locals of `degree` (1: tangent planes, 2:
    /// osculating paraboloids) fitted to each vertex's position, normal and ring, blended by
    /// `bfunction`.
    ///
    /// # Errors
    ///
    /// Non-finite positions or normals, triangle indices out of range or repeated, triangles
    /// not consistently oriented or not forming a manifold around a vertex (naming
    /// `triangles[t]` or `vertices[i]`), a vertex in no triangle, a degree other than 1 or 2.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::basis::BFunction;
    /// use splinekit::triangle::{Triangle, TriangulatedSurface, TriangulationBlend};
    /// let sphere = TriangulatedSurface::icosphere(1.0, 1).unwrap();
    /// let s = TriangulationBlend::new(&sphere, 2, BFunction::erbs_default()).unwrap();
    /// // It passes through every vertex, and stays close to the sphere in between.
    /// let t = s.triangle(7);
    /// let corner = t.point(1.0, 0.0, 0.0);
    /// assert!((corner - sphere.positions[sphere.triangles[7][0] as usize]).norm() < 1e-15);
    /// assert!((t.point(0.3, 0.3, 0.4).norm() - 1.0).abs() < 0.02);
    /// ```
    pub fn new(surface: &TriangulatedSurface, degree: usize, bfunction: BFunction) -> Result<Self> {
        if !(1..=2).contains(&degree) {
            return Err(Error::invalid("degree", format!("a fitted local has degree 1 or 2, got {degree}")));
        }
        let mut data = Self::topology(surface, bfunction)?;
        let n = data.positions.len();
        let mut locals = Vec::with_capacity(n);
        for i in 0..n {
            let patch = data.fit(i, degree)?;
            // The local's own value at ζ = 0 (the vertex, to an ulp of the net's arithmetic).
            let origin = patch.point(0.5, 0.5);
            locals.push(Local { patch, origin, frame: Affine::identity() });
        }
        data.locals = locals;
        Ok(TriangulationBlend { data: Arc::new(data) })
    }

    /// Checks the triangulation and builds the fans, normals and charts (no locals yet).
    fn topology(surface: &TriangulatedSurface, bfunction: BFunction) -> Result<BlendData> {
        let positions = surface.positions.clone();
        let n = positions.len();
        if n < 3 || surface.triangles.is_empty() {
            return Err(Error::invalid("triangles", "need at least one triangle"));
        }
        if let Some(i) = positions.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(Error::invalid(format!("vertices[{i}]"), "is not finite"));
        }
        let mut next: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
        for (t, tri) in surface.triangles.iter().enumerate() {
            for (m, &c) in tri.iter().enumerate() {
                if c as usize >= n {
                    return Err(Error::invalid(
                        format!("triangles[{t}]"),
                        format!("vertex {c} does not exist (there are {n})"),
                    ));
                }
                if tri[(m + 1) % 3] == c {
                    return Err(Error::invalid(format!("triangles[{t}]"), "repeats a vertex"));
                }
                if next.insert((c, tri[(m + 1) % 3]), (t, m)).is_some() {
                    return Err(Error::invalid(
                        format!("triangles[{t}]"),
                        format!(
                            "the edge {c}–{} is used twice in the same direction: triangles are inconsistently oriented or the surface is not a manifold there",
                            tri[(m + 1) % 3]
                        ),
                    ));
                }
            }
        }
        // Fans: around vertex i, triangle (i, a, b) is followed by the one starting i → b.
        let mut incident: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
        for (t, tri) in surface.triangles.iter().enumerate() {
            for m in 0..3 {
                incident[tri[m] as usize].push((t, m));
            }
        }
        let mut fan = vec![[0u32; 3]; surface.triangles.len()];
        let (mut alpha, mut valence, mut boundary) = (vec![1.0; n], vec![0u32; n], vec![false; n]);
        for i in 0..n {
            let around = &incident[i];
            if around.is_empty() {
                return Err(Error::invalid(format!("vertices[{i}]"), "is in no triangle"));
            }
            let tri = |&(t, m): &(usize, usize)| {
                let c = surface.triangles[t];
                (c[(m + 1) % 3], c[(m + 2) % 3])
            };
            // A start without a predecessor (boundary), else any.
            let start = around
                .iter()
                .copied()
                .find(|tm| {
                    let (a, _) = tri(tm);
                    !around.iter().any(|o| tri(o).1 == a)
                })
                .unwrap_or(around[0]);
            let is_boundary = around.iter().any(|tm| {
                let (a, _) = tri(tm);
                !around.iter().any(|o| tri(o).1 == a)
            });
            let mut current = start;
            let mut k = 0u32;
            loop {
                fan[current.0][current.1] = k;
                k += 1;
                let (_, b) = tri(&current);
                match next.get(&(i as u32, b)) {
                    Some(&tm) if tm != start => current = tm,
                    _ => break,
                }
                if k as usize > around.len() {
                    break;
                }
            }
            if k as usize != around.len() {
                return Err(Error::invalid(
                    format!("vertices[{i}]"),
                    format!("its {} triangles do not make one fan (the surface is not a manifold there)", around.len()),
                ));
            }
            valence[i] = k;
            boundary[i] = is_boundary;
            // A boundary fan of at most three triangles (180°) is a planar chart as it is.
            alpha[i] = if is_boundary { (3.0 / k as f64).min(1.0) } else { 6.0 / k as f64 };
        }
        let normals = if surface.normals.is_empty() {
            let mut sum = vec![Point::<3>::zeros(); n];
            for tri in &surface.triangles {
                let [a, b, c] = tri.map(|x| positions[x as usize]);
                let f = (b - a).cross(&(c - a));
                for &x in tri {
                    sum[x as usize] += f;
                }
            }
            let mut out = Vec::with_capacity(n);
            for (i, s) in sum.iter().enumerate() {
                let len = s.norm();
                if !(len > 0.0 && len.is_finite()) {
                    return Err(Error::invalid(
                        format!("vertices[{i}]"),
                        "its triangles have no area to take a normal from",
                    ));
                }
                out.push(s / len);
            }
            out
        } else {
            if surface.normals.len() != n {
                return Err(Error::count("normals", format!("{n} vectors, one per vertex"), surface.normals.len()));
            }
            let mut out = Vec::with_capacity(n);
            for (i, v) in surface.normals.iter().enumerate() {
                let len = v.norm();
                if !(len > 0.0 && len.is_finite()) {
                    return Err(Error::invalid(format!("normals[{i}]"), "must be finite and non-zero"));
                }
                out.push(v / len);
            }
            out
        };
        Ok(BlendData {
            positions,
            triangles: surface.triangles.clone(),
            fan,
            incident,
            alpha,
            valence,
            boundary,
            normals,
            locals: Vec::new(),
            bfunction,
        })
    }

    /// The number of vertices (and locals).
    pub fn vertex_count(&self) -> usize {
        self.data.positions.len()
    }

    /// The triangles.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.data.triangles
    }

    /// The vertex positions (the locals' origins before any frame).
    pub fn positions(&self) -> &[Point<3>] {
        &self.data.positions
    }

    /// The unit normal at each vertex (given or estimated).
    pub fn normals(&self) -> &[Point<3>] {
        &self.data.normals
    }

    /// Vertex i's valence (triangles around it) and whether it is on the boundary.
    pub fn valence(&self, i: usize) -> (usize, bool) {
        (self.data.valence[i] as usize, self.data.boundary[i])
    }

    /// The B-function.
    pub fn bfunction(&self) -> &BFunction {
        &self.data.bfunction
    }

    /// Local i's patch over ζ ∈ [−1, 1]², without its frame.
    pub fn local(&self, i: usize) -> Option<&BezierSurface<3>> {
        self.data.locals.get(i).map(|l| &l.patch)
    }

    /// Local i's origin L_i(0), the point its frame acts about.
    pub fn origin(&self, i: usize) -> Option<Point<3>> {
        self.data.locals.get(i).map(|l| l.origin)
    }

    /// Local i's frame.
    pub fn frame(&self, i: usize) -> Option<&Affine<3>> {
        self.data.locals.get(i).map(|l| &l.frame)
    }

    /// Every local's frame, by vertex.
    pub fn frames(&self) -> Vec<Affine<3>> {
        self.data.locals.iter().map(|l| l.frame).collect()
    }

    fn check_vertex(&self, i: usize) -> Result<()> {
        if i < self.vertex_count() {
            Ok(())
        } else {
            Err(Error::invalid("local", format!("vertex {i} does not exist (there are {})", self.vertex_count())))
        }
    }

    /// Sets local i's frame (acting about its origin).
    pub fn set_frame(&mut self, i: usize, frame: Affine<3>) -> Result<()> {
        self.check_vertex(i)?;
        self.data_mut().locals[i].frame = frame;
        Ok(())
    }

    /// Replaces local i's patch (an edited net over ζ ∈ [−1, 1]²); its origin becomes its
    /// value at ζ = 0.
    pub fn set_local(&mut self, i: usize, patch: BezierSurface<3>) -> Result<()> {
        self.check_vertex(i)?;
        let origin = patch.point(0.5, 0.5);
        let l = &mut self.data_mut().locals[i];
        l.patch = patch;
        l.origin = origin;
        Ok(())
    }

    fn data_mut(&mut self) -> &mut BlendData {
        let d = &self.data;
        if Arc::strong_count(d) > 1 {
            let copy = BlendData {
                positions: d.positions.clone(),
                triangles: d.triangles.clone(),
                fan: d.fan.clone(),
                incident: d.incident.clone(),
                alpha: d.alpha.clone(),
                valence: d.valence.clone(),
                boundary: d.boundary.clone(),
                normals: d.normals.clone(),
                locals: d.locals.clone(),
                bfunction: d.bfunction.clone(),
            };
            self.data = Arc::new(copy);
        }
        Arc::get_mut(&mut self.data).expect("unique after the copy")
    }

    /// Triangle t as a [`Triangle`], corners u, v, w at its vertices in the given order.
    ///
    /// # Panics
    ///
    /// If t is not a triangle's number.
    pub fn triangle(&self, t: usize) -> BlendTriangle {
        assert!(t < self.data.triangles.len(), "triangle {t} of {}", self.data.triangles.len());
        BlendTriangle { data: self.data.clone(), index: t }
    }

    /// The weights (β at corner u, v, w) at (u, v, 1 − u − v): the same functions in every
    /// triangle (each is equilateral in the flat structure).
    pub fn weights(&self, u: f64, v: f64) -> [f64; 3] {
        let (u, v) = clamp_uv(u, v);
        let lam = [Jet::constant(0, 0, u), Jet::constant(0, 0, v), Jet::constant(0, 0, 1.0 - u - v)];
        let b = self.data.weight_jets(&lam).map(|b| b.as_ref().map_or(0.0, Jet::value));
        let sum = b[0] + b[1] + b[2];
        b.map(|x| x / sum)
    }

    /// The chart point ζ (as (X, Y)) of vertex `corner` (0, 1, 2) of triangle t at its
    /// barycentric (u, v, 1 − u − v).
    pub fn chart_point(&self, t: usize, corner: usize, u: f64, v: f64) -> Point<2> {
        let lam = [Jet::constant(0, 0, u), Jet::constant(0, 0, v), Jet::constant(0, 0, 1.0 - u - v)];
        let z = self.data.chart_jet(t, corner, &lam);
        Point::<2>::new(z.re.value(), z.im.value())
    }

    /// Local i with its frame at the chart point ζ: its partials ∂^{a+b}/∂X^a∂Y^b for
    /// a ≤ `dx`, b ≤ `dy` into `out[a·(dy+1) + b]`.
    pub fn local_partials(&self, i: usize, zeta: Point<2>, dx: usize, dy: usize, out: &mut [Point<3>]) -> Result<()> {
        self.check_vertex(i)?;
        self.data.local_partials(i, zeta, dx, dy, out);
        Ok(())
    }

    /// The surface as an atlas of its triangles (corners shared, so meshes weld).
    pub fn atlas(&self) -> TriangleAtlas<3> {
        let charts =
            (0..self.data.triangles.len()).map(|t| Arc::new(self.triangle(t)) as Arc<dyn Triangle<3>>).collect();
        TriangleAtlas::with_corner_ids(charts, self.data.triangles.clone())
            .expect("one corner triple per triangle")
            .with_enclosing_box(self.enclosing_box())
    }

    /// A box that holds the surface: that of every local's control net in its frame. On each
    /// triangle S is a convex combination (β ≥ 0, Σ β = 1) of locals evaluated at |ζ| ≤ 1, in
    /// the square [−1, 1]² their Bézier nets span, so within the hull of the framed nets.
    pub fn enclosing_box(&self) -> crate::query::Aabb<3> {
        let points: Vec<Point<3>> = self
            .data
            .locals
            .iter()
            .flat_map(|l| {
                l.patch.control_points().iter().flatten().map(move |p| l.frame.apply_point_about(&l.origin, p))
            })
            .collect();
        crate::query::Aabb::around(&points, 0.0)
    }
}

impl BlendData {
    /// Fits vertex i's local of `degree` (see the module documentation).
    fn fit(&self, i: usize, degree: usize) -> Result<BezierSurface<3>> {
        let p = self.positions[i];
        let nrm = self.normals[i];
        let helper = if nrm.x.abs() < 0.9 { Point::<3>::x() } else { Point::<3>::y() };
        let t1 = nrm.cross(&helper).normalize();
        let t2 = nrm.cross(&t1);
        // Samples of the reference surface (each triangle's PN triangle) over the disc
        // r_i < ρ where local i's weight lives, at their chart points.
        let mut ring: Vec<(Point<2>, Point<3>)> = Vec::new();
        const LEVEL: usize = 8;
        for &(t, m) in &self.incident[i] {
            {
                let reference = self.pn_triangle(t);
                for a in 0..=LEVEL {
                    for bb in 0..=LEVEL - a {
                        let (la, lb) = (a as f64 / LEVEL as f64, bb as f64 / LEVEL as f64);
                        if (la * la + la * lb + lb * lb).sqrt() >= SUPPORT_RADIUS || (la == 0.0 && lb == 0.0) {
                            continue;
                        }
                        let mut lam = [0.0; 3];
                        lam[m] = 1.0 - la - lb;
                        lam[(m + 1) % 3] = la;
                        lam[(m + 2) % 3] = lb;
                        let jets = lam.map(|x| Jet::constant(0, 0, x));
                        let z = self.chart_jet(t, m, &jets);
                        ring.push((
                            Point::<2>::new(z.re.value(), z.im.value()),
                            reference.point(lam[0], lam[1], lam[2]),
                        ));
                    }
                }
            }
        }
        // Tangential components: linear in ζ (degree 1, or rings of fewer than five), else a
        // full quadratic; the normal component: the quadratic h₂₀X² + h₁₁XY + h₀₂Y².
        let quadratic = degree == 2;
        let basis = |z: &Point<2>| [z.x, z.y, z.x * z.x, z.x * z.y, z.y * z.y];
        let (mut a, mut b1, mut b2) = ([[0.0; 5]; 5], [0.0; 5], [0.0; 5]);
        let k = if quadratic { 5 } else { 2 };
        for (z, q) in &ring {
            let d = q - p;
            let f = basis(z);
            for r in 0..k {
                for c in 0..k {
                    a[r][c] += f[r] * f[c];
                }
                b1[r] += f[r] * d.dot(&t1);
                b2[r] += f[r] * d.dot(&t2);
            }
        }
        if !quadratic {
            for (r, row) in a.iter_mut().enumerate().skip(2) {
                row[r] = 1.0;
            }
        }
        let (j1, j2) = (solve_damped(a, b1), solve_damped(a, b2));
        let tangential = |r: usize| t1 * j1[r] + t2 * j2[r];
        let mut c = vec![vec![Point::<3>::zeros(); degree + 1]; degree + 1];
        c[0][0] = p;
        c[1][0] = tangential(0);
        c[0][1] = tangential(1);
        if degree == 2 {
            let (mut a, mut b) = ([[0.0; 3]; 3], [0.0; 3]);
            for (z, q) in &ring {
                let f = [z.x * z.x, z.x * z.y, z.y * z.y];
                let h = (q - p).dot(&nrm);
                for r in 0..3 {
                    for s in 0..3 {
                        a[r][s] += f[r] * f[s];
                    }
                    b[r] += f[r] * h;
                }
            }
            let h = solve_damped(a, b);
            c[2][0] = nrm * h[0] + tangential(2);
            c[1][1] = nrm * h[1] + tangential(3);
            c[0][2] = nrm * h[2] + tangential(4);
        }
        monomial_patch(degree, &c).map_err(|e| Error::invalid(format!("vertices[{i}]"), e.to_string()))
    }

    /// Triangle t's PN triangle (Vlachos, Peters, Boyd and Mitchell, *Curved PN triangles*,
    /// 2001): the cubic Bézier triangle through its corners with their normals, each edge
    /// point the corner's third-point projected onto its tangent plane,
    /// b₂₁₀ = (2P₁ + P₂ − ((P₂ − P₁)·N₁) N₁)/3, and b₁₁₁ = E + (E − V)/2 (E the mean of the six
    /// edge points, V of the corners). Neighbours share their edges' cubics, so the
    /// triangles make a continuous reference surface that the locals are fitted to.
    fn pn_triangle(&self, t: usize) -> crate::triangle::BezierTriangle<3> {
        let c = self.triangles[t].map(|x| x as usize);
        let (p, n) = (c.map(|i| self.positions[i]), c.map(|i| self.normals[i]));
        let edge = |i: usize, j: usize| (p[i] * 2.0 + p[j] - n[i] * (p[j] - p[i]).dot(&n[i])) / 3.0;
        let e: Point<3> = (edge(0, 1) + edge(1, 0) + edge(1, 2) + edge(2, 1) + edge(2, 0) + edge(0, 2)) / 6.0;
        let v = (p[0] + p[1] + p[2]) / 3.0;
        crate::triangle::BezierTriangle::from_fn(3, |(a, b, k)| match (a, b, k) {
            (3, 0, 0) => p[0],
            (0, 3, 0) => p[1],
            (0, 0, 3) => p[2],
            (2, 1, 0) => edge(0, 1),
            (1, 2, 0) => edge(1, 0),
            (0, 2, 1) => edge(1, 2),
            (0, 1, 2) => edge(2, 1),
            (1, 0, 2) => edge(2, 0),
            (2, 0, 1) => edge(0, 2),
            _ => e + (e - v) / 2.0,
        })
        .expect("a cubic net of finite points")
    }

    /// The jets of b at the three corners (`None` where b ≡ 0 near the point) from the
    /// barycentric jets λ.
    fn weight_jets(&self, lam: &[Jet; 3]) -> [Option<Jet>; 3] {
        let (p, q) = lam[0].orders();
        let n = p + q;
        let mut d: SmallVec<[f64; 8]> = smallvec![0.0; n + 1];
        std::array::from_fn(|m| {
            let (la, lb) = (&lam[(m + 1) % 3], &lam[(m + 2) % 3]);
            let r2 = la.mul(la).add(&la.mul(lb)).add(&lb.mul(lb));
            let r0 = r2.value().max(0.0).sqrt();
            if r0 >= SUPPORT_RADIUS {
                return None;
            }
            if r0 == 0.0 {
                return Some(Jet::constant(p, q, 1.0));
            }
            let s = r2.sqrt().scale(-1.0 / SUPPORT_RADIUS).shift(1.0);
            self.bfunction.eval(s.value(), &mut d);
            Some(s.compose(&d))
        })
    }

    /// ζ of corner m of triangle t as a complex jet of the barycentric jets λ.
    fn chart_jet(&self, t: usize, m: usize, lam: &[Jet; 3]) -> ComplexJet {
        let i = self.triangles[t][m] as usize;
        let (la, lb) = (&lam[(m + 1) % 3], &lam[(m + 2) % 3]);
        let h = 3f64.sqrt() / 2.0;
        let z = ComplexJet { re: la.add(&lb.scale(0.5)), im: lb.scale(h) };
        let alpha = self.alpha[i];
        let turn = alpha * self.fan[t][m] as f64 * PI / 3.0;
        let powered = if alpha == 1.0 {
            z
        } else if z.re.value() == 0.0 && z.im.value() == 0.0 {
            // The corner itself: ζ = 0; its derivatives in (u, v) do not exist for α ≠ 1.
            let (p, q) = la.orders();
            ComplexJet { re: Jet::nan_derivatives(p, q, 0.0), im: Jet::nan_derivatives(p, q, 0.0) }
        } else {
            z.powf(alpha)
        };
        if turn == 0.0 {
            return powered;
        }
        let (s, c) = turn.sin_cos();
        ComplexJet {
            re: powered.re.scale(c).sub(&powered.im.scale(s)),
            im: powered.re.scale(s).add(&powered.im.scale(c)),
        }
    }

    /// Local i with its frame: partials in (X, Y) at ζ.
    fn local_partials(&self, i: usize, zeta: Point<2>, dx: usize, dy: usize, out: &mut [Point<3>]) {
        let l = &self.locals[i];
        let n = (dx + 1) * (dy + 1);
        l.patch.eval_partials((zeta.x + 1.0) / 2.0, (zeta.y + 1.0) / 2.0, dx, dy, &mut out[..n]);
        for a in 0..=dx {
            for b in 0..=dy {
                out[a * (dy + 1) + b] *= 0.5f64.powi((a + b) as i32);
            }
        }
        l.frame.apply_derivatives_about(&l.origin, &mut out[..n]);
    }

    fn eval(&self, t: usize, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let cols = dv + 1;
        let size = (du + 1) * cols;
        let lam = [
            Jet::affine(du, dv, u, 1.0, 0.0),
            Jet::affine(du, dv, v, 0.0, 1.0),
            Jet::affine(du, dv, 1.0 - u - v, -1.0, -1.0),
        ];
        let b = self.weight_jets(&lam);
        let sum = b.iter().flatten().fold(Jet::constant(du, dv, 0.0), |acc, j| acc.add(j));
        let inv = sum.recip();
        out[..size].iter_mut().for_each(|o| *o = Point::<3>::zeros());
        let n = du + dv;
        let w = n + 1;
        let mut lp: SmallVec<[Point<3>; 25]> = smallvec![Point::<3>::zeros(); w * w];
        let mut local: SmallVec<[Point<3>; 16]> = smallvec![Point::<3>::zeros(); size];
        for (m, bm) in b.iter().enumerate() {
            let Some(bm) = bm else { continue };
            let beta = bm.mul(&inv);
            let i = self.triangles[t][m] as usize;
            let zeta = self.chart_jet(t, m, &lam);
            self.local_partials(i, Point::<2>::new(zeta.re.value(), zeta.im.value()), n, n, &mut lp);
            compose_point(&zeta.re, &zeta.im, &lp, &mut local);
            for k in 0..=du {
                for l in 0..=dv {
                    let mut acc = Point::<3>::zeros();
                    for p in 0..=k {
                        for q in 0..=l {
                            let c = beta.partial(p, q);
                            if c != 0.0 {
                                acc += local[(k - p) * cols + (l - q)] * (binomial(k, p) * binomial(l, q) * c);
                            }
                        }
                    }
                    out[k * cols + l] += acc;
                }
            }
        }
    }
}

/// One triangle of a [`TriangulationBlend`].
#[derive(Debug, Clone)]
pub struct BlendTriangle {
    data: Arc<BlendData>,
    index: usize,
}

impl BlendTriangle {
    /// The triangle's number.
    pub fn index(&self) -> usize {
        self.index
    }
}

impl Triangle<3> for BlendTriangle {
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let (u, v) = clamp_uv(u, v);
        self.data.eval(self.index, u, v, du, dv, out);
    }

    /// At a corner, the local's normal in its chart (defined whatever the valence);
    /// elsewhere T_u × T_v normalised.
    fn normal(&self, u: f64, v: f64, w: f64) -> Option<Point<3>> {
        let (u, v) = clamp_to_triangle(u, v, w);
        let lam = [u, v, 1.0 - u - v];
        if let Some(m) = lam.iter().position(|&x| x == 1.0) {
            let i = self.data.triangles[self.index][m] as usize;
            let mut o = [Point::<3>::zeros(); 4];
            self.data.local_partials(i, Point::<2>::zeros(), 1, 1, &mut o);
            return unit_normal(&o[2], &o[1]);
        }
        let mut o = [Point::<3>::zeros(); 4];
        self.data.eval(self.index, u, v, 1, 1, &mut o);
        unit_normal(&o[2], &o[1])
    }
}
