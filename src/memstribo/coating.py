"""Self-assembled monolayer (SAM) coatings of the teeth and their wear state (thesis 5.2-5.4, 5.5.3).

A coating is a parameter set (``coatings/<name>.toml``: value, unit and source of each
property). Where either surface is coated no chemical bonds form (U_chem = 0, thesis 5.4);
van der Waals bonds and elastic interlocking remain, with the coating's own vdW parameters.

Wear state Omega (5.5.3): the pinion's coating is fully worn and a fraction Omega of the
gear's coating is worn, so that Omega = 0 is the fully functionalised pair and Omega = 1
bare silicon. :func:`wear_sweep` runs the meshing-cycle simulation
(:func:`memstribo.mesh.simulate_mesh`) for a list of Omega and returns COF, its split, the
friction force, the available tangential force and the stiction margin for each.
"""

from __future__ import annotations

import functools
import math
import tomllib
from dataclasses import dataclass, field, replace
from importlib import resources

import numpy as np

from .errors import InputError, did_you_mean
from .references import cites

__all__ = ["Coating", "available_coatings", "get_coating", "check_wear", "wear_sweep", "critical_wear",
           "cof_at_wear", "calibrate_vdw_bond_energy", "SWEEP_VARIABLES"]

#: Variables of :func:`wear_sweep`'s dataset (and keys of ``memstribo coating --json``), with units.
SWEEP_VARIABLES = {
    "cof": ("", "coefficient of friction over the meshing cycle"),
    "cof_chemical": ("", "COF from chemical bonds"),
    "cof_vdw": ("", "COF from van der Waals bonds"),
    "cof_elastic": ("", "COF from elastic interlocking"),
    "friction_force": ("N", "largest resisting force R(c): friction of all pairs in mesh (MODEL 7b)"),
    "tangential_force": ("N", "available tangential force F_t = T / r (4-27)"),
    "stiction": ("", "1 where max R(c) > F_t (stiction), else 0"),
    "stiction_margin": ("N", "stiction margin F_t - max R(c) (MODEL 7b)"),
}


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
          "water_contact_angle_deg": "deg"}


