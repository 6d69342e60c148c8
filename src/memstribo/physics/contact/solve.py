r"""The public entry of the line solver, :func:`solve_line_contact`: plain, adhesive or capillary, load or approach.

How it solves (the notes of :func:`solve_line_contact`)
-------------------------------------------------------
Minimises the complementary energy :math:`\frac12 p^T A p + p^T h` subject to
:math:`p \ge 0` and :math:`dx\sum p = w`. On a fixed contact set C the equations
:math:`A_{CC} p_C - \delta = -h_C`, :math:`dx\sum p_C = w` are solved by a conjugate
gradient preconditioned as in Vollebregt (2014) with :math:`P_C\,\mathcal F^{-1}\frac{E^*|q|}{2}\mathcal F\,P_C`
(P_C: restriction to C with the mean removed, so the load is kept); then C is updated
(points with p < 0 leave, points that penetrate join: a primal-dual active-set step)
until it no longer changes. The constrained CG of Polonsky & Keer (1999) is the fallback and the
alternative. The convergence test is the same for both: the largest gap error on C or
penetration outside it, relative to the peak-to-valley of h, at most ``tolerance``.

**Adhesion** (Maugis-Dugdale, docs/contact.md "Adhesive contact"): the traction is -sigma0
wherever the deformed gap lies in (0, h0], 0 beyond h0, and in contact (gap 0) the
pressure is p >= -sigma0 (Rey et al. 2017, Bazrafshan et al. 2017). With the cohesive set S (contact plus cohesive zone)
fixed, writing p = p+ - sigma0 on S makes the problem the non-adhesive one for p+ >= 0
with the gap h - sigma0 A 1_S and the load w + sigma0 dx |S|, which the machinery above
solves (warm-started from the previous p+); then S is updated to {gap <= h0} until it no
longer changes (each element carries the fraction of it where the interpolated gap is
<= h0, so the discrete front is unique; settled when no fraction moves by more than 1e-4,
or the zone's load by less than 1e-4 with no fraction moving by more than 0.25; updates of
creeping fronts are Aitken-extrapolated; under load control each inner solve starts from the last p+ extrapolated
along its last change and first solves on that guess's contact set). Under load control the solution need not be
unique (jump-in, pull-off): the state returned is the one the set iteration reaches from ``initial_pressure`` (its
cohesive set is where it is non-zero: continuation from a previous state), or without it
from the non-adhesive solution at the same load (w > 0; the adhered, loading-branch
state) or from the set {h - min h <= h0} (w <= 0). If the cohesive zone cannot carry a
tensile load (past pull-off on that branch) the result has ``converged=False``. Under
approach control (``approach``) the same splitting, the inner problem at the fixed
approach solved by a primal-dual active set with direct (Cholesky) solves on small contact
sets and the preconditioned CG (warm-started) on larger ones.
"""

from __future__ import annotations

import numpy as np  # noqa: F401  (the doctest of solve_line_contact)

import memstribo.physics.contact.settings as _settings
from memstribo.physics.contact.cohesive import _solve_adhesive, _solve_capillary
from memstribo.physics.contact.line import _solve_elastic
from memstribo.references import cites


