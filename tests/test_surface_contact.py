"""Surface (3D) contact solver: Hertz sphere, wavy surfaces, an independent dense solver, bad input, CLI."""

import numpy as np
import pytest

from memstribo.physics import closed_form as ref
from memstribo.errors import InputError
from memstribo.physics.surface_contact import (SurfaceContactSolution, complementarity_residual, rectangle_influence,
                                       solve_surface_contact, surface_displacement)

E = 100e9  # Pa
R, F = 1e-6, 1e-6  # sphere radius [m], force [N]


def _sphere(n, length):
    d = length / n
    x = (np.arange(n) - n // 2) * d
    return (x[None, :] ** 2 + x[:, None] ** 2) / (2 * R), d


# one rough-map synthesis and one independent dense solver, shared with the validation rows
from memstribo.validation.surface_contact import _rough, dense_nnls_solution  # noqa: E402


# ----------------------------------------------------------------------------- Hertz sphere


@pytest.fixture(scope="module")
def hertz_errors():
    """Relative errors of contact radius, peak pressure and approach on three grids (free boundary)."""
    a = float(ref.hertz_sphere_radius(F, R, E))
    p0 = float(ref.hertz_sphere_peak_pressure(F, R, E))
    delta = float(ref.hertz_sphere_approach(F, R, E))
    rows = []
    for n in (32, 64, 128):
        h, d = _sphere(n, 3 * a)
        sol = solve_surface_contact(h, d, d, E, load=F)
        assert sol.converged, sol.message
        radius = np.sqrt(sol.contact_area / np.pi)
        rows.append((n, abs(radius / a - 1), abs(sol.max_pressure / p0 - 1), abs(sol.approach / delta - 1), sol))
    return rows


def test_hertz_sphere_radius_and_peak_pressure(hertz_errors):
    n, radius_error, pressure_error, approach_error, sol = hertz_errors[-1]  # 128 x 128, ~43 elements across a
    assert radius_error < 0.005
    assert pressure_error < 1e-4
    assert approach_error < 1e-4
    assert sol.load == pytest.approx(F, rel=1e-10)
    assert not sol.contact[0].any() and not sol.contact[:, 0].any()


def test_hertz_sphere_convergence_order(hertz_errors):
    # errors fall with the element size: peak pressure and approach at least like h^1.3, the
    # contact radius (a staircase of elements) at least like h^0.5 over the three grids
    errors = np.array([row[1:4] for row in hertz_errors])
    orders = np.log2(errors[:-1] / errors[1:])  # per halving of the element size
    assert np.all(orders[:, 1:] > 1.3), orders
    assert np.log2(errors[0, 0] / errors[-1, 0]) / 2 > 0.5, errors[:, 0]


def test_rectangle_influence_is_love_and_far_field_is_point_load():
    # centre of a square: u = 4 a ln(1 + sqrt 2) * 2 / (pi E*) (Johnson 1985, §3.2)
    a = 1e-9
    centre = rectangle_influence(0.0, 0.0, a, a, E)
    assert centre == pytest.approx(2 * a * 4 * np.log(1 + np.sqrt(2)) / (np.pi * E), rel=1e-12)
    far = rectangle_influence(1e-6, 3e-7, a, a, E)
    assert far == pytest.approx((2 * a) ** 2 / (np.pi * E * np.hypot(1e-6, 3e-7)), rel=1e-6)


# ----------------------------------------------------------------------- periodic wavy surfaces


def test_bisinusoidal_full_contact_is_exact():
    # h = -D cos(kx) cos(ky): full contact p = pbar + p* cos cos, p* = sqrt(2) pi E* D / lambda
    n, lam, D = 64, 1e-6, 1e-10
    x = np.arange(n) * lam / n
    shape = np.outer(np.cos(2 * np.pi * x / lam), np.cos(2 * np.pi * x / lam))
    p_star = float(ref.wavy_surface_full_contact_amplitude(D, lam, E))
    p_bar = 2 * p_star
    sol = solve_surface_contact(-D * shape, lam / n, lam / n, E, mean_pressure=p_bar, periodic=True, tolerance=1e-12)
    assert sol.converged and sol.contact.all()
    assert np.abs(sol.pressure - (p_bar + p_star * shape)).max() <= 1e-10 * p_bar


def test_wavy_partial_contact_matches_westergaard():
    # 1D-wavy surface h = D (1 - cos(2 pi x / lambda)), constant along y: Westergaard's closed form
    nx, ny, lam, D = 256, 4, 1e-6, 1e-9
    x = np.arange(nx) * lam / nx
    h = np.tile(D * (1 - np.cos(2 * np.pi * x / lam)), (ny, 1))
    p_star = np.pi * E * D / lam
    for fraction in (0.2, 0.5):
        p_bar = fraction * p_star
        sol = solve_surface_contact(h, lam / nx, lam / nx, E, mean_pressure=p_bar, periodic=True)
        assert sol.converged
        assert np.all(sol.pressure == sol.pressure[:1])  # uniform along y
        half_width = float(ref.westergaard_contact_half_width(p_bar, D, lam, E))
        assert sol.contact[0].sum() * lam / nx / 2 == pytest.approx(half_width, abs=lam / nx)
        exact = ref.westergaard_pressure(np.where(x > lam / 2, x - lam, x), p_bar, D, lam, E)
        assert sol.max_pressure == pytest.approx(exact.max(), rel=1e-3)
        assert np.abs(sol.pressure[0] - exact).max() < 0.03 * exact.max()  # the edges: square-root singular


def test_load_balance_and_outputs():
    n, length = 64, 1e-6
    z = _rough(n, length, 1e-9, seed=3)
    sol = solve_surface_contact(z.max() - z, length / n, length / n, E, mean_pressure=2e8, periodic=True)
    assert isinstance(sol, SurfaceContactSolution)
    assert sol.converged and sol.residual <= 1e-8
    assert sol.load == pytest.approx(2e8 * length**2, rel=1e-10)
    assert np.all(sol.pressure >= 0) and np.all(sol.gap >= 0)
    assert np.all(sol.gap[sol.contact] == 0) and np.all(sol.pressure[~sol.contact] == 0)
    assert 0 < sol.contact_fraction < 1 and sol.max_pressure > 2e8 and sol.mean_gap > 0
    ds = sol.to_xarray()
    assert ds["pressure"].dims == ("y", "x") and ds["pressure"].attrs["units"] == "Pa"
    assert ds["gap"].attrs["units"] == "m" and ds["x"].attrs["units"] == "m"
    assert ds.sizes == {"y": n, "x": n}


def test_nested_grids_and_cold_start_agree():
    n, length = 256, 1e-6
    z = _rough(n, length, 1e-9, seed=5)
    h = z.max() - z
    nested = solve_surface_contact(h, length / n, length / n, E, mean_pressure=3e8, periodic=True)
    cold = solve_surface_contact(h, length / n, length / n, E, mean_pressure=3e8, periodic=True, continuation=False)
    assert nested.converged and cold.converged and nested.coarse_iterations > 0
    assert np.array_equal(nested.contact, cold.contact)
    assert np.abs(nested.pressure - cold.pressure).max() < 1e-6 * nested.max_pressure


def test_not_converged_is_reported():
    n, length = 64, 1e-6
    z = _rough(n, length, 1e-9, seed=3)
    sol = solve_surface_contact(z.max() - z, length / n, length / n, E, mean_pressure=2e8, periodic=True,
                                max_iterations=2, continuation=False)
    assert not sol.converged and "NOT converged" in sol.message and sol.residual > 1e-8


# ------------------------------------------------------------------ independent dense solver


def test_periodic_rough_matches_dense_nnls():
    n, length, p_bar = 32, 1e-6, 3e8
    d = length / n
    z = _rough(n, length, 1e-9, seed=7)
    h = z.max() - z
    sol = solve_surface_contact(h, d, d, E, mean_pressure=p_bar, periodic=True, tolerance=1e-12)
    # independent: dense cosine-sum matrix, Cholesky, scipy NNLS at the solver's approach
    p = dense_nnls_solution(h, d, p_bar, sol.approach)
    assert np.array_equal(p > 0, sol.contact)
    assert np.abs(p - sol.pressure).max() < 1e-6 * sol.max_pressure
    assert p.mean() == pytest.approx(p_bar, rel=1e-6)
    assert complementarity_residual(h, sol.pressure, d, d, E, periodic=True) <= 1e-12


def test_free_boundary_displacement_matches_dense_sum():
    n, d = 12, 1e-9
    rng = np.random.default_rng(1)
    p = rng.uniform(0, 1e9, size=(n, n + 3))
    iy, ix = np.mgrid[0:n, 0:n + 3]
    K = rectangle_influence((ix.ravel()[:, None] - ix.ravel()[None, :]) * d,
                            (iy.ravel()[:, None] - iy.ravel()[None, :]) * 2 * d, d / 2, d, E)
    u = surface_displacement(p, d, 2 * d, E)
    assert np.allclose(u.ravel(), K @ p.ravel(), rtol=1e-12, atol=0)


# ---------------------------------------------------------------------------------- bad input


@pytest.mark.parametrize("args, kwargs, match", [
    ((np.zeros(8), 1e-9, 1e-9, E), {"load": 1.0}, "2-D array"),
    ((np.full((4, 4), np.nan), 1e-9, 1e-9, E), {"load": 1.0}, "NaN"),
    ((np.zeros((4, 4)), -1e-9, 1e-9, E), {"load": 1.0}, r"dx must be a positive finite number \[m\]"),
    ((np.zeros((4, 4)), 1e-9, 0.0, E), {"load": 1.0}, r"dy .*\[m\]"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, -E), {"load": 1.0}, r"contact_modulus .*\[Pa\]"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {}, "exactly one of load"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {"load": 1.0, "mean_pressure": 1.0}, "exactly one of load"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {"load": -1.0}, r"load must be a positive .*\[N\]"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {"mean_pressure": 0.0}, r"mean_pressure .*\[Pa\]"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {"load": 1.0, "tolerance": 2.0}, "tolerance"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {"load": 1.0, "max_iterations": 0}, "max_iterations"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {"load": 1.0, "initial_pressure": np.ones((3, 3))}, "initial_pressure"),
    ((np.zeros((4, 4)), 1e-9, 1e-9, E), {"load": 1.0, "interaction": "md"}, "not implemented"),
])
def test_bad_input(args, kwargs, match):
    with pytest.raises(InputError, match=match):
        solve_surface_contact(*args, **kwargs)


