"""Every piece of advice of a study, computed once: the summary, level 2 and the next-wave section read it.

Kinds (``tables/advice.csv``): ``check_target`` (a target no simulated setting comes near, or one the
surrogate cannot meet), ``recalibrate`` (no point meets every target, or a surrogate does not predict, or the
best point sits on a bound the surrogate says widening cannot help: :mod:`demid.criticism.reach`),
``add_observable`` (the measurement that narrows most, or that a new kind is needed), ``widen`` (a bound
that cuts the plausible set, or the best point when no point meets every target, and only where moving it
can narrow or reach something), ``next_runs`` and ``stop`` (what the next wave can still buy; for a simulated
study with waves, why its loop stopped: :func:`demid.waves.stop_decision`), and ``measurement_order`` (the
observable ranking in words, one sentence per starting set: :mod:`demid.story.measurements`).

One item per material is the **next step** (``decision``): the first by :data:`PRIORITY`; the others follow it
as "also".  The generic add-observable line (no observable to name) stands only where nothing else is advised.
``measurement_order`` is detail, read where the ranking is shown, never a step.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace

import numpy as np
import pandas as pd

from ..criticism.reach import Reach, saturation_advice
from ..precision import rough_text, shares_change_text
from ..surrogate_choice import sets_do_not_predict
from .measurements import measurement_order
from .verdicts import unpredictive_responses
from .words import level2_within, unit_text

ADVICE_COLUMNS = ["material", "kind", "factor", "bound", "observable", "text", "decision"]
#: Which advice comes first: a target to check before anything is calibrated against it, a model to refit before
#: its sets are trusted, a range to widen before runs are placed in it, then runs, then measurements, then stop.
PRIORITY = ("check_target", "recalibrate", "widen", "next_runs", "add_observable", "stop")
#: Where each kind is read in the report besides the summary.
LEVEL2_KINDS = ("check_target", "recalibrate", "widen")
NEXT_WAVE_KINDS = ("next_runs", "stop")
#: Advice read beside the observable ranking only: the walk through it, set by set.
RANKING_KINDS = ("measurement_order",)


@dataclass(frozen=True)
class AdviceItem:
    material: str
    kind: str
    factor: str
    bound: str
    observable: str
    text: str
    decision: bool = False


@dataclass
class StudyAdvice:
    """The advice of one or more materials, in the order the summary gives it."""

    items: list[AdviceItem]

    def to_frame(self) -> pd.DataFrame:
        return pd.DataFrame([asdict(i) for i in self.items], columns=ADVICE_COLUMNS)

    @classmethod
    def from_frame(cls, frame: pd.DataFrame | None) -> StudyAdvice:
        if frame is None or not len(frame):
            return cls([])
        clean = frame.astype(object).fillna("").astype(str)  # an all-empty column reads as float
        text_columns = [c for c in ADVICE_COLUMNS if c != "decision"]
        return cls([AdviceItem(*(row[c] for c in text_columns), decision=row.get("decision", "").lower() == "true")
                    for _, row in clean.iterrows()])

    def texts(self, material: str, kinds=None) -> list[str]:
        return [i.text for i in self.items if i.material == material and (kinds is None or i.kind in kinds)]

    def next_step(self, material: str) -> tuple[str | None, list[str]]:
        """The material's next step and the other advice ("also"), in priority order."""
        own = [i for i in self.items if i.material == material and i.kind in PRIORITY]
        decision = next((i.text for i in own if i.decision), None)
        return decision, [i.text for i in own if not i.decision]


def _label(spec, name: str) -> str:
    return spec.response_labels.get(name, name)


def _unit(spec, name: str) -> str:
    unit = next((r.unit for r in spec.responses if r.name == name), "-")
    return unit_text(unit) if unit != "-" else ""


def _bound_text(f, side: str) -> str:
    unit = f" {unit_text(f.unit)}" if f.unit != "-" else ""
    limit = f.limits[0 if side == "lower" else 1]
    up_to = (f", {'down' if side == 'lower' else 'up'} to its physical limit {limit:.4g}{unit},"
             if limit is not None else "")
    return f"{side} bound ({(f.lower if side == 'lower' else f.upper):.4g}{unit}){up_to}"


