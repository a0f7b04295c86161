//! Model curves with analytic derivatives of every order. All are 3-D (planar ones lie in
//! z = 0), except [`Line`], which lives in any dimension.

pub mod butterfly;
pub mod chrysanthemum;
pub mod circle;
pub mod ellipse;
pub mod heart;
pub mod helix;
pub mod line;
pub mod lissajous;
pub mod logarithmic_spiral;
pub mod rose;
pub mod trefoil;
pub mod trig;
pub mod trochoid;

pub use butterfly::Butterfly;
pub use chrysanthemum::Chrysanthemum;
pub use circle::Circle;
pub use ellipse::Ellipse;
pub use heart::Heart;
pub use helix::Helix;
pub use line::Line;
pub use lissajous::Lissajous;
pub use logarithmic_spiral::LogarithmicSpiral;
pub use rose::Rose;
pub use trefoil::Trefoil;
pub use trig::{Term, TrigCurve, TrigSeries};
pub use trochoid::{Rolling, Trochoid};
