"""Scene text -> data, remembering where every key and value is, for `file:line:col` errors.

JSON is parsed here (a small recursive-descent reader: the standard library's parser keeps no
positions); TOML is parsed by tomllib and its keys located by a line scan of the text (tables,
arrays of tables, `key = value` lines), which is exact for the block style scene files use and
falls back to the nearest enclosing key otherwise.
"""

from __future__ import annotations

import json
import re
import sys
from dataclasses import dataclass, field

Path = tuple  # of str (keys) and int (array indices)


@dataclass
class Located:
    data: object
    positions: dict[Path, tuple[int, int]] = field(default_factory=dict)

    def where(self, path: Path) -> tuple[int, int]:
        """The position of `path`, or of its nearest located ancestor, else 1:1."""
        p = tuple(path)
        while p:
            if p in self.positions:
                return self.positions[p]
            p = p[:-1]
        return (1, 1)


class TextError(ValueError):
    def __init__(self, line: int, col: int, message: str) -> None:
        super().__init__(message)
        self.line, self.col, self.message = line, col, message


# ---------------------------------------------------------------------------------------------
# JSON
# ---------------------------------------------------------------------------------------------

_NUMBER = re.compile(r"-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?")
_STRING = re.compile(r'"(?:[^"\\\x00-\x1f]|\\(?:["\\/bfnrt]|u[0-9a-fA-F]{4}))*"')
_WS = re.compile(r"[ \t\r\n]*")


class _JsonReader:
    def __init__(self, text: str) -> None:
        self.text = text
        self.i = 0
        self.positions: dict[Path, tuple[int, int]] = {}
        self._line_starts = [0] + [m.end() for m in re.finditer("\n", text)]

    def pos(self, i: int | None = None) -> tuple[int, int]:
        i = self.i if i is None else i
        lo, hi = 0, len(self._line_starts) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if self._line_starts[mid] <= i:
                lo = mid
            else:
                hi = mid - 1
        return lo + 1, i - self._line_starts[lo] + 1

    def fail(self, message: str, i: int | None = None) -> TextError:
        line, col = self.pos(i)
        return TextError(line, col, message)

    def ws(self) -> None:
        self.i = _WS.match(self.text, self.i).end()

    def value(self, path: Path) -> object:
        self.ws()
        if self.i >= len(self.text):
            raise self.fail("unexpected end of the file")
        ch = self.text[self.i]
        if ch == "{":
            return self.obj(path)
        if ch == "[":
            return self.arr(path)
        if ch == '"':
            return self.string()
        m = _NUMBER.match(self.text, self.i)
        if m and m.end() > self.i:
            self.i = m.end()
            return _number(m.group())
        for word, val in (("true", True), ("false", False), ("null", None)):
            if self.text.startswith(word, self.i):
                self.i += len(word)
                return val
        raise self.fail(f"unexpected {ch!r}: expected a value")

    def string(self) -> str:
        m = _STRING.match(self.text, self.i)
        if not m:
            raise self.fail("a bad string (unterminated, or a control character in it)")
        text = json.loads(m.group())
        bad = unpaired_surrogate(text)
        if bad is not None:
            raise self.fail(f"a string with an unpaired surrogate escape \\u{ord(bad):04x} "
                            "(not Unicode text)")
        self.i = m.end()
        return text

    def obj(self, path: Path) -> dict:
        self.i += 1
        out: dict = {}
        self.ws()
        if self.text.startswith("}", self.i):
            self.i += 1
            return out
        while True:
            self.ws()
            start = self.i
            if not self.text.startswith('"', self.i):
                raise self.fail("expected a key in double quotes")
            key = self.string()
            if key in out:
                raise self.fail(f"duplicate key '{key}'", start)
            self.positions[path + (key,)] = self.pos(start)
            self.ws()
            if not self.text.startswith(":", self.i):
                raise self.fail("expected ':' after the key")
            self.i += 1
            out[key] = self.value(path + (key,))
            self.ws()
            if self.text.startswith(",", self.i):
                self.i += 1
                continue
            if self.text.startswith("}", self.i):
                self.i += 1
                return out
            raise self.fail("expected ',' or '}'")

    def arr(self, path: Path) -> list:
        self.i += 1
        out: list = []
        self.ws()
        if self.text.startswith("]", self.i):
            self.i += 1
            return out
        while True:
            self.ws()
            self.positions[path + (len(out),)] = self.pos()
            out.append(self.value(path + (len(out),)))
            self.ws()
            if self.text.startswith(",", self.i):
                self.i += 1
                continue
            if self.text.startswith("]", self.i):
                self.i += 1
                return out
            raise self.fail("expected ',' or ']'")


