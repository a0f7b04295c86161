//! Centred trochoids, the spirograph curves: a circle of radius r rolls without slipping
//! inside (hypotrochoid) or outside (epitrochoid) a fixed circle of radius R, and a pen at
//! distance d from the rolling circle's centre draws the curve.
//!
//! With t the angle of the rolling circle's centre about the fixed centre,
//!
//! - hypotrochoid: c(t) = ((R − r) cos t + d cos(k t), (R − r) sin t − d sin(k t), 0), k = (R − r)/r,
//! - epitrochoid:  c(t) = ((R + r) cos t − d cos(k t), (R + r) sin t − d sin(k t), 0), k = (R + r)/r.
//!
//! Both are sums of two uniform circular motions, so every derivative is exact
//! (d^j/dt^j a cos(ωt) = a ω^j cos(ωt + jπ/2), see [`super::trig`]).
//!
//! **Period.** The centre returns after t = 2π and the pen's arm after t = 2π/k, so the
//! curve closes at the first t = 2π·q with both q and q·k whole numbers. Writing
//! R/r = p/q in lowest terms (k = (p ∓ q)/q), that is q = r/gcd(R, r) turns of the centre;
//! e.g. R = 5, r = 3 closes after 3 turns. [`Trochoid::new`] finds p/q from the numbers R
//! and r by continued fractions (a fraction within [`RATIO_TOLERANCE`] of R/r, with
//! q ≤ [`MAX_TURNS`]) and refuses ratios that do not close within that many turns, asking
//! for an explicit number of turns instead ([`Trochoid::with_turns`]).
//!
//! Special cases: d = 0 is a circle of radius R ∓ r; d = r gives the hypocycloid and
//! epicycloid, with cusps where c′ = 0; a hypotrochoid with R = 2r is the ellipse
//! ((r + d) cos t, (r − d) sin t); an epitrochoid with R = r = d is the cardioid.

use super::trig::{Term, TrigCurve, TrigSeries, finite, positive, trig_model_curve};
use crate::curve::Interval;
use std::f64::consts::TAU;

/// Where the rolling circle rolls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rolling {
    /// Inside the fixed circle: the hypotrochoid (the classic spirograph ring).
    Inside,
    /// Outside the fixed circle: the epitrochoid.
    Outside,
}

/// Largest number of turns q of the rolling circle's centre after which [`Trochoid::new`]
/// accepts a ratio R/r = p/q as closing.
pub const MAX_TURNS: u64 = 1000;

/// Largest relative difference |R/r − p/q| / (R/r) for which R/r is taken to be p/q
/// (decimal inputs such as R = 1, r = 0.3 are then read as 10/3).
pub const RATIO_TOLERANCE: f64 = 1e-12;

/// A hypotrochoid or epitrochoid in the plane z = 0 (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct Trochoid {
    curve: TrigCurve,
}

impl Trochoid {
    /// The closed trochoid over its whole period t ∈ [0, 2π·q], where R/r = p/q in lowest
    /// terms. R = `fixed_radius` > 0, r = `rolling_radius` > 0 (r ≠ R when rolling
    /// inside), d = `distance` finite. Fails when R/r is not within [`RATIO_TOLERANCE`] of
    /// a fraction with q ≤ [`MAX_TURNS`].
    pub fn new(rolling: Rolling, fixed_radius: f64, rolling_radius: f64, distance: f64) -> crate::Result<Self> {
        let (big, small) = radii(rolling, fixed_radius, rolling_radius)?;
        let (k, period) = arm_frequency(rolling, big / small);
        let q = period.ok_or_else(|| {
            crate::Error::invalid(
                "rolling_radius",
                format!(
                    "fixed_radius/rolling_radius = {} is not a fraction p/q with q ≤ {MAX_TURNS}, so the curve does \
                     not close within {MAX_TURNS} turns; give turns explicitly",
                    big / small
                ),
            )
        })?;
        Self::build(rolling, big, small, distance, k, TAU * q as f64, true)
    }

    /// The trochoid over t ∈ [0, 2π·turns] (turns > 0), closed when `turns` is a whole
    /// multiple of the period's q (within [`RATIO_TOLERANCE`]), open otherwise.
    pub fn with_turns(
        rolling: Rolling,
        fixed_radius: f64,
        rolling_radius: f64,
        distance: f64,
        turns: f64,
    ) -> crate::Result<Self> {
        let (big, small) = radii(rolling, fixed_radius, rolling_radius)?;
        let turns = positive("turns", turns)?;
        let (k, period) = arm_frequency(rolling, big / small);
        let closed = period.is_some_and(|q| is_whole(turns / q as f64));
        Self::build(rolling, big, small, distance, k, TAU * turns, closed)
    }

