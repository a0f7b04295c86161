//! The product structure of a STEP file: which parts it holds, where each is placed, and
//! which entities carry each part's geometry.
//!
//! # The STEP structure read
//!
//! ISO 10303-44 (product structure) and -41 (product definition), as AP203, AP214 and
//! AP242 use them:
//!
//! ```text
//! PRODUCT(id, name, …) ← PRODUCT_DEFINITION_FORMATION(…, of_product)
//!                      ← PRODUCT_DEFINITION(id, …, formation, …)              a "part" or assembly
//! PRODUCT_DEFINITION_SHAPE(…, definition: PRODUCT_DEFINITION)
//!   ← SHAPE_DEFINITION_REPRESENTATION(definition, used_representation)      its shape
//! NEXT_ASSEMBLY_USAGE_OCCURRENCE(id, name, …, relating: parent PD, related: child PD, …)
//! PRODUCT_DEFINITION_SHAPE(…, definition: NAUO)
//!   ← CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(representation_relation, that shape)
//!       representation_relation = (REPRESENTATION_RELATIONSHIP(…, rep_1, rep_2)
//!                                  REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(op)
//!                                  SHAPE_REPRESENTATION_RELATIONSHIP())
//!       op = ITEM_DEFINED_TRANSFORMATION(…, transform_item_1, transform_item_2)
//! ```
//!
//! ISO 10303-43 (representation structures) relates representations:
//! `SHAPE_REPRESENTATION_RELATIONSHIP(…, rep_1, rep_2)` without a transformation says that
//! two representations describe one shape in one coordinate space (a product's
//! `SHAPE_REPRESENTATION` and the `ADVANCED_BREP_SHAPE_REPRESENTATION` holding its solid);
//! `MAPPED_ITEM(name, REPRESENTATION_MAP(mapping_origin, mapped_representation),
//! mapping_target)` places a copy of a representation inside another one.
//!
//! # Transformations
//!
//! A placement `AXIS2_PLACEMENT_3D` (ISO 10303-42) is the frame M(p) = o + R p with
//! R = [x y z] (`build_axes`: z = axis, default (0, 0, 1); x = the part of ref_direction
//! orthogonal to z, default `first_proj_axis`). An `ITEM_DEFINED_TRANSFORMATION` maps the
//! frame of its item in the child's representation onto the frame of its item in the
//! parent's: T = M_parent ∘ M_child⁻¹. ISO 10303-43 puts transform_item_1 in rep_1 and
//! transform_item_2 in rep_2; writers disagree on which of rep_1 and rep_2 is the child
//! (SolidWorks writes the assembly first, ST-Developer and OpenCASCADE the component), so
//! the child is told by the representations: the side that is a representation of the
//! NAUO's related product definition (or of the parent's, the other side). A `MAPPED_ITEM`
//! is placed by T = M_target ∘ M_origin⁻¹. A `CARTESIAN_TRANSFORMATION_OPERATOR_3D` (a
//! functionally defined transformation) is read as the frame of its axes and origin; one
//! that scales or mirrors is refused, since placements here are rigid.
//!
//! Each frame's origin is a length in the units of its own representation's context, so
//! the two frames of one transformation may be in different units (an Inventor part in
//! millimetres inside an assembly in inches): both are converted to millimetres before the
//! transformation is formed, and every [`RigidTransform`] here is in millimetres.
//!
//! # What is produced
//!
//! [`ProductStructure`]: the parts (a product definition and the geometry items of its
//! shape) once each, and the instances: one per leaf occurrence, with the path of
//! occurrence names from the root product, the part, and the placement in the root's
//! coordinates. A part used several times is one [`Part`] and several [`PartInstance`]s.
//! Representations holding geometry that no product reaches (files without product
//! structure) are parts of their own, each with one instance at the identity.
//!
//! Malformed structure (a reference of the wrong type, a zero direction, a non-finite
//! coordinate, an assembly that contains itself) is an error naming the entity `#id` and
//! its field; structure that is merely incomplete (an occurrence without placement) is
//! read as far as it goes and said in [`ProductStructure::notes`].

use std::collections::{BTreeSet, HashMap, HashSet};

use crate::error::{Result, StepError};
use crate::part21::{Instance, Param, Record, StepFile};
use crate::units::context_units;

pub use splinekit_scene::placement::RigidTransform;

/// What kind of geometry a [`ShapeItem`] is (ISO 10303-42 geometric and topological
/// representation items).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ItemKind {
    /// `MANIFOLD_SOLID_BREP`: a solid bounded by one closed shell.
    ManifoldSolidBrep,
    /// `BREP_WITH_VOIDS`: a solid with an outer closed shell and inner void shells.
    BrepWithVoids,
    /// `FACETED_BREP`: a solid of planar polygonal faces.
    FacetedBrep,
    /// `SHELL_BASED_SURFACE_MODEL`: open or closed shells that bound no solid.
    ShellBasedSurfaceModel,
    /// `GEOMETRIC_SET` or `GEOMETRIC_CURVE_SET`: loose points, curves and surfaces
    /// (construction or supplemental geometry).
    GeometricSet,
}

impl ItemKind {
    /// The kind of an entity type name (`(A B)` for complex instances), if it is one.
    pub fn of_type(type_name: &str) -> Option<ItemKind> {
        const KINDS: [(&str, ItemKind); 6] = [
            ("MANIFOLD_SOLID_BREP", ItemKind::ManifoldSolidBrep),
            ("BREP_WITH_VOIDS", ItemKind::BrepWithVoids),
            ("FACETED_BREP", ItemKind::FacetedBrep),
            ("SHELL_BASED_SURFACE_MODEL", ItemKind::ShellBasedSurfaceModel),
            ("GEOMETRIC_SET", ItemKind::GeometricSet),
            ("GEOMETRIC_CURVE_SET", ItemKind::GeometricSet),
        ];
        // A subtype wins over its supertype in a complex instance (BREP_WITH_VOIDS is a
        // MANIFOLD_SOLID_BREP).
        let mut found = None;
        for (name, kind) in KINDS {
            if has_record(type_name, name) {
                found = match (found, kind) {
                    (Some(ItemKind::BrepWithVoids), _) => found,
                    _ => Some(kind),
                };
            }
        }
        found
    }

    /// Whether it bounds a solid (what OpenCASCADE counts as a solid).
    pub fn is_solid(self) -> bool {
        matches!(self, ItemKind::ManifoldSolidBrep | ItemKind::BrepWithVoids | ItemKind::FacetedBrep)
    }
}

/// One geometry item of a part.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeItem {
    /// The item's `#id` (a `MANIFOLD_SOLID_BREP`, `BREP_WITH_VOIDS`, …).
    pub id: u64,
    /// What it is.
    pub kind: ItemKind,
    /// The representation whose items list holds it.
    pub representation: u64,
    /// That representation's context: its units ([`crate::units::context_units`]) are
    /// the item's.
    pub context: u64,
    /// Where the item lies in its part's coordinates: the identity, unless a `MAPPED_ITEM`
    /// inside the part's own representations places it.
    pub placement: RigidTransform,
}

/// A part: a product definition whose shape holds geometry (or, in a file without
/// product structure, a representation that holds geometry).
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// The `PRODUCT_DEFINITION`, if the part comes from one.
    pub product_definition: Option<u64>,
    /// Its `PRODUCT`, if one is found.
    pub product: Option<u64>,
    /// The product's name (its `id` where the name is blank), or the representation's
    /// name (else `#id`) for a representation outside any product.
    pub name: String,
    /// The representations of its shape: those its `SHAPE_DEFINITION_REPRESENTATION`s
    /// name and those related to them by `SHAPE_REPRESENTATION_RELATIONSHIP`s without a
    /// transformation.
    pub representations: Vec<u64>,
    /// Its geometry items.
    pub items: Vec<ShapeItem>,
}

