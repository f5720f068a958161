//! The interval solver of the C runtime (`runtime/c/max2code_roots.c`), ported operation for
//! operation: the same preparation, Budan-Fourier isolation with certified signs, derivative
//! (Yuksel) method for what the counts do not resolve, and safeguarded Newton polished with
//! compensated Horner.  Every floating-point operation is the C one in the same order (`fma`
//! is `mul_add`, both correctly rounded; the C runtime is compiled without contraction, as
//! `-std=c11` does), so the results are bit-identical to the C runtime's; the cross-language
//! tests check that on every hard case, random polynomial and fuzz vector.
//!
//! The comments of the C source explain the why of each step; they are not repeated here.

// Indexed loops and negated comparisons mirror the C source line by line (a negated
// comparison is also true for NaN, which the C code relies on).
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

use std::mem::MaybeUninit;

use crate::count;
use crate::fp::{ilogb, ldexp};

pub(crate) const MAXN: usize = 16;
const U: f64 = f64::EPSILON / 2.0;
const SAFE_LOW: f64 = 1.329_227_995_784_916e36; // 2^120
const SAFE_HIGH: f64 = 1.152_921_504_606_847e18; // 2^60
const FAST_LIMIT_LOW: f64 = 1.267_650_600_228_229_4e30; // 2^100
const FAST_LIMIT_HIGH: f64 = 7.205_759_403_792_794e16; // 2^56
const MAX_ITER: usize = 200;
/// After this many iterations a Newton step that moves x by over 2^-10 of it in a bracket
/// spanning more than a factor 8 is replaced by a geometric bisection (from lo = 0: hi / 2^64):
/// far from every root Newton converges only linearly (see the C runtime).
const SLOW_AFTER: usize = 16;
const TOL_CRITICAL: f64 = 1.455_191_522_836_685_2e-11; // 2^-36
const TOL_LEVEL: f64 = 3.725_290_298_461_914e-9; // 2^-28
const PRECISE_FROM: f64 = 1.490_116_119_384_765_6e-8; // 2^-26
/// C `GUESS_DONE`, `GUESS_FAST`: the guess's Laguerre also stops after a step below GUESS_DONE
/// (relative) that was at most GUESS_FAST of the step before.
const GUESS_DONE: f64 = 6.103_515_625e-5; // 2^-14
const GUESS_FAST: f64 = 0.0625; // 2^-4
const NOISE_STEP: f64 = 32.0 * U;
const MAX_SPLITS: usize = 40;
const SPLIT_NEWTON: f64 = 2.0;
const MIN_WIDTH: f64 = 9.536_743_164_062_5e-7; // 2^-20
const EARLY_WIDTH: f64 = 0.25;
const MAX_SPREAD: i32 = 1021;

pub(crate) type Coeffs = [f64; MAXN + 1];

// The parts, one file each in solver/, as the C runtime's roots/*.inc and in their order.
// Each part starts with `use super::*`: the shared names above and, through the globs below,
// the other parts' `pub(super)` items (the ones used across parts).
mod prepare;    // validation, exponents, root bounds, reduce, normalise
mod evaluate;   // Horner (scaled, the fma dispatch), the noise factors, signs
mod quadratic;  // the closed form for degree 2
mod newton;     // compensated Horner, touch values, safeguarded Newton
mod bernstein;  // Budan-Fourier points, Taylor tables, the Bernstein tests
mod isolate;    // Laguerre's guess and the Budan-Fourier bisection
mod derivative; // the derivative method, its scan, touches and their certificates
mod interval;   // the interval solver and its degree-specialised copies
mod spread;     // coefficients spanning more than 2^MAX_SPREAD, solved by slices
mod early;      // the early exits before the preparation (steps 0a', 0b)
mod never_late; // never later than the first root: the rounding-band certificates

