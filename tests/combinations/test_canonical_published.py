"""Canonical analysis against published worked examples: the printed data run through demid's own fit path
(read the table, fit the quadratic in the design's coding, canonical analysis), compared with the printed
numbers at their printed precision.  A saddle (Lawson's trebuchet, a 3-factor Box-Behnken design) and two
rising ridges (Myers, Montgomery & Anderson-Cook's Table 6.2 and Box, Hunter & Hunter's replicated 3^2 CO
emissions table); the maximum (Montgomery's Example 11.2) is in ``test_canonical.py``.  A textbook's named
surfaces (Gramacy: maximum, stationary ridge, rising ridge) are checked against their analysis worked by hand.  The last tests run the
same tables through ``python -m demid fit`` without ``--design`` and read the canonical section of its JSON.

Every expected number below is copied from its source, not from demid.
"""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from demid.canonical import fit_canonical
from demid.design import Coding
from demid.surrogate import fit_response
from ..helpers import run_demid

# Lawson, J. (2015) Design and Analysis of Experiments with R, CRC Press, Section 10.7 (p. 410, "Example 16":
# summary(treb.quad) of rsm); data set `Treb` of the R package daewr: a trebuchet, distance thrown y [ft] vs arm
# length A [ft], counterweight B [lb], missile weight C [oz]; coding x1 = (A - 6)/2, x2 = (B - 15)/5,
# x3 = (C - 2.5)/0.5.
TREBUCHET = [(4, 10, 2.5, 33), (8, 10, 2.5, 85), (4, 20, 2.5, 86), (8, 20, 2.5, 113), (4, 15, 2.0, 75),
             (8, 15, 2.0, 105), (4, 15, 3.0, 40), (8, 15, 3.0, 89), (6, 10, 2.0, 83), (6, 20, 2.0, 108),
             (6, 10, 3.0, 49), (6, 20, 3.0, 101), (6, 15, 2.5, 88), (6, 15, 2.5, 91), (6, 15, 2.5, 91)]

# Myers, Montgomery & Anderson-Cook, Response Surface Methodology, Table 6.2: the rising-ridge example (a
# face-centred CCD in coded units, 3 centre runs), as R's rsm documents it (?rsm: "Example of a rising-ridge
# situation from Montgomery et al, Table 6.2 ... canonical(RRex.rsm) # rising ridge is detected"), run order
# of rsm's ccd(): factorial (A fastest), then axial (-A, +A, -B, +B), then centre.
RISING_RIDGE = [(-1, -1, 52.3), (1, -1, 5.3), (-1, 1, 46.7), (1, 1, 44.2), (-1, 0, 58.5), (1, 0, 33.5),
                (0, -1, 32.8), (0, 1, 49.2), (0, 0, 49.3), (0, 0, 50.2), (0, 0, 51.6)]

# Box, Hunter & Hunter (2005) Statistics for Experimenters, 2nd ed., Table 10.17 (p. 396): a replicated 3^2 on
# CO concentration vs ethanol concentration and air/fuel ratio, coded (as rsm's `codata`, after BH^2 Fig. 11.17)
# x1 = (ethanol - 0.2)/0.1, x2 = air/fuel ratio - 15; BH^2 discuss it as a sloping (rising) ridge, pp. 466-7.
CO_EMISSIONS = [(-1, -1, 61.9), (-1, -1, 65.6), (0, -1, 80.9), (0, -1, 78.0), (1, -1, 89.7), (1, -1, 93.8),
                (-1, 0, 72.1), (-1, 0, 67.3), (0, 0, 80.1), (0, 0, 81.4), (1, 0, 77.8), (1, 0, 74.8),
                (-1, 1, 66.4), (-1, 1, 68.2), (0, 1, 68.9), (0, 1, 66.0), (1, 1, 60.2), (1, 1, 57.9)]


def _table(rows, columns):
    table = pd.DataFrame(rows, columns=columns)
    table.insert(0, "run", range(1, len(rows) + 1))
    return table


def _trebuchet_table():
    return _table(TREBUCHET, ["A", "B", "C", "y"])


def _co_table():
    """The CO table in actual units (ethanol concentration, air/fuel ratio), as the book prints its levels."""
    rows = [(round(0.2 + 0.1 * x1, 1), 15 + x2, y) for x1, x2, y in CO_EMISSIONS]
    return _table(rows, ["ethanol", "af_ratio", "co"])


