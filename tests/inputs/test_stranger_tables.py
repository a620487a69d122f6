"""Tables and configs nobody here made: valid designs pass, every bad input is one clear line."""

from __future__ import annotations

import itertools
import json
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from demid.config import load_config, validate_schema
from demid.data import read_table, validate_material
from demid.design import ccd_points, model_matrix, quadratic_terms
from demid.errors import InputError
from demid.spec import MaterialSpec
from ..helpers import run_demid

REPO = Path(__file__).resolve().parents[2]


def _write_design(tmp_path, coded, lower, upper, design, seed=0, alpha=None, name="t.csv", extra_cols=None):
    """Actual-unit table from coded points; the outermost coded level maps onto the bounds."""
    rng = np.random.default_rng(seed)
    coded = np.asarray(coded, float)
    k = coded.shape[1]
    reach = np.abs(coded).max()
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    centre, unit = (lower + upper) / 2, (upper - lower) / (2 * reach)
    actual = coded * unit + centre
    beta = rng.normal(0, 3, len(quadratic_terms(k)))
    beta[0] = 50
    y = model_matrix(coded, quadratic_terms(k)) @ beta + 0.2 * rng.standard_normal(len(coded))
    order = rng.permutation(len(coded))
    names = [f"x{i + 1}" for i in range(k)]
    lines = ["run," + ",".join(names) + ",y"]
    for run, i in enumerate(order, start=1):
        lines.append(f"{run}," + ",".join(f"{v:.6f}" for v in actual[i]) + f",{y[i]:.3f}")
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    cfg = {"data": str(path), "design": design,
           "factors": {f: {"lower": float(lo), "upper": float(hi)} for f, lo, hi in zip(names, lower, upper)},
           "responses": {"y": {}}}
    return cfg, coded[order], unit, centre


def _full_factorial(k, levels):
    return np.array(list(itertools.product(levels, repeat=k)), dtype=float)


CASES = {
    "3x3 factorial": (_full_factorial(2, [-1, 0, 1]), {"type": "factorial", "center_runs": 1}),
    "3x3x3 factorial": (_full_factorial(3, [-1, 0, 1]), {"type": "factorial", "center_runs": 1}),
    "face-centred CCD, one centre run": (ccd_points(2, 1.0, 1), {"type": "ccd", "alpha": 1.0, "center_runs": 1}),
    "face-centred 3-factor CCD, one centre run": (ccd_points(3, 1.0, 1),
                                                  {"type": "ccd", "alpha": 1.0, "center_runs": 1}),
    "3-factor CCD, one centre run": (ccd_points(3, 1.68179, 1), {"type": "ccd", "alpha": 1.68179, "center_runs": 1}),
    "3-factor CCD, two centre runs": (ccd_points(3, 1.68179, 2), {"type": "ccd", "alpha": 1.68179, "center_runs": 2}),
    "4-factor CCD, one centre run": (ccd_points(4, 2.0, 1), {"type": "ccd", "alpha": 2.0, "center_runs": 1}),
    "4-factor CCD, two centre runs": (ccd_points(4, 2.0, 2), {"type": "ccd", "alpha": 2.0, "center_runs": 2}),
    "5-factor CCD, two centre runs": (ccd_points(5, 2.37841, 2), {"type": "ccd", "alpha": 2.37841, "center_runs": 2}),
    "6-factor CCD, one centre run": (ccd_points(6, 2.82843, 1), {"type": "ccd", "alpha": 2.82843, "center_runs": 1}),
    "2-factor CCD, two centre runs": (ccd_points(2, 1.41421, 2), {"type": "ccd", "alpha": 1.41421, "center_runs": 2}),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_valid_designs_validate_and_are_coded_by_their_geometry(tmp_path, case):
    coded, design = CASES[case]
    k = coded.shape[1]
    lower = np.linspace(0.1, 2.0, k)
    cfg, coded_order, unit, centre = _write_design(tmp_path, coded, lower, lower * 7 + 1, design, seed=k)
    vt = validate_material(MaterialSpec.from_material("m", cfg))
    # the coding recovers the design's own coded points (factorial points at +-1, centre at 0)
    got = vt.coding.to_coded(vt.table[list(cfg["factors"])].to_numpy())
    assert np.allclose(got, coded_order[np.argsort(np.arange(len(coded_order)))], atol=1e-4)
    assert int(np.sum(vt.point_types == "center")) == design["center_runs"]


def test_mistyped_factor_cell_is_located_not_absorbed_into_the_coding(tmp_path):
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(3, 1.68179, 1), [0.1, 1, 10], [0.5, 5, 50],
                                 {"type": "ccd", "alpha": 1.68179, "center_runs": 1})
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    cells = lines[4].split(",")
    cells[2] = f"{float(cells[2]) * 1.1:.6f}"  # off every level, still inside the bounds
    lines[4] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match=r"run 4, column 'x2': value 3\.3 is not a level of the declared ccd design "
                                         r"\(coded \+0\.252\); nearest valid level: 3 \(coded \+0\)$"):
        validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("k,alpha", [(2, 1.41421), (3, 1.73205), (3, 1.68179), (2, 1.0)])
def test_ccd_whose_centre_runs_all_failed_is_refused(tmp_path, k, alpha):
    # On the sphere the intercept cannot be estimated; off it (rotatable 3-factor, face-centred) it would
    # be extrapolated to the centre from runs at radius >= 1.
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(k, alpha, 3), [0.1] * k, [0.9] * k,
                                 {"type": "ccd", "alpha": alpha, "center_runs": 3})
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    out = [lines[0] + ",status"]
    for line in lines[1:]:
        cells = line.split(",")
        centre = all(abs(float(v) - 0.5) < 1e-9 for v in cells[1:1 + k])
        out.append(",".join(cells[:-1] + ["", "failed"]) if centre else line + ",ok")
    path.write_text("\n".join(out) + "\n")
    spherical = abs(alpha - np.sqrt(k)) < 1e-3
    message = (r"cannot be estimated.*all 3 centre run\(s\) failed\); at least" if spherical else
               r"cannot be trusted: all 3 centre run\(s\) failed, so its value at the design centre would be "
               r"extrapolated")
    with pytest.raises(InputError, match=r"column 'y': the quadratic model " + message):
        validate_material(MaterialSpec.from_material("m", cfg))


def _tiny(tmp_path, rows, header="run,x1,x2,y,status"):
    path = tmp_path / "t.csv"
    path.write_text(header + "\n" + "\n".join(rows) + "\n")
    return path


def test_failed_run_with_a_value_left_in_its_cell_is_an_error(tmp_path):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok", "2,0.2,2,7.5,failed", "3,0.3,3,,failed"])
    with pytest.raises(InputError, match=r"t\.csv, run 2, column 'y': the run is marked 'failed' in column "
                                         r"'status' but this cell holds '7.5'"):
        read_table(path, ["x1", "x2"], ["y"])


def test_partial_failure_is_written_as_nan_with_status_ok(tmp_path):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok", "2,0.2,2,NaN,ok"])
    table, warnings = read_table(path, ["x1", "x2"], ["y"])
    assert np.isnan(table.loc[table["run"] == 2, "y"].iloc[0]) and "treated as a failed simulation" in warnings[0]


