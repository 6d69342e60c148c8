"""Readers: every shipped AFM file loads with a sensible default channel and the README's values.

Oracles: data/afm/README.md (Rq, Ra per file, printed to 4 significant digits: rtol 5e-4 of the
last digit) and SurfaceTopography's own statistics for the same levelling (rtol 1e-6).
"""

from __future__ import annotations

import io
import warnings
import zipfile

import numpy as np
import pytest

from memstribo.errors import DataFileError, InputError
from memstribo.surfaces.readers import SurfaceMap, read_topography
from memstribo.surfaces.roughness import Profile, areal_statistics, line_scan_statistics, profile_statistics

from conftest import AFM

# SurfaceTopography's statistics call its own deprecated aliases (Rq, Sq) internally
pytestmark = pytest.mark.filterwarnings("ignore:Function/property:DeprecationWarning")


def _sig(value, printed):
    """Agreement to the digits printed: half a unit of the last printed digit."""
    text = f"{printed}"
    decimals = len(text.split(".")[1]) if "." in text else 0
    return abs(value - printed) <= 0.5 * 10 ** (-decimals) * (1 + 1e-9)


@pytest.fixture(scope="module")
def loaded():
    """Every shipped file read once (SurfaceTopography is slow to import)."""
    names = {
        "linescan": ("si_profile_linescan.txt", None),
        "di": ("di-3.di", None),
        "di_height": ("di-3.di", "Height"),
        "park": ("example_ps.tiff", None),
        "opdx": ("opdx-3.opdx", None),
        "ibw": ("IgorIBWReader_P0089OP0027.ibw", None),
        "grating": ("topography_in_nanometers.txt", None),
        "uncd": ("container-2.zip", None),
        "uncd_ch1": ("container-2.zip", "uncd_35::ch1"),
        "stylus": ("container-2.zip", "stylus"),
        "tem": ("container-2.zip", "80_Scale"),
    }
    return {key: read_topography(AFM / name, channel=channel) for key, (name, channel) in names.items()}


@pytest.fixture(scope="module")
def st():
    """SurfaceTopography's open_topography, warnings silenced."""
    from SurfaceTopography import open_topography

    def open_(source, **kwargs):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            reader = open_topography(source)
            return reader.topography(**kwargs).to_unit("m").detrend("height")

    return open_


# --- README table (nm, as printed) -----------------------------------------------------------
MAPS = {  # key: (Sq, Sa) in nm, from data/afm/README.md
    "di": (35.22, 26.23),
    "di_height": (45.46, 34.01),
    "park": (3.933, 3.077),
    "ibw": (8.094, 6.664),
    "grating": (204.5, 182.7),
    "uncd": (4.688, 3.674),
    "uncd_ch1": (4.718, 3.690),
}
PROFILES = {  # key: (Rq, Ra) in nm
    "linescan": (4.468, 3.403),
    "opdx": (2.826, 2.406),
    "stylus": (12.65, 9.62),
}


@pytest.mark.parametrize("key", sorted(MAPS))
def test_maps_match_readme(loaded, key):
    surface = loaded[key]
    assert isinstance(surface, SurfaceMap)
    stats = areal_statistics(surface.heights, surface.dx, surface.dy)
    sq, sa = MAPS[key]
    assert _sig(stats.Sq * 1e9, sq), (stats.Sq, sq)
    assert _sig(stats.Sa * 1e9, sa), (stats.Sa, sa)


@pytest.mark.parametrize("key", sorted(PROFILES))
def test_profiles_match_readme(loaded, key):
    profile = loaded[key]
    assert isinstance(profile, Profile) and not profile.synthetic
    stats = profile_statistics(profile)
    rq, ra = PROFILES[key]
    assert _sig(stats.Rq * 1e9, rq), (stats.Rq, rq)
    assert _sig(stats.Ra * 1e9, ra), (stats.Ra, ra)


def test_linescan_slope_matches_header(loaded):
    # header of si_profile_linescan.txt: rms slope (first differences) = 0.2794
    assert _sig(profile_statistics(loaded["linescan"]).rms_slope, 0.2794)


def test_default_channels_and_shapes(loaded):
    assert loaded["di"].channel == "ZSensor" and loaded["di_height"].channel == "Height"
    assert loaded["park"].shape == (512, 512)
    assert loaded["grating"].shape == (128, 128)
    assert loaded["uncd"].channel.startswith("gain_control_uncd_35_z03tr3R.001")
    assert loaded["opdx"].n_points == 3001
    assert loaded["tem"].n_points == 76 and not loaded["tem"].is_uniform
    assert loaded["stylus"].is_uniform and loaded["stylus"].n_points == 3001


