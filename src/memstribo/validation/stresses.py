"""Validation rows: surface and subsurface stresses (thesis 5.5; MODEL §9) against closed forms."""

from __future__ import annotations

import math

from memstribo.validation.rows import ValidationRow, compare

TOPIC = "stresses"
COMMAND = "python -m memstribo.validation"


def rows() -> list[ValidationRow]:
    import numpy as np

    from memstribo.physics import stresses as st

    a, p0, nu = 1.0, 1.0, 0.3

    def hertz(r):
        return st.hertz_pressure(r, a, p0)

    z = np.linspace(0.3, 0.7, 401)
    tau = st.principal_shear_stress(st.stress_field(0.0, 0.0, z, hertz, a, 0.0, nu))
    grid = np.array([[x, y, d] for x in (-1.4, -0.9, -0.3, 0.0, 0.2, 0.7, 1.05) for y in (0.0, 0.35)
                     for d in (0.0, 0.05, 0.3, 0.48, 1.2)])
    numeric = st.stress_field(*grid.T, hertz, a, 0.0, nu).tensor()
    closed = st.hamilton_sliding_sphere(*grid.T, a, p0, 0.0, nu).tensor()
    numeric_f = st.stress_field(*grid.T, hertz, a, 0.3, nu).tensor()
    closed_f = st.hamilton_sliding_sphere(*grid.T, a, p0, 0.3, nu).tensor()
    mu = 0.25
    edge = float(st.stress_field(-a, 0.0, 0.0, hertz, a, mu, nu).sigma_xx)
    x = np.linspace(-1.5, 1.5, 121)
    depth = np.linspace(0.0, 1.0, 101)
    tau_f = st.principal_shear_profile(x, depth, hertz, a, 0.5, nu)
    return [
        compare(TOPIC, "max tau_1 below a Hertz contact (nu = 0.3)", "Johnson 1985 §3.4: 0.31 p0", 0.31,
                float(tau.max()), "p0", atol=0.005, command=COMMAND),
        compare(TOPIC, "depth of max tau_1 (nu = 0.3)", "Johnson 1985 §3.4: 0.48 a", 0.48, float(z[np.argmax(tau)]),
                "a", atol=0.005, command=COMMAND),
        compare(TOPIC, "complex-depth integral vs Hamilton closed form (max |difference|, 70 points)",
                "Hamilton 1983, normal load", 0.0, float(np.max(np.abs(numeric - closed))), "p0", atol=2e-7,
                command=COMMAND),
        compare(TOPIC, "complex-depth integral vs closed form with friction mu = 0.3 (max |difference|, 70 points)",
                "Hamilton 1983 normal load; tangential part integrated analytically", 0.0,
                float(np.max(np.abs(numeric_f - closed_f))), "p0", atol=2e-6, command=COMMAND,
                note="largest next to the contact edge just below the surface (near-surface extrapolation)"),
        compare(TOPIC, "tensile stress at the trailing edge, mu = 0.25", "Hamilton 1983: p0 [(1-2nu)/3 + pi(4+nu)mu/8]",
                (1 - 2 * nu) / 3 + math.pi * (4 + nu) * mu / 8, edge, "p0", atol=2e-6, command=COMMAND),
        ValidationRow(TOPIC, "mu = 0.5: max tau_1 on the surface", "Johnson 1985 §7.1 (mu > 0.3)", 0.0,
                      float(depth[np.unravel_index(np.argmax(tau_f), tau_f.shape)[0]]), "a", "exact", bool(
                          depth[np.unravel_index(np.argmax(tau_f), tau_f.shape)[0]] == 0.0), COMMAND,
                      note="depth of the maximum of tau_1 over the x-z plane"),
    ]