@cites("polonsky_keer_1999", "vollebregt_2014", "johnson_1985", "model")
def solve_line_contact(separation, dx, contact_modulus, *, load=None, mean_pressure=None, periodic=False,
                       tolerance=1e-8, max_iterations=None, reference_distance=None, initial_pressure=None,
                       precondition=True, continuation=True, method="active-set", cohesive_stress=None,
                       cohesive_range=None, approach=None, capillary_stress=None, capillary_range=None, settings=None):
    r"""Solve the normal contact of a rough line contact under a given load (or approach), optionally adhesive.

    Parameters
    ----------
    separation : array_like
        Undeformed gap h(x) [m] at the element centres of a uniform grid (any offset: only
        differences matter).
    dx : float
        Element width [m].
    contact_modulus : float
        Contact modulus E* [Pa], 1/E* = (1-nu1²)/E1 + (1-nu2²)/E2.
    load : float, optional
        Load per unit face width w [N/m]. Give this or ``mean_pressure``.
    mean_pressure : float, optional
        Nominal pressure w / (n dx) [Pa].
    periodic : bool, optional
        Periodic half-plane instead of the free boundary (module docstring).
    tolerance : float, optional
        Convergence tolerance on the dimensionless complementarity residual (see
        :class:`ContactSolution`).
    max_iterations : int, optional
        Iteration cap (default: max(1000, n // 4)).
    reference_distance : float, optional
        Free-boundary displacement datum [m] (default: the domain length n dx).
    initial_pressure : array_like, optional
        Warm start [Pa], e.g. the previous step's pressure of a meshing cycle; rescaled to
        the load.
    precondition : bool, optional
        Use the Fourier preconditioner (default). ``False`` with ``method="polonsky-keer"``
        gives the plain Polonsky-Keer iteration (for comparison).
    continuation : bool, optional
        Start from the solution on nested coarser grids (every other point, down to 512
        elements, each solved loosely, docs/contact.md) when no ``initial_pressure`` is given
        (default).
    method : {"active-set", "polonsky-keer"}, optional
        "active-set" (default): primal-dual active set, each contact set solved by the
        preconditioned CG, falling back to Polonsky-Keer should the set not settle within 30
        updates; "polonsky-keer": the constrained CG of [1]_ throughout. Under load control a
        free-boundary grid of at most ``settings.dense_solve_max`` (1024) elements, such as a meshing
        window, is solved with the dense influence matrix instead, each contact set exactly by
        Cholesky (with or without adhesion; the same answer to the tolerance, tested), and
        ``iterations`` then counts contact sets (or cohesive-zone updates).
    cohesive_stress : float, optional
        Dugdale stress sigma0 [Pa] of a Maugis-Dugdale cohesive zone (give it with
        ``cohesive_range``; :func:`memstribo.physics.adhesion.maugis_stress`). Both None (default):
        no adhesion, the non-adhesive solver above, unchanged.
    cohesive_range : float, optional
        Range h0 [m] of the Dugdale stress (w = sigma0 h0, :func:`memstribo.physics.adhesion.maugis_range`).
    approach : float, optional
        Rigid-body approach [m] (same datum as :attr:`ContactSolution.approach`): displacement
        control instead of ``load``/``mean_pressure`` (with or without adhesion). Needed to
        follow a load-approach curve through the pull-off instability.
    capillary_stress : float, optional
        Laplace pressure gamma / r_K [Pa] of capillary menisci (humid air,
        :func:`memstribo.physics.capillary.laplace_pressure`): a second Dugdale-type traction
        (-capillary_stress where the gap is at most ``capillary_range``), alone or added to the
        Maugis-Dugdale zone above: the traction is then a sum of two step functions of the gap.
        Give it with ``capillary_range``; None or 0 (default): no menisci, the solvers above unchanged.
    capillary_range : float or array_like, optional
        Condensation height h_c [m] (:func:`memstribo.physics.capillary.condensation_height`), a number
        or one value per element (e.g. bare and coated parts of a flank).
    settings : SolverSettings, optional
        The solvers' tolerances, caps and switches (:mod:`memstribo.physics.contact.settings`); None: the
        defaults every documented number was computed with. They change the path to the answer, not the answer.

    Returns
    -------
    ContactSolution
        Pressure, gap, contact set, approach, iterations, residual, converged flag, timing.
        Non-convergence is reported by ``converged=False`` and ``message``, never hidden. How the solve works:
        :mod:`memstribo.physics.contact.solve`.

    Examples
    --------
    >>> x = (np.arange(1024) - 511.5) * 1e-9
    >>> sol = solve_line_contact(x**2 / (2 * 20e-6), 1e-9, 100e9, load=1.0)
    >>> sol.converged, round(sol.contact_length * 1e9)
    (True, 32)
    """
    settings = _settings.resolve(settings)
    if capillary_stress is not None or capillary_range is not None:
        return _solve_capillary(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                                max_iterations, reference_distance, initial_pressure, precondition, continuation,
                                cohesive_stress, cohesive_range, capillary_stress, capillary_range, settings=settings)
    if cohesive_stress is not None or cohesive_range is not None or approach is not None:
        return _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                               max_iterations, reference_distance, initial_pressure, precondition, continuation,
                               cohesive_stress, cohesive_range, settings=settings)
    return _solve_elastic(separation, dx, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                          reference_distance, initial_pressure, precondition, continuation, method, settings=settings)
