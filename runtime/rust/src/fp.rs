//! Floating-point helpers: exact power-of-two scaling, Horner evaluation, error bounds.

/// Unit roundoff of binary64, u = 2^-53.
pub(crate) const U: f64 = f64::EPSILON / 2.0;

/// Safety factor applied to the Horner error bound in the graze test.
///
/// The Horner bound `gamma_{2n} * sum |c_i| |x|^i` covers the rounding of the evaluation
/// itself.  Two further errors of the same order are present in practice: the coefficients
/// arrive already rounded (each carries a relative error of at least `u`, usually a few `u`
/// from the generated expression), and the critical point is itself only located to within
/// rounding.  A factor of 2 covers both without turning clear misses into grazes.
pub(crate) const GRAZE_SAFETY: f64 = 2.0;

/// `gamma_k = k u / (1 - k u)` (Higham, Accuracy and Stability, sec. 3.1).
#[inline]
pub(crate) fn gamma(k: usize) -> f64 {
    let ku = k as f64 * U;
    ku / (1.0 - ku)
}

/// Exponent of a finite non-zero double: `2^e <= |x| < 2^(e+1)` (also for subnormals).
/// Returns `i32::MIN / 4` for zero so that callers can treat it as "very small".
#[inline]
pub(crate) fn ilogb(x: f64) -> i32 {
    let bits = x.to_bits() & 0x7fff_ffff_ffff_ffff;
    if bits == 0 {
        return i32::MIN / 4;
    }
    let exp = (bits >> 52) as i32;
    if exp == 0 {
        // subnormal: value = m * 2^-1074
        let m = bits & ((1u64 << 52) - 1);
        (63 - m.leading_zeros() as i32) - 1074
    } else {
        exp - 1023
    }
}

/// `2^k` for `-1074 <= k <= 1023`, exactly (subnormal powers included).
#[inline]
fn pow2(k: i32) -> f64 {
    debug_assert!((-1074..=1023).contains(&k));
    if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (k + 1074))
    }
}

/// `x * 2^k` without intermediate overflow or double rounding: exact unless the result
/// is subnormal (one rounding), overflows (±inf) or underflows (±0).
///
/// Never inlined (C's is a libm call): the solver calls it only off its hot paths, and
/// inlined there, its bit tricks were hoisted into the Newton loop and computed on every step.
#[inline(never)]
pub(crate) fn ldexp(x: f64, k: i64) -> f64 {
    if x == 0.0 || !x.is_finite() || k == 0 {
        return x;
    }
    // Normalise x to m in [1, 2) exactly.
    let mut m = x;
    let mut ex = ilogb(m);
    if ex < -1022 {
        m *= pow2(64);
        ex = ilogb(m);
        m *= pow2(-ex);
        ex -= 64;
    } else {
        m *= pow2(-ex);
    }
    let target = ex as i64 + k;
    if target > 1023 {
        return f64::INFINITY.copysign(x);
    }
    if target < -1076 {
        return 0.0f64.copysign(x);
    }
    let t = target as i32;
    if t >= -1022 {
        m * pow2(t)
    } else {
        // one rounding, into the subnormal range
        (m * pow2(-1022)) * pow2(t + 1022)
    }
}

/// Evaluations at |x| above this are scaled (see [`scale_k`]).
const SCALE_LIMIT: f64 = 1.329_227_995_784_916e36; // 2^120

/// Exponent k such that evaluating at `x / 2^k` cannot overflow: 0 for |x| <= 2^120.
/// (Coefficients are normalised to at most 2 in magnitude and n <= 8.)
#[inline]
pub(crate) fn scale_k(x: f64) -> i32 {
    if x.abs() <= SCALE_LIMIT {
        0
    } else {
        ilogb(x) + 1
    }
}

/// Horner evaluation of `p(x) / 2^(k n)` (plain multiply-add, no FMA, so that the result
/// is the same in every language without FMA and the bound `gamma_{2n}` applies).  With
/// `k != 0` the argument and the coefficients are scaled by exact powers of two, so roots
/// near 1e154 and beyond evaluate without overflow; the sign is that of `p(x)`.
#[inline]
pub(crate) fn eval_k(c: &[f64], n: usize, x: f64, k: i32) -> f64 {
    let mut p = c[n];
    let mut i = n;
    if k == 0 {
        while i > 0 {
            i -= 1;
            p = p * x + c[i];
        }
    } else {
        let xs = ldexp(x, -(k as i64));
        let f = ldexp(1.0, -(k as i64));
        let mut fi = 1.0;
        while i > 0 {
            i -= 1;
            fi *= f;
            p = p * xs + c[i] * fi;
        }
    }
    p
}

/// `p(x)`, scaled by `2^-(k n)` with `k = scale_k(x)` (only for |x| > 2^120).
#[inline]
pub(crate) fn eval(c: &[f64], n: usize, x: f64) -> f64 {
    eval_k(c, n, x, scale_k(x))
}

