"""Universal kriging against independent computations, and the per-response choice between it and the quadratic.

The closed forms here are written from the kriging equations as a textbook states them (the bordered system
of the Lagrange multipliers for the weights and the variance), not from demid.kriging's GLS form; the
leave-one-out residuals are checked against refits without each run."""

import math

import numpy as np
import pandas as pd
import pytest

from demid.kriging import KIND, QUADRATIC, GaussianSystem, KrigingSurrogate

LENGTHS = np.array([0.35, 0.6])
NUGGET = 0.02


def _matern(a, b, lengths):
    """Matérn 5/2 correlation, one pair at a time."""
    out = np.empty((len(a), len(b)))
    for i, p in enumerate(a):
        for j, q in enumerate(b):
            d = math.sqrt(5.0 * sum(((pi - qi) / li) ** 2 for pi, qi, li in zip(p, q, lengths)))
            out[i, j] = (1 + d + d * d / 3) * math.exp(-d)
    return out


def _trend(u):
    return np.array([[1, a, b, a * b, a * a, b * b] for a, b in u])


def _bordered_kriging(u, y, at, lengths, nugget):
    """Mean and variance of the universal-kriging predictor by the bordered (Lagrange) system
    [[K, F], [F', 0]] [λ; μ] = [k; f]: mean λ'y, variance σ² (1 - λ'k - μ'f), σ² the REML scale."""
    n, p = len(u), 6
    k_mat = _matern(u, u, lengths) + nugget * np.eye(n)
    f_mat = _trend(u)
    border = np.block([[k_mat, f_mat], [f_mat.T, np.zeros((p, p))]])
    k_inv = np.linalg.inv(k_mat)
    beta = np.linalg.inv(f_mat.T @ k_inv @ f_mat) @ f_mat.T @ k_inv @ y
    resid = y - f_mat @ beta
    sigma2 = resid @ k_inv @ resid / (n - p)
    means, variances = [], []
    for point in at:
        k_at = _matern(u, [point], lengths)[:, 0]
        solution = np.linalg.solve(border, np.concatenate([k_at, _trend([point])[0]]))
        lam, mu = solution[:n], solution[n:]
        means.append(lam @ y)
        variances.append(sigma2 * (1 - lam @ k_at - mu @ _trend([point])[0]))
    return np.array(means), np.array(variances), sigma2


def _tiny():
    rng = np.random.default_rng(7)
    u = rng.random((11, 2))
    y = np.tanh(3 * (u[:, 0] - 0.4)) + 0.5 * u[:, 1] ** 3 + 0.01 * rng.standard_normal(11)
    return u, y


def _surrogate(u, y, lengths=LENGTHS, nugget=NUGGET):
    """A kriging surrogate on the unit square itself (factors from 0 to 1), fixed hyper-parameters."""
    return KrigingSurrogate("y", ["a", "b"], u, y, np.zeros(2), np.ones(2), np.asarray(lengths), nugget)


def test_mean_and_standard_errors_match_the_bordered_kriging_system():
    u, y = _tiny()
    at = np.array([[0.1, 0.9], [0.5, 0.5], [0.95, 0.05], *u[:2]])
    sur = _surrogate(u, y)
    # the surrogate standardises y; the kriging predictor is equivariant, the variance scales with sd(y)^2
    z = (y - y.mean()) / y.std()
    means, variances, sigma2 = _bordered_kriging(u, z, at, LENGTHS, NUGGET)
    assert sur.predict(at) == pytest.approx(y.mean() + y.std() * means, rel=1e-9, abs=1e-9)
    assert sur.se_mean(at) == pytest.approx(y.std() * np.sqrt(variances), rel=1e-6)
    assert sur.resid_var == pytest.approx(y.var() * sigma2 * NUGGET, rel=1e-9)
    assert sur.se_prediction(at) ** 2 == pytest.approx(sur.se_mean(at) ** 2 + y.var() * sigma2 * NUGGET, rel=1e-9)


def test_standard_error_includes_the_trend_uncertainty():
    """Far from the runs the simple-kriging part of the variance tends to σ² (the process's own variance); the
    trend's extrapolation adds to it, so the se exceeds σ there."""
    u, y = _tiny()
    sur = _surrogate(u, y, lengths=[0.1, 0.1])
    far = np.array([[3.0, 3.0]])
    sigma = y.std() * math.sqrt(sur.system.sigma2)
    assert sur.se_mean(far)[0] > 1.5 * sigma


