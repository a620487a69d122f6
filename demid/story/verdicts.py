"""Per factor and scenario, one verdict judged on the plausible interval, the strict interval beside it.

The plausible interval is the span of the plausible set (:data:`~demid.sampling.residuals.PLAUSIBLE_DEFINITION`,
``robust_identifiability.csv``); the strict interval (Table 3) is what the data would identify if the
surrogate and the measurements were exact.  ``tables/verdicts.csv`` is this table.  The verdict rule
itself (:func:`factor_verdict` and :data:`VERDICT_TEXT`, the rule in words) lives here, its width thresholds
(``IDENTIFIED_MAX_WIDTH``, ``UNRESOLVED_MIN_WIDTH``) beside ``BOUND_TOUCH`` in :mod:`demid.sampling.domain`, where
the combinations read them too; the report only renders it.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

# the thresholds are the search range's scale, shared with the combinations: defined beside BOUND_TOUCH
from ..sampling.domain import BOUND_TOUCH, IDENTIFIED_MAX_WIDTH, SIDES_OF, UNRESOLVED_MIN_WIDTH, Domain, sides_at_limit
from .words import unit_text

VERDICT_TEXT = (
    f"**identified**: admissible interval at most {100 * IDENTIFIED_MAX_WIDTH:g} % of the search range wide and "
    f"clear of both bounds (or ending at a physical limit); **bounded**: narrower than "
    f"{100 * UNRESOLVED_MIN_WIDTH:g} % of the range and clear of both bounds (or at a limit); **unresolved**: "
    f"{100 * UNRESOLVED_MIN_WIDTH:g} % of the range or more is admissible, the observables say (almost) nothing "
    f"about the factor; **cut by the search range**: narrower than that but touching a search bound (within "
    f"{100 * BOUND_TOUCH:g} % of the range), so the true interval may extend beyond it (a bound at the factor's "
    f"physical limit, `limits` in the config, cuts nothing: no value lies beyond it); **no admissible point**: no "
    f"point of the domain meets every target. Widths are measured in search units (log10 for log-scaled factors)."
)

VERDICT_COLUMNS = ["material", "scenario", "factor", "strict_lower", "strict_upper", "plausible_lower",
                   "plausible_upper", "verdict", "reason"]

UNINFORMATIVE = "uninformative observable"


def factor_verdict(lower: float, upper: float, bound_lower: float, bound_upper: float, log: bool = False,
                   at_bound: str | None = None, limits: tuple = (None, None)) -> tuple[str, float]:
    """Verdict and width (fraction of the search range) of one admissible interval.

    ``at_bound`` is the interval's ``at_bound`` value from the identifiability table (which
    ends of the search range the set reaches); without it, it is derived the same way
    (:meth:`~demid.sampling.domain.Domain.at_bound`).  An end of the range at the factor's physical
    ``limits`` does not cut the set: no value lies beyond it.
    """
    if not (np.isfinite(lower) and np.isfinite(upper)):
        return "no admissible point", float("nan")
    f = np.log10 if log else (lambda v: v)
    width = (f(upper) - f(lower)) / (f(bound_upper) - f(bound_lower))
    if width >= UNRESOLVED_MIN_WIDTH:
        return "unresolved", width
    if not isinstance(at_bound, str):  # not given (or an older table without the column)
        at_bound = interval_at_bound(lower, upper, bound_lower, bound_upper, log)
    cut = [side for side in SIDES_OF[at_bound] if side not in sides_at_limit((bound_lower, bound_upper), limits)]
    if cut:
        return f"cut by the search range ({' and '.join(cut)} bound)", width
    return ("identified" if width <= IDENTIFIED_MAX_WIDTH else "bounded"), width


def interval_at_bound(lower: float, upper: float, bound_lower: float, bound_upper: float, log: bool = False) -> str:
    """The ``at_bound`` value of one interval in its factor's range (:meth:`Domain.at_bound`)."""
    return Domain(("x",), (bound_lower,), (bound_upper,), (log,)).at_bound([lower], [upper])[0]


def _pct(width: float) -> str:
    return f"{100 * width:.3g} % of the search range"


