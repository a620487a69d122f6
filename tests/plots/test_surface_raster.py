"""The response-surface figure draws every design run; above RASTER_ABOVE_POINTS runs they are one image inside
the SVG (the PNG is the same), at a CCD's size vector markers."""

from __future__ import annotations

import sys
from pathlib import Path

import pandas as pd
import pytest

from demid.config import load_config
from demid.plots import surface_figure_from_surrogates
from demid.spec import MaterialSpec
from demid.surrogate import fit_response

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
from scaling import write_study  # noqa: E402  (the benchmark's generated study)


@pytest.mark.parametrize("runs", [60, 2500])
def test_design_runs_are_one_image_in_the_svg_only_by_the_thousand(runs, tmp_path):
    config_path = write_study(tmp_path, 2, runs)
    config = load_config(config_path, base_dir=tmp_path)
    spec = MaterialSpec.from_config("study", config)
    table = pd.read_csv(tmp_path / "study.csv")
    surrogates = {r: fit_response(table, list(spec.domain.factors), r, alpha=1.0).surrogate()
                  for r in spec.response_names}
    fig = surface_figure_from_surrogates(surrogates, spec, table, n=21)
    drawn = [line for ax in fig.axes for line in ax.get_lines() if line.get_label() == "design runs"]
    assert drawn and all(len(line.get_xdata()) == runs for line in drawn)
    assert all(line.get_rasterized() is (runs > 2000) for line in drawn)
