"""Level-1 and level-2 findings in words (criticism.messages), read back number by number: the gain of an extension
against the leave-one-out errors it was computed from (its 0.995/1.005 band included), the runs and values an
outlier, a slip, a drift and unequal scatter quote, the aliased terms listed, and the observable level 2 names as the
worst against its own tolerance.  Expected values are computed here from the inputs, not read from the module."""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np
import pytest

from demid.criticism.catalogue import Hypothesis
from demid.criticism.messages import and_list, finding_message, level2_miss_text, percent_text


def _data(runs, factors=("e", "mu"), simulated=False):
    runs = np.asarray(runs)
    return SimpleNamespace(response="angle", runs=runs, factors=list(factors), simulated=simulated, n=len(runs))


def _gain(text: str) -> tuple[str, float | None]:
    """The gain clause of a finding: ("cut", %), ("loss", %), ("unchanged", None) or ("none", None)."""
    if (m := re.search(r"cuts the leave-one-out error by (\d+) %", text)):
        return "cut", float(m.group(1))
    if (m := re.search(r"does not reduce the leave-one-out error \(\+(\d+) %\)", text)):
        return "loss", float(m.group(1))
    if "leaves the leave-one-out error unchanged" in text:
        return "unchanged", None
    assert "could not be computed" in text
    return "none", None


def _check_gain(text: str, before: float, after: float) -> None:
    kind, pct = _gain(text)
    if not (np.isfinite(before) and np.isfinite(after) and before > 0):
        assert kind == "none"
        return
    change = 100 * (after - before) / before  # negative: the extension cuts the error
    if change < -0.5:
        assert kind == "cut" and abs(pct - (-change)) <= 0.5 + 1e-9
    elif change <= 0.5:
        assert kind == "unchanged"
    else:
        assert kind == "loss" and abs(pct - change) <= 0.5 + 1e-9


# before, after: cuts and losses of several sizes, both edges of the unchanged band, and what cannot be computed
GAINS = [(2.0, 1.2), (1.0, 0.1), (0.3, 0.29), (1000.0, 994.0), (1000.0, 995.0), (1000.0, 996.0),
         (1000.0, 1004.0), (1000.0, 1005.0), (1000.0, 1006.0), (1.0, 1.03), (0.5, 1.0), (4.0, 13.0),
         (0.0, 1.0), (1.0, float("nan")), (float("inf"), 1.0)]


@pytest.mark.parametrize("seed, before, after", [(i, *g) for i, g in enumerate(GAINS)])
def test_an_outlier_finding_quotes_its_run_values_and_gain(seed, before, after):
    rng = np.random.default_rng(seed)
    runs = np.sort(rng.choice(np.arange(1, 60), size=9, replace=False))
    k = int(rng.integers(0, 9))
    observed, predicted = float(rng.normal(30, 5)), float(rng.normal(30, 5))
    h = Hypothesis("outlier", k, statistic=float(rng.normal(0, 4)))
    info = {"observed": observed, "predicted_without": predicted}
    simulated = seed % 2 == 1  # demid's own runs: no transcription error to blame
    text = finding_message(_data(runs, simulated=simulated), h, info, before, after, 8, [], None)
    assert ("demid simulated that run itself" in text) == simulated
    assert ("a transcription or export error is the usual cause" in text) == (not simulated)
    found = re.search(r"run (\S+) does not fit the other runs \(observed (\S+), the other runs predict (\S+), "
                      r"externally studentised residual (\S+)\);", text)
    assert found, text
    assert int(found.group(1)) == runs[k]
    assert float(found.group(2)) == pytest.approx(observed, rel=1e-3)
    assert float(found.group(3)) == pytest.approx(predicted, rel=1e-3)
    assert float(found.group(4)) == pytest.approx(h.statistic, abs=0.05)
    assert "on the other 8 runs" in text
    _check_gain(text, before, after)


