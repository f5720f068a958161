use super::*;

const INF: f64 = f64::INFINITY;
const ALL: [Method; 3] = [Method::Interval, Method::IntervalNoGraze, Method::Closed];

/// Coefficients (ascending) of prod (t - r_i) * prod (t^2 - 2 re t + re^2 + im^2), in f64.
fn from_roots(real: &[f64], pairs: &[(f64, f64)]) -> Vec<f64> {
    let mut c = vec![1.0];
    let mul = |c: &Vec<f64>, f: &[f64]| {
        let mut out = vec![0.0; c.len() + f.len() - 1];
        for (i, a) in c.iter().enumerate() {
            for (j, b) in f.iter().enumerate() {
                out[i + j] += a * b;
            }
        }
        out
    };
    for r in real {
        c = mul(&c, &[-r, 1.0]);
    }
    for (re, im) in pairs {
        c = mul(&c, &[re * re + im * im, -2.0 * re, 1.0]);
    }
    c
}

fn root(c: &[f64], tmax: f64, m: Method) -> (f64, bool) {
    match first_root_status(c, tmax, m) {
        Status::Root { t, graze } => (t, graze),
        s => panic!("expected a root for {c:?} ({m:?}), got {s:?}"),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Small deterministic generator (no dependencies): SplitMix64.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn unif(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unif()
    }
}

#[test]
fn kahan_quadratic() {
    // a x^2 - 2 b x + c with b^2 - a c = 1 exactly: roots 1 and (b+1)/a.
    let (a, b, c) = (94906266.375, 94906267.375, 94906268.375);
    for m in ALL {
        assert_eq!(root(&[c, -2.0 * b, a], INF, m), (1.0, false));
        // reversed: roots 1 and a/c, the smaller first
        let (t, g) = root(&[a, -2.0 * b, c], INF, m);
        assert_eq!(t, a / c);
        assert!(!g);
        // the second root (c/a and 1 reciprocal pair): window excluding the first
        assert_eq!(first_root_status(&[a, -2.0 * b, c], 0.999_999_9, m), Status::NoRoot);
    }
    // the naive discriminant would have been wrong
    let naive: f64 = (2.0 * b) * (2.0 * b) - 4.0 * a * c;
    assert_ne!(naive, 4.0);
}

#[test]
fn infinite_window_keeps_a_root_near_a_tiny_constant() {
    // issue 33: a ball an ulp above a boundary, thrown up; with tmax = inf the t^2 term was
    // dropped as negligible against the rest's bound (its root -1e-16), and the root with it
    let c = [1e-16, 1.0, -4.905];
    let at_ten = first_root(&c, 10.0).expect("a root in (0, 10]");
    assert!((at_ten - 1.0 / 4.905).abs() < 1e-15);
    for m in ALL {
        assert_eq!(root(&c, INF, m), root(&c, 10.0, m), "{m:?}");
    }
}

#[test]
fn never_later_than_the_exact_first_root() {
    // issue 33, item 11: clusters inside the rounding band, each with the exact first root of
    // its coefficients (tests/runtime/exact_roots.py); answered up to 3.4e-4 relative late
    // before never_late (the third only through the leading term reduce dropped)
    let cases: [(&[f64], f64, f64); 5] = [
        (&[-4526.265110260407, -42727.67068683713, -43243.986313008056, 8486.923451889525, -128.9677850737716, -70.65389590902764, 6.269276635973642, -0.2119931648724115, 0.0026213544068177425], INF, 18.242840935185004),
        (&[-0.002419247692347698, 0.11568422999746697, -1.3819507078372428, -0.024011912462834347], 0.08361970241593972, 0.04180985086584152),
        (&[-5.121619597754312e18, 1.535294570156115e19, 5.133535999313145e18, -3.581561506212387e19, -1.1936864364923536e16, 2.046266936056272e19, 20462806090370.785, 136.71790701603214], 0.5003398148909429, 0.500289785922801),
        (&[-3.672911555825168e16, -3.273982845668814e19, 4.4853203804724896e19, -2.302840884981096e19, 5.253905943544464e18, -4.494728355956265e17, -153319395885.92047, 163.17136555397104], 2.922824995152161, 2.9221192809420873),
        (&[2.0541031863583015e20, -1.6292853547313964e21, 3.2308147721405014e21, -254362408655.78323, 4.836523629394905], 1000.0, 0.25214774805569956),
    ];
    for (c, tmax, exact) in cases {
        let (t, _) = root(c, tmax, Method::Interval);
        assert!(t <= exact * (1.0 + 4.0 * f64::EPSILON), "{t} later than {exact} for {c:?}");
        assert!(rel(t, exact) < 1e-2, "{t} far from {exact}");
    }
}

#[test]
fn linear_and_trivial() {
    assert_eq!(first_root(&[-1.0, 1.0], 1.0), Some(1.0));
    assert_eq!(first_root(&[-1.0, 1.0], 0.5), None);
    assert_eq!(first_root(&[1.0, 1.0], INF), None);
    assert_eq!(first_root(&[3.0], INF), None);
    assert_eq!(first_root(&[], INF), None);
    assert_eq!(first_root(&[0.0; 9], INF), None);
    assert_eq!(first_root(&[-6.0, 11.0, -6.0, 1.0], INF), Some(1.0));
    assert_eq!(first_root_status(&[], INF, Method::Interval), Status::Invalid);
}

#[test]
fn invalid_input() {
    for m in ALL {
        assert_eq!(first_root_status(&[f64::NAN, 1.0], 1.0, m), Status::Invalid);
        assert_eq!(first_root_status(&[1.0, f64::INFINITY], 1.0, m), Status::Invalid);
        assert_eq!(first_root_status(&[1.0, -1.0, f64::NEG_INFINITY], 1.0, m), Status::Invalid);
        assert_eq!(first_root_status(&[-1.0, 1.0], f64::NAN, m), Status::Invalid);
        assert_eq!(first_root_status(&[-1.0, 1.0], 0.0, m), Status::Invalid);
        assert_eq!(first_root_status(&[-1.0, 1.0], -1.0, m), Status::Invalid);
        assert_eq!(first_root_status(&[-1.0, 1.0], f64::NEG_INFINITY, m), Status::Invalid);
        assert_eq!(first_root_status(&[1.0; 18], 1.0, m), Status::Invalid);
        assert_ne!(first_root_status(&[1.0; 17], 1.0, m), Status::Invalid);
    }
    assert_eq!(first_root(&[f64::NAN, 1.0], 1.0), None);
    assert_eq!(try_first_root(&[f64::NAN, 1.0], 1.0), Err(InvalidInput));
    assert_eq!(try_first_root(&[1.0, 1.0], 1.0), Ok(None));
    assert_eq!(try_first_root(&[-1.0, 1.0], 1.0), Ok(Some(1.0)));
    for eps in [f64::NAN, -1e-9, f64::INFINITY] {
        assert_eq!(first_root_skin(&[-1.0, 1.0], 1.0, eps), Status::Invalid);
    }
}

#[test]
fn contact_skin() {
    // (t - 1)^2 + d: a pass at distance d above zero at t = 1, then a crossing at 3 (times 
    // (t - 3)): p = ((t-1)^2 + d)(3 - t) > 0 on (0, 3)
    let d = 1e-9;
    let c = [3.0 * (1.0 + d), -(7.0 + d), 5.0, -1.0];
    let no_skin = first_root_status(&c, INF, Method::Interval);
    assert!(matches!(no_skin, Status::Root { t, graze: false } if (t - 3.0).abs() < 1e-12), "{no_skin:?}");
    let with = first_root_skin(&c, INF, 1e-8);
    assert!(matches!(with, Status::Root { t, graze: true } if (t - 1.0).abs() < 1e-6), "{with:?}");
    // a skin below the gap changes nothing
    assert_eq!(first_root_skin(&c, INF, 1e-10), no_skin);
    assert_eq!(first_root_skin(&c, INF, 0.0), no_skin);
    // the quadratic's vertex
    let q = [1.0 + d, -2.0, 1.0];
    assert_eq!(first_root_status(&q, INF, Method::Interval), Status::NoRoot);
    assert!(matches!(first_root_skin(&q, INF, 2e-9), Status::Root { t, graze: true } if (t - 1.0).abs() < 1e-15));
}

#[test]
fn batch_matches_single_calls() {
    let rows = [[-6.0, 11.0, -6.0, 1.0], [1.0, 1.0, 1.0, 1.0], [f64::NAN, 1.0, 0.0, 0.0], [2.0, -3.0, 1.0, 0.0]];
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    let mut out = [0.0; 4];
    assert_eq!(first_roots(&flat, 3, INF, 0.0, &mut out), Ok(2));
    assert_eq!(out[0], 1.0);
    assert!(out[1].is_nan() && out[2].is_nan());
    assert_eq!(out[3], 1.0);
    assert_eq!(first_roots(&flat, 4, INF, 0.0, &mut out), Err(InvalidInput));
    assert_eq!(first_roots(&flat, 17, INF, 0.0, &mut out), Err(InvalidInput));
    // the largest degree: refused, no overflow of degree + 1 (a panic in debug builds before)
    assert_eq!(first_roots(&flat, usize::MAX, INF, 0.0, &mut out), Err(InvalidInput));
}

#[test]
fn degree_16() {
    // (t - 0.5)(t - 2)^15: first root 0.5; (t + 1)^16 - 2^16 t^8 ... a generic one by roots
    let roots = [0.5, 1.25, 2.0, 3.0, -1.0, -2.0, 4.5, 5.0, 6.0, -0.75, 7.0, 8.0, -3.0, 9.0, 10.0, 11.0];
    let c = from_roots(&roots, &[]);
    assert_eq!(c.len(), 17);
    let (t, g) = root(&c, INF, Method::Interval);
    assert!(rel(t, 0.5) < 1e-14 && !g, "{t}");
    let (t, _) = root(&c, INF, Method::IntervalNoGraze);
    assert!(rel(t, 0.5) < 1e-14, "{t}");
}

#[test]
fn roots_near_zero() {
    for r0 in [1e-7, 1e-12, 1e-30, 1e-200] {
        for (real, pairs) in [
            (vec![r0, 1.0, 2.0], vec![]),
            (vec![r0, 0.5, 3.0, -1.0], vec![]),
            (vec![r0, 1.5, -2.0, -0.25, 4.0], vec![(1.0, 2.0)]),
            (vec![r0, 0.75, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0], vec![]),
        ] {
            let c = from_roots(&real, &pairs);
            for m in ALL {
                let (t, g) = root(&c, INF, m);
                assert!(!g);
                assert!(rel(t, r0) < 4e-15, "{m:?} deg {}: {t:e} vs {r0:e}", c.len() - 1);
                let (t, _) = root(&c, 10.0, m);
                assert!(rel(t, r0) < 4e-15, "{m:?} deg {}: {t:e} vs {r0:e}", c.len() - 1);
            }
        }
    }
}

#[test]
fn touching_now_divides_by_t() {
    // t (t - 2)(t - 3): root at 0 is "now"; the next root is 2
    let c = from_roots(&[0.0, 2.0, 3.0], &[]);
    assert_eq!(c[0], 0.0);
    for m in ALL {
        assert_eq!(root(&c, INF, m).0, 2.0);
    }
    // t^3 (t - 0.5): next root 0.5
    assert_eq!(first_root(&[0.0, 0.0, 0.0, -0.5, 1.0], INF), Some(0.5));
}

#[test]
fn degree_drop() {
    // exact zeros on top
    let q = [-2.0, 1.0, 1.0]; // roots 1, -2
    for m in ALL {
        let base = first_root_status(&q, INF, m);
        assert_eq!(base, Status::Root { t: 1.0, graze: false });
        assert_eq!(first_root_status(&[-2.0, 1.0, 1.0, 0.0, 0.0, 0.0], INF, m), base);
        // a leading coefficient negligible relative to the others over the window
        assert_eq!(first_root_status(&[-2.0, 1.0, 1.0, 0.0, 1e-30], 10.0, m), base);
        assert_eq!(first_root_status(&[-2.0, 1.0, 1.0, 1e-30], INF, m), base);
        assert_eq!(first_root_status(&[-2.0, 1.0, 1.0, -1e-30, 1e-31], INF, m), base);
    }
    // relative, not absolute: a tiny polynomial keeps all its terms
    let tiny: Vec<f64> = q.iter().map(|v| v * 2f64.powi(-1000)).collect();
    assert_eq!(first_root(&tiny, INF), Some(1.0));
    let huge: Vec<f64> = q.iter().map(|v| v * 2f64.powi(1000)).collect();
    assert_eq!(first_root(&huge, INF), Some(1.0));
    // not negligible when the window is long enough for the top term to matter
    let c = [-2.0, 1.0, 1.0, 1e-30];
    match first_root_status(&c, 1e20, Method::Interval) {
        Status::Root { t, .. } => assert!(rel(t, 1.0) < 1e-15),
        s => panic!("{s:?}"),
    }
    // top term alone decides: c0 + c8 t^8
    let mut c = [0.0; 9];
    c[0] = -1e-30;
    c[8] = 1.0;
    let (t, _) = root(&c, INF, Method::Interval);
    assert!(rel(t, 1e-30f64.powf(0.125)) < 4e-16, "{t}");
}

#[test]
fn no_root_in_window() {
    for m in ALL {
        let c = from_roots(&[2.0, 3.0, -1.0], &[]);
        assert_eq!(first_root_status(&c, 1.5, m), Status::NoRoot);
        assert_eq!(root(&c, 2.0, m).0, 2.0);
        // all roots negative or complex
        let c = from_roots(&[-1.0, -2.0], &[(1.0, 1.0), (0.5, 3.0)]);
        assert_eq!(first_root_status(&c, INF, m), Status::NoRoot);
        let c = from_roots(&[-1.0, -2.0, -3.0], &[(1.0, 0.1)]);
        assert_eq!(first_root_status(&c, INF, m), Status::NoRoot);
        // Descartes: all coefficients positive
        assert_eq!(first_root_status(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0], INF, m), Status::NoRoot);
    }
}

