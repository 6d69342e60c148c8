"""Priors of the constants nobody measured (MODEL 7d), as data in the parameter sets.

Each assumed, fitted or single-source constant of a parameter set (``parameters/sets/*.toml``) or
coating (``parameters/coatings/*.toml``) carries a ``prior`` table next to its value::

    [parameters.vdw_bond_energy.prior]
    distribution = "loguniform"          # uniform | loguniform | normal (truncated to [low, high])
    low = 3.6e-21                        # SI, the unit of the value
    high = 3.7e-20
    source = "..."                       # where the range comes from
    reason = "..."                       # why it is this wide
    measure = "..."                      # the experiment that would pin it down (optional)

A coating's prior (``[properties.vdw_bond_energy.prior]``) is the prior of the parameter
``coating_vdw_bond_energy``. :func:`priors_for` returns the priors of every constant that the
user has not fixed: a value given by ``--set``, a config file or :meth:`Parameters.updated` is
fixed (its source is no longer the set's) and is not sampled. Measured inputs (the scan, the
gear design, the torque) carry no prior.
"""

from __future__ import annotations

import functools
import math
import tomllib
from dataclasses import asdict, dataclass
from importlib import resources

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["Prior", "DISTRIBUTIONS", "RULE_UNUSED", "unused_by_rule", "priors_for", "check_priors", "set_priors", "coating_priors"]

#: distributions a prior may have
DISTRIBUTIONS = ("uniform", "loguniform", "normal")

#: keys of a ``prior`` table
PRIOR_KEYS = ("distribution", "low", "high", "mean", "sd", "source", "reason", "measure")


@dataclass(frozen=True)
class Prior:
    """The prior of one uncertain constant (SI values, the unit of the parameter).

    Attributes
    ----------
    name : str
        The parameter's canonical name (``coating_<property>`` for a coating's constant).
    distribution : {"uniform", "loguniform", "normal"}
        ``normal`` is truncated to ``[low, high]``.
    low, high : float
        Bounds of the prior, ``low < high`` (``low > 0`` for ``loguniform``) [unit of the parameter].
    mean, sd : float or None
        Mean and standard deviation of a ``normal`` prior before truncation [unit of the parameter].
    source : str
        Where the range comes from (papers, the thesis's own numbers).
    reason : str
        Why the range is this wide.
    measure : str
        The experiment that would pin the constant down (the designer's sentence names it).
    """

    name: str
    distribution: str
    low: float
    high: float
    mean: float | None = None
    sd: float | None = None
    source: str = ""
    reason: str = ""
    measure: str = ""

    def __post_init__(self):
        what = f"prior of '{self.name}'"
        if self.distribution not in DISTRIBUTIONS:
            raise InputError(f"{what}: distribution '{self.distribution}' is not one of {', '.join(DISTRIBUTIONS)}.")
        for key in ("low", "high"):
            value = getattr(self, key)
            if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
                raise InputError(f"{what}: {key} must be a finite number, got {value!r}.")
        if not self.low < self.high:
            raise InputError(f"{what}: empty or inverted range [{self.low:g}, {self.high:g}]: low must be below "
                             "high (fix a constant with --set NAME=VALUE instead of giving it an empty range).")
        if self.distribution == "loguniform" and self.low <= 0:
            raise InputError(f"{what}: a log-uniform prior needs low > 0, got {self.low:g}.")
        if self.distribution == "normal":
            if self.mean is None or self.sd is None or not (math.isfinite(self.mean) and math.isfinite(self.sd)):
                raise InputError(f"{what}: a normal prior needs a finite mean and sd.")
            if self.sd <= 0:
                raise InputError(f"{what}: sd must be positive, got {self.sd:g}.")
            if not self.low <= self.mean <= self.high:
                raise InputError(f"{what}: mean {self.mean:g} lies outside its bounds [{self.low:g}, {self.high:g}].")

    def ppf(self, u):
        """The value at cumulative probability ``u`` in [0, 1] (inverse CDF) [unit of the parameter].

        ``uniform``: ``low + u (high - low)``; ``loguniform``: ``low (high/low)^u``; ``normal``: the
        truncated normal's quantile (:func:`scipy.stats.truncnorm`). Arrays give arrays.
        """
        u = np.asarray(u, dtype=float)
        if np.any((u < 0) | (u > 1)) or np.any(np.isnan(u)):
            raise InputError(f"prior of '{self.name}': ppf takes probabilities in [0, 1].")
        if self.distribution == "uniform":
            out = self.low + u * (self.high - self.low)
        elif self.distribution == "loguniform":
            out = np.exp(np.log(self.low) + u * (np.log(self.high) - np.log(self.low)))
        else:
            from scipy.stats import truncnorm

            a, b = (self.low - self.mean) / self.sd, (self.high - self.mean) / self.sd
            out = truncnorm.ppf(u, a, b, loc=self.mean, scale=self.sd)
        out = np.clip(out, self.low, self.high)  # round-off at u = 0 and 1
        return float(out) if out.ndim == 0 else out

    def cdf(self, x):
        """Cumulative probability of the value ``x`` (inverse of :meth:`ppf`) [-]."""
        x = np.clip(np.asarray(x, dtype=float), self.low, self.high)
        if self.distribution == "uniform":
            out = (x - self.low) / (self.high - self.low)
        elif self.distribution == "loguniform":
            out = np.log(x / self.low) / np.log(self.high / self.low)
        else:
            from scipy.stats import truncnorm

            a, b = (self.low - self.mean) / self.sd, (self.high - self.mean) / self.sd
            out = truncnorm.cdf(x, a, b, loc=self.mean, scale=self.sd)
        return float(out) if np.ndim(out) == 0 else out

    @property
    def log_scale(self) -> bool:
        """Whether the prior is naturally read on a log axis (a log-uniform prior)."""
        return self.distribution == "loguniform"

    def describe(self) -> str:
        """One line: distribution and range (SI numbers)."""
        text = f"{self.distribution} [{self.low:.4g}, {self.high:.4g}]"
        if self.distribution == "normal":
            text += f", mean {self.mean:.4g}, sd {self.sd:.4g}"
        return text

    def to_dict(self) -> dict:
        """Plain dict (JSON)."""
        return asdict(self)


