"""The materials of a laboratory row as data, and the parameters of its case (issue 37 item 3, MODEL 7e).

:func:`material_table` reads ``materials.toml`` (silicon nitride, silica; polysilicon and silicon are the parameter
set's own values). :func:`row_parameters` builds the parameters of one row's case: the base set (the user's
``--parameter-set`` / ``--set``, else silicon_oxide_air in air and silicon_thesis otherwise), the sampled constants,
the row's environment and humidity, its material pair and its coating (any coating the package ships: OTS, FDTS,
DDMS, W). :func:`material_priors` gives each material constant's prior (:class:`memstribo.uncertainty.priors.Prior`).
"""

from __future__ import annotations

import functools
import math
import tomllib
from importlib import resources

from memstribo.errors import InputError, did_you_mean
from memstribo.references import cites

__all__ = ["MATERIALS", "material_table", "material_priors", "row_parameters", "pair_overrides",
           "COATED_BOND_ENERGY"]

#: the materials a row may name (polysilicon and silicon: the parameter set's own constants)
MATERIALS = ("polysilicon", "silicon", "silica", "silicon_nitride")
#: chemical bond energy of a coated surface [J]: no chemical bonds (thesis 5.4), the spec's floor 1e-21 J
COATED_BOND_ENERGY = 1e-21
#: the material constants a material entry may give (parameter names of the body)
PROPERTIES = ("youngs_modulus", "poisson_ratio", "hardness", "hamaker_constant", "bond_energy", "water_contact_angle")


@functools.lru_cache(maxsize=1)
def material_table() -> dict:
    """``{material: {property: {value, unit, source, prior}}}`` of ``materials.toml`` (no entry: the set's own)."""
    text = (resources.files(__package__) / "materials.toml").read_text(encoding="utf-8")
    table = tomllib.loads(text)["materials"]
    out = {}
    for name, entry in table.items():
        out[name] = {k: v for k, v in entry.items() if isinstance(v, dict)}
        unknown = set(out[name]) - set(PROPERTIES)
        if unknown:
            raise InputError(f"materials.toml: {name} gives {', '.join(sorted(unknown))}; allowed: {', '.join(PROPERTIES)}.")
    return out


def _check_material(name, field):
    if name not in MATERIALS:
        raise InputError(f"{field} {name!r} is not a material memstribo knows.{did_you_mean(str(name), MATERIALS)} "
                         f"Allowed: {', '.join(MATERIALS)}.")
    return material_table().get(name, {})


def material_priors(name) -> dict:
    """The priors of material ``name``'s constants, ``{property: Prior}`` (empty for polysilicon and silicon)."""
    from memstribo.uncertainty.priors import Prior

    out = {}
    for prop, entry in _check_material(name, "material").items():
        prior = entry["prior"]
        out[prop] = Prior(name=prop, **{k: prior[k] for k in ("distribution", "low", "high", "source", "reason")
                                        if k in prior})
    return out


@cites("israelachvili_2011", "vlassak_nix_1992", "bergstrom_1997")
def pair_overrides(params, material="polysilicon", counter_material="polysilicon") -> dict:
    """Parameter overrides of a material pair: the body's and the counter's E and nu, the pair's Hamaker constant
    sqrt(A11 A22) (combining rule, Israelachvili 2011 ch. 13), the softer body's hardness, the bond energy and
    water contact angle of the material that sets the surface chemistry (a nitride or oxide surface, else the
    set's). Empty for a polysilicon or silicon pair."""
    body, counter = _check_material(material, "material"), _check_material(counter_material, "counter_material")
    if not body and not counter:
        return {}

    def value(entry, prop):
        return float(entry[prop]["value"]) if prop in entry else float(params[prop])

    out = {"youngs_modulus": value(body, "youngs_modulus"), "poisson_ratio": value(body, "poisson_ratio"),
           "counter_youngs_modulus": value(counter, "youngs_modulus"),
           "counter_poisson_ratio": value(counter, "poisson_ratio"),
           "hamaker_constant": math.sqrt(value(body, "hamaker_constant") * value(counter, "hamaker_constant")),
           "hardness": min(value(body, "hardness"), value(counter, "hardness"))}
    chemistry = body if "bond_energy" in body else counter
    for prop in ("bond_energy", "water_contact_angle"):
        if prop in chemistry:
            out[prop] = float(chemistry[prop]["value"])
    if params["work_of_adhesion"] is not None:
        out["work_of_adhesion"] = None  # derived again from the pair's Hamaker constant (3-34)
    return out


def _coating_overrides(params, coating_name) -> dict:
    from memstribo.physics.coating import get_coating

    coating = get_coating(coating_name, params)
    out = {"bond_energy": COATED_BOND_ENERGY, "vdw_bond_energy": coating.vdw_bond_energy,
           "hamaker_constant": coating.hamaker_constant, "cutoff_distance": coating.cutoff_distance,
           "work_of_adhesion": coating.work_of_adhesion}
    if math.isfinite(coating.water_contact_angle_deg):
        out["water_contact_angle"] = math.radians(coating.water_contact_angle_deg)
    return out


def _base(row, base):
    from memstribo.parameters import get_parameter_values

    if base is not None:
        return base, base.name
    name = "silicon_oxide_air" if row.environment == "air" else "silicon_thesis"
    return get_parameter_values(name), name


def row_parameters(row, base=None, sample=None, calibration_coating="OTS"):
    """The parameters of one row's case: ``(Parameters, set name)``.

    Parameters
    ----------
    row : memstribo.laboratory.data.Measurement
    base : memstribo.parameters.Parameters, optional
        The user's parameter set with their ``--set`` values; default silicon_oxide_air in air, silicon_thesis
        otherwise.
    sample : dict, optional
        Sampled constants (``coating_*`` keys stand for ``calibration_coating`` and apply only to its rows).
    """
    from memstribo.parameters.definitions import SPECS

    params, name = _base(row, base)
    overrides = {}
    environment = row.environment if row.environment in ("vacuum", "air") else "vacuum"  # dry nitrogen: no water
    if params["environment"] != environment:
        overrides["environment"] = environment
    rh = row.number("relative_humidity")
    overrides["relative_humidity"] = rh if environment == "air" and rh is not None else 0.0
    temperature = row.number("temperature")
    if temperature is not None:
        overrides["ambient_temperature"] = temperature  # the Kelvin radius and water's surface tension at it
    for key in ("vapour", "surface_termination", "vapour_pressure_ratio"):  # the condensate of MODEL 7g
        if row.condition(key) is not None and environment == "air":
            overrides[key] = row.condition(key)
    coated = {}
    for key, value in (sample or {}).items():
        if key.startswith("coating_"):
            if row.coating and row.coating.upper() == str(calibration_coating).upper():
                coated[key.removeprefix("coating_")] = value
            continue
        if key not in SPECS:
            raise InputError(f"constant sample names {key!r}, which is not a parameter; see 'memstribo parameters'.")
        overrides[key] = value
    overrides.update(pair_overrides(params, row.condition("material", "polysilicon"),
                                    row.condition("counter_material", "polysilicon")))
    if row.coating:
        overrides.update(_coating_overrides(params, row.coating))
        overrides.update(coated)
    return params.updated(overrides, origin=f"laboratory case of row {row.id}"), name
