//! The early exits before the preparation, steps 0a' and 0b (C:
//! `runtime/c/roots/early.inc`).

use super::*;

/// C `outweighed`, step 0a' of `solve` (see the C header): no root in (0, inf) by the AM-GM
/// inequality, where every negative coefficient of sign(c_0) c stands alone between two
/// positive ones, a t^(i-1) + b t^(i+1) >= 2 sqrt(a b) t^i for t > 0: each positive coefficient
/// lends half of itself to each of two negative neighbours (all of itself to one), shown for
/// the envelope q with twice the noise factor, so that no computed graze test sees a touch
/// where this sees none.  The rounding of the comparison is within K; an infinite right side
/// is a true one.  Only with tmax = inf (where step 0b needs the preparation first).
/// c: n + 1 coefficients, c[0] != 0, n >= 3.
pub(crate) fn outweighed(c: &Coeffs, n: usize) -> bool {
    let s = if c[0] < 0.0 { -1.0 } else { 1.0 };
    let e = 2.0 * noise_factor(n);
    let k = (1.0 + e) / (1.0 - e) * (1.0 + 16.0 * U);
    if !(s * c[n] > 0.0) {
        return false;
    }
    // C's order: the signs as bit masks, the pattern in one test (every negative's two
    // neighbours positive), then each negative's comparison by its bit, no exit at a failure
    // (the branches on the signs are data; see the C comment)
    let (mut neg, mut pos) = (0u32, 0u32);
    for (i, &ci) in c.iter().enumerate().take(n + 1) {
        let v = s * ci;
        neg |= u32::from(v < 0.0) << i;
        pos |= u32::from(v > 0.0) << i;
    }
    if ((neg << 1) | (neg >> 1)) & !pos != 0 {
        return false; // a zero, or two negatives side by side
    }
    let mut ok = true;
    let mut m = neg;
    while m != 0 {
        let i = m.trailing_zeros() as usize; // the lowest negative left (1 <= i < n)
        m &= m - 1;
        let v = s * c[i];
        let (mut a, mut b) = (s * c[i - 1], s * c[i + 1]);
        // a lends to i - 2 too when that is negative, b to i + 2
        a *= 1.0 - 0.5 * f64::from(((neg << 2) >> i) & 1);
        b *= 1.0 - 0.5 * f64::from((neg >> (i + 2)) & 1);
        ok &= -v * k < 2.0 * (a.sqrt() * b.sqrt());
    }
    ok
}

/// C `cleared_at_once`, step 0b of `solve` (see the C header): no root in (0, tmax] by the
/// bounds of `clearly_positive` at 0 over the whole of [0, tmax], on the coefficients as
/// given, before the preparation -- which, with the `Point` it fills, is most of the cost of a
/// solve that this test settles.  The lower bounds L_k are those `point_at_zero` and
/// `clearly_positive` form from p = c 2^-E sign(c_0) (`normalise`'s exact scaling), bit for
/// bit.  Only where `reduce` would keep every term (the exponents show it: `leading_far`) and
/// the spread is in range, so that the polynomial tested is the one the full path solves; any
/// window [0, w] may be tested, so that the bound B on the roots is not needed.  Where it
/// fails, the full path runs as before (then with w = min(tmax, B), which may clear what this
/// did not).  `Some(true)`: no root (C 1); `Some(false)`: the test failed (C 0); `None`: not
/// tried (C -1).  c: n + 1 coefficients with c[0] != 0, tmax finite.  Out of line, as in C.
#[inline(never)]
pub(crate) fn cleared_at_once(c: &Coeffs, e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, tmax: f64, sc: Scan) -> Option<bool> {
    let big_e = sc.emax + 1;
    // (DBL_MIN_EXP = -1021, DBL_MAX_EXP - 2 = 1022: the range where normalise scales by one
    // product; the spread is computed only for a nonzero c_n, so never of the empty scan)
    if !nz[n] || sc.emax - sc.emin > MAX_SPREAD || !(-1021..=1022).contains(&big_e) || !leading_far(e, nz, n, tmax, sc.emax) {
        return None;
    }
    let f = (if c[0] < 0.0 { -1.0 } else { 1.0 }) * pow2(-big_e);
    let en = noise_factor(n);
    let (mut qt, mut tol) = ([0.0f64; MAXN + 1], [0.0f64; MAXN + 1]);
    for k in 0..n + 1 {
        let p = c[k] * f;
        qt[k] = p - en * p.abs();
        tol[k] = f64::EPSILON * p.abs();
    }
    Some(bounds_positive(&qt, &tol, n, tmax, 1))
}
