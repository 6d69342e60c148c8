"""Rough line-contact solver: Hertz, Westergaard, an independent direct solver, invariants, bad input."""

import numpy as np
import pytest

from memstribo.physics import closed_form as ref
from memstribo.physics.contact import ContactSolution, elastic_displacement, solve_line_contact, strip_influence
from memstribo.errors import InputError

R, E, W = 20e-6, 100e9, 1.0  # m, Pa, N/m


def _tune(monkeypatch, **fields):
    """Replace fields of the contact solvers' default settings for one test (:mod:`memstribo.physics.contact.settings`)."""
    import dataclasses

    from memstribo.physics.contact import settings

    monkeypatch.setattr(settings, "DEFAULTS", dataclasses.replace(settings.DEFAULTS, **fields))


def _rough(n, length, rms, seed, hurst=0.8):
    """Periodic self-affine profile by Fourier synthesis (test-local; independent of roughness.py)."""
    rng = np.random.default_rng(seed)
    q = 2 * np.pi * np.fft.rfftfreq(n, length / n)
    amplitude = np.zeros_like(q)
    amplitude[1:] = q[1:] ** (-0.5 - hurst)
    spectrum = amplitude * (rng.normal(size=q.size) + 1j * rng.normal(size=q.size))
    spectrum[-1] = spectrum[-1].real
    z = np.fft.irfft(spectrum, n)
    return z * rms / z.std()


