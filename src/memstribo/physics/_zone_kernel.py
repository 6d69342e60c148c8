"""The small-grid cohesive-zone solve of :func:`memstribo.physics.contact._dense_capillary`, compiled (numba).

A meshing cycle solves some ten thousand Maugis-Dugdale (and capillary) line contacts on grids of
~170 elements, each by ~20 updates of the cohesive fraction. In numpy every update is some 30
calls on small arrays (~30 us of call overhead for a few us of arithmetic), so the loop is compiled
here: the same fixed point, the same settling rule, the same inner active-set solve with exact
(Cholesky) solves on each contact set; only the order of the floating-point sums differs (matrix
products over the non-zero columns only). Imported lazily (with numba: ~0.3 s) and
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


def _jit(function):
    """``numba.njit`` with numba's cache, or without it where no cache folder is writable (numba raises then;
    each process compiles anew, ~6 s)."""
    try:
        return njit(cache=True, nogil=True)(function)
    except RuntimeError:  # "cannot cache function ...: no locator available"
        return njit(nogil=True)(function)


@_jit
def _cholesky(matrix, indices, m, factor):
    """Lower Cholesky factor of matrix[indices[:m], indices[:m]] into factor[:m, :m]; False if not positive definite."""
    for j in range(m):
        jj = indices[j]
        s = matrix[jj, jj]
        for k in range(j):
            s -= factor[j, k] * factor[j, k]
        if not s > 0.0:  # also NaN
            return False
        d = math.sqrt(s)
        factor[j, j] = d
        for i in range(j + 1, m):
            t = matrix[indices[i], jj]
            for k in range(j):
                t -= factor[i, k] * factor[j, k]
            factor[i, j] = t / d
    return True


@_jit
def _cholesky_solve(factor, m, b, out):
    """out[:m] = (L L^T)^-1 b[:m]."""
    for i in range(m):
        s = b[i]
        for k in range(i):
            s -= factor[i, k] * out[k]
        out[i] = s / factor[i, i]
    for i in range(m - 1, -1, -1):
        s = out[i]
        for k in range(i + 1, m):
            s -= factor[k, i] * out[k]
        out[i] = s / factor[i, i]


@_jit
def _columns_product(matrix, values, support, count, out):
    """out = matrix @ values for values non-zero only at support[:count] (matrix symmetric: rows are read)."""
    out[:] = 0.0
    n = out.size
    for c in range(count):
        j = support[c]
        v = values[j]
        for i in range(n):
            out[i] += matrix[j, i] * v


@_jit
def _contact(matrix, h, total, contact, tolerance_abs, max_sets, state):
    """Non-adhesive contact under load control on the grid (as contact._dense_contact); fills p, gap, contact.

    ``state``: the work arrays and the cached factor (kept between calls while the contact set stays).
    Returns (ok, delta).
    """
    (p, gap, indices, factor, ones, y, rhs, cached, seen, new) = state
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
        if not same or cached[n] == 0:  # a new set: factorise (cached[n] flags a valid factor)
            cached[n] = 0
            if not _cholesky(matrix, indices, m, factor):
                return False, 0.0
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
        _columns_product(matrix, p, indices, m, gap)
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
def zone_solve(matrix, h, total, sigmas, reaches, per_element, periodic, fraction, contact, tolerance_abs,
               max_updates, max_sets, fraction_tolerance, load_tolerance, max_change, aitken_min, aitken_max):
    """The cohesive-zone fixed point on a small grid (contact._dense_capillary); see the module's docstring.

    ``fraction`` and ``contact`` hold the start and are overwritten. Returns (status, p, gap, delta, updates).
    """
    n = h.size
    sigma = 0.0
    for z in range(sigmas.size):
        sigma += sigmas[z]
    p = np.zeros(n)
    gap = np.zeros(n)
    state = (p, gap, np.zeros(n, np.int64), np.zeros((n, n)), np.zeros(n), np.zeros(n), np.zeros(n),
             np.zeros(n + 1, np.bool_), np.zeros((max_sets, n), np.bool_), np.zeros(n, np.bool_))
    h_eff = np.empty(n)
    pulled = np.empty(n)
    support = np.empty(n, np.int64)
    new = np.empty(n)
    history = np.zeros((3, n))  # the last three gaps (ring), for the Aitken extrapolation
    stored = 0
    extrapolated = np.empty(n)
    for outer in range(1, max_updates + 1):
        extra = 0.0
        count = 0
        for i in range(n):
            extra += fraction[i]
            if fraction[i] != 0.0:
                support[count] = i
                count += 1
        extra *= sigma
        if total + extra <= 0.0:
            return FAILED, p, gap, 0.0, outer
        if extra > 0.0:
            _columns_product(matrix, fraction, support, count, pulled)
            for i in range(n):
                h_eff[i] = h[i] - sigma * pulled[i]
        else:
            h_eff[:] = h
        ok, delta = _contact(matrix, h_eff, total + extra, contact, tolerance_abs, max_sets, state)
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
