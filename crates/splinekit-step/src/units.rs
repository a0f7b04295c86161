//! The units of a STEP file's geometry, read from the context of each representation.
//!
//! A representation (`ADVANCED_BREP_SHAPE_REPRESENTATION`, `SHAPE_REPRESENTATION`, …) holds
//! items in a context whose `GLOBAL_UNIT_ASSIGNED_CONTEXT` names a length unit and a plane
//! angle unit, and whose `GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT` may give the distance within
//! which the writer considers two points one. An assembly's parts may each have their own
//! context (an Inventor part in millimetres inside an assembly in inches): units belong to
//! items, not to the file.
//!
//! Units are `SI_UNIT(prefix, name)` (metre or radian with an optional prefix: `.MILLI.`,
//! `.CENTI.`, `.KILO.`, …) or `CONVERSION_BASED_UNIT(name, measure)` whose measure is a
//! number of another unit (`'INCH'` = `LENGTH_MEASURE(25.4)` millimetres, `'DEGREE'` =
//! `PLANE_ANGLE_MEASURE(0.01745…)` radians). Reading converts lengths to millimetres and
//! angles to radians, as [`Units::length`] and [`Units::angle`] say; what a parameter is
//! depends on its curve or surface (a circle's parameter is an angle, a B-spline's a
//! number).

use std::collections::HashMap;

use crate::error::{Result, StepError};
use crate::part21::{Instance, Param, StepFile};

/// The units of one representation context.
#[derive(Debug, Clone, PartialEq)]
pub struct Units {
    /// Millimetres per length unit of the file.
    pub length: f64,
    /// The length unit's name as the file gives it (`millimetre`, `inch`, …).
    pub length_name: String,
    /// Radians per plane angle unit of the file.
    pub angle: f64,
    /// The context's distance uncertainty, in millimetres, if it gives one.
    pub uncertainty: Option<f64>,
}

impl Default for Units {
    /// Millimetres and radians, no uncertainty: what a file without units is read in.
    fn default() -> Self {
        Units { length: 1.0, length_name: "millimetre".into(), angle: 1.0, uncertainty: None }
    }
}

impl Units {
    /// The identity: numbers read as they stand (the parameter space of pcurves).
    pub fn none() -> Self {
        Units { length: 1.0, length_name: "1".into(), angle: 1.0, uncertainty: None }
    }
}

/// The factor of an SI prefix.
fn prefix(name: &str) -> Option<f64> {
    Some(match name {
        "EXA" => 1e18,
        "PETA" => 1e15,
        "TERA" => 1e12,
        "GIGA" => 1e9,
        "MEGA" => 1e6,
        "KILO" => 1e3,
        "HECTO" => 1e2,
        "DECA" => 1e1,
        "DECI" => 1e-1,
        "CENTI" => 1e-2,
        "MILLI" => 1e-3,
        "MICRO" => 1e-6,
        "NANO" => 1e-9,
        "PICO" => 1e-12,
        "FEMTO" => 1e-15,
        "ATTO" => 1e-18,
        _ => return None,
    })
}

/// A number, bare or typed (`LENGTH_MEASURE(25.4)`; some writers leave the type out).
fn number(p: &Param) -> Option<f64> {
    match p {
        Param::Real(x) => Some(*x),
        Param::Integer(i) => Some(*i as f64),
        Param::Typed(_, inner) => number(inner),
        _ => None,
    }
}

/// What a unit measures.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Quantity {
    Length,
    Angle,
    Other,
}

fn quantity(inst: &Instance) -> Quantity {
    if inst.record("LENGTH_UNIT").is_some() {
        Quantity::Length
    } else if inst.record("PLANE_ANGLE_UNIT").is_some() {
        Quantity::Angle
    } else {
        Quantity::Other
    }
}

/// Most conversion-based units a unit may be defined through (a guard against cycles).
const MAX_UNIT_DEPTH: usize = 8;

