"""Capillary condensation relations (issue #17): Kelvin, meniscus forces, their limits (memstribo.physics.capillary)."""

import math

import numpy as np
import pytest

from memstribo.physics.capillary import (capillary_force_cylinder, capillary_force_from_gap, capillary_force_sphere,
                                 capillary_pressure, condensation_height, kelvin_radius, laplace_pressure)
from memstribo.errors import InputError


def _tune(monkeypatch, **fields):
    """Replace fields of the contact solvers' default settings for one test (:mod:`memstribo.physics.contact.settings`)."""
    import dataclasses

    from memstribo.physics.contact import settings

    monkeypatch.setattr(settings, "DEFAULTS", dataclasses.replace(settings.DEFAULTS, **fields))


def test_kelvin_radius_of_water_at_room_temperature():
    # gamma V_m / (R T) = 0.072 * 18.07e-6 / (8.314462618 * 298.15) = 0.5248 nm (about 0.52 nm, issue #17)
    assert kelvin_radius(1 / math.e) == pytest.approx(0.072 * 18.07e-6 / (8.314462618 * 298.15), rel=1e-12)
    assert kelvin_radius(0.5) == pytest.approx(0.5248e-9 / math.log(2), rel=1e-3)
    assert kelvin_radius(0.0) == 0.0  # dry: no meniscus
    radii = kelvin_radius(np.array([0.1, 0.5, 0.9]))
    assert np.all(np.diff(radii) > 0)  # wetter air, flatter menisci
    with pytest.raises(InputError, match="relative_humidity"):
        kelvin_radius(1.0)


def test_sphere_on_a_flat_reaches_four_pi_r_gamma_cos_theta():
    """A numerical meniscus (Laplace pressure over the wetted area of a sphere's gap) against the closed form."""
    radius, theta = 1e-6, math.radians(30)
    r_k = kelvin_radius(0.4)
    dx = 0.5e-9
    x = (np.arange(801) - 400) * dx
    gap = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius)
    numeric = capillary_force_from_gap(gap, dx * dx, r_k, theta)
    assert numeric == pytest.approx(capillary_force_sphere(radius, theta), rel=0.02)
    assert capillary_force_sphere(radius, theta) == pytest.approx(4 * math.pi * radius * 0.072 * math.cos(theta))


def test_cylinder_per_unit_length_against_a_numerical_meniscus():
    radius, theta = 10e-6, math.radians(20)
    r_k = kelvin_radius(0.5)
    dx = 0.05e-9
    x = (np.arange(40001) - 20000) * dx
    numeric = capillary_force_from_gap(x**2 / (2 * radius), dx, r_k, theta)  # per unit length: area dx * 1 m
    assert numeric == pytest.approx(capillary_force_cylinder(radius, r_k, theta), rel=1e-3)


def test_no_capillary_force_when_dry_or_hydrophobic():
    assert capillary_force_cylinder(1e-6, kelvin_radius(0.0), 0.3) == 0.0
    hydrophobic = math.radians(112)  # OTS
    assert condensation_height(kelvin_radius(0.9), hydrophobic) == 0.0
    assert capillary_force_sphere(1e-6, hydrophobic) == 0.0
    assert capillary_force_sphere(1e-6, math.radians(90)) == pytest.approx(0.0, abs=1e-20)
    assert np.all(capillary_pressure(np.zeros(5), kelvin_radius(0.9), hydrophobic) == 0.0)
    # one hydrophilic and one hydrophobic surface: cos 20 + cos 112 > 0, a (weaker) meniscus still forms
    assert condensation_height(kelvin_radius(0.5), math.radians(20), math.radians(112)) > 0


def test_adhesion_grows_with_humidity_on_a_rough_gap():
    """Monotone growth of the wetted area with RH on a rough gap; the Laplace pressure falls: the force over a
    rough line grows with RH (more of the roughness fills)."""
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.roughness import default_profile

    profile = default_profile(get_parameter_values(), length=4e-6)
    gap = np.maximum(profile.z.max() - profile.z, 0.0)  # a flat touching the highest peak
    dx = float(profile.x[1] - profile.x[0])
    theta = math.radians(25)
    wetted = [float(np.sum(capillary_pressure(gap, kelvin_radius(rh), theta) > 0)) for rh in (0.2, 0.5, 0.8, 0.95)]
    assert wetted == sorted(wetted) and wetted[-1] > wetted[0]
    forces = [capillary_force_from_gap(gap, dx * 1e-6, kelvin_radius(rh), theta) for rh in (0.0, 0.3, 0.6, 0.9)]
    assert forces[0] == 0.0 and all(f > 0 for f in forces[1:])


