//! The interval solver of the C runtime (`runtime/c/max2code_roots.c`), ported operation for
//! operation: the same preparation, Budan-Fourier isolation with certified signs, derivative
//! (Yuksel) method for what the counts do not resolve, and safeguarded Newton polished with
//! compensated Horner.  Every floating-point operation is the C one in the same order (`fma`
//! is `mul_add`, both correctly rounded; the C runtime is compiled without contraction, as
//! `-std=c11` does), so the results are bit-identical to the C runtime's; the cross-language
//! tests check that on every hard case, random polynomial and fuzz vector.
//!
//! The comments of the C source explain the why of each step; they are not repeated here.

// Indexed loops and negated comparisons mirror the C source line by line (a negated
// comparison is also true for NaN, which the C code relies on).
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

use std::mem::MaybeUninit;

use crate::count;
use crate::fp::{ilogb, ldexp};

pub(crate) const MAXN: usize = 16;
const U: f64 = f64::EPSILON / 2.0;
const SAFE_LOW: f64 = 1.329_227_995_784_916e36; // 2^120
const SAFE_HIGH: f64 = 1.152_921_504_606_847e18; // 2^60
const FAST_LIMIT_LOW: f64 = 1.267_650_600_228_229_4e30; // 2^100
const FAST_LIMIT_HIGH: f64 = 7.205_759_403_792_794e16; // 2^56
const MAX_ITER: usize = 200;
/// After this many iterations a Newton step that moves x by over 2^-10 of it in a bracket
/// spanning more than a factor 8 is replaced by a geometric bisection (from lo = 0: hi / 2^64):
/// far from every root Newton converges only linearly (see the C runtime).
const SLOW_AFTER: usize = 16;
const TOL_CRITICAL: f64 = 1.455_191_522_836_685_2e-11; // 2^-36
const TOL_LEVEL: f64 = 3.725_290_298_461_914e-9; // 2^-28
const PRECISE_FROM: f64 = 1.490_116_119_384_765_6e-8; // 2^-26
/// C `GUESS_DONE`, `GUESS_FAST`: the guess's Laguerre also stops after a step below GUESS_DONE
/// (relative) that was at most GUESS_FAST of the step before.
const GUESS_DONE: f64 = 6.103_515_625e-5; // 2^-14
const GUESS_FAST: f64 = 0.0625; // 2^-4
const NOISE_STEP: f64 = 32.0 * U;
const MAX_SPLITS: usize = 40;
const SPLIT_NEWTON: f64 = 2.0;
const MIN_WIDTH: f64 = 9.536_743_164_062_5e-7; // 2^-20
const EARLY_WIDTH: f64 = 0.25;
const MAX_SPREAD: i32 = 1021;

pub(crate) type Coeffs = [f64; MAXN + 1];

/// Exponent of a finite nonzero double (as C's `exponent_of`/`ilogb`).
#[inline]
fn exponent_of(x: f64) -> i32 {
    ilogb(x)
}

/// `2^e`, exact, for a normal result.
#[inline]
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// ceil(2^32 / d) for the ceiling division below; 32 entries so that an index masked to 5 bits
/// needs no bounds check (entries beyond MAXN are never used).
static MAGIC: [u64; 32] = magic_table();

const fn magic_table() -> [u64; 32] {
    let mut t = [0u64; 32];
    let mut d = 1;
    while d < 32 {
        t[d] = (1u64 << 32).div_ceil(d as u64);
        d += 1;
    }
    t
}

/// ceil(num / den) for 0 < den <= 16 and |num| < 2^12, as C computes it, without a division
/// (C `ceil_div`): x = num + 2^12 den + den - 1 is positive and below 2^17, and for such x
/// floor(x / den) = floor(x ceil(2^32 / den) / 2^32).
#[inline]
fn ceil_div(num: i32, den: i32) -> i32 {
    debug_assert!((1..=MAXN as i32).contains(&den) && num.abs() < 1 << 12);
    let x = (num + 4096 * den + den - 1) as u64;
    ((x * MAGIC[den as usize & 31]) >> 32) as i32 - 4096
}

/// What `load_coefficients` reads off the bits besides the exponents, in the same pass (C
/// `Scan`): the largest and smallest exponent of the nonzero coefficients (the spread, unless
/// `reduce` drops terms) and the number of sign changes with zeros (of either sign) skipped:
/// Descartes' bound on the positive roots, which clears a solve with no sign change before any
/// preparation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Scan {
    /// No NaN, no infinity.
    pub(crate) finite: bool,
    /// `i32::MIN` when every coefficient is 0.
    pub(crate) emax: i32,
    /// `i32::MAX` when every coefficient is 0.
    pub(crate) emin: i32,
    pub(crate) changes: i32,
}

/// C `load_coefficients`: copies `src` (n + 1 = src.len() <= 17 entries) to c and reads the
/// exponents from the bits in the same pass: e[i] = ilogb(c[i]), nz[i] = (c[i] != 0), e[i] = 0
/// for zeros; the `Scan` of the same bits (`.finite` false: invalid input).  Branch-free but
/// for subnormals, as in C: the common case first, every coefficient a normal number (no zeros
/// to skip, no subnormal's ilogb: see the C source for what it saves), anything else read
/// again by `load_any`, with the same results where both apply.
#[inline]
pub(crate) fn load_coefficients(src: &[f64], c: &mut Coeffs, e: &mut [i32; MAXN + 1], nz: &mut [bool; MAXN + 1]) -> Scan {
    let (mut hi, mut lo, mut changes) = (i32::MIN, i32::MAX, 0);
    let mut prev = src[0].to_bits();
    for (((&x, ci), ei), nzi) in src.iter().zip(c.iter_mut()).zip(e.iter_mut()).zip(nz.iter_mut()) {
        let b = x.to_bits();
        // SAFETY: ci is a valid, aligned &mut f64 (volatile: see `load_any`).
        unsafe { std::ptr::write_volatile(ci, x) };
        let exp = ((b >> 52) & 0x7ff) as i32 - 1023;
        *ei = exp;
        *nzi = true;
        hi = if exp > hi { exp } else { hi };
        lo = if exp < lo { exp } else { lo };
        changes += ((b ^ prev) >> 63) as i32;
        prev = b;
    }
    // (biased exponent 0 -- a zero or a subnormal -- reads as -1023, 0x7ff -- an infinity or a
    // NaN -- as 1024)
    if lo > -1023 && hi < 1024 {
        return Scan { finite: true, emax: hi, emin: lo, changes };
    }
    load_any(src, c, e, nz)
}

/// `load_coefficients` for any coefficients: zeros skipped in the sign changes, subnormals'
/// exponents by ilogb, infinities and NaN flagged.  Out of line, as in C.
#[inline(never)]
fn load_any(src: &[f64], c: &mut Coeffs, e: &mut [i32; MAXN + 1], nz: &mut [bool; MAXN + 1]) -> Scan {
    let (mut bad, mut hi, mut lo, mut changes) = (false, i32::MIN, i32::MAX, 0);
    let mut last = 0u64; // the sign bit of the last nonzero, + 1; 0: none yet
    for (((&x, ci), ei), nzi) in src.iter().zip(c.iter_mut()).zip(e.iter_mut()).zip(nz.iter_mut()) {
        let b = x.to_bits();
        // SAFETY: ci is a valid, aligned &mut f64.  (A volatile store is a plain one here; it
        // keeps LLVM from splitting the copy out of this loop into a memcpy call, which cost
        // 4 % of a quick solve.)
        unsafe { std::ptr::write_volatile(ci, x) };
        let be = ((b >> 52) & 0x7ff) as i32;
        bad |= be == 0x7ff;
        let z = (b << 1) != 0;
        *nzi = z;
        let exp = if be != 0 {
            be - 1023
        } else if z {
            ilogb(x) // subnormal: rare
        } else {
            0
        };
        *ei = exp;
        let (h, l) = if z { (exp, exp) } else { (i32::MIN, i32::MAX) };
        hi = if h > hi { h } else { hi };
        lo = if l < lo { l } else { lo };
        let sg = (b >> 63) + 1;
        changes += i32::from(z & (last != 0) & (last != sg));
        last = if z { sg } else { last };
    }
    Scan { finite: !bad, emax: hi, emin: lo, changes }
}

/// C `root_bound_exponent`: every root is below 2^(the result); `None` when all c_i (i < n)
/// are 0.  e, nz: the exponents of c[0..=n] (`load_coefficients`; only their differences
/// matter).  With the coefficients `c` (`Some`), over the c_i of the sign opposite to c_n's
/// only: Kioustelidis' bound on the positive roots (`None` where no sign differs: no
/// positive root).  Branch-free, as in C: which term gives the maximum, and the signs, are
/// data.
#[inline]
fn root_bound_exponent(e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], c: Option<&Coeffs>, n: usize) -> Option<i32> {
    let en = e[n];
    let sn = c.map_or(0, |c| c[n].to_bits());
    let only = c.is_some();
    let mut best = i32::MIN;
    for i in 0..n {
        let q = ceil_div(e[i] + 1 - en, (n - i) as i32);
        let si = c.map_or(sn, |c| c[i].to_bits());
        let opposite = ((si ^ sn) >> 63) != 0;
        let q = if nz[i] & (opposite | !only) { q } else { i32::MIN };
        best = if q > best { q } else { best };
    }
    (best != i32::MIN).then_some(best + 1)
}

/// C `root_bound`: Fujiwara's bound (`c` None) or Kioustelidis' on the positive roots (`c`
/// Some); 0 when no c_i (i < n) counts, f64::MAX beyond the range.
pub(crate) fn root_bound(e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], c: Option<&Coeffs>, n: usize) -> f64 {
    match root_bound_exponent(e, nz, c, n) {
        None => 0.0,
        Some(b) if b >= 1024 => f64::MAX,
        Some(b) if b >= -1022 => pow2(b),
        Some(b) => ldexp(1.0, i64::from(b)),
    }
}

/// C `scaled_le`: |a| T^j <= k |b| (T > 0 finite), in mantissas and exponents.
#[cold]
fn scaled_le(a: f64, t: f64, j: usize, k: f64, b: f64) -> bool {
    let et = exponent_of(t);
    let mt = ldexp(t, -i64::from(et));
    let (mut ea, mut eb, ek) = (exponent_of(a), exponent_of(b), exponent_of(k));
    let mut ma = ldexp(a.abs(), -i64::from(ea));
    let mut mb = ldexp(b.abs(), -i64::from(eb)) * ldexp(k, -i64::from(ek));
    for _ in 0..j {
        ma *= mt;
        let e = ma >= 2.0;
        if e {
            ma *= 0.5;
        }
        ea += et + i32::from(e);
    }
    let e = mb >= 2.0;
    if e {
        mb *= 0.5;
    }
    eb += ek + i32::from(e);
    ea < eb || (ea == eb && ma <= mb)
}

/// C `leading_far`: do the exponents alone show the leading term far from negligible over
/// [0, T] (T finite): |c_n| T^(n-i) above 4 n eps |c_i| by a factor 8 for every i, beyond all
/// the roundings of the comparison?  Almost always; then `leading_negligible` needs no
/// floating-point loop, and `cleared_at_once` knows that `reduce` keeps every term.
/// Branch-free, as in C (which terms are nonzero is data).
fn leading_far(e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, t: f64, emax: i32) -> bool {
    if !(f64::MIN_POSITIVE..=f64::MAX).contains(&t) {
        return false;
    }
    // T >= 2^eT, k < 2^(ek + 1), |c| in [2^e, 2^(e + 1))
    let (e_t, ek) = (exponent_of(t), exponent_of(4.0 * n as f64 * f64::EPSILON));
    // emax (a bound on every e_i of a nonzero c_i: the Scan's largest; i32::MIN, every c_i 0,
    // leaves it to the loop): the least left side settles every term
    if emax > i32::MIN && e[n] + if e_t >= 0 { e_t } else { n as i32 * e_t } >= emax + ek + 5 {
        return true;
    }
    let mut far = true;
    let mut lhs = e[n] + e_t; // a lower bound on log2 |c_n| T^(n-i)
    for i in (0..n).rev() {
        far &= !nz[i] | (lhs >= e[i] + ek + 5);
        lhs += e_t;
    }
    far
}

/// C `leading_negligible` (in exponents where a side leaves the normal range).  e, nz: the
/// exponents of c (`load_coefficients`).  When the exponents alone show |c_n| T^(n-i) above
/// k |c_i| by a factor 8 for every i (`leading_far`), the answer is no without the
/// floating-point loop.  tmax = inf: no (`reduce` weighs over a finite K).
fn leading_negligible(c: &Coeffs, e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, tmax: f64, emax: i32) -> bool {
    let t = tmax;
    if t.is_infinite() {
        return false;
    }
    let k = 4.0 * n as f64 * f64::EPSILON;
    if leading_far(e, nz, n, t, emax) {
        return false;
    }
    let mut tp = 1.0;
    for i in (0..n).rev() {
        tp *= t;
        if c[i] == 0.0 {
            continue;
        }
        let (lhs, rhs) = (c[n].abs() * tp, k * c[i].abs());
        let normal = (f64::MIN_POSITIVE..=f64::MAX).contains(&tp)
            && (f64::MIN_POSITIVE..=f64::MAX).contains(&lhs)
            && rhs >= f64::MIN_POSITIVE;
        if if normal { lhs <= rhs } else { scaled_le(c[n], t, n - i, k, c[i]) } {
            return true;
        }
    }
    false
}

