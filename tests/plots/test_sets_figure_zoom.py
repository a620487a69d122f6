"""The zoom panel of a thin set is drawn from the surrogates on its own fine grid: the band's pixels
match the closed form at the panel's resolution, not the evaluation grid's blocks."""

from __future__ import annotations

import numpy as np

from demid.admissibility import evaluate_scenarios
from demid.design import quadratic_terms
from demid.plots.sets import ZOOM_PIXELS, sets_figure
from demid.scenario import judged_scenarios
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate


def _thin_band_material():
    # y = 10 + x2 on x1, x2 in [-1, 1]; |y - 10.2| <= 0.002*10.2 is the strip |x2 - 0.2| <= 0.0204:
    # about 2 % of the range, so the figure zooms.
    cfg = {
        "data": "unused.csv",
        "factors": {"x1": {"lower": -1.0, "upper": 1.0}, "x2": {"lower": -1.0, "upper": 1.0}},
        "design": {"type": "ccd", "alpha": 1.0},
        "responses": {"y": {"target": 10.2}},
        "scenarios": {"band": {"observables": ["y"], "tolerance": 0.002}},
    }
    terms = quadratic_terms(2)
    coefficients = np.zeros(len(terms))
    coefficients[0] = 10.0
    coefficients[[k for k, t in enumerate(terms) if tuple(t) == (0, 1)][0]] = 1.0
    surrogate = Surrogate("y", ["x1", "x2"], terms, coefficients, np.zeros((6, 6)), 0.0, 7)
    return MaterialSpec.from_material("m", cfg), {"y": surrogate}


def test_zoom_panel_resolves_a_thin_band_at_figure_resolution():
    spec, surrogates = _thin_band_material()
    n = 41  # coarse evaluation grid: a cell is 0.05 high, the band 0.041
    _, sets = evaluate_scenarios(surrogates, spec, n)
    fig = sets_figure(spec, sets, n, judged_scenarios(spec, surrogates, 2.0))
    zoom_images = fig.axes[1].get_images()
    assert zoom_images, "the thin set must get a zoom panel with its own image"
    image = np.asarray(zoom_images[0].get_array(), dtype=float)
    assert image.shape == (ZOOM_PIXELS, ZOOM_PIXELS)
    x0, x1, y0, y1 = zoom_images[0].get_extent()
    ys = np.linspace(y0, y1, ZOOM_PIXELS)
    inside = np.abs(ys - 0.2) <= 0.002 * 10.2
    # every column is the same strip; its rows are exactly the closed-form band
    assert np.array_equal(image[:, 0] > 0, inside)
    assert np.array_equal(image[:, -1] > 0, inside)
    assert y0 < 0.2 - 0.0204 and y1 > 0.2 + 0.0204 and (y1 - y0) < 0.5  # zoomed around the band
