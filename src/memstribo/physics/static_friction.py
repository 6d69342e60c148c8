"""Static friction from mechanics (MODEL 7f, issue #35): the lateral peak of a bond, the static force of a bond
population at its registries, the Prandtl-Tomlinson threshold, the ageing of bonds at rest and the start-up torque
balance of an involute pair.

Version 3 started a gear by pulling every bond past the peak of its *radial* law (2.69 U/D for the 12-6 bond, reached
along the bond's axis) with every bond at that peak at once. A bond formed across the interface is sheared
*sideways* at its normal gap, and a population of bonds at different registries does not peak at once; the friction
of each pair acts on each gear with the flank's radius of curvature as moment arm. The functions below are those
relations, each one published or derived in its docstring. SI units throughout.
"""

from __future__ import annotations

import math

import numpy as np

from memstribo.checks import as_array
from memstribo.errors import InputError
from memstribo.references import cites

__all__ = [
    "LATERAL_PEAK_STRETCH",
    "LATERAL_PEAK_OFFSET",
    "LATERAL_PEAK_FORCE",
    "lennard_jones_lateral_force",
    "lennard_jones_lateral_peak",
    "bond_lateral_law",
    "bond_lateral_mean",
    "population_static_force",
    "prandtl_tomlinson_parameter",
    "tomlinson_quasistatic",
    "logarithmic_ageing_share",
    "friction_lever",
    "startup_drive_torque",
    "coulomb_startup_torque",
    "self_locking_friction_coefficient",
]


def _result(value):
    value = np.asarray(value)
    return float(value) if value.ndim == 0 else value


def _peak_stretch() -> float:
    """t* = (D / r*)^2 of the 12-6 bond's lateral peak: the root in (1/2, 1) of 7/2 / t - 1/2 / (1 - t) - 3 t^2 /
    (1 - t^3) = 0 (the derivative of ln g(t), :func:`lennard_jones_lateral_peak`)."""
    from scipy.optimize import brentq

    return float(brentq(lambda t: 3.5 / t - 0.5 / (1.0 - t) - 3.0 * t * t / (1.0 - t ** 3), 0.5, 1.0 - 1e-12,
                        xtol=1e-15, rtol=1e-15))


#: (D / r*)^2 at the lateral peak of the 12-6 bond sheared at its normal gap D [-] (0.741538).
LATERAL_PEAK_STRETCH = _peak_stretch()
#: Lateral offset x* of that peak over the bond length D [-] (0.590380): x* = D sqrt(1 / t* - 1).
LATERAL_PEAK_OFFSET = math.sqrt(1.0 / LATERAL_PEAK_STRETCH - 1.0)
#: The peak lateral force over U / D [-] (1.268666): 12 sqrt(t* (1 - t*)) (t*^3 - t*^6).
LATERAL_PEAK_FORCE = 12.0 * math.sqrt(LATERAL_PEAK_STRETCH * (1.0 - LATERAL_PEAK_STRETCH)) * (
    LATERAL_PEAK_STRETCH ** 3 - LATERAL_PEAK_STRETCH ** 6)


@cites("thesis", "model")
def lennard_jones_lateral_force(offset, bond_energy, bond_length):
    """Lateral force of a 12-6 bond sheared sideways at its normal gap [N] (MODEL 7f).

    The bond is the thesis's Lennard-Jones pair (3-14, 3-16) of well depth U at its equilibrium distance D (the bond
    length), U(r) = U [(D / r)^12 - 2 (D / r)^6]. Formed across the interface at the normal gap D and displaced by
    ``offset`` x along the sliding direction, r = sqrt(D^2 + x^2), and the force it exerts against the displacement is
    the lateral component of the radial force:

        F_x(x) = U'(r) x / r,   which with t = (D / r)^2 (so x / r = sqrt(1 - t), D / r = sqrt(t)) is
        F_x = (12 U / D) sqrt(t (1 - t)) (t^3 - t^6) sign(x).

    Positive where it resists a positive displacement (odd in x); zero at x = 0.

    Parameters
    ----------
    offset : numeric
        Lateral displacement x from the partner atom [m].
    bond_energy : numeric
        Well depth U (U_chem or U_vdW) [J], >= 0.
    bond_length : numeric
        D [m], > 0: the equilibrium distance and the normal gap.

    Returns
    -------
    numeric
        Lateral resisting force [N].

    Examples
    --------
    >>> round(lennard_jones_lateral_force(0.590380, 1.0, 1.0), 5)
    1.26867
    """
    x = as_array(offset, "offset", "m")
    u = as_array(bond_energy, "bond_energy", "J", nonnegative=True)
    d = as_array(bond_length, "bond_length", "m", positive=True)
    t = 1.0 / (1.0 + (x / d) ** 2)
    return _result(12.0 * u / d * np.sqrt(t * (1.0 - t)) * (t ** 3 - t ** 6) * np.sign(x))


