//! Geometry items → a complete AP214 file that strict readers (OpenCASCADE's
//! `STEPControl_Reader`) accept and transfer: header, application protocol, one product
//! with its definition and shape, millimetre/radian units with an uncertainty, and a
//! `GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION` holding one `GEOMETRIC_SET` of
//! every curve and surface, each named after its object, and faces (trimmed surfaces) in
//! the open shells of a `MANIFOLD_SURFACE_SHAPE_REPRESENTATION`. Every set item is bounded
//! (B-splines, trimmed curves, rectangular trimmed surfaces), as geometric sets require.

use splinekit::Point;

use crate::geometry::{
    Axes, Curve, FaceGeometry, Geometry, Item, LoopEdge, SplineCurve, SplineSurface, Surface, knot_multiplicities,
};
use crate::part21::writer::{HeaderInfo, Part21Writer};
use crate::part21::{Param, Record};

fn s(text: &str) -> Param {
    Param::String(text.to_string())
}
fn r(id: u64) -> Param {
    Param::Reference(id)
}
fn e(name: &str) -> Param {
    Param::Enumeration(name.to_string())
}
fn real(x: f64) -> Param {
    Param::Real(x)
}
fn reals(xs: &[f64]) -> Param {
    Param::List(xs.iter().map(|&x| real(x)).collect())
}
fn ints(xs: &[usize]) -> Param {
    Param::List(xs.iter().map(|&x| Param::Integer(x as i64)).collect())
}
fn flag(b: bool) -> Param {
    e(if b { "T" } else { "F" })
}
fn rec(name: &str, params: Vec<Param>) -> Record {
    Record { name: name.to_string(), params }
}

/// Writes geometry entities into a [`Part21Writer`].
pub struct GeometryWriter<'a> {
    w: &'a mut Part21Writer,
    /// The parameter-plane context of pcurves, written with the first one.
    parameter_context: Option<u64>,
}

impl<'a> GeometryWriter<'a> {
    /// Writes into `w`.
    pub fn new(w: &'a mut Part21Writer) -> Self {
        GeometryWriter { w, parameter_context: None }
    }

    fn point(&mut self, p: &[f64]) -> u64 {
        self.w.add("CARTESIAN_POINT", vec![s(""), reals(p)])
    }

    fn direction(&mut self, d: &[f64]) -> u64 {
        self.w.add("DIRECTION", vec![s(""), reals(d)])
    }

    fn axes(&mut self, a: &Axes) -> u64 {
        let (o, z, x) =
            (self.point(a.origin.as_slice()), self.direction(a.z.as_slice()), self.direction(a.x.as_slice()));
        self.w.add("AXIS2_PLACEMENT_3D", vec![s(""), r(o), r(z), r(x)])
    }

    /// An elementary curve or surface on a placement: `entity(name, #axes, sizes…)` (the
    /// circle's radius, the torus's two radii, none for the plane), its
    /// `AXIS2_PLACEMENT_3D` written first.
    fn placed(&mut self, entity: &str, name: &str, axes: &Axes, sizes: &[f64]) -> u64 {
        let a = self.axes(axes);
        let params = [s(name), r(a)].into_iter().chain(sizes.iter().map(|&x| real(x))).collect();
        self.w.add(entity, params)
    }

    fn axis1(&mut self, origin: Point<3>, axis: Point<3>) -> u64 {
        let (o, z) = (self.point(origin.as_slice()), self.direction(axis.as_slice()));
        self.w.add("AXIS1_PLACEMENT", vec![s(""), r(o), r(z)])
    }

    fn vector(&mut self, v: &[f64]) -> u64 {
        let len = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        let unit: Vec<f64> = v.iter().map(|x| x / len).collect();
        let d = self.direction(&unit);
        self.w.add("VECTOR", vec![s(""), r(d), real(len)])
    }

    /// Writes a curve named `name`; returns its `#id`.
    pub fn curve(&mut self, c: &Curve, name: &str) -> u64 {
        match c {
            Curve::Line { origin, direction } => {
                let (o, v) = (self.point(origin), self.vector(direction));
                self.w.add("LINE", vec![s(name), r(o), r(v)])
            }
            Curve::Circle { axes, radius } => self.placed("CIRCLE", name, axes, &[*radius]),
            Curve::Ellipse { axes, a, b } => self.placed("ELLIPSE", name, axes, &[*a, *b]),
            Curve::Spline(sc) => self.spline_curve(sc, name),
            Curve::Trimmed { basis, start, end } => {
                let b = self.curve(basis, "");
                let trim = |t: f64| Param::List(vec![Param::Typed("PARAMETER_VALUE".into(), Box::new(real(t)))]);
                self.w.add("TRIMMED_CURVE", vec![s(name), r(b), trim(*start), trim(*end), flag(true), e("PARAMETER")])
            }
        }
    }

