"""Sliding models of friction between nominally flat surfaces (thesis 2.6.2, 3.4; MODEL §4, §5).

Three models, each a function returning an :class:`xarray.Dataset` over the dimension
``step`` (coordinate ``sliding_distance`` [m]); :func:`summarize` gives the means and totals
printed by ``memstribo slide``.

- :func:`slide_single` (2.6.2): one nanoblock (one atomic block on one adhesive block on the
  bulk) under a fixed load on a flat counter surface: all bonds engaged all the time, a
  constant coefficient of friction, no elastic loss.
- :func:`slide_fixed_gap` (3.4.1) and :func:`slide_fixed_load` (3.4.2): a hierarchical
  structure of ``slider_blocks`` nanoblocks (each ``m x m`` atomic blocks on an adhesive
  block) sliding over a rigid rough counter profile, with its backing held at a fixed gap or
  free to move vertically under a fixed load.

Geometry of the structure models (memstribo's reading of Figures 3-16 to 3-19, 3-27):

- the nanoblocks sit side by side along the sliding direction ``x``; the ``m`` columns of
  atomic blocks of a nanoblock are centred on it at the pitch ``atomic_pitch``; the ``m``
  rows across the sliding direction see the same line profile (a line scan has no width);
- the interference of an atomic block with the counter surface is the highest point of the
  (linearly interpolated) profile under its face: the rigid flat face touches that point;
- a touching atomic block bonds chemically over the part of its face where the counter
  profile lies within one bond length ``D_chem`` of the face (``L_chem`` of (3-10));
- an adhesive block forms vdW bonds over the part of its face where the counter profile lies
  within the adhesive layer (thickness ``adhesive_layer_thickness``, unset: the
  adhesive-block height, thesis 3.5; the same rule as the meshing cycle,
  :func:`memstribo.physics.nanoblock.geometry.adhesive_layer_thickness`) below the face (``L_vdW`` of (3-12)), and adheres with the pull-off
  force (3-32) of a contact of half-width ``a = L_vdW / 2`` (``a = w_adh / 2`` when fully
  inside, as in 3.5);
- every time the structure slides by ``D_chem`` all current bonds break and re-form (3.5);
- the elastic interlocking energy (3-25) of a block is released once per bond length: per
  step of length ``dx`` it is ``1/2 k (d delta)^2 D_chem / dx``, which is (3-25) with
  ``delta_e`` the change of compression over one bond length and makes the result
  independent of the step once the step resolves the profile;
- the adhesive face does not touch the counter surface mechanically (only its atomic blocks
  do); that is the model's premise (the atomic blocks stand proud of it).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import asdict, dataclass, field
from types import SimpleNamespace

import numpy as np

from memstribo.checks import as_positive_scalar
from memstribo.physics import friction
from memstribo.errors import InputError
from memstribo.physics.nanoblock import mechanics
from memstribo.physics.nanoblock.geometry import adhesive_layer_thickness
from memstribo.physics.vdw_energy import vdw_bond_energy_of, vdw_site_density_of
from memstribo.quantities import attrs as quantity_attrs
from memstribo.references import cites

__all__ = [
    "MODELS",
    "SlideSummary",
    "slide",
    "slide_single",
    "slide_fixed_gap",
    "slide_fixed_load",
    "summarize",
    "structure_footprints",
]

MODELS = ("single", "fixed-gap", "fixed-load")

_CHUNK = 16384  # steps per vectorised chunk (bounds the memory of the footprint samples)


# --------------------------------------------------------------------------------------
# inputs
# --------------------------------------------------------------------------------------

def _geometry(params):
    from memstribo.physics.nanoblock.geometry import NanoblockGeometry

    return NanoblockGeometry.from_parameters(params)


def _constants(params):
    from memstribo.physics.adhesion import nanoscale_constants

    return nanoscale_constants(params)


def _positions(distance, step):
    distance = float(distance)
    if not math.isfinite(distance) or distance < 0:
        raise InputError(f"distance must be >= 0 [m], got {distance!r}.")
    step = as_positive_scalar(step, "step", "m")
    n = int(round(distance / step))
    if abs(n * step - distance) > 1e-9 * max(step, distance):
        n = int(math.ceil(distance / step))
    if n > 1_000_000:
        raise InputError(f"{n} steps: more than 1e6 (the per-block time series would not fit in memory); "
                         "use a larger step (--step, sliding_step) or a shorter distance.")
    positions = np.linspace(0.0, distance, n + 1) if n > 0 else np.zeros(1)
    return positions


# --------------------------------------------------------------------------------------
# profile queries (vectorised over steps and blocks)
# --------------------------------------------------------------------------------------

class _RangeMax:
    """Sparse table: maximum of ``z[i0:i1+1]`` for many index ranges at once (O(1) per query)."""

    def __init__(self, z):
        levels = [np.asarray(z, dtype=float)]
        width = 1
        while 2 * width <= levels[0].size:
            prev = levels[-1]
            levels.append(np.maximum(prev[:-width], prev[width:]))
            width *= 2
        self.levels = levels

    def query(self, i0, i1):
        length = i1 - i0 + 1
        valid = length >= 1
        safe_len = np.where(valid, length, 1)
        k = np.floor(np.log2(safe_len)).astype(int)
        out = np.full(np.shape(i0), -np.inf)
        for level in np.unique(k[valid]) if np.any(valid) else []:
            sel = valid & (k == level)
            table = self.levels[level]
            out[sel] = np.maximum(table[i0[sel]], table[i1[sel] - (1 << level) + 1])
        return out


def _footprint_max(x, z, table, left, right):
    """Exact maximum of the linear interpolant of (x, z) over [left, right] (arrays of any shape)."""
    ends = np.maximum(np.interp(left, x, z), np.interp(right, x, z))
    i0 = np.searchsorted(x, left, side="left")
    i1 = np.searchsorted(x, right, side="right") - 1
    return np.maximum(ends, table.query(i0, i1))


def structure_footprints(geometry, blocks):
    """Offsets of the atomic-block centres from the structure's trailing edge [m], shape (blocks, m).

    Parameters
    ----------
    geometry : NanoblockGeometry
    blocks : int
        Number of nanoblocks (adhesive blocks) side by side.
    """
    m = int(geometry.atomic_per_side)
    w_adh, w_at, pitch = geometry.adhesive_width, geometry.atomic_width, geometry.atomic_pitch
    span = (m - 1) * pitch + w_at
    if span > w_adh * (1 + 1e-12):
        raise InputError(f"{m} atomic blocks of width {w_at:g} m at pitch {pitch:g} m span {span:g} m, more than "
                         f"the adhesive block width {w_adh:g} m: reduce atomic_pitch or atomic_per_side.")
    if m > 1 and pitch < w_at:
        raise InputError(f"atomic_pitch {pitch:g} m is smaller than atomic_width {w_at:g} m: blocks would overlap.")
    columns = (np.arange(m) - (m - 1) / 2) * pitch
    return np.arange(blocks)[:, None] * w_adh + w_adh / 2 + columns[None, :]


# --------------------------------------------------------------------------------------
# dataset
# --------------------------------------------------------------------------------------

def _dataset(variables, positions, attrs):
    import xarray as xr

    # units and long names from the vocabulary (memstribo.quantities)
    data_vars = {name: (dims, np.asarray(values), quantity_attrs(name)) for name, (dims, values) in variables.items()}
    coords = {"sliding_distance": ("step", positions, quantity_attrs("sliding_distance", "distance slid"))}
    dataset = xr.Dataset(data_vars, coords=coords, attrs=attrs)
    return dataset


def _rates(bonds_chem, bonds_vdw, elastic_energy, steps, params):
    """Friction forces by mechanism and step energies, from bonds and interlocking energies."""
    d = params["bond_length"]
    f_chem = bonds_chem * params["bond_energy"] / d
    f_vdw = bonds_vdw * vdw_bond_energy_of(params) / d  # U_vdW by the set's vdw_energy_rule (MODEL 7h)
    safe = np.where(steps > 0, steps, 1.0)
    f_el = np.where(steps > 0, elastic_energy / safe, 0.0)
    return f_chem, f_vdw, f_el, f_chem * steps, f_vdw * steps, elastic_energy


def _cof(forces, normal, adhesion):
    pressing = normal + adhesion
    safe = np.where(pressing > 0, pressing, 1.0)
    return [np.where(pressing > 0, f / safe, 0.0) for f in forces]


# --------------------------------------------------------------------------------------
# single nanoblock (2.6.2)
# --------------------------------------------------------------------------------------

@cites("thesis", "model")
def slide_single(params, *, load=None, distance=None, step=None):
    """One nanoblock sliding under a fixed load on a flat counter surface (2.6.2 in [1]_).

    A single atomic block (``w_at`` square, ``H_at`` high) on a single adhesive block on the
    bulk, pressed with ``load`` against a flat surface. Its whole atomic face bonds
    chemically (``N_chem = (w_at / D_chem)^2``) and its whole adhesive face lies inside the
    adhesive layer (``N_vdW = (w_adh / D_chem)^2``, ``F_adh = F_adh,1`` with
    ``a = w_adh / 2``). Nothing changes while it slides: the coefficient of friction is
    constant and there is no elastic interlocking.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameter set.
    load : float, optional
        Normal load ``P`` [N], > 0; default ``normal_load`` (25 uN).
    distance : float, optional
        Sliding distance [m], >= 0; default 100 bond lengths.
    step : float, optional
        Sliding step [m]; default ``sliding_step`` (unset: ``bond_length``).

    Returns
    -------
    xarray.Dataset
        Over ``step``; each variable with its unit and long name from :mod:`memstribo.quantities`.

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, section 2.6.2.
    """
    load = as_positive_scalar(params["normal_load"] if load is None else load, "load", "N")
    d = params["bond_length"]
    step = params["sliding_step"] or d if step is None else step
    positions = _positions(100 * d if distance is None else distance, step)
    n = positions.size
    geometry = _geometry(params)
    single = SimpleNamespace(**{**{k: getattr(geometry, k) for k in ("atomic_width", "atomic_height",
                                                                      "adhesive_width", "adhesive_height",
                                                                      "bulk_height")}, "atomic_per_side": 1})
    constants = _constants(params)
    stiffness = mechanics.BlockStiffness.from_geometry(single, params["youngs_modulus"],
                                                       constants.contact_modulus, params["threshold_strain"])
    state = mechanics.structure_fixed_load(np.zeros((1, 1)), stiffness, load)
    bonds_chem = np.full(n, friction.full_overlap_bond_count(geometry.atomic_width, d))
    bonds_vdw = np.full(n, friction.vdw_bond_count(geometry.adhesive_width, geometry.adhesive_width, d,
                                                   vdw_site_density_of(params)))
    adhesion = np.full(n, constants.pull_off_force_block)
    normal = np.full(n, float(state.total_force))
    steps = np.diff(positions, prepend=positions[0])
    f_chem, f_vdw, f_el, e_chem, e_vdw, e_el = _rates(bonds_chem, bonds_vdw, np.zeros(n), steps, params)
    total = f_chem + f_vdw + f_el
    cof, cof_chem, cof_vdw, cof_el = _cof([total, f_chem, f_vdw, f_el], normal, adhesion)
    tile = lambda a: np.broadcast_to(a, (n,) + np.shape(a)).copy()  # noqa: E731
    variables = {
        "normal_force": ("step", normal), "adhesion_force": ("step", adhesion),
        "friction_force": ("step", total), "friction_force_chemical": ("step", f_chem),
        "friction_force_vdw": ("step", f_vdw), "friction_force_elastic": ("step", f_el),
        "cof": ("step", cof), "cof_chemical": ("step", cof_chem), "cof_vdw": ("step", cof_vdw),
        "cof_elastic": ("step", cof_el), "bonds_chemical": ("step", bonds_chem),
        "bonds_vdw": ("step", bonds_vdw), "energy_chemical": ("step", e_chem),
        "energy_vdw": ("step", e_vdw), "energy_elastic": ("step", e_el),
        "atomic_in_contact": ("step", np.ones(n)),
        "max_atomic_stress": ("step", np.full(n, float(state.atomic_force.max()) / stiffness.atomic_area)),
        "approach": ("step", np.full(n, float(state.approach))),
        "load_residual": ("step", np.full(n, float(state.residual))),
        "block_force": (("step", "block"), tile(state.adhesive_force)),
        "adhesive_compression": (("step", "block"), tile(state.adhesive_compression)),
        "bulk_compression": (("step", "block"), tile(state.bulk_compression)),
        "shrink": (("step", "block"), tile(state.shrink)),
        "atomic_compression": (("step", "block", "atomic"), tile(state.atomic_compression)),
        "atomic_stress": (("step", "block", "atomic"), tile(state.atomic_force / stiffness.atomic_area)),
        "atomic_rigid": (("step", "block", "atomic"), tile(state.rigid.astype(np.int8))),
    }
    attrs = {"model": "single", "load": load, "profile": "flat counter surface",
             "profile_source": "flat", "synthetic_profile": 0}
    return _dataset(variables, positions, attrs)


# --------------------------------------------------------------------------------------
# hierarchical structure on a rough profile (3.4)
# --------------------------------------------------------------------------------------

def _prepare_profile(profile, params):
    from memstribo.surfaces.roughness import default_profile, level_profile

    if profile is None:
        profile = default_profile(params)
    elif hasattr(profile, "line_scans"):
        profile = profile.line_scans()[0]
    if not hasattr(profile, "x") or not hasattr(profile, "z"):
        raise InputError("profile must be a roughness.Profile (or a map whose first line scan is used).")
    return level_profile(profile)


def _slide_variables(r, positions, stiffness, d_chem, params, tips, mode) -> dict:
    """The slide's variables (name -> (dims, values)): forces, COF split, bonds, energies, block and atomic states;
    elastic interlocking released once per bond length (module docstring)."""
    steps = np.diff(positions, prepend=positions[0])
    d_at = np.diff(r["at_c"], axis=0, prepend=r["at_c"][:1])
    d_adh = np.diff(r["adh_c"], axis=0, prepend=r["adh_c"][:1])
    raw = (mechanics.elastic_interlocking_energy(stiffness.atomic, d_at).sum(axis=(-2, -1))
           + mechanics.elastic_interlocking_energy(stiffness.adhesive, d_adh).sum(axis=-1))
    safe = np.where(steps > 0, steps, 1.0)
    elastic = np.where(steps > 0, raw * d_chem / safe, 0.0)
    f_chem, f_vdw, f_el, e_chem, e_vdw, e_el = _rates(r["bonds_chem"], r["bonds_vdw"], elastic, steps, params)
    total = f_chem + f_vdw + f_el
    cof, cof_chem, cof_vdw, cof_el = _cof([total, f_chem, f_vdw, f_el], r["normal"], r["adhesion"])
    stress = r["at_f"] / stiffness.atomic_area
    variables = {
        "normal_force": ("step", r["normal"]), "adhesion_force": ("step", r["adhesion"]),
        "friction_force": ("step", total), "friction_force_chemical": ("step", f_chem),
        "friction_force_vdw": ("step", f_vdw), "friction_force_elastic": ("step", f_el),
        "cof": ("step", cof), "cof_chemical": ("step", cof_chem), "cof_vdw": ("step", cof_vdw),
        "cof_elastic": ("step", cof_el), "bonds_chemical": ("step", r["bonds_chem"]),
        "bonds_vdw": ("step", r["bonds_vdw"]), "energy_chemical": ("step", e_chem),
        "energy_vdw": ("step", e_vdw), "energy_elastic": ("step", e_el),
        "atomic_in_contact": ("step", r["contacts"]),
        "max_atomic_stress": ("step", stress.max(axis=(-2, -1))),
        "structure_height": ("step", tips - r["approach"]),
        "approach": ("step", r["approach"]),
        "block_force": (("step", "block"), r["block_force"]),
        "block_adhesion_force": (("step", "block"), r["block_adhesion"]),
        "adhesive_compression": (("step", "block"), r["adh_c"]),
        "bulk_compression": (("step", "block"), r["bulk_c"]),
        "shrink": (("step", "block"), r["shrink"]),
        "atomic_compression": (("step", "block", "atomic"), r["at_c"]),
        "atomic_stress": (("step", "block", "atomic"), stress),
        "atomic_rigid": (("step", "block", "atomic"), r["rigid"].astype(np.int8)),
    }
    if mode == "fixed-load":
        variables["load_residual"] = ("step", r["residual"])
    return variables


def _footprint_offsets(centres, w_at, w_adh, blocks, h):
    """Grid offsets (in steps of ``h`` [m]) of the samples across each atomic face (n, m, k) and adhesive face (n, k)."""
    def offsets(left_edge, width, samples):
        centres_ = left_edge[..., None] + (np.arange(samples) + 0.5) / samples * width
        return np.rint(centres_ / h).astype(np.intp)

    at_offsets = offsets(centres - w_at / 2, w_at, int(np.clip(round(w_at / h), 5, 17)))  # (n, m, k)
    adh_offsets = offsets(np.arange(blocks) * w_adh, w_adh, int(np.clip(round(w_adh / h), 9, 33)))  # (n, k)
    return at_offsets, adh_offsets


def _slide_distance(profile, x, blocks, w_adh, distance):
    """The sliding distance [m]: the given one, or all the profile allows; InputError if it does not fit."""
    length = blocks * w_adh
    available = x[-1] - x[0] - length
    if available < 0:
        raise InputError(f"profile '{profile.name}' is {x[-1] - x[0]:.4g} m long, shorter than the sliding "
                         f"structure ({blocks} blocks x {w_adh:.4g} m = {length:.4g} m): use a longer profile "
                         "or fewer slider_blocks.")
    if distance is None:
        return available
    if distance > available * (1 + 1e-12):
        raise InputError(f"sliding distance {distance:.4g} m does not fit on profile '{profile.name}': the "
                         f"structure ({length:.4g} m) can slide at most {available:.4g} m over it.")
    return distance


def _tips(params, mode, z, gap, load):
    """(height of the atomic blocks' tips [m], load [N] or None): at the gap (fixed gap; default Rq), or level with
    the profile's highest point (fixed load)."""
    if mode == "fixed-gap":
        if gap is None:
            gap = params["sliding_gap"]
        tips = float(np.sqrt(np.mean(z**2))) if gap is None else float(gap)  # default: Rq
        if not math.isfinite(tips):
            raise InputError(f"gap must be finite [m], got {gap!r}.")
        return tips, load
    load = as_positive_scalar(params["normal_load"] if load is None else load, "load", "N")
    return float(z.max()), load  # reference: tips level with the highest point of the profile


@cites("thesis", "model", "borodich_savencu_2017")
def _slide_structure(params, mode, profile=None, *, gap=None, load=None, distance=None, step=None,
                     progress=False):
    profile = _prepare_profile(profile, params)
    x, z = np.asarray(profile.x), np.asarray(profile.z)
    geometry = _geometry(params)
    constants = _constants(params)
    blocks = int(params["slider_blocks"])
    m = int(geometry.atomic_per_side)
    d_chem = params["bond_length"]
    step = (params["sliding_step"] or d_chem) if step is None else step
    w_at, w_adh = geometry.atomic_width, geometry.adhesive_width
    length = blocks * w_adh
    distance = _slide_distance(profile, x, blocks, w_adh, distance)
    positions = _positions(distance, step)
    centres = structure_footprints(geometry, blocks)  # (n, m)
    table = _RangeMax(z)
    layer = adhesive_layer_thickness(params, geometry)  # one rule with the meshing cycle
    stiffness = mechanics.BlockStiffness.from_geometry(geometry, params["youngs_modulus"],
                                                       constants.contact_modulus, params["threshold_strain"])
    tips, load = _tips(params, mode, z, gap, load)

    # The m rows of atomic blocks across the sliding direction see the same line profile: solve
    # for one block per column with m times the stiffness (exact), then spread the result.
    columns = dataclasses.replace(stiffness, atomic=m * stiffness.atomic, atomic_area=m * stiffness.atomic_area)
    # The profile on a uniform grid aligned with the steps and fine enough for the footprints
    # (<= w_at / 16): the bond fractions are then gathers, not interpolations.
    n_steps = positions.size
    slide_step = float(positions[1] - positions[0]) if n_steps > 1 else float(step)
    refine = max(1, math.ceil(slide_step / (w_at / 16) - 1e-9))
    h = slide_step / refine
    n_grid = (n_steps - 1) * refine + int(math.ceil(length / h)) + 2
    grid = np.interp(np.minimum(x[0] + h * np.arange(n_grid), x[-1]), x, z)
    at_offsets, adh_offsets = _footprint_offsets(centres, w_at, w_adh, blocks, h)
    out = {key: [] for key in ("bonds_chem", "bonds_vdw", "adhesion", "block_adhesion", "normal", "approach",
                               "residual", "block_force", "adh_c", "bulk_c", "shrink", "at_c", "at_f", "rigid",
                               "contacts")}
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=n_steps, desc=f"slide {mode}", unit="step", unit_scale=True, leave=False)
    full_chem = friction.full_overlap_bond_count(w_at, d_chem)
    full_vdw = friction.vdw_bond_count(w_adh, w_adh, d_chem, vdw_site_density_of(params))
    for start in range(0, n_steps, _CHUNK):
        if bar is not None and start:
            bar.update(_CHUNK)
        pos = positions[start:start + _CHUNK] + x[0]
        left = pos[:, None, None] + centres[None] - w_at / 2  # (N, n, m)
        peak = _footprint_max(x, z, table, left, left + w_at)
        if mode == "fixed-gap":
            state = mechanics.structure_fixed_gap(peak - tips, columns)
        else:
            state = mechanics.structure_fixed_load(peak - tips, columns, load)
        spread = lambda a: np.repeat(a[:, :, None, :], m, axis=2).reshape(a.shape[:2] + (m * m,))  # noqa: E731
        base = (np.arange(start, start + pos.size) * refine)[:, None, None]
        # chemical bonds: the part of each touching atomic face within one bond length of the profile
        samples = grid[np.minimum(base[..., None] + at_offsets, n_grid - 1)]  # (N, n, m, k)
        chem_fraction = (samples >= (peak - d_chem)[..., None]).mean(axis=-1)
        touching = state.atomic_force > 0
        chem = chem_fraction * touching
        # vdW bonds: the part of each adhesive face inside the adhesive layer
        u = state.adhesive_compression + state.bulk_compression
        face = tips - state.approach[:, None] + u + geometry.atomic_height  # (N, n)
        samples = grid[np.minimum(base + adh_offsets, n_grid - 1)]  # (N, n, k)
        vdw_fraction = (samples >= (face - layer)[..., None]).mean(axis=-1)
        block_adhesion = constants.pull_off_force_block * vdw_fraction**1.5  # (3-32) with a = L_vdW / 2
        out["bonds_chem"].append(m * chem.sum(axis=(-2, -1)) * full_chem)
        out["bonds_vdw"].append(vdw_fraction.sum(axis=-1) * full_vdw)
        out["block_adhesion"].append(block_adhesion)
        out["adhesion"].append(friction.adhesion_force(block_adhesion))
        out["normal"].append(state.total_force)
        out["approach"].append(state.approach)
        out["residual"].append(state.residual)
        out["block_force"].append(state.adhesive_force)
        out["adh_c"].append(state.adhesive_compression)
        out["bulk_c"].append(state.bulk_compression)
        out["shrink"].append(state.shrink)
        out["at_c"].append(spread(state.atomic_compression))
        out["at_f"].append(spread(state.atomic_force / m))
        out["rigid"].append(spread(state.rigid))
        out["contacts"].append(m * touching.sum(axis=(-2, -1)))
    if bar is not None:
        bar.close()
    r = {key: np.concatenate(values, axis=0) for key, values in out.items()}
    if mode == "fixed-gap" and not np.any(r["contacts"]):
        raise InputError(f"gap {tips:.4g} m: no atomic block touches the counter profile anywhere on the slide "
                         f"(highest point {z.max():.4g} m above the mean line); give a smaller gap.")
    variables = _slide_variables(r, positions, stiffness, d_chem, params, tips, mode)
    attrs = {"model": mode, "profile": profile.name, "profile_source": profile.source,
             "synthetic_profile": int(bool(getattr(profile, "synthetic", False))),
             "adhesive_layer_thickness": layer, "slider_blocks": blocks}
    if mode == "fixed-gap":
        attrs["gap"] = tips
    else:
        attrs["load"] = load
    return _dataset(variables, positions, attrs)


