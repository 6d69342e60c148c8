"""Lennard-Jones potentials (thesis 3.3.3-3.3.5): calibration, closed forms against direct
numerical integration of the pair potential, forces, equilibrium distances, bad input."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate

from memstribo.physics import potentials as pot
from memstribo.errors import InputError

# reduced units for the integration checks: sigma = epsilon = N1 = l_z = 1
EPS, SIG, N1, LZ = 1.0, 1.0, 1.0, 1.0
RTOL_QUAD = 1e-7  # quadrature of smooth integrands; the closed forms are exact


def _pair(r):
    return 4.0 * EPS * ((SIG / r) ** 12 - (SIG / r) ** 6)


def _monolayer_numeric(z):
    """Pair potential summed over a continuous monolayer: integral of N1 U(l) 2 pi r dr."""
    value, _ = integrate.quad(lambda r: N1 * _pair(np.hypot(r, z)) * 2 * np.pi * r, 0, np.inf,
                              epsabs=0, epsrel=1e-11, limit=200)
    return value


def _half_space_numeric(z):
    """Pair potential over a half-space of density N1/l_z below the depth z (double integral)."""
    value, _ = integrate.quad(lambda zeta: _monolayer_numeric(zeta) / LZ, z, np.inf, epsabs=0, epsrel=1e-10,
                              limit=200)
    return value


def _chain_numeric(z):
    """Chain of atoms (spacing l_z) whose end is z from the half-space: repeated integral as
    (1/l_z^2) * integral over zeta >= z of (zeta - z) * monolayer(zeta) (Cauchy's formula)."""
    value, _ = integrate.quad(lambda zeta: (zeta - z) * _monolayer_numeric(zeta) / LZ**2, z, np.inf, epsabs=0,
                              epsrel=1e-10, limit=200)
    return value


# --- calibration: thesis 3.3.3-3.3.4 numbers -------------------------------------------------------

def test_sigma_from_bond_length_thesis_value():
    # thesis 3.3.3: sigma = D_chem (1/2)^(1/6) = 2.093 A (printed with 4 digits: 2.0936 rounds to 2.094;
    # the thesis truncates); tolerance: the printed digits, 1e-3 A
    assert pot.lennard_jones_sigma(2.35e-10) == pytest.approx(2.093e-10, abs=1e-13)


def test_epsilon_from_modulus_thesis_value():
    # thesis 3.3.4: epsilon = 2.9020e-20 J from E = 161 GPa, D_chem = 2.35 A
    assert pot.lennard_jones_epsilon(161e9, 2.35e-10) == pytest.approx(2.9020e-20, abs=0.00005e-20)


def test_areal_density_thesis_value():
    assert pot.areal_density(2.35e-10) == pytest.approx(1.8108e19, abs=0.00005e19)


def test_modulus_round_trip():
    eps = pot.lennard_jones_epsilon(161e9, 2.35e-10)
    assert pot.lennard_jones_modulus(eps, 2.35e-10) == pytest.approx(161e9, rel=1e-14)


def test_modulus_is_slope_of_layer_stress():
    """E = d(N1 F)/de at rho = D_chem, with e = (z - rho)/rho (3-19 to 3-21): check by finite differences.

    Sign: a compressive strain (z < rho) gives a repulsive (positive) pair force, so the
    stress-strain slope is -rho N1 dF/dz."""
    d, e_young = 2.35e-10, 161e9
    eps, sig = pot.lennard_jones_epsilon(e_young, d), pot.lennard_jones_sigma(d)
    h = 1e-6 * d
    slope = -(pot.lennard_jones_force(d + h, eps, sig) - pot.lennard_jones_force(d - h, eps, sig)) / (2 * h)
    assert slope * d * pot.areal_density(d) == pytest.approx(e_young, rel=1e-6)


# --- pair potential ---------------------------------------------------------------------------------

def test_pair_potential_minimum_and_zero():
    r_min = pot.equilibrium_distance(SIG, "12-6")
    assert pot.lennard_jones_potential(r_min, EPS, SIG) == pytest.approx(-EPS, rel=1e-14)
    assert pot.lennard_jones_potential(SIG, EPS, SIG) == pytest.approx(0.0, abs=1e-15)
    assert pot.lennard_jones_force(r_min, EPS, SIG) == pytest.approx(0.0, abs=1e-13)


@pytest.mark.parametrize("name", ["lennard_jones", "particle_monolayer", "particle_half_space", "chain_half_space"])
def test_force_is_minus_derivative_of_potential(name):
    u = getattr(pot, f"{name}_potential")
    f = getattr(pot, f"{name}_force")
    extra = () if name == "lennard_jones" else ((N1,) if name == "particle_monolayer" else (N1, LZ))
    z = np.linspace(0.8, 3.0, 12)
    h = 1e-6
    numeric = -(u(z + h, EPS, SIG, *extra) - u(z - h, EPS, SIG, *extra)) / (2 * h)
    np.testing.assert_allclose(f(z, EPS, SIG, *extra), numeric, rtol=1e-6, atol=1e-8)


# --- integrated forms against direct numerical integration of the pair potential ---------------------

@pytest.mark.parametrize("z", [0.85, 1.0, 1.3, 2.0])
def test_monolayer_matches_numerical_integration(z):
    assert pot.particle_monolayer_potential(z, EPS, SIG, N1) == pytest.approx(_monolayer_numeric(z), rel=RTOL_QUAD)


@pytest.mark.parametrize("z", [0.8, 1.0, 1.5])
def test_half_space_matches_numerical_integration(z):
    assert pot.particle_half_space_potential(z, EPS, SIG, N1, LZ) == pytest.approx(_half_space_numeric(z),
                                                                                   rel=RTOL_QUAD)


@pytest.mark.parametrize("z", [0.7, 1.0, 1.5])
def test_chain_matches_numerical_integration(z):
    assert pot.chain_half_space_potential(z, EPS, SIG, N1, LZ) == pytest.approx(_chain_numeric(z), rel=RTOL_QUAD)


def test_chain_form_matches_thesis_second_form():
    # thesis 3.3.5 prints U_8-2 also as pi eps N1 sigma^4/(3 lz^2) (sigma^8/(30 z^8) - sigma^2/z^2)
    z = np.array([0.7, 1.0, 2.0]) * 2.09e-10
    eps, sig, n1, lz = 2.9e-20, 2.09e-10, 1.81e19, 2.35e-10
    thesis = np.pi * eps * n1 * sig**4 / (3 * lz**2) * (sig**8 / (30 * z**8) - sig**2 / z**2)
    np.testing.assert_allclose(pot.chain_half_space_potential(z, eps, sig, n1, lz), thesis, rtol=1e-13)


def test_si_scaling_consistent_with_reduced_units():
    eps, sig, n1, lz = 2.902e-20, 2.0936e-10, 1.8108e19, 2.35e-10
    z = 1.3 * sig
    reduced = pot.particle_half_space_potential(1.3, 1.0, 1.0, 1.0, 1.0)
    assert pot.particle_half_space_potential(z, eps, sig, n1, lz) == pytest.approx(
        reduced * eps * n1 * sig**3 / lz, rel=1e-13)


@pytest.mark.parametrize("form,name,extra", [
    ("12-6", "lennard_jones", ()),
    ("10-4", "particle_monolayer", (N1,)),
    ("9-3", "particle_half_space", (N1, LZ)),
    ("8-2", "chain_half_space", (N1, LZ)),
])
def test_equilibrium_distance_is_zero_of_force_and_minimum(form, name, extra):
    z0 = pot.equilibrium_distance(SIG, form)
    f = getattr(pot, f"{name}_force")
    u = getattr(pot, f"{name}_potential")
    assert f(z0, EPS, SIG, *extra) == pytest.approx(0.0, abs=1e-12)
    # repulsive inside, attractive outside; the potential is minimal there
    assert f(0.98 * z0, EPS, SIG, *extra) > 0 > f(1.02 * z0, EPS, SIG, *extra)
    assert u(z0, EPS, SIG, *extra) < min(u(0.98 * z0, EPS, SIG, *extra), u(1.02 * z0, EPS, SIG, *extra))


def test_vectorised_shape():
    z = np.linspace(1.0, 2.0, 6).reshape(2, 3)
    assert pot.particle_half_space_force(z, EPS, SIG, N1, LZ).shape == (2, 3)
    assert isinstance(pot.lennard_jones_potential(1.5, EPS, SIG), float)


# --- bad input -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("call,match", [
    (lambda: pot.lennard_jones_sigma(0.0), "bond_length"),
    (lambda: pot.lennard_jones_sigma(-2e-10), "bond_length"),
    (lambda: pot.lennard_jones_epsilon(-1.0, 2.35e-10), "youngs_modulus"),
    (lambda: pot.lennard_jones_epsilon(161e9, float("nan")), "bond_length"),
    (lambda: pot.lennard_jones_potential(0.0, 1.0, 1.0), "separation"),
    (lambda: pot.lennard_jones_force([1.0, -1.0], 1.0, 1.0), "separation"),
    (lambda: pot.particle_monolayer_potential(1.0, 0.0, 1.0, 1.0), "epsilon"),
    (lambda: pot.particle_half_space_potential(1.0, 1.0, 1.0, 1.0, 0.0), "layer_spacing"),
    (lambda: pot.chain_half_space_force(1.0, 1.0, -1.0, 1.0, 1.0), "sigma"),
    (lambda: pot.equilibrium_distance(1.0, "7-3"), "form"),
])
def test_bad_input(call, match):
    with pytest.raises(InputError, match=match):
        call()
