"""What every laboratory case shares: the interface's stresses and the rough contact solved with its adhesion.

The interface (MODEL 5, 7c, 7f, 7g), per element of a contact solution of local gap g:

- friction: on the real contact (g = 0) one chemical bond and one vdW bond per D^2 (thesis (3-10), (3-12)); each
  breaks and re-forms once per sliding distance D (3-1), so the kinetic shear stress is (U_chem + U_vdW) / D^3.
  Off contact, the vdW bonds within ``vdw_cutoff`` hold U_vdW (D0 / (D0 + g))^2 (the 'gap' interface of MODEL 7c).
  The static stress takes each bond at its lateral peak, 1.27 U / D per bond (MODEL 7f,
  :func:`memstribo.physics.static_friction.lennard_jones_lateral_peak`), times the share formed at rest (the
  ageing law). Both are capped at the ideal shear strength (a physical bound).
- adhesion: off contact, the Lennard-Jones (9-3) surface law of the pair's work of adhesion at separation D0 + g
  (:func:`memstribo.physics.adhesion.lennard_jones_surface_stress`, at most 16 w / (9 sqrt(3) D0)), plus the menisci
  (:func:`memstribo.laboratory.cases._menisci.meniscus_pressure`, at most gamma / r_K).

The rough contact (:func:`adhesive_contact`) is the elastic-plastic boundary-element solve of
:func:`memstribo.physics.surface_contact.solve_surface_contact` (pressure capped at the hardness) with the adhesion
added to the load it carries (a DMT-type fixed point: the attraction outside the contact presses the contact
spots), iterated until the adhesive force changes by less than 0.5 %.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["contact_modulus", "shear_strengths", "adhesive_stress", "friction_stress", "rough_surface",
           "ContactState", "adhesive_contact", "MIN_CONTACT_ELEMENTS"]

#: fewest contact elements for a resolved real contact area (below: the area is taken from the smallest resolved
#: load, scaled with the load: the real area of a rough contact is proportional to its load at small loads)
MIN_CONTACT_ELEMENTS = 16
#: relative change of the adhesive force that ends the adhesion fixed point
ADHESION_TOLERANCE = 5e-3
ADHESION_ITERATIONS = 40


def contact_modulus(params) -> float:
    """E* of the pair [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson 1985, (4.22)); the counter body's
    constants default to the body's own."""
    e1, n1 = float(params["youngs_modulus"]), float(params["poisson_ratio"])
    e2 = params["counter_youngs_modulus"] or e1
    n2 = params["counter_poisson_ratio"]
    n2 = n1 if n2 is None else float(n2)
    return 1.0 / ((1.0 - n1**2) / e1 + (1.0 - n2**2) / float(e2))


def work_of_adhesion(params) -> float:
    """w12 [J/m^2]: the set's value, else A / (12 pi D0^2) (3-34)."""
    w = params["work_of_adhesion"]
    return float(w) if w else float(params["hamaker_constant"]) / (12 * math.pi * float(params["cutoff_distance"])**2)


@cites("thesis", "model")
def shear_strengths(params):
    """Kinetic and static shear stress of the real contact [Pa], and whether the ideal shear strength capped them.

    Returns
    -------
    tuple
        (tau_kinetic, tau_static, capped): tau_k = (U_chem + U_vdW) / D^3 (3-1, 3-10, 3-12); tau_s = formed share x
        (lateral peak of each bond) / D^2 (MODEL 7f); each at most ``ideal_shear_strength``.
    """
    from memstribo.physics.static_friction import lennard_jones_lateral_peak
    from memstribo.simulations.mesh.limits import formed_share

    d = float(params["bond_length"])
    energies = (float(params["bond_energy"]), float(params["vdw_bond_energy"]))
    kinetic = sum(energies) / d**3
    static = formed_share(params) * sum(float(lennard_jones_lateral_peak(u, d)[0]) for u in energies if u > 0) / d**2
    cap = float(params["ideal_shear_strength"])
    return min(kinetic, cap), min(static, cap), kinetic > cap or static > cap


