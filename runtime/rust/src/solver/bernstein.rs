//! Budan-Fourier points, Taylor tables and the Bernstein tests (C:
//! `runtime/c/roots/bernstein.inc`).

use super::*;

// ---------------------------------------------------------------------------------------
// Budan-Fourier isolation
// ---------------------------------------------------------------------------------------

fn sign_changes(v: &[f64], n: usize) -> i32 {
    let (mut count, mut last) = (0, 0);
    for &x in &v[..=n] {
        let s = i32::from(x > 0.0) - i32::from(x < 0.0);
        count += i32::from(s * last < 0);
        last = if s != 0 { s } else { last };
    }
    count
}

/// C `changes_certain`: the sign changes of `v[..=n]` when no entry is 0 or NaN, from the sign
/// bits alone (a third of `sign_changes`' instructions).
fn changes_certain(v: &[f64], n: usize) -> i32 {
    let mut prev = v[0].to_bits();
    let mut count = 0;
    for &x in &v[1..=n] {
        let b = x.to_bits();
        count += ((b ^ prev) >> 63) as i32;
        prev = b;
    }
    count
}

/// The Taylor table of the C runtime.  Only the entries `[k][j]` with `j + k <= n` are written
/// and only those are read (as in C, where the rest stays uninitialised): zeroing two 17 x 17
/// tables on every solve would cost more than the solve of a window without a root.
pub(super) struct Taylor {
    tk: Table,
    ta: Table,
    e: f64,
    skin: f64,
}

type Table = [[MaybeUninit<f64>; MAXN + 1]; MAXN + 1];

#[cfg(test)]
pub(super) fn binom(k: usize, j: usize) -> f64 {
    // C(j + k, k), exact in doubles for j + k <= 16
    let mut r = 1.0f64;
    for i in 1..=k {
        r = r * (j + i) as f64 / i as f64;
    }
    r
}

/// Fills `slot` in place and returns it (returning the 4.6 kB table by value would copy it,
/// and building it as a struct literal makes the compiler zero it, on every solve).
pub(super) fn taylor_table<'a>(p: &[f64], n: usize, e: f64, skin: f64, slot: &'a mut MaybeUninit<Taylor>) -> &'a Taylor {
    let tb = slot.as_mut_ptr();
    // SAFETY: field writes through the slot's pointer (no drop glue, no reference to
    // uninitialised memory); afterwards every field is initialised (the tables are arrays of
    // MaybeUninit), so the reference returned is to a valid Taylor.
    unsafe {
        (*tb).e = e;
        (*tb).skin = skin;
        for k in 0..n + 1 {
            for j in 0..n - k + 1 {
                let v = BINOM[k][j] * p[j + k];
                (*tb).tk[k][j] = MaybeUninit::new(v);
                (*tb).ta[k][j] = MaybeUninit::new(v.abs());
            }
        }
        // zeros up to degree 8, for point_at's fixed bounds
        for k in 0..9 {
            for j in (n + 1).saturating_sub(k)..9 - k {
                (*tb).tk[k][j] = MaybeUninit::new(0.0);
                (*tb).ta[k][j] = MaybeUninit::new(0.0);
            }
        }
        slot.assume_init_ref()
    }
}

/// What is known at a point of the window (C's Point): p's Taylor coefficients there (`pt`),
/// q's (`qt`) and bounds on their errors (`tol`).  The arrays hold entries 0..=n only, as in
/// C: writing all 17 of each for every point would cost more than the counts.
#[derive(Clone, Copy)]
pub(super) struct Point {
    pub(super) x: f64,
    pub(super) px: f64,
    pub(super) dpx: f64,
    pub(super) vp: i32,
    pub(super) vq: i32,
    pt: [MaybeUninit<f64>; MAXN + 1],
    qt: [MaybeUninit<f64>; MAXN + 1],
    tol: [MaybeUninit<f64>; MAXN + 1],
}

