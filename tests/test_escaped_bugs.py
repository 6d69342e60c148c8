"""Tests for the bugs that slipped through before (issue 41 item 4), each against a reference computed here.

Every test below was checked by planting its bug in the code and seeing it fail (docs/hardening.md, "Round
four"): each row reading row 0's lattice registry, one pinion phase for all rows, the menisci's rupture energy
with cos theta -> 1, the Sobol' design's columns misassigned, the root effective area with exponent 1 instead of
m, the flash temperature's heat flux doubled, ``counter_poisson_ratio`` ignored. The README's root stress,
fracture probability and flash temperature are recomputed from the parameters by hand (ISO 6336-3 method B with
the mask-drawn fillet, Weibull's weakest link, Jaeger's band source at low Péclet with Blok's partition).
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from memstribo.parameters import get_parameter_values
from memstribo.simulations.mesh import simulate_mesh, summarize

REPO = Path(__file__).resolve().parent.parent
EULER_GAMMA = 0.5772156649015329


@pytest.fixture(scope="module")
def params():
    return get_parameter_values()


@pytest.fixture(scope="module")
def default_run(params):
    """The README's cycle: the default parameters at the default 481 steps (about 2 s)."""
    ds = simulate_mesh(params, steps=int(params["mesh_steps"]))
    return ds, summarize(ds)


# ------------------------------------------------------------------------------------------- lattice registry
def test_every_row_draws_its_own_registry(params):
    """Each row's pinion phase, gear phase, gear lattice turn and bond phase are its own draws (MODEL 7d, 7f)."""
    from memstribo.simulations.mesh.setup import lattice_registry

    rows = 12
    reg = lattice_registry(params, rows, 0)
    w_adh = params["adhesive_width"]
    for name in ("pinion_phase", "gear_phase", "gear_pitch_scale", "bond_phase"):
        values = np.asarray(getattr(reg, name), dtype=float)
        assert values.shape == (rows,), name
        assert np.unique(values).size == rows, f"{name}: rows share a value"
    assert np.all((reg.pinion_phase >= 0) & (reg.pinion_phase < w_adh))
    assert np.all((reg.bond_phase >= 0) & (reg.bond_phase < 1))
    # uniform draws: twelve phases spread over their range, not clustered at one value
    assert np.ptp(reg.pinion_phase) > 0.3 * w_adh and np.ptp(reg.bond_phase) > 0.3


def test_row_rolls_subtract_the_rows_own_phases():
    from memstribo.simulations.mesh.steps import _row_rolls

    s1, s2 = np.linspace(0.0, 1e-6, 5), np.linspace(1e-6, 0.0, 5)
    registry = SimpleNamespace(pinion_phase=np.array([1e-10, 2e-10, 3e-10]),
                               gear_phase=np.array([5e-11, 6e-11, 7e-11]), gear_pitch_scale=np.array([1.0, 1.2, 1.4]))
    setup = SimpleNamespace(registry=registry)
    for row in range(3):
        r1, r2, scale = _row_rolls(setup, {"s1": s1, "s2": s2}, row)
        np.testing.assert_allclose(s1 - r1, registry.pinion_phase[row], rtol=0, atol=1e-18)
        np.testing.assert_allclose(s2 - r2, registry.gear_phase[row], rtol=0, atol=1e-18)
        assert scale == registry.gear_pitch_scale[row]


