"""Every named cause comes with runs that would confirm it, and one run's two readings (an outlier, a slipped
factor value) are reported together: criticism.naming.confirming_rivals, verdict.other_reading_of_the_run."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize, discrimination
from demid.criticism.catalogue import Hypothesis
from demid.criticism.slips import SlipCandidate
from demid.criticism.naming import confirming_rivals
from demid.criticism.verdict import NAMING_VERDICTS, ONE_RUN_READINGS_BAYES_FACTOR, other_reading_of_the_run
from demid.design import model_matrix, parse_term
from tests.generators import FACTORS, ccd_table, design, later_runs


# --------------------------------------------------------------------------- one run, two readings
def _slip(row: int, bayes_factor: float) -> Hypothesis:
    return Hypothesis("factor_level", SlipCandidate(row, 0, 1, 3.0), info={"bayes_factor": bayes_factor})


def test_the_other_reading_of_a_run_is_listed_unless_the_bayes_factor_decides_at_twenty_to_one():
    edge = ONE_RUN_READINGS_BAYES_FACTOR
    assert edge == pytest.approx(np.exp(discrimination.AMBIGUOUS_AICC / 2), rel=0.01)
    outlier = Hypothesis("outlier", 4)
    for factor, slip_reading, outlier_reading in [(2.0, "outlier", "factor_level"), (0.2, "outlier", "factor_level"),
                                                  (edge * 1.01, None, None), (1 / edge / 1.01, None, None)]:
        slip = _slip(4, factor)
        assert other_reading_of_the_run(slip, [outlier, slip]) == slip_reading, factor
        assert other_reading_of_the_run(outlier, [outlier, slip]) == outlier_reading, factor
    assert other_reading_of_the_run(outlier, [outlier, _slip(5, 2.0)]) is None  # a slip of another run
    assert other_reading_of_the_run(Hypothesis("drift", "run"), [_slip(4, 2.0)]) is None


def test_an_outlier_read_as_a_slip_of_the_same_run_is_reported_with_the_outlier_as_its_alias():
    """Planted outliers (3 factors, seeds 0-19): a slip of the planted run named in place of the outlier says
    the same evidence reads as an outlier of that run (JSON aliases and message); no outlier table is named as
    a slip alone, and the case occurs."""
    slips = 0
    for seed in range(20):
        table, planted = ccd_table(seed, 3, "outlier", 10.0)
        result = criticize(table, FACTORS[3], "y", n_null=199)
        for f in result.findings[:1]:
            if f.cause == "factor_level":
                assert f.detail == planted.run and "outlier" in f.aliases, (seed, f.aliases)
                assert "reads as an outlier of run" in f.message
                assert result.to_json()["findings"][0]["aliases"] == ["outlier"]
                slips += 1
    assert slips >= 1


@pytest.mark.workflow  # a benchmark-like batch of tables
def test_an_ambiguous_verdicts_slip_of_the_planted_run_lists_the_outlier_as_its_alias():
    """Planted outliers (2 and 3 factors, seeds 0-39): where the verdict is ambiguous and a one-run candidate sits
    at the planted run, it is the outlier or a slip that lists the outlier as its alias (and says so), as a
    named slip does; the case occurs."""
    slips = 0
    for k in (2, 3):
        for seed in range(40):
            table, planted = ccd_table(seed, k, "outlier", 10.0)
            result = criticize(table, FACTORS[k], "y", n_null=199)
            for c in result.candidates:
                if c["cause"] in ("outlier", "factor_level") and c["detail"] == planted.run:
                    assert c["cause"] == "outlier" or "outlier" in c["aliases"], (k, seed, c)
                    if c["cause"] == "factor_level":
                        assert f"(run {planted.run}; or an outlier)" in result.summary
                        slips += 1
    assert slips >= 1


def test_an_ambiguous_verdict_says_what_each_candidates_runs_read_as_equally_well():
    from demid.criticism.verdict import ambiguous_message

    candidates = [{"cause": "missing_term", "detail": "gamma^3", "delta_aicc": 0.0,
                   "aliases": ["gamma^3", "mu_s^2:gamma"]},
                  {"cause": "heteroscedasticity", "detail": "gamma", "delta_aicc": 2.0, "aliases": ["gamma", "fitted"]},
                  {"cause": "factor_level", "detail": 20, "delta_aicc": 4.0, "aliases": ["outlier"]},
                  {"cause": "outlier", "detail": 11, "delta_aicc": 5.0, "aliases": []}]
    text = ambiguous_message("y", candidates, [])
    assert ("missing term gamma^3 (or mu_s^2:gamma), unequal scatter with gamma (or the predicted value), "
            "run fitting another factor level (run 20; or an outlier), outlying run (run 11) explain" in text)


# --------------------------------------------------------------------------- confirming runs
def _entry(cause, detail, aicc):
    return {"cause": cause, "detail": detail, "aicc": aicc}


def test_a_named_cause_without_a_close_rival_is_confirmed_against_the_nearest_kind():
    entries = [_entry("drift", "run", 0.0), _entry("outlier", 3, 25.0), _entry("step", 7, 14.0),
               _entry("step", 8, 12.0), _entry("missing_term", "a^3", 40.0)]
    assert [(e["cause"], e["detail"]) for e in confirming_rivals(entries, ("drift", "run"))] == \
        [("drift", "run"), ("step", 8)]
    # within CONFIRM_AICC every kind is kept, as before
    entries[1]["aicc"] = discrimination.CONFIRM_AICC - 0.5
    assert [e["cause"] for e in confirming_rivals(entries, ("drift", "run"))] == ["drift", "outlier"]


def _simulate_term(seed: int, k: int, term: str, size: float, runs: list[dict]) -> pd.DataFrame:
    """The proposed runs as ccd_table's missing term would have made them after its runs."""
    new, new_coded = later_runs(seed, k, runs)
    new["y"] += size * model_matrix(new_coded, [parse_term(term, design(k)[0])])[:, 0]
    return new


