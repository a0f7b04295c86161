//! STEP entities → geometry items: the curves and surfaces of geometric sets and
//! representations, and faces with their bounds (as parameter-space loops from the
//! pcurves of their edges). Every instance that is neither converted nor part of the
//! file's product, unit and representation structure is counted by type, so callers can
//! say what was left out.

use std::collections::{BTreeMap, HashMap, HashSet};

use splinekit::Point;
use splinekit::axes::{OrthonormalAxes, unit_vector};

use crate::error::{Result, StepError};
use crate::geometry::{Axes, Curve, SplineCurve, SplineSurface, Surface, expand_knots};
use crate::part21::{Instance, Param, StepFile};
use crate::units::{Units, context_units};

/// A face: a surface and its bounds as closed loops of curves in the surface's (u, v)
/// parameters (each loop a list of 2-D curves end to end).
#[derive(Debug, Clone, PartialEq)]
pub struct Face {
    /// The face's name.
    pub name: String,
    /// The underlying surface.
    pub surface: Surface,
    /// Parameter-space loops; `outer` first when known.
    pub loops: Vec<Vec<Curve>>,
    /// For each piece of each loop, the edge's `#id` and the other pcurve of a seam edge (a
    /// closed surface's seam carries one pcurve per side; a loop that uses the seam twice
    /// runs once along each, and which is which is told by continuity, see
    /// `documents::import`).
    pub seam_twins: Vec<Vec<Option<(u64, Curve)>>>,
    /// Which loop is the outer bound (`FACE_OUTER_BOUND`), if one is marked.
    pub outer: Option<usize>,
    /// What each piece of each loop is (parallel to `loops`).
    pub roles: Vec<Vec<Role>>,
    /// The face's `#id`.
    pub id: u64,
    /// Whether the face's normal is the surface's (`same_sense`).
    pub same_sense: bool,
}

/// What a piece of a face's loop is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Role {
    /// A use of the edge `#id`, from its start vertex to its end (`forward`) or back.
    Edge {
        /// The `EDGE_CURVE`'s `#id`.
        id: u64,
        /// Whether the loop runs from the edge's start vertex to its end.
        forward: bool,
    },
    /// One side of a cut across a periodic surface; `twin` is the other side's index in
    /// the loop.
    Cut {
        /// The other side.
        twin: usize,
    },
    /// The line of a pole or apex (one point in space).
    Pole,
}

/// An edge read from a face: its 3-D curve and the parameters of its ends.
#[derive(Debug, Clone, PartialEq)]
pub struct EdgeRead {
    /// The 3-D curve.
    pub curve: Curve,
    /// The parameters of the start and end vertex on the curve, (lo, hi) increasing (the
    /// curve runs from start to end when `same_sense`).
    pub range: (f64, f64),
    /// Whether the curve's direction is from the start vertex to the end.
    pub same_sense: bool,
    /// The start and end `VERTEX_POINT`s.
    pub vertices: [u64; 2],
}

/// A shell as read: its faces' indices in [`Imported::geometry`].
#[derive(Debug, Clone, PartialEq)]
pub struct ShellRead {
    /// The shell's `#id`.
    pub id: u64,
    /// `CLOSED_SHELL` (else `OPEN_SHELL`).
    pub closed: bool,
    /// The faces converted.
    pub faces: Vec<usize>,
    /// Faces of the shell that were not converted.
    pub missing: usize,
}

/// A solid as read.
#[derive(Debug, Clone, PartialEq)]
pub struct SolidRead {
    /// The solid's `#id`.
    pub id: u64,
    /// Its name.
    pub name: String,
    /// Its shells' indices in [`Imported::shells`], the outer one first.
    pub shells: Vec<usize>,
    /// Per shell, whether the solid uses it reversed (an `ORIENTED_CLOSED_SHELL` with
    /// orientation `.F.`, as voids are written): its faces turn the other way.
    pub reversed: Vec<bool>,
}

/// What an import found.
#[derive(Debug, Clone, Default)]
pub struct Imported {
    /// Named curves and surfaces of geometric sets and representations.
    pub geometry: Vec<(String, GeometryOrFace)>,
    /// Entity types read but not converted, with counts.
    pub not_understood: BTreeMap<String, usize>,
    /// The shells whose faces were read.
    pub shells: Vec<ShellRead>,
    /// The solids of those shells.
    pub solids: Vec<SolidRead>,
    /// The edges the faces use, by `#id`.
    pub edges: BTreeMap<u64, EdgeRead>,
    /// The vertices of those edges, by `#id`, in millimetres.
    pub vertices: BTreeMap<u64, Point<3>>,
    /// The length unit of the geometry read (the first context's).
    pub source_unit: Option<String>,
}

/// A free curve or surface, or a bounded face.
#[derive(Debug, Clone, PartialEq)]
pub enum GeometryOrFace {
    /// A curve.
    Curve(Curve),
    /// A surface.
    Surface(Surface),
    /// A face.
    Face(Face),
}

/// Types that carry structure (product, context, units, representations, topology that
/// faces consume) rather than geometry; they are never reported as not understood.
const STRUCTURE: &[&str] = &[
    "APPLICATION_CONTEXT",
    "APPLICATION_PROTOCOL_DEFINITION",
    "PRODUCT",
    "PRODUCT_CONTEXT",
    "PRODUCT_DEFINITION",
    "PRODUCT_DEFINITION_CONTEXT",
    "PRODUCT_DEFINITION_FORMATION",
    "PRODUCT_DEFINITION_FORMATION_WITH_SPECIFIED_SOURCE",
    "PRODUCT_DEFINITION_SHAPE",
    "PRODUCT_RELATED_PRODUCT_CATEGORY",
    "PRODUCT_CATEGORY",
    "SHAPE_DEFINITION_REPRESENTATION",
    "SHAPE_REPRESENTATION",
    "ADVANCED_BREP_SHAPE_REPRESENTATION",
    "MANIFOLD_SURFACE_SHAPE_REPRESENTATION",
    "GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION",
    "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION",
    "SHAPE_REPRESENTATION_RELATIONSHIP",
    "UNCERTAINTY_MEASURE_WITH_UNIT",
    "GEOMETRIC_SET",
    "GEOMETRIC_CURVE_SET",
    "SHELL_BASED_SURFACE_MODEL",
    "OPEN_SHELL",
    "CLOSED_SHELL",
    "MANIFOLD_SOLID_BREP",
    "AXIS2_PLACEMENT_3D",
    "DEFINITIONAL_REPRESENTATION",
    "APPLICATION_PROTOCOL",
];

