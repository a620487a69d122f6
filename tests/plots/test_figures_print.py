"""Figures fit a two-column page and say what they show: widths over the demo, equations without
round-off terms, constant axes without offsets, plain log labels, legends with configured labels."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.figure import Figure
from PIL import Image

from demid.plots.layout import PAGE_WIDTH_IN, hold_constant_axis, panel_grid
from demid.plots.uncertainty import spaced_ticks
from demid.report.rsm import equation


@pytest.mark.workflow
def test_every_demo_figure_fits_a_page_width(demo_run):
    pngs = sorted((demo_run / "results").rglob("*.png"))
    assert pngs, "the demo made no figure"
    too_wide = []
    for path in pngs:
        with Image.open(path) as im:
            dpi = im.info["dpi"][0]
            width_in = im.size[0] / dpi
        if width_in > 7.5:
            too_wide.append(f"{path.name}: {width_in:.2f} in")
    assert not too_wide, too_wide


@pytest.mark.parametrize("n, ncol, nrow", [(1, 1, 1), (2, 2, 1), (3, 2, 2), (4, 2, 2), (5, 2, 3)])
def test_panels_wrap_instead_of_shrinking(n, ncol, nrow):
    rows, cols, (width, height) = panel_grid(n, 3.6, 3.0)
    assert (rows, cols) == (nrow, ncol)
    assert width <= PAGE_WIDTH_IN
    assert height == pytest.approx(3.0 * nrow)


def test_equation_leaves_out_round_off_terms():
    names = ["Intercept", "A", "B", "A:B", "B:C"]
    text = equation(names, np.array([120.0, 3.5, -2.25, 1.819e-12, 0.0]), {"A": "A", "B": "B", "C": "C"}, "S")
    assert text == "S = 120 + 3.5·A − 2.25·B"
    # a small but real coefficient stays
    kept = equation(names[:3], np.array([1.0, 1e-6, 2.0]), {"A": "A", "B": "B"}, "y")
    assert kept == "y = 1 + 1e-06·A + 2·B"


def test_a_constant_series_gets_a_readable_axis():
    fig = Figure()
    ax = fig.subplots()
    ax.plot([1, 2, 3], [0.3364] * 3)
    ax.plot([1, 2, 3], [0.3364 + 1e-13] * 3)
    hold_constant_axis(ax)
    lo, hi = ax.get_ylim()
    assert lo == pytest.approx(0.3364 * 0.95) and hi == pytest.approx(0.3364 * 1.05)
    assert ax.yaxis.get_major_formatter().get_useOffset() is False
    # a varying series keeps its autoscaled range
    other = Figure().subplots()
    other.plot([1, 2], [0.1, 0.9])
    before = other.get_ylim()
    hold_constant_axis(other)
    assert other.get_ylim() == before


def test_log_tick_labels_are_spaced():
    assert spaced_ticks([0.5, 1, 2, 3, 5, 7.5, 10, 15, 20]) == {0.5, 1, 2, 3, 5, 7.5, 15}
    assert spaced_ticks([1, 10, 100]) == {1, 10, 100}


def test_posterior_legend_uses_configured_labels():
    from types import SimpleNamespace

    from demid.plots.uncertainty import posterior_figure

    x = np.linspace(0, 1, 50)
    post = SimpleNamespace(factors=["mu_r"], observables=("angle_of_repose",), axes_actual=[x],
                           marginals=[np.exp(-((x - 0.4) / 0.1) ** 2)], credible_lower=[0.25],
                           credible_upper=[0.55], log=[False], information_gain_bits=1.5)
    fig = posterior_figure({"a": post}, "Study", observable_labels={"angle_of_repose": "$\\theta$"})
    texts = [t.get_text() for legend in fig.legends for t in legend.get_texts()]
    assert texts == ["$\\theta$ (1.50 bits)"]
    assert not any("angle_of_repose" in t for t in texts)


def test_report_text_speaks_in_configured_labels():
    from demid.story.words import labelled
    from demid.spec import MaterialSpec

    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"},
        "factors": {"mu_s": {"lower": 0.1, "upper": 0.9, "label": "μ_s"}, "e": {"lower": 0.2, "upper": 0.8}},
        "responses": {"angle_of_repose": {"target": 24, "label": "θ"}},
        "scenarios": {"a": {"observables": ["angle_of_repose"], "tolerance": 0.04}}})
    text = ("the closest point (mu_s=0.9, e=0.5) misses (angle_of_repose under-predicted); "
            "key materials.m.responses.angle_of_repose.target, file mu_s.csv")
    assert labelled(text, spec) == ("the closest point (μ_s=0.9, e=0.5) misses (θ under-predicted); "
                                    "key materials.m.responses.angle_of_repose.target, file mu_s.csv")


def test_names_read_in_config_then_natural_order():
    from demid.story.words import in_order, natural_key

    assert sorted(["d10", "d15", "d5"], key=natural_key) == ["d5", "d10", "d15"]
    as_read = {"d10": 2, "d15": 3, "d5": 1, "x": 0}  # a JSON file's sorted keys
    assert [k for k, _ in in_order(as_read, ["x"])] == ["x", "d5", "d10", "d15"]


@pytest.mark.parametrize("n_factors", [2, 3])
def test_the_waves_figure_fits_a_page_width(n_factors):
    """One panel per factor plus the fraction panel: 3 or 4 panels of 3.2 in wrap into rows of 2 (≤ 7.2 in)."""
    import pandas as pd

    from demid.plots.waves import waves_figure
    from demid.spec import MaterialSpec

    names = ["a", "b", "c"][:n_factors]
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {f: {"lower": 0.0, "upper": 1.0} for f in names},
                "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02}}}
    spec = MaterialSpec.from_material("m", material, grid_points=11)
    history = pd.DataFrame([{"material": "m", "wave": w, "runs_simulated": 9 * w, "runs_analysed": 9, "scenario": "s",
                             "feasible_fraction_pct": 10.0, "feasible_fraction_of_omega_pct": 10.0 / w, "factor": f,
                             "lower": 0.2, "upper": 0.6, "width": 0.4, "box_lower": 0.0, "box_upper": 1.0}
                            for w in (1, 2) for f in names])
    fig = waves_figure(history, spec)
    width, _ = fig.get_size_inches()
    assert width <= PAGE_WIDTH_IN + 1e-9
    assert sum(ax.get_visible() for ax in fig.axes) == 1 + n_factors
