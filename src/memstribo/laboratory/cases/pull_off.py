"""Pull-off force of a probe (sphere) or a plate on a flat (MODEL 7c, 7e, 7g).

- Smooth probe: the Maugis-Dugdale sphere (Maugis 1992) with the Dugdale stress of the pair's 9-3 law
  (:func:`memstribo.physics.adhesion.maugis_stress`): :func:`maugis_dugdale_sphere_pull_off`, from DMT (2 pi w R,
  small Tabor-Maugis parameter) to JKR (3/2 pi w R, large). The menisci add their force, integrated over the gap.
- Rough probe or plate: the surfaces rigid at their rough gap field (the probe touching the highest summit); the
  pull-off is the largest total attraction over the extra separation, max_s sum sigma(g + s) dA
  (:func:`rigid_pull_off`) with the interface's vdW law and menisci
  (:func:`memstribo.laboratory.cases._interface.adhesive_stress`); a smooth rigid sphere gives DMT's 2 pi w R and a
  smooth plate 16 w / (9 sqrt(3) D0) per area, the 9-3 law's largest stress. Rough contacts are DMT-like (small
  asperity radii: small Tabor parameters); the elastic flattening of the asperities is neglected (said in the case).
Every force stays below its bound: the vdW stress below 16 w / (9 sqrt(3) D0), the menisci below gamma / r_K.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["maugis_dugdale_sphere_load", "maugis_dugdale_sphere_pull_off", "rigid_pull_off", "probe_pull_off",
           "plate_pull_off"]


def _maugis_m(a_bar, lam):
    def eq(m):
        root, acos = math.sqrt(m * m - 1.0), math.acos(1.0 / m)
        return (lam * a_bar**2 / 2.0 * ((m * m - 2.0) * acos + root)
                + 4.0 * lam**2 * a_bar / 3.0 * (root * acos - m + 1.0) - 1.0)

    hi = 2.0
    while eq(hi) < 0:
        hi = 1.0 + 2.0 * (hi - 1.0)
        if hi > 1e12:
            raise InputError("Maugis-Dugdale: no cohesive zone solves the energy balance.")
    return brentq(eq, 1.0 + 1e-15, hi, xtol=1e-14)


@cites("maugis_1992")
def maugis_dugdale_sphere_load(a_bar, parameter):
    """Maugis (1992) sphere: the load P / (pi w R) at contact radius A = a (K / (pi w R^2))^(1/3), K = 4/3 E*.

    With m = c / a (c: the edge of the Dugdale zone) from
    lambda A^2 / 2 [(m^2 - 2) arccos(1/m) + sqrt(m^2 - 1)] + 4 lambda^2 A / 3 [sqrt(m^2 - 1) arccos(1/m) - m + 1] = 1,
    P / (pi w R) = A^3 - lambda A^2 [sqrt(m^2 - 1) + m^2 arccos(1/m)]; ``parameter`` lambda = 2 sigma0 (R / (pi w K^2))^(1/3).
    """
    m = _maugis_m(a_bar, parameter)
    return a_bar**3 - parameter * a_bar**2 * (math.sqrt(m * m - 1.0) + m * m * math.acos(1.0 / m))


@cites("maugis_1992", "johnson_1985")
def maugis_dugdale_sphere_pull_off(radius, contact_modulus, work_of_adhesion, cohesive_stress):
    """Pull-off force of a smooth elastic sphere on a flat [N] (Maugis 1992; load control: the least load).

    Parameters
    ----------
    radius : float
        R [m].
    contact_modulus : float
        E* [Pa].
    work_of_adhesion : float
        w [J/m^2].
    cohesive_stress : float
        Dugdale stress sigma0 [Pa].

    Returns
    -------
    tuple
        (pull-off force [N] (positive: tensile), Maugis parameter lambda [-]). Limits: 2 pi w R (DMT, lambda -> 0)
        and 3/2 pi w R (JKR, lambda -> infinity).
    """
    k = 4.0 / 3.0 * contact_modulus
    lam = 2.0 * cohesive_stress * (radius / (math.pi * work_of_adhesion * k * k)) ** (1.0 / 3.0)
    res = minimize_scalar(lambda a: maugis_dugdale_sphere_load(a, lam), bounds=(1e-6, 5.0), method="bounded",
                          options={"xatol": 1e-10})
    return -float(res.fun) * math.pi * work_of_adhesion * radius, lam


@cites("maugis_1992", "model")
def rigid_pull_off(gap, element_area, params, relative_humidity, contact_angles=None):
    """The largest total attraction of a rigid gap field over the extra separation [N]: (total, capillary part)."""
    from memstribo.laboratory.cases._interface import adhesive_stress
    from memstribo.laboratory.cases._menisci import meniscus_pressure

    g = np.asarray(gap, dtype=float)
    best, cap_best = 0.0, 0.0
    for s in np.concatenate([[0.0], np.geomspace(1e-13, 5e-9, 300)]):
        total = float(np.sum(adhesive_stress(g + s, params, relative_humidity, contact_angles))) * element_area
        if total > best:
            best = total
            cap_best = float(np.sum(meniscus_pressure(g + s, params, relative_humidity, contact_angles))) * element_area
    return best, cap_best


def probe_pull_off(params, radius, rq=0.0, correlation_length=None, seed=0, relative_humidity=None, grid=256):
    """Pull-off force of a probe of ``radius`` [m] on a flat [N] and the case in words (module docstring)."""
    from memstribo.laboratory.cases._interface import contact_modulus, rough_surface, work_of_adhesion
    from memstribo.physics.adhesion import maugis_stress

    if not (radius > 0 and math.isfinite(radius)):
        raise InputError(f"sphere_radius must be a positive length in m, got {radius!r}.")
    w, d0 = work_of_adhesion(params), float(params["cutoff_distance"])
    window = 2.0 * math.sqrt(2.0 * radius * 20e-9)  # where the gap reaches 20 nm: beyond it no attraction counts
    if rq > 0:
        window = max(window, 8 * correlation_length)
    dx = window / grid
    x = (np.arange(grid) - grid / 2 + 0.5) * dx
    h = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius)
    if rq > 0:
        z = rough_surface(grid, dx, math.sqrt(2.0) * rq, correlation_length, seed)
        h = h + z.max() - z
        h = h - h.min()
        force, cap = rigid_pull_off(h, dx * dx, params, relative_humidity)
        return force, (f"rigid rough probe (R {radius:.3g} m, Rq {rq:.3g} m each surface): the largest attraction "
                       f"of its gap field, menisci {cap:.3g} N")
    vdw, lam = maugis_dugdale_sphere_pull_off(radius, contact_modulus(params), w, float(maugis_stress(w, d0)))
    _, cap = rigid_pull_off(h, dx * dx, params, relative_humidity)
    return vdw + cap, (f"smooth elastic probe (R {radius:.3g} m): Maugis-Dugdale pull-off, lambda {lam:.3g}, "
                       f"{vdw:.3g} N, plus menisci {cap:.3g} N")


def plate_pull_off(params, area, rq=0.0, correlation_length=None, seed=0, relative_humidity=None, grid=128):
    """Pull-off force of a flat plate of ``area`` [m^2] [N] and the case in words (module docstring)."""
    from memstribo.laboratory.cases._interface import rough_surface

    if not (area > 0 and math.isfinite(area)):
        raise InputError(f"pad_area must be a positive area in m^2, got {area!r}.")
    if rq > 0:
        dx = correlation_length / 4
        z = rough_surface(grid, dx, math.sqrt(2.0) * rq, correlation_length, seed)
        per_area, cap = rigid_pull_off(z.max() - z, 1.0 / z.size, params, relative_humidity)
    else:
        per_area, cap = rigid_pull_off(np.zeros((1, 1)), 1.0, params, relative_humidity)
    return per_area * area, f"rigid plate of {area:.3g} m^2: the largest attraction per area {per_area:.3g} Pa"
