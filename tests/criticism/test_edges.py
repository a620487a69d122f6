"""Edges and extrapolation: at_bound of closed-form sets, "widen the range" and extrapolation warnings."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.admissibility import evaluate_scenarios
from demid.criticism import calibration_check
from demid.design import quadratic_terms
from demid.report.tables import IDENTIFIABILITY_COLUMNS
from demid.sampling import evaluate_set
from demid.sampling.domain import BOUND_TOUCH, Domain
from demid.spec import MaterialSpec
from demid.story import material_advice
from demid.story.verdicts import factor_verdict
from demid.surrogate import Surrogate


def _linear(name: str, factors: list[str], j: int, log: tuple[str, ...] = ()) -> Surrogate:
    """y = 10 + 10 z_j (z: model units, log10 for log factors): its sets are intervals in closed form."""
    terms = quadratic_terms(len(factors))
    coef = np.zeros(len(terms))
    coef[0] = 10.0
    coef[1 + j] = 10.0
    return Surrogate(name, factors, terms, coef, np.zeros((len(terms), len(terms))), 0.0, 7, log_factors=log)


def _verdicts(identifiability: pd.DataFrame, spec) -> list[str]:
    """The story's verdict of each row of an identifiability table, read with its ``at_bound`` column."""
    out = []
    for _, row in identifiability.iterrows():
        f = spec.factor(row["factor"])
        out.append(factor_verdict(float(row["lower"]), float(row["upper"]), f.lower, f.upper, f.log,
                                  row.get("at_bound"), f.limits)[0])
    return out


def _interval(target: float, eps: float) -> tuple[float, float]:
    """{z : |10 + 10 z - t| <= eps t}, before clipping to the range."""
    return (target * (1 - eps) - 10) / 10, (target * (1 + eps) - 10) / 10


@pytest.mark.parametrize("target, eps, expected", [
    (19.9, 0.02, "upper"),    # x in [0.9502, 1.0298] within [0, 1]
    (10.1, 0.02, "lower"),    # [-0.0102, 0.0302]
    (15.0, 0.02, "none"),     # [0.47, 0.53]
    (15.0, 0.5, "both"),      # [-0.25, 1.25]
    (19.7, 0.0120, "none"),   # upper end 0.99364: 0.64 % of the range short of the bound
    (19.7, 0.0130, "upper"),  # upper end 0.99561: 0.44 % short, within the 0.5 % tolerance
])
def test_at_bound_of_closed_form_exact_sets(target, eps, expected):
    lo_z, hi_z = _interval(target, eps)
    # the known answer, from the closed form and the documented tolerance
    assert expected == ["none", "lower", "upper", "both"][int(lo_z <= BOUND_TOUCH) + 2 * int(1 - hi_z <= BOUND_TOUCH)]
    factors = ["x", "w"]
    surrogates = {"y1": _linear("y1", factors, 0), "y2": _linear("y2", factors, 1)}
    domain = Domain(("x", "w"), (0.0, 0.0), (1.0, 1.0))
    aset = evaluate_set(surrogates, domain, ["y1", "y2"], {"y1": target, "y2": 15.0}, eps, 51)
    assert aset.exact is not None
    assert aset.lower[0] == pytest.approx(max(lo_z, 0.0), abs=1e-9)
    assert aset.upper[0] == pytest.approx(min(hi_z, 1.0), abs=1e-9)
    assert aset.at_bound == (expected, "both" if eps >= 0.5 else "none")


def test_at_bound_tolerance_is_relative_to_the_range_and_in_log_units():
    # w on a log scale 1..1000: y = 10 + 10 log10(w); target 39.6 at 1 % reaches log10 w = 2.9996 -> 3 = bound
    domain = Domain(("x", "w"), (0.0, 1.0), (1.0, 1000.0), (False, True))
    assert domain.at_bound([0.2, 10 ** 2.99], [0.8, 1000.0]) == ("none", "upper")
    # 0.4 % of the log range from the lower bound touches, 0.6 % does not
    assert domain.at_bound([0.0, 10 ** 0.012], [1.0, 10.0]) == ("both", "lower")
    assert domain.at_bound([0.0, 10 ** 0.018], [1.0, 10.0]) == ("both", "none")
    assert domain.at_bound([np.nan, np.nan], [np.nan, np.nan]) == ("none", "none")
    # scaled: a range of 1000 units, 4 units from the bound touches (0.4 %), 6 do not
    wide = Domain(("a",), (0.0,), (1000.0,))
    assert wide.at_bound([4.0], [500.0]) == ("lower",) and wide.at_bound([6.0], [500.0]) == ("none",)
    # "within 0.5 %" includes 0.5 % itself, at both ends
    assert wide.at_bound([5.0], [995.0]) == ("both",)


