//! How the four sides of a surface's parameter rectangle meet in space, found by sampling
//! the surface: a side whose image is a single point is a **pole** (sphere poles, cone
//! apexes, the tip of a shell), and two opposite sides whose images coincide point by point
//! are a **seam**, either running the same way (cylinder, torus, any closed direction) or
//! reversed (the ends of a Möbius band or a Klein bottle meet flipped).
//!
//! Meshers weld through [`Gluing::node`]: every lattice point of a pole becomes one vertex,
//! and the points of one side of a seam become the points of the other. Detection looks at
//! the geometry, so surfaces that close without saying so (a revolved profile ending on the
//! axis, a clamped NURBS torus) are welded like those whose model reports `is_closed_u/v`.
//!
//! A pole's normal is the limit of the unit normal from inside the domain, averaged along
//! the side: at a pole on v = v₀ the first partial S_u vanishes identically, so
//! S_u(u, v₀ + h) = h S_uv(u, v₀) + O(h²) and N → ±(S_uv × S_v)/|S_uv × S_v|; where that
//! vanishes too (poles of higher order) the normal a small step inside is used.

use splinekit::Point;
use splinekit::curve::Interval;
use splinekit::query::Aabb;
use splinekit::surface::{Surface, unit_normal};

use crate::mesh_options::to3;
use crate::triangle_mesh::v3;

/// Samples along each side used to decide how it is glued.
const SIDE_SAMPLES: usize = 33;
/// Samples per direction of the interior grid that sets the surface's size.
const SIZE_SAMPLES: usize = 9;
/// Points closer than this fraction of the surface's size (in every coordinate) are the
/// same point.
const RELATIVE_TOLERANCE: f64 = 1e-9;

/// A side of the parameter rectangle: u = u₀, u = u₁, v = v₀ or v = v₁.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// u = u₀ (lattice i = 0).
    U0,
    /// u = u₁ (lattice i = n_u).
    U1,
    /// v = v₀ (lattice j = 0).
    V0,
    /// v = v₁ (lattice j = n_v).
    V1,
}

impl Side {
    const ALL: [Side; 4] = [Side::U0, Side::U1, Side::V0, Side::V1];

    /// The unit-square parameters of the point at fraction `t` along the side.
    fn at(self, t: f64) -> (f64, f64) {
        match self {
            Side::U0 => (0.0, t),
            Side::U1 => (1.0, t),
            Side::V0 => (t, 0.0),
            Side::V1 => (t, 1.0),
        }
    }

    /// Whether lattice point (i, j) of an n_u × n_v lattice lies on the side.
    fn contains(self, i: i64, j: i64, n: (i64, i64)) -> bool {
        match self {
            Side::U0 => i == 0,
            Side::U1 => i == n.0,
            Side::V0 => j == 0,
            Side::V1 => j == n.1,
        }
    }
}

/// How the two sides of a seam are matched.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Seam {
    /// S(u₁, v) = S(u₀, v) (or S(u, v₁) = S(u, v₀)).
    Direct,
    /// S(u₁, v) = S(u₀, v₀ + v₁ − v) (or S(u, v₁) = S(u₀ + u₁ − u, v₀)).
    Flipped,
}

/// A side whose image is one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pole {
    /// The point.
    pub position: [f64; 3],
    /// The limit unit normal averaged along the side; `None` where it has no meaningful
    /// average (normals cancelling, or a surface outside ℝ³).
    pub normal: Option<[f64; 3]>,
    /// Where its single vertex sits in the unit parameter square (the middle of the side).
    pub uv: [f64; 2],
}

/// A lattice point after gluing: a pole, or a lattice point standing for its class.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Node {
    /// The pole of this side (sides meeting at a corner share one).
    Pole(usize),
    /// A lattice point (i, j).
    Grid(i64, i64),
}

/// Poles and seams of a surface.
#[derive(Debug, Clone, PartialEq)]
pub struct Gluing {
    /// Per side (in [`Side`] order), its pole.
    poles: [Option<Pole>; 4],
    /// Per side, the side whose pole stands for it (collapsed sides meeting at a corner are
    /// one point).
    pole_class: [usize; 4],
    /// How side U1 is glued to U0.
    pub seam_u: Option<Seam>,
    /// How side V1 is glued to V0.
    pub seam_v: Option<Seam>,
}