def slide_fixed_gap(params, profile=None, *, gap=None, distance=None, step=None, progress=False):
    """Hierarchical structure sliding at a fixed gap over a rough profile (3.4.1 in [1]_).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameter set (geometry, constants, ``slider_blocks``, ``sliding_gap``, ...).
    profile : roughness.Profile or readers.SurfaceMap, optional
        Counter surface (levelled here); default: the seeded synthetic thesis profile
        (:func:`memstribo.surfaces.roughness.default_profile`); of a map, the first line scan.
    gap : float, optional
        Height of the undeformed atomic tips above the profile's mean line [m] (negative:
        interference); default ``sliding_gap`` (unset: the profile's Rq).
    distance : float, optional
        Sliding distance [m]; default: as far as the profile allows.
    step : float, optional
        Sliding step [m]; default ``sliding_step`` (unset: ``bond_length``).
    progress : bool
        Show a progress bar on stderr.

    Returns
    -------
    xarray.Dataset
        Over ``step`` (coordinate ``sliding_distance``), with per-block (``block``) and
        per-atomic-block (``block``, ``atomic``) variables; ``attrs`` name the profile.

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, section 3.4.1.
    """
    return _slide_structure(params, "fixed-gap", profile, gap=gap, distance=distance, step=step,
                            progress=progress)


