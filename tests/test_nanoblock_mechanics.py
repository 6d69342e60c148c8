"""Nanoblock mechanics: columns (2-6)-(2-8), hierarchical structures, interlocking (3-25)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.physics.nanoblock.mechanics import (
    BlockStiffness,
    axial_stiffness,
    column_fixed_gap,
    column_fixed_load,
    elastic_interlocking_energy,
    structure_fixed_gap,
    structure_fixed_load,
    structure_interlocking_energy,
)

E, E_STAR = 161e9, 85e9


@pytest.fixture
def geometry():
    """The chapter-4 nanoblock of the default parameter set (MODEL §1.4)."""
    return SimpleNamespace(atomic_width=19.5e-9, atomic_height=0.82e-9, adhesive_width=195.5e-9,
                           adhesive_height=5e-9, atomic_per_side=3, bulk_height=None)


@pytest.fixture
def stiffness(geometry):
    return BlockStiffness.from_geometry(geometry, E, E_STAR, 0.3)


def _brute_column(overlap, k):
    """Reference: bisection on the column compression u (independent of the knot algorithm)."""
    lo, hi = 0.0, max(overlap.max(), 0.0) + 1e-9
    f = lambda u: k.column * u - (k.atomic * np.clip(overlap - u, 0, k.atomic_threshold)).sum()
    if f(0.0) >= 0:
        u = 0.0
    else:
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
        u = 0.5 * (lo + hi)
    u = max(u, overlap.max() - k.atomic_threshold)
    return k.column * u


def test_stiffness_values(stiffness):
    # k = E A / H (3-24): E* (19.5 nm)^2 / 0.82 nm; bulk E (195.5 nm)^2 / 195.5 nm
    assert stiffness.atomic == pytest.approx(85e9 * 19.5e-9**2 / 0.82e-9, rel=1e-12)
    assert stiffness.adhesive == pytest.approx(85e9 * 195.5e-9**2 / 5e-9, rel=1e-12)
    assert stiffness.bulk == pytest.approx(161e9 * 195.5e-9, rel=1e-12)
    assert stiffness.bulk_height == 195.5e-9  # unset -> adhesive_width (MODEL §4)
    assert stiffness.atomic_threshold == pytest.approx(0.3 * 0.82e-9)
    assert 1 / stiffness.column == pytest.approx(1 / stiffness.adhesive + 1 / stiffness.bulk)


def test_model_sanity_strains(stiffness):
    """MODEL §4: 25 uN on one atomic block strains it ~77 %; shared by 9 blocks ~9 %."""
    strain_one = 25e-6 / stiffness.atomic / stiffness.atomic_height
    assert strain_one == pytest.approx(0.77, abs=0.005)
    assert strain_one / 9 == pytest.approx(0.086, abs=0.001)  # MODEL prints "~9 %"


def test_one_atomic_block_turns_rigid(stiffness):
    """25 uN on a single touching block: it stops at 30 % and the column carries the rest."""
    overlap = np.full((1, 9), -1e-9)
    overlap[0, 0] = 0.0
    state = structure_fixed_load(overlap, stiffness, 25e-6)
    assert state.rigid[0, 0] and state.rigid.sum() == 1
    assert state.atomic_compression[0, 0] == pytest.approx(stiffness.atomic_threshold, rel=1e-12)
    assert state.atomic_force[0, 0] == pytest.approx(25e-6, rel=1e-12)
    assert state.adhesive_compression[0] == pytest.approx(25e-6 / stiffness.adhesive, rel=1e-12)
    # approach = threshold + column compression
    assert state.approach == pytest.approx(stiffness.atomic_threshold + 25e-6 / stiffness.column, rel=1e-12)


def test_nine_equal_blocks_share_the_load(stiffness):
    overlap = np.zeros((1, 9))
    state = structure_fixed_load(overlap, stiffness, 25e-6)
    assert not state.rigid.any()
    strain = state.atomic_compression / stiffness.atomic_height
    np.testing.assert_allclose(strain, 25e-6 / 9 / stiffness.atomic / stiffness.atomic_height, rtol=1e-12)


def test_fixed_gap_matches_bisection(stiffness):
    rng = np.random.default_rng(3)
    overlap = rng.normal(0.0, 0.4e-9, (60, 2, 9))
    state = structure_fixed_gap(overlap, stiffness)
    ref = np.array([[_brute_column(overlap[i, j], stiffness) for j in range(2)] for i in range(60)])
    np.testing.assert_allclose(state.adhesive_force, ref, rtol=1e-9, atol=1e-18)
    assert np.all(state.approach == 0) and np.all(state.residual == 0)


def test_structure_invariants(stiffness):
    rng = np.random.default_rng(4)
    overlap = rng.normal(0.0, 0.4e-9, (500, 2, 9))
    state = structure_fixed_gap(overlap, stiffness)
    assert np.all(state.atomic_force >= 0) and np.all(state.atomic_compression >= 0)
    assert np.all(state.atomic_compression <= stiffness.atomic_threshold * (1 + 1e-12))
    # equilibrium: atomic forces add up to the adhesive force; total = sum of nanoblocks
    np.testing.assert_allclose(state.atomic_force.sum(-1), state.adhesive_force, rtol=1e-10, atol=1e-20)
    np.testing.assert_allclose(state.adhesive_force.sum(-1), state.total_force, rtol=1e-12)
    # unilateral: blocks that do not reach the counter surface carry nothing
    assert np.all(state.atomic_force[overlap <= 0] == 0)
    # compatibility: every touching elastic block closes its gap exactly
    u = state.adhesive_compression + state.bulk_compression
    touching = state.atomic_force > 0
    gap_closed = overlap - u[..., None] - state.atomic_compression
    assert np.all(np.abs(gap_closed[touching]) < 1e-18)
    assert np.all(gap_closed[~touching] <= 1e-18)
    assert np.all(state.shrink >= 0)


@pytest.mark.parametrize("load", [1e-7, 5e-6, 25e-6, 2e-4, 1e-2])
def test_fixed_load_balance_and_consistency(stiffness, load):
    rng = np.random.default_rng(5)
    overlap = rng.normal(0.0, 0.5e-9, (300, 2, 9))
    state = structure_fixed_load(overlap, stiffness, load)
    assert state.residual.max() < 1e-10
    np.testing.assert_allclose(state.total_force, load, rtol=1e-10)
    # the same approach under a fixed gap gives the same state
    again = structure_fixed_gap(overlap + state.approach[:, None, None], stiffness)
    np.testing.assert_allclose(again.adhesive_force, state.adhesive_force, rtol=1e-9, atol=1e-18)


def test_fixed_load_monotone_in_load(stiffness):
    rng = np.random.default_rng(6)
    overlap = np.broadcast_to(rng.normal(0.0, 0.5e-9, (2, 9)), (50, 2, 9))
    loads = np.geomspace(1e-8, 1e-3, 50)
    state = structure_fixed_load(overlap, stiffness, loads)
    assert np.all(np.diff(state.approach) > 0)
    assert np.all(np.diff(state.shrink.max(-1)) >= 0)


def test_column_fixed_gap_closed_form():
    # (2-3) with equal areas: delta_1 = (h + sum H - G) / (1 + E1 H2/(E2 H1) + E1 H3/(E3 H1))
    h, heights, moduli, areas = 1e-9, [1e-9, 2e-9, 10e-9], [85e9, 85e9, 161e9], [1e-16, 1e-16, 1e-16]
    gap = 12e-9
    state = column_fixed_gap(gap, h, heights, moduli, areas)
    d1 = (h + sum(heights) - gap) / (1 + 85e9 * 2e-9 / (85e9 * 1e-9) + 85e9 * 10e-9 / (161e9 * 1e-9))
    assert state.compressions[0] == pytest.approx(d1, rel=1e-12)
    assert state.compressions[1] == pytest.approx(d1 * 2, rel=1e-12)
    # geometry (2-1): h + sum(H - delta) = G
    assert h + sum(heights) - state.compressions.sum() == pytest.approx(gap, rel=1e-12)
    # equal forces in series (2-5)
    k = np.array(moduli) * np.array(areas) / np.array(heights)
    np.testing.assert_allclose(state.compressions * k, state.force, rtol=1e-12)
    # no contact, no force (unilateral)
    assert column_fixed_gap(20e-9, h, heights, moduli, areas).force == 0


def test_column_fixed_load_inverts_fixed_gap():
    args = (0.5e-9, [0.82e-9, 5e-9, 195.5e-9], [85e9, 85e9, 161e9], [19.5e-9**2, 195.5e-9**2, 195.5e-9**2])
    loaded = column_fixed_load(25e-6, *args)
    # MODEL §4: ~77 % atomic strain at 25 uN (the single column has no bilinear cap)
    assert loaded.compressions[0] / 0.82e-9 == pytest.approx(0.773, abs=1e-3)
    back = column_fixed_gap(loaded.gap, *args)
    assert back.force == pytest.approx(25e-6, rel=1e-10)


def test_interlocking_energy():
    assert elastic_interlocking_energy(40.0, 0.1e-9) == pytest.approx(0.5 * 40 * 1e-20)
    assert elastic_interlocking_energy(40.0, -0.1e-9) == elastic_interlocking_energy(40.0, 0.1e-9)


def test_structure_interlocking_energy(stiffness):
    rng = np.random.default_rng(7)
    overlap = rng.normal(0.0, 0.4e-9, (40, 2, 9))
    states = structure_fixed_gap(overlap, stiffness)
    atomic, adhesive = structure_interlocking_energy(states, stiffness)
    assert atomic.shape == (40,) and atomic[0] == 0 and adhesive[0] == 0
    assert np.all(atomic >= 0) and np.all(adhesive >= 0)
    # a structure that does not move dissipates nothing
    still = structure_fixed_gap(np.broadcast_to(overlap[0], (10, 2, 9)), stiffness)
    assert not np.any(np.concatenate(structure_interlocking_energy(still, stiffness)))


def test_bad_input(stiffness, geometry):
    with pytest.raises(InputError, match="load must be a positive"):
        structure_fixed_load(np.zeros((2, 9)), stiffness, -1e-6)
    with pytest.raises(InputError, match="finite"):
        structure_fixed_gap(np.full((2, 9), np.nan), stiffness)
    with pytest.raises(InputError, match="shape"):
        structure_fixed_gap(np.zeros(9), stiffness)
    with pytest.raises(InputError, match="positive"):
        BlockStiffness.from_geometry(geometry, -1.0, E_STAR, 0.3)
    with pytest.raises(InputError, match="threshold_strain"):
        BlockStiffness.from_geometry(geometry, E, E_STAR, 0.0)
    wide = SimpleNamespace(**{**vars(geometry), "atomic_per_side": 11})
    with pytest.raises(InputError, match="do not fit"):
        BlockStiffness.from_geometry(wide, E, E_STAR, 0.3)
    with pytest.raises(InputError, match="load"):
        column_fixed_load(-1.0, 0.0, [1, 1, 1], [1, 1, 1], [1, 1, 1])
    with pytest.raises(InputError, match="3 values"):
        column_fixed_gap(1.0, 0.0, [1, 1], [1, 1], [1, 1])
    with pytest.raises(InputError, match="positive"):
        axial_stiffness(0.0, 1.0, 1.0)
    with pytest.raises(InputError, match="stiffness"):
        elastic_interlocking_energy(-1.0, 1e-9)
