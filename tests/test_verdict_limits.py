"""What the verdict hangs on (MODEL 7d, issue #26): the lattice registry per row, the start-up verdict, the local
limits, the pressure capped at the hardness, and a window that sizes itself."""

import json
import math
from types import SimpleNamespace

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.physics import friction
from memstribo.physics.contact import solve_line_contact, solve_line_contact_capped
from memstribo.simulations.mesh import simulate_mesh, summarize
from memstribo.simulations.mesh.limits import formed_share, startup_and_limits, stiction_mode
from memstribo.simulations.mesh.setup import _prepare, lattice_registry

STEPS = 41


@pytest.fixture(scope="module")
def default_cycle():
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    return params, simulate_mesh(params, steps=STEPS)


# ----------------------------------------------------------------------------------------------- start-up verdict
def test_peak_bond_force_is_the_largest_slope_of_the_lennard_jones_bond():
    """A bond of energy U at equilibrium distance D (sigma = D 2^(-1/6), 3-16): the largest |dU/dr| of the 12-6 law
    lies at r* = (26/7)^(1/6) sigma, where it is (24 U / sigma) (7/26)^(7/6) (12/26)."""
    u, d = 0.543e-18, 0.235e-9
    sigma = d * 2 ** (-1 / 6)
    written = 24 * u / sigma * (7 / 26) ** (7 / 6) * (12 / 26)
    assert friction.peak_bond_force(1.0, u, d) == pytest.approx(written, rel=1e-12)
    assert friction.peak_bond_force(1.0, u, d) == pytest.approx(2.6899 * u / d, rel=1e-4)
    # the slope at r* is the largest: a finite-difference scan of the same law finds no larger one
    r = np.linspace(0.9 * d, 3 * d, 20001)
    lj = 4 * u * ((sigma / r) ** 12 - (sigma / r) ** 6)
    assert np.max(np.diff(lj) / np.diff(r)) == pytest.approx(written, rel=1e-4)
    assert friction.peak_bond_force(7.0, u, d) == pytest.approx(7 * written, rel=1e-12)


def _one_block_cycle(bonds, params, rows=1, phases=None, rho=(4e-6, 20e-6)):
    """A cycle of three rest positions whose middle one holds ``bonds`` chemical bonds in each of ``rows`` rows (at
    ``phases``), one pair in mesh at the radii of curvature ``rho``."""
    u, d = params["bond_energy"], params["bond_length"]
    zeros = np.zeros(3)
    row_bonds = np.zeros((3, 3, rows))
    row_bonds[0, 1, :] = bonds
    f_chem = row_bonds[0].sum(axis=1) * u / d  # its kinetic force (3-1, 3.5)
    out = {"f_chem": f_chem, "f_vdw": zeros, "f_cap": zeros, "f_vdw_capped": zeros, "f_vdw_over": zeros,
           "f_chem_rigid": zeros, "row_bonds": row_bonds}
    rb1, rb2, rw1 = 10e-6, 40e-6, 11e-6
    pair = SimpleNamespace(first_contact=-1.0, last_contact=1.0, base_pitch=10.0, base_radii=np.array([rb1, rb2]),
                           pitch_radii=np.array([rw1, 4 * rw1]),
                           radii_of_curvature=lambda c: (np.full(np.shape(c), rho[0]), np.full(np.shape(c), rho[1])))
    registry = SimpleNamespace(bond_phase=np.zeros(rows) if phases is None else np.asarray(phases))
    setup = SimpleNamespace(pair=pair, positions=np.array([-1.0, 0.0, 1.0]), registry=registry)
    cycle = {"out": out, "f_el": zeros, "kin": {"sliding": np.ones(3)}}
    verdict = {"friction_avg": f_chem / 3, "averaging": 1.0, "energy": f_chem}
    return startup_and_limits(params, setup, cycle, verdict), (rb1, rb2, rw1, rho)


