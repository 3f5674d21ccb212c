"""Chapter 6, forward flight: the claims table, each claim of the paper's section 5 with the
verdict in each reading, the evidence and where we differ, made from the chapter's results.

Part of :mod:`rotorlyap.chapters.forward_flight`, which re-exports its names.
"""

from __future__ import annotations

import re

from dataclasses import dataclass

import numpy as np

from ..export import markdown_table  # the claims table; also re-exported for the chapters
from .checks import ConvergenceData, SensitivityData, ThresholdData
from .loads import RateAzimuthData, WSpheresData
from .regions import HoverFlutterCheck, RegionMaps

__all__ = ["CLAIMS_HEADER", "ClaimsTable", "myst_math", "claims_table", "markdown_table"]


# --------------------------------------------------------------------------------------
# The claims table
# --------------------------------------------------------------------------------------


#: Header of chapter 6's claims table.
CLAIMS_HEADER = ("claim (the paper's figure numbers)", "strict (numerical certificate)",
                 "practical (indicator, not a certificate)", "evidence", "where we differ, and why")


@dataclass(frozen=True)
class ClaimsTable:
    """Each claim of the paper's section 5 with the verdict in each reading, the evidence and
    where we differ (chapter 6).

    Attributes
    ----------
    header : tuple of str
    rows : tuple of tuple of str
        One per claim, in the order of ``header`` (the evidence cells hold MyST roles).
    """

    header: tuple
    rows: tuple

    def markdown(self) -> str:
        """The table in Markdown (:func:`rotorlyap.chapters.export.markdown_table`), its symbols
        typeset (:func:`myst_math`)."""
        return markdown_table([myst_math(h) for h in self.header],
                              [[myst_math(c) for c in r] for r in self.rows])

    def summary(self) -> str:
        """One line per claim: its start and the start of each reading's verdict."""
        lines = []
        for r in self.rows:
            strict, practical = r[1].split(":")[0], r[2].split(":")[0]
            lines.append(f"{r[0][:60]:60s} | strict: {strict[:30]:30s} | practical: {practical[:30]}")
        return "\n".join(lines)


_PLAIN_SYMBOLS = re.compile(r"\b(?:(max|min|inf|sup) )?W\b('?)|\bmu\b|\bA\^2\b|\bx = 0\b|\b1e-7\b")
_KEEP = re.compile(r"(\$[^$]*\$|\{[a-z:]+\}`[^`]*`)")


def myst_math(text: str) -> str:
    """``text`` with its plain-text symbols typeset as MyST math: ``W'``, ``max W'``, ``inf W``,
    ``mu``, ``A^2``, ``x = 0``, ``1e-7``; math and roles already in ``text`` are left alone."""
    def sub(m: re.Match) -> str:
        t = m.group(0)
        if t == "mu":
            return r"$\mu$"
        if t == "1e-7":
            return r"$10^{-7}$"
        if m.group(1):
            return "$\\%s W%s$" % (m.group(1), m.group(2))
        return f"${t}$"
    parts = _KEEP.split(text)
    return "".join(p if i % 2 else _PLAIN_SYMBOLS.sub(sub, p) for i, p in enumerate(parts))


