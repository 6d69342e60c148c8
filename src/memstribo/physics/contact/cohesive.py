"""The cohesive-zone fixed point: Maugis-Dugdale adhesion and capillary menisci inside the line solve, under load
or approach control (Rey et al. 2017, Bazrafshan et al. 2017; docs/contact.md "Adhesive contact", docs/humidity.md)."""

from __future__ import annotations

import dataclasses
import functools
import time

import numpy as np
import scipy.linalg

from memstribo.errors import InputError
from memstribo.physics.contact.dense import _dense_fraction, _small_capillary, _small_contact
from memstribo.physics.contact.halfplane import ContactSolution, _dot
from memstribo.physics.contact.inputs import _check_adhesive_inputs, _check_problem
from memstribo.physics.contact.subgrid import resolved_zones
from memstribo.physics.contact.line import (_active_set, _cold_start, _nested_guess, _operator_and_limits,
                                            _polonsky_keer, _solve_elastic)
from memstribo.references import cites


def _solve_on_set(operator, indices, rhs, tolerance, cap, factors=None, guess=None, *, settings):
    """Pressure on the contact set ``indices`` with a prescribed displacement: A_CC p = rhs [m].

    Cholesky on sets up to ``settings.approach_direct_max`` elements (larger LAPACK factorisations may go
    threaded, which is slow on a busy machine; the factor of the last set is kept in the dict ``factors``:
    the cohesive-zone updates often keep the contact set), else the CG preconditioned with the
    Fourier-space inverse restricted to the set, from ``guess`` [Pa] (on the set), until the
    largest displacement residual is at most ``tolerance`` [m]. Returns the pressure [Pa] and
    the iterations.
    """
    if indices.size <= settings.approach_direct_max:
        key = indices.tobytes()
        factor = factors.get(key) if factors is not None else None
        if factor is None:
            matrix = operator.matrix(indices, operator.green_kernel)
            try:
                factor = scipy.linalg.cho_factor(matrix, overwrite_a=True, check_finite=False)
            except np.linalg.LinAlgError:
                factor = None
            if factors is not None and factor is not None:
                factors.clear()
                factors[key] = factor
        if factor is not None:
            return scipy.linalg.cho_solve(factor, rhs, check_finite=False), 1
    green, stiffness = operator.green, operator.stiffness
    if guess is not None:
        x = guess.copy()
        r = rhs - operator.restricted(x, indices, green)
    else:
        x = np.zeros(indices.size)
        r = rhs.copy()
    t = None
    G_old = 1.0
    used = 0
    while used < cap and np.abs(r).max() > tolerance:
        used += 1
        z = operator.restricted(r, indices, stiffness)
        G = _dot(r, z)
        if G <= 0.0:  # round-off: no descent direction left
            break
        t = z if t is None else z + (G / G_old) * t
        G_old = G
        q = operator.restricted(t, indices, green)
        denominator = _dot(q, t)
        if denominator <= 0.0:
            break
        tau = _dot(r, t) / denominator
        x += tau * t
        r -= tau * q
    return x, used


def _approach_contact(operator, h, delta, p_start, tolerance_abs, cap, factors=None, *, settings):
    """Non-adhesive contact at a given approach ``delta`` [m] (gap h + A p - delta): primal-dual active set.

    On each contact set C, A_CC p_C = delta - h_C is solved directly (or by the CG); then points
    with p <= 0 leave C and points that penetrate join, until C no longer changes. Returns the
    pressure, gap, contact mask, iterations, set updates and whether the set settled.
    """
    contact = (p_start > 0.0) if p_start is not None else (h - delta < 0.0)
    iterations = 0
    seen = set()
    p = np.zeros(h.size) if p_start is None else np.maximum(p_start, 0.0)
    g = h - delta
    for outer in range(1, settings.adhesive_max_outer + 1):
        indices = np.flatnonzero(contact)
        previous, p = p, np.zeros(h.size)
        if indices.size:
            p[indices], used = _solve_on_set(operator, indices, delta - h[indices], 0.1 * tolerance_abs, cap, factors,
                                             previous[indices], settings=settings)
            iterations += used
            g = h + operator.displacement(p) - delta
        else:
            g = h - delta
        new = (contact & (p > 0.0)) | (~contact & (g < -tolerance_abs))
        if np.array_equal(new, contact):
            return p, g, contact, iterations, outer, True
        key = np.packbits(new).tobytes()
        if key in seen:
            return p, g, contact, iterations, outer, False
        seen.add(key)
        contact = new
    return p, g, contact, iterations, outer, False


