"""Closed-form quartic after Orellana & De Michele, ACM TOMS Algorithm 1010.

Why this method: Ferrari-type formulas lose digits on spread or clustered
roots; the paper's LDL^T view picks, among algebraically equivalent ways of
splitting the quartic into two quadratics, the one with the least residual,
then refines the four factor coefficients by Newton.  It is the "closed"
method of the runtime for degree 3 (as t * p(t), whose extra root 0 is
outside (0, tmax]) and 4.  Same structure as the C version.
"""
from __future__ import annotations

import cmath
import math

EPS = 2.0**-52
CUBIC_RESCALE = 3.488062113727083e102  # DBL_MAX^(1/3) / golden ratio
QUARTIC_RESCALE = 7.156344627944542e76  # DBL_MAX^(1/4) / golden ratio


def _cubic_dominant_scaled(g: float, h: float) -> float:
    """Largest-magnitude real root of x^3 + g x + h with the discriminant
    R^2 - Q^3 carried scaled (as K) so huge g, h do not overflow."""
    Q, R = -g / 3, 0.5 * h
    if R == 0:
        return math.sqrt(-g) if g <= 0 else 0.0
    if abs(Q) < abs(R):
        qr = Q / R
        K = 1 - Q * qr * qr
    else:
        rq = R / Q
        K = math.copysign(1.0, Q) * (rq * rq / Q - 1)
    if K < 0:  # three real roots, Q > 0
        sq = math.sqrt(Q)
        theta = math.acos(max(-1.0, min(1.0, (R / abs(Q)) / sq)))
        return -2 * sq * math.cos(theta / 3) if theta < math.pi / 2 else -2 * sq * math.cos((theta + 2 * math.pi) / 3)
    if abs(Q) < abs(R):
        A = -math.copysign(math.cbrt(abs(R) * (1 + math.sqrt(K))), R)
    else:
        A = -math.copysign(math.cbrt(abs(R) + math.sqrt(abs(Q)) * abs(Q) * math.sqrt(K)), R)
    return A + (0.0 if A == 0 else Q / A)


def _cubic_dominant(g: float, h: float) -> float:
    """Same root by Cardano / trigonometric form for moderate g, h."""
    Q, R = -g / 3, 0.5 * h
    if abs(Q) > 1e102 or abs(R) > 1e154:
        return _cubic_dominant_scaled(g, h)
    Q3, R2 = Q * Q * Q, R * R
    if R2 < Q3:
        theta = math.acos(max(-1.0, min(1.0, R / math.sqrt(Q3))))
        s = -2 * math.sqrt(Q)
        return s * math.cos(theta / 3) if theta < math.pi / 2 else s * math.cos((theta + 2 * math.pi) / 3)
    A = -math.copysign(math.cbrt(abs(R) + math.sqrt(R2 - Q3)), R)
    return A + (0.0 if A == 0 else Q / A)


def _finite(x: float) -> bool:
    return math.isfinite(x)


def _resolvent_phi0(a: float, b: float, c: float, d: float, scaled: bool) -> float:
    """Dominant root of the resolvent cubic of x^4 + a x^3 + b x^2 + c x + d,
    computed on the quartic shifted to an inflection point (the resolvent
    variable is shift invariant), then polished by Newton while the
    residual decreases."""
    disc = 9 * a * a - 24 * b
    if disc > 0:
        disc = math.sqrt(disc)
        s = -2 * b / (3 * a + disc) if a > 0 else -2 * b / (3 * a - disc)
    else:
        s = -a / 4
    as_ = a + 4 * s
    bs = b + 3 * s * (a + 2 * s)
    cs = c + s * (2 * b + s * (3 * a + 4 * s))
    ds = d + s * (c + s * (b + s * (a + s)))
    gg, hh = bs * bs / 9, as_ * cs
    g = hh - 4 * ds - 3 * gg
    h = (8 * ds + hh - 2 * gg) * bs / 3 - cs * cs - ds * as_ * as_
    x = _cubic_dominant(g, h) if _finite(g) and _finite(h) else math.nan
    if not _finite(x):
        x = _cubic_dominant_scaled(g, h) if _finite(g) and _finite(h) else math.nan
        if not _finite(x) and scaled:
            r = CUBIC_RESCALE
            r2 = r * r
            a2, b2, c2, d2 = as_ / r, bs / r, cs / r, ds / r2
            gg2, hh2 = b2 * b2 / 9, a2 * c2
            g = hh2 - 4 * d2 - 3 * gg2
            h = (8 * d2 + hh2 - 2 * gg2) * b2 / 3 - c2 * (c2 / r) - (ds / r) * a2 * a2
            x = _cubic_dominant(g, h)
            if not _finite(x):
                x = _cubic_dominant_scaled(g, h)
            x *= r
    if not _finite(x):
        return x
    f = x * (x * x + g) + h
    scale = max(abs(x * x * x), abs(g * x), abs(h))
    if not abs(f) > EPS * scale:
        return x
    for _ in range(8):
        df = 3 * x * x + g
        if df == 0:
            break
        xn = x - f / df
        fn = xn * (xn * xn + g) + h
        if fn == 0:
            return xn
        if not abs(fn) < abs(f):
            break
        x, f = xn, fn
    return x


