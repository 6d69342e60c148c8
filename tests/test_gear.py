"""Involute spur pair: closed forms, the thesis's numbers, invariants and bad input (thesis 4.3-4.7)."""

import math

import numpy as np
import pytest

from memstribo.materials.pair import contact_modulus
from memstribo.errors import InputError
from memstribo.physics.gear import (
    GearPair,
    first_contact_point,
    hertz_line_contact,
    load_share_dry,
    load_share_lubricated,
    module_from_outer_diameters,
    tangential_force,
)


@pytest.fixture
def pair(params):
    return GearPair.from_parameters(params)


def test_module_from_outer_diameters_matches_default(params):
    # MODEL §6: (81 + 303) um / (19 + 76 + 4) = 3.8788 um; the parameter set stores that value
    module = module_from_outer_diameters(81e-6, 303e-6, 19, 76)
    assert module == pytest.approx(3.878787878787879e-6, rel=1e-12)
    assert params["module"] == pytest.approx(module, rel=1e-12)
    built = GearPair.from_outer_diameters(81e-6, 303e-6, 19, 76, math.radians(20), 2e-6)
    assert built.module == pytest.approx(module, rel=1e-12)
    # the sum of the tip diameters is reproduced exactly (each alone within 0.5 um)
    assert 2 * built.tip_radii.sum() == pytest.approx(384e-6, rel=1e-12)
    np.testing.assert_allclose(2 * built.tip_radii, [81e-6, 303e-6], atol=0.5e-6)


def test_radii_and_base_pitch_closed_forms(pair):
    m, phi = pair.module, pair.pressure_angle
    np.testing.assert_allclose(pair.pitch_radii, [19 * m / 2, 76 * m / 2], rtol=1e-14)
    np.testing.assert_allclose(pair.base_radii, pair.pitch_radii * math.cos(phi), rtol=1e-14)
    np.testing.assert_allclose(pair.tip_radii, pair.pitch_radii + m, rtol=1e-14)
    assert pair.base_pitch == pytest.approx(math.pi * m * math.cos(phi), rel=1e-14)


def test_contact_ratio_textbook_formula(pair):
    # epsilon = [sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2) - a sin(phi)] / p_b, a = r1 + r2
    (ra1, ra2), (rb1, rb2) = pair.tip_radii, pair.base_radii
    a = pair.pitch_radii.sum()
    expected = (math.sqrt(ra1**2 - rb1**2) + math.sqrt(ra2**2 - rb2**2) - a * math.sin(pair.pressure_angle)) \
        / pair.base_pitch
    assert pair.contact_ratio == pytest.approx(expected, rel=1e-12)
    assert pair.contact_ratio == pytest.approx(1.6814, abs=5e-5)
    assert pair.first_contact < 0 < pair.last_contact
    a_, b_ = pair.single_tooth_zone
    assert b_ - a_ == pytest.approx((2 - pair.contact_ratio) * pair.base_pitch, rel=1e-12)


def test_radii_of_curvature_sum_is_constant_and_pitch_values(pair):
    c = np.linspace(pair.first_contact, pair.last_contact, 7)
    r1, r2 = pair.radii_of_curvature(c)
    # R1 + R2 = (rb1 + rb2) tan(phi) = a sin(phi) along the whole path
    np.testing.assert_allclose(r1 + r2, pair.pitch_radii.sum() * math.sin(pair.pressure_angle), rtol=1e-12)
    r1p, r2p = pair.radii_of_curvature(0.0)
    assert r1p == pytest.approx(pair.pitch_radii[0] * math.sin(pair.pressure_angle), rel=1e-12)
    assert pair.effective_radius(0.0) == pytest.approx(r1p * r2p / (r1p + r2p), rel=1e-12)
    assert pair.effective_radius(0.0) == pytest.approx(10.08e-6, rel=5e-4)


def test_velocities_equal_at_pitch_point_and_sliding_linear(pair):
    u1, u2 = pair.surface_velocities(0.0)
    assert u1 == pytest.approx(u2, rel=1e-12)
    assert pair.sliding_velocity(0.0) == pytest.approx(0.0, abs=1e-15)
    c = np.linspace(pair.first_contact, pair.last_contact, 9)
    np.testing.assert_allclose(pair.sliding_velocity(c), c * (pair.pinion_speed + pair.gear_speed), atol=1e-15)


def test_time_along_the_path(pair):
    assert pair.time(pair.first_contact) == 0.0
    assert pair.time(pair.last_contact) == pytest.approx(pair.path_of_contact / (pair.base_radii[0]
                                                                                    * pair.pinion_speed))
    assert pair.mesh_duration == pytest.approx(pair.time(pair.last_contact), rel=1e-12)