def _cohesive_fraction(gap, h0, contact, periodic, zones=None):
    """Fraction [-] of each element on which the Dugdale stress acts: gap <= h0 on the linear interpolant.

    ``zones``: ((sigma_1, h_1), (sigma_2, h_2), ...) for a traction made of several step functions
    of the gap (vdW and capillary zones): the sigma-weighted mean of their fractions, so that
    ``sum(sigma_i) * fraction`` is the traction (``h0`` is then unused; ``h_i`` a number or per element).

    The gap is interpolated linearly between element centres; each half element contributes the
    part of it where the interpolant is <= h0 (1 in contact). A continuous (not 0/1) cohesive
    front makes the discrete Dugdale problem's solution unique up to the tolerance: with 0/1
    elements a band of several elements of consistent fronts exists (3-5 % in a).
    """
    if zones is not None:  # an element of zero range carries none of that zone, not even in contact
        total = sum(sigma for sigma, _ in zones)
        return sum(sigma * _cohesive_fraction(gap, reach, contact, periodic) * (np.asarray(reach) > 0.0)
                   for sigma, reach in zones) / total
    if periodic:
        left, right = np.roll(gap, 1), np.roll(gap, -1)
    else:
        left = np.concatenate((gap[:1], gap[:-1]))
        right = np.concatenate((gap[1:], gap[-1:]))
    fraction = np.zeros(gap.size)
    for neighbour in (left, right):
        edge = 0.5 * (neighbour + gap)
        low, high = np.minimum(edge, gap), np.maximum(edge, gap)
        span = high - low
        with np.errstate(divide="ignore", invalid="ignore"):
            part = np.where(span > 0.0, (h0 - low) / np.where(span > 0.0, span, 1.0), (low <= h0) * 1.0)
        fraction += 0.5 * np.clip(part, 0.0, 1.0)
    fraction[contact] = 1.0
    return fraction


