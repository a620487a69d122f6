"""Every bad-input case: one clear line naming file/key, run and column; non-zero exit; no traceback;
the raw table untouched; no results written.  Run through Snakemake exactly as a user would."""

from __future__ import annotations

import re

import pytest

from ..workflow_helpers import run_snakemake, sha256, written_results

pytestmark = pytest.mark.workflow


def _set_cell(text: str, run: int, column: str, value: str) -> str:
    lines = text.splitlines()
    header = lines[0].split(",")
    col = header.index(column)
    for i, line in enumerate(lines[1:], start=1):
        cells = line.split(",")
        if cells[0] == str(run):
            cells[col] = value
            lines[i] = ",".join(cells)
    return "\n".join(lines) + "\n"


def _cell(text: str, run: int, column: str) -> str:
    lines = text.splitlines()
    col = lines[0].split(",").index(column)
    return next(ln.split(",")[col] for ln in lines[1:] if ln.split(",")[0] == str(run))


# (name, table mutation, config mutation, expected pieces of the one-line message)
def _misspelled(t, c):
    return t.replace("run,a,b,y1,y2", "run,a,b,y1,y_2"), c


def _non_numeric(t, c):
    return _set_cell(t, 4, "y1", "12x.5"), c


def _empty(t, c):
    return _set_cell(t, 6, "y2", ""), c


def _decimal_comma(t, c):
    return _set_cell(t, 3, "y1", '"101,5"'), c


def _duplicate_run(t, c):
    lines = t.splitlines()
    lines[2] = "1" + lines[2][lines[2].index(","):]
    return "\n".join(lines) + "\n", c


def _too_few(t, c):
    return "\n".join(t.splitlines()[:6]) + "\n", c


def _off_level(t, c):
    value = float(_cell(t, 5, "a"))
    return _set_cell(t, 5, "a", f"{value + 0.031:.4f}"), c


def _out_of_bounds(t, c):
    return t, c.replace("a: {lower: 0.1, upper: 0.9}", "a: {lower: 0.15, upper: 0.9}")


def _unknown_key(t, c):
    return t, c.replace("grid_points: 101", "grid_points: 101\ngrid_pionts: 5")


def _unknown_observable(t, c):
    return t, c.replace("observables: [y1, y2]", "observables: [y1, y3]")


def _no_target(t, c):
    return t, c.replace("y2: {target: 95}", "y2: {}")


def _bad_tolerance(t, c):
    return t, c.replace("tolerance: 0.02}\n      both", "tolerance: 0}\n      both")


def _tolerance_one(t, c):
    return t, c.replace("observables: [y1, y2], tolerance: 0.02", "observables: [y1, y2], tolerance: 1.5")


def _bounds_reversed(t, c):
    return t, c.replace("b: {lower: 1.0, upper: 11.0}", "b: {lower: 11.0, upper: 1.0}")


def _limit_inside_range(t, c):
    return t, c.replace("a: {lower: 0.1, upper: 0.9}", "a: {lower: 0.1, upper: 0.9, limits: {lower: 0, upper: 0.8}}")


def _missing_file(t, c):
    return t, c.replace("data: data/m.csv", "data: data/missing.csv")


def _repeated_key(t, c):
    return t, c.replace("      y2: {target: 95}\n", "      y2: {target: 95}\n      y1: {target: 120}\n")


def _missing_published(t, c):
    return t, "published: paper_numbers.yaml\n" + c


