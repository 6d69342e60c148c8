"""Contact temperature of sliding teeth: flash temperature of a moving band heat source (MODEL §10).

A line contact of half-width ``a`` dissipates the friction power ``q = F_f v_s / (2 a b)`` per
unit area. Each tooth surface moves through the contact at its own speed ``u`` (its surface
velocity relative to the contact point), so that for that body the contact is a band heat
source moving over a half-space at speed ``u``: Jaeger's (1942) moving band source. With the
Péclet number ``L = u a / (2 kappa)`` its exact surface temperature is (Carslaw and Jaeger
1959, 10.7: the moving line source on a half-space, integrated over the band)

    theta(x) = q / (pi k) integral_{-a}^{a} exp(-(u / 2 kappa)(x - x')) K0((u / 2 kappa)|x - x'|) dx'   (1)

with the two limits that the tests check:

* high Péclet (L >> 1): each point is heated for ``2a / u`` as a 1D half-space, so
  ``theta_max = (2 / sqrt(pi)) q a / (k sqrt(L))`` and the band mean is 2/3 of it;            (2)
* low Péclet (L << 1): ``K0(z) ~ -ln(z / 2) - gamma`` gives the band mean
  ``theta_mean = (2 q a / (pi k)) (3/2 - gamma - ln L)`` (memstribo's integration of (1));    (3)
  the 2D conduction has no steady state without motion, so this grows without bound as L -> 0.

Blok's (1937) postulate shares the heat between the two bodies so that their mean contact
temperatures are equal: ``theta_f = q f1 f2 / (f1 + f2)`` with ``f_i`` the mean temperature per
unit flux of body i (:func:`blok_flash_temperature`). The bulk temperature of the teeth rises
by the mean friction power over the heat conductance to the surroundings
(:func:`bulk_temperature_rise`).

References: Jaeger 1942; Blok 1937; Carslaw and Jaeger 1959 (memstribo.references).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["peclet_number", "band_temperature", "band_mean_factor", "band_mean_factor_high_peclet",
           "band_mean_factor_low_peclet", "band_max_factor_high_peclet", "blok_flash_temperature",
           "bulk_temperature_rise"]

_EULER_GAMMA = 0.5772156649015329
#: Péclet numbers beyond which :func:`band_mean_factor` uses the limits (2) and (3) instead of integrating (1)
HIGH_PECLET, LOW_PECLET = 50.0, 1e-3


@functools.lru_cache(maxsize=8)
def _gauss(points):
    """Gauss-Legendre nodes and weights on [-1, 1] (cached: computing 400 of them costs an eigenvalue solve)."""
    nodes, weights = np.polynomial.legendre.leggauss(int(points))
    nodes.flags.writeable = False
    weights.flags.writeable = False
    return nodes, weights


def peclet_number(speed, half_width, diffusivity):
    """Jaeger's Péclet number L = |u| a / (2 kappa) [-].

    Parameters
    ----------
    speed : array_like
        Speed u of the surface through the heat source [m/s].
    half_width : array_like
        Half-width a of the band [m].
    diffusivity : float
        Thermal diffusivity kappa [m^2/s].
    """
    u = np.abs(as_array(speed, "speed", "m/s"))
    a = as_array(half_width, "half_width", "m", nonnegative=True)
    kappa = as_array(diffusivity, "thermal_diffusivity", "m^2/s", positive=True)
    result = u * a / (2 * kappa)
    return float(result) if np.ndim(result) == 0 else result


@cites("jaeger_1942", "carslaw_jaeger_1959")
def band_temperature(x, peclet, points=400):
    """Dimensionless surface temperature theta k / (q a) of the moving band source at x / a, Eq. (1) [-].

    The band spans x/a in [-1, 1]; the surface material enters the band at x/a = +1 and leaves it at
    x/a = -1, its hottest point (the trailing edge).

    Parameters
    ----------
    x : array_like
        Positions x / a [-].
    peclet : float
        L = u a / (2 kappa) [-] (> 0).
    points : int
        Gauss-Legendre points on each side of x (the log singularity of K0 is removed by the
        substitution |x - x'| = t^2).
    """
    from scipy.special import k0e

    L = float(peclet)
    if not (math.isfinite(L) and L > 0):
        raise InputError(f"the Péclet number must be a positive finite number, got {peclet!r}.")
    xs = np.clip(np.atleast_1d(np.asarray(x, dtype=float)), -1.0, 1.0)
    nodes, weights = _gauss(int(points))
    out = np.zeros(xs.size)
    # sources behind (x' < x, factor exp(-L d) K0(L d)) and ahead (x' > x, factor exp(+L d) K0(L d))
    for span, sign in ((xs + 1.0, -1.0), (1.0 - xs, 1.0)):
        t_hi = np.sqrt(np.maximum(span, 0.0))[:, None]
        t = 0.5 * t_hi * (nodes + 1.0)[None, :]
        z = L * t * t
        # exp(sign L d) K0(L d) = k0e(L d) exp(L d (sign - 1)) (K0 = k0e exp(-z)): no overflow
        f = k0e(np.maximum(z, 1e-300)) * np.exp(z * (sign - 1.0)) * 2.0 * t
        out += 0.5 * t_hi[:, 0] * np.sum(weights[None, :] * f, axis=1)
    out /= math.pi
    return out if np.ndim(x) else float(out[0])


def band_mean_factor_high_peclet(peclet):
    """Band-mean theta k / (q a) in the high-Péclet limit, (4 / (3 sqrt(pi))) L^(-1/2), Eq. (2) [-]."""
    return 4.0 / (3.0 * math.sqrt(math.pi)) / np.sqrt(peclet)


def band_max_factor_high_peclet(peclet):
    """Largest theta k / (q a) in the high-Péclet limit, (2 / sqrt(pi)) L^(-1/2), Eq. (2) [-]."""
    return 2.0 / math.sqrt(math.pi) / np.sqrt(peclet)


def band_mean_factor_low_peclet(peclet):
    """Band-mean theta k / (q a) in the low-Péclet limit, (2 / pi)(3/2 - gamma - ln L), Eq. (3) [-]."""
    return 2.0 / math.pi * (1.5 - _EULER_GAMMA - np.log(peclet))


@cites("jaeger_1942")
def band_mean_factor(peclet):
    """Band-mean surface temperature per unit flux, theta_mean k / (q a), of the moving band source [-].

    Eq. (1) averaged over the band (Gauss-Legendre), and the limits (2) above L = 50 and (3) below
    L = 1e-3, where they agree with (1) to better than 1 % (tests/test_thermal.py).
    """
    L = np.atleast_1d(np.asarray(peclet, dtype=float))
    if np.any(~np.isfinite(L)) or np.any(L <= 0):
        raise InputError("the Péclet number must be positive and finite.")
    out = np.empty(L.size)
    nodes, weights = _gauss(24)
    for i, li in enumerate(L):
        if li >= HIGH_PECLET:
            out[i] = band_mean_factor_high_peclet(li)
        elif li <= LOW_PECLET:
            out[i] = band_mean_factor_low_peclet(li)
        else:
            out[i] = 0.5 * float(np.sum(weights * band_temperature(nodes, li)))
    return out if np.ndim(peclet) else float(out[0])


@cites("blok_1937", "jaeger_1942")
def blok_flash_temperature(heat_flux, half_width, speed_1, speed_2, conductivity, diffusivity):
    """Flash temperature rise of a sliding line contact, Blok's equal-mean-temperature partition [K].

    Parameters
    ----------
    heat_flux : array_like
        Friction power per unit contact area q = F_f |v_s| / (2 a b) [W/m^2].
    half_width : array_like
        Contact half-width a [m].
    speed_1, speed_2 : array_like
        Surface speeds of the two bodies through the contact [m/s].
    conductivity : float
        Thermal conductivity k of both bodies [W/(m K)].
    diffusivity : float
        Thermal diffusivity kappa of both bodies [m^2/s].

    Returns
    -------
    dict of numpy.ndarray
        ``flash`` mean contact temperature rise [K], ``share_1`` the share of the heat into body 1 [-],
        ``peclet_1``, ``peclet_2`` [-].
    """
    q = as_array(heat_flux, "heat_flux", "W/m^2", nonnegative=True)
    a = as_array(half_width, "half_width", "m", nonnegative=True)
    k = float(as_array(conductivity, "thermal_conductivity", "W/(m K)", positive=True))
    l1 = np.atleast_1d(peclet_number(speed_1, a, diffusivity))
    l2 = np.atleast_1d(peclet_number(speed_2, a, diffusivity))
    tiny = 1e-12  # a surface at rest in the contact: (3) at L = 1e-12, a finite stand-in for the 2D divergence
    f1 = band_mean_factor(np.maximum(l1, tiny))
    f2 = band_mean_factor(np.maximum(l2, tiny))
    share = f2 / (f1 + f2)
    flash = np.atleast_1d(q) * np.atleast_1d(a) * f1 * f2 / (f1 + f2) / k
    flash = np.where(np.atleast_1d(a) > 0, flash, 0.0)
    return {"flash": flash, "share_1": share, "peclet_1": l1, "peclet_2": l2}


def bulk_temperature_rise(mean_power, heat_transfer_coefficient, area):
    """Bulk temperature rise of a body losing the mean power P to its surroundings, P / (h A) [K].

    Parameters
    ----------
    mean_power : array_like
        Mean friction power into the body [W].
    heat_transfer_coefficient : float
        h [W/(m^2 K)].
    area : array_like
        Area A through which the heat leaves [m^2].
    """
    p = as_array(mean_power, "mean_power", "W", nonnegative=True)
    h = as_array(heat_transfer_coefficient, "heat_transfer_coefficient", "W/(m^2 K)", positive=True)
    area_ = as_array(area, "area", "m^2", positive=True)
    result = p / (h * area_)
    return float(result) if np.ndim(result) == 0 else result
