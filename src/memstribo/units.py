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

from .errors import InputError

_PLAIN_NUMBER = re.compile(r"^\s*[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?\s*$")


@functools.lru_cache(maxsize=1)
def _registry():
    import pint

    return pint.UnitRegistry()


def to_si(value, unit: str, name: str = "value") -> float:
    """Convert ``value`` to a float in the SI unit ``unit``.

    Parameters
    ----------
    value : float, int or str
        A number (taken as already SI) or a string such as ``"25 uN"``, ``"20 deg"``,
        ``"195.5nm"``.
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
            raise InputError(f"{name}: must be a finite number, got {value!r}.")
        if _PLAIN_NUMBER.match(text):
            result = float(text)
        else:
            result = _parse_quantity(text, unit, name)
    else:
        try:
            result = float(value)
        except (TypeError, ValueError):
            raise InputError(f"{name}: expected a number or a quantity string like '25 uN', got {value!r}.") from None
    if not math.isfinite(result):
        raise InputError(f"{name}: must be a finite number, got {value!r}.")
    return result


def _parse_quantity(text: str, unit: str, name: str) -> float:
    import pint

    ureg = _registry()
    # "25uN" -> "25 uN": pint needs no space, but "1e-9m" style strings parse better with one.
    spaced = re.sub(r"^([-+]?[\d.]+(?:[eE][-+]?\d+)?)\s*([A-Za-zµμ°%])", r"\1 \2", text)
    spaced = spaced.replace("µ", "u").replace("μ", "u").replace("°", " deg")
    try:
        quantity = ureg.Quantity(spaced)
    except (pint.errors.PintError, ValueError, TypeError, AttributeError, SyntaxError) as exc:
        raise InputError(
            f"{name}: cannot read {text!r} as a quantity ({exc}). "
            f"Give a number in SI ({unit or 'dimensionless'}) or a value with a unit, e.g. '25 uN', '195.5 nm', '20 deg'."
        ) from None
    target = unit or "dimensionless"
    try:
        # round off the last-bit noise of unit conversion (25 uN -> 2.5e-05, not 2.4999...e-05)
        return float(f"{float(quantity.to(target).magnitude):.15g}")
    except pint.errors.DimensionalityError:
        raise InputError(
            f"{name}: {text!r} has units of {quantity.units:~}, but {name} needs units convertible to {target}."
        ) from None
