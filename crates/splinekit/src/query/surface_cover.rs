//! A cover of a surface by bicubic Hermite patches with error radii: the bounding
//! hierarchy that surface projection searches.
//!
//! On a patch [u₀, u₁] × [v₀, v₁] (widths h_u, h_v) the bicubic Hermite interpolant H of
//! S, S_u, S_v and S_uv at the four corners has the Bézier net (corner b at (u_c, v_c),
//! σ = +1 at the lower end and −1 at the upper one, in each direction)
//! b = S, b ± h_u/3·S_u, b ± h_v/3·S_v, b ± h_u/3·S_u ± h_v/3·S_v + σ_uσ_v h_u h_v/9·S_uv.
//! It reproduces bicubic polynomials, so bicubic B-spline patches (cut at their knot lines)
//! are exact. For other surfaces its error is measured at the centre and the four edge
//! midpoints, which the patch samples anyway to split into four; as for curves
//! ([`crate::query::curve_cover`]) the measured error e (position) and e_s (first
//! derivatives in the patch parameters s, t ∈ [0, 1]) are enlarged into bounds:
//! `radius` = SAFETY·(e + ¼e_s) on |S − H|, `slope_radius` = SAFETY·(3.1e + e_s) on the
//! first derivatives and `curvature_radius` = SAFETY·(32e + 6e_s) on the second (for an
//! error K s²(1 − s)² the second derivative peaks at 2K = 32·K/16).

use crate::Point;
use crate::curve::Interval;
use crate::query::bounds::Aabb;
use crate::query::curve_cover::{ROUNDING, SAFETY, is_tame};
use crate::surface::Surface;

/// The fewest root patches in each direction.
const MIN_ROOT_PATCHES: usize = 4;

/// The cached hierarchy stops below this fraction of each domain.
const CACHE_DEPTH_WIDTH: f64 = 1.0 / 256.0;

/// S, S_u, S_v and S_uv at (u, v).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceSample<const D: usize> {
    /// u.
    pub u: f64,
    /// v.
    pub v: f64,
    /// S(u, v).
    pub point: Point<D>,
    /// ∂S/∂u.
    pub du: Point<D>,
    /// ∂S/∂v.
    pub dv: Point<D>,
    /// ∂²S/∂u∂v.
    pub duv: Point<D>,
}

impl<const D: usize> SurfaceSample<D> {
    /// Evaluates the surface and its first partials at (u, v).
    pub fn at<S: Surface<D> + ?Sized>(surface: &S, u: f64, v: f64) -> Self {
        let mut o = [Point::<D>::zeros(); 4];
        surface.eval_partials(u, v, 1, 1, &mut o);
        SurfaceSample { u, v, point: o[0], du: o[2], dv: o[1], duv: o[3] }
    }
}

/// Cubic Bernstein values and derivatives at s.
#[inline]
pub fn cubic_bernstein(s: f64) -> ([f64; 4], [f64; 4]) {
    let r = 1.0 - s;
    (
        [r * r * r, 3.0 * s * r * r, 3.0 * s * s * r, s * s * s],
        [-3.0 * r * r, 3.0 * r * r - 6.0 * s * r, 6.0 * s * r - 3.0 * s * s, 3.0 * s * s],
    )
}

/// H, H_s and H_t of a bicubic Bézier net (`net[i·4 + j]`, i along s) at (s, t).
pub fn bicubic_eval<const D: usize>(net: &[Point<D>; 16], s: f64, t: f64) -> [Point<D>; 3] {
    let ((bs, ds), (bt, dt)) = (cubic_bernstein(s), cubic_bernstein(t));
    let mut out = [Point::<D>::zeros(); 3];
    for i in 0..4 {
        for j in 0..4 {
            let p = &net[i * 4 + j];
            out[0] += p * (bs[i] * bt[j]);
            out[1] += p * (ds[i] * bt[j]);
            out[2] += p * (bs[i] * dt[j]);
        }
    }
    out
}

