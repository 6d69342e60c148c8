"""The laboratory comparison (issue 28): measurement data, bands, calibration weights, fitted-constant flags."""

import math
from pathlib import Path

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.laboratory import calibration, data, predict
from memstribo.parameters import fitted
from memstribo.parameters import get_parameter_values
from memstribo.physics.capillary import WATER, kelvin_radius
from memstribo.physics.coating import get_coating
from memstribo.references import REFERENCES

REPO = Path(__file__).resolve().parent.parent

ROW = '''
[[measurement]]
id = "made_up"
quantity = "kinetic_cof"
value = 0.2
unit = "1"
scatter = { kind = "sd", value = 0.02 }
geometry = "flat"
contact = "test"
contact_pressure = 1e4
environment = "vacuum"
temperature = "not stated"
coating = "none"
surface = "silicon"
speed = "not stated"
roughness = "not stated"
citation = "thesis"
calibration = false
source_text = "made up for the test"
'''


def _rows(tmp_path, text):
    path = tmp_path / "m.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_shipped_measurements_load_with_citations_and_a_declared_subset():
    rows = data.load_measurements()
    assert len(rows) >= 12
    assert 0 < sum(r.calibration for r in rows) <= len(rows) / 3
    for r in rows:
        text = REFERENCES[r.citation]
        # traceable: a DOI, a report, an ISBN, a proceedings record, or the record where the abstract was read
        assert any(k in text for k in ("doi:", "report", "ISBN", "proceedings", "record: ")), r.id
    kinds = {r.quantity for r in rows}
    assert {"static_cof", "kinetic_cof", "adhesion_energy"} <= kinds
    assert any(r.quantity.startswith("cycles") for r in rows)


@pytest.mark.parametrize("drop", ["citation", "environment", "unit", "contact"])
def test_a_row_without_a_condition_unit_or_citation_is_refused_by_name(tmp_path, drop):
    text = "\n".join(line for line in ROW.splitlines() if not line.startswith(drop + " ="))
    with pytest.raises(InputError, match=r"made_up.*lacks " + drop):
        data.load_measurements(_rows(tmp_path, text))


def test_a_wrong_unit_or_an_unknown_citation_is_refused(tmp_path):
    with pytest.raises(InputError, match="made_up.*unit 'N'"):
        data.load_measurements(_rows(tmp_path, ROW.replace('unit = "1"', 'unit = "N"')))
    with pytest.raises(InputError, match="made_up.*citation 'nobody_2020'"):
        data.load_measurements(_rows(tmp_path, ROW.replace('citation = "thesis"', 'citation = "nobody_2020"')))


def test_more_than_a_third_for_calibration_is_refused(tmp_path):
    rows = ROW.replace("calibration = false", "calibration = true") + ROW.replace("made_up", "other")
    with pytest.raises(InputError, match="1 of 2 rows are declared for calibration"):
        data.load_measurements(_rows(tmp_path, rows))
    assert len(data.load_measurements(_rows(tmp_path, rows + ROW.replace("made_up", "third")))) == 3


def test_band_is_the_hazen_percentile_and_weights_select_samples():
    values = np.arange(40.0).reshape(4, 10)
    expected = np.percentile(values.ravel(), [50, 5, 95], method="hazen")
    assert predict.band(values) == pytest.approx(expected)
    only_last = predict.band(values, weights=[0, 0, 0, 1])
    assert only_last == pytest.approx(np.percentile(values[3], [50, 5, 95], method="hazen"))
    with pytest.raises(InputError):
        predict.band(values, weights=[1, 1])


def test_inside_and_outside_with_hand_made_samples():
    row = next(r for r in data.load_measurements() if r.id == "srinivasan1998_kinetic_ots")
    inside = predict.judge(row, np.full((3, 4), row.value) * np.linspace(0.5, 1.5, 4))
    assert inside.inside and inside.low < row.value < inside.high
    outside = predict.judge(row, np.full((3, 4), 10 * row.value))
    assert outside.inside is False and outside.ratio == pytest.approx(0.1)


def test_cases_the_model_cannot_build_are_listed_with_their_reason():
    rows = {r.id: r for r in data.load_measurements()}
    cases = {"lim1990_static_poly_poly": "load is not stated", "lim1990_static_nitride_poly": "load is not stated",
             "gabriel1990_kinetic_turbine": "rotor_hub", "mehregany2005_micromotor_starts": "damage law"}
    for rid, words in cases.items():
        p = predict.predict_row(rows[rid])
        assert p.status == "not predicted" and words in p.reason


def test_constant_samples_reach_the_coated_case():
    row = next(r for r in data.load_measurements() if r.id == "srinivasan1998_kinetic_ots")
    u = get_coating("OTS").vdw_bond_energy
    values, _ = predict.row_values(row, [{"coating_vdw_bond_energy": u}, {"coating_vdw_bond_energy": 2 * u}],
                                   realisations=1)
    assert values[1, 0] > 1.2 * values[0, 0]
    fdts = next(r for r in data.load_measurements() if r.id == "srinivasan1998_kinetic_fdts")
    values, _ = predict.row_values(fdts, [{"coating_vdw_bond_energy": u}, {"coating_vdw_bond_energy": 2 * u}],
                                   realisations=1)
    assert values[0, 0] == values[1, 0]  # the sampled coating constants stand for OTS only