#[test]
fn exact_double_root_quadratic() {
    // (t - 1)^2: exact zero discriminant
    assert_eq!(first_root_status(&[1.0, -2.0, 1.0], INF, Method::Interval), Status::Root { t: 1.0, graze: true });
    assert_eq!(first_root_status(&[1.0, -2.0, 1.0], INF, Method::Closed), Status::Root { t: 1.0, graze: true });
    // an exact zero is a root for every method
    assert_eq!(first_root_status(&[1.0, -2.0, 1.0], INF, Method::IntervalNoGraze), Status::Root { t: 1.0, graze: true });
    // exact double root at a critical point of a cubic: (t - 1)^2 (t - 4)
    // (the graze-checking method answers the left edge of compensated Horner's band, where a
    // crossing of rounded coefficients could hide: a few ulps early, never late, issue 33)
    let c = from_roots(&[1.0, 1.0, 4.0], &[]);
    for m in ALL {
        match first_root_status(&c, INF, m) {
            Status::Root { t, graze: true } if m == Method::Interval => {
                assert!(t <= 1.0 && rel(t, 1.0) < 1e-14, "{m:?}: {t}")
            }
            s => assert_eq!(s, Status::Root { t: 1.0, graze: true }, "{m:?}"),
        }
    }
    // (t - 0.1)^2 + tiny: negative discriminant within rounding -> graze at the vertex
    let c = [0.01 + 1e-18, -0.2, 1.0];
    let (t, g) = root(&c, INF, Method::Interval);
    assert!(g && rel(t, 0.1) < 1e-15);
    assert_eq!(first_root_status(&c, INF, Method::IntervalNoGraze), Status::NoRoot);
    // a clear miss is not a graze
    assert_eq!(first_root_status(&[0.01 + 1e-9, -0.2, 1.0], INF, Method::Interval), Status::NoRoot);
}

