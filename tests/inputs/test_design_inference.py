"""Without --design, fit / criticize / check-transcription infer the design from the table's geometry, say which,
and never call it declared.  Tables printed with levels rounded to practical values (one axial distance per
factor) validate; a CCD with a run off its points is still refused with one line."""

from __future__ import annotations

import itertools
import json
import re

import numpy as np
import pandas as pd
import pytest

from demid.data import validate_material
from demid.design import box_behnken_points, ccd_points, model_matrix, quadratic_terms, term_name
from demid.design_inference import infer_design
from demid.spec import MaterialSpec
from ..helpers import run_demid


def _cli(*args):
    return run_demid(*args)


def _full_factorial(k, levels):
    return np.array(list(itertools.product(levels, repeat=k)), dtype=float)


def _plant(tmp_path, coded, centre, unit, seed, decimals=6, axial_decimals=None, name="t.csv"):
    """A table of an exact quadratic in the design's coded units (the known coefficients ``beta``), factors
    printed to ``decimals``; ``axial_decimals`` (one per factor) rounds a CCD's axial levels to practical values
    before the response is computed (the response is the quadratic at the values the table prints)."""
    rng = np.random.default_rng(seed)
    k = coded.shape[1]
    actual = coded * unit + centre
    for j, places in enumerate(axial_decimals or ()):
        axial = np.abs(coded[:, j]) > 1.01
        actual[axial, j] = np.round(actual[axial, j], places)
    actual = np.round(actual, decimals)
    beta = rng.normal(0, 3, len(quadratic_terms(k)))
    beta[0] = 50
    y = model_matrix((actual - centre) / unit, quadratic_terms(k)) @ beta
    order = rng.permutation(len(coded))
    names = [f"x{i + 1}" for i in range(k)]
    frame = pd.DataFrame(actual[order], columns=names)
    frame.insert(0, "run", np.arange(1, len(coded) + 1))
    frame["y"] = y[order]
    path = tmp_path / name
    path.write_text(frame.to_csv(index=False, float_format="%.9f"))
    return path, names, beta


_CENTRE3, _UNIT3 = np.array([0.5, 5.0, 20.0]), np.array([0.2, 2.0, 5.0])

# (case, coded points, centre, unit, axial decimals, expected note fragment)
_TABLES = {
    "box_behnken_3": (box_behnken_points(3, 3), _CENTRE3, _UNIT3, None,
                      r"a 3-factor Box-Behnken design with 3 centre runs"),
    "box_behnken_4": (box_behnken_points(4, 2), np.array([0.5, 5.0, 20.0, 1.0]), np.array([0.2, 2.0, 5.0, 0.5]), None,
                      r"a 4-factor Box-Behnken design with 2 centre runs"),
    "factorial_3^3": (_full_factorial(3, [-1, 0, 1]), _CENTRE3, _UNIT3, None, r"a 3\^3 full factorial, 1 centre run"),
    "factorial_3^3+2": (np.vstack([_full_factorial(3, [-1, 0, 1]), np.zeros((2, 3))]), _CENTRE3, _UNIT3, None,
                        r"a 3\^3 full factorial, 3 centre runs"),
    # 0.5 +- 0.3536 -> 0.15 / 0.85 (alpha 1.4), 10 +- 4.95 -> 5 / 15 (alpha 1.4286): levels printed to practice
    "rounded_ccd_2": (ccd_points(2, 1.41421, 5), np.array([0.5, 10.0]), np.array([0.25, 3.5]),
                      (2, 0),
                      r"a 2-factor central composite design \(CCD\), axial distance 1\.4 for x1, 1\.429 for x2, "
                      r"5 centre runs"),
    "rounded_ccd_3": (ccd_points(3, 1.68179, 3), _CENTRE3, _UNIT3,
                      (2, 1, 0),
                      r"a 3-factor central composite design \(CCD\), axial distance 1\.7 for x1, 1\.7 for x2, "
                      r"1\.6 for x3, 3 centre runs"),
    "rotatable_ccd_2": (ccd_points(2, 1.41421, 3), np.array([0.5, 10.0]), np.array([0.25, 3.5]), None,
                        r"a 2-factor central composite design \(CCD\), axial distance alpha = 1\.41421, 3 centre runs"),
}


