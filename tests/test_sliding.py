"""Sliding models (thesis 2.6.2, 3.4, 3.6) and the ``memstribo slide`` command."""

from __future__ import annotations

import numpy as np
import pytest

from memstribo.simulations import sliding
from memstribo.errors import InputError
from memstribo.surfaces.roughness import Profile

SPLIT = ("cof_chemical", "cof_vdw", "cof_elastic")
ENERGIES = ("energy_chemical", "energy_vdw", "energy_elastic")


@pytest.fixture(scope="module")
def params_m():
    """The default set with the thesis's vdW constants (U_chem / 100, A = 1.1e-18 J): the thesis's sliding models."""
    from memstribo.parameters import THESIS_VDW, get_parameter_values

    return get_parameter_values().updated(THESIS_VDW)


@pytest.fixture(scope="module")
def fixed_load(params_m):
    return sliding.slide_fixed_load(params_m, distance=2e-6)


@pytest.fixture(scope="module")
def fixed_gap(params_m):
    return sliding.slide_fixed_gap(params_m, distance=2e-6)


def _invariants(ds):
    for name in ENERGIES + ("friction_force", "normal_force", "adhesion_force", "bonds_chemical", "bonds_vdw"):
        assert np.all(ds[name].values >= 0), name
    np.testing.assert_allclose(sum(ds[n].values for n in SPLIT), ds["cof"].values, rtol=1e-12, atol=1e-15)
    assert np.all(ds["atomic_compression"].values >= 0)
    for name, var in ds.variables.items():
        assert "units" in var.attrs and "long_name" in var.attrs, name


def test_single_model(params_m):
    """2.6.2: constant COF, no elastic loss. Thesis: mu = 0.389, vdW loss 7 % below chemical.

    With our constants mu = 0.575 and the vdW loss is 0.5 % *above* the chemical loss: the
    thesis's 7 % comes from its N_chem = 7388.6 (not (19.5 nm / 2.35 A)^2 = 6885.5) and 0.389
    does not follow from its printed inputs (see docs/friction.md).
    """
    ds = sliding.slide_single(params_m)
    _invariants(ds)
    assert np.ptp(ds["cof"].values) == 0 and ds.sizes["step"] == 101
    assert np.all(ds["energy_elastic"].values == 0)
    summary = sliding.summarize(ds)
    assert summary.cof_mean == pytest.approx(_by_hand()[1], rel=1e-9)
    assert summary.energy_vdw / summary.energy_chemical == pytest.approx(1.0051, abs=1e-4)
    assert summary.normal_force_mean == pytest.approx(25e-6, rel=1e-12)
    # 25 uN on one atomic block: past the threshold, rigid (MODEL §4)
    assert ds["atomic_rigid"].values.all()
    # with the thesis's bond count, the vdW loss is 7 % below the chemical loss (2.6.2)
    thesis_like = sliding.summarize(sliding.slide_single(params_m.updated({"bond_energy": 7388.6 / 6885.47 * 5.43e-19})))
    assert 1 - thesis_like.energy_vdw / thesis_like.energy_chemical == pytest.approx(0.063, abs=0.01)


def test_fixed_load(fixed_load):
    _invariants(fixed_load)
    np.testing.assert_allclose(fixed_load["normal_force"].values, 25e-6, rtol=1e-10)
    assert fixed_load["load_residual"].values.max() < 1e-10
    summary = sliding.summarize(fixed_load)
    assert summary.load_residual < 1e-10
    # thesis 3.6 anchor: chemical > 60 %, elastic < 1 %, the rest vdW
    assert summary.fraction_chemical > 0.6
    assert summary.fraction_elastic < 0.01
    assert summary.fraction_vdw == pytest.approx(1 - summary.fraction_chemical - summary.fraction_elastic)
    assert summary.friction_force_mean == pytest.approx(sum(getattr(summary, e) for e in ENERGIES) / 2e-6, rel=1e-12)


def test_fixed_gap(fixed_gap, params_m):
    _invariants(fixed_gap)
    assert "load_residual" not in fixed_gap
    assert fixed_gap["atomic_in_contact"].values.max() > 0
    # a smaller gap presses harder
    closer = sliding.slide_fixed_gap(params_m, gap=0.0, distance=2e-6)
    assert closer["normal_force"].values.mean() > fixed_gap["normal_force"].values.mean()


@pytest.mark.parametrize("model", sliding.MODELS)
def test_zero_distance_dissipates_nothing(params_m, model):
    gap = 0.0 if model == "fixed-gap" else None  # tips at the mean line: in contact at the start
    ds = sliding.slide(model, params_m, distance=0.0, gap=gap)
    assert ds.sizes["step"] == 1
    summary = sliding.summarize(ds)
    assert summary.energy_chemical == summary.energy_vdw == summary.energy_elastic == 0.0


