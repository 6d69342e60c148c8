"""Closed-form contact references: internal consistency, quadrature and limits."""

import numpy as np
import pytest
from scipy import integrate

from memstribo.physics import closed_form as ref
from memstribo.errors import InputError

W, R, E = 12.5, 20e-6, 100e9  # N/m, m, Pa


def test_hertz_line_numbers():
    # a = sqrt(4 w R / (pi E*)) = sqrt(1e-3/(pi 1e11)) by hand
    a = ref.hertz_line_half_width(W, R, E)
    assert a == pytest.approx(np.sqrt(4 * W * R / (np.pi * E)), rel=1e-15)
    assert a == pytest.approx(56.419e-9, rel=1e-4)
    p0 = ref.hertz_line_peak_pressure(W, R, E)
    assert p0 == pytest.approx(np.sqrt(W * E / (np.pi * R)), rel=1e-12)


def test_hertz_line_pressure_integrates_to_load():
    a = ref.hertz_line_half_width(W, R, E)
    load, _ = integrate.quad(lambda x: ref.hertz_line_pressure(x, W, R, E), -a, a)
    assert load == pytest.approx(W, rel=1e-8)
    assert ref.hertz_line_pressure(2 * a, W, R, E) == 0.0


def _displacement_difference(d, a, p0):
    # u(0) - u(d) = 2/(pi E*) * int p(s) [ln|d-s| - ln|s|] ds, by quadrature
    f = lambda s: p0 * np.sqrt(1 - (s / a) ** 2) * (np.log(abs(d - s)) - np.log(abs(s)))
    value, _ = integrate.quad(f, -a, a, points=[0.0], limit=200)
    return 2 / (np.pi * E) * value


@pytest.mark.parametrize("ratio", [1.0, 1.5, 4.0, 30.0])
def test_hertz_line_approach_to_point_matches_quadrature(ratio):
    a = ref.hertz_line_half_width(W, R, E)
    p0 = ref.hertz_line_peak_pressure(W, R, E)
    expected = _displacement_difference(ratio * a, a, p0)
    assert ref.hertz_line_approach_to_point(W, R, E, ratio * a) == pytest.approx(expected, rel=1e-6)


def test_hertz_line_approach_limits():
    a = ref.hertz_line_half_width(W, R, E)
    # at the contact edge the centre approach equals the profile height a^2/(2R)
    assert ref.hertz_line_approach_to_point(W, R, E, a) == pytest.approx(a**2 / (2 * R), rel=1e-12)
    # far away it tends to the far-field datum form
    far = 1e4 * a
    assert ref.hertz_line_approach_to_point(W, R, E, far) == pytest.approx(
        ref.hertz_line_approach(W, R, E, far), rel=1e-8)


def test_hertz_line_approach_far_field_datum_by_quadrature():
    # u(0) = 2/(pi E*) int p(s) ln(L/|s|) ds, exact for any L
    a = ref.hertz_line_half_width(W, R, E)
    L = 3.3 * a
    f = lambda s: ref.hertz_line_pressure(s, W, R, E) * np.log(L / abs(s))
    value, _ = integrate.quad(f, -a, a, points=[0.0], limit=200)
    assert ref.hertz_line_approach(W, R, E, L) == pytest.approx(2 / (np.pi * E) * value, rel=1e-7)


def test_hertz_sphere_consistency():
    F = 25e-6
    a = ref.hertz_sphere_radius(F, R, E)
    assert ref.hertz_sphere_approach(F, R, E) == pytest.approx(a**2 / R)
    load, _ = integrate.quad(lambda r: 2 * np.pi * r * ref.hertz_sphere_pressure(r, F, R, E), 0, a)
    assert load == pytest.approx(F, rel=1e-6)  # quad error at the sqrt edge singularity ~3e-7
    # F = 4 E* a^3 / (3 R)
    assert 4 * E * a**3 / (3 * R) == pytest.approx(F, rel=1e-12)


def test_flat_punch_integrates_to_load():
    b = 1e-6
    load, _ = integrate.quad(lambda x: ref.flat_punch_line_pressure(x, W, b), -b, b, limit=200)
    assert load == pytest.approx(W, rel=1e-6)
    assert ref.flat_punch_line_pressure(2 * b, W, b) == 0.0


@pytest.mark.parametrize("mean_pressure", [0.05e9, 0.5e9, 1.5e9])
def test_westergaard_balances_load(mean_pressure):
    amplitude, wavelength = 5e-9, 1e-6
    p_star = np.pi * E * amplitude / wavelength  # 1.57e9 Pa
    a = ref.westergaard_contact_half_width(mean_pressure, amplitude, wavelength, E)
    if mean_pressure < p_star:
        assert ref.westergaard_mean_pressure(a, amplitude, wavelength, E) == pytest.approx(mean_pressure, rel=1e-12)
    load, _ = integrate.quad(lambda x: ref.westergaard_pressure(x, mean_pressure, amplitude, wavelength, E),
                             -wavelength / 2, wavelength / 2, points=[-a, a] if a < wavelength / 2 else None,
                             limit=200)
    assert load / wavelength == pytest.approx(mean_pressure, rel=1e-7)


@pytest.mark.parametrize("call, match", [
    (lambda: ref.hertz_line_half_width(-1.0, R, E), "load must be positive"),
    (lambda: ref.hertz_line_half_width(W, 0.0, E), "radius must be positive"),
    (lambda: ref.hertz_line_peak_pressure(W, R, np.nan), "contact_modulus must be positive"),
    (lambda: ref.hertz_line_approach_to_point(W, R, E, 1e-9), "distance must be at least"),
    (lambda: ref.hertz_sphere_radius(W, R, -E), "contact_modulus must be positive"),
    (lambda: ref.westergaard_pressure(0.0, 1e6, -1e-9, 1e-6, E), "amplitude must be positive"),
])
def test_bad_input(call, match):
    with pytest.raises(InputError, match=match):
        call()
