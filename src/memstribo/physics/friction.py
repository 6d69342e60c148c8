"""Friction from dissipated energy (thesis 3.3, 3.5; MODEL §5).

Sliding breaks the chemical bonds of the atomic-subscale blocks and the van der Waals bonds
of the adhesive-subscale blocks that touch the counter surface; every time the surfaces
slide by one bond length ``D_chem`` all current bonds break and re-form (3.5). Elastic
interlocking adds the energy of (3-25). The friction force is the dissipated energy per
sliding distance (3-1) and the apparent coefficient of friction divides it by the normal
force plus the adhesion force (3-7), term by term (3-8, 3-9).

Every function is vectorised (numpy broadcasting) and works in SI units.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.physics.potentials import lennard_jones_force, lennard_jones_sigma
from memstribo.references import cites

__all__ = [
    "chemical_bond_count",
    "vdw_bond_count",
    "full_overlap_bond_count",
    "bond_breaking_energy",
    "friction_force",
    "peak_bond_force",
    "friction_coefficient",
    "friction_coefficient_split",
    "adhesion_force",
    "FrictionEstimate",
    "thesis_estimate",
    "estimate_from_parameters",
    "THESIS_3_5_INPUTS",
    "THESIS_3_5_COUNTS",
]


def _result(value):
    value = np.asarray(value)
    return float(value) if value.ndim == 0 else value


@cites("thesis")
def chemical_bond_count(atomic_width, chemical_length, bond_length):
    """Chemical bonds held by one atomic block, ``N_chem = w_at L_chem / D_chem^2``, Eq. (3-10) in [1]_.

    Parameters
    ----------
    atomic_width : numeric
        Width ``w_at`` of the square atomic block, across the sliding direction [m].
    chemical_length : numeric
        Length ``L_chem`` of the chemically interacting part, along the sliding direction [m].
    bond_length : numeric
        Bond length ``D_chem`` (one bond per ``D_chem^2`` of contact) [m].

    Returns
    -------
    numeric
        Number of bonds [-] (not rounded).

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, section 3.3.1.

    Examples
    --------
    >>> round(chemical_bond_count(19.5e-9, 19.5e-9, 2.35e-10), 1)  # fully overlapped block
    6885.5
    """
    w = as_array(atomic_width, "atomic_width", "m", nonnegative=True)
    length = as_array(chemical_length, "chemical_length", "m", nonnegative=True)
    d = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(w * length / d**2)


@cites("thesis")
def vdw_bond_count(adhesive_width, vdw_length, bond_length, site_density=None):
    """van der Waals bonds held by one adhesive block, ``N_vdW = w_adh L_vdW / D_chem^2``, Eq. (3-12) in [1]_.

    With ``site_density`` n_site (MODEL 7h): ``N_vdW = w_adh L_vdW n_site``; the thesis's 1 / D_chem^2 is its default.

    Parameters
    ----------
    adhesive_width : numeric
        Width ``w_adh`` of the square adhesive block [m].
    vdw_length : numeric
        Length ``L_vdW`` of the block inside the adhesive layer, along the sliding direction [m].
    bond_length : numeric
        ``D_chem`` [m]: the vdW bonds have the atomic density of the chemical ones (3.5).
    site_density : numeric, optional
        Areal density of vdW sites [1/m^2], > 0; default ``1 / D_chem^2``.

    Returns
    -------
    numeric
        Number of bonds [-].
    """
    w = as_array(adhesive_width, "adhesive_width", "m", nonnegative=True)
    length = as_array(vdw_length, "vdw_length", "m", nonnegative=True)
    d = as_array(bond_length, "bond_length", "m", positive=True)
    density = 1.0 / d**2 if site_density is None else as_array(site_density, "site_density", "1/m^2", positive=True)
    return _result(w * length * density)


@cites("thesis")
def full_overlap_bond_count(width, bond_length):
    """Bonds of a fully overlapped square block, ``N = (w / D_chem)^2`` (3.5 in [1]_).

    This is (3-10) or (3-12) with ``L = w``. The thesis prints 7388.6 for
    ``w = 19.5 nm``; ``(19.5 nm / 2.35 Å)^2`` is 6885.5. For 195 nm its 688546.8 is right.

    Parameters
    ----------
    width : numeric
        Block width [m].
    bond_length : numeric
        ``D_chem`` [m].

    Returns
    -------
    numeric
        Number of bonds [-].
    """
    return chemical_bond_count(width, width, bond_length)


@cites("thesis")
def bond_breaking_energy(bond_count, bond_energy, distance, bond_length):
    """Energy dissipated by breaking bonds while sliding, ``U = N U_b x / D_chem`` (3.5 in [1]_).

    All current bonds break and re-form every time the surfaces slide by one bond length.

    Parameters
    ----------
    bond_count : numeric
        Current number of bonds ``N`` (summed over the blocks in contact) [-].
    bond_energy : numeric
        Energy of one bond ``U_chem`` or ``U_vdW`` [J].
    distance : numeric
        Sliding distance ``x`` [m], >= 0.
    bond_length : numeric
        ``D_chem`` [m].

    Returns
    -------
    numeric
        Dissipated energy [J], >= 0.

    Notes
    -----
    Eqs. (3-2), (3-3), (3-11), (3-13) give the energy of one rupture of all bonds,
    ``N U``; 3.5 multiplies it by the number of ruptures ``x / D_chem``.
    """
    n = as_array(bond_count, "bond_count", "-", nonnegative=True)
    u = as_array(bond_energy, "bond_energy", "J", nonnegative=True)
    x = as_array(distance, "distance", "m", nonnegative=True)
    d = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(n * u * x / d)


@cites("thesis")
def friction_force(dissipated_energy, distance):
    """Friction force from the dissipated energy, ``F_f = U_diss / x``, Eq. (3-1) in [1]_.

    Parameters
    ----------
    dissipated_energy : numeric
        Energy dissipated over the sliding distance [J], >= 0.
    distance : numeric
        Sliding distance ``x`` [m], > 0.

    Returns
    -------
    numeric
        Friction force [N].
    """
    u = as_array(dissipated_energy, "dissipated_energy", "J", nonnegative=True)
    x = as_array(distance, "distance", "m", positive=True)
    return _result(u / x)


@cites("thesis", "model")
def peak_bond_force(bond_count, bond_energy, bond_length):
    """Peak force of a bond population pulled along the bonds' axes: N times the largest slope of the bond law [N].

    A bond is the Lennard-Jones 12-6 pair (3-14) with well depth ``U`` (its energy) and its
    equilibrium distance at the bond length, sigma = D_chem 2^(-1/6) (3-16). Pulled along its
    axis from rest it resists with -dU/dr, whose largest value lies at
    r* = (26/7)^(1/6) sigma (the inflection point of U):

        F_peak = N |F(r*)| = N (24 U / sigma) (7/26)^(7/6) (12/26) = 2.6899 N U / D_chem,

    against the kinetic force N U / D_chem of the same bonds (3-1, 3.5). Version 3 started the
    gear with this peak; a bond formed across the interface is sheared sideways at its gap, not
    pulled along its axis, and its lateral peak is 1.2687 U / D
    (:func:`memstribo.physics.static_friction.lennard_jones_lateral_peak`), which the start-up
    verdict uses since version 4 (MODEL 7f). Kept as the axial strength of a bond.

    Parameters
    ----------
    bond_count : numeric
        Bonds N formed at rest [-], >= 0.
    bond_energy : numeric
        Energy of one bond U_chem or U_vdW [J], >= 0 (the LJ well depth).
    bond_length : numeric
        D_chem [m], > 0 (the LJ equilibrium distance).

    Returns
    -------
    numeric
        Peak lateral force [N], >= 0.

    Examples
    --------
    >>> round(peak_bond_force(1.0, 1.0, 1.0), 4)
    2.6899
    """
    n = as_array(bond_count, "bond_count", "-", nonnegative=True)
    u = as_array(bond_energy, "bond_energy", "J", nonnegative=True)
    d = as_array(bond_length, "bond_length", "m", positive=True)
    sigma = lennard_jones_sigma(d)
    inflection = (26.0 / 7.0) ** (1.0 / 6.0) * sigma
    per_unit_energy = np.abs(lennard_jones_force(inflection, 1.0, sigma))  # |F(r*)| per joule of well depth [1/m]
    return _result(n * u * per_unit_energy)


@cites("thesis")
def friction_coefficient(dissipated_energy, normal_force, adhesion_force, distance):
    """Apparent coefficient of friction ``mu = U_diss / ((F_N + F_adh) x)``, Eq. (3-7) in [1]_.

    Parameters
    ----------
    dissipated_energy : numeric
        Energy dissipated over ``distance`` [J], >= 0.
    normal_force : numeric
        Normal (external) force ``F_N`` [N], >= 0.
    adhesion_force : numeric
        Adhesion force ``F_adh`` [N], >= 0.
    distance : numeric
        Sliding distance ``x`` [m], > 0.

    Returns
    -------
    numeric
        ``mu`` [-]. Where ``F_N + F_adh = 0`` there is no contact: ``mu`` is 0 if nothing is
        dissipated, and an :class:`InputError` is raised otherwise.
    """
    u = as_array(dissipated_energy, "dissipated_energy", "J", nonnegative=True)
    fn = as_array(normal_force, "normal_force", "N", nonnegative=True)
    fa = as_array(adhesion_force, "adhesion_force", "N", nonnegative=True)
    x = as_array(distance, "distance", "m", positive=True)
    pressing = fn + fa
    if np.any((pressing == 0) & (u > 0)):
        raise InputError("energy is dissipated where the normal force plus the adhesion force is zero: "
                         "the coefficient of friction (3-7) is undefined there.")
    safe = np.where(pressing > 0, pressing, 1.0)
    return _result(np.where(pressing > 0, u / (safe * x), 0.0))


@cites("thesis")
def friction_coefficient_split(energy_chemical, energy_vdw, energy_elastic, normal_force, adhesion_force,
                               distance):
    """Split of the coefficient of friction by mechanism, Eqs. (3-8), (3-9) in [1]_.

    Parameters
    ----------
    energy_chemical, energy_vdw, energy_elastic : numeric
        Energies dissipated by breaking chemical bonds, vdW bonds and by elastic
        interlocking over ``distance`` [J].
    normal_force, adhesion_force : numeric
        ``F_N`` and ``F_adh`` [N].
    distance : numeric
        Sliding distance [m].

    Returns
    -------
    tuple of numeric
        ``(mu_chem, mu_vdW, mu_elastic)`` [-]; their sum is ``mu`` of (3-7).
    """
    return tuple(friction_coefficient(u, normal_force, adhesion_force, distance)
                 for u in (energy_chemical, energy_vdw, energy_elastic))


@cites("thesis")
def adhesion_force(pull_off_forces, axis=-1):
    """Adhesion force of the blocks inside the adhesive layer, ``F_adh = sum F_adh,1``, Eq. (3-31) in [1]_.

    Parameters
    ----------
    pull_off_forces : array_like
        Pull-off force (3-32) of each block [N] (zero for a block outside the layer);
        blocks along ``axis``.
    axis : int
        Axis over the blocks.

    Returns
    -------
    numeric
        ``F_adh`` [N].

    See Also
    --------
    memstribo.physics.adhesion.pull_off_force : (3-32) for one block.
    """
    f = as_array(pull_off_forces, "pull_off_forces", "N", nonnegative=True)
    return _result(f.sum(axis=axis))


# --------------------------------------------------------------------------------------
# the estimate of thesis 3.5
# --------------------------------------------------------------------------------------

THESIS_3_5_INPUTS = {
    "blocks": 9,
    "chemical_energy_per_block": 4e-15,
    "vdw_energy_per_block": 3.73e-15,
    "adhesion_force": 3.386e-4,
    "load": 25e-6,
    "bond_length": 2.35e-10,
}
"""The intermediate values printed in thesis 3.5: ``n``, ``N_chem U_chem`` [J], ``N_vdW U_vdW`` [J],
``F_adh`` [N], ``F_ext`` [N], ``D_chem`` [m]."""

THESIS_3_5_COUNTS = {
    "blocks": 9,
    "chemical_energy_per_block": 7388.6 * 5.42e-19,
    "vdw_energy_per_block": 688546.8 * 5.42e-21,
    "adhesion_force": 3.386e-4,
    "load": 25e-6,
    "bond_length": 2.35e-10,
}
"""As :data:`THESIS_3_5_INPUTS` but with the energies unrounded: the printed bond counts 7388.6 and
688546.8 times the printed bond energies 5.42e-19 J and 5.42e-21 J (this gives MODEL §5's 0.815)."""


@dataclass(frozen=True)
class FrictionEstimate:
    """The fully-overlapped estimate of the coefficient of friction (thesis 3.5).

    Attributes
    ----------
    blocks : int
        ``n``, blocks in contact [-].
    chemical_bonds, vdw_bonds : float or None
        ``N_chem`` per atomic block and ``N_vdW`` per adhesive block [-] (None when the
        energies were given directly).
    chemical_energy_per_block, vdw_energy_per_block : float
        ``N_chem U_chem`` and ``N_vdW U_vdW`` [J].
    pull_off_force_block : float or None
        ``F_adh,1`` (3-32) [N] (None when ``F_adh`` was given directly).
    adhesion_force : float
        ``F_adh = n F_adh,1`` (3-31) [N].
    load : float
        ``F_ext`` [N].
    friction_force : float
        ``F_f = n (N_chem U_chem + N_vdW U_vdW) / D_chem`` [N].
    cof, cof_chemical, cof_vdw : float
        Apparent ``mu`` (3-30) and its chemical and vdW parts [-] (no elastic part: the blocks
        are not displaced vertically).
    """

    blocks: int
    chemical_bonds: float | None
    vdw_bonds: float | None
    chemical_energy_per_block: float
    vdw_energy_per_block: float
    pull_off_force_block: float | None
    adhesion_force: float
    load: float
    friction_force: float
    cof: float
    cof_chemical: float
    cof_vdw: float


@cites("thesis")
def thesis_estimate(blocks, chemical_energy_per_block, vdw_energy_per_block, adhesion_force, load,
                    bond_length, *, chemical_bonds=None, vdw_bonds=None, pull_off_force_block=None
                    ) -> FrictionEstimate:
    """The estimate of 3.5 in [1]_: ``mu = n (N_chem U_chem + N_vdW U_vdW) / ((F_ext + F_adh) D_chem)``.

    Parameters
    ----------
    blocks : int
        ``n`` [-], > 0.
    chemical_energy_per_block, vdw_energy_per_block : float
        ``N_chem U_chem`` and ``N_vdW U_vdW`` [J].
    adhesion_force : float
        ``F_adh`` [N].
    load : float
        ``F_ext`` [N], > 0.
    bond_length : float
        ``D_chem`` [m].

    Returns
    -------
    FrictionEstimate

    Examples
    --------
    >>> round(thesis_estimate(**THESIS_3_5_INPUTS).cof, 4)  # the thesis prints 0.82
    0.8142
    """
    if int(blocks) != blocks or blocks < 1:
        raise InputError(f"blocks must be a positive integer, got {blocks!r}.")
    as_array(load, "load", "N", positive=True)
    per_distance_chem = bond_breaking_energy(blocks, chemical_energy_per_block, 1.0, bond_length)
    per_distance_vdw = bond_breaking_energy(blocks, vdw_energy_per_block, 1.0, bond_length)
    mu_chem, mu_vdw = (friction_coefficient(u, load, adhesion_force, 1.0)
                       for u in (per_distance_chem, per_distance_vdw))
    return FrictionEstimate(
        blocks=int(blocks), chemical_bonds=chemical_bonds, vdw_bonds=vdw_bonds,
        chemical_energy_per_block=float(chemical_energy_per_block),
        vdw_energy_per_block=float(vdw_energy_per_block), pull_off_force_block=pull_off_force_block,
        adhesion_force=float(adhesion_force), load=float(load),
        friction_force=float(friction_force(per_distance_chem + per_distance_vdw, 1.0)),
        cof=float(mu_chem + mu_vdw), cof_chemical=float(mu_chem), cof_vdw=float(mu_vdw),
    )


@cites("thesis", "model")
def estimate_from_parameters(params, blocks: int = 9, load: float | None = None) -> FrictionEstimate:
    """The 3.5 estimate from first principles, with the constants of a parameter set.

    ``N_chem = (w_at / D_chem)^2``, ``N_vdW = w_adh^2 n_site`` (fully overlapped blocks; n_site = 1 / D_chem^2
    unless ``vdw_site_density`` is set), ``U_chem`` from the set, ``U_vdW`` by the set's ``vdw_energy_rule``
    (:func:`memstribo.physics.vdw_energy.vdw_bond_energy_of`), ``F_adh,1`` from (3-32) with ``a = w_adh / 2``, ``w``
    from (3-34) (0.445 J/m^2 for silicon, not the thesis's printed 1.31 J/m^2), and, as in
    the thesis, ``n`` counting both the chemical and the vdW terms and the pull-off force.

    Parameters
    ----------
    params : Mapping
        Parameter set (:func:`memstribo.parameters.get_parameter_values`).
    blocks : int
        ``n`` (9 in 3.5).
    load : float, optional
        ``F_ext`` [N]; default ``params["normal_load"]``.

    Returns
    -------
    FrictionEstimate
    """
    from memstribo.physics.adhesion import nanoscale_constants
    from memstribo.physics.vdw_energy import vdw_site_density_of

    constants = nanoscale_constants(params)
    d = float(params["bond_length"])
    n_chem = full_overlap_bond_count(params["atomic_width"], d)
    n_vdw = vdw_bond_count(params["adhesive_width"], params["adhesive_width"], d, vdw_site_density_of(params))
    load = float(params["normal_load"] if load is None else load)
    return thesis_estimate(
        blocks, n_chem * params["bond_energy"], n_vdw * constants.bond_energy_vdw,
        blocks * constants.pull_off_force_block, load, d,
        chemical_bonds=n_chem, vdw_bonds=n_vdw, pull_off_force_block=constants.pull_off_force_block,
    )