def test_a_named_term_comes_with_confirming_runs_that_keep_it_named_among_its_aliases():
    """A cubic term planted on a 2-factor CCD is named with the terms the runs alias with it: every named verdict
    carries confirming runs (here with no rival within CONFIRM_AICC), and those runs also tell the term from its
    aliases, so simulated from the generator they leave the planted term named (not an alias that the new runs
    happen to prefer)."""
    checked = 0
    alpha = design(2)[3]  # the design's, not inferred from the levels the new runs add
    for seed in range(12):
        table, planted = ccd_table(seed, 2, "term", 6.0)
        first = criticize(table, FACTORS[2], "y", alpha=alpha, n_null=199)
        if not first.findings or first.candidates or planted.term not in first.findings[0].aliases:
            continue
        runs = first.discriminating_runs
        assert runs and all(r["purpose"] == discrimination.CONFIRM_PURPOSE for r in runs), seed
        assert first.verdict != "defect" or "would confirm it or correct it" in first.verdict_message
        again = criticize(pd.concat([table, _simulate_term(seed, 2, planted.term, 6.0, runs)], ignore_index=True),
                          FACTORS[2], "y", alpha=alpha, n_null=199)
        f = again.findings[0]
        assert f.cause == "missing_term" and planted.term in f.aliases, (seed, f.aliases)
        checked += 1
    assert checked >= 8


