"""docs/validation.md is generated from the code: it must equal a fresh generation."""

from __future__ import annotations

from pathlib import Path

import pytest

from memstribo.validation import ValidationRow, all_rows, compare
from memstribo.validation.__main__ import DEFAULT_OUTPUT, format_number, render_markdown, summary

REPO = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def rows():
    return all_rows()


def test_committed_validation_md_equals_a_fresh_generation(rows):
    assert DEFAULT_OUTPUT == REPO / "docs" / "validation.md"
    committed = DEFAULT_OUTPUT.read_text(encoding="utf-8")
    fresh = render_markdown(rows)
    assert committed == fresh, ("docs/validation.md is out of date: run 'python -m memstribo.validation' "
                                "and commit the result")


def test_every_row_names_its_command_and_explains_a_difference(rows):
    assert rows, "no validation rows at all"
    for row in rows:
        assert row.command.startswith(("memstribo ", "python ")), row
        assert row.tolerance and row.reference and row.quantity, row
        if not row.agrees:
            assert row.note, f"row {row.quantity!r} differs without a note saying why"


def test_render_groups_by_topic_escapes_pipes_and_counts():
    rows = [compare("alpha", "a|b", "closed form", 1.0, 1.0000001, "m", rtol=1e-6, command="memstribo x --json"),
            ValidationRow("beta", "trend", "thesis 4.9", None, None, "", "trend", False, "memstribo y",
                          "differs: see docs"),
            compare("alpha", "c", "thesis (3-1)", 2.0, 3.0, "", atol=0.1, command="memstribo z", note="why")]
    text = render_markdown(rows)
    assert text.index("## alpha") < text.index("## beta")
    assert text.count("## alpha") == 1
    assert "a\\|b" in text and "| - | - |" in text
    assert "**3 comparisons: 1 agree, 2 differ" in text
    assert summary(rows) == {"rows": 3, "agree": 1, "differ": 2}
    assert "GENERATED FILE" in text


def test_format_number_is_six_significant_digits():
    assert format_number(3.878787878) == "3.87879"
    assert format_number(2.82e-3) == "0.00282"
    assert format_number(None) == "-"


def test_check_mode_and_writing(tmp_path, monkeypatch, capsys):
    from memstribo.validation import __main__ as generator

    rows = [compare("alpha", "x", "closed form", 1.0, 1.0, "", rtol=0, command="memstribo x")]
    monkeypatch.setattr(generator, "all_rows", lambda: rows)
    target = tmp_path / "validation.md"
    target.write_text("old\n", encoding="utf-8")
    assert generator.main(["--check", "--output", str(target)]) == 1
    assert "out of date" in capsys.readouterr().err
    assert generator.main(["--output", str(target)]) == 0
    assert target.read_text(encoding="utf-8") == render_markdown(rows)
    assert generator.main(["--check", "--output", str(target)]) == 0
    assert not list(tmp_path.glob("*.tmp"))


def test_round_off_residuals_are_shown_as_bounds_not_digits():
    from memstribo.validation.__main__ import format_value

    residual = compare("alpha", "r", "invariant", 0.0, 9.75836e-08, "p0", atol=2e-6, command="python x")
    assert residual.shown_as_bound and format_value(residual) == "< 2e-06"
    assert "9.758" not in render_markdown([residual])
    # an exact zero, a failing residual and a relative comparison keep their digits
    assert format_value(compare("a", "z", "invariant", 0.0, 0.0, atol=1e-10, command="python x")) == "0"
    failing = compare("a", "f", "invariant", 0.0, 3e-3, atol=1e-6, command="python x")
    assert not failing.shown_as_bound and format_value(failing) == "0.003"
    assert format_value(compare("a", "q", "thesis", 1.0, 1.0000001, rtol=1e-6, command="python x")) == "1"


def test_committed_table_holds_no_round_off_digits(rows):
    """Rows of round-off residuals are bounds in the committed doc: the same on every platform."""
    from memstribo.validation.__main__ import format_value

    for row in rows:
        if row.reference_value == 0 and row.agrees and row.value not in (0, None) and "abs" in row.tolerance:
            assert format_value(row).startswith("< "), row
