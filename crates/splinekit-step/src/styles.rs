//! Colours of a STEP file's solids, shells, faces and representations.
//!
//! # The STEP structure read
//!
//! ISO 10303-46 (visual presentation), as AP214 and AP242 use it:
//!
//! ```text
//! STYLED_ITEM(name, styles, item)                 item: a solid, shell, face, curve,
//!   OVER_RIDING_STYLED_ITEM(…, over_ridden_style)       MAPPED_ITEM or representation
//!     CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM(…, style_context)
//! styles: PRESENTATION_STYLE_ASSIGNMENT((style, …))   (or …_BY_CONTEXT)
//!   SURFACE_STYLE_USAGE(side, SURFACE_SIDE_STYLE(name, (element, …)))
//!     SURFACE_STYLE_FILL_AREA(FILL_AREA_STYLE(name, (FILL_AREA_STYLE_COLOUR(name, colour), …)))
//!     SURFACE_STYLE_RENDERING(method, colour)
//!     SURFACE_STYLE_RENDERING_WITH_PROPERTIES(method, colour,
//!                                             (SURFACE_STYLE_TRANSPARENT(t), …))
//!   CURVE_STYLE(name, font, width, colour)
//!   NULL_STYLE(.NULL.)
//! colour: COLOUR_RGB(name, red, green, blue) | DRAUGHTING_PRE_DEFINED_COLOUR(name)
//! ```
//!
//! Styled items are grouped by presentation representations,
//! `MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION(name, items, context)` and
//! `DRAUGHTING_MODEL(name, items, context)`; each [`Style`] lists the groups it is in.
//!
//! # Colours and precedence
//!
//! A style's surface colour is its fill-area colour, else its rendering colour; alpha is
//! 1 − the transparency of `SURFACE_STYLE_TRANSPARENT` (opaque without one). Where a
//! style has usages for both sides, `.BOTH.` or `.POSITIVE.` (the side the surface normal
//! points to) is taken over `.NEGATIVE.`. Components are the file's numbers in [0, 1] (in
//! practice sRGB: OpenCASCADE reads them as such). Pre-defined colours are ISO 10303-46's
//! eight: red, green, blue, yellow, magenta, cyan, black, white.
//!
//! Several styles of one item: an `OVER_RIDING_STYLED_ITEM` wins over the style it
//! overrides (and a chain of them, the last), a context-dependent one included; between
//! styles of equal rank, the later instance (greater `#id`) wins. A face's colour wins over
//! its shell's, a shell's over its solid's, a solid's over its representation's or mapped
//! item's: [`Styles::effective`] takes the ids from the most specific down.
//!
//! Styles are decorative: one that cannot be read (a missing reference, a colour out of
//! range, a kind of style not read here) is left out and said in [`Styles::skipped`], and
//! the rest is read.

use std::collections::{BTreeSet, HashMap, HashSet};

use crate::assembly::has_record;
use crate::part21::{Instance, Param, StepFile};

/// A colour with opacity, every component in [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rgba {
    /// Red.
    pub red: f64,
    /// Green.
    pub green: f64,
    /// Blue.
    pub blue: f64,
    /// Opacity: 1 opaque, 0 invisible.
    pub alpha: f64,
}

impl Rgba {
    /// An opaque colour.
    pub const fn opaque(red: f64, green: f64, blue: f64) -> Rgba {
        Rgba { red, green, blue, alpha: 1.0 }
    }

    /// The components as an array (red, green, blue, alpha).
    pub fn to_array(self) -> [f64; 4] {
        [self.red, self.green, self.blue, self.alpha]
    }
}

/// What a styled item styles, by the target's entity type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StyledKind {
    /// `ADVANCED_FACE`, `FACE_SURFACE`, `FACE`.
    Face,
    /// `CLOSED_SHELL`, `OPEN_SHELL`, `ORIENTED_CLOSED_SHELL`, `ORIENTED_OPEN_SHELL`.
    Shell,
    /// `MANIFOLD_SOLID_BREP`, `BREP_WITH_VOIDS`, `FACETED_BREP`,
    /// `SHELL_BASED_SURFACE_MODEL`.
    Solid,
    /// A `MAPPED_ITEM` (a placed copy of a representation).
    MappedItem,
    /// A representation (a whole shape; context-dependent overrides style these).
    Representation,
    /// Anything else: curves, points, geometric sets.
    Other,
}

