"""A material whose every target is out of reach still gets its uncertainty tables and figures."""

from __future__ import annotations

import numpy as np

from demid.io import save_figure
from demid.surrogate import fit_response
from demid.uncertainty import analyse_material

from .helpers import make_ccd_table


def _material(y2_target):
    table = make_ccd_table(lambda x: {"y1": 100 + 20 * x[:, 0] - 2 * x[:, 1] + 10 * x[:, 0] ** 2,
                                      "y2": 80 + 5 * x[:, 0] + 3 * x[:, 1] - 0.1 * x[:, 1] ** 2},
                           [0.1, 1.0], [0.9, 11.0], noise=0.3, seed=8, decimals=3)
    cfg = {"data": "t.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
           "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1.0, "upper": 11.0}},
           "responses": {"y1": {"target": 10 * table["y1"].max()}, "y2": {"target": y2_target}},
           "scenarios": {"y1_only": {"observables": ["y1"], "tolerance": 0.02},
                         "both": {"observables": ["y1", "y2"], "tolerance": 0.02}}}
    surrogates = {r: fit_response(table, ["x1", "x2"], r, alpha=1.41421).surrogate() for r in ("y1", "y2")}
    return surrogates, cfg


def test_every_target_out_of_reach_still_draws_sweep_and_posterior(tmp_path):
    surrogates, cfg = _material(y2_target=95.0)
    result = analyse_material(surrogates, cfg, z=2.0, tolerances=[0.01, 0.05, 0.2])
    sweep = result.sweep
    sets_with_y1 = sweep[sweep["observables"].str.contains("y1")]
    assert (sets_with_y1["feasible_fraction_pct"] == 0).all()
    save_figure(result.sweep_figure("unreachable"), tmp_path / "sweep.png")
    save_figure(result.posterior_figure("unreachable"), tmp_path / "posterior.png")
    assert (tmp_path / "sweep.png").stat().st_size > 0 and (tmp_path / "posterior.png").stat().st_size > 0
    assert np.isfinite(result.ranking.select_dtypes("number").to_numpy(dtype=float)).any()
