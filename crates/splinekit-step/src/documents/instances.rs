//! The solids and shells of a file placed by its product structure
//! ([`crate::assembly::read_product_structure`]): one object per use of a part, at the
//! rigid motion that takes the part's coordinates into the root product's, and a part used
//! several times instanced (its later uses name the first by `instance_of`), not copied.
//!
//! A part's geometry items are matched with what was read by their `#id`s: a solid
//! (`MANIFOLD_SOLID_BREP`, `BREP_WITH_VOIDS`, `FACETED_BREP`) by its own, a
//! `SHELL_BASED_SURFACE_MODEL` by its shells'. An item placed inside its part by a
//! `MAPPED_ITEM` moves by that too: the object's placement is instance ∘ item. Solids that
//! no product reaches stay where the file put them, as before.

use std::collections::{BTreeMap, HashMap};

use splinekit_scene::placement::RigidTransform;
use splinekit_scene::{ShapeDocument, SurfaceDocument};

use super::import::ImportedItem;
use super::solid::BrepRead;
use crate::assembly::{ItemKind, read_product_structure};
use crate::part21::StepFile;

/// The objects of `breps`, placed (see the module). Where the product structure cannot be
/// read, `notes` says why, with a count of 1, and the solids stay unplaced.
pub fn place_breps(file: &StepFile, breps: Vec<BrepRead>, notes: &mut BTreeMap<String, usize>) -> Vec<ImportedItem> {
    let unplaced = |breps: Vec<BrepRead>| -> Vec<ImportedItem> {
        breps
            .into_iter()
            .map(|b| ImportedItem::new(b.name, None, ShapeDocument::Surface(SurfaceDocument::Brep(b.document))))
            .collect()
    };
    let structure = match read_product_structure(file) {
        Ok(s) => s,
        Err(e) => {
            notes.insert(format!("product structure ({e}); each solid at its own origin"), 1);
            return unplaced(breps);
        }
    };
    let by_source: HashMap<u64, usize> = breps.iter().enumerate().map(|(k, b)| (b.source, k)).collect();
    // Per part: (read brep, placement of its item within the part).
    let part_breps: Vec<Vec<(usize, RigidTransform)>> = structure
        .parts
        .iter()
        .map(|part| {
            let mut found = Vec::new();
            for item in &part.items {
                let sources = match item.kind {
                    ItemKind::ManifoldSolidBrep | ItemKind::BrepWithVoids | ItemKind::FacetedBrep => vec![item.id],
                    ItemKind::ShellBasedSurfaceModel => shells_of(file, item.id),
                    ItemKind::GeometricSet => Vec::new(),
                };
                found.extend(sources.iter().filter_map(|s| by_source.get(s)).map(|&b| (b, item.placement)));
            }
            found
        })
        .collect();
    let mut items = Vec::new();
    let mut first_use: HashMap<usize, usize> = HashMap::new();
    for instance in &structure.instances {
        let part = &structure.parts[instance.part];
        let label = occurrence_label(instance, &part.name);
        let several = part_breps[instance.part].len() > 1;
        for &(b, within) in &part_breps[instance.part] {
            let brep = &breps[b];
            let name = match (several, brep.name.is_empty()) {
                (true, false) => format!("{label}/{}", brep.name),
                _ => label.clone(),
            };
            let placement = instance.placement.compose(&within);
            let document = ShapeDocument::Surface(SurfaceDocument::Brep(brep.document.clone()));
            let mut item = ImportedItem::new(name, None, document);
            item.placement = (placement != RigidTransform::IDENTITY).then_some(placement);
            item.instance_of = first_use.get(&b).copied();
            first_use.entry(b).or_insert(items.len());
            items.push(item);
        }
    }
    let left: Vec<BrepRead> =
        breps.into_iter().enumerate().filter(|(k, _)| !first_use.contains_key(k)).map(|(_, b)| b).collect();
    items.extend(unplaced(left));
    items
}

/// The shells a `SHELL_BASED_SURFACE_MODEL` lists (its references; none where it cannot
/// be read, which the import has reported).
fn shells_of(file: &StepFile, id: u64) -> Vec<u64> {
    let mut out = Vec::new();
    if let Ok(instance) = file.get(id) {
        for record in &instance.records {
            for p in &record.params {
                p.for_each_reference(&mut |r| out.push(r));
            }
        }
    }
    out
}

/// An instance's name: the part's, then its occurrences below the root joined by `/`
/// (each the occurrence's name, or its id) in parentheses; the part's alone for a part
/// placed at the root.
fn occurrence_label(instance: &crate::assembly::PartInstance, part: &str) -> String {
    let below: Vec<&str> = instance.path.iter().skip(1).map(|o| o.name.as_str()).collect();
    if below.is_empty() { part.to_string() } else { format!("{part} ({})", below.join("/")) }
}
