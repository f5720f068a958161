//! The interval solver and its degree-specialised copies (C:
//! `runtime/c/roots/interval.inc`).

use super::*;

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
