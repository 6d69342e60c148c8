"""Design maps (`memstribo map`): spec validation, dimensions, resume, Dask scheduler, figures, CLI."""

from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from memstribo.simulations.design_map import design_map, load_map_spec, map_spec
from memstribo.errors import InputError

ROOT = Path(__file__).resolve().parents[1]

TINY = """\
[map]
name = "tiny"
realisations = 2
steps = 11
plot = ["drive_torque", "face_width"]

[map.grid]
drive_torque = ["5e-8 N*m", "2e-7 N*m"]
face_width = {start = "1 um", stop = "3 um", num = 2}
"""


@pytest.fixture(scope="module")
def client():
    """One local Dask cluster (2 processes) for the tests of this module."""
    from distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster, set_as_default=False)
    yield client
    client.close()
    cluster.close()


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def tiny_map(tmp_path_factory, client):
    """The tiny map computed once on the shared cluster: (spec, result)."""
    folder = tmp_path_factory.mktemp("tiny")
    spec = load_map_spec(write(folder / "spec.toml", TINY))
    return spec, design_map(spec, folder / "out", client=client)


# --- spec ---------------------------------------------------------------------------------------------

def test_spec_axes_units_and_defaults(tmp_path):
    spec = load_map_spec(write(tmp_path / "s.toml", TINY))
    assert spec.dims == ("drive_torque", "face_width")
    assert spec.shape == (2, 2)
    assert spec.realisations == 2 and spec.steps == 11
    assert spec.axes[1][1] == pytest.approx([1e-6, 3e-6])
    default = map_spec({"grid": {"module": ["3 um", "4 um"], "coating": ["none", "OTS"]}})
    assert default.realisations == 4
    assert default.plot == ("module",)  # the numeric axes only


@pytest.mark.parametrize("table, message", [
    ({"grid": {"drive_torque": [1e-7]}, "realisation": 2}, "Did you mean .realisations."),
    ({"grid": {}}, "no axes"),
    ({"grid": {"face_width": ["2 um"]}, "fixed": {"face_width": "3 um"}}, "both in"),
    ({"grid": {"face_width": ["2 um", "3 um"]}, "plot": ["module"]}, "plot axis"),
    ({"grid": {"face_width": ["2 um", "3 um"]}, "realisations": 0}, "realisations"),
    ({"grid": {"face_width": ["2 um", "3 um"]}, "wear_sweep": [0.5]}, "wear_sweep"),
    ({"grid": {"face_width": {"start": 1e-6, "stop": 2e-6}}}, "start, stop, num"),
])
def test_spec_errors(table, message):
    with pytest.raises(InputError, match=message):
        map_spec(table)


def test_spec_file_errors(tmp_path):
    with pytest.raises(InputError, match="no \\[map\\] table"):
        load_map_spec(write(tmp_path / "a.toml", "[parameters]\nmodule = '4 um'\n"))
    with pytest.raises(InputError, match="\\[map\\] and \\[parameters\\] only"):
        load_map_spec(write(tmp_path / "b.toml", TINY + "\n[study]\nname = 'x'\n"))
    spec = load_map_spec(write(tmp_path / "c.toml", TINY.replace("[map.grid]", "[map.grid]\nfrobnicate = [1, 2]")))
    with pytest.raises(InputError, match="unknown key 'frobnicate'"):
        design_map(spec, tmp_path / "out", workers=1)  # every point is checked before anything runs


# --- the map ------------------------------------------------------------------------------------------

def test_map_has_one_dimension_per_axis(tiny_map):
    import xarray as xr

    spec, result = tiny_map
    ds = result.dataset
    assert result.n_points == 4 and result.n_computed == 4 and result.n_failed == 0
    assert ds["stiction_probability"].dims == ("drive_torque", "face_width")
    assert ds["drive_torque"].values == pytest.approx([5e-8, 2e-7])
    assert ds["drive_torque"].attrs["units"] == "N*m"
    for key in ("stiction_probability", "stiction_margin_median", "stiction_margin_p05", "stiction_margin_p95",
                "cof_mean_median", "cof_mean_p05", "cof_mean_p95", "mesh_efficiency_median"):
        assert np.isfinite(ds[key].values).all(), key
    assert ((ds["stiction_probability"] >= 0) & (ds["stiction_probability"] <= 1)).all()
    assert (ds["stiction_margin_p05"] <= ds["stiction_margin_p95"]).all()
    assert np.isnan(ds["cycles_to_failure"].values).all()  # bare silicon: no coating life
    with xr.open_dataset(result.folder / "map.nc") as disk:
        assert disk["stiction_probability"].dims == ("drive_torque", "face_width")
        assert disk.attrs["Conventions"] == "CF-1.8"
        assert disk.attrs["stage"] == "design map"
        assert json.loads(disk.attrs["map_axes"]) == ["drive_torque", "face_width"]
        assert json.loads(disk.attrs["parameters"])["realisations"]["value"] == 2
        assert disk["stiction_margin_median"].attrs["units"] == "N"
        np.testing.assert_array_equal(disk["stiction_probability"].values, ds["stiction_probability"].values)
    csv = (result.folder / "map.csv").read_text(encoding="utf-8")
    assert "stiction_probability" in csv and "drive_torque [" in csv
    stems = {p.name for p in result.figures}
    assert {"design_map_stiction.png", "design_map_stiction.svg", "design_map_efficiency.png"} <= stems


