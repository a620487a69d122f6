"""Tests for demid.transcription: agreement with the source's statistics and single-cell slip search."""

import json

import numpy as np
import pandas as pd
import pytest
from numpy.testing import assert_allclose

from demid.design import Coding, ccd_points, quadratic_terms, rotatable_alpha
from demid.errors import InputError
from demid.surrogate import fit_response
from demid.transcription import (
    KINDS,
    STATISTICS,
    check_table,
    check_transcription,
    parse_printed,
    single_cell_slips,
)
from demid.transcription.engine import DesignFit, evaluate_designs, lack_of_fit_p

CENTRES = (0.5, 6.4, -2.0)
UNITS = (0.3, 2.0, 1.5)


def ccd_table(k: int, seed: int) -> tuple[pd.DataFrame, list[str], float]:
    """A rotatable CCD as printed (strings): factors with 4 decimals, response with 2, runs shuffled."""
    rng = np.random.default_rng(seed)
    alpha = rotatable_alpha(k)
    coded = ccd_points(k, alpha, center_runs=5 if k == 2 else 6)
    c = coded[rng.permutation(len(coded))]
    y = 2 + 3 * c[:, 0] - 2 * c[:, 1] + 1.5 * c[:, 0] ** 2 - c[:, 1] ** 2 + 0.8 * c[:, 0] * c[:, 1]
    if k == 3:
        y = y - 1.2 * c[:, 2] + 0.6 * c[:, 2] ** 2
    y = y + rng.normal(0, 0.4, len(c))
    printed = {"run": [str(i + 1) for i in range(len(c))]}
    for i in range(k):
        printed[f"x{i + 1}"] = [f"{v:.4f}" for v in CENTRES[i] + UNITS[i] * c[:, i]]
    printed["y"] = [f"{v:.2f}" for v in y]
    return pd.DataFrame(printed), [f"x{i + 1}" for i in range(k)], alpha


def numeric(printed: pd.DataFrame) -> pd.DataFrame:
    return printed.apply(pd.to_numeric)


def published_as_printed(table: pd.DataFrame, factors: list[str], alpha: float) -> dict[str, str]:
    """The unmutated table's statistics rounded as a source would print them."""
    fit = fit_response(table, factors, "y", alpha=alpha)
    s, a = fit.statistics(), fit.anova()
    return {"r2": f"{s.r2:.4f}", "adj_r2": f"{s.adj_r2:.4f}", "rmse": f"{s.rmse:.4f}",
            "resid_std": f"{s.resid_std:.3f}", "lof_f": f"{s.lof_f:.2f}",
            "ss_model": f"{a.ss_model:.2f}", "ss_residual": f"{a.ss_residual:.2f}",
            "ss_lof": f"{a.ss_lof:.2f}", "ss_pure_error": f"{a.ss_pure_error:.2f}"}


@pytest.fixture(scope="module")
def tables():
    out = {}
    for k, seed in ((2, 11), (3, 12)):
        printed, factors, alpha = ccd_table(k, seed)
        out[k] = (printed, factors, alpha, published_as_printed(numeric(printed), factors, alpha))
    return out


# Montgomery, Design and Analysis of Experiments, Example 11.2 (coded CCD, alpha = 1.414).
MONTGOMERY = [(-1, -1, 76.5), (-1, 1, 77.0), (1, -1, 78.0), (1, 1, 79.5), (0, 0, 79.9), (0, 0, 80.3),
              (0, 0, 80.0), (0, 0, 79.7), (0, 0, 79.8), (1.414, 0, 78.4), (-1.414, 0, 75.6),
              (0, 1.414, 78.5), (0, -1.414, 77.0)]
MONTGOMERY_PUBLISHED = {"r2": "0.9827", "ss_model": "28.25", "ss_residual": "0.50", "ss_lof": "0.28",
                        "ss_pure_error": "0.21"}


def montgomery() -> pd.DataFrame:
    table = pd.DataFrame(MONTGOMERY, columns=["x1", "x2", "y"])
    table.insert(0, "run", np.arange(1, len(table) + 1))
    return table


