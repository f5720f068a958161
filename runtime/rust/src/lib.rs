//! max2code runtime for Rust: the time of next collision, i.e. the smallest root in
//! `(0, tmax]` of a polynomial `c[0] + c[1] t + ... + c[n] t^n` of degree `n <= 16`.
//!
//! The default method ([`Method::Interval`]) is a port of the C runtime's interval solver
//! (`runtime/c/max2code_roots.c`, whose header documents the algorithm and its tolerances),
//! operation for operation: its answers are **bit-identical** to the C runtime's (checked on
//! every hard case, random polynomial and fuzz vector of the test suite).  No dependencies.
//!
//! # Contract
//!
//! * [`first_root_status`] returns [`Status::Root`] with `0 < t <= tmax`, `t` finite;
//!   [`Status::NoRoot`] when there is no root in `(0, tmax]` -- also when the first root is
//!   not representable (it underflows to 0 or overflows); [`Status::Invalid`] for a NaN or
//!   infinite coefficient, more than 17 coefficients, no coefficients, or `tmax` NaN or `<= 0`
//!   (and a contact skin that is NaN, negative or infinite).
//! * [`first_root`] folds invalid input into `None`, as generated code wants ("no collision to
//!   schedule"); [`try_first_root`] tells them apart: `Err(InvalidInput)` for invalid input,
//!   `Ok(None)` for no root.
//! * `tmax = f64::INFINITY` means no upper limit.  All-zero coefficients: no root.
//!
//! # Preparation (as in C)
//!
//! An interval solve without a contact skin whose nonzero coefficients all have one sign
//! (`c[0] != 0`) has no root in `(0, inf)` (Descartes' rule of signs) and returns at once.
//! Else, with `tmax` finite, no skin, degree >= 3 and the preparation bound to keep every term
//! (the exponents show it), the first exclusion test of the interval method (a lower bound on
//! the noise envelope from its Taylor coefficients at 0) runs over all of `[0, tmax]` on the
//! coefficients as given, scaled as below: where it holds there is no root, before the rest of
//! the preparation (a third of a "no root in the window" solve's work).
//! Leading coefficients that are exactly 0, or negligible over the window
//! (`|c_n| T^n <= 4 n eps max_{i<n} |c_i| T^i`, `T = tmax`; with `tmax` infinite `T` is the
//! bound on the positive roots of the polynomial as it stands, and the window becomes `(0, T]`
//! once a term is dropped), are dropped; `c[0] == 0` (touching now) divides by
//! `t`; the coefficients are scaled by a power of two.  At the extremes (coefficients spanning
//! more than `2^1021`) the variable is rescaled by the power of two that spreads them least and
//! terms still below `2^-1022` of the largest are dropped (the documented tolerance).
//!
//! # Grazes and the contact skin
//!
//! A double root (two bodies touching and separating) is a critical point where the polynomial
//! does not change sign; rounding turns it into two close roots or into none.  A critical
//! point before the first sign change where `|p(x)| <= 2 gamma_{2n} sum |c_i| x^i` (the
//! Horner rounding-error bound, safety factor 2) is reported as `Root { t: x, graze: true }`.
//! Whether the sign changes before a critical point is decided there by compensated Horner,
//! as in C: at a touch the sign of the fma Horner value is noise.
//! [`first_root_skin`] adds a contact skin `eps >= 0` (in the units of `c`: distance squared
//! for the shipped equations) to that bound: a near-miss whose minimum is within `eps` counts
//! as contact at the time of closest approach; crossings are unchanged; `eps = 0` is the
//! default.  [`Method::IntervalNoGraze`] skips the check.
//!
//! # Guarantees
//!
//! Never NaN, never a panic, never an unbounded loop (all iterations are capped).

mod closed;
mod count;
mod fp;
mod solver;

use solver::{Coeffs, MAXN};

/// The cost accounting of the C runtime's `-DM2C_COUNT` build, for the control-flow test
/// (feature `count` only; see `src/count.rs`).
#[cfg(feature = "count")]
#[doc(hidden)]
pub use count::take as take_counts;

/// Highest supported degree (so at most `MAX_DEGREE + 1` coefficients).
pub const MAX_DEGREE: usize = MAXN;

