"""A design's block check as the JSON a user reads (``blocks`` in the criticism's output): every field against the
check it writes, the largest correlation rounded to six decimals (written out here with Python's round), over
CCDs of 2-3 factors in 2-3 blocks (the orthogonal blocking or labels drawn at random) with 1-6 centre runs."""

from __future__ import annotations

import json

import numpy as np
from hypothesis import Phase, given, settings, strategies as st

from demid.blocks import ccd_blocks, check_blocks
from demid.design import ccd_points, model_matrix, quadratic_terms


@given(seed=st.integers(0, 10_000), k=st.sampled_from([2, 3]), blocks=st.integers(2, 3),
       orthogonal_blocks=st.booleans(), centres=st.integers(1, 6))
@settings(max_examples=20, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
def test_the_block_checks_json_holds_each_field_and_the_correlation_to_six_decimals(seed, k, blocks,
                                                                                    orthogonal_blocks, centres):
    rng = np.random.default_rng(seed)
    coded = ccd_points(k, None, centres)
    number = ccd_blocks(coded, blocks) if orthogonal_blocks else rng.integers(1, blocks + 1, len(coded))
    labels = [f"wave {n}" for n in number]
    found = check_blocks(coded, labels, model_matrix(coded, quadratic_terms(k)))
    written = json.loads(json.dumps(found.to_json()))
    assert written == {"blocks": list(found.levels), "runs": found.runs, "centre_runs": found.centre_runs,
                       "orthogonal": found.orthogonal, "max_correlation": round(found.max_correlation, 6),
                       "notes": list(found.notes)}
    assert len(repr(written["max_correlation"]).split(".")[-1]) <= 6 or "e" in repr(written["max_correlation"])
    assert sum(written["runs"].values()) == len(coded) and list(written["runs"]) == written["blocks"]
