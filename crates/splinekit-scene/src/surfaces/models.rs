//! The model surfaces' documents: closed-form surfaces of the kernel (plane, sphere, torus,
//! …), each a struct of fields with defaults declared by `model_document!`.

use splinekit::surface::model::{
    Apple, Cone, Cylinder, Enneper, HeartSurface, Helicoid, KleinBottle, MobiusStrip, Plane, Seashell, Sphere, Torus,
    dupin_cyclide,
};

use super::{SurfaceForm, Surfaces};
use crate::points::to_point;
use crate::registry::model_document;

model_document! {
    /// `{"type":"plane","origin":[0,0,0],"u_axis":[1,0,0],"v_axis":[0,1,0]}`
    pub struct PlaneDoc in Surfaces {
        /// S(0, 0) (default the origin).
        pub origin: Vec<f64> = vec![0.0, 0.0, 0.0],
        /// ∂S/∂u (default x).
        pub u_axis: Vec<f64> = vec![1.0, 0.0, 0.0],
        /// ∂S/∂v (default y).
        pub v_axis: Vec<f64> = vec![0.0, 1.0, 0.0],
    }
    build(|d| Plane::new(to_point("origin", &d.origin)?, to_point("u_axis", &d.u_axis)?, to_point("v_axis", &d.v_axis)?))
    exact(|d| SurfaceForm::Plane { origin: &d.origin, u_axis: &d.u_axis, v_axis: &d.v_axis })
}

model_document! {
    /// `{"type":"cylinder","radius":1,"height":1}`
    pub struct CylinderDoc in Surfaces {
        /// Radius (default 1).
        pub radius: f64 = 1.0,
        /// Height (default 1).
        pub height: f64 = 1.0,
    }
    build(|d| Cylinder::new(d.radius, d.height))
    exact(|d| SurfaceForm::Cylinder { radius: d.radius, height: d.height })
}

model_document! {
    /// `{"type":"cone","radius":1,"height":2}`
    pub struct ConeDoc in Surfaces {
        /// Base radius (default 1).
        pub radius: f64 = 1.0,
        /// Height (default 2).
        pub height: f64 = 2.0,
    }
    build(|d| Cone::new(d.radius, d.height))
    exact(|d| SurfaceForm::Cone { radius: d.radius, height: d.height })
}

model_document! {
    /// `{"type":"sphere","radius":1}`
    pub struct SphereDoc in Surfaces {
        /// Radius (default 1).
        pub radius: f64 = 1.0,
    }
    build(|d| Sphere::new(d.radius))
    exact(|d| SurfaceForm::Sphere { radius: d.radius })
}

model_document! {
    /// `{"type":"torus","major_radius":3,"minor_radius":1}`
    pub struct TorusDoc in Surfaces {
        /// R (default 3).
        pub major_radius: f64 = 3.0,
        /// r (default 1).
        pub minor_radius: f64 = 1.0,
    }
    build(|d| Torus::new(d.major_radius, d.minor_radius))
    exact(|d| SurfaceForm::Torus { major_radius: d.major_radius, minor_radius: d.minor_radius })
}

