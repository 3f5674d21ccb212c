"""What the chapter "How large a disturbance" gathers and prints (rotorlyap.chapters.large_disturbances).

Each test names the fact it checks. The chapter's own numbers are compared by nbval; here the
data object is checked against the functions it gathers (one hover case with the quadratic
function alone, in two worker processes), its reading of the design program's attempts on made-up
attempts, and its figures for legibility.
"""

import dataclasses

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from rotorlyap import certify  # noqa: E402
from rotorlyap.analysis.certify import Candidate  # noqa: E402
from rotorlyap.analysis.sweep import process_map  # noqa: E402
from rotorlyap.conventions import DEFAULT_SCALES  # noqa: E402
from rotorlyap.chapters import large_disturbances as chapter  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402


@pytest.fixture(scope="module")
def data():
    case = dataclasses.replace(chapter.CASES[0], function="quadratic", file=None)
    return chapter.large_disturbances([case], workers=2)


def _square(x):
    return x * x


def test_process_map_keeps_the_order_of_the_items_whatever_finishes_first():
    assert process_map(_square, [3, 1, 2], workers=2) == [9, 1, 4]
    with pytest.raises(ValueError, match="workers must be >= 1"):
        process_map(_square, [1], workers=0)


@pytest.mark.slow
def test_a_case_holds_the_certificate_certify_gives_and_its_yardstick(data):
    r = data["forward"]
    direct = certify(r.case.params(), 0.0, condition="none", function="quadratic", scales=r.case.scales)
    (cand,) = r.candidates
    assert cand.function == "quadratic" and cand.certified
    assert cand.start_region == pytest.approx(direct.start_region, rel=1e-9)  # same numbers in a worker
    per_hinge = direct.start_region_per_hinge
    assert r.per_component(cand.start_region)[0] == pytest.approx(per_hinge["flap"][0], rel=1e-12)
    assert r.per_component(cand.start_region)[3] == pytest.approx(per_hinge["flap"][1], rel=1e-12)
    # the yardstick in the same units: deg and deg/s of the region's own per-hinge reading
    assert r.simulated[1] == pytest.approx(r.region.per_hinge["lag"][0], rel=1e-12)
    assert r.simulated[4] == pytest.approx(r.region.per_hinge["lag"][1], rel=1e-12)
    # the certificate starts inside the region of stable motion, along every component
    assert np.all(r.reach("quadratic") < 1.0)
    assert np.all(np.isnan(r.reach("energy")))
    # the start set holds the ball and is certify's, per hinge in the same units; it too lies
    # inside the region of stable motion (a start set beyond the simulated region would be false)
    assert np.all(r.set_reach("quadratic") >= r.reach("quadratic")) and np.all(r.set_reach("quadratic") < 1.0)
    whole = r.per_component(np.asarray(cand.start_set))
    assert whole[2] == pytest.approx(direct.start_set_per_hinge["pitch"][0], rel=1e-9)
    # the slices' start set holds its inner ball's points and nothing beyond the bound
    axis, inside = r.set_slices["flap-lag"]
    yi, yj = np.meshgrid(axis, axis, indexing="ij")
    rho = np.hypot(yi, yj)
    assert np.all(inside[rho < 0.999 * cand.start_region]) and not np.any(inside[rho >= cand.bound])
    # the strips' angles of attack at the bound along each hinge (hover): flapping up (a positive
    # flap rate) lowers every strip's angle of attack below the equilibrium's, flapping down raises
    # it, and the stalled strips counted are those past the airfoil's stall angles
    ba = r.bound_angles
    assert ba is not None and ba.A == pytest.approx(cand.bound, rel=1e-12)
    blade = direct.lyapunov.blade
    rest = blade.angle_of_attack(0.0, direct.lyapunov.steady.state)
    assert np.all(ba.angles[3, 0] < rest) and np.all(ba.angles[3, 1] > rest)
    for i in range(6):
        for k, sign in ((0, 1), (1, -1)):
            a = ba.angles[i, k]
            assert ba.stalled(i, sign) == np.sum((a > ba.alpha_stall) | (a < ba.alpha_stall_negative))
    assert "strips' angles of attack" in data.summary()


@pytest.mark.slow
def test_the_table_csv_and_figures_are_made_from_the_data(data, tmp_path):
    table = data.markdown()
    assert table.count("\n") == 1 + 3  # header, rule, then the yardstick and one function's set and ball
    assert "quadratic function: start set" in table and "quadratic function: start ball" in table
    assert "augmented energy" not in table
    facts = data.facts()
    assert facts["ch11_forward_chosen"] == "quadratic function"
    assert "ch11_gain_lo" not in facts  # no designed function: no gain to quote
    path = figure_csv(data.export(), tmp_path / "d.csv")
    assert path.read_text().splitlines()[0].startswith("case,quantity,beta")
    chapter.figure_reach(data)
    chapter.figure_slices(data, keys=("forward",))


def _result(tried):
    region = type("Region", (), {"component_extent": np.full(6, 10.0)})()
    cand = Candidate("energy", True, 8.0, 3.0, "ok", tried)
    return chapter.CaseResult(chapter.CASES[0], 10.0, np.asarray(DEFAULT_SCALES), -0.1, "energy", (cand,), region)


