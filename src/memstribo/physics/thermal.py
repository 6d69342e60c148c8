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
unit flux of body i (:func:`blok_flash_temperature`). The half-space holds while the heat's
diffusion length (:func:`half_space_diffusion_length`) stays inside the tooth.

Where the heat goes next (issue 38, MODEL 7h): along the tooth to its root by conduction, the
tooth a straight fin of uniform cross-section losing heat from its sides (Incropera et al. 2007,
section 3.6: :func:`fin_parameter`, :func:`fin_heat_rate_infinite`, :func:`fin_heat_rate_adiabatic`,
:func:`fin_heat_rate_convective_tip`, and :func:`fin_tip_excess_heat_input` for the tooth, heated at
its flank), then from the gear's disc through its hub to the substrate and by radiation
(:func:`radiation_coefficient`); in air also across the air gap (:func:`disc_temperature_rise`).
:func:`bulk_temperature_rise` is the single-conductance rise of version 3.

References: Jaeger 1942; Blok 1937; Carslaw and Jaeger 1959; Incropera et al. 2007 (memstribo.references).
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
           "bulk_temperature_rise", "half_space_diffusion_length", "radiation_coefficient", "fin_parameter",
           "fin_heat_rate_infinite", "fin_heat_rate_adiabatic", "fin_heat_rate_convective_tip",
           "fin_tip_excess_heat_input", "disc_temperature_rise", "STEFAN_BOLTZMANN"]

#: Stefan-Boltzmann constant sigma [W/(m^2 K^4)] (CODATA 2018, exact in the 2019 SI)
STEFAN_BOLTZMANN = 5.670374419e-8

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


@cites("jaeger_1942", "carslaw_jaeger_1959")
def half_space_diffusion_length(half_width, peclet):
    """How far the heat of a moving band source reaches into the body, a / min(L, sqrt(L)) [m].

    High Péclet (L >= 1): each point is heated for 2a/u, to the depth sqrt(2 kappa a / u) = a / sqrt(L)
    (Eq. (2)'s 1D conduction). Low Péclet (L < 1): the field of the moving source reaches
    2 kappa / u = a / L ahead of and beside it (the exponent of Eq. (1), Carslaw and Jaeger 1959, 10.7).
    The half-space solution holds while this length stays below the body's size (the tooth's
    thickness, for a gear tooth).

    Parameters
    ----------
    half_width : array_like
        Band half-width a [m].
    peclet : array_like
        L = u a / (2 kappa) [-] (> 0).
    """
    a = as_array(half_width, "half_width", "m", nonnegative=True)
    L = as_array(peclet, "peclet", "", positive=True)
    result = a / np.minimum(L, np.sqrt(L))
    return float(result) if np.ndim(result) == 0 else result


def _emissivity(value):
    eps = as_array(value, "emissivity", "", positive=True)
    if np.any(eps > 1.0):
        raise InputError(f"emissivity must lie in (0, 1] (a grey surface emits at most as a black body), got "
                         f"{float(np.max(eps)):g}.")
    return eps


@cites("incropera_2007")
def radiation_coefficient(emissivity, temperature, surroundings_temperature=None):
    """Radiation heat transfer coefficient of a small grey surface in large surroundings [W/(m^2 K)].

    ``h_r = eps sigma (T + T_sur)(T^2 + T_sur^2)`` (Incropera et al. 2007, Eq. 1.9), which linearises
    the net exchange ``q'' = eps sigma (T^4 - T_sur^4)`` (Eq. 1.7) and tends to ``4 eps sigma T^3`` as
    T_sur -> T: 6.1 eps W/(m^2 K) at 300 K.

    Parameters
    ----------
    emissivity : array_like
        Total hemispherical emissivity eps of the surface, in (0, 1] [-].
    temperature : array_like
        Surface temperature T [K] (> 0).
    surroundings_temperature : array_like, optional
        Temperature T_sur of the surroundings [K] (> 0); unset: T (the linearised 4 eps sigma T^3).
    """
    eps = _emissivity(emissivity)
    t = as_array(temperature, "temperature", "K", positive=True)
    t_sur = t if surroundings_temperature is None else as_array(surroundings_temperature,
                                                                "surroundings_temperature", "K", positive=True)
    result = eps * STEFAN_BOLTZMANN * (t + t_sur) * (t * t + t_sur * t_sur)
    return float(result) if np.ndim(result) == 0 else result


def _fin_inputs(heat_transfer_coefficient, perimeter, conductivity, area):
    h = as_array(heat_transfer_coefficient, "heat_transfer_coefficient", "W/(m^2 K)", nonnegative=True)
    p = as_array(perimeter, "perimeter", "m", positive=True)
    k = as_array(conductivity, "thermal_conductivity", "W/(m K)", positive=True)
    a = as_array(area, "area", "m^2", positive=True)
    return h, p, k, a


