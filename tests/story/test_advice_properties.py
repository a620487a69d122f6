"""The numbers the advice quotes, over generated studies: the observable it names to add is the one with the
largest gain (and the bits it quotes are that gain), and the next-runs advice quotes the shrink it is given, in
per cent, consistent with the two fractions it shows."""

from __future__ import annotations

import re

import pandas as pd
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.spec import MaterialSpec
from demid.story import material_advice

NO_VERDICTS = pd.DataFrame(columns=["scenario", "factor", "verdict"])
NAMES = ["y1", "y2", "y3", "y4", "y5"]


def _spec(n_responses: int, used: int, targets: list[float]) -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": {n: {"target": t} for n, t in zip(NAMES[:n_responses], targets)},
                "scenarios": {"s": {"observables": NAMES[:used], "tolerance": 0.05}}}
    return MaterialSpec.from_material("m", material, grid_points=11)


@st.composite
def studies_with_candidates(draw):
    """A scenario using 1-3 observables and 1-3 others that could be added, each with its own gain."""
    used = draw(st.integers(1, 3))
    extra = draw(st.integers(1, 4 - used + 1 if used < 3 else 2))
    n = used + extra
    targets = draw(st.lists(st.floats(-1e4, 1e4).filter(lambda t: abs(t) > 1e-3), min_size=n, max_size=n))
    gains = draw(st.lists(st.floats(0.0, 20.0), min_size=extra, max_size=extra, unique=True))
    fractions = draw(st.lists(st.floats(0.01, 99.0), min_size=extra, max_size=extra))
    return used, n, targets, gains, fractions


@given(studies_with_candidates())
@settings(max_examples=25, deadline=None, derandomize=True)
def test_the_observable_advised_is_the_one_with_the_largest_gain_and_its_bits_are_quoted(study):
    used, n, targets, gains, fractions = study
    spec = _spec(n, used, targets)
    base = "+".join(NAMES[:used])
    rows = [{"observables": base + "+" + NAMES[used + k], "n_observables": used + 1, "best_subset": base,
             "gain_vs_best_subset_bits": g, "information_gain_bits": g, "feasible_fraction_pct": f,
             "targets_reachable": True}
            for k, (g, f) in enumerate(zip(gains, fractions))]
    ranking = pd.DataFrame(rows).sample(frac=1.0, random_state=len(rows))  # the table's order says nothing
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, ranking=ranking) if i.kind == "add_observable"]
    best = max(range(len(gains)), key=gains.__getitem__)
    assert item.observable == NAMES[used + best]
    said = re.fullmatch(r"Measure (\S+) as well: it adds ([\d.]+) bits of information and leaves ([\d.e+-]+) % "
                        r"of the domain admissible\.", item.text)
    assert said, item.text
    assert said.group(1) == NAMES[used + best]
    assert abs(float(said.group(2)) - gains[best]) <= 0.005 + 1e-12
    assert abs(float(said.group(3)) - fractions[best]) <= 5e-3 * fractions[best]


@given(shrink=st.floats(0.005, 0.995), before=st.floats(0.01, 90.0), count=st.integers(1, 20))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_next_runs_advice_quotes_the_expected_shrink_in_per_cent(shrink, before, count):
    spec = _spec(1, 1, [5.0])
    after = before * (1 - shrink)
    value = {"scenario": "s", "expected_contraction": shrink, "count": count, "plausible_fraction_pct": before,
             "expected_fraction_pct": after}
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, wave_value=value) if i.kind == "next_runs"]
    said = re.search(r"Simulate the (\d+) proposed runs .*shrink the plausible set of \*s\* by about (\d+) % "
                     r"\(([\d.e+-]+) % → ([\d.e+-]+) % of the search range\)", item.text)
    assert said, item.text
    assert int(said.group(1)) == count
    assert abs(int(said.group(2)) - 100 * shrink) <= 0.5 + 1e-9
    # the quoted fractions give back the quoted shrink (each to its 3 printed digits)
    shown_before, shown_after = float(said.group(3)), float(said.group(4))
    assert abs(100 * (1 - shown_after / shown_before) - 100 * shrink) <= 0.5 + 100 * 1e-2 * (1 - shrink) + 1e-9


@given(shrink=st.floats(0.0005, 0.05), before=st.floats(0.01, 90.0))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_stop_advice_quotes_the_small_shrink_in_per_cent(shrink, before):
    spec = _spec(1, 1, [5.0])
    value = {"scenario": "s", "expected_contraction": shrink, "count": 4, "plausible_fraction_pct": before,
             "expected_fraction_pct": before * (1 - shrink), "stop": True}
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, wave_value=value) if i.kind == "stop"]
    said = re.search(r"by only ([\d.]+) %", item.text)
    assert said and abs(float(said.group(1)) - 100 * shrink) <= 0.05 + 1e-9, item.text
