"""A missing cubic term aliased with another (criticism.level1's finding and its sentence), over 2-factor CCDs
with a planted cubic term, their levels exact or one factorial level printed a little off (a relative 1e-4 or
3e-4).  Whether the two terms can be told apart is computed here from the singular values of their columns
residualised on the quadratic by least squares: where they cannot, the finding proposes extra runs that separate
them and its sentence names exactly those runs; where the design already separates them (barely, through the
printed level), no run is proposed and the sentence proposes none."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize
from demid.design import model_matrix, quadratic_terms, term_name
from tests.generators import FACTORS, design


def _separable(coded: np.ndarray, terms: list[tuple[int, int]]) -> bool:
    """True when the terms' columns, residualised on the full quadratic, have full rank (relative 1e-9)."""
    base = model_matrix(coded, quadratic_terms(2))
    cols = model_matrix(coded, terms)
    resid = cols - base @ np.linalg.lstsq(base, cols, rcond=None)[0]
    s = np.linalg.svd(resid, compute_uv=False)
    return bool(s[-1] > 1e-9 * np.linalg.norm(cols))


@pytest.mark.parametrize("factor,offset", [(0, 0.0), (1, 0.0), (0, 1e-4), (1, 3e-4)])
def test_extra_runs_are_proposed_and_named_only_where_the_runs_cannot_tell_the_terms_apart(factor, offset):
    factors, coding, coded, alpha = design(2)
    coded = coded.copy()
    coded[0, factor] *= 1 - offset  # a factorial level printed a little off
    other = 1 - factor
    cubic = tuple(3 if j == factor else 0 for j in range(2))
    alias = tuple(1 if j == factor else 2 for j in range(2))  # x * (other factor)^2: equal on the factorial runs
    rng = np.random.default_rng(factor)
    y = 100 + 10 * coded[:, factor] + 5 * coded[:, other] + 8 * coded[:, factor] ** 3 + rng.normal(size=13) * 0.3
    table = pd.DataFrame(coding.to_actual(coded), columns=factors)
    table.insert(0, "run", np.arange(1, 14))
    table["y"] = y
    (finding, *_) = criticize(table, FACTORS[2], "y", n_null=99).findings
    assert finding.cause == "missing_term"
    assert finding.aliases == [term_name(cubic, factors), term_name(alias, factors)]
    head = (f"y: the quadratic misses curvature along {factors[factor]} (term {term_name(cubic, factors)}, aliased "
            f"with {term_name(alias, factors)} in this design); adding it cuts the leave-one-out error by ")
    assert finding.message.startswith(head)
    if _separable(coded, [cubic, alias]):
        assert offset > 0
        assert finding.extra_runs == []
        assert finding.message.endswith(" %.")
        return
    assert offset == 0
    assert finding.extra_runs
    extra = coding.to_coded(np.array([[p[f] for f in factors] for p in finding.extra_runs]))
    assert _separable(np.vstack([coded, extra]), [cubic, alias])
    points = " and ".join("(" + ", ".join(f"{f}={p[f]:g}" for f in factors) + ")" for p in finding.extra_runs)
    assert finding.message.endswith(f" %. Extra runs at {points} would tell the two apart.")
