//! The registry of document kinds: what every curve or surface kind declares, and the
//! macro that turns one list of kinds into the document enum and everything that
//! dispatches on it.
//!
//! A kind is a document struct (its fields, with serde) that implements [`DocumentKind`]:
//! its dimension, its kernel object, an example document, what a scene draws besides it,
//! and how it poses animations. The lists in [`crate::curves`] and [`crate::surfaces`] name
//! each kind once with its `type`; the `document_kinds!` macro makes from them the enum, the
//! `"type"` dispatch of parsing and serialising, the list of type names, and `dimension`,
//! `build`, `examples`, `family_decoration` and `set_time` on the enum — each a match over every
//! kind, so a kind that lacks one of them does not compile.

use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::Value;

use crate::budget::ShapeCost;
use crate::dimension::{ShapeFamily, same_type};
use crate::error::{DocumentError, Result};

/// The `type` name of a kind, set by its line in the `document_kinds!` list of its family.
pub trait KindName {
    /// The `type` in documents, e.g. `"bezier"`.
    const TYPE: &'static str;
}

/// One kind of curve or surface document.
pub trait DocumentKind: KindName + Clone + Serialize + DeserializeOwned {
    /// Curves or surfaces.
    type Family: ShapeFamily;

    /// Parses the document's fields (the object without its `type`). The default is serde
    /// with located errors; kinds whose fields depend on each other check them here.
    fn from_fields(fields: Value) -> Result<Self> {
        crate::json::fields(fields)
    }

    /// The dimension of the shape's points, read from the document (model shapes: 3).
    fn dimension(&self) -> Result<usize>;

    /// What building the kernel object and evaluating it cost, estimated from the
    /// document's counts, degrees and nesting without building anything (see
    /// [`crate::budget`]).
    fn cost(&self) -> ShapeCost;

    /// The kernel object in dimension D, which must be the document's [`Self::dimension`].
    fn build_in<const D: usize>(&self) -> Result<Box<<Self::Family as ShapeFamily>::Shape<D>>>;

    /// A document of this kind with sensible values, for editors and galleries.
    fn example() -> Self;

    /// What a scene may draw besides the shape, in its family's terms
    /// ([`CurveDecoration`](crate::curves::CurveDecoration),
    /// [`SurfaceDecoration`](crate::surfaces::SurfaceDecoration)).
    fn decoration(&self) -> <Self::Family as ShapeFamily>::Decoration<'_>;

    /// Poses every animated blending spline in the document, nested ones too, at `time`
    /// (seconds); kinds without animations and without nested documents do nothing.
    fn set_time(&mut self, time: f64);

    /// The control points, knots and weights the document holds, for the operations and
    /// editors that work on them (refinement, knot operations, Properties); `None` for
    /// kinds that hold other fields.
    fn spline(&self) -> Option<<Self::Family as ShapeFamily>::Spline<'_>>;

    /// What the shape is exactly (a spline, a conic, a quadric, …; see
    /// [`CurveForm`](crate::curves::CurveForm), [`SurfaceForm`](crate::surfaces::SurfaceForm)):
    /// what exporters write. An error where the document's numbers make no shape.
    fn exact_form(&self) -> Result<<Self::Family as ShapeFamily>::Form<'_>>;

    /// Whether editors offer a blending spline of this kind's example (the model shapes).
    const BLENDING_MODEL: bool;
}

