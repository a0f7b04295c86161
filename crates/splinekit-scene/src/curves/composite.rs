//! Curve documents made from B-functions and other curves: `bfunction` and `blend`.

use serde::{Deserialize, Serialize};
use splinekit::blend::{BFunctionCurve, TwoCurveBlend};
use splinekit::curve::Curve;

use super::{CurveDecoration, CurveDocument, CurveForm, Curves};
use crate::bfunctions::{BFunctionDoc, ErbsDoc, NoParams, PolynomialDoc};
use crate::budget::ShapeCost;
use crate::dimension::same_type;
use crate::error::{DocumentError, Result};
use crate::registry::{DocumentKind, approximated_kind_items};

/// `{"type":"bfunction","bfunction":{…}}`: the B-function as a 1-D curve on [0, 1].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BFunctionShapeDoc {
    /// The B-function.
    pub bfunction: BFunctionDoc,
}

impl DocumentKind for BFunctionShapeDoc {
    type Family = Curves;
    approximated_kind_items!(SplineView, CurveForm);
    fn dimension(&self) -> Result<usize> {
        Ok(1)
    }
    fn cost(&self) -> ShapeCost {
        ShapeCost::new("bfunction", 1024.0, 0.0, crate::budget::BFUNCTION_EVALUATION)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        let b = self.bfunction.build().map_err(|e| e.within("bfunction"))?;
        let curve: Box<dyn Curve<1>> = Box::new(BFunctionCurve(b));
        same_type(curve).ok_or_else(|| DocumentError::new("type", "a bfunction is a 1-D curve"))
    }
    fn example() -> Self {
        BFunctionShapeDoc { bfunction: BFunctionDoc::Erbs(ErbsDoc::default()) }
    }
    fn decoration(&self) -> CurveDecoration<'_> {
        CurveDecoration::None
    }
    fn set_time(&mut self, _time: f64) {}
}

/// `{"type":"blend","first":{…},"second":{…},"overlap":x,"bfunction":{…}}`: the two-curve
/// blend on [0, 1 + x] (B-function default: polynomial smoothness 1, i.e. 3t² − 2t³).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlendDoc {
    /// The curve before the overlap.
    pub first: Box<CurveDocument>,
    /// The curve after it.
    pub second: Box<CurveDocument>,
    /// x ∈ (0, 1).
    pub overlap: f64,
    /// The B-function (`None`: [`BlendDoc::DEFAULT_BFUNCTION`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bfunction: Option<BFunctionDoc>,
}

impl BlendDoc {
    /// The B-function when none is given: 3t² − 2t³.
    pub const DEFAULT_BFUNCTION: BFunctionDoc = BFunctionDoc::Polynomial(PolynomialDoc { smoothness: 1 });
}

impl DocumentKind for BlendDoc {
    type Family = Curves;
    approximated_kind_items!(SplineView, CurveForm);
    fn dimension(&self) -> Result<usize> {
        let a = self.first.dimension().map_err(|e| e.within("first"))?;
        let b = self.second.dimension().map_err(|e| e.within("second"))?;
        if a != b {
            return Err(DocumentError::new("second", format!("expected a curve of dimension {a} like first, got {b}")));
        }
        Ok(a)
    }
    /// Both curves, each evaluated once per point where they overlap, and the B-function.
    fn cost(&self) -> ShapeCost {
        let mut c = self.first.cost().within("first").and(self.second.cost().within("second"));
        c.eval += crate::budget::BFUNCTION_EVALUATION;
        c
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        let bfunction = self.bfunction.as_ref().unwrap_or(&Self::DEFAULT_BFUNCTION);
        Ok(Box::new(TwoCurveBlend::new(
            self.first.build_in::<D>().map_err(|e| e.within("first"))?,
            self.second.build_in::<D>().map_err(|e| e.within("second"))?,
            self.overlap,
            bfunction.build().map_err(|e| e.within("bfunction"))?,
        )?))
    }
    /// Two lines blended over half their length by the trigonometric B-function.
    fn example() -> Self {
        use super::LineDoc;
        let line =
            |from: [f64; 2], to: [f64; 2]| Box::new(CurveDocument::Line(LineDoc { from: from.into(), to: to.into() }));
        BlendDoc {
            first: line([0.0, 0.0], [1.0, 0.0]),
            second: line([0.5, 0.0], [1.5, 1.0]),
            overlap: 0.5,
            bfunction: Some(BFunctionDoc::Trigonometric(NoParams {})),
        }
    }
    fn decoration(&self) -> CurveDecoration<'_> {
        CurveDecoration::None
    }
    fn set_time(&mut self, time: f64) {
        self.first.set_time(time);
        self.second.set_time(time);
    }
}
