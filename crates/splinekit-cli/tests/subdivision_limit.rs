//! `splinekit subdivide-surface` with the schemes, creases and `--limit` of issue 24.

mod common;
use common::{ScratchDir, run};

fn cube() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/meshes/cube.obj")).unwrap()
}

/// Runs `splinekit subdivide-surface ARGS` on `stdin` and checks that it succeeds.
fn subdivide(args: &[&str], stdin: &str) -> common::Output {
    let o = run(&[&["subdivide-surface"], args].concat(), stdin);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    o
}

/// `splinekit subdivide-surface - --scheme SCHEME FLAGS… -o OUT` on `stdin`, checked to
/// succeed; returns the file it wrote.
fn subdivided(scheme: &str, flags: &[&str], out: &std::path::Path, stdin: &str) -> String {
    let path = out.to_str().unwrap();
    subdivide(&[&["-", "--scheme", scheme], flags, &["-o", path]].concat(), stdin);
    std::fs::read_to_string(out).unwrap()
}

/// `splinekit subdivide-surface ARGS` on `stdin`: exit 2, nothing on standard output, one
/// line naming `must_contain`.
fn assert_refused(args: &[&str], stdin: &str, must_contain: &str) {
    let args = [&["subdivide-surface"], args].concat();
    let o = run(&args, stdin);
    assert_eq!(o.code, 2, "{args:?}: exit {} (stderr {:?})", o.code, o.stderr);
    assert!(o.stdout.is_empty(), "{args:?}: printed {:?}", o.stdout);
    assert_eq!(o.stderr.lines().count(), 1, "{args:?}: stderr {:?}", o.stderr);
    assert!(o.stderr.starts_with("error: ") && !o.stderr.contains("panicked"), "{:?}", o.stderr);
    assert!(o.stderr.contains(must_contain), "{args:?}: {:?} lacks {must_contain:?}", o.stderr);
}

