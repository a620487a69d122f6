"""Admissible parameter sets of a material's scenarios (eq. 2-4 of the paper).

A point x of the search domain Omega is admissible for the observable set O at
tolerance eps when every relative residual r_k = (y_k(x) - y_k*) / |y_k*|,
k in O, lies in [-eps, eps].  The estimators live in :mod:`demid.sampling`;
this module evaluates every configured scenario of a material with them and
re-exports the names earlier callers import from here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

# Re-exported: the estimators' public names, as earlier callers import them from here.
from .sampling import (MAX_GRID_DIM, AdmissibleSet, CellCount, Domain, admissible_set,
                       cell_count, evaluate_set, plane_band_fraction, predict_grid, relative_residuals,
                       sobol_admissible_set)

if TYPE_CHECKING:
    from .scenario import JudgedScenario
    from .spec import MaterialSpec
    from .surrogate import Surrogate

__all__ = ["MAX_GRID_DIM", "AdmissibleSet", "CellCount", "Domain", "admissible_set", "cell_count", "evaluate_scenarios",
           "evaluate_set", "plane_band_fraction", "predict_grid", "relative_residuals", "sobol_admissible_set"]


def evaluate_scenarios(surrogates: dict[str, Surrogate], spec: MaterialSpec, n: int | None = None,
                       grid_predictions: pd.DataFrame | None = None,
                       judged: dict[str, JudgedScenario] | None = None) -> tuple[pd.DataFrame, dict[str, AdmissibleSet]]:
    """Every configured scenario of a material: long table (one row per scenario x factor) and the sets.

    ``spec`` is the material's :class:`~demid.spec.MaterialSpec`; ``n`` defaults to its evaluation size;
    ``judged``: the scenarios judged once by the caller (name -> :class:`~demid.scenario.JudgedScenario`).
    """
    from .scenario import judged_scenarios

    n = spec.grid_points if n is None else n
    # strict sets only: the plausible set's z does not enter
    judged = judged_scenarios(spec, surrogates, 0.0) if judged is None else judged
    frames, sets = [], {}
    for scen in spec.scenarios:
        # an observable with its own tolerance is judged by it (demid.scenario); a spec's reference point is
        # None or a filled dict (MaterialSpec.from_material reads an empty one as None)
        result = judged[scen.name].strict_set(n, grid_predictions, grid=True, reference=spec.reference_point)
        frame = result.to_frame()
        frame.insert(0, "scenario", scen.name)
        frames.append(frame)
        sets[scen.name] = result
    columns = ["scenario", "observables", "tolerance", "feasible_fraction_pct", "factor", "lower", "upper",
               "width", "node_fraction_pct", "n_admissible_nodes", "best_max_rel_error", "fraction_error_pct", "at_bound"]
    table = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=columns)
    return table[columns], sets
