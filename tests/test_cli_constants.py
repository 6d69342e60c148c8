"""``memstribo constants``: keys, SI values, overrides through the parameter set, bad input."""

from __future__ import annotations

import pytest

KEYS = {"sigma", "epsilon", "contact_modulus", "work_of_adhesion", "no_slip_coefficient", "pull_off_force_block",
        "maugis_stress", "maugis_range", "bond_energy_chemical", "bond_energy_vdw", "bond_length"}


def test_constants_json_keys_and_thesis_values(cli):
    from memstribo.parameters import THESIS_VDW_FLAGS

    values = cli.json("constants", *THESIS_VDW_FLAGS.split())
    assert KEYS <= set(values)
    assert values["sigma"] == pytest.approx(2.0936e-10, rel=1e-4)
    assert values["epsilon"] == pytest.approx(2.902e-20, abs=5e-24)
    assert values["contact_modulus"] == pytest.approx(85.0e9, abs=0.05e9)
    assert values["work_of_adhesion"] == pytest.approx(0.445, abs=5e-4)
    assert values["no_slip_coefficient"] == pytest.approx(1.044, abs=5e-4)
    assert values["bond_energy_chemical"] == 5.43e-19
    assert values["bond_energy_vdw"] == 5.43e-21
    assert values["bond_length"] == 2.35e-10
    assert values["maugis_stress"] * values["maugis_range"] == pytest.approx(values["work_of_adhesion"], rel=1e-14)
    # default half width = 195.5 nm / 2
    assert values["half_width"] == pytest.approx(97.75e-9)


def test_constants_thesis_half_width(cli):
    from memstribo.parameters import THESIS_VDW_FLAGS

    values = cli.json("constants", "--half-width", "97.5 nm", *THESIS_VDW_FLAGS.split())
    assert values["half_width"] == pytest.approx(97.5e-9)
    assert values["pull_off_force_block"] == pytest.approx(3.03e-5, abs=0.005e-5)  # thesis prints 3.75e-5: see docs


def test_constants_follow_parameter_overrides(cli):
    values = cli.json("constants", "--set", "poisson_ratio=0.5")
    assert values["no_slip_coefficient"] == 1.0
    assert values["contact_modulus"] == pytest.approx(161e9 / 1.5)
    values = cli.json("constants", "--set", "work_of_adhesion=1.31 J/m^2")
    assert values["work_of_adhesion"] == 1.31


def test_constants_readable_output_has_units(cli):
    code, out, err = cli("constants")
    assert code == 0
    assert "GPa" in out and "J/m^2" in out and "µN" in out


@pytest.mark.parametrize("argv,match", [
    (["--set", "poisson_ratio=0.6"], "poisson_ratio"),
    (["--set", "poisson_ratio=-1"], "poisson_ratio"),
    (["--set", "youngs_modulus=0"], "youngs_modulus"),
    (["--set", "adhesive_width=-1 nm"], "adhesive_width"),
    (["--set", "hamaker_constant=-1e-18"], "hamaker_constant"),
    (["--half-width=-3 nm"], "half-width"),
    (["--half-width", "3 N"], "half-width"),
])
def test_constants_bad_input_exit_2(cli, argv, match):
    code, out, err = cli("constants", *argv)
    assert code == 2
    assert match in err
    assert "Traceback" not in err
