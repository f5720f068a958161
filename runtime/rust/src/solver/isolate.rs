//! Budan-Fourier isolation: Laguerre's guess and the bisection (C:
//! `runtime/c/roots/isolate.inc`).

use super::*;

/// Laguerre steps `speculate_first_root` takes at most (but for a touch's, below).
const SPECULATE_STEPS: usize = 8;
/// The certificate's interval reaches this far beyond the speculated root, relative (2^-20).
const SPECULATE_MARGIN: f64 = 9.536_743_164_062_5e-7;
/// Laguerre steps beyond SPECULATE_STEPS while the ratios of a touch last.
const TOUCH_EXTRA: usize = 4;
/// Newton steps on p' towards a touch's critical point, at most.
const TOUCH_STEPS: usize = 6;
/// The step ratios of Laguerre converging linearly to a double root (0.25 at degree 3, 0.284
/// at 8, 0.289 at 16) lie in [TOUCH_RATIO_LO, TOUCH_RATIO_HI].
const TOUCH_RATIO_LO: f64 = 0.25;
const TOUCH_RATIO_HI: f64 = 0.31;
/// Ratios in a row in that range that make the guess turn to the critical point.
const TOUCH_STEADY: usize = 3;
/// Newton steps that may take Laguerre's place where its square root's argument is negative.
const GUESS_NEWTON: usize = 2;
/// A critical point is a touch where |p| is within this times the rounding bound (2^20).
const TOUCH_NEAR: f64 = 1_048_576.0;
/// Half-width (relative) of the interval around a touch that goes to the derivative method
/// (2^-10; `isolate_first_root`).
const TOUCH_WIDTH: f64 = 9.765_625e-4;

/// What `speculate_first_root` found (C: its return value, `*r`, `*touch` and `*over`; C's
/// `*dip`, where p dips towards complex roots near the axis, is its out-parameter `dip`: set
/// where it saw one, whatever it returns).
enum Guess {
    /// Laguerre converged here: maybe the first root (the caller certifies it).
    Root(f64),
    /// A step went past a root: p < 0 at `over`, a root in (0, over), Newton's start inside
    /// the step first (C's OVERSHOT; the caller certifies it up to `over`).
    Overshot { start: f64, over: f64 },
    /// The critical point of a touch ahead (p there within TOUCH_NEAR rounding bounds).
    Touch(f64),
    Nothing,
}

