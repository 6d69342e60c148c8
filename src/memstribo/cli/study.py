"""``memstribo study SPEC.toml``: a grid or list of points through dask.distributed, resumable."""

from __future__ import annotations


from memstribo.cli.common import CommandResult, add_progress_argument, progress_enabled

NAME = "study"
HELP = "run a parameter study (grid or list of points) on Dask; resumable after an interruption"
ORDER = 80

DESCRIPTION = """\
Run a parameter study: every point of SPEC.toml (a [study] table with a grid and/or a list
of points over model parameters and coating, wear, roughness, seed, steps) through
dask.distributed. Each finished point is written at once to OUT/points/; after an
interruption (even kill -9) rerun with --resume: no point is lost and none is computed
twice, and the points that failed run again. Results go to OUT/results.nc and
OUT/results.csv (dimension point); a grid-only study also writes OUT/results_grid.nc/.csv
with one dimension per swept key. The spec names one of memstribo's point functions (mesh, gear, slide);
--dry-run checks the spec and every point without running anything. See docs/studies.md.
"""


def register(subparsers, parents):
    import argparse

    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=DESCRIPTION,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("spec", metavar="SPEC.toml", help="study specification (see examples/study_load_wear.toml)")
    parser.add_argument("--out", default=None, metavar="DIR",
                        help="output folder (default: memstribo-study-<spec file name>)")
    parser.add_argument("--scheduler", default=None, metavar="ADDRESS",
                        help="address of an existing Dask scheduler (tcp://host:8786); default: a local cluster")
    parser.add_argument("--workers", type=int, default=None, metavar="N",
                        help="worker processes of the local cluster (default: number of cores)")
    parser.add_argument("--resume", action="store_true",
                        help="finish a study interrupted in --out, and run its failed points again")
    parser.add_argument("--dry-run", action="store_true",
                        help="check the spec and every point (keys, ranges, files) and print the number of points; "
                             "run nothing")
    add_progress_argument(parser)
    parser.set_defaults(handler=run)


def run(args, params):
    from pathlib import Path

    from memstribo.errors import InputError
    from memstribo.simulations.study import function_name, load_study_spec, prepare_points, run_study

    spec = load_study_spec(args.spec)
    if args.workers is not None and not 1 <= args.workers <= 4096:
        raise InputError(f"--workers {args.workers}: give a positive integer (at most 4096).")
    from memstribo.cli.mesh import cap_workers

    args.workers = cap_workers(args.workers, "study", quiet=getattr(args, "quiet", False))
    if args.dry_run:
        points = prepare_points(spec, params)
        return CommandResult(values={"name": spec.name, "function": function_name(spec.function),
                                     "points": len(points)},
                             title=f"study '{spec.name}': spec and points valid (dry run, nothing computed)")
    out = Path(args.out) if args.out else Path(f"memstribo-study-{Path(args.spec).stem}")
    progress = progress_enabled(args)
    result = run_study(spec, out, params, scheduler=args.scheduler, workers=args.workers, resume=args.resume,
                       progress=progress)
    values = {
        "name": spec.name,
        "function": function_name(spec.function),
        "points": result.n_points,
        "computed": result.n_computed,
        "reused": result.n_reused,
        "retried": result.n_retried,
        "failed": result.n_failed,
        "elapsed": result.elapsed,
        "folder": str(result.folder),
        "results_netcdf": str(result.folder / "results.nc"),
        "results_csv": str(result.folder / "results.csv"),
    }
    if (result.folder / "results_grid.nc").is_file():
        values["results_grid_netcdf"] = str(result.folder / "results_grid.nc")
    units = {"elapsed": "s"}
    notes = []
    if result.n_retried:
        notes.append(f"  reran {result.n_retried} point(s) that had failed in an earlier run")
    notes += [f"  failed point {pid}: {message}" for pid, message in list(result.errors.items())[:10]]
    if result.n_failed > 10:
        notes.append(f"  ... and {result.n_failed - 10} more (see the 'error' column of results.csv)")
    return CommandResult(values=values, units=units, title=f"study '{spec.name}'", notes=notes)
