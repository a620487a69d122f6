"""The residual figure of many runs draws its points as an image in the SVG, every point still there; on
fewer runs (the demo's, every study of a few hundred) the points stay vector markers."""

from __future__ import annotations

import pytest

from demid.criticism import criticize, residual_figure
from demid.io import save_figure
from demid.plots import criticism as criticism_plots
from demid.surrogate import fit_response

from ..generators import FACTORS, ccd_table, design


@pytest.mark.parametrize("raster_runs,rasterized", [(None, False), (5, True)])
def test_points_become_an_image_above_raster_runs(raster_runs, rasterized, monkeypatch, tmp_path):
    table, _ = ccd_table(21, 2, "clean", 0.0, response="y")
    if raster_runs is not None:
        monkeypatch.setattr(criticism_plots, "RASTER_RUNS", raster_runs)
    fit = fit_response(table, FACTORS[2], "y", alpha=design(2)[3])
    fig = residual_figure([fit], [criticize(table, FACTORS[2], "y")], "mortar")
    points = [ax.collections[0] for ax in fig.axes]
    assert [len(c.get_offsets()) for c in points] == [len(table)] * 3  # every run drawn
    assert all(c.get_rasterized() is rasterized for c in points)
    save_figure(fig, tmp_path / "residuals.png")
    svg = (tmp_path / "residuals.svg").read_text()
    assert ("<image" in svg) is rasterized