/// `(p(x) / 2^(k n), p(x) / p'(x))`: the (scaled) value and the Newton step.
#[inline]
pub(crate) fn eval_newton(c: &[f64], n: usize, x: f64) -> (f64, f64) {
    let k = scale_k(x);
    let (xs, f) = if k == 0 { (x, 1.0) } else { (ldexp(x, -(k as i64)), ldexp(1.0, -(k as i64))) };
    let mut p = c[n];
    let mut d = 0.0;
    let mut fi = 1.0;
    let mut i = n;
    while i > 0 {
        i -= 1;
        fi *= f;
        d = d * xs + p;
        p = p * xs + c[i] * fi;
    }
    // p = P(x)/2^(kn), d = P'(x)/2^(k(n-1)): P/P' = (p/d) 2^k
    let step = p / d;
    (p, if k == 0 { step } else { ldexp(step, k as i64) })
}

/// `sum |c_i| |x|^i`, scaled like [`eval`] at the same x: the scale of its rounding error.
#[inline]
pub(crate) fn eval_abs(c: &[f64], n: usize, x: f64) -> f64 {
    let k = scale_k(x);
    let (ax, f) = if k == 0 {
        (x.abs(), 1.0)
    } else {
        (ldexp(x.abs(), -(k as i64)), ldexp(1.0, -(k as i64)))
    };
    let mut p = c[n].abs();
    let mut fi = 1.0;
    let mut i = n;
    while i > 0 {
        i -= 1;
        fi *= f;
        p = p * ax + c[i].abs() * fi;
    }
    p
}

/// Graze threshold at x for a degree-n polynomial: `GRAZE_SAFETY * gamma_{2n} * sum|c_i||x|^i`
/// (scaled like [`eval`] at the same x, so the two compare directly).
#[inline]
pub(crate) fn graze_bound(c: &[f64], n: usize, x: f64) -> f64 {
    GRAZE_SAFETY * gamma(2 * n) * eval_abs(c, n, x)
}



/// Robust real roots of `a x^2 + b x + c` (a != 0).
///
/// The discriminant is computed with Kahan's FMA correction: the exact rounding errors of
/// `b*b` and `4ac` are recovered with `mul_add` and added back, so that a discriminant that
/// is small compared with `b^2` keeps its leading digits.  The roots are formed without
/// cancellation (`q = -(b + sign(b) sqrt(disc))/2`, roots `q/a` and `c/q`).
pub(crate) enum Quad {
    /// Two real roots, sorted ascending (they may be equal).
    Real(f64, f64),
    /// Discriminant exactly zero: the double root `-b/(2a)`.
    Double(f64),
    /// Negative discriminant: no real root; the vertex `-b/(2a)` is returned.
    Complex(f64),
}

pub(crate) fn quadratic(a: f64, b: f64, c: f64) -> Quad {
    let bb = b * b;
    let ebb = b.mul_add(b, -bb);
    let a4 = 4.0 * a;
    let ac4 = a4 * c;
    let eac = a4.mul_add(c, -ac4);
    let disc = (bb - ac4) + (ebb - eac);
    let vertex = -b / (2.0 * a);
    if disc > 0.0 {
        let s = disc.sqrt();
        let q = -0.5 * (b + s.copysign(b));
        let r1 = q / a;
        let r2 = if q != 0.0 { c / q } else { r1 };
        if r1 <= r2 {
            Quad::Real(r1, r2)
        } else {
            Quad::Real(r2, r1)
        }
    } else if disc == 0.0 {
        Quad::Double(vertex)
    } else if disc.is_nan() {
        // only reachable through overflow; report no real root
        Quad::Complex(f64::NAN)
    } else {
        Quad::Complex(vertex)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ilogb_and_ldexp() {
        assert_eq!(ilogb(1.0), 0);
        assert_eq!(ilogb(1.5), 0);
        assert_eq!(ilogb(0.75), -1);
        assert_eq!(ilogb(f64::MAX), 1023);
        assert_eq!(ilogb(f64::MIN_POSITIVE), -1022);
        assert_eq!(ilogb(f64::from_bits(1)), -1074);
        assert_eq!(ldexp(1.0, 1023), pow2(1023));
        assert_eq!(ldexp(3.0, -1074), f64::from_bits(3));
        assert_eq!(ldexp(f64::MAX, -2000), f64::MAX * pow2(-1000) * pow2(-1000));
        assert_eq!(ldexp(f64::from_bits(1), 2000), pow2(-1074 + 2000));
        assert_eq!(ldexp(1e300, 100), f64::INFINITY);
        assert_eq!(ldexp(-1e-300, -100), -0.0);
        assert_eq!(ldexp(0.7, 5), 0.7 * 32.0);
    }
}
