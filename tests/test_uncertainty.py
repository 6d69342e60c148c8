"""What the verdict hangs on (MODEL 7d, issue 27): priors, intervals, designs, the rescaling, Sobol' indices,
critical values and the command line."""

from __future__ import annotations

import math

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.uncertainty.intervals import binomial_interval, ensemble_interval, format_probability
from memstribo.uncertainty.priors import Prior, check_priors, priors_for
from memstribo.uncertainty.sampling import sample_constants


@pytest.fixture
def params():
    """The default set under the thesis's vdW rule: U_vdW is sampled and rescaled there. Under the default rule
    (MODEL 7h, issue 38) U_vdW follows from phi w12 / n_site and phi is sampled instead (tests/test_vdw_energy.py)."""
    from memstribo.parameters import get_parameter_values

    return get_parameter_values().updated({"vdw_energy_rule": "thesis"})


Z95 = 1.959963984540054  # the 97.5 % quantile of the standard normal


# --- intervals ---------------------------------------------------------------------------------------------
def test_wilson_interval_of_zero_events_is_its_closed_form():
    # Wilson (1927) with k = 0: [0, z^2 / (n + z^2)]
    for n in (4, 16, 64, 256):
        low, high = binomial_interval(0, n)
        assert low == 0.0
        assert high == pytest.approx(Z95 ** 2 / (n + Z95 ** 2), rel=1e-9)
    assert binomial_interval(0, 16)[1] == pytest.approx(0.19, abs=0.005)  # the "upper bound near 0.19"


def test_wilson_interval_of_k_events_is_its_closed_form():
    k, n = 7, 40
    p = k / n
    centre = (p + Z95 ** 2 / (2 * n)) / (1 + Z95 ** 2 / n)
    half = Z95 / (1 + Z95 ** 2 / n) * math.sqrt(p * (1 - p) / n + Z95 ** 2 / (4 * n ** 2))
    assert binomial_interval(k, n) == pytest.approx((centre - half, centre + half), rel=1e-9)


def test_clopper_pearson_interval_of_zero_events_is_its_closed_form():
    # the exact interval with k = 0: upper = 1 - (alpha/2)^(1/n)
    assert binomial_interval(0, 16, method="clopper-pearson")[1] == pytest.approx(1 - 0.025 ** (1 / 16), rel=1e-9)
    assert binomial_interval(16, 16, method="clopper-pearson")[0] == pytest.approx(0.025 ** (1 / 16), rel=1e-9)


