//! The [`Surface`] view of a [`TriangleAtlas`] (see [`super::atlas`]): chart c over
//! u ∈ [c, c + 1], v ∈ [0, 1], triangle c at (s(1 − t), s t, 1 − s), partials by the chain
//! rule in jets.

use smallvec::{SmallVec, smallvec};

use crate::query::Aabb;
use crate::surface::Surface;
use crate::triangle::atlas::TriangleAtlas;
use crate::triangle::degenerate_patch::degenerate_patch_parameters;
use crate::triangle::jet::{Jet, compose_point};
use crate::{Interval, Point};

impl<const D: usize> Surface<D> for TriangleAtlas<D> {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, self.charts().len() as f64)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }

    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (c, s, t) = self.locate(u, v);
        let tri = self.charts()[c].as_ref();
        let [a, b, _] = degenerate_patch_parameters(s, t);
        if du == 0 && dv == 0 {
            tri.eval_partials(a, b, 0, 0, out);
            return;
        }
        let n = du + dv;
        let w = n + 1;
        let mut partials: SmallVec<[Point<D>; 25]> = smallvec![Point::<D>::zeros(); w * w];
        tri.eval_partials(a, b, n, n, &mut partials);
        if partials.iter().any(|p| !p.iter().all(|x| x.is_finite())) {
            // A singular corner (a blending triangulation's vertex of valence ≠ 6, where the
            // partials in (u, v) do not exist): those 10⁻⁹ towards the centroid, the point kept.
            let value = partials[0];
            let nudge = |x: f64| x + (1.0 / 3.0 - x) * 1e-9;
            tri.eval_partials(nudge(a), nudge(b), n, n, &mut partials);
            if value.iter().all(|x| x.is_finite()) {
                partials[0] = value;
            }
        }
        // u = s − s t and v = s t about (s, t): the jets of the bilinear map.
        let mut x = Jet::affine(du, dv, a, 1.0 - t, -s);
        let mut y = Jet::affine(du, dv, b, t, s);
        if du >= 1 && dv >= 1 {
            let cross = Jet::affine(du, dv, 0.0, 1.0, 0.0).mul(&Jet::affine(du, dv, 0.0, 0.0, 1.0));
            x = x.sub(&cross);
            y = y.add(&cross);
        }
        compose_point(&x, &y, &partials, out);
    }

    fn breakpoints_u(&self) -> Vec<f64> {
        (0..=self.charts().len()).map(|c| c as f64).collect()
    }

    /// The triangle's own normal (defined at the collapsed corner too).
    fn normal(&self, u: f64, v: f64) -> Option<Point<D>> {
        let (c, s, t) = self.locate(u, v);
        let [a, b, w] = degenerate_patch_parameters(s, t);
        self.charts()[c].normal(a, b, w)
    }

    /// The box given to [`TriangleAtlas::with_enclosing_box`], else the box of the control
    /// points where every chart is a Bézier triangle (convex hull property; rational ones
    /// with positive weights), else `None`.
    fn enclosing_box(&self) -> Option<Aabb<D>> {
        if let Some(b) = self.given_box() {
            return Some(b);
        }
        let mut points: Vec<Point<D>> = Vec::new();
        for chart in self.charts() {
            points.extend_from_slice(chart.bezier_net()?.points);
        }
        Some(Aabb::around(&points, 0.0))
    }

    fn triangle_atlas(&self) -> Option<&TriangleAtlas<D>> {
        Some(self)
    }
}
