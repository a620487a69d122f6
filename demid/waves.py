"""Waves of a simulated material: which runs each wave simulates and what each wave analyses.

Wave 1 is the declared design over the configured bounds (:func:`first_wave`).
Wave k+1 simulates wave k's proposed runs (``waves.next_runs``, placed over Omega where they decide the set:
:func:`demid.next_wave.plan_omega_wave`) and is
analysed with every run of waves 1..k+1 over the search range Omega the user declared, as a ``custom``
design: a box is only where runs were placed, so every fraction, width and verdict of every wave is
relative to Omega, and no part of the set is reported empty because it lies outside the last box.
Run numbers continue across waves.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from .precision import counted, q2_text, shares_change_text
from .simulation import reserved_file
from .spec import MaterialSpec
from .surrogate_choice import MISFIT_P


def waves_max(spec: MaterialSpec) -> int:
    """How many waves the material runs at most (``waves.max``)."""
    return int(spec.waves["max"])


def stops_early(spec: MaterialSpec) -> bool:
    """Whether the stop advice ends the material's waves before ``waves.max`` (``waves.stop_early``)."""
    return bool(spec.waves["stop_early"])


def first_wave(spec: MaterialSpec, seed: int) -> pd.DataFrame:
    """Wave 1 of a simulated material: its declared design over the factor bounds, in randomised order
    (:func:`demid.design_generation.generate_sheet`, as ``demid design --seed`` writes it).  Columns
    ``run`` and one per factor (actual units); log-scale factors are designed in log10."""
    from .design_generation import FactorRange, generate_sheet

    ranges = [FactorRange(f.name, math.log10(f.lower) if f.log else f.lower,
                          math.log10(f.upper) if f.log else f.upper) for f in spec.factors]
    sheet = generate_sheet(spec.design_type, ranges, center_runs=spec.center_runs, alpha=repr(spec.alpha),
                           seed=seed)
    frame = sheet.to_frame().drop(columns="std_order")
    for f in spec.factors:
        if f.log:
            frame[f.name] = [_from_log10(v, f.lower, f.upper) for v in frame[f.name]]
    return frame


def _from_log10(level: float, lower: float, upper: float) -> float:
    """A log-scale factor's level from its log10 on the sheet, to 12 significant digits.  The sheet holds a bound's
    log10 to 12 digits, so 10**level misses the bound in the last digits (50 came back as 50.0000000005, outside
    a bound of 50): a level that close to a declared bound is that bound, so a bound run is simulated on it."""
    actual = float(f"{10 ** level:.12g}")
    return next((bound for bound in (lower, upper) if math.isclose(actual, bound, rel_tol=1e-9)), actual)


def wave_material(material: dict, data: str, domain: pd.DataFrame | None = None) -> dict:
    """The ``materials`` entry wave k analyses: the table ``data`` over the declared bounds (Omega) and, after
    wave 1 (a box ``domain`` holds the runs placed since), a ``custom`` design: the table holds every run of
    waves 1..k, not the declared design.  Published statistics (of another table) are dropped;
    ``waves.next_runs`` is the wave's ``next_runs``."""
    mat = copy.deepcopy(material)
    mat.pop("simulation", None)
    waves = mat.pop("waves", None) or {}
    mat["data"] = str(data)
    if waves.get("next_runs"):
        mat["next_runs"] = copy.deepcopy(waves["next_runs"])
    if domain is None:
        return mat
    mat["design"] = {"type": "custom"}
    for response in mat["responses"].values():
        response.pop("published", None)
    mat.pop("confirmed_values", None)
    return mat


def wave_spec(spec: MaterialSpec, data: str, domain: pd.DataFrame | None = None) -> MaterialSpec:
    """The :class:`MaterialSpec` of one wave's analysis (see :func:`wave_material`)."""
    return MaterialSpec.from_material(spec.name, wave_material(spec.material_config(), data, domain),
                                      grid_points=spec.grid_points)


def inside_domain(table: pd.DataFrame, domain: pd.DataFrame | None, rel_tol: float = 1e-9) -> pd.DataFrame:
    """The runs of ``table`` inside the box ``domain`` (all runs when there is none).  A wave analyses every
    run (see the module docstring); this says which of them lie where a box placed runs."""
    if domain is None:
        return table
    keep = np.ones(len(table), dtype=bool)
    for row in domain.itertuples():
        tol = rel_tol * (row.upper - row.lower)
        values = table[row.factor].to_numpy(dtype=float)
        keep &= (values >= row.lower - tol) & (values <= row.upper + tol)
    return table[keep].reset_index(drop=True)


