"""What widening a bound could buy when no point meets the targets and the best point sits on that bound.

The fitted surrogate is followed outwards from the best point along the factor, the others held:
its slope and curvature there (central differences, exact for a quadratic in search units), the
extension of the range a straight line and the surrogate's own quadratic extrapolation need to bring
the worst-missed observable into its tolerance band, and the quadratic's stationary point when it
turns back before the band (the response saturates along that factor).  Extensions are fractions of
the search range beyond the bound.  Level 2's message and the advice (:mod:`demid.story.advice`)
both read this one result: widening is advised only where the extrapolation reaches the band
within :data:`WIDEN_LIMIT` of the range.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from ..design import model_matrix
from .models import short_number

#: Largest extension (fraction of the search range beyond the bound) worth advising as "widen": further out
#: the quadratic's extrapolation rests on no run, and a target it reaches there is no evidence the model can.
WIDEN_LIMIT = 0.5
_STEP = 0.01  # finite-difference step, fraction of the range
#: A second difference within this many machine epsilons of the predictions' terms is round-off (each of the three
#: predictions carries a few epsilons of the size of the terms it sums).
_ROUND_OFF = 64 * np.finfo(float).eps


@dataclass(frozen=True)
class Reach:
    """How far past a search-range bound the best point would move to meet the target it misses most."""
    factor: str
    side: str                      # lower / upper: the bound the best point sits on
    observable: str                # the observable missing its target most at the best point
    value: float                   # its prediction at the best point
    target: float
    band_edge: float               # the nearest edge of the target's tolerance band
    slope: float                   # d observable / d factor at the bound (per actual unit; per decade if log)
    curvature: float               # d² observable / d t² outwards (t: fraction of the range)
    straight_extension: float      # fraction of the range a straight line needs (inf: it moves away)
    quadratic_extension: float     # fraction the surrogate's quadratic extrapolation needs (inf: never)
    levels_off_extension: float    # where the quadratic stops approaching the target (inf: it does not)
    levels_off_value: float        # its value there (nan when it does not level off)
    straight_factor_value: float   # the factor's value a straight line needs (nan: never)
    quadratic_factor_value: float  # the factor's value the quadratic needs (nan: never)
    levels_off_factor_value: float
    widen: bool                    # the quadratic reaches the band within WIDEN_LIMIT and the physical limit
    log: bool = False              # a log-scale factor: the slope is per decade
    limit_extension: float = np.inf  # fraction of the range from the bound to the factor's physical limit
    limit_value: float = np.nan      # that limit (nan: none on this side)

    @property
    def beyond_limit(self) -> bool:
        """The surrogate reaches the band only beyond the factor's physical limit (or the bound is the limit)."""
        return bool(self.limit_extension <= 0.0 or self.limit_extension < self.quadratic_extension < np.inf)

    @property
    def levels_off(self) -> bool:
        return bool(np.isfinite(self.levels_off_extension) and not np.isfinite(self.quadratic_extension))

    @property
    def flat(self) -> bool:
        """The observable does not change along the factor: widening it cannot bring it nearer its target."""
        return abs(self.slope) + abs(self.curvature) <= 1e-9 * max(1.0, abs(self.value))

    @property
    def missing(self) -> float:
        """What the observable misses its target by at the best point (target minus prediction)."""
        return self.target - self.value

    def to_json(self) -> dict:
        out = {k: (None if isinstance(v, float) and not np.isfinite(v) else v) for k, v in asdict(self).items()}
        out["levels_off"] = self.levels_off
        return out

    @classmethod
    def from_json(cls, payload: dict) -> Reach:
        fields = {k: (np.nan if payload.get(k) is None and k.endswith("value") else
                      np.inf if payload.get(k) is None else payload[k])
                  for k in cls.__dataclass_fields__ if k != "log"}
        fields["log"] = bool(payload.get("log", False))
        return cls(**fields)