/// Drop zero/negligible leading terms and factors of t; the degree left, or -1.  c and its
/// exponents (e, nz) are modified in place.  emax: load_coefficients' largest exponent, which stays
/// a bound on every e_i left (`leading_far`).  With *tmax = inf the leading term is weighed over
/// (0, K], K the bound on the positive roots of the polynomial as it stands (with a skin,
/// `every_root`, on every root), and where it is dropped *tmax becomes K: roots of the rest
/// beyond K are none of the whole polynomial's (C `reduce`, whose comment has the history).
pub(crate) fn reduce(
    c: &mut Coeffs, e: &mut [i32; MAXN + 1], nz: &mut [bool; MAXN + 1], mut n: usize, tmax: &mut f64,
    every_root: bool, emax: i32,
) -> i32 {
    loop {
        while n > 0 && c[n] == 0.0 {
            n -= 1;
        }
        if n == 0 {
            return if c[0] == 0.0 { -1 } else { 0 };
        }
        if c[0] == 0.0 {
            for i in 0..n {
                c[i] = c[i + 1];
                e[i] = e[i + 1];
                nz[i] = nz[i + 1];
            }
            c[n] = 0.0;
            e[n] = 0;
            nz[n] = false;
            n -= 1;
            continue;
        }
        let mut t = *tmax;
        if t.is_infinite() {
            let k = root_bound(e, nz, if every_root { None } else { Some(&*c) }, n);
            t = if k > 0.0 && k < f64::MAX { k } else { f64::INFINITY };
        }
        if leading_negligible(c, e, nz, n, t, emax) {
            *tmax = t;
            c[n] = 0.0;
            e[n] = 0;
            nz[n] = false;
            n -= 1;
            continue;
        }
        return n as i32;
    }
}

/// C `spread`: the spread of the exponents e of c[0..=n] (-1: all zero) and the largest.
pub(crate) fn spread(e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize) -> (i32, i32) {
    let (mut hi, mut lo) = (i32::MIN, i32::MAX);
    for (&ei, &nzi) in e[..=n].iter().zip(&nz[..=n]) {
        if nzi {
            hi = hi.max(ei);
            lo = lo.min(ei);
        }
    }
    (if hi == i32::MIN { -1 } else { hi - lo }, hi)
}

/// C `exponents`: the exponents of c[0..=n] (finite; nz: nonzero), their spread (-1: all zero)
/// and the largest exponent.
pub(crate) fn exponents(c: &[f64], n: usize, e: &mut [i32; MAXN + 1], nz: &mut [bool; MAXN + 1]) -> (i32, i32) {
    let mut copy: Coeffs = [0.0; MAXN + 1];
    load_coefficients(&c[..=n], &mut copy, e, nz);
    spread(e, nz, n)
}

/// The spread above which `solve` takes `first_root_sliced`.
pub(crate) const fn max_spread() -> i32 {
    MAX_SPREAD
}

/// C `normalise`: scales exactly by sign 2^-E (sign +-1) so that max |c_i| (exponent emax) is
/// in [1/2, 1); returns E.  (The sign costs no pass of its own: the interval method wants
/// p(0) > 0, and -c has c's roots.)
pub(crate) fn normalise(c: &mut Coeffs, n: usize, emax: i32, sign: f64) -> i32 {
    let big_e = emax + 1;
    if (-1021..=1022).contains(&big_e) {
        let f = sign * pow2(-big_e);
        for v in c.iter_mut().take(n + 1) {
            *v *= f;
        }
    } else {
        for v in c.iter_mut().take(n + 1) {
            *v = ldexp(sign * *v, -i64::from(big_e));
        }
    }
    big_e
}

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

#[inline]
fn scale_exponent(x: f64, m: usize) -> i32 {
    if x.abs() <= if m <= 8 { SAFE_LOW } else { SAFE_HIGH } {
        0
    } else {
        ilogb(x) + 1
    }
}

/// Whether the CPU has the fma instruction, where the build did not assume it (C
/// `FMA_DISPATCH`): the precise kernels below then run their copies compiled for it
/// (`#[target_feature(enable = "fma")]`), with the same bits -- `mul_add` is correctly rounded
/// as an instruction or as the libm call it is otherwise, and the compensated Horner's error-free
/// product is exact either way (`fma(s, x, -s x)` or Dekker's).  std caches the detection.
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[inline(always)]
fn hw_fma() -> bool {
    std::arch::is_x86_feature_detected!("fma")
}

/// C `horner_core`: p(x) / 2^(k n) by Horner, fused (`mul_add`) or multiply-then-add.
#[inline(always)]
fn horner_core(c: &[f64], n: usize, x: f64, k: i32, fused: bool) -> f64 {
    let c = &c[..=n];
    let mut acc = c[n];
    if k == 0 {
        for &ci in c[..n].iter().rev() {
            acc = if fused { acc.mul_add(x, ci) } else { acc * x + ci };
        }
        return acc;
    }
    let xs = ldexp(x, -i64::from(k));
    let f = ldexp(1.0, -i64::from(k));
    let mut fi = 1.0;
    for i in (0..n).rev() {
        fi *= f;
        acc = if fused { acc.mul_add(xs, c[i] * fi) } else { acc * xs + c[i] * fi };
    }
    acc
}

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[target_feature(enable = "fma")]
#[inline(never)]
fn horner_fma_hw(c: &[f64], n: usize, x: f64, k: i32) -> f64 {
    horner_core(c, n, x, k, true)
}

/// C `horner`.
fn horner(c: &[f64], n: usize, x: f64, k: i32, precise: bool) -> f64 {
    count::madds(n);
    if !precise {
        return horner_core(c, n, x, k, false);
    }
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if hw_fma() {
        // SAFETY: the CPU has the fma instruction (detected above)
        return unsafe { horner_fma_hw(c, n, x, k) };
    }
    horner_core(c, n, x, k, true)
}

fn horner_abs(c: &[f64], n: usize, x: f64, k: i32) -> f64 {
    count::madds(n);
    let ax = x.abs();
    let mut acc = c[n].abs();
    if k == 0 {
        // (as C: the common case without the scaling's products)
        for i in (0..n).rev() {
            acc = acc * ax + c[i].abs();
        }
        return acc;
    }
    let xs = ldexp(ax, -i64::from(k));
    let f = ldexp(1.0, -i64::from(k));
    let mut fi = 1.0;
    for i in (0..n).rev() {
        fi *= f;
        acc = acc * xs + c[i].abs() * fi;
    }
    acc
}

/// 2 gamma_{2n}, tabulated as in C (a division per call is not free).
static NOISE: [f64; MAXN + 1] = noise_table();

const fn noise_table() -> [f64; MAXN + 1] {
    let mut t = [0.0; MAXN + 1];
    let mut n = 0;
    while n <= MAXN {
        let k = n as f64;
        t[n] = 2.0 * (2.0 * k * U / (1.0 - 2.0 * k * U));
        n += 1;
    }
    t
}

#[inline]
pub(crate) fn noise_factor(n: usize) -> f64 {
    NOISE[n]
}

fn within_noise(c: &[f64], n: usize, x: f64, skin: f64) -> bool {
    let k = scale_exponent(x, n);
    noise_holds(c, n, x, k, horner(c, n, x, k, true), skin)
}

/// C `noise_holds`: `within_noise` from v = horner(c, n, x, k, true), already computed.
fn noise_holds(c: &[f64], n: usize, x: f64, k: i32, v: f64, skin: f64) -> bool {
    let sk = if k == 0 { skin } else { ldexp(skin, -i64::from(k) * n as i64) };
    v.abs() <= noise_factor(n) * horner_abs(c, n, x, k) + sk
}

fn sign_at(c: &[f64], n: usize, x: f64, precise: bool) -> i32 {
    let v = horner(c, n, x, scale_exponent(x, n), precise);
    i32::from(v > 0.0) - i32::from(v < 0.0)
}

/// C `quad_roots`: ascending real roots and the discriminant, or None when it is negative.
pub(crate) fn quad_roots(a: f64, b: f64, c: f64) -> (Option<[f64; 2]>, f64) {
    let m = a.abs().max(b.abs().max(c.abs()));
    let e = -ilogb(m);
    // as C: the scaling by an exact power of two, which rounds as ldexp does (ldexp, a call,
    // only where that power is not a normal number)
    let (a, b, c) = if (-1022..=1023).contains(&e) {
        let f = pow2(e);
        (a * f, b * f, c * f)
    } else {
        let e = i64::from(e);
        (ldexp(a, e), ldexp(b, e), ldexp(c, e))
    };
    let h = -0.5 * b;
    let (p, q) = (h * h, a * c);
    let dp = h.mul_add(h, -p);
    let dq = a.mul_add(c, -q);
    let d = (p - q) + (dp - dq);
    if d < 0.0 {
        return (None, d);
    }
    let w = h + d.sqrt().copysign(h);
    let (r1, r2) = if w == 0.0 { (0.0, 0.0) } else { (w / a, c / w) };
    (Some([r1.min(r2), r1.max(r2)]), d)
}

fn first_root_quadratic(c: &[f64], lo: f64, tmax: f64, skin: f64) -> Option<(f64, bool)> {
    let (roots, disc) = quad_roots(c[2], c[1], c[0]);
    if let Some(r) = roots {
        for x in r {
            if x > lo && x <= tmax {
                return Some((x, disc == 0.0));
            }
        }
        return None;
    }
    if skin < 0.0 {
        return None;
    }
    let x = -c[1] / (2.0 * c[2]);
    (x > lo && x <= tmax && within_noise(c, 2, x, skin)).then_some((x, true))
}

fn split_point(lo: f64, hi: f64) -> f64 {
    if lo == 0.0 {
        return hi * 9.765_625e-4; // 2^-10
    }
    if hi > 8.0 * lo {
        return lo.sqrt() * hi.sqrt();
    }
    lo + 0.5 * (hi - lo)
}

/// C `dekker_split`: v = hi + lo exactly, each with at most 26 bits.
#[inline(always)]
fn dekker_split(v: f64) -> (f64, f64) {
    const SPLIT: f64 = 134_217_729.0; // 2^27 + 1
    let t = SPLIT * v;
    let hi = t - (t - v);
    (hi, v - hi)
}

/// C `compensated_step`: one step of compensated Horner (s, c) <- (s x + P_i, its error);
/// `hw`: the error-free product by the fma instruction, else Dekker's.
#[inline(always)]
fn compensated_step(s: f64, c: f64, x: f64, xh: f64, xl: f64, pi: f64, hw: bool) -> (f64, f64) {
    let pr = s * x;
    let pe = if hw {
        s.mul_add(x, -pr)
    } else {
        let (sh, sl) = dekker_split(s);
        ((sh * xh - pr) + sh * xl + sl * xh) + sl * xl
    };
    let sn = pr + pi;
    let bb = sn - pr;
    let se = (pr - (sn - bb)) + (pi - bb);
    (sn, c * x + (pe + se))
}

/// C `compensated_core`.
#[inline(always)]
fn compensated_core(p: &[f64], m: usize, x: f64, hw: bool) -> f64 {
    let (xh, xl) = if hw { (0.0, 0.0) } else { dekker_split(x) };
    let (mut s, mut c) = (p[m], 0.0);
    for &pi in p[..m].iter().rev() {
        (s, c) = compensated_step(s, c, x, xh, xl, pi, hw);
    }
    s + c
}

/// C `compensated_slope_core`.
#[inline(always)]
fn compensated_slope_core(p: &[f64], d: &[f64], m: usize, x: f64, hw: bool) -> (f64, f64) {
    let (xh, xl) = if hw { (0.0, 0.0) } else { dekker_split(x) };
    let (mut s, mut c, mut df) = (p[m], 0.0, d[m - 1]);
    for i in (1..m).rev() {
        (s, c) = compensated_step(s, c, x, xh, xl, p[i], hw);
        df = df * x + d[i - 1];
    }
    (s, c) = compensated_step(s, c, x, xh, xl, p[0], hw);
    (s + c, df)
}

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[target_feature(enable = "fma")]
#[inline(never)]
fn compensated_hw(p: &[f64], m: usize, x: f64) -> f64 {
    compensated_core(p, m, x, true)
}

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[target_feature(enable = "fma")]
#[inline(never)]
fn compensated_slope_hw(p: &[f64], d: &[f64], m: usize, x: f64) -> (f64, f64) {
    compensated_slope_core(p, d, m, x, true)
}

/// Whether the build itself has the fma instruction (C `FMA_BUILT_IN`).
const FMA_BUILT_IN: bool = cfg!(target_feature = "fma");

/// C `horner_compensated`.
fn horner_compensated(p: &[f64], m: usize, x: f64) -> f64 {
    count::madds(10 * m);
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if hw_fma() {
        // SAFETY: the CPU has the fma instruction (detected above)
        return unsafe { compensated_hw(p, m, x) };
    }
    compensated_core(p, m, x, FMA_BUILT_IN)
}

/// 2^-50 and 2^60 (never_late).
const TWO_M50: f64 = 1.0 / 1_125_899_906_842_624.0;
const TWO_60: f64 = 1_152_921_504_606_846_976.0;

/// C `band_side`: which side of the rounding band x is on, for p = c_0..c_n plus the terms
/// reduce dropped, tail[j] x^(n+1+j) (scaled as c): p's own by compensated Horner (its error
/// within u |v| + gamma_{2n}^2 sum |c_i| x^i), the tail's by plain Horner (within 2 gamma_{2(n+m)}
/// of its sum of |terms|), taken twice: 1 where p(x) > 0 certainly, -1 where p(x) < 0
/// certainly, 0 within.
fn band_side(c: &[f64], n: usize, tail: &[f64], x: f64) -> i32 {
    let g = 0.5 * noise_factor(n); // gamma_{2n}
    let mut v = horner_compensated(c, n, x);
    let a = horner_abs(c, n, x, 0);
    let mut et = 0.0;
    let m = tail.len();
    if m > 0 {
        let mut xp = x;
        for _ in 0..n {
            xp *= x; // x^(n+1)
        }
        let (mut tv, mut ta) = (tail[m - 1], tail[m - 1].abs());
        for j in (0..m - 1).rev() {
            tv = tv * x + tail[j];
            ta = ta * x + tail[j].abs();
        }
        v += tv * xp;
        et = noise_factor(n + m) * (ta * xp);
    }
    let eb = 2.0 * (U * v.abs() + g * g * a) + et;
    if v > eb {
        1
    } else if v < -eb {
        -1
    } else {
        0
    }
}

