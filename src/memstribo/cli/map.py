"""``memstribo map SPEC.toml``: a design map of the stiction verdict over a grid, on Dask, resumable."""

from __future__ import annotations

import sys

from memstribo.cli.common import CommandResult

NAME = "map"
HELP = "design map: stiction probability, COF and efficiency of an ensemble over a grid of design parameters"
ORDER = 85

DESCRIPTION = """\
Compute a design map: SPEC.toml names the axes ([map.grid]: any model parameter such as
drive_torque, face_width, module, teeth_pinion, roughness_rq, plus coating and wear) and
each grid point is an ensemble verdict over [map] realisations (default 4) roughness
realisations: stiction probability, stiction margin, COF and mesh efficiency (median,
5 and 95 %), and for coated points with a damage coefficient or [map] cycles_observed the
cycles to coating failure and to returning stiction. The points run on Dask (a local
cluster, or --scheduler); each finished point is written at once to OUT/points/, and
--resume finishes an interrupted map (failed points run again). Results: OUT/map.nc (one
dimension per axis), OUT/map.csv, OUT/figures/. See docs/design-maps.md.
"""


def register(subparsers, parents):
    import argparse

    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=DESCRIPTION,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("spec", metavar="SPEC.toml", help="map specification (see docs/design-maps.md)")
    parser.add_argument("--out", default=None, metavar="DIR",
                        help="output folder (default: memstribo-map-<spec file name>)")
    parser.add_argument("--scheduler", default=None, metavar="ADDRESS",
                        help="address of an existing Dask scheduler (tcp://host:8786); default: a local cluster")
    parser.add_argument("--workers", type=int, default=None, metavar="N",
                        help="worker processes of the local cluster (default: number of cores)")
    parser.add_argument("--resume", action="store_true",
                        help="finish a map interrupted in --out, and run its failed points again")
    parser.add_argument("--progress", choices=("auto", "on", "off"), default="auto",
                        help="progress bar on stderr: auto (when stderr is a terminal), on, off")
    from memstribo.cli.common import add_verbosity_arguments

    add_verbosity_arguments(parser)
    parser.set_defaults(handler=run)


def run(args, params):
    from pathlib import Path

    from memstribo.simulations.design_map import design_map, load_map_spec
    from memstribo.errors import InputError

    spec = load_map_spec(args.spec)
    if args.workers is not None and not 1 <= args.workers <= 4096:
        raise InputError(f"--workers {args.workers}: give a positive integer (at most 4096).")
    from memstribo.cli.mesh import cap_workers

    args.workers = cap_workers(args.workers, "map", quiet=getattr(args, "quiet", False))
    out = Path(args.out) if args.out else Path(f"memstribo-map-{Path(args.spec).stem}")
    from memstribo.cli.common import progress_enabled

    progress = progress_enabled(args)
    result = design_map(spec, out, params, scheduler=args.scheduler, workers=args.workers, resume=args.resume,
                        progress=progress)
    probability = result.dataset["stiction_probability"].values
    finite = probability[probability == probability]  # without NaN (failed points)
    values = {
        "name": spec.name,
        "axes": {key: len(v) for key, v in spec.axes},
        "realisations": spec.realisations,
        "uncertainty_samples": spec.uncertainty,
        "points": result.n_points,
        "computed": result.n_computed,
        "reused": result.n_reused,
        "retried": result.n_retried,
        "failed": result.n_failed,
        "stiction_probability_min": float(finite.min()) if finite.size else None,
        "stiction_probability_max": float(finite.max()) if finite.size else None,
        "elapsed": result.elapsed,
        "folder": str(result.folder),
        "map_netcdf": str(result.folder / "map.nc"),
        "map_csv": str(result.folder / "map.csv"),
        "figures": [str(p) for p in result.figures],
    }
    notes = list(result.notes)
    if result.n_retried:
        notes.append(f"  reran {result.n_retried} point(s) that had failed in an earlier run")
    notes += [f"  failed point {pid}: {message}" for pid, message in list(result.errors.items())[:10]]
    if result.n_failed > 10:
        notes.append(f"  ... and {result.n_failed - 10} more (see the 'error' variable of map.nc)")
    return CommandResult(values=values, title=f"design map '{spec.name}'", notes=notes,
                         exit_status=1 if result.n_failed else 0)
