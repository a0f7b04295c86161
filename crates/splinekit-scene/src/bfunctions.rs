//! B-function documents: `{"type":"erbs","alpha":1,"beta":1,"gamma":1,"lambda":0.5}`,
//! `{"type":"polynomial","smoothness":1}`, `{"type":"beta","a":3,"b":3}`,
//! `{"type":"trigonometric"}`, `{"type":"half_cosine"}`, `{"type":"rational"}`,
//! `{"type":"linear"}`.

use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use splinekit::basis::BFunction;

use crate::error::{DocumentError, Result};
use crate::json::{fields, nested, split_type};

/// ERBS parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ErbsDoc {
    /// α (default 1).
    pub alpha: f64,
    /// β (default 1).
    pub beta: f64,
    /// γ (default 1).
    pub gamma: f64,
    /// λ (default ½).
    pub lambda: f64,
}

impl ErbsDoc {
    /// α = β = γ = 1, λ = ½.
    pub const DEFAULT: ErbsDoc = ErbsDoc { alpha: 1.0, beta: 1.0, gamma: 1.0, lambda: 0.5 };
}

impl Default for ErbsDoc {
    fn default() -> Self {
        ErbsDoc::DEFAULT
    }
}

/// Polynomial smoothness.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PolynomialDoc {
    /// k ≥ 1 (default 1: 3t² − 2t³).
    pub smoothness: usize,
}

impl Default for PolynomialDoc {
    fn default() -> Self {
        PolynomialDoc { smoothness: 1 }
    }
}

/// Beta-function B-spline exponents.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BetaDoc {
    /// a (default 3).
    pub a: usize,
    /// b (default 3).
    pub b: usize,
}

impl Default for BetaDoc {
    fn default() -> Self {
        BetaDoc { a: 3, b: 3 }
    }
}

/// No parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NoParams {}

/// A B-function document.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
#[allow(missing_docs)]
pub enum BFunctionDoc {
    Linear(NoParams),
    Polynomial(PolynomialDoc),
    Beta(BetaDoc),
    Trigonometric(NoParams),
    HalfCosine(NoParams),
    Rational(NoParams),
    Erbs(ErbsDoc),
}

impl BFunctionDoc {
    /// Every `type` of B-function, the default (ERBS) first.
    pub const TYPES: [&'static str; 7] =
        ["erbs", "polynomial", "trigonometric", "half_cosine", "rational", "beta", "linear"];

    /// Parses a B-function object.
    pub fn parse(value: &Value) -> Result<Self> {
        Self::from_value(value.clone())
    }

    /// Parses a B-function document, taking the JSON value.
    pub fn from_value(value: Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        use BFunctionDoc as B;
        Ok(match ty.as_str() {
            "linear" => B::Linear(fields(rest)?),
            "polynomial" => B::Polynomial(fields(rest)?),
            "beta" => B::Beta(fields(rest)?),
            "trigonometric" => B::Trigonometric(fields(rest)?),
            "half_cosine" => B::HalfCosine(fields(rest)?),
            "rational" => B::Rational(fields(rest)?),
            "erbs" => B::Erbs(fields(rest)?),
            _ => {
                return Err(DocumentError::new(
                    "type",
                    format!(
                        "unknown B-function \"{ty}\" (expected linear, polynomial, beta, trigonometric, half_cosine, rational or erbs)"
                    ),
                ));
            }
        })
    }

    /// Builds the B-function.
    pub fn build(&self) -> Result<BFunction> {
        use BFunctionDoc as B;
        Ok(match self {
            B::Linear(_) => BFunction::Linear,
            B::Polynomial(d) => BFunction::polynomial(d.smoothness)?,
            B::Beta(d) => BFunction::beta(d.a, d.b)?,
            B::Trigonometric(_) => BFunction::Trigonometric,
            B::HalfCosine(_) => BFunction::HalfCosine,
            B::Rational(_) => BFunction::Rational,
            B::Erbs(d) => BFunction::erbs(d.alpha, d.beta, d.gamma, d.lambda)?,
        })
    }
}

impl<'de> Deserialize<'de> for BFunctionDoc {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        nested(deserializer, Self::from_value)
    }
}

/// The B-function of blending splines when none is given: ERBS with α = β = γ = 1, λ = ½.
pub const DEFAULT_BFUNCTION: BFunctionDoc = BFunctionDoc::Erbs(ErbsDoc::DEFAULT);
