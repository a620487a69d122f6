"""The lack-of-fit F read from the printed sums when the pure error is zero (demid.transcription.check).

With replicate centre runs a few thousandths apart the pure-error sum of squares prints as 0.0 (or 0.00), and the
printed F can then only come from a pure error inside (0, half width]: a printed F agrees through its printed sums
exactly when it lies between the F of the smallest lack-of-fit sum over the largest pure error and the F of the
largest over the same pure error (a smaller pure error only raises F); a printed F below that range comes from no
pure error the source can have had and is reported as disagreeing.  Without replicates there are no pure-error
degrees of freedom and no F at all: a printed F of zero agrees with nothing, though the printed sums do.  The sums
are computed here by least squares written out, on two- and three-factor central composite designs."""

from __future__ import annotations

from itertools import product

import numpy as np
import pandas as pd
import pytest

from demid.transcription.check import check_transcription


def _ccd(k: int, centre: int) -> np.ndarray:
    alpha = (2 ** k) ** 0.25
    axial = [sign * alpha * np.eye(k)[j] for j in range(k) for sign in (-1.0, 1.0)]
    return np.vstack([np.array(list(product((-1.0, 1.0), repeat=k))), axial, np.zeros((centre, k))])


def _quadratic(x: np.ndarray) -> np.ndarray:
    k = x.shape[1]
    cols = [np.ones(len(x)), *x.T, *[x[:, i] * x[:, j] for i in range(k) for j in range(i + 1, k)], *(x.T ** 2)]
    return np.column_stack(cols)


def _sums(x: np.ndarray, y: np.ndarray) -> tuple[float, float, int, int]:
    """Lack-of-fit and pure-error sums of squares and their degrees of freedom."""
    design = _quadratic(x)
    beta = np.linalg.lstsq(design, y, rcond=None)[0]
    ss_res = float(np.sum((y - design @ beta) ** 2))
    _, group = np.unique(np.round(x, 9), axis=0, return_inverse=True)
    group = group.ravel()
    ss_pe = float(sum(np.sum((y[group == g] - y[group == g].mean()) ** 2) for g in np.unique(group)))
    df_pe = len(y) - len(np.unique(group))
    df_lof = len(y) - design.shape[1] - df_pe
    return ss_res - ss_pe, ss_pe, df_lof, df_pe


@pytest.mark.parametrize("k, centre, decimals, seed", [(2, 5, 1, 0), (2, 4, 2, 1), (3, 6, 1, 2), (3, 5, 2, 3)])
def test_printed_f_agrees_only_from_a_pure_error_the_sums_allow(k, centre, decimals, seed):
    rng = np.random.default_rng(seed)
    x = _ccd(k, centre)
    # a cubic term the quadratic cannot fit (lack of fit of a few units), replicates 10^-3 apart
    y = 20.0 + x @ rng.uniform(1, 3, k) + 3.0 * x[:, 0] ** 3 + rng.normal(0, 0.02, len(x))
    centre_rows = np.all(x == 0, axis=1)
    y[centre_rows] = 20.0 + 0.002 * np.arange(centre_rows.sum())
    ss_lof, ss_pe, df_lof, df_pe = _sums(x, y)
    w = 0.5 * 10.0 ** -decimals
    assert ss_pe < w and ss_lof > 10 * w  # the pure error prints as zero, the lack of fit does not
    lof_text = f"{ss_lof:.{decimals}f}"
    a = float(lof_text)
    f_low, f_high = ((a - w) / df_lof) / (w / df_pe), ((a + w) / df_lof) / (w / df_pe)
    table = pd.DataFrame(x, columns=[f"x{j + 1}" for j in range(k)]).assign(y=y)
    factors = list(table.columns[:k])
    printed = table.astype(str)

    def agrees(f_value: float) -> bool:
        published = {"ss_lof": lof_text, "ss_pure_error": f"{0.0:.{decimals}f}", "lof_f": f"{f_value:.2f}"}
        result = check_transcription(table, factors, "y", published, alpha=(2 ** k) ** 0.25, printed=printed)
        assert result.agrees["ss_lof"] and result.agrees["ss_pure_error"]
        return result.agrees["lof_f"]

    assert agrees(0.5 * (f_low + f_high))
    assert not agrees(0.8 * f_low)  # no pure error in (0, w] gives an F this small
    assert not agrees(0.5 * f_low)
    assert not agrees(1.2 * f_high)


@pytest.mark.parametrize("k, decimals, seed", [(2, 1, 4), (3, 2, 5)])
def test_no_replicates_give_no_f_to_agree_with(k, decimals, seed):
    rng = np.random.default_rng(seed)
    x = _ccd(k, 1)
    y = 20.0 + x @ rng.uniform(1, 3, k) + 3.0 * x[:, 0] ** 3 + rng.normal(0, 0.02, len(x))
    ss_lof, ss_pe, df_lof, df_pe = _sums(x, y)
    assert df_pe == 0 and ss_pe == 0.0 and df_lof > 0
    table = pd.DataFrame(x, columns=[f"x{j + 1}" for j in range(k)]).assign(y=y)
    zero = f"{0.0:.{decimals}f}"
    published = {"ss_lof": f"{ss_lof:.{decimals}f}", "ss_pure_error": zero, "lof_f": zero}
    result = check_transcription(table, list(table.columns[:k]), "y", published, alpha=(2 ** k) ** 0.25,
                                 printed=table.astype(str))
    assert result.agrees["ss_lof"] and result.agrees["ss_pure_error"]
    assert not result.agrees["lof_f"] and not result.consistent
