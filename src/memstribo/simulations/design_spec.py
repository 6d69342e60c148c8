"""The design search's specification: variables, constraints, objectives and budget (issue #39).

A design spec (TOML) names the design variables with their bounds, the geometric constraints,
the objectives and the search's budget; :func:`load_design_spec` validates it whole before any
meshing cycle runs (bounds in the wrong order, a constraint no design can meet, an unknown
objective, a coating that is not shipped, a budget that cannot finish one generation).
:mod:`memstribo.simulations.design_search` runs the search.

Spec file::

    [parameters]                        # optional: base overrides (the default design)
    mesh_elements_across_contact = 24

    [design]
    name = "thesis pair"
    objectives = ["window", "footprint"]   # window, efficiency, coating_life, footprint
    population = 8                      # designs per generation
    generations = 4
    seed = 1
    realisations = 4                    # roughness realisations per verdict
    steps = 21                          # positions per meshing cycle (cheap cycles)
    stiction_probability = 0.5          # p_s: the 95 % upper bound of P(stiction) must be below it
    fracture_probability = 0.01         # p_f over the required cycles
    cycles = 1e9                        # required life [pinion revolutions]
    max_cycles = 5000                   # optional budget of meshing cycles

    [design.torque]                     # the operating torque range searched for the window
    min = "20 nN*m"
    max = "400 nN*m"
    num = 8                             # log-spaced torques where the stiction edge is located

    [design.variables]
    module = {min = "3 um", max = "5 um"}
    face_width = {min = "1 um", max = "4 um", step = "0.5 um"}
    teeth_pinion = {min = 17, max = 25}
    ratio = {min = 3, max = 5}          # or teeth_gear = {min = ..., max = ...}
    pressure_angle = {min = "14.5 deg", max = "25 deg"}
    coating = ["none", "OTS"]

    [design.constraints]
    contact_ratio_min = 1.2
    tooth_thickness_min = "0.5 um"      # tip tooth thickness s_a >= the process's minimum feature
    centre_distance = "190 um"          # fixed: the module follows from the teeth
    # ratio = 4                         # fixed: z2 = round(4 z1)
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from memstribo.checks import refuse_unknown_keys
from memstribo.errors import InputError, did_you_mean
from memstribo.units import printable

__all__ = ["DesignSpec", "DesignVariable", "OBJECTIVES", "design_spec", "load_design_spec", "decode",
           "complete", "design_key", "geometry_constraints", "CONSTRAINT_NAMES", "design_parameters"]

#: objectives: name -> (sense, meaning); the search minimises ``sense * value``
OBJECTIVES = {
    "window": (-1.0, "width of the safe drive-torque window [N*m] (maximised)"),
    "efficiency": (-1.0, "median mesh efficiency at the window's lower edge [-] (maximised)"),
    "coating_life": (-1.0, "meshing cycles to coating failure at the window's lower edge (maximised, log10)"),
    "footprint": (1.0, "area of the pair's bounding rectangle [m^2] (minimised)"),
}
FLOAT_VARIABLES = ("module", "face_width", "pressure_angle", "addendum_coefficient", "ratio")
INT_VARIABLES = ("teeth_pinion", "teeth_gear")
_DESIGN_KEYS = {"name", "objectives", "population", "generations", "seed", "realisations", "steps",
                "stiction_probability", "fracture_probability", "cycles", "max_cycles", "cycles_observed",
                "torque", "variables", "constraints"}
_CONSTRAINT_KEYS = {"contact_ratio_min", "tooth_thickness_min", "centre_distance", "ratio"}
#: the geometric constraints, in the order of :func:`geometry_constraints` (each <= 0 where met)
CONSTRAINT_NAMES = ("undercut of the pinion", "undercut of the gear", "interference", "pointed tip",
                    "contact ratio >= contact_ratio_min", "tip tooth thickness >= tooth_thickness_min",
                    "module within its allowed range (fixed centre distance)",
                    "root fillet fits the tooth space (the root stress's tooth form)")
#: designs sampled from the box to find a constraint that no design can meet
FEASIBILITY_SAMPLES = 2000


@dataclass(frozen=True)
class DesignVariable:
    """One design variable: ``kind`` is "float", "int" or "choice"; bounds in SI; ``step`` rounds a float."""

    name: str
    kind: str
    low: float = 0.0
    high: float = 0.0
    step: float | None = None
    choices: tuple[str, ...] = ()

    @property
    def bounds(self) -> tuple[float, float]:
        """The variable's interval in the search's real coordinates."""
        if self.kind == "choice":
            return 0.0, len(self.choices) - 1e-9
        return self.low, self.high

    def value(self, x: float):
        """The design value of the real coordinate ``x`` (rounded for integers, steps and choices)."""
        lo, hi = self.bounds
        x = min(max(float(x), lo), hi)
        if self.kind == "choice":
            return self.choices[min(int(math.floor(x)), len(self.choices) - 1)]
        if self.kind == "int":
            return int(round(x))
        if self.step:
            k = round((x - self.low) / self.step)
            return float(f"{min(self.low + k * self.step, self.high):.12g}")  # 5e-06, not 4.9999999999999996e-06
        return float(x)

    def coordinate(self, value) -> float:
        """The real coordinate of a design value (the inverse of :meth:`value` on its grid)."""
        if self.kind == "choice":
            return float(self.choices.index(value))
        return float(value)


@dataclass(frozen=True)
class DesignSpec:
    """A design search: the variables, constraints, objectives, torque range and budget (SI units)."""

    name: str
    variables: tuple[DesignVariable, ...]
    objectives: tuple[str, ...]
    torque_min: float
    torque_max: float
    torque_num: int = 8
    population: int = 8
    generations: int = 4
    seed: int = 1
    realisations: int = 4
    steps: int | None = None
    stiction_probability: float = 0.5
    fracture_probability: float = 0.01
    cycles: float = 1e9
    max_cycles: int | None = None
    cycles_observed: float | None = None
    contact_ratio_min: float = 1.2
    tooth_thickness_min: float = 0.0
    centre_distance: float | None = None
    ratio: float | None = None
    parameters: dict[str, Any] = field(default_factory=dict)
    source: str = "python"

    @property
    def torques(self) -> np.ndarray:
        """The log-spaced drive torques [N*m] on which the window's lower (stiction) edge is located."""
        return np.geomspace(self.torque_min, self.torque_max, self.torque_num)

    @property
    def probes(self) -> int:
        """Most ensemble verdicts per design: the bisection over the torques, plus the coating-life rerun."""
        return int(math.ceil(math.log2(self.torque_num + 1))) + (1 if "coating_life" in self.objectives else 0)

    @property
    def cycles_per_design(self) -> int:
        """Most meshing cycles one design costs (convergence checks not counted)."""
        return self.realisations * self.probes