@cites("incropera_2007")
def fin_parameter(heat_transfer_coefficient, perimeter, conductivity, area):
    """Fin parameter m = sqrt(h P / (k A_c)) of a fin of uniform cross-section [1/m].

    Incropera et al. 2007, Eq. 3.69; the fin equation d^2 theta / dx^2 - m^2 theta = 0 (Eq. 3.70) for the
    excess temperature theta = T - T_inf along the fin.

    Parameters
    ----------
    heat_transfer_coefficient : array_like
        h of the fin's sides [W/(m^2 K)] (>= 0; radiation's :func:`radiation_coefficient` in vacuum).
    perimeter : array_like
        Perimeter P of the cross-section [m].
    conductivity : array_like
        Thermal conductivity k [W/(m K)].
    area : array_like
        Cross-section A_c [m^2].
    """
    h, p, k, a = _fin_inputs(heat_transfer_coefficient, perimeter, conductivity, area)
    result = np.sqrt(h * p / (k * a))
    return float(result) if np.ndim(result) == 0 else result


@cites("incropera_2007")
def fin_heat_rate_infinite(base_excess, heat_transfer_coefficient, perimeter, conductivity, area):
    """Heat rate through the base of an infinitely long fin, q_f = sqrt(h P k A_c) theta_b [W].

    Incropera et al. 2007, Table 3.4 case D, Eq. 3.85 (theta = theta_b exp(-m x), Eq. 3.84).

    Parameters
    ----------
    base_excess : array_like
        theta_b = T_b - T_inf at the base [K].
    heat_transfer_coefficient, perimeter, conductivity, area : array_like
        As :func:`fin_parameter` [W/(m^2 K)], [m], [W/(m K)], [m^2].
    """
    theta_b = as_array(base_excess, "base_excess", "K")
    h, p, k, a = _fin_inputs(heat_transfer_coefficient, perimeter, conductivity, area)
    result = np.sqrt(h * p * k * a) * theta_b
    return float(result) if np.ndim(result) == 0 else result


@cites("incropera_2007")
def fin_heat_rate_adiabatic(base_excess, heat_transfer_coefficient, perimeter, conductivity, area, length):
    """Heat rate through the base of a fin with an adiabatic tip, q_f = M tanh(m L) [W].

    Incropera et al. 2007, Table 3.4 case B, Eq. 3.81 with M = sqrt(h P k A_c) theta_b
    (theta / theta_b = cosh(m (L - x)) / cosh(m L), Eq. 3.80).

    Parameters
    ----------
    base_excess : array_like
        theta_b = T_b - T_inf at the base [K].
    heat_transfer_coefficient, perimeter, conductivity, area : array_like
        As :func:`fin_parameter` [W/(m^2 K)], [m], [W/(m K)], [m^2].
    length : array_like
        Fin length L [m].
    """
    theta_b = as_array(base_excess, "base_excess", "K")
    h, p, k, a = _fin_inputs(heat_transfer_coefficient, perimeter, conductivity, area)
    length_ = as_array(length, "length", "m", nonnegative=True)
    m = np.sqrt(h * p / (k * a))
    result = np.sqrt(h * p * k * a) * theta_b * np.tanh(m * length_)
    return float(result) if np.ndim(result) == 0 else result


@cites("incropera_2007")
def fin_heat_rate_convective_tip(base_excess, heat_transfer_coefficient, perimeter, conductivity, area, length):
    """Heat rate through the base of a fin whose tip loses heat with the sides' h [W].

    ``q_f = M (sinh mL + (h / mk) cosh mL) / (cosh mL + (h / mk) sinh mL)``, M = sqrt(h P k A_c) theta_b
    (Incropera et al. 2007, Table 3.4 case A, Eq. 3.77; the temperature is Eq. 3.75). It lies between
    the adiabatic tip (Eq. 3.81) and the infinite fin (Eq. 3.85) while h / (m k) < 1.

    Parameters
    ----------
    base_excess : array_like
        theta_b = T_b - T_inf at the base [K].
    heat_transfer_coefficient, perimeter, conductivity, area : array_like
        As :func:`fin_parameter` [W/(m^2 K)], [m], [W/(m K)], [m^2]; h > 0.
    length : array_like
        Fin length L [m].
    """
    theta_b = as_array(base_excess, "base_excess", "K")
    h, p, k, a = _fin_inputs(heat_transfer_coefficient, perimeter, conductivity, area)
    if np.any(h <= 0):
        raise InputError("heat_transfer_coefficient must be > 0 [W/(m^2 K)] for a convective tip "
                         "(h = 0 is the adiabatic tip: fin_heat_rate_adiabatic).")
    length_ = as_array(length, "length", "m", nonnegative=True)
    m = np.sqrt(h * p / (k * a))
    ratio = h / (m * k)
    ml = m * length_
    result = (np.sqrt(h * p * k * a) * theta_b * (np.sinh(ml) + ratio * np.cosh(ml))
              / (np.cosh(ml) + ratio * np.sinh(ml)))
    return float(result) if np.ndim(result) == 0 else result


