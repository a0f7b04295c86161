//! Inserting or splitting a knot line of a blending-spline surface. Insertion: a new u-knot u* adds a row of
//! local patches (k*, l), one per v-knot (a v-knot adds a column), keeping the surface as
//! closely as one row of new patches allows.
//!
//! Method (the surface analogue of [`BlendingSplineCurve::insert_local`]): with Bézier
//! patches of degrees (d_u, d_v), patch (k*, l) is the Bézier patch Hermite-fitted to the
//! *current* surface at (u*, v_l): its mixed partials ∂^{i,j}S for i ≤ d_u, j ≤ d_v there
//! (the surface's Taylor polynomial of those degrees), C = H_u⁻¹ G H_v⁻ᵀ on the support
//! [u_{k*−1}, u_{k*+1}] × [v_{l−1}, v_{l+1}]. Sub-surface patches get the model itself.
//! The rows k* − 1 and k* + 1, whose u-supports shrink, keep their polynomials: each net's
//! columns are re-expressed on the new support ([`rebased_points`], exact up to rounding).
//! The new patches' frames are the identity about the model's point g(u*, v_l), like
//! every patch's origin.
//!
//! Exactness (ERBS): outside (u_k, u_{k+1}) × (the whole v-domain) nothing changes; on the
//! knot lines u_k and u_{k+1} all partials are kept, and on u* the partials up to
//! (d_u, d_v) at every knot pair (u*, v_l). Inside the two strips, as for curves, in u the
//! surface moves by at most |s* − S| + |S − s_k| (blended in v), the Taylor remainder of the
//! new row plus the neighbouring row's distance from the surface.
//!
//! [`BlendingSplineCurve::insert_local`]: super::BlendingSplineCurve::insert_local

use super::blending_surface::{BlendingSplineSurface, LocalPatch, MAX_PATCHES, PatchKind, PatchShape, hermite_patch};
use super::hermite::rebased_points;
use crate::Point;
use crate::error::{Error, Result};
use crate::frame::Affine;
use crate::surface::{Direction, Surface};

impl<const D: usize> BlendingSplineSurface<D> {
    /// Inserts the knot line `direction` = t (a u-knot for [`Direction::U`], the isocurve
    /// u = t becoming a row of new patches; a v-knot for [`Direction::V`]) and returns the
    /// new row's (column's) index. See the module documentation for the method and what
    /// it keeps. An error naming `u` or `v` when t is not strictly inside the domain, falls
    /// on a knot, or the surface would pass 10⁶ patches.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendingSplineSurface, BlendingSurfaceOptions};
    /// use splinekit::surface::{Direction, Surface};
    /// use splinekit::surface::model::Torus;
    /// let torus = Arc::new(Torus::new(3.0, 1.0).unwrap());
    /// let mut s = BlendingSplineSurface::from_model(torus, (8, 6), &BlendingSurfaceOptions::default()).unwrap();
    /// let before = s.clone();
    /// let u = 0.5 * (s.knots().0.centre(2) + s.knots().0.centre(3));
    /// assert_eq!(s.insert_knot_line(Direction::U, u).unwrap(), 3);
    /// assert_eq!(s.local_count(), (9, 6));
    /// // At the new knot line the surface is where it was, with its first partials.
    /// let v = s.knots().1.centre(4);
    /// assert!((s.point(u, v) - before.point(u, v)).norm() < 1e-12);
    /// assert!(s.insert_knot_line(Direction::V, 99.0).unwrap_err().to_string().contains("v"));
    /// ```
    pub fn insert_knot_line(&mut self, direction: Direction, t: f64) -> Result<usize> {
        let along_u = direction == Direction::U;
        let field = if along_u { "u" } else { "v" };
        let (nu, nv) = self.local_count();
        let (rows, others) = if along_u { (nu, nv) } else { (nv, nu) };
        if (rows + 1) * others > MAX_PATCHES {
            return Err(Error::invalid(field, format!("at most 10⁶ patches, got {}", (rows + 1) * others)));
        }
        let mut knots = if along_u { self.knots_u.clone() } else { self.knots_v.clone() };
        let k = knots.insert_as(t, field)?;
        let (new_u, new_v) = if along_u { (knots, self.knots_v.clone()) } else { (self.knots_u.clone(), knots) };
        // The new patches, fitted to the surface as it is (old knots).
        let mut fresh = Vec::with_capacity(others);
        for l in 0..others {
            let (a, b) = if along_u { (k, l) } else { (l, k) };
            let (uc, vc) = (new_u.centre(a), new_v.centre(b));
            let (shape, own) = match (self.kind, &self.model) {
                (PatchKind::SubSurface, Some(model)) => (PatchShape::Shared(model.clone()), model.point(uc, vc)),
                // (A surface without a model has Bézier patches; bicubic for the type's sake.)
                (kind, _) => {
                    let (du, dv) = if let PatchKind::Bezier(du, dv) = kind { (du, dv) } else { (3, 3) };
                    let mut g = vec![Point::<D>::zeros(); (du + 1) * (dv + 1)];
                    self.eval_partials(uc, vc, du, dv, &mut g);
                    let support = crate::ParamRect::new(new_u.support(a), new_v.support(b));
                    (PatchShape::Bezier(hermite_patch(&g, (du, dv), support, (uc, vc), "the surface's")?), g[0])
                }
            };
            // The frame's centre: the model's point, as for every patch made from a model;
            // without a model (Hermite data), the surface's own point there.
            let origin = self.model.as_ref().map_or(own, |m| m.point(uc, vc));
            fresh.push(LocalPatch { shape, origin, transform: Affine::identity() });
        }
        // Patch (a, b) at a·n_v′ + b in the new grid.
        let old = std::mem::take(&mut self.patches);
        let mut fresh = fresh.into_iter();
        let (nu2, nv2) = if along_u { (nu + 1, nv) } else { (nu, nv + 1) };
        let mut old = old.into_iter();
        for a in 0..nu2 {
            for b in 0..nv2 {
                let new_one = if along_u { a == k } else { b == k };
                let patch = if new_one { fresh.next() } else { old.next() };
                self.patches.push(patch.expect("one patch per grid place"));
            }
        }
        self.knots_u = new_u;
        self.knots_v = new_v;
        let m = rows + 1;
        for j in [(k + m - 1) % m, (k + 1) % m] {
            for l in 0..others {
                let (a, b) = if along_u { (j, l) } else { (l, j) };
                self.rebase_patch(a, b, along_u);
            }
        }
        Ok(k)
    }

