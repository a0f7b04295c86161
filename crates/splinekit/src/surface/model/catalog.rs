//! The model surfaces. Each states its formula, domain and closedness; all are 3-D.

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::Point;
use crate::curve::Interval;
use crate::curve::model::{Term, TrigSeries};
use crate::error::{Result, check_points_finite};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

macro_rules! model {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[derive(Debug, Clone, PartialEq)]
        pub struct $name {
            surface: SeparableSurface,
        }
        separable_model_surface!($name);
    };
}

fn one() -> F {
    F::constant(1.0)
}
fn linear(a: f64, b: f64) -> F {
    F::Polynomial(vec![a, b])
}

/// The surface (r g(v) cos u, r g(v) sin u, h v), u ∈ [0, 2π] closed, v ∈ [0, 1]: the
/// profile radius r g(v) turned about the z-axis (g = 1 a cylinder, g = 1 − v a cone).
fn about_z(r: f64, g: F, h: f64) -> SeparableSurface {
    SeparableSurface {
        coordinates: [
            vec![term(r, F::cos(1.0, 1.0), g.clone())],
            vec![term(r, F::sin(1.0, 1.0), g)],
            vec![term(h, one(), linear(0.0, 1.0))],
        ],
        domain_u: Interval::new(0.0, TAU),
        domain_v: Interval::new(0.0, 1.0),
        closed_u: true,
        closed_v: false,
    }
}