def test_a_single_block_starts_at_the_lateral_peak_of_its_bonds_through_its_moment_arm(params):
    """One row of N chemical bonds at rest, every bond formed: the bonds, sheared sideways, resist with N times the
    lateral peak of the 12-6 law (1.2687 U / D, not the axial 2.69 U / D); the drive torque needed is that force times
    r_b1 |rho1 / r_b1 - rho2 / r_b2| (the rigid-body balance), as a force at the pitch radius."""
    n = 1000.0
    u, d = params["bond_energy"], params["bond_length"]
    limits, (rb1, rb2, rw1, (rho1, rho2)) = _one_block_cycle(n, params)
    peak = n * 1.2686660 * u / d
    assert limits["static"][1] == pytest.approx(peak, rel=1e-6)
    assert limits["startup_resisting"][1] == pytest.approx(peak * rb1 * abs(rho1 / rb1 - rho2 / rb2) / rw1, rel=1e-6)
    # a load torque on the gear adds T_L r_b1 / (r_b2 r_w1) at every rest position
    loaded, _ = _one_block_cycle(n, params.updated({"load_torque": 1e-9}))
    np.testing.assert_allclose(loaded["startup_resisting"] - limits["startup_resisting"], 1e-9 * rb1 / (rb2 * rw1))
    # after a dwell, the logarithmic ageing share of them (Li et al. 2011)
    dwelt = params.updated({"startup_dwell": 1.0, "ageing_onset_time": 0.1, "ageing_full_time": 1000.0})
    share = math.log1p(10.0) / math.log1p(1e4)
    assert formed_share(dwelt) == pytest.approx(share)
    assert _one_block_cycle(n, dwelt)[0]["static"][1] == pytest.approx(share * peak, rel=1e-12)
    assert formed_share(params.updated({"startup_dwell": 0.0})) == 0.0
    assert formed_share(params) == 1.0  # unset: every bond formed


def test_rows_out_of_phase_start_more_easily_than_rows_in_phase(params):
    """Ten rows of equal bond populations: in phase (a shared registry) 10 peaks; at random phases less, never
    below the mean over the offset."""
    from memstribo.physics.static_friction import bond_lateral_mean

    n, u, d = 500.0, params["bond_energy"], params["bond_length"]
    shared, _ = _one_block_cycle(n, params, rows=10)
    random, _ = _one_block_cycle(n, params, rows=10, phases=np.random.default_rng(4).random(10))
    assert shared["static"][1] == pytest.approx(10 * n * 1.2686660 * u / d, rel=1e-6)
    assert 10 * n * bond_lateral_mean() * u / d <= random["static"][1] < 0.8 * shared["static"][1]


def test_start_up_against_the_running_verdict(default_cycle):
    _, ds = default_cycle
    summary = summarize(ds)
    assert summary["stiction_mode"] == stiction_mode(summary["stiction_margin"], summary["startup_margin"])
    assert summary["startup_stiction"] == (summary["startup_margin"] < 0)
    assert summary["stiction"] == (summary["stiction_margin"] < 0)  # the running verdict keeps its names
    # the start-up force of a pair never exceeds its rows' bonds all at their lateral peak, plus the rest
    peak = 1.2686660 * (ds.friction_force_chemical + ds.friction_force_vdw) + ds.friction_force_elastic
    assert np.all(ds.static_friction_force.values <= peak.values * (1 + 1e-9) + 1e-15)
    assert {"bonds_chemical_row", "bonds_vdw_bare_row", "bond_phase"} <= set(ds.variables)
    np.testing.assert_allclose(ds.bonds_chemical_row.sum("row"), ds.bonds_chemical, rtol=1e-12)


def test_a_shared_registry_starts_no_more_easily_than_a_random_one(params):
    """MODEL 7f, issue #35 done-when: --set lattice_registry=shared gives a start-up force at least as large as
    random (the rows' bond forces in phase add their peaks)."""
    random = summarize(simulate_mesh(params, steps=41))
    shared = summarize(simulate_mesh(params.updated({"lattice_registry": "shared"}), steps=41))
    r_random = random["tangential_force"] - random["startup_margin"]
    r_shared = shared["tangential_force"] - shared["startup_margin"]
    assert r_shared >= r_random


def test_stiction_mode_names_the_verdict_that_fails():
    assert stiction_mode(-1.0, -2.0) == "running"
    assert stiction_mode(1.0, -2.0) == "start-up"
    assert stiction_mode(1.0, 0.5) == "none"


