"""Round three of the bad inputs (issue #29, "Inputs that slip through"): one test per input, each with the
behaviour the issue states; the version and citation agree with the changelog."""

from __future__ import annotations

import re
import struct
from pathlib import Path

import numpy as np
import pytest

import memstribo
from memstribo.errors import DataFileError, InputError

REPO = Path(__file__).resolve().parent.parent


# --- hangs and sizes refused up front --------------------------------------------------------------

def test_config_that_is_a_device_is_refused(cli):
    code, out, err = cli("constants", "--config", "/dev/zero")
    assert code == 2 and "not a regular file" in err


@pytest.mark.parametrize("command", [("roughness", "/dev/zero"), ("contact", "--surface", "/dev/zero.npy")])
def test_surface_that_is_a_device_is_refused(cli, command):
    if command[0] == "contact":
        code, out, err = cli(*command, "--load", "1 uN", "--physical-size", "1um")
        assert code == 2 and ("not found" in err or "not a regular file" in err)
        return
    code, out, err = cli(*command)
    assert code == 2 and "not a regular file" in err and "empty" not in err


def test_npy_map_that_is_a_device_is_refused(tmp_path):
    from memstribo.surfaces.readers import read_height_array

    link = tmp_path / "zero.npy"
    link.symlink_to("/dev/zero")
    with pytest.raises(DataFileError, match="not a regular file"):
        read_height_array(link)


@pytest.mark.parametrize("count", ["0", "10001", "100000"])
def test_realisations_option_obeys_the_parameter_bounds(cli, count):
    code, out, err = cli("mesh", "--realisations", count, "--steps", "5")
    assert code == 2 and "1 to 10,000" in err


def test_sweep_realisations_obeys_the_parameter_bounds(cli):
    code, out, err = cli("sweep", "load", "--values", "25uN", "--realisations", "20000", "--steps", "5")
    assert code == 2 and "realisations" in err and "10,000" in err


def test_api_refuses_steps_beyond_the_bounds_before_allocating():
    # 10**9 steps would allocate gigabytes of positions before any later check: refused at once
    with pytest.raises(InputError, match="steps must be a whole number from 3 to 100,000"):
        memstribo.mesh_cycle(steps=10**9)


def test_api_applies_the_memory_estimate_of_the_command_line():
    params = memstribo.parameter_set(mesh_window="100 um", mesh_grid_spacing="1 nm")  # 1e5 elements per step
    with pytest.raises(InputError, match="GiB of memory"):
        memstribo.mesh_cycle(params, steps=100_000)


# --- the API raises InputError, never a bare TypeError --------------------------------------------------

@pytest.mark.parametrize("call", [
    lambda: memstribo.parameter_set(5),
    lambda: memstribo.parameter_set(overrides=[1, 2]),
    lambda: memstribo.parameter_set(overrides={1: 2}),
    lambda: memstribo.mesh_cycle(realisations="2"),
    lambda: memstribo.mesh_cycle(realisations=0),
    lambda: memstribo.mesh_cycle(realisations=-3),
    lambda: memstribo.mesh_cycle(realisations=2.5),
    lambda: memstribo.mesh_cycle(steps=5.5),
    lambda: memstribo.mesh_cycle(steps="9"),
    lambda: memstribo.mesh_cycle(steps=True),
    lambda: memstribo.mesh_cycle(wear="half"),
    lambda: memstribo.mesh_cycle({"normal_load": 1e-5}),
    lambda: memstribo.sweep(memstribo.parameter_set(), "load", [25e-6], steps=2.5),
], ids=["set-int", "overrides-list", "overrides-int-key", "realisations-str", "realisations-0", "realisations-neg",
        "realisations-frac", "steps-frac", "steps-str", "steps-bool", "wear-str", "params-dict", "sweep-steps"])
def test_api_bad_arguments_are_input_errors(call):
    with pytest.raises(InputError):
        call()


def test_api_counts_accept_whole_floats():
    from memstribo.checks import as_count

    assert as_count(4.0, "realisations", 1, 10) == 4 and as_count(np.int64(3), "steps", 3, 5) == 3


# --- silently wrong with exit 0 ----------------------------------------------------------------------

def _rough_map(n=32, rq=1e-9, seed=3):
    return np.random.default_rng(seed).normal(0.0, rq, (n, n))


@pytest.mark.parametrize("dtype,match", [(np.int8, "int8 values.*Integers are counts"),
                                         (np.complex128, "complex")])
