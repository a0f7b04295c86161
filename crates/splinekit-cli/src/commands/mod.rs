//! One module per subcommand.

pub mod eval;
pub mod fit;
pub mod refine;
pub mod subdivide;
pub mod tessellate;
