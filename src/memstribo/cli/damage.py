"""``memstribo damage``: damage of the SAM coating per meshing cycle, lives, cycles to stiction (thesis 5.5)."""

from __future__ import annotations

from memstribo.cli.common import CommandResult, add_progress_argument, progress_enabled

NAME = "damage"
HELP = "damage accumulation in the coating (5-10): omega/c1 per cycle, relative lives, cycles to stiction"
ORDER = 72

#: Thesis Table 5-1: loads of one nanoblock (adhesive asperity) [N].


def register(subparsers, parents):
    parser = subparsers.add_parser(NAME, parents=parents, help=HELP, description=HELP + (
        ". The load peaks come from the coated pair's meshing cycle (per-nanoblock loads) or from --loads. "
        "Set the damage law with --set damage_exponent=M and --set damage_coefficient=C1 (c1 in Pa^-m); "
        "without c1 only omega/c1 and relative lives are known."))
    parser.add_argument("--loads", metavar="LIST",
                        help="nanoblock peak loads instead of the meshing cycle: comma-separated, with a unit on "
                             "each or none (SI), e.g. '0.8166 uN,7.0165 uN'; 'table5-1' for the thesis's six loads. "
                             "They are repeated in turn to the peaks_per_cycle peaks of a cycle")
    parser.add_argument("--coating", default="OTS", help="coating whose wear decides stiction: OTS (default) or FDTS")
    parser.add_argument("--observed-life", metavar="N", type=float,
                        help="calibrate c1 from an observed coating life of N meshing cycles")
    parser.add_argument("--wear-points", type=int, default=6,
                        help="wear states Omega in the COF sweep that decides stiction (default 6: 0, 0.2, ... 1)")
    parser.add_argument("--load-case", choices=("torque", "thesis"),
                        help="normal load of the meshing cycles: 'torque' (default) or 'thesis' (normal_load, 25 uN)")
    parser.add_argument("--steps", type=int, default=None, help="steps of each meshing-cycle simulation")
    parser.add_argument("--out", metavar="DIR", help="write datasets (NetCDF + CSV) and figures to DIR")
    add_progress_argument(parser)
    parser.set_defaults(handler=run)


def parse_loads(text) -> list[float]:
    """'0.8166 uN, 0.99 uN' or 'table5-1' -> loads [N], each > 0."""
    from memstribo.errors import InputError
    from memstribo.units import to_si

    if str(text).strip().lower().replace(" ", "") in ("table5-1", "thesis"):
        from memstribo.parameters.thesis_tables import TABLE_5_1_LOADS

        return TABLE_5_1_LOADS.tolist()
    items = [item.strip() for item in str(text).split(",")]
    if any(item == "" for item in items):
        raise InputError(f"--loads must be a comma-separated list of loads > 0 N, got {text!r}.")
    if len(items) > 10_000:
        raise InputError(f"--loads: {len(items)} loads; give at most 10 000 (they repeat to peaks_per_cycle anyway).")
    loads = [to_si(item, "N", "--loads") for item in items]
    if any(load <= 0 for load in loads):
        raise InputError(f"--loads must all be > 0 N, got {text!r}.")
    from memstribo.parameters import coerce_value

    for item in items:  # a nanoblock carries at most what a tooth does
        try:
            coerce_value("normal_load", item)
        except InputError as exc:
            raise InputError(f"--loads: {exc}") from None
    return loads


