"""A lab's own measurements: user TOML files for ``memstribo validate-lab FILE`` and ``memstribo calibrate FILE``
(issue 37 item 1, MODEL 7e).

A user file holds ``[[measurement]]`` tables like the packaged ``measurements.toml``, with the same checks
(:func:`memstribo.laboratory.data.load_measurements`: quantity, unit in SI, value, scatter, geometry, environment,
the load of a friction row, the humidity in air) and the cases' range checks
(:func:`memstribo.laboratory.cases.check_conditions`), each error naming the row and the field. What differs:

- ``citation`` may be a key of :data:`memstribo.references.REFERENCES`, a DOI (``"doi:10.xxxx/..."``), free text, or
  ``"own measurement"`` together with ``measured_by`` and ``measured_on`` (a date);
- the descriptive fields (contact, temperature, coating, surface, speed, roughness, source_text) default to
  "not stated" ("none" for the coating); ``calibration`` defaults to false;
- no share of calibration rows is imposed (a lab may calibrate on its one measurement); ``memstribo calibrate``
  uses the rows marked ``calibration = true``, or every row where none is marked.

:func:`calibrate_rows` importance-samples the priors of MODEL 7d on the calibration rows
(:mod:`memstribo.laboratory.calibration`'s likelihood) with the user's parameter set as the base of every row, and
:func:`calibrated_set` writes the posterior as a parameter set file for ``memstribo mesh --parameter-set FILE``.
"""

from __future__ import annotations

import dataclasses
import datetime
import re

import numpy as np

from memstribo.errors import InputError
from memstribo.references import REFERENCES, cites

__all__ = ["OWN", "DEFAULTS", "load_user_measurements", "calibrate_rows", "calibrated_set", "DEFAULT_CONSTANTS"]

#: the citation of a lab's own measurement (with measured_by and measured_on)
OWN = "own measurement"
#: descriptive fields a user row may leave out, and what they default to
DEFAULTS = {"contact": "not stated", "temperature": "not stated", "coating": "none", "surface": "not stated",
            "speed": "not stated", "roughness": "not stated", "source_text": "user file", "calibration": False}
#: constants a user calibration updates unless the file's [calibration] table names others
#: (the set's vdW rule keeps the one of vdw_bond_energy / vdw_dissipated_fraction it uses: MODEL 7h)
DEFAULT_CONSTANTS = ("bond_energy", "vdw_bond_energy", "vdw_dissipated_fraction", "coating_vdw_bond_energy")
_DOI = re.compile(r"^doi:10\.\d{4,9}/\S+$", re.IGNORECASE)
#: a citation key stated in place of the row's own (the packaged checks accept only registered keys)
_PLACEHOLDER = "model"


def _check_citation(name, row):
    citation = row.get("citation")
    if citation in (None, ""):
        raise InputError(f"measurement row {name}: field citation is missing; give a key of memstribo.references, a "
                         "DOI ('doi:10....'), the reference as free text, or 'own measurement' with measured_by and "
                         "measured_on.")
    if not isinstance(citation, str):
        raise InputError(f"measurement row {name}: field citation must be text, got {citation!r}.")
    text = citation.strip()
    if text.lower() == OWN:
        for field in ("measured_by", "measured_on"):
            if row.get(field) in (None, ""):
                raise InputError(f"measurement row {name}: field {field} is missing; an 'own measurement' says who "
                                 "measured it (measured_by) and when (measured_on, a date such as 2026-11-28).")
        when = row["measured_on"]
        if isinstance(when, str):
            try:
                datetime.date.fromisoformat(when)
            except ValueError:
                raise InputError(f"measurement row {name}: field measured_on = {when!r} is not a date "
                                 "(YYYY-MM-DD).") from None
        elif not isinstance(when, (datetime.date, datetime.datetime)):
            raise InputError(f"measurement row {name}: field measured_on = {when!r} is not a date (YYYY-MM-DD).")
        return OWN
    if text.lower().startswith("doi:") and not _DOI.match(text):
        raise InputError(f"measurement row {name}: field citation {text!r} is not a DOI of the form 'doi:10.NNNN/...'.")
    if text not in REFERENCES and not text.lower().startswith("doi:") and len(text) < 10:
        raise InputError(f"measurement row {name}: field citation {text!r} is neither a key of memstribo.references "
                         "nor a DOI nor a reference in words (authors, title, journal, year).")
    return text


