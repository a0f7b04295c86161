//! Tensor-product splines S(u, v) = Σ_i Σ_j N_i(u) M_j(v) c_ij over any linear space of
//! coefficients (points for B-spline surfaces, homogeneous points for NURBS surfaces).

use smallvec::{SmallVec, smallvec};

use crate::Coefficient;
use crate::basis::{SplineAxis, basis_derivatives};
use crate::curve::bezier_spans::by_width;
use crate::curve::span_kernel::eval_local;
use crate::error::{Error, Result};

/// Degree, knots and coefficients of a tensor-product spline, ready to evaluate.
#[derive(Debug, Clone, PartialEq)]
pub struct TensorSpline<T> {
    /// The u-direction (first index of the net).
    pub u: SplineAxis,
    /// The v-direction (second index of the net).
    pub v: SplineAxis,
    /// Evaluation net (unrolled in periodic directions), row-major: `[i · nv_eval + j]`.
    net: Vec<T>,
}

/// The `Surface` methods every tensor-product surface with a `spline: TensorSpline<_>`
/// field shares: domains and closedness come from the two axes.
macro_rules! tensor_surface_domains {
    () => {
        fn domain_u(&self) -> $crate::curve::Interval {
            self.spline.u.domain()
        }
        fn domain_v(&self) -> $crate::curve::Interval {
            self.spline.v.domain()
        }
        fn is_closed_u(&self) -> bool {
            self.spline.u.is_periodic()
        }
        fn is_closed_v(&self) -> bool {
            self.spline.v.is_periodic()
        }
        fn breakpoints_u(&self) -> Vec<f64> {
            self.spline.u.breakpoints()
        }
        fn breakpoints_v(&self) -> Vec<f64> {
            self.spline.v.breakpoints()
        }
    };
}
pub(crate) use tensor_surface_domains;

/// The inherent accessors every tensor-product surface with a `net` field (the control
/// points as given) and a `spline: TensorSpline<_>` field shares: degrees, knots, net and
/// periodic flags.
macro_rules! tensor_surface_accessors {
    () => {
        /// Degrees (p, q).
        pub fn degrees(&self) -> (usize, usize) {
            (self.spline.u.degree(), self.spline.v.degree())
        }
        /// Knots in u and v as given.
        pub fn knots(&self) -> (&[f64], &[f64]) {
            (self.spline.u.knots(), self.spline.v.knots())
        }
        /// The control net.
        pub fn control_points(&self) -> &[Vec<Point<D>>] {
            &self.net
        }
        /// Periodic flags (u, v).
        pub fn periodic(&self) -> (bool, bool) {
            (self.spline.u.is_periodic(), self.spline.v.is_periodic())
        }
    };
}
pub(crate) use tensor_surface_accessors;

/// Validates a control net (rectangular, finite) and builds the two axes of a
/// tensor-product spline of `degrees` on `knots_u`, `knots_v`.
pub fn net_axes<const D: usize>(
    degrees: (usize, usize),
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    net: &[Vec<crate::Point<D>>],
    periodic: (bool, bool),
) -> Result<(SplineAxis, SplineAxis)> {
    let (nu, nv) = checked_net(net)?;
    let u = SplineAxis::new(degrees.0, knots_u, nu, periodic.0, "knots_u")?;
    let v = SplineAxis::new(degrees.1, knots_v, nv, periodic.1, "knots_v")?;
    Ok((u, v))
}

/// [`net_shape`] plus finiteness of every control point.
pub fn checked_net<const D: usize>(net: &[Vec<crate::Point<D>>]) -> Result<(usize, usize)> {
    let shape = net_shape(net, "control_points")?;
    for (i, row) in net.iter().enumerate() {
        crate::error::check_points_finite(&format!("control_points[{i}]"), row)?;
    }
    Ok(shape)
}

/// Checks a net for raggedness; returns (rows, columns).
pub fn net_shape<T>(rows: &[Vec<T>], field: &str) -> Result<(usize, usize)> {
    let nu = rows.len();
    if nu == 0 {
        return Err(Error::count(field, "at least 1 row", 0));
    }
    let nv = rows[0].len();
    if nv == 0 {
        return Err(Error::count(format!("{field}[0]"), "at least 1 point", 0));
    }
    for (i, r) in rows.iter().enumerate() {
        if r.len() != nv {
            return Err(Error::count(format!("{field}[{i}]"), format!("{nv} points like the first row"), r.len()));
        }
    }
    Ok((nu, nv))
}

