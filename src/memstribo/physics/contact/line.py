"""The line solver (periodic and free boundary), load control: primal-dual active set with a preconditioned CG
on each contact set, nested coarser grids as the initial guess, Polonsky & Keer's constrained CG as the fallback."""

from __future__ import annotations

import time

import numpy as np

from memstribo.errors import InputError

from memstribo.physics.contact.dense import _direct_solution, _small_contact
from memstribo.physics.contact.halfplane import ContactSolution, _cg_update, _dot, _half_plane
from memstribo.physics.contact.inputs import _check_inputs


def _polonsky_keer(operator, h, p, target, tolerance, scale, cap, precondition, iteration):
    """Polonsky & Keer's constrained CG from pressure ``p``; also the final exact residual check."""
    n = h.size
    t = np.zeros(n)
    G_old = 1.0
    conjugate = False
    residual = np.inf
    while True:
        u = operator.displacement(p)
        g = h + u
        contact = p > 0.0
        n_contact = np.count_nonzero(contact)
        g_mean = g[contact].sum() / n_contact
        r = np.where(contact, g - g_mean, 0.0)
        # complementarity residual: gap error on the contact set, penetration outside it
        penetration = np.where(contact, 0.0, np.maximum(g_mean - g, 0.0))
        residual = max(np.abs(r).max(), penetration.max()) / scale
        if residual <= tolerance or iteration >= cap:
            break
        iteration += 1
        # working set: the contact set plus the points that penetrate (Polonsky-Keer's I_ol)
        overlap = (~contact) & (g < g_mean)
        reactivate = bool(overlap.any())
        if reactivate and precondition:
            work = contact | overlap
            r = np.where(work, g - g_mean, 0.0)
            n_work = np.count_nonzero(work)
        else:
            work, n_work = contact, n_contact
        if precondition:
            z = operator.precondition(r)
            z = np.where(work, z, 0.0)
            z[work] -= z[work].sum() / n_work
        else:
            z = r
        G = _dot(r, z)
        if G <= 0.0:  # round-off: no descent direction left
            break
        if conjugate:
            t = z + (G / G_old) * t
            t[~work] = 0.0
        else:
            t = z
        G_old = G
        q = operator.displacement(t)
        q_mean = q[work].sum() / n_work
        q = np.where(work, q - q_mean, 0.0)
        denominator = _dot(q, t)
        if denominator <= 0.0:  # no descent left: restart along the (preconditioned) gradient
            t[:] = 0.0
            conjugate = False
            continue
        tau = _dot(r, t) / denominator
        p = p - tau * t
        p[p < 0.0] = 0.0
        if reactivate and not precondition:
            p[overlap] = (g_mean - g[overlap]) * tau
        conjugate = not reactivate
        total = p.mean()
        if total <= 0.0:
            p = np.full(n, target)
            conjugate = False
        else:
            p *= target / total

    return p, g, contact, g_mean, residual, iteration


