"""What a Maxima process may do: its environment, its resource limits, and (on Linux) what it
may read, write, execute and connect to.

Maxima runs programs from .mxm files that a build may take from any repository, so the process
is confined by the operating system as well as by the Lisp lock-down of lockdown.py:

* an environment holding only what Maxima needs (PATH, a private HOME and MAXIMA_USERDIR so
  no user init file is read, the locale, and the MAXIMA_*/GCL_*/SBCL_HOME variables that choose
  and tune a Lisp);
* RLIMIT_AS (memory; GCL sizes its heap from it), RLIMIT_CPU (a backstop behind the timeout),
  no core files;
* PR_SET_PDEATHSIG: the kernel kills Maxima when max2code dies, even by SIGKILL (the signal
  follows the thread that started it, which waits for it);
* PR_SET_NO_NEW_PRIVS, then a Landlock ruleset (Linux 5.13+, used when the kernel has it):
  read and execute only the system's program and library folders, Maxima's installation, the
  private folder and the files the program may load; write nothing; no TCP (ABI 4+), no
  signals or abstract sockets outside the process (ABI 6+). `--allow-unsafe-maxima` drops the
  Landlock ruleset, not the limits.

All of it runs in the child between fork and exec (`preexec`), with everything it needs
prepared beforehand.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import resource
import signal
import sys
from dataclasses import dataclass
from typing import Callable

# Measured: GCL (Maxima 5.46) does not start below 256 MiB of address space; under a limit it
# sizes its heap to GCL_MEM_MULTIPLE of it (we pass 0.9), so a bigger limit is faster on huge
# expansions (expand((a+b+c+d)^60): 3.5 s unlimited, 9 s at 2 GiB, 110 s at 512 MiB).
DEFAULT_MEMORY_MIB = 2048
MIN_MEMORY_MIB = 256
CPU_GRACE_SECONDS = 10

_PASSED_ON = ("PATH", "SBCL_HOME")
_PASSED_PREFIXES = ("MAXIMA_", "GCL_")

_PR_SET_PDEATHSIG = 1
_PR_SET_NO_NEW_PRIVS = 38


@dataclass(frozen=True)
class Limits:
    """The resources one Maxima run may use; memory 0 means no memory limit."""

    timeout: float
    memory_mib: int = DEFAULT_MEMORY_MIB


def environment(private: str) -> dict[str, str]:
    """Maxima's whole environment: nothing of the user's but PATH and the Lisp's own settings."""
    env = {k: v for k, v in os.environ.items()
           if k in _PASSED_ON or k.startswith(_PASSED_PREFIXES)}
    env.setdefault("PATH", os.defpath)
    env.setdefault("GCL_MEM_MULTIPLE", "0.9")
    env.update(HOME=private, MAXIMA_USERDIR=private, TMPDIR=private, LANG="C.UTF-8",
               LC_ALL="C.UTF-8")
    env.pop("MAXIMA", None)  # ours: the executable's path
    return env


def preexec(limits: Limits, readable: tuple[str, ...], sandbox: bool) -> Callable[[], None]:
    """The function the child runs before exec: limits, parent-death signal, Landlock.

    `readable` are the paths (folders or files) the child may read besides the system's; when
    `sandbox` is False (or the kernel has no Landlock) only the limits and the death signal apply.
    """
    parent = os.getpid()
    libc = _libc()
    ruleset = _Landlock.prepare(readable) if sandbox and libc is not None else None
    cpu = int(limits.timeout) + CPU_GRACE_SECONDS
    memory = limits.memory_mib * 1024 * 1024

    def setup() -> None:
        if libc is not None:
            libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
            if os.getppid() != parent:  # max2code died before the line above: so does Maxima
                os._exit(137)
        _lower(resource.RLIMIT_CORE, 0, 0)
        _lower(resource.RLIMIT_CPU, cpu, cpu + 5)  # SIGXCPU first (a diagnostic), then SIGKILL
        if memory:
            _lower(resource.RLIMIT_AS, memory, memory)
        if ruleset is not None:
            ruleset.restrict(libc)

    return setup


def _lower(which: int, soft: int, hard: int) -> None:
    """Lower a limit, never raise it; a platform without it is left alone."""
    try:
        _, current = resource.getrlimit(which)
        if current != resource.RLIM_INFINITY:
            soft, hard = min(soft, current), min(hard, current)
        resource.setrlimit(which, (soft, hard))
    except (OSError, ValueError):
        pass


