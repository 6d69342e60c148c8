"""The Maugis-Dugdale zone on a grid that does not resolve it: the same work of adhesion, a zone the grid resolves.

On the meshing cycle's default grid (24.8 nm) the cohesive zone at a contact edge (5-9 nm wide) lies inside the
element next to the edge: the gap at that element's centre is already several h0, the piecewise-linear gap of
:func:`memstribo.physics.contact.cohesive._cohesive_fraction` gives it no fraction, and the attraction that acts
depends on where the grid's elements fall, not on w (doubling w did not change it; issue #25). Where the zone is
narrow against the contact (the JKR-like side, Maugis parameter above ~1) the contact and its attraction depend on
the work of adhesion w = sigma0 h0, and on sigma0 only weakly (the closed form of
:func:`memstribo.physics.closed_form.maugis_dugdale_line_tension` at the torque's load: the whole tension 46.82,
46.24 and 45.74 N/m at sigma0, sigma0 / 2 and sigma0 / 2.5, the contact half-width 529.6, 522.1, 519.0 nm). So,
as cohesive finite elements do (Turon et al. 2007): where the zone's small-scale width d is narrower than
``elements`` grid elements, the solve uses the lower stress and longer range that keep w and make the zone
``elements`` elements wide, while an element in contact still holds a tension up to sigma0 before it opens
(:func:`resolved_zones`); where the grid resolves the zone, nothing changes (docs/contact.md, "Unresolved zone").
"""

from __future__ import annotations

import math

from memstribo.references import cites


@cites("maugis_1992", "dugdale_1960")
def zone_width(contact_modulus, cohesive_stress, cohesive_range):
    """Width d [m] of the Dugdale zone at a contact edge in the small-scale (JKR-like) limit.

    d = pi w E* / (4 sigma0^2) = pi h0 E* / (4 sigma0): the small-scale limit of Dugdale's (1960) strip zone,
    d = pi K^2 / (8 sigma0^2), with the energy release rate K^2 / E' = w (Maugis 1992) and the plane-strain modulus
    of one material E' = 2 E* (E* the pair's contact modulus, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2).
    ``contact_modulus`` E* [Pa], ``cohesive_stress`` sigma0 [Pa], ``cohesive_range`` h0 [m]. Si/Si (E* = 85 GPa,
    sigma0 = 1.785 GPa, h0 = 0.249 nm): 9.33 nm; the Maugis-Dugdale line contact at the torque's load (Maugis
    parameter 3.6) has 7.64 nm.
    """
    return math.pi * float(cohesive_range) * float(contact_modulus) / (4.0 * float(cohesive_stress))


@cites("turon_2007", "maugis_1992")
def resolved_zone(dx, contact_modulus, cohesive_stress, cohesive_range, elements):
    """(sigma [Pa], h [m]) of the Dugdale law the solve uses on a grid of spacing ``dx`` [m].

    (``cohesive_stress``, ``cohesive_range``) unchanged where the zone width d of :func:`zone_width` spans at least
    ``elements`` [count] grid elements (or ``elements`` <= 0: off); else sigma = sigma0 sqrt(d / (elements dx)) and
    h = w / sigma, which keep w = sigma0 h0 and make the small-scale zone ``elements`` elements wide (Turon et
    al. 2007: the interface strength lowered so that a chosen number of elements spans the cohesive zone, the
    fracture energy kept). ``contact_modulus`` E* [Pa].
    """
    sigma0, h0 = float(cohesive_stress), float(cohesive_range)
    if not (elements > 0 and sigma0 > 0.0 and h0 > 0.0 and dx > 0.0):
        return sigma0, h0
    d = zone_width(contact_modulus, sigma0, h0)
    if d >= elements * dx:
        return sigma0, h0
    sigma = sigma0 * math.sqrt(d / (elements * dx))
    return sigma, sigma0 * h0 / sigma


def resolved_zones(dx, contact_modulus, cohesive_stress, cohesive_range, elements, contact_only):
    """The solve's cohesive zones (``zones`` of :func:`.cohesive._cohesive_fraction`) and their range.

    Returns (None, h0) where the grid resolves the zone (:func:`resolved_zone` leaves it as it is), else
    (((sigma, h), (sigma0 - sigma, contact_only h0)), h): the resolved law (sigma, h) of :func:`resolved_zone`
    outside the contact, and the rest of sigma0 on the elements in contact only. An element in contact then still
    holds a tension up to sigma0 before it opens, as on a fine grid (with sigma alone the coarse contact split
    between asperities where the fine one stays closed, and its tension fell a further 2-3 %); the work of
    separation stays w (the second part has no range: ``contact_only`` [-], its range relative to h0, is so small,
    ``SolverSettings.contact_only_range``, that only elements in contact carry it). Arguments as
    :func:`resolved_zone` (dx [m], E* [Pa], sigma0 [Pa], h0 [m], elements [count]); sigma [Pa], h [m].
    """
    sigma0, h0 = float(cohesive_stress), float(cohesive_range)
    sigma, h = resolved_zone(dx, contact_modulus, sigma0, h0, elements)
    if sigma >= sigma0:
        return None, h0
    return ((sigma, h), (sigma0 - sigma, contact_only * h0)), h
