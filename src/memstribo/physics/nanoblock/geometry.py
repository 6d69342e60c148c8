"""Nanoblock geometry: explicit (a parameter set) or derived from a measured profile.

A nanoblock (thesis 3.4, 4.2.3, Figure 4-23) is a square adhesive-subscale block (width
w_adh, height H_adh) carrying an m x m array of square atomic-subscale blocks (width w_at,
height H_at) at a pitch of about lambda_q; nanoblocks tile the surface on a square lattice
of period w_adh, on an elastic bulk segment of height H_bulk.

Derivation from a profile (MODEL §1.4), after levelling by the least-squares line:

- H_at = 0.5 Rq, H_adh = 1.2 Rq (thesis 3.4.1);
- w_at = mean width (3-26) of the asperities cut at the level +H_at above the mean line;
- w_adh = mean width of the asperities cut at the level -H_adh, i.e. 1.2 Rq *below* the
  mean line: the adhesive subscale lies under the atomic one, so its blocks are the wider
  bases of the asperities (cutting at +1.2 Rq would give blocks narrower than the atomic
  ones; see docs/roughness.md);
- pitch = lambda_q = 2 pi Rq / Delta_q (4-5); m = floor(w_adh / lambda_q) (error if < 1);
- H_bulk = w_adh (the thesis does not give it; MODEL §4).

References
----------
.. [1] N. S. T. Almuramady, PhD thesis (see :data:`memstribo.references.REFERENCES`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from memstribo.errors import InputError
from memstribo.references import cites
from memstribo.surfaces.roughness import Profile, asperity_widths, level_profile, rms_wavelength

__all__ = ["NanoblockGeometry", "nanoblock_geometry_from_profile", "adhesive_layer_thickness",
           "ATOMIC_HEIGHT_FACTOR", "ADHESIVE_HEIGHT_FACTOR"]

#: H_at / Rq (thesis 3.4.1: the atomic subscale "at 50 percent of Rq")
ATOMIC_HEIGHT_FACTOR = 0.5
#: H_adh / Rq (thesis 3.4.1: the adhesive subscale "at 1.2 Rq")
ADHESIVE_HEIGHT_FACTOR = 1.2


@dataclass(frozen=True)
class NanoblockGeometry:
    """Sizes of one nanoblock.

    Attributes
    ----------
    atomic_width : float
        Width w_at of a square atomic-subscale block [m].
    atomic_height : float
        Height H_at of an atomic-subscale block [m].
    adhesive_width : float
        Width w_adh of the square adhesive-subscale block (the nanoblock, and the lattice
        period of nanoblocks) [m].
    adhesive_height : float
        Height H_adh of the adhesive-subscale block [m].
    atomic_pitch : float
        Centre-to-centre pitch of the atomic blocks (about lambda_q) [m].
    atomic_per_side : int
        m: the nanoblock carries m x m atomic blocks [-].
    bulk_height : float
        Height of the elastic bulk segment under a nanoblock [m].
    rules : dict
        Quantity name -> the rule (and numbers) that produced it.
    """

    atomic_width: float
    atomic_height: float
    adhesive_width: float
    adhesive_height: float
    atomic_pitch: float
    atomic_per_side: int
    bulk_height: float
    rules: dict = field(default_factory=dict, compare=False)

    def __post_init__(self):
        for name in ("atomic_width", "atomic_height", "adhesive_width", "adhesive_height", "atomic_pitch",
                     "bulk_height"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float, np.floating, np.integer)) and math.isfinite(value) and value > 0):
                raise InputError(f"nanoblock geometry: {name} must be a positive length in m (got {value!r}).")
            object.__setattr__(self, name, float(value))
        m = self.atomic_per_side
        if isinstance(m, float) and m.is_integer():
            m = int(m)
        if not isinstance(m, (int, np.integer)) or isinstance(m, bool) or m < 1:
            raise InputError(f"nanoblock geometry: atomic_per_side must be an integer >= 1 (got {m!r}).")
        object.__setattr__(self, "atomic_per_side", int(m))
        if m > 1 and self.atomic_width > self.atomic_pitch:
            raise InputError(f"nanoblock geometry: atomic_width {self.atomic_width:.4g} m is larger than atomic_pitch "
                             f"{self.atomic_pitch:.4g} m: neighbouring atomic blocks would overlap.")
        footprint = (m - 1) * self.atomic_pitch + self.atomic_width
        if footprint > self.adhesive_width * (1 + 1e-12):
            raise InputError(f"nanoblock geometry: {m} x {m} atomic blocks at pitch {self.atomic_pitch:.4g} m span "
                             f"{footprint:.4g} m, more than adhesive_width {self.adhesive_width:.4g} m: lower "
                             "atomic_per_side or atomic_pitch, or widen the adhesive block.")
        object.__setattr__(self, "rules", dict(self.rules))

    @property
    def n_atomic(self) -> int:
        """Number of atomic blocks on one nanoblock, m^2."""
        return self.atomic_per_side ** 2

    def to_dict(self) -> dict:
        """Fields as a dict (SI values; ``rules`` included)."""
        return {"atomic_width": self.atomic_width, "atomic_height": self.atomic_height,
                "adhesive_width": self.adhesive_width, "adhesive_height": self.adhesive_height,
                "atomic_pitch": self.atomic_pitch, "atomic_per_side": self.atomic_per_side,
                "bulk_height": self.bulk_height, "rules": dict(self.rules)}

    @classmethod
    @cites("thesis", "model")
    def from_parameters(cls, params) -> "NanoblockGeometry":
        """The geometry given explicitly by a parameter set (default: thesis chapter 4, Figure 4-23).

        Parameters
        ----------
        params : memstribo.parameters.Parameters
            Uses atomic_width, atomic_height, adhesive_width, adhesive_height, atomic_pitch,
            atomic_per_side and bulk_height (unset: adhesive_width).

        Returns
        -------
        NanoblockGeometry
        """
        names = ("atomic_width", "atomic_height", "adhesive_width", "adhesive_height", "atomic_pitch",
                 "atomic_per_side")
        rules = {name: f"parameter set '{params.name}': {params.source(name)}" for name in names}
        bulk = params["bulk_height"]
        if bulk is None:
            bulk = params["adhesive_width"]
            rules["bulk_height"] = "bulk_height unset: equal to adhesive_width (MODEL §4)"
        else:
            rules["bulk_height"] = f"parameter set '{params.name}': {params.source('bulk_height')}"
        return cls(**{name: params[name] for name in names}, bulk_height=bulk, rules=rules)


@cites("thesis")
def adhesive_layer_thickness(params, geometry: NanoblockGeometry) -> float:
    """Thickness of the adhesive layer of a nanoblock [m]: the one rule of every friction model.

    An adhesive block forms van der Waals bonds and adheres where its gap to the counter
    surface is inside this layer. The parameter ``adhesive_layer_thickness`` when set;
    unset, the height of the adhesive-subscale block, ``geometry.adhesive_height`` (thesis
    3.5, 3.6: "the thickness is assumed to be equal to the height of the adhesive subscale
    asperity"). The layer is a geometric band of the nanoblock model, not a property of the
    surface chemistry: bare and coated blocks use the same layer. The Maugis range
    ``h0 = w / sigma0`` (3-17, MODEL.md §2; ``memstribo constants`` prints it) is the physical
    alternative, available as an explicit setting (``--set adhesive_layer_thickness="0.2494 nm"``).

    Used by the flat sliding models (:mod:`memstribo.simulations.sliding`) and the meshing cycle
    (:mod:`memstribo.simulations.mesh`).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Uses ``adhesive_layer_thickness`` [m] (optional).
    geometry : NanoblockGeometry
        The nanoblock geometry; its ``adhesive_height`` [m] is the default.

    Returns
    -------
    float
        The layer thickness [m].
    """
    layer = params["adhesive_layer_thickness"]
    return float(geometry.adhesive_height if layer is None else layer)


def _line_scans(surface):
    if isinstance(surface, Profile):
        return [surface]
    if hasattr(surface, "line_scans"):
        return surface.line_scans()
    if isinstance(surface, Sequence) and surface and all(isinstance(p, Profile) for p in surface):
        return list(surface)
    raise InputError("nanoblock geometry needs a Profile, a list of Profiles or a SurfaceMap.")


@cites("thesis", "model")
def nanoblock_geometry_from_profile(surface, *, atomic_height_factor=ATOMIC_HEIGHT_FACTOR,
                                    adhesive_height_factor=ADHESIVE_HEIGHT_FACTOR, bulk_height=None):
    """Nanoblock geometry derived from a measured profile (MODEL §1.4; thesis 3.4.1, 4.2.3).

    Each line scan is levelled by its own least-squares line. With several line scans
    (a map), Rq and Delta_q are pooled (rms over all scans) and the asperity widths of all
    scans are averaged together.

    Parameters
    ----------
    surface : Profile, list of Profile or SurfaceMap
        The measured surface (heights [m]).
    atomic_height_factor : float
        H_at / Rq [-] (0.5, thesis 3.4.1); the atomic widths are cut at +H_at.
    adhesive_height_factor : float
        H_adh / Rq [-] (1.2, thesis 3.4.1); the adhesive widths are cut at -H_adh.
    bulk_height : float, optional
        Height of the bulk segment [m]; default: the adhesive width.

    Returns
    -------
    NanoblockGeometry
        With ``rules`` naming the rule and the numbers behind each value.

    Raises
    ------
    InputError
        Profile too short (no complete asperity at a cut level) or w_adh < lambda_q (m < 1).
    """
    for label, value in (("atomic_height_factor", atomic_height_factor),
                         ("adhesive_height_factor", adhesive_height_factor)):
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"{label} must be a positive number (got {value!r}).")
    scans = [level_profile(p) for p in _line_scans(surface)]
    if any(p.n_points < 3 for p in scans):
        raise InputError("nanoblock geometry: every line scan needs at least 3 points.")
    squares = np.array([np.sum(p.z ** 2) for p in scans])
    slope_squares = np.array([np.sum((np.diff(p.z) / np.diff(p.x)) ** 2) for p in scans])
    n_points = sum(p.n_points for p in scans)
    rq = float(np.sqrt(squares.sum() / n_points))
    if rq == 0:
        raise InputError("nanoblock geometry: the surface is flat after levelling (Rq = 0).")
    slope = float(np.sqrt(slope_squares.sum() / (n_points - len(scans))))
    lambda_q = rms_wavelength(rq, slope)
    h_at = atomic_height_factor * rq
    h_adh = adhesive_height_factor * rq
    widths_at = np.concatenate([asperity_widths(p, h_at) for p in scans])
    widths_adh = np.concatenate([asperity_widths(p, -h_adh) for p in scans])
    for widths, what, lvl in ((widths_at, "atomic", h_at), (widths_adh, "adhesive", -h_adh)):
        if widths.size == 0:
            raise InputError(f"nanoblock geometry: no complete asperity crosses the {what} cut level {lvl:.4g} m "
                             "(the profile is too short for this statistic; use a longer scan).")
    w_at, w_adh = float(widths_at.mean()), float(widths_adh.mean())
    m = int(math.floor(w_adh / lambda_q))
    if m < 1:
        raise InputError(f"nanoblock geometry: the adhesive width {w_adh:.4g} m is smaller than lambda_q = "
                         f"{lambda_q:.4g} m, so not even one atomic block fits at that pitch "
                         "(m = floor(w_adh / lambda_q) = 0). Give the geometry explicitly (parameters) instead.")
    what = f"{len(scans)} line scan(s), {n_points} points"
    rules = {
        "atomic_height": f"{atomic_height_factor:g} Rq, Rq = {rq:.6g} m ({what}); thesis 3.4.1, MODEL §1.4",
        "adhesive_height": f"{adhesive_height_factor:g} Rq, Rq = {rq:.6g} m; thesis 3.4.1, MODEL §1.4",
        "atomic_width": (f"mean width (3-26) of the {widths_at.size} asperities above +{atomic_height_factor:g} Rq "
                         f"= {h_at:.4g} m; MODEL §1.4"),
        "adhesive_width": (f"mean width (3-26) of the {widths_adh.size} asperities above -{adhesive_height_factor:g} Rq "
                           f"= {-h_adh:.4g} m (the adhesive subscale lies below the atomic one); MODEL §1.4"),
        "atomic_pitch": f"lambda_q = 2 pi Rq / Delta_q (4-5), Delta_q = {slope:.6g} (4-6); MODEL §1.4",
        "atomic_per_side": f"floor(adhesive_width / lambda_q) = floor({w_adh / lambda_q:.4g}); MODEL §1.4",
    }
    if bulk_height is None:
        bulk_height = w_adh
        rules["bulk_height"] = "equal to adhesive_width (MODEL §4)"
    else:
        rules["bulk_height"] = "given"
    return NanoblockGeometry(atomic_width=w_at, atomic_height=h_at, adhesive_width=w_adh, adhesive_height=h_adh,
                             atomic_pitch=lambda_q, atomic_per_side=m, bulk_height=bulk_height, rules=rules)
