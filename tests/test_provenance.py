"""Provenance and CF attributes on every file that ``memstribo run`` writes (issue #15, item 9).

One small run through the command line (a config file with a parameter override and a measured
profile, ``--set`` on top), then every NetCDF and CSV file it wrote is opened and checked: the
memstribo version, the creation time, every parameter and override with its origin, the load
case, the models, the roughness source (file + SHA-256, or synthetic + seed) and, per variable,
``units`` in UDUNITS form (``'1'`` for dimensionless) and a ``long_name``.
"""

from __future__ import annotations

import hashlib
import json
import re
from datetime import datetime, timedelta, timezone
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import memstribo
from memstribo.output import provenance_attributes, udunits, write_dataset
from memstribo.parameters import SPECS, get_parameter_values
from memstribo.quantities import known, quantity

REPO = Path(__file__).resolve().parent.parent
SCAN = REPO / "data" / "afm" / "si_profile_linescan.txt"

#: Unit symbols the model's outputs use; a UDUNITS unit here is a product of these with integer powers.
SYMBOLS = {"m", "s", "N", "Pa", "J", "rad", "W", "kg", "K", "1"}
UNIT = re.compile(r"^(?P<sym>[A-Za-z]+|1)(\^-?[0-9]+)?$")


def is_udunits(unit: str) -> bool:
    """Whether ``unit`` is a product/quotient of known symbols with integer exponents (and not 'X^1')."""
    if not unit or unit != unit.strip() or re.search(r"\^1(?![0-9])", unit):
        return False
    for token in re.split(r"[ */.]", unit):
        match = UNIT.match(token)
        if not match or match.group("sym") not in SYMBOLS:
            return False
    return True


@pytest.fixture(scope="module")
def run_folder(tmp_path_factory):
    """``memstribo run CONFIG --set ... --out DIR`` with few steps and two points per sweep."""
    from memstribo.cli.main import main

    folder = tmp_path_factory.mktemp("provenance")
    config = folder / "case.toml"
    config.write_text(
        "[parameters]\n"
        'roughness_seed = 7\n'
        "[run]\n"
        f"roughness_files = [{json.dumps(str(SCAN))}]\n"
        "steps = 8\n"
        "uncertainty = 8\n"  # a cheap uncertainty stage: its files, not its numbers (issue 40 item 5)
        "realisations = 4\n"
        'loads = ["25 uN", "150 uN"]\n'
        "areas = [1, 4]\n"
        "wear = [0.0, 1.0]\n"
        'sliding_distance = "0.5 um"\n'
        "validation = false\n", encoding="utf-8")
    start = datetime.now(timezone.utc).replace(microsecond=0)
    code = main(["run", str(config), "--set", "normal_load=30 uN", "--out", str(folder / "out"), "--progress", "off"])
    assert code == 0
    return folder / "out", start, datetime.now(timezone.utc) + timedelta(seconds=1)


def test_udunits_forms():
    assert [udunits(u) for u in ("", None, "-", "dimensionless", "Pa^1", "Pa**2", "J/m^2", "m/s", "N*m")] == \
        ["1", "1", "1", "1", "Pa", "Pa^2", "J/m^2", "m/s", "N*m"]
    assert udunits("m^10") == "m^10" and udunits("Pa^1.5") == "Pa^1.5"


def test_every_file_of_a_run_carries_provenance(run_folder):
    folder, start, end = run_folder
    manifest = json.loads((folder / "run.json").read_text())
    assert all(stage["status"] == "done" for stage in manifest["stages"]), manifest["stages"]
    listed = {f for stage in manifest["stages"] for f in stage["files"]}
    netcdf = sorted((folder / "data").glob("*.nc"))
    csv = sorted((folder / "data").glob("*.csv"))
    assert {f"data/{p.name}" for p in netcdf + csv} <= listed
    assert len(netcdf) >= 11 and len(csv) >= 10
    scan_sha = hashlib.sha256(SCAN.read_bytes()).hexdigest()
    unknown = []
    for path in netcdf:
        with xr.open_dataset(path) as dataset:
            attrs = dict(dataset.attrs)
            _check_global_attributes(path.name, attrs, start, end, scan_sha)
            for name, variable in dataset.variables.items():
                label = f"{path.name}:{name}"
                assert str(variable.attrs.get("long_name", "")).strip(), f"{label} has no long_name"
                if variable.dtype.kind in "fiub":
                    assert is_udunits(variable.attrs.get("units", "")), \
                        f"{label}: units {variable.attrs.get('units')!r} are not UDUNITS"
                # one vocabulary (#11 item 3): every name is defined in memstribo.quantities, with its unit
                if not known(str(name)):
                    unknown.append(label)
                elif variable.dtype.kind in "fiub" and quantity(str(name)).unit:
                    assert variable.attrs["units"] == quantity(str(name)).unit, label
    assert not unknown, f"names the vocabulary (memstribo.quantities) does not know: {unknown}"