impl Point {
    /// p's Taylor coefficient k (k <= n: written by point_at / point_at_zero).
    #[inline]
    fn pt(&self, k: usize) -> f64 {
        // SAFETY: every Point in use had entries 0..=n written, and k <= n here.
        unsafe { self.pt[k].assume_init() }
    }

    /// q's Taylor coefficient k (k <= n: written by point_at / point_at_zero).
    #[inline]
    pub(super) fn qt(&self, k: usize) -> f64 {
        // SAFETY: every Point in use had entries 0..=n written, and k <= n here.
        unsafe { self.qt[k].assume_init() }
    }

    #[inline]
    pub(super) fn tol(&self, k: usize) -> f64 {
        // SAFETY: as for qt.
        unsafe { self.tol[k].assume_init() }
    }

    /// q's Taylor coefficients 0..=n as a slice.
    #[inline(always)]
    fn qts(&self, n: usize) -> &[f64] {
        let n = n.min(MAXN);
        // SAFETY: MaybeUninit<f64> has f64's layout, and entries 0..=n of every Point in use
        // were written (point_at / point_at_zero).
        unsafe { std::slice::from_raw_parts(self.qt.as_ptr().cast::<f64>(), n + 1) }
    }

    /// The error bounds 0..=n as a slice.
    #[inline(always)]
    fn tols(&self, n: usize) -> &[f64] {
        let n = n.min(MAXN);
        // SAFETY: as for qts.
        unsafe { std::slice::from_raw_parts(self.tol.as_ptr().cast::<f64>(), n + 1) }
    }

    /// C's `a = *b`, the entries in use only (0..=n), one double at a time: a struct copy is a
    /// memcpy of 440 bytes whose wide loads wait for point_at's 8-byte stores to retire (a
    /// store-forwarding stall), measured at 7 % of the benchmark's Rust time.
    #[inline]
    pub(super) fn assign(&mut self, b: &Point, n: usize) {
        self.x = b.x;
        self.px = b.px;
        self.dpx = b.dpx;
        self.vp = b.vp;
        self.vq = b.vq;
        for k in 0..n.min(MAXN) + 1 {
            self.pt[k] = b.pt[k];
            self.qt[k] = b.qt[k];
            self.tol[k] = b.tol[k];
        }
    }
}

#[inline(always)]
/// C `point_at_zero`, written in place into a slot (building a `Point` and returning it cost a
/// memset and a 300-byte memcpy per solve: a tenth of a "no root" solve).
pub(super) fn point_at_zero<'a>(p: &[f64], n: usize, e: f64, skin: f64, slot: &'a mut MaybeUninit<Point>) -> &'a mut Point {
    let n = n.min(MAXN);
    let pt = slot.as_mut_ptr();
    // SAFETY: field writes through the slot's pointer (no reference to uninitialised memory is
    // made; the fields have no drop glue); every field is written before the reference is made
    // (pt, qt and tol entries 0..=n, all that is ever read).
    unsafe {
        (*pt).x = 0.0;
        (*pt).px = p[0];
        (*pt).dpx = p[1];
        let mut zero = false;
        for i in 0..n + 1 {
            (*pt).pt[i] = MaybeUninit::new(p[i]);
            (*pt).qt[i] = MaybeUninit::new(p[i] - e * p[i].abs());
            (*pt).tol[i] = MaybeUninit::new(f64::EPSILON * p[i].abs());
            zero |= p[i] == 0.0;
        }
        // (without zeros, from the sign bits)
        (*pt).vp = if zero { sign_changes(p, n) } else { changes_certain(p, n) };
        (*pt).vq = (*pt).vp;
        let pt = slot.assume_init_mut();
        if skin > 0.0 {
            pt.qt[0] = MaybeUninit::new(pt.qt(0) - skin);
            pt.tol[0] = MaybeUninit::new(pt.tol(0) + f64::EPSILON * skin);
            let mut qt = [0.0f64; MAXN + 1];
            for (i, q) in qt.iter_mut().enumerate().take(n + 1) {
                *q = pt.qt(i);
            }
            pt.vq = sign_changes(&qt, n);
        }
        pt
    }
}