def test_ambiguous_thousands_separator_is_not_silently_read_as_decimal_comma(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text('run;x1;x2;y\n1;0.1;1;4,576\n')
    with pytest.raises(InputError) as err:
        read_table(path, ["x1", "x2"], ["y"])
    message = str(err.value)
    assert "run 1, column 'y'" in message and "thousands separator (4576)" in message
    assert "decimal comma (4.576)" in message
    path.write_text('run;x1;x2;y\n1;0.1;1;4,57\n')  # not ambiguous: a decimal comma
    with pytest.raises(InputError, match=r"a decimal comma; expected a decimal point, e\.g\. '4\.57'"):
        read_table(path, ["x1", "x2"], ["y"])


def test_a_header_with_a_repeated_name_names_the_repeat_and_the_missing_column(tmp_path):
    """d5,d10,d10 for d5,d10,d15: the repeat is the slip; 'd5', a column of its own, is no misspelling."""
    path = _tiny(tmp_path, ["1,0.1,1,5.0,6.0,7.0"], header="run,x1,x2,d5,d10,d10")
    with pytest.raises(InputError, match=r"t\.csv, column 'd10': column appears more than once in the header; "
                                         r"'d15' is missing: is one of them 'd15'\?$"):
        read_table(path, ["x1", "x2"], ["d5", "d10", "d15"])
    path = _tiny(tmp_path, ["1,0.1,1,5.0,6.0,7.0"], header="run,x1,x2,d5,d10,d1")
    with pytest.raises(InputError, match=r"column 'd15': missing column .*; found 'd1' — misspelled\?$"):
        read_table(path, ["x1", "x2"], ["d5", "d10", "d15"])


@pytest.mark.parametrize("cell", ["1_29.3", "12_9.3", "_129.3"])
def test_a_number_with_an_underscore_is_refused(tmp_path, cell):
    """Python reads 1_29.3 as 129.3; a table cell with an underscore is a slip, not a number."""
    path = _tiny(tmp_path, [f"1,0.1,1,{cell},ok"])
    with pytest.raises(InputError, match=rf"run 1, column 'y': .*found '{cell}', a number with an underscore"):
        read_table(path, ["x1", "x2"], ["y"])


def test_line_numbers_count_comment_and_blank_lines(tmp_path):
    path = _tiny(tmp_path, ["# measured 2024-03-01", "1,0.1,1,5.0,ok", "", "# second batch", "2,0.2,2,7.5"])
    with pytest.raises(InputError, match=r"line 6 has 4 cells, the header has 5"):
        read_table(path, ["x1", "x2"], ["y"])
    path = _tiny(tmp_path, ["# note", "1,0.1,1,5.0,ok", "# note", "1,0.2,2,7.5,ok"])
    with pytest.raises(InputError, match=r"duplicate run number \(lines 3 and 5\)"):
        read_table(path, ["x1", "x2"], ["y"])


# ----------------------------------------------------------------------------- config checks
def _demo_config():
    return yaml.safe_load((REPO / "config.yaml").read_text(encoding="utf-8"))


def test_numbers_written_1e_minus_6_are_read_as_numbers():
    raw = _demo_config()
    raw["materials"]["poraver"]["responses"]["aor"]["sigma"] = "1e-6"
    raw["grid_points"] = "1e3"
    checked = validate_schema(raw)
    assert checked["materials"]["poraver"]["responses"]["aor"]["sigma"] == 1e-6
    assert checked["grid_points"] == 1000 and isinstance(checked["grid_points"], int)
    raw["materials"]["poraver"]["responses"]["aor"]["sigma"] = "about 1e-6"
    with pytest.raises(InputError, match="responses.aor.sigma"):
        validate_schema(raw)


def _load(tmp_path, mutate, encoding="utf-8"):
    raw = _demo_config()
    mutate(raw)
    path = tmp_path / "c.yaml"
    path.write_text(yaml.safe_dump(raw, allow_unicode=True), encoding=encoding, errors="replace")
    return load_config(path, base_dir=REPO)


def test_cp1252_config_is_one_clear_line(tmp_path):
    with pytest.raises(InputError, match=r"c\.yaml: not UTF-8 text \(byte \d+\); save it as UTF-8"):
        _load(tmp_path, lambda c: None, encoding="cp1252")


@pytest.mark.parametrize("key,value,match", [
    ("grid_points", 20001, r"grid_points: .*20001 is greater than the maximum of 4096"),
    ("grid_points", 10 ** 7, r"grid_points: .*greater than the maximum"),
    ("grid_points_3d", 400, r"grid_points_3d: .*greater than the maximum of 256"),
])
def test_grid_sizes_beyond_memory_are_rejected(tmp_path, key, value, match):
    with pytest.raises(InputError, match=match):
        _load(tmp_path, lambda c: c.update({key: value}))


def test_material_grid_override_beyond_memory_is_rejected(tmp_path):
    def mutate(c):
        c["materials"]["paste"]["grid_points"] = 300  # 3 factors: 27 million points
    with pytest.raises(InputError, match=r"materials\.paste\.grid_points: 300 gives 27,000,000 evaluation points"):
        _load(tmp_path, mutate)


@pytest.mark.parametrize("value", ["", "  ", "/"])
def test_results_dir_cannot_be_empty_or_root(tmp_path, value):
    with pytest.raises(InputError, match="results_dir"):
        _load(tmp_path, lambda c: c.update({"results_dir": value}))


def test_pareto_needs_two_different_responses(tmp_path):
    def mutate(c):
        c["materials"]["paste"]["pareto"] = {"error_of": "D", "minimise": "D", "max_error": 0.02}
    with pytest.raises(InputError, match=r"materials\.paste\.pareto: error_of and minimise are both 'D'"):
        _load(tmp_path, mutate)


@pytest.mark.parametrize("where,label", [
    (("factors", "mu_r", "label"), r"$\mu_{r$"),
    (("responses", "d5", "unit"), r"$\mathrm{mm$"),
    (("responses", "d10", "label"), r"$d_{10} \alpah$"),
    (("factors", "mu_r", "label"), "x^"),            # demid typesets ^ and _ itself: no $ needed to fail
    (("responses", "d5", "label"), "a^b^c"),
    (("factors", "gamma", "label"), "T_^"),
])
def test_mathtext_typo_in_a_label_names_the_config_key(tmp_path, where, label):
    def mutate(c):
        c["materials"]["mortar"][where[0]][where[1]][where[2]] = label
    key = re.escape(f"materials.mortar.{'.'.join(where)}")
    with pytest.raises(InputError, match=rf"config key {key}: .* is not valid matplotlib mathtext"):
        _load(tmp_path, mutate)


def test_material_without_scenarios_is_refused_at_validation(tmp_path):
    with pytest.raises(InputError, match=r"materials\.mortar\.scenarios: no scenario; .*observables: \[d"):
        _load(tmp_path, lambda c: c["materials"]["mortar"].pop("scenarios"))


def test_valid_mathtext_and_dollar_free_labels_pass(tmp_path):
    def mutate(c):
        c["materials"]["mortar"]["factors"]["mu_r"]["label"] = r"$\mu_{r}$ (M)"
        c["materials"]["mortar"]["responses"]["d5"]["unit"] = "US$ 5"
    assert "mortar" in _load(tmp_path, mutate)["materials"]


def test_readme_example_config_validates_on_the_shipped_table(tmp_path):
    text = (REPO / "README.md").read_text(encoding="utf-8")
    block = re.search(r"```yaml\n(.*?)```", text, re.S).group(1)
    path = tmp_path / "readme.yaml"
    path.write_text(block, encoding="utf-8")
    config = load_config(path, base_dir=REPO)
    for name, mat in config["materials"].items():
        validate_material(MaterialSpec.from_material(name, mat), base_dir=REPO)


# ----------------------------------------------------------------------------- command line
def _cli(*args, cwd=None):
    return run_demid(*args, cwd=cwd)


def test_criticize_refuses_a_factor_at_two_levels(tmp_path):
    coded = _full_factorial(2, [-1, 1])
    coded = np.vstack([coded, coded, [[0, -1], [0, 1]]])  # x1 never at a third level among 10 runs
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1, 1], [0.9, 9], {"type": "custom"})
    proc = _cli("criticize", "--data", cfg["data"], "--factors", "x1,x2", "--response", "y",
                "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2
    assert "cannot be estimated (rank 5 of 6 terms)" in proc.stderr


def test_criticize_and_fit_refuse_a_saturated_fit(tmp_path):
    coded = ccd_points(2, 1.41421, 0)[:6]  # 4 factorial + 2 axial runs: 6 runs for 6 coefficients
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1, 1], [0.9, 9], {"type": "custom"})
    for command in (["criticize", "--response", "y"], ["fit", "--responses", "y"]):
        proc = _cli(*command, "--data", cfg["data"], "--factors", "x1,x2", "--out", str(tmp_path / "o.json"))
        assert proc.returncode == 2, proc.stderr
        assert re.fullmatch(r"demid: error: .*t\.csv, column 'y': only 6 usable runs for a quadratic model with 6 "
                            r"coefficients.*saturated.*\n", proc.stderr)
        assert not (tmp_path / "o.json").exists()


