//! Line-oriented driver for the cross-language tests.
//!
//! Each input line: `METHOD TMAX c0 c1 ... cn` with METHOD one of `interval`, `nograze`,
//! `closed` or `skin:EPS` (the default method with a contact skin), TMAX a number or `inf`.
//! Each output line: `root T GRAZE` (T with 17 significant digits, GRAZE 0 or 1), `noroot`,
//! `invalid`, or `error MESSAGE` for a line that cannot be parsed; with the argument
//! `--time`, each answer line ends with the call's wall time in ns.  Blank lines and lines
//! starting with `#` are echoed as blank lines.

use max2code_runtime::{first_root_skin, first_root_status, Method, Status};
use std::io::{self, BufRead, BufWriter, Write};
use std::time::Instant;

enum Call {
    Method(Method),
    Skin(f64),
}

fn parse(line: &str) -> Result<(Call, f64, Vec<f64>), String> {
    let mut it = line.split_whitespace();
    let method = match it.next() {
        Some("interval") => Call::Method(Method::Interval),
        Some("nograze") => Call::Method(Method::IntervalNoGraze),
        Some("closed") => Call::Method(Method::Closed),
        Some(s) if s.starts_with("skin:") => {
            Call::Skin(s[5..].parse::<f64>().map_err(|e| format!("bad skin {s:?}: {e}"))?)
        }
        other => return Err(format!("bad method {other:?}")),
    };
    let num = |s: &str| s.parse::<f64>().map_err(|e| format!("bad number {s:?}: {e}"));
    let tmax = num(it.next().ok_or("missing tmax")?)?;
    let c = it.map(num).collect::<Result<Vec<_>, _>>()?;
    Ok((method, tmax, c))
}

fn main() {
    let timed = std::env::args().nth(1).as_deref() == Some("--time");
    let stdin = io::stdin();
    let mut out = BufWriter::new(io::stdout().lock());
    for line in stdin.lock().lines() {
        let Ok(line) = line else { break };
        let line = line.trim();
        let text = if line.is_empty() || line.starts_with('#') {
            String::new()
        } else {
            match parse(line) {
                Ok((call, tmax, c)) => {
                    let start = Instant::now();
                    let st = match call {
                        Call::Method(m) => first_root_status(&c, tmax, m),
                        Call::Skin(eps) => first_root_skin(&c, tmax, eps),
                    };
                    let ns = start.elapsed().as_nanos();
                    let text = match st {
                        Status::Root { t, graze } => format!("root {t:.16e} {}", u8::from(graze)),
                        Status::NoRoot => "noroot".to_string(),
                        Status::Invalid => "invalid".to_string(),
                    };
                    if timed {
                        format!("{text} {ns}")
                    } else {
                        text
                    }
                }
                Err(e) => format!("error {e}"),
            }
        };
        if writeln!(out, "{text}").is_err() {
            return;
        }
    }
}