# --------------------------------------------------------------------------- confirming runs in the next wave
def test_a_next_wave_makes_the_runs_the_criticism_proposes_and_no_others():
    """Planted defects (2 factors, seeds 0-7): a named cause's confirming runs (replicates included) reach the
    criticism frame's finding row and from there the next wave with purpose 'confirm the named cause', as the
    message says; an ambiguous verdict's deciding runs reach its row; a verdict without runs puts none there."""
    from demid.next_wave import PURPOSE_CONFIRM, PURPOSE_DECIDE
    from demid.wave_runs import deciding_runs

    seen = set()
    for kind, size in (("term", 6.0), ("drift", 8.0), ("outlier", 10.0), ("clean", 0.0)):
        for seed in range(8):
            table, _ = ccd_table(seed, 2, kind, size)
            result = criticize(table, FACTORS[2], "y", n_null=199)
            frame = result.to_frame()
            runs = deciding_runs(frame, FACTORS[2])
            proposed = [{f: r[f] for f in FACTORS[2]} for r in result.discriminating_runs]
            # candidates (an 'ambiguous' row, also under does_not_predict) or a named cause's verdict
            if (result.candidates or result.verdict in NAMING_VERDICTS) and proposed:
                seen.add("decide" if result.candidates else "confirm")
                purpose = PURPOSE_DECIDE if result.candidates else PURPOSE_CONFIRM
                assert [{f: r[f] for f in FACTORS[2]} for r in runs] == proposed, (kind, seed)
                assert {r["purpose"] for r in runs} == {purpose}
                row = frame.index[frame["cause"] == "ambiguous"][0] if result.candidates else 0
                assert isinstance(frame.loc[row, "discriminating_runs"], str)
                if not result.candidates:
                    assert "a next wave (next_runs) makes those inside its box first." in result.verdict_message
                if result.verdict == "defect":
                    # the finding's message joins the verdict's without naming the response twice
                    assert result.verdict_message.startswith("y: defect named — ")
                    assert not result.verdict_message.startswith("y: defect named — y: ")
            else:
                assert runs == [] and "discriminating_runs" not in frame, (kind, seed)
    assert seen == {"decide", "confirm"}


def test_a_cause_named_when_the_quadratic_does_not_predict_is_offered_its_confirming_runs():
    """Large planted outliers (2 factors, seeds 0-15): where the quadratic predicts worse than the mean
    (does_not_predict) and the criticism names a cause, the verdict offers the runs that would confirm it, as a
    defect's does, and they reach the next wave; the case occurs."""
    from demid.next_wave import PURPOSE_CONFIRM
    from demid.wave_runs import deciding_runs

    seen = 0
    for seed in range(16):
        table, _ = ccd_table(seed, 2, "outlier", 20.0)
        result = criticize(table, FACTORS[2], "y", n_null=199)
        if result.verdict != "does_not_predict" or not result.findings:
            continue
        seen += 1
        assert result.discriminating_runs and result.runs_for_next_wave, seed
        text = result.verdict_message
        assert text.startswith("y: does not predict")
        assert "a next wave (next_runs) makes those inside its box first." in text
        runs = deciding_runs(result.to_frame(), FACTORS[2])
        assert [{f: r[f] for f in FACTORS[2]} for r in runs] == [{f: r[f] for f in FACTORS[2]}
                                                                 for r in result.discriminating_runs]
        assert {r["purpose"] for r in runs} == {PURPOSE_CONFIRM}
    assert seen >= 2