/// Outcome of a root search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Status {
    /// The first root in `(0, tmax]`; `graze` marks a double root (tangency) found by the
    /// rounding-error test (or within the contact skin) rather than by a sign change.
    Root { t: f64, graze: bool },
    /// No root in `(0, tmax]` (or the first one is not representable).
    NoRoot,
    /// Bad input: NaN/infinite coefficient, no or more than 17 coefficients, `tmax` NaN or
    /// `<= 0`, a contact skin NaN, negative or infinite.
    Invalid,
}

/// Invalid input (see [`Status::Invalid`]), from [`try_first_root`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct InvalidInput;

impl std::fmt::Display for InvalidInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("invalid input: a NaN or infinite coefficient, no or more than 17 coefficients, \
                     tmax NaN or <= 0, or eps NaN, negative or infinite; for first_roots, a degree \
                     above 16, a length that is not a multiple of degree + 1, or out too short")
    }
}

impl std::error::Error for InvalidInput {}

// BEGIN methods: written from runtime/methods.toml by scripts/runtime-methods
/// Root-finding method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Interval solver with the graze (double root) check: the default.
    #[default]
    Interval,
    /// Interval solver, sign changes only (no graze check).
    IntervalNoGraze,
    /// Closed forms up to degree 4, the interval solver above or if a closed form overflows.
    Closed,
}
// END methods

/// First root of `sum c[i] t^i` in `(0, tmax]` by the interval method; `None` when there is
/// no root or the input is invalid (see [`try_first_root`] to tell them apart).
pub fn first_root(c: &[f64], tmax: f64) -> Option<f64> {
    match solve(c, tmax, Method::Interval, 0.0) {
        Status::Root { t, .. } => Some(t),
        _ => None,
    }
}

/// First root of `sum c[i] t^i` in `(0, tmax]`: `Ok(Some(t))`, `Ok(None)` when there is no
/// root, `Err(InvalidInput)` for invalid input.
pub fn try_first_root(c: &[f64], tmax: f64) -> Result<Option<f64>, InvalidInput> {
    match solve(c, tmax, Method::Interval, 0.0) {
        Status::Root { t, .. } => Ok(Some(t)),
        Status::NoRoot => Ok(None),
        Status::Invalid => Err(InvalidInput),
    }
}

/// First root of `sum c[i] t^i` in `(0, tmax]` with the given method.
pub fn first_root_status(c: &[f64], tmax: f64, method: Method) -> Status {
    solve(c, tmax, method, 0.0)
}

/// The default method with a contact skin `eps >= 0` (see the crate docs); `eps = 0` is
/// [`first_root_status`] with [`Method::Interval`].
pub fn first_root_skin(c: &[f64], tmax: f64, eps: f64) -> Status {
    solve(c, tmax, Method::Interval, eps)
}

/// Batch: the rows of `c` (each `degree + 1` coefficients, `c.len()` a multiple of that)
/// solved as [`first_root_skin`] would; `out[i]` is the root of row `i` or NaN (none, or an
/// invalid row).  Returns the number of roots found, or `Err(InvalidInput)` (nothing written)
/// when `degree > 16`, `c.len()` is not a multiple of `degree + 1` or `out` is too short.
pub fn first_roots(c: &[f64], degree: usize, tmax: f64, eps: f64, out: &mut [f64]) -> Result<usize, InvalidInput> {
    if degree > MAX_DEGREE {
        return Err(InvalidInput); // (before degree + 1, which overflows at usize::MAX)
    }
    let w = degree + 1;
    if c.len() / w * w != c.len() || out.len() < c.len() / w {
        return Err(InvalidInput);
    }
    let mut found = 0;
    for (row, t) in c.chunks_exact(w).zip(out.iter_mut()) {
        *t = match solve(row, tmax, Method::Interval, eps) {
            Status::Root { t, .. } => {
                found += 1;
                t
            }
            _ => f64::NAN,
        };
    }
    Ok(found)
}

