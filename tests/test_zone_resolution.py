"""The Maugis-Dugdale zone on a grid that does not resolve it (issue #25): the same work of adhesion, a zone two
elements wide (memstribo.physics.contact.subgrid)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from memstribo.api import parameter_set
from memstribo.physics.closed_form import maugis_dugdale_line_tension
from memstribo.physics.contact import settings as contact_settings
from memstribo.physics.contact import solve_line_contact
from memstribo.physics.contact.subgrid import resolved_zone, resolved_zones, zone_width

E_STAR, SIGMA0, H0 = 85e9, 1.785e9, 0.2494e-9


def test_zone_width_is_the_small_scale_dugdale_strip():
    """d = pi K^2 / (8 sigma0^2) with K^2 = E' w, E' = 2 E* (identical materials), w = sigma0 h0."""
    w = SIGMA0 * H0
    assert zone_width(E_STAR, SIGMA0, H0) == pytest.approx(math.pi * (2 * E_STAR * w) / (8 * SIGMA0**2), rel=1e-12)


def test_the_resolved_law_keeps_w_and_spans_the_elements_asked_for():
    d = zone_width(E_STAR, SIGMA0, H0)
    assert resolved_zone(d / 2, E_STAR, SIGMA0, H0, 2) == (SIGMA0, H0)  # resolved: unchanged
    assert resolved_zones(d / 2, E_STAR, SIGMA0, H0, 2, 1e-6) == (None, H0)
    assert resolved_zone(24.8e-9, E_STAR, SIGMA0, H0, 0) == (SIGMA0, H0)  # off
    sigma, h = resolved_zone(24.8e-9, E_STAR, SIGMA0, H0, 2)
    assert sigma < SIGMA0 and sigma * h == pytest.approx(SIGMA0 * H0, rel=1e-12)
    assert zone_width(E_STAR, sigma, h) == pytest.approx(2 * 24.8e-9, rel=1e-12)
    zones, reach = resolved_zones(24.8e-9, E_STAR, SIGMA0, H0, 2, 1e-6)
    assert zones == ((sigma, h), (SIGMA0 - sigma, 1e-6 * H0)) and reach == h


def _torque_contact():
    """(line load [N/m], R [m], E* [Pa], w [J/m^2], sigma0 [Pa]) of smooth teeth at the pitch point, torque case."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).parent))
    from test_convergence import _torque_contact as contact

    from memstribo.parameters import THESIS_VDW

    # the thesis's Hamaker constant (w = 0.445 J/m^2, d = 9.3 nm): the unresolved zone this module is about; at the
    # Lifshitz default (issue 38) the zone is 51 nm wide and the default grid resolves it on smooth teeth
    return contact(parameter_set().updated(THESIS_VDW))


def _tension(dx, offset, work_factor=1.0, elements=None):
    """The solve's whole tension [N/m] on smooth teeth at the torque's load (as test_convergence._smooth_solve)."""
    load, radius, modulus, w, sigma0 = _torque_contact()
    sigma0, w = sigma0 * work_factor, w * work_factor  # sigma0 follows w (nanoscale_constants), h0 stays
    settings = contact_settings.DEFAULTS
    if elements is not None:
        settings = dataclasses.replace(settings, zone_elements=elements)
    n = int(round(1.3e-6 / dx))
    x = (np.arange(n) - 0.5 * (n - 1) + offset) * dx
    solution = solve_line_contact(x**2 / (2 * radius), dx, modulus, load=load, cohesive_stress=sigma0,
                                  cohesive_range=w / sigma0, settings=settings)
    assert solution.converged, solution.message
    closed = maugis_dugdale_line_tension(load, radius, modulus, w, sigma0)[0]
    return float(np.maximum(-solution.pressure, 0.0).sum() * dx), closed


