"""Run sheets for a first wave of simulations: CCD, Box-Behnken and three-level factorial designs.

A sheet lists the runs in a randomised execution order (``run``) with the standard order
(``std_order``) alongside and one column per factor in actual units.  The search range
LOW:HIGH of each factor is the design's outer extent: the axial points of a CCD sit on it
(factorial points at +-1 = +-range/(2 alpha)), the +-1 levels of Box-Behnken and factorial
designs sit on it.  The config fragment written with the sheet declares the same design, so
the pipeline validates the filled-in sheet as that design.
"""

from __future__ import annotations

import re

from dataclasses import dataclass
from itertools import product

import numpy as np
import pandas as pd

from .design import Coding, box_behnken_points, ccd_points, rotatable_alpha, unreadable_alpha
from .errors import InputError
from .numbers import unusable_number

DESIGN_TYPES = ("ccd", "box_behnken", "factorial")


@dataclass(frozen=True)
class FactorRange:
    name: str
    low: float
    high: float


#: Column and material names the config accepts (its schema's propertyNames pattern).
NAME_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


def check_name(name: str, option: str, what: str = "column name") -> None:
    """Refuse a name the config would refuse (its schema's propertyNames pattern), naming the option."""
    if not NAME_PATTERN.fullmatch(name):
        raise InputError(f"{option}: '{name}' is not a valid {what} (letters, digits, _; starts with a letter)")


def parse_factor(text: str) -> FactorRange:
    """``NAME=LOW:HIGH`` -> FactorRange; raises InputError naming the option."""
    name, sep, rng = text.partition("=")
    low, sep2, high = rng.partition(":")
    name = name.strip()
    if not (sep and sep2 and name):
        raise InputError(f"--factor: expected NAME=LOW:HIGH, found '{text}'")
    check_name(name, "--factor")
    try:
        lo, hi = float(low), float(high)
    except ValueError:
        raise InputError(f"--factor {name}: LOW and HIGH must be numbers, found '{rng}'") from None
    problem = unusable_number(lo, low) or unusable_number(hi, high)
    if problem:
        raise InputError(f"--factor {name}: {problem}")
    if not (np.isfinite(lo) and np.isfinite(hi)) or lo >= hi:
        raise InputError(f"--factor {name}: LOW must be below HIGH, found {low}:{high}")
    return FactorRange(name, lo, hi)


def parse_alpha(text: str, n_factors: int) -> float:
    """``rotatable`` -> (2^k)^(1/4), ``face`` -> 1, or a number >= 1."""
    if text == "rotatable":
        return rotatable_alpha(n_factors)
    if text == "face":
        return 1.0
    try:
        value = float(text)
    except ValueError:
        raise InputError(f"--alpha: expected rotatable, face or a number, found '{text}'") from None
    if not np.isfinite(value) or value < 1:
        raise InputError(f"--alpha: a CCD needs alpha >= 1, found {text}")
    unreadable = unreadable_alpha(value)
    if unreadable:
        raise InputError(f"--alpha {text}: {unreadable}")
    return value


def factorial_points(n_factors: int, center_runs: int) -> np.ndarray:
    """Coded 3^k full factorial (the smallest factorial a quadratic can be fitted to); the grid's
    own centre point counts as the first of ``center_runs`` centre runs."""
    grid = np.array(list(product((-1.0, 0.0, 1.0), repeat=n_factors)))[:, ::-1]
    extra = max(center_runs - 1, 0)
    return np.vstack([grid, np.zeros((extra, n_factors))])


@dataclass(frozen=True)
class RunSheet:
    design_type: str
    factors: tuple[FactorRange, ...]
    alpha: float
    center_runs: int
    coded: np.ndarray  # standard order
    order: np.ndarray  # order[i] = standard-order index of execution run i + 1
    blocks: np.ndarray | None = None  # block number of each standard-order point (demid.blocks), or None

    @property
    def coding(self) -> Coding:
        lo = np.array([f.low for f in self.factors])
        hi = np.array([f.high for f in self.factors])
        outer = self.alpha if self.design_type == "ccd" else 1.0
        return Coding(tuple(f.name for f in self.factors), tuple((lo + hi) / 2), tuple((hi - lo) / (2 * outer)))

    def to_frame(self) -> pd.DataFrame:
        actual = self.coding.to_actual(self.coded)
        frame = pd.DataFrame({"run": np.arange(1, len(self.order) + 1), "std_order": self.order + 1})
        for i, f in enumerate(self.factors):
            # Rounded to 12 significant digits so that the printed sheet is exact to read back.
            frame[f.name] = [float(f"{v:.12g}") for v in actual[self.order, i]]
        if self.blocks is not None:
            frame["block"] = self.blocks[self.order]
        return frame

    def design_config(self) -> dict:
        out = {"type": self.design_type, "center_runs": int(self.center_runs)}
        if self.design_type == "ccd":
            out["alpha"] = float(f"{self.alpha:.12g}")
        return out

    def material_config(self, data_path: str, responses=()) -> dict:
        cfg = {"data": str(data_path), "design": self.design_config(),
               "factors": {f.name: {"lower": f.low, "upper": f.high} for f in self.factors}}
        if responses:
            cfg["responses"] = {r: {} for r in responses}
        return cfg


