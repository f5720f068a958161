"""Rust (2021 edition): `// file.mxm:LINE` comments, `f64` methods, keywords avoided.

Generated Rust must build without warnings and pass `cargo clippy -- -D warnings`:
* exact constants (`%pi`, and any float equal to one of `std::f64::consts`) are written by name,
  because clippy's `approx_constant` rejects a literal 3.141592653589793;
* parameter names that are not snake_case (`TYPE`, `X1`) would trip `non_snake_case`; renaming
  them could collide (`type` and `TYPE`), so the template allows that one lint on the function
  that binds them, and only when a name needs it (`lint_allows`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...diagnostics import Pos
from ..signed import SignedOperands

# Strict and reserved keywords (all editions; weak ones such as `union` are ordinary names).
RUST_KEYWORDS = frozenset("""
as break const continue crate else enum extern false fn for if impl in let loop match mod move
mut pub ref return self Self static struct super trait true type unsafe use where while async
await dyn abstract become box do final macro override priv typeof unsized virtual yield try gen _
""".split())
# Keywords that cannot be raw identifiers either (`r#self` is an error).
NOT_RAW = frozenset({"self", "Self", "super", "crate", "_"})

# What a `let` pattern would read as something other than a new binding (the prelude's enum
# variants), the primitive types, the crates a module names in paths, and the prelude's traits
# and types the module's code names.
RUST_PREDECLARED = frozenset("""
None Some Ok Err Option From Into Clone Copy Debug Default PartialEq
f32 f64 i8 i16 i32 i64 i128 isize u8 u16 u32 u64 u128 usize bool char str std core alloc
max2code_runtime
""".split())

# The module's own constants and types (module.j2); its private names begin `m2c_`.
RUST_GENERATED = frozenset("NAME PARAMS DEGREE STRATEGY VARIANTS Params".split())
# Its public functions and methods (and their formals): a parameter may keep such a name (a
# `Params` field `variant`), since a `let` binding shadows a function and the functions that
# bind parameters call none of these.
RUST_FUNCTIONS = frozenset("coefficients coefficients_degree first_root variant from p "
                           "tmax".split())

# Values clippy's `approx_constant` knows, by the name Rust gives them.
F64_CONSTS = (
    "E", "FRAC_1_PI", "FRAC_1_SQRT_2", "FRAC_2_PI", "FRAC_2_SQRT_PI", "FRAC_PI_2", "FRAC_PI_3",
    "FRAC_PI_4", "FRAC_PI_6", "FRAC_PI_8", "LN_10", "LN_2", "LOG10_E", "LOG2_E", "LOG2_10",
    "LOG10_2", "PI", "SQRT_2", "TAU",
)
_CONST_VALUES = {
    "E": math.e, "FRAC_1_PI": 1 / math.pi, "FRAC_1_SQRT_2": 1 / math.sqrt(2),
    "FRAC_2_PI": 2 / math.pi, "FRAC_2_SQRT_PI": 2 / math.sqrt(math.pi), "FRAC_PI_2": math.pi / 2,
    "FRAC_PI_3": math.pi / 3, "FRAC_PI_4": math.pi / 4, "FRAC_PI_6": math.pi / 6,
    "FRAC_PI_8": math.pi / 8, "LN_10": math.log(10), "LN_2": math.log(2),
    "LOG10_E": math.log10(math.e), "LOG2_E": math.log2(math.e), "LOG2_10": math.log2(10),
    "LOG10_2": math.log10(2), "PI": math.pi, "SQRT_2": math.sqrt(2), "TAU": math.tau,
}
assert set(_CONST_VALUES) == set(F64_CONSTS)


def is_snake_case(ident: str) -> bool:
    """rustc's test for the `non_snake_case` lint: no upper case, no `__` inside."""
    core = ident.removeprefix("r#").strip("_")
    return not any(ch.isupper() for ch in core) and "__" not in core


@dataclass(frozen=True)
class Rust(SignedOperands):
    name: str = "rust"
    title: str = "Rust"
    extension: str = ".rs"
    keywords: frozenset[str] = RUST_KEYWORDS
    predeclared: frozenset[str] = RUST_PREDECLARED
    reserved_pattern: str = r"(?i:m2c)_|coefficients_v[0-9]+$"
    # Rust's maths are f64 methods, written as paths (`f64::sin(x)`) so any argument text works.
    functions: tuple[tuple[str, str], ...] = tuple((m, f"f64::{r}") for m, r in (
        ("sin", "sin"), ("cos", "cos"), ("tan", "tan"), ("sqrt", "sqrt"), ("exp", "exp"),
        ("log", "ln"), ("abs", "abs"), ("atan", "atan"), ("atan2", "atan2"), ("asin", "asin"),
        ("acos", "acos"), ("sinh", "sinh"), ("cosh", "cosh"), ("tanh", "tanh")))

    def float_literal(self, value: float) -> str:
        for name, const in _CONST_VALUES.items():
            if float(value) == const:
                return f"std::f64::consts::{name}"
        return super().float_literal(value)

    def power_call(self, base: str, exponent: str) -> str:
        return f"f64::powf({base}, {exponent})"

    def generated(self, module: str) -> frozenset[str]:
        return RUST_GENERATED

    def reserved(self, ident: str, module: str | None) -> str | None:
        """A raw identifier (`r#type`) is how Rust writes a keyword as a name."""
        if ident.startswith("r#"):
            base = ident[2:]
            return None if base in self.keywords and base not in NOT_RAW else "invalid"
        return super().reserved(ident, module)

    def escape(self, ident: str, why: str) -> str:
        if why == "keyword" and ident not in NOT_RAW:
            return "r#" + ident
        return super().escape(ident, why)

    def module_name_problem(self, module: str) -> str | None:
        if module in self.keywords:
            return "a Rust keyword"
        if module in ("std", "core", "alloc", "max2code_runtime"):
            return "the name of a crate the module uses"
        return None

    def line_directive(self, pos: Pos) -> str:
        return f"// {self.comment_text(pos.file)}:{pos.line}"

    def lint_allows(self, idents: list[str]) -> str:
        """An `#[allow(...)]` line for a function binding these names, or '' if none is needed."""
        if all(is_snake_case(i) for i in idents):
            return ""
        return "#[allow(non_snake_case)] // parameter names as the .mxm spells them"
