"""Shared fixtures. Test data live in the repository's data/afm/ (never ../shared/)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
AFM = REPO / "data" / "afm"


@pytest.fixture
def afm_dir() -> Path:
    """Folder of the real AFM/stylus files shipped with the repository."""
    return AFM


@pytest.fixture
def params():
    """The default parameter set (the thesis's silicon microgear case)."""
    from memstribo.parameters import get_parameter_values

    return get_parameter_values()


@pytest.fixture
def cli(capsys):
    """Run the CLI in-process: ``cli("roughness", path, "--json")`` -> (exit code, stdout, stderr).

    With ``--json`` in the arguments and exit code 0, stdout is also parsed: use ``cli.json(...)``.
    """
    from memstribo.cli.main import main

    class Runner:
        def __call__(self, *argv):
            code = main([str(a) for a in argv])
            out, err = capsys.readouterr()
            return code, out, err

        def json(self, *argv):
            code, out, err = self(*argv, "--json")
            assert code == 0, err
            assert "Traceback" not in err
            return json.loads(out)

    return Runner()


#: The suite's heaviest files (wall seconds on 2 cores, 2026-11-29), first: pytest-xdist hands out whole files
#: (``--dist loadfile``) in this order (``--no-loadscope-reorder``: not the most tests first, which left the longest
#: single tests, the docs build and the validation table's topics, for the end), so that both workers end together
#: (longest first; issue 40: the suite in 8 minutes on 2 cores). The rest keep their order.
HEAVY_FIRST = ("test_docs_build.py", "test_map.py", "test_speed.py", "test_provenance.py",
               "test_validation_fresh_a.py", "test_validation_fresh_c.py", "test_validation_fresh_b.py",
               "test_hardening4_physics.py", "test_chain.py", "test_notebook.py", "test_readme.py", "test_report.py",
               "test_uncertainty.py", "test_adhesive_contact.py", "test_static_friction.py")


def pytest_collection_modifyitems(config, items):
    rank = {name: i for i, name in enumerate(HEAVY_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))  # stable: within a file, the file's order
