//! Closed-form cubic and quartic (Method::Closed).
//!
//! Cubic: Cardano / trigonometric form of the depressed cubic, every real root polished by
//! Newton on the original polynomial.  Quartic: Ferrari's factorisation into two real
//! quadratics through the largest root of the resolvent cubic, the factorisation refined by
//! Newton on its four defining equations (the refinement step of Strobach and of
//! Orellana & De Michele, TOMS Algorithm 1010), each quadratic solved with the robust
//! quadratic, and every real root polished by Newton on the original quartic.
//!
//! Complex pairs close to the real axis are tested for a graze at their real part (refined
//! to the nearby critical point of p), with the same rounding-error bound as the interval
//! method.  Any non-finite intermediate, a root in the window whose residual exceeds
//! `32 gamma_{2n} sum |c_i| |x|^i`, or a root just beyond the window end makes the caller
//! fall back to the interval method.

use crate::fp::{eval, eval_abs, eval_k, eval_newton, gamma, graze_bound, quadratic, scale_k, Quad};

const POLISH_ITER: usize = 8;

/// Newton polishing of an approximate root of `c`; steps are kept only while |p| decreases.
fn polish(c: &[f64], n: usize, mut x: f64) -> f64 {
    let k = scale_k(x); // one scale for the whole loop, so |p| values compare
    let mut fx = eval_k(c, n, x, k).abs();
    for _ in 0..POLISH_ITER {
        if fx == 0.0 {
            break;
        }
        let (_, step) = eval_newton(c, n, x);
        let xn = x - step;
        if !xn.is_finite() || xn == x {
            break;
        }
        let fxn = eval_k(c, n, xn, k).abs();
        if fxn >= fx {
            break;
        }
        x = xn;
        fx = fxn;
    }
    x
}

/// A few Newton steps on p' from x, towards the critical point of p near x.
fn refine_critical(c: &[f64], n: usize, mut x: f64) -> f64 {
    let mut d = [0.0; 9];
    for i in 0..n {
        d[i] = (i + 1) as f64 * c[i + 1];
    }
    for _ in 0..4 {
        let (_, step) = eval_newton(&d, n - 1, x);
        let xn = x - step;
        if !xn.is_finite() || xn == x {
            break;
        }
        x = xn;
    }
    x
}

/// A polished closed-form root must leave a residual of the order of the evaluation
/// rounding error; this factor (times `gamma_{2n} sum |c_i| |x|^i`) separates genuine roots
/// from spurious ones (a factorisation that converged to the wrong pairing).
const RESIDUAL_FACTOR: f64 = 32.0;

/// Relative distance beyond the window end within which a closed-form root is ambiguous
/// (it may be the window end itself, displaced by rounding).
const EDGE: f64 = 1e-9;

/// Real roots of the monic cubic `x^3 + a x^2 + b x + c` (unpolished).  Returns the roots
/// and, when only one is real, the real part of the other two (a complex pair, or a double
/// root in the degenerate case), which is a graze candidate.
fn cubic_monic(a: f64, b: f64, c: f64, out: &mut [f64; 3]) -> (usize, Option<f64>) {
    let a3 = a / 3.0;
    // depressed: y^3 - 3 Q y + 2 R = 0 with x = y - a/3
    let q = (a3 * a3) - b / 3.0;
    let r = 0.5 * (c + a3 * (2.0 * a3 * a3 - b));
    let q3 = q * q * q;
    let r2 = r * r;
    if r2 < q3 {
        // three real roots (q > 0)
        let sq = q.sqrt();
        let cos_t = (r / (q * sq)).clamp(-1.0, 1.0);
        let theta = cos_t.acos();
        let m = -2.0 * sq;
        let tau = 2.0 * std::f64::consts::PI;
        out[0] = m * (theta / 3.0).cos() - a3;
        out[1] = m * ((theta + tau) / 3.0).cos() - a3;
        out[2] = m * ((theta - tau) / 3.0).cos() - a3;
        (3, None)
    } else {
        let big_a = -(r.abs() + (r2 - q3).sqrt()).cbrt().copysign(r);
        let big_b = if big_a != 0.0 { q / big_a } else { 0.0 };
        let y = big_a + big_b;
        out[0] = y - a3;
        // real part of the other two roots (a double root when r2 == q3)
        (1, Some(-0.5 * y - a3))
    }
}