# ----------------------------------------------------------------------------------------------- local limits
def test_local_limits_are_one_warning_with_the_capped_margins(default_cycle, params):
    _, ds = default_cycle
    summary = summarize(ds)
    warnings = summary["warnings"]
    about = [w for w in warnings if "threshold strain" in w]
    assert len(about) == 1 and "capped" in about[0] and "verdict" in about[0]
    assert not any(" in 41 step(s)" in w for w in warnings)  # no per-step count
    # a chemical bond population transmits U / D^3 = 41.8 GPa, beyond the ideal shear strength: its share is the
    # chemical friction's, and capping it can only lower the friction
    stress = params["bond_energy"] / params["bond_length"] ** 3
    assert stress / 1e9 == pytest.approx(41.8, abs=0.05) and stress > params["ideal_shear_strength"]
    assert summary["friction_share_overstrength"] >= summary["cof_chemical"] / summary["cof_mean"] - 1e-12
    assert 0 < summary["friction_share_rigid"] <= summary["cof_chemical"] / summary["cof_mean"] + 1e-12
    assert summary["stiction_margin_capped"] >= summary["stiction_margin"]
    assert summary["startup_margin_capped"] >= summary["startup_margin"]
    assert f"{summary['stiction_margin_capped'] * 1e6:.4g} µN" in about[0]


# ----------------------------------------------------------------------------------------------- lattice registry
def test_the_registry_is_drawn_apart_from_the_roughness(params):
    random = lattice_registry(params, 20, 0)
    assert random.mode == "random"
    assert np.all((random.pinion_phase >= 0) & (random.pinion_phase < params["adhesive_width"]))
    assert np.all((random.gear_pitch_scale >= 1.0) & (random.gear_pitch_scale <= math.sqrt(2) + 1e-12))
    assert np.unique(random.gear_phase).size == 20
    np.testing.assert_array_equal(lattice_registry(params, 20, 0).gear_phase, random.gear_phase)  # seeded
    assert not np.array_equal(lattice_registry(params, 20, 1).gear_phase, random.gear_phase)
    shared = lattice_registry(params.updated({"lattice_registry": "shared"}), 20, 0)
    assert not shared.pinion_phase.any() and not shared.gear_phase.any() and np.all(shared.gear_pitch_scale == 1)
    # the roughness lines are the same under either registry (its own stream of the seed)
    a = _prepare(params, None, 11)
    b = _prepare(params.updated({"lattice_registry": "shared"}), None, 11)
    for (xa, za), (xb, zb) in zip(a.pinion_profiles + a.gear_profiles, b.pinion_profiles + b.gear_profiles):
        np.testing.assert_array_equal(za, zb)


@pytest.mark.slow
def test_the_chemical_friction_fluctuates_less_on_a_wider_face(params):
    """Issue #26: with a registry per row the chemical spikes of the rows no longer add in phase: its step-to-step
    fluctuation/mean at 8 um face width falls below 0.7x that at 2 um (thesis load case, no zone), as the vdW
    friction's does; a registry shared by every row keeps it (the spikes at the same positions)."""
    base = params.updated({"load_case": "thesis", "contact_adhesion": "none"})

    def fluctuation(registry, width):
        ds = simulate_mesh(base.updated({"lattice_registry": registry, "face_width": width}), steps=241)
        chem = ds.friction_force_chemical.values
        return chem.std() / chem.mean()

    assert fluctuation("random", 8e-6) < 0.7 * fluctuation("random", 2e-6)
    assert fluctuation("shared", 8e-6) > 0.9 * fluctuation("shared", 2e-6)


# ----------------------------------------------------------------------------------------------- the hardness cap
def _rough_gap(n=512, seed=3):
    rng = np.random.default_rng(seed)
    q = np.fft.rfftfreq(n)
    spectrum = np.zeros(q.size, complex)
    spectrum[1:] = q[1:] ** -1.6 * np.exp(2j * np.pi * rng.random(q.size - 1))
    z = np.fft.irfft(spectrum, n)
    z *= 5e-9 / z.std()
    return z - z.min(), 2e-9


