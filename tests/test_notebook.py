"""examples/worked_example.ipynb is committed without outputs (so that diffs stay readable and no stale numbers are
shown). That it runs from top to bottom without an error, printing its results and drawing its four figures, is
tested by the docs build, which executes it (tests/test_docs_build.py; issue 40: not executed twice in the suite)."""

from __future__ import annotations

from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
NOTEBOOK = REPO / "examples" / "worked_example.ipynb"


def test_committed_notebook_has_no_outputs():
    nbformat = pytest.importorskip("nbformat")
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    nbformat.validate(notebook)
    for cell in notebook.cells:
        if cell.cell_type == "code":
            assert cell.outputs == [] and cell.execution_count is None, "strip the outputs before committing"
