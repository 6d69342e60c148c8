"""Roughness parameters: closed forms, PCHIP, synthetic profiles, thesis numbers, bad input, CLI."""

from __future__ import annotations

import math

import numpy as np
import pytest

from memstribo.surfaces import roughness as r
from memstribo.errors import InputError
from memstribo.surfaces.roughness import Profile

from conftest import AFM

A = 2.0e-9           # amplitude [m]
WAVELENGTH = 100e-9  # [m]
PER_PERIOD = 1000


@pytest.fixture(scope="module")
def sine():
    """20 whole periods of A sin(2 pi x / wavelength), 1000 points per period (endpoint excluded)."""
    n = 20 * PER_PERIOD
    x = np.arange(n) * (WAVELENGTH / PER_PERIOD)
    return x, A * np.sin(2 * np.pi * x / WAVELENGTH)


# --- closed forms ---------------------------------------------------------------------------
def test_sine_heights(sine):
    _, z = sine
    # uniform samples over whole periods: Rq is exact; Ra has an O(1/N^2) sampling error
    assert r.rms_height(z) == pytest.approx(A / math.sqrt(2), rel=1e-12)
    assert r.arithmetic_mean_height(z) == pytest.approx(2 * A / math.pi, rel=1e-5)
    assert r.skewness(z) == pytest.approx(0.0, abs=1e-9)
    assert r.kurtosis(z) == pytest.approx(1.5, rel=1e-9)
    assert r.max_peak_height(z) == pytest.approx(A, rel=1e-12)
    assert r.max_valley_depth(z) == pytest.approx(A, rel=1e-12)
    assert r.max_height(z) == pytest.approx(2 * A, rel=1e-12)
    assert r.Ra is r.arithmetic_mean_height and r.Rq is r.rms_height


def test_sine_slope_and_wavelength(sine):
    x, z = sine
    dq = r.rms_slope(z, x=x)
    # continuum value 2 pi A / (sqrt 2 wavelength); first differences lose (pi dx / wavelength)^2 / 6 ~ 1.6e-6,
    # and the n - 1 slopes miss one of the 20000 steps of whole periods (a steep one): ~2.5e-5. Tolerance 1e-4.
    assert dq == pytest.approx(2 * np.pi * A / (math.sqrt(2) * WAVELENGTH), rel=1e-4)
    assert r.rms_slope(z, sample_spacing=x[1]) == pytest.approx(dq, rel=1e-12)
    assert r.rms_wavelength(r.rms_height(z), dq) == pytest.approx(WAVELENGTH, rel=1e-4)


def test_rms_slope_uses_n_minus_one():
    # (4-6): n points, n - 1 slopes, divided by n - 1: a straight line of slope 0.3 gives 0.3
    x = np.linspace(0, 1e-6, 7)
    assert r.rms_slope(0.3 * x, x=x) == pytest.approx(0.3, rel=1e-12)


def test_asperity_width_of_sine(sine):
    x, z = sine
    # above c = A/2: sin > 1/2 over a third of each period; crossings are interpolated linearly
    assert r.mean_asperity_width(z, 0.5 * A, x=x) == pytest.approx(WAVELENGTH / 3, rel=1e-5)
    assert r.mean_asperity_width(z, 0.0, x=x) == pytest.approx(WAVELENGTH / 2, rel=1e-5)
    # the first period starts on the mean line going up: the run above -A/2 that begins before
    # the scan is cut off and left out; 19 complete runs remain
    widths = r.asperity_widths(z, -0.5 * A, x=x)
    assert widths.size == 19
    assert widths.mean() == pytest.approx(2 * WAVELENGTH / 3, rel=1e-5)


def test_asperity_width_needs_a_complete_run(sine):
    x, z = sine
    with pytest.raises(InputError, match="no complete asperity"):
        r.mean_asperity_width(z, 1.1 * A, x=x)
    with pytest.raises(InputError, match="no complete asperity"):
        r.mean_asperity_width(z[:300], -0.5 * A, x=x[:300])