def test_dubrule_leave_one_out_matches_refits_without_each_run():
    u, y = _tiny()
    sur = _surrogate(u, y)
    z = (y - y.mean()) / y.std()
    refits = []
    for i in range(len(u)):
        keep = np.arange(len(u)) != i
        mean, _, _ = _bordered_kriging(u[keep], z[keep], u[i:i + 1], LENGTHS, NUGGET)
        refits.append(y[i] - (y.mean() + y.std() * mean[0]))
    refits = np.array(refits)
    assert sur.loo_residuals == pytest.approx(refits, rel=1e-7, abs=1e-10)
    q2 = 1 - np.sum(refits ** 2) / np.sum((y - y.mean()) ** 2)
    assert sur.q2 == pytest.approx(q2, rel=1e-9)


def test_the_fit_is_deterministic_and_its_stored_hyperparameters_rebuild_it():
    u, y = _tiny()
    first = KrigingSurrogate.fit("y", ["a", "b"], u, y, [0, 0], [1, 1])
    second = KrigingSurrogate.fit("y", ["a", "b"], u, y, [0, 0], [1, 1])
    rebuilt = KrigingSurrogate.from_hyperparameters("y", ["a", "b"], u, y, [0, 0], [1, 1],
                                                    first.hyperparameters_json())
    at = np.random.default_rng(1).random((50, 2))
    assert first.hyperparameters_json() == second.hyperparameters_json()
    assert np.array_equal(first.predict(at), rebuilt.predict(at)) and np.array_equal(first.se_mean(at),
                                                                                      rebuilt.se_mean(at))


def test_a_log_scale_factor_is_kriged_in_log10_over_its_search_range():
    """A factor on a log scale: the same surrogate as one on its log10 values, bounds in log10 (search units)."""
    u, y = _tiny()
    x = np.column_stack([u[:, 0], 10 ** (-3 + 2 * u[:, 1])])  # b from 1e-3 to 1e-1
    logged = KrigingSurrogate("y", ["a", "b"], x, y, np.array([0.0, -3.0]), np.array([1.0, -1.0]), LENGTHS, NUGGET,
                              log_factors=("b",))
    at = np.array([[0.2, 0.004], [0.9, 0.05]])
    plain = _surrogate(u, y)
    at_unit = np.column_stack([at[:, 0], (np.log10(at[:, 1]) + 3) / 2])
    assert logged.predict(at) == pytest.approx(plain.predict(at_unit), rel=1e-10)
    assert logged.se_mean(at) == pytest.approx(plain.se_mean(at_unit), rel=1e-8)


def test_rescaling_for_an_own_tolerance_moves_predictions_and_errors_like_a_polynomial():
    u, y = _tiny()
    sur = _surrogate(u, y)
    at = np.array([[0.2, 0.3], [0.7, 0.8]])
    scaled = sur.rescaled(0.4, 2.5)
    assert scaled.predict(at) == pytest.approx(0.4 + 2.5 * (sur.predict(at) - 0.4))
    assert scaled.se_mean(at) == pytest.approx(2.5 * sur.se_mean(at))
    assert scaled.resid_var == pytest.approx(2.5 ** 2 * sur.resid_var)


def test_se_after_new_runs_is_the_se_of_the_grown_design():
    """The planned wave's standard error equals that of a fit whose runs include the new ones (hyper-parameters
    and scale held), and shrinks at the new runs."""
    u, y = _tiny()
    sur = _surrogate(u, y)
    new = np.array([[0.9, 0.9], [0.1, 0.1]])
    after = sur.se_mean_after(new, new)
    grown = GaussianSystem(np.vstack([u, new]), np.zeros(len(u) + 2), LENGTHS, NUGGET)
    assert after == pytest.approx(y.std() * np.sqrt(sur.system.sigma2 * grown.mean_variance(new)), rel=1e-9)
    assert np.all(after < sur.se_mean(new))


# ------------------------------------------------------------------ the choice on a wave
LO, HI = np.array([0.1, 1.0]), np.array([0.9, 11.0])


