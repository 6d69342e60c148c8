"""Studies on dask.distributed: spec expansion, determinism across schedulers, resume after kill -9."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import _study_points
from memstribo.errors import InputError
from memstribo.simulations.study import POINT_FUNCTIONS, load_study_spec, prepare_points, run_study, study_spec

TESTS = Path(__file__).resolve().parent
#: through the Python API a study runs any module-level function; spec files name registered ones ("hertz")
HERTZ = _study_points.hertz_point

#: `memstribo study` in a subprocess that first registers the test function as "hertz" (Python API)
CLI_WITH_HERTZ = ("import sys, _study_points; from memstribo.simulations.study import register_point_function; "
                  "register_point_function('hertz', _study_points.hertz_point); "
                  "from memstribo.cli.main import main; sys.exit(main(sys.argv[1:]))")


@pytest.fixture(autouse=True)
def _workers_find_test_functions(monkeypatch):
    """Dask worker processes import the test point functions from tests/ (spawned, via PYTHONPATH);
    spec files name the test function "hertz" (registered for the test only)."""
    monkeypatch.syspath_prepend(str(TESTS))
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(TESTS), os.environ.get("PYTHONPATH", "")]))
    monkeypatch.setitem(POINT_FUNCTIONS, "hertz", _study_points.hertz_point)


def write_spec(path: Path, body: str) -> Path:
    path.write_text(body, encoding="utf-8")
    return path


# --- spec ----------------------------------------------------------------------------------------

def test_grid_is_the_product_in_written_order_and_fixed_applies_to_all():
    spec = study_spec({"function": HERTZ, "fixed": {"module": "4 um"},
                       "grid": {"normal_load": ["25 uN", "50 uN"], "seed": [1, 2, 3]},
                       "points": [{"normal_load": "75 uN"}]})
    assert len(spec.points) == 2 * 3 + 1
    assert [p["seed"] for p in spec.points[:3]] == [1, 2, 3]
    assert [p["normal_load"] for p in spec.points[::3]] == ["25 uN", "50 uN", "75 uN"]
    assert all(p["module"] == "4 um" for p in spec.points)


def test_range_table_is_linspace_in_si(params):
    spec = study_spec({"function": HERTZ, "grid": {"normal_load": {"start": "25 uN", "stop": "300 uN", "num": 12}}})
    loads = [p["normal_load"] for p in spec.points]
    np.testing.assert_allclose(loads, np.arange(25, 301, 25) * 1e-6, rtol=1e-12)
    points = prepare_points(spec, params)
    assert points[-1].params["normal_load"] == pytest.approx(300e-6, rel=1e-12)


def test_point_ids_are_stable_and_distinct(params):
    spec = study_spec({"function": HERTZ, "grid": {"seed": [1, 2]}})
    first, again = prepare_points(spec, params), prepare_points(spec, params)
    assert [p.id for p in first] == [p.id for p in again]
    assert len({p.id for p in first}) == 2
    assert first[1].params["roughness_seed"] == 2


@pytest.mark.parametrize("study, match", [
    ({"function": HERTZ}, "no points"),
    ({"function": HERTZ, "grid": {"normal_lod": ["25 uN"]}}, "unknown key 'normal_lod'.*normal_load"),
    ({"function": HERTZ, "grid": {"normal_load": []}}, "empty list"),
    ({"function": HERTZ, "grid": {"normal_load": ["-5 uN"]}}, "study point 0.*outside its range"),
    ({"function": HERTZ, "grid": {"normal_load": {"start": 1, "stop": 2}}}, "start, stop, num"),
    ({"function": HERTZ, "grid": {"wear": [1.5]}, "fixed": {"coating": "OTS"}}, "outside 0 to 1"),
    ({"function": HERTZ, "grid": {"wear": [0.5]}}, "needs a coating"),
    ({"function": HERTZ, "grid": {"roughness": ["no/such/file.txt"]}}, "does not exist"),
    ({"function": HERTZ, "grid": {"steps": [1]}}, "integer >= 2"),
    ({"function": HERTZ, "grid": {"seed": [1]}, "grdi": {}}, "unknown key.*grdi"),
    ({"function": HERTZ, "grid": {"normal_load": [["25 uN"]]}}, "not a list"),
    ({"function": HERTZ, "grid": {"normal_load": {"start": 1, "stop": 2, "num": 10**6}}}, "num = an integer"),
    ({"function": HERTZ, "grid": {"seed": list(range(1000)), "module": list(range(1000))}}, "1,000,000 points"),
    ({"function": HERTZ, "grid": {"seed": [1]}, "fixed": {"coating": "OST"}}, "unknown coating 'OST'.*OTS"),
    ({"function": HERTZ, "grid": {"seed": [1]}, "name": 5}, "name must be a short text"),
    ({"function": HERTZ, "grid": {"seed": [1]}, "fixed": ["x"]}, "must be tables"),
    ({"function": HERTZ, "grid": {"steps": [10**7]}}, "<= 100000"),
])
def test_bad_specs_raise_input_error(params, study, match):
    with pytest.raises(InputError, match=match):
        prepare_points(study_spec(study), params)


def test_unknown_point_function_is_an_input_error(params, tmp_path):
    with pytest.raises(InputError, match="unknown point function 'mseh'.*mesh"):
        study_spec({"function": "mseh", "grid": {"seed": [1]}})
    with pytest.raises(InputError, match="unknown point function 'no_such_module:f'.*never code to import"):
        study_spec({"function": "no_such_module:f", "grid": {"seed": [1]}})


def test_spec_file_cannot_import_code(cli, tmp_path, monkeypatch):
    """A data file must not run code: 'os:system' was once imported and called on a worker."""
    import sys as _sys

    monkeypatch.delitem(_sys.modules, "antigravity", raising=False)
    spec = write_spec(tmp_path / "evil.toml", '[study]\nfunction = "antigravity:fly"\n[study.grid]\nseed = [1]\n')
    code, out, err = cli("study", spec, "--out", tmp_path / "out")
    assert code == 2 and "unknown point function 'antigravity:fly'" in err and "never code to import" in err
    assert "antigravity" not in _sys.modules and not (tmp_path / "out").exists()
    spec = write_spec(tmp_path / "os.toml", '[study]\nfunction = "os:system"\n[study.grid]\nseed = [1]\n')
    code, out, err = cli("study", spec, "--dry-run")
    assert code == 2 and "unknown point function 'os:system'" in err


def test_spec_file_needs_a_study_table(tmp_path):
    path = write_spec(tmp_path / "s.toml", "normal_load = '25 uN'\n")
    with pytest.raises(InputError, match=r"no \[study\] table"):
        load_study_spec(path)


# --- running ----------------------------------------------------------------------------------------

SPEC = """
[parameters]
module = "3.9 um"