def test_contact_surface_npy_of_integers_or_complex_is_refused(cli, tmp_path, dtype, match):
    path = tmp_path / "map.npy"
    np.save(path, (np.random.default_rng(1).integers(-100, 100, (16, 16))).astype(dtype))
    code, out, err = cli("contact", "--surface", path, "--physical-size", "1um", "--load", "1 uN")
    assert code == 2 and re.search(match, err), err


def test_contact_surface_npy_heights_not_in_metres_are_refused(cli, tmp_path):
    path = tmp_path / "map.npy"
    np.save(path, _rough_map() * 1e12)  # 1 nm heights written as if 1e12 times larger
    code, out, err = cli("contact", "--surface", path, "--physical-size", "1um", "--load", "1 uN")
    assert code == 2 and "more than 0.1 m" in err


def test_npy_header_claiming_a_huge_array_names_the_file_and_shape(tmp_path):
    from memstribo.surfaces.readers import read_height_array, read_topography

    path = tmp_path / "huge.npy"
    header = {"descr": "<f8", "fortran_order": False, "shape": (10**6, 10**6)}
    with open(path, "wb") as handle:
        np.lib.format.write_array_header_1_0(handle, header)
        handle.write(b"\0" * 64)  # the data are missing: only the header may be read
    for reader in (read_height_array, read_topography):
        with pytest.raises(DataFileError, match=r"huge\.npy.*shape 1000000 x 1000000"):
            reader(path)


def test_npy_profile_complex_says_complex(tmp_path):
    from memstribo.surfaces.readers import read_topography

    path = tmp_path / "p.npy"
    np.save(path, np.column_stack([np.arange(10) * 1e-8, np.ones(10) * 1e-9]).astype(complex))
    with pytest.raises(DataFileError, match="complex"):
        read_topography(path)


def _gwy_string(text):
    return text.encode("utf-8") + b"\0"


def _gwy_object(name, components):
    body = b"".join(components)
    return _gwy_string(name) + struct.pack("<L", len(body)) + body


def _gwy_component(name, kind, payload):
    return _gwy_string(name) + kind.encode("ascii") + payload


def write_gwy(path, xreal=1e-6, yreal=1e-6, z_unit="m", n=8, seed=0):
    """A minimal Gwyddion file (GWYP container, one data field '/0/data'), the layout SurfaceTopography reads."""
    data = np.random.default_rng(seed).normal(0.0, 1e-9, n * n)
    unit = lambda u: _gwy_object("GwySIUnit", [_gwy_component("unitstr", "s", _gwy_string(u))])
    field = _gwy_object("GwyDataField", [
        _gwy_component("xres", "i", struct.pack("<i", n)), _gwy_component("yres", "i", struct.pack("<i", n)),
        _gwy_component("xreal", "d", struct.pack("<d", xreal)), _gwy_component("yreal", "d", struct.pack("<d", yreal)),
        _gwy_component("si_unit_xy", "o", unit("m")), _gwy_component("si_unit_z", "o", unit(z_unit)),
        _gwy_component("data", "D", struct.pack("<L", data.size) + data.astype("<f8").tobytes())])
    container = _gwy_object("GwyContainer", [_gwy_component("/0/data/title", "s", _gwy_string("Height")),
                                             _gwy_component("/0/data", "o", field)])
    Path(path).write_bytes(b"GWYP" + container)
    return data


def test_gwyddion_writer_reads_back(tmp_path):
    from memstribo.surfaces.readers import read_topography

    data = write_gwy(tmp_path / "ok.gwy")
    surface = read_topography(tmp_path / "ok.gwy")
    assert surface.shape == (8, 8) and surface.dx == pytest.approx(1e-6 / 8)
    np.testing.assert_allclose(surface.heights, data.reshape(8, 8), rtol=1e-12)


@pytest.mark.parametrize("size", [0.0, float("nan")])
def test_gwyddion_scan_size_zero_or_nan_is_refused(tmp_path, size):
    from memstribo.surfaces.readers import read_topography

    write_gwy(tmp_path / "bad.gwy", xreal=size)
    with pytest.raises(DataFileError, match="scan size of (0.0|nan).*not a positive length"):
        read_topography(tmp_path / "bad.gwy")


def test_gwyddion_height_in_volts_is_refused_clearly(tmp_path, cli):
    write_gwy(tmp_path / "volts.gwy", z_unit="V")
    code, out, err = cli("roughness", tmp_path / "volts.gwy")
    assert code == 2 and "no height channel" in err and "V" in err and "IndexError" not in err


