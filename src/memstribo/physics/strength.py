"""Strength of polysilicon teeth: Weibull fracture with its size effect, and delayed failure in air (MODEL §10).

Fracture on the first load (weakest link, Weibull 1951): a tooth whose etched surface of
effective area ``A_eff`` carries the peak tensile stress ``sigma`` breaks with probability

    P_f = 1 - exp(-(A_eff / A_0) (sigma / sigma_theta)^m)                         (1)

``sigma_theta`` is the characteristic strength measured on specimens of effective area ``A_0``
and ``m`` the Weibull modulus. Polysilicon MEMS break from flaws on their etched surfaces
(sidewalls), so the size effect scales with area (Jadaan et al. 2003). The effective area of
a non-uniformly stressed surface is ``A_eff = integral (sigma(s) / sigma_max)^m dA``
(:func:`effective_area`).

Delayed failure under cyclic load in air (Muhlstein, Brown and Ritchie 2001: lives of 5e5 to
1e11 cycles at stress amplitudes falling to about half the low-cycle strength; faster in
humid air, slower or absent in high vacuum, Alsem et al. 2005): the characteristic strength falls with the
number of load cycles as a power law (the stress-life form of subcritical crack growth),

    sigma_theta(N) = sigma_theta N_eff^(-1 / n),    N_eff = N 10^(k_RH (RH - RH_ref))    (2)

with the fatigue exponent ``n`` and the humidity sensitivity ``k_RH`` per unit of relative
humidity about the humidity of the data (RH_ref = 0.4). (2) in (1) gives the probability of
fracture within N cycles and, inverted, the cycles to a given probability
(:func:`cycles_to_probability`). Every constant has a prior in ``STRENGTH_PRIORS`` (the
parameter specs' ``prior``) for the uncertainty analysis.

References: Weibull 1951; Jadaan et al. 2003; Boyce 2010; LaVan et al. 2001; Muhlstein et al. 2001;
Alsem et al. 2005; Theillet and Pierron 2009 (memstribo.references).
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["FATIGUE_REFERENCE_HUMIDITY", "check_weibull", "fracture_probability", "effective_area",
           "fatigue_strength_factor", "fatigue_fracture_probability", "cycles_to_probability"]

#: relative humidity of the stress-life data the fatigue constants come from (laboratory air, 30-50 % RH,
#: Muhlstein et al. 2001) [-]
FATIGUE_REFERENCE_HUMIDITY = 0.4


def check_weibull(characteristic_strength, weibull_modulus, reference_area):
    """Validate the Weibull constants; :class:`InputError` naming the bad one (strength or area <= 0, m <= 0)."""
    for name, value, unit in (("strength_characteristic", characteristic_strength, "Pa"),
                              ("weibull_modulus", weibull_modulus, ""),
                              ("strength_reference_area", reference_area, "m^2")):
        v = np.asarray(value, dtype=float)
        if v.size == 0 or not np.all(np.isfinite(v)) or np.any(v <= 0):
            raise InputError(f"{name} must be a positive, finite number{f' [{unit}]' if unit else ''} "
                             f"(a Weibull {'modulus' if name == 'weibull_modulus' else 'strength or area'} <= 0 has "
                             f"no meaning), got {value!r}.")


@cites("weibull_1951", "jadaan_2003")
def fracture_probability(stress, effective_area_, characteristic_strength, weibull_modulus, reference_area):
    """Probability of fracture on the first load, Eq. (1) (Weibull 1951) [-].

    Parameters
    ----------
    stress : array_like
        Peak tensile stress sigma [Pa]; compression (<= 0) cannot break the tooth (P_f = 0).
    effective_area_ : array_like
        A_eff [m^2] of the stressed surface.
    characteristic_strength : float
        sigma_theta [Pa] at the reference area.
    weibull_modulus : float
        m [-].
    reference_area : float
        A_0 [m^2].

    Returns
    -------
    numpy.ndarray or float
        P_f in [0, 1].
    """
    check_weibull(characteristic_strength, weibull_modulus, reference_area)
    s = as_array(stress, "stress", "Pa")
    area = as_array(effective_area_, "effective_area", "m^2", nonnegative=True)
    ratio = np.maximum(s, 0.0) / characteristic_strength
    risk = area / reference_area * ratio ** weibull_modulus
    result = -np.expm1(-risk)
    return float(result) if np.ndim(result) == 0 else result


@cites("weibull_1951")
def effective_area(arc_length, stress, width, weibull_modulus):
    """Effective area A_eff = b integral (sigma(s)/sigma_max)^m ds of a surface stressed along a line [m^2].

    Parameters
    ----------
    arc_length : array_like
        Positions s along the surface line (increasing) [m].
    stress : array_like
        Tensile stress at s [Pa] (compression counts as 0).
    width : float
        Width b of the surface across the line (the face width) [m].
    weibull_modulus : float
        m [-].
    """
    s = as_array(arc_length, "arc_length", "m")
    sigma = np.maximum(as_array(stress, "stress", "Pa"), 0.0)
    b = float(as_array(width, "width", "m", positive=True))
    if sigma.max() <= 0:
        return 0.0
    ratio = (sigma / sigma.max()) ** float(weibull_modulus)
    return float(b * np.sum(0.5 * (ratio[1:] + ratio[:-1]) * np.diff(s)))


def _cycles(cycles):
    n = as_array(cycles, "cycles", "", nonnegative=True)
    return n


@cites("muhlstein_2001", "alsem_2005", "theillet_pierron_2009")
def fatigue_strength_factor(cycles, fatigue_exponent, relative_humidity=FATIGUE_REFERENCE_HUMIDITY,
                            humidity_sensitivity=0.0):
    """sigma_theta(N) / sigma_theta = N_eff^(-1/n), Eq. (2), 1 for N_eff <= 1 [-].

    Parameters
    ----------
    cycles : array_like
        Load cycles N of the tooth [-].
    fatigue_exponent : float
        n [-] (> 0).
    relative_humidity : float
        RH [-] of the air (0 in vacuum).
    humidity_sensitivity : float
        k_RH: decades of life lost per unit RH above RH_ref [-].
    """
    n_exp = float(fatigue_exponent)
    if not (math.isfinite(n_exp) and n_exp > 0):
        raise InputError(f"fatigue_exponent must be a positive number, got {fatigue_exponent!r}.")
    n_eff = _cycles(cycles) * 10.0 ** (float(humidity_sensitivity) * (float(relative_humidity)
                                                                       - FATIGUE_REFERENCE_HUMIDITY))
    result = np.maximum(n_eff, 1.0) ** (-1.0 / n_exp)
    return float(result) if np.ndim(result) == 0 else result


def fatigue_fracture_probability(stress, effective_area_, cycles, characteristic_strength, weibull_modulus,
                                 reference_area, fatigue_exponent, relative_humidity=FATIGUE_REFERENCE_HUMIDITY,
                                 humidity_sensitivity=0.0):
    """Probability of fracture within N load cycles, Eqs. (1) and (2) [-] (N <= 1: the first load)."""
    factor = fatigue_strength_factor(cycles, fatigue_exponent, relative_humidity, humidity_sensitivity)
    return fracture_probability(np.asarray(stress) / factor, effective_area_, characteristic_strength,
                                weibull_modulus, reference_area)


def cycles_to_probability(probability, risk_first_load, weibull_modulus, fatigue_exponent,
                          relative_humidity=FATIGUE_REFERENCE_HUMIDITY, humidity_sensitivity=0.0):
    """Load cycles N at which the fracture probability reaches ``probability`` [-] (Eqs. (1), (2) inverted).

    Parameters
    ----------
    probability : float
        Target probability, in (0, 1).
    risk_first_load : float
        The risk of rupture on the first load, ``R_1 = sum_i (A_eff,i / A_0) (sigma_i / sigma_theta)^m`` over
        the teeth that see N cycles (P_f = 1 - exp(-R_1) on the first load) [-].
    weibull_modulus, fatigue_exponent : float
        m and n [-].
    relative_humidity, humidity_sensitivity : float
        RH [-] and k_RH [-] of Eq. (2).

    Returns
    -------
    float
        N [-]; 1.0 if the first load already reaches the probability; ``inf`` without any tensile stress.
    """
    p = float(probability)
    if not 0.0 < p < 1.0:
        raise InputError(f"probability must lie in (0, 1), got {probability!r}.")
    target = -math.log1p(-p)
    risk = float(risk_first_load)
    if risk <= 0:
        return math.inf
    if risk >= target:
        return 1.0
    # R(N) = R_1 N_eff^(m/n)  ->  N_eff = (target / R_1)^(n/m)
    log_n_eff = (float(fatigue_exponent) / float(weibull_modulus)) * math.log10(target / risk)
    log_n = log_n_eff - float(humidity_sensitivity) * (float(relative_humidity) - FATIGUE_REFERENCE_HUMIDITY)
    return max(10.0 ** min(log_n, 300.0), 1.0)