/// The C runtime's `solve`: by its copy for the degree where there is one (C's `SOLVE_CLONE`:
/// degrees 2, 4 and 8, where the length of `coef` is a constant in the copy, so that the
/// loading and the early tests are compiled for it), else `solve_core`.
/// (`try_from` tests the length: no panic path.)
fn solve(coef: &[f64], tmax: f64, method: Method, eps: f64) -> Status {
    if let Ok(a) = <&[f64; 9]>::try_from(coef) {
        solve_degree(a, tmax, method, eps)
    } else if let Ok(a) = <&[f64; 5]>::try_from(coef) {
        solve_degree(a, tmax, method, eps)
    } else if let Ok(a) = <&[f64; 3]>::try_from(coef) {
        solve_degree(a, tmax, method, eps)
    } else {
        solve_core(coef, tmax, method, eps)
    }
}

/// `solve_core` for `L` coefficients, out of line as C's clones.
#[inline(never)]
fn solve_degree<const L: usize>(coef: &[f64; L], tmax: f64, method: Method, eps: f64) -> Status {
    solve_core(coef, tmax, method, eps)
}

/// The common path (C `solve_core`).
#[inline(always)]
fn solve_core(coef: &[f64], tmax: f64, method: Method, eps: f64) -> Status {
    if coef.is_empty() || coef.len() > MAX_DEGREE + 1 || tmax.is_nan() || tmax <= 0.0 || !(0.0..f64::INFINITY).contains(&eps) {
        return Status::Invalid;
    }
    let mut c: Coeffs = [0.0; MAXN + 1];
    let mut e = [0i32; MAXN + 1];
    let mut nz = [false; MAXN + 1];
    // the copy, the exponents and their scan in one pass, as C's (a NaN or an infinity: invalid)
    let sc = solver::load_coefficients(coef, &mut c, &mut e, &mut nz);
    if !sc.finite {
        return Status::Invalid;
    }
    count::phase(0);
    count::event(8);
    // where the early exits below apply, as C: the interval methods, no skin, c_0 != 0
    let early = c[0] != 0.0 && eps == 0.0 && matches!(method, Method::Interval | Method::IntervalNoGraze);
    // Descartes on the input, as C: no sign change and c_0 != 0, no root in (0, inf); the
    // interval methods would clear it after the preparation (most of such a solve's cost)
    if early && sc.changes == 0 {
        return Status::NoRoot;
    }
    let degree = coef.len() - 1;
    // Step 0a', as C: AM-GM, with tmax = inf
    if early && degree >= 3 && tmax == f64::INFINITY && solver::outweighed(&c, degree) {
        return Status::NoRoot;
    }
    // Step 0b, as C: the window's first test, before the preparation; where it fails, the
    // window [0, tmax] it failed on (0: not tried), which the default method then does not
    // test again (the no-graze method's test at 0 has no noise envelope: not the same test)
    let mut failed_w = 0.0;
    let mut cleared = None;
    if early && degree >= 3 && tmax < f64::INFINITY {
        cleared = solver::cleared_at_once(&c, &e, &nz, degree, tmax, sc);
        if cleared == Some(true) {
            return Status::NoRoot;
        }
        failed_w = if cleared == Some(false) && method == Method::Interval { tmax } else { 0.0 };
    }
    // (a test step 0b ran -- only where c_n, c_0 != 0 and leading_far shows the leading term
    // far from negligible over [0, tmax] -- means reduce would drop nothing: not repeated)
    let mut tmax = tmax;
    let n = if cleared == Some(false) {
        degree as i32
    } else {
        let every_root = eps > 0.0 && method != Method::IntervalNoGraze;
        solver::reduce(&mut c, &mut e, &mut nz, degree, &mut tmax, every_root, sc.emax)
    };
    if n <= 0 {
        return Status::NoRoot;
    }
    let n = n as usize;
    let (spread, emax) = if n == degree {
        (sc.emax - sc.emin, sc.emax) // reduce dropped nothing
    } else {
        solver::spread(&e, &nz, n)
    };
    let dropped = if n == degree { &coef[..0] } else { solver::dropped_terms(coef, n) };
    let hit = if spread > solver::max_spread() {
        solver::first_root_sliced(&c, n, tmax, eps, method == Method::IntervalNoGraze, dropped)
    } else {
        solve_normalised(&mut c, &e, &nz, n, emax, tmax, method, eps, failed_w, dropped)
    };
    let Some((t, graze)) = hit else {
        return Status::NoRoot;
    };
    if t > 0.0 && t <= tmax && t < f64::INFINITY {
        Status::Root { t, graze }
    } else {
        Status::NoRoot
    }
}