def test_criticize_refuses_a_rank_deficient_fit(tmp_path):
    coded = ccd_points(2, 1.41421, 0)  # rotatable CCD without centre runs: every run on one circle
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1, 1], [0.9, 9], {"type": "custom"})
    proc = _cli("criticize", "--data", cfg["data"], "--factors", "x1,x2", "--response", "y",
                "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2
    assert "cannot be estimated: every usable run lies at the same distance from the design centre" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert not (tmp_path / "o.json").exists()


def test_fit_and_criticize_accept_design(tmp_path):
    coded = _full_factorial(2, [-1, 0, 1])
    coded = np.vstack([coded, np.zeros((2, 2))])  # 3x3 factorial plus two more centre runs
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1, 1], [0.9, 9], {"type": "factorial"})
    out = tmp_path / "fit.json"
    proc = _cli("fit", "--data", cfg["data"], "--factors", "x1,x2", "--responses", "y", "--design", "factorial",
                "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    coef = json.loads(out.read_text())["y"]["coefficients_coded"]
    # factorial coding: the table's extremes are at +-1, so the coded quadratic equals the generator's
    rng = np.random.default_rng(0)  # the generator's seed in _write_design
    beta = rng.normal(0, 3, 6)
    beta[0] = 50
    assert coef["x1^2"] == pytest.approx(beta[4], abs=0.6) and coef["x1:x2"] == pytest.approx(beta[3], abs=0.6)
    out = tmp_path / "crit.json"
    proc = _cli("criticize", "--data", cfg["data"], "--factors", "x1,x2", "--response", "y", "--design", "factorial",
                "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    assert out.exists()


def test_one_factor_study_is_refused_at_validation(tmp_path):
    def mutate(c):
        del c["materials"]["mortar"]["factors"]["gamma"]
        del c["materials"]["mortar"]["reference_point"]
    with pytest.raises(InputError, match=r"config key materials\.mortar\.factors: only one factor \('mu_r'\); "
                                         r"demid needs at least two"):
        _load(tmp_path, mutate)


def test_material_without_any_target_is_refused_at_validation(tmp_path):
    def mutate(c):
        c["materials"] = {"paste": c["materials"]["paste"]}
        del c["materials"]["paste"]["responses"]["D"]["target"]
        del c["materials"]["paste"]["scenarios"]
        del c["materials"]["paste"]["pareto"]
    with pytest.raises(InputError, match=r"config key materials\.paste\.responses: no response has a target"):
        _load(tmp_path, mutate)


# ----------------------------------------------------------------------------- slips in the config
@pytest.mark.parametrize("bound, value", [("upper", 9.24264), ("upper", 92.4264), ("lower", 0.75736),
                                          ("lower", -0.075736)])
def test_a_search_bound_one_slip_from_the_runs_extreme_is_refused(tmp_path, bound, value):
    """A bound beyond the runs that a shifted point, swapped digits or a lost sign turn into the runs'
    own extreme value is a slip in the config: one line naming the key and the value it looks like."""
    if value > 0.924264 or value < 0.075736:
        config = _load(tmp_path, lambda c: c["materials"]["poraver"]["factors"]["e"].update({bound: value}))
        with pytest.raises(InputError, match=rf"materials\.poraver\.factors\.e\.{bound}: {value:g} lies beyond the "
                                             rf"runs.*looks like {0.924264 if bound == 'upper' else 0.075736:g}"):
            validate_material(MaterialSpec.from_material("poraver", config["materials"]["poraver"]), base_dir=REPO)
    else:  # a bound inside the runs is the runs-outside-bounds error, located at the run
        config = _load(tmp_path, lambda c: c["materials"]["poraver"]["factors"]["e"].update({bound: value}))
        with pytest.raises(InputError, match="outside the declared bounds"):
            validate_material(MaterialSpec.from_material("poraver", config["materials"]["poraver"]), base_dir=REPO)


def test_a_deliberately_wider_search_range_is_accepted_and_warned_about(tmp_path):
    path = tmp_path / "c.yaml"
    raw = _demo_config()
    raw["materials"] = {"poraver": raw["materials"]["poraver"]}
    raw["materials"]["poraver"]["data"] = str(REPO / raw["materials"]["poraver"]["data"])
    raw["published"] = str(REPO / raw["published"])
    raw["materials"]["poraver"]["factors"]["e"]["upper"] = 1.0
    path.write_text(yaml.safe_dump(raw, allow_unicode=True), encoding="utf-8")
    run = _cli("validate", "--config", str(path))
    assert run.returncode == 0, run.stderr
    assert "search range of e, 0.07574 to 1, reaches beyond the runs" in run.stderr


@pytest.mark.parametrize("target, looks_like", [(264.0, "26.4 with the decimal point shifted"),
                                                (-26.4, "26.4 with its sign lost"),
                                                (2640.0, "26.4 with the decimal point shifted"),
                                                (900.0, None),
                                                # a mistyped digit (29, 39 or 49) is no slip a target is known by
                                                (99.0, None)])
def test_a_target_far_outside_every_simulated_value_is_said_before_the_run(tmp_path, target, looks_like):
    from demid.data import far_target_warnings

    poraver = MaterialSpec.from_material("poraver", _demo_config()["materials"]["poraver"])
    table = validate_material(poraver, base_dir=REPO).table
    assert far_target_warnings(table, {"aor": 26.4, "shape": 154.75}, "t.csv") == []  # the demo's targets: silent
    (warning,) = far_target_warnings(table, {"aor": target, "shape": 154.75}, "t.csv")
    assert f"t.csv, column 'aor': the target {target:g} lies far outside every simulated value" in warning
    if looks_like:
        assert f"looks like {looks_like}" in warning
    else:
        assert "looks like" not in warning and "discrepancy" in warning
    assert far_target_warnings(table, {"aor": 60.0}, "t.csv") == []  # beyond the runs, by less than their spread
    # validation itself carries it (the validation summary, the report and demid validate show it)
    config = _load(tmp_path, lambda c: c["materials"]["poraver"]["responses"]["aor"].update({"target": target}))
    src = config["materials"]["poraver"]["data"]
    (keyed,) = far_target_warnings(table, {"aor": target}, src, "poraver")
    assert "(config key materials.poraver.responses.aor.target)" in keyed
    poraver = MaterialSpec.from_material("poraver", config["materials"]["poraver"])
    assert keyed in validate_material(poraver, base_dir=REPO).warnings


@pytest.mark.parametrize("scale", [1e-3, 1e3, 1e-6])
def test_a_target_in_another_unit_names_the_key_and_the_power_of_ten(scale):
    """1.505 (g cm^-3) for 1505 (kg m^-3): the key and the repair, ×1000 → inside the simulated range."""
    from demid.data import far_target_warnings, implausible_targets

    table = pd.DataFrame({"rho": [1474.0, 1490.0, 1505.0, 1521.0, 1534.0]})
    (warning,) = far_target_warnings(table, {"rho": 1505.0 * scale}, "m.csv", "m")
    assert "config key materials.m.responses.rho.target" in warning
    factor = f"×{1 / scale:g}" if scale < 1 else f"÷{scale:g}"
    assert f"repair: {factor} → 1505 lies inside the simulated range (1474 to 1534)" in warning
    assert implausible_targets(table, {"rho": 1505.0}) == {}
    assert implausible_targets(table, {"rho": 1700.0})["rho"]["factor"] is None  # far, but no power of ten


@pytest.mark.parametrize("where", ["scenario", "sweep"])
def test_a_tolerance_written_in_percent_gets_the_fraction_as_hint(where):
    raw = _demo_config()
    if where == "scenario":
        raw["materials"]["poraver"]["scenarios"]["aor_only"]["tolerance"] = 5
        key = r"materials\.poraver\.scenarios\.aor_only\.tolerance"
    else:
        raw["sweep_tolerances"] = [0.01, 2.5]
        key = r"sweep_tolerances\.1"
    with pytest.raises(InputError, match=rf"config key {key}: .*; tolerances are fractions: .* % is 0\.0\d+$"):
        validate_schema(raw)
    raw["robust_z"] = 0  # other range errors get no tolerance hint
    raw["materials"]["poraver"]["scenarios"]["aor_only"]["tolerance"] = 0.01
    raw["sweep_tolerances"] = [0.01]
    with pytest.raises(InputError) as err:
        validate_schema(raw)
    assert "tolerances are fractions" not in str(err.value)


def test_a_response_with_the_same_value_in_every_run_is_warned_about(tmp_path):
    table = (REPO / "data/ccd/poraver.csv").read_text(encoding="utf-8").splitlines()
    header = table[0].split(",")
    col = header.index("shape")
    rows = [",".join(v if i != col else "150" for i, v in enumerate(line.split(","))) for line in table[1:]]
    path = tmp_path / "t.csv"
    path.write_text("\n".join([table[0], *rows]) + "\n", encoding="utf-8")
    mat = {**_demo_config()["materials"]["poraver"], "data": str(path)}
    warnings = validate_material(MaterialSpec.from_material("poraver", mat), base_dir=REPO).warnings
    assert [w for w in warnings if "column 'shape': the same value (150) in every run" in w]
    poraver = MaterialSpec.from_material("poraver", _demo_config()["materials"]["poraver"])
    assert not [w for w in validate_material(poraver, base_dir=REPO).warnings
                if "the same value" in w]


@pytest.mark.parametrize("design_name", ["ccd2", "ccd3", "bbd3"])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_factor_cell_typed_as_another_runs_level_is_located(tmp_path, design_name, seed):
    """One factor cell of one run holds a level another run uses: every value is a level, but the run is no
    point of the design.  The error names that run, the column and the value that completes the design."""
    from demid.design_generation import box_behnken_points

    k = int(design_name[-1])
    if design_name.startswith("ccd"):
        alpha = round((2 ** k) ** 0.25, 5)
        coded, design = ccd_points(k, alpha, 3), {"type": "ccd", "alpha": alpha, "center_runs": 3}
    else:
        coded, design = box_behnken_points(k, 3), {"type": "box_behnken", "center_runs": 3}
    cfg, coded_order, unit, centre = _write_design(tmp_path, coded, [0.1] * k, [0.9] * k, design, seed=seed)
    rng = np.random.default_rng(seed)
    # a non-centre run (ccd: factorial or axial; bbd: edge) with one nonzero coordinate set to 0 or to the
    # other factorial level gives a point of no type; a centre run with one factor at +1 likewise
    row = int(rng.choice(np.flatnonzero(np.abs(coded_order).sum(axis=1) == 0)))
    j = int(rng.integers(k))
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    cells = lines[row + 1].split(",")
    truth = cells[1 + j]
    cells[1 + j] = f"{centre[j] + unit[j]:.6f}"
    lines[row + 1] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match=rf"run {row + 1}, column 'x{j + 1}': the point \(.*\) is not an? .* point of "
                                         rf"the declared {design['type']} design; with x{j + 1} = {float(truth):g} it "
                                         r"would be the centre run the design is short of"):
        validate_material(MaterialSpec.from_material("m", cfg))


def test_a_level_value_that_differs_from_the_other_runs_at_its_level_is_warned_about(tmp_path):
    """0.5003 where every other run at the centre level reads 0.5: on the level (fitted as recorded), but a
    typo is likely; a table whose levels are printed consistently gets no such warning."""
    cfg, coded_order, unit, centre = _write_design(tmp_path, ccd_points(2, 1.41421, 3), [0.1, 1.0], [0.9, 5.0],
                                                   {"type": "ccd", "alpha": 1.41421, "center_runs": 3})
    assert not [w for w in validate_material(MaterialSpec.from_material("m", cfg)).warnings if "a typo?" in w]
    row = int(np.flatnonzero(np.all(coded_order == 0, axis=1))[0])
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    cells = lines[row + 1].split(",")
    usual = cells[1]
    cells[1] = f"{float(cells[1]) + 0.0003:.6f}"
    lines[row + 1] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    (warning,) = [w for w in validate_material(MaterialSpec.from_material("m", cfg)).warnings if "a typo?" in w]
    # the centre level of x1: 3 centre runs and the 2 axial runs of x2, 4 of them unchanged
    assert f"run {row + 1}, column 'x1': {float(cells[1]):.10g}, where the other 4 runs at this level read " \
           f"{float(usual):.10g}" in warning


def test_empty_columns_a_spreadsheet_adds_after_the_last_are_ignored(tmp_path):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok,,", "2,0.2,2,7.5,ok,,", "3,0.3,3,6.0,ok,,"], header="run,x1,x2,y,status,,")
    table, _ = read_table(path, ["x1", "x2"], ["y"])
    assert list(table["y"]) == [5.0, 7.5, 6.0]
    # an unnamed column that holds a value is still refused: it is data without a name
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok,,", "2,0.2,2,7.5,ok,,9", "3,0.3,3,6.0,ok,,"], header="run,x1,x2,y,status,,")
    with pytest.raises(InputError):
        read_table(path, ["x1", "x2"], ["y"])


def test_a_column_name_in_another_case_is_named_in_the_error(tmp_path):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok"], header="run,X1,x2,y,status")
    with pytest.raises(InputError, match=r"column 'x1': missing column .*found 'X1', which differs only in upper/lower"):
        read_table(path, ["x1", "x2"], ["y"])


@pytest.mark.parametrize("stat,value,match", [
    ("r2", 98.9, r"published\.r2: 98\.9 is not a possible R² .*written in percent\? 98\.9 % is 0\.989"),
    ("r2", -0.1, r"published\.r2: -0\.1 is not a possible R²"),
    ("adj_r2", 1.2, r"published\.adj_r2: 1\.2 is not a possible adjusted R²"),
    ("lof_p", 5, r"published\.lof_p: 5 is not a possible lack-of-fit p-value .*5 % is 0\.05"),
])
def test_an_impossible_published_statistic_is_refused(tmp_path, stat, value, match):
    def mutate(c):
        c["materials"]["mortar"]["responses"]["d5"].setdefault("published", {})[stat] = value
    with pytest.raises(InputError, match=rf"config key materials\.mortar\.responses\.d5\.{match}"):
        _load(tmp_path, mutate)


@pytest.mark.parametrize("stat,value", [("r2", "98.9%"), ("adj_r2", -0.3), ("lof_p", "<0.0001"), ("q2", -1.48),
                                        ("q2", "\u22121.48")])
def test_possible_published_statistics_pass(tmp_path, stat, value):
    def mutate(c):
        c["materials"]["mortar"]["responses"]["d5"].setdefault("published", {})[stat] = value
    assert "mortar" in _load(tmp_path, mutate)["materials"]


def test_two_scenarios_with_one_label_are_refused(tmp_path):
    def mutate(c):
        scenarios = c["materials"]["mortar"]["scenarios"]
        first = next(iter(scenarios.values()))
        scenarios["again"] = {"observables": list(first["observables"]), "tolerance": 0.03, "label": first["label"]}
    # (which of the two is named depends on the order of the keys in the file)
    with pytest.raises(InputError, match=r"materials\.mortar\.scenarios\.\w+\.label: '.+' is also the label of "
                                         r"scenario '\w+'; give each scenario its own label"):
        _load(tmp_path, mutate)


def test_a_value_beyond_the_header_is_not_dropped_with_the_empty_columns(tmp_path):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok,,", "2,0.2,2,7.5,ok,,,9", "3,0.3,3,6.0,ok,,"], header="run,x1,x2,y,status,,")
    with pytest.raises(InputError, match=r"line 3 has 8 cells, the header has 5"):
        read_table(path, ["x1", "x2"], ["y"])


@pytest.mark.parametrize("k, table_alpha, declared", [(2, 1.41421, 1.682), (2, 1.41421, 1.0), (3, 1.68179, 1.41421),
                                                      (2, 1.0, 1.41421), (3, 1.0, 1.68179), (4, 2.0, 1.68179)])
def test_a_wrong_design_alpha_names_the_key_and_the_alpha_the_runs_show(tmp_path, k, table_alpha, declared):
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(k, table_alpha, 3), [0.1] * k, [0.9] * k,
                                 {"type": "ccd", "alpha": declared, "center_runs": 3}, seed=k)
    with pytest.raises(InputError, match=rf"config key materials\.m\.design\.alpha: the runs form a CCD with "
                                         rf"alpha = {table_alpha:.6g} .*not the declared {declared:g}; set "
                                         rf"design\.alpha: {table_alpha:.6g}$"):
        validate_material(MaterialSpec.from_material("m", cfg))
    hinted = {**cfg, "design": {**cfg["design"], "alpha": table_alpha}}
    validate_material(MaterialSpec.from_material("m", hinted))  # the hint validates