# --------------------------------------------------------------------------- printed values
def test_parse_printed_keeps_decimals_as_printed():
    assert parse_printed("0.970").decimals == 3
    assert parse_printed(0.97).decimals == 2          # a YAML float: decimals from repr
    assert parse_printed(28).decimals == 0
    assert parse_printed(1e-05).decimals == 5
    assert parse_printed(0.97, 4).decimals == 4       # explicit decimals win
    pct = parse_printed("98.27%")
    assert pct.value == pytest.approx(0.9827) and pct.decimals == 4
    bound = parse_printed("< 0.0001")
    assert bound.relation == "<" and bound.value == 1e-4
    assert bound.agrees(3e-5) and not bound.agrees(2e-4)
    with pytest.raises(InputError):
        parse_printed("n/a", where="published")


def test_agreement_accepts_either_rounding_at_the_half_way_point():
    value = parse_printed("0.2")
    assert value.agrees(0.25) and value.agrees(0.15)   # half up / half even both accepted
    assert value.agrees(0.2049) and not value.agrees(0.2501) and not value.agrees(np.nan)
    assert value.misfit(0.2) == 0.0 and value.misfit(0.3) == pytest.approx(2.0)


def test_single_cell_slips_cover_every_kind():
    slips = {(kind, text) for kind, text, _ in single_cell_slips("79.5")}
    assert ("transposition", "97.5") in slips
    assert ("decimal_shift", "7.95") in slips and ("decimal_shift", "795") in slips
    assert ("sign_lost", "-79.5") in slips
    assert ("digit_substitution", "78.5") in slips
    assert ("digit_dropped", "779.5") in slips
    assert ("digit_doubled", "7.5") in {(k, t) for k, t, _ in single_cell_slips("7.55")}
    values = [v for _, _, v in single_cell_slips("79.5")]
    assert len(values) == len(set(values)) and 79.5 not in values
    assert {k for k, _, _ in single_cell_slips("-0.0445")} == set(KINDS)
    # no table prints a leading zero: "500.3" was not typed for "050.3"
    assert not [t for _, t, _ in single_cell_slips("500.3") if t.lstrip("-").startswith("0") and t[1:2] != "."]
    assert ("decimal_shift", "50.03") in {(k, t) for k, t, _ in single_cell_slips("500.3")}


# --------------------------------------------------------------------------- statistics
@pytest.mark.parametrize("k", [2, 3])
def test_reproduced_statistics_equal_fit_response(tables, k):
    printed, factors, alpha, _ = tables[k]
    table = numeric(printed)
    table.loc[2, "y"] = np.nan  # a failed run is dropped, as fit_response does
    fit = fit_response(table, factors, "y", alpha=alpha)
    s, a = fit.statistics(), fit.anova()
    coef = fit.coefficients().set_index("term")
    published = {name: "0" for name in STATISTICS}
    published["coefficients"] = {"units": "coded", "values": {t: 0 for t in coef.index}}
    result = check_transcription(table, factors, "y", published, alpha=alpha)
    expected = {**{n: getattr(s, n) for n in ("r2", "adj_r2", "rmse", "resid_std", "q2", "lof_f", "lof_p")},
                **{n: getattr(a, n) for n in ("ss_model", "ss_residual", "ss_lof", "ss_pure_error", "ss_total")}}
    for name, value in expected.items():
        assert result.reproduced[name] == pytest.approx(value, rel=1e-10, abs=1e-12), name
    for term, row in coef.iterrows():
        assert result.reproduced[f"coef_coded[{term}]"] == pytest.approx(row["coefficient_coded"], abs=1e-10)
    actual = check_transcription(table, factors, "y",
                                 {"coefficients": {"units": "actual", "values": {t: 0 for t in coef.index}}},
                                 alpha=alpha)
    for term, row in coef.iterrows():
        assert actual.reproduced[f"coef_actual[{term}]"] == pytest.approx(row["coefficient_actual"], abs=1e-8)


