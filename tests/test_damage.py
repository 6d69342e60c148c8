"""Damage accumulation in the coating (thesis 5.5, (5-10), Tables 5-3 and 5-4) and lifetimes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from memstribo.physics.damage import (
    calibrate_damage_coefficient,
    cyclic_peak_loads,
    cycles_to_failure,
    cycles_to_stiction,
    damage_after,
    damage_sum,
    load_peaks,
    nanoblock_damage,
    principal_shear_profile,
    surface_stresses,
    worn_fraction,
)
from memstribo.errors import InputError

# thesis Table 5-1 (nanoblock loads [N]), Table 5-3 (m = 1, Pa) and Table 5-4 (m = 2, Pa^2): max omega/c1, location x [m]
from memstribo.parameters.thesis_tables import TABLE_5_1_LOADS, TABLE_5_3, TABLE_5_4


# --- surface stresses ---------------------------------------------------------------------------------------


def _hertz_surface(xi, nu):
    """Hertz's surface stresses / p0 along a diameter (Johnson 1985, (3.45))."""
    r = np.abs(xi)
    s = np.sqrt(np.clip(1 - r ** 2, 0, None))
    inner = np.where(r < 1, 1 - s ** 3, 1.0)
    radial = (1 - 2 * nu) / 3 / r ** 2 * inner - s
    hoop = -(1 - 2 * nu) / 3 / r ** 2 * inner - 2 * nu * s
    return radial, hoop


@pytest.mark.parametrize("nu", [0.0, 0.23, 0.3])
def test_surface_stresses_reproduce_hertz(nu):
    xi = np.array([-1.4, -1.2, -0.8, -0.5, -0.2, 0.3, 0.7, 0.9, 1.3])
    s = surface_stresses(xi, 2.0, 0.0, nu)
    radial, hoop = _hertz_surface(xi, nu)
    # discretisation: 400 cells over the diameter; the edge kink (|xi| = 1) is excluded
    np.testing.assert_allclose(s["sigma_xx"], radial, atol=2e-3)
    np.testing.assert_allclose(s["sigma_yy"], hoop, atol=2e-3)
    centre = surface_stresses(0.0, 2.0, 0.0, nu)
    assert float(centre["sigma_xx"]) == pytest.approx(-(1 + 2 * nu) / 2, abs=2e-3)


@pytest.mark.parametrize("nu", [0.0, 0.3])
def test_surface_stress_of_hertz_traction(nu):
    """Sliding sphere, traction mu p0 sqrt(1 - r^2/a^2): sigma_x = -pi (4 + nu)/8 mu p0 x/a (Johnson 1985, 7.2)."""
    xi = np.array([-0.8, -0.5, -0.2, 0.2, 0.5, 0.8])
    with_traction = surface_stresses(xi, 2.0, 1.0, nu)["sigma_xx"]
    without = surface_stresses(xi, 2.0, 0.0, nu)["sigma_xx"]
    np.testing.assert_allclose((with_traction - without) / xi, -math.pi * (4 + nu) / 8, rtol=2e-3)


@pytest.mark.parametrize("degree, mu", [(2.0, 0.3), (4.0, 0.1)])
def test_fft_surface_solution_agrees_with_stresses_module(degree, mu):
    """Two independent surface solutions: FFT over cells (damage) and exact integration (stresses)."""
    from memstribo.physics.damage import normalised_principal_shear

    xi = np.concatenate([np.linspace(-1.5, -1.2, 4), np.linspace(-0.85, 0.85, 10), np.linspace(1.2, 1.5, 4)])
    fft = surface_stresses(xi, degree, mu, 0.23)["tau1"]
    exact = normalised_principal_shear(xi, degree, mu, 0.23)
    np.testing.assert_allclose(fft, exact, atol=3e-3 * exact.max())  # 0.3 %: the FFT cell discretisation
    # at the contact edge tau_1 has a cusp: the cell solution converges slowly there (about h^0.6)
    assert float(surface_stresses(-1.0, degree, mu, 0.23)["tau1"]) < float(normalised_principal_shear(-1.0, degree,
                                                                                                       mu, 0.23))


