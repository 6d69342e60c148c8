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
