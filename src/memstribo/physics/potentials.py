"""Interatomic potentials: Lennard-Jones 12-6 and its integrated 10-4, 9-3 and 8-2 forms.

Thesis sections 3.3.3 to 3.3.5 ([1]_). The pair potential of two atoms (3-14) is calibrated
to silicon from the bond length (3-16) and Young's modulus (3-19 to 3-23); summing it over a
monolayer, a half-space and a vertical chain of atoms (the Bradley-Hamaker approach, 3.3.5)
gives the particle-monolayer (10-4), particle-half-space (9-3) and chain-half-space (8-2)
potentials used for van der Waals interactions between surfaces.

Conventions: all quantities SI; separations are positive; a *force* is ``-dU/dz``, so a
positive force is repulsive and a negative one attractive. The summed forms assume a
continuum of atoms with ``areal_density`` N1 atoms per unit area in each atomic layer and
``layer_spacing`` l_z between layers (volume density N1 / l_z), as in the thesis.

References
----------
.. [1] N. S. T. Almuramady, 'Dry friction between rough surfaces of silicon and
   functionalized gear MEMS', PhD thesis, Cardiff University.
.. [2] J. N. Israelachvili, Intermolecular and Surface Forces, 3rd ed., Academic Press, 2011.
"""

from __future__ import annotations

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "EQUILIBRIUM_FACTORS",
    "areal_density",
    "lennard_jones_sigma",
    "lennard_jones_epsilon",
    "lennard_jones_modulus",
    "lennard_jones_potential",
    "lennard_jones_force",
    "particle_monolayer_potential",
    "particle_monolayer_force",
    "particle_half_space_potential",
    "particle_half_space_force",
    "chain_half_space_potential",
    "chain_half_space_force",
    "equilibrium_distance",
]

#: Equilibrium distance (zero force) of each form in units of sigma:
#: 12-6: 2^(1/6); 10-4: 1; 9-3: (2/5)^(1/6); 8-2: (2/15)^(1/6).
EQUILIBRIUM_FACTORS: dict[str, float] = {
    "12-6": 2.0 ** (1.0 / 6.0),
    "10-4": 1.0,
    "9-3": (2.0 / 5.0) ** (1.0 / 6.0),
    "8-2": (2.0 / 15.0) ** (1.0 / 6.0),
}


def _result(value):
    return float(value) if np.ndim(value) == 0 else value


def _pair_inputs(separation, epsilon, sigma):
    """The checked separation [m], pair well depth epsilon [J] and zero-potential distance sigma [m]."""
    return (as_array(separation, "separation", "m", positive=True),
            as_array(epsilon, "epsilon", "J", positive=True),
            as_array(sigma, "sigma", "m", positive=True))


def _layer_inputs(separation, epsilon, sigma, areal_density):
    """:func:`_pair_inputs` and the checked areal density N1 [1/m²] of an atomic layer."""
    return (*_pair_inputs(separation, epsilon, sigma),
            as_array(areal_density, "areal_density", "1/m^2", positive=True))


def _half_space_inputs(separation, epsilon, sigma, areal_density, layer_spacing):
    """:func:`_layer_inputs` and the checked layer spacing l_z [m]."""
    return (*_layer_inputs(separation, epsilon, sigma, areal_density),
            as_array(layer_spacing, "layer_spacing", "m", positive=True))


def areal_density(bond_length):
    """Number of atoms per unit area of an atomic layer, N1 = 1 / D_chem².

    Parameters
    ----------
    bond_length : float or array_like
        Bond length D_chem [m].

    Returns
    -------
    float or ndarray
        Areal density N1 [1/m²] (1.8108e19 m⁻² for silicon, thesis 3.3.4).
    """
    bond_length = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(1.0 / bond_length**2)


