"""Rough line contact: plane-strain half-plane boundary elements, FFT, constrained conjugate gradient.

The normal contact of two elastic bodies with a rough gap is solved on the half-plane
(docs/model.md, section 7): the combined undeformed gap ``separation`` h(x) [m] is given on a
uniform grid of ``n`` piecewise-constant pressure elements of width ``dx`` [m]; the unknown is
the pressure p >= 0 [Pa] with the gap

    g(x) = h(x) + u(x) - approach >= 0,     p g = 0,     dx * sum(p) = load,

where u is the combined elastic surface displacement (positive: the surfaces move apart) and
``approach`` [m] the rigid-body approach. Two half-planes are offered:

``periodic=False`` (free boundary, the right model for a gear tooth)
    Influence coefficients of uniformly loaded strips (Johnson 1985, Eq. 2.25a), evaluated by
    a linear (zero-padded, non-periodic) FFT convolution. In plane strain the displacement
    under a finite load grows like ``log(distance)``, so it needs a datum: the displacement of
    a point load is taken as zero at ``reference_distance`` (default: the domain length
    n*dx), i.e. the kernel is ``(2/(pi E*)) ln(L/|x|)``; :func:`memstribo.physics.closed_form.hertz_line_approach`
    is exact for this datum.
``periodic=True`` (for comparison with periodic solvers)
    The spectral Green's function u_k = 2 p_k / (E* |q_k|) at the grid wavenumbers, with a
    zero mean displacement (the convention of ContactMechanics and Tamaas, so the same
    problem is solved).

The solver (load control) is a primal-dual active-set iteration: on each contact set a
conjugate gradient preconditioned with the inverse of the half-plane operator in Fourier
space (E*|q|/2), restricted to the set, in the manner of Vollebregt (2014); the initial guess
from nested coarser grids; Polonsky & Keer's (1999) constrained conjugate gradient as the
fallback and alternative. On small grids (FFT size <= 1024) contact sets of up to 256 elements
are solved directly (Cholesky) and the CG uses dense matrices instead of FFTs. The operator is diagonal in Fourier space with a symbol |q|^-1, so
plain CG iteration counts grow quickly with n; here they grow roughly like sqrt(n) and the
measured lead over Tamaas and ContactMechanics widens with n (docs/contact.md,
bench/README-contact.md).

References
----------
.. [1] I. A. Polonsky, L. M. Keer, Wear 231 (1999) 206-219. :doi:`10.1016/S0043-1648(99)00113-1`
.. [2] E. A. H. Vollebregt, 'A new solver for the elastic normal contact problem using conjugate
   gradients, deflation, and an FFT-based preconditioner', J. Comput. Phys. 257 (2014) 333-351.
   :doi:`10.1016/j.jcp.2013.10.005`
.. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985.
.. [4] V. Rey, G. Anciaux, J.-F. Molinari, 'Normal adhesive contact on rough surfaces: efficient
   algorithm for FFT-based BEM resolution', Comput. Mech. 60 (2017) 69-81.
   :doi:`10.1007/s00466-017-1392-5`
.. [5] M. Bazrafshan, M. B. de Rooij, M. Valefi, D. J. Schipper, 'Numerical method for the
   adhesive normal contact analysis based on a Dugdale approximation', Tribol. Int. 112 (2017)
   117-128. :doi:`10.1016/j.triboint.2017.04.001`
"""

from __future__ import annotations

import dataclasses
import functools
import math
import time
from dataclasses import dataclass

import numpy as np
import scipy.fft
import scipy.linalg

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["ContactSolution", "solve_line_contact", "elastic_displacement", "strip_influence", "HalfPlane"]

#: Set updates of the cohesive zone (load control) or of the contact and cohesive sets (approach
#: control) before the adhesive solve gives up (converged=False).
_ADHESIVE_MAX_OUTER = 200
#: Cohesive-zone updates allowed on grids of at most _SMALL_ZONE elements (an update costs ~0.3 ms
#: there; damped updates, see _STALLED_UPDATES, may need several hundred: thesis load case).
_SMALL_ZONE_MAX_UPDATES = 1000
_SMALL_ZONE = 2048
#: The cohesive zone has settled when no element's cohesive fraction changes by more than this.
_FRACTION_TOLERANCE = 1e-4
#: ... or when the cohesive load changes by less than this relative amount (sum of the changes of
#: the fractions over the zone) and no fraction by more than _ZONE_MAX_CHANGE.
_ZONE_LOAD_TOLERANCE = 1e-4
_ZONE_MAX_CHANGE = 0.25
#: Gap accuracy of the inner solves, as a fraction of h0 times the last change of the cohesive fraction.
_GAP_FRACTION = 0.01
#: Updates without a new smallest change of the cohesive fraction after which the update is
#: under-relaxed (halved each time, down to _MIN_RELAXATION): breaks limit cycles at fronts.
_STALLED_UPDATES = 20
_MIN_RELAXATION = 0.25
#: ... and doubled again after this many updates in a row that each reach a new smallest change.
_IMPROVING_UPDATES = 5
#: Loosest relative tolerance of the inner solves.
_LOOSE_TOLERANCE = 1e-4
#: Contact sets up to this size are solved by Cholesky under approach control (larger: the CG).
_APPROACH_DIRECT_MAX = 64
#: Cohesive-zone updates of a coarse nested level (only a guess).
_COARSE_MAX_UPDATES = 15
#: Largest coarse level solved with adhesion; finer grids start from the non-adhesive nested
#: guess instead (2^16: 4.4x the plain solve against 5.3x with adhesive levels up to 2^15).
_LARGEST_ADHESIVE_LEVEL = 2**13
#: Tolerance on the cohesive fraction of the coarse nested levels (only a guess).
_COARSE_FRACTION_TOLERANCE = 1e-2
#: Warm-started inner solves of the cohesive-zone updates first solve on the guess's contact set
#: (:func:`_active_set`, ``settle_first``); False restores the former first set update from the
#: unsolved guess (kept for tests/test_adhesive_contact.py and the benchmark's comparison).
_SETTLE_FIRST = True
#: Warm start of each cohesive-zone update's inner solve (load control) extrapolated along the last change of p+
#: (:func:`_cohesive_iteration`); False: the last p+ as it is (the former start).
_LINEAR_RESPONSE_START = True
#: Largest convergence ratio used in the Aitken extrapolation of the cohesive-zone updates.
_AITKEN_MAX_RATIO = 0.95
#: ... applied only where the measured ratio is at least this (slow, creeping fronts).
_AITKEN_MIN_RATIO = 0.8

