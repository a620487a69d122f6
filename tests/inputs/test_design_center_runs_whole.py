"""A centre-run count the config writes as 3.0 (the schema's integer admits it) is the count 3: every design's
refusal of a table with another number of centre runs quotes it as the count the user declared, as it quotes
the count it found."""

from __future__ import annotations

from itertools import product

import numpy as np
import pandas as pd
import pytest

from demid.design import box_behnken_points, ccd_points
from demid.design_check import check_design
from demid.errors import InputError
from demid.schema import load_schema


def _table(coded: np.ndarray) -> pd.DataFrame:
    columns = {f"x{j + 1}": 10.0 * (j + 1) + 2.0 * coded[:, j] for j in range(coded.shape[1])}
    return pd.DataFrame({"run": np.arange(1, len(coded) + 1), **columns})


def _factorial(center_runs: int) -> np.ndarray:
    # the 3^2 factorial holds its centre point once; the others are extra centre runs
    return np.array(list(product((-1.0, 0.0, 1.0), repeat=2)) + [(0.0, 0.0)] * (center_runs - 1))


CASES = [  # (design type and alpha, coded runs with 2 centre runs)
    ({"type": "ccd", "alpha": 1.41421}, ccd_points(2, 1.41421, 2)),
    ({"type": "factorial"}, _factorial(2)),
    ({"type": "box_behnken"}, box_behnken_points(3, 2)),
]


def test_a_count_written_with_a_decimal_point_passes_the_config_schema():
    import jsonschema

    schema = load_schema()["definitions"]["material"]["properties"]["design"]["properties"]["center_runs"]
    assert jsonschema.Draft7Validator(schema).is_valid(3.0)


@pytest.mark.parametrize("design, coded", CASES, ids=[d["type"] for d, _ in CASES])
def test_a_wrong_centre_run_count_quotes_the_declared_count_as_a_whole_number(design, coded):
    table = _table(coded)
    n_found = int(np.sum(np.all(coded == 0.0, axis=1)))
    assert n_found == 2
    with pytest.raises(InputError) as info:
        check_design(table, list(table.columns[1:]), {**design, "center_runs": 3.0}, "t.csv", "materials.m")
    text = str(info.value)
    assert text.startswith("t.csv: config key materials.m.design.center_runs: expected 3 centre run"), text
    assert f"found {n_found}" in text and "3.0" not in text


@pytest.mark.parametrize("design, coded", CASES, ids=[d["type"] for d, _ in CASES])
def test_the_declared_count_written_3_0_accepts_a_table_with_three_centre_runs(design, coded):
    coded = np.vstack([coded, np.zeros((1, coded.shape[1]))])
    table = _table(coded)
    _, types = check_design(table, list(table.columns[1:]), {**design, "center_runs": 3.0}, "t.csv", "materials.m")
    assert int(np.sum(types == "center")) == 3
