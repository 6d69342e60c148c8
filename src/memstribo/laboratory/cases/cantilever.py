"""A cantilever beam array: crack length and adhesion energy (de Boer and Michalske 1999; MODEL 7e, 7g).

An S-shaped cantilever of thickness t at height h above its substrate, adhered over its tip from the crack length
s onwards, is in fracture equilibrium when the elastic energy release equals the adhesion energy:

    Gamma = 3 E t^3 h^2 / (2 s^4)        (de Boer and Michalske 1999, J. Appl. Phys. 86, 817)

(:func:`beam_adhesion_energy`; :func:`beam_crack_length` inverts it). The model's adhesion energy is the work of
separation of the rough interface under the beam (:func:`work_of_separation`): the two surfaces are pulled apart
from their rough gap field (a rigid beam resting on the highest summit of the combined roughness) to infinity, the
attraction being the interface's vdW surface law and menisci
(:func:`memstribo.laboratory.cases._interface.adhesive_stress`). Smooth, it is w12 (+ 2 gamma cos theta wetted).
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["beam_adhesion_energy", "beam_crack_length", "work_of_separation", "beam_gap_field", "GRID"]

GRID = 128
ELEMENTS_PER_CORRELATION = 4


def _positive(name, value, unit):
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise InputError(f"{name} must be a positive number in {unit}, got {value!r}.")
    return float(value)


@cites("de_boer_michalske_1999")
def beam_adhesion_energy(youngs_modulus, thickness, gap, crack_length):
    """Adhesion energy of an S-shaped adhered cantilever, Gamma = 3 E t^3 h^2 / (2 s^4) [J/m^2].

    de Boer and Michalske (1999), J. Appl. Phys. 86, 817: the beam clamped at its support (height h) and flat
    (zero slope) where it meets the substrate at distance s has the deflection h (1 - 3 (x/s)^2 + 2 (x/s)^3), strain
    energy 6 E I h^2 / s^3 per beam (I = b t^3 / 12), and dU/ds = -Gamma b at equilibrium.

    Parameters
    ----------
    youngs_modulus : float
        E [Pa].
    thickness : float
        t [m].
    gap : float
        h [m], height of the beam above the substrate.
    crack_length : float
        s [m], unattached length.
    """
    e = _positive("youngs_modulus", youngs_modulus, "Pa")
    t, h, s = (_positive(n, v, "m") for n, v in (("beam_thickness", thickness), ("beam_gap", gap),
                                                   ("crack_length", crack_length)))
    return 3.0 * e * t**3 * h**2 / (2.0 * s**4)


@cites("de_boer_michalske_1999")
def beam_crack_length(youngs_modulus, thickness, gap, adhesion_energy):
    """Crack length s = (3 E t^3 h^2 / (2 Gamma))^(1/4) [m] of an adhered cantilever (inverse of
    :func:`beam_adhesion_energy`)."""
    e = _positive("youngs_modulus", youngs_modulus, "Pa")
    t, h = _positive("beam_thickness", thickness, "m"), _positive("beam_gap", gap, "m")
    g = _positive("adhesion_energy", adhesion_energy, "J/m^2")
    return (3.0 * e * t**3 * h**2 / (2.0 * g)) ** 0.25


def beam_gap_field(rq, correlation_length, seed, grid=GRID):
    """Gaps under a rigid beam resting on the highest summit of two rough surfaces of ``rq`` each [m]."""
    from memstribo.laboratory.cases._interface import rough_surface

    if rq == 0:
        return np.zeros((8, 8))
    z = rough_surface(grid, correlation_length / ELEMENTS_PER_CORRELATION, math.sqrt(2.0) * rq, correlation_length, seed)
    return z.max() - z


@cites("maugis_1992", "israelachvili_2011", "model")
def work_of_separation(gap, params, relative_humidity):
    """Work of separation of a rigid rough interface [J/m^2]: (total, vdW part, capillary part).

    The integral over the extra separation s >= 0 of the mean attraction at gaps g + s
    (:func:`memstribo.laboratory.cases._interface.adhesive_stress`): the 9-3 law integrates to w12 on a touching
    interface, the menisci to 2 gamma cos theta over the wetted share.
    """
    from memstribo.laboratory.cases._interface import adhesive_stress
    from memstribo.laboratory.cases._menisci import meniscus_pressure, meniscus_state

    g = np.asarray(gap, dtype=float).ravel()
    s = np.concatenate([[0.0], np.geomspace(1e-13, 2e-6, 900)])
    _, h_c = meniscus_state(params, relative_humidity)
    if h_c > 0:  # the menisci's edge (a step of the Laplace pressure at the bridging height) as grid points
        edges = h_c - np.unique(g)[:200]
        s = np.unique(np.concatenate([s, edges[edges > 0] * (1 - 1e-9), edges[edges > 0] * (1 + 1e-9)]))
    total = np.array([np.mean(adhesive_stress(g + si, params, relative_humidity)) for si in s])
    cap = np.array([np.mean(meniscus_pressure(g + si, params, relative_humidity)) for si in s])
    w_total, w_cap = float(np.trapezoid(total, s)), float(np.trapezoid(cap, s))
    return w_total, w_total - w_cap, w_cap
