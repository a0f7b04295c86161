//! `trimmed` documents: a surface restricted by closed 2-D loops in its parameter domain.

use serde::{Deserialize, Serialize};
use splinekit::curve::Curve;
use splinekit::surface::{Surface, TrimmedSurface};

use super::{SurfaceDecoration, SurfaceDocument, SurfaceForm, Surfaces};
use crate::budget::ShapeCost;
use crate::curves::{CatmullRomDoc, CurveDocument};
use crate::error::{DocumentError, Result};
use crate::registry::{DocumentKind, self_form_kind_items};

/// `{"type":"trimmed","surface":{…},"outer":{…},"holes":[{…}]}`: the surface restricted to
/// the inside of `outer` (default: the whole domain) and outside every hole; loops are
/// closed 2-D curves in the surface's (u, v) domain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrimmedDoc {
    /// The underlying surface.
    pub surface: Box<SurfaceDocument>,
    /// The outer trimming loop.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer: Option<Box<CurveDocument>>,
    /// Holes.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub holes: Vec<CurveDocument>,
}

/// Points a trimming loop is flattened to (an upper estimate).
const TRIM_SAMPLES: f64 = 10_000.0;

/// A trimming loop as a 2-D curve.
fn trimming_loop(c: &CurveDocument, field: &str) -> Result<Box<dyn Curve<2>>> {
    if c.dimension().map_err(|e| e.within(field))? != 2 {
        return Err(DocumentError::new(field, "a trimming loop must be a 2-D curve in the (u, v) domain"));
    }
    c.build_in::<2>().map_err(|e| e.within(field))
}

impl DocumentKind for TrimmedDoc {
    type Family = Surfaces;
    self_form_kind_items!(NetView, SurfaceForm::Trimmed);
    fn dimension(&self) -> Result<usize> {
        self.surface.dimension().map_err(|e| e.within("surface"))
    }
    /// The surface and its loops (each flattened to a polyline when built).
    fn cost(&self) -> ShapeCost {
        let loops = self
            .outer
            .iter()
            .map(|o| o.cost().within("outer"))
            .chain(self.holes.iter().enumerate().map(|(i, h)| h.cost().within(&format!("holes[{i}]"))));
        let mut c = loops.fold(self.surface.cost().within("surface"), |acc, l| {
            let mut l = l;
            l.build.work += TRIM_SAMPLES * l.eval;
            l.build.bytes += TRIM_SAMPLES * 16.0;
            l.eval = 0.0;
            acc.and(l)
        });
        c.eval += 100.0;
        c
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let outer = self.outer.as_ref().map(|o| trimming_loop(o, "outer")).transpose()?;
        let holes: Vec<Box<dyn Curve<2>>> = self
            .holes
            .iter()
            .enumerate()
            .map(|(i, h)| trimming_loop(h, &format!("holes[{i}]")))
            .collect::<Result<_>>()?;
        let hole_refs: Vec<&dyn Curve<2>> = holes.iter().map(|h| h.as_ref()).collect();
        Ok(Box::new(TrimmedSurface::new(
            self.surface.build_in::<D>().map_err(|e| e.within("surface"))?,
            outer.as_deref(),
            &hole_refs,
        )?))
    }
    /// The unit square of the plane with a square hole in the middle.
    fn example() -> Self {
        let square = [[0.4, 0.4], [0.6, 0.4], [0.6, 0.6], [0.4, 0.6]];
        let hole = CatmullRomDoc { points: square.iter().map(|p| p.to_vec()).collect(), alpha: 0.0, closed: true };
        TrimmedDoc {
            surface: Box::new(SurfaceDocument::Plane(super::PlaneDoc::default())),
            outer: None,
            holes: vec![CurveDocument::CatmullRom(hole)],
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::None
    }
    fn set_time(&mut self, time: f64) {
        self.surface.set_time(time);
    }
}
