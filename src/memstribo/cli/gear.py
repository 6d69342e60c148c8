"""``memstribo gear``: geometry, kinematics and Hertz contact of the involute spur pair."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "gear"
HELP = "involute spur pair: radii, path of contact, contact ratio, Hertz contact at the pitch point, F_t"
ORDER = 40


def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP, description=HELP + ". Change the pair with --set teeth_pinion=..., "
        "teeth_gear, module, pressure_angle ('20 deg'), face_width, addendum_coefficient, normal_load, drive_torque.")
    parser.add_argument("--outer-diameters", metavar="D1,D2",
                        help="tip diameters of pinion and gear ('81um,303um'): sets the module of a standard pair, "
                             "m = (D1 + D2) / (z1 + z2 + 4 h_a)")
    parser.set_defaults(handler=run)


def _module_from_option(text, params):
    from memstribo.errors import InputError
    from memstribo.physics.gear import module_from_outer_diameters
    from memstribo.units import to_si

    parts = [p for p in text.split(",") if p.strip()]
    if len(parts) != 2:
        raise InputError(f"--outer-diameters expects two lengths D1,D2 (e.g. 81um,303um), got {text!r}.")
    d1, d2 = (to_si(p, "m", "--outer-diameters") for p in parts)
    try:
        return module_from_outer_diameters(d1, d2, params["teeth_pinion"], params["teeth_gear"],
                                           params["addendum_coefficient"])
    except InputError as exc:
        raise InputError(f"--outer-diameters {text}: {exc}") from None


def run(args, params):
    import math

    if args.outer_diameters:
        params = params.updated({"module": _module_from_option(args.outer_diameters, params)},
                                origin="--outer-diameters")
    from memstribo.physics.gear import gear_summary

    values, units = gear_summary(params)
    warnings = list(values.pop("design_warnings", []))
    units.pop("design_warnings", None)
    notes = [
        f"  pressure angle {math.degrees(values['pressure_angle']):.4g} deg; radii as [pinion, gear]; positions c on "
        "the line of action, 0 at the pitch point.",
        f"  Hertz line contact at the pitch point under normal_load = {params['normal_load'] * 1e6:.4g} µN "
        "(Eqs. 4-22..4-26); the thesis prints a = 58.9 nm, which does not follow from its inputs.",
        "  design checks (ISO 21771:2007): pointed teeth (tip thickness s_a <= 0), undercut, interference and a "
        "contact ratio below 1 are refused; s_a < 0.25 m and a contact ratio below 1.2 are warned about.",
    ]
    return CommandResult(values=values, units=units, title="involute spur gear pair (thesis 4.3-4.7)", notes=notes,
                         warnings=warnings)