/// C `shift_dd`: the coefficients of p(x + w u) in u (w a power of two), by Horner's Taylor
/// shift in double-double (each product split by fma, each sum by two_sum), rounded once at
/// the end.
fn shift_dd(c: &[f64], n: usize, x: f64, w: f64) -> Coeffs {
    let mut hi: Coeffs = [0.0; MAXN + 1];
    let mut lo: Coeffs = [0.0; MAXN + 1];
    hi[..=n].copy_from_slice(&c[..=n]);
    for k in 0..n {
        for i in (k..n).rev() {
            let ph = hi[i + 1] * x;
            let pl = hi[i + 1].mul_add(x, -ph) + lo[i + 1] * x;
            let sh = hi[i] + ph;
            let bb = sh - hi[i];
            let mut se = (hi[i] - (sh - bb)) + (ph - bb);
            se += lo[i] + pl;
            hi[i] = sh + se;
            lo[i] = se - (hi[i] - sh);
        }
    }
    let mut q: Coeffs = [0.0; MAXN + 1];
    let mut f = 1.0;
    for k in 0..=n {
        q[k] = (hi[k] + lo[k]) * f;
        f *= w;
    }
    q
}

/// C `noise_chains`: Horner's chains for the Taylor certificates, f = p, p', p''/2, p'''/6 at
/// x, and at y >= |x| the sums of |terms| g_k = sum C(i, k) |c_i| y^(i-k), k = 0..4, that
/// bound their rounding and, at |z| <= y, the derivatives |p^(k)(z)| / k!.
#[inline(always)]
fn noise_chains(c: &[f64], n: usize, x: f64, y: f64) -> ([f64; 4], [f64; 5]) {
    let (mut f1, mut f2, mut f3) = (0.0, 0.0, 0.0);
    let mut f0 = c[n];
    let (mut g0, mut g1, mut g2, mut g3, mut g4) = (c[n].abs(), 0.0, 0.0, 0.0, 0.0);
    for &ci in c[..n].iter().rev() {
        f3 = f3 * x + f2;
        f2 = f2 * x + f1;
        f1 = f1 * x + f0;
        f0 = f0 * x + ci;
        g4 = g4 * y + g3;
        g3 = g3 * y + g2;
        g2 = g2 * y + g1;
        g1 = g1 * y + g0;
        g0 = g0 * y + ci.abs();
    }
    ([f0, f1, f2, f3], [g0, g1, g2, g3, g4])
}

/// C `half_curvature_floor`: a lower bound of p''/2 over [x - h, x + h] within [-y, y], by
/// Taylor from the chains at x (`noise_chains`).
#[inline(always)]
fn half_curvature_floor(f: &[f64; 4], g: &[f64; 5], e: f64, rel: f64, h: f64) -> f64 {
    f[2] * (1.0 - rel) - (e * g[2] + 3.0 * (f[3].abs() + e * g[3]) * h + 6.0 * g[4] * h * h) * (1.0 + rel)
}

/// C `positive_through_the_noise`: p certainly positive on [r - h, r] and above the fma noise
/// at r - h (Taylor's bound from Horner's chains at r; the C source has it).
fn positive_through_the_noise(c: &[f64], n: usize, r: f64) -> bool {
    let (f, gs) = noise_chains(c, n, r, r);
    let ([_, f1, f2, _], [g0, g1, ..]) = (f, gs);
    let e = noise_factor(n);
    let rel = 4.0 * (n + 1) as f64 * U;
    let g = 0.5 * e;
    let v = horner_compensated(c, n, r);
    let m = v - 2.0 * (U * v.abs() + g * g * g0); // p(r) >= m
    let s = (f1.abs() + e * g1) * (1.0 + rel); // >= |p'(r)|
    let noise = e * g0 * (1.0 + rel); // >= the fma noise anywhere in [0, r]
    if !(m > 0.0 && f2 > 0.0) {
        return false;
    }
    let h = (s + (s * s + 4.0 * f2 * noise).sqrt()) / f2;
    let l = half_curvature_floor(&f, &gs, e, rel, h);
    h < r && l > 0.0 && s * s < 4.0 * l * m * (1.0 - rel) && (m - s * h + l * h * h) * (1.0 - rel) > noise
}

/// C `falls_through_the_noise`: p' certainly negative on [r - h, r] and p above the fma noise
/// at r - h, so no crossing pair hides in the noise left of the crossing r (Taylor's bounds
/// from Horner's chains at r, signed; the C source has it).
fn falls_through_the_noise(c: &[f64], n: usize, r: f64) -> bool {
    let (f, gs) = noise_chains(c, n, r, r);
    let ([f0, f1, f2, _], [g0, g1, ..]) = (f, gs);
    let e = noise_factor(n);
    let rel = 4.0 * (n + 1) as f64 * U;
    let noise = e * g0 * (1.0 + rel); // >= the fma noise anywhere in [0, r]
    let m = f0 - noise; // p(r) >= m (the chain's own noise)
    let d = -(f1 + e * g1) * (1.0 - rel); // <= -p'(r)
    if !(d > 0.0 && noise > m) {
        return false;
    }
    let k = if f2 > 0.0 { f2 } else { 0.0 };
    let h = 4.0 * (noise - m) / (d + (d * d + 4.0 * k * (noise - m)).sqrt());
    let l = half_curvature_floor(&f, &gs, e, rel, h);
    let low = if l < 0.0 { l } else { 0.0 };
    h < r && d + 2.0 * low * h * (1.0 + rel) > 0.0 && (m + d * h + l * h * h) * (1.0 - rel) > noise
}

/// C `inside_the_noise`: a touch r where p is certainly positive (compensated), found only
/// because its fma value was within the noise there (`touch`), or a crossing r that the
/// derivative method's scan found by fma signs: p solved again from where the noise begins to
/// its left, x_b, after a shift to x_b in double-double, over (x_b, r); its first root if it
/// has one, else the answer as it was -- unless Taylor's bounds at r show that nothing hides
/// there (the C source says why).
#[inline(never)]
fn inside_the_noise(c: &[f64], n: usize, touch: bool, hit: (f64, bool)) -> (f64, bool) {
    let r = hit.0;
    if scale_exponent(r, n) != 0
        || if touch { positive_through_the_noise(c, n, r) } else { falls_through_the_noise(c, n, r) }
    {
        return hit;
    }
    let mut step = r * TWO_M50;
    let xb = loop {
        step *= 2.0;
        let xb = r - step;
        if !(xb > 0.0) || step > r * 0.0625 {
            return hit;
        }
        if !within_noise(c, n, xb, 0.0) {
            break xb;
        }
    };
    if sign_at(c, n, xb, true) <= 0 {
        return hit; // (not a near miss: left to never_late's steps)
    }
    let w = r - xb;
    let e = ilogb(w) + 1;
    let mut q = shift_dd(c, n, xb, ldexp(1.0, i64::from(e)));
    let mut eq = [0i32; MAXN + 1];
    let mut nz = [false; MAXN + 1];
    let (spread, emax) = exponents(&q, n, &mut eq, &mut nz);
    if !(q[0] > 0.0) || spread > MAX_SPREAD {
        return hit;
    }
    normalise(&mut q, n, emax, 1.0);
    match first_root_interval(&q, n, ldexp(w, -i64::from(e)), 0.0, 0.0) {
        Some((u, gu, _)) => {
            let t = xb + ldexp(u, i64::from(e));
            if !(t < r) {
                return hit;
            }
            // q's doubles are p shifted and rounded once: near a cluster that moves q's roots
            // by far more than p's own band, so t is held to p's compensated band as
            // never_late holds a root (no second look inside the noise).
            let d = t * TWO_M50;
            let hs = band_side(c, n, &[], if gu { t } else { t - d });
            if if gu { hs == -1 } else { hs != 1 } {
                band_walk(c, n, &[], t, d, hs, gu)
            } else {
                (t, gu)
            }
        }
        None => hit,
    }
}

/// C `never_late` (issue 33, item 11): never later than the first root of the polynomial as
/// given (c and the dropped terms, tail).  A root stands where p is certainly positive just
/// before it, at r (1 - 2^-50), a touch unless p is certainly negative at it; else the earliest
/// point that cannot be excluded (steps to the left, doubling, then bisection), a crossing
/// where p is certainly negative there, else a touch.
pub(crate) fn never_late(c: &[f64], n: usize, tail: &[f64], hit: (f64, bool)) -> (f64, bool) {
    let (r, g) = hit;
    if !(r > 0.0 && r <= TWO_60) {
        return hit;
    }
    let d = r * TWO_M50; // (exact, as ldexp)
    if !(d > 0.0) {
        return hit; // (r below 2^-1024: the steps would not move)
    }
    let hs = band_side(c, n, tail, if g { r } else { r - d });
    if g && hs == 1 && n >= 3 && tail.is_empty() {
        return inside_the_noise(c, n, true, hit);
    }
    if if g { hs != -1 } else { hs == 1 } {
        return hit;
    }
    band_walk(c, n, tail, r, d, hs, g)
}

/// C `band_walk`: never_late's steps from a root r that does not stand (d = r 2^-50, hs p's
/// band side at r - d for a crossing, at r for a touch).
#[inline(never)]
fn band_walk(c: &[f64], n: usize, tail: &[f64], r: f64, d: f64, hs: i32, g: bool) -> (f64, bool) {
    let mut hs = hs;
    let (mut hi, mut lo, mut step) = (if g { r } else { r - d }, 0.0, 2.0 * d);
    loop {
        let x = r - step;
        if !(x > 0.0) {
            break; // lo = 0: p(0) > 0
        }
        let s = band_side(c, n, tail, x);
        if s == 1 {
            lo = x;
            break;
        }
        hi = x;
        hs = s;
        step *= 2.0;
    }
    while hi - lo > d {
        // (to d: what a root that stands may be late by)
        let mid = lo + 0.5 * (hi - lo);
        if !(mid > lo && mid < hi) {
            break;
        }
        let s = band_side(c, n, tail, mid);
        if s == 1 {
            lo = mid;
        } else {
            hi = mid;
            hs = s;
        }
    }
    (hi, hs != -1)
}

/// C `late_scanned`: `never_late` for a root the derivative method found, no terms dropped; a
/// crossing there is then looked for again inside the fma noise to its left
/// (`inside_the_noise`), from where it stands or where never_late's steps left it -- where
/// those steps can run (r 2^-50 > 0, r <= 2^60).
#[inline(never)]
pub(crate) fn late_scanned(c: &[f64], n: usize, hit: (f64, bool)) -> (f64, bool) {
    let crossing = !hit.1 && n >= 3;
    let out = never_late(c, n, &[], hit);
    let r = out.0;
    if crossing && r <= TWO_60 && r * TWO_M50 > 0.0 {
        inside_the_noise(c, n, false, out)
    } else {
        out
    }
}

/// C `dropped_terms`: the leading terms reduce dropped from coef (n kept after the factors of t
/// it divided out), up to the last nonzero; empty where it dropped none.
pub(crate) fn dropped_terms(coef: &[f64], n: usize) -> &[f64] {
    let low = coef.iter().position(|&v| v != 0.0).unwrap_or(0);
    let top = coef.iter().rposition(|&v| v != 0.0).unwrap_or(0).max(low + n);
    &coef[low + n + 1..=top]
}

/// C `compensated_with_slope`: (`horner_compensated(p, m, x)`, d(x) by plain Horner in the same
/// loop; d of degree m - 1, m >= 1).
fn compensated_with_slope(p: &[f64], d: &[f64], m: usize, x: f64) -> (f64, f64) {
    count::madds(10 * m);
    compensated_slope_ahead(p, d, m, x)
}

/// C `compensated_slope_ahead`: the same, uncounted (an evaluation done ahead of its use,
/// counted there).  Inlined (C's flattened degree copies inline it too).
#[inline(always)]
fn compensated_slope_ahead(p: &[f64], d: &[f64], m: usize, x: f64) -> (f64, f64) {
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if hw_fma() {
        // SAFETY: the CPU has the fma instruction (detected above)
        return unsafe { compensated_slope_hw(p, d, m, x) };
    }
    compensated_slope_core(p, d, m, x, FMA_BUILT_IN)
}

/// C `TouchValues`: what `scan_pieces` and `touch_point` read on a touch's interval, computed in
/// one pass (`touch_values`): p(b) by fma Horner, compensated, sum |p_i| b^i, p(hi) by fma
/// Horner, p'(b) compensated and p''(b) plain -- the same values, bit for bit.
#[derive(Clone, Copy)]
struct TouchValues {
    vb: f64,
    pb: f64,
    ab: f64,
    vhi: f64,
    dv: f64,
    ddv: f64,
}

