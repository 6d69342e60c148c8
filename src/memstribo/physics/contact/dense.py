"""The small-grid dense path: Cholesky solves of contact sets with the full influence matrix, and the compiled
cohesive-zone loop (:mod:`memstribo.physics._zone_kernel`) for meshing windows of up to ~1024 elements."""

from __future__ import annotations

import functools
import math
import time

import numpy as np
import scipy.linalg

from memstribo.physics.contact.halfplane import ContactSolution, _full_matrix, _half_plane
from memstribo.physics.contact.inputs import _check_adhesive_inputs
from memstribo.physics._threads import limit_blas_threads
from memstribo.references import cites

limit_blas_threads()  # small dense algebra, many calls: one BLAS thread (memstribo.physics._threads)


_kernel_module = None  # memstribo.physics._zone_kernel, once imported (numba: on first use)


def _compiled():
    """The compiled zone loop's module, imported on first use (an import statement costs ~2 us per solve)."""
    global _kernel_module
    if _kernel_module is None:
        from memstribo.physics import _zone_kernel

        _kernel_module = _zone_kernel
    return _kernel_module


@functools.lru_cache(maxsize=8)
def _toeplitz_kernel(n, dx, contact_modulus, periodic, reference_distance):
    """(kernel, reversed kernel) of the influence matrix of a uniform grid of n elements: A[i, j] = kernel[|i - j|]
    [m/Pa] (:meth:`HalfPlane.matrix` gathers the same numbers), cached per grid; read-only. The compiled zone loop
    reads these n numbers instead of the n x n matrix (10 MB at 1116 elements, past the cache)."""
    kernel = np.ascontiguousarray(_half_plane(n, dx, contact_modulus, periodic, reference_distance).green_kernel[:n])
    reverse = np.ascontiguousarray(kernel[::-1])
    kernel.setflags(write=False)
    reverse.setflags(write=False)
    return kernel, reverse


@functools.cache
def _lapack_cholesky():
    return scipy.linalg.get_lapack_funcs(("potrf", "potrs"), (np.empty(1),))


def _saddle_point(matrix, h_contact, total):
    """(p_C [Pa], approach [m]) of ``A_CC p_C - approach = -h_C`` with ``sum(p_C) = total``, or None.

    Two solves with one Cholesky factor, ``A_CC y1 = 1`` and ``A_CC y2 = -h_C``, then
    ``p_C = approach y1 + y2``; None if A_CC is not numerically positive definite (the caller then
    uses the CG). ``matrix`` (symmetric, float64) is overwritten.
    """
    # LAPACK directly (scipy.linalg.cho_factor/cho_solve add ~30 us per call); the matrix is
    # symmetric, so its transpose is the Fortran-ordered array potrf wants, without a copy
    potrf, potrs = _lapack_cholesky()
    factor, info = potrf(matrix.T, lower=False, clean=False, overwrite_a=True)
    if info != 0:
        return None
    rhs = np.empty((h_contact.size, 2), order="F")
    rhs[:, 0] = 1.0
    np.negative(h_contact, out=rhs[:, 1])
    y, info = potrs(factor, rhs, lower=False, overwrite_b=True)
    if info != 0:
        return None
    ones_sum = y[:, 0].sum()
    if not np.isfinite(ones_sum) or ones_sum <= 0.0:
        return None
    approach = (total - y[:, 1].sum()) / ones_sum
    return approach * y[:, 0] + y[:, 1], approach


def _direct_solution(operator, h, indices, total):
    """Pressure [Pa] on the contact set ``indices`` by a Cholesky solve of the saddle-point system.

    ``A_CC p_C - approach = -h_C`` with ``sum(p_C) = total``: two solves with one factor,
    ``A_CC y1 = 1`` and ``A_CC y2 = -h_C``, then ``p_C = approach y1 + y2``. Returns None if
    A_CC is not numerically positive definite (the caller then uses the CG).
    """
    solved = _saddle_point(operator.matrix(indices, operator.green_kernel), h[indices], total)
    if solved is None:
        return None
    p = np.zeros(h.size)
    p[indices] = solved[0]
    return p


