"""A sphere or pin on a flat, of any radius: Hertz plus roughness through the rough contact solve (MODEL 7e).

The undeformed gap is the sphere's r^2 / (2R) plus the combined roughness of the two surfaces; the free-boundary
elastic-plastic solve with its adhesion (:func:`memstribo.laboratory.cases._interface.adhesive_contact`) under the
normal force F gives the contact, the real area and the adhesive force; friction and COF as for the flat pad
(mu = F_f / (F + F_adh), thesis (3-7)). The window is 5 Hertz radii of the load plus a DMT adhesion estimate
(Johnson 1985 (4.22)); where the roughness cannot be resolved in it with :data:`MAX_GRID` elements (a sphere far
larger than the roughness's correlation length), the contact is the flat pad under the Hertz mean pressure
F / (pi a^2), said in the note. Smooth (rq = 0, no adhesion) the contact area is Hertz's pi a^2.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["sphere_contact", "sphere_friction", "GRID", "MAX_GRID"]

GRID = 128
MAX_GRID = 256
#: elements per correlation length of the roughness (at least)
ELEMENTS_PER_CORRELATION = 4


@cites("johnson_1985", "model")
def sphere_contact(params, force, radius, rq=0.0, correlation_length=None, seed=0, relative_humidity=None,
                   adhesion=True):
    """The contact of a sphere of ``radius`` [m] on a flat under ``force`` [N] (module docstring).

    Returns
    -------
    ContactState or None
        None when the roughness cannot be resolved in the window (the caller takes the flat pad).
    """
    from memstribo.laboratory.cases._interface import adhesive_contact, contact_modulus, rough_surface, work_of_adhesion
    from memstribo.physics.closed_form import hertz_sphere_radius

    if not (radius > 0 and math.isfinite(radius)):
        raise InputError(f"sphere_radius must be a positive length in m, got {radius!r}.")
    if not (force >= 0 and math.isfinite(force)):
        raise InputError(f"normal_force must be a finite force >= 0 N, got {force!r}.")
    modulus = contact_modulus(params)
    sizing = force + (2 * math.pi * radius * work_of_adhesion(params) if adhesion else 0.0)
    a = float(hertz_sphere_radius(max(sizing, 1e-12), radius, modulus))
    window = 5.0 * a
    grid = GRID
    if rq > 0:
        needed = int(math.ceil(window / (correlation_length / ELEMENTS_PER_CORRELATION)))
        if needed > MAX_GRID:
            return None
        grid = max(GRID, needed + needed % 2)
    dx = window / grid
    x = (np.arange(grid) - grid / 2 + 0.5) * dx
    h = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius)
    if rq > 0:
        z = rough_surface(grid, dx, math.sqrt(2.0) * rq, correlation_length, seed)
        h = h + (z.max() - z)
    return adhesive_contact(h, dx, params, force, relative_humidity, periodic=False, adhesion=adhesion)


@cites("thesis", "johnson_1985", "model")
def sphere_friction(params, force, radius, rq=0.0, correlation_length=None, seed=0, relative_humidity=None,
                    adhesion=True) -> dict:
    """Static and kinetic COF of a sphere on a flat, its real area and interfacial shear stress.

    Returns
    -------
    dict
        ``kinetic_cof``, ``static_cof`` [-], ``real_area`` [m^2], ``adhesion_force`` [N], ``shear_strength``
        F_f / A_r [Pa] (kinetic), ``plastic_fraction``, ``converged``, ``note``.
    """
    from memstribo.laboratory.cases._interface import friction_stress, shear_strengths
    from memstribo.physics.closed_form import hertz_sphere_radius

    state = sphere_contact(params, force, radius, rq, correlation_length, seed, relative_humidity, adhesion)
    if state is None:
        from memstribo.laboratory.cases.flat_pad import flat_pad_friction
        from memstribo.laboratory.cases._interface import contact_modulus

        a = float(hertz_sphere_radius(force, radius, contact_modulus(params)))
        mean = force / (math.pi * a * a)
        out = flat_pad_friction(params, mean, rq, correlation_length, seed, relative_humidity, adhesion)
        out["note"] = (f"sphere far larger than the roughness's correlation length: the flat pad under the Hertz mean "
                       f"pressure {mean:.3g} Pa over pi a^2 = {math.pi * a * a:.3g} m^2. " + out["note"]).strip()
        out["shear_strength"] = out["kinetic_cof"] * (mean + out["adhesion_pressure"]) / max(out["real_area_fraction"], 1e-300)
        return out
    pressing = state.load + state.adhesion
    tau_k, tau_s, capped = shear_strengths(params)
    out = {"real_area": state.real_area, "adhesion_force": state.adhesion, "plastic_fraction": state.plastic_fraction,
           "converged": state.converged, "note": state.note, "capped": capped, "resolved": state.resolved}
    for key, static, tau in (("kinetic", False, tau_k), ("static", True, tau_s)):
        off = friction_stress(state.gap, state.contact, params, static)
        friction = tau * state.real_area + float(np.sum(np.where(state.contact, 0.0, off))) * state.element_area
        out[f"{key}_cof"] = friction / pressing if pressing > 0 else math.nan
        if key == "kinetic":
            out["shear_strength"] = friction / state.real_area if state.real_area > 0 else math.nan
    return out
