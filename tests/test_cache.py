"""Build conventions: the Maxima result cache, the build results cache, --jobs, dependency files,
and runtime discovery.

Whether Maxima runs is controlled through a wrapper given as MAXIMA: while a flag file exists
it fails at once ("a forbidden Maxima run"), so a run that succeeds then was served by the
cache, and one that fails asked for Maxima. (A wrapper cannot log its calls to a file: Maxima
is confined and writes nothing, see max2code/maxima/confine.py.)
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

from max2code import cache
from max2code.maxima import depfile


def run(*args: str, env: dict[str, str], cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "max2code", *args], capture_output=True,
                          text=True, cwd=cwd, env=env, timeout=300)


class Switch:
    """Allows or forbids Maxima runs through the MAXIMA wrapper."""

    def __init__(self, flag: Path) -> None:
        self.flag = flag

    def forbid(self) -> None:
        self.flag.write_text("")

    def allow(self) -> None:
        self.flag.unlink(missing_ok=True)


@pytest.fixture
def logged(tmp_path: Path, maxima_exe: str) -> tuple[dict[str, str], Switch]:
    """An environment whose Maxima can be forbidden, and the switch."""
    flag = tmp_path / "forbidden"
    wrapper = tmp_path / "bin" / "maxima-wrapper"
    wrapper.parent.mkdir()
    wrapper.write_text(f'#!/bin/sh\nif [ -e "{flag}" ]; then echo "a forbidden Maxima run"; '
                       f'exit 3; fi\nexec "{maxima_exe}" "$@"\n')
    wrapper.chmod(0o755)
    env = {**os.environ, "MAXIMA": str(wrapper), "MAX2CODE_CACHE": str(tmp_path / "cache"),
           "PYTHONPATH": str(ROOT), "XDG_CONFIG_HOME": str(tmp_path / "config")}
    env.pop("MAX2CODE_NO_CACHE", None)
    return env, Switch(flag)


def entries(env: dict[str, str], kind: str = cache.MAXIMA_KIND) -> list[Path]:
    return sorted((Path(env["MAX2CODE_CACHE"]) / kind).rglob("*"), key=str)


@pytest.fixture(autouse=True)
def private_secret(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """In-process cache use signs with a secret of its own, not the user's."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    monkeypatch.setattr(cache, "_secret", None)


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
    (path,) = [p for p in (tmp_path / cache.MAXIMA_KIND).rglob("*") if p.is_file()]
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

