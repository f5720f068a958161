"""Evaluation: Horner (scaled), the noise factors, signs (C: ``runtime/c/roots/evaluate.inc``)."""

from __future__ import annotations

from typing import Sequence

from .shared import SAFE_HIGH, SAFE_LOW, U, fma, ilogb, ldexp


# ---------------------------------------------------------------------------
# Evaluation
# ---------------------------------------------------------------------------


def scale_exponent(x: float, m: int) -> int:
    return 0 if abs(x) <= (SAFE_LOW if m <= 8 else SAFE_HIGH) else ilogb(x) + 1


def horner(c: Sequence[float], n: int, x: float, k: int, precise: bool) -> float:
    acc = c[n]
    if k == 0:
        if precise:
            for i in range(n - 1, -1, -1):
                acc = fma(acc, x, c[i])
        else:
            for i in range(n - 1, -1, -1):
                acc = acc * x + c[i]
        return acc
    xs, f, fi = ldexp(x, -k), ldexp(1.0, -k), 1.0
    for i in range(n - 1, -1, -1):
        fi *= f
        acc = fma(acc, xs, c[i] * fi) if precise else acc * xs + c[i] * fi
    return acc


def horner_abs(c: Sequence[float], n: int, x: float, k: int) -> float:
    ax = abs(x)
    acc = abs(c[n])
    xs = ldexp(ax, -k) if k else ax
    f, fi = ldexp(1.0, -k), 1.0
    for i in range(n - 1, -1, -1):
        fi *= f
        acc = acc * xs + abs(c[i]) * fi
    return acc


def noise_factor(n: int) -> float:
    return 2.0 * (2.0 * n * U / (1.0 - 2.0 * n * U))


def within_noise(c: Sequence[float], n: int, x: float, skin: float) -> bool:
    k = scale_exponent(x, n)
    sk = skin if k == 0 else ldexp(skin, -k * n)
    return abs(horner(c, n, x, k, True)) <= noise_factor(n) * horner_abs(c, n, x, k) + sk


def sign_at(c: Sequence[float], n: int, x: float, precise: bool) -> int:
    v = horner(c, n, x, scale_exponent(x, n), precise)
    return (v > 0) - (v < 0)
