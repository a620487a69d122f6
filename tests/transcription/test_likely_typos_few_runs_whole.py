"""The typo screen (demid.transcription.likely_typos) at the fewest runs it judges: the full quadratic in two
factors (six coefficients) leaves one residual degree of freedom to the runs' externally studentised residuals at
eight runs, and a response cell whose decimal point slipped one place is flagged there, with the value the other
runs predict; at seven runs there is none, and nothing is judged."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.data import read_printed, validate_material
from demid.spec import MaterialSpec
from demid.transcription import likely_typos


def _spec(path):
    return MaterialSpec.from_material("m", {
        "data": str(path), "design": {"type": "custom"},
        "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1, "upper": 11}}, "responses": {"y": {}}})


@pytest.mark.parametrize("runs", [7, 8])
def test_one_residual_degree_of_freedom_is_enough_to_flag_a_slipped_point(tmp_path, runs):
    points = np.array([(a, b) for a in (0.1, 0.5, 0.9) for b in (1.0, 6.0, 11.0)])[:runs]
    y = 100 + 20 * points[:, 0] - 3 * points[:, 1] + 8 * points[:, 0] ** 2
    y = np.round(y + 0.01 * np.random.default_rng(0).normal(size=runs), 2)
    table = pd.DataFrame({"run": np.arange(1, runs + 1), "x1": points[:, 0], "x2": points[:, 1], "y": y})
    true_text = f"{y[4]:.2f}"
    table["y"] = table["y"].map(lambda v: f"{v:.2f}")
    table.loc[4, "y"] = f"{y[4] / 10:.3f}"  # run 5's point one place left
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    validated = validate_material(_spec(path))
    flags = likely_typos(validated, _spec(path), read_printed(path, validated.table))
    if runs == 7:  # as many runs as coefficients and one more: no degree of freedom for the scatter
        assert flags == []
        return
    assert [(f["run"], f["column"], f["kind"]) for f in flags] == [(5, "y", "decimal_shift")]
    flag = flags[0]
    assert flag["found"] == float(table.loc[4, "y"]) and flag["suggested"] == float(true_text)
    assert flag["student_resid"] < 0 and abs(flag["predicted_from_other_runs"] - y[4]) < 0.1
