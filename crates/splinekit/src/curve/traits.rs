//! The [`Curve`] trait: what every parametric curve c: [a, b] → ℝᴰ can do.

use smallvec::{SmallVec, smallvec};

use crate::basis::Side;
use crate::{Interval, Point};

/// The part of c″ normal to the tangent counts as zero (no principal normal: the curve is
/// straight there) below this fraction of |c″|.
pub const STRAIGHT_RELATIVE: f64 = 1e-14;

/// The Frenet frame of a curve at a parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrenetFrame<const D: usize> {
    /// Unit tangent T = c'/|c'|.
    pub tangent: Point<D>,
    /// Unit principal normal N = (c'' − (c''·T)T)/|…|, `None` where the curvature vanishes.
    pub normal: Option<Point<D>>,
    /// Binormal B = T × N (3-D curves with a normal only).
    pub binormal: Option<Point<D>>,
    /// Curvature κ.
    pub curvature: f64,
}

/// A parametric curve c: [a, b] → ℝᴰ.
///
/// Implementors provide [`Curve::domain`] and [`Curve::eval_side`] (and
/// [`Curve::is_closed`] when the curve is periodic), which writes the position and the first `out.len() − 1`
/// derivatives with respect to the curve's own parameter into a caller-provided buffer
/// (no heap allocation per call for the curves of this crate at practical degrees).
///
/// Parameters outside the domain are clamped for open curves and wrapped periodically for
/// closed ones.
///
/// # Examples
///
/// ```
/// use splinekit::curve::{Curve, CurveArcLength};
/// use splinekit::curve::model::Circle;
/// // The circle of radius 2: curvature ½ everywhere, length 4π, closed.
/// let c = Circle::new(2.0).unwrap();
/// assert!(c.is_closed());
/// assert!((c.curvature(0.3) - 0.5).abs() < 1e-15);
/// assert!((c.length(1e-12) - 4.0 * std::f64::consts::PI).abs() < 1e-12);
/// // Position and the first two derivatives in one call, into a buffer of the caller.
/// let mut out = [splinekit::Point::<3>::zeros(); 3];
/// c.eval(0.0, &mut out);
/// assert_eq!(out[1], splinekit::Point::<3>::new(0.0, 2.0, 0.0));
/// ```
pub trait Curve<const D: usize>: Send + Sync {
    /// The parameter domain [a, b].
    fn domain(&self) -> Interval;

    /// Whether c(a) = c(b) with the curve continuing smoothly (periodic). Most kinds are
    /// open; the default says so.
    fn is_closed(&self) -> bool {
        false
    }

    /// Writes c(t), c'(t), …, c^{(k)}(t) into `out[0..=k]`, k = `out.len() − 1`.
    /// At a parameter where the curve is not smooth, `side` selects the one-sided limit.
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]);

    /// [`Curve::eval_side`] with the right-hand limit.
    #[inline]
    fn eval(&self, t: f64, out: &mut [Point<D>]) {
        self.eval_side(t, Side::Right, out)
    }

    /// Evaluates at many parameters: `out[i*(order+1) + k]` = c^{(k)}(`params[i]`).
    /// Spline curves override this to reuse span search and basis work.
    fn eval_many(&self, params: &[f64], order: usize, out: &mut [Point<D>]) {
        let w = order + 1;
        for (i, &t) in params.iter().enumerate() {
            self.eval(t, &mut out[i * w..(i + 1) * w]);
        }
    }

    /// [`Curve::eval_many`] into memory not yet written (a new output array): the same
    /// values, and every one of the first `params.len() · (order + 1)` slots written. The
    /// default zeroes `out` and calls `eval_many`; B-spline curves write each slot once
    /// ([`crate::curve::output_slot`]).
    fn eval_many_uninit(&self, params: &[f64], order: usize, out: &mut [std::mem::MaybeUninit<Point<D>>]) {
        self.eval_many(params, order, crate::curve::output_slot::zeroed(out))
    }

    /// Parameters where the curve may lose smoothness (knots, segment joins), including
    /// both ends of the domain, in increasing order. Integration and search use them.
    fn breakpoints(&self) -> Vec<f64> {
        let d = self.domain();
        vec![d.start, d.end]
    }

    /// The point c(t).
    #[inline]
    fn point(&self, t: f64) -> Point<D> {
        let mut out = [Point::<D>::zeros()];
        self.eval(t, &mut out);
        out[0]
    }

    /// The derivative c^{(order)}(t).
    fn derivative(&self, t: f64, order: usize) -> Point<D> {
        let mut out: SmallVec<[Point<D>; 4]> = smallvec![Point::<D>::zeros(); order + 1];
        self.eval(t, &mut out);
        out[order]
    }

    /// The unit tangent c'/|c'|; the zero vector where the curve is not regular.
    fn tangent(&self, t: f64) -> Point<D> {
        let d = self.derivative(t, 1);
        let n = d.norm();
        if n > 0.0 { d / n } else { d }
    }

    /// Curvature κ = √(|c'|²|c''|² − (c'·c'')²) / |c'|³ (in 3-D, |c'×c''|/|c'|³);
    /// zero where c' vanishes.
    fn curvature(&self, t: f64) -> f64 {
        let mut out = [Point::<D>::zeros(); 3];
        self.eval(t, &mut out);
        curvature_from(&out[1], &out[2])
    }

    /// The Frenet frame (tangent, principal normal, binormal in 3-D, curvature);
    /// `None` where c' vanishes.
    fn frame(&self, t: f64) -> Option<FrenetFrame<D>> {
        let mut out = [Point::<D>::zeros(); 3];
        self.eval(t, &mut out);
        let speed = out[1].norm();
        if speed == 0.0 {
            return None;
        }
        let tangent = out[1] / speed;
        let perp = out[2] - tangent * tangent.dot(&out[2]);
        let curvature = curvature_from(&out[1], &out[2]);
        let normal = if perp.norm() > STRAIGHT_RELATIVE * out[2].norm().max(f64::MIN_POSITIVE) {
            Some(perp.normalize())
        } else {
            None
        };
        let binormal = match normal {
            Some(n) if D == 3 => {
                let mut b = Point::<D>::zeros();
                b[0] = tangent[1] * n[2] - tangent[2] * n[1];
                b[1] = tangent[2] * n[0] - tangent[0] * n[2];
                b[2] = tangent[0] * n[1] - tangent[1] * n[0];
                Some(b)
            }
            _ => None,
        };
        Some(FrenetFrame { tangent, normal, binormal, curvature })
    }

    /// A box that certainly holds the curve, where the kind has one for the asking: the
    /// box of the control points for B-spline, Bézier and NURBS curves (positive weights;
    /// convex hull property; not tight in general). `None` (the default) for other kinds.
    /// [`CurveExtent::extent`](crate::query::extent::CurveExtent::extent) takes it before
    /// sampling.
    fn enclosing_box(&self) -> Option<crate::query::Aabb<D>> {
        None
    }
}

