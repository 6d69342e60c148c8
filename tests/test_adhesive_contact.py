"""Adhesive (Maugis-Dugdale) line contact: solver, closed forms, pull-off, CLI (docs/contact.md, model §7c)."""

from __future__ import annotations

import contextlib
import io
import json
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from memstribo.physics.adhesive_contact import line_contact_pull_off, load_approach_curve
from memstribo.physics.contact import solve_line_contact
from memstribo.errors import InputError
from memstribo.physics.closed_form import (dugdale_rigid_line_pull_off, hertz_line_half_width, jkr_line_load,
                                 jkr_line_pull_off_half_width, jkr_line_pull_off_load, maugis_dugdale_line_load,
                                 maugis_dugdale_line_pull_off, maugis_line_parameter)

# silicon teeth (docs/model.md §2, §3): E* = 85 GPa, w = A/(12 pi D0^2), sigma0 = 16 w/(9 sqrt 3 D0), h0 = w/sigma0
E_STAR, W, SIGMA0 = 85e9, 0.445, 1.78e9
H0 = W / SIGMA0


def _tune(monkeypatch, **fields):
    """Replace fields of the contact solvers' default settings for one test (:mod:`memstribo.physics.contact.settings`)."""
    import dataclasses

    from memstribo.physics.contact import settings

    monkeypatch.setattr(settings, "DEFAULTS", dataclasses.replace(settings.DEFAULTS, **fields))


def cylinder(n, length, radius):
    dx = length / n
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    return x**2 / (2.0 * radius), dx


def rough(n, dx, rms, seed=1):
    rng = np.random.default_rng(seed)
    q = 2 * np.pi * np.fft.rfftfreq(n, dx)
    amplitude = np.zeros_like(q)
    amplitude[1:] = q[1:] ** -1.3
    z = np.fft.irfft(amplitude * (rng.normal(size=q.size) + 1j * rng.normal(size=q.size)), n)
    z *= rms / z.std()
    return z.max() - z


# ----------------------------------------------------------------------------- closed forms


def test_jkr_line_closed_forms():
    R = 10e-6
    a_c = float(jkr_line_pull_off_half_width(R, E_STAR, W))
    p_c = float(jkr_line_pull_off_load(R, E_STAR, W))
    assert p_c == pytest.approx(float(jkr_line_load(a_c, R, E_STAR, W)), rel=1e-12)
    # the minimum of P(a)
    for factor in (0.9, 1.1):
        assert float(jkr_line_load(factor * a_c, R, E_STAR, W)) > p_c
    # w = 0: Hertz
    a = float(hertz_line_half_width(3.0, R, E_STAR))
    assert float(jkr_line_load(a, R, E_STAR, 0.0)) == pytest.approx(3.0, rel=1e-12)


def test_maugis_dugdale_line_limits():
    R = 10e-6
    assert float(maugis_line_parameter(R, E_STAR, W, SIGMA0)) == pytest.approx(3.548, abs=1e-3)
    # large sigma0 (JKR): the load at a half-width and the pull-off tend to JKR
    load, c = maugis_dugdale_line_load(100e-9, R, E_STAR, W, 100 * SIGMA0)
    assert load == pytest.approx(float(jkr_line_load(100e-9, R, E_STAR, W)), rel=1e-4)
    assert 100e-9 < c < 100.1e-9
    pull, width = maugis_dugdale_line_pull_off(R, E_STAR, W, 100 * SIGMA0)
    assert pull == pytest.approx(float(jkr_line_pull_off_load(R, E_STAR, W)), rel=1e-4)
    assert width == pytest.approx(float(jkr_line_pull_off_half_width(R, E_STAR, W)), rel=1e-3)
    # small sigma0 (rigid Derjaguin limit, 2 sigma0 sqrt(2 R h0)), lambda = 0.002
    pull, width = maugis_dugdale_line_pull_off(R, E_STAR, W, 1e6)
    assert -pull == pytest.approx(float(dugdale_rigid_line_pull_off(R, W, 1e6)), rel=1e-3)


# ----------------------------------------------------------------------------- solver: limits and balance


def test_no_adhesion_is_the_plain_solver():
    h, dx = cylinder(1024, 200e-9, 20e-6)
    plain = solve_line_contact(h, dx, 100e9, load=1.0)
    assert plain.adhesive_load == 0.0 and plain.cohesive is None
    zero = solve_line_contact(h, dx, 100e9, load=1.0, cohesive_stress=0.0, cohesive_range=0.0)
    assert zero.converged and zero.adhesive_load == 0.0 and not zero.cohesive.any()
    np.testing.assert_allclose(zero.pressure, plain.pressure, rtol=0, atol=1e-6 * plain.max_pressure)
    assert zero.approach == pytest.approx(plain.approach, rel=1e-6)
    # a vanishing work of adhesion (sigma0 -> 0 at fixed h0) tends to Hertz
    weak = solve_line_contact(h, dx, 100e9, load=1.0, cohesive_stress=1e3, cohesive_range=H0)
    assert weak.converged
    assert weak.contact_length == pytest.approx(plain.contact_length, abs=2.1 * dx)
    assert weak.contact_length / 2 == pytest.approx(float(hertz_line_half_width(1.0, 20e-6, 100e9)), rel=0.03)


