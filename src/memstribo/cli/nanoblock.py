"""``memstribo nanoblock``: the nanoblock geometry, explicit or derived from a measured profile (thesis 3.4, 4.2.3)."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "nanoblock"
HELP = "nanoblock geometry: from the parameter set, or derived from a measured profile (--from PATH)"
ORDER = 11

def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP,
        description=HELP + ". Derived: H_at = 0.5 Rq, H_adh = 1.2 Rq, widths = mean asperity widths cut at +H_at and "
        "-H_adh, pitch = lambda_q, m = floor(w_adh / lambda_q) (MODEL §1.4). The rule behind each number is printed.")
    parser.add_argument("--from", dest="source", metavar="PATH",
                        help="derive the geometry from this file (or 'thesis': the default synthetic profile)")
    parser.add_argument("--channel", metavar="NAME", help="channel name or chN (for --from)")
    parser.add_argument("--unit", metavar="U", help="unit of x and heights for files that do not say (for --from)")
    parser.add_argument("--physical-size", metavar="SIZE",
                        help="lateral size of a file that does not give one (for --from): '10 um' or '10 um, 5 um'")
    parser.set_defaults(handler=run)


def run(args, params):
    from memstribo.physics.nanoblock.geometry import NanoblockGeometry, nanoblock_geometry_from_profile

    notes = []
    if args.source is None:
        geometry = NanoblockGeometry.from_parameters(params)
        title = f"nanoblock geometry of parameter set '{params.name}'"
    else:
        from memstribo.surfaces.readers import read_topography
        from memstribo.surfaces.roughness import default_profile

        if args.source == "thesis":
            surface = default_profile(params)
            notes.append("SYNTHETIC profile: the thesis's AFM scan is not published (seeded Gaussian profile with the "
                         "chapter-4 statistics).")
        else:
            surface = read_topography(args.source, channel=args.channel, unit=args.unit,
                                      physical_size=args.physical_size)
        geometry = nanoblock_geometry_from_profile(surface, bulk_height=params["bulk_height"])
        title = f"nanoblock geometry derived from {surface.name}"
    values = geometry.to_dict()
    rules = values.pop("rules")
    values = {key: values[key] for key in ("atomic_width", "atomic_height", "adhesive_width", "adhesive_height",
                                            "atomic_pitch", "atomic_per_side", "bulk_height")}
    values["rules"] = rules
    if not args.json:
        values.pop("rules")
        notes = ["rules:"] + [f"  {key}: {rule}" for key, rule in rules.items()] + notes
    return CommandResult(values=values, title=title, notes=notes)
