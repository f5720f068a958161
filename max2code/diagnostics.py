"""Diagnostics in the gcc form `file:line:col: error: message`, so editors and build logs link them."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Pos:
    """A place in a source file; line and column count from 1 like gcc's."""

    file: str
    line: int = 1
    col: int = 1

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.col}"


@dataclass(frozen=True)
class Diagnostic:
    pos: Pos
    message: str
    severity: str = "error"

    def __str__(self) -> str:
        return f"{self.pos}: {self.severity}: {self.message}"


class Max2CodeError(Exception):
    """Raised with one or more diagnostics; the CLI prints them and exits non-zero."""

    def __init__(self, *diagnostics: Diagnostic) -> None:
        super().__init__("\n".join(str(d) for d in diagnostics))
        self.diagnostics = diagnostics


def error(pos: Pos, message: str) -> Max2CodeError:
    return Max2CodeError(Diagnostic(pos, message))
