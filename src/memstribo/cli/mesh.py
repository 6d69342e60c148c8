"""``memstribo mesh``: friction, adhesion, COF and stiction of rough silicon teeth over one meshing cycle."""

from __future__ import annotations


import argparse

from memstribo.cli.common import CommandResult, add_progress_argument, progress_enabled

NAME = "mesh"
HELP = "meshing-cycle simulation: friction, adhesion, COF and its split, stiction margin (thesis 4.6-4.9)"
ORDER = 50

MESH_KEYS = ("load_case", "interface_model", "contact_adhesion", "cof_mean", "cof_max", "cof_chemical", "cof_vdw",
             "cof_elastic", "friction_force_mean", "friction_force_max", "resisting_force_max", "adhesion_force_mean",
             "normal_force_max", "tangential_force", "verdict", "stiction", "stiction_margin", "mesh_efficiency",
             "steps",
             "sliding_distance", "roughness_rows", "max_shear_stress", "warnings")

#: the samples that share a contact solve without ``--solve-sets`` (the main job's,
#: :data:`memstribo.job.workers.RUN_SOLVE_SETS`): pairs, half the solves; the interval carries the design effect
#: (issue 40; docs/uncertainty.md)
DEFAULT_SOLVE_SETS = "pairs"

#: Keys of the ensemble verdict (``--realisations N``).
ENSEMBLE_KEYS = ("realisations", "stiction_probability", "stiction_margin_median", "stiction_margin_p05",
                 "stiction_margin_p95", "cof_mean_median", "cof_mean_p05", "cof_mean_p95", "mesh_efficiency_median",
                 "mesh_efficiency_p05", "mesh_efficiency_p95", "per_realisation")

#: ... and of its start-up verdict (MODEL 7d).
STARTUP_ENSEMBLE_KEYS = ("startup_stiction_probability", "startup_stiction_count", "startup_stiction_probability_ci",
                         "startup_stiction_probability_text", "startup_margin_median", "startup_margin_p05",
                         "startup_margin_p95")


def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP,
        description=HELP + ". The rough contact is solved at every step along the whole path of contact with the "
        "load-sharing function; nanoblocks tile both flanks, every row with its own roughness. The default load case "
        "'torque' loads the teeth with F_n = F_t / cos(alpha) from the drive torque; '--load-case thesis' uses "
        "normal_load (25 µN). The verdict compares F_t with R(c), the friction of all pairs in mesh.")
    add_common_arguments(parser)
    parser.add_argument("--realisations", type=int, metavar="N",
                        help="independent roughness realisations: the verdict as a stiction probability with "
                             "5-95 %% bands (default: the parameter realisations, 1)")
    parser.add_argument("--scheduler", metavar="ADDRESS", help="run the realisations on a dask.distributed scheduler")
    parser.add_argument("--uncertainty", metavar="N|auto",
                        help="the verdict over what nobody measured (MODEL 7d): N samples of roughness realisations x "
                             "constants drawn from their priors ('memstribo parameters' lists them), or 'auto' (until "
                             "the 95 %% interval's half-width is below 0.05, at most 1024); reports P(stiction) with "
                             "its interval, the constants ranked by the regional index of the verdict and the "
                             "critical values of the rescaled ones (tens of cycles); --sobol adds the Sobol' design")
    parser.add_argument("--fix", action="append", default=[], metavar="NAME[,NAME]",
                        help="with --uncertainty: keep these constants at their value (each must have a prior; "
                             "--set NAME=VALUE fixes one at another value)")
    parser.add_argument("--sobol", action="store_true",
                        help="with --uncertainty: also the Sobol' indices of the margin and the COF (Saltelli's "
                             "design), every decisive constant's critical value, whether one alone flips the verdict "
                             "at the end of its prior, and the robust-Bayes bands (hundreds of cycles)")
    parser.add_argument("--sobol-samples", type=int, metavar="N",
                        help="with --uncertainty (implies --sobol): base samples of the Sobol' design, a power of two "
                             "(default 32): N x (constants + 3) cycles or rescalings")
    parser.add_argument("--solve-sets", metavar="G|pairs|all",
                        help="with --uncertainty: the constants that need a contact solve take G values per "
                             "realisation, the bond energies keep every set's ('pairs', the default: one solve per two "
                             "sets; 'all': every constant set solved apart, the default with --calibration); the "
                             "interval is widened by the design effect of the samples that share a solve, and a "
                             "design that widens it beyond the precision asked says so")
    parser.add_argument("--regional", action="store_true",
                        help="with --uncertainty: the regional analysis (the default; kept for scripts): refused "
                             "with --sobol")
    parser.add_argument("--calibration", metavar="FILE.toml",
                        help="with --uncertainty: P(stiction) and P(start-up stiction) also under the posterior of "
                             "FILE (a measurements TOML, or a calibrated parameter set with [posterior.NAME]), by "
                             "importance weights on the same samples, beside the prior's; names the rows that moved it")
    parser.add_argument("--workers", type=int, metavar="N",
                        help="with --uncertainty or --realisations: run the cycles on a local Dask cluster of N "
                             "worker processes")
    parser.add_argument("--refine", "--step-check", dest="refine", action=argparse.BooleanOptionalAction,
                        default=True,
                        help="the self-refining cycle (MODEL 7d): compare with twice the steps, then with twice the "
                             "grid's resolution, refining until the margin (of |margin|) and the mean COF change by "
                             "less than 2 %%, at most mesh_step_refinements and mesh_grid_refinements times; reports "
                             "converged, step_change_*, grid_change_* (default: on; --no-refine: one cycle as asked)")
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
    parser.add_argument("--contact", choices=("line", "surface"),
                        help="contact solve per step: 'line' (one line contact per nanoblock row, default) or "
                             "'surface' (the face width's strip as one surface contact: rows interact); sets the "
                             "parameter mesh_contact")
    parser.add_argument("--sliding-axis", choices=("x", "y"), default="x",
                        help="axis of a 2D map along the flank (the sliding direction): x = the scan lines "
                             "(default), y = the map's columns")
    parser.add_argument("--load-case", choices=("torque", "thesis"),
                        help="normal load: 'torque' (F_t / cos alpha from the drive torque, default) or 'thesis' "
                             "(normal_load as given, 25 µN); sets the parameter load_case")
    parser.add_argument("--wear", type=float, default=None, metavar="OMEGA",
                        help="worn fraction of the gear's coating, 0 (intact) .. 1 (bare), with --coating (default: "
                             "the parameter coating_wear, 0)")
    add_progress_argument(parser)