def test_laplace_pressure_and_bad_input():
    assert laplace_pressure(1e-9) == pytest.approx(0.072e9)
    assert laplace_pressure(0.0) == 0.0
    with pytest.raises(InputError, match="contact angles"):
        condensation_height(1e-9, 4.0)
    with pytest.raises(InputError, match="gap"):
        capillary_pressure([np.nan], 1e-9, 0.3)


def test_humid_air_in_the_meshing_cycle():
    """Issue #17: vacuum is untouched; in air the menisci add attraction to F_adh and a capillary part to the
    COF split (which still adds up); dry air equals vacuum; OTS-coated teeth (hydrophobic) form no menisci."""
    from memstribo.physics.coating import get_coating
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    vacuum = summarize(simulate_mesh(params, steps=21))
    assert vacuum["environment"] == "vacuum" and vacuum["cof_capillary"] == 0.0
    dry = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.0}), steps=21))
    assert dry["cof_mean"] == vacuum["cof_mean"] and dry["stiction_margin"] == vacuum["stiction_margin"]
    humid = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.6}), steps=21))
    assert humid["cof_capillary"] > 0 and humid["energy_capillary"] > 0
    assert humid["adhesion_force_mean"] > vacuum["adhesion_force_mean"]
    assert humid["cof_mean"] == pytest.approx(humid["cof_chemical"] + humid["cof_vdw"] + humid["cof_elastic"]
                                              + humid["cof_capillary"], rel=1e-12)
    coated = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.6}), steps=21,
                                     coating=get_coating("OTS"), wear=0.0))
    # the pinion is bare (30 deg) and the gear OTS (112 deg): cos 30 + cos 112 > 0, a weak meniscus remains
    assert 0 < coated["cof_capillary"] < humid["cof_capillary"]


def test_cli_sweep_humidity(cli, tmp_path):
    out = cli.json("sweep", "humidity", "--values", "0,0.7", "--steps", "11", "--out", tmp_path)
    dry, wet = out["points"]
    assert dry["relative_humidity"] == 0.0 and dry["cof_capillary"] == 0.0 and wet["cof_capillary"] > 0
    # the default case does not stick: no critical humidity in the range, and a note that says so
    assert out["critical_humidity"] is None and "no stiction in the swept range" in out["critical_humidity_note"]
    assert out["coating"] == "none" and "warnings" in out
    import xarray as xr

    with xr.open_dataset(tmp_path / "sweep_humidity.nc") as saved:
        assert np.isnan(saved.attrs["critical_humidity"]) and "no stiction" in saved.attrs["critical_humidity_note"]
        assert saved["relative_humidity"].attrs["units"] == "1"


def test_critical_humidity_interpolates_the_margin_and_its_spread():
    from memstribo.simulations.mesh import critical_humidity

    points = [{"relative_humidity": rh, "stiction_margin": m,
               "stiction_margin_realisations": [m, m - 1e-6, m + 5e-6]}
              for rh, m in ((0.0, 3e-6), (0.2, 2e-6), (0.4, -2e-6), (0.6, -4e-6))]
    out = critical_humidity(points[::-1])  # any order
    assert out["critical_humidity"] == pytest.approx(0.3)  # 2 uN at 0.2, -2 uN at 0.4: zero half way
    assert out["critical_humidity_realisations"][0] == pytest.approx(0.3)
    assert out["critical_humidity_realisations"][1] == pytest.approx(0.2 + 0.2 * 1 / 4)  # 1 uN -> -3 uN
    assert out["critical_humidity_realisations"][2] is None  # +5 uN: never sticks up to 0.6
    assert out["critical_humidity_crossing_fraction"] == pytest.approx(2 / 3)
    assert out["critical_humidity_p05"] <= out["critical_humidity_median"] <= out["critical_humidity_p95"]
    assert "1 of 3 realisation(s) do not stick" in out["critical_humidity_note"]
    assert out["critical_humidity_stuck_at_lowest"] == 0
    stuck = critical_humidity([{"relative_humidity": 0.1, "stiction_margin": -1.0},
                               {"relative_humidity": 0.5, "stiction_margin": -2.0}])
    assert stuck["critical_humidity"] == 0.1 and "already at the lowest" in stuck["critical_humidity_note"]
    # a crossing below RH 0.1 (Kelvin radius of a molecular size) is flagged; a realisation stuck when dry is counted
    early = critical_humidity([{"relative_humidity": rh, "stiction_margin": m,
                                "stiction_margin_realisations": [m, -1.0]} for rh, m in ((0.0, 1.0), (0.1, -1.0))])
    assert early["critical_humidity"] == pytest.approx(0.05) and "does not hold" in early["critical_humidity_note"]
    assert early["critical_humidity_stuck_at_lowest"] == 1 and "already stick at the lowest" in early[
        "critical_humidity_note"]
    with pytest.raises(InputError, match="humidity sweep"):
        critical_humidity([{"normal_load": 1e-6}])