impl<T: Coefficient> TensorSpline<T> {
    /// Builds from axes and a net of `u.count()` rows of `v.count()` coefficients.
    pub fn new(u: SplineAxis, v: SplineAxis, rows: &[Vec<T>]) -> Self {
        let (nue, nve) = (u.eval_count(), v.eval_count());
        let mut net = Vec::with_capacity(nue * nve);
        for i in 0..nue {
            let row = &rows[u.wrap_index(i)];
            for j in 0..nve {
                net.push(row[v.wrap_index(j)]);
            }
        }
        TensorSpline { u, v, net }
    }

    /// Writes the partials ∂^{i+j}/∂uⁱ∂vʲ, i ≤ du, j ≤ dv into `out[i·(dv+1) + j]`.
    pub fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [T]) {
        let (u, v) = (self.u.normalise(u), self.v.normalise(v));
        let (su, sv) = (self.u.span(u), self.v.span(v));
        let (pu, pv) = (self.u.degree(), self.v.degree());
        let nve = self.v.eval_count();
        let w = dv + 1;
        let mut rows: SmallVec<[T; 32]> = smallvec![T::zero(); (pu + 1) * w];
        for r in 0..=pu {
            let i = su - pu + r;
            let local = &self.net[i * nve + sv - pv..=i * nve + sv];
            eval_local(self.v.eval_knots(), self.v.reciprocals(), local, pv, sv, v, &mut rows[r * w..(r + 1) * w]);
        }
        let mut col: SmallVec<[T; 8]> = smallvec![T::zero(); pu + 1];
        let mut res: SmallVec<[T; 8]> = smallvec![T::zero(); du + 1];
        for j in 0..=dv {
            for r in 0..=pu {
                col[r] = rows[r * w + j];
            }
            eval_local(self.u.eval_knots(), self.u.reciprocals(), &col, pu, su, u, &mut res);
            for i in 0..=du {
                out[i * w + j] = res[i];
            }
        }
    }

    /// Grid evaluation (layout as [`crate::surface::Surface::eval_grid`]): the v-basis is
    /// computed once per v; per u the isocurve coefficients C_i(u) = Σ_r N_r^{(i)}(u) row_r
    /// are formed once, then every grid point is a (p_v + 1)-term sum.
    pub fn eval_grid(&self, us: &[f64], vs: &[f64], du: usize, dv: usize, out: &mut [T]) {
        let (pu, pv) = (self.u.degree(), self.v.degree());
        let (wu, wv) = (pu + 1, pv + 1);
        let nve = self.v.eval_count();
        let block = (du + 1) * (dv + 1);
        // v-basis per column parameter.
        let mut v_spans = Vec::with_capacity(vs.len());
        let mut v_basis = vec![0.0; vs.len() * (dv + 1) * wv];
        let mut scratch = vec![0.0; (dv.max(du) + 1) * (pu.max(pv) + 1)];
        for (b, &v) in vs.iter().enumerate() {
            let v = self.v.normalise(v);
            let sv = self.v.span(v);
            v_spans.push(sv);
            basis_derivatives(self.v.eval_knots(), pv, sv, v, dv, &mut scratch[..(dv + 1) * wv]);
            v_basis[b * (dv + 1) * wv..(b + 1) * (dv + 1) * wv].copy_from_slice(&scratch[..(dv + 1) * wv]);
        }
        let mut iso = vec![T::zero(); (du + 1) * nve];
        let mut nu_basis = vec![0.0; (du + 1) * wu];
        for (a, &u) in us.iter().enumerate() {
            let u = self.u.normalise(u);
            let su = self.u.span(u);
            basis_derivatives(self.u.eval_knots(), pu, su, u, du, &mut nu_basis);
            for i in 0..=du {
                let c = &mut iso[i * nve..(i + 1) * nve];
                c.iter_mut().for_each(|x| *x = T::zero());
                for r in 0..wu {
                    let n = nu_basis[i * wu + r];
                    let row = &self.net[(su - pu + r) * nve..(su - pu + r + 1) * nve];
                    for (x, y) in c.iter_mut().zip(row) {
                        *x += *y * n;
                    }
                }
            }
            for (b, &sv) in v_spans.iter().enumerate() {
                let nb = &v_basis[b * (dv + 1) * wv..(b + 1) * (dv + 1) * wv];
                let o = &mut out[(a * vs.len() + b) * block..(a * vs.len() + b + 1) * block];
                for i in 0..=du {
                    let c = &iso[i * nve + sv - pv..=i * nve + sv];
                    for j in 0..=dv {
                        let nj = &nb[j * wv..(j + 1) * wv];
                        let mut acc = T::zero();
                        for r in 0..wv {
                            acc += c[r] * nj[r];
                        }
                        o[i * (dv + 1) + j] = acc;
                    }
                }
            }
        }
    }

    /// Grid evaluation of S, ∂S/∂u and ∂S/∂v only: calls `f(k, s, s_u, s_v)` for grid
    /// point k = a·vs.len() + b. Same scheme as [`TensorSpline::eval_grid`] with two
    /// isocurve coefficient sets per row and three (p_v + 1)-term sums per point.
    #[inline]
    pub fn eval_grid_first(&self, us: &[f64], vs: &[f64], mut f: impl FnMut(usize, T, T, T)) {
        let (pu, pv) = (self.u.degree(), self.v.degree());
        let (wu, wv) = (pu + 1, pv + 1);
        let nve = self.v.eval_count();
        let mut v_spans = Vec::with_capacity(vs.len());
        let mut v_basis = vec![0.0; vs.len() * 2 * wv];
        let mut scratch = vec![0.0; 2 * (pu.max(pv) + 1)];
        for (b, &v) in vs.iter().enumerate() {
            let v = self.v.normalise(v);
            let sv = self.v.span(v);
            v_spans.push(sv - pv);
            basis_derivatives(self.v.eval_knots(), pv, sv, v, 1, &mut scratch[..2 * wv]);
            v_basis[b * 2 * wv..(b + 1) * 2 * wv].copy_from_slice(&scratch[..2 * wv]);
        }
        let mut iso0 = vec![T::zero(); nve];
        let mut iso1 = vec![T::zero(); nve];
        let mut nu_basis = vec![0.0; 2 * wu];
        for (a, &u) in us.iter().enumerate() {
            let u = self.u.normalise(u);
            let su = self.u.span(u);
            basis_derivatives(self.u.eval_knots(), pu, su, u, 1, &mut nu_basis);
            iso0.iter_mut().for_each(|x| *x = T::zero());
            iso1.iter_mut().for_each(|x| *x = T::zero());
            for r in 0..wu {
                let (n0, n1) = (nu_basis[r], nu_basis[wu + r]);
                let row = &self.net[(su - pu + r) * nve..(su - pu + r + 1) * nve];
                for ((x0, x1), y) in iso0.iter_mut().zip(iso1.iter_mut()).zip(row) {
                    *x0 += *y * n0;
                    *x1 += *y * n1;
                }
            }
            let row = a * vs.len();
            match wv {
                2 => row_first::<2, T>(&iso0, &iso1, &v_spans, &v_basis, row, &mut f),
                3 => row_first::<3, T>(&iso0, &iso1, &v_spans, &v_basis, row, &mut f),
                4 => row_first::<4, T>(&iso0, &iso1, &v_spans, &v_basis, row, &mut f),
                5 => row_first::<5, T>(&iso0, &iso1, &v_spans, &v_basis, row, &mut f),
                6 => row_first::<6, T>(&iso0, &iso1, &v_spans, &v_basis, row, &mut f),
                _ => {
                    for (b, &base) in v_spans.iter().enumerate() {
                        let nb = &v_basis[b * 2 * wv..(b + 1) * 2 * wv];
                        let (c0, c1) = (&iso0[base..base + wv], &iso1[base..base + wv]);
                        let (mut s, mut s_u, mut s_v) = (T::zero(), T::zero(), T::zero());
                        for r in 0..wv {
                            s += c0[r] * nb[r];
                            s_v += c0[r] * nb[wv + r];
                            s_u += c1[r] * nb[r];
                        }
                        f(row + b, s, s_u, s_v);
                    }
                }
            }
        }
    }
}

