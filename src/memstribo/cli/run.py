"""``memstribo run [CONFIG.toml] [--out DIR]``: the thesis case end to end, with report.html."""

from __future__ import annotations

import sys

from memstribo.cli.common import CommandResult, add_progress_argument, progress_enabled

NAME = "run"
HELP = "the main job: roughness -> nanoblocks -> meshing cycle -> sweeps -> coating -> wear -> damage, with report.html"
ORDER = 1

DESCRIPTION = """\
Run the thesis case end to end with the default parameters (or CONFIG.toml): roughness
(the default synthetic profile and any file the config names) -> nanoblock geometry ->
gear pair -> bare silicon meshing cycle -> load and area sweeps -> coated pair -> wear
sweep -> damage and lifetime. Writes datasets (NetCDF + CSV) to DIR/data, figures (PNG +
SVG) to DIR/figures, parameters.toml, references.txt, run.json and DIR/report.html; each
stage's files as soon as it finishes.

CONFIG.toml may hold parameter overrides ([parameters]) and a [run] table, e.g.
  [run]
  roughness_files = ["data/afm/si_profile_linescan.txt"]
  steps = 60
  loads = ["25 uN", "100 uN", "300 uN"]
  wear = [0.0, 0.5, 1.0]
  coating = "OTS"
  stages = ["roughness", "geometry", "gear", "mesh"]
See examples/run_thesis_case.toml.
"""


def register(subparsers, parents):
    import argparse

    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=DESCRIPTION,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("config_file", nargs="?", metavar="CONFIG.toml",
                        help="parameter overrides and a [run] table (optional)")
    parser.add_argument("--out", default="memstribo-results", metavar="DIR",
                        help="output folder (default: memstribo-results)")
    parser.add_argument("--steps", type=int, default=None, metavar="N",
                        help="positions along the path of contact per meshing simulation (overrides [run] steps)")
    parser.add_argument("--roughness", action="append", default=[], metavar="FILE",
                        help="a measured profile or AFM file to analyse as well (repeatable)")
    add_progress_argument(parser)
    parser.add_argument("--load-case", choices=("torque", "thesis"),
                        help="normal load of the meshing stages: 'torque' (F_t / cos alpha, default) or 'thesis' "
                             "(normal_load, 25 uN); the load sweep always uses the thesis case")
    parser.add_argument("--overwrite", action="store_true",
                        help="write into DIR although it holds an earlier run: the files its run.json lists are "
                             "deleted first; a DIR holding any other file, or an input of this run, is refused; "
                             "without it a non-empty DIR is refused")
    parser.add_argument("--resume", action="store_true",
                        help="continue the run in DIR (killed, or with failed stages): stages run.json records as "
                             "done are read back, not recomputed; failed and missing stages (and those after them "
                             "that use them) run again; give the same config and options as that run")
    # --quiet (no log lines on stderr, errors only) and --verbose (each stage's files): add_progress_argument
    parser.set_defaults(handler=run)