def _number(value, unit: str, key: str, where: str) -> float:
    from memstribo.units import to_si

    try:
        number = to_si(value, unit, key)
    except InputError as exc:
        raise InputError(f"{where}: {key}: {exc}") from None
    if not math.isfinite(number):
        raise InputError(f"{where}: {key} = {printable(repr(value), 40)} is not a finite number.")
    return number


def _integer(table, key, default, low, high, where) -> int:
    value = table.get(key, default)
    if not isinstance(value, int) or isinstance(value, bool) or not low <= value <= high:
        raise InputError(f"{where}: {key} = {printable(repr(value), 40)}: give an integer from {low} to {high}.")
    return value


def _variable(key: str, raw, base, where: str) -> DesignVariable:
    from memstribo.physics.coating import available_coatings
    from memstribo.simulations.study import _unit_of

    if key == "coating":
        shipped = available_coatings()
        if not isinstance(raw, list) or not raw or not all(isinstance(c, str) for c in raw):
            raise InputError(f"{where}: coating = {printable(repr(raw), 60)}: give a list of coating names "
                             f"(\"none\" for bare silicon), from {shipped}.")
        names = []
        for name in raw:
            match = [c for c in shipped if c.lower() == name.lower()]
            if name.lower() != "none" and not match:
                raise InputError(f"{where}: coating '{printable(name, 40)}' is not a shipped coating; shipped: "
                                 f"{shipped} (or \"none\").{did_you_mean(name, shipped)}")
            names.append("none" if name.lower() == "none" else match[0])
        if len(set(names)) != len(names):
            raise InputError(f"{where}: coating lists {names}: give each coating once.")
        return DesignVariable("coating", "choice", choices=tuple(names))
    if key.startswith("profile_shift"):
        raise InputError(f"{where}: {key}: memstribo's meshing model has no profile shift yet (GearPair: x = 0, the "
                         "standard centre distance), so it cannot be a design variable; allowed: "
                         f"{sorted(FLOAT_VARIABLES + INT_VARIABLES + ('coating',))}.")
    allowed = FLOAT_VARIABLES + INT_VARIABLES + ("coating",)
    if key not in allowed:
        raise InputError(f"{where}: unknown design variable '{printable(key, 40)}'; allowed: {sorted(allowed)}."
                         f"{did_you_mean(key, allowed)}")
    if not isinstance(raw, Mapping) or set(raw) - {"min", "max", "step"} or not {"min", "max"} <= set(raw):
        raise InputError(f"{where}: {key} = {printable(repr(raw), 60)}: give a table {{min = ..., max = ...}} "
                         "(and optionally step = ...); units allowed.")
    unit = "" if key == "ratio" else _unit_of(key)
    low, high = (_number(raw[b], unit, key, where) for b in ("min", "max"))
    if not low < high:
        raise InputError(f"{where}: {key}: the bounds are in the wrong order or equal (min = {raw['min']!r}, "
                         f"max = {raw['max']!r}): give min < max (fix a value in [parameters] instead).")
    step = _number(raw["step"], unit, key, where) if "step" in raw else None
    if step is not None and not 0 < step <= high - low:
        raise InputError(f"{where}: {key}: step = {raw['step']!r} must be > 0 and at most max - min.")
    if key in INT_VARIABLES:
        if low != int(low) or high != int(high):
            raise InputError(f"{where}: {key}: tooth counts are integers, got min = {raw['min']!r}, "
                             f"max = {raw['max']!r}.")
        return DesignVariable(key, "int", low, high)
    if key == "ratio" and low < 1:
        raise InputError(f"{where}: ratio = z2 / z1 must be at least 1 (the pinion drives), got min = {low:g}.")
    if key != "ratio":
        for bound in (low, high):  # the parameter's own allowed range (pressure angle 10-35 deg, ...)
            try:
                base.updated({key: bound}, origin=where)
            except InputError as exc:
                raise InputError(f"{where}: bound of {key}: {exc}") from None
    return DesignVariable(key, "float", low, high, step)


