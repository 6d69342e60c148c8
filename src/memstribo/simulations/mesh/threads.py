"""The rows' contact solves of a meshing cycle on threads (issue 40 item 4: the cores a machine has, where it pays).

Each roughness row's contact solves (every step of the row, each started from the step before it) depend on no other
row, and the compiled zone loop that takes most of their time (:mod:`memstribo.physics._zone_kernel`) runs without
Python's lock. On grids of :data:`MIN_ELEMENTS` elements and more (a solve of a millisecond and more: the thesis load
case's 1300- and 2600-element windows) with the Maugis-Dugdale zone (the compiled loop) the rows are solved on
:func:`row_threads` threads, the next rows while this thread adds up the last; the results are taken in row order, so every number is the one the rows solved one after
the other give, bit for bit (tests/test_mesh_threads.py). Below it (the default cycle's ~130-element windows, solves
of ~50 us, mostly Python) the threads would wait on each other: one thread. Inside a Dask worker (an ensemble, an
uncertainty study: one worker per core already) one thread.

``MEMSTRIBO_THREADS`` (an environment variable, a whole number >= 1) sets the threads; by default the cores this
process may run on, at most :data:`MAX_THREADS`.
"""

from __future__ import annotations

import os
import sys
from collections import deque

__all__ = ["MIN_ELEMENTS", "MAX_THREADS", "row_threads", "ordered_map"]

#: Grids of at least this many elements solve their rows on threads (a solve takes ~1 ms at 1300 elements, ~0.05 ms
#: at the default cycle's ~130, where Python's share of a solve would keep the threads waiting on each other).
MIN_ELEMENTS = 512

#: At most this many threads (the step loop's own Python work between the rows keeps one busy).
MAX_THREADS = 4


def _cores() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def _in_dask_worker() -> bool:
    """Whether this process is a Dask worker running a task (its cores are the cluster's to share)."""
    if "distributed" not in sys.modules:
        return False
    try:
        from distributed import get_worker

        get_worker()
    except (ImportError, ValueError):
        return False
    return True


def row_threads(elements: int, rows: int, compiled: bool = True) -> int:
    """Threads to solve ``rows`` rows of contacts on a grid of ``elements`` elements [count]: 1 below
    :data:`MIN_ELEMENTS` or above the compiled loop's grids (``SolverSettings.zone_kernel_max``), where the solves are
    not the compiled zone loop's (``compiled`` False: the plain dense solve's LAPACK and BLAS calls from two threads
    wait on each other, the validation table's coated teeth 20 -> 43 s), for one row or inside a Dask worker; else
    ``MEMSTRIBO_THREADS`` or the cores (at most :data:`MAX_THREADS`), at most the rows.

    Raises
    ------
    InputError
        ``MEMSTRIBO_THREADS`` that is not a whole number >= 1.
    """
    chosen = os.environ.get("MEMSTRIBO_THREADS")
    if chosen is not None:
        try:
            threads = int(chosen)
        except ValueError:
            threads = 0
        if threads < 1:
            from memstribo.errors import InputError

            raise InputError(f"MEMSTRIBO_THREADS must be a whole number >= 1 (the threads of a cycle's contact "
                             f"solves), got {chosen!r}.")
    else:
        threads = min(_cores(), MAX_THREADS)
    from memstribo.physics.contact import settings

    if (not compiled or elements < MIN_ELEMENTS or elements > settings.DEFAULTS.zone_kernel_max or rows < 2
            or threads < 2 or _in_dask_worker()):
        return 1
    return min(threads, rows)


def ordered_map(function, items, threads: int):
    """``function(item)`` of each item, yielded in the order of ``items``; on ``threads`` threads where more than one
    (at most ``threads`` items ahead of the one yielded: each result is held until it is taken). The threads run in
    this thread's reference collectors (:func:`memstribo.references.collect_references`), so that what they cite is
    recorded where the caller collects it. An exception of ``function`` is raised here, at its item."""
    items = list(items)
    if threads < 2 or len(items) < 2:
        for item in items:
            yield function(item)
        return
    from concurrent.futures import ThreadPoolExecutor

    from memstribo.references import _local

    collectors = _local.collectors

    def task(item):
        _local.collectors = collectors
        try:
            return function(item)
        finally:
            _local.collectors = None

    pending = deque()
    pool = ThreadPoolExecutor(max_workers=threads, thread_name_prefix="memstribo-rows")
    try:
        upcoming = iter(items)
        for item in upcoming:
            pending.append(pool.submit(task, item))
            if len(pending) >= threads:
                break
        while pending:
            result = pending.popleft().result()
            for item in upcoming:
                pending.append(pool.submit(task, item))
                break
            yield result
    finally:
        for future in pending:
            future.cancel()
        pool.shutdown(wait=True)