def test_the_cycle_reads_each_rows_own_registry(params, monkeypatch):
    """Spy on the cycle's step loop: the roll coordinates of row r are the kinematics less row r's phases, for every
    row, and the dataset's bond phases are the rows' draws (a cycle of 11 steps: a few seconds)."""
    from memstribo.simulations.mesh import steps
    from memstribo.simulations.mesh.setup import lattice_registry

    seen = []
    original = steps._flank_blocks

    def spy(out, ctx, pressure, gap, rolls):
        seen.append(rolls)
        return original(out, ctx, pressure, gap, rolls)

    monkeypatch.setattr(steps, "_flank_blocks", spy)
    ds = simulate_mesh(params, steps=11)
    rows = ds.sizes["row"]
    assert rows >= 2 and len(seen) == rows
    reg = lattice_registry(params, rows, 0)
    np.testing.assert_array_equal(ds.bond_phase.values, reg.bond_phase)
    shifts_1 = [float(np.median(np.asarray(rolls[0]))) for rolls in seen]
    shifts_2 = [float(np.median(np.asarray(rolls[1]))) for rolls in seen]
    # the same kinematics for every row: the rows' roll coordinates differ by their phases' differences
    np.testing.assert_allclose(np.diff(shifts_1), -np.diff(reg.pinion_phase), rtol=0, atol=1e-15)
    np.testing.assert_allclose(np.diff(shifts_2), -np.diff(reg.gear_phase), rtol=0, atol=1e-15)
    assert [rolls[2] for rolls in seen] == pytest.approx(list(reg.gear_pitch_scale), rel=1e-12)


# ------------------------------------------------------------------------------------------- menisci
def test_the_menisci_rupture_energy_carries_both_contact_angles(params):
    """Capillary friction = wetted area x gamma (cos theta_1 + cos theta_2) / renewal distance (MODEL 7e), with
    gamma = 0.072 N/m at 298.15 K and the bare silicon's 30 deg on both flanks: 2 cos 30 deg, not 2."""
    humid = params.updated({"environment": "air", "relative_humidity": 0.5})
    assert humid["ambient_temperature"] == 298.15
    ds = simulate_mesh(humid, steps=11)
    theta = float(humid["water_contact_angle"])
    assert math.degrees(theta) == pytest.approx(30.0, abs=1e-3)
    renewal = humid["meniscus_renewal_distance"] or humid["atomic_pitch"]
    expected = ds.wetted_area.values * 0.072 * 2.0 * math.cos(theta) / renewal
    assert np.all(ds.wetted_area.values >= 0) and ds.wetted_area.values.max() > 0
    np.testing.assert_allclose(ds.friction_force_capillary.values, expected, rtol=1e-9, atol=0)


# ------------------------------------------------------------------------------------------- Sobol' design
def test_the_sobol_design_assigns_each_column_to_its_factor(params):
    """A synthetic model of one named constant (and a little of the roughness realisation) run through the study's
    Sobol' stage (uncertainty.study._sensitivity, its runner replaced): the indices go to the constants that the
    model reads, so the design's columns reach the right factors."""
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.study import REALISATION_FACTOR, _sensitivity

    priors = priors_for(params)
    names = [n for n in ("vdw_bond_energy", "vdw_dissipated_fraction", "bond_energy", "cutoff_distance")
             if n in priors]  # the vdW rule samples U_vdW ('thesis') or phi ('hysteresis', the default)
    assert len(names) == 3, sorted(priors)
    sampled = {n: priors[n] for n in names}
    realisations = 16
    weights = {names[0]: 4.0, names[1]: 2.0, names[2]: 0.0}  # unequal: a shift, a swap or a reversal moves them

    class FakeRunner:
        def rescalable(self):
            return ()

        def summaries(self, points):
            out = []
            for realisation, constants in points:
                u = {n: float(sampled[n].cdf(constants.get(n, params[n]))) for n in names}
                margin = sum(weights[n] * u[n] for n in names) + 0.5 * realisation / realisations - 3.0
                out.append({"stiction_margin": margin, "cof_mean": 1.0 + u[names[1]], "stiction": margin < 0})
            return out

    result = {"confidence": 0.95}
    _sensitivity(result, params, FakeRunner(), sampled, realisations, 0, 0.95, None, 11, None, 0.0, None, False,
                 256, None, False, 0.05, 3)
    s = result["sensitivity"]
    # variance shares: w^2 / 12 of each constant (uniform in its quantile), (0.5)^2 (R^2 - 1) / (12 R^2) of the
    # realisation (a discrete uniform index)
    variances = {n: weights[n] ** 2 / 12.0 for n in names}
    variances[REALISATION_FACTOR] = 0.25 * (realisations ** 2 - 1) / (12.0 * realisations ** 2)
    total = sum(variances.values())
    for name, variance in variances.items():
        assert s[name]["total"] == pytest.approx(variance / total, abs=0.04), name
        assert s[name]["first"] == pytest.approx(variance / total, abs=0.06), name
    assert s[names[1]]["cof_total"] == pytest.approx(1.0, abs=0.05)
    assert abs(s[names[0]]["cof_total"]) < 0.03 and abs(s[names[2]]["cof_total"]) < 0.03
    driver = names[0]
    assert result["dominant"] == driver