/// Declares the document enum of a family from its list of kinds.
///
/// ```text
/// document_kinds! {
///     /// A curve shape document.
///     pub enum CurveDocument of Curves {
///         /// Bézier curve.
///         Bezier(BezierDoc) = "bezier",
///         …
///     }
/// }
/// ```
///
/// Each `Variant(Doc) = "name"` line makes an enum variant serialised with
/// `"type": "name"` and gives `Doc` its [`KindName`]; `Doc` must implement
/// [`DocumentKind`] of that family. The enum gets `TYPES`, `type_name`, `parse_fields`,
/// `examples`, `dimension`, `cost`, `build_in`, `build`, `family_decoration`, `set_time`,
/// `parse`, `to_value`, and a `Deserialize`, both through its own `from_value` (written
/// beside the list, for the family's message about unknown types).
macro_rules! document_kinds {
    (
        $(#[$meta:meta])*
        pub enum $Enum:ident of $Family:ty {
            $( $(#[$variant_meta:meta])* $Variant:ident($Doc:ty) = $name:literal, python($($python:tt)*), )+
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, PartialEq, serde::Serialize)]
        #[serde(tag = "type")]
        pub enum $Enum {
            $( $(#[$variant_meta])* #[serde(rename = $name)] $Variant($Doc), )+
        }

        $( impl $crate::registry::KindName for $Doc {
            const TYPE: &'static str = $name;
        } )+

        impl $Enum {
            /// Every `type` name of the family, in the order of its registry.
            pub const TYPES: &'static [&'static str] = &[$($name),+];

            /// The `type` name.
            pub fn type_name(&self) -> &'static str {
                match self {
                    $( Self::$Variant(_) => $name, )+
                }
            }

            /// Parses the fields of a document of type `ty` (the object without its
            /// `type`); `None` when `ty` is not a kind of this family.
            pub fn parse_fields(ty: &str, fields: serde_json::Value) -> Option<$crate::Result<Self>> {
                match ty {
                    $( $name => Some(
                        <$Doc as $crate::registry::DocumentKind>::from_fields(fields).map(Self::$Variant)
                    ), )+
                    _ => None,
                }
            }

            /// A document of every kind, with sensible values, in the order of the registry.
            pub fn examples() -> Vec<Self> {
                vec![$( Self::$Variant(<$Doc as $crate::registry::DocumentKind>::example()), )+]
            }

            /// The dimension of the shape's points.
            pub fn dimension(&self) -> $crate::Result<usize> {
                match self {
                    $( Self::$Variant(d) => $crate::registry::DocumentKind::dimension(d), )+
                }
            }

            /// What building and evaluating the shape cost (see [`crate::budget`]).
            pub fn cost(&self) -> $crate::budget::ShapeCost {
                match self {
                    $( Self::$Variant(d) => $crate::registry::DocumentKind::cost(d), )+
                }
            }

            /// Builds the shape in dimension D (which must be the document's).
            pub fn build_in<const D: usize>(
                &self,
            ) -> $crate::Result<Box<<$Family as $crate::dimension::ShapeFamily>::Shape<D>>> {
                match self {
                    $( Self::$Variant(d) => $crate::registry::DocumentKind::build_in::<D>(d), )+
                }
            }

            /// Builds the shape in the dimension its points ask for.
            pub fn build(&self) -> $crate::Result<$crate::dimension::AnyDimension<$Family>> {
                let dimension = self.dimension()?;
                $crate::with_dimension!(dimension, "control_points", D => {
                    $crate::dimension::AnyDimension::new(self.build_in::<D>()?, "control_points")
                })
            }

            /// What a scene may draw besides the shape, in the family's terms (the
            /// [`Decoration`](crate::Decoration) of scenes is made of it).
            pub fn family_decoration(&self) -> <$Family as $crate::dimension::ShapeFamily>::Decoration<'_> {
                match self {
                    $( Self::$Variant(d) => $crate::registry::DocumentKind::decoration(d), )+
                }
            }

            /// Poses every animated blending spline in the document (nested ones too) at
            /// `time` (seconds).
            pub fn set_time(&mut self, time: f64) {
                match self {
                    $( Self::$Variant(d) => $crate::registry::DocumentKind::set_time(d, time), )+
                }
            }

            /// The control points, knots and weights the document holds (see
            /// [`DocumentKind::spline`](crate::registry::DocumentKind::spline)).
            pub fn spline(&self) -> Option<<$Family as $crate::dimension::ShapeFamily>::Spline<'_>> {
                match self {
                    $( Self::$Variant(d) => $crate::registry::DocumentKind::spline(d), )+
                }
            }

            /// What the shape is exactly (see
            /// [`DocumentKind::exact_form`](crate::registry::DocumentKind::exact_form)).
            pub fn exact_form(&self) -> $crate::Result<<$Family as $crate::dimension::ShapeFamily>::Form<'_>> {
                match self {
                    $( Self::$Variant(d) => $crate::registry::DocumentKind::exact_form(d), )+
                }
            }

            /// Whether editors offer a blending spline of this kind's example.
            pub fn blending_model(&self) -> bool {
                match self {
                    $( Self::$Variant(_) => <$Doc as $crate::registry::DocumentKind>::BLENDING_MODEL, )+
                }
            }

            /// Parses a document of the family (a copy of `value`; see `from_value`).
            pub fn parse(value: &serde_json::Value) -> $crate::Result<Self> {
                Self::from_value(value.clone())
            }

            /// The document as JSON.
            pub fn to_value(&self) -> serde_json::Value {
                serde_json::to_value(self).expect("documents serialise")
            }
        }

        impl<'de> serde::Deserialize<'de> for $Enum {
            fn deserialize<De: serde::Deserializer<'de>>(deserializer: De) -> std::result::Result<Self, De::Error> {
                $crate::json::nested(deserializer, Self::from_value)
            }
        }
    };
}
pub(crate) use document_kinds;

