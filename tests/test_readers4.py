"""Round four of the bad inputs (issue #41, "Files read with the wrong geometry, silently"): one test per
instrument-file case. Each broken file is the shipped file edited in place (same length, so every offset
still holds) or a small synthetic file; each must be refused with a message naming the file, the
contradiction and what is allowed."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from memstribo.errors import DataFileError
from memstribo.surfaces.readers import read_height_array, read_topography

from conftest import AFM
from test_hardening3 import write_gwy

pytestmark = pytest.mark.filterwarnings("ignore:Function/property:DeprecationWarning")

IBW = "IgorIBWReader_P0089OP0027.ibw"


def _edited(tmp_path, name, old, new, count=1, start=0):
    """The shipped file ``name`` with the ``count`` first occurrences of ``old`` after byte ``start``
    replaced by ``new`` (same length: no offset of the file moves)."""
    assert len(old) == len(new)
    data = (AFM / name).read_bytes()
    head, tail = data[:start], data[start:]
    assert tail.count(old) >= count, (name, old)
    path = tmp_path / name
    path.write_bytes(head + tail.replace(old, new, count))
    return path


# --- Asylum .ibw: the note against the wave ------------------------------------------------------------

def test_ibw_note_scan_points_contradicting_the_wave_is_refused(tmp_path):
    # the note says 512 points per line, the wave holds 256: a pixel of 2 um / 512 would halve every length
    path = _edited(tmp_path, IBW, b"\rScanPoints: 256", b"\rScanPoints: 512")
    with pytest.raises(DataFileError, match=r"IgorIBWReader.*ScanPoints: 512.*256.*points per line") as err:
        read_topography(path)
    assert "equal" in str(err.value)  # what is allowed


def test_ibw_note_scan_lines_contradicting_the_wave_is_refused(tmp_path):
    path = _edited(tmp_path, IBW, b"\rScanLines: 256", b"\rScanLines: 128")
    with pytest.raises(DataFileError, match=r"IgorIBWReader.*ScanLines: 128.*256.*lines"):
        read_topography(path)


@pytest.mark.parametrize("value", [b"NaN  ", b"inf  ", b"-2e-6", b"0    "])
def test_ibw_note_scan_size_not_finite_is_refused_without_printing_nan(tmp_path, value):
    path = _edited(tmp_path, IBW, b"\rFastScanSize: 2e-06", b"\rFastScanSize: " + value)
    with pytest.raises(DataFileError, match=r"IgorIBWReader.*FastScanSize.*not a positive finite length") as err:
        read_topography(path)
    assert "dx nan" not in str(err.value) and "nan m" not in str(err.value)


def test_ibw_shipped_note_still_gives_scan_size_over_points(tmp_path):
    surface = read_topography(AFM / IBW)
    assert surface.dx == pytest.approx(2e-6 / 256, rel=1e-12) and surface.shape == (256, 256)


# --- NanoScope: the image section's line counts against its data block ------------------------------------

def _image_section(name="di-3.di"):
    """Byte offset of the first image section's header (after the global scan list)."""
    return (AFM / name).read_bytes().index(b"\\*Ciao image list")


@pytest.mark.parametrize("old,new,what", [
    (b"\\Samps/line: 256", b"\\Samps/line: 999", r"Samps/line 999"),
    (b"\\Number of lines: 256", b"\\Number of lines: 128", r"Number of lines 128"),
])
def test_nanoscope_line_counts_contradicting_the_data_block_are_refused(tmp_path, old, new, what):
    # SurfaceTopography took the global 256 x 256 and scaled the 10 um scan size by 256/999 (2.56 um) or
    # 256/128 (20 um): a map read with the wrong geometry
    path = _edited(tmp_path, "di-3.di", old, new, start=_image_section())
    with pytest.raises(DataFileError, match=rf"di-3\.di.*{what}.*131,?072 bytes") as err:
        read_topography(path)
    assert "256 x 256" in str(err.value)


def test_nanoscope_issue_file_ten_micrometres_read_as_25_nm_is_refused(tmp_path):
    # the issue's file: 'Samps/line: 100000' in the image section; 3 bytes of the header's zero padding are
    # dropped so that every offset still holds
    data = (AFM / "di-3.di").read_bytes()
    start = _image_section()
    old, new = b"\\Samps/line: 256", b"\\Samps/line: 100000"
    i = data.index(old, start)
    assert data[40960 - 3:40960] == b"\0\0\0"
    path = tmp_path / "di-3.di"
    path.write_bytes(data[:i] + new + data[i + len(old):40960 - 3] + data[40960:])
    from SurfaceTopography import open_topography

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sizes = open_topography(str(path)).channels[0].physical_sizes
    assert sizes[0] == pytest.approx(25.6)  # nm: what SurfaceTopography makes of it (10 um x 256 / 100000)
    with pytest.raises(DataFileError, match=r"di-3\.di.*Samps/line 100000.*131,072 bytes.*256 x 256"):
        read_topography(path)


def test_nanoscope_shipped_file_reads_its_ten_micrometres():
    surface = read_topography(AFM / "di-3.di")
    assert surface.physical_sizes == pytest.approx((10e-6, 10e-6), rel=1e-12)


# --- Gwyddion: negative sizes ----------------------------------------------------------------------------

@pytest.mark.parametrize("which", ["xreal", "yreal"])
def test_gwyddion_negative_scan_size_is_refused(tmp_path, which):
    write_gwy(tmp_path / "neg.gwy", **{which: -1e-6})
    with pytest.raises(DataFileError, match=rf"neg\.gwy.*-1e-06 \({which}\).*not a positive length.*negative"):
        read_topography(tmp_path / "neg.gwy")


