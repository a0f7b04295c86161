//! Least-squares fitting and interpolation.