def _check_targets(spec, implausible: dict, ranking) -> list[AdviceItem]:
    from ..data import UNIT_SLIP_RATIO, power_of_ten_repair

    items = []
    for r, found in implausible.items():
        key = f"materials.{spec.name}.responses.{r}.target"
        where = ("farther from every simulated value ({lo:.4g} to {hi:.4g}) than the simulated range itself"
                 if found.get("far", True) else
                 "outside every simulated value ({lo:.4g} to {hi:.4g}) by more than a factor of {ratio:g}")
        head = (f"Check the target of {_label(spec, r)} (config key {key}): {spec.targets[r]:.6g} lies "
                + where.format(lo=found["lo"], hi=found["hi"], ratio=UNIT_SLIP_RATIO))
        if found["factor"] is not None:
            text = (f"{head}; {power_of_ten_repair(found)}, so it is likely a unit or typing slip. No widening "
                    "of the search range can reach it.")
        else:
            text = (f"{head}: a discrepancy between simulation and experiment, not a calibration; check the target "
                    "and the simulation of it. No widening of the search range is advised for it.")
        items.append(AdviceItem(spec.name, "check_target", "", "", r, text))
    if ranking is not None and len(ranking) and "targets_reachable" in ranking.columns:
        reachable = ranking["targets_reachable"].astype(str).str.lower() == "true"
        for o in ranking[(ranking["n_observables"] == 1) & ~reachable]["observables"]:
            if o in implausible:
                continue
            items.append(AdviceItem(spec.name, "check_target", "", "", o, (
                f"Check the target of {_label(spec, o)} and the simulation of it: the surrogate cannot meet it "
                "anywhere in the search range within the tolerance. That is a discrepancy between simulation and "
                "experiment, not information; observable sets with it are ranked last and get no information gain.")))
    return items


def _recalibrate(spec, level1: dict, level2: dict, checked: set) -> list[AdviceItem]:
    items = []
    for r, res in level1.items():  # material_advice passes a dict (level 1's, or empty)
        if sets_do_not_predict(res):
            in_sets = any(r in sc.observables for sc in spec.scenarios)
            pareto = spec.pareto is not None and r in (spec.pareto.error_of, spec.pareto.minimise)
            uses = ("the sets that use it are not to be trusted" if in_sets else
                    "the Pareto front that uses it is indicative only" if pareto else
                    "do not use it to judge parameter sets")
            items.append(AdviceItem(spec.name, "recalibrate", "", "", r, (
                f"Refit or resimulate {_label(spec, r)}: its surrogate does not predict left-out runs (Q² < 0), so "
                f"{uses}.")))
    if level2 and not level2.get("feasible", True):
        limit = level2.get("bottleneck")
        if limit not in checked:
            which = (f"the target and the simulation of {_label(spec, limit)}, the observable that limits the best "
                     "match" if limit else "the targets and their simulation")
            items.append(AdviceItem(spec.name, "recalibrate", "", "", limit or "", (
                f"No parameter set meets every target within {level2_within(level2, spec)}: settle that first. "
                f"Check {which}.")))
    return items


def _unpredictive(level1: dict) -> set[str]:
    """The responses whose surrogate does not predict left-out runs (Q² < 0): advice built on them says so
    and quotes their numbers to :data:`~demid.precision.UNPREDICTIVE_DIGITS` (:func:`~demid.precision.rough_text`)."""
    return set(unpredictive_responses(level1))


def _not_predicting(spec, names) -> str:
    many = len(names) > 1
    return (f"the surrogate{'s' if many else ''} of {', '.join(_label(spec, o) for o in names)} "
            f"{'do' if many else 'does'} not predict left-out runs (Q² < 0)")


def _add_observable(spec, ranking, uninformative: dict, level2: dict, unpredictive=frozenset()) -> list[AdviceItem]:
    used = max((sc.observables for sc in spec.scenarios), key=len, default=())
    if not used or (level2 and not level2.get("feasible", True)):
        return []
    if ranking is not None and len(ranking):
        if "targets_reachable" in ranking.columns:
            ranking = ranking[ranking["targets_reachable"].astype(str).str.lower() == "true"]
        grow = ranking[(ranking["best_subset"] == "+".join(used)) & (ranking["n_observables"] == len(used) + 1)]
        grow = grow[[not any(o in uninformative for o in s.split("+") if o not in used) for s in grow["observables"]]]
        if len(grow):
            best = grow.sort_values("gain_vs_best_subset_bits", ascending=False).iloc[0]
            added = [o for o in best["observables"].split("+") if o not in used]
            measure = f"Measure {', '.join(_label(spec, o) for o in added)} as well"
            weak = [o for o in best["observables"].split("+") if o in unpredictive]
            bits = rough_text(best["gain_vs_best_subset_bits"])
            text = (f"{measure}: it adds {best['gain_vs_best_subset_bits']:.2f} bits of information and leaves "
                    f"{best['feasible_fraction_pct']:.3g} % of the domain admissible." if not weak else
                    f"{measure}: by the surrogates it adds about {bits} bit{'' if bits == '1' else 's'} of "
                    f"information and leaves about {rough_text(best['feasible_fraction_pct'])} % of the "
                    f"domain admissible, but {_not_predicting(spec, weak)}, so these numbers are rough.")
            return [AdviceItem(spec.name, "add_observable", "", "", "+".join(added), text)]
    return [AdviceItem(spec.name, "add_observable", "", "", "", GENERIC_ADD_OBSERVABLE)]