def test_closed_form_hypotheses_equal_direct_refits(tables):
    """The batched response and design evaluations equal fit_response on each repaired table."""
    printed, factors, alpha, _ = tables[3]
    table = numeric(printed)
    terms = quadratic_terms(3)
    x = table[factors].to_numpy(float)
    y = table["y"].to_numpy(float)
    coding = Coding.from_levels(factors, x, alpha)
    coef = {"coef_coded[x1]": ("coded", 1)}
    ymat = np.repeat(y[:, None], 3, axis=1)
    ymat[[0, 5, 19], [0, 1, 2]] = [10.0, -3.0, 0.5]
    batch = lack_of_fit_p(DesignFit(coding.to_coded(x), terms, coding, False).evaluate(ymat, coef))
    designs = []
    for row, col, value in ((0, 0, 0.8), (5, 2, -3.5), (19, 1, 9.7636)):
        repaired = x.copy()
        repaired[row, col] = value
        designs.append(repaired)
    codings = [Coding.from_levels(factors, d, alpha) for d in designs]
    stack = np.stack([c.to_coded(d) for c, d in zip(codings, designs)])
    refits = lack_of_fit_p(evaluate_designs(stack, y, terms, None, coef))
    for i in range(3):
        for values, frame in ((batch, table.assign(y=ymat[:, i])),
                              (refits, table.assign(**{f: designs[i][:, j] for j, f in enumerate(factors)}))):
            fit = fit_response(frame, factors, "y", alpha=alpha)
            s, a = fit.statistics(), fit.anova()
            for name in ("r2", "adj_r2", "rmse", "q2", "lof_f", "lof_p"):
                assert values[name][i] == pytest.approx(getattr(s, name), rel=1e-9), name
            for name in ("ss_lof", "ss_pure_error"):
                assert values[name][i] == pytest.approx(getattr(a, name), rel=1e-9, abs=1e-12), name
            assert values["coef_coded[x1]"][i] == pytest.approx(fit.results.params["x1"], rel=1e-9)


# --------------------------------------------------------------------------- consistent tables
@pytest.mark.parametrize("k", [2, 3])
def test_unmutated_table_is_consistent_with_no_suspects(tables, k):
    printed, factors, alpha, published = tables[k]
    result = check_transcription(numeric(printed), factors, "y", published, alpha=alpha, printed=printed)
    assert result.consistent and result.suspects == [] and result.explained is None
    assert all(result.agrees.values())
    assert "reproduces all 9 published statistics" in result.message


def test_montgomery_example_is_consistent():
    result = check_transcription(montgomery(), ["x1", "x2"], "y", MONTGOMERY_PUBLISHED, alpha=1.414)
    assert result.consistent and result.suspects == []
    assert result.reproduced["r2"] == pytest.approx(0.98273, abs=1e-5)
    assert result.reproduced["ss_pure_error"] == pytest.approx(0.212, abs=1e-9)


# --------------------------------------------------------------------------- single slips
CASES = [  # (factors, column, run, as published, as transcribed, kind)
    (2, "y", 4, "6.65", "6.15", "digit_substitution"),
    (2, "y", 8, "9.16", "9.61", "transposition"),
    (2, "y", 5, "2.68", "26.8", "decimal_shift"),
    (2, "y", 1, "-2.67", "2.67", "sign_lost"),
    (2, "y", 10, "4.57", "4.7", "digit_dropped"),
    (2, "y", 7, "1.09", "11.09", "digit_doubled"),
    (2, "x1", 10, "0.8000", "0.3000", "digit_substitution"),
    (2, "x1", 7, "0.0757", "0.0577", "transposition"),      # an axial point: sets the coding's range
    (2, "x2", 5, "3.5716", "35.716", "decimal_shift"),
    (2, "x1", 13, "0.2000", "-0.2000", "sign_lost"),        # a stray minus
    (2, "x2", 12, "9.2284", "9.284", "digit_dropped"),
    (2, "x2", 9, "6.4000", "6.44000", "digit_doubled"),
    (3, "y", 13, "8.26", "8.86", "digit_substitution"),
    (3, "y", 3, "6.81", "6.18", "transposition"),
    (3, "y", 6, "11.26", "1.126", "decimal_shift"),
    (3, "y", 12, "-4.14", "4.14", "sign_lost"),
    (3, "y", 15, "-4.48", "-4.8", "digit_dropped"),
    (3, "y", 2, "5.35", "5.335", "digit_doubled"),
    (3, "x2", 18, "4.4000", "4.9000", "digit_substitution"),
    (3, "x1", 20, "-0.0045", "-0.0054", "transposition"),
    (3, "x3", 7, "0.5227", "5.227", "decimal_shift"),
    (3, "x3", 4, "-2.0000", "2.0000", "sign_lost"),
    (3, "x2", 15, "9.7636", "9.736", "digit_dropped"),
    (3, "x1", 6, "1.0045", "1.00045", "digit_doubled"),
]