def test_the_next_wave_makes_the_deciding_runs_before_the_confirming_ones():
    """Criticism rows of two responses (a confirming row first): next_runs lists the deciding runs first, then the
    confirming ones, each with its own purpose; a replicate is kept, a point both responses propose once made
    serves both; the reason counts both."""
    import json

    from demid.next_wave import PURPOSE_CONFIRM, PURPOSE_DECIDE, plan_next_wave
    from demid.wave_runs import deciding_runs
    from tests.test_next_wave import _annulus_material

    confirm = [{"a": 0.3, "b": 0.7, "purpose": PURPOSE_CONFIRM}, {"a": 0.5, "b": 0.5, "purpose": PURPOSE_CONFIRM},
               {"a": 0.3, "b": 0.7, "purpose": PURPOSE_CONFIRM}]
    decide = [{"a": 0.5, "b": 0.5, "purpose": PURPOSE_DECIDE}, {"a": 0.2, "b": 0.8, "purpose": PURPOSE_DECIDE},
              {"a": 0.2, "b": 0.8, "purpose": PURPOSE_DECIDE}]
    findings = pd.DataFrame([
        {"response": "y", "cause": "drift", "detail": "run", "aliases": "", "discriminating_runs": json.dumps(confirm)},
        {"response": "y2", "cause": "ambiguous", "detail": "outlier (3);step (9)", "aliases": "",
         "discriminating_runs": json.dumps(decide)}])
    runs = deciding_runs(findings, ["a", "b"])
    assert [(r["a"], r["b"], r["purpose"], r["response"]) for r in runs] == [
        (0.5, 0.5, PURPOSE_DECIDE, "y2"), (0.2, 0.8, PURPOSE_DECIDE, "y2"), (0.2, 0.8, PURPOSE_DECIDE, "y2"),
        (0.3, 0.7, PURPOSE_CONFIRM, "y"), (0.3, 0.7, PURPOSE_CONFIRM, "y")]
    table, surrogates, cfg, plausible = _annulus_material(count=12)
    wave = plan_next_wave("m", table, surrogates, cfg, plausible, findings, z=2.0)
    assert len(wave.runs) == 12  # the count includes them
    assert wave.runs["purpose"].tolist()[:5] == [PURPOSE_DECIDE] * 3 + [PURPOSE_CONFIRM] * 2
    assert not {PURPOSE_DECIDE, PURPOSE_CONFIRM} & set(wave.runs["purpose"].tolist()[5:])
    assert ("first 3 run(s) to decide between causes the criticism cannot tell apart (y2), then 2 run(s) to "
            "confirm or correct a cause the criticism named (y)") in wave.reason


def test_criticism_runs_outside_the_next_box_are_left_out_and_the_reason_says_so():
    """The next wave's table keeps only runs inside its box: a criticism run far outside it is not proposed (the
    reason counts it), one outside by less than the criticism's rounding is put on the bound, one inside is
    kept as it is."""
    import json

    from demid.next_wave import PURPOSE_DECIDE, plan_next_wave
    from demid.wave_runs import CRITICISM_ROUNDING
    from tests.test_next_wave import _annulus_material

    table, surrogates, cfg, plausible = _annulus_material(count=9)
    plain = plan_next_wave("m", table, surrogates, cfg, plausible, None, z=2.0)
    box = plain.domain.set_index("factor")
    (a_lo, a_hi), (b_lo, b_hi) = box.loc["a", ["lower", "upper"]], box.loc["b", ["lower", "upper"]]
    assert a_hi < 0.9 and b_lo > 0.1  # refocused: room outside the box within the search range [0, 1]
    edge = {"a": a_hi + CRITICISM_ROUNDING / 4, "b": (b_lo + b_hi) / 2, "purpose": PURPOSE_DECIDE}
    far = {"a": 0.95, "b": 0.05, "purpose": PURPOSE_DECIDE}
    inside = {"a": (a_lo + a_hi) / 2, "b": (b_lo + b_hi) / 2, "purpose": PURPOSE_DECIDE}
    findings = pd.DataFrame([{"response": "y", "cause": "ambiguous", "detail": "outlier (3);step (9)", "aliases": "",
                              "discriminating_runs": json.dumps([far, edge, inside])}])
    wave = plan_next_wave("m", table, surrogates, cfg, plausible, findings, z=2.0)
    assert len(wave.runs) == len(plain.runs)  # the count includes them
    assert wave.runs["a"].iloc[0] == a_hi  # on the bound exactly (the sheet rounds to 10 digits)
    assert wave.runs[["a", "b"]].to_numpy()[:2] == pytest.approx(np.array([[a_hi, edge["b"]],
                                                                           [inside["a"], inside["b"]]]), rel=1e-9)
    assert wave.runs["purpose"].tolist()[:2] == [PURPOSE_DECIDE] * 2
    assert "first 2 run(s) to decide between causes" in wave.reason
    assert "; 1 run(s) the criticism proposed lie outside the refocused box and are left out" in wave.reason