use prepare::*;
use evaluate::*;
use quadratic::*;
use newton::*;
use bernstein::*;
use isolate::*;
use derivative::*;
use never_late::*;

// What lib.rs (the entry points) and the crate's tests call.
pub(crate) use prepare::{load_coefficients, max_spread, normalise, reduce, root_bound, spread};
pub(crate) use early::{cleared_at_once, outweighed};
pub(crate) use evaluate::noise_factor;
pub(crate) use quadratic::{quad_roots, quadratic};
pub(crate) use never_late::{dropped_terms, late_low_degree, late_scanned, never_late};
pub(crate) use interval::first_root_interval;
pub(crate) use spread::first_root_sliced;

#[cfg(test)]
mod check {
    #[test]
    fn binomials() {
        for k in 0..=super::MAXN {
            for j in 0..=super::MAXN - k {
                assert_eq!(super::BINOM[k][j], super::binom(k, j));
            }
        }
        assert_eq!(super::BINOM[8][8], 12870.0);
    }
}

#[cfg(test)]
mod ceil {
    #[test]
    fn ceil_div_is_the_ceiling() {
        // every den and every num of the documented domain (|num| < 2^12)
        for den in 1..=16 {
            for num in -4095..=4095 {
                assert_eq!(super::ceil_div(num, den), num.div_euclid(den) + i32::from(num.rem_euclid(den) != 0), "{num} / {den}");
            }
        }
    }
}

#[cfg(test)]
mod preparation {
    use super::{load_coefficients, root_bound, Coeffs, Scan, MAXN};

    #[test]
    fn inverse_binomials_are_the_rounded_quotients() {
        // against C(n, k) from the product formula and a division at run time
        for n in 0..=MAXN {
            let mut c = 1u64;
            for k in 0..=n {
                let q = std::hint::black_box(1.0) / c as f64;
                assert_eq!(super::INV_BINOM[n][k].to_bits(), q.to_bits(), "1 / C({n}, {k})");
                c = c * (n - k) as u64 / (k + 1) as u64;
            }
        }
        assert_eq!(super::INV_BINOM[16][8], 1.0 / 12870.0);
    }