def _dense_fraction(gap, zones, contact, periodic, *, settings):
    """:func:`_cohesive_fraction` with ``zones`` on a small grid (the same formula, less overhead).

    One zone of one range (the Maugis-Dugdale zone) is evaluated only where the gap can reach it
    (:func:`_sparse_fraction`).
    """
    if len(zones) == 1 and np.ndim(zones[0][1]) == 0:
        fraction = _sparse_fraction(gap, float(zones[0][0]), float(zones[0][1]), contact, periodic,
                                    settings=settings)
        if fraction is not None:
            return fraction
    neighbours = np.empty((2, gap.size))
    if periodic:
        neighbours[0], neighbours[1] = np.roll(gap, 1), np.roll(gap, -1)
    else:
        neighbours[0, 0], neighbours[0, 1:] = gap[0], gap[:-1]
        neighbours[1, -1], neighbours[1, :-1] = gap[-1], gap[1:]
    edge = 0.5 * (neighbours + gap)
    low, high = np.minimum(edge, gap), np.maximum(edge, gap)
    span = high - low
    positive = span > 0.0
    total = 0.0
    out = np.zeros(gap.size)
    for sigma, reach in zones:
        part = np.divide(reach - low, span, out=(low <= reach) * 1.0, where=positive)
        fraction = 0.5 * np.minimum(np.maximum(part, 0.0), 1.0).sum(axis=0)
        fraction[contact] = 1.0
        if np.ndim(reach):
            fraction[reach <= 0.0] = 0.0
        out += sigma * fraction
        total += sigma
    return out / total


def _sparse_fraction(gap, sigma, reach, contact, periodic, *, settings):
    """The cohesive fraction [-] of one zone (stress ``sigma`` [Pa], range ``reach`` [m]), or None.

    The formula of :func:`_dense_fraction`, element by element (the same floating-point operations) on the few
    elements outside the contact set that can carry a fraction: a half element does only where its lower end
    ``min(g_i, (g_i + g_j) / 2)`` is <= reach, which with every gap >= min(g) needs ``g_i <= 2 reach - min(g)``.
    None where more than ``settings.sparse_fraction_max`` elements qualify.
    """
    n = gap.size
    last = n - 1
    limit = 2.0 * reach - min(float(gap.min()), 0.0)
    fraction = contact.astype(float)
    candidates = ((gap <= limit + abs(limit) * 1e-9) & ~contact).nonzero()[0]
    if candidates.size > settings.sparse_fraction_max:
        return None
    values = gap.tolist()
    for i in candidates.tolist():  # plain floats: cheaper than numpy on a handful of elements
        g = values[i]
        both = 0.0
        for j in (i - 1, i + 1):  # the left and the right half
            neighbour = values[j % n] if periodic else values[0 if j < 0 else (last if j > last else j)]
            edge = 0.5 * (neighbour + g)
            low, high = (edge, g) if edge < g else (g, edge)
            span = high - low
            part = (reach - low) / span if span > 0.0 else float(low <= reach)
            both += 0.0 if part < 0.0 else (1.0 if part > 1.0 else part)
        fraction[i] = (sigma * (0.5 * both)) / sigma
    return fraction


def _dense_factor(matrix, indices):
    """(indices, Cholesky factor of A_CC, y1 = A_CC^-1 1, sum(y1)) on the contact set C (``indices``).

    None where A_CC is not numerically positive definite (as :func:`_saddle_point`).
    """
    potrf, potrs = _lapack_cholesky()
    factor, info = potrf(matrix[indices[:, None], indices].T, lower=False, clean=False, overwrite_a=True)
    if info != 0:
        return None
    ones, info = potrs(factor, np.ones(indices.size), lower=False, overwrite_b=True)
    ones_sum = float(ones.sum())
    if info != 0 or not math.isfinite(ones_sum) or ones_sum <= 0.0:
        return None
    return indices, factor, ones, ones_sum


def _dense_contact(matrix, h, total, contact, tolerance_abs, *, settings):
    """Non-adhesive contact on a small grid under load control: primal-dual active set with Cholesky solves.

    ``A_CC p_C - delta = -h_C``, ``sum(p_C) = total`` on the contact set C (:func:`_saddle_point`'s two
    solves with one factor), then C updated (p < 0 leaves, penetration joins) until it settles. Returns
    (p, gap, contact, delta, sets solved) or None (no set, cycling, not positive definite: the caller falls
    back to the general solver). The cohesive-zone problems run the same loop compiled
    (:mod:`memstribo.physics._zone_kernel`).
    """
    key = contact.tobytes()
    if b"\x01" not in key:
        contact = h <= h.min()
        key = contact.tobytes()
    potrs = _lapack_cholesky()[1]
    seen = set()
    for updates in range(1, settings.max_outer + 1):
        factored = _dense_factor(matrix, contact.nonzero()[0])
        if factored is None:
            return None
        indices, factor, ones, ones_sum = factored
        y, info = potrs(factor, -h[indices], lower=False, overwrite_b=True)
        if info != 0:
            return None
        delta = (total - y.sum()) / ones_sum
        p_contact = delta * ones + y
        p = np.zeros(h.size)
        p[indices] = p_contact
        gap = matrix @ p
        gap += h
        gap -= delta
        new = gap < -tolerance_abs
        new[indices] = p_contact > 0.0
        new_key = new.tobytes()
        if new_key == key:
            gap[indices] = 0.0
            return p, gap, contact, delta, updates
        if new_key in seen or b"\x01" not in new_key:
            return None
        seen.add(new_key)
        contact, key = new, new_key
    return None


