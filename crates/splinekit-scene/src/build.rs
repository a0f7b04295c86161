//! Building kernel curves from documents, in the dimension the points ask for.

use splinekit::blend::{BFunctionCurve, TwoCurveBlend};
use splinekit::curve::model::{Butterfly, Circle, Ellipse, Heart, Helix, Line, Lissajous, Rose, Trefoil};
use splinekit::curve::{
    BSplineCurve, BezierCurve, CatmullRomCurve, Curve, HermiteCurve, NurbsCurve, RationalBezierCurve,
};

use crate::curves::CurveDocument;
use crate::error::{DocumentError, Result};
use crate::points::{check_finite_list, dimension_of, to_point, to_points};
use crate::with_dimension;

/// A curve of a dimension known only at run time.
#[allow(missing_docs)]
pub enum AnyCurve {
    D1(Box<dyn Curve<1>>),
    D2(Box<dyn Curve<2>>),
    D3(Box<dyn Curve<3>>),
    D4(Box<dyn Curve<4>>),
}

/// Something to do with a curve of any dimension (see [`AnyCurve::visit`]).
pub trait CurveVisitor {
    /// The result.
    type Output;
    /// Called with the curve at its dimension.
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Self::Output;
}

impl AnyCurve {
    /// Calls `visitor` with the curve at its compile-time dimension.
    pub fn visit<V: CurveVisitor>(&self, visitor: V) -> V::Output {
        match self {
            AnyCurve::D1(c) => visitor.visit(c.as_ref()),
            AnyCurve::D2(c) => visitor.visit(c.as_ref()),
            AnyCurve::D3(c) => visitor.visit(c.as_ref()),
            AnyCurve::D4(c) => visitor.visit(c.as_ref()),
        }
    }
    /// The dimension of the curve's points.
    pub fn dimension(&self) -> usize {
        match self {
            AnyCurve::D1(_) => 1,
            AnyCurve::D2(_) => 2,
            AnyCurve::D3(_) => 3,
            AnyCurve::D4(_) => 4,
        }
    }
}

/// Wraps a boxed curve of a const dimension into [`AnyCurve`].
pub trait IntoAnyCurve {
    /// The wrapped curve.
    fn into_any(self) -> AnyCurve;
}
macro_rules! into_any {
    ($d:literal, $v:ident) => {
        impl IntoAnyCurve for Box<dyn Curve<$d>> {
            fn into_any(self) -> AnyCurve {
                AnyCurve::$v(self)
            }
        }
    };
}
into_any!(1, D1);
into_any!(2, D2);
into_any!(3, D3);
into_any!(4, D4);

impl CurveDocument {
    /// The dimension of the document's points (3 for model curves).
    pub fn dimension(&self) -> Result<usize> {
        use CurveDocument as C;
        Ok(match self {
            C::Bezier(d) => dimension_of("control_points", &d.control_points)?,
            C::RationalBezier(d) => dimension_of("control_points", &d.control_points)?,
            C::Bspline(d) => dimension_of("control_points", &d.control_points)?,
            C::Nurbs(d) => dimension_of("control_points", &d.control_points)?,
            C::Hermite(d) => dimension_of("points", &d.points)?,
            C::CatmullRom(d) => dimension_of("points", &d.points)?,
            C::Line(d) => dimension_of("from", std::slice::from_ref(&d.from))?,
            C::Bfunction(_) => 1,
            C::BlendingSpline(d) => d.dimension()?,
            C::Blend(d) => {
                let a = d.first.dimension().map_err(|e| e.within("first"))?;
                let b = d.second.dimension().map_err(|e| e.within("second"))?;
                if a != b {
                    return Err(DocumentError::new(
                        "second",
                        format!("expected a curve of dimension {a} like first, got {b}"),
                    ));
                }
                a
            }
            _ => 3,
        })
    }

    /// Builds the curve.
    pub fn build(&self) -> Result<AnyCurve> {
        let dim = self.dimension()?;
        with_dimension!(dim, "control_points", D => Ok(self.build_in::<D>()?.into_any()))
    }

