"""Damage accumulation in the SAM coating, coating life and the cycles until stiction returns (thesis 5.5).

The modified Goryacheva-Torskaya model of the thesis (5.5.1-5.5.2): the coating on an atomic
asperity accumulates damage omega (Rabotnov; 0 intact, 1 worn through) at each point x along
the sliding direction, by linear summation over the load peaks i of a meshing cycle,

.. math:: \\omega(x, k) = \\sum_{i=1}^{k} c_1 \\left(\\Delta\\tau_{1,i}(x)\\right)^m \\qquad (5\\text{-}10)

where Delta tau_1,i(x) is the amplitude of the principal shear stress at x in load cycle i,
computed under the power-law asperity's contact pressure p (:mod:`memstribo.physics.asperity`) with
the friction traction mu p (:mod:`memstribo.physics.asperity_shear`, :mod:`memstribo.physics.stresses`). c1 [Pa^-m] and m are phenomenological.

The chain: nanoblock load peaks (from the meshing simulation's ``block_load`` or a given
list, thesis Table 5-1) -> loads of the m x m atomic asperities with their mutual influence
(:func:`memstribo.physics.asperity.nanoblock_load_sharing`) -> tau_1 along x through each asperity's
centre -> omega/c1 per meshing cycle for every asperity -> relative lives, and with c1 the
cycles to coating failure, the worn fraction Omega(N), COF(N) and the cycle at which the
friction force reaches the available tangential force (stiction returns).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from memstribo.materials.pair import contact_modulus_of
from memstribo.physics.asperity import (
    nanoblock_load_sharing,
    position_classes,
    power_law_contact_radius,
)
from memstribo.errors import InputError
from memstribo.physics.asperity_shear import (normalised_principal_shear, principal_shear_profile,  # noqa: F401
                                              surface_stresses)
from memstribo.references import cites

__all__ = [
    "POSITIONS",
    "DamageResult",
    "DamageOutcome",
    "normalised_principal_shear",
    "surface_stresses",
    "principal_shear_profile",
    "damage_sum",
    "cyclic_peak_loads",
    "load_peaks",
    "nanoblock_damage",
    "mesh_damage",
    "cycles_to_failure",
    "calibrate_damage_coefficient",
    "damage_after",
    "worn_fraction",
    "cycles_to_stiction",
    "run_damage",
]

POSITIONS = ("corner", "side", "central")


def _check_exponent(damage_exponent) -> float:
    try:
        m = float(damage_exponent)
    except (TypeError, ValueError):
        raise InputError(f"damage_exponent m must be a number > 0, got {damage_exponent!r}.") from None
    if not math.isfinite(m) or m <= 0:
        raise InputError(f"damage_exponent m must be a finite number > 0, got {damage_exponent!r}.")
    return m


def _check_coefficient(damage_coefficient) -> float:
    try:
        c1 = float(damage_coefficient)
    except (TypeError, ValueError):
        raise InputError(f"damage_coefficient c1 must be a number > 0 [Pa^-m], got {damage_coefficient!r}.") from None
    if not math.isfinite(c1) or c1 <= 0:
        raise InputError(f"damage_coefficient c1 must be a finite number > 0 [Pa^-m], got {damage_coefficient!r}.")
    return c1


# --- damage law ---------------------------------------------------------------------------------------------


@cites("thesis", "rabotnov_1963", "goryacheva_torskaya_2003")
def damage_sum(stress_amplitude, damage_exponent: float, damage_coefficient: float = 1.0, axis: int = 0):
    """Linear damage summation over load cycles, omega = sum_i c1 (Delta tau_1,i)^m, Eq. (5-10) in [1]_.

    Parameters
    ----------
    stress_amplitude : array_like
        Amplitudes Delta tau_1,i >= 0 of the principal shear stress [Pa], cycles along ``axis``.
    damage_exponent : float
        m > 0 [-].
    damage_coefficient : float
        c1 > 0 [Pa^-m]; 1 gives omega / c1 [Pa^m].
    axis : int
        Axis of the load cycles.

    Returns
    -------
    ndarray
        omega [-] (or omega / c1 [Pa^m] with c1 = 1), not clipped to 1.

    References
    ----------
    .. [1] N. S. T. Almuramady, PhD thesis, Cardiff University, 5.5.2, (5-8)-(5-11).
    """
    m = _check_exponent(damage_exponent)
    c1 = _check_coefficient(damage_coefficient)
    amplitude = np.asarray(stress_amplitude, dtype=float)
    if np.any(amplitude < 0) or not np.all(np.isfinite(amplitude)):
        raise InputError("stress amplitudes must be finite and >= 0 Pa.")
    return c1 * np.sum(amplitude ** m, axis=axis)


def cyclic_peak_loads(loads, peaks_per_cycle: int) -> np.ndarray:
    """The load peaks of one meshing cycle from a short list: the list repeated to k peaks [N].

    A list of n loads (thesis Table 5-1: six nanoblock loads) stands for the k peaks of a
    meshing cycle (k = 48, Figure 5-18) taken in turn: peak i has load ``loads[i % n]``.
    """
    loads = np.atleast_1d(np.asarray(loads, dtype=float))
    if loads.ndim != 1 or loads.size == 0 or not np.all(np.isfinite(loads)) or np.any(loads <= 0):
        raise InputError(f"loads must be a non-empty list of finite loads > 0 N, got {loads.tolist()!r}.")
    if int(peaks_per_cycle) != peaks_per_cycle or peaks_per_cycle < 1:
        raise InputError(f"peaks_per_cycle must be an integer >= 1, got {peaks_per_cycle!r}.")
    return loads[np.arange(int(peaks_per_cycle)) % loads.size]


def load_peaks(history) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Load peaks of each nanoblock over a meshing cycle, and the valley before each [N].

    Parameters
    ----------
    history : array_like
        Loads of the nanoblocks over the cycle [N], shape (steps, blocks) (the mesh's
        ``block_load``). NaN (block out of the contact) counts as 0.

    Returns
    -------
    (peak, valley, block) : ndarrays of one entry per peak
        Peak load [N], the lowest load since the block's previous peak (or since the start) [N],
        and the block index. A peak is a step whose load exceeds the previous step's and is
        at least the next step's (the first and last steps count against a zero load).
    """
    loads = np.nan_to_num(np.asarray(history, dtype=float), nan=0.0)
    if loads.ndim != 2:
        raise InputError(f"block load history must have shape (steps, blocks), got {loads.shape}.")
    if np.any(loads < 0):
        loads = np.clip(loads, 0.0, None)  # adhesive (tensile) loads do not load the coating in compression
    padded = np.pad(loads, ((1, 1), (0, 0)))
    is_peak = (padded[1:-1] > padded[:-2]) & (padded[1:-1] >= padded[2:]) & (loads > 0)
    # group g of block b: the steps after its g-th peak up to and including its (g+1)-th
    group = np.cumsum(is_peak, axis=0) - is_peak
    group_id = group + (group.max() + 1) * np.arange(loads.shape[1])[None, :]
    minima = np.full(int(group_id.max()) + 1, np.inf)
    np.minimum.at(minima, group_id.ravel(), loads.ravel())
    steps, blocks = np.nonzero(is_peak)
    order = np.lexsort((steps, blocks))
    steps, blocks = steps[order], blocks[order]
    valley = minima[group_id[steps, blocks]]
    valley = np.where(group[steps, blocks] == 0, 0.0, valley)  # the block was unloaded before the cycle
    return loads[steps, blocks], np.minimum(valley, loads[steps, blocks]), blocks


