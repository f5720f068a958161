"""Rust: one crate per check holding every equation's module and one driver (src/main.rs),
depending on runtime/rust (`max2code-runtime`) by path, built with `cargo build --release` and
RUSTFLAGS=-D warnings. The crate folder is named by a digest of its contents and the target
folder is shared (BUILD_DIR/cargo-target), so an unchanged check rebuilds nothing and the
runtime crate is compiled once. Numbers travel as f64 bit patterns in hex, exactly."""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

from ...output import write_if_changed
from ...paths import runtime_dir
from ..harness import Harness, Outcome, Unit, bits_hex, from_bits_hex, parse_lines, run, tool


class RustHarness(Harness):
    lang = "rust"
    tools = ("cargo",)

    def run(self, units: list[Unit], workdir: Path, build_dir: Path) -> dict[str, list[Outcome]]:
        cargo = tool("cargo")
        files = {}
        for unit in units:
            files[f"src/{unit.name}.rs"] = self.module_text(unit, Path(f"{unit.name}.rs"))[0]
        files["src/main.rs"] = self.render(names=[u.name for u in units])
        digest = hashlib.sha256(repr(sorted(files.items())).encode()
                                + str(runtime_dir("rust")).encode()).hexdigest()[:16]
        package = f"max2code-check-{digest}"
        files["Cargo.toml"] = (
            f'[package]\nname = "{package}"\nversion = "0.0.0"\nedition = "2021"\n'
            'publish = false\n\n[dependencies]\n'
            f'max2code-runtime = {{ path = "{runtime_dir("rust").as_posix()}" }}\n')
        crate = build_dir / f"crate-{digest}"
        (crate / "src").mkdir(parents=True, exist_ok=True)
        for name, text in files.items():
            write_if_changed(str(crate / name), text)
        target = build_dir / "cargo-target"
        env = {**os.environ, "CARGO_TARGET_DIR": str(target), "RUSTFLAGS": "-D warnings"}
        run([cargo, "build", "--release", "--quiet"], cwd=crate, env=env)
        stdin = "".join(" ".join([unit.name, *(bits_hex(x) for x in (case.tmax, *case.params))])
                        + "\n" for unit in units for case in unit.cases)
        lines = run([str(target / "release" / package)], input=stdin).splitlines(keepends=True)
        results, start = {}, 0
        for unit in units:
            chunk = "".join(lines[start:start + len(unit.cases)])
            results[unit.name] = parse_lines(chunk, len(unit.cases), from_bits_hex)
            start += len(unit.cases)
        return results
