"""The main job: every stage end to end on small settings, outputs on disk, CLI, bad input."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from memstribo.job.chain import RunChain, verdict
from memstribo.job.options import STAGES, RunOptions, options_for_test
from memstribo.errors import InputError

REPO = Path(__file__).resolve().parent.parent

@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    """One small run of every stage (few steps, two points per sweep), shared by the tests below."""
    from memstribo.parameters import get_parameter_values

    out = tmp_path_factory.mktemp("run")
    options = options_for_test(roughness_files=(str(REPO / "data" / "afm" / "si_profile_linescan.txt"),))
    return RunChain(get_parameter_values(), out, options).run()


def test_every_stage_runs(small_run):
    for record in small_run.stages:
        assert record.status == "done", f"{record.name}: {record.status}: {record.message}"
    assert small_run.ok
    assert [r.name for r in small_run.stages] == list(STAGES)


def test_outputs_are_on_disk_with_units(small_run):
    import xarray as xr

    folder = small_run.folder
    for name in ("parameters.toml", "references.txt", "run.json", "report.html"):
        assert (folder / name).is_file(), name
    manifest = json.loads((folder / "run.json").read_text())
    assert [s["name"] for s in manifest["stages"]] == list(STAGES)
    for record in small_run.stages:
        for file in record.files:
            assert (folder / file).is_file(), file
    for figure in small_run.figures:
        assert (folder / "figures" / f"{figure.stem}.png").stat().st_size > 1000
        assert (folder / "figures" / f"{figure.stem}.svg").is_file()
    stats = xr.open_dataset(folder / "data" / "roughness_statistics.nc")
    assert stats["Rq"].attrs["units"] == "m"
    # the default profile is labelled synthetic, the file is named with its provenance
    assert small_run.inputs[0]["synthetic"] is True and "synthetic" in small_run.inputs[0]["source"]
    assert [item["meshing"] for item in small_run.inputs][0] is True  # mesh_roughness = "synthetic"
    if len(small_run.inputs) > 1:
        assert small_run.inputs[1]["synthetic"] is False
        assert "si_profile_linescan" in small_run.inputs[1]["source"]
    # the parameters file is a valid config that reproduces the parameters
    from memstribo.parameters import get_parameter_values, read_config

    again = get_parameter_values().updated(read_config(folder / "parameters.toml")["parameters"])
    assert again.to_dict() == small_run.params.to_dict()
    assert "[thesis]" in (folder / "references.txt").read_text()


def test_gear_stage_matches_the_thesis_tangential_force(small_run):
    # thesis 4.7 (4-27): F_t = 2.82e-3 N, printed to 3 digits
    assert small_run.verdict["tangential_force"] == pytest.approx(2.82e-3, rel=5e-3)


def test_mesh_stages(small_run):
    summaries = small_run.summaries
    bare = summaries["mesh"]
    assert bare["energy_dissipated"] >= 0 and bare["friction_force_max"] > 0
    # the verdict over the ensemble, its step check, one criterion
    assert bare["realisations"] == 3 and 0.0 <= bare["stiction_probability"] <= 1.0
    assert bare["stiction_margin"] == bare["tangential_force"] - bare["resisting_force_max"]
    assert "step_converged" in bare and small_run.verdict["bare_realisations"] == 3
    # the run's bare cycle is exactly what 'memstribo mesh' computes (the same independent synthetic rows)
    from memstribo.simulations.mesh import simulate_mesh, summarize

    alone = summarize(simulate_mesh(small_run.params, steps=8))
    assert bare["cof_mean"] == alone["cof_mean"] and bare["stiction_margin"] == alone["stiction_margin"]
    # the energy split adds up (mesh.summarize: cof_x = energy_x / integral (F_N + F_adh) ds)
    assert bare["energy_dissipated"] == pytest.approx(bare["energy_chemical"] + bare["energy_vdw"]
                                                      + bare["energy_elastic"], rel=1e-12)
    assert small_run.verdict["bare_stiction"] == (bare["stiction_margin"] < 0)
    assert small_run.verdict["tangential_force"] == bare["tangential_force"]
    loads = summaries["load_sweep"]
    assert loads["normal_load"] == pytest.approx([25e-6, 150e-6])
    assert loads["energy_dissipated"][1] > loads["energy_dissipated"][0]  # more load, more dissipation (4.9.3)
    single = summaries["sliding"]["single"]
    # thesis 2.6.2: one nanoblock on a flat, COF constant in time; the split adds up
    assert single["cof_mean"] == pytest.approx(single["cof_chemical"] + single["cof_vdw"] + single["cof_elastic"],
                                          rel=1e-9)
    assert single["fraction_chemical"] + single["fraction_vdw"] + single["fraction_elastic"] == pytest.approx(1)
    # a coating forms no chemical bonds: less friction than bare silicon (thesis 5.4)
    assert summaries["coated"]["energy_chemical"] == 0.0
    assert summaries["coated"]["friction_force_max"] < bare["friction_force_max"]
    sweep = summaries["wear_sweep"]
    # wear = 1 is bare silicon (the contract of mesh.simulate_mesh)
    assert sweep["stiction_margin"][-1] == pytest.approx(bare["stiction_margin"], rel=1e-9)
    critical = small_run.verdict["wear_at_stiction"]
    assert critical is None or 0.0 <= critical <= 1.0


def test_verdict_from_stage_summaries():
    bare = {"resisting_force_max": 3e-3, "stiction_margin": -0.18e-3, "cof_mean": 0.9, "load_case": "torque",
            "stiction_probability": 0.75, "realisations": 16, "warnings": ["w"]}
    coated = {"resisting_force_max": 1e-4, "stiction_margin": 2.72e-3, "cof_mean": 0.19, "load_case": "torque"}
    v = verdict({"gear": {"tangential_force": 2.82e-3}, "mesh": bare, "coated": coated,
                 "wear_sweep": {"critical_wear": 0.5}, "damage": {"cycles_to_stiction": None,
                                                                 "damage_per_cycle_over_c1": 2e10}})
    assert v["bare_stiction"] is True and v["coated_stiction"] is False
    assert v["bare_stiction_margin"] == -0.18e-3 and v["wear_at_stiction"] == 0.5
    assert v["bare_stiction_probability"] == 0.75 and v["load_case"] == "torque" and v["bare_warnings"] == ["w"]
    assert v["cycles_to_stiction"] is None and v["damage_per_cycle_over_c1"] == 2e10
    assert verdict({}) == {}


def test_run_options_from_a_config_table(tmp_path):
    # a readable profile: [run] roughness_files are read before the first stage (#29)
    (tmp_path / "scan.txt").write_text("".join(f"{i * 1e-8!r} {1e-9 * ((i * 7) % 5 - 2)!r}\n" for i in range(40)))
    options = RunOptions.from_table({"steps": 10, "loads": ["25 uN", "0.1 mN"], "wear": [0, 0.5],
                                     "roughness_files": ["scan.txt"], "stages": ["mesh", "roughness"]}, tmp_path)
    assert options.steps == 10 and options.loads == pytest.approx((25e-6, 1e-4))
    assert options.roughness_files == (str((tmp_path / "scan.txt").resolve()),)
    assert options.stages == ("roughness", "mesh")  # always in chain order
    assert RunOptions().loads == pytest.approx((25e-6, 50e-6, 100e-6, 150e-6, 200e-6, 300e-6))  # thesis 4.9.3
    assert RunOptions().realisations == 16


@pytest.mark.parametrize("table, match", [
    ({"step": 3}, "unknown key 'step'.*steps"),
    ({"steps": 2}, "integer >= 3"),
    ({"realisations": 0}, "from 1 to 10000"),
    ({"loads": []}, "non-empty list"),
    ({"loads": ["-1 uN"]}, "outside its range"),
    ({"loads": ["25 m"]}, "25 m"),
    ({"wear": [1.2]}, "outside its range"),
    ({"roughness_files": ["nope.txt"]}, "does not exist"),
    ({"stages": ["mseh"]}, "unknown stage 'mseh'.*mesh"),
    ({"mesh_roughness": 3}, "mesh_roughness"),
    ({"cycles_observed": -5}, "cycles > 0"),
    ({"areas": [1.5]}, "whole multiples"),
    ({"sliding_distance": "-1 nm"}, "length > 0"),
    ({"validation": "yes"}, "recompute"),
])
def test_bad_run_tables_raise_input_error(table, match, tmp_path):
    with pytest.raises(InputError, match=match):
        RunOptions.from_table(table, tmp_path)


def test_the_validation_table_is_shipped_or_recomputed_as_asked(tmp_path):
    assert RunOptions.from_table({}, tmp_path).validation is True  # the rows shipped with this version
    assert RunOptions.from_table({"validation": "recompute"}, tmp_path).validation == "recompute"
    assert RunOptions.from_table({"validation": False}, tmp_path).validation is False


def test_cli_run_json_with_config_file(cli, tmp_path):
    config = tmp_path / "case.toml"
    config.write_text('[parameters]\nnormal_load = "50 uN"\n[run]\nstages = ["roughness", "geometry", "gear"]\nvalidation = false\n')
    values = cli.json("run", config, "--out", tmp_path / "out", "--steps", "5")
    assert values["stages"]["gear"] == "done" and values["stages"]["mesh"] == "skipped"
    assert values["complete"] is True
    assert Path(values["report"]).is_file()
    assert "normal_load" in (tmp_path / "out" / "parameters.toml").read_text()
    text = (tmp_path / "out" / "parameters.toml").read_text()
    assert re.search(r"\[parameters.normal_load\]\nvalue = 5e-05", text)


@pytest.mark.parametrize("argv, message", [
    (("run", "missing.toml"), "does not exist"),
    (("run", "--steps", "1"), "--steps 1"),
    (("run", "--roughness", "no_such_scan.txt"), "does not exist"),
])
def test_cli_run_bad_input_exits_2(cli, tmp_path, argv, message):
    code, out, err = cli(*argv, "--out", tmp_path / "out")
    assert code == 2 and message in err and "Traceback" not in err


def test_cli_run_bad_run_table_exits_2(cli, tmp_path):
    config = tmp_path / "bad.toml"
    config.write_text("[run]\nwear = [2]\n")
    code, out, err = cli("run", config, "--out", tmp_path / "out")
    assert code == 2 and "outside its range" in err and "Traceback" not in err


@pytest.mark.browser
def test_report_of_a_real_run_renders_every_figure(small_run, tmp_path):
    from test_report import browser_dom

    dom = browser_dom(small_run.folder / "report.html", tmp_path / "profile")
    assert f'data-figures="ok {len(small_run.figures)}"' in dom
    assert len(small_run.figures) >= 1


def test_example_run_config_is_valid():
    from memstribo.parameters import read_config

    path = REPO / "examples" / "run_thesis_case.toml"
    options = RunOptions.from_table(read_config(path)["run"], path.parent)
    assert len(options.roughness_files) == 2 and all(Path(f).is_file() for f in options.roughness_files)
    assert options.coating == "OTS" and options.wear[0] == 0.0 and options.wear[-1] == 1.0


def test_python_api_example_on_a_real_profile(capsys):
    import runpy

    namespace = runpy.run_path(str(REPO / "examples" / "api_afm_profile.py"))
    results = namespace["main"](refine=False)  # one cycle each (the script's own run refines: 30 s more)
    out = capsys.readouterr().out
    assert "opdx-3.opdx" in out and "Rq = 2.826 nm" in out  # data/afm/README.md: Rq 2.826 nm
    assert results["coated"]["friction_force_max"] < results["bare"]["friction_force_max"]


def test_run_progress_bar_over_the_stages(params, tmp_path, capsys):
    RunChain(params, tmp_path / "out", options_for_test(stages=("gear",), validation=False), progress=True).run()
    err = capsys.readouterr().err
    assert "memstribo run" in err and f"{len(STAGES)}/{len(STAGES)}" in err and "stage" in err


def test_an_interrupted_run_keeps_what_it_finished(params, tmp_path, monkeypatch):
    """Ctrl-C in a later stage: the earlier stages' files and run.json stay on disk."""
    def interrupt(self):
        raise KeyboardInterrupt

    monkeypatch.setattr(RunChain, "mesh", interrupt)
    chain = RunChain(params, tmp_path / "out", options_for_test(validation=False))
    with pytest.raises(KeyboardInterrupt):
        chain.run()
    manifest = json.loads((tmp_path / "out" / "run.json").read_text())
    done = [s["name"] for s in manifest["stages"] if s["status"] == "done"]
    assert "roughness" in done and "gear" in done
    assert (tmp_path / "out" / "data" / "gear.json").is_file()
    assert (tmp_path / "out" / "report.html").is_file()