    #[test]
    fn exponents_from_the_bits() {
        let src = [1.0, -0.75, 0.0, -0.0, 5e-324, 3.0e-310, f64::MAX, -f64::MIN_POSITIVE];
        let (mut c, mut e, mut nz): (Coeffs, _, _) = ([9.0; MAXN + 1], [9; MAXN + 1], [true; MAXN + 1]);
        assert!(load_coefficients(&src, &mut c, &mut e, &mut nz).finite);
        assert_eq!(&c[..src.len()], &src);
        assert_eq!(&e[..src.len()], &[0, -1, 0, 0, -1074, -1029, 1023, -1022]);
        assert_eq!(&nz[..src.len()], &[true, true, false, false, true, true, true, true]);
        // 3.0e-310 is in [2^-1029, 2^-1028) (subnormals: 2^k = bit 1074 + k)
        assert!(f64::from_bits(1 << 45) <= 3.0e-310 && 3.0e-310 < f64::from_bits(1 << 46));
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert!(!load_coefficients(&[1.0, bad, 2.0], &mut c, &mut e, &mut nz).finite);
        }
    }

    /// The plain definition of the scan: `2^e <= |x| < 2^(e + 1)` by comparison with exact
    /// powers of two (subnormal ones included), sign changes between consecutive nonzero
    /// coefficients (x == 0.0 is true for -0.0 too).
    fn plain_scan(src: &[f64]) -> Scan {
        let pow2 = |k: i32| if k >= -1022 { f64::from_bits(((k + 1023) as u64) << 52) } else { f64::from_bits(1u64 << (k + 1074)) };
        let (mut emax, mut emin, mut changes, mut last) = (i32::MIN, i32::MAX, 0, 0);
        for &x in src {
            if x == 0.0 {
                continue;
            }
            let a = x.abs();
            let mut k = (a.log2().floor() as i32).clamp(-1074, 1023);
            while pow2(k) > a {
                k -= 1;
            }
            while k < 1023 && pow2(k + 1) <= a {
                k += 1;
            }
            emax = emax.max(k);
            emin = emin.min(k);
            let s = if x > 0.0 { 1 } else { -1 };
            changes += i32::from(last != 0 && s != last);
            last = s;
        }
        Scan { finite: true, emax, emin, changes }
    }

    #[test]
    fn scan_is_the_plain_definition() {
        let (mut c, mut e, mut nz): (Coeffs, _, _) = ([0.0; MAXN + 1], [0; MAXN + 1], [false; MAXN + 1]);
        let mut scan = |src: &[f64]| load_coefficients(src, &mut c, &mut e, &mut nz);
        // zeros of both signs are skipped: -0.0 is no negative coefficient
        let fixed: [(&[f64], i32, i32, i32); 8] = [
            (&[1.0, -0.0, 2.0], 1, 0, 0),
            (&[-1.0, 0.0, -0.0, -3.0], 1, 0, 0),
            (&[-0.0, 1.0, -1.0], 0, 0, 1),
            (&[0.5, 0.0, -0.0, -4.0, 0.0, 8.0], 3, -1, 2),
            (&[5e-324, -f64::MAX], 1023, -1074, 1),
            (&[-0.0], i32::MIN, i32::MAX, 0),
            (&[0.0, -0.0, 0.0], i32::MIN, i32::MAX, 0),
            (&[-2.0], 1, 1, 0),
        ];
        for (src, emax, emin, changes) in fixed {
            assert_eq!(scan(src), Scan { finite: true, emax, emin, changes }, "{src:?}");
        }
        // random coefficients over the whole range, one in four a zero of either sign
        let mut s = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for trial in 0..20000 {
            let n = trial % (MAXN + 1);
            let src: Vec<f64> = (0..=n)
                .map(|_| {
                    let r = next();
                    match r % 8 {
                        0 => 0.0,
                        1 => -0.0,
                        // any finite bit pattern: normal and subnormal, either sign
                        _ => {
                            let x = f64::from_bits(r >> 3 | (r & 1) << 63);
                            if x.is_finite() { x } else { 1.5 }
                        }
                    }
                })
                .collect();
            assert_eq!(scan(&src), plain_scan(&src), "{src:?}");
        }
    }

    #[test]
    fn root_bound_bounds_the_roots() {
        // (t - 3)(t + 5)(t - 0.25) = t^3 + 1.75 t^2 - 15.5 t + 3.75: |c_1 / c_3| < 2^4 gives
        // 2^(ceil(4 / 2) + 1) = 8, above the largest root (5); the other terms give less
        let src = [3.75, -15.5, 1.75, 1.0];
        let (mut c, mut e, mut nz): (Coeffs, _, _) = ([0.0; MAXN + 1], [0; MAXN + 1], [false; MAXN + 1]);
        assert!(load_coefficients(&src, &mut c, &mut e, &mut nz).finite);
        assert_eq!(root_bound(&e, &nz, None, 3), 8.0);
        // on the positive roots (3, 0.25) only c_1 counts, the one term of the sign opposite
        // to c_3's: the same 8 here; with c_1 > 0, (t + 3)(t + 5)(t + 0.25) has no sign
        // change and no bound
        assert_eq!(root_bound(&e, &nz, Some(&c), 3), 8.0);
        let pos = [3.75, 23.0, 8.25, 1.0];
        assert!(load_coefficients(&pos, &mut c, &mut e, &mut nz).finite);
        assert_eq!(root_bound(&e, &nz, None, 3), 32.0);
        assert_eq!(root_bound(&e, &nz, Some(&c), 3), 0.0);
        // (t - 0.5)(t + 100) = t^2 + 99.5 t - 50: Fujiwara 2^8, Kioustelidis only from -50
        let mixed = [-50.0, 99.5, 1.0];
        assert!(load_coefficients(&mixed, &mut c, &mut e, &mut nz).finite);
        assert_eq!(root_bound(&e, &nz, None, 2), 256.0);
        assert_eq!(root_bound(&e, &nz, Some(&c), 2), 16.0);
        // only the leading term: no bound
        let (mut e2, mut nz2) = ([0; MAXN + 1], [false; MAXN + 1]);
        assert!(load_coefficients(&[0.0, 0.0, 2.0], &mut c, &mut e2, &mut nz2).finite);
        assert_eq!(root_bound(&e2, &nz2, None, 2), 0.0);
    }
}

