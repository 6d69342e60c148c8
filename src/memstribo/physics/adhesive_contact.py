"""Adhesive line contact (Maugis-Dugdale cohesive zone): load-approach curves and pull-off.

Built on :func:`memstribo.physics.contact.solve_line_contact` with ``cohesive_stress`` (sigma0 [Pa])
and ``cohesive_range`` (h0 [m], w = sigma0 h0): a cylinder of radius R on a flat (or any gap
profile), followed quasi-statically under approach (displacement) control, each step
warm-started from the previous one, so that the jump-in on loading and the pull-off on
unloading show up as the hysteresis of the load-approach curve (docs/contact.md, "Adhesive
contact"; docs/model.md §7c).

References
----------
.. [1] D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269 (the Dugdale model of adhesion).
.. [2] V. Rey, G. Anciaux, J.-F. Molinari, Comput. Mech. 60 (2017) 69-81 (adhesive BEM).
.. [3] J. M. Baney, C.-Y. Hui, J. Adhesion Sci. Technol. 11 (1997) 393-406 (Maugis-Dugdale cylinder).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["LoadApproachCurve", "PullOff", "load_approach_curve", "line_contact_pull_off"]


@dataclass(frozen=True)
class LoadApproachCurve:
    """A quasi-static load-approach curve of an adhesive line contact.

    Attributes
    ----------
    approach : numpy.ndarray
        Rigid-body approach of each step [m] (datum as in :class:`memstribo.physics.contact.ContactSolution`).
    load : numpy.ndarray
        Net load per unit length [N/m] (negative: tensile).
    half_width : numpy.ndarray
        Half the contact length (contact elements times dx / 2) [m].
    adhesive_load : numpy.ndarray
        Tensile load of the cohesive zone outside the contact [N/m].
    converged : numpy.ndarray
        Whether each step converged.
    """

    approach: np.ndarray
    load: np.ndarray
    half_width: np.ndarray
    adhesive_load: np.ndarray
    converged: np.ndarray


@dataclass(frozen=True)
class PullOff:
    """Pull-off of an adhesive cylinder-on-flat line contact (approach-controlled unloading).

    Attributes
    ----------
    pull_off_line_load : float
        Largest tensile load on the unloading curve [N/m], positive.
    pull_off_half_width : float
        Contact half-width there [m].
    maugis_parameter : float
        lambda = 2 sigma0 (R / (pi w E*²))^(1/3) [-] (:func:`memstribo.physics.closed_form.maugis_line_parameter`).
    cohesive_range : float
        h0 = w / sigma0 [m].
    curve : LoadApproachCurve
        The unloading curve, from zero load to separation (or the last step).
    dx : float
        Element width [m].
    length : float
        Domain length [m].
    converged : bool
        Whether every step converged and the maximum tension was passed.
    message : str
        What happened, in words.
    """

    pull_off_line_load: float
    pull_off_half_width: float
    maugis_parameter: float
    cohesive_range: float
    curve: LoadApproachCurve
    dx: float
    length: float
    converged: bool
    message: str


def _positive(name, value, unit):
    if not np.isscalar(value) or not np.isfinite(value) or value <= 0:
        raise InputError(f"{name} must be a positive finite number [{unit}], got {value!r}")
    return float(value)


def _summary(solution):
    return (solution.approach, solution.load, 0.5 * solution.contact_length, solution.adhesive_load,
            solution.converged)


def _curve(rows):
    columns = list(zip(*rows)) if rows else [[]] * 5
    return LoadApproachCurve(*(np.asarray(c, dtype=bool if i == 4 else float) for i, c in enumerate(columns)))


@cites("maugis_1992", "rey_2017", "model")
def load_approach_curve(separation, dx, contact_modulus, approaches, *, cohesive_stress, cohesive_range,
                        periodic=False, tolerance=1e-8, initial_pressure=None):
    """Follow a sequence of approaches quasi-statically (each step warm-started from the previous one).

    Parameters
    ----------
    separation : array_like
        Undeformed gap h(x) [m] on a uniform grid.
    dx : float
        Element width [m].
    contact_modulus : float
        Contact modulus E* [Pa].
    approaches : array_like
        Rigid-body approaches [m], in the order followed (increasing: loading, decreasing: unloading).
    cohesive_stress, cohesive_range : float
        Dugdale stress sigma0 [Pa] and range h0 [m].
    periodic : bool, optional
        Periodic half-plane instead of the free boundary.
    tolerance : float, optional
        Solver tolerance.
    initial_pressure : array_like, optional
        State to start from [Pa] (e.g. the end of a loading curve).

    Returns
    -------
    LoadApproachCurve
        And, as a second value, the pressure of the last step [Pa] (to continue from).

    Notes
    -----
    On loading from separation the cohesive zone forms where the gap falls below h0 and the
    surfaces jump into contact where that state loses stability; on unloading the contact
    holds under tension down to pull-off: the two branches differ (hysteresis).
    """
    rows = []
    pressure = None if initial_pressure is None else np.asarray(initial_pressure, dtype=float)
    from memstribo.physics.contact import solve_line_contact

    for approach in np.asarray(approaches, dtype=float):
        solution = solve_line_contact(separation, dx, contact_modulus, approach=float(approach), periodic=periodic,
                                      tolerance=tolerance, initial_pressure=pressure,
                                      cohesive_stress=cohesive_stress, cohesive_range=cohesive_range)
        rows.append(_summary(solution))
        pressure = solution.pressure
    return _curve(rows), pressure


def _unload(separation, dx, modulus, options, start, rows, h0, target, max_steps):
    """Reduce the approach step by step from the adhered state ``start`` (rows appended to ``rows``, steps adapted
    to change the load by about ``target`` [N/m]); returns (whether the maximum tension was passed, why it stopped)."""
    from memstribo.physics.contact import solve_line_contact

    pressure, approach = start.pressure, start.approach
    step = 0.25 * h0
    smallest = 1e-3 * h0
    passed = False
    message = ""
    for _ in range(max_steps):
        solution = solve_line_contact(separation, dx, modulus, approach=approach - step, initial_pressure=pressure,
                                      **options)
        lost = rows[-1][2] > 0 and not solution.contact.any()
        if (lost or not solution.converged) and step > smallest:
            # the set iteration may leave the adhered state before it ends (jump-out): retry with
            # half the step, so that the end of the adhered branch is found to within h0/1000
            step *= 0.5
            continue
        if not solution.converged:
            if passed:  # beyond the maximum tension: the end of the adhered branch
                message = f"the set iteration finds no adhered state beyond this point ({solution.message})"
            else:
                rows.append(_summary(solution))
                message = f"an unloading step did not converge: {solution.message}"
            break
        rows.append(_summary(solution))
        approach -= step
        pressure = solution.pressure
        change = abs(rows[-1][1] - rows[-2][1])
        if len(rows) >= 3 and rows[-1][1] > rows[-2][1]:
            passed = True
        if lost and rows[-1][1] > rows[-2][1]:
            message = "the contact was lost (jump-out)"
            break
        if passed and (rows[-1][1] >= 0.0 or rows[-1][1] > 0.5 * min(r[1] for r in rows)):
            message = "the tension fell below half its maximum"
            break
        step *= float(np.clip(target / change, 0.5, 2.0)) if change > 0 else 2.0
    return passed, message


def _largest_tension(curve):
    """(index, load [N/m], half-width [m]) of the largest tension on the curve, refined by a parabola through the
    three steps around it."""
    k = int(np.argmin(curve.load))
    load_min, width = float(curve.load[k]), float(curve.half_width[k])
    if 0 < k < len(curve.load) - 1 and (curve.half_width[k + 1] > 0 or curve.half_width[k] == 0):
        d = curve.approach[k - 1:k + 2]
        p = curve.load[k - 1:k + 2]
        coefficients = np.polyfit(d - d[1], p, 2)
        if coefficients[0] > 0:
            vertex = -coefficients[1] / (2.0 * coefficients[0])
            if d[0] - d[1] <= vertex <= d[2] - d[1] or d[2] - d[1] <= vertex <= d[0] - d[1]:
                load_min = float(np.polyval(coefficients, vertex))
                width = float(np.interp(vertex + d[1], d[::-1], curve.half_width[k - 1:k + 2][::-1])
                              if d[0] > d[2] else np.interp(vertex + d[1], d, curve.half_width[k - 1:k + 2]))
    return k, load_min, width


@cites("maugis_1992", "baney_hui_1997", "johnson_greenwood_2008", "model")
def line_contact_pull_off(radius, contact_modulus, work_of_adhesion, cohesive_stress, *, points=2048, length=None,
                          steps=40, tolerance=1e-8, periodic=False, max_steps=None, settings=None):
    r"""Pull-off of a smooth cylinder from a flat with a Maugis-Dugdale cohesive zone (per unit length).

    Parameters
    ----------
    radius : float
        Effective radius R [m].
    contact_modulus : float
        Contact modulus E* [Pa].
    work_of_adhesion : float
        Work of adhesion w [J/m²].
    cohesive_stress : float
        Dugdale stress sigma0 [Pa]; the range is h0 = w / sigma0.
    points : int, optional
        Number of elements.
    length : float, optional
        Domain length [m] (default: 5 times the larger of the JKR half-width at zero load,
        (32 R² w / (pi E*))^(1/3), and the rigid cohesive half-width sqrt(2 R h0)).
    steps : int, optional
        Approximate number of unloading steps from zero load to the maximum tension (the step is
        adapted so that each changes the load by about |P_JKR| / steps).
    tolerance : float, optional
        Solver tolerance.
    periodic : bool, optional
        Periodic half-plane (the cylinder repeats with the domain length) instead of the free boundary.
    max_steps : int, optional
        Cap on the unloading steps (default 4 x steps).
    settings : SolverSettings, optional
        The solver's settings (:mod:`memstribo.physics.contact.settings`; None: the defaults), used with
        ``contact_only_range = 0`` (see Notes).

    Returns
    -------
    PullOff

    Notes
    -----
    The adhered state at zero load is solved under load control (the branch continuous from
    the non-adhesive contact: the surfaces in contact), then the approach is reduced step by
    step (approach control, warm starts) until the contact is lost (a step that loses it is
    retried with half the step, down to h0/1000, so the end of the adhered branch is found) or,
    at small Maugis parameter where the contact shrinks to nothing without a jump, until the
    tension has fallen below half its maximum; the pull-off load is the largest tension on
    that curve, refined by a parabola through the three steps around it.
    Under load control the contact would separate there; under approach control it follows
    the curve further, to a jump-out at smaller tension. Compare with
    :func:`memstribo.physics.closed_form.maugis_dugdale_line_pull_off` and, at large Maugis parameter,
    :func:`memstribo.physics.closed_form.jkr_line_pull_off_load`.

    Where the grid does not resolve the Dugdale zone (e.g. R = 1 mm on 2048 elements) the solve widens it at the
    same w (:func:`memstribo.physics.contact.subgrid.resolved_zone`, Turon et al. 2007), here without the
    contact-only part of sigma0 the meshing cycle keeps: a strength criterion on the contact's edge element that
    depends on its width (R = 1 mm: 495.8 N/m with it, 453.0 without, closed forms 447.0; docs/contact.md). The
    result is flagged unconverged where the widening itself moves the closed-form pull-off by more than 1 %.
    """
    from memstribo.physics.contact import solve_line_contact
    from memstribo.physics.closed_form import jkr_line_pull_off_load, maugis_line_parameter

    radius = _positive("radius", radius, "m")
    modulus = _positive("contact_modulus", contact_modulus, "Pa")
    w = _positive("work_of_adhesion", work_of_adhesion, "J/m^2")
    sigma0 = _positive("cohesive_stress", cohesive_stress, "Pa")
    if int(points) != points or points < 64:
        raise InputError(f"points must be an integer >= 64, got {points!r}")
    if int(steps) != steps or steps < 4:
        raise InputError(f"steps must be an integer >= 4, got {steps!r}")
    h0 = w / sigma0
    a_zero = np.cbrt(32.0 * radius**2 * w / (np.pi * modulus))
    length = _positive("length", length, "m") if length is not None else 5.0 * max(a_zero, np.sqrt(2 * radius * h0))
    n = int(points)
    dx = length / n
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    separation = x**2 / (2.0 * radius)
    options, sigma_used = _pull_off_options(dx, modulus, sigma0, h0, periodic, tolerance, settings)
    lam = float(maugis_line_parameter(radius, modulus, w, sigma0))
    scale = abs(float(jkr_line_pull_off_load(radius, modulus, w)))

    start = solve_line_contact(separation, dx, modulus, load=0.0, **options)
    rows = [_summary(start)]
    if not start.converged:
        return PullOff(np.nan, np.nan, lam, h0, _curve(rows), dx, length, False,
                       f"the adhered state at zero load did not converge: {start.message}")
    max_steps = int(max_steps) if max_steps is not None else 4 * int(steps)
    passed, message = _unload(separation, dx, modulus, options, start, rows, h0, scale / steps, max_steps)
    curve = _curve(rows)
    k, load_min, width = _largest_tension(curve)
    converged = bool(passed and curve.converged.all())
    if not passed and not message:
        message = f"the maximum tension was not passed within {max_steps} steps: raise max_steps"
    if converged:
        message = (f"pull-off {-load_min:.4g} N/m at half-width {width * 1e9:.4g} nm after {len(rows) - 1} unloading "
                   f"steps; {message or 'stopped at the step cap'}")
    zone = float(curve.adhesive_load[k]) / (sigma_used * dx)  # elements of both edges' zones at pull-off
    if zone < 4:
        message += f"; the cohesive zone at pull-off spans only {zone:.1f} elements: use more points"
    converged, message = _widened_zone_check(radius, modulus, w, sigma0, sigma_used, converged, message)
    return PullOff(-load_min, width, lam, h0, curve, dx, length, converged, message)


def _pull_off_options(dx, modulus, sigma0, h0, periodic, tolerance, settings):
    """The solver options of the pull-off's solves (the settings with ``contact_only_range = 0``) and the Dugdale
    stress [Pa] the solve uses on this grid (sigma0 itself where the grid resolves the zone)."""
    from memstribo.physics.contact.settings import resolve
    from memstribo.physics.contact.subgrid import resolved_zone

    solver = dataclasses.replace(resolve(settings), contact_only_range=0.0)
    options = dict(periodic=periodic, tolerance=tolerance, cohesive_stress=sigma0, cohesive_range=h0,
                   settings=solver)
    return options, resolved_zone(dx, modulus, sigma0, h0, solver.zone_elements)[0]


def _widened_zone_check(radius, modulus, w, sigma0, sigma_used, converged, message):
    """(converged, message) of a pull-off solved with the widened stress ``sigma_used`` [Pa] instead of ``sigma0``
    [Pa]: not converged where the widening moves the closed-form Maugis-Dugdale pull-off by more than 1 %
    (R [m], E* [Pa], w [J/m²])."""
    if sigma_used >= sigma0:
        return converged, message
    from memstribo.physics.closed_form import maugis_dugdale_line_pull_off

    given = float(maugis_dugdale_line_pull_off(radius, modulus, w, sigma0)[0])
    widened = float(maugis_dugdale_line_pull_off(radius, modulus, w, sigma_used)[0])
    shift = abs(widened / given - 1.0)
    message += (f"; the grid does not resolve the Dugdale zone: solved with the same w over sigma = "
                f"{sigma_used:.4g} Pa, which moves the closed-form pull-off by {100 * shift:.2g} %")
    if shift > 0.01 and converged:
        converged = False
        message += ": more than 1 %, NOT converged; use more points or a shorter length"
    return converged, message
