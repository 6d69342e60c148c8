"""Property-based tests (hypothesis): parameter parsing and physical invariants."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from memstribo.errors import InputError
from memstribo.parameters import SPECS, coerce_value, get_parameter_values, parse_assignment
from memstribo.units import to_si

QUICK = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
SLOW = settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])

#: a unit each SI unit can be written in, with its size in SI
OTHER_UNITS = {"m": [("nm", 1e-9), ("um", 1e-6), ("mm", 1e-3), ("pm", 1e-12)], "N": [("uN", 1e-6), ("mN", 1e-3),
               ("nN", 1e-9)], "Pa": [("GPa", 1e9), ("MPa", 1e6), ("kPa", 1e3)], "J": [("eV", 1.602176634e-19),
               ("aJ", 1e-18)], "rad": [("deg", math.pi / 180)], "J/m^2": [("mJ/m^2", 1e-3)],
               "N*m": [("uN*m", 1e-6), ("N*um", 1e-6)], "rad/s": [("rad/ms", 1e3)]}

NUMERIC = sorted(name for name, spec in SPECS.items() if spec.kind in ("float", "int"))


def _inside(spec):
    """Values strictly inside the range of ``spec`` (a margin keeps 15-digit rounding inside it)."""
    lo, hi = spec.minimum, spec.maximum
    if spec.kind == "int":
        return st.integers(int(lo) + (1 if spec.exclusive_minimum else 0), min(int(hi), 2**53))
    low = lo + abs(lo) * 1e-9 if lo != 0 else (1e-300 if spec.exclusive_minimum else 0.0)
    high = hi - abs(hi) * 1e-9
    if lo > 0:  # many decades: draw the exponent
        return st.floats(math.log10(low), math.log10(high)).map(lambda e: float(f"{10.0 ** e:.12g}")).filter(
            lambda v: lo < v < hi)
    return st.floats(low, high, allow_nan=False, allow_infinity=False)


@QUICK
@given(data=st.data(), name=st.sampled_from(NUMERIC))
def test_valid_values_round_trip_plain_and_with_units(data, name):
    spec = SPECS[name]
    value = data.draw(_inside(spec))
    assert coerce_value(name, value) == value
    assert coerce_value(name, repr(value)) == value  # plain SI text
    if spec.kind == "float" and spec.unit in OTHER_UNITS:
        unit, size = data.draw(st.sampled_from(OTHER_UNITS[spec.unit]))
        text = f"{value / size!r} {unit}"
        assert coerce_value(name, text) == pytest.approx(value, rel=1e-12, abs=1e-300)
        assert coerce_value(name, text.replace(" ", "")) == pytest.approx(value, rel=1e-12, abs=1e-300)
        assert parse_assignment(f"{name}={text}") == (name, text)


garbage = st.one_of(
    st.text(max_size=30),
    st.from_regex(r"\A[-+]?[0-9.eE]{0,6} ?[a-zA-Z\u00b5\u00b0/*^()0-9 %-]{0,10}\Z"),
    st.sampled_from(["5 (uN", "5 uN/0", "uN", "1e999 N", "nan", "inf", "--5", "5 uN)", "()", "5 N/0/0", "**2",
                     "5 uN\x1b[2J", "\x00", "5" * 400]),
)


@QUICK
@given(text=garbage, name=st.sampled_from(sorted(SPECS)))
def test_garbage_is_an_input_error_never_another_exception(text, name):
    spec = SPECS[name]
    try:
        value = coerce_value(name, text)
    except InputError as exc:
        assert "\x1b" not in str(exc) and "\x00" not in str(exc)
        return
    # whatever parses is a valid value of the parameter
    if spec.kind in ("float", "int"):
        assert math.isfinite(value) and spec.minimum <= value <= spec.maximum
    elif spec.kind == "str":
        assert value in spec.choices


@QUICK
@given(text=garbage, unit=st.sampled_from(["N", "m", "Pa", "rad", "", "J/m^2"]))
def test_to_si_raises_only_input_error(text, unit):
    try:
        value = to_si(text, unit, "x")
    except InputError:
        return
    assert math.isfinite(value)


# --- physics invariants ------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def params():
    return get_parameter_values()


@SLOW
@given(load=st.floats(1e-6, 300e-6), bonds=st.integers(4, 12))
def test_dissipated_energy_of_a_slide_is_not_negative(params, load, bonds):
    from memstribo.simulations import sliding

    dataset = sliding.slide("fixed-load", params, load=load, distance=bonds * params["bond_length"])
    for name in ("energy_chemical", "energy_vdw", "energy_elastic"):
        assert np.all(dataset[name].values >= 0), name
    summary = sliding.summarize(dataset)
    assert summary.energy_chemical + summary.energy_vdw + summary.energy_elastic >= 0
    assert summary.friction_force_mean >= 0


@QUICK
@given(load=st.floats(1e-7, 1e-3), width_factor=st.floats(0.5, 2.0))
def test_bond_breaking_energy_and_friction_estimate_are_not_negative(params, load, width_factor):
    from memstribo.physics import friction

    estimate = friction.estimate_from_parameters(
        params.updated({"adhesive_width": params["adhesive_width"] * width_factor}), load=load)
    assert estimate.chemical_energy_per_block >= 0 and estimate.vdw_energy_per_block >= 0
    assert estimate.friction_force >= 0 and estimate.cof >= 0
    energy = friction.bond_breaking_energy(np.arange(5), params["bond_energy"], 3 * params["bond_length"],
                                           params["bond_length"])
    assert np.all(np.asarray(energy) >= 0)


@QUICK
@given(amplitudes=st.lists(st.floats(0, 5e9), min_size=1, max_size=60), exponent=st.floats(0.5, 4.0),
       coefficient=st.floats(1e-40, 1e-5))
def test_damage_does_not_decrease_with_cycles(amplitudes, exponent, coefficient):
    from memstribo.physics.damage import damage_sum

    with np.errstate(over="ignore"):
        totals = [float(damage_sum(amplitudes[:n], exponent, coefficient)) for n in range(len(amplitudes) + 1)]
    assume(all(math.isfinite(t) for t in totals))
    # numpy's pairwise summation may reorder the additions when a cycle is added: equal to round-off (1 ulp)
    assert all(b >= a * (1 - 4 * np.finfo(float).eps) for a, b in zip(totals, totals[1:]))


@QUICK
@given(load=st.floats(1e-7, 1e-2), face_width=st.floats(1e-7, 1e-4), radius=st.floats(1e-7, 1e-3),
       modulus=st.floats(1e9, 1e12))
def test_hertz_line_contact_carries_its_load(load, face_width, radius, modulus):
    from memstribo.physics.gear import hertz_line_contact

    contact = hertz_line_contact(load, face_width, radius, modulus)
    # elliptical pressure p0 sqrt(1 - x^2/a^2) over -a..a, times the face width, is the load
    carried = math.pi / 2 * float(contact.half_width) * float(contact.peak_pressure) * face_width
    assert carried == pytest.approx(load, rel=1e-12)


@QUICK
@given(load=st.floats(1e-9, 1e-5), degree=st.floats(1.5, 8.0), height_nm=st.floats(0.1, 10.0))
def test_power_law_asperity_pressure_integrates_to_the_load(load, degree, height_nm):
    from scipy.integrate import quad

    from memstribo.physics.asperity import power_law_contact, power_law_pressure

    shape = height_nm * 1e-9 / (10e-9) ** degree   # B_d: a height of height_nm at r = 10 nm
    modulus = 91e9
    contact = power_law_contact(load, degree, shape, modulus)
    a = float(contact.contact_radius)
    # r = a sin(t) takes the square-root edge of the pressure out of the integrand
    integrand = lambda t: float(power_law_pressure(a * math.sin(t), load, degree, shape, modulus)) * \
        2 * math.pi * a * math.sin(t) * a * math.cos(t)
    carried, _ = quad(integrand, 0.0, math.pi / 2, limit=200)
    assert carried == pytest.approx(load, rel=1e-5)
    assert float(contact.mean_pressure) * math.pi * a ** 2 == pytest.approx(load, rel=1e-9)