/// C `touch_values_core`: the five evaluations' chains side by side, each in its kernel's order.
#[inline(always)]
fn touch_values_core(c: &[f64], d1: &[f64], d2: &[f64], n: usize, b: f64, hi: f64, hw: bool) -> TouchValues {
    let (bh, bl) = if hw { (0.0, 0.0) } else { dekker_split(b) };
    let m = n - 1; // p' = d1, of degree m; p'' = d2
    let (mut vb, mut vhi, mut ab, axb) = (c[n], c[n], c[n].abs(), b.abs());
    let (mut s, mut e, mut s1, mut e1, mut df) = (c[n], 0.0, d1[m], 0.0, d2[m - 1]);
    for i in (0..n).rev() {
        vb = vb.mul_add(b, c[i]);
        vhi = vhi.mul_add(hi, c[i]);
        ab = ab * axb + c[i].abs();
        (s, e) = compensated_step(s, e, b, bh, bl, c[i], hw);
        if i < m {
            (s1, e1) = compensated_step(s1, e1, b, bh, bl, d1[i], hw);
            if i >= 1 {
                df = df * b + d2[i - 1];
            }
        }
    }
    TouchValues { vb, pb: s + e, ab, vhi, dv: s1 + e1, ddv: df }
}

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[target_feature(enable = "fma")]
#[inline(never)]
fn touch_values_hw(c: &[f64], d1: &[f64], d2: &[f64], n: usize, b: f64, hi: f64) -> TouchValues {
    touch_values_core(c, d1, d2, n, b, hi, true)
}

/// C `touch_values` (for b, hi that need no scaling).
fn touch_values(c: &[f64], d1: &[f64], d2: &[f64], n: usize, b: f64, hi: f64) -> TouchValues {
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if hw_fma() {
        // SAFETY: the CPU has the fma instruction (detected above)
        return unsafe { touch_values_hw(c, d1, d2, n, b, hi) };
    }
    touch_values_core(c, d1, d2, n, b, hi, FMA_BUILT_IN)
}

#[inline(always)]
fn value_and_slope(p: &[f64], d: &[f64], m: usize, x: f64, k: i32, precise: bool) -> (f64, f64, f64) {
    if k != 0 {
        let slope = horner(d, m - 1, x, k, false);
        let size = horner_abs(p, m, x, k);
        return (horner(p, m, x, k, precise), slope, size);
    }
    count::madds(3 * m - 1); // (the cost model's count, either way)
    if precise {
        // (C: the slope in the compensated loop; the size is not looked at)
        let (f, df) = compensated_with_slope(p, d, m, x);
        return (f, df, 0.0);
    }
    let (p, d) = (&p[..=m], &d[..m]);
    let mut f = p[m];
    let mut df = d[m - 1];
    let ax = x.abs();
    let mut sz = p[m].abs();
    f = f * x + p[m - 1];
    sz = sz * ax + p[m - 1].abs();
    for (&pi, &di) in p[..m - 1].iter().zip(&d[..m - 1]).rev() {
        df = df * x + di;
        sz = sz * ax + pi.abs();
        f = f * x + pi;
    }
    (f, df, sz)
}

/// C `PRECISE_NOW`: `refine_root`'s tol for an x0 already converged (the guess's Laguerre
/// iterate): full accuracy, precise from the first step.
const PRECISE_NOW: f64 = -1.0;

#[allow(clippy::too_many_arguments)]
#[inline(never)]
fn refine_root(p: &[f64], d: &[f64], m: usize, lo: f64, hi: f64, slo: i32, tol: f64, x0: f64) -> f64 {
    refine_root_from(p, d, m, lo, hi, slo, tol, x0, None)
}

/// C `refine_root_from`: `refine_root`, with (P(x0), P'(x0)) as `value_and_slope` gives them
/// precisely (k = 0) computed ahead by the caller for the first step.
/// Inlined into its two callers: `refine_root` (out of line, for every other) and the
/// degree copies of `first_root_interval` (as C's flattened copies).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn refine_root_from(p: &[f64], d: &[f64], m: usize, mut lo: f64, mut hi: f64, slo: i32, tol: f64, x0: f64,
                    first: Option<(f64, f64)>) -> f64 {
    let mut x = x0;
    let mut step = hi - lo;
    let mut step_old = step;
    let mut precise = tol < 0.0; // PRECISE_NOW: x0 converged, precise from the first step
    let tol = if tol < 0.0 { 0.0 } else { tol };
    let mut stop = if tol > 0.0 {
        tol
    } else if precise {
        2.0 * U
    } else {
        PRECISE_FROM
    };
    for it in 0..MAX_ITER {
        count::event(if precise { 5 } else { 4 });
        let k = scale_exponent(x, m);
        let (f, df, size) = match first {
            Some((f, df)) if it == 0 => {
                count::madds(3 * m - 1 + 10 * m); // (value_and_slope's, precise, k = 0)
                (f, df, 0.0)
            }
            _ => value_and_slope(p, d, m, x, k, precise),
        };
        if tol == 0.0 && !precise && f.abs() <= noise_factor(m) * size {
            precise = true;
            stop = 2.0 * U;
            continue;
        }
        if f == 0.0 {
            return x;
        }
        if (f > 0.0) == (slo > 0) {
            lo = x;
        } else {
            hi = x;
        }
        if hi - lo <= 2.0 * f64::EPSILON * hi || (tol > 0.0 && hi - lo <= tol * hi) {
            if precise || tol > 0.0 {
                return x;
            }
            precise = true;
            stop = 2.0 * U;
            continue;
        }
        if tol == 0.0 && hi - lo <= PRECISE_FROM * hi {
            precise = true;
            stop = 2.0 * U;
        }
        let mut xn = x - if k != 0 { ldexp(f / df, i64::from(k)) } else { f / df };
        let mut s = x - xn;
        // see SLOW_AFTER
        let slow = it >= SLOW_AFTER && (lo == 0.0 || hi > 8.0 * lo) && s.abs() > 9.765_625e-4 * xn.abs(); // 2^-10
        if !(xn > lo && xn < hi) || s.abs() > 0.5 * step_old.abs() || slow {
            // (with tol > 0 too: a step in the noise that a noisy sign pushed out of the
            // bracket; bisecting from there crept to tol, see C refine_root)
            if (precise || tol > 0.0) && s.abs() <= NOISE_STEP * x.abs() {
                return x;
            }
            let far = hi * f64::from_bits(0x3bf0_0000_0000_0000); // 2^-64
            xn = if slow && lo == 0.0 && far > f64::MIN_POSITIVE { far } else { split_point(lo, hi) };
            s = x - xn;
        }
        step_old = step;
        step = s;
        if s.abs() <= stop * xn.abs() || (precise && s.abs() <= NOISE_STEP * x.abs()) {
            if precise || tol > 0.0 {
                return xn;
            }
            precise = true;
            stop = 2.0 * U;
        }
        x = xn;
    }
    x
}

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
struct Taylor {
    tk: Table,
    ta: Table,
    e: f64,
    skin: f64,
}

type Table = [[MaybeUninit<f64>; MAXN + 1]; MAXN + 1];

#[cfg(test)]
fn binom(k: usize, j: usize) -> f64 {
    // C(j + k, k), exact in doubles for j + k <= 16
    let mut r = 1.0f64;
    for i in 1..=k {
        r = r * (j + i) as f64 / i as f64;
    }
    r
}

/// Fills `slot` in place and returns it (returning the 4.6 kB table by value would copy it,
/// and building it as a struct literal makes the compiler zero it, on every solve).
fn taylor_table<'a>(p: &[f64], n: usize, e: f64, skin: f64, slot: &'a mut MaybeUninit<Taylor>) -> &'a Taylor {
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
struct Point {
    x: f64,
    px: f64,
    dpx: f64,
    vp: i32,
    vq: i32,
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
    fn qt(&self, k: usize) -> f64 {
        // SAFETY: every Point in use had entries 0..=n written, and k <= n here.
        unsafe { self.qt[k].assume_init() }
    }