def test_the_capped_contact_meets_the_elastic_plastic_conditions():
    """Elastic-perfectly-plastic line contact: 0 <= p <= H, the gap closed where 0 < p < H, closed or penetrating
    where p = H, open where p = 0 (checked with numpy's FFT, not the solver's operator), and the load kept."""
    h, dx = _rough_gap()
    modulus, load = 90e9, 2e9 * 512 * 2e-9
    plain = solve_line_contact(h, dx, modulus, load=load, periodic=True, tolerance=1e-10)
    hardness = 0.5 * plain.pressure.max()  # a cap well inside the elastic peak
    result = solve_line_contact_capped(h, dx, modulus, hardness=hardness, load=load, periodic=True,
                                       tolerance=1e-10)
    p = result.solution.pressure
    assert result.solution.converged and result.plastic.any() and result.updates >= 1
    assert p.max() <= hardness * (1 + 1e-12) and p.min() >= 0
    assert p.sum() * dx == pytest.approx(load, rel=1e-9)
    q = 2 * np.pi * np.fft.rfftfreq(h.size, dx)
    pk = np.fft.rfft(p)
    uk = np.zeros_like(pk)
    uk[1:] = 2 * pk[1:] / (modulus * q[1:])
    total = h + np.fft.irfft(uk, h.size)
    elastic = (p > 0) & ~result.plastic
    gap = total - total[elastic].mean()
    scale = np.ptp(h)
    assert np.abs(gap[elastic]).max() < 1e-8 * scale
    assert gap[result.plastic].max() < 1e-8 * scale
    assert gap[p == 0].min() > -1e-8 * scale
    assert np.all(result.plastic_depth[result.plastic] >= 0)
    assert result.plastic_fraction == pytest.approx(result.plastic.sum() / result.solution.contact.sum())
    # a cap above the elastic peak, or none, is the elastic solution itself, bit for bit
    for cap in (None, 2 * plain.pressure.max()):
        same = solve_line_contact_capped(h, dx, modulus, hardness=cap, load=load, periodic=True, tolerance=1e-10)
        np.testing.assert_array_equal(same.solution.pressure, plain.pressure)
        assert not same.plastic.any()


def test_a_real_scan_reports_its_plastic_flow_and_both_margins(params, afm_dir):
    ds = simulate_mesh(params, afm_dir / "si_profile_linescan.txt", steps=STEPS)
    summary = summarize(ds)
    assert summary["hardness"] == params["hardness"]
    assert 0 < summary["plastic_fraction"] <= summary["plastic_fraction_max"] <= 1
    # the cap holds wherever the capped solve converged; a step where it did not is flagged and warned about
    converged = np.asarray(ds.contact_converged, dtype=bool)
    pressure = np.asarray(ds.max_contact_pressure)
    assert summary["plastic_steps"] > 0 and pressure[converged].max() <= params["hardness"] * (1 + 1e-9)
    if not converged.all():
        assert any(f"did not converge in {int((~converged).sum())} step(s)" in w for w in summary["warnings"])
    assert {"stiction_margin_uncapped", "startup_margin_uncapped", "cof_mean_uncapped"} <= set(summary)
    assert summary["stiction_margin_uncapped"] != summary["stiction_margin"]
    assert any("hardness" in w and "purely elastic" in w for w in summary["warnings"])
    assert not any("window" in w for w in summary["warnings"])
    elastic = summarize(simulate_mesh(params.updated({"hardness": None}), afm_dir / "si_profile_linescan.txt",
                                      steps=STEPS))
    assert elastic["stiction_margin"] == pytest.approx(summary["stiction_margin_uncapped"], rel=1e-12)
    assert elastic["plastic_fraction"] == 0 and elastic["max_contact_pressure"] > params["hardness"]


# ----------------------------------------------------------------------------------------------- the window
def test_the_window_sizes_itself_to_hold_the_contact(params, afm_dir):
    """A rough map whose contact outgrows the Hertz-sized window: the window grows until no step reaches its ends;
    a window set by the user stays as set and says how to let it size itself."""
    ds = simulate_mesh(params, afm_dir / "di-3.di", steps=STEPS)
    summary = summarize(ds)
    sized = _prepare(params, None, STEPS)
    assert summary["window"] > sized.grid.size * sized.grid_spacing
    assert summary["window_exceeded_steps"] == 0
    assert not any("window" in w for w in summary["warnings"])
    fixed = simulate_mesh(params.updated({"mesh_window": "1.3 um", "mesh_grid_spacing": "10 nm"}), steps=11)
    text = json.loads(fixed.attrs["warnings"])
    assert any("mesh_window is set; unset it" in w for w in text)


# ----------------------------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("change, message", [
    ({"hardness": "50 GPa"}, "hardness .* above what the ideal shear strength allows"),
    ({"startup_dwell": -1.0}, "startup_dwell.*outside its range"),
    ({"ageing_onset_time": "-1 s"}, "ageing_onset_time.*outside its range"),
    ({"ageing_full_time": 0.0}, "ageing_full_time.*outside its range"),
    ({"load_torque": "-1 nN m"}, "load_torque.*outside its range"),
    ({"load_torque": 1.0}, "load_torque.*outside its range"),
    ({"lattice_registry": "aligned"}, "lattice_registry"),
])
def test_bad_options_are_refused(params, change, message):
    with pytest.raises(InputError, match=message):
        params.updated(change)


