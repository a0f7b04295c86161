//! `curve_on_surface` documents: a 2-D curve in a surface's (u, v) domain mapped onto the
//! surface (GMlib's `PSurfCurve`).

use serde::{Deserialize, Serialize};
use splinekit::curve::Curve;
use splinekit::surface::CurveOnSurface;

use super::{CurveDecoration, CurveDocument, CurveForm, Curves, LineDoc};
use crate::budget::ShapeCost;
use crate::error::{DocumentError, Result};
use crate::registry::{DocumentKind, approximated_kind_items};
use crate::surfaces::{SurfaceDocument, TorusDoc};

/// `{"type":"curve_on_surface","curve":{…},"surface":{…}}`: c(t) = S(u(t), v(t)) on the
/// curve's domain, in the surface's dimension.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveOnSurfaceDoc {
    /// The 2-D curve (u(t), v(t)) in the surface's domain.
    pub curve: Box<CurveDocument>,
    /// The host surface (any dimension).
    pub surface: Box<SurfaceDocument>,
}

impl DocumentKind for CurveOnSurfaceDoc {
    type Family = Curves;
    approximated_kind_items!(SplineView, CurveForm);
    fn dimension(&self) -> Result<usize> {
        let d = self.curve.dimension().map_err(|e| e.within("curve"))?;
        if d != 2 {
            return Err(DocumentError::new(
                "curve",
                format!("a curve on a surface is a 2-D curve in the surface's (u, v) domain, got a {d}-D curve"),
            ));
        }
        self.surface.dimension().map_err(|e| e.within("surface"))
    }
    /// The curve and the host's partials up to the order asked (≤ 3 for curvature), then
    /// the products of the Taylor polynomials.
    fn cost(&self) -> ShapeCost {
        let mut cost = self.curve.cost().within("curve").and(self.surface.cost().within("surface"));
        cost.eval = 16.0 * cost.eval + 200.0;
        cost
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        self.dimension()?;
        let curve = self.curve.build_in::<2>().map_err(|e| e.within("curve"))?;
        let surface = self.surface.build_in::<D>().map_err(|e| e.within("surface"))?;
        Ok(Box::new(CurveOnSurface::new(curve, surface).map_err(DocumentError::from)?))
    }
    /// The (2, 3) torus knot: the line from (0, 0) to (4π, 6π) on the torus.
    fn example() -> Self {
        let tau = std::f64::consts::TAU;
        CurveOnSurfaceDoc {
            curve: Box::new(CurveDocument::Line(LineDoc { from: vec![0.0, 0.0], to: vec![2.0 * tau, 3.0 * tau] })),
            surface: Box::new(SurfaceDocument::Torus(TorusDoc::default())),
        }
    }
    fn decoration(&self) -> CurveDecoration<'_> {
        CurveDecoration::None
    }
    fn set_time(&mut self, time: f64) {
        self.curve.set_time(time);
        self.surface.set_time(time);
    }
}
