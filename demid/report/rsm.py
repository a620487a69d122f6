"""Response-surface output as Design-Expert and R's rsm print it, from one fitted quadratic.

Per response: the fitted equation in coded and in actual units, the ANOVA by term block
(linear, two-factor interaction, pure quadratic; each block's partial sum of squares, i.e. the
extra sum of squares of dropping it from the full model), residual split into lack of fit and
pure error, the coefficient table and the canonical analysis of the surface.  Every statistic is the
fit's (:class:`~demid.surrogate.SurrogateFit`, its statsmodels OLS in coded units), as the fit step stored
it (``fits/{material}.parquet``, ``fits/{material}_anova.parquet``, ``fits/{material}.json``): this module
only lays the numbers out.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..precision import ROUND_OFF
from ..surrogate import TERM_BLOCKS

#: Rows of the stored ANOVA that split the row above them: the term groups split the model, lack of fit and
#: pure error the residual.
SPLIT_ROWS = frozenset(TERM_BLOCKS) | {"Higher order", "Lack of fit", "Pure error"}


def anova_table(anova: pd.DataFrame) -> pd.DataFrame:
    """One response's ANOVA as the fit step stored it (:meth:`~demid.surrogate.SurrogateFit.anova_frame`), for
    printing: a split row marked ``↳``."""
    frame = anova[["source", "df", "sum_sq", "mean_sq", "F", "p_value"]].reset_index(drop=True)
    frame["source"] = [f"↳ {s}" if s in SPLIT_ROWS else s for s in frame["source"]]
    return frame


def coefficient_table(coefficients: pd.DataFrame) -> pd.DataFrame:
    """Estimate (coded units), standard error, t and p per term, from the fit's coefficient table
    (:meth:`~demid.surrogate.SurrogateFit.coefficients`, or the stored ``fits/{material}.parquet`` rows)."""
    return pd.DataFrame({"term": coefficients["term"].to_numpy(),
                         "estimate": coefficients["coefficient_coded"].to_numpy(),
                         "std_error": coefficients["std_err_coded"].to_numpy(),
                         "t": coefficients["t_value"].to_numpy(), "p_value": coefficients["p_value"].to_numpy()})


@dataclass(frozen=True)
class StoredSurface:
    """One response's fitted quadratic as the fit step stored it, laid out for printing."""

    response: str
    coefficients: pd.DataFrame  # coefficient_table: coded units
    actual: np.ndarray          # the coefficients in actual units, in the same order
    anova: pd.DataFrame         # anova_table
    blocked: bool               # the fit carries a block term (demid.blocks)


def stored_surfaces(fits: pd.DataFrame, anova: pd.DataFrame, table: pd.DataFrame, spec) -> list[StoredSurface]:
    """Every fitted response of ``spec``, in its order, from ``fits/{material}.parquet``, its ANOVA table and
    the validated runs: nothing is fitted again."""
    from ..blocks import block_labels

    out = []
    for response in [r for r in spec.response_names if (fits["response"] == r).any()]:
        stored = fits[fits["response"] == response].reset_index(drop=True)
        fitted_runs = table.loc[np.isfinite(table[response].to_numpy(dtype=float))]
        out.append(StoredSurface(response, coefficient_table(stored), stored["coefficient_actual"].to_numpy(),
                                 anova_table(anova[anova["response"] == response]),
                                 block_labels(fitted_runs) is not None))
    return out


def term_symbol(name: str, symbols: dict[str, str]) -> str:
    """A model term in ``symbols`` (factor -> letter or label): ``a:b`` as ``A·B``, ``a^2`` as ``A²``; the
    intercept as "–"."""
    if name == "Intercept":
        return "–"
    return ":".join(symbols.get(p.split("^")[0], p.split("^")[0]) + ("²" if p.endswith("^2") else "")
                    for p in name.split(":")).replace(":", "·")




def equation(names: list[str], coefficients, symbols: dict[str, str], response: str, digits: int = 4) -> str:
    """``y = b0 + b1·x1 − …`` with ``·`` between factors of a term; terms at round-off are left out."""
    # coefficients at round-off of the largest are terms the data do not carry (1.8e-12·A·B beside terms of
    # order 1): left out
    floor = ROUND_OFF * max((abs(float(b)) for b in coefficients), default=0.0)
    b0 = float(coefficients[0])
    text = f"{response} = {0.0 if abs(b0) <= floor else b0:.{digits}g}"
    for name, b in zip(names[1:], coefficients[1:]):
        if abs(float(b)) <= floor:
            continue
        text += f" {'−' if b < 0 else '+'} {abs(b):.{digits}g}·" + term_symbol(name, symbols)
    return text


def canonical_text(canonical: dict, factors: list[str], spec, letters: dict[str, str], label: str) -> str:
    """The canonical analysis in words (as rsm's ``canonical()``): eigenvalues and eigenvectors of the
    quadratic part, the kind, the stationary point (coded and actual) and whether it lies inside the
    region of the runs; for a ridge, the ridge point nearest the design centre and the ridge direction.
    ``canonical`` is the fit JSON's entry (``fits/{material}.json``)."""
    names = [letters[f] for f in factors]

    def number(v, digits):  # the stored JSON writes NaN (and what overflowed) as null
        return "–" if v is None or v != v else f"{v:.{digits}g}"

    def point(coded, actual):
        return (", ".join(f"{n} = {number(v, 3)}" for n, v in zip(names, coded)) + " (coded), "
                + ", ".join(f"{spec.factor(f).label} = {number(v, 4)}" for f, v in zip(factors, actual)))

    def vector(vec):
        return "(" + ", ".join(f"{n} {x:+.3f}" for n, x in zip(names, vec)) + ")"

    values = ", ".join(f"{v:.4g}" for v in canonical["eigenvalues"])
    text = (f"Canonical analysis (eigenvalues below {canonical['threshold']:.3g}, a tenth of the largest, count as "
            f"zero): eigenvalues {values}; eigenvectors " + "; ".join(vector(v) for v in canonical["eigenvectors"])
            + ". ")
    finite = all(v is not None and v == v for v in canonical["stationary_coded"])  # null/NaN: B is singular
    where = "inside" if canonical["inside"] else "outside"
    stationary = (f"stationary point {point(canonical['stationary_coded'], canonical['stationary_actual'])}, "
                  f"predicted {label} = {number(canonical['predicted'], 4)}, {where} the region of the runs" if finite
                  else "no stationary point (the quadratic part is singular)")
    if "ridge" in canonical["kind"]:
        ridge = "; ".join(vector(v) for v in canonical.get("ridge_directions", []))
        slope = ", ".join(f"{v:.3g}" for v in canonical.get("ridge_slopes", []))
        text += (f"A **{canonical['kind']}** along {ridge} (slope {slope} per coded unit): the response "
                 + ("keeps rising one way along it, up to the edge of the region" if canonical["kind"] == "rising ridge"
                    else "hardly changes along it, a line of near-equal responses")
                 + f"; {stationary}. The ridge point nearest the design centre, within the region: "
                 f"{point(canonical['ridge_point_coded'], canonical['ridge_point_actual'])}, predicted {label} = "
                 f"{number(canonical['ridge_predicted'], 4)}.")
    else:
        text += f"A **{canonical['kind']}**: {stationary}."
    return text
