"""The meshing cycle's strength and temperature (memstribo.simulations.tooth_life) on synthetic cycles."""

import math
import re

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.parameters import get_parameter_values
from memstribo.physics.coating import available_coatings, get_coating
from memstribo.quantities import known
from memstribo.simulations.tooth_life import TOOTH_LIFE_KEYS, fracture_probability_within, synthetic_cycle, tooth_life


@pytest.fixture(scope="module")
def params():
    return get_parameter_values()


def test_fracture_probability_rises_with_torque(params):
    torques = [0.4e-7, 0.6e-7, 0.8e-7, 1.0e-7, 2.0e-7]
    results = [tooth_life(synthetic_cycle(params.updated({"drive_torque": t})), params.updated({"drive_torque": t}))
               for t in torques]
    p = [r["fracture_probability"] for r in results]
    life = [r["cycles_to_fracture_p01"] for r in results]
    assert all(b > a for a, b in zip(p, p[1:]))
    assert all(b < a for a, b in zip(life[:4], life[1:4]))  # fatigue lives shorten with the torque
    assert life[4] == 1.0 and p[4] > 0.01  # twice the thesis's torque: 1 % of pairs break on the first load
    # root stress is linear in the load (same COF): 2.5 times the torque, 2.5 times the stress
    assert results[3]["root_stress_max"][0] == pytest.approx(2.5 * results[0]["root_stress_max"][0], rel=1e-9)


def test_result_keys_registered_and_consistent(params):
    result = tooth_life(synthetic_cycle(params), params)
    for key in TOOTH_LIFE_KEYS:
        assert known(key), key
        assert key in result
    p_pinion, p_gear = result["fracture_probability_pinion_tooth"], result["fracture_probability_gear_tooth"]
    # the pair's probability from its teeth's: 1 - (1 - p1)^z1 (1 - p2)^z2
    expected = 1 - (1 - p_pinion) ** params["teeth_pinion"] * (1 - p_gear) ** params["teeth_gear"]
    assert result["fracture_probability"] == pytest.approx(expected, rel=1e-9)
    assert result["root_stress_max"][0] > result["root_stress_max"][1] > 0  # the small pinion is stressed more
    assert result["contact_temperature_max"] == pytest.approx(
        params["ambient_temperature"] + result["bulk_temperature_rise"] + result["flash_temperature_max"], rel=1e-12)


def test_humidity_shortens_the_fatigue_life_not_the_first_load(params):
    light = params.updated({"drive_torque": 0.6e-7})  # long lives: none clipped at the first cycle
    dry = light.updated({"environment": "air", "relative_humidity": 0.1})
    wet = light.updated({"environment": "air", "relative_humidity": 0.9})
    cycle = synthetic_cycle(light)
    a, b = tooth_life(cycle, dry), tooth_life(cycle, wet)
    assert a["fracture_probability"] == b["fracture_probability"]
    # k_RH decades per unit RH: 0.8 RH apart
    ratio = a["cycles_to_fracture_p01"] / b["cycles_to_fracture_p01"]
    assert ratio == pytest.approx(10 ** (params["fatigue_humidity_sensitivity"] * 0.8), rel=1e-9)


def test_flash_temperature_scales_with_friction_and_speed(params):
    base = tooth_life(synthetic_cycle(params, cof=0.2), params)["flash_temperature_max"]
    double = tooth_life(synthetic_cycle(params, cof=0.4), params)["flash_temperature_max"]
    assert double == pytest.approx(2 * base, rel=1e-9)
    fast = params.updated({"pinion_speed": 1e5})
    assert tooth_life(synthetic_cycle(fast, cof=0.2), fast)["flash_temperature_max"] > 10 * base