impl Gluing {
    /// No poles and no seams: every lattice point is its own vertex.
    pub fn none() -> Self {
        Gluing { poles: [None; 4], pole_class: [0, 1, 2, 3], seam_u: None, seam_v: None }
    }

    /// Samples the surface along its sides and decides which are poles and seams.
    pub fn detect<const D: usize, S: Surface<D> + ?Sized>(surface: &S) -> Self {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let point = |(s, t): (f64, f64)| to3(&surface.point(at_fraction(du, s), at_fraction(dv, t)));
        let fraction = |k: usize| k as f64 / (SIDE_SAMPLES - 1) as f64;
        let sides: Vec<Vec<[f64; 3]>> =
            Side::ALL.iter().map(|s| (0..SIDE_SAMPLES).map(|k| point(s.at(fraction(k)))).collect()).collect();
        let interior = (0..SIZE_SAMPLES * SIZE_SAMPLES).map(|k| {
            let f = |i: usize| i as f64 / (SIZE_SAMPLES - 1) as f64;
            point((f(k / SIZE_SAMPLES), f(k % SIZE_SAMPLES)))
        });
        // The box of the samples (NaN coordinates passed over), kept as the size measure:
        // the gluing tolerance, so the meshes, are defined by this sample set.
        let Some(b) = Aabb::spanning(interior.chain(sides.iter().flatten().copied()).map(Point::<3>::from)) else {
            return Gluing::none();
        };
        // Half the widest extent, halved first so that it stays finite for huge surfaces.
        let half_size = (0..3).map(|k| 0.5 * b.max[k] - 0.5 * b.min[k]).fold(0.0, f64::max);
        if !(half_size > 0.0 && half_size.is_finite()) {
            return Gluing::none();
        }
        let tol = RELATIVE_TOLERANCE * half_size;
        let mut gluing = Gluing::none();
        for (k, side) in Side::ALL.iter().enumerate() {
            let pts = &sides[k];
            if pts.iter().all(|p| apart(*p, pts[0]) <= tol) {
                let uv = side.at(0.5);
                gluing.poles[k] =
                    Some(Pole { position: pts[0], normal: pole_normal(surface, *side), uv: [uv.0, uv.1] });
            }
        }
        let matched = |a: &[[f64; 3]], b: &[[f64; 3]], flip: bool| {
            (0..SIDE_SAMPLES).all(|k| apart(a[k], b[if flip { SIDE_SAMPLES - 1 - k } else { k }]) <= tol)
        };
        let seam = |a: usize, b: usize| {
            if gluing.poles[a].is_some() || gluing.poles[b].is_some() {
                None
            } else if matched(&sides[a], &sides[b], false) {
                Some(Seam::Direct)
            } else if matched(&sides[a], &sides[b], true) {
                Some(Seam::Flipped)
            } else {
                None
            }
        };
        gluing.seam_u = seam(0, 1);
        gluing.seam_v = seam(2, 3);
        // Collapsed sides sharing a corner (a u-side and a v-side) are the same point.
        for (a, b) in [(0, 2), (0, 3), (1, 2), (1, 3)] {
            if gluing.poles[a].is_some() && gluing.poles[b].is_some() {
                let (ca, cb) = (gluing.pole_class[a], gluing.pole_class[b]);
                let keep = ca.min(cb);
                for c in gluing.pole_class.iter_mut() {
                    if *c == ca || *c == cb {
                        *c = keep;
                    }
                }
            }
        }
        gluing
    }

    /// The pole standing for `Node::Pole(class)`.
    pub fn pole(&self, class: usize) -> &Pole {
        self.poles[class].as_ref().expect("a pole node names a collapsed side")
    }

    /// Whether some side is a pole.
    pub fn has_poles(&self) -> bool {
        self.poles.iter().any(Option::is_some)
    }