def _reason(verdict: str, width: float, strict_verdict: str, strict_width: float, strict: tuple,
            limit_ends: dict | None = None) -> str:
    """``limit_ends``: the ends of the plausible interval at a physical limit (side -> limit)."""
    limit_ends = limit_ends or {}
    if verdict == "no admissible point":
        text = ("no point of the search range is plausible: a discrepancy between simulation and experiment "
                "(see level 2)")
    elif verdict == "unresolved":
        text = f"the plausible interval covers {_pct(width)}: the observables say (almost) nothing about it"
    elif verdict.startswith("cut"):
        sides = verdict.split("(")[1].rstrip(")")
        text = (f"the plausible interval ({_pct(width)}) reaches the {sides}: the set may extend beyond the "
                "search range" + "".join(f"; its {s} end is the physical limit ({v:.4g})"
                                         for s, v in limit_ends.items()))
    elif verdict == "identified":
        text = f"the plausible interval is {_pct(width)} wide and {_clear_of_bounds(limit_ends)}"
    else:
        text = (f"the plausible interval is {_pct(width)} wide (identified needs at most "
                f"{100 * IDENTIFIED_MAX_WIDTH:g} %) and {_clear_of_bounds(limit_ends)}")
    if strict_verdict != verdict:
        if strict_verdict == "no admissible point":
            text += "; strictly (surrogate and measurements exact) no point meets every target"
        else:
            shown = f"[{strict[0]:.4g}, {strict[1]:.4g}], {_pct(strict_width)}"
            text += (f"; identified if surrogate and measurements were exact (strict interval {shown})"
                     if strict_verdict == "identified" else f"; strictly (surrogate and measurements exact): {strict_verdict}, "
                f"{shown}")
    return text


def _clear_of_bounds(limit_ends: dict) -> str:
    if not limit_ends:
        return "clear of both bounds"
    if len(limit_ends) == 2:
        return (f"reaches the physical limits at both ends ({limit_ends['lower']:.4g} and "
                f"{limit_ends['upper']:.4g}), beyond which no value lies")
    (side, value), = limit_ends.items()
    other = "upper" if side == "lower" else "lower"
    return (f"clear of the {other} bound, ending at the physical {side} limit ({value:.4g}), beyond which no value "
            "lies")


def _limit_ends(factor, lower: float, upper: float) -> dict:
    """The ends of an interval that reach an end of the factor's range at its physical limit: side -> limit."""
    if not (np.isfinite(lower) and np.isfinite(upper)):
        return {}
    limits = dict(zip(("lower", "upper"), factor.limits))
    return {s: limits[s] for s in SIDES_OF[interval_at_bound(lower, upper, factor.lower, factor.upper, factor.log)]
            if s in sides_at_limit((factor.lower, factor.upper), factor.limits)}


