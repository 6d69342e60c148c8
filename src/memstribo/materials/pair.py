"""The properties of a pair of materials in contact, each defined once.

E* (the contact modulus, Johnson 1985), Dundurs' beta (the coupling of normal and tangential
contact of dissimilar bodies), the work of adhesion w12 from the Hamaker constant (thesis 3-34) and
the no-slip coefficient C_NS of adhesive contact (thesis 3-33). The physics modules (adhesion,
gear, asperity, contact) and the simulations take these values from here.
"""

from __future__ import annotations

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["contact_modulus", "contact_modulus_of", "dundurs_beta", "work_of_adhesion", "no_slip_coefficient", "check_poisson_ratio"]


def _result(value):
    return float(value) if np.ndim(value) == 0 else value


def check_poisson_ratio(value, name: str = "poisson_ratio") -> np.ndarray:
    """Poisson's ratio as an array, checked to lie in (-1, 0.5] [-]; InputError naming ``name`` otherwise."""
    try:
        nu = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a number in (-1, 0.5], got {value!r}.") from None
    if not np.all(np.isfinite(nu)) or np.any(nu <= -1.0) or np.any(nu > 0.5):
        raise InputError(f"{name} must lie in (-1, 0.5] (isotropic, stable solid), got {value!r}.")
    return nu


@cites("thesis", "johnson_1985")
def contact_modulus(youngs_modulus, poisson_ratio, counter_youngs_modulus=None, counter_poisson_ratio=None):
    """Contact (reduced) modulus E* of two elastic bodies.

    .. math:: \\frac{1}{E^*} = \\frac{1-\\nu_1^2}{E_1} + \\frac{1-\\nu_2^2}{E_2}

    Thesis 3.5 ([1]_) with identical bodies: E* = E / (2 (1 - nu²)) = 85.0 GPa for silicon.

    Parameters
    ----------
    youngs_modulus : float or array_like
        Young's modulus E1 [Pa], > 0.
    poisson_ratio : float or array_like
        Poisson's ratio nu1 [-], in (-1, 0.5].
    counter_youngs_modulus : float, optional
        E2 [Pa]; default: the same as E1.
    counter_poisson_ratio : float, optional
        nu2 [-]; default: the same as nu1.

    Returns
    -------
    float or ndarray
        E* [Pa].

    Examples
    --------
    >>> print(f"{contact_modulus(161e9, 0.23) / 1e9:.1f}")
    85.0
    """
    e1 = as_array(youngs_modulus, "youngs_modulus", "Pa", positive=True)
    nu1 = check_poisson_ratio(poisson_ratio)
    e2 = e1 if counter_youngs_modulus is None else as_array(counter_youngs_modulus, "counter_youngs_modulus", "Pa",
                                                            positive=True)
    nu2 = nu1 if counter_poisson_ratio is None else check_poisson_ratio(counter_poisson_ratio, "counter_poisson_ratio")
    return _result(1.0 / ((1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2))


@cites("johnson_1985")
def dundurs_beta(youngs_modulus, poisson_ratio, counter_youngs_modulus=None, counter_poisson_ratio=None):
    """Dundurs' second parameter beta of two elastic bodies (plane strain).

    Parameters
    ----------
    youngs_modulus, counter_youngs_modulus : float
        E1, E2 [Pa] (the counter body defaults to the first).
    poisson_ratio, counter_poisson_ratio : float
        nu1, nu2 [-].

    Returns
    -------
    float
        beta = 1/2 [(1-2nu1)/G1 - (1-2nu2)/G2] / [(1-nu1)/G1 + (1-nu2)/G2] [-]; zero for identical
        materials, where normal and tangential contact problems uncouple (Johnson 1985, 5.4).
    """
    e2 = youngs_modulus if counter_youngs_modulus is None else counter_youngs_modulus
    nu2 = poisson_ratio if counter_poisson_ratio is None else counter_poisson_ratio
    g1, g2 = youngs_modulus / (2 * (1 + poisson_ratio)), e2 / (2 * (1 + nu2))
    return 0.5 * ((1 - 2 * poisson_ratio) / g1 - (1 - 2 * nu2) / g2) / ((1 - poisson_ratio) / g1 + (1 - nu2) / g2)


@cites("thesis", "israelachvili_2011")
def work_of_adhesion(hamaker_constant, cutoff_distance):
    """Work of adhesion of two flat surfaces from the Hamaker constant, Eq. (3-34) in [1]_.

    .. math:: w_{12} = \\frac{A_{12}}{12\\pi D_0^2}

    Parameters
    ----------
    hamaker_constant : float or array_like
        Hamaker constant A12 [J].
    cutoff_distance : float or array_like
        Cut-off (contact) separation D0 [m].

    Returns
    -------
    float or ndarray
        w12 [J/m²]: 0.445 J/m² for silicon (A = 1.1e-18 J, D0 = 2.56 Å).

    Notes
    -----
    Thesis 3.5 prints 1.31 J/m² for the same inputs; that is A / (4 pi D0²), three times
    (3-34). docs/model.md §3 decides for the formula; a parameter set may override w12.

    Examples
    --------
    >>> print(f"{work_of_adhesion(1.1e-18, 2.56e-10):.3f}")
    0.445
    """
    a12 = as_array(hamaker_constant, "hamaker_constant", "J", positive=True)
    d0 = as_array(cutoff_distance, "cutoff_distance", "m", positive=True)
    return _result(a12 / (12.0 * np.pi * d0**2))


def _log1p_ratio(x: np.ndarray) -> np.ndarray:
    """ln(1 + x) / x, exact limit 1 at x = 0 (series for |x| < 1e-3)."""
    small = np.abs(x) < 1e-3
    safe = np.where(small, 1.0, x)
    series = 1.0 - x / 2.0 + x**2 / 3.0 - x**3 / 4.0 + x**4 / 5.0 - x**5 / 6.0
    return np.where(small, series, np.log1p(safe) / safe)


@cites("thesis", "borodich_2014")
def no_slip_coefficient(poisson_ratio):
    """No-slip coefficient C_NS of adhesive contact, Eq. (3-33) in [1]_ ([3]_).

    .. math:: C_{NS} = \\frac{(1-\\nu)\\ln(3-4\\nu)}{1-2\\nu}

    With t = 1 - 2 nu this is (1 - nu) 2 ln(1 + 2t) / (2t); the ratio ln(1+x)/x is
    evaluated by its series for ``|x| < 1e-3``, so C_NS is smooth through nu = 0.5, where it
    is exactly 1 (the frictionless value).

    Parameters
    ----------
    poisson_ratio : float or array_like
        nu [-], in (-1, 0.5].

    Returns
    -------
    float or ndarray
        C_NS [-] (1.044 for nu = 0.23).

    Examples
    --------
    >>> print(f"{no_slip_coefficient(0.23):.3f}", no_slip_coefficient(0.5))
    1.044 1.0
    """
    nu = check_poisson_ratio(poisson_ratio)
    x = 2.0 * (1.0 - 2.0 * nu)  # 3 - 4 nu = 1 + x
    return _result((1.0 - nu) * 2.0 * _log1p_ratio(x))


def contact_modulus_of(params) -> float:
    """E* [Pa] of a parameter set: the tooth (``youngs_modulus``, ``poisson_ratio``) against the counter body
    (``counter_youngs_modulus``, ``counter_poisson_ratio``; unset: the same material), by :func:`contact_modulus`."""
    return float(contact_modulus(params["youngs_modulus"], params["poisson_ratio"], params.get("counter_youngs_modulus"),
                                 params.get("counter_poisson_ratio")))