@cites("maugis_1992", "rey_2017", "bazrafshan_2017", "model")
def _cohesive_iteration(operator, h, sigma0, h0, fraction, guess, inner, periodic, tolerance, scale,
                        fraction_tolerance, max_outer, zones=None, extrapolate=False, *, settings):
    """Fixed point on the cohesive fraction: traction -sigma0*fraction, inner non-adhesive solve for p+.

    ``inner(h_eff, extra, guess, tol)`` solves the non-adhesive problem for p+ >= 0 with the gap h_eff
    and (load control) the extra compressive sum ``extra`` = sigma0 * sum(fraction) [Pa] to the
    relative tolerance ``tol`` (``settings.loose_tolerance`` while whole elements still change state,
    i.e. the cohesive fraction changes by 0.5 or more somewhere; else ``tolerance``), and
    returns (p+, gap, contact, approach, iterations, residual, ok, why). Every third update
    is Aitken-extrapolated (the plain update creeps: linear convergence with a ratio near 1).

    The inner solves dominate the cost (FFTs of the contact-set CG), so each is warm-started
    from the last p+; with ``extrapolate`` (load control) from the last p+ plus c times its last
    change where the new change of the fraction repeats c (least squares, 0 <= c <= 1) times the
    last one (p+ depends linearly on the fraction for a fixed contact set), and solved on the
    guess's contact set before that set is first updated (:func:`_active_set` ``settle_first``).
    (Under approach control the guess's positive set is the inner active set's first contact
    set, solved exactly on small grids: there the last p+ is kept as it is.) The splitting and the
    fixed point are those of Rey, Anciaux & Molinari (2017) and Bazrafshan et al. (2017)
    (traction -sigma0 on the cohesive set, the non-adhesive problem for the rest); their single
    constrained CG over the three sets is not used (docs/contact.md, "Adhesive contact", "Speed").
    """
    iterations = 0
    gaps = []
    state = None
    change = 1.0
    # under-relaxation, engaged only if the largest change of the fraction stops shrinking: the
    # plain update can fall into a limit cycle at a front (an element between two rough-surface
    # asperities creeps, its neighbour jumps, it falls back: the thesis load case, 567 points)
    relax, best, stalled, improving = 1.0, np.inf, 0, 0
    previous = None  # (fraction, p+) of the previous update
    for outer in range(1, max_outer + 1):
        h_eff = h - sigma0 * operator.displacement(fraction) if fraction.any() else h
        # inexact inner solves: a gap error of settings.gap_fraction * change * h0 moves a front by a small
        # part of its last change (no looser than settings.loose_tolerance; the final solve at ``tolerance``)
        tol = min(max(tolerance, settings.gap_fraction * change * h0 / scale), max(tolerance, settings.loose_tolerance))
        p_plus, gap, contact, approach, used, residual, ok, why = inner(h_eff, sigma0 * fraction.sum(), guess, tol)
        iterations += used
        state = (p_plus - sigma0 * fraction, gap, contact, fraction, approach, iterations, outer, residual)
        if not ok and (tol <= tolerance or not np.isfinite(residual)):
            return state + (False, why)
        new = _cohesive_fraction(gap, h0, contact, periodic, zones)
        step = np.abs(new - fraction)
        change = measured = step.max()
        # settled: no element's fraction moves by more than fraction_tolerance, or (many fronts,
        # a few of them creeping) the zone's load moves by less than settings.zone_load_tolerance of it
        # and no element by more than settings.zone_max_change
        zone = float(new[~contact].sum())
        if change <= fraction_tolerance or (change <= settings.zone_max_change
                                            and step.sum() <= settings.zone_load_tolerance * max(zone, 1.0)):
            if tol <= tolerance:
                return state + (True, "")
            change = 0.0  # settled on a loose solve: once more at the full tolerance
        if measured < best:
            best, stalled = measured, 0
            improving += 1
            if relax < 1.0 and improving >= settings.improving_updates:  # converging again: less damping
                relax, improving = min(1.0, 2.0 * relax), 0
        else:
            improving = 0
            stalled += 1
            if stalled >= settings.stalled_updates and relax > settings.min_relaxation:
                relax, stalled = 0.5 * relax, 0
        # the plain update creeps (the front moves a fixed fraction, often ~0.9, of the remaining
        # way per update); every third update the gap outside the contact is extrapolated by
        # Aitken's rule with the ratio of its last two changes (plain updates in between correct
        # an overshoot). The gap, not the fraction, is extrapolated: it moves the front by
        # several elements at once.
        gaps.append(np.where(contact, 0.0, gap))
        if len(gaps) >= 3 and outer % 3 == 0:
            d1, d0 = gaps[-1] - gaps[-2], gaps[-2] - gaps[-3]
            denominator = _dot(d0, d0)
            ratio = min(_dot(d1, d0) / denominator, settings.aitken_max_ratio) if denominator > 0 else 0.0
            # a creeping front (a smooth contact; rough contacts rarely), not while damped
            if ratio >= settings.aitken_min_ratio and relax == 1.0:
                new = _cohesive_fraction(gap + d1 * (ratio / (1.0 - ratio)), h0, contact, periodic, zones)
        del gaps[:-3]
        if relax < 1.0:  # damped: part of the way, but every element in contact carries its full stress
            new = np.where(contact, new, fraction + relax * (new - fraction))
        # warm start of the next inner solve: p+ responds linearly to the fraction (for a fixed contact
        # set), so where the new change of the fraction repeats a multiple c of the last one (a
        # creeping front), p+ is expected to repeat c times its last change (c from a least-squares
        # fit, used in [0, 1])
        guess = p_plus
        if previous is not None and extrapolate and settings.linear_response_start:
            last = fraction - previous[0]
            norm = _dot(last, last)
            c = min(max(_dot(new - fraction, last) / norm, 0.0), 1.0) if norm > 0.0 else 0.0
            if c > 0.0:
                guess = np.maximum(p_plus + c * (p_plus - previous[1]), 0.0)
        previous = (fraction, p_plus)
        fraction = new
    return state + (False, f"the cohesive zone did not settle (last change of the cohesive fraction {change:.1e})")


