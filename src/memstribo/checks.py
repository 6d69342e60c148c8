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

__all__ = ["as_array", "as_positive_scalar", "as_count", "check_mesh_arguments", "check_parameter_set_arguments",
           "user_set", "check_unused_values", "refuse_unknown_keys", "check_coating_wear", "coating_wear_of",
           "refuse_unused_coating_wear", "point_wear"]


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


def as_count(value, name: str, minimum: int, maximum: int) -> int:
    """``value`` as a whole number within ``minimum..maximum``; InputError for anything else.

    Parameters
    ----------
    value : int
        A count (steps, realisations); a float with an integral value (``4.0``) is accepted, a bool,
        a string, a fraction or a value outside the bounds is not.
    name : str
        The argument's name, used in the message.
    minimum, maximum : int
        The allowed range (inclusive).

    Returns
    -------
    int

    Examples
    --------
    >>> as_count(4, "realisations", 1, 10_000)
    4
    """
    allowed = f"a whole number from {minimum:,} to {maximum:,}"
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputError(f"{name} must be {allowed}, got {value!r} ({type(value).__name__}).")
    if not np.isfinite(value) or float(value) != int(value):
        raise InputError(f"{name} must be {allowed}, got {value!r}.")
    if not minimum <= int(value) <= maximum:
        raise InputError(f"{name} must be {allowed}, got {value!r}.")
    return int(value)


def check_mesh_arguments(params, steps=None, realisations=1, wear=1.0) -> None:
    """The checks the command line applies to a meshing cycle, before anything is allocated.

    ``steps`` and ``realisations`` obey the bounds of the parameters ``mesh_steps`` (3..100 000)
    and ``realisations`` (1..10 000); ``steps`` with a given ``mesh_window`` and
    ``mesh_grid_spacing`` obeys the memory estimate (``parameters.check_mesh_size``); ``wear``
    is a fraction. Used by :func:`memstribo.api.mesh_cycle` and ``sweep``.

    Raises
    ------
    InputError
        A wrong type, a fraction where a count is needed, a value outside its bounds, a cycle
        too large for memory; ``params`` that is not a parameter set.
    """
    from memstribo.parameters import Parameters, check_mesh_size
    from memstribo.parameters.definitions import SPECS

    if params is not None and not isinstance(params, Parameters):
        raise InputError(f"params must be a parameter set (memstribo.parameter_set(...)), got "
                         f"{type(params).__name__}.")
    if steps is not None:
        spec = SPECS["mesh_steps"]
        steps = as_count(steps, "steps", int(spec.minimum), int(spec.maximum))
        if params is not None:
            check_mesh_size(steps, params["mesh_window"], params["mesh_grid_spacing"], what="steps")
    spec = SPECS["realisations"]
    as_count(realisations, "realisations", int(spec.minimum), int(spec.maximum))
    if isinstance(wear, bool) or not isinstance(wear, (int, float, np.integer, np.floating)) \
            or not 0.0 <= float(wear) <= 1.0:
        raise InputError(f"wear (the worn fraction Omega of the gear's coating) must be a number within 0..1, "
                         f"got {wear!r}.")


def check_parameter_set_arguments(name, overrides) -> None:
    """``memstribo.parameter_set``'s arguments: a set name (str) and a mapping of parameter names (str)."""
    from collections.abc import Mapping

    if not isinstance(name, str):
        raise InputError(f"the parameter set name must be a string (e.g. 'silicon_thesis'), got {name!r} "
                         f"({type(name).__name__}).")
    if overrides is None:
        return
    if not isinstance(overrides, Mapping):
        raise InputError(f"overrides must be a mapping of parameter names to values (a dict), got "
                         f"{type(overrides).__name__}.")
    for key in overrides:
        if not isinstance(key, str):
            raise InputError(f"overrides: parameter names are strings (e.g. 'normal_load'), got {key!r} "
                             f"({type(key).__name__}).")


def user_set(params, name: str) -> bool:
    """Whether ``name`` in ``params`` was changed from its parameter set (``--set``, a config file, the API)."""
    from memstribo.parameters import get_parameter_values

    try:
        base = get_parameter_values(params.name)
    except Exception:  # a custom set: every source that is not a set file counts as the user's
        return not params.source(name).startswith("thesis")
    return params.source(name) != base.source(name) or params[name] != base[name]


def check_unused_values(params) -> None:
    """Refuse values the user set that the model would ignore without a word.

    ``relative_humidity`` (and the vapour, its pressure ratio and the surface termination, which set the menisci)
    act only in air (``environment = 'air'``); as ``--wear`` without ``--coating`` is refused, a humidity in
    vacuum is too. (``ambient_temperature`` acts in vacuum as well: the tooth's
    temperature and the coating's stability, docs/thermal.md.) ``vdw_bond_energy`` acts only under
    ``vdw_energy_rule = 'thesis'`` and ``vdw_dissipated_fraction`` only under ``'hysteresis'`` (MODEL 7h).
    """
    rule = params.get("vdw_energy_rule")
    if rule == "hysteresis" and user_set(params, "vdw_bond_energy"):
        raise InputError("vdw_bond_energy is used only under vdw_energy_rule 'thesis'; the default rule 'hysteresis' "
                         "derives U_vdW = vdw_dissipated_fraction x w12 / vdw_site_density (MODEL 7h): add --set "
                         "vdw_energy_rule=thesis, or set vdw_dissipated_fraction instead.")
    if rule == "thesis" and user_set(params, "vdw_dissipated_fraction"):
        raise InputError("vdw_dissipated_fraction is used only under vdw_energy_rule 'hysteresis' (U_vdW = phi w12 / "
                         "n_site), but the rule is 'thesis' (vdw_bond_energy as given): set vdw_energy_rule=hysteresis, "
                         "or leave vdw_dissipated_fraction out.")
    if params["environment"] == "vacuum":
        for name in ("relative_humidity", "vapour", "vapour_pressure_ratio", "surface_termination"):
            if user_set(params, name):
                raise InputError(f"{name} is used only in air, but environment is 'vacuum' (the default): add "
                                 f"--set environment=air, or leave {name} out.")