def test_point_equals_ensemble(tiny_map):
    """A map point is the ensemble verdict of mesh.simulate_ensemble with the same inputs."""
    from memstribo.simulations import mesh
    from memstribo.parameters import get_parameter_values

    spec, result = tiny_map
    params = get_parameter_values().updated({"drive_torque": 2e-7, "face_width": 1e-6, "realisations": 2})
    ensemble = mesh.simulate_ensemble(params, steps=11)
    point = result.dataset.isel(drive_torque=1, face_width=0)
    for key in ("stiction_probability", "stiction_margin_median", "cof_mean_p95", "mesh_efficiency_median"):
        assert float(point[key]) == ensemble[key], key


def test_resume_loses_nothing_and_reruns_failed(tiny_map, client, tmp_path):
    spec, result = tiny_map
    folder = tmp_path / "out"
    shutil.copytree(result.folder, folder)
    with pytest.raises(InputError, match="--resume"):
        design_map(spec, folder, client=client)
    (folder / "map.nc").unlink()
    files = sorted((folder / "points").glob("*.json"))
    files[0].unlink()
    files[3].unlink()
    failed = json.loads(files[1].read_text())
    failed.update(values={}, error="SimulatedError: worker lost")  # as a failed point is recorded
    files[1].write_text(json.dumps(failed))
    (folder / "points" / (files[2].name + ".tmp")).write_text("{torn")  # a write cut short by kill -9
    again = design_map(spec, folder, client=client, resume=True, figures=False)
    assert (again.n_computed, again.n_reused, again.n_retried, again.n_failed) == (3, 1, 1, 0)
    assert again.dataset.equals(result.dataset)
    assert not list((folder / "points").glob("*.tmp"))
    other = load_map_spec(write(tmp_path / "other.toml", TINY.replace("num = 2", "num = 3")))
    with pytest.raises(InputError, match="different map"):
        design_map(other, folder, client=client, resume=True)


def test_a_corrupted_point_file_is_computed_again_on_resume(tiny_map, client, tmp_path):
    """#29: a finished point file later damaged is computed again on resume; the others are reused."""
    spec, result = tiny_map
    folder = tmp_path / "out"
    shutil.copytree(result.folder, folder)
    (folder / "map.nc").unlink()
    files = sorted((folder / "points").glob("*.json"))
    files[0].write_bytes(b"\x00garbage{")
    again = design_map(spec, folder, client=client, resume=True, figures=False)
    assert (again.n_computed, again.n_reused, again.n_failed) == (1, len(files) - 1, 0)
    assert again.dataset.equals(result.dataset)


def test_coated_points_get_a_coating_life(client, tmp_path):
    spec = map_spec({"realisations": 1, "steps": 11, "cycles_observed": 1e6, "wear_sweep": [0.0, 1.0],
                     "grid": {"coating": ["none", "OTS"]}})
    result = design_map(spec, tmp_path / "out", client=client)
    ds = result.dataset
    assert ds["stiction_probability"].dims == ("coating",)
    assert list(ds["coating"].values) == ["none", "OTS"]
    assert np.isnan(float(ds["cycles_to_failure"].sel(coating="none")))
    assert float(ds["cycles_to_failure"].sel(coating="OTS")) == pytest.approx(1e6)  # calibrated on it
    assert result.figures == [] and any("no figure" in n for n in result.notes)
    unknown = design_map(map_spec({"realisations": 1, "steps": 11, "grid": {"coating": ["OTS"]}}),
                         tmp_path / "unknown", client=client)
    assert np.isnan(unknown.dataset["cycles_to_failure"].values).all()
    assert "coating life unknown" in str(unknown.dataset["note"].values[0])


