"""A material's advice against the rules written out here, over generated studies: 2-3 factors with units and
physical limits, 2-4 observables, the fullest scenario of 1-3 observables, rankings of every subset with gains and
fractions of any size, unreachable and uninformative observables, verdicts cut at either bound (or both) in several
scenarios, a next wave that is worth simulating or not, level 2 feasible or not.  Checked: which observable the
add-observable advice names (the largest gain over the used set among reachable, informative ones) and the gain and
fraction it quotes, the widen items per factor and side in config order with the bound and scenarios they quote, the
next wave's shrink and fractions, the priority order and the one next step, and the CSV round trip."""

from __future__ import annotations

import re
from itertools import combinations

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings, strategies as st

from demid.spec import MaterialSpec
from demid.story.advice import PRIORITY, StudyAdvice, material_advice


def _study(rng, k, count, used_size):
    factors = {}
    for i in range(k):
        lo = float(rng.uniform(-100, 100))
        hi = lo + float(rng.uniform(0.5, 50))
        block = {"lower": lo, "upper": hi, "label": f"F{i}", "unit": "kPa" if i % 2 else None}
        if rng.uniform() < 0.4:
            block["limits"] = {"lower": lo - float(rng.uniform(1, 10))}
        factors[f"f{i}"] = block
    names = [f"y{j}" for j in range(count)]
    responses = {o: {"target": float(rng.choice([-1, 1]) * rng.uniform(1, 50)), "label": f"Y{o[1:]}"} for o in names}
    used = names[:used_size]
    scenarios = {"full": {"observables": used, "tolerance": 0.05, "label": "Full set"}}
    if used_size > 1:
        scenarios["one"] = {"observables": used[:1], "tolerance": 0.05, "label": "First alone"}
    spec = MaterialSpec.from_material("m", {"data": "x.csv", "design": {"type": "custom"}, "factors": factors,
                                            "responses": responses, "scenarios": scenarios}, grid_points=21)
    return spec, names, used


def _ranking(rng, names, used, unreachable):
    rows = []
    for size in range(1, len(names) + 1):
        for s in combinations(names, size):
            reachable = not any(o in unreachable for o in s)
            gain = float(rng.uniform(0, 8)) if reachable else np.nan
            best = "+".join(used) if size == len(used) + 1 and set(used) <= set(s) else "+".join(s[:-1]) or "(none)"
            rows.append({"observables": "+".join(s), "n_observables": size,
                         "information_gain_bits": gain, "feasible_fraction_pct": float(10 ** rng.uniform(-3, 2)),
                         "best_subset": best, "gain_vs_best_subset_bits": float(rng.uniform(0.01, 6)),
                         "targets_reachable": reachable})
    return pd.DataFrame(rows)