#: Grids with fewer elements are solved directly (the coarsest level of the nested grids).
_COARSEST = 512
#: Tolerance of the coarse levels of the nested grids (only their contact set matters).
_COARSE_TOLERANCE = 1e-3
#: ... and at most this fraction of the rms height step between neighbouring points.
_COARSE_STEP_FRACTION = 0.1
#: Contact sets up to this many elements (and n_contact^2 <= 4 x FFT size) use dense influence
#: matrices in the CG (a BLAS matrix-vector product of this size takes a few microseconds and
#: stays single-threaded; larger ones may go threaded, which is slow on a busy machine).
_DENSE_MAX = 256
#: ... or, for sets up to _DENSE_MAX, on grids of at most this FFT size, where the overhead of the
#: FFT calls (~7 us each) dominates. The matrices are built on a working set of at most
#: _DENSE_MAX elements that holds the contact set, and reused while later sets stay inside it.
_DENSE_GRID = 1024
#: On such small grids, contact sets up to this size are solved directly (Cholesky, ~0.15 ms at
#: 170 elements) instead of by the CG: exact solves need fewer contact-set updates.
_DIRECT_MAX = 256
#: Without an initial guess, start with a uniform pressure on this fraction of the grid with the
#: smallest gap (1.0: everywhere). Points that penetrate join in one set update, points with
#: p < 0 leave more slowly, so an under-estimate is cheaper than full contact: 1.1-1.5x faster
#: cold solves at 5-20 % contact, ~5 % slower at 45-90 % (bench/README-contact.md).
_START_FRACTION = 0.3
#: Problems up to this many elements use the measures for small problems: direct solves on small
#: grids, the cold start above, short directly solved coarse levels and the narrower interpolation.
_SMALL_PROBLEM = 2**14
#: Coarse levels solved directly (exact solves) stop after this many set updates: only a guess
#: is needed, and the fine grid settles the set (2^10: 2.15 -> 1.96 ms; 2^12-2^14 no slower).
_COARSE_MAX_OUTER = 3
#: Outer iterations (contact-set updates) of the active-set method before Polonsky-Keer takes over.
_MAX_OUTER = 30
#: Inner CG tolerance relative to the complementarity violation of the previous contact set.
_INNER_FACTOR = 0.2

#: Threads scipy.fft may use in the solver (1 = serial; the benchmark compares on one core).
FFT_WORKERS = 1


@dataclass(frozen=True)
class ContactSolve:
    """The fields every contact solve returns (line and surface); their meanings are those of
    :class:`ContactSolution` (the surface solution's are in :mod:`memstribo.physics.surface_contact`)."""

    pressure: np.ndarray
    gap: np.ndarray
    contact: np.ndarray
    approach: float
    load: float
    iterations: int
    residual: float
    converged: bool
    solve_time: float
    message: str


@dataclass(frozen=True)
class ContactSolution(ContactSolve):
    """Solution of a line contact.

    Attributes
    ----------
    pressure : numpy.ndarray
        Contact pressure of each element [Pa], >= 0.
    gap : numpy.ndarray
        Deformed gap of each element [m], >= 0 (zero on the contact set up to the tolerance).
    contact : numpy.ndarray
        Boolean mask of the elements in contact (pressure > 0).
    approach : float
        Rigid-body approach of the two bodies [m] (for ``periodic=False`` relative to the
        far-field datum ``reference_distance``; for ``periodic=True`` relative to a zero mean
        elastic displacement).
    load : float
        Load per unit face width carried, dx * sum(pressure) [N/m].
    iterations : int
        Conjugate-gradient iterations used (a direct solve on a small contact set counts as one).
    residual : float
        Complementarity residual at the end, dimensionless: the largest gap error on the
        contact set or penetration outside it, divided by the peak-to-valley of the separation.
    converged : bool
        Whether ``residual <= tolerance`` was reached within ``max_iterations``.
    solve_time : float
        Wall-clock time of the solve alone [s].
    message : str
        What happened, in words (why it did not converge, warnings on resolution).
    dx : float
        Element width [m].
    periodic : bool
        Whether the periodic half-plane was used.
    coarse_iterations : int
        CG iterations spent on the coarser nested grids that gave the initial guess (not
        included in ``iterations``).
    adhesive_load : float
        Tensile line load carried by the Maugis-Dugdale cohesive zone outside the contact,
        sigma0 * dx * (sum of the cohesive fractions of its elements) [N/m], >= 0; 0 without
        adhesion. The net ``load`` is the compressive load of the contact set minus this.
    cohesive : numpy.ndarray or None
        Boolean mask of the cohesive zone: elements out of contact (gap in (0, h0], the front
        elements partly) on which the Dugdale traction acts (-sigma0 times the fraction of the
        element within h0); None for the non-adhesive solver (no zone).
    capillary_load : float
        Line load of the capillary (meniscus) zone, ``capillary_stress * dx * (sum of the
        fractions of the elements whose gap is below ``capillary_range``, contact included)``
        [N/m], >= 0; 0 without it. Not part of ``adhesive_load`` (the vdW zone alone).

    Notes
    -----
    With adhesion (``cohesive_stress``/``cohesive_range`` given to :func:`solve_line_contact`)
    ``pressure`` is the net pressure, >= -sigma0 (negative: tensile), and ``load`` the net
    applied load, which may be negative (tensile).
    """

    dx: float
    periodic: bool
    coarse_iterations: int = 0
    adhesive_load: float = 0.0
    cohesive: np.ndarray | None = None
    capillary_load: float = 0.0

    @property
    def contact_length(self) -> float:
        """Measure of the contact set, dx times the number of elements in contact [m]."""
        return float(np.count_nonzero(self.contact) * self.dx)

    @property
    def max_pressure(self) -> float:
        """Largest element pressure [Pa]."""
        return float(self.pressure.max())

    @property
    def mean_pressure(self) -> float:
        """Mean pressure over the contact set, load / contact_length [Pa]."""
        length = self.contact_length
        return self.load / length if length > 0 else 0.0


