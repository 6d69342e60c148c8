"""``memstribo mesh``: friction, adhesion, COF and stiction of rough silicon teeth over one meshing cycle."""

from __future__ import annotations

import sys

from .common import CommandResult

NAME = "mesh"
HELP = "meshing-cycle simulation: friction, adhesion, COF and its split, stiction margin (thesis 4.6-4.9)"
ORDER = 50

MESH_KEYS = ("cof_mean", "cof_max", "cof_chemical", "cof_vdw", "cof_elastic", "friction_force_mean",
             "friction_force_max", "adhesion_force_mean", "normal_force_max", "tangential_force", "stiction",
             "stiction_margin", "steps", "sliding_distance")


def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP,
        description=HELP + ". The rough contact is solved at every step along the whole path of contact with the "
        "load-sharing function; nanoblocks tile both flanks. Change the load with --set normal_load='50 uN', the "
        "resolution with --set mesh_grid_spacing='1 nm'.")
    add_common_arguments(parser)
    parser.add_argument("--out", metavar="DIR", help="write the time series (NetCDF + CSV) and the figures (PNG + SVG)")
    parser.set_defaults(handler=run)


def add_common_arguments(parser):
    """--roughness, --steps, --coating, --wear, --progress (shared with ``memstribo sweep``)."""
    parser.add_argument("--roughness", metavar="PATH", default="thesis",
                        help="roughness of both flanks: an AFM/profile file, or 'thesis' (the default synthetic "
                             "profile); a 2D map gives one scan line per row of nanoblocks")
    parser.add_argument("--steps", type=int, metavar="N", help="positions along the path of contact (default: "
                                                               "the parameter mesh_steps)")
    parser.add_argument("--coating", metavar="NAME", help="SAM coating of the teeth (e.g. OTS); default: bare silicon")
    parser.add_argument("--wear", type=float, default=1.0, metavar="OMEGA",
                        help="worn fraction of the gear's coating, 0..1 (with --coating; default 1 = bare)")
    parser.add_argument("--progress", action="store_true", help="progress bar on stderr (default: when stderr is "
                                                                  "a terminal)")


def simulation_options(args):
    """Keyword arguments of :func:`memstribo.mesh.simulate_mesh` from the command line."""
    from ..errors import InputError

    coating = None
    if args.coating:
        from ..coating import get_coating

        coating = get_coating(args.coating)
    elif args.wear != 1.0:
        raise InputError("--wear needs --coating (bare silicon has no coating to wear).")
    if args.steps is not None and args.steps < 3:
        raise InputError(f"--steps must be at least 3, got {args.steps}.")
    progress = bool(args.progress or sys.stderr.isatty())
    return dict(steps=args.steps, coating=coating, wear=args.wear, progress=progress)


def run(args, params):
    from ..mesh import SUMMARY_UNITS, simulate_mesh, summarize

    options = simulation_options(args)
    dataset = simulate_mesh(params, args.roughness, **options)
    summary = summarize(dataset)
    values = {key: summary[key] for key in MESH_KEYS}
    values.update({key: summary[key] for key in summary if key not in MESH_KEYS})
    notes = [
        f"  roughness: {dataset.attrs['roughness']}"
        + (" (synthetic: the thesis's scan is not published)" if dataset.attrs["roughness_synthetic"] else ""),
        f"  block loads: {dataset.attrs['block_load_variant']}",
        f"  {dataset.attrs['rows']} rows of nanoblocks across the face width; contact grid "
        f"{dataset.attrs['grid_spacing'] * 1e9:.3g} nm over a {dataset.attrs['window'] * 1e6:.3g} um window",
        f"  Dundurs beta {dataset.attrs['dundurs_beta']:.3g}: "
        + ("identical materials, one pass is exact" if dataset.attrs["dundurs_beta"] == 0
           else f"F_t/F_f iteration, {dataset.attrs['friction_passes']} passes"),
    ]
    if summary["unconverged_steps"]:
        notes.append(f"  WARNING: the contact solve did not converge in {summary['unconverged_steps']} step(s); they are "
                     "flagged in the dataset (contact_converged).")
    if summary["window_exceeded_steps"]:
        notes.append(f"  WARNING: the contact reached the ends of the window in {summary['window_exceeded_steps']} "
                     f"step(s): raise mesh_window (now {dataset.attrs['window'] * 1e6:.3g} um), e.g. --set "
                     f"mesh_window='{2 * dataset.attrs['window'] * 1e6:.3g} um'.")
    if summary["steps_above_elastic_limit"]:
        notes.append(f"  WARNING: the rough contact's peak pressure exceeds the elastic limit of silicon "
                     f"({dataset.attrs['elastic_limit_pressure'] / 1e9:.3g} GPa) in {summary['steps_above_elastic_limit']} "
                     "step(s): the elastic model is stretched there.")
    if summary["stiction"]:
        notes.append("  stiction: the friction force exceeds the pair's share of F_t in part of the cycle.")
    if args.out:
        from pathlib import Path

        from ..output import provenance_attributes

        roughness = args.roughness if Path(str(args.roughness)).is_file() else dataset.attrs.get("roughness_source")
        notes.extend(write_outputs(dataset, args.out, provenance_attributes(
            params, roughness=roughness, extra={"command": "memstribo mesh",
                                                "models": "memstribo.mesh.simulate_mesh (thesis 4.6-4.9)"})))
    return CommandResult(values=values, units=dict(SUMMARY_UNITS), title="meshing cycle (thesis 4.6-4.9)",
                         notes=notes)


