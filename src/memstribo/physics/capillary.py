"""Capillary condensation between hydrophilic surfaces in humid air (beyond the thesis: MODEL §10, issue #17).

In air, water condenses wherever the gap between two surfaces is narrower than the capillary
condensation height. The meniscus's curvature is set by the Kelvin equation; its Laplace
pressure pulls the surfaces together over the wetted area. For a sphere on a flat with
r_K << R the force is 4 pi R gamma cos(theta) whatever the humidity; for a cylinder it grows as
sqrt(R / r_K). These are the building blocks of the humid-air model: every function takes the
local gap of a contact solution, so the same relations serve the line contact, the surface
contact and the meshing cycle.

The model: the circular-meniscus (Laplace-Kelvin) approximation with the meniscus at
equilibrium with the vapour (Fisher and Israelachvili 1981; Butt and Kappl 2009), the
condensation height ``h_c = r_K (cos theta_1 + cos theta_2)``, the Laplace pressure
``gamma / r_K`` acting over the wetted area, and no meniscus on a hydrophobic pair
(``cos theta_1 + cos theta_2 <= 0``). A meniscus needs a Kelvin radius of at least one molecular diameter
(:func:`molecular_kelvin_radius`, 0.311 nm for water: RH 0.185 at 25 degC); below it the condensate is an adsorbed
film, whose attraction is the interface's own, and no meniscus force is counted (:func:`forms_meniscus`, issue #36).
No meniscus pulls with more than its Laplace pressure over its wetted area plus gamma on its contact lines
(:func:`meniscus_force_bound`); an elastic pull-off law of a bridged interface is capped by it
(:func:`bounded_pull_off`, MODEL 7g). The
adsorbed water film's thickness (a published isotherm on silicon oxide, [4]_ [5]_) sets how far a water bridge
reaches: :func:`bridging_height`, :func:`meniscus_work_of_separation` (issue #28).

References
----------
.. [1] L. R. Fisher, J. N. Israelachvili, "Direct measurement of the effect of meniscus forces on
   adhesion", Colloids Surf. 3 (1981) 303-319.
.. [2] H.-J. Butt, M. Kappl, "Normal capillary forces", Adv. Colloid Interface Sci. 146 (2009)
   48-60. :doi:`10.1016/j.cis.2008.10.002`
.. [3] J. N. Israelachvili, Intermolecular and Surface Forces, 3rd ed., Academic Press, 2011,
   chapter 17.
.. [4] D. B. Asay, S. H. Kim, "Evolution of the adsorbed water layer structure on silicon oxide at room
   temperature", J. Phys. Chem. B 109 (2005) 16760-16763.
.. [5] A. Verdaguer et al., "Growth and structure of water on SiO2 films on Si investigated by Kelvin probe
   microscopy and in situ X-ray spectroscopies", Langmuir 23 (2007) 9699-9703. :doi:`10.1021/la700893w`
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["GAS_CONSTANT", "WATER", "REFERENCE_TEMPERATURE", "water_surface_tension", "kelvin_radius",
           "condensation_height", "laplace_pressure",
           "capillary_force_sphere", "capillary_force_cylinder", "capillary_pressure", "capillary_force_from_gap",
           "WATER_ISOTHERM_SIO2", "water_monolayer_thickness", "adsorbed_water_thickness", "liquid_water_thickness", "bridging_height",
           "meniscus_work_of_separation", "molecular_kelvin_radius", "forms_meniscus", "meniscus_force_bound",
           "bounded_pull_off"]

#: Molar gas constant R [J/(mol K)] (CODATA 2018, exact).
GAS_CONSTANT = 8.314462618

#: Water at 25 degC: surface tension [N/m] and molar volume [m^3/mol] (Israelachvili 2011, Table 17.1).
WATER = {"surface_tension": 0.072, "molar_volume": 18.07e-6}

#: Adsorbed water on silicon oxide at room temperature: (RH [-], thickness in molecular layers [-]) read from the
#: published isotherms: about 3 (ice-like) layers at RH 0.3 (Asay and Kim 2005, ATR-IR); 4-5 layers (4.5) at RH 0.75
#: and 6-7 monolayers (6.5) at RH 0.9 (Verdaguer et al. 2007, Kelvin probe + X-ray spectroscopies).
WATER_ISOTHERM_SIO2 = ((0.0, 0.0), (0.3, 3.0), (0.75, 4.5), (0.9, 6.5))

#: temperature of the values in :data:`WATER` [K]
REFERENCE_TEMPERATURE = 298.15
#: IAPWS R1-76(2014) surface tension of water: critical temperature [K], B [N/m], b [-], mu [-]
_IAPWS = (647.096, 0.2358, -0.625, 1.256)
#: lowest temperature of the IAPWS correlation (supercooled water) [K]
WATER_MIN_TEMPERATURE = 248.15


def _iapws_surface_tension(temperature):
    t_c, big_b, small_b, mu = _IAPWS
    tau = 1.0 - temperature / t_c
    return big_b * tau**mu * (1.0 + small_b * tau)


@cites("iapws_2014", "israelachvili_2011")
def water_surface_tension(temperature=REFERENCE_TEMPERATURE):
    """Surface tension of water at ``temperature`` [N/m]: 0.072 N/m at 25 degC scaled by the IAPWS correlation.

    ``gamma(T) = 0.072 gamma_IAPWS(T) / gamma_IAPWS(298.15 K)`` with ``gamma_IAPWS = B tau^mu (1 + b tau)``,
    ``tau = 1 - T / 647.096 K`` (IAPWS R1-76(2014)): exactly :data:`WATER`'s 0.072 N/m at 298.15 K, and
    the measured temperature dependence (-0.16 mN/(m K) near room temperature) elsewhere.

    Parameters
    ----------
    temperature : numeric
        T [K], from 248.15 K (supercooled water, the correlation's lower end) to below the critical
        point 647.096 K (no liquid water, so no meniscus, above it).

    Raises
    ------
    InputError
        A temperature outside that range: no liquid water, so no capillary meniscus.
    """
    t = as_array(temperature, "temperature", "K", positive=True)
    if np.any(t < WATER_MIN_TEMPERATURE) or np.any(t >= _IAPWS[0]):
        raise InputError(f"temperature {temperature!r} K is outside the liquid range of water that the capillary "
                         f"model needs ({WATER_MIN_TEMPERATURE:g} K to below the critical point {_IAPWS[0]:g} K): "
                         "no menisci can form there.")
    if np.ndim(t) == 0 and float(t) == REFERENCE_TEMPERATURE:
        return WATER["surface_tension"]
    result = WATER["surface_tension"] * (_iapws_surface_tension(t) / _iapws_surface_tension(REFERENCE_TEMPERATURE))
    return float(result) if np.ndim(result) == 0 else result


def _humidity(relative_humidity):
    rh = np.asarray(relative_humidity, dtype=float)
    if np.any(~np.isfinite(rh)) or np.any(rh < 0) or np.any(rh >= 1):
        raise InputError(f"relative_humidity must lie in [0, 1) (1 is saturation: no finite Kelvin radius), got "
                         f"{relative_humidity!r}.")
    return rh


def _angles(*theta):
    out = [np.asarray(t, dtype=float) for t in theta]
    for t in out:
        if np.any(~np.isfinite(t)) or np.any(t < 0) or np.any(t > math.pi):
            raise InputError("water contact angles must lie in [0, pi] rad (0 to 180 deg).")
    return out


@cites("israelachvili_2011")
def kelvin_radius(relative_humidity, temperature=REFERENCE_TEMPERATURE, surface_tension=None,
                  molar_volume=WATER["molar_volume"]):
    """Kelvin radius of a water meniscus, ``r_K = gamma V_m / (R T ln(1/RH))``, Eq. (17.21) in [3]_.

    Parameters
    ----------
    relative_humidity : numeric
        RH = p / p_sat [-], in [0, 1).
    temperature : numeric
        T [K], > 0.
    surface_tension : numeric, optional
        gamma of the liquid [N/m]; default water's at ``temperature`` (:func:`water_surface_tension`,
        0.072 N/m at 298.15 K).
    molar_volume : numeric
        V_m of the liquid [m^3/mol] (water's at 25 degC; it changes by under 4 % from 0 to 100 degC).

    Returns
    -------
    numeric
        r_K [m] (positive: the meniscus is concave); 0 at RH = 0 (no meniscus can form).

    Examples
    --------
    >>> print(f"{float(kelvin_radius(1 / math.e)) * 1e9:.3f}")  # gamma V_m / (R T) at 25 degC [nm]
    0.525
    """
    rh = _humidity(relative_humidity)
    t = as_array(temperature, "temperature", "K", positive=True)
    if surface_tension is None:
        surface_tension = water_surface_tension(temperature)
    gamma = as_array(surface_tension, "surface_tension", "N/m", positive=True)
    volume = as_array(molar_volume, "molar_volume", "m^3/mol", positive=True)
    scale = gamma * volume / (GAS_CONSTANT * t)
    with np.errstate(divide="ignore"):
        log = np.where(rh > 0, np.log(1.0 / np.where(rh > 0, rh, 1.0)), np.inf)
    result = np.where(rh > 0, scale / log, 0.0)
    return float(result) if np.ndim(result) == 0 else result


def condensation_height(kelvin, contact_angle_1, contact_angle_2=None):
    """Largest gap that fills with condensed water, ``h_c = r_K (cos theta_1 + cos theta_2)`` [m], [2]_.

    ``contact_angle_2`` defaults to ``contact_angle_1`` (two like surfaces: ``2 r_K cos theta``).
    Zero (no meniscus) for a hydrophobic pair, ``cos theta_1 + cos theta_2 <= 0``.
    """
    r = as_array(kelvin, "kelvin", "m", nonnegative=True)
    t1, t2 = _angles(contact_angle_1, contact_angle_1 if contact_angle_2 is None else contact_angle_2)
    result = r * np.maximum(np.cos(t1) + np.cos(t2), 0.0)
    return float(result) if np.ndim(result) == 0 else result


def laplace_pressure(kelvin, surface_tension=WATER["surface_tension"]):
    """Laplace pressure of the meniscus, ``gamma / r_K`` [Pa] (attractive), Eq. (17.3) in [3]_; 0 where r_K = 0."""
    r = as_array(kelvin, "kelvin", "m", nonnegative=True)
    gamma = as_array(surface_tension, "surface_tension", "N/m", positive=True)
    result = np.divide(gamma, r, out=np.zeros(np.broadcast(gamma, r).shape), where=r > 0)
    return float(result) if np.ndim(result) == 0 else result


@cites("israelachvili_2011")
def capillary_force_sphere(radius, contact_angle_1, contact_angle_2=None, surface_tension=WATER["surface_tension"]):
    """Capillary force of a sphere on a flat, ``2 pi R gamma (cos theta_1 + cos theta_2)`` [N], [1]_, [2]_.

    The limit r_K << R: ``4 pi R gamma cos theta`` for like surfaces, independent of humidity.
    """
    r = as_array(radius, "radius", "m", positive=True)
    gamma = as_array(surface_tension, "surface_tension", "N/m", positive=True)
    t1, t2 = _angles(contact_angle_1, contact_angle_1 if contact_angle_2 is None else contact_angle_2)
    result = 2 * math.pi * r * gamma * np.maximum(np.cos(t1) + np.cos(t2), 0.0)
    return float(result) if np.ndim(result) == 0 else result


def capillary_force_cylinder(radius, kelvin, contact_angle_1, contact_angle_2=None,
                             surface_tension=WATER["surface_tension"]):
    """Capillary force per unit length of a cylinder on a flat [N/m] (r_K << R), [2]_.

    The meniscus fills the gap ``x^2 / (2R) <= h_c``, a width ``2 sqrt(2 R h_c)``; the Laplace
    pressure ``gamma / r_K`` over it gives ``2 gamma sqrt(2 R h_c) / r_K``
    = ``2 gamma sqrt(2 R (cos theta_1 + cos theta_2) / r_K)``: it grows as the humidity falls
    (r_K smaller), unlike the sphere's.
    """
    r = as_array(radius, "radius", "m", positive=True)
    k = as_array(kelvin, "kelvin", "m", nonnegative=True)
    gamma = as_array(surface_tension, "surface_tension", "N/m", positive=True)
    h = condensation_height(k, contact_angle_1, contact_angle_2)
    result = np.divide(2 * gamma * np.sqrt(2 * r * h), k, out=np.zeros(np.broadcast(r, k, gamma).shape),
                       where=k > 0)
    return float(result) if np.ndim(result) == 0 else result


def capillary_pressure(gap, kelvin, contact_angle_1, contact_angle_2=None, surface_tension=WATER["surface_tension"]):
    """Attractive meniscus pressure at each local gap [Pa]: ``gamma / r_K`` where ``gap <= h_c``, else 0.

    Parameters
    ----------
    gap : array_like
        Local gap between the surfaces [m] (0 in contact: the contact spots are wetted around).
    kelvin : float
        r_K [m].
    contact_angle_1, contact_angle_2 : float
        Water contact angles of the two surfaces [rad].
    surface_tension : float
        [N/m].
    """
    g = np.asarray(gap, dtype=float)
    if np.any(~np.isfinite(g)):
        raise InputError("gap contains NaN or infinite values.")
    h_c = condensation_height(kelvin, contact_angle_1, contact_angle_2)
    return np.where((g <= h_c) & (h_c > 0), laplace_pressure(kelvin, surface_tension), 0.0)


def capillary_force_from_gap(gap, area_per_element, kelvin, contact_angle_1, contact_angle_2=None,
                             surface_tension=WATER["surface_tension"]):
    """Capillary force [N] of a gap field: the meniscus pressure summed over the wetted elements.

    ``area_per_element`` [m^2] (e.g. dx dy for a surface, dx times the width for a line).
    """
    area = as_array(area_per_element, "area_per_element", "m^2", positive=True)
    return float(np.sum(capillary_pressure(gap, kelvin, contact_angle_1, contact_angle_2, surface_tension)) * area)


def water_monolayer_thickness(molar_volume=WATER["molar_volume"]):
    """Thickness of one molecular layer of water [m]: the cube root of the volume per molecule, (V_m / N_A)^(1/3).

    0.311 nm for V_m = 18.07e-6 m^3/mol (:data:`WATER`). ``molar_volume`` [m^3/mol].
    """
    volume = float(as_array(molar_volume, "molar_volume", "m^3/mol", positive=True))
    return (volume / 6.02214076e23) ** (1.0 / 3.0)


@cites("asay_kim_2005", "verdaguer_2007")
def adsorbed_water_thickness(relative_humidity):
    """Thickness t of the water film adsorbed on a hydrophilic silicon oxide at room temperature [m].

    The published isotherm :data:`WATER_ISOTHERM_SIO2` (molecular layers against RH: about 3 layers at RH 0.3,
    Asay and Kim 2005; 4.5 at RH 0.75 and 6.5 at RH 0.9, Verdaguer et al. 2007) interpolated linearly between its
    points, times :func:`water_monolayer_thickness` (0.311 nm): 0.93 nm at RH 0.3, 1.40 nm at RH 0.75, 2.02 nm at
    RH 0.9. Above RH 0.9 the last slope is extended (the measured film thickens steeply towards a macroscopic drop
    at saturation: read values above 0.9 as a lower bound). 0 when dry.

    Parameters
    ----------
    relative_humidity : float or array_like
        RH [-] in [0, 1).

    Returns
    -------
    float or ndarray
        t [m].
    """
    rh = _humidity(relative_humidity)
    x, layers = (np.array(c, dtype=float) for c in zip(*WATER_ISOTHERM_SIO2))
    slope = (layers[-1] - layers[-2]) / (x[-1] - x[-2])
    n = np.where(rh <= x[-1], np.interp(rh, x, layers), layers[-1] + slope * (rh - x[-1]))
    result = n * water_monolayer_thickness()
    return float(result) if np.ndim(result) == 0 else result


@cites("asay_kim_2005", "verdaguer_2007")
def liquid_water_thickness(relative_humidity):
    """The liquid-like part of the water film on silicon oxide [m]: :func:`adsorbed_water_thickness` less its
    ice-like layers.

    The first three layers, complete by RH 0.3, are ice-like (hydrogen-bonded to the silanols, Asay and Kim 2005)
    and do not flow into a meniscus; what grows above them is liquid-like: ``max(t(RH) - t(0.3), 0)``, 0 up to
    RH 0.3, 0.21 nm at RH 0.5, 1.09 nm at RH 0.9. ``relative_humidity`` [-] in [0, 1).
    """
    ice = adsorbed_water_thickness(WATER_ISOTHERM_SIO2[1][0])
    result = np.maximum(adsorbed_water_thickness(relative_humidity) - ice, 0.0)
    return float(result) if np.ndim(result) == 0 else result


@cites("butt_kappl_2009")
def bridging_height(kelvin, film_1, film_2, contact_angle_1, contact_angle_2=None):
    """Largest gap that a water bridge spans, ``h_c + t_1 + t_2`` [m] (Butt and Kappl 2009, [2]_).

    The adsorbed films (thickness ``film_1``, ``film_2`` [m] on each surface) narrow the gap the meniscus must
    close: condensation occurs where the gap between the films' surfaces is below ``h_c`` (:func:`condensation_height`).
    Zero for a hydrophobic pair (``cos theta_1 + cos theta_2 <= 0``: no meniscus, whatever the films).
    ``kelvin`` r_K [m]; angles [rad].
    """
    h_c = condensation_height(kelvin, contact_angle_1, contact_angle_2)
    t1 = as_array(film_1, "film_1", "m", nonnegative=True)
    t2 = as_array(film_2, "film_2", "m", nonnegative=True)
    result = np.where(h_c > 0, h_c + t1 + t2, 0.0)
    return float(result) if np.ndim(result) == 0 else result


@cites("israelachvili_2011")
def meniscus_work_of_separation(gap, kelvin, height, films=0.0, surface_tension=WATER["surface_tension"]):
    """Work per area to pull a water bridge apart [J/m^2]: ``(gamma / r_K) max(height - max(gap, films), 0)``.

    The Laplace pressure ``gamma / r_K`` (:func:`laplace_pressure`) acts while the local separation grows from the
    gap ``gap`` (or from ``films`` = t_1 + t_2 where the adsorbed films overlap: there the gap is full of film
    water, whose own attraction is the interface's, not the bridge's) to the bridging height ``height``
    (:func:`bridging_height`), where the bridge breaks (the meniscus keeps its Kelvin curvature: equilibrium with
    the vapour). Its largest value, at a gap below the films, is ``(gamma / r_K) h_c = gamma (cos theta_1 +
    cos theta_2)``, the wetted-interface work of the microbeam model
    (:func:`memstribo.laboratory.predict.beam_work_of_separation`) whatever the RH (Israelachvili 2011, ch. 17: the
    grand-potential difference of a filled and an empty slit): the RH enters through the area that is bridged,
    which grows with ``height``.

    Parameters
    ----------
    gap : array_like
        Local gaps [m], >= 0 (0 where touching).
    kelvin : float
        r_K [m] (0: dry, no work).
    height : float or array_like
        Bridging height [m] (per element where the surfaces differ).
    films : float or array_like
        t_1 + t_2, the adsorbed films' summed thickness [m] (:func:`adsorbed_water_thickness`), <= ``height``.
    surface_tension : float
        gamma [N/m].

    Returns
    -------
    ndarray
        Work of separation per area at each gap [J/m^2].
    """
    g = np.asarray(gap, dtype=float)
    if np.any(~np.isfinite(g)):
        raise InputError("gap contains NaN or infinite values.")
    h = as_array(height, "height", "m", nonnegative=True)
    t = as_array(films, "films", "m", nonnegative=True)
    k = float(as_array(kelvin, "kelvin", "m", nonnegative=True))
    if k == 0.0:
        return np.zeros(np.broadcast(g, h, t).shape)
    return laplace_pressure(k, surface_tension) * np.maximum(h - np.maximum(g, np.minimum(t, h)), 0.0)


@cites("fisher_gamble_1981", "yang_2020")
def molecular_kelvin_radius(molar_volume=WATER["molar_volume"]):
    """The smallest Kelvin radius of a meniscus [m]: one molecular diameter of the liquid, ``(V_m / N_A)^(1/3)``.

    0.311 nm for water (:func:`water_monolayer_thickness`; r_K reaches it at RH 0.185, 25 degC). Below it the
    condensate cannot be a continuum meniscus: it is an adsorbed film, one molecular layer or less, whose attraction
    is the interface's own (van der Waals, counted by the interface law), not a Laplace pressure. The Kelvin equation
    with bulk water's constants has been checked down to meniscus radii of about 9 nm for water (Fisher, Gamble and
    Middlehurst 1981; menisci of diameter >= 8 nm by the consensus Yang et al. 2020 review) and, in slits under
    0.4 nm that hold one monolayer, found to describe the condensation transition of strongly hydrophilic walls
    (Yang et al. 2020, "fortuitous", by the walls' elastic deformation): one molecular diameter is where a meniscus
    ends, since a smaller radius of curvature has no molecule to make it of. ``molar_volume`` [m^3/mol].
    """
    return water_monolayer_thickness(molar_volume)


def forms_meniscus(kelvin, molar_volume=WATER["molar_volume"]):
    """Whether a condensate of Kelvin radius ``kelvin`` [m] is a meniscus (True) or an adsorbed film (False).

    A meniscus needs r_K at least :func:`molecular_kelvin_radius` (0.311 nm for water); dry air (r_K = 0) forms none.
    """
    k = float(as_array(kelvin, "kelvin", "m", nonnegative=True))
    return k >= molecular_kelvin_radius(molar_volume)


@cites("israelachvili_2011", "butt_kappl_2009")
def meniscus_force_bound(area, perimeter, kelvin, surface_tension=WATER["surface_tension"]):
    """The largest force a meniscus can pull with [N]: ``(gamma / r_K) A + gamma L``, Eqs. (17.3), (17.10) in [3]_.

    The Laplace pressure ``gamma / r_K`` (:func:`laplace_pressure`) over the wetted area ``A`` plus the surface
    tension on its perimeter ``L`` (the liquid-vapour interface pulls each solid with at most ``gamma`` per length of
    contact line: ``gamma sin`` of its angle to the surface, [2]_). No water bridge holds more: any pull-off law of a
    bridged interface is capped by it (:func:`bounded_pull_off`). For a sphere on a flat (``A = 2 pi R h_c``) the
    area term is the closed form :func:`capillary_force_sphere`; for a cylinder (per length, ``A = 2 sqrt(2 R h_c)``)
    it is :func:`capillary_force_cylinder`.

    Parameters
    ----------
    area : numeric
        Wetted area A [m^2] (the gap map's elements narrower than the condensation height), >= 0.
    perimeter : numeric
        Length L [m] of the meniscus's contact line, >= 0.
    kelvin : numeric
        r_K [m] (0: no meniscus, no force).
    surface_tension : numeric
        gamma [N/m].
    """
    a = as_array(area, "area", "m^2", nonnegative=True)
    length = as_array(perimeter, "perimeter", "m", nonnegative=True)
    gamma = as_array(surface_tension, "surface_tension", "N/m", positive=True)
    k = as_array(kelvin, "kelvin", "m", nonnegative=True)
    result = np.where(k > 0, laplace_pressure(k, gamma) * a + gamma * length, 0.0)
    return float(result) if np.ndim(result) == 0 else result


@cites("maugis_1992", "israelachvili_2011")
def bounded_pull_off(crack_force, area, perimeter, kelvin, surface_tension=WATER["surface_tension"]):
    """Pull-off force of a bridged interface [N]: the smaller of its elastic crack law and the meniscus bound.

    ``F = min(F_crack, (gamma / r_K) A + gamma L)`` (:func:`meniscus_force_bound`). The criterion: an elastic
    pull-off law (the thesis's block pull-off (3-32), a Griffith/Kendall crack with the bridge's work) holds only
    where the mean tension it needs over the bridged area, ``F_crack / A``, stays below the Laplace pressure
    ``gamma / r_K`` that the water can hold; past it the bridge fails by its strength, not by a crack (Maugis 1992:
    the Dugdale zone's strength-limited branch). At the gear's block size the crack law needs about 540 MPa, above
    gamma / r_K at every RH below 0.995, so the bound decides there.

    ``crack_force`` [N] (>= 0), ``area`` [m^2], ``perimeter`` [m], ``kelvin`` r_K [m], ``surface_tension`` [N/m].
    """
    crack = as_array(crack_force, "crack_force", "N", nonnegative=True)
    result = np.minimum(crack, meniscus_force_bound(area, perimeter, kelvin, surface_tension))
    return float(result) if np.ndim(result) == 0 else result