def _adhesive_nested(h, dx, modulus, load, mean_pressure, periodic, reference, sigma0, h0, cap, precondition,
                     zones=None, *, settings):
    """Initial p+ [Pa] and cohesive fraction from the adhesive problem on nested coarser grids (every other point).

    Each level is solved loosely (``settings.coarse_tolerance``, cohesive fraction to
    ``settings.coarse_fraction_tolerance``); a level that does not settle is still used (a guess).
    Returns (None, None, 0) where n is odd or below 2 x ``settings.coarsest``.
    """
    n = h.size
    if n % 2 or n < 2 * settings.coarsest or n // 2 > settings.largest_adhesive_level:
        return None, None, 0
    coarse_mean = None if mean_pressure is None else mean_pressure
    state = _solve_adhesive(h[::2], 2.0 * dx, modulus, load, coarse_mean, None, periodic, settings.coarse_tolerance,
                            cap, reference, None, precondition, True, sigma0, h0,
                            fraction_tolerance=settings.coarse_fraction_tolerance, internal=True,
                            zones=_coarse_zones(zones), settings=settings)
    p_plus, fraction, used = state
    if p_plus is None:
        return None, None, used

    def interpolate(values):
        following = np.roll(values, -1) if periodic else np.append(values[1:], values[-1])
        fine = np.empty(n)
        fine[0::2] = values
        fine[1::2] = 0.5 * (values + following)
        return fine

    return interpolate(p_plus), interpolate(fraction), used


def _coarse_zones(zones):
    """The zones of :func:`_cohesive_fraction` on the nested coarser grid (every other point)."""
    if zones is None:
        return None
    return tuple((sigma, reach if np.ndim(reach) == 0 else reach[::2]) for sigma, reach in zones)


