"""Rough surface (3D) contact: elastic half-space boundary elements, 2D FFT, constrained conjugate gradient.

The normal, frictionless, non-adhesive contact of two elastic bodies with a rough gap is
solved on the elastic half-space: the combined undeformed gap ``separation`` h(x, y) [m] is
given at the centres of a uniform (ny, nx) grid of rectangular elements of size dx by dy [m]
carrying piecewise-constant pressures; the unknown is the pressure p >= 0 [Pa] with

    g(x, y) = h + u - approach >= 0,     p g = 0,     dx dy sum(p) = load,

where u is the combined elastic surface displacement (positive: the surfaces move apart) and
``approach`` [m] the rigid-body approach. Arrays are indexed ``[iy, ix]`` (rows are lines
along x), as :class:`memstribo.surfaces.readers.SurfaceMap` stores heights.

``periodic=False`` (free boundary)
    Influence coefficients of uniformly loaded rectangles (Love 1929; Johnson 1985, §3.2,
    Eq. (3.25)), applied by a linear (zero-padded to 2n per axis) 2D FFT convolution
    (Stanley & Kato 1997 for the FFT evaluation; here the exact non-periodic convolution, no
    wrap-around error). The displacement vanishes far away (the half-space datum).
``periodic=True``
    The spectral Green's function u_q = 2 p_q / (E* |q|) at the grid wavenumbers with a
    zero mean displacement (the convention of ContactMechanics and Tamaas, so the same
    discrete problem is solved; Stanley & Kato 1997).

The solver (load control) is the one of :mod:`memstribo.physics.contact`, in 2D: a primal-dual
active-set iteration whose contact-set problems are solved by a conjugate gradient
preconditioned in Fourier space with the inverse of the half-space operator (E*|q|/2,
restricted to the set; Vollebregt 2014), started from nested coarser grids (every other
point in x and y, each solved loosely); Polonsky & Keer's (1999) constrained conjugate
gradient (preconditioned) is the fallback. Real 2D FFTs (scipy.fft, ``workers=1``), kernels
cached per grid, float64 throughout.

Plastic flow (``hardness``): the pressure is capped at the hardness H of the softer body, the
elastic-perfectly-plastic surface model of the line solve
(:func:`memstribo.physics.contact.solve_line_contact_capped`, MODEL 7d) and of the peer BEM codes
(ContactMechanics' ``constrained_conjugate_gradients(..., hardness=H)``, whose CG leaves out the
elements at H and truncates the pressure there, with its ``PlasticNonSmoothContactSystem``; Tamaas'
``KatoSaturated`` solver with its saturation pressure ``pmax``; Almqvist et al. 2007):
0 <= p <= H, g = 0 where 0 < p < H, g <= 0 where p = H (the interpenetration is the plastic
flattening), g >= 0 where p = 0, dx dy sum(p) = W; solved, as in the line solve, by an active set on
the plastic elements around the elastic solver (:func:`_solve_capped`).

Adhesion hook: the solver is written for the non-adhesive complementarity conditions; the
keyword ``interaction`` of :func:`solve_surface_contact` is reserved for a cohesive-zone law
(Maugis-Dugdale: a constant tensile traction where 0 < g < range), which would enter as an
extra gap-dependent traction in :func:`_active_set` (the pressure bound p >= 0 becomes
p >= -sigma_0 on the cohesive zone). Giving it now raises :class:`InputError`.

References
----------
.. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985, §3.2 (Love's
   uniformly loaded rectangle).
.. [2] I. A. Polonsky, L. M. Keer, Wear 231 (1999) 206-219. :doi:`10.1016/S0043-1648(99)00113-1`
.. [3] H. M. Stanley, T. Kato, 'An FFT-based method for rough surface contact', J. Tribol.
   119 (1997) 481-485. :doi:`10.1115/1.2833523`
.. [4] E. A. H. Vollebregt, J. Comput. Phys. 257 (2014) 333-351. :doi:`10.1016/j.jcp.2013.10.005`
.. [5] A. Almqvist, F. Sahlin, R. Larsson, S. Glavatskih, Tribol. Int. 40 (2007) 574-579
   (elastic-perfectly-plastic contact of rough surfaces, the pressure capped at the hardness).
.. [6] L. Frérot, G. Anciaux, V. Rey, S. Pham-Ba, J.-F. Molinari, 'Tamaas: a library for elastic-plastic contact
   of periodic rough surfaces', J. Open Source Softw. 5 (2020) 2121 (``KatoSaturated``).
"""

from __future__ import annotations

import dataclasses
import functools
import time
from dataclasses import dataclass

import numpy as np
import scipy.fft

from memstribo.errors import InputError
from memstribo.physics.contact.halfplane import ContactSolve, _cg_update
from memstribo.physics.contact.settings import DEFAULTS as _LINE_DEFAULTS
from memstribo.references import cites