model!(
    /// The plane origin + u·U + v·V on [0, 1]², open.
    Plane
);
impl Plane {
    /// The plane spanned by two axes at an origin.
    pub fn new(origin: Point<3>, u_axis: Point<3>, v_axis: Point<3>) -> Result<Self> {
        check_points_finite("origin", &[origin])?;
        check_points_finite("u_axis", &[u_axis])?;
        check_points_finite("v_axis", &[v_axis])?;
        let coord = |c: usize| {
            vec![
                term(origin[c], one(), one()),
                term(u_axis[c], linear(0.0, 1.0), one()),
                term(v_axis[c], one(), linear(0.0, 1.0)),
            ]
        };
        Ok(Plane {
            surface: SeparableSurface {
                coordinates: [coord(0), coord(1), coord(2)],
                domain_u: Interval::new(0.0, 1.0),
                domain_v: Interval::new(0.0, 1.0),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}

model!(
    /// The cylinder (r cos u, r sin u, h v), u ∈ [0, 2π] closed, v ∈ [0, 1].
    Cylinder
);
impl Cylinder {
    /// Radius r > 0 and height h > 0.
    pub fn new(radius: f64, height: f64) -> Result<Self> {
        let (r, h) = (positive("radius", radius)?, positive("height", height)?);
        Ok(Cylinder { surface: about_z(r, one(), h) })
    }
}

model!(
    /// The cone (r (1 − v) cos u, r (1 − v) sin u, h v), u ∈ [0, 2π] closed, v ∈ [0, 1]
    /// (apex at v = 1).
    Cone
);
impl Cone {
    /// Base radius r > 0 and height h > 0.
    pub fn new(radius: f64, height: f64) -> Result<Self> {
        let (r, h) = (positive("radius", radius)?, positive("height", height)?);
        Ok(Cone { surface: about_z(r, linear(1.0, -1.0), h) })
    }
}

model!(
    /// The sphere (r cos u cos v, r sin u cos v, r sin v), u ∈ [0, 2π] closed,
    /// v ∈ [−π/2, π/2] (poles at the ends).
    Sphere
);
impl Sphere {
    /// Radius r > 0.
    pub fn new(radius: f64) -> Result<Self> {
        let r = positive("radius", radius)?;
        Ok(Sphere {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(r, F::cos(1.0, 1.0), F::cos(1.0, 1.0))],
                    vec![term(r, F::sin(1.0, 1.0), F::cos(1.0, 1.0))],
                    vec![term(r, one(), F::sin(1.0, 1.0))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(-FRAC_PI_2, FRAC_PI_2),
                closed_u: true,
                closed_v: false,
            },
        })
    }
}

/// The torus ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), u, v ∈ [0, 2π],
/// closed both ways.
#[derive(Debug, Clone, PartialEq)]
pub struct Torus {
    surface: SeparableSurface,
    major: f64,
    minor: f64,
}

impl crate::surface::Surface<3> for Torus {
    fn domain_u(&self) -> Interval {
        self.surface.domain_u
    }
    fn domain_v(&self) -> Interval {
        self.surface.domain_v
    }
    fn is_closed_u(&self) -> bool {
        true
    }
    fn is_closed_v(&self) -> bool {
        true
    }
    /// The separable terms' partials in closed form, one sine and cosine per angle:
    /// ∂ⁱ_u∂ʲ_v x = ρ_j cos⁽ⁱ⁾u, y = ρ_j sin⁽ⁱ⁾u with ρ_j = [j = 0]·R + r cos⁽ʲ⁾v, and
    /// z = [i = 0]·r sin⁽ʲ⁾v (the values of the separable form, which tests compare).
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let side = crate::basis::Side::Right;
        let (u, v) = (self.surface.domain_u.wrap_periodic(u, side), self.surface.domain_v.wrap_periodic(v, side));
        let ((su, cu), (sv, cv)) = (u.sin_cos(), v.sin_cos());
        // k-th derivatives of cos and sin: cos, −sin, −cos, sin and sin, cos, −sin, −cos.
        let dcos = |k: usize, s: f64, c: f64| [c, -s, -c, s][k % 4];
        let dsin = |k: usize, s: f64, c: f64| [s, c, -s, -c][k % 4];
        for i in 0..=du {
            for j in 0..=dv {
                let rho = if j == 0 { self.major } else { 0.0 } + self.minor * dcos(j, sv, cv);
                let z = if i == 0 { self.minor * dsin(j, sv, cv) } else { 0.0 };
                out[i * (dv + 1) + j] = Point::<3>::new(rho * dcos(i, su, cu), rho * dsin(i, su, cu), z);
            }
        }
    }
}

impl Torus {
    /// Major radius R and minor radius r, 0 < r.
    pub fn new(major_radius: f64, minor_radius: f64) -> Result<Self> {
        let (big, r) = (positive("major_radius", major_radius)?, positive("minor_radius", minor_radius)?);
        Ok(Torus {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(big, F::cos(1.0, 1.0), one()), term(r, F::cos(1.0, 1.0), F::cos(1.0, 1.0))],
                    vec![term(big, F::sin(1.0, 1.0), one()), term(r, F::sin(1.0, 1.0), F::cos(1.0, 1.0))],
                    vec![term(r, one(), F::sin(1.0, 1.0))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(0.0, TAU),
                closed_u: true,
                closed_v: true,
            },
            major: big,
            minor: r,
        })
    }
}

model!(
    /// The Möbius strip ((R + v cos(u/2)) cos u, (R + v cos(u/2)) sin u, v sin(u/2)),
    /// u ∈ [0, 2π], v ∈ [−w, w]. Its ends meet with a flip, so it is not closed in u as a
    /// parametrisation.
    MobiusStrip
);
impl MobiusStrip {
    /// Centre radius R > 0 and half-width w > 0.
    pub fn new(radius: f64, half_width: f64) -> Result<Self> {
        let (big, w) = (positive("radius", radius)?, positive("half_width", half_width)?);
        // cos(u/2) cos u = ½(cos(3u/2) + cos(u/2)), cos(u/2) sin u = ½(sin(3u/2) + sin(u/2)).
        let half_sum_cos = F::Series(TrigSeries::of(&[Term::cos(0.5, 1.5), Term::cos(0.5, 0.5)]));
        let half_sum_sin = F::Series(TrigSeries::of(&[Term::sin(0.5, 1.5), Term::sin(0.5, 0.5)]));
        let v = linear(0.0, 1.0);
        Ok(MobiusStrip {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(big, F::cos(1.0, 1.0), one()), term(1.0, half_sum_cos, v.clone())],
                    vec![term(big, F::sin(1.0, 1.0), one()), term(1.0, half_sum_sin, v.clone())],
                    vec![term(1.0, F::sin(1.0, 0.5), v)],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(-w, w),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}

model!(
    /// The figure-8 Klein bottle: with a = R + cos(u/2) sin v − sin(u/2) sin 2v,
    /// (a cos u, a sin u, sin(u/2) sin v + cos(u/2) sin 2v), u, v ∈ [0, 2π]. Closed in v;
    /// in u the ends meet with a flip.
    KleinBottle
);
impl KleinBottle {
    /// Radius R > 0 (default 3 in documents).
    pub fn new(radius: f64) -> Result<Self> {
        let big = positive("radius", radius)?;
        let c2 = |a: f64, w: f64| F::cos(a, w);
        let s2 = |a: f64, w: f64| F::sin(a, w);
        // cos(u/2)cos u = ½[cos(3u/2) + cos(u/2)], sin(u/2)cos u = ½[sin(3u/2) − sin(u/2)],
        // cos(u/2)sin u = ½[sin(3u/2) + sin(u/2)], sin(u/2)sin u = ½[cos(u/2) − cos(3u/2)].
        let ser = |t: &[Term]| F::Series(TrigSeries::of(t));
        let cc = ser(&[Term::cos(0.5, 1.5), Term::cos(0.5, 0.5)]);
        let sc = ser(&[Term::sin(0.5, 1.5), Term::sin(-0.5, 0.5)]);
        let cs = ser(&[Term::sin(0.5, 1.5), Term::sin(0.5, 0.5)]);
        let ss = ser(&[Term::cos(0.5, 0.5), Term::cos(-0.5, 1.5)]);
        Ok(KleinBottle {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(big, c2(1.0, 1.0), one()), term(1.0, cc, s2(1.0, 1.0)), term(-1.0, sc, s2(1.0, 2.0))],
                    vec![term(big, s2(1.0, 1.0), one()), term(1.0, cs, s2(1.0, 1.0)), term(-1.0, ss, s2(1.0, 2.0))],
                    vec![term(1.0, s2(1.0, 0.5), s2(1.0, 1.0)), term(1.0, c2(1.0, 0.5), s2(1.0, 2.0))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(0.0, TAU),
                closed_u: false,
                closed_v: true,
            },
        })
    }
}

model!(
    /// Enneper's minimal surface (u − u³/3 + u v², v − v³/3 + v u², u² − v²) on
    /// [−e, e]², open.
    Enneper
);
impl Enneper {
    /// Half-extent e > 0 of the square domain.
    pub fn new(extent: f64) -> Result<Self> {
        let e = positive("extent", extent)?;
        let p = |c: &[f64]| F::Polynomial(c.to_vec());
        Ok(Enneper {
            surface: SeparableSurface {
                coordinates: [
                    vec![
                        term(1.0, p(&[0.0, 1.0, 0.0, -1.0 / 3.0]), one()),
                        term(1.0, p(&[0.0, 1.0]), p(&[0.0, 0.0, 1.0])),
                    ],
                    vec![
                        term(1.0, one(), p(&[0.0, 1.0, 0.0, -1.0 / 3.0])),
                        term(1.0, p(&[0.0, 0.0, 1.0]), p(&[0.0, 1.0])),
                    ],
                    vec![term(1.0, p(&[0.0, 0.0, 1.0]), one()), term(-1.0, one(), p(&[0.0, 0.0, 1.0]))],
                ],
                domain_u: Interval::new(-e, e),
                domain_v: Interval::new(-e, e),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}

model!(
    /// The helicoid (v cos u, v sin u, pitch·u/2π), u ∈ [0, 2π·turns], v ∈ [−r, r], open.
    Helicoid
);
impl Helicoid {
    /// Radius r > 0, rise per turn, number of turns > 0.
    pub fn new(radius: f64, pitch: f64, turns: f64) -> Result<Self> {
        let (r, t) = (positive("radius", radius)?, positive("turns", turns)?);
        if !pitch.is_finite() {
            return Err(crate::Error::invalid("pitch", format!("must be finite, got {pitch}")));
        }
        let v = linear(0.0, 1.0);
        Ok(Helicoid {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(1.0, F::cos(1.0, 1.0), v.clone())],
                    vec![term(1.0, F::sin(1.0, 1.0), v)],
                    vec![term(pitch / TAU, linear(0.0, 1.0), one())],
                ],
                domain_u: Interval::new(0.0, TAU * t),
                domain_v: Interval::new(-r, r),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}

model!(
    /// A seashell: with s = 1 − v/2π, ((a s (1 + cos u) + c) cos nv, (a s (1 + cos u) + c)
    /// sin nv, b v/2π + a s sin u), u ∈ [0, 2π] closed, v ∈ [0, 2π].
    Seashell
);
impl Seashell {
    /// Tube radius a, height b, inner radius c, turns n.
    pub fn new(a: f64, b: f64, c: f64, turns: f64) -> Result<Self> {
        let (a, b, n) = (positive("a", a)?, positive("b", b)?, positive("turns", turns)?);
        if !(c.is_finite() && c >= 0.0) {
            return Err(crate::Error::invalid("c", format!("must be finite and ≥ 0, got {c}")));
        }
        let s = linear(1.0, -1.0 / TAU);
        let one_plus_cos =
            F::Series(TrigSeries { constant: 1.0, linear: 0.0, terms: smallvec::smallvec![Term::cos(1.0, 1.0)] });
        Ok(Seashell {
            surface: SeparableSurface {
                coordinates: [
                    vec![
                        term(a, one_plus_cos.clone(), s.clone().times(F::cos(1.0, n))),
                        term(c, one(), F::cos(1.0, n)),
                    ],
                    vec![term(a, one_plus_cos, s.clone().times(F::sin(1.0, n))), term(c, one(), F::sin(1.0, n))],
                    vec![term(b / TAU, one(), linear(0.0, 1.0)), term(a, F::sin(1.0, 1.0), s)],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(0.0, TAU),
                closed_u: true,
                closed_v: false,
            },
        })
    }
}

model!(
    /// GMlib's apple: (cos u (4 + 3.8 cos v), sin u (4 + 3.8 cos v),
    /// (cos v + sin v − 1)(1 + sin v) ln(1 − πv/10) + 7.5 sin v), u ∈ [0, 2π] closed,
    /// v ∈ [−π, π], scaled by `scale`.
    Apple
);
impl Apple {
    /// The apple scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let s = positive("scale", scale)?;
        let ring =
            F::Series(TrigSeries { constant: 4.0, linear: 0.0, terms: smallvec::smallvec![Term::cos(3.8, 1.0)] });
        // (cos v + sin v − 1)(1 + sin v) = cos v − ½ + ½ sin 2v − ½ cos 2v.
        let bump = F::Series(TrigSeries {
            constant: -0.5,
            linear: 0.0,
            terms: smallvec::smallvec![Term::cos(1.0, 1.0), Term::sin(0.5, 2.0), Term::cos(-0.5, 2.0)],
        });
        let z = bump.times(F::LogOneMinus(PI / 10.0));
        Ok(Apple {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(s, F::cos(1.0, 1.0), ring.clone())],
                    vec![term(s, F::sin(1.0, 1.0), ring)],
                    vec![term(s, one(), z), term(7.5 * s, one(), F::sin(1.0, 1.0))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(-PI, PI),
                closed_u: true,
                closed_v: false,
            },
        })
    }
}

model!(
    /// A heart-shaped surface of revolution: the right half of the heart curve,
    /// h(u) = (16 sin³u, 13 cos u − 5 cos 2u − 2 cos 3u − cos 4u), u ∈ [0, π], turned about
    /// its axis: (h_x(u) cos v, h_x(u) sin v, h_y(u)), v ∈ [0, 2π] closed.
    HeartSurface
);
impl HeartSurface {
    /// The heart scaled by `scale` > 0 (1: 16 units wide).
    pub fn new(scale: f64) -> Result<Self> {
        let s = positive("scale", scale)?;
        let hx = F::Series(TrigSeries::of(&[Term::sin(12.0, 1.0), Term::sin(-4.0, 3.0)]));
        let hy = F::Series(TrigSeries::of(&[
            Term::cos(13.0, 1.0),
            Term::cos(-5.0, 2.0),
            Term::cos(-2.0, 3.0),
            Term::cos(-1.0, 4.0),
        ]));
        Ok(HeartSurface {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(s, hx.clone(), F::cos(1.0, 1.0))],
                    vec![term(s, hx, F::sin(1.0, 1.0))],
                    vec![term(s, hy, one())],
                ],
                domain_u: Interval::new(0.0, PI),
                domain_v: Interval::new(0.0, TAU),
                closed_u: false,
                closed_v: true,
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::Surface;

    #[test]
    fn the_torus_closed_form_matches_its_separable_terms() {
        let torus = Torus::new(3.0, 1.25).unwrap();
        for (u, v) in [(0.0, 0.0), (0.7, 2.9), (-1.3, 7.1), (TAU, 4.4)] {
            let (mut ours, mut terms) = ([Point::<3>::zeros(); 16], [Point::<3>::zeros(); 16]);
            torus.eval_partials(u, v, 3, 3, &mut ours);
            torus.surface.eval_into(u, v, 3, 3, &mut terms);
            for (a, b) in ours.iter().zip(&terms) {
                assert!((a - b).norm() <= 1e-14 * 5.0, "at ({u}, {v}): {a:?} vs {b:?}");
            }
        }
    }
}