@cites("thesis")
def lennard_jones_sigma(bond_length):
    """Zero-potential distance sigma of the LJ 12-6 potential from the bond length.

    The bond length is the equilibrium (zero-force) distance of the pair, so
    sigma = D_chem 2^(-1/6), Eq. (3-16) in [1]_ (2.093 Å for silicon).

    Parameters
    ----------
    bond_length : float or array_like
        Bond length D_chem [m], the pair's equilibrium distance.

    Returns
    -------
    float or ndarray
        sigma [m].

    Examples
    --------
    >>> round(lennard_jones_sigma(2.35e-10) * 1e10, 3)
    2.094
    """
    bond_length = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(bond_length * 2.0 ** (-1.0 / 6.0))


@cites("thesis")
def lennard_jones_epsilon(youngs_modulus, bond_length):
    """Well depth epsilon of the LJ 12-6 potential calibrated to Young's modulus.

    The stress between two atomic layers is N1 times the pair force; its slope
    with respect to the strain e = (z - rho)/rho at the equilibrium distance rho = D_chem
    is Young's modulus: E = 72 epsilon N1 / rho (Eqs. (3-19) to (3-23) in [1]_), hence

    .. math:: \\varepsilon = \\frac{\\rho E}{72 N_1} = \\frac{D_{chem}^3 E}{72}.

    Parameters
    ----------
    youngs_modulus : float or array_like
        Young's modulus E [Pa].
    bond_length : float or array_like
        Bond length D_chem = rho [m].

    Returns
    -------
    float or ndarray
        epsilon [J] (2.902e-20 J for silicon, thesis 3.3.4).

    Examples
    --------
    >>> print(f"{lennard_jones_epsilon(161e9, 2.35e-10):.4g}")
    2.902e-20
    """
    youngs_modulus = as_array(youngs_modulus, "youngs_modulus", "Pa", positive=True)
    bond_length = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(bond_length * youngs_modulus / (72.0 * (1.0 / bond_length**2)))


@cites("thesis")
def lennard_jones_modulus(epsilon, bond_length):
    """Young's modulus implied by a LJ 12-6 bond, E = 72 epsilon N1 / rho, Eq. (3-23) in [1]_.

    The inverse of :func:`lennard_jones_epsilon`.

    Parameters
    ----------
    epsilon : float or array_like
        Well depth [J].
    bond_length : float or array_like
        Bond length D_chem = rho [m].

    Returns
    -------
    float or ndarray
        Young's modulus [Pa].
    """
    epsilon = as_array(epsilon, "epsilon", "J", positive=True)
    bond_length = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(72.0 * epsilon / bond_length**3)


@cites("thesis")
def lennard_jones_potential(separation, epsilon, sigma):
    """Lennard-Jones 12-6 pair potential, Eq. (3-14) in [1]_.

    .. math:: U(r) = 4\\varepsilon\\left[(\\sigma/r)^{12} - (\\sigma/r)^6\\right]

    Parameters
    ----------
    separation : float or array_like
        Distance r between the two atoms [m], > 0.
    epsilon : float
        Well depth [J].
    sigma : float
        Distance of zero potential [m].

    Returns
    -------
    float or ndarray
        Potential energy [J]; minimum -epsilon at r = 2^(1/6) sigma.
    """
    r, epsilon, sigma = _pair_inputs(separation, epsilon, sigma)
    s6 = (sigma / r) ** 6
    return _result(4.0 * epsilon * (s6 * s6 - s6))


@cites("thesis")
def lennard_jones_force(separation, epsilon, sigma):
    """Lennard-Jones 12-6 pair force -dU/dr, Eq. (3-15) in [1]_ (positive = repulsive).

    .. math:: F(r) = 24\\varepsilon\\left(\\frac{2\\sigma^{12}}{r^{13}} - \\frac{\\sigma^6}{r^7}\\right)

    Parameters
    ----------
    separation : float or array_like
        Distance r [m], > 0.
    epsilon, sigma : as in :func:`lennard_jones_potential` (well depth [J], distance of zero potential [m])

    Returns
    -------
    float or ndarray
        Force [N].
    """
    r, epsilon, sigma = _pair_inputs(separation, epsilon, sigma)
    s6 = (sigma / r) ** 6
    return _result(24.0 * epsilon * (2.0 * s6 * s6 - s6) / r)


