"""The gear verdict under the laboratory's posterior (issue 37 item 6): importance weights on the study's samples."""

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.laboratory import posterior
from memstribo.uncertainty.priors import Prior

ROW = '''
[[measurement]]
id = "own_sidewall"
quantity = "kinetic_cof"
value = {value}
unit = "1"
scatter = {{ kind = "sd", value = {sd} }}
geometry = "flat"
contact = "our test structure"
contact_pressure = 1e5
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


def _points(n=12):
    energies = np.geomspace(1e-21, 3e-20, n)
    return [(0, {"vdw_bond_energy": float(e)}) for e in energies], energies


def test_weighted_probability_is_the_weighted_share_with_wilson_at_the_effective_size():
    from memstribo.uncertainty.intervals import wilson_interval

    flags = [1, 0, 0, 1]
    equal = posterior.weighted_probability(flags, [0.25] * 4)
    assert equal["probability"] == 0.5 and equal["effective_samples"] == pytest.approx(4.0)
    assert equal["ci"] == pytest.approx(list(wilson_interval(0.5, 4.0)))
    skewed = posterior.weighted_probability(flags, [0.7, 0.1, 0.1, 0.1])
    assert skewed["probability"] == pytest.approx(0.8)
    assert skewed["effective_samples"] == pytest.approx(1.0 / (0.49 + 0.03))
    assert skewed["ci"][1] - skewed["ci"][0] > equal["ci"][1] - equal["ci"][0] - 0.2  # fewer samples, no narrower
    with pytest.raises(InputError):
        posterior.weighted_probability([1, 0], [1.0])


def test_measurement_rows_move_the_verdict_towards_the_constants_they_favour(tmp_path):
    """A stuck sample is one with a large U_vdW (here by construction); a measured COF that only large U_vdW
    predicts must raise P(stiction), one that only small U_vdW predicts must lower it."""
    from memstribo.laboratory.predict import row_values
    from memstribo.laboratory.data import load_measurements

    points, energies = _points(5)
    summaries = [{"stiction": bool(e > 6e-21), "startup_stiction": bool(e > 1.5e-20)} for e in energies]
    path = tmp_path / "m.toml"
    path.write_text(ROW.format(value=0.3, sd=0.03), encoding="utf-8")
    (row,) = load_measurements(path)
    values, _ = row_values(row, [c for _, c in points], 1)
    cof = values[:, 0]
    assert np.all(np.diff(cof) > 0)  # the COF rises with U_vdW: the row can tell the samples apart
    priors = {"vdw_bond_energy": Prior("vdw_bond_energy", "loguniform", 1e-21, 3e-20)}
    results = {}
    for label, target in (("high", cof[-1]), ("low", cof[0])):
        path.write_text(ROW.format(value=float(target), sd=0.05 * float(target)), encoding="utf-8")
        results[label] = posterior.gear_posterior(path, points, summaries, priors, coating="OTS")
    prior_p = results["high"]["prior"]["stiction"]["probability"]
    assert results["high"]["posterior"]["stiction"]["probability"] > prior_p
    assert results["low"]["posterior"]["stiction"]["probability"] < prior_p
    for r in results.values():
        assert r["moved_by"][0]["id"] == "own_sidewall"
        assert 1.0 <= r["posterior_effective_samples"] <= len(points)
        for key in ("stiction", "startup_stiction"):
            low, high = r["posterior"][key]["ci"]
            assert low <= r["posterior"][key]["probability"] <= high
    lines = posterior.posterior_notes(results["high"])
    assert any("prior" in l and "posterior" in l and "P(stiction)" in l for l in lines)


def test_a_calibrated_set_weighs_by_its_posterior_over_the_prior(tmp_path):
    points, energies = _points(40)
    summaries = [{"stiction": bool(e > 6e-21)} for e in energies]
    priors = {"vdw_bond_energy": Prior("vdw_bond_energy", "loguniform", 1e-21, 3e-20)}
    path = tmp_path / "calibrated.toml"
    path.write_text("[posterior.vdw_bond_energy]\nmedian = 2e-20\np05 = 1.5e-20\np95 = 2.6e-20\n", encoding="utf-8")
    out = posterior.gear_posterior(path, points, summaries, priors)
    assert out["posterior"]["stiction"]["probability"] > 0.95 > out["prior"]["stiction"]["probability"]
    assert out["rows_used"] == ["[posterior.vdw_bond_energy]"]
    path.write_text("[posterior.nothing_sampled]\nmedian = 1\np05 = 0.5\np95 = 2\n", encoding="utf-8")
    with pytest.raises(InputError, match="none of the study's sampled constants"):
        posterior.gear_posterior(path, points, summaries, priors)


def test_a_file_that_is_neither_is_refused_by_name(tmp_path):
    path = tmp_path / "x.toml"
    path.write_text("[meta]\nname = 'x'\n", encoding="utf-8")
    with pytest.raises(InputError, match="neither"):
        posterior.calibration_kind(path)
    with pytest.raises(InputError, match="no such file"):
        posterior.calibration_kind(tmp_path / "missing.toml")


def test_calibration_needs_uncertainty(cli):
    code, out, err = cli("mesh", "--steps", "3", "--no-step-check", "--calibration", "x.toml")
    assert code != 0 and "--calibration need --uncertainty" in out + err


@pytest.mark.slow
def test_mesh_uncertainty_with_a_calibration_prints_prior_and_posterior(cli, tmp_path):
    path = tmp_path / "ours.toml"
    path.write_text(ROW.format(value=0.3, sd=0.05), encoding="utf-8")
    out = cli.json("mesh", "--steps", "3", "--no-step-check", "--uncertainty", "4", "--sobol-samples", "2",
                   "--calibration", str(path))
    assert 0.0 <= out["posterior_stiction_probability"] <= 1.0
    low, high = out["posterior_stiction_probability_ci"]
    assert low <= out["posterior_stiction_probability"] <= high
    assert 1.0 <= out["posterior_effective_samples"] <= out["uncertainty_samples"]
    assert out["posterior_moved_by"][0]["id"] == "own_sidewall"
    assert math.isfinite(out["stiction_probability"])