__all__ = ["SurfaceContactSolution", "solve_surface_contact", "surface_displacement", "rectangle_influence",
           "HalfSpace", "complementarity_residual"]

#: Threads scipy.fft may use (1: serial; the benchmark compares on one core).
FFT_WORKERS = 1
#: Nested grids stop coarsening below this many elements along the shorter axis.
_COARSEST = 64
#: Gap tolerance of the coarse levels, relative to the peak-to-valley of h ...
_COARSE_TOLERANCE = 1e-3
#: ... and at most this fraction of the rms height step between neighbouring points.
_COARSE_STEP_FRACTION = 0.1
#: Contact-set updates on the coarse levels (only a guess is needed there).
_COARSE_MAX_OUTER = 8
#: Contact-set updates on the fine grid before the Polonsky-Keer fallback takes over.
_MAX_OUTER = 40
_INNER_FACTOR = _LINE_DEFAULTS.inner_factor  # the line contact's inner CG tolerance, for the same reason


@dataclass(frozen=True)
class SurfaceContactSolution(ContactSolve):
    """Solution of a rough surface contact.

    Attributes
    ----------
    pressure : numpy.ndarray
        Contact pressure [Pa] of each element, >= 0; shape (ny, nx).
    gap : numpy.ndarray
        Deformed gap [m], >= 0 when converged (zero on the contact set), shape (ny, nx).
    contact : numpy.ndarray
        True where an element is in contact (pressure > 0); shape (ny, nx).
    converged : bool
        True when the residual met the tolerance within the iteration cap.
    solve_time : float
        Wall time of this solve [s].
    message : str
        What happened, in words.
    periodic : bool
        True for the periodic half-space.
    coarse_iterations : int
        CG iterations on the nested coarser grids (not in ``iterations``).
    approach : float
        Rigid-body approach [m] (free boundary: relative to the undisplaced far field;
        periodic: relative to a zero mean elastic displacement), for the separation as given.
    load : float
        Normal force carried, dx dy sum(pressure) [N].
    iterations : int
        Conjugate-gradient iterations on the full grid.
    residual : float
        The largest gap error on the contact set or penetration outside it over the
        peak-to-valley of the separation [-].
    dx, dy : float
        Element sizes along x and y [m].
    plastic : numpy.ndarray or None
        Where a ``hardness`` was given: True where an element is in plastic flow (pressure at the hardness),
        shape (ny, nx); None without a hardness.
    plastic_updates : int
        Updates of the plastic set (0 where no element reached the hardness).
    """

    dx: float
    dy: float
    periodic: bool
    coarse_iterations: int = 0
    plastic: np.ndarray | None = None
    plastic_updates: int = 0

    @property
    def plastic_fraction(self) -> float:
        """Share of the elements in contact that are at the hardness [-] (0 without a hardness or contact)."""
        n_contact = int(np.count_nonzero(self.contact))
        if self.plastic is None or n_contact == 0:
            return 0.0
        return float(np.count_nonzero(self.plastic) / n_contact)

    @property
    def contact_fraction(self) -> float:
        """Fraction of the elements in contact, A/A0 [-]."""
        return float(np.count_nonzero(self.contact) / self.contact.size)

    @property
    def contact_area(self) -> float:
        """True contact area, dx dy times the number of elements in contact [m^2]."""
        return float(np.count_nonzero(self.contact) * self.dx * self.dy)

    @property
    def max_pressure(self) -> float:
        """Largest element pressure [Pa]."""
        return float(self.pressure.max())

    @property
    def mean_gap(self) -> float:
        """Mean deformed gap over the whole grid [m]."""
        return float(self.gap.mean())

    def to_xarray(self):
        """The fields as an :class:`xarray.Dataset` (dims y, x; coordinates in m; units attrs)."""
        import xarray as xr

        ny, nx = self.pressure.shape
        coords = {"y": ("y", np.arange(ny) * self.dy, {"units": "m", "long_name": "position along y"}),
                  "x": ("x", np.arange(nx) * self.dx, {"units": "m", "long_name": "position along x"})}
        data = {
            "pressure": (("y", "x"), self.pressure, {"units": "Pa", "long_name": "contact pressure"}),
            "gap": (("y", "x"), self.gap, {"units": "m", "long_name": "deformed gap"}),
            "contact": (("y", "x"), self.contact.astype(np.int8),
                        {"units": "1", "long_name": "in contact (1) or not (0)"}),
        }
        if self.plastic is not None:
            data["plastic"] = (("y", "x"), self.plastic.astype(np.int8),
                               {"units": "1", "long_name": "at the hardness, plastic flow (1) or not (0)"})
        attrs = {"approach": self.approach, "approach_units": "m", "load": self.load, "load_units": "N",
                 "contact_fraction": self.contact_fraction, "iterations": self.iterations,
                 "residual": self.residual, "converged": int(self.converged), "periodic": int(self.periodic),
                 "message": self.message, "solver": "memstribo.physics.surface_contact.solve_surface_contact",
                 "plastic_fraction": self.plastic_fraction}
        return xr.Dataset(data, coords=coords, attrs=attrs)


