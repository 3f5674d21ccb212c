"""Tables and figures of one blade for the command line (``rotorlyap modes``, ``simulate``, ``--plot``).

Each ``plot_*`` function draws one result of the library into a new figure (closed in pyplot,
laid out and checked for legibility by :func:`rotorlyap.chapters.style.finish`):

* :func:`plot_modes`: the fan diagram (:func:`rotorlyap.analysis.modes.fan_plot`: frequency per
  rev of the nominal rotor speed against the rotor speed in % of it, with the 1/rev to 4/rev
  lines, damping ratio) and the Floquet modes
  of the trimmed periodic motion (:func:`rotorlyap.analysis.modes.floquet_modes`: frequency per
  rev and growth rate per rev against the advance ratio), either or both;
* :func:`plot_disturbed_motion`: the hinge angles of a disturbed motion
  (:func:`rotorlyap.analysis.disturbance.simulate_disturbance`) against revolutions, with the
  steady motion and the certificate's bound about it;
* :func:`plot_certificate`: a certificate's start region and bound per hinge, angles in deg and
  rates in deg/s;
* :func:`plot_sweep_table`: a sweep's table, the largest Floquet real part and the certified flap
  start region against one grid column, a line per value of the others.

:func:`write_table` writes records (``export()`` of the data objects) as CSV or JSON by the
file's suffix, :func:`save_figure` a figure as PNG or SVG.
"""

from __future__ import annotations

import csv
import itertools
import json
import math
from pathlib import Path

import numpy as np

from ..conventions import HINGES
from .export import format_value
from .style import BOOK_DPI, HINGE_COLORS, HINGE_LINESTYLES, finish, subplots

__all__ = ["FIGURE_SUFFIXES", "TABLE_SUFFIXES", "plot_certificate", "plot_disturbed_motion", "plot_modes",
           "plot_sweep_table", "save_figure", "write_table"]

TABLE_SUFFIXES = (".csv", ".json")
"""The formats of :func:`write_table`."""

FIGURE_SUFFIXES = (".png", ".svg")
"""The formats of :func:`save_figure`."""

_REV_LINES = (1, 2, 3, 4)  # the n/rev lines of the fan diagram


