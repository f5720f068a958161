"""Lark tree -> Spec, with `file:line:col` diagnostics for everything a user can get wrong."""

from __future__ import annotations

import difflib
import os
import re
from functools import lru_cache
from importlib import resources

from lark import Lark, Token, Transformer, Tree, v_args
from lark.exceptions import (UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken,
                             VisitError)
from lark.tree import Meta

from ..maxima import names as maxima_names
from ..diagnostics import Max2CodeError, Pos, error
from ..maxima.text import split_statements, string_end
from .spec import CodeBlock, Declared, Program, Role, Spec, Term


@lru_cache(maxsize=1)
def _parser() -> Lark:
    grammar = resources.files(__package__).joinpath("mxm.lark").read_text(encoding="utf-8")
    return Lark(grammar, parser="lalr", regex=True, propagate_positions=True, maybe_placeholders=False)


# A collision equation is a few kilobytes, and Maxima reads a program at some tens of
# statements a second (a 1 MB program did not finish in 300 s): beyond this, say so at once.
MAX_SOURCE_BYTES = 4 * 1024 * 1024


def read_source(path: str) -> str:
    """Read an .mxm file as text; CRLF and CR endings become LF so positions are plain lines."""
    try:
        with open(path, "rb") as f:
            data = f.read(MAX_SOURCE_BYTES + 1)
    except FileNotFoundError:
        raise error(Pos(path, 1, 1), "no such file") from None
    except IsADirectoryError:
        raise error(Pos(path, 1, 1), "is a directory, not an .mxm file") from None
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot read: {exc.strerror}") from None
    if len(data) > MAX_SOURCE_BYTES:
        size = os.path.getsize(path) if os.path.isfile(path) else len(data)
        raise error(Pos(path, 1, 1), f"the file is {size / 1e6:.1f} MB; an .mxm may be at most "
                    f"{MAX_SOURCE_BYTES // (1024 * 1024)} MiB (a collision equation is a few "
                    f"kilobytes, and Maxima would not finish a program this long)")
    return decode_source(data, path)


def decode_source(data: bytes, path: str) -> str:
    """An .mxm file's bytes as text (UTF-8, a byte-order mark allowed), line ends made LF."""
    if b"\0" in data:
        line = data[: data.index(b"\0")].count(b"\n") + 1
        raise error(Pos(path, line, 1), "binary data (NUL byte): not an .mxm text file")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        col = exc.start - data.rfind(b"\n", 0, exc.start)
        raise error(Pos(path, line, col), f"not UTF-8 text (invalid byte 0x{data[exc.start]:02x} at "
                    f"offset {exc.start})") from None
    return text.replace("\r\n", "\n").replace("\r", "\n")


def parse_file(path: str) -> Spec:
    return parse_text(read_source(path), path)


def parse_text(text: str, path: str) -> Spec:
    if not text.strip():
        raise error(Pos(path, 1, 1), "empty file: expected .mxm sections and a Maxima program")
    try:
        tree = _parser().parse(stand_in(text, path))
    except UnexpectedInput as exc:
        raise _syntax_error(exc, text, path) from None
    return _Builder(path, text).build(tree)


# What the pre-pass looks for in header text, and inside a block.
_HEADER = re.compile(r"//[^\n]*|/\*[\s\S]*?(?:\*/|\Z)|\{|(?<![\w])begin(?![\w])", re.I)
# Inside a block: braces, and what hides them (strings, /* */ and // comments).
_IN_BLOCK = re.compile(r'[{}"]|/\*|//')
_END_LINE = re.compile(r"^[ \t]*end\b", re.I | re.M)


def stand_in(text: str, path: str) -> str:
    """`text` with every code block and the `begin ... end` program replaced by a stand-in of
    the same length and line breaks (`{   }`, `begin  end`), so the grammar's terminals never
    scan their content. One pass, linear in the text's length whatever it holds (an unbalanced
    brace used to make the grammar's recursive regular expression backtrack for seconds)."""
    out: list[str] = []
    done = 0
    for m in _HEADER.finditer(text):
        if m.start() < done or m.group().startswith("/") or _begin_is_a_name(text, m):
            continue
        if m.group() == "{":
            end = _block_end(text, m.start(), path)
            out += [text[done:m.start()], "{", _blank(text, m.start() + 1, end - 1), "}"]
        else:
            line = _END_LINE.search(text, m.end())
            if line is None:
                raise error(_pos(text, m.start(), path),
                            "unterminated 'begin': no line starting with 'end' follows")
            end = line.end()
            out += [text[done:m.start()], text[m.start():m.end()],
                    _blank(text, m.end(), end - 3), text[end - 3:end]]
        done = end
    out.append(text[done:])
    return "".join(out)


