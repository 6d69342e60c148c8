"""The line contact with the pressure capped at the hardness: elastic-perfectly-plastic saturation (MODEL 7d).

Real scans are rougher than the thesis's statistics; their asperity pressures pass the elastic
limit of silicon in nearly every step of a meshing cycle (MODEL 7d). Where the elastic solution
would press harder than the hardness ``H`` of the softer body, the material flows: the pressure
saturates at ``H`` and the surfaces close in by plastic flattening (the gap there would be
negative, an interpenetration, which is the plastic deformation). This is the
elastic-perfectly-plastic surface model of the peer BEM codes (ContactMechanics' ``PlasticTopography``,
Tamaas' ``KatoSaturated``; Almqvist et al. 2007):

    0 <= p <= H,   g = h + u(p) - delta,
    g = 0 where 0 < p < H (elastic contact),   g <= 0 where p = H (plastic),   g >= 0 where p = 0,
    dx * sum(p) = w.

It is solved here by an active set on the plastic elements P around the elastic solver
(:func:`memstribo.physics.contact.solve_line_contact`, unchanged; at most
``SolverSettings.max_plastic_updates`` updates): with P fixed at p = H, the
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
from memstribo.physics.contact.halfplane import elastic_displacement
from memstribo.physics.contact.settings import resolve
from memstribo.physics.contact.solve import solve_line_contact
from memstribo.references import cites

__all__ = ["PlasticContactSolution", "solve_line_contact_capped"]

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
                              reference_distance=None, initial_pressure=None, elastic=None,
                              **options) -> PlasticContactSolution:
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
    elastic : ContactSolution, optional
        The elastic solution of the same problem when the caller has it already (it is not solved again).
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
    is and the plastic set has settled. Checked against ContactMechanics' plastic constrained
    conjugate gradient on the shipped line scan (bench/bench_plastic_contact.py, docs/mesh.md):
    pressures agree to 1e-9, contact and plastic sets element for element.
    """
    if hardness is not None and not (np.isfinite(float(hardness)) and float(hardness) > 0):
        raise InputError(f"hardness must be a positive pressure [Pa] or None, got {hardness!r}.")
    h = np.asarray(separation, dtype=float)
    common = dict(periodic=periodic, reference_distance=reference_distance, **options)
    start = None if initial_pressure is None else np.asarray(initial_pressure, dtype=float)
    sol = elastic if elastic is not None else solve_line_contact(h, dx, contact_modulus, load=load,
                                                                 initial_pressure=start, **common)
    if hardness is None or not np.any(sol.pressure > float(hardness)):
        return PlasticContactSolution(sol, np.zeros(h.shape, bool), np.zeros(h.shape), 0.0, 0)
    problem = _Capped(h, float(dx), float(contact_modulus), float(hardness), float(load), common)
    # each set's solve starts from the last pressure: the elastic solution first (with adhesion the contact can
    # have several states, and the capped one is the elastic one's neighbour)
    plastic, updates, note, start = sol.pressure > problem.hardness, 0, "", sol.pressure
    history = set()
    while True:
        updates += 1
        inner, pressure, gap_all, delta = problem.solve(plastic, start)
        start = pressure
        joining = (inner.pressure > problem.hardness) & ~plastic
        leaving = plastic & (gap_all > 0.0)
        if not joining.any() and not leaving.any():
            break
        history.add(plastic.tobytes())
        plastic = (plastic | joining) & ~leaving
        if plastic.tobytes() in history or updates >= resolve(options.get("settings")).max_plastic_updates:
            note = f"; NOT converged: the plastic set did not settle in {updates} updates"
            break
    depth = np.where(plastic, np.maximum(-gap_all, 0.0), 0.0)
    n_plastic = int(np.count_nonzero(plastic))
    result = dataclasses.replace(
        inner, pressure=pressure, gap=np.where(plastic, 0.0, inner.gap), contact=inner.contact | plastic,
        approach=delta, load=float(pressure.sum() * dx), converged=bool(inner.converged and not note),
        message=f"{inner.message}; pressure capped at the hardness {problem.hardness / 1e9:.3g} GPa on {n_plastic} "
                f"element(s) after {updates} plastic-set update(s){note}")
    return PlasticContactSolution(result, plastic, depth, problem.hardness * float(dx) * n_plastic, updates)


@dataclasses.dataclass
class _Capped:
    """One capped problem: the elastic solve with a given plastic set held at the hardness."""

    h: np.ndarray
    dx: float
    modulus: float
    hardness: float
    load: float
    common: dict
    cache: dict = dataclasses.field(default_factory=dict)

    def displacement(self, pressure):
        """Elastic displacement of a pressure field [m] (the solver's operator and datum)."""
        return elastic_displacement(pressure, self.dx, self.modulus, periodic=self.common["periodic"],
                                    reference_distance=self.common["reference_distance"])

    def solve(self, plastic, start):
        """(elastic solution of the rest, pressure [Pa], gap of the elastic bodies [m], approach [m]) with p = H on P.

        The gap is h + u(H 1_P) + u(p_rest); the elements of P are lifted out of reach of the elastic solve
        (above the highest other element by the peak-to-valley), and the rest carries w - H dx |P|.
        """
        key = plastic.tobytes()
        if key not in self.cache:
            self.cache = {key: self.displacement(np.where(plastic, self.hardness, 0.0))}
        raised = self.h + self.cache[key]
        free = ~plastic
        top = float(raised[free].max()) if free.any() else float(raised.max())
        lifted = np.where(plastic, np.maximum(raised, top) + max(float(np.ptp(raised)), 1e-12), raised)
        rest = self.load - self.hardness * self.dx * int(np.count_nonzero(plastic))
        guess = None if start is None else np.where(plastic, 0.0, np.clip(start, None, self.hardness))
        inner = solve_line_contact(lifted, self.dx, self.modulus, load=rest, initial_pressure=guess, **self.common)
        pressure = np.where(plastic, self.hardness, inner.pressure)
        total = raised + self.displacement(inner.pressure)
        elastic_contact = inner.contact & free
        # the approach from the elastic contact set; with every element in contact plastic, where the last closes
        delta = float(np.mean(total[elastic_contact])) if elastic_contact.any() else float(np.max(total[plastic]))
        return inner, pressure, total - delta, delta