@pytest.mark.parametrize("k, column, run, truth, typo, kind", CASES,
                         ids=[f"{c[0]}f-{c[1]}-{c[5]}" for c in CASES])
def test_single_slip_is_found_at_the_top(tables, k, column, run, truth, typo, kind):
    printed, factors, alpha, published = tables[k]
    row = run - 1
    assert printed.loc[row, column] == truth
    mutated = printed.copy()
    mutated.loc[row, column] = typo
    result = check_transcription(numeric(mutated), factors, "y", published, alpha=alpha, printed=mutated)
    assert not result.consistent and result.explained
    best = result.suspects[0]
    assert (best.run, best.column, best.suggested, best.kind) == (run, column, float(truth), kind)
    assert best.found == float(typo) and best.restores == len(published)
    # Without the printed strings the cell's form is reconstructed from the numbers; same verdict.
    plain = check_transcription(numeric(mutated), factors, "y", published, alpha=alpha)
    assert (plain.suspects[0].run, plain.suspects[0].column, plain.suspects[0].suggested) == (run, column,
                                                                                               float(truth))


def test_two_cell_corruption_is_not_explained(tables):
    printed, factors, alpha, published = tables[3]
    mutated = printed.copy()
    mutated.loc[2, "y"] = "6.18"    # run 3: 6.81 transposed
    mutated.loc[12, "y"] = "8.86"   # run 13: 8.26 substituted
    result = check_transcription(numeric(mutated), factors, "y", published, alpha=alpha, printed=mutated)
    assert not result.consistent and result.explained is False
    assert "No single-cell slip explains the disagreement" in result.message
    assert all(s.restores < len(published) for s in result.suspects)


def test_different_model_is_not_explained(tables):
    """Dropping a run is a bigger difference than any single cell."""
    printed, factors, alpha, published = tables[2]
    reduced = printed.drop(index=3).reset_index(drop=True)
    result = check_transcription(numeric(reduced), factors, "y", published, alpha=alpha, printed=reduced)
    assert result.explained is False and "dropped run" in result.message


@pytest.mark.parametrize("column, row, typo, kind", [("y", 3, "97.5", "transposition"),
                                                     ("y", 5, "8.03", "decimal_shift"),
                                                     ("x1", 9, "1.441", "transposition"),
                                                     ("x2", 12, "1.414", "sign_lost")])
def test_planted_typo_in_montgomery_example(column, row, typo, kind):
    table = montgomery()
    truth = table.loc[row, column]
    table.loc[row, column] = float(typo)
    result = check_transcription(table, ["x1", "x2"], "y", MONTGOMERY_PUBLISHED, alpha=1.414)
    best = result.suspects[0]
    assert result.explained and (best.run, best.column, best.suggested, best.kind) == (row + 1, column, truth, kind)


