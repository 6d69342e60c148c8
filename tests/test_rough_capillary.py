"""Rough-surface capillary adhesion Gamma(RH) of microbeams (issue #36 item 2; memstribo.physics.rough_capillary)."""

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.laboratory.microbeam_humidity import MICROBEAM_HUMIDITY
from memstribo.physics.capillary import WATER, kelvin_radius, liquid_water_thickness
from memstribo.physics.rough_capillary import (capillary_adhesion_energy, capillary_threshold_humidity,
                                               rigid_interface_gaps, rough_adhesion_energy, vdw_adhesion_energy)


@pytest.fixture(scope="module")
def beam():
    """The laboratory's microbeam: two Gaussian-correlated maps (Rq 3 nm, 100 nm, the DelRio row's assumption)."""
    from memstribo.laboratory.predict import _beam_gap
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values("silicon_oxide_air")
    return _beam_gap(3e-9, 100e-9, 20260528), params


def _gamma(beam, rh):
    from memstribo.laboratory.predict import beam_work_of_separation

    return beam_work_of_separation(beam[0], beam[1], rh)[0]


def test_rough_microbeam_gamma_has_its_plateau_and_its_rise(beam):
    """Done when (issue #36): change < 2x from RH 0.05 to 0.3, rise > 10x from 0.3 to 0.95; below the published
    upper limit (DelRio et al. 2007: 144 mJ/m^2) and rising towards 2 gamma cos theta near saturation."""
    g05, g30, g95, g99 = (_gamma(beam, rh) for rh in (0.05, 0.3, 0.95, 0.99))
    assert g30 / g05 < 2.0 and g95 / g30 > 10.0
    upper = next(r for r in MICROBEAM_HUMIDITY if r["kind"] == "upper limit")
    assert g95 < g99 <= upper["adhesion_energy"]
    assert g99 > 0.5 * 2 * WATER["surface_tension"] * math.cos(beam[1]["water_contact_angle"])
    # the published plateau and rise, in the model's words: flat below RH 0.3, rising over 0.3-0.95
    for record in MICROBEAM_HUMIDITY:
        low, high = record["relative_humidity"]
        if record["kind"] == "plateau":
            assert _gamma(beam, high) < 2 * _gamma(beam, max(low, 0.05)), record["source"]
        elif record["kind"] == "rise":
            values = [_gamma(beam, rh) for rh in np.linspace(low, high, 5)]
            assert np.all(np.diff(values) > 0) and values[-1] > 10 * values[0], record["source"]


def test_the_threshold_lies_where_the_bridges_reach_the_asperities_next_to_the_contact(beam):
    gaps, params = beam
    rh = capillary_threshold_humidity(gaps, params["hamaker_constant"], params["cutoff_distance"],
                                      params["water_contact_angle"])
    assert 0.3 < rh < 0.95
    assert _gamma(beam, rh) == pytest.approx(2 * _gamma(beam, 0.0), rel=1e-3)
    hydrophobic = capillary_threshold_humidity(gaps, params["hamaker_constant"], params["cutoff_distance"],
                                               math.radians(112))  # OTS: no bridge, no threshold
    assert hydrophobic is None
    with pytest.raises(InputError, match="factor"):
        capillary_threshold_humidity(gaps, 1e-19, 2e-10, 0.5, factor=1.0)


