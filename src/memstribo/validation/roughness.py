"""Validation rows of roughness and nanoblock geometry (thesis 3.4.1, 4.2; data/afm/README.md)."""

from __future__ import annotations

from pathlib import Path

from memstribo.validation.rows import ValidationRow, compare

AFM = Path(__file__).resolve().parents[3] / "data" / "afm"  # in a source tree; see afm_folder()
README = "data/afm/README.md (SurfaceTopography 1.25, height detrend)"

# file, channel, statistic, README value [nm], note
_FILES = [
    ("si_profile_linescan.txt", None, "Rq", 4.468, ""),
    ("si_profile_linescan.txt", None, "Ra", 3.403, ""),
    ("opdx-3.opdx", None, "Rq", 2.826, ""),
    ("container-2.zip", "stylus", "Rq", 12.65, "stylus member, x-z in mm (unit from meta.yml)"),
    ("container-2.zip", None, "Sq", 4.688, "NanoScope member's own calibration; meta.yml's height_scale not applied "
                                          "a second time (that would give 0.525 nm)"),
    ("di-3.di", None, "Sq", 35.22, "default channel ch0 ZSensor"),
    ("di-3.di", "Height", "Sq", 45.46, "channel ch3 Height"),
    ("example_ps.tiff", None, "Sq", 3.933, "Park TIFF, rows = scan lines along x"),
    ("IgorIBWReader_P0089OP0027.ibw", None, "Sq", 8.094, ""),
    ("topography_in_nanometers.txt", None, "Sq", 204.5, "own reader: 11 header lines, 128 x 128 row-major, nm"),
]


def _file_rows() -> list[ValidationRow]:
    from memstribo.surfaces.readers import SurfaceMap, read_topography
    from memstribo.surfaces.roughness import areal_statistics, profile_statistics

    rows = []
    afm = afm_folder() or AFM
    for name, channel, key, printed, note in _FILES:
        surface = read_topography(afm / name, channel=channel)
        if isinstance(surface, SurfaceMap):
            value = getattr(areal_statistics(surface.heights, surface.dx, surface.dy), key)
        else:
            value = getattr(profile_statistics(surface), key)
        option = f" --channel {channel}" if channel else ""
        decimals = len(str(printed).split(".")[1])
        rows.append(compare("roughness", f"{key} of {name}" + (f" ({channel})" if channel else ""), README, printed,
                            value * 1e9, "nm", atol=0.5 * 10 ** -decimals,
                            command=f"memstribo roughness data/afm/{name}{option} --json", note=note))
    tem = read_topography(afm / "container-2.zip", channel="80_Scale")
    rows.append(compare(
        "roughness", "Rq of the TEM profile (76 non-uniform points)", README + ", point-wise", 3.51,
        profile_statistics(tem).Rq * 1e9, "nm", atol=0.005, differs=(3.495, 3.505),
        command="memstribo roughness data/afm/container-2.zip --channel 80_Scale --json",
        note="differs on purpose: memstribo levels by the least-squares line through the points (3.504 nm); "
             "the README's 3.51 nm is point-wise after SurfaceTopography's integral line fit"))
    return rows


def _thesis_rows() -> list[ValidationRow]:
    from memstribo.physics.nanoblock.geometry import NanoblockGeometry, nanoblock_geometry_from_profile
    from memstribo.parameters import get_parameter_values
    from memstribo.surfaces.roughness import default_profile, profile_statistics

    params = get_parameter_values()
    command = "memstribo roughness thesis --resample '78 nm' --json"
    raw = profile_statistics(default_profile(params, spacing=params["roughness_sample_spacing"]))
    ch3 = params.updated({"roughness_rq": "1.6433 nm", "roughness_rms_slope": 0.0245,
                          "roughness_resample_spacing": "78 nm"})
    derived = nanoblock_geometry_from_profile(default_profile(ch3))
    ch3_command = ("memstribo nanoblock --from thesis --set roughness_rq=1.6433nm --set roughness_rms_slope=0.0245 "
                   "--set 'roughness_resample_spacing=78 nm' --json")
    explicit = NanoblockGeometry.from_parameters(params)
    return [
        compare("roughness", "Rq of the default (synthetic) profile at 78 nm", "thesis 4.2.3 (4-2)", 1.6235,
                raw.Rq * 1e9, "nm", rtol=1e-9, command=command,
                note="synthetic profile made to have the chapter-4 statistics (the scan is not published)"),
        compare("roughness", "rms slope of the default (synthetic) profile at 78 nm", "thesis 4.2.3 (4-6)", 0.0241,
                raw.rms_slope, "", rtol=1e-9, command=command),
        compare("roughness", "lambda_q of the default profile", "thesis 4.2.3 (4-5), printed", 58.4,
                raw.lambda_q * 1e9, "nm", rtol=1e-3, command=command, differs=(420.0, 426.0),
                note="differs on purpose: 2 pi Rq / Delta_q with the printed Rq = 1.6235 nm and Delta_q = 0.0241 is "
                     "423 nm; the printed 58.4 nm does not follow from them (MODEL §1.3). The atomic pitch of the "
                     "default parameter set keeps 58.4 nm"),
        compare("roughness", "H_at = 0.5 Rq (chapter 3, Rq = 1.6433 nm)", "thesis 3.4.1, printed", 0.82164,
                derived.atomic_height * 1e9, "nm", atol=1e-5, command=ch3_command,
                note="0.5 x 1.6433 nm = 0.821650 nm; the thesis truncates the last digit"),
        compare("roughness", "H_adh = 1.2 Rq (chapter 3, Rq = 1.6433 nm)", "thesis 3.4.1, printed", 2.11,
                derived.adhesive_height * 1e9, "nm", atol=0.005, command=ch3_command, differs=(1.97, 1.975),
                note="differs on purpose: 1.2 x 1.6433 nm = 1.972 nm; the printed 2.11 nm is 1.284 Rq. memstribo "
                     "applies the stated rule (MODEL §1.4)"),
        compare("roughness", "atomic blocks per nanoblock (parameter set)", "thesis 4.2.3, Figure 4-23", 9,
                explicit.n_atomic, "", atol=0, command="memstribo nanoblock --json"),
    ]


def afm_folder() -> Path | None:
    """The repository's data/afm/ folder: of the source tree memstribo runs from or, for an installed wheel
    (which does not carry it), of the checkout the command runs in (:func:`memstribo.output.checkout_root`)."""
    from memstribo.output import checkout_root

    root = checkout_root()
    folder = root / "data" / "afm" if root is not None else AFM
    return folder if folder.is_dir() else None


def measured_files_available() -> bool:
    """Whether the repository's data/afm/ folder is here (see :func:`afm_folder`)."""
    return afm_folder() is not None


def rows() -> list[ValidationRow]:
    """The rows of the measured files (from a checkout only) and of the thesis's roughness numbers."""
    return (_file_rows() if measured_files_available() else []) + _thesis_rows()
