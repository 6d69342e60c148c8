"""Layer 1, surfaces: measured and synthetic roughness.

``readers`` turns instrument files into profiles and maps (SurfaceTopography first, plain text as
the fallback); ``roughness`` levels and resamples them, computes ISO 4287 statistics and power
spectra, and synthesises independent lines with the same spectrum (thesis 3.4.1, 4.2).
Nothing here knows about materials, contact or gears.
"""
