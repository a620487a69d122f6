"""A term the design cannot estimate at all gets the runs that would make it estimable: in a face-centred CCD
every factor takes only the levels -1, 0 and 1, where a^3 equals a, so the pure cubes are reported as not
testable, each with runs after which its column is no longer a combination of the quadratic's."""

from __future__ import annotations

import numpy as np

from demid.criticism import criticize
from demid.design import model_matrix, parse_term, quadratic_terms
from tests.generators import FACTORS, ccd_table


def _coded(table, factors):
    x = table[factors].to_numpy(dtype=float)
    lo, hi = x.min(axis=0), x.max(axis=0)
    return lambda actual: (np.asarray(actual, dtype=float) - (lo + hi) / 2) / ((hi - lo) / 2)


def _left_over(coded, term):
    """Norm of the term's column off the quadratic's columns, relative to the column's norm."""
    x, z = model_matrix(coded, quadratic_terms(coded.shape[1])), model_matrix(coded, [term])[:, 0]
    resid = z - x @ np.linalg.lstsq(x, z, rcond=None)[0]
    return float(np.linalg.norm(resid) / np.linalg.norm(z))


def test_pure_cubes_of_a_face_centred_design_get_runs_that_make_them_estimable():
    factors = FACTORS[2]
    table, _ = ccd_table(4, 2, "clean", alpha=1.0)
    to_coded = _coded(table, factors)
    coded = to_coded(table[factors])
    result = criticize(table, factors, "y", n_null=19)
    cubes = {f"{f}^3" for f in factors}
    untestable = [a for a in result.alias_sets if not a.testable]
    assert {a.representative for a in untestable} == cubes
    for a in untestable:
        term = parse_term(a.representative, factors)
        assert _left_over(coded, term) < 1e-9  # a^3 is a at the levels -1, 0, 1
        assert a.extra_runs, a.representative
        added = to_coded([[run[f] for f in factors] for run in a.extra_runs])
        assert _left_over(np.vstack([coded, added]), term) > 1e-3


def _apart_by(relative, decimals, sign=(1, -1, -1, 1, 1, -1, 1, 1, -1, 1, -1, 1, -1)):
    """The face-centred design with its outer levels of gamma written a little differently in each run."""
    table, _ = ccd_table(4, 2, "clean", alpha=1.0)
    sign = np.array(sign)
    g = table["gamma"].to_numpy(dtype=float)
    table["gamma"] = np.where(g != 8.0, np.round(g * (1 + relative * sign), decimals), g)
    return table


def test_a_cube_apart_from_the_quadratic_by_less_than_a_ten_millionth_is_not_testable():
    # gamma^3 differs from a combination of the quadratic's columns by less than 1e-7 of its own size: no test
    # of it can be told from round-off, so it is reported as not testable, with the runs that would make it so
    table = _apart_by(5e-8, 9, sign=(-1, 1, 1, -1, -1, 0, -1, 0, 0, 0, 1, 1, -1))
    term = parse_term("gamma^3", FACTORS[2])
    assert _left_over(_coded(table, FACTORS[2])(table[FACTORS[2]]), term) < 1e-7
    result = criticize(table, FACTORS[2], "y", n_null=19)
    cube = next(a for a in result.alias_sets if a.representative == "gamma^3")
    assert not cube.testable and cube.extra_runs


def _narrowly_apart():
    """The same design with its outer levels of gamma written to seven digits, each run's a little differently:
    the pure cube of gamma stays barely apart from gamma."""
    table = _apart_by(3e-7, 6)
    coded = _coded(table, FACTORS[2])(table[FACTORS[2]])
    assert _left_over(coded, parse_term("gamma^3", FACTORS[2])) < 1e-5
    return table, coded


def test_a_term_the_runs_estimate_however_narrowly_gets_no_runs():
    # testable, and a testable lone term needs no run to be told apart
    table, _ = _narrowly_apart()
    result = criticize(table, FACTORS[2], "y", n_null=19)
    alone = [a for a in result.alias_sets if len(a.members) == 1 and a.testable]
    assert "gamma^3" in {a.representative for a in alone}
    assert all(a.extra_runs == () for a in alone)


def test_a_lone_missing_term_named_on_such_runs_proposes_no_runs_to_separate_it():
    table, coded = _narrowly_apart()
    x = model_matrix(coded, quadratic_terms(2))
    z = model_matrix(coded, [parse_term("gamma^3", FACTORS[2])])[:, 0]
    resid = z - x @ np.linalg.lstsq(x, z, rcond=None)[0]
    table["y"] = table["y"] + 10.0 * resid / np.linalg.norm(resid)  # the response follows that narrow direction
    result = criticize(table, FACTORS[2], "y", n_null=99)
    assert [(f.cause, f.detail) for f in result.findings] == [("missing_term", "gamma^3")]
    assert result.findings[0].extra_runs == [] and "extra_runs" not in result.findings[0].to_json()