/// C `solve_normalised`: coefficients within 2^MAX_SPREAD, scaled exactly, then by degree and
/// method.  e, nz: the exponents of c before scaling (the root bound depends only on their
/// differences, which scaling by a power of two keeps).  failed_w: the window step 0b tested
/// in vain (0: none).
#[allow(clippy::too_many_arguments)]
fn solve_normalised(c: &mut Coeffs, e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, emax: i32, tu: f64, method: Method, eps: f64, failed_w: f64, dropped: &[f64]) -> Option<(f64, bool)> {
    let closed_form = method == Method::Closed && n <= 4;
    let by_interval = n > 2 && !closed_form;
    // the interval method wants p(0) > 0: p = -c has the same roots (the sign goes into the
    // exact scaling: no pass of its own)
    let sign = if by_interval && c[0] < 0.0 { -1.0 } else { 1.0 };
    let big_e = solver::normalise(c, n, emax, sign);
    // the dropped terms, scaled as c (never_late)
    let mut tail = [0.0; MAXN];
    for (t, &v) in tail.iter_mut().zip(dropped) {
        *t = fp::ldexp(sign * v, -i64::from(big_e));
    }
    let tail = &tail[..dropped.len()];
    let skin = if method == Method::IntervalNoGraze {
        -1.0
    } else if eps == 0.0 {
        0.0
    } else {
        fp::ldexp(eps, -i64::from(big_e))
    };
    match n {
        1 | 2 => {
            let hit = if n == 1 {
                let r = -c[0] / c[1];
                (r > 0.0 && r <= tu).then_some((r, false))
            } else {
                solver::quadratic(c, tu, skin)
            };
            match hit {
                Some(h) if skin >= 0.0 && !tail.is_empty() => Some(solver::late_low_degree(c, n, tail, h)),
                _ => hit,
            }
        }
        3 | 4 if closed_form => {
            let mut c9 = [0.0; 9];
            c9.copy_from_slice(&c[..9]);
            let res = if n == 3 { closed::cubic_first(&c9, tu) } else { closed::quartic_first(&c9, tu) };
            match res {
                Ok(hit) => hit,
                Err(()) => {
                    // (Rust's own fallback, not C's: the sign normalise left to the closed form)
                    let mut flipped = [0.0; MAXN];
                    flipped[..tail.len()].copy_from_slice(tail);
                    if c[0] < 0.0 {
                        c.iter_mut().take(n + 1).for_each(|v| *v = -*v);
                        flipped.iter_mut().for_each(|v| *v = -*v);
                    }
                    interval(c, e, nz, n, tu, skin, 0.0, &flipped[..tail.len()])
                }
            }
        }
        _ => interval(c, e, nz, n, tu, skin, failed_w, tail),
    }
}

/// The interval method on c (normalised, c[0] > 0) over (0, min(tu, the bound on the positive
/// roots)], never later than the first root (without a skin: `solver::never_late`; tail, the
/// terms reduce dropped, scaled as c).
#[allow(clippy::too_many_arguments)]
fn interval(c: &Coeffs, e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, tu: f64, skin: f64, failed_w: f64, tail: &[f64]) -> Option<(f64, bool)> {
    // every positive root below it (with a skin, Fujiwara's on every root, as the skin's
    // contact need not be near a positive root)
    let b = solver::root_bound(e, nz, if skin > 0.0 { None } else { Some(c) }, n);
    let t_end = if tu < b { tu } else { b };
    if t_end > 0.0 {
        let (t, g, scanned) = solver::first_root_interval(c, n, t_end, skin, failed_w)?;
        Some(if skin < 0.0 {
            (t, g)
        } else if scanned && tail.is_empty() {
            solver::late_scanned(c, n, (t, g))
        } else {
            solver::never_late(c, n, tail, (t, g))
        })
    } else {
        None
    }
}

#[cfg(test)]
mod tests;
