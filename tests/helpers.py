"""Builders of small synthetic design tables for tests."""

from __future__ import annotations

import numpy as np
import pandas as pd

from demid.design import ccd_points


def make_ccd_table(coef_fn, lower, upper, alpha=1.41421, center_runs=5, noise=0.0, seed=0, decimals=None):
    """A CCD over the box [lower, upper] (axial points on the bounds) with responses from ``coef_fn``.

    ``coef_fn(actual_points) -> dict[name, values]``.  Runs are shuffled (run order != standard order).
    """
    rng = np.random.default_rng(seed)
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    coded = ccd_points(len(lower), alpha, center_runs)
    center, unit = (lower + upper) / 2, (upper - lower) / (2 * alpha)
    actual = coded * unit + center
    responses = coef_fn(actual)
    order = rng.permutation(len(coded))
    data = {"run": np.arange(1, len(coded) + 1)}
    for i in range(len(lower)):
        data[f"x{i + 1}"] = actual[order, i]
    for name, values in responses.items():
        values = np.asarray(values, float) + noise * rng.standard_normal(len(coded))
        data[name] = values[order] if decimals is None else np.round(values[order], decimals)
    return pd.DataFrame(data)