def test_pixel_sizes(loaded):
    # .ibw: ScanSize / points = 2 um / 256 (not SurfaceTopography's 2.008 um / 256)
    assert loaded["ibw"].dx == pytest.approx(7.8125e-9, rel=1e-12)
    assert loaded["park"].dx == pytest.approx(1e-6 / 512, rel=1e-12)
    assert loaded["grating"].dx == pytest.approx(10e-6 / 128, rel=1e-12)
    assert loaded["uncd"].physical_sizes[0] == pytest.approx(100e-9, rel=1e-9)
    assert loaded["linescan"].sample_spacing == pytest.approx(1.953125e-9, rel=1e-9)
    assert loaded["linescan"].length == pytest.approx(1e-6, rel=1e-9)


def test_park_rows_are_scan_lines(loaded):
    # the Park software line-levelled every scan line: each ROW must have zero mean and slope
    h = loaded["park"].heights
    assert np.abs(h.mean(axis=1)).max() < 1e-6 * np.abs(h).max()
    assert np.abs(h.mean(axis=0)).max() > 1e-3 * np.abs(h).max()
    # the shipped line scan is stored row 256 counted from the top of the file; SurfaceTopography
    # (and so memstribo) orders y from the bottom, so it is our row 511 - 256 = 255
    z = loaded["linescan"].z
    assert np.allclose(h[255], z, rtol=0, atol=1e-6 * np.abs(z).max())


def test_tem_pointwise_values(loaded):
    # non-uniform TEM profile: point-wise Rq/Ra after a least-squares line through the points.
    x, z = loaded["tem"].x, loaded["tem"].z
    residual = z - np.polyval(np.polyfit(x, z, 1), x)
    stats = profile_statistics(loaded["tem"])
    assert stats.Rq == pytest.approx(np.sqrt(np.mean(residual ** 2)), rel=1e-9)
    assert not stats.uniform
    # README prints 3.51 nm (point-wise after SurfaceTopography's integral line fit) and Ra 3.01 nm;
    # our least-squares line through the points gives 3.504 nm and 3.001 nm (docs/roughness.md).
    assert stats.Rq * 1e9 == pytest.approx(3.5036, abs=5e-4)
    assert stats.Ra * 1e9 == pytest.approx(3.0014, abs=5e-4)


# --- against SurfaceTopography, same levelling, rtol 1e-6 ------------------------------------
@pytest.mark.parametrize("key,name,channel", [
    ("di", "di-3.di", 0), ("di_height", "di-3.di", 3), ("park", "example_ps.tiff", 0),
    ("ibw", "IgorIBWReader_P0089OP0027.ibw", 0)])
def test_maps_against_surfacetopography(loaded, st, key, name, channel):
    topography = st(str(AFM / name), channel_index=channel)
    h = topography.heights()
    stats = areal_statistics(loaded[key].heights)
    assert stats.Sq == pytest.approx(topography.rms_height_from_area(), rel=1e-6)
    assert stats.Sa == pytest.approx(np.mean(np.abs(h - h.mean())), rel=1e-6)


def test_container_afm_member_against_surfacetopography(loaded, st):
    data = zipfile.ZipFile(AFM / "container-2.zip").read("gain_control_uncd_35_z03tr3R.001")
    topography = st(io.BytesIO(data), channel_index=0)
    stats = areal_statistics(loaded["uncd"].heights)
    assert stats.Sq == pytest.approx(topography.rms_height_from_area(), rel=1e-6)
    assert stats.Sq == pytest.approx(4.688e-9, rel=2e-4)  # not 0.525 nm: meta.yml's scale is not applied twice


@pytest.mark.parametrize("key,source,kwargs", [
    ("linescan", "si_profile_linescan.txt", {"unit": "m"}), ("opdx", "opdx-3.opdx", {})])
def test_profiles_against_surfacetopography(loaded, st, key, source, kwargs):
    topography = st(str(AFM / source), **kwargs)
    h = topography.heights()
    stats = profile_statistics(loaded[key])
    assert stats.Rq == pytest.approx(topography.rms_height_from_profile(), rel=1e-6)
    assert stats.Ra == pytest.approx(np.mean(np.abs(h - h.mean())), rel=1e-6)


def test_stylus_against_surfacetopography(loaded, st):
    data = zipfile.ZipFile(AFM / "container-2.zip").read("uncd_stylus_300um_5mar_3_k0HpKJt.txt")
    topography = st(io.BytesIO(data), unit="mm")
    stats = profile_statistics(loaded["stylus"])
    assert stats.Rq == pytest.approx(topography.rms_height_from_profile(), rel=1e-6)


