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
