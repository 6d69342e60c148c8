"""Sweeps of a meshing cycle over a parameter (load, torque, area, humidity, ...) and the critical humidity."""

from __future__ import annotations

import numpy as np

from memstribo.errors import InputError
from memstribo.simulations.mesh.cycle import simulate_mesh
from memstribo.simulations.mesh.ensemble import simulate_ensemble
from memstribo.simulations.mesh.verdict import _LOWEST_MENISCUS_HUMIDITY, summarize


def sweep(params, parameter, values, roughness=None, *, steps=None, coating=None, wear=1.0, progress=False,
          realisations=1, client=None, check=False):
    """Meshing cycles over a list of loads, drive torques or nominal areas (thesis 4.9.3, 4.9.4).

    Parameters
    ----------
    params : Parameters
    parameter : {"load", "torque", "area"}
        ``"load"``: ``values`` are normal loads [N] (the ``thesis`` load case: the normal load is
        given). ``"torque"``: drive torques [N m] (the ``torque`` load case). ``"area"``:
        nominal contact areas in multiples of A_adh = w_adh^2 [-]; the face width is set to
        ``n w_adh`` so that ``n`` rows of nanoblocks share the load (the thesis's "nominal area").
    values : sequence of float
    roughness, steps, coating, wear
        As for :func:`simulate_mesh`.
    progress : bool
        tqdm progress bar over the points (stderr).
    realisations : int
        Roughness realisations per point: above 1 each point also carries the ensemble's
        ``stiction_probability`` and quantiles (:func:`simulate_ensemble`), e.g. the stiction
        probability versus drive torque.
    client : distributed.Client, optional
        Runs each point's realisations on a Dask cluster.
    check : bool
        Check each point's first cycle at twice the steps and at twice the grid's resolution
        (:func:`memstribo.simulations.mesh.convergence.check_cycle`, MODEL 7d: three cycles or more per point).

    Returns
    -------
    list of dict
        One summary (:func:`summarize`) per value, with the swept value first under
        ``"normal_load"``, ``"drive_torque"`` or ``"area"`` (and ``"area_multiple"`` for areas), and
        ``converged`` (True or False with ``check``, else None: not checked) with the check's changes.
    """
    values = [float(v) for v in values]
    if not values:
        raise InputError("a sweep needs at least one value.")
    if parameter not in ("load", "torque", "area", "humidity"):
        raise InputError(f"sweep parameter '{parameter}' is unknown: use 'load', 'torque', 'area' or 'humidity'.")
    iterator = values
    if progress:
        from tqdm.auto import tqdm

        iterator = tqdm(values, desc=f"sweep {parameter}", unit="cycle")
    points = []
    warm = None
    for value in iterator:
        if parameter == "load":
            if value <= 0:
                raise InputError(f"sweep load values must be positive forces, got {value!r} N.")
            point_params = params.updated({"normal_load": value, "load_case": "thesis"}, origin="sweep")
            head = {"normal_load": value}
        elif parameter == "humidity":
            if not 0.0 <= value <= 0.99:
                raise InputError(f"sweep humidity values are relative humidities from 0 to 0.99, got {value!r}.")
            point_params = params.updated({"environment": "air", "relative_humidity": value}, origin="sweep")
            head = {"relative_humidity": value}
            # each point starts from the previous one's contacts, where the contact has one solution: with
            # the Maugis-Dugdale zone a step can have two (adhered or not), and the state reached would
            # then depend on the humidity swept before it, so those points start cold
            if params["contact_adhesion"] == "none":
                warm = {} if warm is None else warm
        elif parameter == "torque":
            if value <= 0:
                raise InputError(f"sweep torque values must be positive torques, got {value!r} N m.")
            point_params = params.updated({"drive_torque": value, "load_case": "torque"}, origin="sweep")
            head = {"drive_torque": value}
        else:
            if value < 1 or not float(value).is_integer():
                raise InputError(f"sweep area values are whole multiples of A_adh (1, 2, 3, ...), got {value!r}.")
            w_adh = params["adhesive_width"]
            point_params = params.updated({"face_width": value * w_adh * (1 + 1e-9)}, origin="sweep")
            head = {"area_multiple": int(value), "area": value * w_adh**2}
        if realisations > 1:
            ensemble = simulate_ensemble(point_params, roughness, realisations=realisations, steps=steps,
                                         coating=coating, wear=wear, client=client)
            summary = dict(ensemble["summaries"][0])
            summary.update({k: v for k, v in ensemble.items() if k not in ("summaries", "per_realisation")})
            if parameter == "humidity":  # each realisation's margin, for its critical humidity
                summary["stiction_margin_realisations"] = [r["stiction_margin"] for r in ensemble["per_realisation"]]
            dataset = None
        else:
            dataset = simulate_mesh(point_params, roughness, steps=steps, coating=coating, wear=wear, warm_start=warm)
            summary = summarize(dataset)
        summary["converged"] = None
        if check:  # with the point's cycle, each comparison is first the spot check (mesh.spot)
            from memstribo.simulations.mesh.convergence import check_cycle

            summary.update(check_cycle(point_params, roughness, steps=steps, coating=coating, wear=wear,
                                       dataset=dataset))
        points.append({**head, **summary})
    return points