def coded_points(design_type: str, n_factors: int, alpha: float, center_runs: int) -> np.ndarray:
    if design_type == "ccd":
        return ccd_points(n_factors, alpha, center_runs)
    if design_type == "box_behnken":
        return box_behnken_points(n_factors, center_runs)
    return factorial_points(n_factors, center_runs)


def _check_counts(design_type: str, n_factors: int, center_runs: int) -> None:
    if center_runs < 0:
        raise InputError(f"--center-runs: must be 0 or more, found {center_runs}")
    if design_type == "box_behnken" and not 3 <= n_factors <= 5:
        raise InputError(f"--type box_behnken: needs 3 to 5 factors, found {n_factors}")
    if design_type == "factorial" and center_runs < 1:
        raise InputError("--center-runs: a 3^k factorial contains its centre point, so at least 1")
    if center_runs < 1:
        # without a centre run the intercept and the squared terms cannot be told apart when every run
        # lies on one sphere (rotatable CCD, Box-Behnken), and the pipeline refuses such a table
        raise InputError(f"--center-runs: a {design_type} design needs at least 1 centre run, found 0")
    if not 1 <= n_factors <= 6:
        raise InputError(f"--factor: 1 to 6 factors are supported, found {n_factors}")


def _check_blocks(design_type: str, n_factors: int, center_runs: int, blocks: int, coded: np.ndarray) -> np.ndarray:
    """Block numbers of a blocked CCD's points (the factorial runs split over blocks 1..B-1, the axial runs in
    the last), after checking that every block gets a centre run."""
    from .blocks import ccd_blocks

    if design_type != "ccd":
        raise InputError(f"--blocks: only a ccd design is written in blocks (factorial and axial blocks), not "
                         f"--type {design_type}")
    if blocks not in ((2, 3) if n_factors >= 3 else (2,)):
        raise InputError(f"--blocks: a {n_factors}-factor CCD is run in 2 blocks (factorial | axial)"
                         + (" or 3 (two half-factorials | axial)" if n_factors >= 3 else "")
                         + f", found {blocks}")
    if center_runs < blocks:
        raise InputError(f"--center-runs: {blocks} blocks need a centre run each, found {center_runs} centre runs")
    return ccd_blocks(coded, blocks)


def _check_recoverable(sheet: RunSheet) -> None:
    """The pipeline checks the table against its design and infers the levels from it: make sure it accepts
    this sheet and recovers its coding."""
    from .design_check import check_design

    frame = sheet.to_frame()
    names = [f.name for f in sheet.factors]
    try:
        inferred = check_design(frame, names, sheet.design_config(), "sheet", None)[0]
    except InputError:
        inferred = None
    if inferred is None or not np.allclose(inferred.center, sheet.coding.center, rtol=1e-9, atol=1e-12):
        raise InputError(f"--center-runs {sheet.center_runs}: the pipeline would not recover this "
                         "design's levels from the sheet; choose another number of centre runs")


def generate_sheet(design_type: str, factors: list[FactorRange], *, center_runs: int, alpha: str = "rotatable",
                   seed: int = 0, blocks: int = 1) -> RunSheet:
    """A randomised run sheet of the given design; the same seed gives the same sheet."""
    if design_type not in DESIGN_TYPES:
        raise InputError(f"--type: expected one of {', '.join(DESIGN_TYPES)}, found '{design_type}'")
    names = [f.name for f in factors]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise InputError(f"--factor: '{dupes[0]}' given more than once")
    k = len(factors)
    _check_counts(design_type, k, center_runs)
    a = parse_alpha(alpha, k) if design_type == "ccd" else 1.0
    coded = coded_points(design_type, k, a, center_runs)
    order = np.random.default_rng(seed).permutation(len(coded))
    block_of = None
    if blocks > 1:
        block_of = _check_blocks(design_type, k, center_runs, blocks, coded)
        order = order[np.argsort(block_of[order], kind="stable")]  # block after block, randomised within each
    sheet = RunSheet(design_type, tuple(factors), a, center_runs, coded, order, block_of)
    _check_recoverable(sheet)
    return sheet


def fragment_yaml(sheet: RunSheet, material: str, data_path: str, responses=()) -> str:
    """The config fragment declaring the sheet's design (YAML text with a header comment)."""
    import yaml

    body = yaml.safe_dump({"materials": {material: sheet.material_config(data_path, responses)}},
                          sort_keys=False, default_flow_style=None)
    scenarios = ("# and `scenarios:` (e.g. all: {observables: [...], tolerance: 0.05}) before running the pipeline.\n"
                 "# A factor with a physical limit takes `limits:` (a coefficient of restitution {lower: 0, upper: 1},\n"
                 "# a friction coefficient {lower: 0}): advice to widen its range stops there.\n")
    note = ("# Generated with the run sheet; add a target to each response that is measured,\n"
            if responses else "# Generated with the run sheet; add `responses:` (one per simulated response "
                              "column, with targets),\n") + scenarios
    return note + body