def test_approach_control_reproduces_load_control():
    h, dx = cylinder(1024, 200e-9, 20e-6)
    plain = solve_line_contact(h, dx, 100e9, load=1.0)
    controlled = solve_line_contact(h, dx, 100e9, approach=plain.approach)
    assert controlled.converged
    assert controlled.load == pytest.approx(1.0, rel=1e-6)
    adhesive = solve_line_contact(h, dx, E_STAR, load=5.0, cohesive_stress=SIGMA0, cohesive_range=H0)
    back = solve_line_contact(h, dx, E_STAR, approach=adhesive.approach, cohesive_stress=SIGMA0, cohesive_range=H0,
                              initial_pressure=adhesive.pressure)
    assert back.converged
    assert back.load == pytest.approx(5.0, abs=1e-3 * adhesive.adhesive_load)


@pytest.mark.parametrize("load", [60.0, 0.0, -60.0])
def test_silicon_cylinder_against_maugis_dugdale(load):
    """Si/Si tooth, R = 10 um, lambda = 3.55: the half-width at a load matches Baney-Hui's cylinder."""
    R = 10e-6
    h, dx = cylinder(2048, 1000e-9, R)
    sol = solve_line_contact(h, dx, E_STAR, load=load, cohesive_stress=SIGMA0, cohesive_range=H0)
    assert sol.converged, sol.message
    # force balance: net load = dx sum(p) = imposed load
    assert sol.load == pytest.approx(load, abs=1e-10 * sol.adhesive_load)
    assert abs(sol.load - dx * sol.pressure.sum()) <= 1e-12 * sol.adhesive_load
    a = sol.contact_length / 2
    a_md = brentq(lambda s: maugis_dugdale_line_load(s, R, E_STAR, W, SIGMA0)[0] - load, 30e-9, 500e-9)
    assert a == pytest.approx(a_md, abs=2.1 * dx)  # contact_length counts whole elements
    # Dugdale law: p >= -sigma0; the tensile zone beyond the contact
    assert sol.pressure.min() >= -SIGMA0 * (1 + 1e-12)
    assert sol.adhesive_load == pytest.approx(SIGMA0 * dx * -sol.pressure[sol.cohesive].sum() / SIGMA0, rel=1e-12)
    outside = ~sol.contact
    assert np.all(sol.gap[outside & (sol.pressure == 0)] > H0 * (1 - 1e-6))
    assert np.all(sol.gap[outside & (sol.pressure == -SIGMA0)] <= H0 * (1 + 1e-6))
    # JKR is 3-6 % off at lambda = 3.55 (neither JKR nor DMT, model §7c)
    a_jkr = brentq(lambda s: float(jkr_line_load(s, R, E_STAR, W)) - load, 70e-9, 500e-9)
    assert 0.01 < 1 - a / a_jkr < 0.08


def test_large_maugis_parameter_matches_jkr():
    """R = 100 um (lambda = 7.6): load vs half-width within 1.5 % of JKR in a."""
    R = 100e-6
    h, dx = cylinder(2048, 3e-6, R)
    for load in (-100.0,):
        sol = solve_line_contact(h, dx, E_STAR, load=load, cohesive_stress=SIGMA0, cohesive_range=H0)
        assert sol.converged, sol.message
        a_jkr = brentq(lambda s: float(jkr_line_load(s, R, E_STAR, W)) - load, 300e-9, 2e-6)
        assert sol.contact_length / 2 == pytest.approx(a_jkr, rel=0.015)


def test_periodic_and_free_boundary():
    R = 10e-6
    h, dx = cylinder(2048, 1000e-9, R)
    free = solve_line_contact(h, dx, E_STAR, load=0.0, cohesive_stress=SIGMA0, cohesive_range=H0)
    periodic = solve_line_contact(h, dx, E_STAR, load=0.0, cohesive_stress=SIGMA0, cohesive_range=H0, periodic=True)
    assert periodic.converged and periodic.periodic
    assert abs(periodic.load) <= 1e-10 * periodic.adhesive_load
    # the periodic images (one cylinder per micrometre) change the half-width by a few per cent only
    assert periodic.contact_length == pytest.approx(free.contact_length, rel=0.05)


