"""The wave history's plausible columns are float columns whatever numeric type the plausible frame holds: a
plausible table written by the pipeline's CSV writer prints whole-number shares without a point (100, 25), so read
back it holds integers; the history quotes them as the same shares, as floats, like its other share columns, and its
JSON text reads 100.0, never 100."""

from __future__ import annotations

import json

import pandas as pd
import pytest

from demid.config import validate_schema
from demid.io import write_csv
from demid.spec import MaterialSpec
from demid.waves import wave_history

_FLOAT_COLUMNS = ["feasible_fraction_of_omega_pct", "lower", "upper", "width", "box_share_of_omega_pct",
                  "plausible_fraction_of_omega_pct", "plausible_lower", "plausible_upper"]


def _spec() -> MaterialSpec:
    material = {"data": "m.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
                "factors": {"a": {"lower": -2.0, "upper": 6.0}, "b": {"lower": 1.0, "upper": 9.0}},
                "responses": {"y": {"target": 5.0}},
                "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}}
    return MaterialSpec.from_material("m", validate_schema({"materials": {"m": material}})["materials"]["m"])


@pytest.mark.parametrize("shares, ends", [((100, 100), (-2, 6)), ((25, 25), (0, 3)), ((0, 0), (1, 1))])
def test_whole_number_shares_read_back_from_the_plausible_csv_are_quoted_as_floats(tmp_path, shares, ends):
    spec = _spec()
    plausible = pd.DataFrame([{"scenario": "s", "factor": f, "robust_fraction_pct": float(p),
                               "robust_lower": float(ends[0]), "robust_upper": float(ends[1])}
                              for f, p in zip(("a", "b"), shares)])
    write_csv(plausible, tmp_path / "plausible.csv")
    text = (tmp_path / "plausible.csv").read_text(encoding="utf-8")
    assert f",{shares[0]},{ends[0]},{ends[1]}\n" in text  # premise: printed without a point
    read = pd.read_csv(tmp_path / "plausible.csv")
    assert read["robust_fraction_pct"].dtype.kind == "i"  # premise: read back as integers
    scenarios = pd.DataFrame([{"scenario": "s", "factor": f, "feasible_fraction_pct": 1.0, "lower": -1.0,
                               "upper": 2.0, "width": 3.0} for f in ("a", "b")])
    history = wave_history(spec, [{"scenarios": scenarios, "domain": None, "simulated": 10, "analysed": 9,
                                   "plausible": read}])
    for column in _FLOAT_COLUMNS:
        assert history[column].dtype.kind == "f", column
    assert list(history["plausible_fraction_of_omega_pct"]) == [float(p) for p in shares]
    assert list(history["plausible_lower"]) == [float(ends[0])] * 2
    assert list(history["plausible_upper"]) == [float(ends[1])] * 2
    records = json.loads(history.to_json(orient="records"))
    quoted = json.dumps([r["plausible_fraction_of_omega_pct"] for r in records])
    assert quoted == json.dumps([float(p) for p in shares])  # "[100.0, 100.0]", not "[100, 100]"
    assert all(type(v) is float for v in history["plausible_fraction_of_omega_pct"].tolist())
