"""Validation rows of the surface (3D) contact solver: Hertz sphere, wavy surfaces, an independent dense solver."""

from __future__ import annotations

import numpy as np

from memstribo.validation.rows import ValidationRow, compare

TOPIC = "surface contact"
E, R, F = 100e9, 1e-6, 1e-6  # Pa, m, N
CALL = "python -m memstribo.validation (memstribo.physics.surface_contact.solve_surface_contact"


def _rough(n, length, rms, seed, hurst=0.8):
    """Periodic isotropic self-affine map by Fourier synthesis [m]."""
    rng = np.random.default_rng(seed)
    qy = np.fft.fftfreq(n, length / n)[:, None]
    qx = np.fft.rfftfreq(n, length / n)[None, :]
    q = np.hypot(qx, qy)
    amplitude = np.zeros_like(q)
    amplitude[q > 0] = q[q > 0] ** (-1 - hurst)
    z = np.fft.irfft2(amplitude * (rng.normal(size=q.shape) + 1j * rng.normal(size=q.shape)), s=(n, n))
    return z * rms / z.std()


def _dense_periodic_operator(n, d):
    """The periodic half-space influence matrix from an explicit cosine sum (no FFT) [m/Pa]."""
    k = np.fft.fftfreq(n, 1.0 / n)
    ky, kx = np.meshgrid(k, k, indexing="ij")
    q = 2 * np.pi * np.hypot(kx, ky) / (n * d)
    weights = np.zeros_like(q)
    weights[q > 0] = 2.0 / (E * q[q > 0]) / n**2
    i = np.arange(n)
    phase = 2 * np.pi / n * (ky.ravel()[:, None, None] * i[None, :, None] + kx.ravel()[:, None, None] * i[None, None, :])
    kernel = np.einsum("k,kyx->yx", weights.ravel(), np.cos(phase))
    iy, ix = np.divmod(np.arange(n * n), n)
    return kernel[(iy[:, None] - iy[None, :]) % n, (ix[:, None] - ix[None, :]) % n]


def dense_nnls_solution(h, d, mean_pressure, approach):
    """Independent solve of a small periodic problem: dense matrix, Cholesky, scipy NNLS [Pa].

    The periodic operator A is singular in the mean; under load control A + c 1 1^T has the
    same minimiser, with the approach shifted by c * sum(p). Given that approach, the
    displacement-controlled problem min 1/2 p^T A1 p - (approach - h)^T p, p >= 0 is an NNLS
    problem in the Cholesky factor of A1.
    """
    from scipy.optimize import nnls

    n = h.shape[0]
    A = _dense_periodic_operator(n, d) + 0.0
    c = float(np.abs(A).max())
    A += c
    L = np.linalg.cholesky(A)
    p, _ = nnls(L.T, np.linalg.solve(L, approach + c * mean_pressure * n * n - h.ravel()), maxiter=50 * n * n)
    return p.reshape(n, n)


