//! The C runtime's cost accounting (`-DM2C_COUNT`: `m2c_count`, `COUNT`, `COUNT_MADDS`,
//! `PHASE`), at the same places, so that a test can check that this port takes C's path step
//! for step and not only that it gives C's answers (answers are robust to a skipped step: a
//! root is polished to the last bit from any bracket).  Compiled in only with the cargo
//! feature `count`; without it every function here is empty and inlined away.
//!
//! The counters, as C's `m2c_count`: 0-3 multiply-adds by phase (0 preparation, 1
//! Budan-Fourier counts and exclusion tests, 2 Newton polishing and speculation, 3 the
//! derivative method), 4 and 5 Newton steps with plain and with compensated evaluation,
//! 6 Taylor points, 7 derivative-method calls, 8 solves, 9 Bernstein tests.  Per thread (the
//! unit tests run in parallel threads).

#[cfg(feature = "count")]
mod on {
    use std::cell::Cell;

    thread_local! {
        pub(super) static COUNTS: Cell<[f64; 10]> = const { Cell::new([0.0; 10]) };
        pub(super) static PHASE: Cell<usize> = const { Cell::new(0) };
    }
}

/// C `COUNT(i)`.
#[inline(always)]
pub(crate) fn event(i: usize) {
    #[cfg(feature = "count")]
    on::COUNTS.with(|c| {
        let mut v = c.get();
        v[i] += 1.0;
        c.set(v);
    });
    #[cfg(not(feature = "count"))]
    let _ = i;
}

/// C `COUNT_MADDS(k)`: k multiply-adds in the current phase.
#[inline(always)]
pub(crate) fn madds(k: usize) {
    #[cfg(feature = "count")]
    on::COUNTS.with(|c| {
        let mut v = c.get();
        v[on::PHASE.with(std::cell::Cell::get)] += k as f64;
        c.set(v);
    });
    #[cfg(not(feature = "count"))]
    let _ = k;
}

/// C `PHASE(p)`.
#[inline(always)]
pub(crate) fn phase(p: usize) {
    #[cfg(feature = "count")]
    on::PHASE.with(|c| c.set(p));
    #[cfg(not(feature = "count"))]
    let _ = p;
}

/// The counters of this thread (see the module docs), and zeros them.
#[cfg(feature = "count")]
pub fn take() -> [f64; 10] {
    on::COUNTS.with(|c| c.replace([0.0; 10]))
}