    fn build(
        rolling: Rolling,
        big: f64,
        small: f64,
        distance: f64,
        k: f64,
        end: f64,
        closed: bool,
    ) -> crate::Result<Self> {
        let d = finite("distance", distance)?;
        let (centre, arm) = match rolling {
            Rolling::Inside => (big - small, d),
            Rolling::Outside => (big + small, -d),
        };
        let x = TrigSeries::of(&[Term::cos(centre, 1.0), Term::cos(arm, k)]);
        let y = TrigSeries::of(&[Term::sin(centre, 1.0), Term::sin(-d, k)]);
        let curve = TrigCurve { coordinates: [x, y, TrigSeries::default()], domain: Interval::new(0.0, end), closed };
        Ok(Trochoid { curve })
    }
}

/// Checks R and r; a circle rolling inside one of its own size does not move.
fn radii(rolling: Rolling, fixed_radius: f64, rolling_radius: f64) -> crate::Result<(f64, f64)> {
    let big = positive("fixed_radius", fixed_radius)?;
    let small = positive("rolling_radius", rolling_radius)?;
    if rolling == Rolling::Inside && big == small {
        return Err(crate::Error::invalid(
            "rolling_radius",
            format!("a circle of radius {small} rolling inside one of the same radius does not move; choose r ≠ R"),
        ));
    }
    Ok((big, small))
}

/// The pen arm's angular frequency k = R/r ∓ 1 and the period's q when R/r = p/q closes
/// (then k = (p ∓ q)/q from the exact fraction, so that k·2πq is a whole number of turns).
fn arm_frequency(rolling: Rolling, ratio: f64) -> (f64, Option<u64>) {
    let sign = match rolling {
        Rolling::Inside => -1.0,
        Rolling::Outside => 1.0,
    };
    match closing_ratio(ratio) {
        Some((p, q)) => ((p as f64 + sign * q as f64) / q as f64, Some(q)),
        None => (ratio + sign, None),
    }
}

/// Whether x is within [`RATIO_TOLERANCE`] of a whole number.
fn is_whole(x: f64) -> bool {
    (x - x.round()).abs() <= RATIO_TOLERANCE * x.abs().max(1.0)
}

/// The fraction p/q in lowest terms with q ≤ [`MAX_TURNS`] within [`RATIO_TOLERANCE`] of
/// `ratio` > 0: the first such convergent of its continued fraction (convergents are the
/// best rational approximations, so none with a smaller q is closer).
fn closing_ratio(ratio: f64) -> Option<(u64, u64)> {
    let (mut h0, mut h1) = (0.0f64, 1.0f64);
    let (mut k0, mut k1) = (1.0f64, 0.0f64);
    let mut x = ratio;
    for _ in 0..64 {
        let a = x.floor();
        (h0, h1) = (h1, a * h1 + h0);
        (k0, k1) = (k1, a * k1 + k0);
        if k1 > MAX_TURNS as f64 {
            return None;
        }
        if (ratio - h1 / k1).abs() <= RATIO_TOLERANCE * ratio {
            return Some((h1 as u64, k1 as u64));
        }
        let frac = x - a;
        if frac == 0.0 {
            return None;
        }
        x = 1.0 / frac;
    }
    None
}

