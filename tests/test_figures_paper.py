"""Data and drawing functions of the reproduction figures (Figs 4-8), on coarse grids.

Each test names the fact it checks. The grids are far coarser than the book's; what is
checked is the structure of the data, the readings' labels and the physical facts the
chapters rest on.
"""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from rotorlyap.analysis.functions import energy_function  # noqa: E402
from rotorlyap.figures import paper  # noqa: E402
from rotorlyap.figures.export import figure_csv  # noqa: E402
from rotorlyap.conventions import DEFAULT_SCALES, PAPER_TEST_DISTURBANCES  # noqa: E402


@pytest.fixture(scope="module")
def trim():
    return paper.hover_trim_data(cg_values=(0.22, 0.25))


def test_fig4_thrust_equals_the_weight_for_every_trim(trim):
    assert np.allclose(trim.thrust, trim.weight, rtol=0, atol=1e-6)
    assert np.allclose(trim.case_thrust, trim.weight, rtol=0, atol=1e-6)
    assert trim.weight == pytest.approx(6400.0 * 9.80665)


def test_fig4_collective_decreases_as_the_cg_moves_aft_and_the_pitch_angle_stays(trim):
    assert trim.case_names == ("forward", "neutral", "backward")
    assert np.all(np.diff(trim.case_collective) < 0)
    assert np.ptp(trim.case_equilibrium[:, 2]) < np.radians(0.1)
    assert trim.equilibrium.shape == (2, 3) and trim.case_equilibrium.shape == (3, 3)


def test_fig4_draws_and_writes_its_csv(trim, tmp_path):
    fig, axes = plt.subplots(1, 2)
    paper.plot_hover_trim(trim, axes)
    plt.close(fig)
    out = figure_csv(trim, tmp_path / "trim.csv")
    assert out.read_text().startswith("field,")


def test_fig5_strict_positive_practical_zero_and_labelled():
    d = paper.hover_rate_data((0.23, 0.27), n_sphere=64, n_refine=4, n_fraction=512, n_grid=11)
    assert d.strict_label == "strict (certificate)"
    assert d.practical_label == "practical (indicator, not a certificate)"
    # the caution on the real model: W' > 0 on the sphere at every C.G., found by the search
    assert np.all(d.strict_max > 50.0)
    assert np.all(d.strict_positive_fraction > 0.05)
    # the argmax is mostly a pitch displacement with a flap rate
    assert np.all(np.abs(d.strict_argmax[:, 2]) > 0.8) and np.all(np.abs(d.strict_argmax[:, 3]) > 0.1)
    # and its work is the aerodynamic flap moment on the flap rate
    assert np.all(d.terms_aero[:, 0] > 0.9 * d.strict_max)
    # practical: pure displacements do no work, pure rates are damped
    assert np.all(d.practical_max <= 1e-9)
    disp = np.abs(d.test_disturbances[:, :3]).max(axis=1) > 0.5
    assert np.allclose(d.practical_dW[:, disp], 0.0, atol=1e-9)
    assert np.all(d.practical_dW[:, ~disp] < 0.0)
    # linear theory: stable forward, unstable backward (pitch-flap flutter)
    assert d.eig_max_real[0] < 0 < d.eig_max_real[1]
    assert d.slice_dW.shape == (11, 11)
    fig, axes = plt.subplots(2, 2)
    paper.plot_hover_rate(d, axes.ravel())
    plt.close(fig)


def test_fig6_energy_does_not_depend_on_azimuth_and_grows_as_A_squared():
    d = paper.w_spheres_data("forward", 0.15, (0.5, 1.0, 2.0), n_psi=6, n_sphere=16)
    assert d.strict_inf.shape == (3, 6) and d.practical_max.shape == (3, 6)
    assert np.allclose(d.strict_inf, d.strict_inf[:, :1], rtol=1e-9)
    assert np.all(np.diff(d.strict_inf.mean(axis=1)) > 0)
    ratio = d.strict_inf.mean(axis=1) / d.A_values ** 2
    assert np.allclose(ratio, ratio[0], rtol=0.02)
    assert np.all(d.strict_inf <= d.practical_min + 1e-12)
    assert np.all(d.strict_sup >= d.practical_max - 1e-12)
    fig, axes = plt.subplots(1, 2)
    paper.plot_w_spheres(d, axes)
    plt.close(fig)


def test_fig7_shapes_hover_zero_and_forward_flight_positive():
    """Pure displacement disturbances (zero rates) have W' = 0 exactly, so the practical maximum
    is never negative; in hover it is 0 (damping only), about the hover equilibrium reused at
    mu = 0.15 a rate disturbance gains energy at most azimuths."""
    d = paper.rate_azimuth_data("forward", (0.0, 0.15), n_psi=8, n_sphere=16)
    assert d.strict_max.shape == (2, 8) == d.practical_max.shape
    assert np.allclose(d.practical_max[0], 0.0, atol=1e-9)
    assert np.all(d.practical_max[1] >= 0) and (d.practical_max[1] > 1.0).sum() >= 5
    assert np.all(d.strict_max >= d.practical_max - 1e-9)
    fig, axes = plt.subplots(1, 2)
    paper.plot_rate_azimuth(d, axes)
    plt.close(fig)