@dataclass(frozen=True)
class DamageResult:
    """Damage per meshing cycle of the coating on the atomic asperities of nanoblocks.

    Attributes
    ----------
    x : ndarray
        Positions along the sliding direction through an asperity's centre [m], shape (n_x,).
    omega_over_c1 : ndarray
        omega / c1 per meshing cycle [Pa^m], shape (blocks, m*m, n_x).
    classes : ndarray of str
        'corner', 'side' or 'central' of each asperity (row-major), shape (m*m,).
    damage_exponent : float
        m [-].
    peaks_per_cycle : ndarray
        Load peaks k of each block in the cycle [-], shape (blocks,).
    asperity_peak_loads : ndarray
        Peak loads of the asperities of the most damaged block [N], shape (k, m*m).
    maximum : dict
        Position class -> largest omega / c1 per cycle over x and over blocks [Pa^m].
    location : dict
        Position class -> x of that maximum [m].
    """

    x: np.ndarray
    omega_over_c1: np.ndarray
    classes: np.ndarray
    damage_exponent: float
    peaks_per_cycle: np.ndarray
    asperity_peak_loads: np.ndarray
    maximum: dict = field(default_factory=dict)
    location: dict = field(default_factory=dict)

    @property
    def per_asperity(self) -> np.ndarray:
        """Largest omega / c1 over x of each asperity of each block [Pa^m], shape (blocks, m*m)."""
        return self.omega_over_c1.max(axis=-1)

    @property
    def life_ratio_corner_to_central(self) -> float | None:
        """Life of the corner asperity over that of the central one [-] (thesis: 0.91 for m = 1).

        None for a nanoblock without both (fewer than 3 asperities per side).
        """
        if "corner" not in self.maximum or "central" not in self.maximum:
            return None
        return self.maximum["central"] / self.maximum["corner"]