def smallest_positive_root(a: float, b: float, c: float) -> float:
    """Smallest t > 0 with a t² + b t + c = 0 (inf when none; a root at 0 is none, a double root is one).  A
    quadratic coefficient below 1e-12 of the others' (and of 1) is round-off: the line b t + c gives the root."""
    if abs(a) < 1e-12 * max(abs(b), abs(c), 1.0):
        return -c / b if b and -c / b > 0 else np.inf
    disc = b * b - 4 * a * c
    if disc < 0:
        return np.inf
    roots = [(-b - np.sqrt(disc)) / (2 * a), (-b + np.sqrt(disc)) / (2 * a)]
    positive = [t for t in roots if t > 1e-12]
    return min(positive) if positive else np.inf


def terms_size(surrogate, points) -> np.ndarray:
    """Per point (actual units), the size a prediction's round-off is relative to: for a polynomial surrogate the
    sum of its terms' absolute values (y = 1.1 (x - 1011) is 0 at x = 1011, summed from terms of 1112), otherwise
    the prediction's own size."""
    from ..surrogate import Surrogate  # here: the reading jobs import this module and never fit

    if isinstance(surrogate, Surrogate):
        return np.abs(model_matrix(surrogate.model_units(points), surrogate.terms)) @ np.abs(surrogate.coefficients)
    return np.abs(np.asarray(surrogate.predict(points), dtype=float))


def reach_beyond_bound(surrogate, domain, factor: str, side: str, point: dict, observable: str,
                       target: float, tolerance: float) -> Reach:
    """How far beyond ``side`` of ``factor`` the surrogate of ``observable`` must be followed, from ``point``
    (actual units, every factor), to come within ``tolerance`` (relative) of ``target``.  A response already at its
    stationary point on the bound (slope 0 there) neither approaches the band nor levels off beyond the bound."""
    factors = list(domain.factors)
    i = factors.index(factor)
    lo, hi = domain.search_bounds()
    width = float(hi[i] - lo[i])
    outward = 1.0 if side == "upper" else -1.0
    base = domain.to_search(np.array([[float(point[f]) for f in factors]], dtype=float))[0]
    base[i] = hi[i] if side == "upper" else lo[i]

    def along(t):
        s = np.repeat(base[None, :], len(t), axis=0)
        s[:, i] = base[i] + outward * np.asarray(t, dtype=float) * width
        return s

    def predict(t):
        return np.asarray(surrogate.predict(domain.to_actual(along(t))), dtype=float)

    def factor_value(t):
        return float(domain.to_actual(along([t]))[0, i]) if np.isfinite(t) else np.nan

    steps = [-_STEP, 0.0, _STEP]
    f_minus, f0, f_plus = predict(steps)
    g = (f_plus - f_minus) / (2 * _STEP)           # per fraction of the range, outwards
    c = (f_plus - 2 * f0 + f_minus) / _STEP ** 2
    # a straight response's second difference is round-off, not curvature: taken as curvature, it put a response
    # moving away from its target "back in its band" some 1e10 ranges beyond the bound
    if abs(c) <= _ROUND_OFF * float(np.max(terms_size(surrogate, domain.to_actual(along(steps))))) / _STEP ** 2:
        c = 0.0
    direction = 1.0 if f0 < target else -1.0      # the observable must rise (+1) or fall (-1)
    edge = target - direction * tolerance * abs(target)
    gap = direction * (edge - f0)                  # > 0 while outside the band
    rate, bend = direction * g, direction * c      # progress towards the band per unit t, and its change
    straight = gap / rate if rate > 0 else np.inf
    quadratic = smallest_positive_root(bend / 2, rate, -gap)
    turn = -rate / bend if rate > 0 and bend < 0 else np.inf
    level = f0 + g * turn + c * turn ** 2 / 2 if np.isfinite(turn) else np.nan
    room = domain.room_beyond(factor, side)  # >= 0, and quadratic > 0: a range ending at its limit is never widened
    return Reach(factor=factor, side=side, observable=observable, value=float(f0), target=float(target),
                 band_edge=float(edge), slope=float(outward * g / width), curvature=float(c),
                 straight_extension=float(max(straight, 0.0)), quadratic_extension=float(max(quadratic, 0.0)),
                 levels_off_extension=float(turn), levels_off_value=float(level),
                 straight_factor_value=factor_value(straight), quadratic_factor_value=factor_value(quadratic),
                 levels_off_factor_value=factor_value(turn),
                 widen=bool(quadratic <= min(WIDEN_LIMIT, room)), log=bool(domain.log[i]),
                 limit_extension=room, limit_value=factor_value(room))