/// κ from first and second derivative (any dimension, Lagrange identity).
pub fn curvature_from<const D: usize>(d1: &Point<D>, d2: &Point<D>) -> f64 {
    let s2 = d1.norm_squared();
    if s2 == 0.0 {
        return 0.0;
    }
    let cross2 = (s2 * d2.norm_squared() - d1.dot(d2).powi(2)).max(0.0);
    cross2.sqrt() / (s2 * s2.sqrt())
}

/// Implements a kernel trait (`Curve` or `Surface`, generic over the dimension D) for
/// `&T`, `Box<T>` and `Arc<T>` of any `T` that implements it, forwarding every listed
/// method — given by its signature, `fn name(&self, arg: Type, …) -> Return;`, attributes
/// first — to the pointee, `(**self).name(arg, …)`. Listing the provided methods too keeps
/// an override in the pointee (a faster `eval_many`, a trimmed surface's loops) behind
/// any pointer.
macro_rules! forward_through_pointers {
    ($tr:ident { $($methods:tt)* }) => {
        $crate::curve::traits::forward_through_pointers!(@impl ['a] &'a T, $tr { $($methods)* });
        $crate::curve::traits::forward_through_pointers!(@impl [] Box<T>, $tr { $($methods)* });
        $crate::curve::traits::forward_through_pointers!(@impl [] std::sync::Arc<T>, $tr { $($methods)* });
    };
    (@impl [$($lt:lifetime)?] $ptr:ty, $tr:ident {
        $($(#[$attr:meta])* fn $name:ident(&self $(, $arg:ident: $ty:ty)*) $(-> $ret:ty)?;)*
    }) => {
        impl<$($lt,)? const D: usize, T: $tr<D> + ?Sized> $tr<D> for $ptr {
            $(
                $(#[$attr])*
                fn $name(&self $(, $arg: $ty)*) $(-> $ret)? {
                    (**self).$name($($arg),*)
                }
            )*
        }
    };
}
pub(crate) use forward_through_pointers;

forward_through_pointers!(Curve {
    #[inline] fn domain(&self) -> Interval;
    #[inline] fn is_closed(&self) -> bool;
    #[inline] fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]);
    #[inline] fn eval(&self, t: f64, out: &mut [Point<D>]);
    fn eval_many(&self, params: &[f64], order: usize, out: &mut [Point<D>]);
    fn eval_many_uninit(&self, params: &[f64], order: usize, out: &mut [std::mem::MaybeUninit<Point<D>>]);
    fn breakpoints(&self) -> Vec<f64>;
    #[inline] fn point(&self, t: f64) -> Point<D>;
    fn derivative(&self, t: f64, order: usize) -> Point<D>;
    fn tangent(&self, t: f64) -> Point<D>;
    fn curvature(&self, t: f64) -> f64;
    fn frame(&self, t: f64) -> Option<FrenetFrame<D>>;
    fn enclosing_box(&self) -> Option<crate::query::Aabb<D>>;
});