/// The Taylor coefficients of p and |p| at x > 0 up to degree 8, over degree 8 with constant
/// bounds, as C writes it out (the table is 0 above degree n, and 0 x + 0 = 0 for x > 0: the
/// same values as `taylor_shift`, bit for bit; entries above n are 0).
#[inline(always)]
pub(super) fn taylor_shift_8(tb: &Taylor, x: f64, a: &mut [f64; MAXN + 1], s: &mut [f64; MAXN + 1]) {
    let (mut a9, mut s9) = ([0.0f64; 9], [0.0f64; 9]);
    for d in (0..9).rev() {
        for k in 0..9 - d {
            // SAFETY: k + d <= 8: taylor_table wrote [k][d] (p's entry or a zero).
            let (t, u) = unsafe { (tb.tk[k][d].assume_init(), tb.ta[k][d].assume_init()) };
            a9[k] = a9[k] * x + t;
            s9[k] = s9[k] * x + u;
        }
    }
    a[..9].copy_from_slice(&a9);
    s[..9].copy_from_slice(&s9);
}

/// The Taylor coefficients of p and |p| at x (entries 0..=n), C's loop (bounds that vary
/// with n): above degree 8.
pub(super) fn taylor_shift(tb: &Taylor, n: usize, x: f64, a: &mut [f64; MAXN + 1], s: &mut [f64; MAXN + 1]) {
    assert!(n <= MAXN);
    for d in (0..n + 1).rev() {
        for k in 0..n - d + 1 {
            // SAFETY: k + d <= n <= MAXN (asserted), so every index is in bounds, and
            // [k][d] is an entry taylor_table wrote.  (Unchecked: this double loop was the
            // solver's hottest code, and the bounds checks cost 30 % of it.)
            unsafe {
                let t = tb.tk.get_unchecked(k).get_unchecked(d).assume_init();
                let u = tb.ta.get_unchecked(k).get_unchecked(d).assume_init();
                let ak = a.get_unchecked_mut(k);
                *ak = *ak * x + t;
                let sk = s.get_unchecked_mut(k);
                *sk = *sk * x + u;
            }
        }
    }
}

/// Writes the point x into `slot` (all of x, px, dpx, vp, vq and entries 0..=n of pt, qt and tol) and
/// returns true, or returns false (slot not to be used) when a sign is not certain.
pub(super) fn point_at(tb: &Taylor, n: usize, x: f64, slot: &mut MaybeUninit<Point>) -> bool {
    count::event(6);
    count::madds((n + 1) * (n + 2));
    let pt = slot.as_mut_ptr();
    let mut a = [0.0f64; MAXN + 1];
    let mut s = [0.0f64; MAXN + 1];
    if n <= 8 {
        taylor_shift_8(tb, x, &mut a, &mut s);
    } else {
        taylor_shift(tb, n, x, &mut a, &mut s);
    }
    let rel = 8.0 * (n + 1) as f64 * U;
    let tiny = f64::MIN_POSITIVE;
    for k in 0..n + 1 {
        let mut b = a[k] - tb.e * s[k];
        let mut tol = rel * s[k] + tiny;
        if k == 0 && tb.skin > 0.0 {
            b -= tb.skin;
            tol += rel * tb.skin;
        }
        if !(a[k].abs() > tol && b.abs() > tol) {
            return false;
        }
        // SAFETY: field writes through the slot's pointer (no reference to uninitialised
        // memory is made; the fields have no drop glue).
        unsafe {
            (*pt).pt[k] = MaybeUninit::new(a[k]);
            (*pt).qt[k] = MaybeUninit::new(b);
            (*pt).tol[k] = MaybeUninit::new(tol);
        }
        s[k] = b;
    }
    // SAFETY: as above.
    unsafe {
        (*pt).x = x;
        (*pt).px = a[0];
        (*pt).dpx = a[1];
        (*pt).vp = changes_certain(&a, n); // (every |a_k|, |b_k| > tol > 0 above)
        (*pt).vq = changes_certain(&s, n);
    }
    true
}

