"""Static friction from mechanics (MODEL 7f, issue #35): the lateral peak of a bond against an independent numerical
maximisation, the static force of a bond population (in phase: N peaks; random phases: N m + O(sqrt N)), the
Prandtl-Tomlinson threshold of an elastic block, the ageing law and the start-up torque balance of an involute pair
against a rigid-body equilibrium solved from vectors."""

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from memstribo.errors import InputError
from memstribo.physics import friction
from memstribo.physics import static_friction as sf
from memstribo.physics.potentials import lennard_jones_potential, lennard_jones_sigma


# ------------------------------------------------------------------------------------------- lateral peak of a bond
def _lateral_by_finite_difference(x, u, d):
    """-dE/dx of the thesis's 12-6 bond (potentials.lennard_jones_potential) at the normal gap d, by central
    differences: independent of the closed form in static_friction."""
    sigma = lennard_jones_sigma(d)
    h = 1e-6 * d

    def energy(xx):
        return lennard_jones_potential(math.hypot(d, xx), u, sigma)

    return (energy(x + h) - energy(x - h)) / (2 * h)


@pytest.mark.parametrize("u, d", [(1.0, 1.0), (5.43e-19, 2.35e-10), (5.4e-21, 3.0e-10)])
def test_lateral_peak_matches_a_numerical_maximisation(u, d):
    best = minimize_scalar(lambda x: -_lateral_by_finite_difference(x, u, d), bounds=(0.05 * d, 2 * d),
                           method="bounded", options={"xatol": 1e-10 * d})
    force, offset = sf.lennard_jones_lateral_peak(u, d)
    assert force == pytest.approx(-best.fun, rel=1e-6)
    assert offset == pytest.approx(best.x, rel=1e-4)
    assert force == pytest.approx(1.26867 * u / d, rel=1e-5)
    # sideways: less than half the axial peak of version 3 (2.69 U / D)
    assert force < 0.5 * friction.peak_bond_force(1.0, u, d)
    for x in (0.2 * d, 0.59 * d, 1.3 * d):
        assert sf.lennard_jones_lateral_force(x, u, d) == pytest.approx(_lateral_by_finite_difference(x, u, d),
                                                                        rel=1e-6)


def test_the_per_bond_law_rises_over_its_period_and_peaks_at_the_snap():
    p = np.linspace(0.0, 1.0, 1001)
    law = sf.bond_lateral_law(p, 1.0, 1.0)
    assert np.all(np.diff(law) > 0)
    assert law[-1] == pytest.approx(sf.LATERAL_PEAK_FORCE, rel=1e-12)
    # its mean is the work of one period over D (the energy given up at the snap)
    fine = np.linspace(0.0, 1.0, 200001)
    assert np.trapezoid(sf.bond_lateral_law(fine, 1.0, 1.0), fine) == pytest.approx(sf.bond_lateral_mean(), rel=1e-8)
    with pytest.raises(InputError, match="phase must lie in"):
        sf.bond_lateral_law(1.5, 1.0, 1.0)


# ------------------------------------------------------------------------------------ static force of a population
def test_groups_in_phase_give_the_sum_of_their_peaks():
    forces = np.array([3.0, 1.0, 2.5, 0.5])
    for phase in (0.0, 0.37, 0.99):
        assert sf.population_static_force(forces, np.full(4, phase)) == pytest.approx(
            sf.LATERAL_PEAK_FORCE * forces.sum(), rel=1e-12)
    # N identical bonds in phase: N times the single bond's lateral peak
    assert sf.population_static_force(np.ones(250), np.zeros(250)) == pytest.approx(
        250 * sf.lennard_jones_lateral_peak(1.0, 1.0)[0], rel=1e-12)


def test_the_static_force_is_the_maximum_over_the_offset():
    """Against a brute-force scan of the sliding offset (the exact evaluation takes the left limits at the snaps)."""
    rng = np.random.default_rng(3)
    forces, phases = rng.random(7), rng.random(7)
    s = np.linspace(0.0, 1.0, 400001)[:-1]
    total = sum(f * sf.bond_lateral_law(np.mod(p + s, 1.0), 1.0, 1.0) for f, p in zip(forces, phases))
    exact = sf.population_static_force(forces, phases)
    assert exact >= total.max() - 1e-12
    assert exact == pytest.approx(total.max(), rel=1e-4)
    # bounds: the mean over the offset, and the in-phase sum
    assert forces.sum() * sf.bond_lateral_mean() <= exact <= forces.sum() * sf.LATERAL_PEAK_FORCE


