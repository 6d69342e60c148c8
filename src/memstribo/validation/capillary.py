"""Validation rows of the capillary relations (humid air, issue #17; memstribo.physics.capillary).

A numerical meniscus (the Laplace pressure summed over the wetted elements of a gap field,
``capillary.capillary_force_from_gap``, the route a contact solution takes) against the closed
forms of a sphere and a cylinder on a flat, and the limits that must hold.
"""

from __future__ import annotations

import math

from memstribo.validation.rows import ValidationRow, compare

TOPIC = "capillary"
COMMAND = "python -m memstribo.validation"


def rows() -> list[ValidationRow]:
    import numpy as np

    from memstribo.physics.capillary import (capillary_force_cylinder, capillary_force_from_gap, capillary_force_sphere,
                             condensation_height, kelvin_radius)

    out = [compare(TOPIC, "Kelvin radius gamma V_m / (R T) of water at 25 degC (RH = 1/e)",
                   "issue #17 (about 0.52 nm); Israelachvili 2011 (17.21)", 0.52, kelvin_radius(1 / math.e) * 1e9,
                   "nm", atol=0.01, command=COMMAND)]
    radius, theta = 1e-6, math.radians(30)
    dx = 0.5e-9
    x = (np.arange(801) - 400) * dx
    gap = (x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius)
    numeric = capillary_force_from_gap(gap, dx * dx, kelvin_radius(0.4), theta)
    out.append(compare(TOPIC, "sphere on a flat, R = 1 um, theta = 30 deg, RH 0.4: numerical meniscus",
                       "4 pi R gamma cos(theta) (r_K << R; Fisher and Israelachvili 1981)",
                       round(capillary_force_sphere(radius, theta) * 1e9, 3), round(numeric * 1e9, 2), "nN", rtol=0.02,
                       command=COMMAND, note="0.5 nm grid: the wetted disc is counted element by element"))
    radius_c, theta_c = 10e-6, math.radians(20)
    dxc = 0.05e-9
    xc = (np.arange(40001) - 20000) * dxc
    numeric_c = capillary_force_from_gap(xc**2 / (2 * radius_c), dxc, kelvin_radius(0.5), theta_c)
    out.append(compare(TOPIC, "cylinder on a flat per unit length, R = 10 um, theta = 20 deg, RH 0.5",
                       "2 gamma sqrt(2 R h_c) / r_K (Butt and Kappl 2009)",
                       round(capillary_force_cylinder(radius_c, kelvin_radius(0.5), theta_c), 3), round(numeric_c, 2),
                       "N/m", rtol=2e-3, command=COMMAND))
    dry = capillary_force_cylinder(radius_c, kelvin_radius(0.0), theta_c)
    out.append(ValidationRow(TOPIC, "no capillary force in dry air (RH -> 0)", "limit", 0.0, dry, "N/m", "exact",
                             dry == 0.0, COMMAND))
    hydrophobic = condensation_height(kelvin_radius(0.9), math.radians(112))
    out.append(ValidationRow(TOPIC, "no meniscus between OTS-coated surfaces (theta = 112 deg >= 90 deg)", "limit",
                             0.0, hydrophobic, "m", "exact", hydrophobic == 0.0, COMMAND))
    return out
