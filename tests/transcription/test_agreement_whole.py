"""Which printed statistics agree with a refit (demid.transcription.printed._agreement), over generated ANOVA
tables printed to 1-4 decimals, some statistics printed from slightly other sums or from the printed sums, several hypotheses at once:
a statistic agrees when the refit rounds to it, or when the source's own printed inputs (all agreeing with the
refit, possibly themselves through their inputs, in the documented order) give it: F, p and R² for any value of
the inputs within their rounding (the corners of the rounding box, scipy's F tail), adjusted R², residual SD and
RMSE from the printed inputs themselves.  Every agreement flag and the set of statistics that agree only through
their inputs are compared with these rules written out here."""

from __future__ import annotations

from itertools import product

import numpy as np
from scipy import stats

from demid.transcription.printed import _agreement, parse_printed


def _f(a, b, dfa, dfb):
    return (a / dfa) / (b / dfb) if dfa > 0 and dfb > 0 and b > 0 else np.nan


def _tail(f, dfa, dfb):
    if not (dfa > 0 and dfb > 0 and np.isfinite(f)):
        return np.nan
    return stats.f.sf(max(f, 0.0), dfa, dfb)


def _adj(res, tot, df, n):
    return 1 - (res / df) / (tot / (n - 1)) if df > 0 and n > 1 and tot > 0 else np.nan


def _root(res, df):
    return np.sqrt(max(res, 0.0) / df) if df > 0 and res >= 0 else np.nan


# (statistic, inputs, formula(inputs..., hypothesis degrees of freedom), read over the inputs' rounding)
RULES = [
    ("lof_f", ("ss_lof", "ss_pure_error"), lambda a, b, d: _f(a, b, d["_df_lof"], d["_df_pe"]), True),
    ("lof_p", ("lof_f",), lambda f, d: _tail(f, d["_df_lof"], d["_df_pe"]), True),
    ("lof_p", ("ss_lof", "ss_pure_error"), lambda a, b, d: _tail(_f(a, b, d["_df_lof"], d["_df_pe"]), d["_df_lof"],
                                                                  d["_df_pe"]), True),
    ("r2", ("ss_model", "ss_total"), lambda a, b, d: a / b if b > 0 else np.nan, True),
    ("r2", ("ss_residual", "ss_total"), lambda a, b, d: 1 - a / b if b > 0 else np.nan, True),
    ("adj_r2", ("ss_residual", "ss_total"), lambda a, b, d: _adj(a, b, d["_df_model_resid"], d["_n"]), False),
    ("adj_r2", ("ss_model", "ss_total"), lambda a, b, d: _adj(b - a, b, d["_df_model_resid"], d["_n"]), False),
    ("resid_std", ("ss_residual",), lambda a, d: _root(a, d["_df_model_resid"]), False),
    ("rmse", ("ss_residual",), lambda a, d: _root(a, d["_n"]), False),
]


def _rounds_to(printed, x):
    return bool(np.isfinite(x) and abs(x - printed.value) <= printed.half_width * (1 + 1e-6))


def _expected(targets, values, hypotheses):
    agrees = {name: [_rounds_to(t, values[name][h]) for h in range(hypotheses)] for name, t in targets.items()}
    via = set()
    for name, inputs, formula, interval in RULES:
        if name not in targets or any(i not in targets for i in inputs):
            continue
        target = targets[name]
        for h in range(hypotheses):
            if agrees[name][h] or not all(agrees[i][h] for i in inputs):
                continue
            dof = {key: values[key][h] for key in ("_df_lof", "_df_pe", "_n", "_df_model_resid")}
            widths = [targets[i].half_width if interval else 0.0 for i in inputs]
            corners = [formula(*[targets[i].value + s * w for i, s, w in zip(inputs, signs, widths)], dof)
                       for signs in product((-1.0, 1.0), repeat=len(inputs))]
            finite = [c for c in corners if np.isfinite(c)]
            slack = target.half_width * (1 + 1e-6)
            if finite and target.value + slack >= min(finite) and target.value - slack <= max(finite):
                agrees[name][h] = True
                via.add(name)
    return agrees, via


