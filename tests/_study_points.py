"""Light point functions for tests/test_study.py (the study machinery, without the mesh model).

Importable by the Dask workers because the tests put this folder on PYTHONPATH.
"""

from __future__ import annotations

import math
import os
import time

import numpy as np


def hertz_point(params, coating=None, wear=1.0, roughness=None, steps=None):
    """Hertz line contact at the pitch point, plus a seeded random number (determinism check)."""
    delay = float(os.environ.get("MEMSTRIBO_TEST_POINT_DELAY", "0"))
    if delay:
        time.sleep(delay)
    e, nu = params["youngs_modulus"], params["poisson_ratio"]
    contact_modulus = e / (2 * (1 - nu**2))
    pitch_radius1 = params["module"] * params["teeth_pinion"] / 2
    pitch_radius2 = params["module"] * params["teeth_gear"] / 2
    phi = params["pressure_angle"]
    r1, r2 = pitch_radius1 * math.sin(phi), pitch_radius2 * math.sin(phi)
    radius = r1 * r2 / (r1 + r2)
    load_per_width = params["normal_load"] / params["face_width"]
    half_width = math.sqrt(4 * load_per_width * radius / (math.pi * contact_modulus))
    noise = float(np.random.default_rng(params["roughness_seed"]).standard_normal())
    return {"half_width": half_width, "peak_pressure": 2 * load_per_width / (math.pi * half_width),
            "noise": noise, "wear_used": wear, "pid_parity": 0.0}


hertz_point.units = {"half_width": "m", "peak_pressure": "Pa", "noise": "", "wear_used": ""}


def failing_point(params, **options):
    """Raises a model error for loads above 100 uN (recorded, the study goes on)."""
    from memstribo.errors import InputError

    if params["normal_load"] > 100e-6:
        raise InputError("normal_load too high for this test function")
    return {"load": params["normal_load"]}


def flaky_point(params, **options):
    """Fails until the file named by MEMSTRIBO_TEST_FLAKY exists (resume must run failed points again)."""
    from memstribo.errors import InputError

    marker = os.environ.get("MEMSTRIBO_TEST_FLAKY")
    if marker and not os.path.exists(marker):
        raise InputError("not ready yet")
    return {"load": params["normal_load"]}
