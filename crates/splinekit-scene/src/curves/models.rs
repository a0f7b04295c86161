//! The model curves' documents: closed-form curves of the kernel (circle, helix, rose, …),
//! each a struct of fields with defaults declared by `model_document!`.

use splinekit::curve::model::{Butterfly, Circle, Ellipse, Heart, Helix, Lissajous, Rolling, Rose, Trefoil, Trochoid};

use super::{CurveForm, Curves};
use crate::defaults::is_false;
use crate::registry::model_document;

model_document! {
    /// `{"type":"circle","radius":1}`: (r cos t, r sin t, 0), t ∈ [0, 2π].
    pub struct CircleDoc in Curves {
        /// Radius r (default 1).
        pub radius: f64 = 1.0,
    }
    build(|d| Circle::new(d.radius))
    exact(|d| CurveForm::Circle { radius: d.radius })
}

model_document! {
    /// `{"type":"ellipse","a":2,"b":1}`: (a cos t, b sin t, 0), t ∈ [0, 2π].
    pub struct EllipseDoc in Curves {
        /// Semi-axis along x (default 2).
        pub a: f64 = 2.0,
        /// Semi-axis along y (default 1).
        pub b: f64 = 1.0,
    }
    build(|d| Ellipse::new(d.a, d.b))
    exact(|d| CurveForm::Ellipse { a: d.a, b: d.b })
}

model_document! {
    /// `{"type":"helix","radius":1,"pitch":1,"turns":3}`: (r cos t, r sin t, pitch·t/2π).
    pub struct HelixDoc in Curves {
        /// Radius (default 1).
        pub radius: f64 = 1.0,
        /// Rise per turn (default 1).
        pub pitch: f64 = 1.0,
        /// Number of turns; t ∈ [0, 2π·turns] (default 3).
        pub turns: f64 = 3.0,
    }
    build(|d| Helix::new(d.radius, d.pitch, d.turns))
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"heart","scale":1}`: s·(16 sin³t, 13 cos t − 5 cos 2t − 2 cos 3t − cos 4t, 0).
    pub struct HeartDoc in Curves {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| Heart::new(d.scale))
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"rose","radius":1,"n":4,"planar":false}`.
    pub struct RoseDoc in Curves {
        /// Radius r (default 1).
        pub radius: f64 = 1.0,
        /// Petal parameter n (default 4).
        pub n: f64 = 4.0,
        /// Drop z = r sin(nt) (default false: the 3-D rose).
        #[serde(skip_serializing_if = "is_false")]
        pub planar: bool = false,
    }
    build(|d| Rose::new(d.radius, d.n, d.planar))
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"lissajous","amplitudes":[1,1,0],"frequencies":[3,2,0],"delta":π/2}`.
    pub struct LissajousDoc in Curves {
        /// (A, B, C) (default [1, 1, 0]).
        pub amplitudes: [f64; 3] = [1.0, 1.0, 0.0],
        /// (a, b, c) (default [3, 2, 0]).
        pub frequencies: [f64; 3] = [3.0, 2.0, 0.0],
        /// Phase of x (default π/2).
        pub delta: f64 = std::f64::consts::FRAC_PI_2,
    }
    build(|d| Lissajous::new(d.amplitudes, d.frequencies, d.delta))
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"trefoil","scale":1}`: s·(sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t).
    pub struct TrefoilDoc in Curves {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| Trefoil::new(d.scale))
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"butterfly","scale":1}`: Fay's butterfly, t ∈ [0, 24π].
    pub struct ButterflyDoc in Curves {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| Butterfly::new(d.scale))
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"trochoid","rolling":"inside","fixed_radius":5,"rolling_radius":3,"distance":5}`:
    /// the spirograph curve drawn by a pen at distance d from the centre of a circle of
    /// radius r rolling inside (hypotrochoid) or outside (epitrochoid) a circle of radius R,
    /// over its whole period t ∈ [0, 2π·q] where R/r = p/q, or over t ∈ [0, 2π·turns].
    pub struct TrochoidDoc in Curves {
        /// `"inside"` (default: the hypotrochoid) or `"outside"` (the epitrochoid).
        pub rolling: RollingDoc = RollingDoc::Inside,
        /// R (default 5).
        pub fixed_radius: f64 = 5.0,
        /// r (default 3).
        pub rolling_radius: f64 = 3.0,
        /// d (default 5).
        pub distance: f64 = 5.0,
        /// Turns of the rolling circle's centre (default: until the curve closes).
        #[serde(skip_serializing_if = "Option::is_none")]
        pub turns: Option<f64> = None,
    }
    build(|d| {
        let rolling = match d.rolling {
            RollingDoc::Inside => Rolling::Inside,
            RollingDoc::Outside => Rolling::Outside,
        };
        match d.turns {
            None => Trochoid::new(rolling, d.fixed_radius, d.rolling_radius, d.distance),
            Some(turns) => Trochoid::with_turns(rolling, d.fixed_radius, d.rolling_radius, d.distance, turns),
        }
    })
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"logarithmic_spiral","a":1,"b":0.1,"turns":4}`: (a e^{bt} cos t, a e^{bt} sin t, 0),
    /// t ∈ [0, 2π·turns].
    pub struct LogarithmicSpiralDoc in Curves {
        /// Radius at t = 0 (default 1).
        pub a: f64 = 1.0,
        /// Growth per radian, any finite value (default 0.1).
        pub b: f64 = 0.1,
        /// Turns (default 4).
        pub turns: f64 = 4.0,
    }
    build(|d| splinekit::curve::model::LogarithmicSpiral::new(d.a, d.b, d.turns))
    exact(|_d| CurveForm::Approximate)
}

model_document! {
    /// `{"type":"chrysanthemum","scale":1}`: s·r(t)(cos t, sin t, 0),
    /// r = 5(1 + sin(11t/5)) − 4 sin⁴(17t/3) sin⁸(2 cos 3t − 28t), t ∈ [0, 21π].
    pub struct ChrysanthemumDoc in Curves {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| splinekit::curve::model::Chrysanthemum::new(d.scale))
    exact(|_d| CurveForm::Approximate)
}

/// Where the circle of a trochoid rolls: `"inside"` or `"outside"` the fixed circle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
#[allow(missing_docs)]
pub enum RollingDoc {
    Inside,
    Outside,
}
