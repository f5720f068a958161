"""A .mxm program may do algebra, nothing else: no shell, no Lisp, no files but its own loads.

A code generator that builds run on files from any repository must not be a shell, and Maxima
is one: `system("...")`, `:lisp`, `?`-prefixed Lisp calls, `load` of any file, `writefile`,
plotting (which runs gnuplot through a shell), ... So a program is refused, before Maxima runs,
when it names any of that (`check`, with `file:line:col` on the construct); and since names
can be built at run time (`apply(concat("sys", "tem"), ...)`, a variable holding `system`),
Maxima itself is locked down before the program's first statement (`prelude`):

* Lisp's `open` and `load` read only Maxima's own folders and the program's checked loads,
  and write nothing; Lisp's ways to run programs, open sockets, change folders or delete,
  rename and create files are replaced by a refusal;
* every Maxima function of the refused list is replaced by a refusal (so a built name reaches
  the refusal, and says which function it was);
* `?name` (a Lisp symbol in Maxima syntax) is refused by the reader, also inside `eval_string`,
  except in Maxima's own library files;
* `:lisp` and every other break command are refused, except the exact marker lines max2code
  itself writes between statements.

A refusal prints `@@M2C-REFUSED what` and stops the program; session.py reports it at the
statement that ran into it. The operating system confines Maxima as well (confine.py).
`--allow-unsafe-maxima` turns all of this off (the resource limits stay).
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass

from ..diagnostics import Pos, error
from . import depfile, text as maxima_text
from .text import advance
from ..front.spec import Statement

LIFTED = "--allow-unsafe-maxima lifts this"

# Maxima functions and variables a .mxm program may not name, and why.
_SHELL = "runs a program"
_FILES = "reads or writes files"
_PLOT = "plots, which runs an external program"
_CODE = "turns text into code (a way around these checks)"
_LISP = "enters Lisp"
REFUSED: dict[str, str] = {
    **dict.fromkeys(("system", "run_program"), _SHELL),
    **dict.fromkeys(("to_lisp", "compile", "compile_lisp_file"), _LISP),
    **dict.fromkeys(("eval_string", "parse_string", "eval_string_lisp"), _CODE),
    **dict.fromkeys((
        "loadfile", "writefile", "appendfile", "closefile", "save", "stringout",
        "with_stdout", "opena", "openr", "openw", "opena_binary", "openr_binary", "openw_binary",
        "printfile", "read_list", "read_matrix", "read_array", "read_hashed_array",
        "read_nested_list", "read_binary_list", "read_binary_matrix", "read_binary_array",
        "write_data", "write_binary_data", "compfile", "compile_file", "translate_file",
        "setup_autoload", "directory", "delete_file", "rename_file", "copy_file", "mkdir",
        "rmdir", "chdir", "getenv", "demo", "run_testsuite", "dribble", "file_output_append",
        "tex", "gentran", "stardisp_file"), _FILES),
    **dict.fromkeys((
        "plot2d", "plot3d", "contour_plot", "implicit_plot", "plotdf", "julia", "mandelbrot",
        "draw", "draw2d", "draw3d", "draw_file", "wxdraw", "wxdraw2d", "wxdraw3d", "wxplot2d",
        "wxplot3d", "wxcontour_plot", "wximplicit_plot", "multiplot_mode", "set_plot_option",
        "gnuplot_start", "gnuplot_close", "gnuplot_restart", "gnuplot_send", "gnuplot_replot",
        "gnuplot_reset", "scene", "set_draw_defaults", "draw_graph"), _PLOT),
}
LOADS = ("load", "batchload", "batch")
LISP_EXTENSIONS = (".lisp", ".lsp", ".o", ".fas", ".fasl", ".so")


class _Where:
    """A position computed only when a diagnostic needs it (a program can be megabytes long)."""

    def __init__(self, start: Pos, text: str, offset: int) -> None:
        self.start, self.text, self.offset = start, text, offset

    def pos(self) -> Pos:
        return advance(self.start, self.text[: self.offset])


def why(what: str) -> str:
    """What a refused run-time call (as the prelude names it) would have done."""
    if what in REFUSED:
        return REFUSED[what].split(", ")[0]
    if what.startswith(("open ", "load ", "delete-file", "rename", "mkdir", "unlink", "chdir")):
        return _FILES
    if what.startswith((":", "?")):
        return _LISP
    return _SHELL


@dataclass(frozen=True)
class Loaded:
    """A file a program may load (checked, inside the .mxm's folder) and where it is loaded."""

    path: str
    pos: Pos


def check(statements: tuple[Statement, ...], names: frozenset[str] = frozenset()) -> tuple[str, ...]:
    """Refuse a program (and the files it loads) that escapes the algebra; return the files
    it may load (absolute paths), which the lock-down lets Maxima read.

    `names` are the .mxm's declared parameters and variable: a user may call a parameter
    `compile` or `save` (a symbol in the algebra), so such a name is refused only where it is
    called, `name(`; any other way to call it (`apply`, a variable holding it) reaches the
    lock-down's refusal at run time."""
    if not statements:
        return ()
    folder = os.path.dirname(os.path.abspath(statements[0].pos.file))
    texts = [(s.text, s.pos) for s in statements]
    whole = "\n".join(s.text for s in statements)
    allowed: list[str] = []
    while texts:
        text, start = texts.pop(0)
        for loaded in _scan(text, start, folder, whole, names):
            if loaded.path not in allowed:
                allowed.append(loaded.path)
                try:
                    with open(loaded.path, encoding="utf-8", errors="replace") as f:
                        texts.append((f.read(), Pos(loaded.path, 1, 1)))
                except OSError:
                    raise error(loaded.pos, f"cannot read {loaded.path!r}") from None
    return tuple(allowed)


_NAMES = "|".join(sorted((re.escape(n) for n in (*REFUSED, *LOADS)), key=len, reverse=True))
# What the scan stops at: strings and comments (skipped whole), '?' and '\\', statement ends,
# and the names it refuses or checks. Everything else is passed over by the regex engine.
_HIT = re.compile(rf'"|/\*|[?\\;$]|(?<![\w%])(?:{_NAMES})(?![\w%])')
_BLANK = re.compile(r"\s*")


def _scan(text: str, start: Pos, folder: str, whole: str,
          names: frozenset[str] = frozenset()) -> list[Loaded]:
    """Maxima's tokens as its reader sees them; the first refused construct is an error."""
    loads: list[Loaded] = []
    i = _statement_start(text, 0, start)
    while True:
        m = _HIT.search(text, i)
        if m is None:
            return loads
        token, i = m.group(), m.end()
        where = _Where(start, text, m.start())
        if token == '"':
            i = maxima_text.string_end(text, m.start())
            if i < 0:
                return loads  # maxima_text has refused an unterminated string in the program
        elif token == "/*":
            i = _comment_end(text, m.start())
        elif token in (";", "$"):
            i = _statement_start(text, i, start)
        elif token == "?":
            raise error(where.pos(), f"'?{_word_after(text, i)}' names a Lisp function or variable; "
                        f"not allowed in a .mxm ({LIFTED})")
        elif token == "\\":
            raise error(where.pos(), f"a backslash outside a string (an escaped character in a name) "
                        f"can hide a Lisp name or the end of a statement; not allowed in a .mxm "
                        f"({LIFTED})")
        elif token in REFUSED and token in names and not _called(text, i):
            continue
        elif token in REFUSED:
            raise error(where.pos(), f"'{token}' {REFUSED[token]}; not allowed in a .mxm ({LIFTED})")
        else:
            loads.extend(_load(text, i, token, where, folder, whole))


def _called(text: str, i: int) -> bool:
    """Is the name ending at `i` applied: followed by `(` (blanks between)?"""
    return text.startswith("(", _BLANK.match(text, i).end())  # type: ignore[union-attr]


def _statement_start(text: str, i: int, start: Pos) -> int:
    """Where the statement beginning at `i` starts after blanks and comments; a break command
    (`:lisp`, which Maxima reads only there) is an error."""
    while True:
        i = _BLANK.match(text, i).end()  # type: ignore[union-attr]
        if not text.startswith("/*", i):
            break
        i = _comment_end(text, i)
    if text.startswith(":", i):
        raise error(_Where(start, text, i).pos(), f"':{_word_after(text, i + 1)}' is a break "
                    f"command: it runs Lisp; not allowed in a .mxm ({LIFTED})")
    return i


def _comment_end(text: str, i: int) -> int:
    """The end of the (nested) comment starting at `i`; the text's end if it never closes
    (maxima_text has already refused that for the program)."""
    end = maxima_text.comment_end(text, i)
    return len(text) if end < 0 else end


def _word_after(text: str, i: int) -> str:
    m = re.match(r"[\w\\:*-]*", text[i:i + 40])
    return m.group() if m else ""


def _load(text: str, i: int, name: str, where: _Where, folder: str, whole: str) -> list[Loaded]:
    """A load must name a Maxima file inside the .mxm's folder, or a package of Maxima's own
    library, literally."""
    call = depfile.load_call_at(text, i - len(name))
    if call is None or (call.name is None and call.symbol is None):
        raise error(where.pos(), f"'{name}' of a computed file name: max2code cannot check or "
                    f"track what it reads; not allowed in a .mxm (write the name as a string; "
                    f"{LIFTED})")
    if call.symbol is not None:  # Maxima's library, unless the program gives it a value
        if depfile.assigned(call.symbol, whole):
            raise error(where.pos(), f"'{name}({call.symbol})' loads the file named by a "
                        f"variable; not allowed in a .mxm (write the name as a string; {LIFTED})")
        return []
    target = call.name or ""
    ext = os.path.splitext(target)[1].lower()
    if ext in LISP_EXTENSIONS:
        raise error(where.pos(), f"'{name}(\"{target}\")' loads Lisp code; not allowed in a .mxm "
                    f"({LIFTED})")
    base = target if os.path.isabs(target) else os.path.join(folder, target)
    candidates = [base] + ([base + e for e in depfile.MAXIMA_EXTENSIONS] if not ext else [])
    found = next((c for c in candidates if os.path.isfile(c)), None)
    inside = os.path.realpath(folder) + os.sep
    if found is not None:
        real = os.path.realpath(found)
        if not real.startswith(inside):
            raise error(where.pos(), f"'{name}(\"{target}\")' reads a file outside the .mxm's "
                        f"folder; not allowed in a .mxm ({LIFTED})")
        return [Loaded(real, where.pos())]
    if os.path.isabs(target) or "/" in target or "\\" in target:
        raise error(where.pos(), f"'{name}(\"{target}\")': no such file in the .mxm's folder; "
                    f"loading from elsewhere is not allowed in a .mxm ({LIFTED})")
    return []  # a package of Maxima's library by name: Maxima finds it in its own folders


def prelude(readable: tuple[str, ...], markers: str) -> str:
    """The Lisp that locks Maxima down, as script lines (`:lisp` forms) to run before the
    program. `readable`: the files the program may load; `markers`: the prefix of the marker
    lines (`~%@@M2C-`) that `:lisp` still accepts afterwards."""
    files = " ".join(_lisp_string(os.path.realpath(p)) for p in readable)
    shell = " ".join(_lisp_string(n.upper()) for n in REFUSED)
    lisp = _PRELUDE.replace("@FILES@", files).replace("@MAXIMA-NAMES@", shell)
    lisp = lisp.replace("@MARK@", _lisp_string(markers)[1:-1])
    forms = [" ".join(form.split()) for form in lisp.strip().split("\n\n")]
    return "".join(f":lisp {form}\n" for form in forms)


def _lisp_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


# One form per paragraph. Runs in Maxima's package; GCL's names are looked up by string, so the
# same text is harmless under another Lisp (the operating system's confinement still holds).
_PRELUDE = r"""
(defun m2c-refuse (what) (format t "~%@@M2C-REFUSED ~a~%" what) (finish-output) (merror (format nil "refused: ~a" what)))

(defvar *m2c-readable-files* (list @FILES@))

(defvar *m2c-readable-roots* (remove nil (mapcar (lambda (v) (and (boundp v) (stringp (symbol-value v)) (ignore-errors (namestring (truename (concatenate 'string (string-right-trim "/" (symbol-value v)) "/")))))) '(*maxima-sharedir* *maxima-srcdir* *maxima-demodir* *maxima-infodir* *maxima-htmldir* *maxima-prefix*))))

(defun m2c-under-roots (true) (some (lambda (root) (and (> (length true) (length root)) (string= root true :end2 (length root)))) *m2c-readable-roots*))

(defun m2c-readable-p (file) (let ((true (ignore-errors (namestring (truename file))))) (and true (or (member true *m2c-readable-files* :test #'string=) (m2c-under-roots true)))))

(handler-bind ((warning #'muffle-warning)) (let ((original (symbol-function 'open))) (setf (symbol-function 'open) (lambda (file &rest args) (let ((direction (getf args :direction :input))) (if (or (eq direction :probe) (and (eq direction :input) (m2c-readable-p file))) (apply original file args) (m2c-refuse (format nil "open ~a (~(~a~))" (ignore-errors (namestring file)) direction))))))))

(handler-bind ((warning #'muffle-warning)) (let ((original (symbol-function 'load))) (setf (symbol-function 'load) (lambda (file &rest args) (if (m2c-readable-p file) (apply original file args) (m2c-refuse (format nil "load ~a" (ignore-errors (namestring file)))))))))

(handler-bind ((warning #'muffle-warning)) (dolist (name '(("SYSTEM" "SYSTEM") ("SYSTEM" "RUN-PROCESS") ("SYSTEM" "SOCKET") ("SYSTEM" "MAKE-SOCKET-PAIR") ("SYSTEM" "MAKE-SOCKET-STREAM") ("SYSTEM" "OPEN-NAMED-SOCKET") ("SYSTEM" "ACCEPT-SOCKET-CONNECTION") ("MAXIMA" "OPEN-SOCKET") ("SYSTEM" "CHDIR") ("SYSTEM" "CHDIR1") ("LISP" "DELETE-FILE") ("SYSTEM" "UNLINK") ("LISP" "RENAME-FILE") ("SYSTEM" "RENAME") ("SYSTEM" "MKDIR") ("SYSTEM" "SETENV") ("SYSTEM" "OPEN-FASD") ("SYSTEM" "XDR-OPEN") ("COMPILER" "SAFE-SYSTEM") ("SYSTEM" "SAVE-SYSTEM") ("LISP" "COMPILE-FILE") ("LISP" "COMPILE") ("SYSTEM" "FORK") ("SYSTEM" "EXECVE") ("SB-EXT" "RUN-PROGRAM") ("EXT" "RUN-PROGRAM") ("EXT" "SHELL") ("CCL" "RUN-PROGRAM") ("UIOP" "RUN-PROGRAM"))) (let* ((package (find-package (first name))) (symbol (and package (find-symbol (second name) package)))) (when (and symbol (fboundp symbol) (not (special-operator-p symbol)) (not (macro-function symbol))) (let ((label (string-downcase (second name)))) (setf (symbol-function symbol) (lambda (&rest args) (declare (ignore args)) (m2c-refuse label))))))))

(handler-bind ((warning #'muffle-warning)) (dolist (name (list @MAXIMA-NAMES@)) (let ((symbol (intern (concatenate 'string "$" name) :maxima)) (label (string-downcase name))) (remprop symbol 'autoload) (ignore-errors (mremprop symbol 'mexpr)) (ignore-errors (mremprop symbol 'mmacro)) (when (get symbol 'mfexpr*) (setf (get symbol 'mfexpr*) (lambda (&rest args) (declare (ignore args)) (m2c-refuse label)))) (setf (symbol-function symbol) (lambda (&rest args) (declare (ignore args)) (m2c-refuse label))) (let ((impl (find-symbol (concatenate 'string name "-IMPL") :maxima))) (when (and impl (fboundp impl)) (setf (symbol-function impl) (lambda (&rest args) (declare (ignore args)) (m2c-refuse label))))))))

(defun m2c-library-stream-p (stream) (let ((true (and (typep stream 'file-stream) (ignore-errors (namestring (truename (pathname stream))))))) (and true (m2c-under-roots true))))

(handler-bind ((warning #'muffle-warning)) (dolist (name '("SCAN-LISP-TOKEN" "SCAN-LISP-STRING")) (let ((symbol (find-symbol name :maxima))) (when (and symbol (fboundp symbol)) (let ((original (symbol-function symbol))) (setf (symbol-function symbol) (lambda (&rest args) (if (m2c-library-stream-p *parse-stream*) (apply original args) (m2c-refuse "?")))))))))

(handler-bind ((warning #'muffle-warning)) (setf (symbol-function 'break-call) (lambda (key args &rest more) (declare (ignore more)) (let ((form (and (eq key :lisp) (= (length args) 1) (first args)))) (if (and (consp form) (eq (first form) 'format) (eq (second form) t) (stringp (third form)) (null (cdddr form)) (let ((s (third form))) (and (> (length s) (length "@MARK@")) (string= "@MARK@" s :end2 (length "@MARK@")) (string= "~%" s :start2 (- (length s) 2)) (every (lambda (c) (or (upper-case-p c) (digit-char-p c) (member c '(#\- #\Space)))) (subseq s (length "@MARK@") (- (length s) 2)))))) (progn (format t (third form)) nil) (m2c-refuse (format nil ":~(~a~)" key)))))))
"""