def write_outputs(dataset, folder, provenance=None) -> list[str]:
    """NetCDF (everything), NetCDF + CSV of the per-step series, and the chapter-4 figures."""
    from ..output import write_dataset

    written = write_dataset(dataset, folder, "mesh", csv=False, provenance=provenance)
    series = dataset.drop_vars([name for name in dataset.variables if "block" in dataset[name].dims])
    written += write_dataset(series, folder, "mesh_cycle", csv=True, provenance=provenance)
    written += plot_cycle(dataset, folder)
    return ["  wrote " + ", ".join(str(path) for path in written)]


def plot_cycle(dataset, folder) -> list:
    """Figures over the cycle: friction force, adhesion force, COF (split), dissipated energy (PNG + SVG)."""
    import numpy as np

    from ..output import new_figure, save_figure

    c = np.asarray(dataset["c"]) * 1e6
    written = []

    def axes(title, ylabel):
        figure, ax = new_figure(figsize=(6.4, 3.6))
        ax.set_xlabel("position on the line of action c [um] (0: pitch point)")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        ax.axvline(0.0, color="0.6", lw=0.8, ls=":")
        return figure, ax

    figure, ax = axes("Friction force over the meshing cycle", "force [uN]")
    ax.plot(c, dataset["friction_force"] * 1e6, lw=0.9, label="friction force F_f")
    ax.plot(c, dataset["tangential_force"] * 1e6, lw=0.9, ls="--", label="available F_t (pair's share)")
    ax.legend(fontsize=8)
    written += save_figure(figure, folder, "mesh_friction_force")

    figure, ax = axes("Adhesion force over the meshing cycle", "force [uN]")
    ax.plot(c, dataset["adhesion_force"] * 1e6, lw=0.9, label="adhesion force F_adh")
    ax.plot(c, dataset["normal_force"] * 1e6, lw=0.9, ls="--", label="normal force F_N")
    ax.legend(fontsize=8)
    written += save_figure(figure, folder, "mesh_adhesion_force")

    figure, ax = axes("COF over the meshing cycle", "COF [-]")
    ax.plot(c, dataset["cof"], lw=0.9, color="k", label="COF")
    ax.plot(c, dataset["cof_chemical"], lw=0.7, label="chemical")
    ax.plot(c, dataset["cof_vdw"], lw=0.7, label="vdW")
    ax.plot(c, dataset["cof_elastic"], lw=0.7, label="elastic interlocking")
    ax.legend(fontsize=8)
    written += save_figure(figure, folder, "mesh_cof")

    figure, ax = axes("Energy dissipated per step", "energy [fJ]")
    for name, label in (("energy_chemical", "chemical bonds"), ("energy_vdw", "vdW bonds"),
                        ("energy_elastic", "elastic interlocking"), ("energy_dissipated", "total")):
        ax.plot(c, dataset[name] * 1e15, lw=0.8, label=label)
    ax.legend(fontsize=8)
    written += save_figure(figure, folder, "mesh_energy")
    return written