def _material(targets, data):
    return {"data": str(data), "design": {"type": "custom"},
            "factors": {"a": {"lower": float(LO[0]), "upper": float(HI[0])},
                        "b": {"lower": float(LO[1]), "upper": float(HI[1])}},
            "responses": {r: {"target": float(t)} for r, t in targets.items()},
            "scenarios": {"all": {"observables": list(targets), "tolerance": 0.02}}}


def _spec(targets, data):
    from demid.config import check_semantics, validate_schema
    from demid.spec import MaterialSpec

    config = validate_schema({"materials": {"m": _material(targets, data)}})
    check_semantics(config)
    return MaterialSpec.from_material("m", config["materials"]["m"], grid_points=config["grid_points"])


def _saturating(x):
    u = (x - LO) / (HI - LO)
    return 20 + 18 * np.tanh(4 * (u[:, 0] - 0.25)) + 6 * np.tanh(3 * u[:, 1])


def _quadratic(x):
    u = (x - LO) / (HI - LO)
    return 30 + 6 * u[:, 0] + 4 * u[:, 1] - 3 * u[:, 0] ** 2 + 2 * u[:, 0] * u[:, 1]


def _wave_table(fn, seed, n=31, noise=0.1):
    from scipy.stats import qmc

    points = LO + qmc.LatinHypercube(d=2, seed=seed).random(n) * (HI - LO)
    y = fn(points) + noise * np.random.default_rng(seed).standard_normal(n)
    return pd.DataFrame({"run": np.arange(1, n + 1), "a": points[:, 0], "b": points[:, 1], "y": y,
                         "status": "ok"})


def _choice(fn, seed, tmp_path, noise=0.1):
    from demid.surrogate import fit_frames, fit_response, surrogates_from_frame
    from demid.surrogate_choice import choose_surrogates

    table = _wave_table(fn, seed, noise=noise)
    table.to_csv(tmp_path / "t.csv", index=False)
    target = float(fn(np.array([LO + np.array([0.45, 0.55]) * (HI - LO)]))[0])
    spec = _spec({"y": target}, tmp_path / "t.csv")
    fit = fit_response(table, ["a", "b"], "y")
    frames = fit_frames([fit])
    quadratic = surrogates_from_frame(frames["fits"], ["a", "b"])
    return spec, target, quadratic, choose_surrogates(table, spec, quadratic, frames["statistics"])


def _set_error(fn, surrogate, target):
    axes = [np.linspace(lo, hi, 121) for lo, hi in zip(LO, HI)]
    grid = np.column_stack([g.ravel() for g in np.meshgrid(*axes, indexing="ij")])
    truth = np.abs(fn(grid) - target) <= 0.02 * abs(target)
    estimate = np.abs(surrogate.predict(grid) - target) <= 0.02 * abs(target)
    return np.sum(truth ^ estimate) / max(truth.sum(), 1)


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_a_saturating_response_is_judged_by_kriging_and_its_set_is_closer_to_the_truth(seed, tmp_path):
    _, target, quadratic, choice = _choice(_saturating, seed, tmp_path)
    row = choice.statistics.iloc[0]
    assert row["surrogate"] == KIND and 1 - row["q2_kriging"] <= 0.5 * (1 - row["q2_quadratic"])
    assert choice.surrogates["y"].kind == KIND
    assert _set_error(_saturating, choice.surrogates["y"], target) < _set_error(_saturating, quadratic["y"], target)