def check_coating_wear(params, coating) -> None:
    """Refuse ``coating_wear`` set by the user for bare silicon (as ``--wear`` without ``--coating``)."""
    if not coating and user_set(params, "coating_wear"):
        raise InputError("coating_wear needs a coating (--coating NAME): bare silicon has no coating to wear.")


def refuse_unused_coating_wear(params, where: str, why: str) -> None:
    """Refuse a user-set ``coating_wear`` where the worn fraction comes from elsewhere (``why`` says where).

    ``memstribo run`` and ``memstribo damage`` start from the intact coating (Omega = 0) and sweep Omega
    themselves: a ``coating_wear`` given to them would be ignored without a word (issue #41).
    """
    if user_set(params, "coating_wear"):
        raise InputError(f"coating_wear = {float(params['coating_wear']):g} is not used by {where}: {why}; leave "
                         "coating_wear out.")


def coating_wear_of(params, coating, wear=None, option: str = "--wear") -> float:
    """The worn fraction Omega [-] of the gear's coating that a meshing cycle uses (1 for bare silicon).

    With a coating: ``wear`` when given, else the parameter ``coating_wear`` (0 by default, the fully
    functionalised gear tooth of thesis 5.5.3), so that ``--set coating_wear=0.2`` acts as ``--wear 0.2``
    does (issue #41: it was ignored, and the cycle ran at Omega = 1, bare silicon). Without a coating: 1.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
    coating : str, Coating or None
        The coating given (None or "" for bare silicon).
    wear : float, optional
        The worn fraction given explicitly (``--wear``, the API's ``wear``); None: not given.
    option : str
        How ``wear`` was given, for the messages (``"--wear"`` or ``"wear"``).

    Raises
    ------
    InputError
        ``wear`` outside 0..1; ``wear`` (other than 1) or a user-set ``coating_wear`` without a coating;
        ``wear`` and a user-set ``coating_wear`` that disagree (two values of one quantity).
    """
    shown = (lambda value: f"{option} {value:g}") if option.startswith("-") else (lambda value: f"{option}={value:g}")
    if wear is not None:
        check_mesh_arguments(None, None, 1, wear)  # a number within 0..1
        wear = float(wear)
    if not coating:
        check_coating_wear(params, coating)
        if wear is not None and wear != 1.0:
            coating_option = "--coating NAME" if option.startswith("-") else "coating=NAME"
            raise InputError(f"{shown(wear)} needs a coating ({coating_option}, e.g. OTS): bare silicon has no "
                             "coating to wear (it is wear 1).")
        return 1.0
    if wear is None:
        return float(params["coating_wear"])
    if user_set(params, "coating_wear") and wear != float(params["coating_wear"]):
        raise InputError(f"{shown(wear)} and the parameter coating_wear = {float(params['coating_wear']):g} disagree: "
                         "both are the worn fraction Omega of the gear's coating; give one of them.")
    return wear


def point_wear(options: dict, raw, params, where: str) -> dict:
    """A study or map point's options with its worn fraction: its ``wear``, else the point's ``coating_wear``.

    ``options`` are the point's validated study options (``coating``, and ``wear`` when ``raw``, the point as
    the spec gives it, has one); ``params`` its parameters; ``where`` names the point in the messages.
    A coated point without ``wear`` ran at Omega = 0 whatever ``coating_wear`` said (issue #41); now it takes
    the point's ``coating_wear`` (0 unless the spec sets it, so earlier studies keep their points' hashes).
    A point giving both, disagreeing, and a bare point given ``coating_wear`` itself, are refused.
    """
    coating_wear = float(params["coating_wear"]) if "coating_wear" in params else 0.0
    if not options.get("coating"):
        if "coating_wear" in raw:
            raise InputError(f"{where}: coating_wear = {coating_wear:g} needs a coating (add coating = 'OTS' to the "
                             "point): bare silicon has no coating to wear.")
        return {**options, "wear": options.get("wear", 1.0)}
    if "wear" not in raw:
        return {**options, "wear": coating_wear}
    if "coating_wear" in params and user_set(params, "coating_wear") and options["wear"] != coating_wear:
        raise InputError(f"{where}: wear = {options['wear']:g} and coating_wear = {coating_wear:g} disagree: both are "
                         "the worn fraction Omega of the gear's coating; give one of them.")
    return options


def refuse_unknown_keys(table, allowed, where: str, what: str) -> None:
    """Refuse the keys of ``table`` outside ``allowed`` (InputError naming them, escaped, with the allowed ones and the
    closest match): one wording for every spec table (``what``, e.g. "key(s) ... in [map]", "constraint(s)")."""
    from memstribo.errors import did_you_mean
    from memstribo.units import printable

    unknown = sorted(str(k) for k in set(table) - set(allowed))
    if unknown:
        raise InputError(f"{where}: unknown {what.format(keys=[printable(k, 40) for k in unknown])}; allowed: "
                         f"{sorted(allowed)}.{did_you_mean(unknown[0], allowed)}")

