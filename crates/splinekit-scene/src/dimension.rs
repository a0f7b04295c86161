//! Shapes whose dimension is known only at run time.
//!
//! The kernel's curves and surfaces carry their dimension D as a const generic, while a
//! document's dimension is read from its points. This module is the one bridge between
//! the two: [`with_dimension!`](crate::with_dimension) runs code with `const D` bound to a
//! run-time dimension, [`AnyDimension`] holds a built curve or surface of any supported
//! dimension, and a [`DimensionVisitor`] is handed the shape back at its compile-time D.

use std::any::Any;

use crate::error::{DocumentError, Result};

/// Largest point dimension documents are built in.
pub const MAX_DIMENSION: usize = 4;

/// Runs `$body` with `const $d: usize` bound to the run-time dimension `$dim` (1 … 4);
/// other dimensions are an error naming `$field`: `Err(From::from(DocumentError))`, or
/// with `, or $err` at the end `Err($err(DocumentError))` (for error types that cannot
/// implement `From<DocumentError>`, such as the Python bindings' `PyErr`).
#[macro_export]
macro_rules! with_dimension {
    // One arm per supported dimension, each binding its own `const $d`.
    (@arms $dim:expr, $field:expr, $d:ident => $body:expr, or $err:path, [$($n:literal),+]) => {
        match $dim {
            $($n => {
                const $d: usize = $n;
                $body
            })+
            other => Err($err($crate::dimension::unsupported($field, other))),
        }
    };
    ($dim:expr, $field:expr, $d:ident => $body:expr) => {
        $crate::with_dimension!($dim, $field, $d => $body, or ::core::convert::From::from)
    };
    ($dim:expr, $field:expr, $d:ident => $body:expr, or $err:path) => {
        $crate::with_dimension!(@arms $dim, $field, $d => $body, or $err, [1, 2, 3, 4]) // 1 … MAX_DIMENSION
    };
}

/// The error for a dimension outside 1 … [`MAX_DIMENSION`].
pub fn unsupported(field: &str, dimension: usize) -> DocumentError {
    DocumentError::new(field, format!("points of dimension {dimension} are not supported (1 to {MAX_DIMENSION})"))
}

/// A family of shapes with one trait object type per dimension: curves or surfaces
/// ([`Curves`](crate::curves::Curves), [`Surfaces`](crate::surfaces::Surfaces), each
/// declared with its kinds).
pub trait ShapeFamily {
    /// The shape in dimension D (`dyn Curve<D>` or `dyn Surface<D>`).
    type Shape<const D: usize>: ?Sized + 'static;
    /// The spline data a document of the family may hold ([`SplineView`](crate::views::SplineView) or
    /// [`NetView`](crate::views::NetView)).
    type Spline<'a>;
    /// The exact forms of the family ([`CurveForm`](crate::curves::CurveForm) or
    /// [`SurfaceForm`](crate::surfaces::SurfaceForm)).
    type Form<'a>;
    /// What a scene may draw besides a shape of the family
    /// ([`CurveDecoration`](crate::curves::CurveDecoration) or
    /// [`SurfaceDecoration`](crate::surfaces::SurfaceDecoration)); the default is nothing.
    type Decoration<'a>: Default;
}

/// A boxed curve or surface of a dimension known only at run time.
#[allow(missing_docs)]
pub enum AnyDimension<F: ShapeFamily> {
    D1(Box<F::Shape<1>>),
    D2(Box<F::Shape<2>>),
    D3(Box<F::Shape<3>>),
    D4(Box<F::Shape<4>>),
}

/// Something to do with a shape of any dimension (see [`AnyDimension::visit`]).
pub trait DimensionVisitor<F: ShapeFamily> {
    /// The result.
    type Output;
    /// Called with the shape at its compile-time dimension.
    fn visit<const D: usize>(self, shape: &F::Shape<D>) -> Self::Output;
}

impl<F: ShapeFamily> AnyDimension<F> {
    /// Wraps a shape of dimension D; D above [`MAX_DIMENSION`] is an error naming `field`.
    pub fn new<const D: usize>(shape: Box<F::Shape<D>>, field: &str) -> Result<Self> {
        let wrapped = match D {
            1 => same_type(shape).map(Self::D1),
            2 => same_type(shape).map(Self::D2),
            3 => same_type(shape).map(Self::D3),
            4 => same_type(shape).map(Self::D4),
            _ => None,
        };
        wrapped.ok_or_else(|| unsupported(field, D))
    }

    /// Calls `visitor` with the shape at its compile-time dimension.
    pub fn visit<V: DimensionVisitor<F>>(&self, visitor: V) -> V::Output {
        match self {
            Self::D1(s) => visitor.visit::<1>(s.as_ref()),
            Self::D2(s) => visitor.visit::<2>(s.as_ref()),
            Self::D3(s) => visitor.visit::<3>(s.as_ref()),
            Self::D4(s) => visitor.visit::<4>(s.as_ref()),
        }
    }

    /// The dimension of the shape's points.
    pub fn dimension(&self) -> usize {
        match self {
            Self::D1(_) => 1,
            Self::D2(_) => 2,
            Self::D3(_) => 3,
            Self::D4(_) => 4,
        }
    }
}

/// `value` as a `U` when `T` and `U` are the same type, which the compiler cannot see
/// for const-generic dimensions (`Box<dyn Curve<3>>` and `Box<dyn Curve<D>>` with D = 3);
/// `None` when they differ.
pub fn same_type<T: 'static, U: 'static>(value: T) -> Option<U> {
    let any: Box<dyn Any> = Box::new(value);
    any.downcast::<U>().ok().map(|u| *u)
}