def _asperity_damage(peak_block_loads, valley_block_loads, block_index, n_blocks, params, x=None):
    """omega/c1 per cycle on every asperity of every block (vectorised over all peaks)."""
    per_side = params["atomic_per_side"]
    degree = params["asperity_degree"]
    coefficient = params["asperity_shape_coefficient"]
    modulus = contact_modulus_of(params)
    m = _check_exponent(params["damage_exponent"])
    friction = params["asperity_friction_coefficient"]
    nu = params["poisson_ratio"]
    both = np.concatenate([peak_block_loads, valley_block_loads])
    positive = both > 0
    asperity_loads = np.zeros((both.size, per_side * per_side))
    if positive.any():
        sharing = nanoblock_load_sharing(both[positive], per_side, params["atomic_pitch"], degree, coefficient,
                                         modulus)
        asperity_loads[positive] = sharing.loads
    peaks, valleys = asperity_loads[:peak_block_loads.size], asperity_loads[peak_block_loads.size:]

    def omega_at(points):
        omega = np.zeros((n_blocks, peaks.shape[1], np.size(points)))
        # in chunks of peaks: the stress profiles of all peaks at once would take (peaks x asperities x n_x) floats
        chunk = max(1, _CHUNK_VALUES // max(1, peaks.shape[1] * np.size(points)))
        for start in range(0, peaks.shape[0], chunk):
            part = slice(start, start + chunk)
            tau_peak = principal_shear_profile(points, peaks[part], degree, coefficient, modulus, friction, nu)
            tau_valley = principal_shear_profile(points, valleys[part], degree, coefficient, modulus, friction, nu)
            np.add.at(omega, block_index[part], np.abs(tau_peak - tau_valley) ** m)  # (chunk, m*m, n_x)
        return omega

    if x is not None:
        return x, omega_at(x), peaks, m
    # a uniform grid plus the contact edges of the loads: tau_1 peaks in a cusp at an edge, so the damage
    # profile's maximum lies at or next to one. With up to _MAX_EDGE_LOADS distinct loads all edges are in the grid;
    # with more (a meshing cycle has tens of thousands) the largest half of that number and evenly spaced
    # others, and then, after a first pass, every edge near each asperity's largest values
    # (:func:`_edges_near_maxima`): without them the maximum fell 0.2-3 % short and depended on which edges
    # the grid held, so on round-off in the loads (0.8 %: docs/damage.md, "Resolution of the maximum"). Each
    # block's own maximum (Omega(N)) is refined only where it is near these largest values.
    distinct = np.unique(peaks[peaks > 0])
    loaded = _edge_loads(distinct)
    radii = power_law_contact_radius(loaded, degree, coefficient, modulus) if loaded.size else np.ones(1)
    a_max = float(radii.max())
    x = np.unique(np.concatenate([np.linspace(-1.25 * a_max, 1.25 * a_max, _UNIFORM_POINTS), radii, -radii]))
    omega = omega_at(x)
    if loaded.size < distinct.size:
        all_radii = power_law_contact_radius(distinct, degree, coefficient, modulus)
        extra = _edges_near_maxima(x, omega, np.concatenate([-all_radii, all_radii]))
        if extra.size:
            x = np.concatenate([x, extra])
            order = np.argsort(x)
            x, omega = x[order], np.concatenate([omega, omega_at(extra)], axis=-1)[..., order]
    return x, omega, peaks, m


#: Points of the uniform part of the damage profiles' x grid (over +-1.25 times the largest contact radius).
_UNIFORM_POINTS = 501
#: The second pass of :func:`_asperity_damage` adds the contact edges within this many grid points of every
#: grid value of an asperity's damage profile (largest over the blocks) that is at least _NEAR_MAXIMUM of its
#: largest value (the first pass's grid misses the maximum by up to ~4 %: a 501-point grid without the edges).
_EDGE_WINDOW = 1
_NEAR_MAXIMUM = 0.95


def _edges_near_maxima(x, omega, edges):
    """The contact edges [m] not yet in the grid ``x`` that lie near each asperity's largest damage values."""
    profile = omega.max(axis=0)  # (asperities, n_x): the largest over the blocks
    near = profile >= _NEAR_MAXIMUM * profile.max(axis=-1, keepdims=True)
    near &= profile > 0
    hits = np.nonzero(near.any(axis=0))[0]
    if hits.size == 0:
        return np.zeros(0)
    low = x[np.maximum(hits - _EDGE_WINDOW, 0)]
    high = x[np.minimum(hits + _EDGE_WINDOW, x.size - 1)]
    edges = np.unique(edges)
    inside = np.zeros(edges.size, dtype=bool)
    for lo, hi in zip(low, high):  # one window per grid point near a maximum
        inside[np.searchsorted(edges, lo):np.searchsorted(edges, hi, side="right")] = True
    return np.setdiff1d(edges[inside], x)


#: At most this many distinct asperity loads put their contact edges into the x grid (:func:`_edge_loads`).
_MAX_EDGE_LOADS = 256
#: Stress values per chunk of peaks in :func:`_asperity_damage` (~160 MB of float64).
_CHUNK_VALUES = 20_000_000


def _edge_loads(loaded):
    """The sorted distinct loads whose contact edges join the x grid: all of them up to _MAX_EDGE_LOADS, else the
    largest half of that number and evenly spaced ones among the rest."""
    if loaded.size <= _MAX_EDGE_LOADS:
        return loaded
    top = _MAX_EDGE_LOADS // 2
    rest = loaded[:-top]
    return np.concatenate([rest[np.linspace(0, rest.size - 1, _MAX_EDGE_LOADS - top).astype(int)], loaded[-top:]])


def _result(x, omega, classes, m, counts, peak_loads_of_worst):
    maximum, location = {}, {}
    for position in POSITIONS:
        mask = classes == position
        if not mask.any():
            continue
        sub = omega[:, mask, :]
        flat = int(np.argmax(sub))
        maximum[position] = float(sub.ravel()[flat])
        location[position] = float(x[np.unravel_index(flat, sub.shape)[-1]])
    return DamageResult(x, omega, classes, m, counts, peak_loads_of_worst, maximum, location)


@cites("thesis", "goryacheva_torskaya_2003", "rabotnov_1963")
def nanoblock_damage(loads, params, *, peaks_per_cycle: int | None = None, x=None) -> DamageResult:
    """omega / c1 per meshing cycle of one nanoblock loaded by a list of peak loads (Tables 5-3, 5-4).

    Parameters
    ----------
    loads : array_like
        Nanoblock loads [N] (thesis Table 5-1), repeated in turn to the k peaks of a cycle
        (:func:`cyclic_peak_loads`); between peaks the block unloads completely.
    params : memstribo.parameters.Parameters
        Uses atomic_per_side, atomic_pitch, asperity_degree, asperity_shape_coefficient,
        asperity_friction_coefficient, damage_exponent, peaks_per_cycle and the moduli.
    peaks_per_cycle : int, optional
        k; default the parameter ``peaks_per_cycle`` (48).
    x : array_like, optional
        Positions through the asperity centre [m]; default 501 points over +-1.25 a_max plus the contact edges
        of the loads (:func:`_asperity_damage`). A given grid is used as it is: the maxima are its largest values.

    Returns
    -------
    DamageResult
    """
    k = params["peaks_per_cycle"] if peaks_per_cycle is None else peaks_per_cycle
    peaks = cyclic_peak_loads(loads, k)
    x, omega, asperity_peaks, m = _asperity_damage(peaks, np.zeros_like(peaks), np.zeros(peaks.size, dtype=int), 1,
                                                   params, x)
    classes = position_classes(params["atomic_per_side"])
    return _result(x, omega, classes, m, np.array([peaks.size]), asperity_peaks)


@cites("thesis", "goryacheva_torskaya_2003", "rabotnov_1963", "model")
def mesh_damage(dataset, params, *, x=None) -> DamageResult:
    """omega / c1 per meshing cycle of every nanoblock from a meshing-cycle simulation.

    Parameters
    ----------
    dataset : xarray.Dataset
        Result of :func:`memstribo.simulations.mesh.simulate_mesh` with ``block_load`` (dims step, block) [N].
    params : memstribo.parameters.Parameters
        As for :func:`nanoblock_damage` (``peaks_per_cycle`` is not used: the peaks are counted).
    x : array_like, optional
        Positions through the asperity centre [m]; default as :func:`nanoblock_damage`, and where the
        cycle has more than ``_MAX_EDGE_LOADS`` distinct asperity loads, a second pass adds the contact edges
        near the largest values (docs/damage.md, "Resolution of the maximum"). A given grid is used as it is.

    Returns
    -------
    DamageResult
        One row of ``omega_over_c1`` per nanoblock of the dataset.
    """
    if "block_load" not in getattr(dataset, "variables", {}):
        raise InputError("the meshing-cycle dataset has no 'block_load' (per-nanoblock loads); "
                         "damage needs the mesh's block loads or a --loads list.")
    block_load = dataset["block_load"]
    if "block_flank" in block_load.coords:  # the coating that wears is the gear's (thesis 5.5.3)
        block_load = block_load.isel(block=np.asarray(block_load["block_flank"].values) == "gear")
    history = np.asarray(block_load.transpose("step", ...).values, dtype=float)
    history = history.reshape(history.shape[0], -1)
    peaks, valleys, blocks = load_peaks(history)
    if peaks.size == 0:
        raise InputError("no nanoblock carries a load peak in this meshing cycle: nothing to damage.")
    x, omega, asperity_peaks, m = _asperity_damage(peaks, valleys, blocks, history.shape[1], params, x)
    counts = np.bincount(blocks, minlength=history.shape[1])
    worst = int(np.argmax(omega.max(axis=(1, 2))))
    classes = position_classes(params["atomic_per_side"])
    return _result(x, omega, classes, m, counts, asperity_peaks[blocks == worst])


# --- lifetime --------------------------------------------------------------------------------------------------


def cycles_to_failure(omega_over_c1_per_cycle, damage_coefficient: float):
    """Meshing cycles until omega = 1 where damage accumulates fastest, N_f = 1 / (c1 omega/c1) [-].

    Parameters
    ----------
    omega_over_c1_per_cycle : numeric
        omega / c1 accumulated per meshing cycle [Pa^m] (> 0; 0 gives inf: never).
    damage_coefficient : float
        c1 [Pa^-m].
    """
    c1 = _check_coefficient(damage_coefficient)
    rate = np.asarray(omega_over_c1_per_cycle, dtype=float)
    if np.any(rate < 0) or not np.all(np.isfinite(rate)):
        raise InputError("omega/c1 per cycle must be finite and >= 0.")
    with np.errstate(divide="ignore"):
        life = np.where(rate > 0, 1.0 / (c1 * np.where(rate > 0, rate, 1.0)), np.inf)
    return float(life) if life.ndim == 0 else life


def calibrate_damage_coefficient(omega_over_c1_per_cycle: float, observed_cycles: float) -> float:
    """c1 [Pa^-m] such that the coating fails (omega = 1) after ``observed_cycles`` meshing cycles."""
    try:
        n = float(observed_cycles)
    except (TypeError, ValueError):
        raise InputError(f"observed coating life must be a number of cycles > 0, got {observed_cycles!r}.") from None
    if not math.isfinite(n) or n <= 0:
        raise InputError(f"observed coating life must be a number of cycles > 0, got {observed_cycles!r}.")
    rate = float(omega_over_c1_per_cycle)
    if not math.isfinite(rate) or rate <= 0:
        raise InputError("cannot calibrate c1: the damage per cycle is zero.")
    return 1.0 / (rate * n)


@cites("thesis", "rabotnov_1963")
def damage_after(cycles, omega_over_c1_per_cycle, damage_coefficient: float):
    """Damage omega(N) = min(1, c1 N omega/c1) after N meshing cycles [-] (linear summation).

    Non-decreasing in N by construction (each cycle adds c1 sum (Delta tau)^m >= 0).
    """
    c1 = _check_coefficient(damage_coefficient)
    n = np.asarray(cycles, dtype=float)
    if np.any(n < 0) or not np.all(np.isfinite(n)):
        raise InputError("cycles must be finite and >= 0.")
    rate = np.asarray(omega_over_c1_per_cycle, dtype=float)
    return np.minimum(1.0, c1 * np.multiply.outer(n, rate))


def worn_fraction(cycles, lives, weights=None):
    """Worn fraction Omega(N) of the coating: the weight of asperities whose coating has failed [-].

    Parameters
    ----------
    cycles : numeric
        Meshing cycles N [-].
    lives : array_like
        Cycles to failure of each asperity's coating [-] (inf: never).
    weights : array_like, optional
        Share of the coated area of each asperity (default equal); normalised to sum 1.
    """
    lives = np.asarray(lives, dtype=float).ravel()
    w = np.ones_like(lives) if weights is None else np.asarray(weights, dtype=float).ravel()
    if w.shape != lives.shape or np.any(w < 0) or w.sum() <= 0:
        raise InputError("weights must be >= 0, one per asperity, not all zero.")
    w = w / w.sum()
    n = np.asarray(cycles, dtype=float)
    return (np.multiply.outer(n, np.ones_like(lives)) >= lives).astype(float) @ w


def cycles_to_stiction(lives, critical_wear: float | None, weights=None) -> float | None:
    """Fewest meshing cycles after which the worn fraction reaches ``critical_wear`` [-] (None: never).

    Parameters
    ----------
    lives : array_like
        Cycles to failure of each asperity's coating [-].
    critical_wear : float or None
        Worn fraction Omega at which F_f >= F_t (:func:`memstribo.physics.coating.critical_wear`);
        None (no stiction even when bare) gives None.
    weights : array_like, optional
        As for :func:`worn_fraction`.
    """
    if critical_wear is None:
        return None
    lives = np.asarray(lives, dtype=float).ravel()
    w = np.ones_like(lives) if weights is None else np.asarray(weights, dtype=float).ravel()
    order = np.argsort(lives)
    cumulative = np.cumsum(w[order]) / w.sum()
    if critical_wear <= 0:
        return 0.0
    reached = np.flatnonzero(cumulative >= critical_wear - 1e-12)
    if reached.size == 0:
        return None
    life = float(lives[order][reached[0]])
    return life if math.isfinite(life) else None


# --- the whole damage stage -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class DamageOutcome:
    """What :func:`run_damage` computed: a JSON-able summary, datasets and figures.

    Attributes
    ----------
    summary : dict
        ``omega_over_c1_max`` (corner/side/central) [Pa^m], ``location`` [m],
        ``life_ratio_corner_to_central`` [-], ``damage_per_cycle_over_c1`` [Pa^m],
        ``damage_coefficient`` [Pa^-m] or None, ``cycles_to_failure``, ``cycles_to_stiction``
        [meshing cycles] or None, ``critical_wear`` [-] or None.
    result : DamageResult
    datasets : dict
        Stem -> xarray.Dataset (``damage_profile``, ``damage_history`` when c1 is known).
    figures : dict
        Stem -> (matplotlib figure, caption).
    """

    summary: dict
    result: DamageResult
    datasets: dict = field(default_factory=dict)
    figures: dict = field(default_factory=dict)


def _sweep_arrays(wear_sweep):
    """(wear, cof, stiction_margin) from a coating.wear_sweep dataset or the chain's summary dict."""
    if wear_sweep is None:
        return None
    def pick(*names):
        for name in names:
            if name in wear_sweep:
                value = wear_sweep[name]
                return np.asarray(getattr(value, "values", value), dtype=float)
        raise InputError(f"the wear sweep has none of {names}.")
    wear = pick("wear")
    return wear, pick("cof_mean"), pick("stiction_margin", "stiction_margin_min")


@cites("thesis", "model")
def run_damage(params, mesh_dataset=None, *, loads=None, wear_sweep=None, cycles_observed=None,
               figures: bool = True) -> DamageOutcome:
    """Damage per cycle, relative lives, and (with c1) cycles to failure and to stiction (5.5).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Model parameters (``damage_coefficient`` c1 may be unset).
    mesh_dataset : xarray.Dataset, optional
        A meshing cycle (of the coated pair) with ``block_load``; used when ``loads`` is None.
    loads : array_like, optional
        Nanoblock peak loads [N] (Table 5-1), instead of the mesh.
    wear_sweep : xarray.Dataset or dict, optional
        COF and stiction margin versus Omega (:func:`memstribo.simulations.coating_wear.wear_sweep`, or the
        chain's summary with ``cof_mean`` and ``stiction_margin_min``): gives the critical
        wear and COF(N).
    cycles_observed : float, optional
        An observed coating life [meshing cycles] to calibrate c1 (overrides the parameter).
    figures : bool
        Build the figures (damage profiles, map, Omega(N) and COF(N)).

    Returns
    -------
    DamageOutcome
    """
    from memstribo.physics.coating import critical_wear as _critical_wear

    if loads is not None:
        result = nanoblock_damage(loads, params)
    elif mesh_dataset is not None:
        result = mesh_damage(mesh_dataset, params)
    else:
        raise InputError("damage needs nanoblock loads (--loads) or a meshing-cycle dataset.")
    per_asperity = result.per_asperity  # (blocks, m*m)
    rate_max = float(per_asperity.max())
    c1 = params["damage_coefficient"]
    if cycles_observed is not None:
        c1 = calibrate_damage_coefficient(rate_max, cycles_observed)
    summary = {
        "omega_over_c1_max": dict(result.maximum),
        "location": dict(result.location),
        "life_ratio_corner_to_central": result.life_ratio_corner_to_central,
        "damage_per_cycle_over_c1": rate_max,
        "damage_exponent": result.damage_exponent,
        "peaks_per_cycle": int(result.peaks_per_cycle.max()),
        "damage_coefficient": c1,
    }
    sweep = _sweep_arrays(wear_sweep)
    crit = None
    if sweep is not None:
        import xarray as xr

        crit = _critical_wear(xr.Dataset({"stiction_margin": ("wear", sweep[2])}, coords={"wear": sweep[0]}))
        summary["critical_wear"] = crit
    datasets = {"damage_profile": _profile_dataset(result)}
    if c1 is not None:
        # Omega counts the coating where the teeth touch: the asperities of the nanoblocks that carry
        # load in the cycle (a block never loaded neither wears nor adds friction; the mesh's Omega is
        # a fraction of bare blocks spread evenly over the flank, i.e. also over the touching ones)
        loaded = result.peaks_per_cycle > 0
        lives = cycles_to_failure(per_asperity[loaded], c1)
        summary["cycles_to_failure"] = float(np.min(lives))
        summary["cycles_to_failure_by_position"] = {
            p: float(np.min(lives[:, result.classes == p])) for p in POSITIONS if (result.classes == p).any()}
        summary["cycles_to_stiction"] = cycles_to_stiction(lives, crit) if sweep is not None else None
        datasets["damage_history"] = _history_dataset(lives, sweep, summary["cycles_to_failure"])
    out_figures = _figures(result, datasets) if figures else {}
    return DamageOutcome(summary, result, datasets, out_figures)


def _profile_dataset(result: DamageResult):
    import xarray as xr

    worst = int(np.argmax(result.per_asperity.max(axis=1)))
    data = {}
    for position in POSITIONS:
        mask = result.classes == position
        if mask.any():
            profile = result.omega_over_c1[worst][mask].max(axis=0)
            data[f"omega_over_c1_{position}"] = ("x", profile, {
                "units": f"Pa^{result.damage_exponent:g}",
                "long_name": f"omega/c1 per meshing cycle, {position} asperity (most damaged block)"})
    return xr.Dataset(data, coords={"x": ("x", result.x, {"units": "m",
                                                         "long_name": "position along sliding through the centre"})})


def _history_dataset(lives, sweep, first_failure):
    import xarray as xr

    finite = lives[np.isfinite(lives)]
    top = float(finite.max()) if finite.size else first_failure
    cycles = np.unique(np.concatenate([np.linspace(0, 1.2 * top, 241), np.sort(finite.ravel())]))
    omega = worn_fraction(cycles, lives)
    data = {"worn_fraction": ("cycles", omega, {"units": "", "long_name": "worn fraction Omega of the coating"})}
    if sweep is not None:
        order = np.argsort(sweep[0])
        data["cof_mean"] = ("cycles", np.interp(omega, sweep[0][order], sweep[1][order]),
                       {"units": "", "long_name": "COF at the worn fraction Omega(N)"})
        data["stiction_margin"] = ("cycles", np.interp(omega, sweep[0][order], sweep[2][order]),
                                   {"units": "N", "long_name": "stiction margin F_t - F_f at Omega(N)"})
    return xr.Dataset(data, coords={"cycles": ("cycles", cycles, {"units": "", "long_name": "meshing cycles N"})})


def _figures(result: DamageResult, datasets) -> dict:
    from memstribo.output import new_figure

    figures = {}
    profile = datasets["damage_profile"]
    fig, ax = new_figure(figsize=(5, 3.5))
    for position, style in zip(POSITIONS, ("r-", "g-", "y-")):
        key = f"omega_over_c1_{position}"
        if key in profile:
            ax.plot(profile["x"].values * 1e9, profile[key].values, style, label=position)
    from memstribo.output import engineering_scale

    ax.set_xlabel("x along sliding [nm]")
    power = "" if result.damage_exponent == 1 else f"^{result.damage_exponent:g}"
    keys = [f"omega_over_c1_{position}" for position in POSITIONS if f"omega_over_c1_{position}" in profile]
    factor, unit = engineering_scale([np.nanmax(np.abs(profile[k].values)) for k in keys] or [1.0], f"Pa{power}")
    for line in ax.get_lines():  # drawn in SI above; scaled so that the axis carries no offset
        line.set_ydata(np.asarray(line.get_ydata(), dtype=float) / factor)
    ax.relim()
    ax.autoscale_view()
    ax.set_ylabel(f"omega / c1 per cycle [{unit}]")
    ax.legend()
    figures["damage_profile"] = (fig, f"Damage per meshing cycle omega/c1 along the sliding direction through the "
                                      f"corner, side and central asperities, m = {result.damage_exponent:g} "
                                      "(thesis Figures 5-22, 5-23).")
    per_side = int(math.isqrt(result.classes.size))
    worst = int(np.argmax(result.per_asperity.max(axis=1)))
    fig, ax = new_figure(figsize=(4, 3.5))
    worst_map = result.per_asperity[worst].reshape(per_side, per_side)
    factor, unit = engineering_scale(worst_map, f"Pa{power}")  # no "1e9" offset over the colour bar
    image = ax.imshow(worst_map / factor, cmap="magma", origin="lower")
    fig.colorbar(image, ax=ax, label=f"max omega/c1 per cycle [{unit}]")
    ax.set_xticks(range(per_side))
    ax.set_yticks(range(per_side))
    ax.set_title("damage map of a nanoblock")
    ax.set_xlabel("asperity column")
    ax.set_ylabel("asperity row")
    figures["damage_map"] = (fig, "Largest damage per cycle of each atomic asperity of the most damaged nanoblock.")
    if "damage_history" in datasets:
        history = datasets["damage_history"]
        fig, ax = new_figure(figsize=(5, 3.5))
        ax.plot(history["cycles"].values, history["worn_fraction"].values * 100, "k-", label="Omega(N)")
        ax.set_xlabel("meshing cycles N")
        ax.set_ylabel("worn fraction Omega [%]")
        if "cof" in history:
            twin = ax.twinx()
            twin.plot(history["cycles"].values, history["cof_mean"].values, "b--", label="COF(N)")
            twin.set_ylabel("COF [-]")
        figures["damage_history"] = (fig, "Worn fraction of the coating and COF versus meshing cycles.")
    return figures
