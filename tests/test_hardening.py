"""Every bad input a clear error (issues #14, #15): one test per fix, library and command line."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from memstribo.errors import DataFileError, InputError
from memstribo.surfaces.readers import SurfaceMap, read_topography

DATA = Path(__file__).resolve().parent / "data"
AFM = Path(__file__).resolve().parent.parent / "data" / "afm"


def _profile_text(n=40, sep=" ", x_scale=1e-8, z_scale=1e-9):
    x = np.arange(n) * x_scale
    z = np.sin(np.arange(n) / 3.0) * z_scale
    return "".join(f"{float(a)!r}{sep}{float(b)!r}\n" for a, b in zip(x, z)), x, z


# --- reading ------------------------------------------------------------------------------------------

def test_dektak_csv_goes_through_surface_topography():
    """A Bruker Dektak stylus-profiler CSV export (SurfaceTopography's Dektak header) was refused before."""
    profile = read_topography(DATA / "dektak_style.csv")
    assert "read by SurfaceTopography" in profile.source and "um" in profile.source
    assert profile.n_points == 301 and profile.sample_spacing == pytest.approx(0.1e-6, rel=1e-12)
    # the same numbers straight from the file (x and height in micrometres, "Lateral um,Raw Micrometer")
    rows = [line.split(",")[:2] for line in DATA.joinpath("dektak_style.csv").read_text("latin-1").splitlines()
            if line[:1].isdigit()]
    z = np.array([float(b) for _, b in rows]) * 1e-6
    np.testing.assert_allclose(profile.z, z, rtol=1e-12, atol=0)


def test_dektak_csv_roughness_cli(cli):
    values = cli.json("roughness", DATA / "dektak_style.csv")
    assert values["kind"] == "profile" and values["n_points"] == 301
    assert 1e-9 < values["Rq"] < 1e-8


def test_utf8_bom_keeps_the_first_row(tmp_path):
    text, x, z = _profile_text()
    plain, bom = tmp_path / "plain.csv", tmp_path / "bom.csv"
    plain.write_text(text.replace(" ", ","))
    bom.write_bytes(b"\xef\xbb\xbf" + text.replace(" ", ",").encode())
    a, b = read_topography(plain), read_topography(bom)
    assert a.n_points == b.n_points == 40
    np.testing.assert_array_equal(a.z, b.z)
    assert b.z[0] == z[0]


@pytest.mark.parametrize("encode", [
    lambda t: t.encode("utf-16"),                      # UTF-16 with BOM
    lambda t: t.replace("\n", "\r").encode(),          # CR-only line ends (classic Mac)
    lambda t: t.replace("\n", "\r\n").encode(),        # CRLF
    lambda t: ("\ufeff" + t).encode("utf-8"),          # UTF-8 BOM
])
def test_text_encodings_and_line_ends_read_the_same(tmp_path, encode):
    text, x, z = _profile_text()
    path = tmp_path / "p.txt"
    path.write_bytes(encode(text))
    profile = read_topography(path)
    assert profile.n_points == 40
    np.testing.assert_allclose(profile.z, z, rtol=0, atol=0)


@pytest.mark.parametrize("body, match", [
    ("0 1e-9\n1e-8 nan\n2e-8 3e-9\n3e-8 1e-9\n", "1 of 4 heights are NaN"),
    ("0 1e-9\n1e-8 inf\n2e-8 3e-9\n3e-8 1e-9\n", "1 of 4 heights are NaN or undefined"),
    ("0 1e-9\n2e-8 2e-9\n1e-8 3e-9\n3e-8 1e-9\n", "x decreases at data row 3"),
    ("0 1e-9\n1e-8 2e-9\n1e-8 3e-9\n3e-8 1e-9\n", "x repeats at data row 3"),
    ("0 1e-9\n", "1 point.*at least 3"),
    ("0 1e-9\n1e-8 2e-9\n", "2 point.*at least 3"),
    ("0 1e300\n1e-8 -1e300\n2e-8 3e300\n", "reach 3e\\+300 m.*--unit"),
    ("0 1e-9\n1e-20 2e-9\n2e-20 1e-9\n", "x step 1e-20 m.*not a measured surface"),
    ("0|1e-9\n1e-8|2e-9\n2e-8|3e-9\n", "line 2 '1e-8\\|2e-9' is not numbers"),
    ("0 1e-9\n1e-8\n2e-8 3e-9\n", "data row 2 has 1 column"),
])
def test_bad_text_profiles_are_clear_errors(tmp_path, body, match):
    path = tmp_path / "bad.txt"
    path.write_text(body)
    with pytest.raises(DataFileError, match=match):
        read_topography(path)


def test_header_units_per_axis(tmp_path):
    text, x, z = _profile_text(x_scale=10.0, z_scale=2.0)  # numbers: x in um, heights in nm
    path = tmp_path / "units.csv"
    path.write_text("x [um], z [nm]\n" + text.replace(" ", ","))
    profile = read_topography(path)
    np.testing.assert_allclose(profile.z, z * 1e-9, rtol=1e-15)
    assert profile.sample_spacing == pytest.approx(10e-6)
    assert "x in um, heights in nm" in profile.source
    with pytest.raises(DataFileError, match=r"gives the units.*--unit \(nm\) is only for files without"):
        read_topography(path, unit="nm")
    path.write_text("x [um], z\n" + text)
    with pytest.raises(DataFileError, match="unit for one column only"):
        read_topography(path)
    path.write_text("x (um), z (V)\n" + text)
    with pytest.raises(DataFileError, match="has unit 'V', not a length"):
        read_topography(path)


def test_units_in_the_comment_line_before_the_data(tmp_path):
    text, x, z = _profile_text(x_scale=10.0, z_scale=2.0)
    path = tmp_path / "commented.txt"
    path.write_text("# my scan\n# x [um]   height [nm]\n" + text)
    profile = read_topography(path)
    np.testing.assert_allclose(profile.z, z * 1e-9, rtol=1e-15)
    assert profile.sample_spacing == pytest.approx(10e-6)
    path.write_text("# x [um]   height [nm]\n# more notes\n" + text)  # not right before the data: a note
    with pytest.raises(DataFileError, match="unit is probably wrong"):
        read_topography(path)


def test_z_only_text_needs_physical_size(tmp_path):
    path = tmp_path / "z.txt"
    path.write_text("".join(f"{float(np.sin(i / 3) * 1e-9)!r}\n" for i in range(50)))
    with pytest.raises(DataFileError, match="--physical-size"):
        read_topography(path)
    profile = read_topography(path, physical_size="5 um")
    assert profile.n_points == 50 and profile.sample_spacing == pytest.approx(0.1e-6)


def test_map_without_lateral_size_names_physical_size(tmp_path, cli):
    heights = np.random.default_rng(3).standard_normal((16, 16)) * 1e-9
    path = tmp_path / "matrix.asc"
    path.write_text("\n".join(" ".join(repr(float(v)) for v in row) for row in heights))
    with pytest.raises(DataFileError, match="does not give its lateral size.*--physical-size"):
        read_topography(path)
    surface = read_topography(path, physical_size="1.6 um")
    assert isinstance(surface, SurfaceMap) and surface.dx == pytest.approx(0.1e-6)
    code, out, err = cli("roughness", path)
    assert code == 2 and "--physical-size" in err
    values = cli.json("roughness", path, "--physical-size", "1.6 um, 1.6 um")
    assert values["kind"] == "map"
    with pytest.raises(DataFileError, match="gives its lateral size; --physical-size is only for"):
        read_topography(AFM / "di-3.di", physical_size="1 um")


@pytest.mark.parametrize("fraction", [0.1, 0.5, 0.99])
def test_truncated_park_tiff_is_a_clear_error(tmp_path, fraction, cli):
    data = (AFM / "example_ps.tiff").read_bytes()
    path = tmp_path / "cut.tiff"
    path.write_bytes(data[: int(len(data) * fraction)])
    with pytest.raises(DataFileError, match="truncated|could not read"):
        read_topography(path)
    code, out, err = cli("roughness", path)
    assert code == 2 and "internal error" not in err and len(err.splitlines()) <= 5


def test_unreadable_file_is_one_short_message_without_raw_bytes(tmp_path):
    path = tmp_path / "evil.di"
    path.write_bytes(b"\\*File list\r\n\x1b[2J\x1b]0;pwned\x07" + bytes(range(256)) * 20)
    with pytest.raises(DataFileError) as info:
        read_topography(path)
    message = str(info.value)
    assert "\x1b" not in message and "\x07" not in message
    assert len(message.splitlines()) == 1 and len(message) <= 600
    assert "tried" not in message  # not SurfaceTopography's list of every reader


def test_empty_file(tmp_path):
    path = tmp_path / "empty.csv"
    path.write_bytes(b"")
    with pytest.raises(DataFileError, match="empty"):
        read_topography(path)


# --- units ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("text, match", [
    ("5 (uN", "is not a unit"),
    ("5 uN/0", "one number and one unit"),  # arithmetic is named as such (#29)
    ("uN", "must start with a number"),
    ("1 2 uN", "one number and one unit"),
    ("5 uN\x1b[31m", "is not a unit"),
    ("1e999 uN", "finite"),
])
def test_odd_unit_strings_are_input_errors(text, match):
    from memstribo.units import to_si

    with pytest.raises(InputError, match=match) as info:
        to_si(text, "N", "normal_load")
    assert "\x1b" not in str(info.value)


