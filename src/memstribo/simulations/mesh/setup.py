"""Set-up of a meshing cycle: gear geometry and load, the positions, the contact window, the roughness lines of
every row of nanoblocks on both flanks (:class:`MeshSetup`)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from memstribo.errors import InputError
from memstribo.materials.pair import contact_modulus_of, work_of_adhesion
from memstribo.physics.gear import GearPair, hertz_line_contact, tangential_force


#: Largest Hertz half-width over radius of relative curvature a / R_ef that a meshing cycle accepts: beyond it the
#: contact is as wide as the teeth's curvature and the half-space model (a << R) says nothing (#15 item 4).
HERTZ_RATIO_LIMIT = 0.5


# --------------------------------------------------------------------------------------------
# small published relations used here
# --------------------------------------------------------------------------------------------
def roll_coordinate(radius_of_curvature, base_radius):
    """Arc length of an involute from the base circle to the point of radius of curvature R.

    Parameters
    ----------
    radius_of_curvature : array_like
        R [m] (the distance to the base-circle tangency point, 4-20/4-21).
    base_radius : float
        r_b [m].

    Returns
    -------
    ndarray
        s = R^2 / (2 r_b) [m]; ds/dt = R omega is the surface speed u (4-12).
    """
    return np.asarray(radius_of_curvature, dtype=float) ** 2 / (2.0 * base_radius)


def _work_of_adhesion(params):
    """w12 of the parameter set, or A / (12 pi D0^2) (3-34) when unset [J/m^2]."""
    w = params["work_of_adhesion"]
    return float(work_of_adhesion(params["hamaker_constant"], params["cutoff_distance"]) if w is None else w)


# --------------------------------------------------------------------------------------------
# set-up: geometry, roughness on both flanks, lattices
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class MeshSetup:
    """Everything a meshing simulation needs besides the physics constants.

    Attributes
    ----------
    pair : GearPair
    positions : ndarray
        c of each step [m] (includes the pitch point c = 0).
    step_time : ndarray
        Time weight of each step (trapezoidal) [s].
    load : ndarray
        Normal load on the pair at each step, share(c) F_ext [N].
    rows : int
        Nanoblock rows across the face width [-].
    effective_face_width : float
        rows * w_adh [m].
    grid : ndarray
        x of the contact elements relative to the contact point [m].
    pinion_profiles, gear_profiles : list of (x, z)
        Levelled roughness of each row of each flank, x = roll coordinate [m].
    roughness_name : str
    roughness_synthetic : bool
    roughness_source : str
    grid_spacing : float
        Element width of the contact solves [m].
    row_roughness : memstribo.surfaces.roughness.RowRoughness
        How the rows' lines were made (measured, synthesised), and the lattice offsets.
    realisation : int
        Index of the roughness realisation.
    hertz_width_ratio : float
        Largest Hertz half-width over the radius of relative curvature a / R_ef of the cycle [-]
        (the half-space model needs a << R; refused above :data:`HERTZ_RATIO_LIMIT`, warned above 0.2).
    registry : LatticeRegistry or None
        Each row's lattice phase and orientation along the sliding direction (:func:`lattice_registry`);
        None: every row in the same registry.
    """

    pair: GearPair
    positions: np.ndarray
    step_time: np.ndarray
    load: np.ndarray
    rows: int
    effective_face_width: float
    grid: np.ndarray
    pinion_profiles: list
    gear_profiles: list
    roughness_name: str
    roughness_synthetic: bool
    roughness_source: str
    grid_spacing: float
    row_roughness: object
    realisation: int
    hertz_width_ratio: float = 0.0
    registry: object = None


@dataclass(frozen=True)
class LatticeRegistry:
    """Where each row's atomic-block lattices sit along the sliding direction (MODEL 7d).

    Attributes
    ----------
    pinion_phase, gear_phase : ndarray
        Shift of each row's nanoblock lattice along its flank's roll coordinate [m], in [0, w_adh): block k
        of row r spans [k w_adh + phase_r, (k + 1) w_adh + phase_r).
    gear_pitch_scale : ndarray
        Each row's gear atomic pitch along the sliding direction over the pinion's, 1 / cos(theta_r) [-]: the
        gear's lattice turned by theta_r in the plane of the flank (a square lattice: |theta| <= 45 deg).
    mode : str
        ``random`` or ``shared``.
    bond_phase : ndarray
        Each row's phase in the renewal period of its bonds (one bond length of sliding) at rest [-], in [0, 1): the
        atomic registry of the two crystals the row's bonds join (MODEL 7f). 0 for every row where ``shared``.
    """

    pinion_phase: np.ndarray
    gear_phase: np.ndarray
    gear_pitch_scale: np.ndarray
    mode: str
    bond_phase: np.ndarray = None


#: Stream of the seed sequence that draws the lattice registry, apart from the roughness lines' (so 'shared' leaves
#: every line as it was).
_REGISTRY_STREAM = 26


def lattice_registry(params, rows: int, realisation: int = 0) -> LatticeRegistry:
    """Each row's lattice phase and orientation along the sliding direction, seeded like the roughness lines.

    ``lattice_registry = 'random'`` (MODEL 7d): polysilicon grains, and involute flanks cut across crystal planes,
    have no common registry across the face width. Each row's pinion and gear lattices are shifted by phases
    uniform in [0, w_adh) and the gear's is turned by an angle uniform in [-45, 45] deg (all orientations of a
    square lattice), which stretches its atomic pitch along the sliding direction by 1 / cos(theta). The draws
    come from the seed sequence (``roughness_seed``, realisation, 26), apart from the roughness lines' stream.
    Each row's bonds also sit at a phase of their renewal period uniform in [0, 1) (the start-up force, MODEL 7f).
    ``'shared'``: no shift, no turn, phase 0: every row in the registry of a commensurate single-crystal contact.

    Parameters
    ----------
    params : Parameters
        ``lattice_registry``, ``roughness_seed``, ``adhesive_width`` [m].
    rows : int
        Rows of nanoblocks across the face width.
    realisation : int
        Index of the roughness realisation.

    Returns
    -------
    LatticeRegistry
    """
    if params["lattice_registry"] == "shared":
        return LatticeRegistry(np.zeros(rows), np.zeros(rows), np.ones(rows), "shared", np.zeros(rows))
    rng = np.random.default_rng(np.random.SeedSequence([int(params["roughness_seed"]), int(realisation),
                                                        _REGISTRY_STREAM]))
    w_adh = float(params["adhesive_width"])
    pinion, gear = rng.random(rows) * w_adh, rng.random(rows) * w_adh
    theta = rng.uniform(-0.25 * math.pi, 0.25 * math.pi, rows)
    bond_phase = rng.random(rows)  # drawn last: the phases and turns above stay as they were (version 3)
    return LatticeRegistry(pinion, gear, 1.0 / np.cos(theta), "random", bond_phase)


def _positions(pair: GearPair, steps: int) -> np.ndarray:
    """``steps`` positions from c_f to c_l, nearly uniform, with the pitch point c = 0 among them."""
    c_f, c_l = pair.first_contact, pair.last_contact
    n_before = int(round((steps - 1) * (-c_f) / (c_l - c_f)))
    n_before = min(max(n_before, 1), steps - 2)
    before = np.linspace(c_f, 0.0, n_before + 1)
    after = np.linspace(0.0, c_l, steps - n_before)
    return np.concatenate([before, after[1:]])


def _flank_ranges(pair, positions, window):
    r1, r2 = pair.radii_of_curvature(positions)
    s1 = roll_coordinate(r1, pair.base_radii[0])
    s2 = roll_coordinate(r2, pair.base_radii[1])
    half = 0.5 * window
    return s1, s2, (s1.min() - half, s1.max() + half), (s2.min() - half, s2.max() + half)


def orient_map(surface, sliding_axis: str = "x"):
    """A map turned so that its rows run along the sliding direction (the flank's roll coordinate).

    ``sliding_axis="x"``: the scan lines (rows along x) run along the flank, as scanned;
    ``"y"``: the map is transposed, its columns become the lines. Profiles pass unchanged.
    """
    if sliding_axis not in ("x", "y"):
        raise InputError(f"sliding axis must be 'x' or 'y', got {sliding_axis!r}.")
    if sliding_axis == "y" and not hasattr(surface, "line_scans"):  # was ignored without a word (issue #41)
        raise InputError(f"--sliding-axis y needs a 2D map, but the roughness '{getattr(surface, 'source', '')}' is "
                         "a profile (one line, along x); allowed for a profile: --sliding-axis x (the default).")
    if sliding_axis == "x":
        return surface
    from dataclasses import replace

    return replace(surface, heights=np.ascontiguousarray(np.asarray(surface.heights).T), dx=surface.dy,
                   dy=surface.dx, source=f"{surface.source}; transposed: sliding along y")


def _read_roughness(roughness, sliding_axis="x"):
    """A Profile, a map (rows along the sliding direction), or None (the synthetic default)."""
    from memstribo.surfaces import roughness as rough

    if roughness is None or (isinstance(roughness, str) and roughness == "thesis"):
        if sliding_axis == "y":
            raise InputError("--sliding-axis y needs a 2D map, but the default roughness ('thesis') is a synthetic "
                             "profile; give a map with --roughness, or leave --sliding-axis at x.")
        return None
    if isinstance(roughness, (str, Path)):
        from memstribo.surfaces.readers import read_topography

        return orient_map(read_topography(roughness), sliding_axis)
    if isinstance(roughness, rough.Profile) or hasattr(roughness, "line_scans"):
        return orient_map(roughness, sliding_axis)
    raise InputError(f"roughness must be None, 'thesis', a file path, a Profile or a SurfaceMap; got "
                     f"{type(roughness).__name__}.")


def normal_force_of_load_case(params, pair: GearPair) -> float:
    """Total tooth normal force of the load case [N] (MODEL 7b).

    ``torque``: F_n = F_t / cos alpha_w with F_t = T / r_w1 (4-27), the force that the drive
    torque implies on the line of action; ``thesis``: ``normal_load`` as given (F_ext of 4.9).
    """
    if params["load_case"] == "thesis":
        return float(params["normal_load"])
    f_t = float(tangential_force(params["drive_torque"], pair.pitch_radii[0]))
    return f_t / math.cos(pair.pressure_angle)


def _prepare(params, roughness, steps, realisation=0, sliding_axis="x", window=None, lines=None) -> MeshSetup:
    """The set-up of a cycle; ``window`` [m] overrides the sized window (the cycle's self-sizing), ``lines``
    (a :class:`~memstribo.surfaces.roughness.RowRoughness`) are reused where they are long enough."""
    from memstribo.surfaces import roughness as rough

    pair = GearPair.from_parameters(params)
    steps = int(params["mesh_steps"] if steps is None else steps)
    if steps < 3:
        raise InputError(f"a meshing cycle needs at least 3 steps, got {steps}.")
    positions = _positions(pair, steps)
    t = pair.time(positions)
    step_time = np.concatenate([[0.5 * (t[1] - t[0])], 0.5 * (t[2:] - t[:-2]), [0.5 * (t[-1] - t[-2])]])
    share = pair.load_share(positions, params["load_sharing"])
    load = share * normal_force_of_load_case(params, pair)
    w_adh = params["adhesive_width"]
    rows = int(params["face_width"] // w_adh)
    if rows < 1:
        raise InputError(f"face_width ({params['face_width']:.4g} m) is narrower than one nanoblock "
                         f"(adhesive_width {w_adh:.4g} m).")
    # grid and window from the largest Hertz contact of the load case, unless given
    modulus = contact_modulus_of(params)
    hertz = hertz_line_contact(load, rows * w_adh, pair.effective_radius(positions), modulus)
    a_max = float(np.max(hertz.half_width))
    hertz_peak = hertz.peak_pressure
    if hertz_peak.max() > params["elastic_limit_pressure"]:
        i = int(np.argmax(hertz_peak))
        raise InputError(f"the tooth load ({load[i] * 1e6:.4g} µN, load case '{params['load_case']}') is beyond "
                         f"the elastic range: the Hertz peak pressure reaches {hertz_peak[i] / 1e9:.3g} GPa at c = "
                         f"{positions[i] * 1e6:.3g} µm, above the elastic limit of silicon "
                         f"({params['elastic_limit_pressure'] / 1e9:.3g} GPa, elastic_limit_pressure); the elastic "
                         "model of the thesis no longer holds.")
    ratio = float(np.max(hertz.half_width / pair.effective_radius(positions)))
    if ratio > HERTZ_RATIO_LIMIT:  # a contact as wide as the teeth's curvature: no half-space, no Hertz, no answer
        raise InputError(
            f"the contact of the teeth would be {a_max * 1e6:.3g} µm wide on each side, {ratio:.2g} times their radius "
            f"of relative curvature (E* = {modulus / 1e9:.3g} GPa under {float(np.max(load)) * 1e3:.3g} mN): the "
            f"elastic half-space contact model needs a half-width well below the radius (allowed: a/R_ef <= "
            f"{HERTZ_RATIO_LIMIT:g}). A counter body this soft, or this load, is outside the model; use a stiffer "
            "counter_youngs_modulus or a smaller load.")
    dx = params["mesh_grid_spacing"]
    if dx is None:
        dx = 2 * a_max / int(params["mesh_elements_across_contact"])
    if window is None:
        window = params["mesh_window"] or 2.4 * a_max + 6 * w_adh
    if params["mesh_grid_spacing"] is None:
        dx = min(dx, window / 64)  # a sized grid always has the 64 elements the solver needs
    n = int(round(window / dx))
    if n < 64:
        raise InputError(f"mesh_window / mesh_grid_spacing = {n}: at least 64 contact elements are needed.")
    from memstribo.parameters import check_mesh_size

    check_mesh_size(steps, n * dx, dx, what="mesh_steps" if steps == params["mesh_steps"] else "steps")
    grid = (np.arange(n) - 0.5 * (n - 1)) * dx
    _, _, (lo1, hi1), (lo2, hi2) = _flank_ranges(pair, positions, n * dx + 2 * w_adh)
    needed = max(hi1 - lo1, hi2 - lo2)
    if lines is None or min(float(p.x[-1] - p.x[0]) for p in lines.pinion + lines.gear) < needed:
        lines = rough.row_roughness(_read_roughness(roughness, sliding_axis), params, rows, needed, realisation)
    pinion, gear = [], []
    for scan_p, scan_g in zip(lines.pinion, lines.gear):
        for scan in (scan_p, scan_g):
            span = float(scan.x[-1] - scan.x[0])
            if span < needed:  # pragma: no cover - row_roughness synthesises long enough lines
                raise InputError(f"roughness line '{scan.name}' is {span * 1e6:.4g} µm long, but the flank travel "
                                 f"needs {needed * 1e6:.4g} µm.")
        # each line's middle sits at the middle of its flank's travel (independent of the window)
        zp = rough.level_profile(scan_p)
        pinion.append((zp.x - 0.5 * (zp.x[0] + zp.x[-1]) + 0.5 * (lo1 + hi1), zp.z))
        zg = rough.level_profile(scan_g)
        gear.append((zg.x - 0.5 * (zg.x[0] + zg.x[-1]) + 0.5 * (lo2 + hi2), zg.z))
    return MeshSetup(pair, positions, step_time, load, rows, rows * w_adh, grid, pinion, gear, lines.name,
                     lines.synthetic, lines.source, float(dx), lines, realisation, ratio,
                     lattice_registry(params, rows, realisation))


def _heights(profile, coordinate):
    from scipy.interpolate import PchipInterpolator

    x, z = profile
    return PchipInterpolator(x, z, extrapolate=False)(coordinate)


def _geometry(params):
    from memstribo.physics.nanoblock.geometry import NanoblockGeometry

    return NanoblockGeometry.from_parameters(params)