def test_a_measured_meshing_profile_sets_the_geometry_downstream(tmp_path):
    """#11 item 5: with a measured profile for the meshing cycle, the nanoblock geometry is derived from it
    (as 'memstribo nanoblock --from' does) and used by the meshing stages; the verdict says so."""
    from memstribo.physics.nanoblock.geometry import nanoblock_geometry_from_profile
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.readers import read_topography

    scan = REPO / "data" / "afm" / "si_profile_linescan.txt"
    options = options_for_test(roughness_files=(str(scan),), mesh_roughness=0, stages=("roughness", "geometry", "mesh"),
                               realisations=1)
    chain = RunChain(get_parameter_values(), tmp_path / "out", options)
    result = chain.run()
    assert [r.status for r in result.stages if r.name in options.stages] == ["done"] * 3
    derived = nanoblock_geometry_from_profile(read_topography(scan))
    assert chain.model_params["atomic_height"] == derived.atomic_height
    assert chain.model_params["adhesive_width"] == derived.adhesive_width
    assert "derived from the scan" in chain.model_params.source("atomic_height")
    assert result.verdict["nanoblock_geometry"].startswith("from the meshing surface")
    # a scan whose geometry cannot be derived keeps the parameters' geometry, and the stage says why
    odd = options_for_test(roughness_files=(str(REPO / "data" / "afm" / "opdx-3.opdx"),), mesh_roughness=0,
                           stages=("roughness", "geometry"))
    fallback = RunChain(get_parameter_values(), tmp_path / "odd", odd)
    record = next(r for r in fallback.run().stages if r.name == "geometry")
    assert "could not be derived" in record.message and fallback.model_params is fallback.params
    # the default run keeps the parameter set's geometry
    default = RunChain(get_parameter_values(), tmp_path / "default", options_for_test(stages=("roughness", "geometry")))
    assert default.run().verdict["nanoblock_geometry"] == "parameters"


