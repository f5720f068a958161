"""Rust: a module included into a crate that depends on the runtime crate."""

from ..entry import Entry
from .printer import Rust
from .runtime import info

ENTRY = Entry(Rust(), __name__, harness="RustHarness", runtime=info)