impl StyledKind {
    /// The kind of an entity type name.
    pub fn of_type(type_name: &str) -> StyledKind {
        let any = |names: &[&str]| names.iter().any(|n| has_record(type_name, n));
        if any(&["ADVANCED_FACE", "FACE_SURFACE", "FACE", "ORIENTED_FACE"]) {
            StyledKind::Face
        } else if any(&["CLOSED_SHELL", "OPEN_SHELL", "ORIENTED_CLOSED_SHELL", "ORIENTED_OPEN_SHELL"]) {
            StyledKind::Shell
        } else if any(&["MANIFOLD_SOLID_BREP", "BREP_WITH_VOIDS", "FACETED_BREP", "SHELL_BASED_SURFACE_MODEL"]) {
            StyledKind::Solid
        } else if any(&["MAPPED_ITEM"]) {
            StyledKind::MappedItem
        } else if type_name.ends_with("REPRESENTATION")
            || type_name.starts_with('(') && type_name.contains("REPRESENTATION ")
        {
            StyledKind::Representation
        } else {
            StyledKind::Other
        }
    }
}

/// One styled item as read.
#[derive(Debug, Clone, PartialEq)]
pub struct Style {
    /// The `STYLED_ITEM` (or over-riding one) `#id`.
    pub styled_item: u64,
    /// The item it styles.
    pub item: u64,
    /// What the item is.
    pub kind: StyledKind,
    /// The surface colour, if the styles give one.
    pub surface: Option<Rgba>,
    /// The curve colour (`CURVE_STYLE`), if the styles give one.
    pub curve: Option<Rgba>,
    /// The style it overrides (`OVER_RIDING_STYLED_ITEM.over_ridden_style`).
    pub overrides: Option<u64>,
    /// Where it applies (`CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM.style_context`: the
    /// occurrences' `CONTEXT_DEPENDENT_SHAPE_REPRESENTATION`s, representations or items);
    /// empty for a style that applies everywhere.
    pub context: Vec<u64>,
    /// The presentation representations that list it (`MECHANICAL_DESIGN_…` or
    /// `DRAUGHTING_MODEL`).
    pub groups: Vec<u64>,
}

/// The styles of a file (see the module documentation).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Styles {
    /// Every styled item read, by increasing `#id`.
    pub styles: Vec<Style>,
    /// Each styled item's surface colour under the precedence of over-riding styles: what
    /// [`Styles::colour`] answers.
    pub colours: HashMap<u64, Rgba>,
    /// What was left out, and why.
    pub skipped: Vec<String>,
    /// Every entity read: styled items, style assignments, styles, colours, groups.
    pub entities: BTreeSet<u64>,
}

impl Styles {
    /// The surface colour given to `item` itself.
    pub fn colour(&self, item: u64) -> Option<Rgba> {
        self.colours.get(&item).copied()
    }

    /// The colour that shows on a face: the first of `items` that has one, most specific
    /// first (`[face, shell, solid, representation]`).
    pub fn effective(&self, items: &[u64]) -> Option<Rgba> {
        items.iter().find_map(|i| self.colour(*i))
    }
}