def test_at_bound_on_the_sobol_path():
    # four factors: no exact set; the polished Sobol spans reach the bound exactly
    factors = ["a", "b", "c", "d"]
    surrogates = {f"y{j}": _linear(f"y{j}", factors, j) for j in range(4)}
    domain = Domain(tuple(factors), (0.0,) * 4, (1.0,) * 4)
    targets = {"y0": 19.9, "y1": 10.1, "y2": 15.0, "y3": 15.0}
    aset = evaluate_set(surrogates, domain, list(targets), targets, 0.1, 2 ** 12)
    assert aset.exact is None
    # y0: [0.791, 1.189] -> upper; y1: [-0.091, 0.111] -> lower; y2, y3: [0.35, 0.65] -> none
    assert aset.at_bound == ("upper", "lower", "none", "none")


def _material(targets: dict[str, float], eps: float = 0.02) -> dict:
    return {"data": "t.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 1},
            "factors": {"x": {"lower": 0.0, "upper": 1.0}, "w": {"lower": 0.0, "upper": 1.0}},
            "responses": {k: {"target": v} for k, v in targets.items()},
            "scenarios": {"both": {"observables": list(targets), "tolerance": eps}}}


def test_identifiability_rows_carry_at_bound_and_the_verdict_follows_it():
    factors = ["x", "w"]
    surrogates = {"y1": _linear("y1", factors, 0), "y2": _linear("y2", factors, 1)}
    material = _material({"y1": 19.9, "y2": 15.0})
    table, sets = evaluate_scenarios(surrogates, MaterialSpec.from_material("m", material), 51)
    assert IDENTIFIABILITY_COLUMNS[-1] == "at_bound"
    assert list(table["at_bound"]) == ["upper", "none"]
    spec = MaterialSpec.from_material("m", material)
    verdicts = _verdicts(table, spec)
    assert verdicts == ["cut by the search range (upper bound)", "identified"]
    # the verdict is derived from the column: the same interval marked as touching reads as cut
    marked = table.assign(at_bound=["none", "lower"])
    assert _verdicts(marked, spec) == ["identified", "cut by the search range (lower bound)"]
    # the advice reads the verdict rows (here the strict ones, as tables/verdicts.csv holds them)
    rows = pd.DataFrame({"scenario": "both", "factor": ["x", "w"], "verdict": verdicts})
    steps = [i.text for i in material_advice(spec, rows) if i.kind == "widen"]
    assert steps == ["Widen the range of x beyond its upper bound (1) and simulate runs there: the plausible set "
                     "of *both* ends there only because the search range does."]


def _level2(targets, runs=None, reference=None, with_set=True):
    factors = ["x", "w"]
    surrogates = {"y1": _linear("y1", factors, 0), "y2": _linear("y2", factors, 1)}
    domain = Domain(("x", "w"), (0.0, 0.0), (1.0, 1.0))
    strict = evaluate_set(surrogates, domain, list(targets), targets, 0.02, 21) if with_set else None
    return calibration_check(surrogates, domain, targets, 0.02, 21, reference, strict_set=strict, runs=runs)


def test_level2_says_widen_the_range_when_the_set_or_best_point_sits_on_a_bound():
    inside = _level2({"y1": 15.0, "y2": 15.0})
    assert inside.widen == {} and "Widen" not in inside.message
    assert inside.set_at_bound == {"x": "none", "w": "none"}
    cut = _level2({"y1": 19.9, "y2": 15.0})  # the set is x in [0.9502, 1]: cut by the upper bound
    assert cut.feasible and cut.set_at_bound == {"x": "upper", "w": "none"}
    assert cut.widen == {"x": ["upper"]}
    assert "Widen the range of x: the admissible set reaches its upper bound" in cut.message
    assert "above 1" in cut.message
    # y1 = 21 needs x = 1.1: out of reach; the best point is x = 1, on the bound
    beyond = _level2({"y1": 21.0, "y2": 15.0})
    assert not beyond.feasible and beyond.best_point["x"] == pytest.approx(1.0)
    assert beyond.best_at_bound["x"] == "upper" and beyond.widen == {"x": ["upper"]}
    assert "Widen the range of x: the best point lies on its upper bound" in beyond.message
    low = _level2({"y1": 9.0, "y2": 15.0})
    assert low.widen == {"x": ["lower"]} and "below 0" in low.message
    payload = beyond.to_json()
    assert payload["widen"] == {"x": ["upper"]} and payload["best_point_at_bound"]["x"] == "upper"


# A 2-factor design covering x in [0.2, 0.8] only, w in [0, 1]: a diamond (axial points) and its centre.
DIAMOND = np.array([[0.5, 0.0], [0.5, 1.0], [0.2, 0.5], [0.8, 0.5], [0.5, 0.5]])