def test_atomic_height_above_adhesive_height_is_refused(cli):
    code, out, err = cli("nanoblock", "--set", "atomic_height=1 um", "--set", "adhesive_height=1 nm")
    assert code == 2 and "atomic_height" in err and "adhesive_height" in err


def test_interference_deeper_than_the_block_is_refused(cli):
    code, out, err = cli("slide", "--set", "atomic_height=0.1 nm", "--set", "adhesive_height=1 nm",
                         "--set", "sliding_gap=-100 nm")
    assert code == 2 and "deeper than the nanoblock" in err
    with pytest.raises(InputError, match="deeper than the nanoblock"):
        memstribo.parameter_set(atomic_height="0.1 nm", adhesive_height="1 nm", sliding_gap="-2 nm")
    memstribo.parameter_set(atomic_height="0.1 nm", adhesive_height="1 nm", sliding_gap="-1 nm")  # at the limit


def test_coating_wear_on_bare_silicon_is_refused_like_wear(cli):
    code, out, err = cli("mesh", "--set", "coating_wear=0.5", "--steps", "5")
    assert code == 2 and "coating_wear needs a coating" in err
    code, out, err = cli("mesh", "--wear", "0.5", "--steps", "5")
    assert code == 2 and "--wear needs --coating" in err
    with pytest.raises(InputError, match="coating_wear needs a coating"):
        memstribo.mesh_cycle(memstribo.parameter_set(coating_wear=0.5), steps=5)


def test_humidity_in_vacuum_is_refused(cli):
    code, out, err = cli("mesh", "--set", "environment=vacuum", "--set", "relative_humidity=0.9", "--steps", "5")
    assert code == 2 and "only in air" in err
    with pytest.raises(InputError, match="only in air"):
        memstribo.mesh_cycle(memstribo.parameter_set(relative_humidity=0.9), steps=5)


# --- misleading messages -----------------------------------------------------------------------------

def test_arithmetic_in_a_quantity_asks_for_one_number_and_one_unit(cli):
    code, out, err = cli("constants", "--set", "youngs_modulus=1e3 GPa/1000")
    assert code == 2 and "one number and one unit" in err and "pint" not in err
    assert memstribo.parameter_set(youngs_modulus="1.69e11 N/m^2")["youngs_modulus"] == pytest.approx(1.69e11)


def _run_config(tmp_path, text):
    path = tmp_path / "run.toml"
    path.write_text("[run]\n" + text + "\n")
    return path


@pytest.mark.parametrize("line,match", [
    ('roughness_files = ["/etc/passwd"]', r"roughness_files: .*passwd"),
    ('roughness_files = ["/dev/zero"]', "not a regular file"),
    ('sliding_distance = "1 m"', r"sliding_distance = 1 m is .* sliding steps"),
])
def test_run_values_are_checked_before_the_first_stage(cli, tmp_path, line, match):
    if "passwd" in line and not Path("/etc/passwd").is_file():
        pytest.skip("no /etc/passwd here")
    out = tmp_path / "out"
    code, stdout, err = cli("run", "--config", _run_config(tmp_path, line), "--out", out)
    assert code == 2 and re.search(match, err), err
    assert not (out / "run.json").exists()  # no stage ran


# --- version and citation -----------------------------------------------------------------------------

def test_version_follows_the_changelog(cli):
    changelog = (REPO / "CHANGELOG.md").read_text(encoding="utf-8")
    top = re.search(r"^## \[(\d+\.\d+\.\d+)\]", changelog, re.MULTILINE).group(1)
    assert memstribo.__version__.startswith(top)  # 3.0.0.dev0 while 3.0.0 is unreleased
    with pytest.raises(SystemExit):
        cli("--version")
    cff = (REPO / "CITATION.cff").read_text(encoding="utf-8")
    assert f'version: "{memstribo.__version__}"' in cff
    pyproject = (REPO / "pyproject.toml").read_text(encoding="utf-8")
    assert 'license = "MIT"' in pyproject and 'attr = "memstribo.__version__"' in pyproject


def test_version_option_prints_it(capsys):
    from memstribo.cli.main import main

    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0 and capsys.readouterr().out.strip() == f"memstribo {memstribo.__version__}"


# --- the command line: JSON errors, parameters with bounds, quiet and verbose, completion -----------------

def _json_error(out):
    import json

    value = json.loads(out)
    assert set(value) >= {"error", "parameter"}
    return value


def test_gear_json_error_in_degrees(cli):
    code, out, err = cli("gear", "--json", "--set", "pressure_angle=95 deg")
    assert code == 2
    value = _json_error(out)
    assert value["parameter"] == "pressure_angle" and ">= 10 deg and <= 35 deg" in value["error"] and value["error"] in err


