//! The product structure and colours of real CAD files, against OpenCASCADE and against
//! the files' own text.
//!
//! The STEP files are the repository's `tests/step/real/` (SOURCES.md says where each
//! came from), or the folder in `SPLINEKIT_REAL_STEP`; a file missing from it fails. OpenCASCADE's numbers are in
//! `tests/data/real/occ_assembly.json`, made by `tools/occ_assembly_reference.py`
//! (XCAF: each leaf occurrence's path, part, solids, location and placed vertex box, each
//! part's colour).
//!
//! Independent checks:
//! - solid instances: the number of solids OpenCASCADE makes;
//! - placement: every instance's solids' `VERTEX_POINT`s, found by following references
//!   from the solid (not by the module's own reading), moved by the instance's placement,
//!   span OpenCASCADE's vertex box of the same instance within 1e-6 of the file's diagonal
//!   (or lie inside it where OpenCASCADE's shape healing made more vertices), and lie inside
//!   OpenCASCADE's optimal box of the whole shape (`occ_reference.json` beside the files);
//! - paths: for assemblies, the names OpenCASCADE gives each component;
//! - colours: each styled item's surface colour is the `COLOUR_RGB` literal its style
//!   chain reaches in the file's text (a scanner of the text, not the Part 21 reader), and
//!   the colour OpenCASCADE gives each part.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::PathBuf;

use serde_json::Value;
use splinekit_step::assembly::{ProductStructure, read_product_structure};
use splinekit_step::part21::{Param, StepFile};
use splinekit_step::structure::structure_entities;
use splinekit_step::styles::{Rgba, StyledKind, read_styles};
use splinekit_step::units::context_units;

fn folder() -> PathBuf {
    std::env::var("SPLINEKIT_REAL_STEP")
        .map(PathBuf::from)
        .unwrap_or_else(|_| PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/step/real")))
}

fn occ() -> serde_json::Map<String, Value> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/real/occ_assembly.json");
    let text = std::fs::read_to_string(path).expect("occ_assembly.json");
    match serde_json::from_str(&text).expect("JSON") {
        Value::Object(m) => m,
        _ => panic!("occ_assembly.json is an object"),
    }
}

fn files() -> Vec<(String, PathBuf, Value)> {
    let dir = folder();
    let mut out = Vec::new();
    for (name, reference) in occ() {
        if name.starts_with('_') {
            continue;
        }
        let path = dir.join(&name);
        assert!(path.is_file(), "{} missing", path.display());
        out.push((name, path, reference));
    }
    out
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array().expect("an array").iter().map(|x| x.as_f64().expect("a number")).collect()
}

type Box3 = ([f64; 3], [f64; 3]);

fn empty_box() -> Box3 {
    ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3])
}

fn grow(b: &mut Box3, p: [f64; 3]) {
    for k in 0..3 {
        b.0[k] = b.0[k].min(p[k]);
        b.1[k] = b.1[k].max(p[k]);
    }
}

fn box_of(v: &Value) -> Box3 {
    let (lo, hi) = (numbers(&v["min"]), numbers(&v["max"]));
    ([lo[0], lo[1], lo[2]], [hi[0], hi[1], hi[2]])
}

fn box_gap(a: &Box3, b: &Box3) -> f64 {
    (0..3).map(|k| (a.0[k] - b.0[k]).abs().max((a.1[k] - b.1[k]).abs())).fold(0.0, f64::max)
}

fn diagonal(b: &Box3) -> f64 {
    (0..3).map(|k| (b.1[k] - b.0[k]).powi(2)).sum::<f64>().sqrt()
}