@pytest.mark.parametrize("case", sorted(_TABLES))
def test_fit_and_criticize_without_design_infer_the_family_and_say_so(tmp_path, case):
    coded, centre, unit, axial_decimals, note = _TABLES[case]
    path, names, beta = _plant(tmp_path, coded, centre, unit, seed=len(case), axial_decimals=axial_decimals)
    out = tmp_path / "fit.json"
    proc = _cli("fit", "--data", str(path), "--factors", ",".join(names), "--responses", "y", "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    line = rf"^demid: note: .*t\.csv: design inferred from the table \(no --design given\): {note}$"
    assert re.search(line, proc.stderr, re.M), proc.stderr
    assert "declared" not in proc.stderr
    # coded by the design's geometry: the factorial (or +-1) levels at +-1, so the coded fit is the generator's
    fitted = json.loads(out.read_text())["y"]["coefficients_coded"]
    expected = {term_name(t, names): b for t, b in zip(quadratic_terms(len(names)), beta)}
    assert [fitted[t] for t in expected] == pytest.approx(list(expected.values()), abs=1e-5)
    out = tmp_path / "crit.json"
    proc = _cli("criticize", "--data", str(path), "--factors", ",".join(names), "--response", "y", "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    assert re.search(line, proc.stderr, re.M) and "declared" not in proc.stderr
    assert out.exists()


@pytest.mark.parametrize("k", [2, 3])
def test_a_two_level_factorial_with_centre_runs_is_inferred_and_refused_only_for_its_squares(tmp_path, k):
    coded = np.vstack([_full_factorial(k, [-1, 1]), np.zeros((4, k))])
    path, names, _ = _plant(tmp_path, coded, _CENTRE3[:k], _UNIT3[:k], seed=k)
    table = pd.read_csv(path)
    inferred = infer_design(table, names, str(path))
    assert (inferred.family, inferred.center_runs) == ("two_level", 4)
    assert inferred.describe() == f"a {k}-factor two-level factorial with 4 centre runs"
    proc = _cli("fit", "--data", str(path), "--factors", ",".join(names), "--responses", "y",
                "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1, proc.stderr
    # the refusal is the estimability one (why the squares cannot be fitted), not a design refusal
    assert "cannot be estimated" in proc.stderr and "as in a two-level factorial with centre runs" in proc.stderr


def test_a_table_of_no_standard_design_is_inferred_custom(tmp_path):
    rng = np.random.default_rng(3)
    coded = rng.uniform(-1, 1, (15, 2))
    path, names, beta = _plant(tmp_path, coded, np.array([0.5, 10.0]), np.array([0.25, 3.5]), seed=3)
    out = tmp_path / "fit.json"
    proc = _cli("fit", "--data", str(path), "--factors", ",".join(names), "--responses", "y", "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    assert "no standard design (custom" in proc.stderr


def _broken(tmp_path, edit):
    coded = ccd_points(2, 1.41421, 5)
    path, names, _ = _plant(tmp_path, coded, np.array([0.5, 10.0]), np.array([0.25, 3.5]), seed=0,
                            axial_decimals=(3, 0))
    table = pd.read_csv(path)
    run = edit(table)
    path.write_text(table.to_csv(index=False, float_format="%.9f"))
    return path, run


@pytest.mark.parametrize("edit, message", [
    # a centre run with x1 at a factorial level: no point of a CCD
    (lambda t: _set(t, (t.x1 == 0.5) & (t.x2 == 10.0), "x1", 0.75),
     r"run (\d+): the point \(x1 0\.75, x2 10\) is not a factorial, axial or centre point of the inferred ccd design"),
    # a factorial cell typed as a level no other run has
    (lambda t: _set(t, (t.x1 == 0.25) & (t.x2 == 6.5), "x1", 0.35),
     r"run (\d+), column 'x1': value 0\.35 is not a level of the inferred ccd design"),
    # one axial cell off: its two axial levels are no longer symmetric about the centre
    (lambda t: _set(t, t.x1 == t.x1.max(), "x1", 0.951),
     r"runs \d+ and (\d+), column 'x1': the levels of x1 are a CCD's but its axial levels 0\.146 and 0\.951 lie "
     r"1\.416 and 1\.804 coded units from the centre 0\.5: one of these axial cells is mistyped"),
])
@pytest.mark.parametrize("command", ["fit", "criticize"])
def test_a_broken_ccd_is_still_refused_with_one_line_naming_the_run(tmp_path, edit, message, command):
    path, run = _broken(tmp_path, edit)
    flag = "--responses" if command == "fit" else "--response"
    out = tmp_path / "o.json"
    proc = _cli(command, "--data", str(path), "--factors", "x1,x2", flag, "y", "--out", str(out))
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr, proc.stderr
    found = re.search(message, proc.stderr)
    assert found, proc.stderr
    assert int(found.group(1)) == run and "declared" not in proc.stderr and not out.exists()


def _set(table, where, column, value) -> int:
    i = int(np.flatnonzero(where.to_numpy())[0])
    table.loc[i, column] = value
    return int(table["run"].iloc[i])


def test_a_ccd_with_levels_rounded_to_practical_values_validates_against_its_declared_alpha(tmp_path):
    coded = ccd_points(2, 1.41421, 5)
    path, names, _ = _plant(tmp_path, coded, np.array([0.5, 10.0]), np.array([0.25, 3.5]), seed=1,
                            axial_decimals=(3, 0))
    cfg = {"data": str(path), "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
           "factors": {"x1": {"lower": 0.146, "upper": 0.854}, "x2": {"lower": 5.0, "upper": 15.0}},
           "responses": {"y": {}}}
    vt = validate_material(MaterialSpec.from_material("m", cfg))
    assert vt.coding.center == pytest.approx((0.5, 10.0)) and vt.coding.unit == pytest.approx((0.25, 3.5))
    assert sorted(vt.point_types.tolist()).count("axial") == 4


def test_check_transcription_without_design_codes_a_rounded_ccd_by_its_geometry(tmp_path):
    coded = ccd_points(2, 1.41421, 5)
    path, names, beta = _plant(tmp_path, coded, np.array([0.5, 10.0]), np.array([0.25, 3.5]), seed=2,
                               axial_decimals=(2, 0))
    out = tmp_path / "t.json"
    proc = _cli("check-transcription", "--data", str(path), "--factors", "x1,x2", "--response", "y",
                "--published", "r2=1.0000", "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    assert re.search(r"design inferred from the table .*axial distance 1\.4 for x1, 1\.429 for x2", proc.stderr)
    assert json.loads(out.read_text())["consistent"] is True


def test_a_ccd_without_one_axial_run_is_still_inferred_from_the_other(tmp_path):
    """A failed run may be left out of a command-line table: the factor then shows four levels."""
    coded = ccd_points(2, 1.41421, 5)
    path, names, beta = _plant(tmp_path, coded, np.array([0.5, 10.0]), np.array([0.25, 3.5]), seed=4,
                               axial_decimals=(3, 0))
    table = pd.read_csv(path)
    table = table[table["x1"] != table["x1"].max()]  # the +alpha run of x1 failed
    path.write_text(table.to_csv(index=False, float_format="%.9f"))
    out = tmp_path / "fit.json"
    proc = _cli("fit", "--data", str(path), "--factors", "x1,x2", "--responses", "y", "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    assert re.search(r"central composite design \(CCD\), axial distance 1\.416 for x1, 1\.429 for x2, 5 centre runs",
                     proc.stderr), proc.stderr
    fitted = json.loads(out.read_text())["y"]["coefficients_coded"]
    assert fitted["x1^2"] == pytest.approx(beta[4], abs=1e-5) and fitted["x1:x2"] == pytest.approx(beta[3], abs=1e-5)


def test_a_box_behnken_cell_off_its_level_is_refused_naming_the_inferred_design(tmp_path):
    path, names, _ = _plant(tmp_path, box_behnken_points(3, 3), _CENTRE3, _UNIT3, seed=5)
    table = pd.read_csv(path)
    row = int(np.flatnonzero(np.isclose(table["x1"], 0.5))[0])
    table.loc[row, "x1"] = 0.56
    path.write_text(table.to_csv(index=False, float_format="%.6f"))
    proc = _cli("criticize", "--data", str(path), "--factors", ",".join(names), "--response", "y",
                "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1, proc.stderr
    assert re.search(rf"run {int(table['run'].iloc[row])}, column 'x1': value 0\.56 is not a level of the inferred "
                     r"box_behnken design \(coded \+0\.300\); nearest valid level: 0\.5", proc.stderr), proc.stderr


def _print_factors_as_integers(path, names):
    table = pd.read_csv(path)
    table[names] = table[names].round().astype(int)
    path.write_text(table.to_csv(index=False, float_format="%.9f"))


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("kind", ["ccd", "box_behnken", "factorial"])
def test_levels_printed_to_few_digits_of_the_factors_unit_validate_without_design(tmp_path, seed, kind):
    """Every factor cell printed to whole units where a factor's coded unit is only 5-9 of them: the centre and
    the factorial levels are rounded too, so the coding read from them is off by up to half a digit at each end
    and an axial level by up to (2 + alpha) half digits.  Such a table is the design as printed, not a slip."""
    rng = np.random.default_rng(seed)
    k = 2 + seed % 2 if kind != "box_behnken" else 3
    coded = {"ccd": lambda: ccd_points(k, (2 ** k) ** 0.25, 5), "box_behnken": lambda: box_behnken_points(3, 3),
             "factorial": lambda: _full_factorial(k, (-1.0, 0.0, 1.0))}[kind]()
    centre, unit = rng.uniform(50, 150, k), rng.uniform(5, 9, k)
    path, names, _ = _plant(tmp_path, coded, centre, unit, seed, decimals=0)
    _print_factors_as_integers(path, names)
    out = tmp_path / "c.json"
    proc = _cli("criticize", "--data", str(path), "--factors", ",".join(names), "--response", "y", "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    family = {"ccd": "central composite", "box_behnken": "Box-Behnken", "factorial": "full factorial"}[kind]
    assert family in proc.stderr
    assert json.loads(out.read_text())["verdict"] == "adequate"  # the exact quadratic of the printed cells


def test_the_same_levels_printed_with_trailing_zeros_are_held_to_that_print(tmp_path):
    """The rounding allowed is the print's, read from the text: levels that are whole numbers but printed to
    nine decimals are not rounded, so a factorial level a unit off its place is refused."""
    coded = ccd_points(2, 1.41421, 5)
    path, names, _ = _plant(tmp_path, coded, np.array([107.4, 64.3]), np.array([5.9, 8.2]), seed=3, decimals=0)
    proc = _cli("fit", "--data", str(path), "--factors", "x1,x2", "--responses", "y", "--out", str(tmp_path / "f"))
    assert proc.returncode == 2 and "is not a level of the inferred" in proc.stderr, proc.stderr
    _print_factors_as_integers(path, names)
    proc = _cli("fit", "--data", str(path), "--factors", "x1,x2", "--responses", "y", "--out", str(tmp_path / "f"))
    assert proc.returncode == 0, proc.stderr


def test_a_slipped_cell_is_still_refused_where_levels_are_printed_to_few_digits(tmp_path):
    coded = ccd_points(2, 1.41421, 5)
    path, names, _ = _plant(tmp_path, coded, np.array([107.4, 64.3]), np.array([5.9, 8.2]), seed=3, decimals=0)
    _print_factors_as_integers(path, names)
    table = pd.read_csv(path)
    run = _set(table, table.x1 == table.x1.max(), "x1", table.x1.max() + 3)  # half a coded unit off its level
    path.write_text(table.to_csv(index=False))
    proc = _cli("fit", "--data", str(path), "--factors", "x1,x2", "--responses", "y", "--out", str(tmp_path / "f"))
    assert proc.returncode == 2 and re.search(rf"runs? (\d+ and )?{run}\b[^:]*, column 'x1'", proc.stderr), proc.stderr