def _spaced(unit: str) -> str:
    return "" if not unit else unit if unit.startswith("°") else f" {unit}"


def saturation_finding(r: Reach, factor: str, observable: str, unit: str = "") -> str:
    """Level 2's finding in words, for a bound where widening is not advised (``r.widen`` False)."""
    u = _spaced(unit)
    if r.beyond_limit:
        if r.limit_extension <= 0.0:
            return (f"The range of {factor} already ends at its physical limit {short_number(r.limit_value)}, where "
                    f"{observable} still misses its target {short_number(r.target)}{u}: no simulation beyond it is "
                    f"possible.")
        return (f"The surrogate of {observable} reaches its target band only at {factor} ≈ "
                f"{short_number(r.quadratic_factor_value)}, beyond the physical limit of {factor} "
                f"({short_number(r.limit_value)}): a "
                f"wider range of {factor} cannot reach the target.")
    if r.levels_off and r.levels_off_extension > r.limit_extension:
        return (f"Along {factor} the surrogate of {observable} stays short of its target {short_number(r.target)}{u} "
                f"up to the "
                f"physical limit of {factor} ({short_number(r.limit_value)}): a wider range of {factor} cannot reach "
                f"it.")
    if r.levels_off:
        return (f"Along {factor} the surrogate of {observable} levels off at {short_number(r.levels_off_value)}{u} "
                f"({factor} ≈ {short_number(r.levels_off_factor_value)}), short of its target "
                f"{short_number(r.target)}{u}: the response "
                f"saturates along {factor}, so a wider range of {factor} is unlikely to reach the target.")
    if np.isfinite(r.quadratic_extension):
        return (f"The surrogate of {observable} reaches its target band only at {factor} ≈ "
                f"{short_number(r.quadratic_factor_value)}, {100 * r.quadratic_extension:.0f} % of the range beyond "
                f"the bound: "
                f"far beyond what the runs support, so a wider range of {factor} is unlikely to reach the target.")
    return (f"Beyond the bound of {factor} the surrogate of {observable} does not approach its target, so a wider "
            f"range of {factor} is unlikely to reach it.")


def saturation_advice(r: Reach, factor: str, observable: str, unit: str = "") -> str:
    """What to do instead of widening: the model lacks something, or the target is off."""
    u = _spaced(unit)
    if r.beyond_limit:
        where = ("its range already ends at its physical limit" if r.limit_extension <= 0.0 else
                 f"the surrogate reaches the target only at {factor} ≈ {short_number(r.quadratic_factor_value)}, "
                 f"beyond its "
                 "physical limit")
        return (f"Do not widen {factor} for {observable} = {short_number(r.target)}{u}: {where} "
                f"{short_number(r.limit_value)}. The "
                f"missing {short_number(abs(r.missing))}{u} of {observable} needs another mechanism in the model (a "
                f"factor not "
                f"varied) or a check of the target.")
    toward = r.slope * (1 if r.side == "upper" else -1) * (1 if r.missing > 0 else -1) > 0
    straight = (f"; a straight line would reach the target band at {factor} ≈ {short_number(r.straight_factor_value)}"
                if np.isfinite(r.straight_factor_value) and r.straight_extension <= r.limit_extension else "")
    per = "decade of" if r.log else "unit"
    return (f"Do not widen {factor} for {observable} = {short_number(r.target)}{u}: at the bound {observable} "
            f"{'gains only' if toward else 'moves away by'} {short_number(abs(r.slope))}{u} per {per} "
            f"{factor}{straight}. "
            f"The missing {short_number(abs(r.missing))}{u} of {observable} needs another mechanism in the model (a "
            f"factor not "
            f"varied) or a check of the target.")