@cites("thesis", "model")
def lennard_jones_lateral_peak(bond_energy, bond_length):
    """Largest lateral force of a 12-6 bond sheared at its normal gap, and where it is reached: (force [N], offset [m]).

    Derivation: with t = (D / r)^2 in (0, 1], the lateral force of :func:`lennard_jones_lateral_force` is
    (12 U / D) g(t), g = t^(1/2) (1 - t)^(1/2) (t^3 - t^6). d ln g / dt = 7 / (2 t) - 1 / (2 (1 - t)) - 3 t^2 /
    (1 - t^3) vanishes once in (1/2, 1), at t* = 0.741538 (solved by Brent's method to machine precision), so

        F_peak = 12 g(t*) U / D = 1.268666 U / D   at   x* = D sqrt(1 / t* - 1) = 0.590380 D,

    against 2.6899 U / D when the same bond is pulled along its axis
    (:func:`memstribo.physics.friction.peak_bond_force`, at r = 1.1087 D): a bond sheared sideways gives less than half.
    The model's van der Waals bonds follow the same 12-6 law with well depth U_vdW (thesis 3.3.5), so this is the
    peak of both bond laws; the model has no other (its bilinear law, Figure 3-13, is the atomic blocks' compression,
    not a bond).

    Parameters
    ----------
    bond_energy : numeric
        U [J], >= 0.
    bond_length : numeric
        D [m], > 0.

    Returns
    -------
    tuple
        (peak lateral force [N], offset x* of the peak [m]).

    Examples
    --------
    >>> force, offset = lennard_jones_lateral_peak(1.0, 1.0)
    >>> round(force, 6), round(offset, 6)
    (1.268666, 0.59038)
    """
    u = as_array(bond_energy, "bond_energy", "J", nonnegative=True)
    d = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(LATERAL_PEAK_FORCE * u / d), _result(LATERAL_PEAK_OFFSET * d)


def _law(phase):
    """The per-bond lateral law over its renewal period, in units of U / D (:func:`bond_lateral_law`)."""
    x = LATERAL_PEAK_OFFSET - (1.0 - phase)  # over D: from x* - D (just re-formed) to x* (at its peak, breaking)
    t = 1.0 / (1.0 + x * x)
    return 12.0 * np.sqrt(t * (1.0 - t)) * (t ** 3 - t ** 6) * np.sign(x)


@cites("thesis", "model")
def bond_lateral_law(phase, bond_energy, bond_length):
    """Lateral force of one bond at ``phase`` of its renewal period while the surfaces slide [N] (MODEL 7f).

    The thesis's bonds break and re-form once per bond length D of sliding (3.5). A bond sheared sideways is stable
    up to its lateral peak (:func:`lennard_jones_lateral_peak`, at x* = 0.590 D); past it the force falls with
    stretch and the bond snaps, and it re-forms with the next partner atom, one lattice period D behind. Over one
    period the bond therefore runs from x = x* - D (just re-formed: it pushes forward, -0.983 U / D) through 0 to x*
    (1.269 U / D), rising monotonically (the lateral force is increasing between its extremes at -x* and +x*). With
    the phase ``p`` in [0, 1) of the period, x = x* - (1 - p) D.

    Parameters
    ----------
    phase : numeric
        Phase in the renewal period [-], in [0, 1] (1: the left limit, at the peak).
    bond_energy, bond_length
        U [J] and D [m] of :func:`lennard_jones_lateral_force`.

    Returns
    -------
    numeric
        Lateral resisting force [N].
    """
    p = as_array(phase, "phase", "")
    if np.any((p < 0.0) | (p > 1.0)):
        raise InputError(f"phase must lie in [0, 1] (a fraction of the bond's renewal period), got {phase!r}.")
    u = as_array(bond_energy, "bond_energy", "J", nonnegative=True)
    d = as_array(bond_length, "bond_length", "m", positive=True)
    return _result(_law(p) * u / d)


