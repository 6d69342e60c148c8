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
TOPICS = ["roughness", "readers", "potentials", "adhesion", "nanoblock", "friction", "sliding", "gear", "contact",
          "mesh", "coating", "asperity", "stresses", "damage", "study", "chain", "parameters", "output"]


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
    for topic in TOPICS:
        page = html / "api" / f"{topic}.html"
        assert page.is_file(), topic
        assert f"memstribo.{topic}" in page.read_text(encoding="utf-8"), topic
    text = (html / "api" / "mesh.html").read_text(encoding="utf-8")
    assert "simulate_mesh" in text and "Parameters" in text  # numpydoc sections rendered by napoleon
    assert (html / "model.html").is_file() and (html / "validation.html").is_file()  # the Markdown pages
    assert seconds < 120, f"the docs build took {seconds:.0f} s"