def test_coating_degradation_temperature_warns(params):
    cycle = synthetic_cycle(params)
    hot = params.updated({"ambient_temperature": 480.0})  # above OTS's 473 K, below DDMS's 673 K
    ots = tooth_life(cycle, hot, coating=get_coating("OTS"))
    ddms = tooth_life(cycle, hot, coating=get_coating("DDMS"))
    assert any("degradation temperature of OTS" in w for w in ots["warnings"])
    assert not any("degradation" in w for w in ddms["warnings"])


def test_every_coating_has_a_published_degradation_temperature():
    assert {"OTS", "FDTS", "DDMS", "W"} <= set(available_coatings())
    for name in available_coatings():
        coating = get_coating(name)
        assert 300.0 < coating.degradation_temperature < 1687.0
        assert re.search(r"\b(19|20)\d\d\b", coating.sources["degradation_temperature"])  # a dated publication


def test_coating_without_degradation_temperature_is_refused(monkeypatch):
    from memstribo.physics import coating as module

    text = module._coating_files()["OTS"]
    stripped = text[:text.index("[properties.degradation_temperature]")]
    monkeypatch.setattr(module, "_coating_files", lambda: {"OTS": stripped})
    with pytest.raises(InputError, match="degradation temperature"):
        module.get_coating("OTS")


def test_missing_dataset_variable_is_a_clear_error(params):
    cycle = synthetic_cycle(params)
    del cycle["hertz_half_width"]
    with pytest.raises(InputError, match="hertz_half_width"):
        tooth_life(cycle, params)


@pytest.mark.parametrize("name", ["DDMS", "W"])
def test_new_coatings_run_through_the_coating_command(cli, name):
    """``memstribo coating --coating DDMS --wear 0 --json`` (issue #30), on a short cycle; the set is listed too."""
    out = cli.json("coating", "--coating", name, "--wear", "0", "--steps", "5")
    assert out["coating"] == name and out["wear"] == 0.0 and out["cof_mean"] > 0
    listed = cli.json("parameters", "--coating", name)
    assert listed["degradation_temperature"] == pytest.approx(673.15)


def test_probability_within_n_cycles_starts_at_the_first_load_and_reaches_one_percent_at_the_life(params):
    light = params.updated({"drive_torque": 0.6e-7})
    result = tooth_life(synthetic_cycle(light), light)
    assert fracture_probability_within(result, 1.0) == pytest.approx(result["fracture_probability"], rel=1e-12)
    assert fracture_probability_within(result, result["cycles_to_fracture_p01"]) == pytest.approx(0.01, rel=1e-9)
    curve = fracture_probability_within(result, np.logspace(0, 20, 21))
    assert np.all(np.diff(curve) >= 0) and curve[-1] > 0.01


def test_the_meshing_cycle_reports_its_tooth_life(cli, params):
    """`memstribo mesh --json` carries the tooth-life keys of the same cycle's tooth_life (MODEL §10)."""
    from memstribo.simulations.mesh import simulate_mesh

    result = cli.json("mesh", "--steps", "31", "--no-step-check")
    for key in ("root_stress_max", "fracture_probability", "cycles_to_fracture_p01", "flash_temperature_max",
                "bulk_temperature_rise"):
        assert key in result
    assert len(result["root_stress_max"]) == 2 and min(result["root_stress_max"]) > 0
    direct = tooth_life(simulate_mesh(params, steps=31), params)
    assert result["fracture_probability"] == pytest.approx(direct["fracture_probability"], rel=1e-9)
    assert result["root_stress_max"] == pytest.approx(direct["root_stress_max"], rel=1e-9)


def test_the_torque_sweep_shows_fracture_rising_with_torque(cli):
    """A torque sweep gives the window between 'sticks' (low torque) and 'breaks' (high torque)."""
    points = cli.json("sweep", "torque", "--values", "5e-8,1.5e-7", "--steps", "31")["points"]
    low, high = points
    assert high["fracture_probability"] > 10 * low["fracture_probability"] > 0
    assert high["root_stress_max"][0] > low["root_stress_max"][0]