@pytest.mark.parametrize("ratio", [0.25, 0.6, 0.99, 1.0, 1.7, 4.4])
def test_unequal_scatter_is_quoted_as_the_larger_over_the_smaller_spread(ratio):
    h = Hypothesis("heteroscedasticity", "e")
    text = finding_message(_data([1, 2, 3]), h, {"sd_ratio": ratio}, 1.0, 0.5, 3, [], None)
    found = re.search(r"the scatter of the runs (grows|shrinks) with e \(residual spread about (\S+) times larger at "
                      r"the (high|low) end", text)
    assert found, text
    grows = ratio >= 1
    assert (found.group(1), found.group(3)) == (("grows", "high") if grows else ("shrinks", "low"))
    assert float(found.group(2)) >= 1.0 and float(found.group(2)) == pytest.approx(max(ratio, 1 / ratio), abs=0.05)
    _check_gain(text, 1.0, 0.5)


@pytest.mark.parametrize("runs", [[1, 2, 3, 4, 5], [3, 7, 8, 20], [10, 11, 40, 41, 42, 100]])
@pytest.mark.parametrize("slope", [0.25, -0.031])
def test_a_drift_quotes_its_slope_and_the_change_from_first_to_last_run(runs, slope):
    h = Hypothesis("drift", None)
    text = finding_message(_data(runs), h, {"drift_per_run": slope}, 2.0, 1.0, len(runs), [], None)
    found = re.search(r"\((\S+) per run, (\S+) from first to last run\)", text)
    assert found, text
    assert float(found.group(1)) == pytest.approx(slope, rel=5e-3)
    assert float(found.group(2)) == pytest.approx(slope * (max(runs) - min(runs)), rel=5e-3)
    assert found.group(2)[0] == ("+" if slope > 0 else "-")


@pytest.mark.parametrize("aliases", [["e:mu^2"], ["e:mu^2", "e^3"], ["e:mu^2", "e^3", "mu^3", "e^2:mu"]])
def test_a_missing_term_names_its_aliases_and_the_runs_that_tell_them_apart(aliases):
    h = Hypothesis("missing_term", SimpleNamespace(terms=[(1, 2)]), aliases=list(aliases))
    points = [{"e": 0.5, "mu": 0.125}, {"e": -1.0, "mu": 2.0}]
    text = finding_message(_data([1, 2, 3]), h, {}, 1.0, 0.7, 3, points, None)
    assert "misses a change of the mu curvature with e (term e:mu^2" in text
    others = aliases[1:]
    if others:
        listed = re.search(r", aliased with (.+) in this design\)", text).group(1)
        assert listed == (others[0] if len(others) == 1 else ", ".join(others[:-1]) + " and " + others[-1])
        assert f" Extra runs at (e=0.5, mu=0.125) and (e=-1, mu=2) would tell the " \
               f"{'two' if len(aliases) == 2 else len(aliases)} apart." in text
    else:
        assert "aliased" not in text and "Extra runs" not in text
    _check_gain(text, 1.0, 0.7)


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_and_list_joins_every_name_once_with_and_before_the_last(n):
    names = [f"t{i}" for i in range(n)]
    text = and_list(names)
    head, _, last = text.rpartition(" and ")
    assert last == names[-1] and (head.split(", ") if n > 1 else [text]) == (names[:-1] if n > 1 else names)


def _parse_miss(text: str):
    found = re.fullmatch(r"(\S+) by (\S+) % \((\S+) times its tolerance of (\S+) %\)", text)
    assert found, text
    return found.group(1), float(found.group(2)), float(found.group(3)), float(found.group(4))


@pytest.mark.parametrize("seed", range(6))
def test_level2_names_the_worst_observable_against_its_own_tolerance(seed):
    rng = np.random.default_rng(seed)
    names = ["d5", "d10", "rho", "aor"][: 2 + seed % 3]
    tolerances = {o: float(rng.choice([0.005, 0.02, 0.1])) for o in names}
    tolerances[names[0]] = 0.003 if tolerances[names[0]] != 0.003 else 0.1  # never all the same
    errors = {o: float(rng.uniform(-0.2, 0.2)) for o in names}
    text = level2_miss_text(errors, 0.05, tolerances)
    worst = max(names, key=lambda o: abs(errors[o]) / tolerances[o])
    name, pct, times, tol = _parse_miss(text)
    assert name == worst
    assert pct == pytest.approx(100 * abs(errors[worst]), rel=0.01)
    assert times == pytest.approx(abs(errors[worst]) / tolerances[worst], rel=0.03)
    assert tol == pytest.approx(100 * tolerances[worst], rel=1e-6)


