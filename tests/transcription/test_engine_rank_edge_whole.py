"""The refit engine's rank (demid.transcription.engine.DesignFit) on designs at the edge of rank: a two-level factor
one of whose runs sits 1e-15 to 1e-12 coded units off its level (a value carried to the last printed digit), so the
quadratic's squared term of that factor is all but the intercept, over 2-3 factors and 40-240 runs.  The rank is
numpy.linalg.matrix_rank's (tolerance: the largest singular value times the larger of the matrix's two sizes times
the machine epsilon), which many of these designs straddle."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import Coding, model_matrix, quadratic_terms
from demid.transcription.engine import DesignFit


@given(k=st.integers(2, 3), n=st.integers(40, 240), exponent=st.floats(-15.0, -12.0), seed=st.integers(0, 10_000))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_the_rank_is_numpys_on_a_design_at_the_edge_of_rank(k, n, exponent, seed):
    rng = np.random.default_rng(seed)
    coded = np.column_stack([np.where(rng.random(n) < 0.5, -1.0, 1.0)]
                            + [rng.choice([-1.0, 0.0, 1.0], n) for _ in range(k - 1)])
    coded[0, 0] = 1.0 + 10.0 ** exponent
    terms = quadratic_terms(k)
    fit = DesignFit(coded, terms, Coding(tuple(f"x{i}" for i in range(k)), (0.0,) * k, (1.0,) * k), False)
    matrix = model_matrix(coded, terms)
    assert fit.rank == np.linalg.matrix_rank(matrix)
    assert (fit.n, fit.p) == matrix.shape