trig_model_curve!(Trochoid);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point;
    use crate::curve::Curve;

    fn eval(c: &Trochoid, t: f64, order: usize) -> Vec<Point<3>> {
        let mut out = vec![Point::<3>::zeros(); order + 1];
        c.eval(t, &mut out);
        out
    }

    /// The defining formula, evaluated directly.
    fn formula(rolling: Rolling, big: f64, small: f64, d: f64, t: f64) -> Point<3> {
        match rolling {
            Rolling::Inside => {
                let k = (big - small) / small;
                Point::<3>::new(
                    (big - small) * t.cos() + d * (k * t).cos(),
                    (big - small) * t.sin() - d * (k * t).sin(),
                    0.0,
                )
            }
            Rolling::Outside => {
                let k = (big + small) / small;
                Point::<3>::new(
                    (big + small) * t.cos() - d * (k * t).cos(),
                    (big + small) * t.sin() - d * (k * t).sin(),
                    0.0,
                )
            }
        }
    }

    #[test]
    fn positions_follow_the_rolling_circle_construction() {
        for (rolling, big, small, d) in
            [(Rolling::Inside, 5.0, 3.0, 5.0), (Rolling::Outside, 3.0, 1.0, 0.5), (Rolling::Inside, 7.0, 2.0, 1.0)]
        {
            let c = Trochoid::new(rolling, big, small, d).unwrap();
            let dom = c.domain();
            for i in 0..=40 {
                let t = dom.lerp(i as f64 / 40.0);
                let p = c.point(t);
                assert!((p - formula(rolling, big, small, d, t)).norm() < 1e-12 * big, "{rolling:?} t = {t}");
            }
        }
    }

    #[test]
    fn derivatives_match_central_differences() {
        let h = 1e-4;
        for rolling in [Rolling::Inside, Rolling::Outside] {
            let c = Trochoid::new(rolling, 5.0, 3.0, 2.0).unwrap();
            for &t in &[0.3, 1.7, 4.0, 11.5] {
                let d = eval(&c, t, 4);
                for k in 1..=4 {
                    // (f^{(k−1)}(t + h) − f^{(k−1)}(t − h)) / 2h, error O(h²·|f^{(k+2)}|).
                    let fd = (eval(&c, t + h, k - 1)[k - 1] - eval(&c, t - h, k - 1)[k - 1]) / (2.0 * h);
                    let scale = d[k].norm().max(1.0);
                    assert!((fd - d[k]).norm() < 1e-6 * scale, "{rolling:?} order {k} at {t}");
                }
            }
        }
    }

    #[test]
    fn derivatives_match_the_closed_form() {
        // Hypotrochoid R = 7, r = 2, d = 1.5: k = 5/2;
        // c^{(j)} = (R − r)(cos, sin)^{(j)}(t) + d (k^j cos^{(j)}(kt), −k^j sin^{(j)}(kt)).
        let (big, small, d) = (7.0, 2.0, 1.5);
        let c = Trochoid::new(Rolling::Inside, big, small, d).unwrap();
        let k: f64 = 2.5;
        let t = 0.9;
        let cos_j = |j: usize, x: f64| (x + j as f64 * std::f64::consts::FRAC_PI_2).cos();
        let sin_j = |j: usize, x: f64| (x + j as f64 * std::f64::consts::FRAC_PI_2).sin();
        let out = eval(&c, t, 7);
        for (j, v) in out.iter().enumerate() {
            let kj = k.powi(j as i32);
            let x = (big - small) * cos_j(j, t) + d * kj * cos_j(j, k * t);
            let y = (big - small) * sin_j(j, t) - d * kj * sin_j(j, k * t);
            assert!((v - Point::<3>::new(x, y, 0.0)).norm() < 1e-11 * kj.max(1.0) * big, "order {j}");
        }
    }

    #[test]
    fn hypotrochoid_with_fixed_radius_twice_the_rolling_one_is_an_ellipse() {
        let (r, d) = (2.0, 0.5);
        let c = Trochoid::new(Rolling::Inside, 2.0 * r, r, d).unwrap();
        assert_eq!(c.domain(), Interval::new(0.0, TAU));
        for i in 0..16 {
            let t = TAU * i as f64 / 16.0;
            let e = Point::<3>::new((r + d) * t.cos(), (r - d) * t.sin(), 0.0);
            assert!((c.point(t) - e).norm() < 1e-14 * (r + d), "t = {t}");
            let de = Point::<3>::new(-(r + d) * t.sin(), (r - d) * t.cos(), 0.0);
            assert!((c.derivative(t, 1) - de).norm() < 1e-14 * (r + d));
        }
    }

    #[test]
    fn cycloids_have_cusps_exactly_where_the_pen_touches_the_fixed_circle() {
        // d = r: the pen is on the rolling circle; it stops (c′ = 0) at t_j = 2πj r/R, on
        // the fixed circle |c| = R, and moves everywhere else.
        for rolling in [Rolling::Inside, Rolling::Outside] {
            let (big, small) = (5.0, 2.0);
            let c = Trochoid::new(rolling, big, small, small).unwrap();
            let q = 2; // 5/2 closes after 2 turns, with p = 5 cusps.
            assert_eq!(c.domain().end, TAU * q as f64);
            for j in 0..5 {
                let t = TAU * j as f64 * small / big;
                assert!(c.derivative(t, 1).norm() < 1e-12 * big, "{rolling:?} cusp {j}");
                assert!((c.point(t).norm() - big).abs() < 1e-12 * big);
                let between = t + TAU * small / big / 2.0;
                assert!(c.derivative(between, 1).norm() > 0.5, "{rolling:?} between cusps");
            }
        }
    }

    #[test]
    fn epitrochoid_with_equal_radii_and_arm_is_the_cardioid() {
        let a = 1.5;
        let c = Trochoid::new(Rolling::Outside, a, a, a).unwrap();
        assert_eq!(c.domain(), Interval::new(0.0, TAU));
        for i in 0..12 {
            let t = TAU * i as f64 / 12.0;
            let e = Point::<3>::new(a * (2.0 * t.cos() - (2.0 * t).cos()), a * (2.0 * t.sin() - (2.0 * t).sin()), 0.0);
            assert!((c.point(t) - e).norm() < 1e-14 * 4.0 * a);
        }
    }

    #[test]
    fn the_curve_closes_after_its_period_and_not_before() {
        // R/r = 5/3 closes after q = 3 turns. On the twice-as-long domain [0, 12π] the
        // parameter 6π is interior (no wrapping), so this checks the period itself:
        // c^{(j)}(6π) = c^{(j)}(0) for every order.
        for rolling in [Rolling::Inside, Rolling::Outside] {
            let c = Trochoid::new(rolling, 5.0, 3.0, 2.2).unwrap();
            assert!(c.is_closed());
            assert_eq!(c.domain(), Interval::new(0.0, 3.0 * TAU));
            let twice = Trochoid::with_turns(rolling, 5.0, 3.0, 2.2, 6.0).unwrap();
            assert!(twice.is_closed());
            let (start, period) = (eval(&twice, 0.0, 4), eval(&twice, 3.0 * TAU, 4));
            for j in 0..=4 {
                assert!((start[j] - period[j]).norm() < 1e-12 * 10.0 * 3f64.powi(j as i32), "{rolling:?} order {j}");
            }
            for turn in [1.0, 2.0] {
                assert!((twice.point(turn * TAU) - start[0]).norm() > 0.1, "{rolling:?} closed early at {turn}");
            }
            // The closed curve's two ends agree to the last bit, derivatives included.
            let dom = c.domain();
            assert_eq!(eval(&c, dom.start, 3), eval(&c, dom.end, 3));
        }
    }

    #[test]
    fn decimal_radii_are_read_as_their_fraction() {
        // 1/0.3 is 10/3 to within rounding: closes after 3 turns.
        let c = Trochoid::new(Rolling::Inside, 1.0, 0.3, 0.2).unwrap();
        assert_eq!(c.domain().end, 3.0 * TAU);
        // 96/36 = 8/3: the spirograph's 96-tooth ring with a 36-tooth wheel.
        let c = Trochoid::new(Rolling::Inside, 96.0, 36.0, 20.0).unwrap();
        assert_eq!(c.domain().end, 3.0 * TAU);
    }

    #[test]
    fn ratios_that_never_close_ask_for_turns() {
        let err = Trochoid::new(Rolling::Inside, std::f64::consts::PI, 1.0, 0.5).unwrap_err().to_string();
        assert!(err.starts_with("rolling_radius:") && err.contains("give turns explicitly"), "{err}");
        let c = Trochoid::with_turns(Rolling::Inside, std::f64::consts::PI, 1.0, 0.5, 10.0).unwrap();
        assert!(!c.is_closed());
        assert_eq!(c.domain().end, 10.0 * TAU);
        // Whole turns that are not a multiple of the period leave the curve open.
        assert!(!Trochoid::with_turns(Rolling::Inside, 5.0, 3.0, 1.0, 2.0).unwrap().is_closed());
    }

    #[test]
    fn bad_parameters_name_their_field() {
        let msg = |r: crate::Result<Trochoid>| r.unwrap_err().to_string();
        assert!(msg(Trochoid::new(Rolling::Inside, 0.0, 1.0, 1.0)).starts_with("fixed_radius:"));
        assert!(msg(Trochoid::new(Rolling::Outside, 1.0, f64::NAN, 1.0)).starts_with("rolling_radius:"));
        assert!(msg(Trochoid::new(Rolling::Inside, 2.0, 2.0, 1.0)).starts_with("rolling_radius:"));
        assert!(msg(Trochoid::new(Rolling::Inside, 5.0, 3.0, f64::INFINITY)).starts_with("distance:"));
        assert!(msg(Trochoid::with_turns(Rolling::Inside, 5.0, 3.0, 1.0, -1.0)).starts_with("turns:"));
        // A circle rolling outside one of its own size is fine (the limaçons).
        assert!(Trochoid::new(Rolling::Outside, 2.0, 2.0, 1.0).is_ok());
    }
}