@pytest.mark.parametrize("model", ["fixed-load", "fixed-gap"])
def test_step_independence(params_m, model):
    """Once the step resolves the bond length, halving it changes the means by < 0.5 % (relative).

    The forces are exact at every step; what moves is the sampling of the bonded fractions of
    the faces (17 points per atomic face, 33 per adhesive face, on a grid aligned with the steps).
    """
    d = params_m["bond_length"]
    coarse = sliding.summarize(sliding.slide(model, params_m, distance=1e-6, step=d))
    fine = sliding.summarize(sliding.slide(model, params_m, distance=1e-6, step=d / 2))
    for key in ("cof_mean", "cof_chemical", "cof_vdw", "energy_chemical", "energy_vdw", "normal_force_mean"):
        assert getattr(fine, key) == pytest.approx(getattr(coarse, key), rel=5e-3), key
    assert fine.energy_elastic == pytest.approx(coarse.energy_elastic, rel=0.03)


def test_flat_counter_surface_matches_full_overlap(params_m):
    """On a flat profile every block touches over its full face: bonds are (w / D)^2 each, no interlocking."""
    x = np.arange(2000) * 1e-9
    flat = Profile(x=x, z=np.zeros_like(x), name="flat")
    ds = sliding.slide_fixed_load(params_m, flat, distance=100e-9)
    d = params_m["bond_length"]
    np.testing.assert_allclose(ds["bonds_chemical"].values, 2 * 9 * (19.5e-9 / d) ** 2, rtol=1e-12)
    np.testing.assert_allclose(ds["bonds_vdw"].values, 2 * (195.5e-9 / d) ** 2, rtol=1e-12)
    assert np.all(ds["energy_elastic"].values < 1e-30)
    # the load is shared equally by the 18 atomic blocks
    np.testing.assert_allclose(ds["atomic_stress"].values, 25e-6 / 18 / 19.5e-9**2, rtol=1e-9)


def test_real_afm_profile(params_m, afm_dir):
    from memstribo.surfaces.readers import read_topography

    profile = read_topography(afm_dir / "si_profile_linescan.txt")
    ds = sliding.slide_fixed_load(params_m, profile, distance=0.3e-6)
    _invariants(ds)
    assert ds.attrs["synthetic_profile"] == 0 and "si_profile_linescan" in ds.attrs["profile_source"]


def test_bad_input(params_m):
    with pytest.raises(InputError, match="load must be a positive"):
        sliding.slide_fixed_load(params_m, load=-1e-6, distance=1e-8)
    with pytest.raises(InputError, match="no atomic block touches"):
        sliding.slide_fixed_gap(params_m, gap=50e-9, distance=1e-7)
    short = Profile(x=np.arange(100) * 1e-9, z=np.zeros(100), name="short")
    with pytest.raises(InputError, match="shorter than the sliding structure"):
        sliding.slide_fixed_load(params_m, short)
    with pytest.raises(InputError, match="does not fit"):
        sliding.slide_fixed_load(params_m, distance=1.0)
    with pytest.raises(InputError, match="distance must be >= 0"):
        sliding.slide_single(params_m, distance=-1e-9)
    with pytest.raises(InputError, match="step must be a positive"):
        sliding.slide_single(params_m, step=0.0)
    with pytest.raises(InputError, match="unknown sliding model"):
        sliding.slide("sticky", params_m)
    with pytest.raises(InputError, match="takes a gap, not a load"):
        sliding.slide("fixed-gap", params_m, load=1e-6)
    with pytest.raises(InputError, match="span"):
        sliding.slide_fixed_load(params_m.updated({"atomic_pitch": "100 nm"}), distance=1e-8)


KEYS = {"cof_mean", "cof_chemical", "cof_vdw", "cof_elastic", "friction_force_mean", "adhesion_force_mean",
        "normal_force_mean", "sliding_distance",
        "energy_chemical", "energy_vdw", "energy_elastic"}


