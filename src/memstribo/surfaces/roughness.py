"""Roughness of measured and synthetic surfaces (thesis 3.4.1, 4.2; MODEL §1).

The names below live in four modules, re-exported here: :mod:`memstribo.surfaces.profile` (the profile,
levelling, PCHIP resampling), :mod:`memstribo.surfaces.statistics` (ISO 4287 / 25178 parameters and the
statistics records), :mod:`memstribo.surfaces.asperity_widths` (asperity widths at a level, 3-26) and
:mod:`memstribo.surfaces.synthesis` (synthetic profiles, rows across the face width).

A :class:`Profile` is one line scan ``z(x)`` in metres. This module levels profiles and
maps (least-squares line or plane), resamples them with shape-preserving PCHIP (MATLAB's
``pchip``), computes the ISO 4287 profile parameters and the ISO 25178 areal ones, the
Abbott-Firestone curve and the mean width of the asperities cut at a level (3-26), and
makes seeded synthetic Gaussian profiles with an exact Rq and rms slope.

Conventions
-----------
- Heights are taken about the mean line (the mean of the heights given); the functions
  that compute one parameter do not level: :func:`level_profile` first, or call
  :func:`profile_statistics`, which levels.
- The local slope is the first difference ``S_i = (z[i+1] - z[i]) / (x[i+1] - x[i])``, so
  that a profile of n points has n - 1 slopes and Eq. (4-6) in [1] reads
  ``rms_slope = sqrt(sum(S_i**2) / (n - 1))``.
- Rz is the maximum height Rp + Rv of the whole profile (ISO 4287 would average it over
  sampling lengths; the thesis uses none).

References
----------
.. [1] N. S. T. Almuramady, PhD thesis (see :data:`memstribo.references.REFERENCES`).
.. [2] ISO 4287:1997; ISO 25178-2:2012.
.. [3] F. N. Fritsch, R. E. Carlson, SIAM J. Numer. Anal. 17 (1980) 238-246.
"""

from __future__ import annotations

from memstribo.surfaces.asperity_widths import asperity_widths, mean_asperity_width
from memstribo.surfaces.profile import UNIFORM_RTOL, Profile, level_plane, level_profile, resample_pchip  # noqa: F401
from memstribo.surfaces.statistics import (ArealStatistics, LineScanStatistics, ProfileStatistics, Ra, Rku, Rp, Rq,
                                           Rsk, Rv, Rz, areal_statistics, arithmetic_mean_height, bearing_area_curve,
                                           kurtosis, line_scan_statistics, max_height, max_peak_height,
                                           max_valley_depth, profile_statistics, rms_height, rms_slope,
                                           rms_wavelength, skewness)
from memstribo.surfaces.synthesis import (RowRoughness, complete_line, default_profile, power_spectrum_1d,
                                          row_roughness, synthesize_like, synthetic_profile)

__all__ = [
    "Profile",
    "ProfileStatistics",
    "ArealStatistics",
    "LineScanStatistics",
    "level_profile",
    "level_plane",
    "resample_pchip",
    "arithmetic_mean_height",
    "rms_height",
    "skewness",
    "kurtosis",
    "max_peak_height",
    "max_valley_depth",
    "max_height",
    "rms_slope",
    "rms_wavelength",
    "bearing_area_curve",
    "asperity_widths",
    "mean_asperity_width",
    "profile_statistics",
    "areal_statistics",
    "line_scan_statistics",
    "synthetic_profile",
    "power_spectrum_1d",
    "synthesize_like",
    "complete_line",
    "RowRoughness",
    "row_roughness",
    "default_profile",
    "Ra",
    "Rq",
    "Rsk",
    "Rku",
    "Rp",
    "Rv",
    "Rz",
]