/// Candidate collector: smallest root in (0, hi], roots preferred over grazes on ties.
/// `doubtful` is set when a root in the window fails the residual test, or a root lies just
/// beyond the window end: the caller then falls back to the interval method.
struct Best {
    t: f64,
    graze: bool,
    found: bool,
    doubtful: bool,
}

impl Best {
    fn new() -> Self {
        Best { t: f64::INFINITY, graze: false, found: false, doubtful: false }
    }
    fn offer(&mut self, t: f64, graze: bool, hi: f64) {
        if t > 0.0 && t <= hi && (t < self.t || (t == self.t && !graze)) {
            self.t = t;
            self.graze = graze;
            self.found = true;
        }
    }
    fn offer_root(&mut self, c: &[f64], n: usize, x: f64, hi: f64) {
        if !x.is_finite() {
            self.doubtful = true;
            return;
        }
        let t = polish(c, n, x);
        if t > hi && t <= hi * (1.0 + EDGE) {
            self.doubtful = true;
        }
        if t > 0.0 && t <= hi && t < self.t {
            let ok = eval(c, n, t).abs() <= RESIDUAL_FACTOR * gamma(2 * n) * eval_abs(c, n, t);
            if !ok {
                self.doubtful = true;
            }
        }
        self.offer(t, false, hi);
    }
    fn offer_graze(&mut self, c: &[f64], n: usize, x: f64, hi: f64) {
        if !(x > 0.0 && x < hi) || x >= self.t {
            return;
        }
        let xc = refine_critical(c, n, x);
        if xc > 0.0 && xc < hi && eval(c, n, xc).abs() <= graze_bound(c, n, xc) {
            self.offer(xc, true, hi);
        }
    }
}

/// Outcome of a closed-form solve: `Err(())` means a non-finite intermediate (fall back).
pub(crate) type Closed = Result<Option<(f64, bool)>, ()>;

fn finish(best: Best) -> Closed {
    if best.doubtful {
        return Err(());
    }
    if best.found {
        if best.t.is_finite() {
            Ok(Some((best.t, best.graze)))
        } else {
            Err(())
        }
    } else {
        Ok(None)
    }
}

/// First root in (0, hi] of the cubic `c[0..=3]`.
pub(crate) fn cubic_first(c: &[f64; 9], hi: f64) -> Closed {
    let (a, b, cc) = (c[2] / c[3], c[1] / c[3], c[0] / c[3]);
    if !(a.is_finite() && b.is_finite() && cc.is_finite()) {
        return Err(());
    }
    let mut r = [0.0; 3];
    let (k, pair) = cubic_monic(a, b, cc, &mut r);
    let mut best = Best::new();
    for &x in &r[..k] {
        best.offer_root(c, 3, x, hi);
    }
    if let Some(re) = pair {
        if !re.is_finite() {
            return Err(());
        }
        best.offer_graze(c, 3, re, hi);
    }
    finish(best)
}

/// Relative residual of the factorisation `(x^2 + p0 x + q0)(x^2 + p1 x + q1)` of the monic
/// quartic `x^4 + a x^3 + b x^2 + c x + d` (sum over the four equations).
fn fact_err(coef: &[f64; 4], v: &[f64; 4]) -> f64 {
    let r = residual(coef, v);
    let mut s = 0.0;
    for i in 0..4 {
        s += if coef[i] != 0.0 { (r[i] / coef[i]).abs() } else { r[i].abs() };
    }
    s
}

/// Residuals of the four factorisation equations, `v = [p0, q0, p1, q1]`, `coef = [a, b, c, d]`.
fn residual(coef: &[f64; 4], v: &[f64; 4]) -> [f64; 4] {
    let [p0, q0, p1, q1] = *v;
    [
        p0 + p1 - coef[0],
        q0 + p0 * p1 + q1 - coef[1],
        p0 * q1 + p1 * q0 - coef[2],
        q0 * q1 - coef[3],
    ]
}

/// Solve the 4x4 system `m x = r` by Gaussian elimination with partial pivoting.
fn solve4(mut m: [[f64; 4]; 4], mut r: [f64; 4]) -> Option<[f64; 4]> {
    for col in 0..4 {
        let mut piv = col;
        for row in col + 1..4 {
            if m[row][col].abs() > m[piv][col].abs() {
                piv = row;
            }
        }
        if m[piv][col] == 0.0 || !m[piv][col].is_finite() {
            return None;
        }
        m.swap(col, piv);
        r.swap(col, piv);
        let pivot_row = m[col];
        for row in col + 1..4 {
            let f = m[row][col] / pivot_row[col];
            for (dst, src) in m[row][col..].iter_mut().zip(&pivot_row[col..]) {
                *dst -= f * src;
            }
            r[row] -= f * r[col];
        }
    }
    let mut x = [0.0; 4];
    for col in (0..4).rev() {
        let mut s = r[col];
        for k in col + 1..4 {
            s -= m[col][k] * x[k];
        }
        x[col] = s / m[col][col];
    }
    Some(x)
}

