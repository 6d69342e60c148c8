"""Surface and subsurface stresses (thesis 5.5, MODEL §9): point-load kernels, the complex-depth
integral against Hamilton's closed form and against direct 2-D integration of Cerruti's solution,
surface closed forms with friction, invariants, bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from memstribo.physics import stresses as st
from memstribo.errors import InputError

NU = 0.3
A, P0 = 1.0, 1.0  # Hertz case in units of a and p0 (the solution is scale-invariant; SI case below)
COMPONENTS = ("xx", "yy", "zz", "xy", "xz", "yz")


def hertz(r):
    return st.hertz_pressure(r, A, P0)


def _values(field):
    return np.array([getattr(field, f"sigma_{c}") for c in COMPONENTS])


# --- point-load kernels ------------------------------------------------------------------------------

POINTS = np.array([[0.3, -0.7, 0.45], [1.2, 0.4, 0.1], [-0.2, 0.05, 2.0], [0.0, 0.0, 0.7]])


def test_boussinesq_matches_johnson_closed_form():
    x, y, z = POINTS.T
    r = np.sqrt(x**2 + y**2 + z**2)
    s = st.boussinesq(x, y, z, 1.0, NU)
    np.testing.assert_allclose(s.sigma_zz, -3 * z**3 / (2 * np.pi * r**5), rtol=1e-12)
    np.testing.assert_allclose(s.sigma_xz, -3 * x * z**2 / (2 * np.pi * r**5), rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(s.sigma_yz, -3 * y * z**2 / (2 * np.pi * r**5), rtol=1e-12, atol=1e-15)
    # Johnson (1985) section 3.2: sigma_x off the axis
    rho2 = x[:3] ** 2 + y[:3] ** 2
    sxx = 1 / (2 * np.pi) * ((1 - 2 * NU) / rho2 * ((1 - z[:3] / r[:3]) * (x[:3] ** 2 - y[:3] ** 2) / rho2
                                                     + z[:3] * y[:3] ** 2 / r[:3] ** 3) - 3 * z[:3] * x[:3] ** 2 / r[:3] ** 5)
    np.testing.assert_allclose(s.sigma_xx[:3], sxx, rtol=1e-10)


def test_cerruti_matches_johnson_closed_form():
    x, y, z = POINTS.T
    r = np.sqrt(x**2 + y**2 + z**2)
    s = st.cerruti(x, y, z, 1.0, NU)
    np.testing.assert_allclose(s.sigma_zz, -3 * x * z**2 / (2 * np.pi * r**5), rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(s.sigma_xz, -3 * x**2 * z / (2 * np.pi * r**5), rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(s.sigma_yz, -3 * x * y * z / (2 * np.pi * r**5), rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("solution", [st.boussinesq, st.cerruti])
def test_point_loads_satisfy_equilibrium_and_free_surface(solution):
    h = 1e-5
    for x, y, z in POINTS:
        div = np.zeros(3)
        for axis, (dx, dy, dz) in enumerate(np.eye(3) * h):
            plus = solution(x + dx, y + dy, z + dz, 1.0, NU).tensor()
            minus = solution(x - dx, y - dy, z - dz, 1.0, NU).tensor()
            div += (plus - minus)[:, axis] / (2 * h)
        assert np.max(np.abs(div)) < 1e-6
    # the surface away from the load is traction-free
    s = solution(np.array([0.5, -1.0, 0.3]), np.array([0.2, 0.4, -0.9]), 1e-9, 1.0, NU)
    assert np.max(np.abs([s.sigma_zz, s.sigma_xz, s.sigma_yz])) < 1e-7


def test_point_load_resultant_balances_load():
    """The tractions on a hemisphere of radius rho around the load balance it (Gauss quadrature)."""
    rho = 2.0
    theta, wt = np.polynomial.legendre.leggauss(40)
    theta = 0.25 * np.pi * (theta + 1)  # polar angle from the z axis, 0..pi/2
    wt = 0.25 * np.pi * wt
    phi = np.linspace(0, 2 * np.pi, 80, endpoint=False)
    t, f = np.meshgrid(theta, phi, indexing="ij")
    n = np.stack([np.sin(t) * np.cos(f), np.sin(t) * np.sin(f), np.cos(t)], -1)
    area = (rho**2 * np.sin(t) * wt[:, None] * (2 * np.pi / phi.size))[..., None]
    for solution, expected in [(st.boussinesq, [0, 0, -1.0]), (st.cerruti, [-1.0, 0, 0])]:
        sigma = solution(rho * n[..., 0], rho * n[..., 1], rho * n[..., 2], 1.0, NU).tensor()
        force = np.sum(np.einsum("...ij,...j->...i", sigma, n) * area, axis=(0, 1))
        # the body inside the hemisphere is pulled by the outside material with -load
        np.testing.assert_allclose(force, expected, atol=1e-6)


# --- Hertz without friction: the integral against Hamilton's closed form -------------------------------

GRID = np.array([[x, y, z] for x in (-1.4, -0.9, -0.3, 0.0, 0.2, 0.7, 1.05) for y in (0.0, 0.35)
                 for z in (0.0, 1e-4, 0.05, 0.3, 0.48, 1.2)])


def test_integral_matches_hamilton_closed_form_frictionless():
    x, y, z = GRID.T
    numeric = _values(st.stress_field(x, y, z, hertz, A, 0.0, NU))
    closed = _values(st.hamilton_sliding_sphere(x, y, z, A, P0, 0.0, NU))
    # tolerance: 2e-7 p0 (quadrature of the line integral, 64 nodes a side; Chebyshev series of W)
    np.testing.assert_allclose(numeric, closed, atol=2e-7 * P0)


def test_integral_matches_hamilton_closed_form_with_friction():
    """The tangential part of hamilton_sliding_sphere is an analytic (quadrature-free) evaluation
    of the same field: it checks the quadrature, the weight W and the near-surface extrapolation."""
    x, y, z = GRID.T
    for mu in (0.2, 0.5):
        numeric = _values(st.stress_field(x, y, z, hertz, A, mu, NU))
        closed = _values(st.hamilton_sliding_sphere(x, y, z, A, P0, mu, NU))
        np.testing.assert_allclose(numeric, closed, atol=2e-6 * P0)
        deep = z >= 0.05
        np.testing.assert_allclose(numeric[:, deep], closed[:, deep], atol=2e-8 * P0)


def test_hamilton_tangential_closed_form_on_the_surface():
    """Surface values of the tangential part (Hamilton 1983; Johnson 7.1) from the closed form, to 1e-9."""
    x = np.array([-0.999, -0.5, 0.3, 0.9, 0.99])
    both = st.hamilton_sliding_sphere(x, 0.0, 0.0, A, P0, 1.0, NU)
    normal = st.hamilton_sliding_sphere(x, 0.0, 0.0, A, P0, 0.0, NU)
    np.testing.assert_allclose(both.sigma_xx - normal.sigma_xx, -np.pi * (4 + NU) / 8 * x, atol=1e-9)
    np.testing.assert_allclose(both.sigma_yy - normal.sigma_yy, -3 * np.pi * NU / 8 * x, atol=1e-9)
    np.testing.assert_allclose(both.sigma_xz, -np.sqrt(1 - x**2), atol=1e-9)
    # at and next to the contact edge, on the axis: the quadrature fallback keeps it continuous
    edge = st.hamilton_sliding_sphere(np.array([-1.0, -1.0 + 1e-3, 1e-8]), 0.0, np.array([0.0, 0.0, 0.3]),
                                      A, P0, 0.25, NU)
    assert float(edge.sigma_xx[0]) == pytest.approx((1 - 2 * NU) / 3 + np.pi * (4 + NU) * 0.25 / 8, abs=2e-6)
    assert np.all(np.isfinite(edge.tensor()))


def test_hamilton_axis_and_surface_closed_forms():
    z = np.array([0.1, 0.48, 1.0, 3.0])
    s = st.hamilton_sliding_sphere(0.0, 0.0, z, A, P0, 0.0, NU)
    # Johnson (3.45): on the axis
    np.testing.assert_allclose(s.sigma_zz, -P0 / (1 + z**2), rtol=1e-9)
    sr = P0 * (-(1 + NU) * (1 - z * np.arctan(1 / z)) + 0.5 / (1 + z**2))
    np.testing.assert_allclose(s.sigma_xx, sr, rtol=1e-8)
    # Johnson (3.44): on the surface, inside and outside the contact
    r = np.array([0.2, 0.6, 0.95, 1.5, 2.0])
    s = st.hamilton_sliding_sphere(r, 0.0, 0.0, A, P0, 0.0, NU)
    inside = r < 1
    root = np.sqrt(np.clip(1 - r**2, 0, None))
    sr = (1 - 2 * NU) / 3 / r**2 * (1 - root**3) - root
    st_ = -(1 - 2 * NU) / 3 / r**2 * (1 - root**3) - 2 * NU * root
    np.testing.assert_allclose(s.sigma_xx, sr * P0, atol=1e-7)
    np.testing.assert_allclose(s.sigma_yy, st_ * P0, atol=1e-7)
    np.testing.assert_allclose(s.sigma_zz[inside], -root[inside] * P0, atol=1e-7)


def test_maximum_subsurface_shear_frictionless():
    """Johnson 3.4: max tau_1 = 0.31 p0 at z = 0.48 a on the axis (nu = 0.3)."""
    z = np.linspace(0.3, 0.7, 401)
    tau = st.principal_shear_stress(st.stress_field(0.0, 0.0, z, hertz, A, 0.0, NU))
    assert tau.max() == pytest.approx(0.31 * P0, abs=0.005)
    assert z[np.argmax(tau)] == pytest.approx(0.48 * A, abs=0.005)
    # the same from the closed form
    tau_h = st.principal_shear_stress(st.hamilton_sliding_sphere(0.0, 0.0, z, A, P0, 0.0, NU))
    np.testing.assert_allclose(tau, tau_h, atol=1e-7)


# --- friction -------------------------------------------------------------------------------------------

def test_surface_stresses_with_friction_closed_form():
    """On the surface along the sliding line the tangential traction q = mu p adds
    sigma_xx = -pi (4 + nu)/8 q0 x/a, sigma_yy = -3 pi nu/8 q0 x/a, sigma_xz = -q (Hamilton 1983;
    Johnson 7.1); the trailing edge x = -a carries p0 [(1 - 2 nu)/3 + pi (4 + nu) mu / 8]."""
    mu = 0.4
    x = np.array([-1.0, -0.6, -0.1, 0.3, 0.8])
    both = st.stress_field(x, 0.0, 0.0, hertz, A, mu, NU)
    normal = st.stress_field(x, 0.0, 0.0, hertz, A, 0.0, NU)
    q0 = mu * P0
    np.testing.assert_allclose(both.sigma_xx - normal.sigma_xx, -np.pi * (4 + NU) / 8 * q0 * x / A, atol=2e-6)
    np.testing.assert_allclose(both.sigma_yy - normal.sigma_yy, -3 * np.pi * NU / 8 * q0 * x / A, atol=2e-6)
    np.testing.assert_allclose(both.sigma_xz, -q0 * np.sqrt(1 - x**2), atol=2e-6)
    assert both.sigma_xx[0] == pytest.approx(P0 * ((1 - 2 * NU) / 3 + np.pi * (4 + NU) * mu / 8), abs=2e-6)


def _cerruti_brute_force(x, y, z, mu, nodes=160):
    """Direct 2-D integration of Cerruti's point load over the Hertz traction mu p(r) on the disk:
    r = a sin(t) (removes the square-root edge), Gauss-Legendre in t, trapezoid in the angle."""
    t, wt = np.polynomial.legendre.leggauss(nodes)
    t = 0.25 * np.pi * (t + 1)
    wt = 0.25 * np.pi * wt
    phi = np.linspace(0, 2 * np.pi, 2 * nodes, endpoint=False)
    r = A * np.sin(t)[:, None]
    dA = (r * A * np.cos(t)[:, None]) * wt[:, None] * (2 * np.pi / phi.size)
    q = mu * P0 * np.cos(t)[:, None]
    s = st.cerruti(x - r * np.cos(phi), y - r * np.sin(phi), z, 1.0, NU)
    return np.array([np.sum(getattr(s, f"sigma_{c}") * q * dA) for c in COMPONENTS])


@pytest.mark.parametrize("point", [(0.2, 0.1, 0.5), (-0.6, 0.3, 0.3), (1.3, -0.2, 0.4)])
def test_friction_part_matches_direct_integration_of_cerruti(point):
    mu = 0.3
    both = _values(st.stress_field(*point, hertz, A, mu, NU))
    normal = _values(st.stress_field(*point, hertz, A, 0.0, NU))
    np.testing.assert_allclose(both - normal, _cerruti_brute_force(*point, mu), atol=1e-7)
    hamilton = _values(st.hamilton_sliding_sphere(*point, A, P0, mu, NU))
    np.testing.assert_allclose(both, hamilton, atol=2e-7)


def test_friction_raises_and_moves_the_maximum_shear_towards_the_surface():
    z = np.linspace(0.0, 1.0, 101)
    x = np.linspace(-1.5, 1.5, 121)
    tau0 = st.principal_shear_profile(x, z, hertz, A, 0.0, NU)
    tau5 = st.principal_shear_profile(x, z, hertz, A, 0.5, NU)
    assert tau5.max() > tau0.max()
    # mu = 0.5 > 0.3: the maximum is on the surface (Johnson 7.1, Hamilton 1983)
    assert z[np.unravel_index(np.argmax(tau5), tau5.shape)[0]] == 0.0
    assert z[np.unravel_index(np.argmax(tau0), tau0.shape)[0]] == pytest.approx(0.48, abs=0.011)


# --- general pressures, invariants --------------------------------------------------------------------

def test_power_law_pressure_far_field_and_load():
    """A d = 4 power-law-like pressure (a² + 2 r²) sqrt(a² - r²): the weight's load equals the
    integral of p, and far below the contact sigma_zz -> -3P/(2 pi z²) (Boussinesq)."""
    def pressure(r):
        return (A**2 + 2 * r**2) * np.sqrt(np.clip(A**2 - r**2, 0, None))

    weight = st.flat_punch_weight(pressure, A)
    from scipy import integrate

    load, _ = integrate.quad(lambda r: 2 * np.pi * r * pressure(r), 0, A, epsrel=1e-12)
    assert weight.load == pytest.approx(load, rel=1e-9)
    z = 100.0 * A
    s = st.stress_field(0.0, 0.0, z, pressure, A, 0.0, NU)
    assert float(s.sigma_zz) == pytest.approx(-3 * load / (2 * np.pi * z**2), rel=1e-3)


def test_samples_equal_callable():
    r = np.linspace(0, A, 2001)
    from_samples = _values(st.stress_field(0.3, 0.1, 0.2, (r, hertz(r)), A, 0.2, NU))
    from_callable = _values(st.stress_field(0.3, 0.1, 0.2, hertz, A, 0.2, NU))
    np.testing.assert_allclose(from_samples, from_callable, atol=1e-5)


def test_symmetries_and_scaling():
    x = np.linspace(-1.5, 1.5, 31)
    z = np.array([0.0, 0.2, 0.6])
    tau = st.principal_shear_profile(x, z, hertz, A, 0.0, NU)
    np.testing.assert_allclose(tau, tau[:, ::-1], atol=1e-9)  # frictionless: symmetric in x
    plus = st.principal_shear_profile(x, z, hertz, A, 0.3, NU)
    minus = st.principal_shear_profile(x, z, hertz, A, -0.3, NU)
    np.testing.assert_allclose(plus, minus[:, ::-1], atol=1e-9)  # reversing the sliding mirrors x
    assert np.all(tau >= 0) and np.all(plus >= 0)
    # SI scaling: a = 8.95 nm, p0 = 5 GPa is the unit case times p0 at points times a
    a_si, p0_si = 8.95e-9, 5e9
    si = st.principal_shear_profile(x * a_si, z * a_si, lambda r: st.hertz_pressure(r, a_si, p0_si), a_si, 0.3, NU)
    np.testing.assert_allclose(si, plus * p0_si, rtol=1e-7, atol=1e-9 * p0_si)


def test_surface_value_is_limit_from_below():
    """z = 0 is extrapolated from z = 1, 2, 4e-5 a: it continues the directly integrated field
    smoothly and, at the contact edge (where p = 0), gives zero surface tractions."""
    x = np.array([-0.8, 0.0, 0.5, 1.3])
    at0 = _values(st.stress_field(x, 0.0, 0.0, hertz, A, 0.3, NU))
    direct = _values(st.stress_field(x, 0.0, 1e-4, hertz, A, 0.3, NU))  # evaluated directly
    np.testing.assert_allclose(at0, direct, atol=3e-4)  # |grad sigma| <= ~3 p0/a times 1e-4 a
    edge = st.stress_field(1.0, 0.0, 0.0, hertz, A, 0.3, NU)
    assert abs(float(edge.sigma_zz)) < 1e-6 and abs(float(edge.sigma_xz)) < 1e-6


def test_principal_stresses_ordered_and_consistent():
    field = st.stress_field(GRID[:, 0], GRID[:, 1], GRID[:, 2], hertz, A, 0.3, NU)
    principal = st.principal_stresses(field)
    assert principal.shape == (len(GRID), 3)
    assert np.all(np.diff(principal, axis=-1) <= 1e-12)
    np.testing.assert_allclose(principal.sum(-1), field.sigma_xx + field.sigma_yy + field.sigma_zz, atol=1e-12)
    np.testing.assert_allclose(st.principal_shear_stress(field), 0.5 * (principal[:, 0] - principal[:, 2]))
    # a tensor array works too
    np.testing.assert_allclose(st.principal_shear_stress(field.tensor()), st.principal_shear_stress(field))


def test_profile_shapes():
    x = np.linspace(-2e-8, 2e-8, 50)
    p = lambda r: st.hertz_pressure(r, 9e-9, 4e9)  # noqa: E731
    assert st.principal_shear_profile(x, 0.0, p, 9e-9, 0.2, 0.23).shape == (50,)
    assert st.principal_shear_profile(x, [0.0, 2e-9, 5e-9], p, 9e-9, 0.2, 0.23).shape == (3, 50)


# --- bad input -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("call,match", [
    (lambda: st.stress_field(0.0, 0.0, -1.0, hertz, A, 0.0, NU), "depth"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, hertz, 0.0, 0.0, NU), "contact_radius"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, hertz, A, 0.0, 0.6), "poisson_ratio"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, hertz, A, 0.0, -1.0), "poisson_ratio"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, hertz, A, float("nan"), NU), "friction_coefficient"),
    (lambda: st.stress_field(np.nan, 0.0, 0.1, hertz, A, 0.0, NU), "x"),
    (lambda: st.stress_field([0.0, 1.0], 0.0, [0.1, 0.2, 0.3], hertz, A, 0.0, NU), "broadcast"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, lambda r: -hertz(r), A, 0.0, NU), "pressure"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, lambda r: np.full_like(r, np.inf), A, 0.0, NU), "pressure"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, "hertz", A, 0.0, NU), "pressure"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, ([0.0, 0.5, 0.2], [1, 1, 1]), A, 0.0, NU), "increasing"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, hertz, A, 0.0, NU, nodes=2), "nodes"),
    (lambda: st.stress_field(0.0, 0.0, 0.1, st.flat_punch_weight(hertz, A), 2 * A, 0.0, NU), "weight"),
    (lambda: st.hamilton_sliding_sphere(0.0, 0.0, 0.1, A, 0.0, 0.0, NU), "max_pressure"),
    (lambda: st.hamilton_sliding_sphere(0.0, 0.0, 0.1, -A, 1.0, 0.0, NU), "contact_radius"),
    (lambda: st.boussinesq(0.0, 0.0, 0.0, 1.0, NU), "z must be > 0"),
    (lambda: st.cerruti(0.1, 0.0, 0.1, 1.0, 0.7), "poisson_ratio"),
    (lambda: st.principal_shear_stress(np.zeros((4, 2))), "3 x 3"),
    (lambda: st.principal_shear_profile(np.zeros((2, 2)), 0.0, hertz, A), "1-D"),
])
def test_bad_input(call, match):
    with pytest.raises(InputError, match=match):
        call()


def test_validation_rows_agree():
    from memstribo.validation.stresses import rows

    table = rows()
    assert len(table) >= 5 and all(row.agrees for row in table), [r for r in table if not r.agrees]
