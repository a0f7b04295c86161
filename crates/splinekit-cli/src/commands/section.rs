//! `splinekit section`: plane sections (contours) of a surface, as intersection curves
//! with planes.

use anyhow::{Result, bail};
use clap::Args;
use splinekit::Point;
use splinekit_scene::answers::{MAX_SECTION_LEVELS, sections};

use crate::commands::intersect::Precision;
use crate::input::{parse_numbers, read_shapes};
use crate::output::{check_finite, write_json};

/// Most planes one call may cut with.
pub const MAX_LEVELS: usize = MAX_SECTION_LEVELS;

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

pub fn run(args: &SectionArgs) -> Result<()> {
    let (o, n) = parse_plane(&args.plane)?;
    let (tolerance, chord) = args.precision.parse()?;
    if args.levels == 0 || args.levels > MAX_LEVELS {
        bail!("--levels: expected 1 … {MAX_LEVELS}, got {}", args.levels);
    }
    // A scene is answered object by object: `{"objects": [ANSWER, …]}`.
    let value = read_shapes(&args.surface)?
        .answer_each(|doc| Ok(sections(doc, "SURFACE", (&o, &n), args.levels, tolerance, chord)?))?;
    check_finite(&value, "result")?;
    write_json(&value, args.output.as_deref())
}
