"""A statistic the source computed from its own printed, rounded inputs agrees; real typos are still found."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from demid.transcription import check_transcription

# Montgomery, Design and Analysis of Experiments, Example 11.2 (Example 11-1 in the ANOVA table's edition):
# the book prints SS lack of fit 0.28, pure error 0.21, F = 1.78 and p = 0.2897 from its rounded sums.
MONTGOMERY = pd.DataFrame({
    "run": range(1, 14),
    "x1": [-1, -1, 1, 1, 0, 0, 0, 0, 0, 1.414, -1.414, 0, 0],
    "x2": [-1, 1, -1, 1, 0, 0, 0, 0, 0, 0, 0, 1.414, -1.414],
    "y": [76.5, 77.0, 78.0, 79.5, 79.9, 80.3, 80.0, 79.7, 79.8, 78.4, 75.6, 78.5, 77.0],
})
PRINTED = {"ss_lof": "0.28", "ss_pure_error": "0.21", "lof_f": "1.78", "lof_p": "0.2897", "ss_residual": "0.50"}


def test_montgomery_printed_lack_of_fit_agrees():
    result = check_transcription(MONTGOMERY, ["x1", "x2"], "y", PRINTED, alpha=1.414)
    assert result.consistent, result.message
    assert result.reproduced["lof_f"] == pytest.approx(1.7885, abs=5e-4)  # the exact refit is not 1.78
    assert "printed, rounded inputs" in result.message


def test_without_the_printed_inputs_the_exact_refit_decides():
    result = check_transcription(MONTGOMERY, ["x1", "x2"], "y", {"lof_f": "1.78", "lof_p": "0.2897"},
                                 alpha=1.414)
    assert not result.consistent


def test_a_statistic_inconsistent_with_its_printed_inputs_still_disagrees():
    printed = dict(PRINTED, lof_f="1.87")  # digits swapped in the printed F: no rounding of the SS gives it
    ss_lof, ss_pe = (0.275, 0.285), (0.205, 0.215)
    reachable = [(a / 3) / (b / 4) for a in ss_lof for b in ss_pe]  # [1.705, 1.854]
    assert not min(reachable) - 0.005 <= 1.87 <= max(reachable) + 0.005
    result = check_transcription(MONTGOMERY, ["x1", "x2"], "y", printed, alpha=1.414)
    assert not result.consistent and not result.agrees["lof_f"]


@pytest.mark.parametrize("run,typed", [(4, "97.5"), (11, "57.6"), (7, "8.00")])
def test_genuine_table_typos_are_still_found_and_located(tmp_path, run, typed):
    table = MONTGOMERY.copy()
    table["y"] = table["y"].astype(object)
    table.loc[table["run"] == run, "y"] = typed
    printed = table.astype(str)
    table["y"] = table["y"].astype(float)
    result = check_transcription(table, ["x1", "x2"], "y", PRINTED, alpha=1.414, printed=printed)
    assert not result.consistent
    assert result.explained, result.message
    assert (result.suspects[0].run, result.suspects[0].column) == (run, "y")
    assert result.suspects[0].suggested == pytest.approx(float(MONTGOMERY.loc[MONTGOMERY["run"] == run, "y"].iloc[0]))


@pytest.mark.parametrize("seed", [3, 4, 5])
def test_rounded_anova_of_other_tables_agrees(seed):
    """Any table: print SS to 2 significant decimals, F and p recomputed from those rounded sums."""
    rng = np.random.default_rng(seed)
    table = MONTGOMERY.copy()
    table["y"] = np.round(table["y"] + rng.normal(0, 0.4, len(table)), 1)
    exact = check_transcription(table, ["x1", "x2"], "y", {"ss_lof": "0", "ss_pure_error": "0"}, alpha=1.414)
    ss_lof, ss_pe = exact.reproduced["ss_lof"], exact.reproduced["ss_pure_error"]
    lof_r, pe_r = round(ss_lof, 2), round(ss_pe, 2)
    f = (lof_r / 3) / (pe_r / 4)
    printed = {"ss_lof": f"{lof_r:.2f}", "ss_pure_error": f"{pe_r:.2f}", "lof_f": f"{f:.2f}",
               "lof_p": f"{stats.f.sf(round(f, 2), 3, 4):.4f}"}
    result = check_transcription(table, ["x1", "x2"], "y", printed, alpha=1.414)
    assert result.consistent, result.message


def test_r2_from_printed_sums_of_squares_agrees():
    """R² printed from rounded SS model / SS total (28.25 / 28.74 = 0.9830) agrees; the exact refit gives 0.9827."""
    exact = check_transcription(MONTGOMERY, ["x1", "x2"], "y", {"r2": "0.9827"}, alpha=1.414)
    assert exact.consistent
    printed = {"ss_model": "28.25", "ss_total": "28.74", "r2": "0.9830"}
    result = check_transcription(MONTGOMERY, ["x1", "x2"], "y", printed, alpha=1.414)
    assert result.consistent, result.message
    assert not check_transcription(MONTGOMERY, ["x1", "x2"], "y", {"r2": "0.9830"}, alpha=1.414).consistent
    wrong = dict(printed, r2="0.9803")  # digits swapped: no rounding of the printed sums gives it
    assert not check_transcription(MONTGOMERY, ["x1", "x2"], "y", wrong, alpha=1.414).consistent


def test_table_cells_keep_six_significant_digits_and_the_printed_precision(tmp_path):
    """A statistic printed with 7 significant digits is judged at its printed decimals, but its table cell
    (like every number in the tables) carries at most 6; trailing zeros of short values are kept."""
    from demid.io import write_csv

    exact = check_transcription(MONTGOMERY, ["x1", "x2"], "y", {"ss_residual": "0.50"}, alpha=1.414)
    residual = exact.reproduced["ss_residual"]
    seven = f"{10000 * residual:.3f}"  # the same data in other units: 7 significant digits, 3 decimals
    scaled = MONTGOMERY.assign(y=MONTGOMERY["y"] * 100.0)
    result = check_transcription(scaled, ["x1", "x2"], "y", {"ss_residual": seven, "r2": "0.9830"},
                                 alpha=1.414)
    assert len(seven.replace(".", "").lstrip("0")) == 7
    frame = result.to_frame().set_index("statistic")
    assert frame.loc["ss_residual", "printed_decimals"] == 3
    assert frame.loc["ss_residual", "printed"] == f"{float(seven):.6g}"
    assert frame.loc["r2", "printed"] == "0.9830" and frame.loc["r2", "printed_decimals"] == 4
    write_csv(frame.reset_index(), tmp_path / "t.csv")
    for cell in pd.read_csv(tmp_path / "t.csv", dtype=str).to_numpy().ravel():
        digits = str(cell).lstrip("-<>").split("e")[0].replace(".", "").rstrip("%").lstrip("0")
        assert not digits.isdigit() or len(digits) <= 6, cell


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_adjusted_r2_residual_sd_and_rmse_from_printed_sums_of_squares_agree(seed):
    """adj. R², residual SD and RMSE a source computed from its own sums of squares printed to one decimal
    agree, even where the exact refit rounds otherwise; a digit slip in one of them still disagrees."""
    rng = np.random.default_rng(seed)
    table = MONTGOMERY.assign(y=np.round(MONTGOMERY["y"] * 10 + rng.normal(0, 4, len(MONTGOMERY)), 1))
    every = ("ss_residual", "ss_total", "ss_model", "adj_r2", "resid_std", "rmse")
    exact = check_transcription(table, ["x1", "x2"], "y", dict.fromkeys(every, "0"), alpha=1.414).reproduced
    n, p = len(table), 6
    res, tot = round(exact["ss_residual"], 1), round(exact["ss_total"], 1)  # printed to one decimal
    model = round(exact["ss_model"], 1)
    from_printed = {"adj_r2": 1 - (res / (n - p)) / (tot / (n - 1)), "resid_std": np.sqrt(res / (n - p)),
                    "rmse": np.sqrt(res / n)}
    printed = {"ss_residual": f"{res:.1f}", "ss_total": f"{tot:.1f}", "ss_model": f"{model:.1f}",
               **{k: f"{v:.6f}" for k, v in from_printed.items()}}
    # the premise: at six decimals the exact refit does not round to what the printed sums give
    assert any(round(exact[k], 6) != round(v, 6) for k, v in from_printed.items())
    result = check_transcription(table, ["x1", "x2"], "y", printed, alpha=1.414)
    assert result.consistent, result.message
    for name in from_printed:
        alone = check_transcription(table, ["x1", "x2"], "y", {name: printed[name]}, alpha=1.414)
        assert alone.consistent == (round(exact[name], 6) == round(from_printed[name], 6))
    slipped = dict(printed, resid_std=f"{from_printed['resid_std'] * 10:.6f}")  # decimal point shifted
    assert not check_transcription(table, ["x1", "x2"], "y", slipped, alpha=1.414).agrees["resid_std"]