def simulation_options(args, params=None):
    """Keyword arguments of :func:`memstribo.simulations.mesh.simulate_mesh` from the command line."""
    from memstribo.errors import InputError

    from memstribo.checks import check_coating_wear, check_mesh_arguments, coating_wear_of

    coating = None
    if params is not None:
        check_coating_wear(params, args.coating)
    if args.coating:
        from memstribo.physics.coating import get_coating

        coating = get_coating(args.coating, params)
    elif args.wear is not None and args.wear != 1.0:
        raise InputError("--wear needs --coating (bare silicon has no coating to wear).")
    if args.steps is not None and args.steps < 3:
        raise InputError(f"--steps must be at least 3, got {args.steps}.")
    check_mesh_arguments(params, args.steps, 1, 1.0 if args.wear is None else args.wear)
    # --wear, else the parameter coating_wear (it was ignored: a coated cycle ran at Omega = 1, issue #41)
    wear = coating_wear_of(params, args.coating, args.wear) if params is not None else \
        (1.0 if args.wear is None else args.wear)
    progress = progress_enabled(args)
    return dict(steps=args.steps, coating=coating, wear=wear, progress=progress)


def roughness_of(args):
    """The roughness the command line names, read once and turned along the sliding axis (None: the default)."""
    from memstribo.simulations.mesh import _read_roughness

    return _read_roughness(None if args.roughness in (None, "thesis") else args.roughness,
                           getattr(args, "sliding_axis", "x"))


def apply_load_case(args, params):
    """The parameter set with ``--load-case`` and ``--contact`` applied (unchanged without them)."""
    if getattr(args, "load_case", None):
        params = params.updated({"load_case": args.load_case}, origin="--load-case")
    if getattr(args, "contact", None):
        params = params.updated({"mesh_contact": args.contact}, origin="--contact")
    return params