/// Reads every styled item's colours (see the module documentation).
pub fn read_styles(file: &StepFile) -> Styles {
    let mut r = Reader { file, read: HashSet::new(), skipped: Vec::new() };
    let mut styles = Vec::new();
    let mut groups: HashMap<u64, Vec<u64>> = HashMap::new();
    let mut group_reps = Vec::new();
    for id in file.ids() {
        let t = file.type_of(id).unwrap_or("");
        if is_styled_item(t) {
            match r.styled_item(id) {
                Ok(Some(s)) => styles.push(s),
                Ok(None) => {}
                Err(reason) => r.skipped.push(format!("#{id}: {reason}")),
            }
        } else if has_record(t, "MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION")
            || has_record(t, "DRAUGHTING_MODEL")
        {
            group_reps.push(id);
        }
    }
    let styled: HashSet<u64> = styles.iter().map(|s| s.styled_item).collect();
    for g in group_reps {
        let Ok(inst) = file.get(g) else { continue };
        let Some(rec) = inst.records.iter().find(|x| x.params.len() >= 3) else { continue };
        let Some(Param::List(items)) = rec.params.get(1) else { continue };
        let items: Vec<u64> =
            items.iter().filter_map(|p| if let Param::Reference(i) = p { Some(*i) } else { None }).collect();
        for i in &items {
            if styled.contains(i) {
                groups.entry(*i).or_default().push(g);
            }
        }
        // A group of nothing but styled items read here is read; one that also holds
        // annotations (PMI) is left for the census.
        if !items.is_empty() && items.iter().all(|i| styled.contains(i)) {
            r.read.insert(g);
            if let Some(Param::Reference(context)) = rec.params.get(2) {
                r.read.insert(*context);
            }
        }
    }
    for s in &mut styles {
        s.groups = groups.remove(&s.styled_item).unwrap_or_default();
    }
    let colours = precedence(&styles);
    Styles { styles, colours, skipped: r.skipped, entities: r.read.into_iter().collect() }
}

/// Whether an entity type is a styled item read here (annotation occurrences, also
/// styled items, are PMI and not read).
fn is_styled_item(type_name: &str) -> bool {
    (has_record(type_name, "STYLED_ITEM")
        || has_record(type_name, "OVER_RIDING_STYLED_ITEM")
        || has_record(type_name, "CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM"))
        && !type_name.contains("ANNOTATION")
}

/// The winning surface colour of each item: the greatest override rank, then the greatest
/// `#id`.
fn precedence(styles: &[Style]) -> HashMap<u64, Rgba> {
    let by_id: HashMap<u64, &Style> = styles.iter().map(|s| (s.styled_item, s)).collect();
    let rank = |s: &Style| {
        let mut n = 0usize;
        let mut next = s.overrides;
        // Bounded: a chain of overrides cannot be longer than the styles.
        while let Some(o) = next {
            n += 1;
            if n > styles.len() {
                break;
            }
            next = by_id.get(&o).and_then(|p| p.overrides);
        }
        n
    };
    let mut best: HashMap<u64, (usize, u64, Rgba)> = HashMap::new();
    for s in styles {
        let Some(c) = s.surface else { continue };
        let key = (rank(s), s.styled_item);
        match best.get(&s.item) {
            Some((r, id, _)) if (*r, *id) >= key => {}
            _ => {
                best.insert(s.item, (key.0, key.1, c));
            }
        }
    }
    best.into_iter().map(|(item, (_, _, c))| (item, c)).collect()
}

/// Why a style was not read.
type Reason = String;

struct Reader<'a> {
    file: &'a StepFile,
    read: HashSet<u64>,
    skipped: Vec<String>,
}

/// The colours one presentation style assignment gives.
#[derive(Debug, Clone, Copy, Default)]
struct Found {
    /// (colour, whether from the negative side only).
    surface: Option<(Rgba, bool)>,
    curve: Option<Rgba>,
}

