"""The rank require_estimable reads off the usable runs: singular values of the model matrix below 1e-8 of the
largest count as zero (numpy's singular values, the rule written out here).  A one-factor quadratic whose third
level sits delta from the centre level: at delta = 3.2e-8 its smallest singular value is 6.8e-9 of the largest, so
the runs hold two levels and the refusal quotes rank 2 of 3; at 6e-8 (1.3e-8 of the largest) they hold three."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import model_matrix, quadratic_terms
from demid.errors import InputError
from demid.estimability import require_estimable


@pytest.mark.parametrize("delta, rank", [(3.2e-8, 2), (6e-8, 3), (1e-6, 3), (1e-10, 2)])
def test_singular_values_below_a_hundred_millionth_of_the_largest_are_zero(delta, rank):
    coded = np.array([[-1.0], [-1.0], [0.0], [0.0], [delta]])
    singular = np.linalg.svd(model_matrix(coded, quadratic_terms(1)), compute_uv=False)
    assert int(np.sum(singular > 1e-8 * singular.max())) == rank  # the rule, written out
    usable = np.ones(len(coded), dtype=bool)
    if rank == 3:
        require_estimable(coded, usable, None, "t.csv", "y", ["a"])
        return
    with pytest.raises(InputError) as info:
        require_estimable(coded, usable, None, "t.csv", "y", ["a"])
    assert "the quadratic model cannot be estimated (rank 2 of 3 terms)" in str(info.value)
    assert info.value.column == "y"