def run(args, params):
    from memstribo.errors import InputError
    from memstribo.simulations.mesh import SUMMARY_UNITS, simulate_mesh, summarize
    from memstribo.simulations.mesh.convergence import refined_cycle, settings_of

    params = apply_load_case(args, params)
    options = simulation_options(args, params)
    uncertainty = _uncertainty_option(args)
    realisations = params["realisations"] if args.realisations is None else args.realisations
    from memstribo.parameters.definitions import SPECS

    spec = SPECS["realisations"]
    if not spec.minimum <= realisations <= spec.maximum:
        raise InputError(f"--realisations must be from {int(spec.minimum):,} to {int(spec.maximum):,} (the bounds "
                         f"of the parameter realisations), got {realisations:,}.")
    _check_parallel(args, uncertainty, realisations)
    if uncertainty is not None:
        _check_study(args, params, options, uncertainty, realisations)
    roughness = roughness_of(args)
    if args.refine:  # the finest cycle of the self-refining one, and its checks (MODEL 7d)
        dataset, summary = refined_cycle(params, roughness, **options)
        if uncertainty is None:  # the ensemble runs at the settings reached (the uncertainty study at those asked)
            params, options["steps"] = settings_of(params, summary)
    else:
        dataset = simulate_mesh(params, roughness, **options)
        summary = summarize(dataset)
    values = {key: summary[key] for key in MESH_KEYS}
    values.update({key: summary[key] for key in summary if key not in MESH_KEYS})
    if summary["verdict"] == "undetermined":  # no COF or margin presented as a result (issue #25)
        values.update({key: None for key in values if key.startswith("cof_") or key == "stiction_margin"})
    study = None
    if uncertainty is not None:
        shown, study = _uncertainty(args, params, roughness, options, uncertainty, realisations)
        values.update(shown)
    elif realisations > 1:
        values.update(_ensemble(args, params, roughness, options, realisations))
    notes = [
        f"  load case '{summary['load_case']}': normal force {summary['normal_force_total'] * 1e3:.4g} mN on the "
        f"teeth, F_t {summary['tangential_force'] * 1e3:.4g} mN"
        + (" (the thesis's F_ext: not the normal force the torque implies)" if summary["load_case"] == "thesis" else ""),
        (f"  verdict: UNDETERMINED: {summary['undetermined_reason']}" if summary["verdict"] == "undetermined" else
         f"  verdict: {'STICTION' if summary['stiction'] else 'no stiction'}: largest resisting force R(c) "
         f"{summary['resisting_force_max'] * 1e3:.4g} mN (friction of every pair in mesh) against F_t "
         f"{summary['tangential_force'] * 1e3:.4g} mN, margin {summary['stiction_margin'] * 1e3:+.4g} mN"),
        f"  start-up verdict (every bond formed after a dwell, MODEL 7d): "
        f"{'STICTION' if summary['startup_stiction'] else 'starts'}: start-up margin "
        f"{summary['startup_margin'] * 1e3:+.4g} mN, largest start-up COF {summary['static_cof_max']:.3g}; "
        f"stiction_mode '{summary['stiction_mode']}'",
        f"  interface: vdW '{summary['interface_model']}', contact adhesion '{summary['contact_adhesion']}'; "
        f"rows: {summary['roughness_rows']}",
        f"  roughness: {dataset.attrs['roughness']}"
        + (" (synthetic: the thesis's scan is not published)" if dataset.attrs["roughness_synthetic"] else ""),
        f"  block loads: {dataset.attrs['block_load_variant']}",
        f"  {dataset.attrs['rows']} rows of nanoblocks across the face width; contact grid "
        f"{dataset.attrs['grid_spacing'] * 1e9:.3g} nm over a {dataset.attrs['window'] * 1e6:.3g} µm window",
        f"  Dundurs beta {dataset.attrs['dundurs_beta']:.3g}: "
        + ("identical materials, one pass is exact" if dataset.attrs["dundurs_beta"] == 0
           else f"F_t/F_f iteration, {dataset.attrs['friction_passes']} passes"),
    ]
    if "converged" in values:
        notes.append(f"  {'converged' if values['converged'] else 'NOT converged'} (MODEL 7d: margin within 2 % of "
                     f"|margin|, mean COF within 2 %): {values['steps']} steps, {values['elements_across_contact']} "
                     "elements across 2a; " + "; ".join(values["refinement"] or ["no check"]))
    if "uncertainty_samples" in values:  # the study's keys that only the JSON carries are read in words here
        notes.extend(uncertainty_notes({**(study or {}), **values}))
    elif "stiction_probability" in values:
        notes.append(f"  ensemble of {values['realisations']} roughness realisations: stiction probability "
                     f"{values['stiction_probability_text']}, margin {values['stiction_margin_p05'] * 1e3:+.3g} .. "
                     f"{values['stiction_margin_p95'] * 1e3:+.3g} mN (5-95 %), mean COF {values['cof_mean_p05']:.3g} .. "
                     f"{values['cof_mean_p95']:.3g}"
                     + (f"; start-up stiction probability {values['startup_stiction_probability_text']}"
                        if "startup_stiction_probability_text" in values else ""))
    for text in summary["warnings"]:
        notes.append(f"  WARNING: {text}.")
    if args.out:
        from pathlib import Path

        from memstribo.output import provenance_attributes

        roughness = args.roughness if Path(str(args.roughness)).is_file() else dataset.attrs.get("roughness_source")
        notes.extend(write_outputs(dataset, args.out, provenance_attributes(
            params, roughness=roughness, extra={"command": "memstribo mesh",
                                                "models": "memstribo.simulations.mesh.simulate_mesh (thesis 4.6-4.9)"})))
        if study is not None:
            from memstribo.uncertainty.figures import write_figures

            notes.append("  wrote " + ", ".join(str(path) for path in write_figures(study, args.out)))
    return CommandResult(values=values, units=dict(SUMMARY_UNITS), title="meshing cycle (thesis 4.6-4.9)",
                         notes=notes)