/// One bicubic Hermite patch of the cover (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct SurfacePatch<const D: usize> {
    /// Samples on the 3 × 3 grid of corners, edge midpoints and centre: `grid[a·3 + b]` at
    /// (u₀ + a·h_u/2, v₀ + b·h_v/2).
    pub grid: [SurfaceSample<D>; 9],
    /// The Hermite Bézier net, `control[i·4 + j]`.
    pub control: [Point<D>; 16],
    /// Bound on |S − H|.
    pub radius: f64,
    /// Bound on the first partials of S − H in the patch parameters.
    pub slope_radius: f64,
    /// Bound on the second partials of S − H in the patch parameters.
    pub curvature_radius: f64,
    /// The net's box grown by `radius`: it holds the patch.
    pub bounds: Aabb<D>,
}

impl<const D: usize> SurfacePatch<D> {
    /// The patch with the given 3 × 3 grid of samples.
    pub fn from_grid(grid: [SurfaceSample<D>; 9]) -> Self {
        let (hu, hv) = (grid[8].u - grid[0].u, grid[8].v - grid[0].v);
        let mut control = [Point::<D>::zeros(); 16];
        for (a, b) in [(0usize, 0usize), (0, 2), (2, 0), (2, 2)] {
            let c = &grid[a * 3 + b];
            let (i, j) = (a / 2 * 3, b / 2 * 3);
            let (su, sv) = (if a == 0 { 1.0 } else { -1.0 }, if b == 0 { 1.0 } else { -1.0 });
            let (eu, ev) = (c.du * (su * hu / 3.0), c.dv * (sv * hv / 3.0));
            let (i1, j1) = ((i as isize + su as isize) as usize, (j as isize + sv as isize) as usize);
            control[i * 4 + j] = c.point;
            control[i1 * 4 + j] = c.point + eu;
            control[i * 4 + j1] = c.point + ev;
            control[i1 * 4 + j1] = c.point + eu + ev + c.duv * (su * sv * hu * hv / 9.0);
        }
        let (mut err, mut err_s) = (0.0f64, 0.0f64);
        for k in [1usize, 3, 4, 5, 7] {
            let g = &grid[k];
            let h = bicubic_eval(&control, (k / 3) as f64 / 2.0, (k % 3) as f64 / 2.0);
            err = err.max((g.point - h[0]).norm());
            err_s = err_s.max((g.du * hu - h[1]).norm()).max((g.dv * hv - h[2]).norm());
        }
        let scale = control.iter().fold(0.0f64, |m, p| m.max(p.amax()));
        let round = ROUNDING * scale;
        let radius = SAFETY * (err + 0.25 * err_s) + round;
        let slope_radius = SAFETY * (3.1 * err + err_s) + round;
        let curvature_radius = SAFETY * (32.0 * err + 6.0 * err_s) + round;
        let bounds = Aabb::around(&control, radius);
        SurfacePatch { grid, control, radius, slope_radius, curvature_radius, bounds }
    }

    /// The patch over [u₀, u₁] × [v₀, v₁]; evaluates the surface on the 3 × 3 grid.
    pub fn new<S: Surface<D> + ?Sized>(surface: &S, u: Interval, v: Interval) -> Self {
        let grid = std::array::from_fn(|k| {
            SurfaceSample::at(surface, u.lerp((k / 3) as f64 / 2.0), v.lerp((k % 3) as f64 / 2.0))
        });
        Self::from_grid(grid)
    }

    /// The u-interval.
    #[inline]
    pub fn u(&self) -> Interval {
        Interval::new(self.grid[0].u, self.grid[8].u)
    }

    /// The v-interval.
    #[inline]
    pub fn v(&self) -> Interval {
        Interval::new(self.grid[0].v, self.grid[8].v)
    }

    /// The four quarters (16 new evaluations), in the order (low u, low v), (low u, high v),
    /// (high u, low v), (high u, high v).
    pub fn split<S: Surface<D> + ?Sized>(&self, surface: &S) -> [Self; 4] {
        let (u, v) = (self.u(), self.v());
        let fine: Vec<SurfaceSample<D>> = (0..25)
            .map(|k| {
                let (a, b) = (k / 5, k % 5);
                if a % 2 == 0 && b % 2 == 0 {
                    self.grid[a / 2 * 3 + b / 2]
                } else {
                    SurfaceSample::at(surface, u.lerp(a as f64 / 4.0), v.lerp(b as f64 / 4.0))
                }
            })
            .collect();
        std::array::from_fn(|c| {
            let (ca, cb) = (c / 2 * 2, c % 2 * 2);
            Self::from_grid(std::array::from_fn(|k| fine[(ca + k / 3) * 5 + cb + k % 3]))
        })
    }