def _same_up_to_sign(actual_columns, printed_columns):
    for got, want in zip(np.asarray(actual_columns, dtype=float).T, np.asarray(printed_columns, dtype=float).T):
        sign = np.sign(got @ want)
        assert sign * got == pytest.approx(want, abs=1e-6)


def test_saddle_lawson_trebuchet_box_behnken():
    """Lawson (2015), p. 410, as rsm prints it:
        Stationary point of response surface:   x1 0.9236846  x2 -1.7161183  x3 -2.7698217
        Stationary point in original units:     A 7.847369    B 6.419409     C 1.115089
        Eigenanalysis: $values 1.280298 -3.551452 -11.853845
        $vectors        [,1]       [,2]       [,3]
                  x1 -0.1236692  0.5238084  0.8428112
                  x2  0.8323200 -0.4077092  0.3755217
                  x3  0.5403233  0.7479291 -0.3855551
    Eigenvalues of both signs (none below a tenth of the largest): a saddle point, outside the design
    (x3 = -2.77 is beyond the +-1 levels)."""
    fit = fit_response(_trebuchet_table(), ["A", "B", "C"], "y",
                       coding=Coding(("A", "B", "C"), (6.0, 15.0, 2.5), (2.0, 5.0, 0.5)))
    c = fit_canonical(fit)
    assert c.eigenvalues == pytest.approx([1.280298, -3.551452, -11.853845], abs=5e-7)
    _same_up_to_sign(c.eigenvectors, [[-0.1236692, 0.5238084, 0.8428112],
                                      [0.8323200, -0.4077092, 0.3755217],
                                      [0.5403233, 0.7479291, -0.3855551]])
    assert c.stationary_coded == pytest.approx([0.9236846, -1.7161183, -2.7698217], abs=5e-8)
    assert c.stationary_actual == pytest.approx([7.847369, 6.419409, 1.115089], abs=5e-7)
    assert c.kind == "saddle point" and not c.is_ridge
    assert not c.inside


def test_rising_ridge_myers_montgomery_table_6_2():
    """MMA-C Table 6.2 through rsm's canonical() (threshold 0 for the full stationary point; the values as the
    reference tests of the mistat package hold them, gedeck/mistat src/mistat/rsm/tests/
    test_responseSurfaceMethod.py, test_RidgeRisingSituation):
        xs = (-5.176505, -2.706733); eigenvalues -0.509419, -12.706370;
        eigenvectors (0.8396245, 0.5431673) and (-0.5431673, 0.8396245).
    The kind as rsm's documentation names it: |-0.509| is below a tenth of 12.71, so rsm's default threshold sets
    it to zero, "rising ridge is detected"; the stationary point lies far outside the +-1 square."""
    fit = fit_response(_table(RISING_RIDGE, ["A", "B", "y"]), ["A", "B"], "y",
                       coding=Coding(("A", "B"), (0.0, 0.0), (1.0, 1.0)))
    c = fit_canonical(fit)
    assert c.eigenvalues == pytest.approx([-0.509419, -12.706370], abs=5e-7)
    _same_up_to_sign(c.eigenvectors, [[0.8396245, -0.5431673], [0.5431673, 0.8396245]])
    assert c.stationary_coded == pytest.approx([-5.176505, -2.706733], abs=5e-7)
    assert c.kind == "rising ridge" and not c.inside
    # the ridge runs along the first eigenvector; rsm's thresholded point lies on the second axis through the
    # centre (x = t * (-0.5431673, 0.8396245)), within the design
    _same_up_to_sign(c.ridge_directions, [[0.8396245], [0.5431673]])
    assert np.all(np.abs(c.ridge_point_coded) <= 1)
    assert c.ridge_point_coded @ np.array([0.8396245, 0.5431673]) == pytest.approx(0, abs=1e-6)


