"""SAM coatings as parameter sets and the wear state Omega (thesis 5.3-5.4, 5.5.3)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from memstribo.physics.coating import (
    Coating,
    available_coatings,
    check_wear,
    cof_at_wear,
    critical_wear,
    get_coating,
)
from memstribo.errors import InputError


def test_available_coatings():
    assert available_coatings() == ["DDMS", "FDTS", "OTS", "W"]


def test_ots_values_and_sources():
    ots = get_coating("ots")
    assert ots.name == "OTS"
    # work of adhesion of a CH3-terminated pair, 2 gamma with gamma about 0.02-0.025 J/m^2
    assert 0.04 <= ots.work_of_adhesion <= 0.05
    # consistent with (3-34), w = A / (12 pi D0^2), to the printed digits
    assert ots.work_of_adhesion == pytest.approx(ots.hamaker_constant / (12 * math.pi * ots.cutoff_distance ** 2),
                                                 rel=1e-4)
    for key in ("vdw_bond_energy", "hamaker_constant", "cutoff_distance", "work_of_adhesion"):
        assert ots.sources[key]


def test_fdts_adheres_less_than_ots():
    ots, fdts = get_coating("OTS"), get_coating("FDTS")
    assert fdts.work_of_adhesion < ots.work_of_adhesion
    assert fdts.hamaker_constant < ots.hamaker_constant
    assert fdts.work_of_adhesion == pytest.approx(
        fdts.hamaker_constant / (12 * math.pi * fdts.cutoff_distance ** 2), rel=1e-4)


def test_coating_weaker_than_bare_silicon(params):
    ots = get_coating("OTS")
    assert ots.vdw_bond_energy < params["vdw_bond_energy"]
    assert ots.hamaker_constant < params["hamaker_constant"]


def test_unknown_coating_lists_available():
    with pytest.raises(InputError, match="available: DDMS, FDTS, OTS, W"):
        get_coating("teflon")


def test_updated_checks_values():
    ots = get_coating("OTS")
    assert ots.updated(vdw_bond_energy=1e-22).vdw_bond_energy == 1e-22
    with pytest.raises(InputError, match="vdw_bond_energy"):
        ots.updated(vdw_bond_energy=-1.0)
    with pytest.raises(InputError, match="cannot change"):
        ots.updated(name="x")


@pytest.mark.parametrize("bad", [-0.1, 1.2, math.nan, [0.2, 1.5], []])
def test_wear_outside_zero_one(bad):
    with pytest.raises(InputError, match="wear"):
        check_wear(bad)


def _sweep(margins, cofs=None):
    wear = np.linspace(0, 1, len(margins))
    cofs = np.linspace(0.2, 0.8, len(margins)) if cofs is None else cofs
    return xr.Dataset({"stiction_margin": ("wear", np.asarray(margins, float)), "cof_mean": ("wear", cofs)},
                      coords={"wear": wear})


def test_critical_wear_interpolates_the_margin():
    assert critical_wear(_sweep([2.0, 1.0, -1.0])) == pytest.approx(0.75)
    assert critical_wear(_sweep([2.0, 1.0, 0.5])) is None
    assert critical_wear(_sweep([-1.0, -2.0])) == 0.0


def test_cof_at_wear():
    sweep = _sweep([1, 1, 1], cofs=np.array([0.2, 0.4, 0.8]))
    np.testing.assert_allclose(cof_at_wear([0, 0.25, 1], sweep), [0.2, 0.3, 0.8])


@pytest.mark.parametrize("argv, match", [
    (["--wear", "1.5"], "wear"),
    (["--wear=-0.2"], "wear"),
    (["--wear", "0,x"], "wear"),
    (["--coating", "PTFE", "--wear", "0"], "unknown coating"),
])
def test_cli_bad_input(cli, argv, match):
    code, out, err = cli("coating", *argv)
    assert code == 2
    assert match in err and "Traceback" not in err


def test_coating_is_frozen():
    with pytest.raises(AttributeError):
        get_coating("OTS").name = "x"
    assert isinstance(get_coating("FDTS"), Coating)


# --- with the meshing-cycle simulation (few steps: fast) ------------------------------------------------------

STEPS = 24  # coarse, yet every wear state differs from the bare one (8 steps: Omega = 0.8 equals bare)


@pytest.fixture(scope="module")
def ots_sweep():
    from memstribo.simulations.coating_wear import wear_sweep
    from memstribo.parameters import get_parameter_values

    return wear_sweep(get_parameter_values(), "OTS", [0.0, 0.2, 0.4, 0.6, 0.8, 1.0], steps=STEPS)


def test_wear_one_equals_the_bare_mesh(params, ots_sweep):
    from memstribo.simulations import mesh

    bare = mesh.summarize(mesh.simulate_mesh(params, steps=STEPS))
    last = ots_sweep.sel(wear=1.0)
    assert float(last["cof_mean"]) == bare["cof_mean"]
    assert float(last["resisting_force_max"]) == bare["resisting_force_max"]
    assert float(last["stiction_margin"]) == bare["stiction_margin"]
    assert float(last["cof_chemical"]) == bare["cof_chemical"]


def test_cli_wear_one_equals_cli_mesh(cli):
    coated = cli.json("coating", "--wear", "1", "--steps", str(STEPS))
    bare = cli.json("mesh", "--steps", str(STEPS), "--no-refine")  # the one cycle, as the coating command runs
    assert coated["cof_mean"] == bare["cof_mean"]
    assert coated["stiction_margin"] == bare["stiction_margin"]
    assert coated["tangential_force"] == bare["tangential_force"]


def test_coated_cof_below_bare_at_every_wear(ots_sweep):
    cof = ots_sweep["cof_mean"].values
    assert np.all(cof[:-1] < cof[-1])
    assert ots_sweep["cof_chemical"].values[0] == 0.0  # a fully coated pair forms no chemical bonds
    assert ots_sweep["cof_chemical"].values[-1] > 0  # bare silicon does


def test_sweep_invariants(ots_sweep):
    assert np.all(ots_sweep["cof_mean"].values >= 0)
    margin = ots_sweep["stiction_margin"].values
    stiction = ots_sweep["stiction"].values.astype(bool)
    np.testing.assert_array_equal(stiction, margin < 0)  # stiction only where F_f reaches F_t
    from memstribo.quantities import quantity
    from memstribo.simulations.coating_wear import SWEEP_VARIABLES

    for name in SWEEP_VARIABLES:  # the names and units of the meshing cycle's summary (one vocabulary)
        assert ots_sweep[name].attrs == {"units": quantity(name).unit, "long_name": quantity(name).long_name}


def test_calibrated_ots_gives_the_thesis_cof(params):
    """The shipped OTS U_vdW is calibrated (docs/coating.md) to COF 0.185 at Omega = 0 (thesis 5.5.3)."""
    from memstribo.simulations.coating_wear import wear_sweep

    # at the thesis's reference conditions: its load case (25 uN), its full-energy vdW band, no adhesion in the solve
    from memstribo.parameters import THESIS_CONDITIONS

    reference = params.updated(THESIS_CONDITIONS)
    cof = float(wear_sweep(reference, "OTS", [0.0])["cof_mean"][0])
    # the mesh's default steps; tolerance 0.01 leaves room for small changes of the mesh model
    assert cof == pytest.approx(0.185, abs=0.01)


def test_calibration_reaches_its_target(params):
    from memstribo.simulations.coating_wear import calibrate_vdw_bond_energy, wear_sweep

    calibrated, record = calibrate_vdw_bond_energy(params, "OTS", 0.25, steps=STEPS)
    assert record["converged"] and record["cof_after"] == pytest.approx(0.25, rel=1e-3)
    assert float(wear_sweep(params, calibrated, [0.0], steps=STEPS)["cof_mean"][0]) == pytest.approx(0.25, rel=1e-3)


def test_cli_table_and_json_points(cli, tmp_path):
    out = cli.json("coating", "--wear", "0,1", "--steps", str(STEPS), "--out", tmp_path)
    assert out["coating"] == "OTS" and [p["wear"] for p in out["points"]] == [0.0, 1.0]
    assert set(out["points"][0]) == {"wear", "cof_mean", "cof_chemical", "cof_vdw", "cof_elastic", "resisting_force_max",
                                     "tangential_force", "stiction", "stiction_margin"}
    for name in ("coating_wear.nc", "coating_wear.csv", "cof_vs_wear.png", "cof_vs_wear.svg",
                 "friction_vs_tangential.png"):
        assert (tmp_path / name).stat().st_size > 0
    code, text, err = cli("coating", "--wear", "0,0.5", "--steps", str(STEPS))
    assert code == 0 and "cof_chemical" in text and "mN" in text


def test_cli_calibrate_and_percent_wear(cli):
    out = cli.json("coating", "--calibrate", "0.3", "--steps", str(STEPS))
    assert out["converged"] and out["cof_after"] == pytest.approx(0.3, rel=1e-3)
    assert out["vdw_bond_energy_after"] == pytest.approx(out["factor"] * out["vdw_bond_energy_before"])
    half = cli.json("coating", "--wear", "50%", "--steps", str(STEPS))
    assert half["wear"] == 0.5


def test_coatings_are_parameter_sets_reached_by_set_and_config(cli, tmp_path):
    """#11 item 4: --set reaches every coating value; --calibrate --out writes a config that --config reads back."""
    listed = cli.json("parameters", "--coating", "OTS")
    assert listed["coating"] == "OTS" and "Israelachvili" in listed["sources"]["hamaker_constant"]
    changed = cli.json("parameters", "--coating", "OTS", "--set", "coating_work_of_adhesion=0.05 J/m^2")
    assert changed["work_of_adhesion"] == pytest.approx(0.05) and "--set" in changed["sources"]["work_of_adhesion"]
    target = tmp_path / "ots_calibrated.toml"
    record = cli.json("coating", "--calibrate", "0.3", "--steps", "11", "--out", target)
    assert target.exists() and record["config_file"] == str(target)
    read_back = cli.json("parameters", "--coating", "OTS", "--config", target)
    assert read_back["vdw_bond_energy"] == pytest.approx(record["vdw_bond_energy_after"], rel=1e-12)
    # the calibrated coating gives the target COF through the config file
    coated = cli.json("coating", "--wear", "0", "--steps", "11", "--config", target)
    assert coated["cof_mean"] == pytest.approx(0.3, rel=2e-3)
