"""The validator's typo flag: extreme studentised residual + a digit slip that would fit."""

import pytest

from demid.data import read_printed, validate_material
from demid.spec import MaterialSpec
from demid.transcription import likely_typos

from ..helpers import make_ccd_table


def _cfg(path):
    return MaterialSpec.from_material("m", {
        "data": str(path), "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1, "upper": 11}}, "responses": {"y": {}}})


@pytest.mark.parametrize("seed", range(5))
@pytest.mark.parametrize("slip", ["decimal", "decimal_up", "transposition"])
def test_planted_slip_is_flagged_and_clean_table_is_silent(tmp_path, seed, slip):
    table = make_ccd_table(lambda x: {"y": 100 + 20 * x[:, 0] - 3 * x[:, 1] + 8 * x[:, 0] ** 2},
                           [0.1, 1], [0.9, 11], noise=0.3, seed=seed, decimals=2)
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    vt = validate_material(_cfg(path))
    assert likely_typos(vt, _cfg(path), read_printed(path, vt.table)) == []

    true_value = table.loc[table["run"] == 5, "y"].iloc[0]
    text = f"{true_value:.2f}"
    if slip == "decimal":
        typo = f"{true_value / 10:.3f}"
    elif slip == "decimal_up":  # the point one place right: also a digit swap of other cells' shape
        typo = f"{true_value * 10:.1f}"
    else:  # swap the first two digits: 1xy.zz -> x1y.zz
        typo = text[1] + text[0] + text[2:]
        if typo == text:
            pytest.skip("identical digits")
    lines = path.read_text().splitlines()
    lines = [ln if not ln.startswith("5,") else ",".join(ln.split(",")[:-1] + [typo]) for ln in lines]
    path.write_text("\n".join(lines) + "\n")
    vt = validate_material(_cfg(path))
    flags = likely_typos(vt, _cfg(path), read_printed(path, vt.table))
    assert [(f["run"], f["column"]) for f in flags] == [(5, "y")]
    assert flags[0]["suggested"] == pytest.approx(true_value)
    assert flags[0]["kind"] == ("transposition" if slip == "transposition" else "decimal_shift")


@pytest.mark.parametrize("df", [1, 2, 3, 4, 5, 8, 13, 40, 121])
def test_two_sided_t_p_matches_scipy(df):
    import numpy as np
    from scipy import stats

    from demid.transcription.typos import two_sided_t_p

    t = np.concatenate([[0.0, np.nan, np.inf], np.geomspace(1e-3, 200.0, 60), -np.geomspace(0.5, 30.0, 7)])
    expected = 2 * stats.t.sf(np.abs(t), df)
    got = two_sided_t_p(t, df)
    assert np.isnan(got[1])
    finite = ~np.isnan(t)
    np.testing.assert_allclose(got[finite], expected[finite], rtol=0, atol=1e-13)
    small = finite & (expected > 1e-8) & (expected < 1e-2)  # the Bonferroni thresholds live here
    np.testing.assert_allclose(got[small], expected[small], rtol=1e-6)


@pytest.mark.parametrize("seed", range(3))
def test_studentised_residuals_match_statsmodels(tmp_path, seed):
    import numpy as np

    from demid.design import quadratic_terms
    from demid.surrogate import fit_response
    from demid.transcription.typos import studentised_residuals

    table = make_ccd_table(lambda x: {"y": 100 + 20 * x[:, 0] - 3 * x[:, 1] + 8 * x[:, 0] ** 2},
                           [0.1, 1], [0.9, 11], noise=0.3, seed=seed, decimals=2)
    table.loc[table["run"] == 4, "y"] += 9.0  # one outlying run
    fit = fit_response(table, ["x1", "x2"], "y")
    got = studentised_residuals(fit.coded, fit.y, quadratic_terms(2))
    reference = fit.results.get_influence()
    np.testing.assert_allclose(got["student_resid"], reference.resid_studentized_external, rtol=1e-9)
    np.testing.assert_allclose(got["leverage"], reference.hat_matrix_diag, rtol=1e-9)
    np.testing.assert_allclose(got["residual"], fit.results.resid, rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("seed", range(4))
def test_a_shifted_point_is_not_read_as_a_swap_with_a_leading_zero(tmp_path, seed):
    """500.3 typed for 50.03: the point moved one place.  Swapping its first two digits gives 050.3 = 50.3,
    which may land closer to the prediction, but no table prints 050.3; the shift is the repair named."""
    table = make_ccd_table(lambda x: {"y": 50.15 + 0.0 * x[:, 0]}, [0.1, 1], [0.9, 11], noise=0.15, seed=seed,
                           decimals=2)
    path = tmp_path / "t.csv"
    lines = table.to_csv(index=False).splitlines()
    lines = [ln if not ln.startswith("5,") else ",".join(ln.split(",")[:-1] + ["500.3"]) for ln in lines]
    path.write_text("\n".join(lines) + "\n")
    vt = validate_material(_cfg(path))
    flags = likely_typos(vt, _cfg(path), read_printed(path, vt.table))
    assert [(f["run"], f["kind"], f["suggested"]) for f in flags] == [(5, "decimal_shift", 50.03)]


@pytest.mark.parametrize("text", ["12.345", "7", "100", "0.5", "-3.25", "1.5e3", "2E+2", "1.5e-3", "\u22120.04",
                                  "nan", "abc", " 4.10 "])
def test_decimals_count_the_digits_after_the_point_of_the_positional_form(text):
    from decimal import Decimal, InvalidOperation

    from demid.transcription.typos import cell_decimals

    # independently: write the number out positionally and count what follows the point
    try:
        number = Decimal(text.strip().replace("\u2212", "-"))
        positional = format(number, "f") if number.is_finite() else ""
    except InvalidOperation:
        positional = ""
    expected = len(positional.split(".")[1]) if "." in positional else 0
    assert cell_decimals(text) == expected


@pytest.mark.parametrize("text", ["10.5", "359.17", "-20.04", "7", "1001.5", "0.25"])
def test_added_digit_repairs_remove_each_digit_once(text):
    from demid.transcription.typos import added_digit_repairs

    # brute force: every cell with one digit removed that still prints like a table number (no leading zero
    # before another digit) and reads as another value
    expected = set()
    for i, ch in enumerate(text):
        candidate = text[:i] + text[i + 1:]
        bare = candidate.lstrip("-")
        if not ch.isdigit() or not any(c.isdigit() for c in bare) or (len(bare) > 1 and bare[0] == "0"
                                                                       and bare[1].isdigit()):
            continue
        if float(candidate) != float(text):
            expected.add(("digit_added", candidate, float(candidate)))
    got = added_digit_repairs(text)
    assert set(got) == expected
    if text == "10.5":
        assert ("digit_added", "0.5", 0.5) in got  # 0.5 is printed with its leading zero


@pytest.mark.parametrize("found, suggested, predicted, explains", [
    (100.0, 10.3, 10.0, True),    # the repair leaves 0.3 of a 90 miss
    (10.0, 9.5, 9.0, False),      # it leaves half of the miss: a shuffle of a noisy value
    (10.0, 9.2, 9.0, True),       # exactly the 20 % share still counts
    (-50.0, 52.0, 50.0, True),    # a lost sign: 2 of a 100 miss
    (2.0, 1.0, -1.0, False)])     # 2 of a 3 miss
def test_a_repair_explains_the_miss_when_it_removes_four_fifths_of_it(found, suggested, predicted, explains):
    from demid.transcription.typos import repair_explains

    flag = {"found": found, "suggested": suggested, "predicted_from_other_runs": predicted}
    assert repair_explains(flag) is explains
    assert (abs(suggested - predicted) <= 0.2 * abs(found - predicted) + 1e-12) is explains


@pytest.mark.parametrize("seed", range(4))
def test_the_named_repair_is_the_fitting_one_closest_to_the_prediction_from_the_other_runs(tmp_path, seed):
    # a leading digit dropped (112.3 printed 12.3) with noise sd 4: several inserted digits (102.3, 112.3,
    # 12x.3) land within three prediction errors; the named one is the closest to the leave-one-out prediction,
    # refitted here with statsmodels in a basis of its own
    import numpy as np
    import statsmodels.api as sm

    table = make_ccd_table(lambda x: {"y": 112 + 6 * x[:, 0] - 0.4 * x[:, 1] + 2 * x[:, 0] ** 2},
                           [0.1, 1], [0.9, 11], noise=4.0, seed=seed, decimals=1)
    texts = [f"{v:.1f}" for v in table["y"]]
    i = next(j for j, t in enumerate(texts) if len(t) == 5 and t[0] == "1" and t[1] != "0")
    run = int(table["run"].iloc[i])
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    lines = path.read_text().splitlines()
    lines = [ln if not ln.startswith(f"{run},") else ",".join(ln.split(",")[:-1] + [texts[i][1:]]) for ln in lines]
    path.write_text("\n".join(lines) + "\n")
    vt = validate_material(_cfg(path))
    flags = likely_typos(vt, _cfg(path), read_printed(path, vt.table), kinds=("digit_dropped",))
    assert [f["run"] for f in flags] == [run]
    x = table[["x1", "x2"]].to_numpy(dtype=float)
    basis = np.column_stack([np.ones(len(x)), x[:, 0], x[:, 1], x[:, 0] ** 2, x[:, 0] * x[:, 1], x[:, 1] ** 2])
    others = np.arange(len(x)) != i
    fit = sm.OLS(table["y"].to_numpy(dtype=float)[others], basis[others]).fit()
    prediction = fit.get_prediction(basis[i:i + 1])
    loo, se = float(prediction.predicted_mean[0]), float(prediction.se_obs[0])
    assert flags[0]["predicted_from_other_runs"] == pytest.approx(loo, rel=1e-9)
    assert flags[0]["prediction_se"] == pytest.approx(se, rel=1e-9)
    # every digit inserted anywhere in the printed cell, one decimal at most, no leading zero
    printed = texts[i][1:]
    candidates = {float(printed[:k] + d + printed[k:]) for k in range(len(printed) + 1) for d in "0123456789"
                  if not (printed[:k] + d + printed[k:]).startswith("0")
                  and len((printed[:k] + d + printed[k:]).split(".")[1]) <= 1}
    fitting = sorted((abs(v - loo), v) for v in candidates if abs(v - loo) <= 3 * se)
    assert fitting  # several for some seeds: there the closest is not the smallest, nor the first found
    assert flags[0]["suggested"] == pytest.approx(fitting[0][1])