def test_declared_coding_and_coefficients(tables):
    """A slip found through published coefficients alone, with the coding of the declared bounds."""
    printed, factors, alpha, _ = tables[2]
    table = numeric(printed)
    coef = fit_response(table, factors, "y", alpha=alpha).coefficients().set_index("term")
    published = {"r2": "0.9941", "coefficients": {"units": "coded", "values": {
        t: f"{v:.3f}" for t, v in coef["coefficient_coded"].items()}}}
    declared = Coding.from_levels(factors, np.array([[0.0757, 3.5716], [0.9243, 9.2284]]), alpha)
    assert check_transcription(table, factors, "y", published, alpha=alpha, coding=declared).consistent
    mutated = printed.copy()
    mutated.loc[6, "x1"] = "0.757"  # run 7, axial point, decimal shift
    result = check_transcription(numeric(mutated), factors, "y", published, alpha=alpha, coding=declared,
                                 printed=mutated)
    best = result.suspects[0]
    assert (best.run, best.column, best.suggested, best.kind) == (7, "x1", 0.0757, "decimal_shift")


def box_behnken_table() -> pd.DataFrame:
    """3-factor Box-Behnken design, 3 centre runs; pressure P on a log scale (3.162, 10, 31.623)."""
    rng = np.random.default_rng(5)
    points = []
    for i, j in ((0, 1), (0, 2), (1, 2)):
        for a in (-1, 1):
            for b in (-1, 1):
                point = [0, 0, 0]
                point[i], point[j] = a, b
                points.append(point)
    c = np.array(points + [[0, 0, 0]] * 3, dtype=float)
    y = 10 + 2 * c[:, 0] - c[:, 1] + 0.5 * c[:, 2] + 1.2 * c[:, 0] ** 2 - 0.8 * c[:, 1] * c[:, 2]
    y = y + rng.normal(0, 0.3, len(c))
    return pd.DataFrame({"run": np.arange(1, 16), "T": 150 + 25 * c[:, 0],
                         "P": np.round(10 ** (1 + 0.5 * c[:, 1]), 3), "t": 30 + 10 * c[:, 2],
                         "y": np.round(y, 2)})


@pytest.mark.parametrize("log_factors", [(), ("P",)])
def test_box_behnken_with_log_factor(log_factors):
    table = box_behnken_table()
    factors = ["T", "P", "t"]
    fit = fit_response(table, factors, "y", log_factors=log_factors)
    s, a = fit.statistics(), fit.anova()
    published = {"r2": f"{s.r2:.4f}", "rmse": f"{s.rmse:.4f}", "ss_model": f"{a.ss_model:.2f}",
                 "ss_residual": f"{a.ss_residual:.3f}", "ss_pure_error": f"{a.ss_pure_error:.3f}"}
    options = {"design_type": "box_behnken", "log_factors": log_factors}
    clean = check_transcription(table, factors, "y", published, **options)
    assert clean.consistent and clean.reproduced["r2"] == pytest.approx(s.r2, rel=1e-12)
    for column, row, typo, kind in (("P", 1, 31.263, "transposition"), ("T", 2, 17.5, "decimal_shift")):
        mutated = table.copy()
        truth = mutated.loc[row, column]
        mutated.loc[row, column] = typo
        best = check_transcription(mutated, factors, "y", published, **options).suspects[0]
        assert (best.run, best.column, best.suggested, best.kind) == (row + 1, column, truth, kind)


# --------------------------------------------------------------------------- output and input
def test_json_and_frame(tables):
    printed, factors, alpha, published = tables[2]
    mutated = printed.copy()
    mutated.loc[3, "y"] = "6.15"
    result = check_transcription(numeric(mutated), factors, "y", published, alpha=alpha, printed=mutated)
    doc = json.loads(json.dumps(result.to_json(), allow_nan=False))
    assert {"consistent", "published", "reproduced", "suspects", "message"} <= set(doc)
    assert doc["consistent"] is False and doc["published"]["r2"] == 0.9941
    assert set(doc["suspects"][0]) == {"run", "column", "found", "suggested", "kind", "restores"}
    assert doc["suspects"][0] == {"run": 4, "column": "y", "found": 6.15, "suggested": 6.65,
                                  "kind": "digit_substitution", "restores": 9}
    frame = result.to_frame()
    assert list(frame.columns[:5]) == ["response", "statistic", "published", "reproduced", "agrees"]
    assert list(frame["statistic"]) == list(published) and frame["agrees"].dtype == bool
    assert_allclose(frame["published"], [float(v) for v in published.values()])