def test_one_axial_cell_off_its_level_still_names_the_cell_not_alpha(tmp_path):
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(2, 1.41421, 3), [0.1, 0.1], [0.9, 0.9],
                                 {"type": "ccd", "alpha": 1.41421, "center_runs": 3})
    path = Path(cfg["data"])
    text = path.read_text()
    assert text.count("0.900000") == 2  # the two +alpha cells, one per factor
    path.write_text(text.replace("0.900000", "0.850000", 1))  # inside the bounds, off every level
    with pytest.raises(InputError, match=r"run \d+, column 'x\d': value 0\.85 is not a level.*\(coded \+1\.414\)$"):
        validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("command", ["fit", "criticize"])
@pytest.mark.parametrize("design, table_points, message", [
    ("box_behnken", ccd_points(3, 1.68179, 3), r"is not a level of the declared box_behnken design"),
    ("factorial", ccd_points(2, 1.41421, 3), r"is not a level of the declared factorial design"),
    ("ccd", np.array([p for p in _full_factorial(3, [-1, 0, 1]) if np.sum(np.abs(p)) == 2] + [[0, 0, 0]] * 3),
     r"is not a factorial, axial or centre point of the declared ccd design"),
])
def test_fit_and_criticize_refuse_a_table_that_is_not_the_declared_design(tmp_path, command, design, table_points,
                                                                            message):
    k = table_points.shape[1]
    cfg, _, _, _ = _write_design(tmp_path, table_points, [0.1] * k, [0.9] * k, {"type": design})
    names = ",".join(f"x{i + 1}" for i in range(k))
    response_flag = "--responses" if command == "fit" else "--response"
    out = tmp_path / "o.json"
    proc = _cli(command, "--data", cfg["data"], "--factors", names, response_flag, "y", "--design", design,
                "--out", str(out))
    assert proc.returncode == 2 and re.search(message, proc.stderr), proc.stderr
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr and not out.exists()


