//! Never later than the first root: the rounding-band certificates (C:
//! `runtime/c/roots/never_late.inc`).

use super::*;

/// 2^-50 and 2^60 (never_late).
const TWO_M50: f64 = 1.0 / 1_125_899_906_842_624.0;
const TWO_60: f64 = 1_152_921_504_606_846_976.0;

/// C `exact_sign`: p(x)'s exact sign inside the band (1, -1, 0 where p(x) = 0 exactly) by
/// Horner in floating-point expansions (each product split by fma, each sum by two_sum, the
/// running sum compressed after each step), or 2 where the a priori test fails (a partial sum
/// of |a_i| x^(i-k) above 2^1000, or a term's last bit ulp(a_i) ulp(x)^i below 2^-1000): only
/// under that test is no bit lost.
fn exact_sign(c: &[f64], n: usize, tail: &[f64], x: f64) -> i32 {
    const LEN: usize = 128;
    let top = n + tail.len();
    let coef = |i: usize| if i <= n { c[i] } else { tail[i - n - 1] };
    if !(x > 0.0 && x < f64::INFINITY) {
        return 2;
    }
    let lx = ilogb(x) - 52;
    let mut bound = 0.0f64;
    for i in (0..=top).rev() {
        let a = coef(i);
        bound = bound * x + a.abs();
        if !(bound <= TWO_1000) {
            return 2;
        }
        if a != 0.0 && ilogb(a) - 52 + (i as i32) * lx < -1000 {
            return 2;
        }
    }
    let (mut e, mut h) = ([0.0f64; LEN], [0.0f64; LEN]);
    let mut len = 0;
    if coef(top) != 0.0 {
        e[0] = coef(top);
        len = 1;
    }
    for i in (0..top).rev() {
        let mut k = 0;
        let mut q = 0.0;
        // scale: e * x, each product split, summed from the smallest up
        for j in 0..len {
            let p1 = e[j] * x;
            let p0 = e[j].mul_add(x, -p1);
            if j == 0 {
                push_nonzero(&mut h, &mut k, p0);
                q = p1;
                continue;
            }
            let (s, err) = two_sum(q, p0);
            push_nonzero(&mut h, &mut k, err);
            let q2 = p1 + s;
            let err = s - (q2 - p1);
            push_nonzero(&mut h, &mut k, err);
            q = q2;
        }
        push_nonzero(&mut h, &mut k, q);
        // grow: + a_i
        q = coef(i);
        len = 0;
        for j in 0..k {
            let (s, err) = two_sum(q, h[j]);
            push_nonzero(&mut e, &mut len, err);
            q = s;
        }
        push_nonzero(&mut e, &mut len, q);
        // compress: largest first, then back up from the smallest
        if len > 1 {
            let mut bottom = len - 1;
            let mut big = e[len - 1];
            for j in (0..len - 1).rev() {
                let s = big + e[j];
                let small = e[j] - (s - big);
                if small != 0.0 {
                    h[bottom] = s;
                    bottom -= 1;
                    big = small;
                } else {
                    big = s;
                }
            }
            h[bottom] = big;
            let mut out = 0;
            let mut acc = h[bottom];
            for j in bottom + 1..len {
                let s = h[j] + acc;
                let small = acc - (s - h[j]);
                push_nonzero(&mut e, &mut out, small);
                acc = s;
            }
            e[out] = acc;
            len = out + 1;
        }
        if 2 * len + 2 > LEN {
            return 2; // (cannot happen under the test: at most ~40 components)
        }
    }
    if len == 0 {
        return 0;
    }
    let lead = e[len - 1];
    if lead > 0.0 {
        1
    } else if lead < 0.0 {
        -1
    } else {
        0
    }
}

/// Appends v to h (at k) unless it is 0: expansions keep no zero components.
fn push_nonzero(h: &mut [f64], k: &mut usize, v: f64) {
    if v != 0.0 {
        h[*k] = v;
        *k += 1;
    }
}

/// Knuth's two_sum: a + b rounded and its exact rounding error.
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

const TWO_1000: f64 = 1.0715086071862673e301; // 2^1000

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
        // inside the band: exactly, where it can
        match exact_sign(c, n, tail, x) {
            2 => 0,
            s => s,
        }
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
pub(super) fn noise_chains(c: &[f64], n: usize, x: f64, y: f64) -> ([f64; 4], [f64; 5]) {
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
pub(super) fn half_curvature_floor(f: &[f64; 4], g: &[f64; 5], e: f64, rel: f64, h: f64) -> f64 {
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
            let walk = if gu {
                hs == -1 || (hs == 0 && band_side(c, n, &[], t - d) != 1)
            } else {
                hs != 1
            };
            if walk {
                band_walk(c, n, &[], t, d, hs, gu)
            } else {
                (t, gu)
            }
        }
        None => hit,
    }
}

