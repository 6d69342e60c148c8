"""Shared checks of numeric inputs.

Every model function turns its numeric arguments into float arrays and refuses values the
model does not allow (non-numeric, NaN, infinite, and where the relation needs it zero or
negative) with a :class:`memstribo.errors.InputError` whose message names the input, its
unit and what is allowed. These two functions are that check, written once.

Messages read ``"<name> must be <allowed> [<unit>], got <value>."`` where ``<allowed>`` is
``"positive and finite"``, ``">= 0 and finite"`` or ``"finite"`` (:func:`as_array`), or
``"a positive, finite number"`` (:func:`as_positive_scalar`). For arrays, the message
gives the number of offending values and the first of them rather than the whole array.
"""

from __future__ import annotations

import numpy as np

from memstribo.errors import InputError

__all__ = ["as_array", "as_positive_scalar"]


def _unit(unit: str) -> str:
    return f" [{unit}]" if unit else ""


def _got(value, array: np.ndarray, bad: np.ndarray) -> str:
    """Describe the offending value(s): the value itself for a scalar, else a count and the first."""
    if array.ndim == 0:
        return f", got {value!r}"
    first = float(array[bad].flat[0])
    return f", but {int(np.count_nonzero(bad))} of {array.size} values are not (the first: {first!r})"


def as_array(value, name: str, unit: str = "", *, positive: bool = False,
             nonnegative: bool = False) -> np.ndarray:
    """Convert ``value`` to a float array and check that it is finite (and > 0 or >= 0).

    Parameters
    ----------
    value : numeric or array_like
        The input to check, in the unit ``unit``.
    name : str
        The input's name as the user knows it (argument or parameter name), used in the message.
    unit : str, optional
        The input's unit, shown in brackets in the message (``"m"``, ``"Pa"``); ``""`` (the
        default) for a dimensionless input shows none.
    positive : bool, optional
        Require every value > 0.
    nonnegative : bool, optional
        Require every value >= 0 (ignored when ``positive`` is set).

    Returns
    -------
    numpy.ndarray
        ``np.asarray(value, dtype=float)``: a 0-d array for a scalar, else the array's shape.

    Raises
    ------
    InputError
        If ``value`` is not numeric, holds NaN or an infinite value, or (as asked) a value
        <= 0 or < 0. The message names the input, its unit and what is allowed.

    Examples
    --------
    >>> as_array([1.0, 2.0], "load", "N", positive=True)
    array([1., 2.])
    """
    if positive:
        allowed = "positive and finite"
    elif nonnegative:
        allowed = ">= 0 and finite"
    else:
        allowed = "finite"
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be numeric and {allowed}{_unit(unit)}, got {value!r}.") from None
    bad = ~np.isfinite(array)
    if positive:
        bad |= array <= 0.0  # NaN compares False: already flagged as not finite
    elif nonnegative:
        bad |= array < 0.0
    if np.any(bad):
        raise InputError(f"{name} must be {allowed}{_unit(unit)}{_got(value, array, bad)}.")
    return array


def as_positive_scalar(value, name: str, unit: str = "") -> float:
    """Convert ``value`` to one positive, finite float.

    Parameters
    ----------
    value : numeric
        The input to check, one number in the unit ``unit``.
    name : str
        The input's name, used in the message.
    unit : str, optional
        The input's unit, shown in brackets in the message; ``""`` for none.

    Returns
    -------
    float
        ``value`` as a Python float [unit].

    Raises
    ------
    InputError
        If ``value`` is not one number (None, a string, an array with more than a 0-d shape),
        is NaN or infinite, or is <= 0.

    Examples
    --------
    >>> as_positive_scalar(2, "step", "m")
    2.0
    """
    message = f"{name} must be a positive, finite number{_unit(unit)}, got {value!r}."
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(message) from None
    if array.ndim != 0 or not np.isfinite(array) or array <= 0.0:
        raise InputError(message)
    return float(array)
