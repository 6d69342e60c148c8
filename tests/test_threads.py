"""One BLAS thread per process for the dense contact algebra (issue 40; memstribo.physics._threads)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from memstribo.errors import InputError


@pytest.fixture
def clean_env(monkeypatch):
    for name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "MEMSTRIBO_BLAS_THREADS"):
        monkeypatch.delenv(name, raising=False)
    return monkeypatch


def test_one_thread_unless_the_user_chose(clean_env):
    from memstribo.physics._threads import _wanted

    assert _wanted() == 1
    clean_env.setenv("OMP_NUM_THREADS", "4")
    assert _wanted() is None  # the user's choice stands
    clean_env.setenv("MEMSTRIBO_BLAS_THREADS", "2")
    assert _wanted() == 2
    clean_env.setenv("MEMSTRIBO_BLAS_THREADS", "keep")
    assert _wanted() is None


@pytest.mark.parametrize("text", ["0", "many", "-1"])
def test_a_bad_thread_count_is_refused_by_name(clean_env, text):
    from memstribo.physics._threads import _wanted

    clean_env.setenv("MEMSTRIBO_BLAS_THREADS", text)
    with pytest.raises(InputError, match=f"MEMSTRIBO_BLAS_THREADS must be a whole number >= 1 or 'keep', got '{text}'"):
        _wanted()


def _blas_threads(env):
    code = ("import memstribo.physics.contact.dense\n"
            "from threadpoolctl import threadpool_info\n"
            "print(sorted({i['num_threads'] for i in threadpool_info() if i['user_api'] == 'blas'}))")
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True).stdout


def test_the_dense_path_sets_every_blas_library_to_one_thread_in_a_fresh_process(clean_env):
    """numpy's and scipy's BLAS (two libraries) both at one thread once the dense path is imported; with
    MEMSTRIBO_BLAS_THREADS=keep they keep their own count (OpenBLAS: the machine's cores, 2 in CI)."""
    import os

    env = {k: v for k, v in os.environ.items()}
    assert _blas_threads(env).strip() == "[1]"
    kept = _blas_threads({**env, "MEMSTRIBO_BLAS_THREADS": "keep"}).strip()
    assert kept != "" and kept.startswith("[")
    if (os.cpu_count() or 1) > 1:
        assert kept != "[1]"
