//! Evaluation: Horner (scaled, the fma dispatch), the noise factors, signs (C:
//! `runtime/c/roots/evaluate.inc`).

use super::*;

#[inline]
pub(super) fn scale_exponent(x: f64, m: usize) -> i32 {
    if x.abs() <= if m <= 8 { SAFE_LOW } else { SAFE_HIGH } {
        0
    } else {
        ilogb(x) + 1
    }
}

/// Whether the CPU has the fma instruction, where the build did not assume it (C
/// `FMA_DISPATCH`): the precise kernels below then run their copies compiled for it
/// (`#[target_feature(enable = "fma")]`), with the same bits -- `mul_add` is correctly rounded
/// as an instruction or as the libm call it is otherwise, and the compensated Horner's error-free
/// product is exact either way (`fma(s, x, -s x)` or Dekker's).  std caches the detection.
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[inline(always)]
pub(super) fn hw_fma() -> bool {
    std::arch::is_x86_feature_detected!("fma")
}

/// C `horner_core`: p(x) / 2^(k n) by Horner, fused (`mul_add`) or multiply-then-add.
#[inline(always)]
pub(super) fn horner_core(c: &[f64], n: usize, x: f64, k: i32, fused: bool) -> f64 {
    let c = &c[..=n];
    let mut acc = c[n];
    if k == 0 {
        for &ci in c[..n].iter().rev() {
            acc = if fused { acc.mul_add(x, ci) } else { acc * x + ci };
        }
        return acc;
    }
    let xs = ldexp(x, -i64::from(k));
    let f = ldexp(1.0, -i64::from(k));
    let mut fi = 1.0;
    for i in (0..n).rev() {
        fi *= f;
        acc = if fused { acc.mul_add(xs, c[i] * fi) } else { acc * xs + c[i] * fi };
    }
    acc
}

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[target_feature(enable = "fma")]
#[inline(never)]
pub(super) fn horner_fma_hw(c: &[f64], n: usize, x: f64, k: i32) -> f64 {
    horner_core(c, n, x, k, true)
}

/// C `horner`.
pub(super) fn horner(c: &[f64], n: usize, x: f64, k: i32, precise: bool) -> f64 {
    count::madds(n);
    if !precise {
        return horner_core(c, n, x, k, false);
    }
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if hw_fma() {
        // SAFETY: the CPU has the fma instruction (detected above)
        return unsafe { horner_fma_hw(c, n, x, k) };
    }
    horner_core(c, n, x, k, true)
}

pub(super) fn horner_abs(c: &[f64], n: usize, x: f64, k: i32) -> f64 {
    count::madds(n);
    let ax = x.abs();
    let mut acc = c[n].abs();
    if k == 0 {
        // (as C: the common case without the scaling's products)
        for i in (0..n).rev() {
            acc = acc * ax + c[i].abs();
        }
        return acc;
    }
    let xs = ldexp(ax, -i64::from(k));
    let f = ldexp(1.0, -i64::from(k));
    let mut fi = 1.0;
    for i in (0..n).rev() {
        fi *= f;
        acc = acc * xs + c[i].abs() * fi;
    }
    acc
}

/// 2 gamma_{2n}, tabulated as in C (a division per call is not free).
static NOISE: [f64; MAXN + 1] = noise_table();

const fn noise_table() -> [f64; MAXN + 1] {
    let mut t = [0.0; MAXN + 1];
    let mut n = 0;
    while n <= MAXN {
        let k = n as f64;
        t[n] = 2.0 * (2.0 * k * U / (1.0 - 2.0 * k * U));
        n += 1;
    }
    t
}

#[inline]
pub(crate) fn noise_factor(n: usize) -> f64 {
    NOISE[n]
}

pub(super) fn within_noise(c: &[f64], n: usize, x: f64, skin: f64) -> bool {
    let k = scale_exponent(x, n);
    noise_holds(c, n, x, k, horner(c, n, x, k, true), skin)
}

/// C `noise_holds`: `within_noise` from v = horner(c, n, x, k, true), already computed.
pub(super) fn noise_holds(c: &[f64], n: usize, x: f64, k: i32, v: f64, skin: f64) -> bool {
    let sk = if k == 0 { skin } else { ldexp(skin, -i64::from(k) * n as i64) };
    v.abs() <= noise_factor(n) * horner_abs(c, n, x, k) + sk
}

pub(super) fn sign_at(c: &[f64], n: usize, x: f64, precise: bool) -> i32 {
    let v = horner(c, n, x, scale_exponent(x, n), precise);
    i32::from(v > 0.0) - i32::from(v < 0.0)
}