def _ensemble(args, params, roughness, options, realisations) -> dict:
    """``--realisations N``: the ensemble verdict's keys, with the interval of its probability (MODEL 7d)."""
    from memstribo.job.workers import ENSEMBLE_REALISATIONS
    from memstribo.simulations.mesh import simulate_ensemble
    from memstribo.uncertainty.intervals import ensemble_interval

    client = _client(args, realisations, ENSEMBLE_REALISATIONS)
    try:
        ensemble = simulate_ensemble(params, roughness, realisations=realisations, steps=options["steps"],
                                     coating=options["coating"], wear=options["wear"], client=client,
                                     progress=options["progress"])
    finally:
        _close(client, args)
    ensemble = ensemble_interval(ensemble)  # no probability without its interval
    keys = ENSEMBLE_KEYS + ENSEMBLE_INTERVAL_KEYS + STARTUP_ENSEMBLE_KEYS
    return {key: ensemble[key] for key in keys if key in ensemble}


#: Keys the ensemble verdict gains from :func:`memstribo.uncertainty.intervals.ensemble_interval`.
ENSEMBLE_INTERVAL_KEYS = ("stiction_count", "stiction_probability_ci", "stiction_probability_text")

#: Keys of the uncertainty study (``--uncertainty``) in the JSON, from
#: :func:`memstribo.uncertainty.study.uncertainty_study` (``samples`` as ``uncertainty_samples``,
#: ``dominant`` as ``dominant_constant``).
UNCERTAINTY_KEYS = ("stiction_probability", "stiction_probability_ci", "stiction_count", "uncertainty_samples",
                    "stiction_probability_text", "stiction_probability_nominal", "stiction_probability_nominal_ci",
                    "stiction_probability_nominal_text", "realisations", "constant_sets", "margin_quantiles",
                    "margin_quantiles_nominal", "startup_margin_quantiles", "cof_quantiles", "cof_split_quantiles",
                    "sensitivity", "dominant_constant", "designer_sentence", "sampled_constants", "fixed_constants",
                    "unconverged_samples", "failed_samples", "priors", "solve_sets", "design_effect",
                    "effective_samples", "sobol_design", "decision_sensitivity", "decision_design",
                    "flipping_constants", "flipping_constants_startup", "robust_bayes", "prior_dominated",
                    "prior_dominated_constants", "decision_sentence", "decision_depth", "sensitivity_method",
                    "margin_correlation", "dominant_entry", "nominal_cycles_reused",
                    # the start-up verdict over the priors (MODEL 7f, issue #35)
                    "startup_stiction_probability", "startup_stiction_probability_ci", "startup_stiction_count",
                    "startup_stiction_probability_text", "startup_stiction_probability_nominal",
                    "startup_stiction_probability_nominal_ci", "startup_stiction_probability_nominal_text")


#: the analysis without ``--sobol``: the main job's (:data:`memstribo.job.workers.RUN_DECISION`, ``RUN_CRITICAL``)
REGIONAL = {"sensitivity": "regional", "critical": "rescaled", "decision": {"depth": "regional"}}

#: Keys only the JSON carries (the readable output gives them as notes).
UNCERTAINTY_JSON_ONLY = ("priors", "sensitivity", "cof_split_quantiles", "sampled_constants",
                         "margin_quantiles_nominal", "sobol_design", "decision_sensitivity", "decision_design",
                         "robust_bayes", "decision_sentence", "margin_correlation", "dominant_entry")


