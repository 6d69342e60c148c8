"""Sensitivity of the decision and priors that admit what they are (MODEL 7h, issue 38 items 2 and 4): the regional
index of the verdict, the robust-Bayes band against its closed form, Sobol' indices inside [0, 1], bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.uncertainty.decision import (clip_unit, ks_distance, measurable, moved_priors, regional_sensitivity,
                                            robust_bayes_band)
from memstribo.uncertainty.priors import Prior


@pytest.fixture
def params():
    """The default set under the thesis's vdW rule: U_vdW is sampled and rescaled there. Under the default rule
    (MODEL 7h, issue 38) U_vdW follows from phi w12 / n_site and phi is sampled instead (tests/test_vdw_energy.py)."""
    from memstribo.parameters import get_parameter_values

    return get_parameter_values().updated({"vdw_energy_rule": "thesis"})


# --- the regional index of the verdict --------------------------------------------------------------------------
def test_ks_distance_closed_forms():
    assert ks_distance([1, 2, 3], [4, 5]) == 1.0  # disjoint: the CDFs part completely
    assert ks_distance([1, 2, 3], [3, 2, 1]) == 0.0
    # {0, 1} against {1, 2}: at 0 the first CDF is 1/2, the second 0; at 1: 1 against 1/2
    assert ks_distance([0, 1], [1, 2]) == pytest.approx(0.5)
    assert math.isnan(ks_distance([], [1.0]))


def test_the_decisive_factor_has_index_one_and_the_noise_near_zero():
    rng = np.random.default_rng(3)
    n = 400
    decisive, noise = rng.uniform(size=n), rng.uniform(size=n)
    stuck = decisive > 0.6  # the verdict hangs on one factor alone
    out = regional_sensitivity({"decisive": decisive, "noise": noise}, stuck, resamples=200, seed=1)
    assert out["decisive"]["index"] == 1.0
    assert out["decisive"]["index_ci"][0] > 0.95
    assert out["noise"]["index"] < 0.15
    assert out["noise"]["index"] < out["decisive"]["noise_level"] < 0.2  # what noise reaches with 400 samples
    assert out["decisive"]["index"] > out["decisive"]["noise_level"]
    for entry in out.values():
        assert 0.0 <= entry["index_ci"][0] <= entry["index_ci"][1] <= 1.0


def test_a_blurred_threshold_and_blocks_of_shared_rows():
    rng = np.random.default_rng(5)
    base = rng.uniform(size=(60, 2))
    # blocks of 3 rows that share the first factor's value (as a Saltelli block shares its A row's columns)
    x = np.repeat(base[:, 0], 3)
    z = rng.uniform(size=x.size)
    stuck = x + 0.1 * rng.standard_normal(x.size) > 0.5
    blocks = np.repeat(np.arange(60), 3)
    out = regional_sensitivity({"x": x, "z": z}, stuck, blocks=blocks, resamples=200, seed=0)
    assert 0.6 < out["x"]["index"] < 1.0
    assert out["x"]["index"] > out["x"]["noise_level"] > out["z"]["index"] * 0.5
    assert out["z"]["index"] < out["z"]["noise_level"]
    # one outcome everywhere: nothing to split
    assert regional_sensitivity({"x": x}, np.zeros(x.size, bool))["x"]["index"] is None


# --- the robust-Bayes band ----------------------------------------------------------------------------------------
def _probability_over(critical, n=20000):
    """P(x > critical) under a prior, by a midpoint rule over its quantiles (margin = critical - x: stiction above)."""
    u = (np.arange(n) + 0.5) / n

    def under(prior):
        p = float(np.mean(prior.ppf(u) > critical))
        return {"probability": p, "ci": [max(0.0, p - 0.01), min(1.0, p + 0.01)]}
    return under


def test_robust_bayes_band_of_a_log_uniform_prior_is_its_closed_form():
    a, b, c = 3.6e-21, 3.7e-20, 8.87e-21  # the U_vdW prior and the critical value
    prior = Prior("vdw_bond_energy", "loguniform", a, b)
    band = robust_bayes_band(_probability_over(c), prior)
    rows = {r["label"]: r for r in band["priors"]}
    closed = {"prior": math.log(b / c) / math.log(b / a),  # 0.61: the "P is the prior"
              "shifted down": math.log(b / 2 / c) / math.log(b / a),
              "shifted up": math.log(2 * b / c) / math.log(b / a),
              "widened": math.log(2 * b / c) / math.log(4 * b / a),
              "narrowed": math.log(b / 2 / c) / math.log(b / (4 * a))}
    assert set(rows) == set(closed)
    for label, p in closed.items():
        assert rows[label]["probability"] == pytest.approx(p, abs=1e-3), label
    assert rows["prior"]["probability"] == pytest.approx(0.61, abs=0.01)
    assert rows["shifted down"]["low"] == pytest.approx(a / 2) and rows["shifted up"]["high"] == pytest.approx(2 * b)
    # monotone verdict: the extremes are the shifted priors
    assert band["band"] == pytest.approx([closed["shifted down"], closed["shifted up"]], abs=1e-3)
    assert band["span"] == pytest.approx(closed["shifted up"] - closed["shifted down"], abs=2e-3)
    assert band["prior_dominated"] is True  # 0.32 to 0.91
    assert band["band_ci"][0] <= band["band"][0] and band["band_ci"][1] >= band["band"][1]


def test_a_band_that_stays_narrow_is_not_prior_dominated():
    prior = Prior("x", "uniform", 1.0, 3.0)
    band = robust_bayes_band(_probability_over(10.0), prior)  # never stiction, whatever the prior
    assert band["span"] == 0.0 and band["prior_dominated"] is False


def test_moved_priors_of_uniform_and_normal_priors():
    uniform = {m["label"]: m["prior"] for m in moved_priors(Prior("x", "uniform", 1.0, 3.0))}
    # each bound's distance from the centre (2) doubled or halved
    assert (uniform["shifted down"].low, uniform["shifted down"].high) == pytest.approx((0.0, 2.5))
    assert (uniform["shifted up"].low, uniform["shifted up"].high) == pytest.approx((1.5, 4.0))
    assert (uniform["widened"].low, uniform["widened"].high) == pytest.approx((0.0, 4.0))
    assert (uniform["narrowed"].low, uniform["narrowed"].high) == pytest.approx((1.5, 2.5))
    normal = {m["label"]: m["prior"] for m in moved_priors(Prior("y", "normal", 1.0, 3.0, mean=2.0, sd=0.5))}
    assert normal["widened"].sd == pytest.approx(1.0) and normal["narrowed"].sd == pytest.approx(0.25)
    assert normal["shifted up"].mean == 2.0 and normal["shifted up"].sd == pytest.approx(0.5)
    # a log-uniform prior whose bounds are within a factor 4: no narrowed prior
    assert "narrowed" not in {m["label"] for m in moved_priors(Prior("z", "loguniform", 1.0, 3.0))}
    # a moved bound stays inside the parameter's physical range (a strain above 0)
    widened = [m for m in moved_priors(Prior("threshold_strain", "uniform", 0.1, 0.5)) if m["label"] == "widened"][0]
    assert widened["clipped"] and 0.0 < widened["prior"].low < 1e-6 and widened["prior"].high == pytest.approx(0.7)


def test_critical_values_in_measurable_units(params):
    tau, hysteresis = measurable("vdw_bond_energy", 5.43e-21, params)
    d = params["bond_length"]
    assert tau["unit"] == "MPa" and tau["value"] == pytest.approx(5.43e-21 / d ** 3 / 1e6)
    assert tau["value"] == pytest.approx(418, rel=0.01)  # the thesis's U_chem / 100 as a shear strength
    assert hysteresis["unit"] == "mJ/m^2" and hysteresis["value"] == pytest.approx(5.43e-21 / d ** 2 * 1e3)
    (w,) = measurable("hamaker_constant", 1.1e-18, params.updated({"cutoff_distance": 2.56e-10}))
    assert w["unit"] == "mJ/m^2" and w["value"] == pytest.approx(445, rel=0.01)  # w12 of the thesis (3-34)
    (width,) = measurable("adhesive_width", 1.955e-7, params)
    assert width["unit"] == "nm" and width["value"] == pytest.approx(195.5)


# --- Sobol' indices inside [0, 1] --------------------------------------------------------------------------------
def test_clip_unit():
    assert clip_unit(1.45) == 1.0 and clip_unit(-0.2) == 0.0 and clip_unit(0.3) == 0.3
    assert clip_unit([-0.1, 1.17]) == [0.0, 1.0]
    assert clip_unit(None) is None and math.isnan(clip_unit(float("nan")))


def test_sobol_indices_and_intervals_stay_inside_zero_one():
    from memstribo.uncertainty.study import _saltelli_design, sobol_indices

    design = _saltelli_design(4, 4, seed=2)  # 4 base samples: the estimators stray outside [0, 1]
    rng = np.random.default_rng(0)
    y = np.exp(3 * design[:, 0]) + rng.standard_normal(design.shape[0])
    out = sobol_indices(["a", "b", "c", "d"], {"y": y}, 4)["y"]
    clipped = 0
    for entry in out.values():
        for key in ("first", "total"):
            assert 0.0 <= entry[key] <= 1.0
            assert 0.0 <= entry[f"{key}_ci"][0] <= entry[f"{key}_ci"][1] <= 1.0
        clipped += entry["clipped"]
    assert clipped > 0  # the raw estimates were outside, and the output says so


# --- bad input ----------------------------------------------------------------------------------------------------
def test_bad_decision_input(params):
    from memstribo.uncertainty.study import uncertainty_study

    with pytest.raises(InputError, match="low must be below"):
        Prior("x", "uniform", 3.0, 1.0)  # bounds in the wrong order
    with pytest.raises(InputError, match="factor above 1"):
        moved_priors(Prior("x", "uniform", 1.0, 3.0), factor=1.0)
    with pytest.raises(InputError, match=r"\(0, 1\]"):
        robust_bayes_band(_probability_over(2.0), Prior("x", "uniform", 1.0, 3.0), span=1.5)
    with pytest.raises(InputError, match="confidence"):
        regional_sensitivity({"x": [1.0, 2.0]}, [True, False], confidence=1.0)
    for kwargs, message in (({"confidence": 1.5}, "confidence"), ({"threshold": -0.1}, "threshold"),
                            ({"decision": {"band_factor": 0.5}}, "band_factor"),
                            ({"decision": {"span": 0.0}}, r"\(0, 1\]"), ({"decision": {"span": 1.2}}, r"\(0, 1\]"),
                            ({"decision": {"band_samples": 0}}, "band_samples"),
                            ({"decision": {"factor": 2}}, "unknown option")):
        with pytest.raises(InputError, match=message):
            uncertainty_study(params, samples=2, realisations=1, steps=5, **kwargs)


# --- one small study, end to end ----------------------------------------------------------------------------------
def test_a_small_study_reports_the_decisions_sensitivity(params):
    """Only U_vdW sampled (rescaled: two contact solves in all): the index, the end points, the band."""
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.study import uncertainty_study

    fixed = [name for name in priors_for(params) if name != "vdw_bond_energy"]
    result = uncertainty_study(params, samples=8, realisations=2, steps=11, sobol_samples=2, fixed=fixed,
                               curve_points=2)
    assert result["sobol_design"]["base_samples"] == 2
    for entry in result["sensitivity"].values():
        for key in ("first", "total", "cof_first", "cof_total"):
            assert 0.0 <= entry[key] <= 1.0 and 0.0 <= entry[f"{key}_ci"][0] <= entry[f"{key}_ci"][1] <= 1.0
        assert isinstance(entry["clipped"], bool)
    decision = result["decision_sensitivity"]
    assert set(decision) == {"vdw_bond_energy", "roughness_realisation"}
    entry = decision["vdw_bond_energy"]
    assert entry["realisations"] == 2 and "stiction_at_low" in entry and "margin_at_high" in entry
    # the margin falls as U_vdW rises (the friction is linear in it)
    assert entry["margin_at_high"] < entry["nominal_margin"] < entry["margin_at_low"]
    assert entry["can_flip"] == ((entry["margin_at_high"] < 0) != (entry["nominal_margin"] < 0)
                                 or (entry["margin_at_low"] < 0) != (entry["nominal_margin"] < 0))
    assert result["flipping_constants"] == (["vdw_bond_energy"] if entry["can_flip"] else [])
    assert result["decision_design"]["samples"] == 8 + 2 * 4  # the study's and the Sobol' rows
    if entry["index"] is not None:
        assert 0.0 <= entry["index_ci"][0] <= entry["index_ci"][1] <= 1.0
    band = result["robust_bayes"]["vdw_bond_energy"]
    assert band["priors"][0]["label"] == "prior"
    assert band["priors"][0]["probability"] == result["stiction_probability"]  # the study's own samples
    assert band["samples"] == 8 and len(band["priors"]) == 5
    assert band["band"][0] <= result["stiction_probability"] <= band["band"][1]
    assert result["prior_dominated"] == band["prior_dominated"]
    assert result["decision_sentence"]


def test_the_regional_depth_solves_nothing_beyond_the_studys_samples(params):
    """depth "regional" (the main job's, issue 40): the regional index on the samples, no end point, no band; the
    flips are None (not checked), never an empty list (which would say "none flips")."""
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.study import uncertainty_study

    fixed = [name for name in priors_for(params) if name not in ("vdw_bond_energy", "adhesive_height")]
    kwargs = dict(samples=4, realisations=2, steps=11, sobol_samples=2, fixed=fixed, curve_points=2)
    full = uncertainty_study(params, **kwargs)
    regional = uncertainty_study(params, decision={"depth": "regional"}, critical="rescaled", **kwargs)
    assert full["decision_depth"] == "full" and regional["decision_depth"] == "regional"
    assert regional["flipping_constants"] is None and regional["robust_bayes"] is None
    assert regional["prior_dominated"] is None
    assert "memstribo mesh --uncertainty" in regional["decision_sentence"]
    assert regional["solves"] < full["solves"]
    for name in ("vdw_bond_energy", "adhesive_height", "roughness_realisation"):  # the same index on the same rows
        assert regional["decision_sensitivity"][name]["index"] == full["decision_sensitivity"][name]["index"]
        assert "margin_at_low" not in regional["decision_sensitivity"][name]
    assert regional["stiction_probability"] == full["stiction_probability"]
    # critical values: the rescaled bond energy's is searched, the solved constant's is not (and says so)
    assert regional["sensitivity"]["adhesive_height"]["critical_value"] is None
    if regional["sensitivity"]["adhesive_height"]["total"] > 0.1:
        assert "not searched here" in regional["sensitivity"]["adhesive_height"]["note"]
    assert (regional["sensitivity"]["vdw_bond_energy"]["critical_value"]
            == full["sensitivity"]["vdw_bond_energy"]["critical_value"])
    with pytest.raises(InputError, match="depth"):
        uncertainty_study(params, decision={"depth": "deep"}, **kwargs)
    with pytest.raises(InputError, match="critical"):
        uncertainty_study(params, critical="some", **kwargs)


def test_nominal_cycles_solved_already_are_reused_bit_for_bit(params):
    """The run's mesh ensemble hands its reduced cycles to the uncertainty stage: no solve of them again, the same
    result as solving them."""
    from memstribo.simulations.mesh import simulate_mesh
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.rescale import reduce_cycle
    from memstribo.uncertainty.study import uncertainty_study

    fixed = [name for name in priors_for(params) if name != "vdw_bond_energy"]
    kwargs = dict(samples=4, realisations=2, steps=11, fixed=fixed, sensitivity=False)
    plain = uncertainty_study(params, **kwargs)
    cycles = {r: reduce_cycle(simulate_mesh(params, steps=11, realisation=r)) for r in range(2)}
    reused = uncertainty_study(params, nominal_cycles=cycles, **kwargs)
    assert reused["nominal_cycles_reused"] == 2 and plain["nominal_cycles_reused"] == 0
    assert reused["solves"] == plain["solves"] - 2
    for key in ("stiction_probability", "margin_quantiles", "margin_quantiles_nominal", "cof_quantiles"):
        assert reused[key] == plain[key]


def test_a_regional_study_ranks_by_the_verdict_and_draws_its_figure(params, tmp_path):
    """sensitivity="regional" (the main job's, issue 40): no Sobol' design; the dominant constant is the first whose
    regional index is above its noise level, or, where every sample gives the same verdict, the one most correlated
    with the margin; the figure shows whichever ranked them."""
    from memstribo.uncertainty.figures import plot_sensitivity
    from memstribo.uncertainty.priors import priors_for
    from memstribo.uncertainty.study import uncertainty_study

    fixed = [name for name in priors_for(params) if name not in ("vdw_bond_energy", "adhesive_height")]
    result = uncertainty_study(params, samples=8, realisations=2, steps=11, fixed=fixed, sensitivity="regional",
                               critical="rescaled", curve_points=2)
    assert result["sensitivity_method"] == "regional" and "sobol_design" not in result
    assert result["sensitivity"] == {} and result["decision_depth"] == "regional"
    correlation = result["margin_correlation"]
    assert set(correlation) == {"vdw_bond_energy", "adhesive_height", "roughness_realisation"}
    assert all(-1 <= c["rho"] <= 1 and 0 <= c["p_value"] <= 1 for c in correlation.values())
    assert correlation["vdw_bond_energy"]["rho"] < 0  # more vdW energy, more friction, less margin
    regional = result["decision_sensitivity"]
    above = [n for n, e in regional.items() if n != "roughness_realisation" and e["index"] is not None
             and e["index"] > e["noise_level"]]
    significant = sorted((n for n in ("vdw_bond_energy", "adhesive_height") if correlation[n]["p_value"] < 0.05),
                         key=lambda n: -abs(correlation[n]["rho"]))
    expected = above[0] if above else (significant[0] if significant else None)
    assert result["dominant"] == expected
    if expected == "vdw_bond_energy":  # rescaled: its critical value is searched, at no new cycle
        assert result["dominant_entry"]["searched"] is True and result["critical_curve"]["name"] == expected
    written = plot_sensitivity(result, tmp_path)
    assert {p.suffix for p in written} == {".png", ".svg"}
    with pytest.raises(InputError, match="sensitivity"):
        uncertainty_study(params, samples=8, realisations=2, steps=11, fixed=fixed, sensitivity="sobol")


def test_the_regional_sentence_says_a_unanimous_verdict_and_noise_apart():
    from memstribo.uncertainty.decision import _regional_words

    none = {"a": {"index": None, "noise_level": None}, "b": {"index": None, "noise_level": None}}
    assert _regional_words(none, []).startswith("Every sample gives the same verdict")
    noisy = {"a": {"index": 0.2, "noise_level": 0.3}}
    assert _regional_words(noisy, []).startswith("No factor separates")
    assert _regional_words({"a": {"index": 0.9, "noise_level": 0.3}}, ["a"]).endswith("most in a (regional "
                                                                                     "sensitivity)")