def _check_global_attributes(name, attrs, start, end, scan_sha):
    for key in ("Conventions", "title", "source", "history", "date_created", "memstribo_version", "parameters",
                "parameter_overrides", "parameter_set", "load_case", "stage", "models", "models_cited",
                "roughness_provenance", "run_options"):
        assert key in attrs, f"{name}: no global attribute {key!r}"
    assert attrs["Conventions"] == "CF-1.8"
    assert attrs["memstribo_version"] == memstribo.__version__ and memstribo.__version__ in attrs["source"] + \
        attrs["history"]
    created = datetime.fromisoformat(attrs["date_created"].replace("Z", "+00:00"))
    assert created.tzinfo is not None and start <= created <= end, attrs["date_created"]
    parameters = json.loads(attrs["parameters"])
    assert set(parameters) == set(SPECS)
    for pname, entry in parameters.items():
        assert set(entry) == {"value", "unit", "source"}, pname
        if SPECS[pname].kind in ("float", "int"):
            assert is_udunits(entry["unit"]), (pname, entry["unit"])
    assert parameters["normal_load"]["value"] == pytest.approx(30e-6) and parameters["normal_load"]["unit"] == "N"
    overrides = json.loads(attrs["parameter_overrides"])
    assert overrides["normal_load"]["origin"] == "--set"
    assert overrides["roughness_seed"]["origin"].startswith("config file") and overrides["roughness_seed"]["value"] == 7
    assert set(overrides) == {"normal_load", "roughness_seed"}
    assert attrs["parameter_set"] == "silicon_thesis"
    assert json.loads(attrs["load_case_parameters"])["normal_load"] == {"value": pytest.approx(30e-6), "unit": "N"}
    assert attrs["load_case"] == "torque"
    assert attrs["models"].strip() and attrs["stage"]
    options = json.loads(attrs["run_options"])
    assert options["steps"] == 8
    roughness = attrs["roughness_provenance"]
    if name == "roughness_statistics.nc":  # both profiles: synthetic default and the measured file
        assert json.loads(roughness) == ["synthetic: seed 7", f"file {SCAN}, sha256 {scan_sha}"]
        assert json.loads(attrs["roughness_file_sha256"]) == [None, scan_sha]
    elif name == "profile_1.nc":
        assert roughness == f"file {SCAN}, sha256 {scan_sha}" and attrs["roughness_file_sha256"] == scan_sha
    elif name == "sliding_single.nc":
        assert roughness.startswith("none")
    else:  # every meshing stage runs on the synthetic default (mesh_roughness = "synthetic")
        assert roughness == "synthetic: seed 7", (name, roughness)


def test_every_csv_has_a_provenance_header_and_reads_back(run_folder):
    import pandas as pd

    folder, start, end = run_folder
    for path in sorted((folder / "data").glob("*.csv")):
        lines = path.read_text(encoding="utf-8").splitlines()
        header = [line for line in lines if line.startswith("#")]
        assert lines[0].startswith(f"# memstribo {memstribo.__version__}: {path.name}")
        assert lines[: len(header)] == header, "the provenance block comes first"
        keys = {line[2:].split(":", 1)[0] for line in header}
        for key in ("Conventions", "date_created", "parameters", "parameter_overrides", "load_case",
                    "roughness_provenance", "models"):
            assert key in keys, f"{path.name}: no '# {key}:' line"
        table = pd.read_csv(path, comment="#", index_col=0)
        with xr.open_dataset(path.with_suffix(".nc")) as dataset:
            for column in list(table.columns) + [table.index.name]:
                match = re.fullmatch(r"(.+) \[(.+)\]", column)
                name = match.group(1) if match else column
                if name not in dataset.variables:  # a dimension without a coordinate: the row number
                    assert name in dataset.dims and not match, f"{path.name}: column {column!r}"
                    continue
                variable = dataset[name]
                if variable.dtype.kind in "fiub":
                    assert match and match.group(2) == variable.attrs["units"], f"{path.name}: {column!r}"
            main = table.index.name.split(" [")[0]
            assert len(table) == dataset.sizes[main]
        # numpy reads it too
        values = np.loadtxt(path, delimiter=",", comments="#", skiprows=len(header) + 1, ndmin=2,
                            usecols=range(1, len(table.columns) + 1), dtype=str)
        assert values.shape[0] == len(table)
        if path.name.startswith("profile_"):  # a written profile reads back as a profile
            from memstribo.surfaces.readers import read_topography

            profile = read_topography(path)
            np.testing.assert_allclose(profile.z, table.iloc[:, 0].to_numpy(), rtol=1e-12, atol=0)