def _dense_operator(n, dx, periodic, reference_distance):
    """The influence matrix built directly (no FFT): strip coefficients or the explicit cosine sum."""
    i = np.arange(n)
    if periodic:
        k = np.arange(1, n // 2 + 1)
        q = 2 * np.pi * k / (n * dx)
        weights = np.where(k == n // 2, 1.0, 2.0) * 2.0 / (E * q)  # Nyquist term counted once
        offsets = (i[:, None] - i[None, :]) * dx
        return np.einsum("k,ijk->ij", weights, np.cos(offsets[..., None] * q)) / n
    return strip_influence((i[:, None] - i[None, :]) * dx, dx, E, reference_distance)


def _direct_solution(A, h, mean_pressure):
    """Independent reference: active-set method with exact linear solves (small grids only)."""
    n = h.size
    contact = h <= np.quantile(h, 0.5)
    for _ in range(200):
        idx = np.flatnonzero(contact)
        m = idx.size
        system = np.zeros((m + 1, m + 1))
        system[:m, :m] = A[np.ix_(idx, idx)]
        system[:m, m] = -1.0
        system[m, :m] = 1.0
        rhs = np.concatenate([-h[idx], [mean_pressure * n]])
        solution = np.linalg.solve(system, rhs)
        p = np.zeros(n)
        p[idx] = solution[:m]
        gap = h + A @ p - solution[m]
        new = (contact & (p > 0)) | (~contact & (gap < -1e-15 * np.ptp(h)))
        if np.array_equal(new, contact) and np.all(p >= 0):
            return p, solution[m]
        contact = new
    raise AssertionError("direct reference did not settle")


# ------------------------------------------------------------------------------------ Hertz


@pytest.fixture(scope="module")
def hertz():
    a = ref.hertz_line_half_width(W, R, E)
    n = 2048
    dx = 8 * a / n
    x = (np.arange(n) - n / 2 + 0.5) * dx
    return x, dx, solve_line_contact(x**2 / (2 * R), dx, E, load=W)


def test_hertz_half_width_and_peak(hertz):
    x, dx, sol = hertz
    assert sol.converged and isinstance(sol, ContactSolution)
    a = ref.hertz_line_half_width(W, R, E)
    p0 = ref.hertz_line_peak_pressure(W, R, E)
    # discretisation: the contact length is a whole number of elements (dx = a/256)
    assert sol.contact_length / 2 == pytest.approx(a, abs=dx)
    assert sol.max_pressure == pytest.approx(p0, rel=1e-3)
    assert np.abs(sol.pressure - ref.hertz_line_pressure(x, W, R, E)).max() < 0.02 * p0


def test_hertz_approach_far_field_datum(hertz):
    x, dx, sol = hertz
    expected = ref.hertz_line_approach(W, R, E, x.size * dx)
    assert sol.approach == pytest.approx(expected, rel=1e-4)


def test_hertz_converges_with_refinement():
    # errors in the peak pressure fall with the element width (first order or better)
    a = ref.hertz_line_half_width(W, R, E)
    p0 = ref.hertz_line_peak_pressure(W, R, E)
    errors = []
    for n in (128, 512):
        dx = 8 * a / n
        x = (np.arange(n) - n / 2 + 0.5) * dx
        errors.append(abs(solve_line_contact(x**2 / (2 * R), dx, E, load=W).max_pressure / p0 - 1))
    assert errors[1] < errors[0] / 2
    assert errors[0] < 0.01  # 1 % already at 32 elements across the contact


def test_load_balance_and_complementarity(hertz):
    _, dx, sol = hertz
    assert sol.load == pytest.approx(W, rel=1e-12)
    assert sol.pressure.sum() * dx == pytest.approx(W, rel=1e-12)
    assert np.all(sol.pressure >= 0) and np.all(sol.gap >= 0)
    assert np.all(sol.gap[sol.contact] == 0) and np.all(sol.pressure[~sol.contact] == 0)


# ------------------------------------------------------------------------------ Westergaard


def test_periodic_westergaard():
    n, wavelength, amplitude = 1024, 1e-6, 2e-9
    dx = wavelength / n
    x = (np.arange(n) - n / 2) * dx
    h = amplitude * (1 - np.cos(2 * np.pi * x / wavelength))
    p_star = np.pi * E * amplitude / wavelength
    mean_pressure = 0.3 * p_star
    sol = solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=True)
    assert sol.converged
    a = ref.westergaard_contact_half_width(mean_pressure, amplitude, wavelength, E)
    assert sol.contact_length / 2 == pytest.approx(a, abs=dx)
    exact = ref.westergaard_pressure(x, mean_pressure, amplitude, wavelength, E)
    assert np.abs(sol.pressure - exact).max() < 0.02 * exact.max()
    assert sol.pressure.mean() == pytest.approx(mean_pressure, rel=1e-12)


# ---------------------------------------------------------- against an independent direct solver


@pytest.mark.parametrize("periodic", [True, False])
def test_rough_against_direct_solver(periodic):
    n, length = 128, 1e-6
    dx = length / n
    z = _rough(n, length, 1e-9, seed=3)
    x = (np.arange(n) - n / 2 + 0.5) * dx
    h = (z.max() - z) if periodic else (x**2 / (2 * 5e-6) - z)
    h = h - h.min()
    mean_pressure = 0.2e9 if periodic else 0.3e9
    A = _dense_operator(n, dx, periodic, n * dx)
    p_direct, approach_direct = _direct_solution(A, h, mean_pressure)
    sol = solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=periodic, tolerance=1e-10)
    assert sol.converged
    assert 0.05 < sol.contact.mean() < 0.6  # a genuinely partial, rough contact
    assert np.abs(sol.pressure - p_direct).max() < 1e-7 * p_direct.max()
    assert sol.approach == pytest.approx(approach_direct, rel=1e-7, abs=1e-9 * np.ptp(h))
    # the FFT operator equals the dense one
    assert np.allclose(elastic_displacement(p_direct, dx, E, periodic=periodic), A @ p_direct, rtol=0,
                       atol=1e-12 * np.abs(A @ p_direct).max())


def test_preconditioning_and_plain_agree_on_rough_profile():
    n, length = 2048, 1e-6
    z = _rough(n, length, 1e-9, seed=7)
    h = z.max() - z
    dx = length / n
    plain = solve_line_contact(h, dx, E, mean_pressure=0.5e9, periodic=True, precondition=False)
    fast = solve_line_contact(h, dx, E, mean_pressure=0.5e9, periodic=True)
    assert plain.converged and fast.converged
    assert fast.iterations < plain.iterations
    assert np.abs(fast.pressure - plain.pressure).max() < 1e-6 * plain.max_pressure


