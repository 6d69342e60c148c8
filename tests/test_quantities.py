"""One vocabulary of results (#11 item 3): every name a command prints or a file holds is defined once, in
memstribo.quantities, with its unit; the same quantity has the same name in every command."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from memstribo.output import udunits
from memstribo.quantities import QUANTITIES, STATISTICS, known, markdown_table, quantity

REPO = Path(__file__).resolve().parent.parent
DI = REPO / "data" / "afm" / "di-3.di"

#: keys whose value is a free-form map (parameter names -> values), not quantities of their own
FREE_FORM = {"parameters", "rules", "overrides"}


def _keys(value, found: set[str]):
    if isinstance(value, dict):
        for key, item in value.items():
            found.add(key)
            if key not in FREE_FORM:
                _keys(item, found)
    elif isinstance(value, list) and value and isinstance(value[0], dict):
        for item in value:
            _keys(item, found)
    return found


def test_the_registry_is_well_formed():
    for name, q in QUANTITIES.items():
        assert q.name == name and q.long_name and q.description, name
        assert q.unit == "" or udunits(q.unit) == q.unit, f"{name}: unit {q.unit!r} is not in UDUNITS form"
        base, _, suffix = name.rpartition("_")
        # a statistic is never registered by hand: it is derived (the same unit, the same base name)
        assert not (suffix in STATISTICS and base in QUANTITIES), f"{name} is a statistic of {base}"


def test_statistics_and_parameters_are_derived():
    assert quantity("cof_mean").unit == "1" and "mean" in quantity("cof_mean").long_name
    assert quantity("stiction_margin_p05").unit == "N"
    assert quantity("cof_mean_p95").unit == "1"
    assert quantity("normal_load").unit == "N" and "input parameter" in quantity("normal_load").description
    assert not known("cof_average") and not known("friction")
    with pytest.raises(KeyError, match="vocabulary"):
        quantity("no_such_quantity")


def test_docs_page_is_generated_from_the_registry():
    page = (REPO / "docs" / "quantities.md").read_text(encoding="utf-8")
    assert page == markdown_table(), "regenerate: python -m memstribo.quantities > docs/quantities.md"


COMMANDS = [
    ("constants",),
    ("nanoblock",),
    ("gear",),
    ("parameters",),
    ("roughness", "thesis"),
    ("roughness", str(DI)),
    ("slide", "--model", "fixed-load", "--distance", "0.2 um", "--load", "25 uN"),
    ("slide", "--model", "estimate"),
    ("asperity", "--load", "1 uN"),
    ("contact", "--flat", "--radius", "10 um", "--load", "100 uN/m"),
    ("contact", "--flat", "--radius", "10 um", "--adhesion", "--pull-off"),
    ("contact", "--surface", str(DI), "--mean-pressure", "1 MPa"),
    ("mesh", "--steps", "11"),
    ("coating", "--steps", "11", "--wear", "0"),
    ("coating", "--calibrate", "0.2", "--steps", "11"),
    ("damage", "--steps", "11"),
    ("sweep", "load", "--values", "10uN,20uN", "--steps", "11"),
]


@pytest.mark.parametrize("argv", COMMANDS, ids=[" ".join(c[:2]) for c in COMMANDS])
def test_every_json_key_of_every_command_is_in_the_vocabulary(cli, argv):
    out = cli.json(*argv)
    unknown = sorted(k for k in _keys(out, set()) if not known(k))
    assert not unknown, f"memstribo {' '.join(argv)} prints names the vocabulary does not know: {unknown}"


def test_the_same_quantity_has_the_same_name_in_mesh_coating_and_slide(cli):
    mesh = cli.json("mesh", "--steps", "11", "--no-refine")
    coating = cli.json("coating", "--steps", "11", "--wear", "1")  # Omega = 1: the bare teeth
    slide = cli.json("slide", "--model", "single")
    shared = set(coating) - {"coating", "wear", "warnings"}
    assert shared <= set(mesh), f"coating names that the meshing cycle calls otherwise: {shared - set(mesh)}"
    for key in shared:
        assert coating[key] == pytest.approx(mesh[key], rel=1e-12), key
    assert {"cof_mean", "friction_force_mean", "adhesion_force_mean", "sliding_distance"} <= set(slide)
    assert not {"cof", "friction_force", "distance"} & set(slide)


def test_the_meshing_cycle_writes_the_vocabularys_units_and_long_names(params):
    from memstribo.simulations.mesh import simulate_mesh

    dataset = simulate_mesh(params, steps=11)
    for name, variable in dataset.variables.items():
        q = quantity(str(name))
        assert variable.attrs.get("units", q.unit) == q.unit, name
        if name != "load_share":  # its long name says which load-sharing rule was used
            assert variable.attrs.get("long_name") == q.long_name, name


def test_a_command_that_names_its_own_unit_agrees_with_the_vocabulary():
    """CommandResult.units overrides the registry only where a unit depends on the input (damage's Pa^m)."""
    code = ("import json, sys; from memstribo.cli import common; from memstribo.quantities import known, unit\n"
            "bad = []\n"
            "orig = common.CommandResult.json_values\n"
            "def check(self):\n"
            "    for k, u in self.units.items():\n"
            "        mine = '1' if u == '' else u\n"
            "        if known(k) and unit(k) not in ('', mine) and k not in ('omega_over_c1_max', 'damage_coefficient'):\n"
            "            bad.append((k, u, unit(k)))\n"
            "    return orig(self)\n"
            "common.CommandResult.json_values = check\n"
            "from memstribo.cli.main import main\n"
            "for argv in [['gear'], ['constants'], ['nanoblock'], ['contact', '--flat', '--radius', '10um', "
            "'--load', '100uN/m'], ['asperity', '--load', '1uN'], ['roughness', 'thesis']]:\n"
            "    main(argv + ['--json'])\n"
            "print(json.dumps(bad), file=sys.stderr)\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stderr.strip().splitlines()[-1] == "[]", result.stderr


def test_every_numeric_registered_unit_reads_in_text_output():
    from memstribo.output import format_quantity

    assert format_quantity(0.25, "1") == "0.25"
    assert format_quantity(2.5e-5, "N") == "25 µN"
    assert np.isfinite(len(QUANTITIES)) and len(QUANTITIES) > 150
