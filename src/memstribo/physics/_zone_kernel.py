"""The small-grid cohesive-zone solve of :func:`memstribo.physics.contact._dense_capillary`, compiled (numba).

A meshing cycle solves some ten thousand Maugis-Dugdale (and capillary) line contacts on grids of
~170 elements, each by ~20 updates of the cohesive fraction. In numpy every update is some 30
calls on small arrays (~30 us of call overhead for a few us of arithmetic), so the loop is compiled
here: the same fixed point, the same settling rule, the same inner active-set solve with exact
(Cholesky) solves on each contact set; only the order of the floating-point sums differs (matrix
products over the non-zero columns only). Between zone updates the contact set changes at a few edge
elements: its factor is updated (rows removed by a rank-one update of the trailing block, rows added
at the end) rather than computed anew where at most an eighth of the set (at least 4 elements) is removed; any
number of rows is added (issue #25: 3.9 -> 2.4 ms per solve at 160 elements across the Hertz width, the same
results to round-off). The influence matrix of the uniform grid is Toeplitz (A[i, j] = kernel[|i - j|]): the loop
reads its n numbers, not the n x n matrix (10 MB at the 1116 elements of the thesis load case, past the caches),
and the dot products of the factorisation and of its solves are summed in any order (vectorised; ``_REORDERED_SUMS``):
1116 elements 7.9 -> 3.1 ms per solve, 381 elements 1.39 -> 0.82 ms (issue #25, bench/bench_convergence.py), the
same zone updates, pressures within 1.5e-8 of their largest; the product of the cohesive fractions with the matrix
is updated by the columns whose fraction changed (2.8 ms at 1116 elements, 0.71 ms at 381). Imported lazily (with numba: ~0.3 s) and
compiled once per machine (numba's cache, next to this file or in the user's cache directory;
without a writable one, once per process).

Status codes of :func:`zone_solve`: 0 settled, 1 the update budget ran out, 2 the inner solve
failed (no positive-definite contact set, a cycling or empty set, or a non-positive total load):
the caller hands the problem on to the general solver for 1 and 2.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

SETTLED, UNSETTLED, FAILED = 0, 1, 2


def _jit(function, **options):
    """``numba.njit`` with numba's cache, or without it where no cache folder is writable (numba raises then;
    each process compiles anew, ~6 s). ``options``: more of njit's (``fastmath``)."""
    try:
        return njit(cache=True, nogil=True, **options)(function)
    except RuntimeError:  # "cannot cache function ...: no locator available"
        return njit(nogil=True, **options)(function)


#: The dot products of the Cholesky factorisation and its updates may be summed in any order (vectorised: 2.4x at
#: 165 elements); the factor then differs from the one summed in order by round-off (2e-15 of its largest entry).
_REORDERED_SUMS = {"reassoc", "contract"}


def _jit_sums(function):
    """:func:`_jit` with the sums of ``function`` free to be reordered (:data:`_REORDERED_SUMS`)."""
    return _jit(function, fastmath=_REORDERED_SUMS)


@_jit_sums
def _cholesky(kernel, indices, m, factor):
    """Lower Cholesky factor of A[indices[:m], indices[:m]] into factor[:m, :m], A[i, j] = kernel[|i - j|] (a symmetric
    Toeplitz matrix: the influence matrix of a uniform grid); False if not positive definite."""
    for j in range(m):
        jj = indices[j]
        s = kernel[0]
        for k in range(j):
            s -= factor[j, k] * factor[j, k]
        if not s > 0.0:  # also NaN
            return False
        d = math.sqrt(s)
        factor[j, j] = d
        for i in range(j + 1, m):
            t = kernel[abs(indices[i] - jj)]
            for k in range(j):
                t -= factor[i, k] * factor[j, k]
            factor[i, j] = t / d
    return True


@_jit_sums
def _cholesky_solve(factor, m, b, out):
    """out[:m] = (L L^T)^-1 b[:m]."""
    for i in range(m):
        s = b[i]
        for k in range(i):
            s -= factor[i, k] * out[k]
        out[i] = s / factor[i, i]
    for i in range(m - 1, -1, -1):  # L^T by rows of L (contiguous; the column of L^T was read with a stride of n)
        value = out[i] / factor[i, i]
        out[i] = value
        row = factor[i, :i]
        for k in range(i):
            out[k] -= row[k] * value


