"""The design search (`memstribo design`, issue #39): bad specs refused before any cycle, the geometry
constraints against GearPair, the brute-force check on a tiny problem, an interrupted search resumed, --explain."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("pymoo")

from memstribo.errors import InputError  # noqa: E402
from memstribo.parameters import get_parameter_values  # noqa: E402
from memstribo.simulations import design_search  # noqa: E402
from memstribo.simulations.design_search import brute_force, run_design  # noqa: E402
from memstribo.simulations.design_spec import (CONSTRAINT_NAMES, design_spec, geometry_constraints,  # noqa: E402
                                               load_design_spec)

ROOT = Path(__file__).resolve().parents[1]

#: cheap cycles: 5 steps, 8 elements across the Hertz width, no convergence check, 2 realisations
CHEAP = {"mesh_elements_across_contact": 8, "mesh_step_refinements": 0, "mesh_grid_refinements": 0}


def _table(**changes):
    table = {"name": "tiny", "objectives": ["window"], "population": 4, "generations": 3, "seed": 1,
             "realisations": 1, "stiction_probability": 0.8, "steps": 5, "cycles": 1e3, "fracture_probability": 0.1,
             "torque": {"min": "30 nN*m", "max": "600 nN*m", "num": 3},
             "variables": {"module": {"min": "3 um", "max": "5 um", "step": "1 um"},
                           "face_width": {"min": "1 um", "max": "3 um", "step": "2 um"}}}
    table.update(changes)
    return table


# --- bad input, refused before any cycle runs ------------------------------------------------------------------

@pytest.mark.parametrize("changes,match", [
    ({"variables": {"module": {"min": "5 um", "max": "3 um"}}}, "wrong order"),
    ({"torque": {"min": "600 nN*m", "max": "30 nN*m"}}, "wrong order"),
    ({"objectives": ["windw"]}, "unknown objective 'windw'.*window"),
    ({"variables": {"coating": ["none", "teflon"]}}, "'teflon' is not a shipped coating"),
    ({"variables": {"profile_shift_pinion": {"min": 0, "max": 0.5}}}, "no profile shift"),
    ({"variables": {"moduel": {"min": "3 um", "max": "5 um"}}}, "unknown design variable 'moduel'.*module"),
    ({"variables": {"teeth_pinion": {"min": 8, "max": 12}}}, "meets \\['undercut of the pinion'"),
    ({"constraints": {"contact_ratio_min": 2.5}}, "contact ratio >= contact_ratio_min"),
    ({"constraints": {"tooth_thickness_min": "10 um"}}, "tip tooth thickness"),
    ({"max_cycles": 5}, "cannot finish one generation"),
    ({"stiction_probability": 0.5}, "no design can meet stiction_probability = 0.5.*realisations >= 4"),
    ({"objectives": ["coating_life"]}, "coating_life needs a coating"),
    ({"constraints": {"centre_distance": "200 um"}}, "remove module"),
    ({"speed": 3}, "unknown key"),
    ({"variables": {"pressure_angle": {"min": "5 deg", "max": "20 deg"}}}, "bound of pressure_angle"),
])
def test_bad_specs_are_refused_by_name(changes, match, monkeypatch):
    def no_cycle(*args, **kwargs):
        raise AssertionError("a cycle ran for a bad spec")

    monkeypatch.setattr("memstribo.simulations.design_map.map_point", no_cycle)
    with pytest.raises(InputError, match=match):
        design_spec(_table(**changes), CHEAP)


def test_cli_refuses_a_bad_spec_with_exit_2_and_writes_nothing(tmp_path, capsys):
    from memstribo.cli.main import main

    spec = tmp_path / "bad.toml"
    spec.write_text('[design]\nobjectives = ["window"]\n[design.torque]\nmin = "1 nN*m"\nmax = "2 nN*m"\n'
                    '[design.variables]\nface_width = {min = "3 um", max = "1 um"}\n', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["design", str(spec), "--out", str(out)]) == 2
    assert "wrong order" in capsys.readouterr().err
    assert not out.exists()


# --- geometry ------------------------------------------------------------------------------------------------

def test_geometry_constraints_agree_with_gear_pair():
    """A design meets undercut, interference, pointed-tip and contact-ratio (>= 1) constraints exactly when
    GearPair accepts it."""
    from memstribo.physics.gear import GearPair

    base = get_parameter_values()
    spec = design_spec(_table(constraints={"contact_ratio_min": 1.0}), CHEAP)
    rng = np.random.default_rng(4)
    agreed = {True: 0, False: 0}
    for _ in range(300):
        design = {"teeth_pinion": int(rng.integers(6, 40)), "teeth_gear": int(rng.integers(6, 120)),
                  "module": float(rng.uniform(2e-6, 6e-6)), "pressure_angle": float(np.radians(rng.uniform(10, 35))),
                  "addendum_coefficient": float(rng.uniform(0.6, 1.6))}
        if design["teeth_gear"] < design["teeth_pinion"]:
            continue
        g = geometry_constraints(spec, base, design)
        try:
            GearPair(design["teeth_pinion"], design["teeth_gear"], design["module"], design["pressure_angle"],
                     2e-6, design["addendum_coefficient"])
            accepted = True
        except InputError:
            accepted = False
        assert accepted == bool(np.all(g[:5] <= 0)), (design, dict(zip(CONSTRAINT_NAMES, g)))
        agreed[accepted] += 1
    assert agreed[True] > 20 and agreed[False] > 20  # both kinds were drawn


def test_thesis_pair_is_feasible_and_a_fixed_centre_distance_sets_the_module():
    base = get_parameter_values()
    spec = design_spec(_table(), CHEAP)
    assert np.all(geometry_constraints(spec, base, {}) <= 0)
    fixed = design_spec(_table(variables={"teeth_pinion": {"min": 18, "max": 24}},
                               constraints={"centre_distance": "190 um", "ratio": 4}), CHEAP)
    from memstribo.simulations.design_spec import decode

    design = decode(fixed, [20.2], base)
    assert design["teeth_pinion"] == 20 and design["teeth_gear"] == 80
    assert design["module"] * (20 + 80) / 2 == pytest.approx(190e-6)


# --- the search against brute force, on cheap cycles ------------------------------------------------------------

def test_search_finds_the_best_window_of_the_full_grid(tmp_path):
    """Module x face width (3 x 2 points), the rest fixed: NSGA-II's widest window is the grid's widest (both from
    the same evaluation store, so the grid adds only the points the search did not visit)."""
    spec = design_spec(_table(), CHEAP)
    result = run_design(spec, tmp_path / "search", workers=1, figures=False)
    assert result.n_failed == 0 and result.cycles_spent > 0
    best_search = float(result.best["values"]["torque_window"])
    grid = brute_force(spec, tmp_path / "search", workers=1)
    assert grid["designs"] == 6
    assert grid["window"] > 0
    windows = [float(r["values"]["torque_window"]) for r in
               (json.loads(p.read_text()) for p in (tmp_path / "search" / "evaluations").glob("*.json"))]
    assert len(set(np.round(windows, 15))) > 2  # the designs differ: the test can fail
    assert best_search == pytest.approx(grid["window"], rel=1e-12)
    # the Pareto set (one objective: the widest window) with its intervals and converged flag, in NetCDF and CSV
    import xarray as xr

    with xr.open_dataset(tmp_path / "search" / "pareto.nc") as pareto:
        assert float(pareto["torque_window"][0]) == pytest.approx(best_search)
        for key in ("torque_window_high", "stiction_probability_high", "converged", "module", "face_width"):
            assert key in pareto
        assert pareto["torque_window"].attrs["units"] == "N m" or pareto["torque_window"].attrs["units"]
        assert np.all(pareto["torque_window_high"].values >= pareto["torque_window"].values)
    assert (tmp_path / "search" / "pareto.csv").is_file()


def test_window_edges_follow_their_definitions(tmp_path):
    """The stiction edge is a grid torque with P(stiction) upper bounds below p_s; the window is the fracture edge
    (capped at the range's top) minus it."""
    spec = design_spec(_table(generations=1, population=2), CHEAP)
    base = get_parameter_values().updated(CHEAP)
    values = design_search.evaluate_design(base, {"module": 5e-6, "face_width": 1e-6}, torques=list(spec.torques),
                                           realisations=2, steps=5, stiction_probability=0.7,
                                           fracture_probability=0.1, cycles=1e3)
    assert values["stiction_torque"] in [pytest.approx(t) for t in spec.torques]
    assert values["stiction_probability_high"] < 0.7
    upper = min(values["fracture_torque"], spec.torque_max)
    assert values["torque_window"] == pytest.approx(max(0.0, upper - values["stiction_torque"]))
    assert values["cycles_spent"] == 2 * values["verdicts"]
    from memstribo.simulations.tooth_life import fracture_probability_within, synthetic_cycle, tooth_life

    q = base.updated({"module": 5e-6, "face_width": 1e-6, "drive_torque": values["fracture_torque"]})
    risk = fracture_probability_within(tooth_life(synthetic_cycle(q, cof=values["cof_mean_median"], steps=41), q),
                                       1e3)
    assert risk == pytest.approx(0.1, rel=0.01)


# --- resume -------------------------------------------------------------------------------------------------------

def _fake(params, design, **options):
    """A cheap stand-in for evaluate_design (no cycle): a smooth window over module and face width."""
    m, b = design.get("module", 4e-6) * 1e6, design.get("face_width", 2e-6) * 1e6
    window = 1e-7 * (1.0 - (m - 4.2) ** 2 / 4 - (b - 2.5) ** 2 / 8)
    return {"torque_window": window, "torque_window_high": window, "footprint": m * 1e-10, "cycles_spent": 2.0,
            "mesh_efficiency_median": 0.9, "converged": 1.0, "stiction_torque": 3e-8, "fracture_torque": 3e-8 + window}


def test_interrupted_search_resumes_without_repeating_evaluations(tmp_path, monkeypatch):
    table = _table(population=6, generations=4, objectives=["window", "footprint"],
                   variables={"module": {"min": "3 um", "max": "5 um", "step": "0.25 um"},
                              "face_width": {"min": "1 um", "max": "4 um", "step": "0.5 um"}})
    spec = design_spec(table, CHEAP)
    calls, interrupt = [], [9]

    def counted(params, design, **options):
        calls.append(json.dumps(design, sort_keys=True))
        if len(calls) == interrupt[0]:
            interrupt[0] = -1
            raise KeyboardInterrupt  # the user stops the search in its second generation
        return _fake(params, design, **options)

    monkeypatch.setattr(design_search, "evaluate_design", counted)
    with pytest.raises(KeyboardInterrupt):
        run_design(spec, tmp_path / "a", workers=1, figures=False)
    first = list(calls)
    assert len(list((tmp_path / "a" / "evaluations").glob("*.json"))) == 8
    with pytest.raises(InputError, match="--resume"):
        run_design(spec, tmp_path / "a", workers=1, figures=False)
    resumed = run_design(spec, tmp_path / "a", workers=1, figures=False, resume=True)
    again = calls[len(first):]
    assert not set(again) & set(first[:-1]), "a finished evaluation ran again"
    assert resumed.n_reused == 8 and resumed.n_computed == len(again)
    # the same Pareto set as a search never interrupted
    calls.clear()
    whole = run_design(spec, tmp_path / "b", workers=1, figures=False)
    assert len(calls) == len(first) - 1 + len(again)
    for key in ("torque_window", "footprint", "module", "face_width"):
        np.testing.assert_array_equal(resumed.dataset[key].values, whole.dataset[key].values)
    with pytest.raises(InputError, match="different design search"):
        run_design(design_spec({**table, "seed": 2}, CHEAP), tmp_path / "a", workers=1, figures=False, resume=True)


def test_pareto_set_is_non_dominated(tmp_path, monkeypatch):
    monkeypatch.setattr(design_search, "evaluate_design", _fake)
    spec = design_spec(_table(population=6, generations=3, objectives=["window", "footprint"]), CHEAP)
    result = run_design(spec, tmp_path, workers=1)
    f = np.column_stack([-result.dataset["torque_window"].values, result.dataset["footprint"].values])
    assert np.all(design_search.pareto_mask(f))
    assert (tmp_path / "figures" / "design_front.png").is_file()
    assert result.default["feasible"] and result.default["design"] == {"module": pytest.approx(3.8788e-6, rel=1e-4),
                                                                         "face_width": 2e-06}


# --- the command ----------------------------------------------------------------------------------------------------

def test_example_spec_loads():
    spec = load_design_spec(ROOT / "examples" / "design_thesis_pair.toml")
    assert "window" in spec.objectives and spec.population * spec.generations >= 8


def test_cli_search_and_explain(tmp_path, capsys, monkeypatch):
    """The command runs the search (cheap stand-in), then --explain 0 prints the mesh verdict of that design with
    the memstribo mesh command line that gives it."""
    from memstribo.cli.main import main

    monkeypatch.setattr(design_search, "evaluate_design", _fake)
    spec = tmp_path / "spec.toml"
    spec.write_text('[parameters]\nmesh_elements_across_contact = 8\n[design]\nname = "cli"\npopulation = 4\n'
                    'generations = 2\nrealisations = 2\nstiction_probability = 0.7\nsteps = 5\n'
                    '[design.torque]\nmin = "30 nN*m"\nmax = "600 nN*m"\nnum = 3\n'
                    '[design.variables]\nmodule = {min = "3 um", max = "5 um", step = "1 um"}\n', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["design", str(spec), "--out", str(out), "--workers", "1", "--json"]) == 0
    values = json.loads(capsys.readouterr().out)
    assert values["best_torque_window"] > 0 and values["pareto_designs"] >= 1
    assert main(["design", str(spec), "--out", str(out), "--explain", "0"]) == 0
    text = capsys.readouterr().out
    assert "Pareto design 0" in text and "memstribo mesh --set module=" in text and "stiction" in text
    assert main(["design", str(spec), "--out", str(out), "--explain", "99"]) == 2
    assert "designs 0 to" in capsys.readouterr().err
    assert math.isfinite(values["cycles_total"])
    shutil.rmtree(out)


def test_api_design_takes_a_table(tmp_path, monkeypatch):
    import memstribo

    monkeypatch.setattr(design_search, "evaluate_design", _fake)
    result = memstribo.design({**_table(population=4, generations=2), "parameters": CHEAP}, tmp_path, workers=1,
                              figures=False)
    assert "design" in memstribo.__all__
    assert result.best["values"]["torque_window"] == pytest.approx(float(result.dataset["torque_window"][0]))
    with pytest.raises(InputError, match="design spec"):
        memstribo.design(42, tmp_path / "x")


@pytest.mark.slow
def test_search_on_dask_equals_the_search_in_process(tmp_path):
    """The designs of a generation as Dask tasks (2 workers) give the same Pareto set as in this process."""
    pytest.importorskip("distributed")
    spec = design_spec(_table(generations=2), CHEAP)
    serial = run_design(spec, tmp_path / "serial", workers=1, figures=False)
    parallel = run_design(spec, tmp_path / "dask", workers=2, figures=False)
    for key in ("torque_window", "fracture_torque", "module", "face_width"):
        np.testing.assert_array_equal(serial.dataset[key].values, parallel.dataset[key].values)
