//! Line-oriented driver for the cross-language tests.
//!
//! Each input line: `METHOD TMAX c0 c1 ... cn` with METHOD one of `interval`, `nograze`,
//! `closed`, TMAX a number or `inf`.  Each output line: `root T GRAZE` (T with 17
//! significant digits, GRAZE 0 or 1), `noroot`, `invalid`, or `error MESSAGE` for a line that
//! cannot be parsed.  Blank lines and lines starting with `#` are echoed as blank lines.

use max2code_runtime::{first_root_status, Method, Status};
use std::io::{self, BufRead, BufWriter, Write};

fn parse(line: &str) -> Result<(Method, f64, Vec<f64>), String> {
    let mut it = line.split_whitespace();
    let method = match it.next() {
        Some("interval") => Method::Interval,
        Some("nograze") => Method::IntervalNoGraze,
        Some("closed") => Method::Closed,
        other => return Err(format!("bad method {other:?}")),
    };
    let num = |s: &str| s.parse::<f64>().map_err(|e| format!("bad number {s:?}: {e}"));
    let tmax = num(it.next().ok_or("missing tmax")?)?;
    let c = it.map(num).collect::<Result<Vec<_>, _>>()?;
    Ok((method, tmax, c))
}

fn main() {
    let stdin = io::stdin();
    let mut out = BufWriter::new(io::stdout().lock());
    for line in stdin.lock().lines() {
        let Ok(line) = line else { break };
        let line = line.trim();
        let text = if line.is_empty() || line.starts_with('#') {
            String::new()
        } else {
            match parse(line) {
                Ok((m, tmax, c)) => match first_root_status(&c, tmax, m) {
                    Status::Root { t, graze } => format!("root {t:.16e} {}", u8::from(graze)),
                    Status::NoRoot => "noroot".to_string(),
                    Status::Invalid => "invalid".to_string(),
                },
                Err(e) => format!("error {e}"),
            }
        };
        if writeln!(out, "{text}").is_err() {
            return;
        }
    }
}
