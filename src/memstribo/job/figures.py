"""The figures of the main job, one function per figure; each works on its own (a dataset in, a
matplotlib figure out) and is drawn by the stage that owns it (:mod:`memstribo.job.chain`)."""

from __future__ import annotations

import math

import numpy as np


def _legend(ax, **kwargs):
    """A legend outside the axes, to their right: it hides no curve (the saved figure grows to hold it)."""
    ax.legend(fontsize=kwargs.pop("fontsize", 8), loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0,
              **kwargs)


def plot_profiles(profiles):
    """Heights of each roughness profile along the scan (thesis Figures 3-18, 4-21)."""
    from memstribo.output import new_figure

    figure, axes = new_figure(len(profiles), 1, figsize=(7, 2.2 * len(profiles)), squeeze=False)
    for ax, profile in zip(axes[:, 0], profiles):
        ax.plot(np.asarray(profile.x) * 1e6, np.asarray(profile.z) * 1e9, lw=0.8)
        label = "synthetic" if profile.synthetic else "measured"
        ax.set_title(profile.name if label in profile.name else f"{profile.name} ({label})", fontsize=9)
        ax.set_ylabel("z [nm]")
    axes[-1, 0].set_xlabel("x [µm]")
    figure.tight_layout()
    return figure


def plot_map(surface):
    """A measured 2D map as an image (heights [nm] over x, y [µm]), with the scan lines along x."""
    from memstribo.output import new_figure

    heights = np.asarray(surface.heights) * 1e9
    ny, nx = heights.shape
    figure, ax = new_figure(figsize=(6, 5))
    image = ax.imshow(heights - np.mean(heights), origin="lower", cmap="viridis", aspect="equal",
                      extent=(0, nx * surface.dx * 1e6, 0, ny * surface.dy * 1e6))
    figure.colorbar(image, ax=ax, label="height - mean [nm]")
    ax.set_xlabel("x [µm] (scan lines, along the flank by default)")
    ax.set_ylabel("y [µm]")
    ax.set_title(f"{surface.name} (measured map)", fontsize=9)
    figure.tight_layout()
    return figure


def plot_cycle(dataset, tangential_force=None, title=""):
    """Friction, adhesion and normal force, and the COF split, over the meshing cycle (Figs. 4-41..4-46)."""
    from memstribo.output import new_figure

    efficiency = "mesh_efficiency" in dataset
    figure, axes_ = new_figure(3 if efficiency else 2, 1, figsize=(7, 8 if efficiency else 6), sharex=True)
    top, bottom = axes_[0], axes_[1]
    c = np.asarray(dataset["c"].values) * 1e6 if "c" in dataset.coords else np.arange(dataset.sizes["step"])
    if efficiency:
        axes_[2].plot(c, dataset["mesh_efficiency"].values, color="C2", label="instantaneous mesh efficiency")
        axes_[2].axhline(float(dataset.attrs["mesh_efficiency_mean"]), color="k", lw=0.8, ls="--",
                         label="mean over a mesh period")
        axes_[2].set_ylabel("efficiency [-]")
        _legend(axes_[2])
    from memstribo.output import engineering_scale

    forces = [name for name in ("resisting_force", "friction_force", "adhesion_force", "normal_force") if name in dataset]
    factor, unit = engineering_scale([np.nanmax(np.abs(dataset[n].values)) for n in forces]
                                     + ([tangential_force] if tangential_force is not None else []), "N")
    if "resisting_force" in dataset:
        top.plot(c, np.asarray(dataset["resisting_force"].values) / factor, "-", lw=1.3, color="C3",
                 label="resisting force R(c),\nall pairs in mesh")
    for name, style in (("friction_force", "-"), ("adhesion_force", "--"), ("normal_force", ":")):
        top.plot(c, np.asarray(dataset[name].values) / factor, style, label=name.replace("_", " "))
    if tangential_force is not None:
        top.axhline(tangential_force / factor, color="k", lw=0.8, label="tangential force F_t\n(stiction where R > F_t)")
    top.set_ylabel(f"force [{unit}]")
    _legend(top)
    top.set_title(title, fontsize=10)
    for name in ("cof", "cof_chemical", "cof_vdw", "cof_elastic"):
        bottom.plot(c, dataset[name].values, label=name.replace("_", " "))
    bottom.set_ylabel("COF [-]")
    axes_[-1].set_xlabel("position on the line of action c [µm]")
    _legend(bottom)
    figure.tight_layout()
    return figure