/// The kernels written over 9 entries with constant bounds (degree <= 8) against C's plain
/// loops, bit for bit, on wide-range data with exact zeros (as tests/runtime/test_c_kernels.py
/// checks C's written-out forms).
#[cfg(test)]
mod kernels {
    use super::{binomial_sums, compensated_with_slope, halves, horner, horner_abs, horner_compensated, load_any, load_coefficients, taylor_shift, taylor_shift_8, taylor_table, touch_values, touch_values_core, Taylor, MAXN};
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    use super::{compensated_core, compensated_hw, compensated_slope_core, compensated_slope_hw, horner_core, horner_fma_hw, hw_fma};
    use std::mem::MaybeUninit;

    /// xorshift; values of both signs over 2^-30..2^30, one in 16 an exact zero.
    struct Rnd(u64);
    impl Rnd {
        fn next(&mut self) -> f64 {
            let s = &mut self.0;
            *s ^= *s << 13;
            *s ^= *s >> 7;
            *s ^= *s << 17;
            if (*s).is_multiple_of(16) {
                return 0.0;
            }
            let m = (*s >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            m * 2f64.powi(((*s >> 5) % 60) as i32 - 30)
        }
        fn array(&mut self) -> [f64; MAXN + 1] {
            std::array::from_fn(|_| self.next())
        }
    }

    fn bits(v: &[f64]) -> Vec<u64> {
        v.iter().map(|x| x.to_bits()).collect()
    }

    #[test]
    fn loading_normal_numbers_is_load_any() {
        // the loop for normal numbers against the general one, on vectors of normal numbers
        // (most), with zeros (one in 16 entries), and with a subnormal, the extremes of the
        // normal range, an infinity or a NaN put in
        let mut r = Rnd(0x2545_F491_4F6C_DD1D);
        let special = [f64::MIN_POSITIVE, -f64::MAX, 5e-324, -1e-310, f64::INFINITY, f64::NAN, -0.0];
        for trial in 0..20000 {
            let n = trial % (MAXN + 1);
            let mut src = r.array();
            if trial % 5 == 0 {
                src[trial % (n + 1)] = special[(trial / 5) % special.len()];
            }
            let (mut c1, mut e1, mut nz1) = ([0.0; MAXN + 1], [7; MAXN + 1], [false; MAXN + 1]);
            let (mut c2, mut e2, mut nz2) = ([0.0; MAXN + 1], [7; MAXN + 1], [false; MAXN + 1]);
            let s1 = load_coefficients(&src[..=n], &mut c1, &mut e1, &mut nz1);
            let s2 = load_any(&src[..=n], &mut c2, &mut e2, &mut nz2);
            assert_eq!((s1.finite, s1.emax, s1.emin, s1.changes), (s2.finite, s2.emax, s2.emin, s2.changes), "{src:?}");
            assert_eq!(bits(&c1[..=n]), bits(&c2[..=n]));
            assert_eq!((&e1[..=n], &nz1[..=n]), (&e2[..=n], &nz2[..=n]), "{src:?}");
        }
    }