def test_rough_free_boundary_consistency():
    n, dx = 2048, 0.25e-9
    h = rough(n, dx, 1e-9)
    load = 0.05 * E_STAR * n * dx * 0.05
    plain = solve_line_contact(h, dx, E_STAR, load=load)
    sol = solve_line_contact(h, dx, E_STAR, load=load, cohesive_stress=SIGMA0, cohesive_range=H0)
    assert sol.converged, sol.message
    assert sol.load == pytest.approx(load, rel=1e-10)
    assert sol.contact.sum() > plain.contact.sum()  # adhesion pulls more of the surfaces into contact
    assert sol.pressure.min() >= -SIGMA0 * (1 + 1e-12)
    outside = ~sol.contact
    assert np.all(sol.gap[outside & (sol.pressure == 0)] > H0 * (1 - 1e-6))
    assert np.all(sol.gap[outside & (sol.pressure == -SIGMA0)] <= H0 * (1 + 1e-6))
    # warm start from the solution: the same state, at once
    again = solve_line_contact(h, dx, E_STAR, load=load, cohesive_stress=SIGMA0, cohesive_range=H0,
                               initial_pressure=sol.pressure)
    assert again.converged
    # the same state: the zone's load to 1e-4; single front elements within the zone tolerance (0.25)
    assert again.adhesive_load == pytest.approx(sol.adhesive_load, rel=1e-3)
    np.testing.assert_allclose(again.pressure, sol.pressure, atol=0.26 * SIGMA0)
    assert np.count_nonzero(np.abs(again.pressure - sol.pressure) > 1e-3 * SIGMA0) <= 0.02 * n  # the fronts


# ----------------------------------------------------------------------------- instability, pull-off


def test_load_approach_hysteresis():
    """Jump-in on loading, adhered unloading below zero load down to pull-off: the branches differ."""
    h, dx = cylinder(1024, 600e-9, 10e-6)
    # free-boundary datum: without load the surfaces touch at approach 0; start 2 h0 apart
    approaches = np.linspace(-2 * H0, 1.5e-9, 12)
    loading, state = load_approach_curve(h, dx, E_STAR, approaches, cohesive_stress=SIGMA0, cohesive_range=H0)
    assert loading.converged.all()
    assert loading.half_width[0] == 0.0 and loading.load[0] == 0.0  # apart: no force
    jump = int(np.flatnonzero(loading.half_width > 0)[0])
    assert loading.half_width[jump] > 100e-9 and loading.load[jump] < -30.0  # jump-in: a wide contact at once
    assert np.all(loading.half_width[:jump] == 0.0)
    unloading, _ = load_approach_curve(h, dx, E_STAR, approaches[::-1], cohesive_stress=SIGMA0, cohesive_range=H0,
                                       initial_pressure=state)
    assert unloading.converged.all()
    back_load, back_width = unloading.load[::-1], unloading.half_width[::-1]
    # hysteresis: before the jump-in point the unloading branch is still in contact, under tension
    assert np.all(back_width[:jump] > 100e-9) and np.all(back_load[:jump] < -40.0)
    # where both are in contact they are the same state (up to one element at the contact edges)
    np.testing.assert_allclose(back_width[jump:], loading.half_width[jump:], atol=1.01 * dx)
    np.testing.assert_allclose(back_load[jump:], loading.load[jump:], atol=1.0)


def test_pull_off_silicon():
    result = line_contact_pull_off(10e-6, E_STAR, W, SIGMA0, points=1024)
    assert result.converged, result.message
    assert result.maugis_parameter == pytest.approx(3.548, abs=1e-3)
    reference, width = maugis_dugdale_line_pull_off(10e-6, E_STAR, W, SIGMA0)
    assert result.pull_off_line_load == pytest.approx(-reference, rel=0.005)
    assert result.pull_off_half_width == pytest.approx(width, rel=0.05)
    assert result.pull_off_line_load == pytest.approx(-float(jkr_line_pull_off_load(10e-6, E_STAR, W)), rel=0.01)
    assert np.all(np.diff(result.curve.approach) < 0)  # unloading


def test_pull_off_small_maugis_parameter_is_rigid_dugdale():
    """lambda = 0.1: the 2D 'DMT' limit is the rigid Dugdale pull-off 2 sigma0 sqrt(2 R h0) (not 2 w R)."""
    sigma0 = 5e7
    result = line_contact_pull_off(10e-6, E_STAR, W, sigma0, points=1024)
    assert result.converged, result.message
    assert result.maugis_parameter == pytest.approx(0.0997, abs=1e-3)
    reference, _ = maugis_dugdale_line_pull_off(10e-6, E_STAR, W, sigma0)
    assert result.pull_off_line_load == pytest.approx(-reference, rel=0.005)
    assert result.pull_off_line_load == pytest.approx(float(dugdale_rigid_line_pull_off(10e-6, W, sigma0)), rel=0.03)


def test_past_pull_off_under_load_control_is_reported():
    h, dx = cylinder(1024, 800e-9, 10e-6)
    sol = solve_line_contact(h, dx, E_STAR, load=-200.0, cohesive_stress=SIGMA0, cohesive_range=H0)
    assert not sol.converged
    assert "NOT converged" in sol.message


# ----------------------------------------------------------------------------- input errors


@pytest.mark.parametrize("kwargs, name", [
    (dict(cohesive_stress=-1.0, cohesive_range=H0), "cohesive_stress"),
    (dict(cohesive_stress=SIGMA0, cohesive_range=-1e-10), "cohesive_range"),
    (dict(cohesive_stress=SIGMA0), "cohesive_range"),
    (dict(cohesive_stress=np.nan, cohesive_range=H0), "cohesive_stress"),
])
def test_bad_cohesive_input(kwargs, name):
    h, dx = cylinder(256, 200e-9, 10e-6)
    with pytest.raises(InputError, match=name):
        solve_line_contact(h, dx, E_STAR, load=1.0, **kwargs)