impl Reader<'_> {
    fn get(&mut self, id: u64) -> std::result::Result<Instance, Reason> {
        let inst = self.file.get(id).map_err(|e| e.to_string())?;
        self.read.insert(id);
        Ok(inst)
    }

    fn type_of(&self, id: u64) -> &str {
        self.file.type_of(id).unwrap_or("")
    }

    /// A styled item: its target, colours, override and context (None when it is not
    /// read here at all).
    fn styled_item(&mut self, id: u64) -> std::result::Result<Option<Style>, Reason> {
        let inst = self.get(id)?;
        // The simple subtypes list STYLED_ITEM's three attributes first; a complex
        // instance has them in its STYLED_ITEM record.
        let base = inst.record("STYLED_ITEM").unwrap_or(&inst.records[0]);
        let styles = match base.params.get(1) {
            Some(Param::List(s)) => s.clone(),
            other => return Err(format!("STYLED_ITEM.styles: expected a list, got {other:?}")),
        };
        let item = match base.params.get(2) {
            Some(Param::Reference(i)) => *i,
            other => return Err(format!("STYLED_ITEM.item: expected a reference, got {other:?}")),
        };
        let (overrides, context) = match inst.record("OVER_RIDING_STYLED_ITEM") {
            Some(o) if inst.is_complex() => {
                let ctx = inst.record("CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM").and_then(|c| c.params.first());
                (o.params.first(), ctx)
            }
            _ => (inst.records[0].params.get(3), inst.records[0].params.get(4)),
        };
        let overrides = match overrides {
            Some(Param::Reference(o)) => Some(*o),
            _ => None,
        };
        let context = match context {
            Some(Param::List(c)) => {
                c.iter().filter_map(|p| if let Param::Reference(i) = p { Some(*i) } else { None }).collect()
            }
            Some(Param::Reference(c)) => vec![*c],
            _ => Vec::new(),
        };
        let mut found = Found::default();
        for s in styles {
            match s {
                Param::Reference(psa) => match self.assignment(psa) {
                    Ok(f) => {
                        found.curve = found.curve.or(f.curve);
                        found.surface = match (found.surface, f.surface) {
                            (Some((_, true)), Some(new)) | (None, Some(new)) => Some(new),
                            (old, _) => old,
                        };
                    }
                    Err(reason) => self.skipped.push(format!("#{id}: style #{psa}: {reason}")),
                },
                other => self.skipped.push(format!("#{id}: STYLED_ITEM.styles: {other:?} is not a style assignment")),
            }
        }
        let kind = StyledKind::of_type(self.type_of(item));
        Ok(Some(Style {
            styled_item: id,
            item,
            kind,
            surface: found.surface.map(|s| s.0),
            curve: found.curve,
            overrides,
            context,
            groups: Vec::new(),
        }))
    }

    /// A PRESENTATION_STYLE_ASSIGNMENT (or _BY_CONTEXT).
    fn assignment(&mut self, id: u64) -> std::result::Result<Found, Reason> {
        self.expect(id, &["PRESENTATION_STYLE_ASSIGNMENT", "PRESENTATION_STYLE_BY_CONTEXT"])?;
        let inst = self.get(id)?;
        let r = &inst.records[0];
        let styles = match r.params.first() {
            Some(Param::List(s)) => s.clone(),
            other => return Err(format!("PRESENTATION_STYLE_ASSIGNMENT.styles: expected a list, got {other:?}")),
        };
        let mut found = Found::default();
        for s in styles {
            let sid = match s {
                Param::Reference(sid) => sid,
                // NULL_STYLE(.NULL.): no style, deliberately.
                Param::Typed(name, _) if name == "NULL_STYLE" => continue,
                other => {
                    self.skipped.push(format!("#{id}: style {other:?} not read"));
                    continue;
                }
            };
            let t = self.type_of(sid).to_string();
            let result = match t.as_str() {
                "SURFACE_STYLE_USAGE" => self.surface_usage(sid).map(|c| {
                    if let Some(new) = c {
                        if found.surface.is_none_or(|(_, negative)| negative) {
                            found.surface = Some(new);
                        }
                    }
                }),
                "CURVE_STYLE" => self.curve_style(sid).map(|c| found.curve = found.curve.or(c)),
                "NULL_STYLE" => {
                    self.read.insert(sid);
                    Ok(())
                }
                other => Err(format!("a {other} style is not read")),
            };
            if let Err(reason) = result {
                self.skipped.push(format!("#{id}: style #{sid}: {reason}"));
            }
        }
        Ok(found)
    }

    /// SURFACE_STYLE_USAGE(side, style): the colour and whether it is for the negative
    /// side only.
    fn surface_usage(&mut self, id: u64) -> std::result::Result<Option<(Rgba, bool)>, Reason> {
        let inst = self.get(id)?;
        let p = &inst.records[0].params;
        let negative = matches!(p.first(), Some(Param::Enumeration(s)) if s == "NEGATIVE");
        let side_style = match p.get(1) {
            Some(Param::Reference(s)) => *s,
            other => return Err(format!("SURFACE_STYLE_USAGE.style: expected a reference, got {other:?}")),
        };
        self.expect(side_style, &["SURFACE_SIDE_STYLE"])?;
        let side = self.get(side_style)?;
        let elements = match side.records[0].params.get(1) {
            Some(Param::List(e)) => e.clone(),
            other => return Err(format!("SURFACE_SIDE_STYLE.styles: expected a list, got {other:?}")),
        };
        let (mut fill, mut rendering, mut alpha) = (None, None, 1.0);
        for e in elements {
            let Param::Reference(eid) = e else { continue };
            let t = self.type_of(eid).to_string();
            match t.as_str() {
                "SURFACE_STYLE_FILL_AREA" => fill = fill.or(self.fill_area(eid)?),
                "SURFACE_STYLE_RENDERING" | "SURFACE_STYLE_RENDERING_WITH_PROPERTIES" => {
                    let (c, a) = self.rendering(eid)?;
                    rendering = rendering.or(c);
                    alpha = a.unwrap_or(alpha);
                }
                // Boundaries, silhouettes, control grids, parameter lines: curves drawn on
                // a surface, not its colour.
                _ => {}
            }
        }
        Ok(fill.or(rendering).map(|c: Rgba| (Rgba { alpha, ..c }, negative)))
    }

    /// SURFACE_STYLE_FILL_AREA(FILL_AREA_STYLE(name, (FILL_AREA_STYLE_COLOUR(name, colour), …))).
    fn fill_area(&mut self, id: u64) -> std::result::Result<Option<Rgba>, Reason> {
        let inst = self.get(id)?;
        let Some(Param::Reference(fas)) = inst.records[0].params.first() else {
            return Err("SURFACE_STYLE_FILL_AREA.fill_area: expected a reference".into());
        };
        self.expect(*fas, &["FILL_AREA_STYLE"])?;
        let fas = self.get(*fas)?;
        let Some(Param::List(fill_styles)) = fas.records[0].params.get(1) else {
            return Err(format!("#{}: FILL_AREA_STYLE.fill_styles: expected a list", fas.id));
        };
        for f in fill_styles.clone() {
            let Param::Reference(fid) = f else { continue };
            if self.type_of(fid) != "FILL_AREA_STYLE_COLOUR" {
                continue;
            }
            let fc = self.get(fid)?;
            match fc.records[0].params.get(1) {
                Some(Param::Reference(c)) => return self.colour(*c).map(Some),
                other => {
                    return Err(format!(
                        "#{fid}: FILL_AREA_STYLE_COLOUR.fill_colour: expected a reference, got {other:?}"
                    ));
                }
            }
        }
        Ok(None)
    }

    /// SURFACE_STYLE_RENDERING(method, colour) or …_WITH_PROPERTIES(method, colour,
    /// properties): the colour and the opacity of SURFACE_STYLE_TRANSPARENT.
    fn rendering(&mut self, id: u64) -> std::result::Result<(Option<Rgba>, Option<f64>), Reason> {
        let inst = self.get(id)?;
        let p = inst.records[0].params.clone();
        let colour = match p.get(1) {
            Some(Param::Reference(c)) => Some(self.colour(*c)?),
            _ => None,
        };
        let mut alpha = None;
        if let Some(Param::List(props)) = p.get(2) {
            for prop in props {
                let Param::Reference(pid) = prop else { continue };
                if self.type_of(*pid) != "SURFACE_STYLE_TRANSPARENT" {
                    continue;
                }
                let t = self.get(*pid)?;
                let transparency = t.records[0].params.first().and_then(number).unwrap_or(f64::NAN);
                if !(0.0..=1.0).contains(&transparency) {
                    return Err(format!(
                        "#{pid}: SURFACE_STYLE_TRANSPARENT.transparency {transparency} is not in [0, 1]"
                    ));
                }
                alpha = Some(1.0 - transparency);
            }
        }
        Ok((colour, alpha))
    }

    /// CURVE_STYLE(name, font, width, colour).
    fn curve_style(&mut self, id: u64) -> std::result::Result<Option<Rgba>, Reason> {
        let inst = self.get(id)?;
        let p = inst.records[0].params.clone();
        // The font and width are read as what they are: how edges are drawn, which a
        // shaded solid does not show.
        for k in [1, 2] {
            if let Some(Param::Reference(x)) = p.get(k) {
                self.read.insert(*x);
            }
        }
        match p.get(3) {
            Some(Param::Reference(c)) => self.colour(*c).map(Some),
            _ => Ok(None),
        }
    }

    /// COLOUR_RGB or DRAUGHTING_PRE_DEFINED_COLOUR, opaque.
    fn colour(&mut self, id: u64) -> std::result::Result<Rgba, Reason> {
        self.expect(id, &["COLOUR_RGB", "DRAUGHTING_PRE_DEFINED_COLOUR", "PRE_DEFINED_COLOUR"])?;
        let inst = self.get(id)?;
        if let Some(rgb) = inst.record("COLOUR_RGB") {
            let mut c = [0.0; 3];
            for (k, (slot, field)) in c.iter_mut().zip(["red", "green", "blue"]).enumerate() {
                let x = rgb.params.get(k + 1).and_then(number).unwrap_or(f64::NAN);
                // Rounding in the writer may step just outside [0, 1].
                if !(-1e-6..=1.0 + 1e-6).contains(&x) {
                    return Err(format!("#{id}: COLOUR_RGB.{field} {x} is not in [0, 1]"));
                }
                *slot = x.clamp(0.0, 1.0);
            }
            return Ok(Rgba::opaque(c[0], c[1], c[2]));
        }
        if let Some(named) = inst.record("DRAUGHTING_PRE_DEFINED_COLOUR").or_else(|| inst.record("PRE_DEFINED_COLOUR"))
        {
            let name = match named.params.first() {
                Some(Param::String(s)) => s.trim().to_lowercase(),
                _ => String::new(),
            };
            return pre_defined(&name)
                .ok_or_else(|| format!("#{id}: pre-defined colour '{name}' is not one of ISO 10303-46's"));
        }
        Err(format!("#{id}: a {} is not a colour read here", inst.type_name()))
    }

    /// Refuses `id` unless its type is (or holds) one of `types`, before it is read.
    fn expect(&self, id: u64, types: &[&str]) -> std::result::Result<(), Reason> {
        let t = self.type_of(id);
        if types.iter().any(|n| has_record(t, n)) {
            Ok(())
        } else {
            Err(format!("#{id} is a {t}, not a {}", types.join(" or ")))
        }
    }
}

