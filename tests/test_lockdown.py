"""A .mxm cannot escape the algebra, even when it builds the names it calls.

tests/bad/unsafe-*.mxm hold the escapes refused before Maxima runs (each with its exact
diagnostic). Here are the ones that get past that check because the name is built at run time
(`apply(concat(sys, tem), ...)`, a string stream fed to `batch`, ...): each would create a
file if it ran; the test asserts the diagnostic and that the file does not exist. Then the
operating system's confinement on its own (Maxima started without the Lisp lock-down, so a
`:lisp` line runs): it must not write, nor read a file outside what it is given. And what stays
allowed: loads inside the .mxm's folder, Maxima's own library, and everything with
--allow-unsafe-maxima.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

from max2code.maxima import confine, session as maxima
from max2code.diagnostics import Pos


def run(mxm: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "max2code", "--lang=python", "--emit=module",
                           str(mxm), "-o", str(mxm.with_suffix(".py")), "--no-cache", *extra],
                          cwd=ROOT, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})


def program(tmp_path: Path, body: str) -> Path:
    mxm = tmp_path / "eq.mxm"
    mxm.write_text(f"begin\n{body}\n(t - 1)^2;\nend\n")
    return mxm


PWNED = "PWNED"  # created by every escape below, if it ran


# name -> (the program's first statements, the line of the statement reported, what it names)
BUILT_NAMES = {
    "apply-concat-system": ('apply(concat(sys, tem), ["touch {pwned}"])$', 2, "system"),
    "variable-holds-system": ('f: concat(sys, tem)$\nf("touch {pwned}")$', 3, "system"),
    "funmake-ev-eval": ('ev(funmake(concat(sys, tem), ["touch {pwned}"]), eval)$', 2, "system"),
    "subscripted-function": ('g[k] := concat(sys, tem)$\napply(g[1], ["touch {pwned}"])$', 3,
                             "system"),
    "define-buildq": ('define(f(c), buildq([s: concat(sys, tem)], s(c)))$\nf("touch {pwned}")$', 3,
                      "system"),
    "built-writefile": ('apply(concat(write, file), ["{pwned}"])$', 2, "writefile"),
    "built-with-stdout": ('apply(concat(with_st, dout), ["{pwned}", 1])$', 2, "with_stdout"),
    "built-openw": ('apply(concat(open, w), ["{pwned}"])$', 2, "openw"),
    "built-save": ('apply(concat(sa, ve), ["{pwned}", x])$', 2, "save"),
    "built-to-lisp": ('apply(concat(to_, lisp), [])$', 2, "to_lisp"),
    "built-eval-string": ('apply(concat(eval_, string), ["1+1"])$', 2, "eval_string"),
    "built-parse-string": ('apply(concat(parse_, string), ["1+1"])$', 2, "parse_string"),
    "built-plot": ('apply(concat(plot, "2d"), [x, [x, 0, 1]])$', 2, "plot2d"),
    "lisp-in-a-string-stream": (
        'apply(concat(bat, ch), [make_string_input_stream(sconcat(":", "lisp (si:system ",'
        ' ascii(34), "touch {pwned}", ascii(34), ")", ascii(10)))])$', 2, ":lisp"),
    "question-mark-in-a-string-stream": (
        'apply(concat(bat, ch), [make_string_input_stream(sconcat(ascii(63), "print(1);"))])$',
        2, "?"),
    "load-outside-by-built-name": ('apply(concat(lo, ad), ["/etc/passwd"])$', 2,
                                   "load /etc/passwd"),
    "lisp-file-by-built-name": ('apply(concat(lo, ad), [sconcat("{folder}", "/evil.lisp")])$', 2,
                                "load {folder}/evil.lisp"),
}


@pytest.mark.parametrize("name", sorted(BUILT_NAMES))
def test_built_names_are_refused_at_run_time(name: str, tmp_path: Path, maxima_exe: str) -> None:
    pwned = tmp_path / PWNED
    (tmp_path / "evil.lisp").write_text(f'(with-open-file (s "{pwned}" :direction :output) (print 1 s))\n')
    body, line, what = BUILT_NAMES[name]
    mxm = program(tmp_path, body.format(pwned=pwned, folder=tmp_path))
    proc = run(mxm)
    assert proc.returncode == 1, proc.stderr
    first = proc.stderr.splitlines()[0]
    assert first.startswith(f"{mxm}:{line}:1: error: the program reached "
                            f"'{what.format(folder=tmp_path)}' at run time, which "), first
    assert first.endswith("; not allowed in a .mxm (--allow-unsafe-maxima lifts this)"), first
    assert not pwned.exists()
    assert not mxm.with_suffix(".py").exists()


# Look-alikes of a break command that Maxima reads as symbols: nothing must run, whatever the
# outcome (a syntax error or an unevaluated call).
UNICODE_TRICKS = {
    "fullwidth colon": '\uff1alisp (si:system "touch {pwned}")$',
    "no-break space first": 'x: 1$\n\u00a0:lisp (si:system "touch {pwned}")\n',
    "zero-width space inside": ':\u200blisp (si:system "touch {pwned}")\n',
    "cyrillic s in system": '\u0455ystem("touch {pwned}")$',
}


@pytest.mark.parametrize("name", sorted(UNICODE_TRICKS))
def test_unicode_look_alikes_run_nothing(name: str, tmp_path: Path, maxima_exe: str) -> None:
    pwned = tmp_path / PWNED
    mxm = program(tmp_path, UNICODE_TRICKS[name].format(pwned=pwned))
    proc = run(mxm)
    assert "Traceback" not in proc.stderr and proc.returncode in (0, 1)
    assert not pwned.exists()


def test_unsafe_lifts_the_lock(tmp_path: Path, maxima_exe: str) -> None:
    """--allow-unsafe-maxima: the program may run programs and write files (documented)."""
    pwned = tmp_path / PWNED
    mxm = program(tmp_path, f'system("touch {pwned}")$\nwritefile("{tmp_path / "log.txt"}")$')
    assert run(mxm).returncode == 1 and not pwned.exists()
    proc = run(mxm, "--allow-unsafe-maxima")
    assert proc.returncode == 0, proc.stderr
    assert pwned.exists() and (tmp_path / "log.txt").exists()


def test_loads_inside_the_folder_and_the_library_work(tmp_path: Path, maxima_exe: str) -> None:
    (tmp_path / "sub").mkdir()
    # Maxima finds a nested load through its search path (the .mxm's folder), not beside
    # the file that loads it.
    (tmp_path / "sub" / "helper.mac").write_text('load("sub/more.mac")$\nh(t) := g(t) + 1$\n')
    (tmp_path / "sub" / "more.mac").write_text("g(t) := t^2 - 9$\n")
    mxm = tmp_path / "eq.mxm"
    mxm.write_text('begin\nload("sub/helper.mac")$\nload(functs)$\nx: collectterms(h(t)*2, t)$\n'
                   'lcm(2, 3)*x;\nend\n')
    proc = run(mxm)
    assert proc.returncode == 0, proc.stderr
    module: dict[str, object] = {}
    exec(mxm.with_suffix(".py").read_text(), module)
    assert module["coefficients"](()) == [-96.0, 0.0, 12.0]  # type: ignore[operator]


def test_a_loaded_file_is_checked_too(tmp_path: Path, maxima_exe: str) -> None:
    (tmp_path / "helper.mac").write_text(f'x: 1$\ny: system("touch {tmp_path / PWNED}")$\n')
    mxm = program(tmp_path, 'load("helper.mac")$')
    proc = run(mxm)
    assert proc.returncode == 1
    assert proc.stderr.splitlines()[0] == (
        f"{tmp_path / 'helper.mac'}:2:4: error: 'system' runs a program; not allowed in a .mxm "
        f"(--allow-unsafe-maxima lifts this)")
    assert not (tmp_path / PWNED).exists()


def test_a_symlink_out_of_the_folder_is_refused(tmp_path: Path, maxima_exe: str) -> None:
    (tmp_path / "passwd.mac").symlink_to("/etc/passwd")
    mxm = program(tmp_path, 'load("passwd.mac")$')
    proc = run(mxm)
    assert proc.returncode == 1
    assert "reads a file outside the .mxm's folder" in proc.stderr.splitlines()[0]


# --- the operating system's confinement alone ------------------------------------------------

@pytest.fixture
def landlock() -> None:
    if confine.landlock_abi() < 1:
        pytest.skip("this kernel has no Landlock (Linux 5.13+ with landlock in the LSM list): "
                    "only the Lisp lock-down applies here")


def raw(script: str, sandbox: bool, readable: tuple[str, ...] = ()) -> str:
    """Maxima's output for a script run confined, without the Lisp lock-down."""
    old = maxima.policy()
    maxima.configure(allow_unsafe=not sandbox)
    try:
        text, _, reason = maxima._execute(maxima.maxima_executable(), script, Pos("t", 1, 1),
                                          60.0, readable)
    finally:
        maxima.configure(allow_unsafe=old.allow_unsafe)
    assert reason is None
    return text