class HalfPlane:
    """The discrete half-plane operator u = A p and its Fourier-space preconditioner.

    Built once per (n, dx, contact_modulus, periodic, reference_distance) and cached, so
    repeated solves on the same grid (a meshing cycle) pay no set-up cost.

    Parameters
    ----------
    n : int
        Number of elements.
    dx : float
        Element width [m].
    contact_modulus : float
        Contact modulus E* [Pa].
    periodic : bool
        Periodic half-plane (spectral Green's function) or free boundary (zero-padded
        convolution of the strip influence coefficients).
    reference_distance : float
        Datum distance L of the free-boundary displacement [m] (ignored when periodic).
    """

    def __init__(self, n, dx, contact_modulus, periodic, reference_distance):
        self.n, self.dx, self.periodic = n, dx, periodic
        self.modulus = contact_modulus
        if periodic:
            self.size = n
            q = 2.0 * np.pi * np.abs(scipy.fft.rfftfreq(n, d=dx))
            green = np.zeros_like(q)
            green[1:] = 2.0 / (contact_modulus * q[1:])
            self.green = green
            stiffness = 0.5 * contact_modulus * q
        else:
            self.size = scipy.fft.next_fast_len(2 * n, real=True)
            offsets = np.arange(self.size, dtype=float)
            offsets[self.size - n + 1:] -= self.size  # wrap: negative offsets at the end
            offsets[n:self.size - n + 1] = np.nan    # never reaches a collocation point
            kernel = strip_influence(offsets * dx, dx, contact_modulus, reference_distance)
            kernel[np.isnan(kernel)] = 0.0
            self.green = scipy.fft.rfft(kernel, workers=FFT_WORKERS)
            q = 2.0 * np.pi * np.abs(scipy.fft.rfftfreq(self.size, d=dx))
            stiffness = 0.5 * contact_modulus * q
        self.stiffness = stiffness

    def _apply(self, values, symbol):
        if self.periodic:
            return scipy.fft.irfft(scipy.fft.rfft(values, workers=FFT_WORKERS) * symbol, n=self.n,
                                   workers=FFT_WORKERS)
        spectrum = scipy.fft.rfft(values, n=self.size, workers=FFT_WORKERS)
        return scipy.fft.irfft(spectrum * symbol, n=self.size, workers=FFT_WORKERS)[: self.n]

    def restricted(self, values, indices, symbol):
        """Apply a Fourier ``symbol`` to ``values`` given on the elements ``indices`` only; gather there."""
        full = np.zeros(self.size)
        full[indices] = values
        spectrum = scipy.fft.rfft(full, workers=FFT_WORKERS)
        spectrum *= symbol
        return scipy.fft.irfft(spectrum, n=self.size, workers=FFT_WORKERS)[indices]

    @functools.cached_property
    def green_kernel(self):
        """The operator in real space: displacement [m/Pa] at element offset k (modulo the FFT size)."""
        return scipy.fft.irfft(self.green, n=self.size, workers=FFT_WORKERS)

    @functools.cached_property
    def stiffness_kernel(self):
        """The preconditioner in real space [Pa/m], indexed like :attr:`green_kernel`."""
        return scipy.fft.irfft(self.stiffness, n=self.size, workers=FFT_WORKERS)

    def offsets(self, indices):
        """Distances |i - j| (in elements) between the elements ``indices``, as a square index array."""
        differences = indices[:, None] - indices[None, :]
        return np.abs(differences, out=differences)

    def matrix(self, indices, kernel, offsets=None):
        """Dense matrix of a real-space ``kernel`` between the elements ``indices``.

        Both kernels are even (k[size - j] = k[j]) and offsets stay below n <= size, so the
        matrix is gathered at |i - j| (exactly symmetric); ``offsets`` may be given precomputed.
        """
        if offsets is None:
            offsets = self.offsets(indices)
        return kernel.take(offsets)

    def displacement(self, pressure):
        """Combined elastic surface displacement [m] of an element pressure [Pa]."""
        return self._apply(pressure, self.green)

    def precondition(self, gap_residual):
        """Approximate inverse: a pressure [Pa] that would produce ``gap_residual`` [m]."""
        return self._apply(gap_residual, self.stiffness)


def _dot(a, b):
    # BLAS only below its threading threshold: a threaded ddot on a busy machine costs ~1 ms
    # per call at n = 2^14, against 0.02 ms for multiply-and-sum
    if a.size < 4096:
        return float(np.vdot(a, b))
    return float(np.multiply(a, b).sum())


def _cg_update(p_c, r, t, q) -> bool:
    """One conjugate-gradient step on the contact set, in place: ``p_c -= tau t``, ``r -= tau q`` with the step
    ``tau = (r . t) / (q . t)`` along the search direction ``t`` (``q = A t``). False where ``q . t <= 0`` (no descent
    left: the caller stops)."""
    denominator = _dot(q, t)
    if denominator <= 0.0:
        return False
    tau = _dot(r, t) / denominator
    p_c -= tau * t
    r -= tau * q
    return True


@functools.lru_cache(maxsize=16)
def _half_plane(n, dx, contact_modulus, periodic, reference_distance):
    return HalfPlane(n, dx, contact_modulus, periodic, reference_distance)


@cites("johnson_1985")
def strip_influence(x, width, contact_modulus, reference_distance):
    r"""Surface displacement of a half-plane under a uniformly loaded strip of unit pressure.

    Parameters
    ----------
    x : numeric
        Distance of the field point from the strip centre [m].
    width : float
        Strip width dx [m].
    contact_modulus : float
        Contact modulus E* [Pa] (combined for the two bodies).
    reference_distance : float
        Datum distance L [m]: a point load's displacement vanishes at distance L.

    Returns
    -------
    numeric
        Displacement per unit pressure [m/Pa].

    Notes
    -----
    Integral of the point-load displacement :math:`\frac{2}{\pi E^*}\ln\frac{L}{|x-s|}` over
    the strip :math:`|s| \le b = dx/2` (plane strain; Eq. (2.25a) in [3]_ up to the datum):

    .. math:: K(x) = \frac{2}{\pi E^*}\left[2 b \ln L - F(x+b) + F(x-b)\right],
              \quad F(t) = t\ln|t| - t
    """
    b = 0.5 * width
    x = np.asanyarray(x, dtype=float)

    def antiderivative(t):
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t == 0.0, 0.0, t * np.log(np.abs(t))) - t

    return 2.0 / (np.pi * contact_modulus) * (
        2.0 * b * np.log(reference_distance) - antiderivative(x + b) + antiderivative(x - b))


def elastic_displacement(pressure, dx, contact_modulus, *, periodic=False, reference_distance=None):
    """Combined elastic surface displacement of a line-contact pressure.

    Parameters
    ----------
    pressure : array_like
        Element pressures [Pa] on a uniform grid.
    dx : float
        Element width [m].
    contact_modulus : float
        Contact modulus E* [Pa].
    periodic : bool, optional
        Periodic half-plane (zero mean displacement) or free boundary.
    reference_distance : float, optional
        Datum distance [m] of the free boundary (default n*dx).

    Returns
    -------
    numpy.ndarray
        Displacement u [m] (positive: the surfaces move apart).
    """
    pressure = np.asarray(pressure, dtype=float)
    n = pressure.size
    dx, modulus = float(dx), float(contact_modulus)
    reference = float(reference_distance) if reference_distance is not None else n * dx
    return _half_plane(n, dx, modulus, bool(periodic), reference).displacement(pressure)


def _check_problem(separation, dx, contact_modulus) -> np.ndarray:
    """The gap as a float array, checked with the element width and modulus (both solvers)."""
    h = np.asarray(separation, dtype=float)
    if h.ndim != 1 or h.size < 2:
        raise InputError(f"separation must be a 1-D array of at least 2 gap values [m], got shape {h.shape}")
    if not np.all(np.isfinite(h)):
        raise InputError("separation contains NaN or infinite values; fill or remove missing data first")
    for name, value in (("dx", dx), ("contact_modulus", contact_modulus)):
        if not np.isscalar(value) or not np.isfinite(value) or value <= 0:
            raise InputError(f"{name} must be a positive finite number, got {value!r}")
    return h


def _check_solver_options(tolerance, max_iterations, reference_distance) -> None:
    """Tolerance, iteration cap and datum, the same rules for the plain and the adhesive solver."""
    if not (0.0 < tolerance < 1.0):
        raise InputError(f"tolerance must lie in (0, 1), got {tolerance!r}")
    if max_iterations is not None and (int(max_iterations) != max_iterations or max_iterations < 1):
        raise InputError(f"max_iterations must be a positive integer, got {max_iterations!r}")
    if reference_distance is not None and (not np.isfinite(reference_distance) or reference_distance <= 0):
        raise InputError(f"reference_distance must be a positive length [m], got {reference_distance!r}")


