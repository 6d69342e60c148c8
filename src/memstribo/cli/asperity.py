"""``memstribo asperity``: contact of one power-law atomic asperity (thesis 5.5.2, Table 5-2)."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "asperity"
HELP = "contact radius, approach and pressures of a power-law atomic asperity f(r) = B r^d"
ORDER = 60


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP + (
        ". Exact solution of Galin/Sneddon/Borodich; d = 2 is Hertz. With --nanoblock the load is that of a "
        "whole nanoblock, shared by its m x m asperities with their mutual elastic influence (Table 5-1)."))
    parser.add_argument("--load", required=True, metavar="P",
                        help="normal load on the asperity [N], may carry a unit ('0.8275 uN')")
    parser.add_argument("--degree", metavar="D", help="degree d > 0 of the shape (default: asperity_degree = 4)")
    parser.add_argument("--shape-coefficient", metavar="B",
                        help="B_d [m^(1-d)] as an SI number (default: asperity_shape_coefficient = 4e22)")
    parser.add_argument("--nanoblock", action="store_true",
                        help="treat --load as the load of a nanoblock: share it over its asperities and report "
                             "the corner asperity's contact and the shares")
    parser.set_defaults(handler=run)


def run(args, params):
    from memstribo.materials.pair import contact_modulus_of
    from memstribo.physics.asperity import nanoblock_load_sharing, power_law_contact
    from memstribo.errors import InputError
    from memstribo.units import to_si

    from memstribo.parameters import coerce_value

    def option(text, parameter, name):
        try:
            return coerce_value(parameter, text)
        except InputError as exc:
            raise InputError(f"{name}: {exc}") from None

    load = to_si(args.load, "N", "--load")
    if load <= 0:
        raise InputError(f"--load must be > 0 N, got '{args.load}'.")
    load = option(args.load, "normal_load", "--load")  # an asperity carries at most what a tooth does
    degree = params["asperity_degree"] if args.degree is None else option(args.degree, "asperity_degree", "--degree")
    coefficient = (params["asperity_shape_coefficient"] if args.shape_coefficient is None
                   else option(args.shape_coefficient, "asperity_shape_coefficient", "--shape-coefficient"))
    modulus = contact_modulus_of(params)
    notes = [f"  power-law asperity d = {degree:g}, B = {coefficient:g} m^({1 - degree:g}), E* = {modulus / 1e9:.5g} GPa"]
    values = {}
    asperity_load = load
    if args.nanoblock:
        sharing = nanoblock_load_sharing(load, params["atomic_per_side"], params["atomic_pitch"], degree,
                                         coefficient, modulus)
        positions = [p for p in ("corner", "side", "central") if (sharing.classes == p).any()]
        shares = {p: float(sharing.share_of(p)[0]) for p in positions}
        asperity_load = float(sharing.load_of(positions[0])[0])
        values["block_load"] = load
        values["asperity_loads"] = {p: float(sharing.load_of(p)[0]) for p in positions}
        values["shares"] = shares
        notes.append(f"  contact values below are those of the {positions[0]} asperity "
                     f"({params['atomic_per_side']} x {params['atomic_per_side']} asperities at "
                     f"{params['atomic_pitch'] * 1e9:g} nm pitch)")
    contact = power_law_contact(asperity_load, degree, coefficient, modulus)
    values.update({
        "contact_radius": contact.contact_radius,
        "approach": contact.approach,
        "max_pressure": contact.max_pressure,
        "max_pressure_radius": contact.max_pressure_radius,
        "mean_pressure": contact.mean_pressure,
    })
    if degree <= 1:
        notes.append("  d <= 1: the pressure is singular at the centre; max_pressure is infinite (null in JSON)")
    if contact.contact_radius > params["asperity_half_width"]:
        notes.append(f"  warning: the contact radius exceeds the asperity half width "
                     f"{params['asperity_half_width'] * 1e9:g} nm; the power-law shape no longer describes the block")
    return CommandResult(values=values, title="power-law asperity contact", notes=notes)
