"""``memstribo coating``: friction of SAM-coated teeth at a wear state Omega (thesis 5.5.3)."""

from __future__ import annotations

from pathlib import Path

from memstribo.cli.common import CommandResult, add_progress_argument, format_value, progress_enabled

NAME = "coating"
HELP = "COF, friction force and stiction margin of SAM-coated teeth for worn fractions Omega"
ORDER = 70


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP + (
        ". The pinion's coating is fully worn and a fraction Omega of the gear's (thesis 5.5.3): "
        "Omega = 0 is the fully coated pair, Omega = 1 bare silicon (equal to 'memstribo mesh')."))
    parser.add_argument("--coating", default="OTS", help="coating name: OTS (default), FDTS, DDMS or W (parameter sets in "
                        "parameters/coatings; 'memstribo parameters --coating NAME' shows one)")
    parser.add_argument("--wear", default=None, metavar="W",
                        help="worn fraction Omega from 0 to 1, or a comma-separated list '0,0.2,0.4' for a table "
                             "(default: the parameter coating_wear)")
    parser.add_argument("--load-case", choices=("torque", "thesis"),
                        help="normal load of the meshing cycles: 'torque' (default) or 'thesis' (normal_load, 25 uN)")
    parser.add_argument("--steps", type=int, default=None, help="steps of each meshing-cycle simulation")
    parser.add_argument("--out", metavar="DIR", help="write the sweep (NetCDF + CSV) and figures (COF vs Omega, "
                                                     "friction vs tangential force) to DIR; with --calibrate: the "
                                                     "config FILE (TOML) to write")
    add_progress_argument(parser)
    parser.add_argument("--calibrate", nargs="?", const=0.185, type=float, metavar="COF",
                        help="instead of a sweep: scale the coating's U_vdW so that the fully coated pair "
                             "(Omega = 0) has this mean COF (default 0.185, thesis 5.5.3) and print the calibration")
    parser.set_defaults(handler=run)


#: most worn fractions ``--wear`` may list
MAX_WEAR_VALUES = 1000


def parse_wear_list(text) -> list[float]:
    """'0,0.2,0.4' -> [0.0, 0.2, 0.4], each checked to lie in 0..1."""
    from memstribo.physics.coating import check_wear
    from memstribo.errors import InputError

    items = [item.strip() for item in str(text).split(",")]
    if len(items) > MAX_WEAR_VALUES:  # refused before any is read: each is a meshing cycle (issue #41)
        raise InputError(f"--wear lists {len(items):,} values; at most {MAX_WEAR_VALUES} are allowed (one meshing "
                         "cycle each).")
    if not items or any(item == "" for item in items):
        raise InputError(f"--wear must be a number from 0 to 1 or a comma-separated list of them, got {text!r}.")
    try:
        numbers = [float(item.rstrip("%")) / (100.0 if item.endswith("%") else 1.0) for item in items]
    except ValueError:
        raise InputError(f"--wear must be a number from 0 to 1 or a comma-separated list of them, got {text!r}.") from None
    return [float(w) for w in check_wear(numbers)]


