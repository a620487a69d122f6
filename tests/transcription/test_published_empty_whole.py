"""A transcription check given no published statistic at all (an empty mapping, or not a mapping) is refused in
one line, before any refit: there is nothing to compare the table with (decimals alone are no statistic)."""

from __future__ import annotations

from itertools import product

import numpy as np
import pandas as pd
import pytest

from demid.errors import InputError
from demid.transcription.check import check_transcription


def _table() -> pd.DataFrame:
    points = np.array(list(product((-1.0, 0.0, 1.0), repeat=2)) + [(0.0, 0.0)] * 2)
    y = 3.0 + points[:, 0] - 0.5 * points[:, 1] + 0.25 * points[:, 0] ** 2 + 0.01 * (np.arange(len(points)) % 3)
    return pd.DataFrame({"run": range(1, len(points) + 1), "a": points[:, 0], "b": points[:, 1], "y": y})


@pytest.mark.parametrize("published", [{}, {"decimals": {"r2": 3}}, [], None, [("r2", 0.9)]])
def test_no_published_statistics_are_refused_naming_the_source(published):
    with pytest.raises(InputError) as err:
        check_transcription(_table(), ["a", "b"], "y", published, design_type="factorial", source="paper.yaml")
    assert str(err.value).startswith("paper.yaml") and "no published statistics given" in str(err.value)
