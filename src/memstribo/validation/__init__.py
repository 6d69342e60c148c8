"""memstribo against the thesis, closed forms and invariants: the rows of docs/validation.md.

Each module in this package (one per topic) defines ``rows() -> list[ValidationRow]``,
computing memstribo's value by the same library call that the named CLI command makes.
``python -m memstribo.validation`` collects them all and writes docs/validation.md, so the
table cannot drift from the code; the tests assert the same comparisons.
"""

from __future__ import annotations

from memstribo.validation.rows import ValidationRow, compare  # noqa: F401  (the public names of this package)


#: The topic modules of this package, in the order of the table (one ``rows()`` each).
TOPICS = ("adhesion", "adhesive_contact", "capillary", "coating", "contact", "damage", "friction", "gear", "mesh", "roughness", "run",
          "stresses", "surface_contact")


def all_rows() -> list[ValidationRow]:
    """Rows of every topic module in :data:`TOPICS`, in that order."""
    from memstribo.validation import (adhesion, adhesive_contact, capillary, coating, contact, damage, friction, gear, mesh, roughness, run, stresses,
                   surface_contact)

    modules = {"adhesion": adhesion, "adhesive_contact": adhesive_contact, "capillary": capillary, "coating": coating, "contact": contact, "damage": damage, "friction": friction,
               "gear": gear, "mesh": mesh, "roughness": roughness, "run": run, "stresses": stresses, "surface_contact": surface_contact}
    rows: list[ValidationRow] = []
    for name in TOPICS:
        rows.extend(modules[name].rows())
    return rows


#: The rows of this version, written by ``python -m memstribo.validation`` next to docs/validation.md and shipped with
#: the package: the run's report shows them without computing them again (1-2 min; issue 40).
#: tests/test_validation_table.py checks that they render as a fresh computation does.
SHIPPED_ROWS = "rows.json"


def rows_to_json(rows) -> str:
    """The rows as JSON text (one object per row, floats in full)."""
    import dataclasses
    import json

    from memstribo.output import to_jsonable

    return json.dumps(to_jsonable([dataclasses.asdict(row) for row in rows]), indent=1, ensure_ascii=False) + "\n"


def shipped_rows() -> list[ValidationRow] | None:
    """The rows shipped with the package (:data:`SHIPPED_ROWS`), or None where there are none."""
    import json
    from importlib import resources

    source = resources.files("memstribo.validation").joinpath(SHIPPED_ROWS)
    if not source.is_file():
        return None
    rows = []
    for entry in json.loads(source.read_text(encoding="utf-8")):
        if entry.get("band") is not None:
            entry["band"] = tuple(entry["band"])
        rows.append(ValidationRow(**entry))
    return rows
