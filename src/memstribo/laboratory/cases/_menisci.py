"""The menisci of every laboratory case, through one function (MODEL 7g).

Every case of :mod:`memstribo.laboratory.cases` asks :func:`meniscus_pressure` for the attraction of condensed
water at its local gaps, so that the capillary physics can be replaced in one place (the bounded-meniscus model
of MODEL 7g). It uses the bounded-meniscus physics of issue 36: the vapour and surface termination of the parameter set
(:mod:`memstribo.physics.vapours`), no meniscus below a molecular Kelvin radius (an adsorbed film), the bridging
height r_K (cos theta_1 + cos theta_2) plus the liquid-like films, and the Laplace pressure gamma / r_K over the
wetted elements, never more (the meniscus's physical bound).
"""

from __future__ import annotations

import numpy as np

from memstribo.references import cites

__all__ = ["meniscus_pressure", "meniscus_state"]


@cites("israelachvili_2011", "model")
def meniscus_pressure(gap, params, relative_humidity, contact_angles=None):
    """Attractive meniscus pressure at each local gap [Pa] (0 where dry), at most the Laplace pressure gamma / r_K.

    Parameters
    ----------
    gap : array_like
        Local gaps between the surfaces [m], >= 0 (0 in contact: the contact spots are wetted around).
    params : memstribo.parameters.Parameters
        Uses ``vapour``, ``surface_termination``, ``ambient_temperature`` and ``water_contact_angle``.
    relative_humidity : float or None
        RH [-] in [0, 1); 0 or None: no menisci. The set's ``vapour_pressure_ratio``, when given, replaces it
        (the vapour's p / p_sat).
    contact_angles : tuple of float, optional
        Contact angles of the two surfaces [rad] (coated surfaces); default both the vapour's angle on the
        set's termination, with its liquid-like adsorbed film.

    Returns
    -------
    ndarray
        Pressure [Pa], the shape of ``gap``; Eq. (17.3) and (17.21) of Israelachvili (2011), the bridging height
        of :func:`memstribo.physics.capillary.bridging_height`.
    """
    g = np.asarray(gap, dtype=float)
    pressure, height = meniscus_state(params, relative_humidity, contact_angles)
    return np.where((g <= height) & (height > 0), pressure, 0.0)


def meniscus_state(params, relative_humidity, contact_angles=None):
    """(Laplace pressure gamma / r_K [Pa], bridging height [m]) of the condensate; (0, 0) when no meniscus forms.

    The arguments are :func:`meniscus_pressure`'s; the height is r_K (cos theta_1 + cos theta_2) plus the liquid-like
    films (:func:`memstribo.physics.capillary.bridging_height`), 0 below a molecular Kelvin radius.
    """
    from memstribo.physics import capillary
    from memstribo.physics.vapours import (liquid_film_thickness, vapour_contact_angle, vapour_properties,
                                           vapour_surface_tension)

    if not relative_humidity:
        return 0.0, 0.0
    if params["vapour_pressure_ratio"] is not None:  # another vapour's p / p_sat (vapours.vapour_state's rule)
        relative_humidity = params["vapour_pressure_ratio"]
    vapour, termination = params["vapour"], params["surface_termination"]
    gamma = vapour_surface_tension(vapour, params["ambient_temperature"])
    molar_volume = vapour_properties(vapour)["molar_volume"]
    r_k = capillary.kelvin_radius(float(relative_humidity), params["ambient_temperature"], gamma, molar_volume)
    if not capillary.forms_meniscus(r_k, molar_volume):  # below a molecular Kelvin radius: an adsorbed film (MODEL 7g)
        return 0.0, 0.0
    if contact_angles is None:  # bare surfaces of the set's termination: its angle and the liquid-like film
        theta = vapour_contact_angle(vapour, termination, params["water_contact_angle"])
        t1 = t2 = theta
        film = liquid_film_thickness(vapour, termination, float(relative_humidity))
    else:  # coated surfaces: their own angles, no liquid film counted
        t1, t2 = contact_angles
        film = 0.0
    height = float(capillary.bridging_height(r_k, film, film, t1, t2))
    return float(capillary.laplace_pressure(r_k, gamma)), height