# ------------------------------------------------------------------------------------------ CLI

KEYS = {"contact_fraction", "max_pressure", "mean_gap", "approach", "iterations", "residual", "solve_seconds"}


@pytest.fixture(scope="module")
def npy_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("surface") / "rough.npy"
    np.save(path, _rough(64, 1e-6, 1e-9, seed=11))
    return path


def test_cli_surface_npy(cli, npy_map, tmp_path):
    out = cli.json("contact", "--surface", npy_map, "--physical-size", "1um", "--mean-pressure", "300 MPa",
                   "--modulus", "100 GPa", "--periodic", "--out", tmp_path)
    assert set(out) - {"warnings"} == KEYS
    assert 0 < out["contact_fraction"] < 1 and out["residual"] <= 1e-8
    z = np.load(npy_map)
    direct = solve_surface_contact(z.max() - z, 1e-6 / 64, 1e-6 / 64, E, mean_pressure=3e8, periodic=True)
    assert out["max_pressure"] == pytest.approx(direct.max_pressure, rel=1e-9)
    assert (tmp_path / "surface_contact.nc").stat().st_size > 0 and (tmp_path / "surface_contact.png").stat().st_size
    import xarray as xr

    with xr.open_dataset(tmp_path / "surface_contact.nc") as ds:
        assert ds["pressure"].attrs["units"] == "Pa" and ds["gap"].attrs["units"] == "m"
        assert float(ds["pressure"].mean()) == pytest.approx(3e8, rel=1e-9)