def test_bad_control_input():
    h, dx = cylinder(256, 200e-9, 10e-6)
    with pytest.raises(InputError, match="exactly one"):
        solve_line_contact(h, dx, E_STAR, load=1.0, approach=0.0, cohesive_stress=SIGMA0, cohesive_range=H0)
    with pytest.raises(InputError, match="load"):
        solve_line_contact(h, dx, E_STAR, load=-1.0)  # tensile load without adhesion
    with pytest.raises(InputError, match="initial_pressure"):
        solve_line_contact(h, dx, E_STAR, load=1.0, cohesive_stress=SIGMA0, cohesive_range=H0,
                           initial_pressure=np.full(256, -2 * SIGMA0))
    with pytest.raises(InputError, match="cohesive_stress"):
        line_contact_pull_off(10e-6, E_STAR, W, -1.0)


# ----------------------------------------------------------------------------- CLI


def _cli(argv):
    from memstribo.cli.main import main

    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        code = main(list(argv) + ["--json"])
    return code, buffer.getvalue()


def test_cli_adhesion_json():
    code, text = _cli(["contact", "--flat", "--radius", "10 um", "--modulus", "85 GPa", "--load", "10 N/m",
                       "--points", "1024", "--length", "800 nm", "--adhesion", "--set", "hamaker_constant=1.1e-18"])
    assert code == 0, text
    out = json.loads(text)
    assert out["adhesive_load"] > 0 and out["load"] == pytest.approx(10.0, rel=1e-8)
    assert out["maugis_parameter"] == pytest.approx(3.55, abs=0.02)
    assert out["cohesive_stress"] == pytest.approx(SIGMA0, rel=0.01)


def test_cli_pull_off_json():
    # the thesis's Hamaker constant (the default is the Lifshitz value since issue 38): lambda = 3.55, JKR-like
    code, text = _cli(["contact", "--flat", "--radius", "10 um", "--modulus", "85 GPa", "--points", "1024",
                       "--adhesion", "--pull-off", "--set", "hamaker_constant=1.1e-18"])
    assert code == 0, text
    out = json.loads(text)
    for key in ("pull_off_line_load", "maugis_parameter", "pull_off_half_width"):
        assert key in out
    # the JKR line-contact pull-off (3/4)(4 pi E* w^2 R)^(1/3) (Chaudhury et al. 1996; docs/contact.md), w from
    # the set's A / (12 pi D0^2) (3-34); at lambda = 3.55 the Maugis-Dugdale solve lies within 1 % of it
    w = 1.1e-18 / (12 * math.pi * (2.56e-10) ** 2)
    jkr = 0.75 * (4 * math.pi * 85e9 * w**2 * 10e-6) ** (1 / 3)  # 96.31 N/m
    assert out["pull_off_line_load"] == pytest.approx(jkr, rel=0.01)


def test_cli_bad_cohesive_override():
    from memstribo.cli.main import main

    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()) as err:
        code = main(["contact", "--flat", "--radius", "10 um", "--adhesion", "--cohesive-stress", "-1 GPa", "--json"])
    assert code != 0
    assert "--cohesive-stress" in err.getvalue()


def test_adhesive_solve_cites_its_sources():
    """An adhesive solve records the adhesive BEM papers; an approach-controlled solve without adhesion does not."""
    from memstribo.physics import closed_form as reference
    from memstribo.references import REFERENCES, reset_used_references, used_references

    h, dx = cylinder(256, 512e-9, 10e-6)
    reset_used_references()
    solve_line_contact(h, dx, 85e9, approach=0.1e-9)
    assert "rey_2017" not in dict(used_references())
    solve_line_contact(h, dx, 85e9, load=1.0, cohesive_stress=1.78e9, cohesive_range=0.25e-9)
    keys = dict(used_references())
    assert {"maugis_1992", "rey_2017", "bazrafshan_2017"} <= set(keys)
    for function in (reference.maugis_line_parameter, reference.maugis_dugdale_line_load,
                     reference.maugis_dugdale_line_pull_off, reference.dugdale_rigid_line_pull_off):
        assert {"baney_hui_1997", "johnson_greenwood_2008"} <= set(function.references)
    for key in ("rey_2017", "bazrafshan_2017", "baney_hui_1997", "johnson_greenwood_2008"):
        assert "doi:10." in REFERENCES[key]


