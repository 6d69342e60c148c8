"""Surface and subsurface stresses of an elastic half-space under an axisymmetric contact
pressure and a sliding friction traction (thesis 5.5, Figures 5-17 and 5-19 to 5-21).

The half-space occupies z >= 0 (z is the depth below the surface); the pressure p(r),
r = sqrt(x² + y²) < a, presses on it and the friction traction mu p(r) acts on its surface
along +x (the counter body slides in +x, so the trailing edge is at x = -a). Stresses are
Cauchy stresses, tension positive, in [Pa]; tau_1 = (sigma_1 - sigma_3) / 2 is the
principal shear stress used for the damage accumulation (5-8 to 5-10).

Method
------
The stress field is the superposition of the Boussinesq (normal) and Cerruti (tangential)
point-load solutions over the loaded circle [3]_. Every point-load stress component has
the form A + z B with A and B harmonic (derivatives of 1/R, ln(R + z) and
z ln(R + z) - R). An axisymmetric pressure is a superposition of flat-punch distributions,
p(r) = -int_r^a W'(t) / sqrt(t² - r²) dt, with

.. math:: W(\\tau) = \\frac{2}{\\pi}\\int_\\tau^a \\frac{r\\,p(r)}{\\sqrt{r^2-\\tau^2}}\\,dr,

and the potential of such a distribution equals a line integral of the point-load
potential over complex depths z + i tau (Hamilton & Goodman [2]_). Hence, exactly,

.. math:: \\sigma_{ij}(x, y, z) = 2\\pi\\,\\mathrm{Re}\\int_0^a W(\\tau)
          \\left[A_{ij}(x, y, z + i\\tau) + z\\,B_{ij}(x, y, z + i\\tau)\\right] d\\tau,

a one-dimensional integral of elementary functions instead of a singular surface integral.
memstribo evaluates it by Gauss-Legendre quadrature after the substitution
tau = rho + z sinh(u), which resolves the near-singular behaviour at tau = rho when the
field point is close to the surface; W is computed once per pressure and interpolated.
For Hertz's pressure W = p0 (a² - tau²) / (2a), and the integral reproduces Hamilton's
closed form [1]_ (tests: 1e-7 relative, at the surface as well as below it).

References
----------
.. [1] G. M. Hamilton, 'Explicit equations for the stresses beneath a sliding spherical
   contact', Proc. IMechE C 197 (1983) 53-59. :doi:`10.1243/PIME_PROC_1983_197_076_02`
.. [2] G. M. Hamilton, L. E. Goodman, 'The stress field created by a circular sliding
   contact', J. Appl. Mech. 33 (1966) 371-376. :doi:`10.1115/1.3625051`
.. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985, sections 3.2-3.4.
.. [4] N. S. T. Almuramady, 'Dry friction between rough surfaces of silicon and
   functionalized gear MEMS', PhD thesis, Cardiff University, section 5.5.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from memstribo.checks import as_array, as_positive_scalar
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "StressField",
    "boussinesq",
    "cerruti",
    "hertz_pressure",
    "flat_punch_weight",
    "stress_field",
    "hamilton_sliding_sphere",
    "principal_stresses",
    "principal_shear_stress",
    "principal_shear_profile",
]

_COMPONENTS = ("xx", "yy", "zz", "xy", "xz", "yz")
#: Depth (in contact radii) below which the line integral is not evaluated directly: its
#: Cerruti kernels lose precision for z below ~1e-7 a, so stresses at 0 <= z < SURFACE_DEPTH a
#: are extrapolated (Richardson, in powers 0, 1/2 and 1 of z) from z = 1, 2 and 4 SURFACE_DEPTH a.
SURFACE_DEPTH = 1e-5
_CHUNK = 128  # field points per vectorised block (bounds the memory of the kernel evaluation)


@dataclass(frozen=True)
class StressField:
    """Cauchy stress components at a set of points, tension positive.

    Attributes
    ----------
    sigma_xx, sigma_yy, sigma_zz : ndarray
        Normal stresses [Pa] (x: sliding direction, z: depth into the body).
    sigma_xy, sigma_xz, sigma_yz : ndarray
        Shear stresses [Pa].
    """

    sigma_xx: np.ndarray
    sigma_yy: np.ndarray
    sigma_zz: np.ndarray
    sigma_xy: np.ndarray
    sigma_xz: np.ndarray
    sigma_yz: np.ndarray

    @property
    def shape(self) -> tuple[int, ...]:
        return np.shape(self.sigma_xx)

    def tensor(self) -> np.ndarray:
        """The symmetric stress tensor, shape (..., 3, 3) [Pa]."""
        xx, yy, zz, xy, xz, yz = (np.asarray(getattr(self, f"sigma_{c}")) for c in _COMPONENTS)
        return np.stack([np.stack([xx, xy, xz], -1), np.stack([xy, yy, yz], -1), np.stack([xz, yz, zz], -1)], -2)

    def __add__(self, other: "StressField") -> "StressField":
        return StressField(*(getattr(self, f"sigma_{c}") + getattr(other, f"sigma_{c}") for c in _COMPONENTS))

    def scaled(self, factor) -> "StressField":
        """All components times ``factor``."""
        return StressField(*(getattr(self, f"sigma_{c}") * factor for c in _COMPONENTS))


# --- input checks ------------------------------------------------------------------------------

def _poisson(value) -> float:
    array = as_array(value, "poisson_ratio", "-")
    if array.ndim != 0 or not -1.0 < array <= 0.5:
        raise InputError(f"poisson_ratio must be one number in (-1, 0.5], got {value!r}.")
    return float(array)


def _friction(value) -> float:
    array = as_array(value, "friction_coefficient", "-")
    if array.ndim != 0:
        raise InputError(f"friction_coefficient must be one number, got {value!r}.")
    return float(array)


def _points(x, y, z):
    x, y, z = (as_array(v, n, "m") for v, n in ((x, "x"), (y, "y"), (z, "z")))
    if np.any(z < 0):
        raise InputError("z is the depth below the surface and must be >= 0 [m].")
    try:
        return np.broadcast_arrays(x, y, z)
    except ValueError:
        raise InputError(f"x, y and z must broadcast together (shapes {x.shape}, {y.shape}, {z.shape}).") from None


# --- point-load solutions ------------------------------------------------------------------------

def _field_from(values, factor) -> StressField:
    return StressField(*(factor * v for v in values))


def _point_load(x, y, z, load, poisson_ratio, kernels) -> StressField:
    """Stresses of a point load ``load`` [N] on the surface, sigma = load (A + z B), with A and B the
    unit-load components that ``kernels(x, y, z, R, nu)`` returns (see the point-load kernels below)."""
    x, y, z = _points(x, y, z)
    if np.any(z <= 0):
        raise InputError("z must be > 0 [m] for a point load (the surface point itself is singular).")
    nu = _poisson(poisson_ratio)
    load = float(as_array(load, "load", "N"))
    r = np.sqrt(x**2 + y**2 + z**2)
    k = kernels(x, y, z, r, nu)
    return _field_from([k[i] + z * k[i + 6] for i in range(6)], load)


@cites("johnson_1985")
def boussinesq(x, y, z, load, poisson_ratio):
    """Stresses under a normal point load on the surface of a half-space (Boussinesq).

    Parameters
    ----------
    x, y : array_like
        Position relative to the load along the surface [m].
    z : array_like
        Depth below the surface [m], > 0.
    load : float
        Normal load P [N], compressive positive.
    poisson_ratio : float
        nu [-], in (-1, 0.5].

    Returns
    -------
    StressField
        E.g. sigma_zz = -3 P z³ / (2 pi R⁵) (Johnson section 3.2 in [3]_).
    """
    return _point_load(x, y, z, load, poisson_ratio, _boussinesq_kernels)


@cites("johnson_1985")
def cerruti(x, y, z, load, poisson_ratio):
    """Stresses under a tangential point load (along +x) on the surface of a half-space (Cerruti).

    Parameters
    ----------
    x, y, z : as in :func:`boussinesq` (position along the surface [m], depth [m] > 0)
    load : float
        Tangential load Q [N] along +x.
    poisson_ratio : float
        nu [-], in (-1, 0.5].

    Returns
    -------
    StressField
        E.g. sigma_xz = -3 Q x² z / (2 pi R⁵) (Johnson section 3.3 in [3]_).
    """
    return _point_load(x, y, z, load, poisson_ratio, _cerruti_kernels)


# --- pressures ------------------------------------------------------------------------------------

def hertz_pressure(r, contact_radius, max_pressure):
    """Hertz's pressure p0 sqrt(1 - r²/a²) inside the contact circle, 0 outside [Pa].

    Parameters
    ----------
    r : array_like
        Distance from the contact centre [m].
    contact_radius : float
        a [m], > 0.
    max_pressure : float
        p0 [Pa], > 0.
    """
    a = as_positive_scalar(contact_radius, "contact_radius", "m")
    p0 = as_positive_scalar(max_pressure, "max_pressure", "Pa")
    r = as_array(r, "r", "m")
    return p0 * np.sqrt(np.clip(1.0 - (r / a) ** 2, 0.0, None))


class _Weight:
    """W(tau) of a pressure, as a Chebyshev series in alpha, tau = a sin(alpha)."""

    def __init__(self, coefficients: np.ndarray, contact_radius: float, load: float):
        self.coefficients = coefficients
        self.contact_radius = contact_radius
        self.load = load

    def __call__(self, tau):
        xi = 4.0 / np.pi * np.arcsin(np.clip(np.asarray(tau, dtype=float) / self.contact_radius, 0.0, 1.0)) - 1.0
        return np.polynomial.chebyshev.chebval(xi, self.coefficients)


def flat_punch_weight(pressure, contact_radius, *, degree: int = 96, nodes: int = 64) -> _Weight:
    """Weight W(tau) of the flat-punch representation of an axisymmetric pressure.

    .. math:: W(\\tau) = \\frac{2}{\\pi}\\int_\\tau^a\\frac{r\\,p(r)}{\\sqrt{r^2-\\tau^2}}dr
              = \\frac{2}{\\pi}\\int_0^{\\sqrt{a^2-\\tau^2}} p\\left(\\sqrt{\\tau^2+s^2}\\right) ds

    (module notes); the total load is P = 2 pi int_0^a W dtau.

    Parameters
    ----------
    pressure : callable or tuple of arrays
        p(r) [Pa] for 0 <= r <= a (vectorised callable), or samples ``(r, p)`` interpolated
        linearly.
    contact_radius : float
        a [m].
    degree : int
        Degree of the Chebyshev series of W in alpha = arcsin(tau / a).
    nodes : int
        Gauss-Legendre nodes of each W value.

    Returns
    -------
    callable
        W(tau) [Pa·m] = [N/m], with attribute ``load`` (the total load [N]).

    Raises
    ------
    InputError
        If the pressure is negative, not finite, or not a callable / pair of arrays.
    """
    a = as_positive_scalar(contact_radius, "contact_radius", "m")
    p = _pressure_callable(pressure)
    theta, theta_w = np.polynomial.legendre.leggauss(nodes)
    theta = 0.25 * np.pi * (theta + 1.0)
    theta_w = 0.25 * np.pi * theta_w

    def weight_of_xi(xi):
        tau = a * np.sin(0.25 * np.pi * (np.asarray(xi) + 1.0))
        smax = np.sqrt(np.clip(a * a - tau * tau, 0.0, None))
        r = np.sqrt(tau[:, None] ** 2 + (smax[:, None] * np.sin(theta)) ** 2)
        values = np.asarray(p(np.minimum(r, a)), dtype=float)
        if values.shape != r.shape:
            values = np.broadcast_to(values, r.shape)
        if not np.all(np.isfinite(values)) or np.any(values < 0):
            raise InputError("pressure must be finite and >= 0 [Pa] for 0 <= r <= contact_radius.")
        return 2.0 / np.pi * smax * ((values * np.cos(theta)) @ theta_w)

    coefficients = np.polynomial.chebyshev.chebinterpolate(weight_of_xi, degree)
    # total load P = 2 pi int_0^a W dtau, tau = a sin(alpha)
    alpha, alpha_w = np.polynomial.legendre.leggauss(nodes)
    alpha = 0.25 * np.pi * (alpha + 1.0)
    xi = 4.0 / np.pi * alpha - 1.0
    load = 2.0 * np.pi * np.sum(np.polynomial.chebyshev.chebval(xi, coefficients) * a * np.cos(alpha)
                                * 0.25 * np.pi * alpha_w)
    return _Weight(coefficients, a, float(load))


def _pressure_callable(pressure) -> Callable:
    if callable(pressure):
        return pressure
    try:
        r, p = (np.asarray(v, dtype=float) for v in pressure)
    except (TypeError, ValueError):
        raise InputError("pressure must be a callable p(r) [Pa] or a pair of arrays (r [m], p [Pa]).") from None
    if r.ndim != 1 or r.shape != p.shape or r.size < 2 or np.any(np.diff(r) <= 0):
        raise InputError("pressure samples (r, p) must be 1-D arrays of equal length >= 2 with increasing r.")
    return lambda radius: np.interp(radius, r, p, right=0.0)


# --- the stress field of an axisymmetric pressure with friction ------------------------------------

def _complex_integral(x, y, z, a, weight, friction, nu, nodes):
    """2 pi Re int_0^a W(tau) [A + z B](x, y, z + i tau) dtau for flat arrays x, y, z > 0."""
    gx, gw = np.polynomial.legendre.leggauss(nodes)
    out = np.empty((6, x.size))
    for start in range(0, x.size, _CHUNK):
        sl = slice(start, start + _CHUNK)
        xs, ys, zs = x[sl, None], y[sl, None], z[sl, None]
        rho = np.hypot(xs, ys)
        u0 = np.arcsinh(-rho / zs)
        u1 = np.arcsinh((a - rho) / zs)
        mid = np.minimum(0.0, u1)
        u = np.concatenate([0.5 * (mid - u0) * gx + 0.5 * (mid + u0), 0.5 * (u1 - mid) * gx + 0.5 * (u1 + mid)], 1)
        w = np.concatenate([0.5 * (mid - u0) * gw, 0.5 * (u1 - mid) * gw], 1)
        shift = zs * np.sinh(u)  # tau - rho, known without cancellation
        tau = np.clip(rho + shift, 0.0, a)
        factor = zs * np.cosh(u) * w * weight(tau)
        z1 = zs + 1j * tau
        # R^2 = rho^2 + z1^2 = z^2 - (tau - rho)(tau + rho) + 2 i z tau, free of the cancellation in rho^2 - tau^2
        r = np.sqrt(zs * zs - shift * (2.0 * rho + shift) + 2j * zs * tau)
        kernels = _boussinesq_kernels(xs, ys, z1, r, nu)
        components = [kernels[i] + zs * kernels[i + 6] for i in range(6)]
        if friction != 0.0:
            kernels = _cerruti_kernels(xs, ys, z1, r, nu)
            components = [c + friction * (kernels[i] + zs * kernels[i + 6]) for i, c in enumerate(components)]
        for i, component in enumerate(components):
            out[i, sl] = 2.0 * np.pi * np.sum((component * factor).real, axis=1)
    return out


@cites("hamilton_goodman_1966", "johnson_1985", "thesis")
def stress_field(x, y, z, pressure, contact_radius, friction_coefficient=0.0, poisson_ratio=0.3, *,
                 nodes: int = 64):
    """Stresses under an axisymmetric pressure p(r) with the sliding traction mu p(r) along +x.

    The superposition of the Boussinesq and Cerruti point-load solutions over the contact
    circle, evaluated exactly as a line integral over complex depth (module notes, [2]_);
    used for the atomic asperities of thesis 5.5 ([4]_), whose pressure is the power-law
    punch solution.

    Parameters
    ----------
    x, y : array_like
        Position along the surface from the contact centre [m]; x is the sliding direction.
    z : array_like
        Depth below the surface [m], >= 0 (for z < ``SURFACE_DEPTH * a`` the stresses are
        extrapolated from that depth: the limit z -> 0+). x, y and z broadcast together.
    pressure : callable or tuple of arrays
        Contact pressure p(r) [Pa] on 0 <= r <= a, >= 0 (e.g.
        ``lambda r: asperity.power_law_pressure(r, load, 4, 4e22, 85e9)``), or samples (r, p).
    contact_radius : float
        a [m], > 0.
    friction_coefficient : float
        mu [-]: the surface traction is mu p(r) along +x (negative: along -x).
    poisson_ratio : float
        nu [-], in (-1, 0.5].
    nodes : int
        Gauss-Legendre nodes on each side of the near-singular point (default 64: about
        1e-8 relative accuracy against Hamilton's closed form).

    Returns
    -------
    StressField
        Stresses [Pa], tension positive, of the broadcast shape of x, y, z.

    Examples
    --------
    >>> s = stress_field(0.0, 0.0, 0.5e-9, lambda r: hertz_pressure(r, 1e-9, 1e9), 1e-9, 0.0, 0.3)
    >>> print(f"{float(s.sigma_zz) / 1e9:.4f}")  # -p0 a²/(a² + z²) on the axis
    -0.8000
    """
    x, y, z = _points(x, y, z)
    a = as_positive_scalar(contact_radius, "contact_radius", "m")
    mu = _friction(friction_coefficient)
    nu = _poisson(poisson_ratio)
    if int(nodes) != nodes or nodes < 4:
        raise InputError(f"nodes must be an integer >= 4, got {nodes!r}.")
    if isinstance(pressure, _Weight):
        if not np.isclose(pressure.contact_radius, a, rtol=1e-12, atol=0.0):
            raise InputError(f"the flat-punch weight was computed for contact_radius = {pressure.contact_radius!r} m, "
                             f"not {a!r} m: compute it with the same contact_radius.")
        weight = pressure
    else:
        weight = flat_punch_weight(pressure, a)
    shape = x.shape
    values = _near_surface(lambda xx, yy, zz: _complex_integral(xx, yy, zz, a, weight, mu, nu, int(nodes)),
                           x.ravel().astype(float), y.ravel().astype(float), z.ravel().astype(float), a)
    return StressField(*(v.reshape(shape) for v in values))


def _near_surface(evaluate, x, y, z, a):
    """evaluate(x, y, z) for z >= SURFACE_DEPTH a; Richardson extrapolation above that depth."""
    delta = SURFACE_DEPTH * a
    out = np.empty((6, x.size))
    deep = z >= delta
    if np.any(deep):
        out[:, deep] = evaluate(x[deep], y[deep], z[deep])
    shallow = ~deep
    if np.any(shallow):
        # fit f0 + c sqrt(z) + d z through z = delta, 2 delta, 4 delta: exact for the smooth field
        # to O(delta^2) and for the square-root behaviour below the edge of a contact
        xs, ys, zs = x[shallow], y[shallow], z[shallow]
        depths = delta * np.array([1.0, 2.0, 4.0])
        samples = np.stack([evaluate(xs, ys, np.full_like(zs, d)) for d in depths])  # (3, 6, n)
        basis = np.stack([np.ones(3), np.sqrt(depths / delta), depths / delta], axis=1)
        coefficients = np.einsum("ij,j...->i...", np.linalg.inv(basis), samples)
        t = zs / delta
        out[:, shallow] = coefficients[0] + coefficients[1] * np.sqrt(t) + coefficients[2] * t
    return out


# --- Hamilton's closed form for the sliding sphere ---------------------------------------------------

def _hamilton_normal(x, y, z, a, p0, nu):
    """Hamilton (1983) explicit equations, normal load (flat arrays, r > 0, z > 0)."""
    r2 = x * x + y * y
    big_a = r2 + z * z - a * a
    s = np.sqrt(big_a * big_a + 4.0 * a * a * z * z)
    m = np.sqrt(0.5 * (s + big_a))
    n = np.sqrt(np.maximum(0.5 * (s - big_a), 0.0))
    phi = np.arctan2(a, m)
    g = m * m - n * n + z * m - a * n
    h = 2.0 * m * n + a * m + z * n
    k = p0 / a  # = 3 P / (2 pi a^3)
    common = (1 - nu) * n * z * z - (1 - 2 * nu) / 3 * (n * s + 2 * big_a * n + a**3) - nu * m * z * a
    sxx = k * ((1 + nu) * z * phi + ((y * y - x * x) / r2 * common - n * (x * x + 2 * nu * y * y)
                                     - m * x * x * z * a / s) / r2)
    syy = k * ((1 + nu) * z * phi + ((x * x - y * y) / r2 * common - n * (y * y + 2 * nu * x * x)
                                     - m * y * y * z * a / s) / r2)
    szz = k * (-n + a * z * m / s)
    sxy = k * (x * y * (1 - 2 * nu) / r2**2 * (-n * r2 + 2.0 / 3.0 * n * (s + 2 * big_a) - z * (z * n + a * m)
                                               + 2.0 / 3.0 * a**3)
               + x * y * z / r2**2 * (-a * m * r2 / s - z * n + a * m))
    shear = z * h / (g * g + h * h)
    sxz = -k * z * (x * n / s - x * shear)
    syz = -k * z * (y * n / s - y * shear)
    return np.array([sxx, syy, szz, sxy, sxz, syz])


@cites("hamilton_1983", "hamilton_goodman_1966")
def hamilton_sliding_sphere(x, y, z, contact_radius, max_pressure, friction_coefficient, poisson_ratio):
    """Stresses beneath a sliding Hertz contact: pressure p0 sqrt(1 - r²/a²), traction mu p along +x.

    The normal-load part is Hamilton's explicit closed form ([1]_; on and within 1e-3 a of
    the axis, where its terms cancel, the exact line integral is used instead). The
    tangential part is the Hamilton-Goodman line integral over complex depth ([2]_) with
    W(tau) = p0 (a² - tau²) / (2a), integrated analytically in elementary functions (the
    route by which Hamilton obtained his explicit equations; memstribo's expressions were
    derived with sympy, see ``_hamilton_tangential``); within 1e-6 a of the axis and near the
    contact edge just below the surface, where those expressions are ill-conditioned, the
    line integral is evaluated by quadrature instead. Validated against the closed-form
    surface stresses (e.g. sigma_xx = p0 [(1 - 2 nu)/3 + pi (4 + nu) mu / 8] at the trailing
    edge x = -a) and against direct 2-D integration of Cerruti's solution
    (tests/test_stresses.py).

    Parameters
    ----------
    x, y : array_like
        Position from the contact centre [m], x along the sliding direction.
    z : array_like
        Depth [m], >= 0 (z = 0 is the limit z -> 0+).
    contact_radius : float
        a [m], > 0.
    max_pressure : float
        p0 [Pa], > 0.
    friction_coefficient : float
        mu [-].
    poisson_ratio : float
        nu [-], in (-1, 0.5].

    Returns
    -------
    StressField
        Stresses [Pa], tension positive.

    Examples
    --------
    >>> s = hamilton_sliding_sphere(-1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.3)
    >>> print(f"{float(s.sigma_xx):.4f}")  # (1 - 2 nu) / 3 at the contact edge
    0.1333
    """
    x, y, z = _points(x, y, z)
    a = as_positive_scalar(contact_radius, "contact_radius", "m")
    p0 = as_positive_scalar(max_pressure, "max_pressure", "Pa")
    mu = _friction(friction_coefficient)
    nu = _poisson(poisson_ratio)
    shape = x.shape
    xf, yf, zf = x.ravel().astype(float), y.ravel().astype(float), z.ravel().astype(float)
    weight = _HertzWeight(a, p0)
    values = np.empty((6, xf.size))
    near_axis = np.hypot(xf, yf) < 1e-3 * a
    if np.any(~near_axis):
        far = ~near_axis
        values[:, far] = _hamilton_normal(xf[far], yf[far], np.maximum(zf[far], 1e-12 * a), a, p0, nu)
    if np.any(near_axis):
        values[:, near_axis] = _near_surface(
            lambda xx, yy, zz: _complex_integral(xx, yy, zz, a, weight, 0.0, nu, 64),
            xf[near_axis], yf[near_axis], zf[near_axis], a)
    if mu != 0.0:
        closed, usable = _hamilton_tangential(xf, yf, np.maximum(zf, 1e-12 * a), a, p0, nu)
        if not np.all(usable):
            def tangential(xx, yy, zz):
                both = _complex_integral(xx, yy, zz, a, weight, 1.0, nu, 64)
                return both - _complex_integral(xx, yy, zz, a, weight, 0.0, nu, 64)

            rest = ~usable
            closed[:, rest] = _near_surface(tangential, xf[rest], yf[rest], zf[rest], a)
        values = values + mu * closed
    return StressField(*(v.reshape(shape) for v in values))


def _hamilton_tangential(x, y, z, a, p0, nu):
    """Closed form of the stresses of the traction p0 sqrt(1 - r²/a²) along +x (flat arrays, z > 0).

    The Hamilton-Goodman line integral with W = p0 (a² - tau²)/(2a) integrated analytically:
    with w = R + z1 (z1 = z + i tau, R = sqrt(rho² + z1²)) the integrand is rational in w, and
    with s = w / rho each term is c_m rho^(j-7) s^j / (s² + 1)^4, whose antiderivatives G_j(s)
    are elementary. Returns the six components and a mask of the points where the form is
    well conditioned (away from the axis and from the contact edge at the surface, where
    s² + 1 -> 0); elsewhere the caller uses the line integral by quadrature.
    """
    rho = np.hypot(x, y)
    z1 = z + 1j * a
    w1 = np.sqrt(rho * rho + z1 * z1) + z1
    usable = (rho > 1e-6 * a)
    safe_rho = np.where(usable, rho, a)
    s1 = w1 / safe_rho
    usable &= np.abs(s1 * s1 + 1.0) >= 0.05
    s1 = np.where(usable, s1, 2.0)
    s0 = ((np.sqrt(rho * rho + z * z) + z) / safe_rho).astype(complex)
    coefficients = _hamilton_tangential_coefficients(x, y, safe_rho, z, a, nu)
    differences: dict[int, np.ndarray] = {}
    values = np.zeros((6, x.size))
    for index, ij in enumerate(((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))):
        total = np.zeros(x.size, dtype=complex)
        for name, power in _HAMILTON_TANGENTIAL_TERMS[ij]:
            if power not in differences:
                differences[power] = _antiderivative_g(power, s1) - _antiderivative_g(power, s0)
            total += coefficients[name] * safe_rho ** (power - 7) * differences[power]
        values[index] = np.pi * p0 / a * (-1j * total).real
    return values, usable


class _HertzWeight(_Weight):
    def __init__(self, contact_radius, max_pressure):
        self.contact_radius = contact_radius
        self.max_pressure = max_pressure
        self.load = 2.0 * np.pi * contact_radius**2 * max_pressure / 3.0

    def __call__(self, tau):
        return self.max_pressure / (2.0 * self.contact_radius) * (self.contact_radius**2 - np.asarray(tau) ** 2)


# --- principal stresses ------------------------------------------------------------------------------

def _tensor(stress) -> np.ndarray:
    if isinstance(stress, StressField):
        return stress.tensor()
    tensor = np.asarray(stress, dtype=float)
    if tensor.shape[-2:] != (3, 3):
        raise InputError("stress must be a StressField or an array of 3 x 3 tensors (shape (..., 3, 3)).")
    return tensor


def principal_stresses(stress) -> np.ndarray:
    """Principal stresses sigma_1 >= sigma_2 >= sigma_3 [Pa], shape (..., 3).

    Parameters
    ----------
    stress : StressField or array_like of shape (..., 3, 3)
    """
    return np.linalg.eigvalsh(_tensor(stress))[..., ::-1]


def principal_shear_stress(stress) -> np.ndarray:
    """Principal (maximum) shear stress tau_1 = (sigma_1 - sigma_3) / 2 [Pa], >= 0.

    Parameters
    ----------
    stress : StressField or array_like of shape (..., 3, 3)
    """
    values = np.linalg.eigvalsh(_tensor(stress))
    return 0.5 * (values[..., 2] - values[..., 0])


def principal_shear_profile(x, depth, pressure, contact_radius, friction_coefficient=0.0, poisson_ratio=0.3):
    """tau_1 on the line along the sliding direction through the contact centre (thesis 5.5).

    Parameters
    ----------
    x : array_like, 1-D
        Positions along the sliding direction [m] (y = 0).
    depth : float or array_like, 1-D
        Depths below the surface [m], >= 0.
    pressure, contact_radius, friction_coefficient, poisson_ratio
        As :func:`stress_field`.

    Returns
    -------
    ndarray
        tau_1 [Pa] of shape (len(depth), len(x)) (or (len(x),) for a scalar depth).
    """
    x = as_array(x, "x", "m")
    depth = as_array(depth, "depth", "m")
    if x.ndim != 1 or depth.ndim > 1:
        raise InputError("x must be 1-D and depth a number or a 1-D array [m].")
    field = stress_field(x[None, :], 0.0, np.atleast_1d(depth)[:, None], pressure, contact_radius,
                         friction_coefficient, poisson_ratio)
    tau = principal_shear_stress(field)
    return tau[0] if depth.ndim == 0 else tau


# --- point-load kernels --------------------------------------------------------------------------
# Generated with sympy from the displacement fields u = U0 + z U1 of the Boussinesq and Cerruti
# solutions (Johnson 1985, 3.2-3.3; U0, U1 harmonic): each returns the six stress components of
# A (first six: xx, yy, zz, xy, xz, yz) and B (last six) for a unit load, sigma = A + z B. They are
# rational in x, y, z, R = sqrt(x^2 + y^2 + z^2) and valid for complex z (principal square root).
# Checked against the closed forms and against equilibrium in tests/test_stresses.py.
# fmt: off
def _boussinesq_kernels(x, y, z, R, nu):
    t0 = x**2
    t1 = 1/R
    t2 = 2*nu - 1
    t3 = R + z
    t4 = t2/t3**2
    t5 = t1*t4
    t6 = t0*t5
    t7 = 1/t3
    t8 = t2*t7
    t9 = R**(-2)
    t10 = t0*t9
    t11 = t10*t8
    t12 = t9*z
    t13 = nu - 1
    t14 = t12*t13
    t15 = y**2
    t16 = t15*t9
    t17 = t16*t8
    t18 = t15*t5
    t19 = nu/t2
    t20 = t19*(t11 - t12 - 2*t14 + t17 + t18 + t6 - 2*t8)
    t21 = t20 + t8
    t22 = 1/np.pi
    t23 = t1*t22
    t24 = (1/2)*t23
    t25 = (1/2)*t22
    t26 = x*y
    t27 = (1/4)*t23*(-t12*t8 + 2*t13*t9 - t4*(t1*z + 1) + t9)
    t28 = t9*z**2
    t29 = 3*t19*(t10 + t16 + t28 - 1) + 1
    t30 = t25/R**3
    t31 = (3/2)*t22/R**5
    t32 = t31*z
    return (t24*(-t11 + t21 - t6), t24*(-t17 - t18 + t21), t23*((1/2)*t12 + t14 + (1/2)*t20), -t25*t26*t8*t9*(t1 + t7), t27*x, t27*y, t30*(-3*t10 + t29), t30*(-3*t16 + t29), t30*(-3*t28 + t29), -t26*t31, -t32*x, -t32*y)

def _cerruti_kernels(x, y, z, R, nu):
    t0 = 1/R
    t1 = 3*t0
    t2 = R + z
    t3 = t2**(-2)
    t4 = t3*z
    t5 = 1/t2
    t6 = t0*z
    t7 = t5*t6
    t8 = x**2
    t9 = R**(-3)
    t10 = 3*t9
    t11 = t10*t8
    t12 = t2**(-3)
    t13 = 2*t12
    t14 = t13*t6
    t15 = t14*t8
    t16 = t11*t5
    t17 = R**(-2)
    t18 = 3*t17
    t19 = t18*t8
    t20 = -t11 + t15 + t16*z + t19*t4
    t21 = t1 + t20 - 3*t4 - 3*t7
    t22 = nu*t0
    t23 = 2*nu
    t24 = t23 - 1
    t25 = 1/t24
    t26 = -t24
    t27 = R**(-4)
    t28 = z**2
    t29 = t6 + 1
    t30 = t17*t28
    t31 = t3*t30
    t32 = 1 - t30
    t33 = t3*t6
    t34 = t32*t33
    t35 = 2*t3
    t36 = t29*t35
    t37 = t29**2
    t38 = t13*z
    t39 = t17 - t36 + t37*t38
    t40 = -t34 + t39
    t41 = t17*z
    t42 = t41*t5
    t43 = 2*t42
    t44 = z**3
    t45 = t27*t44
    t46 = t45*t5
    t47 = -t43 + 2*t46
    t48 = -2*t27*t28 + t29*t31 + t40 + t47
    t49 = -t48
    t50 = t30*t5
    t51 = t29*t4
    t52 = -t41 - t5 + t50 + t51
    t53 = y**2
    t54 = 3*t42
    t55 = 3*t3
    t56 = t55*t6
    t57 = -3*t17 + t38 + t54 + t56
    t58 = -t32
    t59 = t27*t28
    t60 = 3*t59
    t61 = t30*t36 - t60
    t62 = t39 + t61
    t63 = t33*t58 + t62
    t64 = -t0 + t4 + t7
    t65 = -2*nu*t0*t64 - t17*t5*z + t43*t58 + t46
    t66 = (1/2)*t25*(-2*nu*t0*t21 - 2*nu*t17*t53*t57 - t26*t41*t52 + t26*t49 - t63 - t65)
    t67 = t42*t58 + t47 + t63
    t68 = 1/np.pi
    t69 = t68*x
    t70 = t0*t69
    t71 = t0*t64
    t72 = t17*t53
    t73 = t57*t72
    t74 = t0*t23
    t75 = t24*t52
    t76 = t41*t75
    t77 = t35*t6
    t78 = (1/2)*t70
    t79 = t17*t8
    t80 = R**(-5)
    t81 = t44*t80
    t82 = 6*t37
    t83 = t29**3
    t84 = 6*t9
    t85 = t28*t5
    t86 = t84*t85
    t87 = t8*t9
    t88 = t9*z
    t89 = t85*t9
    t90 = t29*t38 - t3 + t30*t35
    t91 = t24*(-2*t88 + 2*t89 + t90)
    t92 = t27*z
    t93 = 3*t8
    t94 = t0*t8
    t95 = t5*t8
    t96 = t28*t87
    t97 = t15*t29 - t3*t94 + t35*t96 + t41 - t5*t79 + t5 - t50 + t51*t79 - t51 + t60*t95 - t92*t93
    t98 = (1/4)*t68
    t99 = t0*t5
    t100 = t10*t85 - t10*z + t29*t33 + t90 - t99
    t101 = t17*t98*y
    t102 = t101*x
    t103 = 9*t88
    t104 = t12*t29
    t105 = 6*z
    t106 = t28*t8
    t107 = 12*t3
    t108 = t28*t80
    t109 = 15*t108
    t110 = t2**(-4)
    t111 = t110*t29
    t112 = 6*t6
    t113 = t41*t8
    t114 = 6*t104*t113 + t106*t12*t84 + t107*t59*t8 + t109*t95 + t11*t51 + t111*t112*t8 - t13*t94 - t16 - t19*t3 - 15*t8*t80*z
    t115 = t1*t5 + t103 - t104*t105 + t114 - t29*t56 - 6*t31 + t55 - 9*t89
    t116 = 9*t92
    t117 = 15/R**6
    t118 = t117*t44
    t119 = t18*t5
    t120 = t117*t5*z**4
    t121 = t5*t59
    t122 = 18*t121
    t123 = t12*t82
    t124 = 6*t110*t83*z
    t125 = 9*t17*t51
    t126 = t1*t3
    t127 = t126*t32
    t128 = t3*t45
    t129 = 9*t128*t29
    t130 = t123*t30
    t131 = t28*t3*t84
    t132 = t131*t32
    t133 = 6*t104*t32*t6
    t134 = t0*t100
    t135 = -t119
    t136 = t107*t28*t9
    t137 = t104*t112 + t105*t111 + 6*t12*t30 + 15*t121 - t126 - t13 + t135 + t136 + t18*t51 - 15*t92
    t138 = nu*t25*(t0*t115 + t116 - t118 + t119 + t120 - t122 - t123 + t124 - t125 + t127 + t129 + t130 - t132 - t133 - t134 + t137*t72)
    t139 = 4*t29
    t140 = t12*t139
    t141 = 2*t17
    t142 = 6*t59
    t143 = t139*t3
    t144 = t3*t8
    t145 = 4*t12*t37
    t146 = 8*t104
    t147 = t113*t13
    t148 = t17*t4
    t149 = t110*z
    t150 = t5*t81
    t151 = t14*t58 + t141*t4*t58
    return (t70*(nu*t66 + t21*t22 + t67), t22*t69*(t66 - t71 + t73), t78*(nu*t25*(-t21*t74 - t23*t73 - t24*t49 - t34 - t58*t77 - t62 - t65 + t76) - t24*t48 - t40 - 3*t46 + t54 - t61 - t76), (1/2)*t0*t68*y*(nu*t57*t79 - nu*t71 + t22*(t0 + t20 - t4 - t7) + t67), t98*(t0*t24*t52 + 6*t0*t32*t5 - t0*t97 + 4*t12*t83*z - 6*t29*t34 - t3*t82 - t32*t86 + t74*t97 - t75*t87 - t79*t91 - 6*t81 + 6*t9*z), -t102*(t0*t75 - t100*t23 + t100 + t91), t78*(t0*t115 - t138), t78*(-t134 + t137*t17*t53 - t138), -t78*(-t116 + t118 - t120 + t122 + t123 - t124 + t125 - t127 - t129 - t130 + t132 + t133 + t135 + t138), t101*(t114 + t137*t94 - t140*z - 4*t31 + t35 - t36*t6 + t84*z - t86 + 2*t99), t0*t98*(-t106*t117 + t110*t6*t8*t82 - t116*t95 + t118*t95 - t140*t94 - t141 + t142*t144*t29 + t142 - t143*t30 + t143 + 8*t144*t81 - t145*z + t146*t96 - t147*t32 + t147*t37 + t27*t93 - t32*t4*t87 + t32*t77 - t36*t79 - t4*t8*t84 + 6*t42 - 6*t46 + t94*(-t0*t36 + t10 - t103*t5 - t109 + 7*t128 + t131*t29 + t14*t37 - t140 + t146*t30 - 5*t148 + t149*t82 + 15*t150 + t151)), t102*(-t0*t143 + 16*t104*t30 - 30*t108 + 15*t128 + t136*t29 - t14*t32 + t145*t6 - t146 - t148*t32 - 11*t148 + 12*t149*t37 + 30*t150 + t151 - 18*t5*t88 + t84))
# fmt: on


# --- closed form of the tangential Hertz traction (hamilton_sliding_sphere) -------------------------
# Generated with sympy: coefficients c_m of w^m in the numerator of the rational integrand (divided by
# the constant of its denominator C w^k (w^2 + rho^2)^4), and G_j(s) = int s^j / (s^2 + 1)^4 ds.
# fmt: off
def _hamilton_tangential_coefficients(x, y, rho, zr, a, nu):
    t0 = 7*nu
    t1 = nu**2
    t2 = 2*t1
    t3 = 1/np.pi
    t4 = (1/4)*t3
    t5 = 2*nu
    t6 = 1/(t5 - 1)
    t7 = t6*x
    t8 = t4*t7
    t9 = 8*t1
    t10 = t8*zr
    t11 = a**2
    t12 = 8*t11
    t13 = zr**2
    t14 = nu*t11
    t15 = rho**2
    t16 = 3*t15
    t17 = x**2
    t18 = 4*t17
    t19 = nu*t18
    t20 = -t19
    t21 = nu*t13
    t22 = 4*t11
    t23 = t15*t2
    t24 = t1*t18
    t25 = y**2
    t26 = 4*t25
    t27 = t1*t26
    t28 = 4*t13
    t29 = (1/2)*t3
    t30 = t29*t7
    t31 = 40*t17
    t32 = nu*t15
    t33 = 18*t32
    t34 = nu*t17
    t35 = 40*t25
    t36 = t15*t9
    t37 = t1*t17
    t38 = 32*t37
    t39 = t1*t25
    t40 = 32*t39
    t41 = t13*t32
    t42 = 16*t41
    t43 = -t42
    t44 = rho**4
    t45 = t1*t44
    t46 = 6*t45
    t47 = 11*t44
    t48 = t11*t15
    t49 = t13*t15
    t50 = t21*t25
    t51 = t11*t32
    t52 = t11*t38
    t53 = t13*t38
    t54 = t11*t40
    t55 = t13*t40
    t56 = t17*t21
    t57 = t13*t17
    t58 = t18*t32
    t59 = t14*t17
    t60 = -160*t57 + t58 + 32*t59
    t61 = t1*t15
    t62 = t26*t61
    t63 = t18*t61
    t64 = t62 - t63
    t65 = 6*t32
    t66 = t17*t65
    t67 = -16*t45
    t68 = t15*t17
    t69 = 30*t68
    t70 = nu*t44
    t71 = t11*t17
    t72 = 80*t71
    t73 = 80*t57
    t74 = t25*t32
    t75 = t15*t39
    t76 = t15*t37
    t77 = t14*t25
    t78 = 80*t50 - 80*t56 - 80*t59 - 24*t75 + 24*t76 + 80*t77
    t79 = t3*zr
    t80 = t79*x
    t81 = t6*t80
    t82 = (1/2)*t81
    t83 = t15*t22
    t84 = 20*t57
    t85 = -t58
    t86 = 20*t59
    t87 = 2*t13
    t88 = t15*t87
    t89 = -t88
    t90 = 3*t70
    t91 = -t62
    t92 = t11*t36
    t93 = t13*t36
    t94 = 20*t50 + t63
    t95 = t2*t44
    t96 = 20*t37
    t97 = 20*t39
    t98 = -t11*t96 + t11*t97 - t13*t96 + t13*t97 - t95
    t99 = t3*x
    t100 = t6*t99
    t101 = t100*t15
    t102 = t21*t31
    t103 = -t102
    t104 = t14*t31
    t105 = -t104
    t106 = t17*t36
    t107 = t15*t5
    t108 = t25*t36
    t109 = 20*t51
    t110 = 20*t41
    t111 = t14*t35
    t112 = t21*t35
    t113 = t11*t31 + t13*t31 + 2*t68
    t114 = t15*t82
    t115 = -t70
    t116 = 4*t44
    t117 = 8*t32
    t118 = t117*t17
    t119 = -t118 + 64*t57 + 64*t59
    t120 = 64*t37
    t121 = 32*t61
    t122 = 64*t39
    t123 = t106 - t108
    t124 = -t11*t120 + t11*t121 + t11*t122 - t120*t13 + t121*t13 + t122*t13 + t123
    t125 = t44*t8
    t126 = 12*t68
    t127 = 12*t74
    t128 = -9*t44
    t129 = 12*t11
    t130 = t129*t15
    t131 = 12*t13
    t132 = t131*t15
    t133 = 16*t71
    t134 = 16*t57
    t135 = t17*t32
    t136 = t12*t32
    t137 = t117*t13
    t138 = t136 + t137 + 24*t45 + 16*t50 - 16*t56 - 16*t59 + 48*t75 - 48*t76 + 16*t77
    t139 = t10*t44
    t140 = -t11*t65
    t141 = t49*t5
    t142 = -t141
    t143 = 6*t13
    t144 = t143*t15
    t145 = 8*t57
    t146 = t12*t34
    t147 = t145 + t146 + 8*t50
    t148 = t71*t9
    t149 = t57*t9
    t150 = t11*t25
    t151 = t13*t25
    t152 = t150*t9 + t151*t9
    t153 = -t148 - t149 + t152 + t22*t61 + t28*t61 + t64 + t95
    t154 = rho**6
    t155 = t154*t30
    t156 = nu*t26
    t157 = -t16 + t18
    t158 = t36 - 16*t37 + 16*t39
    t159 = rho**8
    t160 = t10*t159
    t161 = t107 + t156 + t20
    t162 = rho**10
    t163 = t162*t4
    t164 = nu*t163
    t165 = t164*t7
    t166 = -t143
    t167 = -t15
    t168 = 24*t14
    t169 = nu*t25
    t170 = 24*t21
    t171 = 64*t61
    t172 = t26*t32
    t173 = t172 + t63 + t91
    t174 = 16*t51
    t175 = 16*t49
    t176 = t174 + t175
    t177 = 3*t44
    t178 = -t177
    t179 = t15*t25
    t180 = t25*t65
    t181 = 14*t48 + 14*t49
    t182 = 20*t56
    t183 = 20*t77
    t184 = 16*t61
    t185 = t48*t5
    t186 = t185 + t88
    t187 = -t112
    t188 = -t111
    t189 = 10*t13
    t190 = -t15*t189 - 10*t48
    t191 = -t109 - t110
    t192 = 5*t70
    t193 = 64*t56
    t194 = 12*t135
    t195 = t15*t28
    t196 = t195 + t83
    t197 = t177 + t196
    t198 = 8*t151
    t199 = t12*t169
    t200 = t143*t32
    t201 = 8*t56
    t202 = t186 - t201
    t203 = t15 - t26
    t204 = 9*t15
    t205 = t129 + t131
    t206 = -t137
    t207 = 24*t49
    t208 = t103 + t187
    t209 = 5*t61
    t210 = 5*t37
    t211 = 5*t39
    t212 = t182 + t86
    t213 = t135 + t74
    t214 = t100*t5
    t215 = 12*t70
    t216 = 4*t32
    t217 = t167 + t17 + t25
    t218 = t4*y
    t219 = t218*zr
    t220 = t29*y
    t221 = -t174 + t43 + t70
    t222 = -nu*t116
    t223 = (1/2)*t79
    t224 = 2*t11
    t225 = t15*t224
    t226 = t70 + t85
    t227 = t15*y
    t228 = 2*t44
    t229 = t15 - t18
    t230 = (3/2)*t79
    t231 = t4*(t131 + t167 + t22)
    t232 = t79*(t11 + t13 - 3*t17)
    t233 = t29*(t144 + t225 - t44 - 48*t57)
    t234 = t80*y
    t235 = 6*t234
    t236 = t99*y
    return {
        "c00_12": -t8*(t0 + t2 - 4),
        "c00_11": t10*(46*nu + t9 - 25),
        "c00_10": -t30*(nu*t16 + t1*t22 + t1*t28 - t12 - 26*t13 + 14*t14 + t20 + 50*t21 - t23 + t24 - t27),
        "c00_9": t10*(nu*t35 - 36*t11 - 36*t13 + 72*t14 - 19*t15 + 72*t21 + t31 + t33 - 72*t34 - t36 + t38 - t40),
        "c00_8": t8*(nu*t47 + t43 - 8*t44 + t46 + 32*t48 + 80*t49 - 160*t50 - 80*t51 - t52 - t53 + t54 + t55 + 192*t56 + t60 + t64),
        "c00_7": t82*(t22*t32 + t28*t32 + 17*t44 - 42*t48 - 42*t49 + t66 + t67 - t69 + 16*t70 + t72 + t73 - 30*t74 + t78),
        "c00_6": t101*(-30*t41 - 22*t51 + t83 + t84 + t85 + t86 + t89 + t90 + t91 + t92 + t93 + t94 + t98),
        "c00_5": t114*(t103 + t105 - t106 + t107*t25 + t108 + t109 + t110 + t111 + t112 + t113 + t47 - 30*t48 - 30*t49 + t66 - 28*t70),
        "c00_4": t125*(t115 + t116 + t119 + t124 + t43 - t46 - 48*t49 + 64*t50 - 48*t51),
        "c00_3": t139*(t126 + t127 + t128 - t130 - t132 + t133 + t134 + 36*t135 + t138 - 30*t70),
        "c00_2": t155*(t140 + t142 - t144 + t147 + t153 + t58 - t90),
        "c00_1": t160*(t156 + t157 + t158 - 10*t32 + 12*t34),
        "c00_0": t165*(t157 + t161),
        "c11_12": -3/4*nu*t99,
        "c11_11": -3/4*t81*(t5 - t9 + 1),
        "c11_10": -t30*(nu*t143 + t1*t129 + t1*t131 - 6*t14 - t156 + t166 + t23 - t24 + t27 + t32),
        "c11_9": t10*(nu*t31 - t129 - t131 + t167 + t168 - 72*t169 + t170 - 42*t32 + t35 - t38 + t40 + 40*t61),
        "c11_8": t8*(-t0*t44 - t11*t171 - t13*t171 - 160*t151 + t173 + t176 + 144*t41 + 10*t45 + 192*t50 + t52 + t53 - t54 - t55 - 160*t56 + 32*t77),
        "c11_7": -t82*(30*t135 - 80*t150 - 80*t151 + t178 + 30*t179 - t180 + t181 + 52*t41 + 52*t51 - 36*t70 + t78),
        "c11_6": -t101*(t11*t184 + t115 + t13*t184 + t13*t33 - 20*t151 + t173 - t182 - t183 + t186 + t98),
        "c11_5": t114*(t102 + t104 + t11*t35 + t123 + t13*t35 + 2*t179 + t180 + t187 + t188 + t190 + t191 + t44 + t5*t68 + t67),
        "c11_4": -t125*(t117*t25 + t124 - 64*t151 + t176 - t192 - t193 + 48*t41 - 64*t77 + t95),
        "c11_3": -t139*(t138 - 16*t150 - 16*t151 - 12*t179 - t194 + t197 + 18*t70 - 36*t74),
        "c11_2": -t155*(t153 - t172 - t198 - t199 + t200 + t202 + t70),
        "c11_1": -t160*(t158 - 12*t169 + t20 + t203 + t65),
        "c11_0": -t165*(t161 + t203),
        "c22_11": -3*t80,
        "c22_10": 2*t100*(nu*t131 + t166 + t37 + t39 - t61),
        "c22_9": t81*(t117 - t168 + 10*t169 - t17*t9 - t170 - t204 + t205 - t25*t9 + 10*t34 + t36),
        "c22_8": t100*(t148 + t149 + t152 + t206 + t207 + t208 - t45 + t75 + t76 - t92 - t93),
        "c22_7": -t81*(t105 + t128 + t130 + t132 + 15*t135 + t174 + t188 + t208 + t42 - 12*t45 + 15*t74 + 12*t75 + 12*t76 + t90),
        "c22_6": 4*t101*(-t11*t209 + t11*t210 + t11*t211 - t13*t16 - t13*t209 + t13*t210 + t13*t211 + t41 + t45 + 5*t50 + 5*t56 - t75 - t76),
        "c22_5": t15*t81*(-t1*t116 + t178 + t183 + t191 + t192 + t212 + t213 + t62 + t94),
        "c22_4": t214*t44*(-t135 - t136 + t147 + t198 + t199 + t201 + t206 - 8*t49 + t70 - t74),
        "c22_3": t70*t81*(t11*t18 + t11*t26 + t127 + t13*t18 + t13*t26 + t16*t17 + t16*t25 + t178 + t194 - t195 - t215 - t83),
        "c22_2": t154*t214*(t115 + t142 + t150*t5 + t151*t5 + t17*t87 - t185 + t213 + t25*t87 + t5*t57 + t5*t71 + t89),
        "c22_1": nu*t159*t81*(t156 + t19 - t216 + t217),
        "c22_0": t1*t100*t162*t217,
        "c01_12": t218*(nu - 2),
        "c01_11": -t219*(4*nu - 11),
        "c01_10": t220*(t11*t5 + t13*t5 - t189 + t20 - t22 + t32),
        "c01_9": t219*(t204 + t205 - t31 - 12*t32 + 32*t34),
        "c01_8": -t218*(-t116 + t221 + 16*t48 + 32*t49 + 32*t56 + t60),
        "c01_7": t223*y*(24*t135 + t181 + t222 - 7*t44 + t69 - t72 - t73),
        "c01_6": -t227*t3*(t140 - t200 + t212 + t225 + t226 + t84),
        "c01_5": -t223*t227*(t113 + t118 + t190 + t222 + 5*t44),
        "c01_4": -t218*t44*(t119 - t175 + t193 + t221 + t228),
        "c01_3": t219*t44*(-t126 - t133 - t134 - 48*t135 + t197 + t215),
        "c01_2": t154*t220*(t141 - t145 - t146 + t202 + t226),
        "c01_1": t159*t219*(t216 + t229 - 16*t34),
        "c01_0": t164*t229*y,
        "c02_10": -t4,
        "c02_9": t230,
        "c02_8": -t231,
        "c02_7": 2*t232,
        "c02_6": -t233,
        "c02_5": t79*(t126 + t178 + t196 - 24*t57 - 24*t71),
        "c02_4": t15*t233,
        "c02_3": t228*t232,
        "c02_2": t154*t231,
        "c02_1": t159*t230,
        "c02_0": t163,
        "c12_5": -t235,
        "c12_4": 24*t13*t236,
        "c12_3": -12*t234*(t167 + t224 + t87),
        "c12_2": -t207*t236,
        "c12_1": -t235*t44,
    }


def _antiderivative_g(j, s):
    """G_j(s) = integral of s^j / (s^2 + 1)^4 ds (principal branches; Re s > 0 on the path)."""
    if j == -5:
        return 10*np.log(s) - 5*np.log(s**2 + 1) + (60*s**8 + 150*s**6 + 110*s**4 + 15*s**2 - 3)/(12*s**10 + 36*s**8 + 36*s**6 + 12*s**4)
    if j == -4:
        return (105/16)*np.arctan(s) + (315*s**8 + 840*s**6 + 693*s**4 + 144*s**2 - 16)/(48*s**9 + 144*s**7 + 144*s**5 + 48*s**3)
    if j == -3:
        return (-12*s**6 - 30*s**4 - 22*s**2 - 3)/(6*s**8 + 18*s**6 + 18*s**4 + 6*s**2) - 4*np.log(s) + 2*np.log(s**2 + 1)
    if j == -2:
        return (-105*s**6 - 280*s**4 - 231*s**2 - 48)/(48*s**7 + 144*s**5 + 144*s**3 + 48*s) - 35/16*np.arctan(s)
    if j == -1:
        return (6*s**4 + 15*s**2 + 11)/(12*s**6 + 36*s**4 + 36*s**2 + 12) + np.log(s) - 1/2*np.log(s**2 + 1)
    if j == 0:
        return (15*s**5 + 40*s**3 + 33*s)/(48*s**6 + 144*s**4 + 144*s**2 + 48) + (5/16)*np.arctan(s)
    if j == 1:
        return -1/(6*s**6 + 18*s**4 + 18*s**2 + 6)
    if j == 2:
        return (3*s**5 + 8*s**3 - 3*s)/(48*s**6 + 144*s**4 + 144*s**2 + 48) + (1/16)*np.arctan(s)
    if j == 3:
        return (-3*s**2 - 1)/(12*s**6 + 36*s**4 + 36*s**2 + 12)
    if j == 4:
        return (3*s**5 - 8*s**3 - 3*s)/(48*s**6 + 144*s**4 + 144*s**2 + 48) + (1/16)*np.arctan(s)
    if j == 5:
        return (-3*s**4 - 3*s**2 - 1)/(6*s**6 + 18*s**4 + 18*s**2 + 6)
    if j == 6:
        return (-33*s**5 - 40*s**3 - 15*s)/(48*s**6 + 144*s**4 + 144*s**2 + 48) + (5/16)*np.arctan(s)
    if j == 7:
        return (18*s**4 + 27*s**2 + 11)/(12*s**6 + 36*s**4 + 36*s**2 + 12) + (1/2)*np.log(s**2 + 1)
    if j == 8:
        return s + (87*s**5 + 136*s**3 + 57*s)/(48*s**6 + 144*s**4 + 144*s**2 + 48) - 35/16*np.arctan(s)
    raise ValueError(j)


_HAMILTON_TANGENTIAL_TERMS = {
    (0, 0): [('c00_12', 7), ('c00_11', 6), ('c00_10', 5), ('c00_9', 4), ('c00_8', 3), ('c00_7', 2), ('c00_6', 1), ('c00_5', 0), ('c00_4', -1), ('c00_3', -2), ('c00_2', -3), ('c00_1', -4), ('c00_0', -5)],
    (1, 1): [('c11_12', 7), ('c11_11', 6), ('c11_10', 5), ('c11_9', 4), ('c11_8', 3), ('c11_7', 2), ('c11_6', 1), ('c11_5', 0), ('c11_4', -1), ('c11_3', -2), ('c11_2', -3), ('c11_1', -4), ('c11_0', -5)],
    (2, 2): [('c22_11', 6), ('c22_10', 5), ('c22_9', 4), ('c22_8', 3), ('c22_7', 2), ('c22_6', 1), ('c22_5', 0), ('c22_4', -1), ('c22_3', -2), ('c22_2', -3), ('c22_1', -4), ('c22_0', -5)],
    (0, 1): [('c01_12', 7), ('c01_11', 6), ('c01_10', 5), ('c01_9', 4), ('c01_8', 3), ('c01_7', 2), ('c01_6', 1), ('c01_5', 0), ('c01_4', -1), ('c01_3', -2), ('c01_2', -3), ('c01_1', -4), ('c01_0', -5)],
    (0, 2): [('c02_10', 8), ('c02_9', 7), ('c02_8', 6), ('c02_7', 5), ('c02_6', 4), ('c02_5', 3), ('c02_4', 2), ('c02_3', 1), ('c02_2', 0), ('c02_1', -1), ('c02_0', -2)],
    (1, 2): [('c12_5', 5), ('c12_4', 4), ('c12_3', 3), ('c12_2', 2), ('c12_1', 1)],
}
# fmt: on
