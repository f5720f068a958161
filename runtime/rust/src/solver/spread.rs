//! Coefficients spanning more than 2^MAX_SPREAD, solved by slices (C:
//! `runtime/c/roots/spread.inc`).

use super::*;

const SLICE: i32 = 32;
const DOMINANCE: i32 = 6;

/// C `dominant_term`: the term that beats every other by 2^DOMINANCE at t = 2^d.
fn dominant_term(e: &[i32; MAXN + 1], nz: &[bool; MAXN + 1], n: usize, d: i32) -> Option<usize> {
    let (mut best, mut top, mut second) = (None, i32::MIN, i32::MIN);
    for i in 0..=n {
        if !nz[i] {
            continue;
        }
        let v = e[i] + d * i as i32;
        if v > top {
            second = top;
            top = v;
            best = Some(i);
        } else if v > second {
            second = v;
        }
    }
    if second == i32::MIN || top - second >= DOMINANCE {
        best
    } else {
        None
    }
}

/// C `first_root_sliced`: coefficients spanning more than 2^MAX_SPREAD, solved slice by slice
/// of t (see the C runtime); c has c[0] != 0 and is not normalised; dropped: the leading terms
/// reduce dropped, in c's units, for never_late.
pub(crate) fn first_root_sliced(c: &[f64], n: usize, tmax: f64, eps: f64, nograze: bool, dropped: &[f64]) -> Option<(f64, bool)> {
    let mut e = [0i32; MAXN + 1];
    let mut nz = [false; MAXN + 1];
    let (_, emax) = exponents(c, n, &mut e, &mut nz);
    let lo = pow2(-16);
    let lo_open = f64::from_bits(lo.to_bits() - 1);
    let hi = pow2(16);
    let mut d = (e[0] - emax - 2).div_euclid(SLICE) * SLICE;
    while d < 1024 {
        if d >= -1074 && ldexp(1.0, i64::from(d)) >= tmax {
            return None;
        }
        let v = dominant_term(&e, &nz, n, d);
        if v.is_some() && v == dominant_term(&e, &nz, n, d + SLICE) {
            d += SLICE;
            continue;
        }
        let k = d + SLICE / 2;
        let mut top = i32::MIN;
        for i in 0..=n {
            if nz[i] {
                top = top.max(e[i] + k * i as i32);
            }
        }
        let mut q = [0.0f64; MAXN + 1];
        for i in 0..=n {
            q[i] = if nz[i] { ldexp(c[i], i64::from(k * i as i32 - top - 1)) } else { 0.0 };
            if q[i].abs() < f64::MIN_POSITIVE {
                q[i] = 0.0;
            }
        }
        let mut m = n;
        while m > 0 && q[m] == 0.0 {
            m -= 1;
        }
        if m > 0 {
            let tu = ldexp(tmax, -i64::from(k));
            let t_end = if tu < hi { tu } else { hi };
            let skin = if nograze {
                -1.0
            } else if eps == 0.0 {
                0.0
            } else {
                ldexp(eps, -i64::from(top + 1))
            };
            let hit = match m {
                1 => {
                    let r = -q[0] / q[1];
                    (r > lo_open && r <= t_end).then_some((r, false))
                }
                2 => first_root_quadratic(&q, lo_open, t_end, skin),
                _ => {
                    let mut s = sign_at(&q, m, lo, true);
                    // within its noise at lo the fma sign may be noise: the precise value
                    // decides (C says why)
                    if s != 0 && within_noise(&q, m, lo, 0.0) {
                        let pc = horner_compensated(&q, m, lo);
                        if pc != 0.0 {
                            s = if pc > 0.0 { 1 } else { -1 };
                        }
                    }
                    if s < 0 {
                        for v in q.iter_mut().take(m + 1) {
                            *v = -*v;
                        }
                    }
                    if s == 0 {
                        Some((lo, false))
                    } else {
                        // never later than the first root, as unsliced (C says why)
                        let sign = if s < 0 { -1.0 } else { 1.0 };
                        // and at the slice's end: the next slice starts from the precise
                        // sign there (C says why)
                        derivative_method(&q, m, lo, t_end, 0.0, skin).or_else(|| {
                            (scale_exponent(t_end, m) == 0
                                && within_noise(&q, m, t_end, 0.0)
                                && horner_compensated(&q, m, t_end) < 0.0)
                                .then_some((t_end, false))
                        })
                        .map(|h| {
                            if skin < 0.0 {
                                h
                            } else if dropped.is_empty() {
                                late_scanned(&q, m, h)
                            } else {
                                late_sliced_tail(&q, m, n, dropped, k, top, sign, h)
                            }
                        })
                    }
                }
            };
            if let Some((r, g)) = hit {
                // a root at or above half the least subnormal rounds up to it (C says why)
                let t = ldexp(r, i64::from(k));
                if t == 0.0 && r >= ldexp(1.0, -1075 - i64::from(k)) {
                    return Some((f64::from_bits(1), g));
                }
                return Some((t, g));
            }
        }
        d += SLICE;
    }
    None
}