def design_spec(table: Mapping[str, Any], parameters: Mapping[str, Any] | None = None, params=None,
                source: str = "python") -> DesignSpec:
    """Build a :class:`DesignSpec` from the ``[design]`` table (a dict), validated whole (InputError)."""
    from memstribo.parameters import get_parameter_values

    where = f"design spec {printable(source, 200)}"
    if not isinstance(table, Mapping):
        raise InputError(f"{where}: [design] must be a table.")
    refuse_unknown_keys(table, _DESIGN_KEYS, where, "key(s) {keys} in [design]")
    base = (params if params is not None else get_parameter_values()).updated(dict(parameters or {}), origin=where)
    name = table.get("name", "design search")
    if not isinstance(name, str) or not name.strip() or len(name) > 200:
        raise InputError(f"{where}: name must be a short text (1 to 200 characters).")
    objectives = table.get("objectives", ["window"])
    if not isinstance(objectives, list) or not objectives or not all(isinstance(o, str) for o in objectives):
        raise InputError(f"{where}: objectives = {printable(repr(objectives), 60)}: give a list from "
                         f"{sorted(OBJECTIVES)}.")
    for objective in objectives:
        if objective not in OBJECTIVES:
            raise InputError(f"{where}: unknown objective '{printable(objective, 40)}'; allowed: {sorted(OBJECTIVES)}."
                             f"{did_you_mean(objective, OBJECTIVES)}")
    if len(set(objectives)) != len(objectives):
        raise InputError(f"{where}: objectives {objectives}: give each once.")
    variables_table = table.get("variables", {})
    if not isinstance(variables_table, Mapping) or not variables_table:
        raise InputError(f"{where}: no design variables: give a [design.variables] table (e.g. module = "
                         "{min = \"3 um\", max = \"5 um\"}).")
    variables = tuple(_variable(str(k), v, base, f"{where} [design.variables]") for k, v in variables_table.items())
    names = [v.name for v in variables]
    if "ratio" in names and "teeth_gear" in names:
        raise InputError(f"{where}: ratio and teeth_gear are both design variables; give one (the ratio sets z2).")
    values = dict(
        name=name, variables=variables, objectives=tuple(objectives), parameters=dict(parameters or {}),
        source=source, population=_integer(table, "population", 8, 2, 10_000, where),
        generations=_integer(table, "generations", 4, 1, 10_000, where),
        seed=_integer(table, "seed", 1, 0, 2**31 - 1, where),
        realisations=_integer(table, "realisations", 4, 1, 10_000, where))
    if table.get("steps") is not None:
        values["steps"] = _integer(table, "steps", None, 3, 100_000, where)
    for key, default in (("stiction_probability", 0.5), ("fracture_probability", 0.01)):
        value = table.get(key, default)
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not 0 < value < 1:
            raise InputError(f"{where}: {key} = {printable(repr(value), 40)}: give a probability between 0 and 1.")
        values[key] = float(value)
    for key in ("cycles", "cycles_observed"):
        if table.get(key) is not None:
            number = _number(table[key], "", key, where)
            if number <= 0:
                raise InputError(f"{where}: {key} = {table[key]!r}: give a number of cycles > 0.")
            values[key] = number
    if table.get("max_cycles") is not None:
        values["max_cycles"] = _integer(table, "max_cycles", None, 1, 10**9, where)
    values.update(_torque(table.get("torque"), where))
    values.update(_constraints(table.get("constraints", {}), names, where))
    spec = DesignSpec(**values)
    _check_feasible(spec, base, where)
    _check_budget(spec, base, where)
    return spec


