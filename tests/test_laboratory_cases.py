"""The common MEMS test structures as cases (issue 37 item 2): each against its smooth closed form, the flat pad's
load dependence through its real contact area, the physical bounds, and the dispatch by geometry."""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import minimize_scalar

from memstribo.errors import InputError
from memstribo.laboratory.cases import cantilever, case_values, check_conditions, flat_pad, nanocontact, pull_off, sphere
from memstribo.laboratory.cases._interface import (adhesive_stress, contact_modulus, friction_stress, shear_strengths,
                                                   work_of_adhesion)
from memstribo.laboratory.data import Measurement
from memstribo.parameters import get_parameter_values
from memstribo.physics import capillary
from memstribo.physics.closed_form import hertz_sphere_radius


@pytest.fixture(scope="module")
def vacuum():
    return get_parameter_values("silicon_thesis")


@pytest.fixture(scope="module")
def air():
    return get_parameter_values("silicon_oxide_air")


def row(**fields):
    base = {"geometry": "flat_pad", "environment": "vacuum", "coating": "none", "contact_pressure": 1e5}
    base.update(fields)
    quantity = base.pop("quantity", "kinetic_cof")
    return Measurement(id="r", quantity=quantity, value=float(base.pop("value", 0.5)), unit="1",
                       scatter={"kind": "sd", "value": 0.1}, calibration=False, citation="thesis", conditions=base)


# --- flat pad: the COF follows the real contact area ----------------------------------------------------------------

def test_flat_pad_cof_changes_with_pressure_where_the_real_area_does(vacuum):
    """Without adhesion mu = (tau A_r + off-contact vdW) / W: between 0.1 and 4 GPa A_r / W falls by a quarter (the
    contact saturates at the hardness and spreads), and the COF falls with it, in the same ratio within 3 %."""
    low = flat_pad.flat_pad_friction(vacuum, 1e8, 5e-9, 80e-9, 3, adhesion=False)
    high = flat_pad.flat_pad_friction(vacuum, 4e9, 5e-9, 80e-9, 3, adhesion=False)
    area_ratio = (high["real_area_fraction"] / 4e9) / (low["real_area_fraction"] / 1e8)
    assert low["resolved"] and high["resolved"]
    assert area_ratio < 0.8
    assert high["kinetic_cof"] / low["kinetic_cof"] == pytest.approx(area_ratio, rel=0.03)


def test_flat_pad_with_adhesion_depends_on_the_nominal_pressure(air):
    """With its adhesion (vdW + menisci at RH 0.4) the pad's COF differs between 1.7 kPa and 1.7 MPa (adhesion
    dominates the load at the lower pressure) and stays finite and positive."""
    cofs = [flat_pad.flat_pad_friction(air, p, 10.3e-9, 83e-9, 1, 0.4)["kinetic_cof"] for p in (1.7e3, 1.7e6)]
    assert all(0 < c < 10 for c in cofs)
    assert abs(cofs[0] / cofs[1] - 1) > 0.1


def test_flat_pad_refuses_a_pressure_above_the_hardness(vacuum):
    with pytest.raises(InputError, match="hardness"):
        flat_pad.flat_pad_friction(vacuum, 2 * vacuum["hardness"], 5e-9, 80e-9, 0)


# --- sphere: Hertz in the smooth limit ------------------------------------------------------------------------------

@pytest.mark.parametrize("radius, force", [(1e-6, 1e-3), (50e-9, 1e-7), (1e-3, 1.0)])
def test_smooth_sphere_contact_area_is_hertz(vacuum, radius, force):
    state = sphere.sphere_contact(vacuum, force, radius, adhesion=False)
    a = float(hertz_sphere_radius(force, radius, contact_modulus(vacuum)))
    assert state.plastic_fraction == 0.0
    assert state.real_area == pytest.approx(math.pi * a * a, rel=0.03)


def test_rough_sphere_touches_less_than_hertz_and_its_cof_is_finite(vacuum):
    smooth = sphere.sphere_contact(vacuum, 1e-4, 10e-6, adhesion=False)
    rough = sphere.sphere_contact(vacuum, 1e-4, 10e-6, 5e-9, 80e-9, 1, adhesion=False)
    assert rough.real_area < 0.8 * smooth.real_area
    out = sphere.sphere_friction(vacuum, 1e-4, 10e-6, 5e-9, 80e-9, 1)
    assert 0 < out["kinetic_cof"] <= out["static_cof"] * 1.0001


# --- cantilever: de Boer and Michalske's beam mechanics --------------------------------------------------------------