def test_a_wrong_alpha_on_the_command_line_names_the_option(tmp_path):
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(2, 1.41421, 3), [0.1, 0.1], [0.9, 0.9], {"type": "ccd"})
    proc = _cli("criticize", "--data", cfg["data"], "--factors", "x1,x2", "--response", "y", "--alpha", "1.682",
                "--out", str(tmp_path / "o.json"))
    assert proc.returncode == 2
    assert re.search(r"--alpha: the runs form a CCD with alpha = 1\.41421 .*; pass --alpha 1\.41421$", proc.stderr.strip())


@pytest.mark.parametrize("k", [2, 3])
def test_a_two_level_factorial_with_centre_runs_is_told_why_its_squares_cannot_be_fitted(tmp_path, k):
    coded = np.vstack([_full_factorial(k, [-1, 1]), np.zeros((4, k))])
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1] * k, [0.9] * k, {"type": "factorial", "center_runs": 4})
    squares = " and ".join([", ".join(f"x{i + 1}^2" for i in range(k - 1)), f"x{k}^2"])
    with pytest.raises(InputError, match=rf"column 'y': the quadratic model cannot be estimated \(rank "
                                         rf"{(k + 1) * (k + 2) // 2 - k + 1} of {(k + 1) * (k + 2) // 2} terms\): the "
                                         rf"usable runs cannot tell {re.escape(squares)} apart .*axial runs \(a CCD\)"):
        validate_material(MaterialSpec.from_material("m", cfg))


def test_the_readme_factorial_line_validates_a_three_level_factorial(tmp_path):
    line = next(ln for ln in (REPO / "README.md").read_text().splitlines() if ln.startswith("design: {type: factorial"))
    design = yaml.safe_load(line.split("#")[0])["design"]
    coded = _full_factorial(2, [-1, 0, 1])
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1, 0.1], [0.9, 0.9], design)
    validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("content, match", [
    ("- 0.97\n- 0.95\n", r"config key published: '.*numbers\.yaml' must hold a mapping"),
    ("poraver: {r2: 0.97}\nporaver: {r2: 0.95}\n", r"config key published: .*numbers\.yaml: line 2: key 'poraver' "
                                                   r"is given twice in one mapping \(first at line 1\)"),
    ("poraver: {r2: [0.97\n", r"config key published: .*numbers\.yaml: not valid YAML"),
])
def test_a_published_values_file_that_cannot_be_read_is_refused_at_validation(tmp_path, content, match):
    (tmp_path / "numbers.yaml").write_text(content, encoding="utf-8")
    with pytest.raises(InputError, match=match):
        _load(tmp_path, lambda c: c.update(published=str(tmp_path / "numbers.yaml")))