def _check_budget(spec: DesignSpec, base, where: str) -> None:
    """Refuse a verdict threshold that no design can meet with the realisations asked, a coating life without
    its data, and a cycle budget that cannot finish one generation."""
    from memstribo.uncertainty.intervals import binomial_interval

    best = binomial_interval(0, spec.realisations)[1]
    if best >= spec.stiction_probability:
        need = next(n for n in range(1, 100_001) if binomial_interval(0, n)[1] < spec.stiction_probability)
        raise InputError(f"{where}: no design can meet stiction_probability = {spec.stiction_probability:g}: with "
                         f"{spec.realisations} realisation(s) the 95 % upper bound of P(stiction) is {best:.3f} even "
                         f"when none sticks; give realisations >= {need} or a larger stiction_probability.")
    if "coating_life" in spec.objectives:
        coatings = next((v.choices for v in spec.variables if v.name == "coating"), ())
        if not [c for c in coatings if c != "none"]:
            raise InputError(f"{where}: objective coating_life needs a coating variable with a coating "
                             "(coating = [\"OTS\", ...]).")
        if base["damage_coefficient"] is None and spec.cycles_observed is None:
            raise InputError(f"{where}: objective coating_life needs the damage coefficient: set the parameter "
                             "damage_coefficient in [parameters] or [design] cycles_observed.")
    if spec.max_cycles is not None and spec.max_cycles < spec.population * spec.cycles_per_design:
        raise InputError(f"{where}: max_cycles = {spec.max_cycles:,} cannot finish one generation: "
                         f"{spec.population} designs x up to {spec.cycles_per_design} meshing cycles each "
                         f"({spec.realisations} realisations x {spec.probes} verdicts) = "
                         f"{spec.population * spec.cycles_per_design:,}; raise max_cycles or lower population, "
                         "realisations or [design.torque] num.")


def _torque(raw, where) -> dict:
    if not isinstance(raw, Mapping) or set(raw) - {"min", "max", "num"} or not {"min", "max"} <= set(raw):
        raise InputError(f"{where}: give the operating torque range [design.torque] min = ..., max = ... (N*m), "
                         "optionally num = ... (default 8).")
    low, high = (_number(raw[b], "N*m", "drive_torque", where) for b in ("min", "max"))
    if not 0 < low < high:
        raise InputError(f"{where}: [design.torque]: the bounds are in the wrong order or not positive (min = "
                         f"{raw['min']!r}, max = {raw['max']!r}): give 0 < min < max.")
    num = _integer(raw, "num", 8, 2, 1000, where + " [design.torque]")
    return {"torque_min": low, "torque_max": high, "torque_num": num}