def next_wave_runs(proposals: pd.DataFrame, factors, first_run: int) -> pd.DataFrame:
    """Wave k+1's runs from wave k's ``next_runs`` table: ``run`` numbered on from ``first_run``, one
    column per factor."""
    frame = proposals[list(factors)].reset_index(drop=True).astype(float)
    frame.insert(0, "run", np.arange(first_run, first_run + len(frame)))
    return frame


#: The leave-one-out Q² a surrogate must reach before the waves may stop on its plausible set: below it the
#: surrogate does not predict the runs it was not fitted to well enough for its set to be the answer.
STOP_Q2 = 0.5
#: A lack-of-fit p-value at or below this says the surrogate misfits the replicated runs: the level at which the
#: surrogate choice calls the quadratic misfitting, one number for both.
LACK_OF_FIT_ALPHA = MISFIT_P
#: After the first design (no change measured yet) the waves stop on a predicted shrink only when each
#: observable's leave-one-out prediction error is at most this share of its tolerance band's half-width: then
#: the set's boundary lies within a quarter of the band of where it is drawn, so the band, not the surrogate,
#: fixes it and more runs cannot move it by much.  A larger error (noise or a surrogate still learning the
#: response) moves the boundary by a good part of the band, which the next wave's runs can still correct.
BAND_FIXED_SHARE = 0.25


@dataclass(frozen=True)
class WaveEvidence:
    """What one wave's analysis says about stopping: its number and the budget (``waves.max``), the plausible
    share of Omega of the refocus scenario now and after the previous wave (None for wave 1), each response of
    that scenario's Q² and lack-of-fit p-value, whether the criticism finds no parameter set meets every target
    and the plausible set is empty too (the model, not the surrogate, is the limit: level 2 searches the
    quadratic, and where the surrogate that judges the sets, kriging or the quadratic with its uncertainty,
    still leaves a plausible region, more runs can change the answer), and how many of the proposed runs are the criticism's
    replicates and deciding runs."""

    wave: int
    max_waves: int
    plausible_pct: float
    previous_pct: float | None
    surrogates: dict  # response -> {"q2": float, "lof_p": float, "loo_band": float}
    model_limit: bool
    proposed: int
    criticism_runs: int


def surrogate_limits(surrogates: dict) -> list[str]:
    """Why the surrogates cannot be stopped on, one clause per response ([] when every one predicts and fits)."""
    out = []
    for response, st in surrogates.items():
        q2, lof_p = st.get("q2"), st.get("lof_p")
        if q2 is None or not np.isfinite(q2):
            out.append(f"the surrogate of {response} is not checked on left-out runs (Q² undefined: a run alone "
                       "fixes it)")
        elif q2 < STOP_Q2:
            out.append(f"the surrogate of {response} does not predict well enough (Q² = {q2_text(q2)} < {STOP_Q2:g})")
        if lof_p is not None and np.isfinite(lof_p) and lof_p <= LACK_OF_FIT_ALPHA:
            out.append(f"the surrogate of {response} misfits the replicated runs (lack of fit p = {lof_p:.2g})")
    return out


def measured_change(evidence: WaveEvidence) -> float | None:
    """The relative change of the plausible share of Omega from the previous wave to this one (None for wave 1
    or after an empty set)."""
    if evidence.previous_pct is None or not evidence.previous_pct > 0:
        return None
    return (evidence.plausible_pct - evidence.previous_pct) / evidence.previous_pct


def _change_text(evidence: WaveEvidence, change: float) -> str:
    shares = shares_change_text(evidence.previous_pct, evidence.plausible_pct)
    return (f"the plausible share of the search range went {shares} from wave {evidence.wave - 1} "
            f"to wave {evidence.wave} ({100 * change:+.1f} %)")