    #[inline]
    fn tol(&self, k: usize) -> f64 {
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
    fn assign(&mut self, b: &Point, n: usize) {
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
fn point_at_zero<'a>(p: &[f64], n: usize, e: f64, skin: f64, slot: &'a mut MaybeUninit<Point>) -> &'a mut Point {
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
fn taylor_shift_8(tb: &Taylor, x: f64, a: &mut [f64; MAXN + 1], s: &mut [f64; MAXN + 1]) {
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
fn taylor_shift(tb: &Taylor, n: usize, x: f64, a: &mut [f64; MAXN + 1], s: &mut [f64; MAXN + 1]) {
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
fn point_at(tb: &Taylor, n: usize, x: f64, slot: &mut MaybeUninit<Point>) -> bool {
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
fn bounds_positive(qt: &[f64], tol: &[f64], n: usize, w: f64, dir: i32) -> bool {
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
fn clearly_positive(pt: &Point, n: usize, w: f64, dir: i32) -> bool {
    bounds_positive(pt.qts(n), pt.tols(n), n, w, dir)
}

/// 1 / C(n, k) (C's INV_BINOM): each the correctly rounded quotient of exact integers, as C's
/// constant expressions `1.0 / 6` are.
static INV_BINOM: [[f64; MAXN + 1]; MAXN + 1] = reciprocals(pascal_table());

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
enum Bernstein {
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
struct Start {
    q: [f64; MAXN + 1],
    err: f64,
    even: bool,
}

/// b_j = sum_{k <= j} C(j, k) a_k, j = 0..=n, in place (C `binomial_sums`): n rounds of
/// running sums, round r adding to each entry j >= r its left neighbour, j descending.  Up to
/// degree 8 over 9 entries with constant bounds (fully unrolled, in registers: the entries
/// above n, zeros, never reach those below), as C writes it out.
#[inline(always)]
fn binomial_sums(a: &mut [f64; MAXN + 1], n: usize) {
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
fn bernstein_test(pt: &Point, n: usize, w: f64, start: Option<&mut Start>) -> Bernstein {
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
fn halves<const W: usize>(inp: &[f64; W], n: usize) -> ([f64; W], [f64; W]) {
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
const DIP_INSIDE: f64 = 0.0625;

/// C `bernstein_clear`: is q > 0 on the interval whose Bernstein coefficients are q[0..=n]
/// (certain signs beyond `err`, an even count)?  Depth-first bisection in the Bernstein basis
/// (left half first); a piece is cleared when its coefficients are all certainly positive, and
/// the answer is no at the first piece with an uncertain sign or differing end signs, or
/// beyond CLEAR_DEPTH halvings.  A child's error bound is its parent's plus 2 n u M + DBL_MIN
/// (see the C source); the first split is at t0 instead (the dip) when that is DIP_INSIDE or
/// more from either end, its error 8 n u M.  Out of line, as in C: a rare path.  Up to degree 8 on arrays of 9
/// (constant sizes: no memcpy or memset calls, and half the stack to zero).
#[inline(never)]
fn bernstein_clear(q: &[f64; MAXN + 1], err0: f64, n: usize, t0: f64) -> bool {
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

/// Laguerre steps `speculate_first_root` takes at most (but for a touch's, below).
const SPECULATE_STEPS: usize = 8;
/// The certificate's interval reaches this far beyond the speculated root, relative (2^-20).
const SPECULATE_MARGIN: f64 = 9.536_743_164_062_5e-7;
/// Laguerre steps beyond SPECULATE_STEPS while the ratios of a touch last.
const TOUCH_EXTRA: usize = 4;
/// Newton steps on p' towards a touch's critical point, at most.
const TOUCH_STEPS: usize = 6;
/// The step ratios of Laguerre converging linearly to a double root (0.25 at degree 3, 0.284
/// at 8, 0.289 at 16) lie in [TOUCH_RATIO_LO, TOUCH_RATIO_HI].
const TOUCH_RATIO_LO: f64 = 0.25;
const TOUCH_RATIO_HI: f64 = 0.31;
/// Ratios in a row in that range that make the guess turn to the critical point.
const TOUCH_STEADY: usize = 3;
/// Newton steps that may take Laguerre's place where its square root's argument is negative.
const GUESS_NEWTON: usize = 2;
/// A critical point is a touch where |p| is within this times the rounding bound (2^20).
const TOUCH_NEAR: f64 = 1_048_576.0;
/// Half-width (relative) of the interval around a touch that goes to the derivative method
/// (2^-10; `isolate_first_root`).
const TOUCH_WIDTH: f64 = 9.765_625e-4;

/// What `speculate_first_root` found (C: its return value, `*r`, `*touch` and `*over`; C's
/// `*dip`, where p dips towards complex roots near the axis, is its out-parameter `dip`: set
/// where it saw one, whatever it returns).
enum Guess {
    /// Laguerre converged here: maybe the first root (the caller certifies it).
    Root(f64),
    /// A step went past a root: p < 0 at `over`, a root in (0, over), Newton's start inside
    /// the step first (C's OVERSHOT; the caller certifies it up to `over`).
    Overshot { start: f64, over: f64 },
    /// The critical point of a touch ahead (p there within TOUCH_NEAR rounding bounds).
    Touch(f64),
    Nothing,
}

/// C `speculate_first_root`: a guess at the first root by Laguerre's method from 0, each step
/// taken to the right (of its two square-root signs, the one that moves x up).  Why Laguerre
/// and not Newton from where p's control polygon crosses 0: Newton from far away creeps (a
/// step is about x / n while p ~ x^n, and the window is many times the first root), while
/// Laguerre, for a polynomial whose roots are all real, converges monotonically to the first
/// root after its start, cubically near it, from any start -- and from 0 that is the first
/// positive root.  Nothing where the square root's argument is negative (complex roots in the
/// way), when no step to the right exists, when x leaves (0, T), when a step from the fifth on
/// has neither halved nor shrunk by more than the step before (far from every root Laguerre
/// creeps, then speeds up: it gives up only while it is not slowing down), or after
/// SPECULATE_STEPS; stops once a step is below PRECISE_FROM, or below GUESS_DONE at most
/// GUESS_FAST of the step before.  Nothing is certain about the
/// result: the caller certifies a root by a Bernstein test.
///
/// A touch ahead (a double root, or two real roots or a complex pair within the rounding noise
/// of one) shows as linear convergence: each step 1 - n / (2 + sqrt((n - 1)(2n - 4))) times
/// the one before.  After TOUCH_STEADY ratios in a row in [TOUCH_RATIO_LO, TOUCH_RATIO_HI] (up
/// to TOUCH_EXTRA steps beyond SPECULATE_STEPS while they last) the guess turns to Newton on
/// p' -- the critical point is a simple root of p', so that converges quadratically where
/// Laguerre would crawl -- and reports a touch where p there is within TOUCH_NEAR times the
/// rounding bound (a complex pair clear of the axis is not: not worth the derivative method).
/// Like the root, it only chooses where to look (`isolate_first_root`).
///
/// A step that lands past a root (complex roots near the first real one, or an iterate one
/// rounding past a root it has converged to) gives `Overshot`: p < 0 at the new x, a root in
/// (0, x), and Newton's start where Newton from x points if inside the step, else its middle.
/// Where the square root's argument is negative and p falls, a Newton step takes Laguerre's
/// place, up to GUESS_NEWTON times: past the complex pair's pull Laguerre's steps often
/// resume, and a step past the root is an overshoot like any other.
///
/// The arithmetic is C's, operation for operation (the results are bit-identical): three
/// Horner chains in C's statement order, `2 * d2 / f` as `(2 d2) / f`, the integer factors
/// converted as C converts them, the exit rules at the same places.
#[inline(always)]
fn speculate_first_root(p: &[f64], n: usize, t_end: f64, dip: &mut f64) -> Guess {
    count::phase(2);
    let p = &p[..=n];
    // C's (n - 1) converted to double, exact (and no usize underflow)
    let (nf, n1f) = (n as f64, n as f64 - 1.0);
    let (mut x, mut last, mut qprev, mut xprev) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut newton = 0; // Newton steps in Laguerre's place
    // critical > 0: Newton on p' (after the double-root signature), its step number
    let (mut critical, mut steady) = (0usize, 0usize);
    for it in 0..SPECULATE_STEPS + TOUCH_EXTRA + TOUCH_STEPS {
        if critical == 0 && it >= SPECULATE_STEPS && (steady == 0 || it >= SPECULATE_STEPS + TOUCH_EXTRA) {
            return Guess::Nothing;
        }
        count::madds(3 * n);
        // p, p' and p''/2 at x (at 0, the first step: the coefficients, the values Horner's
        // chains give there, as in C)
        let (mut f, mut d1, mut d2) = (p[0], p[1], p[2]);
        if it > 0 {
            (f, d1, d2) = (p[n], 0.0f64, 0.0f64);
            for &pi in p[..n].iter().rev() {
                d2 = d2 * x + d1;
                d1 = d1 * x + f;
                f = f * x + pi;
            }
        }
        if critical > 0 {
            // Newton on p' towards the critical point: a simple root of p' where p'' > 0 (a
            // minimum of p > 0)
            if !(d2 > 0.0) {
                return Guess::Nothing;
            }
            let s = d1 / (2.0 * d2);
            x -= s;
            if !(x > 0.0 && x < t_end) {
                return Guess::Nothing;
            }
            if s.abs() <= PRECISE_FROM * x {
                let near = f.abs() <= TOUCH_NEAR * noise_factor(n) * horner_abs(p, n, x, 0);
                // (not near: a dip clear of the axis, complex roots)
                if near {
                    return Guess::Touch(x);
                }
                *dip = x;
                return Guess::Nothing;
            }
            if critical > 1 && !(s.abs() <= 0.5 * last.abs()) {
                return Guess::Nothing;
            }
            critical += 1;
            last = s;
            continue;
        }
        if f == 0.0 {
            return if x > 0.0 { Guess::Root(x) } else { Guess::Nothing };
        }
        if f < 0.0 {
            // past a root: one in (xprev, x)
            let y = x - f / d1;
            let start = if y > xprev && y < x { y } else { xprev + 0.5 * (x - xprev) };
            return Guess::Overshot { start, over: x };
        }
        // (n - 1) f^2 times Laguerre's discriminant: its sign, and the step from one division
        let u = n1f * (d1 * d1) - 2.0 * nf * (f * d2);
        let s = if !(u >= 0.0) {
            // complex roots in the way: one Newton step on p' towards the dip, and in
            // Laguerre's place, up to GUESS_NEWTON times while p falls, a Newton step
            if d2 > 0.0 {
                *dip = x - d1 / (2.0 * d2);
            }
            if newton == GUESS_NEWTON || !(d1 < 0.0) {
                return Guess::Nothing;
            }
            newton += 1;
            f / d1
        } else {
            // the step to the right (negative), or none
            nf * f / (d1 - (n1f * u).sqrt().copysign(f))
        };
        if !(s < 0.0) {
            return Guess::Nothing;
        }
        xprev = x;
        x -= s;
        if !(x > 0.0 && x < t_end) {
            return Guess::Nothing;
        }
        let q = if it > 0 { s / last } else { 0.0 };
        if s.abs() <= PRECISE_FROM * x || (s.abs() <= GUESS_DONE * x && q <= GUESS_FAST) {
            return Guess::Root(x);
        }
        steady = if (TOUCH_RATIO_LO..=TOUCH_RATIO_HI).contains(&q) { steady + 1 } else { 0 };
        if steady >= TOUCH_STEADY {
            critical = 1; // linear convergence: a double root ahead
            last = s;
            continue;
        }
        if it >= 4 && !(s.abs() <= 0.5 * last.abs()) && !(q < qprev) {
            return Guess::Nothing;
        }
        qprev = q;
        last = s;
    }
    Guess::Nothing
}

fn isolation_split(a: f64, b: f64) -> f64 {
    if a == 0.0 {
        return b * 0.0625;
    }
    if b > 8.0 * a {
        return a.sqrt() * b.sqrt();
    }
    a + 0.5 * (b - a)
}

/// C `derivative`: the coefficients of p' (p of degree n) in dp[0..n].
#[inline(always)]
fn derivative(p: &[f64], n: usize) -> [f64; MAXN] {
    let mut dp = [0.0f64; MAXN];
    for i in 0..n {
        dp[i] = (i + 1) as f64 * p[i + 1];
    }
    dp
}

/// C `polish_isolated`: the one simple root of p in (a, b), p(a) = pa > 0 > pb = p(b), by
/// safeguarded Newton from the regula falsi point.
fn polish_isolated(p: &[f64], n: usize, a: f64, b: f64, pa: f64, pb: f64) -> f64 {
    let dp = derivative(p, n);
    let mut x0 = a + (b - a) * (pa / (pa - pb));
    if !(x0 > a && x0 < b) {
        x0 = split_point(a, b);
    }
    count::phase(2);
    refine_root(p, &dp, n, a, b, 1, 0.0, x0)
}

enum Isolation {
    Isolated(f64, bool),
    /// isolated by the derivative method (C SCANNED: never_late looks again)
    Scanned(f64, bool),
    Cleared,
    Unresolved(f64),
}

/// C `isolate_first_root`: the first event in (0, T] for p (T <= FAST_LIMIT, p(0) > 0) by
/// Budan-Fourier bisection.  `failed_w`: the window on which `cleared_at_once` has already
/// run the first exclusion test at 0 and failed (0: none), so that it is not run again.
#[inline(always)]
fn isolate_first_root(p: &[f64], n: usize, skin: f64, t_end: f64, failed_w: f64) -> Isolation {
    count::phase(1);
    let e = if skin >= 0.0 { noise_factor(n) } else { 0.0 };
    let sk = if skin > 0.0 { skin } else { 0.0 };
    let mut a_slot = MaybeUninit::<Point>::uninit();
    let a = point_at_zero(p, n, e, sk, &mut a_slot);
    if !(a.qt(0) - a.tol(0) > 0.0) {
        return Isolation::Unresolved(0.0);
    }
    // Descartes, or q(0) beats every negative term (unless that very test has failed already:
    // cleared_at_once)
    if a.vq == 0 || (t_end != failed_w && clearly_positive(a, n, t_end, 1)) {
        return Isolation::Cleared;
    }
    // A guess first, then a certificate: the guess (Laguerre from 0) and one Bernstein test on
    // (0, r (1 + 2^-20)] settle most solves with a root, which the test on the whole window
    // before them only delayed (measured: see the C source).
    let (mut touch, mut dip) = (0.0, 0.0);
    // a root to certify: (the certificate's end, Newton's start, refine_root's tol) -- after a
    // step past the root, the step's end and plain evaluation first
    let certify = match speculate_first_root(p, n, t_end, &mut dip) {
        Guess::Root(r) => Some((r, r, PRECISE_NOW)),
        Guess::Overshot { start, over } => Some((over, start, 0.0)),
        Guess::Touch(x) => {
            touch = x;
            None
        }
        Guess::Nothing => None,
    };
    if let Some((end, start, tol)) = certify {
        let w = end + end * SPECULATE_MARGIN;
        let w = if w < t_end { w } else { t_end };
        // the polish's first step ahead of the certificate, its chain beside the Bernstein
        // sums (see the C source); counted where the polish uses it
        let dp = derivative(p, n);
        let first = if tol < 0.0 && scale_exponent(start, n) == 0 {
            Some(compensated_slope_ahead(p, &dp, n, start))
        } else {
            None
        };
        count::phase(1);
        if let Bernstein::One(_) = bernstein_test(a, n, w, None) {
            count::phase(2);
            return Isolation::Isolated(refine_root_from(p, &dp, n, 0.0, w, 1, tol, start, first), false);
        }
    }
    count::phase(1);
    let mut from = 0.0; // > 0: (0, from] is settled, the counts go on from it
    // A touch ahead: (0, lo] certified clear by the Bernstein test (q's coefficients all
    // positive), then the derivative method settles (lo, hi] -- small, so with few roots of
    // the derivatives in it -- and the counts go on from hi if it finds nothing there.  This
    // replaces, on the grazes, the Taylor points that bisect down to the touch and the
    // derivative method on the wide interval they leave.  hi is 3 widths to the right: from
    // the middle of a symmetric interval (the critical point to within rounding) the fma
    // noise of p' there sent the derivative method's Newton into bisection, to a neighbour of
    // an exact double root (see the C source).  Not for the no-graze baseline (skin < 0),
    // whose answers stay as they were.  Before the test on the whole window, which a touch
    // ahead leaves undecided (q dips to 0 there; see the C source).
    if touch > 0.0 && skin >= 0.0 {
        let lo = touch - touch * TOUCH_WIDTH;
        let hi = touch + 3.0 * touch * TOUCH_WIDTH;
        let hi = if hi < t_end { hi } else { t_end };
        if let Bernstein::Clear = bernstein_test(a, n, lo, None) {
            // p convex around the touch, its critical point certified in one pass
            // (touch_critical), else the derivative method (see the C source)
            count::phase(3);
            let d = derivative_rows(p, n, n - 2);
            let critical = touch_critical(p, &d, n, lo, hi, touch);
            let convex = critical.is_some();
            let hit = match critical {
                Some(b) => {
                    // (b < hi: no scaling at b when none at hi, touch_critical's)
                    let tv = touch_values(p, d.row(n - 1), d.row(n - 2), n, b, hi);
                    scan_pieces(p, &d, n, lo, hi, &[b], skin, Some(&tv))
                }
                None => derivative_method(p, n, lo, hi, touch, skin),
            };
            count::phase(1);
            // (on (lo, hi], convex by touch_critical's certificate, p falls to b alone: no
            // crossing pair can hide there, not scanned)
            if let Some((t, g)) = hit {
                return if convex { Isolation::Isolated(t, g) } else { Isolation::Scanned(t, g) };
            }
            if hi == t_end {
                return Isolation::Cleared;
            }
            from = hi;
        }
    }
    if from == 0.0 {
        // the whole window, unless a touch's interval settled (0, from]
        let mut start = Start { q: [0.0; MAXN + 1], err: 0.0, even: false };
        match bernstein_test(a, n, t_end, Some(&mut start)) {
            Bernstein::Clear => return Isolation::Cleared,
            Bernstein::One(p_end) => {
                return Isolation::Isolated(polish_isolated(p, n, 0.0, t_end, a.px, p_end), false)
            }
            Bernstein::Unknown => {}
        }
        if start.even && bernstein_clear(&start.q, start.err, n, dip / t_end) {
            // (after a guess that failed)
            return Isolation::Cleared;
        }
    }
    let mut slot = MaybeUninit::<Taylor>::uninit();
    let tb = taylor_table(p, n, e, sk, &mut slot);
    // The right ends, as in C an uninitialised array of which stack[..top] is in use (zeroing
    // 41 points would cost more than most solves); point_at writes a slot in place.
    let mut stack: [MaybeUninit<Point>; MAX_SPLITS + 1] = [const { MaybeUninit::uninit() }; MAX_SPLITS + 1];
    let mut top = 0usize;
    let mut splits = 0usize;
    if !point_at(tb, n, t_end, &mut stack[top]) {
        // (C: *a_out = from when from > 0, else the 0 it started with)
        return Isolation::Unresolved(from);
    }
    top += 1;
    // after a touch the counts start at from: a, the point at 0 until now, is the one there
    let a = if from > 0.0 {
        if !point_at(tb, n, from, &mut a_slot) {
            return Isolation::Unresolved(from);
        }
        // SAFETY: point_at_zero wrote every field of a_slot, and point_at has just rewritten
        // them all (it returned true).
        let a = unsafe { a_slot.assume_init_mut() };
        if !(a.qt(0) - a.tol(0) > 0.0) {
            return Isolation::Unresolved(from);
        }
        a
    } else {
        a
    };
    let mut tested = from == 0.0; // (0, T] has had its Bernstein test
    let mut early_tried = false;
    loop {
        // SAFETY: stack[..top] was written by point_at (every field: x, px, vp, vq; the arrays
        // are MaybeUninit, their entries 0..=n written).
        let b = unsafe { stack[top - 1].assume_init_ref() };
        let w = b.x - a.x;
        let odd = (a.vp - b.vp) % 2 != 0;
        if a.vq == b.vq || (!odd && (clearly_positive(a, n, w, 1) || clearly_positive(b, n, w, -1))) {
            a.assign(b, n);
            tested = false;
            top -= 1;
            if top == 0 {
                return Isolation::Cleared;
            }
            continue;
        }
        if a.vp - b.vp == 1 && a.vq - b.vq == 1 {
            return Isolation::Isolated(polish_isolated(p, n, a.x, b.x, a.px, b.px), false);
        }
        // Descartes in the Bernstein basis where the counts fail: only for an odd count (a
        // root certain), and not again for (0, T] (see the C source)
        if odd && !tested && matches!(bernstein_test(a, n, w, None), Bernstein::One(_)) {
            return Isolation::Isolated(polish_isolated(p, n, a.x, b.x, a.px, b.px), false);
        }
        tested = false;
        // Two roots in (a, b] by both counts within a quarter of b (mostly a touch): to the
        // derivative method at once, once per solve; else split, at the tangent rule's point,
        // or just beyond a when the tangent meets 0 within MIN_WIDTH of it (see the C source)
        let bx = b.x;
        let early = !early_tried && a.vp - b.vp == 2 && a.vq - b.vq == 2 && w <= EARLY_WIDTH * bx;
        early_tried |= early;
        if !early {
            let mut m = isolation_split(a.x, bx);
            let mt = a.x + SPLIT_NEWTON * (-a.px / a.dpx);
            let hair = a.x + 4.0 * MIN_WIDTH * bx;
            if splits == 0 && dip > a.x + DIP_INSIDE * w && dip < bx - DIP_INSIDE * w {
                m = dip; // the first split where the failed guess saw p dip (C says why)
            } else if a.dpx < 0.0 && mt > a.x && mt < bx && mt - a.x > MIN_WIDTH * bx {
                m = mt;
            } else if a.dpx < 0.0 && mt > a.x && mt - a.x <= MIN_WIDTH * bx && hair < bx {
                m = hair;
            }
            if splits < MAX_SPLITS && w > MIN_WIDTH * bx && m > a.x && m < bx && point_at(tb, n, m, &mut stack[top]) {
                splits += 1;
                top += 1;
                continue;
            }
        }
        // SAFETY: as above.
        let b = unsafe { stack[top - 1].assume_init_ref() };
        let hit = derivative_method(p, n, a.x, b.x, 0.0, skin);
        count::phase(1);
        if let Some(hit) = hit {
            return Isolation::Scanned(hit.0, hit.1);
        }
        if !(b.qt(0) - b.tol(0) > 0.0) {
            return Isolation::Unresolved(b.x);
        }
        a.assign(b, n);
        top -= 1;
        if top == 0 {
            return Isolation::Cleared;
        }
    }
}

// ---------------------------------------------------------------------------------------
// Derivative method
// ---------------------------------------------------------------------------------------

/// All derivatives of p (degree n; C's `d[MAXN + 1][MAXN + 1]`): row m is the derivative of
/// order n - m, of degree m.  Only entries 0..=m of rows 1..=n are written and only those are
/// read (as in C, where the rest stays uninitialised): zeroing the 2.3 kB table was 14 % of
/// the instructions of a graze's solve, once the touch path made its derivative method small.
struct Chain {
    t: [[MaybeUninit<f64>; MAXN + 1]; MAXN + 1],
    n: usize,
    low: usize,
}

impl Chain {
    /// Row m (low <= m <= n): the coefficients 0..=m of the derivative of degree m.
    #[inline(always)]
    fn row(&self, m: usize) -> &[f64] {
        assert!((self.low..=self.n).contains(&m));
        // SAFETY: derivative_rows wrote entries 0..=m of every row low <= m <= n (asserted);
        // MaybeUninit<f64> has f64's layout.
        unsafe { std::slice::from_raw_parts(self.t[m].as_ptr().cast::<f64>(), m + 1) }
    }
}

/// C `derivative_chain` (and its `derivative` calls, row m into row m - 1, in place).
#[inline(always)]
fn derivative_chain(c: &[f64], n: usize) -> Chain {
    derivative_rows(c, n, 1)
}

/// Rows n down to low (>= 1) of the chain: C's touch path forms only p' and p''.
#[inline(always)]
fn derivative_rows(c: &[f64], n: usize, low: usize) -> Chain {
    let n = n.min(MAXN);
    let low = low.max(1); // (not clamp: it panics for n = 0, which derivative_chain allowed)
    let mut d = Chain { t: [[MaybeUninit::uninit(); MAXN + 1]; MAXN + 1], n, low };
    for (v, &ci) in d.t[n].iter_mut().zip(&c[..=n]) {
        *v = MaybeUninit::new(ci);
    }
    for m in (low + 1..=n).rev() {
        for i in 0..m {
            // SAFETY: entries 0..=m of row m are written (row n above, row m < n by the
            // previous m), and i + 1 <= m.
            let p = unsafe { d.t[m][i + 1].assume_init() };
            d.t[m - 1][i] = MaybeUninit::new((i + 1) as f64 * p);
        }
    }
    d
}

#[allow(clippy::too_many_arguments)]
fn roots_in_pieces(p: &[f64], d: &[f64], m: usize, lo: f64, crit: &[f64], t_end: f64, tol: f64, x0: f64, out: &mut [f64]) -> usize {
    let mut count = 0;
    let mut a = lo;
    let mut sa = sign_at(p, m, lo, false);
    for j in 0..=crit.len() {
        let b = if j < crit.len() { crit[j] } else { t_end };
        let sb = sign_at(p, m, b, false);
        if sb == 0 {
            if j < crit.len() {
                out[count] = b;
                count += 1;
            }
        } else if sa != 0 && sa != sb {
            out[count] = refine_root(p, d, m, a, b, sa, tol, if x0 > a && x0 < b { x0 } else { split_point(a, b) });
            count += 1;
        }
        a = b;
        sa = sb;
    }
    count
}

/// C `convex_on`: is p'' certainly positive on [lo, t_end], beyond the rounding of its plain
/// Horner value anywhere there (see the C source for the bound)?  Then the derivative
/// method's level for the roots of p'' is empty whatever the levels below it find, and the
/// roots of p' come from an empty level: the same steps and bits as the full recursion.
fn convex_on(d: &Chain, n: usize, lo: f64, t_end: f64) -> bool {
    if n < 4 || !(lo >= 0.0) || scale_exponent(t_end, n) != 0 {
        return false;
    }
    let m = lo + 0.5 * (t_end - lo);
    let h = if m - lo > t_end - m { m - lo } else { t_end - m };
    let v = horner(d.row(n - 2), n - 2, m, 0, false);
    let slope = horner_abs(d.row(n - 3), n - 3, t_end, 0);
    let size = horner_abs(d.row(n - 2), n - 2, t_end, 0);
    let rel = 4.0 * (n + 1) as f64 * U;
    v - h * slope * (1.0 + rel) > 2.0 * noise_factor(n) * size * (1.0 + rel)
}

fn critical_points(d: &Chain, n: usize, lo: f64, t_end: f64, x0: f64, crit: &mut [f64; MAXN]) -> usize {
    let mut level = [0.0f64; MAXN];
    let mut nl = 0usize;
    if n < 3 {
        return 0; // (never: degree >= 3 here; as C says so)
    }
    if convex_on(d, n, lo, t_end) {
        // the roots of p' alone (convex_on)
        return roots_in_pieces(d.row(n - 1), d.row(n - 2), n - 1, lo, &[], t_end, TOL_CRITICAL, x0, crit);
    }
    if let (Some(r), _) = quad_roots(d.row(2)[2], d.row(2)[1], d.row(2)[0]) {
        for x in r {
            if x > lo && x < t_end && (nl == 0 || x > level[nl - 1]) {
                level[nl] = x;
                nl += 1;
            }
        }
    }
    for m in 3..n {
        let mut next = [0.0f64; MAXN];
        let tol = if m == n - 1 { TOL_CRITICAL } else { TOL_LEVEL };
        nl = roots_in_pieces(d.row(m), d.row(m - 1), m, lo, &level[..nl], t_end, tol, 0.0, &mut next);
        level[..nl].copy_from_slice(&next[..nl]);
    }
    crit[..nl].copy_from_slice(&level[..nl]);
    nl
}

/// C `crossing_before_critical`: the root of p in (a, b], p monotone from sign sa at a to
/// pb = p(b) (precise, the other sign) at the critical point b; Newton starts where
/// p(b) + p''(b) (x - b)^2 / 2 meets 0 (for a touch within rounding of the root), else at the
/// split point.
fn crossing_before_critical(c: &[f64], d: &Chain, n: usize, a: f64, b: f64, sa: i32, pb: f64) -> f64 {
    let mut x0 = split_point(a, b);
    let h2 = -2.0 * pb / horner(d.row(n - 2), n - 2, b, 0, false);
    let xq = b - (if h2 > 0.0 { h2 } else { 0.0 }).sqrt();
    if xq > a && xq < b {
        x0 = xq;
    }
    refine_root(c, d.row(n - 1), n, a, b, sa, 0.0, x0)
}

/// C `touch_point`: where a touch is reported -- the critical point b, which plain Newton on
/// p' leaves anywhere within p''s rounding noise, moved by one Newton step on p' evaluated
/// precisely (compensated), kept only when that step is within the noise too (b unscaled).
fn touch_point(d: &Chain, n: usize, b: f64, tv: Option<&TouchValues>) -> f64 {
    if scale_exponent(b, n - 1) != 0 {
        return b;
    }
    count::event(5);
    let (v, slope) = match tv {
        Some(tv) => {
            // (touch_values: the same values)
            count::madds(3 * (n - 1) - 1 + 10 * (n - 1));
            (tv.dv, tv.ddv)
        }
        None => {
            let (v, slope, _) = value_and_slope(d.row(n - 1), d.row(n - 2), n - 1, b, 0, true);
            (v, slope)
        }
    };
    let x = b - v / slope;
    if (x - b).abs() <= NOISE_STEP * b.abs() {
        x
    } else {
        b
    }
}

/// C `derivative_method`: the critical points in (lo, t_end), then `scan_pieces`.
fn derivative_method(c: &[f64], n: usize, lo: f64, t_end: f64, x0: f64, skin: f64) -> Option<(f64, bool)> {
    count::phase(3);
    count::event(7);
    let d = derivative_chain(c, n);
    let mut crit = [0.0f64; MAXN];
    let nc = critical_points(&d, n, lo, t_end, x0, &mut crit);
    scan_pieces(c, &d, n, lo, t_end, &crit[..nc], skin, None)
}

/// C `touch_critical`: the critical point of p in (lo, hi) around the guess's touch x,
/// certified in one pass (p convex on [lo, hi], p' < 0 at lo and > 0 at hi, from Horner's
/// chains for p', p''/2, p'''/6 at x and bounds at hi; see the C source), and found as the
/// derivative method finds it (its first Newton step on p' from x, ending there within
/// TOL_CRITICAL); None where the pass cannot tell.
fn touch_critical(p: &[f64], d: &Chain, n: usize, lo: f64, hi: f64, x: f64) -> Option<f64> {
    // (a bracket below TOL_CRITICAL would end refine_root before its step: left to it)
    if !(lo >= 0.0 && lo < x && hi - x > TOL_CRITICAL * hi) || scale_exponent(hi, n) != 0 {
        return None;
    }
    count::madds(9 * n);
    let (f, gs) = noise_chains(p, n, x, hi);
    let (f1, g1) = (f[1], gs[1]);
    let e = noise_factor(n);
    let rel = 4.0 * (n + 1) as f64 * U;
    let h = if x - lo > hi - x { x - lo } else { hi - x };
    let l = half_curvature_floor(&f, &gs, e, rel, h);
    let slope = (f1.abs() + e * g1) * (1.0 + rel); // >= |p'(x)|
    if !(l > 0.0 && slope < 2.0 * l * (x - lo) * (1.0 - rel) && slope < 2.0 * l * (hi - x) * (1.0 - rel)) {
        return None;
    }
    // refine_root's first step on p' from x (tol TOL_CRITICAL), and its stop
    count::event(4);
    let (v, df, _) = value_and_slope(d.row(n - 1), d.row(n - 2), n - 1, x, 0, false);
    if v == 0.0 {
        return Some(x);
    }
    let b = x - v / df;
    if b > lo && b < hi && (x - b).abs() <= TOL_CRITICAL * b.abs() {
        Some(b)
    } else {
        None
    }
}

/// C `rises_to`: whether p certainly rises on (a, b) (p' at the middle beyond its rounding),
/// so that the critical point b is a maximum of p > 0 -- the farthest pass, never a touch.
fn rises_to(d1: &[f64], n: usize, a: f64, b: f64) -> bool {
    let m = a + 0.5 * (b - a);
    let k = scale_exponent(m, n - 1);
    let v = horner(d1, n - 1, m, k, false);
    v > 0.0 && !noise_holds(d1, n - 1, m, k, v, 0.0)
}

/// C `scan_pieces`: the first root in (lo, t_end] of c (c(lo) > 0), given its critical points
/// there (ascending) and p', p'' in d: monotone pieces scanned left to right, with the graze
/// check at each critical point.  `tv`: on a touch's interval (one critical point, t_end = hi),
/// the values the scan reads, computed in one pass (`touch_values`).
#[allow(clippy::too_many_arguments)]
fn scan_pieces(c: &[f64], d: &Chain, n: usize, lo: f64, t_end: f64, crit: &[f64], skin: f64,
               tv: Option<&TouchValues>) -> Option<(f64, bool)> {
    let nc = crit.len();
    let mut a = lo;
    let sa = 1;
    // p(b) by fma Horner (sign_at's value, kept for the graze check), and whether the last
    // graze check has already taken it at this b (as C)
    let mut vb = 0.0;
    let mut kb = 0;
    let mut vb_known = false;
    for j in 0..=nc {
        let b = if j < nc { crit[j] } else { t_end };
        // (with tv: the critical point, then the end; no scaling at either)
        let at = if j == 0 { tv } else { None };
        if !vb_known {
            kb = scale_exponent(b, n);
            vb = match at {
                Some(at) => {
                    count::madds(n);
                    at.vb
                }
                None => horner(c, n, b, kb, true),
            };
        }
        vb_known = false;
        let mut sb = i32::from(vb > 0.0) - i32::from(vb < 0.0);
        if sb == 0 {
            return Some((b, j < nc));
        }
        // at a critical point the fma sign may be noise (a touch): the precise value decides
        // whether p crosses in (a, b] (where b needs no scaling); so at the window's end when
        // p is within its noise there (C says why)
        let precise = sb != sa && kb == 0 && (j < nc || noise_holds(c, n, b, kb, vb, 0.0));
        let pb = match (precise, at) {
            (false, _) => 0.0,
            (true, Some(at)) => {
                count::madds(10 * n);
                at.pb
            }
            (true, None) => horner_compensated(c, n, b),
        };
        if precise && pb != 0.0 && (pb > 0.0) == (sa > 0) {
            sb = sa; // no crossing in (a, b]: maybe a touch at b (below)
        }
        if sb != sa {
            let t = if precise && j < nc {
                crossing_before_critical(c, d, n, a, b, sa, pb)
            } else {
                refine_root(c, d.row(n - 1), n, a, b, sa, 0.0, split_point(a, b))
            };
            return Some((t, false));
        }
        let near = skin >= 0.0
            && j < nc
            && match at {
                Some(at) => {
                    count::madds(n); // (noise_holds' horner_abs)
                    vb.abs() <= noise_factor(n) * at.ab + skin // (kb = 0)
                }
                // (a maximum is no touch; on a touch's interval b is a minimum)
                None => noise_holds(c, n, b, kb, vb, skin) && !rises_to(d.row(n - 1), n, a, b),
            };
        if near {
            let b2 = if j + 1 < nc { crit[j + 1] } else { t_end };
            kb = scale_exponent(b2, n);
            vb = match at {
                Some(at) if nc == 1 => {
                    count::madds(n);
                    at.vhi
                }
                _ => horner(c, n, b2, kb, true),
            };
            vb_known = true;
            let mut s2 = i32::from(vb > 0.0) - i32::from(vb < 0.0);
            // (its sign too is noise where p is within its noise there: the precise value
            // decides, as above)
            if s2 != sa && kb == 0 && noise_holds(c, n, b2, kb, vb, 0.0) {
                let p2 = horner_compensated(c, n, b2);
                if p2 != 0.0 && (p2 > 0.0) == (sa > 0) {
                    s2 = sa;
                }
            }
            if s2 == sa {
                return Some((touch_point(d, n, b, at), true));
            }
        }
        a = b;
    }
    None
}

/// First root in (0, T] of p (degree n >= 3, normalised, p[0] > 0), as (t, graze, scanned):
/// scanned where the derivative method found it (its scan's fma signs cannot see a crossing
/// pair inside the noise: `never_late` looks again).
/// `failed_w`: see `isolate_first_root`.  By its copy for the degree where there is one (C's
/// `first_root_interval_fixed` and `INTERVAL_CLONE`: degrees 4 and 8, compiled with n a
/// constant; the same operations in the same order).
pub(crate) fn first_root_interval(p: &Coeffs, n: usize, t_end: f64, skin: f64, failed_w: f64) -> Option<(f64, bool, bool)> {
    match n {
        8 => first_root_interval_of::<8>(p, t_end, skin, failed_w),
        4 => first_root_interval_of::<4>(p, t_end, skin, failed_w),
        _ => first_root_interval_any(p, n, t_end, skin, failed_w),
    }
}

/// `first_root_interval_core` for degree `N` (C `first_root_interval_N`).
#[inline(never)]
fn first_root_interval_of<const N: usize>(p: &Coeffs, t_end: f64, skin: f64, failed_w: f64) -> Option<(f64, bool, bool)> {
    first_root_interval_core(p, N, t_end, skin, failed_w)
}

/// `first_root_interval_core` for any degree (C `first_root_interval_any`).
#[inline(never)]
fn first_root_interval_any(p: &Coeffs, n: usize, t_end: f64, skin: f64, failed_w: f64) -> Option<(f64, bool, bool)> {
    first_root_interval_core(p, n, t_end, skin, failed_w)
}

/// C `first_root_interval`.
#[inline(always)]
fn first_root_interval_core(p: &Coeffs, n: usize, t_end: f64, skin: f64, failed_w: f64) -> Option<(f64, bool, bool)> {
    debug_assert!(p[0] > 0.0);
    let mut lo = 0.0;
    if t_end <= if n <= 8 { FAST_LIMIT_LOW } else { FAST_LIMIT_HIGH } {
        match isolate_first_root(p, n, skin, t_end, failed_w) {
            Isolation::Isolated(t, g) => return Some((t, g, false)),
            Isolation::Scanned(t, g) => return Some((t, g, true)),
            Isolation::Cleared => return None,
            Isolation::Unresolved(a) => lo = a,
        }
    }
    derivative_method(p, n, lo, t_end, 0.0, skin).map(|(t, g)| (t, g, true))
}

/// The quadratic, for the entry point.
pub(crate) fn quadratic(c: &[f64], tmax: f64, skin: f64) -> Option<(f64, bool)> {
    first_root_quadratic(c, 0.0, tmax, skin)
}

const SLICE: i32 = 32;
const DOMINANCE: i32 = 6;

/// C `dominant_term`: the term that beats every other by 2^DOMINANCE at t = 2^d.
fn dominant_term(e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, d: i32) -> Option<usize> {
    let (mut best, mut top, mut second) = (None, i32::MIN, i32::MIN);
    for i in 0..=n {
        if !nz[i] {
            continue;
        }
        let v = e[i] + d * i as i32;
        if v > top {
            second = top;
            top = v;
            best = Some(i);
        } else if v > second {
            second = v;
        }
    }
    if second == i32::MIN || top - second >= DOMINANCE {
        best
    } else {
        None
    }
}

/// C `first_root_sliced`: coefficients spanning more than 2^MAX_SPREAD, solved slice by slice
/// of t (see the C runtime); c has c[0] != 0 and is not normalised.
pub(crate) fn first_root_sliced(c: &[f64], n: usize, tmax: f64, eps: f64, nograze: bool) -> Option<(f64, bool)> {
    let mut e = [0i32; MAXN + 1];
    let mut nz = [false; MAXN + 1];
    let (_, emax) = exponents(c, n, &mut e, &mut nz);
    let lo = pow2(-16);
    let lo_open = f64::from_bits(lo.to_bits() - 1);
    let hi = pow2(16);
    let mut d = (e[0] - emax - 2).div_euclid(SLICE) * SLICE;
    while d < 1024 {
        if d >= -1074 && ldexp(1.0, i64::from(d)) >= tmax {
            return None;
        }
        let v = dominant_term(&e, &nz, n, d);
        if v.is_some() && v == dominant_term(&e, &nz, n, d + SLICE) {
            d += SLICE;
            continue;
        }
        let k = d + SLICE / 2;
        let mut top = i32::MIN;
        for i in 0..=n {
            if nz[i] {
                top = top.max(e[i] + k * i as i32);
            }
        }
        let mut q = [0.0f64; MAXN + 1];
        for i in 0..=n {
            q[i] = if nz[i] { ldexp(c[i], i64::from(k * i as i32 - top - 1)) } else { 0.0 };
            if q[i].abs() < f64::MIN_POSITIVE {
                q[i] = 0.0;
            }
        }
        let mut m = n;
        while m > 0 && q[m] == 0.0 {
            m -= 1;
        }
        if m > 0 {
            let tu = ldexp(tmax, -i64::from(k));
            let t_end = if tu < hi { tu } else { hi };
            let skin = if nograze {
                -1.0
            } else if eps == 0.0 {
                0.0
            } else {
                ldexp(eps, -i64::from(top + 1))
            };
            let hit = match m {
                1 => {
                    let r = -q[0] / q[1];
                    (r > lo_open && r <= t_end).then_some((r, false))
                }
                2 => first_root_quadratic(&q, lo_open, t_end, skin),
                _ => {
                    let s = sign_at(&q, m, lo, true);
                    if s < 0 {
                        for v in q.iter_mut().take(m + 1) {
                            *v = -*v;
                        }
                    }
                    if s == 0 {
                        Some((lo, false))
                    } else {
                        derivative_method(&q, m, lo, t_end, 0.0, skin)
                    }
                }
            };
            if let Some((r, g)) = hit {
                // a root at or above half the least subnormal rounds up to it (C says why)
                let t = ldexp(r, i64::from(k));
                if t == 0.0 && r >= ldexp(1.0, -1075 - i64::from(k)) {
                    return Some((f64::from_bits(1), g));
                }
                return Some((t, g));
            }
        }
        d += SLICE;
    }
    None
}

static BINOM: [[f64; MAXN + 1]; MAXN + 1] = binom_table();

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

#[cfg(test)]
mod check {
    #[test]
    fn binomials() {
        for k in 0..=super::MAXN {
            for j in 0..=super::MAXN - k {
                assert_eq!(super::BINOM[k][j], super::binom(k, j));
            }
        }
        assert_eq!(super::BINOM[8][8], 12870.0);
    }
}

#[cfg(test)]
mod ceil {
    #[test]
    fn ceil_div_is_the_ceiling() {
        // every den and every num of the documented domain (|num| < 2^12)
        for den in 1..=16 {
            for num in -4095..=4095 {
                assert_eq!(super::ceil_div(num, den), num.div_euclid(den) + i32::from(num.rem_euclid(den) != 0), "{num} / {den}");
            }
        }
    }
}

#[cfg(test)]
mod preparation {
    use super::{load_coefficients, root_bound, Coeffs, Scan, MAXN};

    #[test]
    fn inverse_binomials_are_the_rounded_quotients() {
        // against C(n, k) from the product formula and a division at run time
        for n in 0..=MAXN {
            let mut c = 1u64;
            for k in 0..=n {
                let q = std::hint::black_box(1.0) / c as f64;
                assert_eq!(super::INV_BINOM[n][k].to_bits(), q.to_bits(), "1 / C({n}, {k})");
                c = c * (n - k) as u64 / (k + 1) as u64;
            }
        }
        assert_eq!(super::INV_BINOM[16][8], 1.0 / 12870.0);
    }

    #[test]
    fn exponents_from_the_bits() {
        let src = [1.0, -0.75, 0.0, -0.0, 5e-324, 3.0e-310, f64::MAX, -f64::MIN_POSITIVE];
        let (mut c, mut e, mut nz): (Coeffs, _, _) = ([9.0; MAXN + 1], [9; MAXN + 1], [true; MAXN + 1]);
        assert!(load_coefficients(&src, &mut c, &mut e, &mut nz).finite);
        assert_eq!(&c[..src.len()], &src);
        assert_eq!(&e[..src.len()], &[0, -1, 0, 0, -1074, -1029, 1023, -1022]);
        assert_eq!(&nz[..src.len()], &[true, true, false, false, true, true, true, true]);
        // 3.0e-310 is in [2^-1029, 2^-1028) (subnormals: 2^k = bit 1074 + k)
        assert!(f64::from_bits(1 << 45) <= 3.0e-310 && 3.0e-310 < f64::from_bits(1 << 46));
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert!(!load_coefficients(&[1.0, bad, 2.0], &mut c, &mut e, &mut nz).finite);
        }
    }

    /// The plain definition of the scan: `2^e <= |x| < 2^(e + 1)` by comparison with exact
    /// powers of two (subnormal ones included), sign changes between consecutive nonzero
    /// coefficients (x == 0.0 is true for -0.0 too).
    fn plain_scan(src: &[f64]) -> Scan {
        let pow2 = |k: i32| if k >= -1022 { f64::from_bits(((k + 1023) as u64) << 52) } else { f64::from_bits(1u64 << (k + 1074)) };
        let (mut emax, mut emin, mut changes, mut last) = (i32::MIN, i32::MAX, 0, 0);
        for &x in src {
            if x == 0.0 {
                continue;
            }
            let a = x.abs();
            let mut k = (a.log2().floor() as i32).clamp(-1074, 1023);
            while pow2(k) > a {
                k -= 1;
            }
            while k < 1023 && pow2(k + 1) <= a {
                k += 1;
            }
            emax = emax.max(k);
            emin = emin.min(k);
            let s = if x > 0.0 { 1 } else { -1 };
            changes += i32::from(last != 0 && s != last);
            last = s;
        }
        Scan { finite: true, emax, emin, changes }
    }

    #[test]
    fn scan_is_the_plain_definition() {
        let (mut c, mut e, mut nz): (Coeffs, _, _) = ([0.0; MAXN + 1], [0; MAXN + 1], [false; MAXN + 1]);
        let mut scan = |src: &[f64]| load_coefficients(src, &mut c, &mut e, &mut nz);
        // zeros of both signs are skipped: -0.0 is no negative coefficient
        let fixed: [(&[f64], i32, i32, i32); 8] = [
            (&[1.0, -0.0, 2.0], 1, 0, 0),
            (&[-1.0, 0.0, -0.0, -3.0], 1, 0, 0),
            (&[-0.0, 1.0, -1.0], 0, 0, 1),
            (&[0.5, 0.0, -0.0, -4.0, 0.0, 8.0], 3, -1, 2),
            (&[5e-324, -f64::MAX], 1023, -1074, 1),
            (&[-0.0], i32::MIN, i32::MAX, 0),
            (&[0.0, -0.0, 0.0], i32::MIN, i32::MAX, 0),
            (&[-2.0], 1, 1, 0),
        ];
        for (src, emax, emin, changes) in fixed {
            assert_eq!(scan(src), Scan { finite: true, emax, emin, changes }, "{src:?}");
        }
        // random coefficients over the whole range, one in four a zero of either sign
        let mut s = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for trial in 0..20000 {
            let n = trial % (MAXN + 1);
            let src: Vec<f64> = (0..=n)
                .map(|_| {
                    let r = next();
                    match r % 8 {
                        0 => 0.0,
                        1 => -0.0,
                        // any finite bit pattern: normal and subnormal, either sign
                        _ => {
                            let x = f64::from_bits(r >> 3 | (r & 1) << 63);
                            if x.is_finite() { x } else { 1.5 }
                        }
                    }
                })
                .collect();
            assert_eq!(scan(&src), plain_scan(&src), "{src:?}");
        }
    }

    #[test]
    fn root_bound_bounds_the_roots() {
        // (t - 3)(t + 5)(t - 0.25) = t^3 + 1.75 t^2 - 15.5 t + 3.75: |c_1 / c_3| < 2^4 gives
        // 2^(ceil(4 / 2) + 1) = 8, above the largest root (5); the other terms give less
        let src = [3.75, -15.5, 1.75, 1.0];
        let (mut c, mut e, mut nz): (Coeffs, _, _) = ([0.0; MAXN + 1], [0; MAXN + 1], [false; MAXN + 1]);
        assert!(load_coefficients(&src, &mut c, &mut e, &mut nz).finite);
        assert_eq!(root_bound(&e, &nz, None, 3), 8.0);
        // on the positive roots (3, 0.25) only c_1 counts, the one term of the sign opposite
        // to c_3's: the same 8 here; with c_1 > 0, (t + 3)(t + 5)(t + 0.25) has no sign
        // change and no bound
        assert_eq!(root_bound(&e, &nz, Some(&c), 3), 8.0);
        let pos = [3.75, 23.0, 8.25, 1.0];
        assert!(load_coefficients(&pos, &mut c, &mut e, &mut nz).finite);
        assert_eq!(root_bound(&e, &nz, None, 3), 32.0);
        assert_eq!(root_bound(&e, &nz, Some(&c), 3), 0.0);
        // (t - 0.5)(t + 100) = t^2 + 99.5 t - 50: Fujiwara 2^8, Kioustelidis only from -50
        let mixed = [-50.0, 99.5, 1.0];
        assert!(load_coefficients(&mixed, &mut c, &mut e, &mut nz).finite);
        assert_eq!(root_bound(&e, &nz, None, 2), 256.0);
        assert_eq!(root_bound(&e, &nz, Some(&c), 2), 16.0);
        // only the leading term: no bound
        let (mut e2, mut nz2) = ([0; MAXN + 1], [false; MAXN + 1]);
        assert!(load_coefficients(&[0.0, 0.0, 2.0], &mut c, &mut e2, &mut nz2).finite);
        assert_eq!(root_bound(&e2, &nz2, None, 2), 0.0);
    }
}

/// The kernels written over 9 entries with constant bounds (degree <= 8) against C's plain
/// loops, bit for bit, on wide-range data with exact zeros (as tests/runtime/test_c_kernels.py
/// checks C's written-out forms).
#[cfg(test)]
mod kernels {
    use super::{binomial_sums, compensated_with_slope, halves, horner, horner_abs, horner_compensated, load_any, load_coefficients, taylor_shift, taylor_shift_8, taylor_table, touch_values, touch_values_core, Taylor, MAXN};
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    use super::{compensated_core, compensated_hw, compensated_slope_core, compensated_slope_hw, horner_core, horner_fma_hw, hw_fma};
    use std::mem::MaybeUninit;

    /// xorshift; values of both signs over 2^-30..2^30, one in 16 an exact zero.
    struct Rnd(u64);
    impl Rnd {
        fn next(&mut self) -> f64 {
            let s = &mut self.0;
            *s ^= *s << 13;
            *s ^= *s >> 7;
            *s ^= *s << 17;
            if (*s).is_multiple_of(16) {
                return 0.0;
            }
            let m = (*s >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            m * 2f64.powi(((*s >> 5) % 60) as i32 - 30)
        }
        fn array(&mut self) -> [f64; MAXN + 1] {
            std::array::from_fn(|_| self.next())
        }
    }

    fn bits(v: &[f64]) -> Vec<u64> {
        v.iter().map(|x| x.to_bits()).collect()
    }

    #[test]
    fn loading_normal_numbers_is_load_any() {
        // the loop for normal numbers against the general one, on vectors of normal numbers
        // (most), with zeros (one in 16 entries), and with a subnormal, the extremes of the
        // normal range, an infinity or a NaN put in
        let mut r = Rnd(0x2545_F491_4F6C_DD1D);
        let special = [f64::MIN_POSITIVE, -f64::MAX, 5e-324, -1e-310, f64::INFINITY, f64::NAN, -0.0];
        for trial in 0..20000 {
            let n = trial % (MAXN + 1);
            let mut src = r.array();
            if trial % 5 == 0 {
                src[trial % (n + 1)] = special[(trial / 5) % special.len()];
            }
            let (mut c1, mut e1, mut nz1) = ([0.0; MAXN + 1], [7; MAXN + 1], [false; MAXN + 1]);
            let (mut c2, mut e2, mut nz2) = ([0.0; MAXN + 1], [7; MAXN + 1], [false; MAXN + 1]);
            let s1 = load_coefficients(&src[..=n], &mut c1, &mut e1, &mut nz1);
            let s2 = load_any(&src[..=n], &mut c2, &mut e2, &mut nz2);
            assert_eq!((s1.finite, s1.emax, s1.emin, s1.changes), (s2.finite, s2.emax, s2.emin, s2.changes), "{src:?}");
            assert_eq!(bits(&c1[..=n]), bits(&c2[..=n]));
            assert_eq!((&e1[..=n], &nz1[..=n]), (&e2[..=n], &nz2[..=n]), "{src:?}");
        }
    }

    #[test]
    fn compensated_value_with_its_slope_is_the_value_alone() {
        // C compensated_with_slope: horner_compensated's value bits, and D's plain Horner in the
        // same loop
        let mut r = Rnd(0x853C_49E6_748F_EA9B);
        for trial in 0..20000 {
            let m = 1 + trial % MAXN;
            let (p, d) = (r.array(), r.array());
            let x = (1.0 + r.next().abs()) * 2f64.powi((trial % 7) as i32 - 3);
            let (v, slope) = compensated_with_slope(&p, &d, m, x);
            let mut want = d[m - 1];
            for j in (0..m - 1).rev() {
                want = want * x + d[j];
            }
            assert_eq!(v.to_bits(), horner_compensated(&p, m, x).to_bits(), "m={m}");
            assert_eq!(slope.to_bits(), want.to_bits(), "m={m}");
        }
    }

    #[test]
    fn fma_copies_give_the_plain_bits() {
        // C FMA_DISPATCH: the precise kernels' copies for the fma instruction against their plain
        // forms (Dekker's product, mul_add by libm), bit for bit; near roots too, where the
        // compensated value is mostly its correction
        #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
        {
            assert!(hw_fma(), "this CPU has no fma instruction: the copies cannot be compared here");
            let mut r = Rnd(0x2545_F491_4F6C_DD1D);
            for trial in 0..20000 {
                let m = 1 + trial % MAXN;
                let (p, d) = (r.array(), r.array());
                let x0 = (1.0 + r.next().abs()) * 2f64.powi((trial % 7) as i32 - 3);
                // a root of p near x0, by a few Newton steps: the compensated value's hard case
                let mut x = x0;
                for _ in 0..6 {
                    let (v, dv) = (horner(&p, m, x, 0, false), horner(&d, m - 1, x, 0, false));
                    if dv != 0.0 && (x - v / dv).is_finite() {
                        x -= v / dv;
                    }
                }
                for x in [x0, x] {
                    // SAFETY: hw_fma() above
                    let (a, b) = unsafe { (compensated_hw(&p, m, x), compensated_slope_hw(&p, &d, m, x)) };
                    assert_eq!(a.to_bits(), compensated_core(&p, m, x, false).to_bits(), "m={m} x={x}");
                    let want = compensated_slope_core(&p, &d, m, x, false);
                    assert_eq!((b.0.to_bits(), b.1.to_bits()), (want.0.to_bits(), want.1.to_bits()));
                    for k in 0..3 {
                        // SAFETY: hw_fma() above
                        let h = unsafe { horner_fma_hw(&p, m, x, k) };
                        assert_eq!(h.to_bits(), horner_core(&p, m, x, k, true).to_bits(), "m={m} k={k}");
                    }
                }
            }
        }
    }

    #[test]
    fn touch_values_are_the_kernels() {
        // C touch_values: the five evaluations of a touch's scan in one loop, against the
        // kernels they replace, bit for bit (dispatched and plain copy)
        let mut r = Rnd(0x6A09_E667_F3BC_C909);
        for trial in 0..20000 {
            let n = 3 + trial % (MAXN - 2);
            let p = r.array();
            let mut d1 = [0.0f64; MAXN + 1];
            let mut d2 = [0.0f64; MAXN + 1];
            for i in 0..n {
                d1[i] = (i + 1) as f64 * p[i + 1];
            }
            for i in 0..n - 1 {
                d2[i] = (i + 1) as f64 * d1[i + 1];
            }
            let x = (1.0 + r.next().abs()) * 2f64.powi((trial % 7) as i32 - 3);
            let hi = x * (1.0 + 2f64.powi(-9));
            let (dv, ddv) = compensated_with_slope(&d1, &d2, n - 1, x);
            let want = [horner(&p, n, x, 0, true), horner_compensated(&p, n, x), horner_abs(&p, n, x, 0),
                        horner(&p, n, hi, 0, true), dv, ddv];
            for tv in [touch_values(&p, &d1, &d2, n, x, hi), touch_values_core(&p, &d1, &d2, n, x, hi, false)] {
                let got = [tv.vb, tv.pb, tv.ab, tv.vhi, tv.dv, tv.ddv];
                for (g, w) in got.iter().zip(want) {
                    assert_eq!(g.to_bits(), w.to_bits(), "n={n} x={x}");
                }
            }
        }
    }

    #[test]
    fn running_sums_are_the_loop() {
        let mut r = Rnd(0x9E37_79B9_7F4A_7C15);
        for trial in 0..20000 {
            let n = 1 + trial % 8;
            let mut a = r.array();
            a[n + 1..].fill(0.0); // (the caller's padding)
            let mut want = a;
            for round in 1..=n {
                for j in (round..=n).rev() {
                    want[j] += want[j - 1];
                }
            }
            binomial_sums(&mut a, n);
            assert_eq!(bits(&a[..=n]), bits(&want[..=n]), "degree {n}");
        }
    }

    #[test]
    fn halves_are_the_loop() {
        // left: the first entries of de Casteljau's triangle; right: its last ones, which are
        // also the left half of the reversed coefficients, reversed (the old way)
        let mut r = Rnd(0x1234_5678_9ABC_DEF1);
        for trial in 0..20000 {
            let n = 1 + trial % 8;
            let a = r.array(); // entries above n must not matter
            let mut w = a;
            let (mut left, mut right) = ([0.0; MAXN + 1], [0.0; MAXN + 1]);
            left[0] = w[0];
            right[n] = w[n];
            for k in 1..=n {
                for j in 0..=n - k {
                    w[j] = (w[j] + w[j + 1]) * 0.5;
                }
                left[k] = w[0];
                right[n - k] = w[n - k];
            }
            let mut v: Vec<f64> = (0..=n).rev().map(|j| a[j]).collect();
            let mut mirrored = vec![0.0; n + 1];
            mirrored[n] = v[0];
            for k in 1..=n {
                for j in 0..=n - k {
                    v[j] = (v[j] + v[j + 1]) * 0.5;
                }
                mirrored[n - k] = v[0];
            }
            assert_eq!(bits(&right[..=n]), bits(&mirrored), "degree {n} (reversed)");
            let a9: [f64; 9] = std::array::from_fn(|j| a[j]);
            let (l9, r9) = halves(&a9, n);
            assert_eq!(bits(&l9[..=n]), bits(&left[..=n]), "degree {n}");
            assert_eq!(bits(&r9[..=n]), bits(&right[..=n]), "degree {n}");
            let (l, rr) = halves(&a, n);
            assert_eq!(bits(&l[..=n]), bits(&left[..=n]), "degree {n} (loop)");
            assert_eq!(bits(&rr[..=n]), bits(&right[..=n]), "degree {n} (loop)");
        }
    }

    #[test]
    fn taylor_shift_8_is_the_loop() {
        let mut r = Rnd(0x0F0F_F0F0_1234_4321);
        for trial in 0..20000 {
            let n = 1 + trial % 8;
            let p = r.array();
            let x = r.next().abs() + f64::MIN_POSITIVE; // x > 0
            let mut slot = MaybeUninit::<Taylor>::uninit();
            let tb = taylor_table(&p, n, 1e-15, 0.0, &mut slot);
            let (mut a, mut s) = ([0.0; MAXN + 1], [0.0; MAXN + 1]);
            let (mut a8, mut s8) = ([0.0; MAXN + 1], [0.0; MAXN + 1]);
            taylor_shift(tb, n, x, &mut a, &mut s);
            taylor_shift_8(tb, x, &mut a8, &mut s8);
            assert_eq!(bits(&a8[..=n]), bits(&a[..=n]), "degree {n} at {x}");
            assert_eq!(bits(&s8[..=n]), bits(&s[..=n]), "degree {n} at {x}");
        }
    }
}