/// Degree-8 polynomial with a double first root at 0.3, nudged (by 4u of the evaluation
/// scale) to the side where rounding makes the pair complex: Interval reports a graze,
/// IntervalNoGraze misses it and returns the next simple root.
#[test]
fn double_first_root_degree8() {
    let others = [1.1, 1.7, -0.5, 2.5];
    let pairs = [(0.0, 1.0)];
    let mut c = from_roots(&[0.3, 0.3, 1.1, 1.7, -0.5, 2.5], &pairs);
    assert_eq!(c.len(), 9);
    let x: f64 = 0.3;
    let side: f64 = others.iter().map(|r| x - r).product::<f64>() * (x * x + 1.0);
    let scale: f64 = c.iter().enumerate().map(|(i, v)| v.abs() * x.powi(i as i32)).sum();
    c[0] += side.signum() * 4.0 * fp::U * scale;
    let (t, g) = root(&c, INF, Method::Interval);
    assert!(g, "graze expected");
    assert!((t - 0.3).abs() < 1e-7, "{t}");
    let (t2, g2) = root(&c, INF, Method::IntervalNoGraze);
    assert!(!g2);
    assert!(rel(t2, 1.1) < 1e-12, "{t2}");
    // the exact (unnudged) double root: found one way or another near 0.3 by Interval
    let c = from_roots(&[0.3, 0.3, 1.1, 1.7, -0.5, 2.5], &pairs);
    let (t, _) = root(&c, INF, Method::Interval);
    assert!((t - 0.3).abs() < 1e-7, "{t}");
    // a degree-4 graze for the closed form
    let mut c = from_roots(&[0.3, 0.3, 2.0], &[(-1.0, 0.5)]);
    let scale: f64 = c.iter().enumerate().map(|(i, v)| v.abs() * x.powi(i as i32)).sum();
    let side = (0.3f64 - 2.0) * ((0.3f64 + 1.0).powi(2) + 0.25);
    c[0] += side.signum() * 4.0 * fp::U * scale;
    for m in [Method::Interval, Method::Closed] {
        let (t, g) = root(&c, INF, m);
        assert!(g && (t - 0.3).abs() < 1e-7, "{m:?} {t} {g}");
    }
    assert_eq!(root(&c, INF, Method::IntervalNoGraze), (2.0, false));
}