impl<const D: usize> TensorSpline<crate::Point<D>> {
    /// Grid of points and unit normals (the layout of
    /// [`crate::surface::Surface::eval_grid_with_normals`]) of a non-rational spline: the
    /// scheme of [`TensorSpline::eval_grid_first`] — v-basis and its derivative once per
    /// column, the isocurve coefficients C(u) = Σ_r N_r(u) row_r and C′(u) once per row —
    /// with the three W-term sums S = Σ_r M_r C_r, S_v = Σ_r M_r′ C_r, S_u = Σ_r M_r C′_r
    /// on plain coordinate arrays and the point and normal written straight into the
    /// output (no partials handed to a callback, so nothing is spilled on the way). For
    /// v-degrees up to 7 the sums unroll; the normal is S_u × S_v/|S_u × S_v| (D = 3), as
    /// [`crate::surface::unit_normal`] computes it, with its fallbacks where it vanishes;
    /// zero where there is none. Points of more than [`PADDED`] coordinates and v-degrees
    /// above 7 go through [`TensorSpline::eval_grid_first`].
    pub fn eval_grid_points_normals(
        &self,
        us: &[f64],
        vs: &[f64],
        points: &mut [crate::Point<D>],
        normals: &mut [crate::Point<D>],
    ) {
        let wv = self.v.degree() + 1;
        if us.is_empty() || vs.is_empty() {
            return;
        }
        if wv > 8 || D > PADDED {
            return self.eval_grid_first(us, vs, |k, s, su, sv| {
                points[k] = s;
                normals[k] = crate::surface::unit_normal(&su, &sv).unwrap_or_else(crate::Point::<D>::zeros);
            });
        }
        by_width!(self.v.degree(), W => {
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU has AVX2 (checked just above).
                return unsafe { self.grid_points_normals_avx2::<W>(us, vs, points, normals) };
            }
            self.grid_points_normals::<W>(us, vs, points, normals)
        })
    }

    /// [`Self::grid_points_normals`] compiled for AVX2: the same operations in the same
    /// order (no fused multiply-adds), so the same bits, wider instructions.
    ///
    /// # Safety
    /// The CPU must support AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn grid_points_normals_avx2<const W: usize>(
        &self,
        us: &[f64],
        vs: &[f64],
        points: &mut [crate::Point<D>],
        normals: &mut [crate::Point<D>],
    ) {
        self.grid_points_normals::<W>(us, vs, points, normals)
    }

    /// [`Self::eval_grid_points_normals`] with W = p_v + 1 known at compile time, for
    /// D ≤ [`PADDED`]: the isocurve coefficients are kept as [`PADDED`]-wide arrays (unused
    /// coordinates zero), so that each of the three W-term sums is one [`PADDED`]-wide
    /// multiply and add per term, which the compiler emits as single vector instructions.
    /// Each coordinate sees the operations of [`TensorSpline::eval_grid_first`]'s sums in
    /// their order (the padding lanes are computed and dropped).
    #[inline(always)]
    fn grid_points_normals<const W: usize>(
        &self,
        us: &[f64],
        vs: &[f64],
        points: &mut [crate::Point<D>],
        normals: &mut [crate::Point<D>],
    ) {
        let (pu, pv) = (self.u.degree(), W - 1);
        let nve = self.v.eval_count();
        // Per column: the first coefficient index and M_r(v), M_r′(v).
        let mut columns: Vec<(usize, [f64; W], [f64; W])> = Vec::with_capacity(vs.len());
        let mut scratch = [0.0; 16];
        for &v in vs {
            let v = self.v.normalise(v);
            let sv = self.v.span(v);
            basis_derivatives(self.v.eval_knots(), pv, sv, v, 1, &mut scratch[..2 * W]);
            let m0: [f64; W] = scratch[..W].try_into().expect("W basis values");
            let m1: [f64; W] = scratch[W..2 * W].try_into().expect("W basis derivatives");
            columns.push((sv - pv, m0, m1));
        }
        let wu = pu + 1;
        let columns = &columns[..];
        let columns_len = columns.len();
        let mut iso0 = vec![[0.0; PADDED]; nve];
        let mut iso1 = vec![[0.0; PADDED]; nve];
        let mut nu_basis = vec![0.0; 2 * wu];
        // The p_u + 1 rows of the net over the current u-span, padded like the isocurve
        // coefficients (so each row's sums are whole-register operations), copied when the
        // span changes.
        let mut span_rows = vec![[0.0; PADDED]; wu * nve];
        let mut rows_span = usize::MAX;
        let rows = points.chunks_exact_mut(columns_len).zip(normals.chunks_exact_mut(columns_len));
        for (&u, (prow, nrow)) in us.iter().zip(rows) {
            let u = self.u.normalise(u);
            let su = self.u.span(u);
            basis_derivatives(self.u.eval_knots(), pu, su, u, 1, &mut nu_basis);
            if su != rows_span {
                for (padded, y) in span_rows.iter_mut().zip(&self.net[(su - pu) * nve..(su + 1) * nve]) {
                    *padded = std::array::from_fn(|c| if c < D { y[c] } else { 0.0 });
                }
                rows_span = su;
            }
            iso0.fill([0.0; PADDED]);
            iso1.fill([0.0; PADDED]);
            for (r, row) in span_rows.chunks_exact(nve).enumerate() {
                let (n0, n1) = (nu_basis[r], nu_basis[wu + r]);
                for ((x0, x1), y) in iso0.iter_mut().zip(iso1.iter_mut()).zip(row) {
                    for c in 0..PADDED {
                        x0[c] += y[c] * n0;
                        x1[c] += y[c] * n1;
                    }
                }
            }
            // Blocks of NORMAL_BLOCK columns: the sums per column, then the cross products,
            // square roots and divisions of the block as arrays, which become vector
            // instructions (the square root and division of one normal at a time were a
            // third of the time, waiting on their latency).
            let mut blocks = columns
                .chunks_exact(NORMAL_BLOCK)
                .zip(prow.chunks_exact_mut(NORMAL_BLOCK).zip(nrow.chunks_exact_mut(NORMAL_BLOCK)));
            for (cols, (ps, ns)) in &mut blocks {
                let mut sums = [([0.0; PADDED], [0.0; PADDED], [0.0; PADDED]); NORMAL_BLOCK];
                for (sum, (base, m0, m1)) in sums.iter_mut().zip(cols) {
                    *sum = padded_sums::<W>(&iso0, &iso1, *base, m0, m1);
                }
                for (p, (s, _, _)) in ps.iter_mut().zip(&sums) {
                    *p = crate::Point::<D>::from_fn(|c, _| s[c]);
                }
                if D != 3 {
                    for (n, (_, s_u, s_v)) in ns.iter_mut().zip(&sums) {
                        *n = normal::<D>(&std::array::from_fn(|c| s_u[c]), &std::array::from_fn(|c| s_v[c]));
                    }
                    continue;
                }
                let mut cross = [[0.0; 3]; NORMAL_BLOCK];
                let mut len2 = [0.0; NORMAL_BLOCK];
                let mut inv = [0.0; NORMAL_BLOCK];
                for l in 0..NORMAL_BLOCK {
                    let (_, a, b) = &sums[l];
                    cross[l] = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
                    len2[l] = cross[l][0] * cross[l][0] + cross[l][1] * cross[l][1] + cross[l][2] * cross[l][2];
                }
                // Every lane is normalised without a branch (a branch per lane let the
                // compiler sink the square root and division into it, one lane at a time);
                // the lanes without a normal are redone after.
                for l in 0..NORMAL_BLOCK {
                    inv[l] = 1.0 / len2[l].sqrt();
                }
                for l in 0..NORMAL_BLOCK {
                    ns[l] = crate::Point::<D>::from_fn(|c, _| cross[l][c] * inv[l]);
                }
                let normalisable = |l: usize| len2[l] > f64::MIN_POSITIVE && len2[l].is_finite();
                if !(0..NORMAL_BLOCK).all(normalisable) {
                    for l in (0..NORMAL_BLOCK).filter(|&l| !normalisable(l)) {
                        let (_, s_u, s_v) = &sums[l];
                        ns[l] = normal::<D>(&std::array::from_fn(|c| s_u[c]), &std::array::from_fn(|c| s_v[c]));
                    }
                }
            }
            let done = columns.len() - columns.len() % NORMAL_BLOCK;
            for ((base, m0, m1), (p, n)) in
                columns[done..].iter().zip(prow[done..].iter_mut().zip(nrow[done..].iter_mut()))
            {
                let (s, s_u, s_v) = padded_sums::<W>(&iso0, &iso1, *base, m0, m1);
                *p = crate::Point::<D>::from_fn(|c, _| s[c]);
                *n = normal::<D>(&std::array::from_fn(|c| s_u[c]), &std::array::from_fn(|c| s_v[c]));
            }
        }
    }
}