def test_limit_cycle_of_the_zone_is_damped(monkeypatch):
    """A step of the thesis load case (interface_model=thesis, 567 points, warm start): the plain zone update cycles.

    With period 11 an element at a front creeps, its neighbour jumps, it falls back; the update is
    under-relaxed once the largest change of the fraction has stopped shrinking, and the zone settles.
    """
    from pathlib import Path

    case = np.load(Path(__file__).parent / "data" / "adhesive_limit_cycle.npz")
    kwargs = dict(load=float(case["load"]), tolerance=float(case["tolerance"]), initial_pressure=case["initial_pressure"],
                  cohesive_stress=float(case["cohesive_stress"]), cohesive_range=float(case["cohesive_range"]))
    sol = solve_line_contact(case["separation"], float(case["dx"]), float(case["modulus"]), **kwargs)
    assert sol.converged, sol.message
    assert sol.load == pytest.approx(kwargs["load"], rel=1e-9)
    assert np.all(sol.pressure >= -kwargs["cohesive_stress"] * (1 + 1e-12))
    # with the Aitken extrapolation's former cap (0.95; the cap of 0.9 since issue #25 avoids this cycle,
    # docs/interface.md) the damping settles it, and without the damping it cycles
    _tune(monkeypatch, aitken_max_ratio=0.95)
    assert solve_line_contact(case["separation"], float(case["dx"]), float(case["modulus"]), **kwargs).converged
    _tune(monkeypatch, stalled_updates=10**6)
    plain = solve_line_contact(case["separation"], float(case["dx"]), float(case["modulus"]), **kwargs)
    assert not plain.converged and "did not settle" in plain.message


def _solved_zones(dx):
    """The zones the solve uses for (SIGMA0, H0) on a grid of spacing dx [m]: the zone 9.3 nm wide is not resolved by
    10 nm elements, so the solve keeps w and widens it (memstribo.physics.contact.subgrid.resolved_zones)."""
    from memstribo.physics.contact.settings import DEFAULTS
    from memstribo.physics.contact.subgrid import resolved_zones

    zones = resolved_zones(dx, E_STAR, SIGMA0, H0, DEFAULTS.zone_elements, DEFAULTS.contact_only_range)[0]
    return zones or ((SIGMA0, H0),)


def _reference_dense_fixed_point(h, dx, modulus, total, sigma, h0, p_start, tolerance, zones=None):
    """The dense cohesive-zone fixed point as first written (commit fcc53e9): one Cholesky factorisation per
    contact set solved and the vectorised cohesive fraction; (p, contact, fraction, updates) or None.
    ``zones``: several (stress, range) zones instead of (sigma, h0), ``sigma`` their summed stress."""
    from memstribo.physics.contact import cohesive, dense, halfplane
    from memstribo.physics.contact.settings import DEFAULTS as tuning

    def cohesive_fraction(gap, contact):
        if zones is None:
            return cohesive._cohesive_fraction(gap, h0, contact, False)
        return cohesive._cohesive_fraction(gap, None, contact, False, zones=zones)

    n = h.size
    matrix = halfplane._full_matrix(n, dx, modulus, False, n * dx)
    scale = float(h.max())
    fraction = np.minimum(np.clip(-p_start / sigma, 0.0, 1.0) + (p_start > 0.0), 1.0)
    contact = p_start > 0.0
    gaps = []
    for outer in range(1, tuning.adhesive_max_outer + 1):
        extra = sigma * fraction.sum()
        h_eff = h - sigma * (matrix @ fraction) if fraction.any() else h
        for _ in range(tuning.max_outer):  # the non-adhesive problem for p+ on the settled contact set
            indices = np.flatnonzero(contact)
            p_c, delta = dense._saddle_point(matrix[indices[:, None], indices], h_eff[indices], total + extra)
            p_plus = np.zeros(n)
            p_plus[indices] = p_c
            gap = h_eff + matrix @ p_plus - delta
            new = (contact & (p_plus > 0.0)) | (~contact & (gap < -tolerance * scale))
            if np.array_equal(new, contact):
                break
            contact = new
        else:
            return None
        gap[contact] = 0.0
        new = cohesive_fraction(gap, contact)
        step = np.abs(new - fraction)
        change = step.max()
        if change <= tuning.fraction_tolerance or (change <= tuning.zone_max_change and step.sum()
                                               <= tuning.zone_load_tolerance * max(float(new[~contact].sum()), 1.0)):
            return p_plus - sigma * fraction, contact, fraction, outer
        gaps.append(gap)
        if len(gaps) >= 3 and outer % 3 == 0:
            d1, d0 = gaps[-1] - gaps[-2], gaps[-2] - gaps[-3]
            ratio = min(np.dot(d1, d0) / np.dot(d0, d0), tuning.aitken_max_ratio) if np.dot(d0, d0) > 0 else 0.0
            if ratio >= tuning.aitken_min_ratio:
                new = cohesive_fraction(gap + d1 * (ratio / (1.0 - ratio)), contact)
        del gaps[:-3]
        fraction = new
    return None