@cites("israelachvili_2011")
def _solve_capillary(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                     max_iterations, reference_distance, initial_pressure, precondition, continuation,
                     cohesive_stress, cohesive_range, capillary_stress, capillary_range, *, settings):
    """:func:`solve_line_contact` with capillary menisci inside the solve (humid air, issue #17, docs/humidity.md).

    The meniscus pulls with its Laplace pressure ``gamma / r_K`` [Pa] wherever the gap is at most the
    condensation height h_c [m] (Eq. (17.3) in Israelachvili 2011; :mod:`memstribo.physics.capillary`): a
    Dugdale-type traction of stress ``capillary_stress`` and range ``capillary_range``. Alone it is
    the Maugis-Dugdale problem with (sigma0, h0) = (gamma / r_K, h_c); with a vdW cohesive zone the
    traction is the sum of the two step functions of the gap, ``-(sigma0 1[g <= h0] + sigma_c 1[g <= h_c])``,
    solved by the same fixed point with the sigma-weighted cohesive fraction (:func:`_cohesive_fraction`).
    Without menisci (zero stress or range, e.g. RH 0 or a hydrophobic pair) the plain or adhesive
    solve is returned unchanged.
    """
    h = _check_problem(separation, dx, contact_modulus)
    if (capillary_stress is None) != (capillary_range is None):
        raise InputError("give both capillary_stress [Pa] and capillary_range [m] (the Laplace pressure gamma/r_K "
                         "and the condensation height h_c), or neither")
    if not np.isscalar(capillary_stress) or not np.isfinite(capillary_stress) or capillary_stress < 0:
        raise InputError(f"capillary_stress must be a finite number >= 0 [Pa], got {capillary_stress!r}")
    reach = np.asarray(capillary_range, dtype=float)
    if (reach.ndim not in (0, 1) or (reach.ndim == 1 and reach.shape != h.shape) or not np.all(np.isfinite(reach))
            or np.any(reach < 0)):
        raise InputError("capillary_range must be finite and >= 0 [m], a number or one value per element of "
                         "separation")
    sigma_c = float(capillary_stress)
    reach = float(reach) if reach.ndim == 0 else reach
    if sigma_c == 0.0 or not np.any(np.asarray(reach) > 0):
        if cohesive_stress is None and cohesive_range is None and approach is None:
            return _solve_elastic(separation, dx, contact_modulus, load, mean_pressure, periodic, tolerance,
                                  max_iterations, reference_distance, initial_pressure, precondition, continuation,
                                  "active-set", settings=settings)
        return _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                               max_iterations, reference_distance, initial_pressure, precondition, continuation,
                               cohesive_stress, cohesive_range, settings=settings)
    if (cohesive_stress is None) != (cohesive_range is None):
        raise InputError("give both cohesive_stress [Pa] and cohesive_range [m] (the Maugis-Dugdale sigma0 and h0), "
                         "or neither")
    vdw = bool(cohesive_stress) and bool(cohesive_range)
    zones = (resolved_zones(float(dx), float(contact_modulus), float(cohesive_stress), float(cohesive_range),
                            settings.zone_elements, settings.contact_only_range)[0]
             or ((float(cohesive_stress), float(cohesive_range)),) if vdw else ())
    zones += ((sigma_c, reach),)
    stress = sum(sigma for sigma, _ in zones)
    reach_max = max(float(np.max(r)) for _, r in zones)
    solution = None
    if approach is None and not periodic and h.size <= settings.zone_kernel_max:  # small free-boundary grids: dense
        solution = _small_capillary(h, dx, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                                    reference_distance, initial_pressure, stress, reach_max, zones,
                                    settings=settings)
    if solution is None:
        solution = _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                                   max_iterations, reference_distance, initial_pressure, precondition, continuation,
                                   stress, reach_max, zones=None if len(zones) == 1 and np.ndim(reach) == 0 else zones,
                                   dense=False, settings=settings)
    contact, gap = solution.contact, solution.gap
    wetted = _dense_fraction(gap, ((1.0, reach),), contact, periodic, settings=settings)
    capillary_load = float(sigma_c * solution.dx * wetted.sum())
    adhesive_load = 0.0
    if vdw:
        sigma0, h0 = zones[0]
        adhesive_load = float(sigma0 * solution.dx * _cohesive_fraction(gap, h0, contact, periodic)[~contact].sum())
    kind = (f"capillary (Laplace pressure {sigma_c:.4g} Pa over gaps <= {float(np.max(reach)):.4g} m"
            + (f", plus the Maugis-Dugdale zone sigma0 = {zones[0][0]:.4g} Pa, h0 = {zones[0][1]:.4g} m)" if vdw
               else ")"))
    message = kind + solution.message[solution.message.index("),") + 1:]
    return dataclasses.replace(solution, adhesive_load=adhesive_load, capillary_load=capillary_load, message=message)