/// C `speculate_first_root`: a guess at the first root by Laguerre's method from 0, each step
/// taken to the right (of its two square-root signs, the one that moves x up).  Why Laguerre
/// and not Newton from where p's control polygon crosses 0: Newton from far away creeps (a
/// step is about x / n while p ~ x^n, and the window is many times the first root), while
/// Laguerre, for a polynomial whose roots are all real, converges monotonically to the first
/// root after its start, cubically near it, from any start -- and from 0 that is the first
/// positive root.  Nothing where the square root's argument is negative (complex roots in the
/// way), when no step to the right exists, when x leaves (0, T), when a step from the fifth on
/// has neither halved nor shrunk by more than the step before (far from every root Laguerre
/// creeps, then speeds up: it gives up only while it is not slowing down), or after
/// SPECULATE_STEPS; stops once a step is below PRECISE_FROM, or below GUESS_DONE at most
/// GUESS_FAST of the step before.  Nothing is certain about the
/// result: the caller certifies a root by a Bernstein test.
///
/// A touch ahead (a double root, or two real roots or a complex pair within the rounding noise
/// of one) shows as linear convergence: each step 1 - n / (2 + sqrt((n - 1)(2n - 4))) times
/// the one before.  After TOUCH_STEADY ratios in a row in [TOUCH_RATIO_LO, TOUCH_RATIO_HI] (up
/// to TOUCH_EXTRA steps beyond SPECULATE_STEPS while they last) the guess turns to Newton on
/// p' -- the critical point is a simple root of p', so that converges quadratically where
/// Laguerre would crawl -- and reports a touch where p there is within TOUCH_NEAR times the
/// rounding bound (a complex pair clear of the axis is not: not worth the derivative method).
/// Like the root, it only chooses where to look (`isolate_first_root`).
///
/// A step that lands past a root (complex roots near the first real one, or an iterate one
/// rounding past a root it has converged to) gives `Overshot`: p < 0 at the new x, a root in
/// (0, x), and Newton's start where Newton from x points if inside the step, else its middle.
/// Where the square root's argument is negative and p falls, a Newton step takes Laguerre's
/// place, up to GUESS_NEWTON times: past the complex pair's pull Laguerre's steps often
/// resume, and a step past the root is an overshoot like any other.
///
/// The arithmetic is C's, operation for operation (the results are bit-identical): three
/// Horner chains in C's statement order, `2 * d2 / f` as `(2 d2) / f`, the integer factors
/// converted as C converts them, the exit rules at the same places.
#[inline(always)]
fn speculate_first_root(p: &[f64], n: usize, t_end: f64, dip: &mut f64) -> Guess {
    count::phase(2);
    let p = &p[..=n];
    // C's (n - 1) converted to double, exact (and no usize underflow)
    let (nf, n1f) = (n as f64, n as f64 - 1.0);
    let (mut x, mut last, mut qprev, mut xprev) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut newton = 0; // Newton steps in Laguerre's place
    // critical > 0: Newton on p' (after the double-root signature), its step number
    let (mut critical, mut steady) = (0usize, 0usize);
    for it in 0..SPECULATE_STEPS + TOUCH_EXTRA + TOUCH_STEPS {
        if critical == 0 && it >= SPECULATE_STEPS && (steady == 0 || it >= SPECULATE_STEPS + TOUCH_EXTRA) {
            return Guess::Nothing;
        }
        count::madds(3 * n);
        // p, p' and p''/2 at x (at 0, the first step: the coefficients, the values Horner's
        // chains give there, as in C)
        let (mut f, mut d1, mut d2) = (p[0], p[1], p[2]);
        if it > 0 {
            (f, d1, d2) = (p[n], 0.0f64, 0.0f64);
            for &pi in p[..n].iter().rev() {
                d2 = d2 * x + d1;
                d1 = d1 * x + f;
                f = f * x + pi;
            }
        }
        if critical > 0 {
            // Newton on p' towards the critical point: a simple root of p' where p'' > 0 (a
            // minimum of p > 0)
            if !(d2 > 0.0) {
                return Guess::Nothing;
            }
            let s = d1 / (2.0 * d2);
            x -= s;
            if !(x > 0.0 && x < t_end) {
                return Guess::Nothing;
            }
            if s.abs() <= PRECISE_FROM * x {
                let near = f.abs() <= TOUCH_NEAR * noise_factor(n) * horner_abs(p, n, x, 0);
                // (not near: a dip clear of the axis, complex roots)
                if near {
                    return Guess::Touch(x);
                }
                *dip = x;
                return Guess::Nothing;
            }
            if critical > 1 && !(s.abs() <= 0.5 * last.abs()) {
                return Guess::Nothing;
            }
            critical += 1;
            last = s;
            continue;
        }
        if f == 0.0 {
            return if x > 0.0 { Guess::Root(x) } else { Guess::Nothing };
        }
        if f < 0.0 {
            // past a root: one in (xprev, x)
            let y = x - f / d1;
            let start = if y > xprev && y < x { y } else { xprev + 0.5 * (x - xprev) };
            return Guess::Overshot { start, over: x };
        }
        // (n - 1) f^2 times Laguerre's discriminant: its sign, and the step from one division
        let u = n1f * (d1 * d1) - 2.0 * nf * (f * d2);
        let s = if !(u >= 0.0) {
            // complex roots in the way: one Newton step on p' towards the dip, and in
            // Laguerre's place, up to GUESS_NEWTON times while p falls, a Newton step
            if d2 > 0.0 {
                *dip = x - d1 / (2.0 * d2);
            }
            if newton == GUESS_NEWTON || !(d1 < 0.0) {
                return Guess::Nothing;
            }
            newton += 1;
            f / d1
        } else {
            // the step to the right (negative), or none
            nf * f / (d1 - (n1f * u).sqrt().copysign(f))
        };
        if !(s < 0.0) {
            return Guess::Nothing;
        }
        xprev = x;
        x -= s;
        if !(x > 0.0 && x < t_end) {
            return Guess::Nothing;
        }
        let q = if it > 0 { s / last } else { 0.0 };
        if s.abs() <= PRECISE_FROM * x || (s.abs() <= GUESS_DONE * x && q <= GUESS_FAST) {
            return Guess::Root(x);
        }
        steady = if (TOUCH_RATIO_LO..=TOUCH_RATIO_HI).contains(&q) { steady + 1 } else { 0 };
        if steady >= TOUCH_STEADY {
            critical = 1; // linear convergence: a double root ahead
            last = s;
            continue;
        }
        if it >= 4 && !(s.abs() <= 0.5 * last.abs()) && !(q < qprev) {
            return Guess::Nothing;
        }
        qprev = q;
        last = s;
    }
    Guess::Nothing
}

