"""Synthetic CCD tables with one planted defect, for the model-criticism tests and benchmark.

A table is what a DEM calibration study produces: a central composite design in
actual factor units, a randomised run order in the ``run`` column and one
response.  The response is a random quadratic (in coded units) plus Gaussian
noise of standard deviation ``noise``, with at most one planted defect:

``term``       the response also contains ``size * noise * x^term`` (coded units,
               factorial points at +-1, axial points at +-alpha);
``log``        the response is log-normal: log(y) is a quadratic spanning ``size``
               nepers over the design, with ``log_noise`` multiplicative noise;
``outlier``    one run is shifted by ``size * noise`` (sign random);
``drift``      the response drifts linearly with run order, ``size * noise`` from
               the first to the last run;
``het``        the noise standard deviation grows with one factor, the ratio of the
               standard deviation at the top axial level to the bottom one being
               ``size``;
``clean``      no defect.

It also builds level-2 cases: three mortar-like observables (slump diameters
after 5, 10 and 15 strokes) whose targets are met exactly at a known point, with
optionally one target shifted by a multiple of the tolerance.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from demid.admissibility import Domain
from demid.design import (Coding, ccd_points, cubic_terms, model_matrix, parse_term, quadratic_terms,
                          rotatable_alpha, term_name)
from demid.surrogate import Surrogate

FACTORS = {2: ["mu_r", "gamma"], 3: ["mu_s", "mu_r", "gamma"]}
RANGES = {"mu_s": (0.05, 0.95), "mu_r": (0.0757, 0.9243), "gamma": (2.0, 14.0)}
CENTER_RUNS = {2: 5, 3: 6}
KINDS = ("clean", "term", "log", "outlier", "drift", "het")


@dataclass(frozen=True)
class Planted:
    """What was hidden in a table: kind, size and where (term name, run value or factor)."""

    kind: str
    size: float
    term: str | None = None
    run: int | None = None
    factor: str | None = None
    runs: tuple[int, ...] = ()  # every run a ``slip`` defect touched
    signal: tuple[float, ...] = ()  # the defect's noise-free shift of the mean, per table row (off-catalogue)


def random_domain(rng: np.random.Generator, k: int, log_mask: int, lower=(-1.0, 1.0), width=(0.5, 2.0)):
    """A search range over factors f0..f{k-1} drawn in search units (log10 for the factors whose bit of
    ``log_mask`` is set): lower ends uniform in ``lower``, widths uniform in ``width``.  (domain, lo_s, hi_s)."""
    log = tuple(bool(log_mask >> i & 1) for i in range(k))
    lo_s = rng.uniform(*lower, k)
    hi_s = lo_s + rng.uniform(*width, k)
    domain = Domain(tuple(f"f{i}" for i in range(k)), tuple(np.where(log, 10.0 ** lo_s, lo_s)),
                    tuple(np.where(log, 10.0 ** hi_s, hi_s)), log)
    return domain, lo_s, hi_s


def design(n_factors: int, alpha: float | None = None, replicates: int = 1
           ) -> tuple[list[str], Coding, np.ndarray, float]:
    """Factor names, coding and coded CCD points (standard order) of the test designs.

    ``replicates`` > 1 repeats every factorial and axial point (DEM runs with
    different particle-generation seeds); the centre runs are not repeated.
    """
    factors = FACTORS[n_factors]
    alpha = rotatable_alpha(n_factors) if alpha is None else alpha
    n_center = CENTER_RUNS[n_factors]
    coded = ccd_points(n_factors, alpha, n_center)
    coded = np.vstack([np.tile(coded[:-n_center], (replicates, 1)), coded[-n_center:]])
    lo = np.array([RANGES[f][0] for f in factors])
    hi = np.array([RANGES[f][1] for f in factors])
    coding = Coding(tuple(factors), tuple((lo + hi) / 2), tuple((hi - lo) / (2 * alpha)))
    return factors, coding, coded, alpha


def random_quadratic(rng: np.random.Generator, n_factors: int) -> np.ndarray:
    """Coded-unit coefficients of a DEM-like response (~100, strong main effects)."""
    terms = quadratic_terms(n_factors)
    coef = np.empty(len(terms))
    for j, t in enumerate(terms):
        order = sum(t)
        coef[j] = 100.0 if order == 0 else rng.normal(0, 8.0 if order == 1 else 3.0)
    return coef


def ccd_table(seed: int, n_factors: int = 2, kind: str = "clean", size: float = 0.0, *,
              term: str | None = None, factor: str | None = None, noise: float = 1.0,
              log_noise: float = 0.03, alpha: float | None = None, replicates: int = 1,
              response: str = "y") -> tuple[pd.DataFrame, Planted]:
    """One CCD table (rows in run order) with the defect ``kind`` of magnitude ``size`` planted.

    ``term``/``factor`` choose where a ``term``/``het`` defect goes (default: random
    cubic term / random factor).
    """
    if kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}")
    rng = np.random.default_rng(seed)
    factors, coding, coded, alpha = design(n_factors, alpha, replicates)
    n = len(coded)
    run_of_row = rng.permutation(n) + 1
    quad = model_matrix(coded, quadratic_terms(n_factors))
    mean = quad @ random_quadratic(rng, n_factors)
    eps = rng.normal(size=n)
    planted = Planted(kind, size)
    if kind == "log":
        shape = quad @ random_quadratic(rng, n_factors)
        shape = (shape - shape.mean()) / (shape.max() - shape.min())
        y = np.exp(np.log(100.0) + size * shape + log_noise * eps)
    else:
        y = mean + noise * eps
    if kind == "term":
        name = term or term_name(cubic_terms(n_factors)[rng.integers(len(cubic_terms(n_factors)))], factors)
        y = y + size * noise * model_matrix(coded, [parse_term(name, factors)])[:, 0]
        planted = Planted(kind, size, term=name)
    elif kind == "outlier":
        row = int(rng.integers(n))
        y[row] += size * noise * rng.choice([-1.0, 1.0])
        planted = Planted(kind, size, run=int(run_of_row[row]))
    elif kind == "drift":
        y = y + size * noise * (run_of_row - (n + 1) / 2) / (n - 1)
    elif kind == "het":
        name = factor or factors[int(rng.integers(n_factors))]
        j = factors.index(name)
        y = mean + noise * eps * size ** (coded[:, j] / (2 * alpha))
        planted = Planted(kind, size, factor=name)
    table = pd.DataFrame(coding.to_actual(coded), columns=factors)
    table.insert(0, "run", run_of_row)
    table[response] = y
    return table.sort_values("run").reset_index(drop=True), planted


# --------------------------------------------------------------------------- level 2
MORTAR_OBSERVABLES = ("d5", "d10", "d15")
EXTENDED_OBSERVABLES = ("d5", "d10", "d15", "d20")


@dataclass(frozen=True)
class Level2Case:
    surrogates: dict[str, Surrogate]
    domain: Domain
    targets: dict[str, float]
    tolerance: float
    true_point: dict[str, float]
    biased: str | None


def later_runs(seed: int, n_factors: int, runs: list[dict]) -> tuple[pd.DataFrame, np.ndarray]:
    """Runs proposed after a ``ccd_table(seed, n_factors)`` table, as its generator would have made them: its
    clean quadratic plus unit noise (a stream of their own), numbered after the table's runs.  Returns the runs
    (``run``, the factors, ``y``) and their coded points; a caller adds the defect that goes on after the table."""
    rng = np.random.default_rng(seed)
    factors, coding, coded, _ = design(n_factors)
    n = len(coded)
    rng.permutation(n)  # as ccd_table draws the run order before the coefficients
    coef = random_quadratic(rng, n_factors)
    new = pd.DataFrame([{f: r[f] for f in factors} for r in runs])
    new_coded = coding.to_coded(new[factors].to_numpy(dtype=float))
    noise = np.random.default_rng(10 ** 6 + seed).normal(size=len(new))
    new["y"] = model_matrix(new_coded, quadratic_terms(n_factors)) @ coef + noise
    new.insert(0, "run", np.arange(n + 1, n + 1 + len(new)))
    return new, new_coded


def mortar_case(seed: int, biased: str | None = None, shift: float = 4.0,
                tolerance: float = 0.02, observables: tuple[str, ...] = MORTAR_OBSERVABLES) -> Level2Case:
    """Three mortar-like diameter surrogates, targets met exactly at a random interior point.

    The diameters grow with the stroke number and depend on rolling friction and
    surface energy with gradient directions about 25-30 degrees apart (the
    sequence is informative but correlated, as in the source study).  ``observables``
    may add a fourth reading (``EXTENDED_OBSERVABLES``).  With
    ``biased`` set, that observable's target is shifted by ``shift * tolerance``
    (relative, random sign): the hidden discrepancy.
    """
    rng = np.random.default_rng(seed)
    factors = ["mu_r", "gamma"]
    lo = np.array([RANGES[f][0] for f in factors])
    hi = np.array([RANGES[f][1] for f in factors])
    coding = Coding(tuple(factors), tuple((lo + hi) / 2), tuple((hi - lo) / 2))
    terms = quadratic_terms(2)
    base = rng.uniform(-0.4, 0.4)
    surrogates = {}
    for i, name in enumerate(observables):
        angle = np.deg2rad(-60.0 + 28.0 * i + rng.normal(0, 3.0))
        level = 110.0 + 10.0 * i
        slope = 0.12 * level
        coded_coef = np.array([level, slope * np.cos(angle + base), slope * np.sin(angle + base),
                               rng.normal(0, 1.0), rng.normal(0, 1.5), rng.normal(0, 1.5)])
        # coded -> actual coefficients: exact interpolation on a 3x3 grid of the same quadratic space
        pts = np.array(np.meshgrid([-1, 0, 1], [-1, 0, 1], indexing="ij")).reshape(2, -1).T
        actual = np.linalg.lstsq(model_matrix(coding.to_actual(pts), terms),
                                 model_matrix(pts, terms) @ coded_coef, rcond=None)[0]
        surrogates[name] = Surrogate(name, factors, terms, actual, np.zeros((6, 6)), 1.0, 7)
    x0 = coding.to_actual(rng.uniform(-0.5, 0.5, size=2))
    targets = {k: float(s.predict(x0[None, :])[0]) for k, s in surrogates.items()}
    if biased is not None:
        targets[biased] *= 1.0 + rng.choice([-1.0, 1.0]) * shift * tolerance
    domain = Domain(tuple(factors), tuple(lo), tuple(hi))
    return Level2Case(surrogates, domain, targets, tolerance, dict(zip(factors, map(float, x0))), biased)


# --------------------------------------------------------------------------- defects outside the catalogue
#: Defects the level-1 catalogue has no cause for (``slip`` has one: ``factor_level``).
OFF_CATALOGUE = ("slip", "plateau", "step", "batch", "hidden", "multiplicative")


def off_catalogue_table(seed: int, n_factors: int = 2, kind: str = "slip", size: float = 1.0, *,
                        n_slipped: int = 1, slip: float = 0.1, noise: float = 1.0, factor: str | None = None,
                        rows: tuple[int, ...] | None = None, response: str = "y") -> tuple[pd.DataFrame, Planted]:
    """One CCD table (rows in run order) with a defect that is not one of :data:`KINDS`.

    ``slip``            ``n_slipped`` runs were simulated at ``slip`` times the recorded value of one
                        factor (a unit or decimal slip in the simulation input); the table records the
                        design value.  ``Planted.runs`` are the slipped runs,
                        ``Planted.factor`` the factor; ``size`` is unused.
    ``plateau``         the response rises along one factor and saturates: ``size * noise * min(a, 0.3)``
                        (coded units, then flat).
    ``step``            a jump of ``size * noise`` where the coded factors sum to more than 0.5 (a regime
                        change in one corner region of the design).
    ``batch``           three random non-centre runs (unrelated to the run order) shifted by ``size * noise``
                        (an unrecorded change of software, seed family or hardware for a batch of runs).
    ``hidden``          an unrecorded factor u ~ U(-1, 1), varied between the non-centre runs (the centre
                        runs repeat its nominal value 0), enters as ``size * noise * u^3``.
    ``multiplicative``  noise proportional to the mean, sd ``size`` % of the response (mean ~100).

    For ``step``, ``batch`` and ``hidden``, ``Planted.runs`` are the runs moved by three noise SDs or more.
    ``factor`` and ``rows`` (indices into the standard-order design) fix the slipped factor and runs.
    """
    rng = np.random.default_rng(seed)
    factors, coding, coded, alpha = design(n_factors)
    n = len(coded)
    run_of_row = rng.permutation(n) + 1
    terms = quadratic_terms(n_factors)
    coef = random_quadratic(rng, n_factors)
    eps = rng.normal(size=n)
    actual = coding.to_actual(coded)
    true_coded = coded.copy()
    planted = Planted(kind, size)
    extra = np.zeros(n)
    if kind == "slip":
        j = int(rng.integers(n_factors)) if factor is None else factors.index(factor)
        rows = rng.choice(n, size=n_slipped, replace=False) if rows is None else np.asarray(rows)
        slipped = actual.copy()
        slipped[rows, j] *= slip
        true_coded = coding.to_coded(slipped)
        planted = Planted(kind, slip, run=int(run_of_row[rows[0]]), factor=factors[j],
                          runs=tuple(int(run_of_row[r]) for r in rows))
    elif kind == "plateau":
        j = int(rng.integers(n_factors))
        extra = size * noise * np.minimum(coded[:, j], 0.3)
        planted = Planted(kind, size, factor=factors[j])
    elif kind == "step":
        extra = size * noise * (coded.sum(axis=1) > 0.5)
    elif kind == "batch":
        outer = np.flatnonzero(np.any(coded != 0, axis=1))
        extra[rng.choice(outer, size=3, replace=False)] = size * noise
    elif kind == "hidden":
        extra = size * noise * rng.uniform(-1, 1, size=n) ** 3 * np.any(coded != 0, axis=1)
    elif kind != "multiplicative":
        raise ValueError(f"unknown kind {kind!r}")
    if kind in ("step", "batch", "hidden"):  # the runs the defect moved by three noise SDs or more
        planted = Planted(kind, size, runs=tuple(int(r) for r in run_of_row[np.abs(extra) >= 3 * noise]))
    mean = model_matrix(true_coded, terms) @ coef
    y = mean + extra + (mean * size / 100 * eps if kind == "multiplicative" else noise * eps)
    table = pd.DataFrame(actual, columns=factors)
    table.insert(0, "run", run_of_row)
    table[response] = y
    order = np.argsort(run_of_row)
    signal = (mean - model_matrix(coded, terms) @ coef + extra)[order]
    return table.iloc[order].reset_index(drop=True), replace(planted, signal=tuple(float(v) for v in signal))
