"""A transcription check called without a source names what it checks: every refusal's one line carries
"published statistics for '<response>'" (the default source), never an empty or missing name."""

from __future__ import annotations

import pandas as pd
import pytest

from demid.errors import InputError
from demid.transcription.check import check_transcription


@pytest.mark.parametrize("response", ["y", "angle_of_repose"])
def test_a_missing_column_is_refused_naming_the_default_source(response):
    table = pd.DataFrame({"a": [-1.0, 1.0, 0.0], "b": [0.0, 1.0, -1.0]})
    with pytest.raises(InputError) as err:
        check_transcription(table, ["a", "b"], response, {"r2": 0.9})
    assert f"published statistics for '{response}'" in str(err.value)
    assert repr(response) in str(err.value)


def test_a_given_source_is_named_instead():
    table = pd.DataFrame({"a": [-1.0, 1.0, 0.0], "b": [0.0, 1.0, -1.0]})
    with pytest.raises(InputError) as err:
        check_transcription(table, ["a", "b"], "y", {"r2": 0.9}, source="data/paper.csv")
    assert "data/paper.csv" in str(err.value) and "published statistics" not in str(err.value)
