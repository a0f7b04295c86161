//! `sub_surface` documents: a surface over a quadrilateral of another surface's domain
//! (GMlib's `PSubSurf`, not bound to the axes), by the bilinear map of its four corners.

use serde::{Deserialize, Serialize};
use splinekit::surface::{QuadSubSurface, Surface};

use super::{SurfaceDecoration, SurfaceDocument, SurfaceForm, Surfaces, TorusDoc};
use crate::budget::ShapeCost;
use crate::error::{DocumentError, Result};
use crate::registry::{DocumentKind, approximated_kind_items};

/// `{"type":"sub_surface","surface":{…},"corners":[[u,v],[u,v],[u,v],[u,v]]}`:
/// P(s, t) = S(φ(s, t)) on [0, 1]², φ the bilinear map with φ(0, 0), φ(1, 0), φ(1, 1),
/// φ(0, 1) the corners in that order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubSurfaceDoc {
    /// The host surface (any dimension).
    pub surface: Box<SurfaceDocument>,
    /// q₀₀, q₁₀, q₁₁, q₀₁ in the host's (u, v), around a convex quadrilateral inside its domain.
    pub corners: [[f64; 2]; 4],
}

impl DocumentKind for SubSurfaceDoc {
    type Family = Surfaces;
    approximated_kind_items!(NetView, SurfaceForm);
    fn dimension(&self) -> Result<usize> {
        self.surface.dimension().map_err(|e| e.within("surface"))
    }
    /// The host, whose partials up to total order d_s + d_t a point needs (≤ 4 for the
    /// first partials and normals that meshes use), and the products of the map's
    /// polynomials.
    fn cost(&self) -> ShapeCost {
        let mut cost = self.surface.cost().within("surface");
        cost.eval = 9.0 * cost.eval + 200.0;
        cost
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        for (i, c) in self.corners.iter().enumerate() {
            for (j, x) in c.iter().enumerate() {
                crate::points::check_magnitude(format_args!("corners[{i}][{j}]"), *x)?;
            }
        }
        let host = self.surface.build_in::<D>().map_err(|e| e.within("surface"))?;
        Ok(Box::new(QuadSubSurface::new(host, self.corners).map_err(DocumentError::from)?))
    }
    /// A skew quadrilateral of the torus: its iso-lines run across the torus's.
    fn example() -> Self {
        SubSurfaceDoc {
            surface: Box::new(SurfaceDocument::Torus(TorusDoc::default())),
            corners: [[0.4, 0.3], [2.9, 0.8], [2.5, 3.6], [0.7, 2.4]],
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::None
    }
    fn set_time(&mut self, time: f64) {
        self.surface.set_time(time);
    }
}
