"""Run sheets: textbook coded designs, randomised order, reproducibility, and validation by the pipeline."""

from itertools import product

import numpy as np
import pandas as pd
import pytest
import yaml

from demid.config import check_semantics, validate_schema
from demid.data import validate_material
from demid.design_generation import FactorRange, generate_sheet, parse_factor
from demid.errors import InputError
from demid.spec import MaterialSpec
from ..helpers import run_demid


def _run(*args, cwd=None):
    return run_demid(*args, cwd=cwd)


def _rows(points):
    return sorted(tuple(round(float(v), 9) for v in row) for row in points)


# Textbook coded designs written out independently (Montgomery, Design and Analysis of Experiments, ch. 11).
R2 = 2 ** 0.5
CCD2_ROTATABLE = [(-1, -1), (1, -1), (-1, 1), (1, 1), (-R2, 0), (R2, 0), (0, -R2), (0, R2)] + [(0, 0)] * 5
BBD3 = ([(a, b, 0) for a in (-1, 1) for b in (-1, 1)] + [(a, 0, c) for a in (-1, 1) for c in (-1, 1)]
        + [(0, b, c) for b in (-1, 1) for c in (-1, 1)] + [(0, 0, 0)] * 3)


def test_ccd_points_match_textbook_and_axial_points_sit_on_the_range():
    sheet = generate_sheet("ccd", [FactorRange("e", 0.1, 0.9), FactorRange("mu", 2.0, 6.0)], center_runs=5)
    frame = sheet.to_frame()
    coded = (frame[["e", "mu"]].to_numpy() - [0.5, 4.0]) / (np.array([0.8, 4.0]) / (2 * R2))
    assert _rows(coded) == _rows(CCD2_ROTATABLE)
    assert frame["e"].min() == pytest.approx(0.1) and frame["e"].max() == pytest.approx(0.9)
    assert frame["mu"].min() == pytest.approx(2.0) and frame["mu"].max() == pytest.approx(6.0)


def test_three_factor_rotatable_alpha_and_face_centred():
    f3 = [FactorRange(n, 0.0, 1.0) for n in "abc"]
    sheet = generate_sheet("ccd", f3, center_runs=6)
    assert sheet.alpha == pytest.approx(8 ** 0.25)
    assert len(sheet.to_frame()) == 8 + 6 + 6
    face = generate_sheet("ccd", f3, center_runs=2, alpha="face").to_frame()
    assert sorted(set(face["a"])) == [0.0, 0.5, 1.0]


def test_box_behnken_matches_textbook():
    sheet = generate_sheet("box_behnken", [FactorRange(n, -2.0, 2.0) for n in "abc"], center_runs=3)
    frame = sheet.to_frame()
    assert _rows(frame[["a", "b", "c"]].to_numpy() / 2.0) == _rows(BBD3)


def test_factorial_is_three_level_grid_with_centre_replicates():
    frame = generate_sheet("factorial", [FactorRange("a", 0, 2), FactorRange("b", 10, 20)], center_runs=3).to_frame()
    expected = [(a, b) for a, b in product((0, 1, 2), (10, 15, 20))] + [(1, 15)] * 2
    assert _rows(frame[["a", "b"]].to_numpy()) == _rows(expected)


def test_randomised_order_and_same_seed_same_sheet():
    factors = [FactorRange("a", 0, 1), FactorRange("b", 0, 1)]
    one = generate_sheet("ccd", factors, center_runs=5, seed=7).to_frame()
    two = generate_sheet("ccd", factors, center_runs=5, seed=7).to_frame()
    other = generate_sheet("ccd", factors, center_runs=5, seed=8).to_frame()
    pd.testing.assert_frame_equal(one, two)
    assert list(one["run"]) == list(range(1, 14))
    assert list(one["std_order"]) != list(range(1, 14))  # not the standard order
    assert list(one["std_order"]) != list(other["std_order"])
    assert sorted(one["std_order"]) == list(range(1, 14))


