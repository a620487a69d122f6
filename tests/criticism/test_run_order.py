"""Run order: drift is tested only where the run column can be the order the runs were made in."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from demid.cli import main
from demid.config import load_config
from demid.criticism import criticize
from demid.criticism.run_order import (SORTED_CORRELATION, STANDARD_ORDER_CORRELATION, assess_run_order,
                                       standard_order_correlation)
from demid.design import ccd_points
from demid.errors import InputError
from demid.spec import MaterialSpec

from ..generators import FACTORS, ccd_table, design

N_NULL = 499  # the family test's Monte Carlo draws: enough for these clear-cut cases, and fast


def _box_behnken_standard(k: int = 3, centre: int = 3) -> np.ndarray:
    """Box-Behnken points in the textbook standard order: each pair of factors (AB, AC, BC) in Yates
    order with the others at 0, then the centre runs (written out here, independently of the code)."""
    rows = []
    for i in range(k):
        for j in range(i + 1, k):
            for b in (-1.0, 1.0):
                for a in (-1.0, 1.0):
                    p = np.zeros(k)
                    p[i], p[j] = a, b
                    rows.append(p)
    return np.vstack(rows + [np.zeros(k)] * centre)


def _three_level_factorial(k: int = 2) -> np.ndarray:
    """3^k full factorial, first factor varying fastest."""
    grid = np.array(np.meshgrid(*[[-1.0, 0.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
    return grid[:, ::-1]


@pytest.mark.parametrize("points", [ccd_points(2, None, 5), ccd_points(3, None, 6), ccd_points(2, None, 13),
                                    ccd_points(4, None, 2), _box_behnken_standard(), _three_level_factorial()],
                         ids=["ccd2", "ccd3", "ccd2-13-centres", "ccd4", "bbd3", "3x3"])
def test_standard_orders_are_recognised_forwards_and_backwards(points):
    n = len(points)
    assert standard_order_correlation(np.arange(1, n + 1), points) == pytest.approx(1.0)
    assert standard_order_correlation(np.arange(n, 0, -1), points) == pytest.approx(1.0)
    # the same order under other run numbers (gaps, offset) is still the standard order
    assert standard_order_correlation(100 + 3 * np.arange(n), points) == pytest.approx(1.0)


def test_standard_order_with_swapped_factor_columns_and_high_level_first():
    points = ccd_points(3, None, 6)
    swapped = -points[:, [2, 0, 1]]  # another naming of the factors, high level listed first
    assert standard_order_correlation(np.arange(1, len(points) + 1), swapped) == pytest.approx(1.0)


def test_random_orders_are_not_taken_for_a_standard_order():
    points = ccd_points(3, None, 6)
    rng = np.random.default_rng(11)
    values = [standard_order_correlation(rng.permutation(len(points)) + 1, points) for _ in range(50)]
    assert max(values) < STANDARD_ORDER_CORRELATION


def test_assessment_reasons():
    points = ccd_points(2, None, 5)
    rng = np.random.default_rng(3)
    y = rng.normal(size=len(points))
    runs = rng.permutation(len(points)) + 1
    assert assess_run_order(runs, points, {"y": y}).drift_tested
    unknown = assess_run_order(runs, points, {"y": y}, "unknown")
    assert not unknown.drift_tested and unknown.reason == "declared_unknown" and "run_order" in unknown.message
    by_response = assess_run_order(np.argsort(np.argsort(-y)) + 1, points, {"other": runs, "y": y})
    assert (by_response.reason, by_response.response) == ("sorted_by_response", "y")
    assert by_response.correlation == pytest.approx(-1.0)
    assert "sorted by y" in by_response.message and "performed" in by_response.message
    standard = assess_run_order(np.arange(1, len(points) + 1), points, {"y": y})
    assert standard.reason == "standard_order" and "standard order" in standard.message
    # a response correlated with the run order just below the threshold keeps drift tested
    weak = runs + rng.normal(scale=4.0, size=len(runs))
    rho = pd.Series(runs).corr(pd.Series(weak), method="spearman")
    assert abs(rho) < SORTED_CORRELATION
    assert assess_run_order(runs, points, {"y": weak}).drift_tested
    with pytest.raises(ValueError):
        assess_run_order(runs, points, {"y": y}, "random")


def _renumbered(table: pd.DataFrame, seed: int, k: int, order: str) -> pd.DataFrame:
    out = table.copy()
    if order == "sorted":
        out["run"] = out["y"].rank(method="first").astype(int)
    else:  # the generator draws each standard-order point's randomised run first
        n = len(design(k)[2])
        randomised = np.random.default_rng(seed).permutation(n) + 1
        out["run"] = out["run"].map({int(r): i + 1 for i, r in enumerate(randomised)})
    return out.sort_values("run").reset_index(drop=True)


@pytest.mark.parametrize("order", ["sorted", "standard"])
def test_tables_printed_in_another_order_get_no_drift_finding(order):
    # Planted: a strong drift in the order the runs were made -- then the table is printed sorted
    # by the response or in standard order, which hides that order.  No drift may be claimed.
    for seed in range(3):
        table, _ = ccd_table(seed, 2, "drift", 12.0)
        result = criticize(_renumbered(table, seed, 2, order), FACTORS[2], "y", n_null=N_NULL)
        assert "drift" not in [f.cause for f in result.findings]
        assert "drift" not in [c["cause"] for c in result.catalogue]
        payload = result.to_json()["run_order"]
        assert payload["drift_tested"] is False
        assert payload["reason"] == ("sorted_by_response" if order == "sorted" else "standard_order")
        assert "Drift was not tested" in result.summary


def test_drift_on_a_randomised_order_is_still_found():
    for seed in range(3):
        table, _ = ccd_table(seed, 2, "drift", 12.0)
        result = criticize(table, FACTORS[2], "y", n_null=N_NULL)
        assert result.run_order.drift_tested
        assert result.findings and result.findings[0].cause == "drift"
        # declared unknown, the same table is not tested for drift
        unknown = criticize(table, FACTORS[2], "y", n_null=N_NULL, run_order="unknown")
        assert "drift" not in [f.cause for f in unknown.findings]


def test_cli_run_order_option(tmp_path):
    table, _ = ccd_table(1, 2, "drift", 12.0)
    table.to_csv(tmp_path / "t.csv", index=False)
    common = ["criticize", "--data", str(tmp_path / "t.csv"), "--factors", "mu_r,gamma", "--response", "y"]
    assert main(common + ["--out", str(tmp_path / "a.json")]) == 0
    tested = json.loads((tmp_path / "a.json").read_text())
    assert tested["run_order"]["declared"] == "performed" and tested["run_order"]["drift_tested"] is True
    assert main(common + ["--run-order", "unknown", "--out", str(tmp_path / "b.json")]) == 0
    untested = json.loads((tmp_path / "b.json").read_text())
    assert untested["run_order"]["drift_tested"] is False
    assert "drift" not in [f["cause"] for f in untested["findings"]]
    with pytest.raises(SystemExit):
        main(common + ["--run-order", "random", "--out", str(tmp_path / "c.json")])


def _config(tmp_path, extra: str = "") -> str:
    (tmp_path / "t.csv").write_text("run,a,b,y\n1,0,0,1\n", encoding="utf-8")
    path = tmp_path / "c.yaml"
    path.write_text("materials:\n  m:\n    data: t.csv\n    design: {type: ccd, alpha: 1.41421, center_runs: 5}\n"
                    "    factors: {a: {lower: 0, upper: 1}, b: {lower: 0, upper: 1}}\n"
                    "    responses: {y: {target: 1}}\n"
                    "    scenarios: {y: {observables: [y], tolerance: 0.05}}\n" + extra, encoding="utf-8")
    return str(path)


def test_config_key_default_and_validation(tmp_path):
    config = load_config(_config(tmp_path), base_dir=tmp_path)
    assert config["materials"]["m"]["run_order"] == "performed"  # the schema's default
    assert MaterialSpec.from_config("m", config).run_order == "performed"
    bare = {"design": {"type": "ccd"}, "factors": {"a": {"lower": 0, "upper": 1}}, "responses": {"y": {}}}
    assert MaterialSpec.from_material("m", bare).run_order == "performed"  # a bare entry gets the schema's default
    unknown = load_config(_config(tmp_path, "    run_order: unknown\n"), base_dir=tmp_path)
    assert MaterialSpec.from_config("m", unknown).run_order == "unknown"
    with pytest.raises(InputError, match="run_order"):
        load_config(_config(tmp_path, "    run_order: random\n"), base_dir=tmp_path)


def test_validate_notes_a_run_column_sorted_by_a_response(tmp_path, capsys):
    import yaml

    repo = Path(__file__).resolve().parents[2]
    config = yaml.safe_load((repo / "config.yaml").read_text(encoding="utf-8"))
    mortar = config["materials"]["mortar"]
    table = pd.read_csv(repo / mortar["data"])
    table.to_csv(tmp_path / "randomised.csv", index=False)
    table.assign(run=table["d10"].rank(method="first").astype(int)).sort_values("run").to_csv(
        tmp_path / "sorted.csv", index=False)
    for data, declared, note in (("randomised.csv", "performed", False), ("sorted.csv", "performed", True),
                                 ("sorted.csv", "unknown", False)):
        path = tmp_path / f"{data}.{declared}.yaml"
        path.write_text(yaml.safe_dump({"materials": {"mortar": {**mortar, "data": data, "run_order": declared}}}),
                        encoding="utf-8")
        assert main(["validate", "--config", str(path)]) == 0
        err = capsys.readouterr().err
        assert ("drift will not be tested: the run order looks sorted by d10" in err) == note, (data, declared, err)