    #[test]
    fn compensated_value_with_its_slope_is_the_value_alone() {
        // C compensated_with_slope: horner_compensated's value bits, and D's plain Horner in the
        // same loop
        let mut r = Rnd(0x853C_49E6_748F_EA9B);
        for trial in 0..20000 {
            let m = 1 + trial % MAXN;
            let (p, d) = (r.array(), r.array());
            let x = (1.0 + r.next().abs()) * 2f64.powi((trial % 7) as i32 - 3);
            let (v, slope) = compensated_with_slope(&p, &d, m, x);
            let mut want = d[m - 1];
            for j in (0..m - 1).rev() {
                want = want * x + d[j];
            }
            assert_eq!(v.to_bits(), horner_compensated(&p, m, x).to_bits(), "m={m}");
            assert_eq!(slope.to_bits(), want.to_bits(), "m={m}");
        }
    }

    #[test]
    fn fma_copies_give_the_plain_bits() {
        // C FMA_DISPATCH: the precise kernels' copies for the fma instruction against their plain
        // forms (Dekker's product, mul_add by libm), bit for bit; near roots too, where the
        // compensated value is mostly its correction
        #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
        {
            assert!(hw_fma(), "this CPU has no fma instruction: the copies cannot be compared here");
            let mut r = Rnd(0x2545_F491_4F6C_DD1D);
            for trial in 0..20000 {
                let m = 1 + trial % MAXN;
                let (p, d) = (r.array(), r.array());
                let x0 = (1.0 + r.next().abs()) * 2f64.powi((trial % 7) as i32 - 3);
                // a root of p near x0, by a few Newton steps: the compensated value's hard case
                let mut x = x0;
                for _ in 0..6 {
                    let (v, dv) = (horner(&p, m, x, 0, false), horner(&d, m - 1, x, 0, false));
                    if dv != 0.0 && (x - v / dv).is_finite() {
                        x -= v / dv;
                    }
                }
                for x in [x0, x] {
                    // SAFETY: hw_fma() above
                    let (a, b) = unsafe { (compensated_hw(&p, m, x), compensated_slope_hw(&p, &d, m, x)) };
                    assert_eq!(a.to_bits(), compensated_core(&p, m, x, false).to_bits(), "m={m} x={x}");
                    let want = compensated_slope_core(&p, &d, m, x, false);
                    assert_eq!((b.0.to_bits(), b.1.to_bits()), (want.0.to_bits(), want.1.to_bits()));
                    for k in 0..3 {
                        // SAFETY: hw_fma() above
                        let h = unsafe { horner_fma_hw(&p, m, x, k) };
                        assert_eq!(h.to_bits(), horner_core(&p, m, x, k, true).to_bits(), "m={m} k={k}");
                    }
                }
            }
        }
    }

    #[test]
    fn touch_values_are_the_kernels() {
        // C touch_values: the five evaluations of a touch's scan in one loop, against the
        // kernels they replace, bit for bit (dispatched and plain copy)
        let mut r = Rnd(0x6A09_E667_F3BC_C909);
        for trial in 0..20000 {
            let n = 3 + trial % (MAXN - 2);
            let p = r.array();
            let mut d1 = [0.0f64; MAXN + 1];
            let mut d2 = [0.0f64; MAXN + 1];
            for i in 0..n {
                d1[i] = (i + 1) as f64 * p[i + 1];
            }
            for i in 0..n - 1 {
                d2[i] = (i + 1) as f64 * d1[i + 1];
            }
            let x = (1.0 + r.next().abs()) * 2f64.powi((trial % 7) as i32 - 3);
            let hi = x * (1.0 + 2f64.powi(-9));
            let (dv, ddv) = compensated_with_slope(&d1, &d2, n - 1, x);
            let want = [horner(&p, n, x, 0, true), horner_compensated(&p, n, x), horner_abs(&p, n, x, 0),
                        horner(&p, n, hi, 0, true), dv, ddv];
            for tv in [touch_values(&p, &d1, &d2, n, x, hi), touch_values_core(&p, &d1, &d2, n, x, hi, false)] {
                let got = [tv.vb, tv.pb, tv.ab, tv.vhi, tv.dv, tv.ddv];
                for (g, w) in got.iter().zip(want) {
                    assert_eq!(g.to_bits(), w.to_bits(), "n={n} x={x}");
                }
            }
        }
    }

