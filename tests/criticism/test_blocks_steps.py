"""Runs made in blocks, a step in run order, and causes the runs cannot tell apart (demid.blocks,
catalogue cause ``step``, criticism.discrimination)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from statsmodels.regression.linear_model import OLS

from demid.blocks import block_columns, check_blocks, pure_error_groups
from demid.criticism import criticize
from demid.design import model_matrix, quadratic_terms
from demid.design_generation import FactorRange, generate_sheet
from demid.surrogate import fit_response
from tests.generators import FACTORS, ccd_table, design, later_runs, off_catalogue_table, random_quadratic

SEEDS = range(5)


def _block_shift_table(seed: int, shift: float, k: int = 2, with_block: bool = True) -> tuple[pd.DataFrame, int]:
    """A clean CCD table whose later half of the runs (in run order) is shifted by ``shift`` noise SDs: a second
    block.  Returns the table and the first run of the second block."""
    table, _ = ccd_table(seed, k, "clean", 0.0)
    first = len(table) // 2 + 1
    later = table["run"] >= first
    table.loc[later, "y"] += shift
    if with_block:
        table["block"] = np.where(later, "wave 2", "wave 1")
    return table, first


@pytest.mark.parametrize("k", [2, 3])
def test_block_shift_is_fitted_away_with_a_block_column(k):
    within_one_se = 0
    for seed in SEEDS:
        table, _ = _block_shift_table(seed, 6.0, k)
        fit = fit_response(table, FACTORS[k], "y")
        effects = fit.block_effects()
        assert set(effects) == {"wave 1", "wave 2"}
        (e1, s1), (e2, s2) = effects["wave 1"], effects["wave 2"]
        assert e1 == pytest.approx(-e2) and s1 == pytest.approx(s2)
        # the planted shift is +6 for wave 2 against wave 1: +3 from the block average
        assert abs(e2 - 3.0) <= 2.5 * s2, (seed, e2, s2)
        within_one_se += abs(e2 - 3.0) <= s2
        result = criticize(table, FACTORS[k], "y", n_null=499)
        assert result.verdict == "adequate", (seed, result.verdict_message)
        assert not any(e["cause"] in ("drift", "step") and e["p_family"] <= 0.05 for e in result.catalogue)
    assert within_one_se >= 3


def test_block_shift_without_a_block_column_is_named_step_not_drift():
    for k in (2, 3):
        for seed in SEEDS:
            table, first = _block_shift_table(100 + seed, 12.0, k, with_block=False)
            result = criticize(table, FACTORS[k], "y", n_null=499)
            assert result.findings, (k, seed, result.verdict_message)
            f = result.findings[0]
            assert f.cause == "step" and f.detail == first, (k, seed, f.cause, f.detail)
            assert f.info["step_size"] == pytest.approx(12.0, abs=4.0)
            assert "block" in f.message and f"run {first}" in f.message


def test_clean_tables_name_no_step_or_drift():
    for k in (2, 3):
        for seed in range(8):
            table, _ = ccd_table(300 + seed, k, "clean", 0.0)
            result = criticize(table, FACTORS[k], "y", n_null=499)
            assert not [f for f in result.findings if f.cause in ("step", "drift")], (k, seed)
            assert result.verdict != "ambiguous"


def test_pure_error_within_blocks_against_a_cell_means_fit():
    """Pure error with blocks is the residual of the model with one mean per (design point, block) cell:
    statsmodels fits that model independently of demid's grouping."""
    factors, coding, coded, _ = design(2)
    rng = np.random.default_rng(7)
    # centre runs split over the two blocks, one extra replicate of a factorial point in each block
    coded = np.vstack([coded, coded[[0]], coded[[0]]])
    block = np.array(["1"] * 4 + ["2"] * 4 + ["1", "2", "1", "2", "1"] + ["1", "2"])
    y = model_matrix(coded, quadratic_terms(2)) @ random_quadratic(rng, 2) + rng.normal(size=len(coded))
    y = y + np.where(block == "2", 5.0, 0.0)
    table = pd.DataFrame(coding.to_actual(coded), columns=factors)
    table.insert(0, "run", np.arange(1, len(coded) + 1))
    table["y"] = y
    table["block"] = block
    fit = fit_response(table, factors, "y", coding=coding)
    anova = fit.anova()
    cells = pd.Series([f"{tuple(np.round(c, 6))}|{b}" for c, b in zip(coded, block)])
    onehot = pd.get_dummies(cells).to_numpy(dtype=float)
    cell_fit = OLS(y, onehot).fit()
    assert anova.ss_pure_error == pytest.approx(float(cell_fit.ssr), rel=1e-10)
    assert anova.df_pure_error == int(round(cell_fit.df_resid))
    # replicates pooled across blocks would include the block shift: larger
    pooled = OLS(y, pd.get_dummies(pd.Series([str(tuple(np.round(c, 6))) for c in coded])).to_numpy(float)).fit()
    assert pooled.ssr > anova.ss_pure_error
    # blocks first: their sum of squares is the spread of the block means
    means = pd.Series(y).groupby(block).transform("mean").to_numpy()
    assert anova.ss_block == pytest.approx(float(np.sum((means - y.mean()) ** 2)), rel=1e-10)
    frame = anova.to_frame()
    assert frame["source"].iloc[0] == "Blocks" and int(frame["df"].iloc[0]) == 1
    total = anova.ss_block + anova.ss_model + anova.ss_residual
    assert total == pytest.approx(anova.ss_total, rel=1e-10)
    assert pure_error_groups(coded, block).max() + 1 == len(set(cells))


