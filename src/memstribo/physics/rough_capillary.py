"""Capillary adhesion of two rough surfaces: the adhesion energy Gamma(RH) of a microbeam (issue #36, MODEL 7g).

Microbeams (cantilevers adhered to their substrate, read by their crack length) measure an adhesion *energy* per
apparent area, not a force. For hydrophilic polysilicon it stays at its dry value, the van der Waals attraction
across the extensive non-contacting areas, below a threshold RH, then jumps as water condenses and rises towards
the upper limit 2 gamma cos theta (144 mJ/m^2 for theta = 0) near saturation ([1]_, [2]_, [3]_). The model is the
asperity-level one of those papers, on a gap map of the measured (or synthesised) topography: the two surfaces held
rigidly with the highest summit of their summed heights touching (:func:`rigid_interface_gaps`); every element of the
map holds the larger of its van der Waals energy at its gap (:func:`vdw_adhesion_energy`) and the work of the water
bridge that fills it where the gap is below the bridging height (:func:`capillary_adhesion_energy`); their mean is
Gamma (:func:`rough_adhesion_energy`). A meniscus needs a Kelvin radius of at least one molecular diameter
(:func:`memstribo.physics.capillary.forms_meniscus`); the adsorbed water film that narrows the gap a bridge must
close is its liquid-like part only (:func:`memstribo.physics.capillary.liquid_water_thickness`: the first three
ice-like layers on silicon oxide, complete by RH 0.3, do not flow into a meniscus, Asay and Kim 2005). The
threshold: the RH at which the water's work reaches the dry energy (:func:`capillary_threshold_humidity`), where
the bridging height reaches the heights of the asperities next to the contacting ones.

Not modelled: the beam's compliance (it touches the highest summit only, a rigid-beam lower bound on the number of
contacts) and the correlation of the beam's underside with the substrate (DelRio et al. 2007 needed it to match
their data, [1]_); the solids' attraction across the water (its Hamaker constant) is taken as the larger of the two
works per element, not their sum.

References
----------
.. [1] F. W. DelRio, M. L. Dunn, L. M. Phinney, C. J. Bourdon, M. P. de Boer, "Rough surface adhesion in the presence
   of capillary condensation", Appl. Phys. Lett. 90 (2007) 163104. :doi:`10.1063/1.2723658`
.. [2] M. P. de Boer, "Capillary adhesion between elastically hard rough surfaces", Exp. Mech. 47 (2007) 171-183.
   :doi:`10.1007/s11340-006-0631-z`
.. [3] "Effects of capillary condensation in adhesion between rough surfaces", Langmuir 25 (2009) 11727-11731.
   :doi:`10.1021/la900455k`
.. [4] J. N. Israelachvili, Intermolecular and Surface Forces, 3rd ed., Academic Press, 2011, chapters 13 and 17.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.physics import capillary
from memstribo.references import cites

__all__ = ["rigid_interface_gaps", "vdw_adhesion_energy", "capillary_adhesion_energy", "rough_adhesion_energy",
           "capillary_threshold_humidity", "meniscus_adhesion_pressure"]


def _gaps(gaps):
    g = np.asarray(gaps, dtype=float)
    if g.size == 0 or np.any(~np.isfinite(g)) or np.any(g < 0):
        raise InputError("gaps must be a non-empty array of finite, non-negative separations [m].")
    return g


@cites("delrio_2007")
def rigid_interface_gaps(heights_1, heights_2=None):
    """Gap map of two rough surfaces held rigidly against each other [m]: ``max(s) - s``, ``s = z_1 + z_2``.

    ``heights_1``, ``heights_2`` [m]: the heights of each surface towards the other on the same grid (a line or a
    map; the second omitted: a rough surface on a flat). Their sum closes the gap; the surfaces touch at the highest
    summit of the sum, the rigid-beam picture of [1]_ (one contact).
    """
    s = np.asarray(heights_1, dtype=float) + (0.0 if heights_2 is None else np.asarray(heights_2, dtype=float))
    if s.size == 0 or np.any(~np.isfinite(s)):
        raise InputError("heights must be a non-empty array of finite heights [m].")
    return s.max() - s


@cites("israelachvili_2011", "delrio_2007")
def vdw_adhesion_energy(gaps, hamaker_constant, cutoff_distance):
    """Van der Waals energy per area of each element of a gap map [J/m^2]: ``A / (12 pi (g + D0)^2)``, Eq. (13.11).

    The flat-flat law of [4]_ at each gap g, offset by the contact separation D0 so that a touching element holds
    the work of adhesion ``A / (12 pi D0^2)``; the dry plateau of a rough interface is its mean (the attraction
    across the non-contacting areas, [1]_). ``hamaker_constant`` A [J], ``cutoff_distance`` D0 [m].
    """
    g = _gaps(gaps)
    a = float(as_array(hamaker_constant, "hamaker_constant", "J", positive=True))
    d0 = float(as_array(cutoff_distance, "cutoff_distance", "m", positive=True))
    return a / (12.0 * math.pi * (g + d0) ** 2)


@cites("delrio_2007", "deboer_2007", "butt_kappl_2009")
def capillary_adhesion_energy(gaps, relative_humidity, contact_angle_1, contact_angle_2=None, films=None,
                              temperature=capillary.REFERENCE_TEMPERATURE, surface_tension=None,
                              molar_volume=capillary.WATER["molar_volume"]):
    """Work of the water bridges per area at each element of a gap map [J/m^2] (0 where dry).

    ``(gamma / r_K) (h - max(g, t_1 + t_2))`` where the gap g is below the bridging height ``h = h_c + t_1 + t_2``
    (:func:`memstribo.physics.capillary.meniscus_work_of_separation`, [2]_): at most ``gamma (cos theta_1 + cos
    theta_2)`` on a filled slit. None below a molecular Kelvin radius (an adsorbed film, not a meniscus).

    Parameters
    ----------
    gaps : array_like
        Gap map [m], >= 0.
    relative_humidity : float
        RH (or p / p_sat of the vapour) [-] in [0, 1).
    contact_angle_1, contact_angle_2 : float
        The liquid's contact angles on the two surfaces [rad]; the second defaults to the first.
    films : float, optional
        t_1 + t_2, the liquid-like adsorbed films [m]; default the oxide's
        (:func:`memstribo.physics.capillary.liquid_water_thickness` on each hydrophilic surface).
    temperature : float
        T [K].
    surface_tension, molar_volume : float, optional
        gamma [N/m] (default water's at T) and V_m [m^3/mol] of the liquid.
    """
    g = _gaps(gaps)
    gamma = capillary.water_surface_tension(temperature) if surface_tension is None else surface_tension
    r_k = capillary.kelvin_radius(relative_humidity, temperature, gamma, molar_volume)
    if not capillary.forms_meniscus(r_k, molar_volume):
        return np.zeros(g.shape)
    theta_2 = contact_angle_1 if contact_angle_2 is None else contact_angle_2
    if films is None:
        t = capillary.liquid_water_thickness(relative_humidity)
        films = sum(t for theta in (contact_angle_1, theta_2) if theta < 0.5 * math.pi)
    height = capillary.bridging_height(r_k, 0.5 * films, 0.5 * films, contact_angle_1, theta_2)
    return capillary.meniscus_work_of_separation(g, r_k, height, films, gamma)


@cites("delrio_2007", "deboer_2007")
def rough_adhesion_energy(gaps, relative_humidity, hamaker_constant, cutoff_distance, contact_angle_1,
                          contact_angle_2=None, films=None, temperature=capillary.REFERENCE_TEMPERATURE,
                          surface_tension=None, molar_volume=capillary.WATER["molar_volume"]):
    """Adhesion energy Gamma of a rough interface in a vapour [J/m^2]: the mean over the gap map of the larger of
    the van der Waals energy and the water bridge's work at each element ([1]_, [2]_).

    One work per element (the wetted solids' work of separation, 2 gamma_SV = W_SLS + 2 gamma cos theta by Young's
    equation, lies between the two; [4]_ ch. 17): dry, the mean of :func:`vdw_adhesion_energy` (the low-RH plateau);
    as the bridging height reaches the heights of the asperities around the contacts, the bridges fill more of the
    map and Gamma rises towards ``gamma (cos theta_1 + cos theta_2)``. The arguments are those of
    :func:`vdw_adhesion_energy` and :func:`capillary_adhesion_energy`.

    Examples
    --------
    >>> g = np.linspace(0.0, 20e-9, 2001)  # a wedge of gaps from contact to 20 nm
    >>> dry = rough_adhesion_energy(g, 0.0, 6.3e-20, 0.165e-9, math.radians(30))
    >>> wet = rough_adhesion_energy(g, 0.95, 6.3e-20, 0.165e-9, math.radians(30))
    >>> print(f"{dry * 1e3:.2f} {wet * 1e3:.1f} mJ/m^2")
    0.52 71.4 mJ/m^2
    """
    vdw = vdw_adhesion_energy(gaps, hamaker_constant, cutoff_distance)
    water = capillary_adhesion_energy(gaps, relative_humidity, contact_angle_1, contact_angle_2, films, temperature,
                                      surface_tension, molar_volume)
    return float(np.mean(np.maximum(vdw, water)))


@cites("delrio_2007")
def capillary_threshold_humidity(gaps, hamaker_constant, cutoff_distance, contact_angle_1, contact_angle_2=None,
                                 temperature=capillary.REFERENCE_TEMPERATURE, factor=2.0):
    """The threshold RH of a rough interface [-]: the lowest RH at which Gamma reaches ``factor`` times its dry value.

    Below it the adhesion is the van der Waals plateau, above it the water's ([1]_: "below a threshold RH, the
    adhesion is mainly due to van der Waals forces across extensive noncontacting areas"). Found by bisection on
    RH in [0, 0.999) (Gamma rises with RH); None when Gamma stays below ``factor`` times the dry value up to RH 0.999
    (a hydrophobic pair). Arguments as :func:`rough_adhesion_energy`; ``factor`` > 1.
    """
    if not factor > 1.0:
        raise InputError(f"factor must be above 1 (Gamma relative to its dry value), got {factor!r}.")

    def excess(rh):
        return rough_adhesion_energy(gaps, rh, hamaker_constant, cutoff_distance, contact_angle_1, contact_angle_2,
                                     temperature=temperature) - factor * dry

    dry = rough_adhesion_energy(gaps, 0.0, hamaker_constant, cutoff_distance, contact_angle_1, contact_angle_2,
                                temperature=temperature)
    low, high = 0.0, 0.999
    if excess(high) < 0:
        return None
    for _ in range(40):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if excess(mid) < 0 else (low, mid)
    return high


@cites("israelachvili_2011", "butt_kappl_2009")
def meniscus_adhesion_pressure(gaps, spacing, kelvin, height, surface_tension=capillary.WATER["surface_tension"]):
    """Mean attraction of the menisci of a rough interface per apparent area [Pa]: the meniscus bound per area.

    ``(gamma / r_K) phi + gamma L / A``: the Laplace pressure over the wetted fraction phi of the gap map (elements
    with ``g <= height``, the bridging height) plus the surface tension on the contact lines, L / A their length per
    apparent area (:func:`memstribo.physics.capillary.meniscus_force_bound` per area; the edges between wetted and
    dry elements of the map, each ``spacing`` long; a line map counts its wetted runs' ends per length). The force a
    flat pad of apparent area A needs beyond its load to come apart, and the adhesion that adds to the load it
    carries (MODEL 7g). 0 when r_K = 0 (dry, or an adsorbed film below a molecular Kelvin radius).

    Parameters
    ----------
    gaps : array_like
        Gap map (2D) or line (1D) [m], >= 0.
    spacing : float
        Grid spacing of the map [m].
    kelvin : float
        r_K [m].
    height : float
        Bridging height [m] (:func:`memstribo.physics.capillary.bridging_height`).
    surface_tension : float
        gamma [N/m].
    """
    g = _gaps(gaps)
    dx = float(as_array(spacing, "spacing", "m", positive=True))
    h = float(as_array(height, "height", "m", nonnegative=True))
    k = float(as_array(kelvin, "kelvin", "m", nonnegative=True))
    if k == 0.0 or h == 0.0:
        return 0.0
    wet = g <= h
    edges = sum(int(np.count_nonzero(np.diff(wet, axis=axis))) for axis in range(wet.ndim))
    if wet.ndim == 1:  # a line: the wetted runs' ends (one more at each end of the line that is wet) per length
        edges += int(wet[0]) + int(wet[-1])
        per_area = edges / (wet.size * dx)
    else:
        per_area = edges * dx / (wet.size * dx * dx)
    return float(capillary.meniscus_force_bound(float(np.mean(wet)), per_area, k, surface_tension))