def loo_error(row) -> float:
    """The root-mean-square leave-one-out prediction error of the surrogate a response's sets use (a fit
    statistics row): the quadratic's sqrt(PRESS / n); kriging's from its Q² on the same runs' total sum of
    squares (SST = PRESS / (1 - Q²) of the quadratic).  NaN where undefined."""
    from .kriging import KIND
    from .surrogate_choice import used_q2

    n, press = float(getattr(row, "n_runs", np.nan)), float(getattr(row, "press", np.nan))
    if not (n > 0 and np.isfinite(press)):
        return float("nan")
    if getattr(row, "surrogate", None) != KIND:
        return math.sqrt(max(press, 0.0) / n)
    q2_quadratic = float(row.q2)
    if not (np.isfinite(q2_quadratic) and q2_quadratic < 1.0):
        return float("nan")
    sst = press / (1.0 - q2_quadratic)
    return math.sqrt(max(1.0 - used_q2(row), 0.0) * sst / n)


def surrogate_evidence(row, band: float = float("nan")) -> dict:
    """One response's Q², lack-of-fit p-value and leave-one-out error in units of its tolerance band's
    half-width ``band`` (``loo_band``) for the stop rule, of the surrogate its sets use (a fit statistics row):
    kriging has no lack-of-fit test (its nugget is the scatter it fits), so only its Q²."""
    from .kriging import KIND
    from .surrogate_choice import used_q2

    lof_p = float("nan") if getattr(row, "surrogate", None) == KIND else float(row.lof_p)
    loo_band = loo_error(row) / band if band > 0 else float("nan")
    return {"q2": used_q2(row), "lof_p": lof_p, "loo_band": loo_band}


def band_fixes_boundary(surrogates: dict) -> bool:
    """Whether every response's leave-one-out error is at most :data:`BAND_FIXED_SHARE` of its band (unknown:
    no)."""
    shares = [st.get("loo_band") for st in surrogates.values()]
    return bool(shares) and all(s is not None and np.isfinite(s) and s <= BAND_FIXED_SHARE for s in shares)


def _largest(surrogates: dict) -> float:
    return max(st["loo_band"] for st in surrogates.values())


def _largest_share(surrogates: dict) -> str:
    shares = [st.get("loo_band") for st in surrogates.values()]
    known = [s for s in shares if s is not None and np.isfinite(s)]
    if len(known) < len(shares) or not known:
        return "the surrogates' leave-one-out error against the tolerance band is not known"
    return (f"the surrogates' leave-one-out error is up to {max(known):.2f} of the tolerance band's half-width "
            f"(more than {BAND_FIXED_SHARE:g}), so the next wave's runs can still move the set's boundary")


def wave_evidence(spec: MaterialSpec, wave: int, domain: pd.DataFrame | None, plausible: pd.DataFrame,
                  statistics: pd.DataFrame, criticism: dict, previous: dict | None, runs: pd.DataFrame) -> WaveEvidence:
    """The :class:`WaveEvidence` of wave ``wave`` of the material ``spec`` (its full search range): from the
    wave's box ``domain``, plausible-identifiability frame, fit statistics, criticism summary and proposed
    ``runs``, and the previous wave's decision (``previous``, None for wave 1)."""
    from .next_wave import refocus_scenario
    from .run_purposes import CONFIRM, DECIDE
    from .tolerance import observable_band

    analysed = wave_spec(spec, "", domain) if domain is not None else spec
    scenario = refocus_scenario(analysed)
    rows = plausible[plausible["scenario"] == scenario]
    plausible = float(rows["robust_fraction_pct"].iloc[0]) if len(rows) else 0.0  # a share of Omega already
    observables = next(sc.observables for sc in analysed.scenarios if sc.name == scenario)
    tolerance = next(sc.tolerance for sc in analysed.scenarios if sc.name == scenario)
    by_response = {row.response: row for row in statistics.itertuples()}
    surrogates = {r: surrogate_evidence(by_response[r], observable_band(analysed.response(r), analysed.targets[r],
                                                                        tolerance))
                  for r in observables if r in by_response}
    level2 = criticism.get("level2") or {}
    return WaveEvidence(wave=wave, max_waves=waves_max(spec), plausible_pct=plausible,
                        previous_pct=None if previous is None else previous.get("plausible_fraction_of_omega_pct"),
                        surrogates=surrogates, model_limit=level2.get("feasible") is False and plausible <= 0.0,
                        proposed=len(runs),
                        criticism_runs=int(runs["purpose"].isin([CONFIRM, DECIDE]).sum()) if len(runs) else 0)