def test_the_sandbox_alone_stops_writes(tmp_path: Path, maxima_exe: str, landlock: None) -> None:
    pwned = tmp_path / PWNED
    script = (f':lisp (si:system "touch {pwned}")\n'
              f':lisp (ignore-errors (with-open-file (s "{tmp_path / "w.txt"}" :direction :output) '
              f'(print 1 s)))\n:lisp (format t "~%DONE~%")\n')
    assert "DONE" in raw(script, sandbox=True)
    assert not pwned.exists() and not (tmp_path / "w.txt").exists()
    raw(script, sandbox=False)  # the same script unconfined does write: the test can fail
    assert pwned.exists() and (tmp_path / "w.txt").exists()


def test_the_sandbox_alone_stops_reads(tmp_path: Path, maxima_exe: str, landlock: None) -> None:
    secret = tmp_path / "secret.txt"
    secret.write_text("the-secret-text\n")
    script = (f':lisp (format t "~%READ ~a~%" (ignore-errors (with-open-file (s "{secret}") '
              f'(read-line s))))\n')
    assert "READ the-secret-text" not in raw(script, sandbox=True)
    assert "READ the-secret-text" in raw(script, sandbox=True, readable=(str(secret),))
    assert "READ the-secret-text" in raw(script, sandbox=False)