fn isolation_split(a: f64, b: f64) -> f64 {
    if a == 0.0 {
        return b * 0.0625;
    }
    if b > 8.0 * a {
        return a.sqrt() * b.sqrt();
    }
    a + 0.5 * (b - a)
}

/// C `derivative`: the coefficients of p' (p of degree n) in dp[0..n].
#[inline(always)]
fn derivative(p: &[f64], n: usize) -> [f64; MAXN] {
    let mut dp = [0.0f64; MAXN];
    for i in 0..n {
        dp[i] = (i + 1) as f64 * p[i + 1];
    }
    dp
}

/// C `polish_isolated`: the one simple root of p in (a, b), p(a) = pa > 0 > pb = p(b), by
/// safeguarded Newton from the regula falsi point.
fn polish_isolated(p: &[f64], n: usize, a: f64, b: f64, pa: f64, pb: f64) -> f64 {
    let dp = derivative(p, n);
    let mut x0 = a + (b - a) * (pa / (pa - pb));
    if !(x0 > a && x0 < b) {
        x0 = split_point(a, b);
    }
    count::phase(2);
    refine_root(p, &dp, n, a, b, 1, 0.0, x0)
}

pub(super) enum Isolation {
    Isolated(f64, bool),
    /// isolated by the derivative method (C SCANNED: never_late looks again)
    Scanned(f64, bool),
    Cleared,
    Unresolved(f64),
}