def test_beam_relation_is_the_energy_minimum_of_the_s_shaped_beam():
    """Gamma = 3 E t^3 h^2 / (2 s^4) checked against an independent energy minimisation: the strain energy of
    w = h (1 - 3 (x/s)^2 + 2 (x/s)^3) integrated numerically, minus Gamma b (L - s), minimised over s."""
    e, t, h, b, length, gamma = 164e9, 2.6e-6, 2.0e-6, 10e-6, 1500e-6, 0.02

    def strain_energy(s):
        curvature = lambda x: h * (-6 / s**2 + 12 * x / s**3)  # noqa: E731
        return 0.5 * e * b * t**3 / 12 * quad(lambda x: curvature(x) ** 2, 0, s)[0]

    found = minimize_scalar(lambda s: strain_energy(s) - gamma * b * (length - s), bounds=(50e-6, 1400e-6),
                            method="bounded", options={"xatol": 1e-12}).x
    assert cantilever.beam_crack_length(e, t, h, gamma) == pytest.approx(found, rel=1e-6)
    assert cantilever.beam_adhesion_energy(e, t, h, found) == pytest.approx(gamma, rel=1e-5)


def test_beam_relation_refuses_a_non_positive_length():
    with pytest.raises(InputError, match="crack_length"):
        cantilever.beam_adhesion_energy(160e9, 2e-6, 2e-6, 0.0)


def test_smooth_work_of_separation_is_w_plus_the_wetted_meniscus(air):
    total, vdw, cap = cantilever.work_of_separation(np.zeros((4, 4)), air, 0.5)
    assert vdw == pytest.approx(work_of_adhesion(air), rel=1e-3)
    # the Laplace pressure over the bridging height: 2 gamma cos(theta) + 2 gamma t / r_K with the liquid-like film t
    from memstribo.physics.capillary import kelvin_radius
    from memstribo.physics.vapours import liquid_film_thickness, vapour_surface_tension

    gamma = vapour_surface_tension("water", air["ambient_temperature"])
    film = liquid_film_thickness("water", air["surface_termination"], 0.5)
    r_k = kelvin_radius(0.5, air["ambient_temperature"], gamma)
    assert film > 0
    assert cap == pytest.approx(2 * gamma * math.cos(air["water_contact_angle"]) + 2 * gamma * film / r_k, rel=2e-3)
    rough = cantilever.work_of_separation(cantilever.beam_gap_field(3e-9, 80e-9, 0), air, 0.5)
    assert rough[0] < total


# --- pull-off: Maugis-Dugdale between DMT and JKR; the rigid integral ------------------------------------------------

def test_maugis_dugdale_sphere_reaches_dmt_and_jkr(vacuum):
    w, modulus, radius = work_of_adhesion(vacuum), contact_modulus(vacuum), 1e-6
    dmt, lam_small = pull_off.maugis_dugdale_sphere_pull_off(radius, modulus, w, 1e4)
    jkr, lam_large = pull_off.maugis_dugdale_sphere_pull_off(radius, modulus, w, 1e12)
    assert lam_small < 1e-4 and lam_large > 100
    assert dmt == pytest.approx(2 * math.pi * w * radius, rel=1e-3)
    assert jkr == pytest.approx(1.5 * math.pi * w * radius, rel=1e-3)


def test_rigid_smooth_probe_is_dmt_and_its_meniscus_is_fisher_israelachvili(vacuum, air):
    radius, grid = 1e-6, 256
    dx = 2 * math.sqrt(2 * radius * 20e-9) / grid
    x = (np.arange(grid) - grid / 2 + 0.5) * dx
    gap = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius)
    force, _ = pull_off.rigid_pull_off(gap, dx * dx, vacuum, None)
    assert force == pytest.approx(2 * math.pi * radius * work_of_adhesion(vacuum), rel=0.01)
    _, cap = pull_off.rigid_pull_off(gap, dx * dx, air, 0.4)
    # Fisher-Israelachvili 2 pi R gamma (cos t1 + cos t2) over the condensation height, widened by the liquid-like films
    # to the bridging height h: 2 pi R (gamma / r_K) h
    from memstribo.physics.vapours import liquid_film_thickness, vapour_surface_tension

    gamma = vapour_surface_tension("water", air["ambient_temperature"])
    r_k = capillary.kelvin_radius(0.4, air["ambient_temperature"], gamma)
    film = liquid_film_thickness("water", air["surface_termination"], 0.4)
    theta = air["water_contact_angle"]
    height = capillary.bridging_height(r_k, film, film, theta, theta)
    assert cap == pytest.approx(2 * math.pi * radius * gamma / r_k * height, rel=0.02)
    assert cap == pytest.approx(capillary.capillary_force_sphere(radius, theta, surface_tension=gamma)
                                * height / capillary.condensation_height(r_k, theta, theta), rel=0.02)