@cites("johnson_1985")
def rectangle_influence(x, y, a, b, contact_modulus):
    r"""Surface displacement of a half-space under a uniformly loaded rectangle of unit pressure.

    Parameters
    ----------
    x, y : numeric
        Position of the field point relative to the rectangle centre [m].
    a, b : float
        Half-sizes of the rectangle along x and y [m] (dx/2, dy/2).
    contact_modulus : float
        Contact modulus E* [Pa] (combined: 1/E* = (1-nu1²)/E1 + (1-nu2²)/E2).

    Returns
    -------
    numeric
        Displacement [m] at each point per unit pressure [Pa] on the rectangle.

    Notes
    -----
    Love's solution (Johnson 1985, §3.2, Eq. (3.25)), written with
    :math:`F(X, Y) = X\,\mathrm{asinh}(Y/|X|) + Y\,\mathrm{asinh}(X/|Y|)`, an antiderivative of
    :math:`1/\sqrt{X^2+Y^2}` in X and Y:

    .. math:: u = \frac{1}{\pi E^*}\left[F(x+a, y+b) - F(x-a, y+b) - F(x+a, y-b) + F(x-a, y-b)\right]
    """
    x = np.asanyarray(x, dtype=float)
    y = np.asanyarray(y, dtype=float)

    def antiderivative(X, Y):
        with np.errstate(divide="ignore", invalid="ignore"):
            first = np.where(X == 0.0, 0.0, X * np.arcsinh(Y / np.abs(X)))
            second = np.where(Y == 0.0, 0.0, Y * np.arcsinh(X / np.abs(Y)))
        return first + second

    return (antiderivative(x + a, y + b) - antiderivative(x - a, y + b) - antiderivative(x + a, y - b)
            + antiderivative(x - a, y - b)) / (np.pi * contact_modulus)


class HalfSpace:
    """The discrete half-space operator u = A p and its Fourier-space preconditioner.

    Built once per (ny, nx, dx, dy, contact_modulus, periodic) and cached.

    Parameters
    ----------
    shape : tuple of int
        Grid shape (ny, nx).
    dx, dy : float
        Element sizes [m].
    contact_modulus : float
        Contact modulus E* [Pa].
    periodic : bool
        Periodic half-space (spectral Green's function, zero mean displacement) or free
        boundary (zero-padded convolution of Love's rectangle coefficients).
    """

    def __init__(self, shape, dx, dy, contact_modulus, periodic):
        ny, nx = shape
        self.shape, self.dx, self.dy, self.periodic = (ny, nx), dx, dy, periodic
        self.modulus = contact_modulus
        if periodic:
            self.fft_shape = (ny, nx)
        else:
            self.fft_shape = (scipy.fft.next_fast_len(2 * ny, real=True), scipy.fft.next_fast_len(2 * nx, real=True))
        my, mx = self.fft_shape
        qy = 2.0 * np.pi * scipy.fft.fftfreq(my, d=dy)
        qx = 2.0 * np.pi * scipy.fft.rfftfreq(mx, d=dx)
        q = np.sqrt(qy[:, None] ** 2 + qx[None, :] ** 2)
        self.stiffness = 0.5 * contact_modulus * q
        if periodic:
            green = np.zeros_like(q)
            green[q > 0] = 2.0 / (contact_modulus * q[q > 0])
            self.green = green
        else:
            # Love's coefficients at the offsets 0..n-1 (they are even in x and y), mirrored into
            # the wrapped layout of the padded grid; the offsets in between never reach a
            # collocation point and stay zero
            quarter = rectangle_influence(np.arange(nx)[None, :] * dx, np.arange(ny)[:, None] * dy, 0.5 * dx,
                                          0.5 * dy, contact_modulus)
            kernel = np.zeros((my, mx))
            kernel[:ny, :nx] = quarter
            kernel[my - ny + 1:, :nx] = quarter[:0:-1]
            kernel[:, mx - nx + 1:] = kernel[:, nx - 1:0:-1]
            self.green = scipy.fft.rfft2(kernel, workers=FFT_WORKERS)
        self.green.flags.writeable = False
        self.stiffness.flags.writeable = False

    def _apply(self, values, symbol):
        if self.periodic:
            # one axis at a time: scipy's irfft2 took ~1.5x as long as ifft along y followed by
            # irfft along x (pocketfft, one thread, 512^2-2048^2)
            spectrum = scipy.fft.rfft(values, axis=1, workers=FFT_WORKERS)
            spectrum = scipy.fft.fft(spectrum, axis=0, workers=FFT_WORKERS, overwrite_x=True)
            spectrum *= symbol
            spectrum = scipy.fft.ifft(spectrum, axis=0, workers=FFT_WORKERS, overwrite_x=True)
            return scipy.fft.irfft(spectrum, n=self.shape[1], axis=1, workers=FFT_WORKERS, overwrite_x=True)
        # zero-padded convolution, pruned: the padding rows are zero before the transform along
        # x, and only the first ny rows are needed after the inverse transform along y
        ny, nx = self.shape
        my, mx = self.fft_shape
        spectrum = scipy.fft.rfft(values, n=mx, axis=1, workers=FFT_WORKERS)
        spectrum = scipy.fft.fft(spectrum, n=my, axis=0, workers=FFT_WORKERS, overwrite_x=True)
        spectrum *= symbol
        spectrum = scipy.fft.ifft(spectrum, axis=0, workers=FFT_WORKERS, overwrite_x=True)[:ny]
        return scipy.fft.irfft(spectrum, n=mx, axis=1, workers=FFT_WORKERS)[:, :nx]

    def displacement(self, pressure):
        """Combined elastic surface displacement [m] of an element pressure field [Pa]."""
        return self._apply(pressure, self.green)

    def precondition(self, gap_residual):
        """Approximate inverse: a pressure [Pa] that would produce ``gap_residual`` [m]."""
        return self._apply(gap_residual, self.stiffness)


