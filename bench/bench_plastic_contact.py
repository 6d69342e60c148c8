"""Check: the line contact capped at the hardness against a peer (ContactMechanics), on the shipped line scan.

The periodic problem: a flat elastic body (E* = 90 GPa) pressed on the first 512 points of
data/afm/si_profile_linescan.txt (dx = 1.95 nm) at nominal pressures of 1 and 3 GPa, the pressure
capped at H = 12 GPa (silicon's hardness). memstribo's capped solve
(:func:`memstribo.physics.contact.solve_line_contact_capped`) against ContactMechanics'
``constrained_conjugate_gradients`` with ``hardness`` (its plastic system; the hardness in force
units per element, H dx). Both are checked independently (numpy FFT, not either solver's operator)
for the conditions of the elastic-perfectly-plastic contact: the gap closed on the elastic contact
set, closed or penetrating on the plastic set, open outside.

Usage (ContactMechanics in a separate environment, never a dependency of memstribo)::

    python3 -m venv /work/peers && /work/peers/bin/pip install -r bench/requirements-peers.txt
    PYTHONPATH=src /work/peers/bin/python bench/bench_plastic_contact.py

Without ContactMechanics only memstribo's side and its independent check run. The numbers are in
docs/mesh.md ("Real scans: the pressure capped at the hardness").
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

MODULUS = 90e9
HARDNESS = 12e9
POINTS = 512


def problem():
    """(gap h [m], dx [m]) of the periodic check: the line scan's first 512 points as a rigid indenter."""
    data = np.loadtxt(Path(__file__).resolve().parent.parent / "data/afm/si_profile_linescan.txt")
    z = data[:POINTS, 1]
    h = -(z - z.mean())
    return h - h.min(), float(data[1, 0] - data[0, 0])


def conditions(h, dx, pressure):
    """Independent check of the capped contact (numpy.fft periodic half-plane): the worst violation / ptp(h)."""
    n = h.size
    q = 2 * np.pi * np.fft.rfftfreq(n, dx)
    pk = np.fft.rfft(pressure)
    uk = np.zeros_like(pk)
    uk[1:] = 2 * pk[1:] / (MODULUS * q[1:])
    total = h + np.fft.irfft(uk, n)
    plastic = pressure >= HARDNESS * (1 - 1e-9)
    elastic = (pressure > 0) & ~plastic
    gap = total - (total[elastic].mean() if elastic.any() else total[plastic].max())
    worst = max(np.abs(gap[elastic]).max(initial=0), gap[plastic].max(initial=0), -gap[pressure <= 0].min(initial=0))
    return float(worst / np.ptp(h)), int(elastic.sum()), int(plastic.sum())


def ours(h, dx, mean_pressure):
    from memstribo.physics.contact import solve_line_contact_capped

    start = time.perf_counter()
    result = solve_line_contact_capped(h, dx, MODULUS, hardness=HARDNESS, load=mean_pressure * h.size * dx,
                                       periodic=True, tolerance=1e-10)
    return result.solution.pressure, time.perf_counter() - start, result.updates


def contactmechanics(h, dx, mean_pressure):
    from ContactMechanics import PeriodicFFTElasticHalfSpace
    from ContactMechanics.Optimization import constrained_conjugate_gradients
    from SurfaceTopography import UniformLineScan

    n = h.size
    substrate = PeriodicFFTElasticHalfSpace((n,), MODULUS, physical_sizes=(n * dx,))
    start = time.perf_counter()
    result = constrained_conjugate_gradients(substrate, UniformLineScan(-h, n * dx, periodic=True),
                                             hardness=HARDNESS * dx, external_force=mean_pressure * n * dx,
                                             pentol=1e-10 * np.ptp(h), maxiter=100000)
    pressure = np.asarray(result.jac).ravel() / dx
    return (-pressure if pressure.sum() < 0 else pressure), time.perf_counter() - start


def main():
    h, dx = problem()
    try:
        import ContactMechanics  # noqa: F401
        peer = True
    except ImportError:
        peer = False
        print("ContactMechanics is not installed: memstribo's side only")
    for mean_pressure in (1e9, 3e9):
        p, elapsed, updates = ours(h, dx, mean_pressure)
        worst, elastic, plastic = conditions(h, dx, p)
        line = (f"p_nominal {mean_pressure / 1e9:g} GPa: memstribo {elapsed * 1e3:.0f} ms, {updates} plastic-set "
                f"updates, {elastic} elastic + {plastic} plastic contact elements, conditions {worst:.1e}")
        if peer:
            q, peer_time = contactmechanics(h, dx, mean_pressure)
            peer_worst, peer_elastic, peer_plastic = conditions(h, dx, q)
            line += (f"; ContactMechanics {peer_time * 1e3:.0f} ms, {peer_elastic} + {peer_plastic}, conditions "
                     f"{peer_worst:.1e}; pressure difference {np.linalg.norm(p - q) / np.linalg.norm(p):.1e} (L2, "
                     f"relative), {int(np.count_nonzero((p > 0) != (q > 0)))} contact and "
                     f"{int(np.count_nonzero((p >= HARDNESS * (1 - 1e-9)) != (q >= HARDNESS * (1 - 1e-6))))} plastic "
                     "elements differ")
        print(line)


if __name__ == "__main__":
    main()
