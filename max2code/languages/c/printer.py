"""C (C11): `#line` directives, `pow` from <math.h>, and C's keywords avoided."""

from __future__ import annotations

import re
from dataclasses import dataclass

from ...diagnostics import Pos
from ..base import Language

# Keywords of C (C89 to C23, with GNU's) and of C++, since a C header is often included from C++.
C_KEYWORDS = frozenset("""
auto break case char const continue default do double else enum extern float for goto if inline
int long register restrict return short signed sizeof static struct switch typedef union unsigned
void volatile while _Alignas _Alignof _Atomic _BitInt _Bool _Complex _Decimal128 _Decimal32
_Decimal64 _Generic _Imaginary _Noreturn _Static_assert _Thread_local alignas alignof bool
constexpr false nullptr static_assert thread_local true typeof typeof_unqual asm
and and_eq bitand bitor catch char8_t char16_t char32_t class co_await co_return co_yield compl
concept const_cast consteval constinit decltype delete dynamic_cast explicit export friend
mutable namespace new noexcept not not_eq operator or or_eq private protected public
reinterpret_cast requires static_cast template this throw try typeid typename using virtual
wchar_t xor xor_eq
""".split())

# Object-like macros of the C library (every standard header, glibc with _GNU_SOURCE) and of
# the runtime's header that no family in C_RESERVED below covers, the compilers' own (`linux`,
# `unix`, `i386` in GNU modes), and the functions the printer calls: a local of that name would
# be replaced by the macro, or hide the function. tests/test_names.py asks gcc for every macro.
C_PREDECLARED = frozenset("""
NULL EOF BUFSIZ FILENAME_MAX FOPEN_MAX TMP_MAX I INFINITY NAN MAXFLOAT DECIMAL_DIG NZERO NSIG
NGREG NGROUPS_MAX NFDBITS MINSIGSTKSZ SIGSTKSZ CHAR_BIT MB_LEN_MAX RAND_MAX CLOCKS_PER_SEC
complex imaginary errno stdin stdout stderr math_errhandling noreturn linux unix i386 i686 main
sa_handler sa_sigaction sigev_notify_attributes sigev_notify_function
sin cos tan sqrt exp log pow fabs atan atan2 asin acos sinh cosh tanh floor ceil fmod
""".split())

# Families of reserved names: the implementation's (`_X`, `__`, C11 7.1.3) and C++'s (`__`
# anywhere), <errno.h>'s E[0-9A-Z], the C library's and POSIX's macro prefixes, our own
# `m2c_`/`M2C_`/`MAX2CODE_` (the runtime, temporaries, arguments) and the module's `NAME_`.
C_RESERVED = (
    r"{module}_|_[A-Z_]|[A-Za-z0-9_]*__|(?i:m2c|max2code)_|E[0-9A-Z]|(SIG|PRI|SCN|CMPLX|SNAN)[A-Za-z0-9_]*$"
    r"|W[A-Z]+$|(si|sa|sigev|sival)_|(DBL|FLT[0-9X]*|LDBL|DEC[0-9]*|FP|U?INT(_FAST|_LEAST)?[0-9]*"
    r"|U?INTMAX|U?INTPTR|S?SIZE|PTRDIFF|WCHAR|WINT|[SU]?CHAR|U?SHRT|U?LONG|U?LLONG|BOOL|MATH"
    r"|HUGE|M|FE|LC|MB|RAND|EXIT|TMP|CLOCKS?|TIME|TIMER|ATOMIC|ONCE|TSS|MTX|THRD|SA|SI|SS|SV"
    r"|SEGV|BUS|CLD|ILL|FPE|POLL|TRAP|STA|MOD|ADJ|REG|SEEK|RENAME|XATTR|CLOSE|PTHREAD|SCHED|CPU"
    r"|FD|STD[A-Z]*|TTY|HOST|LOGIN|NAME|PATH|PIPE|LINE|RTSIG|SEM|MQ|AIO|DELAYTIMER|COLL"
    r"|CHARCLASS|MAX|EXPR|RE|BC|NL|IOV|WORD|BYTE|BIG|LITTLE|PDP|[FLOPRSWX])_"
)


def c_string(text: str) -> str:
    """A C string literal (as `#line` takes it) holding exactly the bytes of `text`: quotes and
    backslashes escaped, `?` as `\\?` (no trigraph under -std=c11), every other byte outside
    printable ASCII as an octal escape (a file name's undecodable bytes come back as they were)."""
    out = ['"']
    for byte in text.encode("utf-8", "surrogateescape"):
        ch = chr(byte)
        if ch in '\\"?':
            out.append("\\" + ch)
        elif 0x20 <= byte < 0x7F:
            out.append(ch)
        else:
            out.append(f"\\{byte:03o}")
    return "".join(out) + '"'


@dataclass(frozen=True)
class C(Language):
    name: str = "c"
    title: str = "C"
    extension: str = ".h"
    keywords: frozenset[str] = C_KEYWORDS
    predeclared: frozenset[str] = C_PREDECLARED
    reserved_pattern: str = C_RESERVED
    functions: tuple[tuple[str, str], ...] = (
        ("sin", "sin"), ("cos", "cos"), ("tan", "tan"), ("sqrt", "sqrt"), ("exp", "exp"),
        ("log", "log"), ("abs", "fabs"), ("atan", "atan"), ("atan2", "atan2"),
        ("asin", "asin"), ("acos", "acos"), ("sinh", "sinh"), ("cosh", "cosh"), ("tanh", "tanh"),
    )

    # No wrapping: a `#line` directive numbers the lines after it, so a statement continued on
    # more lines would claim .mxm lines past the equation.
    max_line: int = 1 << 30

    def power_call(self, base: str, exponent: str) -> str:
        return f"pow({base}, {exponent})"

    def escape(self, ident: str, why: str) -> str:
        """Out of a reserved family by a `p_` prefix, with runs of `_` made one (C reserves any
        name with `__` in it, and `_` followed by a capital)."""
        if why in ("pattern", "invalid"):
            return "p_" + re.sub(r"_+", "_", ident).strip("_")
        return super().escape(ident, why)

    def module_name_problem(self, module: str) -> str | None:
        """Every name of a C module starts `NAME_`: `m2c` would redefine the runtime's
        `m2c_first_root`, and an `M2C_` prefix its macros."""
        if module.lower() == "m2c" or module.lower().startswith("m2c_"):
            return "the prefix of the C runtime's own names"
        return None

    def line_directive(self, pos: Pos) -> str:
        return f"#line {pos.line} {c_string(pos.file)}"

    def resume_directive(self, line: int, file: str) -> str | None:
        return f"#line {line} {c_string(file)}"

    def comment_text(self, text: str) -> str:
        """Inside /* */: nothing may close the comment, or open one (gcc -Wcomment)."""
        return super().comment_text(text).replace("*/", "*\\/").replace("/*", "/\\*")