def _check_inputs(separation, dx, contact_modulus, load, mean_pressure, tolerance, max_iterations,
                  reference_distance, initial_pressure):
    h = _check_problem(separation, dx, contact_modulus)
    if (load is None) == (mean_pressure is None):
        raise InputError("give exactly one of load [N/m] and mean_pressure [Pa]")
    name, value = ("load", load) if load is not None else ("mean_pressure", mean_pressure)
    if not np.isscalar(value) or not np.isfinite(value) or value <= 0:
        raise InputError(f"{name} must be a positive finite number (a compressive load), got {value!r}")
    _check_solver_options(tolerance, max_iterations, reference_distance)
    if initial_pressure is not None:
        p0 = np.asarray(initial_pressure, dtype=float)
        if p0.shape != h.shape or not np.all(np.isfinite(p0)) or np.any(p0 < 0):
            raise InputError("initial_pressure must be finite, >= 0 and of the same shape as separation")
    return h


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


def _operator_and_limits(n, dx, modulus, periodic, reference_distance, max_iterations):
    """(datum [m], CG iteration cap, half-plane operator, small problem?) of a solve on n elements."""
    reference = float(reference_distance) if reference_distance is not None else n * dx
    cap = int(max_iterations) if max_iterations is not None else max(1000, n // 4)
    # the small-problem measures (direct solves, cold start, short coarse levels) pay off up to
    # here; above, the coarse levels' guess matters more than their cost (2^18: 5-9 % slower)
    return reference, cap, _half_plane(n, dx, modulus, bool(periodic), reference), n <= _SMALL_PROBLEM


def _use_direct(operator, n_contact, small):
    return small and n_contact <= _DIRECT_MAX and operator.size <= _DENSE_GRID


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


def _active_set(operator, h, p, target, tolerance, cap, precondition, max_outer=None, small=True,
                settle_first=False):
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
    space = member = influence = inverse = None  # dense path: working set and its matrices
    for outer in range(1, (max_outer or _MAX_OUTER) + 1):
        n_contact = np.count_nonzero(contact)
        if n_contact == 0:
            return p, iterations, outer, False
        p_previous = p
        indices = np.flatnonzero(contact)
        # inexact inner solve: no tighter than needed to tell the next contact set
        inner_tolerance = max(0.5 * tolerance, _INNER_FACTOR * violation)
        p = _direct_solution(operator, h, indices, total) if _use_direct(operator, n_contact, small) else None
        exact = p is not None
        if exact:
            iterations += 1  # one direct solve counted as one iteration
        else:
            if n_contact <= _DENSE_MAX and (n_contact**2 <= 4 * operator.size
                                            or small and operator.size <= _DENSE_GRID):
                # small sets on a larger grid (a tooth contact) or small grids: dense products beat
                # full-grid FFTs. The matrices are built on a working set S that contains the contact
                # set (~n_S^2 operations) and reused while the contact set stays inside S; vectors on
                # S are zero outside the contact set (``mask``).
                if space is None or not member[indices].all():
                    grown = np.union1d(space, indices) if space is not None else indices
                    space = grown if grown.size <= _DENSE_MAX else indices
                    member = np.zeros(n, dtype=bool)
                    member[space] = True
                    offsets = operator.offsets(space)
                    influence = operator.matrix(space, operator.green_kernel, offsets)
                    inverse = operator.matrix(space, operator.stiffness_kernel, offsets) if precondition else None
                    del offsets
                mask = contact[space].astype(float) if space.size > n_contact else None
                apply = influence.__matmul__
                apply_inverse = inverse.__matmul__ if precondition else None
                p_c = p_previous[space]
                if mask is not None:
                    p_c *= mask
                p_c += (total - p_c.sum()) / n_contact * (mask if mask is not None else 1.0)
                r = h[space] + apply(p_c)
                packed = space
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
            if mask is not None:
                r *= mask
                r -= (r.sum() / n_contact) * mask
            else:
                r -= r.sum() / n_contact
            t = None
            G_old = 1.0
            for inner in range(cap):
                if max(r.max(), -r.min()) <= inner_tolerance or iterations >= cap:
                    break
                iterations += 1
                if precondition:
                    z = apply_inverse(r)
                    if mask is not None:
                        z *= mask
                        z -= (z.sum() / n_contact) * mask
                    else:
                        z -= z.sum() / n_contact
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
                if mask is not None:
                    q *= mask
                    q -= (q.sum() / n_contact) * mask
                else:
                    q -= q.sum() / n_contact
                if not _cg_update(p_c, r, t, q):
                    break
            p = np.zeros(n)
            p[packed] = p_c
        g = h + operator.displacement(p)
        gap = g - g[contact].sum() / n_contact
        new = (contact & (p > 0.0)) | (~contact & (gap < 0.0))
        negative = -p[contact].min() if n_contact else 0.0
        violation = max(np.abs(np.where(contact, gap, 0.0)).max(), np.maximum(-gap[~contact], 0.0).max(initial=0.0))
        if violation <= tolerance and negative < 0:  # complementarity holds, all p > 0
            return p, iterations, outer, True
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
                return clipped, iterations, outer, True
        if iterations >= cap:
            break
        contact = new
    return np.maximum(p, 0.0), iterations, outer, False


def _cold_start(h, target, small=True):
    """Initial pressure [Pa] without a guess: uniform on the lower part of the gap (``_START_FRACTION``)."""
    if _START_FRACTION >= 1.0 or not small:
        return np.full(h.size, target)
    k = int(_START_FRACTION * (h.size - 1))
    low = h <= np.partition(h, k)[k]
    return np.where(low, target * h.size / np.count_nonzero(low), 0.0)


def _nested_guess(h, dx, modulus, target, periodic, reference, cap, small=True):
    """Initial pressure from nested coarser grids (every other point), or (None, 0) if n is small or odd.

    Each level runs the active-set method to ``_COARSE_TOLERANCE`` from the level below; its
    result is only a guess, so a level that does not settle is used as it is (no fallback).
    Returns the guess on this grid [Pa] and the CG iterations spent.
    """
    n = h.size
    if n % 2 or n < 2 * _COARSEST:
        return None, 0
    coarse_h = h[::2] - h[::2].min()
    guess, iterations = _nested_guess(coarse_h, 2.0 * dx, modulus, target, periodic, reference, cap, small)
    if guess is None:
        guess = _cold_start(coarse_h, target, small)
    operator = _half_plane(coarse_h.size, 2.0 * dx, modulus, periodic, reference)
    # gap tolerance: the smaller of 1e-3 of the peak-to-valley and 1/10 of the rms step between
    # neighbours (on long domains the first alone is too loose to predict the contact set)
    scale = float(coarse_h.max()) if coarse_h.max() > 0 else 1.0
    local = float(np.std(np.diff(coarse_h))) or scale
    coarse_p, used, _, _ = _active_set(operator, coarse_h, guess * (target / guess.mean()), target,
                                       min(_COARSE_TOLERANCE * scale, _COARSE_STEP_FRACTION * local), cap, True,
                                       _COARSE_MAX_OUTER if small and operator.size <= _DENSE_GRID else None, small)
    fine = np.empty(n)
    fine[0::2] = coarse_p
    following = np.roll(coarse_p, -1) if periodic else np.append(coarse_p[1:], 0.0)
    fine[1::2] = 0.5 * (coarse_p + following)
    if small and _half_plane(n, dx, modulus, periodic, reference).size <= _DENSE_GRID:
        # the fine grid is solved directly (exact solves, fewer set updates from a set close to
        # the final one): in contact only between two coarse points in contact. (The CG levels
        # of larger grids converge faster from the wider set of plain interpolation.)
        fine[1::2] *= (coarse_p > 0) & (following > 0)
    return fine, iterations + used


@cites("polonsky_keer_1999", "vollebregt_2014", "johnson_1985", "model")
def solve_line_contact(separation, dx, contact_modulus, *, load=None, mean_pressure=None, periodic=False,
                       tolerance=1e-8, max_iterations=None, reference_distance=None, initial_pressure=None,
                       precondition=True, continuation=True, method="active-set", cohesive_stress=None,
                       cohesive_range=None, approach=None, capillary_stress=None, capillary_range=None):
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
        free-boundary grid of at most ``_DENSE_SOLVE_MAX`` (1024) elements, such as a meshing
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

    Returns
    -------
    ContactSolution
        Pressure, gap, contact set, approach, iterations, residual, converged flag, timing.
        Non-convergence is reported by ``converged=False`` and ``message``, never hidden.

    Notes
    -----
    Minimises the complementary energy :math:`\frac12 p^T A p + p^T h` subject to
    :math:`p \ge 0` and :math:`dx\sum p = w`. On a fixed contact set C the equations
    :math:`A_{CC} p_C - \delta = -h_C`, :math:`dx\sum p_C = w` are solved by a conjugate
    gradient preconditioned as in [2]_ with :math:`P_C\,\mathcal F^{-1}\frac{E^*|q|}{2}\mathcal F\,P_C`
    (P_C: restriction to C with the mean removed, so the load is kept); then C is updated
    (points with p < 0 leave, points that penetrate join: a primal-dual active-set step)
    until it no longer changes. The constrained CG of [1]_ is the fallback and the
    alternative. The convergence test is the same for both: the largest gap error on C or
    penetration outside it, relative to the peak-to-valley of h, at most ``tolerance``.

    **Adhesion** (Maugis-Dugdale, docs/contact.md "Adhesive contact"): the traction is -sigma0
    wherever the deformed gap lies in (0, h0], 0 beyond h0, and in contact (gap 0) the
    pressure is p >= -sigma0 ([4]_, [5]_). With the cohesive set S (contact plus cohesive zone)
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

    Examples
    --------
    >>> x = (np.arange(1024) - 511.5) * 1e-9
    >>> sol = solve_line_contact(x**2 / (2 * 20e-6), 1e-9, 100e9, load=1.0)
    >>> sol.converged, round(sol.contact_length * 1e9)
    (True, 32)
    """
    if capillary_stress is not None or capillary_range is not None:
        return _solve_capillary(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                                max_iterations, reference_distance, initial_pressure, precondition, continuation,
                                cohesive_stress, cohesive_range, capillary_stress, capillary_range)
    if cohesive_stress is not None or cohesive_range is not None or approach is not None:
        return _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                               max_iterations, reference_distance, initial_pressure, precondition, continuation,
                               cohesive_stress, cohesive_range)
    start = time.perf_counter()
    coarse_iterations = 0
    h = _check_inputs(separation, dx, contact_modulus, load, mean_pressure, tolerance, max_iterations,
                      reference_distance, initial_pressure)
    n = h.size
    if method == "active-set" and precondition and not periodic and n <= _DENSE_SOLVE_MAX:
        solution = _small_contact(h, float(dx), float(contact_modulus), load, mean_pressure, tolerance,
                                  reference_distance, initial_pressure, start)
        if solution is not None:
            return solution
    dx = float(dx)
    modulus = float(contact_modulus)
    target = float(mean_pressure) if mean_pressure is not None else float(load) / (n * dx)
    reference, cap, operator, small = _operator_and_limits(n, dx, modulus, periodic, reference_distance,
                                                          max_iterations)

    offset = float(h.min())
    h = h - offset
    # residual scale [m]: the peak-to-valley of the gap; for a flat gap the displacement scale w/E*
    scale = float(h.max()) if h.max() > 0 else target * n * dx / modulus
    if initial_pressure is None and continuation and precondition:
        initial_pressure, coarse_iterations = _nested_guess(h, dx, modulus, target, periodic, reference, cap, small)
    if initial_pressure is not None and np.sum(initial_pressure) > 0:
        p = np.asarray(initial_pressure, dtype=float) * (target / np.mean(initial_pressure))
    else:
        p = _cold_start(h, target, small)

    iteration = 0
    outer = 0
    method_used = "polonsky-keer"
    if method == "active-set":
        p, iteration, outer, settled = _active_set(operator, h, p, target, tolerance * scale, cap, precondition,
                                                   small=small)
        method_used = "active-set" if settled else "active-set, then polonsky-keer"
    p, g, contact, g_mean, residual, iteration = _polonsky_keer(operator, h, p, target, tolerance, scale, cap,
                                                                precondition, iteration)

    gap = np.where(contact, 0.0, g - g_mean)
    converged = residual <= tolerance
    n_contact = int(np.count_nonzero(contact))
    if converged:
        message = (f"{method_used}: converged in {iteration} iterations (residual {residual:.2e} <= tolerance "
                   f"{tolerance:.1e})")
    else:
        message = (f"{method_used}: NOT converged: residual {residual:.2e} > tolerance {tolerance:.1e} after {iteration} "
                   f"iterations (max_iterations={cap})")
    if coarse_iterations:
        message += f"; {coarse_iterations} more on the coarser nested grids"
    if n_contact < 3:
        message += f"; the contact is resolved by only {n_contact} element(s): refine the grid"
    if not periodic and (contact[0] or contact[-1]):
        message += "; the contact reaches the edge of the domain: enlarge it"
    return ContactSolution(pressure=p, gap=np.maximum(gap, 0.0) if converged else gap, contact=contact,
                           approach=float(g_mean) + offset, load=float(p.sum() * dx), iterations=iteration,
                           residual=float(residual), converged=bool(converged),
                           solve_time=time.perf_counter() - start, message=message, dx=dx,
                           periodic=bool(periodic), coarse_iterations=coarse_iterations)


# --------------------------------------------------------------------------- adhesion (Maugis-Dugdale)


def _check_adhesive_inputs(separation, dx, contact_modulus, load, mean_pressure, approach, tolerance, max_iterations,
                           reference_distance, initial_pressure, cohesive_stress, cohesive_range):
    h = _check_problem(separation, dx, contact_modulus)
    if (cohesive_stress is None) != (cohesive_range is None):
        raise InputError("give both cohesive_stress [Pa] and cohesive_range [m] (the Maugis-Dugdale sigma0 and h0), "
                         "or neither")
    for name, value in (("cohesive_stress", cohesive_stress), ("cohesive_range", cohesive_range)):
        if value is not None and (not np.isscalar(value) or not np.isfinite(value) or value < 0):
            unit = "Pa" if name == "cohesive_stress" else "m"
            raise InputError(f"{name} must be a finite number >= 0 [{unit}], got {value!r}")
    given = [(name, value) for name, value in (("load", load), ("mean_pressure", mean_pressure),
                                               ("approach", approach)) if value is not None]
    if len(given) != 1:
        raise InputError("give exactly one of load [N/m], mean_pressure [Pa] and approach [m]")
    name, value = given[0]
    if not np.isscalar(value) or not np.isfinite(value):
        raise InputError(f"{name} must be a finite number, got {value!r}")
    adhesive = bool(cohesive_stress) and bool(cohesive_range)
    if name != "approach" and value <= 0 and not adhesive:
        raise InputError(f"{name} must be positive (a compressive load) without adhesion, got {value!r}")
    _check_solver_options(tolerance, max_iterations, reference_distance)
    if initial_pressure is not None:
        p0 = np.asarray(initial_pressure, dtype=float)
        floor = -float(cohesive_stress or 0.0) * (1.0 + 1e-9)
        if p0.shape != h.shape or not np.all(np.isfinite(p0)) or np.any(p0 < floor):
            raise InputError("initial_pressure must be finite, >= -cohesive_stress and of the same shape as separation")
    return h


def _solve_on_set(operator, indices, rhs, tolerance, cap, factors=None, guess=None):
    """Pressure on the contact set ``indices`` with a prescribed displacement: A_CC p = rhs [m].

    Cholesky on sets up to ``_APPROACH_DIRECT_MAX`` elements (larger LAPACK factorisations may go
    threaded, which is slow on a busy machine; the factor of the last set is kept in the dict ``factors``:
    the cohesive-zone updates often keep the contact set), else the CG preconditioned with the
    Fourier-space inverse restricted to the set, from ``guess`` [Pa] (on the set), until the
    largest displacement residual is at most ``tolerance`` [m]. Returns the pressure [Pa] and
    the iterations.
    """
    if indices.size <= _APPROACH_DIRECT_MAX:
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


def _approach_contact(operator, h, delta, p_start, tolerance_abs, cap, factors=None):
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
    for outer in range(1, _ADHESIVE_MAX_OUTER + 1):
        indices = np.flatnonzero(contact)
        previous, p = p, np.zeros(h.size)
        if indices.size:
            p[indices], used = _solve_on_set(operator, indices, delta - h[indices], 0.1 * tolerance_abs, cap, factors,
                                             previous[indices])
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
                        fraction_tolerance, max_outer=_ADHESIVE_MAX_OUTER, zones=None, extrapolate=False):
    """Fixed point on the cohesive fraction: traction -sigma0*fraction, inner non-adhesive solve for p+.

    ``inner(h_eff, extra, guess, tol)`` solves the non-adhesive problem for p+ >= 0 with the gap h_eff
    and (load control) the extra compressive sum ``extra`` = sigma0 * sum(fraction) [Pa] to the
    relative tolerance ``tol`` (``_LOOSE_TOLERANCE`` while whole elements still change state,
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
        # inexact inner solves: a gap error of _GAP_FRACTION * change * h0 moves a front by a small
        # part of its last change (no looser than _LOOSE_TOLERANCE; the final solve at ``tolerance``)
        tol = min(max(tolerance, _GAP_FRACTION * change * h0 / scale), max(tolerance, _LOOSE_TOLERANCE))
        p_plus, gap, contact, approach, used, residual, ok, why = inner(h_eff, sigma0 * fraction.sum(), guess, tol)
        iterations += used
        state = (p_plus - sigma0 * fraction, gap, contact, fraction, approach, iterations, outer, residual)
        if not ok and (tol <= tolerance or not np.isfinite(residual)):
            return state + (False, why)
        new = _cohesive_fraction(gap, h0, contact, periodic, zones)
        step = np.abs(new - fraction)
        change = measured = step.max()
        # settled: no element's fraction moves by more than fraction_tolerance, or (many fronts,
        # a few of them creeping) the zone's load moves by less than _ZONE_LOAD_TOLERANCE of it
        # and no element by more than _ZONE_MAX_CHANGE
        zone = float(new[~contact].sum())
        if change <= fraction_tolerance or (change <= _ZONE_MAX_CHANGE
                                            and step.sum() <= _ZONE_LOAD_TOLERANCE * max(zone, 1.0)):
            if tol <= tolerance:
                return state + (True, "")
            change = 0.0  # settled on a loose solve: once more at the full tolerance
        if measured < best:
            best, stalled = measured, 0
            improving += 1
            if relax < 1.0 and improving >= _IMPROVING_UPDATES:  # converging again: less damping
                relax, improving = min(1.0, 2.0 * relax), 0
        else:
            improving = 0
            stalled += 1
            if stalled >= _STALLED_UPDATES and relax > _MIN_RELAXATION:
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
            ratio = min(_dot(d1, d0) / denominator, _AITKEN_MAX_RATIO) if denominator > 0 else 0.0
            # a creeping front (a smooth contact; rough contacts rarely), not while damped
            if ratio >= _AITKEN_MIN_RATIO and relax == 1.0:
                new = _cohesive_fraction(gap + d1 * (ratio / (1.0 - ratio)), h0, contact, periodic, zones)
        del gaps[:-3]
        if relax < 1.0:  # damped: part of the way, but every element in contact carries its full stress
            new = np.where(contact, new, fraction + relax * (new - fraction))
        # warm start of the next inner solve: p+ responds linearly to the fraction (for a fixed contact
        # set), so where the new change of the fraction repeats a multiple c of the last one (a
        # creeping front), p+ is expected to repeat c times its last change (c from a least-squares
        # fit, used in [0, 1])
        guess = p_plus
        if previous is not None and extrapolate and _LINEAR_RESPONSE_START:
            last = fraction - previous[0]
            norm = _dot(last, last)
            c = min(max(_dot(new - fraction, last) / norm, 0.0), 1.0) if norm > 0.0 else 0.0
            if c > 0.0:
                guess = np.maximum(p_plus + c * (p_plus - previous[1]), 0.0)
        previous = (fraction, p_plus)
        fraction = new
    return state + (False, f"the cohesive zone did not settle (last change of the cohesive fraction {change:.1e})")


def _adhesive_nested(h, dx, modulus, load, mean_pressure, periodic, reference, sigma0, h0, cap, precondition,
                     zones=None):
    """Initial p+ [Pa] and cohesive fraction from the adhesive problem on nested coarser grids (every other point).

    Each level is solved loosely (``_COARSE_TOLERANCE``, cohesive fraction to
    ``_COARSE_FRACTION_TOLERANCE``); a level that does not settle is still used (a guess).
    Returns (None, None, 0) where n is odd or below 2 x ``_COARSEST``.
    """
    n = h.size
    if n % 2 or n < 2 * _COARSEST or n // 2 > _LARGEST_ADHESIVE_LEVEL:
        return None, None, 0
    coarse_mean = None if mean_pressure is None else mean_pressure
    state = _solve_adhesive(h[::2], 2.0 * dx, modulus, load, coarse_mean, None, periodic, _COARSE_TOLERANCE, cap,
                            reference, None, precondition, True, sigma0, h0,
                            fraction_tolerance=_COARSE_FRACTION_TOLERANCE, internal=True,
                            zones=_coarse_zones(zones))
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
                     cohesive_stress, cohesive_range, capillary_stress, capillary_range):
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
            return solve_line_contact(separation, dx, contact_modulus, load=load, mean_pressure=mean_pressure,
                                      periodic=periodic, tolerance=tolerance, max_iterations=max_iterations,
                                      reference_distance=reference_distance, initial_pressure=initial_pressure,
                                      precondition=precondition, continuation=continuation)
        return _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                               max_iterations, reference_distance, initial_pressure, precondition, continuation,
                               cohesive_stress, cohesive_range)
    if (cohesive_stress is None) != (cohesive_range is None):
        raise InputError("give both cohesive_stress [Pa] and cohesive_range [m] (the Maugis-Dugdale sigma0 and h0), "
                         "or neither")
    vdw = bool(cohesive_stress) and bool(cohesive_range)
    zones = ((float(cohesive_stress), float(cohesive_range)),) if vdw else ()
    zones += ((sigma_c, reach),)
    stress = sum(sigma for sigma, _ in zones)
    reach_max = max(float(np.max(r)) for _, r in zones)
    solution = None
    if approach is None and not periodic and h.size <= _DENSE_SOLVE_MAX:  # small free-boundary grids: dense
        solution = _small_capillary(h, dx, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                                    reference_distance, initial_pressure, stress, reach_max, zones)
    if solution is None:
        solution = _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                                   max_iterations, reference_distance, initial_pressure, precondition, continuation,
                                   stress, reach_max, zones=None if len(zones) == 1 and np.ndim(reach) == 0 else zones,
                                   dense=False)
    contact, gap = solution.contact, solution.gap
    wetted = _dense_fraction(gap, ((1.0, reach),), contact, periodic)
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