def slide_fixed_load(params, profile=None, *, load=None, distance=None, step=None, progress=False):
    """Hierarchical structure with a vertical degree of freedom under a fixed load (3.4.2 in [1]_).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameter set.
    profile : roughness.Profile or readers.SurfaceMap, optional
        Counter surface; default: the seeded synthetic thesis profile.
    load : float, optional
        Normal load [N], > 0; default ``normal_load`` (25 uN).
    distance, step, progress
        As in :func:`slide_fixed_gap`.

    Returns
    -------
    xarray.Dataset
        As :func:`slide_fixed_gap`, plus ``load_residual`` (exact solver: round-off).

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, section 3.4.2.
    """
    return _slide_structure(params, "fixed-load", profile, load=load, distance=distance, step=step,
                            progress=progress)


def slide(model, params, profile=None, *, gap=None, load=None, distance=None, step=None, progress=False):
    """Run one of :data:`MODELS` ("single", "fixed-gap", "fixed-load").

    The dataset's attributes carry the limits of silicon that :func:`summarize` checks
    (``atomic_area`` [m^2], ``elastic_limit_pressure`` [Pa], ``ideal_shear_strength`` [Pa]).
    """
    if model == "single":
        if profile is not None or gap is not None:
            raise InputError("the single model slides on a flat surface under a load: it takes no profile or gap.")
        dataset = slide_single(params, load=load, distance=distance, step=step)
    elif model == "fixed-gap":
        if load is not None:
            raise InputError("the fixed-gap model takes a gap, not a load (use --model fixed-load).")
        dataset = slide_fixed_gap(params, profile, gap=gap, distance=distance, step=step, progress=progress)
    elif model == "fixed-load":
        if gap is not None:
            raise InputError("the fixed-load model takes a load, not a gap (use --model fixed-gap).")
        dataset = slide_fixed_load(params, profile, load=load, distance=distance, step=step, progress=progress)
    else:
        raise InputError(f"unknown sliding model {model!r}: allowed are {', '.join(MODELS)}.")
    dataset.attrs.update(atomic_area=float(params["atomic_width"]) ** 2,
                         elastic_limit_pressure=float(params["elastic_limit_pressure"]),
                         ideal_shear_strength=float(params["ideal_shear_strength"]))
    return dataset


