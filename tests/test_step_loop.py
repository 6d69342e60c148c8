"""The step loop's array helpers (issue #25 item 5: the cycle made faster without changing a number): each gives, bit
for bit, what the per-step numpy calls it replaced gave."""

import types

import numpy as np
import pytest

from memstribo.errors import InputError
from memstribo.simulations.mesh.steps import _bracket, _interp_rows, _pair_overlaps


def _bits(a):
    return np.asarray(a, dtype=float).view(np.int64)


def test_interp_rows_is_np_interp_row_by_row():
    rng = np.random.default_rng(7)
    for trial in range(60):
        n = int(rng.integers(2, 60))
        xp = np.unique(rng.normal(size=n)) if trial % 2 else (np.arange(n) - 0.5 * (n - 1)) * 2.5e-8
        if xp.size < 2:
            continue
        rows = int(rng.integers(1, 12))
        fp = rng.normal(size=(rows, xp.size)) * 10.0 ** int(rng.integers(-12, 3))
        x = rng.uniform(xp[0] - 0.3 * np.ptp(xp), xp[-1] + 0.3 * np.ptp(xp), size=(rows, 7, 3))
        x[:, 0, 0], x[:, 0, 1], x[:, 0, 2] = xp[0], xp[-1], xp[xp.size // 2]  # on the nodes and the ends
        x[0, 1, 0] = np.nan
        for left, right in ((fp[:, 0], fp[:, -1]), (1.0, 1.0), (rng.normal(size=rows), -2.0)):
            got = _interp_rows(x, xp, fp, left, right)
            lo = np.broadcast_to(np.reshape(left, -1), (rows,))
            hi = np.broadcast_to(np.reshape(right, -1), (rows,))
            want = np.stack([np.interp(x[i].ravel(), xp, fp[i], lo[i], hi[i]) for i in range(rows)]).reshape(x.shape)
            assert np.array_equal(_bits(got), _bits(want)) or np.array_equal(got, want, equal_nan=True)


def test_bracket_is_searchsorted():
    rng = np.random.default_rng(3)
    for trial in range(100):
        n = int(rng.integers(2, 300))
        xp = (np.unique(rng.normal(size=n)) if trial % 3 == 0
              else (np.arange(n) - 0.5 * (n - 1)) * 10.0 ** int(rng.integers(-9, 1)) + rng.normal() * 1e-7)
        if xp.size < 2:
            continue
        x = rng.uniform(xp[0] - 1.0, xp[-1] + 1.0, size=(4, 50)) if trial % 2 else rng.choice(xp, size=(4, 50))
        x[0, :3] = np.nan, np.inf, -np.inf
        assert np.array_equal(_bracket(xp, x), np.searchsorted(xp, x, side="right") - 1)


def test_bracket_needs_no_binary_search_on_a_uniform_grid(monkeypatch):
    """On the cycle's uniform grids the intervals come from the spacing, corrected against the grid (points on the
    nodes and one ulp beside them included), without the fallback to np.searchsorted."""
    rng = np.random.default_rng(5)
    cases = []
    for n in (2, 3, 96, 97, 171, 1117):
        xp = (np.arange(n) - 0.5 * (n - 1)) * 24.8e-9 + rng.normal() * 1e-8
        x = np.concatenate([xp, np.nextafter(xp, -np.inf), np.nextafter(xp, np.inf),
                            rng.uniform(xp[0] - 1e-7, xp[-1] + 1e-7, 500)]).reshape(1, -1)
        cases.append((xp, x, np.searchsorted(xp, x, side="right") - 1))

    def no_search(*args, **kwargs):
        raise AssertionError("fell back to np.searchsorted")

    monkeypatch.setattr(np, "searchsorted", no_search)
    for xp, x, want in cases:
        assert np.array_equal(_bracket(xp, x), want)


def test_pair_overlaps_are_the_dense_sums():
    rng = np.random.default_rng(11)
    ctx = types.SimpleNamespace()
    w_at = 1.95e-8
    for _ in range(20):
        steps, a, b = (int(v) for v in rng.integers(1, 60, size=3))
        xa1 = np.sort(rng.uniform(-2e-7, 2e-7, (steps, a)), axis=1)
        xa2 = np.sort(rng.uniform(-2e-7, 2e-7, (steps, b)), axis=1)
        t1, t2 = rng.random((steps, a)) < rng.random(), rng.random((steps, b)) < rng.random()
        r1, r2 = rng.random((steps, a)) < 0.1, rng.random((steps, b)) < 0.1
        dense = np.clip(w_at - np.abs(xa1[:, :, None] - xa2[:, None, :]), 0.0, None) * (t1[:, :, None] & t2[:, None, :])
        overlap, rigid = _pair_overlaps(ctx, xa1, xa2, t1, t2, r1, r2, w_at)
        assert np.array_equal(_bits(overlap), _bits(dense.sum(axis=(1, 2))))
        assert np.array_equal(_bits(rigid), _bits((dense * (r1[:, :, None] | r2[:, None, :])).sum(axis=(1, 2))))
        assert not ctx.pair_terms.any()  # the kept array is zero again for the next row


def test_the_quicker_input_checks_keep_their_rules():
    from memstribo.physics.contact import solve_line_contact
    from memstribo.physics.contact.inputs import _finite_number

    for value in (1.0, np.float64(2.0), 3, np.int32(4), np.float32(5.0), True, np.nan, np.inf, np.float64(-np.inf),
                  -1.0):
        assert _finite_number(value) == bool(np.isscalar(value) and np.isfinite(value))
    assert not _finite_number(np.array([1.0])) and not _finite_number([1.0])
    x = (np.arange(64) - 31.5) * 1e-9
    h = x**2 / 4e-5
    good = dict(load=0.1, cohesive_stress=1e9, cohesive_range=2e-10)
    assert solve_line_contact(h, 1e-9, 1e11, **good).converged
    for bad, match in (({"initial_pressure": np.full(64, -2e9)}, ">= -cohesive_stress"),
                       ({"initial_pressure": np.r_[np.nan, np.zeros(63)]}, "finite"),
                       ({"initial_pressure": np.zeros(63)}, "same shape"),
                       ({"load": float("nan")}, "finite number"),
                       ({"cohesive_range": -1.0}, "cohesive_range")):
        with pytest.raises(InputError, match=match):
            solve_line_contact(h, 1e-9, 1e11, **{**good, **bad})
    with pytest.raises(InputError, match=">= 0 and"):
        solve_line_contact(h, 1e-9, 1e11, load=0.1, initial_pressure=np.full(64, -1.0))
    with pytest.raises(InputError, match="dx must be a positive finite number"):
        solve_line_contact(h, float("inf"), 1e11, **good)
    with pytest.raises(InputError, match="NaN or infinite"):
        solve_line_contact(np.r_[np.inf, h[1:]], 1e-9, 1e11, **good)