# ------------------------------------------------------------------------------------------- tooth root: by hand
def _involute(angle):
    return math.tan(angle) - angle


class _HandTooth:
    """One tooth drawn from the parameters alone: involute flank above the base circle, radial below it, a circular
    root fillet of radius 0.38 m tangent to the flank and to the root circle r - 1.25 m (the mask's tooth), and
    ISO 6336-3 method B's critical section where the fillet's tangent makes 30 deg with the centreline."""

    def __init__(self, params, teeth):
        from scipy.optimize import brentq

        self.z, self.m, self.alpha = teeth, params["module"], params["pressure_angle"]
        self.b = params["face_width"]
        self.r = self.m * teeth / 2
        self.rb = self.r * math.cos(self.alpha)
        self.ra = self.r + params["addendum_coefficient"] * self.m
        self.rf = self.r - params["dedendum_coefficient"] * self.m
        self.rho = params["root_fillet_coefficient"] * self.m
        self.psi_b = math.pi / (2 * teeth) + _involute(self.alpha)
        big = self.rf + self.rho  # the fillet's centre is this far from the gear's centre (tangent to the root circle)
        foot = math.sqrt(big ** 2 - self.rho ** 2)
        if foot <= self.rb:  # tangent to the radial flank below the base circle, at the foot of the perpendicular
            self.flank_foot = foot
            self.psi_c = self.psi_b + math.asin(self.rho / big)
            self.centre = np.array([big * math.sin(self.psi_c), big * math.cos(self.psi_c)])
        else:  # tangent to the involute: the centre one fillet radius out along the flank's normal
            def centre_at(radius):
                point, normal, _ = self.load_point(radius)
                return point + self.rho * normal

            self.flank_foot = brentq(lambda r: np.linalg.norm(centre_at(r)) - big, self.rb * (1 + 1e-12), self.ra,
                                     xtol=1e-18)
            self.centre = centre_at(self.flank_foot)
            self.psi_c = math.atan2(self.centre[0], self.centre[1])
        thirty = math.radians(30.0)
        self.section = self.centre - self.rho * np.array([math.cos(thirty), math.sin(thirty)])

    def load_point(self, radius):
        """The flank point at ``radius``, the outward normal (towards the base circle's tangent point) and the
        tangent towards the tip."""
        alpha_r = math.acos(min(self.rb / radius, 1.0))
        psi = math.pi / (2 * self.z) + _involute(self.alpha) - _involute(alpha_r)
        point = radius * np.array([math.sin(psi), math.cos(psi)])
        touch = self.rb * np.array([math.sin(psi - alpha_r), math.cos(psi - alpha_r)])
        normal = (point - touch) / np.linalg.norm(point - touch)
        tangent = np.array([-normal[1], normal[0]])
        return point, normal, tangent

    def lever_arm(self, radius):
        point, normal, _ = self.load_point(radius)
        return abs(point[1] - self.section[1] - point[0] * normal[1] / normal[0])

    def stress(self, radius, normal_force, friction_force, sign, design_radius):
        """(tensile root stress [Pa], Y_S, the contact force, the load point)."""
        point, normal, tangent = self.load_point(radius)
        force = -normal_force * normal + sign * friction_force * tangent
        s_fn = 2.0 * self.section[0]
        moment = point[0] * force[1] - (point[1] - self.section[1]) * force[0]
        lever = max(self.lever_arm(radius), self.lever_arm(design_radius))
        ratio, q_s = s_fn / lever, s_fn / (2.0 * self.rho)
        y_s = (1.2 + 0.13 * ratio) * q_s ** (1.0 / (1.21 + 2.3 / ratio))  # ISO 6336-3 Eq. (37)
        return y_s * 6.0 * abs(moment) / (self.b * s_fn ** 2) + force[1] / (self.b * s_fn), y_s, force, point

    def outline_below(self, height, points=4000):
        """The loaded side from the middle of the space up to ``height``: root land, fillet, radial flank, involute."""
        parts = []
        phi = np.linspace(math.pi / self.z, self.psi_c, points)
        parts.append(self.rf * np.stack([np.sin(phi), np.cos(phi)], axis=1))
        start = math.atan2(-self.centre[1], -self.centre[0])  # towards the gear centre: the root circle
        if self.flank_foot < self.rb:
            flank = self.flank_foot * np.array([math.sin(self.psi_b), math.cos(self.psi_b)])
        else:
            flank = self.load_point(self.flank_foot)[0]
        end = math.atan2(*(flank - self.centre)[::-1])  # towards the point where the fillet meets the flank
        while end > start:
            end -= 2 * math.pi
        t = np.linspace(start, end, points)
        parts.append(self.centre + self.rho * np.stack([np.cos(t), np.sin(t)], axis=1))
        if self.flank_foot < self.rb:
            rad = np.linspace(self.flank_foot, self.rb, points)
            parts.append(rad[:, None] * np.array([math.sin(self.psi_b), math.cos(self.psi_b)]))
        radius = np.linspace(max(self.rb, self.flank_foot), self.ra, points)
        psi = self.psi_b - np.array([_involute(math.acos(min(self.rb / r, 1.0))) for r in radius])
        parts.append(radius[:, None] * np.stack([np.sin(psi), np.cos(psi)], axis=1))
        outline = np.concatenate(parts)
        return outline[outline[:, 1] < height]