/// Columns whose normals [`TensorSpline::grid_points_normals_padded`] normalises together.
const NORMAL_BLOCK: usize = 4;

/// S = Σ_r M_r C_r, S_u = Σ_r M_r C′_r and S_v = Σ_r M_r′ C_r over the W padded isocurve
/// coefficients from `base` (each coordinate summed in the order of the plain path).
#[inline(always)]
fn padded_sums<const W: usize>(
    iso0: &[[f64; PADDED]],
    iso1: &[[f64; PADDED]],
    base: usize,
    m0: &[f64; W],
    m1: &[f64; W],
) -> ([f64; PADDED], [f64; PADDED], [f64; PADDED]) {
    let c0: &[[f64; PADDED]; W] = iso0[base..base + W].try_into().expect("W coefficients");
    let c1: &[[f64; PADDED]; W] = iso1[base..base + W].try_into().expect("W coefficients");
    let (mut s, mut s_u, mut s_v) = ([0.0; PADDED], [0.0; PADDED], [0.0; PADDED]);
    for r in 0..W {
        for c in 0..PADDED {
            s[c] += c0[r][c] * m0[r];
            s_v[c] += c0[r][c] * m1[r];
            s_u[c] += c1[r][c] * m0[r];
        }
    }
    (s, s_u, s_v)
}

