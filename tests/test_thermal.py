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


# --- heat in vacuum (issue 38, MODEL 7h): the tooth as a fin, the hub, radiation ---------------------------------
_FIN = {"heat_transfer_coefficient": 50.0, "perimeter": 16e-6, "conductivity": 32.0, "area": 12e-12}


def _fin_fd(m, length, theta_b, tip_flux, points=4001):
    """theta'' = m^2 theta on [0, L], theta(0) = theta_b, theta'(L) = tip_flux: second-order finite differences."""
    from scipy.linalg import solve_banded

    x = np.linspace(0.0, length, points)
    dx = x[1] - x[0]
    n = points - 1  # unknowns theta_1 .. theta_n
    ab = np.zeros((3, n))
    ab[0, 1:] = 1.0  # upper diagonal
    ab[1, :] = -(2.0 + (m * dx) ** 2)
    ab[2, :-1] = 1.0  # lower diagonal
    rhs = np.zeros(n)
    rhs[0] -= theta_b
    # ghost node at x_n + dx: theta_{n+1} = theta_{n-1} + 2 dx tip_flux
    ab[2, n - 2] = 2.0
    rhs[-1] -= 2.0 * dx * tip_flux
    theta = np.concatenate(([theta_b], solve_banded((1, 1), ab, rhs)))
    return x, theta


def test_radiation_coefficient_is_four_eps_sigma_t_cubed_and_linearises_stefan_boltzmann():
    sigma = thermal.STEFAN_BOLTZMANN
    assert thermal.radiation_coefficient(1.0, 300.0) == pytest.approx(4 * sigma * 300.0 ** 3, rel=1e-12)
    assert thermal.radiation_coefficient(1.0, 300.0) == pytest.approx(6.12, abs=0.01)
    # the default (eps = 0.6, 298.15 K): about 3.6 W/(m^2 K), 3600 times below the old air gap's 1.3e4
    assert thermal.radiation_coefficient(0.6, 298.15) == pytest.approx(3.60, abs=0.01)
    # Eq. 1.9 reproduces the net exchange eps sigma (T^4 - T_sur^4) of Eq. 1.7 exactly
    h = thermal.radiation_coefficient(0.7, 350.0, 290.0)
    assert h * (350.0 - 290.0) == pytest.approx(0.7 * sigma * (350.0 ** 4 - 290.0 ** 4), rel=1e-12)


def test_fin_heat_rates_reach_the_infinite_fin_and_the_whole_fin_at_base_temperature():
    m = thermal.fin_parameter(**_FIN)
    assert m == pytest.approx(math.sqrt(50.0 * 16e-6 / (32.0 * 12e-12)), rel=1e-12)
    infinite = thermal.fin_heat_rate_infinite(1.0, **_FIN)
    assert infinite == pytest.approx(math.sqrt(50.0 * 16e-6 * 32.0 * 12e-12), rel=1e-12)
    long = 12.0 / m  # mL = 12: tanh and the convective tip's ratio are 1 to 1e-10
    assert thermal.fin_heat_rate_adiabatic(1.0, **_FIN, length=long) == pytest.approx(infinite, rel=1e-9)
    assert thermal.fin_heat_rate_convective_tip(1.0, **_FIN, length=long) == pytest.approx(infinite, rel=1e-9)
    # a short fin is all at its base temperature: q = h P L theta_b (adiabatic tip), + h A_c theta_b (convective tip)
    short = 1e-4 / m
    assert thermal.fin_heat_rate_adiabatic(1.0, **_FIN, length=short) == pytest.approx(50.0 * 16e-6 * short, rel=1e-6)
    assert thermal.fin_heat_rate_convective_tip(1.0, **_FIN, length=short) == pytest.approx(
        50.0 * (16e-6 * short + 12e-12), rel=1e-6)
    # h / (m k) < 1: the convective tip lies between the adiabatic tip and the infinite fin
    mid = 1.0 / m
    adiabatic = thermal.fin_heat_rate_adiabatic(1.0, **_FIN, length=mid)
    assert adiabatic < thermal.fin_heat_rate_convective_tip(1.0, **_FIN, length=mid) < infinite


