"""Tooth root stress of an involute spur gear over the meshing cycle (MODEL §10, issue #30).

The tooth is drawn as a MEMS mask draws it: involute flanks (above the base circle, radial
lines below it), a root circle ``r_f = r - h_f m`` and a circular root fillet of radius
``rho_f`` tangent to the flank and to the root circle (:class:`ToothShape`). The root stress
is the method B of ISO 6336-3 adapted to a load anywhere on the flank and to the friction
force: the critical section is where the fillet's tangent makes 30 deg with the tooth
centreline (ISO 6336-3, 6.2: ``s_Fn``, ``rho_F``); the nominal bending stress of that section
is ``6 M / (b s_Fn^2)`` with ``M`` the moment of the whole contact force (normal force along
the line of action plus friction along the flank) about the section's centre; the stress
correction factor ``Y_S = (1.2 + 0.13 L) q_s^(1 / (1.21 + 2.3 / L))`` with ``L = s_Fn / h_Fe``
and ``q_s = s_Fn / (2 rho_F)`` (ISO 6336-3, Eq. (37)) turns it into the local fillet stress:

    sigma_F =  Y_S 6 M / (b s_Fn^2) + N / (b s_Fn)                   (tension side)
    sigma_C = -Y_S 6 M / (b s_Fn^2) + N / (b s_Fn)                   (compression side)

with ``h_Fe = M / F_x`` the lever arm of the force component across the centreline and ``N`` its
component along the centreline (negative: pushing the tooth onto its root). For a load on the
line of action alone ``M = F_n cos(alpha_Fen) h_Fe`` and the bending term is ISO's
``F_t / (b m) Y_F Y_S`` (Eqs. (5), (30)); ISO leaves out the direct stress ``N / (b s_Fn)``,
memstribo keeps it because friction along the flank changes it (toward the root it presses the
tooth onto its root, toward the tip it pulls). ``h_Fe`` is ISO's lever arm of the normal force;
below ISO's load point (the outer point of single tooth contact) Y_S keeps its value there
(:func:`cycle_root_stress`). The friction force on both teeth points toward the root before the
pitch point and toward the tip after it (on the driver away from the pitch line, on the driven
gear toward it; Buckingham 1949).

Checked against an independent plane-stress finite-element solve of one tooth with its rim
(scikit-fem, tests/test_tooth_stress.py): the cycle's largest root stress is 6-10 % below the
FE's for COF 0 to 0.6, beyond 10 % for COF near 1; per contact within 10 % on the upper flank,
while a load within about 0.3 m of the fillet gets up to half the FE's stress, a stress below
half the cycle's largest (docs/strength.md gives the numbers).

References
----------
.. [1] ISO 6336-3:2019, Calculation of load capacity of spur and helical gears - Part 3:
   Calculation of tooth bending strength.
.. [2] ISO 53:1998, Cylindrical gears for general and heavy engineering - Standard basic rack
   tooth profile (dedendum 1.25 m, root fillet 0.38 m).
.. [3] E. Buckingham, Analytical Mechanics of Gears, McGraw-Hill, 1949 (Dover 1988).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = ["ToothShape", "tooth_shape", "critical_section", "stress_correction_factor", "root_stress",
           "flank_load_point", "cycle_root_stress"]

#: ISO 6336-3 critical-section tangent angle of external gears [rad] (6.2: 30 deg)
CRITICAL_TANGENT_ANGLE = math.radians(30.0)


def _inv(angle):
    return np.tan(angle) - angle


@dataclass(frozen=True)
class ToothShape:
    """One tooth of an involute spur gear, in a frame with the gear centre at the origin and the tooth
    centreline along +y (right flank at x > 0). Lengths in m, angles in rad.

    Attributes
    ----------
    teeth, module, pressure_angle, addendum_coefficient, dedendum_coefficient : numbers
        z [-], m [m], alpha [rad], h_a / m [-], h_f / m [-].
    fillet_radius : float
        rho_f [m].
    fillet_centre : tuple of float
        Centre (x, y) of the right root fillet [m].
    fillet_angles : tuple of float
        Polar angles (about the fillet centre) of the fillet's ends on the root circle and on the flank [rad].
    flank_tangent_radius : float
        Radius (about the gear centre) where the fillet meets the flank [m].
    """

    teeth: int
    module: float
    pressure_angle: float
    addendum_coefficient: float
    dedendum_coefficient: float
    fillet_radius: float
    fillet_centre: tuple
    fillet_angles: tuple
    flank_tangent_radius: float

    @property
    def pitch_radius(self) -> float:
        """r = m z / 2 [m]."""
        return self.module * self.teeth / 2.0

    @property
    def base_radius(self) -> float:
        """r_b = r cos(alpha) [m]."""
        return self.pitch_radius * math.cos(self.pressure_angle)

    @property
    def tip_radius(self) -> float:
        """r_a = r + h_a m [m]."""
        return self.pitch_radius + self.addendum_coefficient * self.module

    @property
    def root_radius(self) -> float:
        """r_f = r - h_f m [m]."""
        return self.pitch_radius - self.dedendum_coefficient * self.module

    def half_angle(self, radius):
        """Polar half-angle of the tooth at ``radius`` on the flank [rad] (involute above r_b, radial below)."""
        r = np.asarray(radius, dtype=float)
        alpha_r = np.arccos(np.minimum(self.base_radius / r, 1.0))
        return math.pi / (2 * self.teeth) + _inv(self.pressure_angle) - _inv(alpha_r)

    def flank_point(self, radius):
        """(x, y) of the right flank at ``radius`` [m]."""
        r = np.asarray(radius, dtype=float)
        psi = self.half_angle(r)
        return np.stack([r * np.sin(psi), r * np.cos(psi)], axis=-1)

    def flank_tangent(self, radius):
        """Unit tangent of the right flank at ``radius``, pointing toward the tip [-]."""
        r = np.asarray(radius, dtype=float)
        h = 1e-7 * self.module
        d = self.flank_point(r + h) - self.flank_point(r - h)
        return d / np.linalg.norm(d, axis=-1, keepdims=True)

    def fillet_point(self, angle):
        """(x, y) on the right root fillet at polar angle ``angle`` about its centre [m]."""
        a = np.asarray(angle, dtype=float)
        cx, cy = self.fillet_centre
        return np.stack([cx + self.fillet_radius * np.cos(a), cy + self.fillet_radius * np.sin(a)], axis=-1)

    def outline(self, points_fillet=40, points_flank=40, points_tip=10, points_root=8):
        """The right half of the tooth outline from the middle of the space (root circle) to the tip's
        centre, as an (n, 2) array [m]: root land, fillet, flank, tip land."""
        a_root, a_flank = self.fillet_angles
        beta = math.atan2(*self.fillet_point(a_root))  # polar angle of the fillet's end on the root circle
        space = math.pi / self.teeth
        root = self.root_radius * np.stack([np.sin(np.linspace(space, beta, points_root, endpoint=False)),
                                            np.cos(np.linspace(space, beta, points_root, endpoint=False))], axis=-1)
        fillet = self.fillet_point(np.linspace(a_root, a_flank, points_fillet, endpoint=False))
        flank = self.flank_point(np.linspace(self.flank_tangent_radius, self.tip_radius, points_flank,
                                             endpoint=False))
        psi_a = float(self.half_angle(self.tip_radius))
        tip = self.tip_radius * np.stack([np.sin(np.linspace(psi_a, 0.0, points_tip)),
                                          np.cos(np.linspace(psi_a, 0.0, points_tip))], axis=-1)
        return np.concatenate([root, fillet, flank, tip])


@cites("iso_53", "iso_6336_3")
def tooth_shape(teeth, module, pressure_angle, addendum_coefficient=1.0, dedendum_coefficient=1.25,
                fillet_coefficient=0.38) -> ToothShape:
    """The tooth of a standard involute spur gear with a circular root fillet.

    Parameters
    ----------
    teeth : int
        z [-].
    module : float
        m [m].
    pressure_angle : float
        alpha [rad].
    addendum_coefficient, dedendum_coefficient : float
        h_a / m and h_f / m [-] (ISO 53 basic rack: 1 and 1.25).
    fillet_coefficient : float
        Root fillet radius rho_f / m [-] (ISO 53 profile A: 0.38).

    Returns
    -------
    ToothShape

    Raises
    ------
    InputError
        Non-positive sizes, a root circle at or below the gear centre, or a fillet that does not fit
        in the tooth space (tangent to both the root circle and the flank).
    """
    from scipy.optimize import brentq

    z = int(teeth)
    m = float(as_array(module, "module", "m", positive=True))
    alpha = float(pressure_angle)
    if z < 5 or not 0.0 < alpha < math.pi / 2:
        raise InputError(f"a tooth needs at least 5 teeth and a pressure angle in (0, 90) deg, got z = {teeth}, "
                         f"alpha = {math.degrees(alpha):g} deg.")
    for name, value in (("addendum_coefficient", addendum_coefficient), ("dedendum_coefficient",
                        dedendum_coefficient), ("fillet_coefficient", fillet_coefficient)):
        as_array(value, name, "", positive=True)
    rho = float(fillet_coefficient) * m
    r_f = m * z / 2 - float(dedendum_coefficient) * m
    if r_f <= 0:
        raise InputError(f"the root circle (dedendum {dedendum_coefficient:g} m) reaches the gear centre for z = {z}.")
    probe = ToothShape(z, m, alpha, float(addendum_coefficient), float(dedendum_coefficient), rho, (0.0, 0.0),
                       (0.0, 0.0), 0.0)
    r_a = probe.tip_radius
    radii = np.linspace(r_f, r_a, 4001)
    flank = probe.flank_point(radii)

    def centre(beta):
        return (r_f + rho) * np.array([math.sin(beta), math.cos(beta)])

    def clearance(beta):  # distance from the fillet centre to the flank, minus the radius
        return float(np.min(np.linalg.norm(flank - centre(beta), axis=1))) - rho

    space = math.pi / z
    beta_lo = float(probe.half_angle(r_f))
    if clearance(space) <= 0:
        raise InputError(f"a root fillet of {fillet_coefficient:g} x module does not fit in the tooth space of a "
                         f"{z}-tooth gear (it cannot touch both the root circle and the flank): use a smaller "
                         "root_fillet_coefficient.")
    beta = brentq(clearance, beta_lo, space, xtol=1e-14 * space)
    c = centre(beta)
    # refine the tangent point on the flank by minimising the distance on a fine grid around it
    i = int(np.argmin(np.linalg.norm(flank - c, axis=1)))
    fine = np.linspace(radii[max(i - 1, 0)], radii[min(i + 1, radii.size - 1)], 2001)
    j = int(np.argmin(np.linalg.norm(probe.flank_point(fine) - c, axis=1)))
    r_t = float(fine[j])
    t_point = probe.flank_point(r_t)
    # polar angles about the fillet centre in [0, 2 pi): toward the gear centre (the end on the root circle,
    # about 270 deg) and toward the flank (about 180 deg)
    a_root = math.atan2(-c[1], -c[0]) % (2 * math.pi)
    a_flank = math.atan2(t_point[1] - c[1], t_point[0] - c[0]) % (2 * math.pi)
    return ToothShape(z, m, alpha, float(addendum_coefficient), float(dedendum_coefficient), rho,
                      (float(c[0]), float(c[1])), (a_root, a_flank), r_t)


@cites("iso_6336_3")
def critical_section(shape: ToothShape):
    """Critical section of the tooth root (ISO 6336-3 method B, 6.2): the point of the fillet where its
    tangent makes 30 deg with the centreline.

    Returns
    -------
    dict
        ``point`` (x, y) of the right fillet there [m], ``thickness`` s_Fn = 2 x [m], ``height`` y of
        the section [m] (measured from the gear centre), ``fillet_radius`` rho_F [m].
    """
    a_root, a_flank = shape.fillet_angles
    # tangent at 30 deg to the centreline: the fillet centre lies along (cos 30, sin 30) from the point
    angle = math.pi + CRITICAL_TANGENT_ANGLE
    lo, hi = sorted((a_root, a_flank))
    angle = min(max(angle, lo), hi)
    point = shape.fillet_point(angle)
    return {"point": point, "thickness": 2.0 * float(point[0]), "height": float(point[1]),
            "fillet_radius": shape.fillet_radius}


@cites("iso_6336_3")
def stress_correction_factor(thickness, lever_arm, fillet_radius):
    """Stress correction factor Y_S = (1.2 + 0.13 L) q_s^(1 / (1.21 + 2.3 / L)) [-], ISO 6336-3 Eq. (37).

    Parameters
    ----------
    thickness : array_like
        s_Fn, chord of the critical section [m].
    lever_arm : array_like
        h_Fe, bending lever arm [m] (> 0).
    fillet_radius : float
        rho_F [m].

    Returns
    -------
    numpy.ndarray or float
        Y_S [-], with L = s_Fn / h_Fe and q_s = s_Fn / (2 rho_F) (ISO's range of validity 1 <= q_s < 8).
    """
    s = as_array(thickness, "thickness", "m", positive=True)
    h = as_array(lever_arm, "lever_arm", "m", positive=True)
    rho = as_array(fillet_radius, "fillet_radius", "m", positive=True)
    ratio = s / h
    q_s = s / (2 * rho)
    result = (1.2 + 0.13 * ratio) * q_s ** (1.0 / (1.21 + 2.3 / ratio))
    return float(result) if np.ndim(result) == 0 else result


def flank_load_point(shape: ToothShape, radius):
    """Point on the right flank at ``radius`` [m], its outward unit normal and its unit tangent toward the tip."""
    point = shape.flank_point(radius)
    tangent = shape.flank_tangent(radius)
    normal = np.stack([tangent[..., 1], -tangent[..., 0]], axis=-1)  # tangent rotated -90 deg: out of the tooth
    return point, normal, tangent


def design_lever_arm(shape: ToothShape, radius) -> float:
    """ISO's bending lever arm h_Fe [m] of the normal force at ``radius``: from the critical section to where the
    force's line of action crosses the tooth centreline (ISO 6336-3, 6.3)."""
    section = critical_section(shape)
    point, normal, _ = flank_load_point(shape, float(radius))
    return float(abs(point[1] - section["height"] - point[0] * normal[1] / normal[0]))


@cites("iso_6336_3", "buckingham_1949")
def root_stress(shape: ToothShape, radius, normal_force, friction_force, face_width, friction_sign=None,
                design_radius=None):
    """Tooth root stresses for a contact force on the right flank at ``radius`` (ISO 6336-3 method B, adapted).

    Parameters
    ----------
    shape : ToothShape
        The tooth.
    radius : array_like
        Radius of the contact point about the gear centre [m], between the fillet and the tip.
    normal_force : array_like
        Normal force F_n on the flank [N] (>= 0), along the line of action, pushing into the tooth.
    friction_force : array_like
        Friction force F_f on the flank [N] (>= 0), along the flank.
    face_width : float
        b [m].
    friction_sign : array_like, optional
        +1: friction toward the tip, -1: toward the root (default -1 below the pitch circle, +1 above;
        :func:`cycle_root_stress` gives it from the position on the line of action).
    design_radius : float, optional
        Radius [m] of ISO method B's load point, the outer point of single tooth contact
        (:func:`cycle_root_stress` passes it): for contacts below it the stress correction factor Y_S
        keeps that point's value, since Eq. (37) was fitted to lever arms of loads on the upper flank;
        default: each contact's own lever arm.

    Returns
    -------
    dict of numpy.ndarray
        ``tensile`` sigma_F [Pa] (the loaded side's fillet), ``compressive`` sigma_C [Pa] (the other fillet,
        negative), ``bending`` Y_S 6 M / (b s_Fn^2) [Pa] (ISO's sigma_F0 for a load on the line of action),
        ``moment`` M [N m], ``axial_force`` N [N], ``lever_arm`` h_Fe [m],
        ``stress_correction`` Y_S [-], ``section_thickness`` s_Fn [m].
    """
    r = as_array(radius, "radius", "m", positive=True)
    if np.any(r < shape.flank_tangent_radius * (1 - 1e-9)) or np.any(r > shape.tip_radius * (1 + 1e-9)):
        raise InputError(f"the contact radius must lie on the flank, between {shape.flank_tangent_radius:.4g} m and "
                         f"the tip radius {shape.tip_radius:.4g} m.")
    fn = as_array(normal_force, "normal_force", "N", nonnegative=True)
    ff = as_array(friction_force, "friction_force", "N", nonnegative=True)
    b = float(as_array(face_width, "face_width", "m", positive=True))
    if friction_sign is None:
        friction_sign = np.where(r >= shape.pitch_radius, 1.0, -1.0)
    sign = np.asarray(friction_sign, dtype=float)
    point, normal, tangent = flank_load_point(shape, r)
    force = -fn[..., None] * normal + (sign * ff)[..., None] * tangent
    section = critical_section(shape)
    s, y_s = section["thickness"], section["height"]
    arm_x, arm_y = point[..., 0], point[..., 1] - y_s
    moment = arm_x * force[..., 1] - arm_y * force[..., 0]  # > 0 bends the tooth away from the loaded flank
    # ISO's lever arm h_Fe: where the line of action of the normal force crosses the centreline (the tooth's
    # geometry and the contact point, independent of the friction, whose moment adds to M)
    lever = np.abs(arm_y - arm_x * normal[..., 1] / normal[..., 0])
    if design_radius is not None:
        # below ISO's load point (the outer point of single contact) Eq. (37) leaves the lever arms it was fitted
        # on (L = s_Fn / h_Fe grows without bound as the load nears the root): hold Y_S at the load point's value
        lever = np.maximum(lever, design_lever_arm(shape, design_radius))
    y_s_factor = stress_correction_factor(s, lever, section["fillet_radius"])
    bending = y_s_factor * 6.0 * np.abs(moment) / (b * s * s)
    axial = force[..., 1]
    direct = axial / (b * s)
    return {"tensile": bending + direct, "compressive": -bending + direct, "bending": bending, "moment": moment,
            "axial_force": axial, "lever_arm": lever, "stress_correction": np.broadcast_to(y_s_factor, bending.shape),
            "section_thickness": s}


def cycle_root_stress(pair, positions, normal_force, friction_force, dedendum_coefficient=1.25,
                      fillet_coefficient=0.38, face_width=None):
    """Root stresses of the pinion's and the gear's tooth at each position c of the meshing cycle.

    Parameters
    ----------
    pair : memstribo.physics.gear.GearPair
        The gear pair.
    positions : array_like
        c on the line of action [m] (0 at the pitch point).
    normal_force, friction_force : array_like
        Normal and friction force of the pair in contact at each c [N] (the meshing cycle's
        ``normal_force`` and ``friction_force``).
    dedendum_coefficient, fillet_coefficient : float
        h_f / m and rho_f / m [-].
    face_width : float, optional
        b [m]; default the pair's face width.

    Returns
    -------
    dict
        ``pinion`` and ``gear``: the dicts of :func:`root_stress` over the positions, plus ``radius`` [m] of
        the contact point on each tooth and ``shape`` (:class:`ToothShape`).
    """
    c = as_array(positions, "positions", "m")
    b = pair.face_width if face_width is None else face_width
    rb = pair.base_radii
    tan_a = math.tan(pair.pressure_angle)
    sign = np.where(c >= 0.0, 1.0, -1.0)  # toward the root before the pitch point, toward the tip after it
    # outer points of single tooth contact (ISO 6336-3 method B's load point): c_f + p_b on the pinion,
    # c_l - p_b on the gear; the tips when two pairs are always in mesh
    zone = pair.single_tooth_zone
    c_design = (zone[1], zone[0]) if zone is not None else (pair.last_contact, pair.first_contact)
    out = {}
    for i, (name, teeth, roll, roll_design) in enumerate((
            ("pinion", pair.teeth_pinion, rb[0] * tan_a + c, rb[0] * tan_a + c_design[0]),
            ("gear", pair.teeth_gear, rb[1] * tan_a - c, rb[1] * tan_a - c_design[1]))):
        shape = tooth_shape(teeth, pair.module, pair.pressure_angle, pair.addendum_coefficient,
                            dedendum_coefficient, fillet_coefficient)
        radius = np.sqrt(rb[i] ** 2 + roll ** 2)
        radius = np.clip(radius, shape.flank_tangent_radius, shape.tip_radius)
        design = float(np.clip(math.hypot(rb[i], roll_design), shape.flank_tangent_radius, shape.tip_radius))
        result = root_stress(shape, radius, normal_force, friction_force, b, friction_sign=sign, design_radius=design)
        out[name] = {**result, "radius": radius, "shape": shape}
    return out