def test_principal_shear_scales_with_load():
    """For a power-law punch tau_1 scales as P^((d-1)/(d+1)) at fixed x/a."""
    x = np.linspace(-10e-9, 10e-9, 41)
    e_star, b = 84.996e9, 4e22
    t1 = principal_shear_profile(x, 1e-7, 4, b, e_star, 0.1, 0.23)
    t2 = principal_shear_profile(x * 2 ** 0.2, 2e-7, 4, b, e_star, 0.1, 0.23)  # a ~ P^(1/5)
    np.testing.assert_allclose(t2, t1 * 2 ** 0.6, rtol=1e-9)
    assert np.all(principal_shear_profile(x, 0.0, 4, b, e_star, 0.1, 0.23) == 0)


# --- the damage law -----------------------------------------------------------------------------------------


def test_damage_sum_is_5_10():
    amplitudes = np.array([1e9, 2e9, 3e9])
    assert damage_sum(amplitudes, 1) == pytest.approx(6e9)
    assert damage_sum(amplitudes, 2, 1e-20) == pytest.approx(1e-20 * 14e18)


@pytest.mark.parametrize("kwargs, match", [
    (dict(damage_exponent=0), "damage_exponent"),
    (dict(damage_exponent=-1), "damage_exponent"),
    (dict(damage_coefficient=-1e-20), "damage_coefficient"),
    (dict(damage_coefficient=0.0), "damage_coefficient"),
])
def test_damage_sum_bad_input(kwargs, match):
    arguments = dict(stress_amplitude=[1e9], damage_exponent=1.0, damage_coefficient=1.0) | kwargs
    with pytest.raises(InputError, match=match):
        damage_sum(**arguments)


def test_cyclic_peak_loads():
    np.testing.assert_array_equal(cyclic_peak_loads([1.0, 2.0, 3.0], 7), [1, 2, 3, 1, 2, 3, 1])
    with pytest.raises(InputError, match="loads"):
        cyclic_peak_loads([1.0, -2.0], 4)
    with pytest.raises(InputError, match="peaks_per_cycle"):
        cyclic_peak_loads([1.0], 0)


def test_load_peaks_and_valleys():
    history = np.array([[0, 1], [2, 3], [1, 1], [3, 2], [0, 0]], dtype=float)
    peak, valley, block = load_peaks(history)
    np.testing.assert_array_equal(block, [0, 0, 1, 1])
    np.testing.assert_array_equal(peak, [2, 3, 3, 2])
    np.testing.assert_array_equal(valley, [0, 1, 0, 1])


# --- thesis Tables 5-3 and 5-4 ------------------------------------------------------------------------------


@pytest.fixture
def table_params(params):
    return params  # asperity_friction_coefficient = 0.1, d = 4, B_4 = 4e22, 3 x 3 asperities at 58.4 nm


def test_table_5_3_m1(table_params):
    result = nanoblock_damage(TABLE_5_1_LOADS, table_params.updated({"damage_exponent": 1}))
    for position, (value, location) in TABLE_5_3.items():
        # mu = 0.1 (inferred, docs/damage.md): 3-5 % above the printed values (three digits: a rounding of 0.2 %,
        # which the model does not meet), location within 0.15 nm
        assert 1.02 < result.maximum[position] / value < 1.055, position
        assert result.location[position] == pytest.approx(location, abs=0.15e-9)
    # life of the corner asperity 9 % shorter than the central one (thesis); ours 9.5 %
    assert 1 - result.life_ratio_corner_to_central == pytest.approx(0.09, abs=0.01)


