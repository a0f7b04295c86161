//! Subdivision curves.
