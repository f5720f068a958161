//! max2code runtime for Rust: the time of next collision, i.e. the smallest root in
//! `(0, tmax]` of a polynomial `c[0] + c[1] t + ... + c[n] t^n` of degree `n <= 8`.
//!
//! The C and Python runtimes implement the same specification; the four languages agree
//! to within a few units in the last place on well-conditioned roots.  No dependencies.
//!
//! # Pipeline
//!
//! 1. **Validation.**  More than 9 coefficients, a NaN or infinite coefficient, or a `tmax`
//!    that is NaN or `<= 0` gives [`Status::Invalid`].  `tmax = f64::INFINITY` means no upper
//!    limit.  An empty slice or all-zero coefficients give [`Status::NoRoot`].
//! 2. **Degree drop.**  Leading coefficients are dropped while they are exactly zero or
//!    negligible over the window: with `T = tmax` if finite, else a Fujiwara bound of the
//!    remaining coefficients `c[0..n]` on the magnitude of their roots
//!    (`2 max_i |c_i/c_m|^(1/(m-i))`, rounded up to a power of two), `c[n]` is dropped
//!    while `|c[n]| T^n <= 4 n eps max_{i<n} |c[i]| T^i` (`eps = f64::EPSILON`).  The test is
//!    relative — there is no absolute threshold — and a polynomial whose other coefficients
//!    are all zero never loses its leading term.  (When `tmax` is infinite a tiny leading
//!    coefficient only adds roots beyond the bound, which are treated as noise.)
//! 3. **Touching now.**  If `c[0] == 0` exactly, the polynomial is divided by `t` (we want
//!    the next root strictly after 0) and steps 2–3 repeat.  (Exact zeros are removed before
//!    the negligibility test, so that a root at exactly 0 cannot make the bound `T` vanish.)
//! 4. **No positive root.**  If no coefficient has the sign opposite to the leading one,
//!    `p(t)` keeps its sign for all `t > 0` (Descartes) and the answer is `NoRoot`.
//! 5. **Window and scale.**  The coefficients are multiplied by a power of two (exact) so
//!    that the largest lies in `[1, 2)`.  The window is `(0, W]` with `W = min(tmax, B)`, `B`
//!    a power of two strictly above Kioustelidis' bound on the positive roots.  Evaluations
//!    at `|t| > 2^120` scale `t` and the coefficients by exact powers of two, so roots of
//!    magnitude 1e154 and beyond evaluate without overflow.
//! 6. **Solve.**  Degree 1: `-c0/c1`.  Degree 2: robust quadratic with the FMA-corrected
//!    discriminant.  Degree >= 3: [`Method::Interval`] (critical points by recursion on the
//!    derivatives, safeguarded Newton in the first monotone piece with a sign change) or
//!    [`Method::Closed`] for degrees 3 and 4.
//!
//! # Grazes
//!
//! A double root (two bodies touching and separating) is a critical point where the
//! polynomial does not change sign; rounding turns it into two close roots or into none.  With
//! [`Method::Interval`] (and [`Method::Closed`]), a critical point `x` before the first sign
//! change where `|p(x)| <= 2 gamma_{2n} sum |c_i| x^i` (the Horner rounding-error bound with
//! safety factor 2, `gamma_k = k u / (1 - k u)`, `u = 2^-53`) and where `p` has the same sign
//! on both sides is reported as `Root { t: x, graze: true }`.  For a quadratic the critical
//! point is the vertex `-b/2a` when the discriminant is negative.
//! [`Method::IntervalNoGraze`] skips this rounding-error test, so it misses double roots
//! that rounding turned into a complex pair.  Every method reports an *exact* zero at a
//! critical point (and an exactly zero quadratic discriminant) as a root, flagged as a graze
//! unless `p` changes sign across it (the C runtime flags these as grazes unconditionally;
//! the difference only shows for a crossing of odd multiplicity >= 3 that rounds to an exact
//! zero).
//!
//! # Guarantees
//!
//! Never NaN, never a panic, never an unbounded loop (all iterations are capped).  A root that
//! would overflow (beyond `f64::MAX`, only possible with `tmax = inf`) or underflow to 0 is
//! not reported.

mod closed;
mod fp;
mod interval;

