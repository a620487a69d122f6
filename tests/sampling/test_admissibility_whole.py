"""Every column of the admissibility table of a material's scenarios against closed forms, over generated studies:
2-3 factors on ranges away from the origin, 1-3 observables each linear in its own factor (targets and slopes of
either sign, some bands cut by the box's faces), scenarios of different sizes and tolerances.  Each strict set is
the clipped box |x_k - c_k| <= ε|t_k| / |s_k|: its fraction, bounds and widths, the grid nodes inside it
(counted here), the ends of the range it reaches, and its best error (the smallest largest relative error over the grid's nodes)."""

from __future__ import annotations

import numpy as np
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.admissibility import evaluate_scenarios
from demid.sampling.domain import BOUND_TOUCH
from demid.spec import MaterialSpec

from ..uncertainty.test_sweep_plausible_whole import _box, _study

_COLUMNS = ["scenario", "observables", "tolerance", "feasible_fraction_pct", "factor", "lower", "upper", "width",
            "node_fraction_pct", "n_admissible_nodes", "best_max_rel_error", "fraction_error_pct", "at_bound"]


@given(seed=st.integers(0, 10_000), dim=st.sampled_from([2, 3]), n_obs=st.integers(1, 3),
       tolerance=st.sampled_from([0.01, 0.08]))
@settings(max_examples=8, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_each_scenarios_rows_are_its_clipped_box_and_the_grid_nodes_inside_it(seed, dim, n_obs, tolerance):
    # three factors: every factor carries an observable (a slab's exact set in three factors takes seconds)
    n_obs = min(n_obs, dim) if dim == 2 else 3
    domain, surrogates, targets, centres, slopes = _study(seed, dim, n_obs)
    names = list(targets)
    scenarios = {"all": {"observables": names, "tolerance": tolerance}}
    if n_obs > 1 and dim == 2:
        scenarios["last"] = {"observables": names[-1:], "tolerance": 2 * tolerance}
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {f: {"lower": float(lo), "upper": float(hi)}
                    for f, lo, hi in zip(domain.factors, domain.lower, domain.upper)},
        "responses": {o: {"target": float(t)} for o, t in targets.items()}, "scenarios": scenarios})
    n = 21
    table, sets = evaluate_scenarios(surrogates, spec, n)
    assert list(table.columns) == _COLUMNS and set(sets) == set(scenarios)
    assert list(table.index) == list(range(len(table)))
    lo, hi = np.array(domain.lower), np.array(domain.upper)
    axes = [np.linspace(a, b, n) for a, b in zip(lo, hi)]
    nodes = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, dim)
    at = 0
    for name, sc in scenarios.items():
        observables, tol = sc["observables"], sc["tolerance"]
        lower, upper, fraction = _box(domain, observables, targets, centres, slopes, lambda o: tol * abs(targets[o]))
        rows = table.iloc[at:at + dim]
        at += dim
        assert list(rows["scenario"]) == [name] * dim and list(rows["factor"]) == list(domain.factors)
        assert (rows["observables"] == "+".join(observables)).all() and (rows["tolerance"] == tol).all()
        np.testing.assert_allclose(rows["feasible_fraction_pct"], 100 * fraction, rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(rows[["lower", "upper"]].to_numpy(), np.column_stack([lower, upper]), rtol=1e-7,
                                   atol=1e-9)
        np.testing.assert_allclose(rows["width"], upper - lower, rtol=1e-7, atol=1e-9)
        errors = np.max([np.abs(surrogates[o].predict(nodes) - targets[o]) / abs(targets[o]) for o in observables],
                        axis=0)
        inside = errors <= tol
        assert (rows["n_admissible_nodes"] == int(inside.sum())).all()
        np.testing.assert_allclose(rows["node_fraction_pct"], 100 * inside.mean(), rtol=1e-12)
        touch = BOUND_TOUCH * (hi - lo)
        reach = [("none", "lower", "upper", "both")[int(a) + 2 * int(b)]
                 for a, b in zip(lower <= lo + touch, upper >= hi - touch)]
        assert list(rows["at_bound"]) == reach
        # the best error is the grid's: the smallest largest relative error over its nodes
        np.testing.assert_allclose(rows["best_max_rel_error"], errors.min(), rtol=1e-9, atol=1e-15)
        assert ((rows["fraction_error_pct"] >= 0) & (rows["fraction_error_pct"] < 1e-3)).all()
    assert at == len(table)
