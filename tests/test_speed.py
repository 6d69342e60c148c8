"""The compute path of issue 40: contact solves shared by their inputs, worker counts capped at the cores. Speed
itself is measured in bench/ (bench_profile.py, bench_uncertainty.py), never here."""

from __future__ import annotations

import json

import numpy as np
import pytest


def _plain(result):
    """The study's result without its timings, as JSON text (floats compared bit for bit)."""
    drop = {"elapsed", "solve_seconds", "rescale_seconds", "contact_rows_reused"}
    return json.dumps({k: v for k, v in result.items() if k not in drop}, sort_keys=True, default=str)


def test_kept_contact_solves_are_bit_identical_to_new_ones(params):
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.simulations.mesh import solve_cache

    moved = params.updated({"threshold_strain": 0.4})  # block mechanics only: the contact does not see it
    cold = [summarize(simulate_mesh(p, steps=21)) for p in (params, moved)]
    solve_cache.keep_solves()
    try:
        kept = [summarize(simulate_mesh(p, steps=21)) for p in (params, moved)]
        counts = solve_cache.kept_solves()
    finally:
        solve_cache.stop_keeping()
    assert counts["hits"] == counts["misses"] > 0  # the second cycle's rows all came from the first's solves
    for a, b in zip(cold, kept):
        assert json.dumps(a, sort_keys=True, default=str) == json.dumps(b, sort_keys=True, default=str)
    assert cold[0]["stiction_margin"] != cold[1]["stiction_margin"]  # the kept solve did not freeze the answer


def test_a_changed_contact_input_is_solved_anew(params):
    from memstribo.simulations.mesh import simulate_mesh
    from memstribo.simulations.mesh import solve_cache

    solve_cache.keep_solves()
    try:
        simulate_mesh(params, steps=11)
        simulate_mesh(params.updated({"hamaker_constant": 2 * params["hamaker_constant"]}), steps=11)
        counts = solve_cache.kept_solves()
    finally:
        solve_cache.stop_keeping()
    assert counts["hits"] == 0 and counts["misses"] > 0
    assert solve_cache.kept_solves() == {"rows": 0, "bytes": 0, "hits": 0, "misses": 0}


def test_the_solve_store_keeps_within_its_bytes():
    from memstribo.simulations.mesh import solve_cache

    solve_cache.keep_solves(max_bytes=3 * 800)
    try:
        for i in range(5):
            key = solve_cache.solve_digest([np.full(100, float(i))], (i,))
            solve_cache.store(key, (np.zeros(100),))
        state = solve_cache.kept_solves()
        assert state["rows"] == 3 and state["bytes"] == 2400
        assert solve_cache.lookup(solve_cache.solve_digest([np.full(100, 0.0)], (0,))) is None  # the oldest went
        assert solve_cache.lookup(solve_cache.solve_digest([np.full(100, 4.0)], (4,))) is not None
    finally:
        solve_cache.stop_keeping()
    assert solve_cache.solve_digest([np.zeros(3)], ()) is None  # off: nothing is kept or looked up


def test_the_study_with_kept_solves_equals_the_study_without(params, monkeypatch):
    from memstribo.simulations.mesh import solve_cache
    from memstribo.uncertainty.study import uncertainty_study

    from memstribo.uncertainty.priors import priors_for

    # a block constant (its rows' solves are kept), a contact constant (solved anew) and a rescaled one
    fixed = [n for n in priors_for(params) if n not in ("atomic_width", "hamaker_constant", "bond_energy")]
    kwargs = dict(samples=4, realisations=2, steps=11, sobol_samples=2, curve_points=2, fixed=fixed)
    kept = uncertainty_study(params, **kwargs)
    monkeypatch.setattr(solve_cache, "keep_solves", lambda *a, **k: None)
    plain = uncertainty_study(params, **kwargs)
    assert _plain(kept) == _plain(plain)
    assert kept["contact_rows_reused"] > 0 and plain["contact_rows_reused"] == 0


@pytest.mark.parametrize("command", ["study", "map"])
def test_workers_above_the_cores_are_capped_with_a_note(command, capsys, monkeypatch):
    import memstribo.cli.mesh as mesh_cli

    monkeypatch.setattr(mesh_cli, "machine_cores", lambda: 2)
    assert mesh_cli.cap_workers(64, command) == 2
    assert f"memstribo {command}: note: --workers 64 is more than this machine's 2 core(s)" in capsys.readouterr().err
    assert mesh_cli.cap_workers(2, command) == 2 and mesh_cli.cap_workers(None, command) is None
    assert capsys.readouterr().err == ""