def stop_decision(value: dict | None, evidence: WaveEvidence) -> dict:
    """Whether the waves stop after this one, what the study's advice is (``action``: ``stop``, ``next_runs`` or
    ``recalibrate``) and why, in one sentence.

    They never stop on a surrogate that misfits or does not predict (:func:`surrogate_limits`), unless the
    budget is spent (then: ``recalibrate``).  They stop when the criticism finds the model itself is the limit,
    when the budget is spent, when the measured change of the plausible share of Omega between the last two
    waves is within :data:`~demid.wave_value.STOP_CONTRACTION` (the smallest change the loop counts as
    progress), or, with no change measured yet (after the first design), when the proposed runs are expected to
    shrink the set by less than that (``value``: :func:`demid.wave_value.expected_contraction`) AND each
    surrogate's leave-one-out error is small against the tolerance band (:func:`band_fixes_boundary`): only then
    does the band, not the surrogate, fix the set's boundary, so the next wave's expected change is small against
    the set's own uncertainty."""
    from .wave_value import STOP_CONTRACTION

    spent = evidence.wave >= evidence.max_waves
    budget = f"the budget of {counted(evidence.max_waves, 'wave')} is spent"
    limits = surrogate_limits(evidence.surrogates)
    change = measured_change(evidence)
    if limits:
        what = (f"the next wave's {evidence.proposed} proposed runs"
                + (f", {evidence.criticism_runs} of them replicates or runs the criticism asks for," if
                   evidence.criticism_runs else "")
                + " add runs where the set's boundary is decided and refit the surrogate")
        if spent:
            return {"stop": True, "action": "recalibrate", "reason": (
                f"{budget} while {'; '.join(limits)}: the plausible set rests on that surrogate and is not the "
                f"answer yet; raise waves.max so that {what}")}
        return {"stop": False, "action": "next_runs", "reason": (
            f"the waves go on: {'; '.join(limits)}, so the plausible set cannot be the answer yet; {what}")}
    if evidence.model_limit:
        return {"stop": True, "action": "stop", "reason": (
            "the criticism finds no parameter set meets every target: the model, not the surrogate, is the limit, "
            "and more runs of it cannot change that")}
    band_fixed = band_fixes_boundary(evidence.surrogates)
    settled = change is not None and abs(change) <= STOP_CONTRACTION
    if settled and band_fixed:
        return {"stop": True, "action": "stop", "reason": (
            f"{_change_text(evidence, change)}: within the {100 * STOP_CONTRACTION:g} % change the loop needs to "
            f"count a wave as progress, and the surrogates' leave-one-out error is at most "
            f"{_largest(evidence.surrogates):.2f} of the tolerance band's half-width, so the band fixes the set's "
            "boundary and a further wave of this kind is not expected to buy anything measurable")}
    predicted_small = change is None and bool(value and value.get("stop"))
    if predicted_small and band_fixed:  # no change measured yet: the prediction
        return {"stop": True, "action": "stop", "reason": (
            f"the {value['count']} proposed runs are expected to shrink the plausible set of '{value['scenario']}' "
            f"by only {100 * value['expected_contraction']:.1f} % "
            f"({shares_change_text(value['plausible_fraction_pct'], value['expected_fraction_pct'])} "
            f"of the wave's range) and the surrogates' leave-one-out error "
            f"is at most {_largest(evidence.surrogates):.2f} of the tolerance band's half-width: the band, not the "
            "surrogate, fixes the set's boundary, so more runs are not expected to change the set by more than its "
            "own uncertainty")}
    if settled:
        moving = f"{_change_text(evidence, change)}, but {_largest_share(evidence.surrogates)}"
    elif change is not None:
        moving = f"{_change_text(evidence, change)}: the set still moves"
    elif predicted_small:
        moving = (f"the proposed runs are expected to shrink the set by only "
                  f"{100 * value['expected_contraction']:.1f} %, but {_largest_share(evidence.surrogates)}")
    else:
        moving = "the first wave's set has nothing to compare with yet"
    if spent:
        return {"stop": True, "action": "next_runs", "reason": (
            f"{budget} while {moving}; raise waves.max to simulate the {evidence.proposed} proposed runs")}
    return {"stop": False, "action": "next_runs", "reason": (
        f"the waves go on: {moving}; the next wave simulates the {evidence.proposed} proposed runs")}


#: Names a simulated material's factors and responses cannot take: its table's ``wave`` column and
#: the command's run placeholders.
_RESERVED = ("wave", "seed", "run_dir")


