"""Honest causes and verdicts: a slipped factor value is named with its run and factor, misfit that no
catalogued cause explains is reported as unexplained, clean tables stay silent, and every response gets
a verdict a user can act on (adequate with its power, defect, unexplained, does not predict)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm

from demid.criticism import criticize
from demid.criticism.verdict import detectable_departure
from demid.design import Coding, ccd_points, model_matrix, quadratic_terms, rotatable_alpha
from demid.report.columns import TABLE_COLUMNS, columns_table
from demid.report.summary import criticism_lines
from demid.spec import MaterialSpec
from demid.surrogate import fit_response

from ..generators import FACTORS, ccd_table, off_catalogue_table


def _first(result):
    if result.findings:
        return result.findings[0]
    return None


# --------------------------------------------------------------------------- factor_level
SLIP_CASES = [(2, "gamma", 3), (2, "mu_r", 5), (3, "mu_s", 7), (3, "gamma", 13)]


def test_slipped_factor_value_is_named_with_run_and_factor():
    """Runs simulated at a tenth of their recorded value: when a cause is named it is factor_level with
    that run, that factor and the value that fits (or the run itself as an outlier); never another cause."""
    named = 0
    for n_factors, factor, row in SLIP_CASES:
        for seed in range(5):
            table, planted = off_catalogue_table(seed, n_factors, "slip", factor=factor, rows=(row,))
            result = criticize(table, FACTORS[n_factors], "y", n_null=999)
            f = _first(result)
            if f is None:
                continue
            assert f.cause in ("factor_level", "outlier") and f.detail == planted.runs[0], (seed, f.cause, f.detail)
            if f.cause == "factor_level":
                assert f.info["factor"] == factor
                recorded = float(table.loc[table["run"] == planted.runs[0], factor].iloc[0])
                assert f.info["recorded_value"] == pytest.approx(recorded)
                assert f.info["fitting_value"] == pytest.approx(0.1 * recorded)
                assert factor in f.message and f"run {planted.runs[0]}" in f.message
                assert result.to_frame()["cause"].iloc[0] == "factor_level"
                named += 1
    assert named >= 6, named


@pytest.mark.workflow  # a benchmark-like batch of tables
def test_slips_flagged_at_least_as_often_as_by_lack_of_fit():
    """Random slips (run and factor drawn by the generator), 2- and 3-factor CCDs: misfit is reported at
    least as often as the classical lack-of-fit test rejects on the same tables."""
    flagged = detected_by_lof = 0
    for k in (2, 3):
        for seed in range(10):
            table, _ = off_catalogue_table(700 + seed, k, "slip")
            result = criticize(table, FACTORS[k], "y", n_null=999)
            flagged += bool(result.findings or result.unexplained)
            detected_by_lof += fit_response(table, FACTORS[k], "y").statistics().lof_p < 0.05
    assert flagged >= detected_by_lof, (flagged, detected_by_lof)


@pytest.mark.parametrize("k,kind,size", [(2, "plateau", 40), (2, "step", 8), (3, "plateau", 20)])
def test_misfit_flagged_at_least_as_often_as_by_lack_of_fit(k, kind, size):
    """A plateau, a step: misfit that only the lack-of-fit test sees well.  Lack of fit holds 65 % of the
    family's level, so the family flags such tables as often as the classical test alone (12 seeds each:
    7/7, 3/3, 8/8; with equal weights 2, 2 and 2)."""
    flagged = detected_by_lof = 0
    for seed in range(700, 712):
        table, _ = off_catalogue_table(seed, k, kind, size)
        result = criticize(table, FACTORS[k], "y", n_null=999)
        flagged += bool(result.findings or result.unexplained)
        detected_by_lof += fit_response(table, FACTORS[k], "y").statistics().lof_p < 0.05
    assert flagged >= detected_by_lof, (flagged, detected_by_lof)


def test_slip_candidates_are_decimal_slips_of_the_recorded_value():
    """Every candidate moves one factor of one run to 10^k times its recorded value (log-scaled factors:
    log10 shifted by k), k = +-1, +-2, +-3; a zero value has no slip."""
    from demid.criticism.slips import slip_candidates
    from demid.criticism.level1 import prepare_data
    from demid.criticism.models import Model, ModelForm

    table, _ = ccd_table(0, 2, "clean")
    for log_factors in ((), ("gamma",)):
        data, _ = prepare_data(table, FACTORS[2], "y", None, log_factors)
        model = Model(data, ModelForm())
        cands = slip_candidates(data, model)
        assert 0 < len(cands) <= data.n * 2 * 6
        for c in cands[:40]:
            recorded = data.to_actual(data.coded[c.row])[0, c.factor]
            point = data.coded[c.row].copy()
            point[c.factor] = c.coded
            moved = data.to_actual(point)[0, c.factor]
            assert moved == pytest.approx(recorded * 10.0 ** c.power, rel=1e-9)


def test_true_outlier_is_not_renamed_a_slip():
    """A mean shift that no slip explains stays an outlier."""
    hits = 0
    for seed in range(6):
        table, planted = ccd_table(seed, 2, "outlier", 15)
        f = _first(criticize(table, FACTORS[2], "y", n_null=999))
        hits += f is not None and f.cause == "outlier" and f.detail == planted.run
    assert hits >= 5


# --------------------------------------------------------------------------- unexplained
def test_misfit_without_a_catalogue_cause_is_unexplained_or_points_at_a_moved_run():
    """A stranger's table built independently: a regime change moves the three runs with a > 0.5 by +-20
    (sign by b). Lack of fit against the replicated centre runs; no catalogue term describes it. The
    engine reports it as unexplained, or names an outlying run that really moved — never another cause
    (today it names a moved run in every seed)."""
    alpha = rotatable_alpha(2)
    coded = ccd_points(2, alpha, 5)
    moved = coded[:, 0] > 0.5
    unexplained = 0
    for seed in (3, 4, 5):
        rng = np.random.default_rng(seed)
        step = np.where(moved, 20.0, 0.0) * np.where(coded[:, 1] > -0.5, 1.0, -1.0)
        y = 100 + 5 * coded[:, 0] - 3 * coded[:, 1] + step + rng.normal(size=len(coded))
        coding = Coding(("a", "b"), (0.0, 0.0), (1.0, 1.0))
        table = pd.DataFrame(coding.to_actual(coded), columns=["a", "b"])
        runs = rng.permutation(len(coded)) + 1
        table.insert(0, "run", runs)
        table["y"] = y
        result = criticize(table, ["a", "b"], "y", n_null=999)
        assert fit_response(table, ["a", "b"], "y").statistics().lof_p < 0.05
        assert result.verdict != "adequate"
        if result.findings:
            f = result.findings[0]
            assert f.cause == "outlier" and f.detail in set(runs[moved]), (seed, f.cause, f.detail)
            continue
        unexplained += 1
        assert result.unexplained and result.unexplained["tests"]
        frame = result.to_frame()
        assert list(frame["cause"]) == ["unexplained"]
        assert "no catalogued cause" in frame["message"].iloc[0]


@pytest.mark.parametrize("k,kind,size", [(3, "plateau", 40), (2, "hidden", 20)])
def test_off_catalogue_defects_are_mostly_unexplained_not_misnamed(k, kind, size):
    """A plateau along one factor, an unrecorded factor entering as a cubic: misfit is reported, often as
    unexplained (an outlier on a run the defect really moved is not counted as a wrong cause).
    benchmarks/honest_causes.py, 20 seeds: wrong 0.05 / 0.20 (lenient), unexplained 0.95 / 0.55 (0.30 / 0.30 and
    0.45 / 0.35 before a cause had to be singled out); the thresholds are a regression guard."""
    wrong = unexplained = 0
    for seed in range(8):
        table, planted = off_catalogue_table(300 + seed, k, kind, size)
        result = criticize(table, FACTORS[k], "y", n_null=999)
        f = _first(result)
        unexplained += result.unexplained is not None
        wrong += f is not None and not (f.cause == "outlier" and f.detail in planted.runs)
    assert wrong <= 5, (kind, wrong)  # a regression guard at the measured level, not the 10 % goal
    assert unexplained >= 2, (kind, unexplained)


# --------------------------------------------------------------------------- silence and verdicts
def test_clean_tables_are_adequate_with_a_power_caveat():
    alarms = 0
    for seed in range(8):
        for k in (2, 3):
            table, _ = ccd_table(500 + seed, k, "clean")
            result = criticize(table, FACTORS[k], "y", n_null=999)
            if result.verdict != "adequate":
                alarms += 1
                continue
            detail = result.verdict_detail
            assert detail["detectable_sd"] > 1.0
            assert "smaller defects may be present" in detail["message"]
            frame = result.to_frame()
            assert frame.empty or set(frame["verdict"]) == {"adequate"}
    assert alarms <= 1


def test_detectable_departure_has_its_power_by_simulation():
    """A departure of k residual SDs along a direction outside the model is found by the 1-df F test
    at level alpha/m in 80 % of simulated tables (Monte Carlo, independent of the noncentral F)."""
    rng = np.random.default_rng(0)
    for n, p, m in ((13, 6, 10), (20, 10, 14)):
        k = detectable_departure(n - p, m, 0.05)
        df = n - p - 1
        eps = rng.standard_normal((40_000, df + 1))  # residual space coordinates: the departure on axis 0
        eps[:, 0] += k
        f = eps[:, 0] ** 2 / (np.sum(eps[:, 1:] ** 2, axis=1) / df)
        from scipy import stats
        power = np.mean(f > stats.f.ppf(1 - 0.05 / m, 1, df))
        assert power == pytest.approx(0.8, abs=0.01)


def test_noise_only_response_does_not_predict():
    """A response that is pure noise: Q² < 0 (statsmodels PRESS), verdict does_not_predict."""
    for seed in range(3):
        table, _ = ccd_table(seed, 2, "clean")
        rng = np.random.default_rng(seed)
        table["y"] = 100 + rng.normal(size=len(table))
        x = model_matrix(Coding.from_levels(FACTORS[2], table[FACTORS[2]].to_numpy(), rotatable_alpha(2))
                         .to_coded(table[FACTORS[2]].to_numpy()), quadratic_terms(2))
        res = sm.OLS(table["y"].to_numpy(), x).fit()
        press = float(np.sum((res.resid / (1 - res.get_influence().hat_matrix_diag)) ** 2))
        q2 = 1 - press / float(np.sum((table["y"] - table["y"].mean()) ** 2))
        result = criticize(table, FACTORS[2], "y", n_null=499)
        assert result.verdict_detail["q2"] == pytest.approx(q2)
        if q2 < 0:
            assert result.verdict == "does_not_predict"
            assert "Do not use this surrogate" in result.verdict_message
        else:
            assert result.verdict != "does_not_predict"


def test_verdict_column_documented_and_written():
    assert TABLE_COLUMNS["criticism"][-2:] == ["verdict", "discriminating_runs"]
    cols = columns_table({})
    row = cols[(cols["table"] == "criticism.csv") & (cols["column"] == "verdict")]
    assert len(row) == 1 and "does_not_predict" in row["description"].iloc[0]


def test_report_warns_about_scenarios_using_a_surrogate_that_does_not_predict():
    material = {"design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 1}, "b": {"lower": 0, "upper": 1}},
                "responses": {"S": {"target": 1.0}, "T": {"target": 2.0}},
                "scenarios": {"both": {"observables": ["S", "T"], "tolerance": 0.05},
                              "t_only": {"observables": ["T"], "tolerance": 0.05}},
                "pareto": {"error_of": "T", "minimise": "S", "max_error": 0.05},
                "data": "x.csv"}
    try:
        spec = MaterialSpec.from_material("m", material)
    except Exception as exc:  # the spec needs more keys in this version: build it as the config does
        pytest.skip(f"material spec: {exc}")
    info = {"level1": {"S": {"findings": 0, "messages": [], "verdict": "does_not_predict",
                             "verdict_message": "S: does not predict — Q² = -1.48. Do not use this surrogate."},
                       "T": {"findings": 0, "messages": [], "verdict": "adequate",
                             "verdict_message": "T: adequate — smaller defects may be present."}}}
    lines = criticism_lines(info, spec)
    text = "\n".join(lines)
    assert "does not predict" in text and "Q² = -1.48" in text
    assert "smaller defects may be present" in text
    warnings = [line for line in lines if line.startswith("⚠ Scenario")]
    assert len(warnings) == 1 and "both" in warnings[0]
    assert any(line.startswith("⚠ The Pareto front uses S") for line in lines)
    assert "the quadratic fits the simulation runs" not in text


def test_cli_json_carries_the_verdict_and_the_slip(tmp_path):
    """`demid criticize` JSON: the earlier keys plus verdict, verdict_detail and unexplained."""
    import json
    import subprocess
    import sys

    table, planted = off_catalogue_table(4, 3, "slip", factor="mu_s", rows=(7,))
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    out = tmp_path / "c.json"
    proc = subprocess.run([sys.executable, "-m", "demid", "criticize", "--data", str(path), "--factors",
                           ",".join(FACTORS[3]), "--response", "y", "--out", str(out)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    result = json.loads(out.read_text())
    for key in ("response", "baseline", "findings", "extended", "gain", "summary", "catalogue", "runs"):
        assert key in result
    assert result["verdict"] in ("defect", "does_not_predict")
    first = result["findings"][0]
    assert first["cause"] == "factor_level" and first["detail"] == planted.runs[0] and first["factor"] == "mu_s"
    assert "factor_level" in {c["cause"] for c in result["catalogue"]}
    assert result["unexplained"] is None and result["verdict_detail"]["message"]


@pytest.mark.parametrize("seed,n_factors,where", [(4, 3, {"factor": "mu_s", "rows": (7,)}),
                                                  (2, 2, {"factor": "gamma", "rows": (5,)}), (718, 3, {})])
def test_no_further_run_tells_a_slip_from_a_shift_of_the_same_run(seed, n_factors, where):
    """The slipped run's two readings, the run made at the fitting value or the run alone shifted, predict every
    new run alike (at the recorded value, at the fitting one, anywhere in the design's reach): the best MAX_RUNS
    runs separate them by far less than runs that decide need (target_separation), so the message sends the
    user to the run's input, not to more runs."""
    from demid.criticism import discrimination
    from demid.criticism.level1 import prepare_data
    from demid.criticism.models import Model, ModelForm

    table, planted = off_catalogue_table(seed, n_factors, "slip", **where)
    data, _ = prepare_data(table, FACTORS[n_factors], "y", None, ())
    f = criticize(table, FACTORS[n_factors], "y", n_null=199).findings[0]
    assert f.cause == "factor_level" and f.detail == planted.runs[0]
    assert "no further run tells a slip" in f.message
    i, j = int(np.flatnonzero(data.runs == f.detail)[0]), FACTORS[n_factors].index(f.info["factor"])
    point = np.array(table.loc[i, FACTORS[n_factors]], dtype=float)
    point[j] = f.info["fitting_value"]
    moved = float(data.coding.to_coded(point[None, :])[0, j])
    shifted, slipped = Model(data, ModelForm(dropped=(i,))), Model(data, ModelForm(moved=((i, j, moved),)))
    runs = discrimination.discriminating_runs(data, [shifted, slipped], ["shift", "slip"])
    assert len(runs) == discrimination.MAX_RUNS
    assert runs[-1]["separation"] < discrimination.target_separation(0.0) / 5


# --------------------------------------------------------------------------- a cause must be singled out
def _hyp(cause, p, detail=None):
    from demid.criticism.catalogue import Hypothesis
    return Hypothesis(cause, detail, logp=float(np.log(p)))


def test_a_cause_is_named_only_when_its_test_is_the_strongest_evidence():
    """Known answers of the rule: the named cause's nominal p must be the smallest among tests of other
    kinds (lack of fit included) unless it is below 1e-4; an outlier and a slip of the same run are one
    kind; the Box-Cox bootstrap p-value is never compared."""
    from demid.criticism.verdict import OVERWHELMING_P, strongest_rival
    outlier = _hyp("outlier", 1e-3, 4)
    lof = _hyp("lack_of_fit", 5e-4)
    assert strongest_rival(outlier, [outlier, lof, _hyp("drift", 0.2, "run")]) is lof
    assert strongest_rival(outlier, [outlier, _hyp("lack_of_fit", 2e-3)]) is None
    assert strongest_rival(outlier, [outlier, _hyp("factor_level", 1e-5)]) is None  # the same run
    slip = _hyp("factor_level", 5e-4, 4)  # a floored bootstrap p-value: the run's outlier test speaks for it
    assert strongest_rival(slip, [slip, _hyp("outlier", 1e-4, 4), _hyp("lack_of_fit", 2e-4)]) is None
    assert strongest_rival(slip, [slip, _hyp("outlier", 3e-4, 4), lof]) is None
    lof_stronger = _hyp("lack_of_fit", 4e-4)
    assert strongest_rival(slip, [slip, _hyp("outlier", 6e-4, 4), lof_stronger]) is lof_stronger
    het = [_hyp("heteroscedasticity", 3e-3, "a"), _hyp("heteroscedasticity", 1e-3, "b")]
    # the cause's own strongest test counts, whichever covariate was named
    assert strongest_rival(het[0], het + [_hyp("missing_term", 2e-3)]) is None
    assert strongest_rival(het[0], het + [_hyp("missing_term", 9e-4)]).cause == "missing_term"
    strong = _hyp("missing_term", OVERWHELMING_P / 2)
    assert strongest_rival(strong, [strong, _hyp("lack_of_fit", OVERWHELMING_P / 10)]) is None
    boxcox = _hyp("response_transform", 5e-4)
    assert strongest_rival(boxcox, [boxcox, _hyp("lack_of_fit", 1e-6)]) is None


SPREAD_MISFIT = [(3, "hidden", 20), (3, "plateau", 40), (3, "batch", 6), (2, "hidden", 20), (2, "batch", 10)]


@pytest.mark.workflow  # a benchmark-like batch of tables
def test_misfit_spread_over_several_tests_is_not_given_a_cause():
    """An unrecorded factor, a plateau, a batch of three shifted runs: lack of fit and several catalogue tests
    fire about equally.  Over 12 seeds of each of five such cells (60 tables) a confident cause other than
    an outlier on a run the defect really moved is named in 13 tables with the singled-out rule and in 30
    without it (benchmarks/honest_causes.py, 40 seeds: 0.30 -> 0.22 over all off-catalogue cells); the
    unexplained message says which candidate was not singled out."""
    wrong = singled = 0
    for k, kind, size in SPREAD_MISFIT:
        for seed in range(600, 612):
            table, planted = off_catalogue_table(seed, k, kind, size)
            result = criticize(table, FACTORS[k], "y", n_null=999)
            f = _first(result)
            wrong += f is not None and not (f.cause == "outlier" and f.detail in planted.runs)
            if result.unexplained and result.unexplained.get("candidate"):
                singled += 1
                assert "is not singled out" in result.unexplained["message"]
    assert wrong <= 18, wrong
    assert singled >= 10, singled


# --------------------------------------------------------------------------- a cause of the whole design must not rest on one run
def _first_round(table, k, seed=0):
    from demid.criticism.catalogue import Round
    from demid.criticism.level1 import prepare_data
    from demid.criticism.models import Model, ModelForm

    data, _ = prepare_data(table, FACTORS[k], "y", None, ())
    model = Model(data, ModelForm())
    return data, model, Round(data, model, 199, np.random.default_rng(seed))


def test_one_run_deletions_match_refits_without_each_run():
    """Known answers: the cause's test with run i left out equals a refit on the other runs, done here with
    statsmodels alone: the F test of the added term (compare_f_test), and the likelihood ratio of
    var = sigma^2 exp(gamma v) profiled by WLS over the test's gamma grid, in its F form."""
    from scipy import stats as st

    from demid.criticism.catalogue import GAMMA_GRID
    from demid.criticism.one_run import deleted_logp, worst_deletion

    table, _ = ccd_table(3, 3, "term", 4.0)
    data, model, rnd = _first_round(table, 3)
    term = next(h for h in rnd.hypotheses if h.cause == "missing_term")
    het = next(h for h in rnd.hypotheses if h.cause == "heteroscedasticity" and h.detail != "fitted")
    x = model_matrix(model.coded, model.mean_terms)
    extra = model_matrix(model.coded, [term.detail.terms[0]])
    v = model.coded[:, FACTORS[3].index(het.detail)] / data.alpha
    got_term = deleted_logp(data, model, term, model.y[:, None])[:, 0]
    got_het = deleted_logp(data, model, het, model.y[:, None])[:, 0]
    for i in range(data.n):
        keep = np.arange(data.n) != i
        small = sm.OLS(model.y[keep], x[keep]).fit()
        big = sm.OLS(model.y[keep], np.column_stack([x[keep], extra[keep]])).fit()
        assert np.exp(got_term[i]) == pytest.approx(big.compare_f_test(small)[1], rel=1e-6)
        llf = [sm.WLS(model.y[keep], x[keep], weights=np.exp(-g * v[keep])).fit().llf for g in GAMMA_GRID]
        lr = 2 * (max(llf) - llf[int(np.argmin(np.abs(GAMMA_GRID)))])
        df = int(keep.sum()) - x.shape[1]
        p = st.f.sf((df - 1) * np.expm1(lr / keep.sum()), 1, df - 1)
        assert np.exp(got_het[i]) == pytest.approx(p, rel=1e-6)
    worst = worst_deletion(data, model, het)
    assert worst.row == int(np.argmax(got_het)) and worst.p_without == pytest.approx(np.exp(got_het.max()))


def test_unequal_scatter_resting_on_one_run_is_not_named():
    """Known answer of the rule: one run at the top of a factor's range moved by 12 noise SDs makes the
    scatter test against that factor significant; without that run it is not, so the rule returns that run.
    Scatter growing over every replicated point (2-factor CCD, points in triplicate, SD ratio 30) keeps
    its evidence whichever run is left out: named as before."""
    from demid.criticism.verdict import ONE_RUN_P, rests_on_one_run

    table, _ = ccd_table(5, 3, "clean")
    data, model, _ = _first_round(table, 3)
    row = int(np.argmax(data.coded[:, 2]))  # the axial run at the top of gamma
    table.loc[row, "y"] += 12.0
    data, model, rnd = _first_round(table, 3)
    het = next(h for h in rnd.hypotheses if h.cause == "heteroscedasticity" and h.detail == "gamma")
    assert np.exp(het.logp) < 0.01
    one = rests_on_one_run(data, model, het)
    assert one is not None and one.row == row and one.p_without > ONE_RUN_P
    for seed in (101, 102, 103):
        table, planted = ccd_table(seed, 2, "het", 30.0, replicates=3)
        data, model, rnd = _first_round(table, 2)
        het = next(h for h in rnd.hypotheses if h.cause == "heteroscedasticity" and h.detail == planted.factor)
        assert rests_on_one_run(data, model, het) is None
        f = _first(criticize(table, FACTORS[2], "y", n_null=999))
        assert (f.cause, f.detail) == ("heteroscedasticity", planted.factor)


@pytest.mark.workflow  # a benchmark-like batch of tables
def test_one_run_rule_gives_fewer_wrong_causes_on_a_batch_of_shifted_runs():
    """Three runs shifted by 10 noise SDs (3-factor CCD, 13 seeds): without the rule unequal scatter is
    named in three tables from one wild run (seeds 507-509); with it they are unexplained, and no table
    gets a wrong cause it did not get before."""
    from demid.criticism import verdict

    def wrong(table, planted):
        res = criticize(table, FACTORS[3], "y", n_null=999)
        f = _first(res)
        if res.candidates:  # ambiguous: wrong unless a shifted run is among the candidates
            return not any(c["cause"] == "outlier" and c["detail"] in planted.runs for c in res.candidates)
        return f is not None and not (f.cause == "outlier" and f.detail in planted.runs)

    with_rule, without_rule = [], []
    for seed in range(500, 513):
        table, planted = off_catalogue_table(seed, 3, "batch", 10)
        with_rule.append(wrong(table, planted))
        saved = verdict.ONE_RUN_CAUSES
        verdict.ONE_RUN_CAUSES = ()
        try:
            without_rule.append(wrong(table, planted))
        finally:
            verdict.ONE_RUN_CAUSES = saved
    assert sum(with_rule) < sum(without_rule), (sum(with_rule), sum(without_rule))
    assert all(b for a, b in zip(with_rule, without_rule) if a)


def test_a_term_only_the_corner_runs_carry_is_found_by_its_geometry():
    """On a CCD, x1*x2*x3 is carried by the 8 corner runs alone, where it is the only pattern the quadratic
    cannot follow: a regime change in part of the corner region looks exactly like it.  A pure cubic term
    (carried by the axial runs too) and a product of three of four factors are not such terms."""
    import numpy as np

    from demid.criticism.messages import corner_only_runs
    from demid.design import ccd_points

    class Runs:  # the rule reads the coded runs and their number only
        def __init__(self, coded):
            self.coded, self.n = coded, len(coded)

    coded = ccd_points(3, 1.68179, 6)
    assert corner_only_runs(Runs(coded), (1, 1, 1)) == 8
    assert corner_only_runs(Runs(coded), (3, 0, 0)) == 0
    assert corner_only_runs(Runs(coded), (2, 1, 0)) == 0
    # with four factors other products share the corners: no such claim
    assert corner_only_runs(Runs(ccd_points(4, 2.0, 12)), (1, 1, 1, 0)) == 0
    # the claim itself: on the corners, main effects, two-factor interactions and x1*x2*x3 span every pattern
    corners = coded[np.all(np.abs(coded) == 1, axis=1)]
    x = np.column_stack([np.ones(8), corners, corners[:, [0]] * corners[:, [1]], corners[:, [0]] * corners[:, [2]],
                         corners[:, [1]] * corners[:, [2]], np.prod(corners, axis=1)])
    assert np.linalg.matrix_rank(x) == 8


@pytest.mark.parametrize("seed", range(3))
def test_a_corner_step_and_a_three_factor_interaction_are_not_told_apart_by_name(seed):
    """A step over the corner where the coded factors sum past 0.5 and a genuine x1*x2*x3 term look the
    same on a 3-factor CCD's runs: neither is named a missing term; both are reported unexplained with the
    term as the candidate and what runs would separate them.  A pure cubic term is still named."""
    from tests.generators import FACTORS, ccd_table, off_catalogue_table

    factors = FACTORS[3]
    step, _ = off_catalogue_table(100_000 + seed, 3, "step", 12)
    product, _ = ccd_table(seed, 3, "term", 10, term=":".join(factors))
    for table in (step, product):
        result = criticize(table, factors, "y", n_null=499)
        assert not result.findings and result.verdict in ("unexplained", "does_not_predict")
        candidate = result.unexplained["candidate"]
        assert candidate["cause"] == "missing_term" and candidate["corner_only"] == 8
        assert "only the 8 corner runs carry it" in result.unexplained["message"]
    cubic, planted = ccd_table(seed, 3, "term", 10, term=f"{factors[0]}^3")
    result = criticize(cubic, factors, "y", n_null=499)
    assert result.findings and result.findings[0].cause == "missing_term"
    assert planted.term in result.findings[0].aliases


@pytest.mark.parametrize("seed", [0, 1])
def test_large_table_worst_deletion_of_unequal_scatter_equals_every_deletion(seed):
    """Above LOO_REFIT_MAX_RUNS runs only the runs ranked weakest by the fixed-covariate identity are
    refitted: the run and p found equal those of refitting without every run, for the fitted-value and the
    factor covariates (scatter growing with the response, one wild run at a corner)."""
    from demid.criticism.catalogue import Round
    from demid.criticism.level1 import prepare_data
    from demid.criticism.models import Model, ModelForm
    from demid.criticism.one_run import deleted_logp, worst_deletion
    from demid.surrogate import LOO_REFIT_MAX_RUNS

    rng = np.random.default_rng(seed)
    n = LOO_REFIT_MAX_RUNS + 60
    x = rng.uniform(-1, 1, (n, 2))
    mean = 10 + 2 * x[:, 0] - x[:, 1] + 0.5 * x[:, 0] * x[:, 1]
    y = mean + 0.05 * np.exp(0.8 * x[:, 0]) * rng.standard_normal(n)
    y[np.argmax(x[:, 0] + x[:, 1])] += 1.0
    table = pd.DataFrame({"run": np.arange(1, n + 1), FACTORS[2][0]: x[:, 0], FACTORS[2][1]: x[:, 1], "y": y})
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    model = Model(data, ModelForm())
    hypotheses = [h for h in Round(data, model, 99, np.random.default_rng(seed)).hypotheses
                  if h.cause == "heteroscedasticity"]
    assert {h.detail for h in hypotheses} >= {"fitted", FACTORS[2][0]}
    for h in hypotheses:
        every = deleted_logp(data, model, h, model.z[:, None])[:, 0]
        worst = worst_deletion(data, model, h)
        assert worst.row == int(np.flatnonzero(model.keep)[np.argmax(every)])
        assert worst.p_without == pytest.approx(np.exp(every.max()), rel=1e-12)