def test_the_interval_narrows_as_one_over_root_n():
    widths = [np.subtract(*binomial_interval(n // 2, n)[::-1]) for n in (100, 400)]
    assert widths[0] / widths[1] == pytest.approx(2.0, rel=0.02)


def test_probability_text_and_ensemble_interval():
    assert format_probability(0, 16) == "0 of 16 (95 % CI 0–19 %)"
    summary = {"realisations": 16, "stiction_probability": 1 / 16,
               "per_realisation": [{"stiction": i == 3} for i in range(16)]}
    out = ensemble_interval(summary)
    assert out["stiction_count"] == 1
    assert out["stiction_probability_ci"] == pytest.approx(list(binomial_interval(1, 16)))
    assert out["stiction_probability_text"].startswith("1 of 16 (95 % CI ")
    assert "stiction_count" not in summary  # a copy


@pytest.mark.parametrize("k, n, confidence", [(-1, 10, 0.95), (11, 10, 0.95), (0, 0, 0.95), (1, 10, 1.0),
                                              (0.5, 10, 0.95)])
def test_bad_interval_input(k, n, confidence):
    with pytest.raises(InputError):
        binomial_interval(k, n, confidence)


# --- priors --------------------------------------------------------------------------------------------------
def test_wilson_interval_of_a_whole_count_is_the_binomial_one():
    from memstribo.uncertainty.intervals import wilson_interval

    for k, n in ((0, 16), (3, 16), (151, 256), (16, 16)):
        assert wilson_interval(k / n, n) == pytest.approx(binomial_interval(k, n), abs=1e-12)


def test_clustered_interval_counts_correlated_samples_honestly():
    from memstribo.uncertainty.intervals import clustered_interval, wilson_interval

    # every sample its own cluster: the binomial interval, design effect 1
    flags = [True] * 5 + [False] * 11
    alone = clustered_interval(flags, list(range(16)))
    assert alone["design_effect"] == 1.0 and alone["ci"] == pytest.approx(binomial_interval(5, 16))
    # clusters of 4 whose samples always agree: 12 clusters worth n_c - 1 = 11 samples. The cluster-robust
    # variance n_c/(n_c - 1) sum (y_i - p m)^2 / n^2 is then p (1 - p)/(n_c - 1): design effect n / (n_c - 1)
    clusters = [i // 4 for i in range(48)]
    agree = [c < 5 for c in clusters]
    out = clustered_interval(agree, clusters)
    assert out["design_effect"] == pytest.approx(48 / 11)
    assert out["ci"] == pytest.approx(wilson_interval(5 / 12, 11))
    assert out["ci"][1] - out["ci"][0] > np.subtract(*binomial_interval(20, 48)[::-1])
    # every sample agrees (p = 0): no variance to estimate, the worst case (one sample per cluster)
    none = clustered_interval([False] * 48, clusters)
    assert none["design_effect"] == 48 / 12 and none["ci"] == pytest.approx(wilson_interval(0.0, 12))
    # independent samples in clusters: design effect near 1 (never below)
    rng = np.random.default_rng(3)
    independent = clustered_interval(list(rng.random(4000) < 0.3), [i // 8 for i in range(4000)])
    assert 1.0 <= independent["design_effect"] < 1.3
    with pytest.raises(InputError):
        clustered_interval([True, False], [0])


def test_ppf_properties():
    u = np.linspace(0.0, 1.0, 11)
    for prior in (Prior("x", "uniform", 2.0, 6.0), Prior("x", "loguniform", 1e-21, 1e-19),
                  Prior("x", "normal", 1.0, 5.0, mean=2.0, sd=1.0)):
        values = prior.ppf(u)
        assert values[0] == pytest.approx(prior.low) and values[-1] == pytest.approx(prior.high)
        assert np.all(np.diff(values) > 0)
        assert prior.cdf(values) == pytest.approx(u, abs=1e-9)
    assert Prior("x", "loguniform", 1e-21, 1e-19).ppf(0.5) == pytest.approx(1e-20, rel=1e-12)  # geometric mean
    assert Prior("x", "normal", 0.0, 4.0, mean=2.0, sd=1.0).ppf(0.5) == pytest.approx(2.0)  # symmetric truncation


@pytest.mark.parametrize("kwargs", [
    dict(distribution="uniform", low=2.0, high=1.0),                     # inverted
    dict(distribution="uniform", low=1.0, high=1.0),                     # empty
    dict(distribution="loguniform", low=0.0, high=1.0),                  # log of 0
    dict(distribution="normal", low=0.0, high=1.0),                      # no mean/sd
    dict(distribution="normal", low=0.0, high=1.0, mean=2.0, sd=0.1),    # mean outside
    dict(distribution="beta", low=0.0, high=1.0),                        # unknown
    dict(distribution="uniform", low=float("nan"), high=1.0),
])
def test_bad_prior(kwargs):
    with pytest.raises(InputError):
        Prior("poisson_ratio", **kwargs)


def test_priors_outside_physical_bounds_or_named_twice_are_refused(params):
    with pytest.raises(InputError, match="physical bounds"):
        check_priors([Prior("poisson_ratio", "uniform", 0.2, 0.7)])
    with pytest.raises(InputError, match="named twice"):
        check_priors([Prior("poisson_ratio", "uniform", 0.2, 0.3), Prior("poisson_ratio", "uniform", 0.2, 0.4)])
    with pytest.raises(InputError, match="outside its prior"):
        check_priors([Prior("poisson_ratio", "uniform", 0.3, 0.4)], {"poisson_ratio": 0.23})
    with pytest.raises(InputError, match="not a number parameter"):
        check_priors([Prior("load_case", "uniform", 0.3, 0.4)])


def test_every_shipped_prior_holds_its_nominal_value():
    from memstribo.parameters import available_parameter_sets, get_parameter_values
    from memstribo.physics.coating import available_coatings

    for name in available_parameter_sets():
        for coating in [None, *available_coatings()]:
            priors = priors_for(get_parameter_values(name), coating)  # checks bounds and nominal values
            assert priors
            for prior in priors.values():
                assert prior.source and prior.reason


def test_vdw_prior_spans_the_thesis_and_the_w12_values(params):
    prior = priors_for(params)["vdw_bond_energy"]
    assert prior.distribution == "loguniform"
    w12 = params["hamaker_constant"] / (12 * math.pi * params["cutoff_distance"] ** 2)  # (3-34)
    for value in (params["bond_energy"] / 100, w12 * params["bond_length"] ** 2):
        assert prior.low <= value <= prior.high


def test_a_value_the_user_gives_is_fixed(params):
    assert "vdw_bond_energy" in priors_for(params)
    fixed = params.updated({"vdw_bond_energy": "1e-20 J"}, origin="--set")
    assert "vdw_bond_energy" not in priors_for(fixed)
    assert "bond_energy" in priors_for(fixed)


# --- designs -------------------------------------------------------------------------------------------------
def test_sampling_is_reproducible_and_extends(params):
    priors = priors_for(params)
    a = sample_constants(priors, 16, seed=3)
    assert a == sample_constants(priors, 16, seed=3)
    assert a != sample_constants(priors, 16, seed=4)
    assert sample_constants(priors, 32, seed=3)[:16] == a  # a doubled Sobol' design extends the smaller one
    for point in a:
        for name, value in point.items():
            assert priors[name].low <= value <= priors[name].high
    # low discrepancy: every stratum of 1/16 of each prior's probability holds one point
    for name in priors:
        strata = np.floor(16 * np.array([priors[name].cdf(p[name]) for p in a])).astype(int)
        assert sorted(np.minimum(strata, 15)) == list(range(16))
    assert len(sample_constants(priors, 10, seed=3)) == 10  # not a power of two: a Latin hypercube


def test_a_fixed_constant_is_not_sampled(params):
    priors = priors_for(params)
    points = sample_constants(priors, 4, fixed=("vdw_bond_energy",))
    assert all("vdw_bond_energy" not in p for p in points)
    with pytest.raises(InputError, match="no prior"):
        sample_constants(priors, 4, fixed=("normal_load",))
    with pytest.raises(InputError, match="named twice"):
        sample_constants(priors, 4, fixed=("bond_energy", "bond_energy"))
    with pytest.raises(InputError):
        sample_constants(priors, 0)


# --- the rescaling -----------------------------------------------------------------------------------------------
def test_rescaled_bond_energies_equal_a_full_rerun(params):
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.uncertainty.rescale import reduce_cycle, rescale_cycle

    steps = 41
    nominal = reduce_cycle(simulate_mesh(params, steps=steps))
    new = {"vdw_bond_energy": 1.086e-20, "bond_energy": 4.0e-19}
    full = summarize(simulate_mesh(params.updated(new), steps=steps))
    fast = rescale_cycle(nominal, params, new)
    # the same arithmetic in another order: equal to round-off (1e-9 relative is 10^6 ulps)
    for key in ("stiction_margin", "resisting_force_max", "cof_mean", "cof_chemical", "cof_vdw", "mesh_efficiency",
                "friction_force_mean", "energy_dissipated"):
        assert fast[key] == pytest.approx(full[key], rel=1e-9), key
    assert fast["stiction"] == full["stiction"]
    # and it changed something: the doubled U_vdW is not the nominal cycle
    assert fast["cof_vdw"] == pytest.approx(summarize(nominal)["cof_vdw"] * 1.086e-20 / params["vdw_bond_energy"],
                                            rel=1e-9)
    with pytest.raises(InputError, match="cannot be changed"):
        rescale_cycle(nominal, params, {"youngs_modulus": 150e9})


def test_many_sets_of_one_cycle_rescale_as_full_reruns(params):
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.uncertainty.rescale import reduce_cycle, rescale_cycles

    steps = 21
    cycle = reduce_cycle(simulate_mesh(params, steps=steps))
    sets = [{"vdw_bond_energy": 1.086e-20}, {"vdw_bond_energy": 2.0e-20, "bond_energy": 4.0e-19}]
    together = rescale_cycles(cycle, params, sets)
    for overrides, fast in zip(sets, together):
        full = summarize(simulate_mesh(params.updated(overrides), steps=steps))
        for key in ("stiction_margin", "resisting_force_max", "cof_mean", "cof_vdw", "cof_chemical", "mesh_efficiency",
                    "friction_force_mean"):
            assert fast[key] == pytest.approx(full[key], rel=1e-9), key
    # the summary of the cycle given by the caller is the one it would compute
    assert rescale_cycles(cycle, params, sets, base=summarize(cycle)) == together
    with pytest.raises(InputError, match="cannot be changed"):
        rescale_cycles(cycle, params, [{"vdw_bond_energy": 1e-20}, {"youngs_modulus": 150e9}])


def test_a_coated_cycle_rescales_both_vdw_energies(params):
    from memstribo.physics.coating import get_coating
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.uncertainty.rescale import reduce_cycle, rescalable, rescale_cycle

    steps, wear = 21, 0.5

    def cycle(p):
        return simulate_mesh(p, steps=steps, coating=get_coating("OTS", p), wear=wear)

    nominal = reduce_cycle(cycle(params))
    bare, coated = np.asarray(nominal["bonds_vdw_bare"]), np.asarray(nominal["bonds_vdw_coated"])
    assert bare.sum() > 0 and coated.sum() > 0  # half the gear blocks worn: both kinds of block bond
    assert bare + coated == pytest.approx(np.asarray(nominal["bonds_vdw"]), rel=1e-12)
    assert "coating_vdw_bond_energy" in rescalable(nominal) and "vdw_bond_energy" in rescalable(nominal)
    new = {"vdw_bond_energy": 1.086e-20, "coating_vdw_bond_energy": 1.2e-21}
    fast = rescale_cycle(nominal, params, new)
    full = summarize(cycle(params.updated(new)))
    for key in ("stiction_margin", "cof_mean", "cof_vdw", "friction_force_mean"):
        assert fast[key] == pytest.approx(full[key], rel=1e-9), key
    assert fast["cof_vdw"] != pytest.approx(summarize(nominal)["cof_vdw"], rel=1e-3)


# --- sensitivity and critical values ------------------------------------------------------------------------------
def test_sobol_indices_of_the_ishigami_function():
    from memstribo.uncertainty.study import _saltelli_design, sobol_indices

    a, b = 7.0, 0.1
    design = _saltelli_design(3, 1024, seed=1)
    x = -math.pi + 2 * math.pi * design
    y = np.sin(x[:, 0]) + a * np.sin(x[:, 1]) ** 2 + b * x[:, 2] ** 4 * np.sin(x[:, 0])
    # analytic variances (Ishigami and Homma 1990; Saltelli et al. 2008)
    v1 = 0.5 * (1 + b * math.pi ** 4 / 5) ** 2
    v2 = a ** 2 / 8
    v13 = b ** 2 * math.pi ** 8 * (1 / 18 - 1 / 50)
    v = v1 + v2 + v13
    out = sobol_indices(["x1", "x2", "x3"], {"y": y}, 1024, seed=1)["y"]
    assert out["x1"]["first"] == pytest.approx(v1 / v, abs=0.05)
    assert out["x2"]["first"] == pytest.approx(v2 / v, abs=0.05)
    assert out["x3"]["first"] == pytest.approx(0.0, abs=0.05)
    assert out["x1"]["total"] == pytest.approx((v1 + v13) / v, abs=0.05)
    assert out["x3"]["total"] == pytest.approx(v13 / v, abs=0.05)
    ranking = sorted(out, key=lambda n: -out[n]["total"])
    assert ranking == ["x1", "x2", "x3"]
    lo, hi = out["x2"]["total_ci"]
    assert lo < out["x2"]["total"] < hi


def test_critical_value_of_a_synthetic_margin():
    from memstribo.uncertainty.study import critical_value

    found = critical_value(lambda x: 3e-3 - 1e-3 * x, Prior("x", "uniform", 0.0, 10.0))
    assert found["critical_value"] == pytest.approx(3.0, rel=1e-3)
    assert found["stiction_above"] is True
    found = critical_value(lambda u: 1e-3 * (math.log(u) - math.log(2e-20)), Prior("u", "loguniform", 1e-21, 1e-19))
    assert found["critical_value"] == pytest.approx(2e-20, rel=1e-3)
    assert found["stiction_above"] is False
    found = critical_value(lambda x: 1.0 + x, Prior("x", "uniform", 0.0, 10.0))
    assert found["critical_value"] is None and "no crossing within the prior" in found["note"]


def test_uncertainty_study_small(params):
    from memstribo.uncertainty.study import REALISATION_FACTOR, uncertainty_study

    from memstribo.uncertainty.priors import priors_for

    # a rescaled, a contact and a block constant sampled, the rest fixed: the study's parts at a fraction of the cost
    fixed = [n for n in priors_for(params) if n not in ("bond_energy", "hamaker_constant", "atomic_width")]
    result = uncertainty_study(params, samples=8, realisations=2, steps=11, sobol_samples=2, fixed=fixed,
                               curve_points=3)
    assert result["samples"] == 8 and result["constant_sets"] == 4
    low, high = result["stiction_probability_ci"]
    assert low <= result["stiction_probability"] <= high
    assert (low, high) == pytest.approx(binomial_interval(result["stiction_count"], 8))
    assert "youngs_modulus" not in result["sampled_constants"]
    assert "youngs_modulus" not in result["sensitivity"]
    assert REALISATION_FACTOR in result["sensitivity"]
    q = result["margin_quantiles"]
    assert q["p05"] <= q["p50"] <= q["p95"]
    # the bond energies reuse the contact solutions: fewer solves than evaluated points
    assert result["solves"] < result["rescalings"] + result["solves"]
    for entry in result["sensitivity"].values():
        assert entry["total"] <= 0.1 or entry["critical_value"] is not None or entry["note"]


def test_the_study_interval_counts_samples_sharing_a_cycle_once_per_design_effect():
    from memstribo.uncertainty.intervals import clustered_interval
    from memstribo.uncertainty.study import _probability

    flags = [c < 3 for c in range(8) for _ in range(4)]  # 8 cycles of 4 samples that agree
    shared = [{"stiction": f, "cycle_id": i // 4} for i, f in enumerate(flags)]
    alone = [{"stiction": f, "cycle_id": i} for i, f in enumerate(flags)]
    p = _probability(shared, 0.95)
    assert p["count"] == 12 and p["ci"] == clustered_interval(flags, [i // 4 for i in range(32)])["ci"]
    assert p["design_effect"] > 1 and "design effect" in p["text"]
    assert _probability(alone, 0.95)["ci"] == pytest.approx(binomial_interval(12, 32))


def test_samples_that_share_a_solve_widen_the_interval(params):
    from memstribo.uncertainty.study import uncertainty_study

    grouped = uncertainty_study(params, samples=8, realisations=2, steps=11, sensitivity=False, solve_sets=1)
    assert grouped["solves"] == 2 + 2 and grouped["rescalings"] == 8
    k, n = grouped["stiction_count"], grouped["samples"]
    assert grouped["design_effect"] >= 1.0
    assert grouped["effective_samples"] == pytest.approx(n / grouped["design_effect"])
    low, high = grouped["stiction_probability_ci"]
    plain_low, plain_high = binomial_interval(k, n)
    assert low <= plain_low and high >= plain_high and low <= grouped["stiction_probability"] <= high
    with pytest.raises(InputError, match="solve_sets"):
        uncertainty_study(params, samples=8, realisations=2, steps=11, sensitivity=False, solve_sets=0)


def test_sobol_bootstrap_intervals_are_reproducible():
    from memstribo.uncertainty.study import _saltelli_design, sobol_indices

    design = _saltelli_design(3, 16, seed=0)
    y = design[:, 0] + 2 * design[:, 1] ** 2
    assert sobol_indices(["a", "b", "c"], {"y": y}, 16) == sobol_indices(["a", "b", "c"], {"y": y}, 16)


# --- the command line ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("argv, message", [
    (("--uncertainty", "0"), "at least 1"),
    (("--uncertainty", "many"), "number of samples or 'auto'"),
    (("--uncertainty", "4", "--fix", "normal_load"), "no prior"),
    (("--uncertainty", "4", "--fix", "bond_energy,bond_energy"), "named twice"),
    (("--uncertainty", "4", "--set", "bond_energy=4e-19", "--fix", "bond_energy"), "named twice"),
    (("--fix", "bond_energy"), "need --uncertainty"),
    (("--solve-sets", "2"), "need --uncertainty"),
    (("--regional",), "need --uncertainty"),
    (("--sobol",), "need --uncertainty"),
    (("--uncertainty", "4", "--regional", "--sobol-samples", "2"), "no Sobol' design"),
    (("--uncertainty", "4", "--regional", "--sobol"), "no Sobol' design"),
    (("--uncertainty", "4", "--solve-sets", "0"), "'pairs' or 'all', got '0'"),
    (("--uncertainty", "4", "--solve-sets", "some"), "'pairs' or 'all', got 'some'"),
    (("--uncertainty", "5000000"), "memory"),
])
def test_bad_uncertainty_input_exits_2(cli, argv, message):
    code, out, err = cli("mesh", "--steps", "3", "--no-step-check", *argv)
    assert code == 2
    assert message in err and "Traceback" not in err


def test_cli_runs_the_main_jobs_analysis_by_default(cli):
    """``mesh --uncertainty N`` (issue 40): the run's analysis (regional index, rescaled critical values, pairs of
    constant sets sharing a solve), in its JSON; the Sobol' design only with ``--sobol``."""
    out = cli.json("mesh", "--steps", "5", "--no-step-check", "--uncertainty", "8", "--realisations", "2",
                   "--fix", "youngs_modulus,poisson_ratio,threshold_strain,atomic_height,adhesive_height")
    assert out["sensitivity_method"] == "regional" and out["decision_depth"] == "regional"
    assert out["flipping_constants"] is None and "sobol_design" not in out
    assert set(out["margin_correlation"]) >= {"bond_energy", "roughness_realisation"}
    assert out["solve_sets"] == 2 and out["design_effect"] >= 1.0  # 4 sets a realisation: 2 solves


def test_cli_analysis_options():
    """``--sobol`` or ``--sobol-samples`` ask for the Sobol' design; otherwise the main job's; ``--solve-sets``."""
    import argparse

    from memstribo.cli.mesh import REGIONAL, _analysis, _solve_sets

    args = argparse.Namespace(sobol=False, sobol_samples=None, solve_sets=None, calibration=None)
    assert _analysis(args) == REGIONAL and _solve_sets(args) == "pairs"
    assert _analysis(argparse.Namespace(sobol=True, sobol_samples=None)) == {"sobol_samples": None}
    assert _analysis(argparse.Namespace(sobol=False, sobol_samples=4)) == {"sobol_samples": 4}
    assert _solve_sets(argparse.Namespace(solve_sets=None, calibration="lab.toml")) is None  # weights: no sharing
    assert _solve_sets(argparse.Namespace(solve_sets="all", calibration=None)) is None
    assert _solve_sets(argparse.Namespace(solve_sets="3", calibration=None)) == 3


def test_pairs_sharing_a_solve_give_the_same_probability_within_its_interval():
    """The default design of ``mesh --uncertainty`` and the run (issue 40 item 2): two constant sets share the solved
    constants; P(stiction) lies within the interval of every set solved apart and vice versa, at about half the
    solves, and the interval carries the design effect (the default set, 11-step cycles, where the verdict is
    split)."""
    from memstribo.parameters import get_parameter_values
    from memstribo.uncertainty.study import uncertainty_study

    params = get_parameter_values()  # the default vdW rule, as docs/uncertainty.md quotes

    kwargs = {"samples": 32, "realisations": 2, "steps": 11, "sensitivity": False}
    apart = uncertainty_study(params, **kwargs)
    pairs = uncertainty_study(params, solve_sets="pairs", **kwargs)
    assert 0.2 < apart["stiction_probability"] < 0.8  # a split verdict: the comparison can fail
    for one, other in ((apart, pairs), (pairs, apart)):
        low, high = one["stiction_probability_ci"]
        assert low <= other["stiction_probability"] <= high
    assert pairs["solves"] == 2 + 2 * 8 and apart["solves"] >= 2 + 2 * 16 - 2  # nominal + solves (few repeats)
    assert pairs["solve_sets"] == 8 and apart["solve_sets"] is None
    # the counts docs/uncertainty.md quotes ("Fewer solves, an honest interval")
    assert (apart["stiction_count"], pairs["stiction_count"]) == (14, 13)
    assert (apart["solves"], pairs["solves"]) == (34, 18)
    assert pairs["design_effect"] == pytest.approx(1.72, abs=0.005)
    assert pairs["design_effect"] >= 1.0 and apart["design_effect"] == 1.0


def test_pairs_keep_their_partner_when_the_sets_double(params):
    """``samples="auto"`` doubles the sets; the pairs of the smaller design stay pairs (their solves are reused)."""
    from memstribo.uncertainty.study import _design

    priors = priors_for(params)
    rescaled = ("bond_energy", "vdw_bond_energy", "vdw_dissipated_fraction")
    small, large = (_design(priors, 2, sets, "pairs", rescaled, seed=0) for sets in (4, 8))
    assert large[:len(small)] == small
    solved = [tuple(v for k, v in sorted(c.items()) if k not in rescaled) for _, c in large]
    assert all(solved[i] == solved[i + 2] for i in (0, 1, 4, 5, 8, 9, 12, 13))  # point j * 2 + r, pairs in j
    assert len(set(solved)) == len(large) // 2


def test_grouped_design_shares_the_solved_constants_only(params):
    from memstribo.uncertainty.study import _design

    priors = priors_for(params)
    points = _design(priors, 2, 8, 2, ("bond_energy", "vdw_bond_energy"), seed=0)
    assert len(points) == 16 and [r for r, _ in points].count(0) == 8
    for r in (0, 1):
        mine = [c for q, c in points if q == r]
        groups = [mine[:4], mine[4:]]
        for group in groups:
            assert len({c["adhesive_width"] for c in group}) == 1  # one contact solve per group
            assert len({c["vdw_bond_energy"] for c in group}) == 4  # the rescaled energies all differ
        assert groups[0][0]["adhesive_width"] != groups[1][0]["adhesive_width"]
    ungrouped = _design(priors, 2, 8, None, ("bond_energy", "vdw_bond_energy"), seed=0)
    assert len({c["adhesive_width"] for _, c in ungrouped}) == 16


# --- design maps ----------------------------------------------------------------------------------------------
def test_map_point_carries_the_interval(params):
    from memstribo.simulations.design_map import map_point, map_spec

    plain = map_point(params.updated({"realisations": 2}), steps=11)
    assert plain["uncertainty_samples"] == 0
    assert plain["stiction_probability_low"] <= plain["stiction_probability"] <= plain["stiction_probability_high"]
    assert (plain["stiction_probability_low"], plain["stiction_probability_high"]) == pytest.approx(
        binomial_interval(round(2 * plain["stiction_probability"]), 2))
    with_constants = map_point(params.updated({"realisations": 2}), steps=11, uncertainty=4)
    assert with_constants["uncertainty_samples"] == 4
    assert with_constants["stiction_probability_nominal"] == plain["stiction_probability"]
    low, high = with_constants["stiction_probability_low"], with_constants["stiction_probability_high"]
    assert low <= with_constants["stiction_probability"] <= high
    with pytest.raises(InputError, match="uncertainty"):
        map_spec({"realisations": 4, "uncertainty": 2, "grid": {"drive_torque": ["1e-7 N*m", "2e-7 N*m"]}})


def test_the_ensemble_output_has_its_interval(cli):
    out = cli.json("mesh", "--realisations", "2", "--steps", "5", "--no-step-check")
    k = sum(r["stiction"] for r in out["per_realisation"])
    assert out["stiction_count"] == k
    assert out["stiction_probability_ci"] == pytest.approx(list(binomial_interval(k, 2)))
    assert out["stiction_probability_text"] == format_probability(k, 2)


def test_the_dissipated_fraction_rescales_as_a_full_rerun():
    """U_vdW = phi w12 / n_site is linear in phi (MODEL 7h): a cycle with another phi is the nominal cycle rescaled,
    to round-off, with no new contact solve (the hysteresis rule's sampled constant costs no cycle)."""
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.uncertainty.rescale import reduce_cycle, rescale_cycles

    hysteresis = get_parameter_values("silicon_thesis")
    assert hysteresis["vdw_energy_rule"] == "hysteresis"
    steps = 21
    cycle = reduce_cycle(simulate_mesh(hysteresis, steps=steps))
    sets = [{"vdw_dissipated_fraction": 0.35}, {"vdw_dissipated_fraction": 0.8, "bond_energy": 4.0e-19}]
    for overrides, fast in zip(sets, rescale_cycles(cycle, hysteresis, sets)):
        full = summarize(simulate_mesh(hysteresis.updated(overrides), steps=steps))
        for key in ("stiction_margin", "startup_margin", "resisting_force_max", "cof_mean", "cof_vdw", "cof_chemical",
                    "mesh_efficiency", "friction_force_mean"):
            assert fast[key] == pytest.approx(full[key], rel=1e-9), key
    assert fast["cof_vdw"] != pytest.approx(summarize(cycle)["cof_vdw"], rel=1e-3)  # it changed something


def test_the_cli_starts_a_cluster_only_for_enough_cycles_on_several_cores(monkeypatch):
    """``mesh --uncertainty N`` / ``--realisations N`` without --workers (issue 40 item 4): the run's rule
    (:func:`memstribo.job.workers.stage_cluster`): in this process below the threshold or on one core."""
    import argparse

    import memstribo.job.workers as workers
    from memstribo.cli.mesh import _client

    args = argparse.Namespace(scheduler=None, workers=None, quiet=True)
    assert _client(args) is None  # no cycles named: one cycle, this process
    assert _client(args, 8, 32) is None  # under the threshold
    monkeypatch.setattr(workers, "machine_cores", lambda: 1)
    assert _client(args, 1024, 32) is None  # one core


def test_without_critical_values_the_curve_needing_new_solves_is_left_out(params):
    """``critical=False`` (the Sobol' benchmark, issue 40): the dominant constant's curve would need new solves for
    a critical value nobody searched: left out, as with ``critical="rescaled"``."""
    from memstribo.uncertainty.study import uncertainty_study

    fixed = [n for n in priors_for(params) if n != "hamaker_constant"]
    result = uncertainty_study(params, samples=4, realisations=2, steps=11, sobol_samples=2, fixed=fixed,
                               critical=False, curve_points=3)
    assert result["dominant"] == "hamaker_constant" and not result["sensitivity"]["hamaker_constant"]["searched"]
    assert result.get("critical_curve") is None


def test_a_sample_count_the_study_refuses_is_refused_before_the_first_cycle(cli, monkeypatch):
    """Issue 40: not after the self-refining cycle and a cluster's start (16 s), before them."""
    import memstribo.simulations.mesh.convergence as convergence

    def no_cycle(*args, **kwargs):
        raise AssertionError("a cycle ran before the sample count was checked")

    monkeypatch.setattr(convergence, "refined_cycle", no_cycle)
    code, out, err = cli("mesh", "--uncertainty", "5000000")
    assert code == 2 and "at most 1048576" in err and "Traceback" not in err


def test_a_constant_fixed_twice_is_refused_before_the_first_cycle(cli, monkeypatch):
    import memstribo.simulations.mesh.convergence as convergence

    monkeypatch.setattr(convergence, "refined_cycle", lambda *a, **k: (_ for _ in ()).throw(AssertionError("ran")))
    code, out, err = cli("mesh", "--uncertainty", "4", "--set", "bond_energy=4e-19", "--fix", "bond_energy")
    assert code == 2 and "named twice" in err and "Traceback" not in err