def _small_contact(h, dx, modulus, load, mean_pressure, tolerance, reference_distance, initial_pressure, start, *,
                   settings):
    """The non-adhesive free-boundary solve on a small grid by :func:`_dense_contact`, or None (general solver)."""
    n = h.size
    reference = float(reference_distance) if reference_distance is not None else n * dx
    offset = float(h.min())
    h = h - offset
    total = float(load) / dx if load is not None else float(mean_pressure) * n
    scale = float(h.max()) if h.max() > 0 else total * dx / modulus
    contact = (np.asarray(initial_pressure) > 0.0 if initial_pressure is not None
               else np.zeros(n, dtype=bool))
    state = _dense_contact(_full_matrix(n, dx, modulus, False, reference), h, total, contact, tolerance * scale,
                           settings=settings)
    if state is None:
        return None
    p, gap, contact, delta, updates = state
    residual = float(np.maximum(-gap[~contact], 0.0).max(initial=0.0)) / scale
    converged = residual <= tolerance
    verdict = "converged" if converged else "NOT converged"
    message = (f"active-set, load control, dense matrices: {verdict} after {updates} contact set(s), each solved exactly "
               f"(Cholesky) (residual {residual:.2e}, tolerance {tolerance:.1e})")
    n_contact = int(np.count_nonzero(contact))
    if n_contact < 3:
        message += f"; the contact is resolved by only {n_contact} element(s): refine the grid"
    if contact[0] or contact[-1]:
        message += "; the contact reaches the edge of the domain: enlarge it"
    return ContactSolution(pressure=p, gap=np.maximum(gap, 0.0) if converged else gap, contact=contact,
                           approach=float(delta) + offset, load=float(p.sum() * dx), iterations=updates,
                           residual=residual, converged=bool(converged), solve_time=time.perf_counter() - start,
                           message=message, dx=dx, periodic=False, coarse_iterations=0)


def _zone_arrays(zones, n):
    """(sigmas [Pa], reaches [m] per zone and element, whether a zone's reach is per element, summed stress [Pa]) of
    ``zones`` ((sigma, reach) pairs, a reach a number or one per element) on a grid of n elements, as the compiled
    zone loop reads them."""
    sigmas = np.array([float(s) for s, _ in zones])
    reaches = np.empty((len(zones), n))
    per_element = np.zeros(len(zones), dtype=bool)
    for k, (_, reach) in enumerate(zones):
        reaches[k] = reach
        per_element[k] = np.ndim(reach) > 0
    return sigmas, reaches, per_element, float(sigmas.sum())


@functools.lru_cache(maxsize=16)
def _scalar_zone_arrays(zones, n):
    """:func:`_zone_arrays` of zones whose reaches are numbers, kept per (zones, n): a cycle's ~10^4 solves share a
    few. The compiled loop only reads them (they stay writeable: a read-only array would be another numba
    signature)."""
    return _zone_arrays(zones, n)


