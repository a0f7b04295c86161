//! Surfaces whose two parameter directions each come from one object with a domain and a
//! closedness of its own (a sweep's profile and path, a blending surface's two knot
//! vectors): the domain methods they share.

/// Writes, inside an `impl Surface<…> for …`, `domain_u` and `is_closed_u` as the
/// `domain()` and `is_closed()` of the field `$u`, and `domain_v`, `is_closed_v` as those
/// of the field `$v`.
macro_rules! axes_surface_domains {
    ($u:ident, $v:ident) => {
        fn domain_u(&self) -> $crate::Interval {
            self.$u.domain()
        }
        fn domain_v(&self) -> $crate::Interval {
            self.$v.domain()
        }
        fn is_closed_u(&self) -> bool {
            self.$u.is_closed()
        }
        fn is_closed_v(&self) -> bool {
            self.$v.is_closed()
        }
    };
}
pub(crate) use axes_surface_domains;