/// The coordinates of every VERTEX_POINT reachable from `item` by references, in the
/// file's numbers.
fn vertex_points(file: &StepFile, item: u64) -> Vec<[f64; 3]> {
    let mut seen = HashSet::new();
    let mut stack = vec![item];
    let mut out = Vec::new();
    while let Some(id) = stack.pop() {
        if !seen.insert(id) {
            continue;
        }
        let inst = file.get(id).expect("instance");
        if inst.records[0].name == "VERTEX_POINT" {
            let Some(Param::Reference(p)) = inst.records[0].params.get(1) else { panic!("#{id}: vertex point") };
            let point = file.get(*p).expect("point");
            let Some(Param::List(c)) = point.records[0].params.get(1) else { panic!("#{p}: coordinates") };
            let c: Vec<f64> = c
                .iter()
                .map(|x| match x {
                    Param::Real(x) => *x,
                    Param::Integer(i) => *i as f64,
                    other => panic!("#{p}: {other:?}"),
                })
                .collect();
            out.push([c[0], c.get(1).copied().unwrap_or(0.0), c.get(2).copied().unwrap_or(0.0)]);
            continue;
        }
        for r in &inst.records {
            r.params.iter().for_each(|p| p.for_each_reference(&mut |x| stack.push(x)));
        }
    }
    out
}

/// Each instance's box of placed solid vertices and how many distinct vertices there
/// are (None for an instance without solids).
fn instance_boxes(file: &StepFile, s: &ProductStructure) -> Vec<Option<(Box3, usize)>> {
    let mut points: HashMap<u64, Vec<[f64; 3]>> = HashMap::new();
    s.instances
        .iter()
        .map(|inst| {
            let part = &s.parts[inst.part];
            let mut b = empty_box();
            let mut count = 0;
            for item in part.items.iter().filter(|i| i.kind.is_solid()) {
                let mm = context_units(file, item.context).expect("units").length;
                let pts = points.entry(item.id).or_insert_with(|| vertex_points(file, item.id));
                for p in pts.iter() {
                    let local = p.map(|c| c * mm);
                    grow(&mut b, inst.placement.apply(item.placement.apply(local)));
                    count += 1;
                }
            }
            (count > 0).then_some((b, count))
        })
        .collect()
}

/// Whether box `a` lies inside `b` grown by `tolerance`.
fn inside(a: &Box3, b: &Box3, tolerance: f64) -> bool {
    (0..3).all(|k| a.0[k] >= b.0[k] - tolerance && a.1[k] <= b.1[k] + tolerance)
}

fn solids_of(s: &ProductStructure, i: usize) -> usize {
    s.parts[s.instances[i].part].items.iter().filter(|i| i.kind.is_solid()).count()
}

