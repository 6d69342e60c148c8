"""Contact of an axisymmetric power-law asperity with an elastic half-space (thesis 5.5.2).

The atomic-subscale asperities of a nanoblock are approximated by the monomial shape
f(r) = B_d r^d (5-6) (d = 4 looks like a flat punch with rounded edges). The frictionless
contact of such a punch with an elastic half-space has an exact solution for any degree
d > 0 (Galin 1953/1961, Sneddon 1965, Borodich 2014): with

.. math::

    \\kappa_d = \\frac{\\sqrt{\\pi}\\,\\Gamma(d/2 + 1)}{\\Gamma(d/2 + 1/2)},

the approach is :math:`\\delta = \\kappa_d B a^d`, the load
:math:`P = 2 E^* B \\kappa_d \\frac{d}{d+1} a^{d+1}` and the pressure

.. math::

    p(r) = \\frac{E^* d \\kappa_d B a^{d-1}}{\\pi}\\sqrt{1 - \\rho^2}\\;
           {}_2F_1\\!\\left(1 - \\tfrac{d}{2}, 1; \\tfrac{3}{2}; 1 - \\rho^2\\right),
    \\qquad \\rho = r / a,

which for d = 2, B = 1/(2R) is Hertz's solution. The pressure at the centre is finite for
d > 1 and infinite (integrable) for d <= 1; for d > 2 its maximum lies off the centre.

The module also distributes the load of one nanoblock over its m x m atomic asperities
with their mutual elastic influence (:func:`nanoblock_load_sharing`), the loads from which
the damage model (:mod:`memstribo.physics.damage`) starts (thesis Table 5-1).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import ConvergenceError, InputError
from memstribo.references import cites

__all__ = [
    "PowerLawContact",
    "LoadSharing",
    "power_law_factor",
    "power_law_contact",
    "power_law_contact_radius",
    "power_law_pressure",
    "power_law_max_pressure",
    "asperity_positions",
    "nanoblock_load_sharing",
    "position_classes",
]


def _check_degree(degree) -> float:
    try:
        d = float(degree)
    except (TypeError, ValueError):
        raise InputError(f"degree d of the power-law asperity must be a number > 0, got {degree!r}.") from None
    if not math.isfinite(d) or d <= 0:
        raise InputError(f"degree d of the power-law asperity must be a finite number > 0, got {degree!r}.")
    return d


def power_law_factor(degree: float) -> float:
    """Galin's factor kappa_d = sqrt(pi) Gamma(d/2 + 1) / Gamma(d/2 + 1/2) [-].

    The approach of a power-law punch f(r) = B r^d is kappa_d B a^d (kappa_2 = 2, Hertz).

    Parameters
    ----------
    degree : float
        Degree d > 0 of the monomial shape [-].

    Returns
    -------
    float
        kappa_d [-].
    """
    from scipy.special import gammaln

    d = _check_degree(degree)
    return float(math.sqrt(math.pi) * math.exp(gammaln(d / 2 + 1) - gammaln(d / 2 + 0.5)))


@dataclass(frozen=True)
class PowerLawContact:
    """Frictionless contact of a power-law punch f(r) = B r^d with an elastic half-space.

    Attributes
    ----------
    load : float or ndarray
        Normal load P [N].
    degree : float
        Degree d of the shape [-].
    shape_coefficient : float
        B_d [m^(1-d)].
    contact_modulus : float
        E* [Pa].
    contact_radius : float or ndarray
        Radius a of the contact circle [m].
    approach : float or ndarray
        Rigid-body approach (indentation depth) delta [m].
    max_pressure : float or ndarray
        Largest contact pressure [Pa] (``inf`` for d <= 1: singular at the centre).
    max_pressure_radius : float or ndarray
        Radius at which the pressure is largest [m] (0 for d <= 2).
    mean_pressure : float or ndarray
        P / (pi a^2) [Pa].
    """

    load: float | np.ndarray
    degree: float
    shape_coefficient: float
    contact_modulus: float
    contact_radius: float | np.ndarray
    approach: float | np.ndarray
    max_pressure: float | np.ndarray
    max_pressure_radius: float | np.ndarray
    mean_pressure: float | np.ndarray


def _load_factor(degree: float, shape_coefficient: float, modulus: float) -> float:
    """K in P = K a^(d+1): 2 E* B kappa_d d / (d + 1) [N m^-(d+1)]."""
    return 2.0 * modulus * shape_coefficient * power_law_factor(degree) * degree / (degree + 1.0)


@cites("galin_1961", "sneddon_1965", "borodich_2014", "thesis")
def power_law_contact_radius(load, degree: float, shape_coefficient: float, contact_modulus: float):
    """Contact radius of a power-law punch, a = (P / K)^(1/(d+1)) [m].

    Parameters
    ----------
    load : numeric
        Normal load P > 0 [N].
    degree : float
        Degree d > 0 of the shape f(r) = B r^d (5-6) [-].
    shape_coefficient : float
        B_d > 0 [m^(1-d)] (the thesis's B_4 = 4e22 m^-3).
    contact_modulus : float
        E* [Pa].

    Returns
    -------
    numeric
        a [m], same shape as ``load``.

    Notes
    -----
    .. math:: P = 2 E^* B \\kappa_d \\frac{d}{d+1} a^{d+1}

    (Sneddon 1965, Eq. (6.5)-(6.6) in [1]_; Borodich 2014 [2]_). d = 2, B = 1/(2R) gives
    Hertz's a^3 = 3PR/(4E*).

    References
    ----------
    .. [1] I. N. Sneddon, Int. J. Eng. Sci. 3 (1965) 47-57. doi:10.1016/0020-7225(65)90019-4
    .. [2] F. M. Borodich, Adv. Appl. Mech. 47 (2014) 225-366.
    """
    d = _check_degree(degree)
    as_array(load, "load", "N", positive=True)
    as_array(shape_coefficient, "shape_coefficient B", "m^(1-d)", positive=True)
    as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    factor = _load_factor(d, float(shape_coefficient), float(contact_modulus))
    return (np.asarray(load, dtype=float) / factor) ** (1.0 / (d + 1.0))


def _normalised_pressure(rho, degree: float) -> np.ndarray:
    """sqrt(1 - rho^2) 2F1(1 - d/2, 1; 3/2; 1 - rho^2), zero outside rho < 1."""
    from scipy.special import hyp2f1

    rho = np.abs(np.asarray(rho, dtype=float))
    inside = rho < 1.0
    z = np.where(inside, 1.0 - rho ** 2, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        shape = np.sqrt(z) * hyp2f1(1.0 - degree / 2.0, 1.0, 1.5, z)
    if degree <= 1.0:
        shape = np.where(inside & (rho == 0.0), np.inf, shape)
    return np.where(inside, shape, 0.0)


@functools.lru_cache(maxsize=64)
def _normalised_maximum(degree: float) -> tuple[float, float]:
    """(rho at the maximum, maximum) of the normalised pressure shape for d > 1."""
    from scipy.optimize import minimize_scalar

    if degree <= 2.0:  # monotonically decreasing from the centre
        return 0.0, float(_normalised_pressure(0.0, degree))
    grid = np.linspace(0.0, 0.999, 1000)
    values = _normalised_pressure(grid, degree)
    i = int(np.argmax(values))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    best = minimize_scalar(lambda r: -float(_normalised_pressure(r, degree)), bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-10})
    return float(best.x), float(-best.fun)


def _pressure_scale(degree, shape_coefficient, modulus, radius):
    return modulus * degree * power_law_factor(degree) * shape_coefficient * radius ** (degree - 1.0) / math.pi


@cites("galin_1961", "sneddon_1965", "borodich_2014", "thesis")
def power_law_pressure(r, load, degree: float, shape_coefficient: float, contact_modulus: float):
    """Contact pressure p(r) under a power-law punch [Pa] (Galin's solution).

    Parameters
    ----------
    r : numeric
        Radial distance from the contact centre [m]; broadcast against ``load``.
    load : numeric
        Normal load P > 0 [N].
    degree : float
        Degree d > 0 of the shape f(r) = B r^d (5-6) [-].
    shape_coefficient : float
        B_d > 0 [m^(1-d)].
    contact_modulus : float
        E* [Pa].

    Returns
    -------
    numeric
        p(r) [Pa]; 0 outside the contact circle, ``inf`` at r = 0 for d <= 1.

    Notes
    -----
    .. math::

        p(r) = \\frac{E^*}{\\pi}\\int_r^a \\frac{g'(s)}{\\sqrt{s^2 - r^2}}\\,ds,\\quad g(s) = \\kappa_d B s^d,

    which integrates to the hypergeometric form in the module docstring (Galin 1961 [1]_,
    Borodich 2014 [2]_). d = 2 gives Hertz's p0 sqrt(1 - r^2/a^2).

    References
    ----------
    .. [1] L. A. Galin, Contact Problems in the Theory of Elasticity, 1961.
    .. [2] F. M. Borodich, Adv. Appl. Mech. 47 (2014) 225-366.
    """
    d = _check_degree(degree)
    a = power_law_contact_radius(load, d, shape_coefficient, contact_modulus)
    r = np.asarray(r, dtype=float)
    scale = _pressure_scale(d, float(shape_coefficient), float(contact_modulus), a)
    with np.errstate(invalid="ignore"):
        return scale * _normalised_pressure(r / a, d)


@cites("galin_1961", "borodich_2014")
def power_law_max_pressure(load, degree: float, shape_coefficient: float, contact_modulus: float):
    """Largest contact pressure under a power-law punch [Pa] and the radius where it acts [m].

    Parameters
    ----------
    load : numeric
        Normal load P > 0 [N].
    degree : float
        Degree d > 0 [-].
    shape_coefficient : float
        B_d [m^(1-d)].
    contact_modulus : float
        E* [Pa].

    Returns
    -------
    (numeric, numeric)
        Maximum pressure [Pa] (``inf`` for d <= 1, singular centre) and its radius [m]
        (0 for d <= 2; inside the contact, off the centre, for d > 2).
    """
    d = _check_degree(degree)
    a = power_law_contact_radius(load, d, shape_coefficient, contact_modulus)
    if d <= 1.0:
        return np.full_like(a, np.inf), np.zeros_like(a)
    rho_max, shape_max = _normalised_maximum(d)
    return _pressure_scale(d, float(shape_coefficient), float(contact_modulus), a) * shape_max, rho_max * a


@cites("galin_1961", "sneddon_1965", "borodich_2014", "thesis")
def power_law_contact(load, degree: float, shape_coefficient: float, contact_modulus: float) -> PowerLawContact:
    """Contact radius, approach, maximum and mean pressure of a power-law asperity.

    Parameters
    ----------
    load : numeric
        Normal load P > 0 [N].
    degree : float
        Degree d > 0 of the shape f(r) = B r^d, Eq. (5-6) in [1]_ [-].
    shape_coefficient : float
        B_d > 0 [m^(1-d)] (thesis: B_4 = 4e22 m^-3).
    contact_modulus : float
        E* [Pa].

    Returns
    -------
    PowerLawContact

    Notes
    -----
    a from P = 2E*B kappa_d d/(d+1) a^(d+1), approach delta = kappa_d B a^d
    (Galin [2]_, Sneddon [3]_). For the thesis's corner asperity (0.8275 uN, d = 4,
    B_4 = 4e22 m^-3, E* = 84.996 GPa) a = 8.938 nm; Table 5-2 of [1]_ prints 8.95 nm.

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, section 5.5.2.
    .. [2] L. A. Galin, Contact Problems in the Theory of Elasticity, 1961.
    .. [3] I. N. Sneddon, Int. J. Eng. Sci. 3 (1965) 47-57.

    Examples
    --------
    >>> c = power_law_contact(0.8275e-6, 4, 4e22, 84.996e9)
    >>> round(c.contact_radius * 1e9, 3)
    8.938
    """
    d = _check_degree(degree)
    a = power_law_contact_radius(load, d, shape_coefficient, contact_modulus)
    load_array = np.asarray(load, dtype=float)
    approach = power_law_factor(d) * float(shape_coefficient) * a ** d
    p_max, r_max = power_law_max_pressure(load, d, shape_coefficient, contact_modulus)
    mean = load_array / (math.pi * a ** 2)

    def out(x):
        return float(x) if np.ndim(x) == 0 else x

    return PowerLawContact(out(load_array), d, float(shape_coefficient), float(contact_modulus), out(a),
                           out(approach), out(p_max), out(r_max), out(mean))


def _approach_from_load(load, degree, shape_coefficient, modulus):
    """Own approach of an asperity, kappa B (P/K)^(d/(d+1)), and its derivative d delta/dP."""
    factor = _load_factor(degree, shape_coefficient, modulus)
    kb = power_law_factor(degree) * shape_coefficient
    a = (load / factor) ** (1.0 / (degree + 1.0))
    delta = kb * a ** degree
    return delta, degree / (degree + 1.0) * delta / load


# --- load sharing inside a nanoblock ------------------------------------------------------------


def asperity_positions(per_side: int, pitch: float) -> np.ndarray:
    """Centres (x, y) [m] of the m x m atomic asperities of a nanoblock, shape (m*m, 2).

    Row-major: index i*m + j is row i, column j; the block's centre is the origin.
    """
    if int(per_side) != per_side or per_side < 1:
        raise InputError(f"atomic_per_side must be an integer >= 1, got {per_side!r}.")
    as_array(pitch, "atomic_pitch", "m", positive=True)
    m = int(per_side)
    coords = (np.arange(m) - (m - 1) / 2.0) * pitch
    yy, xx = np.meshgrid(coords, coords, indexing="ij")
    return np.column_stack([xx.ravel(), yy.ravel()])


def position_classes(per_side: int) -> np.ndarray:
    """'corner', 'side' or 'central' for each asperity of an m x m nanoblock (row-major)."""
    m = int(per_side)
    i, j = np.divmod(np.arange(m * m), m)
    edges = (i == 0).astype(int) + (i == m - 1) + (j == 0) + (j == m - 1)
    if m == 1:
        return np.array(["central"])
    return np.where(edges >= 2, "corner", np.where(edges == 1, "side", "central"))


@dataclass(frozen=True)
class LoadSharing:
    """Loads of the atomic asperities of one nanoblock pressed by a rigid adhesive block.

    Attributes
    ----------
    block_load : ndarray
        Load of the nanoblock [N], shape (n_loads,).
    loads : ndarray
        Load of each asperity [N], shape (n_loads, m*m), row-major.
    shares : ndarray
        loads / block_load [-].
    approach : ndarray
        Common approach of the rigid block [m], shape (n_loads,).
    positions : ndarray
        Asperity centres (x, y) [m], shape (m*m, 2).
    classes : ndarray of str
        'corner', 'side' or 'central' per asperity.
    iterations : int
        Newton iterations used.
    residual : float
        Largest relative mismatch of the approach compatibility [-].
    """

    block_load: np.ndarray
    loads: np.ndarray
    shares: np.ndarray
    approach: np.ndarray
    positions: np.ndarray
    classes: np.ndarray
    iterations: int
    residual: float

    def share_of(self, position: str) -> np.ndarray:
        """Mean share [-] of the asperities of one class ('corner', 'side', 'central'), per load."""
        mask = self.classes == position
        if not mask.any():
            raise InputError(f"no '{position}' asperity in a {int(math.isqrt(self.classes.size))}-per-side nanoblock.")
        return self.shares[:, mask].mean(axis=1)

    def load_of(self, position: str) -> np.ndarray:
        """Mean load [N] of the asperities of one class, per block load."""
        return self.share_of(position) * self.block_load


def _point_load_influence(positions, contact_modulus):
    """Boussinesq displacement [m/N] of each asperity under a unit load on each other one, 1/(pi E* s_ij)."""
    distance = np.linalg.norm(positions[:, None, :] - positions[None, :, :], axis=-1)
    influence = np.zeros_like(distance)
    off = distance > 0
    influence[off] = 1.0 / (math.pi * contact_modulus * distance[off])
    return influence


@cites("sneddon_1965", "johnson_1985", "thesis")
def nanoblock_load_sharing(block_load, per_side: int, pitch: float, degree: float, shape_coefficient: float,
                           contact_modulus: float, *, tolerance: float = 1e-12,
                           max_iterations: int = 50) -> LoadSharing:
    """Distribute a nanoblock's load over its m x m power-law asperities (thesis Table 5-1).

    A rigid adhesive block pushes all asperities (of equal height) through one approach
    delta; each asperity sinks by its own power-law compliance plus the Boussinesq
    displacement caused by the other asperities' loads:

    .. math::

        \\kappa_d B \\left(P_i / K\\right)^{d/(d+1)} + \\sum_{j \\neq i} \\frac{P_j}{\\pi E^* s_{ij}} = \\delta,
        \\qquad \\sum_i P_i = W,

    solved by Newton's method, vectorised over the block loads W.

    Parameters
    ----------
    block_load : numeric
        Load of the nanoblock W > 0 [N]; a 1-D array gives one solution per load.
    per_side : int
        Asperities per side m [-].
    pitch : float
        Centre-to-centre distance s of neighbouring asperities [m].
    degree : float
        Degree d of the asperity shape [-].
    shape_coefficient : float
        B_d [m^(1-d)].
    contact_modulus : float
        E* [Pa].
    tolerance : float
        Relative tolerance of the approach compatibility [-].
    max_iterations : int
        Newton iterations allowed.

    Returns
    -------
    LoadSharing

    Raises
    ------
    ConvergenceError
        If Newton's method does not reach ``tolerance`` (not seen for physical inputs).

    Notes
    -----
    The cross-influence uses the point-load (Boussinesq) displacement u = P/(pi E* s),
    Eq. (3.22) in [1]_; the first correction for a pressure spread over the contact circle is
    <r^2>/(4 s^2) of it (d = 4: <r^2> = 0.476 a^2), 0.3 % for a = 8.9 nm, s = 58.4 nm. Corner asperities have the fewest neighbours,
    sink least under the others' loads and so carry most; the shares depend weakly on
    the load because the asperity law is non-linear.

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985.
    """
    d = _check_degree(degree)
    loads_total = np.atleast_1d(as_array(block_load, "block_load", "N", positive=True)).astype(float)
    if loads_total.ndim != 1:
        raise InputError("block_load must be a number or a 1-D list of loads.")
    as_array(shape_coefficient, "shape_coefficient B", "m^(1-d)", positive=True)
    as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    positions = asperity_positions(per_side, pitch)
    n = positions.shape[0]
    influence = _point_load_influence(positions, contact_modulus)
    shares = np.full((loads_total.size, n), 1.0 / n)
    p = shares * loads_total[:, None]
    eye = np.eye(n)
    residual = np.inf
    for iteration in range(1, max_iterations + 1):
        own, slope = _approach_from_load(p, d, float(shape_coefficient), float(contact_modulus))
        total = own + p @ influence.T
        delta = (total * (1.0 / slope)).sum(axis=1) / (1.0 / slope).sum(axis=1)  # a fair mean approach
        # Newton on (P, delta): J = [[diag(slope) + C, -1], [1^T, 0]]
        jac = np.zeros((loads_total.size, n + 1, n + 1))
        jac[:, :n, :n] = slope[:, :, None] * eye + influence
        jac[:, :n, n] = -1.0
        jac[:, n, :n] = 1.0
        rhs = np.concatenate([-(total - delta[:, None]), (loads_total - p.sum(axis=1))[:, None]], axis=1)
        step = np.linalg.solve(jac, rhs[..., None])[..., 0]
        dp = step[:, :n]
        # damping keeps every load positive
        ratio = np.where(dp < 0, -0.9 * p / np.where(dp < 0, dp, -1.0), np.inf)
        alpha = np.minimum(1.0, ratio.min(axis=1))
        p = p + alpha[:, None] * dp
        own, _ = _approach_from_load(p, d, float(shape_coefficient), float(contact_modulus))
        total = own + p @ influence.T
        scale = total.mean(axis=1, keepdims=True)
        residual = float(np.max(np.abs(total - scale) / scale))
        if residual < tolerance:
            break
    else:
        raise ConvergenceError(f"nanoblock load sharing did not converge in {max_iterations} iterations "
                               f"(residual {residual:.3g}).")
    approach = total.mean(axis=1)
    return LoadSharing(loads_total, p, p / loads_total[:, None], approach, positions, position_classes(per_side),
                       iteration, residual)