#: Free-boundary grids up to this many elements solve under load control with dense matrices (plain, Maugis-Dugdale
#: and capillary problems): a meshing cycle's window (~100 elements, thousands of solves) is dominated by per-call
#: overhead of the FFT-based solver.
_DENSE_SOLVE_MAX = 1024


@functools.lru_cache(maxsize=8)
def _full_matrix(n, dx, contact_modulus, periodic, reference_distance):
    """The dense influence matrix [m/Pa] of the whole grid (small grids only), cached per grid."""
    operator = _half_plane(n, dx, contact_modulus, periodic, reference_distance)
    matrix = operator.matrix(np.arange(n), operator.green_kernel)
    matrix.setflags(write=False)
    return matrix


def _dense_fraction(gap, zones, contact, periodic):
    """:func:`_cohesive_fraction` with ``zones`` on a small grid (the same formula, less overhead).

    One zone of one range (the Maugis-Dugdale zone) is evaluated only where the gap can reach it
    (:func:`_sparse_fraction`).
    """
    if len(zones) == 1 and np.ndim(zones[0][1]) == 0:
        fraction = _sparse_fraction(gap, float(zones[0][0]), float(zones[0][1]), contact, periodic)
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


#: :func:`_sparse_fraction` evaluates the cohesive fraction element by element on at most this many elements
#: outside the contact set (more: the vectorised formula of :func:`_dense_fraction` is cheaper).
_SPARSE_FRACTION_MAX = 8