fn structural(type_name: &str) -> bool {
    STRUCTURE.contains(&type_name)
        || type_name.starts_with('(') && (type_name.contains("UNIT") || type_name.contains("REPRESENTATION_CONTEXT"))
}

/// Reads every curve, surface and face the file's geometric sets, shape representations
/// and shells hold.
pub fn import(file: &StepFile) -> Result<Imported> {
    let mut r = Reader {
        file,
        visited: HashSet::new(),
        scale: None,
        units: Units::default(),
        contexts: crate::units::item_contexts(file),
        context_units: HashMap::new(),
        edges: BTreeMap::new(),
        vertices: BTreeMap::new(),
    };
    let mut out = Imported::default();
    // Each root with the set or shell that holds it, whose context gives its units.
    let mut roots: Vec<(u64, u64)> = Vec::new();
    for container in ["GEOMETRIC_SET", "GEOMETRIC_CURVE_SET", "OPEN_SHELL", "CLOSED_SHELL"] {
        for id in file.ids_of_type(container) {
            r.visited.insert(id);
            let inst = file.get(id)?;
            roots.extend(refs(param(&inst, 1)?).map_err(|e| e.within(inst.line, id))?.into_iter().map(|e| (id, e)));
        }
    }
    let mut shell_index: HashMap<u64, usize> = HashMap::new();
    for (container, id) in roots {
        r.units = r.units_of(container)?;
        if out.source_unit.is_none() && r.contexts.contains_key(&container) {
            out.source_unit = Some(r.units.length_name.clone());
        }
        r.visited.insert(id);
        let inst = file.get(id)?;
        let name = inst_name(&inst);
        let geometry = match inst.records[0].name.as_str() {
            "ADVANCED_FACE" | "FACE_SURFACE" => r.face(&inst).map(GeometryOrFace::Face),
            _ if r.is_surface(&inst) => r.surface(id).map(GeometryOrFace::Surface),
            _ => r.curve(id).map(GeometryOrFace::Curve),
        };
        let shell = match file.type_of(container) {
            Some(t @ ("OPEN_SHELL" | "CLOSED_SHELL")) => {
                let closed = t == "CLOSED_SHELL";
                let k = *shell_index.entry(container).or_insert_with(|| {
                    out.shells.push(ShellRead { id: container, closed, faces: Vec::new(), missing: 0 });
                    out.shells.len() - 1
                });
                Some(k)
            }
            _ => None,
        };
        match geometry {
            Ok(g) => {
                if let Some(k) = shell {
                    out.shells[k].faces.push(out.geometry.len());
                }
                out.geometry.push((name, g));
            }
            Err(Unsupported::Type(t)) => {
                if let Some(k) = shell {
                    out.shells[k].missing += 1;
                }
                *out.not_understood.entry(t).or_default() += 1
            }
            Err(Unsupported::Bad(e)) => return Err(e),
        }
    }
    // Solids: an outer shell, and the shells of its voids.
    for (kind, voids) in [("MANIFOLD_SOLID_BREP", false), ("BREP_WITH_VOIDS", true)] {
        for id in file.ids_of_type(kind) {
            r.visited.insert(id);
            let inst = file.get(id)?;
            let mut shells = vec![reference(param(&inst, 1)?).map_err(|e| e.within(inst.line, id))?];
            if voids {
                shells.extend(refs(param(&inst, 2)?).map_err(|e| e.within(inst.line, id))?);
            }
            // A void is usually an ORIENTED_CLOSED_SHELL(name, *, shell, orientation): the
            // shell used reversed (.F.), its faces' normals into the void.
            let mut read = Vec::with_capacity(shells.len());
            for s in shells {
                let (s, reversed) = match file.type_of(s) {
                    Some("ORIENTED_CLOSED_SHELL") => {
                        r.visited.insert(s);
                        let oriented = file.get(s)?;
                        let element = reference(param(&oriented, 2)?).map_err(|e| e.within(oriented.line, s))?;
                        (element, matches!(param(&oriented, 3)?, Param::Enumeration(e) if e == "F"))
                    }
                    _ => (s, false),
                };
                if let Some(&k) = shell_index.get(&s) {
                    read.push((k, reversed));
                }
            }
            if !read.is_empty() {
                let (shells, reversed) = read.into_iter().unzip();
                out.solids.push(SolidRead { id, name: inst_name(&inst), shells, reversed });
            }
        }
    }
    out.edges = std::mem::take(&mut r.edges);
    out.vertices = std::mem::take(&mut r.vertices);
    // A placement passed over as structure (a representation's own frame, which places
    // nothing) takes its point and directions with it.
    for id in file.ids_of_type("AXIS2_PLACEMENT_3D") {
        if !r.visited.contains(&id) {
            let inst = file.get(id)?;
            r.visited.extend(inst.records[0].params.iter().filter_map(|p| match p {
                Param::Reference(part) => Some(*part),
                _ => None,
            }));
        }
    }
    for id in file.ids() {
        let t = file.type_of(id).unwrap_or("");
        if !r.visited.contains(&id) && !structural(t) {
            *out.not_understood.entry(t.to_string()).or_default() += 1;
        }
    }
    Ok(out)
}

/// Why an entity was not converted: a type without a mapping, or a malformed file.
enum Unsupported {
    Type(String),
    Bad(StepError),
}

impl From<StepError> for Unsupported {
    fn from(e: StepError) -> Self {
        Unsupported::Bad(e)
    }
}

type Conv<T> = std::result::Result<T, Unsupported>;

fn inst_name(inst: &Instance) -> String {
    let r = inst.record("REPRESENTATION_ITEM").unwrap_or(&inst.records[0]);
    match r.params.first() {
        Some(Param::String(s)) => s.clone(),
        _ => String::new(),
    }
}