#: The add-observable advice when no observable can be named: said only where nothing else is advised.
GENERIC_ADD_OBSERVABLE = ("Every informative observable with a target is already used; a narrower set needs a new "
                          "kind of measurement or a tighter measurement (a smaller σ or tolerance).")


def decided(items: list[AdviceItem]) -> list[AdviceItem]:
    """One material's advice in :data:`PRIORITY` order (stable within a kind), the first marked as the next
    step; the generic add-observable line is dropped unless it is all there is (then it is the next step).
    Kinds outside :data:`PRIORITY` (:data:`RANKING_KINDS`) follow, in their order, never a step."""
    steps = [i for i in items if i.kind in PRIORITY]
    specific = [i for i in steps if i.text != GENERIC_ADD_OBSERVABLE]
    ordered = sorted(specific or steps, key=lambda i: PRIORITY.index(i.kind))
    return [replace(i, decision=k == 0) for k, i in enumerate(ordered)] + [i for i in items if i.kind not in PRIORITY]


def _unjudged_reach(spec, r: Reach, factor: str) -> str:
    """The recalibrate advice on a bound whose reach was estimated by a surrogate that does not predict: no
    verdict on widening, its numbers to one digit."""
    unit = _unit(spec, r.observable)
    u = f" {unit}" if unit and not unit.startswith("°") else unit
    per = "decade of" if r.log else "unit"
    return (f"Whether widening {factor} beyond its {r.side} bound can bring {_label(spec, r.observable)} to its "
            f"target cannot be judged: {_not_predicting(spec, [r.observable])}, so what it says there (about "
            f"{rough_text(abs(r.slope))}{u} per {per} {factor}, about {rough_text(abs(r.missing))}{u} short of the "
            f"target) is no evidence either way. Refit or resimulate {_label(spec, r.observable)} first, then "
            "judge the bound again.")


def _widen(spec, verdicts: pd.DataFrame, level2: dict, implausible: dict, unpredictive=frozenset()) -> list[AdviceItem]:
    sides: dict[str, set] = {}
    why: dict[str, list[str]] = {}
    for _, row in verdicts.iterrows():
        if not str(row["verdict"]).startswith("cut"):
            continue  # unresolved, uninformative or empty: a wider range narrows nothing
        found = str(row["verdict"]).split("(")[1].split(" bound")[0]
        sides.setdefault(row["factor"], set()).update(found.split(" and "))
        label = next((sc.label for sc in spec.scenarios if sc.name == row["scenario"]), row["scenario"])
        why.setdefault(row["factor"], []).append(f"the plausible set of *{label}* ends there only because the "
                                                 "search range does")
    misses = level2 and not level2.get("feasible", True)
    movable = [o for o in (level2 or {}).get("observables", []) if o not in (level2 or {}).get("unmoved", [])]
    items = []
    if misses and not any(o in implausible for o in (level2 or {}).get("observables", [])) and movable:
        # level 2's estimate of what widening buys (demid.criticism.reach): a bound whose extrapolation levels off
        # or needs a far extension is no place to look; the model lacks something (a factor not varied)
        beyond = [Reach.from_json(r) for r in level2.get("reach") or []]
        futile = {(r.factor, r.side): r for r in beyond if not r.widen}
        for name, value in (level2.get("best_point_at_bound") or {}).items():
            found = [s for s in (["lower", "upper"] if value == "both" else [value]) if s != "none"]
            for side in found:
                if (name, side) in futile:
                    r = futile[(name, side)]
                    f = next((x for x in spec.factors if x.name == name), None)
                    label = f.label if f else name
                    items.append(AdviceItem(spec.name, "recalibrate", name, side, r.observable, (
                        _unjudged_reach(spec, r, label) if r.observable in unpredictive else saturation_advice(
                            r, label, _label(spec, r.observable), _unit(spec, r.observable)))))
                    continue
                if "widen" in level2 and side not in level2["widen"].get(name, ()):
                    continue  # level 2 found the worst-missed observable flat along it: widening buys nothing
                sides.setdefault(name, set()).add(side)
                why.setdefault(name, []).append("no point meets every target and the best point lies on it")
    for f in spec.factors:
        for side in [s for s in ("lower", "upper") if s in sides.get(f.name, ())]:
            items.append(AdviceItem(spec.name, "widen", f.name, side, "", (
                f"Widen the range of {f.label} beyond its {_bound_text(f, side)} and simulate runs there: "
                f"{'; '.join(dict.fromkeys(why[f.name]))}.")))
    return items