def test_warm_start_same_answer_fewer_iterations():
    n, length = 1024, 1e-6
    z = _rough(n, length, 1e-9, seed=11)
    h = z.max() - z
    dx = length / n
    cold = solve_line_contact(h, dx, E, mean_pressure=0.5e9, periodic=True, continuation=False)
    warm = solve_line_contact(h, dx, E, mean_pressure=0.5e9, periodic=True, initial_pressure=cold.pressure)
    assert warm.iterations < cold.iterations / 4
    assert np.abs(warm.pressure - cold.pressure).max() < 1e-6 * cold.max_pressure


def test_contact_grows_with_load():
    n, length = 512, 1e-6
    z = _rough(n, length, 1e-9, seed=5)
    h = z.max() - z
    lengths = [solve_line_contact(h, length / n, E, mean_pressure=p, periodic=True).contact_length
               for p in (0.1e9, 0.5e9, 2e9)]
    assert lengths[0] < lengths[1] < lengths[2]


# ------------------------------------------------------------------------------ non-convergence


def test_unconverged_is_flagged_not_hidden():
    n, length = 1024, 1e-6
    h = _rough(n, length, 1e-9, seed=1)
    sol = solve_line_contact(h - h.min(), length / n, E, mean_pressure=0.5e9, periodic=True, max_iterations=2,
                             continuation=False)
    assert not sol.converged
    assert sol.residual > 1e-8
    assert "NOT converged" in sol.message and "max_iterations=2" in sol.message


# ------------------------------------------------------------------------------------ bad input


@pytest.mark.parametrize("kwargs, match", [
    (dict(separation=np.zeros(1)), "at least 2"),
    (dict(separation=np.array([0.0, np.nan, 1.0])), "NaN"),
    (dict(dx=0.0), "dx must be a positive"),
    (dict(contact_modulus=-1.0), "contact_modulus must be a positive"),
    (dict(load=None), "exactly one of load"),
    (dict(mean_pressure=1e6), "exactly one of load"),
    (dict(load=-1.0), "load must be a positive"),
    (dict(tolerance=0.0), "tolerance must lie"),
    (dict(max_iterations=0), "max_iterations must be"),
    (dict(initial_pressure=-np.ones(4)), "initial_pressure"),
])
def test_bad_input(kwargs, match):
    arguments = dict(separation=np.array([1e-9, 0.0, 0.0, 1e-9]), dx=1e-9, contact_modulus=E, load=1.0)
    arguments.update(kwargs)
    separation = arguments.pop("separation")
    dx = arguments.pop("dx")
    modulus = arguments.pop("contact_modulus")
    with pytest.raises(InputError, match=match):
        solve_line_contact(separation, dx, modulus, **arguments)


# ------------------------------------------------------------------------------------------ CLI

KEYS = {"contact_length", "max_pressure", "mean_pressure", "load", "approach", "converged", "iterations",
        "residual", "solve_seconds"}


def test_cli_flat_matches_hertz(cli):
    out = cli.json("contact", "--flat", "--radius", "20 um", "--load", "1 N/m", "--modulus", "100 GPa",
                   "--points", "2048")
    assert set(out) - {"warnings"} == KEYS and out["warnings"] == []
    a = ref.hertz_line_half_width(W, R, E)
    assert out["contact_length"] == pytest.approx(2 * a, rel=0.01)
    assert out["max_pressure"] == pytest.approx(ref.hertz_line_peak_pressure(W, R, E), rel=0.01)
    assert out["load"] == pytest.approx(1.0, rel=1e-12)
    assert out["converged"] is True


def test_cli_readable_output(cli):
    code, out, err = cli("contact", "--flat", "--radius", "20 um", "--load", "1 N/m", "--modulus", "100 GPa")
    assert code == 0
    assert "contact_length" in out and "nm" in out and "Pa" in out and "Hertz" in out


def test_cli_profile(cli, afm_dir):
    out = cli.json("contact", "--profile", afm_dir / "si_profile_linescan.txt", "--load", "12.5 N/m")
    assert out["converged"] is True and out["contact_length"] > 0
    assert out["load"] == pytest.approx(12.5, rel=1e-12)