def _spec_of(name: str):
    from memstribo.parameters import SPECS

    return SPECS.get(name)


def check_priors(priors, values=None) -> dict[str, Prior]:
    """Check a list of priors and return them by name.

    Parameters
    ----------
    priors : iterable of Prior
    values : Mapping, optional
        Nominal values [SI]; each must lie inside its prior.

    Raises
    ------
    InputError
        A constant named twice, a constant that is not a parameter, a prior outside the parameter's
        physical bounds (its ``SPECS`` range), a nominal value outside its prior.
    """
    from memstribo.parameters import _in_range  # the parameter's physical range

    out: dict[str, Prior] = {}
    for prior in priors:
        if prior.name in out:
            raise InputError(f"the constant '{prior.name}' is named twice among the priors; give each one prior.")
        spec = _spec_of(prior.name)
        if spec is None or spec.kind != "float":
            raise InputError(f"prior of '{prior.name}': not a number parameter of memstribo "
                             "('memstribo parameters' lists them).")
        for key in ("low", "high"):
            if not _in_range(getattr(prior, key), spec):
                raise InputError(f"prior of '{prior.name}': {key} = {getattr(prior, key):g} is outside the "
                                 f"parameter's physical bounds: {spec.allowed()}" + (f"; {spec.why}" if spec.why
                                                                                     else "") + ".")
        if values is not None and values.get(prior.name) is not None:
            value = float(values[prior.name])
            if not prior.low <= value <= prior.high:
                raise InputError(f"the nominal value of '{prior.name}' ({value:.4g}) lies outside its prior "
                                 f"[{prior.low:.4g}, {prior.high:.4g}]: widen the prior or fix the constant.")
        out[prior.name] = prior
    return out


def _prior_from_table(name: str, table, where: str) -> Prior:
    if not isinstance(table, dict):
        raise InputError(f"{where}: the prior of '{name}' must be a table.")
    unknown = [k for k in table if k not in PRIOR_KEYS]
    if unknown:
        raise InputError(f"{where}: the prior of '{name}' has unknown key '{unknown[0]}'; allowed: "
                         f"{', '.join(PRIOR_KEYS)}.")
    missing = [k for k in ("distribution", "low", "high") if k not in table]
    if missing:
        raise InputError(f"{where}: the prior of '{name}' lacks {', '.join(missing)}.")
    return Prior(name=name, **{k: table[k] for k in PRIOR_KEYS if k in table})