def adhesive_stress(gap, params, relative_humidity, contact_angles=None) -> np.ndarray:
    """Attraction at each local gap [Pa] (>= 0): the 9-3 surface law at D0 + g plus the menisci; 0 on the contact
    (g = 0: the surfaces at their equilibrium separation, the law's zero)."""
    from memstribo.laboratory.cases._menisci import meniscus_pressure
    from memstribo.physics.adhesion import lennard_jones_surface_stress

    g = np.maximum(np.asarray(gap, dtype=float), 0.0)
    d0 = float(params["cutoff_distance"])
    vdw = np.maximum(-np.asarray(lennard_jones_surface_stress(d0 + g, work_of_adhesion(params), d0)), 0.0)
    return vdw + meniscus_pressure(g, params, relative_humidity, contact_angles)


def friction_stress(gap, contact, params, static=False) -> np.ndarray:
    """Shear stress of each element [Pa]: the bonds' stress on the contact, the vdW bonds at their gap off it."""
    from memstribo.physics.static_friction import LATERAL_PEAK_FORCE
    from memstribo.simulations.mesh.limits import formed_share

    tau_k, tau_s, _ = shear_strengths(params)
    d, d0 = float(params["bond_length"]), float(params["cutoff_distance"])
    g = np.maximum(np.asarray(gap, dtype=float), 0.0)
    near = (~contact) & (g < float(params["vdw_cutoff"]))
    vdw = float(params["vdw_bond_energy"]) / d**3 * (d0 / (d0 + g)) ** 2
    if static:
        vdw = vdw * LATERAL_PEAK_FORCE * formed_share(params)
    vdw = np.minimum(vdw, float(params["ideal_shear_strength"]))
    return np.where(contact, tau_s if static else tau_k, np.where(near, vdw, 0.0))


def rough_surface(n, dx, rq, correlation_length, seed) -> np.ndarray:
    """A periodic Gaussian random surface [m], shape (n, n): rms ``rq``, autocorrelation exp(-r^2 / l^2)
    (a Gaussian filter of white noise in Fourier space); zero mean. ``rq = 0``: flat."""
    if rq == 0:
        return np.zeros((n, n))
    rng = np.random.default_rng(seed)
    q = 2 * np.pi * np.fft.fftfreq(n, dx)
    q2 = q[None, :] ** 2 + q[:, None] ** 2
    z = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal((n, n))) * np.exp(-q2 * correlation_length**2 / 8)))
    z -= z.mean()
    return z * (rq / z.std())


@dataclass(frozen=True)
class ContactState:
    """A rough contact solved with its adhesion.

    Attributes
    ----------
    gap : ndarray
        Deformed gaps [m] (0 on the contact).
    contact : ndarray of bool
    element_area : float
        dx dy [m^2].
    load : float
        External normal force W [N] (>= 0).
    adhesion : float
        Adhesive force F_adh [N] (the attraction off the contact, vdW + menisci).
    real_area : float
        Real contact area [m^2] (resolved, or scaled from the smallest resolved load: see ``note``).
    resolved : bool
        Whether the real area was resolved at this load (at least :data:`MIN_CONTACT_ELEMENTS` elements).
    plastic_fraction : float
        Share of the contact at the hardness [-].
    converged : bool
    note : str
    """

    gap: np.ndarray
    contact: np.ndarray
    element_area: float
    load: float
    adhesion: float
    real_area: float
    resolved: bool
    plastic_fraction: float
    converged: bool
    note: str = ""


def _solve(h, dx, modulus, hardness, total, periodic):
    from memstribo.physics.surface_contact import solve_surface_contact

    return solve_surface_contact(h, dx, dx, modulus, load=total, periodic=periodic, hardness=hardness)


