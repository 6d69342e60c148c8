"""``memstribo contact``: rough (or smooth) line contact of a cylinder on a profile, by the BEM solver."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "contact"
HELP = "line contact of a cylinder on a measured or flat profile: contact length, pressures, approach"
ORDER = 45

#: Fewest elements across the Hertz width 2a that still resolve the contact (1 % on a and p0 needs ~20).
MIN_ELEMENTS_ACROSS = 10


def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP,
        description=HELP + ". Plane strain, per unit face width; the gap is x^2/(2R) minus the profile heights "
        "(the profile's mean line through the cylinder's apex at the profile centre). Defaults: --radius is the "
        "gear pair's effective radius at the pitch point, --modulus the contact modulus of the parameter set, "
        "--load normal_load / face_width.")
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("--profile", metavar="PATH", help="profile file (any format readers.read_topography reads)")
    source.add_argument("--flat", action="store_true", help="smooth flat counter surface (Hertz check)")
    register_surface(parser, source)
    parser.add_argument("--channel", help="channel of a multi-channel file")
    parser.add_argument("--row", type=int, default=0, help="line scan (row) of a 2D map to use (default 0)")
    parser.add_argument("--length", help="domain length with --flat, e.g. '400 nm' (default: 8 Hertz half-widths)")
    parser.add_argument("--points", type=int, default=2048, help="number of elements with --flat (default 2048)")
    parser.add_argument("--radius", help="effective radius R, e.g. '20 um' (default: gear pair at the pitch point)")
    parser.add_argument("--load", help="load per unit face width w, e.g. '12.5 N/m' (default: normal_load/face_width)")
    parser.add_argument("--modulus", help="contact modulus E*, e.g. '85 GPa' (default: from the parameter set)")
    parser.add_argument("--periodic", action="store_true",
                        help="periodic half-plane (the gap repeats with the domain length) instead of a free boundary")
    parser.add_argument("--tolerance", type=float, default=1e-8, help="solver tolerance (default 1e-8)")
    parser.add_argument("--max-iterations", type=int, default=None, help="iteration cap of the solver")
    parser.add_argument("--allow-unconverged", action="store_true",
                        help="print an unconverged result (flagged converged=false) instead of exiting with status 2")
    register_adhesion(parser)
    parser.set_defaults(handler=run)


def _defaults(params):
    from memstribo.physics.gear import pitch_point_line_contact

    return pitch_point_line_contact(params)


def _positive(text, unit, name):
    from memstribo.errors import InputError
    from memstribo.units import to_si

    value = to_si(text, unit, name)
    if value <= 0:
        raise InputError(f"{name} must be positive, got {text!r}")
    return value


def contact_problem(args, params):
    """The separation [m], element width [m], modulus [Pa], radius [m], load [N/m] and a description."""
    import numpy as np

    from memstribo.errors import InputError
    from memstribo.physics.closed_form import hertz_line_half_width

    need_defaults = args.modulus is None or args.radius is None or args.load is None
    modulus, radius, load = _defaults(params) if need_defaults else (None, None, None)
    modulus = _positive(args.modulus, "Pa", "--modulus") if args.modulus is not None else modulus
    radius = _positive(args.radius, "m", "--radius") if args.radius is not None else radius
    load = _positive(args.load, "N/m", "--load") if args.load is not None else load
    half_width = float(hertz_line_half_width(load, radius, modulus))

    if args.flat:
        if args.points < 2:
            raise InputError(f"--points must be at least 2, got {args.points}")
        length = _positive(args.length, "m", "--length") if args.length is not None else 8.0 * half_width
        n = args.points
        dx = length / n
        heights = np.zeros(n)  # the gap is the library's cylinder_on_flat (the same x grid below)
        label = f"smooth cylinder on a flat, {n} elements over {length * 1e9:.4g} nm"
    else:
        from memstribo.surfaces.readers import read_topography

        data = read_topography(args.profile, channel=args.channel)
        if hasattr(data, "line_scans"):
            scans = data.line_scans()
            if not 0 <= args.row < len(scans):
                raise InputError(f"--row {args.row} is outside the map's rows 0..{len(scans) - 1}")
            data = scans[args.row]
        if not data.is_uniform:
            raise InputError(f"profile '{data.name}' is not uniformly sampled; the contact solver needs a uniform "
                             "grid: resample it first (memstribo roughness --resample STEP)")
        heights = np.asarray(data.z, dtype=float)
        n = heights.size
        dx = float(data.x[-1] - data.x[0]) / (n - 1)
        length = n * dx
        heights = heights - heights.mean()
        label = f"cylinder on profile '{data.name}' ({data.source}), {n} elements of {dx * 1e9:.4g} nm"

    elements = 2.0 * half_width / dx
    if elements < MIN_ELEMENTS_ACROSS:
        raise InputError(
            f"the grid is too coarse for this contact: the element width {dx * 1e9:.4g} nm gives only "
            f"{elements:.3g} elements across the Hertz width 2a = {2 * half_width * 1e9:.4g} nm (R = "
            f"{radius * 1e6:.4g} µm, w = {load:.4g} N/m, E* = {modulus / 1e9:.4g} GPa); at least "
            f"{MIN_ELEMENTS_ACROSS} are needed: use a finer profile or more --points")
    if length < 4.0 * half_width:
        raise InputError(f"the domain ({length * 1e9:.4g} nm) is shorter than twice the Hertz width 2a = "
                         f"{2 * half_width * 1e9:.4g} nm: use a longer profile or --length, or a smaller load")
    x = (np.arange(n) - 0.5 * (n - 1)) * dx
    separation = x**2 / (2.0 * radius) - heights
    return separation, dx, modulus, radius, load, label


def _check_points(args) -> None:
    """``--points`` within the elements of one contact solve, before anything is allocated (issue #41: 10^9
    points ended in a generic memory message)."""
    from memstribo.errors import InputError
    from memstribo.parameters import MAX_CONTACT_ELEMENTS

    points = getattr(args, "points", None)
    if points is not None and points > MAX_CONTACT_ELEMENTS:
        raise InputError(f"--points {points:,} is more elements than one contact solve may have: at most "
                         f"{MAX_CONTACT_ELEMENTS:,} (its arrays would not fit in memory); use fewer --points.")


def run(args, params):
    if getattr(args, "surface", None) is not None:
        return run_surface(args, params)
    _refuse_surface_options(args)
    _check_points(args)
    if getattr(args, "adhesion", False) or getattr(args, "pull_off", False):
        return run_adhesion(args, params)
    from memstribo.physics.contact import solve_line_contact
    from memstribo.errors import ConvergenceError, InputError
    from memstribo.physics.closed_form import hertz_line_half_width, hertz_line_peak_pressure

    separation, dx, modulus, radius, load, label = contact_problem(args, params)
    solution = solve_line_contact(separation, dx, modulus, load=load, periodic=args.periodic,
                                  tolerance=args.tolerance, max_iterations=args.max_iterations)
    if not solution.converged and not args.allow_unconverged:
        raise ConvergenceError(f"the contact solver did not converge: {solution.message}. Raise --max-iterations, "
                               "loosen --tolerance, or use --allow-unconverged to print the result anyway")
    if not args.periodic and (solution.contact[0] or solution.contact[-1]):
        raise InputError("the contact reaches the end of the domain: the free-boundary result would be wrong; "
                         "use a longer profile (or --length) or a smaller load")
    values = {
        "contact_length": solution.contact_length,
        "max_pressure": solution.max_pressure,
        "mean_pressure": solution.mean_pressure,
        "load": solution.load,
        "approach": solution.approach,
        "converged": solution.converged,
        "iterations": solution.iterations,
        "residual": solution.residual,
        "solve_seconds": solution.solve_time,
    }
    a = float(hertz_line_half_width(load, radius, modulus))
    p0 = float(hertz_line_peak_pressure(load, radius, modulus))
    notes = [
        f"  {label}; {'periodic' if args.periodic else 'free-boundary'} half-plane, E* = {modulus / 1e9:.4g} GPa, "
        f"R = {radius * 1e6:.4g} µm.",
        f"  smooth Hertz reference: contact length 2a = {2 * a * 1e9:.4g} nm, peak pressure p0 = {p0 / 1e9:.4g} GPa.",
        f"  approach relative to the far-field datum at the domain length {separation.size * dx * 1e9:.4g} nm "
        "(docs/contact.md)." if not args.periodic else "  approach relative to a zero mean elastic displacement.",
        f"  solver: {solution.message}.",
    ]
    return CommandResult(values=values, title="line contact (plane strain, per unit face width)",
                         notes=notes)


# --------------------------------------------------------------------------- adhesion (Maugis-Dugdale)


def register_adhesion(parser):
    """The ``--adhesion`` options of ``memstribo contact`` (docs/contact.md, "Adhesive contact")."""
    group = parser.add_argument_group("adhesion (Maugis-Dugdale cohesive zone, docs/contact.md)")
    group.add_argument("--adhesion", action="store_true",
                       help="solve with a Maugis-Dugdale cohesive zone: tension sigma0 where the gap is in (0, h0]; "
                            "prints adhesive_load and the Maugis parameter (load may then be negative: tensile)")
    group.add_argument("--pull-off", action="store_true",
                       help="with --flat: unload the smooth cylinder under approach control from zero load to "
                            "separation; prints pull_off_line_load (N/m, positive), pull_off_half_width, "
                            "maugis_parameter")
    group.add_argument("--cohesive-stress", metavar="STRESS",
                       help="Dugdale stress sigma0, e.g. '1.78 GPa' (default: 16 w / (9 sqrt(3) D0) of the parameter "
                            "set, as 'memstribo constants' prints)")
    group.add_argument("--cohesive-range", metavar="LENGTH",
                       help="range h0 of the Dugdale stress, e.g. '0.25 nm' (default: w / sigma0); the work of "
                            "adhesion is sigma0 h0")


def cohesive_law(args, params):
    """sigma0 [Pa], h0 [m] and w = sigma0 h0 [J/m^2]: the parameter set's Maugis values unless overridden."""
    from memstribo.physics.adhesion import nanoscale_constants

    constants = nanoscale_constants(params)
    sigma0 = (_positive(args.cohesive_stress, "Pa", "--cohesive-stress") if args.cohesive_stress is not None
              else float(constants.maugis_stress))
    if args.cohesive_range is not None:
        h0 = _positive(args.cohesive_range, "m", "--cohesive-range")
    elif args.cohesive_stress is not None:
        h0 = float(constants.work_of_adhesion) / sigma0  # keep w, change the stress
    else:
        h0 = float(constants.maugis_range)
    return sigma0, h0, sigma0 * h0


