"""The documentation builds as one site with Sphinx without a single warning: the guides (Markdown
pages), the API reference and the executed worked-example notebook.

Same command as a developer's, a plain ``sphinx-build docs OUT`` (docs/conf.py), into a temporary
folder, with warnings as errors (``-W --keep-going`` reports every warning, then fails).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
#: API page -> the module it documents (one page per topic module, in its layer)
TOPICS = {"roughness": "surfaces.roughness", "readers": "surfaces.readers", "materials": "materials.pair",
          "potentials": "physics.potentials", "adhesion": "physics.adhesion", "nanoblock": "physics.nanoblock",
          "friction": "physics.friction", "sliding": "simulations.sliding", "gear": "physics.gear",
          "contact": "physics.contact", "mesh": "simulations.mesh", "coating": "physics.coating",
          "asperity": "physics.asperity", "stresses": "physics.stresses", "damage": "physics.damage",
          "study": "simulations.study", "chain": "job.chain", "parameters": "parameters", "output": "output"}


#: stderr lines that are not Sphinx warnings: the notebook kernel's notice about its local TCP transport
NOT_WARNINGS = ("[IPKernelApp] WARNING | Kernel is running over TCP",)


def test_docs_build_as_one_site_without_warnings(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_nb")
    pytest.importorskip("ipykernel")
    result = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-E", "-b", "html",
         "-d", str(tmp_path / "doctrees"), str(REPO / "docs"), str(tmp_path / "html")],
        capture_output=True, text=True, timeout=900)  # its time is a benchmark, not a test: bench/README.md
    stderr = "\n".join(line for line in result.stderr.splitlines() if not line.startswith(NOT_WARNINGS)).strip()
    assert result.returncode == 0 and not stderr, f"sphinx warnings:\n{result.stderr}"
    html = tmp_path / "html"
    index = (html / "index.html").read_text(encoding="utf-8")
    for page in ("model.html", "validation.html", "examples/worked_example.html", "api/mesh.html"):
        assert page in index, page  # one site: guides, notebook and API reference from one start page
    for topic, module in TOPICS.items():
        page = html / "api" / f"{topic}.html"
        assert page.is_file(), topic
        assert f"memstribo.{module}" in page.read_text(encoding="utf-8"), topic
    text = (html / "api" / "mesh.html").read_text(encoding="utf-8")
    assert "simulate_mesh" in text and "Parameters" in text  # numpydoc sections rendered by napoleon
    assert (html / "model.html").is_file() and (html / "validation.html").is_file()  # the Markdown pages
    notebook = (html / "examples" / "worked_example.html").read_text(encoding="utf-8")
    assert "OTS intact: COF" in notebook and "stiction returns at Omega" in notebook  # executed: its outputs
    assert notebook.count("<img") >= 4  # and its four figures (the AFM map, the cycle twice, the wear sweep)
    assert "Traceback" not in notebook and "CellExecutionError" not in notebook