[study]
name = "hertz check"
function = "hertz"

[study.grid]
normal_load = ["25 uN", "50 uN", "100 uN"]
seed = [1, 2]
"""


def test_results_identical_with_one_worker_and_an_external_two_worker_cluster(params, tmp_path):
    from distributed import LocalCluster

    spec = load_study_spec(write_spec(tmp_path / "s.toml", SPEC))
    one = run_study(spec, tmp_path / "one", params, workers=1)
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None, processes=True) as cluster:
        two = run_study(spec, tmp_path / "two", params, scheduler=cluster.scheduler_address)
    assert one.n_points == two.n_points == 6 and one.n_computed == 6 and one.n_failed == 0
    for name in ("half_width", "peak_pressure", "noise", "input_normal_load"):
        np.testing.assert_array_equal(one.dataset[name].values, two.dataset[name].values)
    # the seed decides the random number, the load does not
    noise = one.dataset["noise"].values
    assert noise[0] == noise[2] == noise[4] != noise[1]
    # closed form: Hertz half width grows as sqrt(load)
    width = one.dataset["half_width"].values
    assert width[4] / width[0] == pytest.approx(2.0, rel=1e-12)
    assert one.dataset["half_width"].attrs["units"] == "m"
    csv = [line for line in (tmp_path / "one" / "results.csv").read_text().splitlines() if line[:1] != "#"]
    assert csv[0].startswith("point [1],input_normal_load [N]") and len(csv) == 7
    assert (tmp_path / "one" / "results.nc").is_file()


def test_own_local_cluster_leaves_glibc_memory_settings_alone(monkeypatch):
    """Dask's nannies export MALLOC_TRIM_THRESHOLD_=65536, which fixes glibc's mmap threshold (a meshing
    cycle then costs 44 % more CPU); memstribo's own cluster does not add it and keeps Dask's thread limits.
    (A plain Dask cluster started earlier in the same process leaves it in os.environ, where the workers
    inherit it: unset here, as in a fresh `memstribo map`.)"""
    import os

    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)

    from distributed import Client

    from memstribo.simulations.study import local_cluster

    def environment():
        import os

        import dask
        return (os.environ.get("MALLOC_TRIM_THRESHOLD_"), os.environ.get("OMP_NUM_THREADS"),
                dask.config.get("distributed.worker.profile.enabled"))

    before = os.environ.get("MALLOC_TRIM_THRESHOLD_")
    with local_cluster(1) as cluster, Client(cluster, set_as_default=False) as client:
        # and without Dask's sampling profiler (it cost the 2-worker speed-up a few per cent)
        assert list(client.run(environment).values()) == [(None, "1", False)]
    assert os.environ.get("MALLOC_TRIM_THRESHOLD_") == before  # the nanny's process is not changed either


def test_rerun_needs_resume_and_resume_reuses_everything(params, tmp_path):
    spec = load_study_spec(write_spec(tmp_path / "s.toml", SPEC))
    run_study(spec, tmp_path / "out", params, workers=1)
    with pytest.raises(InputError, match="already holds a study; add --resume"):
        run_study(spec, tmp_path / "out", params, workers=1)
    again = run_study(spec, tmp_path / "out", params, resume=True)
    assert (again.n_computed, again.n_reused) == (0, 6)
    other = study_spec({"function": HERTZ, "grid": {"seed": [7]}}, source=str(tmp_path / "s.toml"))
    with pytest.raises(InputError, match="holds a different study"):
        run_study(other, tmp_path / "out", params, resume=True)
    with pytest.raises(InputError, match="holds a different study"):
        run_study(spec, tmp_path / "out", params.updated({"face_width": "3 um"}), resume=True)


def test_failed_points_are_recorded_and_the_study_goes_on(params, tmp_path):
    spec = study_spec({"function": _study_points.failing_point,
                       "grid": {"normal_load": ["50 uN", "200 uN"]}})
    result = run_study(spec, tmp_path / "out", params, workers=1)
    assert result.n_failed == 1 and result.n_points == 2
    (message,) = result.errors.values()
    assert "too high" in message
    assert result.dataset["error"].values[0] == "" and np.isnan(result.dataset["load"].values[1])


def test_resume_runs_failed_points_again_and_says_how_many(params, tmp_path, monkeypatch, cli):
    marker = tmp_path / "ready"
    monkeypatch.setenv("MEMSTRIBO_TEST_FLAKY", str(marker))
    monkeypatch.setitem(POINT_FUNCTIONS, "flaky", _study_points.flaky_point)
    spec = write_spec(tmp_path / "s.toml", '[study]\nfunction = "flaky"\n[study.grid]\nnormal_load = ["25 uN", "50 uN"]\n')
    first = cli.json("study", spec, "--out", tmp_path / "out", "--workers", "1")
    assert (first["failed"], first["computed"], first["retried"]) == (2, 2, 0)
    marker.write_text("")
    code, out, err = cli("study", spec, "--out", tmp_path / "out", "--workers", "1", "--resume")
    assert code == 0, err
    assert "reran 2 point(s) that had failed in an earlier run" in out
    again = cli.json("study", spec, "--out", tmp_path / "out", "--workers", "1", "--resume")
    assert (again["failed"], again["computed"], again["reused"], again["retried"]) == (0, 0, 2, 0)


def test_kill_9_then_resume_loses_no_point_and_computes_none_twice(tmp_path):
    """A real `memstribo study` process group is killed with SIGKILL mid-study, then resumed."""
    spec = write_spec(tmp_path / "s.toml", f"""