@functools.lru_cache(maxsize=8)
def _half_space(shape, dx, dy, contact_modulus, periodic):
    return HalfSpace(shape, dx, dy, contact_modulus, periodic)


def surface_displacement(pressure, dx, dy, contact_modulus, *, periodic=False):
    """Combined elastic surface displacement of a piecewise-constant pressure field.

    Parameters
    ----------
    pressure : array_like
        Element pressures [Pa], shape (ny, nx).
    dx, dy : float
        Element sizes along x and y [m].
    contact_modulus : float
        Contact modulus E* [Pa].
    periodic : bool, optional
        Periodic half-space (zero mean displacement) or free boundary.

    Returns
    -------
    numpy.ndarray
        Displacement u [m] at the element centres (positive: the surfaces move apart).
    """
    pressure = np.asarray(pressure, dtype=float)
    if pressure.ndim != 2:
        raise InputError(f"pressure must be a 2-D array (ny, nx) [Pa], got shape {pressure.shape}")
    return _half_space(pressure.shape, float(dx), float(dy), float(contact_modulus), bool(periodic)).displacement(
        pressure)


def complementarity_residual(separation, pressure, dx, dy, contact_modulus, *, periodic=False):
    """The dimensionless complementarity (KKT) residual of a pressure field.

    Parameters
    ----------
    separation : array_like
        Undeformed gap h [m], shape (ny, nx).
    pressure : array_like
        Pressure [Pa], same shape, >= 0.
    dx, dy : float
        Element sizes [m].
    contact_modulus : float
        Contact modulus E* [Pa].
    periodic : bool, optional
        Periodic or free-boundary half-space.

    Returns
    -------
    float
        max(|g - mean_C g| on C, penetration outside C) / ptp(h), C = {p > 0}.
    """
    h = np.asarray(separation, dtype=float)
    p = np.asarray(pressure, dtype=float)
    g = h + surface_displacement(p, dx, dy, contact_modulus, periodic=periodic)
    contact = p > 0
    if not contact.any():
        return float("inf")
    approach = g[contact].mean()
    gap = g - approach
    error = max(np.abs(gap[contact]).max(), np.maximum(-gap[~contact], 0.0).max(initial=0.0))
    return float(error / np.ptp(h)) if np.ptp(h) > 0 else float(error)


def _dot(a, b):
    # einsum, not BLAS: a threaded ddot on a busy machine costs tens of ms per call at 512^2
    return float(np.einsum("ij,ij->", a, b))