def physical_limits(dataset) -> tuple[float, list[str]]:
    """Largest friction stress on the touching atomic blocks [Pa], and warnings of silicon's limits (MODEL 7c).

    The friction stress is the friction force over the area of the atomic blocks in contact
    (``atomic_in_contact`` times ``atomic_area``); a warning names every limit passed: the
    ideal shear strength of silicon (friction stress) and the elastic limit (normal stress on an
    atomic block). Without the limits in the attributes (a dataset not made by :func:`slide`)
    there are no warnings.
    """
    area = dataset.attrs.get("atomic_area")
    touching = np.asarray(dataset["atomic_in_contact"].values, dtype=float) if "atomic_in_contact" in dataset else None
    shear = 0.0
    if area and touching is not None:
        force = np.asarray(dataset["friction_force"].values, dtype=float)
        stress = np.divide(force, touching * area, out=np.zeros_like(force), where=touching > 0)
        shear = float(stress.max()) if stress.size else 0.0
    warnings = []
    strength = dataset.attrs.get("ideal_shear_strength")
    if strength and shear > strength:
        warnings.append(f"the friction stress on the touching atomic blocks reaches {shear / 1e9:.3g} GPa, above the "
                        f"ideal shear strength of silicon ({strength / 1e9:.3g} GPa): the blocks would shear off")
    limit = dataset.attrs.get("elastic_limit_pressure")
    normal = float(dataset["max_atomic_stress"].max()) if "max_atomic_stress" in dataset else 0.0
    if limit and normal > limit:
        warnings.append(f"the normal stress on an atomic block reaches {normal / 1e9:.3g} GPa, above the elastic limit "
                        f"of silicon ({limit / 1e9:.3g} GPa): the elastic nanoblock model does not hold there")
    return shear, warnings