@pytest.mark.parametrize("elements, within", [(None, True), (0, False)])
def test_the_default_grid_carries_the_closed_form_tension(elements, within):
    """Smooth teeth at the torque's load on the meshing cycle's default 24.8 nm grid (the zone is 7.6 nm wide): the
    tension, averaged over four positions of the grid, is Baney & Hui's within 5 % (46.8 N/m), and twice w raises
    it as the closed form does (78.3 N/m). Without the resolved zone (``zone_elements = 0``) it was 27.8 N/m at both
    w: the zone fell inside the element next to the contact's edge."""
    offsets = (0.0, 0.25, 0.5, 0.75)
    single = [_tension(24.8e-9, offset, elements=elements) for offset in offsets]
    double = [_tension(24.8e-9, offset, 2.0, elements=elements) for offset in offsets]
    mean_single, closed_single = np.mean([t for t, _ in single]), single[0][1]
    mean_double, closed_double = np.mean([t for t, _ in double]), double[0][1]
    agrees = bool(abs(mean_single / closed_single - 1) < 0.05 and abs(mean_double / closed_double - 1) < 0.05
              and mean_double > 1.5 * mean_single)
    assert agrees is within, (mean_single, closed_single, mean_double, closed_double)


def test_fine_grids_are_left_as_they_are():
    """On a grid that resolves the zone (1.55 nm, d = 9.3 nm) the solve is the one without the closure."""
    assert _tension(1.55e-9, 0.3) == _tension(1.55e-9, 0.3, elements=0)


def test_the_adhesion_force_on_the_shipped_scan_converges_or_is_flagged():
    """Issue 38 item 5: on data/afm/si_profile_linescan.txt the adhesion force changes < 5 % on the last grid halving,
    or the cycle says it is not resolved (``adhesion_force_resolved`` false and a warning); the margin is checked
    apart from it. Measured (docs/contact.md, "Where the sub-grid zone holds"): 31 %, 65 %, 52 % on the halvings
    48 -> 384 elements across 2a at the Lifshitz Hamaker constant, while the margin moves 3.5 %, 0.42 %, 0.37 %."""
    from pathlib import Path

    from memstribo.simulations.mesh.convergence import ADHESION_TOLERANCE, refined_cycle

    scan = Path(__file__).resolve().parent.parent / "data" / "afm" / "si_profile_linescan.txt"
    params = parameter_set().updated({"mesh_step_refinements": 0, "mesh_grid_refinements": 1})
    dataset, summary = refined_cycle(params, scan, steps=11)
    change = summary["grid_change_adhesion"]
    assert change is not None and np.isfinite(change)
    assert summary["adhesion_force_resolved"] is bool(change < ADHESION_TOLERANCE)
    flagged = [w for w in summary.get("warnings", []) if "adhesion force is not resolved" in w]
    assert bool(flagged) is (not summary["adhesion_force_resolved"])
    # the scan's nano-asperities are DMT-like at the default constants: the zone (51 nm) is wider than the
    # grid's asperity contacts, so the force is not resolved here (the flag, not a silent number)
    assert summary["adhesion_force_resolved"] is False and change > ADHESION_TOLERANCE


def test_the_zone_is_wider_at_the_lifshitz_hamaker_constant():
    """The small-scale Dugdale strip d = pi E' w / (8 sigma0^2): 51 nm at A = 2e-19 J against 9.3 nm at the thesis's
    1.1e-18 J (sigma0 = 16 w / (9 sqrt(3) D0) scales with w, so d scales as 1 / w)."""
    from memstribo.parameters import THESIS_VDW
    from memstribo.physics.adhesion import nanoscale_constants

    widths = []
    for params in (parameter_set(), parameter_set().updated(THESIS_VDW)):
        c = nanoscale_constants(params)
        widths.append(zone_width(c.contact_modulus, c.maugis_stress, c.maugis_range))
    assert widths[0] == pytest.approx(51.3e-9, rel=2e-3) and widths[1] == pytest.approx(9.33e-9, rel=2e-3)
    assert widths[0] / widths[1] == pytest.approx(1.1e-18 / 2.0e-19, rel=1e-9)