/// C `never_late` (issue 33, item 11): never later than the first root of the polynomial as
/// given (c and the dropped terms, tail).  A root or a touch stands where p is certainly
/// positive just before it, at r (1 - 2^-50), a touch also where p is certainly positive at it
/// (a near miss); else (inside the band, where a rounded multiple root's exact first root may
/// lie anywhere before r) the earliest point that cannot be excluded (steps to the left, doubling, then bisection), a crossing
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
    if g && hs == 0 && band_side(c, n, tail, r - d) == 1 {
        return hit; // a touch at the band's left edge: p certainly positive before it
    }
    if !g && hs == 1 {
        return hit;
    }
    band_walk(c, n, tail, r, d, hs, g)
}

/// C `band_walk`: never_late's steps from a root r that does not stand (d = r 2^-50, hs p's
/// band side at r - d for a crossing, at r for a touch).
#[inline(never)]
fn band_walk(c: &[f64], n: usize, tail: &[f64], r: f64, d: f64, mut hs: i32, g: bool) -> (f64, bool) {
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

/// C `late_sliced_tail`: `never_late` on a slice where reduce dropped leading terms: q (degree
/// m) is c_i 2^(k i - top - 1) times sign, its terms of degrees m+1..n 0 in the tail, the
/// dropped ones scaled alike after them.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn late_sliced_tail(q: &[f64], m: usize, n: usize, dropped: &[f64], k: i32, top: i32, sign: f64, hit: (f64, bool)) -> (f64, bool) {
    let mut tail = [0.0f64; MAXN];
    for (j, &v) in dropped.iter().enumerate() {
        tail[n - m + j] = ldexp(sign * v, i64::from(k * (n + 1 + j) as i32 - top - 1));
    }
    never_late(q, m, &tail[..n - m + dropped.len()], hit)
}

/// C `late_low_degree`: `never_late` for the closed forms of degree 1 and 2 after reduce
/// dropped leading terms (tail, scaled as c), with p(0) made positive, as never_late wants.
#[inline(never)]
pub(crate) fn late_low_degree(c: &[f64], n: usize, tail: &[f64], hit: (f64, bool)) -> (f64, bool) {
    let s = if c[0] < 0.0 { -1.0 } else { 1.0 };
    let mut p = [0.0f64; 3];
    for (v, &x) in p.iter_mut().zip(&c[..=n]) {
        *v = s * x;
    }
    let mut t = [0.0f64; MAXN];
    for (v, &x) in t.iter_mut().zip(tail) {
        *v = s * x;
    }
    never_late(&p[..=n], n, &t[..tail.len()], hit)
}

/// C `dropped_terms`: the leading terms reduce dropped from coef (n kept after the factors of t
/// it divided out), up to the last nonzero; empty where it dropped none.
pub(crate) fn dropped_terms(coef: &[f64], n: usize) -> &[f64] {
    let low = coef.iter().position(|&v| v != 0.0).unwrap_or(0);
    let top = coef.iter().rposition(|&v| v != 0.0).unwrap_or(0).max(low + n);
    &coef[low + n + 1..=top]
}

#[cfg(test)]
mod exact_sign_tests {
    use super::exact_sign;

    /// p(x) 2^(s N) in i128 for integer coefficients and x = (2^s + k) / 2^s: exact where it fits.
    fn exact_scaled(a: &[i64], s: u32, k: i64) -> i128 {
        let num = (1i128 << s) + i128::from(k);
        let n = a.len() - 1;
        let mut w: i128 = 0;
        let mut pw: i128 = 1;
        for (i, &ai) in a.iter().enumerate() {
            w += i128::from(ai) * pw * (1i128 << (s * (n - i) as u32));
            pw *= num;
        }
        w
    }

    #[test]
    fn exact_sign_agrees_with_integer_arithmetic_near_clusters() {
        // (x - 1)^3 (x - 3), (x - 1)^4, (x - 1)^2 (x + 2) (x - 1 - 2^-18): roots clustered at 1
        let polys: [&[i64]; 3] = [&[-3, 10, -12, 6, -1], &[1, -4, 6, -4, 1], &[2, -3, 0, 1]];
        let s = 20;
        for a in polys {
            let c: Vec<f64> = a.iter().map(|&v| v as f64).collect();
            for k in -40i64..=40 {
                let x = 1.0 + (k as f64) / f64::from(1u32 << s);
                let want = exact_scaled(a, s, k).signum() as i32;
                for n in 1..c.len() {
                    // the rest as never_late's tail (dropped terms): the same polynomial
                    assert_eq!(exact_sign(&c[..=n], n, &c[n + 1..], x), want, "{a:?} k={k} n={n}");
                }
            }
        }
    }

    #[test]
    fn exact_sign_refuses_what_could_lose_bits() {
        assert_eq!(exact_sign(&[1.0, 1e300, 1e300], 2, &[], 8.0), 2); // a partial sum above 2^1000
        assert_eq!(exact_sign(&[1.0, 1e-300, 1.0], 2, &[], 1.0), 2); // a last bit below 2^-1000
        assert_eq!(exact_sign(&[1.0, -2.0, 1.0], 2, &[], 1.0), 0); // (x - 1)^2 at 1: exactly 0
    }
}