def run_adhesion(args, params):
    """``memstribo contact --adhesion [--pull-off]``: the adhesive line contact and its pull-off."""
    import argparse

    import numpy as np

    from memstribo.errors import ConvergenceError, InputError
    from memstribo.physics.closed_form import (jkr_line_pull_off_load, maugis_dugdale_line_pull_off, maugis_line_parameter)

    sigma0, h0, w = cohesive_law(args, params)
    need_defaults = args.modulus is None or args.radius is None or args.load is None
    modulus, radius, load = _defaults(params) if need_defaults else (None, None, None)
    modulus = _positive(args.modulus, "Pa", "--modulus") if args.modulus is not None else modulus
    radius = _positive(args.radius, "m", "--radius") if args.radius is not None else radius
    lam = float(maugis_line_parameter(radius, modulus, w, sigma0))
    law = {"cohesive_stress": sigma0, "cohesive_range": h0, "work_of_adhesion": w, "maugis_parameter": lam}
    law_note = (f"  Maugis-Dugdale law: sigma0 = {sigma0 / 1e9:.4g} GPa over h0 = {h0 * 1e9:.4g} nm "
                f"(w = {w:.4g} J/m^2); "
                f"Maugis parameter lambda = 2 sigma0 (R/(pi w E*^2))^(1/3) = {lam:.3g} (R = {radius * 1e6:.4g} µm, "
                f"E* = {modulus / 1e9:.4g} GPa).")

    if args.pull_off:
        from memstribo.physics.adhesive_contact import line_contact_pull_off

        if not args.flat:
            raise InputError("--pull-off needs --flat (a smooth cylinder on a flat)")
        length = _positive(args.length, "m", "--length") if args.length is not None else None
        if args.points < 64:
            raise InputError(f"--points must be at least 64 for --pull-off, got {args.points}")
        result = line_contact_pull_off(radius, modulus, w, sigma0, points=args.points, length=length,
                                       tolerance=args.tolerance, periodic=args.periodic)
        if not result.converged and not args.allow_unconverged:
            raise ConvergenceError(f"the pull-off search did not finish: {result.message}. Use more --points, a "
                                   "longer --length, or --allow-unconverged to print the result anyway")
        reference, reference_width = maugis_dugdale_line_pull_off(radius, modulus, w, sigma0)
        jkr = -float(jkr_line_pull_off_load(radius, modulus, w))
        values = {"pull_off_line_load": result.pull_off_line_load, "pull_off_half_width": result.pull_off_half_width,
                  **law, "maugis_dugdale_pull_off_line_load": -reference,
                  "maugis_dugdale_pull_off_half_width": reference_width, "jkr_pull_off_line_load": jkr,
                  "unloading_steps": int(len(result.curve.load) - 1), "converged": result.converged}
        notes = [law_note,
                 f"  smooth cylinder, {args.points} elements over {result.length * 1e9:.4g} nm, "
                 f"{'periodic' if args.periodic else 'free-boundary'} half-plane; unloaded under approach control.",
                 f"  closed forms: Maugis-Dugdale cylinder (Baney & Hui 1997) {-reference:.4g} N/m, JKR line contact "
                 f"(3/4)(4 pi E* w^2 R)^(1/3) = {jkr:.4g} N/m.",
                 f"  {result.message}."]
        return CommandResult(values=values, title="adhesive line contact: pull-off (per unit face width)",
                             notes=notes)

    from memstribo.physics.contact import solve_line_contact

    from memstribo.physics.closed_form import hertz_line_half_width
    from memstribo.units import to_si

    # the load may be tensile (negative) with adhesion; the grid checks of contact_problem use the
    # Hertz load whose half-width is the larger of Hertz's at |load| and JKR's at zero load
    applied = to_si(args.load, "N/m", "--load") if args.load is not None else load
    a_zero = float(np.cbrt(32.0 * radius**2 * w / (np.pi * modulus)))
    a_hertz = float(hertz_line_half_width(abs(applied), radius, modulus)) if applied else 0.0
    size_load = np.pi * modulus * max(a_hertz, a_zero) ** 2 / (4.0 * radius)
    overrides = {"load": f"{size_load} N/m", "modulus": f"{modulus} Pa", "radius": f"{radius} m"}
    if args.flat and args.length is None:  # wider than Hertz's contact: 5 JKR half-widths at zero load
        overrides["length"] = f"{max(8.0 * a_hertz, 5.0 * a_zero)} m"
    separation, dx, modulus, radius, _, label = contact_problem(argparse.Namespace(**{**vars(args), **overrides}),
                                                                params)
    load = applied
    solution = solve_line_contact(separation, dx, modulus, load=load, periodic=args.periodic,
                                  tolerance=args.tolerance, max_iterations=args.max_iterations,
                                  cohesive_stress=sigma0, cohesive_range=h0)
    if not solution.converged and not args.allow_unconverged:
        raise ConvergenceError(f"the adhesive contact solve did not converge: {solution.message}. Raise "
                               "--max-iterations, loosen --tolerance, or use --allow-unconverged to print it anyway")
    if not args.periodic and (solution.contact[0] or solution.contact[-1] or solution.cohesive[0]
                              or solution.cohesive[-1]):
        raise InputError("the contact or its cohesive zone reaches the end of the domain: the free-boundary result "
                         "would be wrong; use a longer profile (or --length) or a smaller load")
    values = {
        "contact_length": solution.contact_length,
        "cohesive_length": float(np.count_nonzero(solution.cohesive) * dx),
        "adhesive_load": solution.adhesive_load,
        "load": solution.load,
        "max_pressure": solution.max_pressure,
        "min_pressure": float(solution.pressure.min()),
        "approach": solution.approach,
        **law,
        "converged": solution.converged,
        "iterations": solution.iterations,
        "residual": solution.residual,
        "solve_seconds": solution.solve_time,
    }
    notes = [f"  {label}; {'periodic' if args.periodic else 'free-boundary'} half-plane.", law_note,
             "  load = compressive load of the contact - adhesive_load (the tension of the cohesive zone outside it).",
             f"  solver: {solution.message}."]
    return CommandResult(values=values,
                         title="adhesive line contact (Maugis-Dugdale, per unit face width)", notes=notes)


