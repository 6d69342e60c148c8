"""``memstribo roughness PATH``: roughness parameters of a measured profile or map (thesis 4.2)."""

from __future__ import annotations

from memstribo.cli.common import CommandResult

NAME = "roughness"
HELP = "roughness parameters (Ra, Rq, rms slope, lambda_q, ...) of an AFM/profilometer file"
ORDER = 10

_KEYS = ("Ra", "Rq", "Rsk", "Rku", "Rp", "Rv", "Rz", "rms_slope", "lambda_q", "n_points", "sample_spacing", "length")
def register(subparsers, parents):
    parser = subparsers.add_parser(
        NAME, parents=parents, help=HELP,
        description=HELP + ". PATH is an instrument file (NanoScope .di/.001, Park .tiff, Asylum .ibw, Dektak .opdx, "
        "Gwyddion, x3p, ...), a contact.engineering .zip, an x-z text/CSV or .npy profile, or 'thesis' for the "
        "thesis case's default (synthetic) profile. Profiles are levelled by their least-squares line; for a map the "
        "R values are per scan line (each line levelled on its own), the S values are areal (plane levelled).")
    parser.add_argument("path", metavar="PATH", help="measurement file, or 'thesis'")
    parser.add_argument("--resample", metavar="STEP", help="PCHIP-resample to this step first ('39 nm' or metres)")
    parser.add_argument("--channel", metavar="NAME", help="channel name or chN; for a .zip a member name (or part)")
    parser.add_argument("--unit", metavar="U", help="unit of x and heights for files that do not say (m, mm, um, nm)")
    parser.add_argument("--physical-size", metavar="SIZE",
                        help="lateral size of a file that does not give one: '10 um' (profile or square map) or "
                             "'10 um, 5 um' (map)")
    parser.add_argument("--save-profile", metavar="FILE",
                        help="write the profile as analysed (after --resample, before levelling) to FILE (.txt/.csv, "
                             "x and height in m); for a map, its middle scan line")
    parser.set_defaults(handler=run)


def _resample_rows(surface, step):
    """PCHIP-resample every row of a map along x [m]."""
    import numpy as np
    from scipy.interpolate import PchipInterpolator

    from memstribo.errors import InputError

    ny, nx = surface.heights.shape
    x = np.arange(nx) * surface.dx
    n = int(np.floor(x[-1] / step * (1 + 1e-12))) + 1
    if n < 3:
        raise InputError(f"--resample {step:.4g} m leaves fewer than 3 points per scan line ({x[-1]:.4g} m long).")
    x_new = np.arange(n) * step
    return PchipInterpolator(x, surface.heights, axis=1)(np.minimum(x_new, x[-1]))


def run(args, params):
    from memstribo.surfaces import roughness as rough
    from memstribo.surfaces.readers import SurfaceMap, read_topography
    from memstribo.units import to_si

    from memstribo.errors import InputError
    from memstribo.parameters import check_points

    step = None
    if args.resample is not None:
        step = to_si(args.resample, "m", "--resample")
        if not 1e-12 <= step <= 1e-3:
            raise InputError(f"--resample must be a positive length from 1 pm to 1 mm ('39 nm'), got '{args.resample}'.")
    notes = []
    if args.path == "thesis":
        if step is not None:
            check_points(params["roughness_length"], step, "--resample")
        surface = rough.default_profile(params, spacing=step)
        step = None
        notes.append("SYNTHETIC profile: the thesis's AFM scan is not published; this seeded Gaussian profile has the "
                     "chapter-4 Rq and rms slope at the 78 nm step, then PCHIP-resampled (see 'source').")
    else:
        surface = read_topography(args.path, channel=args.channel, unit=args.unit, physical_size=args.physical_size)
    values = {}
    if isinstance(surface, SurfaceMap):
        import numpy as np

        heights, dx = surface.heights, surface.dx
        if step is not None:
            from memstribo.parameters import MAX_POINTS

            n = check_points(surface.physical_sizes[0], step, "--resample")
            if n * surface.shape[0] > MAX_POINTS:
                raise InputError(f"--resample {step:.3g} m: {surface.shape[0]} scan lines x {n:,} points is more "
                                 f"than {MAX_POINTS:,} heights (the arrays would not fit in memory); use a larger "
                                 "step.")
            heights, dx = _resample_rows(surface, step), step
        lines = rough.line_scan_statistics(heights, dx)
        areal = rough.areal_statistics(surface.heights, surface.dx, surface.dy)
        values.update({key: getattr(lines, key) for key in _KEYS})
        values.update(areal.to_dict())
        values.update(n_line_scans=lines.n_line_scans, Rq_std=lines.Rq_std, channel=surface.channel, kind="map",
                      dy=surface.dy, n_rows=int(np.shape(surface.heights)[0]))
        notes.append("R values: every scan line (row along x) levelled by its own least-squares line; Rq and rms_slope "
                     "pooled over the lines (rms), lambda_q from them, the others averaged over the lines.")
        notes.append("S values: the whole map levelled by its least-squares plane (ISO 25178).")
    else:
        if step is not None:
            check_points(float(surface.x[-1] - surface.x[0]), step, "--resample")
        profile = surface if step is None else rough.resample_pchip(surface, step)
        stats = rough.profile_statistics(profile)
        values.update({key: getattr(stats, key) for key in _KEYS})
        values.update(uniform=stats.uniform, kind="profile", channel=getattr(surface, "channel", "default"))
        if not stats.uniform:
            notes.append("non-uniform sampling: point-wise statistics, slopes between neighbouring points; "
                         "--resample STEP gives a uniform grid.")
    values.update(synthetic=bool(getattr(surface, "synthetic", False)), name=surface.name, source=surface.source)
    if args.save_profile:
        from memstribo.surfaces.readers import write_profile

        if isinstance(surface, SurfaceMap):
            scans = surface.line_scans()
            saved = scans[len(scans) // 2]
            if step is not None:
                saved = rough.resample_pchip(saved, step)
        else:
            saved = profile
        values["saved_profile"] = str(write_profile(saved, args.save_profile))
        notes.append(f"profile written to {values['saved_profile']} ({saved.name})")
    return CommandResult(values=values, title=f"roughness of {surface.name}", notes=notes)
