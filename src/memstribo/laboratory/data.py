"""The published measurements as data: loading and checking ``measurements.toml`` (MODEL 7e).

Each row is one measured value with its conditions and its citation. :func:`load_measurements`
refuses a row that lacks a condition, a unit or a citation, naming the row, so that nothing is
compared against a number whose conditions nobody wrote down.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

from memstribo.errors import InputError
from memstribo.references import REFERENCES

__all__ = ["QUANTITY_UNITS", "REQUIRED", "Measurement", "load_measurements", "calibration_settings"]

#: the measured quantities the laboratory knows, with their SI unit ('1': dimensionless)
QUANTITY_UNITS = {
    "static_cof": "1",
    "kinetic_cof": "1",
    "adhesion_energy": "J/m^2",
    "pull_off_force": "N",
    "adhesion_trend_with_rh": "1",
    "cycles_to_failure": "1",
    "cycles_without_failure": "1",
    "interfacial_shear_strength": "Pa",
    "crack_length": "m",
}

#: conditions every row must state (a value, or the words "not stated" where the source gives none)
REQUIRED = ("id", "quantity", "value", "unit", "scatter", "geometry", "contact", "environment", "temperature",
            "coating", "surface", "speed", "roughness", "citation", "calibration", "source_text")

#: the load of a friction row: one of these must be present (a number or "not stated")
LOAD_KEYS = ("contact_pressure", "normal_force")

ENVIRONMENTS = ("vacuum", "dry_nitrogen", "air")
GEOMETRIES = ("flat", "sidewall", "microbeam", "gear", "rotor_hub", "micromotor", "sphere_on_flat", "flat_pad",
              "cantilever_array", "pull_off", "nanocontact")
SCATTER_KINDS = ("sd", "range", "not stated", "upper limit", "lower bound", "sign")


@dataclass(frozen=True)
class Measurement:
    """One published measurement (a row of ``measurements.toml``).

    Attributes
    ----------
    id : str
        Unique name of the row.
    quantity : str
        One of :data:`QUANTITY_UNITS`.
    value : float
        The measured value, in ``unit`` (SI).
    unit : str
    scatter : dict
        As the source states it: ``kind`` ('sd', 'range', 'not stated', 'upper limit', 'lower bound',
        'sign') with ``value`` (sd), ``low``/``high`` (range), or ``relative_sd_assumed`` and ``reason``.
    calibration : bool
        Whether the row calibrates the constants (else it is held out for validation).
    citation : str
        Key of :data:`memstribo.references.REFERENCES`.
    conditions : dict
        Every other field of the row (geometry, contact, load, environment, humidity, coating, ...).
    """

    id: str
    quantity: str
    value: float
    unit: str
    scatter: dict
    calibration: bool
    citation: str
    conditions: dict = field(default_factory=dict)

    def condition(self, name, default=None):
        """A condition's value (``default`` when the row does not give it)."""
        return self.conditions.get(name, default)

    def number(self, name):
        """A condition as a number: the stated value, else its ``<name>_assumed`` value, else None."""
        value = self.conditions.get(name)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value)
        assumed = self.conditions.get(f"{name}_assumed")
        if isinstance(assumed, (int, float)) and not isinstance(assumed, bool):
            return float(assumed)
        return None

    def relative_sd(self) -> float | None:
        """The relative standard deviation of the measurement [-] used by the likelihood and the band test.

        'sd': sd / value; 'range': (high - low) / 4 / value (a range read as +-2 sd); otherwise the row's
        ``relative_sd_assumed``; None for a sign or a bound without one.
        """
        kind = self.scatter["kind"]
        if kind == "sd":
            return float(self.scatter["value"]) / abs(self.value)
        if kind == "range":
            return (float(self.scatter["high"]) - float(self.scatter["low"])) / 4.0 / abs(self.value)
        assumed = self.scatter.get("relative_sd_assumed")
        return None if assumed is None else float(assumed)

    @property
    def environment(self) -> str:
        return self.conditions["environment"]

    @property
    def coating(self) -> str | None:
        name = self.conditions["coating"]
        return None if str(name).lower() == "none" else str(name)


def _refuse(row_name, problem):
    raise InputError(f"measurement row {row_name}: {problem}")


