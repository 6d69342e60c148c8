"""Closed-form contact solutions: the references the numerical contact solver is checked against.

All functions take and return SI values and broadcast over numpy arrays. The elastic
bodies enter through the contact (reduced) modulus ``contact_modulus`` E* with
``1/E* = (1 - nu1**2)/E1 + (1 - nu2**2)/E2``.

Line contacts (plane strain) are per unit face width: ``load`` is w [N/m]. In plane
strain the surface displacement of a half-plane under a finite load grows like
``log(distance)``, so the rigid-body approach of a line contact is defined only relative to
a datum. memstribo's datum (also used by :func:`memstribo.physics.contact.solve_line_contact`) is
the far field: the surface displacement under a load w tends to
``(2 w / (pi E*)) ln(reference_distance / r)`` at a distance ``r`` from the load, i.e. the
displacement vanishes at ``reference_distance`` from a point load. With this datum the
Hertz approach :func:`hertz_line_approach` is exact for any ``reference_distance``;
:func:`hertz_line_approach_to_point` gives the approach measured to a surface point at a
finite distance instead.

References
----------
.. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985,
   sections 2.8, 4.2, 4.3, 5.6 and 13.1. :doi:`10.1017/CBO9781139171731`
.. [2] N. S. T. Almuramady, PhD thesis, Cardiff University, Eqs. (4-22) to (4-26).
.. [3] H. M. Westergaard, 'Bearing pressures and cracks', J. Appl. Mech. 6 (1939) A49-A53.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "maugis_dugdale_line_tension",
    "wavy_surface_full_contact_amplitude",
    "hertz_line_half_width",
    "hertz_line_peak_pressure",
    "hertz_line_pressure",
    "hertz_line_approach",
    "hertz_line_approach_to_point",
    "hertz_sphere_radius",
    "hertz_sphere_approach",
    "hertz_sphere_peak_pressure",
    "hertz_sphere_pressure",
    "flat_punch_line_pressure",
    "westergaard_mean_pressure",
    "westergaard_contact_half_width",
    "westergaard_pressure",
    "jkr_line_load",
    "jkr_line_pull_off_load",
    "jkr_line_pull_off_half_width",
    "maugis_line_parameter",
    "maugis_dugdale_line_load",
    "maugis_dugdale_line_pull_off",
    "dugdale_rigid_line_pull_off",
]


# --------------------------------------------------------------------------- Hertz line contact


@cites("johnson_1985", "thesis")
def hertz_line_half_width(load, radius, contact_modulus):
    r"""Half-width of the Hertz line (cylinder) contact.

    Parameters
    ----------
    load : numeric
        Load per unit face width w [N/m].
    radius : numeric
        Effective radius of curvature R [m].
    contact_modulus : numeric
        Contact modulus E* [Pa].

    Returns
    -------
    numeric
        Contact half-width a [m].

    Notes
    -----
    .. math:: a = \sqrt{\frac{4 w R}{\pi E^*}}

    Eq. (4.43) in [1]_ and Eq. (4-22) in [2]_ (section 6 of docs/model.md).

    Examples
    --------
    >>> round(float(hertz_line_half_width(12.5, 20e-6, 100e9)) * 1e9, 2)
    56.42
    """
    w = as_array(load, "load", "N/m", positive=True)
    radius = as_array(radius, "radius", "m", positive=True)
    contact_modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    return np.sqrt(4.0 * w * radius / (np.pi * contact_modulus))


@cites("johnson_1985", "thesis")
def hertz_line_peak_pressure(load, radius, contact_modulus):
    r"""Peak pressure of the Hertz line contact.

    Parameters
    ----------
    load, radius, contact_modulus : as in :func:`hertz_line_half_width` (w [N/m], R [m], E* [Pa])

    Returns
    -------
    numeric
        Peak pressure p0 [Pa].

    Notes
    -----
    .. math:: p_0 = \frac{2 w}{\pi a} = \sqrt{\frac{w E^*}{\pi R}}

    Eq. (4.44) in [1]_, Eq. (4-23) in [2]_.
    """
    w = as_array(load, "load", "N/m", positive=True)
    return 2.0 * w / (np.pi * hertz_line_half_width(load, radius, contact_modulus))


@cites("johnson_1985")
def hertz_line_pressure(x, load, radius, contact_modulus):
    r"""Hertz pressure distribution of a line contact.

    Parameters
    ----------
    x : numeric
        Position from the contact centre [m].
    load, radius, contact_modulus : as in :func:`hertz_line_half_width` (w [N/m], R [m], E* [Pa])

    Returns
    -------
    numeric
        Pressure p(x) [Pa], zero outside the contact.

    Notes
    -----
    .. math:: p(x) = p_0 \sqrt{1 - x^2/a^2}, \quad |x| \le a

    Eq. (4.42) in [1]_.
    """
    a = hertz_line_half_width(load, radius, contact_modulus)
    p0 = hertz_line_peak_pressure(load, radius, contact_modulus)
    ratio = np.asanyarray(x, dtype=float) / a
    return p0 * np.sqrt(np.clip(1.0 - ratio**2, 0.0, None))


@cites("johnson_1985")
def hertz_line_approach(load, radius, contact_modulus, reference_distance):
    r"""Approach of a Hertz line contact relative to memstribo's far-field datum.

    Parameters
    ----------
    load, radius, contact_modulus : as in :func:`hertz_line_half_width` (w [N/m], R [m], E* [Pa])
    reference_distance : numeric
        Datum distance L [m]: the displacement due to a point load is taken as zero at
        distance L from it (module docstring).

    Returns
    -------
    numeric
        Approach (elastic displacement at the contact centre) delta [m].

    Notes
    -----
    With the half-plane displacement :math:`u(x) = \frac{2}{\pi E^*}\int p(s)\ln\frac{L}{|x-s|}ds`
    and the Hertz pressure, :math:`u(0)` is

    .. math:: \delta = \frac{w}{\pi E^*}\left(1 + 2\ln\frac{2L}{a}\right)

    the far-field limit of the cylinder approach in section 5.6 of [1]_ (derivation in
    docs/contact.md). A 2D approach needs such a reference length; it is not a property of
    the contact alone.
    """
    w = as_array(load, "load", "N/m", positive=True)
    L = as_array(reference_distance, "reference_distance", "m", positive=True)
    a = hertz_line_half_width(load, radius, contact_modulus)
    contact_modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    return w / (np.pi * contact_modulus) * (1.0 + 2.0 * np.log(2.0 * L / a))


@cites("johnson_1985")
def hertz_line_approach_to_point(load, radius, contact_modulus, distance):
    r"""Approach of a Hertz line contact measured to a surface point at a finite distance.

    Parameters
    ----------
    load, radius, contact_modulus : as in :func:`hertz_line_half_width` (w [N/m], R [m], E* [Pa])
    distance : numeric
        Distance d >= a of the surface reference point from the contact centre [m].

    Returns
    -------
    numeric
        u(0) - u(d) [m], the displacement of the centre relative to that point.

    Notes
    -----
    With D = d/a >= 1,

    .. math:: \delta(d) = \frac{2w}{\pi E^*}\left(D^2 - D\sqrt{D^2-1} + \operatorname{arccosh} D\right)

    which gives a²/(2R) at D = 1 (the contact edge) and tends to
    :func:`hertz_line_approach` with L = d for D >> 1 (docs/contact.md).
    """
    w = as_array(load, "load", "N/m", positive=True)
    a = hertz_line_half_width(load, radius, contact_modulus)
    D = as_array(distance, "distance", "m", positive=True) / a
    if np.any(D < 1.0):
        raise InputError("distance must be at least the Hertz half-width a (the point must lie outside the contact)")
    return 2.0 * w / (np.pi * as_array(contact_modulus, "contact_modulus", "Pa", positive=True)) * (
        D**2 - D * np.sqrt(D**2 - 1.0) + np.arccosh(D))


# ------------------------------------------------------------------------------ Hertz sphere


@cites("johnson_1985")
def hertz_sphere_radius(force, radius, contact_modulus):
    r"""Contact radius of a Hertz sphere-on-flat contact.

    Parameters
    ----------
    force : numeric
        Normal force F [N].
    radius : numeric
        Effective radius R [m].
    contact_modulus : numeric
        Contact modulus E* [Pa].

    Returns
    -------
    numeric
        Contact radius a [m].

    Notes
    -----
    .. math:: a = \left(\frac{3 F R}{4 E^*}\right)^{1/3}

    Eq. (4.22) in [1]_.
    """
    return np.cbrt(3.0 * as_array(force, "force", "N", positive=True) * as_array(radius, "radius", "m", positive=True)
                   / (4.0 * as_array(contact_modulus, "contact_modulus", "Pa", positive=True)))


@cites("johnson_1985")
def hertz_sphere_approach(force, radius, contact_modulus):
    r"""Approach (mutual indentation) of a Hertz sphere contact.

    Parameters
    ----------
    force, radius, contact_modulus : as in :func:`hertz_sphere_radius` (F [N], R [m], E* [Pa])

    Returns
    -------
    delta : numeric
        Approach a²/R [m].

    Notes
    -----
    Eq. (4.23) in [1]_.
    """
    return hertz_sphere_radius(force, radius, contact_modulus) ** 2 / as_array(radius, "radius", "m", positive=True)


@cites("johnson_1985")
def hertz_sphere_peak_pressure(force, radius, contact_modulus):
    r"""Peak pressure of a Hertz sphere contact.

    Parameters
    ----------
    force, radius, contact_modulus : as in :func:`hertz_sphere_radius` (F [N], R [m], E* [Pa])

    Returns
    -------
    p0 : numeric
        Peak pressure 3F/(2 pi a²) [Pa].

    Notes
    -----
    Eq. (4.21) in [1]_.
    """
    a = hertz_sphere_radius(force, radius, contact_modulus)
    return 3.0 * as_array(force, "force", "N", positive=True) / (2.0 * np.pi * a**2)


@cites("johnson_1985")
def hertz_sphere_pressure(r, force, radius, contact_modulus):
    r"""Hertz pressure distribution of a sphere contact.

    Parameters
    ----------
    r : numeric
        Radial distance from the contact centre [m].
    force, radius, contact_modulus : as in :func:`hertz_sphere_radius` (F [N], R [m], E* [Pa])

    Returns
    -------
    numeric
        p(r) = p0 sqrt(1 - r²/a²) inside the contact, 0 outside [Pa].

    Notes
    -----
    Eq. (4.20) in [1]_.
    """
    a = hertz_sphere_radius(force, radius, contact_modulus)
    ratio = np.asanyarray(r, dtype=float) / a
    return hertz_sphere_peak_pressure(force, radius, contact_modulus) * np.sqrt(np.clip(1.0 - ratio**2, 0.0, None))


# ------------------------------------------------------------------- rigid flat punch (2D)


@cites("johnson_1985")
def flat_punch_line_pressure(x, load, half_width):
    r"""Pressure under a rigid flat punch pressed into a half-plane (plane strain).

    Parameters
    ----------
    x : numeric
        Position from the punch centre [m].
    load : numeric
        Load per unit face width w [N/m].
    half_width : numeric
        Punch half-width b [m].

    Returns
    -------
    numeric
        p(x) = w / (pi sqrt(b² - x²)) for ``|x| < b``, 0 outside [Pa] (singular at the edges).

    Notes
    -----
    Eq. (2.64) in [1]_ (section 2.8).
    """
    b = as_array(half_width, "half_width", "m", positive=True)
    x = np.asanyarray(x, dtype=float)
    inside = np.abs(x) < b
    squared = np.where(inside, b**2 - x**2, 1.0)
    return np.where(inside, as_array(load, "load", "N/m", positive=True) / (np.pi * np.sqrt(squared)), 0.0)


# ----------------------------------------------------- Westergaard periodic wavy contact (2D)


def _westergaard_full_contact_pressure(amplitude, wavelength, contact_modulus):
    contact_modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    amplitude = as_array(amplitude, "amplitude", "m", positive=True)
    return np.pi * contact_modulus * amplitude / as_array(wavelength, "wavelength", "m", positive=True)


@cites("johnson_1985")
def westergaard_mean_pressure(half_width, amplitude, wavelength, contact_modulus):
    r"""Mean pressure of a periodic wavy line contact for a given contact half-width.

    The undeformed gap is :math:`h(x) = \Delta (1 - \cos(2\pi x/\lambda))` (peak-to-valley 2Δ)
    against a flat, periodic with wavelength λ.

    Parameters
    ----------
    half_width : numeric
        Contact half-width a, 0 <= a <= λ/2 [m].
    amplitude : numeric
        Amplitude Δ [m].
    wavelength : numeric
        Wavelength λ [m].
    contact_modulus : numeric
        Contact modulus E* [Pa].

    Returns
    -------
    numeric
        Mean (nominal) pressure p̄ = p* sin²(π a/λ) with p* = π E* Δ/λ [Pa].

    Notes
    -----
    Eq. (13.6) in [1]_ (Westergaard [3]_).
    """
    p_star = _westergaard_full_contact_pressure(amplitude, wavelength, contact_modulus)
    return p_star * np.sin(np.pi * np.asanyarray(half_width, dtype=float) / wavelength) ** 2


@cites("johnson_1985")
def westergaard_contact_half_width(mean_pressure, amplitude, wavelength, contact_modulus):
    r"""Contact half-width of a periodic wavy line contact at a given mean pressure.

    Parameters
    ----------
    mean_pressure : numeric
        Mean pressure p̄ [Pa]; at p̄ >= p* = π E* Δ/λ the contact is complete (a = λ/2).
    amplitude, wavelength, contact_modulus : as in :func:`westergaard_mean_pressure` (Δ [m], λ [m], E* [Pa])

    Returns
    -------
    numeric
        a = (λ/π) arcsin(sqrt(p̄/p*)) [m].

    Notes
    -----
    Inverse of Eq. (13.6) in [1]_.
    """
    p_star = _westergaard_full_contact_pressure(amplitude, wavelength, contact_modulus)
    ratio = np.clip(as_array(mean_pressure, "mean_pressure", "Pa", positive=True) / p_star, 0.0, 1.0)
    return wavelength / np.pi * np.arcsin(np.sqrt(ratio))


@cites("johnson_1985")
def westergaard_pressure(x, mean_pressure, amplitude, wavelength, contact_modulus):
    r"""Pressure of a periodic wavy line contact (Westergaard).

    Parameters
    ----------
    x : numeric
        Position from a crest (the centre of a contact) [m].
    mean_pressure : numeric
        Mean pressure p̄ [Pa].
    amplitude, wavelength, contact_modulus : as in :func:`westergaard_mean_pressure` (Δ [m], λ [m], E* [Pa])

    Returns
    -------
    numeric
        p(x) [Pa].

    Notes
    -----
    Partial contact (p̄ < p*), Eq. (13.7) in [1]_:

    .. math:: p(x) = \frac{2\bar p \cos(\pi x/\lambda)}{\sin^2(\pi a/\lambda)}
              \sqrt{\sin^2(\pi a/\lambda) - \sin^2(\pi x/\lambda)}

    Full contact (p̄ >= p*): :math:`p(x) = \bar p + p^* \cos(2\pi x/\lambda)`.
    """
    p_bar = as_array(mean_pressure, "mean_pressure", "Pa", positive=True)
    p_star = _westergaard_full_contact_pressure(amplitude, wavelength, contact_modulus)
    x = np.asanyarray(x, dtype=float)
    if np.all(p_bar >= p_star):
        return p_bar + p_star * np.cos(2.0 * np.pi * x / wavelength)
    a = westergaard_contact_half_width(mean_pressure, amplitude, wavelength, contact_modulus)
    s_a = np.sin(np.pi * a / wavelength) ** 2
    s_x = np.sin(np.pi * x / wavelength) ** 2
    return 2.0 * p_bar * np.abs(np.cos(np.pi * x / wavelength)) / s_a * np.sqrt(np.clip(s_a - s_x, 0.0, None))


# --------------------------------------------------------------------------- adhesive line contact


@cites("johnson_1985", "model")
def jkr_line_load(half_width, radius, contact_modulus, work_of_adhesion):
    r"""Load of the JKR line contact (cylinder on a flat, plane strain, per unit length) at a half-width.

    Parameters
    ----------
    half_width : numeric
        Contact half-width a [m].
    radius : numeric
        Effective radius R [m].
    contact_modulus : numeric
        Contact modulus E* [Pa].
    work_of_adhesion : numeric
        Work of adhesion w [J/m²].

    Returns
    -------
    numeric
        Net load per unit length P [N/m] (negative: tensile).

    Notes
    -----
    .. math:: P = \frac{\pi E^* a^2}{4R} - \sqrt{2\pi E^* w a}

    The Hertz load of half-width a minus the flat-punch load whose edge stress intensity
    :math:`K = \sqrt{2E^*w}` releases the energy w (Barquins, J. Adhesion 26 (1988) 1;
    Chaudhury, Weaver, Hui, Kramer, J. Appl. Phys. 80 (1996) 30; docs/model.md §7c).

    Examples
    --------
    >>> round(float(jkr_line_load(100e-9, 10e-6, 85e9, 0.445)), 2)
    -87.4
    """
    a = as_array(half_width, "half_width", "m", positive=True)
    radius = as_array(radius, "radius", "m", positive=True)
    modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", nonnegative=True)
    return np.pi * modulus * a**2 / (4.0 * radius) - np.sqrt(2.0 * np.pi * modulus * w * a)


@cites("johnson_1985", "model")
def jkr_line_pull_off_load(radius, contact_modulus, work_of_adhesion):
    r"""Pull-off load of the JKR line contact under load control, per unit length.

    Parameters
    ----------
    radius, contact_modulus, work_of_adhesion : as in :func:`jkr_line_load` (R [m], E* [Pa], w [J/m²])

    Returns
    -------
    load : numeric
        The (negative, tensile) load at pull-off P_c [N/m], the minimum of :func:`jkr_line_load`.

    Notes
    -----
    .. math:: P_c = -\frac34\left(4\pi E^* w^2 R\right)^{1/3}

    at :math:`a_c = (2 R^2 w / (\pi E^*))^{1/3}` (Chaudhury et al. 1996; docs/model.md §7c).

    Examples
    --------
    >>> round(float(jkr_line_pull_off_load(10e-6, 85e9, 0.445)), 2)
    -96.27
    """
    radius = as_array(radius, "radius", "m", positive=True)
    modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", nonnegative=True)
    return -0.75 * np.cbrt(4.0 * np.pi * modulus * w**2 * radius)


@cites("johnson_1985", "model")
def jkr_line_pull_off_half_width(radius, contact_modulus, work_of_adhesion):
    r"""Contact half-width of the JKR line contact at pull-off (load control) [m].

    Parameters
    ----------
    radius, contact_modulus, work_of_adhesion : as in :func:`jkr_line_load` (R [m], E* [Pa], w [J/m²])

    Returns
    -------
    half_width : numeric
        :math:`a_c = (2 R^2 w / (\pi E^*))^{1/3}` [m], where dP/da = 0 in :func:`jkr_line_load`.
    """
    radius = as_array(radius, "radius", "m", positive=True)
    modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", nonnegative=True)
    return np.cbrt(2.0 * radius**2 * w / (np.pi * modulus))


@cites("maugis_1992", "johnson_greenwood_2008", "baney_hui_1997")
def maugis_line_parameter(radius, contact_modulus, work_of_adhesion, cohesive_stress):
    r"""Maugis parameter of a line contact [-].

    Parameters
    ----------
    radius, contact_modulus, work_of_adhesion : as in :func:`jkr_line_load` (R [m], E* [Pa], w [J/m²])
    cohesive_stress : numeric
        Dugdale stress sigma0 [Pa] (w = sigma0 h0 sets the range h0).

    Returns
    -------
    numeric
        :math:`\lambda = 2\sigma_0 \left(\frac{R}{\pi w E^{*2}}\right)^{1/3}`.

    Notes
    -----
    The definition of Maugis (1992) for spheres, used unchanged for the cylinder (as by
    Johnson & Greenwood, "A Maugis analysis of adhesive line contact", J. Phys. D: Appl. Phys. 41
    (2008), and Baney & Hui, J. Adhesion Sci. Technol.
    11 (1997) 393, up to their normalisation of the load). Large lambda: JKR; small: the
    rigid (Derjaguin) limit :func:`dugdale_rigid_line_pull_off`. Silicon teeth (E* = 85 GPa,
    R = 10 um, w = 0.445 J/m², sigma0 = 1.78 GPa): lambda = 3.55.

    Examples
    --------
    >>> round(float(maugis_line_parameter(10e-6, 85e9, 0.445, 1.78e9)), 2)
    3.55
    """
    radius = as_array(radius, "radius", "m", positive=True)
    modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True)
    sigma0 = as_array(cohesive_stress, "cohesive_stress", "Pa", nonnegative=True)
    return 2.0 * sigma0 * np.cbrt(radius / (np.pi * w * modulus**2))


def _dugdale_opening_integral(m):
    """int_1^m ln((T + s)/(T - s)) dxi with T = sqrt(m^2 - 1), s = sqrt(xi^2 - 1) (xi = sqrt(1 + T^2 sin^2 t))."""
    from scipy.integrate import quad

    t2 = m * m - 1.0
    if t2 <= 0.0:
        return 0.0

    def integrand(theta):
        sine = np.sin(theta)
        return 2.0 * np.arctanh(min(sine, 1.0 - 1e-16)) * t2 * sine * np.cos(theta) / np.sqrt(1.0 + t2 * sine**2)

    return quad(integrand, 0.0, 0.5 * np.pi, limit=200)[0]


def _maugis_line_scalar(a, radius, modulus, w, sigma0):
    from scipy.optimize import brentq

    h0 = w / sigma0

    def opening(m):  # gap at the end c = m a of the cohesive zone, minus h0
        t = np.sqrt(m * m - 1.0)
        return (a * a / (2.0 * radius) * (m * t - np.arccosh(m))
                + 2.0 * sigma0 * a / (np.pi * modulus) * _dugdale_opening_integral(m) - h0)

    upper = 2.0
    while opening(upper) < 0.0:
        upper *= 2.0
    m = brentq(opening, 1.0, upper, xtol=1e-14, rtol=1e-13)
    load = np.pi * modulus * a * a / (4.0 * radius) - 2.0 * sigma0 * a * np.sqrt(m * m - 1.0)
    return load, m * a


@cites("maugis_1992", "baney_hui_1997", "johnson_greenwood_2008", "johnson_1985")
def maugis_dugdale_line_load(half_width, radius, contact_modulus, work_of_adhesion, cohesive_stress):
    r"""Maugis-Dugdale line contact (cylinder on a flat, per unit length): load and cohesive zone at a half-width.

    Parameters
    ----------
    half_width, radius, contact_modulus, work_of_adhesion : numeric
        As in :func:`jkr_line_load` (a [m], R [m], E* [Pa], w [J/m²]).
    cohesive_stress : numeric
        Dugdale stress sigma0 [Pa]; the range is h0 = w / sigma0.

    Returns
    -------
    load : numeric
        Net load P [N/m] (negative: tensile).
    cohesive_half_width : numeric
        End c of the cohesive zone [m] (the Dugdale stress acts on a < |x| < c).

    Notes
    -----
    Plane strain, tension -sigma0 on a < |x| < c, bounded stress at the contact edge (the
    line-contact analogue of Maugis 1992; Baney & Hui 1997; Johnson & Greenwood 2008).
    With m = c/a, from the inversion of the half-plane equation on |x| < a,

    .. math:: P = \frac{\pi E^* a^2}{4R} - 2\sigma_0 a\sqrt{m^2-1}

    and the gap at c equals h0:

    .. math:: \frac{a^2}{2R}\left[m\sqrt{m^2-1} - \operatorname{arccosh} m\right]
              + \frac{2\sigma_0 a}{\pi E^*}\int_1^m
              \ln\frac{\sqrt{m^2-1}+\sqrt{\xi^2-1}}{\sqrt{m^2-1}-\sqrt{\xi^2-1}}\,d\xi = h_0

    (the first term is the Hertz gap of half-width a, the second the opening by the Dugdale
    tension, whose slope outside the contact is
    :math:`\frac{2\sigma_0}{\pi E^*}\ln\frac{t_c+b}{t_c-b}`, b = sqrt(x²-a²), t_c = sqrt(c²-a²);
    derived for memstribo, docs/contact.md). The integral is evaluated by quadrature and m by
    root finding. As sigma0 -> infinity (w fixed) P tends to :func:`jkr_line_load`
    (checked in tests/test_adhesive_contact.py).

    Examples
    --------
    >>> load, c = maugis_dugdale_line_load(169.2e-9, 10e-6, 85e9, 0.445, 1.78e9)
    >>> round(float(load), 1), round(float(c) * 1e9, 1)
    (-0.2, 177.5)
    """
    a = as_array(half_width, "half_width", "m", positive=True)
    radius = float(as_array(radius, "radius", "m", positive=True))
    modulus = float(as_array(contact_modulus, "contact_modulus", "Pa", positive=True))
    w = float(as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True))
    sigma0 = float(as_array(cohesive_stress, "cohesive_stress", "Pa", positive=True))
    values = [_maugis_line_scalar(float(x), radius, modulus, w, sigma0) for x in np.ravel(a)]
    load = np.array([v[0] for v in values]).reshape(np.shape(a))
    c = np.array([v[1] for v in values]).reshape(np.shape(a))
    if np.ndim(a) == 0:
        return float(load), float(c)
    return load, c


@cites("maugis_1992", "baney_hui_1997", "johnson_greenwood_2008", "johnson_1985")
def maugis_dugdale_line_pull_off(radius, contact_modulus, work_of_adhesion, cohesive_stress):
    r"""Pull-off of the Maugis-Dugdale line contact under load control (least load of :func:`maugis_dugdale_line_load`).

    Parameters
    ----------
    radius, contact_modulus, work_of_adhesion, cohesive_stress : numeric
        As in :func:`maugis_dugdale_line_load` (R [m], E* [Pa], w [J/m²], sigma0 [Pa]).

    Returns
    -------
    load : float
        The (negative) load at pull-off [N/m].
    half_width : float
        The contact half-width there [m].

    Notes
    -----
    Minimum over a > 0 of P(a) (bounded scalar minimisation, a from 1e-4 to 10 times the JKR
    pull-off half-width). As the Maugis parameter grows it tends to
    :func:`jkr_line_pull_off_load`; as it vanishes, to :func:`dugdale_rigid_line_pull_off`
    (the minimum then sits at a -> 0).
    """
    from scipy.optimize import minimize_scalar

    radius = float(as_array(radius, "radius", "m", positive=True))
    modulus = float(as_array(contact_modulus, "contact_modulus", "Pa", positive=True))
    w = float(as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True))
    sigma0 = float(as_array(cohesive_stress, "cohesive_stress", "Pa", positive=True))
    scale = float(jkr_line_pull_off_half_width(radius, modulus, w))
    result = minimize_scalar(lambda s: _maugis_line_scalar(np.exp(s) * scale, radius, modulus, w, sigma0)[0],
                             bounds=(np.log(1e-4), np.log(10.0)), method="bounded",
                             options={"xatol": 1e-7})
    half_width = float(np.exp(result.x) * scale)
    return float(result.fun), half_width


@cites("maugis_1992", "baney_hui_1997", "johnson_greenwood_2008", "johnson_1985")
def maugis_dugdale_line_tension(line_load, radius, contact_modulus, work_of_adhesion, cohesive_stress):
    r"""Attraction of the Maugis-Dugdale line contact under a load: its total tensile traction and its zone.

    Parameters
    ----------
    line_load : float
        Net load P per unit length [N/m] (compressive positive; above the pull-off load).
    radius, contact_modulus, work_of_adhesion, cohesive_stress : float
        As in :func:`maugis_dugdale_line_load` (R [m], E* [Pa], w [J/m²], sigma0 [Pa]).

    Returns
    -------
    tension : float
        The whole tensile traction per unit length [N/m]: the Dugdale zones a < |x| < c and the
        tensile edges of the contact, where the pressure below is negative.
    half_width : float
        Contact half-width a [m].
    zone_end : float
        End c of the cohesive zone [m] (each zone is c - a wide).

    Notes
    -----
    The pressure on the contact of :func:`maugis_dugdale_line_load` (the Hertz pressure of
    half-width a plus the bounded response of a rigid flat to the Dugdale tension on the zones):

    .. math:: p(x) = \frac{E^*}{2R}\sqrt{a^2-x^2}
              - \frac{2\sigma_0}{\pi}\arctan\frac{\sqrt{c^2-a^2}}{\sqrt{a^2-x^2}}, \quad |x| < a,

    and -sigma0 on the zones; its integral is the load of :func:`maugis_dugdale_line_load` (checked in
    tests/test_convergence.py). It is tensile near the contact's edges, down to -sigma0 at |x| = a. The
    tension is :math:`2\sigma_0(c-a) + 2\int_{x_0}^{a} -p\,dx` with :math:`p(x_0) = 0`: the attraction that
    adds to the load the contact carries (the meshing cycle's adhesion force, MODEL 7c). The adhesive
    term of the load equation, :math:`2\sigma_0\sqrt{c^2-a^2}` (Hertz load at a minus P), is larger: it
    counts the adhesive pressure where the compressive Hertz pressure outweighs it.
    """
    from scipy.integrate import quad
    from scipy.optimize import brentq

    radius = float(as_array(radius, "radius", "m", positive=True))
    modulus = float(as_array(contact_modulus, "contact_modulus", "Pa", positive=True))
    w = float(as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", positive=True))
    sigma0 = float(as_array(cohesive_stress, "cohesive_stress", "Pa", positive=True))
    load = float(line_load)
    pull_off, a_pull = maugis_dugdale_line_pull_off(radius, modulus, w, sigma0)
    if not load > pull_off:
        raise InputError(f"line_load {load:.4g} N/m is at or below the pull-off load {pull_off:.4g} N/m: no "
                         "adhered state under load control.")
    upper = max(2.0 * a_pull, 1e-9)
    while _maugis_line_scalar(upper, radius, modulus, w, sigma0)[0] < load:
        upper *= 2.0
    a = brentq(lambda x: _maugis_line_scalar(x, radius, modulus, w, sigma0)[0] - load, a_pull, upper,
               xtol=1e-16, rtol=1e-14)
    c = _maugis_line_scalar(a, radius, modulus, w, sigma0)[1]
    t = math.sqrt(max(c * c - a * a, 0.0))

    def pressure(x):
        s = math.sqrt(max(a * a - x * x, 0.0))
        return modulus / (2.0 * radius) * s - 2.0 * sigma0 / math.pi * math.atan2(t, s)

    x0 = brentq(pressure, 0.0, a) if pressure(0.0) > 0.0 else 0.0
    inside = quad(lambda x: -pressure(x), x0, a, limit=400)[0]
    return 2.0 * sigma0 * (c - a) + 2.0 * inside, float(a), float(c)


@cites("maugis_1992", "johnson_greenwood_2008", "baney_hui_1997")
def dugdale_rigid_line_pull_off(radius, work_of_adhesion, cohesive_stress):
    r"""Pull-off line load of a rigid cylinder on a rigid flat with a Dugdale law (small Maugis parameter) [N/m].

    Parameters
    ----------
    radius : numeric
        Effective radius R [m].
    work_of_adhesion : numeric
        Work of adhesion w [J/m²].
    cohesive_stress : numeric
        Dugdale stress sigma0 [Pa] (range h0 = w / sigma0).

    Returns
    -------
    numeric
        Magnitude of the pull-off load per unit length [N/m] (positive).

    Notes
    -----
    Derjaguin's approximation at touching contact: the stress sigma0 acts where
    x²/(2R) <= h0, so

    .. math:: F = 2\sigma_0\sqrt{2 R h_0} = 2\sqrt{2 R \sigma_0 w}

    Unlike the sphere (DMT, 2 pi w R, independent of the law), the 2D limit depends on the
    range of the law, not on w alone (Johnson & Greenwood 2008; Baney & Hui 1997): there is
    no law-independent "DMT line contact" (2 w R per unit length is not a line load).
    """
    radius = as_array(radius, "radius", "m", positive=True)
    w = as_array(work_of_adhesion, "work_of_adhesion", "J/m^2", nonnegative=True)
    sigma0 = as_array(cohesive_stress, "cohesive_stress", "Pa", positive=True)
    return 2.0 * np.sqrt(2.0 * radius * sigma0 * w)


# ------------------------------------------------------ bi-sinusoidal surface, full contact


@cites("johnson_1985")
def wavy_surface_full_contact_amplitude(amplitude, wavelength, contact_modulus):
    r"""Pressure amplitude of a bi-sinusoidal surface in full contact.

    Parameters
    ----------
    amplitude : numeric
        Amplitude Δ [m] of :math:`h(x, y) = -\Delta\cos(2\pi x/\lambda)\cos(2\pi y/\lambda)`.
    wavelength : numeric
        Wavelength λ [m] along x and y.
    contact_modulus : numeric
        Contact modulus E* [Pa].

    Returns
    -------
    numeric
        p* = sqrt(2) π E* Δ / λ [Pa]: in full contact p = p̄ + p* cos(2πx/λ) cos(2πy/λ).

    Notes
    -----
    The half-space response to a surface mode of wavenumber :math:`|q| = \sqrt2\,2\pi/\lambda`
    is :math:`p_q = E^*|q| u_q / 2` (Johnson & Greenwood's bi-sinusoidal surface, Johnson,
    Greenwood, Higginson, Int. J. Mech. Sci. 27 (1985) 383; the 1D Westergaard case has
    p* = π E* Δ/λ, Eq. (13.6) in [1]_).
    """
    contact_modulus = as_array(contact_modulus, "contact_modulus", "Pa", positive=True)
    amplitude = as_array(amplitude, "amplitude", "m", positive=True)
    return np.sqrt(2.0) * np.pi * contact_modulus * amplitude / as_array(wavelength, "wavelength", "m",
                                                                          positive=True)