def _uncertainty_option(args):
    """``--uncertainty``: None, ``"auto"`` or a sample count; the options that need it are refused without it."""
    from memstribo.errors import InputError

    text = getattr(args, "uncertainty", None)
    if text is None:
        if getattr(args, "fix", None) or getattr(args, "sobol_samples", None) is not None \
                or getattr(args, "solve_sets", None) is not None or getattr(args, "calibration", None) \
                or getattr(args, "regional", False) or getattr(args, "sobol", False):
            raise InputError("--fix, --sobol, --sobol-samples, --solve-sets, --regional and --calibration need "
                             "--uncertainty N|auto.")
        return None
    if getattr(args, "regional", False) and (getattr(args, "sobol_samples", None) is not None
                                             or getattr(args, "sobol", False)):
        raise InputError("--regional has no Sobol' design: drop --sobol/--sobol-samples (or --regional).")
    _solve_sets(args)  # a bad value is refused before the first cycle
    from memstribo.uncertainty.study import check_sobol_samples

    check_sobol_samples(getattr(args, "sobol_samples", None), "--sobol-samples")  # before the first cycle
    text = str(text).strip().lower()
    if text == "auto":
        return "auto"
    try:
        n = int(text)
    except ValueError:
        raise InputError(f"--uncertainty expects a number of samples or 'auto', got '{text}'.") from None
    if n < 1:
        raise InputError(f"--uncertainty must be at least 1 sample, got {n}.")
    return n


def _solve_sets(args):
    """``--solve-sets``: an int >= 1, "pairs", or None for 'all' (every set solved apart); default
    :data:`DEFAULT_SOLVE_SETS`, or 'all' with ``--calibration`` (the posterior's weights do not carry the design
    effect of samples that share a solve)."""
    from memstribo.errors import InputError

    text = getattr(args, "solve_sets", None)
    if text is None:
        return None if getattr(args, "calibration", None) else DEFAULT_SOLVE_SETS
    text = str(text).strip().lower()
    if text == "all":
        return None
    if text == "pairs":
        return "pairs"
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise InputError("--solve-sets expects a whole number >= 1 (distinct solves per realisation), 'pairs' or "
                         f"'all', got '{text}'.")
    return value


def _analysis(args) -> dict:
    """The study's analysis options: the Sobol' design with ``--sobol`` or ``--sobol-samples``, else
    :data:`REGIONAL`."""
    if getattr(args, "sobol", False) or getattr(args, "sobol_samples", None) is not None:
        return {"sobol_samples": args.sobol_samples}
    return dict(REGIONAL)


#: most worker processes ``--workers`` may ask for (as ``study`` and ``map``)
MAX_WORKERS = 4096


def machine_cores() -> int:
    """The cores this process may run on (:func:`memstribo.job.workers.machine_cores`)."""
    from memstribo.job.workers import machine_cores as cores

    return cores()


def _check_parallel(args, uncertainty, realisations) -> None:
    """``--workers`` and ``--scheduler`` only with work to share (issue #41), ``--workers`` within its bounds.

    One realisation without ``--uncertainty`` is one cycle in this process: the options would be ignored, so
    they are refused. ``--workers`` above :data:`MAX_WORKERS` is refused; above the machine's cores it is
    capped at them with a note on stderr (more processes than cores only share them).
    """
    from memstribo.errors import InputError

    workers, scheduler = getattr(args, "workers", None), getattr(args, "scheduler", None)
    if workers is None and not scheduler:
        return
    option = f"--workers {workers}" if workers is not None else f"--scheduler {scheduler}"
    if workers is not None and scheduler:
        raise InputError(f"--workers {workers} and --scheduler {scheduler} contradict each other: --workers starts a "
                         "local cluster, --scheduler uses an existing one; give one of them.")
    if uncertainty is None and realisations <= 1:
        raise InputError(f"{option} shares realisations or uncertainty samples between workers, but this run has one "
                         "realisation and no --uncertainty (one cycle, run in this process): add --realisations N "
                         f"(N > 1) or --uncertainty N|auto, or drop {option.split()[0]}.")
    if workers is None:
        return
    if workers < 1 or workers > MAX_WORKERS:
        raise InputError(f"--workers must be from 1 to {MAX_WORKERS:,} worker processes, got {workers:,}.")
    args.workers = cap_workers(workers, "mesh", quiet=getattr(args, "quiet", False))