def test_line_scans_against_surfacetopography(loaded):
    """Per-row levelling: rows of the ZSensor map against SurfaceTopography 1-D line scans."""
    from SurfaceTopography import UniformLineScan

    surface = loaded["di"]
    rows = [0, 100, 255]
    rq = []
    for i in rows:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            line = UniformLineScan(np.array(surface.heights[i]), surface.physical_sizes[0]).detrend("height")
        rq.append(line.rms_height_from_profile())
        assert profile_statistics(surface.line_scans()[i]).Rq == pytest.approx(rq[-1], rel=1e-6)
    sub = line_scan_statistics(surface.heights[rows], surface.dx)
    assert sub.Rq == pytest.approx(np.sqrt(np.mean(np.square(rq))), rel=1e-6)  # pooled rms


def test_line_scans_are_rows(loaded):
    surface = loaded["ibw"]
    scans = surface.line_scans()
    assert len(scans) == surface.shape[0]
    assert np.array_equal(scans[5].z, surface.heights[5])
    assert scans[5].sample_spacing == pytest.approx(surface.dx)


# --- own formats --------------------------------------------------------------------------------
def test_csv_with_comments_and_unit(tmp_path):
    x = np.arange(200) * 10.0  # nm
    z = 3.0 * np.sin(2 * np.pi * x / 400.0)
    path = tmp_path / "p.csv"
    path.write_text("# x [nm], z [nm]\n" + "\n".join(f"{a},{b}" for a, b in zip(x, z)))
    profile = read_topography(path, unit="nm")
    assert profile.sample_spacing == pytest.approx(10e-9)
    assert profile.z.max() == pytest.approx(3e-9, rel=1e-9)


def test_csv_with_column_names(tmp_path):
    path = tmp_path / "named.csv"
    path.write_text("x_m,z_m\n" + "\n".join(f"{i * 1e-8},{np.sin(i) * 1e-9}" for i in range(20)))
    profile = read_topography(path)
    assert profile.n_points == 20 and profile.z[1] == pytest.approx(np.sin(1) * 1e-9)


def test_npy_profile(tmp_path):
    x = np.arange(100) * 1e-8
    z = 1e-9 * np.cos(x / 3e-8)
    np.save(tmp_path / "a.npy", np.column_stack([x, z]))
    np.save(tmp_path / "b.npy", np.vstack([x, z]))
    for name in ("a.npy", "b.npy"):
        profile = read_topography(tmp_path / name)
        assert np.allclose(profile.z, z) and profile.sample_spacing == pytest.approx(1e-8)


# --- bad input -------------------------------------------------------------------------------
def test_missing_file():
    with pytest.raises(DataFileError, match="file not found"):
        read_topography(AFM / "no_such_file.txt")


def test_unknown_format_lists_supported(tmp_path):
    path = tmp_path / "scan.xyzw"
    path.write_text("1 2\n")
    with pytest.raises(DataFileError, match=r"unknown format '.xyzw'. Supported: .*\.di.*\.ibw"):
        read_topography(path)


def test_corrupt_instrument_file(tmp_path):
    path = tmp_path / "broken.di"
    path.write_bytes(b"\x00garbage" * 50)
    with pytest.raises(DataFileError, match="could not read"):
        read_topography(path)


def test_corrupt_zip(tmp_path):
    path = tmp_path / "broken.zip"
    path.write_bytes(b"PK not really")
    with pytest.raises(DataFileError, match="not a readable zip"):
        read_topography(path)


def test_unreadable_text(tmp_path):
    path = tmp_path / "words.txt"
    path.write_text("hello world\nthis is not data\n")
    with pytest.raises(DataFileError, match="not a readable x-z text profile"):
        read_topography(path)


def test_three_columns(tmp_path):
    # three columns of numbers that are no x, y, z grid: SurfaceTopography reads them as a 10 x 3 height
    # matrix (its .asc format), which gives no lateral size
    path = tmp_path / "three.txt"
    values = np.random.default_rng(1).random((10, 3))
    path.write_text("\n".join(f"{a} {b} {c}" for a, b, c in values))
    with pytest.raises(DataFileError, match="does not give its lateral size; give the scan size with --physical-size"):
        read_topography(path)


def test_unknown_channel_lists_channels():
    with pytest.raises(DataFileError, match=r"no channel 'Topo'. Channels: ZSensor \(ch0\), .*Height \(ch3\)"):
        read_topography(AFM / "di-3.di", channel="Topo")


def test_non_height_channel():
    with pytest.raises(DataFileError, match="not a height channel"):
        read_topography(AFM / "di-3.di", channel="Phase")