@pytest.mark.parametrize("ml", [1e-6, 0.05, 0.5, 2.0])
def test_tooth_heated_at_its_tip_against_a_finite_difference_solution_of_the_fin_equation(ml):
    m = thermal.fin_parameter(**_FIN)
    length = ml / m
    heat, theta_b = 2e-6, 1.5
    k_a = _FIN["conductivity"] * _FIN["area"]
    _, theta = _fin_fd(m, length, theta_b, heat / k_a)
    tip = thermal.fin_tip_excess_heat_input(heat, theta_b, **_FIN, length=length)
    assert tip == pytest.approx(theta[-1], rel=1e-6)
    if ml < 1e-3:  # sides that lose nothing: Fourier's law of a rod
        assert tip == pytest.approx(theta_b + heat * length / k_a, rel=1e-9)
    if ml < 1e-3:
        return  # the adiabatic fin's base heat rate is below round-off there
    # no heat at the tip: the adiabatic fin's base heat rate from the same numerical solution
    x, cold = _fin_fd(m, length, theta_b, 0.0)
    base_rate = -k_a * (-3 * cold[0] + 4 * cold[1] - cold[2]) / (2 * (x[1] - x[0]))
    assert base_rate == pytest.approx(thermal.fin_heat_rate_adiabatic(theta_b, **_FIN, length=length), rel=1e-5)


def test_tooth_with_adiabatic_sides_is_fouriers_law():
    sides = dict(_FIN, heat_transfer_coefficient=0.0)
    assert thermal.fin_tip_excess_heat_input(1e-6, 0.0, **sides, length=5e-6) == pytest.approx(
        1e-6 * 5e-6 / (32.0 * 12e-12), rel=1e-12)


def test_half_space_diffusion_length_in_both_peclet_limits():
    assert thermal.half_space_diffusion_length(1e-7, 100.0) == pytest.approx(1e-8, rel=1e-12)  # a / sqrt(L)
    assert thermal.half_space_diffusion_length(1e-7, 1e-3) == pytest.approx(1e-4, rel=1e-12)  # a / L = 2 kappa / u
    assert thermal.half_space_diffusion_length(1e-7, 1.0) == pytest.approx(1e-7, rel=1e-12)


def test_disc_rise_adds_parallel_paths_and_needs_one():
    # hub 1e-6 W/K, radiation 4 W/(m^2 K) over 1e-7 m^2, air gap 1e4 W/(m^2 K) over 5e-8 m^2
    assert thermal.disc_temperature_rise(1e-6, 1e-6, 4.0, 1e-7, 1e4, 5e-8) == pytest.approx(
        1e-6 / (1e-6 + 4e-7 + 5e-4), rel=1e-12)
    assert thermal.disc_temperature_rise(1e-6, 0.0, 4.0, 1e-7) == pytest.approx(1e-6 / 4e-7, rel=1e-12)
    with pytest.raises(InputError, match="no path for its heat"):
        thermal.disc_temperature_rise(1e-6, 0.0, 0.0, 1e-7)


@pytest.mark.parametrize("call, match", [
    (lambda: thermal.disc_temperature_rise(1e-6, -1e-6, 4.0, 1e-7), "hub_thermal_conductance"),
    (lambda: thermal.radiation_coefficient(0.0, 300.0), "emissivity"),
    (lambda: thermal.radiation_coefficient(1.2, 300.0), r"emissivity must lie in \(0, 1\]"),
    (lambda: thermal.radiation_coefficient(-0.5, 300.0), "emissivity"),
    (lambda: thermal.radiation_coefficient(0.6, -300.0), "temperature"),
    (lambda: thermal.fin_parameter(-1.0, 16e-6, 32.0, 12e-12), "heat_transfer_coefficient"),
    (lambda: thermal.fin_tip_excess_heat_input(-1e-6, 0.0, 4.0, 16e-6, 32.0, 12e-12, 5e-6), "heat"),
    (lambda: thermal.fin_heat_rate_convective_tip(1.0, 0.0, 16e-6, 32.0, 12e-12, 5e-6), "adiabatic tip"),
])
def test_heat_path_bad_input(call, match):
    with pytest.raises(InputError, match=match):
        call()


