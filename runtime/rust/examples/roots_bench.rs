//! Timing harness for bench/roots.py: the Rust runtime's default method, timed the way
//! bench/roots_harness.c times the C runtime.
//!
//! Input (stdin), one polynomial a line: `TMAX DEGREE C0 .. CDEGREE` (decimal, exact
//! round-trip forms).  Argument 1: number of sweeps (default 7).  Each sweep visits every
//! polynomial once in an order shuffled anew (xorshift, as the C harness), and times each call
//! on its own with `Instant` (CLOCK_MONOTONIC); the cost of an empty timed region is
//! subtracted.  The polynomials are stored as the C harness stores them, coefficients inline
//! in one array (a `Vec` per polynomial adds a dependent load from another cache line to every
//! call: measured 10-25 % of the quick solves in a shuffled stream).  Output: `# overhead_ns X`, then one line per polynomial:
//! `INDEX STATUS T NS_MEDIAN` (T with 17 significant digits, `nan` when there is no root).

use max2code_runtime::{first_root_status, Method, Status, MAX_DEGREE};
use std::hint::black_box;
use std::io::{self, BufRead, Write};
use std::time::Instant;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn main() {
    let sweeps: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(7).max(1);
    // (tmax, number of coefficients, coefficients): C's `Poly`
    let mut polys: Vec<(f64, usize, [f64; MAX_DEGREE + 1])> = Vec::new();
    for line in io::stdin().lock().lines() {
        let line = line.expect("stdin");
        let mut it = line.split_whitespace();
        let Some(tmax) = it.next().and_then(|s| s.parse::<f64>().ok()) else { continue };
        let degree: usize = it.next().and_then(|s| s.parse().ok()).expect("degree");
        let c: Vec<f64> = it.take(degree + 1).map(|s| s.parse().expect("coefficient")).collect();
        assert!(degree <= MAX_DEGREE, "degree {degree} above {MAX_DEGREE}");
        let mut inline = [0.0; MAX_DEGREE + 1];
        inline[..c.len()].copy_from_slice(&c);
        polys.push((tmax, c.len(), inline));
    }
    let mut empty: Vec<f64> = (0..4001)
        .map(|_| {
            let a = Instant::now();
            a.elapsed().as_nanos() as f64
        })
        .collect();
    let overhead = median(&mut empty);
    let n = polys.len();
    let mut ns = vec![0.0f64; n * sweeps];
    let mut answers = vec![Status::NoRoot; n];
    let mut order: Vec<usize> = (0..n).collect();
    let mut state: u64 = 88172645463325252;
    for s in 0..sweeps {
        for i in (2..=n).rev() {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            order.swap(i - 1, (state % i as u64) as usize);
        }
        for &i in &order {
            let (tmax, len, inline) = &polys[i];
            let c = &inline[..*len];
            let a = Instant::now();
            let st = first_root_status(black_box(c), black_box(*tmax), Method::Interval);
            let t = a.elapsed().as_nanos() as f64;
            black_box(st);
            ns[i * sweeps + s] = t - overhead;
            answers[i] = st;
        }
    }
    let out = io::stdout();
    let mut out = out.lock();
    writeln!(out, "# overhead_ns {overhead:.2}").unwrap();
    for i in 0..n {
        let med = median(&mut ns[i * sweeps..(i + 1) * sweeps]);
        let (st, t) = match answers[i] {
            Status::Root { t, .. } => (1, format!("{t:.16e}")),
            Status::NoRoot => (0, "nan".to_string()),
            Status::Invalid => (-1, "nan".to_string()),
        };
        writeln!(out, "{i} {st} {t} {med:.2}").unwrap();
    }
}
