"""Figure of docs/interface.md: vdW energy and attraction per area versus the local gap (MODEL 7c).

Writes ``interface_vdw.png`` into ``examples/output/interface_figure/`` (or the folder given as the first
argument; the documentation's copy is made with ``docs/figures``)::

    python examples/interface_figure.py [OUT_DIR]
    python examples/interface_figure.py docs/figures      # the figure of docs/interface.md
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np


def main(out_dir: str | None = None) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from memstribo.materials.pair import work_of_adhesion
    from memstribo.physics.adhesion import lennard_jones_surface_stress, maugis_range, maugis_stress
    from memstribo.simulations.mesh import vdw_gap_factor
    from memstribo.parameters import get_parameter_values

    params = get_parameter_values()
    d0, a_h, cutoff = params["cutoff_distance"], params["hamaker_constant"], params["vdw_cutoff"]
    w = float(work_of_adhesion(a_h, d0))
    sigma0 = float(maugis_stress(w, d0))
    h0 = float(maugis_range(w, sigma0))
    gap = np.linspace(0.0, 8e-9, 801)
    factor = vdw_gap_factor(gap, d0, cutoff)
    attraction = a_h / (6 * np.pi * np.maximum(gap, d0) ** 3) * (gap < cutoff)
    figure, (left, right) = plt.subplots(1, 2, figsize=(9, 3.6))
    left.plot(gap * 1e9, factor * w, label="gap model: w (D0 / max(D, D0))^2, cut at vdw_cutoff")
    left.plot(gap * 1e9, np.where(gap <= params["adhesive_height"], w, 0.0), "--",
              label="thesis model: full w inside the 5 nm band")
    left.set_xlabel("local gap D [nm]")
    left.set_ylabel("vdW energy per area [J/m^2]")
    left.legend(fontsize=7)
    right.semilogy(gap * 1e9, np.maximum(attraction, 1e3) / 1e6, label="Hamaker A / (6 pi max(D, D0)^3)")
    lj = np.abs(lennard_jones_surface_stress(gap + d0, w, d0))
    right.semilogy(gap * 1e9, np.maximum(lj, 1e3) / 1e6, ":", label="Lennard-Jones surfaces (3-17), at D0 + D")
    right.semilogy(gap * 1e9, np.where(gap <= h0, sigma0, 1e3) / 1e6, "--",
                   label=f"Maugis-Dugdale: {sigma0 / 1e9:.2g} GPa up to h0 = {h0 * 1e9:.3g} nm")
    right.set_xlabel("local gap D [nm]")
    right.set_ylabel("attraction [MPa]")
    right.set_ylim(1e-1, 2e4)
    right.legend(fontsize=7)
    figure.tight_layout()
    folder = Path(out_dir) if out_dir else Path(__file__).resolve().parent / "output" / "interface_figure"
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "interface_vdw.png"
    figure.savefig(path, dpi=120)
    plt.close(figure)
    return path


if __name__ == "__main__":
    print(main(sys.argv[1] if len(sys.argv) > 1 else None))