#[test]
fn random_known_roots() {
    let mut rng = Rng(12345);
    let mut worst = [0.0f64; 3];
    for case in 0..4000 {
        let deg = 1 + case % 8;
        let npairs = rng.next() as usize % (deg / 2 + 1);
        let nreal = deg - 2 * npairs;
        let mut real = Vec::new();
        for _ in 0..nreal {
            // positive and negative roots, well separated (multiplicative jitter)
            let mag = rng.range(0.05, 10.0);
            real.push(if rng.unif() < 0.6 { mag } else { -mag });
        }
        let mut pairs = Vec::new();
        for _ in 0..npairs {
            pairs.push((rng.range(-5.0, 5.0), rng.range(0.2, 5.0)));
        }
        // require a minimum gap between positive roots so the test is well conditioned
        let mut pos: Vec<f64> = real.iter().copied().filter(|r| *r > 0.0).collect();
        pos.sort_by(f64::total_cmp);
        if pos.windows(2).any(|w| w[1] - w[0] < 0.05) {
            continue;
        }
        let c = from_roots(&real, &pairs);
        let tmax = if case % 3 == 0 { INF } else { rng.range(0.1, 12.0) };
        let expect = pos.iter().copied().find(|r| *r <= tmax);
        for (k, m) in ALL.iter().enumerate() {
            let s = first_root_status(&c, tmax, *m);
            match (expect, s) {
                (Some(r), Status::Root { t, graze: false }) => {
                    let e = rel(t, r);
                    worst[k] = worst[k].max(e);
                    assert!(e < 1e-9, "case {case} {m:?}: {t} vs {r}, c={c:?}");
                }
                // an expected root very close to tmax may fall either side after rounding
                (Some(r), Status::NoRoot) if rel(r, tmax) < 1e-9 => {}
                (None, Status::NoRoot) => {}
                (None, Status::Root { t, .. }) if rel(t, tmax) < 1e-9 => {}
                (e, s) => panic!("case {case} {m:?}: expected {e:?}, got {s:?}; c={c:?} tmax={tmax}"),
            }
        }
    }
    eprintln!("random_known_roots worst rel err (Interval, NoGraze, Closed): {worst:?}");
}

