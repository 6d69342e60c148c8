"""Adhesion of silicon asperities: contact modulus, work of adhesion, Maugis-Dugdale law,
bilinear elastic-perfectly rigid law, no-slip coefficient and pull-off forces.

Thesis sections 3.3.3 and 3.5 ([1]_); decisions in docs/model.md §2-3 and
docs/nanoscale-physics.md. All quantities SI.

References
----------
.. [1] N. S. T. Almuramady, 'Dry friction between rough surfaces of silicon and
   functionalized gear MEMS', PhD thesis, Cardiff University.
.. [2] D. Maugis, 'Adhesion of spheres: the JKR-DMT transition using a Dugdale model',
   J. Colloid Interface Sci. 150 (1992) 243-269. :doi:`10.1016/0021-9797(92)90285-T`
.. [3] F. M. Borodich, 'The Hertz-type and adhesive contact problems for depth-sensing
   indentation', Adv. Appl. Mech. 47 (2014) 225-366. :doi:`10.1016/B978-0-12-800130-1.00003-5`
.. [4] K. Kendall, 'The adhesion and surface energy of elastic solids', J. Phys. D 4
   (1971) 1186. :doi:`10.1088/0022-3727/4/8/320`
.. [5] J. N. Israelachvili, Intermolecular and Surface Forces, 3rd ed., Academic Press, 2011.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.materials.pair import contact_modulus_of, no_slip_coefficient, work_of_adhesion
from memstribo.references import cites

__all__ = [
    "lennard_jones_surface_stress",
    "maugis_stress",
    "maugis_range",
    "bilinear_stress",
    "bilinear_strain",
    "pull_off_force",
    "total_adhesion_force",
    "NanoscaleConstants",
    "nanoscale_constants",
]


def _result(value):
    return float(value) if np.ndim(value) == 0 else value


@cites("maugis_1992")
def lennard_jones_surface_stress(gap, work_of_adhesion, equilibrium_distance):
    """Normal stress between two flat half-spaces interacting by a Lennard-Jones law.

    The integrated (9-3) surface law used by Maugis ([2]_) for the Dugdale approximation:

    .. math:: \\sigma(h) = \\frac{8w}{3z_0}\\left[\\left(\\frac{z_0}{h}\\right)^9 - \\left(\\frac{z_0}{h}\\right)^3\\right]

    positive = repulsive; zero at h = z0; its integral from z0 to infinity is -w; its
    maximum attraction 16 w / (9 sqrt(3) z0) is at h = 3^(1/6) z0.

    Parameters
    ----------
    gap : float or array_like
        Separation h of the surfaces [m], > 0.
    work_of_adhesion : float
        w [J/m²].
    equilibrium_distance : float
        Equilibrium separation z0 [m] (memstribo takes the cut-off distance D0).

    Returns
    -------
    float or ndarray
        Stress [Pa].
    """
    h = as_array(gap, "gap", "m", positive=True)
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True)
    z0 = as_array(equilibrium_distance, "equilibrium_distance", "m", positive=True)
    s3 = (z0 / h) ** 3
    return _result(8.0 * w / (3.0 * z0) * (s3**3 - s3))


@cites("thesis", "maugis_1992")
def maugis_stress(work_of_adhesion, equilibrium_distance):
    """Dugdale stress sigma0 of the Maugis approximation ([2]_; thesis 3.3.3, [1]_).

    The constant attractive stress equals the maximum attractive stress of the
    Lennard-Jones surface law (:func:`lennard_jones_surface_stress`) with the same work of
    adhesion:

    .. math:: \\sigma_0 = \\frac{16\\,w}{9\\sqrt{3}\\,z_0}

    Parameters
    ----------
    work_of_adhesion : float or array_like
        w [J/m²].
    equilibrium_distance : float or array_like
        Equilibrium separation z0 [m] (memstribo: the cut-off distance D0 = 2.56 Å).

    Returns
    -------
    float or ndarray
        sigma0 [Pa] (1.78 GPa for silicon with w = 0.445 J/m²).
    """
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True)
    z0 = as_array(equilibrium_distance, "equilibrium_distance", "m", positive=True)
    return _result(16.0 * w / (9.0 * math.sqrt(3.0) * z0))


@cites("thesis", "maugis_1992")
def maugis_range(work_of_adhesion, maugis_stress):
    """Range h0 of the Dugdale stress, from w = sigma0 h0, Eq. (3-17) in [1]_.

    Parameters
    ----------
    work_of_adhesion : float or array_like
        w [J/m²].
    maugis_stress : float or array_like
        sigma0 [Pa].

    Returns
    -------
    float or ndarray
        h0 [m]; with :func:`maugis_stress` it is 9 sqrt(3)/16 z0 = 0.974 z0.
    """
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True)
    s0 = as_array(maugis_stress, "maugis_stress", "Pa", positive=True)
    return _result(w / s0)


def _threshold(threshold_strain):
    eps = as_array(threshold_strain, "threshold_strain", "", positive=True)
    if np.any(eps > 1.0):
        raise InputError(f"threshold_strain must lie in (0, 1], got {threshold_strain!r}.")
    return eps


@cites("thesis", "borodich_savencu_2017")
def bilinear_stress(strain, modulus, threshold_strain):
    """Compressive stress of a nano-asperity below its rigid threshold (Figure 3-13 in [1]_).

    Elastic-perfectly rigid law: Hooke's law sigma = E e for 0 <= e <= e_th; at
    e = e_th the asperity turns rigid, so any further load passes to the next scale and
    larger strains cannot occur. Compression is positive.

    Parameters
    ----------
    strain : float or array_like
        Compressive strain e [-], 0 <= e <= threshold_strain.
    modulus : float or array_like
        Modulus E of the asperity [Pa] (the contact modulus for the atomic and adhesive
        subscales, MODEL §4).
    threshold_strain : float
        e_th [-] (0.30 for silicon nano-asperities).

    Returns
    -------
    float or ndarray
        Stress [Pa]; E e_th at the threshold (the least stress of the rigid state).

    Raises
    ------
    InputError
        If a strain is negative (no tension in a unilateral contact) or exceeds the threshold.
    See Also
    --------
    bilinear_strain : the strain of a given stress (defined for every stress >= 0).
    """
    e = as_array(strain, "strain", "", nonnegative=True)
    modulus = as_array(modulus, "modulus", "Pa", positive=True)
    eth = _threshold(threshold_strain)
    if np.any(e > eth * (1.0 + 1e-12)):
        raise InputError(
            f"strain exceeds threshold_strain = {float(np.max(eth)):g}: an elastic-perfectly rigid asperity "
            "cannot strain past its threshold (use bilinear_strain for a given stress)."
        )
    return _result(modulus * np.minimum(e, eth))


@cites("thesis", "borodich_savencu_2017")
def bilinear_strain(stress, modulus, threshold_strain):
    """Compressive strain of a nano-asperity under a stress, elastic-perfectly rigid law.

    e = min(sigma / E, e_th) (Figure 3-13 in [1]_): Hooke's law up to the threshold strain,
    then rigid. Compression is positive.

    Parameters
    ----------
    stress : float or array_like
        Compressive stress [Pa], >= 0.
    modulus : float or array_like
        Modulus E [Pa].
    threshold_strain : float
        e_th [-].

    Returns
    -------
    float or ndarray
        Strain [-].
    """
    s = as_array(stress, "stress", "Pa", nonnegative=True)
    modulus = as_array(modulus, "modulus", "Pa", positive=True)
    eth = _threshold(threshold_strain)
    return _result(np.minimum(s / modulus, eth))


@cites("thesis", "borodich_2014", "kendall_1971")
def pull_off_force(work_of_adhesion, contact_modulus, no_slip_coefficient, half_width):
    """Pull-off force of one block (no-slip Boussinesq-Kendall), Eq. (3-32) in [1]_.

    .. math:: F_{adh,1} = \\sqrt{8\\pi w E^* C_{NS} a^3}

    Parameters
    ----------
    work_of_adhesion : float or array_like
        w [J/m²].
    contact_modulus : float or array_like
        E* [Pa].
    no_slip_coefficient : float or array_like
        C_NS [-] (from :func:`no_slip_coefficient`), > 0.
    half_width : float or array_like
        Contact radius a [m]: half the block width (97.5 nm in thesis 3.5).

    Returns
    -------
    float or ndarray
        Pull-off force [N].

    Examples
    --------
    >>> print(f"{pull_off_force(0.4452, 85.0e9, 1.0440, 97.5e-9):.3e}")
    3.034e-05
    """
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True)
    e_star = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    c_ns = as_array(no_slip_coefficient, "no_slip_coefficient", "", positive=True)
    a = as_array(half_width, "half_width", "m", positive=True)
    return _result(np.sqrt(8.0 * np.pi * w * e_star * c_ns * a**3))


@cites("thesis")
def total_adhesion_force(gap, adhesive_range, pull_off_force, axis=-1):
    """Total adhesion force of the blocks inside the adhesive layer, Eq. (3-31) in [1]_.

    F_adh = sum of F_adh,1 over the blocks whose gap to the counter surface is at most
    the adhesive layer thickness (those blocks have "jumped into contact").

    Parameters
    ----------
    gap : array_like
        Gap of each block to the counter surface [m] (<= 0: in contact); blocks along
        ``axis``, any leading batch dimensions (e.g. sliding steps).
    adhesive_range : float
        Thickness of the adhesive layer [m], >= 0 (thesis 3.5: the adhesive-block height;
        the Maugis range h0 is the physical alternative).
    pull_off_force : float or array_like
        Pull-off force of one block [N], >= 0 (broadcast against ``gap``).
    axis : int
        Axis of ``gap`` that runs over the blocks.

    Returns
    -------
    float or ndarray
        F_adh [N] with ``axis`` summed out.
    """
    gap = as_array(gap, "gap", "m")
    h = as_array(adhesive_range, "adhesive_range", "m", nonnegative=True)
    force = as_array(pull_off_force, "pull_off_force", "N", nonnegative=True)
    inside = gap <= h
    return _result(np.sum(np.where(inside, force, 0.0), axis=axis))


@dataclass(frozen=True)
class NanoscaleConstants:
    """The nanoscale constants of a parameter set (what ``memstribo constants`` prints).

    Attributes
    ----------
    sigma : float
        LJ zero-potential distance [m] (3-16).
    epsilon : float
        LJ well depth [J] (3-19 to 3-23).
    contact_modulus : float
        E* [Pa].
    work_of_adhesion : float
        w12 [J/m²] ((3-34), or the parameter set's override).
    work_of_adhesion_source : str
        "formula (3-34)" or "parameter".
    no_slip_coefficient : float
        C_NS [-] (3-33).
    pull_off_force_block : float
        F_adh,1 of one block with a = adhesive_width / 2 [N] (3-32).
    half_width : float
        The a used [m].
    maugis_stress : float
        Dugdale stress sigma0 [Pa].
    maugis_range : float
        h0 = w / sigma0 [m] (3-17).
    bond_energy_chemical : float
        U_chem [J].
    bond_energy_vdw : float
        U_vdW [J].
    bond_length : float
        D_chem [m].
    """

    sigma: float
    epsilon: float
    contact_modulus: float
    work_of_adhesion: float
    work_of_adhesion_source: str
    no_slip_coefficient: float
    pull_off_force_block: float
    half_width: float
    maugis_stress: float
    maugis_range: float
    bond_energy_chemical: float
    bond_energy_vdw: float
    bond_length: float


def nanoscale_constants(params: Mapping) -> NanoscaleConstants:
    """Compute the nanoscale constants from a parameter set.

    Parameters
    ----------
    params : Mapping
        A :class:`memstribo.parameters.Parameters` (or dict) with ``youngs_modulus``,
        ``poisson_ratio``, ``counter_youngs_modulus``, ``counter_poisson_ratio``,
        ``bond_length``, ``bond_energy``, ``vdw_bond_energy``, ``hamaker_constant``,
        ``cutoff_distance``, ``work_of_adhesion`` (None: derive) and ``adhesive_width``.

    Returns
    -------
    NanoscaleConstants
    """
    from memstribo.physics import potentials
    from memstribo.physics.vdw_energy import vdw_bond_energy_of

    e_star = contact_modulus_of(params)
    if params.get("work_of_adhesion") is None:
        w = work_of_adhesion(params["hamaker_constant"], params["cutoff_distance"])
        w_source = "formula (3-34): A / (12 pi D0^2)"
    else:
        w = float(as_array(params["work_of_adhesion"], "work_of_adhesion", "J/m^2", positive=True))
        w_source = "parameter work_of_adhesion"
    c_ns = no_slip_coefficient(params["poisson_ratio"])
    a = 0.5 * float(params["adhesive_width"])
    s0 = maugis_stress(w, params["cutoff_distance"])
    return NanoscaleConstants(
        sigma=potentials.lennard_jones_sigma(params["bond_length"]),
        epsilon=potentials.lennard_jones_epsilon(params["youngs_modulus"], params["bond_length"]),
        contact_modulus=e_star,
        work_of_adhesion=w,
        work_of_adhesion_source=w_source,
        no_slip_coefficient=c_ns,
        pull_off_force_block=pull_off_force(w, e_star, c_ns, a),
        half_width=a,
        maugis_stress=s0,
        maugis_range=maugis_range(w, s0),
        bond_energy_chemical=float(params["bond_energy"]),
        bond_energy_vdw=vdw_bond_energy_of(params),
        bond_length=float(params["bond_length"]),
    )
