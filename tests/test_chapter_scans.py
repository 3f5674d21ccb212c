"""The scans' verdict maps (:mod:`rotorlyap.chapters.scans`, shared by chapters 7 and 8): the
summary, certificate table, facts and figure of a :class:`~rotorlyap.chapters.scans.ScanData`
built by hand with chapter 7's candidates, so that the tests check what the chapters print and
glue from given numbers (the rounding, the glue names and the selections, not the physics).
"""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from rotorlyap.chapters import scans  # noqa: E402
from rotorlyap.chapters import validation as fv  # noqa: E402

TWO_PI = 2 * np.pi


def _closed(fig) -> bool:
    return not plt.fignum_exists(fig.number)


@pytest.fixture(scope="module")
def scan():
    """Six candidates, three cases, mu = 0, 0.1, 0.15, four azimuths (0, 90, 180, 270 deg)."""
    keys = tuple(c.key for c in fv.CANDIDATES)
    c_, k_, m_, n_ = len(keys), 3, 3, 4
    cat = np.zeros((c_, k_, m_, n_), dtype=int)
    lam = np.full((c_, k_, m_, n_), 0.1)
    aused = np.full((c_, k_, m_), 0.5)
    astep3 = np.full((c_, k_, m_), 0.5)

    def fail(c, i, j, category=2, band=False):
        cat[keys.index(c), i, j] = category
        lam[keys.index(c), i, j] = 0.0
        aused[keys.index(c), i, j] = 0.0 if category in (2, 3) else np.nan
        astep3[keys.index(c), i, j] = (0.3 if band else 0.0) if category in (2, 3) else np.nan

    for i in range(3):
        for j in (1, 2):
            fail("paper", i, j)
            fail("quadratic-hover", i, j)
        for j in range(3):
            fail("energy", i, j)
    fail("energy-practical", 0, 2)
    cat[keys.index("energy-practical"), 0, 2] = [3, 2, 2, 3]  # W' > 0 over the rear half only
    cq, co = keys.index("quadratic"), keys.index("quadratic-opt")
    lam[cq, 0] = [[0.1, 0.11, 0.12, 0.13], [0.08, 0.09, 0.09, 0.09], [0.06, 0.07, 0.07, 0.07]]
    lam[co, 0] = [[0.3, 0.3, 0.3, 0.3], [0.2, 0.21, 0.22, 0.23], [0.25, 0.25, 0.26, 0.26]]
    fail("quadratic", 2, 1, category=5)
    cat[cq, 2, 2] = [0, 0, 1, 1]  # step 6 fails at two azimuths
    lam[cq, 2, 0] = 0.0019
    fail("quadratic-opt", 1, 2, band=True)  # step 3 passes, the band fails at every bound
    fail("quadratic-opt", 2, 1, category=4)
    fail("quadratic-opt", 2, 2)
    return scans.ScanData(cases=fv.CASES, mu_values=np.array([0.0, 0.1, 0.15]), psi=TWO_PI * np.arange(4) / 4,
                          keys=keys, labels=tuple(c.label for c in fv.CANDIDATES),
                          readings=tuple(c.reading for c in fv.CANDIDATES), category=cat, stable=cat == 0,
                          lambda0=np.where(cat == 0, lam, 0.0), A_used=aused, A_step3=astep3,
                          weights=np.ones((3, 6)), messages=())


def test_scan_summary_counts_stable_azimuths_and_names_why_nothing_is_certified(scan):
    lines = scan.summary().splitlines()
    i = lines.index("quadratic Q = I, strict, periodic motion")
    assert lines[i + 3] == "   backward     4/0    noXi     2/2"
    assert lines[lines.index("energy, strict, periodic motion") + 1] == "   forward       s3      s3      s3"
    j = lines.index("quadratic, optimised Q, strict, periodic motion")
    assert lines[j + 2].split()[-1] == "band"  # the neutral C.G., optimised, mu = 0.15
    assert "(passing or certified / step-6-fails azimuths of 4;" in lines[-2]
    assert lines[-1] == "optimised weights (forward C.G.): [1. 1. 1. 1. 1. 1.]"


def test_scan_certificate_rows_give_the_certified_lambda0_range_per_advance_ratio(scan):
    rows = scan.certificate_rows()
    assert len(rows) == 6
    assert rows[0][1:] == ("0", "0.500", "0.500", "0.100", "0.130", "4 of 4")
    assert scan.certificate_table().splitlines()[0].startswith("| function (forward C.G., strict")
    assert scan.min_certified_lambda0("quadratic", "forward") == (0.1, 0.08, 0.06)


def test_scan_facts_find_where_the_energy_fails_and_on_which_half_of_the_disc(scan):
    f = scan.facts()
    assert (f["ch7_ep_mu_last"], f["ch7_ep_mu_fail"], f["ch7_ep_rear"], f["ch7_ep_front"]) == (0.1, 0.15, 1.0, 0.0)
    assert "at 1.00 of the azimuths over the rear half (270 to 90 deg), 0.00 over the front half" in \
        scan.certificate_summary()


def test_scan_facts_count_certified_cells_and_list_the_advance_ratios_of_each_outcome(scan):
    f = scan.facts()
    assert (f["ch7_lam_q0"], f["ch7_lam_q25"], f["ch7_lam_o0"], f["ch7_lam_o_min"], f["ch7_lam_o_max"]) == \
        (0.1, 0.06, 0.3, 0.2, 0.25)
    assert f["ch7_deg_o0"] == round(0.3 * 2.0, 2)
    assert f["ch7_fwd_opt_none_mu"] == ""  # the forward C.G.'s optimised function certifies every mu
    assert (f["ch7_energy_cert"], f["ch7_energy_cells"], f["ch7_qh_fw"], f["ch7_qh_hover"]) == (0, 36, 0, 12)
    assert (f["ch7_ncert_q_bwd"], f["ch7_ncert_o_bwd"], f["ch7_lam_q0_bwd"]) == (6, 4, 0.0019)
    assert (f["ch7_bwd_cert_mu"], f["ch7_bwd_s3_mu"], f["ch7_bwd_band_mu"]) == ("0", "", "")
    assert f["ch7_neu_opt_none_mu"] == "0.15"
    summary = scan.certificate_summary()
    assert "backward, Q = I: every azimuth certified at mu = 0; some azimuths at mu = 0.15" in summary.splitlines()
    assert "[]" not in summary and " | " not in summary  # no empty lists, no rows of the table below it


def test_scan_figure_has_a_panel_per_candidate_and_case_and_is_closed(scan):
    fig = scans.figure_scan(scan)
    assert len(fig.axes) == 18 and _closed(fig)
