"""Capillary condensation relations (issue #17): Kelvin, meniscus forces, their limits (memstribo.physics.capillary)."""

import math

import numpy as np
import pytest

from memstribo.physics.capillary import (capillary_force_cylinder, capillary_force_from_gap, capillary_force_sphere,
                                 capillary_pressure, condensation_height, kelvin_radius, laplace_pressure)
from memstribo.errors import InputError


def test_kelvin_radius_of_water_at_room_temperature():
    # gamma V_m / (R T) = 0.072 * 18.07e-6 / (8.314462618 * 298.15) = 0.5248 nm (about 0.52 nm, issue #17)
    assert kelvin_radius(1 / math.e) == pytest.approx(0.072 * 18.07e-6 / (8.314462618 * 298.15), rel=1e-12)
    assert kelvin_radius(0.5) == pytest.approx(0.5248e-9 / math.log(2), rel=1e-3)
    assert kelvin_radius(0.0) == 0.0  # dry: no meniscus
    radii = kelvin_radius(np.array([0.1, 0.5, 0.9]))
    assert np.all(np.diff(radii) > 0)  # wetter air, flatter menisci
    with pytest.raises(InputError, match="relative_humidity"):
        kelvin_radius(1.0)


def test_sphere_on_a_flat_reaches_four_pi_r_gamma_cos_theta():
    """A numerical meniscus (Laplace pressure over the wetted area of a sphere's gap) against the closed form."""
    radius, theta = 1e-6, math.radians(30)
    r_k = kelvin_radius(0.4)
    dx = 0.5e-9
    x = (np.arange(801) - 400) * dx
    gap = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius)
    numeric = capillary_force_from_gap(gap, dx * dx, r_k, theta)
    assert numeric == pytest.approx(capillary_force_sphere(radius, theta), rel=0.02)
    assert capillary_force_sphere(radius, theta) == pytest.approx(4 * math.pi * radius * 0.072 * math.cos(theta))


def test_cylinder_per_unit_length_against_a_numerical_meniscus():
    radius, theta = 10e-6, math.radians(20)
    r_k = kelvin_radius(0.5)
    dx = 0.05e-9
    x = (np.arange(40001) - 20000) * dx
    numeric = capillary_force_from_gap(x**2 / (2 * radius), dx, r_k, theta)  # per unit length: area dx * 1 m
    assert numeric == pytest.approx(capillary_force_cylinder(radius, r_k, theta), rel=1e-3)


def test_no_capillary_force_when_dry_or_hydrophobic():
    assert capillary_force_cylinder(1e-6, kelvin_radius(0.0), 0.3) == 0.0
    hydrophobic = math.radians(112)  # OTS
    assert condensation_height(kelvin_radius(0.9), hydrophobic) == 0.0
    assert capillary_force_sphere(1e-6, hydrophobic) == 0.0
    assert capillary_force_sphere(1e-6, math.radians(90)) == pytest.approx(0.0, abs=1e-20)
    assert np.all(capillary_pressure(np.zeros(5), kelvin_radius(0.9), hydrophobic) == 0.0)
    # one hydrophilic and one hydrophobic surface: cos 20 + cos 112 > 0, a (weaker) meniscus still forms
    assert condensation_height(kelvin_radius(0.5), math.radians(20), math.radians(112)) > 0


def test_adhesion_grows_with_humidity_on_a_rough_gap():
    """Monotone growth of the wetted area with RH on a rough gap; the Laplace pressure falls: the force over a
    rough line grows with RH (more of the roughness fills)."""
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.roughness import default_profile

    profile = default_profile(get_parameter_values(), length=4e-6)
    gap = np.maximum(profile.z.max() - profile.z, 0.0)  # a flat touching the highest peak
    dx = float(profile.x[1] - profile.x[0])
    theta = math.radians(25)
    wetted = [float(np.sum(capillary_pressure(gap, kelvin_radius(rh), theta) > 0)) for rh in (0.2, 0.5, 0.8, 0.95)]
    assert wetted == sorted(wetted) and wetted[-1] > wetted[0]
    forces = [capillary_force_from_gap(gap, dx * 1e-6, kelvin_radius(rh), theta) for rh in (0.0, 0.3, 0.6, 0.9)]
    assert forces[0] == 0.0 and all(f > 0 for f in forces[1:])


def test_laplace_pressure_and_bad_input():
    assert laplace_pressure(1e-9) == pytest.approx(0.072e9)
    assert laplace_pressure(0.0) == 0.0
    with pytest.raises(InputError, match="contact angles"):
        condensation_height(1e-9, 4.0)
    with pytest.raises(InputError, match="gap"):
        capillary_pressure([np.nan], 1e-9, 0.3)


def test_humid_air_in_the_meshing_cycle():
    """Issue #17: vacuum is untouched; in air the menisci add attraction to F_adh and a capillary part to the
    COF split (which still adds up); dry air equals vacuum; OTS-coated teeth (hydrophobic) form no menisci."""
    from memstribo.physics.coating import get_coating
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    vacuum = summarize(simulate_mesh(params, steps=21))
    assert vacuum["environment"] == "vacuum" and vacuum["cof_capillary"] == 0.0
    dry = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.0}), steps=21))
    assert dry["cof_mean"] == vacuum["cof_mean"] and dry["stiction_margin"] == vacuum["stiction_margin"]
    humid = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.6}), steps=21))
    assert humid["cof_capillary"] > 0 and humid["energy_capillary"] > 0
    assert humid["adhesion_force_mean"] > vacuum["adhesion_force_mean"]
    assert humid["cof_mean"] == pytest.approx(humid["cof_chemical"] + humid["cof_vdw"] + humid["cof_elastic"]
                                              + humid["cof_capillary"], rel=1e-12)
    coated = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.6}), steps=21,
                                     coating=get_coating("OTS"), wear=0.0))
    # the pinion is bare (30 deg) and the gear OTS (112 deg): cos 30 + cos 112 > 0, a weak meniscus remains
    assert 0 < coated["cof_capillary"] < humid["cof_capillary"]


def test_cli_sweep_humidity(cli):
    out = cli.json("sweep", "humidity", "--values", "0,0.7", "--steps", "11")
    dry, wet = out["points"]
    assert dry["relative_humidity"] == 0.0 and dry["cof_capillary"] == 0.0 and wet["cof_capillary"] > 0
