//! Real parts from CAD systems (tests/step/real/, where each file came from and its
//! licence in SOURCES.md) measured by `splinekit measure` against OpenCASCADE's reading of
//! the same files (`occ_reference.json`, made by `occ_reference.py` with OCP 8.0.1.1):
//! the faces and solids read, the exact area and volume of the trimmed faces, and the
//! watertight mesh's open edges and box.
//!
//! The files here are the ones a debug build measures within a minute; the larger ones (NIST's
//! CTC-02, the SolidWorks and Fusion 360 assemblies, Rhino's NURBS solid) are measured by
//! `tools/real_step_compare.py` on a release build.

use serde_json::Value;

#[allow(dead_code)] // ScratchDir serves the other test files.
mod common;
use common::run;

fn reference(file: &str) -> Value {
    let text = include_str!("../../../tests/step/real/occ_reference.json");
    let all: Value = serde_json::from_str(text).unwrap();
    all[file].clone()
}

/// What one file must give: the relative error allowed in the exact area and volume
/// (OpenCASCADE integrates the same exact faces), and whether the mesh must be closed.
struct Expect {
    area: f64,
    volume: f64,
    closed_mesh: bool,
}

fn check(file: &str, expect: Expect) {
    let path = format!("{}/../../tests/step/real/{file}", env!("CARGO_MANIFEST_DIR"));
    let o = run(&["measure", &path], "");
    assert_eq!(o.code, 0, "{file}: {}", o.stderr);
    let m: Value = serde_json::from_str(&o.stdout).unwrap();
    let parts: Vec<Value> = match m.get("objects") {
        Some(objects) => objects.as_array().unwrap().clone(),
        None => vec![m],
    };
    let occ = reference(file);
    let faces: u64 = parts.iter().map(|p| p["faces"].as_u64().unwrap()).sum();
    assert_eq!(faces, occ["counts"]["faces"].as_u64().unwrap(), "{file}: faces");
    let volumes: Vec<f64> = parts
        .iter()
        .flat_map(|p| p["solids"].as_array().unwrap().iter().map(|s| s["volume"].as_f64().unwrap()))
        .collect();
    let occ_volumes: Vec<f64> = occ["volume_solids"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
    assert_eq!(volumes.len(), occ_volumes.len(), "{file}: solids");
    for (k, (v, w)) in volumes.iter().zip(&occ_volumes).enumerate() {
        assert!((v - w).abs() <= expect.volume * w.abs(), "{file}: solid {k}'s volume {v} against OpenCASCADE's {w}");
    }
    let area: f64 = parts.iter().map(|p| p["area"].as_f64().unwrap()).sum();
    let occ_area = occ["area"].as_f64().unwrap();
    assert!((area - occ_area).abs() <= expect.area * occ_area, "{file}: area {area} against OpenCASCADE's {occ_area}");
    for (k, p) in parts.iter().enumerate() {
        let mesh = &p["mesh"];
        let tolerance = mesh["tolerance"].as_f64().unwrap();
        if expect.closed_mesh {
            assert_eq!(mesh["open_edges"].as_u64(), Some(0), "{file}: part {k}'s mesh has open edges");
        }
        // The mesh's vertices lie on the faces, so its box lies within the exact box (by
        // OpenCASCADE's optimal box) and reaches it to within the chord tolerance.
        let (lo, hi) = (&mesh["box"][0], &mesh["box"][1]);
        let (occ_lo, occ_hi) = (&occ["bbox_optimal"]["min"], &occ["bbox_optimal"]["max"]);
        if parts.len() == 1 {
            for i in 0..3 {
                let (a, b) = (lo[i].as_f64().unwrap(), occ_lo[i].as_f64().unwrap());
                let (c, d) = (hi[i].as_f64().unwrap(), occ_hi[i].as_f64().unwrap());
                assert!(a >= b - 1e-9 * d.abs().max(1.0) && a - b <= tolerance, "{file}: box min[{i}] {a} against {b}");
                assert!(c <= d + 1e-9 * d.abs().max(1.0) && d - c <= tolerance, "{file}: box max[{i}] {c} against {d}");
            }
        }
    }
}

#[test]
fn catia_v5_block_with_a_hole_in_inches() {
    check("catiav5_one_hole_ap242_inch.stp", Expect { area: 1e-14, volume: 1e-12, closed_mesh: true });
}

#[test]
fn catia_v5_with_a_signature_after_the_end_marker() {
    check("catiav5_one_hole_ap242_inch_signed.stp", Expect { area: 1e-14, volume: 1e-12, closed_mesh: true });
}

#[test]
fn fusion_360_horn() {
    check("fusion360_passive_horn_ap242.stp", Expect { area: 1e-14, volume: 1e-12, closed_mesh: true });
}

#[test]
fn pro_engineer_2000i_axle_in_metres() {
    check("proe2000_lego_gear_shaft_m.stp", Expect { area: 1e-14, volume: 1e-12, closed_mesh: true });
}

/// Rhino's cylinder is cut by a B-spline surface: the cut's pcurves are fitted within
/// 10⁻⁷ of the part's size, which bounds the area's error.
#[test]
fn rhino_8_sliced_cylinder_in_centimetres() {
    check("rhino8_sliced_cylinder_cm.stp", Expect { area: 1e-5, volume: 1e-5, closed_mesh: true });
}

/// Inventor's bolt: area and volume within 2·10⁻⁸ of OpenCASCADE's (pcurves fitted on its
/// cone and thread); before its faces were filled by the parity of the loops crossed, two
/// slivers along its edges left 40 open edges.
#[test]
fn inventor_2011_bolt_with_crlf_lines() {
    check("inventor2011_din933_m4x8_crlf.stp", Expect { area: 1e-7, volume: 1e-7, closed_mesh: true });
}

/// SolidWorks 2017's timing pulley: 76 faces, exact (its teeth's pcurves are exact lines
/// and circles); its mesh had 161 open edges before faces were filled by parity.
#[test]
fn solidworks_2017_timing_pulley() {
    check("sw2017_timing_pulley_mm.stp", Expect { area: 1e-14, volume: 1e-13, closed_mesh: true });
}

/// SolidWorks 2018's plate written as AP203 (no colours) in inches.
#[test]
fn solidworks_2018_plate_ap203_in_inches() {
    check("sw2018_base_interface_ap203_inch.stp", Expect { area: 1e-14, volume: 1e-13, closed_mesh: true });
}
