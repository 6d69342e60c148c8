"""One van der Waals interaction (MODEL 7h, issue 38): the friction energy of a vdW site from the adhesion it holds.

The thesis gives the vdW bonds of a sliding contact an energy of their own, U_vdW = U_chem / 100 (3.5), while the
work of adhesion w12 = A / (12 pi D0^2) (3-34) of the same interaction sets the adhesion force; the two never met.
Here a site's friction energy is the part of the adhesion energy it holds that is dissipated when it breaks and
re-forms while sliding, the adhesion hysteresis:

.. math:: U_{vdW} = \\varphi \\, w_{12} \\, A_{site}, \\qquad A_{site} = 1 / n_{site}, \\qquad 0 < \\varphi \\le 1.

Friction follows the adhesion hysteresis, not the adhesion itself: Yoshizawa, Chen and Israelachvili ([2]_) found
the friction of monolayer-coated surfaces correlated with the energy dissipated in a loading-unloading cycle, which
ranges from nearly none to a large part of the adhesion energy with the monolayers' phase state ([3]_, 9.8 and
9.11). With N = n_site A bonds in an area A, each renewed once per bond length D_chem of sliding (3.5), the vdW
friction stress is tau_vdW = n_site U_vdW / D_chem = phi w12 / D_chem: the site density cancels, and the vdW friction
and the adhesion force share w12. The thesis's U_chem / 100 stays available as the rule ``thesis``.

References
----------
.. [1] N. S. T. Almuramady, 'Dry friction between rough surfaces of silicon and functionalized gear MEMS', PhD
   thesis, Cardiff University.
.. [2] H. Yoshizawa, Y.-L. Chen, J. Israelachvili, 'Recent advances in molecular level understanding of adhesion,
   friction and lubrication', Wear 168 (1993) 161-166. :doi:`10.1016/0043-1648(93)90212-5`
.. [3] J. N. Israelachvili, A. D. Berman, 'Surface forces and microrheology of molecularly thin liquid films', in
   B. Bhushan (ed.), Handbook of Micro/Nanotribology, 2nd ed., CRC Press, 1999, ch. 9.
.. [4] C. Kittel, Introduction to Solid State Physics, 8th ed., Wiley, 2005 (the diamond structure, ch. 1).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["VDW_ENERGY_RULES", "hysteresis_site_energy", "surface_atom_density", "vdw_site_density_of",
           "vdw_bond_energy_of"]

#: the rules for the friction energy of a vdW site (parameter ``vdw_energy_rule``)
VDW_ENERGY_RULES = ("hysteresis", "thesis")

#: atoms per a^2 on the low-index faces of the diamond lattice (conventional cubic cell of side a)
_ATOMS_PER_A2 = {"100": 2.0, "110": 2.0 * math.sqrt(2.0), "111": 4.0 / math.sqrt(3.0)}


def _result(value):
    return float(value) if np.ndim(value) == 0 else value


@cites("yoshizawa_1993", "israelachvili_berman_1999", "model")
def hysteresis_site_energy(dissipated_fraction, work_of_adhesion, site_density):
    """Friction energy of one vdW site, U_vdW = phi w12 / n_site [J] (MODEL 7h; adhesion hysteresis, [2]_, [3]_).

    Parameters
    ----------
    dissipated_fraction : float or array_like
        phi [-], the dissipated fraction of the adhesion energy a site holds, 0 < phi <= 1.
    work_of_adhesion : float or array_like
        w12 [J/m^2], > 0 ((3-34): A / (12 pi D0^2)).
    site_density : float or array_like
        n_site [1/m^2], > 0: the site's area is A_site = 1 / n_site.

    Returns
    -------
    float or ndarray
        U_vdW [J].

    Raises
    ------
    InputError
        A fraction outside (0, 1], a negative or zero work of adhesion or site density.

    Examples
    --------
    >>> round(hysteresis_site_energy(1.0, 0.0810, 1.0 / 2.35e-10**2) * 1e21, 3)  # Lifshitz w12, thesis density
    4.473
    """
    phi = as_array(dissipated_fraction, "dissipated_fraction", "", positive=True)
    if np.any(phi > 1.0):
        raise InputError(f"dissipated_fraction must lie in (0, 1] (a fraction of the adhesion energy), got "
                         f"{float(np.max(phi)):g}.")
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True)
    n = as_array(site_density, "site_density", "1/m^2", positive=True)
    return _result(phi * w / n)


@cites("kittel_2005")
def surface_atom_density(lattice_constant, plane: str = "100"):
    """Atoms per unit area of a bulk-terminated low-index face of the diamond lattice [1/m^2] ([4]_).

    (100): 2 / a^2; (110): 2 sqrt(2) / a^2; (111) (one layer of the bilayer): 4 / (sqrt(3) a^2). For silicon
    (a = 0.543 nm): 6.78e18, 9.59e18 and 7.83e18 m^-2, against the thesis's 1 / D_chem^2 = 1.81e19 m^-2.

    Examples
    --------
    >>> round(surface_atom_density(5.43e-10, "100") / 1e18, 2)
    6.78
    """
    if plane not in _ATOMS_PER_A2:
        raise InputError(f"plane must be one of {', '.join(_ATOMS_PER_A2)}, got {plane!r}.")
    a = as_array(lattice_constant, "lattice_constant", "m", positive=True)
    return _result(_ATOMS_PER_A2[plane] / a ** 2)


@cites("thesis", "model")
def vdw_site_density_of(params: Mapping) -> float:
    """The areal density of vdW sites of a parameter set [1/m^2]: ``vdw_site_density``, unset 1 / D_chem^2 (3-12)."""
    density = params.get("vdw_site_density")
    if density is None:
        return 1.0 / float(params["bond_length"]) ** 2
    density = float(density)
    if not density > 0.0 or not math.isfinite(density):
        raise InputError(f"vdw_site_density must be a positive number of sites per m^2, got {density:g}.")
    return density


@cites("thesis", "model")
def vdw_bond_energy_of(params: Mapping) -> float:
    """The friction energy U_vdW of a bare vdW site under the set's ``vdw_energy_rule`` [J].

    ``hysteresis`` (MODEL 7h): :func:`hysteresis_site_energy` with ``vdw_dissipated_fraction``, the work of
    adhesion (``work_of_adhesion``, unset A / (12 pi D0^2), (3-34)) and :func:`vdw_site_density_of`;
    ``thesis``: ``vdw_bond_energy`` as given (U_chem / 100, 3.5). A mapping without the rule is ``thesis``.
    """
    rule = params.get("vdw_energy_rule") or "thesis"
    if rule not in VDW_ENERGY_RULES:
        raise InputError(f"vdw_energy_rule must be one of {', '.join(VDW_ENERGY_RULES)}, got {rule!r}.")
    if rule == "thesis":
        return float(params["vdw_bond_energy"])
    from memstribo.materials.pair import work_of_adhesion

    w = params.get("work_of_adhesion")
    if w is None:
        w = work_of_adhesion(params["hamaker_constant"], params["cutoff_distance"])
    return float(hysteresis_site_energy(params["vdw_dissipated_fraction"], w, vdw_site_density_of(params)))