def cap_workers(workers, command: str, quiet: bool = False):
    """``workers`` capped at the machine's cores (:func:`machine_cores`), with a note on stderr where it is (more
    processes than cores only share them); None stays None (issue 40)."""
    import sys

    if workers is None:
        return None
    cores = machine_cores()
    if workers > cores:
        if not quiet:
            print(f"memstribo {command}: note: --workers {workers:,} is more than this machine's {cores} core(s): "
                  f"using {cores} worker processes.", file=sys.stderr)
        return cores
    return workers


def _client(args, cycles=None, threshold=None):
    """A Dask client: --scheduler ADDRESS, or a local cluster of --workers N processes; without either, a local
    cluster of the machine's cores for ``cycles`` cycles from ``threshold`` on where dask.distributed is installed
    (issue 40 item 4: the run's rule, :func:`memstribo.job.workers.stage_cluster`, said on stderr), or None."""
    from memstribo.simulations.study import require_dask

    if getattr(args, "scheduler", None):
        require_dask("--scheduler")
        from distributed import Client

        return Client(args.scheduler)
    if getattr(args, "workers", None):
        from memstribo.errors import InputError

        if args.workers < 1:
            raise InputError(f"--workers must be at least 1, got {args.workers}.")
        require_dask("--workers")
        from distributed import Client

        from memstribo.simulations.study import local_cluster

        return Client(local_cluster(args.workers))
    if cycles is None:
        return None
    from memstribo.job.workers import stage_cluster

    cluster = stage_cluster(cycles, "mesh", threshold)
    if cluster is None:
        return None
    from distributed import Client

    if not getattr(args, "quiet", False):
        import sys

        print(f"memstribo mesh: note: the cycles run on {len(cluster.workers)} worker processes (this machine's "
              "cores, one BLAS thread each); --workers N sets their number.", file=sys.stderr)
    return Client(cluster, set_as_default=False)


def _close(client, args) -> None:
    """Close a client of :func:`_client`, and the local cluster it started (--workers, or the machine's cores)."""
    if client is None:
        return
    cluster = getattr(client, "cluster", None)
    client.close()
    if cluster is not None and not getattr(args, "scheduler", None):
        cluster.close()


def _fixed(args) -> list[str]:
    """The constants of ``--fix``."""
    return [name.strip() for item in args.fix for name in item.split(",") if name.strip()]


def _check_study(args, params, options, samples, realisations) -> None:
    """Refuse what the study would refuse (its sample count, a constant fixed twice, a bad calibration file) before
    the first cycle and before a cluster starts."""
    from memstribo.errors import InputError
    from memstribo.uncertainty.study import DEFAULT_BUDGET, DEFAULT_REALISATIONS, _check_samples

    count = DEFAULT_BUDGET if samples == "auto" else int(samples)
    _check_samples(samples, realisations if args.realisations is not None else min(DEFAULT_REALISATIONS, count),
                   int(options["steps"] or params["mesh_steps"]))
    for name in _fixed(args):
        if name in params and params.source(name) in ("--set",) or str(params.source(name) if name in params
                                                                         else "").startswith("config file"):
            raise InputError(f"the constant '{name}' is named twice: --fix {name} and a value given by "
                             f"{params.source(name)} (a given value is already fixed; drop --fix {name}).")
    if getattr(args, "calibration", None):
        from memstribo.laboratory.posterior import calibration_kind

        calibration_kind(args.calibration)


def _uncertainty(args, params, roughness, options, samples, realisations):
    """Run :func:`memstribo.uncertainty.study.uncertainty_study` for ``--uncertainty``: (its keys shown, the result)."""
    from memstribo.uncertainty.study import uncertainty_study

    fixed = _fixed(args)
    calibration = getattr(args, "calibration", None)
    from memstribo.job.workers import PARALLEL_SAMPLES
    from memstribo.uncertainty.study import DEFAULT_BUDGET

    client = _client(args, DEFAULT_BUDGET if samples == "auto" else int(samples), PARALLEL_SAMPLES)
    try:
        result = uncertainty_study(params, roughness, samples=samples, keep_samples=bool(calibration),
                                   realisations=None if args.realisations is None else realisations,
                                   steps=options["steps"], coating=options["coating"], wear=options["wear"],
                                   client=client, progress=options["progress"], fixed=fixed,
                                   solve_sets=_solve_sets(args), **_analysis(args))
    finally:
        _close(client, args)
    result["uncertainty_samples"] = result.pop("samples")
    result["dominant_constant"] = result.pop("dominant")
    if calibration:
        result.update(_posterior(calibration, result, options))
    shown = UNCERTAINTY_KEYS if getattr(args, "json", False) else \
        [key for key in UNCERTAINTY_KEYS if key not in UNCERTAINTY_JSON_ONLY]  # the notes give them in words
    shown = list(shown) + [key for key in POSTERIOR_KEYS if key in result]
    return {key: result[key] for key in shown if key in result}, result