def _constraints(raw, names, where) -> dict:
    if not isinstance(raw, Mapping):
        raise InputError(f"{where}: [design.constraints] must be a table.")
    refuse_unknown_keys(raw, _CONSTRAINT_KEYS, where, "constraint(s) {keys}")
    out: dict[str, Any] = {}
    if "contact_ratio_min" in raw:
        out["contact_ratio_min"] = _number(raw["contact_ratio_min"], "", "contact_ratio_min", where)
        if not 1.0 <= out["contact_ratio_min"] < 5.0:
            raise InputError(f"{where}: contact_ratio_min = {raw['contact_ratio_min']!r}: give 1 to 5.")
    if "tooth_thickness_min" in raw:
        out["tooth_thickness_min"] = _number(raw["tooth_thickness_min"], "m", "tooth_thickness_min", where)
        if out["tooth_thickness_min"] < 0:
            raise InputError(f"{where}: tooth_thickness_min must be >= 0.")
    if "centre_distance" in raw:
        if "module" in names:
            raise InputError(f"{where}: a fixed centre_distance sets the module (m = 2 a / (z1 + z2)): remove module "
                             "from [design.variables].")
        out["centre_distance"] = _number(raw["centre_distance"], "m", "centre_distance", where)
        if out["centre_distance"] <= 0:
            raise InputError(f"{where}: centre_distance must be > 0.")
    if "ratio" in raw:
        if "ratio" in names or "teeth_gear" in names:
            raise InputError(f"{where}: a fixed ratio sets teeth_gear = round(ratio z1): remove ratio and "
                             "teeth_gear from [design.variables].")
        out["ratio"] = _number(raw["ratio"], "", "ratio", where)
        if out["ratio"] < 1:
            raise InputError(f"{where}: ratio must be at least 1 (z2 >= z1), got {out['ratio']:g}.")
    return out


def load_design_spec(path: str | Path, params=None) -> DesignSpec:
    """Read a design spec TOML file (``[design]``, optional ``[parameters]``), validated whole."""
    from memstribo.parameters import read_config

    config = read_config(path)
    if "design" not in config:
        raise InputError(f"design spec '{printable(path, 200)}' has no [design] table; see docs/design.md.")
    others = sorted(set(config) - {"design", "parameters", "meta"})
    if others:
        raise InputError(f"design spec '{printable(path, 200)}' has {others} table(s); it holds [design] and "
                         "[parameters] only.")
    return design_spec(config["design"], config.get("parameters"), params, source=str(path))


# --- designs ------------------------------------------------------------------------------------------

def decode(spec: DesignSpec, x, base) -> dict[str, Any]:
    """The design of the real vector ``x``: its variables rounded to their grids, z2 and the module derived
    where the ratio or the centre distance is fixed (the base parameters give the teeth not varied)."""
    return complete(spec, {v.name: v.value(xi) for v, xi in zip(spec.variables, x)}, base)


def complete(spec: DesignSpec, design: Mapping[str, Any], base) -> dict[str, Any]:
    """``design`` with the dependent values set: teeth_gear from a ratio, the module from a centre distance."""
    design = dict(design)
    ratio = design.pop("ratio", spec.ratio)
    if ratio is not None:
        design["teeth_gear"] = int(round(float(ratio) * int(design.get("teeth_pinion", base["teeth_pinion"]))))
    if spec.centre_distance is not None:
        z1 = int(design.get("teeth_pinion", base["teeth_pinion"]))
        z2 = int(design.get("teeth_gear", base["teeth_gear"]))
        design["module"] = 2.0 * spec.centre_distance / (z1 + z2)
    return design


def design_key(design: Mapping[str, Any]) -> str:
    """A short stable id of a design (its values at 12 significant digits)."""
    import hashlib
    import json

    text = json.dumps({k: (f"{v:.12g}" if isinstance(v, float) else v) for k, v in sorted(design.items())})
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def design_parameters(base, design: Mapping[str, Any]):
    """The base parameters with the design's values (the coating is not a parameter and stays out)."""
    return base.updated({k: v for k, v in design.items() if k != "coating"}, origin="design")


@functools.lru_cache(maxsize=4096)
def _fillet_fits(teeth: int, pressure_angle: float, addendum: float, dedendum: float, fillet: float) -> bool:
    """Whether the ISO 53 root fillet fits the tooth space (:func:`memstribo.physics.tooth_stress.tooth_shape`,
    whose form does not depend on the module: it is drawn at 1 m)."""
    from memstribo.physics.tooth_stress import tooth_shape

    try:
        tooth_shape(teeth, 1.0, pressure_angle, addendum, dedendum, fillet)
    except InputError:
        return False
    return True