#[test]
fn closed_matches_interval_on_quartics() {
    let mut rng = Rng(777);
    for _ in 0..2000 {
        let c: Vec<f64> = (0..5).map(|_| rng.range(-1.0, 1.0)).collect();
        let a = first_root_status(&c, INF, Method::Interval);
        let b = first_root_status(&c, INF, Method::Closed);
        match (a, b) {
            (Status::Root { t: x, .. }, Status::Root { t: y, .. }) => {
                assert!(rel(y, x) < 1e-9, "{c:?}: {x} {y}")
            }
            (Status::NoRoot, Status::NoRoot) => {}
            _ => panic!("{c:?}: {a:?} vs {b:?}"),
        }
    }
}

#[test]
fn extreme_magnitudes_never_nan() {
    let mut rng = Rng(99);
    let specials = [0.0, -0.0, 1e-320, -5e-324, 1e154, -1e154, 1e300, -1.7e308, f64::MIN_POSITIVE];
    for case in 0..50_000 {
        let n = 1 + (rng.next() % 9) as usize;
        let c: Vec<f64> = (0..n)
            .map(|_| {
                let r = rng.next();
                if r.is_multiple_of(5) {
                    specials[(r / 5 % specials.len() as u64) as usize]
                } else {
                    let s = if r & 8 != 0 { -1.0 } else { 1.0 };
                    s * rng.unif() * 10f64.powi((rng.next() % 617) as i32 - 308)
                }
            })
            .collect();
        let tmax = match case % 4 {
            0 => INF,
            1 => 1.0,
            2 => 10f64.powi((rng.next() % 600) as i32 - 300),
            _ => f64::MAX,
        };
        for m in ALL {
            match first_root_status(&c, tmax, m) {
                Status::Root { t, .. } => {
                    assert!(t > 0.0 && t <= tmax && t.is_finite(), "{c:?} {tmax} {m:?} -> {t}")
                }
                Status::NoRoot => {}
                Status::Invalid => panic!("{c:?} {tmax} reported invalid"),
            }
        }
    }
}