    /// Which direction to halve a patch with an edge collapsed to a point (a sphere's pole,
    /// a cone's apex): `Some(true)` halves v when an edge v = const is a point, `Some(false)`
    /// halves u when an edge u = const is; `None` when no edge is (or both directions have
    /// one). An edge is a point when its three samples lie within 10⁻⁹ of the patch's
    /// diagonal of each other. Splitting such a patch across the point would multiply the
    /// patches that all hold the point with every level; halving only the other way keeps
    /// their number.
    pub fn collapsed_split(&self) -> Option<bool> {
        let spread = |k: [usize; 3]| {
            let (a, b, c) = (&self.grid[k[0]].point, &self.grid[k[1]].point, &self.grid[k[2]].point);
            (a - b).norm().max((a - c).norm()).max((b - c).norm())
        };
        let eps = 1e-9 * self.bounds.diagonal();
        let v_edge = spread([0, 3, 6]) <= eps || spread([2, 5, 8]) <= eps;
        let u_edge = spread([0, 1, 2]) <= eps || spread([6, 7, 8]) <= eps;
        match (v_edge, u_edge) {
            (true, false) => Some(true),
            (false, true) => Some(false),
            _ => None,
        }
    }

    /// The two halves in v (`along_v`) or in u, low half first (12 new evaluations).
    pub fn halves<S: Surface<D> + ?Sized>(&self, surface: &S, along_v: bool) -> [Self; 2] {
        let (u, v) = (self.u(), self.v());
        std::array::from_fn(|h| {
            let half = |i: Interval| {
                if h == 0 { Interval::new(i.start, i.lerp(0.5)) } else { Interval::new(i.lerp(0.5), i.end) }
            };
            if along_v { Self::new(surface, u, half(v)) } else { Self::new(surface, half(u), v) }
        })
    }

    /// Whether the box says something useful: the error radius is small beside the patch
    /// (or at rounding level).
    pub fn is_tame(&self) -> bool {
        is_tame(&self.control, self.radius)
    }
}

/// A node of the cached hierarchy: a patch and, unless it is a leaf, its four quarters.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchNode<const D: usize> {
    /// The patch.
    pub patch: SurfacePatch<D>,
    /// Indices of the quarters in [`SurfaceCover::nodes`], `None` for a leaf.
    pub children: Option<[u32; 4]>,
}

/// The cached bounding hierarchy of a surface: root patches on the grid of its breakpoint
/// lines (at least `MIN_ROOT_PATCHES` each way), each split until its box is tame.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceCover<const D: usize> {
    /// Every node; the roots first.
    pub nodes: Vec<PatchNode<D>>,
    /// How many roots.
    pub roots: usize,
    /// The u-domain.
    pub domain_u: Interval,
    /// The v-domain.
    pub domain_v: Interval,
    /// Closedness in u and v.
    pub closed: (bool, bool),
    /// The largest coordinate magnitude of the root boxes (for rounding-level tolerances).
    pub scale: f64,
}

/// Cuts between consecutive breakpoints, each span split evenly so there are at least
/// `min` pieces.
fn cuts(domain: Interval, breaks: Vec<f64>, min: usize) -> Vec<f64> {
    let mut b: Vec<f64> = breaks.into_iter().filter(|&t| t >= domain.start && t <= domain.end).collect();
    b.dedup();
    if b.len() < 2 {
        b = vec![domain.start, domain.end];
    }
    let per = min.div_ceil(b.len() - 1);
    let mut out: Vec<f64> = Vec::new();
    for w in b.windows(2).filter(|w| w[1] > w[0]) {
        out.extend((0..per).map(|i| w[0] + (w[1] - w[0]) * i as f64 / per as f64));
    }
    out.push(domain.end);
    out
}