def test_dense_maugis_solves_follow_the_reference_fixed_point():
    """The small-grid Maugis-Dugdale solve (compiled: reused Cholesky factors, products over the non-zero
    columns) is the fixed point as first written in numpy, update for update: warm-started solves along a rough
    200-element window, as in the meshing cycle, where the state reached depends on the path (jump-in)."""
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.roughness import default_profile

    zone = []  # cohesive line loads outside the contact set
    profile = default_profile(get_parameter_values(), length=8e-6)
    n, dx, tolerance = 200, 10e-9, 1e-8
    x = (np.arange(n) - n / 2) * dx
    previous = None
    updates = []
    for shift in np.arange(12) * 1.5 * dx:  # the window moves by 1.5 elements a step
        rough = np.interp(x + 2.5e-6 + shift, profile.x - profile.x[0], profile.z)
        separation = x**2 / (2 * 20e-6) - rough
        solution = solve_line_contact(separation, dx, E_STAR, load=60.0, tolerance=tolerance, initial_pressure=previous,
                                      cohesive_stress=SIGMA0, cohesive_range=H0)
        assert "dense matrices" in solution.message and solution.converged
        if previous is not None:
            h = separation - separation.min()
            reference = _reference_dense_fixed_point(h, dx, E_STAR, 60.0 / dx, SIGMA0, H0, previous, tolerance,
                                                     zones=_solved_zones(dx))
            assert reference is not None
            p, contact, fraction, outer = reference
            assert solution.iterations == outer and np.array_equal(solution.contact, contact)
            assert np.allclose(solution.pressure, p, rtol=0, atol=1e-9 * np.abs(p).max())
            assert solution.adhesive_load == pytest.approx(SIGMA0 * dx * fraction[solution.cohesive].sum(), rel=1e-9)
            updates.append(outer)
            zone.append(solution.adhesive_load)
        previous = solution.pressure
    assert max(updates) > 1 and max(zone) > 0.0


def test_dense_humid_solves_follow_the_reference_fixed_point():
    """The same with two zones, as in humid air: the Maugis-Dugdale zone and the menisci's Laplace pressure
    over a condensation height that varies per element (zero on some: no meniscus there, not even in
    contact); the compiled loop follows the numpy fixed point update for update."""
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.roughness import default_profile

    profile = default_profile(get_parameter_values(), length=8e-6)
    n, dx, tolerance = 200, 10e-9, 1e-8
    x = (np.arange(n) - n / 2) * dx
    laplace = 1.2e8
    reach = 1.2e-9 * (1.0 + 0.5 * np.sin(np.arange(n) / 7.0))
    reach[::3] = 0.0
    zones = _solved_zones(dx) + ((laplace, reach),)
    previous = None
    updates, wetted = [], []
    for shift in np.arange(10) * 1.5 * dx:
        rough = np.interp(x + 2.5e-6 + shift, profile.x - profile.x[0], profile.z)
        separation = x**2 / (2 * 20e-6) - rough
        solution = solve_line_contact(separation, dx, E_STAR, load=60.0, tolerance=tolerance, initial_pressure=previous,
                                      cohesive_stress=SIGMA0, cohesive_range=H0, capillary_stress=laplace,
                                      capillary_range=reach)
        assert "dense matrices" in solution.message and solution.converged
        if previous is not None:
            h = separation - separation.min()
            reference = _reference_dense_fixed_point(h, dx, E_STAR, 60.0 / dx, SIGMA0 + laplace, None, previous,
                                                     tolerance, zones=zones)
            assert reference is not None
            p, contact, fraction, outer = reference
            assert solution.iterations == outer and np.array_equal(solution.contact, contact)
            assert np.allclose(solution.pressure, p, rtol=0, atol=1e-9 * np.abs(p).max())
            updates.append(outer)
            wetted.append(solution.capillary_load)
        previous = solution.pressure
    assert max(updates) > 1 and min(wetted) > 0.0


def test_sparse_cohesive_fraction_is_the_vectorised_formula(monkeypatch):
    """The fraction evaluated only on the elements within reach of the zone is the vectorised formula's, bit for
    bit (ends, periodic wrap, gaps below zero, contact); with too many such elements it declines (None) and
    :func:`_dense_fraction` takes the vectorised path."""
    from memstribo.physics.contact import cohesive
    from memstribo.physics.contact import dense as c
    from memstribo.physics.contact.settings import DEFAULTS

    def vectorised(gap, r, contact, periodic):
        with monkeypatch.context() as m:
            _tune(m, sparse_fraction_max=-1)
            return c._dense_fraction(gap, ((1.78e9, r),), contact, periodic, settings=DEFAULTS)

    rng = np.random.default_rng(3)
    n, reach = 200, 0.25e-9
    gap = rng.uniform(3e-9, 8e-9, n)
    contact = np.zeros(n, dtype=bool)
    contact[[0, 60, 61, 62, 130]] = True
    gap[contact] = 0.0
    fronts = [1, 59, 63, 64, 129, 131, 199]  # zones beside the contact sets and at both ends
    gap[fronts] = [0.1e-9, 0.3e-9, 0.45e-9, 0.9e-9, 0.2e-9, 0.6e-9, 0.4e-9]
    gap[100] = -1e-12  # a slightly penetrating element outside the set
    evaluated = 0
    for periodic in (False, True):
        for r in (reach, 0.6e-9):
            sparse = c._sparse_fraction(gap, 1.78e9, r, contact, periodic, settings=DEFAULTS)
            expected = vectorised(gap, r, contact, periodic)
            assert sparse is not None and np.array_equal(sparse, expected)
            assert np.array_equal(c._dense_fraction(gap, ((1.78e9, r),), contact, periodic, settings=DEFAULTS), expected)
            assert np.allclose(expected, cohesive._cohesive_fraction(gap, r, contact, periodic), rtol=1e-14, atol=0)
            evaluated += np.count_nonzero((expected > 0) & ~contact)
        wide = 20e-9  # most elements are within reach: the vectorised formula
        assert c._sparse_fraction(gap, 1.78e9, wide, contact, periodic, settings=DEFAULTS) is None
        assert np.array_equal(c._dense_fraction(gap, ((1.78e9, wide),), contact, periodic, settings=DEFAULTS),
                              vectorised(gap, wide, contact, periodic))
    assert evaluated >= 16