# ---------------------------------------------------------------- surface (3D) contact: --surface


def register_surface(parser, source):
    """Options of the surface (3D) contact: ``--surface FILE`` and its companions."""
    source.add_argument("--surface", metavar="FILE",
                        help="rough surface (3D) contact of a 2D height map against a flat: any map "
                        "readers.read_topography reads, or a NumPy .npy 2D array of heights in m (then "
                        "--physical-size is needed). With --surface, give --mean-pressure P or --load W (the "
                        "normal force in N); --periodic uses the periodic half-space")
    parser.add_argument("--physical-size", metavar="SIZE",
                        help="lateral size of the --surface map: one length for a square ('10um') or 'LXxLY' "
                        "('10umx5um'); needed for .npy files, overrides the file's own size")
    parser.add_argument("--mean-pressure", metavar="P", help="nominal pressure with --surface, e.g. '50 MPa'")
    parser.add_argument("--out", metavar="DIR",
                        help="with --surface: write pressure and gap (NetCDF) and a figure (PNG) to DIR")


def _refuse_surface_options(args):
    """The --surface options make no sense for a line contact: say so rather than ignore them."""
    from memstribo.errors import InputError

    given = [flag for flag, name in (("--physical-size", "physical_size"), ("--mean-pressure", "mean_pressure"),
                                     ("--out", "out")) if getattr(args, name, None) is not None]
    if given:
        raise InputError(f"{', '.join(given)} go(es) with --surface FILE only, not with --profile or --flat")


