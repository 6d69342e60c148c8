"""Self-assembled monolayer (SAM) coatings of the teeth and their wear state (thesis 5.2-5.4, 5.5.3).

A coating is a parameter set (``coatings/<name>.toml``: value, unit and source of each
property). Where either surface is coated no chemical bonds form (U_chem = 0, thesis 5.4);
van der Waals bonds and elastic interlocking remain, with the coating's own vdW parameters.

Wear state Omega (5.5.3): the pinion's coating is fully worn and a fraction Omega of the
gear's coating is worn, so that Omega = 0 is the fully functionalised pair and Omega = 1
bare silicon. :func:`memstribo.simulations.coating_wear.wear_sweep` runs the meshing cycle for a list of
Omega; :func:`critical_wear` and :func:`cof_at_wear` read its result.
"""

from __future__ import annotations

import functools
import math
import tomllib
from dataclasses import dataclass, field, replace
from importlib import resources

import numpy as np

from memstribo.errors import InputError, did_you_mean
from memstribo.references import cites

__all__ = ["Coating", "available_coatings", "get_coating", "coating_config", "check_wear", "critical_wear", "cof_at_wear"]

@dataclass(frozen=True)
class Coating:
    """A SAM coating as a parameter set (thesis 5.3-5.4).

    Attributes
    ----------
    name : str
        Short name, e.g. ``"OTS"``.
    vdw_bond_energy : float
        Energy of one vdW bond between coated surfaces U_vdW [J].
    hamaker_constant : float
        Hamaker constant of the coated pair across vacuum A [J].
    cutoff_distance : float
        Contact (cut-off) separation D0 of the coated pair [m].
    work_of_adhesion : float
        Work of adhesion of the coated pair w [J/m^2].
    water_contact_angle_deg : float
        Static water contact angle [deg] (informative).
    degradation_temperature : float
        Temperature above which the coating degrades in air [K] (published; a contact temperature
        past it is a warning, :func:`memstribo.simulations.tooth_life.tooth_life`).
    description : str
        Chemistry in words.
    sources : dict
        Property name -> provenance text.
    """

    name: str
    vdw_bond_energy: float
    hamaker_constant: float
    cutoff_distance: float
    work_of_adhesion: float
    water_contact_angle_deg: float = math.nan
    degradation_temperature: float = math.nan
    description: str = ""
    sources: dict = field(default_factory=dict, compare=False, hash=False)

    def updated(self, **changes) -> "Coating":
        """A copy with some properties changed (e.g. a calibrated ``vdw_bond_energy``)."""
        unknown = set(changes) - {"vdw_bond_energy", "hamaker_constant", "cutoff_distance", "work_of_adhesion"}
        if unknown:
            raise InputError(f"cannot change coating properties {sorted(unknown)}; allowed: vdw_bond_energy, "
                             "hamaker_constant, cutoff_distance, work_of_adhesion.")
        for key, value in changes.items():
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise InputError(f"coating {key} must be a finite number > 0, got {value!r}.")
        sources = dict(self.sources) | {key: "changed by the caller" for key in changes}
        return replace(self, sources=sources, **changes)


_UNITS = {"vdw_bond_energy": "J", "hamaker_constant": "J", "cutoff_distance": "m", "work_of_adhesion": "J/m^2",
          "water_contact_angle_deg": "deg", "degradation_temperature": "K"}


@functools.lru_cache(maxsize=None)
def _coating_files() -> dict[str, str]:
    folder = resources.files("memstribo.parameters") / "coatings"
    files = {}
    for entry in folder.iterdir():
        if entry.name.endswith(".toml"):
            data = tomllib.loads(entry.read_text(encoding="utf-8"))
            files[data["meta"]["name"].upper()] = entry.read_text(encoding="utf-8")
    return files


def available_coatings() -> list[str]:
    """Names of the coatings shipped with memstribo (``coatings/*.toml``)."""
    return sorted(_coating_files())