def test_with_a_next_box_the_criticism_chooses_its_runs_inside_it():
    """Given the next box's grid (next_wave.box_points), every run the criticism proposes lies inside the box, so
    the next wave leaves none out, and each is a point of that grid written as the next wave writes its own; without
    it (the design's levels) some proposed runs lie outside the same box.  Planted drifts and outliers, 2 factors,
    seeds 0-5; a box over the upper half of each factor's range."""
    from demid.next_wave import box_points
    from demid.wave_runs import criticism_runs_in_box
    from demid.sampling import Domain
    from tests.generators import RANGES

    factors = FACTORS[2]
    domain = Domain(tuple(factors), tuple(RANGES[f][0] for f in factors), tuple(RANGES[f][1] for f in factors))
    lo_u, hi_u = domain.search_bounds()
    lo, hi = lo_u + 0.4537 * (hi_u - lo_u), hi_u  # bounds that 4 digits of the range do not write exactly
    candidates = box_points(domain, lo, hi)
    outside_without, proposed = 0, 0
    for kind, size in (("drift", 8.0), ("outlier", 10.0)):
        for seed in range(6):
            table, _ = ccd_table(seed, 2, kind, size)
            inside = criticize(table, factors, "y", n_null=199, run_candidates=candidates)
            if inside.runs_for_next_wave:
                kept, left_out = criticism_runs_in_box(inside.discriminating_runs, factors, domain, lo, hi)
                assert left_out == 0 and len(kept) == len(inside.discriminating_runs), (kind, seed)
                # none moved: the next wave writes the points the criticism names (both to 6 digits)
                assert [{f: f"{r[f]:.6g}" for f in factors} for r in kept] == [
                    {f: f"{r[f]:.6g}" for f in factors} for r in inside.discriminating_runs], (kind, seed)
                # each one a point of the box's grid, written as the next wave writes its own (6 digits)
                points = np.array([[r[f] for f in factors] for r in kept])
                assert np.all(np.min(np.max(np.abs(points[:, None, :] - candidates[None, :, :]), axis=2), axis=1)
                              <= 5e-6 * np.max(np.abs(candidates))), (kind, seed)
                assert "chosen on the next wave's box grid" in inside.verdict_message
                proposed += 1
            plain = criticize(table, factors, "y", n_null=199)
            if plain.runs_for_next_wave:
                outside_without += criticism_runs_in_box(plain.discriminating_runs, factors, domain, lo, hi)[1]
                assert "box grid" not in plain.verdict_message
    assert proposed >= 3 and outside_without > 0


def test_a_run_on_the_box_grid_is_written_to_six_digits_and_a_bound_at_zero_as_zero():
    """Data.point_dict of a box-grid point: 6 significant digits, as next_runs.csv writes its runs; float noise
    of the coding's round trip at a bound of 0 is written 0, not 1e-17."""
    from dataclasses import replace

    from demid.criticism.level1 import prepare_data

    table, _ = ccd_table(0, 2, "clean", 0.0)
    table["mu_r"] = table["mu_r"] - table["mu_r"].min()  # the factor's range starts at 0
    data, _ = prepare_data(table, FACTORS[2], "y", None, (), None)
    grid = replace(data, run_candidates=np.zeros((1, 2)))
    for actual, written in (([1e-17, 8.0], {"mu_r": 0.0, "gamma": 8.0}), ([-2e-16, 8.0], {"mu_r": 0.0, "gamma": 8.0}),
                            ([0.123456789, 3.14159265], {"mu_r": 0.123457, "gamma": 3.14159})):
        point = data.coding.to_coded(np.array([actual]))
        assert grid.point_dict(point) == written, actual
        assert str(grid.point_dict(point)["mu_r"]) != "-0.0"
    # without the grid, the design's levels: 4 digits of the range
    assert data.point_dict(data.coding.to_coded(np.array([[0.123456789, 3.14159265]]))) == {"mu_r": 0.1235,
                                                                                          "gamma": 3.14}