@cites("model")
def bond_lateral_mean():
    """Mean over its renewal period of the per-bond lateral law, over U / D [-] (0.2123).

    The period's mean of :func:`bond_lateral_law` is the work of one period over D: [U_x(x*) - U_x(x* - D)] / U, with
    U_x(x) = U(sqrt(D^2 + x^2)) the bond's energy at a lateral offset. A population with random phases resists on
    average with this mean per bond; its static force exceeds N times this mean by a fluctuation of order sqrt(N)
    (:func:`population_static_force`).
    """

    def energy(x):
        r2 = 1.0 + x * x
        return r2 ** -6 - 2.0 * r2 ** -3

    return energy(LATERAL_PEAK_OFFSET) - energy(LATERAL_PEAK_OFFSET - 1.0)


@cites("model")
def population_static_force(forces, phases):
    """Static force of bond populations: the largest summed lateral force over the sliding offset [N] (MODEL 7f).

    Group j holds bonds in one registry, at phase ``phases[j]`` of their common renewal period (the bonds of one
    nanoblock row: one crystal grain per row, MODEL 7d), and resists with ``forces[j]`` x f(p), where ``forces[j]`` is
    the group's N_j U_j / D_j (its kinetic bond force, 3-1 and 3-10/3-12) and f the per-bond law over U / D
    (:func:`bond_lateral_law`). Sliding all groups together by an offset s (a rigid tooth) gives
    S(s) = sum_j F_j f((p_j + s) mod 1); the static force is max_s S(s).

    Exact evaluation: f rises monotonically within its period and drops where a bond snaps, so S rises between
    snaps and its maximum is the left limit at a snap of some group k: at s = 1 - p_k, where group k sits at its
    peak f(1) and group j at (p_j - p_k) mod 1 (at its peak too where it shares k's phase). So
    max_s S = max_k sum_j F_j f(u_jk), u_jk = (p_j - p_k) mod 1, or 1 where that is 0: G^2 evaluations for G groups.

    Checks (tests/test_static_friction.py): groups in phase give sum_j F_j f(1) = 1.2687 sum_j U_j N_j / D_j; N
    groups of one bond at independent uniform phases give N m + O(sqrt(N)) with m = :func:`bond_lateral_mean`; the
    static force is never below the mean over the offset (sum_j F_j m) nor above the in-phase sum.

    Parameters
    ----------
    forces : array_like
        (..., G) each group's N U / D [N], >= 0 (the leading axes: e.g. the steps of a cycle).
    phases : array_like
        (G,) or (..., G): each group's phase [-] in [0, 1).

    Returns
    -------
    numeric
        Static force [N] (shape of the leading axes).
    """
    f = np.asarray(forces, dtype=float)
    p = np.broadcast_to(np.asarray(phases, dtype=float), f.shape)
    if f.shape[-1] == 0:
        return _result(np.zeros(f.shape[:-1]))
    if np.any(f < 0) or not np.all(np.isfinite(f)):
        raise InputError("forces must be finite and >= 0 (each group's N U / D [N]).")
    if np.any((p < 0) | (p >= 1)):
        raise InputError("phases must lie in [0, 1) (a fraction of the bonds' renewal period).")
    u = np.mod(p[..., :, None] - p[..., None, :], 1.0)  # (..., j, k)
    u = np.where(u == 0.0, 1.0, u)  # a group in k's phase is at its peak with it (the left limit)
    totals = np.einsum("...j,...jk->...k", f, _law(u))
    return _result(totals.max(axis=-1))


@cites("prandtl_1928")
def prandtl_tomlinson_parameter(corrugation, stiffness, period):
    """The Prandtl-Tomlinson parameter eta = 4 pi^2 U0 / (k a^2) [-] of an elastic block on a corrugated potential.

    A block on the potential V(x) = -U0 cos(2 pi x / a), pulled through a spring of stiffness k by a support at X,
    rests where k (X - x) = V'(x). That equilibrium is stable while k + V''(x) > 0; V'' reaches -U0 (2 pi / a)^2, so
    every position stays stable (smooth sliding, no static force beyond the corrugation's) if eta < 1, and the block
    sticks and slips, losing the barrier's energy at each snap, if eta > 1 (Prandtl 1928, Tomlinson 1929; Socoliuc et
    al. 2004).

    Parameters
    ----------
    corrugation : numeric
        U0 [J], >= 0: half the peak-to-peak corrugation of the potential.
    stiffness : numeric
        k [N/m], > 0.
    period : numeric
        a [m], > 0.
    """
    u0 = as_array(corrugation, "corrugation", "J", nonnegative=True)
    k = as_array(stiffness, "stiffness", "N/m", positive=True)
    a = as_array(period, "period", "m", positive=True)
    return _result(4.0 * math.pi ** 2 * u0 / (k * a * a))