/// One step of an occurrence path.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Occurrence {
    /// The entity: the root `PRODUCT_DEFINITION` (first step), a
    /// `NEXT_ASSEMBLY_USAGE_OCCURRENCE`, or a `MAPPED_ITEM` that places a product's shape.
    pub id: u64,
    /// Its name: the root product's name; the NAUO's name, or its `id` where the name is
    /// blank (as OpenCASCADE names components); the mapped item's name, else the placed
    /// product's.
    pub name: String,
}

/// One placed use of a part.
#[derive(Debug, Clone, PartialEq)]
pub struct PartInstance {
    /// Index into [`ProductStructure::parts`].
    pub part: usize,
    /// From the root product through each sub-assembly occurrence to the part's.
    pub path: Vec<Occurrence>,
    /// Part coordinates → the root's coordinates, in millimetres.
    pub placement: RigidTransform,
}

/// The parts and instances of a file (see the module documentation).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ProductStructure {
    /// Each part once, in the order first met (roots by increasing `#id`).
    pub parts: Vec<Part>,
    /// Every leaf occurrence.
    pub instances: Vec<PartInstance>,
    /// What was incomplete and how it was read (an occurrence without a placement, a
    /// relationship that could not be oriented).
    pub notes: Vec<String>,
    /// Every entity read: products, definitions, occurrences, relationships,
    /// transformations and their placements, representations, maps and contexts.
    pub entities: BTreeSet<u64>,
}

/// Most instances a file may expand to (an assembly of assemblies used twice at every
/// level doubles with each level).
pub const MAX_INSTANCES: usize = 1_000_000;

/// Deepest nesting of assemblies, and of mapped items inside mapped items.
pub const MAX_DEPTH: usize = 64;

/// Reads the product structure (see the module documentation).
pub fn read_product_structure(file: &StepFile) -> Result<ProductStructure> {
    let mut r = Reader::new(file);
    let mut out = r.read()?;
    out.entities = std::mem::take(&mut r.read).into_iter().collect();
    Ok(out)
}

/// Every entity [`read_product_structure`] reads; reading that fails stops where it
/// failed and gives what was read before.
pub fn product_structure_entities(file: &StepFile) -> HashSet<u64> {
    let mut r = Reader::new(file);
    let _ = r.read();
    std::mem::take(&mut r.read)
}

/// Whether a type name (`A` or `(A B C)`) is or contains the record `name`.
pub(crate) fn has_record(type_name: &str, name: &str) -> bool {
    match type_name.strip_prefix('(') {
        Some(rest) => rest.trim_end_matches(')').split(' ').any(|t| t == name),
        None => type_name == name,
    }
}

/// An error at `inst`'s field `field`.
pub(crate) fn field_error(inst: &Instance, field: &str, message: impl std::fmt::Display) -> StepError {
    StepError::at(inst.line, Some(inst.id), format!("{field}: {message}"))
}

/// The record `name` of an instance (simple or complex).
pub(crate) fn record<'a>(inst: &'a Instance, name: &str) -> Result<&'a Record> {
    inst.record(name)
        .ok_or_else(|| StepError::at(inst.line, Some(inst.id), format!("expected {name}, got {}", inst.type_name())))
}

/// Parameter `i` of record `r` of `inst`, named `field` in errors.
pub(crate) fn arg<'a>(inst: &Instance, r: &'a Record, i: usize, field: &str) -> Result<&'a Param> {
    r.params.get(i).ok_or_else(|| field_error(inst, &format!("{}.{field}", r.name), "missing"))
}

/// A reference parameter.
pub(crate) fn reference_arg(inst: &Instance, r: &Record, i: usize, field: &str) -> Result<u64> {
    match arg(inst, r, i, field)? {
        Param::Reference(id) => Ok(*id),
        other => {
            Err(field_error(inst, &format!("{}.{field}", r.name), format!("expected a reference #id, got {other:?}")))
        }
    }
}

/// A list-of-references parameter (a lone reference is read as a list of one).
pub(crate) fn references_arg(inst: &Instance, r: &Record, i: usize, field: &str) -> Result<Vec<u64>> {
    match arg(inst, r, i, field)? {
        Param::List(items) => items
            .iter()
            .map(|p| match p {
                Param::Reference(id) => Ok(*id),
                other => Err(field_error(
                    inst,
                    &format!("{}.{field}", r.name),
                    format!("expected a list of references, got {other:?} in it"),
                )),
            })
            .collect(),
        Param::Reference(id) => Ok(vec![*id]),
        other => Err(field_error(
            inst,
            &format!("{}.{field}", r.name),
            format!("expected a list of references, got {other:?}"),
        )),
    }
}

/// A string parameter ("" for `$`, `*` and anything else that is not a string).
pub(crate) fn text(p: Option<&Param>) -> String {
    match p {
        Some(Param::String(s)) => s.clone(),
        _ => String::new(),
    }
}

/// A number parameter, bare or typed (`LENGTH_MEASURE(1.)`), finite.
pub(crate) fn finite(inst: &Instance, p: &Param, field: &str) -> Result<f64> {
    let x = match p {
        Param::Real(x) => *x,
        Param::Integer(i) => *i as f64,
        Param::Typed(_, inner) => return finite(inst, inner, field),
        other => return Err(field_error(inst, field, format!("expected a number, got {other:?}"))),
    };
    if x.is_finite() { Ok(x) } else { Err(field_error(inst, field, format!("not a finite number: {x}"))) }
}

/// The first record of a representation: (name, items, context_of_items).
fn representation_record(inst: &Instance) -> Option<&Record> {
    inst.records
        .iter()
        .find(|r| (r.name.ends_with("REPRESENTATION") || r.name == "DRAUGHTING_MODEL") && r.params.len() >= 3)
}

/// An assembly occurrence.
#[derive(Debug, Clone)]
struct Nauo {
    id: u64,
    name: String,
    parent: u64,
    child: u64,
}

/// A product's shape placed inside another product's representation by a `MAPPED_ITEM`.
#[derive(Debug, Clone)]
struct MappedOccurrence {
    item: u64,
    name: String,
    child: u64,
    placement: RigidTransform,
}

/// A product definition's shape, gathered.
#[derive(Debug, Clone, Default)]
struct Gathered {
    items: Vec<ShapeItem>,
    reps: Vec<u64>,
    mapped: Vec<MappedOccurrence>,
}

/// The indexes of one pass over the file, and what has been read.
struct Reader<'a> {
    file: &'a StepFile,
    read: HashSet<u64>,
    /// Millimetres per length unit of each context read.
    lengths: HashMap<u64, f64>,
    /// Product definition → (name, PRODUCT id).
    products: HashMap<u64, (String, Option<u64>)>,
    /// Product definitions, increasing.
    definitions: Vec<u64>,
    /// Product definition → the representations its SDRs name.
    shapes: HashMap<u64, Vec<u64>>,
    /// Representation → the product definition whose SDR names it.
    owner: HashMap<u64, u64>,
    nauos: Vec<Nauo>,
    /// Product definition → the indexes in `nauos` of its components.
    components: HashMap<u64, Vec<usize>>,
    /// Product definitions walked, and how many occurrences were.
    walked: HashSet<u64>,
    steps: usize,
    /// NAUO → the representation relationships of its CDSRs.
    placements: HashMap<u64, Vec<u64>>,
    /// Representation → (relationship, the other representation) for every shape
    /// representation relationship without a transformation and outside any CDSR.
    same_space: HashMap<u64, Vec<(u64, u64)>>,
    /// Relationships with a transformation outside any CDSR (noted, not followed).
    loose_transformed: Vec<u64>,
    /// Parts by product definition (or by representation for loose ones).
    part_of: HashMap<u64, Option<usize>>,
    gathered: HashMap<u64, Gathered>,
    out: ProductStructure,
}