def landlock_abi() -> int:
    """The kernel's Landlock ABI version, 0 when there is none (not Linux, or disabled)."""
    libc = _libc()
    if libc is None:
        return 0
    version = libc.syscall(_Landlock.CREATE, None, 0, 1)  # LANDLOCK_CREATE_RULESET_VERSION
    return max(int(version), 0)


def _libc() -> ctypes.CDLL | None:
    if not sys.platform.startswith("linux"):
        return None
    try:
        return ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
    except OSError:
        return None


class _RulesetAttr(ctypes.Structure):
    _fields_ = [("handled_access_fs", ctypes.c_uint64), ("handled_access_net", ctypes.c_uint64),
                ("scoped", ctypes.c_uint64)]


class _PathBeneathAttr(ctypes.Structure):
    _pack_ = 1
    _fields_ = [("allowed_access", ctypes.c_uint64), ("parent_fd", ctypes.c_int32)]


# System folders a Lisp and the `maxima` shell wrapper read and execute from; /proc for the
# memory size GCL sizes its heap by; /dev/null and /dev/urandom.
SYSTEM_READABLE = ("/usr", "/lib", "/lib64", "/lib32", "/bin", "/sbin", "/etc/ld.so.cache",
                   "/etc/localtime", "/proc", "/sys/devices/system/cpu", "/dev/null",
                   "/dev/urandom")


@dataclass(frozen=True)
class _Landlock:
    """A prepared ruleset: the attributes and rules, applied in the child by `restrict`."""

    CREATE = 444  # landlock_create_ruleset, landlock_add_rule, landlock_restrict_self: the
    ADD_RULE = 445  # same numbers on every Linux architecture (the unified syscall table)
    RESTRICT = 446

    abi: int
    paths: tuple[str, ...]

    # LANDLOCK_ACCESS_FS_*: execute, write, read file, read dir, and everything that changes
    # the file system (remove, make, refer, truncate, ioctl on devices), by ABI version.
    EXECUTE, WRITE_FILE, READ_FILE, READ_DIR = 1, 2, 4, 8

    @classmethod
    def prepare(cls, readable: tuple[str, ...]) -> _Landlock | None:
        abi = landlock_abi()
        if abi < 1:
            return None
        paths = tuple(p for p in dict.fromkeys((*SYSTEM_READABLE, *readable)) if os.path.exists(p))
        return cls(abi, paths)

    def handled_fs(self) -> int:
        bits = (1 << 13) - 1  # ABI 1: execute .. make_sym
        if self.abi >= 2:
            bits |= 1 << 13  # refer
        if self.abi >= 3:
            bits |= 1 << 14  # truncate
        if self.abi >= 5:
            bits |= 1 << 15  # ioctl_dev
        return bits

    def restrict(self, libc: ctypes.CDLL) -> None:
        """In the child: create the ruleset, allow reading `paths`, and confine the process.
        A failure leaves the process unconfined by Landlock only if the kernel refuses the
        ruleset; the Lisp lock-down still applies."""
        attr = _RulesetAttr(self.handled_fs(), 3 if self.abi >= 4 else 0, 3 if self.abi >= 6 else 0)
        size = 8 if self.abi < 4 else 16 if self.abi < 6 else 24
        fd = libc.syscall(self.CREATE, ctypes.byref(attr), size, 0)
        if fd < 0:
            return
        read = self.EXECUTE | self.READ_FILE | self.READ_DIR
        for path in self.paths:
            try:
                target = os.open(path, os.O_PATH | os.O_CLOEXEC)
            except OSError:
                continue
            allowed = read & attr.handled_access_fs
            if not os.path.isdir(path):
                allowed &= self.EXECUTE | self.READ_FILE  # a file takes no directory rights
                if path == "/dev/null":
                    allowed |= self.WRITE_FILE
            rule = _PathBeneathAttr(allowed, target)
            libc.syscall(self.ADD_RULE, fd, 1, ctypes.byref(rule), 0)  # LANDLOCK_RULE_PATH_BENEATH
            os.close(target)
        libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
        libc.syscall(self.RESTRICT, fd, 0)
        os.close(fd)