def test_table_5_4_m2(table_params):
    result = nanoblock_damage(TABLE_5_1_LOADS, table_params.updated({"damage_exponent": 2}))
    for position, (value, location) in TABLE_5_4.items():
        # Table 5-4 prints seven digits (0.1706082e20: a rounding of 3e-7 relative), which the model does not meet:
        # with the inferred mu = 0.1 its maxima come out 19-23 % above the thesis and 0.76-0.79 nm further out
        # (docs/damage.md, section 4: the m = 2 excess says the thesis's peaks spread their stress amplitudes
        # differently). The band pins that documented excess instead of hiding it under rel=0.25.
        assert 1.18 < result.maximum[position] / value < 1.24, position
        assert 0.70e-9 < location - result.location[position] < 0.85e-9, position
    # corner life 18.65 % shorter (thesis); ours 19.7 %
    assert 1 - result.life_ratio_corner_to_central == pytest.approx(0.1865, abs=0.015)


def test_corner_damages_most(table_params):
    result = nanoblock_damage(TABLE_5_1_LOADS, table_params)
    assert result.maximum["corner"] > result.maximum["side"] > result.maximum["central"] > 0


@pytest.mark.parametrize("m", [1.0, 2.0])
def test_damage_scales_with_load_as_the_stress_solution(params, m):
    """One asperity (no load sharing): omega/c1 ~ P^(m (d-1)/(d+1)) exactly (d = 4: P^(0.6 m))."""
    single = params.updated({"atomic_per_side": 1, "damage_exponent": m})
    base = nanoblock_damage([1e-7], single, peaks_per_cycle=1).maximum["central"]
    doubled = nanoblock_damage([2e-7], single, peaks_per_cycle=1).maximum["central"]
    assert doubled / base == pytest.approx(2 ** (0.6 * m), rel=2e-3)  # rel: the x grid's resolution
    # and linearly with the number of peaks (linear summation)
    assert nanoblock_damage([1e-7], single, peaks_per_cycle=10).maximum["central"] == pytest.approx(10 * base)


# --- lifetime -----------------------------------------------------------------------------------------------


def test_damage_never_decreases():
    cycles = np.linspace(0, 1e6, 101)
    omega = damage_after(cycles, [2.5e10, 2.3e10], 1e-16)
    assert np.all(np.diff(omega, axis=0) >= 0)
    assert np.all((omega >= 0) & (omega <= 1))


def test_cycles_to_failure_and_calibration():
    assert cycles_to_failure(2.5e10, 4e-16) == pytest.approx(1e5)
    c1 = calibrate_damage_coefficient(2.5e10, 1e5)
    assert cycles_to_failure(2.5e10, c1) == pytest.approx(1e5)
    assert math.isinf(cycles_to_failure(0.0, 1e-16))
    with pytest.raises(InputError, match="damage_coefficient"):
        cycles_to_failure(2.5e10, -1.0)
    with pytest.raises(InputError, match="observed"):
        calibrate_damage_coefficient(2.5e10, 0)


def test_worn_fraction_and_stiction():
    lives = np.array([100.0, 100.0, 200.0, 300.0])
    np.testing.assert_allclose(worn_fraction([0, 99, 100, 250, 300], lives), [0, 0, 0.5, 0.75, 1.0])
    assert np.all(np.diff(worn_fraction(np.linspace(0, 400, 50), lives)) >= 0)
    assert cycles_to_stiction(lives, 0.6) == 200.0
    assert cycles_to_stiction(lives, 0.5) == 100.0
    assert cycles_to_stiction(lives, None) is None  # F_f < F_t even bare: never
    assert cycles_to_stiction(np.array([100.0, np.inf]), 0.9) is None


def test_stiction_only_when_friction_reaches_tangential_force(params):
    """cycles_to_stiction is the first N at which Omega(N) reaches the wear where F_f >= F_t."""
    import xarray as xr

    from memstribo.physics.damage import run_damage

    p = params.updated({"damage_coefficient": 1e-16})
    sweep = xr.Dataset({"cof_mean": ("wear", [0.2, 0.5, 0.8]), "stiction_margin": ("wear", [1e-3, 5e-4, -5e-4])},
                       coords={"wear": [0.0, 0.5, 1.0]})
    outcome = run_damage(p, loads=TABLE_5_1_LOADS, wear_sweep=sweep, figures=False)
    s = outcome.summary
    assert s["critical_wear"] == pytest.approx(0.75)
    lives = s["cycles_to_failure_by_position"]
    # corners (4/9) then sides (8/9 >= 0.75): stiction when the side asperities' coating fails
    assert s["cycles_to_stiction"] == pytest.approx(lives["side"])
    assert s["cycles_to_failure"] == pytest.approx(lives["corner"])
    history = outcome.datasets["damage_history"]
    margin = history["stiction_margin"].values
    cycles = history["cycles"].values
    assert np.all(margin[cycles < s["cycles_to_stiction"]] > 0)
    assert np.all(np.diff(history["worn_fraction"].values) >= 0)
    no_stiction = sweep.assign(stiction_margin=("wear", [1e-3, 5e-4, 1e-4]))
    assert run_damage(p, loads=TABLE_5_1_LOADS, wear_sweep=no_stiction, figures=False).summary[
        "cycles_to_stiction"] is None