# Integers longer than this are read as floats (an int of 100 000 digits is data, and Python's
# int() refuses more than 4300 digits): as a float it is infinite, and the checker refuses it.
_INT_DIGITS = 400


def _number(text: str) -> int | float:
    """A JSON number: an int when it is written as one and short, else a float (possibly
    infinite, as 1e400 is: the scene checker refuses it with its place)."""
    if re.fullmatch(r"-?\d+", text) and len(text) <= _INT_DIGITS:
        return int(text)
    return float(text)


def unpaired_surrogate(text: str) -> str | None:
    """The first lone surrogate (a \\ud800 escape without its pair) in text, else None: such a
    string cannot be written out as UTF-8, so it is refused where it is read."""
    m = re.search("[\ud800-\udfff]", text)
    return m.group() if m else None


def parse_json(text: str) -> Located:
    r = _JsonReader(text)
    data = r.value(())
    r.ws()
    if r.i != len(text):
        raise r.fail("unexpected text after the end of the JSON value")
    return Located(data, r.positions)


# ---------------------------------------------------------------------------------------------
# TOML
# ---------------------------------------------------------------------------------------------

_KEY = r'(?:[A-Za-z0-9_-]+|"[^"]*"|\'[^\']*\')'
_DOTTED = rf"{_KEY}(?:\s*\.\s*{_KEY})*"
_ARRAY_TABLE = re.compile(rf"\s*\[\[\s*({_DOTTED})\s*\]\]")
_TABLE = re.compile(rf"\s*\[\s*({_DOTTED})\s*\]")
_ASSIGN = re.compile(rf"\s*({_DOTTED})\s*=")


def _keys(dotted: str) -> tuple[str, ...]:
    parts = re.findall(_KEY, dotted)
    return tuple(p[1:-1] if p[:1] in "\"'" else p for p in parts)


def parse_toml(text: str) -> Located:
    try:
        import tomllib
    except ImportError as exc:  # Python 3.10
        raise TextError(1, 1, "TOML scenes need Python 3.11 or later (use JSON)") from exc
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        m = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        line, col = (int(m.group(1)), int(m.group(2))) if m else (1, 1)
        raise TextError(line, col, re.sub(r"\s*\(at line.*\)", "", str(exc))) from exc
    except ValueError as exc:  # an integer too long for int() (tomllib gives no position)
        m = max(re.finditer(r"[0-9A-Za-z_]+", text), key=lambda m: len(m.group()), default=None)
        offset = m.start() if m else 0
        line = text.count("\n", 0, offset) + 1
        col = offset - (text.rfind("\n", 0, offset) + 1) + 1
        raise TextError(line, col, f"a number too long to read (more than "
                        f"{sys.get_int_max_str_digits()} digits)") from exc
    positions: dict[Path, tuple[int, int]] = {}
    table: Path = ()
    counts: dict[Path, int] = {}          # an array of tables (its path): elements so far
    current: dict[tuple[str, ...], int] = {}   # an array of tables (its name): its last element

    def resolve(name: tuple[str, ...]) -> Path:
        """A header's path: within an array of tables' last element ([[bodies.parts]] is
        bodies[i].parts, i the last [[bodies]])."""
        out: Path = ()
        for k in range(len(name)):
            out += (name[k],)
            if k + 1 < len(name) and name[:k + 1] in current:
                out += (current[name[:k + 1]],)
        return out

    for lineno, line in enumerate(text.splitlines(), 1):
        m = _ARRAY_TABLE.match(line)
        if m:
            name = _keys(m.group(1))
            where = resolve(name)
            counts[where] = counts.get(where, -1) + 1
            current[name] = counts[where]
            table = where + (counts[where],)
            positions.setdefault(table, (lineno, m.start(1) + 1))
            continue
        m = _TABLE.match(line)
        if m:
            table = resolve(_keys(m.group(1)))
            positions.setdefault(table, (lineno, m.start(1) + 1))
            continue
        m = _ASSIGN.match(line)
        if m:
            positions.setdefault(table + _keys(m.group(1)), (lineno, m.start(1) + 1))
    return Located(data, positions)
