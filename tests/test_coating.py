"""SAM coatings as parameter sets and the wear state Omega (thesis 5.3-5.4, 5.5.3)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from memstribo.coating import (
    Coating,
    available_coatings,
    check_wear,
    cof_at_wear,
    critical_wear,
    get_coating,
)
from memstribo.errors import InputError


def test_available_coatings():
    assert available_coatings() == ["FDTS", "OTS"]


def test_ots_values_and_sources():
    ots = get_coating("ots")
    assert ots.name == "OTS"
    # work of adhesion of a CH3-terminated pair, 2 gamma with gamma about 0.02-0.025 J/m^2
    assert 0.04 <= ots.work_of_adhesion <= 0.05
    # consistent with (3-34), w = A / (12 pi D0^2), to the printed digits
    assert ots.work_of_adhesion == pytest.approx(ots.hamaker_constant / (12 * math.pi * ots.cutoff_distance ** 2),
                                                 rel=1e-4)
    for key in ("vdw_bond_energy", "hamaker_constant", "cutoff_distance", "work_of_adhesion"):
        assert ots.sources[key]


def test_fdts_adheres_less_than_ots():
    ots, fdts = get_coating("OTS"), get_coating("FDTS")
    assert fdts.work_of_adhesion < ots.work_of_adhesion
    assert fdts.hamaker_constant < ots.hamaker_constant
    assert fdts.work_of_adhesion == pytest.approx(
        fdts.hamaker_constant / (12 * math.pi * fdts.cutoff_distance ** 2), rel=1e-4)


def test_coating_weaker_than_bare_silicon(params):
    ots = get_coating("OTS")
    assert ots.vdw_bond_energy < params["vdw_bond_energy"]
    assert ots.hamaker_constant < params["hamaker_constant"]


def test_unknown_coating_lists_available():
    with pytest.raises(InputError, match="available: FDTS, OTS"):
        get_coating("teflon")


def test_updated_checks_values():
    ots = get_coating("OTS")
    assert ots.updated(vdw_bond_energy=1e-22).vdw_bond_energy == 1e-22
    with pytest.raises(InputError, match="vdw_bond_energy"):
        ots.updated(vdw_bond_energy=-1.0)
    with pytest.raises(InputError, match="cannot change"):
        ots.updated(name="x")


@pytest.mark.parametrize("bad", [-0.1, 1.2, math.nan, [0.2, 1.5], []])
def test_wear_outside_zero_one(bad):
    with pytest.raises(InputError, match="wear"):
        check_wear(bad)


def _sweep(margins, cofs=None):
    wear = np.linspace(0, 1, len(margins))
    cofs = np.linspace(0.2, 0.8, len(margins)) if cofs is None else cofs
    return xr.Dataset({"stiction_margin": ("wear", np.asarray(margins, float)), "cof": ("wear", cofs)},
                      coords={"wear": wear})


def test_critical_wear_interpolates_the_margin():
    assert critical_wear(_sweep([2.0, 1.0, -1.0])) == pytest.approx(0.75)
    assert critical_wear(_sweep([2.0, 1.0, 0.5])) is None
    assert critical_wear(_sweep([-1.0, -2.0])) == 0.0


def test_cof_at_wear():
    sweep = _sweep([1, 1, 1], cofs=np.array([0.2, 0.4, 0.8]))
    np.testing.assert_allclose(cof_at_wear([0, 0.25, 1], sweep), [0.2, 0.3, 0.8])


@pytest.mark.parametrize("argv, match", [
    (["--wear", "1.5"], "wear"),
    (["--wear=-0.2"], "wear"),
    (["--wear", "0,x"], "wear"),
    (["--coating", "PTFE", "--wear", "0"], "unknown coating"),
])
def test_cli_bad_input(cli, argv, match):
    code, out, err = cli("coating", *argv)
    assert code == 2
    assert match in err and "Traceback" not in err


def test_coating_is_frozen():
    with pytest.raises(AttributeError):
        get_coating("OTS").name = "x"
    assert isinstance(get_coating("FDTS"), Coating)