def _hand_root(params, ds, gear):
    """The largest tensile root stress over the cycle of the pinion (gear=False) or the gear, by hand, and the
    effective area A_eff = b integral (sigma / sigma_max)^m ds along the loaded side at that step."""
    z1, z2 = int(params["teeth_pinion"]), int(params["teeth_gear"])
    tooth = _HandTooth(params, z2 if gear else z1)
    pinion, wheel = _HandTooth(params, z1), _HandTooth(params, z2)
    tan_a = math.tan(params["pressure_angle"])
    # the path of contact on the line of action, from the pitch point: first contact at the gear's tip, last at the
    # pinion's; ISO's load points, the outer points of single tooth contact, one base pitch inside them
    first = -(math.sqrt(wheel.ra ** 2 - wheel.rb ** 2) - wheel.rb * tan_a)
    last = math.sqrt(pinion.ra ** 2 - pinion.rb ** 2) - pinion.rb * tan_a
    base_pitch = math.pi * params["module"] * math.cos(params["pressure_angle"])
    c_design = last - base_pitch if gear else first + base_pitch

    def radius_at(c):
        roll = tooth.rb * tan_a - c if gear else tooth.rb * tan_a + c
        return float(np.clip(math.hypot(tooth.rb, roll), tooth.flank_foot, tooth.ra))

    best = None
    for c, fn, ff in zip(ds.c.values, ds.normal_force.values, ds.friction_force.values):
        sign = 1.0 if c >= 0 else -1.0  # friction toward the root before the pitch point, toward the tip after it
        sigma = tooth.stress(radius_at(c), fn, max(ff, 0.0), sign, radius_at(c_design))
        if best is None or sigma[0] > best[0][0]:
            best = (sigma, c)
    (sigma_max, y_s, force, point), _ = best
    side = tooth.outline_below(point[1])
    moment = point[0] * force[1] - (point[1] - side[:, 1]) * force[0]
    sigma = np.minimum(y_s * 6.0 * np.abs(moment) / (tooth.b * (2.0 * side[:, 0]) ** 2), sigma_max)
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(side, axis=0).T))])
    ratio = (sigma / sigma_max) ** params["weibull_modulus"]
    area = tooth.b * float(np.sum(0.5 * (ratio[1:] + ratio[:-1]) * np.diff(arc)))
    return sigma_max, area