def _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                    max_iterations, reference_distance, initial_pressure, precondition, continuation,
                    cohesive_stress, cohesive_range, fraction_tolerance=None, internal=False, zones=None, dense=True,
                    *, settings):
    """:func:`solve_line_contact` with a Maugis-Dugdale zone and/or under approach control.

    ``internal``: return (p+, cohesive fraction, CG iterations) for the nested levels instead.
    ``dense``: small free-boundary grids under load control first try the dense-matrix solve
    (:func:`_small_capillary` with the one zone); False skips it (its caller already tried).
    ``zones``: a traction of several step functions (:func:`_cohesive_fraction`); ``cohesive_stress``
    is then their summed stress and ``cohesive_range`` their largest range (:func:`_solve_capillary`).
    """
    start = time.perf_counter()
    fraction_tolerance = settings.fraction_tolerance if fraction_tolerance is None else fraction_tolerance
    h = _check_adhesive_inputs(separation, dx, contact_modulus, load, mean_pressure, approach, tolerance,
                               max_iterations, reference_distance, initial_pressure, cohesive_stress, cohesive_range)
    n = h.size
    dx = float(dx)
    modulus = float(contact_modulus)
    sigma0 = float(cohesive_stress or 0.0)
    h0 = float(cohesive_range or 0.0)
    if sigma0 == 0.0 or h0 == 0.0:
        sigma0 = h0 = 0.0
    elif not internal and zones is None:  # a zone the grid does not resolve: the same w, one it resolves
        zones, h0 = resolved_zones(dx, modulus, sigma0, h0, settings.zone_elements, settings.contact_only_range)
    if (dense and approach is None and not periodic and not internal
            and n <= (settings.zone_kernel_max if sigma0 else settings.dense_solve_max)):
        solution = _dense_adhesive(h, dx, modulus, load, mean_pressure, tolerance, max_iterations, reference_distance,
                                   initial_pressure, sigma0, h0, zones, start, settings)
        if solution is not None:
            return solution
    reference, cap, operator, small = _operator_and_limits(n, dx, modulus, periodic, reference_distance,
                                                          max_iterations, settings=settings)
    offset = float(h.min())
    h = h - offset
    p_start = np.asarray(initial_pressure, dtype=float) if initial_pressure is not None else None
    if sigma0 and approach is None and settings.cohesive_start == "loading":
        p_start = None  # the loading-branch state: the one this solver reaches without a start
    coarse = [0]
    problem = (operator, h, dx, modulus, periodic, reference, cap, small, sigma0, h0, zones, p_start)
    if approach is not None:
        inner, scale, fraction, nested_guess = _approach_problem(*problem, float(approach) - offset,
                                                                 settings=settings)
        control = "approach control"
    else:
        inner, scale, fraction, nested_guess = _load_problem(*problem, offset, load, mean_pressure, precondition,
                                                             continuation, coarse, settings=settings)
        control = "load control"
    if sigma0:
        guess = np.maximum(p_start + sigma0 * fraction, 0.0) if p_start is not None else None
        if approach is None and nested_guess is not None:
            guess = nested_guess
        (p, gap, contact, fraction, approach_out, iterations, outer, residual, settled,
         why) = _cohesive_iteration(operator, h, sigma0, h0, fraction, guess, inner, periodic, tolerance, scale,
                                    fraction_tolerance,
                                    settings.coarse_max_updates if internal
                                    else settings.small_zone_max_updates if n <= settings.small_zone
                                    else settings.adhesive_max_outer,
                                    zones, extrapolate=approach is None, settings=settings)
        if internal:
            ok = np.isfinite(residual)
            return (p + sigma0 * fraction if ok else None), (fraction if ok else None), iterations + coarse[0]
        cohesive = (fraction > 0.0) & ~contact
        adhesive_load = float(sigma0 * dx * fraction[cohesive].sum())
    else:
        p, gap, contact, approach_out, iterations, residual, settled, why = inner(
            h, 0.0, np.maximum(p_start, 0.0) if p_start is not None else None, tolerance)
        outer, cohesive, adhesive_load = 1, np.zeros(n, dtype=bool), 0.0
    converged = bool(settled and residual <= tolerance)
    kind = _zone_kind(sigma0, h0, zones) if sigma0 else "non-adhesive"
    message = _adhesive_message(kind, control, converged, outer, iterations, residual, tolerance, why, cap,
                                coarse[0], contact, cohesive, periodic)
    return ContactSolution(pressure=p, gap=np.maximum(gap, 0.0) if converged else gap, contact=contact,
                           approach=float(approach_out) + offset, load=float(p.sum() * dx), iterations=iterations,
                           residual=float(residual), converged=converged, solve_time=time.perf_counter() - start,
                           message=message, dx=dx, periodic=bool(periodic), coarse_iterations=coarse[0],
                           adhesive_load=adhesive_load, cohesive=cohesive)