impl<const D: usize> SurfaceCover<D> {
    /// Builds the cover of `surface`.
    pub fn new<S: Surface<D> + ?Sized>(surface: &S) -> Self {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let (cu, cv) =
            (cuts(du, surface.breakpoints_u(), MIN_ROOT_PATCHES), cuts(dv, surface.breakpoints_v(), MIN_ROOT_PATCHES));
        let mut nodes: Vec<PatchNode<D>> = Vec::with_capacity(cu.len() * cv.len());
        for wu in cu.windows(2) {
            for wv in cv.windows(2) {
                let patch = SurfacePatch::new(surface, Interval::new(wu[0], wu[1]), Interval::new(wv[0], wv[1]));
                nodes.push(PatchNode { patch, children: None });
            }
        }
        let roots = nodes.len();
        let (min_u, min_v) = (CACHE_DEPTH_WIDTH * du.length(), CACHE_DEPTH_WIDTH * dv.length());
        let mut k = 0;
        while k < nodes.len() {
            let p = &nodes[k].patch;
            if !p.is_tame() && p.u().length() > min_u && p.v().length() > min_v {
                let quarters = p.split(surface);
                let first = nodes.len() as u32;
                nodes.extend(quarters.into_iter().map(|patch| PatchNode { patch, children: None }));
                nodes[k].children = Some([first, first + 1, first + 2, first + 3]);
            }
            k += 1;
        }
        let scale =
            nodes[..roots].iter().fold(0.0f64, |m, n| m.max(n.patch.bounds.min.amax()).max(n.patch.bounds.max.amax()));
        let closed = (surface.is_closed_u(), surface.is_closed_v());
        SurfaceCover { nodes, roots, domain_u: du, domain_v: dv, closed, scale }
    }
}

/// A patch being searched: a cached node or a quarter split off during the query.
#[derive(Debug, Clone)]
pub enum SearchPatch<'a, const D: usize> {
    /// A cached node.
    Cached(&'a PatchNode<D>),
    /// A patch made by the query.
    Owned(Box<SurfacePatch<D>>),
}

impl<'a, const D: usize> SearchPatch<'a, D> {
    /// The patch.
    pub fn patch(&self) -> &SurfacePatch<D> {
        match self {
            SearchPatch::Cached(n) => &n.patch,
            SearchPatch::Owned(p) => p,
        }
    }

    /// The four quarters: cached ones when the hierarchy has them, else freshly evaluated.
    pub fn split<S: Surface<D> + ?Sized>(&self, cover: &'a SurfaceCover<D>, surface: &S) -> [SearchPatch<'a, D>; 4] {
        match self {
            SearchPatch::Cached(PatchNode { children: Some(c), .. }) => {
                c.map(|i| SearchPatch::Cached(&cover.nodes[i as usize]))
            }
            _ => self.patch().split(surface).map(|p| SearchPatch::Owned(Box::new(p))),
        }
    }

    /// As [`SearchPatch::split`], but a patch with an edge collapsed to a point is halved
    /// only the other way ([`SurfacePatch::collapsed_split`]): the pieces of a search that
    /// meets a pole stay as many as the patches around it instead of doubling per level.
    pub fn split_around_points<S: Surface<D> + ?Sized>(
        &self,
        cover: &'a SurfaceCover<D>,
        surface: &S,
    ) -> Vec<SearchPatch<'a, D>> {
        match self.patch().collapsed_split() {
            Some(along_v) => {
                self.patch().halves(surface, along_v).into_iter().map(|p| SearchPatch::Owned(Box::new(p))).collect()
            }
            None => self.split(cover, surface).into_iter().collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::BSplineSurface;
    use crate::surface::model::Torus;

    #[test]
    fn bicubic_patches_are_exact_and_torus_patches_bound_the_surface() {
        let net: Vec<Vec<Point<3>>> = (0..6)
            .map(|i| (0..5).map(|j| Point::<3>::new(i as f64, j as f64, ((i * j) % 4) as f64 * 0.5)).collect())
            .collect();
        let s = BSplineSurface::clamped_uniform((3, 3), net).unwrap();
        let cover = SurfaceCover::new(&s);
        for node in &cover.nodes[..cover.roots] {
            assert!(node.patch.radius < 1e-12, "radius {}", node.patch.radius);
        }
        let torus = Torus::new(3.0, 1.0).unwrap();
        let cover = SurfaceCover::new(&torus);
        for node in &cover.nodes {
            let p = &node.patch;
            for k in 0..=10 {
                for l in 0..=10 {
                    let (s, t) = (k as f64 / 10.0, l as f64 / 10.0);
                    let h = bicubic_eval(&p.control, s, t)[0];
                    let exact = torus.point(p.u().lerp(s), p.v().lerp(t));
                    assert!((h - exact).norm() <= p.radius, "patch {:?} × {:?}", p.u(), p.v());
                }
            }
        }
    }
}