#[test]
fn huge_and_tiny_roots() {
    // roots 1e154 and 2e154: c = [2e308 would overflow]; use scaled coefficients
    // (t - 1e154)(t - 2e154) / 1e308 = 2 - 3e-154 t + 1e-308 t^2
    let c = [2.0, -3e-154, 1e-308];
    for m in ALL {
        let (t, _) = root(&c, INF, m);
        assert!(rel(t, 1e154) < 1e-14, "{m:?} {t:e}");
    }
    // roots at 1e-150 and 3e-150 with unit-size leading coefficient
    let c = from_roots(&[1e-150, 3e-150], &[]);
    for m in ALL {
        let (t, _) = root(&c, INF, m);
        assert!(rel(t, 1e-150) < 1e-14, "{m:?} {t:e}");
    }
    // a root beyond f64::MAX is not reported
    assert_eq!(first_root(&[-1.0, 1e-300], INF), Some(1.0 / 1e-300));
    assert_eq!(first_root(&[-1e300, 1e-300], INF), None);
}

#[test]
fn spread_quartic_roots() {
    // TOMS 1010 style: roots 1e9, 1e6, 1e3, 1 and clusters
    for (roots, tol) in [
        (vec![1e9, 1e6, 1e3, 1.0], 1e-15),
        // conditioning of the rounded coefficients limits this one to ~1e-7
        (vec![1.003, 1.002, 1.001, 1.0], 1e-6),
        (vec![1e53, 1e50, 1e49, 1e47], 1e-15),
        (vec![1e14, 2.0, 1.0, -1.0], 1e-15),
    ] {
        let c = from_roots(&roots, &[]);
        let smallest = roots.iter().copied().filter(|r| *r > 0.0).fold(INF, f64::min);
        for m in ALL {
            let (t, _) = root(&c, INF, m);
            assert!(rel(t, smallest) < tol, "{m:?} {roots:?}: {t:e}");
        }
    }
}