/// A family whose model shapes (circle, torus, …) exist in 3-D only.
pub trait ModelFamily: ShapeFamily {
    /// The error for the model kind `name` asked for in a dimension other than 3.
    fn not_3d(name: &str) -> DocumentError;

    /// The 3-D shape made by `build` as a shape of dimension D; [`Self::not_3d`] unless
    /// D = 3.
    fn model_in<const D: usize>(
        name: &str,
        build: impl FnOnce() -> Result<Box<Self::Shape<3>>>,
    ) -> Result<Box<Self::Shape<D>>> {
        if D != 3 {
            return Err(Self::not_3d(name));
        }
        same_type(build()?).ok_or_else(|| Self::not_3d(name))
    }
}

/// Declares a model shape's document: a struct of fields that all have defaults (given
/// after `=`; they are the struct's `Default` and serde's for missing fields), and its
/// [`DocumentKind`]: 3-D, built as `build(|d| …)` from the document `d`, exactly the form
/// `exact(|d| …)` (a value of the family's form; `?` may refuse the document); its example is
/// its default document, it holds no spline, has nothing to decorate or pose, and editors
/// offer blending splines of it.
///
/// ```text
/// model_document! {
///     /// `{"type":"circle","radius":1}`: (r cos t, r sin t, 0), t ∈ [0, 2π].
///     pub struct CircleDoc in Curves {
///         /// Radius r (default 1).
///         pub radius: f64 = 1.0,
///     }
///     build(|d| Circle::new(d.radius))
///     exact(|d| CurveForm::Circle { radius: d.radius })
/// }
/// ```
macro_rules! model_document {
    (
        $(#[$meta:meta])*
        pub struct $doc:ident in $family:ident {
            $( $(#[$field_meta:meta])* pub $field:ident: $ty:ty = $default:expr, )+
        }
        build(|$d:ident| $build:expr)
        exact(|$e:ident| $exact:expr)
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct $doc {
            $( $(#[$field_meta])* pub $field: $ty, )+
        }

        impl Default for $doc {
            fn default() -> Self {
                $doc { $( $field: $default, )+ }
            }
        }

        impl $crate::registry::DocumentKind for $doc {
            type Family = $family;
            fn dimension(&self) -> $crate::Result<usize> {
                Ok(3)
            }
            fn cost(&self) -> $crate::budget::ShapeCost {
                $crate::budget::ShapeCost::model()
            }
            fn build_in<const D: usize>(
                &self,
            ) -> $crate::Result<Box<<$family as $crate::dimension::ShapeFamily>::Shape<D>>> {
                let $d = self;
                $crate::registry::check_magnitudes(&serde_json::to_value(self).expect("documents serialise"), "")?;
                <$family as $crate::registry::ModelFamily>::model_in::<D>(
                    <Self as $crate::registry::KindName>::TYPE,
                    || Ok(Box::new($build?)),
                )
            }
            fn example() -> Self {
                Self::default()
            }
            fn decoration(&self) -> <$family as $crate::dimension::ShapeFamily>::Decoration<'_> {
                Default::default()
            }
            fn set_time(&mut self, _time: f64) {}
            fn spline(&self) -> Option<<$family as $crate::dimension::ShapeFamily>::Spline<'_>> {
                None
            }
            fn exact_form(&self) -> $crate::Result<<$family as $crate::dimension::ShapeFamily>::Form<'_>> {
                let $e = self;
                Ok($exact)
            }
            const BLENDING_MODEL: bool = true;
        }
    };
}
pub(crate) use model_document;

/// The declarations a spline kind shares, written inside its `impl DocumentKind`: a
/// document that holds a spline's own data (its `control_points`, with the knots and
/// weights its [`DocumentKind::spline`] view names) is exactly that spline (`$form`'s
/// `Spline`, `$form` the family's form type as named where the macro is used), has the
/// dimension of its control points (`$dimension`, which checks them), draws them
/// (`$decoration`, given them and the view), is not offered as a blending model and has
/// nothing to pose in time.
macro_rules! spline_kind_items {
    ($form:ident, $dimension:path, $decoration:path) => {
        fn exact_form(&self) -> $crate::Result<$form<'_>> {
            Ok($form::Spline(self.spline().expect("a spline kind")))
        }
        fn decoration(&self) -> <Self::Family as $crate::dimension::ShapeFamily>::Decoration<'_> {
            $decoration(&self.control_points, &self.spline().expect("a spline kind"))
        }
        const BLENDING_MODEL: bool = false;
        fn dimension(&self) -> $crate::Result<usize> {
            $dimension("control_points", &self.control_points)
        }
        fn set_time(&mut self, _time: f64) {}
    };
}
pub(crate) use spline_kind_items;

