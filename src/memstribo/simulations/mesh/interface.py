"""The nanoblock interface of a step: block lattices on both flanks, the vdW share at a gap, the lattice overlap
across the face width, elastic interlocking, and the low-discrepancy choice of bare gear blocks."""

from __future__ import annotations

import math

import numpy as np



_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


_SILVER = math.sqrt(2.0) - 1.0


def vdw_gap_factor(gap, cutoff_distance, vdw_cutoff):
    """Share of a block's contact vdW energy at local gap D: (D0 / max(D, D0))^2, 0 beyond the cut-off.

    The flat-flat Hamaker law: the interaction energy per area at separation D is
    A / (12 pi D^2) (Israelachvili 2011, Table 13.1), which at contact (D <= D0) is the work of
    adhesion w12 = A / (12 pi D0^2) (3-34); the ratio is the factor (MODEL 7c).

    Parameters
    ----------
    gap : array_like
        Local gap D between the surfaces [m] (0 in contact).
    cutoff_distance : float
        D0 [m].
    vdw_cutoff : float
        Gap beyond which vdW is neglected (a numerical cut-off) [m].

    Returns
    -------
    ndarray
        Factor in [0, 1] [-].
    """
    d = np.maximum(np.asarray(gap, dtype=float), cutoff_distance)
    return np.where(d < vdw_cutoff, (cutoff_distance / d) ** 2, 0.0)


def lattice_overlap_across(atomic_width, atomic_pitch, atomic_per_side, adhesive_width, offset):
    """Summed overlap width across the face width of two facing rows of atomic blocks [m].

    Each nanoblock carries ``m`` rows of atomic blocks (width ``w_at``, pitch ``atomic_pitch``)
    across the face width; the gear's lattice is shifted by ``offset`` relative to the
    pinion's, and repeats with the nanoblock width. The result is
    sum_i sum_j max(0, w_at - |y_i - y_j - offset|) over the pinion's rows i and the gear's rows
    j (with their periodic images): ``m w_at`` when the lattices are aligned, less when not.
    """
    m = int(atomic_per_side)
    y = (np.arange(m) - 0.5 * (m - 1)) * atomic_pitch
    images = np.array([-adhesive_width, 0.0, adhesive_width])
    gear = (y[:, None] + offset + images[None, :]).ravel()
    return float(np.clip(atomic_width - np.abs(y[:, None] - gear[None, :]), 0.0, None).sum())


def _lattice(roll, w_adh, grid_half):
    """Material indices k of the nanoblocks whose footprint meets the window, per step (steps, slots)."""
    # block k of a flank spans roll coordinates [k w_adh, (k+1) w_adh)
    lo = roll - grid_half - w_adh
    k0 = np.floor(lo / w_adh).astype(int)
    slots = int(math.ceil((2 * grid_half + 2 * w_adh) / w_adh)) + 1
    return k0[:, None] + np.arange(slots)[None, :]


def _interlocking(k, comp_at, comp_adh, stiffness, interlocking_energy):
    """Sum over material blocks of 1/2 k de^2 (3-25, ``interlocking_energy``) between consecutive steps."""
    n_steps = k.shape[0]
    k_min = int(k.min())
    width = int(k.max()) - k_min + 1
    steps = np.repeat(np.arange(n_steps), k.shape[1])
    at = np.zeros((n_steps, width, comp_at.shape[-1]))
    adh = np.zeros((n_steps, width))
    at[steps, (k - k_min).ravel()] = comp_at.reshape(-1, comp_at.shape[-1])
    adh[steps, (k - k_min).ravel()] = comp_adh.ravel()
    d_at = np.diff(at, axis=0, prepend=at[:1])
    d_adh = np.diff(adh, axis=0, prepend=adh[:1])
    return (interlocking_energy(stiffness.atomic, d_at).sum(axis=(1, 2))
            + interlocking_energy(stiffness.adhesive, d_adh).sum(axis=1))