def run(args, params):
    import numpy as np

    from memstribo.physics.coating import get_coating
    from memstribo.simulations.coating_wear import wear_sweep
    from memstribo.physics.damage import run_damage

    from memstribo.cli.mesh import apply_load_case

    params = apply_load_case(args, params)
    loads = parse_loads(args.loads) if args.loads is not None else None
    _check_arguments(args, params)
    from memstribo.checks import refuse_unused_coating_wear

    refuse_unused_coating_wear(params, "memstribo damage", "the damage analysis loads the intact coating "
                               "(Omega = 0) and sweeps Omega over --wear-points itself")
    coating = get_coating(args.coating, params)
    c1_known = params["damage_coefficient"] is not None or args.observed_life is not None
    mesh_dataset = None
    notes = []
    if loads is None:
        from memstribo.simulations.mesh import simulate_mesh

        mesh_dataset = simulate_mesh(params, steps=args.steps, coating=coating, wear=0.0)
        notes.append(f"  load peaks: nanoblock loads of the {coating.name}-coated meshing cycle "
                     f"({mesh_dataset.sizes['step']} steps)")
    else:
        notes.append(f"  load peaks: {len(loads)} nanoblock loads repeated to k = {params['peaks_per_cycle']} peaks "
                     "per cycle, full unloading between peaks")
    sweep = None
    if c1_known:
        sweep = wear_sweep(params, coating, np.linspace(0.0, 1.0, args.wear_points), steps=args.steps,
                           progress=progress_enabled(args))
    outcome = run_damage(params, mesh_dataset, loads=loads, wear_sweep=sweep, cycles_observed=args.observed_life,
                         figures=bool(args.out))
    s = outcome.summary
    m = s["damage_exponent"]
    if loads is None:
        notes.append(f"  peaks_per_cycle: the most load peaks of one nanoblock in the cycle (thesis: k = 48)")
    values = {
        "omega_over_c1_max": s["omega_over_c1_max"],
        "location": s["location"],
        "life_ratio_corner_to_central": s["life_ratio_corner_to_central"],
        "damage_exponent": m,
        "peaks_per_cycle": s["peaks_per_cycle"],
    }
    power = "" if m == 1 else f"^{m:g}"
    units = {"omega_over_c1_max": f"Pa{power}", "location": "m", "damage_coefficient": f"Pa^-{m:g}"}
    if c1_known:
        values.update({
            "damage_coefficient": s["damage_coefficient"],
            "cycles_to_failure": s["cycles_to_failure"],
            "cycles_to_failure_by_position": s["cycles_to_failure_by_position"],
            "critical_wear": s.get("critical_wear"),
            "cycles_to_stiction": s["cycles_to_stiction"],
        })
        if s["cycles_to_stiction"] is None:
            notes.append("  cycles_to_stiction: none - the friction force stays below the tangential force "
                         "at every wear state of the sweep, even bare")
    else:
        notes.append("  c1 unknown: give --set damage_coefficient=C1 [Pa^-m] or --observed-life N for cycles to "
                     "failure and to stiction")
    notes += _asperity_warning(params, outcome)
    ratio = s["life_ratio_corner_to_central"]
    if ratio is None:
        notes.append("  life_ratio_corner_to_central: none - a nanoblock needs atomic_per_side >= 3 to have both "
                     "corner and central asperities")
    else:
        notes.append(f"  corner life / central life = {ratio:.4g} "
                     f"(the corner's coating wears through {100 * (1 - ratio):.3g} % sooner)")
    if args.out:
        from memstribo.output import provenance_attributes, save_figure, write_dataset
        from memstribo.surfaces.roughness import default_profile

        uses_mesh = loads is None or sweep is not None
        provenance = provenance_attributes(params, roughness=default_profile(params) if uses_mesh else None, extra={
            "command": "memstribo damage", "coating": coating.name,
            "models": "memstribo.physics.damage.run_damage (thesis 5.5)",
            **({} if uses_mesh else {"roughness_provenance": "none: nanoblock loads given (--loads)"})})
        written = []
        for stem, dataset in outcome.datasets.items():
            written += write_dataset(dataset, args.out, stem, provenance=provenance)
        if sweep is not None:
            written += write_dataset(sweep, args.out, "coating_wear", provenance=provenance)
        for stem, (figure, _caption) in outcome.figures.items():
            written += save_figure(figure, args.out, stem)
        written += _stress_figures(params, outcome, args.out)
        notes.append("  wrote " + ", ".join(str(p) for p in written))
    return CommandResult(values=values, units=units, title="damage accumulation in the coating (5-10)", notes=notes)