def _statistics(ss_model, ss_residual, ss_pe, n, p, groups):
    df_pe, df_res = n - groups, n - p
    df_lof = df_res - df_pe
    ss_total = ss_model + ss_residual
    ss_lof = ss_residual - ss_pe
    lof_f = _f(ss_lof, ss_pe, df_lof, df_pe)
    return {"ss_model": ss_model, "ss_residual": ss_residual, "ss_total": ss_total, "ss_lof": ss_lof,
            "ss_pure_error": ss_pe, "lof_f": lof_f, "lof_p": _tail(lof_f, df_lof, df_pe),
            "r2": ss_model / ss_total, "adj_r2": _adj(ss_residual, ss_total, df_res, n),
            "resid_std": _root(ss_residual, df_res), "rmse": _root(ss_residual, n),
            "_df_lof": df_lof, "_df_pe": df_pe, "_n": n, "_df_model_resid": df_res}


def test_every_agreement_flag_and_the_statistics_that_agree_through_their_inputs():
    via_seen, extra_seen = set(), 0
    for seed in range(60):
        rng = np.random.default_rng(seed)
        n, p, groups = int(rng.integers(10, 30)), int(rng.integers(3, 7)), 0
        groups = int(rng.integers(p + 1, n))  # lack-of-fit and pure-error degrees of freedom both positive
        scale = 10.0 ** rng.integers(-1, 3)
        source = _statistics(scale * rng.uniform(50, 100), scale * rng.uniform(1, 10), scale * rng.uniform(0.2, 0.9),
                             n, p, groups)
        source["ss_pure_error"] = min(source["ss_pure_error"], 0.9 * source["ss_residual"])
        # the source printed each statistic to its own decimals; the refit hypotheses move the sums a little
        decimals = {name: int(rng.integers(1, 5)) for name in source if not name.startswith("_")}
        if seed % 2:  # a source that derived its statistics from its own printed (rounded) sums
            rounded = {key: round(source[key], decimals[key]) for key in ("ss_model", "ss_residual", "ss_pure_error")}
            derived = _statistics(rounded["ss_model"], rounded["ss_residual"], rounded["ss_pure_error"], n, p, groups)
            source.update({key: derived[key] for key in ("lof_f", "lof_p", "r2", "adj_r2", "resid_std", "rmse")})
            decimals.update({key: 4 for key in ("adj_r2", "resid_std", "rmse")})
        printed = {name: parse_printed(f"{source[name]:.{d}f}") for name, d in decimals.items()
                   if np.isfinite(source[name]) and rng.random() < 0.85}
        hypotheses = []
        for _ in range(3):
            moved = {key: source[key] * (1 + rng.choice([0.0, 1e-4, 3e-3, 0.05]) * rng.choice([-1, 1]))
                     for key in ("ss_model", "ss_residual", "ss_pure_error")}
            hypotheses.append(_statistics(moved["ss_model"], moved["ss_residual"],
                                          min(moved["ss_pure_error"], 0.9 * moved["ss_residual"]), n, p, groups))
        values = {key: np.array([h[key] for h in hypotheses], dtype=float) for key in hypotheses[0]}
        agrees, via = _agreement(printed, values)
        want, want_via = _expected(printed, values, 3)
        for name in printed:
            assert list(agrees[name]) == want[name], (seed, name)
        assert via == want_via, seed
        via_seen |= via
        extra_seen += sum(want[name][h] and not _rounds_to(printed[name], values[name][h])
                          for name in printed for h in range(3))
    # the generated tables reach the printed-inputs rule for several statistics
    assert extra_seen > 10 and {"lof_f", "lof_p", "r2", "adj_r2", "resid_std", "rmse"} <= via_seen, via_seen