def test_extrapolation_warnings_for_bounds_and_reference_point():
    quiet = _level2({"y1": 15.0, "y2": 15.0}, runs=np.array([[0, 0], [0, 1], [1, 0], [1, 1], [0.5, 0.5]]),
                    reference={"x": 0.5, "w": 0.5})
    assert quiet.extrapolation == []
    wide = _level2({"y1": 15.0, "y2": 15.0}, runs=DIAMOND, reference={"x": 0.5, "w": 0.6})
    assert len(wide.extrapolation) == 1
    assert "search range of x, 0 to 1, reaches beyond the runs, which cover 0.2 to 0.8" in wide.extrapolation[0]
    assert "the range of w" not in " ".join(wide.extrapolation)
    outside = _level2({"y1": 15.0, "y2": 15.0}, runs=DIAMOND, reference={"x": 0.9, "w": 0.5})
    assert any("reference point lies outside the range of the runs (x = 0.9" in w for w in outside.extrapolation)
    # inside both factors' ranges but outside the diamond (the runs' convex hull): |x-0.5|/0.3 + |w-0.5|/0.5 > 1
    corner = _level2({"y1": 15.0, "y2": 15.0}, runs=DIAMOND, reference={"x": 0.75, "w": 0.9})
    assert any("outside the region the design runs cover" in w for w in corner.extrapolation)
    assert "Extrapolation" in corner.message
    inner = _level2({"y1": 15.0, "y2": 15.0}, runs=DIAMOND, reference={"x": 0.6, "w": 0.6})
    assert not any("reference point" in w for w in inner.extrapolation)


def test_summary_lines_carry_best_point_and_extrapolation():
    from demid.report.summary import criticism_lines

    spec = MaterialSpec.from_material("m", _material({"y1": 21.0, "y2": 15.0}))
    level2 = _level2({"y1": 21.0, "y2": 15.0}, runs=DIAMOND).to_json()
    lines = criticism_lines({"level2": level2}, spec)
    assert any(ln.startswith("Extrapolation: the search range of x") for ln in lines)
    verdicts = pd.DataFrame(columns=["scenario", "factor", "verdict"])
    assert [i.text for i in material_advice(spec, verdicts, criticism={"level2": level2}) if i.kind == "widen"] == [
        "Widen the range of x beyond its upper bound (1) and simulate runs there: no point meets every target and "
        "the best point lies on it."]


def test_a_reference_point_beyond_the_search_range_is_said_to_be_outside_it():
    from demid.criticism.edges import extrapolation_warnings
    from demid.sampling.domain import Domain

    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), ())
    runs = np.array([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0], [0.5, 0.5]])
    inside = extrapolation_warnings(domain, runs, {"a": 0.5, "b": 0.5})
    assert inside == []
    beyond = extrapolation_warnings(domain, runs, {"a": 1.5, "b": 0.5})
    assert any("outside the search range (a = 1.5 (search range 0 to 1))" in w for w in beyond)


def test_an_observable_no_factor_moves_is_named_and_does_not_pick_the_best_point():
    """z2 = 0 in every run (post-processing failed) with a target of 12: it misses by 100 % everywhere, so the
    largest error tied over the domain and the best point fell on a corner, with 'widen the range' for every
    factor.  The best point now meets z1 (z1 = 10 + 5 p + 3 q, target 13), z2 is named, and no range is to be
    widened for a response no factor moves."""
    import numpy as np

    from demid.criticism.level2 import calibration_check
    from demid.design import quadratic_terms
    from demid.sampling.domain import Domain
    from demid.surrogate import Surrogate

    names, terms = ["p", "q", "s"], quadratic_terms(3)
    moved = np.zeros(len(terms))
    moved[[0, 1, 2]] = [10.0, 5.0, 3.0]
    surrogates = {"z1": Surrogate("z1", names, terms, moved, np.zeros((10, 10)), 0.0, 20),
                  "z2": Surrogate("z2", names, terms, np.zeros(len(terms)), np.zeros((10, 10)), 0.0, 20)}
    result = calibration_check(surrogates, Domain(tuple(names), (0.0,) * 3, (1.0,) * 3),
                               {"z1": 13.0, "z2": 12.0}, 0.05, 21)
    assert abs(result.best_errors["z1"]) <= 1e-6 and result.best_errors["z2"] == -1.0
    assert result.unmoved == ["z2"] and result.widen == {} and "Widen" not in result.message
    assert "z2 is predicted the same everywhere in the search range (no factor moves it)" in result.message


def test_extrapolation_warnings_in_actual_units_of_a_scaled_and_a_log_factor():
    """The diamond of runs on x in [10, 20] (linear) and w in [1, 100] (log): the runs cover x = 12 to 18 (a
    fifth of the range to four fifths) and all of w.  A reference point inside the diamond, or on its vertex,
    gets no warning; one at x = 19 is outside the runs' range but inside the search range."""
    from demid.criticism.edges import extrapolation_warnings

    domain = Domain(("x", "w"), (10.0, 1.0), (20.0, 100.0), log=(False, True))
    runs = np.column_stack([10.0 + 10.0 * DIAMOND[:, 0], 10.0 ** (2.0 * DIAMOND[:, 1])])
    (only,) = extrapolation_warnings(domain, runs, None)
    assert "search range of x, 10 to 20, reaches beyond the runs, which cover 12 to 18;" in only
    assert "lower and upper bound" in only
    for inside in ({"x": 16.0, "w": 10.0 ** 1.2}, {"x": 18.0, "w": 10.0}, {"x": 15.0, "w": 100.0}):
        assert extrapolation_warnings(domain, runs, inside) == [only], inside
    out = extrapolation_warnings(domain, runs, {"x": 19.0, "w": 10.0})
    assert len(out) == 2 and "outside the range of the runs (x = 19 (runs: 12 to 18))" in out[1]
