"""The gain of extending a model: a material that ``extends`` another (its model plus factors) against it.

Read, not recomputed: the best point's largest relative error is level 2's ``best_max_error``
(``criticism/{m}.json``), the admissible fraction of Ω is identifiability's ``feasible_fraction_pct``
(``tables/identifiability.csv``) and the surrogate it is read off is judged by the lowest leave-one-out Q² of the
scenario's observables (``tables/surrogate_fit.csv``), one row per scenario the two materials share.  A share
read off a surrogate below :data:`~demid.waves.STOP_Q2` (the level the waves need before they stop on a set)
is told with that Q² beside it: the gain is then what the surrogates say, not yet the answer.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..precision import q2_text

MODEL_EXTENSION_COLUMNS = ["material", "extends", "added_factors", "best_error_before", "best_error_after",
                           "feasible_fraction_before_pct", "feasible_fraction_after_pct", "scenario",
                           "surrogate_q2_before", "surrogate_q2_after"]


def _fractions(identifiability: pd.DataFrame, material: str) -> dict[str, float]:
    rows = identifiability[identifiability["material"] == material]
    return {str(s): float(g["feasible_fraction_pct"].iloc[0]) for s, g in rows.groupby("scenario", sort=False)}


def _lowest_q2(surrogate_fit: pd.DataFrame | None, material: str, observables) -> float:
    """The lowest leave-one-out Q² of the material's surrogates of ``observables`` (NaN when none is there or
    one is undefined: a set is only as predictive as its weakest surrogate)."""
    if surrogate_fit is None:
        return np.nan
    rows = surrogate_fit[(surrogate_fit["material"] == material) & surrogate_fit["response"].isin(list(observables))]
    q2 = rows["q2"].to_numpy(dtype=float)
    # every observable needs its row (a scenario has at least one, so no rows at all is NaN too)
    return float(q2.min()) if len(set(rows["response"])) == len(set(observables)) else np.nan


def _best_error(criticism: dict) -> float:
    level2 = (criticism or {}).get("level2") or {}
    value = level2.get("best_max_error")
    return float(value) if value is not None else np.nan


def model_extensions(specs: dict, extends: dict[str, str], criticism: dict[str, dict],
                     identifiability: pd.DataFrame, surrogate_fit: pd.DataFrame | None = None) -> pd.DataFrame:
    """One row per (material with ``extends``, scenario both materials have), in config order.

    ``specs``: name -> MaterialSpec; ``extends``: name -> the material it extends (empty: none);
    ``criticism``: name -> its criticism JSON; ``identifiability``: tables/identifiability.csv;
    ``surrogate_fit``: tables/surrogate_fit.csv (None: the Q² columns are NaN).
    """
    rows = []
    for name, spec in specs.items():
        base = extends.get(name) or ""
        if not base or base not in specs:
            continue
        added = [f for f in spec.factor_names if f not in specs[base].factor_names]
        before, after = _fractions(identifiability, base), _fractions(identifiability, name)
        for scenario in [s for s in after if s in before]:
            observables = {m: next(sc.observables for sc in specs[m].scenarios if sc.name == scenario)
                           for m in (base, name)}
            rows.append({"material": name, "extends": base, "added_factors": "+".join(added),
                         "best_error_before": _best_error(criticism.get(base)),
                         "best_error_after": _best_error(criticism.get(name)),
                         "feasible_fraction_before_pct": before[scenario],
                         "feasible_fraction_after_pct": after[scenario], "scenario": scenario,
                         "surrogate_q2_before": _lowest_q2(surrogate_fit, base, observables[base]),
                         "surrogate_q2_after": _lowest_q2(surrogate_fit, name, observables[name])})
    return pd.DataFrame(rows, columns=MODEL_EXTENSION_COLUMNS)


def extension_sentence(row: dict, labels: dict[str, str], factor_labels: dict[str, str],
                       scenario_label: str) -> str:
    """"Adding μ_r to the model of no_rolling: the best point's error falls from 23.7 % to 0 %; ..." """
    from ..precision import percent_text
    from ..waves import STOP_Q2

    added = [factor_labels.get(f, f) for f in str(row["added_factors"] or "").split("+") if f]
    what = f"Adding {', '.join(added)} to" if added else "Extending"
    before, after = abs(row["best_error_before"]), abs(row["best_error_after"])
    verb = "falls" if after < before else "does not fall" if after == before else "rises"

    def weak(q2) -> bool:
        # a Q² is a number (NaN when unknown), or "" or None in the report's rows (read with NaN filled by "")
        return isinstance(q2, (int, float)) and q2 < STOP_Q2

    def share(pct, q2):
        text = "empty" if pct <= 0 else f"{pct:.3g} % of Ω"
        return text + (f" (surrogate Q² = {q2_text(q2)} < {STOP_Q2:g})" if weak(q2) else "")

    grow = ("grows" if row["feasible_fraction_after_pct"] > row["feasible_fraction_before_pct"] else
            "does not grow")
    return (f"{what} the model of {labels.get(row['extends'], row['extends'])} "
            f"({labels.get(row['material'], row['material'])}): the best point's largest error {verb} from "
            f"{percent_text(before)} to {percent_text(after)}; the admissible set of *{scenario_label}* {grow} from "
            f"{share(row['feasible_fraction_before_pct'], row.get('surrogate_q2_before'))} to "
            f"{share(row['feasible_fraction_after_pct'], row.get('surrogate_q2_after'))}."
            + (f" A set read off a surrogate whose leave-one-out Q² is below {STOP_Q2:g} is what that surrogate "
               "says, not yet the answer: it does not predict the runs left out of its fit well enough (more runs, "
               "or replicates where the runs' scatter dominates, come first)."
               if weak(row.get("surrogate_q2_before")) or weak(row.get("surrogate_q2_after")) else ""))