@pytest.mark.parametrize("argv,parameter", [
    (("mesh", "--json", "--steps", "x"), "--steps"),  # a usage error (argparse)
    (("mesh", "--json", "--realisations", "0", "--steps", "5"), "--realisations"),
    (("constants", "--json", "--set", "normal_load=5 kg"), "normal_load"),
    (("roughness", "--json", "/dev/zero"), None),
])
def test_json_errors_are_one_object_on_stdout(cli, capsys, argv, parameter):
    try:
        code, out, err = cli(*argv)
    except SystemExit as stop:  # argparse exits from inside main
        code, (out, err) = stop.code, capsys.readouterr()
    assert code == 2 and err.strip()
    assert _json_error(out)["parameter"] == parameter


def test_errors_without_json_leave_stdout_empty(cli):
    code, out, err = cli("gear", "--set", "pressure_angle=95 deg")
    assert code == 2 and out == "" and "pressure_angle" in err


def test_parameters_json_gives_units_bounds_and_sources(cli):
    values = cli.json("parameters", "--set", "normal_load=50 uN")
    assert values["normal_load"] == 50e-6  # the flat values stay
    entry = values["parameters"]["normal_load"]
    assert entry["unit"] == "N" and entry["source"] == "--set" and entry["value"] == 50e-6
    assert entry["minimum"] < entry["value"] < entry["maximum"]
    from memstribo.parameters.definitions import SPECS

    assert set(values["parameters"]) == set(SPECS)
    assert values["parameters"]["load_case"]["choices"] == ["torque", "thesis"]


@pytest.mark.parametrize("command", ["mesh", "sweep", "run", "map", "study", "slide", "coating", "damage"])
def test_long_commands_take_quiet_and_verbose(capsys, command):
    from memstribo.cli.main import main

    with pytest.raises(SystemExit):
        main([command, "--help"])
    text = capsys.readouterr().out
    assert "--quiet" in text and "--verbose" in text


def test_quiet_prints_the_values_only(cli):
    code, out, err = cli("slide", "--model", "estimate", "--quiet")
    assert code == 0 and err == ""
    code_loud, loud, _ = cli("slide", "--model", "estimate")
    assert len(out.splitlines()) < len(loud.splitlines())


def test_completion_is_declared_and_hooked():
    pyproject = (REPO / "pyproject.toml").read_text(encoding="utf-8")
    assert "argcomplete" in pyproject
    main_source = (REPO / "src" / "memstribo" / "cli" / "main.py").read_text(encoding="utf-8")
    assert "PYTHON_ARGCOMPLETE_OK" in main_source and "argcomplete.autocomplete(parser)" in main_source


# --- results folders: two runs into one --out, --overwrite, a damaged partial result resumed ---------------

def test_two_runs_into_one_out_overwrite_and_a_damaged_run_json(cli, tmp_path):
    config = tmp_path / "small.toml"
    config.write_text('[run]\nstages = ["gear"]\nvalidation = false\n')
    out = tmp_path / "out"
    code, _, err = cli("run", config, "--out", out, "--progress", "off")
    assert code == 0, err
    first = (out / "run.json").read_text()
    code, _, err = cli("run", config, "--out", out, "--progress", "off")  # the second run into the same --out
    assert code == 2 and "not empty" in err and (out / "run.json").read_text() == first
    code, _, err = cli("run", config, "--out", out, "--overwrite", "--progress", "off")
    assert code == 0, err
    (out / "run.json").write_text(first[: len(first) // 2])  # cut short
    code, _, err = cli("run", config, "--out", out, "--resume", "--progress", "off")
    assert code == 2 and "not a run.json of memstribo" in err and "Traceback" not in err


@pytest.mark.parametrize("argv", [("run", "--steps", "1000000000"), ("coating", "--steps", "1000000000"),
                                  ("damage", "--steps", "1000000000")])
def test_huge_steps_are_refused_before_any_stage(cli, tmp_path, argv):
    code, out, err = cli(*argv, *(("--out", tmp_path / "out") if argv[0] == "run" else ()))
    assert code == 2 and ("100,000" in err or "100 000" in err), err


def test_a_map_refuses_heights_that_are_not_metres():
    from memstribo.surfaces.readers import SurfaceMap

    with pytest.raises(InputError, match="more than 0.1 m"):
        SurfaceMap(_rough_map() * 1e12, 1e-8, 1e-8, name="scaled")
    assert SurfaceMap(_rough_map(), 1e-8, 1e-8).shape == (32, 32)
