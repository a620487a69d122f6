"""The walk through the observable ranking in words (demid/story/measurements.py) over generated rankings of 2-4
observables: one sentence per starting set, naming the added measurement of largest gain, the runner-up and the
one the fraction criterion prefers, each number the sentence quotes parsed back and compared with the ranking's."""

from __future__ import annotations

import itertools
import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.story.measurements import measurement_order

_NUM = r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?"


def _ranking(k: int, seed: int, ties: bool = False) -> tuple[list[str], dict, pd.DataFrame]:
    """Gains grow with the set and fractions shrink; with ``ties`` the gains of sets of one size take two values
    only (equal gains are told apart by the smaller fraction), else distinct ones."""
    rng = np.random.default_rng(seed)
    names = list("pqrs"[:k])
    share = dict(zip(names, rng.uniform(0.1, 0.8, k)))
    sets = {}
    for size in range(1, k + 1):
        for combo in itertools.combinations(names, size):
            fraction = 100.0 * np.prod([share[o] for o in combo]) * rng.uniform(0.9, 1.0)
            sets[combo] = (size + (rng.choice([0.25, 0.75]) if ties else rng.uniform(0.0, 0.98)), fraction)
    frame = pd.DataFrame({"observables": ["+".join(c) for c in sets],
                          "n_observables": [len(c) for c in sets],
                          "information_gain_bits": [g for g, _ in sets.values()],
                          "feasible_fraction_pct": [f for _, f in sets.values()]})
    return names, sets, frame.sample(frac=1.0, random_state=seed).reset_index(drop=True)


@given(k=st.integers(2, 4), seed=st.integers(0, 10_000), ties=st.booleans())
@settings(max_examples=50, deadline=None, derandomize=True)
def test_each_starting_set_names_the_measurement_of_largest_gain_with_its_numbers(k, seed, ties):
    names, sets, frame = _ranking(k, seed, ties)
    sets[()] = (0.0, 100.0)
    lines = measurement_order(frame)
    starts = [s for size in range(k) for s in itertools.combinations(names, size)]
    assert len(lines) == len(starts)
    for start, line in zip(starts, lines):
        g0, f0 = sets[start]
        options = sorted(((sets[tuple(sorted(start + (o,)))][0] - g0, sets[tuple(sorted(start + (o,)))][1], o)
                          for o in names if o not in start), key=lambda t: (-t[0], t[1]))
        delta, f_new, best = options[0]
        g_new = g0 + delta
        if not start:
            m = re.fullmatch(rf"As a first measurement, (\w) is the most informative: ({_NUM}) bits, admissible "
                             rf"fraction ({_NUM}) % of the domain(.*)\.", line)
            assert m, line
            assert m[1] == best and float(m[2]) == pytest.approx(g_new, abs=0.0051)
            assert float(m[3]) == pytest.approx(f_new, rel=5.1e-3)
            rest = m[4]
        else:
            m = re.fullmatch(rf"From ([\w +]+), adding (\w) gains ({_NUM}) bits \(({_NUM}) -> ({_NUM})\)(.*)\.", line)
            assert m, line
            assert m[1] == " + ".join(start) and m[2] == best
            assert [float(m[i]) for i in (3, 4, 5)] == pytest.approx([delta, g0, g_new], abs=0.0051)
            rest = m[6]
            shrink = re.match(rf" and shrinks the admissible fraction by ({_NUM}) % \(({_NUM}) % -> ({_NUM}) %\)", rest)
            assert shrink, rest  # fractions shrink with every added observable here
            assert float(shrink[1]) == pytest.approx(100 * (1 - f_new / f0), abs=0.051)
            assert float(shrink[2]) == pytest.approx(f0, rel=5.1e-3)
            assert float(shrink[3]) == pytest.approx(f_new, rel=5.1e-3)
        if len(options) > 1:
            runner = re.search(rf"; (\w) would gain ({_NUM}) bits", rest)
            assert runner and runner[1] == options[1][2], rest
            assert float(runner[2]) == pytest.approx(options[1][0], abs=0.0051)
            by_fraction = min(options, key=lambda t: t[1])
            said = re.search(rf"; by fraction alone (\w) contracts more \(({_NUM}) % vs ({_NUM}) %\)", rest)
            if by_fraction[2] != best and by_fraction[1] < f_new:
                assert said and said[1] == by_fraction[2], rest
                assert float(said[2]) == pytest.approx(by_fraction[1], rel=5.1e-3)
                assert float(said[3]) == pytest.approx(f_new, rel=5.1e-3)
            else:
                assert not said, rest
        else:
            assert "would gain" not in rest


