//! The [`Surface`](crate::surface::Surface) methods a wrapping surface takes unchanged from
//! the surface it wraps.
//!
//! A wrapper that keeps the parameters of its inner surface S (a rigid placement
//! R S + o, a trim that only masks the domain, a cache of samples) has S's domains
//! [u₀, u₁] × [v₀, v₁] and S's closedness in each direction; only its evaluation or its
//! trim differs. [`wrapped_surface_domains!`](crate::wrapped_surface_domains) writes those
//! four methods once for every such wrapper, in this crate and out of it.

/// Writes, inside an `impl Surface<…> for W`, the methods `domain_u`, `domain_v`,
/// `is_closed_u` and `is_closed_v` as those of the surface in W's field `$field`.
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::surface::Surface;
/// use splinekit::surface::model::Sphere;
/// // A sphere seen from twice as far: the same parameters, points halved.
/// struct Half(Sphere);
/// impl Surface<3> for Half {
///     splinekit::wrapped_surface_domains!(0);
///     fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
///         self.0.eval_partials(u, v, du, dv, out);
///         out[..(du + 1) * (dv + 1)].iter_mut().for_each(|p| *p /= 2.0);
///     }
/// }
/// let (s, h) = (Sphere::new(2.0).unwrap(), Half(Sphere::new(2.0).unwrap()));
/// assert_eq!((h.domain_u(), h.domain_v()), (s.domain_u(), s.domain_v()));
/// assert_eq!((h.is_closed_u(), h.is_closed_v()), (s.is_closed_u(), s.is_closed_v()));
/// assert_eq!(h.point(0.3, 0.4), s.point(0.3, 0.4) / 2.0);
/// ```
#[macro_export]
macro_rules! wrapped_surface_domains {
    ($field:tt) => {
        fn domain_u(&self) -> $crate::Interval {
            self.$field.domain_u()
        }
        fn domain_v(&self) -> $crate::Interval {
            self.$field.domain_v()
        }
        fn is_closed_u(&self) -> bool {
            self.$field.is_closed_u()
        }
        fn is_closed_v(&self) -> bool {
            self.$field.is_closed_v()
        }
    };
}