def test_design_writes_a_blocked_ccd_sheet():
    factors = [FactorRange("a", 0.0, 1.0), FactorRange("b", 2.0, 14.0)]
    sheet = generate_sheet("ccd", factors, center_runs=4, blocks=2, seed=3)
    frame = sheet.to_frame()
    assert list(frame["block"]) == sorted(frame["block"])  # block after block
    coded = sheet.coded[sheet.order]
    centre = np.all(np.abs(coded) < 1e-9, axis=1)
    factorial = np.all(np.abs(np.abs(coded) - 1) < 1e-9, axis=1)
    assert set(frame.loc[factorial, "block"]) == {1} and set(frame.loc[~factorial & ~centre, "block"]) == {2}
    assert all(np.any(centre & (frame["block"] == b).to_numpy()) for b in (1, 2))
    check = check_blocks(coded, frame["block"].astype(str).to_numpy(dtype=object),
                         model_matrix(coded, quadratic_terms(2)))
    assert not check.problems and check.centre_runs == {"1": 2, "2": 2}
    # with 2 centre runs per block the rotatable CCD's blocks are orthogonal to the quadratic (Box & Hunter):
    # the factorial block's second moment per run equals the axial block's
    assert check.orthogonal


def test_block_columns_are_effect_coded():
    cols = block_columns(np.array(["x", "y", "z", "x"], dtype=object))
    assert cols.tolist() == [[1, 0], [0, 1], [-1, -1], [1, 0]]


def test_outlier_against_a_batch_gives_ambiguous_and_runs_that_decide():
    """A batch of three shifted runs where an outlier and a step in run order explain the misfit equally:
    the verdict is ambiguous, and the proposed runs, simulated as the generator would make them (the batch
    was a past event: new runs are not shifted), refute the step."""
    found = 0
    for seed in range(12):
        table, planted = off_catalogue_table(seed, 2, "batch", 6.0)
        result = criticize(table, FACTORS[2], "y", n_null=499)
        if result.verdict != "ambiguous":
            continue
        found += 1
        out = result.to_json()
        causes = {c["cause"] for c in out["candidates"]}
        assert len(out["candidates"]) >= 2 and "outlier" in causes and not result.findings
        runs = out["discriminating_runs"]
        assert 1 <= len(runs) <= 4 and all(r["purpose"] == "decide between causes" for r in runs)
        assert "ambiguous" in result.verdict_message and "would decide" in result.verdict_message
        # simulate the proposed runs from the generator's quadratic (no batch shift), with its noise
        rng = np.random.default_rng(seed)
        factors, coding, coded, _ = design(2)
        n = len(coded)
        rng.permutation(n)
        coef = random_quadratic(rng, 2)
        new = pd.DataFrame([{f: r[f] for f in factors} for r in runs])
        new_coded = coding.to_coded(new[factors].to_numpy(dtype=float))
        new["y"] = model_matrix(new_coded, quadratic_terms(2)) @ coef + rng.normal(size=len(new))
        new.insert(0, "run", np.arange(n + 1, n + 1 + len(new)))
        again = criticize(pd.concat([table, new], ignore_index=True), FACTORS[2], "y", n_null=499)
        assert not [f for f in again.findings if f.cause == "step"], (seed, again.verdict_message)
        assert not any(c["cause"] == "step" for c in again.candidates), (seed, again.candidates)
    assert found >= 1