def _rel(v: complex | float, ref: float) -> float:
    return abs(v) if ref == 0 else abs((v - ref) / ref)


def _factor_error(a: float, b: float, c: float, d: float, p, q, r, s, include_d: bool = True) -> float:
    """Relative residual of (x^2 + p x + q)(x^2 + r x + s) against the quartic
    (real or complex factor coefficients)."""
    e = _rel(q * r + p * s, c) + _rel(q + p * r + s, b) + _rel(p + r, a)
    return e + _rel(q * s, d) if include_d else e


def _ldlt_error(b: float, c: float, d: float, d2: float, l1: float, l2: float, l3: float) -> float:
    return _rel(d2 + l1 * l1 + 2 * l3, b) + _rel(2 * d2 * l2 + 2 * l1 * l3, c) + _rel(d2 * l2 * l2 + l3 * l3, d)


def _refine_factors(a: float, b: float, c: float, d: float, x: list[float]) -> None:
    """Newton on the factor coefficients (p, q, r, s) = x against
    q s = d, q r + p s = c, q + p r + s = b, p + r = a; stops when the
    summed relative residual stops decreasing."""
    ref = (d, c, b, a)

    def residuals() -> tuple[list[float], float]:
        fv = [x[1] * x[3] - d, x[1] * x[2] + x[0] * x[3] - c, x[1] + x[0] * x[2] + x[3] - b, x[0] + x[2] - a]
        return fv, sum(abs(f) if r == 0 else abs(f / r) for f, r in zip(fv, ref))

    fv, err = residuals()
    for _ in range(8):
        pr = x[0] - x[2]
        det = x[1] * x[1] + x[1] * (-x[2] * pr - 2 * x[3]) + x[3] * (x[0] * pr + x[3])
        if det == 0:
            break
        j01 = x[3] - x[1]
        j02 = x[1] * x[2] - x[0] * x[3]
        J = [
            [pr, j01, j02, -x[1] * j01 - x[0] * j02],
            [x[0] * pr + j01, -x[1] * pr, -x[1] * j01, -x[1] * j02],
            [-pr, -j01, -j02, j02 * x[2] + j01 * x[3]],
            [-x[2] * pr - j01, pr * x[3], x[3] * j01, x[3] * j02],
        ]
        old, old_err = list(x), err
        for i in range(4):
            x[i] -= sum(J[i][k] * fv[k] for k in range(4)) / det
        fv, err = residuals()
        if err == 0:
            break
        if not err < old_err:
            x[:] = old
            break


def _monic_quadratic_roots(p: float, q: float) -> list[complex]:
    disc = p * p - 4 * q
    if disc >= 0:
        big = 0.5 * (-p - math.sqrt(disc) if p >= 0 else -p + math.sqrt(disc))
        return [complex(big), complex(0.0 if big == 0 else q / big)]
    im = 0.5 * math.sqrt(-disc)
    return [complex(-0.5 * p, im), complex(-0.5 * p, -im)]