def test_work_of_separation_of_a_touching_interface_is_the_larger_of_w_and_the_meniscus():
    params = get_parameter_values("silicon_oxide_air")
    z0 = params["cutoff_distance"]
    w = params["hamaker_constant"] / (12 * math.pi * z0**2)
    total, vdw, cap = predict.beam_work_of_separation(np.zeros(50), params, 0.0)
    assert vdw == pytest.approx(w, rel=0.01) and cap == 0.0
    total, _, cap = predict.beam_work_of_separation(np.zeros(50), params, 0.9)
    assert cap == pytest.approx(2 * WATER["surface_tension"] * math.cos(params["water_contact_angle"]), rel=0.01)
    assert total == pytest.approx(max(w, cap), rel=1e-12)  # one work per element (issue #36)
    assert kelvin_radius(0.9) > 0


def test_likelihood_prefers_the_sample_that_matches_and_weights_normalise():
    row = next(r for r in data.load_measurements() if r.calibration)
    values = np.array([[row.value * 3] * 3, [row.value] * 3, [row.value / 3] * 3])
    ll = calibration.log_likelihood([row], [values])
    assert np.argmax(ll) == 1 and ll[0] == pytest.approx(ll[2])
    w = calibration.importance_weights(ll)
    assert w.sum() == pytest.approx(1.0) and w[1] > 0.9
    assert calibration.effective_sample_size(np.ones(7)) == pytest.approx(7.0)
    assert calibration.weighted_quantile([1, 2, 3], [0, 1, 0], 0.5) == pytest.approx(2.0)


def test_fitted_constants_are_listed_and_far_runs_warn():
    params = get_parameter_values("silicon_oxide_air")
    names = {(f["name"], f["where"]) for f in fitted.fitted_constants(params, get_coating("OTS"))}
    assert names == {("vdw_bond_energy", "parameter set silicon_oxide_air"), ("coating_vdw_bond_energy", "coating OTS")}
    assert fitted.fitted_constants(params.updated({"vdw_bond_energy": 1e-21})) == []
    assert fitted.fitted_constants(get_parameter_values("silicon_thesis")) == []
    far = fitted.fit_condition_warnings(params, 3e-3, "OTS")
    assert any("2.5e-05 N" in w and "120 times" in w for w in far)
    near = fitted.fit_condition_warnings(get_parameter_values("silicon_thesis"), 25e-6, "OTS")
    assert near == []
    with pytest.raises(InputError):
        fitted.fit_condition_warnings(params, -1.0)


@pytest.mark.slow
def test_docs_experiments_regenerates_identically():
    from memstribo.laboratory.report import markdown, run_all

    page = (REPO / "docs" / "experiments.md").read_text(encoding="utf-8")
    assert markdown(run_all()) == page, "regenerate: python -m memstribo.laboratory --write docs/experiments.md"


def test_validate_lab_command_prints_every_row_with_registered_keys(cli, monkeypatch):
    from memstribo.laboratory import report
    from memstribo.quantities import QUANTITIES

    for key, value in {"nominal_realisations": 1, "prior_samples": 4, "calibration_realisations": 1}.items():
        monkeypatch.setitem(report.SETTINGS, key, value)
    out = cli.json("validate-lab")
    assert [r["id"] for r in out["laboratory_rows"]] == [r.id for r in data.load_measurements()]
    assert all(("median" in r) == (r["status"] == "predicted") and ("reason" in r) != ("median" in r)
               for r in out["laboratory_rows"])
    assert set(out) - {"warnings"} <= set(QUANTITIES)


def test_static_rows_are_predicted_with_the_start_up_force(params):
    """MODEL 7f / issue #35 item 6: a static row reads the structure's start-up force (its bonds at their lateral
    peak, 1.2687 U / D, in one registry, plus the elastic friction) over F_N + F_adh, averaged over the rest
    positions; a kinetic row the kinetic COF."""
    from memstribo.laboratory.predict import _profile, static_cof
    from memstribo.simulations import sliding

    profile = _profile(1.6e-9, 60e-9, 2.4e-6, 3)
    slid = sliding.slide_fixed_load(params, profile, load=2e-6, distance=0.2e-6)
    bonds = slid.friction_force_chemical + slid.friction_force_vdw
    expected = ((1.2686660 * bonds + slid.friction_force_elastic) / (slid.normal_force + slid.adhesion_force)).mean()
    assert static_cof(slid, params) == pytest.approx(float(expected), rel=1e-6)
    kinetic = sliding.summarize(slid).cof_mean
    assert static_cof(slid, params) != pytest.approx(kinetic, rel=1e-3)
    # after a short dwell fewer bonds have formed: a lower static COF
    assert static_cof(slid, params.updated({"startup_dwell": 0.01})) < static_cof(slid, params)