fn param(inst: &Instance, i: usize) -> Result<&Param> {
    inst.records[0].params.get(i).ok_or_else(|| {
        StepError::at(
            inst.line,
            Some(inst.id),
            format!("{}: expected at least {} parameters", inst.records[0].name, i + 1),
        )
    })
}

fn bad(what: &str, got: &Param) -> StepError {
    StepError::plain(format!("expected {what}, got {got:?}"))
}

fn real(p: &Param) -> Result<f64> {
    match p {
        Param::Real(x) => Ok(*x),
        Param::Integer(i) => Ok(*i as f64),
        Param::Typed(_, inner) => real(inner),
        other => Err(bad("a number", other)),
    }
}

/// The items of a list, each read by `item`; anything but a list is refused as not `what`.
fn list<T>(p: &Param, what: &str, item: fn(&Param) -> Result<T>) -> Result<Vec<T>> {
    match p {
        Param::List(items) => items.iter().map(item).collect(),
        other => Err(bad(what, other)),
    }
}

fn reals(p: &Param) -> Result<Vec<f64>> {
    list(p, "a list of numbers", real)
}

fn integer(p: &Param) -> Result<usize> {
    match p {
        Param::Integer(i) if *i >= 0 => Ok(*i as usize),
        other => Err(bad("a non-negative integer", other)),
    }
}

fn reference(p: &Param) -> Result<u64> {
    match p {
        Param::Reference(id) => Ok(*id),
        other => Err(bad("a reference #id", other)),
    }
}

/// The parameters of an instance's first record from index `from` on (none when it has
/// fewer).
fn tail(inst: &Instance, from: usize) -> Vec<Param> {
    inst.records[0].params.get(from..).map_or_else(Vec::new, <[Param]>::to_vec)
}

/// The `B_SPLINE_{kind}` and `B_SPLINE_{kind}_WITH_KNOTS` parameters of a B-spline
/// (`kind` `CURVE` or `SURFACE`): the records of the complex (rational) entity, or the
/// simple entity's parameters after its name split where the knot lists start
/// (`knots_from`); refused when they are fewer than `least`.
fn spline_params(
    inst: &Instance,
    kind: &str,
    knots_from: usize,
    least: (usize, usize),
) -> Conv<(Vec<Param>, Vec<Param>)> {
    let (spline, knots) = match inst.record(&format!("B_SPLINE_{kind}")) {
        Some(s) => (s.params.clone(), inst.record(&format!("B_SPLINE_{kind}_WITH_KNOTS")).map(|k| k.params.clone())),
        None => (tail(inst, 1), Some(tail(inst, knots_from))),
    };
    let knots = knots.ok_or_else(|| Unsupported::Type(inst.type_name()))?;
    if spline.len() < least.0 || knots.len() < least.1 {
        let what = kind.to_lowercase();
        return Err(StepError::plain(format!("B-spline {what}: missing parameters")).into());
    }
    Ok((spline, knots))
}

fn refs(p: &Param) -> Result<Vec<u64>> {
    list(p, "a list of references", reference)
}

/// The multiplicities of a B-spline's distinct knots.
fn multiplicities(p: &Param) -> Result<Vec<usize>> {
    list(p, "knot multiplicities", integer)
}

fn boolean(p: &Param) -> Result<bool> {
    match p {
        Param::Enumeration(e) if e == "T" => Ok(true),
        Param::Enumeration(e) if e == "F" || e == "U" => Ok(false),
        other => Err(bad(".T. or .F.", other)),
    }
}

/// A point or direction of 1 to 3 coordinates as three (missing ones are 0).
fn to3(v: &[f64]) -> Point<3> {
    Point::<3>::from_fn(|k, _| v.get(k).copied().unwrap_or(0.0))
}

/// Highest degree of a B-spline read from a file (as `splinekit_scene::budget::MAX_DEGREE`).
const MAX_SPLINE_DEGREE: usize = 1024;

/// The full knot vector of a B-spline of `degree` with `points` control points in one
/// direction (`what`), from its distinct values and multiplicities, checked before it is
/// expanded: 1 ≤ degree ≤ [`MAX_SPLINE_DEGREE`], as many multiplicities as values, and
/// multiplicities summing to points + degree + 1 (so a file cannot ask for more knots
/// than it has control points for).
fn checked_knots(what: &str, degree: usize, points: usize, values: &[f64], mults: &[usize]) -> Result<Vec<f64>> {
    if !(1..=MAX_SPLINE_DEGREE).contains(&degree) {
        return Err(StepError::plain(format!("{what}: degree must be 1 to {MAX_SPLINE_DEGREE}, got {degree}")));
    }
    if values.len() != mults.len() {
        return Err(StepError::plain(format!(
            "{what}: {} knot values but {} multiplicities",
            values.len(),
            mults.len()
        )));
    }
    let total = mults.iter().try_fold(0usize, |sum, &m| sum.checked_add(m));
    let needed = points + degree + 1;
    if points <= degree || total != Some(needed) {
        let total = total.map_or("more than any machine holds".to_string(), |t| t.to_string());
        return Err(StepError::plain(format!(
            "{what}: {points} control points of degree {degree} need {needed} knots (and more than {degree} points), the multiplicities give {total}"
        )));
    }
    Ok(expand_knots(values, mults))
}

/// v/|v| (an error naming the direction when it is zero).
fn unit(v: Point<3>) -> Result<Point<3>> {
    unit_vector(v.into(), "direction").map(Point::<3>::from).map_err(|e| StepError::plain(e.to_string()))
}

/// The curve entities that carry a 3-D curve and the pcurves or surfaces it lies on
/// (`SURFACE_CURVE` and its subtypes).
const SURFACE_CURVES: &[&str] = &["SURFACE_CURVE", "SEAM_CURVE", "INTERSECTION_CURVE", "BOUNDED_SURFACE_CURVE"];

/// Follows references, marking what it reads.
struct Reader<'a> {
    file: &'a StepFile,
    visited: HashSet<u64>,
    /// The size of the model, for tolerances (made on first use).
    scale: Option<f64>,
    /// The units of what is being read (its representation's context); lengths are
    /// multiplied by `units.length` into millimetres, angles by `units.angle` into radians.
    units: Units,
    /// The context of every representation item, shell and set (`units::item_contexts`).
    contexts: HashMap<u64, u64>,
    /// The units of each context read so far.
    context_units: HashMap<u64, Units>,
    /// The edges read so far, by `#id`.
    edges: BTreeMap<u64, EdgeRead>,
    /// Their vertices, by `#id`.
    vertices: BTreeMap<u64, Point<3>>,
}