def test_load_sharing_dry_and_lubricated(pair):
    a, b = pair.single_tooth_zone
    c = np.array([pair.first_contact, 0.5 * (pair.first_contact + a), 0.5 * (a + b), 0.5 * (b + pair.last_contact),
                  pair.last_contact, pair.last_contact + 1e-6])
    np.testing.assert_array_equal(pair.load_share(c), [0.5, 0.5, 1.0, 0.5, 0.5, 0.0])
    lub = pair.load_share(c, "lubricated")
    np.testing.assert_allclose(lub, [1 / 3, 0.5, 1.0, 0.5, 1 / 3, 0.0], rtol=1e-12)
    assert pair.load_share(a - 1e-12, "lubricated") == pytest.approx(2 / 3, rel=1e-6)
    # dry sharing conserves the load: the pairs in contact at any instant carry it all
    cs = np.linspace(pair.first_contact, pair.first_contact + pair.base_pitch, 50, endpoint=False)
    total = sum(load_share_dry(cs + k * pair.base_pitch, pair.first_contact, pair.last_contact, pair.base_pitch)
                for k in range(-2, 3))
    np.testing.assert_allclose(total, 1.0, rtol=1e-12)
    with pytest.raises(InputError, match="'dry' or 'lubricated'"):
        pair.load_share(0.0, "wet")
    with pytest.raises(InputError, match="contact ratio between"):
        load_share_lubricated(0.0, -3.0, 3.0, 2.0)


def test_hertz_at_pitch_point_closed_form_and_thesis(pair):
    modulus = contact_modulus(161e9, 0.23)
    assert modulus == pytest.approx(85.0e9, rel=1e-3)  # MODEL §2: 85.0 GPa
    hertz = pair.hertz(0.0, 25e-6, modulus)
    w = 25e-6 / 2e-6
    r_ef = pair.effective_radius(0.0)
    assert hertz.half_width == pytest.approx(math.sqrt(4 * w * r_ef / (math.pi * modulus)), rel=1e-12)
    # ours: 43.45 nm. The thesis prints 58.87 nm (4.5), which does not follow from its inputs (MODEL §6)
    assert hertz.half_width == pytest.approx(43.45e-9, rel=1e-3)
    assert hertz.half_width != pytest.approx(58.869e-9, rel=0.05)
    # the elliptic pressure carries the load: integral p dx = pi a p0 / 2 = w
    assert math.pi * hertz.half_width * hertz.peak_pressure / 2 == pytest.approx(w, rel=1e-12)
    assert hertz.contact_area == pytest.approx(2 * hertz.half_width * 2e-6, rel=1e-12)
    # a grows as sqrt(load)
    h4 = hertz_line_contact(100e-6, 2e-6, r_ef, modulus)
    assert h4.half_width / hertz.half_width == pytest.approx(2.0, rel=1e-12)


def test_tangential_force_thesis_value(params, pair):
    # thesis 4.7 (4-27): F_t = 2.82e-3 N
    assert tangential_force(params["drive_torque"], pair.pitch_radii[0]) == pytest.approx(2.82e-3, rel=1e-3)


def test_dissimilar_contact_modulus():
    assert contact_modulus(161e9, 0.23, 1e300, 0.0) == pytest.approx(161e9 / (1 - 0.23**2), rel=1e-12)


@pytest.mark.parametrize("overrides, match", [
    (dict(teeth_pinion=12), "interference"),
    (dict(teeth_pinion=15, teeth_gear=16), "undercut"),
    (dict(addendum_coefficient=0.3), "contact ratio 0.55"),
])
def test_non_meshing_pairs_raise(params, overrides, match):
    with pytest.raises(InputError, match=match):
        GearPair.from_parameters(params.updated(overrides))


def test_tip_below_base_radius_raises():
    with pytest.raises(InputError, match="tip radius .* not above its base radius"):
        first_contact_point(10e-6, 9e-6, math.radians(20))


def test_bad_construction_values():
    with pytest.raises(InputError, match="pressure angle"):
        GearPair(19, 76, 4e-6, 0.0, 2e-6)
    with pytest.raises(InputError, match="positive"):
        GearPair(19, 76, -4e-6, 0.3, 2e-6)
    with pytest.raises(InputError, match="at least 2 steps"):
        GearPair(19, 76, 4e-6, math.radians(20), 2e-6).positions(1)
    with pytest.raises(InputError, match="positive load"):
        hertz_line_contact(0.0, 2e-6, 1e-5, 85e9)


def test_cli_gear_json(cli):
    values = cli.json("gear")
    for key in ("module", "pressure_angle", "pitch_radii", "base_radii", "tip_radii", "base_pitch",
                "path_of_contact", "contact_ratio", "single_tooth_zone", "effective_radius_pitch",
                "hertz_half_width", "hertz_peak_pressure", "tangential_force"):
        assert key in values
    assert values["tangential_force"] == pytest.approx(2.82e-3, rel=1e-3)
    assert values["hertz_half_width"] == pytest.approx(43.45e-9, rel=1e-3)
    assert len(values["pitch_radii"]) == 2
    code, out, err = cli("gear")
    assert code == 0 and "contact_ratio" in out and "µm" in out and " um" not in out
    assert "pressure_angle          20 deg" in out  # angles in degrees (issue #29), not 0.3491 rad
    code, out, err = cli("gear", "--set", "pressure_angle=95 deg")
    assert code == 2 and ">= 10 deg and <= 35 deg" in err