def test_smooth_plate_pulls_off_at_the_largest_stress_of_the_93_law(vacuum):
    force, _ = pull_off.plate_pull_off(vacuum, 1e-8)
    w, d0 = work_of_adhesion(vacuum), vacuum["cutoff_distance"]
    assert force == pytest.approx(16 * w / (9 * math.sqrt(3) * d0) * 1e-8, rel=1e-3)


# --- nanocontact: the bonds' shear stress ---------------------------------------------------------------------------

def test_smooth_nanocontact_shear_strength_is_the_bonds_stress(air):
    """Without vdW bonds (U_vdW = 0: none off the contact) the interfacial shear strength of a smooth tip is the
    chemical bonds' U_chem / D^3 exactly; with them it is larger, never smaller."""
    tau = shear_strengths(air)[0]
    assert tau == pytest.approx((air["bond_energy"] + air["vdw_bond_energy"]) / air["bond_length"] ** 3)
    bare = air.updated({"vdw_bond_energy": 0.0})
    chemical = air["bond_energy"] / air["bond_length"] ** 3
    assert nanocontact.interfacial_shear_strength(bare, 10e-9, 50e-9)["shear_strength"] == pytest.approx(chemical,
                                                                                                        rel=1e-9)
    assert nanocontact.interfacial_shear_strength(air, 10e-9, 50e-9)["shear_strength"] >= tau


# --- physical bounds ------------------------------------------------------------------------------------------------

def test_no_stress_above_its_bound(vacuum, air):
    gap = np.concatenate([[0.0], np.geomspace(1e-13, 1e-7, 400)])
    contact = gap == 0
    assert friction_stress(gap, contact, vacuum).max() <= vacuum["ideal_shear_strength"]
    assert shear_strengths(vacuum)[2]  # U_chem / D^3 of Si-Si (42 GPa) is capped at the ideal shear strength
    w, d0 = work_of_adhesion(air), air["cutoff_distance"]
    laplace = capillary.laplace_pressure(capillary.kelvin_radius(0.9, air["ambient_temperature"]))
    assert adhesive_stress(gap, air, 0.9).max() <= 16 * w / (9 * math.sqrt(3) * d0) + laplace


# --- dispatch by geometry -------------------------------------------------------------------------------------------

def test_every_geometry_dispatches_to_its_case():
    cases = [row(), row(geometry="sidewall", contact_pressure=84e6, quantity="static_cof"),
             row(geometry="sphere_on_flat", sphere_radius=1e-6, normal_force=1e-6, contact_pressure="not stated"),
             row(geometry="cantilever_array", quantity="crack_length", beam_thickness=2.6e-6, beam_gap=2e-6,
                 value=5e-4),
             row(geometry="pull_off", quantity="pull_off_force", sphere_radius=1e-6, value=1e-6),
             row(geometry="nanocontact", quantity="interfacial_shear_strength", sphere_radius=50e-9,
                 normal_force=5e-9, value=1e9)]
    for r in cases:
        values, text = case_values(r, [{}], 1)
        assert values is not None, text
        assert np.all(np.isfinite(values)) and np.all(values > 0), text
    assert case_values(row(geometry="microbeam", quantity="adhesion_energy"), [{}], 1) is NotImplemented


def test_nitride_and_ddms_rows_are_predicted_and_differ_from_polysilicon():
    poly = case_values(row(geometry="sphere_on_flat", sphere_radius=1e-6, normal_force=1e-6), [{}], 1)[0]
    nitride = case_values(row(geometry="sphere_on_flat", sphere_radius=1e-6, normal_force=1e-6,
                              material="silicon_nitride"), [{}], 1)[0]
    ddms = case_values(row(geometry="sphere_on_flat", sphere_radius=1e-6, normal_force=1e-6, coating="DDMS"),
                       [{}], 1)[0]
    assert nitride[0, 0] != pytest.approx(poly[0, 0], rel=0.05)
    assert 0 < ddms[0, 0] < poly[0, 0]


def test_conditions_outside_the_range_are_refused_by_field():
    with pytest.raises(InputError, match="relative_humidity"):
        check_conditions(row(environment="air", relative_humidity=1.5))
    with pytest.raises(InputError, match="sphere_radius"):
        check_conditions(row(geometry="sphere_on_flat", normal_force=1e-6))
    with pytest.raises(InputError, match="material"):
        check_conditions(row(material="diamond"))
    with pytest.raises(InputError, match="contact_pressure"):
        check_conditions(row(contact_pressure=2e10), hardness=12e9)
    with pytest.raises(InputError, match="field temperature = 1000 K"):
        check_conditions(row(temperature=1000.0))