@pytest.mark.parametrize("args", [
    ("ccd", ["a=0:1", "b=0:1"], "rotatable", 5),
    ("ccd", ["a=0:1", "b=0:1", "c=1:3"], "face", 2),
    ("ccd", ["a=0:1", "b=0:1", "c=1:3"], "1.5", 4),
    ("ccd", ["a=0:1", "b=0:1"], "1.04", 3),  # the closest alpha to 1 whose levels are told apart
    ("ccd", ["a=0:1", "b=0:1", "c=1:3"], "50", 3),  # and the widest
    ("box_behnken", ["a=0:1", "b=0:1", "c=1:3"], None, 3),
    ("box_behnken", ["a=0:1", "b=0:1", "c=1:3", "d=5:9"], None, 2),
    ("factorial", ["a=0:1", "b=-1:1"], None, 2),
])
def test_cli_sheet_validates_as_its_design(tmp_path, args):
    dtype, factors, alpha, centres = args
    cmd = ["design", "--type", dtype, "--center-runs", str(centres), "--seed", "3",
           "--response", "y", "--out", "sheet.csv", "--config-out", "study.yaml"]
    if alpha is not None:  # a CCD's axial distance; other designs refuse --alpha
        cmd += ["--alpha", alpha]
    for f in factors:
        cmd += ["--factor", f]
    proc = _run(*cmd, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    sheet = pd.read_csv(tmp_path / "sheet.csv")
    names = [f.split("=")[0] for f in factors]
    rng = np.random.default_rng(0)
    sheet["y"] = 1.0 + sheet[names].sum(axis=1) ** 2 + 0.01 * rng.standard_normal(len(sheet))  # filled in
    sheet.to_csv(tmp_path / "sheet.csv", index=False)
    fragment = yaml.safe_load((tmp_path / "study.yaml").read_text())
    fragment["materials"]["study"]["responses"]["y"]["target"] = 2.0  # the measurement the user adds
    fragment["materials"]["study"]["scenarios"] = {"y": {"observables": ["y"], "tolerance": 0.05}}  # and a scenario
    config = validate_schema(fragment)
    check_semantics(config, base_dir=tmp_path)
    vt = validate_material(MaterialSpec.from_material("study", config["materials"]["study"]), base_dir=tmp_path)
    counts = vt.summary("study")["point_types"]
    assert counts.get("center", 0) == centres
    if dtype == "ccd":
        assert counts["factorial"] == 2 ** len(factors) and counts["axial"] == 2 * len(factors)
    if dtype == "box_behnken":
        assert counts["edge"] == 2 * len(factors) * (len(factors) - 1)


def test_a_sheet_with_a_moved_point_does_not_validate(tmp_path):
    """The validation used above can fail: one factorial point moved off its level is caught."""
    proc = _run("design", "--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--center-runs", "5",
                "--response", "y", "--out", "sheet.csv", "--config-out", "study.yaml", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    sheet = pd.read_csv(tmp_path / "sheet.csv")
    sheet["y"] = np.arange(len(sheet), dtype=float) ** 1.5
    i = int(np.flatnonzero(sheet["std_order"] == 1)[0])
    sheet.loc[i, "a"] += 0.07
    sheet.to_csv(tmp_path / "sheet.csv", index=False)
    fragment = yaml.safe_load((tmp_path / "study.yaml").read_text())
    fragment["materials"]["study"]["responses"]["y"]["target"] = 2.0  # the measurement the user adds
    fragment["materials"]["study"]["scenarios"] = {"y": {"observables": ["y"], "tolerance": 0.05}}  # and a scenario
    config = validate_schema(fragment)
    with pytest.raises(InputError, match="not a level"):
        validate_material(MaterialSpec.from_material("study", config["materials"]["study"]), base_dir=tmp_path)


@pytest.mark.parametrize("argv, fragment", [
    (["--type", "ccd", "--factor", "a=1:0"], "LOW must be below HIGH"),
    (["--type", "ccd", "--factor", "a0:1"], "NAME=LOW:HIGH"),
    (["--type", "ccd", "--factor", "a=0:x"], "must be numbers"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "a=0:2"], "more than once"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--alpha", "0.5"], "alpha >= 1"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--alpha", "wide"], "rotatable, face or a number"),
    (["--type", "box_behnken", "--factor", "a=0:1", "--factor", "b=0:1"], "3 to 5 factors"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--center-runs", "0"], "at least 1"),
    (["--type", "cube", "--factor", "a=0:1"], "invalid choice"),
    (["--type", "ccd"], "at least two"),
    (["--type", "box_behnken", "--factor", "a=0:1", "--factor", "b=0:1", "--factor", "c=0:1", "--alpha", "face"],
     "only a ccd design has an axial distance"),
    (["--type", "ccd", "--factor", "a=0:1"], "at least two"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--response", "a"], "more than once"),
    (["--type", "ccd", "--factor", "run=0:1", "--factor", "b=0:1"], "'run' names a column demid writes itself"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--response", "status"], "'status' names a column"),
    (["--type", "ccd", "--factor", "\u03bc_r=0:1", "--factor", "b=0:1"], "is not a valid column name"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--material", "my mat"], "--material: 'my mat'"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--seed", "-5"], "--seed: must be 0 or more"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--config-out", "sheet.csv"], "same file as --out"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--response", "std_order"], "'std_order' names a column"),
    (["--type", "ccd", "--factor", "std_order=0:1", "--factor", "b=0:1"], "'std_order' names a column"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--alpha", "1e9"], "--alpha 1e9: puts the factorial"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--alpha", "70"], "--alpha 70: puts the factorial"),
    (["--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--alpha", "1.01"], "--alpha 1.01: puts the axial"),
])
def test_bad_input_is_one_line_with_status_2(tmp_path, argv, fragment):
    proc = _run("design", *argv, "--out", "sheet.csv", cwd=tmp_path)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("demid: error: ") and fragment in lines[0], proc.stderr
    assert not (tmp_path / "sheet.csv").exists()


