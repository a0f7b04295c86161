//! Knot insertion in one parameter direction of a spline-net document (`bezier_surface`,
//! `bspline_surface`, `nurbs_surface`, read through its [`NetView`]): the surface does not
//! change.
//!
//! Inserting u-knots acts on every column of the net as Boehm's insertion on a curve (all
//! columns share the u-knots, so they end with the same knots); v-knots act on every row.
//! The kernel does that ([`BSplineSurface::refine`], [`NurbsSurface::refine`]); this file
//! only reads the document's net and writes the result back. A Bézier net is first the
//! clamped B-spline (NURBS) of one span on [0, 1]² with the same points, so a Bézier surface
//! becomes a `bspline_surface` (a rational one, with weights, a `nurbs_surface`).

use splinekit::curve::bezier::bezier_knots;
use splinekit::surface::iso_curve::Direction;
use splinekit::surface::{BSplineSurface, NurbsSurface};

use crate::error::{DocumentError, Result};
use crate::points::{from_points, to_points};
use crate::surfaces::{BSplineSurfaceDoc, NurbsSurfaceDoc, SurfaceDocument};
use crate::views::NetView;
use crate::with_dimension;

/// Most knots inserted at once.
const MAX_KNOTS: usize = 1_000_000;

/// The document of the same surface with `knots` inserted in `direction` (u-knots for
/// [`Direction::U`], the isocurves u = const; v-knots for [`Direction::V`]). Each value is
/// inserted once (repeat it to raise its multiplicity). An error names the field: a kind
/// without a control net, a knot that is not finite or lies outside the direction's domain.
pub fn insert_net_knots(doc: &SurfaceDocument, direction: Direction, knots: &[f64]) -> Result<SurfaceDocument> {
    if let Some((i, v)) = knots.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(DocumentError::new(format!("knot {i}"), format!("not finite ({v})")));
    }
    if knots.len() > MAX_KNOTS {
        return Err(DocumentError::new(
            "knots",
            format!("{} knots at once is more than the limit of {MAX_KNOTS}", knots.len()),
        ));
    }
    let Some(view) = doc.spline() else {
        return Err(DocumentError::new(
            "type",
            format!(
                "knot insertion works on bezier_surface, bspline_surface and nurbs_surface documents, not {}",
                doc.type_name()
            ),
        ));
    };
    let dim = doc.dimension()?;
    with_dimension!(dim, "control_points", D => insert_in::<D>(&view, direction, knots))
}