/// Newton refinement of the factorisation; keeps an iterate only while the error decreases.
fn refine_factors(coef: &[f64; 4], mut v: [f64; 4]) -> [f64; 4] {
    let mut err = fact_err(coef, &v);
    for _ in 0..8 {
        if err == 0.0 {
            break;
        }
        let [p0, q0, p1, q1] = v;
        // rows: d/d(p0, q0, p1, q1) of the four equations
        let jac = [
            [1.0, 0.0, 1.0, 0.0],
            [p1, 1.0, p0, 1.0],
            [q1, p1, q0, p0],
            [0.0, q1, 0.0, q0],
        ];
        let Some(dx) = solve4(jac, residual(coef, &v)) else { break };
        let mut w = v;
        for i in 0..4 {
            w[i] -= dx[i];
        }
        let e = fact_err(coef, &w);
        // (also stops on NaN)
        if e.partial_cmp(&err) != Some(std::cmp::Ordering::Less) {
            break;
        }
        v = w;
        err = e;
    }
    v
}

/// First root in (0, hi] of the quartic `c[0..=4]`.
pub(crate) fn quartic_first(c: &[f64; 9], hi: f64) -> Closed {
    let (a, b, cc, d) = (c[3] / c[4], c[2] / c[4], c[1] / c[4], c[0] / c[4]);
    let coef = [a, b, cc, d];
    // Resolvent cubic y^3 - b y^2 + (a c - 4 d) y - (a^2 d - 4 b d + c^2), largest real root.
    let rc = [-(a * a * d - 4.0 * b * d + cc * cc), a * cc - 4.0 * d, -b, 1.0];
    if rc.iter().any(|v| !v.is_finite()) {
        return Err(());
    }
    let mut r = [0.0; 3];
    let (k, _) = cubic_monic(rc[2], rc[1], rc[0], &mut r);
    let mut y = f64::NEG_INFINITY;
    for &v in &r[..k] {
        y = y.max(v);
    }
    if !y.is_finite() {
        return Err(());
    }
    let y = polish(&rc, 3, y);
    // x^4 + ... = (x^2 + a/2 x + y/2)^2 - (E x + F)^2 with
    // E^2 = a^2/4 - b + y, F^2 = y^2/4 - d, 2 E F = a y / 2 - c.
    let e2 = 0.25 * a * a - b + y;
    let f2 = 0.25 * y * y - d;
    let g = 0.5 * a * y - cc;
    let e = e2.max(0.0).sqrt();
    let f = f2.max(0.0).sqrt().copysign(g);
    let mut cands: [(f64, f64); 3] = [(e, f), (e, f), (e, f)];
    if e != 0.0 {
        cands[1] = (e, g / (2.0 * e));
    }
    if f != 0.0 {
        cands[2] = (g / (2.0 * f), f);
    }
    let mut best_v = [0.0; 4];
    let mut best_err = f64::INFINITY;
    for &(ee, ff) in &cands {
        let v = [0.5 * a + ee, 0.5 * y + ff, 0.5 * a - ee, 0.5 * y - ff];
        let err = fact_err(&coef, &v);
        if err < best_err || best_err.is_infinite() && v.iter().all(|t| t.is_finite()) {
            best_err = err;
            best_v = v;
        }
    }
    if best_v.iter().any(|t| !t.is_finite()) {
        return Err(());
    }
    let v = refine_factors(&coef, best_v);
    let mut best = Best::new();
    for (p, q) in [(v[0], v[1]), (v[2], v[3])] {
        if !(p.is_finite() && q.is_finite()) {
            return Err(());
        }
        match quadratic(1.0, p, q) {
            Quad::Real(r1, r2) => {
                best.offer_root(c, 4, r1, hi);
                best.offer_root(c, 4, r2, hi);
            }
            Quad::Double(re) | Quad::Complex(re) => {
                if !re.is_finite() {
                    return Err(());
                }
                best.offer_graze(c, 4, re, hi);
            }
        }
    }
    finish(best)
}