def _next_wave(spec, value: dict | None, best_observable: str) -> list[AdviceItem]:
    if not value:
        return []
    label = next((sc.label for sc in spec.scenarios if sc.name == value["scenario"]), value["scenario"])
    shrink = value["expected_contraction"]
    shares = shares_change_text(value["plausible_fraction_pct"], value["expected_fraction_pct"])
    if value.get("stop"):
        helps = (f"measuring {best_observable}" if best_observable else "a new kind of measurement")
        return [AdviceItem(spec.name, "stop", "", "", "", (
            f"Stop simulating runs of this kind: the {value['count']} proposed runs (tables/next_runs.csv) are "
            f"expected to shrink the plausible set of *{label}* by only {100 * shrink:.1f} % "
            f"({shares} of the search range); "
            f"its width is set by the measurement band, not by the surrogate. What would help: {helps}, or a "
            "tighter measurement of the observables already used."))]
    expect = (f"they are expected to shrink the plausible set of *{label}* by about {100 * shrink:.0f} % "
              f"({shares} of the search range)"
              if np.isfinite(shrink) else "the plausible set is empty, so their value cannot be estimated")
    return [AdviceItem(spec.name, "next_runs", "", "", "", (
        f"Simulate the {value['count']} proposed runs (tables/next_runs.csv): {expect}."))]


def _measurement_order(spec, ranking, unpredictive=frozenset()) -> list[AdviceItem]:
    if ranking is None or not len(ranking):
        return []
    labels = {o: _label(spec, o) for o in spec.response_names}
    ranked = {o for s in ranking["observables"] for o in str(s).split("+")}
    weak = [o for o in spec.response_names if o in ranked and o in unpredictive]
    caveat = ([f"The ranking rests on surrogates of which {_not_predicting(spec, weak)}: its gains and fractions "
               "are rough, given to one significant digit."] if weak else [])
    return [AdviceItem(spec.name, "measurement_order", "", "", "", text)
            for text in caveat + measurement_order(ranking, labels, rough=bool(weak))]


#: The advice's opening words per kind of a simulated study's wave decision (demid.waves.stop_decision).
WAVE_DECISION_WORDS = {"stop": "Stop the waves", "next_runs": "Simulate another wave",
                       "recalibrate": "Do not take the plausible set as the answer yet"}


def _wave_decision(spec, decision: dict | None) -> list[AdviceItem]:
    """A simulated study's last wave decision as one ``stop``, ``next_runs`` or ``recalibrate`` item."""
    if not decision or not decision.get("reason"):
        return []
    action = decision["action"]
    return [AdviceItem(spec.name, action, "", "", "", f"{WAVE_DECISION_WORDS[action]}: {decision['reason']}.")]


def material_advice(spec, verdicts: pd.DataFrame, *, ranking: pd.DataFrame | None = None,
                    criticism: dict | None = None, implausible: dict | None = None,
                    uninformative: dict | None = None, wave_value: dict | None = None,
                    ridge_advice: list[str] = (), wave_decision: dict | None = None) -> list[AdviceItem]:
    """Every piece of advice of one material, the next step first (:func:`decided`).

    ``verdicts``: its rows of :func:`~demid.story.verdicts.verdict_frame`; ``criticism``: its
    ``criticism/{m}.json``; ``implausible``: :func:`~demid.data.implausible_targets` of its table;
    ``uninformative``: from the uncertainty summary; ``wave_value``: ``next_wave/value.json``'s entry;
    ``ridge_advice``: which other observable would break an identified combination's ridge
    (``combinations/{m}.json``), given as ``add_observable`` advice; ``ranking``: its rows of
    ``tables/observable_ranking.csv``, also walked through in words (``measurement_order``); ``wave_decision``: a
    simulated study's last wave decision (``waves/summary_{m}.json``), given as a ``stop``, ``next_runs`` or
    ``recalibrate`` item.
    """
    criticism, implausible, uninformative = criticism or {}, implausible or {}, uninformative or {}
    level2 = criticism.get("level2") or {}
    unpredictive = _unpredictive(criticism.get("level1") or {})
    checks = _check_targets(spec, implausible, ranking)
    add = _add_observable(spec, ranking, uninformative, level2, unpredictive)
    best = next((i.observable for i in add if i.observable), "")
    return decided(checks + _recalibrate(spec, criticism.get("level1") or {}, level2, {i.observable for i in checks})
                   + add + [AdviceItem(spec.name, "add_observable", "", "", "", text) for text in ridge_advice]
                   + _widen(spec, verdicts, level2, implausible, unpredictive)
                   + _next_wave(spec, wave_value, ", ".join(_label(spec, o) for o in best.split("+") if o))
                   + _wave_decision(spec, wave_decision)
                   + _measurement_order(spec, ranking, unpredictive))