def test_a_shared_solve_design_that_widens_the_interval_past_the_precision_says_so():
    from memstribo.uncertainty.study import TARGET_HALF_WIDTH, _warnings

    base = {"failed_samples": 0, "unconverged_samples": 0, "solve_sets": 1, "confidence": 0.95, "samples": 1024,
            "stiction_count": 512}
    wide = _warnings({**base, "design_effect": 4.0, "stiction_probability_ci": [0.5 - 0.06, 0.5 + 0.06]})
    assert any("shared-solve design (solve_sets = 1) widens" in w and f"+-{TARGET_HALF_WIDTH:g}" in w for w in wide)
    assert _warnings({**base, "design_effect": 1.2, "stiction_probability_ci": [0.5 - 0.04, 0.5 + 0.04]}) == []
    assert _warnings({**base, "solve_sets": None, "design_effect": 1.0,
                      "stiction_probability_ci": [0.44, 0.56]}) == []


def test_the_study_on_two_workers_equals_the_study_in_this_process(params):
    from memstribo.simulations.study import local_cluster
    from memstribo.uncertainty.study import uncertainty_study

    kwargs = dict(samples=4, realisations=2, steps=11, sensitivity=False)
    alone = uncertainty_study(params, **kwargs)
    with local_cluster(2) as cluster:
        shared = uncertainty_study(params, client=cluster, **kwargs)
    assert alone["workers"] == 1 and shared["workers"] == 2
    drop = {"workers"}
    assert _plain({k: v for k, v in alone.items() if k not in drop}) == \
        _plain({k: v for k, v in shared.items() if k not in drop})


def test_the_run_starts_workers_only_where_the_stage_has_work_for_them(monkeypatch, caplog):
    import logging

    import memstribo.job.workers as workers

    started = []
    monkeypatch.setattr("memstribo.simulations.study.local_cluster", lambda n: started.append(n) or f"cluster {n}")
    with caplog.at_level(logging.INFO, logger="memstribo.run"):
        monkeypatch.setattr(workers, "machine_cores", lambda: 2)
        assert workers.stage_cluster(workers.PARALLEL_SAMPLES - 1, "uncertainty") is None
        assert workers.stage_cluster(64, "uncertainty") == "cluster 2" and started == [2]
        monkeypatch.setattr(workers, "machine_cores", lambda: 1)
        assert workers.stage_cluster(64, "uncertainty") is None and started == [2]
    text = caplog.text
    assert "uncertainty: the cycles run on 2 worker processes (this machine's cores)" in text
    assert "under 32" in text and "one core" in text


def test_the_runs_ensemble_on_the_cluster_equals_the_ensemble_in_this_process(params, tmp_path, monkeypatch, caplog):
    import logging

    import memstribo.job.workers as workers
    from memstribo.job.chain import RunChain
    from memstribo.job.options import options_for_test

    # the first realisation runs here, the others (at least ENSEMBLE_REALISATIONS of them) on the cluster
    options = options_for_test(stages=("roughness", "geometry", "mesh"),
                               realisations=workers.ENSEMBLE_REALISATIONS + 1)
    monkeypatch.setattr(workers, "machine_cores", lambda: 2)
    chain = RunChain(params, tmp_path / "two", options)
    with caplog.at_level(logging.INFO, logger="memstribo.run"):
        shared = chain.run()
    assert "mesh ensemble: the cycles run on 2 worker processes" in caplog.text
    assert chain.workers.cluster is None  # closed at the end of the run
    monkeypatch.setattr(workers, "machine_cores", lambda: 1)
    alone = RunChain(params, tmp_path / "one", options).run()
    assert shared.ok and alone.ok
    a, b = (json.loads((tmp_path / name / "data" / "mesh_bare_ensemble.json").read_text()) for name in ("two", "one"))
    assert json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)


def test_the_runs_uncertainty_stage_reuses_the_mesh_ensemble_and_ranks_on_its_samples(params, tmp_path):
    """Issue 40: the uncertainty stage takes the mesh stage's realisations as its nominal ones (the same numbers as
    solving them again, three solves fewer), ranks by the regional index on its own samples (no Sobol' design, no
    end points or bands) and says where the full analysis is."""
    from memstribo.job.chain import RunChain
    from memstribo.job.options import options_for_test

    with_mesh = RunChain(params, tmp_path / "with", options_for_test(
        stages=("roughness", "geometry", "mesh", "uncertainty"))).run()
    alone = RunChain(params, tmp_path / "alone", options_for_test(
        stages=("roughness", "geometry", "uncertainty"))).run()
    assert with_mesh.ok and alone.ok
    a, b = (json.loads((tmp_path / name / "data" / "uncertainty.json").read_text()) for name in ("with", "alone"))
    assert a["nominal_cycles_reused"] == 3 and b["nominal_cycles_reused"] == 0
    assert a["solves"] == b["solves"] - 3
    for key in ("stiction_probability", "stiction_probability_ci", "margin_quantiles", "margin_quantiles_nominal",
                "cof_quantiles", "decision_sensitivity", "margin_correlation"):
        assert json.dumps(a[key], sort_keys=True) == json.dumps(b[key], sort_keys=True), key
    assert a["sensitivity_method"] == "regional" and "sobol_design" not in a
    assert a["decision_depth"] == "regional" and a["robust_bayes"] is None
    assert "memstribo mesh --uncertainty" in a["decision_sentence"]


