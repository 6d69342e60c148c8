"""Water bridges in the gaps of the rough rows and the adsorbed water films (issue #28 item 4, docs/humidity.md)."""

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.physics.capillary import (WATER, adsorbed_water_thickness, bridging_height, condensation_height,
                                         kelvin_radius, meniscus_work_of_separation, water_monolayer_thickness)

AVOGADRO = 6.02214076e23  # 1/mol, exact (SI 2019)


def test_water_monolayer_is_the_cube_root_of_the_volume_per_molecule():
    expected = (WATER["molar_volume"] / AVOGADRO) ** (1 / 3)
    assert water_monolayer_thickness() == pytest.approx(expected, rel=1e-12)
    assert 0.30e-9 < water_monolayer_thickness() < 0.32e-9


@pytest.mark.parametrize("rh, layers", [
    (0.3, 3.0),   # Asay and Kim 2005: the ice-like film grows to about three layers by RH 0.3
    (0.75, 4.5),  # Verdaguer et al. 2007: a uniform film 4-5 layers thick up to RH 0.75
    (0.9, 6.5),   # Verdaguer et al. 2007: 6-7 monolayers at about RH 0.9
])
def test_adsorbed_water_film_follows_the_published_isotherm_on_silicon_oxide(rh, layers):
    assert adsorbed_water_thickness(rh) == pytest.approx(layers * water_monolayer_thickness(), rel=1e-12)


def test_adsorbed_water_film_grows_with_humidity_and_refuses_bad_input():
    rh = np.array([0.0, 0.05, 0.2, 0.5, 0.8, 0.95])
    t = adsorbed_water_thickness(rh)
    assert t[0] == 0.0 and np.all(np.diff(t) > 0)
    for bad in (-0.1, 1.0, float("nan")):
        with pytest.raises(InputError, match="relative_humidity"):
            adsorbed_water_thickness(bad)


def test_a_water_bridge_spans_h_c_plus_the_films_and_works_gamma_cos_theta_at_most():
    theta = math.radians(30)
    gamma = WATER["surface_tension"]
    r_k = kelvin_radius(0.5)
    films = 2 * adsorbed_water_thickness(0.5)
    h = bridging_height(r_k, films / 2, films / 2, theta)
    assert h == pytest.approx(condensation_height(r_k, theta) + films, rel=1e-12)
    gaps = np.array([0.0, 0.5 * films, films, 0.5 * (films + h), h, 2 * h])
    work = meniscus_work_of_separation(gaps, r_k, h, films, gamma)
    # below the films: gamma (cos theta1 + cos theta2), the grand-potential difference of a filled slit
    assert work[:3] == pytest.approx(2 * gamma * math.cos(theta), rel=1e-9)
    assert work[3] == pytest.approx(gamma / r_k * 0.5 * (h - films), rel=1e-12)
    assert work[4] == 0.0 and work[5] == 0.0
    # a hydrophobic pair (OTS, 112 deg, on both flanks) forms no bridge, whatever the films
    assert bridging_height(r_k, films / 2, films / 2, math.radians(112)) == 0.0
    assert np.all(meniscus_work_of_separation(gaps, r_k, 0.0, 0.0) == 0.0)
    assert np.all(meniscus_work_of_separation(gaps, 0.0, h, films) == 0.0)  # dry


def test_bare_hydrophilic_bridges_are_bounded_by_their_laplace_pressure_in_the_sweep(cli):
    """Issue #36 (MODEL 7g): the water bridges' pull-off is the Laplace pressure over the bridged area plus the
    contact lines, never the elastic crack law's hundreds of MPa: none at RH 0.1 (r_K 0.23 nm, below a water
    molecule: an adsorbed film), then it falls as gamma / r_K falls faster than the bridged area grows (below the
    issue's bounds 174 and 37 uN at RH 0.5 and 0.9). F_adh holds the bridges' part."""
    out = cli.json("sweep", "humidity", "--values", "0.1,0.5,0.9", "--steps", "41")
    pull = [p["capillary_pull_off_mean"] for p in out["points"]]
    assert pull[0] == 0.0 and pull[1] > pull[2] > 0
    # within the strength bounds (computed with the whole adsorbed film; the bridges take its liquid part)
    assert 0.5 * 174e-6 < pull[1] <= 174e-6 * 1.02 and 0.5 * 37e-6 < pull[2] <= 37e-6 * 1.02
    for point in out["points"][1:]:  # the bridges add at most their own pull-off to F_adh, and F_adh holds it
        part = point["capillary_adhesion_force_mean"]
        assert 0 < part <= point["capillary_pull_off_mean"] and part < point["adhesion_force_mean"]