def simulated_materials(config: dict) -> list[str]:
    return [m for m, mat in config["materials"].items() if mat.get("simulation")]


def check_simulated(config: dict, source: str = "config") -> None:
    """Cross-references of ``simulation`` and ``waves``; raises InputError naming the key."""
    from .errors import InputError

    for name, mat in config["materials"].items():
        key = f"materials.{name}"
        waves = mat.get("waves")
        if not mat.get("simulation"):
            if waves:
                raise InputError(f"config key {key}.waves: waves need simulation (a command demid runs per run); "
                                 "a finished table is one wave", source=source)
            continue
        clash = sorted(set(_RESERVED) & (set(mat["factors"]) | set(mat["responses"])))
        if clash:
            raise InputError(f"config key {key}: '{clash[0]}' names the simulated table's wave column or a run "
                             "placeholder; rename that factor or response", source=source)
        responses_file = mat["simulation"]["responses_file"]
        if reserved_file(responses_file):
            raise InputError(f"config key {key}.simulation.responses_file: '{responses_file}' is demid's own file in "
                             "each run's folder; name the command's responses file otherwise (e.g. responses.json)",
                             source=source)
        if mat["design"]["type"] == "custom":
            raise InputError(f"config key {key}.design.type: the first wave of a simulated material is its design; "
                             "declare ccd, box_behnken or factorial", source=source)
        spec = MaterialSpec.from_material(name, mat)
        try:
            first_wave(spec, int(mat["simulation"]["seed"]))
        except InputError as err:
            raise InputError(f"config key {key}.design: the first wave cannot be generated: {err.detail}",
                             source=source) from None
        if not waves:
            continue
        if mat.get("next_runs"):
            raise InputError(f"config key {key}.next_runs: with waves, each wave's next runs are waves.next_runs; "
                             "move next_runs there", source=source)
        nr = waves.get("next_runs")
        if waves_max(spec) > 1 and not nr:
            raise InputError(f"config key {key}.waves: max {waves_max(spec)} needs next_runs (e.g. next_runs: "
                             "{count: 9}), the runs each further wave simulates", source=source)
        k = len(mat["factors"])
        needed = (k + 1) * (k + 2) // 2 + 1  # a quadratic's coefficients, and one degree of freedom
        if nr and nr["count"] < needed:
            raise InputError(f"config key {key}.waves.next_runs.count: {nr['count']} runs cannot determine a quadratic "
                             f"in {k} factors over the next box when no earlier run lies in it; at least {needed}",
                             source=source)
        if nr and nr.get("scenario") and nr["scenario"] not in (mat.get("scenarios") or {}):
            raise InputError(f"config key {key}.waves.next_runs.scenario: unknown scenario '{nr['scenario']}' "
                             f"(known: {', '.join(mat.get('scenarios') or {})})", source=source)


def box_share(spec: MaterialSpec, domain: pd.DataFrame | None) -> float:
    """The volume of a wave's box ``domain`` as a share of the material's search range Omega (in search
    units, so log-scale factors count in log10); 1 without a box."""
    if domain is None:
        return 1.0
    bounds = domain.set_index("factor").loc[spec.factor_names]
    lo, hi = spec.domain.to_search(np.array([bounds["lower"].to_numpy(), bounds["upper"].to_numpy()], dtype=float))
    omega_lo, omega_hi = spec.domain.search_bounds()
    return float(np.prod((hi - lo) / (omega_hi - omega_lo)))


HISTORY_COLUMNS = ["material", "wave", "runs_simulated", "runs_analysed", "scenario", "feasible_fraction_of_omega_pct",
                   "factor", "lower", "upper", "width", "box_lower", "box_upper", "box_share_of_omega_pct",
                   "plausible_fraction_of_omega_pct", "plausible_lower", "plausible_upper"]