def _real_factors(a: float, b: float, c: float, d: float, l1: float, l2: float, l3: float, d2: float) -> list[float]:
    """Case d2 < 0: real factors; the linear coefficient of the factor with
    the smaller one is recomputed from whichever equation fits best."""
    gamma = math.sqrt(-d2)
    p, q, r, s = l1 + gamma, l3 + gamma * l2, l1 - gamma, l3 - gamma * l2
    if abs(s) < abs(q):
        s = d / q
    elif abs(s) > abs(q):
        q = d / s
    if abs(p) < abs(r):
        cand = ([(c - q * r) / s] if s != 0 else []) + ([(b - s - q) / r] if r != 0 else []) + [a - r]
        p = min(cand, key=lambda v: _factor_error(a, b, c, d, v, q, r, s, False))
    else:
        cand = ([(c - p * s) / q] if q != 0 else []) + ([(b - q - s) / p] if p != 0 else []) + [a - p]
        r = min(cand, key=lambda v: _factor_error(a, b, c, d, p, q, v, s, False))
    return [p, q, r, s]


def quartic_roots(cf: list[float]) -> list[complex]:
    """The four roots of cf[4] x^4 + ... + cf[0] (cf[4] != 0)."""
    a, b, c, d = cf[3] / cf[4], cf[2] / cf[4], cf[1] / cf[4], cf[0] / cf[4]
    rescale = 1.0
    phi0 = _resolvent_phi0(a, b, c, d, False)
    if not _finite(phi0):
        rescale = QUARTIC_RESCALE
        r2 = rescale * rescale
        a, b, c, d = a / rescale, b / r2, c / (r2 * rescale), d / (r2 * r2)
        phi0 = _resolvent_phi0(a, b, c, d, True)
    l1, l3 = a / 2, b / 6 + phi0 / 2
    del2 = c - a * l3
    d2_direct = 2 * b / 3 - phi0 - l1 * l1
    d3 = d - l3 * l3

    cands: list[tuple[float, float]] = []  # (d2, l2) candidates, least residual wins
    if d2_direct != 0:
        cands.append((d2_direct, del2 / (2 * d2_direct)))
    if del2 != 0:
        l2 = 2 * d3 / del2
        if l2 != 0:
            cands.append((del2 / (2 * l2), l2))
        cands.append((d2_direct, l2))
    d2, l2 = min(cands, key=lambda t: _ldlt_error(b, c, d, t[0], l1, t[1], l3)) if cands else (0.0, 0.0)

    kind = -1  # 1 real factors, 0 complex-conjugate factors, -1 undecided
    x = [0.0] * 4
    cp = cq = 0j
    if d2 < 0:
        x, kind = _real_factors(a, b, c, d, l1, l2, l3, d2), 1
    elif d2 > 0:
        gamma = math.sqrt(d2)
        cp, cq, kind = complex(l1, gamma), complex(l3, gamma * l2), 0
    tiny = EPS * max(abs(2 * b / 3), abs(phi0), l1 * l1)
    if kind == -1 or abs(d2) <= tiny:  # d2 ~ 0: compare with the d2 = 0 split
        err0 = math.inf
        if kind == 1:
            err0 = _factor_error(a, b, c, d, *x)
        elif kind == 0:
            err0 = _factor_error(a, b, c, d, cp, cq, cp.conjugate(), cq.conjugate())
        if d3 <= 0:
            y = [l1, l3 + math.sqrt(-d3), l1, l3 - math.sqrt(-d3)]
            if abs(y[3]) < abs(y[1]):
                y[3] = d / y[1]
            elif abs(y[3]) > abs(y[1]):
                y[1] = d / y[3]
            if kind == -1 or _factor_error(a, b, c, d, *y) < err0:
                x, kind = y, 1
        else:
            p1, q1 = complex(l1), complex(l3, math.sqrt(d3))
            if kind == -1 or _factor_error(a, b, c, d, p1, q1, p1.conjugate(), q1.conjugate()) < err0:
                cp, cq, kind = p1, q1, 0
    if kind == 1:
        _refine_factors(a, b, c, d, x)
        roots = _monic_quadratic_roots(x[0], x[1]) + _monic_quadratic_roots(x[2], x[3])
    else:
        disc = cmath.sqrt(cp * cp / 4 - cq)
        z1, z2 = -cp / 2 + disc, -cp / 2 - disc
        zmax = z1 if abs(z1) > abs(z2) else z2
        zmin = cq / zmax if zmax != 0 else 0j
        roots = [zmin, zmin.conjugate(), zmax, zmax.conjugate()]
    return [z * rescale for z in roots]