/// Computed pcurves follow their edges within this fraction of the model's size (the
/// largest vertex coordinate).
const PCURVE_TOLERANCE: f64 = 1e-7;

impl Reader<'_> {
    /// The largest coordinate of the file's vertices (at least 1): the model's size.
    fn scale(&mut self) -> f64 {
        if let Some(s) = self.scale {
            return s;
        }
        let mut size = 1.0_f64;
        for id in self.file.ids_of_type("VERTEX_POINT") {
            let Ok(v) = self.file.get(id) else { continue };
            let Some(Param::Reference(p)) = v.records[0].params.get(1) else { continue };
            let Ok(p) = self.file.get(*p) else { continue };
            if let Some(Ok(c)) = p.records[0].params.get(1).map(reals) {
                size = c.iter().fold(size, |m, x| m.max(x.abs()));
            }
        }
        self.scale = Some(size);
        size
    }

    /// The 3-D tolerance of computed pcurves (in millimetres, as the geometry read).
    fn tolerance(&mut self) -> f64 {
        PCURVE_TOLERANCE * self.scale() * self.units.length
    }

    /// The units of the set or shell `container`: those of its representation's context,
    /// millimetres and radians where it has none.
    fn units_of(&mut self, container: u64) -> Result<Units> {
        let Some(&context) = self.contexts.get(&container) else { return Ok(Units::default()) };
        if let Some(u) = self.context_units.get(&context) {
            return Ok(u.clone());
        }
        let u = context_units(self.file, context)?;
        self.context_units.insert(context, u.clone());
        Ok(u)
    }

    /// A length read from the file, in millimetres.
    fn length(&self, p: &Param) -> Result<f64> {
        Ok(real(p)? * self.units.length)
    }

    /// A plane angle read from the file, in radians.
    fn angle(&self, p: &Param) -> Result<f64> {
        Ok(real(p)? * self.units.angle)
    }
}