def _check_inputs(separation, dx, dy, contact_modulus, load, mean_pressure, tolerance, max_iterations,
                  initial_pressure, interaction, hardness=None):
    h = np.asarray(separation, dtype=float)
    if h.ndim != 2 or min(h.shape) < 2:
        raise InputError(f"separation must be a 2-D array (ny, nx) of gap values [m] with ny, nx >= 2, got shape "
                         f"{h.shape}")
    if not np.all(np.isfinite(h)):
        raise InputError("separation contains NaN or infinite values [m]; fill or remove missing data first")
    for name, value, unit in (("dx", dx, "m"), ("dy", dy, "m"), ("contact_modulus", contact_modulus, "Pa")):
        if not np.isscalar(value) or not np.isfinite(value) or value <= 0:
            raise InputError(f"{name} must be a positive finite number [{unit}], got {value!r}")
    if (load is None) == (mean_pressure is None):
        raise InputError("give exactly one of load [N] and mean_pressure [Pa]")
    name, value, unit = ("load", load, "N") if load is not None else ("mean_pressure", mean_pressure, "Pa")
    if not np.isscalar(value) or not np.isfinite(value) or value <= 0:
        raise InputError(f"{name} must be a positive finite number [{unit}] (a compressive load), got {value!r}")
    if not (0.0 < tolerance < 1.0):
        raise InputError(f"tolerance must lie in (0, 1) (dimensionless), got {tolerance!r}")
    if max_iterations is not None and (int(max_iterations) != max_iterations or max_iterations < 1):
        raise InputError(f"max_iterations must be a positive integer, got {max_iterations!r}")
    if initial_pressure is not None:
        p0 = np.asarray(initial_pressure, dtype=float)
        if p0.shape != h.shape or not np.all(np.isfinite(p0)) or np.any(p0 < 0):
            raise InputError("initial_pressure [Pa] must be finite, >= 0 and of the same shape as separation")
    if hardness is not None and not (np.isscalar(hardness) and np.isfinite(hardness) and hardness > 0):
        raise InputError(f"hardness must be a positive finite pressure [Pa] or None (no cap), got {hardness!r}")
    if interaction is not None:
        raise InputError("interaction (an adhesive cohesive-zone law, e.g. Maugis-Dugdale) is reserved and not "
                         "implemented yet; leave it None (non-adhesive contact)")
    return h


def _active_set(operator, h, p, total, tolerance, cap, max_outer):
    """Primal-dual active set with a Fourier-preconditioned CG on each contact set.

    ``total``: sum of the element pressures [Pa] to keep; ``tolerance``: absolute gap
    tolerance [m]. Returns the pressure, CG iterations, whether converged.
    """
    contact = p > 0.0
    iterations = 0
    violation = np.inf
    for _ in range(max_outer):
        n_contact = np.count_nonzero(contact)
        if n_contact == 0:
            return p, iterations, False
        mask = contact.astype(float)
        inner_tolerance = max(0.5 * tolerance, _INNER_FACTOR * violation)
        p_c = p * mask
        p_c += (total - p_c.sum()) / n_contact * mask
        r = h + operator.displacement(p_c)
        r *= mask
        r -= (r.sum() / n_contact) * mask
        t = None
        G_old = 1.0
        first = True
        while iterations < cap:
            if max(r.max(), -r.min()) <= inner_tolerance:
                break
            iterations += 1
            z = operator.precondition(r)
            z *= mask
            z -= (z.sum() / n_contact) * mask
            G = _dot(r, z)
            if first:
                t = z
                first = False
            else:
                t *= G / G_old
                t += z
            G_old = G
            q = operator.displacement(t)
            q *= mask
            q -= (q.sum() / n_contact) * mask
            if not _cg_update(p_c, r, t, q):
                break
        p = p_c
        g = h + operator.displacement(p)
        g -= g[contact].sum() / n_contact
        negative = -p[contact].min()
        on_set = np.abs(g[contact]).max()
        outside = np.maximum(-g[~contact], 0.0).max(initial=0.0)
        violation = max(on_set, outside)
        if violation <= tolerance and negative < 0.0:
            return p, iterations, True
        if violation <= tolerance:
            # complementarity holds on the set, but some pressures are <= 0: try the clipped field
            clipped = np.maximum(p, 0.0)
            clipped *= total / clipped.sum()
            kept = clipped > 0.0
            gc = h + operator.displacement(clipped)
            gc -= gc[kept].mean()
            if max(np.abs(gc[kept]).max(), np.maximum(-gc[~kept], 0.0).max(initial=0.0)) <= tolerance:
                return clipped, iterations, True
        if iterations >= cap:
            break
        contact = (contact & (p > 0.0)) | (~contact & (g < 0.0))
    return np.maximum(p, 0.0), iterations, False


def _polonsky_keer(operator, h, p, total, tolerance, cap, iterations):
    """Polonsky & Keer's constrained CG (Fourier-preconditioned) from ``p``; returns (p, iterations)."""
    n = h.size
    t = np.zeros_like(h)
    G_old = 1.0
    conjugate = False
    while iterations < cap:
        g = h + operator.displacement(p)
        contact = p > 0.0
        n_contact = np.count_nonzero(contact)
        g_mean = g[contact].sum() / n_contact
        r = np.where(contact, g - g_mean, 0.0)
        if max(np.abs(r).max(), np.maximum(g_mean - g[~contact], 0.0).max(initial=0.0)) <= tolerance:
            break
        iterations += 1
        overlap = (~contact) & (g < g_mean)
        reactivate = bool(overlap.any())
        work = contact | overlap if reactivate else contact
        r = np.where(work, g - g_mean, 0.0)
        n_work = np.count_nonzero(work)
        z = np.where(work, operator.precondition(r), 0.0)
        z[work] -= z[work].sum() / n_work
        G = _dot(r, z)
        t = z + (G / G_old) * t if conjugate else z
        t[~work] = 0.0
        G_old = G
        q = operator.displacement(t)
        q = np.where(work, q - q[work].sum() / n_work, 0.0)
        denominator = _dot(q, t)
        if denominator <= 0.0:
            t = np.zeros_like(h)
            conjugate = False
            continue
        tau = _dot(r, t) / denominator
        p = np.maximum(p - tau * t, 0.0)
        conjugate = not reactivate
        s = p.sum()
        p = p * (total / s) if s > 0 else np.full_like(h, total / n)
    return p, iterations


