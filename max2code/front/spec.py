"""The validated, immutable description of one .mxm file, as every later stage reads it.

Positions are kept on everything a diagnostic or a `#line` directive may point at.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..diagnostics import Pos


@dataclass(frozen=True)
class CodeBlock:
    """Target-language text from `initialise`, `term K` or `finalise`, kept verbatim.

    `lang` is None for an untagged block (it serves every language that has no tagged one).
    `pos` is where the text itself starts (just after the opening brace), for `#line`.
    """

    text: str
    pos: Pos
    lang: str | None = None


@dataclass(frozen=True)
class Term:
    index: int
    prefix: CodeBlock
    pos: Pos


@dataclass(frozen=True)
class Statement:
    """One Maxima statement of the program, with its terminator (`;` or `$`)."""

    text: str
    pos: Pos


@dataclass(frozen=True)
class Program:
    """The Maxima program; `//` comments already blanked out, `quit();` dropped."""

    statements: tuple[Statement, ...]
    pos: Pos

    @property
    def last_pos(self) -> Pos:
        """Where the equation itself is stated: the last statement, or the program start."""
        return self.statements[-1].pos if self.statements else self.pos


@dataclass(frozen=True)
class Declared:
    """A header value together with where it was written, for diagnostics."""

    value: object
    pos: Pos


@dataclass(frozen=True)
class Role:
    """`role NAME = p, q`: when all of p, q are zero the motion is simpler (a variant)."""

    name: str
    params: tuple[str, ...]
    pos: Pos


@dataclass(frozen=True)
class Spec:
    path: str
    program: Program
    terms_declared: Declared | None = None
    function: Declared | None = None
    parameters: Declared | None = None
    variable: str = "t"
    initialise: tuple[CodeBlock, ...] = ()
    terms: tuple[Term, ...] = ()
    finalise: tuple[CodeBlock, ...] = ()
    roles: tuple[Role, ...] = ()

    @property
    def parameter_order(self) -> tuple[str, ...] | None:
        return tuple(self.parameters.value) if self.parameters else None  # type: ignore[arg-type]

    @property
    def own_names(self) -> frozenset[str]:
        """The names the .mxm declares (parameters and the variable): symbols of its algebra."""
        return frozenset((*(self.parameter_order or ()), self.variable))

    def language_tags(self) -> tuple[CodeBlock, ...]:
        """Every tagged block, so a caller can check the tags against the language registry."""
        blocks = list(self.initialise) + [t.prefix for t in self.terms] + list(self.finalise)
        return tuple(b for b in blocks if b.lang is not None)

    def block_for(self, blocks: tuple[CodeBlock, ...], lang: str) -> CodeBlock | None:
        """The block tagged for `lang`, else the untagged one, else None."""
        tagged = [b for b in blocks if b.lang == lang]
        if tagged:
            return tagged[0]
        plain = [b for b in blocks if b.lang is None]
        return plain[0] if plain else None

    def term_prefixes(self, lang: str) -> dict[int, Term]:
        """Term blocks for one language by index: tagged ones win over untagged ones."""
        chosen: dict[int, Term] = {}
        for term in self.terms:
            if term.prefix.lang is None:
                chosen.setdefault(term.index, term)
        for term in self.terms:
            if term.prefix.lang == lang:
                chosen[term.index] = term
        return chosen