def _sparse_fraction(gap, sigma, reach, contact, periodic):
    """The cohesive fraction [-] of one zone (stress ``sigma`` [Pa], range ``reach`` [m]), or None.

    The formula of :func:`_dense_fraction`, element by element (the same floating-point operations) on the few
    elements outside the contact set that can carry a fraction: a half element does only where its lower end
    ``min(g_i, (g_i + g_j) / 2)`` is <= reach, which with every gap >= min(g) needs ``g_i <= 2 reach - min(g)``.
    None where more than ``_SPARSE_FRACTION_MAX`` elements qualify.
    """
    n = gap.size
    last = n - 1
    limit = 2.0 * reach - min(float(gap.min()), 0.0)
    fraction = contact.astype(float)
    candidates = ((gap <= limit + abs(limit) * 1e-9) & ~contact).nonzero()[0]
    if candidates.size > _SPARSE_FRACTION_MAX:
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


def _dense_contact(matrix, h, total, contact, tolerance_abs):
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
    for updates in range(1, _MAX_OUTER + 1):
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


def _small_contact(h, dx, modulus, load, mean_pressure, tolerance, reference_distance, initial_pressure, start):
    """The non-adhesive free-boundary solve on a small grid by :func:`_dense_contact`, or None (general solver)."""
    n = h.size
    reference = float(reference_distance) if reference_distance is not None else n * dx
    offset = float(h.min())
    h = h - offset
    total = float(load) / dx if load is not None else float(mean_pressure) * n
    scale = float(h.max()) if h.max() > 0 else total * dx / modulus
    contact = (np.asarray(initial_pressure) > 0.0 if initial_pressure is not None
               else np.zeros(n, dtype=bool))
    state = _dense_contact(_full_matrix(n, dx, modulus, False, reference), h, total, contact, tolerance * scale)
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