    /// Splits the knot line u = u_k ([`Direction::U`]; v = v_k for [`Direction::V`]) along
    /// the other direction (GMlib's `splitKnotAlong`): the knot is doubled and the row of
    /// patches (k, ·) (the column (·, k)) copied to k + 1, so the two rows can be edited
    /// independently: the iso-curve u = u_k becomes a seam between two sheets, the left
    /// limit made by row k and the right one by its copy. At each knot pair (u_k, v_l) only
    /// patch (k, l) (or its copy) is active, so turning or scaling copies about their
    /// origins keeps the sheets joined there (C⁰, with the tangent planes jumping: a
    /// crease); between the knot pairs they part unless the copies stay alike. The surface
    /// does not change: on [u_{k−1}, u_k) rows k − 1 and k are
    /// blended as before, on [u_k, u_{k+2}) the copy and the old row k + 1, and the empty
    /// interval between the copies is never used; Bézier copies are re-expressed on their
    /// new supports ([`rebased_points`], the same polynomials), as the curve's
    /// [`split_knot`](super::BlendingSplineCurve::split_knot) does. An error naming `k` for
    /// an end knot of an open direction or a knot already double, and at 10⁶ patches.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendingSplineSurface, BlendingSurfaceOptions};
    /// use splinekit::surface::{Direction, Surface};
    /// use splinekit::surface::model::Torus;
    /// let torus = Arc::new(Torus::new(3.0, 1.0).unwrap());
    /// let mut s = BlendingSplineSurface::from_model(torus, (8, 6), &BlendingSurfaceOptions::default()).unwrap();
    /// let before = s.clone();
    /// s.split_knot_line(Direction::V, 2).unwrap();
    /// assert_eq!(s.local_count(), (8, 7));
    /// assert_eq!(s.knots().1.centre(2), s.knots().1.centre(3));
    /// assert!((s.point(1.0, 2.5) - before.point(1.0, 2.5)).norm() < 1e-12);
    /// assert!(s.split_knot_line(Direction::V, 2).unwrap_err().to_string().contains("already double"));
    /// ```
    pub fn split_knot_line(&mut self, direction: Direction, k: usize) -> Result<()> {
        let along_u = direction == Direction::U;
        let (nu, nv) = self.local_count();
        let (rows, others) = if along_u { (nu, nv) } else { (nv, nu) };
        if (rows + 1) * others > MAX_PATCHES {
            return Err(Error::invalid("k", format!("at most 10⁶ patches, got {}", (rows + 1) * others)));
        }
        let mut knots = if along_u { self.knots_u.clone() } else { self.knots_v.clone() };
        knots.split(k)?;
        let old = std::mem::take(&mut self.patches);
        let (nu2, nv2) = if along_u { (nu + 1, nv) } else { (nu, nv + 1) };
        for a in 0..nu2 {
            for b in 0..nv2 {
                // Grid place (a, b) of the new grid takes old patch (a′, b′), row k twice.
                let (a0, b0) = match along_u {
                    true if a > k => (a - 1, b),
                    false if b > k => (a, b - 1),
                    _ => (a, b),
                };
                self.patches.push(old[a0 * nv + b0].clone());
            }
        }
        if along_u {
            self.knots_u = knots;
        } else {
            self.knots_v = knots;
        }
        for j in [k, k + 1] {
            for l in 0..others {
                let (a, b) = if along_u { (j, l) } else { (l, j) };
                self.rebase_patch(a, b, along_u);
            }
        }
        Ok(())
    }

    /// Re-expresses Bézier patch (a, b) on its support in the current knots along u
    /// (`along_u`) or v: the same polynomial, its net's columns (rows) moved by
    /// [`rebased_points`]; the frame is applied again.
    fn rebase_patch(&mut self, a: usize, b: usize, along_u: bool) {
        let support = if along_u { self.knots_u.support(a) } else { self.knots_v.support(b) };
        let i = a * self.knots_v.count() + b;
        let patch = &mut self.patches[i];
        let PatchShape::Bezier(p) = &mut patch.shape else { return };
        let (du, dv) = p.degrees;
        let from = if along_u { p.support.u } else { p.support.v };
        if along_u {
            for col in 0..=dv {
                let line: Vec<Point<D>> = (0..=du).map(|r| p.net[r * (dv + 1) + col]).collect();
                for (r, q) in rebased_points(&line, from, support).into_iter().enumerate() {
                    p.net[r * (dv + 1) + col] = q;
                }
            }
            p.support.u = support;
        } else {
            for row in 0..=du {
                let line = &mut p.net[row * (dv + 1)..(row + 1) * (dv + 1)];
                let moved = rebased_points(line, from, support);
                line.copy_from_slice(&moved);
            }
            p.support.v = support;
        }
        let transform = patch.transform;
        patch.set_transform(transform);
    }
}