def _check_row(index, row) -> Measurement:
    name = f"#{index + 1} ({row.get('id', 'no id')!r})"
    missing = [key for key in REQUIRED if key not in row or row[key] in ("", None)]
    if missing:
        _refuse(name, f"lacks {', '.join(missing)}; every row states {', '.join(REQUIRED)} "
                      "(write 'not stated' where the source gives none).")
    quantity = row["quantity"]
    if quantity not in QUANTITY_UNITS:
        _refuse(name, f"unknown quantity {quantity!r}; allowed: {', '.join(QUANTITY_UNITS)}.")
    if row["unit"] != QUANTITY_UNITS[quantity]:
        _refuse(name, f"unit {row['unit']!r} for {quantity}; it must be given in {QUANTITY_UNITS[quantity]!r} (SI).")
    value = row["value"]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        _refuse(name, f"value must be a finite number in {QUANTITY_UNITS[quantity]}, got {value!r}.")
    if quantity != "adhesion_trend_with_rh" and value <= 0:
        _refuse(name, f"value must be positive, got {value!r}.")
    scatter = row["scatter"]
    if not isinstance(scatter, dict) or scatter.get("kind") not in SCATTER_KINDS:
        _refuse(name, f"scatter must be a table with kind one of {', '.join(SCATTER_KINDS)}, got {scatter!r}.")
    if scatter["kind"] == "sd" and not (isinstance(scatter.get("value"), (int, float)) and scatter["value"] > 0):
        _refuse(name, "scatter kind 'sd' needs a positive 'value' (same unit as the row).")
    if scatter["kind"] == "range" and not ("low" in scatter and "high" in scatter):
        _refuse(name, "scatter kind 'range' needs 'low' and 'high'.")
    if scatter["kind"] not in ("sd", "range") and "reason" not in scatter:
        _refuse(name, f"scatter kind {scatter['kind']!r} needs a 'reason' (what the source says, what is assumed).")
    if row["environment"] not in ENVIRONMENTS:
        _refuse(name, f"environment {row['environment']!r}; allowed: {', '.join(ENVIRONMENTS)}.")
    if row["environment"] == "air" and "relative_humidity" not in row:
        _refuse(name, "environment 'air' needs relative_humidity (a number, or 'not stated').")
    if row["geometry"] not in GEOMETRIES:
        _refuse(name, f"geometry {row['geometry']!r}; allowed: {', '.join(GEOMETRIES)}.")
    if quantity in ("static_cof", "kinetic_cof") and not any(key in row for key in LOAD_KEYS):
        _refuse(name, f"a friction row needs its load: one of {', '.join(LOAD_KEYS)} (a number or 'not stated').")
    if row["citation"] not in REFERENCES:
        _refuse(name, f"citation {row['citation']!r} is not in memstribo.references.REFERENCES.")
    if not isinstance(row["calibration"], bool):
        _refuse(name, f"calibration must be true or false, got {row['calibration']!r}.")
    conditions = {k: v for k, v in row.items() if k not in ("id", "quantity", "value", "unit", "scatter",
                                                             "calibration", "citation")}
    return Measurement(id=str(row["id"]), quantity=quantity, value=float(value), unit=row["unit"],
                       scatter=dict(scatter), calibration=row["calibration"], citation=row["citation"],
                       conditions=conditions)


def _read(path):
    if path is None:
        text = (resources.files(__package__) / "measurements.toml").read_text(encoding="utf-8")
    else:
        text = Path(path).read_text(encoding="utf-8")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise InputError(f"measurement file {path or 'measurements.toml'}: not valid TOML ({error}).") from None


def load_measurements(path=None) -> list[Measurement]:
    """The published measurements, checked row by row.

    Parameters
    ----------
    path : str or Path, optional
        A TOML file of ``[[measurement]]`` tables; default the shipped ``measurements.toml``.

    Returns
    -------
    list of Measurement

    Raises
    ------
    InputError
        A row without a required condition, with an unknown quantity or a unit other than the
        quantity's SI unit, a citation that is not in the references, duplicate ids, or more than a
        third of the rows declared for calibration; the message names the row.
    """
    data = _read(path)
    rows = data.get("measurement", [])
    if not rows:
        raise InputError("measurement file holds no [[measurement]] rows.")
    measurements = [_check_row(i, row) for i, row in enumerate(rows)]
    seen = set()
    for m in measurements:
        if m.id in seen:
            raise InputError(f"measurement row {m.id!r}: the id is used twice.")
        seen.add(m.id)
    n_cal = sum(m.calibration for m in measurements)
    if 3 * n_cal > len(measurements):
        raise InputError(f"{n_cal} of {len(measurements)} rows are declared for calibration; at most a third may be "
                         "(the rest is the validation).")
    return measurements


def calibration_settings(path=None) -> dict:
    """The ``[calibration]`` table: ``constants`` (names), ``coating``, ``fallback_prior`` {name: [low, high] factors}."""
    table = dict(_read(path).get("calibration", {}))
    table.setdefault("constants", [])
    table.setdefault("coating", None)
    table.setdefault("fallback_prior", {})
    return table
