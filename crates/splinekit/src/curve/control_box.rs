//! Curves that lie in the convex hull of their control points (Bézier and B-spline curves,
//! rational Bézier and NURBS curves with positive weights): the box of the control points
//! encloses them, a cheap and certain `enclosing_box`.

/// Writes, inside an `impl Curve<D> for …` of a type with `control_points()`, the method
/// `enclosing_box` as the box of the control points (exact bounds of the points, no
/// margin); `$kind` names the curve in the method's documentation ("a Bézier curve").
macro_rules! control_point_box {
    ($kind:literal) => {
        #[doc = concat!("The box of the control points: it holds the curve, since ", $kind, " lies in the")]
        #[doc = "convex hull of its control points; not tight in general."]
        fn enclosing_box(&self) -> Option<$crate::query::Aabb<D>> {
            Some($crate::query::Aabb::around(self.control_points(), 0.0))
        }
    };
}
pub(crate) use control_point_box;