impl<'a> Reader<'a> {
    fn new(file: &'a StepFile) -> Self {
        Reader {
            file,
            read: HashSet::new(),
            lengths: HashMap::new(),
            products: HashMap::new(),
            definitions: Vec::new(),
            shapes: HashMap::new(),
            owner: HashMap::new(),
            nauos: Vec::new(),
            components: HashMap::new(),
            walked: HashSet::new(),
            steps: 0,
            placements: HashMap::new(),
            same_space: HashMap::new(),
            loose_transformed: Vec::new(),
            part_of: HashMap::new(),
            gathered: HashMap::new(),
            out: ProductStructure::default(),
        }
    }

    fn get(&mut self, id: u64) -> Result<Instance> {
        self.read.insert(id);
        self.file.get(id)
    }

    fn type_of(&self, id: u64) -> &'a str {
        self.file.type_of(id).unwrap_or("")
    }

    fn read(&mut self) -> Result<ProductStructure> {
        self.index()?;
        // Roots: product definitions no occurrence uses, by increasing #id.
        let children: HashSet<u64> = self.nauos.iter().map(|n| n.child).collect();
        let roots: Vec<u64> = self.definitions.iter().copied().filter(|pd| !children.contains(pd)).collect();
        for root in roots {
            let name = self.products.get(&root).map(|p| p.0.clone()).unwrap_or_default();
            let path = vec![Occurrence { id: root, name }];
            let mut stack = vec![root];
            self.walk(root, RigidTransform::IDENTITY, path, &mut stack)?;
        }
        // An assembly no root reaches is in a cycle of occurrences (one that contains
        // itself, directly or through others).
        if let Some(n) = self.nauos.iter().find(|n| !self.walked.contains(&n.parent)) {
            return Err(StepError::at(
                self.file.line_of(n.id),
                Some(n.id),
                format!(
                    "its assembly #{} is reached from no root product: occurrences that contain themselves (a cycle)",
                    n.parent
                ),
            ));
        }
        self.loose_representations()?;
        for rr in std::mem::take(&mut self.loose_transformed) {
            self.out.notes.push(format!(
                "#{rr}: a representation relationship with a transformation that no CONTEXT_DEPENDENT_SHAPE_REPRESENTATION uses is not followed"
            ));
        }
        Ok(std::mem::take(&mut self.out))
    }

    /// One pass over the file's instance index: products, shapes, occurrences and
    /// relationships.
    fn index(&mut self) -> Result<()> {
        let mut pds = Vec::new();
        let mut sdrs = Vec::new();
        let mut nauos = Vec::new();
        let mut cdsrs = Vec::new();
        let mut relationships = Vec::new();
        for id in self.file.ids() {
            let t = self.type_of(id);
            if has_record(t, "PRODUCT_DEFINITION") || t == "PRODUCT_DEFINITION_WITH_ASSOCIATED_DOCUMENTS" {
                pds.push(id);
            } else if t == "SHAPE_DEFINITION_REPRESENTATION" {
                sdrs.push(id);
            } else if t == "NEXT_ASSEMBLY_USAGE_OCCURRENCE" {
                nauos.push(id);
            } else if t == "CONTEXT_DEPENDENT_SHAPE_REPRESENTATION" {
                cdsrs.push(id);
            } else if t == "SHAPE_REPRESENTATION_RELATIONSHIP"
                || has_record(t, "REPRESENTATION_RELATIONSHIP")
                    && (has_record(t, "SHAPE_REPRESENTATION_RELATIONSHIP")
                        || has_record(t, "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION"))
            {
                relationships.push(id);
            }
        }
        for pd in pds {
            let inst = self.get(pd)?;
            let r = inst.records.iter().find(|r| r.name.starts_with("PRODUCT_DEFINITION")).unwrap_or(&inst.records[0]);
            let formation = reference_arg(&inst, r, 2, "formation")?;
            let (name, product) = self.product_name(formation)?;
            self.products.insert(pd, (name, product));
            self.definitions.push(pd);
        }
        for sdr in sdrs {
            let inst = self.file.get(sdr)?;
            let r = &inst.records[0];
            let definition = reference_arg(&inst, r, 0, "definition")?;
            let rep = reference_arg(&inst, r, 1, "used_representation")?;
            // The shape of a product definition; shapes of shape aspects (PMI) and of
            // occurrences are not parts.
            let Some(pd) = self.shape_of(definition)? else { continue };
            if !self.products.contains_key(&pd) {
                continue;
            }
            self.read.extend([sdr, definition, rep]);
            self.shapes.entry(pd).or_default().push(rep);
            self.owner.entry(rep).or_insert(pd);
        }
        for id in nauos {
            let inst = self.get(id)?;
            let r = &inst.records[0];
            let parent = reference_arg(&inst, r, 3, "relating_product_definition")?;
            let child = reference_arg(&inst, r, 4, "related_product_definition")?;
            for (pd, field) in [(parent, "relating_product_definition"), (child, "related_product_definition")] {
                if !self.products.contains_key(&pd) {
                    return Err(field_error(
                        &inst,
                        &format!("NEXT_ASSEMBLY_USAGE_OCCURRENCE.{field}"),
                        format!("#{pd} is a {}, not a PRODUCT_DEFINITION", self.type_of(pd)),
                    ));
                }
            }
            if parent == child {
                return Err(field_error(
                    &inst,
                    "NEXT_ASSEMBLY_USAGE_OCCURRENCE.related_product_definition",
                    format!("#{child} is used inside itself"),
                ));
            }
            let name = text(r.params.get(1));
            let name = if name.trim().is_empty() { text(r.params.first()) } else { name };
            self.components.entry(parent).or_default().push(self.nauos.len());
            self.nauos.push(Nauo { id, name, parent, child });
        }
        let mut in_cdsr = HashSet::new();
        for id in cdsrs {
            let inst = self.file.get(id)?;
            let r = &inst.records[0];
            let relation = reference_arg(&inst, r, 0, "representation_relation")?;
            let shape = reference_arg(&inst, r, 1, "represented_product_relation")?;
            let pds = self.file.get(shape)?;
            let definition = reference_arg(&pds, record(&pds, "PRODUCT_DEFINITION_SHAPE")?, 2, "definition")?;
            if self.type_of(definition) != "NEXT_ASSEMBLY_USAGE_OCCURRENCE" {
                self.out.notes.push(format!(
                    "#{id}: the context of this CONTEXT_DEPENDENT_SHAPE_REPRESENTATION is a {}, not an assembly occurrence: not read",
                    self.type_of(definition)
                ));
                continue;
            }
            self.read.extend([id, shape, definition]);
            in_cdsr.insert(relation);
            self.placements.entry(definition).or_default().push(relation);
        }
        for id in relationships {
            if in_cdsr.contains(&id) {
                continue;
            }
            // Marked read where followed (`gather`).
            let inst = self.file.get(id)?;
            if inst.record("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION").is_some() {
                self.loose_transformed.push(id);
                continue;
            }
            let r = inst.record("REPRESENTATION_RELATIONSHIP").unwrap_or(&inst.records[0]);
            let a = reference_arg(&inst, r, 2, "rep_1")?;
            let b = reference_arg(&inst, r, 3, "rep_2")?;
            self.same_space.entry(a).or_default().push((id, b));
            self.same_space.entry(b).or_default().push((id, a));
        }
        Ok(())
    }

    /// The name and PRODUCT of a PRODUCT_DEFINITION_FORMATION.
    fn product_name(&mut self, formation: u64) -> Result<(String, Option<u64>)> {
        let inst = self.get(formation)?;
        let r = inst
            .records
            .iter()
            .find(|r| r.name.starts_with("PRODUCT_DEFINITION_FORMATION"))
            .unwrap_or(&inst.records[0]);
        let product = reference_arg(&inst, r, 2, "of_product")?;
        let p = self.get(product)?;
        let pr = record(&p, "PRODUCT")?;
        let name = text(pr.params.get(1));
        let name = if name.trim().is_empty() { text(pr.params.first()) } else { name };
        Ok((name, Some(product)))
    }

    /// The product definition a PRODUCT_DEFINITION_SHAPE describes (None for the shape of
    /// anything else: a shape aspect, an occurrence).
    fn shape_of(&mut self, definition: u64) -> Result<Option<u64>> {
        if !has_record(self.type_of(definition), "PRODUCT_DEFINITION_SHAPE") {
            return Ok(None);
        }
        let inst = self.file.get(definition)?;
        let pd = reference_arg(&inst, record(&inst, "PRODUCT_DEFINITION_SHAPE")?, 2, "definition")?;
        Ok(self.products.contains_key(&pd).then_some(pd))
    }

    /// Millimetres per length unit of a context.
    fn length_unit(&mut self, context: u64) -> Result<f64> {
        if let Some(&l) = self.lengths.get(&context) {
            return Ok(l);
        }
        self.read.insert(context);
        let l = context_units(self.file, context)?.length;
        self.lengths.insert(context, l);
        Ok(l)
    }

    /// A representation's items and context.
    fn representation(&mut self, id: u64) -> Result<(Vec<u64>, u64)> {
        let inst = self.get(id)?;
        let r = representation_record(&inst).ok_or_else(|| {
            StepError::at(inst.line, Some(id), format!("expected a representation, got {}", inst.type_name()))
        })?;
        let items = references_arg(&inst, r, 1, "items")?;
        let context = reference_arg(&inst, r, 2, "context_of_items")?;
        Ok((items, context))
    }

    /// The context of a representation.
    fn context_of(&mut self, rep: u64) -> Result<u64> {
        Ok(self.representation(rep)?.1)
    }

    /// A direction's unit vector.
    fn direction(&mut self, id: u64, field: &str) -> Result<[f64; 3]> {
        let inst = self.get(id)?;
        let r = record(&inst, "DIRECTION")?;
        let ratios = match arg(&inst, r, 1, "direction_ratios")? {
            Param::List(c) if (2..=3).contains(&c.len()) => {
                c.iter().map(|p| finite(&inst, p, "DIRECTION.direction_ratios")).collect::<Result<Vec<f64>>>()?
            }
            other => {
                return Err(field_error(
                    &inst,
                    "DIRECTION.direction_ratios",
                    format!("expected 2 or 3 numbers, got {other:?}"),
                ));
            }
        };
        let v = [ratios[0], ratios[1], ratios.get(2).copied().unwrap_or(0.0)];
        splinekit::axes::unit_vector(v, field).map_err(|e| field_error(&inst, "DIRECTION.direction_ratios", e))
    }

    /// A point in millimetres (coordinates × `length`).
    fn point(&mut self, id: u64, length: f64) -> Result<[f64; 3]> {
        let inst = self.get(id)?;
        let r = record(&inst, "CARTESIAN_POINT")?;
        let c = match arg(&inst, r, 1, "coordinates")? {
            Param::List(c) if (1..=3).contains(&c.len()) => {
                c.iter().map(|p| finite(&inst, p, "CARTESIAN_POINT.coordinates")).collect::<Result<Vec<f64>>>()?
            }
            other => {
                return Err(field_error(
                    &inst,
                    "CARTESIAN_POINT.coordinates",
                    format!("expected 1 to 3 numbers, got {other:?}"),
                ));
            }
        };
        Ok(std::array::from_fn(|k| c.get(k).copied().unwrap_or(0.0) * length))
    }

    /// The frame of an `AXIS2_PLACEMENT_3D` or `CARTESIAN_TRANSFORMATION_OPERATOR_3D` whose
    /// lengths are in units of `length` millimetres.
    fn frame(&mut self, id: u64, length: f64) -> Result<RigidTransform> {
        let t = self.type_of(id);
        if has_record(t, "CARTESIAN_TRANSFORMATION_OPERATOR_3D") {
            return self.operator(id, length);
        }
        let inst = self.get(id)?;
        let r = record(&inst, "AXIS2_PLACEMENT_3D")?;
        let origin = self.point(reference_arg(&inst, r, 1, "location")?, length)?;
        let z = match arg(&inst, r, 2, "axis")? {
            Param::Reference(d) => self.direction(*d, "axis")?,
            Param::Unset => [0.0, 0.0, 1.0],
            other => {
                return Err(field_error(
                    &inst,
                    "AXIS2_PLACEMENT_3D.axis",
                    format!("expected a direction, got {other:?}"),
                ));
            }
        };
        let reference = match r.params.get(3) {
            Some(Param::Reference(d)) => Some(self.direction(*d, "ref_direction")?),
            None | Some(Param::Unset) => None,
            Some(other) => {
                return Err(field_error(
                    &inst,
                    "AXIS2_PLACEMENT_3D.ref_direction",
                    format!("expected a direction, got {other:?}"),
                ));
            }
        };
        let axes = build_axes(z, reference).map_err(|e| field_error(&inst, "AXIS2_PLACEMENT_3D.ref_direction", e))?;
        Ok(RigidTransform::frame(origin, axes.x, axes.y, axes.z))
    }

    /// A `CARTESIAN_TRANSFORMATION_OPERATOR_3D` (ISO 10303-42: axis1, axis2, local_origin,
    /// scale, axis3; its axes by `base_axis`), refused unless it is rigid.
    fn operator(&mut self, id: u64, length: f64) -> Result<RigidTransform> {
        let inst = self.get(id)?;
        // The simple instance lists every inherited attribute before these five; the
        // complex one splits them between CARTESIAN_TRANSFORMATION_OPERATOR (axis1, axis2,
        // local_origin, scale last) and CARTESIAN_TRANSFORMATION_OPERATOR_3D (axis3).
        let params: Vec<Param> = match inst.record("CARTESIAN_TRANSFORMATION_OPERATOR") {
            Some(base) => {
                let mut p: Vec<Param> = base.params.iter().rev().take(4).rev().cloned().collect();
                let three = record(&inst, "CARTESIAN_TRANSFORMATION_OPERATOR_3D")?;
                p.push(three.params.last().cloned().unwrap_or(Param::Unset));
                p
            }
            None => inst.records[0].params.iter().rev().take(5).rev().cloned().collect(),
        };
        let field = |name: &str| format!("CARTESIAN_TRANSFORMATION_OPERATOR_3D.{name}");
        if params.len() < 5 {
            return Err(field_error(&inst, &field("axis3"), "missing"));
        }
        let axis = |p: &Param, name: &str, this: &mut Self| -> Result<Option<[f64; 3]>> {
            match p {
                Param::Reference(d) => this.direction(*d, name).map(Some),
                Param::Unset => Ok(None),
                other => Err(field_error(&inst, &field(name), format!("expected a direction, got {other:?}"))),
            }
        };
        let a1 = axis(&params[0], "axis1", self)?;
        let a2 = axis(&params[1], "axis2", self)?;
        let a3 = axis(&params[4], "axis3", self)?;
        let origin = match &params[2] {
            Param::Reference(p) => self.point(*p, length)?,
            other => {
                return Err(field_error(&inst, &field("local_origin"), format!("expected a point, got {other:?}")));
            }
        };
        let scale = match &params[3] {
            Param::Unset | Param::Derived => 1.0,
            p => finite(&inst, p, &field("scale"))?,
        };
        if (scale - 1.0).abs() > 1e-9 {
            return Err(field_error(
                &inst,
                &field("scale"),
                format!("{scale}: a placement that scales is not a rigid motion"),
            ));
        }
        let z = a3.unwrap_or([0.0, 0.0, 1.0]);
        let axes = build_axes(z, a1).map_err(|e| field_error(&inst, &field("axis1"), e))?;
        if let Some(a2) = a2 {
            // base_axis: y is axis2 made orthogonal to z and x; against z × x it mirrors.
            if dot(a2, axes.y) <= 0.0 {
                return Err(field_error(&inst, &field("axis2"), "a placement that mirrors is not a rigid motion"));
            }
        }
        Ok(RigidTransform::frame(origin, axes.x, axes.y, axes.z))
    }

    /// The transformation of an assembly occurrence from its CDSR's relationship: child
    /// coordinates → parent coordinates.
    fn occurrence_placement(&mut self, nauo: &Nauo, relation: u64) -> Result<RigidTransform> {
        let inst = self.get(relation)?;
        let r = record(&inst, "REPRESENTATION_RELATIONSHIP")?;
        let rep_1 = reference_arg(&inst, r, 2, "rep_1")?;
        let rep_2 = reference_arg(&inst, r, 3, "rep_2")?;
        let Some(with) = inst.record("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION") else {
            // A relationship without a transformation: the child lies in the parent's
            // space as it is.
            return Ok(RigidTransform::IDENTITY);
        };
        let op = reference_arg(&inst, with, 0, "transformation_operator")?;
        // Which side is the child: a representation of the child's shape, or else the
        // side that is not the parent's; rep_1 (ISO 10303-43's transformation maps rep_1
        // into rep_2) where neither tells.
        let child_reps = self.shape_reps(nauo.child)?;
        let parent_reps = self.shape_reps(nauo.parent)?;
        let rep_1_is_child = if child_reps.contains(&rep_1) || parent_reps.contains(&rep_2) {
            true
        } else if child_reps.contains(&rep_2) || parent_reps.contains(&rep_1) {
            false
        } else {
            self.out.notes.push(format!(
                "#{relation}: neither rep_1 #{rep_1} nor rep_2 #{rep_2} is a representation of #{} or #{}: rep_1 taken as the component's",
                nauo.child, nauo.parent
            ));
            true
        };
        let (child_rep, parent_rep) = if rep_1_is_child { (rep_1, rep_2) } else { (rep_2, rep_1) };
        let child_context = self.context_of(child_rep)?;
        let child_length = self.length_unit(child_context)?;
        let parent_context = self.context_of(parent_rep)?;
        let parent_length = self.length_unit(parent_context)?;
        let op_type = self.type_of(op);
        if op_type == "ITEM_DEFINED_TRANSFORMATION" {
            let idt = self.get(op)?;
            let ir = &idt.records[0];
            let item_1 = reference_arg(&idt, ir, 2, "transform_item_1")?;
            let item_2 = reference_arg(&idt, ir, 3, "transform_item_2")?;
            let (child_item, parent_item) = if rep_1_is_child { (item_1, item_2) } else { (item_2, item_1) };
            let child_frame = self.frame(child_item, child_length).map_err(|e| e.within(idt.line, idt.id))?;
            let parent_frame = self.frame(parent_item, parent_length).map_err(|e| e.within(idt.line, idt.id))?;
            Ok(parent_frame.compose(&child_frame.inverse()))
        } else if has_record(op_type, "CARTESIAN_TRANSFORMATION_OPERATOR_3D") {
            // The operator maps rep_1's coordinates into rep_2's, its origin a length of
            // rep_2's context.
            let length = if rep_1_is_child { parent_length } else { child_length };
            let t = self.operator(op, length)?;
            Ok(if rep_1_is_child { t } else { t.inverse() })
        } else {
            Err(field_error(
                &inst,
                "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION.transformation_operator",
                format!(
                    "#{op} is a {op_type}, not an ITEM_DEFINED_TRANSFORMATION or CARTESIAN_TRANSFORMATION_OPERATOR_3D"
                ),
            ))
        }
    }

    /// The representations of a product definition's shape (gathered once).
    fn shape_reps(&mut self, pd: u64) -> Result<Vec<u64>> {
        Ok(self.gather_definition(pd)?.reps.clone())
    }

    /// A product definition's shape: its representations, geometry items, and the
    /// products its mapped items place.
    fn gather_definition(&mut self, pd: u64) -> Result<&Gathered> {
        if !self.gathered.contains_key(&pd) {
            let roots = self.shapes.get(&pd).cloned().unwrap_or_default();
            let mut g = Gathered::default();
            self.gather(&roots, RigidTransform::IDENTITY, Some(pd), 0, &mut g)?;
            self.gathered.insert(pd, g);
        }
        Ok(&self.gathered[&pd])
    }

    /// Collects into `g` the items of the representations `roots` and of those related to
    /// them in the same space, placed by `placement`, following mapped items (`depth` deep
    /// in them). A representation that is another product's shape is not followed: a
    /// mapped item that places one is an occurrence of that product.
    fn gather(
        &mut self,
        roots: &[u64],
        placement: RigidTransform,
        owner: Option<u64>,
        depth: usize,
        g: &mut Gathered,
    ) -> Result<()> {
        let mut seen = HashSet::new();
        let mut queue = roots.to_vec();
        while let Some(rep) = queue.pop() {
            if !seen.insert(rep) {
                continue;
            }
            if depth == 0 {
                g.reps.push(rep);
            }
            let (items, context) = self.representation(rep)?;
            for item in items {
                let t = self.type_of(item);
                if let Some(kind) = ItemKind::of_type(t) {
                    // Geometry: the geometry readers mark it.
                    g.items.push(ShapeItem { id: item, kind, representation: rep, context, placement });
                } else if has_record(t, "MAPPED_ITEM") {
                    self.mapped_item(item, context, placement, owner, depth, g)?;
                }
            }
            for (relationship, other) in self.same_space.get(&rep).cloned().unwrap_or_default() {
                match self.owner.get(&other) {
                    Some(o) if Some(*o) != owner => self.out.notes.push(format!(
                        "#{relationship}: relates #{rep} to #{other}, the shape of another product (#{o}), without a transformation: not followed"
                    )),
                    _ => {
                        self.read.insert(relationship);
                        queue.push(other);
                    }
                }
            }
        }
        Ok(())
    }

    /// A `MAPPED_ITEM` inside a representation of context `context`.
    fn mapped_item(
        &mut self,
        item: u64,
        context: u64,
        placement: RigidTransform,
        owner: Option<u64>,
        depth: usize,
        g: &mut Gathered,
    ) -> Result<()> {
        let inst = self.get(item)?;
        let r = record(&inst, "MAPPED_ITEM")?;
        let source = reference_arg(&inst, r, 1, "mapping_source")?;
        let target = reference_arg(&inst, r, 2, "mapping_target")?;
        let map = self.get(source)?;
        let mr = record(&map, "REPRESENTATION_MAP")?;
        let origin = reference_arg(&map, mr, 0, "mapping_origin")?;
        let mapped = reference_arg(&map, mr, 1, "mapped_representation")?;
        let mapped_context = self.context_of(mapped)?;
        let origin_length = self.length_unit(mapped_context)?;
        let target_length = self.length_unit(context)?;
        let origin_frame = self.frame(origin, origin_length).map_err(|e| e.within(map.line, map.id))?;
        let target_frame = self.frame(target, target_length).map_err(|e| e.within(inst.line, inst.id))?;
        let t = placement.compose(&target_frame.compose(&origin_frame.inverse()));
        match self.owner.get(&mapped) {
            Some(&other) if Some(other) != owner => {
                let name = text(r.params.first());
                let name = if name.trim().is_empty() {
                    self.products.get(&other).map(|p| p.0.clone()).unwrap_or_default()
                } else {
                    name
                };
                g.mapped.push(MappedOccurrence { item, name, child: other, placement: t });
                Ok(())
            }
            _ => {
                if depth >= MAX_DEPTH {
                    return Err(field_error(
                        &inst,
                        "MAPPED_ITEM.mapping_source",
                        format!("mapped items nested more than {MAX_DEPTH} deep (a representation that maps itself?)"),
                    ));
                }
                self.gather(&[mapped], t, owner, depth + 1, g)
            }
        }
    }

    /// The part of a product definition, made on first use (None when its shape holds no
    /// geometry).
    fn part(&mut self, pd: u64) -> Result<Option<usize>> {
        if let Some(p) = self.part_of.get(&pd) {
            return Ok(*p);
        }
        let g = self.gather_definition(pd)?.clone();
        let part = if g.items.is_empty() {
            None
        } else {
            let (name, product) = self.products.get(&pd).cloned().unwrap_or_default();
            self.out.parts.push(Part {
                product_definition: Some(pd),
                product,
                name,
                representations: g.reps.clone(),
                items: g.items.clone(),
            });
            Some(self.out.parts.len() - 1)
        };
        self.part_of.insert(pd, part);
        Ok(part)
    }

    /// Instances of `pd` placed by `placement`, reached through `path`; `stack` holds the
    /// product definitions above it.
    fn walk(&mut self, pd: u64, placement: RigidTransform, path: Vec<Occurrence>, stack: &mut Vec<u64>) -> Result<()> {
        self.walked.insert(pd);
        self.steps += 1;
        if self.steps > 4 * MAX_INSTANCES {
            return Err(StepError::plain(format!(
                "the assembly expands to more than {} occurrences",
                4 * MAX_INSTANCES
            )));
        }
        if let Some(part) = self.part(pd)? {
            if self.out.instances.len() >= MAX_INSTANCES {
                return Err(StepError::plain(format!(
                    "the assembly expands to more than {MAX_INSTANCES} part instances"
                )));
            }
            self.out.instances.push(PartInstance { part, path: path.clone(), placement });
        }
        let mut mapped = self.gather_definition(pd)?.mapped.clone();
        let children: Vec<Nauo> =
            self.components.get(&pd).map_or_else(Vec::new, |k| k.iter().map(|&k| self.nauos[k].clone()).collect());
        let mut occurrences: Vec<(Occurrence, u64, RigidTransform)> = Vec::new();
        for nauo in children {
            let relations = self.placements.get(&nauo.id).cloned().unwrap_or_default();
            let occurrence = Occurrence { id: nauo.id, name: nauo.name.clone() };
            if let Some(&relation) = relations.first() {
                if relations.len() > 1 {
                    self.out.notes.push(format!(
                        "#{}: {} placements (CONTEXT_DEPENDENT_SHAPE_REPRESENTATION); the first, #{relation}, is used",
                        nauo.id,
                        relations.len()
                    ));
                }
                let t = self.occurrence_placement(&nauo, relation)?;
                if t == RigidTransform::IDENTITY && self.type_of(relation) == "SHAPE_REPRESENTATION_RELATIONSHIP" {
                    // Placed by a mapped item of the parent's shape, if one places the child.
                    if let Some(k) = mapped.iter().position(|m| m.child == nauo.child) {
                        let m = mapped.remove(k);
                        occurrences.push((occurrence, nauo.child, m.placement));
                        continue;
                    }
                }
                occurrences.push((occurrence, nauo.child, t));
            } else if let Some(k) = mapped.iter().position(|m| m.child == nauo.child) {
                let m = mapped.remove(k);
                occurrences.push((occurrence, nauo.child, m.placement));
            } else {
                self.out.notes.push(format!(
                    "#{}: no CONTEXT_DEPENDENT_SHAPE_REPRESENTATION or MAPPED_ITEM places this occurrence: placed at the identity",
                    nauo.id
                ));
                occurrences.push((occurrence, nauo.child, RigidTransform::IDENTITY));
            }
        }
        for m in mapped {
            occurrences.push((Occurrence { id: m.item, name: m.name }, m.child, m.placement));
        }
        for (occurrence, child, t) in occurrences {
            if stack.contains(&child) {
                return Err(StepError::at(
                    self.file.line_of(occurrence.id),
                    Some(occurrence.id),
                    format!(
                        "uses #{child}, which contains this occurrence's assembly #{pd}: an assembly inside itself"
                    ),
                ));
            }
            if stack.len() >= MAX_DEPTH {
                return Err(StepError::at(
                    self.file.line_of(occurrence.id),
                    Some(occurrence.id),
                    format!("assemblies nested more than {MAX_DEPTH} deep"),
                ));
            }
            let mut p = path.clone();
            p.push(occurrence);
            stack.push(child);
            self.walk(child, placement.compose(&t), p, stack)?;
            stack.pop();
        }
        Ok(())
    }

    /// Representations with geometry items that no product reaches: a part and an
    /// instance each (those that other such shape representations map are reached
    /// through them, and are parts only for what those leave).
    fn loose_representations(&mut self) -> Result<()> {
        let mut reached: HashSet<u64> = self.out.parts.iter().flat_map(|p| p.items.iter().map(|i| i.id)).collect();
        // Items reached only through mapped items placing other products, never
        // instanced, are reached too.
        for g in self.gathered.values() {
            reached.extend(g.items.iter().map(|i| i.id));
        }
        let mut holding = Vec::new();
        let mut mapped_targets = HashSet::new();
        for id in self.file.ids() {
            let t = self.type_of(id);
            if has_record(t, "REPRESENTATION_MAP") {
                if let Ok(inst) = self.file.get(id) {
                    if let Some(Param::Reference(rep)) = inst.records[0].params.get(1) {
                        mapped_targets.insert(*rep);
                    }
                }
                continue;
            }
            if !(t.ends_with("REPRESENTATION") || t.starts_with('(') && t.contains("REPRESENTATION ")) {
                continue;
            }
            let Ok(inst) = self.file.get(id) else { continue };
            let Some(r) = representation_record(&inst) else { continue };
            let Some(Param::List(items)) = r.params.get(1) else { continue };
            // Geometry of its own not reached yet, or mapped items of a shape
            // representation (presentations map shapes too, to show them).
            let shape = t.contains("SHAPE_REPRESENTATION");
            let geometry = items.iter().any(|p| match p {
                Param::Reference(item) => {
                    let kind = self.type_of(*item);
                    ItemKind::of_type(kind).is_some() && !reached.contains(item)
                        || shape && has_record(kind, "MAPPED_ITEM")
                }
                _ => false,
            });
            if geometry {
                holding.push(id);
            }
        }
        // Mapped representations after the ones that map them; whatever is still not
        // reached then is a root of its own.
        holding.sort_by_key(|id| (mapped_targets.contains(id), *id));
        for rep in holding {
            let mut g = Gathered::default();
            self.gather(&[rep], RigidTransform::IDENTITY, None, 0, &mut g)?;
            g.items.retain(|i| !reached.contains(&i.id));
            if g.items.is_empty() {
                continue;
            }
            reached.extend(g.items.iter().map(|i| i.id));
            let inst = self.get(rep)?;
            let name = representation_record(&inst).map(|r| text(r.params.first())).unwrap_or_default();
            let name = if name.trim().is_empty() { format!("#{rep}") } else { name };
            self.out.parts.push(Part {
                product_definition: None,
                product: None,
                name: name.clone(),
                representations: g.reps,
                items: g.items,
            });
            let part = self.out.parts.len() - 1;
            self.out.instances.push(PartInstance {
                part,
                path: vec![Occurrence { id: rep, name }],
                placement: RigidTransform::IDENTITY,
            });
            self.part_of.insert(rep, Some(part));
        }
        Ok(())
    }
}