def test_a_parameter_may_be_called_like_a_refused_function(tmp_path: Path, maxima_exe: str) -> None:
    """Parameters named `compile` or `save` (names users have) are symbols of the algebra; the
    same name called, directly or through a variable holding it, is still refused."""
    mxm = tmp_path / "eq.mxm"
    mxm.write_text("parameters compile, save\nbegin\n(t - compile)*(t + save);\nend\n")
    proc = run(mxm)
    assert proc.returncode == 0, proc.stderr
    module: dict[str, object] = {}
    exec(mxm.with_suffix(".py").read_text(), module)
    assert module["coefficients"]((2.0, 3.0)) == [-6.0, 1.0, 1.0]  # type: ignore[operator]
    pwned = tmp_path / PWNED
    for body, line in ((f'compile(x)$\nsystem("touch {pwned}")$', 3),
                       (f'f: system$\nf("touch {pwned}")$', 4)):
        mxm.write_text(f"parameters system, compile\nbegin\n{body}\n(t - compile)^2;\nend\n")
        proc = run(mxm)
        assert proc.returncode == 1 and not pwned.exists(), proc.stderr
        assert proc.stderr.startswith(f"{mxm}:{line}:"), proc.stderr
        assert "'compile'" in proc.stderr or "'system'" in proc.stderr
