//! Inserting local pieces into blending splines from the window, without a window (issue
//! 22): the Properties panel's, the Edit menu's and the key L's Insert local piece arm the
//! tool; a click on the heart
//! (examples/scenes/heart_local_curves.json) inserts one local curve there, a click on the
//! blending torus (torus_before.json) one row of local patches (Shift + click: a column);
//! the document builds the kernel's insertion, and the shape keeps what the method promises (unchanged outside the split interval or strip, the same at the new knot, and
//! here within 1 % of its size), and one undo gives the document back exactly.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use serde_json::Value;
use splinekit::curve::Curve;
use splinekit::surface::{Direction, Surface};
use splinekit_scene::{ShapeDocument, SurfaceDocument};
use splinekit_studio::actions::Action;
use splinekit_studio::knot_edit::{KnotTool, curve_samples};
use splinekit_studio::net_knot_edit::{GRID, parameters_at, surface_samples};
use splinekit_studio::studio::Studio;

#[path = "common/knot_tools.rs"]
mod knot_tools;
use knot_tools::{armed, assert_armed_from_the_window, blending_curve, frame, open, open_selected, projector};

fn shape(studio: &Studio, object: usize) -> Value {
    studio.document.scene().objects[object].to_value()["shape"].clone()
}

/// The diagonal of the samples' bounding box.
fn diagonal(samples: &[(f64, [f64; 3])]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for (_, p) in samples {
        for i in 0..3 {
            lo[i] = lo[i].min(p[i]);
            hi[i] = hi[i].max(p[i]);
        }
    }
    (0..3).map(|i| (hi[i] - lo[i]).powi(2)).sum::<f64>().sqrt()
}

