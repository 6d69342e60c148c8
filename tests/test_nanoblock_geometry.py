"""Nanoblock geometry: the parameter set (thesis ch. 4), the derivation from a profile (MODEL §1.4), CLI."""

from __future__ import annotations

import math

import numpy as np
import pytest

from memstribo.surfaces import roughness as r
from memstribo.errors import InputError
from memstribo.physics.nanoblock.geometry import NanoblockGeometry, nanoblock_geometry_from_profile
from memstribo.surfaces.readers import SurfaceMap
from memstribo.surfaces.roughness import Profile

from conftest import AFM

KEYS = ("atomic_width", "atomic_height", "adhesive_width", "adhesive_height", "atomic_pitch", "atomic_per_side",
        "bulk_height")


@pytest.fixture(scope="module")
def gaussian():
    """A long seeded Gaussian profile (lambda_q = 2 pi * 40 nm, ~800 lambda_q long)."""
    return r.synthetic_profile(200e-6, 2e-9, 1e-9, 0.025, rng=3)


def test_from_parameters_is_thesis_chapter_4(params):
    g = NanoblockGeometry.from_parameters(params)
    # thesis 4.2.3, Figure 4-23; MODEL §1.4 (H_at = 0.5 Rq = 0.82 nm; H_bulk = w_adh, MODEL §4)
    assert g.atomic_width == pytest.approx(19.5e-9)
    assert g.atomic_height == pytest.approx(0.82e-9)
    assert g.adhesive_width == pytest.approx(195.5e-9)
    assert g.adhesive_height == pytest.approx(5e-9)
    assert g.atomic_pitch == pytest.approx(58.4e-9)
    assert g.atomic_per_side == 3 and g.n_atomic == 9
    assert g.bulk_height == pytest.approx(195.5e-9)
    assert set(g.rules) == set(KEYS)
    assert "unset" in g.rules["bulk_height"] and "parameter set" in g.rules["atomic_width"]


def test_from_parameters_with_overrides(params):
    g = NanoblockGeometry.from_parameters(params.updated({"bulk_height": "1 um", "atomic_per_side": 4}))
    assert g.bulk_height == pytest.approx(1e-6) and g.atomic_per_side == 4  # 3 x 58.4 + 19.5 = 194.7 <= 195.5 nm
    assert "--set" in g.rules["bulk_height"] or "override" in g.rules["bulk_height"]


def test_geometry_validation(params):
    base = NanoblockGeometry.from_parameters(params).to_dict()
    base.pop("rules")
    with pytest.raises(InputError, match="span .* more than adhesive_width"):
        NanoblockGeometry(**{**base, "atomic_per_side": 5})
    with pytest.raises(InputError, match="would overlap"):
        NanoblockGeometry(**{**base, "atomic_width": 60e-9})
    with pytest.raises(InputError, match="atomic_height must be a positive length"):
        NanoblockGeometry(**{**base, "atomic_height": -1e-9})
    with pytest.raises(InputError, match="integer >= 1"):
        NanoblockGeometry(**{**base, "atomic_per_side": 0})
    with pytest.raises(InputError, match="integer >= 1"):
        NanoblockGeometry(**{**base, "atomic_per_side": 2.5})


def test_from_profile_follows_the_rules(gaussian):
    g = nanoblock_geometry_from_profile(gaussian)
    stats = r.profile_statistics(gaussian)
    levelled = r.level_profile(gaussian)
    assert g.atomic_height == pytest.approx(0.5 * stats.Rq, rel=1e-12)
    assert g.adhesive_height == pytest.approx(1.2 * stats.Rq, rel=1e-12)
    assert g.atomic_width == pytest.approx(r.mean_asperity_width(levelled, 0.5 * stats.Rq), rel=1e-12)
    assert g.adhesive_width == pytest.approx(r.mean_asperity_width(levelled, -1.2 * stats.Rq), rel=1e-12)
    assert g.atomic_pitch == pytest.approx(stats.lambda_q, rel=1e-12)
    assert g.atomic_per_side == math.floor(g.adhesive_width / stats.lambda_q) >= 1
    assert g.bulk_height == g.adhesive_width
    assert set(g.rules) == set(KEYS)
    assert "0.5 Rq" in g.rules["atomic_height"] and "lambda_q" in g.rules["atomic_pitch"]
    # hierarchy: the adhesive block is wider than the atomic blocks it carries
    assert g.adhesive_width > g.atomic_pitch > g.atomic_width