# Where the grammar wants a NAME, `begin` is one (a parameter may be called BEGIN): after a
# comma, an `=`, or a section keyword that a name follows (the word ends the text it is
# matched against: the header up to the blanks before this `begin`).
_NAME_BEFORE = re.compile(r"(?:[,=]|(?<![\w])(?:function|parameters|variable|role|initialise|term"
                          r"|finalise))\Z", re.I)
_WORD_BEFORE = 10  # the longest keyword above, `parameters`


def _begin_is_a_name(text: str, m: re.Match[str]) -> bool:
    """Is this `begin` a name in a header list rather than the program's start? The blanks
    before it are walked back over (each text position at most once in the whole pre-pass:
    blanks before one `begin` are not before another), then a word of bounded length is
    matched, so the pre-pass stays linear."""
    if m.group() == "{":
        return False
    i = m.start()
    while i > 0 and text[i - 1] in " \t\r\n":
        i -= 1
    return _NAME_BEFORE.search(text, max(0, i - _WORD_BEFORE - 1), i) is not None


def _block_end(text: str, start: int, path: str) -> int:
    """The offset just after the '}' matching the '{' at `start` (braces in strings and
    comments do not count); an error at the '{' if there is none. An unterminated string or
    comment inside runs to the end of the text."""
    depth, i = 0, start
    while True:
        m = _IN_BLOCK.search(text, i)
        if m is None:
            raise error(_pos(text, start, path), "unterminated block: this '{' has no matching '}'")
        token, i = m.group(), m.end()
        if token == "{":
            depth += 1
        elif token == "}":
            depth -= 1
            if depth == 0:
                return i
        elif token == '"':
            i = string_end(text, m.start())
        elif token == "/*":
            i = text.find("*/", i)
            i = i + 2 if i >= 0 else -1
        else:
            i = text.find("\n", i)
        if i < 0:
            i = len(text)


def _blank(text: str, start: int, end: int) -> str:
    """Spaces for text[start:end], keeping its line breaks (so Lark's positions are right)."""
    return "\n".join(" " * len(line) for line in text[start:end].split("\n"))


def _pos(text: str, offset: int, path: str) -> Pos:
    line = text.count("\n", 0, offset) + 1
    return Pos(path, line, offset - text.rfind("\n", 0, offset))


def _syntax_error(exc: UnexpectedInput, text: str, path: str) -> Max2CodeError:
    end = Pos(path, text.count("\n") + 1, len(text) - text.rfind("\n"))
    eof_message = "unexpected end of file: expected the Maxima program (begin ... end, or a { ... } block)"
    if isinstance(exc, UnexpectedEOF):
        return error(end, eof_message)
    pos = Pos(path, exc.line, exc.column)
    if isinstance(exc, UnexpectedCharacters):
        ch = text[exc.pos_in_stream] if exc.pos_in_stream < len(text) else ""
        if ch == "{":
            return error(pos, "unterminated block: this '{' has no matching '}'")
        if ch == "}":
            return error(pos, "'}' without a matching '{'")
        if text.startswith("begin", exc.pos_in_stream):
            return error(pos, "unterminated 'begin': no line starting with 'end' follows")
        return error(pos, f"unexpected character {ch!r}")
    if isinstance(exc, UnexpectedToken):
        tok = exc.token
        if tok.type == "$END":
            return error(end, eof_message)
        if str(tok).lower() == "begin":  # BEGIN_END did not match: no closing 'end' line
            return error(pos, "unterminated 'begin': no line starting with 'end' follows")
        described = sorted(_describe(t) for t in exc.expected)
        expected = ", ".join(described)
        return error(pos, f"unexpected {_describe(tok.type)} {str(tok)[:20]!r}; expected "
                          f"{expected}{_did_you_mean(str(tok), described)}")
    return error(pos, str(exc).splitlines()[0])


def _did_you_mean(word: str, described: list[str]) -> str:
    """A misspelt section keyword (`paramters`) is named with its likely meaning, as gcc and
    Python do for a misspelt identifier."""
    keywords = [d for d in described if d.isalpha()]
    close = difflib.get_close_matches(word.lower(), keywords, n=1, cutoff=0.75)
    return f"; did you mean '{close[0]}'?" if close else ""


