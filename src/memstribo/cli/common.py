"""Shared pieces of the subcommands: the result type and readable formatting."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

_PREFIXES = [(1e-18, "a"), (1e-15, "f"), (1e-12, "p"), (1e-9, "n"), (1e-6, "u"), (1e-3, "m"), (1.0, ""),
             (1e3, "k"), (1e6, "M"), (1e9, "G"), (1e12, "T")]
# units that take SI prefixes in readable output
_PREFIXABLE = {"m", "N", "Pa", "J", "s", "N*m", "N/m", "J/m^2", "W"}


@dataclass
class CommandResult:
    """What a subcommand computed.

    Attributes
    ----------
    values : dict
        Keys and SI values, exactly what ``--json`` prints.
    units : dict
        SI unit of each key (``""`` for dimensionless); used for readable output.
    title : str
        Heading of the readable output.
    notes : list of str
        Lines printed after the table (assumptions, files written, warnings).
    """

    values: dict[str, Any]
    units: dict[str, str] = field(default_factory=dict)
    title: str = ""
    notes: list[str] = field(default_factory=list)

    def to_text(self) -> str:
        lines = [self.title] if self.title else []
        width = max((len(k) for k in self.values), default=0)
        for key, value in self.values.items():
            lines.append(f"  {key:<{width}}  {format_value(value, self.units.get(key, ''))}")
        lines.extend(self.notes)
        return "\n".join(lines)


def format_quantity(value: float, unit: str = "") -> str:
    """``2.5e-05, "N"`` -> ``"25 uN"``: a number with an engineering prefix and its unit."""
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    if isinstance(value, (int, np.integer)) and not unit:
        return str(int(value))
    value = float(value)
    if not math.isfinite(value):
        return str(value)
    if unit in _PREFIXABLE and value != 0.0:
        magnitude = abs(value)
        factor, prefix = _PREFIXES[0]
        for f, p in _PREFIXES:
            if magnitude >= f * 0.9995:
                factor, prefix = f, p
        if unit == "m" and prefix == "":
            pass
        return f"{value / factor:.4g} {prefix}{unit}"
    return f"{value:.4g} {unit}".rstrip()


def format_value(value: Any, unit: str = "") -> str:
    """Readable form of a result value: scalars with units, lists and dicts element-wise."""
    if isinstance(value, dict):
        return ", ".join(f"{k}: {format_value(v, unit)}" for k, v in value.items())
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(format_value(v, unit) for v in value) + "]"
    if isinstance(value, str):
        return value
    return format_quantity(value, unit)