def test_random_phases_give_the_mean_plus_a_fluctuation_of_order_root_n():
    """N bonds at independent uniform phases: S(s) - N m is a sum of N independent zero-mean terms of variance
    sigma^2 (m, sigma^2: the mean and variance of the law over its period), so max_s S - N m = sqrt(N) sigma Z_N with
    Z_N converging in distribution as N grows (the maximum of a stationary process over one period). Expected:
    E[(max - N m) / sqrt(N)] the same at N = 64 and 1024 (within sampling error), positive, and far below the
    in-phase excess sqrt(N) (peak - m)."""
    rng = np.random.default_rng(2026)
    m = sf.bond_lateral_mean()
    fine = np.linspace(0.0, 1.0, 100001)
    sigma = math.sqrt(np.trapezoid((sf.bond_lateral_law(fine, 1.0, 1.0) - m) ** 2, fine))
    scaled = {}
    for n in (64, 1024):
        draws = np.array([(sf.population_static_force(np.ones(n), rng.random(n)) - n * m) / math.sqrt(n)
                          for _ in range(200)])
        assert np.all(draws > 0)
        scaled[n] = (draws.mean(), draws.std(ddof=1) / math.sqrt(draws.size))
    (a, sa), (b, sb) = scaled[64], scaled[1024]
    assert abs(a - b) < 4 * math.hypot(sa, sb) + 0.05 * a
    assert 0.5 * sigma < b < 4 * sigma  # of the order of the law's standard deviation
    assert b * math.sqrt(1024) < 0.05 * 1024 * (sf.LATERAL_PEAK_FORCE - m)


def test_tomlinson_input_errors():
    with pytest.raises(InputError, match="increasing order"):
        sf.tomlinson_quasistatic([1.0, 0.0], 1.0, 1.0, 1.0)
    with pytest.raises(InputError, match="stiffness"):
        sf.tomlinson_quasistatic([0.0, 1.0], 1.0, -1.0, 1.0)


def test_population_input_errors():
    with pytest.raises(InputError, match="phases must lie in"):
        sf.population_static_force([1.0], [1.0])
    with pytest.raises(InputError, match="forces must be finite"):
        sf.population_static_force([-1.0], [0.5])


# ------------------------------------------------------------------------------------------------ Prandtl-Tomlinson
@pytest.mark.parametrize("eta, slips", [(0.5, False), (0.85, False), (1.2, True), (3.0, True)])
def test_an_elastic_block_sticks_and_slips_only_past_the_prandtl_tomlinson_threshold(eta, slips):
    a, k = 2.0e-10, 5.0
    u0 = eta * k * a * a / (4 * math.pi ** 2)
    assert sf.prandtl_tomlinson_parameter(u0, k, a) == pytest.approx(eta, rel=1e-12)
    support = np.linspace(0.0, 3 * a, 3001)
    x, force = sf.tomlinson_quasistatic(support, u0, k, a)
    jump = np.abs(np.diff(x)).max()
    assert (jump > 0.1 * a) == slips
    if not slips:  # smooth: the spring force follows the corrugation's force, at most 2 pi U0 / a
        assert force.max() == pytest.approx(2 * math.pi * u0 / a, rel=1e-3)
    else:  # stick-slip: the block is dragged past the corrugation's steepest point before it snaps
        assert force.max() <= 2 * math.pi * u0 / a * (1 + 1e-9)


# ----------------------------------------------------------------------------------------------------------- ageing
def test_logarithmic_ageing_is_linear_early_and_logarithmic_late():
    tc, tf = 0.1, 1e3
    assert sf.logarithmic_ageing_share(0.0, tc, tf) == 0.0
    assert sf.logarithmic_ageing_share(tf, tc, tf) == pytest.approx(1.0)
    assert sf.logarithmic_ageing_share(10 * tf, tc, tf) == 1.0
    early = sf.logarithmic_ageing_share(np.array([1e-4, 2e-4]), tc, tf)
    assert early[1] / early[0] == pytest.approx(2.0, rel=2e-3)  # linear for t << t_c (Tian et al. 2020)
    late = sf.logarithmic_ageing_share(np.array([1.0, 10.0, 100.0]), tc, tf)
    assert late[2] - late[1] == pytest.approx(late[1] - late[0], rel=0.05)  # equal steps per decade (Li et al. 2011)


