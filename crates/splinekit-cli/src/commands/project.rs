//! `splinekit project`: the nearest point of a curve or surface to given points (point
//! inversion), or every local minimum of the distance.

use anyhow::{Result, bail};
use clap::Args;
use serde_json::{Value, json};
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::query::{CurveProjector, Nearest, NearestOnSurface, SurfaceProjector};
use splinekit::surface::Surface;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument, Surfaces};

use crate::input::{parse_numbers, read_points, read_shapes};
use crate::output::{check_finite, write_json};

/// Most points one call may project.
pub const MAX_POINTS: usize = 1_000_000;

#[derive(Args, Debug)]
#[command(group(clap::ArgGroup::new("query").required(true).args(["point", "points"])))]
pub struct ProjectArgs {
    /// Shape document (JSON file, or - for standard input); a scene is answered object by
    /// object (`{"objects": [ANSWER, …]}`).
    pub shape: String,
    /// The point to project, X,Y or X,Y,Z (as many coordinates as the shape has).
    #[arg(long, allow_hyphen_values = true)]
    pub point: Option<String>,
    /// Many points to project (JSON array or CSV, as `fit` reads them); the shape's
    /// bounding hierarchy is built once for all of them.
    #[arg(long)]
    pub points: Option<String>,
    /// Report every local minimum of the distance instead of the nearest point only.
    #[arg(long)]
    pub all: bool,
    /// Absolute accuracy of the nearest distance (≥ 0); 0 asks for the exact minimum to
    /// rounding.
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    pub accuracy: String,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

struct Query {
    points: Vec<Vec<f64>>,
    all: bool,
    accuracy: f64,
}

impl Query {
    fn point<const D: usize>(&self, i: usize) -> Result<Point<D>> {
        let p = &self.points[i];
        if p.len() != D {
            bail!("--point: the shape is {D}-D, the point has {} coordinates", p.len());
        }
        Ok(Point::<D>::from_fn(|k, _| p[k]))
    }

    /// The answer for every query point: with --all the list of its local minima of the
    /// distance (`minima`), else its nearest point (`nearest`), each written as its
    /// [`Entry`]; wrapped as [`Query::wrap`] says.
    fn answer<const D: usize, N: Entry>(
        &self,
        single: bool,
        nearest: impl Fn(&Point<D>, f64) -> Result<N>,
        minima: impl Fn(&Point<D>, f64) -> Result<Vec<N>>,
    ) -> Result<Value> {
        let mut entries = Vec::with_capacity(self.points.len());
        for i in 0..self.points.len() {
            let q = self.point::<D>(i)?;
            entries.push(if self.all {
                Value::Array(minima(&q, self.accuracy)?.iter().map(Entry::entry).collect())
            } else {
                nearest(&q, self.accuracy)?.entry()
            });
        }
        Ok(self.wrap(entries, single))
    }

    /// One entry per point (an object, or a list of objects with --all), or the single
    /// entry for --point.
    fn wrap(&self, entries: Vec<Value>, single: bool) -> Value {
        let key = if self.all { "minima" } else { "nearest" };
        if single {
            json!({ key: entries.into_iter().next().unwrap_or(Value::Null) })
        } else {
            json!({ "projections": entries.into_iter().map(|e| json!({ key: e })).collect::<Vec<_>>() })
        }
    }
}

fn coords<const D: usize>(p: &Point<D>) -> Vec<f64> {
    p.iter().copied().collect()
}

/// A nearest point or local minimum as the answer writes it: its parameters, the point
/// and the distance.
trait Entry {
    fn entry(&self) -> Value;
}

impl<const D: usize> Entry for Nearest<D> {
    fn entry(&self) -> Value {
        json!({"t": self.t, "point": coords(&self.point), "distance": self.distance})
    }
}

impl<const D: usize> Entry for NearestOnSurface<D> {
    fn entry(&self) -> Value {
        json!({"u": self.u, "v": self.v, "point": coords(&self.point), "distance": self.distance})
    }
}

/// Answers the query (the flag: a single `--point`) on a curve or on a surface, through
/// the shape's projector.
struct Project<'a>(&'a Query, bool);

impl DimensionVisitor<Curves> for Project<'_> {
    type Output = Result<Value>;
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Result<Value> {
        let projector = CurveProjector::new(curve);
        self.0.answer(self.1, |q, a| Ok(projector.nearest(q, a)?), |q, a| Ok(projector.local_minima(q, a)?))
    }
}

impl DimensionVisitor<Surfaces> for Project<'_> {
    type Output = Result<Value>;
    fn visit<const D: usize>(self, surface: &dyn Surface<D>) -> Result<Value> {
        let projector = SurfaceProjector::new(surface);
        self.0.answer(self.1, |q, a| Ok(projector.nearest(q, a)?), |q, a| Ok(projector.local_minima(q, a)?))
    }
}

pub fn run(args: &ProjectArgs) -> Result<()> {
    let accuracy = parse_numbers("--accuracy", &args.accuracy)?;
    let accuracy = match accuracy[..] {
        [a] if a >= 0.0 => a,
        _ => bail!("--accuracy: expected one number ≥ 0, got '{}'", args.accuracy),
    };
    let (points, single) = match (&args.point, &args.points) {
        (Some(p), _) => (vec![parse_numbers("--point", p)?], true),
        (None, Some(path)) => (read_points(path)?, false),
        (None, None) => bail!("--point: give --point X,Y[,Z] or --points FILE"),
    };
    if points.len() > MAX_POINTS {
        bail!("--points: {} points is more than the limit of {MAX_POINTS}", points.len());
    }
    let query = Query { points, all: args.all, accuracy };
    // A scene is answered object by object: `{"objects": [ANSWER, …]}`.
    let value = read_shapes(&args.shape)?.answer_each(|doc| match doc {
        ShapeDocument::Curve(c) => c.build()?.visit(Project(&query, single)),
        ShapeDocument::Surface(s) => s.build()?.visit(Project(&query, single)),
    })?;
    check_finite(&value, "result")?;
    write_json(&value, args.output.as_deref())
}