def test_cli_map(tmp_path):
    from memstribo.cli.main import main

    spec = write(tmp_path / "spec.toml", TINY.replace('face_width = {start = "1 um", stop = "3 um", num = 2}',
                                                      'face_width = ["2 um"]').replace(
        'plot = ["drive_torque", "face_width"]', 'plot = ["drive_torque"]'))
    out = tmp_path / "out"
    code = main(["map", str(spec), "--out", str(out), "--workers", "1", "--progress", "off", "--json"])
    assert code == 0
    assert (out / "map.nc").is_file() and (out / "figures" / "design_map_stiction.png").is_file()
    assert main(["map", str(spec), "--out", str(out), "--workers", "1", "--progress", "off", "--resume"]) == 0
    assert main(["map", str(tmp_path / "missing.toml")]) == 2


# --- a real Dask cluster: scheduler and workers as processes ------------------------------------------------

def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_scheduler_and_two_workers_give_the_local_result_bit_for_bit(tiny_map, tmp_path):
    from distributed import Client

    spec, local = tiny_map
    dask = [sys.executable, "-m", "distributed.cli.dask_scheduler"]
    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = {**os.environ, "PYTHONWARNINGS": "ignore"}
    processes = [subprocess.Popen(dask + ["--host", "127.0.0.1", "--port", str(port), "--no-dashboard"],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)]
    try:
        for _ in range(2):
            processes.append(subprocess.Popen(
                [sys.executable, "-m", "distributed.cli.dask_worker", address, "--nthreads", "1",
                 "--no-dashboard", "--host", "127.0.0.1"],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env))
        with Client(address, timeout="30s", set_as_default=False) as client:
            client.wait_for_workers(2, timeout=60)
            assert len(client.scheduler_info()["workers"]) == 2
        remote = design_map(spec, tmp_path / "out", scheduler=address, figures=False)
    finally:
        for process in reversed(processes):
            process.terminate()
        for process in processes:
            try:
                process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait(timeout=10)
    for name in local.dataset.data_vars:
        np.testing.assert_array_equal(remote.dataset[name].values, local.dataset[name].values, err_msg=name)
    hosts = {json.loads(p.read_text())["pid"] for p in (tmp_path / "out" / "points").glob("*.json")}
    assert os.getpid() not in hosts


# --- the worked example ------------------------------------------------------------------------------------