def _first_crossing(humidity, margin):
    """RH [-] where ``margin`` first falls to <= 0, linear between sweep points; None without a crossing."""
    for i, value in enumerate(margin):
        if value <= 0.0:
            if i == 0:
                return float(humidity[0])
            before = margin[i - 1]
            return float(humidity[i - 1] + (humidity[i] - humidity[i - 1]) * before / (before - value))
    return None


def critical_humidity(points) -> dict:
    """Relative humidity at which stiction sets in, from a humidity sweep (issue #17, docs/humidity.md).

    The stiction margin M = F_t - max R(c) (MODEL 7b) of each point is interpolated linearly in RH
    between neighbouring sweep points; the critical humidity is the lowest RH where it reaches 0
    (stiction for every RH above, up to the next crossing back, if any). With several roughness
    realisations per point (``sweep(..., realisations=N)``) each realisation's margin gives its own
    critical humidity, and their 5/50/95 % quantiles give the spread.

    Parameters
    ----------
    points : list of dict
        :func:`sweep` ``"humidity"`` points: ``relative_humidity`` [-] and ``stiction_margin`` [N]
        (and ``stiction_margin_realisations`` with realisations).

    Returns
    -------
    dict
        ``critical_humidity`` [-] (None when the margin does not cross zero in the swept range),
        ``critical_humidity_note`` (why, in words), ``critical_humidity_range`` [RH min, RH max];
        with realisations also ``critical_humidity_realisations`` (one value or None each),
        ``critical_humidity_p05``/``_median``/``_p95`` over the realisations that cross and
        ``critical_humidity_crossing_fraction`` and ``critical_humidity_stuck_at_lowest`` (realisations
        that already stick at the lowest RH, counted there). A crossing below RH 0.185 (no meniscus: MODEL 7g) is flagged in the note.
    """
    if not points or any("relative_humidity" not in p or "stiction_margin" not in p for p in points):
        raise InputError("critical_humidity needs the points of a humidity sweep (relative_humidity, "
                         "stiction_margin).")
    ordered = sorted(points, key=lambda p: p["relative_humidity"])
    humidity = np.array([p["relative_humidity"] for p in ordered], dtype=float)
    margin = np.array([p["stiction_margin"] for p in ordered], dtype=float)
    low, high = float(humidity[0]), float(humidity[-1])
    value = _first_crossing(humidity, margin)
    if value is not None and 0.0 < value < _LOWEST_MENISCUS_HUMIDITY:
        low_note = (f"; RH {value:.3f} is below {_LOWEST_MENISCUS_HUMIDITY:g}, where the Kelvin radius is below a "
                    "molecular size and the meniscus model does not hold (an adsorbed film, no meniscus force: MODEL "
                    "7g): the crossing lies between the swept points, read it as 'as soon as menisci form'")
    else:
        low_note = ""
    if value is None:
        note = (f"no stiction in the swept range RH {low:g}-{high:g}: the stiction margin stays positive (smallest "
                f"{margin.min() * 1e6:.4g} µN at RH {humidity[int(np.argmin(margin))]:g}); the critical humidity, if "
                "any, lies above the range")
    elif value == low and margin[0] <= 0.0:
        note = (f"stiction already at the lowest swept humidity RH {low:g}: the critical humidity is at or below it "
                "(extend the sweep downwards)")
    else:
        note = (f"the stiction margin crosses zero at RH {value:.3f} (linear between the sweep points; resolution "
                f"{np.diff(humidity).max() if humidity.size > 1 else 0:.3g})")
    out = {"critical_humidity": value, "critical_humidity_note": note + low_note,
           "critical_humidity_range": [low, high]}
    if all("stiction_margin_realisations" in p for p in ordered):
        per = np.array([p["stiction_margin_realisations"] for p in ordered], dtype=float)  # (points, realisations)
        values = [_first_crossing(humidity, per[:, j]) for j in range(per.shape[1])]
        crossing = np.array([v for v in values if v is not None])
        out["critical_humidity_realisations"] = values
        out["critical_humidity_crossing_fraction"] = float(crossing.size / len(values))
        for name, q in (("p05", 0.05), ("median", 0.5), ("p95", 0.95)):
            out[f"critical_humidity_{name}"] = float(np.quantile(crossing, q)) if crossing.size else None
        stuck = sum(1 for j, v in enumerate(values) if v is not None and v == low and per[0, j] <= 0.0)
        out["critical_humidity_stuck_at_lowest"] = stuck
        if stuck:
            out["critical_humidity_note"] += (f"; {stuck} of {len(values)} realisation(s) already stick at the lowest "
                                              f"RH {low:g} (counted there)")
        if crossing.size == 0:
            out["critical_humidity_note"] += f"; none of the {len(values)} realisations sticks in the range"
        elif crossing.size < len(values):
            out["critical_humidity_note"] += (f"; {len(values) - crossing.size} of {len(values)} realisation(s) do "
                                              "not stick in the range (the quantiles are over those that do)")
    return out