def plot_ensemble(ensemble, tangential_force):
    """Stiction margin and mean COF of every roughness realisation, with the 5-95 % band (MODEL 7b)."""
    from memstribo.output import new_figure

    rows = ensemble["per_realisation"]
    index = np.arange(len(rows))
    figure, (left, right) = new_figure(1, 2, figsize=(8, 3.4))
    for ax, key, scale, label in ((left, "stiction_margin", 1e3, "minimum margin F_t - R [mN]"),
                                  (right, "cof_mean", 1.0, "mean COF [-]")):
        values = np.array([r[key] for r in rows]) * scale
        ax.fill_between([-0.5, len(rows) - 0.5], ensemble[f"{key}_p05"] * scale, ensemble[f"{key}_p95"] * scale,
                        color="C0", alpha=0.15, label="5-95 %")
        ax.axhline(ensemble[f"{key}_median"] * scale, color="C0", ls="--", lw=0.9, label="median")
        ax.plot(index, values, "o", ms=4, color="C0")
        ax.set_xlabel("roughness realisation")
        ax.set_ylabel(label)
    left.axhline(0.0, color="C3", lw=0.9, label="stiction below")
    left.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=3)
    text = ensemble.get("stiction_probability_text", f"{ensemble['stiction_probability'] * 100:.0f} %")
    left.set_title(f"stiction: {text}", fontsize=10)  # no probability without its interval (MODEL 7d)
    figure.tight_layout()
    return figure


def plot_sliding(dataset, title="", max_points=4000):
    """Forces and COF split over the sliding distance (thesis Figures 2-20, 3-22 to 3-27).

    Long slides are drawn with every k-th step (k chosen so that at most ``max_points`` are drawn).
    """
    from memstribo.output import new_figure

    stride = max(1, int(math.ceil(dataset.sizes["step"] / max_points)))
    data = dataset.isel(step=slice(None, None, stride))
    distance = np.asarray(data["sliding_distance"].values) * 1e9
    figure, (top, bottom) = new_figure(2, 1, figsize=(7, 5.5), sharex=True)
    for name, style in (("friction_force", "-"), ("adhesion_force", "--"), ("normal_force", ":")):
        top.plot(distance, np.asarray(data[name].values) * 1e6, style, lw=0.8, label=name.replace("_", " "))
    top.set_ylabel("force [µN]")
    _legend(top)
    top.set_title(title + (f" (every {stride}th step drawn)" if stride > 1 else ""), fontsize=10)
    for name in ("cof", "cof_chemical", "cof_vdw", "cof_elastic"):
        bottom.plot(distance, data[name].values, lw=0.8, label=name.replace("_", " "))
    bottom.set_ylabel("COF [-]")
    bottom.set_xlabel("sliding distance [nm]")
    _legend(bottom)
    figure.tight_layout()
    return figure


def plot_gear(pair, load, contact_modulus, points=401):
    """Load share, effective radius, sliding velocity and Hertz half-width along the path of contact (4.3-4.5)."""
    from memstribo.output import new_figure

    c = np.linspace(pair.first_contact, pair.last_contact, points)
    figure, axes = new_figure(2, 2, figsize=(9, 5.5), sharex=True)
    (share, radius), (sliding, width) = axes
    for kind, style in (("dry", "-"), ("lubricated", "--")):
        share.plot(c * 1e6, pair.load_share(c, kind), style, label=kind)
    share.set_ylabel("load share of one pair [-]")
    share.legend(fontsize=8, loc="lower center")
    radius.plot(c * 1e6, np.asarray(pair.effective_radius(c)) * 1e6)
    radius.set_ylabel("R_ef [µm]")
    sliding.plot(c * 1e6, pair.sliding_velocity(c))
    sliding.axhline(0.0, color="k", lw=0.5)
    sliding.set_ylabel("sliding velocity [m/s]")
    hertz = pair.hertz(c, load * np.asarray(pair.load_share(c, "dry")), contact_modulus)
    width.plot(c * 1e6, np.asarray(hertz.half_width) * 1e9)
    width.set_ylabel("Hertz half-width a [nm]")
    for ax in axes[1]:
        ax.set_xlabel("position on the line of action c [µm]")
    figure.tight_layout()
    return figure