def run(args, params):
    from memstribo.physics.coating import get_coating
    from memstribo.quantities import unit
    from memstribo.simulations.coating_wear import SWEEP_VARIABLES, wear_sweep
    from memstribo.errors import InputError

    from memstribo.cli.mesh import apply_load_case

    params = apply_load_case(args, params)
    coating = get_coating(args.coating, params)
    if args.calibrate is not None:
        return _calibrate(args, params, coating)
    from memstribo.checks import user_set

    wears = parse_wear_list(params["coating_wear"] if args.wear is None else args.wear)
    if args.wear is not None and user_set(params, "coating_wear") and list(wears) != [params["coating_wear"]]:
        from memstribo.units import printable  # two values of one quantity (issue #41)

        raise InputError(f"--wear {printable(args.wear)} and the parameter coating_wear = "
                         f"{float(params['coating_wear']):g} disagree: both give the worn fraction Omega of the gear's "
                         "coating; give one of them (--wear for a table of several).")
    if args.steps is not None and not 2 <= args.steps <= 100_000:
        raise InputError(f"--steps must be an integer from 2 to 100 000, got {args.steps}.")
    sweep = wear_sweep(params, coating, wears, steps=args.steps, progress=progress_enabled(args))
    points = []
    for i, w in enumerate(wears):
        point = {"wear": w}
        for key in SWEEP_VARIABLES:
            value = float(sweep[key].values[i])
            point[key] = bool(value) if key == "stiction" else value
        points.append(point)
    notes = [f"  coating {coating.name}: U_vdW = {coating.vdw_bond_energy:.4g} J, A = {coating.hamaker_constant:.3g} J, "
             f"w = {coating.work_of_adhesion:.4g} J/m^2; the pinion's coating fully worn (thesis 5.5.3)"]
    if args.out:
        from memstribo.output import provenance_attributes
        from memstribo.surfaces.roughness import default_profile

        provenance = provenance_attributes(params, roughness=default_profile(params), extra={
            "command": "memstribo coating", "coating": coating.name,
            "models": "memstribo.simulations.coating_wear.wear_sweep (thesis 5.4, 5.5.3)"})
        notes.extend(_write_outputs(sweep, coating, args.out, provenance))
    if len(points) == 1:
        return CommandResult(values={"coating": coating.name, **points[0]},
                             title=f"{coating.name}-coated teeth at wear Omega = {wears[0]:g}", notes=notes)
    if args.json:
        return CommandResult(values={"coating": coating.name, "points": points})
    keys = ["wear", *SWEEP_VARIABLES]
    width = max(len(k) for k in keys) + 2
    lines = ["  " + "".join(f"{k:>{width}}" for k in keys)]
    for point in points:
        lines.append("  " + "".join(f"{format_value(point[k], unit(k)):>{width}}" for k in keys))
    return CommandResult(values={}, title=f"{coating.name}-coated teeth over wear states Omega",
                         notes=lines + notes)


def _write_outputs(sweep, coating, folder, provenance=None) -> list[str]:
    from memstribo.output import new_figure, save_figure, write_dataset

    written = write_dataset(sweep, folder, "coating_wear", provenance=provenance)
    wear = sweep["wear"].values * 100
    fig, ax = new_figure(figsize=(5, 3.5))
    ax.plot(wear, sweep["cof_mean"].values, "o-", label="total")
    for key, label in (("cof_chemical", "chemical"), ("cof_vdw", "vdW"), ("cof_elastic", "elastic")):
        ax.plot(wear, sweep[key].values, ".--", label=label)
    ax.set_xlabel("worn fraction of the gear's coating Omega [%]")
    ax.set_ylabel("COF [-]")
    ax.set_title(f"COF vs wear, {coating.name} (thesis Figure 5-28)")
    ax.legend()
    written += save_figure(fig, folder, "cof_vs_wear")
    fig, ax = new_figure(figsize=(5, 3.5))
    ax.plot(wear, sweep["resisting_force_max"].values * 1e3, "o-", label="largest resisting force R")
    ax.plot(wear, sweep["tangential_force"].values * 1e3, "k--", label="tangential force F_t")
    ax.set_xlabel("worn fraction of the gear's coating Omega [%]")
    ax.set_ylabel("force [mN]")
    ax.set_title("friction vs available tangential force (thesis Figure 5-24)")
    ax.legend()
    written += save_figure(fig, folder, "friction_vs_tangential")
    return ["  wrote " + ", ".join(str(p) for p in written)]


def _calibrate(args, params, coating):
    from memstribo.physics.coating import coating_config
    from memstribo.simulations.coating_wear import calibrate_vdw_bond_energy
    from memstribo.output import atomic_write_text

    calibrated, record = calibrate_vdw_bond_energy(params, coating, args.calibrate, steps=args.steps)
    values = {"coating": coating.name, "target_cof": args.calibrate, **record,
              "factor": record["vdw_bond_energy_after"] / record["vdw_bond_energy_before"],
              "load_case": params["load_case"], "interface_model": params["interface_model"]}
    note = (f"calibrated to COF {args.calibrate:g} at Omega = 0 by 'memstribo coating --calibrate' (load case "
            f"{params['load_case']}, interface model {params['interface_model']})")
    if args.out:
        path = atomic_write_text(Path(args.out), coating_config(calibrated, note))
        values["config_file"] = str(path)
        notes = [f"  wrote {path}: use it with --config {path} (it sets coating_vdw_bond_energy and the other "
                 "coating_* parameters)"]
    else:
        notes = [f"  calibrated vdw_bond_energy = {calibrated.vdw_bond_energy:.4g} J; '--out FILE' writes it as a "
                 "config file that --config FILE reads back"]
    return CommandResult(values=values, title=f"calibration of {coating.name}'s U_vdW", notes=notes)