# --------------------------------------------------------------------------------------
# summary
# --------------------------------------------------------------------------------------

@dataclass(frozen=True)
class SlideSummary:
    """Means over a slide (what ``memstribo slide --json`` prints).

    Attributes
    ----------
    cof_mean, cof_chemical, cof_vdw, cof_elastic : float
        Means of the coefficient of friction and its parts over the steps [-] (the parts add up to cof_mean).
    friction_force_mean : float
        Mean friction force = total dissipated energy / distance [N].
    adhesion_force_mean, normal_force_mean : float
        Means over the steps [N].
    energy_chemical, energy_vdw, energy_elastic : float
        Energies dissipated over the whole slide, by mechanism [J] (totals, not means).
    fraction_chemical, fraction_vdw, fraction_elastic : float
        Shares of the dissipated energy [-] (thesis 3.6: > 0.6, rest, < 0.01).
    sliding_distance : float
        Distance slid in all [m].
    steps : int
        Number of positions.
    max_atomic_stress : float
        Largest normal stress on an atomic block [Pa].
    load_residual : float or None
        Largest relative force-balance error (fixed-load model only) [-].
    max_shear_stress : float
        Largest friction stress on the touching atomic blocks [Pa] (0 when unknown).
    warnings : list of str
        Limits of silicon passed (:func:`physical_limits`), empty when none.
    """

    cof_mean: float
    cof_chemical: float
    cof_vdw: float
    cof_elastic: float
    friction_force_mean: float
    adhesion_force_mean: float
    normal_force_mean: float
    energy_chemical: float
    energy_vdw: float
    energy_elastic: float
    fraction_chemical: float
    fraction_vdw: float
    fraction_elastic: float
    sliding_distance: float
    steps: int
    max_atomic_stress: float
    load_residual: float | None = None
    max_shear_stress: float = 0.0
    warnings: list = field(default_factory=list)

    def to_dict(self) -> dict:
        values = asdict(self)
        if values["load_residual"] is None:
            del values["load_residual"]
        return values