    fn spline_curve(&mut self, c: &SplineCurve, name: &str) -> u64 {
        let pts: Vec<Param> = c.points.iter().map(|p| r(self.point(p))).collect();
        let (values, mults) = knot_multiplicities(&c.knots);
        let closed = flag(c.closed);
        let curve = vec![Param::Integer(c.degree as i64), Param::List(pts), e("UNSPECIFIED"), closed, flag(false)];
        let knots = vec![ints(&mults), reals(&values), e("UNSPECIFIED")];
        self.b_spline("CURVE", name, curve, knots, c.weights.as_deref().map(reals))
    }

    fn spline_surface(&mut self, sf: &SplineSurface, name: &str) -> u64 {
        let net: Vec<Param> =
            sf.points.iter().map(|row| Param::List(row.iter().map(|p| r(self.point(p))).collect())).collect();
        let (ku, mu) = knot_multiplicities(&sf.knots_u);
        let (kv, mv) = knot_multiplicities(&sf.knots_v);
        let surface = vec![
            Param::Integer(sf.degrees.0 as i64),
            Param::Integer(sf.degrees.1 as i64),
            Param::List(net),
            e("UNSPECIFIED"),
            flag(sf.closed.0),
            flag(sf.closed.1),
            flag(false),
        ];
        let knots = vec![ints(&mu), ints(&mv), reals(&ku), reals(&kv), e("UNSPECIFIED")];
        let weights = sf.weights.as_ref().map(|w| Param::List(w.iter().map(|row| reals(row)).collect()));
        self.b_spline("SURFACE", name, surface, knots, weights)
    }

    /// A B-spline curve or surface (`kind` `CURVE` or `SURFACE`) from its `B_SPLINE_{kind}`
    /// and `…_WITH_KNOTS` parameters: the simple entity `B_SPLINE_{kind}_WITH_KNOTS`, or
    /// with `weights` the complex entity of the rational one (the writer orders its
    /// records alphabetically, as Part 21 requires).
    fn b_spline(
        &mut self,
        kind: &str,
        name: &str,
        spline: Vec<Param>,
        knots: Vec<Param>,
        weights: Option<Param>,
    ) -> u64 {
        let Some(w) = weights else {
            let params = [vec![s(name)], spline, knots].concat();
            return self.w.add(&format!("B_SPLINE_{kind}_WITH_KNOTS"), params);
        };
        self.w.add_complex(vec![
            rec(&format!("BOUNDED_{kind}"), vec![]),
            rec(&format!("B_SPLINE_{kind}"), spline),
            rec(&format!("B_SPLINE_{kind}_WITH_KNOTS"), knots),
            rec(kind, vec![]),
            rec("GEOMETRIC_REPRESENTATION_ITEM", vec![]),
            rec(&format!("RATIONAL_B_SPLINE_{kind}"), vec![w]),
            rec("REPRESENTATION_ITEM", vec![s(name)]),
        ])
    }

    /// Writes a surface named `name`; returns its `#id`.
    pub fn surface(&mut self, sf: &Surface, name: &str) -> u64 {
        match sf {
            Surface::Plane(axes) => self.placed("PLANE", name, axes, &[]),
            Surface::Cylinder { axes, radius } => self.placed("CYLINDRICAL_SURFACE", name, axes, &[*radius]),
            Surface::Cone { axes, radius, semi_angle } => {
                self.placed("CONICAL_SURFACE", name, axes, &[*radius, *semi_angle])
            }
            Surface::Sphere { axes, radius } => self.placed("SPHERICAL_SURFACE", name, axes, &[*radius]),
            Surface::Torus { axes, major_radius, minor_radius } => {
                self.placed("TOROIDAL_SURFACE", name, axes, &[*major_radius, *minor_radius])
            }
            Surface::Spline(b) => self.spline_surface(b, name),
            Surface::Revolution { profile, axis_origin, axis } => {
                let c = self.curve(profile, "");
                let a = self.axis1(*axis_origin, *axis);
                self.w.add("SURFACE_OF_REVOLUTION", vec![s(name), r(c), r(a)])
            }
            Surface::Extrusion { profile, direction } => {
                let c = self.curve(profile, "");
                let v = self.vector(direction.as_slice());
                self.w.add("SURFACE_OF_LINEAR_EXTRUSION", vec![s(name), r(c), r(v)])
            }
            Surface::Trimmed { basis, u, v } => {
                let b = self.surface(basis, "");
                self.w.add(
                    "RECTANGULAR_TRIMMED_SURFACE",
                    vec![s(name), r(b), real(u.0), real(u.1), real(v.0), real(v.1), flag(true), flag(true)],
                )
            }
        }
    }
}