def test_conditions_the_cases_do_not_model_are_not_predicted_with_the_reason():
    # issue 36's vapours reach the cases: pentanol in air is predicted, a vapour in vacuum is not (with the reason)
    assert "vacuum" in case_values(row(vapour="pentanol", environment="vacuum"), [{}], 1)[1]
    assert case_values(row(vapour="pentanol", environment="vacuum"), [{}], 1)[0] is None


def test_vapour_and_termination_reach_the_flat_pad():
    humid = {"environment": "air", "relative_humidity": 0.9}
    water = case_values(row(**humid), [{}], 1)[0][0, 0]
    pentanol = case_values(row(vapour="pentanol", **humid), [{}], 1)[0][0, 0]
    hydrogen = case_values(row(surface_termination="hydrogen", **humid), [{}], 1)[0][0, 0]
    assert np.isfinite(pentanol) and pentanol != water
    assert hydrogen != water  # hydrophobic Si-H: no water meniscus (its 111 deg contact angle)


def test_cantilever_crack_length_is_the_beam_relation_of_the_predicted_energy(vacuum):
    common = {"geometry": "cantilever_array", "roughness": {"rq": 2e-9, "correlation_length": 80e-9}}
    energy = case_values(row(quantity="adhesion_energy", value=0.02, **common), [{}], 1)[0][0, 0]
    crack = case_values(row(quantity="crack_length", value=5e-4, beam_thickness=2.6e-6, beam_gap=2e-6, **common),
                        [{}], 1)[0][0, 0]
    assert crack == pytest.approx(cantilever.beam_crack_length(vacuum["youngs_modulus"], 2.6e-6, 2e-6, energy))
    assert 0 < energy < work_of_adhesion(vacuum)


def test_the_rough_contact_never_carries_more_than_the_hardness(vacuum):
    """Force balance against the physical bound: the contact carries W + F_adh over its real area, at most the
    hardness on average (each element is capped there), up to nominal pressures at the hardness itself."""
    from memstribo.laboratory.cases._interface import adhesive_contact

    h = np.random.default_rng(3).normal(0.0, 3e-9, (64, 64))
    dx = 10e-9
    carried = []
    for nominal in (1e8, 2e9, 8e9):
        state = adhesive_contact(h, dx, vacuum, nominal * (64 * dx) ** 2, None, periodic=True)
        if state.resolved:
            carried.append((state.load + state.adhesion) / state.real_area)
    assert carried and max(carried) <= vacuum["hardness"] * (1 + 1e-6)
    assert max(carried) > 0.5 * vacuum["hardness"]  # the bound is reached, so the test can fail


# --- exact reuse across constant samples (issue 40: validate-lab <= 2 min) ------------------------------------------

def test_samples_reuse_a_case_only_where_it_read_the_same_values(monkeypatch):
    """A pull-off reads no bond energy: one evaluation per realisation serves every sample; a friction case reads
    them: every sample is its own. Either way the values equal a fresh evaluation of every sample, bit for bit."""
    import memstribo.laboratory.cases as cases
    from memstribo.laboratory.materials import row_parameters

    samples = [{"bond_energy": u, "vdw_bond_energy": u / 50} for u in (2e-19, 4e-19, 8e-19)]
    calls = []
    original = cases._one
    monkeypatch.setattr(cases, "_one", lambda *a: calls.append(a[3]) or original(*a))
    pull = row(geometry="pull_off", quantity="pull_off_force", sphere_radius=1e-6, value=1e-6)
    friction = row(geometry="sphere_on_flat", sphere_radius=1e-6, normal_force=1e-6)
    for r, evaluations in ((pull, 2), (friction, 6)):
        calls.clear()
        values, _ = case_values(r, samples, 2)
        assert len(calls) == evaluations
        for i, sample in enumerate(samples):
            params = row_parameters(r, None, sample)[0]
            for k in range(2):
                fresh = original(r, params, cases.row_roughness(r, params), 20260528 + k)[0]
                assert values[i, k] == fresh
    assert len(set(case_values(friction, samples, 1)[0][:, 0])) == 3  # the bond energies do act on friction


def test_the_read_recorder_keys_what_was_read():
    from memstribo.laboratory.cases._memo import ReadRecorder, read_key

    params = get_parameter_values("silicon_thesis")
    recorder = ReadRecorder(params)
    recorder["hamaker_constant"], recorder.get("cutoff_distance")
    assert recorder.names() == ("cutoff_distance", "hamaker_constant")
    other = params.updated({"bond_energy": 1e-19})
    assert read_key(params, recorder.names()) == read_key(other, recorder.names())
    assert read_key(params, None) != read_key(other, None)
    recorder.updated({"bond_energy": 1e-19})
    assert recorder.names() is None  # a copy reads everything