impl Reader<'_> {
    fn get(&mut self, id: u64) -> Result<Instance> {
        self.visited.insert(id);
        self.file.get(id)
    }

    /// Runs `f` on the instance, placing its errors at the instance.
    fn with<T>(&mut self, id: u64, f: impl FnOnce(&mut Self, &Instance) -> Conv<T>) -> Conv<T> {
        let inst = self.get(id)?;
        f(self, &inst).map_err(|e| match e {
            Unsupported::Bad(err) => Unsupported::Bad(err.within(inst.line, inst.id)),
            other => other,
        })
    }

    fn is_surface(&self, inst: &Instance) -> bool {
        inst.records.iter().any(|r| r.name.contains("SURFACE") && !r.name.contains("CURVE"))
            || inst.records[0].name == "PLANE"
    }

    fn point(&mut self, id: u64) -> Conv<Vec<f64>> {
        let length = self.units.length;
        self.with(id, |_, inst| match inst.records[0].name.as_str() {
            "CARTESIAN_POINT" => {
                let c = reals(param(inst, 1)?)?;
                if !(1..=3).contains(&c.len()) {
                    return Err(StepError::plain(format!("a point has 1 to 3 coordinates, got {}", c.len())).into());
                }
                Ok(c.into_iter().map(|x| x * length).collect())
            }
            other => Err(Unsupported::Type(other.to_string())),
        })
    }

    fn direction(&mut self, id: u64) -> Conv<Point<3>> {
        self.with(id, |_, inst| Ok(unit(to3(&reals(param(inst, 1)?)?))?))
    }

    fn vector(&mut self, id: u64) -> Conv<Vec<f64>> {
        self.with(id, |r, inst| {
            let d = r.with(reference(param(inst, 1)?)?, |_, i| Ok(reals(param(i, 1)?)?))?;
            let len = to3(&d).norm();
            let m = r.length(param(inst, 2)?)?;
            Ok(d.iter().map(|c| c / len * m).collect())
        })
    }

    fn axes(&mut self, id: u64) -> Conv<Axes> {
        self.with(id, |r, inst| {
            let origin = to3(&r.point(reference(param(inst, 1)?)?)?);
            if inst.records[0].name == "AXIS2_PLACEMENT_2D" {
                // (name, location, ref_direction): the plane's own z, x from ref_direction.
                let x = match param(inst, 2)? {
                    Param::Unset => Point::<3>::new(1.0, 0.0, 0.0),
                    p => r.direction(reference(p)?)?,
                };
                return Ok(Axes {
                    origin,
                    z: Point::<3>::new(0.0, 0.0, 1.0),
                    x: unit(Point::<3>::new(x[0], x[1], 0.0))?,
                });
            }
            let z = match param(inst, 2)? {
                Param::Unset => Point::<3>::new(0.0, 0.0, 1.0),
                p => r.direction(reference(p)?)?,
            };
            let x0 = match inst.records[0].params.get(3) {
                Some(Param::Reference(d)) => r.direction(*d)?,
                _ => {
                    if z[0].abs() < 0.9 {
                        Point::<3>::new(1.0, 0.0, 0.0)
                    } else {
                        Point::<3>::new(0.0, 1.0, 0.0)
                    }
                }
            };
            // Reference direction made orthogonal to the axis (ISO 10303-42 build_axes).
            let OrthonormalAxes { x, z, .. } =
                OrthonormalAxes::build(z.into(), x0.into()).map_err(|e| StepError::plain(e.to_string()))?;
            Ok(Axes { origin, z: z.into(), x: x.into() })
        })
    }

    fn spline_curve(&mut self, inst: &Instance) -> Conv<SplineCurve> {
        let (curve, knots) = spline_params(inst, "CURVE", 6, (5, 2))?;
        let degree = integer(&curve[0])?;
        let points = refs(&curve[1])?.into_iter().map(|id| self.point(id)).collect::<Conv<Vec<_>>>()?;
        let mults = multiplicities(&knots[0])?;
        let values = reals(&knots[1])?;
        let knots = checked_knots("B-spline curve", degree, points.len(), &values, &mults)?;
        let weights = match inst.record("RATIONAL_B_SPLINE_CURVE") {
            Some(r) => {
                Some(reals(r.params.first().ok_or_else(|| StepError::plain("rational curve: missing weights"))?)?)
            }
            None => None,
        };
        if let Some(w) = &weights
            && w.len() != points.len()
        {
            return Err(StepError::plain(format!(
                "rational curve: {} weights for {} control points",
                w.len(),
                points.len()
            ))
            .into());
        }
        Ok(SplineCurve { degree, knots, points, weights, closed: boolean(&curve[3])? })
    }

    fn curve(&mut self, id: u64) -> Conv<Curve> {
        self.with(id, |r, inst| {
            if inst.record("B_SPLINE_CURVE_WITH_KNOTS").is_some() {
                return Ok(Curve::Spline(r.spline_curve(inst)?));
            }
            Ok(match inst.records[0].name.as_str() {
                "LINE" => Curve::Line {
                    origin: r.point(reference(param(inst, 1)?)?)?,
                    direction: r.vector(reference(param(inst, 2)?)?)?,
                },
                "CIRCLE" => {
                    Curve::Circle { axes: r.axes(reference(param(inst, 1)?)?)?, radius: r.length(param(inst, 2)?)? }
                }
                "ELLIPSE" => Curve::Ellipse {
                    axes: r.axes(reference(param(inst, 1)?)?)?,
                    a: r.length(param(inst, 2)?)?,
                    b: r.length(param(inst, 3)?)?,
                },
                "TRIMMED_CURVE" => {
                    let basis = r.curve(reference(param(inst, 1)?)?)?;
                    // A conic's parameter is a plane angle; a line's and a spline's are
                    // numbers (a line's vector carries the length).
                    let unit = match basis {
                        Curve::Circle { .. } | Curve::Ellipse { .. } => r.units.angle,
                        _ => 1.0,
                    };
                    let trim = |p: &Param| -> Option<f64> {
                        match p {
                            Param::List(items) => items.iter().find_map(|i| match i {
                                Param::Typed(n, v) if n == "PARAMETER_VALUE" => real(v).ok().map(|t| t * unit),
                                _ => None,
                            }),
                            _ => None,
                        }
                    };
                    // Trimmed by a point where no parameter is given: the point's parameter
                    // on the basis.
                    let mut by_point = |p: &Param| -> Conv<Option<f64>> {
                        let Param::List(items) = p else { return Ok(None) };
                        for i in items {
                            if let Param::Reference(id) = i {
                                let q = to3(&r.point(*id)?);
                                return Ok(Some(parameter_on(&basis, q)?));
                            }
                        }
                        Ok(None)
                    };
                    let (p1, p2) = (param(inst, 2)?, param(inst, 3)?);
                    let start = match trim(p1) {
                        Some(t) => Some(t),
                        None => by_point(p1)?,
                    };
                    let end = match trim(p2) {
                        Some(t) => Some(t),
                        None => by_point(p2)?,
                    };
                    let (Some(start), Some(end)) = (start, end) else {
                        return Err(Unsupported::Type("TRIMMED_CURVE (trimmed by neither parameter nor point)".into()));
                    };
                    // Against the basis' sense the piece runs from the second trim back to
                    // the first: the same points (an edge's curve is bounded by its vertices
                    // anyway; a free curve is read with the basis' direction).
                    let (start, end) = if boolean(param(inst, 4)?)? { (start, end) } else { (end, start) };
                    let (start, end) = match basis {
                        Curve::Circle { .. } | Curve::Ellipse { .. } if end < start => {
                            (start, end + std::f64::consts::TAU)
                        }
                        _ => (start, end),
                    };
                    // Trimming points given beside the parameters say the same (the
                    // parameters are read; the points are not left behind as unread).
                    for select in [param(inst, 2)?, param(inst, 3)?] {
                        if let Param::List(items) = select {
                            r.visited.extend(items.iter().filter_map(|i| match i {
                                Param::Reference(point) => Some(*point),
                                _ => None,
                            }));
                        }
                    }
                    Curve::Trimmed { basis: Box::new(basis), start, end }
                }
                name if SURFACE_CURVES.contains(&name) => r.curve(reference(param(inst, 1)?)?)?,
                "POLYLINE" => {
                    // Segment i runs over parameters [i − 1, i] (ISO 10303-42): the degree-1
                    // B-spline through the points with knots 0, 0, 1, …, n − 1, n − 1.
                    let points = refs(param(inst, 1)?)?.into_iter().map(|id| r.point(id)).collect::<Conv<Vec<_>>>()?;
                    if points.len() < 2 {
                        return Err(StepError::plain(format!("a polyline of {} points", points.len())).into());
                    }
                    let n = points.len();
                    let knots =
                        std::iter::once(0.0).chain((0..n).map(|i| i as f64)).chain(std::iter::once((n - 1) as f64));
                    Curve::Spline(SplineCurve {
                        degree: 1,
                        knots: knots.collect(),
                        points,
                        weights: None,
                        closed: false,
                    })
                }
                other => return Err(Unsupported::Type(other.to_string())),
            })
        })
    }

    fn spline_surface(&mut self, inst: &Instance) -> Conv<SplineSurface> {
        let (surf, knots) = spline_params(inst, "SURFACE", 8, (7, 4))?;
        let degrees = (integer(&surf[0])?, integer(&surf[1])?);
        let rows = match &surf[2] {
            Param::List(rows) => rows.clone(),
            other => return Err(bad("a net of point references", other).into()),
        };
        let mut points = Vec::with_capacity(rows.len());
        for row in &rows {
            points.push(refs(row)?.into_iter().map(|id| self.point(id)).collect::<Conv<Vec<_>>>()?);
        }
        let (mu, mv) = (multiplicities(&knots[0])?, multiplicities(&knots[1])?);
        let (ku, kv) = (reals(&knots[2])?, reals(&knots[3])?);
        let weights = match inst.record("RATIONAL_B_SPLINE_SURFACE").map(|r| r.params.first()) {
            Some(Some(Param::List(rows))) => Some(rows.iter().map(reals).collect::<Result<Vec<_>>>()?),
            Some(Some(other)) => return Err(bad("rows of weights", other).into()),
            Some(None) => return Err(StepError::plain("rational surface: missing weights").into()),
            None => None,
        };
        let columns = points.first().map_or(0, Vec::len);
        if let Some(i) = points.iter().position(|row| row.len() != columns) {
            return Err(StepError::plain(format!(
                "B-spline surface: row {i} of the control net has {} points, row 0 has {columns}",
                points[i].len()
            ))
            .into());
        }
        if let Some(w) = &weights
            && (w.len() != points.len() || w.iter().any(|row| row.len() != columns))
        {
            return Err(StepError::plain(format!(
                "rational surface: the weights are not a {}×{columns} net like the control points",
                points.len()
            ))
            .into());
        }
        Ok(SplineSurface {
            degrees,
            knots_u: checked_knots("B-spline surface (u)", degrees.0, points.len(), &ku, &mu)?,
            knots_v: checked_knots("B-spline surface (v)", degrees.1, columns, &kv, &mv)?,
            points,
            weights,
            closed: (boolean(&surf[4])?, boolean(&surf[5])?),
        })
    }

    fn surface(&mut self, id: u64) -> Conv<Surface> {
        self.with(id, |r, inst| {
            if inst.record("B_SPLINE_SURFACE_WITH_KNOTS").is_some() {
                return Ok(Surface::Spline(r.spline_surface(inst)?));
            }
            let axes = |r: &mut Self| -> Conv<Axes> { r.axes(reference(param(inst, 1)?)?) };
            Ok(match inst.records[0].name.as_str() {
                "PLANE" => Surface::Plane(axes(r)?),
                "CYLINDRICAL_SURFACE" => Surface::Cylinder { axes: axes(r)?, radius: r.length(param(inst, 2)?)? },
                "CONICAL_SURFACE" => Surface::Cone {
                    axes: axes(r)?,
                    radius: r.length(param(inst, 2)?)?,
                    semi_angle: r.angle(param(inst, 3)?)?,
                },
                "SPHERICAL_SURFACE" => Surface::Sphere { axes: axes(r)?, radius: r.length(param(inst, 2)?)? },
                "TOROIDAL_SURFACE" => Surface::Torus {
                    axes: axes(r)?,
                    major_radius: r.length(param(inst, 2)?)?,
                    minor_radius: r.length(param(inst, 3)?)?,
                },
                "SURFACE_OF_REVOLUTION" => {
                    let profile = r.curve(reference(param(inst, 1)?)?)?;
                    let (axis_origin, axis) = r.with(reference(param(inst, 2)?)?, |r, a| {
                        let o = to3(&r.point(reference(param(a, 1)?)?)?);
                        let z = match param(a, 2)? {
                            Param::Unset => Point::<3>::new(0.0, 0.0, 1.0),
                            p => r.direction(reference(p)?)?,
                        };
                        Ok((o, z))
                    })?;
                    Surface::Revolution { profile, axis_origin, axis }
                }
                "SURFACE_OF_LINEAR_EXTRUSION" => {
                    let profile = r.curve(reference(param(inst, 1)?)?)?;
                    Surface::Extrusion { profile, direction: to3(&r.vector(reference(param(inst, 2)?)?)?) }
                }
                "RECTANGULAR_TRIMMED_SURFACE" => {
                    let basis = r.surface(reference(param(inst, 1)?)?)?;
                    let v = |i| real(param(inst, i)?);
                    if !(boolean(param(inst, 6)?)? && boolean(param(inst, 7)?)?) {
                        return Err(Unsupported::Type("RECTANGULAR_TRIMMED_SURFACE (reversed sense)".into()));
                    }
                    // Each parameter in its unit: lengths on planes and along axes, angles
                    // around them, numbers on splines and along swept profiles.
                    let (length, angle) = (r.units.length, r.units.angle);
                    let (su, sv) = match &basis {
                        Surface::Plane(_) => (length, length),
                        Surface::Cylinder { .. } | Surface::Cone { .. } => (angle, length),
                        Surface::Sphere { .. } | Surface::Torus { .. } => (angle, angle),
                        Surface::Revolution { profile, .. } => match profile {
                            Curve::Circle { .. } | Curve::Ellipse { .. } => (angle, angle),
                            _ => (angle, 1.0),
                        },
                        Surface::Extrusion { profile: Curve::Circle { .. } | Curve::Ellipse { .. }, .. } => {
                            (angle, 1.0)
                        }
                        _ => (1.0, 1.0),
                    };
                    Surface::Trimmed {
                        basis: Box::new(basis),
                        u: (v(2)? * su, v(3)? * su),
                        v: (v(4)? * sv, v(5)? * sv),
                    }
                }
                other => return Err(Unsupported::Type(other.to_string())),
            })
        })
    }

    /// A face: its surface and its loops from the pcurves its edges carry on that surface.
    fn face(&mut self, inst: &Instance) -> Conv<Face> {
        let surface_id = reference(param(inst, 2)?)?;
        let surface = self.surface(surface_id)?;
        let mut loops = Vec::new();
        let mut seam_twins = Vec::new();
        let mut roles = Vec::new();
        let mut outer = None;
        for bound in refs(param(inst, 1)?)? {
            let b = self.get(bound)?;
            let forward = boolean(param(&b, 2)?)?;
            let lp = self.get(reference(param(&b, 1)?)?)?;
            if lp.records[0].name == "VERTEX_LOOP" {
                // A bound that is one point (a pole of a sphere's face): in (u, v) it is the
                // pole's line, which the loops' gap bridging supplies.
                let vertex = self.get(reference(param(&lp, 1)?)?)?;
                self.get(reference(param(&vertex, 1)?)?)?;
                continue;
            }
            if b.records[0].name == "FACE_OUTER_BOUND" {
                outer = Some(loops.len());
            }
            if lp.records[0].name != "EDGE_LOOP" {
                return Err(Unsupported::Type(format!("face bound {}", lp.records[0].name)));
            }
            let mut pieces = Vec::new();
            for oe in refs(param(&lp, 1)?)? {
                let oe = self.get(oe)?;
                let oriented = boolean(param(&oe, 4)?)?;
                let edge_id = reference(param(&oe, 3)?)?;
                let edge = self.get(edge_id)?;
                let mut ends = Vec::with_capacity(2);
                let mut vertex_ids = [0u64; 2];
                for v in [1, 2] {
                    let vertex = reference(param(&edge, v)?)?;
                    let vp = self.get(vertex)?;
                    let p = to3(&self.point(reference(param(&vp, 1)?)?)?);
                    self.vertices.insert(vertex, p);
                    vertex_ids[v - 1] = vertex;
                    ends.push(p);
                }
                let same_sense = boolean(param(&edge, 4)?)?;
                let (space, mut pcurves) = self.pcurves_on(reference(param(&edge, 3)?)?, surface_id)?;
                let one_vertex = reference(param(&edge, 1)?)? == reference(param(&edge, 2)?)?;
                let (lo, hi) = match &space {
                    // A closed spline edge (one vertex) runs over the whole curve.
                    Curve::Spline(s) if one_vertex => (s.knots[s.degree], s.knots[s.knots.len() - 1 - s.degree]),
                    _ => {
                        let (t0, t1) = (parameter_on(&space, ends[0])?, parameter_on(&space, ends[1])?);
                        let (lo, mut hi) = if same_sense { (t0, t1) } else { (t1, t0) };
                        if hi <= lo && is_conic(&space) {
                            hi += std::f64::consts::TAU;
                        }
                        (lo, hi)
                    }
                };
                if pcurves.is_empty() {
                    // The file gives the edge's 3-D curve alone (most CAD systems do): its
                    // pcurve on this face's surface is computed (`crate::pcurve`).
                    let tolerance = self.tolerance();
                    // A pcurve that cannot be computed leaves this face out, named with the
                    // reason, and the rest of the file is read.
                    let computed = crate::pcurve::pcurve(&space, &surface, (lo, hi), tolerance)
                        .map_err(|e| Unsupported::Type(format!("face #{} (edge #{edge_id}: {e})", inst.id)))?;
                    pcurves.push(computed.curve);
                    pcurves.extend(computed.twin);
                }
                self.edges.entry(edge_id).or_insert_with(|| EdgeRead {
                    curve: space.clone(),
                    range: (lo, hi),
                    same_sense,
                    vertices: vertex_ids,
                });
                // A generatrix of a cone: its 3-D line runs by length, its pcurve (a line of
                // constant u) by the height v of the cone's parametrisation, whatever the
                // pcurve's speed and start; the pcurve's parameters at the edge's ends
                // follow from their heights v = (p − origin)·z.
                let trim = |c: &Curve| {
                    let (start, end) = match (&surface, &space, c) {
                        (Surface::Cone { axes, .. }, Curve::Line { .. }, Curve::Line { origin, direction })
                            if direction.len() >= 2 && direction[1] != 0.0 =>
                        {
                            let at = |p: Point<3>| {
                                let height = (p - axes.origin).dot(&axes.z);
                                (height - origin.get(1).copied().unwrap_or(0.0)) / direction[1]
                            };
                            let (a, b) = (at(ends[0]), at(ends[1]));
                            if same_sense { (a, b) } else { (b, a) }
                        }
                        _ => (lo, hi),
                    };
                    Curve::Trimmed { basis: Box::new(c.clone()), start, end }
                };
                pieces.push((
                    trim(&pcurves[0]),
                    pcurves.get(1).map(|c| (edge_id, trim(c))),
                    oriented == same_sense,
                    Role::Edge { id: edge_id, forward: oriented },
                ));
            }
            if !forward {
                pieces.reverse();
                pieces.iter_mut().for_each(|p| {
                    p.2 = !p.2;
                    if let Role::Edge { forward, .. } = &mut p.3 {
                        *forward = !*forward;
                    }
                });
            }
            let run = |c: Curve, fwd: bool| if fwd { Some(c) } else { reversed(c) };
            let mut curves = Vec::new();
            let mut twins = Vec::new();
            roles.push(pieces.iter().map(|p| p.3).collect());
            for (c, twin, fwd, _) in pieces {
                let no_reversal = || Unsupported::Type("face loop with a reversed ellipse pcurve".into());
                curves.push(run(c, fwd).ok_or_else(no_reversal)?);
                twins.push(match twin {
                    Some((id, t)) => Some((id, run(t, fwd).ok_or_else(no_reversal)?)),
                    None => None,
                });
            }
            loops.push(curves);
            seam_twins.push(twins);
        }
        let same_sense = match inst.records[0].params.get(3) {
            Some(p) => boolean(p)?,
            None => true,
        };
        let mut face =
            Face { name: inst_name(inst), surface, loops, seam_twins, outer, roles, id: inst.id, same_sense };
        crate::wrapping_loops::close_wrapping_loops(&mut face);
        Ok(face)
    }

    /// The 3-D curve of an edge's geometry and its 2-D pcurves on the surface `surface_id`
    /// (same parametrisation, as ISO 10303-42 requires of a surface curve): one, or two for
    /// a seam curve on a closed surface.
    fn pcurves_on(&mut self, edge_geometry: u64, surface_id: u64) -> Conv<(Curve, Vec<Curve>)> {
        let g = self.get(edge_geometry)?;
        if !SURFACE_CURVES.contains(&g.records[0].name.as_str()) {
            return Ok((self.curve(edge_geometry)?, Vec::new()));
        }
        let space = self.curve(reference(param(&g, 1)?)?)?;
        let mut found = Vec::new();
        for pc in refs(param(&g, 2)?)? {
            let pci = self.get(pc)?;
            if pci.records[0].name != "PCURVE" || reference(param(&pci, 1)?)? != surface_id {
                // A pcurve on the other face's surface, or the surface itself (writers may
                // name the surfaces a curve lies on instead of its pcurves).
                continue;
            }
            let rep = self.get(reference(param(&pci, 2)?)?)?;
            let items = refs(param(&rep, 1)?)?;
            self.visited.insert(reference(param(&rep, 2)?)?);
            let c = items.first().ok_or_else(|| StepError::plain("an empty pcurve representation"))?;
            // A pcurve lies in the surface's parameter plane, a context without units.
            let units = std::mem::replace(&mut self.units, Units::none());
            let pcurve = self.curve(*c);
            self.units = units;
            found.push(pcurve?);
        }
        Ok((space, found))
    }
}

