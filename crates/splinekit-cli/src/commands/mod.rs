//! One module per subcommand (and [`spread`], the even parameters two of them share).

pub mod arc_length;
pub mod convert;
pub mod eval;
pub mod eval_surface;
pub mod fit;
pub mod intersect;
pub mod measure;
pub mod offset;
pub mod project;
pub mod refine;
pub mod render;
pub mod section;
pub mod spread;
pub mod subdivide;
pub mod subdivide_surface;
pub mod tessellate;
pub mod view;