@functools.lru_cache(maxsize=None)
def _set_table(set_name: str) -> dict:
    text = (resources.files("memstribo.parameters") / "sets" / f"{set_name}.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


@cites("model")
def set_priors(set_name: str) -> dict[str, Prior]:
    """The priors written in parameter set ``set_name`` (and its base sets; a set's own prior replaces its base's).

    A set that changes a value of its base without giving it a prior keeps no prior for it: that
    value is then not sampled (the base's range was for the base's value).
    """
    from memstribo.parameters import available_parameter_sets

    if set_name not in available_parameter_sets():
        raise InputError(f"unknown parameter set '{set_name}'.")
    data = _set_table(set_name)
    base = data.get("meta", {}).get("base")
    out = dict(set_priors(base)) if base and base != set_name else {}
    for name, entry in data.get("parameters", {}).items():
        if not isinstance(entry, dict):
            continue
        if "prior" in entry:
            out[name] = _prior_from_table(name, entry["prior"], f"parameter set '{set_name}'")
        elif "value" in entry and name in out:
            del out[name]  # the value changed and its range was for the old one
    return out


def coating_priors(coating) -> dict[str, Prior]:
    """The priors of a coating's constants, named ``coating_<property>`` (the parameters that override them).

    ``coating``: a name (``"OTS"``) or a :class:`memstribo.physics.coating.Coating`.
    """
    from memstribo.physics.coating import _OVERRIDABLE, _coating_files

    name = getattr(coating, "name", coating)
    files = _coating_files()
    key = str(name).strip().upper()
    if key not in files:
        raise InputError(f"unknown coating {name!r}; available: {', '.join(sorted(files))}.")
    data = tomllib.loads(files[key])
    out = {}
    for prop, entry in data.get("properties", {}).items():
        if isinstance(entry, dict) and "prior" in entry:
            if prop not in _OVERRIDABLE:
                raise InputError(f"coating file {key}: {prop} has a prior but is not a constant memstribo can vary "
                                 f"(allowed: {', '.join(_OVERRIDABLE)}).")
            out[f"coating_{prop}"] = _prior_from_table(f"coating_{prop}", entry["prior"], f"coating file {key}")
    return out


def _set_sources(set_name: str) -> dict[str, str]:
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values(set_name)
    return {name: params.source(name) for name in params}


#: the constants each ``vdw_energy_rule`` leaves without effect on the result (MODEL 7h): under 'hysteresis'
#: U_vdW = phi w12 / n_site, so vdw_bond_energy is not used and the site density cancels in the vdW friction
#: (n_site U_vdW / D_chem = phi w12 / D_chem); under 'thesis' the dissipated fraction is not used
RULE_UNUSED = {"hysteresis": ("vdw_bond_energy", "vdw_site_density"), "thesis": ("vdw_dissipated_fraction",)}


def unused_by_rule(params) -> tuple[str, ...]:
    """The constants that ``params``'s ``vdw_energy_rule`` does not use (not sampled; :data:`RULE_UNUSED`)."""
    rule = params.get("vdw_energy_rule") if hasattr(params, "get") else None
    return RULE_UNUSED.get(rule or "thesis", ())


def priors_for(params, coating=None) -> dict[str, Prior]:
    """The priors of every uncertain constant of ``params`` that the user has not fixed.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        The parameter set (its ``name`` says which set's priors apply; an unknown name: the
        default set's). A constant whose value came from ``--set``, a config file or
        :meth:`~memstribo.parameters.Parameters.updated` (its source is not the set's) is fixed.
    coating : str or Coating, optional
        The coating whose constants are added (``coating_*``; unless set as parameters).

    Returns
    -------
    dict
        ``{name: Prior}`` in the order of the set file, without the constants the set's ``vdw_energy_rule`` does
        not use (:func:`unused_by_rule`).

    Raises
    ------
    InputError
        A prior outside its parameter's physical bounds, a nominal value outside its prior, a
        constant named twice.
    """
    from memstribo.parameters import DEFAULT_SET, available_parameter_sets

    set_name = params.name if getattr(params, "name", None) in available_parameter_sets() else DEFAULT_SET
    sources = _set_sources(set_name)
    unused = unused_by_rule(params)
    priors = []
    for name, prior in set_priors(set_name).items():
        if name in params and params.source(name) != sources.get(name):
            continue  # fixed by the user
        if name in unused:
            continue  # the vdW energy rule does not use it (MODEL 7h)
        priors.append(prior)
    values = {p.name: params[p.name] for p in priors if p.name in params}
    if coating is not None:
        for name, prior in coating_priors(coating).items():
            if name in params and params[name] is not None:
                continue  # set as a parameter: fixed
            priors.append(prior)
            from memstribo.physics.coating import get_coating

            values[name] = getattr(get_coating(getattr(coating, "name", coating)), name[len("coating_"):])
    return check_priors(priors, values)
