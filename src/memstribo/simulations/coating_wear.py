"""The meshing cycle of coated teeth over their wear state Omega, and the calibration of a coating's vdW bond
energy (thesis 5.4, 5.5.3): simulations built on :mod:`memstribo.physics.coating` and
:mod:`memstribo.simulations.mesh`."""

from __future__ import annotations

import numpy as np

from memstribo.errors import InputError
from memstribo.physics.coating import Coating, check_wear, get_coating
from memstribo.quantities import attrs as quantity_attrs
from memstribo.references import cites

__all__ = ["SWEEP_VARIABLES", "wear_sweep", "calibrate_vdw_bond_energy"]

#: Variables of :func:`wear_sweep`'s dataset (and keys of ``memstribo coating --json``): the meshing cycle's
#: summary values (:func:`memstribo.simulations.mesh.summarize`) under the same names; units and meanings in
#: :mod:`memstribo.quantities`.
SWEEP_VARIABLES = ("cof_mean", "cof_chemical", "cof_vdw", "cof_elastic", "resisting_force_max", "tangential_force",
                   "stiction", "stiction_margin")


@cites("thesis", "model")
def wear_sweep(params, coating: Coating | str | None, wears, *, roughness=None, steps: int | None = None,
               progress: bool = False, known=None):
    """COF, its split, friction force and stiction margin for each worn fraction Omega (5.5.3).

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Model parameters (gear, load, roughness, nanoblocks).
    coating : Coating, str or None
        The gear's coating (``None``: bare silicon, all Omega give the bare result).
    wears : sequence of float
        Worn fractions Omega of the gear's coating, each from 0 to 1 [-].
    roughness : Profile, optional
        Roughness of the flanks; ``None`` uses the mesh's default.
    steps : int, optional
        Steps of each meshing-cycle simulation (the mesh's default if None).
    progress : bool
        Show a progress bar over the wear states on stderr.
    known : mapping of float to xarray.Dataset, optional
        Meshing cycles already computed with exactly these arguments (``simulate_mesh(params,
        roughness, steps=steps, coating=coating, wear=Omega)``), by Omega: used instead of
        computing them again (the same numbers; a design map passes its point's first cycle).

    Returns
    -------
    xarray.Dataset
        Over dimension ``wear``: the variables of :data:`SWEEP_VARIABLES` with ``units`` and
        ``long_name`` attributes; the per-wear values are those of ``mesh.summarize``.

    Notes
    -----
    The pinion's coating is fully worn and Omega of the gear's (thesis 5.5.3), so Omega = 1
    equals the bare mesh result. Thesis Figure 5-28: COF 0.185 (Omega = 0), 0.32 (0.2),
    about 0.75 (0.8), 0.84 (1).
    """
    import xarray as xr

    from memstribo.simulations import mesh

    if isinstance(coating, str):
        coating = get_coating(coating, params)
    omega = np.atleast_1d(check_wear(wears))
    rows = {key: np.empty(omega.size) for key in SWEEP_VARIABLES}
    states = enumerate(omega)
    if progress:
        import sys

        from tqdm.auto import tqdm

        states = tqdm(states, total=omega.size, desc="wear states", unit="cycle", file=sys.stderr, leave=False)
    known = {float(w): dataset for w, dataset in (known or {}).items()}
    from memstribo.simulations.mesh.solve_cache import solves_kept

    with solves_kept():  # a row's contact solve that another wear state repeats is taken, the same bits (issue 40)
        for i, w in states:  # one meshing-cycle simulation per wear state
            dataset = known.get(float(w))
            if dataset is None:
                dataset = mesh.simulate_mesh(params, roughness, steps=steps, coating=coating, wear=float(w))
            summary = mesh.summarize(dataset)
            for key in SWEEP_VARIABLES:
                rows[key][i] = float(summary[key])
    sweep = xr.Dataset(
        {key: ("wear", rows[key], quantity_attrs(key)) for key in SWEEP_VARIABLES},
        coords={"wear": ("wear", omega, quantity_attrs("wear"))},
        attrs={"coating": "bare silicon" if coating is None else coating.name},
    )
    return sweep



@cites("thesis", "model")
def calibrate_vdw_bond_energy(params, coating: Coating | str, target_cof: float = 0.185, *, roughness=None,
                              steps: int | None = None, rtol: float = 1e-3,
                              max_runs: int = 6) -> tuple[Coating, dict]:
    """Scale the coating's U_vdW so that the fully coated pair (Omega = 0) has COF ``target_cof``.

    Parameters
    ----------
    params : memstribo.parameters.Parameters
        Model parameters (the reference conditions of thesis 5.4: 25 uN, the default gear).
    coating : Coating or str
        Coating to calibrate.
    target_cof : float
        COF of the fully coated pair [-] (thesis 5.5.3: 0.185).
    roughness, steps
        As for :func:`wear_sweep`.
    rtol : float
        Relative tolerance on the COF [-].
    max_runs : int
        Meshing-cycle runs allowed.

    Returns
    -------
    (Coating, dict)
        The calibrated coating and a record: ``vdw_bond_energy_before``, ``..._after`` [J],
        ``cof_before``, ``cof_after`` [-], ``runs``, ``converged``.

    Notes
    -----
    With the coating U_chem = 0, so COF = cof_vdw + cof_elastic, and cof_vdw is proportional to
    U_vdW at a fixed contact; the contact itself barely depends on U_vdW (the vdW adhesion force
    does, slightly), so U_vdW <- U_vdW (target - cof_elastic) / (COF - cof_elastic) converges in
    a few meshing-cycle runs (at most ``max_runs``; tolerance ``rtol`` on the cycle's mean COF).
    Raises :class:`InputError` if cof_elastic alone reaches the target.
    """
    if isinstance(coating, str):
        coating = get_coating(coating, params)
    if not (0 < target_cof < 10):
        raise InputError(f"target_cof must be a COF between 0 and 10, got {target_cof!r}.")
    current = coating
    history = []
    from memstribo.simulations.mesh.solve_cache import solves_kept

    with solves_kept():  # each run changes U_vdW only: its rows' contact solves are the first run's (same bits)
        return _calibrate_runs(params, roughness, steps, current, target_cof, rtol, max_runs, history)


def _calibrate_runs(params, roughness, steps, current, target_cof, rtol, max_runs, history):
    """The runs of :func:`calibrate_vdw_bond_energy`."""
    from memstribo.simulations import mesh

    for _ in range(max_runs):
        summary = mesh.summarize(mesh.simulate_mesh(params, roughness, steps=steps, coating=current, wear=0.0))
        cof, cof_elastic = float(summary["cof_mean"]), float(summary["cof_elastic"])
        history.append((current.vdw_bond_energy, cof))
        if abs(cof - target_cof) <= rtol * target_cof:
            break
        if cof_elastic >= target_cof or cof <= cof_elastic:
            raise InputError(f"cannot calibrate U_vdW: the elastic COF {cof_elastic:.3g} alone (total {cof:.3g}) "
                             f"does not leave room for the target {target_cof:g}.")
        current = current.updated(vdw_bond_energy=current.vdw_bond_energy * (target_cof - cof_elastic)
                                  / (cof - cof_elastic))
    return current, {"vdw_bond_energy_before": history[0][0],
                     "vdw_bond_energy_after": current.vdw_bond_energy,
                     "cof_before": history[0][1], "cof_after": history[-1][1], "runs": len(history),
                     "converged": abs(history[-1][1] - target_cof) <= rtol * target_cof}
