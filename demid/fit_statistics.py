"""The statistics of a quadratic fit as the tables and the report print them: pure error of replicated runs,
the fit's summary statistics, the ANOVA with lack of fit against pure error, and the residual diagnostics.
Filled by :class:`demid.surrogate.SurrogateFit`; small dataclasses with ``to_frame()``.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
import pandas as pd

from .formulas import f_tail


def pure_error_ss(y, groups) -> float:
    """Sum of squares of the responses about their replicate-group means (pure error)."""
    y, groups = np.asarray(y, dtype=float), np.asarray(groups)
    if not np.all(np.isfinite(y)):
        return float("nan")  # as a sum over every group would give
    # each group's runs in table order, groups in sorted order: one sort, not a pass over the runs per group
    order = np.argsort(groups, kind="stable")
    bounds = np.flatnonzero(groups[order][1:] != groups[order][:-1]) + 1
    # a run without replicates adds exactly 0.0: left out, so a table of distinct runs costs one sort
    return float(sum(np.sum((seg - seg.mean()) ** 2) for seg in np.split(y[order], bounds) if len(seg) > 1))


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class FitStatistics:
    """Table 2 statistics.  rmse = sqrt(SSE/n); resid_std = sqrt(SSE/(n-p)); q2 = 1 - PRESS/SST."""

    response: str
    n_runs: int
    n_params: int
    r2: float
    adj_r2: float
    rmse: float
    resid_std: float
    press: float
    q2: float
    lof_f: float
    lof_p: float

    def to_frame(self) -> pd.DataFrame:
        return pd.DataFrame([asdict(self)])


@dataclass(frozen=True)
class LackOfFitAnova:
    """ANOVA with the residual split into lack of fit and pure error (replicated points).

    Verified against Montgomery, *Design and Analysis of Experiments*, Example 11.2.
    """

    response: str
    ss_model: float
    df_model: int
    ss_residual: float
    df_residual: int
    ss_lof: float
    df_lof: int
    ss_pure_error: float
    df_pure_error: int
    ss_total: float
    df_total: int
    ss_floor: float = 0.0  # sums of squares at or below this are round-off: an F-ratio over them is undefined
    ss_block: float = 0.0  # between blocks (blocks first, the model adjusted for them); 0 df without blocks
    df_block: int = 0

    def _f(self, ss_a, df_a, ss_b, df_b):
        if df_a <= 0 or df_b <= 0 or ss_b <= self.ss_floor * df_b:
            return np.nan, np.nan
        f = (ss_a / df_a) / (ss_b / df_b)
        return float(f), float(f_tail(f, df_a, df_b))

    @property
    def model_f(self):
        return self._f(self.ss_model, self.df_model, self.ss_residual, self.df_residual)

    @property
    def block_f(self):
        return self._f(self.ss_block, self.df_block, self.ss_residual, self.df_residual)

    @property
    def lof_f(self):
        return self._f(self.ss_lof, self.df_lof, self.ss_pure_error, self.df_pure_error)

    @property
    def lof_note(self) -> str:
        """Why lack of fit has no F-ratio, or '' when it has one."""
        if self.df_pure_error <= 0:
            return "undefined: no replicated runs, so no pure error to test lack of fit against"
        if self.df_lof <= 0:
            return "undefined: no degrees of freedom for lack of fit"
        if self.ss_pure_error <= self.ss_floor * self.df_pure_error:
            return ("undefined: pure error is zero (replicated runs give identical responses, as from a "
                    "deterministic simulator), so lack of fit cannot be tested against it")
        return ""

    def to_frame(self) -> pd.DataFrame:
        mf, mp = self.model_f
        lf, lp = self.lof_f
        rows = [("Blocks", self.ss_block, self.df_block, *self.block_f)] if self.df_block > 0 else []
        rows += [
            ("Model", self.ss_model, self.df_model, mf, mp),
            ("Residual", self.ss_residual, self.df_residual, np.nan, np.nan),
            ("Lack of fit", self.ss_lof, self.df_lof, lf, lp),
            ("Pure error", self.ss_pure_error, self.df_pure_error, np.nan, np.nan),
            ("Total (corrected)", self.ss_total, self.df_total, np.nan, np.nan),
        ]
        df = pd.DataFrame(rows, columns=["source", "sum_sq", "df", "F", "p_value"])
        # no mean square without degrees of freedom (pandas divides by 0 without a warning; the NaN replaces it)
        df["mean_sq"] = (df["sum_sq"] / df["df"]).where(df["df"] > 0)
        df.insert(0, "response", self.response)
        df["note"] = np.where(df["source"] == "Lack of fit", self.lof_note, "")
        return df[["response", "source", "df", "sum_sq", "mean_sq", "F", "p_value", "note"]]


@dataclass(frozen=True)
class Diagnostics:
    """Residual diagnostics, all computed with statsmodels / scipy."""

    response: str
    breusch_pagan_lm: float
    breusch_pagan_p: float
    reset_f: float
    reset_p: float
    shapiro_w: float
    shapiro_p: float
    max_vif: float
    max_cooks_d: float
    max_abs_student_resid: float

    def to_frame(self) -> pd.DataFrame:
        return pd.DataFrame([asdict(self)])