@pytest.fixture(scope="module")
def regions():
    return paper.regions_data(("forward",), (0.0, 0.1), reading="practical", n_psi=8)


def test_fig8_practical_reading_is_labelled_and_hover_is_indicated_stable(regions):
    assert regions.reading == "practical"
    assert regions.label == "practical (indicator, not a certificate)"
    assert regions.category.shape == (1, 2, 8) == regions.stable.shape
    assert regions.stable[0, 0].all()
    assert not regions.stable[0, 1].any()
    assert set(np.unique(regions.category)) <= {0, 1, 2, 3}


def test_fig8_strict_reading_is_labelled_and_certifies_nothing_in_hover():
    reg = paper.regions_data(("forward",), (0.0,), reading="strict", n_psi=4, n_sphere=64)
    assert reg.label == "strict (certificate)"
    assert not reg.stable.any()
    assert np.all(reg.A_used == 0.0)


def test_fig8_polar_plot_puts_the_tail_at_psi_0_and_the_advancing_side_at_psi_90(regions):
    fig = plt.figure()
    ax = fig.add_subplot(projection="polar")
    paper.plot_regions_polar(regions, ax, 0)
    # psi = 0 points down (the tail), psi increases counter-clockwise: psi = 90 deg is on the right
    assert np.cos(ax.get_theta_offset()) == pytest.approx(0.0, abs=1e-12)
    assert np.sin(ax.get_theta_offset()) == pytest.approx(-1.0)
    assert ax.get_theta_direction() == 1
    to_xy = lambda th: (np.cos(th * ax.get_theta_direction() + ax.get_theta_offset()),  # noqa: E731
                        np.sin(th * ax.get_theta_direction() + ax.get_theta_offset()))
    assert to_xy(0.0)[1] == pytest.approx(-1.0)
    assert to_xy(np.pi / 2)[0] == pytest.approx(1.0)
    fig.canvas.draw()
    labels = {lab.get_text(): theta for lab, theta in zip(ax.get_xticklabels(), ax.get_xticks())}
    for word, angle in (("advancing", 90), ("retreating", 270), ("tail", 0), ("nose", 180)):
        [(text, theta)] = [(k, v) for k, v in labels.items() if word in k]
        assert theta == pytest.approx(np.radians(angle)), word
    plt.close(fig)


def test_fig8_reverse_flow_reaches_the_root_only_on_the_retreating_side():
    p = paper.case_params("forward")
    psi = np.radians([90.0, 270.0])
    b = paper.reverse_flow_boundary(p, psi)
    assert np.isinf(b[0])
    assert b[1] == pytest.approx(p.root_r_over_R)


def test_fig8_plane_plot_draws(regions):
    fig, ax = plt.subplots()
    paper.plot_regions_plane(regions, ax, 0)
    plt.close(fig)


def test_balanced_scales_give_every_axis_the_same_energy():
    from rotorlyap import Blade

    p = paper.case_params("forward")
    a = paper.balanced_scales(p)
    fun = energy_function(Blade(p, 0.0))
    w = fun.W(0.0, np.eye(6) * a)
    assert np.ptp(w) / w.mean() < 0.05
    assert np.all(DEFAULT_SCALES > 0)


def test_sensitivity_variants_keep_their_labels_and_directions():
    d = paper.sensitivity_data("forward", (0.0, 0.1), {"default": {}, "flap-lag": dict(
        test_disturbances=paper.FLAP_LAG_TEST_DISTURBANCES)}, n_psi=4)
    assert d.names == ("default", "flap-lag")
    assert d.n_tests == (12, 8)
    assert all(r.reading == "practical" for r in d.regions)
    assert len(d.first_unstable()) == 2
    fig, axes = plt.subplots(1, 3)
    paper.plot_sensitivity(d, axes)
    plt.close(fig)


def test_practical_threshold_is_below_the_first_forward_flight_grid_point():
    mu = paper.practical_threshold_mu("forward", mu_lo=1e-4, n_psi=8, n_bisect=2)
    assert 0 < mu <= paper.MU_GRID[1]


def test_paper_test_disturbances_are_the_twelve_signed_axes():
    assert PAPER_TEST_DISTURBANCES.shape == (12, 6)
    assert paper.AXES_AND_DIAGONALS.shape == (72, 6)
    assert paper.FLAP_LAG_TEST_DISTURBANCES.shape == (8, 6)
    assert np.all(paper.FLAP_LAG_TEST_DISTURBANCES[:, [2, 5]] == 0)


def test_markdown_table_escapes_pipes():
    t = paper.markdown_table(("a", "b"), [("x|y", "z")])
    assert t.splitlines()[0] == "| a | b |"
    assert "x\\|y" in t