@cites("maugis_1992", "rey_2017", "bazrafshan_2017", "model")  # the fixed point of _cohesive_iteration
def _dense_capillary(h, dx, modulus, total, periodic, reference, zones, p_start, tolerance):
    """The capillary (and vdW) zone problem on a small grid under load control, by dense matrices.

    The same fixed point on the cohesive fraction as :func:`_cohesive_iteration` (traction
    -sigma f, the non-adhesive problem for p+ with the gap h - sigma A f and the sum
    total + sigma sum(f); settled when no fraction moves by more than ``_FRACTION_TOLERANCE``, or
    the zone's load by less than ``_ZONE_LOAD_TOLERANCE`` with no fraction moving by more than
    ``_ZONE_MAX_CHANGE``; Aitken extrapolation of creeping fronts every third update), each
    inner problem solved exactly (Cholesky on the contact set, primal-dual active set as
    :func:`_dense_contact`). The loop is compiled (:func:`memstribo.physics._zone_kernel.zone_solve`):
    a meshing cycle makes ~10^4 of these solves of ~20 updates each. ``h`` has its minimum at 0.
    Returns (p, gap, contact, fraction, delta, updates) or None where it cannot (the general solver then runs).
    """
    from memstribo.physics._zone_kernel import SETTLED, zone_solve  # numba: imported on first use

    n = h.size
    matrix = _full_matrix(n, dx, modulus, periodic, reference)
    sigmas = np.array([float(s) for s, _ in zones])
    reaches = np.empty((len(zones), n))
    per_element = np.zeros(len(zones), dtype=bool)
    for k, (_, reach) in enumerate(zones):
        reaches[k] = reach
        per_element[k] = np.ndim(reach) > 0
    sigma = float(sigmas.sum())
    top = float(h.max())
    scale = top if top > 0 else max(abs(total) * dx / modulus, max(float(np.max(r)) for _, r in zones))
    if p_start is not None:  # min(clip(-p/sigma, 0, 1) + (p > 0), 1)
        contact = p_start > 0.0
        fraction = np.minimum(np.maximum(-p_start / sigma, 0.0), 1.0)
        fraction[contact] = 1.0
    else:
        fraction = np.zeros(n)
        contact = np.zeros(n, dtype=bool)
    status, p, gap, delta, updates = zone_solve(
        matrix, np.ascontiguousarray(h, dtype=float), float(total), sigmas, reaches, per_element, bool(periodic),
        fraction, contact, tolerance * scale, _ADHESIVE_MAX_OUTER, _MAX_OUTER, _FRACTION_TOLERANCE,
        _ZONE_LOAD_TOLERANCE, _ZONE_MAX_CHANGE, _AITKEN_MIN_RATIO, _AITKEN_MAX_RATIO)
    if status != SETTLED:
        return None
    return p, gap, contact, fraction, delta, updates