/// C `bounds_positive`: is q > 0 on [x, x + w] (dir = 1) or [x - w, x] (dir = -1), from q's
/// Taylor coefficients at x (`qt`) and the bounds on their errors (`tol`), entries 0..=n?  The
/// first-order exclusion test, then the second-order one (see the C source).  On arrays, so
/// that `cleared_at_once` can run it on the coefficients as given, before any `Point` exists.
pub(super) fn bounds_positive(qt: &[f64], tol: &[f64], n: usize, w: f64, dir: i32) -> bool {
    count::madds(n);
    let (qt, tol) = (&qt[..=n], &tol[..=n]);
    let rel = 4.0 * (n + 1) as f64 * U;
    let l = |k: usize| (if dir < 0 && k % 2 == 1 { -qt[k] } else { qt[k] }) - tol[k];
    let mut r3 = 0.0;
    for k in (3..n + 1).rev() {
        let lk = l(k);
        r3 = r3 * w + if lk < 0.0 { -lk } else { 0.0 };
    }
    let mut lk = [0.0f64; 3];
    for (k, v) in lk.iter_mut().enumerate().take(n.min(2) + 1) {
        *v = l(k);
    }
    let mut neg = r3;
    for k in (1..n.min(2) + 1).rev() {
        neg = neg * w + if lk[k] < 0.0 { -lk[k] } else { 0.0 };
    }
    neg *= w;
    let l0 = lk[0];
    if l0 > neg + rel * neg {
        return true;
    }
    if n < 2 {
        return false;
    }
    let l1 = lk[1];
    let l2 = lk[2] - r3 * w * (1.0 + rel);
    if !(l2 > 0.0) {
        return false;
    }
    let mut h = -l1 / (2.0 * l2);
    h = if h < 0.0 { 0.0 } else if h > w { w } else { h };
    let m = l0 + h * (l1 + h * l2);
    let size = l0.abs() + h * (l1.abs() + h * l2);
    m > 2.0 * rel * size
}

/// C's clearly_positive: `bounds_positive` on a point's q and error bounds.
#[inline(always)]
pub(super) fn clearly_positive(pt: &Point, n: usize, w: f64, dir: i32) -> bool {
    bounds_positive(pt.qts(n), pt.tols(n), n, w, dir)
}

/// 1 / C(n, k) (C's INV_BINOM): each the correctly rounded quotient of exact integers, as C's
/// constant expressions `1.0 / 6` are.
pub(super) static INV_BINOM: [[f64; MAXN + 1]; MAXN + 1] = reciprocals(pascal_table());

/// 1 / x for the nonzero entries (0 stays 0).
const fn reciprocals(mut t: [[f64; MAXN + 1]; MAXN + 1]) -> [[f64; MAXN + 1]; MAXN + 1] {
    let mut i = 0;
    while i < (MAXN + 1) * (MAXN + 1) {
        let x = t[i / (MAXN + 1)][i % (MAXN + 1)];
        if x != 0.0 {
            t[i / (MAXN + 1)][i % (MAXN + 1)] = 1.0 / x;
        }
        i += 1;
    }
    t
}

/// PASCAL[j][k] = C(j, k) = BINOM[k][j - k]: the rows of Pascal's triangle (the same exact
/// integers as C's tables).
const fn pascal_table() -> [[f64; MAXN + 1]; MAXN + 1] {
    let binom = binom_table();
    let mut t = [[0.0; MAXN + 1]; MAXN + 1];
    let mut j = 0;
    while j <= MAXN {
        let mut k = 0;
        while k <= j {
            t[j][k] = binom[k][j - k];
            k += 1;
        }
        j += 1;
    }
    t
}