def test_write_dataset_normalises_units_and_keeps_the_input(tmp_path):
    dataset = xr.Dataset({"cof": ("step", np.linspace(0.1, 0.5, 3), {"units": ""}),
                          "damage": ("step", np.ones(3), {"units": "Pa^1", "long_name": "damage"}),
                          "flag": ("step", np.array([True, False, True]))},
                         coords={"step": np.arange(3)}, attrs={"coating": "OTS", "intact": True})
    params = get_parameter_values().updated({"normal_load": "50 uN"}, origin="--set")
    provenance = provenance_attributes(params, roughness=SCAN, extra={"stage": "test", "note": {"a": 1}})
    nc, csv = write_dataset(dataset, tmp_path, "t", provenance=provenance)
    assert dataset["cof"].attrs == {"units": ""} and "Conventions" not in dataset.attrs  # input untouched
    again = xr.load_dataset(nc)
    assert again["cof"].attrs == {"units": "1", "long_name": "coefficient of friction"}  # from the vocabulary
    assert again["damage"].attrs["units"] == "Pa" and again["flag"].attrs["units"] == "1"
    assert again.attrs["coating"] == "OTS" and again.attrs["intact"] == 1 and json.loads(again.attrs["note"]) == {"a": 1}
    assert again.attrs["roughness_file_sha256"] == hashlib.sha256(SCAN.read_bytes()).hexdigest()
    assert json.loads(again.attrs["parameter_overrides"]) == {"normal_load": {"value": 5e-05, "unit": "N",
                                                                              "origin": "--set"}}
    # without provenance: still version, time and conventions
    nc, _ = write_dataset(dataset, tmp_path, "bare")
    attrs = xr.load_dataset(nc).attrs
    assert attrs["Conventions"] == "CF-1.8" and attrs["memstribo_version"] == memstribo.__version__
    assert "date_created" in attrs and "parameters" not in attrs


def test_synthetic_roughness_names_its_seed():
    from memstribo.surfaces.roughness import default_profile

    params = get_parameter_values()
    attrs = provenance_attributes(params, roughness=default_profile(params))
    assert attrs["roughness_provenance"] == f"synthetic: seed {params['roughness_seed']}"
    assert "roughness_file_sha256" not in attrs


@pytest.mark.parametrize("argv, expected", [
    (("mesh", "--steps", "5"), "synthetic: seed"),
    (("sweep", "load", "--values", "25uN,50uN", "--steps", "5"), "synthetic: seed"),
    (("coating", "--wear", "0,1", "--steps", "5"), "synthetic: seed"),
    (("slide", "--model", "single"), "none"),
    (("slide", "--model", "fixed-load", "--profile", str(SCAN), "--distance", "0.2 um"), f"file {SCAN}, sha256"),
])
def test_other_commands_write_provenance(cli, tmp_path, argv, expected):
    # a parameter the command does not set itself (a load sweep refuses a --set normal_load: issue 41)
    overridden = "hardness" if argv[:2] == ("sweep", "load") else "normal_load"
    value = "12 GPa" if overridden == "hardness" else "30 uN"
    code, out, err = cli(*argv, "--set", f"{overridden}={value}", "--out", tmp_path)
    assert code == 0, err
    files = sorted(tmp_path.glob("*.nc"))
    assert files
    for path in files:
        with xr.open_dataset(path) as dataset:
            attrs = dataset.attrs
            assert attrs["Conventions"] == "CF-1.8" and attrs["command"].startswith(f"memstribo {argv[0]}")
            assert json.loads(attrs["parameter_overrides"])[overridden]["origin"] == "--set"
            assert attrs["roughness_provenance"].startswith(expected), (path.name, attrs["roughness_provenance"])
            for name, variable in dataset.variables.items():
                if variable.dtype.kind in "fiub":
                    assert is_udunits(variable.attrs["units"]), f"{path.name}:{name} {variable.attrs['units']!r}"
    for path in tmp_path.glob("*.csv"):
        assert path.read_text(encoding="utf-8").startswith("# memstribo ")


