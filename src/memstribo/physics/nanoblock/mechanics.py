"""Mechanics of nanoblocks: single columns and hierarchical structures (thesis 2.6, 3.3.6, 3.4).

A nanoblock is a column of three elastic segments in series: the atomic-subscale block
(width ``w_at``, height ``H_at``), the adhesive-subscale block (``w_adh``, ``H_adh``) and the
"considered bulk section" under it (``w_adh`` square, height ``H_bulk``). Each segment is a
linear spring of stiffness ``k = E A / H`` (3-24). Moduli follow MODEL §4 / thesis 2.6.2:
the bulk has silicon's Young's modulus ``E``; the adhesive and atomic subscales have the
contact modulus ``E*``.

The hierarchical structure of 3.4 carries ``m x m`` atomic blocks in parallel on each
adhesive block, and ``n`` nanoblocks side by side under a rigid backing (the "top" of the
structure). Conventions used throughout:

- compressions are positive [m]; contacts are unilateral (an atomic block that does not
  touch the counter surface carries no force, never tension);
- ``overlap`` is the interference [m] of each atomic block's undeformed tip with the
  (rigid) counter surface at zero structure displacement: positive means the block would
  penetrate the counter surface by that much;
- atomic blocks follow the bilinear elastic–perfectly-rigid law (Figure 3-13): Hooke's law
  up to the threshold compression ``threshold_strain * H_at``, then rigid, so that further
  approach compresses the adhesive block and the bulk ("the adhesive block carries the
  rest"); the force in a rigid block is whatever equilibrium needs;
- each nanoblock has its own bulk segment (a ``w_adh x w_adh x H_bulk`` column, MODEL §4),
  so under a fixed gap the nanoblocks are independent; under a fixed load they share the
  one rigid backing, whose displacement ``approach`` is found from the force balance.

All solvers are exact: the force–approach relation of a nanoblock is piecewise linear, so
sorting its breakpoints gives the solution without iteration. Every function is vectorised
over leading batch dimensions (the steps of a slide or of a meshing cycle).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "BlockStiffness",
    "ColumnState",
    "StructureState",
    "axial_stiffness",
    "column_fixed_gap",
    "column_fixed_load",
    "structure_fixed_gap",
    "structure_fixed_load",
    "elastic_interlocking_energy",
    "structure_interlocking_energy",
]


@cites("thesis")
def axial_stiffness(youngs_modulus, area, height):
    """Axial stiffness of a prismatic block, ``k = E A / H``.

    Parameters
    ----------
    youngs_modulus : numeric
        Modulus of the block [Pa].
    area : numeric
        Cross-section [m^2].
    height : numeric
        Height (length along the load) [m].

    Returns
    -------
    numeric
        Stiffness [N/m].

    Notes
    -----
    From :math:`\\delta = P H / (E A)`, Eq. (3-24) in [1]_.

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, section 3.3.6.

    Examples
    --------
    >>> round(float(axial_stiffness(85e9, (19.5e-9) ** 2, 0.82e-9)), 1)  # one atomic block, Si/Si [N/m]
    39416.2
    """
    youngs_modulus = as_array(youngs_modulus, "youngs_modulus", "Pa", positive=True)
    area = as_array(area, "area", "m^2", positive=True)
    return youngs_modulus * area / as_array(height, "height", "m", positive=True)


@dataclass(frozen=True)
class BlockStiffness:
    """Stiffnesses of the segments of a hierarchical nanoblock structure.

    Attributes
    ----------
    atomic : float
        Stiffness of one atomic block, ``E* w_at^2 / H_at`` [N/m].
    adhesive : float
        Stiffness of one adhesive block, ``E* w_adh^2 / H_adh`` [N/m].
    bulk : float
        Stiffness of the bulk segment under one nanoblock, ``E w_adh^2 / H_bulk`` [N/m].
    atomic_threshold : float
        Compression at which an atomic block turns rigid, ``threshold_strain * H_at`` [m].
    atomic_area, adhesive_area : float
        Cross-sections of an atomic and an adhesive block [m^2].
    atomic_height, adhesive_height, bulk_height : float
        Heights of the segments [m].
    atomic_per_side : int
        ``m``: each nanoblock carries ``m x m`` atomic blocks [-].
    """

    atomic: float
    adhesive: float
    bulk: float
    atomic_threshold: float
    atomic_area: float
    adhesive_area: float
    atomic_height: float
    adhesive_height: float
    bulk_height: float
    atomic_per_side: int

    @property
    def column(self) -> float:
        """Adhesive block and bulk in series [N/m]."""
        return 1.0 / (1.0 / self.adhesive + 1.0 / self.bulk)

    @property
    def atomic_threshold_force(self) -> float:
        """Force in an atomic block at the threshold compression [N]."""
        return self.atomic * self.atomic_threshold

    @classmethod
    def from_geometry(cls, geometry, youngs_modulus: float, contact_modulus: float,
                      threshold_strain: float) -> "BlockStiffness":
        """Stiffnesses from a :class:`~memstribo.physics.nanoblock.geometry.NanoblockGeometry`.

        Parameters
        ----------
        geometry : NanoblockGeometry
            Any object with ``atomic_width``, ``atomic_height``, ``adhesive_width``,
            ``adhesive_height``, ``atomic_per_side`` and ``bulk_height`` ([m]; a
            ``bulk_height`` of ``None`` means ``adhesive_width``, MODEL §4).
        youngs_modulus : float
            Young's modulus of the bulk [Pa] (161 GPa for silicon).
        contact_modulus : float
            Contact modulus ``E*`` used for the adhesive and atomic subscales [Pa] (85 GPa, Si/Si).
        threshold_strain : float
            Strain at which an atomic block turns rigid (0.3, Figure 3-13) [-].
        """
        try:
            w_at = float(geometry.atomic_width)
            h_at = float(geometry.atomic_height)
            w_adh = float(geometry.adhesive_width)
            h_adh = float(geometry.adhesive_height)
            m = int(geometry.atomic_per_side)
            h_bulk = getattr(geometry, "bulk_height", None)
        except AttributeError as exc:
            raise InputError(f"geometry lacks a nanoblock dimension: {exc}.") from None
        h_bulk = w_adh if h_bulk is None else float(h_bulk)
        for name, value in [("atomic_width", w_at), ("atomic_height", h_at), ("adhesive_width", w_adh),
                            ("adhesive_height", h_adh), ("bulk_height", h_bulk)]:
            as_array(value, name, "m", positive=True)
        for name, value in [("youngs_modulus", youngs_modulus), ("contact_modulus", contact_modulus)]:
            as_array(value, name, "Pa", positive=True)
        if m < 1:
            raise InputError(f"atomic_per_side must be >= 1, got {m}.")
        if not 0 < threshold_strain <= 1:
            raise InputError(f"threshold_strain must be in (0, 1], got {threshold_strain!r}.")
        if m * w_at > w_adh * (1 + 1e-12):
            raise InputError(f"{m} x {m} atomic blocks of width {w_at:g} m do not fit on an adhesive block "
                             f"of width {w_adh:g} m.")
        a_at, a_adh = w_at**2, w_adh**2
        return cls(
            atomic=float(axial_stiffness(contact_modulus, a_at, h_at)),
            adhesive=float(axial_stiffness(contact_modulus, a_adh, h_adh)),
            bulk=float(axial_stiffness(youngs_modulus, a_adh, h_bulk)),
            atomic_threshold=float(threshold_strain * h_at),
            atomic_area=a_at, adhesive_area=a_adh,
            atomic_height=h_at, adhesive_height=h_adh, bulk_height=h_bulk,
            atomic_per_side=m,
        )


# --------------------------------------------------------------------------------------
# single column (2.6.1, 2.6.2)
# --------------------------------------------------------------------------------------

@dataclass(frozen=True)
class ColumnState:
    """State of a single three-segment column (atomic, adhesive, bulk in series).

    Attributes
    ----------
    compressions : ndarray
        Compressions ``delta_1, delta_2, delta_3`` of the atomic, adhesive and bulk segments [m],
        shape (..., 3).
    force : ndarray
        Compressive force in the column [N].
    gap : ndarray
        Distance ``G`` between the column's top and the counter surface's mean line [m].
    """

    compressions: np.ndarray
    force: np.ndarray
    gap: np.ndarray


def _column_inputs(counter_height, heights, moduli, areas):
    heights = as_array(heights, "heights", "m", positive=True)
    moduli = as_array(moduli, "moduli", "Pa", positive=True)
    areas = as_array(areas, "areas", "m^2", positive=True)
    if heights.shape[-1:] != (3,) or moduli.shape[-1:] != (3,) or areas.shape[-1:] != (3,):
        raise InputError("heights, moduli and areas must each give 3 values: atomic, adhesive, bulk.")
    h = as_array(counter_height, "counter_height", "m")
    return h, heights, moduli * areas / heights


@cites("thesis", "borodich_savencu_2017")
def column_fixed_gap(gap, counter_height, heights, moduli, areas) -> ColumnState:
    """Single nanoblock column held at a fixed gap, Eqs. (2-6) to (2-8) in [1]_.

    Parameters
    ----------
    gap : numeric
        Distance ``G`` from the column's top to the counter surface's mean line [m].
    counter_height : numeric
        Height ``h`` of the counter asperity above the mean line [m].
    heights : array_like, shape (3,)
        ``H_1, H_2, H_3``: atomic, adhesive and bulk segment heights [m].
    moduli : array_like, shape (3,)
        ``E_1, E_2, E_3`` [Pa].
    areas : array_like, shape (3,)
        ``A_1, A_2, A_3`` [m^2].

    Returns
    -------
    ColumnState

    Notes
    -----
    .. math::

        \\delta_1 = \\frac{h + H_1 + H_2 + H_3 - G}
                  {1 + \\frac{E_1 A_1 H_2}{E_2 A_2 H_1} + \\frac{E_1 A_1 H_3}{E_3 A_3 H_1}},
        \\quad \\delta_2 = \\delta_1 \\frac{E_1 A_1 H_2}{E_2 A_2 H_1},
        \\quad \\delta_3 = \\delta_1 \\frac{E_1 A_1 H_3}{E_3 A_3 H_1}

    The contact is unilateral: where ``h + H_1 + H_2 + H_3 < G`` the column does not
    touch and all compressions are zero (the thesis's formula would give tension).

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, section 2.6.
    .. [2] F. M. Borodich, O. Savencu (2017), doi:10.1007/978-3-319-59114-8_10
    """
    h, heights, k = _column_inputs(counter_height, heights, moduli, areas)
    g = as_array(gap, "gap", "m")
    interference = np.maximum(h + heights.sum(-1) - g, 0.0)
    ratio2 = k[..., 0] / k[..., 1]
    ratio3 = k[..., 0] / k[..., 2]
    delta1 = interference / (1.0 + ratio2 + ratio3)
    compressions = np.stack(np.broadcast_arrays(delta1, delta1 * ratio2, delta1 * ratio3), axis=-1)
    force = delta1 * k[..., 0]
    return ColumnState(compressions, force, np.broadcast_to(g, force.shape).copy())


@cites("thesis", "borodich_savencu_2017")
def column_fixed_load(load, counter_height, heights, moduli, areas) -> ColumnState:
    """Single nanoblock column under a fixed load ``P`` (2.6.2, Figure 2-7 in [1]_).

    Parameters
    ----------
    load : numeric
        Compressive force ``P`` on the column's top [N], >= 0.
    counter_height, heights, moduli, areas
        As in :func:`column_fixed_gap`.

    Returns
    -------
    ColumnState
        ``delta_i = P H_i / (E_i A_i)`` (3-24) and the gap ``G = h + sum(H_i - delta_i)`` (2-1).
    """
    h, heights, k = _column_inputs(counter_height, heights, moduli, areas)
    p = np.asarray(load, dtype=float)
    if not np.all(np.isfinite(p)) or np.any(p < 0):
        raise InputError(f"load must be finite and >= 0 (compression), got {load!r}.")
    compressions = p[..., None] / k
    gap = h + (heights - compressions).sum(-1)
    return ColumnState(compressions, np.broadcast_to(p, gap.shape).copy(), gap)


# --------------------------------------------------------------------------------------
# hierarchical structure (3.4.1, 3.4.2)
# --------------------------------------------------------------------------------------

@dataclass(frozen=True)
class StructureState:
    """Deformation and forces of a hierarchical nanoblock structure.

    Shapes: ``B`` = batch (steps), ``n`` = nanoblocks (adhesive blocks), ``M = m*m`` atomic
    blocks per nanoblock.

    Attributes
    ----------
    atomic_compression : ndarray, (B..., n, M)
        Compression of every atomic block [m] (at most the threshold compression).
    adhesive_compression : ndarray, (B..., n)
        Compression of every adhesive block [m].
    bulk_compression : ndarray, (B..., n)
        Compression of the bulk segment under every nanoblock [m].
    atomic_force : ndarray, (B..., n, M)
        Force carried by every atomic block [N].
    adhesive_force : ndarray, (B..., n)
        Force through every adhesive block (= the sum of its atomic forces) [N].
    total_force : ndarray, (B...)
        Normal force of the structure on the counter surface [N].
    rigid : ndarray of bool, (B..., n, M)
        Atomic blocks at the threshold compression (the rigid branch of the bilinear law).
    approach : ndarray, (B...)
        Displacement of the structure's rigid backing towards the counter surface, added
        to ``overlap`` [m]; zero under a fixed gap.
    residual : ndarray, (B...)
        Relative force-balance error ``|total_force - load| / load`` of a fixed-load solution;
        zero under a fixed gap [-].
    """

    atomic_compression: np.ndarray
    adhesive_compression: np.ndarray
    bulk_compression: np.ndarray
    atomic_force: np.ndarray
    adhesive_force: np.ndarray
    total_force: np.ndarray
    rigid: np.ndarray
    approach: np.ndarray
    residual: np.ndarray

    @property
    def shrink(self) -> np.ndarray:
        """Total shortening of each nanoblock column at its most compressed atomic block [m], (B..., n)."""
        return self.adhesive_compression + self.bulk_compression + self.atomic_compression.max(axis=-1)

    @property
    def in_contact(self) -> np.ndarray:
        """Atomic blocks that touch the counter surface (force > 0), (B..., n, M)."""
        return self.atomic_force > 0


def _check_overlap(overlap) -> np.ndarray:
    o = np.asarray(overlap, dtype=float)
    if o.ndim < 2:
        raise InputError(f"overlap must have shape (..., n_adhesive, m*m), got shape {o.shape}.")
    if not np.all(np.isfinite(o)):
        raise InputError("overlap must be finite (NaN or inf found); give the interference of every atomic "
                         "block [m], a large negative value where a block is far from the counter surface.")
    return o


def _column_knots(overlap_sorted_desc, ratio):
    """Positions ``d_k`` of the nanoblock's force-approach breakpoints.

    With ``s`` the position of the adhesive block's base relative to the counter surface
    (atomic compressions ``o_i + s``), the column is in balance when
    ``d = s + ratio * sum(max(o_i + s, 0))``; ``d_k`` is this at ``s = -o_(k)``.
    """
    o = overlap_sorted_desc
    k_index = np.arange(o.shape[-1])
    cum_before = np.cumsum(o, axis=-1) - o  # sum of the k larger overlaps
    return -o + ratio * (cum_before - k_index * o)


def _solve_columns(overlap, stiffness: BlockStiffness, approach):
    """Exact state of every nanoblock at a given backing displacement ``approach`` (B...)."""
    k_at, k_col, d_t = stiffness.atomic, stiffness.column, stiffness.atomic_threshold
    ratio = k_at / k_col
    o = overlap + approach[..., None, None]
    o_desc = -np.sort(-o, axis=-1)
    knots = _column_knots(o_desc, ratio)
    # number of atomic blocks in contact: knots strictly below d = 0
    p = (knots < 0.0).sum(axis=-1)
    cum = np.concatenate([np.zeros(o.shape[:-1] + (1,)), np.cumsum(o_desc, axis=-1)], axis=-1)
    s_p = np.take_along_axis(cum, p[..., None], axis=-1)[..., 0]
    s = -ratio * s_p / (1.0 + ratio * p)
    o_max = o_desc[..., 0]
    s_rigid = d_t - o_max
    rigid_col = s > s_rigid
    s = np.minimum(s, s_rigid)
    delta = np.clip(o + s[..., None], 0.0, d_t)
    elastic = k_at * delta
    u = -s  # adhesive + bulk compression of the column
    u = np.where(rigid_col, u, np.maximum(u, 0.0))
    column_force = k_col * np.maximum(u, 0.0)
    # rigid blocks (at the threshold) share what the elastic law cannot carry
    rigid = rigid_col[..., None] & (o >= o_max[..., None] - 1e-15 * np.maximum(np.abs(o_max[..., None]), 1e-30))
    rigid = rigid | (delta >= d_t * (1 - 1e-12)) & rigid_col[..., None]
    excess = column_force - elastic.sum(axis=-1)
    n_rigid = np.maximum(rigid.sum(axis=-1), 1)
    atomic_force = elastic + np.where(rigid, (np.maximum(excess, 0.0) / n_rigid)[..., None], 0.0)
    column_force = np.where(rigid_col, column_force, elastic.sum(axis=-1))
    return delta, atomic_force, column_force, rigid


def _state(overlap, stiffness, approach, residual):
    delta, atomic_force, column_force, rigid = _solve_columns(overlap, stiffness, approach)
    return StructureState(
        atomic_compression=delta,
        adhesive_compression=column_force / stiffness.adhesive,
        bulk_compression=column_force / stiffness.bulk,
        atomic_force=atomic_force,
        adhesive_force=column_force,
        total_force=column_force.sum(axis=-1),
        rigid=rigid,
        approach=approach,
        residual=residual,
    )


@cites("thesis", "borodich_savencu_2017")
def structure_fixed_gap(overlap, stiffness: BlockStiffness) -> StructureState:
    """Hierarchical structure held at a fixed gap (3.4.1 in [1]_), solved exactly.

    Parameters
    ----------
    overlap : array_like, shape (..., n_adhesive, m*m)
        Interference of every atomic block's undeformed tip with the rigid counter surface
        at the given gap [m] (positive: penetration; zero or negative: no contact).
    stiffness : BlockStiffness
        Segment stiffnesses and the atomic threshold compression.

    Returns
    -------
    StructureState
        ``approach`` and ``residual`` are zero.

    Notes
    -----
    For each nanoblock, with ``u`` the compression of its adhesive block and bulk in series
    (stiffness ``k_c``) and ``k_a`` the atomic stiffness, the atomic compressions are
    ``delta_i = min(max(o_i - u, 0), delta_t)`` and ``k_c u = sum k_a delta_i`` while no
    block is rigid. The left side minus the right is piecewise linear and increasing in
    ``u``; sorting the overlaps gives the active set and ``u`` in closed form. When the
    most compressed block reaches ``delta_t`` it turns rigid (bilinear law, Figure 3-13)
    and ``u = o_max - delta_t``: the adhesive block and bulk carry the rest.

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, sections 3.3.4, 3.4.1.
    """
    o = _check_overlap(overlap)
    zero = np.zeros(o.shape[:-2])
    return _state(o, stiffness, zero, zero.copy())


@cites("thesis", "borodich_savencu_2017")
def structure_fixed_load(overlap, stiffness: BlockStiffness, load) -> StructureState:
    """Hierarchical structure under a fixed normal load: vertical degree of freedom (3.4.2 in [1]_).

    Parameters
    ----------
    overlap : array_like, shape (..., n_adhesive, m*m)
        Interference of every atomic block with the counter surface at zero displacement of
        the structure's backing [m].
    stiffness : BlockStiffness
        Segment stiffnesses and the atomic threshold compression.
    load : numeric
        Normal load on the structure [N], > 0; broadcast against the batch dimensions.

    Returns
    -------
    StructureState
        ``approach`` is the backing displacement that balances ``load``; ``residual`` the
        relative force-balance error (round-off only: the solution is exact).

    Notes
    -----
    The total force is a continuous, piecewise-linear, non-decreasing function of the
    approach ``d``. Its breakpoints are known in closed form for every nanoblock (an atomic
    block touches; the most compressed one turns rigid), so the force at all of them is
    evaluated at once, the bracketing segment is found by counting, and ``d`` follows by
    linear interpolation — exact up to round-off, no iteration.
    """
    o = _check_overlap(overlap)
    batch = o.shape[:-2]
    load_arr = np.asarray(load, dtype=float)
    if not np.all(np.isfinite(load_arr)) or np.any(load_arr <= 0):
        raise InputError(f"load must be a positive force [N], got {load!r}.")
    try:
        load_arr = np.broadcast_to(load_arr, batch)
    except ValueError:
        raise InputError(f"load of shape {load_arr.shape} does not broadcast to the batch shape {batch}.") from None
    k_at, k_col, d_t = stiffness.atomic, stiffness.column, stiffness.atomic_threshold
    ratio = k_at / k_col
    n = o.shape[-2]
    o_desc = -np.sort(-o, axis=-1)
    o_max = o_desc[..., 0]
    s_rigid = d_t - o_max  # (B, n)
    # breakpoints in the approach d: an atomic block touches, the most compressed turns rigid
    # (d(s) is increasing, so capping s at the rigid point caps d at d(s_rigid))
    d_rigid = s_rigid + ratio * np.maximum(o + s_rigid[..., None], 0.0).sum(-1)
    d_knots = np.concatenate([np.minimum(_column_knots(o_desc, ratio), d_rigid[..., None]),
                              d_rigid[..., None]], axis=-1)
    queries = d_knots.reshape(batch + (-1,))  # (B, n*(M+1))
    total = np.zeros(queries.shape)
    for j in range(n):  # loop over nanoblocks (few), vectorised over steps and queries
        total += _column_force_at(o_desc[..., j, :], s_rigid[..., j], queries, ratio, k_col)
    order = np.argsort(queries, axis=-1)
    q_sorted = np.take_along_axis(queries, order, axis=-1)
    f_sorted = np.maximum.accumulate(np.take_along_axis(total, order, axis=-1), axis=-1)
    idx = (f_sorted < load_arr[..., None]).sum(axis=-1)
    last = q_sorted.shape[-1] - 1
    beyond = idx > last
    hi = np.minimum(idx, last)
    lo = np.maximum(hi - 1, 0)
    d_lo = np.take_along_axis(q_sorted, lo[..., None], -1)[..., 0]
    d_hi = np.take_along_axis(q_sorted, hi[..., None], -1)[..., 0]
    f_lo = np.take_along_axis(f_sorted, lo[..., None], -1)[..., 0]
    f_hi = np.take_along_axis(f_sorted, hi[..., None], -1)[..., 0]
    df = f_hi - f_lo
    safe = np.where(df > 0, df, 1.0)
    d_in = np.where(df > 0, d_lo + (load_arr - f_lo) * (d_hi - d_lo) / safe, d_hi)
    # beyond the last breakpoint every nanoblock is rigid: slope n * k_col
    d_out = q_sorted[..., -1] + (load_arr - f_sorted[..., -1]) / (n * k_col)
    approach = np.where(beyond, d_out, d_in)
    state = _state(o, stiffness, approach, np.zeros(batch))
    residual = np.abs(state.total_force - load_arr) / load_arr
    return StructureState(**{**state.__dict__, "residual": residual})


def _column_force_at(o_desc, s_rigid, d, ratio, k_col):
    """Force of one nanoblock at backing displacements ``d`` (B, Q); overlaps (B, M) sorted descending."""
    knots = _column_knots(o_desc, ratio)  # (B, M), in d, for s = -o_(k)
    p = (knots[..., None, :] < d[..., :, None]).sum(-1)  # (B, Q) blocks in contact
    cum = np.concatenate([np.zeros(o_desc.shape[:-1] + (1,)), np.cumsum(o_desc, axis=-1)], axis=-1)
    s_p = np.take_along_axis(cum, p, axis=-1)
    s = (d - ratio * s_p) / (1.0 + ratio * p)
    s = np.minimum(s, s_rigid[..., None])
    return k_col * np.maximum(d - s, 0.0)


# --------------------------------------------------------------------------------------
# elastic interlocking (3.3.6)
# --------------------------------------------------------------------------------------

@cites("thesis")
def elastic_interlocking_energy(stiffness, delta_compression):
    """Energy dissipated by elastic interlocking, ``dU = 1/2 (E A / H) delta_e^2``, Eq. (3-25) in [1]_.

    Parameters
    ----------
    stiffness : numeric
        Stiffness ``E A / H`` of the block [N/m].
    delta_compression : numeric
        Change ``delta_e`` of the block's compression between two positions [m].

    Returns
    -------
    numeric
        Energy [J], >= 0, broadcast shape of the inputs.

    Examples
    --------
    >>> print(f"{float(elastic_interlocking_energy(40.0, 0.1e-9)):.3g}")  # [J]
    2e-19
    """
    k = as_array(stiffness, "stiffness", "N/m", nonnegative=True)
    de = np.asarray(delta_compression, dtype=float)
    if np.any(np.isnan(de)):
        raise InputError("delta_compression contains NaN.")
    return 0.5 * k * de**2


@cites("thesis")
def structure_interlocking_energy(states: StructureState, stiffness: BlockStiffness, axis: int = 0):
    """Elastic interlocking energy of a structure between consecutive steps (3-25, 3.3.6 in [1]_).

    The sum, over all atomic and adhesive blocks, of ``1/2 k delta_e^2`` for the change of
    each block's compression from one step to the next ("the energies spent to deform all
    parts of the atomic subscale [and] the adhesive subscale"). The bulk segment is not an
    asperity and is left out.

    Parameters
    ----------
    states : StructureState
        States over a batch dimension of steps (``axis``).
    stiffness : BlockStiffness
    axis : int
        The step axis of the batch dimensions.

    Returns
    -------
    ndarray
        Energy per step [J] (length of the step axis; zero at the first step),
        split as ``(atomic, adhesive)``.
    """
    d_at = np.diff(states.atomic_compression, axis=axis, prepend=np.take(states.atomic_compression, [0], axis))
    d_adh = np.diff(states.adhesive_compression, axis=axis,
                    prepend=np.take(states.adhesive_compression, [0], axis))
    atomic = elastic_interlocking_energy(stiffness.atomic, d_at).sum(axis=(-2, -1))
    adhesive = elastic_interlocking_energy(stiffness.adhesive, d_adh).sum(axis=-1)
    return atomic, adhesive
