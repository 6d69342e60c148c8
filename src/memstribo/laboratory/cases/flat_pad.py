"""Flat pads on a substrate under a nominal pressure: the real contact area from the rough contact solve (MODEL 7e).

A square patch of the pad (periodic, :data:`GRID` elements a side, ``correlation_length / 6`` each) carries the
combined roughness of the two surfaces (Rq sqrt(2) for two surfaces of Rq each) and the nominal pressure p. The
elastic-plastic boundary-element solve with its adhesion (:func:`memstribo.laboratory.cases._interface.adhesive_contact`)
gives the real contact area A_r and the adhesive force F_adh; the friction is the bonds' shear stress over A_r plus
the vdW bonds off it (:func:`memstribo.laboratory.cases._interface.friction_stress`); the coefficient is

    mu = F_f / (W + F_adh)        (thesis (3-7): friction over the normal force plus the adhesion force),

so that mu follows A_r / W: it changes with the nominal pressure where the real area is not proportional to the
load (adhesion at low pressure, plastic saturation and the approach to full contact at high pressure).

Known limit: where the load is too small for the grid to resolve the real area (fewer than
:data:`memstribo.laboratory.cases._interface.MIN_CONTACT_ELEMENTS` elements touch) the adhesive force rests on the
few elements beside the contact spots, whose sub-nanometre gaps the grid does not resolve: on silicon_thesis at
1.7 kPa (Rq 10.3 nm, l 83 nm) F_adh / A was 74 kPa at l / 6 and 330 kPa at l / 12, the COF 0.91 and 1.13. The case
says so in its note; the spread over realisations (0.91 and 1.47 for two seeds) is part of the band.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["GRID", "flat_pad_contact", "flat_pad_friction"]

#: elements a side of the pad's patch
GRID = 128
#: elements per correlation length of the roughness
ELEMENTS_PER_CORRELATION = 6


def flat_pad_contact(params, pressure, rq, correlation_length, seed, relative_humidity=None, adhesion=True, grid=GRID):
    """The contact of a patch of the pad under nominal ``pressure`` [Pa] (>= 0; 0: held by its adhesion alone).

    ``rq`` [m] is each surface's rms roughness (the patch carries sqrt(2) rq), ``correlation_length`` [m] the
    Gaussian autocorrelation length. Returns (:class:`~memstribo.laboratory.cases._interface.ContactState`, patch
    area [m^2]).
    """
    from memstribo.laboratory.cases._interface import adhesive_contact, rough_surface

    if not (pressure >= 0 and math.isfinite(pressure)):
        raise InputError(f"contact_pressure must be a finite number >= 0 Pa, got {pressure!r}.")
    if pressure > float(params["hardness"]):
        raise InputError(f"contact_pressure {pressure:.3g} Pa is above the hardness {params['hardness']:.3g} Pa of the "
                         "softer body: the pad would flow plastically over its whole area (outside the model's range).")
    if rq <= 0 or correlation_length <= 0:
        raise InputError("a flat pad needs a positive roughness rq and correlation_length (m).")
    dx = correlation_length / ELEMENTS_PER_CORRELATION
    z = rough_surface(grid, dx, math.sqrt(2.0) * rq, correlation_length, seed)
    area = grid * grid * dx * dx
    state = adhesive_contact(z.max() - z, dx, params, pressure * area, relative_humidity, periodic=True,
                             adhesion=adhesion)
    return state, area


@cites("thesis", "model")
def flat_pad_friction(params, pressure, rq, correlation_length, seed, relative_humidity=None, adhesion=True,
                      grid=GRID) -> dict:
    """Static and kinetic COF of a flat pad under nominal pressure ``pressure`` [Pa] (module docstring).

    Returns
    -------
    dict
        ``kinetic_cof``, ``static_cof`` [-], ``real_area_fraction`` A_r / A [-], ``adhesion_pressure`` F_adh / A [Pa],
        ``plastic_fraction`` [-], ``resolved`` (bool), ``converged`` (bool), ``note``.
    """
    from memstribo.laboratory.cases._interface import friction_stress, shear_strengths

    state, area = flat_pad_contact(params, pressure, rq, correlation_length, seed, relative_humidity, adhesion, grid)
    out = {"real_area_fraction": state.real_area / area, "adhesion_pressure": state.adhesion / area,
           "plastic_fraction": state.plastic_fraction, "resolved": state.resolved, "converged": state.converged,
           "note": state.note, "capped": shear_strengths(params)[2]}
    pressing = state.load + state.adhesion
    if pressing <= 0:
        raise InputError("the pad is neither loaded nor adhering: no friction coefficient.")
    tau_k, tau_s, _ = shear_strengths(params)
    for key, static, tau in (("kinetic_cof", False, tau_k), ("static_cof", True, tau_s)):
        off = friction_stress(state.gap, state.contact, params, static)
        off_contact = float(np.sum(np.where(state.contact, 0.0, off))) * state.element_area
        out[key] = (tau * state.real_area + off_contact) / pressing
    return out