#[test]
fn instances_parts_and_placements_match_opencascade() {
    let mut table = Vec::new();
    for (name, path, reference) in files() {
        let file = StepFile::open(&path).expect("the file reads");
        let s = read_product_structure(&file).unwrap_or_else(|e| panic!("{name}: {e}"));
        for note in &s.notes {
            eprintln!("{name}: note: {note}");
        }
        let solids: usize = (0..s.instances.len()).map(|i| solids_of(&s, i)).sum();
        let occ_solids = reference["solids"].as_u64().expect("solids") as usize;
        assert_eq!(solids, occ_solids, "{name}: solid instances");
        let occ_instances: Vec<&Value> = reference["instances"]
            .as_array()
            .expect("instances")
            .iter()
            .filter(|i| i["solids"].as_u64() > Some(0))
            .collect();
        let ours: Vec<usize> = (0..s.instances.len()).filter(|&i| solids_of(&s, i) > 0).collect();
        assert_eq!(ours.len(), occ_instances.len(), "{name}: instances with solids");
        let parts_with_solids = s.parts.iter().filter(|p| p.items.iter().any(|i| i.kind.is_solid())).count();
        let occ_parts =
            reference["parts"].as_array().expect("parts").iter().filter(|p| p["solids"].as_u64() > Some(0)).count();
        assert_eq!(parts_with_solids, occ_parts, "{name}: parts");

        // Boxes: each of ours has OCC's instance of the same box (matched greedily, since
        // OCC's order and names of loose solids differ).
        let file_box = box_of(&reference["vertex_box"]);
        let diag = diagonal(&file_box);
        let boxes = instance_boxes(&file, &s);
        let mut unmatched: Vec<(Box3, usize)> = occ_instances
            .iter()
            .map(|i| (box_of(&i["vertex_box"]), i["vertices"].as_u64().expect("vertices") as usize))
            .collect();
        let mut worst = 0.0_f64;
        let mut healed = 0;
        let mut total = empty_box();
        for &i in &ours {
            let (b, vertices) = boxes[i].expect("a solid instance has vertices");
            grow(&mut total, b.0);
            grow(&mut total, b.1);
            let (k, gap) = unmatched
                .iter()
                .enumerate()
                .map(|(k, o)| (k, box_gap(&b, &o.0)))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .expect("an OCC instance left");
            let (occ_box, occ_vertices) = unmatched.remove(k);
            if occ_vertices == vertices {
                assert!(
                    gap <= 1e-6 * diag,
                    "{name}: instance {:?}: box {b:?} is {gap} from OCC's {occ_box:?}",
                    s.instances[i].path
                );
                worst = worst.max(gap / diag);
            } else {
                // OCC's shape healing split edges and made vertices the file does not
                // have: the file's vertices lie inside OCC's box.
                assert!(occ_vertices > vertices, "{name}: OCC has {occ_vertices} vertices, the file {vertices}");
                assert!(
                    inside(&b, &occ_box, 1e-6 * diag),
                    "{name}: instance {:?}: box {b:?} outside OCC's {occ_box:?}",
                    s.instances[i].path
                );
                healed += 1;
            }
        }

        // Paths of assemblies, as OCC names components (NAUO name, else its id).
        let has_assembly = file.ids_of_type("NEXT_ASSEMBLY_USAGE_OCCURRENCE").next().is_some();
        if has_assembly {
            let mut ours_paths: Vec<Vec<String>> =
                ours.iter().map(|&i| s.instances[i].path.iter().map(|o| o.name.clone()).collect()).collect();
            let mut occ_paths: Vec<Vec<String>> = occ_instances
                .iter()
                .map(|i| {
                    i["path"].as_array().expect("path").iter().map(|x| x.as_str().unwrap_or("").to_string()).collect()
                })
                .collect();
            ours_paths.sort();
            occ_paths.sort();
            assert_eq!(ours_paths, occ_paths, "{name}: occurrence paths");
            // And the placements themselves, path by path.
            for &i in &ours {
                let names: Vec<&str> = s.instances[i].path.iter().map(|o| o.name.as_str()).collect();
                let o = occ_instances
                    .iter()
                    .find(|o| {
                        o["path"]
                            .as_array()
                            .is_some_and(|p| p.iter().map(|x| x.as_str().unwrap_or("")).eq(names.iter().copied()))
                    })
                    .expect("the same path");
                let (r, t) = (numbers(&o["rotation"]), numbers(&o["translation"]));
                let p = s.instances[i].placement;
                for a in 0..3 {
                    assert!(
                        (p.translation[a] - t[a]).abs() <= 1e-9 * diag,
                        "{name} {names:?}: translation {p:?} vs {t:?}"
                    );
                    for b in 0..3 {
                        assert!(
                            (p.rotation[a][b] - r[3 * a + b]).abs() <= 1e-9,
                            "{name} {names:?}: rotation {p:?} vs {r:?}"
                        );
                    }
                }
            }
        }
        // The solids' vertex box against OCC's optimal box of the shape (which reaches past
        // the vertices where a curved face bulges).
        let optimal = folder().join("occ_reference.json");
        let optimal_box = std::fs::read_to_string(&optimal)
            .ok()
            .and_then(|t| serde_json::from_str::<Value>(&t).ok())
            .and_then(|v| v.get(&name).map(|e| box_of(&e["bbox_optimal"])));
        if let Some(o) = optimal_box {
            assert!(inside(&total, &o, 1e-6 * diagonal(&o)), "{name}: vertices {total:?} outside OCC's box {o:?}");
        }
        let optimal_gap = optimal_box.map(|o| box_gap(&total, &o) / diagonal(&o));
        table.push(format!(
            "{name:42} parts {:2} instances {:2} solids {:2}  placed vertex boxes vs OCC's {worst:.1e}{}  vs OCC optimal box {}",
            s.parts.len(),
            s.instances.len(),
            solids,
            if healed > 0 { format!(" ({healed} healed by OCC: inside)") } else { String::new() },
            optimal_gap.map_or("-".into(), |g| format!("{g:.1e}"))
        ));
    }
    eprintln!("{}", table.join("\n"));
}