fn lines(text: &str, tag: &str) -> Vec<Vec<f64>> {
    text.lines()
        .filter(|l| l.starts_with(tag))
        .map(|l| l.split_whitespace().skip(1).map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// `--steps 0 --limit` gives the cube's limit points in input order: (±½, ±½, ±½) (the
/// valence-3 mask (9v + 4Σe + Σd)/24), with normals along them.
#[test]
fn steps_zero_limit_gives_the_cage_limit_points_in_order() {
    let dir = ScratchDir::new("subdiv-zero");
    let out = dir.join("limit.obj");

    let text = subdivided("catmull-clark", &["--steps", "0", "--limit"], &out, &cube());
    let cage = lines(&cube(), "v ");
    let v = lines(&text, "v ");
    let n = lines(&text, "vn ");
    assert_eq!(v.len(), 8);
    assert_eq!(n.len(), 8);
    for i in 0..8 {
        for c in 0..3 {
            assert!((v[i][c] - cage[i][c] / 2.0).abs() < 1e-15, "vertex {i}: {:?}", v[i]);
            assert!((n[i][c] - cage[i][c] / 3f64.sqrt()).abs() < 1e-15, "normal {i}: {:?}", n[i]);
        }
    }
    assert!(text.contains("f 1//1 3//3 4//4 2//2"));
    // Two steps: the face centre vertex (index 8 + face) is at the limit 68/81.

    let v = lines(&subdivided("catmull-clark", &["--steps", "2", "--limit"], &out, &cube()), "v ");
    assert!(v.iter().any(|p| p[0].abs() < 1e-15 && p[1].abs() < 1e-15 && (p[2] - 68.0 / 81.0).abs() < 1e-15));
}

/// Loop on triangles, bilinear, OBJ crease tags and boundary rules from the command line.
#[test]
fn schemes_creases_and_boundaries() {
    let dir = ScratchDir::new("subdiv-schemes");
    let out = dir.join("out.obj");

    let text = subdivided("loop", &["--triangulate", "--steps", "1"], &out, &cube());
    // 12 triangles → 48; 8 + 18 edges vertices.
    assert_eq!(lines(&text, "f ").len(), 48);
    assert_eq!(lines(&text, "v ").len(), 26);
    let v = lines(&subdivided("bilinear", &["--steps", "1", "--limit"], &out, &cube()), "v ");
    assert_eq!(v[7], vec![1.0, 1.0, 1.0], "bilinear keeps the cage's vertices");
    // An infinitely sharp crease ring around the cube's top face (OBJ tags, 0-based): the
    // top corners have two sharp edges, so they are crease vertices with the limit
    // (e₀ + 4v + e₁)/6 of the cubic B-spline crease curve: for (1, 1, 1) with crease
    // neighbours (−1, 1, 1) and (1, −1, 1), (2/3, 2/3, 1).
    let creased =
        format!("{}t crease 2/1 4 5 10\nt crease 2/1 5 7 10\nt crease 2/1 7 6 10\nt crease 2/1 6 4 10\n", cube());
    let text = subdivided("catmull-clark", &["--steps", "0", "--limit"], &out, &creased);
    let v = lines(&text, "v ");
    for (x, want) in v[7].iter().zip([2.0 / 3.0, 2.0 / 3.0, 1.0]) {
        assert!((x - want).abs() < 1e-15, "{:?}", v[7]);
    }
    // The crease splits the normals: the top face's corners and the side faces' corners at
    // the four top vertices each get their own `vn` (8 vertex normals + 8 side ones).
    assert_eq!(lines(&text, "vn ").len(), 16);
    assert!(text.contains("f 5//5 6//6 8//8 7//7") && text.contains("f 1//1 2//2 6//9 5//10"), "{text}");
    let n = lines(&text, "vn ");
    assert!(n[8][2] < n[5][2] - 0.1, "the side's normal at the crease leans outward: {:?} vs {:?}", n[8], n[5]);
    // An open grid of one quad: edge-only smooths its corners, edge-and-corner keeps them.
    let quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    let text = subdivided("catmull-clark", &["--steps", "0", "--limit", "--boundary", "edge-and-corner"], &out, quad);
    assert_eq!(lines(&text, "v ")[2], vec![1.0, 1.0, 0.0]);
}

/// Doo–Sabin's `--limit` on the cube [−1, 1]³: a corner's points in its three faces are
/// 9/16 v + 3/16 (two neighbours) + 1/16 (the opposite corner), e.g. (½, ½, 1); their
/// centroid, the limit, is ⅔ v, the normal v/√3 by symmetry. After two steps every vertex
/// has moved (the polygons' count and order kept).
#[test]
fn doo_sabin_limit_points_of_the_cube() {
    let dir = ScratchDir::new("subdiv-doo-sabin");
    let out = dir.join("limit.obj");
    let limit_of = |steps: &str| subdivided("doo-sabin", &["--steps", steps, "--limit"], &out, &cube());
    let text = limit_of("0");
    let (cage, v, n) = (lines(&cube(), "v "), lines(&text, "v "), lines(&text, "vn "));
    assert_eq!((v.len(), n.len()), (8, 8));
    for i in 0..8 {
        for c in 0..3 {
            assert!((v[i][c] - cage[i][c] * 2.0 / 3.0).abs() < 1e-15, "vertex {i}: {:?}", v[i]);
            assert!((n[i][c] - cage[i][c] / 3f64.sqrt()).abs() < 1e-15, "normal {i}: {:?}", n[i]);
        }
    }
    let limit = limit_of("2");
    let plain = dir.join("plain.obj");
    let plain = subdivided("doo-sabin", &["--steps", "2"], &plain, &cube());
    let (a, b) = (lines(&limit, "v "), lines(&plain, "v "));
    assert_eq!(a.len(), b.len());
    assert_eq!(
        limit.lines().filter(|l| l.starts_with("f ")).count(),
        plain.lines().filter(|l| l.starts_with("f ")).count()
    );
    assert!(a.iter().zip(&b).all(|(p, q)| p != q), "every vertex moves onto the limit");
}

#[test]
fn bad_subdivision_input_is_refused_in_one_line() {
    let out = std::env::temp_dir().join("splinekit-subdiv-never.obj");
    let o = out.to_str().unwrap();
    // Doo–Sabin's limit needs a closed mesh: the cube without its last face is open.
    let open: String = {
        let text = cube();
        let last = text.lines().rfind(|l| l.starts_with("f ")).unwrap().to_string();
        text.lines().filter(|&l| l != last).map(|l| format!("{l}\n")).collect()
    };
    assert_refused(&["-", "--scheme", "doo-sabin", "--limit", "-o", o], &open, "open border");
    assert_refused(&["-", "--scheme", "loop", "-o", o], &cube(), "faces[0]");
    let bad_tag = format!("{}t crease 2/1 0 1\n", cube());
    assert_refused(&["-", "--scheme", "catmull-clark", "-o", o], &bad_tag, "crease");
    let not_edge = format!("{}t crease 2/1 0 7 2\n", cube());
    assert_refused(&["-", "--scheme", "catmull-clark", "-o", o], &not_edge, "creases[0]");
    let negative = format!("{}t crease 2/1 0 1 -2\n", cube());
    assert_refused(&["-", "--scheme", "catmull-clark", "-o", o], &negative, "sharpness");
    assert!(!out.exists());
}

/// `--at FACE,U,V` prints the exact limit: the cube's face centre at 68/81 with its
/// partials (a regular point), its corner (±½, ±½, ±½) without (an extraordinary vertex).
#[test]
fn at_evaluates_the_limit_exactly() {
    let o = subdivide(&["-", "--scheme", "catmull-clark", "--at", "1,0.5,0.5", "--at", "1,0,0"], &cube());
    let v: serde_json::Value = serde_json::from_str(&o.stdout).unwrap();
    let z = v[0]["position"][2].as_f64().unwrap();
    assert!((z - 68.0 / 81.0).abs() < 1e-15, "{z}");
    assert!((v[0]["normal"][2].as_f64().unwrap() - 1.0).abs() < 1e-15);
    assert!(v[0]["partials"]["du"].is_array());
    assert!(v[1]["partials"].is_null());
    for c in 0..3 {
        assert!((v[1]["position"][c].as_f64().unwrap().abs() - 0.5).abs() < 1e-15);
    }
    assert_refused(&["-", "--scheme", "catmull-clark", "--at", "1,0.5"], &cube(), "FACE,U,V");
    assert_refused(&["-", "--scheme", "catmull-clark", "--at", "6,0.5,0.5"], &cube(), "6 does not exist");
    assert_refused(&["-", "--scheme", "loop", "--triangulate", "--at", "0,0.8,0.8"], &cube(), "outside");
    assert_refused(&["-", "--scheme", "catmull-clark"], &cube(), "-o");
}

/// `-o OUT.step`: the cube's 8 extraordinary vertices leave, after 3 levels, 2 × 72 exact
/// bicubic patches (regular faces of levels 2 and 3) and 24 bilinear ones (the faces at
/// the extraordinary vertices); --steps 0 and more than 30 levels are refused.
#[test]
fn step_export_writes_bicubic_patches() {
    let dir = ScratchDir::new("subdiv-step");
    let out = dir.join("cube.step");
    let o = subdivide(&["-", "--scheme", "catmull-clark", "--steps", "3", "-o", out.to_str().unwrap()], &cube());
    assert!(o.stderr.contains("144 exact bicubic patches, 24 bilinear stand-ins (down to level 3)"), "{}", o.stderr);
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("ISO-10303-21;"), "{}", &text[..40]);
    assert_eq!((degrees(&text, "3"), degrees(&text, "1")), (144, 24));
    let step = out.to_str().unwrap();
    assert_refused(&["-", "--scheme", "catmull-clark", "--steps", "0", "-o", step], &cube(), "at least 1");
    assert_refused(&["-", "--scheme", "catmull-clark", "--steps", "31", "-o", step], &cube(), "limit of 30");
    assert_refused(&["-", "--scheme", "doo-sabin", "-o", step], &cube(), "not doo-sabin");
}

/// `--scheme loop --triangulate -o OUT.step --tolerance 1e-4`: the fan-split cube as
/// (4, 4) patches with one collapsed edge and flat triangles (degree 1) within 10⁻⁴ of
/// the cage's size, as many as reported (the counts of splinekit-step's test of `convert`);
/// `--scheme bilinear` writes the six faces.
#[test]
fn step_export_of_loop_surfaces() {
    let dir = ScratchDir::new("subdiv-step-loop");
    let out = dir.join("loop.step");
    let o = subdivide(
        &["-", "--scheme", "loop", "--triangulate", "--tolerance", "1e-4", "-o", out.to_str().unwrap()],
        &cube(),
    );
    let text = std::fs::read_to_string(&out).unwrap();
    let (quartic, bilinear) = (degrees(&text, "4"), degrees(&text, "1"));
    assert_eq!((quartic, bilinear), (456, 24), "{}", o.stderr);
    assert!(o.stderr.contains("456 exact quartic patches, 24 bilinear stand-ins (down to level 7)"), "{}", o.stderr);
    let deviation: f64 = o.stderr.split("within ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
    assert!(deviation <= 1e-4 * 2.0 * 3f64.sqrt(), "{}", o.stderr);
    // The bilinear scheme: its six faces.
    let o = subdivide(&["-", "--scheme", "bilinear", "-o", out.to_str().unwrap()], &cube());
    assert!(o.stderr.contains("6 exact bilinear patches"), "{}", o.stderr);
    assert_eq!(degrees(&std::fs::read_to_string(&out).unwrap(), "1"), 6);
}

/// STEP `B_SPLINE_SURFACE_WITH_KNOTS` entities of degree `d` in both directions.
fn degrees(text: &str, d: &str) -> usize {
    text.lines().filter(|l| l.contains("B_SPLINE_SURFACE_WITH_KNOTS(") && l.contains(&format!(")',{d},{d},"))).count()
}

/// `-o OUT.step --tolerance 1e-6` on `creased_cube.obj`: each face at an extraordinary
/// vertex refined to the fewest levels within 10⁻⁶ of the cage's size (13 at the deepest,
/// the same patches as `convert` writes for the document); a tolerance 30 levels do not
/// reach is refused with the one they do, and --tolerance is for STEP only.
#[test]
fn step_export_meets_a_tolerance() {
    let dir = ScratchDir::new("subdiv-step-tolerance");
    let out = dir.join("creased.step");
    let mesh = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/meshes/creased_cube.obj");
    let o = subdivide(&[mesh, "--scheme", "catmull-clark", "--tolerance", "1e-6", "-o", out.to_str().unwrap()], "");
    let text = std::fs::read_to_string(&out).unwrap();
    let (bicubic, bilinear) = (degrees(&text, "3"), degrees(&text, "1"));
    assert!(
        o.stderr
            .contains(&format!("{bicubic} exact bicubic patches, {bilinear} bilinear stand-ins (down to level 13)")),
        "{}",
        o.stderr
    );
    let deviation: f64 = o.stderr.split("within ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
    assert!(deviation <= 1e-6 * 2.0 * 3f64.sqrt() && bilinear == 16, "{}", o.stderr);
    let step = out.to_str().unwrap();
    assert_refused(
        &[mesh, "--scheme", "catmull-clark", "--tolerance", "1e-15", "-o", step],
        "",
        "--tolerance: the patches at extraordinary vertices come within",
    );
    assert_refused(
        &[mesh, "--scheme", "catmull-clark", "--tolerance", "1e-3", "-o", "x.obj"],
        "",
        "--tolerance: is for .step output",
    );
}

/// An open cage around an extraordinary vertex: vertex 1 at the origin (valence 5, four
/// quads and a triangle around it), its ring on the boundary, off the plane by a little.
fn open_fan() -> String {
    let mut obj = String::from("v 0 0 0.1\n");
    let angle = |k: f64| std::f64::consts::TAU * k / 5.0;
    for k in 0..5 {
        let (s, c) = angle(k as f64).sin_cos();
        obj += &format!("v {} {} {}\n", c, s, 0.3 * (1.3 * k as f64).sin());
    }
    for k in 0..4 {
        let (s, c) = angle(k as f64 + 0.5).sin_cos();
        obj += &format!("v {} {} {}\n", 1.7 * c, 1.7 * s, 0.2 * (0.7 * k as f64).cos());
    }
    for k in 0..4 {
        obj += &format!("f 1 {} {} {}\n", k + 2, k + 7, k + 3);
    }
    obj + "f 1 6 2\n"
}

/// The output depends on the input only: separate runs (each hash map seeded anew) of
/// both polygon schemes write the same bytes, a face order fixed by the input.
#[test]
fn subdivide_surface_writes_the_same_bytes_every_run() {
    let dir = ScratchDir::new("subdiv-same");
    let out = dir.join("out.obj");
    for scheme in ["doo-sabin", "catmull-clark"] {
        let first = subdivided(scheme, &["--steps", "3"], &out, &open_fan());
        for _ in 0..4 {
            let again = subdivided(scheme, &["--steps", "3"], &out, &open_fan());
            assert!(again == first, "{scheme}: the output changed between runs");
        }
    }
}