def test_check_table_runs_responses_with_a_published_block(tables):
    printed, factors, alpha, published = tables[2]
    table = numeric(printed).assign(w=lambda t: 2 * t["y"])
    cfg = {"y": {"target": 1.0, "published": {**published, "decimals": {"r2": 4}}}, "w": {"target": 2.0}}
    results = check_table(table, factors, cfg, alpha=alpha, design_type="ccd")
    assert [r.response for r in results] == ["y"] and results[0].consistent


def test_unusable_input_raises_input_error(tables):
    printed, factors, alpha, published = tables[2]
    table = numeric(printed)
    with pytest.raises(InputError, match="unknown statistic 'r_squared'"):
        check_transcription(table, factors, "y", {"r_squared": 0.9}, alpha=alpha)
    with pytest.raises(InputError, match="'z'"):
        check_transcription(table, factors, "z", published, alpha=alpha)
    with pytest.raises(InputError, match="not a term"):
        check_transcription(table, factors, "y", {"coefficients": {"units": "coded", "values": {"x3": 1}}})
    bad = printed.copy()
    bad.loc[4, "y"] = "2,68"
    with pytest.raises(InputError, match="run 5, column 'y'"):
        check_transcription(bad, factors, "y", published, alpha=alpha)


def _slipped(text: str, slip: str) -> str:
    """``text`` as a typist would have mistyped it (the slip that :func:`single_cell_slips` undoes)."""
    from decimal import Decimal

    if slip == "decimal_shift":
        return format(Decimal(text).scaleb(1), "f")
    if slip == "sign_lost":
        return "-" + text
    i = next(i for i in range(len(text) - 1, 0, -1) if text[i].isdigit() and text[i - 1].isdigit()
             and (slip == "digit_doubled" or text[i] != text[i - 1]))
    if slip == "digit_doubled":
        return text[:i] + text[i] + text[i:]
    return text[:i - 1] + text[i] + text[i - 1] + text[i + 1:]  # transposition


@pytest.mark.parametrize("k", [2, 3])
@pytest.mark.parametrize("statistic, slip", [("rmse", "decimal_shift"), ("r2", "transposition"),
                                             ("adj_r2", "digit_doubled"), ("rmse", "sign_lost")])
def test_a_slip_in_one_printed_statistic_is_located_in_the_statistic_not_the_table(tables, k, statistic, slip):
    """Every other statistic agrees and a one-keystroke slip of the disagreeing one's printed text rounds to
    the refit: the slip is in the printed statistic.  The table is not blamed and no cell is suspected."""
    printed, factors, alpha, published = tables[k]
    true_text = published[statistic]
    wrong = _slipped(true_text, slip)
    result = check_transcription(numeric(printed), factors, "y", {**published, statistic: wrong}, alpha=alpha,
                                 printed=printed)
    assert not result.consistent and result.suspects == [] and result.explained is False
    assert result.printed_slip == {"statistic": statistic, "printed": wrong, "looks_like": true_text, "kind": slip}
    assert f"the printed {statistic}, {wrong}, looks like {true_text}" in result.message
    assert json.loads(json.dumps(result.to_json()))["printed_slip"]["looks_like"] == true_text


def test_a_single_published_statistic_off_is_not_blamed_on_the_print_alone(tables):
    """With one published number there is nothing that agrees to vouch for the table: no printed slip is
    claimed, and the message allows both readings."""
    printed, factors, alpha, published = tables[2]
    result = check_transcription(numeric(printed), factors, "y", {"r2": "0.1234"}, alpha=alpha, printed=printed)
    assert result.printed_slip is None and not result.consistent
    assert "or the printed value is itself wrong" in result.message