def plot_block_loads(dataset, title=""):
    """Normal load of every nanoblock over the meshing cycle (the load peaks of thesis Figure 5-18)."""
    from memstribo.output import new_figure

    loads = np.asarray(dataset["block_load"].values) * 1e6  # (step, block)
    c = np.asarray(dataset["c"].values) * 1e6 if "c" in dataset.coords else np.arange(loads.shape[0])
    figure, (image_ax, peak_ax) = new_figure(2, 1, figsize=(7, 5.5), sharex=True,
                                             gridspec_kw={"height_ratios": [2, 1]})
    image = image_ax.imshow(loads.T, aspect="auto", origin="lower", cmap="viridis", interpolation="nearest",
                            extent=(c[0], c[-1], -0.5, loads.shape[1] - 0.5))
    figure.colorbar(image, ax=[image_ax, peak_ax], label="block load [µN]", fraction=0.04)
    image_ax.set_ylabel("nanoblock (flank, row, index)")
    image_ax.set_title(title, fontsize=10)
    peak_ax.plot(c, loads.max(axis=1), lw=0.8)
    peak_ax.set_ylabel("largest block load [µN]")
    peak_ax.set_xlabel("position on the line of action c [µm]")
    return figure


def plot_energy(dataset, title=""):
    """Energy dissipated per step by mechanism over the meshing cycle (Figure 4-47)."""
    from memstribo.output import new_figure

    figure, ax = new_figure(figsize=(7, 3.5))
    c = np.asarray(dataset["c"].values) * 1e6 if "c" in dataset.coords else np.arange(dataset.sizes["step"])
    for name in ("energy_chemical", "energy_vdw", "energy_elastic"):
        ax.plot(c, dataset[name].values, label=name.replace("_", " "))
    ax.set_yscale("symlog", linthresh=1e-20)
    ax.set_xlabel("position on the line of action c [µm]")
    ax.set_ylabel("energy per step [J]")
    ax.set_title(title, fontsize=10)
    _legend(ax)
    figure.tight_layout()
    return figure


def plot_sweep(dataset, x, x_label, x_scale=1.0, tangential_force=None, title=""):
    """COF (split) and dissipated energy of a sweep (Figures 4-48..4-51, 5-22..5-25)."""
    from memstribo.output import new_figure

    figure, (left, right) = new_figure(1, 2, figsize=(10, 3.8))
    xs = np.asarray(dataset[x].values) * x_scale
    for name in ("cof_mean", "cof_chemical", "cof_vdw", "cof_elastic"):
        left.plot(xs, dataset[name].values, "o-", ms=3, label=name.replace("_mean", " (time mean)").replace("_", " "))
    left.set_xlabel(x_label)
    left.set_ylabel("mean COF over the cycle [-]")
    left.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=2)
    if tangential_force is None:
        from memstribo.output import engineering_scale

        energy = np.asarray(dataset["energy_dissipated"].values, dtype=float)
        factor, unit = engineering_scale(energy, "J")  # nJ or pJ, never a "1e-10" offset
        right.plot(xs, energy / factor, "o-", ms=3)
        right.set_ylabel(f"energy dissipated per cycle [{unit}]")
    else:
        from memstribo.output import engineering_scale

        force = np.asarray(dataset["resisting_force_max"].values, dtype=float)
        factor, unit = engineering_scale(np.append(force, tangential_force), "N")
        right.plot(xs, force / factor, "o-", ms=3, label="largest resisting force R")
        right.plot(xs, np.full_like(xs, tangential_force / factor, dtype=float), "k-", lw=0.8,
                   label="F_t (stiction where R > F_t)")  # a line that autoscaling keeps inside the axes
        right.margins(y=0.08)
        right.set_ylabel(f"force [{unit}]")
        right.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=2)
    right.set_xlabel(x_label)
    figure.suptitle(title, fontsize=10)
    figure.tight_layout()
    return figure