def test_the_limit_is_read_from_the_design_the_certificate_rests_on():
    # the search's attempts, then the thorough re-designs: 3.2 failed thoroughly, 1.6 passed
    tried = ((0.8, 2.0, True), (1.6, 4.0, True), (3.2, 8.0, True), (6.4, 16.0, False), (4.5, 11.0, False),
             (3.2, 8.0, False), (1.6, 4.0, True))
    assert _result(tried).limit("energy") == (1.6, 3.2)
    # the largest success hardened at once, then a bisection step above it that failed last
    tried = ((0.8, 2.0, True), (1.6, 4.0, True), (3.2, 8.0, True), (6.4, 16.0, False), (3.2, 8.0, True),
             (4.5, 11.0, False))
    assert _result(tried).limit("energy") == (3.2, 4.5)
    # nothing larger failed: no limit found by the program
    assert np.isnan(_result(((0.8, 2.0, True), (0.8, 2.0, True))).limit("energy")[1])
    # the last attempt failed: the design was not made
    assert all(np.isnan(_result(((0.8, 2.0, False),)).limit("energy")))


def test_anatomy_measures_the_energy_share_and_the_sign_of_w_dot_beyond_the_bound():
    """A made-up function of two basis functions, "energy" = |y|^2 and y_0^2 (coefficients 1, 1),
    along y' = -y + y^3: W' = sum 2 y_i^2 (y_i^2 - 1) + 2 y_0^2 (y_0^2 - 1). On the sphere
    |y| = r the mean of y_0^2 is r^2 / 6, so the energy's share of W is 6 / 7; W' < 0 wherever
    every |y_i| < 1 (so on the sphere 0.9), and on the sphere 1.125 it is largest along y_0."""

    from types import SimpleNamespace

    from rotorlyap.methods.scenario import Basis, BasisFunction

    a = np.ones(6)

    def f(psi, x):
        return -x + x ** 3

    basis = Basis(("energy", "y0^2"),
                  lambda psi, x: np.column_stack([np.sum(x * x, axis=1), x[:, 0] ** 2]),
                  lambda psi, x: np.column_stack([np.sum(2 * x * f(psi, x), axis=1), 2 * x[:, 0] * f(psi, x)[:, 0]]))
    fun = SimpleNamespace(function=BasisFunction(basis, np.array([1.0, 1.0]), f), scales=a, autonomous=True)
    an = chapter.anatomy(fun, A=0.9, lam0=0.5, samples=1024)
    assert an.energy_share == pytest.approx(6 / 7, rel=0.02)
    assert an.max_dw[0] < 0 and an.positive_fraction[0] == 0.0  # radius 1 A = 0.9
    k = chapter.ANATOMY_RADII.index(1.25)  # radius 1.125
    assert an.max_dw[k] > 0 and abs(an.direction[k][0]) > 0.9
    assert an.energy_dw[k] > 0  # |y|^2 grows there too (the "energy" term is the whole |y|^2)


def test_anatomy_finds_a_positive_cap_of_w_dot_that_its_sample_misses():
    """W' = |y|^2 (1.5 (u . u*)^40 - 1), u = y / |y|: positive only within about 0.14 rad of the
    direction u* (where it is |y|^2 / 2), a cap no sampled direction hits, but W' grows towards it
    from the best samples, so the search from them finds it: the largest W' on each sphere is
    r^2 / 2 along u*, although no sampled state has W' >= 0."""
    from types import SimpleNamespace

    from rotorlyap.methods.scenario import Basis, BasisFunction

    a = np.ones(6)
    star = np.array([0.3, -0.5, 0.2, 0.6, -0.1, 0.5])
    star /= np.linalg.norm(star)

    def rate(psi, x):
        r2 = np.sum(x * x, axis=1)
        g = np.clip(x @ star / np.sqrt(r2), 0.0, None) ** 40
        return r2 * (1.5 * g - 1.0)

    basis = Basis(("energy",), lambda psi, x: np.sum(x * x, axis=1)[:, None], lambda psi, x: rate(psi, x)[:, None])
    fun = SimpleNamespace(function=BasisFunction(basis, np.array([1.0]), None), scales=a, autonomous=True)
    an = chapter.anatomy(fun, A=1.0, lam0=0.5, samples=1024)
    assert all(fr == 0.0 for fr in an.positive_fraction)
    for k, m, d in zip(an.radii, an.max_dw, an.direction):
        assert m == pytest.approx(0.5 * k ** 2, rel=1e-6)
        assert np.dot(d, star) == pytest.approx(1.0, abs=1e-6)


@pytest.mark.slow
def test_a_case_with_a_certificate_file_verifies_it_and_keeps_it_beside_the_quadratic_function(tmp_path):
    """A case that names a certificate file reads and verifies it (its verdict printed in the
    summary), lists it beside the quadratic function it computes, and takes it as the chapter's
    certificate where its start region is larger; a file of another case is refused."""
    params = chapter.CASES[0].params()
    certify(params, 0.0, condition="none", function="quadratic", A=0.5,
            scales=chapter.CASES[0].scales).save(tmp_path / "small.json")  # in the case's norm
    case = dataclasses.replace(chapter.CASES[0], function="quadratic", file="small.json")
    kind, _, folder = "certificate", case, tmp_path
    out = chapter._compute((kind, case, folder))
    chosen, candidates, verification = out[3], out[4], out[8]
    assert [c.function for c in candidates] == ["quadratic", "quadratic"]
    assert candidates[1].certified and candidates[1].bound == pytest.approx(0.5)
    assert verification.startswith("VERIFIED") and chosen == "quadratic"
    other = dataclasses.replace(case, mu=0.1)
    with pytest.raises(ValueError, match="a certificate of another case"):
        chapter._compute((kind, other, folder))
