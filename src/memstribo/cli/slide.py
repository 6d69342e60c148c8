"""``memstribo slide``: friction from dissipated energy in the sliding models (thesis 2.6.2, 3.4, 3.5)."""

from __future__ import annotations


from memstribo.cli.common import CommandResult, add_progress_argument, progress_enabled

NAME = "slide"
HELP = "friction of nanoblocks sliding on a flat or rough surface (single, fixed-gap, fixed-load; 3.5 estimate)"
ORDER = 40

_MODELS = ("single", "fixed-gap", "fixed-load", "estimate")


def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP,
        description=HELP + ". Prints the means over the run (COF and its split, forces) and the energies "
                           "dissipated by mechanism (totals). '--model estimate' prints the estimate of "
                           "thesis 3.5, from the thesis's printed inputs and from first principles.")
    parser.add_argument("--model", choices=_MODELS, default="fixed-load",
                        help="sliding model (default: fixed-load)")
    parser.add_argument("--profile", metavar="PATH",
                        help="counter surface: an AFM file or x-z profile (first line scan of a map); "
                             "default: the seeded synthetic thesis profile")
    parser.add_argument("--load", metavar="F", help="normal load, e.g. '25 uN' (default: normal_load)")
    parser.add_argument("--gap", metavar="G",
                        help="fixed-gap model: height of the undeformed atomic tips above the profile's mean "
                             "line, e.g. '1 nm' (default: sliding_gap, unset: the profile's Rq)")
    parser.add_argument("--distance", metavar="X",
                        help="sliding distance, e.g. '2 um' (default: as far as the profile allows; "
                             "single: 100 bond lengths)")
    parser.add_argument("--step", metavar="DX", help="sliding step, e.g. '0.1 nm' (default: sliding_step, "
                                                     "unset: bond_length)")
    parser.add_argument("--out", metavar="DIR", help="write the time series (NetCDF + CSV) and figures here")
    add_progress_argument(parser)
    parser.set_defaults(handler=run)


def _quantity(text, unit, name, parameter=None):
    """The option's value in SI; with ``parameter``, checked against that parameter's range."""
    from memstribo.units import to_si

    if text is None:
        return None
    value = to_si(text, unit, name)
    if parameter is None:
        return value
    from memstribo.errors import InputError

    if parameter == "normal_load" and value <= 0:
        raise InputError(f"{name} must be a positive force, got '{text}'.")
    from memstribo.parameters import coerce_value

    try:
        return coerce_value(parameter, text)
    except InputError as exc:
        raise InputError(f"{name}: {exc}") from None


def run(args, params):
    from memstribo.errors import InputError

    if args.model == "estimate":
        return _estimate(args, params)
    from memstribo.simulations import sliding

    load = _quantity(args.load, "N", "--load", "normal_load")
    gap = _quantity(args.gap, "m", "--gap", "sliding_gap")
    distance = _quantity(args.distance, "m", "--distance")
    step = _quantity(args.step, "m", "--step", "sliding_step")
    if load is not None and load <= 0:
        raise InputError(f"--load must be a positive force, got {args.load!r}.")
    if distance is not None and distance < 0:
        raise InputError(f"--distance must be >= 0, got {args.distance!r}.")
    if step is not None and step <= 0:
        raise InputError(f"--step must be positive, got {args.step!r}.")
    one_step = (params["sliding_step"] or params["bond_length"]) if step is None else step
    if distance is not None and distance < one_step:  # COF 0.93 over no sliding before (issue #41)
        raise InputError(f"--distance {args.distance!r} is shorter than one sliding step ({one_step:.4g} m, "
                         f"{'--step' if step is not None else 'sliding_step, unset: bond_length'}): a slide of no "
                         "length has no friction; allowed: at least one step.")
    profile = None
    if args.profile:
        if args.model == "single":
            raise InputError("--profile: the single model slides on a flat surface; use fixed-gap or fixed-load.")
        from memstribo.surfaces.readers import read_topography

        profile = read_topography(args.profile)
    progress = progress_enabled(args)
    dataset = sliding.slide(args.model, params, profile, gap=gap, load=load, distance=distance, step=step,
                            progress=progress)
    summary = sliding.summarize(dataset)
    values = summary.to_dict()
    notes = [f"  profile: {dataset.attrs['profile_source']}"]
    if dataset.attrs.get("synthetic_profile"):
        notes.append("  (synthetic: the thesis's own scan is not published; give --profile for a measured one)")
    notes.append("  cof, forces: means over the steps; energies: totals over the slide")
    if args.out:
        from memstribo.output import provenance_attributes

        roughness = args.profile or (dataset.attrs.get("profile_source") if args.model != "single" else None)
        provenance = provenance_attributes(params, roughness=roughness, extra={
            "command": f"memstribo slide --model {args.model}", "models": f"memstribo.simulations.sliding.slide ({args.model})",
            **({} if roughness else {"roughness_provenance": "none: a nanoblock on a flat"})})
        notes += [f"  wrote {path}" for path in _write(dataset, args.out, provenance)]
    return CommandResult(values=values, title=f"memstribo slide --model {args.model}",
                         notes=notes)