@pytest.mark.parametrize("seed", [0, 3, 5])
def test_a_quadratic_response_keeps_the_quadratic(seed, tmp_path):
    _, _, quadratic, choice = _choice(_quadratic, seed, tmp_path, noise=0.05)
    row = choice.statistics.iloc[0]
    assert row["surrogate"] == QUADRATIC and np.isfinite(row["q2_kriging"])
    assert choice.surrogates["y"] is quadratic["y"]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_the_stop_rules_leave_one_out_error_is_the_used_surrogates_own(seed, tmp_path):
    """The stop rule's leave-one-out error of a response (demid.waves.loo_error, read from the stored statistics)
    is the root mean square of the leave-one-out residuals of the surrogate its sets use, computed here from the
    surrogate itself: kriging's on a saturating response, the quadratic's where it is kept."""
    from demid.kriging import QUADRATIC
    from demid.waves import loo_error, surrogate_evidence

    _, _, _, choice = _choice(_saturating, seed, tmp_path)
    row = next(choice.statistics.itertuples())
    used = choice.surrogates["y"]
    expected = float(np.sqrt(np.mean(used.loo_residuals ** 2)))
    assert loo_error(row) == pytest.approx(expected, rel=1e-9)
    table = _wave_table(_saturating, seed)  # the quadratic's leave-one-out residuals e / (1 - h) by hand
    a, b, y = (table[c].to_numpy(dtype=float) for c in ("a", "b", "y"))
    x = np.column_stack([np.ones_like(a), a, b, a * a, a * b, b * b])
    hat = x @ np.linalg.pinv(x)
    loo = (y - hat @ y) / (1.0 - np.diag(hat))
    assert loo_error(row._replace(surrogate=QUADRATIC)) == pytest.approx(float(np.sqrt(np.mean(loo ** 2))), rel=1e-6)
    assert surrogate_evidence(row, 2 * expected)["loo_band"] == pytest.approx(0.5, rel=1e-9)
    assert np.isnan(surrogate_evidence(row)["loo_band"])


def test_the_choice_is_rebuilt_for_the_next_wave_and_tells_the_stop_rule_its_q2(tmp_path):
    from demid.surrogate_choice import choice_text, chosen_surrogates
    from demid.waves import surrogate_evidence

    spec, _, quadratic, choice = _choice(_saturating, 0, tmp_path)
    table = _wave_table(_saturating, 0)
    rebuilt = chosen_surrogates(table, spec, quadratic, choice.statistics)
    at = np.column_stack([np.linspace(LO[0], HI[0], 7), np.linspace(LO[1], HI[1], 7)])
    assert np.array_equal(rebuilt["y"].predict(at), choice.surrogates["y"].predict(at))
    row = next(choice.statistics.itertuples())
    evidence = surrogate_evidence(row)
    assert evidence["q2"] == pytest.approx(row.q2_kriging) and np.isnan(evidence["lof_p"])
    import re

    text = choice_text("θ", row)
    printed = re.fullmatch(r"θ by kriging \(Q² (-?[0-9.]+) against the quadratic's (-?[0-9.]+)\)", text)
    assert printed, text
    for shown, q2 in zip(printed.groups(), (row.q2_kriging, row.q2_quadratic)):
        places = len(shown.partition(".")[2])  # each Q² read back is its value at the places it shows,
        assert places >= 2 and float(shown) == pytest.approx(round(q2, places))
        assert q2 >= 1 or float(shown) < 1  # and one below 1 never reads as a perfect 1.00


def test_a_wave_analysed_with_the_choice_judges_its_sets_by_kriging_and_criticises_the_quadratic(tmp_path):
    """The whole per-material step with ``choose_surrogate``: the statistics say kriging, the plausible (plausible)
    set is the one of the kriging surrogate, and the criticism, the canonical analysis and Table 2's columns
    are the quadratic's."""
    from demid.io import as_stored, write_full_csv
    from demid.scenario import JudgedScenario
    from demid.steps import material_step

    table = _wave_table(_saturating, 1)
    path = tmp_path / "wave.csv"
    write_full_csv(table, path)
    target = float(_saturating(np.array([LO + np.array([0.45, 0.55]) * (HI - LO)]))[0])
    spec = _spec({"y": target}, path)
    plain = material_step(spec, path, z=2.0, tolerances=[0.02], typo_stop=False)
    chosen = material_step(spec, path, z=2.0, tolerances=[0.02], typo_stop=False, choose_surrogate=True)
    stats = as_stored(chosen.parquet["statistics"])
    assert stats["surrogate"].iloc[0] == KIND
    plain_stats = as_stored(plain.parquet["statistics"])
    assert "surrogate" not in plain_stats
    assert stats["q2"].iloc[0] == pytest.approx(plain_stats["q2"].iloc[0])  # Table 2's Q²: the quadratic's
    assert chosen.parquet["fits"].equals(plain.parquet["fits"])
    assert chosen.json["fit_summary"] == plain.json["fit_summary"]
    assert chosen.parquet["findings"].equals(plain.parquet["findings"])
    from demid.sampling.evaluate import EXACT_METHOD

    assert set(plain.parquet["scenarios"]["method"]) == {EXACT_METHOD}  # the quadratic's set: exact
    assert EXACT_METHOD not in set(chosen.parquet["scenarios"]["method"])  # kriging's: on the grid
    plausible = as_stored(chosen.parquet["plausible"])
    plain_robust = as_stored(plain.parquet["plausible"])
    kriging = KrigingSurrogate.from_hyperparameters("y", ["a", "b"], table[["a", "b"]].to_numpy(),
                                                    table["y"].to_numpy(), *spec.domain.search_bounds(),
                                                    stats["kriging_hyperparameters"].iloc[0])
    judged = JudgedScenario(spec, spec.scenarios[0], {"y": kriging}, 2.0)
    share = 100 * judged.contains(spec.domain.grid(201)).mean()
    assert plausible["robust_fraction_pct"].iloc[0] == pytest.approx(share, abs=0.3)
    assert plausible["robust_fraction_pct"].iloc[0] != pytest.approx(plain_robust["robust_fraction_pct"].iloc[0],
                                                                 abs=0.3)


