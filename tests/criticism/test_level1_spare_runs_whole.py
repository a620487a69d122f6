"""Level 1's rounds stop when too few spare runs are left for a further round's tests: after a finding, another
round is made while the extended model keeps at least 4 residual degrees of freedom (each added-variable test of
the next round then has at least 3), and not at 3.  Two outliers planted in a 3x3 factorial with 2 or 1 centre
replicates (11 or 10 runs, the quadratic's 6 terms): after the first outlier the model keeps exactly 4 or 3."""
from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize


def _two_outliers(centre_runs: int) -> pd.DataFrame:
    levels = np.array([-1.0, 0.0, 1.0])
    a, b = (g.ravel() for g in np.meshgrid(levels, levels))
    a, b = np.append(a, np.zeros(centre_runs)), np.append(b, np.zeros(centre_runs))
    y = 10 + 2 * a - b + 0.5 * a * b + a * a + 0.05 * np.random.default_rng(0).standard_normal(len(a))
    y[1] += 1000.0  # the larger outlier, named first
    y[6] -= 15.0
    return pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a + 2, "b": b + 2, "y": y})


@pytest.mark.parametrize("centre_runs, named_runs", [(2, [2, 7]), (1, [2])])
def test_a_second_round_is_made_at_exactly_four_spare_degrees_of_freedom_not_three(centre_runs, named_runs):
    table = _two_outliers(centre_runs)
    result = criticize(table, ["a", "b"], "y", n_null=199)
    assert [f.cause for f in result.findings] == ["outlier"] * len(named_runs)
    assert [f.detail for f in result.findings] == named_runs
    # spare degrees of freedom: runs - 6 quadratic terms - one per outlier named
    assert result._extended_model.df_resid == len(table) - 6 - len(named_runs)


def _quadratic(a, b):
    return np.column_stack([np.ones_like(a), a, b, a * b, a * a, b * b])


def _fit(x, y):
    """(SSE, PRESS residuals with NaN where a run's leverage is 0.99 or more) of least squares."""
    h = np.einsum("ij,ji->i", x, np.linalg.pinv(x))
    resid = y - x @ np.linalg.lstsq(x, y, rcond=None)[0]
    return float(resid @ resid), np.where(h < 0.99, resid / (1 - h), np.nan)


def _aicc(sse, n_all, k):
    """AICc of a Gaussian fit of all n_all runs (a dropped run a mean shift of its own) with k parameters."""
    llf = -0.5 * n_all * (np.log(2 * np.pi * sse / n_all) + 1.0)
    return -2 * llf + 2 * k + 2 * k * (k + 1) / (n_all - k - 1)


@pytest.mark.parametrize("max_findings, named", [(0, 0), (1, 0), (2, 2)])
def test_findings_stop_at_max_findings_and_the_gain_and_summary_are_the_refits(max_findings, named):
    """Rounds stop at ``max_findings``: with one allowed, the second outlier is misfit no cause was named for, and
    the honest report names none (the whole misfit is unexplained); with two or more allowed, both outliers are
    named.  The gain, the extended model's summary and the summary's quoted change against refits written here."""
    table = _two_outliers(2)
    result = criticize(table, ["a", "b"], "y", n_null=199, max_findings=max_findings)
    assert [f.detail for f in result.findings] == [2, 7][:named]
    a, b, y = (table[c].to_numpy(float) for c in ("a", "b", "y"))
    x, n = _quadratic(a, b), len(y)
    kept = ~np.isin(table["run"].to_numpy(), [2, 7][:named])
    sse_base, press_base = _fit(x, y)
    sse_ext, press_ext = _fit(x[kept], y[kept])
    same = kept & np.isfinite(press_base)
    same[kept] &= np.isfinite(press_ext)
    loo_base = np.sqrt(np.mean(press_base[same] ** 2))
    loo_ext = np.sqrt(np.mean(press_ext[same[kept]] ** 2))
    gain = result.gain
    assert gain["compared_runs"] == int(same.sum()) == n - named
    assert gain["loo_rmse_baseline_same_runs"] == pytest.approx(loo_base, rel=1e-9)
    assert gain["loo_rmse_ratio"] == pytest.approx(loo_ext / loo_base, rel=1e-9)
    assert gain["delta_aicc"] == pytest.approx(_aicc(sse_ext, n, 7 + named) - _aicc(sse_base, n, 7) if named else 0.0,
                                               rel=1e-9, abs=1e-9)
    ext = result.extended
    assert (ext["n_runs"], ext["n_params"], ext["excluded_runs"]) == (n - named, 7 + named, [2, 7][:named])
    assert ext["rmse"] == pytest.approx(np.sqrt(sse_ext / (n - named)), rel=1e-9)
    assert ext["r2"] == pytest.approx(1 - sse_ext / np.sum((y[kept] - y[kept].mean()) ** 2), rel=1e-9)
    assert ext["aicc"] == pytest.approx(_aicc(sse_ext, n, 7 + named), rel=1e-9)
    if named:
        said = re.search(r"(\d) finding\(s\) at a family-wise 5 % level: (.*); together they change the "
                         r"leave-one-out error by ([+-]\d+) %\.$", result.summary)
        assert said.group(1) == str(named)
        assert said.group(2) == ", ".join(f"outlier ({r})" for r in [2, 7][:named])
        assert int(said.group(3)) == round(100 * (loo_ext / loo_base - 1))
    else:
        assert result.summary.startswith("y: the runs show misfit that no catalogued cause accounts for.")


@pytest.mark.parametrize("max_findings", [2])
def test_a_run_order_not_performed_adds_its_sentence_after_the_summary(max_findings):
    """The findings' sentence, one space, then why drift was not tested; the same
    findings as in performed order (two outliers are no run-order cause)."""
    table = _two_outliers(2)
    performed = criticize(table, ["a", "b"], "y", n_null=199, max_findings=max_findings)
    unknown = criticize(table, ["a", "b"], "y", n_null=199, max_findings=max_findings, run_order="unknown")
    message = unknown.run_order.message
    assert message.startswith("Drift was not tested: the run order is declared unknown")
    assert [f.detail for f in unknown.findings] == [f.detail for f in performed.findings]
    head = unknown.summary[:-len(message) - 1]
    assert unknown.summary == head + " " + message
    assert head.endswith(".") and not head.endswith(" ") and head.startswith("y: ")
    assert performed.summary == performed.summary.strip() and message not in performed.summary