@functools.lru_cache(maxsize=None)
def _coating_files() -> dict[str, str]:
    folder = resources.files("memstribo") / "coatings"
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
        ``"OTS"`` (octadecyltrichlorosilane, the thesis's coating, default) or ``"FDTS"``.
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
        For an unknown name; the message lists the available coatings.
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
_SUMMARY_KEYS = {"cof": "cof_mean", "friction_force": "resisting_force_max"}


def _summary_value(summary: dict, dataset, key: str) -> float:
    """A sweep quantity from the mesh summary, or from the dataset where the summary lacks it."""
    key_in_summary = _SUMMARY_KEYS.get(key, key)
    if key_in_summary in summary and summary[key_in_summary] is not None:
        key = key_in_summary
        value = summary[key]
        return float(value) if not isinstance(value, (bool, np.bool_)) else float(bool(value))
    if key == "stiction" and "stiction_margin" in summary:
        return float(summary["stiction_margin"] < 0)
    if key in dataset:
        data = dataset[key]
        if key == "stiction_margin":
            return float(data.min())
        if key == "friction_force":
            return float(data.max())
        return float(data.mean())
    raise KeyError(key)


@cites("thesis", "model")
def wear_sweep(params, coating: Coating | str | None, wears, *, roughness=None, steps: int | None = None,
               progress: bool = False, known=None):
    """COF, its split, friction force and stiction margin for each worn fraction Omega (5.5.3).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Model parameters (gear, load, roughness, nanoblocks).
    coating : Coating, str or None
        The gear's coating (``None``: bare silicon, all Omega give the bare result).
    wears : sequence of float
        Worn fractions Omega of the gear's coating, each from 0 to 1 [-].
    roughness : Profile, optional
        Roughness of the flanks; ``None`` uses the mesh's default.
    steps : int, optional
        Steps of each meshing-cycle simulation (the mesh's default if None).
    progress : bool
        Show a progress bar over the wear states on stderr.
    known : mapping of float to xarray.Dataset, optional
        Meshing cycles already computed with exactly these arguments (``simulate_mesh(params,
        roughness, steps=steps, coating=coating, wear=Omega)``), by Omega: used instead of
        computing them again (the same numbers; a design map passes its point's first cycle).

    Returns
    -------
    xarray.Dataset
        Over dimension ``wear``: the variables of :data:`SWEEP_VARIABLES` with ``units`` and
        ``long_name`` attributes; the per-wear values are those of ``mesh.summarize``.

    Notes
    -----
    The pinion's coating is fully worn and Omega of the gear's (thesis 5.5.3), so Omega = 1
    equals the bare mesh result. Thesis Figure 5-28: COF 0.185 (Omega = 0), 0.32 (0.2),
    about 0.75 (0.8), 0.84 (1).
    """
    import xarray as xr

    from . import mesh

    if isinstance(coating, str):
        coating = get_coating(coating, params)
    omega = np.atleast_1d(check_wear(wears))
    rows = {key: np.empty(omega.size) for key in SWEEP_VARIABLES}
    states = enumerate(omega)
    if progress:
        import sys

        from tqdm.auto import tqdm

        states = tqdm(states, total=omega.size, desc="wear states", unit="cycle", file=sys.stderr, leave=False)
    known = {float(w): dataset for w, dataset in (known or {}).items()}
    for i, w in states:  # one meshing-cycle simulation per wear state
        dataset = known.get(float(w))
        if dataset is None:
            dataset = mesh.simulate_mesh(params, roughness, steps=steps, coating=coating, wear=float(w))
        summary = mesh.summarize(dataset)
        for key in SWEEP_VARIABLES:
            rows[key][i] = _summary_value(summary, dataset, key)
    sweep = xr.Dataset(
        {key: ("wear", rows[key], {"units": unit, "long_name": text}) for key, (unit, text) in SWEEP_VARIABLES.items()},
        coords={"wear": ("wear", omega, {"units": "", "long_name": "worn fraction Omega of the gear's coating"})},
        attrs={"coating": "bare silicon" if coating is None else coating.name},
    )
    return sweep


def cof_at_wear(wear, sweep) -> np.ndarray:
    """COF at worn fraction(s) Omega by linear interpolation of a :func:`wear_sweep` [-]."""
    omega = check_wear(wear)
    return np.interp(omega, sweep["wear"].values, sweep["cof"].values)


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


@cites("thesis", "model")
def calibrate_vdw_bond_energy(params, coating: Coating | str, target_cof: float = 0.185, *, roughness=None,
                              steps: int | None = None, rtol: float = 1e-3,
                              max_runs: int = 6) -> tuple[Coating, dict]:
    """Scale the coating's U_vdW so that the fully coated pair (Omega = 0) has COF ``target_cof``.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Model parameters (the reference conditions of thesis 5.4: 25 uN, the default gear).
    coating : Coating or str
        Coating to calibrate.
    target_cof : float
        COF of the fully coated pair [-] (thesis 5.5.3: 0.185).
    roughness, steps
        As for :func:`wear_sweep`.
    rtol : float
        Relative tolerance on the COF [-].
    max_runs : int
        Meshing-cycle runs allowed.

    Returns
    -------
    (Coating, dict)
        The calibrated coating and a record: ``vdw_bond_energy_before``, ``..._after`` [J],
        ``cof_before``, ``cof_after`` [-], ``runs``, ``converged``.

    Notes
    -----
    With the coating U_chem = 0, so COF = cof_vdw + cof_elastic, and cof_vdw is proportional to
    U_vdW at a fixed contact; the contact itself barely depends on U_vdW (the vdW adhesion force
    does, slightly), so U_vdW <- U_vdW (target - cof_elastic) / (COF - cof_elastic) converges in
    a few meshing-cycle runs (at most ``max_runs``; tolerance ``rtol`` on the cycle's mean COF).
    Raises :class:`InputError` if cof_elastic alone reaches the target.
    """
    from . import mesh

    if isinstance(coating, str):
        coating = get_coating(coating, params)
    if not (0 < target_cof < 10):
        raise InputError(f"target_cof must be a COF between 0 and 10, got {target_cof!r}.")
    current = coating
    history = []
    for _ in range(max_runs):
        summary = mesh.summarize(mesh.simulate_mesh(params, roughness, steps=steps, coating=current, wear=0.0))
        cof, cof_elastic = float(summary["cof_mean"]), float(summary["cof_elastic"])
        history.append((current.vdw_bond_energy, cof))
        if abs(cof - target_cof) <= rtol * target_cof:
            break
        if cof_elastic >= target_cof or cof <= cof_elastic:
            raise InputError(f"cannot calibrate U_vdW: the elastic COF {cof_elastic:.3g} alone (total {cof:.3g}) "
                             f"does not leave room for the target {target_cof:g}.")
        current = current.updated(vdw_bond_energy=current.vdw_bond_energy * (target_cof - cof_elastic)
                                  / (cof - cof_elastic))
    return current, {"vdw_bond_energy_before": coating.vdw_bond_energy,
                     "vdw_bond_energy_after": current.vdw_bond_energy,
                     "cof_before": history[0][1], "cof_after": history[-1][1], "runs": len(history),
                     "converged": abs(history[-1][1] - target_cof) <= rtol * target_cof}