def test_every_option_has_help():
    from demid.cli import build_parser

    parser = build_parser()
    design = parser._subparsers._group_actions[0].choices["design"]
    for action in design._actions:
        assert action.help, action.dest


def test_parse_factor():
    assert parse_factor("mu_r=0.05:0.35") == FactorRange("mu_r", 0.05, 0.35)


@pytest.mark.parametrize("k", [2, 3, 4])
@pytest.mark.parametrize("blocks", [1, 2, 3, 4])
@pytest.mark.parametrize("centres", [1, 2, 3, 5])
def test_a_ccd_is_written_in_two_blocks_and_from_three_factors_in_three_each_with_a_centre_run(k, blocks, centres):
    """2 blocks (factorial | axial) for any CCD, 3 (two half-factorials | axial) from three factors on; each block
    needs a centre run; 1 block is no blocking."""
    factors = [FactorRange(f"x{i}", 0.0, 1.0 + i) for i in range(k)]
    allowed = blocks == 1 or (blocks == 2 or (blocks == 3 and k >= 3))
    if not allowed:
        with pytest.raises(InputError, match=f"--blocks: a {k}-factor CCD is run in 2 blocks .*found {blocks}"):
            generate_sheet("ccd", factors, center_runs=centres, blocks=blocks)
        return
    if blocks > centres:
        with pytest.raises(InputError, match=f"--center-runs: {blocks} blocks need a centre run each, found "
                                             f"{centres} centre runs"):
            generate_sheet("ccd", factors, center_runs=centres, blocks=blocks)
        return
    frame = generate_sheet("ccd", factors, center_runs=centres, blocks=blocks, seed=3).to_frame()
    if blocks == 1:
        assert "block" not in frame
        return
    assert sorted(set(frame["block"])) == list(range(1, blocks + 1))
    assert list(frame["block"]) == sorted(frame["block"])  # block after block
    coded = frame[[f.name for f in factors]].to_numpy() / np.array([1.0 + i for i in range(k)]) * 2 - 1
    centre = np.all(np.abs(coded) < 1e-9, axis=1)
    axial = ~centre & np.any(np.abs(coded) < 1e-9, axis=1)
    assert set(frame.loc[axial, "block"]) == {blocks}
    assert all(centre[frame["block"] == b].any() for b in range(1, blocks + 1))


def test_the_config_fragment_keeps_the_factors_in_the_sheets_order():
    from demid.design_generation import fragment_yaml

    factors = [FactorRange("zeta", 1.0, 2.0), FactorRange("alpha", 0.1, 0.9), FactorRange("mu", 3.0, 5.0)]
    sheet = generate_sheet("ccd", factors, center_runs=3)
    material = yaml.safe_load(fragment_yaml(sheet, "m", "m.csv", responses=("y2", "y1")))["materials"]["m"]
    assert list(material) == ["data", "design", "factors", "responses"]
    assert list(material["factors"]) == ["zeta", "alpha", "mu"] and list(material["responses"]) == ["y2", "y1"]
    assert material["factors"]["alpha"] == {"lower": 0.1, "upper": 0.9}


def test_a_fragment_opens_with_what_to_add_before_the_pipeline_runs():
    from demid.design_generation import fragment_yaml

    sheet = generate_sheet("ccd", [FactorRange("a", 0.0, 1.0), FactorRange("b", 1.0, 2.0)], center_runs=3)
    text = fragment_yaml(sheet, "m", "m.csv")
    assert text.startswith("# Generated with the run sheet; add `responses:`")
    assert "# A factor with a physical limit takes `limits:`" in text
    assert fragment_yaml(sheet, "m", "m.csv", responses=("y",)).startswith(
        "# Generated with the run sheet; add a target to each response that is measured,")


