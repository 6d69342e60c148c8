"""Load and nominal-area studies (thesis 4.9.3, 4.9.4): library sweep, CLI, value parsing, bad input."""

import pytest

from memstribo.cli.sweep import parse_values
from memstribo.errors import InputError
from memstribo.simulations.mesh import sweep

STEPS = "21"


def test_parse_values_ranges_and_lists():
    values = parse_values("25uN:300uN:25uN", "N")
    assert len(values) == 12
    assert values[0] == pytest.approx(25e-6) and values[-1] == pytest.approx(300e-6)
    assert parse_values("1,2,4", "") == [1.0, 2.0, 4.0]
    assert parse_values("1:3:1", "") == [1.0, 2.0, 3.0]
    with pytest.raises(InputError, match="START:STOP:STEP"):
        parse_values("1:2", "")
    with pytest.raises(InputError, match="STEP must be positive"):
        parse_values("3uN:1uN:1uN", "N")
    with pytest.raises(InputError):
        parse_values("25 m:50 m:5 m", "N")  # wrong dimension


def test_area_sweep_sets_rows(params):
    points = sweep(params, "area", [1, 3], steps=21)
    assert [p["area_multiple"] for p in points] == [1, 3]
    assert points[1]["area"] == pytest.approx(3 * params["adhesive_width"] ** 2)
    # more nanoblocks under the same 25 uN: more bonds, more dissipated energy (thesis 4.9.4, Figure 4-51)
    assert points[1]["energy_dissipated"] > points[0]["energy_dissipated"]


def test_sweep_bad_input(params):
    with pytest.raises(InputError, match="whole multiples"):
        sweep(params, "area", [1.5], steps=11)
    with pytest.raises(InputError, match="positive forces"):
        sweep(params, "load", [-1e-6], steps=11)
    with pytest.raises(InputError, match="'load', 'torque', 'area' or 'humidity'"):
        sweep(params, "speed", [1.0], steps=11)
    with pytest.raises(InputError, match="at least one value"):
        sweep(params, "load", [], steps=11)


def test_cli_sweep_load_json(cli):
    result = cli.json("sweep", "load", "--values", "25uN:75uN:50uN", "--steps", STEPS)
    assert result["parameter"] == "load"
    points = result["points"]
    assert [p["normal_load"] for p in points] == pytest.approx([25e-6, 75e-6])
    for key in ("cof_mean", "cof_chemical", "cof_vdw", "cof_elastic", "friction_force_mean", "stiction_margin",
                "sliding_distance", "steps"):
        assert key in points[0]
    # thesis 4.9.3: the dissipated energy rises with the load (a larger contact holds more bonds).
    # The COF is nearly flat with the thesis-3.5 adhesive layer (0.724 -> 0.703 from 25 to 300 uN
    # at 481 steps, docs/mesh.md) and not resolved at 21 steps, so only the energy and force trend is asserted.
    assert points[1]["energy_dissipated"] > points[0]["energy_dissipated"]
    assert points[1]["friction_force_mean"] > points[0]["friction_force_mean"]


def test_cli_sweep_area_text_and_out(cli, tmp_path):
    code, out, err = cli("sweep", "area", "--values", "1,2", "--steps", STEPS, "--out", tmp_path)
    assert code == 0, err
    assert "A_adh" in out and "cof_mean" in out
    for name in ("sweep_area.csv", "sweep_area.nc", "sweep_area_cof.png", "sweep_area_energy.svg"):
        assert (tmp_path / name).exists(), name


def test_cli_sweep_bad_values_exit_2(cli):
    code, out, err = cli("sweep", "load", "--values", "25uN:10uN:5uN", "--steps", STEPS)
    assert code == 2 and "STEP must be positive" in err and "Traceback" not in err
    code, out, err = cli("sweep", "area", "--values", "0.5", "--steps", STEPS)
    assert code == 2 and "whole multiples" in err and "Traceback" not in err


def test_cli_sweep_progress_bar_on_stderr(cli):
    code, out, err = cli("sweep", "load", "--values", "25uN", "--steps", "11", "--progress", "--json")
    assert code == 0 and "sweep load" in err
    assert out.lstrip().startswith("{")  # stdout stays one JSON object


def test_cli_sweep_torque_with_realisations_gives_the_stiction_probability(cli):
    """#13 item 7: stiction probability and efficiency versus drive torque (adhesion makes light loads stick)."""
    out = cli.json("sweep", "torque", "--values", "0.2e-7,1e-7", "--steps", "21", "--realisations", "2")
    low, high = out["points"]
    assert low["drive_torque"] == pytest.approx(0.2e-7) and 0.0 <= low["stiction_probability"] <= 1.0
    assert low["load_case"] == "torque" and 0.0 < high["mesh_efficiency"] < 1.0
    assert low["stiction_margin"] < high["stiction_margin"]  # less torque, less margin
