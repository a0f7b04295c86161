//! Shapes that lie in the convex hull of their control points (Bézier and B-spline curves
//! and surfaces, rational Bézier and NURBS curves and NURBS surfaces with positive
//! weights): the box of the control points encloses them, a cheap and certain
//! `enclosing_box`.

/// Writes, inside an `impl Curve<D> for …` of a type with `control_points()` (a slice of
/// points), the method `enclosing_box` as the box of the control points (exact bounds of
/// the points, no margin); with `net` first, inside an `impl Surface<D> for …` of a type
/// whose `control_points()` is a net (rows of points), the box of every point of the net.
/// `$kind` names the shape in the method's documentation ("a Bézier curve").
macro_rules! control_point_box {
    ($kind:literal) => {
        $crate::curve::control_box::control_point_box!(@box "points", "curve", $kind, control_points());
    };
    (net $kind:literal) => {
        $crate::curve::control_box::control_point_box!(@box "net", "surface", $kind, control_points().iter().flatten());
    };
    (@box $what:literal, $shape:literal, $kind:literal, $($points:tt)+) => {
        #[doc = concat!("The box of the control ", $what, ": it holds the ", $shape, ", since ", $kind, " lies in the")]
        #[doc = "convex hull of its control points; not tight in general."]
        fn enclosing_box(&self) -> Option<$crate::query::Aabb<D>> {
            Some($crate::query::Aabb::around(self.$($points)+, 0.0))
        }
    };
}
pub(crate) use control_point_box;
