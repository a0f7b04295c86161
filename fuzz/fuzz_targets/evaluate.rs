//! Built documents evaluated at arbitrary parameters (inside, outside and at the ends of
//! their domains) with derivatives: never a panic. The input is a line of parameters (raw
//! bytes read as f64s) followed by a JSON document.
#![no_main]

use libfuzzer_sys::fuzz_target;
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_scene::budget::Budget;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument, Surfaces};

fuzz_target!(|data: &[u8]| {
    let Some(split) = data.iter().position(|&b| b == b'\n') else { return };
    let (head, doc) = data.split_at(split);
    let Ok(text) = std::str::from_utf8(&doc[1..]) else { return };
    let Ok(doc) = ShapeDocument::from_json(text) else { return };
    let params: Vec<f64> = head.chunks_exact(8).take(16).map(|c| f64::from_le_bytes(c.try_into().unwrap())).collect();
    let order = head.first().map_or(0, |b| (b % 4) as usize);
    let cost = doc.cost();
    let budget = Budget { max_bytes: 64e6, max_work: 1e7 };
    if budget.check_shape(&cost).is_err() || cost.evaluations(params.len() as f64 + 2.0, order) > 1e7 {
        return;
    }
    match doc {
        ShapeDocument::Curve(c) => {
            if let Ok(curve) = c.build() {
                curve.visit(EvalCurve(&params, order));
            }
        }
        ShapeDocument::Surface(s) => {
            if let Ok(surface) = s.build() {
                surface.visit(EvalSurface(&params, order));
            }
        }
    }
});

/// The parameters as given, and the domain's ends.
fn parameters(params: &[f64], start: f64, end: f64) -> Vec<f64> {
    let mut all = params.to_vec();
    all.extend([start, end, 0.5 * (start + end)]);
    all
}

struct EvalCurve<'a>(&'a [f64], usize);

impl DimensionVisitor<Curves> for EvalCurve<'_> {
    type Output = ();
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) {
        let dom = curve.domain();
        let params = parameters(self.0, dom.start, dom.end);
        let mut out = vec![Point::<D>::zeros(); self.1 + 1];
        for &t in &params {
            curve.eval(t, &mut out);
        }
        let finite: Vec<f64> = params.iter().copied().filter(|t| t.is_finite()).collect();
        let mut many = vec![Point::<D>::zeros(); finite.len() * (self.1 + 1)];
        curve.eval_many(&finite, self.1, &mut many);
    }
}

struct EvalSurface<'a>(&'a [f64], usize);

impl DimensionVisitor<Surfaces> for EvalSurface<'_> {
    type Output = ();
    fn visit<const D: usize>(self, surface: &dyn Surface<D>) {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let us = parameters(self.0, du.start, du.end);
        let vs = parameters(&self.0[self.0.len() / 2..], dv.start, dv.end);
        let k = self.1;
        let mut out = vec![Point::<D>::zeros(); (k + 1) * (k + 1)];
        for (&u, &v) in us.iter().zip(vs.iter().cycle()) {
            surface.eval_partials(u, v, k, k, &mut out);
            let _ = surface.trim_contains(u, v);
        }
    }
}