# --- text: column order and digits -------------------------------------------------------------------------

def _text_profile(n=64, seed=1):
    rng = np.random.default_rng(seed)
    return np.arange(n) * 0.01, rng.normal(0.0, 2.0, n)  # x in um, z in nm


@pytest.mark.parametrize("header", ["z [nm], x [um]", "# height (nm)  position (um)", "Height nm, X um",
                                    "z, x"])
def test_text_header_naming_the_height_first_is_refused(tmp_path, header):
    x, z = _text_profile()
    path = tmp_path / "swapped.csv"
    # the data are x then z: read by column position, x took the height's unit and z the position's
    # (x in nm, heights in um, a 1000-fold error both ways) without a word
    rows = "\n".join(f"{a:.6g}, {b:.6g}" for a, b in zip(x, z))
    path.write_text(header + "\n" + rows + "\n")
    with pytest.raises(DataFileError, match=r"swapped\.csv.*names the height.*first.*x .*first"):
        read_topography(path, unit="um" if header == "z, x" else None)  # unit-less columns need --unit


def test_text_header_in_the_usual_order_still_reads(tmp_path):
    x, z = _text_profile()
    path = tmp_path / "ok.csv"
    path.write_text("x [um], z [nm]\n" + "\n".join(f"{a:.6g}, {b:.6g}" for a, b in zip(x, z)) + "\n")
    profile = read_topography(path)
    assert profile.z == pytest.approx(np.asarray([float(f"{b:.6g}") for b in z]) * 1e-9)


@pytest.mark.parametrize("digits", [
    str.maketrans("0123456789", "\uff10\uff11\uff12\uff13\uff14\uff15\uff16\uff17\uff18\uff19"),  # full width
    str.maketrans("0123456789", "\u0660\u0661\u0662\u0663\u0664\u0665\u0666\u0667\u0668\u0669"),  # Arabic-Indic
], ids=["full-width", "arabic-indic"])
def test_text_with_non_ascii_digits_is_refused(tmp_path, digits):
    x, z = _text_profile()
    rows = [f"{a:.6g} {b:.6g}" for a, b in zip(x, z)]
    rows[5] = rows[5].translate(digits)
    path = tmp_path / "digits.txt"
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    with pytest.raises(DataFileError, match=r"digits\.txt.*line 6.*non-ASCII digit.*U\+0?(FF1|66).*0-9"):
        read_topography(path, unit="um")


def test_header_export_with_non_ascii_digits_is_refused(tmp_path):
    text = (AFM / "topography_in_nanometers.txt").read_text(encoding="utf-8", errors="strict")
    path = tmp_path / "export.txt"
    path.write_text(text.replace("Image Width : 128", "Image Width : \uff11\uff12\uff18", 1), encoding="utf-8")
    with pytest.raises(DataFileError, match=r"export\.txt.*non-ASCII digit"):
        read_topography(path)


# --- .npy maps: float16, constant, all zero ----------------------------------------------------------------

def _rough(n=16, rq=1e-9, seed=2):
    return np.random.default_rng(seed).normal(0.0, rq, (n, n))


def test_npy_map_float16_is_refused(tmp_path):
    path = tmp_path / "half.npy"
    np.save(path, _rough().astype(np.float16))  # 1 nm heights in metres: float16 holds them as 0 or 6e-8 steps
    with pytest.raises(DataFileError, match=r"half\.npy.*float16.*float32 or float64"):
        read_height_array(path)


def test_npy_profile_float16_is_refused(tmp_path):
    path = tmp_path / "half.npy"
    np.save(path, np.column_stack([np.arange(50) * 10.0, np.random.default_rng(1).normal(0, 2, 50)])
            .astype(np.float16))
    with pytest.raises(DataFileError, match=r"half\.npy.*float16"):
        read_topography(path, unit="nm")


@pytest.mark.parametrize("value", [0.0, 3e-9], ids=["all-zero", "constant"])
def test_npy_map_constant_is_refused(tmp_path, value):
    path = tmp_path / "flat.npy"
    np.save(path, np.full((16, 16), value))
    with pytest.raises(DataFileError, match=r"flat\.npy.*every height.*constant map has no roughness"):
        read_height_array(path)


@pytest.mark.parametrize("value", [0.0, 3e-9], ids=["all-zero", "constant"])
def test_contact_surface_constant_npy_is_refused(cli, tmp_path, value):
    path = tmp_path / "flat.npy"
    np.save(path, np.full((16, 16), value))
    code, out, err = cli("contact", "--surface", path, "--physical-size", "1um", "--load", "1 uN")
    assert code == 2 and "no roughness" in err and not out


def test_npy_map_rough_float32_still_reads(tmp_path):
    path = tmp_path / "ok.npy"
    heights = _rough().astype(np.float32)
    np.save(path, heights)
    np.testing.assert_array_equal(read_height_array(path), heights.astype(float))


@pytest.mark.parametrize("value", [0.0, 5.0])
def test_constant_text_profile_says_constant_not_wrong_unit(tmp_path, value):
    path = tmp_path / "flat.txt"
    path.write_text("\n".join(f"{i * 0.01:.2f} {value}" for i in range(50)) + "\n")
    with pytest.raises(DataFileError, match=r"flat\.txt.*every height is .* constant surface has no roughness") as err:
        read_topography(path, unit="um")
    assert "unit" not in str(err.value).split("roughness")[0]