def test_the_relations_on_simple_gaps():
    a, d0, theta = 6.3e-20, 0.165e-9, math.radians(30)
    w = a / (12 * math.pi * d0**2)
    assert vdw_adhesion_energy([0.0], a, d0)[0] == pytest.approx(w, rel=1e-12)
    assert vdw_adhesion_energy([d0], a, d0)[0] == pytest.approx(w / 4, rel=1e-12)  # (D0 / 2 D0)^2
    gaps = rigid_interface_gaps([1e-9, 3e-9, 2e-9], [0.0, -1e-9, 0.0])
    assert np.allclose(gaps, [1e-9, 0.0, 0.0])
    # a filled slit (gap below the films) works 2 gamma cos theta; a gap beyond the bridging height nothing
    work = capillary_adhesion_energy([0.0, 1e-6], 0.9, theta)
    assert work[0] == pytest.approx(2 * WATER["surface_tension"] * math.cos(theta), rel=1e-9) and work[1] == 0.0
    assert np.all(capillary_adhesion_energy([0.0, 1e-10], 0.1, theta) == 0.0)  # r_K 0.23 nm: an adsorbed film
    assert kelvin_radius(0.1) < 0.311e-9
    # touching: one work per element, the larger
    assert rough_adhesion_energy([0.0], 0.9, a, d0, theta) == pytest.approx(
        max(w, 2 * WATER["surface_tension"] * math.cos(theta)), rel=1e-9)
    # the ice-like layers (RH <= 0.3) do not bridge; the liquid-like film grows above them
    assert liquid_water_thickness(0.3) == 0.0 and 0 < liquid_water_thickness(0.5) < liquid_water_thickness(0.9)
    for bad in ([], [-1e-9], [np.nan]):
        with pytest.raises(InputError, match="gaps"):
            vdw_adhesion_energy(bad, a, d0)
    with pytest.raises(InputError, match="relative_humidity"):
        capillary_adhesion_energy([0.0], 1.0, theta)


def test_meniscus_adhesion_pressure_is_the_laplace_bound_per_area():
    """(gamma / r_K) phi + gamma L / A on a map and on a line; never above gamma / r_K plus its contact lines."""
    from memstribo.physics.rough_capillary import meniscus_adhesion_pressure

    gamma, r_k, dx = 0.072, kelvin_radius(0.7), 10e-9
    line = np.array([0.0, 1e-9, 5e-9, 5e-9, 0.5e-9, 5e-9])  # wet runs [0, 1] and [4]: 4 ends over 6 dx
    assert meniscus_adhesion_pressure(line, dx, r_k, 2e-9, gamma) == pytest.approx(
        gamma / r_k * 3 / 6 + gamma * 4 / (6 * dx), rel=1e-12)
    square = np.full((4, 4), 5e-9)
    square[1:3, 1:3] = 0.0  # a 2 x 2 wet patch: 8 edges of dx around it
    assert meniscus_adhesion_pressure(square, dx, r_k, 2e-9, gamma) == pytest.approx(
        gamma / r_k * 4 / 16 + gamma * 8 * dx / (16 * dx * dx), rel=1e-12)
    assert meniscus_adhesion_pressure(square, dx, 0.0, 2e-9) == 0.0  # dry or an adsorbed film
    assert meniscus_adhesion_pressure(np.zeros((3, 3)), dx, r_k, 2e-9, gamma) == pytest.approx(gamma / r_k)


def test_the_flat_friction_case_answers_humidity():
    """Issue #36: the laboratory's flat (and sidewall) case adds the menisci's attraction to its load: RH 0 and 0.9
    give different COFs on the bare oxide; coated (OTS on both surfaces, 112 deg) rows form no meniscus; pentanol
    vapour runs the flat contact."""
    import copy

    from memstribo.laboratory import data, predict

    rows = {r.id: r for r in data.load_measurements()}

    def at(row_id, rh, samples=None):
        row = copy.deepcopy(rows[row_id])
        row.conditions["relative_humidity"] = rh
        return predict.row_values(row, samples, realisations=1)[0][0, 0]

    assert at("srinivasan1998_static_oxide", 0.9) < 0.99 * at("srinivasan1998_static_oxide", 0.0)
    assert at("srinivasan1998_kinetic_ots", 0.9) == at("srinivasan1998_kinetic_ots", 0.0)
    pentanol = at("srinivasan1998_static_oxide", 0.9, [{"vapour": "pentanol"}])
    assert np.isfinite(pentanol) and pentanol != at("srinivasan1998_static_oxide", 0.9)
