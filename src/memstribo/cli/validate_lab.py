"""``memstribo validate-lab``: published MEMS measurements predicted with their uncertainty (issue 28, MODEL 7e)."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "validate-lab"
HELP = ("predict published MEMS friction and adhesion measurements at their conditions (median, 90 %% band), "
        "calibrate on the declared rows, and say which lie inside")
ORDER = 95


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP.replace("%%", "%") + ". The rows are "
                                   "src/memstribo/laboratory/measurements.toml; the page is docs/experiments.md.")
    parser.add_argument("--write", metavar="FILE", default=None,
                        help="also write the page (docs/experiments.md), its figure and the calibrated parameter set")
    parser.set_defaults(handler=run)


def run(args, params):
    from memstribo.laboratory.report import COMMAND, run_all, write

    res = write(args.write, None) if args.write else run_all()
    result = res["result"]
    rows = []
    for p in res["nominal"]:
        entry = {"id": p.id, "quantity": p.quantity, "measured": p.measured, "status": p.status}
        if p.status == "predicted":
            entry.update({"median": p.median, "low": p.low, "high": p.high, "inside": bool(p.inside)})
        else:
            entry["reason"] = p.reason
        rows.append(entry)
    values = {
        "laboratory_rows": rows,
        "held_out_inside_before": result.held_out_before["inside"],
        "held_out_inside_after": result.held_out_after["inside"],
        "held_out_predicted": result.held_out_before["predicted"],
        "effective_sample_size": result.ess,
    }
    notes = [f"  {r['id']}: measured {r['measured']:.3g}, "
             + (f"predicted {r['median']:.3g} [{r['low']:.3g}, {r['high']:.3g}] {'inside' if r['inside'] else 'outside'}"
                if r["status"] == "predicted" else f"not predicted ({r['reason']})") for r in rows]
    if args.write:
        notes.append(f"  wrote {args.write} and its figure; the calibrated parameter set is written by '{COMMAND}'")
    return CommandResult(values=values, title="published MEMS measurements against the model (docs/experiments.md)", notes=notes)