def test_fit_command_reports_block_effects_and_a_blocks_row(tmp_path):
    import json
    import os
    import subprocess
    import sys

    table, _ = _block_shift_table(11, 6.0, 2)
    path = tmp_path / "blocked.csv"
    table.to_csv(path, index=False)
    out = tmp_path / "fit.json"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(p) for p in sys.path if p])}
    proc = subprocess.run([sys.executable, "-m", "demid", "fit", "--data", str(path), "--factors", "mu_r,gamma",
                           "--responses", "y", "--out", str(out)], capture_output=True, text=True, env=env)
    assert proc.returncode == 0, proc.stderr
    fit = json.loads(out.read_text())["y"]
    assert set(fit["block_effects"]) == {"wave 1", "wave 2"}
    direct = fit_response(table, FACTORS[2], "y").block_effects()
    assert fit["block_effects"]["wave 2"] == pytest.approx(direct["wave 2"][0], rel=1e-6, abs=1e-9)
    assert fit["anova"][0]["source"] == "Blocks"
    assert "blocking" in proc.stderr  # orthogonal or not, said


def test_ambiguous_runs_reach_the_next_wave_first():
    from demid.next_wave import PURPOSE_DECIDE
    from demid.wave_runs import deciding_runs

    for seed in range(12):
        table, _ = off_catalogue_table(seed, 2, "batch", 6.0)
        result = criticize(table, FACTORS[2], "y", n_null=499)
        if result.verdict == "ambiguous":
            break
    else:
        pytest.fail("no ambiguous table among the seeds")
    frame = result.to_frame()
    assert frame["cause"].tolist() == ["ambiguous"]
    runs = deciding_runs(frame, FACTORS[2])
    assert [{f: r[f] for f in FACTORS[2]} for r in runs] == \
        [{f: r[f] for f in FACTORS[2]} for r in result.discriminating_runs]
    assert PURPOSE_DECIDE == "decide between causes"


def test_plan_next_wave_lists_the_deciding_runs_first():
    import json

    from demid.next_wave import PURPOSE_DECIDE, plan_next_wave
    from tests.test_next_wave import _annulus_material

    table, surrogates, cfg, plausible = _annulus_material(count=5)
    deciding = [{"a": 0.25, "b": 0.75, "purpose": PURPOSE_DECIDE}, {"a": 0.5, "b": 0.5, "purpose": PURPOSE_DECIDE}]
    findings = pd.DataFrame([{"response": "y", "cause": "ambiguous", "detail": "outlier (3);step (9)",
                              "aliases": "", "discriminating_runs": json.dumps(deciding)}])
    plain = plan_next_wave("m", table, surrogates, cfg, plausible, None, z=2.0)
    wave = plan_next_wave("m", table, surrogates, cfg, plausible, findings, z=2.0)
    assert len(wave.runs) == len(plain.runs) == 5  # count is the whole wave: the deciding runs come inside it
    n_deciding = int((wave.runs["purpose"] == PURPOSE_DECIDE).sum())
    assert 1 <= n_deciding <= 2 and wave.runs["purpose"].tolist()[:n_deciding] == [PURPOSE_DECIDE] * n_deciding
    assert wave.runs[["a", "b"]].to_numpy()[:n_deciding].tolist() == [[0.25, 0.75], [0.5, 0.5]][:n_deciding]
    assert set(wave.runs["purpose"].tolist()[n_deciding:]) <= set(plain.runs["purpose"].tolist())
    if n_deciding < 2:  # the box's quadratic keeps the design runs it is short of; the rest is said
        assert f"{2 - n_deciding} more run(s) the criticism proposed do not fit in the wave's 5 runs" in wave.reason
    assert "decide between causes" in wave.reason


BLOCKED_CCD = """run,x1,x2,block,y
1,-1,-1,1,80.5
2,1,-1,1,81.5
3,-1,1,1,82.0
4,1,1,1,83.5
5,0,0,1,83.9
6,0,0,1,84.3
7,0,0,1,84.0
8,0,0,2,79.7
9,0,0,2,79.8
10,0,0,2,79.5
11,1.414,0,2,78.4
12,-1.414,0,2,75.6
13,0,1.414,2,78.5
14,0,-1.414,2,77.0
"""


