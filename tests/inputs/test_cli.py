"""The command line: contracts of `fit` and `validate`, and one-line errors with exit status 2."""

import json
from pathlib import Path

import pytest
import statsmodels.api as sm

from demid.design import model_matrix, quadratic_terms
from ..helpers import run_demid

ROOT = Path(__file__).resolve().parents[2]


def _run(*args, cwd=None):
    return run_demid(*args, cwd=cwd)


def test_fit_json_contract_matches_statsmodels(study_dir, tmp_path):
    out = tmp_path / "fit.json"
    proc = _run("fit", "--data", str(study_dir / "data" / "m.csv"), "--factors", "a,b", "--responses", "y1,y2",
                "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    result = json.loads(out.read_text())
    assert set(result) == {"y1", "y2"}
    for key in ["n_runs", "r2", "adj_r2", "rmse", "resid_std", "q2", "lof_f", "lof_p", "coefficients"]:
        assert key in result["y1"]
    import pandas as pd

    table = pd.read_csv(study_dir / "data" / "m.csv")
    ref = sm.OLS(table["y1"], model_matrix(table[["a", "b"]].to_numpy(), quadratic_terms(2))).fit()
    assert result["y1"]["r2"] == pytest.approx(ref.rsquared, rel=1e-9)
    names = ["Intercept", "a", "b", "a:b", "a^2", "b^2"]
    assert [result["y1"]["coefficients"][n] for n in names] == pytest.approx(ref.params.tolist(), rel=1e-6)
    assert result["y1"]["n_runs"] == 13


def test_validate_command(study_dir):
    proc = _run("validate", "--config", "study.yaml", cwd=study_dir)
    assert proc.returncode == 0, proc.stderr
    assert "m: data/m.csv OK (13 runs" in proc.stdout


def test_user_error_is_one_line_exit_2(study_dir):
    text = (study_dir / "study.yaml").read_text().replace("y2: {target: 95}", "y2: {target: 95, colour: red}")
    (study_dir / "study.yaml").write_text(text)
    proc = _run("validate", "--config", "study.yaml", cwd=study_dir)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    assert proc.stderr.strip().count("\n") == 0
    assert "materials.m.responses.y2" in proc.stderr and "colour" in proc.stderr


def test_check_transcription_cli_finds_planted_slip(tmp_path):
    from ..test_surrogate import MONTGOMERY

    table = MONTGOMERY.copy()
    table.loc[table["run"] == 4, "y"] = 97.5  # 79.5 with two digits transposed
    path = tmp_path / "m.csv"
    table.to_csv(path, index=False)
    out = tmp_path / "out.json"
    proc = _run("check-transcription", "--data", str(path), "--factors", "x1,x2", "--response", "y",
                "--published", "r2=0.9827,ss_model=28.25,ss_residual=0.50,ss_lof=0.28,ss_pure_error=0.21",
                "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    result = json.loads(out.read_text())
    assert {"consistent", "published", "reproduced", "suspects"} <= set(result)
    assert result["consistent"] is False
    top = result["suspects"][0]
    assert {"run", "column", "found", "suggested", "kind", "restores"} <= set(top)
    assert (top["run"], top["column"], top["suggested"], top["kind"]) == (4, "y", 79.5, "transposition")


def test_check_transcription_cli_consistent_exit_0(tmp_path):
    from ..test_surrogate import MONTGOMERY

    path = tmp_path / "m.csv"
    MONTGOMERY.to_csv(path, index=False)
    out = tmp_path / "out.json"
    proc = _run("check-transcription", "--data", str(path), "--factors", "x1,x2", "--response", "y",
                "--published", "r2=0.9827,ss_lof=0.28", "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    result = json.loads(out.read_text())
    assert result["consistent"] is True and result["suspects"] == []


@pytest.mark.parametrize("published", ["r2=98.27%,lof_p=>0.05", "r2=0.9827,lof_p=>=0.05", "r2=98.27 %"])
def test_check_transcription_cli_reads_bounds_and_percentages_as_the_config_does(tmp_path, published):
    from ..test_surrogate import MONTGOMERY

    path = tmp_path / "m.csv"
    MONTGOMERY.to_csv(path, index=False)
    out = tmp_path / "out.json"
    proc = _run("check-transcription", "--data", str(path), "--factors", "x1,x2", "--response", "y",
                "--published", published, "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    result = json.loads(out.read_text())
    assert result["consistent"] is True and result["published"]["r2"] == pytest.approx(0.9827)


@pytest.mark.parametrize("published, message", [
    ("r2=98.27", r"--published r2: 98.27 is not a possible R² .*written in percent\? 98.27 % is 0.9827"),
    ("lof_p=1.7", r"--published lof_p: 1.7 is not a possible lack-of-fit p-value"),
    ("r2=0.98,r2=0.99", r"--published: 'r2' is given twice \(0.98 and 0.99\)"),
    ("rr2=0.98", r"--published: unknown statistic 'rr2'; did you mean 'r2'\?"),
    ("lof_f=1,78", r"--published: 'lof_f=1,78' has a decimal comma; write lof_f=1\.78"),
    ("r2=0.98,rmse", r"--published: expected key=value, found 'rmse'"),
    ("rmse=1,234.5", r"--published: 'rmse=1,234\.5' has a thousands separator; write rmse=1234\.5"),
])
def test_check_transcription_cli_refuses_an_impossible_repeated_or_unknown_statistic(tmp_path, published, message):
    import re

    from ..test_surrogate import MONTGOMERY

    path = tmp_path / "m.csv"
    MONTGOMERY.to_csv(path, index=False)
    out = tmp_path / "out.json"
    proc = _run("check-transcription", "--data", str(path), "--factors", "x1,x2", "--response", "y",
                "--published", published, "--out", str(out))
    assert proc.returncode == 2 and re.search(message, proc.stderr), proc.stderr
    assert proc.stderr.count("\n") == 1 and not out.exists()


@pytest.mark.parametrize("extra, message", [
    (["--alpha", "-1"], r"--alpha: a CCD's axial distance is at least 1 \(1 is face-centred\), found -1"),
    (["--alpha", "0"], r"--alpha: a CCD's axial distance is at least 1"),
    (["--alpha", "inf"], r"--alpha: a CCD's axial distance is a finite number, found inf"),
    (["--alpha", "1.5", "--design", "box_behnken"], r"--alpha: only a ccd design has an axial distance"),
])
def test_fit_refuses_an_impossible_or_misplaced_alpha(tmp_path, extra, message):
    import re

    from ..test_surrogate import MONTGOMERY

    path = tmp_path / "m.csv"
    MONTGOMERY.to_csv(path, index=False)
    proc = _run("fit", "--data", str(path), "--factors", "x1,x2", "--responses", "y", *extra,
                "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2 and re.search(message, proc.stderr), proc.stderr
    assert "Traceback" not in proc.stderr and not (tmp_path / "o.json").exists()


def test_a_negative_published_rmse_is_refused(tmp_path):
    from ..test_surrogate import MONTGOMERY

    path = tmp_path / "m.csv"
    MONTGOMERY.to_csv(path, index=False)
    proc = _run("check-transcription", "--data", str(path), "--factors", "x1,x2", "--response", "y",
                "--published", "rmse=-0.01", "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2 and "--published rmse: -0.01 is not a possible RMSE (it cannot be negative)" in proc.stderr


@pytest.mark.parametrize("left_out", [13, 5])  # an axial run of e, an axial run of mu_r
def test_fit_and_criticize_code_a_table_with_a_run_left_out_as_the_whole_design(tmp_path, left_out):
    """A failed run left out must not move the coding: the coded coefficients are those of the same runs in
    the design's own coding (the centre and factorial half-ranges of the full CCD), exactly as validation
    codes them, and criticism reports the same quadratic."""
    import numpy as np
    import pandas as pd

    from demid.design_check import infer_coding

    source = pd.read_csv(ROOT / "data" / "ccd" / "poraver.csv")
    design = {"type": "ccd", "alpha": 1.41421}
    coding = infer_coding(source, ["e", "mu_r"], design, "poraver.csv")
    table = source[source["run"] != left_out]
    path = tmp_path / "left_out.csv"
    table.to_csv(path, index=False)
    coded = coding.to_coded(table[["e", "mu_r"]].to_numpy(dtype=float))
    ref = sm.OLS(table["aor"].to_numpy(), model_matrix(coded, quadratic_terms(2))).fit()
    out = tmp_path / "fit.json"
    proc = _run("fit", "--data", str(path), "--factors", "e,mu_r", "--responses", "aor", "--design", "ccd",
                "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    got = json.loads(out.read_text())["aor"]["coefficients_coded"]
    names = ["Intercept", "e", "mu_r", "e:mu_r", "e^2", "mu_r^2"]
    assert [got[n] for n in names] == pytest.approx(ref.params.tolist(), rel=1e-6)
    assert not np.allclose(coding.to_coded(table[["e", "mu_r"]].to_numpy(dtype=float)).mean(axis=0), 0)  # premise
    out = tmp_path / "crit.json"
    proc = _run("criticize", "--data", str(path), "--factors", "e,mu_r", "--response", "aor", "--design", "ccd",
                "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    fitted = {r["run"]: r["fitted"] for r in json.loads(out.read_text())["runs"]}
    assert [fitted[r] for r in table["run"]] == pytest.approx(ref.fittedvalues.tolist(), rel=1e-9)


@pytest.mark.parametrize("args, message", [
    (["criticize", "--factors", "e;mu_r", "--response", "aor"], r"'e;mu_r': separate the names with commas"),
    (["criticize", "--factors", "e,mu_r", "--response", "aor,shape"], r"--response: criticize takes one response"),
    (["fit", "--factors", "e,mu_r", "--responses", "aor,e"], r"'e' is given both as a factor and as a response"),
    (["fit", "--factors", ",", "--responses", "aor"], r"--factors: no column named"),
    (["check-transcription", "--factors", "e,mu_r", "--response", "aor", "--published", "R2=0.989"],
     r"unknown statistic 'R2'; did you mean 'r2'\?"),
])
def test_column_options_written_another_way_are_one_line(tmp_path, args, message):
    import re

    proc = _run(*args, "--data", str(ROOT / "data" / "ccd" / "poraver.csv"), "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and re.search(message, lines[0]), proc.stderr


@pytest.mark.parametrize("command", ["fit", "criticize"])
def test_out_naming_a_folder_names_the_folder(study_dir, tmp_path, command):
    """The error named the temporary file the result was written to, not the user's --out."""
    flag = "--responses" if command == "fit" else "--response"
    folder = tmp_path / "results"
    folder.mkdir()
    proc = _run(command, "--data", str(study_dir / "data" / "m.csv"), "--factors", "a,b", flag, "y1",
                "--out", str(folder))
    assert proc.returncode == 2
    assert proc.stderr.strip() == f"demid: error: {folder}: is a folder; name the file to write"
    assert list(folder.iterdir()) == []


def test_a_factor_left_out_of_factors_is_warned_about(study_dir, tmp_path):
    """--factors a on a table that varies a and b: runs at one level of a become 'replicates' and lack of fit
    is judged against b's effect.  The warning names b; a response left out (y2) is no factor."""
    data = str(study_dir / "data" / "m.csv")
    proc = _run("fit", "--data", data, "--factors", "a", "--responses", "y1", "--out", str(tmp_path / "f.json"))
    assert proc.returncode == 0, proc.stderr
    warnings = [ln for ln in proc.stderr.splitlines() if ln.startswith("demid: warning:")]
    assert len(warnings) == 1 and "column 'b'" in warnings[0] and "add it to --factors" in warnings[0], proc.stderr
    proc = _run("fit", "--data", data, "--factors", "a,b", "--responses", "y1", "--out", str(tmp_path / "f.json"))
    assert proc.returncode == 0 and "warning" not in proc.stderr, proc.stderr


def test_a_coded_copy_of_a_listed_factor_in_a_shuffled_file_is_no_left_out_factor(study_dir, tmp_path):
    """The file's rows were paired with the table's, which is in run order: in a file not in run order a
    column that only repeats a listed factor (a_coded) was said to vary between replicates."""
    import pandas as pd

    table = pd.read_csv(study_dir / "data" / "m.csv")
    centre, half = (table["a"].max() + table["a"].min()) / 2, (table["a"].max() - table["a"].min()) / 2
    table["a_coded"] = ((table["a"] - centre) / half).round(4)
    shuffled = table.sample(frac=1.0, random_state=3)
    path = tmp_path / "shuffled.csv"
    shuffled.to_csv(path, index=False)
    proc = _run("fit", "--data", str(path), "--factors", "a,b", "--responses", "y1", "--out", str(tmp_path / "f.json"))
    assert proc.returncode == 0 and "warning" not in proc.stderr, proc.stderr
    proc = _run("fit", "--data", str(path), "--factors", "a", "--responses", "y1", "--out", str(tmp_path / "f.json"))
    assert "column 'b'" in proc.stderr and "column 'a_coded'" not in proc.stderr, proc.stderr


def test_validate_counts_runs_by_what_they_are(tmp_path):
    """Point types where the design has them, 'custom design' where it has none, and failed runs apart."""
    from types import SimpleNamespace

    import numpy as np
    import pandas as pd

    from demid.cli import run_counts

    ccd = SimpleNamespace(table=pd.DataFrame({"run": range(1, 14)}), failed={},
                          summary=lambda _: {"point_types": {"axial": 4, "center": 5, "factorial": 4}})
    assert run_counts(ccd, "ccd", ["y"]) == "13 runs: 4 factorial, 4 axial, 5 centre"
    custom = SimpleNamespace(table=pd.DataFrame({"run": np.arange(1, 25)}), failed={"y": [3, 7], "z": [7]},
                             summary=lambda _: {"point_types": {"other": 24}})
    assert run_counts(custom, "custom", ["y", "z"]) == "24 runs (custom design); 22 complete, 1 failed, 1 with a response missing"