def test_a_measurement_that_leaves_the_fraction_says_so_and_an_empty_set_is_named():
    frame = pd.DataFrame({"observables": ["p", "q", "p+q"], "information_gain_bits": [1.0, 0.5, 1.7],
                          "feasible_fraction_pct": [40.0, 60.0, 39.99]})
    lines = measurement_order(frame)
    assert lines[1] == "From p, adding q gains 0.70 bits (1.00 -> 1.70) but leaves the admissible fraction at 40 %."
    assert lines[2].startswith("From q, adding p gains 1.20 bits (0.50 -> 1.70) and shrinks the admissible fraction "
                               "by 33.4 % (60 % -> 40 %)")
    empty = measurement_order(frame.assign(feasible_fraction_pct=[0.0, 60.0, 0.0]))
    assert empty[1] == ("From p, adding q gains 0.70 bits (1.00 -> 1.70) (the admissible set is already empty at "
                        "this tolerance).")


def test_an_unreachable_target_is_named_first_and_left_out_and_a_ranking_cut_by_hand_is_read():
    frame = pd.DataFrame({"observables": ["p", "q", "r", "p+q", "p+r", "q+r", "p+q+r"],
                          "information_gain_bits": [1.0, float("-inf"), 0.8, float("-inf"), 1.5, float("-inf"),
                                                    float("-inf")],
                          "feasible_fraction_pct": [40.0, 0.0, 50.0, 0.0, 20.0, 0.0, 0.0]})
    lines = measurement_order(frame, labels={"q": "Q_label"})
    assert lines[0].startswith("The target of Q_label cannot be met anywhere in the search range")
    assert not any("Q_label" in line for line in lines[1:])
    assert lines[1].startswith("As a first measurement, p is the most informative: 1.00 bits")
    # a ranking without one observable's own row (cut by hand): the rest is still read
    cut = measurement_order(frame[frame["observables"] != "r"])
    assert cut[0].startswith("The target of q cannot be met") and len(cut) >= 2
    # two targets each within reach but not together
    pair = pd.DataFrame({"observables": ["p", "q", "p+q"], "information_gain_bits": [1.0, 0.9, float("-inf")],
                         "feasible_fraction_pct": [40.0, 30.0, 0.0]})
    assert measurement_order(pair)[0].startswith("The targets of p + q can each be met but not together")


@pytest.mark.parametrize("scale", [1.0, 0.02, 1e-4])
def test_leaving_or_shrinking_the_fraction_reads_the_same_at_any_size_of_the_fraction(scale):
    """Whether an added measurement leaves the admissible fraction (a relative change under 5e-4) or shrinks it, and
    by what share, depends on the ratio of the fractions only: the same words for a set of 40 % and of 0.004 %."""
    frame = pd.DataFrame({"observables": ["p", "q", "p+q"], "information_gain_bits": [1.0, 0.5, 1.7],
                          "feasible_fraction_pct": [40.0 * scale, 60.0 * scale, 39.99 * scale]})
    lines = measurement_order(frame)
    assert re.fullmatch(r"From p, adding q gains 0\.70 bits \(1\.00 -> 1\.70\) but leaves the admissible fraction "
                        rf"at ({_NUM}) %\.", lines[1]), lines[1]
    shrink = re.search(rf"and shrinks the admissible fraction by ({_NUM}) %", lines[2])
    assert shrink, lines[2]
    assert float(shrink[1]) == pytest.approx(100 * (1 - 39.99 / 60.0), abs=0.051)


@pytest.mark.parametrize("seed", range(3))
def test_the_narrower_measurement_is_named_when_gains_in_bits_exceed_fractions_in_percent(seed):
    """A posterior on under 1 % of the domain gains about log2(100 / fraction) bits, several times its fraction in
    percent: the measurement that contracts more is still named beside the more informative one."""
    rng = np.random.default_rng(seed)
    fractions = np.sort(rng.uniform(0.05, 0.9, 2))  # q is the narrower
    gains = {"p": float(np.log2(100 / fractions[1]) + 1.0), "q": float(np.log2(100 / fractions[0]) - 1.5)}
    assert gains["p"] > gains["q"] > 1.0 > fractions[1]
    frame = pd.DataFrame({"observables": ["p", "q", "p+q"],
                          "information_gain_bits": [gains["p"], gains["q"], gains["p"] + 1.0],
                          "feasible_fraction_pct": [fractions[1], fractions[0], fractions[0] / 2]})
    first = measurement_order(frame)[0]
    assert first == (f"As a first measurement, p is the most informative: {gains['p']:.2f} bits, admissible fraction "
                     f"{fractions[1]:.3g} % of the domain; q would gain {gains['q']:.2f} bits; by fraction alone q "
                     f"contracts more ({fractions[0]:.3g} % vs {fractions[1]:.3g} %).")
