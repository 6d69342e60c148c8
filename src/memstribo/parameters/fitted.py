"""Fitted constants a run uses, and warnings when a run is far from their fit conditions (issue 28 item 5).

A parameter set or coating TOML marks a fitted value with ``fitted = {conditions = "...", normal_force = ...,
environment = ..., relative_humidity = ..., target = ...}`` beside its value, unit and source.
:func:`fitted_constants` lists the markers that apply to a run (a value the user replaced is no longer
the fitted one and is not listed); :func:`fit_condition_warnings` says where the run is far from them.
"""

from __future__ import annotations

import functools
import math
import tomllib
from importlib import resources

from memstribo.errors import InputError

__all__ = ["fitted_constants", "fit_condition_warnings", "FORCE_FACTOR", "HUMIDITY_DISTANCE"]

#: a run whose normal force differs from the fit's by more than this factor (either way) warns
FORCE_FACTOR = 3.0
#: a run whose relative humidity differs from the fit's by more than this warns
HUMIDITY_DISTANCE = 0.3


@functools.lru_cache(maxsize=32)
def _parsed(text):
    """The TOML document ``text`` parsed, kept per text (a meshing cycle reads its set's files twice: ~10 ms of
    parsing each time). Read-only for the callers: the same dict is handed to each."""
    return tomllib.loads(text)


def _set_tables(name):
    """[(set name, parameters table)] of a shipped set and its bases, the set itself first."""
    tables, seen = [], set()
    while name and name not in seen:
        seen.add(name)
        path = resources.files("memstribo.parameters") / "sets" / f"{name}.toml"
        if not path.is_file():
            break
        data = _parsed(path.read_text(encoding="utf-8"))
        tables.append((name, data.get("parameters", {})))
        name = data.get("meta", {}).get("base")
    return tables


def _coating_table(name):
    folder = resources.files("memstribo.parameters") / "coatings"
    for entry in folder.iterdir():
        if entry.name.endswith(".toml"):
            data = _parsed(entry.read_text(encoding="utf-8"))
            if str(data.get("meta", {}).get("name", "")).upper() == str(name).upper():
                return data.get("properties", {})
    raise InputError(f"unknown coating {name!r}.")


def _entry(name, value, unit, where, marker, source):
    if not isinstance(marker, dict) or "conditions" not in marker:
        raise InputError(f"{where}: the 'fitted' marker of {name} must be a table with 'conditions' (text).")
    return {"name": name, "value": value, "unit": unit, "where": where, "conditions": marker["conditions"],
            "normal_force": marker.get("normal_force"), "environment": marker.get("environment"),
            "relative_humidity": marker.get("relative_humidity"), "target": marker.get("target"), "source": source}


def fitted_constants(params, coating=None) -> list[dict]:
    """The fitted (calibrated) constants a run with ``params`` and ``coating`` uses, with their fit conditions.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        The run's parameters (a shipped set, possibly with overrides; an overridden value is not listed).
    coating : Coating or str, optional
        The run's coating (object or name); None: bare.

    Returns
    -------
    list of dict
        One per fitted constant: ``name`` (parameter name, or ``coating_<property>`` for a coating's),
        ``value`` (SI), ``unit``, ``where`` (set or coating file), ``conditions`` (text), ``normal_force`` [N],
        ``environment``, ``relative_humidity`` [-] and ``target`` (what it was fitted to), where given, and
        ``source``.
    """
    out = []
    listed = set()
    for set_name, table in _set_tables(getattr(params, "name", None)):
        for name, entry in table.items():
            if name in listed or not isinstance(entry, dict) or "fitted" not in entry:
                continue
            listed.add(name)
            if name in params and params.source(name) != entry.get("source", ""):
                continue  # replaced by the caller: no longer the fitted value
            out.append(_entry(name, params[name], entry.get("unit", ""), f"parameter set {set_name}", entry["fitted"],
                              entry.get("source", "")))
        # a set's own value of a parameter hides its base's marker
        listed.update(table)
    if coating is not None:
        cname = coating if isinstance(coating, str) else coating.name
        for prop, entry in _coating_table(cname).items():
            if not isinstance(entry, dict) or "fitted" not in entry:
                continue
            override = f"coating_{prop}"
            if override in params and params[override] is not None:
                continue  # the caller's value replaces the fitted one
            value = getattr(coating, prop, entry.get("value")) if not isinstance(coating, str) else entry.get("value")
            out.append(_entry(override, value, entry.get("unit", ""), f"coating {cname}", entry["fitted"],
                              entry.get("source", "")))
    return out


def fit_condition_warnings(params, normal_force, coating=None) -> list[str]:
    """Warnings for a run far from the fit conditions of the fitted constants it uses.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
    normal_force : float
        The run's normal force [N] (a mesh run: the load case's tooth normal force).
    coating : Coating or str, optional

    Returns
    -------
    list of str
        One warning per fitted constant whose fit was made at a normal force more than
        :data:`FORCE_FACTOR` times larger or smaller, in another environment, or at a relative humidity
        more than :data:`HUMIDITY_DISTANCE` away; empty when the run is near every fit.
    """
    if not (isinstance(normal_force, (int, float)) and math.isfinite(normal_force) and normal_force > 0):
        raise InputError(f"normal_force must be a positive force in N, got {normal_force!r}.")
    warnings = []
    environment = params["environment"] if "environment" in params else "vacuum"
    for fit in fitted_constants(params, coating):
        label = f"{fit['name']} ({fit['where']})"
        force = fit.get("normal_force")
        if force:
            ratio = normal_force / force
            if ratio > FORCE_FACTOR or ratio < 1.0 / FORCE_FACTOR:
                warnings.append(f"{label} was fitted at a normal force of {force:.3g} N ({fit['conditions']}); this run "
                                f"is at {normal_force:.3g} N, {ratio:.3g} times that: the fitted value does not carry over "
                                "(the model's COF falls with load), read the result as an extrapolation.")
        fit_env = fit.get("environment")
        if fit_env and fit_env != environment:
            warnings.append(f"{label} was fitted in {fit_env}; this run is in {environment}.")
        fit_rh = fit.get("relative_humidity")
        if fit_rh is not None and environment == "air" and abs(params["relative_humidity"] - fit_rh) > HUMIDITY_DISTANCE:
            warnings.append(f"{label} was fitted at RH {fit_rh:g}; this run is at RH {params['relative_humidity']:g}.")
    return warnings
