"""Vapours and surface terminations as data (issue #36 items 4-5; memstribo.physics.vapours)."""

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.parameters import get_parameter_values
from memstribo.physics import capillary
from memstribo.physics.vapours import (VAPOURS, adsorbed_film_thickness, liquid_film_thickness,
                                       vapour_contact_angle, vapour_properties, vapour_state, vapour_surface_tension)


def test_the_default_is_todays_water_on_the_oxide():
    params = get_parameter_values().updated({"environment": "air", "relative_humidity": 0.5})
    assert params["vapour"] == "water" and params["surface_termination"] == "oxide"
    assert params["vapour_pressure_ratio"] is None
    state = vapour_state(params)
    assert state["ratio"] == 0.5 and state["surface_tension"] == 0.072
    assert state["kelvin"] == capillary.kelvin_radius(0.5)
    assert state["contact_angle"] == params["water_contact_angle"]
    assert state["film"] == capillary.adsorbed_water_thickness(0.5)


def test_pentanol_is_data_with_its_sources():
    pentanol = vapour_properties("pentanol")
    assert vapour_surface_tension("pentanol") == pytest.approx(0.02536, rel=1e-3)  # Jasper 1972 at 25 degC
    assert pentanol["molar_volume"] == pytest.approx(108.5e-6, rel=1e-3)  # 88.148 g/mol / 0.81219 g/cm^3
    assert all(key in pentanol["source"] for key in ("surface_tension", "molar_volume", "contact_angle", "isotherm"))
    # a monolayer at p/p_sat 0.5 (Tribol. Lett. 2014): (V_m / N_A)^(1/3) = 0.565 nm; its first layer is bound
    layer = capillary.water_monolayer_thickness(pentanol["molar_volume"])
    assert adsorbed_film_thickness("pentanol", "oxide", 0.5) == pytest.approx(layer, rel=1e-12)
    assert liquid_film_thickness("pentanol", "oxide", 0.5) == 0.0
    params = get_parameter_values().updated({"environment": "air", "vapour": "pentanol",
                                             "vapour_pressure_ratio": 0.5})
    state = vapour_state(params)
    assert state["kelvin"] == pytest.approx(0.02536 * 108.5e-6 / (capillary.GAS_CONSTANT * 298.15) / math.log(2),
                                            rel=2e-3)


def test_hydrogen_termination_is_hydrophobic_to_water_and_carries_less_film():
    """Si-H: 111 deg (freshly etched), less than a monolayer at RH 0.9 (Chen et al. 2018); the oxide: 30 deg and
    6.5 layers at RH 0.9."""
    assert math.degrees(vapour_contact_angle("water", "hydrogen")) == pytest.approx(111.0)
    assert capillary.condensation_height(1e-9, vapour_contact_angle("water", "hydrogen")) == 0.0
    assert adsorbed_film_thickness("water", "hydrogen", 0.9) <= capillary.water_monolayer_thickness() * (1 + 1e-12)
    assert adsorbed_film_thickness("water", "oxide", 0.9) > 6 * adsorbed_film_thickness("water", "hydrogen", 0.9)


def test_oxide_adheres_more_than_hydrogen_in_humid_air_as_measured():
    """Hydrophilic (oxide) surfaces adhere more as RH rises, hydrophobic ones do not (de Boer 1998 and the group's
    coated beams; water adsorption: Chen et al. 2018): the gear's F_adh and the microbeam's Gamma at RH 0.9."""
    from memstribo.laboratory.predict import _beam_gap, beam_work_of_separation
    from memstribo.simulations.mesh import simulate_mesh, summarize

    air = get_parameter_values().updated({"environment": "air", "relative_humidity": 0.9})
    oxide = summarize(simulate_mesh(air, steps=21))
    hydrogen = summarize(simulate_mesh(air.updated({"surface_termination": "hydrogen"}), steps=21))
    dry = summarize(simulate_mesh(air.updated({"relative_humidity": 0.0}), steps=21))
    assert oxide["adhesion_force_mean"] > hydrogen["adhesion_force_mean"]
    assert hydrogen["adhesion_force_mean"] == pytest.approx(dry["adhesion_force_mean"], rel=1e-12)
    beam = get_parameter_values("silicon_oxide_air")
    gaps = _beam_gap(3e-9, 100e-9, 1)
    wet_oxide = beam_work_of_separation(gaps, beam, 0.9)[0]
    wet_hydrogen = beam_work_of_separation(gaps, beam.updated({"surface_termination": "hydrogen"}), 0.9)[0]
    assert wet_oxide > 10 * wet_hydrogen and wet_hydrogen == beam_work_of_separation(gaps, beam, 0.0)[0]


def test_pentanol_runs_the_gear(cli):
    out = cli.json("mesh", "--set", "environment=air", "--set", "vapour=pentanol", "--set",
                   "vapour_pressure_ratio=0.5", "--steps", "11")
    assert out["capillary_pull_off_mean"] > 0 and out["cof_capillary"] > 0
    water = cli.json("mesh", "--set", "environment=air", "--set", "relative_humidity=0.5", "--steps", "11")
    assert out["capillary_pull_off_mean"] != water["capillary_pull_off_mean"]


def test_bad_vapour_input_is_refused_with_what_is_allowed():
    params = get_parameter_values()
    with pytest.raises(InputError, match="'water', 'pentanol'"):
        params.updated({"vapour": "ethanol"})
    with pytest.raises(InputError, match="'oxide', 'hydrogen'"):
        params.updated({"surface_termination": "fluorine"})
    for bad in (-0.1, 1.0):
        with pytest.raises(InputError, match="vapour_pressure_ratio"):
            params.updated({"vapour_pressure_ratio": bad})
        with pytest.raises(InputError, match="relative_humidity"):
            params.updated({"relative_humidity": bad})
    with pytest.raises(InputError, match="water_contact_angle"):
        params.updated({"water_contact_angle": 4.0})  # above pi: 229 deg
    with pytest.raises(InputError, match=r"\[0, pi\]"):
        vapour_contact_angle("water", "oxide", -0.1)
    with pytest.raises(InputError, match="unknown vapour"):
        vapour_properties("ethanol")
    with pytest.raises(InputError, match="surface_termination"):
        adsorbed_film_thickness("water", "fluorine", 0.5)
    with pytest.raises(InputError, match=r"\[0, 1\)"):
        adsorbed_film_thickness("pentanol", "oxide", 1.0)
    from memstribo.physics.coating import get_coating
    from memstribo.simulations.mesh import simulate_mesh

    with pytest.raises(InputError, match="coated gear in pentanol"):
        simulate_mesh(params.updated({"environment": "air", "vapour": "pentanol", "vapour_pressure_ratio": 0.5}),
                      steps=5, coating=get_coating("OTS"), wear=0.0)
    assert set(VAPOURS) == {"water", "pentanol"}
    assert np.all(np.diff(adsorbed_film_thickness("water", "hydrogen", np.array([0.0, 0.3, 0.6, 0.9]))) > 0)


def test_a_vapour_in_vacuum_is_refused(cli):
    code, out, err = cli("mesh", "--set", "vapour=pentanol", "--steps", "5")
    assert code == 2 and "only in air" in err and "vapour" in err