def test_second_run_skips_maxima(logged: tuple[dict[str, str], Switch], tmp_path: Path) -> None:
    env, maxima = logged
    out = tmp_path / "point_line.h"
    assert run("--lang=c", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    first = out.read_bytes()
    assert len([p for p in entries(env) if p.is_file()]) == 1
    out.unlink()
    maxima.forbid()
    assert run("--lang=c", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    assert out.read_bytes() == first
    nocache = run("--lang=c", "equations/point-line.mxm", "-o", str(out), "--no-cache", env=env)
    assert nocache.returncode == 1 and "stopped before" in nocache.stderr  # it asked for Maxima


def test_corrupt_entry_is_rewritten(logged: tuple[dict[str, str], Switch], tmp_path: Path,
                                    monkeypatch: pytest.MonkeyPatch) -> None:
    env, _ = logged
    out = tmp_path / "o.py"
    assert run("--lang=python", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    (entry,) = [p for p in entries(env) if p.is_file()]
    good = entry.read_bytes()
    entry.write_bytes(good[: len(good) // 2])
    assert run("--lang=python", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    assert entry.read_bytes() != good[: len(good) // 2]
    monkeypatch.setenv("MAX2CODE_CACHE", env["MAX2CODE_CACHE"])
    assert cache.get(entry.name) is not None


def test_errors_are_not_cached(logged: tuple[dict[str, str], Switch], tmp_path: Path) -> None:
    env, maxima = logged
    bad = tmp_path / "bad.mxm"
    bad.write_text("begin\nx: 1/0;\n(t - x)^2;\nend\n")
    first = run("--lang=c", str(bad), env=env)
    assert first.returncode == 1 and "Maxima error: expt: undefined: 0 to a negative" in first.stderr
    maxima.forbid()
    second = run("--lang=c", str(bad), env=env)
    assert second.returncode == 1 and "stopped before" in second.stderr  # it asked Maxima again
    assert [p for p in entries(env) if p.is_file()] == []


def test_loaded_file_is_found_and_keys_the_cache(logged: tuple[dict[str, str], Switch],
                                                   tmp_path: Path) -> None:
    env, maxima = logged
    folder = tmp_path / "eq"
    folder.mkdir()
    (folder / "helper.mac").write_text("gap(t) := 1000 - 2*t $\n")
    (folder / "use.mxm").write_text('function use\nbegin\nload("helper.mac")$\ngap(t) - 4;\nend\n')
    out = tmp_path / "use.py"
    assert run("--lang=python", "eq/use.mxm", "-o", str(out), "-MD", env=env, cwd=tmp_path).returncode == 0
    assert "996" in out.read_text()
    assert (tmp_path / "use.py.d").read_text() == f"{out}: \\\n  eq/use.mxm \\\n  eq/helper.mac\n"
    maxima.forbid()
    assert run("--lang=python", "eq/use.mxm", "-o", str(out), env=env, cwd=tmp_path).returncode == 0
    (folder / "helper.mac").write_text("gap(t) := 2000 - 2*t $\n")
    assert run("--lang=python", "eq/use.mxm", "-o", str(out), env=env, cwd=tmp_path).returncode == 1
    maxima.allow()
    assert run("--lang=python", "eq/use.mxm", "-o", str(out), env=env, cwd=tmp_path).returncode == 0
    assert "1996" in out.read_text()


# --- forged entries, computed loads, the results key ------------------------------------------

def forge(entry: Path, body: bytes, env: dict[str, str]) -> list[bytes]:
    """Entries carrying `body` for `entry`'s key as a forger could write them: the old unkeyed
    checksum, and an HMAC under a secret that is not the user's."""
    import hashlib
    import hmac
    fake = hmac.new(b"f" * 64, entry.name.encode() + b"\0" + body, hashlib.sha256).hexdigest()
    return [b"max2code-cache-v1 " + hashlib.sha256(body).hexdigest().encode() + b"\n" + body,
            f"{cache.FORMAT} {hashlib.sha256(body).hexdigest()}".encode() + b"\n" + body,
            f"{cache.FORMAT} {fake}".encode() + b"\n" + body]


def test_forged_maxima_entries_are_never_used(logged: tuple[dict[str, str], Switch],
                                             tmp_path: Path) -> None:
    env, maxima = logged
    out = tmp_path / "pl.py"
    assert run("--lang=python", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    genuine = out.read_text()
    (entry,) = [p for p in entries(env) if p.is_file()]
    body = entry.read_bytes().split(b"\n", 1)[1]
    obj = json.loads(body)
    assert "-COEF 0 " in obj["output"]
    obj["output"] = obj["output"].replace("-COEF 0 ", "-COEF 0 987654321+")  # other coefficients
    evil = json.dumps(obj).encode()
    maxima.forbid()
    for forged in forge(entry, evil, env):
        entry.write_bytes(forged)
        proc = run("--lang=python", "equations/point-line.mxm", "-o", str(out), env=env)
        assert proc.returncode == 1 and "stopped before" in proc.stderr  # not used: Maxima asked
        assert out.read_text() == genuine
    maxima.allow()
    assert run("--lang=python", "equations/point-line.mxm", "-o", str(out), env=env).returncode == 0
    assert out.read_text() == genuine and b"987654321" not in entry.read_bytes()


def test_a_results_entry_never_names_a_path(logged: tuple[dict[str, str], Switch],
                                            tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Even an entry that passes the HMAC (the test knows the secret) cannot make `build`
    write outside its output folder."""
    env, _ = logged
    out = tmp_path / "b"
    args = ("build", "equations/point-line.mxm", "-o", str(out), "--lang", "python")
    assert run(*args, env=env).returncode == 0
    (entry,) = [p for p in entries(env, "results") if p.is_file()]
    obj = json.loads(entry.read_bytes().split(b"\n", 1)[1])
    assert [rel for rel, _ in obj["outputs"]] == ["python/point_line.py"]
    evil = tmp_path / "evil.txt"
    monkeypatch.setenv("MAX2CODE_CACHE", env["MAX2CODE_CACHE"])
    monkeypatch.setenv("XDG_CONFIG_HOME", env["XDG_CONFIG_HOME"])
    monkeypatch.setattr(cache, "_secret", None)
    for name in (str(evil), "../../evil.txt", "python/../../evil.txt", "python/x/../evil.txt"):
        cache.put_json(entry.name, {**obj, "outputs": [[name, "owned"]]}, "results")
        assert cache.get_json(entry.name, "results") is not None  # a valid entry...
        proc = run(*args, env=env)
        assert proc.returncode == 0, proc.stderr  # ...is not used: the build is redone
        assert not evil.exists() and not (tmp_path / "evil.txt").exists()
        assert "owned" not in (out / "python" / "point_line.py").read_text()


def test_the_current_folder_is_not_in_the_results_key(logged: tuple[dict[str, str], Switch],
                                                      tmp_path: Path) -> None:
    env, maxima = logged
    source = (ROOT / "equations" / "point-line.mxm").resolve()
    args = ("build", str(source), "-o", str(tmp_path / "b"), "--lang", "c")
    assert run(*args, env=env, cwd=tmp_path).returncode == 0
    (tmp_path / "new-file").write_text("the folder's mtime changes\n")
    os.utime(tmp_path, (5_000_000, 5_000_000))
    maxima.forbid()
    warm = run(*args, env=env, cwd=tmp_path)
    assert warm.returncode == 0, warm.stderr  # served from the results cache


def test_a_computed_load_is_never_cached(logged: tuple[dict[str, str], Switch],
                                         tmp_path: Path) -> None:
    """Issue 12: `load()` of a computed name is not in the key; a stale result (-1.0 where
    -4.0 was right) was reused. Such a run (possible with --allow-unsafe-maxima) is not cached."""
    env, _ = logged
    (tmp_path / "helper.mac").write_text("k: 1$\n")
    (tmp_path / "use.mxm").write_text('function use\nbegin\nf: "helper.mac"$\nload(f)$\n'
                                      "t - k;\nend\n")
    out = tmp_path / "use.py"
    for k in (1, 4):
        (tmp_path / "helper.mac").write_text(f"k: {k}$\n")
        for argv in (("use.mxm", "-o", str(out)), ("build", "use.mxm", "-o", "b", "--lang", "python")):
            proc = run("--lang=python", *argv, "--allow-unsafe-maxima", env=env, cwd=tmp_path) \
                if argv[0] != "build" else run(*argv, "--allow-unsafe-maxima", env=env, cwd=tmp_path)
            assert proc.returncode == 0, proc.stderr
        for text in (out.read_text(), (tmp_path / "b" / "python" / "use.py").read_text()):
            assert f"c0 = -{k}.0" in text or f"-{k}.0" in text
    assert [p for p in entries(env) if p.is_file()] == []
    assert [p for p in entries(env, "results") if p.is_file()] == []


# --- dependency files --------------------------------------------------------------------------

def test_depfile_options(logged: tuple[dict[str, str], Switch], tmp_path: Path) -> None:
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


def test_depfile_is_not_written_on_failure(logged: tuple[dict[str, str], Switch], tmp_path: Path) -> None:
    env, _ = logged
    bad = tmp_path / "bad.mxm"
    bad.write_text("begin\n(t - 1)^2\nend\n")
    assert run("--lang=c", str(bad), "-o", str(tmp_path / "o.h"), "-MD", env=env).returncode == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.mxm", "bin"]


# --- max2code build: --jobs and the results cache -----------------------------------------

def test_build_jobs_is_deterministic(logged: tuple[dict[str, str], Switch], tmp_path: Path) -> None:
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


def test_warm_build_runs_nothing(logged: tuple[dict[str, str], Switch], tmp_path: Path) -> None:
    env, maxima = logged
    out = tmp_path / "b"
    shipped = [str(p.relative_to(ROOT)) for p in sorted((ROOT / "equations").glob("*.mxm"))]
    cold = run("build", *shipped, "-o", str(out), env=env)
    assert cold.returncode == 0, cold.stderr
    maxima.forbid()
    files = {p: p.read_bytes() for p in out.rglob("*") if p.is_file() and p.name != "summary.md"}
    stamps = {p: p.stat().st_mtime_ns for p in files}
    victim = next(iter(files))
    victim.unlink()
    warm = run("build", *shipped, "-o", str(out), env=env)
    assert warm.returncode == 0, warm.stderr
    assert warm.stderr == cold.stderr
    assert {p: p.read_bytes() for p in files} == files  # the deleted one is back
    assert all(p.stat().st_mtime_ns == stamps[p] for p in files if p != victim)
    results = [p for p in entries(env, "results") if p.is_file()]
    assert len(results) >= 4  # 4, or more if max2code's own code changed between the two runs
    json.loads(results[0].read_bytes().split(b"\n", 1)[1])


# --- runtime discovery -------------------------------------------------------------------------

def test_runtime_discovery_and_cmake_follow_the_registry(monkeypatch: pytest.MonkeyPatch,
                                                         tmp_path: Path) -> None:
    """A language added to the registry (README, "Adding a language") is known to `max2code
    runtime` (its runtime folder; no flags) and to the CMake package's max2code_generate(LANG),
    which took a fixed list of the four shipped ones (a reviewer added a toy Lua: KeyError, and
    "LANG must be one of c, python, rust, m2")."""
    import dataclasses

    from max2code import languages
    from max2code.commands import runtime_info
    from max2code.languages.python import Python

    monkeypatch.setitem(languages.LANGUAGES, "toy", dataclasses.replace(Python(), extension=".toy"))
    monkeypatch.setenv("MAX2CODE_CACHE", str(tmp_path / "cache"))
    got = runtime_info.info("toy")
    assert got["dir"].endswith("runtime/toy") and got["cflags"] == got["libs"] == ""
    config = (runtime_info.cmake_dir() / "max2codeConfig.cmake").read_text()
    assert "set(MAX2CODE_LANGUAGE_EXTENSIONS c .h python .py m2 .mod rust .rs toy .toy)" in config


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


def test_a_secret_others_may_write_disables_the_cache(monkeypatch: pytest.MonkeyPatch,
                                                      tmp_path: Path) -> None:
    monkeypatch.setenv("MAX2CODE_CACHE", str(tmp_path / "c"))
    cache.put("ab" * 32, cache.Entry("x", 1.0))
    assert cache.get("ab" * 32) is not None
    assert cache.key_file().stat().st_mode & 0o077 == 0  # made private
    cache.key_file().chmod(0o666)
    monkeypatch.setattr(cache, "_secret", None)
    assert cache.get("ab" * 32) is None
    cache.put("cd" * 32, cache.Entry("y", 1.0))
    assert not list((tmp_path / "c" / cache.MAXIMA_KIND).rglob("cd*"))


def test_two_equations_with_one_function_name(logged: tuple[dict[str, str], Switch],
                                              tmp_path: Path) -> None:
    """Issue 12: `build` silently overwrote one output with the other."""
    env, _ = logged
    text = (ROOT / "equations" / "point-line.mxm").read_text()
    (tmp_path / "a.mxm").write_text(text)
    (tmp_path / "b.mxm").write_text("// the same function name\n" + text)
    shutil.copy(ROOT / "equations" / "circles-accel.mxm", tmp_path / "c.mxm")
    proc = run("build", "a.mxm", "c.mxm", "b.mxm", "-o", "out", "--lang", "c", env=env, cwd=tmp_path)
    assert proc.returncode == 1
    assert proc.stderr.splitlines() == [
        "b.mxm:11:1: error: function 'point_line' is also generated from a.mxm:10:1: both would "
        "write out/c/point_line.h; give one of them another 'function' name"]
    assert sorted(p.name for p in (tmp_path / "out" / "c").iterdir()) == ["circles_accel.h"]
    assert "Failed:\n\n- a.mxm\n- b.mxm" in proc.stdout
