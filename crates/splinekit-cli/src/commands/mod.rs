//! One module per subcommand.

pub mod arc_length;
pub mod convert;
pub mod eval;
pub mod eval_surface;
pub mod fit;
pub mod intersect;
pub mod offset;
pub mod project;
pub mod refine;
pub mod render;
pub mod section;
pub mod subdivide;
pub mod subdivide_surface;
pub mod tessellate;
pub mod view;