@pytest.mark.parametrize("k, blocks", [(5, 2), (5, 3), (6, 3)])
def test_blocked_runs_keep_the_seeded_random_order_within_each_block(k, blocks):
    """Block after block, and within a block the order the seed's permutation gives its runs."""
    from demid.design import ccd_points

    factors = [FactorRange(f"x{i}", 0.0, 1.0) for i in range(k)]
    sheet = generate_sheet("ccd", factors, center_runs=6, blocks=blocks, seed=9)
    n = len(sheet.coded)
    permutation = np.random.default_rng(9).permutation(n)
    expected = [i for b in range(1, blocks + 1) for i in permutation if sheet.blocks[i] == b]
    assert list(sheet.order) == expected
    assert np.allclose(sheet.coded, ccd_points(k, sheet.alpha, 6))


@pytest.mark.parametrize("kind", ["refused", "other_centre"])
def test_a_sheet_whose_levels_the_pipeline_would_not_recover_is_refused_naming_the_centre_runs(monkeypatch, kind):
    """The sheet is checked the way the pipeline checks a table: when that check refuses it, or codes it about
    another centre, the command stops with one line naming --center-runs instead of writing the sheet."""
    import dataclasses

    import demid.design_check as design_check

    real = design_check.check_design

    def check(table, factors, design, src, config_key, *args, **kwargs):
        if kind == "refused":
            raise InputError("sheet: not a design")
        coding, coded = real(table, factors, design, src, config_key, *args, **kwargs)
        return dataclasses.replace(coding, center=np.asarray(coding.center) + 1e-3), coded

    factors = [FactorRange("a", 0.0, 1.0), FactorRange("b", 10.0, 20.0)]
    assert generate_sheet("ccd", factors, center_runs=3).center_runs == 3
    monkeypatch.setattr(design_check, "check_design", check)
    with pytest.raises(InputError, match="^--center-runs 3: the pipeline would not recover this design's levels"):
        generate_sheet("ccd", factors, center_runs=3)


def test_a_sheets_whole_output_over_designs_ranges_and_seeds():
    """Every design type, 2-4 factors (Box-Behnken 3-4), 1-4 centre runs, ranges of either sign and any scale,
    three alphas: the runs numbered 1..n, std_order a permutation naming each run's textbook point, each
    factor value the point mapped onto its range (the CCD's axial points on the range's ends), the design
    config and the material config as written out here."""
    from demid.design import box_behnken_points, ccd_points, rotatable_alpha

    rng = np.random.default_rng(17)
    cases = [(t, k, c, a) for t in ("ccd", "box_behnken", "factorial") for k in (2, 3, 4) for c in (1, 2, 4)
             for a in (["rotatable", "face", "1.5"] if t == "ccd" else ["rotatable"]) if t != "box_behnken" or k > 2]
    for design_type, k, centres, alpha_text in cases:
        low = rng.uniform(-5.0, 5.0, k) * 10.0 ** rng.integers(-3, 4, k)
        high = low + rng.uniform(0.1, 3.0, k) * np.abs(low).clip(1e-3)
        factors = [FactorRange(f"x{i}", float(lo), float(hi)) for i, (lo, hi) in enumerate(zip(low, high))]
        sheet = generate_sheet(design_type, factors, center_runs=centres, alpha=alpha_text,
                               seed=int(rng.integers(0, 1000)))
        alpha = {"rotatable": rotatable_alpha(k), "face": 1.0}.get(alpha_text, 1.5)
        textbook = (ccd_points(k, alpha, centres) if design_type == "ccd" else box_behnken_points(k, centres)
                    if design_type == "box_behnken" else np.vstack(
                        [np.array(list(product((-1.0, 0.0, 1.0), repeat=k)))[:, ::-1], np.zeros((centres - 1, k))]))
        outer = alpha if design_type == "ccd" else 1.0
        frame = sheet.to_frame()
        assert list(frame["run"]) == list(range(1, len(textbook) + 1))
        assert sorted(frame["std_order"]) == list(range(1, len(textbook) + 1))
        expected = (low + high) / 2 + textbook[frame["std_order"].to_numpy() - 1] * (high - low) / (2 * outer)
        assert np.allclose(frame[[f"x{i}" for i in range(k)]].to_numpy(), expected, rtol=1e-11, atol=0.0)
        values = frame[[f"x{i}" for i in range(k)]].to_numpy()
        assert np.allclose(values.min(axis=0), low, rtol=1e-11) and np.allclose(values.max(axis=0), high, rtol=1e-11)
        config = {"type": design_type, "center_runs": centres, **({"alpha": float(f"{alpha:.12g}")}
                                                                 if design_type == "ccd" else {})}
        assert sheet.design_config() == config
        assert sheet.material_config("t.csv", ["y"]) == {
            "data": "t.csv", "design": config, "responses": {"y": {}},
            "factors": {f"x{i}": {"lower": float(lo), "upper": float(hi)} for i, (lo, hi) in enumerate(zip(low, high))}}
