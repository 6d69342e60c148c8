"""Damage accumulation in the SAM coating, coating life and the cycles until stiction returns (thesis 5.5).

The modified Goryacheva-Torskaya model of the thesis (5.5.1-5.5.2): the coating on an atomic
asperity accumulates damage omega (Rabotnov; 0 intact, 1 worn through) at each point x along
the sliding direction, by linear summation over the load peaks i of a meshing cycle,

.. math:: \\omega(x, k) = \\sum_{i=1}^{k} c_1 \\left(\\Delta\\tau_{1,i}(x)\\right)^m \\qquad (5\\text{-}10)

where Delta tau_1,i(x) is the amplitude of the principal shear stress at x in load cycle i,
computed under the power-law asperity's contact pressure p (:mod:`memstribo.physics.asperity`) with
the friction traction mu p (:mod:`memstribo.physics.stresses`). c1 [Pa^-m] and m are phenomenological.

The chain: nanoblock load peaks (from the meshing simulation's ``block_load`` or a given
list, thesis Table 5-1) -> loads of the m x m atomic asperities with their mutual influence
(:func:`memstribo.physics.asperity.nanoblock_load_sharing`) -> tau_1 along x through each asperity's
centre -> omega/c1 per meshing cycle for every asperity -> relative lives, and with c1 the
cycles to coating failure, the worn fraction Omega(N), COF(N) and the cycle at which the
friction force reaches the available tangential force (stiction returns).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from memstribo.materials.pair import contact_modulus_of
from memstribo.physics.asperity import (
    _pressure_scale,
    nanoblock_load_sharing,
    position_classes,
    power_law_contact_radius,
)
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "POSITIONS",
    "DamageResult",
    "DamageOutcome",
    "normalised_principal_shear",
    "surface_stresses",
    "principal_shear_profile",
    "damage_sum",
    "cyclic_peak_loads",
    "load_peaks",
    "nanoblock_damage",
    "mesh_damage",
    "cycles_to_failure",
    "calibrate_damage_coefficient",
    "damage_after",
    "worn_fraction",
    "cycles_to_stiction",
    "run_damage",
]

POSITIONS = ("corner", "side", "central")


def _check_exponent(damage_exponent) -> float:
    try:
        m = float(damage_exponent)
    except (TypeError, ValueError):
        raise InputError(f"damage_exponent m must be a number > 0, got {damage_exponent!r}.") from None
    if not math.isfinite(m) or m <= 0:
        raise InputError(f"damage_exponent m must be a finite number > 0, got {damage_exponent!r}.")
    return m


def _check_coefficient(damage_coefficient) -> float:
    try:
        c1 = float(damage_coefficient)
    except (TypeError, ValueError):
        raise InputError(f"damage_coefficient c1 must be a number > 0 [Pa^-m], got {damage_coefficient!r}.") from None
    if not math.isfinite(c1) or c1 <= 0:
        raise InputError(f"damage_coefficient c1 must be a finite number > 0 [Pa^-m], got {damage_coefficient!r}.")
    return c1


# --- stresses -----------------------------------------------------------------------------------------


def _cell_kernels(n: int, h: float, poisson_ratio: float):
    """Surface displacement kernels of a half-space for unit tractions over square cells (x G).

    Returns a dict of (2n-1) x (2n-1) arrays K[(i, j)]: displacement u_i at the cell-centre
    offset (dx, dy) per unit traction t_j [Pa] on a cell of side h, times the shear modulus G.
    Point-load solutions of Boussinesq and Cerruti (Johnson 1985, Eqs. (3.19), (3.21)); the
    cell's own singular term is integrated exactly (int 1/r dA = 4 h asinh(1)).
    """
    nu = poisson_ratio
    offsets = (np.arange(2 * n - 1) - (n - 1)) * h
    dy, dx = np.meshgrid(offsets, offsets, indexing="ij")
    r = np.hypot(dx, dy)
    centre = r == 0
    r_safe = np.where(centre, 1.0, r)
    area = h * h
    inv_r = np.where(centre, 4.0 * h * math.asinh(1.0) / area, 1.0 / r_safe)
    x2_r3 = np.where(centre, 0.5 * inv_r, dx * dx / r_safe ** 3)
    xy_r3 = np.where(centre, 0.0, dx * dy / r_safe ** 3)
    x_r2 = np.where(centre, 0.0, dx / r_safe ** 2)
    y_r2 = np.where(centre, 0.0, dy / r_safe ** 2)
    scale = area / (2.0 * math.pi)
    return {
        # tangential traction along x (Cerruti)
        ("x", "x"): scale * ((1 - nu) * inv_r + nu * x2_r3),
        ("y", "x"): scale * nu * xy_r3,
        # normal pressure, compressive (Boussinesq): u_r = -(1 - 2 nu) P / (4 pi G r), towards the load
        ("x", "z"): -scale * 0.5 * (1 - 2 * nu) * x_r2,
        ("y", "z"): -scale * 0.5 * (1 - 2 * nu) * y_r2,
    }


def _convolve(kernel: np.ndarray, field: np.ndarray) -> np.ndarray:
    """Linear (non-periodic) convolution of an n x n field with a (2n-1)^2 kernel, by FFT."""
    n = field.shape[0]
    size = 2 * n
    spectrum = np.fft.rfft2(kernel, s=(size, size)) * np.fft.rfft2(field, s=(size, size))
    full = np.fft.irfft2(spectrum, s=(size, size))
    return full[n - 1:2 * n - 1, n - 1:2 * n - 1]


@functools.lru_cache(maxsize=32)
def _normalised_surface_stress(degree: float, friction_coefficient: float, poisson_ratio: float,
                               cells: int) -> tuple[np.ndarray, np.ndarray]:
    """(xi, tau_1 / p_scale) along y = 0 at the surface, for a = 1 and p = p_scale * shape(r)."""
    from memstribo.physics.asperity import _normalised_pressure

    half = 1.5
    h = 2.0 / cells
    n = int(round(2 * half / h)) | 1  # odd: a grid line through the centre
    coords = (np.arange(n) - (n - 1) / 2) * h
    yy, xx = np.meshgrid(coords, coords, indexing="ij")
    # p = sqrt(z) F(z), z = 1 - rho^2, with F = 2F1(1 - d/2, 1; 3/2; z) smooth: tabulate F once
    z_table = np.linspace(0.0, 1.0, 4001)
    f_table = _normalised_pressure(np.sqrt(1.0 - z_table), degree) / np.sqrt(np.where(z_table > 0, z_table, 1.0))
    f_table[0] = 2 * f_table[1] - f_table[2]

    def shape(rho):
        z = np.clip(1.0 - rho * rho, 0.0, None)
        return np.sqrt(z) * np.interp(z, z_table, f_table)

    # cell-averaged pressure (the sqrt edge is averaged on a 4 x 4 sub-grid)
    sub = (np.arange(4) + 0.5) / 4 - 0.5
    pressure = np.zeros((n, n))
    for sx in sub:  # 16 evaluations of a vectorised field
        for sy in sub:
            pressure += shape(np.hypot(xx + sx * h, yy + sy * h))
    pressure /= sub.size ** 2
    traction = friction_coefficient * pressure
    kernels = _cell_kernels(n, h, poisson_ratio)
    # displacements times G
    ux = _convolve(kernels[("x", "x")], traction) + _convolve(kernels[("x", "z")], pressure)
    uy = _convolve(kernels[("y", "x")], traction) + _convolve(kernels[("y", "z")], pressure)
    row = (n - 1) // 2  # y = 0
    exx = np.gradient(ux, h, axis=1)[row]
    eyy = np.gradient(uy, h, axis=0)[row]
    exy = 0.5 * (np.gradient(ux, h, axis=0)[row] + np.gradient(uy, h, axis=1)[row])
    p_line, q_line = pressure[row], traction[row]
    nu = poisson_ratio
    k = nu / (1 - nu)
    # surface Hooke's law with sigma_zz = -p (G = 1 units): sigma_xx = 2 (e_xx + k (e_xx + e_yy)) - k p
    sxx = 2.0 * (exx + k * (exx + eyy)) - k * p_line
    syy = 2.0 * (eyy + k * (exx + eyy)) - k * p_line
    sxy = 2.0 * exy
    tensor = np.zeros((n, 3, 3))
    tensor[:, 0, 0], tensor[:, 1, 1], tensor[:, 2, 2] = sxx, syy, -p_line
    tensor[:, 0, 1] = tensor[:, 1, 0] = sxy
    tensor[:, 0, 2] = tensor[:, 2, 0] = -q_line
    principal = np.linalg.eigvalsh(tensor)
    tau1 = 0.5 * (principal[:, -1] - principal[:, 0])
    stresses = np.stack([sxx, syy, -p_line, sxy, -q_line, tau1])
    return coords, stresses


@cites("johnson_1985")
def surface_stresses(xi, degree: float, friction_coefficient: float, poisson_ratio: float,
                     cells: int = 400) -> dict:
    """Surface stresses / p_scale along y = 0 under a power-law pressure and traction mu p [-].

    Parameters
    ----------
    xi : numeric
        x / a [-].
    degree : float
        d of the asperity shape [-].
    friction_coefficient : float
        mu of the traction mu p along +x [-].
    poisson_ratio : float
        nu [-].
    cells : int
        Grid cells across the contact diameter.

    Returns
    -------
    dict
        ``sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_xz, tau1`` over p_scale (tension positive).

    Notes
    -----
    The surface displacements of the half-space are convolutions of the tractions with the
    Boussinesq and Cerruti point-load solutions (Johnson 1985, (3.19), (3.21)), evaluated by
    FFT on square cells; the in-plane strains are their central differences, and Hooke's law
    with the known surface tractions (sigma_zz = -p, tau_xz = -mu p) gives the surface
    stresses. d = 2 reproduces Hertz's closed-form surface stresses within 2e-3 p0 away from the
    contact edge, and a Hertzian traction the sliding-sphere sigma_x of Johnson (1985, 7.2)
    within 0.2 %. The peak of tau_1 at the contact edge converges as about h^0.6 with the cell
    size h: 200 cells give 0.1446, 400 cells 0.1487, 800 cells 0.1511 (d = 4, mu = 0.1,
    nu = 0.23), about 4 % below the extrapolated limit at the default 400.
    """
    if int(cells) < 20:
        raise InputError(f"cells must be >= 20, got {cells!r}.")
    if not (-1.0 < poisson_ratio < 0.5):
        raise InputError(f"poisson_ratio must be within (-1, 0.5), got {poisson_ratio!r}.")
    if friction_coefficient < 0 or not math.isfinite(friction_coefficient):
        raise InputError(f"friction coefficient must be a finite number >= 0, got {friction_coefficient!r}.")
    coords, table = _normalised_surface_stress(float(degree), float(friction_coefficient), float(poisson_ratio),
                                               int(cells))
    xi = np.asarray(xi, dtype=float)
    names = ("sigma_xx", "sigma_yy", "sigma_zz", "tau_xy", "tau_xz", "tau1")
    return {name: np.interp(xi, coords, table[i]) for i, name in enumerate(names)}


def _table_points() -> np.ndarray:
    """x / a of the tau_1 table: uniform, refined towards the contact edges (cusp of tau_1 at |x| = a)."""
    near = np.geomspace(1e-5, 0.1, 60)
    edges = np.concatenate([1 - near, 1 + near, [1.0]])
    return np.unique(np.concatenate([np.linspace(-2.5, 2.5, 1001), edges, -edges]))


@functools.lru_cache(maxsize=32)
def _tau1_table(degree: float, friction_coefficient: float, poisson_ratio: float) -> tuple[np.ndarray, np.ndarray]:
    from memstribo.physics import stresses
    from memstribo.physics.asperity import _normalised_pressure

    xi = _table_points()
    tau = stresses.principal_shear_profile(xi, 0.0, lambda r: _normalised_pressure(r, degree), 1.0,
                                           friction_coefficient, poisson_ratio)
    return xi, np.asarray(tau, dtype=float)


@cites("goryacheva_torskaya_2003", "hamilton_1983", "johnson_1985")
def normalised_principal_shear(xi, degree: float, friction_coefficient: float, poisson_ratio: float) -> np.ndarray:
    """Surface principal shear stress tau_1 / p_scale along x through the centre of a power-law contact [-].

    Parameters
    ----------
    xi : numeric
        x / a, position along the sliding direction over the contact radius [-].
    degree : float
        Degree d of the asperity shape [-].
    friction_coefficient : float
        mu of the traction mu p along +x [-].
    poisson_ratio : float
        nu of the asperity [-].

    Returns
    -------
    ndarray
        tau_1 / p_scale with p_scale = E* d kappa_d B a^(d-1) / pi, the scale of
        :func:`memstribo.physics.asperity.power_law_pressure`. For a power-law punch the pressure is
        p_scale times a shape of r/a only, so the surface stresses scale the same way and
        one table serves every load.

    Notes
    -----
    The table (1 240 points on ``|x/a| <= 2.5``, refined to 1e-5 a at the contact edges, where
    tau_1 has a cusp) comes from :func:`memstribo.physics.stresses.principal_shear_profile` at z = 0+
    (Boussinesq and Cerruti solutions integrated exactly over the contact circle); it is
    interpolated linearly. :func:`surface_stresses` is an independent FFT solution of the
    same surface problem: the two agree to 1e-4 p_scale away from the edge (tests).
    """
    if not (-1.0 < poisson_ratio <= 0.5):
        raise InputError(f"poisson_ratio must be within (-1, 0.5], got {poisson_ratio!r}.")
    if not (math.isfinite(friction_coefficient) and friction_coefficient >= 0):
        raise InputError(f"friction coefficient must be a finite number >= 0, got {friction_coefficient!r}.")
    xi_table, tau_table = _tau1_table(float(degree), float(friction_coefficient), float(poisson_ratio))
    xi = np.asarray(xi, dtype=float)
    outside = np.abs(xi) > xi_table[-1]
    value = np.interp(xi, xi_table, tau_table)
    if np.any(outside):  # far field: tau_1 decays as (a/x)^2, continued from the table's end
        value = np.where(outside, np.interp(np.sign(xi) * xi_table[-1], xi_table, tau_table)
                         * (xi_table[-1] / np.where(outside, np.abs(xi), 1.0)) ** 2, value)
    return value


@cites("goryacheva_torskaya_2003", "galin_1961", "thesis")
def principal_shear_profile(x, load, degree: float, shape_coefficient: float, contact_modulus: float,
                            friction_coefficient: float, poisson_ratio: float) -> np.ndarray:
    """Principal shear stress tau_1(x) at the surface along the sliding direction [Pa].

    Parameters
    ----------
    x : numeric
        Positions along the sliding direction through the asperity's centre [m], shape (n_x,).
    load : numeric
        Asperity loads P [N], shape (...,); zero gives zero stress.
    degree, shape_coefficient : float
        d [-] and B_d [m^(1-d)] of the asperity shape (5-6).
    contact_modulus : float
        E* [Pa].
    friction_coefficient : float
        mu of the traction mu p [-].
    poisson_ratio : float
        nu [-].

    Returns
    -------
    ndarray
        tau_1 [Pa], shape (..., n_x).
    """
    load = np.asarray(load, dtype=float)
    if np.any(load < 0) or not np.all(np.isfinite(load)):
        raise InputError("asperity loads must be finite and >= 0 N.")
    x = np.asarray(x, dtype=float)
    positive = np.where(load > 0, load, 1.0)
    a = power_law_contact_radius(positive, degree, shape_coefficient, contact_modulus)
    scale = _pressure_scale(float(degree), float(shape_coefficient), float(contact_modulus), a)
    scale = np.where(load > 0, scale, 0.0)
    xi = x / a[..., None]
    return scale[..., None] * normalised_principal_shear(xi, degree, friction_coefficient, poisson_ratio)


# --- damage law ---------------------------------------------------------------------------------------------


@cites("thesis", "rabotnov_1963", "goryacheva_torskaya_2003")
def damage_sum(stress_amplitude, damage_exponent: float, damage_coefficient: float = 1.0, axis: int = 0):
    """Linear damage summation over load cycles, omega = sum_i c1 (Delta tau_1,i)^m, Eq. (5-10) in [1]_.

    Parameters
    ----------
    stress_amplitude : array_like
        Amplitudes Delta tau_1,i >= 0 of the principal shear stress [Pa], cycles along ``axis``.
    damage_exponent : float
        m > 0 [-].
    damage_coefficient : float
        c1 > 0 [Pa^-m]; 1 gives omega / c1 [Pa^m].
    axis : int
        Axis of the load cycles.

    Returns
    -------
    ndarray
        omega [-] (or omega / c1 [Pa^m] with c1 = 1), not clipped to 1.

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, 5.5.2, (5-8)-(5-11).
    """
    m = _check_exponent(damage_exponent)
    c1 = _check_coefficient(damage_coefficient)
    amplitude = np.asarray(stress_amplitude, dtype=float)
    if np.any(amplitude < 0) or not np.all(np.isfinite(amplitude)):
        raise InputError("stress amplitudes must be finite and >= 0 Pa.")
    return c1 * np.sum(amplitude ** m, axis=axis)


def cyclic_peak_loads(loads, peaks_per_cycle: int) -> np.ndarray:
    """The load peaks of one meshing cycle from a short list: the list repeated to k peaks [N].

    A list of n loads (thesis Table 5-1: six nanoblock loads) stands for the k peaks of a
    meshing cycle (k = 48, Figure 5-18) taken in turn: peak i has load ``loads[i % n]``.
    """
    loads = np.atleast_1d(np.asarray(loads, dtype=float))
    if loads.ndim != 1 or loads.size == 0 or not np.all(np.isfinite(loads)) or np.any(loads <= 0):
        raise InputError(f"loads must be a non-empty list of finite loads > 0 N, got {loads.tolist()!r}.")
    if int(peaks_per_cycle) != peaks_per_cycle or peaks_per_cycle < 1:
        raise InputError(f"peaks_per_cycle must be an integer >= 1, got {peaks_per_cycle!r}.")
    return loads[np.arange(int(peaks_per_cycle)) % loads.size]


def load_peaks(history) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Load peaks of each nanoblock over a meshing cycle, and the valley before each [N].

    Parameters
    ----------
    history : array_like
        Loads of the nanoblocks over the cycle [N], shape (steps, blocks) (the mesh's
        ``block_load``). NaN (block out of the contact) counts as 0.

    Returns
    -------
    (peak, valley, block) : ndarrays of one entry per peak
        Peak load [N], the lowest load since the block's previous peak (or since the start) [N],
        and the block index. A peak is a step whose load exceeds the previous step's and is
        at least the next step's (the first and last steps count against a zero load).
    """
    loads = np.nan_to_num(np.asarray(history, dtype=float), nan=0.0)
    if loads.ndim != 2:
        raise InputError(f"block load history must have shape (steps, blocks), got {loads.shape}.")
    if np.any(loads < 0):
        loads = np.clip(loads, 0.0, None)  # adhesive (tensile) loads do not load the coating in compression
    padded = np.pad(loads, ((1, 1), (0, 0)))
    is_peak = (padded[1:-1] > padded[:-2]) & (padded[1:-1] >= padded[2:]) & (loads > 0)
    # group g of block b: the steps after its g-th peak up to and including its (g+1)-th
    group = np.cumsum(is_peak, axis=0) - is_peak
    group_id = group + (group.max() + 1) * np.arange(loads.shape[1])[None, :]
    minima = np.full(int(group_id.max()) + 1, np.inf)
    np.minimum.at(minima, group_id.ravel(), loads.ravel())
    steps, blocks = np.nonzero(is_peak)
    order = np.lexsort((steps, blocks))
    steps, blocks = steps[order], blocks[order]
    valley = minima[group_id[steps, blocks]]
    valley = np.where(group[steps, blocks] == 0, 0.0, valley)  # the block was unloaded before the cycle
    return loads[steps, blocks], np.minimum(valley, loads[steps, blocks]), blocks