def test_negative_option_values_reach_the_range_check(cli):
    code, out, err = cli("slide", "--load", "-5uN")
    assert code == 2 and "--load must be a positive force, got '-5uN'" in err and "expected one argument" not in err
    code, out, err = cli("slide", "--load", "-5e-6")
    assert code == 2 and "--load must be a positive force" in err
    code, out, err = cli("gear", "--set", "normal_load=-5uN")
    assert code == 2 and "outside its range" in err


# --- config files -------------------------------------------------------------------------------------

@pytest.mark.parametrize("body, match", [
    ('[parameter]\nnormal_load = "50 uN"\n', r"unknown table \[parameter\].*Did you mean 'parameters'"),
    ("[Run]\nsteps = 3\n", r"unknown table \[Run\].*Did you mean 'run'"),
    ("[parameters.normal_load]\nvaleu = 5e-5\n", "unknown key 'valeu'.*Did you mean 'value'"),
    ("[parameters]\nnormal_lod = 5e-5\n", "unknown parameter 'normal_lod'.*normal_load"),
    ("[run]\nstesp = 5\n", r"\[run\] has unknown key 'stesp'.*steps"),
    ("normal_load = \n", r"not valid TOML: .*line 1, column"),
    ("normal_load = true\n", "expected a number, got a boolean"),
    ('[parameters]\nload_sharing = 5\n', "expected a string"),
    ("[parameters]\nmesh_steps = [1, 2]\n", "not a list"),
    ("[normal_load]\nvalue = 1\n", r"unknown table \[normal_load\].*\[parameters.normal_load\]"),
])
def test_config_files_are_validated_whole(cli, tmp_path, body, match):
    import re

    path = tmp_path / "c.toml"
    path.write_text(body)
    code, out, err = cli("gear", "--config", path)
    assert code == 2, out
    assert re.search(match, err), err
    assert str(path) in err


