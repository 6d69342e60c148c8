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

from memstribo.errors import InputError, did_you_mean
from memstribo.units import printable, to_si
from memstribo.parameters.definitions import MEMORY_LIMIT_BYTES, RUN_DEFAULT_COATING, RUN_DEFAULT_WEAR, RUN_KEYS, SPECS, ParameterSpec

__all__ = [
    "SPECS",
    "ParameterSpec",
    "Parameters",
    "available_parameter_sets",
    "get_parameter_values",
    "parameter_set_file",
    "parse_assignment",
    "read_config",
    "coerce_value",
    "THESIS_CONDITIONS",
    "THESIS_FLAGS",
    "THESIS_VDW",
    "THESIS_VDW_FLAGS",
]

DEFAULT_SET = "silicon_thesis"

#: The thesis's own conditions, for the reproduction rows and examples (docs/validation.md "[thesis case]"):
#: its load case (F_ext = 25 uN), its full-energy vdW band, no adhesion inside the contact solve
#: (the thesis counts adhesion as the sum of block pull-off forces, 3-31), and its van der Waals constants
#: (U_vdW = U_chem / 100 and A = 1.1e-18 J, 3.5). memstribo's defaults are MODEL 7b, 7c and 7h: the torque's
#: load, vdW at the actual gap, the Maugis-Dugdale zone in the solve, one vdW interaction with the Lifshitz A.
THESIS_CONDITIONS = {"load_case": "thesis", "interface_model": "thesis", "contact_adhesion": "none",
                     "vdw_energy_rule": "thesis", "hamaker_constant": 1.1e-18}