@dataclass(frozen=True)
class DamageResult:
    """Damage per meshing cycle of the coating on the atomic asperities of nanoblocks.

    Attributes
    ----------
    x : ndarray
        Positions along the sliding direction through an asperity's centre [m], shape (n_x,).
    omega_over_c1 : ndarray
        omega / c1 per meshing cycle [Pa^m], shape (blocks, m*m, n_x).
    classes : ndarray of str
        'corner', 'side' or 'central' of each asperity (row-major), shape (m*m,).
    damage_exponent : float
        m [-].
    peaks_per_cycle : ndarray
        Load peaks k of each block in the cycle [-], shape (blocks,).
    asperity_peak_loads : ndarray
        Peak loads of the asperities of the most damaged block [N], shape (k, m*m).
    maximum : dict
        Position class -> largest omega / c1 per cycle over x and over blocks [Pa^m].
    location : dict
        Position class -> x of that maximum [m].
    """

    x: np.ndarray
    omega_over_c1: np.ndarray
    classes: np.ndarray
    damage_exponent: float
    peaks_per_cycle: np.ndarray
    asperity_peak_loads: np.ndarray
    maximum: dict = field(default_factory=dict)
    location: dict = field(default_factory=dict)

    @property
    def per_asperity(self) -> np.ndarray:
        """Largest omega / c1 over x of each asperity of each block [Pa^m], shape (blocks, m*m)."""
        return self.omega_over_c1.max(axis=-1)

    @property
    def life_ratio_corner_to_central(self) -> float | None:
        """Life of the corner asperity over that of the central one [-] (thesis: 0.91 for m = 1).

        None for a nanoblock without both (fewer than 3 asperities per side).
        """
        if "corner" not in self.maximum or "central" not in self.maximum:
            return None
        return self.maximum["central"] / self.maximum["corner"]


