//! Running code at the compile-time dimension D of points whose dimension is known only
//! at run time (1 … 4, as documents).

/// Runs `$body` with `const $d: usize` bound to `$dim` (1 … 4); other dimensions raise
/// the documents' `ValueError` naming `$field`.
macro_rules! by_dimension {
    ($dim:expr, $field:expr, $d:ident => $body:expr) => {
        match $dim {
            1 => {
                const $d: usize = 1;
                $body
            }
            2 => {
                const $d: usize = 2;
                $body
            }
            3 => {
                const $d: usize = 3;
                $body
            }
            4 => {
                const $d: usize = 4;
                $body
            }
            other => Err($crate::errors::value_error(splinekit_scene::dimension::unsupported($field, other))),
        }
    };
}
pub(crate) use by_dimension;
