"""runtime/methods.toml is the one definition of the runtimes' root methods: each runtime's
constants are written from it (scripts/runtime-methods), and a hand edit of either side alone
is caught here."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import max2code_runtime as rt

from conftest import ROOT

SCRIPT = ROOT / "scripts" / "runtime-methods"
TABLE = tomllib.loads((ROOT / "runtime" / "methods.toml").read_text())["method"]


def check(root: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, str(root / "scripts" / "runtime-methods"), "--check"],
                          capture_output=True, text=True, timeout=60)


def test_every_runtime_holds_the_table() -> None:
    result = check(ROOT)
    assert result.returncode == 0, result.stderr


def test_an_edit_on_one_side_is_caught(tmp_path: Path) -> None:
    """A new method added to the table alone, or a number changed in one runtime alone."""
    shutil.copytree(ROOT / "scripts", tmp_path / "scripts")
    shutil.copytree(ROOT / "runtime", tmp_path / "runtime",
                    ignore=shutil.ignore_patterns("target", "__pycache__", "*.so", "*.o"))
    header = tmp_path / "runtime" / "c" / "max2code_roots.h"
    text = header.read_text()
    header.write_text(text.replace("#define M2C_METHOD_CLOSED 3", "#define M2C_METHOD_CLOSED 4"))
    result = check(tmp_path)
    assert result.returncode == 1 and "runtime/c/max2code_roots.h" in result.stderr
    header.write_text(text)
    assert check(tmp_path).returncode == 0
    table = tmp_path / "runtime" / "methods.toml"
    table.write_text(table.read_text() + '\n[[method]]\nname = "newton"\ncamel = "Newton"\n'
                     'number = 4\nruntimes = ["c", "m2", "python", "rust"]\ndoc = "x"\n')
    result = check(tmp_path)
    assert result.returncode == 1
    assert all(f in result.stderr for f in ("max2code_roots.h", "Max2codeRoots.def",
                                            "max2code_runtime/__init__.py", "lib.rs"))
    subprocess.run([sys.executable, str(tmp_path / "scripts" / "runtime-methods")], check=True,
                   timeout=60)
    assert check(tmp_path).returncode == 0
    assert "#define M2C_METHOD_NEWTON 4" in header.read_text()
    assert "#define M2C_METHOD_COUNT 5" in header.read_text()


def test_the_runtimes_obey_the_table() -> None:
    """Python offers exactly its methods, each answering; the next number is invalid input in
    C; Modula-2 exports every constant it defines."""
    offered = [m["name"] for m in TABLE if "python" in m["runtimes"]]
    assert rt.METHODS == tuple(offered)
    for name in offered:
        status, t, _ = rt.first_root_status([1.0, -3.0, 2.0], 10.0, method=name)
        assert (status, t) == (1, 0.5), name
    assert rt.first_root_status([1.0, -3.0, 2.0], 10.0, method="no-such")[0] == -1
    if rt.BACKEND == "c":
        from max2code_runtime import _C  # type: ignore[attr-defined]
        assert _C.solve([1.0, -3.0, 2.0], 10.0, len(TABLE), 0.0)[0] == -1
        assert _C.solve([1.0, -3.0, 2.0], 10.0, len(TABLE) - 1, 0.0)[:2] == (1, 0.5)
    definition = (ROOT / "runtime" / "m2" / "Max2codeRoots.def").read_text()
    exported = re.search(r"EXPORT UNQUALIFIED(.*?);", definition, re.S).group(1)
    for m in TABLE:
        if "m2" in m["runtimes"]:
            assert f"Method{m['camel']}" in exported, m["name"]