def test_rice_formula_on_gaussian_profile():
    """Mean width above u for a Gaussian profile: lambda_q Q(u/Rq) exp(u^2 / 2 Rq^2) (Rice).

    Statistical tolerance 3 % for 65536 points (about 500 lambda_q). At u = +0.5 Rq this is
    0.3496 lambda_q; the thesis's chapter-3 ratio w_at / lambda_q = 22.48 / 64.35 = 0.3493.
    """
    from scipy.stats import norm

    profile = r.synthetic_profile(65536.0, 1.0, 1.0, 0.05, rng=1)
    stats = r.profile_statistics(profile)
    for k in (0.5, -1.2):
        expected = stats.lambda_q * norm.sf(k) * math.exp(k * k / 2)
        assert r.mean_asperity_width(profile, k * stats.Rq) == pytest.approx(expected, rel=0.03)


def test_bearing_area_curve(sine):
    _, z = sine
    ratio, levels = r.bearing_area_curve(z)
    assert np.all(np.diff(ratio) > 0) and np.all(np.diff(levels) <= 0)
    assert ratio[-1] == 1.0 and levels[0] == z.max()
    at, _ = r.bearing_area_curve(z, [1.01 * A, 0.0, 0.5 * A, -1.01 * A])
    assert at[0] == 0.0 and at[3] == 1.0
    # samples that fall exactly on a level count as "at or above" it (up to 20 points of 20000)
    assert at[1] == pytest.approx(0.5, abs=10 / z.size)
    assert at[2] == pytest.approx(1 / 3, abs=10 / z.size)


# --- levelling ------------------------------------------------------------------------------
def test_level_profile_removes_line(sine):
    x, z = sine
    cosine = A * np.cos(2 * np.pi * x / WAVELENGTH)
    tilted = cosine + 3e-9 + 0.02 * x
    levelled = r.level_profile(tilted, x=x)
    # a whole-period cosine is (nearly) orthogonal to a line: the fit leaves it unchanged
    assert np.allclose(levelled, cosine - cosine.mean(), rtol=0, atol=1e-3 * A)
    assert abs(levelled.mean()) < 1e-20 and abs(np.polyfit(x, levelled, 1)[0]) < 1e-12
    profile = r.level_profile(Profile(x=x, z=tilted, name="t"))
    assert isinstance(profile, Profile) and np.allclose(profile.z, levelled)


def test_level_plane_removes_plane():
    rng = np.random.default_rng(3)
    pattern = rng.standard_normal((40, 60)) * 1e-9
    y, x = np.mgrid[0:40, 0:60] * 1e-8
    residual = r.level_plane(pattern + 5e-9 + 0.01 * x - 0.03 * y, 1e-8, 1e-8)
    expected = r.level_plane(pattern, 1e-8, 1e-8)
    assert np.allclose(residual, expected, rtol=0, atol=1e-20)
    design = np.column_stack([np.ones(x.size), x.ravel(), y.ravel()])
    assert np.allclose(design.T @ residual.ravel(), 0, atol=1e-20)  # orthogonal to the plane


def test_areal_and_line_scan_statistics():
    rng = np.random.default_rng(4)
    h = rng.standard_normal((30, 50)) * 2e-9 + np.linspace(0, 1e-8, 50)
    areal = r.areal_statistics(h, 1e-8, 1e-8)
    flat = r.level_plane(h).ravel()
    assert areal.Sq == pytest.approx(np.sqrt(np.mean(flat ** 2)), rel=1e-12)
    assert areal.Sa == pytest.approx(np.mean(np.abs(flat)), rel=1e-12)
    assert areal.Sz == pytest.approx(areal.Sp + areal.Sv, rel=1e-12)
    lines = r.line_scan_statistics(h, 1e-8)
    rows = [r.profile_statistics(Profile(x=np.arange(50) * 1e-8, z=row)) for row in h]
    assert lines.n_line_scans == 30 and lines.n_points == 50
    assert lines.Rq == pytest.approx(np.sqrt(np.mean([s.Rq ** 2 for s in rows])), rel=1e-12)
    assert lines.Ra == pytest.approx(np.mean([s.Ra for s in rows]), rel=1e-12)
    assert lines.rms_slope == pytest.approx(np.sqrt(np.mean([s.rms_slope ** 2 for s in rows])), rel=1e-12)
    assert lines.Rz == pytest.approx(np.mean([s.Rz for s in rows]), rel=1e-12)
    assert lines.Rsk == pytest.approx(np.mean([s.Rsk for s in rows]), rel=1e-9)


