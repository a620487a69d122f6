"""The observable ranking of a four-factor study, where feasible fractions come from scrambled Sobol points: called
as a user calls it (no ``sobol_points``), each set's fraction agrees with a fine uniform Monte Carlo count of its
bands to a small fraction of a percentage point."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.uncertainty.ranking import rank_observable_sets

FACTORS = ("a", "b", "c", "d")
BOX = Domain(FACTORS, (0.0,) * 4, (1.0,) * 4)


@dataclass
class _Posterior:
    information_gain_bits: float
    information_gain_error_bits: float


def _linear(name: str, coefficients) -> Surrogate:
    """y = c0 + c1 a + c2 b + c3 c + c4 d."""
    terms = [(0, 0, 0, 0)] + [tuple(int(i == j) for j in range(4)) for i in range(4)]
    return Surrogate(name, list(FACTORS), terms, np.asarray(coefficients, dtype=float), np.eye(5) * 1e-6, 0.01, 10)


def test_four_factor_fractions_are_their_bands_by_default():
    coefficients = {"y0": [10.0, 3.0, -2.0, 1.5, 0.5], "y1": [-8.0, 1.0, 2.5, -0.7, 3.0]}
    surrogates = {n: _linear(n, c) for n, c in coefficients.items()}
    at = np.array([0.45, 0.55, 0.5, 0.4])
    targets = {n: float(c[0] + np.dot(c[1:], at)) for n, c in coefficients.items()}
    tolerance = 0.07
    posteriors = {("y0",): _Posterior(1.0, 0.1), ("y1",): _Posterior(0.8, 0.1), ("y0", "y1"): _Posterior(2.0, 0.1)}
    frame = rank_observable_sets(surrogates, BOX, ["y0", "y1"], targets, {"y0": 1.0, "y1": 1.0}, tolerance, 11,
                                 posteriors=posteriors)

    u = np.random.default_rng(7).uniform(0, 1, (400_000, 4))
    inside = {n: np.abs(c[0] + u @ np.asarray(c[1:]) - targets[n]) <= tolerance * abs(targets[n])
              for n, c in coefficients.items()}
    expected = {"y0": inside["y0"].mean(), "y1": inside["y1"].mean(), "y0+y1": (inside["y0"] & inside["y1"]).mean()}
    assert 0.03 < expected["y0+y1"] < expected["y1"] < expected["y0"] < 0.5  # bands that cut the box
    got = dict(zip(frame["observables"], frame["feasible_fraction_pct"]))
    assert set(got) == set(expected)
    for name, fraction in expected.items():
        # Monte Carlo standard error below 0.08 points; 2**16 Sobol points much closer still
        assert got[name] == pytest.approx(100 * fraction, abs=0.3), name