# --- CLI ----------------------------------------------------------------------------------------------------


def test_cli_damage_table_loads(cli):
    out = cli.json("damage", "--loads", "table5-1")
    assert set(out["omega_over_c1_max"]) == {"corner", "side", "central"}
    assert out["omega_over_c1_max"]["corner"] == pytest.approx(0.248e11, rel=0.06)
    assert out["life_ratio_corner_to_central"] == pytest.approx(0.91, abs=0.01)
    assert "cycles_to_failure" not in out
    m2 = cli.json("damage", "--loads", "table5-1", "--set", "damage_exponent=2")
    assert 1.18 < m2["omega_over_c1_max"]["corner"] / 0.1706082e20 < 1.24  # Table 5-4, 19-23 % high (test_table_5_4_m2)


def test_cli_damage_units_in_loads(cli):
    a = cli.json("damage", "--loads", "0.8166 uN,7.0165 uN")
    b = cli.json("damage", "--loads", "8.166e-7,7.0165e-6")
    assert a == b


@pytest.mark.parametrize("argv, match", [
    (["--loads", "1 uN,-2 uN"], "loads"),
    (["--loads", "1 m"], "loads"),
    (["--loads", "table5-1", "--set", "damage_coefficient=-1"], "damage_coefficient"),
    (["--loads", "table5-1", "--set", "damage_exponent=0"], "damage_exponent"),
    (["--loads", "table5-1", "--set", "asperity_degree=0"], "asperity_degree"),
    (["--loads", "table5-1", "--observed-life", "-5"], "observed-life"),
    (["--loads", "table5-1", "--coating", "wax"], "unknown coating"),
])
def test_cli_damage_bad_input(cli, argv, match):
    code, out, err = cli("damage", *argv)
    assert code == 2
    assert match in err and "Traceback" not in err


# --- from the meshing cycle ---------------------------------------------------------------------------------


def test_mesh_damage_from_block_loads(params):
    from memstribo.simulations import mesh
    from memstribo.physics.coating import get_coating
    from memstribo.physics.damage import mesh_damage

    dataset = mesh.simulate_mesh(params, steps=24, coating=get_coating("OTS"), wear=0.0)
    result = mesh_damage(dataset, params)
    gear_blocks = int((dataset["block_flank"].values == "gear").sum())
    assert result.omega_over_c1.shape[:2] == (gear_blocks, 9)
    assert result.peaks_per_cycle.sum() > 0
    assert result.maximum["corner"] > result.maximum["central"] > 0
    assert np.all(result.omega_over_c1 >= 0)
    # a block that never carries load is never damaged
    assert np.all(result.per_asperity[result.peaks_per_cycle == 0] == 0)
    with pytest.raises(InputError, match="block_load"):
        mesh_damage(dataset.drop_vars("block_load"), params)