/// x · y.
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// ISO 10303-42 `build_axes` from a unit axis z and an optional unit reference direction:
/// x = the part of the reference orthogonal to z (`first_proj_axis`: without one,
/// (1, 0, 0), or (0, 0, 1) where z is along (1, 0, 0)); y = z × x.
fn build_axes(z: [f64; 3], reference: Option<[f64; 3]>) -> splinekit::Result<splinekit::axes::OrthonormalAxes> {
    let reference = reference.unwrap_or(if z[1] == 0.0 && z[2] == 0.0 { [0.0, 0.0, 1.0] } else { [1.0, 0.0, 0.0] });
    splinekit::axes::OrthonormalAxes::build(z, reference)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file_text(data: &str) -> String {
        format!(
            "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\n\
             FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n{data}\nENDSEC;\nEND-ISO-10303-21;\n"
        )
    }

    fn file(data: &str) -> StepFile {
        StepFile::from_bytes(file_text(data).into_bytes()).expect("a valid test file")
    }

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        (0..3).all(|k| (a[k] - b[k]).abs() < 1e-12)
    }

    #[test]
    fn transforms_compose_and_invert() {
        let t = RigidTransform::frame([1.0, 2.0, 3.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        assert!(close(t.apply([1.0, 0.0, 0.0]), [1.0, 3.0, 3.0]));
        let back = t.inverse().compose(&t);
        assert!(close(back.apply([0.3, -2.0, 5.0]), [0.3, -2.0, 5.0]));
        let twice = t.compose(&t);
        assert!(close(twice.apply([0.0; 3]), t.apply(t.apply([0.0; 3]))));
    }

    /// Two products: an assembly in inches holding a millimetre part twice, once by an
    /// assembly occurrence (rep_1 the component) and once with rep_1 the assembly.
    const ASSEMBLY: &str = "\
#1=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));
#2=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.CENTI.,.METRE.));
#3=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(2.54),#2);
#4=(CONVERSION_BASED_UNIT('INCH',#3)LENGTH_UNIT()NAMED_UNIT(*));
#5=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNIT_ASSIGNED_CONTEXT((#1))REPRESENTATION_CONTEXT('mm','3D'));
#6=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNIT_ASSIGNED_CONTEXT((#4))REPRESENTATION_CONTEXT('in','3D'));
#10=PRODUCT('asm','Assembly','',());
#11=PRODUCT_DEFINITION_FORMATION('','',#10);
#12=PRODUCT_DEFINITION('design','',#11,$);
#13=PRODUCT_DEFINITION_SHAPE('','',#12);
#14=SHAPE_DEFINITION_REPRESENTATION(#13,#15);
#15=SHAPE_REPRESENTATION('',(#16,#17,#18),#6);
#16=AXIS2_PLACEMENT_3D('',#40,$,$);
#17=AXIS2_PLACEMENT_3D('',#41,#42,#43);
#18=AXIS2_PLACEMENT_3D('',#44,$,$);
#20=PRODUCT('bolt','','',());
#21=PRODUCT_DEFINITION_FORMATION('','',#20);
#22=PRODUCT_DEFINITION('design','',#21,$);
#23=PRODUCT_DEFINITION_SHAPE('','',#22);
#24=SHAPE_DEFINITION_REPRESENTATION(#23,#25);
#25=SHAPE_REPRESENTATION('',(#26),#5);
#26=AXIS2_PLACEMENT_3D('',#45,$,$);
#27=ADVANCED_BREP_SHAPE_REPRESENTATION('',(#28),#5);
#28=MANIFOLD_SOLID_BREP('body',#29);
#29=CLOSED_SHELL('',());
#30=SHAPE_REPRESENTATION_RELATIONSHIP('','',#25,#27);
#31=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N1','',$,#12,#22,$);
#32=PRODUCT_DEFINITION_SHAPE('','',#31);
#33=(REPRESENTATION_RELATIONSHIP('','',#25,#15)REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#34)SHAPE_REPRESENTATION_RELATIONSHIP());
#34=ITEM_DEFINED_TRANSFORMATION('','',#26,#17);
#35=CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#33,#32);
#36=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N2','second',$,#12,#22,$);
#37=PRODUCT_DEFINITION_SHAPE('','',#36);
#38=(REPRESENTATION_RELATIONSHIP('','',#15,#25)REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#39)SHAPE_REPRESENTATION_RELATIONSHIP());
#39=ITEM_DEFINED_TRANSFORMATION('','',#18,#26);
#46=CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#38,#37);
#40=CARTESIAN_POINT('',(0.,0.,0.));
#41=CARTESIAN_POINT('',(1.,0.,0.));
#42=DIRECTION('',(0.,0.,1.));
#43=DIRECTION('',(0.,1.,0.));
#44=CARTESIAN_POINT('',(0.,0.,2.));
#45=CARTESIAN_POINT('',(0.,0.,0.));
";

    #[test]
    fn an_inch_assembly_places_a_millimetre_part_twice() {
        let s = read_product_structure(&file(ASSEMBLY)).unwrap();
        assert_eq!(s.parts.len(), 1, "{s:?}");
        assert_eq!(s.parts[0].name, "bolt");
        assert_eq!(s.parts[0].items.len(), 1);
        assert_eq!(s.parts[0].items[0].id, 28);
        assert_eq!(s.instances.len(), 2);
        let names: Vec<Vec<&str>> =
            s.instances.iter().map(|i| i.path.iter().map(|o| o.name.as_str()).collect()).collect();
        assert_eq!(names, vec![vec!["Assembly", "N1"], vec!["Assembly", "second"]]);
        // N1: the part's origin frame onto (1 in, 0, 0) with x along y: a quarter turn.
        let a = s.instances[0].placement;
        assert!(close(a.apply([0.0; 3]), [25.4, 0.0, 0.0]), "{a:?}");
        assert!(close(a.apply([1.0, 0.0, 0.0]), [25.4, 1.0, 0.0]), "{a:?}");
        // N2 (rep_1 the assembly): onto (0, 0, 2 in).
        let b = s.instances[1].placement;
        assert!(close(b.apply([1.0, 0.0, 0.0]), [1.0, 0.0, 50.8]), "{b:?}");
        assert!(s.notes.is_empty(), "{:?}", s.notes);
        for id in [10, 12, 13, 14, 22, 30, 31, 32, 33, 34, 35, 36, 38, 39, 46, 17, 41, 5, 6] {
            assert!(s.entities.contains(&id), "#{id} read");
        }
        // Geometry is for the geometry readers to mark.
        assert!(!s.entities.contains(&28) && !s.entities.contains(&29));
    }

    #[test]
    fn an_assembly_inside_itself_is_refused_naming_the_occurrence() {
        // The bolt also holds the assembly: bolt → asm → bolt.
        let cyclic = format!("{ASSEMBLY}#50=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N3','',$,#22,#12,$);\n");
        let e = read_product_structure(&file(&cyclic)).unwrap_err();
        assert!(e.message.contains("cycle") && e.location.entity.is_some(), "{e}");
        // The same beside a product of its own, which is a root.
        let beside = format!(
            "{cyclic}#60=PRODUCT('loose','','',());\n#61=PRODUCT_DEFINITION_FORMATION('','',#60);\n\
             #62=PRODUCT_DEFINITION('design','',#61,$);\n"
        );
        let e = read_product_structure(&file(&beside)).unwrap_err();
        assert!(e.message.contains("cycle") && e.location.entity.is_some(), "{e}");
        let selfish = format!("{ASSEMBLY}#50=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N3','',$,#22,#22,$);\n");
        let e = read_product_structure(&file(&selfish)).unwrap_err();
        assert_eq!(e.location.entity, Some(50), "{e}");
    }

    #[test]
    fn a_zero_direction_and_a_wrong_reference_are_named() {
        let zero = ASSEMBLY.replace("#42=DIRECTION('',(0.,0.,1.))", "#42=DIRECTION('',(0.,0.,0.))");
        let e = read_product_structure(&file(&zero)).unwrap_err();
        assert_eq!(e.location.entity, Some(42), "{e}");
        assert!(e.message.contains("direction_ratios"), "{e}");
        let wrong = ASSEMBLY.replace(
            "#31=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N1','',$,#12,#22,$)",
            "#31=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N1','',$,#12,#40,$)",
        );
        let e = read_product_structure(&file(&wrong)).unwrap_err();
        assert_eq!(e.location.entity, Some(31), "{e}");
        assert!(e.message.contains("related_product_definition"), "{e}");
        let nan = ASSEMBLY.replace("#41=CARTESIAN_POINT('',(1.,0.,0.))", "#41=CARTESIAN_POINT('',(1.,0.,'x'))");
        let e = read_product_structure(&file(&nan)).unwrap_err();
        assert_eq!(e.location.entity, Some(41), "{e}");
    }

    #[test]
    fn any_reference_pointed_anywhere_is_an_error_or_a_reading_never_a_panic() {
        // Every reference of the test assembly replaced in turn by one to an entity of each
        // kind: a unit, a context, a product, a placement, a point, a direction, a solid.
        let refs: Vec<(usize, usize)> = ASSEMBLY
            .match_indices('#')
            .filter(|(k, _)| ASSEMBLY[..*k].ends_with([',', '(']))
            .map(|(k, _)| (k, k + 1 + ASSEMBLY[k + 1..].find(|c: char| !c.is_ascii_digit()).unwrap_or(0)))
            .collect();
        assert!(refs.len() > 40, "{}", refs.len());
        for (start, end) in refs {
            for target in ["#1", "#5", "#10", "#12", "#17", "#28", "#31", "#41", "#42", "#33"] {
                let text = format!("{}{target}{}", &ASSEMBLY[..start], &ASSEMBLY[end..]);
                let data = file_text(&text);
                // A reference cycle is refused when the file is opened.
                let Ok(f) = StepFile::from_bytes(data.into_bytes()) else { continue };
                let _ = read_product_structure(&f);
                let _ = crate::styles::read_styles(&f);
                let _ = crate::structure::structure_entities(&f);
            }
        }
        // A non-finite number stops at the reader, before any structure is read.
        let huge = ASSEMBLY.replace("#41=CARTESIAN_POINT('',(1.,0.,0.))", "#41=CARTESIAN_POINT('',(1.E400,0.,0.))");
        let e = StepFile::from_bytes(file_text(&huge).into_bytes()).unwrap_err();
        assert!(e.message.contains("out of range"), "{e}");
    }

    #[test]
    fn an_occurrence_without_placement_is_noted_and_placed_at_the_identity() {
        let bare = ASSEMBLY.replace("#35=CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#33,#32);\n", "");
        let s = read_product_structure(&file(&bare)).unwrap();
        assert_eq!(s.instances.len(), 2);
        assert_eq!(s.instances[0].placement, RigidTransform::IDENTITY);
        assert!(s.notes.iter().any(|n| n.contains("#31")), "{:?}", s.notes);
    }

    #[test]
    fn a_mapped_item_places_a_representation_and_loose_geometry_is_a_part() {
        let data = "\
#5=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNIT_ASSIGNED_CONTEXT((#1))REPRESENTATION_CONTEXT('','3D'));
#1=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.METRE.));
#10=SHAPE_REPRESENTATION('top',(#11),#5);
#11=MAPPED_ITEM('copy',#12,#13);
#12=REPRESENTATION_MAP(#14,#15);
#13=(CARTESIAN_TRANSFORMATION_OPERATOR('','',#20,#21,#22,1.)CARTESIAN_TRANSFORMATION_OPERATOR_3D(#23)FUNCTIONALLY_DEFINED_TRANSFORMATION('','')GEOMETRIC_REPRESENTATION_ITEM()REPRESENTATION_ITEM(''));
#14=AXIS2_PLACEMENT_3D('',#24,$,$);
#15=ADVANCED_BREP_SHAPE_REPRESENTATION('body',(#16,#14),#5);
#16=MANIFOLD_SOLID_BREP('',#17);
#17=CLOSED_SHELL('',());
#20=DIRECTION('',(0.,1.,0.));
#21=DIRECTION('',(-1.,0.,0.));
#22=CARTESIAN_POINT('',(0.,0.,1.));
#23=DIRECTION('',(0.,0.,1.));
#24=CARTESIAN_POINT('',(0.,0.,0.));
";
        let s = read_product_structure(&file(data)).unwrap();
        assert_eq!(s.parts.len(), 1, "{s:?}");
        assert_eq!(s.parts[0].name, "top");
        let item = &s.parts[0].items[0];
        assert_eq!((item.id, item.representation, item.context), (16, 15, 5));
        // One metre up, a quarter turn about z.
        assert!(close(item.placement.apply([1.0, 0.0, 0.0]), [0.0, 1.0, 1000.0]), "{:?}", item.placement);
        assert_eq!(s.instances.len(), 1);
        let mirrored = data.replace("#21=DIRECTION('',(-1.,0.,0.))", "#21=DIRECTION('',(1.,0.,0.))");
        let e = read_product_structure(&file(&mirrored)).unwrap_err();
        assert!(e.message.contains("mirrors"), "{e}");
        let scaled = data.replace("#22,1.)", "#22,2.)");
        let e = read_product_structure(&file(&scaled)).unwrap_err();
        assert!(e.message.contains("scale"), "{e}");
    }

    #[test]
    fn an_assembly_inside_itself_below_a_root_is_refused_naming_the_occurrence() {
        // A root uses the assembly, and the bolt holds the assembly: root → asm → bolt → asm.
        let cyclic = format!(
            "{ASSEMBLY}#50=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N3','',$,#22,#12,$);\n\
             #60=PRODUCT('root','','',());\n#61=PRODUCT_DEFINITION_FORMATION('','',#60);\n\
             #62=PRODUCT_DEFINITION('design','',#61,$);\n#63=NEXT_ASSEMBLY_USAGE_OCCURRENCE('N4','',$,#62,#12,$);\n"
        );
        let e = read_product_structure(&file(&cyclic)).unwrap_err();
        assert_eq!(e.location.entity, Some(50), "{e}");
        assert!(e.message.contains("inside itself"), "{e}");
    }
}