def _small_capillary(separation, dx, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                     reference_distance, initial_pressure, stress, reach, zones, kind="capillary (dense)",
                     checked=False):
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
    state = _dense_capillary(h, dx, modulus, total, bool(periodic), reference, zones, p_start, tolerance)
    if state is None:
        return None
    p, gap, contact, fraction, delta, outer = state
    top = float(h.max())
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


def _solve_adhesive(separation, dx, contact_modulus, load, mean_pressure, approach, periodic, tolerance,
                    max_iterations, reference_distance, initial_pressure, precondition, continuation,
                    cohesive_stress, cohesive_range, fraction_tolerance=None, internal=False, zones=None, dense=True):
    """:func:`solve_line_contact` with a Maugis-Dugdale zone and/or under approach control.

    ``internal``: return (p+, cohesive fraction, CG iterations) for the nested levels instead.
    ``dense``: small free-boundary grids under load control first try the dense-matrix solve
    (:func:`_small_capillary` with the one zone); False skips it (its caller already tried).
    ``zones``: a traction of several step functions (:func:`_cohesive_fraction`); ``cohesive_stress``
    is then their summed stress and ``cohesive_range`` their largest range (:func:`_solve_capillary`).
    """
    start = time.perf_counter()
    fraction_tolerance = _FRACTION_TOLERANCE if fraction_tolerance is None else fraction_tolerance
    h = _check_adhesive_inputs(separation, dx, contact_modulus, load, mean_pressure, approach, tolerance,
                               max_iterations, reference_distance, initial_pressure, cohesive_stress, cohesive_range)
    n = h.size
    dx = float(dx)
    modulus = float(contact_modulus)
    sigma0 = float(cohesive_stress or 0.0)
    h0 = float(cohesive_range or 0.0)
    if sigma0 == 0.0 or h0 == 0.0:
        sigma0 = h0 = 0.0
    if dense and not sigma0 and approach is None and not periodic and not internal and n <= _DENSE_SOLVE_MAX:
        solution = _small_contact(h, dx, modulus, load, mean_pressure, tolerance, reference_distance, initial_pressure,
                                  start)  # no zone: the plain small-grid solve, as solve_line_contact without one
        if solution is not None:
            return dataclasses.replace(solution, adhesive_load=0.0, cohesive=np.zeros(n, dtype=bool))
    if dense and sigma0 and approach is None and not periodic and not internal and zones is None and n <= _DENSE_SOLVE_MAX:
        solution = _small_capillary(h, dx, modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                                    reference_distance, initial_pressure, sigma0, h0, ((sigma0, h0),),
                                    kind=f"adhesive (Maugis-Dugdale, sigma0 = {sigma0:.4g} Pa, h0 = {h0:.4g} m)",
                                    checked=True)
        if solution is not None:
            return solution
    reference, cap, operator, small = _operator_and_limits(n, dx, modulus, periodic, reference_distance,
                                                          max_iterations)
    offset = float(h.min())
    h = h - offset
    p_start = np.asarray(initial_pressure, dtype=float) if initial_pressure is not None else None
    coarse = [0]
    if approach is not None:
        delta = float(approach) - offset
        scale = float(h.max()) if h.max() > 0 else max(abs(delta), h0, dx)
        control = "approach control"

        factors = {}

        def inner(h_eff, extra, guess, tol):
            p, g, contact, used, outer, settled = _approach_contact(operator, h_eff, delta, guess, tol * scale, cap,
                                                                    factors)
            # gap error on the contact set, penetration outside it
            residual = max(np.abs(g[contact]).max(initial=0.0), np.maximum(-g[~contact], 0.0).max(initial=0.0)) / scale
            return p, g, contact, delta, used, residual, settled, "the contact set did not settle (it cycles)"

        if sigma0:
            fraction = (np.clip(-p_start / sigma0, 0.0, 1.0) + (p_start > 0.0) if p_start is not None
                        else _cohesive_fraction(h - delta, h0, h - delta <= 0.0, periodic, zones))
            fraction = np.minimum(fraction, 1.0)
    else:
        total = float(load) / dx if load is not None else float(mean_pressure) * n
        scale = float(h.max()) if h.max() > 0 else max(abs(total) * dx / modulus, h0)
        control = "load control"

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
                    guess, used = _nested_guess(h_eff, dx, modulus, target, periodic, reference, cap, small)
                    coarse[0] += used
                if guess is None:
                    guess = _cold_start(h_eff, target, small)
            p = guess * (target / guess.mean())
            p, used, _, _ = _active_set(operator, h_eff, p, target, tol * scale, cap, precondition, small=small,
                                        settle_first=warm and _SETTLE_FIRST)
            p, g, contact, g_mean, residual, used = _polonsky_keer(operator, h_eff, p, target, tol, scale, cap,
                                                                   precondition, used)
            return p, g - g_mean, contact, float(g_mean) + shift, used, residual, residual <= tol, ""

        nested_guess = None
        if sigma0 and p_start is None and continuation and precondition:
            nested_guess, nested_fraction, used = _adhesive_nested(h + offset, dx, modulus, load, mean_pressure,
                                                                   periodic, reference, sigma0, h0, cap, precondition,
                                                                   zones)
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
    if sigma0:
        guess = np.maximum(p_start + sigma0 * fraction, 0.0) if p_start is not None else None
        if approach is None and nested_guess is not None:
            guess = nested_guess
        (p, gap, contact, fraction, approach_out, iterations, outer, residual, settled,
         why) = _cohesive_iteration(operator, h, sigma0, h0, fraction, guess, inner, periodic, tolerance, scale,
                                    fraction_tolerance,
                                    _COARSE_MAX_UPDATES if internal
                                    else _SMALL_ZONE_MAX_UPDATES if n <= _SMALL_ZONE else _ADHESIVE_MAX_OUTER,
                                    zones, extrapolate=approach is None)
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
    kind = f"adhesive (Maugis-Dugdale, sigma0 = {sigma0:.4g} Pa, h0 = {h0:.4g} m)" if sigma0 else "non-adhesive"
    if converged:
        message = (f"{kind}, {control}: converged after {outer} cohesive-zone update(s), {iterations} iterations "
                   f"(residual {residual:.2e} <= tolerance {tolerance:.1e})")
    else:
        message = (f"{kind}, {control}: NOT converged after {outer} cohesive-zone update(s), {iterations} iterations: "
                   f"{why or f'residual {residual:.2e} > tolerance {tolerance:.1e}'} (max_iterations={cap})")
    if coarse[0]:
        message += f"; {coarse[0]} more on the coarser nested grids"
    n_contact = int(np.count_nonzero(contact))
    if 0 < n_contact < 3:
        message += f"; the contact is resolved by only {n_contact} element(s): refine the grid"
    if not periodic and (contact[0] or contact[-1] or cohesive[0] or cohesive[-1]):
        message += "; the contact or cohesive zone reaches the edge of the domain: enlarge it"
    return ContactSolution(pressure=p, gap=np.maximum(gap, 0.0) if converged else gap, contact=contact,
                           approach=float(approach_out) + offset, load=float(p.sum() * dx), iterations=iterations,
                           residual=float(residual), converged=converged, solve_time=time.perf_counter() - start,
                           message=message, dx=dx, periodic=bool(periodic), coarse_iterations=coarse[0],
                           adhesive_load=adhesive_load, cohesive=cohesive)


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