/// `outweighed` reads the signs as bit masks and makes every comparison without an exit: on
/// 100,000 random vectors (degrees 3-16, alternating signs or any, zeros, negatives within
/// 1e-3 and 1e-14 of their AM-GM bound) it decides as its definition, the loop with a branch
/// on each sign and an exit at the first failure (written out here), and both answers occur.
#[test]
fn outweighed_decides_as_its_definition() {
    #[allow(clippy::neg_cmp_op_on_partial_ord)] // (the definition, as C writes it)
    fn reference(c: &Coeffs, n: usize) -> bool {
        let s = if c[0] < 0.0 { -1.0 } else { 1.0 };
        let e = 2.0 * solver::noise_factor(n);
        let k = (1.0 + e) / (1.0 - e) * (1.0 + 16.0 * (f64::EPSILON / 2.0));
        if !(s * c[n] > 0.0) {
            return false;
        }
        for i in 1..n {
            let v = s * c[i];
            if !(v < 0.0) {
                continue;
            }
            let (mut a, mut b) = (s * c[i - 1], s * c[i + 1]);
            if !(a > 0.0 && b > 0.0) {
                return false;
            }
            a *= if i >= 2 && s * c[i - 2] < 0.0 { 0.5 } else { 1.0 };
            b *= if i + 2 <= n && s * c[i + 2] < 0.0 { 0.5 } else { 1.0 };
            if !(-v * k < 2.0 * (a.sqrt() * b.sqrt())) {
                return false;
            }
        }
        true
    }
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let (mut yes, total) = (0, 100_000);
    for _ in 0..total {
        let n = 3 + (rng.unif() * 14.0) as usize;
        let s = if rng.unif() < 0.5 { -1.0 } else { 1.0 };
        let alt = rng.unif() < 0.7;
        let mut c: Coeffs = [0.0; MAXN + 1];
        for (i, ci) in c.iter_mut().enumerate().take(n + 1) {
            let r = rng.unif();
            let sg = if i == 0 { 1.0 } else if alt { if i % 2 == 1 && r < 0.6 { -1.0 } else { 1.0 } } else if r < 0.35 { -1.0 } else { 1.0 };
            let mag = (1.0 + rng.unif()) * 2f64.powi((rng.unif() * 40.0) as i32 - 20);
            *ci = if i > 0 && rng.unif() < 0.03 { 0.0 } else { s * sg * mag };
        }
        for i in 1..n {
            if !(s * c[i] < 0.0 && s * c[i - 1] > 0.0 && s * c[i + 1] > 0.0) {
                continue;
            }
            let a = s * c[i - 1] * if i >= 2 && s * c[i - 2] < 0.0 { 0.5 } else { 1.0 };
            let b = s * c[i + 1] * if i + 2 <= n && s * c[i + 2] < 0.0 { 0.5 } else { 1.0 };
            let d = (rng.unif() - 0.5) * if rng.unif() < 0.5 { 1e-3 } else { 1e-14 };
            c[i] = -s * 2.0 * a.sqrt() * b.sqrt() * (1.0 - 2e-15 * n as f64 + d);
        }
        let want = reference(&c, n);
        assert_eq!(solver::outweighed(&c, n), want, "n = {n}, c = {:?}", &c[..=n]);
        yes += usize::from(want);
    }
    assert!(yes > total / 20 && yes < total * 19 / 20, "{yes} of {total}");
}

