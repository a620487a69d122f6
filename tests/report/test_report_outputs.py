"""Response-surface output, summary verdicts, figure labels and CSV rounding, against independent computations."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import statsmodels.formula.api as smf

from demid.io import round_significant, write_csv
from demid.plots.labels import tex_label, tex_unit
from demid.report.rsm import anova_table, coefficient_table
from demid.story.verdicts import factor_verdict
from demid.surrogate import fit_response

from ..helpers import make_ccd_table


def _fit(seed, noise=0.5):
    def responses(x):
        a, b = x[:, 0], x[:, 1]
        return {"y": 50 + 8 * a - 3 * b + 4 * a * b - 6 * a**2 - 2 * b**2}

    table = make_ccd_table(responses, [-1.41421, -1.41421], [1.41421, 1.41421], noise=noise, seed=seed)
    return table, fit_response(table, ["x1", "x2"], "y", alpha=1.41421)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_block_anova_matches_statsmodels_nested_f_tests(seed):
    table, fit = _fit(seed)
    # Coded units equal actual units here (axial points at +-alpha = the bounds): statsmodels fits the raw table.
    full = smf.ols("y ~ x1 + x2 + x1:x2 + I(x1**2) + I(x2**2)", table).fit()
    reduced = {"↳ Linear": "y ~ x1:x2 + I(x1**2) + I(x2**2)",
               "↳ Two-factor interaction": "y ~ x1 + x2 + I(x1**2) + I(x2**2)",
               "↳ Pure quadratic": "y ~ x1 + x2 + x1:x2"}
    anova = anova_table(fit.anova_frame()).set_index("source")
    for source, formula in reduced.items():
        f, p, df = full.compare_f_test(smf.ols(formula, table).fit())
        assert anova.loc[source, "F"] == pytest.approx(f, rel=1e-8)
        assert anova.loc[source, "p_value"] == pytest.approx(p, rel=1e-6)
        assert anova.loc[source, "df"] == df
    assert anova.loc["Residual", "sum_sq"] == pytest.approx(full.ssr, rel=1e-10)
    assert anova.loc["Model", "F"] == pytest.approx(full.fvalue, rel=1e-8)
    # Lack of fit + pure error = residual
    assert anova.loc["↳ Lack of fit", "sum_sq"] + anova.loc["↳ Pure error", "sum_sq"] == pytest.approx(full.ssr)


def test_coefficient_table_matches_statsmodels():
    table, fit = _fit(4)
    full = smf.ols("y ~ x1 + x2 + x1:x2 + I(x1**2) + I(x2**2)", table).fit()
    coef = coefficient_table(fit.coefficients()).set_index("term")
    for mine, theirs in [("x1", "x1"), ("x2", "x2"), ("x1:x2", "x1:x2"), ("x1^2", "I(x1 ** 2)"),
                         ("Intercept", "Intercept")]:
        assert coef.loc[mine, "estimate"] == pytest.approx(full.params[theirs], rel=1e-9, abs=1e-9)
        assert coef.loc[mine, "std_error"] == pytest.approx(full.bse[theirs], rel=1e-9)
        assert coef.loc[mine, "p_value"] == pytest.approx(full.pvalues[theirs], rel=1e-6, abs=1e-15)


def test_stationary_point_of_a_known_quadratic():
    # Noise-free y = 50 + 8a - 3b + 4ab - 6a^2 - 2b^2: gradient zero at the solution of the 2x2 system.
    from demid.canonical import fit_canonical

    _, fit = _fit(0, noise=0.0)
    b, big_b = np.array([8.0, -3.0]), np.array([[-6.0, 2.0], [2.0, -2.0]])
    expected = -0.5 * np.linalg.solve(big_b, b)
    point = fit_canonical(fit, threshold=0.0)
    assert np.allclose(point.stationary_actual, expected, atol=1e-8)
    assert point.kind == "maximum"
    assert point.inside == bool(np.all(np.abs(expected) <= 1.41421))
    assert point.value == pytest.approx(50 + b @ expected + expected @ big_b @ expected, rel=1e-9)


@pytest.mark.parametrize("lower, upper, verdict", [
    (0.0, 1.0, "unresolved"),
    (0.40, 0.45, "identified"),
    (0.30, 0.60, "bounded"),
    (0.0, 0.30, "cut by the search range (lower bound)"),
    (0.8, 1.0, "cut by the search range (upper bound)"),
    (np.nan, np.nan, "no admissible point"),
])
def test_factor_verdicts(lower, upper, verdict):
    assert factor_verdict(lower, upper, 0.0, 1.0)[0] == verdict


def test_factor_verdict_in_log_units():
    # 1..10 of 1..1000 is a third of the log range and touches the lower bound.
    assert factor_verdict(1.0, 10.0, 1.0, 1000.0, log=True) == ("cut by the search range (lower bound)",
                                                                 pytest.approx(1 / 3))


@pytest.mark.parametrize("label, tex", [("μ_r,Po", r"$\mu_{\mathrm{r,Po}}$"), ("d_5", r"$d_{\mathrm{5}}$"), ("γ_M", r"$\gamma_{\mathrm{M}}$"),
                                        ("mu_r", r"$\mu_{\mathrm{r}}$"), ("gamma", r"$\gamma$"), ("AoR only", "AoR only")])
def test_mathtext_labels(label, tex):
    assert tex_label(label) == tex


def test_mathtext_units():
    assert tex_unit("J m^-2") == "J m$^{-2}$"
    assert tex_unit("-") == "–"
    assert tex_unit("mm") == "mm"


def test_mathtext_labels_render():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.subplots()
    ax.set_xlabel(" ".join(tex_label(s) for s in ["μ_r,Po", "d_10", "γ_Pa", "θ_Po", "mu_r", "e_Po"]) + tex_unit("J m^-2"))
    fig.canvas.draw()  # raises on a mathtext syntax error


def test_csv_rounding_six_significant_digits(tmp_path):
    frame = pd.DataFrame({"a": [0.1 + 0.2, 123456789.0, 2.220446049250313e-16, np.nan], "n": [1, 2, 3, 4],
                          "s": ["x", "y", "z", "w"]})
    path = tmp_path / "t.csv"
    write_csv(frame, path)
    text = path.read_text()
    assert text.splitlines()[1:3] == ["0.3,1,x", "1.23457e+08,2,y"]
    back = pd.read_csv(path)
    for value in back["a"].dropna():
        assert len(f"{value:.15g}".replace("-", "").split("e")[0].replace(".", "").strip("0")) <= 6
    assert round_significant(frame)["a"].iloc[0] == 0.3
    write_csv(frame, tmp_path / "u.csv")
    assert (tmp_path / "u.csv").read_bytes() == path.read_bytes()


def test_cli_version_and_help_on_every_option(capsys):
    import argparse

    from demid import __version__
    from demid.cli import build_parser, main

    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.strip() == f"demid {__version__}"
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    for name, command in sub.choices.items():
        for action in command._actions:
            assert action.help, f"{name} {action.option_strings} has no help"
            assert "``" not in action.help


def test_columns_dictionary_covers_every_declared_table():
    from demid.report.columns import TABLE_COLUMNS, columns_table
    from demid.report.tables import IDENTIFIABILITY_COLUMNS, SURROGATE_FIT_COLUMNS, TRANSCRIPTION_COLUMNS
    from demid.uncertainty.ranking import RANKING_COLUMNS
    from demid.uncertainty.plausible import PLAUSIBLE_COLUMNS

    table = columns_table({"m": [("a", "mm"), ("b", "-")]})
    assert not table.duplicated(["table", "column"]).any()
    assert (table["description"].str.len() > 10).all()
    for name, cols in [("surrogate_fit", SURROGATE_FIT_COLUMNS), ("identifiability", IDENTIFIABILITY_COLUMNS),
                       ("transcription_check", TRANSCRIPTION_COLUMNS), ("observable_ranking", RANKING_COLUMNS),
                       ("robust_identifiability", PLAUSIBLE_COLUMNS)]:
        assert set(cols) <= set(TABLE_COLUMNS[name]) | {"material"}, name
    units = table.set_index(["table", "column"])["unit"]
    assert units[("identifiability.csv", "tolerance")].startswith("fraction")
    assert units[("identifiability.csv", "feasible_fraction_pct")] == "% of Ω"
    assert units[("pareto_m.csv", "a")] == "mm"


def test_figures_are_png_at_300_dpi_and_svg_byte_identical_on_rerun(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from PIL import Image

    from demid.io import save_figure

    def draw():
        fig = Figure(figsize=(2, 1.5))
        ax = fig.subplots()
        ax.plot([0, 1], [1, 0], label="a")
        ax.set_xlabel(tex_label("μ_r,Po"))
        ax.legend()
        return fig

    save_figure(draw(), tmp_path / "a.png")
    save_figure(draw(), tmp_path / "b.png")
    assert (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()
    assert (tmp_path / "a.svg").read_bytes() == (tmp_path / "b.svg").read_bytes()
    with Image.open(tmp_path / "a.png") as image:
        assert image.size == (600, 450)
    svg = (tmp_path / "a.svg").read_text(encoding="utf-8")
    assert "<dc:date>" not in svg and "Matplotlib v" not in svg


def test_figures_drawn_in_two_processes_are_the_bytes_of_one(tmp_path):
    """save_figures shares the figures out over a forked process: every file is written, byte for byte
    what save_figure writes alone, the tables' writer runs meanwhile, and a figure that cannot be drawn in
    the other process fails the call (it is not silently missing)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from demid.io import save_figure, save_figures

    def draw(k):
        fig = Figure(figsize=(2, 1.5))
        ax = fig.subplots()
        ax.plot([0, 1], [k, 0], label=f"line {k}")
        ax.set_xlabel(tex_label("μ_r,Po"))
        ax.legend()
        return fig

    alone, shared = tmp_path / "alone", tmp_path / "shared"
    for k in range(5):
        save_figure(draw(k), alone / f"f{k}.png")
    written = []
    save_figures({shared / f"f{k}.png": draw(k) for k in range(5)}, also=lambda: written.append("tables"))
    assert written == ["tables"]
    for k in range(5):
        for suffix in (".png", ".svg"):
            assert (shared / f"f{k}{suffix}").read_bytes() == (alone / f"f{k}{suffix}").read_bytes()

    class Broken(Figure):
        def draw(self, renderer):
            raise ValueError("cannot draw")

    with pytest.raises(RuntimeError, match="b.png"):  # the larger figure goes to the other process
        save_figures({tmp_path / "a.png": draw(0), tmp_path / "b.png": Broken()})


