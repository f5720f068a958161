"""docs/games.md's coverage table lists every PGE call, as max2code.pge.COVERAGE has it, and the
module raises `unsupported` for exactly the calls the table says."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import max2code.pge as pge

DOC = Path(__file__).resolve().parents[2] / "docs" / "games.md"


def table() -> dict[str, str]:
    rows = re.findall(r"^\| `([^`]+)` \| (supported|unsupported)", DOC.read_text(), re.M)
    return dict(rows)


def test_the_table_is_the_coverage() -> None:
    rows = table()
    assert set(rows) == set(pge.COVERAGE)
    for name, state in rows.items():
        assert (state == "supported") == (pge.COVERAGE[name] is True), name


def test_every_module_level_call_the_table_names_exists() -> None:
    for name in table():
        if "." not in name and "(" not in name:
            assert callable(getattr(pge, name)), name


@pytest.mark.parametrize("call", [lambda: pge.play("x"),
                                  lambda: pge.message("x"), lambda: pge.delay(1),
                                  lambda: pge.draw_collision(True, True)])
def test_the_unsupported_ones_raise_naming_themselves(call) -> None:
    with pytest.raises(pge.PgeError, match=r"^unsupported: \w+"):
        call()