@pytest.mark.parametrize("argv, match", [
    (("--flat", "--points", "20"), "too coarse"),
    (("--flat", "--load", "-1 N/m"), "--load must be positive"),
    (("--flat", "--modulus", "0 GPa"), "--modulus must be positive"),
    (("--flat", "--radius", "-3 um"), "--radius must be positive"),
    (("--flat", "--load", "3 kg"), "load"),
    (("--flat", "--length", "10 nm", "--points", "4096"), "shorter than twice"),
    (("--flat", "--max-iterations", "1", "--tolerance", "1e-14"), "did not converge"),
])
def test_cli_bad_input_exit_2(cli, argv, match):
    code, out, err = cli("contact", *argv)
    assert code == 2
    assert match in err
    assert "Traceback" not in err


def test_cli_unconverged_allowed(cli):
    out = cli.json("contact", "--flat", "--max-iterations", "1", "--tolerance", "1e-14", "--allow-unconverged")
    assert out["converged"] is False and out["residual"] > 1e-14


def test_validation_rows_agree():
    from memstribo.validation.contact import rows

    table = rows()
    assert len(table) == 5
    assert all(row.agrees for row in table), [row for row in table if not row.agrees]
    assert all(row.command.startswith("memstribo contact") for row in table)


def test_cli_map_row_out_of_range(cli, afm_dir):
    code, out, err = cli("contact", "--profile", afm_dir / "example_ps.tiff", "--row", "100000")
    assert code == 2 and "--row 100000 is outside" in err and "Traceback" not in err


def test_cli_map_row_and_periodic(cli, afm_dir):
    out = cli.json("contact", "--profile", afm_dir / "example_ps.tiff", "--row", "3", "--periodic")
    assert out["converged"] is True
    assert out["load"] == pytest.approx(12.5, rel=1e-12)  # the gear-case default w = F/b


def test_fallback_to_polonsky_keer_when_the_set_does_not_settle(monkeypatch):
    n, length = 1024, 1e-6
    z = _rough(n, length, 1e-9, seed=13)
    h = z.max() - z
    reference_solution = solve_line_contact(h, length / n, E, mean_pressure=0.5e9, periodic=True)
    _tune(monkeypatch, max_outer=1)
    sol = solve_line_contact(h, length / n, E, mean_pressure=0.5e9, periodic=True, continuation=False)
    assert sol.converged and "active-set, then polonsky-keer" in sol.message
    assert np.abs(sol.pressure - reference_solution.pressure).max() < 1e-5 * reference_solution.max_pressure


def test_periodic_westergaard_full_contact():
    n, wavelength, amplitude = 512, 1e-6, 2e-9
    dx = wavelength / n
    x = (np.arange(n) - n / 2) * dx
    h = amplitude * (1 - np.cos(2 * np.pi * x / wavelength))
    mean_pressure = 1.5 * np.pi * E * amplitude / wavelength  # above p*: complete contact
    sol = solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=True)
    exact = ref.westergaard_pressure(x, mean_pressure, amplitude, wavelength, E)
    assert sol.converged and sol.contact.all()
    assert np.abs(sol.pressure - exact).max() < 1e-10 * exact.max()  # exact in the spectral discretisation


def test_flat_punch_free_boundary():
    # a flat gap (rigid flat punch of the domain's width): the residual scale falls back to w/E*
    n, half_width = 1000, 0.5e-6
    dx = 2 * half_width / n
    x = (np.arange(n) - n / 2 + 0.5) * dx
    sol = solve_line_contact(np.zeros(n), dx, E, load=1.0)
    exact = ref.flat_punch_line_pressure(x, 1.0, half_width)
    middle = np.abs(x) < 0.5 * half_width
    assert sol.converged and sol.contact.all()
    assert np.abs(sol.pressure - exact)[middle].max() < 2e-3 * exact[middle].max()
    assert "reaches the edge of the domain" in sol.message