@_jit
def _delete_from_factor(factor, m, k, x):
    """Remove row and column k of the m x m lower Cholesky factor in place (a rank-one update of the trailing block,
    O((m - k)^2)); the factor is then (m - 1) x (m - 1). ``x``: work array of at least m."""
    r = m - k - 1
    for i in range(r):
        x[i] = factor[k + 1 + i, k]
    for i in range(k + 1, m):  # rows below k move up one, columns right of k move left one
        for j in range(k):
            factor[i - 1, j] = factor[i, j]
        for j in range(k + 1, i + 1):
            factor[i - 1, j - 1] = factor[i, j]
    for j in range(r):  # T T^T + x x^T of the trailing block T = factor[k:m-1, k:m-1]
        d = factor[k + j, k + j]
        rr = math.sqrt(d * d + x[j] * x[j])
        c = rr / d
        sn = x[j] / d
        factor[k + j, k + j] = rr
        for i in range(j + 1, r):
            factor[k + i, k + j] = (factor[k + i, k + j] + sn * x[i]) / c
            x[i] = c * x[i] - sn * factor[k + i, k + j]


@_jit_sums
def _append_to_factor(kernel, factor, order, m, j):
    """Add element j as row and column m of the factor of A[order[:m], order[:m]] (A[i, j] = kernel[|i - j|]; O(m^2));
    False if the matrix is then not positive definite."""
    total = 0.0
    for i in range(m):
        value = kernel[abs(order[i] - j)]
        for t in range(i):
            value -= factor[i, t] * factor[m, t]
        value /= factor[i, i]
        factor[m, i] = value
        total += value * value
    d2 = kernel[0] - total
    if not d2 > 0.0:
        return False
    factor[m, m] = math.sqrt(d2)
    order[m] = j
    return True


@_jit
def _update_factor(kernel, contact, cached, order, m_old, factor, x, max_changes):
    """The factor of the contact set from the factor of the previous set (``order[:m_old]``, ``cached``): rows
    removed and added one at a time instead of a new factorisation (the set changes at a few edge elements between
    zone updates). Returns the new size, or -1 where more than ``max_changes`` rows are removed or a row cannot be
    added (the caller factorises anew). Rows added cost no more than a new factorisation (a row added is a row of
    the same left-looking factorisation), so any number of them is added; a row removed costs a rank-one update of
    the rows after it."""
    n = contact.size
    removed = 0
    for i in range(n):
        if cached[i] and not contact[i]:
            removed += 1
    if removed > max_changes:
        return -1
    m = m_old
    for k in range(m_old - 1, -1, -1):  # removals, from the end (earlier positions stay valid)
        if not contact[order[k]]:
            _delete_from_factor(factor, m, k, x)
            for t in range(k, m - 1):
                order[t] = order[t + 1]
            m -= 1
    for i in range(n):
        if contact[i] and not cached[i]:
            if not _append_to_factor(kernel, factor, order, m, i):
                return -1
            m += 1
    return m


@_jit
def _columns_product(kernel, reverse, values, support, count, out):
    """out = A @ values for values non-zero only at support[:count], A[i, j] = kernel[|i - j|] (Toeplitz).

    ``reverse[k] = kernel[n - 1 - k]``, so that both halves of a column are read forwards (vectorised); each out[i]
    sums the columns in the order of ``support``, as the product with the full matrix did (the same numbers).
    """
    out[:] = 0.0
    _columns_product_add(kernel, reverse, values, support, count, out)


@_jit
def _columns_product_add(kernel, reverse, values, support, count, out):
    """out += A @ values for values non-zero only at support[:count] (:func:`_columns_product` without the reset)."""
    n = out.size
    last = n - 1
    for c in range(count):
        j = support[c]
        v = values[j]
        left, before = out[:j], reverse[last - j:last]  # kernel[j - i] = reverse[last - j + i], i < j
        for i in range(j):
            left[i] += before[i] * v
        right, after = out[j:], kernel[:n - j]
        for i in range(n - j):
            right[i] += after[i] * v