/// A scanner of a STEP file's data section: `#id` → (type, the text between the type's
/// parentheses), for simple instances (quotes respected).
fn scan(path: &PathBuf) -> HashMap<u64, (String, String)> {
    let text = String::from_utf8_lossy(&std::fs::read(path).expect("read")).into_owned();
    let data = &text[text.find("DATA;").expect("DATA") + 5..];
    let mut out = HashMap::new();
    let mut statement = String::new();
    let mut quoted = false;
    for ch in data.chars() {
        if ch == '\'' {
            quoted = !quoted;
        }
        if ch == ';' && !quoted {
            let s = statement.trim().replace(['\r', '\n'], "");
            statement.clear();
            let Some(rest) = s.strip_prefix('#') else { continue };
            let Some((id, body)) = rest.split_once('=') else { continue };
            let Ok(id) = id.trim().parse::<u64>() else { continue };
            let body = body.trim();
            if let Some(open) = body.find('(') {
                let t = body[..open].trim().to_string();
                let args = body[open + 1..body.len().saturating_sub(1)].to_string();
                out.insert(id, (t, args));
            }
            continue;
        }
        statement.push(ch);
    }
    out
}

fn references(args: &str) -> Vec<u64> {
    let mut out = Vec::new();
    let b = args.as_bytes();
    let mut k = 0;
    while k < b.len() {
        if b[k] == b'#' {
            let start = k + 1;
            let mut end = start;
            while end < b.len() && b[end].is_ascii_digit() {
                end += 1;
            }
            if let Ok(id) = args[start..end].parse() {
                out.push(id);
            }
            k = end;
        } else {
            k += 1;
        }
    }
    out
}

/// The colours written literally (COLOUR_RGB numbers, pre-defined names) that a styled
/// item's styles reach, not through curve styles.
fn literal_surface_colours(text: &HashMap<u64, (String, String)>, styles: &[u64]) -> Vec<[f64; 3]> {
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    let mut stack = styles.to_vec();
    while let Some(id) = stack.pop() {
        if !seen.insert(id) {
            continue;
        }
        let Some((t, args)) = text.get(&id) else { continue };
        match t.as_str() {
            "CURVE_STYLE" => {}
            "COLOUR_RGB" => {
                let n: Vec<f64> = args.split(',').skip(1).map(|x| x.trim().parse().expect("a number")).collect();
                out.push([n[0], n[1], n[2]]);
            }
            _ => stack.extend(references(args)),
        }
    }
    out
}