# ----------------------------------------------------------------------------- the zone update's inner solves


def _zone_step(sol):
    """Change of each element's cohesive fraction that one more zone update would make (the convergence test's)."""
    from memstribo.physics.contact.cohesive import _cohesive_fraction

    fraction = np.where(sol.contact, 1.0, np.clip(-sol.pressure / SIGMA0, 0.0, 1.0))
    updated = _cohesive_fraction(sol.gap, H0, sol.contact, sol.periodic)
    return np.abs(updated - fraction), float(updated[~sol.contact].sum())


def _former_zone_updates(monkeypatch):
    """The inner solves of the zone updates as before commit ca16598: first set update from the unsolved guess, last p+ as start."""
    _tune(monkeypatch, settle_first=False)
    _tune(monkeypatch, linear_response_start=False)


@pytest.mark.parametrize("exponent, rms, pressure", [
    pytest.param(12, 1.4e-9, 0.0025, marks=pytest.mark.slow),  # the former path's 80 s (issue 40: CI <= 8 min)
    (13, 2e-9, 0.0025), (14, 2e-9, 0.001)])
def test_warm_started_zone_updates_reach_the_former_state(monkeypatch, exponent, rms, pressure):
    """Rough profiles, 2^12-2^14 points: the faster inner solves (docs/contact.md, "Adhesive contact", "Speed") give
    the state of the former ones to the zone's tolerance, and the state keeps the invariants of the Dugdale law."""
    n, dx = 2**exponent, 0.25e-9
    h = rough(n, dx, rms)
    load = pressure * E_STAR * n * dx
    kwargs = dict(load=load, cohesive_stress=SIGMA0, cohesive_range=H0)
    new = solve_line_contact(h, dx, E_STAR, **kwargs)
    assert new.converged, new.message
    # force balance, the Dugdale floor, the zone where the gap is within h0
    assert dx * new.pressure.sum() == pytest.approx(load, rel=1e-10)
    assert new.pressure.min() >= -SIGMA0 * (1 + 1e-12)
    outside = ~new.contact
    assert np.all(new.gap[outside & (new.pressure == -SIGMA0)] <= H0 * (1 + 1e-6))
    assert np.all(new.gap[outside & (new.pressure == 0.0)] >= H0 * (1 - 1e-6))
    step, zone = _zone_step(new)
    assert step.max() <= 1e-4 or (step.max() <= 0.25 and step.sum() <= 1e-4 * max(zone, 1.0))
    assert new.cohesive.sum() > 0.02 * n
    _former_zone_updates(monkeypatch)
    former = solve_line_contact(h, dx, E_STAR, **kwargs)
    assert former.converged, former.message
    assert np.count_nonzero(new.contact != former.contact) <= 2
    assert np.count_nonzero(new.cohesive != former.cohesive) <= 2
    assert new.adhesive_load == pytest.approx(former.adhesive_load, rel=1e-3)
    assert np.linalg.norm(new.pressure - former.pressure) <= 1e-2 * np.linalg.norm(former.pressure)
    assert new.approach == pytest.approx(former.approach, abs=1e-3 * H0)


def test_load_control_may_reach_another_adhered_state(monkeypatch):
    """Under load control a rough profile may have several adhered states; which one the zone iteration reaches
    depends on its path. Here (2^13 points) the former and the new inner solves reach two that differ by 29
    contact elements and 3 % of the zone's load; each is a fixed point (a warm-started solve from it stays)."""
    n, dx = 2**13, 0.25e-9
    h = rough(n, dx, 2e-9)
    kwargs = dict(load=0.001 * E_STAR * n * dx, cohesive_stress=SIGMA0, cohesive_range=H0)
    new = solve_line_contact(h, dx, E_STAR, **kwargs)
    again = solve_line_contact(h, dx, E_STAR, initial_pressure=new.pressure, **kwargs)
    _former_zone_updates(monkeypatch)
    former = solve_line_contact(h, dx, E_STAR, **kwargs)
    former_again = solve_line_contact(h, dx, E_STAR, initial_pressure=former.pressure, **kwargs)
    for state, repeat in ((new, again), (former, former_again)):
        assert state.converged and repeat.converged
        assert np.count_nonzero(state.contact != repeat.contact) <= 2
        assert repeat.adhesive_load == pytest.approx(state.adhesive_load, rel=1e-3)