@cites("maugis_1992", "rey_2017", "bazrafshan_2017", "model")  # the fixed point of _cohesive_iteration
def _dense_capillary(h, dx, modulus, total, periodic, reference, zones, p_start, tolerance, top=None, *, settings):
    """The capillary (and vdW) zone problem on a small grid under load control, by dense matrices.

    The same fixed point on the cohesive fraction as :func:`_cohesive_iteration` (traction
    -sigma f, the non-adhesive problem for p+ with the gap h - sigma A f and the sum
    total + sigma sum(f); settled when no fraction moves by more than ``settings.fraction_tolerance``, or
    the zone's load by less than ``settings.zone_load_tolerance`` with no fraction moving by more than
    ``settings.zone_max_change``; Aitken extrapolation of creeping fronts every third update), each
    inner problem solved exactly (Cholesky on the contact set, primal-dual active set as
    :func:`_dense_contact`). The loop is compiled (:func:`memstribo.physics._zone_kernel.zone_solve`):
    a meshing cycle makes ~10^4 of these solves of ~20 updates each. ``h`` has its minimum at 0; ``top``: its
    maximum [m], where the caller has it.
    Returns (p, gap, contact, fraction, delta, updates) or None where it cannot (the general solver then runs).
    """
    compiled = _compiled()
    n = h.size
    kernel, reverse = _toeplitz_kernel(n, dx, modulus, periodic, reference)
    try:  # zones of numbers (the Maugis-Dugdale zone, the menisci of one height): their arrays are kept
        sigmas, reaches, per_element, sigma = _scalar_zone_arrays(zones, n)
    except TypeError:  # a range per element (an array: not hashable)
        sigmas, reaches, per_element, sigma = _zone_arrays(zones, n)
    top = float(h.max()) if top is None else top
    scale = top if top > 0 else max(abs(total) * dx / modulus, max(float(np.max(r)) for _, r in zones))
    if p_start is not None and settings.cohesive_start == "loading":  # the loading branch: the zone empty, the
        # contact set of the start pressure on small grids, none on large ones (from the lowest element, as the
        # general solver, _solve_adhesive): the first update is the non-adhesive problem, whose contact set is unique,
        # so the start changes only the path to it (SolverSettings.loading_start_max, issue 40)
        contact = p_start > 0.0 if n <= settings.loading_start_max else np.zeros(n, dtype=bool)
        fraction = np.zeros(n)
    elif p_start is not None:  # min(clip(-p/sigma, 0, 1) + (p > 0), 1)
        contact = p_start > 0.0
        fraction = np.minimum(np.maximum(-p_start / sigma, 0.0), 1.0)
        fraction[contact] = 1.0
    else:
        fraction = np.zeros(n)
        contact = np.zeros(n, dtype=bool)
    status, p, gap, delta, updates = compiled.zone_solve(
        kernel, reverse, np.ascontiguousarray(h, dtype=float), float(total), sigmas, reaches, per_element, bool(periodic),
        fraction, contact, tolerance * scale, settings.adhesive_max_outer, settings.max_outer,
        settings.fraction_tolerance, settings.zone_load_tolerance, settings.zone_max_change, settings.aitken_min_ratio, settings.aitken_max_ratio)
    if status != compiled.SETTLED:
        return None
    return p, gap, contact, fraction, delta, updates


def _small_capillary(separation, dx, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                     reference_distance, initial_pressure, stress, reach, zones, kind="capillary (dense)",
                     checked=False, *, settings):
    """:func:`_dense_capillary` as a :class:`ContactSolution`, or None (the general solver then runs).

    ``kind`` starts the message (what the zones are); ``checked``: ``separation`` is the array its caller
    has already checked (with the other inputs), so the checks are not run twice.
    """
    start = time.perf_counter()
    h = separation if checked else _check_adhesive_inputs(separation, dx, contact_modulus, load, mean_pressure, None,
                                                          tolerance, max_iterations, reference_distance,
                                                          initial_pressure, stress, reach)
    n = h.size
    dx = float(dx)
    modulus = float(contact_modulus)
    reference = float(reference_distance) if reference_distance is not None else n * dx
    offset = float(h.min())
    h = h - offset
    total = float(load) / dx if load is not None else float(mean_pressure) * n
    p_start = np.asarray(initial_pressure, dtype=float) if initial_pressure is not None else None
    top = float(h.max())
    state = _dense_capillary(h, dx, modulus, total, bool(periodic), reference, zones, p_start, tolerance, top,
                             settings=settings)
    if state is None:
        return None
    p, gap, contact, fraction, delta, outer = state
    scale = top if top > 0 else max(abs(total) * dx / modulus, reach)
    # complementarity residual as the general solver's: penetration outside the contact set (its gap is exact:
    # zero on the set, so the smallest gap is the deepest penetration outside it, if any)
    residual = max(0.0, -float(gap.min())) / scale  # max(0, -0.0): not "-0.00e+00"
    converged = residual <= tolerance
    cohesive = (fraction > 0.0) & ~contact
    verdict = "converged" if converged else "NOT converged"
    message = (f"{kind}, load control, dense matrices: {verdict} after {outer} "
               f"cohesive-zone update(s), each inner problem solved exactly (Cholesky) (residual {residual:.2e}, "
               f"tolerance {tolerance:.1e})")
    if not periodic and (contact[0] or contact[-1] or cohesive[0] or cohesive[-1]):
        message += "; the contact or cohesive zone reaches the edge of the domain: enlarge it"
    return ContactSolution(pressure=p, gap=np.maximum(gap, 0.0) if converged else gap, contact=contact,
                           approach=float(delta) + offset, load=float(p.sum() * dx), iterations=outer,
                           residual=residual, converged=bool(converged), solve_time=time.perf_counter() - start,
                           message=message, dx=dx, periodic=bool(periodic), coarse_iterations=0,
                           adhesive_load=float(stress * dx * fraction[cohesive].sum()), cohesive=cohesive)