def verdict_frame(spec, identifiability: pd.DataFrame, plausible: pd.DataFrame,
                  uninformative: dict[str, str] | None = None, implausible=()) -> pd.DataFrame:
    """One row per scenario x factor of one material (:data:`VERDICT_COLUMNS`).

    ``identifiability``: the material's rows of ``identifiability.csv`` (strict, with ``at_bound``);
    ``plausible``: its rows of ``robust_identifiability.csv`` (``robust_*`` = plausible);
    ``uninformative``: observable -> reason (:func:`~demid.uncertainty.recommended.uninformative_observables`).
    A scenario whose every observable is uninformative gets that verdict.  ``implausible``: observables whose
    target lies far outside every simulated value (:func:`~demid.data.implausible_targets`): an empty set
    with one of them is put down to that target.
    """
    uninformative = uninformative or {}
    rows = []
    for sc in spec.scenarios:
        for f in spec.factors:
            strict = identifiability[(identifiability["scenario"] == sc.name) & (identifiability["factor"] == f.name)]
            plaus = plausible[(plausible["scenario"] == sc.name) & (plausible["factor"] == f.name)]
            if strict.empty or plaus.empty:
                continue
            s_lo, s_hi = float(strict["lower"].iloc[0]), float(strict["upper"].iloc[0])
            p_lo, p_hi = float(plaus["robust_lower"].iloc[0]), float(plaus["robust_upper"].iloc[0])
            if float(plaus["robust_fraction_pct"].iloc[0]) == 0:
                p_lo = p_hi = float("nan")
            strict_verdict, strict_width = factor_verdict(s_lo, s_hi, f.lower, f.upper, f.log,
                                                          strict["at_bound"].iloc[0] if "at_bound" in strict else None,
                                                          f.limits)
            if sc.observables and all(o in uninformative for o in sc.observables):
                verdict = UNINFORMATIVE
                reason = "; ".join(f"{spec.response_labels.get(o, o)}: {uninformative[o]}" for o in sc.observables)
            else:
                verdict, width = factor_verdict(p_lo, p_hi, f.lower, f.upper, f.log, limits=f.limits)
                reason = _reason(verdict, width, strict_verdict, strict_width, (s_lo, s_hi),
                                 _limit_ends(f, p_lo, p_hi))
                slipped = [spec.response_labels.get(o, o) for o in sc.observables if o in implausible]
                if verdict == "no admissible point" and slipped:
                    reason = (f"no point of the search range is plausible: the target of {', '.join(slipped)} lies "
                              "far outside every simulated value (check it: see the next step)")
            rows.append({"material": spec.name, "scenario": sc.name, "factor": f.name, "strict_lower": s_lo,
                         "strict_upper": s_hi, "plausible_lower": p_lo, "plausible_upper": p_hi,
                         "verdict": verdict, "reason": reason})
    return pd.DataFrame(rows, columns=VERDICT_COLUMNS)


def in_combination(verdicts: pd.DataFrame, spec, combinations: dict) -> pd.DataFrame:
    """A factor unresolved alone whose plausible set's narrowest direction is identified with others:
    "unresolved alone; identified in combination with X".  Where only the strict set identifies the
    combination, the verdict stays and the reason says so (it would hold if surrogate and measurements
    were exact).  ``combinations``: ``combinations/{material}.json``."""
    plausible = combinations.get("in_combination_plausible") or {}
    strict = combinations.get("in_combination") or {}
    if not len(verdicts) or not (plausible or strict):
        return verdicts
    out = verdicts.copy()
    for i, row in out.iterrows():
        if row["verdict"] != "unresolved":
            continue
        partners = plausible.get(row["scenario"], {}).get(row["factor"])
        if partners:
            others = " and ".join(spec.factor(p).label for p in partners)
            out.at[i, "verdict"] = f"unresolved alone; identified in combination with {others}"
            out.at[i, "reason"] = (f"{row['reason']}; the plausible set is narrow along a combination of it with "
                                   f"{others} (tables/combinations.csv)")
            continue
        partners = strict.get(row["scenario"], {}).get(row["factor"])
        if partners:
            others = " and ".join(spec.factor(p).label for p in partners)
            out.at[i, "reason"] = (f"{row['reason']}; identified in combination with {others} if surrogate and "
                                   "measurements were exact (the strict set; the plausible set is not narrow along it)")
    return out


def verdict_display(verdicts: pd.DataFrame, spec) -> pd.DataFrame:
    """The summary's table: labels, both intervals, the plausible width and the verdict with its reason."""
    rows = []
    for _, row in verdicts.iterrows():
        f = spec.factor(row["factor"])
        label = next((sc.label for sc in spec.scenarios if sc.name == row["scenario"]), row["scenario"])

        def interval(lo, hi):
            return "–" if not (np.isfinite(lo) and np.isfinite(hi)) else f"[{lo:.4g}, {hi:.4g}]"

        trans = np.log10 if f.log else (lambda v: v)
        width = ((trans(row["plausible_upper"]) - trans(row["plausible_lower"])) / (trans(f.upper) - trans(f.lower))
                 if np.isfinite(row["plausible_lower"]) else float("nan"))
        rows.append({"scenario": label, "factor": f.label, "unit": unit_text(f.unit),
                     "strict interval": interval(row["strict_lower"], row["strict_upper"]),
                     "plausible interval": interval(row["plausible_lower"], row["plausible_upper"]),
                     "plausible width [% of range]": 100 * width, "verdict": row["verdict"], "why": row["reason"]})
    return pd.DataFrame(rows)
