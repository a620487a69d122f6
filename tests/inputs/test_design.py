import numpy as np
import pytest

from demid.design import (Coding, ccd_points, classify_points, cubic_terms, model_matrix, parse_term,
                          quadratic_terms, replicate_groups, rotatable_alpha, term_name)


def test_term_names_round_trip():
    factors = ["a", "b", "c"]
    for term in quadratic_terms(3) + cubic_terms(3):
        assert parse_term(term_name(term, factors), factors) == term
    names = [term_name(t, factors) for t in quadratic_terms(3)]
    assert names == ["Intercept", "a", "b", "c", "a:b", "a:c", "b:c", "a^2", "b^2", "c^2"]
    assert {term_name(t, ["a", "b"]) for t in cubic_terms(2)} == {"a^3", "b^3", "a^2:b", "a:b^2"}


def test_ccd_structure_counts():
    pts = ccd_points(3, rotatable_alpha(3), 6)
    labels = classify_points(pts, rotatable_alpha(3))
    assert len(pts) == 20
    assert (labels == "factorial").sum() == 8 and (labels == "axial").sum() == 6 and (labels == "center").sum() == 6
    assert rotatable_alpha(2) == pytest.approx(np.sqrt(2))
    groups = replicate_groups(pts)
    assert len(np.unique(groups)) == 15


def test_coding_round_trip_and_model_matrix():
    coding = Coding(("a", "b"), (0.5, 7.0), (0.3, 4.0))
    x = np.array([[0.2, 3.0], [0.8, 11.0]])
    assert np.allclose(coding.to_coded(x), [[-1, -1], [1, 1]])
    assert np.allclose(coding.to_actual(coding.to_coded(x)), x)
    m = model_matrix(np.array([[2.0, 3.0]]), quadratic_terms(2))
    assert m.tolist() == [[1, 2, 3, 6, 4, 9]]