def test_the_larger_raw_error_is_not_the_worst_when_its_tolerance_is_wider():
    text = level2_miss_text({"d5": 0.08, "rho": -0.01}, 0.05, {"d5": 0.1, "rho": 0.002})
    assert _parse_miss(text) == ("rho", 1.0, 5.0, 0.2)


@pytest.mark.parametrize("errors", [{"a": 0.031, "b": -0.004}, {"a": -0.12, "b": 0.07, "c": 0.0}])
def test_with_one_tolerance_level2_quotes_the_largest_error(errors):
    largest = max(abs(e) for e in errors.values())
    assert level2_miss_text(errors, 0.05, None) == f"by {percent_text(largest)}"
    assert level2_miss_text(errors, 0.05, {o: 0.05 for o in errors}, at_most=True) == f"by at most {percent_text(largest)}"


@pytest.mark.parametrize("seed", range(8))
def test_corner_only_runs_counts_the_runs_that_carry_a_three_factor_product(seed):
    from demid.criticism.messages import corner_only_runs

    rng = np.random.default_rng(seed)
    n = int(rng.integers(4, 12))
    # coded levels with many zeros: from no run carrying x1*x2*x3 to one, several or every run carrying it
    zero_share = [0.0, 0.3, 0.6, 0.9][seed % 4]
    coded = rng.choice([-1.0, 1.0, 1.5], size=(n, 3)) * (rng.random((n, 3)) >= zero_share)
    if seed == 5:
        coded[:] = 0.0
        coded[int(rng.integers(n))] = [1.0, -1.0, 1.0]  # one corner run alone
    carried = int(np.sum(np.all(coded != 0, axis=1)))
    data = SimpleNamespace(coded=coded, n=n)
    assert corner_only_runs(data, (1, 1, 1)) == (carried if 0 < carried < n else 0)
    assert corner_only_runs(data, (1, 1, 0)) == 0 and corner_only_runs(data, (2, 1, 0)) == 0
    four = SimpleNamespace(coded=np.hstack([coded, np.ones((n, 1))]), n=n)
    assert corner_only_runs(four, (1, 1, 1, 1)) == 0


@pytest.mark.parametrize("lam, scale", [(0.0, "log"), (0.5, "square-root"), (-1.0, "reciprocal"), (0.3, None),
                                        (0.51, None), (2.0, None)])
def test_a_transform_finding_names_its_scale_and_quotes_lambda_and_its_interval(lam, scale):
    rng = np.random.default_rng(int(10 * lam) + 20)
    lo, hi = sorted(rng.uniform(-2, 2, 2))
    info = {"lam": lam, "lambda_hat": lam + 0.0123, "lambda_ci": (lo, hi)}
    text = finding_message(_data([1, 2]), Hypothesis("response_transform", None), info, 3.0, 2.4, 2, [], None)
    kind = "multiplicatively" if lam <= 0.5 else "non-additively"
    on = f"on a {scale} scale" if scale else f"after a Box-Cox transform with lambda = {lam:g}"
    assert text.startswith(f"angle: the response behaves {kind}: the quadratic fits better {on} (Box-Cox lambda = ")
    m = re.search(r"lambda = (\S+), 95 % interval (\S+) to (\S+)\);", text)
    assert m and np.allclose([float(v) for v in m.groups()], [lam + 0.0123, lo, hi], atol=0.005 + 1e-12)
    _check_gain(text, 3.0, 2.4)