@cites("incropera_2007")
def fin_tip_excess_heat_input(heat, base_excess, heat_transfer_coefficient, perimeter, conductivity, area, length):
    """Excess temperature of a fin's tip where the heat Q enters it, the base held at theta_b [K].

    The fin equation (Incropera et al. 2007, Eq. 3.70) with its general solution theta = C1 cosh(mx) +
    C2 sinh(mx) (Eq. 3.71 in hyperbolic form), theta(0) = theta_b and k A_c dtheta/dx (L) = Q (the heat
    entering at the tip: a gear tooth heated at its flank, cooled through its root and its sides):

        theta(L) = theta_b / cosh(m L) + Q tanh(m L) / (m k A_c)

    For m L -> 0 (sides that lose nothing) it is Fourier's law of a rod, theta_b + Q L / (k A_c)
    (Eq. 3.4's wall resistance L / (k A)); the tests check it against a finite-difference solution.

    Parameters
    ----------
    heat : array_like
        Heat rate Q entering at the tip [W] (>= 0).
    base_excess : array_like
        theta_b = T_b - T_inf at the base (the root) [K].
    heat_transfer_coefficient, perimeter, conductivity, area : array_like
        As :func:`fin_parameter` [W/(m^2 K)], [m], [W/(m K)], [m^2]; h >= 0.
    length : array_like
        Distance L from the base to where the heat enters [m].
    """
    q = as_array(heat, "heat", "W", nonnegative=True)
    theta_b = as_array(base_excess, "base_excess", "K")
    h, p, k, a = _fin_inputs(heat_transfer_coefficient, perimeter, conductivity, area)
    length_ = as_array(length, "length", "m", nonnegative=True)
    m = np.sqrt(h * p / (k * a))
    ml = m * length_
    # tanh(mL) / m -> L as m -> 0 (series to third order below mL = 1e-4)
    with np.errstate(invalid="ignore", divide="ignore"):
        reach = np.where(ml > 1e-4, np.tanh(ml) / np.where(m > 0, m, 1.0), length_ * (1.0 - ml * ml / 3.0))
    result = theta_b / np.cosh(ml) + q * reach / (k * a)
    return float(result) if np.ndim(result) == 0 else result


@cites("incropera_2007")
def disc_temperature_rise(mean_power, hub_conductance, radiation_coefficient, radiating_area,
                          gap_coefficient=0.0, gap_area=0.0):
    """Temperature rise of a gear's disc losing the mean power P through parallel paths [K].

    ``Delta T = P / (G_hub + h_r A_r + h_gap A_gap)``: the conductances of parallel heat paths add
    (the thermal circuit of Incropera et al. 2007, section 3.1.3): the hub to the substrate, radiation
    from the disc's surfaces (:func:`radiation_coefficient`) and, in air only, conduction across the
    air gap to the substrate. In vacuum the gap term is zero.

    Parameters
    ----------
    mean_power : array_like
        Mean friction power into the gear [W] (>= 0).
    hub_conductance : array_like
        G_hub from the disc through the hub and anchor to the substrate [W/K] (>= 0).
    radiation_coefficient : array_like
        h_r [W/(m^2 K)] (>= 0).
    radiating_area : array_like
        A_r, both faces of the disc [m^2] (> 0).
    gap_coefficient : array_like
        h_gap, conduction across the gas gap to the substrate [W/(m^2 K)] (>= 0; 0 in vacuum).
    gap_area : array_like
        A_gap, the face over the substrate [m^2] (>= 0).
    """
    p = as_array(mean_power, "mean_power", "W", nonnegative=True)
    g_hub = as_array(hub_conductance, "hub_thermal_conductance", "W/K", nonnegative=True)
    h_r = as_array(radiation_coefficient, "radiation_coefficient", "W/(m^2 K)", nonnegative=True)
    a_r = as_array(radiating_area, "radiating_area", "m^2", positive=True)
    h_g = as_array(gap_coefficient, "gap_coefficient", "W/(m^2 K)", nonnegative=True)
    a_g = as_array(gap_area, "gap_area", "m^2", nonnegative=True)
    conductance = g_hub + h_r * a_r + h_g * a_g
    if np.any(conductance <= 0):
        raise InputError("the disc has no path for its heat: give a hub conductance, an emissivity or a gas gap "
                         "(all zero).")
    result = p / conductance
    return float(result) if np.ndim(result) == 0 else result