[study]
name = "kill test"
function = "hertz"
[study.grid]
seed = {list(range(12))}
""")
    out = tmp_path / "out"
    env = {**os.environ, "MEMSTRIBO_TEST_POINT_DELAY": "0.4"}
    command = [sys.executable, "-c", CLI_WITH_HERTZ, "study", str(spec), "--out", str(out), "--workers", "1"]
    process = subprocess.Popen(command, env=env, start_new_session=True,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    points = out / "points"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and len(list(points.glob("*.json"))) < 3:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait(timeout=30)
    before = {p.name: (p.stat().st_mtime_ns, p.read_text()) for p in points.glob("*.json")}
    assert 3 <= len(before) < 12, "the study should have been killed part-way"
    assert not (out / "results.csv").exists()

    resumed = subprocess.run(command + ["--resume", "--json"], env={**os.environ}, capture_output=True,
                             text=True, timeout=120)
    assert resumed.returncode == 0, resumed.stderr
    summary = json.loads(resumed.stdout)
    assert summary["points"] == 12
    assert summary["reused"] == len(before)
    assert summary["computed"] == 12 - len(before)
    after = {p.name: (p.stat().st_mtime_ns, p.read_text()) for p in points.glob("*.json")}
    assert len(after) == 12
    for name, state in before.items():
        assert after[name] == state, f"{name} was computed twice"
    rows = [line for line in (out / "results.csv").read_text().splitlines() if line[:1] != "#"]
    assert len(rows) == 13
    assert not list(points.glob("*.tmp"))


def test_cli_study_json_and_bad_input_exit_2(cli, tmp_path):
    spec = write_spec(tmp_path / "s.toml", SPEC)
    values = cli.json("study", spec, "--out", tmp_path / "out", "--workers", "1")
    assert values["points"] == 6 and values["computed"] == 6 and values["failed"] == 0
    assert Path(values["results_csv"]).is_file()
    for argv, message in [
        (("study", tmp_path / "missing.toml"), "does not exist"),
        (("study", spec, "--out", tmp_path / "out"), "add --resume"),
        (("study", spec, "--out", tmp_path / "x", "--workers", "0"), "positive integer"),
        (("study", write_spec(tmp_path / "b.toml", "[study]\nfunction='mesh'\n[study.grid]\nfoo=[1]\n")),
         "unknown key 'foo'"),
    ]:
        code, out, err = cli(*argv)
        assert code == 2, err
        assert message in err and "Traceback" not in err


def test_default_point_function_is_the_mesh_summary(params, tmp_path):
    """The built-in 'mesh' point: a coated point at wear = 1 equals bare silicon, and equals a direct call."""
    pytest.importorskip("memstribo.simulations.mesh")
    from memstribo.simulations import mesh

    spec = study_spec({"name": "mesh check", "fixed": {"steps": 6},
                       "points": [{"coating": "OTS", "wear": 1.0}, {"coating": "none"}]})
    assert spec.function == "mesh"
    result = run_study(spec, tmp_path / "out", params, workers=1)
    assert result.n_failed == 0, result.errors
    direct = mesh.summarize(mesh.simulate_mesh(params, steps=6))
    for key in ("stiction_margin", "friction_force_max", "energy_dissipated"):
        values = result.dataset[key].values
        assert values[0] == pytest.approx(values[1], rel=1e-9)
        assert values[1] == direct[key]  # bit for bit: same inputs, no global state
    assert result.dataset["friction_force_max"].attrs["units"] == "N"
    # inputs a point does not set show the value it ran with
    assert list(result.dataset["input_coating"].values) == ["OTS", "none"]
    assert list(result.dataset["input_wear"].values) == [1.0, 1.0]
    assert list(result.dataset["input_steps"].values) == [6, 6]


@pytest.mark.parametrize("name, n_points", [("study_load_wear.toml", 30), ("study_design_points.toml", 4)])
def test_example_study_specs_are_valid(params, name, n_points):
    spec = load_study_spec(TESTS.parent / "examples" / name)
    points = prepare_points(spec, params)
    assert len(points) == n_points
    assert spec.function == "mesh"


def test_unreachable_scheduler_is_an_input_error(cli, tmp_path, monkeypatch):
    import memstribo.simulations.study

    monkeypatch.setattr(memstribo.simulations.study, "CONNECT_TIMEOUT", "1s")
    spec = write_spec(tmp_path / "s.toml", SPEC)
    code, out, err = cli("study", spec, "--out", tmp_path / "out", "--scheduler", "tcp://127.0.0.1:9")
    assert code == 2, err
    assert "cannot connect to the Dask scheduler at 'tcp://127.0.0.1:9'" in err and "Traceback" not in err


def test_progress_bar_shows_points_rate_and_time_left(params, tmp_path, capsys):
    spec = study_spec({"name": "bar", "function": HERTZ, "grid": {"seed": [1, 2, 3]}})
    run_study(spec, tmp_path / "out", params, workers=1, progress=True)
    err = capsys.readouterr().err
    assert "bar: 100%" in err and "3/3" in err and "point/s" in err and "<00:00" in err


def test_study_results_carry_provenance(tmp_path):
    """#15 item 8: the study's NetCDF carries the version, parameters and the spec that made it."""
    import xarray as xr

    from memstribo.simulations.study import run_study, study_spec

    spec = study_spec({"function": "gear", "grid": {"module": ["3 um", "4 um"]}}, parameters={"face_width": "3 um"})
    run_study(spec, tmp_path / "study", workers=1)
    with xr.open_dataset(tmp_path / "study" / "results.nc") as data:
        assert data.attrs["memstribo_version"] and "face_width" in data.attrs["parameter_overrides"]
        assert data.attrs["study_function"] == "gear"


def test_a_corrupted_point_result_is_computed_again_on_resume(params, tmp_path):
    """#29: a point file cut short or damaged (not a .tmp: a finished write later corrupted) is not trusted: resume
    computes that point again and reuses the others unchanged."""
    spec = load_study_spec(write_spec(tmp_path / "s.toml", SPEC))
    first = run_study(spec, tmp_path / "out", params, workers=1)
    files = sorted((tmp_path / "out" / "points").glob("*.json"))
    kept = {p.name: p.read_text() for p in files[1:]}
    files[0].write_text(files[0].read_text()[:20])  # truncated JSON
    again = run_study(spec, tmp_path / "out", params, workers=1, resume=True)
    assert (again.n_computed, again.n_reused) == (1, len(files) - 1)
    assert all((tmp_path / "out" / "points" / name).read_text() == text for name, text in kept.items())
    assert again.dataset.equals(first.dataset)
