"""Shared pieces of the subcommands: the result type and readable formatting."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from memstribo.output import format_quantity, format_value

__all__ = ["CommandResult", "error_object", "add_verbosity_arguments", "format_quantity", "format_value", "add_progress_argument", "progress_enabled",
           "PROGRESS_CHOICES"]

#: The values of every long command's ``--progress`` option.
PROGRESS_CHOICES = ("auto", "on", "off")


def add_progress_argument(parser) -> None:
    """Add the shared ``--progress auto|on|off`` option to a subcommand's parser.

    ``auto`` (the default) shows the progress bar when stderr is a terminal; ``--progress`` without a value
    means ``on`` (the flag's meaning before it took a value).
    """
    parser.add_argument("--progress", nargs="?", const="on", default="auto", choices=PROGRESS_CHOICES,
                        metavar="auto|on|off",
                        help="progress bar on stderr: auto (default: when stderr is a terminal), on, off; "
                             "--progress alone means on")
    add_verbosity_arguments(parser)


def progress_enabled(args, stream=None) -> bool:
    """Whether to show a progress bar: ``--progress on``, or ``auto`` and ``stream`` (stderr) is a terminal."""
    import sys

    if getattr(args, "quiet", False):
        return False
    choice = getattr(args, "progress", "auto")
    if choice is True:  # a namespace built by hand with the old store_true flag
        choice = "on"
    if choice in (None, False):
        choice = "auto" if choice is None else "off"
    if choice == "on":
        return True
    if choice == "off":
        return False
    stream = sys.stderr if stream is None else stream
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):  # a closed or replaced stream
        return False


@dataclass
class CommandResult:
    """What a subcommand computed.

    Attributes
    ----------
    values : dict
        Keys and SI values, exactly what ``--json`` prints.
    units : dict
        Units of keys whose unit is not the registry's (memstribo.quantities), e.g. a unit that depends on an
        input; every other key takes its unit from the registry (:meth:`unit_of`).
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

    def unit_of(self, key: str) -> str:
        """The key's unit: the command's own where it gives one, else the vocabulary's ('' if unknown)."""
        if key in self.units:
            return self.units[key]
        from memstribo.quantities import known, unit

        return unit(key) if known(key) else ""

    def to_text(self) -> str:
        lines = [self.title] if self.title else []
        width = max((len(k) for k in self.values), default=0)
        for key, value in self.values.items():
            lines.append(f"  {key:<{width}}  {format_value(value, self.unit_of(key))}")
        lines.extend(self.notes)
        shown = set(self.values.get("warnings") or [])
        lines.extend(f"  WARNING: {w}." for w in self.warnings if w not in shown)
        return "\n".join(lines)


def _parameter_of(message: str) -> str | None:
    """The parameter or option a message is about, or None: "parameter 'X'", a leading --option, a leading name."""
    import re

    from memstribo.parameters.definitions import SPECS

    found = re.search(r"parameter '([A-Za-z_][\w]*)'", message)
    if found:
        return found.group(1)
    found = re.match(r"\s*argument (--[a-z][\w-]*)", message) or re.match(r"\s*(?:config file '[^']*': )?(--[a-z][\w-]*|\[run\] [a-z_]+)", message)
    if found:
        return found.group(1)
    found = re.match(r"\s*(?:config file '[^']*': )?([a-z_][a-z0-9_]*)\b", message)
    if found and found.group(1) in SPECS:
        return found.group(1)
    names = [n for n in re.findall(r"\b[a-z][a-z0-9]*(?:_[a-z0-9]+)+\b", message) if n in SPECS]
    return names[0] if names else None


def error_object(message: str, command: str | None = None, kind: str = "input") -> dict:
    """The JSON object an error prints on stdout under ``--json``.

    Keys: ``error`` (the message, as on stderr), ``parameter`` (the parameter or option it is about, or
    None), ``command`` and ``kind`` (``"input"``: exit 2; ``"usage"``: a command-line syntax error, exit 2;
    ``"memory"``; ``"internal"``: a bug, exit 1).
    """
    return {"error": str(message), "parameter": _parameter_of(str(message)), "command": command, "kind": kind}


def add_verbosity_arguments(parser) -> None:
    """``--quiet`` (only errors and the result) and ``--verbose`` (progress notes on stderr) of a long command."""
    group = parser.add_mutually_exclusive_group()
    group.add_argument("-q", "--quiet", action="store_true",
                       help="print only the result (and errors): no progress bar, no log lines or warnings on stderr")
    group.add_argument("-v", "--verbose", action="store_true",
                       help="more notes on stderr (the logger 'memstribo'; for 'run', each stage's files)")
