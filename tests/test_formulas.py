"""The shared formulas against scipy and the definitions written out."""

import numpy as np
import pytest
from scipy import stats

from demid.formulas import f_tail, relative_error


def test_relative_error_divides_by_the_size_of_the_target():
    assert relative_error(9.0, 10.0) == pytest.approx(-0.1)
    assert relative_error(-9.0, -10.0) == pytest.approx(0.1)
    block = relative_error(np.array([[1.0, 2.0], [3.0, 4.0]]), np.array([2.0, -4.0])[:, None])
    np.testing.assert_allclose(block, [[-0.5, 0.0], [1.75, 2.0]])


@pytest.mark.parametrize("f, dfn, dfd", [(0.5, 1, 1), (2.7, 3, 7), (10.0, 5, 2), (1e-3, 2, 30), (40.0, 1, 100)])
def test_f_tail_is_scipys_survival_function(f, dfn, dfd):
    assert f_tail(f, dfn, dfd) == pytest.approx(stats.f.sf(f, dfn, dfd), rel=1e-12)
    assert isinstance(f_tail(f, dfn, dfd), float)  # a scalar for scalar arguments, not a 0-d array


def test_f_tail_edges_and_arrays():
    out = f_tail([-1.0, 0.0, np.inf, np.nan, 3.0, 3.0, 3.0], [2, 2, 2, 2, 0, 2, 2], [5, 5, 5, 5, 5, 0, 4])
    assert out[0] == 1.0 and out[1] == 1.0
    assert np.isnan(out[2:6]).all()
    assert out[6] == pytest.approx(stats.f.sf(3.0, 2, 4), rel=1e-12)
    assert isinstance(out, np.ndarray) and out.shape == (7,)
    np.testing.assert_allclose(f_tail([0.5, -0.5], 2, 5), [stats.f.sf(0.5, 2, 5), 1.0], rtol=1e-12)