def test_the_bridges_add_to_f_adh_only_their_work_beyond_the_vdw_work():
    """One work of adhesion per element where F_adh's vdW part acts: the larger of w12 and the bridge's
    (docs/humidity.md).
    With the thesis's block pull-off (contact_adhesion 'none') and its Hamaker constant (1.1e-18 J; the default's
    Lifshitz 2e-19 J gives 0.081 J/m^2) the vdW acts on every touching element with
    w12 = 0.445 J/m^2 > 2 gamma cos 30 deg = 0.125 J/m^2: the bridges there add nothing, so their part of F_adh
    falls short of their own pull-off; with a w12 far below the bridge's it is the bridges' whole pull-off."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh

    params = get_parameter_values().updated({"environment": "air", "relative_humidity": 0.5,
                                             "contact_adhesion": "none",
                                             "hamaker_constant": 1.1e-18})  # the thesis's A: w12 = 0.445 J/m^2
    strong = simulate_mesh(params, steps=21)
    pull, part = np.asarray(strong["capillary_pull_off"]), np.asarray(strong["capillary_adhesion_force"])
    assert np.all(part <= pull * (1 + 1e-12)) and part.sum() < 0.9 * pull.sum()
    weak = simulate_mesh(params.updated({"work_of_adhesion": 1e-6}), steps=21)
    assert np.asarray(weak["capillary_adhesion_force"]) == pytest.approx(np.asarray(weak["capillary_pull_off"]),
                                                                         rel=1e-3)
    # with the Maugis-Dugdale zone (the default) the vdW part of F_adh in humid air is the zone's tension as in dry
    # air: outside the contact and the vdW share of the contact's tensile edges (not the zone outside it alone)
    air = get_parameter_values().updated({"environment": "air"})
    dry = simulate_mesh(air.updated({"relative_humidity": 0.0}), steps=21)
    humid = simulate_mesh(air.updated({"relative_humidity": 0.5}), steps=21)
    vdw_part = float((humid["adhesion_force"] - humid["capillary_adhesion_force"]).mean())
    # (the menisci's traction in the same solve moves the contact a little: 5.3 % at 21 steps)
    assert vdw_part == pytest.approx(float(dry["adhesion_force"].mean()), rel=0.07)
    # in vacuum the dataset has neither (and F_adh is the vdW part alone)
    vacuum = simulate_mesh(get_parameter_values(), steps=11)
    assert "capillary_adhesion_force" not in vacuum and "capillary_pull_off" not in vacuum


def test_teeth_coated_on_both_flanks_stay_flat_in_humidity(cli):
    """Issue #28: an intact hydrophobic coating on both flanks (OTS, 112 deg: the pinion given the coating's angle)
    forms no water bridge: no pull-off, and F_adh is the dry value at every RH (band: 0, to rounding)."""
    ots = str(math.radians(112))
    out = cli.json("sweep", "humidity", "--values", "0,0.5,0.9", "--coating", "OTS", "--wear", "0",
                   "--set", f"water_contact_angle={ots}", "--steps", "41")
    dry, *wet = out["points"]
    for point in wet:
        assert point["capillary_pull_off_mean"] == 0.0
        assert point["adhesion_force_mean"] == pytest.approx(dry["adhesion_force_mean"], rel=1e-9)
    # the thesis's convention (gear coated, pinion bare: cos 30 + cos 112 > 0) keeps weak bridges, below bare teeth
    half = cli.json("sweep", "humidity", "--values", "0.5", "--coating", "OTS", "--wear", "0", "--steps", "41")
    bare = cli.json("sweep", "humidity", "--values", "0.5", "--steps", "41")
    assert 0 < half["points"][0]["capillary_pull_off_mean"] < bare["points"][0]["capillary_pull_off_mean"]


def test_the_microbeam_model_is_the_rough_capillary_relations():
    """The laboratory's rigid microbeam (:func:`memstribo.laboratory.predict.beam_work_of_separation`) is
    :mod:`memstribo.physics.rough_capillary` on its gap field: the bridges' part is the mean of the bridges' work with
    the oxide's liquid-like films; without films it is the closed form of :func:`meniscus_work_of_separation`."""
    from memstribo.laboratory.predict import beam_work_of_separation
    from memstribo.parameters import get_parameter_values
    from memstribo.physics.rough_capillary import capillary_adhesion_energy

    params = get_parameter_values()
    gap = np.random.default_rng(3).exponential(2e-9, 400)
    theta = params["water_contact_angle"]
    total, vdw, cap = beam_work_of_separation(gap, params, 0.7)
    assert cap == pytest.approx(np.mean(capillary_adhesion_energy(gap, 0.7, theta)), rel=1e-12)
    assert max(vdw, cap) <= total <= vdw + cap
    r_k = kelvin_radius(0.7, params["ambient_temperature"])
    closed = np.mean(meniscus_work_of_separation(gap, r_k, condensation_height(r_k, theta)))
    assert np.mean(capillary_adhesion_energy(gap, 0.7, theta, films=0.0)) == pytest.approx(closed, rel=1e-12)