def test_run_refuses_a_non_empty_folder_and_overwrite_clears_stale_files(cli, tmp_path):
    out = tmp_path / "results"
    out.mkdir()
    (out / "report.html").write_text("stale")
    (out / "data").mkdir()
    (out / "data" / "old_stage.nc").write_text("stale")
    # an earlier run: its run.json lists what it wrote (--overwrite deletes only that, issue #41)
    (out / "run.json").write_text('{"stages": [{"name": "mesh", "files": ["data/old_stage.nc"]}]}')
    code, _, err = cli("run", "--out", out, "--set", "mesh_steps=5")
    assert code == 2 and "not empty" in err and "--overwrite" in err
    (out / "notes.txt").write_text("mine")
    code, _, err = cli("run", "--out", out, "--overwrite")
    assert code == 2 and "notes.txt" in err  # never deletes files that are not memstribo's
    (out / "notes.txt").unlink()
    config = tmp_path / "small.toml"
    config.write_text('[run]\nstages = ["gear"]\nvalidation = false\n')
    code, _, err = cli("run", config, "--out", out, "--overwrite", "--progress", "off")
    assert code == 0 and not (out / "data" / "old_stage.nc").exists()
    assert "stage 4/11 gear: done" in err  # one log line per stage off a terminal
    code, _, err = cli("run", config, "--out", tmp_path / "quiet", "--quiet", "--progress", "off")
    assert code == 0 and "stage" not in err