def test_menisci_pull_inside_the_cycles_contact_solve():
    """In air the menisci's traction is part of each step's contact solve: the teeth are pulled together (wider
    contact), and the capillary part of F_adh is the solves' meniscus line load."""
    from memstribo.simulations.mesh import simulate_mesh
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    dry = simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.0}), steps=11)
    wet = simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.6}), steps=11)
    assert float(wet["contact_width"].mean()) > float(dry["contact_width"].mean())
    r_k = kelvin_radius(0.6)
    # the solve's wetted fraction against the wetted elements of its final gap: the same area within 10 %
    assert np.allclose(wet["capillary_force"], laplace_pressure(r_k) * wet["wetted_area"], rtol=0.1)


def test_menisci_inside_the_contact_solve_give_the_cylinder_relation():
    """Issue #17: the Laplace pressure gamma/r_K over gaps <= h_c as a Dugdale-type traction in the line-contact
    solve. In the rigid limit (stiff teeth, near-zero load) the meniscus line load of a cylinder on a flat is the
    closed form 2 gamma sqrt(2 R h_c) / r_K; softer teeth flatten and wet more (a larger pull)."""
    from memstribo.physics.contact import cylinder_on_flat, solve_line_contact

    radius, theta = 10e-6, math.radians(20)
    r_k = kelvin_radius(0.5)
    closed = capillary_force_cylinder(radius, r_k, theta)
    separation, dx = cylinder_on_flat(radius, 1.2e-6, 4096)
    zone = {"capillary_stress": laplace_pressure(r_k), "capillary_range": condensation_height(r_k, theta)}
    stiff = solve_line_contact(separation, dx, 1e13, load=1e-3, **zone)
    assert stiff.converged and stiff.adhesive_load == 0.0
    assert stiff.capillary_load == pytest.approx(closed, rel=0.01)
    # the net load is the applied one; the contact's compressive part (p + gamma/r_K) carries it plus the pull
    assert stiff.load == pytest.approx(1e-3, rel=1e-6)
    compressive = (stiff.pressure[stiff.contact] + zone["capillary_stress"]).sum() * dx
    assert compressive == pytest.approx(1e-3 + stiff.capillary_load, rel=1e-3)
    soft = solve_line_contact(separation, dx, 1e11, load=1e-3, **zone)
    assert soft.converged and closed < soft.capillary_load < 1.2 * closed
    # the pull under approach control: the largest tensile load, just before touching, is the closed form
    pulls = {}
    for offset in (-0.3e-9, -0.1e-9, -0.01e-9, 0.05e-9):
        solution = solve_line_contact(separation, dx, 1e13, approach=separation.min() + offset, **zone)
        assert solution.converged
        pulls[offset] = -solution.load
    assert max(pulls.values()) == pytest.approx(closed, rel=0.01) and max(pulls, key=pulls.get) == -0.01e-9
    assert pulls[-0.3e-9] == pytest.approx(closed * math.sqrt(1 - 0.3e-9 / zone["capillary_range"]), rel=0.01)