/// ISO 10303-46's pre-defined colours.
fn pre_defined(name: &str) -> Option<Rgba> {
    Some(match name {
        "red" => Rgba::opaque(1.0, 0.0, 0.0),
        "green" => Rgba::opaque(0.0, 1.0, 0.0),
        "blue" => Rgba::opaque(0.0, 0.0, 1.0),
        "yellow" => Rgba::opaque(1.0, 1.0, 0.0),
        "magenta" => Rgba::opaque(1.0, 0.0, 1.0),
        "cyan" => Rgba::opaque(0.0, 1.0, 1.0),
        "black" => Rgba::opaque(0.0, 0.0, 0.0),
        "white" => Rgba::opaque(1.0, 1.0, 1.0),
        _ => return None,
    })
}

/// A number, bare or typed.
fn number(p: &Param) -> Option<f64> {
    match p {
        Param::Real(x) if x.is_finite() => Some(*x),
        Param::Integer(i) => Some(*i as f64),
        Param::Typed(_, inner) => number(inner),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(data: &str) -> StepFile {
        let text = format!(
            "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\n\
             FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n{data}\nENDSEC;\nEND-ISO-10303-21;\n"
        );
        StepFile::from_bytes(text.into_bytes()).expect("a valid test file")
    }

    /// A solid styled grey, one of its faces red (pre-defined) and half transparent, and
    /// an override turning the solid blue.
    const STYLED: &str = "\
#1=MANIFOLD_SOLID_BREP('',#2);
#2=CLOSED_SHELL('',(#3));
#3=ADVANCED_FACE('',(),#4,.T.);
#4=PLANE('',#5);
#5=AXIS2_PLACEMENT_3D('',#6,$,$);
#6=CARTESIAN_POINT('',(0.,0.,0.));
#10=STYLED_ITEM('',(#11),#1);
#11=PRESENTATION_STYLE_ASSIGNMENT((#12,#30));
#12=SURFACE_STYLE_USAGE(.BOTH.,#13);
#13=SURFACE_SIDE_STYLE('',(#14));
#14=SURFACE_STYLE_FILL_AREA(#15);
#15=FILL_AREA_STYLE('',(#16));
#16=FILL_AREA_STYLE_COLOUR('',#17);
#17=COLOUR_RGB('',0.5,0.25,0.75);
#30=CURVE_STYLE('',#31,POSITIVE_LENGTH_MEASURE(0.1),#32);
#31=DRAUGHTING_PRE_DEFINED_CURVE_FONT('continuous');
#32=DRAUGHTING_PRE_DEFINED_COLOUR('black');
#20=STYLED_ITEM('',(#21),#3);
#21=PRESENTATION_STYLE_ASSIGNMENT((#22));
#22=SURFACE_STYLE_USAGE(.POSITIVE.,#23);
#23=SURFACE_SIDE_STYLE('',(#24));
#24=SURFACE_STYLE_RENDERING_WITH_PROPERTIES(.NORMAL_SHADING.,#25,(#26));
#25=DRAUGHTING_PRE_DEFINED_COLOUR('red');
#26=SURFACE_STYLE_TRANSPARENT(0.5);
#40=MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION('',(#10,#20),#41);
#41=(GEOMETRIC_REPRESENTATION_CONTEXT(3)REPRESENTATION_CONTEXT('','3D'));
";

    #[test]
    fn face_solid_and_curve_colours_are_read() {
        let s = read_styles(&file(STYLED));
        assert!(s.skipped.is_empty(), "{:?}", s.skipped);
        assert_eq!(s.styles.len(), 2);
        assert_eq!(s.colour(1), Some(Rgba::opaque(0.5, 0.25, 0.75)));
        assert_eq!(s.styles[0].curve, Some(Rgba::opaque(0.0, 0.0, 0.0)));
        assert_eq!(s.styles[0].kind, StyledKind::Solid);
        assert_eq!(s.styles[1].kind, StyledKind::Face);
        assert_eq!(s.styles[0].groups, vec![40]);
        let red = Rgba { red: 1.0, green: 0.0, blue: 0.0, alpha: 0.5 };
        assert_eq!(s.colour(3), Some(red));
        // The face over its shell over its solid.
        assert_eq!(s.effective(&[3, 2, 1]), Some(red));
        assert_eq!(s.effective(&[2, 1]), Some(Rgba::opaque(0.5, 0.25, 0.75)));
        for id in [10, 11, 12, 13, 14, 15, 16, 17, 20, 25, 26, 30, 31, 32, 40, 41] {
            assert!(s.entities.contains(&id), "#{id} read");
        }
        assert!(!s.entities.contains(&1), "the solid is geometry, not style");
    }

    #[test]
    fn any_reference_pointed_anywhere_is_skipped_or_read_never_a_panic() {
        let refs: Vec<(usize, usize)> = STYLED
            .match_indices('#')
            .filter(|(k, _)| STYLED[..*k].ends_with([',', '(']))
            .map(|(k, _)| (k, k + 1 + STYLED[k + 1..].find(|c: char| !c.is_ascii_digit()).unwrap_or(0)))
            .collect();
        assert!(refs.len() > 20, "{}", refs.len());
        for (start, end) in refs {
            for target in ["#1", "#3", "#6", "#10", "#11", "#13", "#16", "#17", "#26", "#32", "#40"] {
                let text = format!("{}{target}{}", &STYLED[..start], &STYLED[end..]);
                let data = format!(
                    "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\n\
                     FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n{text}\nENDSEC;\nEND-ISO-10303-21;\n"
                );
                let Ok(f) = StepFile::from_bytes(data.into_bytes()) else { continue };
                let s = read_styles(&f);
                assert!(s.colours.values().all(|c| c.to_array().iter().all(|x| (0.0..=1.0).contains(x))));
            }
        }
    }

    #[test]
    fn an_over_riding_style_wins_whatever_its_place() {
        // The override comes first in the file, the style it overrides later.
        let data = format!(
            "{STYLED}#7=OVER_RIDING_STYLED_ITEM('',(#8),#1,#10);\n#8=PRESENTATION_STYLE_ASSIGNMENT((#9));\n\
             #9=SURFACE_STYLE_USAGE(.BOTH.,#18);\n#18=SURFACE_SIDE_STYLE('',(#19));\n\
             #19=SURFACE_STYLE_RENDERING(.NORMAL_SHADING.,#27);\n#27=DRAUGHTING_PRE_DEFINED_COLOUR('blue');\n"
        );
        let s = read_styles(&file(&data));
        assert_eq!(s.colour(1), Some(Rgba::opaque(0.0, 0.0, 1.0)));
        assert_eq!(s.styles.iter().find(|x| x.styled_item == 7).and_then(|x| x.overrides), Some(10));
    }

    #[test]
    fn a_context_dependent_override_keeps_its_context() {
        let data = format!(
            "{STYLED}#50=CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM('',(#11),#60,#10,(#61));\n\
             #60=SHAPE_REPRESENTATION('',(#5),#41);\n#61=CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#62,#63);\n\
             #62=SHAPE_REPRESENTATION_RELATIONSHIP('','',#60,#60);\n#63=PRODUCT_DEFINITION_SHAPE('','',$);\n"
        );
        let s = read_styles(&file(&data));
        let cd = s.styles.iter().find(|x| x.styled_item == 50).expect("read");
        assert_eq!((cd.kind, cd.context.clone(), cd.overrides), (StyledKind::Representation, vec![61], Some(10)));
        assert_eq!(s.colour(60), Some(Rgba::opaque(0.5, 0.25, 0.75)));
    }

    #[test]
    fn unreadable_styles_are_skipped_with_the_reason() {
        let data = STYLED
            .replace("#17=COLOUR_RGB('',0.5,0.25,0.75)", "#17=COLOUR_RGB('',127.,0.25,0.75)")
            .replace("DRAUGHTING_PRE_DEFINED_COLOUR('red')", "DRAUGHTING_PRE_DEFINED_COLOUR('mauve')");
        let s = read_styles(&file(&data));
        assert_eq!(s.colour(1), None);
        assert_eq!(s.colour(3), None);
        assert!(s.skipped.iter().any(|r| r.contains("#17") && r.contains("red")), "{:?}", s.skipped);
        assert!(s.skipped.iter().any(|r| r.contains("mauve")), "{:?}", s.skipped);
        let nulls = "#1=MANIFOLD_SOLID_BREP('',#2);\n#2=CLOSED_SHELL('',());\n\
                     #10=STYLED_ITEM('',(#11),#1);\n#11=PRESENTATION_STYLE_ASSIGNMENT((NULL_STYLE(.NULL.)));\n\
                     #12=STYLED_ITEM('',(#1),#1);\n#13=STYLED_ITEM('',$,#1);\n";
        let s = read_styles(&file(nulls));
        assert_eq!(s.colour(1), None);
        assert_eq!(s.styles.len(), 2, "{s:?}");
        assert!(s.skipped.iter().any(|r| r.contains("#13")), "{:?}", s.skipped);
        assert!(s.skipped.iter().any(|r| r.contains("#12")), "{:?}", s.skipped);
    }
}
