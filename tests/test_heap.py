"""memstribo.heap: the glibc allocator setting the benchmarks use (process-wide: tried in a child process, so that
the test run's own heap keeps glibc's defaults)."""

from __future__ import annotations

import sys

import pytest

from memstribo.errors import InputError
from memstribo.heap import keep_freed_memory


def test_threshold_range():
    for bad in (0, 64 * 1024, 64 * 2**20):
        with pytest.raises(InputError, match="threshold"):
            keep_freed_memory(bad)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc only")
def test_glibc_accepts_and_results_are_unchanged():
    import subprocess

    code = """
import numpy as np
from memstribo.heap import keep_freed_memory
from memstribo.physics.contact import solve_line_contact
x = (np.arange(4096) - 2047.5) * 1e-9
h = x**2 / (2 * 20e-6) + 1e-10 * np.sin(x / 7e-9)
before = solve_line_contact(h, 1e-9, 100e9, load=1.0)
assert keep_freed_memory() is True
assert keep_freed_memory(1 << 20) is True
after = solve_line_contact(h, 1e-9, 100e9, load=1.0)
np.testing.assert_array_equal(before.pressure, after.pressure)
print("ok")
"""
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode == 0 and result.stdout.strip() == "ok", result.stderr
