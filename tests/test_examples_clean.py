"""#29 item 7: the examples leave the tree clean. Each writes into its own output folder (examples/output/, ignored
by git), never into tracked files such as docs/figures/; `git status --porcelain` is the same after running them."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent

#: the quick examples and their arguments (the design map at its tiny size); the notebook has its own test
QUICK = [("interface_figure.py", []), ("adhesive_line_contact.py", []), ("design_map_example.py", ["--tiny"]),
         ("api_afm_profile.py", [])]


def _status():
    return subprocess.run(["git", "status", "--porcelain", "--untracked-files=all"], cwd=REPO, capture_output=True,
                          text=True, check=True).stdout


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("git") is None or not (REPO / ".git").exists(), reason="needs a git checkout")
def test_quick_examples_leave_git_status_unchanged():
    before = _status()
    env = {**os.environ, "MPLBACKEND": "Agg"}
    for script, arguments in QUICK:
        run = subprocess.run([sys.executable, str(REPO / "examples" / script), *arguments], cwd=REPO, env=env,
                             capture_output=True, text=True, timeout=600)
        assert run.returncode == 0, f"{script}: {run.stderr[-1500:]}"
    assert _status() == before, "an example wrote into tracked or unignored files"


def test_no_example_writes_into_docs_by_default():
    """The examples' default output is their own folder under examples/output/ (fast, no run)."""
    for path in sorted((REPO / "examples").glob("*.py")):
        text = path.read_text(encoding="utf-8")
        assert '/ "docs" / "figures"' not in text and 'ROOT / "docs"' not in text, path.name


@pytest.mark.skipif(shutil.which("git") is None or not (REPO / ".git").exists(), reason="needs a git checkout")
def test_the_toml_examples_write_into_ignored_folders():
    """Issue 41: the command in each TOML example's first line writes into a folder git ignores (its --out, else the
    command's default folder), so `git status` stays clean after it (fast: no run, `git check-ignore`)."""
    import re
    import shlex

    for path in sorted((REPO / "examples").glob("*.toml")):
        first = path.read_text(encoding="utf-8").splitlines()[0]
        assert first.startswith("# memstribo "), (path.name, first)
        words = shlex.split(first[2:])
        if words[1] == "validate-lab" and "--write" not in words:
            continue  # prints its predictions, writes no file
        if "--out" in words:
            out = words[words.index("--out") + 1]
        else:
            assert words[1] in ("study", "design"), (path.name, words)
            out = f"memstribo-{words[1]}-{path.stem}"  # memstribo study's and design's default folder
        assert not re.match(r"(/|\.\.)", out), out  # inside the checkout
        probe = f"{out}/x.nc"
        ignored = subprocess.run(["git", "check-ignore", "-q", probe], cwd=REPO)
        assert ignored.returncode == 0, f"{path.name}: {out}/ is not ignored by git"