/// `quad_roots` scales by multiplying with an exact power of two where that power is a normal
/// number (ldexp elsewhere): the same scaled coefficients as ldexp's, so the same roots and
/// discriminant, bit for bit (a zero root's sign aside), as its definition with ldexp (written
/// out here) -- on random coefficients over the whole exponent range, subnormals and the two
/// ends of the fallback (the largest coefficient below 2^-1023, or at 2^1023) included.
#[test]
fn quad_roots_scales_as_ldexp() {
    fn reference(a: f64, b: f64, c: f64) -> (Option<[f64; 2]>, f64) {
        let m = a.abs().max(b.abs().max(c.abs()));
        let e = -i64::from(fp::ilogb(m));
        let (a, b, c) = (fp::ldexp(a, e), fp::ldexp(b, e), fp::ldexp(c, e));
        let h = -0.5 * b;
        let (p, q) = (h * h, a * c);
        let d = (p - q) + (h.mul_add(h, -p) - a.mul_add(c, -q));
        if d < 0.0 {
            return (None, d);
        }
        let w = h + d.sqrt().copysign(h);
        let (r1, r2) = if w == 0.0 { (0.0, 0.0) } else { (w / a, c / w) };
        (Some([r1.min(r2), r1.max(r2)]), d)
    }
    let mut rng = Rng(0x5eed_2026_1203);
    let coefficient = |rng: &mut Rng| -> f64 {
        let k = rng.unif();
        let x = if k < 0.05 {
            0.0
        } else if k < 0.12 {
            f64::from_bits(1 + (rng.next() >> 12)) // subnormal
        } else if k < 0.2 {
            (1.0 + rng.unif()) * 2f64.powi(1000 + (rng.unif() * 24.0) as i32)
        } else {
            (1.0 + rng.unif()) * 2f64.powi((rng.unif() * 2093.0) as i32 - 1070)
        };
        if rng.unif() < 0.5 { -x } else { x }
    };
    let (mut real, mut fallback, mut total) = (0, 0, 0);
    while total < 100_000 {
        let (a, b, c) = (coefficient(&mut rng), coefficient(&mut rng), coefficient(&mut rng));
        if a == 0.0 || !(a.is_finite() && b.is_finite() && c.is_finite()) {
            continue;
        }
        total += 1;
        let m = a.abs().max(b.abs().max(c.abs()));
        fallback += usize::from(m < 2f64.powi(-1023) || m >= 2f64.powi(1023));
        let (got, want) = (solver::quad_roots(a, b, c), reference(a, b, c));
        real += usize::from(want.0.is_some());
        // bit for bit, but a zero's sign among the roots (irrelevant: a root must be > 0)
        let bits = |r: Option<[f64; 2]>| r.map(|v| v.map(|x| if x == 0.0 { 0 } else { x.to_bits() }));
        assert!(got.1.to_bits() == want.1.to_bits() && bits(got.0) == bits(want.0), "{a:e} {b:e} {c:e}: {got:?} against {want:?}");
    }
    assert!(real > 30_000 && real < 90_000 && fallback > 500, "{real} {fallback}");
}