# --------------------------------------------------------------------------------------------- torque balance
def _rigid_body_drive_torque(load, friction_force, rho1, rb1, rb2, length, coulomb=None):
    """Drive torque from the equilibrium of both gears, built from position and force vectors (2D cross products),
    solved as a linear system for (T, N): the independent hand calculation of the balance.

    Line of action along +x from the pinion's base tangent point T1 = (0, 0) to the gear's T2 = (L, 0); pinion centre
    (0, r_b1), gear centre (L, -r_b2); the pinion turns counter-clockwise and drives the gear clockwise."""
    o1, o2 = np.array([0.0, rb1]), np.array([length, -rb2])
    p = np.array([rho1, 0.0])
    w1 = 1.0
    w2 = -w1 * rb1 / rb2
    v1 = w1 * np.array([-(p - o1)[1], (p - o1)[0]])
    v2 = w2 * np.array([-(p - o2)[1], (p - o2)[0]])
    slip = v1 - v2
    assert abs(slip[0]) < 1e-12 * abs(v1[0])  # normal velocities agree: only sliding across the line of action
    direction = -np.sign(slip[1])  # friction on the pinion opposes its sliding

    def cross(r, f):
        return r[0] * f[1] - r[1] * f[0]

    # unknowns (T, N); friction either given or mu N
    # pinion: T + cross(p - o1, -N e_x) + cross(p - o1, F_p e_y) = 0; gear: -T_L + cross(p - o2, N e_x) +
    # cross(p - o2, -F_p e_y) = 0 (the gear's load torque resists its clockwise turn: +T_L counter-clockwise)
    a = np.zeros((2, 2))
    b = np.zeros(2)
    ex, ey = np.array([1.0, 0.0]), np.array([0.0, 1.0])
    a[0, 0] = 1.0
    a[0, 1] = cross(p - o1, -ex)
    a[1, 1] = cross(p - o2, ex)
    if coulomb is None:
        b[0] = -cross(p - o1, direction * friction_force * ey)
        b[1] = -load - cross(p - o2, -direction * friction_force * ey)
    else:
        a[0, 1] += cross(p - o1, direction * coulomb * ey)
        a[1, 1] += cross(p - o2, -direction * coulomb * ey)
        b[1] = -load
    torque, normal = np.linalg.solve(a, b)
    return torque, normal


@pytest.mark.parametrize("rho1", [2.0e-6, 9.0e-6, 16.0e-6])
def test_the_start_up_torque_balance_matches_a_rigid_body_equilibrium(rho1):
    rb1, rb2, length, load, force = 20e-6, 80e-6, 25e-6, 3e-7, 1e-3
    rho2 = length - rho1
    expected, normal = _rigid_body_drive_torque(load, force, rho1, rb1, rb2, length)
    assert sf.startup_drive_torque(load, [force], rho1, rho2, rb1, rb2) == pytest.approx(expected, rel=1e-12)
    assert normal > 0
    mu = 0.4
    expected, normal = _rigid_body_drive_torque(load, None, rho1, rb1, rb2, length, coulomb=mu)
    assert sf.coulomb_startup_torque(load, mu, rho1, rho2, rb1, rb2) == pytest.approx(expected, rel=1e-12)


def test_an_involute_pair_self_locks_in_approach_from_rb2_over_rho2():
    rb1, rb2, length, load = 20e-6, 80e-6, 60e-6, 1e-7
    rho1 = 4e-6  # approach: rho1 / rb1 < rho2 / rb2
    rho2 = length - rho1
    critical = sf.self_locking_friction_coefficient(rho2, rb2)
    assert critical == pytest.approx(rb2 / rho2)
    below = sf.coulomb_startup_torque(load, 0.99 * critical, rho1, rho2, rb1, rb2)
    assert math.isfinite(below) and below > sf.coulomb_startup_torque(load, 0.5 * critical, rho1, rho2, rb1, rb2)
    assert sf.coulomb_startup_torque(load, 1.01 * critical, rho1, rho2, rb1, rb2) == math.inf
    # the rigid-body system turns singular there (N grows without bound)
    _, normal = _rigid_body_drive_torque(load, None, rho1, rb1, rb2, length, coulomb=0.999 * critical)
    assert normal > 100 * load / rb2


def test_friction_costs_no_torque_at_the_pitch_point():
    rb1, rb2 = 20e-6, 80e-6
    rho1, rho2 = 5e-6, 20e-6  # rho1 / rb1 = rho2 / rb2: the pitch point
    assert sf.friction_lever(rho1, rho2, rb1, rb2) == 0.0
    assert sf.startup_drive_torque(1e-7, [1.0], rho1, rho2, rb1, rb2) == pytest.approx(1e-7 * rb1 / rb2)