def test_small_contact_dense_path_matches_fft_path_and_direct(monkeypatch):
    # a tooth-like case: Hertz gap plus roughness, a few tens of elements in contact
    n, length, radius = 1024, 1e-6, 10e-6
    dx = length / n
    x = (np.arange(n) - n / 2 + 0.5) * dx
    h = x**2 / (2 * radius) - _rough(n, length, 1e-9, seed=2)
    h -= h.min()
    dense = solve_line_contact(h, dx, 85e9, load=12.5, tolerance=1e-10)
    assert 5 < dense.contact.sum() <= 64  # on the dense path (n_contact^2 <= 4 * 2048)
    _tune(monkeypatch, dense_max=0)
    fft = solve_line_contact(h, dx, 85e9, load=12.5, tolerance=1e-10)
    assert dense.converged and fft.converged
    assert np.array_equal(dense.contact, fft.contact)
    assert np.abs(dense.pressure - fft.pressure).max() < 1e-7 * fft.max_pressure
    A = strip_influence((np.arange(n)[:, None] - np.arange(n)[None, :]) * dx, dx, 85e9, n * dx)
    p_direct, _ = _direct_solution_with(A, h, 12.5 / (n * dx), start=dense.contact)
    assert np.abs(dense.pressure - p_direct).max() < 1e-7 * p_direct.max()


def _direct_solution_with(A, h, mean_pressure, start):
    """The direct active-set reference started from a given contact set (large grids)."""
    n = h.size
    contact = start.copy()
    for _ in range(50):
        idx = np.flatnonzero(contact)
        m = idx.size
        system = np.zeros((m + 1, m + 1))
        system[:m, :m] = A[np.ix_(idx, idx)]
        system[:m, m] = -1.0
        system[m, :m] = 1.0
        solution = np.linalg.solve(system, np.concatenate([-h[idx], [mean_pressure * n]]))
        p = np.zeros(n)
        p[idx] = solution[:m]
        gap = h + A[:, idx] @ solution[:m] - solution[m]
        new = (contact & (p > 0)) | (~contact & (gap < -1e-15 * np.ptp(h)))
        if np.array_equal(new, contact):
            return p, solution[m]
        contact = new
    raise AssertionError("direct reference did not settle")


@pytest.mark.parametrize("path", ["direct", "dense-cg"])
def test_small_grid_dense_paths_match_fft_path(monkeypatch, path):
    """Small periodic grids (FFT size <= _DENSE_GRID): contact sets up to _DIRECT_MAX are solved by
    Cholesky ("direct"), or else by the CG on dense matrices of a working set that contains the
    contact set, masked when larger ("dense-cg"): the same solution as the FFT path."""
    import memstribo.physics.contact as contact_module
    import memstribo.physics.contact.line as contact_line

    n, length = 512, 1e-6
    dx = length / n
    h = -_rough(n, length, 1e-9, seed=5)
    h -= h.min()
    mean_pressure = 0.08 * E * np.std(np.diff(h)) / dx
    calls = {"matrix": 0, "restricted": 0, "direct": 0}
    original_matrix, original_restricted = contact_module.HalfPlane.matrix, contact_module.HalfPlane.restricted
    original_direct = contact_line._direct_solution

    def matrix(self, indices, kernel, offsets=None):
        calls["matrix"] += 1
        return original_matrix(self, indices, kernel, offsets)

    def restricted(self, values, indices, symbol):
        calls["restricted"] += 1
        return original_restricted(self, values, indices, symbol)

    def direct(*args):
        calls["direct"] += 1
        return original_direct(*args)

    monkeypatch.setattr(contact_module.HalfPlane, "matrix", matrix)
    monkeypatch.setattr(contact_module.HalfPlane, "restricted", restricted)
    monkeypatch.setattr(contact_line, "_direct_solution", direct)
    if path == "dense-cg":
        _tune(monkeypatch, direct_max=0)
    dense = solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=True, tolerance=1e-12)
    if path == "direct":
        assert calls["direct"] >= 2  # the final contact set was solved directly
        assert dense.residual < 1e-13  # exact solve: rounding only
    else:
        assert calls["direct"] == 0 and calls["matrix"] >= 2  # influence + preconditioner matrices ...
        assert calls["restricted"] < 2 * dense.iterations  # ... for most CG iterations (not the first, full set)
    used_fft = calls["restricted"]
    _tune(monkeypatch, dense_max=0)
    _tune(monkeypatch, direct_max=0)
    fft = solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=True, tolerance=1e-12)
    assert calls["restricted"] - used_fft >= 2 * fft.iterations  # FFT path only
    assert dense.converged and fft.converged
    assert 0.05 < dense.contact.mean() < 0.4
    assert np.array_equal(dense.contact, fft.contact)
    assert np.abs(dense.pressure - fft.pressure).max() < 1e-10 * fft.max_pressure
    assert dense.approach == pytest.approx(fft.approach, rel=1e-12, abs=1e-12 * np.ptp(h))
    # the independent dense reference (explicit cosine sum, exact solves)
    p_direct, _ = _direct_solution(_dense_operator(n, dx, True, None), h, mean_pressure)
    assert np.abs(dense.pressure - p_direct).max() < 1e-9 * p_direct.max()


