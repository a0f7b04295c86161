//! The entities of a STEP file that carry its product structure and presentation, as the
//! readers of [`crate::assembly`] and [`crate::styles`] read them: what the importer's
//! census of entities "not understood" leaves out.

use std::collections::HashSet;

use crate::part21::StepFile;

/// Every entity the product structure ([`crate::assembly::read_product_structure`]:
/// products, definitions, assembly occurrences, shape representation relationships,
/// transformations and their placements, representations, maps, contexts) and the styles
/// ([`crate::styles::read_styles`]: styled items, style assignments, surface and curve
/// styles, colours, groups of styled items) are read from. The geometry items themselves
/// (solids, shells, faces) are not in it: the geometry readers mark those.
pub fn structure_entities(file: &StepFile) -> HashSet<u64> {
    let mut read = crate::assembly::product_structure_entities(file);
    read.extend(crate::styles::read_styles(file).entities);
    read
}
