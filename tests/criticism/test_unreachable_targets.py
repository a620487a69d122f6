"""A material whose every target is out of reach still gets its uncertainty tables and figures."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import quadratic_terms
from demid.io import save_figure
from demid.sampling.domain import Domain
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate, fit_response
from demid.uncertainty import analyse_material
from demid.story.measurements import measurement_order
from demid.uncertainty.ranking import reachable_targets

from ..helpers import make_ccd_table


def _material(y2_target):
    table = make_ccd_table(lambda x: {"y1": 100 + 20 * x[:, 0] - 2 * x[:, 1] + 10 * x[:, 0] ** 2,
                                      "y2": 80 + 5 * x[:, 0] + 3 * x[:, 1] - 0.1 * x[:, 1] ** 2},
                           [0.1, 1.0], [0.9, 11.0], noise=0.3, seed=8, decimals=3)
    cfg = MaterialSpec.from_material("m", {
        "data": "t.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1.0, "upper": 11.0}},
        "responses": {"y1": {"target": 10 * table["y1"].max()}, "y2": {"target": y2_target}},
        "scenarios": {"y1_only": {"observables": ["y1"], "tolerance": 0.02},
                      "both": {"observables": ["y1", "y2"], "tolerance": 0.02}}})
    surrogates = {r: fit_response(table, ["x1", "x2"], r, alpha=1.41421).surrogate() for r in ("y1", "y2")}
    return surrogates, cfg


def test_every_target_out_of_reach_still_draws_sweep_and_posterior(tmp_path):
    surrogates, cfg = _material(y2_target=95.0)
    result = analyse_material(surrogates, cfg, z=2.0, tolerances=[0.01, 0.05, 0.2])
    sweep = result.sweep
    sets_with_y1 = sweep[sweep["observables"].str.contains("y1")]
    assert (sets_with_y1["feasible_fraction_pct"] == 0).all()
    save_figure(result.sweep_figure("unreachable"), tmp_path / "sweep.png")
    save_figure(result.posterior_figure("unreachable"), tmp_path / "posterior.png")
    assert (tmp_path / "sweep.png").stat().st_size > 0 and (tmp_path / "posterior.png").stat().st_size > 0
    assert np.isfinite(result.ranking.select_dtypes("number").to_numpy(dtype=float)).any()
    # y1's target (ten times its largest run) is out of reach: no set with it carries information
    with_y1 = result.ranking["observables"].str.contains("y1")
    assert not result.ranking.loc[with_y1, "targets_reachable"].any()
    assert result.ranking.loc[with_y1, "information_gain_bits"].isna().all()


def _linear(name: str, j: int) -> Surrogate:
    """y = 10 + 10 x_j on [0, 1]^2: reaches exactly [10, 20]."""
    coef = np.zeros(6)
    coef[0], coef[1 + j] = 10.0, 10.0
    return Surrogate(name, ["x", "w"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)


def _linear_material(y1_target: float) -> tuple[dict, MaterialSpec]:
    surrogates = {"y1": _linear("y1", 0), "y2": _linear("y2", 1)}
    cfg = MaterialSpec.from_material("m", {
        "data": "t.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 1},
        "factors": {"x": {"lower": 0.0, "upper": 1.0}, "w": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y1": {"target": y1_target}, "y2": {"target": 15.0}},
        "scenarios": {"both": {"observables": ["y1", "y2"], "tolerance": 0.02}}})
    return surrogates, cfg


def test_reachability_is_the_closest_approach_within_tolerance():
    surrogates, _ = _linear_material(21.0)
    domain = Domain(("x", "w"), (0.0, 0.0), (1.0, 1.0))
    # closest approaches: 21 -> |20 - 21| / 21 = 4.8 % > 2 %; 20.3 -> 1.5 % <= 2 % (a set 1 % of the range thin)
    for target, reachable in ((21.0, False), (20.3, True), (20.4, True), (20.5, False)):
        found = reachable_targets(surrogates, domain, ["y1", "y2"], {"y1": target, "y2": 15.0}, 0.02,
                                  {"y1": 0.0, "y2": 0.06})  # a sample that missed the y1 set entirely
        assert found == {"y1": reachable, "y2": True}, target


def test_sets_with_an_unreachable_target_rank_last_without_a_gain():
    surrogates, cfg = _linear_material(21.0)
    result = analyse_material(surrogates, cfg, tolerances=[0.02, 0.1])
    ranking = result.ranking.set_index("observables")
    assert ranking.loc["y2", "targets_reachable"] and ranking.loc["y2", "rank"] == 1
    for name in ("y1", "y1+y2"):
        assert not ranking.loc[name, "targets_reachable"]
        assert np.isnan(ranking.loc[name, "information_gain_bits"])
        assert np.isnan(ranking.loc[name, "gain_vs_best_subset_bits"])
        assert ranking.loc[name, "rank"] > 1
    assert list(result.ranking.columns[-1:]) == ["targets_reachable"]
    gains = result.information_gain
    assert gains.loc[gains["observables"].str.contains("y1"), "information_gain_bits"].isna().all()
    assert gains.loc[gains["observables"] == "y2", "information_gain_bits"].notna().all()
    advice = measurement_order(result.ranking, cfg.response_labels)
    assert "discrepancy between simulation and experiment" in advice[0]
    assert "y1" not in " ".join(advice[1:])  # the advice proper leaves the unreachable target out
    assert result.unreachable == ("y1", "y1+y2")
    assert [n for n in result.notes if n.startswith("Sets with targets out of reach (y1, y1+y2): no point")]
    assert not [n for n in result.notes if n.startswith("No scenarios configured")]
    reachable, _ = _linear_material(19.0)
    ranked = analyse_material(reachable, _linear_material(19.0)[1], tolerances=[0.02]).ranking
    assert ranked["targets_reachable"].all() and ranked["information_gain_bits"].notna().all()
    assert "discrepancy" not in " ".join(measurement_order(ranked))


def _same_direction(t1: float, t2: float) -> tuple[dict, dict]:
    """y1 = y2 = 10 + 10 x on [0, 1]^2: every target in [10, 20] is reachable alone; 12 and 18 together would
    need x = 0.2 and x = 0.8 at once."""
    surrogates = {"y1": _linear("y1", 0), "y2": _linear("y2", 0)}
    cfg = {"data": "t.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 1},
           "factors": {"x": {"lower": 0.0, "upper": 1.0}, "w": {"lower": 0.0, "upper": 1.0}},
           "responses": {"y1": {"target": t1}, "y2": {"target": t2}},
           "scenarios": {"both": {"observables": ["y1", "y2"], "tolerance": 0.02}}}
    return surrogates, cfg


def test_targets_that_cannot_be_met_together_are_a_discrepancy_not_information():
    """Each target reachable alone, both together at no point: the set's posterior sat at the compromise and
    ranked first with the most 'information'.  It ranks last without a gain; targets that can be met together
    (12 and 12.1: x in [0.196, 0.204] and [0.197, 0.206]) keep theirs."""
    surrogates, cfg = _same_direction(12.0, 18.0)
    ranking = analyse_material(surrogates, MaterialSpec.from_material("m", cfg),
                               tolerances=[0.02, 0.1]).ranking.set_index("observables")
    assert ranking.loc["y1", "targets_reachable"] and ranking.loc["y2", "targets_reachable"]
    assert not ranking.loc["y1+y2", "targets_reachable"] and np.isnan(ranking.loc["y1+y2", "information_gain_bits"])
    assert ranking.loc["y1+y2", "rank"] == 3 and ranking.loc["y1+y2", "rank_by_fraction"] == 3
    advice = " ".join(measurement_order(ranking.reset_index()))
    assert "The targets of y1 + y2 can each be met but not together within the tolerance" in advice
    surrogates, cfg = _same_direction(12.0, 12.1)
    ranking = analyse_material(surrogates, MaterialSpec.from_material("m", cfg),
                               tolerances=[0.02, 0.1]).ranking.set_index("observables")
    assert ranking.loc["y1+y2", "targets_reachable"] and np.isfinite(ranking.loc["y1+y2", "information_gain_bits"])


def test_the_gain_over_best_subset_is_the_gain_over_that_subset():
    """best_subset is the proper subset with the smallest feasible fraction; the gain column was taken over the
    subset with the largest gain instead, so 'Measure X as well: it adds N bits' could name N of another set.
    Here y1 is narrow at the tolerance but measured loosely (small gain), y2 wide but measured tightly."""
    surrogates = {"y1": _linear("y1", 0), "y2": _linear("y2", 1)}
    surrogates["y2"] = Surrogate("y2", ["x", "w"], quadratic_terms(2), np.array([10.0, 0, 2.0, 0, 0, 0]),
                                 np.zeros((6, 6)), 0.0, 7)
    cfg = {"data": "t.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 1},
           "factors": {"x": {"lower": 0.0, "upper": 1.0}, "w": {"lower": 0.0, "upper": 1.0}},
           "responses": {"y1": {"target": 15.0, "sigma_rel": 0.2}, "y2": {"target": 11.0, "sigma_rel": 0.002}},
           "scenarios": {"both": {"observables": ["y1", "y2"], "tolerance": 0.02}}}
    ranking = analyse_material(surrogates, MaterialSpec.from_material("m", cfg),
                               tolerances=[0.02, 0.1]).ranking.set_index("observables")
    assert ranking.loc["y1+y2", "best_subset"] == "y1"  # premise: y1 is the narrower set ...
    assert ranking.loc["y2", "information_gain_bits"] > ranking.loc["y1", "information_gain_bits"]  # ... y2 gains more
    for name, row in ranking.iterrows():
        if row["n_observables"] > 1:
            base = ranking.loc[row["best_subset"], "information_gain_bits"]
            assert row["gain_vs_best_subset_bits"] == pytest.approx(row["information_gain_bits"] - base), name


@pytest.mark.parametrize("seed", [5, 66, 101, 112, 113, 0, 1, 2])
def test_targets_met_exactly_at_an_interior_point_are_met_together(seed):
    """Five factors, three observables whose targets are their values at one interior point: a simplex
    search on the largest error stalled on its kink and called such sets unreachable (11 of 200 seeds; the
    first five here are such, the last three not)."""
    from demid.uncertainty.ranking import _met_together

    rng = np.random.default_rng(seed)
    names, terms = [f"x{i}" for i in range(5)], quadratic_terms(5)
    surrogates = {f"y{j}": Surrogate(f"y{j}", names, terms, np.r_[20.0, rng.normal(0, 8, len(terms) - 1)],
                                     np.zeros((len(terms), len(terms))), 0.0, 30) for j in range(3)}
    domain = Domain(tuple(names), (0.0,) * 5, (1.0,) * 5)
    inside = rng.uniform(0.1, 0.9, 5)[None, :]
    targets = {o: float(s.predict(inside)[0]) for o, s in surrogates.items()}
    assert _met_together(surrogates, domain, list(surrogates), targets, 0.01)
    far = {o: t * (1.5 if o == "y0" else 1.0) for o, t in targets.items()}  # premise: the search can say no
    reach_y0 = _met_together(surrogates, domain, ["y0"], far, 0.01)
    assert reach_y0 or not _met_together(surrogates, domain, list(surrogates), far, 0.01)
