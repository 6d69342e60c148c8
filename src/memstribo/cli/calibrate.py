"""``memstribo calibrate FILE.toml``: the uncertain constants updated on a lab's own measurements (issue 37, MODEL 7e).

Importance sampling of the MODEL 7d priors on the file's calibration rows (``calibration = true``, or every row where
none is marked), each row predicted at its conditions from ``--parameter-set`` / ``--config`` / ``--set`` when given
(else the lab's rule); writes the posterior as a parameter set file for ``memstribo mesh --parameter-set FILE``.
"""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "calibrate"
HELP = ("update the uncertain constants on your own measurements (a TOML file of [[measurement]] tables) and write "
        "the calibrated parameter set")
ORDER = 96


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP + ". See "
                                   "examples/own_measurement.toml.")
    parser.add_argument("file", metavar="FILE.toml", help="your measurements ([[measurement]] tables)")
    parser.add_argument("--samples", type=int, default=64, metavar="N", help="prior samples of the constants (default 64)")
    parser.add_argument("--realisations", type=int, default=2, metavar="N",
                        help="roughness realisations per sample and row (default 2)")
    parser.add_argument("--seed", type=int, default=0, metavar="N", help="seed of the prior samples (default 0)")
    parser.add_argument("--out", metavar="FILE", default=None,
                        help="where to write the calibrated parameter set (default: FILE's name + '.calibrated.toml')")
    parser.set_defaults(handler=run)


def run(args, params):
    from pathlib import Path

    from memstribo.cli.validate_lab import _notes, _rows, user_base
    from memstribo.laboratory.user import calibrate_rows, calibrated_set, load_user_measurements
    from memstribo.output import atomic_write_text

    base = user_base(args, params)
    rows = load_user_measurements(args.file, base)
    result, settings, base_name = calibrate_rows(rows, args.file, base, args.samples, args.realisations, args.seed)
    out = Path(args.out) if args.out else Path(args.file).with_suffix(".calibrated.toml")
    command = f"memstribo calibrate {args.file}"
    atomic_write_text(out, calibrated_set(result, base_name, args.file, command, base))
    constants = [{k: c[k] for k in ("name", "median", "p05", "p95", "post_median", "post_p05", "post_p95")}
                 for c in result.constants]
    rows_out = _rows(result.posterior_predictions)
    values = {"calibration_rows": settings["used"], "calibrated_constants": constants,
              "effective_sample_size": result.ess, "laboratory_rows": rows_out, "calibrated_set_file": str(out)}
    notes = [f"  {c['name']}: prior median {c['median']:.4g} [{c['p05']:.4g}, {c['p95']:.4g}] -> posterior "
             f"{c['post_median']:.4g} [{c['post_p05']:.4g}, {c['post_p95']:.4g}]" for c in constants]
    notes += _notes(rows_out)
    notes.append(f"  wrote {out}: use it with 'memstribo mesh --parameter-set {out}'")
    if result.ess < 5:
        notes.append(f"  the posterior rests on {result.ess:.1f} effective samples: raise --samples")
    return CommandResult(values=values, title=f"calibration on the measurements of {args.file} ({result.prior})",
                         notes=notes)
