"""What every language's harness shares: the units it runs, the outcomes it returns, and the
plumbing (generating a module, rendering a driver, running a tool, reading the driver's lines).

Every driver prints one line per case:  VARIANT DEGREE c0 .. cDEGREE | STATUS T
where STATUS is 1 when T is the first root in (0, tmax], and every number is written so that
it comes back bit for bit (each harness says how: hex floats, bit patterns, 32-bit halves).
"""

from __future__ import annotations

import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from ..codegen.emit import module_name, template
from ..codegen.generate import generate
from . import LANGUAGES
from ..codegen.poly import Polynomial
from ..front.spec import Spec
from ..codegen.variants import DEFAULT_STRATEGY


class HarnessError(Exception):
    """A tool is missing, or a build or run failed: the message says which and shows its output."""


@dataclass(frozen=True)
class Case:
    params: tuple[float, ...]
    tmax: float


@dataclass(frozen=True)
class Unit:
    """One equation to build and run on its cases."""

    spec: Spec
    poly: Polynomial
    cases: tuple[Case, ...]

    @property
    def name(self) -> str:
        return module_name(self.spec)


@dataclass(frozen=True)
class Outcome:
    variant: int
    degree: int
    coefficients: tuple[float, ...]  # up to the degree used
    root: float | None


class Harness:
    """Builds and runs one language's generated modules; subclasses implement `run`."""

    lang: str = ""
    tools: tuple[str, ...] = ()

    def run(self, units: list[Unit], workdir: Path, build_dir: Path) -> dict[str, list[Outcome]]:
        """Outcomes per unit name. `workdir` is private to this run; `build_dir` persists
        between runs (for caches such as Cargo's target folder)."""
        raise NotImplementedError

    # -- helpers for subclasses ---------------------------------------------------------------

    def module_text(self, unit: Unit, out: Path) -> tuple[str, tuple[tuple[str, str], ...]]:
        result = generate(unit.spec, unit.poly, LANGUAGES[self.lang], "module", str(out),
                          DEFAULT_STRATEGY, True)
        return result.text, result.companions

    def write_module(self, unit: Unit, workdir: Path, extension: str) -> tuple[Path, Path]:
        """A fresh folder for the unit holding its generated module (and any companion, such as
        a Modula-2 .def): (folder, module path)."""
        folder = workdir / unit.name
        folder.mkdir()
        module = folder / f"{unit.name}{extension}"
        text, companions = self.module_text(unit, module)
        module.write_text(text)
        for path, companion in companions:
            Path(path).write_text(companion)
        return folder, module

    def render(self, **data: object) -> str:
        return template(self.lang, "harness").render(**data)


def tool(name: str) -> str:
    """The tool's path; also looks in ~/.cargo/bin (rustup's default, often not on PATH)."""
    found = shutil.which(name)
    if found is None:
        home = Path.home() / ".cargo" / "bin" / name
        if home.exists():
            return str(home)
        raise HarnessError(f"'{name}' is not installed")
    return found


def run(cmd: list[str], **kw: object) -> str:
    """Run a build or driver step; its standard output, or a HarnessError showing what failed."""
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, **kw)  # type: ignore[call-overload]
    except OSError as exc:
        raise HarnessError(f"{cmd[0]}: {exc}") from None
    if proc.returncode != 0:
        raise HarnessError(f"{' '.join(map(str, cmd))} failed (exit {proc.returncode}):\n"
                           f"{proc.stdout[-3000:]}{proc.stderr[-3000:]}")
    return proc.stdout


def parse_lines(text: str, count: int, decode: Callable[[str], float]) -> list[Outcome]:
    lines = text.splitlines()
    if len(lines) != count:
        raise HarnessError(f"the driver printed {len(lines)} lines for {count} cases:\n"
                           + text[-2000:])
    out = []
    for line in lines:
        left, right = line.split(" | ")
        fields = left.split()
        variant, degree = int(fields[0]), int(fields[1])
        coefs = tuple(decode(x) for x in fields[2:])
        if len(coefs) != degree + 1:
            raise HarnessError(f"degree {degree} but {len(coefs)} coefficients: {line}")
        status, value = right.split()
        out.append(Outcome(variant, degree, coefs, decode(value) if status == "1" else None))
    return out


def bits_hex(x: float) -> str:
    import struct
    return f"{struct.unpack('<Q', struct.pack('<d', x))[0]:016x}"


def from_bits_hex(s: str) -> float:
    import struct
    return struct.unpack("<d", struct.pack("<Q", int(s, 16)))[0]
