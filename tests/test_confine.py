"""What max2code/maxima/confine.py gives a child process, observed from inside the child: the environment, the
resource limits, the parent-death signal, and (with Landlock) no writes and no reads outside
what it is given. The child is a Python interpreter reporting on itself, started exactly as
Maxima is (confine.environment, confine.preexec)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from max2code.maxima import confine, session as maxima
from max2code.diagnostics import Max2CodeError

CHILD = r"""
import ctypes, json, os, resource, sys
libc = ctypes.CDLL(None)
death = ctypes.c_int(0)
libc.prctl(2, ctypes.byref(death), 0, 0, 0)  # PR_GET_PDEATHSIG
def attempt(action):
    try:
        action()
        return "allowed"
    except OSError as exc:
        return exc.strerror
secret, written = sys.argv[1], sys.argv[2]
print(json.dumps({
    "env": sorted(os.environ),
    "as": resource.getrlimit(resource.RLIMIT_AS), "cpu": resource.getrlimit(resource.RLIMIT_CPU),
    "core": resource.getrlimit(resource.RLIMIT_CORE), "death": death.value,
    "read": attempt(lambda: open(secret).read()),
    "write": attempt(lambda: open(written, "w").write("x")),
}))
"""


def child(tmp_path: Path, sandbox: bool) -> dict:
    secret = tmp_path / "secret.txt"
    secret.write_text("secret\n")
    private = tmp_path / "private"
    private.mkdir(exist_ok=True)
    python = os.path.realpath(sys.executable)
    readable = (sys.prefix, sys.base_prefix, os.path.dirname(os.path.dirname(python)), str(private))
    proc = subprocess.run([python, "-S", "-c", CHILD, str(secret), str(tmp_path / "written.txt")],
                          env=confine.environment(str(private)), capture_output=True, text=True,
                          preexec_fn=confine.preexec(confine.Limits(30.0, 1024), readable, sandbox),
                          timeout=60)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_environment_limits_and_death_signal(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("AWS_SECRET_ACCESS_KEY", "x")
    monkeypatch.setenv("MAXIMA_LISP", "gcl")
    seen = child(tmp_path, sandbox=False)
    assert "AWS_SECRET_ACCESS_KEY" not in seen["env"] and "MAXIMA_LISP" in seen["env"]
    assert set(seen["env"]) <= {"PATH", "HOME", "MAXIMA_USERDIR", "TMPDIR", "LANG", "LC_ALL",
                                "GCL_MEM_MULTIPLE", "MAXIMA_LISP", "GCL_GC_PAGE_MAX", "SBCL_HOME",
                                "LC_CTYPE"} | {k for k in os.environ if k.startswith(("MAXIMA_", "GCL_"))}
    assert seen["as"] == [1024 * 1024 * 1024] * 2
    assert seen["cpu"] == [30 + confine.CPU_GRACE_SECONDS, 35 + confine.CPU_GRACE_SECONDS]
    assert seen["core"] == [0, 0]
    assert seen["death"] == 9  # SIGKILL when max2code dies
    assert seen["write"] == "allowed" and seen["read"] == "allowed"  # no sandbox asked for


def test_the_sandbox_forbids_writes_and_foreign_reads(tmp_path: Path) -> None:
    if confine.landlock_abi() < 1:
        pytest.skip("this kernel has no Landlock: only the Lisp lock-down applies")
    seen = child(tmp_path, sandbox=True)
    assert seen["write"] == "Permission denied"
    assert seen["read"] == "Permission denied"
    assert not (tmp_path / "written.txt").exists()


def test_a_memory_limit_gcl_cannot_start_under_is_refused() -> None:
    with pytest.raises(Max2CodeError, match="below the 256 MiB GCL needs to start"):
        maxima.configure(memory_mib=100)
    assert maxima.policy().memory_mib == confine.DEFAULT_MEMORY_MIB
