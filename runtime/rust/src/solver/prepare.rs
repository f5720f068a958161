//! Validation and preparation: exponents, root bounds, `reduce`, `normalise`
//! (C: `runtime/c/roots/prepare.inc`).

use super::*;

/// Exponent of a finite nonzero double (as C's `exponent_of`/`ilogb`).
#[inline]
fn exponent_of(x: f64) -> i32 {
    ilogb(x)
}

/// `2^e`, exact, for a normal result.
#[inline]
pub(super) fn pow2(e: i32) -> f64 {
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
pub(super) fn ceil_div(num: i32, den: i32) -> i32 {
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
pub(super) fn load_any(src: &[f64], c: &mut Coeffs, e: &mut [i32; MAXN + 1], nz: &mut [bool; MAXN + 1]) -> Scan {
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
pub(super) fn leading_far(e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, t: f64, emax: i32) -> bool {
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
