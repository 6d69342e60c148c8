"""Shared pieces of the subcommands: the result type and readable formatting."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..output import format_quantity, format_value

__all__ = ["CommandResult", "format_quantity", "format_value"]


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
        Lines printed after the table (assumptions, files written).
    warnings : list of str
        Physical limits passed and numerical trouble (MODEL 7c), as sentences; every command's
        JSON has the key ``warnings`` (empty when none), merged with ``values["warnings"]``.
    """

    values: dict[str, Any]
    units: dict[str, str] = field(default_factory=dict)
    title: str = ""
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    #: exit status after printing (0: done; 1: the job ran but part of it failed, e.g. a stage of 'run')
    exit_status: int = 0

    def json_values(self) -> dict[str, Any]:
        """The values with ``warnings`` (a list, possibly empty) always present."""
        found = list(self.values.get("warnings") or [])
        found += [w for w in self.warnings if w not in found]
        return {**self.values, "warnings": found}

    def to_text(self) -> str:
        lines = [self.title] if self.title else []
        width = max((len(k) for k in self.values), default=0)
        for key, value in self.values.items():
            lines.append(f"  {key:<{width}}  {format_value(value, self.units.get(key, ''))}")
        lines.extend(self.notes)
        shown = set(self.values.get("warnings") or [])
        lines.extend(f"  WARNING: {w}." for w in self.warnings if w not in shown)
        return "\n".join(lines)
