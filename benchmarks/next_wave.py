"""Does the next wave pin the admissible set down better than the same number of random runs?

Hidden simulators of two factors that are smooth but not quadratic (saturating, Hill-type,
mildly periodic) stand in for the DEM model.  Per simulator and seed:

1. a 13-run rotatable CCD (``demid.design_generation``, axial points on the search range) is
   "simulated" with Gaussian noise; targets are the noise-free simulator at a random point of
   the inner half of the domain, so the true admissible set is known to be non-empty;
2. the global quadratic is fitted (``demid.surrogate.fit_material``) and its plausible set taken
   from ``demid.uncertainty.plausible_identifiability_frame``, as in the pipeline;
3. (a) **next wave**: ``demid.next_wave.plan_next_wave`` with ``count`` runs; the proposals are
   simulated, and a new quadratic is fitted in the next domain on the earlier runs inside it plus
   the new runs (``design: custom``); its admissible set lives in that box;
   (b) **random** (the user's flow with random runs, the baseline of the ratios): ``count`` uniformly
   random runs in the same next domain, added to the same earlier runs inside it, fitted over that box;
   (b') **global**: ``count`` uniformly random runs added to the CCD, global quadratic refitted;
   (c) the CCD alone, for reference.
4. Each estimate is scored against the simulator's own admissible set on Omega
   (``demid.admissibility.admissible_set`` with the simulator as the field):
   fraction error |Phi_hat - Phi| / Phi, span-end error (mean |end_hat - end| over factors and
   ends, in % of the factor's range) and the symmetric difference |A_hat xor A| / |A| on a
   401^2 grid.  An empty estimate scores span-end error 100 %.

Simulators: saturating, periodic, Hill-type, saturating with a cross term, a rolling-friction-like
heap angle, and one saturating in the first factor and weak in the second with +-1 % noise.

Printed: one line per simulator and seed with its next / random ratio of the symmetric
difference, then per metric the median next-wave / random ratio, the number of cases where the
next wave wins (also against global random runs), and the number of cases where the next domain
failed to contain the true set.  Goal: median ratio <= 0.8 and wins in >= 2/3 of the cases.

Options: ``--noise`` (sd relative to the response level, default 0.003), ``--observables y1``
(a single-observable scenario: a band across the domain), ``--whole-box-design`` (ablation:
design runs spread over the whole next domain instead of its plausible part).

Held-out checks: ``--seed-start 100`` (seeds the default run does not use) and ``--held-out`` (two
shapes not in the default set: an interaction-dominated band, steep exponentials).

Run:  python benchmarks/next_wave.py [--reps 8] [--count 9] [--quick] [--seed-start 100] [--held-out]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import pandas as pd

from demid.admissibility import Domain, admissible_set
from demid.design_generation import FactorRange, generate_sheet
from demid.next_wave import plan_next_wave
from demid.spec import MaterialSpec
from demid.surrogate import fit_material
from demid.uncertainty import plausible_identifiability_frame

RANGES = {"e": (0.1, 0.9), "mu": (0.05, 0.35)}
FACTORS = list(RANGES)
LO = np.array([r[0] for r in RANGES.values()])
HI = np.array([r[1] for r in RANGES.values()])
TOLERANCE = 0.02
NOISE_REL = 0.003  # noise sd relative to the response level at the centre (--noise)
OBSERVABLES = ("y1", "y2")  # scenario observables (--observables)


def _u(x):
    return (np.atleast_2d(x) - LO) / (HI - LO)


def saturating(x):
    u = _u(x)
    return {"y1": 20 + 18 * (1 - np.exp(-2.5 * u[:, 0])) + 10 * u[:, 1] / (0.3 + u[:, 1]),
            "y2": 150 - 40 * np.tanh(1.5 * (u[:, 1] - 0.3)) + 15 * (1 - np.exp(-2 * u[:, 0]))}


def periodic(x):
    u = _u(x)
    return {"y1": 30 + 12 * u[:, 0] + 6 * u[:, 1] + 1.2 * np.sin(2 * np.pi * (0.8 * u[:, 0] + 0.5 * u[:, 1])),
            "y2": 100 + 20 * u[:, 1] - 8 * u[:, 0] + 1.5 * np.cos(2 * np.pi * (u[:, 0] - 0.6 * u[:, 1]))}


def hill(x):
    u = _u(x)
    return {"y1": 40 + 25 * u[:, 0] ** 2 / (0.35 ** 2 + u[:, 0] ** 2) + 5 * u[:, 1],
            "y2": 60 + 30 * u[:, 1] ** 3 / (0.4 ** 3 + u[:, 1] ** 3) - 6 * u[:, 0] * u[:, 1]}


def saturating_cross(x):
    u = _u(x)
    return {"y1": 50 + 20 * np.log1p(3 * u[:, 0] * (0.5 + u[:, 1])),
            "y2": 80 + 15 * np.sqrt(u[:, 1] + 0.05) + 6 * np.sin(1.5 * u[:, 0] + 0.5)}


def rolling_friction(x):
    """Angle of repose saturating in the rolling friction, barely moved by restitution (cf. the demo)."""
    u = _u(x)
    return {"y1": 22 + 14 * (1 - np.exp(-4 * u[:, 1])) + 1.5 * u[:, 0] + 0.4 * np.sin(3 * u[:, 0]),
            "y2": 140 + 20 * np.tanh(2 * (u[:, 0] - 0.4)) + 10 * np.sqrt(u[:, 1] + 0.02)}


def saturating_weak(x):
    """Saturating in the first factor (flat above ~half its range), weak in the second."""
    u = _u(x)
    return {"y1": 30 + 12 * (1 - np.exp(-5 * u[:, 0])) + 1.0 * u[:, 1],
            "y2": 200 + 25 * np.sqrt(u[:, 1] + 0.03) + 6 * np.tanh(3 * (u[:, 0] - 0.3))}


def interaction(x):
    """Held out (``--held-out``): the first response is dominated by the interaction, so its band is a hyperbola."""
    u = _u(x)
    return {"y1": 40 + 30 * u[:, 0] * u[:, 1] + 2 * u[:, 0],
            "y2": 100 + 15 * u[:, 1] - 12 * u[:, 0] + 3 * np.sin(2 * u[:, 0] * u[:, 1])}


def steep_exponential(x):
    """Held out (``--held-out``): each response grows exponentially in one factor (20-fold over the first)."""
    u = _u(x)
    return {"y1": 10 + 4 * np.exp(3 * u[:, 0]) + 3 * u[:, 1],
            "y2": 50 + 20 * np.exp(2.5 * (u[:, 1] - 0.5)) - 5 * u[:, 0]}


SIMULATORS = {"saturating": saturating, "periodic": periodic, "hill": hill, "saturating_cross": saturating_cross,
              "rolling_friction": rolling_friction, "saturating_weak": saturating_weak}
# Shapes the next wave was not developed on (--held-out), to check it on simulators it has not seen.
HELD_OUT = {"interaction": interaction, "steep_exponential": steep_exponential}
# Simulators whose runs are noisier than --noise (sd relative to the response level): +-1 %.
NOISE_OVERRIDE = {"saturating_weak": 0.01}


class _Field:
    """The simulator as a prediction field for :func:`admissible_set`."""

    def __init__(self, sim, response):
        self.sim, self.response = sim, response

    def predict(self, points):
        return self.sim(points)[self.response]


def _simulate(sim, points, rng, scale):
    out = sim(points)
    noise = NOISE_OVERRIDE.get(sim.__name__, NOISE_REL)
    return {r: v + noise * scale[r] * rng.standard_normal(len(v)) for r, v in out.items()}


def _table(points, responses, start=1):
    frame = pd.DataFrame(points, columns=FACTORS)
    frame.insert(0, "run", np.arange(start, start + len(points)))
    for r, v in responses.items():
        frame[r] = v
    frame["status"] = "ok"
    return frame


def _cfg(lower, upper, targets, design, count=None):
    cfg = {"data": "benchmark", "design": design,
           "factors": {f: {"lower": float(lo), "upper": float(hi)} for f, lo, hi in zip(FACTORS, lower, upper)},
           "responses": {r: {"target": float(t)} for r, t in targets.items()},
           "scenarios": {"both": {"observables": list(targets), "tolerance": TOLERANCE}}}
    if count:
        cfg["next_runs"] = {"count": count, "scenario": "", "margin": 0.1}
    return cfg


def _estimate(table, cfg, n):
    spec = MaterialSpec.from_material("benchmark", cfg)
    surs = {f.response: f.surrogate() for f in fit_material(table, spec)}
    domain = spec.domain
    targets = {r: c["target"] for r, c in cfg["responses"].items()}
    aset = admissible_set(surs, domain, list(targets), targets, TOLERANCE, n)
    return surs, domain, aset


def _mask_on(surs, targets, box_lo, box_hi, grid):
    inside = np.all((grid >= box_lo - 1e-12) & (grid <= box_hi + 1e-12), axis=1)
    ok = np.ones(len(grid), dtype=bool)
    for r, t in targets.items():
        ok &= np.abs(surs[r].predict(grid) - t) <= TOLERANCE * abs(t)
    return ok & inside


def _score(est_fraction, est_lo, est_hi, mask, truth, true_mask):
    frac_err = abs(est_fraction - truth.fraction) / truth.fraction
    if np.isfinite(est_lo).all():
        span_err = 100 * float(np.mean(np.abs(np.concatenate([est_lo - truth.lower, est_hi - truth.upper]))
                                       / np.concatenate([HI - LO, HI - LO])))
    else:
        span_err = 100.0
    sym = float(np.sum(mask ^ true_mask) / max(np.sum(true_mask), 1))
    return frac_err, span_err, sym


def run_case(name, sim, seed, count, n):
    rng = np.random.default_rng(seed)
    u_star = 0.25 + 0.5 * rng.random(2)
    targets = {r: float(v[0]) for r, v in sim(LO + u_star * (HI - LO)).items() if r in OBSERVABLES}
    scale = {r: abs(float(v[0])) for r, v in sim((LO + HI) / 2).items()}
    domain = Domain(tuple(FACTORS), tuple(LO), tuple(HI))
    fields = {r: _Field(sim, r) for r in targets}
    truth = admissible_set(fields, domain, list(targets), targets, TOLERANCE, 801)
    grid = domain.grid(401)
    true_mask = np.ones(len(grid), dtype=bool)
    for r, t in targets.items():
        true_mask &= np.abs(sim(grid)[r] - t) <= TOLERANCE * abs(t)

    sheet = generate_sheet("ccd", [FactorRange(f, lo, hi) for f, (lo, hi) in RANGES.items()], center_runs=5,
                           seed=seed)
    pts = sheet.to_frame()[FACTORS].to_numpy()
    ccd = _table(pts, _simulate(sim, pts, rng, scale))
    ccd_cfg = _cfg(LO, HI, targets, {"type": "ccd", "alpha": 2 ** 0.5, "center_runs": 5}, count)
    surs, _, ccd_set = _estimate(ccd, ccd_cfg, n)
    plausible = plausible_identifiability_frame(surs, domain, {"both": (tuple(targets), TOLERANCE)}, targets, n, z=2.0)
    wave = plan_next_wave("bench", ccd, surs, MaterialSpec.from_material("bench", ccd_cfg), plausible, z=2.0)
    box_lo, box_hi = wave.domain["lower"].to_numpy(), wave.domain["upper"].to_numpy()
    contained = bool(np.all(truth.lower >= box_lo - 1e-9) and np.all(truth.upper <= box_hi + 1e-9))
    # Smallest gap between the true set and a box side that was not clipped to the search range.
    gaps = [(t - b) / (hi - lo) for t, b, b0, lo, hi in zip(truth.lower, box_lo, LO, LO, HI) if b > b0 + 1e-12]
    gaps += [(b - t) / (hi - lo) for t, b, b0, lo, hi in zip(truth.upper, box_hi, HI, LO, HI) if b < b0 - 1e-12]
    slack = 100 * min(gaps) if gaps else np.nan

    # (a) next wave: an ordinary study on the box, earlier runs inside it + the new runs
    new_pts = wave.runs[FACTORS].to_numpy()
    inside = np.all((pts >= box_lo - 1e-12) & (pts <= box_hi + 1e-12), axis=1)
    nxt = pd.concat([ccd[inside], _table(new_pts, _simulate(sim, new_pts, rng, scale), start=100)],
                    ignore_index=True)
    nxt_surs, _, nxt_set = _estimate(nxt, _cfg(box_lo, box_hi, targets, {"type": "custom"}), n)
    box_share = float(np.prod((box_hi - box_lo) / (HI - LO)))
    a = _score(nxt_set.fraction * box_share, nxt_set.lower, nxt_set.upper,
               _mask_on(nxt_surs, targets, box_lo, box_hi, grid), truth, true_mask)

    # (b) the user's flow with random runs: the same number of uniform random runs in the next domain,
    # added to the same earlier runs inside it, fitted over the next domain
    box_pts = box_lo + rng.random((count, 2)) * (box_hi - box_lo)
    rbox = pd.concat([ccd[inside], _table(box_pts, _simulate(sim, box_pts, rng, scale), start=100)],
                     ignore_index=True)
    rbox_surs, _, rbox_set = _estimate(rbox, _cfg(box_lo, box_hi, targets, {"type": "custom"}), n)
    d = _score(rbox_set.fraction * box_share, rbox_set.lower, rbox_set.upper,
               _mask_on(rbox_surs, targets, box_lo, box_hi, grid), truth, true_mask)

    # (b') the same number of uniform random runs added to the CCD, global refit
    rnd_pts = LO + rng.random((count, 2)) * (HI - LO)
    rnd = pd.concat([ccd, _table(rnd_pts, _simulate(sim, rnd_pts, rng, scale), start=100)], ignore_index=True)
    rnd_surs, _, rnd_set = _estimate(rnd, _cfg(LO, HI, targets, {"type": "custom"}), n)
    b = _score(rnd_set.fraction, rnd_set.lower, rnd_set.upper, _mask_on(rnd_surs, targets, LO, HI, grid),
               truth, true_mask)
    c = _score(ccd_set.fraction, ccd_set.lower, ccd_set.upper, _mask_on(surs, targets, LO, HI, grid),
               truth, true_mask)
    return {"simulator": name, "seed": seed, "true_fraction_pct": 100 * truth.fraction,
            "box_share_pct": 100 * box_share, "contained": contained, "slack_pct": slack,
            "frac_err_next": a[0], "frac_err_random": d[0], "frac_err_global": b[0], "frac_err_ccd": c[0],
            "span_err_next": a[1], "span_err_random": d[1], "span_err_global": b[1], "span_err_ccd": c[1],
            "sym_err_next": a[2], "sym_err_random": d[2], "sym_err_global": b[2], "sym_err_ccd": c[2]}


def main(argv=None):
    global NOISE_REL, OBSERVABLES
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", "--reps", type=int, default=8, help="seeds per simulator")
    parser.add_argument("--seed-start", type=int, default=0, help="first seed (e.g. 100: seeds the benchmark "
                        "does not use by default)")
    parser.add_argument("--held-out", action="store_true",
                        help="score the held-out simulators (interaction band, steep exponential) instead")
    parser.add_argument("--count", type=int, default=9, help="runs in the next wave (and random runs added)")
    parser.add_argument("--quick", action="store_true", help="3 seeds, coarser grids")
    parser.add_argument("--noise", type=float, default=NOISE_REL, help="noise sd relative to the response level")
    parser.add_argument("--observables", default=",".join(OBSERVABLES), help="scenario observables, e.g. y1")
    parser.add_argument("--whole-box-design", action="store_true",
                        help="ablation: design runs D-optimal over the whole next domain, not its plausible part")
    args = parser.parse_args(argv)
    if args.whole_box_design:
        import demid.next_wave

        demid.next_wave.plausible_points = lambda *a, **k: np.empty((0, len(FACTORS)))
    NOISE_REL, OBSERVABLES = args.noise, tuple(args.observables.split(","))
    seeds = args.seeds if args.seeds != 8 or not args.quick else 3
    n = 201 if args.quick else 401
    t0 = time.perf_counter()
    simulators = HELD_OUT if args.held_out else SIMULATORS
    rows = [run_case(name, sim, seed, args.count, n) for name, sim in simulators.items()
            for seed in range(args.seed_start, args.seed_start + seeds)]
    frame = pd.DataFrame(rows)
    frame["sym_ratio"] = frame["sym_err_next"] / frame["sym_err_random"].where(frame["sym_err_random"] > 0)
    pd.set_option("display.width", 250)
    pd.set_option("display.max_columns", 30)
    print(frame[["simulator", "seed", "true_fraction_pct", "box_share_pct", "contained", "sym_err_next",
                 "sym_err_random", "sym_err_global", "sym_err_ccd", "sym_ratio", "span_err_next",
                 "span_err_random", "frac_err_next", "frac_err_random"]].round(4).to_string(index=False))
    print(f"\n{len(frame)} cases ({len(simulators)} simulators x {seeds} seeds from {args.seed_start}), count = {args.count}, "
          f"tolerance {TOLERANCE}, noise sd {100 * NOISE_REL:g} % of the response level, "
          f"{time.perf_counter() - t0:.0f} s")
    for metric, label in [("frac_err", "feasible-fraction error (relative)"),
                          ("span_err", "span-end error (% of range)"),
                          ("sym_err", "symmetric difference / |true set|")]:
        ratio = frame[f"{metric}_next"] / frame[f"{metric}_random"].where(frame[f"{metric}_random"] > 0)
        wins = int(np.sum(frame[f"{metric}_next"] < frame[f"{metric}_random"]))
        print(f"{label:38s} median next {frame[f'{metric}_next'].median():.4g}, random "
              f"{frame[f'{metric}_random'].median():.4g}, CCD alone {frame[f'{metric}_ccd'].median():.4g}; "
              f"median ratio next/random {ratio.median():.3f}; next wave better in {wins}/{len(frame)}")
        for name, sub in frame.groupby("simulator", sort=False):
            r = sub[f"{metric}_next"] / sub[f"{metric}_random"]
            print(f"    {name:18s} median ratio {r.median():.3f}, better in "
                  f"{int(np.sum(sub[f'{metric}_next'] < sub[f'{metric}_random']))}/{len(sub)}")
        g_ratio = frame[f"{metric}_next"] / frame[f"{metric}_global"].where(frame[f"{metric}_global"] > 0)
        print(f"    {'vs global random':18s} median ratio {g_ratio.median():.3f}, better in "
              f"{int(np.sum(frame[f'{metric}_next'] < frame[f'{metric}_global']))}/{len(frame)}")
    print(f"smallest gap between the true set and an unclipped side of the next domain: "
          f"{frame['slack_pct'].min():.2f} % of the range")
    wins = int(np.sum(frame["sym_err_next"] < frame["sym_err_random"]))
    met = frame["sym_ratio"].median() <= 0.8 and wins >= 2 * len(frame) / 3
    print(f"GOAL (symmetric difference, next vs random in the next domain): median ratio "
          f"{frame['sym_ratio'].median():.3f} (<= 0.8), wins {wins}/{len(frame)} (>= 2/3): "
          f"{'met' if met else 'NOT met'}")
    misses = frame[~frame["contained"]]
    print(f"next domain contained the true admissible set in {len(frame) - len(misses)}/{len(frame)} cases"
          + ("" if misses.empty else "; misses: " + ", ".join(f"{r.simulator} seed {r.seed}"
                                                             for r in misses.itertuples())))


if __name__ == "__main__":
    main()
