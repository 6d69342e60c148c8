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
from memstribo.physics._stress_kernels import (_HAMILTON_TANGENTIAL_TERMS, _antiderivative_g, _boussinesq_kernels,
                                               _cerruti_kernels, _hamilton_tangential_coefficients)
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