# --- CF compliance (issue #29, item 1) ----------------------------------------------------------
def cf_check(path: Path, report: Path) -> tuple[bool, str]:
    """Run the IOOS compliance checker's CF-1.8 suite on ``path`` (strict: any failed check fails);
    return whether it passed and its text report."""
    pytest.importorskip("compliance_checker")
    from compliance_checker.runner import CheckSuite, ComplianceChecker

    import warnings

    with warnings.catch_warnings():  # the checker's own deprecation notes (its SOS plugins) are not ours
        warnings.simplefilter("ignore", DeprecationWarning)
        CheckSuite.load_all_available_checkers()
    passed, errors = ComplianceChecker.run_checker(str(path), ["cf:1.8"], 0, "strict", output_filename=str(report),
                                                   output_format="text")
    text = report.read_text(encoding="utf-8")
    return bool(passed) and not errors, text + (f"\nchecker errors: {errors}" if errors else "")


def test_every_netcdf_file_of_a_run_passes_the_cf_checker(run_folder, tmp_path):
    folder, _, _ = run_folder
    files = sorted((folder / "data").glob("*.nc"))
    assert len(files) >= 11
    failed = {}
    for path in files:
        passed, text = cf_check(path, tmp_path / f"{path.stem}.txt")
        if not passed:
            failed[path.name] = text[-1500:]
        import netCDF4  # CF-1.8 (and cfchecks) know no variable-length strings: text is a char array

        with netCDF4.Dataset(path) as raw:
            for name, variable in raw.variables.items():
                assert variable.dtype is not str, f"{path.name}:{name} is a variable-length string"
                assert variable.dtype.kind != "i" or variable.dtype.itemsize <= 4, f"{path.name}:{name} is int64"
    assert not failed, "\n\n".join(f"{name}:\n{text}" for name, text in failed.items())


def test_the_cf_checker_catches_what_it_is_here_for(tmp_path):
    """The check can fail: int64, a _FillValue on a coordinate and a variable-length string (the
    encodings of memstribo before issue #29) each fail it; write_dataset's encodings pass it."""
    dataset = xr.Dataset({"cof": ("step", np.linspace(0.1, 0.5, 3), {"units": "1", "long_name": "COF"}),
                          "block_flank": ("block", np.array(["pinion", "gear"]), {"long_name": "flank"})},
                         coords={"step": ("step", np.arange(3, dtype=np.int64), {"long_name": "step", "units": "1"}),
                                 "x": ("x", np.linspace(0.0, 1.0, 2), {"long_name": "x", "units": "m"})})
    dataset.attrs = provenance_attributes()
    plain = tmp_path / "plain.nc"
    dataset.to_netcdf(plain, format="NETCDF4")  # xarray's defaults
    passed, text = cf_check(plain, tmp_path / "plain.txt")
    assert not passed
    assert "int64" in text and "_FillValue" in text
    nc, _ = write_dataset(dataset, tmp_path, "ours")
    passed, text = cf_check(nc, tmp_path / "ours.txt")
    assert passed, text
    again = xr.load_dataset(nc)  # and it reads back as it was: text as str, integers as int32
    assert list(again["block_flank"].values) == ["pinion", "gear"] and again["step"].dtype == np.int32
    assert "_FillValue" not in again["x"].encoding


def test_provenance_names_the_commit_the_command_line_and_the_versions(run_folder, monkeypatch, tmp_path):
    import platform
    import subprocess

    from memstribo import output

    folder, _, _ = run_folder
    head = subprocess.run(["git", "-C", str(REPO), "rev-parse", "HEAD"], capture_output=True, text=True)
    with xr.open_dataset(folder / "data" / "mesh_bare.nc") as dataset:
        attrs = dict(dataset.attrs)
    if head.returncode == 0:
        assert attrs["git_commit"].split()[0] == head.stdout.strip()
    assert attrs["command_line"].startswith("memstribo run ") and "--set 'normal_load=30 uN'" in attrs["command_line"]
    assert attrs["python_version"].startswith(platform.python_version())
    versions = json.loads(attrs["package_versions"])
    assert versions["numpy"] == np.__version__ and versions["xarray"] == xr.__version__
    # the same record in run.json and in parameters.toml's [meta.provenance]
    import tomllib

    manifest = json.loads((folder / "run.json").read_text())
    meta = tomllib.loads((folder / "parameters.toml").read_text())["meta"]["provenance"]
    for record in (manifest["provenance"], meta):
        assert record["git_commit"] == attrs["git_commit"] and record["command_line"] == attrs["command_line"]
        assert record["package_versions"] == versions
    # an installed wheel (the package outside any checkout) run from the repository root finds it;
    # run elsewhere it says so
    monkeypatch.setattr(output, "__file__", str(tmp_path / "site-packages" / "memstribo" / "output.py"))
    monkeypatch.chdir(REPO / "docs")
    assert output.checkout_root() == REPO
    monkeypatch.chdir(tmp_path)
    assert output.checkout_root() is None
    assert output.git_commit() == "none: not run from a checkout of the repository"