def test_rising_ridge_box_hunter_hunter_co_emissions():
    """BH^2 Table 10.17 (rsm's `codata`), fitted in actual units and coded by the book's levels.  Printed by
    Lenth's rsm vignette ("Response-Surface Methods in R, Using rsm", section "Stationary and rising-ridge
    situations"), canonical(CO.rsm, threshold = 0): xs = (-14.81387, 15.44149), eigenvalues 0.1868328 and
    -8.8868328 (the values as the reference test of the industrialstats package holds them,
    DiogoRibeiro7/industrialstats tests/test_validation/test_rsm_reference.py).  With rsm's default threshold
    the small eigenvalue counts as zero and the thresholded stationary point lies "near the design center", on
    "the rising ridge that occurs in the vicinity of the design" (rsm's ?codata: "an example of a rising
    ridge"); without the threshold the stationary point is "a saddle point near the upper-left corner"."""
    fit = fit_response(_co_table(), ["ethanol", "af_ratio"], "co",
                       coding=Coding(("ethanol", "af_ratio"), (0.2, 15.0), (0.1, 1.0)))
    c = fit_canonical(fit)
    assert c.eigenvalues == pytest.approx([0.1868328, -8.8868328], abs=5e-8)
    assert c.stationary_coded == pytest.approx([-14.81387, 15.44149], abs=5e-6)
    assert c.stationary_actual == pytest.approx([0.2 - 0.1 * 14.81387, 15 + 15.44149], abs=5e-6)
    assert c.kind == "rising ridge" and not c.inside
    assert np.all(np.abs(c.ridge_point_coded) < 0.25)
    unthresholded = fit_canonical(fit, threshold=0.0)
    assert unthresholded.kind == "saddle point"
    assert unthresholded.stationary_coded == pytest.approx([-14.81387, 15.44149], abs=5e-6)



# Gramacy, R. B. (2020) Surrogates, CRC Press, Chapter 1 (after Myers, Montgomery & Anderson-Cook, ch. 6): the
# second-order surfaces it draws and names, in coded units (its code, public in efsalvarenga/surrogates
# src/chap1.R): "simple.max", "stationary ridge", "rising ridge".  The expected analysis is worked here by hand.
SURFACE_TERMS = [(0, 0), (1, 0), (0, 1), (2, 0), (0, 2), (1, 1)]


def test_gramacy_named_surfaces():
    """simple maximum 50 + 8x1 + 3x2 - 7x1^2 - 3x2^2 - 4x1x2: B = [[-7, -2], [-2, -3]], eigenvalues -5 +- sqrt 8;
    2Bx = -b gives x_s = (36/68, 10/68).
    stationary ridge 80 + 4x1 + 8x2 - 3x1^2 - 12x2^2 - 12x1x2 and rising ridge 80 - 4x1 + 12x2 - (same B):
    B = [[-3, -6], [-6, -12]] is singular, eigenvalues 0 (along (2, -1)/sqrt5) and -15 (along (1, 2)/sqrt5);
    the slope along the ridge is v'b = 0 (stationary: every point of x1 + 2x2 = 2/3 gives 80 + 4/3) and
    -20/sqrt5 (rising); rsm's thresholded point is the ridge point nearest the centre, (2, 4)/15, for both."""
    from demid.canonical import canonical_analysis, quadratic_parts

    def analysis(coefficients):
        return canonical_analysis(*quadratic_parts(SURFACE_TERMS, coefficients, 2), region_lower=[-1, -1],
                                  region_upper=[1, 1])

    c = analysis([50, 8, 3, -7, -3, -4])
    assert c.kind == "maximum" and c.inside
    assert c.eigenvalues == pytest.approx([-5 + 8 ** 0.5, -5 - 8 ** 0.5])
    assert c.stationary_coded == pytest.approx([36 / 68, 10 / 68])
    for coefficients, slope, kind in (([80, 4, 8, -3, -12, -12], 0.0, "stationary ridge"),
                                      ([80, -4, 12, -3, -12, -12], -20 / 5 ** 0.5, "rising ridge")):
        c = analysis(coefficients)
        assert c.kind == kind
        assert c.eigenvalues == pytest.approx([0, -15], abs=1e-12)
        _same_up_to_sign(c.eigenvectors, np.array([[2, 1], [-1, 2]]) / 5 ** 0.5)
        _same_up_to_sign(c.ridge_directions, np.array([[2], [-1]]) / 5 ** 0.5)
        assert abs(c.ridge_slopes[0]) == pytest.approx(abs(slope), abs=1e-12)
        assert c.ridge_point_coded == pytest.approx([2 / 15, 4 / 15])
        assert np.all(np.isnan(c.stationary_coded)) and not c.inside  # B singular: no single stationary point
    assert analysis([80, 4, 8, -3, -12, -12]).ridge_value == pytest.approx(80 + 4 / 3)