impl GeometryWriter<'_> {
    /// The 2-D `PARAMETRIC_REPRESENTATION_CONTEXT` of pcurves (one per file).
    fn parameter_context(&mut self) -> u64 {
        if let Some(id) = self.parameter_context {
            return id;
        }
        let id = self.w.add_complex(vec![
            rec("GEOMETRIC_REPRESENTATION_CONTEXT", vec![Param::Integer(2)]),
            rec("PARAMETRIC_REPRESENTATION_CONTEXT", vec![]),
            rec("REPRESENTATION_CONTEXT", vec![s("2D SPACE"), s("")]),
        ]);
        self.parameter_context = Some(id);
        id
    }

    /// Writes a face named `name` (`ADVANCED_FACE` with its bounds, edges, vertices, 3-D
    /// curves and pcurves); returns its `#id`.
    pub fn face(&mut self, f: &FaceGeometry, name: &str) -> u64 {
        let surface = self.surface(&f.surface, "");
        let vertices: Vec<u64> = f
            .vertices
            .iter()
            .map(|p| {
                let pt = self.point(p.as_slice());
                self.w.add("VERTEX_POINT", vec![s(""), r(pt)])
            })
            .collect();
        let ctx = self.parameter_context();
        let mut bounds = Vec::with_capacity(f.loops.len());
        for l in &f.loops {
            let mut oriented = Vec::with_capacity(l.edges.len());
            let mut written = Vec::with_capacity(l.edges.len());
            for use_ in &l.edges {
                let (ec, forward) = match use_ {
                    LoopEdge::Edge(edge) => {
                        let c3 = self.curve(&edge.curve, "");
                        let mut pcurves = Vec::with_capacity(2);
                        for pc in std::iter::once(&edge.pcurve).chain(&edge.seam) {
                            let c2 = self.curve(pc, "");
                            let rep = self
                                .w
                                .add("DEFINITIONAL_REPRESENTATION", vec![s(""), Param::List(vec![r(c2)]), r(ctx)]);
                            pcurves.push(r(self.w.add("PCURVE", vec![s(""), r(surface), r(rep)])));
                        }
                        let kind = if edge.seam.is_some() { "SEAM_CURVE" } else { "SURFACE_CURVE" };
                        let geometry = self.w.add(kind, vec![s(""), r(c3), Param::List(pcurves), e("PCURVE_S1")]);
                        let ec = self.w.add(
                            "EDGE_CURVE",
                            vec![s(""), r(vertices[edge.start]), r(vertices[edge.end]), r(geometry), flag(true)],
                        );
                        (ec, true)
                    }
                    LoopEdge::Again(k) => (written[*k], false),
                };
                written.push(ec);
                oriented.push(r(self
                    .w
                    .add("ORIENTED_EDGE", vec![s(""), Param::Derived, Param::Derived, r(ec), flag(forward)])));
            }
            let lp = self.w.add("EDGE_LOOP", vec![s(""), Param::List(oriented)]);
            let kind = if l.outer { "FACE_OUTER_BOUND" } else { "FACE_BOUND" };
            bounds.push(r(self.w.add(kind, vec![s(""), r(lp), flag(l.orientation)])));
        }
        self.w.add("ADVANCED_FACE", vec![s(name), Param::List(bounds), r(surface), flag(true)])
    }
}

/// The ids of the shared context entities.
struct Context {
    geometric_context: u64,
    product_shape: u64,
}

