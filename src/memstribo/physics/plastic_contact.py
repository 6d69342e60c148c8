"""Rough line contact with the pressure capped at the hardness: elastic-perfectly-plastic saturation.

Real scans are rougher than the thesis's statistics; their asperity pressures pass the elastic
limit of silicon in nearly every step of a meshing cycle (MODEL 7d). Where the elastic solution
would press harder than the hardness ``H`` of the softer body, the material flows: the pressure
saturates at ``H`` and the surfaces close in by plastic flattening (the gap there would be
negative, an interpenetration, which is the plastic deformation). This is the
elastic-perfectly-plastic surface model of the peer BEM codes (Tamaas' ``KatoSaturated``,
ContactMechanics' ``PlasticTopography``; Almqvist et al. 2007; Sahlin et al. 2010):

    0 <= p <= H,   g = h + u(p) - delta,
    g = 0 where 0 < p < H (elastic contact),   g <= 0 where p = H (plastic),   g >= 0 where p = 0,
    dx * sum(p) = w.

It is solved here by an active set on the plastic elements P around the elastic solver
(:func:`memstribo.physics.contact.solve_line_contact`, unchanged): with P fixed at p = H, the
rest is the elastic problem with the gap raised by the displacement of the plastic pressure,
``h + u(H 1_P)``, and the load ``w - H dx |P|`` (the elements of P are lifted out of reach);
then elements of the elastic solution above H join P and elements of P whose gap opens
(g > 0) leave, until P no longer changes. Without any element above H this is the elastic
solution itself, bit for bit.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["PlasticContactSolution", "solve_line_contact_capped"]

#: Updates of the plastic set before the capped solve gives up (converged=False).
_MAX_PLASTIC_UPDATES = 60


@dataclasses.dataclass(frozen=True)
class PlasticContactSolution:
    """A line-contact solution with the pressure capped at the hardness.

    Attributes
    ----------
    solution : memstribo.physics.contact.ContactSolution
        The contact solution (pressure <= hardness [Pa]; gap [m], 0 on the plastic elements;
        contact mask including them; approach [m]; load [N/m]; converged and message over the
        whole capped solve).
    plastic : numpy.ndarray
        Boolean mask of the elements in plastic flow (p = hardness).
    plastic_depth : numpy.ndarray
        Depth of plastic flattening of each element [m], >= 0 (the interpenetration h + u - delta
        the elastic bodies would have there; 0 outside ``plastic``).
    plastic_load : float
        Line load carried at the hardness, H dx |P| [N/m].
    updates : int
        Updates of the plastic set [-].
    """

    solution: object
    plastic: np.ndarray
    plastic_depth: np.ndarray
    plastic_load: float
    updates: int

    @property
    def plastic_fraction(self) -> float:
        """Share of the contact elements in plastic flow [-] (0 without contact)."""
        n_contact = int(np.count_nonzero(self.solution.contact))
        return float(np.count_nonzero(self.plastic) / n_contact) if n_contact else 0.0


@cites("johnson_1985", "almqvist_2007", "model")
def solve_line_contact_capped(separation, dx, contact_modulus, *, hardness, load, periodic=False,
                              reference_distance=None, initial_pressure=None, **options) -> PlasticContactSolution:
    """Rough line contact under a load with the pressure capped at the hardness (elastic-perfectly-plastic).

    Parameters
    ----------
    separation : array_like
        Undeformed gap h(x) [m] on a uniform grid (as :func:`memstribo.physics.contact.solve_line_contact`).
    dx : float
        Element width [m].
    contact_modulus : float
        E* [Pa].
    hardness : float or None
        Largest contact pressure H [Pa] (the indentation hardness of the softer body, e.g.
        ``hardness`` of the parameter set); None: no cap (the elastic solution).
    load : float
        Line load w [N/m] (load control).
    periodic, reference_distance, initial_pressure
        As for :func:`memstribo.physics.contact.solve_line_contact`; ``initial_pressure`` [Pa] is
        the warm start (e.g. the previous step's capped pressure).
    **options
        Passed to the elastic solves (``tolerance``, ``cohesive_stress``, ``cohesive_range``,
        ``capillary_stress``, ``capillary_range``, ...).

    Returns
    -------
    PlasticContactSolution

    Raises
    ------
    InputError
        A hardness that is not a positive number.

    Notes
    -----
    The KKT conditions of the bound-constrained minimum of the complementary energy
    (1/2 p^T A p + p^T h subject to 0 <= p <= H and the load), solved by an active set on the
    upper bound (module docstring). The elastic pressure field of each set is
    :func:`~memstribo.physics.contact.solve_line_contact`'s, so the tolerance and convergence
    report are the elastic solver's; the capped solve is converged when the last elastic solve
    is and the plastic set has settled (checked against Tamaas' saturated solver in
    docs/mesh.md).
    """
    from memstribo.physics.contact import elastic_displacement, solve_line_contact

    h = np.asarray(separation, dtype=float)
    common = dict(periodic=periodic, reference_distance=reference_distance, **options)
    if hardness is None:
        sol = solve_line_contact(h, dx, contact_modulus, load=load, initial_pressure=initial_pressure, **common)
        return PlasticContactSolution(sol, np.zeros(h.shape, bool), np.zeros(h.shape), 0.0, 0)
    hardness = float(hardness)
    if not np.isfinite(hardness) or hardness <= 0:
        raise InputError(f"hardness must be a positive pressure [Pa], got {hardness!r}.")
    start = None if initial_pressure is None else np.asarray(initial_pressure, dtype=float)
    sol = solve_line_contact(h, dx, contact_modulus, load=load, initial_pressure=start, **common)
    plastic = sol.pressure > hardness
    if not plastic.any():
        return PlasticContactSolution(sol, plastic, np.zeros(h.shape), 0.0, 0)
    displacement = {}  # displacement of a unit pressure on a set, cached by the set's bytes

    def lifted(mask):
        """h + u(H 1_P), and the elements of P lifted out of reach (by the peak-to-valley, at least once)."""
        key = mask.tobytes()
        if key not in displacement:
            displacement[key] = elastic_displacement(np.where(mask, hardness, 0.0), dx, contact_modulus,
                                                     periodic=periodic, reference_distance=reference_distance)
        raised = h + displacement[key]
        free = ~mask
        top = float(raised[free].max()) if free.any() else float(raised.max())
        lift = max(float(np.ptp(raised)), 1e-12)
        return raised, np.where(mask, np.maximum(raised, top) + lift, raised), displacement[key]

    updates = 0
    inner, gap_all, delta = sol, np.zeros(h.shape), float(sol.approach)
    history = set()
    converged = True
    message = ""
    while True:
        updates += 1
        raised, inner_h, u_plastic = lifted(plastic)
        rest = float(load) - hardness * dx * int(np.count_nonzero(plastic))
        if rest <= 0.0 and not any(options.get(k) for k in ("cohesive_stress", "capillary_stress")):
            converged = False  # cannot happen from an elastic start (the joining elements carried more than H)
            message = "; the plastic set carries the whole load"
            break
        guess = None if start is None else np.where(plastic, 0.0, np.clip(start, None, hardness))
        inner = solve_line_contact(inner_h, dx, contact_modulus, load=rest, initial_pressure=guess, **common)
        pressure = np.where(plastic, hardness, inner.pressure)
        # the gap the elastic bodies would have everywhere (negative on P: plastic flattening)
        u_inner = elastic_displacement(inner.pressure, dx, contact_modulus, periodic=periodic,
                                       reference_distance=reference_distance)
        elastic_contact = inner.contact & ~plastic
        if elastic_contact.any():
            delta = float(np.mean((raised + u_inner)[elastic_contact]))
        else:  # every element in contact is plastic: the approach is where the last one just closes
            delta = float(np.max((raised + u_inner)[plastic]))
        gap_all = raised + u_inner - delta
        joining = (inner.pressure > hardness) & ~plastic
        leaving = plastic & (gap_all > 0.0)
        start = pressure
        if not joining.any() and not leaving.any():
            break
        state = (plastic | joining) & ~leaving
        key = state.tobytes()
        if key in history or updates >= _MAX_PLASTIC_UPDATES:
            converged = False
            message = (f"; the plastic set did not settle in {updates} updates (cycling)" if key in history
                       else f"; the plastic set did not settle in {updates} updates")
            break
        history.add(plastic.tobytes())
        plastic = state
    depth = np.where(plastic, np.maximum(-gap_all, 0.0), 0.0)
    contact = inner.contact | plastic
    gap = np.where(plastic, 0.0, inner.gap)
    result = dataclasses.replace(
        inner, pressure=pressure, gap=gap, contact=contact, approach=delta, load=float(pressure.sum() * dx),
        converged=bool(inner.converged and converged),
        message=f"{inner.message}; pressure capped at the hardness {hardness / 1e9:.3g} GPa on "
                f"{int(np.count_nonzero(plastic))} element(s) after {updates} plastic-set update(s){message}")
    return PlasticContactSolution(result, plastic, depth, hardness * dx * float(np.count_nonzero(plastic)), updates)