@settings(max_examples=20, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(seed=st.integers(0, 100_000), k=st.integers(2, 3), count=st.integers(2, 4), used_size=st.integers(1, 3),
       feasible=st.booleans(), stop=st.booleans(), n_cut=st.integers(0, 4))
def test_every_advice_names_and_quotes_what_its_rule_says(seed, k, count, used_size, feasible, stop, n_cut):
    rng = np.random.default_rng(seed)
    used_size = min(used_size, count)
    spec, names, used = _study(rng, k, count, used_size)
    extra = [o for o in names if o not in used]
    unreachable = {o for o in extra if rng.uniform() < 0.25}
    uninformative = {o: "band covers it" for o in extra if o not in unreachable and rng.uniform() < 0.4}
    ranking = _ranking(rng, names, used, unreachable)
    if uninformative and rng.uniform() < 0.7:  # an uninformative observable with the largest gain is still not named
        o = next(iter(uninformative))
        grows = (ranking["best_subset"] == "+".join(used)) & ranking["observables"].str.split("+").map(
            lambda s: o in s and len(s) == len(used) + 1)
        ranking.loc[grows, "gain_vs_best_subset_bits"] = 6.5

    verdict_rows, cuts = [], {}
    for _ in range(n_cut):
        f = spec.factors[int(rng.integers(0, k))]
        sc = spec.scenarios[int(rng.integers(0, len(spec.scenarios)))]
        side = str(rng.choice(["lower", "upper", "lower and upper"]))
        verdict_rows.append({"scenario": sc.name, "factor": f.name, "verdict": f"cut by the search range ({side} bound)"})
        for s in side.split(" and "):
            cuts.setdefault((f.name, s), []).append(sc.label)
    verdict_rows.append({"scenario": "full", "factor": spec.factors[0].name, "verdict": "unresolved"})
    verdicts = pd.DataFrame(verdict_rows)

    shrink = float(rng.uniform(0.001, 0.95))
    value = {"scenario": "full", "expected_contraction": shrink, "count": int(rng.integers(2, 30)),
             "plausible_fraction_pct": float(rng.uniform(1, 50)), "expected_fraction_pct": float(rng.uniform(0.1, 1)),
             "stop": stop}
    level2 = {"feasible": feasible, "tolerance": 0.05, "best_max_error": 0.01 if feasible else 0.2,
              "observables": list(used), "bottleneck": used[0]}
    items = material_advice(spec, verdicts, ranking=ranking, criticism={"level2": level2},
                            uninformative=uninformative, wave_value=value)

    # --- add_observable: the largest gain over the used set, among reachable and informative observables
    grow = ranking[ranking["targets_reachable"] & (ranking["best_subset"] == "+".join(used))
                   & (ranking["n_observables"] == len(used) + 1)]
    grow = grow[[not any(o in uninformative for o in s.split("+") if o not in used) for s in grow["observables"]]]
    added = [i for i in items if i.kind == "add_observable"]
    named = ""
    if not feasible:
        assert added == []
    elif len(grow):
        best = grow.loc[grow["gain_vs_best_subset_bits"].idxmax()]
        named = next(o for o in best["observables"].split("+") if o not in used)
        assert [i.observable for i in added] == [named]
        said = re.fullmatch(rf"Measure Y{named[1:]} as well: it adds ([\d.]+) bits of information and leaves "
                            r"([\d.e+-]+) % of the domain admissible\.", added[0].text)
        assert said, added[0].text
        assert float(said.group(1)) == pytest.approx(best["gain_vs_best_subset_bits"], abs=0.005 + 1e-12)
        assert float(said.group(2)) == pytest.approx(best["feasible_fraction_pct"], rel=5e-3)
    else:
        assert added == []  # the generic line stands only where nothing else is advised: the next wave is

    # --- the next wave: its count, shrink and fractions
    wave = [i for i in items if i.kind in ("next_runs", "stop")]
    assert len(wave) == 1 and wave[0].kind == ("stop" if stop else "next_runs")
    fractions = re.search(r"\(([\d.e+-]+) % → ([\d.e+-]+) % of the search range\)", wave[0].text)
    assert float(fractions.group(1)) == pytest.approx(value["plausible_fraction_pct"], rel=5e-3)
    assert float(fractions.group(2)) == pytest.approx(value["expected_fraction_pct"], rel=5e-3)
    assert f"the {value['count']} proposed runs" in wave[0].text and "*Full set*" in wave[0].text
    if stop:
        assert float(re.search(r"by only ([\d.]+) %", wave[0].text).group(1)) == pytest.approx(100 * shrink, abs=0.05)
        helps = f"measuring Y{named[1:]}" if named else "a new kind of measurement"
        assert f"What would help: {helps}, or a tighter measurement" in wave[0].text
    else:
        assert float(re.search(r"by about (\d+) %", wave[0].text).group(1)) == pytest.approx(100 * shrink, abs=0.5)

    # --- widen: per factor in config order, lower before upper, with the bound and the scenarios that end there
    widen = [i for i in items if i.kind == "widen"]
    expected = [(f.name, s) for f in spec.factors for s in ("lower", "upper") if (f.name, s) in cuts]
    assert [(i.factor, i.bound) for i in widen] == expected
    for i in widen:
        f = spec.factor(i.factor)
        bound = f.lower if i.bound == "lower" else f.upper
        quoted = re.search(rf"beyond its {i.bound} bound \(([-\d.e+]+)", i.text)
        assert float(quoted.group(1)) == pytest.approx(bound, rel=5e-4, abs=1e-9)
        for label in dict.fromkeys(cuts[(i.factor, i.bound)]):
            assert i.text.count(f"the plausible set of *{label}* ends there only because the search range does") == 1
        limit = f.limits[0] if i.bound == "lower" else f.limits[1]
        if limit is not None:
            assert float(re.search(r"to its physical limit ([-\d.e+]+)", i.text).group(1)) == pytest.approx(
                limit, rel=5e-4)
        else:
            assert "physical limit" not in i.text

    # --- level 2 infeasible: recalibrate names its bottleneck
    recal = [i for i in items if i.kind == "recalibrate"]
    assert [i.observable for i in recal] == ([] if feasible else [used[0]])

    # --- the order: PRIORITY, one next step (the first), measurement_order last and never a step
    steps = [i for i in items if i.kind in PRIORITY]
    assert [PRIORITY.index(i.kind) for i in steps] == sorted(PRIORITY.index(i.kind) for i in steps)
    assert [i.decision for i in items] == [n == 0 for n in range(len(items))]
    assert items[len(steps):] == [i for i in items if i.kind == "measurement_order"] and len(items) > len(steps)

    # --- the CSV round trip and the next step read back
    advice = StudyAdvice(items)
    again = StudyAdvice.from_frame(advice.to_frame().astype(str))
    assert again.items == items
    decision, also = again.next_step("m")
    assert decision == steps[0].text and also == [i.text for i in steps[1:]]
    assert again.texts("m", ["widen"]) == [i.text for i in widen]