def write_table(rows: list[dict], path) -> Path:
    """Write records as a table: ``.csv`` (a header of the first record's keys, numbers with 6
    significant digits, ``nan`` for a missing number) or ``.json`` (a list of records, ``null`` for a
    missing number); returns the path.

    Raises
    ------
    ValueError
        Another suffix, or no records.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in TABLE_SUFFIXES:
        raise ValueError(f"a table's file must end in .csv or .json, got {str(path)!r}")
    if not rows:
        raise ValueError("no rows to write")
    columns = list(rows[0])
    if suffix == ".csv":
        with path.open("w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(columns)
            for r in rows:
                w.writerow([format_value(r.get(c, "")) for c in columns])
    else:
        clean = [{k: (None if isinstance(v, float) and not math.isfinite(v) else v) for k, v in r.items()}
                 for r in rows]
        with path.open("w", encoding="utf-8") as fh:
            json.dump(clean, fh, indent=1, allow_nan=False)
            fh.write("\n")
    return path


def save_figure(fig, path) -> Path:
    """Save ``fig`` as ``.png`` (150 dpi) or ``.svg``, whole (``bbox_inches="tight"``); returns the path.

    Raises
    ------
    ValueError
        Another suffix.
    """
    path = Path(path)
    if path.suffix.lower() not in FIGURE_SUFFIXES:
        raise ValueError(f"a figure's file must end in .png or .svg, got {str(path)!r}")
    fig.savefig(path, dpi=1.5 * BOOK_DPI, bbox_inches="tight")
    return path


# --------------------------------------------------------------------------------------
# Modes
# --------------------------------------------------------------------------------------


def _hinge_of(name: str) -> str:
    return next((h for h in HINGES if name.startswith(h)), "flap")


def _draw_fan(ax_f, ax_d, fan) -> None:
    # the book's unit of a frequency is the rotor's revolution: on the fan diagram, whose rotor
    # speed varies, both axes are taken at the nominal speed Omega_0 (frequency / Omega_0 against
    # Omega / Omega_0 in %), so that the n/rev lines are straight and 1/rev meets the nominal
    # speed at 1
    nominal = float(fan.nominal_rotor_speed)
    omega = fan.rotor_speed
    speed = 100.0 * omega / nominal  # % of nominal
    lo, hi = 0.0, float(speed.max()) * 1.05
    top = 0.0
    for i in range(omega.size):
        if fan.modes[i]:
            top = max(top, float(fan.frequency_hz(i).max()) * 2.0 * np.pi / nominal)
    y_top = 1.1 * max(top, hi / 100.0)
    xs = np.array([lo, hi])
    for n in _REV_LINES:
        ax_f.plot(xs, n * xs / 100.0, color="0.55", lw=0.8, ls=":", zorder=1)
        x_end = min(0.98 * hi, 0.9 * y_top * 100.0 / n)  # near where the line leaves the panel
        ax_f.text(x_end, n * x_end / 100.0, f"{n}/rev ", color="0.35", fontsize=7.5, ha="right", va="bottom")
    # the modes: points of one hinge, oscillatory or not, joined by rank across rotor speeds
    tracks: dict[tuple, list] = {}
    for i, w in enumerate(omega):
        ranks: dict[tuple, int] = {}
        for m in fan.modes[i]:
            key = (m.dominant_hinge, m.oscillatory)
            ranks[key] = ranks.get(key, 0) + 1
            tracks.setdefault(key + (ranks[key],), []).append((w, m))
    for (hinge, osc, _rank), pts in sorted(tracks.items()):
        w = np.array([p[0] for p in pts])
        colour, ls = HINGE_COLORS[hinge], HINGE_LINESTYLES[hinge]
        f_rev = np.array([p[1].frequency for p in pts]) * w / nominal  # per rev of the nominal speed
        zeta = np.array([p[1].damping_ratio for p in pts])
        style = dict(color=colour, marker="o" if osc else "s", ms=4, mfc=colour if osc else "white")
        x = 100.0 * w / nominal
        if osc:
            ax_f.plot(x, f_rev, ls=ls, **style)
        ax_d.plot(x, zeta, ls=ls if osc else "none", **style)
    for ax in (ax_f, ax_d):
        ax.axvline(100.0, color="k", lw=0.8, ls="--")
        ax.set_xlabel(r"rotor speed $\Omega / \Omega_0$ (%)")
        ax.grid(alpha=0.3)
        ax.set_xlim(lo, hi)
    ax_f.set_ylim(0.0, y_top)
    ax_f.set_ylabel(r"frequency (per rev at $\Omega_0$)")
    where = "hover, with air" if fan.air else "in vacuum"
    ax_f.set_title(f"(a) fan diagram, {where}", fontsize=9)
    ax_d.axhline(0.0, color="k", lw=0.8)
    ax_d.set_ylabel("damping ratio (-)")
    ax_d.set_title("(b) damping ratio", fontsize=9)
    from matplotlib.lines import Line2D

    hinges = [h for h in HINGES if any(k[0] == h for k in tracks)]
    handles = [Line2D([], [], color=HINGE_COLORS[h], ls=HINGE_LINESTYLES[h], marker="o", ms=4, label=h)
               for h in hinges]
    handles.append(Line2D([], [], color="k", lw=0.8, ls="--", label="nominal speed"))
    ax_f.legend(handles=handles, fontsize=7.5, loc="upper left")
    if any(not k[1] for k in tracks):
        ax_d.legend(handles=[Line2D([], [], color="0.3", marker="s", mfc="white", ls="none", ms=4,
                                    label="real mode (+1 decays, -1 grows)")],
                    fontsize=7.5, loc="center right")


def _draw_floquet(ax_f, ax_g, fl) -> None:
    for j, name in enumerate(fl.names):
        hinge = _hinge_of(name)
        style = dict(color=HINGE_COLORS[hinge], ls=HINGE_LINESTYLES[hinge], marker="o", ms=4)
        real = not name.endswith("+")  # a complex pair is named "<hinge>+"
        label = f"{name.rstrip('+')}" + (", real" if real else "")
        ax_f.plot(fl.mu, fl.frequency[:, j], label=label, **style)
        ax_g.plot(fl.mu, fl.growth_rate[:, j], **style)
    for n in _REV_LINES[:2]:
        ax_f.axhline(n, color="0.55", lw=0.8, ls=":")
    ax_g.axhline(0.0, color="k", lw=0.8)
    for ax in (ax_f, ax_g):
        ax.set_xlabel(r"advance ratio $\mu$ (-)")
        ax.grid(alpha=0.3)
    ax_f.set_ylabel("frequency (per rev)")
    ax_f.set_title(f"(c) Floquet modes, {fl.condition} trim", fontsize=9)
    ax_g.set_ylabel("growth rate (per rev)")
    ax_g.set_title("(d) growth rate (> 0: unstable)", fontsize=9)
    ax_f.legend(fontsize=7.5, title="mode (in hover)", title_fontsize=7.5)


def plot_modes(fan=None, floquet=None):
    """The fan diagram and/or the Floquet modes against the advance ratio.

    Parameters
    ----------
    fan : FanData, optional
        Panels (a) frequency (per rev of the nominal rotor speed ``Omega_0``) against the rotor
        speed (% of ``Omega_0``), with the n/rev lines and the nominal speed, and (b) the damping ratio (squares: real modes, whose ratio is +1 decaying
        or -1 growing).
    floquet : FloquetModes, optional
        Panels (c) frequency (per rev, the branch followed from hover) and (d) growth rate (per
        rev) against the advance ratio.

    Returns
    -------
    matplotlib.figure.Figure
        7.5 in wide, one row per result given.
    """
    if fan is None and floquet is None:
        raise ValueError("plot_modes needs a fan diagram or Floquet modes (or both)")
    rows = [r for r in (fan, floquet) if r is not None]
    fig, axes = subplots(len(rows), 2, figsize=(7.5, 3.0 * len(rows)), squeeze=False)
    k = 0
    if fan is not None:
        _draw_fan(axes[k, 0], axes[k, 1], fan)
        k += 1
    if floquet is not None:
        _draw_floquet(axes[k, 0], axes[k, 1], floquet)
        if fan is None:
            axes[0, 0].set_title(axes[0, 0].get_title().replace("(c)", "(a)"), fontsize=9)
            axes[0, 1].set_title(axes[0, 1].get_title().replace("(d)", "(b)"), fontsize=9)
    return finish(fig)


# --------------------------------------------------------------------------------------
# A disturbed motion
# --------------------------------------------------------------------------------------


def plot_disturbed_motion(motion):
    """The hinge angles of a disturbed motion against revolutions, one panel per hinge.

    Each panel: the disturbed motion (solid), the steady motion of the trim (grey dashed) and, with a
    certified certificate, the band ``steady +- a_i A`` within which the certificate keeps the
    angle for a disturbance inside its start region (shaded, dotted edges).

    Returns
    -------
    matplotlib.figure.Figure
        7.5 x 5.4 in, closed in pyplot.
    """
    fig, axes = subplots(3, 1, figsize=(7.5, 5.4), sharex=True)
    rev = motion.revolutions
    for i, (ax, hinge) in enumerate(zip(axes, HINGES)):
        steady = motion.steady_deg[:, i]
        ax.plot(rev, motion.angles_deg[:, i], color=HINGE_COLORS[hinge], lw=1.2, label="disturbed motion")
        ax.plot(rev, steady, color="0.4", lw=0.9, ls="--", label="steady motion (trim)")
        if motion.bound_deg is not None:
            b = motion.bound_deg[i]
            ax.fill_between(rev, steady - b, steady + b, color=HINGE_COLORS[hinge], alpha=0.12, lw=0,
                            label=f"certified bound, $\\pm${b:.3g} deg")
            ax.plot(rev, steady + b, color=HINGE_COLORS[hinge], lw=0.7, ls=":")
            ax.plot(rev, steady - b, color=HINGE_COLORS[hinge], lw=0.7, ls=":")
        ax.set_ylabel(f"{hinge} angle (deg)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7.5, loc="upper right", ncol=3)
    axes[-1].set_xlabel("time (revolutions)")
    given = ", ".join(f"{n} {v:.3g} {'deg' if k < 3 else 'deg/s'}"
                      for k, (n, v) in enumerate(zip(("flap", "lag", "pitch", "flap rate", "lag rate", "pitch rate"),
                                                     motion.disturbance)) if v != 0.0)
    title = f"$\\mu$ = {motion.mu:g}, {motion.condition} trim: disturbance {given}"
    if motion.certified is not None:
        if motion.bound_deg is None:
            title += "; not certified"
        else:
            title += "; inside the start region" if motion.inside_start_region else "; outside the start region"
    axes[0].set_title(title, fontsize=9)
    if motion.escaped:
        axes[-1].set_title("stopped: the motion left the escape radius", fontsize=8)
    return finish(fig)


# --------------------------------------------------------------------------------------
# A certificate and a sweep
# --------------------------------------------------------------------------------------


def plot_certificate(certificate):
    """A certificate's start region and bound per hinge: (a) angles in deg, (b) rates in deg/s.

    A disturbance of one hinge within its start bar keeps that hinge's motion within the bound bar
    for ever (a combined disturbance must lie inside the scaled norm's start radius).

    Returns
    -------
    matplotlib.figure.Figure
        7.5 x 3 in, closed in pyplot.
    """
    fig, axes = subplots(1, 2, figsize=(7.5, 3.0))
    start, bound = certificate.start_region_per_hinge, certificate.bound_per_hinge
    x = np.arange(len(HINGES))
    for k, (ax, unit) in enumerate(zip(axes, ("deg", "deg/s"))):
        s = [start[h][k] for h in HINGES]
        b = [bound[h][k] for h in HINGES]
        colours = [HINGE_COLORS[h] for h in HINGES]
        ax.bar(x - 0.2, s, 0.4, color=colours, edgecolor="k", lw=0.6, label="start region")
        ax.bar(x + 0.2, b, 0.4, color=colours, alpha=0.35, edgecolor="k", lw=0.6, hatch="//",
               label="bound (stays within)")
        ax.set_xticks(x, [h if k == 0 else f"{h} rate" for h in HINGES])
        ax.set_ylabel(f"{'angle' if k == 0 else 'rate'} ({unit})")
        ax.grid(alpha=0.3, axis="y")
        ax.set_ylim(0.0, 1.4 * max(max(b), 1e-9))  # room for the legend above the bars
    axes[0].set_title("(a) hinge angles", fontsize=9)
    axes[1].set_title("(b) hinge rates", fontsize=9)
    axes[0].legend(fontsize=7.5, loc="upper left")
    verdict = "certified" if certificate.certified else "not certified: nothing to draw"
    fig.text(0.5, 0.99, f"$\\mu$ = {certificate.mu:g}, {certificate.condition} trim, {certificate.function} "
             f"function: {verdict}", fontsize=9, ha="center", va="top")
    return finish(fig, rect=(0.0, 0.0, 1.0, 0.93))


def plot_sweep_table(result):
    """A sweep's table: (a) the largest Floquet real part, (b) the certified flap start region,
    against one grid column (``mu`` if it varies, else the last column that varies), a line per
    combination of the other varying columns; filled markers certified, crosses not.

    Returns
    -------
    matplotlib.figure.Figure
        7.5 x 3 in, closed in pyplot.
    """
    grid = list(result.grid_columns)
    varying = [c for c in grid if len(set(result.column(c))) > 1]
    x_name = "mu" if "mu" in varying else (varying[-1] if varying else "mu")
    others = [c for c in varying if c != x_name]
    xs = result.column(x_name)
    numeric = all(isinstance(v, (int, float)) for v in xs)
    levels = sorted(set(xs)) if numeric else list(dict.fromkeys(xs))
    pos = {v: (float(v) if numeric else float(k)) for k, v in enumerate(levels)}
    series: dict[tuple, list[int]] = {}
    for r in range(len(result)):
        key = tuple(result.column(c)[r] for c in others)
        series.setdefault(key, []).append(r)
    growth, start, ok = result.column("growth_rate_per_rev"), result.column("start_flap_deg"), result.column("certified")
    fig, (ax1, ax2) = subplots(1, 2, figsize=(7.5, 3.0), sharex=True)
    styles = itertools.cycle((("C0", "o", "-"), ("C1", "s", "--"), ("C2", "^", ":"), ("C3", "D", "-."),
                              ("C4", "v", "-"), ("C5", "P", "--")))
    for key, idx in series.items():
        colour, marker, line = next(styles)
        idx = sorted(idx, key=lambda r: pos[xs[r]])
        x = np.array([pos[xs[r]] for r in idx])
        g = np.array([np.nan if growth[r] is None else growth[r] for r in idx], dtype=float)
        c = np.array([bool(ok[r]) for r in idx])
        s = np.array([start[r] if (c[k] and start[r] is not None) else 0.0 for k, r in enumerate(idx)], dtype=float)
        label = ", ".join(f"{n} = {v:g}" if isinstance(v, float) else f"{n} = {v}" for n, v in zip(others, key)) or None
        ax1.plot(x, g, line, color=colour, marker=marker, ms=4, label=label)
        ax2.plot(x, s, line, color=colour, lw=1)
        if c.any():
            ax2.plot(x[c], s[c], marker, color=colour, ms=5, ls="none")
        if not c.all():  # (an empty line unclipped would stretch the layout)
            ax2.plot(x[~c], s[~c], "x", color=colour, ms=6, ls="none", clip_on=False)
    ax1.axhline(0.0, color="k", lw=0.8)
    ax1.set_ylabel("largest Floquet real part (per rev)")
    ax1.set_title("(a) linear stability", fontsize=9)
    ax2.set_ylabel("certified flap start region (deg)")
    ax2.set_title("(b) the certificate (x: none)", fontsize=9)
    x_label = r"advance ratio $\mu$ (-)" if x_name == "mu" else x_name
    for ax in (ax1, ax2):
        ax.set_xlabel(x_label)
        ax.grid(alpha=0.3)
        if not numeric:
            ax.set_xticks([pos[v] for v in levels], [str(v) for v in levels])
    ax2.set_ylim(bottom=0.0)
    if others:
        ax1.legend(fontsize=7.5)
    return finish(fig)