/// C `isolate_first_root`: the first event in (0, T] for p (T <= FAST_LIMIT, p(0) > 0) by
/// Budan-Fourier bisection.  `failed_w`: the window on which `cleared_at_once` has already
/// run the first exclusion test at 0 and failed (0: none), so that it is not run again.
#[inline(always)]
pub(super) fn isolate_first_root(p: &[f64], n: usize, skin: f64, t_end: f64, failed_w: f64) -> Isolation {
    count::phase(1);
    let e = if skin >= 0.0 { noise_factor(n) } else { 0.0 };
    let sk = if skin > 0.0 { skin } else { 0.0 };
    let mut a_slot = MaybeUninit::<Point>::uninit();
    let a = point_at_zero(p, n, e, sk, &mut a_slot);
    if !(a.qt(0) - a.tol(0) > 0.0) {
        return Isolation::Unresolved(0.0);
    }
    // Descartes, or q(0) beats every negative term (unless that very test has failed already:
    // cleared_at_once)
    if a.vq == 0 || (t_end != failed_w && clearly_positive(a, n, t_end, 1)) {
        return Isolation::Cleared;
    }
    // A guess first, then a certificate: the guess (Laguerre from 0) and one Bernstein test on
    // (0, r (1 + 2^-20)] settle most solves with a root, which the test on the whole window
    // before them only delayed (measured: see the C source).
    let (mut touch, mut dip) = (0.0, 0.0);
    // a root to certify: (the certificate's end, Newton's start, refine_root's tol) -- after a
    // step past the root, the step's end and plain evaluation first
    let certify = match speculate_first_root(p, n, t_end, &mut dip) {
        Guess::Root(r) => Some((r, r, PRECISE_NOW)),
        Guess::Overshot { start, over } => Some((over, start, 0.0)),
        Guess::Touch(x) => {
            touch = x;
            None
        }
        Guess::Nothing => None,
    };
    if let Some((end, start, tol)) = certify {
        let w = end + end * SPECULATE_MARGIN;
        let w = if w < t_end { w } else { t_end };
        // the polish's first step ahead of the certificate, its chain beside the Bernstein
        // sums (see the C source); counted where the polish uses it
        let dp = derivative(p, n);
        let first = if tol < 0.0 && scale_exponent(start, n) == 0 {
            Some(compensated_slope_ahead(p, &dp, n, start))
        } else {
            None
        };
        count::phase(1);
        if let Bernstein::One(_) = bernstein_test(a, n, w, None) {
            count::phase(2);
            return Isolation::Isolated(refine_root_from(p, &dp, n, 0.0, w, 1, tol, start, first), false);
        }
    }
    count::phase(1);
    let mut from = 0.0; // > 0: (0, from] is settled, the counts go on from it
    // A touch ahead: (0, lo] certified clear by the Bernstein test (q's coefficients all
    // positive), then the derivative method settles (lo, hi] -- small, so with few roots of
    // the derivatives in it -- and the counts go on from hi if it finds nothing there.  This
    // replaces, on the grazes, the Taylor points that bisect down to the touch and the
    // derivative method on the wide interval they leave.  hi is 3 widths to the right: from
    // the middle of a symmetric interval (the critical point to within rounding) the fma
    // noise of p' there sent the derivative method's Newton into bisection, to a neighbour of
    // an exact double root (see the C source).  Not for the no-graze baseline (skin < 0),
    // whose answers stay as they were.  Before the test on the whole window, which a touch
    // ahead leaves undecided (q dips to 0 there; see the C source).
    if touch > 0.0 && skin >= 0.0 {
        let lo = touch - touch * TOUCH_WIDTH;
        let hi = touch + 3.0 * touch * TOUCH_WIDTH;
        let hi = if hi < t_end { hi } else { t_end };
        if let Bernstein::Clear = bernstein_test(a, n, lo, None) {
            // p convex around the touch, its critical point certified in one pass
            // (touch_critical), else the derivative method (see the C source)
            count::phase(3);
            let d = derivative_rows(p, n, n - 2);
            let critical = touch_critical(p, &d, n, lo, hi, touch);
            let convex = critical.is_some();
            let hit = match critical {
                Some(b) => {
                    // (b < hi: no scaling at b when none at hi, touch_critical's)
                    let tv = touch_values(p, d.row(n - 1), d.row(n - 2), n, b, hi);
                    scan_pieces(p, &d, n, lo, hi, &[b], skin, Some(&tv))
                }
                None => derivative_method(p, n, lo, hi, touch, skin),
            };
            count::phase(1);
            // (on (lo, hi], convex by touch_critical's certificate, p falls to b alone: no
            // crossing pair can hide there, not scanned)
            if let Some((t, g)) = hit {
                return if convex { Isolation::Isolated(t, g) } else { Isolation::Scanned(t, g) };
            }
            if hi == t_end {
                return Isolation::Cleared;
            }
            from = hi;
        }
    }
    if from == 0.0 {
        // the whole window, unless a touch's interval settled (0, from]
        let mut start = Start { q: [0.0; MAXN + 1], err: 0.0, even: false };
        match bernstein_test(a, n, t_end, Some(&mut start)) {
            Bernstein::Clear => return Isolation::Cleared,
            Bernstein::One(p_end) => {
                return Isolation::Isolated(polish_isolated(p, n, 0.0, t_end, a.px, p_end), false)
            }
            Bernstein::Unknown => {}
        }
        if start.even && bernstein_clear(&start.q, start.err, n, dip / t_end) {
            // (after a guess that failed)
            return Isolation::Cleared;
        }
    }
    let mut slot = MaybeUninit::<Taylor>::uninit();
    let tb = taylor_table(p, n, e, sk, &mut slot);
    // The right ends, as in C an uninitialised array of which stack[..top] is in use (zeroing
    // 41 points would cost more than most solves); point_at writes a slot in place.
    let mut stack: [MaybeUninit<Point>; MAX_SPLITS + 1] = [const { MaybeUninit::uninit() }; MAX_SPLITS + 1];
    let mut top = 0usize;
    let mut splits = 0usize;
    if !point_at(tb, n, t_end, &mut stack[top]) {
        // (C: *a_out = from when from > 0, else the 0 it started with)
        return Isolation::Unresolved(from);
    }
    top += 1;
    // after a touch the counts start at from: a, the point at 0 until now, is the one there
    let a = if from > 0.0 {
        if !point_at(tb, n, from, &mut a_slot) {
            return Isolation::Unresolved(from);
        }
        // SAFETY: point_at_zero wrote every field of a_slot, and point_at has just rewritten
        // them all (it returned true).
        let a = unsafe { a_slot.assume_init_mut() };
        if !(a.qt(0) - a.tol(0) > 0.0) {
            return Isolation::Unresolved(from);
        }
        a
    } else {
        a
    };
    let mut tested = from == 0.0; // (0, T] has had its Bernstein test
    let mut early_tried = false;
    loop {
        // SAFETY: stack[..top] was written by point_at (every field: x, px, vp, vq; the arrays
        // are MaybeUninit, their entries 0..=n written).
        let b = unsafe { stack[top - 1].assume_init_ref() };
        let w = b.x - a.x;
        let odd = (a.vp - b.vp) % 2 != 0;
        if a.vq == b.vq || (!odd && (clearly_positive(a, n, w, 1) || clearly_positive(b, n, w, -1))) {
            a.assign(b, n);
            tested = false;
            top -= 1;
            if top == 0 {
                return Isolation::Cleared;
            }
            continue;
        }
        if a.vp - b.vp == 1 && a.vq - b.vq == 1 {
            return Isolation::Isolated(polish_isolated(p, n, a.x, b.x, a.px, b.px), false);
        }
        // Descartes in the Bernstein basis where the counts fail: only for an odd count (a
        // root certain), and not again for (0, T] (see the C source)
        if odd && !tested && matches!(bernstein_test(a, n, w, None), Bernstein::One(_)) {
            return Isolation::Isolated(polish_isolated(p, n, a.x, b.x, a.px, b.px), false);
        }
        tested = false;
        // Two roots in (a, b] by both counts within a quarter of b (mostly a touch): to the
        // derivative method at once, once per solve; else split, at the tangent rule's point,
        // or just beyond a when the tangent meets 0 within MIN_WIDTH of it (see the C source)
        let bx = b.x;
        let early = !early_tried && a.vp - b.vp == 2 && a.vq - b.vq == 2 && w <= EARLY_WIDTH * bx;
        early_tried |= early;
        if !early {
            let mut m = isolation_split(a.x, bx);
            let mt = a.x + SPLIT_NEWTON * (-a.px / a.dpx);
            let hair = a.x + 4.0 * MIN_WIDTH * bx;
            if splits == 0 && dip > a.x + DIP_INSIDE * w && dip < bx - DIP_INSIDE * w {
                m = dip; // the first split where the failed guess saw p dip (C says why)
            } else if a.dpx < 0.0 && mt > a.x && mt < bx && mt - a.x > MIN_WIDTH * bx {
                m = mt;
            } else if a.dpx < 0.0 && mt > a.x && mt - a.x <= MIN_WIDTH * bx && hair < bx {
                m = hair;
            }
            if splits < MAX_SPLITS && w > MIN_WIDTH * bx && m > a.x && m < bx && point_at(tb, n, m, &mut stack[top]) {
                splits += 1;
                top += 1;
                continue;
            }
        }
        // SAFETY: as above.
        let b = unsafe { stack[top - 1].assume_init_ref() };
        let hit = derivative_method(p, n, a.x, b.x, 0.0, skin);
        count::phase(1);
        if let Some(hit) = hit {
            return Isolation::Scanned(hit.0, hit.1);
        }
        if !(b.qt(0) - b.tol(0) > 0.0) {
            return Isolation::Unresolved(b.x);
        }
        a.assign(b, n);
        top -= 1;
        if top == 0 {
            return Isolation::Cleared;
        }
    }
}
