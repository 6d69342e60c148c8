import math

import pytest

from memstribo.errors import InputError
from memstribo.parameters import SPECS, available_parameter_sets, get_parameter_values, read_config
from memstribo.units import to_si


def test_default_set_is_complete_and_sourced(params):
    assert set(params) == set(SPECS)
    for name in params:
        assert params.source(name), f"{name} has no source"


def test_thesis_values(params):
    assert params["youngs_modulus"] == 161e9
    assert params["poisson_ratio"] == 0.23
    assert params["bond_length"] == 2.35e-10
    # 327 kJ/mol / N_A (thesis 3.5)
    assert params["bond_energy"] == pytest.approx(327e3 / 6.02214076e23, rel=1e-3)
    assert params["vdw_bond_energy"] == pytest.approx(params["bond_energy"] / 100)
    # module from outer diameters 81 and 303 um with standard addendum (MODEL §6)
    assert params["module"] == pytest.approx((81 + 303) / (19 + 76 + 4) * 1e-6)
    assert math.degrees(params["pressure_angle"]) == pytest.approx(20.0)
    # F_t = T / r_pitch,pinion = 2.82e-3 N (thesis 4-27)
    r_pitch = params["teeth_pinion"] * params["module"] / 2
    assert params["drive_torque"] / r_pitch == pytest.approx(2.82e-3)


@pytest.mark.parametrize("text, unit, expected", [
    ("25 uN", "N", 25e-6), ("25uN", "N", 25e-6), ("195.5 nm", "m", 195.5e-9), ("20 deg", "rad", math.radians(20)),
    ("161 GPa", "Pa", 161e9), ("0.5", "", 0.5), (3, "", 3.0), ("1e-9", "m", 1e-9), ("25 µN", "N", 25e-6),
])
def test_to_si(text, unit, expected):
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("overrides, match", [
    ({"poison_ratio": 0.3}, "unknown parameter 'poison_ratio'. Did you mean 'poisson_ratio'"),
    ({"poisson_ratio": 0.7}, "outside its range"),
    ({"poisson_ratio": -1.0}, "outside its range"),
    ({"youngs_modulus": 0}, "outside its range"),
    ({"youngs_modulus": "-5 GPa"}, "outside its range"),
    ({"normal_load": "25 m"}, "needs units convertible to N"),
    ({"normal_load": "lots"}, "cannot read"),
    ({"normal_load": "nan"}, "finite"),
    ({"atomic_per_side": 2.5}, "integer"),
    ({"pressure_angle": 20}, "outside its range"),
    ({"atomic_width": "300 nm"}, "larger than adhesive_width"),
])
def test_bad_overrides(params, overrides, match):
    with pytest.raises(InputError, match=match):
        params.updated(overrides)


def test_overrides_keep_provenance(params):
    updated = params.updated({"poisson_ratio": 0.5, "adhesive_width": "195.5 nm"})
    assert updated["poisson_ratio"] == 0.5
    assert updated["adhesive_width"] == pytest.approx(195.5e-9)
    assert updated.source("poisson_ratio") == "user override"
    assert params["poisson_ratio"] == 0.23  # the original is unchanged


def test_unknown_set():
    with pytest.raises(InputError, match="Available: .*silicon_thesis"):
        get_parameter_values("silicone_thesis")
    assert "silicon_thesis" in available_parameter_sets()


def test_toml_round_trip(params, tmp_path):
    path = tmp_path / "p.toml"
    path.write_text(params.updated({"normal_load": "50 uN"}).to_toml())
    config = read_config(path)
    again = params.updated(config["parameters"])
    assert again.to_dict() == params.updated({"normal_load": 50e-6}).to_dict()


def test_config_errors(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        read_config(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("normal_load = [")
    with pytest.raises(InputError, match="not valid TOML"):
        read_config(bad)
    unknown = tmp_path / "unknown.toml"
    unknown.write_text('normal_lod = "25 uN"\n')
    with pytest.raises(InputError, match="Did you mean 'normal_load'"):
        read_config(unknown)


def test_a_set_with_a_base_changes_only_what_it_lists():
    """silicon_oxide_air (issue #17) names silicon_thesis as its base and changes a few values, each sourced."""
    from memstribo.parameters import available_parameter_sets, get_parameter_values

    assert "silicon_oxide_air" in available_parameter_sets()
    oxide, base = get_parameter_values("silicon_oxide_air"), get_parameter_values("silicon_thesis")
    assert oxide["environment"] == "air" and oxide["bond_energy"] < base["bond_energy"]
    assert "Israelachvili" in oxide.source("hamaker_constant")
    assert oxide["youngs_modulus"] == base["youngs_modulus"]
    assert oxide.source("youngs_modulus") == base.source("youngs_modulus")
