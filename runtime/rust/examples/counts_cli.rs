//! The Rust runtime's answers and its cost accounting (cargo feature `count`), per solve, in
//! the format of tests/runtime/counts_driver.c with `--madds` (the C runtime built with
//! -DM2C_COUNT), for tests/runtime/test_rust_control_flow.py.
//!
//! Each input line:   `METHOD EPS TMAX DEGREE C0 .. CDEGREE` (decimal, exact round-trip forms;
//! `inf`/`nan` accepted).  EPS != 0 calls `first_root_skin` (METHOD then ignored), else
//! `first_root_status` with METHOD 0 (interval) or 1 (interval without the graze check).
//! Each output line:  `STATUS T GRAZE PLAIN PRECISE POINTS DERIVATIVE BERNSTEIN M0 M1 M2 M3`
//! with STATUS 1 (root), 0 (none) or -1 (invalid) as C's, T the shortest round-trip decimal
//! (0 unless STATUS is 1), and the counters of `take_counts` as C's `m2c_count`: Newton steps
//! with plain and with compensated evaluation, Taylor points, derivative-method calls,
//! Bernstein tests, then the multiply-adds by phase.

use max2code_runtime::{first_root_skin, first_root_status, take_counts, Method, Status};
use std::io::{self, BufRead, BufWriter, Write};

fn main() {
    let mut out = BufWriter::new(io::stdout().lock());
    for line in io::stdin().lock().lines() {
        let line = line.expect("stdin");
        let w: Vec<&str> = line.split_whitespace().collect();
        if w.len() < 4 {
            continue;
        }
        let num = |s: &str| s.parse::<f64>().unwrap_or_else(|e| panic!("bad number {s:?}: {e}"));
        let method = if w[0] == "1" { Method::IntervalNoGraze } else { Method::Interval };
        let (eps, tmax) = (num(w[1]), num(w[2]));
        let degree: usize = w[3].parse().expect("degree");
        let c: Vec<f64> = w[4..].iter().take(degree + 1).map(|s| num(s)).collect();
        take_counts();
        let st = if eps != 0.0 { first_root_skin(&c, tmax, eps) } else { first_root_status(&c, tmax, method) };
        let k = take_counts();
        let (code, t, g) = match st {
            Status::Root { t, graze } => (1, t, u8::from(graze)),
            Status::NoRoot => (0, 0.0, 0),
            Status::Invalid => (-1, 0.0, 0),
        };
        writeln!(out, "{code} {t:?} {g} {:.0} {:.0} {:.0} {:.0} {:.0} {:.0} {:.0} {:.0} {:.0}", k[4], k[5], k[6], k[7], k[9], k[0], k[1], k[2], k[3])
            .expect("stdout");
    }
}