@_jit
def _contact(kernel, reverse, h, total, contact, tolerance_abs, max_sets, state):
    """Non-adhesive contact under load control on the grid (as contact._dense_contact); fills p, gap, contact.

    ``state``: the work arrays and the cached factor (kept between calls while the contact set stays).
    Returns (ok, delta).
    """
    (p, gap, indices, factor, ones, y, rhs, cached, seen, new, order, meta, x) = state
    n = h.size
    if not contact.any():
        low = h.min()
        for i in range(n):
            contact[i] = h[i] <= low
    n_seen = 0
    for _ in range(max_sets):
        m = 0
        same = True
        for i in range(n):
            if contact[i]:
                indices[m] = i
                m += 1
            if contact[i] != cached[i]:
                same = False
        if not same or cached[n] == 0:  # a new set (cached[n] flags a valid factor of order[:meta[0]])
            updated = -1
            if cached[n] == 1:  # the previous set's factor, rows removed and added (a few edge elements)
                updated = _update_factor(kernel, contact, cached, order, meta[0], factor, x, max(4, m // 8))
            cached[n] = 0
            if updated == m:
                for i in range(m):
                    indices[i] = order[i]
            else:  # factorise anew, in the order of the elements
                if not _cholesky(kernel, indices, m, factor):
                    return False, 0.0
                for i in range(m):
                    order[i] = indices[i]
            meta[0] = m
            for i in range(m):
                rhs[i] = 1.0
            _cholesky_solve(factor, m, rhs, ones)
            ones_sum = 0.0
            for i in range(m):
                ones_sum += ones[i]
            if not (math.isfinite(ones_sum) and ones_sum > 0.0):
                return False, 0.0
            for i in range(n):
                cached[i] = contact[i]
            cached[n] = 1
        else:
            for i in range(m):  # the factor's order
                indices[i] = order[i]
            ones_sum = 0.0
            for i in range(m):
                ones_sum += ones[i]
        for i in range(m):
            rhs[i] = -h[indices[i]]
        _cholesky_solve(factor, m, rhs, y)
        y_sum = 0.0
        for i in range(m):
            y_sum += y[i]
        delta = (total - y_sum) / ones_sum
        p[:] = 0.0
        for i in range(m):
            p[indices[i]] = delta * ones[i] + y[i]
        _columns_product(kernel, reverse, p, indices, m, gap)
        for i in range(n):
            gap[i] += h[i] - delta
            new[i] = gap[i] < -tolerance_abs
        for i in range(m):
            new[indices[i]] = p[indices[i]] > 0.0
        if (new == contact).all():
            for i in range(m):
                gap[indices[i]] = 0.0
            return True, delta
        if not new.any():
            return False, 0.0
        for s in range(n_seen):
            if (seen[s] == new).all():
                return False, 0.0
        seen[n_seen, :] = new
        n_seen += 1
        contact[:] = new
    return False, 0.0


@_jit
def _fraction(gap, sigmas, reaches, per_element, contact, periodic, out):
    """The sigma-weighted cohesive fraction of the zones (contact._dense_fraction's formula) into out."""
    n = gap.size
    total = 0.0
    for z in range(sigmas.size):
        total += sigmas[z]
    out[:] = 0.0
    for z in range(sigmas.size):
        sigma = sigmas[z]
        for i in range(n):
            if contact[i]:
                f = 1.0
            else:
                g = gap[i]
                reach = reaches[z, i]
                f = 0.0
                for j in (i - 1, i + 1):
                    if periodic:
                        neighbour = gap[j % n]
                    else:
                        neighbour = gap[0 if j < 0 else (n - 1 if j > n - 1 else j)]
                    edge = 0.5 * (neighbour + g)
                    low = edge if edge < g else g
                    high = g if edge < g else edge
                    span = high - low
                    if span > 0.0:
                        part = (reach - low) / span
                        f += 0.0 if part < 0.0 else (1.0 if part > 1.0 else part)
                    else:
                        f += 1.0 if low <= reach else 0.0
                f *= 0.5
            if per_element[z] and reaches[z, i] <= 0.0:
                f = 0.0
            out[i] += sigma * f
    for i in range(n):
        out[i] /= total


@_jit
def zone_solve(kernel, reverse, h, total, sigmas, reaches, per_element, periodic, fraction, contact, tolerance_abs,
               max_updates, max_sets, fraction_tolerance, load_tolerance, max_change, aitken_min, aitken_max):
    """The cohesive-zone fixed point on a small grid (contact._dense_capillary); see the module's docstring.

    ``kernel[k]``: the influence matrix at offset k (A[i, j] = kernel[|i - j|], k < n), ``reverse[k] = kernel[n - 1 -
    k]``. ``fraction`` and ``contact`` hold the start and are overwritten. Returns (status, p, gap, delta, updates).
    """
    n = h.size
    sigma = 0.0
    for z in range(sigmas.size):
        sigma += sigmas[z]
    p = np.zeros(n)
    gap = np.zeros(n)
    state = (p, gap, np.zeros(n, np.int64), np.empty((n, n)), np.zeros(n), np.zeros(n), np.zeros(n),
             np.zeros(n + 1, np.bool_), np.zeros((max_sets, n), np.bool_), np.zeros(n, np.bool_),
             np.zeros(n, np.int64), np.zeros(1, np.int64), np.zeros(n))
    h_eff = np.empty(n)
    pulled = np.empty(n)
    support = np.empty(n, np.int64)
    new = np.empty(n)
    history = np.zeros((3, n))  # the last three gaps (ring), for the Aitken extrapolation
    stored = 0
    extrapolated = np.empty(n)
    pulled[:] = 0.0  # A @ applied: the product of the fractions applied so far, updated by their changes only
    applied = np.zeros(n)
    change_of = np.empty(n)
    for outer in range(1, max_updates + 1):
        extra = 0.0
        count = 0
        for i in range(n):
            extra += fraction[i]
            if fraction[i] != applied[i]:
                support[count] = i
                change_of[i] = fraction[i] - applied[i]
                applied[i] = fraction[i]
                count += 1
        extra *= sigma
        if total + extra <= 0.0:
            return FAILED, p, gap, 0.0, outer
        if extra > 0.0:
            _columns_product_add(kernel, reverse, change_of, support, count, pulled)
            for i in range(n):
                h_eff[i] = h[i] - sigma * pulled[i]
        else:
            h_eff[:] = h
        ok, delta = _contact(kernel, reverse, h_eff, total + extra, contact, tolerance_abs, max_sets, state)
        if not ok:
            return FAILED, p, gap, 0.0, outer
        _fraction(gap, sigmas, reaches, per_element, contact, periodic, new)
        change = 0.0
        moved = 0.0
        zone = 0.0
        for i in range(n):
            step = abs(new[i] - fraction[i])
            moved += step
            if step > change:
                change = step
            if not contact[i]:
                zone += new[i]
        if change <= fraction_tolerance or (change <= max_change and moved <= load_tolerance * max(zone, 1.0)):
            for i in range(n):
                p[i] -= sigma * fraction[i]
            return SETTLED, p, gap, delta, outer
        history[stored % 3, :] = gap
        stored += 1
        if stored >= 3 and outer % 3 == 0:
            last, middle, first = history[(stored - 1) % 3], history[(stored - 2) % 3], history[(stored - 3) % 3]
            d1d0 = 0.0
            d0d0 = 0.0
            for i in range(n):
                d0 = middle[i] - first[i]
                d1d0 += (last[i] - middle[i]) * d0
                d0d0 += d0 * d0
            ratio = min(d1d0 / d0d0, aitken_max) if d0d0 > 0.0 else 0.0
            if ratio >= aitken_min:
                factor = ratio / (1.0 - ratio)
                for i in range(n):
                    extrapolated[i] = gap[i] + (last[i] - middle[i]) * factor
                _fraction(extrapolated, sigmas, reaches, per_element, contact, periodic, new)
        fraction[:] = new
    return UNSETTLED, p, gap, 0.0, max_updates