def _describe(terminal: str) -> str:
    names = {"BRACED": "'{ ... }' block", "BEGIN_END": "'begin ... end'", "INT": "number",
             "NAME": "name", "COMMA": "','", "$END": "end of file"}
    return names.get(terminal, terminal.lower().strip("_"))


class _Builder:
    """Walks the Lark tree once, checking what the grammar alone cannot."""

    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self.text = text  # the original: tokens of blocks and the program are stand-ins

    def original(self, tok: Token) -> str:
        return self.text[tok.start_pos:tok.end_pos]

    def pos(self, tok: Token) -> Pos:
        return Pos(self.path, tok.line or 1, tok.column or 1)

    def at(self, meta: Meta) -> Pos:
        return Pos(self.path, meta.line, meta.column)

    def block(self, tok: Token, lang: str | None) -> CodeBlock:
        """The text inside the braces; its position is that of the first character after '{'."""
        return CodeBlock(self.original(tok)[1:-1], Pos(self.path, tok.line or 1, (tok.column or 1) + 1),
                         lang)

    def build(self, tree: Tree) -> Spec:
        """The sections through _Sections (one method per grammar rule, in file order, so the
        first error in the file is the one reported), then the checks across terms."""
        sections = _Sections(self)
        try:
            sections.transform(tree)
        except VisitError as exc:  # Lark wraps what a rule's method raised
            raise exc.orig_exc from None
        assert sections.found_program is not None  # the grammar requires it
        self.check_terms(sections.terms, sections.fields.get("terms_declared"))  # type: ignore[arg-type]
        return Spec(path=self.path, program=sections.found_program,
                    initialise=tuple(sections.blocks["initialise"]), terms=tuple(sections.terms),
                    finalise=tuple(sections.blocks["finalise"]), roles=tuple(sections.roles),
                    **sections.fields)  # type: ignore[arg-type]

    def check_names(self, tokens: list, symbols_from: int | None) -> None:
        """Declared names: at most MAX_NAME characters (a C string literal of a 5000-character
        parameter name broke -pedantic's 4095), and a symbol of the equation (from index
        `symbols_from` on) must not be a name Maxima gives a value (maxima_names)."""
        for tok in tokens:
            if len(tok) > MAX_NAME:
                raise error(self.pos(tok), f"a name of {len(tok)} characters; at most {MAX_NAME}")
        if symbols_from is not None:
            maxima_names.check_declared([(str(t), self.pos(t)) for t in tokens[symbols_from:]])

    def tagged(self, children: list) -> tuple[str | None, Token]:
        """(language tag or None, the block's token); _Sections.lang_tag made the tag a str."""
        if len(children) == 2:
            return str(children[0]), children[1]
        return None, children[0]

    def check_unique(self, blocks: list[CodeBlock], lang: str | None, kind: str, pos: Pos) -> None:
        for b in blocks:
            if b.lang == lang:
                what = f"'{kind} {lang}'" if lang else f"'{kind}'"
                raise error(pos, f"duplicate {what} block (first at line {b.pos.line})")

    def check_terms(self, terms: list[Term], declared: Declared | None) -> None:
        """Per language tag, terms must run 0, 1, 2, ... once each, within the declared count."""
        by_lang: dict[str | None, list[Term]] = {}
        for term in terms:
            by_lang.setdefault(term.prefix.lang, []).append(term)
        for group in by_lang.values():
            for expected, term in enumerate(group):
                if term.index == expected:
                    continue
                earlier = [t for t in group[:expected] if t.index == term.index]
                if earlier:
                    raise error(term.pos, f"duplicate 'term {term.index}' (first at line "
                                f"{earlier[0].pos.line})")
                if term.index < expected:
                    raise error(term.pos, f"'term {term.index}' is out of order: terms must be "
                                f"given as 0, 1, 2, ...; expected 'term {expected}' here")
                later = [t for t in group[expected:] if t.index == expected]
                if later:
                    raise error(term.pos, f"'term {term.index}' is out of order: terms must be "
                                f"given as 0, 1, 2, ...; expected 'term {expected}' (line "
                                f"{later[0].pos.line}) here")
                raise error(term.pos, f"'term {expected}' is missing before 'term {term.index}'")
            if declared is not None and len(group) > int(declared.value):  # type: ignore[arg-type]
                extra = group[int(declared.value)]  # type: ignore[arg-type]
                raise error(extra.pos, f"'term {extra.index}' is beyond 'polynomial terms "
                            f"{declared.value}' (line {declared.pos.line})")

    def program(self, tok: Token) -> Program:
        raw = self.original(tok)
        if tok.type == "BEGIN_END":
            body = raw[len("begin"):]
            body = body[: body.rstrip().rfind("\n") + 1] if "\n" in body.rstrip() else ""
            offset = len("begin")
        else:
            body, offset = raw[1:-1], 1
        start = Pos(self.path, tok.line or 1, (tok.column or 1) + offset)
        return Program(split_statements(body, start), self.pos(tok))