/// Width of the padded coordinate arrays of the grid with normals (D ≤ 4: 2-D, 3-D and
/// homogeneous 3-D points fill one AVX2 register).
const PADDED: usize = 4;

/// The unit normal S_u × S_v/|S_u × S_v| from coordinate arrays, as
/// [`crate::surface::unit_normal`] computes it (its fallbacks where |S_u × S_v|² is not a
/// normal positive number; zero outside ℝ³ or where there is no normal).
#[inline(always)]
fn normal<const D: usize>(a: &[f64; D], b: &[f64; D]) -> crate::Point<D> {
    if D == 3 {
        let n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        let len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if len2 > f64::MIN_POSITIVE && len2.is_finite() {
            let inv = 1.0 / len2.sqrt();
            return crate::Point::<D>::from_fn(|i, _| n[i] * inv);
        }
    }
    let (a, b) = (crate::Point::<D>::from(*a), crate::Point::<D>::from(*b));
    crate::surface::unit_normal(&a, &b).unwrap_or_else(crate::Point::<D>::zeros)
}

/// One grid row of [`TensorSpline::eval_grid_first`] with the v-order W known at compile
/// time, so the W-term sums unroll.
#[inline(always)]
fn row_first<const W: usize, T: Coefficient>(
    iso0: &[T],
    iso1: &[T],
    v_spans: &[usize],
    v_basis: &[f64],
    row: usize,
    f: &mut impl FnMut(usize, T, T, T),
) {
    for (b, &base) in v_spans.iter().enumerate() {
        // The basis values M_r(v) and their derivatives M_r′(v), W of each, as arrays of
        // the compile-time length (any W: no fixed-size scratch to overflow).
        let nb = &v_basis[b * 2 * W..(b + 1) * 2 * W];
        let m0: &[f64; W] = nb[..W].try_into().expect("W basis values");
        let m1: &[f64; W] = nb[W..].try_into().expect("W basis derivatives");
        let c0: &[T; W] = iso0[base..base + W].try_into().expect("W coefficients");
        let c1: &[T; W] = iso1[base..base + W].try_into().expect("W coefficients");
        let (mut s, mut s_u, mut s_v) = (T::zero(), T::zero(), T::zero());
        for r in 0..W {
            s += c0[r] * m0[r];
            s_v += c0[r] * m1[r];
            s_u += c1[r] * m0[r];
        }
        f(row + b, s, s_u, s_v);
    }
}