def test_capillary_zone_off_is_the_plain_solve_and_zones_add():
    from memstribo.physics.contact import cylinder_on_flat, solve_line_contact

    separation, dx = cylinder_on_flat(10e-6, 1.2e-6, 2048)
    plain = solve_line_contact(separation, dx, 100e9, load=5.0)
    for zone in ({"capillary_stress": 0.0, "capillary_range": 1e-9},  # dry air: r_K = 0, gamma/r_K := 0
                 {"capillary_stress": 1e8, "capillary_range": 0.0}):  # hydrophobic: h_c = 0
        dry = solve_line_contact(separation, dx, 100e9, load=5.0, **zone)
        assert np.array_equal(dry.pressure, plain.pressure) and dry.capillary_load == 0.0
    # two zones of the same range are one zone of the summed stress (vdW Dugdale zone plus menisci)
    both = solve_line_contact(separation, dx, 100e9, load=5.0, cohesive_stress=3e8, cohesive_range=1e-9,
                              capillary_stress=1e8, capillary_range=1e-9)
    one = solve_line_contact(separation, dx, 100e9, load=5.0, cohesive_stress=4e8, cohesive_range=1e-9)
    assert both.converged and one.converged
    assert np.allclose(both.pressure, one.pressure, atol=1e-6 * one.max_pressure)
    assert both.adhesive_load + both.capillary_load == pytest.approx(
        one.adhesive_load + 1e8 * dx * both.contact.sum(), rel=1e-3)
    # per-element condensation heights (bare and coated parts): a zero-height half wets less
    half = np.where(np.arange(separation.size) < separation.size // 2, 1e-9, 0.0)
    mixed = solve_line_contact(separation, dx, 100e9, load=5.0, capillary_stress=1e8, capillary_range=half)
    full = solve_line_contact(separation, dx, 100e9, load=5.0, capillary_stress=1e8, capillary_range=1e-9)
    assert mixed.converged and 0.4 * full.capillary_load < mixed.capillary_load < 0.6 * full.capillary_load
    with pytest.raises(InputError, match="capillary_range"):
        solve_line_contact(separation, dx, 100e9, load=5.0, capillary_stress=1e8, capillary_range=np.ones(3))
    with pytest.raises(InputError, match="both"):
        solve_line_contact(separation, dx, 100e9, load=5.0, capillary_stress=1e8)


def test_dense_small_grid_solves_agree_with_the_general_solver(monkeypatch):
    """Small grids (a meshing window, ~100 elements) take dense matrices; the result is the general solver's:
    plain, Maugis-Dugdale, capillary, and both zones."""
    import memstribo.physics.contact as contact
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.roughness import default_profile

    profile = default_profile(get_parameter_values(), length=2e-6)
    n = 200
    x = (np.arange(n) - n / 2) * 1e-9
    separation = x**2 / (2 * 5e-6) - np.interp(np.linspace(0, 1.9e-6, n), profile.x - profile.x[0], profile.z)
    for zone in ({}, {"cohesive_stress": 3e8, "cohesive_range": 3e-10}, {"capillary_stress": 1e8, "capillary_range": 1.4e-9},
                 {"capillary_stress": 5e7, "capillary_range": 4e-9, "cohesive_stress": 3e8, "cohesive_range": 3e-10}):
        dense = contact.solve_line_contact(separation, 1e-9, 1e11, load=2.0, **zone)
        _tune(monkeypatch, dense_solve_max=0, zone_kernel_max=0)  # the zones' compiled loop has its own bound
        general = contact.solve_line_contact(separation, 1e-9, 1e11, load=2.0, **zone)
        monkeypatch.undo()
        assert "dense matrices" in dense.message and "dense" not in general.message
        assert dense.converged and general.converged
        assert dense.approach == pytest.approx(general.approach, rel=1e-6)
        assert dense.capillary_load == pytest.approx(general.capillary_load, rel=1e-4)
        assert dense.adhesive_load == pytest.approx(general.adhesive_load, rel=1e-3, abs=1e-9)
        assert np.array_equal(dense.contact, general.contact)
        assert np.allclose(dense.pressure, general.pressure, atol=1e-4 * general.max_pressure)


def test_silicon_oxide_air_u_vdw_is_calibrated_to_the_published_cof_in_air():
    """Issue #17: the one value of silicon_oxide_air without a measurement (U_vdW) is calibrated to the dynamic COF
    ~0.3 of polysilicon in laboratory air (Gabriel, as cited by Srinivasan et al. 1998); its source says so."""
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.parameters import get_parameter_values

    oxide = get_parameter_values("silicon_oxide_air")
    assert "CALIBRATED" in oxide.source("vdw_bond_energy") and "10.2172/671989" in oxide.source("vdw_bond_energy")
    summary = summarize(simulate_mesh(oxide))
    assert summary["cof_mean"] == pytest.approx(0.30, rel=0.01)
    assert 0 < summary["cof_capillary"] < 0.01 * summary["cof_mean"]  # the menisci's share stays below 1 %


def test_a_humidity_below_the_meniscus_regime_is_warned_about():
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    low = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.05}), steps=11))
    assert any("molecular size" in w for w in low["warnings"])
    for rh in (0.0, 0.3):
        ok = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": rh}), steps=11))
        assert not any("molecular size" in w for w in ok["warnings"])