#[test]
fn colours_match_the_literal_colours_and_opencascade() {
    let mut table = Vec::new();
    for (name, path, reference) in files() {
        let file = StepFile::open(&path).expect("the file reads");
        let styles = read_styles(&file);
        let text = scan(&path);
        // Every styled item of the text is read, with the colour its chain spells.
        let mut styled = 0;
        for (id, (t, args)) in &text {
            if !matches!(
                t.as_str(),
                "STYLED_ITEM" | "OVER_RIDING_STYLED_ITEM" | "CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM"
            ) {
                continue;
            }
            styled += 1;
            let refs = references(args);
            let (style_refs, target) = {
                // name, (styles…), item, …: the styles are the references before the item.
                let open = args.find('(').expect("styles list");
                let close = open + args[open..].find(')').expect("closed");
                (references(&args[open..close]), references(&args[close..])[0])
            };
            let s = styles.styles.iter().find(|s| s.styled_item == *id).unwrap_or_else(|| panic!("{name}: #{id} read"));
            assert_eq!(s.item, target, "{name}: #{id} item ({refs:?})");
            let literal = literal_surface_colours(&text, &style_refs);
            match (literal.as_slice(), s.surface) {
                ([], None) => {}
                ([c], Some(got)) => {
                    assert_eq!([got.red, got.green, got.blue], *c, "{name}: #{id} colour");
                }
                (l, got) => {
                    // A pre-defined colour has no literal numbers.
                    assert!(l.is_empty() && got.is_some(), "{name}: #{id}: literal {l:?}, read {got:?}");
                }
            }
        }
        assert_eq!(styles.styles.len(), styled, "{name}: styled items");
        assert!(styles.skipped.is_empty(), "{name}: {:?}", styles.skipped);

        // OCC's colour of each part is the colour our styles give its solids (through the
        // solid, or its representation for a context-dependent override).
        let s = read_product_structure(&file).expect("structure");
        let mut occ_colours: BTreeMap<String, Option<[f64; 3]>> = BTreeMap::new();
        for p in reference["parts"].as_array().expect("parts") {
            if p["solids"].as_u64() > Some(0) {
                let c = p["colour"].as_array().map(|c| {
                    let n: Vec<f64> = c.iter().map(|x| x.as_f64().expect("number")).collect();
                    [n[0], n[1], n[2]]
                });
                occ_colours.insert(p["name"].as_str().unwrap_or("").to_string(), c);
            }
        }
        let mut agreed = 0;
        let solid_parts: Vec<_> = s.parts.iter().filter(|p| p.items.iter().any(|i| i.kind.is_solid())).collect();
        for part in &solid_parts {
            // By name; OCC names the solid of a one-part file 'SOLID' where the product's
            // shape holds other representations too.
            let single = (solid_parts.len() == 1 && occ_colours.len() == 1).then(|| occ_colours.values().next());
            let Some(Some(occ)) = occ_colours.get(&part.name).or(single.flatten()) else { continue };
            for item in part.items.iter().filter(|i| i.kind.is_solid()) {
                let chain: Vec<u64> = std::iter::once(item.id).chain(part.representations.iter().copied()).collect();
                let got: Rgba = styles
                    .effective(&chain)
                    .unwrap_or_else(|| panic!("{name}: {} has OCC's colour {occ:?}", part.name));
                assert!(
                    (0..3).all(|k| (got.to_array()[k] - occ[k]).abs() < 1e-6),
                    "{name}: {}: {got:?} vs OCC's {occ:?}",
                    part.name
                );
                agreed += 1;
            }
        }
        let kinds = |k: StyledKind| styles.styles.iter().filter(|s| s.kind == k && s.surface.is_some()).count();
        table.push(format!(
            "{name:42} styled items {:2}: solids {:2} faces {:2} representations {:2} mapped {:2}  colours agreeing with OCC {agreed}",
            styles.styles.len(),
            kinds(StyledKind::Solid),
            kinds(StyledKind::Face),
            kinds(StyledKind::Representation),
            kinds(StyledKind::MappedItem),
        ));
    }
    eprintln!("{}", table.join("\n"));
}

#[test]
fn structure_entities_cover_the_product_and_style_structure() {
    for (name, path, _) in files() {
        let file = StepFile::open(&path).expect("the file reads");
        let read = structure_entities(&file);
        for t in [
            "NEXT_ASSEMBLY_USAGE_OCCURRENCE",
            "CONTEXT_DEPENDENT_SHAPE_REPRESENTATION",
            "ITEM_DEFINED_TRANSFORMATION",
            "PRODUCT",
            "PRODUCT_DEFINITION",
            "STYLED_ITEM",
            "OVER_RIDING_STYLED_ITEM",
            "CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM",
            "MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION",
        ] {
            for id in file.ids_of_type(t) {
                assert!(read.contains(&id), "{name}: #{id} {t} is not marked read");
            }
        }
    }
}

