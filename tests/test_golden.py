"""Golden files: the generated code of every shipped equation in every language, byte for byte.

A change to a printer or template shows up here as a diff to review; refresh deliberately with
`python -m pytest tests/test_golden.py --update-golden`.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import ROOT

from max2code.codegen.emit import module_name
from max2code.codegen.generate import generate, load
from max2code.languages import LANGUAGES

GOLDEN = ROOT / "tests" / "golden"
EQUATIONS = sorted((ROOT / "equations").glob("*.mxm"))


@pytest.mark.parametrize("path", EQUATIONS, ids=lambda p: p.stem)
def test_golden(path: Path, maxima_exe: str, update_golden: bool) -> None:
    rel = str(path.relative_to(ROOT))
    spec, poly = load(rel)
    for lang_name, lang in sorted(LANGUAGES.items()):
        out = f"{module_name(spec)}{lang.extension}"
        result = generate(spec, poly, lang, "module", out)
        files = [(out, result.text)] + [(Path(p).name, t) for p, t in result.companions]
        for name, text in files:
            golden = GOLDEN / lang_name / (name + ".golden")  # not picked up as code by tools
            if update_golden:
                golden.parent.mkdir(parents=True, exist_ok=True)
                golden.write_text(text)
                continue
            assert golden.exists(), f"no golden file {golden}: run with --update-golden"
            assert text == golden.read_text(), f"{golden} differs (review, then --update-golden)"