def _cold_start(h, total):
    """Uniform pressure on the 30 % of the grid with the smallest gap."""
    k = int(0.3 * (h.size - 1))
    low = h <= np.partition(h.ravel(), k)[k]
    return np.where(low, total / np.count_nonzero(low), 0.0)


def _prolong(coarse, shape, periodic):
    """Bilinear interpolation of a coarse field (every other point) onto ``shape``."""
    ny, nx = shape
    fine = np.empty(shape)
    fine[0::2, 0::2] = coarse
    if periodic:
        right = np.roll(coarse, -1, axis=1)
        down = np.roll(coarse, -1, axis=0)
        diagonal = np.roll(right, -1, axis=0)
    else:
        right = np.zeros_like(coarse)
        right[:, :-1] = coarse[:, 1:]
        down = np.zeros_like(coarse)
        down[:-1] = coarse[1:]
        diagonal = np.zeros_like(coarse)
        diagonal[:-1, :-1] = coarse[1:, 1:]
    fine[0::2, 1::2] = 0.5 * (coarse + right)
    fine[1::2, 0::2] = 0.5 * (coarse + down)
    fine[1::2, 1::2] = 0.25 * (coarse + right + down + diagonal)
    return fine


def _nested_guess(h, dx, dy, modulus, target, periodic, cap):
    """Initial pressure [Pa] from nested coarser grids, or (None, 0) when the grid is small or odd."""
    ny, nx = h.shape
    if ny % 2 or nx % 2 or min(ny, nx) < 2 * _COARSEST:
        return None, 0
    coarse_h = h[::2, ::2] - h[::2, ::2].min()
    guess, used = _nested_guess(coarse_h, 2 * dx, 2 * dy, modulus, target, periodic, cap)
    total = target * coarse_h.size
    if guess is None:
        guess = _cold_start(coarse_h, total)
    else:
        guess *= total / guess.sum()
    operator = _half_space(coarse_h.shape, 2 * dx, 2 * dy, modulus, periodic)
    scale = float(coarse_h.max()) if coarse_h.max() > 0 else 1.0
    local = float(np.std(np.diff(coarse_h, axis=1))) or scale
    coarse_p, iterations, _ = _active_set(operator, coarse_h, guess, total,
                                          min(_COARSE_TOLERANCE * scale, _COARSE_STEP_FRACTION * local),
                                          cap, _COARSE_MAX_OUTER)
    return _prolong(np.maximum(coarse_p, 0.0), h.shape, periodic), used + iterations


def _resolution_notes(coarse_iterations, contact, periodic) -> str:
    """What a surface solve's message adds: coarse-grid iterations, too few elements in contact, the domain's edge."""
    message = ""
    if coarse_iterations:
        message += f"; {coarse_iterations} more on the coarser nested grids"
    n_contact = int(np.count_nonzero(contact))
    if n_contact < 10:
        message += f"; the contact is resolved by only {n_contact} element(s): refine the grid"
    if not periodic and (contact[0].any() or contact[-1].any() or contact[:, 0].any() or contact[:, -1].any()):
        message += "; the contact reaches the edge of the domain: enlarge it"
    return message