@pytest.mark.parametrize("seed", range(4))
def test_a_slipped_factor_value_quotes_the_run_both_values_and_the_evidence(seed):
    rng = np.random.default_rng(seed)
    runs = np.arange(1, 12) * (seed + 1)
    row = int(rng.integers(0, 11))
    info = {"factor": "mu", "fitting_value": float(rng.uniform(0.01, 1)), "recorded_value": float(rng.uniform(1, 10)),
            "slip": "x1e1", "observed": float(rng.uniform(20, 40)), "t_moved": float(rng.normal(0, 1)),
            "t_recorded": float(rng.normal(0, 8)), "bayes_factor": float(rng.uniform(2, 90))}
    before, after = 2.0, float(rng.uniform(0.5, 2.5))
    text = finding_message(_data(runs), Hypothesis("factor_level", SimpleNamespace(row=row)), info, before, after, 11,
                           [], None)
    m = re.search(r"run (\d+) fits mu = (\S+) instead of the recorded (\S+) \(x 10\^1: ", text)
    assert m, text
    assert int(m.group(1)) == runs[row]
    assert [float(v) for v in m.groups()[1:]] == pytest.approx([info["fitting_value"], info["recorded_value"]], rel=1e-3)
    m = re.search(r"observed (\S+), the other runs predict it within (\S+) standard errors at mu = \S+ and (\S+) at "
                  r"the recorded value \(Bayes factor (\S+) against", text)
    assert m, text
    quoted = [float(v) for v in m.groups()]
    assert quoted == pytest.approx([info["observed"], abs(info["t_moved"]), abs(info["t_recorded"]),
                                    info["bayes_factor"]], abs=0.05, rel=1e-3)
    _check_gain(text, before, after)


@pytest.mark.parametrize("size, first", [(1.234567, 4), (-0.0123, 7)])
def test_a_step_in_run_order_quotes_its_size_first_run_and_the_runs_before(size, first):
    runs = np.array([2, 4, 6, 8, 10, 12, 14, 16])
    info = {"step_size": size, "runs_before": first}
    text = finding_message(_data(runs), Hypothesis("step", first), info, 1.0, 0.2, 8, [], None)
    m = re.search(r"the runs from run (\d+) on are shifted by (\S+) against the (\d+) runs before", text)
    assert m and int(m.group(1)) == runs[first] and int(m.group(3)) == first
    assert float(m.group(2)) == pytest.approx(size, rel=1e-3) and m.group(2)[0] == ("+" if size > 0 else "-")
    _check_gain(text, 1.0, 0.2)


def test_own_tolerances_are_listed_each_with_its_percentage():
    from demid.criticism.messages import level2_tolerance_text

    own = {"d5": 0.02, "rho": 0.0033, "aor": 0.15}
    listed = "d5 2.00 %, rho 0.33 %, aor 15.0 %"
    assert level2_tolerance_text(0.02, own) == f"their own tolerances ({listed})"
    assert level2_tolerance_text(0.02, own, brackets=False) == f"their own tolerances: {listed}"
    assert level2_tolerance_text(0.05, {"d5": 0.05, "rho": 0.05}) == "5.00 %"
    assert level2_tolerance_text(0.12, None) == "12.0 %"


@pytest.mark.parametrize("ratio", [0.004, 0.005, 0.0051, 0.25, 1.0, 7.77, 31.4])
def test_the_worst_observables_multiple_of_its_tolerance_is_quoted_to_two_digits_down_to_half_a_percent(ratio):
    tol = 0.02
    text = level2_miss_text({"a": ratio * tol, "b": 0.0}, 0.05, {"a": tol, "b": 0.05})
    if ratio * tol / tol >= 0.005:
        m = re.fullmatch(r"a by \S+ % \((\S+) times its tolerance of 2.00 %\)", text)
        assert m and float(m.group(1)) == pytest.approx(ratio, rel=0.03)
    else:
        assert text.endswith("(a negligible fraction of its tolerance of 2.00 %)")


@pytest.mark.parametrize("term, factors, words", [
    ((3, 0), ("e", "mu"), "curvature along e"), ((0, 0, 3), ("e", "mu", "k"), "curvature along k"),
    ((1, 1, 1), ("e", "mu", "k"), "a three-factor interaction of e, mu and k"),
    ((2, 0, 1), ("e", "mu", "k"), "a change of the e curvature with k"),
    ((0, 1, 2, 0), ("e", "mu", "k", "g"), "a change of the k curvature with mu")])
def test_a_missing_term_is_described_by_the_factors_it_holds(term, factors, words):
    h = Hypothesis("missing_term", SimpleNamespace(terms=[term]), aliases=["T"])
    text = finding_message(_data([1, 2, 3], factors), h, {}, 1.0, 1.002, 3, [], None)
    assert text == f"angle: the quadratic misses {words} (term T); adding it leaves the leave-one-out error unchanged."
