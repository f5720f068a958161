//! The derivative (Yuksel) method, its scan, touches and their certificates (C:
//! `runtime/c/roots/derivative.inc`).

use super::*;

// ---------------------------------------------------------------------------------------
// Derivative method
// ---------------------------------------------------------------------------------------

/// All derivatives of p (degree n; C's `d[MAXN + 1][MAXN + 1]`): row m is the derivative of
/// order n - m, of degree m.  Only entries 0..=m of rows 1..=n are written and only those are
/// read (as in C, where the rest stays uninitialised): zeroing the 2.3 kB table was 14 % of
/// the instructions of a graze's solve, once the touch path made its derivative method small.
pub(super) struct Chain {
    t: [[MaybeUninit<f64>; MAXN + 1]; MAXN + 1],
    n: usize,
    low: usize,
}

impl Chain {
    /// Row m (low <= m <= n): the coefficients 0..=m of the derivative of degree m.
    #[inline(always)]
    pub(super) fn row(&self, m: usize) -> &[f64] {
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
pub(super) fn derivative_rows(c: &[f64], n: usize, low: usize) -> Chain {
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
pub(super) fn derivative_method(c: &[f64], n: usize, lo: f64, t_end: f64, x0: f64, skin: f64) -> Option<(f64, bool)> {
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
pub(super) fn touch_critical(p: &[f64], d: &Chain, n: usize, lo: f64, hi: f64, x: f64) -> Option<f64> {
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
pub(super) fn scan_pieces(c: &[f64], d: &Chain, n: usize, lo: f64, t_end: f64, crit: &[f64], skin: f64,
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