#: Keys of ``--calibration`` (:func:`memstribo.laboratory.posterior.gear_posterior`) in the output.
POSTERIOR_KEYS = ("posterior_stiction_probability", "posterior_stiction_probability_ci",
                  "posterior_startup_stiction_probability", "posterior_startup_stiction_probability_ci",
                  "posterior_effective_samples", "posterior_calibration", "posterior_moved_by")


def _posterior(calibration, result, options) -> dict:
    """The study's samples re-weighted by ``--calibration`` (:func:`memstribo.laboratory.posterior.gear_posterior`)."""
    from memstribo.laboratory.posterior import gear_posterior

    points, summaries = result.pop("sample_points"), result.pop("sample_summaries")
    coating = options.get("coating")
    post = gear_posterior(calibration, points, summaries, _study_priors(result),
                          coating=getattr(coating, "name", coating) or "OTS")
    out = {"posterior_effective_samples": post["posterior_effective_samples"],
           "posterior_calibration": post["calibration"]["file"],
           "posterior_moved_by": post["moved_by"], "_posterior": post}
    for key in ("stiction", "startup_stiction"):
        if key in post["posterior"]:
            out[f"posterior_{key}_probability"] = post["posterior"][key]["probability"]
            out[f"posterior_{key}_probability_ci"] = post["posterior"][key]["ci"]
    return out


def _study_priors(result):
    """The study's priors as Prior objects (from its ``priors`` entries)."""
    from memstribo.uncertainty.priors import Prior

    return {name: Prior(**entry) for name, entry in (result.get("priors") or {}).items()}


def uncertainty_notes(values) -> list[str]:
    """The readable lines of an uncertainty study: probabilities with intervals, ranking, critical values."""
    notes = [f"  P(stiction) = {values['stiction_probability_text']} over {values['realisations']} roughness "
             f"realisations x {values['constant_sets']} sets of the uncertain constants",
             f"  P(stiction) at nominal constants = {values['stiction_probability_nominal_text']}"]
    if "startup_stiction_probability_text" in values:
        notes.append(f"  P(start-up stiction) = {values['startup_stiction_probability_text']} (at nominal constants "
                     f"{values['startup_stiction_probability_nominal_text']})")
    q = values.get("margin_quantiles")
    if q:
        notes.append(f"  margin 5/50/95 %: {q['p05'] * 1e3:+.3g} / {q['p50'] * 1e3:+.3g} / {q['p95'] * 1e3:+.3g} mN")
    ranked = [(name, entry) for name, entry in values.get("sensitivity", {}).items()]
    if ranked:
        design = values.get("sobol_design") or {}
        base = f", {design['base_samples']} base samples" if design.get("base_samples") else ""
        notes.append(f"  what the margin hangs on (Sobol' total index [95 % bootstrap interval]{base}, inside [0, 1]; "
                     "critical value):")
        for name, entry in ranked[:6]:
            critical = entry.get("critical_value")
            crit = (f"critical {critical:.4g}" if critical is not None
                    else (entry.get("note") or ""))
            notes.append(f"    {name:<24} {entry['total']:.2f} [{entry['total_ci'][0]:.2f}, {entry['total_ci'][1]:.2f}]"
                         f"  {crit}")
    notes.extend(decision_notes(values))
    if values.get("_posterior"):
        from memstribo.laboratory.posterior import posterior_notes

        notes.extend(posterior_notes(values["_posterior"]))
    if values.get("designer_sentence"):
        notes.append(f"  {values['designer_sentence']}")
    if values.get("decision_sentence"):
        notes.append(f"  {values['decision_sentence']}")
    return notes


