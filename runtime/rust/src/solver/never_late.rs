//! Never later than the first root: the rounding-band certificates (C:
//! `runtime/c/roots/never_late.inc`).

use super::*;

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
/// lie anywhere before r) the earliest point that cannot be excluded (steps to the left,
/// doubling, then bisection), a crossing where p is certainly negative there, else a touch.
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
    if hs == 1 || (g && hs == 0 && band_side(c, n, tail, r - d) == 1) {
        return hit; // p certainly positive before it, or at a touch (a near miss)
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
