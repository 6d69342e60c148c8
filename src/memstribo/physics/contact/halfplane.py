"""The plane-strain half-plane operator: strip influence coefficients, FFT products, the solution records.

The discrete operator u = A p of uniformly loaded strips on a free (Johnson 1985, Eq. 2.25a) or periodic
half-plane, its Fourier-space preconditioner, the CG step shared with the surface solver, and the
records every solve returns (:class:`ContactSolve`, :class:`ContactSolution`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
import scipy.fft

import memstribo.physics.contact.settings as _settings
from memstribo.references import cites


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
    workers : int
        Threads scipy.fft may use (:attr:`SolverSettings.fft_workers`).
    """

    def __init__(self, n, dx, contact_modulus, periodic, reference_distance, workers=1):
        self.n, self.dx, self.periodic = n, dx, periodic
        self.workers = workers
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
            self.green = scipy.fft.rfft(kernel, workers=self.workers)
            q = 2.0 * np.pi * np.abs(scipy.fft.rfftfreq(self.size, d=dx))
            stiffness = 0.5 * contact_modulus * q
        self.stiffness = stiffness

    def _apply(self, values, symbol):
        if self.periodic:
            return scipy.fft.irfft(scipy.fft.rfft(values, workers=self.workers) * symbol, n=self.n,
                                   workers=self.workers)
        spectrum = scipy.fft.rfft(values, n=self.size, workers=self.workers)
        return scipy.fft.irfft(spectrum * symbol, n=self.size, workers=self.workers)[: self.n]

    def restricted(self, values, indices, symbol):
        """Apply a Fourier ``symbol`` to ``values`` given on the elements ``indices`` only; gather there."""
        full = np.zeros(self.size)
        full[indices] = values
        spectrum = scipy.fft.rfft(full, workers=self.workers)
        spectrum *= symbol
        return scipy.fft.irfft(spectrum, n=self.size, workers=self.workers)[indices]

    @functools.cached_property
    def green_kernel(self):
        """The operator in real space: displacement [m/Pa] at element offset k (modulo the FFT size)."""
        return scipy.fft.irfft(self.green, n=self.size, workers=self.workers)

    @functools.cached_property
    def stiffness_kernel(self):
        """The preconditioner in real space [Pa/m], indexed like :attr:`green_kernel`."""
        return scipy.fft.irfft(self.stiffness, n=self.size, workers=self.workers)

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
def _half_plane(n, dx, contact_modulus, periodic, reference_distance, workers=1):
    return HalfPlane(n, dx, contact_modulus, periodic, reference_distance, workers)


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


def elastic_displacement(pressure, dx, contact_modulus, *, periodic=False, reference_distance=None, settings=None):
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
    settings : SolverSettings, optional
        Solver tuning (only ``fft_workers`` is used here); None: :data:`memstribo.physics.contact.settings.DEFAULTS`.

    Returns
    -------
    numpy.ndarray
        Displacement u [m] (positive: the surfaces move apart).
    """
    pressure = np.asarray(pressure, dtype=float)
    n = pressure.size
    dx, modulus = float(dx), float(contact_modulus)
    reference = float(reference_distance) if reference_distance is not None else n * dx
    workers = _settings.resolve(settings).fft_workers
    return _half_plane(n, dx, modulus, bool(periodic), reference, workers).displacement(pressure)


@functools.lru_cache(maxsize=8)
def _full_matrix(n, dx, contact_modulus, periodic, reference_distance):
    """The dense influence matrix [m/Pa] of the whole grid (small grids only), cached per grid."""
    operator = _half_plane(n, dx, contact_modulus, periodic, reference_distance)
    matrix = operator.matrix(np.arange(n), operator.green_kernel)
    matrix.setflags(write=False)
    return matrix