    /// The node of lattice point (i, j) of an n_u × n_v lattice over the domain: poles always
    /// become one node; seams are glued when `weld_seams` (otherwise their two sides stay
    /// separate lattice points, for meshes that store (u, v) per vertex).
    pub fn node(&self, i: i64, j: i64, n: (i64, i64), weld_seams: bool) -> Node {
        for (k, side) in Side::ALL.iter().enumerate() {
            if self.poles[k].is_some() && side.contains(i, j, n) {
                return Node::Pole(self.pole_class[k]);
            }
        }
        if !weld_seams {
            return Node::Grid(i, j);
        }
        let corner = (i == 0 || i == n.0) && (j == 0 || j == n.1);
        if corner && self.seam_u.is_some() && self.seam_v.is_some() {
            return Node::Grid(0, 0);
        }
        let (mut i, mut j) = (i, j);
        if i == n.0 {
            match self.seam_u {
                Some(Seam::Direct) => i = 0,
                Some(Seam::Flipped) => (i, j) = (0, n.1 - j),
                None => {}
            }
        }
        if j == n.1 {
            match self.seam_v {
                Some(Seam::Direct) => j = 0,
                Some(Seam::Flipped) => (i, j) = (n.0 - i, 0),
                None => {}
            }
        }
        Node::Grid(i, j)
    }
    /// The lattice points glued to (i, j) across seams, (i, j) included: more than one for
    /// points on the sides of a seam (up to four at corners).
    pub fn seam_partners(&self, i: i64, j: i64, n: (i64, i64)) -> Vec<(i64, i64)> {
        let mut out = vec![(i, j)];
        let mut k = 0;
        while k < out.len() {
            let (a, b) = out[k];
            let across_u = match self.seam_u {
                Some(Seam::Direct) if a == 0 || a == n.0 => Some((n.0 - a, b)),
                Some(Seam::Flipped) if a == 0 || a == n.0 => Some((n.0 - a, n.1 - b)),
                _ => None,
            };
            let across_v = match self.seam_v {
                Some(Seam::Direct) if b == 0 || b == n.1 => Some((a, n.1 - b)),
                Some(Seam::Flipped) if b == 0 || b == n.1 => Some((n.0 - a, n.1 - b)),
                _ => None,
            };
            for p in [across_u, across_v].into_iter().flatten() {
                if !out.contains(&p) {
                    out.push(p);
                }
            }
            k += 1;
        }
        out
    }
}

/// The mean of the limit normals along a collapsed side, or `None`.
fn pole_normal<const D: usize, S: Surface<D> + ?Sized>(surface: &S, side: Side) -> Option<[f64; 3]> {
    let mut sum = [0.0; 3];
    let mut count = 0usize;
    // Midpoints of equal pieces, so a side whose ends meet is not weighted twice there.
    for k in 0..SIDE_SAMPLES {
        if let Some(n) = limit_normal(surface, side, (k as f64 + 0.5) / SIDE_SAMPLES as f64) {
            for c in 0..3 {
                sum[c] += n[c];
            }
            count += 1;
        }
    }
    let len = v3(sum).norm();
    // Normals that mostly cancel (a pinch point) have no direction worth keeping.
    (count > 0 && len > 0.1 * count as f64).then(|| sum.map(|x| x / len))
}

/// The limit of the unit normal at fraction `t` along a collapsed side, approached from
/// inside the domain (see the module documentation).
fn limit_normal<const D: usize, S: Surface<D> + ?Sized>(surface: &S, side: Side, t: f64) -> Option<[f64; 3]> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let (s, r) = side.at(t);
    let mut o = [Point::<D>::zeros(); 4];
    surface.eval_partials(at_fraction(du, s), at_fraction(dv, r), 1, 1, &mut o);
    // o[1] = S_v, o[2] = S_u, o[3] = S_uv.
    let first_order = match side {
        Side::V0 => unit_normal(&o[3], &o[1]),
        Side::V1 => unit_normal(&o[3], &o[1]).map(|n| -n),
        Side::U0 => unit_normal(&o[2], &o[3]),
        Side::U1 => unit_normal(&o[2], &o[3]).map(|n| -n),
    };
    if let Some(n) = first_order {
        return Some(to3(&n));
    }
    const STEP: f64 = 1e-6;
    let (s, r) = match side {
        Side::U0 => (STEP, r),
        Side::U1 => (1.0 - STEP, r),
        Side::V0 => (s, STEP),
        Side::V1 => (s, 1.0 - STEP),
    };
    surface.eval_partials(at_fraction(du, s), at_fraction(dv, r), 1, 1, &mut o);
    unit_normal(&o[2], &o[1]).map(|n| to3(&n))
}

/// The parameter at fraction `f` of `d`, the ends exactly.
fn at_fraction(d: Interval, f: f64) -> f64 {
    if f == 1.0 { d.end } else { d.lerp(f) }
}

/// The largest coordinate difference of two points (no squares, so no overflow for huge
/// coordinates).
fn apart(p: [f64; 3], q: [f64; 3]) -> f64 {
    (0..3).map(|k| (p[k] - q[k]).abs()).fold(0.0, f64::max)
}
