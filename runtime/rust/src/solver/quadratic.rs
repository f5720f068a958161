//! The closed form for degree 2 (C: `runtime/c/roots/quadratic.inc`).

use super::*;

/// C `quad_roots`: ascending real roots and the discriminant, or None when it is negative.
pub(crate) fn quad_roots(a: f64, b: f64, c: f64) -> (Option<[f64; 2]>, f64) {
    let m = a.abs().max(b.abs().max(c.abs()));
    let e = -ilogb(m);
    // as C: the scaling by an exact power of two, which rounds as ldexp does (ldexp, a call,
    // only where that power is not a normal number)
    let (a, b, c) = if (-1022..=1023).contains(&e) {
        let f = pow2(e);
        (a * f, b * f, c * f)
    } else {
        let e = i64::from(e);
        (ldexp(a, e), ldexp(b, e), ldexp(c, e))
    };
    let h = -0.5 * b;
    let (p, q) = (h * h, a * c);
    let dp = h.mul_add(h, -p);
    let dq = a.mul_add(c, -q);
    let d = (p - q) + (dp - dq);
    if d < 0.0 {
        return (None, d);
    }
    let w = h + d.sqrt().copysign(h);
    let (r1, r2) = if w == 0.0 { (0.0, 0.0) } else { (w / a, c / w) };
    (Some([r1.min(r2), r1.max(r2)]), d)
}

pub(super) fn first_root_quadratic(c: &[f64], lo: f64, tmax: f64, skin: f64) -> Option<(f64, bool)> {
    let (roots, disc) = quad_roots(c[2], c[1], c[0]);
    if let Some(r) = roots {
        for x in r {
            if x > lo && x <= tmax {
                return Some((x, disc == 0.0));
            }
        }
        return None;
    }
    if skin < 0.0 {
        return None;
    }
    let x = -c[1] / (2.0 * c[2]);
    (x > lo && x <= tmax && within_noise(c, 2, x, skin)).then_some((x, true))
}

/// The quadratic, for the entry point.
pub(crate) fn quadratic(c: &[f64], tmax: f64, skin: f64) -> Option<(f64, bool)> {
    first_root_quadratic(c, 0.0, tmax, skin)
}