def summarize(dataset) -> SlideSummary:
    """Means and totals of a slide (see :class:`SlideSummary`)."""
    positions = dataset["sliding_distance"].values
    distance = float(positions[-1] - positions[0])
    moving = slice(1, None) if positions.size > 1 else slice(None)

    def mean(name):
        return float(dataset[name].values[moving].mean())

    energies = [float(dataset[name].values.sum()) for name in ("energy_chemical", "energy_vdw", "energy_elastic")]
    total = sum(energies)
    fractions = [e / total if total > 0 else 0.0 for e in energies]
    friction_force = total / distance if distance > 0 else mean("friction_force")
    residual = float(dataset["load_residual"].values.max()) if "load_residual" in dataset else None
    if dataset.attrs.get("model") == "fixed-gap":
        residual = None
    shear, warnings = physical_limits(dataset)
    return SlideSummary(
        cof_mean=mean("cof"), cof_chemical=mean("cof_chemical"), cof_vdw=mean("cof_vdw"),
        cof_elastic=mean("cof_elastic"), friction_force_mean=friction_force,
        adhesion_force_mean=mean("adhesion_force"), normal_force_mean=mean("normal_force"),
        energy_chemical=energies[0], energy_vdw=energies[1], energy_elastic=energies[2],
        fraction_chemical=fractions[0], fraction_vdw=fractions[1], fraction_elastic=fractions[2],
        sliding_distance=distance, steps=int(positions.size), max_atomic_stress=float(dataset["max_atomic_stress"].max()),
        load_residual=residual, max_shear_stress=shear, warnings=warnings,
    )