# --- PCHIP ----------------------------------------------------------------------------------
def test_pchip_reproduces_linear_data_and_the_points():
    x = np.arange(11) * 78e-9
    z = 2e-9 + 0.01 * x
    x_new, z_new = r.resample_pchip(z, 39e-9, x=x)
    assert x_new.size == 21 and x_new[-1] == pytest.approx(x[-1])
    assert np.allclose(z_new, 2e-9 + 0.01 * x_new, rtol=1e-12, atol=0)
    rng = np.random.default_rng(0)
    wiggly = rng.standard_normal(11) * 1e-9
    _, w_new = r.resample_pchip(wiggly, 39e-9, x=x)
    assert np.allclose(w_new[::2], wiggly, rtol=1e-12, atol=1e-24)


def test_pchip_does_not_overshoot():
    x = np.arange(8) * 1.0
    z = np.array([0, 0, 0, 1, 1, 1, 0.5, 0.5])
    x_new, z_new = r.resample_pchip(z, 0.01, x=x)
    assert z_new.min() >= 0 and z_new.max() <= 1          # no new extrema
    rising = (x_new >= 2) & (x_new <= 3)
    assert np.all(np.diff(z_new[rising]) >= 0)               # monotone where the data are
    flat = (x_new >= 0) & (x_new <= 2)
    assert np.all(z_new[flat] == 0)


def test_pchip_fritsch_carlson_value():
    # interior slopes: harmonic mean of the neighbouring secants (equal steps): d1 = 4/3, d2 = 0.8;
    # Hermite cubic at the midpoint of [1, 2]: (y1 + y2)/2 + h (d1 - d2)/8
    x = np.array([0.0, 1.0, 2.0, 3.0])
    z = np.array([0.0, 1.0, 3.0, 3.5])
    x_new, z_new = r.resample_pchip(z, 0.5, x=x)
    assert z_new[3] == pytest.approx(2.0 + (4 / 3 - 0.8) / 8, rel=1e-12)


def test_resample_profile_keeps_provenance():
    p = Profile(x=np.arange(5) * 1e-8, z=np.array([0, 1, 0, 1, 0]) * 1e-9, name="p", source="file")
    q = r.resample_pchip(p, 5e-9)
    assert q.n_points == 9 and "PCHIP" in q.source and q.name == "p"


@pytest.mark.parametrize("step", [0.0, -1e-9, float("nan"), 1.0])
def test_resample_bad_step(step):
    p = Profile(x=np.arange(5) * 1e-8, z=np.arange(5) * 1e-9)
    with pytest.raises(InputError, match="resampling step"):
        r.resample_pchip(p, step)


# --- synthetic profiles ---------------------------------------------------------------------
def test_synthetic_profile_exact_statistics():
    p = r.synthetic_profile(20e-6, 78e-9, 1.6235e-9, 0.0241, rng=7)
    assert p.synthetic and "synthetic" in p.source
    assert p.n_points == 256 and p.sample_spacing == pytest.approx(78e-9)
    assert r.rms_height(p) == pytest.approx(1.6235e-9, rel=1e-9)
    assert r.rms_slope(p) == pytest.approx(0.0241, rel=1e-9)
    assert abs(p.z.mean()) < 1e-12 * 1.6235e-9                     # levelled
    assert abs(np.polyfit(p.x, p.z, 1)[0]) < 1e-12


def test_synthetic_profile_reproducible_per_seed():
    a = r.synthetic_profile(10e-6, 50e-9, 1e-9, 0.02, rng=11)
    b = r.synthetic_profile(10e-6, 50e-9, 1e-9, 0.02, rng=11)
    c = r.synthetic_profile(10e-6, 50e-9, 1e-9, 0.02, rng=12)
    d = r.synthetic_profile(10e-6, 50e-9, 1e-9, 0.02, rng=np.random.default_rng(11))
    assert np.array_equal(a.z, b.z) and np.array_equal(a.z, d.z)
    assert not np.allclose(a.z, c.z, rtol=1e-3, atol=0)
    assert r.rms_height(c) == pytest.approx(1e-9, rel=1e-9)  # another seed, the same statistics


def test_synthetic_profile_does_not_touch_global_state():
    np.random.seed(0)
    before = np.random.random()
    np.random.seed(0)
    r.synthetic_profile(10e-6, 50e-9, 1e-9, 0.02, rng=5)
    assert np.random.random() == before


