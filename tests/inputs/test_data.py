"""Table reading and design checks at the unit level (the workflow-level cases are in test_bad_input)."""

import numpy as np
import pytest

from demid.csv_cells import parse_number
from demid.data import read_table, validate_material
from demid.errors import InputError
from demid.spec import MaterialSpec

from ..helpers import make_ccd_table


def _material(path, **extra):
    cfg = {"data": str(path), "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
           "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1.0, "upper": 11.0}},
           "responses": {"y": {"target": 10.0}}, "status_column": "status"}
    cfg.update(extra)
    return cfg


@pytest.fixture
def table_path(tmp_path):
    table = make_ccd_table(lambda x: {"y": 5 + x[:, 0] + x[:, 1] ** 2}, [0.1, 1.0], [0.9, 11.0], noise=0.1, seed=4)
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    return path


def test_bom_and_unicode_minus_are_read(table_path):
    text = table_path.read_text(encoding="utf-8")
    lines = text.splitlines()
    cells = lines[1].split(",")
    cells[-1] = "\u2212" + cells[-1]  # a Unicode minus, as copied from a PDF
    lines[1] = ",".join(cells)
    table_path.write_bytes(b"\xef\xbb\xbf" + ("\n".join(lines) + "\n").encode("utf-8"))
    table, warnings = read_table(table_path, ["x1", "x2"], ["y"])
    assert list(table.columns[:4]) == ["run", "x1", "x2", "y"]
    assert table.loc[table["run"] == int(cells[0]), "y"].iloc[0] < 0
    assert warnings == []


def test_semicolon_table_with_decimal_commas_is_named(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("run;x1;x2;y\n1;0,5;1;2\n", encoding="utf-8")
    with pytest.raises(InputError, match=r"t\.csv, run 1, column 'x1': found '0,5', a decimal comma"):
        read_table(path, ["x1", "x2"], ["y"])


def test_parse_number_messages():
    assert parse_number(" \u22121.5 ") == -1.5
    with pytest.raises(ValueError, match="expected a number"):
        parse_number("abc")


def test_failed_run_with_status_column_is_excluded_with_warning(table_path):
    import pandas as pd

    table = pd.read_csv(table_path)
    table["status"] = "ok"
    table.loc[table["run"] == 3, ["y", "status"]] = [np.nan, "failed"]
    table.to_csv(table_path, index=False)
    vt = validate_material(MaterialSpec.from_material("m", _material(table_path)))
    assert vt.failed == {"y": [3]}
    assert any("run(s) 3 excluded" in w for w in vt.warnings)


def test_failed_centre_runs_report_lost_pure_error(table_path):
    import pandas as pd

    table = pd.read_csv(table_path)
    table["status"] = "ok"
    centre = table[(table["x1"] == 0.5) & (table["x2"] == 6.0)]["run"].tolist()
    table.loc[table["run"].isin(centre[:4]), ["y", "status"]] = [np.nan, "failed"]
    table.to_csv(table_path, index=False)
    vt = validate_material(MaterialSpec.from_material("m", _material(table_path)))
    assert any("pure error is no longer available" in w for w in vt.warnings)


def test_wrong_centre_run_count_names_config_key(table_path):
    cfg = _material(table_path)
    cfg["design"]["center_runs"] = 4
    with pytest.raises(InputError, match=r"materials\.m\.design\.center_runs: expected 4 centre run"):
        validate_material(MaterialSpec.from_material("m", cfg))


def test_log_scale_factor_design(tmp_path):
    gamma = np.array([0.001, 0.1])
    table = make_ccd_table(lambda x: {"y": 3 + x[:, 0] + x[:, 1]}, [0.1, np.log10(gamma[0])], [0.9, np.log10(gamma[1])],
                           noise=0.01, seed=1)
    table["x2"] = 10 ** table["x2"]
    path = tmp_path / "log.csv"
    table.to_csv(path, index=False)
    cfg = _material(path)
    cfg["factors"]["x2"] = {"lower": 0.001, "upper": 0.1, "scale": "log"}
    vt = validate_material(MaterialSpec.from_material("m", cfg))
    assert vt.coding.center[1] == pytest.approx(-2.0)
    assert sorted(set(vt.point_types)) == ["axial", "center", "factorial"]
    coded = vt.to_frame()["coded:x2"].to_numpy()  # coded in log10 units: levels 0, +-1, +-alpha
    assert np.min(np.abs(coded[:, None] - np.array([-1.41421, -1, 0, 1, 1.41421])), axis=1).max() < 1e-3