def test_a_repeated_key_in_the_config_is_refused_with_both_lines(tmp_path):
    path = tmp_path / "c.yaml"
    text = yaml.safe_dump(_demo_config(), allow_unicode=True)
    path.write_text(text + "grid_points: 51\n" if "grid_points:" in text else text + "results_dir: a\nresults_dir: b\n",
                    encoding="utf-8")
    with pytest.raises(InputError, match=r"c\.yaml: line \d+: key '(grid_points|results_dir)' is given twice in one "
                                         r"mapping \(first at line \d+\)"):
        load_config(path, base_dir=REPO)


def test_a_wrong_alpha_on_a_table_printed_to_four_decimals_gets_the_rotatable_value(tmp_path):
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(2, 1.41421, 3), [0.1, 1.0], [0.9, 100.0],
                                 {"type": "ccd", "alpha": 1.682, "center_runs": 3})
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    rounded = [lines[0]] + [",".join([c.split(",")[0]] + [f"{float(v):.4f}" for v in c.split(",")[1:]])
                            for c in lines[1:]]
    path.write_text("\n".join(rounded) + "\n")
    with pytest.raises(InputError, match=r"alpha = 1\.41421 .*not the declared 1\.682; set design\.alpha: 1\.41421$"):
        validate_material(MaterialSpec.from_material("m", cfg))


def test_a_wrong_alpha_is_named_before_a_wrong_centre_run_count(tmp_path):
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(2, 1.41421, 3), [0.1, 0.1], [0.9, 0.9],
                                 {"type": "ccd", "alpha": 1.682, "center_runs": 5})
    with pytest.raises(InputError, match=r"design\.alpha: the runs form a CCD with alpha = 1\.41421"):
        validate_material(MaterialSpec.from_material("m", cfg))
    cfg["design"]["alpha"] = 1.41421
    with pytest.raises(InputError, match=r"design\.center_runs: expected 5 centre run\(s\) .* found 3"):
        validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("k, declared", [(2, 1.41421), (3, 1.68179), (3, 1.0)])
def test_a_two_level_factorial_declared_a_ccd_is_told_it_has_no_axial_runs(tmp_path, k, declared):
    # Three levels per factor look like a face-centred CCD, but no alpha makes corners and centres a CCD.
    coded = np.vstack([_full_factorial(k, [-1, 1]), np.zeros((4, k))])
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1] * k, [0.9] * k,
                                 {"type": "ccd", "alpha": declared, "center_runs": 4})
    with pytest.raises(InputError, match=rf"config key materials\.m\.design: the table has no axial runs: its runs "
                                         rf"are a two-level factorial with 4 centre run\(s\).*3\^{k} factorial"):
        validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("k, alpha", [(2, 1.41421), (3, 1.68179)])
def test_a_log_spaced_factor_declared_linear_is_told_its_scale(tmp_path, k, alpha):
    """Surface energies are often designed in decades: every run of that factor is then off the linear
    levels, and the scale key is named instead of the first such cell."""
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(k, alpha, 3), [-3.0] + [0.1] * (k - 1), [-1.0] + [0.9] * (k - 1),
                                 {"type": "ccd", "alpha": alpha, "center_runs": 3}, seed=k)
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    path.write_text("\n".join([lines[0]] + [",".join([c[0], f"{10 ** float(c[1]):.6g}", *c[2:]])
                                            for c in (ln.split(",") for ln in lines[1:])]) + "\n")
    cfg["factors"]["x1"] = {"lower": 0.001, "upper": 0.1}
    with pytest.raises(InputError, match=r"config key materials\.m\.factors\.x1\.scale: the levels of x1 are evenly "
                                         r"spaced on a log scale, not the declared linear one; set scale: log$"):
        validate_material(MaterialSpec.from_material("m", cfg))
    cfg["factors"]["x1"]["scale"] = "log"
    validate_material(MaterialSpec.from_material("m", cfg))  # the hint validates
    cfg["factors"]["x2"]["scale"] = "log"  # a linear factor declared log
    with pytest.raises(InputError, match=r"factors\.x2\.scale: the levels of x2 are evenly spaced on a linear scale, "
                                         r"not the declared log one; remove scale: log$"):
        validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("k", [3, 4])
def test_a_box_behnken_table_declared_factorial_is_named(tmp_path, k):
    edges = [p for p in _full_factorial(k, [-1, 0, 1]) if np.sum(np.abs(p)) == 2]
    coded = np.vstack([edges, np.zeros((3, k))])
    cfg, _, _, _ = _write_design(tmp_path, coded, [0.1] * k, [0.9] * k, {"type": "factorial", "center_runs": 3})
    with pytest.raises(InputError, match=rf"config key materials\.m\.design\.type: the runs are the edge midpoints "
                                         rf"of a Box-Behnken design .*not the 3\^{k} factorial; set design type: "
                                         rf"box_behnken$"):
        validate_material(MaterialSpec.from_material("m", cfg))
    hinted = {**cfg, "design": {"type": "box_behnken", "center_runs": 3}}
    validate_material(MaterialSpec.from_material("m", hinted))  # the hint validates


def test_a_three_level_factorial_with_a_point_left_out_names_the_missing_point(tmp_path):
    points = [p for p in _full_factorial(2, [-1, 0, 1]) if not (p[0] == 1 and p[1] == -1)]
    cfg, _, _, _ = _write_design(tmp_path, np.array(points, float), [0.1, 0.1], [0.9, 0.9],
                                 {"type": "factorial", "center_runs": 1})
    with pytest.raises(InputError, match=r"config key materials\.m\.design: a 3\^2 factorial has 8 non-centre points, "
                                         r"the table has 7; missing 1, e\.g\. the point \(x1=\+1, x2=-1\)"):
        validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("k, table_alpha, declared", [(2, 1.41421, 1.682), (3, 1.68179, 1.41421), (3, 1.68179, 1.0)])
def test_a_wrong_alpha_on_levels_printed_to_two_decimals_gets_the_design_value(tmp_path, k, table_alpha, declared):
    """Levels printed to two decimals put the axial/factorial ratio at 1.4286 or 1.6667: the value the runs
    were designed with (rotatable) is told, since its levels hold every run as well."""
    cfg, _, _, _ = _write_design(tmp_path, ccd_points(k, table_alpha, 3), [0.1] * k, [0.9] * k,
                                 {"type": "ccd", "alpha": declared, "center_runs": 3})
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    path.write_text("\n".join([lines[0]] + [",".join([c.split(",")[0]] + [f"{float(v):.2f}" for v in c.split(",")[1:-1]]
                                                     + [c.split(",")[-1]]) for c in lines[1:]]) + "\n")
    with pytest.raises(InputError, match=rf"alpha = {table_alpha:.6g} .*not the declared {declared:g}; set "
                                         rf"design\.alpha: {table_alpha:.6g}$"):
        validate_material(MaterialSpec.from_material("m", cfg))
    hinted = {**cfg, "design": {**cfg["design"], "alpha": table_alpha}}
    validate_material(MaterialSpec.from_material("m", hinted))  # the hint validates


