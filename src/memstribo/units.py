"""Units at the edges: turn ``"195.5 nm"`` or ``"25uN"`` into SI floats.

Inside memstribo every quantity is a plain float in SI units (m, N, Pa, J, rad).
Users may give values with units on the command line and in TOML files; this module
converts them with pint, imported only when a string carrying a unit is met so that the
CLI starts quickly.
"""

from __future__ import annotations

import functools
import math
import re

from memstribo.errors import InputError

_PLAIN_NUMBER = re.compile(r"^\s*[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?\s*$", re.ASCII)


@functools.lru_cache(maxsize=1)
def _registry():
    import pint

    return pint.UnitRegistry()


def to_si(value, unit: str, name: str = "value") -> float:
    """Convert ``value`` to a float in the SI unit ``unit``.

    Parameters
    ----------
    value : float, int, str or pint.Quantity
        A number (taken as already SI), a string such as ``"25 uN"``, ``"20 deg"``,
        ``"195.5nm"``, or a pint quantity (``50 * ureg.uN``, any unit registry).
    unit : str
        The SI unit expected, in pint syntax (``"m"``, ``"N"``, ``"Pa"``, ``"J"``,
        ``"rad"``, ``"N*m"``, ``""`` for dimensionless).
    name : str
        Name used in error messages.

    Returns
    -------
    float
        The value in ``unit``.

    Raises
    ------
    InputError
        If the string cannot be parsed or has the wrong dimension.
    """
    if isinstance(value, bool):
        raise InputError(f"{name}: expected a number, got a boolean ({value}).")
    if isinstance(value, (int, float)):
        result = float(value)
    elif isinstance(value, str):
        text = value.strip()
        if text.lower() in ("nan", "inf", "+inf", "-inf", "infinity", "-infinity"):
            raise InputError(f"{name}: must be a finite number, got '{printable(value)}'.")
        if _PLAIN_NUMBER.match(text):
            result = float(text)
        else:
            result = _parse_quantity(text, unit, name)
    elif hasattr(value, "magnitude") and hasattr(value, "units"):  # a pint quantity, from any unit registry
        try:
            magnitude = float(value.magnitude)
        except (TypeError, ValueError):
            raise InputError(f"{name}: expected a scalar quantity, got {printable(repr(value))}.") from None
        result = _parse_quantity(f"{magnitude!r} {value.units}", unit, name)
    else:
        try:
            result = float(value)
        except (TypeError, ValueError):
            raise InputError(f"{name}: expected a number or a quantity string like '25 uN', "
                             f"got {printable(repr(value))}.") from None
    if not math.isfinite(result):
        raise InputError(f"{name}: must be a finite number, got {printable(repr(value))}.")
    return result


#: a quantity string: one number, then a unit expression (no second number, no bare unit)
_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)?\s*$", re.ASCII)

#: characters a unit expression may hold (pint syntax: names, *, /, ^, **, parentheses, digits of powers)
_UNIT_TEXT = re.compile(r"^[A-Za-z_\u00b5\u03bc\u00b0%Ω][A-Za-z0-9_\u00b5\u03bc\u00b0%Ω*/^ ().-]*$")


def printable(text, limit: int = 80) -> str:
    """``text`` with every non-printable character escaped (``\\x1b``), cut to ``limit`` characters.

    Anything a user typed or a file held is shown through this before it reaches a message:
    a crafted value cannot write terminal escape sequences.
    """
    text = str(text)
    out = "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in text)
    return out if len(out) <= limit else out[: limit - 3] + "..."


def _parse_quantity(text: str, unit: str, name: str) -> float:
    example = "e.g. '25 uN', '195.5 nm', '20 deg'"
    shown = printable(text)
    match = _QUANTITY.match(text)
    if not match:
        raise InputError(f"{name}: cannot read '{shown}' as a quantity: it must start with a number. "
                         f"Give a number in SI ({unit or 'dimensionless'}) or a number with a unit, {example}.")
    number, unit_text = match.group(1), (match.group(2) or "")
    unit_text = unit_text.replace("µ", "u").replace("μ", "u").replace("°", "deg").strip()
    # a number left in the unit once its exponents are gone is arithmetic ("GPa/1000", "uN*2"), not a unit
    if unit_text.isprintable() and re.search(r"\d", re.sub(r"(\^|\*\*)\s*\(?[-+]?\d+(\.\d+)?\)?", "", unit_text)):
        raise InputError(f"{name}: cannot read '{shown}': expected one number and one unit (e.g. '1 TPa', "
                         f"'195.5 nm'); arithmetic such as '{printable(unit_text)}' is not evaluated. Give the "
                         f"value in SI ({unit or 'dimensionless'}) or as one number with a unit.")
    if not _UNIT_TEXT.match(unit_text):
        raise InputError(f"{name}: cannot read '{shown}' as a quantity: '{printable(unit_text)}' is not a unit. "
                         f"Give a number in SI ({unit or 'dimensionless'}) or a number with a unit, {example}.")
    ureg = _registry()
    try:
        units = ureg.parse_units(unit_text)
        quantity = ureg.Quantity(float(number), units)
    except Exception:  # pint raises many types (AssertionError, ZeroDivisionError, TokenError, ...) on odd text
        raise InputError(f"{name}: cannot read '{shown}' as a quantity: '{printable(unit_text)}' is not a unit "
                         f"pint knows. Give a number in SI ({unit or 'dimensionless'}) or a number with a unit, "
                         f"{example}.") from None
    target = unit or "dimensionless"
    try:
        # round off the last-bit noise of unit conversion (25 uN -> 2.5e-05, not 2.4999...e-05)
        value = float(quantity.to(target).magnitude)
    except Exception:  # DimensionalityError, or an offset unit
        raise InputError(
            f"{name}: '{shown}' has units of {units:~}, but {name} needs units convertible to {target}."
        ) from None
    if not math.isfinite(value):
        raise InputError(f"{name}: '{shown}' is not a finite number in {target}.")
    return float(f"{value:.15g}")