def test_direct_path_falls_back_to_cg_when_cholesky_fails(monkeypatch):
    import memstribo.physics.contact.dense as contact_dense

    n, dx = 400, 1e-9
    x = (np.arange(n) - n / 2 + 0.5) * dx
    h = x**2 / (2 * R)
    direct = solve_line_contact(h, dx, E, load=W, tolerance=1e-10)

    calls = []

    def not_definite(names, arrays):  # LAPACK potrf reporting "not positive definite" (info > 0)
        calls.append(names)
        return (lambda a, **kwargs: (a, 1)), (lambda c, b, **kwargs: (b, 0))

    monkeypatch.setattr(contact_dense, "_lapack_cholesky", lambda: not_definite(("potrf", "potrs"), None))
    fallback = solve_line_contact(h, dx, E, load=W, tolerance=1e-10)
    assert calls  # the direct path was tried
    assert direct.converged and fallback.converged
    assert np.array_equal(direct.contact, fallback.contact)
    assert np.abs(direct.pressure - fallback.pressure).max() < 1e-8 * direct.max_pressure


@pytest.mark.parametrize("load_factor", [0.25, 1.0, 10.0])  # ~5 %, ~20 %, ~90 % contact
def test_cold_start_on_the_lower_gap_same_answer_as_uniform_start(monkeypatch, load_factor):
    from memstribo.physics.contact import settings as contact_settings

    n, length = 1024, 1e-6
    dx = length / n
    h = -_rough(n, length, 1e-9, seed=7)
    mean_pressure = load_factor * 0.08 * E * np.std(np.diff(h)) / dx
    solutions = []
    for fraction in (contact_settings.DEFAULTS.start_fraction, 1.0):
        _tune(monkeypatch, start_fraction=fraction)
        solutions.append(solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=True, tolerance=1e-11))
    lower, uniform = solutions
    assert lower.converged and uniform.converged
    assert np.array_equal(lower.contact, uniform.contact)
    assert np.abs(lower.pressure - uniform.pressure).max() < 1e-8 * uniform.max_pressure


def test_small_problem_measures_same_answer_as_large_problem_path(monkeypatch):
    """Up to _SMALL_PROBLEM elements: direct solves, cold start, short coarse levels; above: the
    plain nested CG levels. Both give the same solution."""
    n, length = 2048, 1e-6
    dx = length / n
    h = -_rough(n, length, 1e-9, seed=11)
    mean_pressure = 0.08 * E * np.std(np.diff(h)) / dx
    small = solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=True, tolerance=1e-11)
    _tune(monkeypatch, small_problem=0)
    large = solve_line_contact(h, dx, E, mean_pressure=mean_pressure, periodic=True, tolerance=1e-11)
    assert small.converged and large.converged
    assert (small.iterations, small.coarse_iterations) != (large.iterations, large.coarse_iterations)
    assert np.array_equal(small.contact, large.contact)
    assert np.abs(small.pressure - large.pressure).max() < 1e-8 * large.max_pressure


def test_an_absurdly_soft_body_is_reported_not_a_crash():
    """A 1 Pa modulus (issue #15: ZeroDivisionError inside the CG) ends as a result flagged unconverged."""
    from memstribo.physics.contact import cylinder_on_flat, solve_line_contact

    separation, dx = cylinder_on_flat(10e-6, 400e-9, 512)
    solution = solve_line_contact(separation, dx, 1.0, load=1.0)
    assert isinstance(solution.converged, bool) and (solution.converged or "NOT converged" in solution.message)