def _check_user_row(index, row, base):
    from memstribo.laboratory.cases import check_conditions
    from memstribo.laboratory.data import _check_row
    from memstribo.laboratory.materials import row_parameters

    if not isinstance(row, dict):
        raise InputError(f"measurement row #{index + 1}: not a table ([[measurement]] with fields).")
    name = f"#{index + 1} ({row.get('id', 'no id')!r})"
    citation = _check_citation(name, row)
    filled = {**DEFAULTS, **{k: v for k, v in row.items() if v not in ("", None)}}
    filled["measured_on"] = str(filled["measured_on"]) if "measured_on" in filled else None
    if filled["measured_on"] is None:
        del filled["measured_on"]
    measurement = _check_row(index, {**filled, "citation": _PLACEHOLDER})
    measurement = dataclasses.replace(measurement, citation=citation)
    check_conditions(measurement)  # the ranges first: the parameters would refuse them without the row's name
    params, _ = row_parameters(measurement, base)
    check_conditions(measurement, float(params["hardness"]))
    return measurement


def load_user_measurements(path, base=None):
    """The measurements of a user file, checked row by row (module docstring).

    Parameters
    ----------
    path : str or Path
        A TOML file of ``[[measurement]]`` tables.
    base : memstribo.parameters.Parameters, optional
        The parameter set the rows will be predicted with (its hardness bounds the contact pressure).

    Raises
    ------
    InputError
        Naming the row and the field: a missing field or citation, a unit that does not fit the quantity, a
        condition outside the model's range, a duplicated id.
    """
    from pathlib import Path

    from memstribo.laboratory.data import _read

    if not Path(path).is_file():
        raise InputError(f"measurement file {path} does not exist (a TOML file of [[measurement]] tables, see "
                         "examples/own_measurement.toml).")
    try:
        data = _read(path)
    except UnicodeDecodeError:
        raise InputError(f"measurement file {path}: not a text (UTF-8 TOML) file.") from None
    rows = data.get("measurement", [])
    if not isinstance(rows, list) or not rows:
        raise InputError(f"measurement file {path}: no [[measurement]] rows.")
    seen = {}
    measurements = []
    for i, row in enumerate(rows):
        m = _check_user_row(i, row, base)
        if m.id in seen:
            raise InputError(f"measurement row #{i + 1} ({m.id!r}): field id is used twice (also row #{seen[m.id]}); "
                             "each row needs its own id.")
        seen[m.id] = i + 1
        measurements.append(m)
    return measurements


def _settings(path, rows):
    from memstribo.laboratory.data import _read

    table = dict(_read(path).get("calibration", {}))
    constants = list(table.get("constants") or DEFAULT_CONSTANTS)
    if not any(r.coating for r in rows):
        constants = [c for c in constants if not c.startswith("coating_")]
    coatings = {r.coating.upper() for r in rows if r.coating}
    coating = table.get("coating") or (sorted(coatings)[0] if coatings else None)
    return {"constants": constants, "coating": coating, "fallback_prior": table.get("fallback_prior", {})}


