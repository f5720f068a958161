//! The interval method (after C. Yuksel, "High-Performance Polynomial Root Finding for
//! Graphics", HPG 2022): the roots of the derivative split the window into monotone pieces;
//! a piece whose end values differ in sign holds exactly one root, found by safeguarded Newton.
//!
//! Everything here works on the scaled polynomial (see `lib.rs`): the window is `(0, hi]`
//! with `hi <= 1`, and the largest coefficient is in `[1, 2)`, so nothing overflows.

use crate::fp::{derivative, eval, eval_newton, graze_bound, opposite, quadratic, Quad, U};

/// Iteration cap of the safeguarded Newton solve.  Bisection is on the bit patterns of the
/// (non-negative) doubles, so it alone reaches adjacent doubles in at most 64 steps; the cap
/// only guards against pathological alternation and is never reached in practice.
const MAX_ITER: usize = 200;

/// Newton has converged when its last step is at most this fraction of the iterate.
const NEWTON_TOL: f64 = 4.0 * U;

/// Midpoint for bisection.  When the bracket spans more than one binade (or starts at 0) the
/// midpoint is taken on the bit patterns, i.e. geometrically, so that roots near zero are
/// found to full *relative* accuracy in a bounded number of steps.
#[inline]
fn midpoint(lo: f64, hi: f64) -> f64 {
    if lo >= 0.0 && hi > 2.0 * lo {
        let lb = if lo > 0.0 { lo.to_bits() } else { 0 };
        let hb = hi.to_bits();
        f64::from_bits(lb + (hb - lb) / 2)
    } else {
        lo + 0.5 * (hi - lo)
    }
}

/// The single root of the monotone piece `[a, b]`, given `f(a)` and `f(b)` of opposite sign.
/// Safeguarded Newton (Numerical Recipes' `rtsafe` rule): a Newton step is taken only if it
/// stays strictly inside the current bracket and at least halves the step before last;
/// otherwise the bracket is bisected.  The bracket shrinks at every evaluation.
pub(crate) fn solve_bracket(c: &[f64], n: usize, a: f64, b: f64, fa: f64, fb: f64) -> f64 {
    let lo_negative = fa < 0.0;
    let (mut lo, mut hi, mut flo, mut fhi) = (a, b, fa, fb);
    // Regula-falsi start: exact for a linear piece, and scale-aware near zero.
    let mut x = a + (b - a) * (fa / (fa - fb));
    if !(x > lo && x < hi) {
        x = midpoint(lo, hi);
    }
    let mut dx_old = b - a;
    let mut dx = dx_old;
    for _ in 0..MAX_ITER {
        let (f, step) = eval_newton(c, n, x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == lo_negative {
            lo = x;
            flo = f;
        } else {
            hi = x;
            fhi = f;
        }
        let newton = x - step;
        let use_newton = newton > lo && newton < hi && 2.0 * step.abs() <= dx_old.abs();
        let xn = if use_newton { newton } else { midpoint(lo, hi) };
        dx_old = dx;
        dx = xn - x;
        if use_newton && dx.abs() <= NEWTON_TOL * xn.abs() {
            return xn;
        }
        if xn <= lo || xn >= hi {
            // lo and hi are adjacent doubles: return the better one
            return if flo.abs() <= fhi.abs() { lo } else { hi };
        }
        x = xn;
    }
    x
}

/// All roots of the degree-n polynomial `c` in the open interval `(0, hi)`, ascending.
/// Used for the critical points (roots of the derivatives); returns the count.
pub(crate) fn all_roots(c: &[f64; 9], n: usize, hi: f64, out: &mut [f64; 8]) -> usize {
    let inside = |r: f64| r > 0.0 && r < hi;
    match n {
        0 => 0,
        1 => {
            let r = -c[0] / c[1];
            if inside(r) {
                out[0] = r;
                1
            } else {
                0
            }
        }
        2 => {
            let mut k = 0;
            match quadratic(c[2], c[1], c[0]) {
                Quad::Real(r1, r2) => {
                    for r in [r1, r2] {
                        if inside(r) {
                            out[k] = r;
                            k += 1;
                        }
                    }
                }
                Quad::Double(r) => {
                    if inside(r) {
                        out[0] = r;
                        k = 1;
                    }
                }
                Quad::Complex(_) => {}
            }
            k
        }
        _ => {
            let d = derivative(c, n);
            let mut crit = [0.0; 8];
            let k = all_roots(&d, n - 1, hi, &mut crit);
            let mut cnt = 0;
            let mut x0 = 0.0;
            let mut f0 = c[0];
            for (j, &x1) in crit[..k].iter().chain(std::iter::once(&hi)).enumerate() {
                let f1 = eval(c, n, x1);
                if opposite(f0, f1) {
                    out[cnt] = solve_bracket(c, n, x0, x1, f0, f1);
                    cnt += 1;
                } else if f1 == 0.0 && j < k {
                    out[cnt] = x1;
                    cnt += 1;
                }
                if cnt == out.len() {
                    break;
                }
                x0 = x1;
                f0 = f1;
            }
            cnt
        }
    }
}

/// First root in `(0, hi]` of the degree-n (n >= 3) polynomial `c` with `c[0] != 0`.
/// Returns `(root, graze)`.  With `graze_test`, a critical point where `|p|` is within the
/// rounding-error bound and `p` keeps its sign on both sides is reported as a graze.  An
/// exact zero at a critical point is reported by both variants (graze unless p changes
/// sign across it).
pub(crate) fn first_root(c: &[f64; 9], n: usize, hi: f64, graze_test: bool) -> Option<(f64, bool)> {
    let d = derivative(c, n);
    let mut crit = [0.0; 8];
    let k = all_roots(&d, n - 1, hi, &mut crit);
    // piece endpoints: 0, crit[0..k], hi
    let point = |j: usize| if j <= k { crit[j - 1] } else { hi };
    let mut x_prev = 0.0;
    let mut f_prev = c[0];
    let mut lookahead: Option<f64> = None;
    for j in 1..=k + 1 {
        let x = point(j);
        let f = lookahead.take().unwrap_or_else(|| eval(c, n, x));
        if opposite(f_prev, f) {
            return Some((solve_bracket(c, n, x_prev, x, f_prev, f), false));
        }
        if j == k + 1 {
            // window end: an exact zero there is a root at tmax
            return if f == 0.0 { Some((x, false)) } else { None };
        }
        // x is a critical point and p has not changed sign up to it
        if f == 0.0 || (graze_test && f.abs() <= graze_bound(c, n, x)) {
            let f_next = eval(c, n, point(j + 1));
            lookahead = Some(f_next);
            if f == 0.0 {
                // An exact zero is a root for every method (the no-graze method skips only
                // the rounding-error test); it is a touch unless p crosses through it.
                return Some((x, !opposite(f_prev, f_next)));
            }
            if !opposite(f, f_next) {
                return Some((x, true));
            }
        }
        x_prev = x;
        f_prev = f;
    }
    None
}
