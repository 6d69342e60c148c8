"""Speed benchmark: memstribo's surface (3D) contact solver against Tamaas and ContactMechanics.

Identical periodic self-affine rough surfaces (n x n) are solved at the same mean pressure by
each solver in one process; the script reports wall times, iteration counts, contact
fractions, the largest pressure difference to memstribo (relative to its peak pressure) and
an independent complementarity (KKT) residual of every pressure field, computed here with
numpy.fft (not with memstribo's operator) in the same way for all. It is a benchmark, not a
test: run it in an environment that has the peers (bench/requirements-peers.txt)::

    python3.11 -m venv /work/bench-venv-surface
    /work/bench-venv-surface/bin/pip install -r bench/requirements-peers.txt
    OMP_NUM_THREADS=1 /work/bench-venv-surface/bin/python bench/bench_surface_contact.py --sizes 8 9 10 11
    /work/bench-venv-surface/bin/python bench/bench_surface_contact.py --memory 11   # peak RSS of memstribo alone

memstribo is imported from ``src/`` (numpy and scipy only for the solver). All solvers run on
one thread (scipy.fft workers=1; OMP/FFTW threads 1).

Tolerances: memstribo stops when the largest gap error on the contact set (or penetration
outside it) is below ``tol * ptp(h)``; ContactMechanics gets ``pentol = tol * ptp(h)``;
Tamaas gets ``tol`` in its own relative measure. The KKT column shows what each reached on
the same measure.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import numpy as np  # noqa: E402

MODULUS = 100e9  # contact modulus E* [Pa]
STEP = 1e-9  # grid step [m], fixed: the domain grows with n
RMS_HEIGHT = 1e-9  # [m]
HURST = 0.8


def self_affine_surface(n, seed=0):
    """Periodic isotropic self-affine heights [m], shape (n, n): PSD ~ q^-(2+2H) from the domain size to 2 steps."""
    rng = np.random.default_rng(seed)
    qy = np.fft.fftfreq(n)[:, None]
    qx = np.fft.rfftfreq(n)[None, :]
    q = np.hypot(qx, qy)
    amplitude = np.zeros_like(q)
    amplitude[q > 0] = q[q > 0] ** (-1.0 - HURST)
    spectrum = amplitude * (rng.normal(size=q.shape) + 1j * rng.normal(size=q.shape))
    z = np.fft.irfft2(spectrum, s=(n, n))
    return z * (RMS_HEIGHT / z.std())


def problem(exponent, seed=0):
    """Gap h [m] (n x n), grid step [m] and mean pressure [Pa] at n = 2^exponent."""
    n = 2**exponent
    z = self_affine_surface(n, seed)
    h = z.max() - z
    slope = np.sqrt(np.mean(np.diff(z, axis=1) ** 2) + np.mean(np.diff(z, axis=0) ** 2)) / STEP
    mean_pressure = 0.06 * MODULUS * slope  # ~10 % contact
    return h, STEP, mean_pressure


def run_memstribo(h, dx, mean_pressure, tol, periodic=True):
    from memstribo.physics.surface_contact import solve_surface_contact

    start = time.perf_counter()
    sol = solve_surface_contact(h, dx, dx, MODULUS, mean_pressure=mean_pressure, periodic=periodic, tolerance=tol,
                                max_iterations=20000)
    return dict(time=time.perf_counter() - start, iterations=f"{sol.iterations}+{sol.coarse_iterations}",
                pressure=sol.pressure, converged=sol.converged)


def run_tamaas(h, dx, mean_pressure, tol):
    import tamaas as tm

    from bench_contact import solve_tamaas_quietly  # the same capture of Tamaas' iteration log

    n = h.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [n * dx, n * dx], [n, n])
    model.E, model.nu = MODULUS, 0.0  # E* = E / (1 - nu^2)
    surface = np.ascontiguousarray(-h)  # Tamaas: heights of the rigid surface
    solver = tm.PolonskyKeerRey(model, surface, tol)
    solver.max_iter = 20000
    elapsed, iterations = solve_tamaas_quietly(solver, mean_pressure)
    pressure = np.array(model.traction).reshape(n, n)
    return dict(time=elapsed, iterations=iterations, pressure=pressure, converged=None)


def run_contactmechanics(h, dx, mean_pressure, tol):
    from ContactMechanics import PeriodicFFTElasticHalfSpace
    from ContactMechanics.Optimization import constrained_conjugate_gradients
    from SurfaceTopography import Topography

    n = h.shape[0]
    size = (n * dx, n * dx)
    substrate = PeriodicFFTElasticHalfSpace((n, n), MODULUS, physical_sizes=size)
    topography = Topography(-h, size, periodic=True)
    start = time.perf_counter()
    result = constrained_conjugate_gradients(substrate, topography, external_force=mean_pressure * size[0] * size[1],
                                             pentol=tol * np.ptp(h), maxiter=20000)
    elapsed = time.perf_counter() - start
    pressure = np.asarray(result.jac).reshape(n, n) / (dx * dx)
    if pressure.sum() < 0:
        pressure = -pressure
    return dict(time=elapsed, iterations=int(result.nit), pressure=pressure, converged=bool(result.success))


def kkt_residual(h, dx, pressure):
    """Independent check (numpy.fft): max gap error on the contact set or penetration outside it, / ptp(h)."""
    n = h.shape[0]
    qy = 2 * np.pi * np.fft.fftfreq(n, dx)[:, None]
    qx = 2 * np.pi * np.fft.rfftfreq(n, dx)[None, :]
    q = np.hypot(qx, qy)
    green = np.zeros_like(q)
    green[q > 0] = 2.0 / (MODULUS * q[q > 0])
    g = h + np.fft.irfft2(np.fft.rfft2(pressure) * green, s=h.shape)
    contact = pressure > 0
    gap = g - g[contact].mean()
    error = max(np.abs(gap[contact]).max(), np.maximum(-gap[~contact], 0).max(initial=0.0))
    return float(error / np.ptp(h))


SOLVERS = {"memstribo": run_memstribo, "tamaas": run_tamaas, "contactmechanics": run_contactmechanics}


def memory(exponent, tol, periodic=True):
    """Peak resident memory [MiB] of a fresh process that builds the problem and solves it with memstribo only."""
    code = (f"import sys, resource; sys.path.insert(0, {str(Path(__file__).resolve().parent)!r}); "
            f"import bench_surface_contact as b; import numpy as np; h, dx, p = b.problem({exponent}); "
            "base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss; "
            f"r = b.run_memstribo(h, dx, p, {tol!r}, {periodic!r}); "
            "print(base / 1024, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, r['time'], r['iterations'])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    return float(out[0]), float(out[1]), float(out[2]), out[3]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[8, 9, 10], help="exponents k of n = 2^k (n x n grid)")
    parser.add_argument("--solvers", nargs="+", default=list(SOLVERS), choices=list(SOLVERS))
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--repeat", type=int, default=1, help="best of this many runs")
    parser.add_argument("--json", help="append the rows to this JSON-lines file")
    parser.add_argument("--memory", type=int, nargs="+", help="only: peak RSS of memstribo alone at these exponents")
    parser.add_argument("--free-boundary", action="store_true",
                        help="with --memory: the same surface on the free-boundary half-space (memstribo only)")
    args = parser.parse_args(argv)
    if args.memory:
        for exponent in args.memory:
            base, peak, elapsed, iterations = memory(exponent, args.tolerance, not args.free_boundary)
            print(f"n = {2**exponent}^2{' (free boundary)' if args.free_boundary else ''}: peak RSS {peak:.0f} MiB (problem set up: {base:.0f} MiB); "
                  f"solve {elapsed:.3g} s, iterations {iterations}", flush=True)
        return

    import scipy

    print(f"# numpy {np.__version__}, scipy {scipy.__version__} (scipy.fft workers=1); "
          f"OMP_NUM_THREADS={os.environ['OMP_NUM_THREADS']}; tolerance {args.tolerance:g}; periodic self-affine "
          f"H={HURST}, rough to 2 grid steps", flush=True)
    print(f"{'n':>6} {'solver':>17} {'time [s]':>10} {'iter':>9} {'contact':>8} {'max|dp|/max p':>14} "
          f"{'KKT residual':>13}", flush=True)
    for exponent in args.sizes:
        h, dx, mean_pressure = problem(exponent)
        results = {}
        for name in args.solvers:
            best = None
            for _ in range(args.repeat):
                result = SOLVERS[name](h, dx, mean_pressure, args.tolerance)
                if best is None or result["time"] < best["time"]:
                    best = result
            results[name] = best
        base = results[args.solvers[0]]["pressure"]
        for name, result in results.items():
            p = result["pressure"]
            row = dict(n=2**exponent, solver=name, time=result["time"], iterations=result["iterations"],
                       contact_fraction=float(np.mean(p > 0)),
                       difference=float(np.abs(p - base).max() / base.max()),
                       residual=kkt_residual(h, dx, p), mean_pressure=mean_pressure, converged=result["converged"])
            print(f"{row['n']:>6} {name:>17} {row['time']:>10.4g} {str(row['iterations']):>9} "
                  f"{row['contact_fraction']:>8.4f} {row['difference']:>14.2e} {row['residual']:>13.2e}", flush=True)
            if args.json:
                with open(args.json, "a") as handle:
                    handle.write(json.dumps(row) + "\n")
        times = {name: r["time"] for name, r in results.items()}
        if "memstribo" in times and len(times) > 1:
            fastest = min(t for name, t in times.items() if name != "memstribo")
            print(f"{'':>6} {'speed-up vs fastest peer':>30}: {fastest / times['memstribo']:.2f}x", flush=True)


if __name__ == "__main__":
    main()