@cites("israelachvili_2011", "srinivasan_1998", "thesis")
def get_coating(name: str = "OTS", params=None) -> Coating:
    """The coating parameter set ``name`` (case-insensitive), with the overrides of ``params``.

    Parameters
    ----------
    name : str
        ``"OTS"`` (octadecyltrichlorosilane, the thesis's coating, default), ``"FDTS"``, ``"DDMS"`` or
        ``"W"`` (a tungsten coating); :func:`available_coatings` lists them.
    params : memstribo.parameters.Parameters, optional
        Its ``coating_*`` parameters that are set (``--set coating_vdw_bond_energy=...``, a
        config file from ``memstribo coating --calibrate --out``) replace the coating's values;
        each replaced value's source says where it came from.

    Returns
    -------
    Coating

    Raises
    ------
    InputError
        For an unknown name (the message lists the available coatings), or a coating file without a
        degradation temperature.
    """
    files = _coating_files()
    key = str(name).strip().upper()
    if key not in files:
        raise InputError(f"unknown coating {name!r}; available: {', '.join(available_coatings())}."
                         + did_you_mean(key, files))
    data = tomllib.loads(files[key])
    values, sources = {}, {}
    for prop, entry in data["properties"].items():
        if prop not in _UNITS:
            raise InputError(f"coating file {key}: unknown property {prop!r}.")
        if entry.get("unit", "") != _UNITS[prop]:
            raise InputError(f"coating file {key}: {prop} must be given in {_UNITS[prop]}, not {entry.get('unit')!r}.")
        values[prop] = float(entry["value"])
        sources[prop] = entry["source"]
    if not (math.isfinite(values.get("degradation_temperature", math.nan)) and values["degradation_temperature"] > 0):
        raise InputError(f"coating file {key} has no degradation temperature: every coating needs "
                         "[properties.degradation_temperature] (value in K and a published source), the "
                         "temperature above which it degrades in air.")
    if params is not None:
        for prop in _OVERRIDABLE:
            value = params[f"coating_{prop}"] if f"coating_{prop}" in params else None
            if value is not None:
                values[prop] = float(value)
                sources[prop] = f"parameter coating_{prop} ({params.source(f'coating_{prop}')})"
    return Coating(name=data["meta"]["name"], description=data["meta"].get("description", ""), sources=sources,
                   **values)


#: Coating properties that the parameters ``coating_<property>`` override.
_OVERRIDABLE = ("vdw_bond_energy", "hamaker_constant", "cutoff_distance", "work_of_adhesion")


def coating_config(coating: Coating, note: str = "") -> str:
    """A config file (TOML, ``[parameters]``) that sets ``coating``'s overridable values.

    ``memstribo --config FILE`` reads it back: the ``coating_*`` parameters then replace the
    coating set's values wherever that coating is used (:func:`get_coating` with the parameters).
    """
    import tomli_w

    table = {f"coating_{prop}": {"value": float(getattr(coating, prop)), "unit": _UNITS[prop],
                                 "source": coating.sources.get(prop, "") + (f"; {note}" if note else "")}
             for prop in _OVERRIDABLE}
    header = (f"# memstribo config: the {coating.name} coating's values ({note or 'as given'}).\n"
              "# Use it with --config FILE (or copy the [parameters] entries into your own config).\n")
    return header + tomli_w.dumps({"parameters": table})


def check_wear(wear) -> np.ndarray:
    """Worn fraction(s) Omega as an array, or :class:`InputError` if outside 0..1."""
    try:
        array = np.asarray(wear, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"wear Omega must be a number or list of numbers from 0 to 1, got {wear!r}.") from None
    if array.size == 0 or not np.all(np.isfinite(array)) or np.any(array < 0) or np.any(array > 1):
        raise InputError(f"wear Omega must be a fraction from 0 (coated) to 1 (bare), got {wear!r}.")
    return array


#: Which key of ``mesh.summarize`` gives each sweep quantity (the cycle's mean COF and its
#: energy split, the largest friction force, the total F_t, the lowest stiction margin).
def cof_at_wear(wear, sweep) -> np.ndarray:
    """COF at worn fraction(s) Omega by linear interpolation of a :func:`wear_sweep` [-]."""
    omega = check_wear(wear)
    return np.interp(omega, sweep["wear"].values, sweep["cof_mean"].values)


def critical_wear(sweep) -> float | None:
    """Smallest worn fraction Omega at which F_f >= F_t (stiction returns) [-], or None.

    The stiction margin F_t - F_f of the sweep is interpolated linearly between its wear
    states; ``None`` if the margin stays positive up to the largest Omega of the sweep.
    """
    wear = sweep["wear"].values
    margin = sweep["stiction_margin"].values
    order = np.argsort(wear)
    wear, margin = wear[order], margin[order]
    if margin[0] <= 0:
        return float(wear[0])
    below = np.flatnonzero(margin <= 0)
    if below.size == 0:
        return None
    j = below[0]
    w0, w1, m0, m1 = wear[j - 1], wear[j], margin[j - 1], margin[j]
    return float(w0 + (w1 - w0) * m0 / (m0 - m1))