def plot_humidity(humidity, title=""):
    """COF with its capillary share, and the stiction margin, versus relative humidity, bare and coated (issue #17).

    ``humidity`` is the run's humidity summary (:meth:`RunChain.humid_air`): per label ("bare",
    "coated") the lists ``cof_mean``, ``cof_capillary``, ``stiction_margin`` [N] over
    ``relative_humidity``, and ``critical_humidity`` (None: no crossing in the range).
    """
    from memstribo.output import new_figure

    figure, (left, right) = new_figure(1, 2, figsize=(10, 3.8))
    rh = np.asarray(humidity["relative_humidity"], dtype=float)
    for label, style in (("bare", "-"), ("coated", "--")):
        part = humidity.get(label)
        if not part:
            continue
        name = part.get("name", label)
        cof = np.asarray(part["cof_mean"], dtype=float)
        left.plot(rh, cof, "o" + style, ms=3, label=f"COF, {name}")
        left.plot(rh, np.asarray(part["cof_capillary"], dtype=float), "s" + style, ms=3,
                  label=f"capillary part, {name}")
        line, = right.plot(rh, np.asarray(part["stiction_margin"], dtype=float) * 1e6, "o" + style, ms=3,
                           label=f"margin, {name}")
        critical = part.get("critical_humidity")
        if critical is not None:
            right.axvline(critical, color=line.get_color(), lw=0.8, ls=":",
                          label=f"critical RH {critical:.2f} ({name})")
    right.axhline(0.0, color="k", lw=0.8)
    left.set_xlabel("relative humidity [-]")
    left.set_ylabel("mean COF over the cycle [-]")
    left.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=2)
    right.set_xlabel("relative humidity [-]")
    right.set_ylabel("stiction margin F_t - max R [µN]")
    right.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=2)
    figure.suptitle(title, fontsize=10)
    figure.tight_layout()
    return figure


def plot_lives(result, cycles, coating_life=None, cycles_to_stiction=None, coating_name="coating"):
    """Stiction, coating life and fracture life on one axis of meshing cycles (MODEL §9, §10).

    ``result``: :func:`memstribo.simulations.tooth_life.tooth_life` of the coated cycle; ``cycles``: pinion
    revolutions N [-]; ``coating_life`` and ``cycles_to_stiction`` [meshing cycles] (None while the damage
    constant c1 is unknown).
    """
    from memstribo.output import new_figure
    from memstribo.simulations.tooth_life import fracture_probability_within

    figure, ax = new_figure(figsize=(6.4, 3.6))
    probability = fracture_probability_within(result, cycles)
    ax.loglog(cycles, np.clip(probability, 1e-12, None), color="C3", label="P(a tooth has broken), fatigue in air")
    ax.axhline(0.01, color="C3", ls=":", lw=0.8, label="1 %")
    for value, colour, label in ((coating_life, "C0", f"{coating_name} worn through (omega = 1)"),
                                 (cycles_to_stiction, "C1", "stiction returns")):
        if value is not None and np.isfinite(value):
            ax.axvline(value, color=colour, lw=1.2, label=f"{label}: {value:.3g} cycles")
    ax.set_xlabel("meshing cycles N [-]")
    ax.set_ylabel("fracture probability [-]")
    ax.set_ylim(max(1e-12, float(np.min(probability)) / 30), 1.5)
    ax.legend(fontsize=7, loc="lower right")
    figure.tight_layout()
    return figure