@cites("prandtl_1928")
def tomlinson_quasistatic(support, corrugation, stiffness, period):
    """The block's positions and the spring force as a support slides quasi-statically: (x [m], k (X - x) [N]).

    At each support position X (increasing) the block stays on the local minimum of V(x) + k (x - X)^2 / 2 it was
    on (V(x) = -U0 cos(2 pi x / a), :func:`prandtl_tomlinson_parameter`), found by Newton's method from the last
    position; where that minimum disappears (k + V''(x) <= 0 on the way), the block slips forward to the next minimum
    (found by descending the energy from there). A jump of x between two close support positions is a slip.

    Parameters
    ----------
    support : array_like
        Support positions X [m], increasing, spaced well below a.
    corrugation, stiffness, period
        U0 [J], k [N/m], a [m].
    """
    xs = np.asarray(as_array(support, "support", "m"), dtype=float).ravel()
    if xs.size == 0 or np.any(np.diff(xs) < 0):
        raise InputError("support must hold at least one position [m], in increasing order (a quasi-static pull).")
    u0 = float(as_array(corrugation, "corrugation", "J", nonnegative=True))
    k = float(as_array(stiffness, "stiffness", "N/m", positive=True))
    a = float(as_array(period, "period", "m", positive=True))
    q = 2.0 * math.pi / a
    lipschitz = k + u0 * q * q  # the largest curvature of the energy: a gradient step of 1 / L never climbs
    tolerance = 1e-12 * max(k * a, u0 * q)
    x = float(xs[0])
    out = np.empty_like(xs)
    for i, X in enumerate(xs):
        for _ in range(100000):
            gradient = u0 * q * math.sin(q * x) + k * (x - X)
            if abs(gradient) < tolerance:
                break
            curvature = u0 * q * q * math.cos(q * x) + k
            newton = gradient / curvature if curvature > 0 else math.inf
            # Newton inside a convex well, else a descent step: from a vanished minimum the block slides forward
            x -= newton if abs(newton) < 0.01 * a else gradient / lipschitz
        out[i] = x
    return out, k * (xs - out)


@cites("li_2011", "tian_2020")
def logarithmic_ageing_share(dwell, onset_time, full_time):
    """Share of the bonds formed after a dwell at rest [-]: ln(1 + t / t_c) / ln(1 + t_full / t_c), at most 1.

    Silica nanocontacts age by forming interfacial siloxane bonds: their static friction grows logarithmically with
    the hold time from 0.1 s to 100 s (Li et al. 2011, AFM silica tip on silica), and nearly linearly below about
    0.1 s (Tian et al. 2020, 5 to 90 ms). ln(1 + t / t_c) has both shapes: linear for t << t_c, logarithmic for
    t >> t_c. Normalised to every bond formed at ``full_time`` (the dwell at which each site has bonded: not
    observed up to 100 s, so a prior, docs/mesh.md).

    Parameters
    ----------
    dwell : numeric
        t [s], >= 0.
    onset_time : numeric
        t_c [s], > 0 (about 0.1 s: where ageing turns logarithmic).
    full_time : numeric
        t_full [s], > 0.

    Returns
    -------
    numeric
        Share in [0, 1].
    """
    t = as_array(dwell, "dwell", "s", nonnegative=True)
    tc = as_array(onset_time, "onset_time", "s", positive=True)
    tf = as_array(full_time, "full_time", "s", positive=True)
    return _result(np.minimum(np.log1p(t / tc) / np.log1p(tf / tc), 1.0))


def _gear_inputs(rho1, rho2, rb1, rb2):
    r1 = as_array(rho1, "rho1", "m", nonnegative=True)
    r2 = as_array(rho2, "rho2", "m", nonnegative=True)
    b1 = as_array(rb1, "base_radius_pinion", "m", positive=True)
    b2 = as_array(rb2, "base_radius_gear", "m", positive=True)
    return r1, r2, b1, b2