def test_cli_damage_from_the_mesh_with_c1(cli, tmp_path):
    out = cli.json("damage", "--steps", "24", "--wear-points", "2", "--set", "damage_coefficient=1e-15",
                   "--out", tmp_path)
    assert set(out["omega_over_c1_max"]) == {"corner", "side", "central"}
    assert out["cycles_to_failure"] == pytest.approx(1 / (1e-15 * out["omega_over_c1_max"]["corner"]))
    assert "cycles_to_stiction" in out
    assert out["life_ratio_corner_to_central"] < 1
    for stem in ("damage_profile", "damage_history", "coating_wear"):
        assert (tmp_path / f"{stem}.nc").exists() and (tmp_path / f"{stem}.csv").exists()
    for stem in ("damage_profile", "damage_map", "damage_history", "pressure_and_tau1", "tau1_corner_loads"):
        assert (tmp_path / f"{stem}.png").exists() and (tmp_path / f"{stem}.svg").exists()


def test_damage_grid_takes_a_bounded_set_of_contact_edges_and_chunks_give_the_same_sum(params, monkeypatch):
    """The x grid holds the contact edges of at most _MAX_EDGE_LOADS distinct loads (the largest half of them
    and evenly spaced others, smallest included); summing the profiles in chunks of peaks changes nothing."""
    import memstribo.physics.damage as damage
    from memstribo.simulations import mesh

    few = np.arange(1.0, 11.0)
    np.testing.assert_array_equal(damage._edge_loads(few), few)
    many = np.sort(np.random.default_rng(3).uniform(1e-9, 1e-6, 5000))
    picked = damage._edge_loads(many)
    assert picked.size == damage._MAX_EDGE_LOADS and np.all(np.diff(picked) > 0)
    np.testing.assert_array_equal(picked[-damage._MAX_EDGE_LOADS // 2:], many[-damage._MAX_EDGE_LOADS // 2:])
    assert picked[0] == many[0]

    dataset = mesh.simulate_mesh(params, steps=24)
    whole = damage.mesh_damage(dataset, params)
    assert whole.x.size <= 501 + 2 * damage._MAX_EDGE_LOADS
    monkeypatch.setattr(damage, "_CHUNK_VALUES", 1)  # one peak per chunk
    chunked = damage.mesh_damage(dataset, params)
    np.testing.assert_array_equal(chunked.x, whole.x)
    np.testing.assert_allclose(chunked.omega_over_c1, whole.omega_over_c1, rtol=1e-12, atol=0.0)


def test_damage_maximum_is_resolved_and_does_not_hang_on_round_off(params):
    """On the coated meshing cycle (tens of thousands of distinct asperity loads) the second pass adds every
    contact edge near the largest values: the maximum then matches a 100x finer grid around it (0.2 %), and
    loads changed by round-off (1e-13, which breaks ties and so changes which edges the first grid holds)
    leave it alone. Without that pass the maximum fell 0.2-3 % short and moved by 0.8 % between two runs
    whose loads differed by round-off (docs/damage.md, "Resolution of the maximum")."""
    import memstribo.physics.damage as damage
    from memstribo.physics.coating import get_coating
    from memstribo.simulations import mesh

    dataset = mesh.simulate_mesh(params, coating=get_coating("OTS", params), wear=0.0)
    base = damage.mesh_damage(dataset, params)
    noise = 1.0 + 1e-13 * np.random.default_rng(5).standard_normal(dataset["block_load"].shape)
    other = damage.mesh_damage(dataset.assign(block_load=dataset["block_load"] * noise), params)
    # the worked numbers of docs/damage.md (`memstribo damage --observed-life 1e5`, printed to 4 digits)
    assert base.maximum["corner"] == pytest.approx(10.23e9, rel=1e-3)
    assert base.maximum["side"] == pytest.approx(9.682e9, rel=1e-3)
    assert base.maximum["central"] == pytest.approx(9.038e9, rel=1e-3)
    assert base.life_ratio_corner_to_central == pytest.approx(0.8836, abs=2e-4)
    spacing = 2.5 * base.x.max() / 1.25 / (damage._UNIFORM_POINTS - 1)
    for position in ("corner", "side", "central"):
        assert other.maximum[position] == pytest.approx(base.maximum[position], rel=1e-9)
        location = base.location[position]
        fine = damage.mesh_damage(dataset, params, x=np.linspace(location - 2 * spacing, location + 2 * spacing, 401))
        assert base.maximum[position] == pytest.approx(fine.maximum[position], rel=2e-3)