def _readme():
    return " ".join((REPO / "README.md").read_text(encoding="utf-8").split())


def test_root_stress_is_iso_6336_3_method_b_by_hand(params, default_run):
    """README: "the tooth's root stress (1.89 GPa in the pinion)"."""
    ds, summary = default_run
    pinion, _ = _hand_root(params, ds, gear=False)
    gear, _ = _hand_root(params, ds, gear=True)
    assert summary["root_stress_max"][0] == pytest.approx(pinion, rel=1e-4)
    assert summary["root_stress_max"][1] == pytest.approx(gear, rel=1e-4)
    assert f"({pinion / 1e9:.3g} GPa in the pinion)" in _readme()


def test_fracture_probability_is_weibulls_weakest_link_by_hand(params, default_run):
    """README: "a 0.7 % probability that a tooth breaks on the first load": 1 - exp(-sum over the z1 + z2 teeth of
    (A_eff / A_0) (sigma / sigma_theta)^m), with A_eff integrated here along the loaded side (exponent m)."""
    ds, summary = default_run
    m, sigma_theta = params["weibull_modulus"], params["strength_characteristic"]
    a_0 = params["strength_reference_area"]
    risk = 0.0
    for gear, teeth in ((False, params["teeth_pinion"]), (True, params["teeth_gear"])):
        sigma, area = _hand_root(params, ds, gear)
        assert summary["root_effective_area"][int(gear)] == pytest.approx(area, rel=0.01)
        risk += teeth * area / a_0 * (sigma / sigma_theta) ** m
    probability = -math.expm1(-risk)
    assert summary["fracture_probability"] == pytest.approx(probability, rel=0.02)
    assert f"a {100 * probability:.1g} % probability that a tooth breaks on the first load" in _readme()
    # at another Weibull modulus the area follows its exponent: (sigma / sigma_max)^m falls with m wherever
    # sigma < sigma_max (an exponent of 1 would leave it unchanged)
    from memstribo.simulations.tooth_life import tooth_life

    stiffer = params.updated({"weibull_modulus": 20.0})
    life = tooth_life(ds, stiffer)
    for gear in (False, True):
        _, area_10 = _hand_root(params, ds, gear)
        _, area_20 = _hand_root(stiffer, ds, gear)
        assert area_20 < 0.9 * area_10
        assert life["root_effective_area"][int(gear)] == pytest.approx(area_20, rel=0.01)


