"""Weibull fracture and delayed failure of polysilicon (memstribo.physics.strength)."""

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.parameters import SPECS, coerce_value
from memstribo.physics import strength


def test_weibull_probability_at_the_characteristic_strength_and_size_effect():
    # at sigma_theta on the reference area: 1 - 1/e (the definition of the characteristic strength)
    assert strength.fracture_probability(2e9, 1e-9, 2e9, 10.0, 1e-9) == pytest.approx(1 - math.exp(-1), rel=1e-12)
    # twice the area: the strength at equal probability falls by 2^(-1/m)
    p1 = strength.fracture_probability(1.5e9, 1e-9, 2e9, 10.0, 1e-9)
    p2 = strength.fracture_probability(1.5e9 * 2 ** (-1 / 10), 2e-9, 2e9, 10.0, 1e-9)
    assert p2 == pytest.approx(p1, rel=1e-12)
    assert strength.fracture_probability(-1e9, 1e-9, 2e9, 10.0, 1e-9) == 0.0  # compression does not break it


def test_effective_area_of_uniform_and_linear_stress():
    s = np.linspace(0.0, 2e-6, 2001)
    assert strength.effective_area(s, np.full_like(s, 1e9), 1e-6, 10.0) == pytest.approx(2e-12, rel=1e-12)
    # linear from 0 to sigma_max: integral (s/L)^m ds = L / (m + 1)
    assert strength.effective_area(s, s / s[-1] * 1e9, 1e-6, 10.0) == pytest.approx(1e-6 * 2e-6 / 11, rel=1e-4)


def test_fatigue_strength_halves_at_two_to_the_n_cycles_and_humidity_shortens_life():
    n = 30.0
    assert strength.fatigue_strength_factor(2.0**n, n) == pytest.approx(0.5, rel=1e-12)
    assert strength.fatigue_strength_factor(0.5, n) == 1.0  # no loss before the first cycle
    wet = strength.fatigue_strength_factor(1e6, n, relative_humidity=0.9, humidity_sensitivity=3.0)
    dry = strength.fatigue_strength_factor(1e6, n, relative_humidity=0.0, humidity_sensitivity=3.0)
    assert wet < strength.fatigue_strength_factor(1e6, n) < dry


def test_cycles_to_probability_inverts_the_fatigue_probability():
    m, n, rh, k = 10.0, 30.0, 0.6, 3.0
    stress, area, sigma, a0 = 1.2e9, 1e-12, 2.5e9, 5e-10
    risk = area / a0 * (stress / sigma) ** m
    cycles = strength.cycles_to_probability(0.01, risk, m, n, rh, k)
    p = strength.fatigue_fracture_probability(stress, area, cycles, sigma, m, a0, n, rh, k)
    assert p == pytest.approx(0.01, rel=1e-9)
    assert strength.cycles_to_probability(0.01, 1.0, m, n) == 1.0  # already past 1 % on the first load
    assert math.isinf(strength.cycles_to_probability(0.01, 0.0, m, n))


@pytest.mark.parametrize("name, value", [("weibull_modulus", 0.0), ("weibull_modulus", -3.0),
                                         ("strength_characteristic", -1e9), ("ambient_temperature", -1.0),
                                         ("ambient_temperature", 0.0), ("ambient_temperature", 1700.0)])
def test_unphysical_strength_and_temperature_parameters_are_refused(name, value):
    with pytest.raises(InputError, match=name):
        coerce_value(name, value)


def test_weibull_constants_checked_in_the_model_too():
    with pytest.raises(InputError, match="weibull_modulus"):
        strength.fracture_probability(1e9, 1e-9, 2e9, 0.0, 1e-9)
    with pytest.raises(InputError, match="strength_characteristic"):
        strength.fracture_probability(1e9, 1e-9, -2e9, 10.0, 1e-9)


def test_every_strength_and_thermal_constant_has_a_prior_with_a_source():
    for name in ("strength_characteristic", "weibull_modulus", "strength_reference_area", "fatigue_exponent",
                 "fatigue_humidity_sensitivity", "thermal_conductivity", "thermal_diffusivity",
                 "heat_transfer_coefficient", "hub_thermal_conductance", "emissivity", "dedendum_coefficient",
                 "root_fillet_coefficient"):
        prior = SPECS[name].prior
        assert prior and prior["distribution"] in ("uniform", "loguniform", "normal", "lognormal")
        low, high = prior["bounds"]
        assert low < high and prior["source"] and prior["reason"]
        assert coerce_value(name, low) == low and coerce_value(name, high) == high  # priors inside the bounds