def test_cli_gear_set_and_bad_input(cli):
    values = cli.json("gear", "--set", "pressure_angle=25 deg", "--set", "teeth_pinion=20")
    assert values["pressure_angle"] == pytest.approx(math.radians(25))
    code, out, err = cli("gear", "--set", "teeth_pinion=12")
    assert code == 2 and "interference" in err and "Traceback" not in err


def test_cli_gear_outer_diameters(cli):
    values = cli.json("gear", "--outer-diameters", "81um,303um")
    assert values["module"] == pytest.approx(3.878787878787879e-6, rel=1e-12)
    code, out, err = cli("gear", "--outer-diameters", "81um")
    assert code == 2 and "two lengths" in err and "Traceback" not in err
    code, out, err = cli("gear", "--outer-diameters=-81um,303um")
    assert code == 2 and "Traceback" not in err


# --- design checks in ISO 21771 terms (issue #15) ----------------------------------------------------------------
def test_tip_thickness_closed_form_and_the_thesis_pair_has_no_warning(pair):
    from memstribo.physics.gear import involute_function, tip_tooth_thickness

    # s_a = d_a (s/d + inv alpha - inv alpha_a), s = pi m / 2 (ISO 21771:2007)
    m, z, alpha = pair.module, pair.teeth_pinion, pair.pressure_angle
    d, d_a = m * z, m * z + 2 * m
    alpha_a = math.acos(d * math.cos(alpha) / d_a)
    expected = d_a * (math.pi * m / 2 / d + (math.tan(alpha) - alpha) - (math.tan(alpha_a) - alpha_a))
    assert pair.tip_thickness[0] == pytest.approx(expected, rel=1e-12)
    assert tip_tooth_thickness(z, m, alpha) == pytest.approx(expected, rel=1e-12)
    assert involute_function(math.radians(20)) == pytest.approx(0.014904383867336446, rel=1e-12)
    # a rack-like tooth (many teeth) tends to the rack's tip thickness pi m / 2 - 2 h_a m tan(alpha)
    assert tip_tooth_thickness(100000, m, alpha) / m == pytest.approx(math.pi / 2 - 2 * math.tan(alpha), rel=1e-3)
    assert pair.tip_thickness[0] / m == pytest.approx(0.6886, abs=1e-3)
    assert pair.centre_distance == pytest.approx(m * (19 + 76) / 2)
    assert pair.warnings == []


@pytest.mark.parametrize("kwargs, match", [
    (dict(pressure_angle=math.radians(89)), "pinion's teeth are pointed"),
    (dict(addendum_coefficient=1.6), r"pointed: the tooth thickness at the tip \(ISO 21771 s_a\) is -0.111"),
    (dict(addendum_coefficient=2.0), "Lower the addendum"),
])
def test_pointed_teeth_are_refused_with_the_reason(kwargs, match):
    args = dict(teeth_pinion=19, teeth_gear=76, module=3.8788e-6, pressure_angle=math.radians(20), face_width=2e-6)
    with pytest.raises(InputError, match=match):
        GearPair(**{**args, **kwargs})


def test_marginal_designs_warn():
    from memstribo.physics.gear import design_warnings

    thin = GearPair(30, 60, 3.88e-6, math.radians(35), 2e-6)  # meshes, but s_a = 0.09 m on the pinion
    found = design_warnings(thin)
    assert thin.warnings == found
    assert any("pinion's tooth thickness at the tip is 0.090 x module" in w for w in found)
    short = GearPair(19, 76, 3.88e-6, math.radians(20), 2e-6, addendum_coefficient=0.65)  # contact ratio 1.14
    assert [w for w in short.warnings if "contact ratio 1.143 is below 1.2" in w]
    assert not [w for w in short.warnings if "tip" in w]


def test_cli_gear_json_has_tip_thickness_and_design_warnings(cli):
    values = cli.json("gear")
    assert len(values["tip_thickness"]) == 2 and values["tip_thickness"][0] > 0.25 * values["module"]
    assert values["warnings"] == [] and "design_warnings" not in values
    warned = cli.json("gear", "--set", "pressure_angle=35 deg", "--set", "teeth_pinion=30", "--set", "teeth_gear=60")
    assert any("tooth thickness at the tip" in w for w in warned["warnings"])
    code, out, err = cli("gear", "--set", "pressure_angle=35 deg", "--set", "teeth_pinion=30", "--set",
                         "teeth_gear=60")
    assert code == 0 and "WARNING: the pinion's tooth thickness at the tip" in out
    # a dedendum deeper than the addendum, so that the tip clearance (issue #41) is not what refuses it
    code, out, err = cli("gear", "--set", "addendum_coefficient=1.6", "--set", "dedendum_coefficient=2")
    assert code == 2 and "pointed" in err and "Traceback" not in err
