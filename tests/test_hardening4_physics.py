"""Issue #41 item 3 (physics): the R = 1 mm adhesive pull-off against its closed form, the hardness cap of the
surface (3D) contact, and a measured map shorter than the flank travel used where it reaches.

Each test fails on the code before the fix (numbers in the docstrings)."""

from __future__ import annotations

import numpy as np
import pytest

from memstribo.physics.adhesive_contact import line_contact_pull_off
from memstribo.physics.closed_form import jkr_line_pull_off_load, maugis_dugdale_line_pull_off

# silicon teeth (docs/model.md §2, §3): E* = 85 GPa, w = A/(12 pi D0^2), sigma0 = 16 w/(9 sqrt 3 D0)
E_STAR, W, SIGMA0 = 85e9, 0.445, 1.78e9


# ----------------------------------------------------------------------------- the pull-off at R = 1 mm


def test_pull_off_at_one_millimetre_matches_the_closed_forms():
    """R = 1 mm, lambda = 16.5: the Dugdale zone (d = 9.3 nm) is narrower than two elements of 18.4 nm, so the
    solve widens it at the same w. With the contact-only part of sigma0 on the edge element (a strength criterion
    that depends on the element's width) the pull-off was 550.2 N/m here (495.8 N/m on the CLI's 2048 elements)
    with converged=True; the closed forms (Maugis-Dugdale, Baney & Hui 1997; JKR line contact) say 446.9 N/m."""
    radius = 1e-3
    result = line_contact_pull_off(radius, E_STAR, W, SIGMA0, points=1024)
    reference, width = maugis_dugdale_line_pull_off(radius, E_STAR, W, SIGMA0)
    jkr = -float(jkr_line_pull_off_load(radius, E_STAR, W))
    assert result.converged, result.message
    assert result.pull_off_line_load == pytest.approx(-reference, rel=0.05)
    assert result.pull_off_line_load == pytest.approx(jkr, rel=0.05)
    assert result.pull_off_half_width == pytest.approx(width, rel=0.05)
    assert "does not resolve the Dugdale zone" in result.message


def test_pull_off_on_a_grid_too_coarse_for_the_law_is_flagged():
    """64 elements over 4 µm at R = 10 µm: the zone widened to two 62.5 nm elements has sigma = 0.27 sigma0 and
    moves the closed-form pull-off by 3 %: not converged, and the message says why (before: converged=True)."""
    result = line_contact_pull_off(10e-6, E_STAR, W, SIGMA0, points=64, length=4e-6)
    assert not result.converged
    assert "more than 1 %" in result.message
    # a grid that resolves the zone is untouched by the check
    fine = line_contact_pull_off(10e-6, E_STAR, W, SIGMA0, points=1024)
    assert fine.converged and "does not resolve" not in fine.message