@pytest.mark.parametrize("where, value", [
    (("materials", "poraver", "factors", "e", "upper"), float("inf")),
    (("materials", "poraver", "responses", "aor", "target"), float("nan")),
    (("materials", "mortar", "reference_point", "mu_r"), float("nan")),
    (("materials", "poraver", "design", "alpha"), float("inf")),
    (("materials", "poraver", "scenarios", "aor_only", "tolerance"), float("nan")),
])
def test_yaml_nan_and_inf_are_refused_with_their_key(tmp_path, where, value):
    """.nan and .inf pass a schema's number type; as a bound, target or tolerance they mean nothing."""
    def mutate(c):
        node = c
        for key in where[:-1]:
            node = node[key]
        assert where[-1] in node  # premise: the key exists in the demo config
        node[where[-1]] = value
    with pytest.raises(InputError, match=rf"config key {re.escape('.'.join(where))}: {value} is not a usable number"):
        _load(tmp_path, mutate)


def test_a_relative_measurement_error_in_percent_gets_the_fraction_as_hint(tmp_path):
    def mutate(c):
        c["materials"]["poraver"]["responses"]["aor"]["sigma_rel"] = 2
    with pytest.raises(InputError, match=r"responses\.aor\.sigma_rel: 2 is greater than the maximum of 1; relative "
                                         r"measurement errors are fractions: 2 % is 0\.02"):
        _load(tmp_path, mutate)


def test_a_response_with_both_sigma_and_sigma_rel_is_refused(tmp_path):
    """sigma silently won over sigma_rel: which measurement error counts must be the user's choice."""
    def mutate(c):
        c["materials"]["poraver"]["responses"]["aor"].update(sigma=0.5, sigma_rel=0.02)
    with pytest.raises(InputError, match=r"config key materials\.poraver\.responses\.aor: both sigma \(0\.5\) and "
                                         r"sigma_rel \(0\.02\) are given; keep the one the measurement reports$"):
        _load(tmp_path, mutate)


def test_a_pareto_error_bound_in_percent_gets_the_fraction_as_hint(tmp_path):
    """max_error: 3 meant 3 %; it summarised Pareto intervals for errors below 300 %."""
    def mutate(c):
        c["materials"]["paste"]["pareto"]["max_error"] = 3
    with pytest.raises(InputError, match=r"config key materials\.paste\.pareto\.max_error: 3 is greater than the "
                                         r"maximum of 1; relative errors are fractions: 3 % is 0\.03$"):
        _load(tmp_path, mutate)


@pytest.mark.parametrize("alpha, fragment", [(1.02, "too close to tell apart; use 1 (face-centred) or at least 1.04"),
                                             (70.0, "too close to tell apart; use at most 50")])
def test_a_ccd_alpha_whose_levels_cannot_be_told_apart_names_the_key(tmp_path, alpha, fragment):
    def mutate(c):
        c["materials"]["mortar"]["design"]["alpha"] = alpha
    with pytest.raises(InputError, match=rf"config key materials\.mortar\.design\.alpha: {alpha:g} "
                                         rf".*{re.escape(fragment)}"):
        _load(tmp_path, mutate)


@pytest.mark.parametrize("reserved", ["status", "run"])
def test_a_response_or_factor_named_like_a_column_demid_reads_itself_is_refused(tmp_path, reserved):
    def mutate(c):
        responses = c["materials"]["poraver"]["responses"]
        responses[reserved] = responses.pop("shape")
        for scenario in c["materials"]["poraver"]["scenarios"].values():
            scenario["observables"] = [reserved if o == "shape" else o for o in scenario["observables"]]
    with pytest.raises(InputError, match=rf"config key materials\.poraver: '{reserved}' names a column demid reads "
                                         r"itself"):
        _load(tmp_path, mutate)


@pytest.mark.parametrize("status", ["timeout", "diverged", "failed (timeout)", "Timed out", "ERROR: segfault"])
def test_failure_words_other_than_failed_mark_a_failed_run(tmp_path, status):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok", f"2,0.2,2,,{status}", "3,0.3,3,6.0,done"])
    table, warnings = read_table(path, ["x1", "x2"], ["y"])
    assert table["status"].tolist() == ["ok", "failed", "ok"] and np.isnan(table["y"].iloc[1])
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok", f"2,0.2,2,7.5,{status}", "3,0.3,3,6.0,ok"])
    with pytest.raises(InputError, match=r"run 2, column 'y': the run is marked"):  # a value left in: not fitted
        read_table(path, ["x1", "x2"], ["y"])


def test_a_status_that_is_neither_ok_nor_failed_is_refused(tmp_path):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok", "2,0.2,2,7.5,rerun?", "3,0.3,3,6.0,ok"])
    with pytest.raises(InputError, match=r"t\.csv, run 2, column 'status': status 'rerun\?' is neither ok nor failed"):
        read_table(path, ["x1", "x2"], ["y"])
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok", "2,0.2,2,,ok", "3,0.3,3,6.0,ok"])
    with pytest.raises(InputError, match=r"run 2, column 'y': .*write failed in its 'status' cell"):
        read_table(path, ["x1", "x2"], ["y"])


@pytest.mark.parametrize("scale", [1e-20, 1e12])
def test_a_factor_in_tiny_or_huge_units_validates_like_the_same_factor_in_unit_units(tmp_path, scale):
    """A Hamaker constant of 1e-20 J is a factor like any other: the levels are merged relative to its own
    magnitude, not at a fixed number of decimals."""
    cfg, coded, _, _ = _write_design(tmp_path, ccd_points(2, 1.41421, 3), [0.1, 0.1], [0.9, 0.9],
                                     {"type": "ccd", "alpha": 1.41421, "center_runs": 3})
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    path.write_text("\n".join([lines[0]] + [",".join([c[0], f"{float(c[1]) * scale:.6e}", *c[2:]])
                                            for c in (ln.split(",") for ln in lines[1:])]) + "\n")
    cfg["factors"]["x1"] = {"lower": 0.1 * scale, "upper": 0.9 * scale}
    vt = validate_material(MaterialSpec.from_material("m", cfg))
    assert vt.summary("m")["point_types"] == {"axial": 4, "center": 3, "factorial": 4}


def test_a_ccd_with_replicated_axial_points_is_pointed_to_custom(tmp_path):
    coded = ccd_points(2, 1.41421, 3)
    axial = coded[np.sum(np.abs(coded) > 1e-9, axis=1) == 1]
    cfg, _, _, _ = _write_design(tmp_path, np.vstack([coded, axial]), [0.1, 0.1], [0.9, 0.9],
                                 {"type": "ccd", "alpha": 1.41421, "center_runs": 3})
    with pytest.raises(InputError, match=r"design: the table has 8 axial runs where a 2-factor CCD has 4: replicated "
                                         r"points\? .*declare design type custom"):
        validate_material(MaterialSpec.from_material("m", cfg))
    validate_material(MaterialSpec.from_material("m", {**cfg, "design": {"type": "custom"}}))


def test_a_run_number_too_large_to_be_exact_is_refused(tmp_path):
    path = _tiny(tmp_path, ["1,0.1,1,5.0,ok", "99999999999999999999,0.2,2,7.5,ok", "3,0.3,3,6.0,ok"])
    with pytest.raises(InputError, match=r"line 3: found '99999999999999999999', expected an integer run number "
                                         r"below 2\^53"):
        read_table(path, ["x1", "x2"], ["y"])