@cites("johnson_1985", "polonsky_keer_1999", "vollebregt_2014")
def solve_surface_contact(separation, dx, dy, contact_modulus, *, load=None, mean_pressure=None, periodic=False,
                          tolerance=1e-8, max_iterations=None, initial_pressure=None, continuation=True,
                          interaction=None, hardness=None):
    r"""Solve the non-adhesive normal contact of a rough surface under a given load.

    Parameters
    ----------
    separation : array_like
        Undeformed gap h(x, y) [m] at the element centres of a uniform grid, shape (ny, nx)
        (rows along x; any offset: only differences matter).
    dx, dy : float
        Element sizes along x and y [m].
    contact_modulus : float
        Contact modulus E* [Pa], 1/E* = (1-nu1²)/E1 + (1-nu2²)/E2.
    load : float, optional
        Normal force W [N]. Give this or ``mean_pressure``.
    mean_pressure : float, optional
        Nominal pressure W / (nx dx ny dy) [Pa].
    periodic : bool, optional
        Periodic half-space instead of the free boundary (module docstring).
    tolerance : float, optional
        Tolerance on the dimensionless complementarity residual (see
        :class:`SurfaceContactSolution`), default 1e-8.
    max_iterations : int, optional
        Cap on the fine-grid CG iterations (default max(1000, sqrt(nx ny))).
    initial_pressure : array_like, optional
        Warm start [Pa] of shape (ny, nx), rescaled to the load (then no nested grids).
    continuation : bool, optional
        Start from nested coarser grids (default).
    interaction : None
        Reserved for an adhesive cohesive-zone law (Maugis-Dugdale); must be None.
    hardness : float, optional
        Largest contact pressure H [Pa] (elastic-perfectly-plastic: the pressure is capped at H, the
        surfaces close in by plastic flattening there; module docstring). None (default): purely elastic.
        Where no element of the elastic solution exceeds H the elastic solution is returned as it is.

    Returns
    -------
    SurfaceContactSolution
        Pressure, gap, contact set, approach, load, iterations, residual, converged flag,
        timing, and with a hardness the plastic elements. Non-convergence is reported by
        ``converged=False`` and ``message``.

    Notes
    -----
    Minimises :math:`\frac12 p^T A p + p^T h` subject to :math:`p \ge 0` and
    :math:`dx\,dy\sum p = W` (Polonsky and Keer 1999). On a fixed contact set C the equations
    :math:`A_{CC} p_C - \delta = -h_C` with the load fixed are solved by a CG preconditioned
    with :math:`P_C\,\mathcal F^{-1}\frac{E^*|q|}{2}\mathcal F\,P_C` (Vollebregt 2014); then C is updated
    (p < 0 leave, penetrating points join) until it settles. Convergence: the largest gap
    error on C or penetration outside it, relative to ptp(h), at most ``tolerance``.

    Examples
    --------
    >>> n, d = 64, 2e-9
    >>> x = (np.arange(n) - n / 2) * d
    >>> h = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * 1e-6)
    >>> sol = solve_surface_contact(h, d, d, 100e9, load=1e-6)
    >>> sol.converged, 0.0 < sol.contact_fraction < 0.2
    (True, True)
    """
    start = time.perf_counter()
    h = _check_inputs(separation, dx, dy, contact_modulus, load, mean_pressure, tolerance, max_iterations,
                      initial_pressure, interaction, hardness)
    elastic = _solve_elastic(h, dx, dy, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                             initial_pressure, continuation, start)
    if hardness is None:
        return elastic
    if not np.any(elastic.pressure > hardness):  # the cap is not reached: the elastic solution, bit for bit
        return dataclasses.replace(elastic, plastic=np.zeros(h.shape, dtype=bool))
    total_load = float(load) if load is not None else float(mean_pressure) * h.size * float(dx) * float(dy)
    return _solve_capped(h, elastic, float(contact_modulus), total_load, float(hardness), tolerance, max_iterations,
                         start)


def _solve_elastic(h, dx, dy, contact_modulus, load, mean_pressure, periodic, tolerance, max_iterations,
                   initial_pressure, continuation, start):
    """The elastic solve of :func:`solve_surface_contact` (inputs checked; ``start`` [s]: when the solve began)."""
    ny, nx = h.shape
    dx, dy, modulus, periodic = float(dx), float(dy), float(contact_modulus), bool(periodic)
    target = float(mean_pressure) if mean_pressure is not None else float(load) / (h.size * dx * dy)
    total = target * h.size
    cap = int(max_iterations) if max_iterations is not None else max(1000, int(np.sqrt(h.size)))
    operator = _half_space((ny, nx), dx, dy, modulus, periodic)
    offset = float(h.min())
    h = h - offset
    scale = float(h.max()) if h.max() > 0 else target * np.sqrt(h.size * dx * dy) / modulus
    coarse_iterations = 0
    if initial_pressure is None and continuation:
        initial_pressure, coarse_iterations = _nested_guess(h, dx, dy, modulus, target, periodic, cap)
    if initial_pressure is not None and np.sum(initial_pressure) > 0:
        p = np.asarray(initial_pressure, dtype=float) * (total / np.sum(initial_pressure))
    else:
        p = _cold_start(h, total)
    p, iterations, settled = _active_set(operator, h, p, total, tolerance * scale, cap, _MAX_OUTER)
    method = "active-set"
    if not settled:
        method = "active-set, then polonsky-keer"
        p, iterations = _polonsky_keer(operator, h, np.maximum(p, 0.0), total, tolerance * scale, cap, iterations)
    g = h + operator.displacement(p)
    contact = p > 0.0
    g_mean = float(g[contact].mean())
    gap = g - g_mean
    residual = max(np.abs(gap[contact]).max(), np.maximum(-gap[~contact], 0.0).max(initial=0.0)) / scale
    converged = residual <= tolerance
    if converged:
        message = f"{method}: converged in {iterations} iterations (residual {residual:.2e} <= {tolerance:.1e})"
        gap = np.where(contact, 0.0, np.maximum(gap, 0.0))
    else:
        message = (f"{method}: NOT converged: residual {residual:.2e} > tolerance {tolerance:.1e} after {iterations} "
                   f"iterations (max_iterations={cap})")
    message += _resolution_notes(coarse_iterations, contact, periodic)
    return SurfaceContactSolution(pressure=p, gap=gap, contact=contact, approach=g_mean + offset,
                                  load=float(p.sum() * dx * dy), iterations=iterations, residual=float(residual),
                                  converged=bool(converged), solve_time=time.perf_counter() - start,
                                  message=message, dx=dx, dy=dy, periodic=periodic,
                                  coarse_iterations=coarse_iterations)


