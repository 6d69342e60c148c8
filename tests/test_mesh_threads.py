"""The rows' contact solves on threads (simulations/mesh/threads.py, issue 40): the same numbers, bit for bit."""

import threading

import numpy as np
import pytest

from memstribo.api import parameter_set
from memstribo.errors import InputError
from memstribo.references import collect_references, cites
from memstribo.simulations.mesh import simulate_mesh
from memstribo.simulations.mesh import threads as mesh_threads
from memstribo.simulations.mesh.threads import MIN_ELEMENTS, ordered_map, row_threads


def test_threads_only_where_a_solve_is_long_and_there_are_rows(monkeypatch):
    monkeypatch.setenv("MEMSTRIBO_THREADS", "2")
    assert row_threads(MIN_ELEMENTS, 40) == 2
    assert row_threads(MIN_ELEMENTS - 1, 40) == 1  # the default cycle's ~130-element windows: one thread
    assert row_threads(MIN_ELEMENTS, 1) == 1
    assert row_threads(MIN_ELEMENTS, 40, compiled=False) == 1  # the plain dense solve's BLAS calls: one thread
    assert row_threads(10**5, 40) == 1  # past the compiled loop's grids
    monkeypatch.setenv("MEMSTRIBO_THREADS", "8")
    assert row_threads(4096, 3) == 3  # at most the rows
    monkeypatch.setenv("MEMSTRIBO_THREADS", "1")
    assert row_threads(4096, 40) == 1
    monkeypatch.delenv("MEMSTRIBO_THREADS")
    monkeypatch.setattr(mesh_threads, "_cores", lambda: 1)
    assert row_threads(4096, 40) == 1


@pytest.mark.parametrize("value", ["0", "two", "-1"])
def test_a_bad_thread_count_is_named(monkeypatch, value):
    monkeypatch.setenv("MEMSTRIBO_THREADS", value)
    with pytest.raises(InputError, match="MEMSTRIBO_THREADS must be a whole number >= 1"):
        row_threads(4096, 40)


def test_ordered_map_keeps_the_order_runs_on_threads_and_raises_at_the_item():
    names = []

    def square(x):
        names.append(threading.current_thread().name)
        return x * x

    assert list(ordered_map(square, range(9), 3)) == [x * x for x in range(9)]
    assert all(name.startswith("memstribo-rows") for name in names)
    assert list(ordered_map(square, range(5), 1)) == [x * x for x in range(5)]

    def fails_at_four(x):
        if x == 4:
            raise ValueError("four")
        return x

    seen = []
    with pytest.raises(ValueError, match="four"):
        for value in ordered_map(fails_at_four, range(9), 2):
            seen.append(value)
    assert seen == [0, 1, 2, 3]


def test_what_the_threads_cite_is_collected_by_the_caller():
    @cites("model")
    def cited(x):
        return x

    with collect_references() as used:
        assert list(ordered_map(cited, range(4), 2)) == [0, 1, 2, 3]
    assert "model" in used


def test_a_cycle_with_its_rows_on_threads_equals_the_cycle_row_by_row(monkeypatch):
    monkeypatch.setattr(mesh_threads, "MIN_ELEMENTS", 1)  # the default cycle's small windows on threads too
    params = parameter_set()
    monkeypatch.setenv("MEMSTRIBO_THREADS", "1")
    one = simulate_mesh(params, steps=21)
    monkeypatch.setenv("MEMSTRIBO_THREADS", "3")
    three = simulate_mesh(params, steps=21)
    assert one.attrs == three.attrs
    for name in one.data_vars:
        assert np.array_equal(one[name].values, three[name].values, equal_nan=True), name