    #[test]
    fn running_sums_are_the_loop() {
        let mut r = Rnd(0x9E37_79B9_7F4A_7C15);
        for trial in 0..20000 {
            let n = 1 + trial % 8;
            let mut a = r.array();
            a[n + 1..].fill(0.0); // (the caller's padding)
            let mut want = a;
            for round in 1..=n {
                for j in (round..=n).rev() {
                    want[j] += want[j - 1];
                }
            }
            binomial_sums(&mut a, n);
            assert_eq!(bits(&a[..=n]), bits(&want[..=n]), "degree {n}");
        }
    }

    #[test]
    fn halves_are_the_loop() {
        // left: the first entries of de Casteljau's triangle; right: its last ones, which are
        // also the left half of the reversed coefficients, reversed (the old way)
        let mut r = Rnd(0x1234_5678_9ABC_DEF1);
        for trial in 0..20000 {
            let n = 1 + trial % 8;
            let a = r.array(); // entries above n must not matter
            let mut w = a;
            let (mut left, mut right) = ([0.0; MAXN + 1], [0.0; MAXN + 1]);
            left[0] = w[0];
            right[n] = w[n];
            for k in 1..=n {
                for j in 0..=n - k {
                    w[j] = (w[j] + w[j + 1]) * 0.5;
                }
                left[k] = w[0];
                right[n - k] = w[n - k];
            }
            let mut v: Vec<f64> = (0..=n).rev().map(|j| a[j]).collect();
            let mut mirrored = vec![0.0; n + 1];
            mirrored[n] = v[0];
            for k in 1..=n {
                for j in 0..=n - k {
                    v[j] = (v[j] + v[j + 1]) * 0.5;
                }
                mirrored[n - k] = v[0];
            }
            assert_eq!(bits(&right[..=n]), bits(&mirrored), "degree {n} (reversed)");
            let a9: [f64; 9] = std::array::from_fn(|j| a[j]);
            let (l9, r9) = halves(&a9, n);
            assert_eq!(bits(&l9[..=n]), bits(&left[..=n]), "degree {n}");
            assert_eq!(bits(&r9[..=n]), bits(&right[..=n]), "degree {n}");
            let (l, rr) = halves(&a, n);
            assert_eq!(bits(&l[..=n]), bits(&left[..=n]), "degree {n} (loop)");
            assert_eq!(bits(&rr[..=n]), bits(&right[..=n]), "degree {n} (loop)");
        }
    }

    #[test]
    fn taylor_shift_8_is_the_loop() {
        let mut r = Rnd(0x0F0F_F0F0_1234_4321);
        for trial in 0..20000 {
            let n = 1 + trial % 8;
            let p = r.array();
            let x = r.next().abs() + f64::MIN_POSITIVE; // x > 0
            let mut slot = MaybeUninit::<Taylor>::uninit();
            let tb = taylor_table(&p, n, 1e-15, 0.0, &mut slot);
            let (mut a, mut s) = ([0.0; MAXN + 1], [0.0; MAXN + 1]);
            let (mut a8, mut s8) = ([0.0; MAXN + 1], [0.0; MAXN + 1]);
            taylor_shift(tb, n, x, &mut a, &mut s);
            taylor_shift_8(tb, x, &mut a8, &mut s8);
            assert_eq!(bits(&a8[..=n]), bits(&a[..=n]), "degree {n} at {x}");
            assert_eq!(bits(&s8[..=n]), bits(&s[..=n]), "degree {n} at {x}");
        }
    }
}