def test_a_humidity_sweep_reuses_the_previous_points_contacts_without_changing_the_result():
    """Each sweep point starts its contact solves from the previous humidity's (what does not depend on RH is
    reused); the result is a cold start's to the contact tolerance. With the Maugis-Dugdale zone (two states
    per step are possible) every point starts cold: its result does not depend on the points before it."""
    from memstribo.simulations.mesh import simulate_mesh, summarize, sweep
    from memstribo.parameters import get_parameter_values

    for adhesion, tolerance in (("none", 1e-3), ("maugis", 0.0)):
        params = get_parameter_values().updated({"contact_adhesion": adhesion})
        warm = sweep(params, "humidity", [0.4, 0.6], steps=21)[-1]
        cold = summarize(simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.6}), steps=21))
        for key in ("cof_mean", "cof_capillary", "adhesion_force_mean", "stiction_margin"):
            assert warm[key] == pytest.approx(cold[key], rel=tolerance), (adhesion, key)
    params = get_parameter_values()
    # the store is per row and holds each step's pressure with the traction's limit it was solved with
    store = {}
    simulate_mesh(params.updated({"environment": "air", "relative_humidity": 0.6}), steps=11, warm_start=store)
    pressure, stress = store[0]
    assert pressure.shape[0] == 11 and stress > 0 and pressure.min() >= -stress * (1 + 1e-9)


def test_water_surface_tension_and_kelvin_radius_follow_the_temperature():
    """IAPWS R1-76(2014) scaled to 0.072 N/m at 25 degC: exactly today's values at 298.15 K, the measured
    slope elsewhere (72.0 -> 58.9 mN/m at 100 degC in the IAPWS table: 71.97 and 58.91 mN/m)."""
    from memstribo.physics.capillary import water_surface_tension

    assert water_surface_tension(298.15) == 0.072
    assert kelvin_radius(0.4, 298.15) == 0.072 * 18.07e-6 / (8.314462618 * 298.15) / math.log(1 / 0.4)
    assert water_surface_tension(373.15) == pytest.approx(0.072 * 58.91 / 71.97, rel=1e-3)
    hot = kelvin_radius(0.4, 350.0)
    assert hot == pytest.approx(water_surface_tension(350.0) * 18.07e-6 / (8.314462618 * 350.0) / math.log(1 / 0.4),
                                rel=1e-12)
    assert hot < kelvin_radius(0.4)  # warmer: weaker surface tension, more thermal energy
    for bad in (200.0, 700.0):
        with pytest.raises(InputError, match="liquid range of water"):
            kelvin_radius(0.4, bad)