def test_the_waves_summary_says_per_wave_which_surrogate_judged_each_response_and_both_q2(tmp_path):
    from demid.waves import wave_summary

    table = pd.DataFrame({"run": [1, 2, 3], "a": 0.5, "b": 5.0, "y": 30.0, "status": "ok"})
    table.to_csv(tmp_path / "t.csv", index=False)
    spec = _spec({"y": 30.0}, tmp_path / "t.csv")
    plausible = pd.DataFrame({"scenario": "all", "factor": ["a", "b"], "robust_fraction_pct": 1.5,
                           "robust_lower": [0.2, 2.0], "robust_upper": [0.4, 4.0]})
    first = pd.DataFrame({"response": ["y"], "q2": [0.42], "lof_p": [0.01]})
    second = first.assign(surrogate=KIND, q2_kriging=0.81, kriging_hyperparameters="{}")
    waves = [{"table": table, "analysed": table, "domain": None, "plausible": plausible, "statistics": stats}
             for stats in (first, second)]
    summary = wave_summary(spec, waves, None)["waves"]
    assert summary[0]["surrogate"] == "quadratic" and summary[0]["q2"] == {"y": 0.42}
    assert summary[1]["surrogate"] == "y by kriging (Q² 0.81 against the quadratic's 0.42)"
    assert summary[1]["q2"] == {"y": 0.81}
    assert summary[1]["surrogates"] == {"y": {"used": KIND, "q2_quadratic": 0.42, "q2_kriging": 0.81}}


def test_sets_judged_by_a_predicting_kriging_are_not_called_untrustworthy_for_the_quadratics_q2(tmp_path):
    """The criticism's "does not predict" is the quadratic's; where kriging (Q² >= 0) judged the sets, the advice
    does not tell the user to distrust them, and the report's warning leaves them out; where kriging does not
    predict either, both still say so."""
    from demid.story.verdicts import unpredictive_responses
    from demid.story import material_advice
    from demid.surrogate_choice import mark_criticism

    table = pd.DataFrame({"run": [1, 2, 3], "a": 0.5, "b": 5.0, "y": 30.0, "status": "ok"})
    table.to_csv(tmp_path / "t.csv", index=False)
    spec = _spec({"y": 30.0}, tmp_path / "t.csv")
    verdicts = pd.DataFrame(columns=["scenario", "factor", "verdict"])
    for q2_kriging, distrusted in ((0.81, False), (-0.2, True)):
        criticism = {"level1": {"y": {"verdict": "does_not_predict"}}}
        mark_criticism(criticism, pd.DataFrame({"response": ["y"], "q2": [-0.4], "surrogate": [KIND],
                                                "q2_kriging": [q2_kriging]}))
        said = [i for i in material_advice(spec, verdicts, criticism=criticism)
                if i.kind == "recalibrate" and "does not predict" in i.text]
        assert bool(said) is distrusted
        assert (unpredictive_responses(criticism["level1"]) == ["y"]) is distrusted