/// What Descartes' rule in the Bernstein basis says about an interval (C's BERN_*).
pub(super) enum Bernstein {
    /// q's coefficients all certainly positive: q > 0 on the interval, nothing in it.
    Clear,
    /// Every sign of p and q certain, each changing once: exactly one simple root of p and
    /// nothing before it but noise.  Holds p at the right end (the last coefficient).
    One(f64),
    Unknown,
}

/// What the test on (0, T] reports besides its verdict (C's `qb` argument): q's Bernstein
/// coefficients (entries 0..=n), the bound on their errors, and whether their signs are
/// certain with an even number of changes (then `bernstein_clear` may clear q).
pub(super) struct Start {
    pub(super) q: [f64; MAXN + 1],
    pub(super) err: f64,
    pub(super) even: bool,
}

/// b_j = sum_{k <= j} C(j, k) a_k, j = 0..=n, in place (C `binomial_sums`): n rounds of
/// running sums, round r adding to each entry j >= r its left neighbour, j descending.  Up to
/// degree 8 over 9 entries with constant bounds (fully unrolled, in registers: the entries
/// above n, zeros, never reach those below), as C writes it out.
#[inline(always)]
pub(super) fn binomial_sums(a: &mut [f64; MAXN + 1], n: usize) {
    if n <= 8 {
        let mut b = [a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8]];
        for r in 1..9 {
            for j in (r..9).rev() {
                b[j] += b[j - 1];
            }
        }
        a[..9].copy_from_slice(&b);
        return;
    }
    let n = n.min(MAXN);
    for r in 1..n + 1 {
        for j in (r..n + 1).rev() {
            a[j] += a[j - 1];
        }
    }
}

/// C `bernstein_test`: the Bernstein coefficients of p and q on [x, x + w] (x = pt.x) from
/// their Taylor coefficients at x, each sign trusted only beyond one scalar error bound (see
/// the C source for why it serves every coefficient); q's first, p's when q's allow `One` or
/// when `start` asks for the guess (then `start` is filled, unless the verdict is `Clear`).
#[inline(always)]
pub(super) fn bernstein_test(pt: &Point, n: usize, w: f64, start: Option<&mut Start>) -> Bernstein {
    let n = n.min(MAXN);
    count::event(9);
    count::madds(n * (n + 1) / 2 + 4 * n); // the sums and the scaling
    // (entries n + 1..=8 zero: binomial_sums reads 9)
    let mut ap = [0.0f64; MAXN + 1];
    let mut aq = [0.0f64; MAXN + 1];
    let rel = 4.0 * (2 * n + 4) as f64 * U;
    let inv = &INV_BINOM[n];
    let (mut wk, mut g) = (1.0, 0.0);
    for k in 0..n + 1 {
        let f = wk * inv[k];
        let (p, q) = (pt.pt(k), pt.qt(k));
        ap[k] = p * f;
        aq[k] = q * f;
        g += (pt.tol(k) + rel * (p.abs() + q.abs())) * wk;
        wk *= w;
    }
    let tol = 2.0 * g + f64::MIN_POSITIVE;
    binomial_sums(&mut aq, n);
    let b = &aq;
    // (branch-free, as in C: the signs are data; the sign bits count only where every sign is
    // certain, which is all that is read of them)
    let (mut certain, mut neg) = (true, 0u64);
    for &bj in &b[..=n] {
        certain &= bj.abs() > tol;
        neg |= bj.to_bits();
    }
    if certain && neg >> 63 == 0 {
        return Bernstein::Clear;
    }
    let vq = changes_certain(b, n);
    if let Some(start) = start {
        if n <= 8 {
            start.q[..9].copy_from_slice(&b[..9]); // (constant size: no memcpy call)
        } else {
            start.q = *b;
        }
        start.err = tol;
        start.even = certain && vq % 2 == 0;
    }
    // (an odd count for p means p(x + w) < 0, so q(x + w) < 0 too: q's count is odd, and
    // start.even already false)
    if !(certain && vq == 1) {
        return Bernstein::Unknown;
    }
    count::madds(n * (n + 1) / 2);
    binomial_sums(&mut ap, n);
    let pend = ap[n];
    for &bj in &ap[..=n] {
        certain &= bj.abs() > tol;
    }
    if certain && changes_certain(&ap, n) == 1 {
        Bernstein::One(pend)
    } else {
        Bernstein::Unknown
    }
}