    /// Builds the curve in dimension D (which must be the document's).
    pub fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        use CurveDocument as C;
        let model_dim = |name: &str| -> Result<()> {
            if D == 3 { Ok(()) } else { Err(DocumentError::new("type", format!("{name} is a 3-D model curve"))) }
        };
        let curve: Box<dyn Curve<D>> = match self {
            C::Bezier(d) => Box::new(BezierCurve::new(to_points::<D>(&d.control_points))?),
            C::RationalBezier(d) => {
                check_finite_list("weights", &d.weights)?;
                Box::new(RationalBezierCurve::new(to_points::<D>(&d.control_points), d.weights.clone())?)
            }
            C::Bspline(d) => {
                check_finite_list("knots", &d.knots)?;
                Box::new(bspline::<D>(d)?)
            }
            C::Nurbs(d) => {
                check_finite_list("knots", &d.knots)?;
                check_finite_list("weights", &d.weights)?;
                Box::new(nurbs::<D>(d)?)
            }
            C::Hermite(d) => {
                if d.tangents.len() != d.points.len() {
                    return Err(DocumentError::new(
                        "tangents",
                        format!("expected {} tangents, one per point, got {}", d.points.len(), d.tangents.len()),
                    ));
                }
                let dt = dimension_of("tangents", &d.tangents)?;
                if dt != D {
                    return Err(DocumentError::new(
                        "tangents",
                        format!("expected {D} coordinates like the points, got {dt}"),
                    ));
                }
                Box::new(HermiteCurve::new(to_points::<D>(&d.points), to_points::<D>(&d.tangents), d.params.clone())?)
            }
            C::CatmullRom(d) => Box::new(CatmullRomCurve::new(to_points::<D>(&d.points), d.alpha, d.closed)?),
            C::Line(d) => Box::new(Line::new(to_point::<D>("from", &d.from)?, to_point::<D>("to", &d.to)?)?),
            C::BlendingSpline(d) => Box::new(d.build_in::<D>()?),
            C::Blend(d) => Box::new(TwoCurveBlend::new(
                d.first.build_in::<D>().map_err(|e| e.within("first"))?,
                d.second.build_in::<D>().map_err(|e| e.within("second"))?,
                d.overlap,
                d.bfunction.build().map_err(|e| e.within("bfunction"))?,
            )?),
            C::Bfunction(d) => {
                let c: Box<dyn Curve<1>> =
                    Box::new(BFunctionCurve(d.bfunction.build().map_err(|e| e.within("bfunction"))?));
                let any: Box<dyn std::any::Any> = Box::new(c);
                return any
                    .downcast::<Box<dyn Curve<D>>>()
                    .map(|b| *b)
                    .map_err(|_| DocumentError::new("type", "a bfunction is a 1-D curve"));
            }
            other => {
                model_dim(other.type_name())?;
                let any: Box<dyn Curve<3>> = match other {
                    C::Circle(d) => Box::new(Circle::new(d.radius)?),
                    C::Ellipse(d) => Box::new(Ellipse::new(d.a, d.b)?),
                    C::Helix(d) => Box::new(Helix::new(d.radius, d.pitch, d.turns)?),
                    C::Heart(d) => Box::new(Heart::new(d.scale)?),
                    C::Rose(d) => Box::new(Rose::new(d.radius, d.n, d.planar)?),
                    C::Lissajous(d) => Box::new(Lissajous::new(d.amplitudes, d.frequencies, d.delta)?),
                    C::Trefoil(d) => Box::new(Trefoil::new(d.scale)?),
                    C::Butterfly(d) => Box::new(Butterfly::new(d.scale)?),
                    _ => unreachable!("handled above"),
                };
                return cast_dimension::<D>(any).ok_or_else(|| DocumentError::new("type", "model curves are 3-D"));
            }
        };
        Ok(curve)
    }

    /// The `type` name.
    pub fn type_name(&self) -> &'static str {
        use CurveDocument as C;
        match self {
            C::Bezier(_) => "bezier",
            C::RationalBezier(_) => "rational_bezier",
            C::Bspline(_) => "bspline",
            C::Nurbs(_) => "nurbs",
            C::Hermite(_) => "hermite",
            C::CatmullRom(_) => "catmull_rom",
            C::Line(_) => "line",
            C::Circle(_) => "circle",
            C::Ellipse(_) => "ellipse",
            C::Helix(_) => "helix",
            C::Heart(_) => "heart",
            C::Rose(_) => "rose",
            C::Lissajous(_) => "lissajous",
            C::Trefoil(_) => "trefoil",
            C::Butterfly(_) => "butterfly",
            C::Bfunction(_) => "bfunction",
            C::Blend(_) => "blend",
            C::BlendingSpline(_) => "blending_spline",
        }
    }
}

/// A 3-D curve as a `Box<dyn Curve<D>>`, which succeeds exactly when D = 3 (the two
/// types are then the same, and `Any` checks it).
pub fn cast_dimension<const D: usize>(c: Box<dyn Curve<3>>) -> Option<Box<dyn Curve<D>>> {
    let any: Box<dyn std::any::Any> = Box::new(c);
    any.downcast::<Box<dyn Curve<D>>>().ok().map(|b| *b)
}

/// The B-spline of a document.
pub fn bspline<const D: usize>(d: &crate::curves::BSplineDoc) -> Result<BSplineCurve<D>> {
    let pts = to_points::<D>(&d.control_points);
    Ok(if d.periodic {
        BSplineCurve::new_periodic(d.degree, d.knots.clone(), pts)?
    } else {
        BSplineCurve::new(d.degree, d.knots.clone(), pts)?
    })
}

/// The NURBS curve of a document.
pub fn nurbs<const D: usize>(d: &crate::curves::NurbsDoc) -> Result<NurbsCurve<D>> {
    let pts = to_points::<D>(&d.control_points);
    Ok(if d.periodic {
        NurbsCurve::new_periodic(d.degree, d.knots.clone(), pts, d.weights.clone())?
    } else {
        NurbsCurve::new(d.degree, d.knots.clone(), pts, d.weights.clone())?
    })
}