@cites("thesis", "israelachvili_2011")
def particle_monolayer_potential(separation, epsilon, sigma, areal_density):
    """Potential of one atom at distance z from a monolayer of atoms (the 10-4 form).

    The pair potential summed over a continuous monolayer of N1 atoms per unit area
    (thesis 3.3.5, [1]_):

    .. math:: U_{10-4}(z) = 4\\pi\\varepsilon N_1\\left(\\frac{\\sigma^{12}}{5z^{10}} - \\frac{\\sigma^6}{2z^4}\\right)

    Parameters
    ----------
    separation : float or array_like
        Distance z of the atom from the layer [m], > 0.
    epsilon : float
        Pair well depth [J].
    sigma : float
        Pair zero-potential distance [m].
    areal_density : float
        Atoms per unit area N1 [1/m²].

    Returns
    -------
    float or ndarray
        Potential energy [J].
    """
    z, epsilon, sigma, n1 = _layer_inputs(separation, epsilon, sigma, areal_density)
    s = sigma / z
    return _result(4.0 * np.pi * epsilon * n1 * sigma**2 * (s**10 / 5.0 - s**4 / 2.0))


@cites("thesis", "israelachvili_2011")
def particle_monolayer_force(separation, epsilon, sigma, areal_density):
    """Force -dU/dz of the 10-4 particle-monolayer potential (positive = repulsive).

    .. math:: F_{10-4}(z) = 8\\pi\\varepsilon N_1\\left(\\frac{\\sigma^{12}}{z^{11}} - \\frac{\\sigma^6}{z^5}\\right)

    Zero at z = sigma. Parameters as :func:`particle_monolayer_potential`; returns [N].
    """
    z, epsilon, sigma, n1 = _layer_inputs(separation, epsilon, sigma, areal_density)
    s = sigma / z
    return _result(8.0 * np.pi * epsilon * n1 * sigma * (s**11 - s**5))


@cites("thesis", "israelachvili_2011")
def particle_half_space_potential(separation, epsilon, sigma, areal_density, layer_spacing):
    """Potential of one atom at distance z from a half-space of atoms (the 9-3 form).

    The 10-4 form summed over layers l_z apart, as an integral (thesis 3.3.5, [1]_):

    .. math:: U_{9-3}(z) = \\frac{4\\pi\\varepsilon N_1}{l_z}\\left(\\frac{\\sigma^{12}}{45z^9} - \\frac{\\sigma^6}{6z^3}\\right)

    Parameters
    ----------
    separation : float or array_like
        Distance z of the atom from the surface of the half-space [m], > 0.
    epsilon, sigma : float
        Pair parameters [J], [m].
    areal_density : float
        Atoms per unit area of one layer N1 [1/m²].
    layer_spacing : float
        Distance l_z between atomic layers [m] (the thesis takes l_z = D_chem).

    Returns
    -------
    float or ndarray
        Potential energy of the atom [J].
    """
    z, epsilon, sigma, n1, lz = _half_space_inputs(separation, epsilon, sigma, areal_density, layer_spacing)
    s = sigma / z
    return _result(4.0 * np.pi * epsilon * n1 * sigma**3 / lz * (s**9 / 45.0 - s**3 / 6.0))


@cites("thesis", "israelachvili_2011")
def particle_half_space_force(separation, epsilon, sigma, areal_density, layer_spacing):
    """Force -dU/dz of the 9-3 particle-half-space potential (positive = repulsive).

    .. math:: F_{9-3}(z) = \\frac{4\\pi\\varepsilon N_1}{l_z}\\left(\\frac{\\sigma^{12}}{5z^{10}} - \\frac{\\sigma^6}{2z^4}\\right)

    Zero at z = (2/5)^(1/6) sigma. Parameters as :func:`particle_half_space_potential`;
    returns [N].
    """
    z, epsilon, sigma, n1, lz = _half_space_inputs(separation, epsilon, sigma, areal_density, layer_spacing)
    s = sigma / z
    return _result(4.0 * np.pi * epsilon * n1 * sigma**2 / lz * (s**10 / 5.0 - s**4 / 2.0))