/// C `halves`: the Bernstein coefficients of both halves of the interval (de Casteljau at 1/2,
/// one triangle of n rounds of averages of neighbours: left[k] is its first entry after round
/// k, right[n - k] its last), from entries 0..=n of `inp` (those above n are not read) to
/// entries 0..=n of the results (those above n are 0).  At degree 8 on arrays of 9 with the
/// degree a constant, so that the loops unroll as C writes them out.
#[inline(always)]
pub(super) fn halves<const W: usize>(inp: &[f64; W], n: usize) -> ([f64; W], [f64; W]) {
    if W == 9 && n == 8 {
        halves_of_degree(inp, 8)
    } else {
        halves_of_degree(inp, n.min(W - 1))
    }
}

#[inline(always)]
fn halves_of_degree<const W: usize>(inp: &[f64; W], n: usize) -> ([f64; W], [f64; W]) {
    let mut w: [f64; W] = std::array::from_fn(|j| if j <= n { inp[j] } else { 0.0 });
    let (mut left, mut right) = ([0.0f64; W], [0.0f64; W]);
    left[0] = w[0];
    right[n] = w[n];
    for k in 1..n + 1 {
        for j in 0..n - k + 1 {
            w[j] = (w[j] + w[j + 1]) * 0.5;
        }
        left[k] = w[0];
        right[n - k] = w[n - k];
    }
    (left, right)
}

/// Halvings after which `bernstein_clear` gives up.
const CLEAR_DEPTH: usize = 12;
/// C `DIP_INSIDE`: a dip counts for a first split when it is at least this fraction of the
/// interval from either end (bernstein_clear, isolate_first_root).
pub(super) const DIP_INSIDE: f64 = 0.0625;

/// C `bernstein_clear`: is q > 0 on the interval whose Bernstein coefficients are q[0..=n]
/// (certain signs beyond `err`, an even count)?  Depth-first bisection in the Bernstein basis
/// (left half first); a piece is cleared when its coefficients are all certainly positive, and
/// the answer is no at the first piece with an uncertain sign or differing end signs, or
/// beyond CLEAR_DEPTH halvings.  A child's error bound is its parent's plus 2 n u M + DBL_MIN
/// (see the C source); the first split is at t0 instead (the dip) when that is DIP_INSIDE or
/// more from either end, its error 8 n u M.  Out of line, as in C: a rare path.  Up to degree 8 on arrays of 9
/// (constant sizes: no memcpy or memset calls, and half the stack to zero).
#[inline(never)]
pub(super) fn bernstein_clear(q: &[f64; MAXN + 1], err0: f64, n: usize, t0: f64) -> bool {
    if n == 8 {
        // degree 8 a constant, its loops' bounds fixed (C's bernstein_clear_8; without it,
        // near the window 1.21 times C's time instead of 1.08-1.11)
        clear_pieces::<9>(std::array::from_fn(|j| q[j]), err0, 8, t0)
    } else if n <= 8 {
        clear_pieces::<9>(std::array::from_fn(|j| q[j]), err0, n, t0)
    } else {
        clear_pieces::<{ MAXN + 1 }>(*q, err0, n, t0)
    }
}