def test_run_exits_non_zero_when_a_stage_fails(cli, tmp_path, monkeypatch):
    from memstribo.errors import InputError as Bad

    def broken(self):
        raise Bad("the gear stage broke on purpose")

    monkeypatch.setattr(RunChain, "gear", broken)
    config = tmp_path / "small.toml"
    config.write_text('[run]\nstages = ["gear"]\nvalidation = false\n')
    values_code, out, err = cli("run", config, "--out", tmp_path / "out", "--json", "--progress", "off")
    import json

    values = json.loads(out)
    assert values_code == 1 and values["complete"] is False
    assert "broke on purpose" in values["failed_stages"]["gear"]


def test_run_checks_the_coating_before_the_first_stage():
    with pytest.raises(InputError, match="unknown coating"):
        RunOptions.from_table({"coating": "PTFE"})


def test_a_run_on_a_2d_map_shows_the_map_and_its_measured_rows(tmp_path):
    """#14: 'memstribo run' with a 2D map for the meshing cycle works end to end; the report shows the map
    and says which rows are measured and which synthesised."""
    from memstribo.parameters import get_parameter_values

    scan = REPO / "data" / "afm" / "di-3.di"
    options = options_for_test(roughness_files=(str(scan),), mesh_roughness=0,
                               stages=("roughness", "geometry", "gear", "mesh"), realisations=1)
    result = RunChain(get_parameter_values(), tmp_path / "out", options).run()
    assert all(r.status == "done" for r in result.stages if r.name in options.stages), result.stages
    assert (tmp_path / "out" / "figures" / "roughness_map_1.png").exists()
    rows = result.verdict["bare_roughness_rows"]
    assert "measured scan lines" in rows and "synthesised" in rows
    page = (tmp_path / "out" / "report.html").read_text(encoding="utf-8")
    assert "roughness_map_1" in page and "measured scan lines" in page