def test_from_profile_gaussian_closed_form(gaussian):
    # Rice: mean width above u = lambda_q Q(u / Rq) exp(u^2 / 2 Rq^2): 0.3496 lambda_q at +0.5 Rq and
    # 1.818 lambda_q at -1.2 Rq (statistical tolerance 3 % for ~800 lambda_q), so m = 1.
    from scipy.stats import norm

    g = nanoblock_geometry_from_profile(gaussian)
    assert g.atomic_width / g.atomic_pitch == pytest.approx(norm.sf(0.5) * math.exp(0.125), rel=0.03)
    assert g.adhesive_width / g.atomic_pitch == pytest.approx(norm.sf(-1.2) * math.exp(0.72), rel=0.03)
    assert g.atomic_per_side == 1


def test_from_map_pools_line_scans(gaussian):
    rows = gaussian.z[: 20 * 5000].reshape(20, 5000)
    surface = SurfaceMap(heights=rows, dx=gaussian.sample_spacing, dy=gaussian.sample_spacing, name="m")
    from_map = nanoblock_geometry_from_profile(surface)
    from_list = nanoblock_geometry_from_profile(surface.line_scans())
    assert from_map.to_dict() == from_list.to_dict()
    levelled = [r.level_profile(p) for p in surface.line_scans()]
    rq = np.sqrt(np.mean([np.mean(p.z ** 2) for p in levelled]))
    assert from_map.atomic_height == pytest.approx(0.5 * rq, rel=1e-12)
    widths = np.concatenate([r.asperity_widths(p, 0.5 * rq) for p in levelled])
    assert from_map.atomic_width == pytest.approx(widths.mean(), rel=1e-12)
    assert "20 line scan(s)" in from_map.rules["atomic_height"]


def test_explicit_bulk_height_and_factors(gaussian):
    g = nanoblock_geometry_from_profile(gaussian, bulk_height=1e-6, atomic_height_factor=0.4)
    assert g.bulk_height == 1e-6 and g.rules["bulk_height"] == "given"
    assert g.atomic_height == pytest.approx(0.4 * r.rms_height(r.level_profile(gaussian)), rel=1e-12)


def test_sine_gives_no_whole_atomic_block():
    # a pure sine: lambda_q = wavelength, and the runs above -1.2 Rq are 0.82 wavelengths wide: m = 0
    x = np.arange(20000) * 1e-10
    sine = Profile(x=x, z=1e-9 * np.cos(2 * np.pi * x / 1e-7))
    with pytest.raises(InputError, match=r"m = floor\(w_adh / lambda_q\) = 0"):
        nanoblock_geometry_from_profile(sine)


def test_from_profile_bad_input(gaussian):
    short = Profile(x=gaussian.x[:40], z=gaussian.z[:40])
    with pytest.raises(InputError, match="no complete asperity"):
        nanoblock_geometry_from_profile(short)
    with pytest.raises(InputError, match="flat after levelling"):
        nanoblock_geometry_from_profile(Profile(x=np.arange(10.0), z=np.arange(10.0)))
    with pytest.raises(InputError, match="atomic_height_factor must be a positive"):
        nanoblock_geometry_from_profile(gaussian, atomic_height_factor=0.0)
    with pytest.raises(InputError, match="needs a Profile"):
        nanoblock_geometry_from_profile(np.arange(10.0))


# --- CLI ------------------------------------------------------------------------------------
def test_cli_parameters(cli):
    out = cli.json("nanoblock")
    assert set(KEYS) | {"rules"} <= set(out)
    assert out["adhesive_width"] == pytest.approx(195.5e-9) and out["atomic_per_side"] == 3
    out = cli.json("nanoblock", "--set", "adhesive_width=200 nm")
    assert out["adhesive_width"] == pytest.approx(200e-9) and out["bulk_height"] == pytest.approx(200e-9)


def test_cli_from_file(cli):
    out = cli.json("nanoblock", "--from", AFM / "si_profile_linescan.txt")
    assert out["atomic_height"] == pytest.approx(0.5 * 4.4679e-9, rel=1e-4)
    assert out["atomic_pitch"] == pytest.approx(100.48e-9, rel=1e-4)
    assert out["atomic_per_side"] == 1 and set(out["rules"]) == set(KEYS)
    code, text, _ = cli("nanoblock", "--from", "thesis")
    assert code == 0 and "SYNTHETIC" in text and "rules:" in text


@pytest.mark.parametrize("argv,message", [
    (["nanoblock", "--from", str(AFM / "opdx-3.opdx")], "m = floor(w_adh / lambda_q) = 0"),
    (["nanoblock", "--from", "missing.txt"], "file not found"),
    (["nanoblock", "--set", "atomic_per_side=5"], "more than adhesive_width"),
    (["nanoblock", "--set", "atomic_width=-3 nm"], "atomic_width"),
])
def test_cli_bad_input(cli, argv, message):
    code, out, err = cli(*argv)
    assert code == 2 and message in err and "Traceback" not in err