def _dense_adhesive(h, dx, modulus, load, mean_pressure, tolerance, max_iterations, reference_distance,
                    initial_pressure, sigma0, h0, zones, start, settings):
    """The small-grid dense solve of a free-boundary problem under load control, or None (use the general one)."""
    n = h.size
    if not sigma0:
        solution = _small_contact(h, dx, modulus, load, mean_pressure, tolerance, reference_distance, initial_pressure,
                                  start, settings=settings)  # no zone: the plain small-grid solve
        if solution is not None:
            return dataclasses.replace(solution, adhesive_load=0.0, cohesive=np.zeros(n, dtype=bool))
        return None
    return _small_capillary(h, dx, modulus, load, mean_pressure, False, tolerance, max_iterations,
                            reference_distance, initial_pressure, sigma0, h0,
                            ((sigma0, h0),) if zones is None else zones, kind=_zone_kind(sigma0, h0, zones),
                            checked=True, settings=settings)


def _zone_kind(sigma0, h0, zones):
    """The start of the message of a Maugis-Dugdale solve [text]: sigma0 [Pa] and h0 [m], and the law of a widened
    zone (``zones`` of :func:`memstribo.physics.contact.subgrid.resolved_zones`, or None)."""
    widened = (zones is not None and len(zones) == 2 and np.ndim(zones[1][1]) == 0
               and zones[1][1] < 1e-3 * zones[0][1])  # the contact-only part has (almost) no range
    if not widened:
        return _kind_text(sigma0, h0)
    (sigma, h), (_, reach) = zones
    return _kind_text(sigma0, h0, sigma, h, reach == 0.0)


@functools.lru_cache(maxsize=16)
def _kind_text(sigma0, h0, sigma=None, h=None, everywhere=False):
    """:func:`_zone_kind`'s text, kept per zone (a meshing cycle's ~10^4 solves share one); ``everywhere``: the
    contact-only part has no range at all (``SolverSettings.contact_only_range = 0``), the contact holds sigma too."""
    if sigma is None:
        return f"adhesive (Maugis-Dugdale, sigma0 = {sigma0:.4g} Pa, h0 = {h0:.4g} m)"
    return (f"adhesive (Maugis-Dugdale, sigma0 = {sigma0:.4g} Pa, h0 = {sigma * h / sigma0:.4g} m; the zone is "
            f"narrower than this grid resolves: the same w over sigma = {sigma:.4g} Pa, h = {h:.4g} m "
            + ("in and outside the contact)" if everywhere else "outside the contact)"))


def _approach_problem(operator, h, dx, modulus, periodic, reference, cap, small, sigma0, h0, zones, p_start, delta,
                      *, settings):
    """(inner solve, residual scale [m], start cohesive fraction, None) of the problem under approach control."""
    scale = float(h.max()) if h.max() > 0 else max(abs(delta), h0, dx)
    factors = {}

    def inner(h_eff, extra, guess, tol):
        p, g, contact, used, outer, settled = _approach_contact(operator, h_eff, delta, guess, tol * scale, cap,
                                                                factors, settings=settings)
        # gap error on the contact set, penetration outside it
        residual = max(np.abs(g[contact]).max(initial=0.0), np.maximum(-g[~contact], 0.0).max(initial=0.0)) / scale
        return p, g, contact, delta, used, residual, settled, "the contact set did not settle (it cycles)"

    fraction = None
    if sigma0:
        fraction = (np.clip(-p_start / sigma0, 0.0, 1.0) + (p_start > 0.0) if p_start is not None
                    else _cohesive_fraction(h - delta, h0, h - delta <= 0.0, periodic, zones))
        fraction = np.minimum(fraction, 1.0)
    return inner, scale, fraction, None


