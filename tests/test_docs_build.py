"""The documentation builds with Sphinx without a single warning (API reference + Markdown pages).

Same command as a developer's (see docs/api/conf.py), into a temporary folder, with warnings
as errors (``-W --keep-going`` reports every warning, then fails).
"""

from __future__ import annotations

import subprocess
import sys
import time
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


def test_docs_build_without_warnings(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    start = time.perf_counter()
    result = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-E", "-b", "html",
         "-c", str(REPO / "docs" / "api"), "-d", str(tmp_path / "doctrees"), str(REPO / "docs"), str(tmp_path / "html")],
        capture_output=True, text=True, timeout=300)
    seconds = time.perf_counter() - start
    assert result.returncode == 0 and not result.stderr.strip(), f"sphinx warnings:\n{result.stderr}"
    html = tmp_path / "html"
    for topic, module in TOPICS.items():
        page = html / "api" / f"{topic}.html"
        assert page.is_file(), topic
        assert f"memstribo.{module}" in page.read_text(encoding="utf-8"), topic
    text = (html / "api" / "mesh.html").read_text(encoding="utf-8")
    assert "simulate_mesh" in text and "Parameters" in text  # numpydoc sections rendered by napoleon
    assert (html / "model.html").is_file() and (html / "validation.html").is_file()  # the Markdown pages
    assert seconds < 120, f"the docs build took {seconds:.0f} s"