@pytest.mark.parametrize("log_factor", [False, True])
def test_stored_fit_prints_what_a_refit_prints(log_factor):
    """The report reads the fits and their statistics as the fit step stored them (parquet round trip)
    instead of fitting again: block ANOVA, coefficients and actual-unit coefficients are the same numbers,
    bit for bit, as from the statsmodels fit itself (a failed run of y2 included)."""
    from demid.io import as_stored
    from demid.report.rsm import stored_surfaces
    from demid.spec import MaterialSpec
    from demid.surrogate import coding_from_frame, fit_frames, fit_material

    def responses(x):
        a, b = x[:, 0], x[:, 1]
        return {"y1": 50 + 8 * a - 3 * b + 4 * a * b - 6 * a**2 - 2 * b**2, "y2": 20 + a + 5 * b**2}

    table = make_ccd_table(responses, [1.0, 2.0], [3.0, 6.0], noise=0.4, seed=7, decimals=4)
    table.loc[3, "y2"] = np.nan
    material = {"data": "t.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
                "factors": {"x1": {"lower": 1.0, "upper": 3.0, "scale": "log" if log_factor else "linear"},
                            "x2": {"lower": 2.0, "upper": 6.0}},
                "responses": {"y1": {}, "y2": {}}, "scenarios": {}}
    spec = MaterialSpec.from_material("m", material)
    table = as_stored(table)
    refits = fit_material(table, spec)
    frames = {name: as_stored(frame) for name, frame in fit_frames(refits).items()}
    surfaces = stored_surfaces(frames["fits"], frames["anova"], table, spec)
    assert [s.response for s in surfaces] == ["y1", "y2"]
    for refit, surface in zip(refits, surfaces):
        pd.testing.assert_frame_equal(surface.anova, anova_table(refit.anova_frame()), check_exact=True)
        pd.testing.assert_frame_equal(surface.coefficients, coefficient_table(refit.coefficients()),
                                      check_exact=True)
        assert np.array_equal(surface.actual, refit.coefficients()["coefficient_actual"])
        assert not surface.blocked
        assert coding_from_frame(frames["fits"], spec.factor_names) == refit.coding