def wave_history(spec: MaterialSpec, waves: list[dict]) -> pd.DataFrame:
    """The admissible sets wave by wave: per wave, scenario and factor the set's span (``lower``, ``upper``,
    ``width``: over Omega, in actual units) and its feasible fraction of Omega (each wave is analysed over
    Omega), and the box the wave's new runs were placed in (``box_lower``, ``box_upper`` and its share of
    Omega; Omega itself for wave 1).

    ``waves``: per wave in order, ``scenarios`` (its scenarios frame), ``domain`` (its box, None for
    wave 1), ``simulated`` (runs simulated up to it, failed ones included), ``analysed`` (runs it analysed) and,
    optionally, ``plausible`` (its plausible-identifiability frame: the plausible share of Omega and interval per
    scenario and factor, the numbers the report's Waves table prints; NaN without it).
    """
    rows = []
    for number, wave in enumerate(waves, start=1):
        share = box_share(spec, wave["domain"])
        box = ({f.name: (f.lower, f.upper) for f in spec.factors} if wave["domain"] is None else
               {r.factor: (float(r.lower), float(r.upper)) for r in wave["domain"].itertuples()})
        plausible = _plausible_by_set(wave.get("plausible"))
        for row in wave["scenarios"].itertuples():
            pct, lower, upper = plausible.get((row.scenario, row.factor), (np.nan, np.nan, np.nan))
            rows.append({"material": spec.name, "wave": number, "runs_simulated": int(wave["simulated"]),
                         "runs_analysed": int(wave["analysed"]), "scenario": row.scenario,
                         "feasible_fraction_of_omega_pct": float(row.feasible_fraction_pct),
                         "factor": row.factor, "lower": float(row.lower), "upper": float(row.upper),
                         "width": float(row.width), "box_lower": box[row.factor][0],
                         "box_upper": box[row.factor][1], "box_share_of_omega_pct": 100 * share,
                         "plausible_fraction_of_omega_pct": pct, "plausible_lower": lower, "plausible_upper": upper})
    return pd.DataFrame(rows, columns=HISTORY_COLUMNS)


def _plausible_by_set(frame: pd.DataFrame | None) -> dict:
    """(scenario, factor) -> (plausible share of Omega in %, plausible lower, upper) of a plausible frame."""
    if frame is None or not len(frame):
        return {}
    return {(r.scenario, r.factor): (float(r.robust_fraction_pct), float(r.robust_lower), float(r.robust_upper))
            for r in frame.itertuples()}


def wave_summary(spec: MaterialSpec, waves: list[dict], decision: dict | None) -> dict:
    """What each wave simulated and found, and why the loop stopped, for the report's "Waves" section.

    ``waves``: per wave in order, ``table`` (every run simulated up to it, with ``status``), ``analysed`` (its
    runs analysed), ``domain`` (its box, None for wave 1), ``plausible`` (its plausible-identifiability frame) and
    ``statistics`` (its fit statistics).  ``decision``: the last wave's decision (:func:`stop_decision`), None
    for a material without waves.  Plausible shares are of Omega (every wave is analysed over Omega); intervals
    are in actual units.  Per wave ``surrogate`` says in words which surrogate judged each response's sets and
    why, ``q2`` is that surrogate's Q² per response, and ``surrogates`` per response the one used with both Q²
    (:mod:`demid.surrogate_choice`; wave 1: the quadratic)."""
    from .next_wave import refocus_scenario
    from .surrogate_choice import choice_text, surrogate_record, used_q2

    rows = []
    for number, wave in enumerate(waves, start=1):
        analysed = wave_spec(spec, "", wave["domain"])
        scenario = refocus_scenario(analysed)
        plausible = wave["plausible"][wave["plausible"]["scenario"] == scenario].set_index("factor")
        stats = wave["statistics"]
        table = wave["table"]
        failed = int((table["status"] == "failed").sum()) if "status" in table else 0
        rows.append({
            "wave": number, "simulated": len(table), "failed": failed, "analysed": len(wave["analysed"]),
            "surrogate": ("; ".join(choice_text(spec.response_labels.get(r.response, r.response), r)
                                    for r in stats.itertuples()) if "surrogate" in stats and len(stats) else "quadratic"),
            "q2": {str(r.response): used_q2(r) for r in stats.itertuples()},
            "surrogates": {str(r.response): surrogate_record(r) for r in stats.itertuples()},
            "scenario": scenario,
            "plausible_fraction_of_omega_pct": float(plausible["robust_fraction_pct"].iloc[0]) if len(plausible) else 0.0,
            "plausible": {f: [float(plausible.at[f, "robust_lower"]), float(plausible.at[f, "robust_upper"])]
                          for f in spec.factor_names if f in plausible.index}})
    return {"material": spec.name, "waves": rows, "decision": decision}