def test_a_slip_that_a_coarse_statistic_cannot_locate_is_not_called_located(tables):
    """With R² alone, printed to two decimals, a repair in many cells restores it: the message says the
    published statistics do not locate the slip, instead of naming the first lead as the slip."""
    printed, factors, alpha, published = tables[2]
    mutated = printed.copy()
    row = 3
    whole, frac = printed.loc[row, "y"].split(".")
    mutated.loc[row, "y"] = f"{whole}{frac[0]}.{frac[1:]}"  # decimal point shifted one place: far off
    fit = fit_response(numeric(printed), factors, "y", alpha=alpha)
    coarse = {"r2": f"{fit.statistics().r2:.2f}"}
    result = check_transcription(numeric(mutated), factors, "y", coarse, alpha=alpha, printed=mutated)
    full = [s for s in result.suspects if s.restores == 1]
    assert not result.consistent and result.explained and len(full) > 1
    assert "do not locate the slip" in result.message and "a single-cell slip explains it" not in result.message
    # Every statistic printed: one repair restores them all, and that one is named as the slip.
    located = check_transcription(numeric(mutated), factors, "y", published, alpha=alpha, printed=mutated)
    assert "a single-cell slip explains it" in located.message
    assert (located.suspects[0].run, located.suspects[0].column) == (row + 1, "y")


def test_one_published_statistic_matched_by_one_repair_is_a_lead_not_the_slip(tables):
    """A single published number off by a little is restored by some digit repair somewhere by chance: on
    a clean table with R² misprinted in its last digits, a lone matching repair is offered as a lead to
    check, never as "the" slip; two statistics still locate a genuine slip."""
    printed, factors, alpha, published = tables[2]
    r2 = fit_response(numeric(printed), factors, "y", alpha=alpha).statistics().r2
    lone = []
    for shift in range(1, 40):
        wrong = {"r2": f"{r2 - shift * 0.0007:.4f}"}  # not the table's R²: no cell is wrong
        result = check_transcription(numeric(printed), factors, "y", wrong, alpha=alpha, printed=printed)
        if result.explained and sum(s.restores == 1 for s in result.suspects) == 1:
            lone.append(result)
    assert lone, "premise: some misprinted R² is restored by exactly one chance repair"
    for result in lone:
        assert "a single-cell slip explains it" not in result.message
        assert "chance match among the" in result.message and "check that cell against the source" in result.message


def test_a_repair_that_only_meets_a_printed_bound_is_not_a_lead(tables):
    """"lof_p < 0.0001" holds for any repair that wrecks the fit: a lead must restore a printed value (here
    the misprinted R²), not only the bound."""
    printed, factors, alpha, published = tables[2]
    table = numeric(printed)
    stats_ = fit_response(table, factors, "y", alpha=alpha).statistics()
    assert stats_.lof_p > 0.001  # premise: the bound is wrong for this table
    r2_text = f"{stats_.r2 - 0.03:.3f}"
    result = check_transcription(table, factors, "y", {"r2": r2_text, "lof_p": "<0.0001"}, alpha=alpha,
                                 printed=printed)
    assert not result.consistent and result.suspects
    for s in result.suspects:
        repaired = table.copy()
        repaired.loc[repaired["run"] == s.run, s.column] = s.suggested
        r2 = fit_response(repaired, factors, "y", alpha=alpha).statistics().r2
        assert abs(r2 - float(r2_text)) <= 0.0005 + 1e-12, (s, r2)


@pytest.mark.parametrize("labels", ["shuffled", "none"])
def test_a_suspect_is_named_by_the_tables_own_run_label(labels):
    """Run labels as the table prints them (not its row numbers); a table without a run column numbers its rows
    from one."""
    table = montgomery()
    row, truth = 3, table.loc[3, "y"]
    table.loc[row, "y"] = 97.5
    if labels == "shuffled":
        table["run"] = np.random.default_rng(4).permutation(np.arange(101, 101 + len(table)))
        expected = int(table.loc[row, "run"])
    else:
        table = table.drop(columns="run")
        expected = row + 1
    result = check_transcription(table, ["x1", "x2"], "y", MONTGOMERY_PUBLISHED, alpha=1.414)
    best = result.suspects[0]
    assert result.explained and (best.run, best.column, best.suggested) == (expected, "y", truth)