def test_run_takes_the_load_case(cli, tmp_path):
    config = tmp_path / "small.toml"
    config.write_text('[run]\nstages = ["roughness", "geometry", "mesh"]\nvalidation = false\nsteps = 11\n'
                      'realisations = 1\n')
    code, out, err = cli("run", config, "--out", tmp_path / "out", "--load-case", "thesis", "--json", "--progress",
                         "off")
    import json

    values = json.loads(out)
    assert code == 0 and values["load_case"] == "thesis"


def _same(a, b, path="run"):
    """Recursive equality of two JSON values, floats to 1e-9 relative."""
    if isinstance(a, dict) and isinstance(b, dict):
        assert set(a) == set(b), f"{path}: keys {sorted(set(a) ^ set(b))}"
        for key in a:
            _same(a[key], b[key], f"{path}.{key}")
    elif isinstance(a, list) and isinstance(b, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and isinstance(b, float):
        assert a == pytest.approx(b, rel=1e-9, abs=1e-300, nan_ok=True), path
    else:
        assert a == b, path


def test_resume_reruns_only_the_failed_stage_and_what_uses_it(params, tmp_path, monkeypatch):
    """#15: a stage fails; --resume reruns it and the stages that use it, reads the others back, and ends
    with the result of a clean run."""
    options = options_for_test(stages=("roughness", "geometry", "gear", "coated", "wear_sweep", "damage"),
                               realisations=1)
    clean = RunChain(params, tmp_path / "clean", options).run()
    assert clean.ok

    real_wear_sweep = RunChain.wear_sweep

    def broken(self):
        raise InputError("the wear sweep broke on purpose")

    monkeypatch.setattr(RunChain, "wear_sweep", broken)
    first = RunChain(params, tmp_path / "out", options).run()
    first_references = json.loads((tmp_path / "out" / "run.json").read_text())["references"]
    status = {s.name: s.status for s in first.stages}
    assert status["wear_sweep"] == "failed" and status["damage"] == "done"  # damage ran without the wear sweep

    calls = []
    for name in ("roughness", "geometry", "gear", "coated", "wear_sweep", "damage"):
        method = real_wear_sweep if name == "wear_sweep" else getattr(RunChain, name)

        def counted(self, _method=method, _name=name):
            calls.append(_name)
            return _method(self)

        monkeypatch.setattr(RunChain, name, counted)
    resumed = RunChain(params, tmp_path / "out", options, resume=True).run()
    assert calls == ["wear_sweep", "damage"]  # the damage stage uses the wear sweep: it runs again too
    assert resumed.kept == ["roughness", "geometry", "gear", "coated"]
    assert resumed.ok
    manifest = json.loads((tmp_path / "out" / "run.json").read_text())
    reference = json.loads((tmp_path / "clean" / "run.json").read_text())
    _same(manifest["verdict"], reference["verdict"])
    _same(manifest["summaries"], reference["summaries"])
    assert [f["stem"] for f in manifest["figures"]] == [f["stem"] for f in reference["figures"]]
    # the kept stages' references stay (a cached model function cites only on its first call in a process, so the
    # rerun stages' references can be fewer than a fresh process's: compare as sets)
    earlier = json.loads((tmp_path / "clean" / "run.json").read_text())["references"]
    assert set(first_references) <= set(manifest["references"]) <= set(earlier)
    assert [s["status"] for s in manifest["stages"]] == [s["status"] for s in reference["stages"]]
    for record in resumed.stages:
        for file in record.files:
            assert (tmp_path / "out" / file).is_file(), file
    assert (tmp_path / "out" / "report.html").is_file()
    # a resume of a complete run recomputes nothing
    calls.clear()
    assert RunChain(params, tmp_path / "out", options, resume=True).run().ok and calls == []


def test_cli_resume_errors(cli, tmp_path):
    code, _, err = cli("run", "--out", tmp_path / "nothing", "--resume")
    assert code == 2 and "no run.json" in err and "Traceback" not in err
    code, _, err = cli("run", "--out", tmp_path / "nothing", "--resume", "--overwrite")
    assert code == 2 and "--resume and --overwrite" in err
    config = tmp_path / "small.toml"
    config.write_text('[run]\nstages = ["gear"]\nvalidation = false\n')
    code, out, _ = cli("run", config, "--out", tmp_path / "out", "--progress", "off", "--quiet")
    assert code == 0
    values = cli.json("run", config, "--out", tmp_path / "out", "--resume", "--progress", "off", "--quiet")
    assert values["kept_stages"] == ["gear"] and values["complete"] is True
    other = tmp_path / "other.toml"
    other.write_text('[run]\nstages = ["gear", "roughness"]\nvalidation = false\n')
    code, _, err = cli("run", other, "--out", tmp_path / "out", "--resume", "--progress", "off")
    assert code == 2 and "other options (stages)" in err
    code, _, err = cli("run", config, "--out", tmp_path / "out", "--resume", "--set", "normal_load=50 uN")
    assert code == 2 and "other parameters (normal_load)" in err


def test_resume_after_a_kill_runs_the_unfinished_stages(params, tmp_path, monkeypatch):
    """Ctrl-C (or a kill) in the coated stage: run.json says 'pending' for it; --resume runs it and keeps the rest."""
    options = options_for_test(stages=("roughness", "gear", "coated"), realisations=1)

    def interrupt(self):
        raise KeyboardInterrupt

    real_coated = RunChain.coated
    monkeypatch.setattr(RunChain, "coated", interrupt)
    with pytest.raises(KeyboardInterrupt):
        RunChain(params, tmp_path / "out", options).run()
    monkeypatch.setattr(RunChain, "coated", real_coated)
    resumed = RunChain(params, tmp_path / "out", options, resume=True).run()
    assert resumed.kept == ["roughness", "gear"] and resumed.ok
    assert (tmp_path / "out" / "data" / "mesh_coated.nc").is_file()
    assert resumed.verdict["coated_stiction_margin"] == resumed.summaries["coated"]["stiction_margin"]


def test_a_run_in_air_adds_the_humid_air_section_and_a_vacuum_run_does_not(tmp_path):
    """Issue #17: in air the run sweeps the humidity (bare and coated), draws COF, capillary part and margin
    versus RH with the critical humidity, and the report gains a section; the default (vacuum) run is unchanged."""
    from memstribo.job.chain import HUMIDITY_VALUES
    from memstribo.parameters import get_parameter_values

    options = options_for_test(stages=("gear",), validation=False)
    vacuum = RunChain(get_parameter_values(), tmp_path / "vacuum", options).run()
    assert "humidity" not in vacuum.summaries and all(s.name != "humidity" for s in vacuum.stages)
    assert "Humid air" not in (tmp_path / "vacuum" / "report.html").read_text(encoding="utf-8")
    air = get_parameter_values().updated({"environment": "air", "relative_humidity": 0.5})
    run = RunChain(air, tmp_path / "air", options).run()
    record = next(s for s in run.stages if s.name == "humidity")
    assert record.status == "done", record.message
    humidity = run.summaries["humidity"]
    assert humidity["relative_humidity"] == list(HUMIDITY_VALUES)
    for label in ("bare", "coated"):
        part = humidity[label]
        assert len(part["cof_mean"]) == len(HUMIDITY_VALUES) and part["cof_capillary"][0] == 0.0
        assert part["critical_humidity"] is None or 0.0 <= part["critical_humidity"] <= 0.9
        assert part["critical_humidity_note"]
    assert max(humidity["bare"]["cof_capillary"]) > 0
    assert (tmp_path / "air" / "figures" / "humidity_cof_margin.png").exists()
    assert (tmp_path / "air" / "data" / "humidity_sweep.json").exists()
    html = (tmp_path / "air" / "report.html").read_text(encoding="utf-8")
    assert "Humid air: capillary adhesion and the critical humidity" in html and "humidity_cof_margin" in html
    assert run.ok  # the extra section is not a requested stage: it does not change the run's status


def test_the_run_says_what_its_verdict_hangs_on(small_run):
    """The uncertainty stage (MODEL 7d): a probability with its interval, the ranked constants, their figures, and
    the box under the verdict in the report."""
    summary = small_run.summaries["uncertainty"]
    low, high = summary["stiction_probability_ci"]
    assert low <= summary["stiction_probability"] <= high and 0 <= low < high <= 1
    assert summary["samples"] == 4
    assert summary["summary"].startswith("P(stiction) = ") and "95 % CI" in summary["summary"]
    stems = {f.stem for f in small_run.figures if f.stage == "uncertainty"}
    assert "uncertainty_sensitivity" in stems
    page = (small_run.folder / "report.html").read_text(encoding="utf-8")
    assert "id='uncertainty'" in page and "95 % CI" in page


def test_no_uncertainty_samples_leaves_the_stage_out():
    options = RunOptions.from_table({"uncertainty": 0})
    assert "uncertainty" not in options.stages and "mesh" in options.stages


def test_the_report_shows_stiction_coating_life_and_fracture_life_together(small_run):
    """MODEL §10: the damage stage draws the fracture probability over the meshing cycles beside the coating's life,
    from the coated cycle's tooth strength."""
    assert "lives" in {f.stem for f in small_run.figures if f.stage == "damage"}
    damage = small_run.summaries["damage"]
    assert 0 < damage["fracture_probability"] < 1
    page = (small_run.folder / "report.html").read_text(encoding="utf-8")
    assert "Lives of the coated pair" in page