def run(args, params):
    from dataclasses import replace
    from pathlib import Path

    from memstribo.job.chain import RunChain
    from memstribo.job.options import RunOptions
    from memstribo.errors import InputError
    from memstribo.parameters import read_config

    table = dict(getattr(args, "config_tables", {}).get("run", {}))
    base = Path(args.config).parent if args.config else None
    if args.config_file:
        config = read_config(args.config_file)
        params = params.updated(config.pop("parameters"), origin=f"config file {args.config_file}")
        table.update(config.get("run", {}))
        base = Path(args.config_file).parent
        if args.overrides:  # --set wins over the config file
            from memstribo.parameters import parse_assignment

            params = params.updated(dict(parse_assignment(t) for t in args.overrides), origin="--set")
    if args.load_case:
        params = params.updated({"load_case": args.load_case}, origin="--load-case")
    options = RunOptions.from_table(table, base)
    if args.steps is not None:
        if args.steps < 3:
            raise InputError(f"--steps {args.steps}: give an integer >= 3 (a meshing cycle needs 3 positions).")
        options = replace(options, steps=args.steps)
    if args.roughness:
        extra = RunOptions.from_table({"roughness_files": args.roughness}, Path.cwd()).roughness_files
        options = replace(options, roughness_files=options.roughness_files + extra)
    progress = progress_enabled(args)
    from memstribo.job.folder import results_folder

    results_folder(args.out, "--out")  # '' would be the current folder
    if args.resume:
        if args.overwrite:
            raise InputError("--resume and --overwrite together: --resume continues the run in --out, --overwrite "
                             "starts it again from nothing; give one of them.")
        if not (Path(args.out) / "run.json").is_file():
            raise InputError(f"--resume: {args.out} holds no run.json (no run of memstribo to continue); run without "
                             "--resume.")
    else:
        # the run's input files: --overwrite must never delete one (issue #41)
        inputs = [*options.roughness_files, options.map, args.config_file, getattr(args, "config", None)]
        _prepare_folder(Path(args.out), args.overwrite, inputs)
    chain = RunChain(params, args.out, options, progress=progress, resume=args.resume)
    _configure_logging(args, progress)
    result = chain.run()
    failed = {s.name: s.message for s in result.stages if s.status == "failed"
              or (s.status == "skipped" and s.name in options.stages)}
    values = {"folder": str(result.folder), "report": str(result.folder / "report.html"),
              "elapsed": result.elapsed, "complete": result.ok and not failed,
              "stages": {s.name: s.status for s in result.stages}, "failed_stages": failed, **result.verdict}
    if args.resume:
        values["kept_stages"] = list(result.kept)
    notes = [f"  {s.name}: {s.status}{' - ' + s.message if s.message else ''}" for s in result.stages
             if s.status != "done" or s.message]
    if args.resume:
        notes.append(f"  resumed: kept {', '.join(result.kept) or 'no stage'} from the earlier run; ran the others again")
    notes.append(f"  open {result.folder / 'report.html'} in a browser")
    if failed:
        notes.append(f"  {len(failed)} requested stage(s) did not finish: exit status 1")
    return CommandResult(values=values, title="memstribo run: the thesis case end to end", notes=notes,
                         exit_status=1 if failed else 0)


def _prepare_folder(folder, overwrite: bool, inputs=()) -> None:
    """Refuse a non-empty results folder unless ``overwrite``; then delete the files its ``run.json`` lists.

    ``--overwrite`` deletes only what the earlier run's manifest lists as written by memstribo, and refuses
    (deleting nothing) a folder that holds any other file or one of ``inputs``, the new run's input files
    (:func:`memstribo.job.folder.clear_for_overwrite`): a results folder owns only what it wrote.
    """
    from memstribo.errors import InputError
    from memstribo.job.folder import clear_for_overwrite

    if not folder.exists():
        return
    if not folder.is_dir():
        raise InputError(f"--out {folder}: exists and is not a folder.")
    entries = sorted(p.name for p in folder.iterdir())
    if not entries:
        return
    if not overwrite:
        shown = ", ".join(entries[:5]) + (", ..." if len(entries) > 5 else "")
        raise InputError(f"--out {folder}: the folder is not empty ({shown}); give another folder or --overwrite "
                         "(stale files of an earlier run would otherwise sit beside the new report).")
    clear_for_overwrite(folder, inputs, "--out")


def _configure_logging(args, progress: bool) -> None:
    """One log line per stage on stderr off a terminal (the progress bar replaces them on one)."""
    import logging

    level = logging.ERROR if args.quiet else (logging.DEBUG if args.verbose else logging.INFO)
    if progress and not args.verbose:
        level = logging.WARNING
    logger = logging.getLogger("memstribo")
    logger.setLevel(level)
    if not any(isinstance(h, _StderrHandler) for h in logger.handlers):
        handler = _StderrHandler()
        handler.setFormatter(logging.Formatter("memstribo run: %(message)s"))
        logger.addHandler(handler)


def _stderr_handler_class():
    import logging

    class StderrHandler(logging.StreamHandler):
        """Writes to whatever ``sys.stderr`` is at the time of the record (not the one at creation)."""

        @property
        def stream(self):
            return sys.stderr

        @stream.setter
        def stream(self, value):  # StreamHandler.__init__ sets it; the property always follows sys.stderr
            pass

    return StderrHandler


_StderrHandler = _stderr_handler_class()