@cites("kish_1965", "model")
def calibrate_rows(rows, path, base=None, samples=64, realisations=2, seed=0):
    """Importance sampling of the MODEL 7d priors on the calibration rows of a user file.

    Returns
    -------
    tuple
        (:class:`memstribo.laboratory.calibration.CalibrationResult`, the settings used, the name of the set whose
        priors were sampled).
    """
    from memstribo.laboratory.calibration import (CalibrationResult, effective_sample_size, hit_rate,
                                                  importance_weights, log_likelihood, prior_samples, weighted_quantile)
    from memstribo.laboratory.predict import _not_predicted, judge, row_values
    from memstribo.parameters import get_parameter_values
    from memstribo.physics.coating import get_coating

    if samples < 2 or realisations < 1:
        raise InputError(f"calibrate needs at least 2 samples and 1 realisation, got {samples} and {realisations}.")
    settings = _settings(path, rows)
    marked = [r for r in rows if r.calibration]
    used = {r.id for r in (marked or rows)}
    prior_set = base if base is not None else get_parameter_values(
        "silicon_oxide_air" if all(r.environment == "air" for r in rows) else "silicon_thesis")
    coating = get_coating(settings["coating"]) if settings["coating"] else None
    from memstribo.uncertainty.priors import priors_for

    free = set(priors_for(prior_set, coating=coating))
    fixed = [c for c in settings["constants"] if c not in free]
    settings["constants"] = [c for c in settings["constants"] if c in free]
    if not settings["constants"]:
        raise InputError(f"no constant to calibrate: {', '.join(fixed)} are fixed (by --set or the parameter set) or "
                         "have no prior; name others in the file's [calibration] constants.")
    draws, prior_text = prior_samples(prior_set, settings, samples, seed=seed, coating=coating)
    computed = {r.id: row_values(r, draws, realisations, settings["coating"] or "OTS", base=base) for r in rows}
    cal = [r for r in rows if r.id in used and computed[r.id][0] is not None]
    if not cal:
        reasons = "; ".join(f"{r.id}: {computed[r.id][1]}" for r in rows if r.id in used)
        raise InputError(f"no calibration row can be predicted ({reasons}).")
    weights = importance_weights(log_likelihood(cal, [computed[r.id][0] for r in cal]))
    prior_pred, post_pred = [], []
    for r in rows:
        values, case = computed[r.id]
        prior_pred.append(_not_predicted(r, case) if values is None else judge(r, values, None, case))
        post_pred.append(_not_predicted(r, case) if values is None else judge(r, values, weights, case))
    constants, flat = [], np.ones(len(draws))
    for name in draws[0]:
        column = np.array([d[name] for d in draws])
        constants.append({"name": name, "median": weighted_quantile(column, flat, 0.5),
                          "p05": weighted_quantile(column, flat, 0.05), "p95": weighted_quantile(column, flat, 0.95),
                          "post_median": weighted_quantile(column, weights, 0.5),
                          "post_p05": weighted_quantile(column, weights, 0.05),
                          "post_p95": weighted_quantile(column, weights, 0.95)})
    held = [p for p in post_pred if p.id not in used]
    result = CalibrationResult(samples=draws, prior=prior_text, weights=weights, ess=effective_sample_size(weights),
                               constants=constants, prior_predictions=prior_pred, posterior_predictions=post_pred,
                               held_out_before=hit_rate([p for p in prior_pred if p.id not in used]),
                               held_out_after=hit_rate(held))
    return result, dict(settings, used=sorted(used)), prior_set.name


def calibrated_set(result, base_name, path, command, base=None) -> str:
    """The calibrated parameter set file (TOML) of a user calibration: the posterior medians (and the user's
    ``--set`` values) on the base set, with the posterior as ``[posterior.NAME]`` tables."""
    from memstribo.laboratory.calibration import calibrated_set_toml
    from memstribo.parameters import get_parameter_values

    text = calibrated_set_toml(result, base=base_name, command=command)
    text = text.replace('description = "silicon_oxide_air with the constants calibrated on the declared laboratory '
                        'rows"', f'description = "{base_name} with the constants calibrated on the measurements of '
                                 f'{path}"')
    text = text.replace("docs/experiments.md", f"measurements of {path}")
    extra = []
    if base is not None:
        shipped = get_parameter_values(base_name) if not str(base_name).endswith(".toml") else None
        calibrated = {c["name"] for c in result.constants}
        for key in base:
            if key in calibrated or shipped is None or base.source(key) == shipped.source(key) or base[key] is None:
                continue
            value = base[key]
            shown = f'"{value}"' if isinstance(value, str) else str(value).lower() if isinstance(value, bool) else repr(value)
            extra += [f"[parameters.{key}]", f"value = {shown}", f'unit = "{base.unit(key)}"',
                      f'source = "given at calibration: {base.source(key)}"', ""]
    marker = "\n[posterior."
    at = text.find(marker)
    return text if not extra else text[:at] + "\n" + "\n".join(extra) + text[at:]