CASES = [
    ("misspelled column", _misspelled, [r"data/m\.csv", r"column 'y2'", r"y_2"]),
    ("non-numeric cell", _non_numeric, [r"data/m\.csv", r"run 4", r"column 'y1'", r"12x\.5"]),
    ("empty cell", _empty, [r"data/m\.csv", r"run 6", r"column 'y2'", r"empty cell"]),
    ("decimal comma", _decimal_comma, [r"data/m\.csv", r"run 3", r"column 'y1'", r"101,5", r"decimal point"]),
    ("duplicate run", _duplicate_run, [r"data/m\.csv", r"run 1", r"column 'run'", r"duplicate"]),
    ("too few runs", _too_few, [r"data/m\.csv", r"column 'y1'", r"usable runs"]),
    ("off-level factor", _off_level, [r"data/m\.csv", r"run 5", r"column 'a'", r"nearest valid level"]),
    ("outside bounds", _out_of_bounds, [r"data/m\.csv", r"run \d+", r"column 'a'", r"outside the declared bounds"]),
    ("unknown config key", _unknown_key, [r"study\.yaml", r"grid_pionts"]),
    ("unknown observable", _unknown_observable, [r"study\.yaml", r"materials\.m\.scenarios\.both", r"y3"]),
    ("observable without target", _no_target, [r"study\.yaml", r"observable 'y2' has no target"]),
    ("tolerance zero", _bad_tolerance, [r"study\.yaml", r"materials\.m\.scenarios\.y1_only\.tolerance"]),
    ("tolerance above one", _tolerance_one, [r"study\.yaml", r"materials\.m\.scenarios\.both\.tolerance"]),
    ("bounds reversed", _bounds_reversed, [r"study\.yaml", r"materials\.m\.factors\.b", r"lower"]),
    ("physical limit inside the range", _limit_inside_range, [r"config key materials\.m\.factors\.a\.limits\.upper",
                                                              r"0\.8 is below the search range's upper bound 0\.9"]),
    ("missing data file", _missing_file, [r"study\.yaml", r"materials\.m\.data", r"missing\.csv",
                                          r"looked for /\S+/data/missing\.csv"]),
    ("repeated config key", _repeated_key, [r"study\.yaml", r"line 12: key 'y1' is given twice", r"first at line 10"]),
    ("missing published file", _missing_published, [r"study\.yaml", r"config key published",
                                                     r"paper_numbers\.yaml' does not exist"]),
]


@pytest.mark.parametrize("name,mutate,expected", CASES, ids=[c[0] for c in CASES])
def test_bad_input_is_one_clear_line(study_dir, name, mutate, expected):
    table_path = study_dir / "data" / "m.csv"
    config_path = study_dir / "study.yaml"
    table, config = mutate(table_path.read_text(encoding="utf-8"), config_path.read_text(encoding="utf-8"))
    table_path.write_text(table, encoding="utf-8")
    config_path.write_text(config, encoding="utf-8")
    before = sha256(table_path)
    proc = run_snakemake(study_dir, config_path)
    output = proc.stdout + proc.stderr
    assert proc.returncode != 0, output
    assert "Traceback" not in output
    lines = [ln for ln in output.splitlines() if ln.startswith("demid: error:")]
    assert len(lines) == 1, output
    for pattern in expected:
        assert re.search(pattern, lines[0]), (pattern, lines[0])
    assert sha256(table_path) == before
    assert not written_results(study_dir / "results")


def _error_lines(proc) -> list[str]:
    return [ln for ln in (proc.stdout + proc.stderr).splitlines() if ln.startswith("demid: error:")]


def test_cells_are_checked_once_in_the_job_and_the_header_at_start_up(study_dir):
    """Start-up (dry runs too) reads each table's header only; the cells are validated in the material's job,
    whose one line reaches the terminal and the job's log."""
    table_path, config = study_dir / "data" / "m.csv", study_dir / "study.yaml"
    text = table_path.read_text(encoding="utf-8")
    table_path.write_text(_set_cell(text, 4, "y1", "12x.5"), encoding="utf-8")
    dry = run_snakemake(study_dir, config, "-n")
    assert dry.returncode == 0 and not _error_lines(dry), dry.stderr[-2000:]
    proc = run_snakemake(study_dir, config)
    lines = _error_lines(proc)
    assert proc.returncode != 0 and "Traceback" not in proc.stdout + proc.stderr
    assert len(lines) == 1 and re.search(r"data/m\.csv, run 4, column 'y1'.*12x\.5", lines[0]), lines
    log = (study_dir / "results" / "logs" / "analyse_material" / "m.log").read_text(encoding="utf-8")
    assert log.splitlines() == lines
    assert not written_results(study_dir / "results")
    table_path.write_text(text.replace("run,a,b,y1,y2", "run,a,b,y1,y_2"), encoding="utf-8")
    dry = run_snakemake(study_dir, config, "-n")
    lines = _error_lines(dry)
    assert dry.returncode != 0 and len(lines) == 1 and "column 'y2'" in lines[0] and "y_2" in lines[0], lines