def _operator_and_limits(n, dx, modulus, periodic, reference_distance, max_iterations, *, settings):
    """(datum [m], CG iteration cap, half-plane operator, small problem?) of a solve on n elements."""
    reference = float(reference_distance) if reference_distance is not None else n * dx
    cap = int(max_iterations) if max_iterations is not None else max(1000, n // 4)
    # the small-problem measures (direct solves, cold start, short coarse levels) pay off up to
    # here; above, the coarse levels' guess matters more than their cost (2^18: 5-9 % slower)
    return (reference, cap, _half_plane(n, dx, modulus, bool(periodic), reference, settings.fft_workers),
            n <= settings.small_problem)


def _use_direct(operator, n_contact, small, *, settings):
    return small and n_contact <= settings.direct_max and operator.size <= settings.dense_grid


def _active_set(operator, h, p, target, tolerance, cap, precondition, max_outer=None, small=True,
                settle_first=False, *, settings):
    """Primal-dual active set: PCG on a fixed contact set, then update the set; until it settles.

    ``settle_first``: the guess ``p`` is a warm start close to the solution (the previous
    cohesive-zone update's p+, :func:`_cohesive_iteration`); its contact set (p > 0) is first
    solved to a fifth of the guess's complementarity violation, and only then updated. Without
    it the first set update is taken from the unsolved guess, which after a change of the
    cohesive zone lets ~100 elements next to the contact edges join (they penetrate only until
    the contact pressure has adjusted) and leave again, each set change restarting the CG
    (docs/contact.md, "Adhesive contact", "Speed").

    Returns the pressure, the CG iterations used, the outer iterations and whether the set
    settled (if not, the caller goes on with Polonsky-Keer from the pressure returned).
    """
    n = h.size
    total = target * n
    contact = p > 0.0
    iterations = 0
    violation = np.inf
    if settle_first and contact.any():
        g = h + operator.displacement(p)
        gap = g - g[contact].sum() / np.count_nonzero(contact)
        violation = max(np.abs(gap[contact]).max(), np.maximum(-gap[~contact], 0.0).max(initial=0.0))
    space = {}  # dense path: the working set and its matrices, kept across set updates
    for outer in range(1, (max_outer or settings.max_outer) + 1):
        n_contact = np.count_nonzero(contact)
        if n_contact == 0:
            return p, iterations, outer, False
        p_previous = p
        indices = np.flatnonzero(contact)
        # inexact inner solve: no tighter than needed to tell the next contact set
        inner_tolerance = max(0.5 * tolerance, settings.inner_factor * violation)
        p = (_direct_solution(operator, h, indices, total) if _use_direct(operator, n_contact, small, settings=settings)
             else None)
        exact = p is not None
        if exact:
            iterations += 1  # one direct solve counted as one iteration
        else:
            p, iterations = _solve_set(operator, h, p_previous, contact, indices, total, inner_tolerance, cap,
                                       precondition, small, iterations, space, settings)
        settled, new, violation = _update_set(operator, h, p, contact, n_contact, total, tolerance, exact)
        if settled is not None:
            return settled, iterations, outer, True
        if iterations >= cap:
            break
        contact = new
    return np.maximum(p, 0.0), iterations, outer, False


def _update_set(operator, h, p, contact, n_contact, total, tolerance, exact):
    """(the accepted pressure or None, the next contact set, the complementarity violation [m]) after a solve."""
    g = h + operator.displacement(p)
    gap = g - g[contact].sum() / n_contact
    new = (contact & (p > 0.0)) | (~contact & (gap < 0.0))
    negative = -p[contact].min() if n_contact else 0.0
    violation = max(np.abs(np.where(contact, gap, 0.0)).max(), np.maximum(-gap[~contact], 0.0).max(initial=0.0))
    if violation <= tolerance and negative < 0:  # complementarity holds, all p > 0
        return p, new, violation
    # complementarity holds but some pressures are <= 0: accept the clipped field if it
    # holds too. After an exact solve only if they are tiny: larger ones (all that occurred
    # in the benchmark problems) fail the check, and the next set update costs about as much
    if violation <= tolerance and (not exact or negative <= 1e-6 * p.max()):
        clipped = np.maximum(p, 0.0)
        clipped *= total / clipped.sum()
        kept = clipped > 0.0
        g = h + operator.displacement(clipped)
        gap = g - g[kept].sum() / np.count_nonzero(kept)
        if max(np.abs(gap[kept]).max(), np.maximum(-gap[~kept], 0.0).max(initial=0.0)) <= tolerance:
            return clipped, new, violation
    return None, new, violation


def _solve_set(operator, h, p_previous, contact, indices, total, inner_tolerance, cap, precondition, small,
               iterations, space, settings):
    """The pressure [Pa] on a fixed contact set by the (preconditioned) CG, and the iteration count so far.

    Small sets (on a small grid, or a tooth contact on a larger one) use dense products on a working set
    kept in ``space`` across set updates; larger ones FFTs on the full grid, on compressed vectors.
    """
    n = h.size
    n_contact = indices.size
    if n_contact <= settings.dense_max and (n_contact**2 <= 4 * operator.size
                                            or small and operator.size <= settings.dense_grid):
        p_c, r, apply, apply_inverse, mask, packed = _dense_set(operator, h, p_previous, contact, indices, total,
                                                                precondition, space, settings)
    else:
        # CG on the contact set only, on compressed vectors (FFTs on the full grid)
        mask, packed = None, indices
        p = np.zeros(n)
        p_c = p_previous[indices]
        p_c += (total - p_c.sum()) / n_contact
        p[indices] = p_c
        r = (h + operator.displacement(p))[indices]
        stiffness, green = operator.stiffness, operator.green

        def apply(values):
            return operator.restricted(values, indices, green)

        def apply_inverse(values):
            return operator.restricted(values, indices, stiffness)
    iterations = _pcg(p_c, r, apply, apply_inverse if precondition else None, mask, n_contact, inner_tolerance,
                      cap, iterations)
    p = np.zeros(n)
    p[packed] = p_c
    return p, iterations


def _dense_set(operator, h, p_previous, contact, indices, total, precondition, space, settings):
    """Start vectors and dense operators of the CG on a working set S that holds the contact set.

    Small sets on a larger grid (a tooth contact) or small grids: dense products beat full-grid FFTs. The
    matrices are built on S (~n_S^2 operations) and reused while the contact set stays inside S; vectors on
    S are zero outside the contact set (``mask``).
    """
    n_contact = indices.size
    if not space or not space["member"][indices].all():
        grown = np.union1d(space["set"], indices) if space else indices
        chosen = grown if grown.size <= settings.dense_max else indices
        member = np.zeros(h.size, dtype=bool)
        member[chosen] = True
        offsets = operator.offsets(chosen)
        space.update(set=chosen, member=member, influence=operator.matrix(chosen, operator.green_kernel, offsets),
                     inverse=operator.matrix(chosen, operator.stiffness_kernel, offsets) if precondition else None)
    chosen = space["set"]
    mask = contact[chosen].astype(float) if chosen.size > n_contact else None
    apply = space["influence"].__matmul__
    apply_inverse = space["inverse"].__matmul__ if precondition else None
    p_c = p_previous[chosen]
    if mask is not None:
        p_c *= mask
    p_c += (total - p_c.sum()) / n_contact * (mask if mask is not None else 1.0)
    r = h[chosen] + apply(p_c)
    return p_c, r, apply, apply_inverse, mask, chosen


def _project(values, mask, n_contact):
    """Remove the mean over the contact set, in place (``mask``: the set within a larger working set)."""
    if mask is not None:
        values *= mask
        values -= (values.sum() / n_contact) * mask
    else:
        values -= values.sum() / n_contact


def _pcg(p_c, r, apply, apply_inverse, mask, n_contact, inner_tolerance, cap, iterations):
    """Preconditioned CG on a fixed contact set, ``p_c`` and ``r`` updated in place; returns the iteration count."""
    _project(r, mask, n_contact)
    t = None
    G_old = 1.0
    for inner in range(cap):
        if max(r.max(), -r.min()) <= inner_tolerance or iterations >= cap:
            break
        iterations += 1
        if apply_inverse is not None:
            z = apply_inverse(r)
            _project(z, mask, n_contact)
        else:
            z = r
        G = _dot(r, z)
        if G <= 0.0:  # the residual vanishes in the preconditioned norm (round-off): nothing to do
            break
        if inner:
            t *= G / G_old
            t += z
        else:
            t = z.copy()
        G_old = G
        q = apply(t)
        _project(q, mask, n_contact)
        if not _cg_update(p_c, r, t, q):
            break
    return iterations


def _cold_start(h, target, small=True, *, settings):
    """Initial pressure [Pa] without a guess: uniform on the lower part of the gap (``settings.start_fraction``)."""
    if settings.start_fraction >= 1.0 or not small:
        return np.full(h.size, target)
    k = int(settings.start_fraction * (h.size - 1))
    low = h <= np.partition(h, k)[k]
    return np.where(low, target * h.size / np.count_nonzero(low), 0.0)


def _nested_guess(h, dx, modulus, target, periodic, reference, cap, small=True, *, settings):
    """Initial pressure from nested coarser grids (every other point), or (None, 0) if n is small or odd.

    Each level runs the active-set method to ``settings.coarse_tolerance`` from the level below; its
    result is only a guess, so a level that does not settle is used as it is (no fallback).
    Returns the guess on this grid [Pa] and the CG iterations spent.
    """
    n = h.size
    if n % 2 or n < 2 * settings.coarsest:
        return None, 0
    coarse_h = h[::2] - h[::2].min()
    guess, iterations = _nested_guess(coarse_h, 2.0 * dx, modulus, target, periodic, reference, cap, small,
                                      settings=settings)
    if guess is None:
        guess = _cold_start(coarse_h, target, small, settings=settings)
    operator = _half_plane(coarse_h.size, 2.0 * dx, modulus, periodic, reference, settings.fft_workers)
    # gap tolerance: the smaller of 1e-3 of the peak-to-valley and 1/10 of the rms step between
    # neighbours (on long domains the first alone is too loose to predict the contact set)
    scale = float(coarse_h.max()) if coarse_h.max() > 0 else 1.0
    local = float(np.std(np.diff(coarse_h))) or scale
    tolerance = min(settings.coarse_tolerance * scale, settings.coarse_step_fraction * local)
    max_outer = settings.coarse_max_outer if small and operator.size <= settings.dense_grid else None
    coarse_p, used, _, _ = _active_set(operator, coarse_h, guess * (target / guess.mean()), target, tolerance, cap,
                                       True, max_outer, small, settings=settings)
    fine = np.empty(n)
    fine[0::2] = coarse_p
    following = np.roll(coarse_p, -1) if periodic else np.append(coarse_p[1:], 0.0)
    fine[1::2] = 0.5 * (coarse_p + following)
    if small and _half_plane(n, dx, modulus, periodic, reference, settings.fft_workers).size <= settings.dense_grid:
        # the fine grid is solved directly (exact solves, fewer set updates from a set close to
        # the final one): in contact only between two coarse points in contact. (The CG levels
        # of larger grids converge faster from the wider set of plain interpolation.)
        fine[1::2] *= (coarse_p > 0) & (following > 0)
    return fine, iterations + used


def cylinder_on_flat(radius, length, points):
    """Undeformed gap of a smooth cylinder on a flat, ``h(x) = x^2 / (2R)`` (Johnson 1985 §4.3).

    Parameters
    ----------
    radius : float
        Radius R of the cylinder (the effective radius of two cylinders) [m], > 0.
    length : float
        Length of the domain [m], > 0, centred on the apex.
    points : int
        Number of elements, >= 2.

    Returns
    -------
    (ndarray, float)
        The separation at the element centres [m] and the element width [m].
    """
    if not (np.isfinite(radius) and radius > 0 and np.isfinite(length) and length > 0):
        raise InputError(f"cylinder_on_flat: radius and length must be positive lengths, got {radius!r}, {length!r}.")
    if int(points) < 2:
        raise InputError(f"cylinder_on_flat: at least 2 elements are needed, got {points!r}.")
    n = int(points)
    dx = float(length) / n
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    return x**2 / (2.0 * float(radius)), dx


def _solve_elastic(separation, dx, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                   reference_distance, initial_pressure, precondition, continuation, method, *, settings):
    """:func:`memstribo.physics.contact.solve_line_contact` without adhesion, under load control."""
    start = time.perf_counter()
    coarse_iterations = 0
    h = _check_inputs(separation, dx, contact_modulus, load, mean_pressure, tolerance, max_iterations,
                      reference_distance, initial_pressure)
    n = h.size
    if method == "active-set" and precondition and not periodic and n <= settings.dense_solve_max:
        solution = _small_contact(h, float(dx), float(contact_modulus), load, mean_pressure, tolerance,
                                  reference_distance, initial_pressure, start, settings=settings)
        if solution is not None:
            return solution
    dx = float(dx)
    modulus = float(contact_modulus)
    target = float(mean_pressure) if mean_pressure is not None else float(load) / (n * dx)
    reference, cap, operator, small = _operator_and_limits(n, dx, modulus, periodic, reference_distance,
                                                          max_iterations, settings=settings)

    offset = float(h.min())
    h = h - offset
    # residual scale [m]: the peak-to-valley of the gap; for a flat gap the displacement scale w/E*
    scale = float(h.max()) if h.max() > 0 else target * n * dx / modulus
    if initial_pressure is None and continuation and precondition:
        initial_pressure, coarse_iterations = _nested_guess(h, dx, modulus, target, periodic, reference, cap, small,
                                                            settings=settings)
    if initial_pressure is not None and np.sum(initial_pressure) > 0:
        p = np.asarray(initial_pressure, dtype=float) * (target / np.mean(initial_pressure))
    else:
        p = _cold_start(h, target, small, settings=settings)

    iteration = 0
    method_used = "polonsky-keer"
    if method == "active-set":
        p, iteration, _, settled = _active_set(operator, h, p, target, tolerance * scale, cap, precondition,
                                               small=small, settings=settings)
        method_used = "active-set" if settled else "active-set, then polonsky-keer"
    p, g, contact, g_mean, residual, iteration = _polonsky_keer(operator, h, p, target, tolerance, scale, cap,
                                                                precondition, iteration)
    gap = np.where(contact, 0.0, g - g_mean)
    converged = residual <= tolerance
    message = _message(method_used, converged, iteration, residual, tolerance, cap, coarse_iterations, contact,
                       periodic)
    return ContactSolution(pressure=p, gap=np.maximum(gap, 0.0) if converged else gap, contact=contact,
                           approach=float(g_mean) + offset, load=float(p.sum() * dx), iterations=iteration,
                           residual=float(residual), converged=bool(converged),
                           solve_time=time.perf_counter() - start, message=message, dx=dx,
                           periodic=bool(periodic), coarse_iterations=coarse_iterations)


def _message(method_used, converged, iteration, residual, tolerance, cap, coarse_iterations, contact, periodic):
    """What the plain solve did, in words (convergence, iterations, resolution and domain warnings)."""
    n_contact = int(np.count_nonzero(contact))
    if converged:
        message = (f"{method_used}: converged in {iteration} iterations (residual {residual:.2e} <= tolerance "
                   f"{tolerance:.1e})")
    else:
        message = (f"{method_used}: NOT converged: residual {residual:.2e} > tolerance {tolerance:.1e} after "
                   f"{iteration} iterations (max_iterations={cap})")
    if coarse_iterations:
        message += f"; {coarse_iterations} more on the coarser nested grids"
    if n_contact < 3:
        message += f"; the contact is resolved by only {n_contact} element(s): refine the grid"
    if not periodic and (contact[0] or contact[-1]):
        message += "; the contact reaches the edge of the domain: enlarge it"
    return message