fn insert_in<const D: usize>(view: &NetView<'_>, direction: Direction, knots: &[f64]) -> Result<SurfaceDocument> {
    let (p, q) = view.degrees;
    crate::budget::check_degree("degree_u", p)?;
    crate::budget::check_degree("degree_v", q)?;
    let (ku, kv) = match &view.knots {
        Some((u, v)) => (u.to_vec(), v.to_vec()),
        None => (bezier_knots(p), bezier_knots(q)),
    };
    crate::points::check_finite_list("knots_u", &ku)?;
    crate::points::check_finite_list("knots_v", &kv)?;
    let (field, own) = match direction {
        Direction::U => ("knots_u", &ku),
        Direction::V => ("knots_v", &kv),
    };
    let degree = if direction == Direction::U { p } else { q };
    let (start, end) = (own[degree.min(own.len() - 1)], own[own.len() - 1 - degree.min(own.len() - 1)]);
    if let Some(&t) = knots.iter().find(|&&t| !(start..=end).contains(&t)) {
        return Err(DocumentError::new(field, format!("a new knot must lie in the domain [{start}, {end}], got {t}")));
    }
    let net: Vec<Vec<_>> = view.control_points.iter().map(|row| to_points::<D>(row)).collect();
    let net_doc = |net: &[Vec<splinekit::Point<D>>]| net.iter().map(|row| from_points(row)).collect::<Vec<_>>();
    Ok(match &view.weights {
        None => {
            let s = BSplineSurface::new(view.degrees, ku, kv, net, view.periodic)?.refine(direction, knots)?;
            let ((p, q), (ku, kv), (pu, pv)) = (s.degrees(), s.knots(), s.periodic());
            SurfaceDocument::BsplineSurface(BSplineSurfaceDoc {
                degree_u: p,
                degree_v: q,
                knots_u: ku.to_vec(),
                knots_v: kv.to_vec(),
                control_points: net_doc(s.control_points()),
                periodic_u: pu,
                periodic_v: pv,
            })
        }
        Some(w) => {
            let s =
                NurbsSurface::new(view.degrees, ku, kv, net, w.to_vec(), view.periodic)?.refine(direction, knots)?;
            let ((p, q), (ku, kv), (pu, pv)) = (s.degrees(), s.knots(), s.periodic());
            SurfaceDocument::NurbsSurface(NurbsSurfaceDoc {
                degree_u: p,
                degree_v: q,
                knots_u: ku.to_vec(),
                knots_v: kv.to_vec(),
                control_points: net_doc(s.control_points()),
                weights: s.weights().to_vec(),
                periodic_u: pu,
                periodic_v: pv,
            })
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;
    use splinekit::surface::Surface;

    /// 13 × 13 points of the surface over its domain (z = 0 for plane nets).
    fn points(doc: &SurfaceDocument) -> Vec<[f64; 3]> {
        struct Grid;
        impl crate::DimensionVisitor<crate::Surfaces> for Grid {
            type Output = Vec<[f64; 3]>;
            fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
                let (du, dv) = (s.domain_u(), s.domain_v());
                let mut out = Vec::new();
                for i in 0..=12 {
                    for j in 0..=12 {
                        let p = s.point(du.lerp(i as f64 / 12.0), dv.lerp(j as f64 / 12.0));
                        out.push([0, 1, 2].map(|k| if k < D { p[k] } else { 0.0 }));
                    }
                }
                out
            }
        }
        doc.build().expect("builds").visit(Grid)
    }

    fn same(a: &SurfaceDocument, b: &SurfaceDocument) {
        for (p, r) in points(a).iter().zip(points(b)) {
            assert!((0..3).all(|k| (p[k] - r[k]).abs() <= 1e-12), "{p:?} vs {r:?}");
        }
    }

    #[test]
    fn a_u_or_v_knot_adds_a_row_or_column_and_keeps_the_surface() {
        let nurbs = SurfaceDocument::from_value(json!({"type": "nurbs_surface", "degree_u": 2, "degree_v": 1,
            "knots_u": [0, 0, 0, 1, 1, 1], "knots_v": [0, 0, 1, 1],
            "control_points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 2]], [[2, 0, 0], [2, 1, 0]]],
            "weights": [[1, 1], [0.5, 2], [1, 1]]}))
        .expect("valid");
        let u = insert_net_knots(&nurbs, Direction::U, &[0.3]).expect("inserts u");
        let v = u.to_value();
        assert_eq!(v["knots_u"].as_array().map(Vec::len), Some(7));
        assert_eq!(v["control_points"].as_array().map(Vec::len), Some(4));
        assert_eq!(v["knots_v"], json!([0.0, 0.0, 1.0, 1.0]));
        same(&nurbs, &u);
        let uv = insert_net_knots(&u, Direction::V, &[0.6]).expect("inserts v");
        assert_eq!(uv.to_value()["control_points"][0].as_array().map(Vec::len), Some(3));
        same(&nurbs, &uv);
        let e = insert_net_knots(&nurbs, Direction::V, &[1.5]).expect_err("outside");
        assert!(e.to_string().contains("knots_v") && e.to_string().contains("1.5"), "{e}");
    }

    #[test]
    fn a_bezier_net_becomes_a_clamped_bspline_of_the_same_surface() {
        let bezier = SurfaceDocument::from_value(json!({"type": "bezier_surface",
            "control_points": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 1], [1, 1, 3], [1, 2, 1]]]}))
        .expect("valid");
        let out = insert_net_knots(&bezier, Direction::V, &[0.25]).expect("inserts");
        assert_eq!(out.type_name(), "bspline_surface");
        assert_eq!(out.to_value()["knots_v"], json!([0.0, 0.0, 0.0, 0.25, 1.0, 1.0, 1.0]));
        same(&bezier, &out);
        let sphere = SurfaceDocument::from_value(json!({"type": "sphere", "radius": 1.0})).expect("valid");
        let e = insert_net_knots(&sphere, Direction::U, &[0.5]).expect_err("no net");
        assert!(e.to_string().contains("sphere"), "{e}");
    }
}