def test_cli_surface_rectangular_size_and_load(cli, npy_map):
    out = cli.json("contact", "--surface", npy_map, "--physical-size", "2umx1um", "--load", "0.5 mN")
    assert set(out) - {"warnings"} == KEYS and out["iterations"] >= 1


def test_cli_surface_measured_map(cli, afm_dir):
    out = cli.json("contact", "--surface", afm_dir / "IgorIBWReader_P0089OP0027.ibw", "--mean-pressure", "200 MPa",
                   "--periodic")
    assert set(out) - {"warnings"} == KEYS and 0 < out["contact_fraction"] < 0.5 and out["residual"] <= 1e-8


@pytest.mark.parametrize("argv, match", [
    (("--mean-pressure", "1 GPa"), "--physical-size"),
    (("--physical-size", "1um"), "exactly one of --mean-pressure"),
    (("--physical-size", "1umx2umx3um", "--load", "1 uN"), "--physical-size"),
    (("--physical-size", "0um", "--load", "1 uN"), "--physical-size must be positive"),
    (("--physical-size", "1um", "--mean-pressure", "3 N"), "mean-pressure"),
])
def test_cli_surface_bad_input(cli, npy_map, argv, match):
    code, out, err = cli("contact", "--surface", npy_map, *argv)
    assert code == 2 and match in err and "Traceback" not in err


def test_cli_surface_profile_is_refused(cli, afm_dir):
    code, out, err = cli("contact", "--surface", afm_dir / "si_profile_linescan.txt", "--load", "1 uN")
    assert code == 2 and "not a 2D map" in err


def test_validation_rows_agree():
    from memstribo.validation.surface_contact import rows

    table = rows()
    assert len(table) == 9
    assert all(row.agrees for row in table), [row for row in table if not row.agrees]
    assert all(row.command.startswith("python ") for row in table)


def test_cli_surface_options_refused_for_line_contact(cli):
    code, out, err = cli("contact", "--flat", "--mean-pressure", "1 GPa")
    assert code == 2 and "--mean-pressure go(es) with --surface" in err


def test_fallback_to_polonsky_keer_when_the_set_does_not_settle(monkeypatch):
    import memstribo.physics.surface_contact as module

    n, length = 64, 1e-6
    z = _rough(n, length, 1e-9, seed=3)
    h = z.max() - z
    reference_solution = solve_surface_contact(h, length / n, length / n, E, mean_pressure=2e8, periodic=True)
    monkeypatch.setattr(module, "_MAX_OUTER", 1)
    sol = solve_surface_contact(h, length / n, length / n, E, mean_pressure=2e8, periodic=True)
    assert "polonsky-keer" in sol.message and sol.converged
    assert np.array_equal(sol.contact, reference_solution.contact)
    assert np.abs(sol.pressure - reference_solution.pressure).max() < 1e-5 * sol.max_pressure