def test_a_printed_two_block_ccd(tmp_path):
    """A 2-factor CCD run in two blocks (factorial runs and axial runs, three centre runs each; the second
    block about 4.5 lower), rows in the order printed: without its block column the shift is a step at the
    first run of block 2; with it, the blocks are (to the printed alpha) orthogonal and nothing is left."""
    from io import StringIO

    table = pd.read_csv(StringIO(BLOCKED_CCD))
    table["block"] = table["block"].astype(str)
    plain = criticize(table.drop(columns="block"), ["x1", "x2"], "y", n_null=499)
    named = [f for f in plain.findings] or []
    assert named and named[0].cause == "step" and named[0].detail == 8, plain.verdict_message
    fit = fit_response(table, ["x1", "x2"], "y", alpha=1.414)
    effects = fit.block_effects()
    # effect coding: the blocks' difference is twice an effect; block means at the centre differ by 4.4
    assert effects["1"][0] - effects["2"][0] == pytest.approx(4.46, abs=0.05)
    coded = fit.coded
    check = check_blocks(coded, table["block"].to_numpy(dtype=object), model_matrix(coded, quadratic_terms(2)))
    assert check.orthogonal and check.centre_runs == {"1": 3, "2": 3}
    blocked = criticize(table, ["x1", "x2"], "y", n_null=499)
    assert blocked.verdict == "adequate", blocked.verdict_message


def test_report_reads_a_blocked_fit_as_the_fit_made_it():
    """The report prints the ANOVA the fit step stored: a Blocks row first, then the partial sums of squares of
    the term groups with the blocks kept, the partial sum of squares of the linear terms equal to statsmodels'
    nested comparison with the blocks in both models."""
    from demid.report.rsm import stored_surfaces
    from demid.spec import MaterialSpec
    from demid.surrogate import fit_frames, fit_material

    table, _ = _block_shift_table(5, 6.0, 2)
    table["status"] = "ok"
    lo, hi = table[FACTORS[2]].min(), table[FACTORS[2]].max()
    material = {"data": "t.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
                "factors": {f: {"lower": float(lo[f]), "upper": float(hi[f])} for f in FACTORS[2]},
                "responses": {"y": {}}, "scenarios": {}}
    spec = MaterialSpec.from_material("m", material)
    refits = fit_material(table, spec)
    frames = fit_frames(refits)
    surface = stored_surfaces(frames["fits"], frames["anova"], table, spec)[0]
    mine = surface.anova
    assert surface.blocked and mine["source"].iloc[0] == "Blocks"
    x = refits[0].results.model.exog
    linear = [1, 2]  # mu_r, gamma
    reduced = OLS(refits[0].y, np.delete(x, linear, axis=1)).fit()
    partial = float(reduced.ssr - refits[0].results.ssr)
    assert mine.set_index("source").loc["↳ Linear", "sum_sq"] == pytest.approx(partial, rel=1e-9)


def _simulate_after_step(seed: int, k: int, shift: float, runs: list[dict]) -> pd.DataFrame:
    """The proposed runs as made after the table of _block_shift_table (clean ccd_table, later half shifted):
    made after the step, every one of them carries the shift."""
    new, _ = later_runs(seed, k, runs)
    new["y"] += shift
    return new


@pytest.mark.workflow  # a benchmark-like batch of tables
def test_later_replicates_of_the_runs_between_two_change_points_tell_which_side_they_were_on():
    """Two change-points level with each other differ only in the side of the step the runs between them fell
    on, and so in the surface fitted near those runs' points.  A run made there after the table is after the step
    under either reading: it repeats the level of a run between them if that run was after the step already, and
    differs from it by the shift if not.  The proposed runs go there, and after them the planted change-point is
    named (not "run 10 or 11": the runs' order fixes which side each run fell on, later runs measure it)."""
    decided = []
    for k in (2, 3):
        for seed in range(20):
            table, first = _block_shift_table(seed, 6.0, k, with_block=False)
            result = criticize(table, FACTORS[k], "y", n_null=499)
            if result.verdict != "ambiguous" or {c["cause"] for c in result.candidates} != {"step"}:
                continue
            new = _simulate_after_step(seed, k, 6.0, result.discriminating_runs)
            again = criticize(pd.concat([table, new], ignore_index=True), FACTORS[k], "y", n_null=499)
            decided.append((k, seed, first, [(f.cause, f.detail) for f in again.findings[:1]]))
    assert len(decided) >= 3, decided
    assert all(named == [("step", first)] for _, _, first, named in decided), decided
