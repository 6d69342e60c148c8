"""``memstribo parameters``: list the model parameters, their values, units and sources."""

from __future__ import annotations

from memstribo.cli.common import CommandResult, format_quantity

NAME = "parameters"
HELP = "list the model parameters with their values, units and sources"
ORDER = 90


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP)
    parser.add_argument("--toml", action="store_true", help="print the parameters as TOML (a valid --config file)")
    parser.add_argument("--coating", metavar="NAME",
                        help="list a coating's parameter set instead (OTS, FDTS, DDMS, W), with the values that --set "
                             "coating_<property>=... or a config file replace")
    parser.set_defaults(handler=run)


def run(args, params):
    from memstribo.errors import InputError
    from memstribo.parameters import SPECS

    if args.toml and args.json:
        raise InputError("--toml and --json contradict each other: --toml prints the parameters as TOML (a --config "
                         "file), --json as one JSON object; give one of them.")
    if args.coating:
        return _coating(args, params)
    if args.toml:
        print(params.to_toml(), end="")
        return None
    if args.json:
        # the values by name (SI) as before, and under "parameters" each with its unit, bounds, source and prior
        values = {**params.to_dict(), "parameters": {name: _entry(SPECS[name], params, name) for name in params}}
        _add_priors(values["parameters"], params)
        return CommandResult(values=values, units={n: SPECS[n].unit for n in params})
    from memstribo.uncertainty.priors import priors_for, set_priors

    from memstribo.uncertainty.priors import unused_by_rule

    free, unused = priors_for(params), unused_by_rule(params)
    priors = {**set_priors(params.name if params.name in _sets() else "silicon_thesis"), **free}
    lines = []
    for name in params:
        spec, value = SPECS[name], params[name]
        shown = "unset (derived)" if value is None else format_quantity(value, spec.unit)
        lines.append(f"  {name:<28} {shown:<16} {spec.description}")
        if spec.kind in ("float", "int"):
            lines.append(f"  {'':<28} allowed: {spec.allowed()}" + (f"; {spec.why}" if spec.why else ""))
        lines.append(f"  {'':<28} source: {params.source(name)}")
        if name in priors:
            prior = priors[name]
            state = ("sampled by --uncertainty" if name in free else
                     f"not sampled: vdw_energy_rule '{params['vdw_energy_rule']}' does not use it" if name in unused
                     else "fixed (its value was given)")
            lines.append(f"  {'':<28} prior: {prior.describe()} ({state}); {prior.source}; width: {prior.reason}")
    return CommandResult(values={}, title=f"parameter set '{params.name}'", notes=lines)


def _entry(spec, params, name) -> dict:
    """One parameter for ``parameters --json``: value [SI], unit, kind, bounds, allowed text, why, source."""
    entry = {"value": params[name], "unit": spec.unit, "kind": spec.kind, "description": spec.description,
             "source": params.source(name)}
    if spec.kind in ("float", "int"):
        entry.update(minimum=spec.minimum, maximum=spec.maximum, exclusive_minimum=spec.exclusive_minimum,
                     exclusive_maximum=spec.exclusive_maximum)
    if spec.choices:
        entry["choices"] = list(spec.choices)
    entry.update(optional=spec.optional, allowed=spec.allowed(), why=spec.why)
    return entry


def _add_priors(entries, params) -> None:
    """Each sampled constant's prior (distribution, bounds, source, why its width) under its entry's ``prior``."""
    from memstribo.uncertainty.priors import priors_for

    for name, prior in priors_for(params).items():
        if name in entries:
            entries[name]["prior"] = {"distribution": prior.distribution, "low": prior.low, "high": prior.high,
                                      "source": prior.source, "reason": prior.reason}


def _sets():
    from memstribo.parameters import available_parameter_sets

    return available_parameter_sets()


def _coating(args, params):
    """The coating's parameter set, each value with its unit and source (overrides applied)."""
    from memstribo.physics.coating import _UNITS, coating_config, get_coating

    coating = get_coating(args.coating, params)
    names = ("vdw_bond_energy", "hamaker_constant", "cutoff_distance", "work_of_adhesion", "water_contact_angle_deg",
             "degradation_temperature")
    notes = {"water_contact_angle_deg": "(informative)", "degradation_temperature": "(a contact temperature past it "
             "is a warning)"}
    if args.toml:
        print(coating_config(coating, "as listed by 'memstribo parameters --coating'"), end="")
        return None
    values = {"coating": coating.name, **{name: getattr(coating, name) for name in names},
              "sources": {name: coating.sources.get(name, "") for name in names}}
    if args.json:
        return CommandResult(values=values, units={name: _UNITS[name] for name in names})
    from memstribo.uncertainty.priors import coating_priors

    priors = coating_priors(coating)
    lines = []
    for name in names:
        unit = _UNITS[name]
        lines.append(f"  {name:<24} {format_quantity(getattr(coating, name), unit):<16} "
                     + notes.get(name, "(--set coating_" + name + "=...)"))
        lines.append(f"  {'':<24} source: {coating.sources.get(name, '')}")
        prior = priors.get(f"coating_{name}")
        if prior is not None:
            lines.append(f"  {'':<24} prior: {prior.describe()}; {prior.source}; width: {prior.reason}")
    return CommandResult(values={}, title=f"coating '{coating.name}': {coating.description}", notes=lines)