/// The declarations of a kind that holds no spline data of its own and has no exact form
/// (exporters approximate it, `$form`'s `Approximate`, `$form` the family's form type as
/// named where the macro is used), written inside its `impl DocumentKind`; it is not
/// offered as a blending model.
macro_rules! approximated_kind_items {
    ($view:ident, $form:ident) => {
        fn spline(&self) -> Option<$crate::views::$view<'_>> {
            None
        }
        fn exact_form(&self) -> $crate::Result<$form<'_>> {
            Ok($form::Approximate)
        }
        const BLENDING_MODEL: bool = false;
    };
}
pub(crate) use approximated_kind_items;

/// The declarations of a kind that holds no spline data of its own and is exactly itself:
/// its form is the family's variant `$variant` holding the document (a revolution, an
/// extrusion, a trimmed or placed surface, a blending spline), whose fields exporters read;
/// written inside its `impl DocumentKind`, it is not offered as a blending model.
macro_rules! self_form_kind_items {
    ($view:ident, $variant:path) => {
        fn spline(&self) -> Option<$crate::views::$view<'_>> {
            None
        }
        fn exact_form(&self) -> $crate::Result<<Self::Family as $crate::dimension::ShapeFamily>::Form<'_>> {
            Ok($variant(self))
        }
        const BLENDING_MODEL: bool = false;
    };
}
pub(crate) use self_form_kind_items;

/// Refuses any number in a (small) document beyond ±[`MAX_MAGNITUDE`](crate::budget::MAX_MAGNITUDE),
/// naming its path.
pub fn check_magnitudes(value: &Value, path: &str) -> Result<()> {
    let join = |key: &str| if path.is_empty() { key.to_string() } else { format!("{path}.{key}") };
    match value {
        Value::Number(n) => crate::points::check_magnitude(path, n.as_f64().unwrap_or(0.0)),
        Value::Array(items) => {
            items.iter().enumerate().try_for_each(|(i, v)| check_magnitudes(v, &format!("{path}[{i}]")))
        }
        Value::Object(map) => map.iter().try_for_each(|(k, v)| check_magnitudes(v, &join(k))),
        _ => Ok(()),
    }
}
