"""Involute spur gear pair: geometry, kinematics, load sharing and the Hertz line contact.

Thesis sections 4.3 to 4.5 and 4.7 (MODEL.md §6). Conventions (written down once):

* index 1 is the pinion (the driver), index 2 the gear (driven);
* ``c`` is the position of the contact point on the line of action [m], zero at the pitch
  point and positive in the direction of motion of the contact point; the contact runs from
  the first point ``c_f < 0`` (gear tip on the pinion root flank) to the last ``c_l > 0``
  (pinion tip on the gear);
* radii of curvature of the flanks at the contact are the distances from the contact point to
  the tangency points on the base circles: ``R1 = rb1 tan(phi) + c``, ``R2 = rb2 tan(phi) - c``
  (4-20, 4-21); both are positive on a meshing path;
* surface velocities ``u_i = R_i omega_i`` are the speeds at which the flank points move
  along the common tangent relative to the contact point (4-12 with signed radii); the
  sliding velocity ``u1 - u2 = c (omega1 + omega2)`` vanishes at the pitch point.

The pair is a :class:`GearPair` (frozen dataclass); every published relation is also a
plain vectorised function of SI arrays.

Examples
--------
>>> from memstribo.parameters import get_parameter_values
>>> pair = GearPair.from_parameters(get_parameter_values())
>>> round(pair.contact_ratio, 3)
1.681
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from memstribo.materials.pair import contact_modulus_of
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "GearPair",
    "gear_summary",
    "HertzLineContact",
    "module_from_outer_diameters",
    "first_contact_point",
    "last_contact_point",
    "contact_ratio",
    "radii_of_curvature",
    "effective_radius",
    "surface_velocities",
    "load_share_dry",
    "load_share_lubricated",
    "hertz_line_contact",
    "tangential_force",
    "minimum_teeth_without_undercut",
    "involute_function",
    "tip_tooth_thickness",
    "design_warnings",
    "TIP_THICKNESS_MIN",
    "CONTACT_RATIO_MIN",
]

#: Tip tooth thickness below which a design is warned about, in modules (s_a < 0.25 m risks tip breakage;
#: ISO 21771:2007 defines s_a, the quarter module is common design practice, e.g. Litvin & Fuentes 2004).
TIP_THICKNESS_MIN = 0.25
#: Transverse contact ratio below which a design is warned about (1.2: margin for tolerances and deflection).
CONTACT_RATIO_MIN = 1.2


# --------------------------------------------------------------------------------------------
# published relations, one function each
# --------------------------------------------------------------------------------------------
def module_from_outer_diameters(outer_diameter_pinion, outer_diameter_gear, teeth_pinion, teeth_gear,
                                addendum_coefficient=1.0):
    """Module of a standard pair from its outer (tip) diameters.

    Parameters
    ----------
    outer_diameter_pinion, outer_diameter_gear : float
        Tip diameters d_a1, d_a2 [m].
    teeth_pinion, teeth_gear : int
        Tooth counts z1, z2 [-].
    addendum_coefficient : float
        Addendum in modules h_a [-] (standard: 1).

    Returns
    -------
    float
        m = (d_a1 + d_a2) / (z1 + z2 + 4 h_a) [m] (MODEL §6: 81 µm and 303 µm give 3.879 µm).
    """
    if outer_diameter_pinion <= 0 or outer_diameter_gear <= 0:
        raise InputError("outer diameters must be positive.")
    module = (outer_diameter_pinion + outer_diameter_gear) / (teeth_pinion + teeth_gear + 4 * addendum_coefficient)
    # each tip diameter must be its own wheel's, d_a = m (z + 2 h_a), within half a module (issue #41: the
    # diameters given in the wrong order gave the same module, silently)
    expected = (module * (teeth_pinion + 2 * addendum_coefficient), module * (teeth_gear + 2 * addendum_coefficient))
    given = (outer_diameter_pinion, outer_diameter_gear)
    if any(abs(d - e) > 0.5 * module for d, e in zip(given, expected)):
        swapped = all(abs(d - e) <= 0.5 * module for d, e in zip(given[::-1], expected))
        raise InputError(
            f"outer diameters {given[0] * 1e6:.4g} µm (pinion, {teeth_pinion} teeth) and {given[1] * 1e6:.4g} µm "
            f"(gear, {teeth_gear} teeth) do not fit a standard pair: with m = {module * 1e6:.4g} µm the tip diameters "
            f"m (z + 2 h_a) are {expected[0] * 1e6:.4g} µm and {expected[1] * 1e6:.4g} µm (allowed: each within half "
            "a module of its own)"
            + ("; they are given in the wrong order: the pinion's first" if swapped else
               "; change teeth_pinion, teeth_gear or addendum_coefficient to match them") + ".")
    return module


def minimum_teeth_without_undercut(pressure_angle, addendum_coefficient=1.0):
    """Smallest tooth count cut by a standard rack without undercut.

    Parameters
    ----------
    pressure_angle : float
        Pressure angle phi [rad].
    addendum_coefficient : float
        Addendum (dedendum of the cutting rack's tip line) in modules [-].

    Returns
    -------
    float
        z_min = 2 h_a / sin^2(phi) [-] (17.1 for 20°).
    """
    return 2.0 * addendum_coefficient / math.sin(pressure_angle) ** 2


def involute_function(angle):
    """The involute function inv(alpha) = tan(alpha) - alpha [rad] (ISO 21771:2007; Litvin & Fuentes 2004, 10.3)."""
    a = np.asarray(angle, dtype=float)
    return np.tan(a) - a


def tip_tooth_thickness(teeth, module, pressure_angle, addendum_coefficient=1.0, profile_shift=0.0):
    """Transverse tooth thickness on the tip circle of an involute spur gear.

    ISO 21771:2007 (tooth thickness on a circle of diameter d_y, here the tip circle d_a); see also
    F. L. Litvin and A. Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., Cambridge University
    Press, 2004, chapter 10 (tooth thickness on an arbitrary circle from the involute function).

    Parameters
    ----------
    teeth : int
        z [-].
    module : float
        m [m].
    pressure_angle : float
        alpha [rad] (on the pitch circle).
    addendum_coefficient : float
        h_a in modules [-]; the tip diameter is d_a = m z + 2 h_a m.
    profile_shift : float
        Profile shift coefficient x [-] (memstribo's pairs have x = 0).

    Returns
    -------
    float
        s_a = d_a (s/d + inv(alpha) - inv(alpha_a)) [m] with s = m (pi/2 + 2 x tan(alpha)) the pitch-circle
        tooth thickness (pi m / 2 for x = 0), d = m z, cos(alpha_a) = d_b / d_a, d_b = d cos(alpha).
        Zero or negative: a pointed tooth (its flanks meet below the tip circle). NaN when the tip circle
        is not above the base circle (no involute there).
    """
    d = module * teeth
    d_a = d + 2.0 * (addendum_coefficient + profile_shift) * module
    d_b = d * math.cos(pressure_angle)
    if d_a <= d_b:
        return float("nan")
    s = module * (math.pi / 2.0 + 2.0 * profile_shift * math.tan(pressure_angle))
    alpha_a = math.acos(d_b / d_a)
    return float(d_a * (s / d + involute_function(pressure_angle) - involute_function(alpha_a)))


def design_warnings(pair: "GearPair") -> list[str]:
    """Design checks that a meshing pair passes but that signal a marginal design (ISO 21771:2007 terms).

    * tip tooth thickness s_a below :data:`TIP_THICKNESS_MIN` m (0.25 m): the tip may break or wear off;
    * transverse contact ratio below :data:`CONTACT_RATIO_MIN` (1.2): little overlap of tooth pairs,
      so tolerances or tooth deflection may interrupt the mesh.

    The centre distance is not checked: memstribo's pairs always sit at the standard (reference) centre
    distance a = m (z1 + z2) / 2 (no parameter sets another), so it cannot differ from it.
    References: ISO 21771:2007; F. L. Litvin and A. Fuentes, *Gear Geometry and Applied Theory*, 2004.

    Returns
    -------
    list of str
        One sentence per finding (empty for a sound design, e.g. the thesis pair).
    """
    found = []
    for name, thickness in zip(("pinion", "gear"), pair.tip_thickness):
        if thickness < TIP_THICKNESS_MIN * pair.module:
            found.append(f"the {name}'s tooth thickness at the tip is {thickness / pair.module:.3f} x module "
                         f"({thickness * 1e9:.4g} nm), below {TIP_THICKNESS_MIN:g} x module: the tip may break "
                         "(ISO 21771 s_a; lower the addendum or the pressure angle)")
    if pair.contact_ratio < CONTACT_RATIO_MIN:
        found.append(f"contact ratio {pair.contact_ratio:.3f} is below {CONTACT_RATIO_MIN:g}: little overlap "
                     "between tooth pairs, so tolerances or tooth deflection may interrupt the mesh")
    return found


@cites("thesis")
def first_contact_point(base_radius_gear, tip_radius_gear, pressure_angle):
    """First point of contact on the line of action (the gear's tip meets the pinion).

    Parameters
    ----------
    base_radius_gear, tip_radius_gear : float
        Base radius r_b2 and tip radius r_t2 of the gear [m].
    pressure_angle : float
        phi [rad].

    Returns
    -------
    float
        c_f = r_b2 tan(phi) - sqrt(r_t2^2 - r_b2^2) [m], Eq. (4-15) in [1]; negative.
    """
    _check_tip_above_base(tip_radius_gear, base_radius_gear, "gear")
    return base_radius_gear * np.tan(pressure_angle) - np.sqrt(tip_radius_gear**2 - base_radius_gear**2)


@cites("thesis")
def last_contact_point(base_radius_pinion, tip_radius_pinion, pressure_angle):
    """Last point of contact on the line of action (the pinion's tip leaves the gear).

    Parameters
    ----------
    base_radius_pinion, tip_radius_pinion : float
        Base radius r_b1 and tip radius r_t1 of the pinion [m].
    pressure_angle : float
        phi [rad].

    Returns
    -------
    float
        c_l = sqrt(r_t1^2 - r_b1^2) - r_b1 tan(phi) [m], Eq. (4-16) in [1]; positive.
    """
    _check_tip_above_base(tip_radius_pinion, base_radius_pinion, "pinion")
    return np.sqrt(tip_radius_pinion**2 - base_radius_pinion**2) - base_radius_pinion * np.tan(pressure_angle)


def _check_tip_above_base(tip_radius, base_radius, name):
    if np.any(np.asarray(tip_radius) <= np.asarray(base_radius)):
        raise InputError(f"the {name}'s tip radius ({np.max(tip_radius) * 1e6:.4g} µm) is not above its base radius "
                         f"({np.max(base_radius) * 1e6:.4g} µm): the tooth has no involute flank to make contact.")


def contact_ratio(first_contact, last_contact, base_pitch):
    """Transverse contact ratio: mean number of tooth pairs in contact.

    Parameters
    ----------
    first_contact, last_contact : float
        c_f and c_l [m].
    base_pitch : float
        p_b = pi m cos(phi) [m].

    Returns
    -------
    float
        epsilon = (c_l - c_f) / p_b = Delta c / p_b [-], with Delta c from Eq. (4-17) in [1].
    """
    return (last_contact - first_contact) / base_pitch


@cites("thesis")
def radii_of_curvature(position, base_radius_pinion, base_radius_gear, pressure_angle):
    """Radii of curvature of the two involute flanks at the contact point.

    Parameters
    ----------
    position : array_like
        c on the line of action [m].
    base_radius_pinion, base_radius_gear : float
        r_b1, r_b2 [m].
    pressure_angle : float
        phi [rad].

    Returns
    -------
    (ndarray, ndarray)
        R1 = r_b1 tan(phi) + c and R2 = r_b2 tan(phi) - c [m], Eqs. (4-20), (4-21) in [1].
    """
    c = np.asarray(position, dtype=float)
    return base_radius_pinion * np.tan(pressure_angle) + c, base_radius_gear * np.tan(pressure_angle) - c


@cites("thesis")
def effective_radius(radius_1, radius_2):
    """Radius of relative curvature of two cylinders.

    Parameters
    ----------
    radius_1, radius_2 : array_like
        Radii of curvature R1, R2 [m] (positive: both convex).

    Returns
    -------
    ndarray
        R_ef with 1/R_ef = 1/R1 + 1/R2 [m], Eq. (4-11) in [1].
    """
    r1, r2 = np.asarray(radius_1, dtype=float), np.asarray(radius_2, dtype=float)
    if np.any(r1 <= 0) or np.any(r2 <= 0):
        raise InputError("radii of curvature must be positive (the contact point lies outside the path "
                         "between the two base-circle tangency points).")
    return r1 * r2 / (r1 + r2)


@cites("thesis")
def surface_velocities(position, base_radius_pinion, base_radius_gear, pressure_angle, pinion_speed,
                       gear_speed):
    """Speeds of the two flank surfaces along the common tangent, relative to the contact point.

    Parameters
    ----------
    position : array_like
        c [m].
    base_radius_pinion, base_radius_gear : float
        r_b1, r_b2 [m].
    pressure_angle : float
        phi [rad].
    pinion_speed, gear_speed : float
        Angular speeds omega1, omega2 [rad/s] (omega2 = omega1 z1/z2 for a meshing pair).

    Returns
    -------
    (ndarray, ndarray)
        u1 = R1 omega1 and u2 = R2 omega2 [m/s], Eq. (4-12) in [1] with the signed radii
        (4-20), (4-21): the thesis prints "+c" for both gears, which would make the sliding
        velocity constant; with R2 = r_b2 tan(phi) - c it is c (omega1 + omega2).
    """
    r1, r2 = radii_of_curvature(position, base_radius_pinion, base_radius_gear, pressure_angle)
    return r1 * pinion_speed, r2 * gear_speed


def _pairs_in_contact(position, first_contact, last_contact, base_pitch):
    c = np.asarray(position, dtype=float)
    # pairs k = ..., -1, 0, 1, ... sit at c + k p_b; count those on the path [c_f, c_l]
    k_low = np.ceil((first_contact - c) / base_pitch - 1e-12)
    k_high = np.floor((last_contact - c) / base_pitch + 1e-12)
    return np.maximum(k_high - k_low + 1, 0).astype(int)


@cites("thesis")
def load_share_dry(position, first_contact, last_contact, base_pitch):
    """Share of the load carried by one tooth pair, dry and rigid teeth (Figure 4-11a).

    Parameters
    ----------
    position : array_like
        c of the pair [m].
    first_contact, last_contact : float
        c_f, c_l [m].
    base_pitch : float
        p_b [m].

    Returns
    -------
    ndarray
        1/n(c) where n pairs are in contact (1 in the single-tooth zone, 1/2 in the
        double-tooth zones), 0 off the path [-].
    """
    c = np.asarray(position, dtype=float)
    pairs = _pairs_in_contact(c, first_contact, last_contact, base_pitch)
    on_path = (c >= first_contact - 1e-15) & (c <= last_contact + 1e-15)
    return np.where(on_path & (pairs > 0), 1.0 / np.maximum(pairs, 1), 0.0)


@cites("thesis")
def load_share_lubricated(position, first_contact, last_contact, base_pitch):
    """Share of the load of one tooth pair with tooth deflection and a lubricant (Figure 4-11b).

    One third at the first and last points of contact, rising linearly to two thirds at the
    ends of the single-tooth zone (A = c_l - p_b, B = c_f + p_b), the full load inside it.

    Parameters
    ----------
    position, first_contact, last_contact, base_pitch : as in :func:`load_share_dry` (c, c_f, c_l, p_b [m])

    Returns
    -------
    ndarray
        Load share [-], 0 off the path.

    Raises
    ------
    InputError
        If the contact ratio is not between 1 and 2 (the function is defined for that case).
    """
    ratio = (last_contact - first_contact) / base_pitch
    if not 1.0 <= ratio < 2.0:
        raise InputError(f"the lubricated load-sharing function (Figure 4-11b) needs a contact ratio between "
                         f"1 and 2; this pair has {ratio:.3f}.")
    c = np.asarray(position, dtype=float)
    a, b = last_contact - base_pitch, first_contact + base_pitch
    entry = 1.0 / 3.0 + (1.0 / 3.0) * (c - first_contact) / max(a - first_contact, 1e-300)
    leave = 1.0 / 3.0 + (1.0 / 3.0) * (last_contact - c) / max(last_contact - b, 1e-300)
    share = np.where(c < a, entry, np.where(c <= b, 1.0, leave))
    on_path = (c >= first_contact - 1e-15) & (c <= last_contact + 1e-15)
    return np.where(on_path, share, 0.0)


@dataclass(frozen=True)
class HertzLineContact:
    """Hertz line contact of two cylinders (thesis 4.4).

    Attributes
    ----------
    half_width : ndarray
        a [m], Eq. (4-24).
    peak_pressure : ndarray
        p0 [Pa], Eq. (4-26).
    contact_area : ndarray
        A = 2 a L [m^2], Eq. (4-23).
    load_per_width : ndarray
        w [N/m].
    """

    half_width: np.ndarray
    peak_pressure: np.ndarray
    contact_area: np.ndarray
    load_per_width: np.ndarray


@cites("thesis", "johnson_1985")
def hertz_line_contact(load, face_width, effective_radius, contact_modulus):
    """Hertz line contact: half-width, peak pressure and area.

    Parameters
    ----------
    load : array_like
        Normal load on the tooth pair [N] (positive).
    face_width : float
        L [m].
    effective_radius : array_like
        R_ef [m].
    contact_modulus : float
        E* [Pa].

    Returns
    -------
    HertzLineContact
        a = sqrt(4 w R_ef / (pi E*)), p0 = 2 w / (pi a), A = 2 a L with w = load / L,
        Eqs. (4-22) to (4-26) in [1]. (The thesis prints a = 58.9 nm for its case; with its
        stated inputs the formula gives 43.4 nm at the pitch point, which memstribo reports.)
    """
    load = np.asarray(load, dtype=float)
    if np.any(load <= 0) or face_width <= 0 or contact_modulus <= 0:
        raise InputError("Hertz line contact needs a positive load, face width and contact modulus.")
    w = load / face_width
    a = np.sqrt(4.0 * w * np.asarray(effective_radius, dtype=float) / (math.pi * contact_modulus))
    return HertzLineContact(a, 2.0 * w / (math.pi * a), 2.0 * a * face_width, w)


@cites("thesis")
def tangential_force(drive_torque, pitch_radius_pinion):
    """Tangential force transmitted by the pinion.

    Parameters
    ----------
    drive_torque : float
        Torque on the pinion T [N m].
    pitch_radius_pinion : float
        r1 [m].

    Returns
    -------
    float
        F_t = T / r1 [N], Eq. (4-27) in [1] (2.82e-3 N for the thesis's case).
    """
    if pitch_radius_pinion <= 0:
        raise InputError("the pitch radius must be positive.")
    return drive_torque / pitch_radius_pinion


# --------------------------------------------------------------------------------------------
# the pair
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class GearPair:
    """An involute spur gear pair with standard addendum (thesis 4.3).

    Attributes
    ----------
    teeth_pinion, teeth_gear : int
        z1, z2 [-].
    module : float
        m [m].
    pressure_angle : float
        phi [rad].
    face_width : float
        L [m].
    addendum_coefficient : float
        Addendum in modules [-].
    pinion_speed : float
        omega1 [rad/s]: the time axis and the surface and sliding speeds (so the friction power and temperatures).

    Raises
    ------
    InputError
        On construction, if the pair cannot mesh: undercut pinion or gear, interference
        (the path of contact reaches beyond a base-circle tangency point), a tip radius not
        above the base radius, pointed teeth (tooth thickness at the tip s_a <= 0, ISO 21771:2007),
        or a contact ratio below 1. A pair that meshes but is marginal (s_a < 0.25 m, contact ratio
        below 1.2) is accepted; :attr:`warnings` says why (:func:`design_warnings`).
    """

    teeth_pinion: int
    teeth_gear: int
    module: float
    pressure_angle: float
    face_width: float
    addendum_coefficient: float = 1.0
    pinion_speed: float = 1.0e3

    def __post_init__(self):
        if self.module <= 0 or self.face_width <= 0:
            raise InputError("module and face width must be positive.")
        if not 0.0 < self.pressure_angle < math.pi / 2:
            raise InputError(f"pressure angle {math.degrees(self.pressure_angle):g}° is outside (0°, 90°).")
        if self.teeth_pinion < 1 or self.teeth_gear < 1:
            raise InputError("tooth counts must be positive integers.")
        for name, tip, base in (("pinion", self.tip_radii[0], self.base_radii[0]),
                                ("gear", self.tip_radii[1], self.base_radii[1])):
            if tip <= base:
                raise InputError(f"the {name}'s tip radius ({tip * 1e6:.4g} µm) is not above its base radius "
                                 f"({base * 1e6:.4g} µm): no involute flank. Raise the addendum or lower the "
                                 f"pressure angle.")
        for name, thickness in zip(("pinion", "gear"), self.tip_thickness):
            if not thickness > 0.0:
                raise InputError(f"the {name}'s teeth are pointed: the tooth thickness at the tip (ISO 21771 s_a) "
                                 f"is {thickness / self.module:.3f} x module, not above 0 (the flanks meet below the "
                                 f"tip circle). "
                                 f"Lower the addendum ({self.addendum_coefficient:g} x module) or the pressure angle "
                                 f"({math.degrees(self.pressure_angle):.4g}°).")
        r1, r2 = self.base_radii * math.tan(self.pressure_angle)
        if -self.first_contact > r1 or self.last_contact > r2:
            raise InputError(f"interference: the path of contact ({self.first_contact * 1e6:.4g} µm to "
                             f"{self.last_contact * 1e6:.4g} µm about the pitch point) runs past the base-circle "
                             f"tangency points (-{r1 * 1e6:.4g} µm, {r2 * 1e6:.4g} µm).")
        z_min = minimum_teeth_without_undercut(self.pressure_angle, self.addendum_coefficient)
        for name, teeth in (("pinion", self.teeth_pinion), ("gear", self.teeth_gear)):
            if teeth < z_min:
                raise InputError(f"the {name} has {teeth} teeth, fewer than the {z_min:.1f} needed to avoid undercut "
                                 f"at a {math.degrees(self.pressure_angle):.4g}° pressure angle and addendum "
                                 f"{self.addendum_coefficient:g} module; use more teeth or a larger pressure angle.")
        if self.contact_ratio < 1.0:
            raise InputError(f"contact ratio {self.contact_ratio:.3f} is below 1: the teeth lose contact between "
                             f"pairs. Raise the addendum or the tooth counts.")

    # construction -----------------------------------------------------------------------------
    @classmethod
    def from_parameters(cls, params) -> "GearPair":
        """The pair described by a parameter set (teeth_pinion, teeth_gear, module, ...)."""
        return cls(int(params["teeth_pinion"]), int(params["teeth_gear"]), float(params["module"]),
                   float(params["pressure_angle"]), float(params["face_width"]),
                   float(params["addendum_coefficient"]), float(params["pinion_speed"]))

    @classmethod
    def from_outer_diameters(cls, outer_diameter_pinion, outer_diameter_gear, teeth_pinion, teeth_gear,
                             pressure_angle, face_width, addendum_coefficient=1.0, pinion_speed=1.0e3):
        """The standard pair with the given tip diameters [m] (MODEL §6: 81 µm / 303 µm)."""
        module = module_from_outer_diameters(outer_diameter_pinion, outer_diameter_gear, teeth_pinion,
                                             teeth_gear, addendum_coefficient)
        return cls(teeth_pinion, teeth_gear, module, pressure_angle, face_width, addendum_coefficient,
                   pinion_speed)

    # geometry ---------------------------------------------------------------------------------
    @property
    def pitch_radii(self) -> np.ndarray:
        """[r1, r2] = m z / 2 [m]."""
        return self.module * np.array([self.teeth_pinion, self.teeth_gear], dtype=float) / 2.0

    @property
    def base_radii(self) -> np.ndarray:
        """[r_b1, r_b2] = r cos(phi) [m]."""
        return self.pitch_radii * math.cos(self.pressure_angle)

    @property
    def tip_radii(self) -> np.ndarray:
        """[r_t1, r_t2] = r + h_a m [m]."""
        return self.pitch_radii + self.addendum_coefficient * self.module

    @property
    def tip_thickness(self) -> np.ndarray:
        """[s_a1, s_a2]: transverse tooth thickness on the tip circle [m] (ISO 21771:2007; Litvin & Fuentes
        2004), :func:`tip_tooth_thickness` with zero profile shift."""
        return np.array([tip_tooth_thickness(z, self.module, self.pressure_angle, self.addendum_coefficient)
                         for z in (self.teeth_pinion, self.teeth_gear)])

    @property
    def centre_distance(self) -> float:
        """a = m (z1 + z2) / 2 [m]: the standard (reference) centre distance, at which memstribo's pairs run."""
        return self.module * (self.teeth_pinion + self.teeth_gear) / 2.0

    @property
    def warnings(self) -> list[str]:
        """Marginal-design findings of :func:`design_warnings` (empty for a sound design)."""
        return design_warnings(self)

    @property
    def base_pitch(self) -> float:
        """p_b = pi m cos(phi) [m]."""
        return math.pi * self.module * math.cos(self.pressure_angle)

    @property
    def gear_ratio(self) -> float:
        """z2 / z1 [-]."""
        return self.teeth_gear / self.teeth_pinion

    @property
    def gear_speed(self) -> float:
        """omega2 = omega1 z1 / z2 [rad/s]."""
        return self.pinion_speed / self.gear_ratio

    @property
    def first_contact(self) -> float:
        """c_f [m], Eq. (4-15)."""
        return float(first_contact_point(self.base_radii[1], self.tip_radii[1], self.pressure_angle))

    @property
    def last_contact(self) -> float:
        """c_l [m], Eq. (4-16)."""
        return float(last_contact_point(self.base_radii[0], self.tip_radii[0], self.pressure_angle))

    @property
    def path_of_contact(self) -> float:
        """Delta c = c_l - c_f [m], Eq. (4-17)."""
        return self.last_contact - self.first_contact

    @property
    def contact_ratio(self) -> float:
        """epsilon = Delta c / p_b [-]."""
        return float(contact_ratio(self.first_contact, self.last_contact, self.base_pitch))

    @property
    def single_tooth_zone(self) -> tuple[float, float] | None:
        """(A, B) = (c_l - p_b, c_f + p_b) [m]: the single-tooth contact zone; None if the contact
        ratio is 2 or more (always at least two pairs in contact)."""
        a, b = self.last_contact - self.base_pitch, self.first_contact + self.base_pitch
        return (a, b) if a < b else None

    @property
    def contact_point_speed(self) -> float:
        """Speed of the contact point along the line of action v = r_b1 omega1 [m/s]."""
        return float(self.base_radii[0] * self.pinion_speed)

    @property
    def mesh_duration(self) -> float:
        """t = Delta c / v [s], Eq. (4-18)."""
        return self.path_of_contact / self.contact_point_speed

    # functions of the position c ------------------------------------------------------------------
    def positions(self, steps: int) -> np.ndarray:
        """``steps`` evenly spaced positions from c_f to c_l [m] (time step t/steps, Eq. (4-19))."""
        if steps < 2:
            raise InputError(f"a meshing cycle needs at least 2 steps, got {steps}.")
        return np.linspace(self.first_contact, self.last_contact, int(steps))

    def radii_of_curvature(self, position):
        """(R1, R2) at c [m], Eqs. (4-20), (4-21)."""
        return radii_of_curvature(position, self.base_radii[0], self.base_radii[1], self.pressure_angle)

    def effective_radius(self, position):
        """R_ef at c [m], Eq. (4-11)."""
        return effective_radius(*self.radii_of_curvature(position))

    def surface_velocities(self, position):
        """(u1, u2) at c [m/s], Eq. (4-12)."""
        return surface_velocities(position, self.base_radii[0], self.base_radii[1], self.pressure_angle,
                                  self.pinion_speed, self.gear_speed)

    def sliding_velocity(self, position):
        """u1 - u2 = c (omega1 + omega2) [m/s]; zero at the pitch point."""
        u1, u2 = self.surface_velocities(position)
        return u1 - u2

    def time(self, position):
        """Time since the first contact t(c) = (c - c_f) / v [s]."""
        return (np.asarray(position, dtype=float) - self.first_contact) / self.contact_point_speed

    def load_share(self, position, kind: str = "dry"):
        """Load share of the pair at c [-]: ``kind`` = "dry" (Figure 4-11a) or "lubricated" (4-11b)."""
        if kind == "dry":
            return load_share_dry(position, self.first_contact, self.last_contact, self.base_pitch)
        if kind == "lubricated":
            return load_share_lubricated(position, self.first_contact, self.last_contact, self.base_pitch)
        raise InputError(f"load sharing '{kind}' is unknown: use 'dry' or 'lubricated'.")

    def hertz(self, position, load, contact_modulus):
        """Hertz line contact at c under the pair's load [N] (not shared): Eqs. (4-22)-(4-26)."""
        return hertz_line_contact(load, self.face_width, self.effective_radius(position), contact_modulus)


def gear_summary(params) -> tuple[dict, dict]:
    """Geometry, kinematics and the pitch-point Hertz contact of the pair (what ``memstribo gear`` prints).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Parameter set (gear geometry, material, normal_load, drive_torque).

    Returns
    -------
    values : dict
        SI values: radii as [pinion, gear] pairs [m], pressure angle [rad], contact ratio [-],
        Hertz half-width [m] and peak pressure [Pa] at the pitch point under ``normal_load``,
        tangential force F_t = T / r_1 [N] (4-27), tooth thickness at the tip s_a as [pinion, gear] [m] and the
        standard centre distance [m] (ISO 21771:2007), ``design_warnings`` (:func:`design_warnings`, a list).
    units : dict
        SI unit of each key.
    """
    pair = GearPair.from_parameters(params)
    modulus = contact_modulus_of(params)
    zone = pair.single_tooth_zone
    hertz = pair.hertz(0.0, params["normal_load"], modulus)
    values = {
        "module": pair.module,
        "pressure_angle": pair.pressure_angle,
        "pitch_radii": pair.pitch_radii.tolist(),
        "base_radii": pair.base_radii.tolist(),
        "tip_radii": pair.tip_radii.tolist(),
        "tip_thickness": pair.tip_thickness.tolist(),
        "centre_distance": pair.centre_distance,
        "base_pitch": pair.base_pitch,
        "first_contact": pair.first_contact,
        "last_contact": pair.last_contact,
        "path_of_contact": pair.path_of_contact,
        "contact_ratio": pair.contact_ratio,
        "single_tooth_zone": None if zone is None else list(zone),
        "effective_radius_pitch": float(pair.effective_radius(0.0)),
        "contact_modulus": modulus,
        "hertz_half_width": float(hertz.half_width),
        "hertz_peak_pressure": float(hertz.peak_pressure),
        "tangential_force": tangential_force(params["drive_torque"], pair.pitch_radii[0]),
        "design_warnings": pair.warnings,
    }
    units = {"module": "m", "pressure_angle": "rad", "pitch_radii": "m", "base_radii": "m", "tip_radii": "m",
             "tip_thickness": "m", "centre_distance": "m", "base_pitch": "m", "first_contact": "m", "last_contact": "m", "path_of_contact": "m",
             "contact_ratio": "", "single_tooth_zone": "m", "effective_radius_pitch": "m", "contact_modulus": "Pa",
             "hertz_half_width": "m", "hertz_peak_pressure": "Pa", "tangential_force": "N",
             "design_warnings": ""}
    return values, units


def pitch_point_line_contact(params) -> tuple[float, float, float]:
    """Contact modulus E* [Pa], effective radius R_ef at the pitch point [m] (4-11) and the line load
    ``normal_load / face_width`` [N/m] of the parameter set: the default line contact of ``memstribo contact``."""

    modulus = contact_modulus_of(params)
    pair = GearPair.from_parameters(params)
    return float(modulus), float(pair.effective_radius(0.0)), params["normal_load"] / params["face_width"]