/// C `split_at`: the Bernstein coefficients of [0, t] and [t, 1] of the interval (de
/// Casteljau at t in (0, 1): n rounds of w_j + t (w_{j+1} - w_j); left[k] the first entry
/// after round k, right[n - k] the last), from entries 0..=n of `inp`.
/// Inlined, so that in `bernstein_clear`'s copy for degree 8 its loops have fixed bounds
/// (C writes it out for degree 8).
#[inline(always)]
fn split_at<const W: usize>(inp: &[f64; W], n: usize, t: f64) -> ([f64; W], [f64; W]) {
    let mut w = *inp;
    let (mut left, mut right) = ([0.0f64; W], [0.0f64; W]);
    left[0] = w[0];
    right[n] = w[n];
    for k in 1..n + 1 {
        for j in 0..n + 1 - k {
            w[j] = w[j] + t * (w[j + 1] - w[j]);
        }
        left[k] = w[0];
        right[n - k] = w[n - k];
    }
    (left, right)
}

/// A piece of `bernstein_clear`'s interval: q's Bernstein coefficients on it (0..=n), the
/// bound on their errors, and the halvings that made it.
#[derive(Clone, Copy)]
struct Piece<const W: usize> {
    b: [f64; W],
    err: f64,
    depth: usize,
}

#[inline(always)]
fn clear_pieces<const W: usize>(q: [f64; W], err: f64, n: usize, t0: f64) -> bool {
    let n = n.min(W - 1);
    // a stack of which st[..top] is in use, not zeroed: most calls end at the first piece
    // (zeroing the stack cost more than such a call)
    let mut st: [MaybeUninit<Piece<W>>; CLEAR_DEPTH + 2] = [const { MaybeUninit::uninit() }; CLEAR_DEPTH + 2];
    st[0] = MaybeUninit::new(Piece { b: q, err, depth: 0 });
    let mut top = 1;
    while top > 0 {
        top -= 1;
        // SAFETY: st[..top + 1] were written (the first above, the others below) before use.
        let Piece { b, err: e, depth: d } = unsafe { st[top].assume_init_read() };
        // with every sign certain (no zeros), the number of sign changes is odd exactly when
        // the end signs differ
        let (mut lo, mut hi, mut amin) = (b[0], b[0], b[0].abs());
        for &bj in &b[1..=n] {
            lo = if bj < lo { bj } else { lo };
            hi = if bj > hi { bj } else { hi };
            amin = if bj.abs() < amin { bj.abs() } else { amin };
        }
        if !(amin > e) || (b[0] > 0.0) != (b[n] > 0.0) {
            return false;
        }
        if lo > 0.0 {
            continue;
        }
        let m = if -lo > hi { -lo } else { hi };
        if d == CLEAR_DEPTH {
            return false;
        }
        // halves: the right one over b's slot, the left one above it (looked at first)
        count::madds(n * (n + 1) / 2);
        // the first split at t0 (the dip: C bernstein_clear says why), the others at 1/2
        let at = d == 0 && t0 > DIP_INSIDE && t0 < 1.0 - DIP_INSIDE;
        let (left, right) = if at { split_at(&b, n, t0) } else { halves(&b, n) };
        let ec = e + ((if at { 8 } else { 2 }) * n) as f64 * U * m + f64::MIN_POSITIVE;
        st[top] = MaybeUninit::new(Piece { b: right, err: ec, depth: d + 1 });
        st[top + 1] = MaybeUninit::new(Piece { b: left, err: ec, depth: d + 1 });
        top += 2;
    }
    true
}

pub(super) static BINOM: [[f64; MAXN + 1]; MAXN + 1] = binom_table();

const fn binom_table() -> [[f64; MAXN + 1]; MAXN + 1] {
    let mut t = [[0.0; MAXN + 1]; MAXN + 1];
    let mut k = 0;
    while k <= MAXN {
        let mut j = 0;
        while j + k <= MAXN {
            // C(j + k, k) by the integer recurrence (exact)
            let mut r: u64 = 1;
            let mut i = 1;
            while i <= k {
                r = r * (j + i) as u64 / i as u64;
                i += 1;
            }
            t[k][j] = r as f64;
            j += 1;
        }
        k += 1;
    }
    t
}
