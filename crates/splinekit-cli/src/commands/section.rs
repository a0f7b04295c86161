//! `splinekit section`: plane sections (contours) of a surface, as intersection curves
//! with planes.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::json;
use splinekit::Point;
use splinekit::query::intersect_surfaces;
use splinekit::surface::Surface;
use splinekit::surface::model::Plane;

use crate::commands::intersect::{Precision, branches_json};
use crate::input::{parse_numbers, read_shapes};
use crate::output::{check_finite, write_json};
use splinekit_scene::ShapeDocument;

/// Most planes one call may cut with.
pub const MAX_LEVELS: usize = 100;

#[derive(Args, Debug)]
#[command(
    mut_arg("tolerance", |a| a.help("Distance within which points lie on both the surface and the plane (> 0)")),
    mut_arg("chord", |a| a.help("Chord error of the contour polylines (> 0)"))
)]
pub struct SectionArgs {
    /// Surface document (JSON file, or - for standard input); 3-D. A scene of surfaces is
    /// answered object by object (`{"objects": [{"sections": …}, …]}`).
    pub surface: String,
    /// The cutting plane as OX,OY,OZ/NX,NY,NZ (a point on it and its normal).
    #[arg(long, allow_hyphen_values = true)]
    pub plane: String,
    /// Number of parallel planes: 1 cuts at the given plane; N > 1 cuts at the middles of
    /// N equal slabs of the surface's extent along the normal.
    #[arg(long, default_value_t = 1)]
    pub levels: usize,
    #[command(flatten)]
    pub precision: Precision,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

/// The origin and unit normal of `--plane`.
fn parse_plane(text: &str) -> Result<(Point<3>, Point<3>)> {
    let Some((o, n)) = text.split_once('/') else {
        bail!("--plane: expected OX,OY,OZ/NX,NY,NZ, got '{text}'");
    };
    let (o, n) = (parse_numbers("--plane", o)?, parse_numbers("--plane", n)?);
    if o.len() != 3 || n.len() != 3 {
        bail!("--plane: expected 3 coordinates for the point and 3 for the normal, got {} and {}", o.len(), n.len());
    }
    let n = Point::<3>::new(n[0], n[1], n[2]);
    if !(n.norm() > 0.0 && n.norm().is_finite()) {
        bail!("--plane: the normal must be a non-zero finite vector, got {n:?}");
    }
    Ok((Point::<3>::new(o[0], o[1], o[2]), n.normalize()))
}

/// Heights (along n, from o) of the cuts, and the surface's centre and size.
fn levels(s: &dyn Surface<3>, o: &Point<3>, n: &Point<3>, count: usize) -> (Vec<f64>, Point<3>, f64) {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let pts: Vec<Point<3>> =
        (0..33 * 33).map(|k| s.point(du.lerp((k / 33) as f64 / 32.0), dv.lerp((k % 33) as f64 / 32.0))).collect();
    let heights: Vec<f64> = pts.iter().map(|p| (p - o).dot(n)).collect();
    let (lo, hi) = heights.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| (a.min(h), b.max(h)));
    let centre = pts.iter().fold(Point::<3>::zeros(), |c, p| c + p) / pts.len() as f64;
    let size = splinekit::query::Aabb::around(&pts, 0.0).diagonal().max(1.0);
    let cuts = if count == 1 {
        vec![0.0]
    } else {
        (0..count).map(|k| lo + (hi - lo) * (k as f64 + 0.5) / count as f64).collect()
    };
    (cuts, centre, size)
}

/// A square plane at height h, centred on the surface and far larger than it.
fn big_plane(o: &Point<3>, n: &Point<3>, h: f64, centre: &Point<3>, size: f64) -> Result<Plane> {
    let helper = if n.x.abs() < 0.9 { Point::<3>::x() } else { Point::<3>::y() };
    let (a, b) = (n.cross(&helper).normalize(), n.cross(&helper).normalize().cross(n));
    let foot = centre - n * ((centre - o).dot(n) - h);
    let (a, b) = (a * (4.0 * size), b * (4.0 * size));
    Ok(Plane::new(foot - (a + b) * 0.5, a, b)?)
}

pub fn run(args: &SectionArgs) -> Result<()> {
    let (o, n) = parse_plane(&args.plane)?;
    let (tolerance, chord) = args.precision.parse()?;
    if args.levels == 0 || args.levels > MAX_LEVELS {
        bail!("--levels: expected 1 … {MAX_LEVELS}, got {}", args.levels);
    }
    // A scene is answered object by object: `{"objects": [ANSWER, …]}`.
    let value = read_shapes(&args.surface)?.answer_each(|doc| section(doc, &o, &n, args.levels, tolerance, chord))?;
    check_finite(&value, "result")?;
    write_json(&value, args.output.as_deref())
}

/// The sections of one surface document: `{"sections": [{origin, normal, curves}, …]}`.
fn section(
    doc: ShapeDocument,
    o: &Point<3>,
    n: &Point<3>,
    count: usize,
    tolerance: f64,
    chord: f64,
) -> Result<serde_json::Value> {
    let ShapeDocument::Surface(doc) = doc else {
        bail!("SURFACE: section cuts surfaces, this document is a curve");
    };
    let dim = doc.dimension()?;
    if dim != 3 {
        bail!("SURFACE: sections are of 3-D surfaces, this one is {dim}-D");
    }
    let surface = doc.build_in::<3>().map_err(|e| anyhow!("SURFACE: {e}"))?;
    let (cuts, centre, size) = levels(surface.as_ref(), o, n, count);
    let mut sections = Vec::with_capacity(cuts.len());
    for h in cuts {
        let plane = big_plane(o, n, h, &centre, size)?;
        let branches = intersect_surfaces(surface.as_ref(), &plane, tolerance, chord)?;
        let curves: Vec<serde_json::Value> = branches_json(&branches, chord)?
            .into_iter()
            .map(|mut c| {
                if let Some(m) = c.as_object_mut() {
                    m.remove("params_b");
                    if let Some(p) = m.remove("params_a") {
                        m.insert("params".into(), p);
                    }
                }
                c
            })
            .collect();
        let origin = o + n * h;
        sections.push(json!({"origin": [origin.x, origin.y, origin.z], "normal": [n.x, n.y, n.z], "curves": curves}));
    }
    Ok(json!({ "sections": sections }))
}
