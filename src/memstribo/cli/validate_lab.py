"""``memstribo validate-lab [FILE]``: measurements predicted with their uncertainty (issue 28, 37; MODEL 7e).

Without FILE: the packaged published measurements, predicted and calibrated on their declared rows. With FILE: a
lab's own measurements (a TOML file of ``[[measurement]]`` tables, :mod:`memstribo.laboratory.user`), predicted at
their conditions. ``--parameter-set``, ``--config`` and ``--set`` are honoured: every row starts from that set (with
the row's environment, humidity, materials and coating on top) instead of the lab's rule (silicon_oxide_air in air,
silicon_thesis otherwise); on the packaged set they give the nominal predictions without the calibration.
"""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "validate-lab"
HELP = ("predict MEMS friction and adhesion measurements at their conditions (median, 90 %% band): the packaged "
        "published ones (and calibrate on the declared rows), or your own from a TOML file")
ORDER = 95


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP.replace("%%", "%") + ". The "
                                   "packaged rows are src/memstribo/laboratory/measurements.toml; the page is "
                                   "docs/experiments.md; a user file has the same [[measurement]] tables (see "
                                   "examples/own_measurement.toml).")
    parser.add_argument("file", nargs="?", metavar="FILE.toml", default=None,
                        help="your own measurements ([[measurement]] tables); default: the packaged published set")
    parser.add_argument("--realisations", type=int, default=4, metavar="N",
                        help="roughness realisations per row for FILE (default 4)")
    parser.add_argument("--write", metavar="FILE", default=None,
                        help="also write the page (docs/experiments.md), its figure and the calibrated parameter set "
                             "(packaged set only)")
    parser.set_defaults(handler=run)


def user_base(args, params):
    """The parameters every row starts from: ``params`` when the command line gave --parameter-set, --config or
    --set; None (the lab's rule) otherwise."""
    from memstribo.cli.main import _Parser

    given = any(str(a).startswith("--parameter-set") for a in _Parser.argv)
    return params if given or args.overrides or args.config else None


def _rows(predictions):
    rows = []
    for p in predictions:
        entry = {"id": p.id, "quantity": p.quantity, "measured": p.measured, "status": p.status}
        if p.status == "predicted":
            entry.update({"median": p.median, "low": p.low, "high": p.high, "inside": bool(p.inside)})
        else:
            entry["reason"] = p.reason
        rows.append(entry)
    return rows


def _notes(rows):
    return [f"  {r['id']}: measured {r['measured']:.3g}, "
            + (f"predicted {r['median']:.3g} [{r['low']:.3g}, {r['high']:.3g}] {'inside' if r['inside'] else 'outside'}"
               if r["status"] == "predicted" else f"not predicted ({r['reason']})") for r in rows]


def run(args, params):
    from memstribo.errors import InputError
    from memstribo.laboratory.predict import predict_all

    base = user_base(args, params)
    if args.realisations < 1:
        raise InputError(f"--realisations must be at least 1, got {args.realisations}.")
    if args.file:
        from memstribo.laboratory.user import load_user_measurements

        if args.write:
            raise InputError("--write regenerates the packaged page; it does not take a FILE.")
        measured = load_user_measurements(args.file, base)
        rows = _rows(predict_all(measured, [{}], args.realisations, base=base))
        start = base.name + " with the command line's values" if base is not None else "the lab's rule"
        return CommandResult(values={"laboratory_rows": rows}, title=f"measurements of {args.file} against the model",
                             notes=_notes(rows) + [f"  every row starts from {start}"])
    if base is not None:
        from memstribo.laboratory.data import load_measurements

        if args.write:
            raise InputError("--write regenerates the packaged page with the packaged sets; it does not take "
                             "--parameter-set, --config or --set.")
        rows = _rows(predict_all(load_measurements(), [{}], args.realisations, base=base))
        return CommandResult(values={"laboratory_rows": rows},
                             title="published MEMS measurements against the model, from the given parameters",
                             notes=_notes(rows) + [f"  every row starts from {base.name} with the command line's "
                                                   "values; nominal constants, no calibration (the page's calibration "
                                                   "is of the packaged sets)"])
    return _packaged(args)


def _packaged(args):
    from memstribo.laboratory.report import COMMAND, run_all, write

    res = write(args.write, None) if args.write else run_all()
    result = res["result"]
    rows = _rows(res["nominal"])
    values = {
        "laboratory_rows": rows,
        "held_out_inside_before": result.held_out_before["inside"],
        "held_out_inside_after": result.held_out_after["inside"],
        "held_out_predicted": result.held_out_before["predicted"],
        "effective_sample_size": result.ess,
    }
    notes = _notes(rows)
    if args.write:
        notes.append(f"  wrote {args.write} and its figure; the calibrated parameter set is written by '{COMMAND}'")
    return CommandResult(values=values, title="published MEMS measurements against the model (docs/experiments.md)",
                         notes=notes)