# The longest name a .mxm may declare (C's string literals must fit 4095 characters; C99 only
# promises 63 significant characters of an identifier, gcc and the others take any length).
MAX_NAME = 255
# declarations naming things -> the index from which their names are symbols of the equation
# (None: no symbol, a module's or a role's own name)
_NAMED: dict[str, int | None] = {"function_decl": None, "parameters_decl": 0,
                                 "variable_decl": 0, "role_decl": 1}


@v_args(meta=True)
class _Sections(Transformer):
    """One method per grammar rule, which Lark calls by the rule's name, in file order: each
    checks its own section (names, counts, duplicates against the sections before it) and
    files its value where the Spec will take it."""

    def __init__(self, builder: _Builder) -> None:
        super().__init__()
        self.b = builder
        self.fields: dict[str, object] = {}
        self.seen: dict[str, Pos] = {}
        self.blocks: dict[str, list[CodeBlock]] = {"initialise": [], "finalise": []}
        self.terms: list[Term] = []
        self.roles: list[Role] = []
        self.found_program: Program | None = None  # (not `program`: that is the rule's method)

    def once(self, kind: str, meta: Meta, children: list) -> Pos:
        """A section that may appear once: a second is an error; its names are checked."""
        pos = self.b.at(meta)
        if kind in self.seen:
            raise error(pos, f"duplicate '{_keyword(kind)}' declaration "
                        f"(first at line {self.seen[kind].line})")
        self.seen[kind] = pos
        if kind in _NAMED:
            self.b.check_names(children, _NAMED[kind])
        return pos

    def lang_tag(self, meta: Meta, children: list) -> str:
        return str(children[0])

    def terms_decl(self, meta: Meta, children: list) -> None:
        pos = self.once("terms_decl", meta, children)
        count = int(children[0])
        if count < 1:
            raise error(self.b.pos(children[0]), "'polynomial terms' must be at least 1")
        self.fields["terms_declared"] = Declared(count, pos)

    def function_decl(self, meta: Meta, children: list) -> None:
        self.once("function_decl", meta, children)
        self.fields["function"] = Declared(str(children[0]), self.b.pos(children[0]))

    def parameters_decl(self, meta: Meta, children: list) -> None:
        pos = self.once("parameters_decl", meta, children)
        names = [str(c) for c in children]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise error(pos, f"parameter {dup[0]!r} is listed twice")
        self.fields["parameters"] = Declared(tuple(names), pos)

    def variable_decl(self, meta: Meta, children: list) -> None:
        self.once("variable_decl", meta, children)
        self.fields["variable"] = str(children[0])

    def initialise(self, meta: Meta, children: list) -> None:
        self.code_block("initialise", meta, children)

    def finalise(self, meta: Meta, children: list) -> None:
        self.code_block("finalise", meta, children)

    def code_block(self, kind: str, meta: Meta, children: list) -> None:
        lang, tok = self.b.tagged(children)
        self.b.check_unique(self.blocks[kind], lang, kind, self.b.at(meta))
        self.blocks[kind].append(self.b.block(tok, lang))

    def term(self, meta: Meta, children: list) -> None:
        lang, tok = self.b.tagged(children[1:])
        self.terms.append(Term(int(children[0]), self.b.block(tok, lang), self.b.at(meta)))

    def role_decl(self, meta: Meta, children: list) -> None:
        pos = self.b.at(meta)
        self.b.check_names(children, _NAMED["role_decl"])
        name, *params = [str(c) for c in children]
        for r in self.roles:
            if r.name == name:
                raise error(pos, f"duplicate role '{name}' (first at line {r.pos.line})")
        if len(set(params)) != len(params):
            raise error(pos, f"role '{name}' lists a parameter twice")
        self.roles.append(Role(name, tuple(params), pos))

    def program(self, meta: Meta, children: list) -> None:
        self.found_program = self.b.program(children[0])


def _keyword(kind: str) -> str:
    return {"terms_decl": "polynomial terms", "function_decl": "function",
            "parameters_decl": "parameters", "variable_decl": "variable"}[kind]