def test_cli_json(cli):
    out = cli.json("slide", "--model", "fixed-load", "--distance", "0.5 um", "--load", "25 uN")
    assert KEYS <= set(out) and "load_residual" in out
    assert out["normal_force_mean"] == pytest.approx(25e-6)
    gap = cli.json("slide", "--model", "fixed-gap", "--distance", "0.5 um", "--gap", "1 nm")
    assert KEYS <= set(gap) and "load_residual" not in gap
    from memstribo.parameters import THESIS_VDW_FLAGS

    single = cli.json("slide", "--model", "single", *THESIS_VDW_FLAGS.split())
    assert single["cof_mean"] == pytest.approx(_by_hand()[1], rel=1e-9)
    estimate = cli.json("slide", "--model", "estimate", *THESIS_VDW_FLAGS.split())
    assert estimate["thesis_inputs_cof"] == pytest.approx(0.8142, abs=5e-5)
    assert estimate["cof"] == pytest.approx(_by_hand()[9], rel=1e-9)


def test_cli_text_and_out(cli, tmp_path, afm_dir):
    code, out, err = cli("slide", "--model", "fixed-load", "--profile", afm_dir / "si_profile_linescan.txt",
                         "--distance", "100 nm", "--out", tmp_path)
    assert code == 0, err
    assert "cof" in out and "µN" in out
    for name in ("slide.nc", "slide_steps.csv", "slide_cof.png", "slide_cof.svg", "slide_shrink.png"):
        assert (tmp_path / name).is_file(), name
    import xarray as xr

    with xr.open_dataset(tmp_path / "slide.nc") as ds:
        assert ds["friction_force"].attrs["units"] == "N"
        assert ds.sizes["block"] == 2 and ds.sizes["atomic"] == 9


@pytest.mark.parametrize("argv, message", [
    (["--model", "fixed-load", "--load", "-5 uN"], "--load must be a positive"),
    (["--model", "fixed-gap", "--gap", "1 um", "--distance", "0.1 um"], "no atomic block touches"),
    (["--model", "fixed-load", "--distance", "1 m"], "does not fit"),
    (["--model", "fixed-load", "--load", "3 m"], "units"),
    (["--model", "single", "--profile", "x.txt"], "flat surface"),
    (["--model", "fixed-load", "--profile", "/nonexistent/profile.txt"], ""),
    (["--model", "estimate", "--distance", "1 um"], "only --load"),
])
def test_cli_bad_input(cli, argv, message):
    code, out, err = cli("slide", *argv)
    assert code == 2
    assert "Traceback" not in err and message in err


def test_too_many_steps(params_m):
    with pytest.raises(InputError, match="more than 1e6"):
        sliding.slide_single(params_m, distance=1e-3)


def test_physical_limits_are_warnings(params):
    """MODEL 7c: results past what silicon can carry say so (the issue's 22-213 GPa at 300 uN)."""
    from memstribo.simulations.sliding import slide, summarize

    heavy = summarize(slide("fixed-load", params.updated({"normal_load": "300 uN"}), distance=20e-9))
    assert heavy.max_atomic_stress > params["elastic_limit_pressure"]
    assert any("elastic limit" in text for text in heavy.warnings)
    assert any("ideal shear strength" in text for text in heavy.warnings) == (
        heavy.max_shear_stress > params["ideal_shear_strength"])
    relaxed = summarize(slide("fixed-load", params.updated({"normal_load": "300 uN", "elastic_limit_pressure": "1 TPa",
                                                             "ideal_shear_strength": "1 TPa"}), distance=20e-9))
    assert relaxed.warnings == []
    assert "warnings" in heavy.to_dict() and "max_shear_stress" in heavy.to_dict()


def _by_hand():
    """mu of 3.5 from the set's inputs by hand: (3-34) w = A/(12 pi D0^2), (3-33) C_NS, (3-32) F_adh,1 =
    sqrt(8 pi w E* C_NS a^3) with a = w_adh/2, N = (w/D)^2 bonds, (3-7)/(3-10)/(3-12) mu = n (N_chem U_chem +
    N_vdW U_vdW) / ((F_ext + n F_adh,1) D): (single nanoblock n = 1, the 3.5 estimate n = 9)."""
    import math

    e, nu, hamaker, d0 = 161e9, 0.23, 1.1e-18, 2.56e-10
    u_chem, u_vdw, d, w_at, w_adh, load = 5.43e-19, 5.43e-21, 2.35e-10, 19.5e-9, 195.5e-9, 25e-6
    e_star = e / (2 * (1 - nu**2))
    w = hamaker / (12 * math.pi * d0**2)
    c_ns = (1 - nu) * math.log(3 - 4 * nu) / (1 - 2 * nu)
    f1 = math.sqrt(8 * math.pi * w * e_star * c_ns * (w_adh / 2) ** 3)
    energy = (w_at / d) ** 2 * u_chem + (w_adh / d) ** 2 * u_vdw
    return {n: n * energy / ((load + n * f1) * d) for n in (1, 9)}  # 0.5752, 0.9599
