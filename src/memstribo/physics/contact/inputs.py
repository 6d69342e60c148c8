"""Input checks of the line-contact solvers: one clear InputError naming the problem and what is allowed.

A meshing cycle runs these checks on each of its ~10^4 contact solves, so they take the quick test first where the
value is a plain float (``math.isfinite``) and reduce arrays by their methods (``np.isfinite(h).all()``): the same
rules, the same errors, a few microseconds less per solve.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.errors import InputError


def _finite_number(value) -> bool:
    """``np.isscalar(value) and np.isfinite(value)``, by ``math.isfinite`` for a float (the common case)."""
    if type(value) is float or type(value) is np.float64:
        return math.isfinite(value)
    return bool(np.isscalar(value) and np.isfinite(value))


def _check_problem(separation, dx, contact_modulus) -> np.ndarray:
    """The gap as a float array, checked with the element width and modulus (both solvers)."""
    h = np.asarray(separation, dtype=float)
    if h.ndim != 1 or h.size < 2:
        raise InputError(f"separation must be a 1-D array of at least 2 gap values [m], got shape {h.shape}")
    if not np.isfinite(h).all():
        raise InputError("separation contains NaN or infinite values; fill or remove missing data first")
    for name, value in (("dx", dx), ("contact_modulus", contact_modulus)):
        if not _finite_number(value) or value <= 0:
            raise InputError(f"{name} must be a positive finite number, got {value!r}")
    return h


def _check_solver_options(tolerance, max_iterations, reference_distance) -> None:
    """Tolerance, iteration cap and datum, the same rules for the plain and the adhesive solver."""
    if not (0.0 < tolerance < 1.0):
        raise InputError(f"tolerance must lie in (0, 1), got {tolerance!r}")
    if max_iterations is not None and (int(max_iterations) != max_iterations or max_iterations < 1):
        raise InputError(f"max_iterations must be a positive integer, got {max_iterations!r}")
    if reference_distance is not None and (not np.isfinite(reference_distance) or reference_distance <= 0):
        raise InputError(f"reference_distance must be a positive length [m], got {reference_distance!r}")


def _check_initial_pressure(initial_pressure, h, floor, allowed) -> None:
    """A warm start of the shape of the gap ``h``, finite and >= ``floor`` [Pa]; ``allowed`` names the floor."""
    p0 = np.asarray(initial_pressure, dtype=float)
    # finite first: then "no value below the floor" is "the smallest value not below it" (size >= 2)
    if p0.shape != h.shape or not np.isfinite(p0).all() or p0.min() < floor:
        raise InputError(f"initial_pressure must be finite, >= {allowed} and of the same shape as separation")


def _check_inputs(separation, dx, contact_modulus, load, mean_pressure, tolerance, max_iterations,
                  reference_distance, initial_pressure):
    h = _check_problem(separation, dx, contact_modulus)
    if (load is None) == (mean_pressure is None):
        raise InputError("give exactly one of load [N/m] and mean_pressure [Pa]")
    name, value = ("load", load) if load is not None else ("mean_pressure", mean_pressure)
    if not _finite_number(value) or value <= 0:
        raise InputError(f"{name} must be a positive finite number (a compressive load), got {value!r}")
    _check_solver_options(tolerance, max_iterations, reference_distance)
    if initial_pressure is not None:
        _check_initial_pressure(initial_pressure, h, 0.0, "0")
    return h


def _check_adhesive_inputs(separation, dx, contact_modulus, load, mean_pressure, approach, tolerance, max_iterations,
                           reference_distance, initial_pressure, cohesive_stress, cohesive_range):
    h = _check_problem(separation, dx, contact_modulus)
    if (cohesive_stress is None) != (cohesive_range is None):
        raise InputError("give both cohesive_stress [Pa] and cohesive_range [m] (the Maugis-Dugdale sigma0 and h0), "
                         "or neither")
    for name, value in (("cohesive_stress", cohesive_stress), ("cohesive_range", cohesive_range)):
        if value is not None and (not _finite_number(value) or value < 0):
            unit = "Pa" if name == "cohesive_stress" else "m"
            raise InputError(f"{name} must be a finite number >= 0 [{unit}], got {value!r}")
    given = [(name, value) for name, value in (("load", load), ("mean_pressure", mean_pressure),
                                               ("approach", approach)) if value is not None]
    if len(given) != 1:
        raise InputError("give exactly one of load [N/m], mean_pressure [Pa] and approach [m]")
    name, value = given[0]
    if not _finite_number(value):
        raise InputError(f"{name} must be a finite number, got {value!r}")
    adhesive = bool(cohesive_stress) and bool(cohesive_range)
    if name != "approach" and value <= 0 and not adhesive:
        raise InputError(f"{name} must be positive (a compressive load) without adhesion, got {value!r}")
    _check_solver_options(tolerance, max_iterations, reference_distance)
    if initial_pressure is not None:
        _check_initial_pressure(initial_pressure, h, -float(cohesive_stress or 0.0) * (1.0 + 1e-9), "-cohesive_stress")
    return h
