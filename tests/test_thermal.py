"""Flash temperature of a moving band heat source (memstribo.physics.thermal): both Péclet limits, Blok's partition."""

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.physics import thermal


def _band_mean(peclet):
    nodes, weights = np.polynomial.legendre.leggauss(24)
    return 0.5 * float(np.sum(weights * thermal.band_temperature(nodes, peclet)))


@pytest.mark.parametrize("peclet", [100.0, 1000.0])
def test_high_peclet_limit_is_one_dimensional_conduction(peclet):
    # each point heated for 2a/u: theta_max = (2/sqrt(pi)) q a / (k sqrt(L)) at the trailing edge, mean 2/3 of it
    x = np.linspace(-1.0, 1.0, 81)
    theta = thermal.band_temperature(x, peclet)
    assert float(theta.max()) == pytest.approx(2 / math.sqrt(math.pi) / math.sqrt(peclet), rel=0.01)
    assert x[int(np.argmax(theta))] < -0.95  # at the trailing edge, x/a = -1 (lateral conduction rounds it off)
    assert _band_mean(peclet) == pytest.approx(4 / (3 * math.sqrt(math.pi)) / math.sqrt(peclet), rel=0.01)


@pytest.mark.parametrize("peclet", [1e-4, 1e-3])
def test_low_peclet_limit_is_the_logarithm_of_the_line_source(peclet):
    # K0(z) ~ -ln(z/2) - gamma: theta_mean = (2/pi)(3/2 - gamma - ln L), theta(0) = (2/pi)(1 - gamma + ln 2 - ln L)
    gamma = 0.5772156649015329
    assert _band_mean(peclet) == pytest.approx(2 / math.pi * (1.5 - gamma - math.log(peclet)), rel=1e-3)
    assert thermal.band_temperature(0.0, peclet) == pytest.approx(
        2 / math.pi * (1 - gamma + math.log(2) - math.log(peclet)), rel=1e-3)


def test_band_mean_factor_is_continuous_where_it_switches_to_the_limits():
    for switch in (thermal.HIGH_PECLET, thermal.LOW_PECLET):
        assert thermal.band_mean_factor(switch * 1.0001) == pytest.approx(thermal.band_mean_factor(switch / 1.0001),
                                                                          rel=0.01)


def test_blok_partition_equal_speeds_share_half_and_heat_scales_with_flux():
    out = thermal.blok_flash_temperature(1e9, 1e-7, 0.1, 0.1, 30.0, 2e-5)
    assert float(out["share_1"][0]) == pytest.approx(0.5, rel=1e-12)
    # equal bodies: theta = q a f / (2 k), half the heat each
    f = thermal.band_mean_factor(thermal.peclet_number(0.1, 1e-7, 2e-5))
    assert float(out["flash"][0]) == pytest.approx(1e9 * 1e-7 * f / (2 * 30.0), rel=1e-12)
    double = thermal.blok_flash_temperature(2e9, 1e-7, 0.1, 0.1, 30.0, 2e-5)
    assert float(double["flash"][0]) == pytest.approx(2 * float(out["flash"][0]), rel=1e-12)
    # the faster surface carries more heat away
    fast = thermal.blok_flash_temperature(1e9, 1e-7, 10.0, 0.1, 30.0, 2e-5)
    assert float(fast["share_1"][0]) > 0.5


def test_bulk_temperature_rise_and_bad_input():
    assert thermal.bulk_temperature_rise(1e-4, 1e4, 1e-8) == pytest.approx(1.0, rel=1e-12)
    with pytest.raises(InputError, match="heat_transfer_coefficient"):
        thermal.bulk_temperature_rise(1e-4, 0.0, 1e-8)
    with pytest.raises(InputError, match="Péclet"):
        thermal.band_temperature(0.0, 0.0)
