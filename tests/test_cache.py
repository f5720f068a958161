"""Build conventions: the Maxima result cache, the build results cache, --jobs, dependency files,
and runtime discovery.

Whether Maxima ran is observed through a wrapper given as MAXIMA that logs each call and then
runs the real Maxima.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from conftest import ROOT

from max2code import cache, depfile


def run(*args: str, env: dict[str, str], cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "max2code", *args], capture_output=True,
                          text=True, cwd=cwd, env=env, timeout=300)


@pytest.fixture
def logged(tmp_path: Path, maxima_exe: str) -> tuple[dict[str, str], Path]:
    """An environment whose Maxima logs its calls, and the log."""
    log = tmp_path / "maxima.log"
    wrapper = tmp_path / "maxima-wrapper"
    wrapper.write_text(f'#!/bin/sh\necho run >> "{log}"\nexec "{maxima_exe}" "$@"\n')
    wrapper.chmod(0o755)
    env = {**os.environ, "MAXIMA": str(wrapper), "MAX2CODE_CACHE": str(tmp_path / "cache"),
           "PYTHONPATH": str(ROOT)}
    env.pop("MAX2CODE_NO_CACHE", None)
    return env, log


def calls(log: Path) -> int:
    return len(log.read_text().splitlines()) if log.exists() else 0


def entries(env: dict[str, str], kind: str = "v1") -> list[Path]:
    return sorted((Path(env["MAX2CODE_CACHE"]) / kind).rglob("*"), key=str)


# --- the cache module --------------------------------------------------------------------------

def test_cache_directory_order(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("MAX2CODE_CACHE", str(tmp_path / "a"))
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache.directory() == tmp_path / "a"
    monkeypatch.delenv("MAX2CODE_CACHE")
    assert cache.directory() == tmp_path / "xdg" / "max2code"
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert cache.directory() == tmp_path / "home" / ".cache" / "max2code"


def test_key_covers_script_maxima_and_loaded_files(tmp_path: Path) -> None:
    exe = tmp_path / "maxima"
    exe.write_text("one")
    mac = tmp_path / "x.mac"
    mac.write_text("f(x) := x$")
    base = cache.key("script", str(exe), (str(mac),))
    assert cache.key("script", str(exe), (str(mac),)) == base
    assert cache.key("script2", str(exe), (str(mac),)) != base
    mac.write_text("f(x) := 2*x$")
    assert cache.key("script", str(exe), (str(mac),)) != base
    exe.write_text("a different maxima")
    assert cache.key("script", str(exe), (str(mac),)) != cache.key("script", str(tmp_path), (str(mac),))


def test_corrupt_entries_are_ignored(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("MAX2CODE_CACHE", str(tmp_path))
    k = "ab" * 32
    cache.put(k, cache.Entry("output text", 1.5))
    assert cache.get(k) == cache.Entry("output text", 1.5)
    (path,) = [p for p in tmp_path.rglob("*") if p.is_file()]
    data = path.read_bytes()
    for bad in (data[:-3], data.replace(b"output text", b"outpuT text"), b"", b"\0" * 40,
                data.split(b"\n", 1)[1]):
        path.write_bytes(bad)
        assert cache.get(k) is None
    path.write_bytes(data)
    assert cache.get("cd" * 32) is None  # an entry copied under another key is not trusted
    other = path.parent.parent / "cd" / ("cd" * 32)
    other.parent.mkdir()
    shutil.copy(path, other)
    assert cache.get("cd" * 32) is None


def test_concurrent_writers_leave_whole_entries(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("MAX2CODE_CACHE", str(tmp_path))
    k = "ef" * 32
    seen: list[str] = []

    def writer(n: int) -> None:
        for i in range(40):
            cache.put(k, cache.Entry(str(n) * (1000 * (i % 7 + 1)), float(n)))
            got = cache.get(k)
            if got is not None:
                seen.append(got.output)

    threads = [threading.Thread(target=writer, args=(n,)) for n in range(1, 7)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert seen and all(len(set(s)) == 1 for s in seen)
    assert [p.name for p in tmp_path.rglob(".tmp-*")] == []


# --- the Maxima cache through the CLI ---------------------------------------------------------

def test_second_run_skips_maxima(logged: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, log = logged
    out = tmp_path / "point_line.h"
    assert run("--lang=c", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    first = out.read_bytes()
    assert calls(log) == 1 and len([p for p in entries(env) if p.is_file()]) == 1
    out.unlink()
    assert run("--lang=c", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    assert calls(log) == 1 and out.read_bytes() == first
    assert run("--lang=c", "equations/point-line.mxm", "-o", str(out), "--no-cache",
               env=env).returncode == 0
    assert calls(log) == 2


def test_corrupt_entry_is_rewritten(logged: tuple[dict[str, str], Path], tmp_path: Path,
                                    monkeypatch: pytest.MonkeyPatch) -> None:
    env, log = logged
    out = tmp_path / "o.py"
    assert run("--lang=python", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    (entry,) = [p for p in entries(env) if p.is_file()]
    good = entry.read_bytes()
    entry.write_bytes(good[: len(good) // 2])
    assert run("--lang=python", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    assert calls(log) == 2 and entry.read_bytes() != good[: len(good) // 2]
    monkeypatch.setenv("MAX2CODE_CACHE", env["MAX2CODE_CACHE"])
    assert cache.get(entry.name) is not None


def test_errors_are_not_cached(logged: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, log = logged
    bad = tmp_path / "bad.mxm"
    bad.write_text("begin\nx: 1/0;\n(t - x)^2;\nend\n")
    for _ in range(2):
        assert run("--lang=c", str(bad), env=env).returncode == 1
    assert calls(log) == 2 and [p for p in entries(env) if p.is_file()] == []


def test_loaded_file_is_found_and_keys_the_cache(logged: tuple[dict[str, str], Path],
                                                   tmp_path: Path) -> None:
    env, log = logged
    folder = tmp_path / "eq"
    folder.mkdir()
    (folder / "helper.mac").write_text("gap(t) := 1000 - 2*t $\n")
    (folder / "use.mxm").write_text('function use\nbegin\nload("helper.mac")$\ngap(t) - 4;\nend\n')
    out = tmp_path / "use.py"
    assert run("--lang=python", "eq/use.mxm", "-o", str(out), "-MD", env=env, cwd=tmp_path).returncode == 0
    assert "996" in out.read_text()
    assert (tmp_path / "use.py.d").read_text() == f"{out}: \\\n  eq/use.mxm \\\n  eq/helper.mac\n"
    assert run("--lang=python", "eq/use.mxm", "-o", str(out), env=env, cwd=tmp_path).returncode == 0
    assert calls(log) == 1
    (folder / "helper.mac").write_text("gap(t) := 2000 - 2*t $\n")
    assert run("--lang=python", "eq/use.mxm", "-o", str(out), env=env, cwd=tmp_path).returncode == 0
    assert calls(log) == 2 and "1996" in out.read_text()


# --- dependency files --------------------------------------------------------------------------

def test_depfile_options(logged: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, _ = logged
    out = tmp_path / "dir with space" / "pl.mod"
    out.parent.mkdir()
    custom = tmp_path / "deps.d"
    result = run("--lang=m2", "equations/point-line.mxm", "-o", str(out), "-MF", str(custom), "-MP",
                 env=env)
    assert result.returncode == 0, result.stderr
    esc = str(out.parent).replace(" ", "\\ ")
    assert custom.read_text() == (f"{esc}/pl.mod {esc}/pl.def: \\\n  equations/point-line.mxm\n")
    assert not (tmp_path / "dir with space" / "pl.mod.d").exists()
    bad = run("--lang=c", "equations/point-line.mxm", "-MD", env=env)
    assert bad.returncode == 2 and "needs an output file" in bad.stderr


def test_depfile_escapes_and_phony_rules() -> None:
    assert depfile.escape("a b$#c") == "a\\ b$$\\#c"
    assert depfile.text(["o.h"], ["x.mxm", "y.mac"], phony=True) == (
        "o.h: \\\n  x.mxm \\\n  y.mac\n\ny.mac:\n")


def test_depfile_is_not_written_on_failure(logged: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, _ = logged
    bad = tmp_path / "bad.mxm"
    bad.write_text("begin\n(t - 1)^2\nend\n")
    assert run("--lang=c", str(bad), "-o", str(tmp_path / "o.h"), "-MD", env=env).returncode == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.mxm", "maxima-wrapper"]


# --- max2code build: --jobs and the results cache -----------------------------------------

def test_build_jobs_is_deterministic(logged: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, _ = logged
    eqs = ["equations/point-line.mxm", "equations/circles-accel.mxm", "tests/bad/non-polynomial.mxm"]
    one = run("build", *eqs, "-o", str(tmp_path / "one"), "--no-cache", "--lang", "c", "--lang",
              "python", env=env)
    four = run("build", *eqs, "-o", str(tmp_path / "four"), "--no-cache", "-j", "4", "--lang", "c",
               "--lang", "python", env=env)
    assert one.returncode == four.returncode == 1, one.stderr + four.stderr  # one bad equation
    assert "Failed:\n\n- tests/bad/non-polynomial.mxm" in four.stdout
    strip = lambda s: [ln.rsplit("|", 4)[0] if ln.startswith("| equations") else ln  # noqa: E731
                       for ln in s.splitlines()]
    # Maxima seconds differ; everything else is the same, in the same order.
    assert [ln.split(" | ")[:4] for ln in strip(one.stdout)] == [ln.split(" | ")[:4] for ln in strip(four.stdout)]
    assert one.stderr == four.stderr
    for lang in ("c", "python"):
        for f in (tmp_path / "one" / lang).iterdir():
            assert (tmp_path / "four" / lang / f.name).read_text().replace("four", "one") == f.read_text()


def test_warm_build_runs_nothing(logged: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, log = logged
    out = tmp_path / "b"
    shipped = [str(p.relative_to(ROOT)) for p in sorted((ROOT / "equations").glob("*.mxm"))]
    cold = run("build", *shipped, "-o", str(out), env=env)
    assert cold.returncode == 0, cold.stderr
    n = calls(log)
    assert n >= 4
    files = {p: p.read_bytes() for p in out.rglob("*") if p.is_file() and p.name != "summary.md"}
    stamps = {p: p.stat().st_mtime_ns for p in files}
    victim = next(iter(files))
    victim.unlink()
    warm = run("build", *shipped, "-o", str(out), env=env)
    assert warm.returncode == 0 and calls(log) == n
    assert warm.stderr == cold.stderr
    assert {p: p.read_bytes() for p in files} == files  # the deleted one is back
    assert all(p.stat().st_mtime_ns == stamps[p] for p in files if p != victim)
    results = [p for p in entries(env, "results") if p.is_file()]
    assert len(results) >= 4  # 4, or more if max2code's own code changed between the two runs
    json.loads(results[0].read_bytes().split(b"\n", 1)[1])


# --- runtime discovery -------------------------------------------------------------------------

def test_runtime_discovery() -> None:
    env = dict(os.environ)
    c = run("runtime", "--lang", "c", "--cflags", env=env).stdout.strip()
    assert c.startswith("-I") and (Path(c[2:]) / "max2code_roots.h").is_file()
    assert Path(run("runtime", "--lang", "c", "--sources", env=env).stdout.strip()).is_file()
    assert run("runtime", "--lang", "c", "--libs", env=env).stdout.split() == ["-lgsl", "-lgslcblas", "-lm"]
    assert (Path(run("runtime", "--lang", "rust", "--dir", env=env).stdout.strip()) / "Cargo.toml").is_file()
    py = Path(run("runtime", "--lang", "python", "--dir", env=env).stdout.strip())
    assert (py / "max2code_runtime" / "__init__.py").is_file()
    m2 = run("runtime", "--lang", "m2", "--cflags", env=env).stdout.split()
    assert m2[0] == "-fiso" and (Path(m2[1][2:]) / "Max2codeRoots.def").is_file()
    everything = run("runtime", env=env)
    assert everything.returncode == 0 and "[c]" in everything.stdout and "[rust]" in everything.stdout
    assert run("runtime", "--lang", "c", "--cargo", env=env).returncode == 2