use fp::{ilogb, ldexp, quadratic, Quad};

/// Highest supported degree (so at most `MAX_DEGREE + 1` coefficients).
pub const MAX_DEGREE: usize = 8;

/// Outcome of a root search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Status {
    /// The first root in `(0, tmax]`; `graze` marks a double root (tangency) found by the
    /// rounding-error test rather than by a sign change.
    Root { t: f64, graze: bool },
    /// No root in `(0, tmax]`.
    NoRoot,
    /// Bad input: NaN/infinite coefficient, more than 9 coefficients, `tmax` NaN or `<= 0`.
    Invalid,
}

/// Root-finding method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Interval method with graze detection (the default, used by [`first_root`]).
    #[default]
    Interval,
    /// Interval method, sign changes only.
    IntervalNoGraze,
    /// Closed forms up to degree 4 (robust quadratic, Cardano cubic, refined Ferrari quartic);
    /// the interval method above degree 4 or if a closed form overflows.
    Closed,
}

/// First root of `sum c[i] t^i` in `(0, tmax]` by the interval method; `None` when there is
/// no root or the input is invalid.
pub fn first_root(c: &[f64], tmax: f64) -> Option<f64> {
    match first_root_status(c, tmax, Method::Interval) {
        Status::Root { t, .. } => Some(t),
        _ => None,
    }
}

/// First root of `sum c[i] t^i` in `(0, tmax]` with the given method.
pub fn first_root_status(c: &[f64], tmax: f64, method: Method) -> Status {
    if c.len() > MAX_DEGREE + 1 || tmax.is_nan() || tmax <= 0.0 || c.iter().any(|v| !v.is_finite()) {
        return Status::Invalid;
    }
    let Some(p) = prepare(c, tmax) else {
        return Status::NoRoot;
    };
    let graze = method != Method::IntervalNoGraze;
    let hit = match p.n {
        1 => {
            let r = -p.c[0] / p.c[1];
            (r > 0.0 && r <= p.hi).then_some((r, false))
        }
        2 => quadratic_first(&p.c, p.hi, graze),
        3 | 4 if method == Method::Closed => {
            let res = if p.n == 3 {
                closed::cubic_first(&p.c, p.hi)
            } else {
                closed::quartic_first(&p.c, p.hi)
            };
            match res {
                Ok(hit) => hit,
                Err(()) => interval::first_root(&p.c, p.n, p.hi, true),
            }
        }
        _ => interval::first_root(&p.c, p.n, p.hi, graze),
    };
    match hit {
        Some((t, g)) => {
            if t > 0.0 && t <= tmax && t.is_finite() {
                Status::Root { t, graze: g }
            } else {
                Status::NoRoot
            }
        }
        None => Status::NoRoot,
    }
}

/// First root in `(0, hi]` of the quadratic `c[0..=2]` (`c[2] != 0`, `c[0] != 0`).
fn quadratic_first(c: &[f64; 9], hi: f64, graze: bool) -> Option<(f64, bool)> {
    let inside = |r: f64| r > 0.0 && r <= hi;
    match quadratic(c[2], c[1], c[0]) {
        Quad::Real(r1, r2) => {
            if inside(r1) {
                Some((r1, false))
            } else if inside(r2) {
                Some((r2, false))
            } else {
                None
            }
        }
        Quad::Double(x) => inside(x).then_some((x, true)),
        Quad::Complex(x) => (graze
            && inside(x)
            && fp::eval(c, 2, x).abs() <= fp::graze_bound(c, 2, x))
        .then_some((x, true)),
    }
}

/// The polynomial after degree reduction and normalisation: `n >= 1`, `c[0] != 0`,
/// `c[n] != 0`, largest coefficient in `[1, 2)`, window `(0, hi]`.
struct Prepared {
    c: [f64; 9],
    n: usize,
    hi: f64,
}