def test_a_bad_hardness_is_refused_by_the_solver():
    h, dx = _rough_gap(128)
    with pytest.raises(InputError, match="hardness"):
        solve_line_contact_capped(h, dx, 90e9, hardness=-1.0, load=1.0, periodic=True)


def test_the_start_up_verdict_calls_the_bond_law(params, monkeypatch):
    """The start-up force is the published relation's (static_friction.population_static_force): replacing it
    changes the verdict."""
    from memstribo.physics import static_friction

    before = summarize(simulate_mesh(params, steps=11))["startup_margin"]
    real = static_friction.population_static_force
    monkeypatch.setattr(static_friction, "population_static_force", lambda *a, **k: 2.0 * np.asarray(real(*a, **k)))
    after = summarize(simulate_mesh(params, steps=11))["startup_margin"]
    assert after < before


def test_the_cap_is_switched_off_from_the_command_line(params):
    assert params.updated({"hardness": "unset"})["hardness"] is None
    assert params.updated({"hardness": "11 GPa"})["hardness"] == pytest.approx(11e9)


def test_the_report_gives_both_verdicts_and_the_limits():
    from memstribo.job.chain import verdict
    from memstribo.job.report import _startup_items

    summary = {"load_case": "torque", "resisting_force_max": 1.9e-3, "stiction_margin": 0.9e-3, "cof_mean": 0.48,
               "startup_margin": -3.3e-3, "startup_stiction": True, "static_cof_max": 2.3, "stiction_mode": "start-up",
               "stiction_margin_capped": 1.4e-3, "startup_margin_capped": -1.0e-3, "stiction_mode_capped": "start-up",
               "plastic_fraction": 0.07, "stiction_margin_uncapped": 0.95e-3}
    items = " ".join(_startup_items(verdict({"mesh": summary})))
    assert "does NOT start" in items and "start-up margin -3.3 mN" in items
    assert "capped" in items and "Plastic flow: 7 %" in items and "purely elastic" in items
    assert _startup_items(verdict({"mesh": {**summary, "startup_stiction": False, "startup_margin": 1e-4}}))[0].count(
        "starts") == 1


def test_the_start_up_verdict_rescales_with_the_bond_energies_exactly(params):
    """The uncertainty study rescales bond energies without a new solve (issue 27): the start-up margin too, from
    the rows' bond counts (issue #35 item 5), equal to the re-solved cycle's."""
    from memstribo.uncertainty.rescale import rescale_cycle

    dataset = simulate_mesh(params, steps=21)
    # the default vdW rule (hysteresis, MODEL 7h) samples phi; U_vdW itself only under the thesis rule
    assert params["vdw_energy_rule"] == "hysteresis"
    with pytest.raises(InputError, match="vdw_dissipated_fraction"):
        rescale_cycle(dataset, params, {"vdw_bond_energy": 3 * params["vdw_bond_energy"]})
    changed = {"vdw_dissipated_fraction": 0.4, "bond_energy": 0.8 * params["bond_energy"]}
    rescaled = rescale_cycle(dataset, params, changed)
    solved = summarize(simulate_mesh(params.updated(changed), steps=21))
    for key in ("startup_margin", "static_cof_max", "startup_margin_capped"):
        assert rescaled[key] == pytest.approx(solved[key], rel=1e-9)
    assert rescaled["startup_stiction"] == solved["startup_stiction"]
    assert rescaled["stiction_mode"] == solved["stiction_mode"] and rescaled["verdict"] == solved["verdict"]


def test_the_capped_start_up_force_is_the_ideal_shear_strength_over_the_bonds_area(params):
    """Local limits at start-up (issue #41's escaped bug: the capped start-up margin without its peak ratio): a bond
    population at its lateral peak transmits 1.2687 U / D^3 = 53 GPa; capped at the ideal shear strength tau, its N
    bonds over N D^2 carry tau N D^2, whatever U, through the same moment arm as the uncapped force."""
    n = 1000.0
    d, tau = params["bond_length"], params["ideal_shear_strength"]
    assert 1.2686660 * params["bond_energy"] / d ** 3 > tau  # the cap binds
    limits, (rb1, rb2, rw1, (rho1, rho2)) = _one_block_cycle(n, params)
    lever = rb1 * abs(rho1 / rb1 - rho2 / rb2) / rw1
    assert limits["startup_resisting_capped"][1] == pytest.approx(n * tau * d ** 2 * lever, rel=1e-9)
    assert limits["startup_resisting"][1] == pytest.approx(n * 1.2686660 * params["bond_energy"] / d * lever, rel=1e-6)