def test_zone_kernel_compiles_without_a_writable_cache(monkeypatch):
    """Where numba finds no writable cache folder it raises at decoration; the kernel then compiles without
    the cache (once per process) instead of failing the import."""
    from memstribo.physics import _zone_kernel as kernel

    calls = []

    def njit(**options):
        calls.append(options)
        if options.get("cache"):
            raise RuntimeError("cannot cache function 'f': no locator available for file 'f.py'")
        return lambda function: ("compiled", function)

    monkeypatch.setattr(kernel, "njit", njit)

    def function():
        return 0

    assert kernel._jit(function) == ("compiled", function)
    assert calls == [{"cache": True, "nogil": True}, {"nogil": True}]


def _former_loading_start(h, dx, load, p_start):
    """The compiled zone loop as ``_dense_capillary`` ran it before issue 40 with ``cohesive_start = "loading"``: the
    first update's contact set started from the start pressure's (the zone empty). (pressure [Pa], contact set
    reached)."""
    from memstribo.physics.contact import dense
    from memstribo.physics.contact.settings import DEFAULTS
    from memstribo.physics.contact.subgrid import resolved_zones

    n = h.size
    zones, _ = resolved_zones(dx, E_STAR, SIGMA0, H0, DEFAULTS.zone_elements, DEFAULTS.contact_only_range)
    zones = zones or ((SIGMA0, H0),)
    kernel, reverse = dense._toeplitz_kernel(n, dx, E_STAR, False, n * dx)
    sigmas, reaches, per_element, _ = dense._zone_arrays(zones, n)
    shifted = h - h.min()
    contact = p_start > 0.0
    status, p, _, _, _ = dense._compiled().zone_solve(
        kernel, reverse, np.ascontiguousarray(shifted), load / dx, sigmas, reaches, per_element, False, np.zeros(n),
        contact, 1e-8 * shifted.max(), DEFAULTS.adhesive_max_outer, DEFAULTS.max_outer, DEFAULTS.fraction_tolerance,
        DEFAULTS.zone_load_tolerance, DEFAULTS.zone_max_change, DEFAULTS.aitken_min_ratio, DEFAULTS.aitken_max_ratio)
    assert status == 0
    return p, contact


@pytest.mark.parametrize("shift", [2, 7])
def test_a_loading_branch_solve_depends_on_its_own_inputs_alone(monkeypatch, shift):
    """The meshing cycle's solves (``cohesive_start = "loading"``) on a thesis-like grid (1300 elements, a rough
    cylinder, the adhesive contact more than twice the non-adhesive one): the compiled zone loop starts the first update
    (the non-adhesive problem) from the lowest element whatever the start pressure, so a step started from the step
    before (the roughness moved by ``shift`` elements) is the same solve as one without a start, bit for bit; the
    former start (the start pressure's contact set, issue 40) reached the same contact set and the same pressures
    to round-off."""
    _tune(monkeypatch, cohesive_start="loading")
    n, dx = 1300, 0.94e-9
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    line = rough(n + 16, dx, 1.5e-9, seed=3)
    before, step = (x**2 / (2 * 2e-6) + line[s:s + n] for s in (0, shift))
    load = 0.0005 * E_STAR * n * dx
    kwargs = dict(load=load, cohesive_stress=SIGMA0, cohesive_range=H0, tolerance=1e-8)
    previous = solve_line_contact(before, dx, E_STAR, **kwargs).pressure
    started = solve_line_contact(step, dx, E_STAR, initial_pressure=previous, **kwargs)
    cold = solve_line_contact(step, dx, E_STAR, **kwargs)
    assert started.converged and "dense" in started.message
    assert np.array_equal(started.pressure, cold.pressure) and started.approach == cold.approach
    assert np.count_nonzero(started.contact) > 2 * np.count_nonzero(solve_line_contact(step, dx, E_STAR, load=load,
                                                                                       tolerance=1e-8).contact)
    former, contact = _former_loading_start(step, dx, load, previous)
    assert np.array_equal(contact, started.contact)
    assert np.abs(former - started.pressure).max() <= 1e-9 * np.abs(former).max()


def test_a_loading_branch_solve_on_a_small_grid_starts_from_the_start_pressures_contact_set(monkeypatch):
    """Up to ``SolverSettings.loading_start_max`` elements (the default cycle's windows, where a step moves the contact
    by a fraction of its width) the first update starts from the start pressure's contact set as before issue 40: the
    same solve, bit for bit."""
    from memstribo.physics.contact.settings import DEFAULTS

    _tune(monkeypatch, cohesive_start="loading")
    n, dx = 200, 2e-9
    assert n <= DEFAULTS.loading_start_max
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    line = rough(n + 4, dx, 0.5e-9, seed=5)
    before, step = (x**2 / (2 * 2e-6) + line[s:s + n] for s in (0, 1))
    load = 0.002 * E_STAR * n * dx
    kwargs = dict(load=load, cohesive_stress=SIGMA0, cohesive_range=H0, tolerance=1e-8)
    previous = solve_line_contact(before, dx, E_STAR, **kwargs).pressure
    started = solve_line_contact(step, dx, E_STAR, initial_pressure=previous, **kwargs)
    assert started.converged and "dense" in started.message
    former, contact = _former_loading_start(step, dx, load, previous)
    assert np.array_equal(former, started.pressure) and np.array_equal(contact, started.contact)
