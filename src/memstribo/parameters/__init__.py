"""Parameter sets as data, with provenance.

A :class:`Parameters` object maps canonical names (see :data:`SPECS`) to SI values and
remembers where each value came from. Parameter sets live in ``sets/<name>.toml``; users
override values with ``--set NAME=VALUE`` on the command line or with a TOML file::

    >>> from memstribo.parameters import get_parameter_values
    >>> params = get_parameter_values()            # the thesis's silicon microgear case
    >>> params["youngs_modulus"]
    161000000000.0
    >>> params.updated({"normal_load": "50 uN"})["normal_load"]
    5e-05
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Iterator, Mapping
from importlib import resources
from pathlib import Path
from typing import Any

from ..errors import InputError, did_you_mean
from ..units import to_si
from .definitions import SPECS, ParameterSpec

__all__ = [
    "SPECS",
    "ParameterSpec",
    "Parameters",
    "available_parameter_sets",
    "get_parameter_values",
    "parse_assignment",
    "read_config",
    "coerce_value",
]

DEFAULT_SET = "silicon_thesis"


def available_parameter_sets() -> list[str]:
    """Names of the parameter sets shipped with memstribo."""
    folder = resources.files(__package__) / "sets"
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


def coerce_value(name: str, value: Any, spec: ParameterSpec | None = None) -> Any:
    """Validate ``value`` for parameter ``name`` and convert it to SI.

    Raises
    ------
    InputError
        Unknown name, unparsable value, wrong unit, or a value outside the allowed range.
    """
    spec = spec or SPECS.get(name)
    if spec is None:
        raise InputError(f"unknown parameter '{name}'.{did_you_mean(name, SPECS)} "
                         f"Run 'memstribo parameters' to list them.")
    if value is None:
        if spec.optional:
            return None
        raise InputError(f"parameter '{name}' needs a value: {spec.allowed()}.")
    if spec.kind == "str":
        value = str(value)
        if spec.choices and value not in spec.choices:
            raise InputError(f"parameter '{name}' = {value!r} is not allowed: {spec.allowed()}."
                             f"{did_you_mean(value, spec.choices)}")
        return value
    if spec.kind == "bool":
        if isinstance(value, bool):
            return value
        text = str(value).strip().lower()
        if text in ("true", "1", "yes", "on"):
            return True
        if text in ("false", "0", "no", "off"):
            return False
        raise InputError(f"parameter '{name}' = {value!r}: expected true or false.")
    number = to_si(value, spec.unit, name)
    if spec.kind == "int":
        if not float(number).is_integer():
            raise InputError(f"parameter '{name}' = {value!r} must be an integer.")
        number = int(number)
    if not _in_range(number, spec):
        raise InputError(f"parameter '{name}' = {value!r} is outside its range: {spec.allowed()}.")
    return number


def _in_range(number: float, spec: ParameterSpec) -> bool:
    if math.isnan(number):
        return False
    if spec.minimum is not None:
        if number < spec.minimum or (spec.exclusive_minimum and number == spec.minimum):
            return False
    if spec.maximum is not None:
        if number > spec.maximum or (spec.exclusive_maximum and number == spec.maximum):
            return False
    return True


class Parameters(Mapping):
    """An immutable mapping of canonical parameter names to SI values, with provenance.

    Use :meth:`updated` to get a copy with overrides; every value is validated.
    ``None`` means "derive it" for the optional parameters (see their descriptions).
    """

    def __init__(self, values: Mapping[str, Any], sources: Mapping[str, str], name: str = "custom"):
        self._values = dict(values)
        self._sources = dict(sources)
        self.name = name

    def __getitem__(self, name: str) -> Any:
        try:
            return self._values[name]
        except KeyError:
            raise InputError(f"unknown parameter '{name}'.{did_you_mean(name, self._values)}") from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __repr__(self) -> str:
        return f"Parameters(name={self.name!r}, {len(self)} values)"

    def source(self, name: str) -> str:
        """Where the value of ``name`` comes from (set file, override, ...)."""
        self[name]
        return self._sources.get(name, "")

    def unit(self, name: str) -> str:
        """SI unit of ``name``."""
        return SPECS[name].unit

    def updated(self, overrides: Mapping[str, Any], origin: str = "user override") -> "Parameters":
        """A copy with ``overrides`` applied (values may carry units: ``"25 uN"``)."""
        values = dict(self._values)
        sources = dict(self._sources)
        for name, value in overrides.items():
            values[name] = coerce_value(name, value)
            sources[name] = origin
        _check_consistency(values)
        return Parameters(values, sources, self.name)

    def to_dict(self) -> dict[str, Any]:
        """Plain ``{name: SI value}`` dict (``None`` for unset derived values)."""
        return dict(self._values)

    def to_toml(self) -> str:
        """The parameters as TOML, each with its unit and source, readable by :func:`read_config`."""
        import tomli_w

        table = {}
        for name, value in self._values.items():
            entry = {"unit": SPECS[name].unit, "source": self._sources.get(name, "")}
            if value is not None:
                entry = {"value": value, **entry}
            table[name] = entry
        return tomli_w.dumps({"meta": {"name": self.name}, "parameters": table})


def _check_consistency(values: Mapping[str, Any]) -> None:
    """Cross-parameter rules that a single range cannot express."""
    if values.get("atomic_width") and values.get("adhesive_width"):
        if values["atomic_width"] > values["adhesive_width"]:
            raise InputError(
                f"atomic_width ({values['atomic_width']:.4g} m) is larger than adhesive_width "
                f"({values['adhesive_width']:.4g} m): atomic blocks sit on top of an adhesive block.")


def get_parameter_values(name: str = DEFAULT_SET) -> Parameters:
    """Load a parameter set shipped with memstribo (default: the thesis's silicon case).

    Raises
    ------
    InputError
        If ``name`` is not a known set; the message lists the available ones.
    """
    available = available_parameter_sets()
    if name not in available:
        raise InputError(f"unknown parameter set '{name}'.{did_you_mean(name, available)} "
                         f"Available: {', '.join(available)}.")
    text = (resources.files(__package__) / "sets" / f"{name}.toml").read_text(encoding="utf-8")
    data = tomllib.loads(text)
    values, sources = {}, {}
    for key, entry in data.get("parameters", {}).items():
        values[key] = coerce_value(key, entry.get("value"))
        sources[key] = entry.get("source", "")
    missing = sorted(set(SPECS) - set(values))
    if missing:
        raise InputError(f"parameter set '{name}' lacks {', '.join(missing)}")
    return Parameters(values, sources, name)


def read_config(path: str | Path) -> dict[str, Any]:
    """Read parameter overrides from a TOML file.

    The file may hold the overrides at top level (``normal_load = "50 uN"``), in a
    ``[parameters]`` table, or in the format written by :meth:`Parameters.to_toml`
    (``[parameters.normal_load]`` with ``value``). Other tables (``[run]``, ...) are
    returned under their own keys for the commands that use them.

    Returns
    -------
    dict
        ``{"parameters": {name: value}, **other_tables}``.
    """
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise InputError(f"config file '{path}' does not exist.") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read config file '{path}': {exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"config file '{path}' is not valid TOML: {exc}") from None
    overrides: dict[str, Any] = {}
    other: dict[str, Any] = {}
    for key, value in data.items():
        if key == "parameters" and isinstance(value, dict):
            for name, entry in value.items():
                if isinstance(entry, dict):
                    if "value" in entry:
                        overrides[name] = entry["value"]
                else:
                    overrides[name] = entry
        elif key == "meta":
            continue
        elif isinstance(value, dict):
            other[key] = value
        else:
            overrides[key] = value
    for name in overrides:
        if name not in SPECS:
            raise InputError(f"config file '{path}': unknown parameter '{name}'.{did_you_mean(name, SPECS)}")
    return {"parameters": overrides, **other}


def parse_assignment(text: str) -> tuple[str, str]:
    """Split ``"NAME=VALUE"`` from ``--set``; raise :class:`InputError` if malformed."""
    name, sep, value = text.partition("=")
    name, value = name.strip(), value.strip()
    if not sep or not name or not value:
        raise InputError(f"--set expects NAME=VALUE (e.g. --set normal_load='50 uN'), got {text!r}.")
    if name not in SPECS:
        raise InputError(f"--set: unknown parameter '{name}'.{did_you_mean(name, SPECS)} "
                         f"Run 'memstribo parameters' to list them.")
    return name, value
