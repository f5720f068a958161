//! Compensated Horner, touch values and safeguarded Newton (C:
//! `runtime/c/roots/newton.inc`).

use super::*;

pub(super) fn split_point(lo: f64, hi: f64) -> f64 {
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
pub(super) fn compensated_core(p: &[f64], m: usize, x: f64, hw: bool) -> f64 {
    let (xh, xl) = if hw { (0.0, 0.0) } else { dekker_split(x) };
    let (mut s, mut c) = (p[m], 0.0);
    for &pi in p[..m].iter().rev() {
        (s, c) = compensated_step(s, c, x, xh, xl, pi, hw);
    }
    s + c
}

/// C `compensated_slope_core`.
#[inline(always)]
pub(super) fn compensated_slope_core(p: &[f64], d: &[f64], m: usize, x: f64, hw: bool) -> (f64, f64) {
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
pub(super) fn compensated_hw(p: &[f64], m: usize, x: f64) -> f64 {
    compensated_core(p, m, x, true)
}

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[target_feature(enable = "fma")]
#[inline(never)]
pub(super) fn compensated_slope_hw(p: &[f64], d: &[f64], m: usize, x: f64) -> (f64, f64) {
    compensated_slope_core(p, d, m, x, true)
}

/// Whether the build itself has the fma instruction (C `FMA_BUILT_IN`).
const FMA_BUILT_IN: bool = cfg!(target_feature = "fma");

/// C `horner_compensated`.
pub(super) fn horner_compensated(p: &[f64], m: usize, x: f64) -> f64 {
    count::madds(10 * m);
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if hw_fma() {
        // SAFETY: the CPU has the fma instruction (detected above)
        return unsafe { compensated_hw(p, m, x) };
    }
    compensated_core(p, m, x, FMA_BUILT_IN)
}

/// C `compensated_with_slope`: (`horner_compensated(p, m, x)`, d(x) by plain Horner in the same
/// loop; d of degree m - 1, m >= 1).
pub(super) fn compensated_with_slope(p: &[f64], d: &[f64], m: usize, x: f64) -> (f64, f64) {
    count::madds(10 * m);
    compensated_slope_ahead(p, d, m, x)
}

/// C `compensated_slope_ahead`: the same, uncounted (an evaluation done ahead of its use,
/// counted there).  Inlined (C's flattened degree copies inline it too).
#[inline(always)]
pub(super) fn compensated_slope_ahead(p: &[f64], d: &[f64], m: usize, x: f64) -> (f64, f64) {
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
pub(super) struct TouchValues {
    pub(super) vb: f64,
    pub(super) pb: f64,
    pub(super) ab: f64,
    pub(super) vhi: f64,
    pub(super) dv: f64,
    pub(super) ddv: f64,
}

/// C `touch_values_core`: the five evaluations' chains side by side, each in its kernel's order.
#[inline(always)]
pub(super) fn touch_values_core(c: &[f64], d1: &[f64], d2: &[f64], n: usize, b: f64, hi: f64, hw: bool) -> TouchValues {
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
pub(super) fn touch_values(c: &[f64], d1: &[f64], d2: &[f64], n: usize, b: f64, hi: f64) -> TouchValues {
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if hw_fma() {
        // SAFETY: the CPU has the fma instruction (detected above)
        return unsafe { touch_values_hw(c, d1, d2, n, b, hi) };
    }
    touch_values_core(c, d1, d2, n, b, hi, FMA_BUILT_IN)
}

#[inline(always)]
pub(super) fn value_and_slope(p: &[f64], d: &[f64], m: usize, x: f64, k: i32, precise: bool) -> (f64, f64, f64) {
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
pub(super) const PRECISE_NOW: f64 = -1.0;

#[allow(clippy::too_many_arguments)]
#[inline(never)]
pub(super) fn refine_root(p: &[f64], d: &[f64], m: usize, lo: f64, hi: f64, slo: i32, tol: f64, x0: f64) -> f64 {
    refine_root_from(p, d, m, lo, hi, slo, tol, x0, None)
}

/// C `refine_root_from`: `refine_root`, with (P(x0), P'(x0)) as `value_and_slope` gives them
/// precisely (k = 0) computed ahead by the caller for the first step.
/// Inlined into its two callers: `refine_root` (out of line, for every other) and the
/// degree copies of `first_root_interval` (as C's flattened copies).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(super) fn refine_root_from(p: &[f64], d: &[f64], m: usize, mut lo: f64, mut hi: f64, slo: i32, tol: f64, x0: f64,
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