def rows() -> list[ValidationRow]:
    from memstribo.physics.closed_form import (hertz_sphere_approach, hertz_sphere_peak_pressure, hertz_sphere_radius,
                             wavy_surface_full_contact_amplitude, westergaard_contact_half_width, westergaard_pressure)
    from memstribo.physics.surface_contact import solve_surface_contact

    rows_ = []
    # Hertz sphere on a flat, free boundary, 128 x 128 elements over 3a
    a = float(hertz_sphere_radius(F, R, E))
    n = 128
    d = 3 * a / n
    x = (np.arange(n) - n // 2) * d
    sol = solve_surface_contact((x[None, :] ** 2 + x[:, None] ** 2) / (2 * R), d, d, E, load=F)
    command = f"{CALL}, Hertz sphere R = 1 um, F = 1 uN, E* = 100 GPa, 128 x 128 over 3a, free boundary)"
    rows_ += [
        compare(TOPIC, "contact radius sqrt(A/pi), smooth sphere (43 elements across a)",
                "Hertz sphere, Johnson (4.22)", a * 1e9, np.sqrt(sol.contact_area / np.pi) * 1e9, "nm", rtol=5e-3,
                command=command, note="staircase of square elements: error ~ first order in the element size"),
        compare(TOPIC, "peak pressure p0, smooth sphere", "Hertz sphere, Johnson (4.21)",
                float(hertz_sphere_peak_pressure(F, R, E)) / 1e9, sol.max_pressure / 1e9, "GPa", rtol=1e-3,
                command=command),
        compare(TOPIC, "approach, smooth sphere (datum: undisplaced far field)", "Hertz sphere a^2/R, Johnson (4.23)",
                float(hertz_sphere_approach(F, R, E)) * 1e12, sol.approach * 1e12, "pm", rtol=1e-3, command=command),
        compare(TOPIC, "load balance dx dy sum(p)", "imposed force 1 uN", F * 1e6, sol.load * 1e6, "uN", rtol=1e-10,
                command=command),
    ]
    # Westergaard: 1D-wavy surface in partial contact, periodic, 256 x 4 elements, p = p*/2
    lam, D, nx = 1e-6, 1e-9, 256
    xw = np.arange(nx) * lam / nx
    h = np.tile(D * (1 - np.cos(2 * np.pi * xw / lam)), (4, 1))
    p_bar = 0.5 * np.pi * E * D / lam
    sol = solve_surface_contact(h, lam / nx, lam / nx, E, mean_pressure=p_bar, periodic=True)
    command = f"{CALL}, wavy h = D(1 - cos 2 pi x/lambda), D = 1 nm, lambda = 1 um, 256 x 4, periodic, p = p*/2)"
    exact = westergaard_pressure(np.where(xw > lam / 2, xw - lam, xw), p_bar, D, lam, E)
    rows_ += [
        compare(TOPIC, "contact half-width a, 1D-wavy surface (64 elements across a)",
                "Westergaard, Johnson (13.6)", float(westergaard_contact_half_width(p_bar, D, lam, E)) * 1e9,
                sol.contact[0].sum() * lam / nx / 2 * 1e9, "nm", atol=lam / nx * 1e9, command=command,
                note="tolerance: one element"),
        compare(TOPIC, "peak pressure, 1D-wavy surface", "Westergaard, Johnson (13.7)", float(exact.max()) / 1e9,
                sol.max_pressure / 1e9, "GPa", rtol=1e-3, command=command),
    ]
    # bi-sinusoidal surface in full contact: exact on the grid (spectral kernel)
    n = 64
    xb = np.arange(n) * lam / n
    shape = np.outer(np.cos(2 * np.pi * xb / lam), np.cos(2 * np.pi * xb / lam))
    p_star = float(wavy_surface_full_contact_amplitude(1e-10, lam, E))
    sol = solve_surface_contact(-1e-10 * shape, lam / n, lam / n, E, mean_pressure=2 * p_star, periodic=True,
                                tolerance=1e-12)
    rows_.append(compare(
        TOPIC, "max |p - (p_mean + p* cos cos)| / p_mean, bi-sinusoidal surface in full contact (64 x 64)",
        "Johnson-Greenwood full contact, p* = sqrt(2) pi E* D / lambda", 0.0,
        float(np.abs(sol.pressure - (2 * p_star + p_star * shape)).max() / (2 * p_star)), "", atol=1e-10,
        command=f"{CALL}, bi-sinusoidal D = 0.1 nm, lambda = 1 um, p_mean = 2 p*, periodic)"))
    # independent dense solver on a 32 x 32 periodic rough surface
    n, length, p_bar = 32, 1e-6, 3e8
    d = length / n
    z = _rough(n, length, 1e-9, seed=7)
    h = z.max() - z
    sol = solve_surface_contact(h, d, d, E, mean_pressure=p_bar, periodic=True, tolerance=1e-12)
    p = dense_nnls_solution(h, d, p_bar, sol.approach)
    command = f"{CALL}, self-affine H = 0.8, Rq 1 nm, 32 x 32 over 1 um, p = 0.3 GPa, periodic, tol 1e-12)"
    rows_ += [
        compare(TOPIC, "max |p - p_NNLS| / p_max, rough surface (32 x 32, dense NNLS on the same coefficients)",
                "independent dense solver (Cholesky + scipy NNLS)", 0.0,
                float(np.abs(p - sol.pressure).max() / sol.max_pressure), "", atol=1e-6, command=command),
        compare(TOPIC, "elements whose contact state differs from the dense NNLS solution",
                "independent dense solver", 0.0, float(np.count_nonzero((p > 0) != sol.contact)), "", atol=0.0,
                command=command),
    ]
    return rows_
