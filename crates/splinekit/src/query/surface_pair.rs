//! The state of marching along the intersection curve of two surfaces: the pair of
//! surfaces with its tolerances ([`Marcher`]), its four parameters' domains and their
//! wrapping, and a point of the curve ([`MarchPoint`]). A leaf shared by the marching step
//! ([`crate::query::march`]), touching curves ([`crate::query::touching`]) and seeding.

use crate::Point;
use crate::curve::Interval;
use crate::surface::Surface;

/// A point of the intersection curve: parameters on both surfaces, the point, the tangent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarchPoint {
    /// (u_a, v_a, u_b, v_b).
    pub x: [f64; 4],
    /// S_a(u_a, v_a).
    pub point: Point<3>,
    /// Unit tangent N_a × N_b.
    pub tangent: Point<3>,
    /// The first partials there: (∂S_a/∂u, ∂S_a/∂v, ∂S_b/∂u, ∂S_b/∂v), which the next
    /// step's predictor uses.
    pub partials: [Point<3>; 4],
}

/// The two surfaces, their domains and closedness, and the tolerances.
pub struct Marcher<'s, A: ?Sized, B: ?Sized> {
    /// First surface.
    pub a: &'s A,
    /// Second surface.
    pub b: &'s B,
    /// Distance within which S_a and S_b must agree at every point.
    pub tolerance: f64,
    /// Chord error allowed between the polyline and the curve.
    pub chord: f64,
    /// The longest step.
    pub max_step: f64,
}

impl<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized> Marcher<'_, A, B> {
    /// The four parameters' domains and whether each is closed.
    pub fn domains(&self) -> [(Interval, bool); 4] {
        [
            (self.a.domain_u(), self.a.is_closed_u()),
            (self.a.domain_v(), self.a.is_closed_v()),
            (self.b.domain_u(), self.b.is_closed_u()),
            (self.b.domain_v(), self.b.is_closed_v()),
        ]
    }

    /// x with closed parameters wrapped into their domains.
    pub fn wrap(&self, x: [f64; 4]) -> [f64; 4] {
        let d = self.domains();
        std::array::from_fn(|k| {
            let (i, closed) = d[k];
            if closed && i.length() > 0.0 { i.start + (x[k] - i.start).rem_euclid(i.length()) } else { x[k] }
        })
    }
}