/// Application protocol, product structure, units and the 3-D representation context.
fn write_context(w: &mut Part21Writer, product_name: &str) -> Context {
    let app = w.add("APPLICATION_CONTEXT", vec![s("core data for automotive mechanical design processes")]);
    w.add(
        "APPLICATION_PROTOCOL_DEFINITION",
        vec![s("international standard"), s("automotive_design"), Param::Integer(2000), r(app)],
    );
    let pc = w.add("PRODUCT_CONTEXT", vec![s(""), r(app), s("mechanical")]);
    let product = w.add("PRODUCT", vec![s(product_name), s(product_name), s(""), Param::List(vec![r(pc)])]);
    w.add("PRODUCT_RELATED_PRODUCT_CATEGORY", vec![s("part"), Param::Unset, Param::List(vec![r(product)])]);
    let formation = w.add("PRODUCT_DEFINITION_FORMATION", vec![s(""), s(""), r(product)]);
    let pdc = w.add("PRODUCT_DEFINITION_CONTEXT", vec![s("part definition"), r(app), s("design")]);
    let pd = w.add("PRODUCT_DEFINITION", vec![s("design"), s(""), r(formation), r(pdc)]);
    let product_shape = w.add("PRODUCT_DEFINITION_SHAPE", vec![s(""), s(""), r(pd)]);
    let mm = w.add_complex(vec![
        rec("LENGTH_UNIT", vec![]),
        rec("NAMED_UNIT", vec![Param::Derived]),
        rec("SI_UNIT", vec![e("MILLI"), e("METRE")]),
    ]);
    let rad = w.add_complex(vec![
        rec("NAMED_UNIT", vec![Param::Derived]),
        rec("PLANE_ANGLE_UNIT", vec![]),
        rec("SI_UNIT", vec![Param::Unset, e("RADIAN")]),
    ]);
    let sr = w.add_complex(vec![
        rec("NAMED_UNIT", vec![Param::Derived]),
        rec("SI_UNIT", vec![Param::Unset, e("STERADIAN")]),
        rec("SOLID_ANGLE_UNIT", vec![]),
    ]);
    let uncertainty = w.add(
        "UNCERTAINTY_MEASURE_WITH_UNIT",
        vec![
            Param::Typed("LENGTH_MEASURE".into(), Box::new(real(1e-7))),
            r(mm),
            s("distance_accuracy_value"),
            s("confusion accuracy"),
        ],
    );
    let geometric_context = w.add_complex(vec![
        rec("GEOMETRIC_REPRESENTATION_CONTEXT", vec![Param::Integer(3)]),
        rec("GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT", vec![Param::List(vec![r(uncertainty)])]),
        rec("GLOBAL_UNIT_ASSIGNED_CONTEXT", vec![Param::List(vec![r(mm), r(rad), r(sr)])]),
        rec("REPRESENTATION_CONTEXT", vec![s("3D"), s("splinekit geometry in millimetres")]),
    ]);
    Context { geometric_context, product_shape }
}

/// The complete file text of `items` (one product named `product_name`): curves and
/// surfaces in a geometric set of a `GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION`,
/// faces each in an `OPEN_SHELL` of one `SHELL_BASED_SURFACE_MODEL` of a
/// `MANIFOLD_SURFACE_SHAPE_REPRESENTATION`, both representations of the product's shape.
pub fn write_step(items: &[Item], product_name: &str, header: &HeaderInfo) -> String {
    let mut w = Part21Writer::new(header);
    let ctx = write_context(&mut w, product_name);
    let (mut ids, mut shells) = (Vec::with_capacity(items.len()), Vec::new());
    {
        let mut g = GeometryWriter::new(&mut w);
        for item in items {
            match &item.geometry {
                Geometry::Curve(c) => ids.push(r(g.curve(c, &item.name))),
                Geometry::Surface(sf) => ids.push(r(g.surface(sf, &item.name))),
                Geometry::Face(f) => {
                    let face = g.face(f, &item.name);
                    shells.push(r(g.w.add("OPEN_SHELL", vec![s(&item.name), Param::List(vec![r(face)])])));
                }
            }
        }
    }
    if !ids.is_empty() || shells.is_empty() {
        let set = w.add("GEOMETRIC_SET", vec![s(product_name), Param::List(ids)]);
        let rep = w.add(
            "GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION",
            vec![s(product_name), Param::List(vec![r(set)]), r(ctx.geometric_context)],
        );
        w.add("SHAPE_DEFINITION_REPRESENTATION", vec![r(ctx.product_shape), r(rep)]);
    }
    if !shells.is_empty() {
        let model = w.add("SHELL_BASED_SURFACE_MODEL", vec![s(product_name), Param::List(shells)]);
        let rep = w.add(
            "MANIFOLD_SURFACE_SHAPE_REPRESENTATION",
            vec![s(product_name), Param::List(vec![r(model)]), r(ctx.geometric_context)],
        );
        w.add("SHAPE_DEFINITION_REPRESENTATION", vec![r(ctx.product_shape), r(rep)]);
    }
    w.finish()
}