@pytest.mark.parametrize("name, value", [("emissivity", 0.0), ("emissivity", 1.01), ("hub_thermal_conductance", -1e-6)])
def test_heat_path_parameters_refuse_values_outside_their_range(params, name, value):
    with pytest.raises(InputError, match=name):
        params.updated({name: value})


def test_bulk_rise_in_vacuum_is_the_hub_and_radiation_not_an_air_gap(params):
    """The vacuum bulk rise is larger than version 3's air-gap value, finite, and radiation alone bounds it."""
    import math as _m

    from memstribo.physics.gear import GearPair
    from memstribo.simulations.tooth_life import synthetic_cycle, tooth_life

    pair = GearPair.from_parameters(params)
    cycle = synthetic_cycle(params, cof=0.3)
    vacuum = tooth_life(cycle, params)
    # the power from the disc's balance: hub + exact radiation eps sigma (T^4 - T_amb^4) (Eq. 1.9 at the disc's T)
    eps, t_amb = params["emissivity"], params["ambient_temperature"]
    tip = pair.tip_radii
    power = [rise * (params["hub_thermal_conductance"]
                     + thermal.radiation_coefficient(eps, t_amb + rise, t_amb) * 2 * _m.pi * r ** 2)
             for rise, r in zip(vacuum["disc_temperature_rise"], tip)]
    # version 3: the mean power over 1.3e4 W/(m^2 K) times the face area, in vacuum too
    old = max(thermal.bulk_temperature_rise(p, params["heat_transfer_coefficient"], _m.pi * r ** 2)
              for p, r in zip(power, tip))
    assert math.isfinite(vacuum["bulk_temperature_rise"])
    assert vacuum["bulk_temperature_rise"] > 10 * old
    i = int(np.argmax(vacuum["disc_temperature_rise"]))
    assert vacuum["bulk_temperature_rise"] == pytest.approx(
        vacuum["disc_temperature_rise"][i] + vacuum["tooth_temperature_rise"][i], rel=1e-6)
    assert min(vacuum["tooth_temperature_rise"]) > 0
    # no hub: radiation alone, P = eps sigma (T^4 - T_amb^4) 2 pi r_a^2, a far larger but finite rise, below the
    # rise with h_r linearised at the ambient (4 eps sigma T_amb^3), which bounds it
    alone = tooth_life(cycle, params.updated({"hub_thermal_conductance": 0.0}))
    t_disc = t_amb + alone["disc_temperature_rise"][0]
    assert power[0] == pytest.approx(eps * thermal.STEFAN_BOLTZMANN * (t_disc ** 4 - t_amb ** 4) * 2 * _m.pi
                                     * tip[0] ** 2, rel=1e-9)
    linear = power[0] / (thermal.radiation_coefficient(eps, t_amb) * 2 * _m.pi * tip[0] ** 2)
    assert 0.5 * linear < alone["disc_temperature_rise"][0] < linear
    assert math.isfinite(alone["bulk_temperature_rise"]) and alone["bulk_temperature_rise"] > vacuum["bulk_temperature_rise"]
    # in air the gap conducts: the rise falls back to the air gap's order
    air = tooth_life(cycle, params.updated({"environment": "air", "relative_humidity": 0.3}))
    assert air["bulk_temperature_rise"] < vacuum["bulk_temperature_rise"] / 10
    # the flash's half-space is outside its Péclet range on this slow cycle, and the run says so
    assert vacuum["flash_diffusion_length_max"] > _m.pi * params["module"] / 2
    assert any("outside its Péclet range" in w for w in vacuum["warnings"])