def _load_problem(operator, h, dx, modulus, periodic, reference, cap, small, sigma0, h0, zones, p_start, offset,
                  load, mean_pressure, precondition, continuation, coarse, *, settings):
    """(inner solve, residual scale [m], start cohesive fraction, nested p+ guess) of the problem under load control.

    ``coarse``: a one-element list that counts the CG iterations spent on the nested coarser grids.
    """
    n = h.size
    total = float(load) / dx if load is not None else float(mean_pressure) * n
    scale = float(h.max()) if h.max() > 0 else max(abs(total) * dx / modulus, h0)

    def inner(h_eff, extra, guess, tol):
        inner_total = total + extra
        if inner_total <= 0.0:
            return (np.zeros(n), h_eff - h_eff.min(), np.zeros(n, dtype=bool), 0.0, 0, np.inf, False,
                    "the cohesive zone cannot carry this tensile load: no adhered state on the branch followed "
                    "(past pull-off); follow the unloading curve under approach control")
        target = inner_total / n
        shift = float(h_eff.min())
        h_eff = h_eff - shift
        warm = guess is not None and guess.sum() > 0.0  # the previous zone update's p+ (or the caller's)
        if not warm:
            guess = None
            if continuation and precondition:
                guess, used = _nested_guess(h_eff, dx, modulus, target, periodic, reference, cap, small,
                                            settings=settings)
                coarse[0] += used
            if guess is None:
                guess = _cold_start(h_eff, target, small, settings=settings)
        p = guess * (target / guess.mean())
        p, used, _, _ = _active_set(operator, h_eff, p, target, tol * scale, cap, precondition, small=small,
                                    settle_first=warm and settings.settle_first, settings=settings)
        p, g, contact, g_mean, residual, used = _polonsky_keer(operator, h_eff, p, target, tol, scale, cap,
                                                               precondition, used)
        return p, g - g_mean, contact, float(g_mean) + shift, used, residual, residual <= tol, ""

    nested_guess = fraction = None
    if sigma0 and p_start is None and continuation and precondition:
        nested_guess, nested_fraction, used = _adhesive_nested(h + offset, dx, modulus, load, mean_pressure,
                                                               periodic, reference, sigma0, h0, cap, precondition,
                                                               zones, settings=settings)
        coarse[0] += used
    if sigma0:
        if nested_guess is not None:
            fraction = nested_fraction
        elif p_start is not None and np.any(p_start != 0.0):
            fraction = np.minimum(np.clip(-p_start / sigma0, 0.0, 1.0) + (p_start > 0.0), 1.0)
        elif total > 0.0:
            fraction = np.zeros(n)
        else:
            fraction = _cohesive_fraction(h, h0, h <= 0.0, periodic, zones)
    return inner, scale, fraction, nested_guess


def _adhesive_message(kind, control, converged, outer, iterations, residual, tolerance, why, cap, coarse_iterations,
                      contact, cohesive, periodic):
    """What the adhesive solve did, in words (convergence, updates, resolution and domain warnings)."""
    if converged:
        message = (f"{kind}, {control}: converged after {outer} cohesive-zone update(s), {iterations} iterations "
                   f"(residual {residual:.2e} <= tolerance {tolerance:.1e})")
    else:
        message = (f"{kind}, {control}: NOT converged after {outer} cohesive-zone update(s), {iterations} iterations: "
                   f"{why or f'residual {residual:.2e} > tolerance {tolerance:.1e}'} (max_iterations={cap})")
    if coarse_iterations:
        message += f"; {coarse_iterations} more on the coarser nested grids"
    n_contact = int(np.count_nonzero(contact))
    if 0 < n_contact < 3:
        message += f"; the contact is resolved by only {n_contact} element(s): refine the grid"
    if not periodic and (contact[0] or contact[-1] or cohesive[0] or cohesive[-1]):
        message += "; the contact or cohesive zone reaches the edge of the domain: enlarge it"
    return message