@cites("johnson_1985", "polonsky_keer_1999", "almqvist_2007", "model")
def adhesive_contact(h, dx, params, load, relative_humidity, *, periodic, adhesion=True, contact_angles=None):
    """Solve the rough contact of undeformed gap ``h`` [m] under ``load`` [N] with its adhesion (module docstring).

    Parameters
    ----------
    h : ndarray
        Undeformed gap (n, n) [m]; only differences matter.
    dx : float
        Element size [m].
    params : memstribo.parameters.Parameters
        E, nu (and the counter body's), ``hardness``, the adhesion constants.
    load : float
        External normal force [N], >= 0 (0: held by its adhesion alone, when ``adhesion``).
    relative_humidity : float or None
    periodic : bool
        Periodic half-space (a patch of a nominally flat pad) or free boundary (a sphere).
    adhesion : bool
        False: the bare elastic-plastic contact (the smooth-limit checks against Hertz).

    Returns
    -------
    ContactState
    """
    key = (np.asarray(h, dtype=float).tobytes(), h.shape, float(dx), contact_modulus(params), float(params["hardness"]),
           float(load), relative_humidity, periodic, adhesion, contact_angles, work_of_adhesion(params),
           float(params["cutoff_distance"]), float(params["water_contact_angle"]), float(params["ambient_temperature"]),
           params["vapour"], params["surface_termination"], params["vapour_pressure_ratio"])
    return _cached_contact(key, np.asarray(h, dtype=float), params)




_CACHE: dict = {}


def _cached_contact(key, h, params):
    if key in _CACHE:
        return _CACHE[key]
    if len(_CACHE) > 256:
        _CACHE.clear()
    _, _, dx, modulus, hardness, load, rh, periodic, adhesion, angles = key[:10]
    area = h.size * dx * dx
    f_adh, converged, sol = 0.0, True, None
    for _ in range(ADHESION_ITERATIONS if adhesion else 1):
        total = load + f_adh
        if total <= 0:
            total = 1e-6 * float(hardness) * dx * dx  # held by adhesion alone: start from a touching summit
        sol = _solve(h, dx, modulus, hardness, total, periodic)
        if not adhesion:
            break
        new = float(np.sum(adhesive_stress(np.where(sol.contact, 0.0, sol.gap), params, rh, angles)) * dx * dx)
        done = abs(new - f_adh) <= ADHESION_TOLERANCE * max(new, 1e-300)
        f_adh = new if f_adh == 0.0 else 0.5 * (f_adh + new)
        if done:
            break
    else:
        converged = False
    converged = converged and bool(sol.converged)
    total = load + f_adh
    n_contact = int(np.count_nonzero(sol.contact))
    real, note, resolved = n_contact * dx * dx, "", n_contact >= MIN_CONTACT_ELEMENTS
    if not resolved and periodic:
        real, note = _scaled_area(h, dx, modulus, hardness, total, area)
    elif not resolved:
        note = f"only {n_contact} elements touch: the real contact area is under-resolved"
    state = ContactState(gap=np.where(sol.contact, 0.0, sol.gap), contact=np.asarray(sol.contact), element_area=dx * dx,
                         load=float(load), adhesion=f_adh, real_area=real, resolved=resolved,
                         plastic_fraction=float(sol.plastic_fraction), converged=converged, note=note)
    _CACHE[key] = state
    return state


def _scaled_area(h, dx, modulus, hardness, total, area):
    """The real area at a load too small to resolve: A(W_r) W / W_r at the smallest doubled load W_r holding
    MIN_CONTACT_ELEMENTS elements (the real area of a rough contact grows in proportion to a small load)."""
    trial = max(total, 1e-9 * area * modulus)
    for _ in range(60):
        sol = _solve(h, dx, modulus, hardness, trial, True)
        n = int(np.count_nonzero(sol.contact))
        if n >= MIN_CONTACT_ELEMENTS:
            real = n * dx * dx * total / trial
            return real, (f"real area below the grid's resolution at this load: {n} elements touch at "
                          f"{trial / area:.3g} Pa, scaled in proportion to the load")
        trial *= 2.0
    raise InputError("the rough contact never resolved its real area (the patch is too coarse for this roughness).")
