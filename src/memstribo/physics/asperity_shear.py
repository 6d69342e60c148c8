"""The principal shear stress tau_1 under a sliding power-law asperity (Goryacheva & Torskaya 2003; thesis 5.5.1):
the surface stresses of the normalised pressure with its friction traction, tau_1 along the sliding direction, and
the profile through an asperity's centre, the stress amplitude that :mod:`memstribo.physics.damage` sums."""

from __future__ import annotations

import functools
import math

import numpy as np

from memstribo.errors import InputError
from memstribo.physics.asperity import _pressure_scale, power_law_contact_radius
from memstribo.references import cites


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