def test_a_decimal_comma_in_a_flow_mapping_is_named(tmp_path):
    text = (REPO / "config.yaml").read_text(encoding="utf-8")
    assert "aor_only:  {observables: [aor], tolerance: 0.01," in text  # premise
    path = tmp_path / "c.yaml"
    path.write_text(text.replace("aor_only:  {observables: [aor], tolerance: 0.01,",
                                 "aor_only:  {observables: [aor], tolerance: 0,01,"), encoding="utf-8")
    with pytest.raises(InputError, match=r"scenarios\.aor_only: Additional properties are not allowed \(1 was "
                                         r"unexpected\); a number written with a decimal comma\?"):
        load_config(path, base_dir=REPO)


def _duplicating_slips(coded):
    """(row, factor, level) such that setting that one factor of that non-centre run to that level makes it
    another non-centre run's point: a factor value typed as another run's level that leaves every run a point
    of the design and every point count as it was."""
    keys = [tuple(p) for p in coded]
    out = []
    for i, p in enumerate(coded):
        if not np.any(p):
            continue
        for j in range(coded.shape[1]):
            for level in np.unique(coded[:, j]):
                q = p.copy()
                q[j] = level
                if level != p[j] and tuple(q) in keys and np.any(q):
                    out.append((i, j, float(level)))
    return out


@pytest.mark.parametrize("design_name", ["ccd2", "ccd3", "face3", "bbd3", "bbd4"])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_factor_cell_that_makes_a_run_another_runs_point_is_located(tmp_path, design_name, seed):
    """Every run is a point and every point count matches, yet one point is run twice and one not at all
    (gamma 15 typed 5): the two runs would be fitted as replicates.  The error names both runs, the column
    and the value that restores the design; the table before the slip validates."""
    from demid.design_generation import box_behnken_points

    k = int(design_name[-1])
    if design_name.startswith("bbd"):
        coded, design = box_behnken_points(k, 3), {"type": "box_behnken", "center_runs": 3}
    else:
        alpha = 1.0 if design_name.startswith("face") else round((2 ** k) ** 0.25, 5)
        coded, design = ccd_points(k, alpha, 3), {"type": "ccd", "alpha": alpha, "center_runs": 3}
    cfg, coded_order, unit, centre = _write_design(tmp_path, coded, [0.1] * k, [0.9] * k, design, seed=seed)
    validate_material(MaterialSpec.from_material("m", cfg))
    rng = np.random.default_rng(seed)
    slips = _duplicating_slips(coded_order)
    row, j, level = slips[int(rng.integers(len(slips)))]
    twin = next(i for i, p in enumerate(coded_order) if i != row and p[j] == level
                and np.all(np.delete(p, j) == np.delete(coded_order[row], j)))
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    cells = lines[row + 1].split(",")
    truth = float(cells[1 + j])
    cells[1 + j] = f"{centre[j] + level * unit[j]:.6f}"
    lines[row + 1] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    runs = sorted((row + 1, twin + 1))
    with pytest.raises(InputError, match=rf"t\.csv, runs {runs[0]} and {runs[1]}, column 'x{j + 1}': both are the "
                                         rf"point \(.*\), which a .* runs once, and the design's point \(.*\) has no "
                                         rf"run: in one of them x{j + 1} is likely (\S+), typed as another "
                                         r"level$") as raised:
        validate_material(MaterialSpec.from_material("m", cfg))
    assert float(re.search(r"is likely (\S+),", str(raised.value)).group(1)) == pytest.approx(truth, rel=1e-4)


@pytest.mark.parametrize("design_name", ["ccd3", "bbd3"])
def test_a_design_point_left_out_or_run_twice_is_named(tmp_path, design_name):
    """A Box-Behnken table was checked for its centre runs alone: a missing edge run or a repeated one passed."""
    from demid.design_generation import box_behnken_points

    if design_name == "bbd3":
        coded, design = box_behnken_points(3, 3), {"type": "box_behnken", "center_runs": 3}
    else:
        coded, design = ccd_points(3, 1.68179, 3), {"type": "ccd", "alpha": 1.68179, "center_runs": 3}
    cfg, coded_order, _, _ = _write_design(tmp_path, coded, [0.1] * 3, [0.9] * 3, design)
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    row = int(np.flatnonzero(np.any(coded_order != 0, axis=1))[0])
    path.write_text("\n".join(lines[:row + 1] + lines[row + 2:]) + "\n")
    with pytest.raises(InputError, match=rf"t\.csv: the .*'s point \(x1 .*\) has no run \({len(coded) - 1} runs in the table\); "
                                         r"keep a failed run in the table with status failed"):
        validate_material(MaterialSpec.from_material("m", cfg))
    cells = lines[row + 1].split(",")
    path.write_text("\n".join(lines + [",".join(["99"] + cells[1:])]) + "\n")
    with pytest.raises(InputError, match=rf"t\.csv, runs {row + 1} and 99: both are the point \(.*\), which a .* runs "
                                         r"once; a replicated point makes it another design: declare design type "
                                         r"custom"):
        validate_material(MaterialSpec.from_material("m", cfg))


@pytest.mark.parametrize("seed", [0, 1])
def test_the_command_line_warns_of_two_runs_made_one_point_by_a_factor_slip(tmp_path, seed):
    """fit and criticize let failed runs be left out, so they do not count points; a factor cell typed as
    another run's level makes two runs replicates.  A replicated point beside a left-out run looks the same,
    so the command line warns (naming both readings) and goes on."""
    coded = ccd_points(2, 1.41421, 3)
    cfg, coded_order, unit, centre = _write_design(tmp_path, coded, [0.1, 1], [0.9, 9],
                                                   {"type": "ccd", "alpha": 1.41421, "center_runs": 3}, seed=seed)
    row, j, level = _duplicating_slips(coded_order)[seed]
    path = Path(cfg["data"])
    lines = path.read_text().splitlines()
    cells = lines[row + 1].split(",")
    cells[1 + j] = f"{centre[j] + level * unit[j]:.6f}"
    lines[row + 1] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    for command in (["criticize", "--response", "y"], ["fit", "--responses", "y"]):
        proc = _cli(*command, "--data", cfg["data"], "--factors", "x1,x2", "--out", str(tmp_path / "o.json"))
        assert proc.returncode == 0, proc.stderr
        assert re.search(rf"^demid: warning: .*runs \d+ and \d+, column 'x{j + 1}': both are the point .* typed as "
                         r"another level \(or a replicated point beside a run left out of the table\)$",
                         proc.stderr.strip(), re.M), proc.stderr


@pytest.mark.parametrize("written, reserved", [("Block", "block"), ("BLOCK", "block"), ("Status", "status")])
def test_a_reserved_column_in_another_case_is_refused_not_ignored(tmp_path, written, reserved):
    # read as an unlisted column, a 'Block' column's shift would be fitted as noise without a word
    header = "run,x1,x2,y,status," + written if reserved == "block" else "run,x1,x2,y," + written
    rows = ["1,0.1,1,5.0,ok,1", "2,0.2,2,7.5,ok,2"] if reserved == "block" else ["1,0.1,1,5.0,ok", "2,0.2,2,7.5,ok"]
    path = _tiny(tmp_path, rows, header=header)
    with pytest.raises(InputError, match=rf"column '{written}': differs only in upper/lower case from the "
                                         rf"reserved column '{reserved}': rename it to '{reserved}'"):
        read_table(path, ["x1", "x2"], ["y"])
    renamed = _tiny(tmp_path, rows, header=header.replace(written, reserved))
    read_table(renamed, ["x1", "x2"], ["y"])
