"""The .mxm grammar: both dialects verbatim, our extensions, and positions for diagnostics."""

from __future__ import annotations

import pytest

from conftest import ROOT

from max2code.diagnostics import Max2CodeError
from max2code.front.parse import parse_file, parse_text

ORIGINAL_DIALECT = """\
// circle against circle, as the original tool's files were written
polynomial terms 3
initialise {
  /* a brace in a comment: { */
  double a[3]; // http://example.org/{path}
  { int nested = 1; (void)nested; }
  const char *s = "}";
}
term 0 { a[0] = }
term 1 { a[1] = }
term 2 { a[2] = }
finalise { t = first(a); }
{
  // a comment in the Maxima program
  S(X) := ''(X^2) ;  /* quote-quote */
  (x + v*t)^2 - r^2 ;
  quit();
}
"""


def test_original_dialect() -> None:
    spec = parse_text(ORIGINAL_DIALECT, "orig.mxm")
    assert spec.terms_declared is not None and spec.terms_declared.value == 3
    init = spec.initialise[0].text
    assert "// http://example.org/{path}" in init  # the target's comment is kept verbatim
    assert '"}"' in init and "{ int nested = 1;" in init
    assert [t.index for t in spec.terms] == [0, 1, 2]
    assert spec.terms[1].prefix.text.strip() == "a[1] ="
    assert spec.finalise[0].text.strip() == "t = first(a);"
    texts = [s.text for s in spec.program.statements]
    assert len(texts) == 2  # quit() dropped, the // comment blanked
    assert texts[0] == "S(X) := ''(X^2) ;"
    assert texts[1].endswith("(x + v*t)^2 - r^2 ;") and "//" not in "".join(texts)
    assert [s.pos.line for s in spec.program.statements] == [15, 16]
    assert spec.program.statements[0].pos.col == 3


@pytest.mark.parametrize("name", ["circle-circle.mxm", "point-line.mxm"])
def test_paper_figures_parse_verbatim(name: str) -> None:
    spec = parse_file(str(ROOT / "equations" / "paper" / name))
    assert spec.terms_declared is not None
    assert len(spec.terms) == spec.terms_declared.value
    assert "findSmallestPositiveRoot(a)" in spec.finalise[0].text
    assert spec.program.statements[-1].text.startswith("format(%, %poly(t))")


def test_extensions_and_language_tags() -> None:
    text = """function collide
parameters b, a
variable s
initialise c { double k[2]; }
initialise python { k = [0.0, 0.0] }
term 0 c { k[0] = }
term 0 { K[0] := }
begin
(a + b*s)^2 - 1;
end
"""
    spec = parse_text(text, "x.mxm")
    assert spec.function is not None and spec.function.value == "collide"
    assert spec.parameter_order == ("b", "a")
    assert spec.variable == "s"
    assert spec.block_for(spec.initialise, "c").text.strip() == "double k[2];"
    assert spec.block_for(spec.initialise, "python").text.strip() == "k = [0.0, 0.0]"
    assert spec.block_for(spec.initialise, "m2") is None
    assert spec.term_prefixes("c")[0].prefix.text.strip() == "k[0] ="
    assert spec.term_prefixes("m2")[0].prefix.text.strip() == "K[0] :="


def test_crlf_tabs_and_non_ascii_comments() -> None:
    text = "// équation\r\npolynomial terms 2\r\n\tterm 0 {\ta[0] = }\r\nterm 1 { a[1] = }\r\nbegin\r\n\t(x + t)*y;\r\nend\r\n"
    spec = parse_text(text.replace("\r\n", "\n"), "crlf.mxm")
    assert spec.program.statements[0].pos.line == 6
    assert spec.terms[0].pos.line == 3


def test_crlf_file_reads_like_lf(tmp_path) -> None:
    path = tmp_path / "crlf.mxm"
    path.write_bytes(b"polynomial terms 2\r\nbegin\r\n(x + t)*y;\r\nend\r\n")
    spec = parse_file(str(path))
    assert spec.program.statements[0].text == "(x + t)*y;"
    assert spec.program.statements[0].pos.line == 3


@pytest.mark.parametrize("text, where, message", [
    ("polynomial terms 2\ninitialise { a\nbegin\nx;\nend\n", "2:12", "unterminated block"),
    ("term 1 { a }\nbegin\nt;\nend\n", "1:1", "'term 0' is missing"),
    ("term 0 { a }\nterm 0 { b }\nbegin\nt;\nend\n", "2:1", "duplicate 'term 0'"),
    ("polynomial terms 1\nterm 0 { a }\nterm 1 { b }\nbegin\nt;\nend\n", "3:1", "beyond"),
    ("polynomial terms 2\n", "2:1", "unexpected end of file"),
    ("begin\nt^2 - 1\nend\n", "2:1", "not terminated"),
    ("polynomial terms 2\npolynomial terms 3\nbegin\nt;\nend\n", "2:1", "duplicate 'polynomial terms'"),
    ("parameters a, a\nbegin\nt;\nend\n", "1:1", "listed twice"),
    ("   \n\n", "1:1", "empty file"),
    ("begin\n x: \"open;\nend\n", "2:5", "unterminated string"),
])
def test_bad_input_positions(text: str, where: str, message: str) -> None:
    with pytest.raises(Max2CodeError) as info:
        parse_text(text, "bad.mxm")
    diag = str(info.value.diagnostics[0])
    assert diag.startswith(f"bad.mxm:{where}: error: "), diag
    assert message in diag


def test_a_parameter_named_begin_is_a_name_not_the_program() -> None:
    """The block pre-pass must not take a header name `BEGIN` (a comma list, a role) for the
    program's start; the grammar's own lexer never did (test_names' corpus has such names)."""
    from max2code.front.parse import parse_text
    spec = parse_text("function f\nparameters a, BEGIN\nrole r = BEGIN\nbegin\n"
                      "a*t - BEGIN;\nend\n", "begin.mxm")
    assert list(spec.parameters.value) == ["a", "BEGIN"]
    assert [st.text.strip() for st in spec.program.statements] == ["a*t - BEGIN;"]
    assert spec.program.pos.line == 4
    # however many blanks stand between the comma and the name
    spec = parse_text("parameters a,\n" + " " * 200 + "BEGIN\nbegin\na*t - BEGIN;\nend\n", "b.mxm")
    assert list(spec.parameters.value) == ["a", "BEGIN"]