def test_flash_temperature_is_jaegers_band_source_with_bloks_partition_by_hand(params, default_run):
    """README: "a flash temperature rise of 0.3 K". q = F_f |u1 - u2| / (2 a b), u_i = omega_i R_i (R1 = r_b1 tan
    alpha + c, R2 = r_b2 tan alpha - c, omega_2 = omega_1 z1 / z2); every step is at low Péclet (L = u a / (2 kappa)
    < 1e-3), where the band mean is (2 / pi)(3/2 - gamma - ln L) q a / k (Jaeger 1942); Blok's equal mean
    temperatures: theta = q a f1 f2 / ((f1 + f2) k)."""
    ds, summary = default_run
    m, alpha = params["module"], params["pressure_angle"]
    z1, z2 = params["teeth_pinion"], params["teeth_gear"]
    omega1 = params["pinion_speed"]
    rb1, rb2 = m * z1 / 2 * math.cos(alpha), m * z2 / 2 * math.cos(alpha)
    c = ds.c.values
    u1, u2 = omega1 * (rb1 * math.tan(alpha) + c), omega1 * z1 / z2 * (rb2 * math.tan(alpha) - c)
    a = ds.hertz_half_width.values
    friction = np.maximum(ds.friction_force_instantaneous.values, 0.0)
    q = friction * np.abs(u1 - u2) / (2.0 * a * params["face_width"])
    kappa, k = params["thermal_diffusivity"], params["thermal_conductivity"]
    l1, l2 = u1 * a / (2 * kappa), u2 * a / (2 * kappa)
    assert max(l1.max(), l2.max()) < 1e-3
    f1, f2 = (2 / math.pi * (1.5 - EULER_GAMMA - np.log(ell)) for ell in (l1, l2))
    flash = q * a * f1 * f2 / ((f1 + f2) * k)
    np.testing.assert_allclose(ds.flash_temperature.values, flash, rtol=1e-9)
    assert summary["flash_temperature_max"] == pytest.approx(flash.max(), rel=1e-9)
    assert f"a flash temperature rise of {flash.max():.1g} K" in _readme()


# ------------------------------------------------------------------------------------------- contact modulus
@pytest.mark.parametrize("e2, nu2", [(161e9, 0.0), (161e9, 0.5), (70e9, 0.17), (200e9, 0.3)])
def test_contact_modulus_uses_the_counter_bodys_poisson_ratio(params, e2, nu2):
    """1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson 1985, 4.3): the counter body's own nu2."""
    from memstribo.materials.pair import contact_modulus, contact_modulus_of

    e1, nu1 = params["youngs_modulus"], params["poisson_ratio"]
    expected = 1.0 / ((1 - nu1 ** 2) / e1 + (1 - nu2 ** 2) / e2)
    assert contact_modulus(e1, nu1, e2, nu2) == pytest.approx(expected, rel=1e-12)
    counter = params.updated({"counter_youngs_modulus": e2, "counter_poisson_ratio": nu2})
    assert contact_modulus_of(counter) == pytest.approx(expected, rel=1e-12)


def test_the_cycle_solves_with_the_counter_bodys_poisson_ratio(params):
    """The cycle's Hertz half-width a = sqrt(4 F' R_ef / (pi E*)) at the same load and radii: against the same
    silicon, a counter body of nu2 = 0.45 widens it by sqrt(E*_Si / E*), E* from both bodies' nu."""
    e2, nu2 = 161e9, 0.45
    counter = params.updated({"counter_youngs_modulus": e2, "counter_poisson_ratio": nu2})
    ds = simulate_mesh(counter, steps=5)
    same = simulate_mesh(params, steps=5)
    e1, nu1 = params["youngs_modulus"], params["poisson_ratio"]
    modulus = 1.0 / ((1 - nu1 ** 2) / e1 + (1 - nu2 ** 2) / e2)
    silicon = e1 / (2 * (1 - nu1 ** 2))
    assert ds.attrs["contact_modulus"] == pytest.approx(modulus, rel=1e-12)
    assert same.attrs["contact_modulus"] == pytest.approx(silicon, rel=1e-12)
    np.testing.assert_allclose(ds.normal_force.values, same.normal_force.values, rtol=1e-12)
    np.testing.assert_allclose(ds.hertz_half_width.values / same.hertz_half_width.values,
                               math.sqrt(silicon / modulus), rtol=1e-9)


# ------------------------------------------------------------------------------------------- CI configuration
def test_ci_runs_the_browser_tests_and_every_modules_doctests():
    ci = (REPO / ".ci" / "run").read_text(encoding="utf-8")
    assert re.search(r"^export CI=true$", ci, re.M), "CI=true: the browser tests fail rather than skip in CI"
    assert "install -y -qq chromium" in ci
    pyproject = (REPO / "pyproject.toml").read_text(encoding="utf-8")
    assert "--doctest-modules" in pyproject and '"src/memstribo"' in pyproject
