"""Figures of the uncertainty study (MODEL 7d): what the verdict hangs on, and where it flips.

matplotlib is imported inside the functions (``import memstribo`` stays light).
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["plot_sensitivity", "plot_stiction_curve", "write_figures"]


def plot_sensitivity(result, folder: str | Path, stem: str = "uncertainty_sensitivity", top: int = 12) -> list[Path]:
    """Ranked bar chart of the total Sobol' indices of the margin (and of the mean COF), with their intervals; a
    study without them (``sensitivity="regional"``): the regional index of the verdict per factor.

    Parameters
    ----------
    result : dict
        Of :func:`memstribo.uncertainty.study.uncertainty_study` (its ``sensitivity``).
    folder : str or Path
        Where ``stem.png`` and ``stem.svg`` go.
    top : int
        Constants shown (the largest total indices).

    Returns
    -------
    list of Path
        The files written (none when the study has no sensitivity).
    """
    import numpy as np

    from memstribo.output import new_figure, save_figure

    sensitivity = result.get("sensitivity") or {}
    if not sensitivity:
        return _plot_regional(result, folder, stem, top)
    names = list(sensitivity)[:top][::-1]  # ranked, largest on top
    y = np.arange(len(names))
    figure, ax = new_figure(figsize=(6.4, 0.45 * len(names) + 1.4))
    for offset, key, label, colour in ((0.18, "total", "margin (total index)", "C3"),
                                       (-0.18, "cof_total", "mean COF (total index)", "C0")):
        values = np.array([sensitivity[n][key] for n in names])
        ci = np.array([sensitivity[n][f"{key}_ci"] for n in names])
        err = np.abs(np.stack([values - ci[:, 0], ci[:, 1] - values]))
        ax.barh(y + offset, values, height=0.34, color=colour, label=label, xerr=err,
                error_kw={"lw": 0.8, "capsize": 2})
    ax.axvline(0.1, color="0.5", ls=":", lw=0.8)
    ax.set_yticks(y)
    ax.set_yticklabels([n + ("" if sensitivity[n].get("critical_value") is None
                             else f"  (critical {sensitivity[n]['critical_value']:.3g})") for n in names], fontsize=8)
    ax.set_xlabel("Sobol' total index [-] (bars: 95 % bootstrap interval; dotted: 0.1)")
    ax.set_xlim(left=min(0.0, ax.get_xlim()[0]))
    ax.set_title("What the stiction verdict hangs on", fontsize=10)
    ax.legend(fontsize=7, loc="lower right")
    return save_figure(figure, folder, stem)


def _plot_regional(result, folder, stem, top) -> list[Path]:
    """The regional index of the verdict per factor with its interval and noise level (a study without Sobol'
    indices, ``sensitivity="regional"``); none without it."""
    import numpy as np

    from memstribo.output import new_figure, save_figure

    regional = {n: e for n, e in (result.get("decision_sensitivity") or {}).items() if e.get("index") is not None}
    if not regional:
        return _plot_correlation(result, folder, stem, top)
    names = list(regional)[:top][::-1]
    y = np.arange(len(names))
    values = np.array([regional[n]["index"] for n in names])
    ci = np.array([regional[n]["index_ci"] for n in names])
    noise = np.array([regional[n]["noise_level"] for n in names])
    figure, ax = new_figure(figsize=(6.4, 0.4 * len(names) + 1.4))
    ax.barh(y, values, height=0.6, color="C3", xerr=np.abs(np.stack([values - ci[:, 0], ci[:, 1] - values])),
            error_kw={"lw": 0.8, "capsize": 2}, label="regional index (KS distance, stuck vs free)")
    ax.plot(noise, y, "k|", ms=10, label="noise level (permutation, 95 %)")
    ax.set_yticks(y)
    ax.set_yticklabels(names, fontsize=8)
    ax.set_xlim(0.0, 1.0)
    ax.set_xlabel("regional index of the stiction verdict [-] (bars: 95 % bootstrap interval)")
    ax.set_title("What separates the samples that stick from those that do not", fontsize=10)
    ax.legend(fontsize=7, loc="lower right")
    return save_figure(figure, folder, stem)


def _plot_correlation(result, folder, stem, top) -> list[Path]:
    """Spearman's rank correlation of the margin with each factor (a unanimous verdict: no regional index)."""
    import numpy as np

    from memstribo.output import new_figure, save_figure

    correlation = result.get("margin_correlation") or {}
    if not correlation:
        return []
    names = sorted(correlation, key=lambda n: -abs(correlation[n]["rho"]))[:top][::-1]
    y = np.arange(len(names))
    rho = np.array([correlation[n]["rho"] for n in names])
    figure, ax = new_figure(figsize=(6.4, 0.4 * len(names) + 1.4))
    ax.barh(y, rho, height=0.6, color=["C3" if correlation[n]["p_value"] < 0.05 else "0.7" for n in names])
    ax.axvline(0.0, color="k", lw=0.6)
    ax.set_yticks(y)
    ax.set_yticklabels(names, fontsize=8)
    ax.set_xlim(-1.0, 1.0)
    ax.set_xlabel("Spearman rank correlation with the stiction margin [-] (red: p < 0.05)")
    ax.set_title("Every sample gives the same verdict: what moves the margin", fontsize=10)
    return save_figure(figure, folder, stem)


def plot_stiction_curve(result, folder: str | Path, stem: str = "uncertainty_stiction_curve") -> list[Path]:
    """P(stiction) over the realisations against the dominant constant (others nominal), with its interval
    and the critical value marked.

    Returns
    -------
    list of Path
        The files written (none when the study has no curve).
    """
    import numpy as np

    from memstribo.output import new_figure, save_figure

    curve = result.get("critical_curve")
    if not curve:
        return []
    x = np.asarray(curve["values"], dtype=float)
    p = np.asarray(curve["probability"], dtype=float)
    low, high = np.asarray(curve["ci_low"]), np.asarray(curve["ci_high"])
    figure, ax = new_figure(figsize=(6.4, 3.8))
    ax.fill_between(x, low, high, color="C0", alpha=0.25, lw=0, label="95 % confidence interval (Wilson)")
    ax.plot(x, p, "o-", color="C0", lw=1.0, ms=3, label=f"P(stiction) over {curve['realisations']} realisations")
    prior = (result.get("priors") or {}).get(curve["name"], {})
    if prior.get("distribution") == "loguniform":
        ax.set_xscale("log")
    if curve.get("critical_value") is not None:
        ax.axvline(curve["critical_value"], color="C3", lw=1.2, ls="--",
                   label=f"critical value {curve['critical_value']:.3g} (median margin = 0)")
    if curve.get("nominal") is not None:
        ax.axvline(curve["nominal"], color="k", lw=0.8, ls=":", label=f"nominal {curve['nominal']:.3g}")
    ax.set_ylim(-0.02, 1.02)
    from memstribo.parameters import SPECS

    unit = SPECS[curve["name"]].unit if curve["name"] in SPECS else ""
    ax.set_xlabel(f"{curve['name']} (others at nominal) [{unit or '-'}]")
    ax.set_ylabel("stiction probability [-]")
    ax.set_title(f"Where the verdict flips: {curve['name']}", fontsize=10)
    ax.legend(fontsize=7)
    return save_figure(figure, folder, stem)


def write_figures(result, folder: str | Path) -> list[Path]:
    """Both figures of the study into ``folder`` (PNG + SVG)."""
    return plot_sensitivity(result, folder) + plot_stiction_curve(result, folder)