def _asperity_damage(peak_block_loads, valley_block_loads, block_index, n_blocks, params, x=None):
    """omega/c1 per cycle on every asperity of every block (vectorised over all peaks)."""
    per_side = params["atomic_per_side"]
    degree = params["asperity_degree"]
    coefficient = params["asperity_shape_coefficient"]
    modulus = contact_modulus_of(params)
    m = _check_exponent(params["damage_exponent"])
    friction = params["asperity_friction_coefficient"]
    nu = params["poisson_ratio"]
    both = np.concatenate([peak_block_loads, valley_block_loads])
    positive = both > 0
    asperity_loads = np.zeros((both.size, per_side * per_side))
    if positive.any():
        sharing = nanoblock_load_sharing(both[positive], per_side, params["atomic_pitch"], degree, coefficient,
                                         modulus)
        asperity_loads[positive] = sharing.loads
    peaks, valleys = asperity_loads[:peak_block_loads.size], asperity_loads[peak_block_loads.size:]

    def omega_at(points):
        omega = np.zeros((n_blocks, peaks.shape[1], np.size(points)))
        # in chunks of peaks: the stress profiles of all peaks at once would take (peaks x asperities x n_x) floats
        chunk = max(1, _CHUNK_VALUES // max(1, peaks.shape[1] * np.size(points)))
        for start in range(0, peaks.shape[0], chunk):
            part = slice(start, start + chunk)
            tau_peak = principal_shear_profile(points, peaks[part], degree, coefficient, modulus, friction, nu)
            tau_valley = principal_shear_profile(points, valleys[part], degree, coefficient, modulus, friction, nu)
            np.add.at(omega, block_index[part], np.abs(tau_peak - tau_valley) ** m)  # (chunk, m*m, n_x)
        return omega

    if x is not None:
        return x, omega_at(x), peaks, m
    # a uniform grid plus the contact edges of the loads: tau_1 peaks in a cusp at an edge, so the damage
    # profile's maximum lies at or next to one. With up to _MAX_EDGE_LOADS distinct loads all edges are in the grid;
    # with more (a meshing cycle has tens of thousands) the largest half of that number and evenly spaced
    # others, and then, after a first pass, every edge near each asperity's largest values
    # (:func:`_edges_near_maxima`): without them the maximum fell 0.2-3 % short and depended on which edges
    # the grid held, so on round-off in the loads (0.8 %: docs/damage.md, "Resolution of the maximum"). Each
    # block's own maximum (Omega(N)) is refined only where it is near these largest values.
    distinct = np.unique(peaks[peaks > 0])
    loaded = _edge_loads(distinct)
    radii = power_law_contact_radius(loaded, degree, coefficient, modulus) if loaded.size else np.ones(1)
    a_max = float(radii.max())
    x = np.unique(np.concatenate([np.linspace(-1.25 * a_max, 1.25 * a_max, _UNIFORM_POINTS), radii, -radii]))
    omega = omega_at(x)
    if loaded.size < distinct.size:
        all_radii = power_law_contact_radius(distinct, degree, coefficient, modulus)
        extra = _edges_near_maxima(x, omega, np.concatenate([-all_radii, all_radii]))
        if extra.size:
            x = np.concatenate([x, extra])
            order = np.argsort(x)
            x, omega = x[order], np.concatenate([omega, omega_at(extra)], axis=-1)[..., order]
    return x, omega, peaks, m


#: Points of the uniform part of the damage profiles' x grid (over +-1.25 times the largest contact radius).
_UNIFORM_POINTS = 501
#: The second pass of :func:`_asperity_damage` adds the contact edges within this many grid points of every
#: grid value of an asperity's damage profile (largest over the blocks) that is at least _NEAR_MAXIMUM of its
#: largest value (the first pass's grid misses the maximum by up to ~4 %: a 501-point grid without the edges).
_EDGE_WINDOW = 1
_NEAR_MAXIMUM = 0.95


def _edges_near_maxima(x, omega, edges):
    """The contact edges [m] not yet in the grid ``x`` that lie near each asperity's largest damage values."""
    profile = omega.max(axis=0)  # (asperities, n_x): the largest over the blocks
    near = profile >= _NEAR_MAXIMUM * profile.max(axis=-1, keepdims=True)
    near &= profile > 0
    hits = np.nonzero(near.any(axis=0))[0]
    if hits.size == 0:
        return np.zeros(0)
    low = x[np.maximum(hits - _EDGE_WINDOW, 0)]
    high = x[np.minimum(hits + _EDGE_WINDOW, x.size - 1)]
    edges = np.unique(edges)
    inside = np.zeros(edges.size, dtype=bool)
    for lo, hi in zip(low, high):  # one window per grid point near a maximum
        inside[np.searchsorted(edges, lo):np.searchsorted(edges, hi, side="right")] = True
    return np.setdiff1d(edges[inside], x)


#: At most this many distinct asperity loads put their contact edges into the x grid (:func:`_edge_loads`).
_MAX_EDGE_LOADS = 256
#: Stress values per chunk of peaks in :func:`_asperity_damage` (~160 MB of float64).
_CHUNK_VALUES = 20_000_000


def _edge_loads(loaded):
    """The sorted distinct loads whose contact edges join the x grid: all of them up to _MAX_EDGE_LOADS, else the
    largest half of that number and evenly spaced ones among the rest."""
    if loaded.size <= _MAX_EDGE_LOADS:
        return loaded
    top = _MAX_EDGE_LOADS // 2
    rest = loaded[:-top]
    return np.concatenate([rest[np.linspace(0, rest.size - 1, _MAX_EDGE_LOADS - top).astype(int)], loaded[-top:]])


def _result(x, omega, classes, m, counts, peak_loads_of_worst):
    maximum, location = {}, {}
    for position in POSITIONS:
        mask = classes == position
        if not mask.any():
            continue
        sub = omega[:, mask, :]
        flat = int(np.argmax(sub))
        maximum[position] = float(sub.ravel()[flat])
        location[position] = float(x[np.unravel_index(flat, sub.shape)[-1]])
    return DamageResult(x, omega, classes, m, counts, peak_loads_of_worst, maximum, location)


@cites("thesis", "goryacheva_torskaya_2003", "rabotnov_1963")
def nanoblock_damage(loads, params, *, peaks_per_cycle: int | None = None, x=None) -> DamageResult:
    """omega / c1 per meshing cycle of one nanoblock loaded by a list of peak loads (Tables 5-3, 5-4).

    Parameters
    ----------
    loads : array_like
        Nanoblock loads [N] (thesis Table 5-1), repeated in turn to the k peaks of a cycle
        (:func:`cyclic_peak_loads`); between peaks the block unloads completely.
    params : memstribo.parameters.Parameters
        Uses atomic_per_side, atomic_pitch, asperity_degree, asperity_shape_coefficient,
        asperity_friction_coefficient, damage_exponent, peaks_per_cycle and the moduli.
    peaks_per_cycle : int, optional
        k; default the parameter ``peaks_per_cycle`` (48).
    x : array_like, optional
        Positions through the asperity centre [m]; default 501 points over +-1.25 a_max plus the contact edges
        of the loads (:func:`_asperity_damage`). A given grid is used as it is: the maxima are its largest values.

    Returns
    -------
    DamageResult
    """
    k = params["peaks_per_cycle"] if peaks_per_cycle is None else peaks_per_cycle
    peaks = cyclic_peak_loads(loads, k)
    x, omega, asperity_peaks, m = _asperity_damage(peaks, np.zeros_like(peaks), np.zeros(peaks.size, dtype=int), 1,
                                                   params, x)
    classes = position_classes(params["atomic_per_side"])
    return _result(x, omega, classes, m, np.array([peaks.size]), asperity_peaks)


@cites("thesis", "goryacheva_torskaya_2003", "rabotnov_1963", "model")
def mesh_damage(dataset, params, *, x=None) -> DamageResult:
    """omega / c1 per meshing cycle of every nanoblock from a meshing-cycle simulation.

    Parameters
    ----------
    dataset : xarray.Dataset
        Result of :func:`memstribo.simulations.mesh.simulate_mesh` with ``block_load`` (dims step, block) [N].
    params : memstribo.parameters.Parameters
        As for :func:`nanoblock_damage` (``peaks_per_cycle`` is not used: the peaks are counted).
    x : array_like, optional
        Positions through the asperity centre [m]; default as :func:`nanoblock_damage`, and where the
        cycle has more than ``_MAX_EDGE_LOADS`` distinct asperity loads, a second pass adds the contact edges
        near the largest values (docs/damage.md, "Resolution of the maximum"). A given grid is used as it is.

    Returns
    -------
    DamageResult
        One row of ``omega_over_c1`` per nanoblock of the dataset.
    """
    if "block_load" not in getattr(dataset, "variables", {}):
        raise InputError("the meshing-cycle dataset has no 'block_load' (per-nanoblock loads); "
                         "damage needs the mesh's block loads or a --loads list.")
    block_load = dataset["block_load"]
    if "block_flank" in block_load.coords:  # the coating that wears is the gear's (thesis 5.5.3)
        block_load = block_load.isel(block=np.asarray(block_load["block_flank"].values) == "gear")
    history = np.asarray(block_load.transpose("step", ...).values, dtype=float)
    history = history.reshape(history.shape[0], -1)
    peaks, valleys, blocks = load_peaks(history)
    if peaks.size == 0:
        raise InputError("no nanoblock carries a load peak in this meshing cycle: nothing to damage.")
    x, omega, asperity_peaks, m = _asperity_damage(peaks, valleys, blocks, history.shape[1], params, x)
    counts = np.bincount(blocks, minlength=history.shape[1])
    worst = int(np.argmax(omega.max(axis=(1, 2))))
    classes = position_classes(params["atomic_per_side"])
    return _result(x, omega, classes, m, counts, asperity_peaks[blocks == worst])


# --- lifetime --------------------------------------------------------------------------------------------------


def cycles_to_failure(omega_over_c1_per_cycle, damage_coefficient: float):
    """Meshing cycles until omega = 1 where damage accumulates fastest, N_f = 1 / (c1 omega/c1) [-].

    Parameters
    ----------
    omega_over_c1_per_cycle : numeric
        omega / c1 accumulated per meshing cycle [Pa^m] (> 0; 0 gives inf: never).
    damage_coefficient : float
        c1 [Pa^-m].
    """
    c1 = _check_coefficient(damage_coefficient)
    rate = np.asarray(omega_over_c1_per_cycle, dtype=float)
    if np.any(rate < 0) or not np.all(np.isfinite(rate)):
        raise InputError("omega/c1 per cycle must be finite and >= 0.")
    with np.errstate(divide="ignore"):
        life = np.where(rate > 0, 1.0 / (c1 * np.where(rate > 0, rate, 1.0)), np.inf)
    return float(life) if life.ndim == 0 else life


def calibrate_damage_coefficient(omega_over_c1_per_cycle: float, observed_cycles: float) -> float:
    """c1 [Pa^-m] such that the coating fails (omega = 1) after ``observed_cycles`` meshing cycles."""
    try:
        n = float(observed_cycles)
    except (TypeError, ValueError):
        raise InputError(f"observed coating life must be a number of cycles > 0, got {observed_cycles!r}.") from None
    if not math.isfinite(n) or n <= 0:
        raise InputError(f"observed coating life must be a number of cycles > 0, got {observed_cycles!r}.")
    rate = float(omega_over_c1_per_cycle)
    if not math.isfinite(rate) or rate <= 0:
        raise InputError("cannot calibrate c1: the damage per cycle is zero.")
    return 1.0 / (rate * n)


@cites("thesis", "rabotnov_1963")
def damage_after(cycles, omega_over_c1_per_cycle, damage_coefficient: float):
    """Damage omega(N) = min(1, c1 N omega/c1) after N meshing cycles [-] (linear summation).

    Non-decreasing in N by construction (each cycle adds c1 sum (Delta tau)^m >= 0).
    """
    c1 = _check_coefficient(damage_coefficient)
    n = np.asarray(cycles, dtype=float)
    if np.any(n < 0) or not np.all(np.isfinite(n)):
        raise InputError("cycles must be finite and >= 0.")
    rate = np.asarray(omega_over_c1_per_cycle, dtype=float)
    return np.minimum(1.0, c1 * np.multiply.outer(n, rate))


def worn_fraction(cycles, lives, weights=None):
    """Worn fraction Omega(N) of the coating: the weight of asperities whose coating has failed [-].

    Parameters
    ----------
    cycles : numeric
        Meshing cycles N [-].
    lives : array_like
        Cycles to failure of each asperity's coating [-] (inf: never).
    weights : array_like, optional
        Share of the coated area of each asperity (default equal); normalised to sum 1.
    """
    lives = np.asarray(lives, dtype=float).ravel()
    w = np.ones_like(lives) if weights is None else np.asarray(weights, dtype=float).ravel()
    if w.shape != lives.shape or np.any(w < 0) or w.sum() <= 0:
        raise InputError("weights must be >= 0, one per asperity, not all zero.")
    w = w / w.sum()
    n = np.asarray(cycles, dtype=float)
    return (np.multiply.outer(n, np.ones_like(lives)) >= lives).astype(float) @ w


def cycles_to_stiction(lives, critical_wear: float | None, weights=None) -> float | None:
    """Fewest meshing cycles after which the worn fraction reaches ``critical_wear`` [-] (None: never).

    Parameters
    ----------
    lives : array_like
        Cycles to failure of each asperity's coating [-].
    critical_wear : float or None
        Worn fraction Omega at which F_f >= F_t (:func:`memstribo.physics.coating.critical_wear`);
        None (no stiction even when bare) gives None.
    weights : array_like, optional
        As for :func:`worn_fraction`.
    """
    if critical_wear is None:
        return None
    lives = np.asarray(lives, dtype=float).ravel()
    w = np.ones_like(lives) if weights is None else np.asarray(weights, dtype=float).ravel()
    order = np.argsort(lives)
    cumulative = np.cumsum(w[order]) / w.sum()
    if critical_wear <= 0:
        return 0.0
    reached = np.flatnonzero(cumulative >= critical_wear - 1e-12)
    if reached.size == 0:
        return None
    life = float(lives[order][reached[0]])
    return life if math.isfinite(life) else None


# --- the whole damage stage -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class DamageOutcome:
    """What :func:`run_damage` computed: a JSON-able summary, datasets and figures.

    Attributes
    ----------
    summary : dict
        ``omega_over_c1_max`` (corner/side/central) [Pa^m], ``location`` [m],
        ``life_ratio_corner_to_central`` [-], ``damage_per_cycle_over_c1`` [Pa^m],
        ``damage_coefficient`` [Pa^-m] or None, ``cycles_to_failure``, ``cycles_to_stiction``
        [meshing cycles] or None, ``critical_wear`` [-] or None.
    result : DamageResult
    datasets : dict
        Stem -> xarray.Dataset (``damage_profile``, ``damage_history`` when c1 is known).
    figures : dict
        Stem -> (matplotlib figure, caption).
    """

    summary: dict
    result: DamageResult
    datasets: dict = field(default_factory=dict)
    figures: dict = field(default_factory=dict)


def _sweep_arrays(wear_sweep):
    """(wear, cof, stiction_margin) from a coating.wear_sweep dataset or the chain's summary dict."""
    if wear_sweep is None:
        return None
    def pick(*names):
        for name in names:
            if name in wear_sweep:
                value = wear_sweep[name]
                return np.asarray(getattr(value, "values", value), dtype=float)
        raise InputError(f"the wear sweep has none of {names}.")
    wear = pick("wear")
    return wear, pick("cof_mean"), pick("stiction_margin", "stiction_margin_min")


@cites("thesis", "model")
def run_damage(params, mesh_dataset=None, *, loads=None, wear_sweep=None, cycles_observed=None,
               figures: bool = True) -> DamageOutcome:
    """Damage per cycle, relative lives, and (with c1) cycles to failure and to stiction (5.5).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Model parameters (``damage_coefficient`` c1 may be unset).
    mesh_dataset : xarray.Dataset, optional
        A meshing cycle (of the coated pair) with ``block_load``; used when ``loads`` is None.
    loads : array_like, optional
        Nanoblock peak loads [N] (Table 5-1), instead of the mesh.
    wear_sweep : xarray.Dataset or dict, optional
        COF and stiction margin versus Omega (:func:`memstribo.simulations.coating_wear.wear_sweep`, or the
        chain's summary with ``cof_mean`` and ``stiction_margin_min``): gives the critical
        wear and COF(N).
    cycles_observed : float, optional
        An observed coating life [meshing cycles] to calibrate c1 (overrides the parameter).
    figures : bool
        Build the figures (damage profiles, map, Omega(N) and COF(N)).

    Returns
    -------
    DamageOutcome
    """
    from memstribo.physics.coating import critical_wear as _critical_wear

    if loads is not None:
        result = nanoblock_damage(loads, params)
    elif mesh_dataset is not None:
        result = mesh_damage(mesh_dataset, params)
    else:
        raise InputError("damage needs nanoblock loads (--loads) or a meshing-cycle dataset.")
    per_asperity = result.per_asperity  # (blocks, m*m)
    rate_max = float(per_asperity.max())
    c1 = params["damage_coefficient"]
    if cycles_observed is not None:
        c1 = calibrate_damage_coefficient(rate_max, cycles_observed)
    summary = {
        "omega_over_c1_max": dict(result.maximum),
        "location": dict(result.location),
        "life_ratio_corner_to_central": result.life_ratio_corner_to_central,
        "damage_per_cycle_over_c1": rate_max,
        "damage_exponent": result.damage_exponent,
        "peaks_per_cycle": int(result.peaks_per_cycle.max()),
        "damage_coefficient": c1,
    }
    sweep = _sweep_arrays(wear_sweep)
    crit = None
    if sweep is not None:
        import xarray as xr

        crit = _critical_wear(xr.Dataset({"stiction_margin": ("wear", sweep[2])}, coords={"wear": sweep[0]}))
        summary["critical_wear"] = crit
    datasets = {"damage_profile": _profile_dataset(result)}
    if c1 is not None:
        # Omega counts the coating where the teeth touch: the asperities of the nanoblocks that carry
        # load in the cycle (a block never loaded neither wears nor adds friction; the mesh's Omega is
        # a fraction of bare blocks spread evenly over the flank, i.e. also over the touching ones)
        loaded = result.peaks_per_cycle > 0
        lives = cycles_to_failure(per_asperity[loaded], c1)
        summary["cycles_to_failure"] = float(np.min(lives))
        summary["cycles_to_failure_by_position"] = {
            p: float(np.min(lives[:, result.classes == p])) for p in POSITIONS if (result.classes == p).any()}
        summary["cycles_to_stiction"] = cycles_to_stiction(lives, crit) if sweep is not None else None
        datasets["damage_history"] = _history_dataset(lives, sweep, summary["cycles_to_failure"])
    out_figures = _figures(result, datasets) if figures else {}
    return DamageOutcome(summary, result, datasets, out_figures)


def _profile_dataset(result: DamageResult):
    import xarray as xr

    worst = int(np.argmax(result.per_asperity.max(axis=1)))
    data = {}
    for position in POSITIONS:
        mask = result.classes == position
        if mask.any():
            profile = result.omega_over_c1[worst][mask].max(axis=0)
            data[f"omega_over_c1_{position}"] = ("x", profile, {
                "units": f"Pa^{result.damage_exponent:g}",
                "long_name": f"omega/c1 per meshing cycle, {position} asperity (most damaged block)"})
    return xr.Dataset(data, coords={"x": ("x", result.x, {"units": "m",
                                                         "long_name": "position along sliding through the centre"})})


def _history_dataset(lives, sweep, first_failure):
    import xarray as xr

    finite = lives[np.isfinite(lives)]
    top = float(finite.max()) if finite.size else first_failure
    cycles = np.unique(np.concatenate([np.linspace(0, 1.2 * top, 241), np.sort(finite.ravel())]))
    omega = worn_fraction(cycles, lives)
    data = {"worn_fraction": ("cycles", omega, {"units": "", "long_name": "worn fraction Omega of the coating"})}
    if sweep is not None:
        order = np.argsort(sweep[0])
        data["cof_mean"] = ("cycles", np.interp(omega, sweep[0][order], sweep[1][order]),
                       {"units": "", "long_name": "COF at the worn fraction Omega(N)"})
        data["stiction_margin"] = ("cycles", np.interp(omega, sweep[0][order], sweep[2][order]),
                                   {"units": "N", "long_name": "stiction margin F_t - F_f at Omega(N)"})
    return xr.Dataset(data, coords={"cycles": ("cycles", cycles, {"units": "", "long_name": "meshing cycles N"})})


def _figures(result: DamageResult, datasets) -> dict:
    from memstribo.output import new_figure

    figures = {}
    profile = datasets["damage_profile"]
    fig, ax = new_figure(figsize=(5, 3.5))
    for position, style in zip(POSITIONS, ("r-", "g-", "y-")):
        key = f"omega_over_c1_{position}"
        if key in profile:
            ax.plot(profile["x"].values * 1e9, profile[key].values, style, label=position)
    from memstribo.output import engineering_scale

    ax.set_xlabel("x along sliding [nm]")
    power = "" if result.damage_exponent == 1 else f"^{result.damage_exponent:g}"
    keys = [f"omega_over_c1_{position}" for position in POSITIONS if f"omega_over_c1_{position}" in profile]
    factor, unit = engineering_scale([np.nanmax(np.abs(profile[k].values)) for k in keys] or [1.0], f"Pa{power}")
    for line in ax.get_lines():  # drawn in SI above; scaled so that the axis carries no offset
        line.set_ydata(np.asarray(line.get_ydata(), dtype=float) / factor)
    ax.relim()
    ax.autoscale_view()
    ax.set_ylabel(f"omega / c1 per cycle [{unit}]")
    ax.legend()
    figures["damage_profile"] = (fig, f"Damage per meshing cycle omega/c1 along the sliding direction through the "
                                      f"corner, side and central asperities, m = {result.damage_exponent:g} "
                                      "(thesis Figures 5-22, 5-23).")
    per_side = int(math.isqrt(result.classes.size))
    worst = int(np.argmax(result.per_asperity.max(axis=1)))
    fig, ax = new_figure(figsize=(4, 3.5))
    worst_map = result.per_asperity[worst].reshape(per_side, per_side)
    factor, unit = engineering_scale(worst_map, f"Pa{power}")  # no "1e9" offset over the colour bar
    image = ax.imshow(worst_map / factor, cmap="magma", origin="lower")
    fig.colorbar(image, ax=ax, label=f"max omega/c1 per cycle [{unit}]")
    ax.set_xticks(range(per_side))
    ax.set_yticks(range(per_side))
    ax.set_title("damage map of a nanoblock")
    ax.set_xlabel("asperity column")
    ax.set_ylabel("asperity row")
    figures["damage_map"] = (fig, "Largest damage per cycle of each atomic asperity of the most damaged nanoblock.")
    if "damage_history" in datasets:
        history = datasets["damage_history"]
        fig, ax = new_figure(figsize=(5, 3.5))
        ax.plot(history["cycles"].values, history["worn_fraction"].values * 100, "k-", label="Omega(N)")
        ax.set_xlabel("meshing cycles N")
        ax.set_ylabel("worn fraction Omega [%]")
        if "cof" in history:
            twin = ax.twinx()
            twin.plot(history["cycles"].values, history["cof_mean"].values, "b--", label="COF(N)")
            twin.set_ylabel("COF [-]")
        figures["damage_history"] = (fig, "Worn fraction of the coating and COF versus meshing cycles.")
    return figures