def _estimate(args, params):
    from memstribo.errors import InputError
    from memstribo.physics.friction import THESIS_3_5_COUNTS, THESIS_3_5_INPUTS, estimate_from_parameters, thesis_estimate

    if args.profile or args.gap or args.distance or args.step or args.out:
        raise InputError("--model estimate takes only --load (the 3.5 estimate has no profile or slide).")
    load = _quantity(args.load, "N", "--load", "normal_load")
    printed = thesis_estimate(**THESIS_3_5_INPUTS)
    counts = thesis_estimate(**THESIS_3_5_COUNTS)
    ours = estimate_from_parameters(params, load=load)
    values = {
        "cof": ours.cof, "cof_chemical": ours.cof_chemical, "cof_vdw": ours.cof_vdw, "cof_elastic": 0.0,
        "friction_force": ours.friction_force, "adhesion_force": ours.adhesion_force,
        "normal_force": ours.load, "bonds_chemical_per_block": ours.chemical_bonds,
        "bonds_vdw_per_block": ours.vdw_bonds, "energy_chemical_per_block": ours.chemical_energy_per_block,
        "energy_vdw_per_block": ours.vdw_energy_per_block, "pull_off_force_block": ours.pull_off_force_block,
        "blocks": ours.blocks,
        "thesis_inputs_cof": printed.cof, "thesis_inputs_friction_force": printed.friction_force,
        "thesis_counts_cof": counts.cof,
    }
    notes = ["  first principles with this parameter set; thesis_inputs_*: from the values printed in 3.5",
             "  (n = 9, N_chem U_chem = 4e-15 J, N_vdW U_vdW = 3.73e-15 J, F_adh = 3.386e-4 N, F_ext = 25 uN);",
             "  thesis_counts_cof: the same with N_chem U_chem = 7388.6 x 5.42e-19 J, N_vdW U_vdW = 688546.8 x",
             "  5.42e-21 J unrounded. The thesis prints 0.82. See docs/friction.md for why the values differ."]
    return CommandResult(values=values, title="memstribo slide --model estimate (thesis 3.5)",
                         notes=notes)


def _write(dataset, folder, provenance=None):
    from memstribo.output import new_figure, save_figure, write_dataset

    written = write_dataset(dataset, folder, "slide", csv=False, provenance=provenance)
    steps_only = dataset[[name for name, var in dataset.data_vars.items() if var.dims == ("step",)]]
    written += write_dataset(steps_only, folder, "slide_steps", csv=True, provenance=provenance)
    x = dataset["sliding_distance"].values * 1e9
    panels = [
        ("friction_force", "friction force [N]", ["friction_force", "friction_force_chemical",
                                                  "friction_force_vdw", "friction_force_elastic"]),
        ("cof", "coefficient of friction [-]", ["cof", "cof_chemical", "cof_vdw", "cof_elastic"]),
        ("forces", "force [N]", ["normal_force", "adhesion_force"]),
        ("energy", "energy per step [J]", ["energy_chemical", "energy_vdw", "energy_elastic"]),
        ("atomic_stress", "max normal stress on atomic blocks [Pa]", ["max_atomic_stress"]),
    ]
    for stem, ylabel, names in panels:
        figure, axes = new_figure(figsize=(7, 3.5))
        for name in names:
            axes.plot(x, dataset[name].values, label=name, lw=0.8)
        axes.set_xlabel("sliding distance [nm]")
        axes.set_ylabel(ylabel)
        axes.set_title(f"{dataset.attrs['model']}: {stem.replace('_', ' ')}")
        axes.legend(fontsize="small")
        written += save_figure(figure, folder, f"slide_{stem}")
    figure, axes = new_figure(figsize=(7, 3.5))
    for block in range(dataset.sizes["block"]):
        axes.plot(x, dataset["shrink"].values[:, block] * 1e9, label=f"nanoblock {block}", lw=0.8)
    axes.set_xlabel("sliding distance [nm]")
    axes.set_ylabel("shrink [nm]")
    axes.set_title(f"{dataset.attrs['model']}: total shrink of the structure")
    axes.legend(fontsize="small")
    written += save_figure(figure, folder, "slide_shrink")
    return written
