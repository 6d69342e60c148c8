"""Process heap settings for large FFT grids (glibc).

glibc serves allocations above 128 KiB with fresh ``mmap`` pages and unmaps them when they are
freed, so every FFT of a large grid (its output array and pocketfft's scratch buffer, ~1 MiB
each for a 2^16-point free-boundary line contact) pays ~256 page faults. On the benchmark
machine the system time of a 2^16-point contact solve equalled its user time
(bench/bench_adhesive_contact.py, docs/contact.md "Adhesive contact", speed). Keeping freed
blocks in the heap removes that cost; the arithmetic, and so every result, is unchanged.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import sys

__all__ = ["keep_freed_memory"]

#: glibc's malloc.h option numbers
_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3
#: glibc's largest accepted mmap threshold on 64-bit systems [bytes]
_MAX_MMAP_THRESHOLD = 32 * 2**20


def keep_freed_memory(threshold: int = _MAX_MMAP_THRESHOLD) -> bool:
    """Serve allocations up to ``threshold`` [bytes] from the heap and keep freed memory for reuse.

    Sets glibc's mmap threshold to ``threshold`` and its trim threshold to four times that, so
    arrays of up to ``threshold`` bytes are no longer mapped and unmapped at every allocation.
    The effect is process-wide, so the library does not call this by itself; the benchmarks
    do. The command line does not: it raised the damage stage's peak memory from 12 to 16 GB. A no-op where the C library is not
    glibc (other systems, or a platform without ``mallopt``).

    Parameters
    ----------
    threshold : int, optional
        Largest allocation served from the heap [bytes], 128 KiB to 32 MiB (default 32 MiB).

    Returns
    -------
    bool
        True if both thresholds were set, False where that is not possible.

    Examples
    --------
    >>> keep_freed_memory() in (True, False)
    True
    """
    threshold = int(threshold)
    if not 128 * 1024 <= threshold <= _MAX_MMAP_THRESHOLD:
        from memstribo.errors import InputError

        raise InputError(f"keep_freed_memory: threshold must lie in 128 KiB .. 32 MiB [bytes], got {threshold}")
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes, mallopt.restype = (ctypes.c_int, ctypes.c_int), ctypes.c_int
    return bool(mallopt(_M_MMAP_THRESHOLD, threshold)) and bool(mallopt(_M_TRIM_THRESHOLD, 4 * threshold))