def test_unknown_container_member():
    with pytest.raises(DataFileError, match="matches no member. Members: .*stylus"):
        read_topography(AFM / "container-2.zip", channel="nothing")


def test_single_channel_file_rejects_channel():
    with pytest.raises(DataFileError, match="one channel"):
        read_topography(AFM / "si_profile_linescan.txt", channel="Height")


def test_nan_heights_are_counted(tmp_path):
    x = np.arange(50) * 1e-8
    z = 1e-9 * np.sin(x / 5e-8)
    z[[3, 7]] = np.nan
    path = tmp_path / "nan.txt"
    np.savetxt(path, np.column_stack([x, z]))
    with pytest.raises(DataFileError, match="2 of 50 heights are NaN"):
        read_topography(path)


def test_nan_in_map():
    heights = np.ones((4, 4))
    heights[0, 0] = np.nan
    with pytest.raises(DataFileError, match="1 of 16 undefined"):
        SurfaceMap(heights=heights, dx=1e-9, dy=1e-9)


@pytest.mark.parametrize("scale", [1.0, 1e-18])
def test_implausible_magnitude_suggests_unit(tmp_path, scale):
    # numbers written in nm (heights ~5) read as metres: Rq ~ 3.5 m; or far below 1 pm
    x = np.arange(100) * 10.0 * scale
    z = 5.0 * np.sin(np.arange(100) / 4.0) * scale
    path = tmp_path / "wrong_unit.txt"
    np.savetxt(path, np.column_stack([x, z]))
    with pytest.raises(DataFileError, match="unit is probably wrong. Give the file's unit with --unit"):
        read_topography(path)


def test_unit_conflicts_with_declared_unit():
    with pytest.raises(DataFileError, match="declares its heights in nm"):
        read_topography(AFM / "di-3.di", unit="um")


def test_unknown_unit():
    with pytest.raises(InputError, match="unknown length unit 'furlong'"):
        read_topography(AFM / "si_profile_linescan.txt", unit="furlong")


def test_too_short_profile(tmp_path):
    path = tmp_path / "short.txt"
    path.write_text("0 1e-9\n1e-8 2e-9\n")
    with pytest.raises(DataFileError, match="at least 3"):
        read_topography(path)


def test_decreasing_x(tmp_path):
    path = tmp_path / "back.txt"
    path.write_text("\n".join(f"{-i * 1e-8} {np.sin(i) * 1e-9}" for i in range(10)))
    with pytest.raises(DataFileError, match="increase strictly"):
        read_topography(path)


def test_folder_is_not_a_file(tmp_path):
    with pytest.raises(DataFileError, match="is a folder"):
        read_topography(tmp_path)


def test_bad_npy(tmp_path):
    np.save(tmp_path / "map.npy", np.zeros((5, 5)))
    with pytest.raises(DataFileError, match=r"shape \(n, 2\)"):
        read_topography(tmp_path / "map.npy")


def test_plain_text_goes_to_surfacetopography_first_and_memstribo_is_the_fallback(tmp_path):
    """#14 item 1: SurfaceTopography reads plain x-z text first (memstribo keeps the header's per-axis units, the
    x origin and its checks); what SurfaceTopography refuses (a z-only column) memstribo's own parser reads."""
    from memstribo.surfaces.readers import read_topography

    xz = tmp_path / "xz.csv"
    xz.write_text("x [um], z [nm]\n5, 1\n6, 2\n7, 1.5\n8, 0.5\n", encoding="utf-8")
    profile = read_topography(xz)
    assert "read by SurfaceTopography" in profile.source and "x in um, heights in nm" in profile.source
    np.testing.assert_allclose(profile.x, [5e-6, 6e-6, 7e-6, 8e-6], rtol=1e-12)  # the file's origin, in um
    np.testing.assert_allclose(profile.z, [1e-9, 2e-9, 1.5e-9, 0.5e-9], rtol=1e-12)  # heights in nm
    z_only = tmp_path / "z.txt"
    z_only.write_text("1e-9\n2e-9\n1.5e-9\n0.5e-9\n", encoding="utf-8")
    profile = read_topography(z_only, physical_size="4 um")
    assert "read by" not in profile.source and "length 4e-06 m given" in profile.source
    reversed_x = tmp_path / "reversed.txt"
    reversed_x.write_text("0 1e-9\n2e-8 2e-9\n1e-8 3e-9\n3e-8 1e-9\n", encoding="utf-8")
    with pytest.raises(DataFileError, match="x decreases at data row 3"):  # memstribo's check, not a silent sort
        read_topography(reversed_x)
