//! Model surfaces with exact partial derivatives of every order.

pub mod asteroidal_sphere;
pub mod bent_horns;
pub mod bohemian_dome;
pub mod boy_surface;
pub mod catalog;
pub mod cross_cap;
pub mod dini_surface;
pub mod dupin_cyclide;
pub mod eight_surface;
pub mod inside_out_torus;
pub mod kuen_surface;
pub mod rational;
pub mod roman_surface;
pub mod separable;
pub mod sine_surface;
pub mod slippers_surface;
pub mod swallowtail;
pub mod trianguloid_trefoil;
pub mod whitney_umbrella;

pub use asteroidal_sphere::AsteroidalSphere;
pub use bent_horns::BentHorns;
pub use bohemian_dome::BohemianDome;
pub use boy_surface::BoySurface;
pub use catalog::{
    Apple, Cone, Cylinder, Enneper, HeartSurface, Helicoid, KleinBottle, MobiusStrip, Plane, Seashell, Sphere, Torus,
};
pub use cross_cap::CrossCap;
pub use dini_surface::DiniSurface;
pub use dupin_cyclide::dupin_cyclide;
pub use eight_surface::EightSurface;
pub use inside_out_torus::InsideOutTorus;
pub use kuen_surface::KuenSurface;
pub use rational::{RationalCoordinate, RationalSurface};
pub use roman_surface::RomanSurface;
pub use separable::{Factor, SeparableSurface, SeparableTerm};
pub use sine_surface::SineSurface;
pub use slippers_surface::SlippersSurface;
pub use swallowtail::Swallowtail;
pub use trianguloid_trefoil::TrianguloidTrefoil;
pub use whitney_umbrella::WhitneyUmbrella;
