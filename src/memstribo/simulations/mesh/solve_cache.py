"""Contact solves kept by their inputs, so that cycles that differ only in what the contact does not see share
them (issue 40 item 2).

A row's contact solve over a cycle (:func:`memstribo.simulations.mesh.contacts._solve_contacts`) depends only on
its inputs: the separation of every step, the grid spacing, the contact modulus, the line loads, the tolerance, the
Maugis-Dugdale zone (sigma0, h0), the menisci, the hardness and the solver's settings. The uncertainty study's
samples that differ only in the block mechanics (block sizes, threshold strain) or in the bond energies have the same
inputs, so their rows' solves are the same, bit for bit. While :func:`keep_solves` is on, each row's solve is kept
under a digest of those inputs (BLAKE2b of their bytes and values) and handed back on the next identical call (a copy:
the result is that of a new solve, bit-identical); the least recently used are dropped beyond ``max_bytes``. Off
(the default): nothing is kept.
"""

from __future__ import annotations

import contextlib
import hashlib
import threading
from collections import OrderedDict

import numpy as np

__all__ = ["keep_solves", "stop_keeping", "solves_kept", "kept_solves", "solve_digest", "lookup", "store", "DEFAULT_BYTES"]

#: bytes of solves kept by default per process (a default cycle's row: ~0.9 MB; 256 MiB: ~28 cycles of 10 rows)
DEFAULT_BYTES = 256 * 2**20

_STATE = {"store": None, "bytes": 0, "max_bytes": 0, "hits": 0, "misses": 0}

#: lookups and stores of the rows solved on threads (simulations/mesh/threads.py) one at a time
_LOCK = threading.Lock()


def keep_solves(max_bytes: int = DEFAULT_BYTES) -> None:
    """Keep the rows' contact solves (at most ``max_bytes`` [B]) from now on in this process; idempotent."""
    if _STATE["store"] is None:
        _STATE.update(store=OrderedDict(), bytes=0, hits=0, misses=0)
    _STATE["max_bytes"] = int(max_bytes)


def stop_keeping() -> dict:
    """Forget every kept solve and keep none from now on; returns the hit and miss counts."""
    counts = {"hits": _STATE["hits"], "misses": _STATE["misses"]}
    _STATE.update(store=None, bytes=0, max_bytes=0, hits=0, misses=0)
    return counts


@contextlib.contextmanager
def solves_kept(max_bytes: int = DEFAULT_BYTES):
    """Keep the rows' contact solves inside a ``with`` block (cycles that differ in nothing the contact solve reads:
    the wear states of one coating, a calibration's bond energies); a store kept already (an enclosing uncertainty
    study) stays as it is, and is not stopped at the end."""
    if _STATE["store"] is not None:
        yield
        return
    keep_solves(max_bytes)
    try:
        yield
    finally:
        stop_keeping()


def kept_solves() -> dict:
    """{"rows", "bytes", "hits", "misses"} of the solves kept now."""
    store = _STATE["store"]
    return {"rows": 0 if store is None else len(store), "bytes": _STATE["bytes"], "hits": _STATE["hits"],
            "misses": _STATE["misses"]}


def solve_digest(arrays, values) -> str | None:
    """The digest of a row solve's inputs (``arrays``: numpy arrays, ``values``: anything with a faithful repr),
    or None while no solves are kept."""
    if _STATE["store"] is None:
        return None
    h = hashlib.blake2b(digest_size=20)
    for a in arrays:
        a = np.ascontiguousarray(a)
        h.update(repr((a.dtype.str, a.shape)).encode())
        h.update(a.tobytes())
    h.update(repr(values).encode())
    return h.hexdigest()


def lookup(key):
    """The kept (pressure, gap, info) of ``key`` as fresh copies, or None."""
    with _LOCK:
        return _lookup(key)


def _lookup(key):
    store = _STATE["store"]
    if key is None or store is None or key not in store:
        if key is not None and store is not None:
            _STATE["misses"] += 1
        return None
    store.move_to_end(key)
    _STATE["hits"] += 1
    return tuple(a.copy() for a in store[key])


def store(key, arrays) -> None:
    """Keep copies of ``arrays`` under ``key`` (dropping the least recently used beyond the byte limit)."""
    with _LOCK:
        _store(key, arrays)


def _store(key, arrays) -> None:
    kept = _STATE["store"]
    if key is None or kept is None:
        return
    copies = tuple(np.array(a, copy=True) for a in arrays)
    size = sum(a.nbytes for a in copies)
    if size > _STATE["max_bytes"]:
        return
    kept[key] = copies
    _STATE["bytes"] += size
    while _STATE["bytes"] > _STATE["max_bytes"]:
        _, dropped = kept.popitem(last=False)
        _STATE["bytes"] -= sum(a.nbytes for a in dropped)