model_document! {
    /// `{"type":"mobius","radius":1,"half_width":0.5}`
    pub struct MobiusDoc in Surfaces {
        /// Centre radius (default 1).
        pub radius: f64 = 1.0,
        /// Half-width (default 0.5).
        pub half_width: f64 = 0.5,
    }
    build(|d| MobiusStrip::new(d.radius, d.half_width))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"klein_bottle","radius":3}`
    pub struct KleinBottleDoc in Surfaces {
        /// Radius R (default 3).
        pub radius: f64 = 3.0,
    }
    build(|d| KleinBottle::new(d.radius))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"enneper","extent":2}`
    pub struct EnneperDoc in Surfaces {
        /// Half-extent of the square domain (default 2).
        pub extent: f64 = 2.0,
    }
    build(|d| Enneper::new(d.extent))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"helicoid","radius":1,"pitch":1,"turns":2}`
    pub struct HelicoidDoc in Surfaces {
        /// Radius (default 1).
        pub radius: f64 = 1.0,
        /// Rise per turn (default 1).
        pub pitch: f64 = 1.0,
        /// Turns (default 2).
        pub turns: f64 = 2.0,
    }
    build(|d| Helicoid::new(d.radius, d.pitch, d.turns))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"seashell","a":1,"b":2,"c":0.1,"turns":2}`
    pub struct SeashellDoc in Surfaces {
        /// Tube radius (default 1).
        pub a: f64 = 1.0,
        /// Height (default 2).
        pub b: f64 = 2.0,
        /// Inner radius (default 0.1).
        pub c: f64 = 0.1,
        /// Turns (default 2).
        pub turns: f64 = 2.0,
    }
    build(|d| Seashell::new(d.a, d.b, d.c, d.turns))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"apple","scale":1}`
    pub struct AppleDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| Apple::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"heart_surface","scale":1}`
    pub struct HeartSurfaceDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| HeartSurface::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"dupin_cyclide","a":3,"c":1,"mu":2}`: the Dupin cyclide of a > c ≥ 0 and μ
    /// (b² = a² − c²), exactly its rational biquadratic form on [0, 2π]²: the point at (u, v)
    /// is (μ (c − a cos θ cos ψ) + b² cos θ, b sin θ (a − μ cos ψ), b sin ψ (c cos θ − μ))
    /// / (a − c cos θ cos ψ) at the angles θ(u), ψ(v) of the nine-point NURBS circle (θ = u
    /// at multiples of π/2); a ring cyclide for c < μ < a.
    pub struct DupinCyclideDoc in Surfaces {
        /// a (default 3).
        pub a: f64 = 3.0,
        /// c, 0 ≤ c < a (default 1).
        pub c: f64 = 1.0,
        /// μ (default 2).
        pub mu: f64 = 2.0,
    }
    build(|d| dupin_cyclide(d.a, d.c, d.mu))
    exact(|d| SurfaceForm::Spline(crate::views::NetView::of_nurbs(&dupin_cyclide(d.a, d.c, d.mu)?)))
}

model_document! {
    /// `{"type":"asteroidal_sphere","a":1,"b":1,"c":1}`: ((a cos u cos v)³, (b sin u cos v)³,
    /// (c sin v)³), u ∈ [0, 2π], v ∈ [−π/2, π/2].
    pub struct AsteroidalSphereDoc in Surfaces {
        /// Semi-axis a (default 1).
        pub a: f64 = 1.0,
        /// Semi-axis b (default 1).
        pub b: f64 = 1.0,
        /// Semi-axis c (default 1).
        pub c: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::AsteroidalSphere::new(d.a, d.b, d.c))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"bent_horns","scale":1}`: with φ = 2π/3, s·((2 + cos u)(v/3 − sin v),
    /// (2 + cos(u − φ))(cos v − 1), (2 + cos(u + φ))(cos v − 1)), u ∈ [−π, π], v ∈ [−2π, 2π].
    pub struct BentHornsDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::BentHorns::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"bohemian_dome","a":1,"b":1,"c":1}`: (a cos u, a sin u + b cos v, c sin v),
    /// u, v ∈ [0, 2π].
    pub struct BohemianDomeDoc in Surfaces {
        /// Radius of the moving circle (default 1).
        pub a: f64 = 1.0,
        /// Semi-axis of its path along y (default 1).
        pub b: f64 = 1.0,
        /// Semi-axis of its path along z (default 1).
        pub c: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::BohemianDome::new(d.a, d.b, d.c))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"boy_surface","scale":1}`: Apéry's Boy surface; with d = 2 − √2 sin 3u sin 2v,
    /// s·((√2 cos²v cos 2u + cos u sin 2v)/d, (√2 cos²v sin 2u − sin u sin 2v)/d, 3 cos²v/d),
    /// u ∈ [−π/2, π/2], v ∈ [0, π].
    pub struct BoySurfaceDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::BoySurface::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"cross_cap","scale":1}`: s·(½ sin u sin 2v, sin 2u sin²v, cos 2u sin²v),
    /// u ∈ [0, 2π], v ∈ [0, π/2].
    pub struct CrossCapDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::CrossCap::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"dini_surface","a":1,"b":0.2}`: (a cos u sin v, a sin u sin v,
    /// a (cos v + ln tan(v/2)) + b u), u ∈ [0, 4π], v ∈ [0.1, 2]; K = −1/(a² + b²).
    pub struct DiniSurfaceDoc in Surfaces {
        /// Radius a (default 1).
        pub a: f64 = 1.0,
        /// Twist b, any finite value (default 0.2).
        pub b: f64 = 0.2,
    }
    build(|d| splinekit::surface::model::DiniSurface::new(d.a, d.b))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"eight_surface","scale":1}`: s·(cos u sin 2v, sin u sin 2v, sin v),
    /// u ∈ [0, 2π], v ∈ [−π/2, π/2].
    pub struct EightSurfaceDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::EightSurface::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"inside_out_torus","wheel_radius":1,"tube_radius_1":2,"tube_radius_2":1.5}`:
    /// ((a + b cos v) cos u, (a + b cos v) sin u, c sin v), u, v ∈ [0, 2π].
    pub struct InsideOutTorusDoc in Surfaces {
        /// Wheel radius a (default 1).
        pub wheel_radius: f64 = 1.0,
        /// Radial semi-axis b of the tube (default 2: through the axis).
        pub tube_radius_1: f64 = 2.0,
        /// Axial semi-axis c of the tube (default 1.5).
        pub tube_radius_2: f64 = 1.5,
    }
    build(|d| splinekit::surface::model::InsideOutTorus::new(d.wheel_radius, d.tube_radius_1, d.tube_radius_2))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"kuen_surface","scale":1}`: with d = 1 + u² sin²v, s·(2(cos u + u sin u) sin v/d,
    /// 2(sin u − u cos u) sin v/d, ln tan(v/2) + 2 cos v/d), u ∈ [−4.5, 4.5],
    /// v ∈ [0.1, π − 0.1]; K = −1/s².
    pub struct KuenSurfaceDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::KuenSurface::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"sine_surface","scale":1}`: s·(sin u, sin v, sin(u + v)), u, v ∈ [0, 2π].
    pub struct SineSurfaceDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::SineSurface::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"slippers_surface","scale":1}`: with φ = 2π/3, s·((2 + cos u) cos³v sin v,
    /// (2 + cos(u + φ)) cos²(v + φ) sin²(v + φ), −(2 + cos(u − φ)) cos²(φ − v) sin³(φ − v)),
    /// u, v ∈ [0, 2π].
    pub struct SlippersSurfaceDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::SlippersSurface::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"roman_surface","radius":1}`: r²·(cos u cos v sin v, sin u cos v sin v,
    /// cos u sin u cos²v), u ∈ [0, 2π], v ∈ [−π/2, π/2].
    pub struct RomanSurfaceDoc in Surfaces {
        /// r, of Steiner's quartic x²y² + y²z² + z²x² = r²xyz (default 1).
        pub radius: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::RomanSurface::new(d.radius))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"swallowtail","scale":1}`: s·(u v² + 3v⁴, −2uv − 4v³, u), u ∈ [−2, 2],
    /// v ∈ [−1, 1].
    pub struct SwallowtailDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::Swallowtail::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"trianguloid_trefoil","scale":1}`: with φ = 2π/3, s·(2 sin 3u/(2 + cos v),
    /// 2(sin u + 2 sin 2u)/(2 + cos(v + φ)), (cos u − 2 cos 2u)(2 + cos v)(2 + cos(v + φ))/4),
    /// u, v ∈ [−π, π].
    pub struct TrianguloidTrefoilDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::TrianguloidTrefoil::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}

model_document! {
    /// `{"type":"whitney_umbrella","scale":1}`: s·(uv, u, v²), u, v ∈ [−1, 1].
    pub struct WhitneyUmbrellaDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::surface::model::WhitneyUmbrella::new(d.scale))
    exact(|_d| SurfaceForm::Approximate)
}
