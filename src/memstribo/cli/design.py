"""``memstribo design SPEC.toml``: the gear pair with the widest safe torque window, by a seeded, resumable
multi-objective search (NSGA-II) under roughness uncertainty (issue #39)."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "design"
HELP = "design search: the pair with the widest safe torque window (stiction to fracture), NSGA-II, resumable"
ORDER = 86

DESCRIPTION = """\
Search a gear pair's design (SPEC.toml: [design.variables] with bounds: module, teeth_pinion,
teeth_gear or ratio, face_width, pressure_angle, addendum_coefficient, coating as a list of
shipped coatings; [design.constraints]: contact_ratio_min, tooth_thickness_min, a fixed
centre_distance or ratio; undercut, interference and pointed tips are always refused) for the
objectives of [design] objectives: window (the safe drive-torque window, from the lowest torque
whose running and start-up P(stiction) are below stiction_probability by their 95 % upper bound
to the torque whose fracture probability within `cycles` reaches fracture_probability),
efficiency, coating_life, footprint. NSGA-II (pymoo), seeded; each design's evaluation is
written to OUT/evaluations/ at once, and --resume continues an interrupted search without
repeating them. Results: OUT/pareto.nc and .csv (the Pareto set), OUT/evaluations.nc and .csv,
OUT/figures/design_front. --explain N prints Pareto design N's verdict as 'memstribo mesh' does.
See docs/design.md.
"""


def register(subparsers, parents):
    import argparse

    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=DESCRIPTION,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("spec", metavar="SPEC.toml", help="design specification (see docs/design.md)")
    parser.add_argument("--out", default=None, metavar="DIR",
                        help="output folder (default: memstribo-design-<spec file name>)")
    parser.add_argument("--scheduler", default=None, metavar="ADDRESS",
                        help="address of an existing Dask scheduler (tcp://host:8786); default: a local cluster")
    parser.add_argument("--workers", type=int, default=None, metavar="N",
                        help="worker processes of the local cluster (default: number of cores; 1: in this process)")
    parser.add_argument("--resume", action="store_true",
                        help="continue a search interrupted in --out (finished evaluations are not repeated)")
    parser.add_argument("--explain", type=int, default=None, metavar="N",
                        help="print Pareto design N's verdict (at its lower torque edge) as 'memstribo mesh' does")
    parser.add_argument("--progress", choices=("auto", "on", "off"), default="auto",
                        help="progress bar on stderr: auto (when stderr is a terminal), on, off")
    from memstribo.cli.common import add_verbosity_arguments

    add_verbosity_arguments(parser)
    parser.set_defaults(handler=run)


def _out(args):
    from pathlib import Path

    return Path(args.out) if args.out else Path(f"memstribo-design-{Path(args.spec).stem}")


def run(args, params):
    from memstribo.errors import InputError
    from memstribo.simulations.design_spec import load_design_spec

    spec = load_design_spec(args.spec, params)
    if args.workers is not None and not 1 <= args.workers <= 4096:
        raise InputError(f"--workers {args.workers}: give a positive integer (at most 4096).")
    if args.explain is not None:
        return explain(args, params)
    from memstribo.cli.common import progress_enabled
    from memstribo.simulations.design_search import run_design

    result = run_design(spec, _out(args), params, scheduler=args.scheduler, workers=args.workers, resume=args.resume,
                        progress=progress_enabled(args))
    default = result.default.get("values") or {}
    best = (result.best or {}).get("values") or {}
    values = {
        "name": spec.name, "objectives": list(spec.objectives), "population": spec.population,
        "generations": spec.generations, "seed": spec.seed, "realisations": spec.realisations,
        "steps": spec.steps, "evaluations": result.n_evaluations, "computed": result.n_computed,
        "reused": result.n_reused, "infeasible": result.n_infeasible, "failed": result.n_failed,
        "cycles_spent": result.cycles_spent, "cycles_total": result.cycles_total,
        "pareto_designs": int(result.dataset.sizes["design"]),
        "default_torque_window": default.get("torque_window"),
        "default_torque_window_high": default.get("torque_window_high"),
        "default_stiction_torque": default.get("stiction_torque"),
        "default_fracture_torque": default.get("fracture_torque"),
        "best_design": (result.best or {}).get("design"),
        "best_torque_window": best.get("torque_window"), "best_torque_window_high": best.get("torque_window_high"),
        "best_stiction_torque": best.get("stiction_torque"), "best_fracture_torque": best.get("fracture_torque"),
        "best_converged": best.get("converged"),
        "elapsed": result.elapsed, "folder": str(result.folder),
        "pareto_netcdf": str(result.folder / "pareto.nc"), "pareto_csv": str(result.folder / "pareto.csv"),
        "figures": [str(p) for p in result.figures],
    }
    notes = [f"  {n}" for n in result.notes]
    notes.append(f"  meshing cycles: {result.cycles_spent} by this run, {result.cycles_total} in the search "
                 f"({spec.realisations} realisations x verdicts; convergence spot checks not counted)")
    units = {f"{who}_{key}": "N*m" for who in ("default", "best") for key in
             ("torque_window", "torque_window_high", "stiction_torque", "fracture_torque")}
    units.update(elapsed="s", best_converged="")
    return CommandResult(values=values, units=units, title=f"design search '{spec.name}'", notes=notes,
                         exit_status=1 if result.n_failed else 0)


def explain(args, params):
    """Pareto design N's verdict by the ``memstribo mesh`` command (its handler, on its own command line)."""
    from memstribo.cli import mesh
    from memstribo.cli.main import build_parser, load_parameters
    from memstribo.simulations.design_search import explain_arguments

    argv, row = explain_arguments(_out(args), args.explain)
    mesh_args = build_parser().parse_args(argv + (["--json"] if args.json else []))
    mesh_args.parameter_set, mesh_args.config, mesh_args.overrides = args.parameter_set, args.config, \
        list(args.overrides) + list(mesh_args.overrides)
    result = mesh.run(mesh_args, load_parameters(mesh_args))
    window = row.get("torque_window")
    result.title = f"Pareto design {args.explain} at its lower torque edge: {result.title}"
    result.notes = list(result.notes) + [
        f"  design search: torque window {window:.4g} N*m (stiction edge {row.get('stiction_torque'):.4g}, "
        f"fracture edge {row.get('fracture_torque'):.4g} N*m), converged {row.get('converged')}",
        "  the search's verdict (its cheap cycles): memstribo " + " ".join(argv),
        "  without --no-refine, memstribo mesh refines the cycle until it converges (MODEL 7d)"]
    return result
