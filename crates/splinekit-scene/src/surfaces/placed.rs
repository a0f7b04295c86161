//! `placed` documents: a 3-D surface moved rigidly into a frame, parameters kept (how
//! STEP places its spheres, cones and tori).

use serde::{Deserialize, Serialize};
use splinekit::surface::{PlacedSurface, Surface};

use super::{SurfaceDecoration, SurfaceDocument, SurfaceForm, Surfaces};
use crate::budget::ShapeCost;
use crate::defaults::{origin, x_axis, z_axis};
use crate::error::{DocumentError, Result};
use crate::points::to_point;
use crate::registry::{DocumentKind, self_form_kind_items};

/// `{"type":"placed","surface":{…},"origin":[0,0,0],"axis":[0,0,1],"ref_direction":[1,0,0]}`:
/// P(u, v) = origin + S₁(u, v) x + S₂(u, v) y + S₃(u, v) z, where z = axis/|axis|, x is
/// `ref_direction` made orthogonal to z and normalised, y = z × x. Same domain and
/// parameters as `surface`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlacedDoc {
    /// The surface in its own frame (3-D).
    pub surface: Box<SurfaceDocument>,
    /// Where the surface's origin goes (default the origin).
    #[serde(default = "origin")]
    pub origin: Vec<f64>,
    /// Where its z axis goes (default z).
    #[serde(default = "z_axis")]
    pub axis: Vec<f64>,
    /// Where its x axis goes, up to the part along `axis` (default x).
    #[serde(default = "x_axis")]
    pub ref_direction: Vec<f64>,
}

fn three(field: &str, v: &[f64]) -> Result<[f64; 3]> {
    let p = to_point::<3>(field, v)?;
    Ok([p[0], p[1], p[2]])
}

impl DocumentKind for PlacedDoc {
    type Family = Surfaces;
    self_form_kind_items!(NetView, SurfaceForm::Placed);
    fn dimension(&self) -> Result<usize> {
        match self.surface.dimension().map_err(|e| e.within("surface"))? {
            3 => Ok(3),
            d => Err(DocumentError::new("surface", format!("a placed surface must be 3-D, got {d}-D"))),
        }
    }
    fn cost(&self) -> ShapeCost {
        self.surface.cost().within("surface")
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        self.dimension()?;
        let (o, z, x) =
            (three("origin", &self.origin)?, three("axis", &self.axis)?, three("ref_direction", &self.ref_direction)?);
        let inner = self.surface.build_in::<D>().map_err(|e| e.within("surface"))?;
        Ok(Box::new(PlacedSurface::new(inner, o, z, x)?))
    }
    /// A sphere of radius 1.5 centred at (1, 2, 0.5), its pole axis along (0, 1, 1).
    fn example() -> Self {
        PlacedDoc {
            surface: Box::new(SurfaceDocument::Sphere(super::SphereDoc { radius: 1.5 })),
            origin: vec![1.0, 2.0, 0.5],
            axis: vec![0.0, 1.0, 1.0],
            ref_direction: vec![1.0, 0.0, 0.0],
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::None
    }
    fn set_time(&mut self, time: f64) {
        self.surface.set_time(time);
    }
}