def test_table_form_unit_is_applied(cli, tmp_path):
    path = tmp_path / "c.toml"
    path.write_text('[parameters.normal_load]\nvalue = 50\nunit = "uN"\n')
    values = cli.json("parameters", "--config", path)
    assert values["normal_load"] == pytest.approx(50e-6)


# --- bounds ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name, value", [
    ("pressure_angle", "89 deg"), ("sliding_gap", "-1 m"), ("normal_load", "1e30 N"), ("mesh_steps", 100_001),
    ("youngs_modulus", "1 Pa"), ("mesh_grid_spacing", "1e-20 m"), ("roughness_sample_spacing", "1e-20 m"),
    ("teeth_pinion", 10**9),
])
def test_impossible_parameters_are_refused(params, name, value):
    with pytest.raises(InputError, match=f"'{name}'.*outside its range"):
        params.updated({name: value})


def test_memory_of_mesh_and_profiles_is_checked_before_allocating(params):
    with pytest.raises(InputError, match="GiB of memory"):
        params.updated({"mesh_steps": 100_000, "mesh_grid_spacing": "0.1 nm", "mesh_window": "1.2 um"})
    with pytest.raises(InputError, match="contact elements per step"):
        params.updated({"mesh_window": "1 mm", "mesh_grid_spacing": "0.1 nm"})
    with pytest.raises(InputError, match="points; at most 10,000,000"):
        params.updated({"roughness_length": "10 cm", "roughness_sample_spacing": "1 nm"})


@pytest.mark.parametrize("argv, match", [
    (("asperity", "--load", "1e30"), "outside its range"),
    (("slide", "--step", "1e-20 m"), "sliding_step"),
    (("slide", "--gap", "-1 m"), "sliding_gap"),
    (("roughness", "thesis", "--resample", "1e-20"), "--resample"),
    (("damage", "--steps", "100000000"), "--steps"),
    (("gear", "--set", "pressure_angle=89 deg"), "contact ratio"),
])
def test_cli_refuses_impossible_options(cli, argv, match):
    code, out, err = cli(*argv)
    assert code == 2 and match in err and "internal error" not in err


def test_parameters_listing_says_allowed_range_and_why(cli):
    code, out, err = cli("parameters")
    assert code == 0 and "allowed: a number >= 0.174533 and <= 0.610865" in out and "involute" in out