def _physical_size(text):
    """'10um' -> (1e-5, 1e-5); '10umx5um' or '10 um x 5 um' -> (1e-5, 5e-6) [m]."""
    import re

    from memstribo.errors import InputError

    parts = [part.strip() for part in re.split(r"(?<=[a-zA-Zµ.\d])\s*[xX×]\s*(?=[\d.])", text.strip())]
    if len(parts) not in (1, 2):
        raise InputError(f"--physical-size must be one length (square) or 'LXxLY', e.g. '10um' or '10umx5um'; "
                         f"got {text!r}")
    sizes = [_positive(part, "m", "--physical-size") for part in parts]
    return (sizes[0], sizes[0]) if len(sizes) == 1 else (sizes[0], sizes[1])


def surface_problem(args):
    """Heights [m] (ny, nx), dx, dy [m] and a description of the ``--surface`` map."""
    from pathlib import Path

    import numpy as np

    from memstribo.errors import InputError

    path = Path(args.surface)
    size = _physical_size(args.physical_size) if args.physical_size is not None else None
    if path.suffix.lower() == ".npy":
        from memstribo.surfaces.readers import read_height_array

        heights = read_height_array(path)  # header checked first: size, float dtype; heights in m (<= 0.1 m)
        if size is None:
            raise InputError(f"--surface {path}: a .npy array has no lateral size: give --physical-size, e.g. "
                             "'1um' (square) or '2umx1um' (LX x LY)")
        name = path.name
        source = f"{path} (NumPy array, heights in m)"
    else:
        from memstribo.surfaces.readers import read_topography

        data = read_topography(path, channel=args.channel)
        if not hasattr(data, "heights"):
            raise InputError(f"--surface {path}: the file holds a line profile, not a 2D map; use --profile")
        heights = np.asarray(data.heights, dtype=float)
        if size is None:
            if not (np.isfinite(data.dx) and np.isfinite(data.dy) and data.dx > 0 and data.dy > 0):
                raise InputError(f"--surface {path}: the file gives no lateral size; give --physical-size")
            size = (data.dx * heights.shape[1], data.dy * heights.shape[0])
        name, source = data.name, data.source
    ny, nx = heights.shape
    dx, dy = size[0] / nx, size[1] / ny
    heights = heights - heights.mean()
    label = (f"surface '{name}' ({source}), {nx} x {ny} elements of {dx * 1e9:.4g} nm x {dy * 1e9:.4g} nm "
             f"({size[0] * 1e6:.4g} µm x {size[1] * 1e6:.4g} µm)")
    return heights, dx, dy, label


