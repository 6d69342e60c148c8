"""``memstribo sweep load|torque|area|humidity``: COF, dissipated energy and the verdict versus load, drive torque,
nominal area (thesis 4.9.3, 4.9.4) or relative humidity."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "sweep"
HELP = ("meshing cycles over loads (sweep load), drive torques (sweep torque), nominal contact areas (sweep area; "
        "thesis 4.9.3-4.9.4) or relative humidities (sweep humidity)")
ORDER = 55

_DEFAULTS = {"load": "25uN:300uN:25uN", "torque": "0.2e-7:2e-7:0.2e-7", "area": "1:10:1", "humidity": "0:0.95:0.05"}
_UNITS = {"load": "N", "torque": "N*m", "area": "", "humidity": ""}
_HEAD = {"load": ["normal_load"], "torque": ["drive_torque"], "area": ["area_multiple", "area"],
         "humidity": ["relative_humidity"]}

#: most values ``--values`` may give, as a comma list or a START:STOP:STEP range (counted before any is read)
MAX_SWEEP_VALUES = 1000

#: what each sweep sets at every point: a different value given by the user contradicts it (issue #41)
_SWEEP_SETS = {"load": {"load_case": "thesis"}, "torque": {"load_case": "torque"},
               "humidity": {"environment": "air"}}
#: the parameter each sweep replaces by its --values
_SWEPT = {"load": "normal_load", "torque": "drive_torque", "area": "face_width", "humidity": "relative_humidity"}


def register(subparsers, parents):
    from memstribo.cli.mesh import add_common_arguments

    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP,
        description=HELP + ". VALUES is START:STOP:STEP (STOP included) or a comma list; loads carry units "
        "('25uN:300uN:25uN'), areas are whole multiples of A_adh = w_adh^2 (the face width is set to that many "
        "nanoblock rows).")
    parser.add_argument("parameter", choices=("load", "torque", "area", "humidity"),
                        help="what to sweep (load: the thesis load case; torque: the torque load case)")
    parser.add_argument("--values", metavar="VALUES",
                        help="default: load 25uN:300uN:25uN, torque 0.2e-7:2e-7:0.2e-7 (N m; or with units, e.g. 20nN*m), area 1:10:1")
    add_common_arguments(parser)
    parser.add_argument("--realisations", type=int, default=1, metavar="N",
                        help="roughness realisations per point: adds the stiction probability and its bands")
    parser.add_argument("--check", action="store_true",
                        help="check every point at twice the steps and at twice the grid's resolution and report "
                             "converged (MODEL 7d: margin within 2 %% of |margin|, mean COF within 2 %%; three cycles "
                             "or more per point); unchecked points carry converged = null")
    parser.add_argument("--out", metavar="DIR", help="write the sweep (NetCDF + CSV) and its figures (PNG + SVG)")
    parser.set_defaults(handler=run)


def parse_values(text: str, unit: str, name: str = "--values") -> list[float]:
    """``"25uN:300uN:25uN"`` -> [2.5e-05, 5e-05, ...]; ``"1,2,4"`` -> [1.0, 2.0, 4.0] (SI)."""
    import numpy as np

    from memstribo.errors import InputError
    from memstribo.units import to_si

    text = text.strip()
    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise InputError(f"{name} {text!r}: a range is START:STOP:STEP (e.g. 25uN:300uN:25uN).")
        start, stop, step = (to_si(p, unit, name) for p in parts)
        if step <= 0 or stop < start:
            raise InputError(f"{name} {text!r}: STEP must be positive and STOP not below START.")
        count = int(np.floor((stop - start) / step * (1 + 1e-9))) + 1
        if count > MAX_SWEEP_VALUES:
            raise InputError(f"{name} {text!r} gives {count} points; at most {MAX_SWEEP_VALUES} are allowed.")
        return [start + i * step for i in range(count)]
    parts = [p for p in text.split(",") if p.strip()]
    if len(parts) > MAX_SWEEP_VALUES:  # refused before any value is converted (100 000 took minutes)
        raise InputError(f"{name} lists {len(parts):,} values; at most {MAX_SWEEP_VALUES} are allowed (a sweep "
                         "runs one meshing cycle per value).")
    values = [to_si(p, unit, name) for p in parts]
    if not values:
        raise InputError(f"{name} is empty.")
    return values


def check_sweep_contradictions(parameter: str, params) -> None:
    """Refuse a value the user gave that the sweep would replace at every point without a word (issue #41):
    ``sweep load --load-case torque`` (the load sweep is the thesis load case), ``sweep torque --load-case
    thesis``, ``sweep humidity --set environment=vacuum``, and the swept parameter itself (``sweep load --set
    normal_load=...``: --values gives it)."""
    from memstribo.checks import user_set
    from memstribo.errors import InputError

    for name, needed in _SWEEP_SETS.get(parameter, {}).items():
        if user_set(params, name) and params[name] != needed:
            other = {"load": " (sweep torque sweeps the torque load case)",
                     "torque": " (sweep load sweeps normal_load in the thesis load case)"}.get(parameter, "")
            raise InputError(f"{name} = '{params[name]}' (from {params.source(name)}) contradicts 'sweep {parameter}', "
                             f"which runs every point with {name} = '{needed}'{other}; drop it or give "
                             f"{name} = '{needed}'.")
    swept = _SWEPT[parameter]
    if user_set(params, swept):
        raise InputError(f"{swept} is what 'sweep {parameter}' sets at every point from --values; the value from "
                         f"{params.source(swept)} would be ignored: drop it, or give it in --values.")


def run(args, params):
    from memstribo.simulations.mesh import sweep
    from memstribo.cli.mesh import MESH_KEYS, apply_load_case, simulation_options

    params = apply_load_case(args, params)
    check_sweep_contradictions(args.parameter, params)
    values = parse_values(_DEFAULTS[args.parameter] if args.values is None else args.values, _UNITS[args.parameter])
    options = simulation_options(args, params)
    progress = options.pop("progress")
    from memstribo.cli.mesh import roughness_of

    from memstribo.checks import as_count
    from memstribo.parameters.definitions import SPECS

    as_count(args.realisations, "--realisations", int(SPECS["realisations"].minimum),
             int(SPECS["realisations"].maximum))
    roughness = roughness_of(args)
    points = sweep(params, args.parameter, values, roughness, progress=progress, realisations=args.realisations,
                   check=args.check, **options)
    critical = None
    if args.parameter == "humidity":  # the RH at which stiction sets in (issue #17)
        from memstribo.simulations.mesh import critical_humidity

        critical = critical_humidity(points)
        critical["coating"] = options.get("coating").name if options.get("coating") is not None else "none"
        critical["wear"] = float(options.get("wear", 1.0))
    head = _HEAD[args.parameter]
    extra = ["stiction_probability", "stiction_margin_p05", "stiction_margin_median", "stiction_margin_p95",
             "cof_mean_p05", "cof_mean_median", "cof_mean_p95"] if args.realisations > 1 else []
    extra += ["cof_capillary", "energy_capillary"] if args.parameter == "humidity" else []
    # the force to pull the flanks apart against the rough rows' water bridges (issue #28), where the run has it
    extra += ["capillary_pull_off_mean", "capillary_adhesion_force_mean"] if args.parameter == "humidity" and all(
        "capillary_pull_off_mean" in point for point in points) else []
    # will a tooth break (MODEL §10): the torque window between "sticks" and "breaks"
    extra += ["fracture_probability", "cycles_to_fracture_p01", "root_stress_max"] if args.parameter == "torque" else []
    points = [{key: point[key] for key in head + list(MESH_KEYS) + ["energy_dissipated", "energy_chemical",
                                                                     "energy_vdw", "energy_elastic",
                                                                     "unconverged_steps", "converged"] + extra
                                                                     + (["step_change_margin", "step_change_cof",
                                                                         "grid_change_margin", "grid_change_cof"]
                                                                        if args.check else [])}
              for point in points]
    notes = []
    if args.check:  # MODEL 7d: a point that is not converged says so, and the sweep counts them
        bad = [p for p in points if p["converged"] is False]
        notes.append(f"  {len(bad)} of {len(points)} point(s) not converged (margin or mean COF change by 2 % or more "
                     "at twice the steps or the grid): hollow markers in the figures")
    if args.out:
        from memstribo.output import provenance_attributes
        from memstribo.surfaces.roughness import default_profile

        provenance = provenance_attributes(
            params, roughness=default_profile(params) if roughness is None else roughness,
            extra={"command": f"memstribo sweep {args.parameter}", "models": "memstribo.simulations.mesh.sweep (thesis 4.9.3-4.9.4)"})
        notes.extend(_write(args.parameter, points, args.out, provenance, critical))
    if args.json:
        return CommandResult(values={"parameter": args.parameter, "points": points, **(critical or {})})
    lines = [f"  {head[0]:>13} {'cof_mean':>9} {'chemical':>9} {'vdW':>9} {'elastic':>9} {'F_f mean':>10} "
             f"{'F_adh mean':>11} {'energy':>10} {'margin':>10} {'efficiency':>10}"
             + (f" {'P(stiction)':>11}" if args.realisations > 1 else "")
             + (f" {'P(fracture)':>11}" if args.parameter == "torque" else "")]
    for p in points:
        swept = (f"{p['normal_load'] * 1e6:.4g} µN" if args.parameter == "load" else
                 f"RH {p['relative_humidity']:.2f}" if args.parameter == "humidity" else
                 f"{p['drive_torque']:.3g} N m" if args.parameter == "torque" else f"{p['area_multiple']} A_adh")
        lines.append(f"  {swept:>13} {p['cof_mean']:9.4g} {p['cof_chemical']:9.4g} {p['cof_vdw']:9.4g} "
                     f"{p['cof_elastic']:9.2g} {p['friction_force_mean'] * 1e6:7.4g} µN "
                     f"{p['adhesion_force_mean'] * 1e6:8.4g} µN {p['energy_dissipated'] * 1e12:7.4g} pJ "
                     f"{p['stiction_margin'] * 1e3:7.3g} mN {p['mesh_efficiency']:10.3g}"
                     + (f" {p['stiction_probability']:11.2f}" if args.realisations > 1 else "")
                     + (f" {_probability(p['fracture_probability']):>11}" if args.parameter == "torque" else ""))
    if critical is not None:
        lines.append(f"  critical humidity ({critical['coating']}, wear {critical['wear']:g}): "
                     + (f"RH {critical['critical_humidity']:.3f}" if critical["critical_humidity"] is not None
                        else "none in the range") + f" -- {critical['critical_humidity_note']}")
        if critical.get("critical_humidity_median") is not None:
            lines.append(f"  over {len(critical['critical_humidity_realisations'])} realisations: median RH "
                         f"{critical['critical_humidity_median']:.3f} (5-95 %: {critical['critical_humidity_p05']:.3f}"
                         f"-{critical['critical_humidity_p95']:.3f})")
    return CommandResult(values={}, title=f"sweep over {args.parameter}" + {"load": " (thesis 4.9.3, load case thesis)",
                                                                      "area": " (thesis 4.9.4)",
                                                                      "torque": " (load case torque)",
                                                                      "humidity": " (humid air)"}[args.parameter],
                         notes=lines + notes)


def _write(parameter, points, folder, provenance=None, critical=None) -> list[str]:
    import numpy as np
    import xarray as xr

    from memstribo.output import new_figure, save_figure, write_dataset
    from memstribo.quantities import attrs

    dim = _HEAD[parameter][0]
    coordinate = np.array([p[dim] for p in points], dtype=float)
    keys = [k for k in points[0] if k not in ("normal_load", "drive_torque", "area_multiple", "area", "stiction", dim)
            and isinstance(points[0][k], (int, float)) and not isinstance(points[0][k], bool)]
    data = {k: (dim, np.array([np.nan if p[k] is None else p[k] for p in points], dtype=float), attrs(k))
            for k in keys}
    dataset = xr.Dataset(data, coords={dim: (dim, coordinate, {"units": _UNITS[parameter] or "1",
                                                              "long_name": dim.replace("_", " ")})})
    if critical is not None:  # NetCDF attributes: NaN and the note where no crossing lies in the range
        for key, value in critical.items():
            if key == "critical_humidity_realisations":
                dataset.attrs[key] = np.array([np.nan if v is None else v for v in value], dtype=float)
            elif key == "critical_humidity_range":
                dataset.attrs[key] = np.array(value, dtype=float)
            else:
                dataset.attrs[key] = np.nan if value is None else value
    written = write_dataset(dataset, folder, f"sweep_{parameter}", provenance=provenance)
    x = coordinate * (1e6 if parameter == "load" else 1.0)
    xlabel = {"load": "external load [µN]", "torque": "drive torque [N m]", "humidity": "relative humidity [-]",
              "area": "nominal contact area [A_adh]"}[parameter]
    figure, ax = new_figure(figsize=(5.6, 3.6))
    ax.plot(x, dataset["cof_mean"], "o-", label="COF (cycle mean)")
    bad = np.array([p.get("converged") is False for p in points])
    if bad.any():  # MODEL 7d: unconverged points hollow
        ax.plot(x[bad], dataset["cof_mean"].values[bad], "o", markerfacecolor="white", markeredgecolor="k",
                markersize=8, label="not converged")
    ax.plot(x, dataset["cof_chemical"], ".--", label="chemical")
    ax.plot(x, dataset["cof_vdw"], ".--", label="vdW")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("COF [-]")
    ax.legend(fontsize=8)
    written += save_figure(figure, folder, f"sweep_{parameter}_cof")
    figure, ax = new_figure(figsize=(5.6, 3.6))
    ax.plot(x, dataset["energy_dissipated"] * 1e12, "o-")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("energy dissipated per cycle [pJ]")
    written += save_figure(figure, folder, f"sweep_{parameter}_energy")
    if "fracture_probability" in dataset:  # the torque window between "sticks" and "breaks" (MODEL §10)
        figure, (ax_s, ax_f) = new_figure(nrows=2, sharex=True, figsize=(5.6, 5.4))
        ax_s.plot(x, dataset["stiction_margin"] * 1e3, "o-")
        ax_s.axhline(0.0, color="0.5", lw=0.8)
        ax_s.set_ylabel("stiction margin [mN]")
        ax_f.semilogy(x, np.clip(dataset["fracture_probability"], 1e-12, None), "o-", color="C3")
        ax_f.set_ylabel("P(a tooth breaks on the first load) [-]")
        ax_f.set_xlabel(xlabel)
        written += save_figure(figure, folder, f"sweep_{parameter}_fracture")
    return ["  wrote " + ", ".join(str(p) for p in written)]


def _probability(value) -> str:
    """A probability for the table: '1.2e-05', or 'n/a' when the tooth strength was not computed."""
    return "n/a" if value is None else f"{value:.2g}"
