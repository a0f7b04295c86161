//! Surfaces parametrised over the unit square [0, 1]² (Bézier surfaces, Coons and ruled
//! patches): the domain methods they share.

/// Writes, inside an `impl Surface<D> for …`, `domain_u` and `domain_v` as [0, 1].
macro_rules! unit_square_domains {
    () => {
        fn domain_u(&self) -> $crate::Interval {
            $crate::Interval::new(0.0, 1.0)
        }
        fn domain_v(&self) -> $crate::Interval {
            $crate::Interval::new(0.0, 1.0)
        }
    };
}
pub(crate) use unit_square_domains;