/// A circle run backwards over the same parameter range [a, b]: with φ = a + b,
/// c(φ − t) = o + r(cos t x′ + sin t y′) where x′ = cos φ x + sin φ y and y′ = sin φ x − cos φ y,
/// the circle of the placement (o, −z, x′).
fn reversed_circle(axes: Axes, radius: f64, (a, b): (f64, f64)) -> Curve {
    let phi = a + b;
    let (x, y) = (axes.x, axes.y());
    let x_reversed = Point::<3>::from_fn(|k, _| phi.cos() * x[k] + phi.sin() * y[k]);
    Curve::Circle { axes: Axes { origin: axes.origin, z: -axes.z, x: x_reversed }, radius }
}

/// The same curve run backwards: c(a + b − t) on [a, b] (lines, splines, circles and their
/// trimmed pieces), or for a trimmed ellipse the arc with its ends swapped (`start > end`:
/// no ellipse in standard form runs backwards over the same parameters); `None` for a
/// whole ellipse.
pub fn reversed(c: Curve) -> Option<Curve> {
    Some(match c {
        Curve::Spline(mut s) => {
            let (a, b) = (s.knots[s.degree], s.knots[s.knots.len() - 1 - s.degree]);
            s.points.reverse();
            if let Some(w) = s.weights.as_mut() {
                w.reverse();
            }
            s.knots = s.knots.iter().rev().map(|k| a + b - k).collect();
            Curve::Spline(s)
        }
        Curve::Trimmed { basis, start, end } => match *basis {
            Curve::Line { origin, direction } => Curve::Trimmed {
                basis: Box::new(Curve::Line { origin, direction: direction.iter().map(|d| -d).collect() }),
                start: -end,
                end: -start,
            },
            Curve::Spline(s) => {
                let (a, b) = (s.knots[s.degree], s.knots[s.knots.len() - 1 - s.degree]);
                Curve::Trimmed { basis: Box::new(reversed(Curve::Spline(s))?), start: a + b - end, end: a + b - start }
            }
            Curve::Circle { axes, radius } => {
                Curve::Trimmed { basis: Box::new(reversed_circle(axes, radius, (start, end))), start, end }
            }
            // No ellipse in standard form runs backwards over the same parameters: the arc
            // is kept with its ends swapped (start > end), a run against the parameter,
            // which the parameter-space loops read as such.
            basis @ Curve::Ellipse { .. } => Curve::Trimmed { basis: Box::new(basis), start: end, end: start },
            _ => return None,
        },
        Curve::Circle { axes, radius } => reversed_circle(axes, radius, (0.0, std::f64::consts::TAU)),
        Curve::Line { origin, direction } => {
            let end: Vec<f64> = origin.iter().zip(&direction).map(|(o, d)| o + d).collect();
            Curve::Line { origin: end, direction: direction.iter().map(|d| -d).collect() }
        }
        _ => return None,
    })
}