def claims_table(convergence: ConvergenceData, w_spheres: WSpheresData, rate: RateAzimuthData,
                 regions: RegionMaps, flutter: HoverFlutterCheck, threshold: ThresholdData,
                 sensitivity: SensitivityData) -> ClaimsTable:
    """The claims table of chapter 6 from the chapter's results (nothing is recomputed)."""
    i12 = convergence.default_stations_index
    col = np.degrees(convergence.collective[:, i12])
    smax_h = convergence.sup_dW_hover[:, -1]
    reg_p, reg_s = regions.practical, regions.strict
    hover_p, hover_s = reg_p.stable[:, 0], reg_s.stable[:, 0]
    n4, mu4, _ = sensitivity.stable_forward_flight("A = 4")
    adv1, ret1 = (a[1] for a in reg_p.positive_side_fractions(0))
    adv_last, ret_last = (a[-1] for a in reg_p.positive_side_fractions(0))
    wsph = w_spheres
    rows = [
        ("paper's Fig. 4: hover equilibrium angles for the three C.G. positions (a code test)",
         "reproduced (a computation, no Liapunov reading involved)",
         "reproduced (a computation, no Liapunov reading involved)",
         "collective " + " / ".join(f"{c:.2f}" for c in col) + " deg for forward / neutral / backward; "
         "equilibrium angles nearly equal; thrust = weight ({numref}`fig-hover-trim`)",
         "the paper's figure is lost: the computation, not its numbers, can be compared"),
        ("paper's Fig. 5: W' in hover against C.G.: stability decreases as the C.G. moves aft",
         "not reproduced: max W' on the sphere " + " / ".join(f"{v:.1f}" for v in smax_h)
         + " J/rad (flat, slightly decreasing aft; nothing certified)",
         "not reproduced: max W' over the 12 axes is 0 at every C.G.",
         "{numref}`fig-hover-rate`; linear theory agrees with the paper: largest real part "
         + " / ".join(f"{e:+.3f}" for e in flutter.growth_rate) + " (forward / neutral / backward)",
         "the statement is true of the model (all three stable, the damping margin shrinking aft), but the "
         "energy cannot see it: its W' > 0 comes from the flap moment due to pitch, which does not depend on the C.G."),
        ("paper's Fig. 6: W at mu = 0.15 (forward C.G.) against azimuth and A: W decreases as A increases",
         f"not reproduced: inf W = {wsph.strict_inf[0].mean():.3f} ... {wsph.strict_inf[-1].mean():.2f} J for A = "
         f"{wsph.A_values[0]:g} ... {wsph.A_values[-1]:g}",
         f"not reproduced: min W over the axes = {wsph.practical_min[0].mean():.3f} ... "
         f"{wsph.practical_min[-1].mean():.2f} J",
         "{numref}`fig-w-spheres`: W grows as A^2 and does not depend on the azimuth",
         "an energy about a constant steady state has no azimuth in it and scales as A^2; the paper's figure "
         "must show another, or a normalised, quantity (unknown)"),
        ("paper's Fig. 7: W' in forward flight (no separate statement)",
         f"W' > 0 at every azimuth for mu > 0; up to {rate.strict_max[-1].max():.0f} J/rad at mu = 0.25",
         f"W' > 0 at {int((rate.practical_max[1] > 0).sum())} of 72 azimuths already at mu = 0.05",
         "{numref}`fig-rate-azimuth`",
         "W' is the work of the forward-flight loads left unbalanced by the reused hover equilibrium"),
        ("paper's Fig. 8: \"stable\" at every azimuth in hover",
         f"not reproduced: nothing certified ({int(hover_s.sum())} of {hover_s.size} (case, azimuth) pairs)",
         f"reproduced: {int(hover_p.sum())} of {hover_p.size} (case, azimuth) pairs pass (indicator)",
         "{numref}`fig-regions-polar`, {numref}`fig-regions-plane`",
         "agrees with linear theory for these blades (all stable), but is an indicator, not a certificate: "
         f"it also passes the hover of a blade that flutters (backward C.G. without pitch damping, "
         f"largest real part {flutter.flutter_growth_rate:+.3f}: {flutter.flutter_stable} of 72 azimuths)"),
        ("paper's Fig. 8: as mu grows, a region of instability appears first on the retreating side (stall flutter)",
         f"not reproduced: nothing certified at any mu ({int(reg_s.stable.sum())} certified cells)",
         f"not reproduced: no azimuth passes from mu = {reg_p.mu_values[1]:g} on, for every C.G. "
         f"({int(reg_p.stable[:, 1:].sum())} passing cells); with A = 4, {n4} of 72 azimuths "
         f"at mu = {mu4:g} and none beyond",
         "{numref}`fig-regions-plane`, {numref}`fig-sensitivity`; per azimuth, W' > 0 on the sphere appears on both "
         f"sides at once ({adv1:.2f} of the advancing and {ret1:.2f} of the "
         f"retreating azimuths at mu = {reg_p.mu_values[1]:g}); threshold below 1e-7 (Glauert inflow), "
         f"{threshold.threshold_of('drees', '12 axes'):.2g} (Drees inflow)",
         "the hover equilibrium is not a forward-flight motion: the unbalanced loads make W' > 0 near x = 0 "
         "at once; our quasi-steady model has no stall-flutter mechanism (no dynamic stall; the pitch-damping "
         "couple has a constant coefficient)"),
        ("paper's Fig. 8: at mu = 0.25 also a region on the advancing side",
         "not reproduced", "not reproduced (the whole disc already fails)",
         f"per azimuth: W' > 0 on the sphere on {adv_last:.2f} of the advancing and "
         f"{ret_last:.2f} of the retreating side at mu = {reg_p.mu_values[-1]:g}",
         "as above"),
    ]
    return ClaimsTable(header=CLAIMS_HEADER, rows=tuple(rows))