def run_surface(args, params):
    """``memstribo contact --surface FILE``: a rough (or measured) surface pressed on a flat."""
    from memstribo.errors import ConvergenceError, InputError
    from memstribo.physics.surface_contact import solve_surface_contact

    if (args.mean_pressure is None) == (args.load is None):
        raise InputError("with --surface give exactly one of --mean-pressure P (e.g. '50 MPa') and --load W "
                         "(the normal force, e.g. '10 uN')")
    heights, dx, dy, label = surface_problem(args)
    modulus = _positive(args.modulus, "Pa", "--modulus") if args.modulus is not None else _defaults(params)[0]
    keywords = ({"mean_pressure": _positive(args.mean_pressure, "Pa", "--mean-pressure")}
                if args.mean_pressure is not None else {"load": _positive(args.load, "N", "--load")})
    # the gap to a flat: the highest point touches first
    separation = heights.max() - heights
    solution = solve_surface_contact(separation, dx, dy, modulus, periodic=args.periodic, tolerance=args.tolerance,
                                     max_iterations=args.max_iterations, **keywords)
    if not solution.converged and not args.allow_unconverged:
        raise ConvergenceError(f"the surface contact solver did not converge: {solution.message}. Raise "
                               "--max-iterations, loosen --tolerance, or use --allow-unconverged")
    values = {
        "contact_fraction": solution.contact_fraction,
        "max_pressure": solution.max_pressure,
        "mean_gap": solution.mean_gap,
        "approach": solution.approach,
        "iterations": solution.iterations,
        "residual": solution.residual,
        "solve_seconds": solution.solve_time,
    }
    notes = [
        f"  {label}; {'periodic' if args.periodic else 'free-boundary'} half-space, E* = {modulus / 1e9:.4g} GPa, "
        f"load {solution.load:.4g} N (mean pressure {solution.load / (heights.size * dx * dy) / 1e6:.4g} MPa).",
        "  the map's highest point touches the flat first; approach from that first touch "
        + ("(zero mean elastic displacement)." if args.periodic else "(undisplaced far field)."),
        f"  converged: {solution.converged}; solver: {solution.message}.",
    ]
    if args.out:
        written = write_surface_outputs(solution, args.out)
        notes.append("  wrote " + ", ".join(str(path) for path in written))
    return CommandResult(values=values, title="surface contact (elastic half-space, flat counter face)",
                         notes=notes)


def write_surface_outputs(solution, folder):
    """Pressure and gap as NetCDF (units attrs) and a PNG figure of pressure and contact; returns the paths."""
    import numpy as np

    from memstribo.output import new_figure, save_figure, write_dataset

    dataset = solution.to_xarray()
    written = write_dataset(dataset, folder, "surface_contact", csv=False)
    figure, axes = new_figure(1, 2, figsize=(9.6, 4.2))
    ny, nx = solution.pressure.shape
    extent = (0.0, nx * solution.dx * 1e6, 0.0, ny * solution.dy * 1e6)
    image = axes[0].imshow(solution.pressure / 1e9, origin="lower", extent=extent, cmap="viridis")
    figure.colorbar(image, ax=axes[0], label="pressure [GPa]")
    axes[0].set_title("contact pressure")
    axes[1].imshow(np.where(solution.contact, 1.0, 0.0), origin="lower", extent=extent, cmap="Greys",
                   vmin=0.0, vmax=1.0)
    axes[1].set_title(f"contact (black), A/A0 = {solution.contact_fraction:.3g}")
    for axis in axes:
        axis.set_xlabel("x [µm]")
        axis.set_ylabel("y [µm]")
    written += save_figure(figure, folder, "surface_contact", formats=("png",))
    return written
