"""The validation table's fresh computation, one topic at a time (tests/test_validation_fresh_*.py).

The shipped rows (``src/memstribo/validation/rows.json``) are what docs/validation.md and the run's report show
(tests/test_validation_table.py checks them against the doc); each topic's rows computed now must render exactly as
the shipped ones and keep their verdicts. The topics are split over a few test files so that the suite's workers
(pytest-xdist, one file per worker) compute them side by side (issue 40: the CI suite in 8 minutes).
"""

from __future__ import annotations

import importlib

from memstribo.validation import TOPICS, shipped_rows
from memstribo.validation.__main__ import render_markdown

#: the topics of each test file, about equal in time (the coating topic's five thesis-case cycles alone in one)
GROUPS = {
    "a": ("coating",),
    "b": ("capillary", "run", "stresses", "damage", "roughness", "friction", "adhesion", "contact"),
    "c": ("mesh", "adhesive_contact", "gear", "surface_contact"),
}


#: the table's headings (``ValidationRow.topic``) of each topic module where they are not its name
HEADINGS = {"adhesion": ("nanoscale physics",), "adhesive_contact": ("adhesive contact",),
            "damage": ("asperity", "damage"), "surface_contact": ("surface contact",)}


def headings(topic: str) -> tuple[str, ...]:
    return HEADINGS.get(topic, (topic,))


def check_topic(topic: str) -> None:
    """The rows of ``topic`` computed now equal the shipped ones (rendered table, verdicts, bands), as expected."""
    fresh = importlib.import_module(f"memstribo.validation.{topic}").rows()
    assert {row.topic for row in fresh} == set(headings(topic)), "a heading changed: update HEADINGS"
    shipped = [row for row in (shipped_rows() or []) if row.topic in headings(topic)]
    assert shipped, f"no shipped rows of {topic}: run 'python -m memstribo.validation' and commit rows.json"
    assert render_markdown(fresh) == render_markdown(shipped), (
        f"the {topic} rows changed: run 'python -m memstribo.validation' and commit docs/validation.md and rows.json")
    key = [(r.topic, r.quantity, r.agrees, r.expected, r.band, r.calibrated) for r in fresh]
    assert key == [(r.topic, r.quantity, r.agrees, r.expected, r.band, r.calibrated) for r in shipped]
    wrong = [f"{row.quantity}: agrees={row.agrees}, expected {row.expected}" for row in fresh if not row.as_expected]
    assert not wrong, "\n".join(wrong)


def every_topic_in_one_group() -> bool:
    return sorted(t for group in GROUPS.values() for t in group) == sorted(TOPICS)