def test_synthetic_profile_bad_input():
    with pytest.raises(InputError, match="too steep"):
        r.synthetic_profile(10e-6, 78e-9, 1e-9, 0.1, rng=1)       # rms slope / Rq above white noise (~sqrt 2 / dx)
    with pytest.raises(InputError, match="does not fit"):
        r.synthetic_profile(2e-6, 10e-9, 1e-9, 1e-5, rng=1)       # lambda_q = 628 um in 2 um
    with pytest.raises(InputError, match="at least 16 points"):
        r.synthetic_profile(1e-6, 78e-9, 1e-9, 0.02, rng=1)
    with pytest.raises(InputError, match="rq must be a positive"):
        r.synthetic_profile(10e-6, 78e-9, -1e-9, 0.02, rng=1)
    with pytest.raises(InputError, match="rng must be a numpy Generator"):
        r.synthetic_profile(10e-6, 78e-9, 1e-9, 0.02, rng=1.5)


def test_default_profile(params):
    p = r.default_profile(params)
    assert p.synthetic and "not published" in p.source
    assert p.sample_spacing == pytest.approx(39e-9) and p.n_points == 511
    raw = r.default_profile(params, spacing=params["roughness_sample_spacing"])
    assert raw.n_points == 256
    # the chapter-4 statistics hold exactly at the measured 78 nm step (thesis 4.2.3: 1.6235 nm, 0.0241)
    assert r.rms_height(raw) == pytest.approx(1.6235e-9, rel=1e-9)
    assert r.rms_slope(raw) == pytest.approx(0.0241, rel=1e-9)
    # PCHIP to 39 nm goes through the 78 nm points
    assert np.allclose(p.z[::2], raw.z, rtol=0, atol=1e-22)
    fine = r.default_profile(params, length=5e-6, spacing=5e-9)
    assert fine.sample_spacing == pytest.approx(5e-9) and fine.x[-1] < 5e-6
    unresampled = r.default_profile(params.updated({"roughness_resample_spacing": None}))
    assert unresampled.n_points == 256


def test_thesis_lambda_q_does_not_follow_from_printed_values():
    # MODEL §1.3: 2 pi Rq / Delta_q with the thesis's printed Rq and Delta_q gives ~423 nm (ch. 4)
    # and ~421 nm (ch. 3), not the printed 58.4 nm and 64.35 nm. We keep the formula.
    assert r.rms_wavelength(1.6235e-9, 0.0241) == pytest.approx(423.27e-9, rel=1e-4)
    assert r.rms_wavelength(1.6433e-9, 0.0245) == pytest.approx(421.44e-9, rel=1e-4)


# --- Profile and statistics: bad input ---------------------------------------------------
def test_profile_validation():
    with pytest.raises(InputError, match="same length"):
        Profile(x=np.arange(3.0), z=np.arange(4.0))
    with pytest.raises(InputError, match="at least 2"):
        Profile(x=[0.0], z=[0.0])
    with pytest.raises(InputError, match="1 NaN or infinite"):
        Profile(x=np.arange(3.0), z=[0.0, np.nan, 1.0])
    with pytest.raises(InputError, match="strictly increasing"):
        Profile(x=[0.0, 2.0, 1.0], z=[0.0, 1.0, 2.0])


def test_profile_is_read_only():
    p = Profile(x=np.arange(3.0), z=np.arange(3.0))
    with pytest.raises(ValueError):
        p.z[0] = 5.0


def test_statistics_bad_input():
    with pytest.raises(InputError, match="at least 3"):
        r.profile_statistics(Profile(x=[0.0, 1.0], z=[0.0, 1.0]))
    with pytest.raises(InputError, match="flat after levelling"):
        r.profile_statistics(Profile(x=np.arange(5.0), z=2.0 * np.arange(5.0)))
    with pytest.raises(InputError, match="needs a Profile"):
        r.profile_statistics(np.arange(5.0))
    with pytest.raises(InputError, match="x .m. or sample_spacing"):
        r.rms_slope(np.arange(5.0))
    with pytest.raises(InputError, match="strictly increasing"):
        r.rms_slope(np.arange(3.0), x=[0.0, 1.0, 1.0])
    with pytest.raises(InputError, match="strictly increasing"):
        r.level_profile(np.arange(3.0), x=[0.0, 0.0, 0.0])
    with pytest.raises(InputError, match="sample_spacing must be a positive"):
        r.rms_slope(np.arange(3.0), sample_spacing=0.0)
    with pytest.raises(InputError, match="NaN or infinite"):
        r.rms_height([1.0, np.nan])
    with pytest.raises(InputError, match="flat profile"):
        r.skewness(np.ones(5))
    with pytest.raises(InputError, match="positive rms slope"):
        r.rms_wavelength(1e-9, 0.0)
    with pytest.raises(InputError, match=r"shape \(ny, nx\)"):
        r.level_plane(np.ones(5))
    with pytest.raises(InputError, match="flat after levelling"):
        r.areal_statistics(np.ones((4, 4)))