def _check_arguments(args, params):
    """InputError on an observed life, wear-point count or step count outside what the command allows."""
    import numpy as np

    from memstribo.errors import InputError

    if args.observed_life is not None and not (np.isfinite(args.observed_life) and 1 <= args.observed_life <= 1e20):
        raise InputError(f"--observed-life must be a number of cycles from 1 to 1e20, got {args.observed_life!r}.")
    if not 2 <= args.wear_points <= 1001:
        raise InputError(f"--wear-points must be from 2 to 1001, got {args.wear_points}.")
    if args.steps is not None and not 2 <= args.steps <= 100_000:
        raise InputError(f"--steps must be an integer from 2 to 100 000, got {args.steps}.")
    if args.steps is not None:
        from memstribo.parameters import check_mesh_size

        check_mesh_size(args.steps, params["mesh_window"], params["mesh_grid_spacing"], what="--steps")


def _asperity_warning(params, outcome) -> list[str]:
    """A note where the largest asperity load's contact radius exceeds the asperity's half width."""
    import numpy as np

    from memstribo.materials.pair import contact_modulus_of
    from memstribo.physics.asperity import power_law_contact_radius

    largest = float(np.max(outcome.result.asperity_peak_loads, initial=0.0))
    if largest > 0:
        radius = float(power_law_contact_radius(largest, params["asperity_degree"],
                                                params["asperity_shape_coefficient"], contact_modulus_of(params)))
        if radius > params["asperity_half_width"]:
            return [f"  warning: the largest asperity load gives a contact radius of {radius * 1e9:.3g} nm, more "
                    f"than the asperity half width {params['asperity_half_width'] * 1e9:.3g} nm: the power-law "
                    "shape no longer describes the asperity there"]
    return []


def _stress_figures(params, outcome, folder):
    """Pressure and tau_1 along x through the corner/side/central asperities at the largest peak."""
    import numpy as np

    from memstribo.materials.pair import contact_modulus_of
    from memstribo.physics.asperity import power_law_pressure
    from memstribo.physics.damage import POSITIONS, principal_shear_profile
    from memstribo.output import new_figure, save_figure

    result = outcome.result
    loads = result.asperity_peak_loads
    top = int(np.argmax(loads.sum(axis=1)))
    modulus = contact_modulus_of(params)
    d, b = params["asperity_degree"], params["asperity_shape_coefficient"]
    x = result.x
    fig, (ax1, ax2) = new_figure(2, 1, figsize=(5, 6), sharex=True)
    for position, style in zip(POSITIONS, ("r-", "g-", "b-")):
        mask = result.classes == position
        if not mask.any():
            continue
        load = float(loads[top][mask].max())
        ax1.plot(x * 1e9, power_law_pressure(np.abs(x), load, d, b, modulus) / 1e9, style,
                 label=f"{position} ({load * 1e6:.3g} µN)")
        tau = principal_shear_profile(x, load, d, b, modulus, params["asperity_friction_coefficient"],
                                      params["poisson_ratio"])
        ax2.plot(x * 1e9, tau / 1e9, style, label=position)
    ax1.set_ylabel("contact pressure p [GPa]")
    ax1.legend()
    ax2.set_ylabel("principal shear stress tau_1 [GPa]")
    ax2.set_xlabel("x along sliding through the asperity centre [nm]")
    ax1.set_title("largest load peak (thesis Figures 5-17, 5-20)")
    written = save_figure(fig, folder, "pressure_and_tau1")
    # tau_1 of the corner asperity at the smallest, a middle and the largest peak (Figure 5-21)
    corner = result.classes == "corner" if (result.classes == "corner").any() else np.ones_like(result.classes, bool)
    corner_loads = np.unique(loads[:, corner].max(axis=1))
    picks = corner_loads[[0, corner_loads.size // 2, -1]] if corner_loads.size >= 3 else corner_loads
    fig, ax = new_figure(figsize=(5, 3.5))
    for load, style in zip(picks, ("r-", "g-", "b-")):
        tau = principal_shear_profile(x, float(load), d, b, modulus, params["asperity_friction_coefficient"],
                                      params["poisson_ratio"])
        ax.plot(x * 1e9, tau / 1e9, style, label=f"{load * 1e6:.3g} µN")
    ax.set_xlabel("x along sliding through the asperity centre [nm]")
    ax.set_ylabel("tau_1 [GPa]")
    ax.set_title("corner asperity at several loads (thesis Figure 5-21)")
    ax.legend()
    return written + save_figure(fig, folder, "tau1_corner_loads")