def geometry_constraints(spec: DesignSpec, base, design: Mapping[str, Any], fillet: bool = True) -> np.ndarray:
    """The geometric constraints of :data:`CONSTRAINT_NAMES` of one design, each <= 0 where met (normalised).

    Undercut (z >= 2 h_a / sin^2 phi), interference (the path of contact within the base-circle tangency
    points), pointed tip (s_a > 0, ISO 21771), contact ratio and minimum tip thickness, the module's range, and
    (``fillet``, for designs that meet the others) the root fillet that the fracture edge's tooth form needs.
    Computed from :mod:`memstribo.physics.gear`'s relations, without a meshing cycle.
    """
    from memstribo.parameters import SPECS
    from memstribo.physics.gear import minimum_teeth_without_undercut, tip_tooth_thickness

    get = {k: design.get(k, base[k]) for k in ("teeth_pinion", "teeth_gear", "module", "pressure_angle",
                                                "addendum_coefficient")}
    z1, z2, m, phi, ha = (int(get["teeth_pinion"]), int(get["teeth_gear"]), float(get["module"]),
                          float(get["pressure_angle"]), float(get["addendum_coefficient"]))
    z_min = minimum_teeth_without_undercut(phi, ha)
    g = np.full(len(CONSTRAINT_NAMES), -1.0)
    g[0], g[1] = (z_min - z1) / z_min, (z_min - z2) / z_min
    rb = np.array([z1, z2]) * m * math.cos(phi) / 2.0
    ra = np.array([z1, z2]) * m / 2.0 + ha * m
    thickness = np.array([tip_tooth_thickness(z, m, phi, ha) for z in (z1, z2)])
    if np.any(ra <= rb) or not np.all(np.isfinite(thickness)):
        g[2:6] = 1.0
    else:
        first = rb[1] * math.tan(phi) - math.sqrt(ra[1] ** 2 - rb[1] ** 2)
        last = math.sqrt(ra[0] ** 2 - rb[0] ** 2) - rb[0] * math.tan(phi)
        tangency = rb * math.tan(phi)
        g[2] = max(-first - tangency[0], last - tangency[1]) / m
        g[3] = (1e-9 * m - thickness.min()) / m
        ratio = (last - first) / (math.pi * m * math.cos(phi))
        g[4] = spec.contact_ratio_min - ratio
        g[5] = (spec.tooth_thickness_min - thickness.min()) / m
    low, high = SPECS["module"].minimum, SPECS["module"].maximum
    g[6] = max((low or 0.0) - m, m - (high if high is not None else math.inf)) / m
    if z1 > z2:
        g[0] = max(g[0], 1.0)  # the pinion is the smaller gear
    if fillet and np.all(g[:7] <= 0):  # ~10 ms a tooth count: only for designs that pass the rest
        fits = all(_fillet_fits(z, round(phi, 12), ha, float(base["dedendum_coefficient"]),
                                float(base["root_fillet_coefficient"])) for z in (z1, z2))
        g[7] = -1.0 if fits else 1.0
    return g


def _check_feasible(spec: DesignSpec, base, where: str) -> None:
    """Refuse a spec whose box holds no design meeting every geometric constraint (sampled), naming the
    constraint that no sample met, or else the share of samples each constraint refused."""
    rng = np.random.default_rng(12345)
    lows = np.array([v.bounds[0] for v in spec.variables])
    highs = np.array([v.bounds[1] for v in spec.variables])
    corners = [np.where(np.array(bits) == 1, highs, lows) for bits in
               np.ndindex(*(2,) * len(spec.variables))] if len(spec.variables) <= 8 else []
    samples = list(corners) + list(rng.uniform(lows, highs, size=(FEASIBILITY_SAMPLES, len(spec.variables))))
    met = np.zeros(len(CONSTRAINT_NAMES), dtype=bool)
    fails = np.zeros(len(CONSTRAINT_NAMES), dtype=int)
    for x in samples:
        g = geometry_constraints(spec, base, decode(spec, x, base), fillet=False)  # the fillet: ~10 ms a design
        if np.all(g <= 0):
            return
        met |= g <= 0
        fails += g > 0
    never = [CONSTRAINT_NAMES[i] for i in np.flatnonzero(~met)]
    if never:
        raise InputError(f"{where}: no design within the bounds meets {never} ({len(samples)} designs sampled "
                         "from the box): widen the bounds or relax that constraint (or those).")
    shares = ", ".join(f"{CONSTRAINT_NAMES[i]}: {fails[i] / len(samples):.0%}" for i in np.flatnonzero(fails))
    raise InputError(f"{where}: no design within the bounds meets all constraints together ({len(samples)} "
                     f"sampled; share refused by each: {shares}): widen the bounds or relax a constraint.")