#: The thesis's van der Waals constants alone (3.5), for the rows that reproduce its nanoscale numbers:
#: U_vdW = U_chem / 100 as given and its Hamaker constant 1.1e-18 J (memstribo's default is the Lifshitz value)
THESIS_VDW = {"vdw_energy_rule": "thesis", "hamaker_constant": 1.1e-18}
#: :data:`THESIS_VDW` as command-line options
THESIS_VDW_FLAGS = "--set vdw_energy_rule=thesis --set hamaker_constant=1.1e-18"
#: :data:`THESIS_CONDITIONS` as command-line options
THESIS_FLAGS = ("--load-case thesis --set interface_model=thesis --set contact_adhesion=none "
                "--set vdw_energy_rule=thesis --set hamaker_constant=1.1e-18")


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
        raise InputError(f"unknown parameter '{printable(name)}'.{did_you_mean(name, SPECS)} "
                         f"Run 'memstribo parameters' to list them.")
    if spec.optional and isinstance(value, str) and value.strip().lower() in ("unset", "none"):
        value = None  # '--set hardness=unset' from the command line: derive it, or switch it off
    if value is None:
        if spec.optional:
            return None
        raise InputError(f"parameter '{name}' needs a value: {spec.allowed()}.")
    shown = printable(repr(value))
    if isinstance(value, (dict, list, tuple)):
        raise InputError(f"parameter '{name}' = {shown}: expected one value, not a "
                         f"{'table' if isinstance(value, dict) else 'list'}: {spec.allowed()}.")
    if spec.kind == "str":
        if not isinstance(value, str):
            raise InputError(f"parameter '{name}' = {shown}: expected a string, {spec.allowed()}.")
        if spec.choices and value not in spec.choices:
            raise InputError(f"parameter '{name}' = {shown} is not allowed: {spec.allowed()}."
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
        raise InputError(f"parameter '{name}' = {shown}: expected true or false.")
    number = to_si(value, spec.unit, name)
    if spec.kind == "int":
        if not float(number).is_integer():
            raise InputError(f"parameter '{name}' = {shown} must be an integer: {spec.allowed()}.")
        number = int(number)
    if not _in_range(number, spec):
        why = f"; {spec.why}" if spec.why else ""
        raise InputError(f"parameter '{name}' = {shown} is outside its range: {spec.allowed()}{why}.")
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


#: bytes the meshing simulation holds per step and contact element (calibrated: 100 000 steps of the
#: default 600-element window took 6.4 GB, i.e. 13.3 bytes x 8 per element and step)
MESH_BYTES_PER_ELEMENT_STEP = 8 * 14

#: largest number of points of a profile or of contact elements in one solve
MAX_POINTS = 10_000_000
MAX_CONTACT_ELEMENTS = 1_000_000


def mesh_memory_bytes(steps: int, window: float, grid_spacing: float) -> float:
    """Estimated memory [bytes] of a meshing simulation of ``steps`` steps (see MESH_BYTES_PER_ELEMENT_STEP)."""
    return float(steps) * (window / grid_spacing) * MESH_BYTES_PER_ELEMENT_STEP


def check_mesh_size(steps: int, window: float, grid_spacing: float, what: str = "mesh_steps") -> None:
    """Refuse a meshing simulation whose arrays would not fit in memory (before anything is allocated).

    Raises
    ------
    InputError
        More than :data:`MAX_CONTACT_ELEMENTS` elements per solve, or an estimated memory above
        :data:`MEMORY_LIMIT_BYTES` (what a 24 GB machine holds besides the interpreter).

    A window or grid spacing of ``None`` (sized from the load case) is checked by the meshing
    cycle once it has sized them (``memstribo.simulations.mesh``), with this same function.
    """
    if window is None or grid_spacing is None:
        return
    elements = window / grid_spacing
    if elements > MAX_CONTACT_ELEMENTS:
        raise InputError(f"mesh_window / mesh_grid_spacing = {elements:.3g} contact elements per step; at most "
                         f"{MAX_CONTACT_ELEMENTS:,} (raise mesh_grid_spacing or shorten mesh_window).")
    need = mesh_memory_bytes(steps, window, grid_spacing)
    if need > MEMORY_LIMIT_BYTES:
        raise InputError(f"{what} = {steps} with {elements:.0f} contact elements per step needs about "
                         f"{need / 2**30:.0f} GiB of memory, more than the {MEMORY_LIMIT_BYTES / 2**30:.0f} GiB "
                         "memstribo plans for; use fewer steps or a coarser mesh_grid_spacing.")


def check_points(length: float, step: float, what: str) -> int:
    """Number of points of a profile ``length`` long sampled at ``step``; refuse more than MAX_POINTS."""
    n = length / step
    if not n < MAX_POINTS:
        raise InputError(f"{what}: a {length:.4g} m profile at a {step:.4g} m step has {n:.3g} points; at most "
                         f"{MAX_POINTS:,} (the arrays would not fit in memory): use a larger step.")
    return int(n)


def _check_consistency(values: Mapping[str, Any]) -> None:
    """Cross-parameter rules that a single range cannot express (and the memory sizes set)."""
    if all(values.get(k) for k in ("mesh_steps", "mesh_window", "mesh_grid_spacing")):
        check_mesh_size(values["mesh_steps"], values["mesh_window"], values["mesh_grid_spacing"])
    if values.get("roughness_length"):
        for key in ("roughness_sample_spacing", "roughness_resample_spacing"):
            if values.get(key):
                check_points(values["roughness_length"], values[key], f"roughness_length / {key}")
    if values.get("atomic_height") and values.get("adhesive_height"):
        if values["atomic_height"] > values["adhesive_height"]:
            raise InputError(
                f"atomic_height ({values['atomic_height']:.4g} m) is larger than adhesive_height "
                f"({values['adhesive_height']:.4g} m): atomic blocks are the top layer of an adhesive block.")
    gap, block = values.get("sliding_gap"), values.get("adhesive_height")
    if gap is not None and block and gap < -block:
        raise InputError(
            f"sliding_gap = {gap:.4g} m is an interference deeper than the nanoblock (adhesive_height "
            f"{block:.4g} m): it would crush the block; allowed: sliding_gap >= -adhesive_height.")
    if values.get("hardness") and values.get("ideal_shear_strength"):
        bound = 6.0 * values["ideal_shear_strength"]  # Tabor H = 3 Y, Tresca Y = 2 tau (MODEL 7d)
        if values["hardness"] > bound:
            raise InputError(
                f"hardness ({values['hardness'] / 1e9:.4g} GPa) is above what the ideal shear strength allows "
                f"(6 x ideal_shear_strength = {bound / 1e9:.4g} GPa: Tabor's H = 3 Y with Tresca's Y = 2 tau): no "
                "solid is harder than its ideal strength; use a hardness at most that, or unset it for no cap.")
    if values.get("atomic_width") and values.get("adhesive_width"):
        if values["atomic_width"] > values["adhesive_width"]:
            raise InputError(
                f"atomic_width ({values['atomic_width']:.4g} m) is larger than adhesive_width "
                f"({values['adhesive_width']:.4g} m): atomic blocks sit on top of an adhesive block.")
    _check_derived(values)


#: the largest contact modulus E* two real solids can make [Pa]: diamond (E = 1.14 TPa, nu = 0.07) against a
#: rigid body, E / (1 - nu^2) = 1.15 TPa, rounded up (issue #41: nu = -0.999 on both bodies gave E* = 40 TPa)
MAX_CONTACT_MODULUS = 1.2e12


def _check_derived(values: Mapping[str, Any]) -> None:
    """Derived quantities against their bounds and lengths against each other (issue #41, round four)."""
    a, d0 = values.get("hamaker_constant"), values.get("cutoff_distance")
    if values.get("work_of_adhesion") is None and a and d0:
        w = a / (12.0 * math.pi * d0**2)  # (3-34), as memstribo.materials.pair.work_of_adhesion
        bound = SPECS["work_of_adhesion"].maximum
        if w > bound:
            raise InputError(
                f"work_of_adhesion derived from hamaker_constant ({a:.4g} J) and cutoff_distance ({d0:.4g} m), "
                f"A / (12 pi D0^2) = {w:.4g} J/m^2, is above its own bound of {bound:g} J/m^2 (surface energies of "
                "solids are below 5 J/m^2): use a smaller hamaker_constant or a larger cutoff_distance, or give "
                "work_of_adhesion.")
    e1, nu1 = values.get("youngs_modulus"), values.get("poisson_ratio")
    if e1 and nu1 is not None:
        e2 = values.get("counter_youngs_modulus") or e1
        nu2 = nu1 if values.get("counter_poisson_ratio") is None else values["counter_poisson_ratio"]
        compliance = (1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2
        modulus = math.inf if compliance <= 0 else 1.0 / compliance
        if modulus > MAX_CONTACT_MODULUS:
            raise InputError(
                f"contact modulus E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2) = {modulus / 1e12:.3g} TPa with "
                f"poisson_ratio {nu1:g} and counter_poisson_ratio {nu2:g} (E1 {e1 / 1e9:.4g} GPa, E2 "
                f"{e2 / 1e9:.4g} GPa) is above {MAX_CONTACT_MODULUS / 1e12:g} TPa, the stiffest contact of real "
                "solids (diamond against a rigid body): near nu = -1 the plane-strain modulus E / (1 - nu^2) "
                "diverges; use Poisson's ratios further from -1.")
    bond = values.get("bond_length")
    for other in ("lattice_constant", "atomic_pitch"):
        if bond and values.get(other) and bond > values[other]:
            raise InputError(
                f"bond_length ({bond:.4g} m) is longer than {other} ({values[other]:.4g} m): a chemical bond joins "
                f"nearest neighbours, which are no further apart than the {other.replace('_', ' ')}; allowed: "
                f"bond_length <= {other}.")
    h_a, h_f = values.get("addendum_coefficient"), values.get("dedendum_coefficient")
    if h_a and h_f and h_f <= h_a:
        raise InputError(
            f"dedendum_coefficient ({h_f:g} x module) is not deeper than the mating addendum_coefficient ({h_a:g} x "
            "module): "
            "the mating tooth's tip would reach the root circle with no tip clearance (ISO 53: 0.25 m); allowed: "
            "dedendum_coefficient > addendum_coefficient.")


def get_parameter_values(name: str = DEFAULT_SET) -> Parameters:
    """Load a parameter set shipped with memstribo (default: the thesis's silicon case).

    Raises
    ------
    InputError
        If ``name`` is not a known set; the message lists the available ones.
    """
    available = available_parameter_sets()
    if name not in available and str(name).lower().endswith(".toml"):  # a set file ('memstribo calibrate' writes one)
        return parameter_set_file(name)
    if name not in available:
        raise InputError(f"unknown parameter set '{name}'.{did_you_mean(name, available)} "
                         f"Available: {', '.join(available)}.")
    text = (resources.files(__package__) / "sets" / f"{name}.toml").read_text(encoding="utf-8")
    data = tomllib.loads(text)
    values, sources = {}, {}
    base = data.get("meta", {}).get("base")
    if base:  # a set may change a few values of another and name it as its base
        if base == name:
            raise InputError(f"parameter set '{name}' names itself as its base.")
        parent = get_parameter_values(base)
        values = {key: parent[key] for key in parent}
        sources = {key: parent.source(key) for key in parent}
    for key, entry in data.get("parameters", {}).items():
        values[key] = coerce_value(key, entry.get("value"))
        sources[key] = entry.get("source", "")
    missing = sorted(set(SPECS) - set(values))
    if missing:
        raise InputError(f"parameter set '{name}' lacks {', '.join(missing)}")
    return Parameters(values, sources, name)



def _set_file_table(path):
    path = Path(path)
    if not path.is_file():
        raise InputError(f"parameter set file '{path}' does not exist; give a shipped set's name or a set file "
                         "written by 'memstribo calibrate'.")
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise InputError(f"parameter set file '{path}': not valid TOML ({error}).") from None


def parameter_set_file(path, _seen=()) -> "Parameters":
    """The :class:`Parameters` of a set file (``--parameter-set FILE.toml``, issue 37: the set 'memstribo calibrate'
    writes): its ``[meta] base`` (a shipped set or another set file) with its ``[parameters.NAME]`` values applied;
    other tables (``[posterior.NAME]``) are ignored here.

    The set keeps its base's name (so that the base's priors apply to every constant the file does not change);
    each value the file gives names the file in its source.
    """
    path = str(path)
    if path in _seen:
        raise InputError(f"parameter set file '{path}' names itself as its base (through {', '.join(_seen)}).")
    data = _set_file_table(path)
    base = data.get("meta", {}).get("base")
    if not base:
        raise InputError(f"parameter set file '{path}': [meta] base is missing (the shipped set it changes, e.g. "
                         "'silicon_oxide_air').")
    nested = str(base).lower().endswith(".toml")
    parent = parameter_set_file(base, (*_seen, path)) if nested else get_parameter_values(base)
    values = {k: parent[k] for k in parent}
    sources = {k: parent.source(k) for k in parent}
    for key, entry in data.get("parameters", {}).items():
        if key not in SPECS:
            raise InputError(f"parameter set file '{path}': unknown parameter '{key}'.{did_you_mean(key, SPECS)}")
        if not isinstance(entry, dict) or "value" not in entry:
            raise InputError(f"parameter set file '{path}': [parameters.{key}] needs a value (with unit and source).")
        values[key] = coerce_value(key, entry["value"])
        sources[key] = f"{entry.get('source', '')} (set file {path})".strip()
    return Parameters(values, sources, parent.name)


#: tables a config file may hold besides [parameters] and [meta], and who reads them
CONFIG_TABLES = {
    "meta": "name and description of the file (ignored)",
    "parameters": "parameter overrides",
    "run": "options of 'memstribo run'",
    "study": "a study for 'memstribo study'",
    "map": "a design map for 'memstribo map'",
    "design": "a design search for 'memstribo design'",
}

#: keys of a table-form parameter (``[parameters.normal_load]``), as written by Parameters.to_toml
_ENTRY_KEYS = ("value", "unit", "source")


def _toml_type(value) -> str:
    return {dict: "table", list: "list", str: "string", bool: "boolean", int: "integer",
            float: "number"}.get(type(value), type(value).__name__)


def _entry_value(path, name: str, entry: dict):
    """The value of a table-form parameter ``[parameters.NAME]``, with its ``unit`` applied."""
    unknown = [k for k in entry if k not in _ENTRY_KEYS]
    if unknown:
        raise InputError(f"config file '{path}': [parameters.{name}] has unknown key '{printable(unknown[0])}'; "
                         f"allowed: {', '.join(_ENTRY_KEYS)}.{did_you_mean(unknown[0], _ENTRY_KEYS)}")
    spec = SPECS[name]
    if "value" not in entry:
        if spec.optional:
            return None  # written by to_toml for an unset (derived) value
        raise InputError(f"config file '{path}': [parameters.{name}] has no 'value' (it is not optional): "
                         f"{spec.allowed()}.")
    value, unit = entry["value"], entry.get("unit")
    if unit is not None and not isinstance(unit, str):
        raise InputError(f"config file '{path}': [parameters.{name}] unit must be a string, got {_toml_type(unit)}.")
    if unit and spec.kind in ("float", "int") and isinstance(value, (int, float)) and not isinstance(value, bool):
        if unit.replace(" ", "") != spec.unit.replace(" ", ""):
            value = f"{value!r} {unit}"  # a number in the unit the entry names, converted to SI by coerce_value
    elif unit and spec.kind in ("float", "int") and isinstance(value, str) and unit != spec.unit:
        raise InputError(f"config file '{path}': [parameters.{name}] gives both a unit ('{printable(unit)}') and a "
                         "value string; give a number with 'unit', or the unit inside the value ('25 uN').")
    return value


def _twice_in_config(shown: str, name: str) -> str:
    """The message for a parameter given both at the top level and in [parameters] of one file (issue #41)."""
    return (f"config file '{shown}': parameter '{name}' is given twice, at the top level and in [parameters]; "
            "one of the two values would be dropped without a word: give it once (either place).")


def read_config(path: str | Path) -> dict[str, Any]:
    """Read parameter overrides from a TOML file, validated whole.

    The file may hold the overrides at top level (``normal_load = "50 uN"``), in a
    ``[parameters]`` table, or in the format written by :meth:`Parameters.to_toml`
    (``[parameters.normal_load]`` with ``value``, ``unit``, ``source``; a ``unit`` other than
    SI converts a plain-number value). The tables of :data:`CONFIG_TABLES` (``[run]``,
    ``[study]``) are returned under their own keys for the commands that use them.

    Returns
    -------
    dict
        ``{"parameters": {name: value}, **other_tables}``.

    Raises
    ------
    InputError
        Missing or unreadable file, TOML syntax error (with line and column), an unknown
        table or key (with a did-you-mean), a value of the wrong type.
    """
    path = Path(path)
    shown = printable(path, 200)
    if path.exists() and not path.is_dir() and not path.is_file():  # /dev/zero, a pipe: reading would never end
        raise InputError(f"config file '{shown}' is not a regular file (a device, pipe or socket); give a TOML file.")
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise InputError(f"config file '{shown}' does not exist.") from None
    except IsADirectoryError:
        raise InputError(f"config file '{shown}' is a folder; give a TOML file.") from None
    except OSError as exc:
        raise InputError(f"cannot read config file '{shown}': {exc.strerror}.") from None
    if raw.startswith(b"\xef\xbb\xbf"):
        raw = raw[3:]
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"config file '{shown}' is not UTF-8 text (byte {exc.start}); TOML files are UTF-8.") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"config file '{shown}' is not valid TOML: {printable(exc, 200)}.") from None
    overrides: dict[str, Any] = {}
    other: dict[str, Any] = {}
    allowed_tables = sorted(CONFIG_TABLES)
    for key, value in data.items():
        if key == "parameters":
            if not isinstance(value, dict):
                raise InputError(f"config file '{shown}': 'parameters' must be a table ([parameters]), "
                                 f"got a {_toml_type(value)}.")
            for name, entry in value.items():
                if name not in SPECS:
                    raise InputError(f"config file '{shown}': unknown parameter '{printable(name)}' in [parameters]."
                                     f"{did_you_mean(name, SPECS)} Run 'memstribo parameters' to list them.")
                if name in overrides:
                    raise InputError(_twice_in_config(shown, name))
                overrides[name] = _entry_value(shown, name, entry) if isinstance(entry, dict) else entry
        elif key in CONFIG_TABLES:
            if not isinstance(value, dict):
                raise InputError(f"config file '{shown}': '{key}' must be a table ([{key}]), got a {_toml_type(value)}.")
            if key != "meta":
                other[key] = value
        elif isinstance(value, dict):
            hint = did_you_mean(key, allowed_tables) or (
                f" Parameter tables go under [parameters.{key}]." if key in SPECS else "")
            raise InputError(f"config file '{shown}': unknown table [{printable(key)}]; allowed tables: "
                             f"{', '.join(f'[{t}]' for t in allowed_tables)}.{hint}")
        elif key in SPECS:
            if key in overrides:
                raise InputError(_twice_in_config(shown, key))
            overrides[key] = value
        else:
            raise InputError(f"config file '{shown}': unknown parameter '{printable(key)}'."
                             f"{did_you_mean(key, list(SPECS) + allowed_tables)} Run 'memstribo parameters' to list "
                             "them.")
    if "run" in other:
        _RUN_KEYS = RUN_KEYS  # the keys of [run]; values are checked by 'memstribo run'

        for key in other["run"]:
            if key not in _RUN_KEYS:
                raise InputError(f"config file '{shown}': [run] has unknown key '{printable(key)}'; allowed: "
                                 f"{', '.join(_RUN_KEYS)}.{did_you_mean(key, _RUN_KEYS)}")
    for name, value in overrides.items():  # every value checked now, whatever command reads the file
        try:
            coerce_value(name, value)
        except InputError as exc:
            raise InputError(f"config file '{shown}': {exc}") from None
    return {"parameters": overrides, **other}


def parse_assignment(text: str) -> tuple[str, str]:
    """Split ``"NAME=VALUE"`` from ``--set``; raise :class:`InputError` if malformed."""
    name, sep, value = text.partition("=")
    name, value = name.strip(), value.strip()
    if not sep or not name or not value:
        raise InputError(f"--set expects NAME=VALUE (e.g. --set normal_load='50 uN'), got '{printable(text)}'.")
    if name not in SPECS:
        raise InputError(f"--set: unknown parameter '{printable(name)}'.{did_you_mean(name, SPECS)} "
                         f"Run 'memstribo parameters' to list them.")
    return name, value