def test_example_runs_at_tiny_size(tmp_path):
    env = {**os.environ, "PYTHONWARNINGS": "error::RuntimeWarning"}
    started = time.perf_counter()
    run = subprocess.run([sys.executable, str(ROOT / "examples" / "design_map_example.py"), "--tiny",
                          "--out", str(tmp_path)], capture_output=True, text=True, env=env, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    assert (tmp_path / "figures" / "design_map_stiction.png").is_file()
    assert time.perf_counter() - started < 120


# --- memstribo study: a grid also comes back with one dimension per swept key --------------------------------

def test_study_grid_has_one_dimension_per_key(tmp_path):
    import xarray as xr

    from memstribo.simulations.study import run_study, study_spec

    spec = study_spec({"function": "gear", "grid": {"module": ["3 um", "4 um", "5 um"], "face_width": ["2 um", "3 um"]}})
    assert spec.grid == ("module", "face_width")
    result = run_study(spec, tmp_path / "out", workers=1)
    assert result.n_failed == 0, result.errors
    with xr.open_dataset(tmp_path / "out" / "results_grid.nc") as grid:
        assert grid["module"].values == pytest.approx([3e-6, 4e-6, 5e-6])
        assert grid["result_module"].values == pytest.approx(np.repeat([[3e-6], [4e-6], [5e-6]], 2, axis=1))
        key = "contact_ratio"
        assert grid[key].dims == ("module", "face_width")
        flat = result.dataset[key].values
        np.testing.assert_array_equal(grid[key].values.ravel(), flat)
        assert float(grid[key].sel(module=4e-6, face_width=3e-6)) == flat[3]
    assert (tmp_path / "out" / "results.nc").is_file()  # the point table stays as it was
    listed = study_spec({"function": "gear", "grid": {"module": ["3 um"]}, "points": [{"module": "4 um"}]})
    assert listed.grid == ()


def test_kill_9_then_resume_loses_no_finished_point(tmp_path):
    """A real `memstribo map` process group is killed with SIGKILL part-way, then resumed."""
    import signal

    spec = write(tmp_path / "s.toml", TINY.replace('face_width = {start = "1 um", stop = "3 um", num = 2}',
                                                   'face_width = ["1 um", "2 um", "3 um", "4 um"]'))
    out = tmp_path / "out"
    command = [sys.executable, "-m", "memstribo.cli.main", "map", str(spec), "--out", str(out), "--workers", "1",
               "--progress", "off"]
    process = subprocess.Popen(command, start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    points = out / "points"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and len(list(points.glob("*.json"))) < 2:
        time.sleep(0.02)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait(timeout=30)
    before = {p.name: p.read_text() for p in points.glob("*.json")}
    assert 2 <= len(before) < 8, "the map should have been killed part-way"
    assert not (out / "map.nc").exists()
    resumed = subprocess.run(command + ["--resume", "--json"], capture_output=True, text=True, timeout=120)
    assert resumed.returncode == 0, resumed.stderr
    summary = json.loads(resumed.stdout)
    assert (summary["points"], summary["reused"], summary["computed"]) == (8, len(before), 8 - len(before))
    after = {p.name: p.read_text() for p in points.glob("*.json")}
    assert len(after) == 8 and all(after[name] == text for name, text in before.items())


def test_figures_coating_life_and_one_axis(tmp_path):
    """Coating life gets its own contour where known; one plot axis gives line plots."""
    from memstribo.simulations.design_map import MAP_RESULTS, map_dataset, map_figures

    spec = map_spec({"grid": {"drive_torque": ["5e-8 N*m", "1e-7 N*m", "2e-7 N*m"], "face_width": ["1 um", "2 um"]}})
    records = []
    for i in range(6):
        values = {key: 0.5 for key in MAP_RESULTS}
        values.update(stiction_probability=i / 5, cycles_to_failure=10.0 ** (6 + i), note="")
        records.append({"id": f"p{i}", "values": values, "error": None})
    dataset = map_dataset(records, spec)
    assert dataset["cycles_to_failure"].dims == ("drive_torque", "face_width")
    written, notes = map_figures(dataset, tmp_path / "two", ["drive_torque", "face_width"])
    assert {p.name for p in written} >= {"design_map_stiction.png", "design_map_coating_life.svg"} and not notes
    written, _ = map_figures(dataset, tmp_path / "one", ["face_width"])
    assert (tmp_path / "one" / "design_map_efficiency.png").is_file()


# --- references: the models used on the workers reach map.nc and the study's files ---------------------------

def test_map_nc_cites_the_models_its_points_used(client, tmp_path):
    """The @cites registry fills in the worker processes; each point brings its keys back to map.nc."""
    import xarray as xr

    from memstribo.references import reset_used_references, used_references

    reset_used_references()  # nothing cited in this (the client's) process
    spec = map_spec({"realisations": 1, "steps": 11, "grid": {"drive_torque": ["1e-7 N*m", "2e-7 N*m"]}})
    result = design_map(spec, tmp_path / "out", client=client, figures=False)
    records = [json.loads(p.read_text()) for p in (tmp_path / "out" / "points").glob("*.json")]
    assert all("polonsky_keer_1999" in r["references"] and "thesis" in r["references"] for r in records)
    assert {r["pid"] for r in records} != {os.getpid()}  # computed elsewhere
    with xr.open_dataset(result.folder / "map.nc") as disk:
        cited = disk.attrs["models_cited"]
    assert cited != "none recorded"
    assert {"thesis", "polonsky_keer_1999", "johnson_1985"} <= set(cited.split(", "))
    assert "polonsky_keer_1999" in dict(used_references())  # and the client's record (references.txt of a run)


def test_study_files_cite_the_models_their_points_used(tmp_path):
    import xarray as xr

    from memstribo.references import reset_used_references
    from memstribo.simulations.study import run_study, study_spec

    reset_used_references()
    spec = study_spec({"function": "mesh", "points": [{"steps": 11}]})
    result = run_study(spec, tmp_path / "out", workers=1)
    assert result.n_failed == 0, result.errors
    with xr.open_dataset(tmp_path / "out" / "results.nc") as disk:
        cited = disk.attrs["models_cited"]
    assert cited != "none recorded" and "polonsky_keer_1999" in cited.split(", ")


def test_collect_references_per_block_and_nested():
    from memstribo.references import cites, collect_references, record_references, used_references

    first = cites("thesis")(lambda: 1)
    second = cites("johnson_1985", "model")(lambda: 2)
    with collect_references() as outer:
        first()
        with collect_references() as inner:
            second()
        assert list(inner) == ["johnson_1985", "model"]
    assert list(outer) == ["thesis", "johnson_1985", "model"]
    second()
    assert list(outer) == ["thesis", "johnson_1985", "model"]  # closed: no longer filled
    record_references(["hu_1986"])
    assert "hu_1986" in dict(used_references())
    with pytest.raises(KeyError, match="unknown reference"):
        record_references(["no_such_paper"])


# --- the local cluster: quiet when another cluster holds the dashboard port -------------------------------------

def test_local_cluster_warns_nothing_when_port_8787_is_taken(capfd):
    """distributed's scheduler starts an HTTP server even with dashboard_address=None, by default on
    port 8787, and warns 'Port 8787 is already in use' when another cluster holds it."""
    import warnings

    from memstribo.simulations.study import _connect

    holder = socket.socket()
    try:
        holder.bind(("0.0.0.0", 8787))  # as another cluster's dashboard would
        holder.listen()
    except OSError:
        pass  # already held by someone else: the same situation
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            client, cluster = _connect(None, 1)
            try:
                assert client.submit(abs, -3, pure=False).result(timeout=60) == 3
            finally:
                client.close()
                cluster.close()
    finally:
        holder.close()
    messages = [str(w.message) for w in caught] + [capfd.readouterr().err]
    assert not [m for m in messages if "already in use" in m], messages


# --- `memstribo run` with [run] map: the map as the last stage, and its section of report.html ------------------

def test_run_with_a_map_spec_writes_the_map_and_its_report_section(tmp_path):
    import xarray as xr

    from memstribo.cli.main import main

    write(tmp_path / "tiny-map.toml", TINY)
    config = write(tmp_path / "run.toml", '[run]\nstages = ["gear"]\nvalidation = false\nmap = "tiny-map.toml"\n')
    out = tmp_path / "out"
    assert main(["run", str(config), "--out", str(out), "--quiet", "--progress", "off"]) == 0
    manifest = json.loads((out / "run.json").read_text())
    stages = {s["name"]: s for s in manifest["stages"]}
    assert stages["design_map"]["status"] == "done" and stages["gear"]["status"] == "done"
    assert "map/map.nc" in stages["design_map"]["files"]
    from memstribo.job.folder import _all_files, owned_files

    # run.json lists every file the run wrote, the map's points included: --overwrite can clear it (#41)
    assert set(_all_files(out)) <= set(owned_files(out, manifest, "--overwrite"))
    summary = manifest["summaries"]["design_map"]
    assert (summary["points"], summary["computed"], summary["realisations"]) == (4, 4, 2)
    with xr.open_dataset(out / "map" / "map.nc") as disk:
        assert disk["stiction_probability"].dims == ("drive_torque", "face_width")
        assert "polonsky_keer_1999" in disk.attrs["models_cited"]
        probability = disk["stiction_probability"].values
    assert summary["points_sticking"] == int((probability >= 0.5).sum())
    assert (out / "figures" / "design_map_stiction.png").is_file()
    assert (out / "figures" / "design_map_efficiency.svg").is_file()
    report = (out / "report.html").read_text()
    section = report[report.index("<h2>Design map</h2>"):report.index("<h2>Stages</h2>")]
    assert "id='fig-design_map_stiction'" in section and "id='fig-design_map_efficiency'" in section
    assert "50 % boundary" in section and "4 designs" in section
    assert report.count("id='fig-design_map_stiction'") == 1  # not also among the other figures
    assert "polonsky_keer_1999" in (out / "references.txt").read_text()  # cited on the map's workers
    # resumable: the finished points are read back, not computed again
    before = {p.name: p.read_text() for p in (out / "map" / "points").glob("*.json")}
    assert main(["run", str(config), "--out", str(out), "--resume", "--quiet", "--progress", "off"]) == 0
    again = json.loads((out / "run.json").read_text())["summaries"]["design_map"]
    assert (again["computed"], again["reused"]) == (0, 4)
    assert {p.name: p.read_text() for p in (out / "map" / "points").glob("*.json")} == before


def test_run_without_a_map_has_no_map_stage_and_a_bad_map_stops_before_the_first_stage(tmp_path):
    from memstribo.job.options import STAGES, RunOptions
    from memstribo.cli.main import main
    from memstribo.job.report import _design_map_html

    assert "design_map" not in STAGES and RunOptions().map is None
    config = write(tmp_path / "run.toml", '[run]\nstages = ["gear"]\nvalidation = false\n')
    assert main(["run", str(config), "--out", str(tmp_path / "plain"), "--quiet"]) == 0
    manifest = json.loads((tmp_path / "plain" / "run.json").read_text())
    assert [s["name"] for s in manifest["stages"]] == list(STAGES)
    assert "Design map" not in (tmp_path / "plain" / "report.html").read_text()
    with pytest.raises(InputError, match="does not exist"):
        RunOptions.from_table({"map": "missing.toml"}, tmp_path)
    write(tmp_path / "bad.toml", TINY.replace("realisations = 2", "realisation = 2"))
    with pytest.raises(InputError, match="\\[run\\] map: .*realisations"):
        RunOptions.from_table({"map": "bad.toml"}, tmp_path)
    bad = write(tmp_path / "bad-run.toml", '[run]\nstages = ["gear"]\nmap = "bad.toml"\n')
    assert main(["run", str(bad), "--out", str(tmp_path / "never")]) == 2
    assert not (tmp_path / "never" / "run.json").exists()
    assert _design_map_html(type("R", (), {"stages": []})()) == ""


def test_longest_points_are_submitted_first():
    """Task order by cost (rows x steps x cycles): the map's tail is short points, not one long one."""
    import functools

    from memstribo.simulations.design_map import _point_cost, _study_of, map_point
    from memstribo.parameters import get_parameter_values
    from memstribo.simulations.study import prepare_points

    spec = map_spec({"realisations": 2, "grid": {"face_width": ["1 um", "4 um"], "coating": ["none", "OTS"]}})
    points = prepare_points(_study_of(spec), get_parameter_values())
    plain = functools.partial(map_point, cycles_observed=None, wear_sweep=[0.0, 1.0])
    life = functools.partial(map_point, cycles_observed=1e6, wear_sweep=[0.0, 1.0])
    costs = [_point_cost(p, plain) for p in points]  # (1 um, none), (1 um, OTS), (4 um, none), (4 um, OTS)
    assert costs[0] == costs[1] < costs[2] == costs[3]
    assert costs[2] / costs[0] == (4e-6 // 195.5e-9) / (1e-6 // 195.5e-9)
    # 2 realisations + the worn state 1 of the coating life (state 0 is the point's own: its first cycle)
    assert _point_cost(points[1], life) == costs[1] * 1.5


def test_report_section_while_the_map_runs_and_when_it_failed():
    from types import SimpleNamespace

    from memstribo.job.options import MAP_STAGE, StageRecord
    from memstribo.job.report import _design_map_html

    record = StageRecord(*MAP_STAGE)
    pending = _design_map_html(SimpleNamespace(stages=[record], summaries={}, figures=[]))
    assert "<h2>Design map</h2>" in pending and "runs after the other stages" in pending
    record.status, record.message = "failed", "InputError: <bad> spec"
    failed = _design_map_html(SimpleNamespace(stages=[record], summaries={}, figures=[]))
    assert "did not finish" in failed and "&lt;bad&gt;" in failed and "<bad>" not in failed


def test_coated_point_reuses_its_first_cycle_in_the_wear_sweep(monkeypatch):
    """The point's realisation-0 cycle is the wear sweep's state at its own wear: computed once, same numbers."""
    from memstribo.simulations import coating_wear as coating
    from memstribo.simulations import mesh
    from memstribo.simulations.design_map import map_point
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values().updated({"realisations": 2})
    calls = []
    simulate = mesh.simulate_mesh

    def counting(*args, **kwargs):
        calls.append(kwargs.get("wear"))
        return simulate(*args, **kwargs)

    monkeypatch.setattr(mesh, "simulate_mesh", counting)
    reused = map_point(params, "OTS", 0.0, steps=11, cycles_observed=1e6, wear_sweep=[0.0, 0.5, 1.0])
    assert len(calls) == 2 + 3 - 1  # 2 realisations, 3 worn states, one of them the first realisation
    sweep = coating.wear_sweep
    monkeypatch.setattr(coating, "wear_sweep", lambda *a, known=None, **k: sweep(*a, **k))  # compute every state
    calls.clear()
    fresh = map_point(params, "OTS", 0.0, steps=11, cycles_observed=1e6, wear_sweep=[0.0, 0.5, 1.0])
    assert len(calls) == 2 + 3
    assert reused.keys() == fresh.keys()
    for key in reused:
        assert reused[key] == fresh[key] or (reused[key] != reused[key] and fresh[key] != fresh[key]), key
