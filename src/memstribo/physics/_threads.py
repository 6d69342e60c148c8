"""One BLAS thread per process for the contact solver's dense algebra (issue 40).

The dense contact path (:mod:`memstribo.physics.contact.dense`) multiplies and factorises matrices of at most a few
thousand rows, thousands of times a cycle. OpenBLAS runs such calls on every core it finds and spin-waits for its
threads between calls; where the cores are already busy (the run's Dask workers, pytest-xdist, a second job) its
threads wait on each other: one thesis-case cycle of 121 steps took 65.5 s of CPU with two BLAS threads on a loaded
2-core machine against 2.9 s with one (bench/README.md, "BLAS threads"). Each process of memstribo is one worker;
the parallelism is across processes (Dask), not inside a BLAS call.

:func:`limit_blas_threads` sets every loaded BLAS library (numpy's and scipy's OpenBLAS, or MKL) to one thread,
once per process, when the dense path is first imported, unless the user chose a thread count through the usual
environment variables (``OPENBLAS_NUM_THREADS``, ``OMP_NUM_THREADS``, ``MKL_NUM_THREADS``) or
``MEMSTRIBO_BLAS_THREADS`` (a number, or ``keep`` to leave the libraries as they are). Dask's nanny already starts its
workers with one BLAS thread each (``distributed.nanny.pre-spawn-environ``); this covers the main process and
processes Dask does not start.
"""

from __future__ import annotations

import os

__all__ = ["limit_blas_threads", "USER_VARIABLES"]

#: environment variables through which a user has chosen the BLAS thread count: respected as given
USER_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")

_done: int | None | bool = False  # the limit applied (None: left as it was), or False before the first call


def _wanted() -> int | None:
    """The thread count to set: 1, MEMSTRIBO_BLAS_THREADS, or None where the user chose (or asked to keep)."""
    from memstribo.errors import InputError

    text = os.environ.get("MEMSTRIBO_BLAS_THREADS", "").strip().lower()
    if text:
        if text == "keep":
            return None
        try:
            value = int(text)
        except ValueError:
            value = 0
        if value < 1:
            raise InputError(f"MEMSTRIBO_BLAS_THREADS must be a whole number >= 1 or 'keep', got '{text}'.")
        return value
    if any(os.environ.get(name, "").strip() for name in USER_VARIABLES):
        return None
    return 1


def limit_blas_threads() -> int | None:
    """Set the loaded BLAS libraries to one thread (or ``MEMSTRIBO_BLAS_THREADS``), once per process; returns the
    count set, or None where the user's environment chose it. Call after numpy and scipy.linalg are imported (a
    library loaded later keeps its own count)."""
    global _done
    if _done is False:
        wanted = _wanted()
        if wanted is not None:
            from threadpoolctl import threadpool_limits

            threadpool_limits(limits=wanted, user_api="blas")  # stays in force: the process's setting
        _done = wanted
    return _done