def decision_notes(values) -> list[str]:
    """The readable lines of the decision's sensitivity (MODEL 7h): the regional index of the verdict, the verdict at
    each end of every prior, and the robust-Bayes bands."""
    decision = values.get("decision_sensitivity") or {}
    notes = []
    if decision:
        design = values.get("decision_design") or {}
        notes.append(f"  what the verdict hangs on (KS distance of each constant between the "
                     f"{design.get('stuck', '?')} stuck and {design.get('free', '?')} free samples [95 % bootstrap "
                     "interval], noise level; "
                     "verdict with the constant alone at the low / high end of its prior):")
        flipping = set(values.get("flipping_constants") or [])
        shown = [n for n in decision][:6] + [n for n in list(decision)[6:] if n in flipping]
        for name in shown:
            entry = decision[name]
            index = ("   -" if entry.get("index") is None else
                     f"{entry['index']:.2f} [{entry['index_ci'][0]:.2f}, {entry['index_ci'][1]:.2f}], noise "
                     f"{entry['noise_level']:.2f}")
            ends = ""
            if "stiction_at_low" in entry:
                ends = (f"; {entry['stiction_at_low']} / {entry['stiction_at_high']} stick"
                        + ("  FLIPS the verdict" if entry.get("can_flip") else ""))
            notes.append(f"    {name:<24} {index}{ends}")
    for name, band in (values.get("robust_bayes") or {}).items():
        if band.get("band") is None:
            continue
        notes.append(f"  robust-Bayes band of P(stiction) over {name}'s prior with its bounds moved by a factor "
                     f"{band['factor']:g}: {band['band'][0]:.2f} to {band['band'][1]:.2f} (intervals "
                     f"{band['band_ci'][0]:.2f}-{band['band_ci'][1]:.2f}, {band['samples']} samples each)"
                     + (": PRIOR-DOMINATED" if band.get("prior_dominated") else ""))
    return notes


def write_outputs(dataset, folder, provenance=None) -> list[str]:
    """NetCDF (everything), NetCDF + CSV of the per-step series, and the chapter-4 figures."""
    from memstribo.output import write_dataset

    written = write_dataset(dataset, folder, "mesh", csv=False, provenance=provenance)
    series = dataset.drop_vars([name for name in dataset.variables if "block" in dataset[name].dims])
    written += write_dataset(series, folder, "mesh_cycle", csv=True, provenance=provenance)
    written += plot_cycle(dataset, folder)
    return ["  wrote " + ", ".join(str(path) for path in written)]


def plot_cycle(dataset, folder) -> list:
    """Figures over the cycle: friction force, adhesion force, COF (split), dissipated energy (PNG + SVG)."""
    import numpy as np

    from memstribo.output import new_figure, save_figure

    c = np.asarray(dataset["c"]) * 1e6
    written = []

    def axes(title, ylabel):
        figure, ax = new_figure(figsize=(6.4, 3.6))
        ax.set_xlabel("position on the line of action c [µm] (0: pitch point)")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        ax.axvline(0.0, color="0.6", lw=0.8, ls=":")
        return figure, ax

    figure, ax = axes("Resisting force and drive over the meshing cycle", "force [µN]")
    ax.plot(c, dataset["friction_force_instantaneous"] * 1e6, lw=0.5, color="0.7", label="F_f of the pair, per step")
    ax.plot(c, dataset["friction_force"] * 1e6, lw=0.9, label="F_f of the pair (averaged over one atomic pitch)")
    ax.plot(c, dataset["resisting_force"] * 1e6, lw=1.2, color="C3", label="R(c): friction of all pairs in mesh")
    ax.plot(c, dataset["tangential_force"] * 1e6, lw=0.9, ls="--", color="k", label="F_t = T / r1 (stiction above)")
    ax.legend(fontsize=7)
    written += save_figure(figure, folder, "mesh_friction_force")

    figure, ax = axes("Adhesion force over the meshing cycle", "force [µN]")
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

    figure, ax = axes("Mesh efficiency over the cycle (all pairs in mesh)", "efficiency [-]")
    ax.plot(c, dataset["mesh_efficiency"], lw=0.9, label="1 - sum F_f |u1 - u2| / (T omega1)")
    ax.axhline(float(dataset.attrs["mesh_efficiency_mean"]), color="k", lw=0.8, ls="--", label="mean over a mesh period")
    ax.legend(fontsize=8)
    written += save_figure(figure, folder, "mesh_efficiency")

    figure, ax = axes("Energy dissipated per step", "energy [fJ]")
    for name, label in (("energy_chemical", "chemical bonds"), ("energy_vdw", "vdW bonds"),
                        ("energy_elastic", "elastic interlocking"), ("energy_dissipated", "total")):
        ax.plot(c, dataset[name] * 1e15, lw=0.8, label=label)
    ax.legend(fontsize=8)
    written += save_figure(figure, folder, "mesh_energy")
    return written