def test_the_runs_sweeps_on_the_cluster_equal_the_sweeps_in_this_process(params, tmp_path, monkeypatch, caplog):
    """Issue 40: once the mesh ensemble has started the run's cluster, the load, area and wear sweeps run their
    cycles on it: the same numbers as in this process."""
    import logging

    import memstribo.job.workers as workers
    from memstribo.job.chain import RunChain
    from memstribo.job.options import options_for_test

    options = options_for_test(stages=("roughness", "geometry", "gear", "mesh", "load_sweep", "area_sweep", "coated",
                                       "wear_sweep"), realisations=workers.ENSEMBLE_REALISATIONS + 1,
                               wear=(0.0, 0.5, 1.0))
    monkeypatch.setattr(workers, "machine_cores", lambda: 2)
    with caplog.at_level(logging.INFO, logger="memstribo.run"):
        shared = RunChain(params, tmp_path / "two", options).run()
    for stage in ("load sweep", "area sweep", "wear sweep"):
        assert f"{stage}: the cycles run on the run's 2 worker processes" in caplog.text
    monkeypatch.setattr(workers, "machine_cores", lambda: 1)
    alone = RunChain(params, tmp_path / "one", options).run()
    assert shared.ok and alone.ok
    for name in ("load_sweep", "area_sweep", "wear_sweep"):
        a, b = ([line for line in (tmp_path / run / "data" / f"{name}.csv").read_text().splitlines()
                 if not line.startswith("#")] for run in ("two", "one"))  # the header has its time of writing
        assert a == b and len(a) > 2, name


def test_a_failed_mesh_stage_cancels_its_realisations_on_the_cluster(params, tmp_path, monkeypatch):
    """The ensemble's realisations go to the cluster before the first one runs here (issue 40): where that one fails,
    they are cancelled, not left running beside the next stages."""
    import distributed

    import memstribo.job.workers as workers
    from memstribo.errors import InputError
    from memstribo.job.chain import RunChain
    from memstribo.job.options import options_for_test

    cancelled = []
    original = distributed.Client.cancel
    monkeypatch.setattr(distributed.Client, "cancel", lambda self, futures, *a, **k: cancelled.append(len(futures))
                        or original(self, futures, *a, **k))
    monkeypatch.setattr(workers, "machine_cores", lambda: 2)

    def broken(*args, **kwargs):
        raise InputError("a refused cycle")

    monkeypatch.setattr(RunChain, "_simulate", broken)
    options = options_for_test(stages=("roughness", "geometry", "mesh"),
                               realisations=workers.ENSEMBLE_REALISATIONS + 1)
    result = RunChain(params, tmp_path / "out", options).run()
    mesh = next(record for record in result.stages if record.name == "mesh")
    assert mesh.status == "failed" and "a refused cycle" in mesh.message
    assert cancelled == [workers.ENSEMBLE_REALISATIONS]


def test_a_wear_sweep_takes_the_contact_solves_its_states_repeat(params, monkeypatch):
    """Issue 40: the wear states of one coating under the thesis conditions (no adhesion in the contact solve) differ
    in bond energies only: every state after the first takes its rows' solves from the store, the same numbers as
    without it; a store kept already (an uncertainty study's) is left kept."""
    import contextlib

    import xarray as xr

    import memstribo.simulations.mesh.solve_cache as cache
    from memstribo.parameters import THESIS_CONDITIONS
    from memstribo.simulations.coating_wear import wear_sweep

    conditions = params.updated(THESIS_CONDITIONS)
    counts = []
    original = cache.stop_keeping
    monkeypatch.setattr(cache, "stop_keeping", lambda: counts.append(original()) or counts[-1])
    kept = wear_sweep(conditions, "OTS", [0.0, 0.5, 1.0], steps=11)
    assert len(counts) == 1 and counts[0]["misses"] > 0 and counts[0]["hits"] == 2 * counts[0]["misses"]
    with monkeypatch.context() as patch:
        patch.setattr(cache, "solves_kept", contextlib.nullcontext)
        plain = wear_sweep(conditions, "OTS", [0.0, 0.5, 1.0], steps=11)
    xr.testing.assert_identical(kept, plain)
    cache.keep_solves()
    try:
        with cache.solves_kept():
            pass
        assert cache.kept_solves() == {"rows": 0, "bytes": 0, "hits": 0, "misses": 0} and cache._STATE["store"] is not None
    finally:
        original()
