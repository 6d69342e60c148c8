"""``memstribo parameters``: list the model parameters, their values, units and sources."""

from __future__ import annotations

from .common import CommandResult, format_quantity

NAME = "parameters"
HELP = "list the model parameters with their values, units and sources"
ORDER = 90


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP)
    parser.add_argument("--toml", action="store_true", help="print the parameters as TOML (a valid --config file)")
    parser.set_defaults(handler=run)


def run(args, params):
    from ..parameters import SPECS

    if args.toml:
        print(params.to_toml(), end="")
        return None
    if args.json:
        return CommandResult(values=params.to_dict(), units={n: SPECS[n].unit for n in params})
    lines = []
    for name in params:
        spec, value = SPECS[name], params[name]
        shown = "unset (derived)" if value is None else format_quantity(value, spec.unit)
        lines.append(f"  {name:<28} {shown:<16} {spec.description}")
        if spec.kind in ("float", "int"):
            lines.append(f"  {'':<28} allowed: {spec.allowed()}" + (f"; {spec.why}" if spec.why else ""))
        lines.append(f"  {'':<28} source: {params.source(name)}")
    return CommandResult(values={}, title=f"parameter set '{params.name}'", notes=lines)
