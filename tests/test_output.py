"""`-o` naming something other than a regular file: a device is written into, never replaced and
never read (the old write-if-changed replaced /dev/null with a regular file when run as root,
and read /dev/full until the OOM killer came); a FIFO is written into when read and refused
when nobody reads it; a symlink is followed and stays a symlink. Devices are made here with
mknod (as root) so that a failure could never touch the real /dev/null.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from conftest import ROOT

from max2code.diagnostics import Max2CodeError
from max2code.output import write_if_changed

TEXT = "generated\n" * 1000


def device(tmp_path: Path, name: str, minor: int) -> Path:
    """A character device like /dev/null (1, 3) or /dev/full (1, 7), made in tmp_path."""
    path = tmp_path / name
    try:
        os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, minor))
    except PermissionError:
        pytest.skip("making a device node needs root (mknod); not run here")
    return path


def test_a_null_device_is_written_into_not_replaced(tmp_path: Path) -> None:
    null = device(tmp_path, "null", 3)
    assert write_if_changed(str(null), TEXT)
    assert stat.S_ISCHR(os.stat(null).st_mode) and os.stat(null).st_rdev == os.makedev(1, 3)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["null"]  # no temporary left either


def test_a_full_device_is_an_error_not_an_endless_read(tmp_path: Path) -> None:
    full = device(tmp_path, "full", 7)
    with pytest.raises(Max2CodeError, match="cannot write output: No space left on device"):
        write_if_changed(str(full), TEXT)
    assert stat.S_ISCHR(os.stat(full).st_mode)


def test_a_fifo_with_a_reader_receives_the_output(tmp_path: Path) -> None:
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    received: list[bytes] = []
    ready = threading.Event()

    def reader() -> None:
        with open(fifo, "rb") as f:
            ready.set()
            received.append(f.read())

    thread = threading.Thread(target=reader)
    thread.start()
    while not ready.is_set():  # the reader must hold the FIFO open before we write
        try:
            write_if_changed(str(fifo), TEXT)
            break
        except Max2CodeError:
            continue
    thread.join(timeout=30)
    assert b"".join(received) == TEXT.encode()
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)


def test_a_fifo_nobody_reads_is_refused_at_once(tmp_path: Path) -> None:
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    with pytest.raises(Max2CodeError, match="it is a FIFO that no process is reading"):
        write_if_changed(str(fifo), TEXT)
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)


def test_a_symlink_is_followed_and_kept(tmp_path: Path) -> None:
    target = tmp_path / "real.h"
    target.write_text("old\n")
    link = tmp_path / "link.h"
    link.symlink_to(target)
    assert write_if_changed(str(link), TEXT)
    assert link.is_symlink() and target.read_text() == TEXT
    stamp = target.stat().st_mtime_ns
    assert not write_if_changed(str(link), TEXT)  # unchanged: not rewritten
    assert target.stat().st_mtime_ns == stamp


def test_a_symlink_to_a_device_stays(tmp_path: Path) -> None:
    null = device(tmp_path, "null", 3)
    link = tmp_path / "out.h"
    link.symlink_to(null)
    assert write_if_changed(str(link), TEXT)
    assert link.is_symlink() and stat.S_ISCHR(os.stat(null).st_mode)


def test_the_cli_writes_into_a_device(tmp_path: Path, maxima_exe: str) -> None:
    null = device(tmp_path, "null", 3)
    proc = subprocess.run([sys.executable, "-m", "max2code", "--lang=c",
                           "equations/point-line.mxm", "-o", str(null), "-MD"], cwd=ROOT,
                          capture_output=True, text=True, timeout=300,
                          env={**os.environ, "MAX2CODE_CACHE": str(tmp_path / "cache")})
    assert proc.returncode == 0, proc.stderr
    assert stat.S_ISCHR(os.stat(null).st_mode)
    assert (tmp_path / "null.d").read_text().startswith(f"{null}: ")


def test_a_regular_file_is_compared_with_a_bounded_read(tmp_path: Path) -> None:
    out = tmp_path / "o.h"
    out.write_text(TEXT + "more")  # longer: different without reading it whole
    assert write_if_changed(str(out), TEXT) and out.read_text() == TEXT
    os.utime(out, ns=(1, 1))
    assert not write_if_changed(str(out), TEXT) and out.stat().st_mtime_ns == 1


def test_files_written_by_a_library_follow_the_same_rules(tmp_path: Path) -> None:
    """output.replaced_atomically (for writers such as Pillow): a symlink is kept, a device is
    written into."""
    from max2code.output import replaced_atomically

    target = tmp_path / "real.png"
    link = tmp_path / "frame.png"
    link.symlink_to(target)
    with replaced_atomically(str(link)) as tmp:
        Path(tmp).write_bytes(b"png")
    assert link.is_symlink() and target.read_bytes() == b"png"
    null = device(tmp_path, "null", 3)
    with replaced_atomically(str(null)) as tmp:
        Path(tmp).write_bytes(b"png")
    assert stat.S_ISCHR(os.stat(null).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frame.png", "null", "real.png"]


def test_regular_files_under_dev_are_replaced_like_any_other() -> None:
    """/dev/shm holds ordinary files: created when missing, replaced whole when shorter (only a
    descriptor's name, /dev/stdout or /dev/fd/N, is written through; a reviewer found a shorter
    log written over the start of the old one)."""
    shm = Path("/dev/shm")
    if not shm.is_dir() or not os.access(shm, os.W_OK):
        pytest.skip("no writable /dev/shm here")
    out = shm / f"max2code-test-{os.getpid()}.txt"
    try:
        assert write_if_changed(str(out), "a long first version\n" * 10)
        assert write_if_changed(str(out), "short\n")
        assert out.read_text() == "short\n"
    finally:
        out.unlink(missing_ok=True)


def test_descriptors_are_written_through() -> None:
    """/dev/stdout into a pipe, from write_if_changed and from a library's writer
    (replaced_atomically: --png, --gif): realpath names no file for a pipe."""
    code = ("from pathlib import Path\n"
            "from max2code.output import replaced_atomically, write_if_changed\n"
            "write_if_changed('/dev/stdout', 'text\\n')\n"
            "with replaced_atomically('/dev/fd/1') as tmp:\n"
            "    Path(tmp).write_bytes(b'bytes\\n')\n")
    r = subprocess.run(f"{sys.executable} -c \"{code}\" | cat", shell=True, capture_output=True,
                       text=True, cwd=ROOT, timeout=60)
    assert r.returncode == 0 and r.stdout == "text\nbytes\n", r.stderr