def test_stationary_ridge_through_the_fit_path():
    # Gramacy's stationary ridge, observed exactly on a 3^2 design with three centre runs: the fitted surface is
    # the book's, and the fit path names it a stationary ridge with its line of maxima through (2, 4)/15
    levels = [(a, b) for a in (-1, 0, 1) for b in (-1, 0, 1)] + [(0, 0), (0, 0)]
    rows = [(a, b, 80 + 4 * a + 8 * b - 3 * a * a - 12 * b * b - 12 * a * b) for a, b in levels]
    fit = fit_response(_table(rows, ["x1", "x2", "y"]), ["x1", "x2"], "y",
                       coding=Coding(("x1", "x2"), (0.0, 0.0), (1.0, 1.0)))
    c = fit_canonical(fit)
    assert c.kind == "stationary ridge"
    assert c.eigenvalues == pytest.approx([0, -15], abs=1e-9)
    assert c.ridge_point_coded == pytest.approx([2 / 15, 4 / 15], abs=1e-9)
    assert c.ridge_value == pytest.approx(80 + 4 / 3, abs=1e-9)

# ---------------------------------------------------------------------------------------------- the CLI path
def _fit_json(tmp_path, table, factors, response):
    """``python -m demid fit`` on a CSV of the table, no --design: the canonical section of its JSON."""
    path = tmp_path / "table.csv"
    table.to_csv(path, index=False)
    out = tmp_path / "fit.json"
    proc = run_demid("fit", "--data", path, "--factors", ",".join(factors), "--responses", response, "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert "design inferred from the table" in proc.stderr
    return json.loads(out.read_text())[response]["canonical"]


def test_cli_fit_gives_the_printed_canonical_analysis_of_the_co_emissions_table(tmp_path):
    # the table as BH^2 print it (ethanol 0.1/0.2/0.3, air/fuel ratio 14/15/16): a replicated 3^2 is inferred and
    # coded by its levels, so the JSON carries the book's coded analysis; numbers as in the test above
    canonical = _fit_json(tmp_path, _co_table(), ["ethanol", "af_ratio"], "co")
    assert set(canonical) >= {"stationary_coded", "stationary_actual", "eigenvalues", "eigenvectors", "kind",
                              "inside"}
    assert canonical["eigenvalues"] == pytest.approx([0.1868328, -8.8868328], abs=5e-8)
    assert canonical["stationary_coded"] == pytest.approx([-14.81387, 15.44149], abs=5e-6)
    assert canonical["stationary_actual"] == pytest.approx([0.2 - 1.481387, 30.44149], abs=5e-6)
    assert canonical["kind"] == "rising ridge" and canonical["inside"] is False
    vectors = np.array(canonical["eigenvectors"])  # one list per eigenvector, unit length
    assert np.linalg.norm(vectors, axis=1) == pytest.approx([1, 1])


def test_cli_fit_gives_the_printed_canonical_analysis_of_the_trebuchet(tmp_path):
    canonical = _fit_json(tmp_path, _trebuchet_table(), ["A", "B", "C"], "y")
    assert canonical["eigenvalues"] == pytest.approx([1.280298, -3.551452, -11.853845], abs=5e-7)
    _same_up_to_sign(np.array(canonical["eigenvectors"]).T, [[-0.1236692, 0.5238084, 0.8428112],
                                                              [0.8323200, -0.4077092, 0.3755217],
                                                              [0.5403233, 0.7479291, -0.3855551]])
    assert canonical["stationary_coded"] == pytest.approx([0.9236846, -1.7161183, -2.7698217], abs=5e-7)
    assert canonical["stationary_actual"] == pytest.approx([7.847369, 6.419409, 1.115089], abs=5e-7)
    assert canonical["kind"] == "saddle point" and canonical["inside"] is False


def test_cli_fit_gives_the_printed_canonical_analysis_of_montgomery_example_11_2(tmp_path):
    # Montgomery, Design and Analysis of Experiments, Table 11.6 (a CCD, alpha = 1.414, 5 centre runs): printed
    # x_s = (0.389, 0.306), i.e. 86.95 min and 176.53 °F, eigenvalues -0.9634 and -1.4141: a maximum inside
    rows = [(80, 170, 76.5), (80, 180, 77.0), (90, 170, 78.0), (90, 180, 79.5), (85, 175, 79.9), (85, 175, 80.3),
            (85, 175, 80.0), (85, 175, 79.7), (85, 175, 79.8), (92.07, 175, 78.4), (77.93, 175, 75.6),
            (85, 182.07, 78.5), (85, 167.93, 77.0)]
    canonical = _fit_json(tmp_path, _table(rows, ["time", "temp", "y"]), ["time", "temp"], "y")
    assert canonical["eigenvalues"] == pytest.approx([-0.9634, -1.4141], abs=2e-4)
    assert canonical["stationary_coded"] == pytest.approx([0.389, 0.306], abs=1e-3)
    assert canonical["stationary_actual"] == pytest.approx([86.95, 176.53], abs=0.01)
    assert canonical["predicted"] == pytest.approx(80.21, abs=0.005)
    assert canonical["kind"] == "maximum" and canonical["inside"] is True


def test_cli_fit_gives_the_printed_canonical_analysis_of_the_blocked_chemical_reactor(tmp_path):
    # rsm's ChemReact (Myers, Montgomery & Anderson-Cook, Table 7.6: Montgomery's CCD run in two blocks, the
    # second block's yields lower) fitted with a block term; Lenth's rsm vignette (section "Fitting a response-
    # surface model", CR2.rsm) prints "the stationary point of the fitted surface is at (0.37, 0.33) in coded
    # units---well within the experimental region; and ... both eigenvalues are negative, indicating that the
    # stationary point is a maximum ... at Time ≈ 87, Temp ≈ 177"
    rows = [("B1", 80, 170, 80.5), ("B1", 80, 180, 81.5), ("B1", 90, 170, 82.0), ("B1", 90, 180, 83.5),
            ("B1", 85, 175, 83.9), ("B1", 85, 175, 84.3), ("B1", 85, 175, 84.0), ("B2", 85, 175, 79.7),
            ("B2", 85, 175, 79.8), ("B2", 85, 175, 79.5), ("B2", 92.07, 175, 78.4), ("B2", 77.93, 175, 75.6),
            ("B2", 85, 182.07, 78.5), ("B2", 85, 167.93, 77.0)]
    canonical = _fit_json(tmp_path, _table(rows, ["block", "Time", "Temp", "Yield"]), ["Time", "Temp"], "Yield")
    assert canonical["stationary_coded"] == pytest.approx([0.37, 0.33], abs=0.005)
    assert canonical["stationary_actual"] == pytest.approx([87, 177], abs=0.5)
    assert max(canonical["eigenvalues"]) < 0
    assert canonical["kind"] == "maximum" and canonical["inside"] is True


def test_cli_fit_calls_the_paper_helicopter_a_saddle_point_near_the_region(tmp_path):
    # Box, Hunter & Hunter (2005), Table 12.5 (rsm's `heli`): a 4-factor CCD (alpha = 2) in two blocks, average
    # flight time vs wing area A, wing length ratio R, body width W, body length L, coded x1 = (A - 12.4)/0.6,
    # x2 = (R - 2.52)/0.26, x3 = (W - 1.25)/0.25, x4 = (L - 2)/0.5.  The rsm vignette (heli.rsm, with a block
    # term): "the stationary point is fairly near the experimental region, but the eigenvalues are of mixed
    # sign, indicating that it is a saddle point"
    coded = [(-1, -1, -1, -1), (1, -1, -1, -1), (-1, 1, -1, -1), (1, 1, -1, -1), (-1, -1, 1, -1), (1, -1, 1, -1),
             (-1, 1, 1, -1), (1, 1, 1, -1), (-1, -1, -1, 1), (1, -1, -1, 1), (-1, 1, -1, 1), (1, 1, -1, 1),
             (-1, -1, 1, 1), (1, -1, 1, 1), (-1, 1, 1, 1), (1, 1, 1, 1), (0, 0, 0, 0), (0, 0, 0, 0),
             (-2, 0, 0, 0), (2, 0, 0, 0), (0, -2, 0, 0), (0, 2, 0, 0), (0, 0, -2, 0), (0, 0, 2, 0), (0, 0, 0, -2),
             (0, 0, 0, 2), (0, 0, 0, 0), (0, 0, 0, 0), (0, 0, 0, 0), (0, 0, 0, 0)]
    ave = [367, 369, 374, 370, 372, 355, 397, 377, 350, 373, 358, 363, 344, 355, 370, 362, 377, 375, 361, 364,
           355, 373, 361, 360, 380, 360, 370, 368, 369, 366]
    rows = [(1 if i < 18 else 2, round(12.4 + 0.6 * a, 1), round(2.52 + 0.26 * r, 2), round(1.25 + 0.25 * w, 2),
             round(2 + 0.5 * length, 1), y) for i, ((a, r, w, length), y) in enumerate(zip(coded, ave))]
    canonical = _fit_json(tmp_path, _table(rows, ["block", "A", "R", "W", "L", "ave"]), ["A", "R", "W", "L"], "ave")
    assert min(canonical["eigenvalues"]) < 0 < max(canonical["eigenvalues"])
    assert canonical["kind"] == "saddle point"
    assert np.all(np.abs(canonical["stationary_coded"]) < 2)  # near the region (its axial points at +-2)
