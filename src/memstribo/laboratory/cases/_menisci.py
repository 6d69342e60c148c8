"""The menisci of every laboratory case, through one function (MODEL 7g).

Every case of :mod:`memstribo.laboratory.cases` asks :func:`meniscus_pressure` for the attraction of condensed
water at its local gaps, so that the capillary physics can be replaced in one place (the bounded-meniscus model
of MODEL 7g). Today it calls :mod:`memstribo.physics.capillary`: the Kelvin radius of the humidity, the
condensation height r_K (cos theta_1 + cos theta_2), and the Laplace pressure gamma / r_K over the wetted
elements, never more (the meniscus's physical bound).
"""

from __future__ import annotations

import numpy as np

from memstribo.references import cites

__all__ = ["meniscus_pressure"]


@cites("israelachvili_2011", "model")
def meniscus_pressure(gap, params, relative_humidity, contact_angles=None):
    """Attractive meniscus pressure at each local gap [Pa] (0 where dry), at most the Laplace pressure gamma / r_K.

    Parameters
    ----------
    gap : array_like
        Local gaps between the surfaces [m], >= 0 (0 in contact: the contact spots are wetted around).
    params : memstribo.parameters.Parameters
        Uses ``ambient_temperature`` and ``water_contact_angle`` (when ``contact_angles`` is None).
    relative_humidity : float or None
        RH [-] in [0, 1); 0 or None: no menisci.
    contact_angles : tuple of float, optional
        Water contact angles of the two surfaces [rad]; default both ``water_contact_angle``.

    Returns
    -------
    ndarray
        Pressure [Pa], the shape of ``gap``; Eq. (17.3) and (17.21) of Israelachvili (2011) through
        :func:`memstribo.physics.capillary.capillary_pressure`.
    """
    from memstribo.physics import capillary

    g = np.asarray(gap, dtype=float)
    if not relative_humidity:
        return np.zeros_like(g)
    theta = params["water_contact_angle"]
    t1, t2 = contact_angles if contact_angles is not None else (theta, theta)
    r_k = capillary.kelvin_radius(float(relative_humidity), params["ambient_temperature"])
    return np.asarray(capillary.capillary_pressure(g, r_k, t1, t2), dtype=float)
