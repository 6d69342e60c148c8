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

__all__ = ["QUANTITY_UNITS", "REQUIRED", "GEOMETRIES", "MATERIALS", "LAB_CALIBRATION", "Measurement",
           "load_measurements", "calibration_settings"]

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
GEOMETRIES = ("flat", "flat_pad", "sidewall", "microbeam", "cantilever_array", "pull_off", "nanocontact", "gear",
              "rotor_hub", "micromotor", "sphere_on_flat")
#: materials of a row's surfaces (``material``, ``counter_material``; missing: polysilicon); coatings go in ``coating``
MATERIALS = ("polysilicon", "silicon", "silica", "silicon_nitride")
VAPOURS = ("water", "pentanol")
TERMINATIONS = ("oxide", "hydrogen")
#: geometry and load fields that, where given as a number, must be positive and finite (SI: m, N, Pa, m^2)
POSITIVE_FIELDS = ("sphere_radius", "normal_force", "contact_pressure", "pad_area", "sliding_amplitude",
                   "beam_thickness", "beam_gap", "beam_length", "crack_length")
#: scoring fields (the lab schema): which fit used a row, duplicates, design targets, the research group
SCORING_FIELDS = {"same_as": str, "design_target": bool, "fitted_by": str, "source_group": str}
#: the name of the laboratory's own calibration in ``fitted_by`` (rows with ``calibration = true``)
LAB_CALIBRATION = "laboratory calibration (measurements.toml [calibration])"
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
    def same_as(self) -> str | None:
        """The id of the row this one duplicates (the same measurement published twice), else None."""
        return self.conditions.get("same_as")

    @property
    def design_target(self) -> bool:
        """Whether the model was designed to reproduce this row (never held out)."""
        return bool(self.conditions.get("design_target", False))

    @property
    def fitted_by(self) -> str | None:
        """The fit that used this row: the row's ``fitted_by``, else the laboratory calibration when
        ``calibration = true``, else None."""
        return self.conditions.get("fitted_by") or (LAB_CALIBRATION if self.calibration else None)

    @property
    def source_group(self) -> str:
        """The research group (leave-one-source-out cross-validation); default the citation."""
        return str(self.conditions.get("source_group") or self.citation)

    @property
    def held_out(self) -> bool:
        """Never used by any fit, not a design target and not a duplicate: a validation row."""
        return not (self.fitted_by or self.design_target or self.same_as)

    @property
    def material(self) -> str:
        return str(self.conditions.get("material", "polysilicon"))

    @property
    def counter_material(self) -> str:
        return str(self.conditions.get("counter_material", self.material))

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
    _check_schema_fields(name, row)
    conditions = {k: v for k, v in row.items() if k not in ("id", "quantity", "value", "unit", "scatter",
                                                             "calibration", "citation")}
    return Measurement(id=str(row["id"]), quantity=quantity, value=float(value), unit=row["unit"],
                       scatter=dict(scatter), calibration=row["calibration"], citation=row["citation"],
                       conditions=conditions)


def _check_schema_fields(name, row):
    """The lab schema's optional fields: materials, vapour, termination, positive geometry numbers, scoring fields."""
    for key in ("material", "counter_material"):
        if key in row and row[key] not in MATERIALS:
            _refuse(name, f"{key} {row[key]!r}; allowed: {', '.join(MATERIALS)} (a coating goes in 'coating').")
    if "vapour" in row and row["vapour"] not in VAPOURS:
        _refuse(name, f"vapour {row['vapour']!r}; allowed: {', '.join(VAPOURS)}.")
    ratio = row.get("vapour_pressure_ratio")
    if ratio is not None and ratio != "not stated" and not (
            isinstance(ratio, (int, float)) and not isinstance(ratio, bool) and 0 <= ratio <= 1):
        _refuse(name, f"vapour_pressure_ratio must be a number in [0, 1] or 'not stated', got {ratio!r}.")
    if "surface_termination" in row and row["surface_termination"] not in TERMINATIONS:
        _refuse(name, f"surface_termination {row['surface_termination']!r}; allowed: {', '.join(TERMINATIONS)}.")
    for key in POSITIVE_FIELDS:
        value = row.get(key)
        if isinstance(value, (int, float)) and not isinstance(value, bool) and not (math.isfinite(value) and value > 0):
            _refuse(name, f"{key} must be a positive finite number (SI) or 'not stated', got {value!r}.")
    for key, kind in SCORING_FIELDS.items():
        if key in row and (not isinstance(row[key], kind) or (kind is str and not row[key].strip())):
            _refuse(name, f"{key} must be {'true or false' if kind is bool else 'a non-empty text'}, got {row[key]!r}.")
    if row.get("same_as") is not None and row["calibration"]:
        _refuse(name, f"a duplicate (same_as {row['same_as']!r}) cannot be a calibration row: mark the row it "
                      "duplicates.")


def _check_duplicates(measurements):
    """``same_as`` must name another row that is not itself a duplicate."""
    by_id = {m.id: m for m in measurements}
    for m in measurements:
        if m.same_as is None:
            continue
        target = by_id.get(m.same_as)
        if target is None or target.id == m.id:
            raise InputError(f"measurement row {m.id!r}: same_as {m.same_as!r} names no other row of the file.")
        if target.same_as is not None:
            raise InputError(f"measurement row {m.id!r}: same_as {m.same_as!r} is itself a duplicate (of "
                             f"{target.same_as!r}); name the first row.")


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
    _check_duplicates(measurements)
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