#: Updates of the plastic set before the capped surface solve gives up (converged=False): the line solve's
#: ``SolverSettings.max_plastic_updates``.
_MAX_PLASTIC_UPDATES = _LINE_DEFAULTS.max_plastic_updates


@cites("almqvist_2007", "johnson_1985", "model")
def _solve_capped(h, elastic, modulus, load, hardness, tolerance, max_iterations, start):
    """The surface contact with the pressure capped at ``hardness`` [Pa] under the ``load`` [N], from its elastic
    solution ``elastic`` (``h`` [m] the separation, ``modulus`` E* [Pa], ``start`` [s] when the solve began).

    An active set on the plastic elements P (those at the hardness), as the line solve's
    (:func:`memstribo.physics.contact.solve_line_contact_capped`): with P held at p = H, the rest is the
    elastic problem with the gap raised by the displacement of the plastic pressure, h + u(H 1_P), and the
    load W - H dx dy |P| (the elements of P lifted out of reach); then elements of the elastic solution above H
    join P and elements of P whose gap opens (g > 0) leave, until P no longer changes. The KKT conditions are
    those of ContactMechanics' constrained CG with a hardness and of Tamaas' ``KatoSaturated``: 0 <= p <= H,
    g = 0 on 0 < p < H, g <= 0 on p = H, g >= 0 on p = 0.
    """
    dx, dy, periodic = elastic.dx, elastic.dy, elastic.periodic
    area = dx * dy
    operator = _half_space(h.shape, dx, dy, modulus, periodic)
    plastic = elastic.pressure > hardness
    guess_pressure = elastic.pressure
    history = set()
    updates, note, iterations = 0, "", elastic.iterations
    while True:
        updates += 1
        raised = h + operator.displacement(np.where(plastic, hardness, 0.0))
        free = ~plastic
        top = float(raised[free].max()) if free.any() else float(raised.max())
        lifted = np.where(plastic, np.maximum(raised, top) + max(float(np.ptp(raised)), 1e-12), raised)
        rest = load - hardness * area * int(np.count_nonzero(plastic))
        if rest <= 0.0 or not free.any():  # cannot happen (each joining element takes less than its share)
            note = "; NOT converged: the plastic set carries the whole load"
            break
        guess = np.where(plastic, 0.0, np.clip(guess_pressure, 0.0, hardness))
        inner = solve_surface_contact(lifted, dx, dy, modulus, load=rest, periodic=periodic, tolerance=tolerance,
                                      max_iterations=max_iterations,
                                      initial_pressure=guess if guess.sum() > 0 else None)
        iterations += inner.iterations
        pressure = np.where(plastic, hardness, inner.pressure)
        total = raised + operator.displacement(inner.pressure)
        elastic_contact = inner.contact & free
        delta = float(total[elastic_contact].mean()) if elastic_contact.any() else float(total[plastic].max())
        gap_all = total - delta
        guess_pressure = pressure
        joining = (inner.pressure > hardness) & free
        leaving = plastic & (gap_all > 0.0)
        if not joining.any() and not leaving.any():
            break
        history.add(plastic.tobytes())
        plastic = (plastic | joining) & ~leaving
        if plastic.tobytes() in history or updates >= _MAX_PLASTIC_UPDATES:
            note = f"; NOT converged: the plastic set did not settle in {updates} updates"
            break
    n_plastic = int(np.count_nonzero(plastic))
    converged = bool(inner.converged and not note)
    message = (f"{inner.message}; pressure capped at the hardness {hardness / 1e9:.3g} GPa on {n_plastic} "
               f"element(s) after {updates} plastic-set update(s){note}")
    return dataclasses.replace(
        inner, pressure=pressure, gap=np.where(plastic, 0.0, inner.gap), contact=inner.contact | plastic,
        approach=delta, load=float(pressure.sum() * area), iterations=iterations, converged=converged,
        solve_time=time.perf_counter() - start, message=message, plastic=plastic, plastic_updates=updates,
        coarse_iterations=elastic.coarse_iterations + inner.coarse_iterations)