/// The brep documents carry the colours: SolidWorks 2018's plate is styled once, on its
/// solid (`COLOUR_RGB #77` and its copy #534), and every face shows it; written as f32.
#[test]
fn brep_faces_and_solids_take_their_colours() {
    use splinekit_scene::{ShapeDocument, SurfaceDocument};
    let path = folder().join("sw2018_base_interface_ap214_inch.stp");
    let file = StepFile::open(&path).expect("the file reads");
    let items = splinekit_step::documents::import_items(&file).expect("it converts");
    let expected = [0.792_156_862_745_098_f64, 0.819_607_843_137_254_9, 0.933_333_333_333_333_3, 1.0].map(|x| x as f32);
    let breps: Vec<_> = items
        .items
        .iter()
        .filter_map(|i| match &i.document {
            ShapeDocument::Surface(SurfaceDocument::Brep(b)) => Some(b),
            _ => None,
        })
        .collect();
    assert_eq!(breps.len(), 1);
    assert_eq!(breps[0].faces.len(), 30);
    assert!(breps[0].faces.iter().all(|f| f.color == Some(expected)), "{:?}", breps[0].faces[0].color);
    assert_eq!(breps[0].solids[0].color, Some(expected));
    // Pro/ENGINEER's axle has no styles: no colours.
    let file = StepFile::open(&folder().join("proe2000_lego_gear_shaft_m.stp")).expect("the file reads");
    let items = splinekit_step::documents::import_items(&file).expect("it converts");
    for i in &items.items {
        if let ShapeDocument::Surface(SurfaceDocument::Brep(b)) = &i.document {
            assert!(b.faces.iter().all(|f| f.color.is_none()));
        }
    }
}

/// The documents a file is read as stand where OpenCASCADE places its parts: each solid's
/// `brep` vertices, moved by the item's placement, lie inside the box of OpenCASCADE's
/// placed vertices, and (where OpenCASCADE's healing made no extra vertices) span it; as
/// many solids as OpenCASCADE's instances hold. A part used again is an instance of its
/// first use, with the same document. The assemblies (importing every file's faces takes
/// minutes in a debug build; the parts of one product stand at the identity).
#[test]
fn imported_parts_stand_where_opencascade_places_them() {
    use splinekit_scene::{ShapeDocument, SurfaceDocument};
    let assemblies = [
        "freecad_flange_screw_aligner_asm.stp",
        "fusion360_sensor_assembly_voids.stp",
        "inventor2011_din933_m4x8_crlf.stp",
        "sw2015_box_sides_assembly_inch.stp",
    ];
    for (name, path, reference) in files().into_iter().filter(|(n, _, _)| assemblies.contains(&n.as_str())) {
        let file = StepFile::open(&path).expect("the file reads");
        let imported = splinekit_step::documents::import_items(&file).unwrap_or_else(|e| panic!("{name}: {e}"));
        let occ_box = box_of(&reference["vertex_box"]);
        let diag = diagonal(&occ_box);
        let mut ours = empty_box();
        let mut solids = 0;
        for (k, item) in imported.items.iter().enumerate() {
            let ShapeDocument::Surface(SurfaceDocument::Brep(b)) = &item.document else { continue };
            solids += b.solids.len();
            if let Some(first) = item.instance_of {
                assert!(first < k && imported.items[first].instance_of.is_none(), "{name}: item {k} of {first}");
                assert_eq!(imported.items[first].document, item.document, "{name}: item {k}");
            }
            for v in &b.vertices {
                let p = [v[0], v[1], v[2]];
                grow(&mut ours, item.placement.map_or(p, |t| t.apply(p)));
            }
        }
        assert_eq!(solids, reference["solids"].as_u64().expect("solids") as usize, "{name}: solids");
        assert!(inside(&ours, &occ_box, 1e-6 * diag), "{name}: {ours:?} outside OCC's {occ_box:?}");
        let occ_vertices: u64 =
            reference["instances"].as_array().expect("instances").iter().filter_map(|i| i["vertices"].as_u64()).sum();
        eprintln!(
            "{name}: placed box {:.1e} of the diagonal from OCC's ({occ_vertices} OCC vertices)",
            box_gap(&ours, &occ_box) / diag
        );
    }
    // SolidWorks 2015's box: ten uses of six parts, the four repeats instances.
    let file = StepFile::open(&folder().join("sw2015_box_sides_assembly_inch.stp")).expect("the file reads");
    let imported = splinekit_step::documents::import_items(&file).expect("it converts");
    assert_eq!(imported.items.len(), 10);
    assert_eq!(imported.items.iter().filter(|i| i.instance_of.is_some()).count(), 4);
    assert!(imported.items.iter().all(|i| i.placement.is_some()));
    assert!(imported.items[0].name.starts_with("box_base ("), "{}", imported.items[0].name);
}