def test_the_meshing_cycle_takes_the_ambient_temperature_in_air():
    """ambient_temperature reaches the menisci (Kelvin radius, Laplace pressure, rupture energy): hotter water has a
    lower surface tension and a larger R T ln(1/RH) / V_m, so the capillary attraction changes; 298.15 K is the
    default, bit for bit."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh, summarize

    air = get_parameter_values().updated({"environment": "air", "relative_humidity": 0.5})
    default = summarize(simulate_mesh(air, steps=21))
    explicit = summarize(simulate_mesh(air.updated({"ambient_temperature": 298.15}), steps=21))
    hot = summarize(simulate_mesh(air.updated({"ambient_temperature": 330.0}), steps=21))
    assert explicit["adhesion_force_mean"] == default["adhesion_force_mean"]
    assert hot["adhesion_force_mean"] != pytest.approx(default["adhesion_force_mean"], rel=1e-3)
    with pytest.raises(InputError, match="liquid range of water"):
        simulate_mesh(air.updated({"ambient_temperature": 700.0}), steps=21)


def test_a_meniscus_force_is_bounded_by_its_laplace_pressure_and_perimeter_closed_forms():
    """Issue #36 (MODEL 7g): (gamma / r_K) A + gamma L; its area term is the sphere's and the cylinder's closed
    form; a pull-off law enters only below the bound (the criterion: its mean tension below gamma / r_K)."""
    from memstribo.physics.capillary import bounded_pull_off, meniscus_force_bound

    gamma, theta, radius = 0.072, math.radians(30), 1e-6
    r_k = kelvin_radius(0.6)
    h_c = condensation_height(r_k, theta)
    # sphere on a flat: wetted disc x^2 / (2R) <= h_c, area 2 pi R h_c, perimeter 2 pi sqrt(2 R h_c)
    sphere = meniscus_force_bound(2 * math.pi * radius * h_c, 0.0, r_k, gamma)
    assert sphere == pytest.approx(capillary_force_sphere(radius, theta), rel=1e-12)
    with_line = meniscus_force_bound(2 * math.pi * radius * h_c, 2 * math.pi * math.sqrt(2 * radius * h_c), r_k, gamma)
    assert with_line - sphere == pytest.approx(gamma * 2 * math.pi * math.sqrt(2 * radius * h_c), rel=1e-12)
    # cylinder on a flat, per unit length: width 2 sqrt(2 R h_c), two contact lines
    cylinder = meniscus_force_bound(2 * math.sqrt(2 * 10e-6 * h_c), 2.0, r_k, gamma)
    assert cylinder == pytest.approx(capillary_force_cylinder(10e-6, r_k, theta) + 2 * gamma, rel=1e-12)
    assert meniscus_force_bound(1e-12, 1e-6, 0.0) == 0.0  # dry
    bound = meniscus_force_bound(1e-14, 1e-7, r_k, gamma)
    assert bounded_pull_off(10 * bound, 1e-14, 1e-7, r_k, gamma) == bound  # a crack law that needs more: the bound
    assert bounded_pull_off(0.5 * bound, 1e-14, 1e-7, r_k, gamma) == 0.5 * bound  # a weaker one holds
    with pytest.raises(InputError, match="area"):
        meniscus_force_bound(-1.0, 0.0, r_k)


def test_below_a_molecular_kelvin_radius_there_is_no_meniscus():
    """One molecular diameter of water, (V_m / N_A)^(1/3) = 0.311 nm (r_K at RH 0.185): below it an adsorbed film."""
    from memstribo.physics.capillary import forms_meniscus, molecular_kelvin_radius

    assert molecular_kelvin_radius() == pytest.approx(0.3106e-9, rel=1e-3)
    assert not forms_meniscus(kelvin_radius(0.1)) and not forms_meniscus(0.0)
    assert forms_meniscus(kelvin_radius(0.2)) and forms_meniscus(kelvin_radius(0.9))


def test_no_meniscus_element_pulls_beyond_its_laplace_pressure():
    """Issue #36, done when: every block's bridge force is at most gamma / r_K over its wetted area plus gamma on
    its contact lines (a block-by-block check on a synthetic row), and the gear's capillary pull-off and its part of
    F_adh at every step stay within (gamma / r_K) bridged_area + gamma bridged_perimeter."""
    from types import SimpleNamespace

    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh
    from memstribo.simulations.mesh.steps import _block_pull_off, _meniscus_ends

    gamma = 0.072
    r_k = kelvin_radius(0.9)
    ctx = SimpleNamespace(dx=2e-9, w_adh=100e-9, modulus=85e9, c_ns=1.044, r_kelvin=r_k, surface_tension=gamma)
    rng = np.random.default_rng(1)
    wet = rng.random((3, 400)) < 0.4
    k1_at_x = np.broadcast_to(np.arange(400) // 50, (3, 400))
    ends = _meniscus_ends(wet)
    work = np.where(wet, 0.125, 1.0)
    total = _block_pull_off(ctx, wet.astype(float), work, k1_at_x, (wet, ends))
    unbounded = _block_pull_off(ctx, wet.astype(float), work, k1_at_x)
    bound = laplace_pressure(r_k, gamma) * wet.sum(axis=1) * ctx.dx * ctx.w_adh + gamma * ends.sum(axis=1) * ctx.w_adh
    assert np.all(total <= bound * (1 + 1e-12)) and np.all(unbounded > 3 * bound)  # the crack law alone: 3x and more
    for rh in (0.5, 0.9):
        ds = simulate_mesh(get_parameter_values().updated({"environment": "air", "relative_humidity": rh}), steps=21)
        limit = (laplace_pressure(kelvin_radius(rh), gamma) * np.asarray(ds["bridged_area"])
                 + gamma * np.asarray(ds["bridged_perimeter"]))
        pull, part = np.asarray(ds["capillary_pull_off"]), np.asarray(ds["capillary_adhesion_force"])
        assert pull.max() > 0 and np.all(pull <= limit * (1 + 1e-12)) and np.all(part <= pull * (1 + 1e-12))