@cites("thesis", "israelachvili_2011")
def chain_half_space_potential(separation, epsilon, sigma, areal_density, layer_spacing):
    """Potential of a vertical chain of atoms (spacing l_z) whose end is z from a half-space.

    The 9-3 form summed along the chain (thesis 3.3.5, [1]_):

    .. math:: U_{8-2}(z) = \\frac{4\\pi\\varepsilon N_1}{l_z^2}\\left(\\frac{\\sigma^{12}}{360z^8} - \\frac{\\sigma^6}{12z^2}\\right)
              = \\frac{\\pi\\varepsilon N_1\\sigma^4}{3l_z^2}\\left(\\frac{\\sigma^8}{30z^8} - \\frac{\\sigma^2}{z^2}\\right)

    N1 times this is the interaction energy per unit area of two half-spaces a gap z apart.

    Parameters
    ----------
    separation : float or array_like
        Distance z of the chain end from the surface [m], > 0.
    epsilon, sigma, areal_density : as in :func:`particle_half_space_potential` ([J], [m], N1 [1/m²])
    layer_spacing : float
        Distance l_z between atoms along the chain and between layers [m].

    Returns
    -------
    float or ndarray
        Potential energy of the chain [J].
    """
    z, epsilon, sigma, n1, lz = _half_space_inputs(separation, epsilon, sigma, areal_density, layer_spacing)
    s = sigma / z
    return _result(4.0 * np.pi * epsilon * n1 * sigma**4 / lz**2 * (s**8 / 360.0 - s**2 / 12.0))


@cites("thesis", "israelachvili_2011")
def chain_half_space_force(separation, epsilon, sigma, areal_density, layer_spacing):
    """Force -dU/dz of the 8-2 chain-half-space potential (positive = repulsive).

    .. math:: F_{8-2}(z) = \\frac{2\\pi\\varepsilon N_1\\sigma^3}{3l_z^2}\\left(\\frac{2}{15}\\frac{\\sigma^9}{z^9} - \\frac{\\sigma^3}{z^3}\\right)

    as printed in thesis 3.3.5 [1]_; zero at z = (2/15)^(1/6) sigma. N1 times this is the
    normal stress between two half-spaces a gap z apart. Parameters as
    :func:`chain_half_space_potential`; returns [N].
    """
    z, epsilon, sigma, n1, lz = _half_space_inputs(separation, epsilon, sigma, areal_density, layer_spacing)
    s = sigma / z
    return _result(2.0 * np.pi * epsilon * n1 * sigma**3 / (3.0 * lz**2) * (2.0 / 15.0 * s**9 - s**3))


def equilibrium_distance(sigma, form: str = "12-6"):
    """Separation at which the force of a potential form vanishes.

    Parameters
    ----------
    sigma : float or array_like
        Pair zero-potential distance [m].
    form : {"12-6", "10-4", "9-3", "8-2"}
        Pair, particle-monolayer, particle-half-space or chain-half-space potential.

    Returns
    -------
    float or ndarray
        Equilibrium distance [m]: 2^(1/6) sigma, sigma, (2/5)^(1/6) sigma or (2/15)^(1/6) sigma.

    Notes
    -----
    Thesis 3.3.5 derives rho = (2/15)^(1/6) sigma for the 8-2 form but then evaluates
    its modulus with the pair value rho = 2^(1/6) sigma; memstribo returns each form's own
    equilibrium distance.
    """
    sigma = as_array(sigma, "sigma", "m", positive=True)
    if form not in EQUILIBRIUM_FACTORS:
        raise InputError(f"form must be one of {', '.join(repr(f) for f in EQUILIBRIUM_FACTORS)}, got {form!r}.")
    return _result(EQUILIBRIUM_FACTORS[form] * sigma)
