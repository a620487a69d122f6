"""Each scenario's strict set as the admissibility step stores it, read back by the later steps.

Next to Table 3's columns, ``scenarios/{material}.parquet`` carries the exact set's own state
(:data:`STATE_COLUMNS`: fraction and its error, spans and the point nearest the reference in
unit coordinates of the box).  The uncertainty and criticism steps rebuild each exact set from
the fits (its residual tensors, a few microseconds) and this state instead of evaluating the set
again: one set per scenario, one number, whichever table shows it.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .evaluate import EXACT_METHOD, exact_set_on_domain, uses_exact
from .grid import AdmissibleSet

STATE_COLUMNS = ["method", "exact_fraction", "exact_fraction_error", "unit_lower", "unit_upper",
                 "reference_distance", "nearest_unit"]


def set_state_frame(sets: dict[str, AdmissibleSet]) -> pd.DataFrame:
    """One row per scenario x factor (the order of the scenarios table): how each set was evaluated
    and, for exact sets, the state :func:`stored_strict_sets` restores (NaN otherwise)."""
    frames = []
    for aset in sets.values():
        d = len(aset.factors)
        state = {"method": aset.method, **{c: np.full(d, np.nan) for c in STATE_COLUMNS[1:]}}
        exact = aset.exact
        if exact is not None:
            unit_spans = exact._unit_spans
            state.update(exact_fraction=exact.fraction, exact_fraction_error=exact.fraction_error,
                         unit_lower=unit_spans[:, 0], unit_upper=unit_spans[:, 1])
            if exact.reference is not None:
                distance, nearest = exact._nearest
                state.update(reference_distance=distance, nearest_unit=nearest)
        frames.append(pd.DataFrame(state, index=range(d)))
    if not frames:
        return pd.DataFrame({c: pd.Series(dtype=object if c == "method" else float) for c in STATE_COLUMNS})
    return pd.concat(frames, ignore_index=True)[STATE_COLUMNS]


def stored_strict_sets(frame: pd.DataFrame, judged: dict, *,
                       reference: bool = False) -> dict[str, AdmissibleSet]:
    """The exact strict sets of the judged scenarios (name -> :class:`~demid.scenario.JudgedScenario`, in
    the spec's order) from the scenarios table (others are left out: their consumers evaluate them on
    their own grids).  With ``reference`` each set also knows its distance to the spec's reference point,
    as stored."""
    sets = {}
    for scen in judged.values():
        spec, surrogates = scen.spec, scen.surrogates
        domain, targets = spec.domain, spec.targets
        point = (spec.reference_point or None) if reference else None
        rows = frame[frame["scenario"] == scen.name] if "method" in frame.columns else frame.iloc[0:0]
        if (rows.empty or rows["method"].iloc[0] != EXACT_METHOD or list(rows["factor"]) != list(domain.factors)
                or float(rows["tolerance"].iloc[0]) != float(scen.tolerance)
                or not uses_exact(surrogates, scen.observables, domain)):
            continue
        exact = exact_set_on_domain(surrogates, domain, scen.observables, targets, scen.tolerance, point)
        # Seed the lazily computed state with the stored values: nothing is evaluated twice.
        exact.__dict__["_fraction"] = (float(rows["exact_fraction"].iloc[0]),
                                       float(rows["exact_fraction_error"].iloc[0]))
        exact.__dict__["_unit_spans"] = rows[["unit_lower", "unit_upper"]].to_numpy(dtype=float)
        if point is not None:
            exact.__dict__["_nearest"] = (float(rows["reference_distance"].iloc[0]),
                                          rows["nearest_unit"].to_numpy(dtype=float))
        spans = exact.spans
        lower, upper = spans["lower"].to_numpy(dtype=float), spans["upper"].to_numpy(dtype=float)
        sets[scen.name] = AdmissibleSet(
            observables=tuple(scen.observables), tolerance=float(scen.tolerance), factors=tuple(domain.factors),
            fraction=float(exact.fraction), node_fraction=np.nan, n_nodes=0, n_admissible_nodes=0,
            n_refined_cells=0, lower=lower, upper=upper,
            mask=np.zeros(0, dtype=bool), best_error=float(rows["best_max_rel_error"].iloc[0]),
            fraction_error=float(exact.fraction_error), method=EXACT_METHOD, exact=exact,
            at_bound=domain.at_bound(lower, upper))  # evaluate_set's test on the same spans: level 2 reads it
    return sets