# --- CLI ------------------------------------------------------------------------------------
def test_cli_linescan(cli):
    out = cli.json("roughness", AFM / "si_profile_linescan.txt")
    for key in ("Ra", "Rq", "Rsk", "Rku", "Rp", "Rv", "Rz", "rms_slope", "lambda_q", "n_points", "sample_spacing",
                "length"):
        assert key in out
    assert out["Rq"] == pytest.approx(4.468e-9, abs=0.5e-12)  # README: 4.468 nm
    assert out["n_points"] == 512 and out["synthetic"] is False


def test_cli_map(cli):
    out = cli.json("roughness", AFM / "IgorIBWReader_P0089OP0027.ibw")
    assert out["Sq"] == pytest.approx(8.094e-9, abs=0.5e-12) and out["n_line_scans"] == 256
    assert out["channel"] == "HeightRetrace" and "Sa" in out
    assert out["sample_spacing"] == pytest.approx(7.8125e-9)


def test_cli_thesis_and_resample(cli):
    out = cli.json("roughness", "thesis", "--resample", "78 nm")
    assert out["synthetic"] is True and "not published" in out["source"]
    assert out["Rq"] == pytest.approx(1.6235e-9, rel=1e-9) and out["rms_slope"] == pytest.approx(0.0241, rel=1e-9)
    code, text, _ = cli("roughness", "thesis")
    assert code == 0 and "SYNTHETIC" in text and " nm" in text


def test_cli_map_resample(cli):
    out = cli.json("roughness", AFM / "IgorIBWReader_P0089OP0027.ibw", "--resample", "3.90625 nm")
    assert out["sample_spacing"] == pytest.approx(3.90625e-9) and out["n_points"] == 511
    assert out["Sq"] == pytest.approx(8.094e-9, abs=0.5e-12)  # areal values are of the map as measured


def test_cli_save_profile_round_trip(cli, tmp_path):
    target = tmp_path / "out" / "thesis.txt"
    out = cli.json("roughness", "thesis", "--resample", "10 nm", "--save-profile", target)
    from memstribo.surfaces.readers import read_topography

    again = read_topography(target)
    assert again.n_points == out["n_points"] and again.sample_spacing == pytest.approx(10e-9, rel=1e-12)
    assert r.profile_statistics(again).Rq == pytest.approx(out["Rq"], rel=1e-12)
    assert "SYNTHETIC" in target.read_text().splitlines()[0]
    code, _, err = cli("roughness", "thesis", "--save-profile", tmp_path / "x.png")
    assert code == 2 and "must end in .txt or .csv" in err and "Traceback" not in err


def test_cli_text_output_has_units(cli):
    code, text, err = cli("roughness", AFM / "opdx-3.opdx")
    assert code == 0 and "Rq" in text and "2.826 nm" in text


@pytest.mark.parametrize("argv,message", [
    (["roughness", "missing.txt"], "file not found"),
    (["roughness", str(AFM / "README.md")], "unknown format"),
    (["roughness", str(AFM / "di-3.di"), "--channel", "Topo"], "no channel 'Topo'"),
    (["roughness", str(AFM / "si_profile_linescan.txt"), "--resample", "-5 nm"], "--resample must be a positive"),
    (["roughness", str(AFM / "si_profile_linescan.txt"), "--resample", "5 kg"], "resample"),
    (["roughness", str(AFM / "si_profile_linescan.txt"), "--unit", "furlong"], "unknown length unit"),
    (["roughness", str(AFM / "si_profile_linescan.txt"), "--resample", "2 um"], "longer than the profile"),
])
def test_cli_bad_input(cli, argv, message):
    code, out, err = cli(*argv)
    assert code == 2
    assert message in err and "Traceback" not in err
