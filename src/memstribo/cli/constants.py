"""``memstribo constants``: the nanoscale constants of the parameter set (thesis 3.3, 3.5)."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "constants"
HELP = "Lennard-Jones, adhesion and bond constants of the material (sigma, epsilon, E*, w, C_NS, pull-off force)"
ORDER = 20

def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP, description=HELP + ". Values follow the parameter set, so "
        "--set poisson_ratio=0.5 or --set work_of_adhesion=1.31 change them.")
    parser.add_argument("--half-width", metavar="LENGTH", default=None,
                        help="contact half width a of one block for the pull-off force (3-32); "
                             "default: adhesive_width / 2 (e.g. '97.5 nm' for thesis 3.5)")
    parser.set_defaults(handler=run)


def run(args, params):
    from memstribo.physics.adhesion import nanoscale_constants, pull_off_force
    from memstribo.errors import InputError
    from memstribo.units import to_si

    constants = nanoscale_constants(params)
    half_width = constants.half_width
    pull_off = constants.pull_off_force_block
    if args.half_width is not None:
        half_width = to_si(args.half_width, "m", "--half-width")
        if not 1e-10 <= half_width <= 1e-3:
            raise InputError(f"--half-width must be a length from 0.1 nm to 1 mm (e.g. '97.5 nm'), got "
                             f"'{args.half_width}'.")
        pull_off = pull_off_force(constants.work_of_adhesion, constants.contact_modulus,
                                  constants.no_slip_coefficient, half_width)
    values = {
        "sigma": constants.sigma,
        "epsilon": constants.epsilon,
        "contact_modulus": constants.contact_modulus,
        "work_of_adhesion": constants.work_of_adhesion,
        "no_slip_coefficient": constants.no_slip_coefficient,
        "pull_off_force_block": pull_off,
        "half_width": half_width,
        "maugis_stress": constants.maugis_stress,
        "maugis_range": constants.maugis_range,
        "bond_energy_chemical": constants.bond_energy_chemical,
        "bond_energy_vdw": constants.bond_energy_vdw,
        "bond_length": constants.bond_length,
    }
    notes = [
        f"  work of adhesion from {constants.work_of_adhesion_source}"
        + (" (the thesis prints 1.31 J/m^2; see docs/nanoscale-physics.md)"
           if constants.work_of_adhesion_source.startswith("formula") else ""),
        "  sigma = D_chem 2^(-1/6) (3-16); epsilon = D_chem^3 E / 72 (3-19..3-23); "
        "pull-off force sqrt(8 pi w E* C_NS a^3) (3-32)",
        "  Maugis-Dugdale: sigma0 = 16 w / (9 sqrt(3) D0), h0 = w / sigma0 (3-17)",
    ]
    return CommandResult(values=values, title=f"nanoscale constants ({params.name})", notes=notes)