@cites("buckingham_1949", "model")
def friction_lever(rho1, rho2, base_radius_pinion, base_radius_gear):
    """Moment arm of a pair's friction against the drive, over the pinion's base radius: |rho1 / r_b1 - rho2 / r_b2|.

    Rigid-body balance of an involute pair (pinion driving, torque T; gear loaded by T_L; normal force N along the
    line of action, whose arm is the base radius; friction F across it, whose arm is the flank's radius of curvature
    rho at the contact): pinion T = N r_b1 + s F rho1, gear N r_b2 + s F rho2 = T_L, s the sign of the sliding
    velocity omega1 (rho1 - rho2 r_b1 / r_b2). Eliminating N:

        T = T_L r_b1 / r_b2 + F r_b1 |rho1 / r_b1 - rho2 / r_b2|,

    so friction costs drive torque in proportion to the sliding speed (zero at the pitch point, where rho1 / rho2 =
    r_b1 / r_b2), as the power balance T omega1 = T_L omega2 + F |u1 - u2| says (Buckingham 1949, ch. 18).

    Returns
    -------
    numeric
        The lever [-] (multiply by F r_b1 for the friction's torque on the pinion).
    """
    r1, r2, b1, b2 = _gear_inputs(rho1, rho2, base_radius_pinion, base_radius_gear)
    return _result(np.abs(r1 / b1 - r2 / b2))


@cites("buckingham_1949", "model")
def startup_drive_torque(load_torque, friction_forces, rho1, rho2, base_radius_pinion, base_radius_gear):
    """Drive torque on the pinion that starts the pair [N m]: T = T_L r_b1 / r_b2 + r_b1 sum_k F_k lever_k.

    ``friction_forces`` F_k [N] of the pairs in mesh at their contacts (radii of curvature ``rho1``, ``rho2`` [m]),
    with the lever of :func:`friction_lever`; the friction forces are given (the bonds' static force does not scale
    with the normal force). ``load_torque`` T_L [N m] on the gear.
    """
    tl = as_array(load_torque, "load_torque", "N m", nonnegative=True)
    f = as_array(friction_forces, "friction_forces", "N", nonnegative=True)
    lever = np.asarray(friction_lever(rho1, rho2, base_radius_pinion, base_radius_gear))
    b1, b2 = float(base_radius_pinion), float(base_radius_gear)
    return _result(tl * b1 / b2 + b1 * np.sum(f * lever, axis=-1))


@cites("buckingham_1949", "model")
def coulomb_startup_torque(load_torque, friction_coefficient, rho1, rho2, base_radius_pinion, base_radius_gear):
    """Drive torque that starts one pair with Coulomb friction F = mu N [N m]; infinite where the pair self-locks.

    From the balance of :func:`friction_lever` with F = mu N: N = T_L / (r_b2 + s mu rho2) and
    T = T_L (r_b1 + s mu rho1) / (r_b2 + s mu rho2), s = sign(rho1 / r_b1 - rho2 / r_b2). In approach (s = -1, the
    contact nearer the gear's tip) the gear's balance needs r_b2 - mu rho2 > 0: for mu >= r_b2 / rho2 no drive
    torque starts the pair (self-locking, :func:`self_locking_friction_coefficient`).
    """
    tl = as_array(load_torque, "load_torque", "N m", nonnegative=True)
    mu = as_array(friction_coefficient, "friction_coefficient", "", nonnegative=True)
    r1, r2, b1, b2 = _gear_inputs(rho1, rho2, base_radius_pinion, base_radius_gear)
    s = np.where(r1 / b1 >= r2 / b2, 1.0, -1.0)
    denominator = b2 + s * mu * r2
    with np.errstate(divide="ignore", invalid="ignore"):
        torque = tl * (b1 + s * mu * r1) / denominator
    return _result(np.where(denominator > 0, torque, np.inf))


@cites("buckingham_1949", "model")
def self_locking_friction_coefficient(rho2, base_radius_gear):
    """Friction coefficient from which an involute pair in approach self-locks, mu* = r_b2 / rho2 [-]
    (:func:`coulomb_startup_torque`); smallest at the first point of contact, where rho2 is the gear's tip radius of
    curvature: mu* = 1 / tan(alpha_a2), alpha_a2 the gear's pressure angle at its tip."""
    r2 = as_array(rho2, "rho2", "m", positive=True)
    b2 = as_array(base_radius_gear, "base_radius_gear", "m", positive=True)
    return _result(b2 / r2)