/// Whether the curve is a circle or an ellipse (or a trimmed piece of one): its parameter
/// is an angle, periodic.
fn is_conic(c: &Curve) -> bool {
    match c {
        Curve::Circle { .. } | Curve::Ellipse { .. } => true,
        Curve::Trimmed { basis, .. } => is_conic(basis),
        _ => false,
    }
}

/// Whether a placement is the world frame.
pub fn is_world(a: &Axes) -> bool {
    *a == Axes::WORLD
}

/// e(θ) = cos θ x + sin θ y of a placement.
pub fn radial(a: &Axes, theta: f64) -> Point<3> {
    let y = a.z.cross(&a.x);
    Point::<3>::from_fn(|k, _| theta.cos() * a.x[k] + theta.sin() * y[k])
}

/// The parameter of the point `p` (a vertex) on a 3-D curve: projection for lines, the
/// angle for conics, the closest point for splines.
fn parameter_on(c: &Curve, p: Point<3>) -> Conv<f64> {
    Ok(match c {
        Curve::Line { origin, direction } => {
            let (o, d) = (to3(origin), to3(direction));
            (p - o).dot(&d) / d.dot(&d)
        }
        Curve::Circle { axes, .. } | Curve::Ellipse { axes, .. } => {
            let q = p - axes.origin;
            let (a, b) = match c {
                Curve::Ellipse { a, b, .. } => (*a, *b),
                _ => (1.0, 1.0),
            };
            let t = (q.dot(&axes.y()) / b).atan2(q.dot(&axes.x) / a);
            if t < 0.0 { t + std::f64::consts::TAU } else { t }
        }
        Curve::Spline(s) => crate::kernel::closest_parameter(s, p)?,
        Curve::Trimmed { basis, .. } => parameter_on(basis, p)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle_point(axes: &Axes, r: f64, t: f64) -> Point<3> {
        axes.at(r * t.cos(), r * t.sin(), 0.0)
    }

    #[test]
    fn a_reversed_circle_runs_the_same_points_backwards() {
        let axes = Axes {
            origin: Point::<3>::new(1.0, -2.0, 0.5),
            z: Point::<3>::new(0.0, 0.6, 0.8),
            x: Point::<3>::new(1.0, 0.0, 0.0),
        };
        let (a, b) = (0.4, 2.9);
        let Curve::Trimmed { basis, start, end } =
            reversed(Curve::Trimmed { basis: Box::new(Curve::Circle { axes, radius: 2.0 }), start: a, end: b })
                .expect("circles reverse")
        else {
            panic!("a trimmed circle stays trimmed")
        };
        let Curve::Circle { axes: back, radius } = *basis else { panic!("still a circle") };
        assert_eq!((start, end, radius), (a, b, 2.0));
        for k in 0..=10 {
            let t = a + (b - a) * k as f64 / 10.0;
            let (p, q) = (circle_point(&back, radius, t), circle_point(&axes, 2.0, a + b - t));
            assert!((0..3).all(|i| (p[i] - q[i]).abs() < 1e-14), "{p:?} vs {q:?}");
        }
    }
}
