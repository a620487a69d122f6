"""The validator's typo flag: extreme studentised residual + a digit slip that would fit."""

import pytest

from demid.data import read_printed, validate_material
from demid.transcription import likely_typos

from .helpers import make_ccd_table


def _cfg(path):
    return {"data": str(path), "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
            "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1, "upper": 11}},
            "responses": {"y": {}}}


@pytest.mark.parametrize("seed", range(5))
@pytest.mark.parametrize("slip", ["decimal", "transposition"])
def test_planted_slip_is_flagged_and_clean_table_is_silent(tmp_path, seed, slip):
    table = make_ccd_table(lambda x: {"y": 100 + 20 * x[:, 0] - 3 * x[:, 1] + 8 * x[:, 0] ** 2},
                           [0.1, 1], [0.9, 11], noise=0.3, seed=seed, decimals=2)
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    vt = validate_material("m", _cfg(path))
    assert likely_typos(vt, _cfg(path), read_printed(path, vt.table)) == []

    true_value = table.loc[table["run"] == 5, "y"].iloc[0]
    text = f"{true_value:.2f}"
    if slip == "decimal":
        typo = f"{true_value / 10:.3f}"
    else:  # swap the first two digits: 1xy.zz -> x1y.zz
        typo = text[1] + text[0] + text[2:]
        if typo == text:
            pytest.skip("identical digits")
    lines = path.read_text().splitlines()
    lines = [ln if not ln.startswith("5,") else ",".join(ln.split(",")[:-1] + [typo]) for ln in lines]
    path.write_text("\n".join(lines) + "\n")
    vt = validate_material("m", _cfg(path))
    flags = likely_typos(vt, _cfg(path), read_printed(path, vt.table))
    assert [(f["run"], f["column"]) for f in flags] == [(5, "y")]
    assert flags[0]["suggested"] == pytest.approx(true_value)
