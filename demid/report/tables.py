"""The cross-material tables: per-material parquet stacked into the CSVs under tables/."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

from ..io import read_parquet

if TYPE_CHECKING:
    from pathlib import Path


SURROGATE_FIT_COLUMNS = ["material", "response", "n_runs", "r2", "adj_r2", "rmse", "resid_std", "q2", "lof_f", "lof_p"]


IDENTIFIABILITY_COLUMNS = ["material", "scenario", "observables", "tolerance", "feasible_fraction_pct", "factor",
                           "lower", "upper", "width", "at_bound"]


TRANSCRIPTION_COLUMNS = ["material", "response", "statistic", "published", "reproduced", "agrees", "printed",
                         "printed_decimals"]


def summary_tables(inputs: dict[str, dict[str, str | Path]]) -> dict[str, pd.DataFrame]:
    """Every cross-material CSV from the per-material parquet files (keyed by the rule's input names)."""
    out = {
        "surrogate_fit": surrogate_fit_table(inputs["statistics"]),
        "identifiability": identifiability_table(list(inputs["scenarios"].values())),
        "transcription": stack_material_tables(inputs["transcription"]).reindex(columns=TRANSCRIPTION_COLUMNS),
    }
    for name in ("plausible", "sweep", "information_gain", "ranking", "findings", "calibration", "combinations"):
        if name in inputs:
            out[name] = stack_material_tables(inputs[name])
    if "combinations" in out:  # materials with other factors stack their loadings in between: widths last
        widths = ["width_coded", "width_fraction_of_range"]
        out["combinations"] = out["combinations"][[c for c in out["combinations"].columns if c not in widths] + widths]
    return out


def surrogate_fit_table(statistics: dict[str, str | Path]) -> pd.DataFrame:
    """Table 2: one row per material x response, from the per-material statistics parquet files."""
    return stack_material_tables(statistics)[SURROGATE_FIT_COLUMNS]


def identifiability_table(scenario_files) -> pd.DataFrame:
    """Table 3 in long form: one row per material x scenario x factor (+ diagnostic columns)."""
    frames = [read_parquet(p) for p in scenario_files]
    frames = [f for f in frames if len(f)]
    if not frames:
        return pd.DataFrame(columns=IDENTIFIABILITY_COLUMNS)
    # Exactly the Table 3 contract; diagnostics (node fraction, closest approach) stay in scenarios/*.parquet.
    return pd.concat(frames, ignore_index=True)[IDENTIFIABILITY_COLUMNS]


def pareto_intervals(path: str | Path) -> pd.DataFrame:
    """The interval summary rows of a tables/pareto_{material}.csv file."""
    frame = pd.read_csv(path)
    rows = frame[frame["kind"] == "interval"]
    return rows[["factor", "lower", "upper", "n_points"]].reset_index(drop=True)


def stack_material_tables(files: dict[str, str | Path]) -> pd.DataFrame:
    """Concatenate per-material parquet tables with a leading ``material`` column (columns kept when empty)."""
    frames = []
    for material, path in files.items():
        frame = read_parquet(path)
        frame.insert(0, "material", material)
        frames.append(frame)
    filled = [f for f in frames if len(f)]
    if filled:
        return pd.concat(filled, ignore_index=True)
    widest = max(frames, key=lambda f: f.shape[1]) if frames else pd.DataFrame(columns=["material"])
    return widest.iloc[0:0]