/// A unit's size in the base unit (millimetres for lengths, radians for angles) and its
/// name.
fn unit_size(file: &StepFile, id: u64, depth: usize) -> Result<(Quantity, f64, String)> {
    if depth > MAX_UNIT_DEPTH {
        return Err(StepError::plain(format!("#{id}: units defined through more than {MAX_UNIT_DEPTH} others")));
    }
    let inst = file.get(id)?;
    let q = quantity(&inst);
    let bad = |what: &str| StepError::at(inst.line, Some(id), format!("unit: {what}"));
    if let Some(si) = inst.record("SI_UNIT") {
        let factor = match si.params.first() {
            Some(Param::Enumeration(p)) => prefix(p).ok_or_else(|| bad(&format!("unknown SI prefix .{p}.")))?,
            _ => 1.0,
        };
        let name = match si.params.get(1) {
            Some(Param::Enumeration(n)) => n.clone(),
            _ => return Err(bad("SI_UNIT without a name")),
        };
        let size = match (q, name.as_str()) {
            (Quantity::Length, "METRE") => factor * 1000.0,
            (Quantity::Angle, "RADIAN") => factor,
            (Quantity::Length | Quantity::Angle, other) => return Err(bad(&format!("a length or angle in .{other}."))),
            _ => factor,
        };
        let prefix_name = match si.params.first() {
            Some(Param::Enumeration(p)) => p.to_lowercase(),
            _ => String::new(),
        };
        return Ok((q, size, format!("{prefix_name}{}", name.to_lowercase())));
    }
    if let Some(conversion) = inst.record("CONVERSION_BASED_UNIT") {
        let name = match conversion.params.first() {
            Some(Param::String(s)) => s.to_lowercase(),
            _ => String::new(),
        };
        let Some(Param::Reference(measure)) = conversion.params.get(1) else {
            return Err(bad("CONVERSION_BASED_UNIT without its measure"));
        };
        let m = file.get(*measure)?;
        let (value, base) = match (m.records[0].params.first(), m.records[0].params.get(1)) {
            (Some(v), Some(Param::Reference(base))) => (number(v), *base),
            _ => (None, 0),
        };
        let value = value.ok_or_else(|| bad("a conversion without a number"))?;
        let (_, base_size, _) = unit_size(file, base, depth + 1)?;
        let size = value * base_size;
        if !(size.is_finite() && size > 0.0) {
            return Err(bad(&format!("'{name}' is {value} of a unit of size {base_size}")));
        }
        return Ok((q, size, name));
    }
    Ok((q, 1.0, String::new()))
}

/// The units of a representation context (defaults where it names none).
pub fn context_units(file: &StepFile, context: u64) -> Result<Units> {
    let inst = file.get(context)?;
    let mut units = Units::default();
    if let Some(Some(Param::List(ids))) = inst.record("GLOBAL_UNIT_ASSIGNED_CONTEXT").map(|r| r.params.first()) {
        for p in ids {
            let Param::Reference(id) = p else { continue };
            match unit_size(file, *id, 0)? {
                (Quantity::Length, size, name) => (units.length, units.length_name) = (size, name),
                (Quantity::Angle, size, _) => units.angle = size,
                _ => {}
            }
        }
    }
    if let Some(Some(Param::List(ids))) = inst.record("GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT").map(|r| r.params.first()) {
        for p in ids {
            let Param::Reference(id) = p else { continue };
            let u = file.get(*id)?;
            let params = &u.records[0].params;
            // UNCERTAINTY_MEASURE_WITH_UNIT(value, unit, name, description).
            let (Some(value), Some(Param::Reference(unit))) = (params.first().and_then(number), params.get(1)) else {
                continue;
            };
            let (q, size, _) = unit_size(file, *unit, 0)?;
            if q == Quantity::Length && value.is_finite() && value > 0.0 {
                let mm = value * size;
                units.uncertainty = Some(units.uncertainty.map_or(mm, |u: f64| u.min(mm)));
            }
        }
    }
    Ok(units)
}

/// The entities through which a representation's items reach their shells and sets.
fn children(inst: &Instance) -> Vec<u64> {
    let mut out = Vec::new();
    let r = &inst.records[0];
    let take = |p: Option<&Param>, out: &mut Vec<u64>| match p {
        Some(Param::Reference(id)) => out.push(*id),
        Some(Param::List(items)) => out.extend(items.iter().filter_map(|i| match i {
            Param::Reference(id) => Some(*id),
            _ => None,
        })),
        _ => {}
    };
    match r.name.as_str() {
        "MANIFOLD_SOLID_BREP" | "FACETED_BREP" | "SHELL_BASED_SURFACE_MODEL" => take(r.params.get(1), &mut out),
        "BREP_WITH_VOIDS" => {
            take(r.params.get(1), &mut out);
            take(r.params.get(2), &mut out);
        }
        _ => {}
    }
    out
}

/// For every item of every representation, and the shells its solids and surface models
/// hold, the context the representation puts them in.
pub fn item_contexts(file: &StepFile) -> HashMap<u64, u64> {
    let mut map = HashMap::new();
    for id in file.ids() {
        let Some(t) = file.type_of(id) else { continue };
        if !(t.ends_with("REPRESENTATION") || t.starts_with('(') && t.contains("REPRESENTATION ")) {
            continue;
        }
        let Ok(inst) = file.get(id) else { continue };
        let Some(rep) = inst.records.iter().find(|r| r.name.ends_with("REPRESENTATION") && r.params.len() >= 3) else {
            continue;
        };
        let (Some(Param::List(items)), Some(Param::Reference(context))) = (rep.params.get(1), rep.params.get(2)) else {
            continue;
        };
        let mut stack: Vec<u64> = items
            .iter()
            .filter_map(|i| match i {
                Param::Reference(id) => Some(*id),
                _ => None,
            })
            .collect();
        let mut depth = 0;
        while let Some(item) = stack.pop() {
            if map.insert(item, *context).is_some() || depth > 1_000_000 {
                continue;
            }
            depth += 1;
            if let Ok(i) = file.get(item) {
                stack.extend(children(&i));
            }
        }
    }
    map
}