#[test]
fn a_click_on_the_heart_inserts_one_local_curve_and_undo_takes_it_back() {
    let (mut studio, projector, original) =
        armed("heart_local_curves.json", Action::InsertLocal, KnotTool::InsertLocal);
    let before = curve_samples(&studio.document.scene().objects[0].shape, 600).expect("samples");
    let original_curve = blending_curve(&studio, 0);
    // Sample 130 of 600, t ≈ 1.36: between knots 2 and 3 (0.63 apart).
    let (t, p) = before[130];
    let (px, _) = projector.project(p).expect("in view");
    studio.knot_click(KnotTool::InsertLocal, &projector, px, false);
    assert_eq!(studio.knot_tool, None);
    let s = shape(&studio, 0);
    assert_eq!(s["local_curves"], serde_json::json!(11), "one local more");
    let knots: Vec<f64> = serde_json::from_value(s["knots"].clone()).expect("knots");
    assert_eq!(knots.len(), 12, "closed: one knot more than locals");
    let k = knots.iter().position(|&c| (c - t).abs() < 0.02).expect("a knot at the click");
    assert_eq!(s["local_control_points"][k.to_string()].as_array().map(Vec::len), Some(3), "its quadratic's points");
    let (lo, hi) = (knots[k - 1], knots[k + 1]);
    let after = curve_samples(&studio.document.scene().objects[0].shape, 600).expect("samples");
    let mut worst: f64 = 0.0;
    for ((t, a), (_, b)) in before.iter().zip(&after) {
        let change = (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
        if *t <= lo || *t >= hi {
            assert!(change < 1e-12, "outside [{lo}, {hi}] the curve moved by {change} at {t}");
        }
        worst = worst.max(change);
    }
    // What the document now builds is the kernel's insertion into the curve before.
    let mut expected = original_curve.clone();
    assert_eq!(expected.insert_local(knots[k]).expect("inserts"), k);
    let now = blending_curve(&studio, 0);
    for i in 0..=600 {
        let t = now.domain().lerp(i as f64 / 600.0);
        assert!((now.point(t) - expected.point(t)).norm() < 1e-12, "at {t}: the kernel's insertion");
    }
    assert!((now.point(knots[k]) - original_curve.point(knots[k])).norm() < 1e-12, "the same at the new knot");
    // Between the neighbouring knots the change is the Taylor remainder of the new local
    // and the neighbours' distance from the curve: here under 1 % of the heart's size.
    let diagonal = diagonal(&before);
    eprintln!("largest change {worst:.3e} of a {diagonal:.1} diagonal");
    assert!(worst < 0.01 * diagonal, "{worst} of {diagonal}");
    studio.undo();
    assert_eq!(studio.document.scene().to_value(), original, "one undo step gives the document back");
}

#[test]
fn a_click_on_the_blending_torus_inserts_a_row_of_patches_and_shift_a_column() {
    let mut studio = open("torus_before.json");
    let object = studio
        .document
        .scene()
        .objects
        .iter()
        .position(|o| matches!(o.shape, ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(_))))
        .expect("the blending torus");
    studio.selection.object = Some(object);
    let projector = projector(&mut studio);
    let original = studio.document.scene().to_value();
    let kernel = |studio: &Studio| match &studio.document.scene().objects[object].shape {
        ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(d)) => d.surface::<3>().expect("builds"),
        _ => panic!("a blending surface"),
    };
    let grid = surface_samples(&studio.document.scene().objects[object].shape, 40).expect("samples");
    let (_, p) = grid[13][22];
    let (px, _) = projector.project(p).expect("in view");
    let mut h = Harness::new_ui_state(frame, studio);
    h.run();
    assert!(h.query_by_label("Insert knot").is_none(), "a blending surface has no B-spline knots");
    h.get_by_label("Insert local piece").click();
    h.run();
    assert_eq!(h.state().knot_tool, Some(KnotTool::InsertLocal));
    let studio = h.state_mut();
    for (shift, direction, counts) in [(false, Direction::U, [9, 6]), (true, Direction::V, [9, 7])] {
        let before = kernel(studio);
        // The parameters the click hits, as the studio finds them.
        let coarse = surface_samples(&studio.document.scene().objects[object].shape, GRID).expect("grid");
        let (u, v) = parameters_at(&coarse, &projector, px).expect("on the surface");
        let t = if shift { v } else { u };
        studio.run_action(Action::InsertLocal);
        studio.knot_click(KnotTool::InsertLocal, &projector, px, shift);
        let s = shape(studio, object);
        assert_eq!(s["local_surfaces"], serde_json::json!(counts), "{direction:?}: one row (column) more");
        let field = if shift { "knots_v" } else { "knots_u" };
        let knots: Vec<f64> = serde_json::from_value(s[field].clone()).expect("knots");
        let k = knots.iter().position(|&c| (c - t).abs() < 1e-9).expect("a knot line at the click");
        // What the document now builds is the kernel's insertion into the surface before.
        let mut expected = before.clone();
        assert_eq!(expected.insert_knot_line(direction, knots[k]).expect("inserts"), k);
        let after = kernel(studio);
        let (lo, hi) = (knots[k - 1], knots[k + 1]);
        for i in 0..=40 {
            for j in 0..=40 {
                let (a, b) = (after.domain_u().lerp(i as f64 / 40.0), after.domain_v().lerp(j as f64 / 40.0));
                let p = after.point(a, b);
                assert!((p - expected.point(a, b)).norm() < 1e-12, "{direction:?}: the kernel's insertion");
                let x = if shift { b } else { a };
                if x <= lo || x >= hi {
                    assert!((p - before.point(a, b)).norm() < 1e-12, "{direction:?}: outside the strip");
                } else {
                    // The torus is 8 across: the change, the Taylor remainder of the new
                    // row plus the neighbouring rows' distance from the surface, stays
                    // under 1 % of it.
                    assert!((p - before.point(a, b)).norm() < 0.08, "{direction:?}: in the strip");
                }
            }
        }
        // On the new knot line, at the other direction's knots, the surface stays put.
        let others: Vec<f64> =
            if shift { after.knots().0.values().to_vec() } else { after.knots().1.values().to_vec() };
        for o in others {
            let (a, b) = if shift { (o, knots[k]) } else { (knots[k], o) };
            assert!((after.point(a, b) - before.point(a, b)).norm() < 1e-9, "{direction:?}: at ({a}, {b})");
        }
    }
    studio.undo();
    studio.undo();
    assert_eq!(studio.document.scene().to_value(), original, "two undo steps give the document back");
}

#[test]
fn after_an_insertion_the_count_follows_the_knots_and_even_knots_respaces_them() {
    let mut studio = open_selected("heart_local_curves.json");
    let projector = projector(&mut studio);
    let (_, p) = curve_samples(&studio.document.scene().objects[0].shape, 600).expect("samples")[130];
    let (px, _) = projector.project(p).expect("in view");
    studio.run_action(Action::InsertLocal);
    studio.knot_click(KnotTool::InsertLocal, &projector, px, false);
    assert!(shape(&studio, 0).get("knots").is_some());
    let mut h = Harness::new_ui_state(frame, studio);
    h.run();
    assert!(h.query_by_label("local curves: 11 (knots as inserted)").is_some());
    assert!(h.query_by_label("knots").is_none(), "no knot spacing to choose");
    h.get_by_label("even knots").click();
    h.run();
    let s = shape(h.state(), 0);
    assert!(s.get("knots").is_none(), "even knots again");
    assert_eq!(s["local_curves"], serde_json::json!(11), "the count stays");
    assert!(h.query_by_label("local curves").is_some(), "an editable count again");
    assert!(h.query_by_label("knots").is_some(), "and the knot spacing");
    h.state_mut().undo();
    assert!(shape(h.state(), 0).get("knots").is_some(), "one undo step");
}

#[test]
fn the_panel_the_key_and_the_edit_menu_arm_the_tool() {
    let (tool, action) = (KnotTool::InsertLocal, Action::InsertLocal);
    assert_armed_from_the_window("heart_local_curves.json", tool, action, egui::Key::L, "Insert local piece  L");
}
