"""A lab's own measurements (issue 37 item 1): user files for validate-lab and calibrate, their checks, --set and
--parameter-set honoured, the calibrated parameter set usable by --parameter-set FILE; the worked example (item 4)."""

import datetime
from pathlib import Path

import pytest

from memstribo.errors import InputError
from memstribo.laboratory.user import load_user_measurements
from memstribo.parameters import get_parameter_values
from memstribo.quantities import QUANTITIES

REPO = Path(__file__).resolve().parent.parent
EXAMPLE = REPO / "examples" / "own_measurement.toml"

ROW = '''
[[measurement]]
id = "{id}"
quantity = "kinetic_cof"
value = 0.3
unit = "1"
scatter = {{ kind = "sd", value = 0.03 }}
geometry = "sidewall"
contact_pressure = 2e7
environment = "air"
relative_humidity = 0.4
roughness = {{ rq = 10.3e-9, correlation_length = 83e-9 }}
citation = "own measurement"
measured_by = "a lab"
measured_on = 2026-11-28
calibration = true
'''


def write(tmp_path, text, name="mine.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def edit(row, old, new):
    assert old in row
    return row.replace(old, new)


def test_every_kind_of_citation_is_accepted(tmp_path):
    rows = [ROW.format(id="own"),
            edit(ROW.format(id="doi"), 'citation = "own measurement"', 'citation = "doi:10.1063/1.370809"'),
            edit(ROW.format(id="text"), 'citation = "own measurement"',
                 'citation = "A. Author, Sidewall friction, J. Something 1 (2020) 1"'),
            edit(ROW.format(id="key"), 'citation = "own measurement"', 'citation = "srinivasan_report_1998"')]
    loaded = load_user_measurements(write(tmp_path, "".join(rows)))
    assert [m.citation for m in loaded] == ["own measurement", "doi:10.1063/1.370809",
                                            "A. Author, Sidewall friction, J. Something 1 (2020) 1",
                                            "srinivasan_report_1998"]
    assert loaded[0].condition("measured_on") == str(datetime.date(2026, 11, 28))
    assert loaded[0].condition("temperature") == "not stated"


@pytest.mark.parametrize("old, new, words", [
    ('citation = "own measurement"\n', "", r"row #1 \('bad'\): field citation is missing"),
    ('measured_by = "a lab"\n', "", r"row #1 \('bad'\): field measured_by is missing"),
    ("measured_on = 2026-11-28", 'measured_on = "last week"', "field measured_on"),
    ('citation = "own measurement"', 'citation = "doi:11.1/x"', "is not a DOI"),
    ('citation = "own measurement"', 'citation = "me"', "neither a key"),
    ('unit = "1"', 'unit = "N"', r"row #1 \('bad'\): unit 'N' for kinetic_cof"),
    ('geometry = "sidewall"\n', "", r"row #1 \('bad'\): lacks geometry"),
    ("relative_humidity = 0.4", "relative_humidity = 1.2", "field relative_humidity = 1.2 is outside the model's range"),
    ("contact_pressure = 2e7", "contact_pressure = 5e10", "field contact_pressure = 5e\\+10 Pa is outside"),
    ('geometry = "sidewall"', 'geometry = "sphere_on_flat"', "field sphere_radius is missing"),
])
def test_bad_rows_are_refused_naming_row_and_field(tmp_path, old, new, words):
    with pytest.raises(InputError, match=words):
        load_user_measurements(write(tmp_path, edit(ROW.format(id="bad"), old, new)))


def test_a_missing_or_broken_file_is_a_clear_error(cli, tmp_path):
    code, _, err = cli("validate-lab", tmp_path / "missing.toml")
    assert code == 2 and "does not exist" in err
    code, _, err = cli("calibrate", write(tmp_path, "[[measurement]\n"))
    assert code == 2 and "not valid TOML" in err
    code, _, err = cli("validate-lab", write(tmp_path, "[other]\nx = 1\n"))
    assert code == 2 and "no [[measurement]] rows" in err


def test_a_duplicated_id_is_refused_naming_both_rows(tmp_path):
    with pytest.raises(InputError, match=r"row #2 \('same'\): field id is used twice \(also row #1\)"):
        load_user_measurements(write(tmp_path, ROW.format(id="same") * 2))


def test_validate_lab_reads_a_user_file_and_honours_set_and_parameter_set(cli, tmp_path):
    path = write(tmp_path, ROW.format(id="mine"))
    plain = cli.json("validate-lab", path, "--realisations", "1")
    # silicon_oxide_air (the lab's set for a row in air) keeps the thesis's vdW rule, where U_vdW is a constant
    more = cli.json("validate-lab", path, "--realisations", "1", "--parameter-set", "silicon_oxide_air",
                    "--set", "vdw_bond_energy=2e-20")
    other = cli.json("validate-lab", path, "--realisations", "1", "--parameter-set", "silicon_thesis")
    medians = [out["laboratory_rows"][0]["median"] for out in (plain, more, other)]
    assert medians[1] > 1.1 * medians[0]  # more vdW bond energy, more friction
    assert medians[2] != pytest.approx(medians[0], rel=0.02)  # silicon's Si-Si bonds instead of the oxide's
    assert set(plain) - {"warnings"} <= set(QUANTITIES)


def test_validate_lab_on_the_packaged_set_honours_set(cli):
    plain = cli.json("validate-lab", "--realisations", "1", "--parameter-set", "silicon_oxide_air")
    more = cli.json("validate-lab", "--realisations", "1", "--parameter-set", "silicon_oxide_air",
                    "--set", "vdw_bond_energy=2e-20")
    a = {r["id"]: r.get("median") for r in plain["laboratory_rows"]}
    b = {r["id"]: r.get("median") for r in more["laboratory_rows"]}
    changed = [k for k in a if a[k] is not None and b[k] != pytest.approx(a[k], rel=1e-3)]
    assert changed


def test_calibrate_writes_a_set_that_parameter_set_reads(cli, tmp_path):
    path = write(tmp_path, ROW.format(id="mine"))
    out = tmp_path / "cal.toml"
    result = cli.json("calibrate", path, "--samples", "12", "--realisations", "1", "--out", out,
                      "--set", "hamaker_constant=7e-20", "--parameter-set", "silicon_oxide_air")
    assert result["calibration_rows"] == ["mine"]
    assert set(result) - {"warnings"} <= set(QUANTITIES)
    params = get_parameter_values(str(out))
    for c in result["calibrated_constants"]:
        assert params[c["name"]] == pytest.approx(c["post_median"], rel=1e-4)
    assert params["hamaker_constant"] == pytest.approx(7e-20)  # the --set value travels with the set
    code, text, err = cli("parameters", "--parameter-set", out)
    assert code == 0 and str(out) in text


def test_a_set_file_without_base_or_with_an_unknown_parameter_is_refused(tmp_path):
    with pytest.raises(InputError, match="base is missing"):
        get_parameter_values(str(write(tmp_path, "[parameters.bond_energy]\nvalue = 1e-20\n", "a.toml")))
    with pytest.raises(InputError, match="unknown parameter 'bond_energie'"):
        get_parameter_values(str(write(tmp_path, '[meta]\nbase = "silicon_thesis"\n[parameters.bond_energie]\n'
                                                 "value = 1e-20\n", "b.toml")))
    with pytest.raises(InputError, match="does not exist"):
        get_parameter_values(str(tmp_path / "missing.toml"))


def test_calibrate_refuses_when_every_constant_is_fixed(cli, tmp_path):
    path = write(tmp_path, ROW.format(id="mine") + '\n[calibration]\nconstants = ["vdw_bond_energy"]\n')
    code, _, err = cli("calibrate", path, "--samples", "4", "--parameter-set", "silicon_oxide_air",
                       "--set", "vdw_bond_energy=5e-21")
    assert code == 2 and "no constant to calibrate" in err


def test_the_worked_example_validates_and_calibrates(cli, tmp_path):
    """examples/own_measurement.toml: our sidewall tribometer's mu_k, then the calibrated set for the gear."""
    checked = cli.json("validate-lab", EXAMPLE, "--realisations", "1")
    assert [r["status"] for r in checked["laboratory_rows"]] == ["predicted", "predicted"]
    out = tmp_path / "own.calibrated.toml"
    cal = cli.json("calibrate", EXAMPLE, "--samples", "16", "--realisations", "1", "--out", out)
    assert cal["calibration_rows"] == ["our_sidewall_kinetic"]
    assert get_parameter_values(str(out))["vdw_bond_energy"] > 0