/// Fujiwara-type bound on the magnitude of the roots of `c[0..=m]` (`c[m] != 0`, `m >= 1`):
/// `2 max_i |c[i]/c[m]|^(1/(m-i))`, each ratio rounded up to a power of two from the
/// exponents alone (no overflow, no logarithms), so the result is a power of two (or
/// `f64::MAX`) and every root `z` has `|z| <` it.  Same formula as the C runtime.
fn root_bound(c: &[f64], m: usize) -> f64 {
    let em = ilogb(c[m]) as i64;
    let best = c[..m]
        .iter()
        .enumerate()
        .filter(|(_, v)| **v != 0.0)
        .map(|(i, v)| {
            // |c_i / c_m| < 2^r; ceil(r / (m - i))
            let r = ilogb(*v) as i64 + 1 - em;
            let k = (m - i) as i64;
            r.div_euclid(k) + i64::from(r.rem_euclid(k) != 0)
        })
        .max();
    match best {
        None => 0.0,
        Some(b) if b + 1 > 1023 => f64::MAX,
        Some(b) => ldexp(1.0, b + 1),
    }
}

/// Is the leading coefficient `c[n]` negligible over `(0, T]` (see the crate docs)?
fn negligible_lead(c: &[f64], n: usize, tmax: f64) -> bool {
    let t = if tmax.is_finite() {
        tmax
    } else {
        // bound on the roots of the remaining coefficients
        let Some(m) = (0..n).rev().find(|&i| c[i] != 0.0) else {
            return false; // c[n] t^n alone: nothing to compare with
        };
        if m == 0 {
            return false; // remaining polynomial is a constant: c[n] decides the roots
        }
        root_bound(c, m)
    };
    let k = 4.0 * n as f64 * f64::EPSILON;
    let lead = c[n].abs();
    // |c[n]| T^n <= k max_i |c[i]| T^i  <=>  exists i: |c[n]| T^(n-i) <= k |c[i]|
    (0..n).any(|i| {
        if c[i] == 0.0 {
            return false;
        }
        let mut lhs = lead;
        for _ in i..n {
            lhs *= t;
        }
        lhs <= k * c[i].abs()
    })
}

/// Steps 2–5 of the pipeline; `None` means no root.
fn prepare(coef: &[f64], tmax: f64) -> Option<Prepared> {
    let mut c = [0.0; 9];
    c[..coef.len()].copy_from_slice(coef);
    // Exact power-of-two normalisation so that the degree-drop test cannot under/overflow.
    let top = coef.iter().filter(|v| **v != 0.0).map(|v| ilogb(*v)).max()?;
    for v in c.iter_mut() {
        *v = ldexp(*v, -(top as i64));
    }
    let mut n = coef.len() - 1;
    // Each pass either returns or lowers n, so this loop runs at most 9 times.
    loop {
        while n > 0 && c[n] == 0.0 {
            n -= 1;
        }
        if n == 0 {
            return None;
        }
        if c[0] == 0.0 {
            shift_down(&mut c, &mut n);
            continue;
        }
        // (after the division by t: roots at exactly 0 would make the bound T vanish)
        if negligible_lead(&c, n, tmax) {
            n -= 1;
            continue;
        }
        // Descartes: no sign opposite to the leading coefficient -> no positive root.
        let lead_neg = c[n] < 0.0;
        let opposite = |v: f64| if lead_neg { v > 0.0 } else { v < 0.0 };
        if !c[..n].iter().any(|v| opposite(*v)) {
            return None;
        }
        // Kioustelidis: positive roots < 2 max_{c_i opposite} (|c_i|/|c_n|)^(1/(n-i)) < 2^eb.
        let ln = ilogb(c[n]) as i64;
        let mut eb = i64::MIN;
        for (i, v) in c[..n].iter().enumerate() {
            if opposite(*v) {
                let r = ilogb(*v) as i64 + 1 - ln; // |c_i|/|c_n| < 2^r
                let k = (n - i) as i64;
                eb = eb.max(r.div_euclid(k) + i64::from(r.rem_euclid(k) != 0) + 1);
            }
        }
        // Window (0, W], W = min(tmax, 2^eb).
        let bound = if eb > 1023 { f64::MAX } else { ldexp(1.0, eb) };
        return Some(Prepared { c, n, hi: tmax.min(bound) });
    }
}

/// Divide by t: `c[i] <- c[i+1]`, degree n-1.
fn shift_down(c: &mut [f64; 9], n: &mut usize) {
    c.copy_within(1..=*n, 0);
    c[*n] = 0.0;
    *n -= 1;
}

#[cfg(test)]
mod tests;
