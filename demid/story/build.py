"""The verdict and advice tables of a study, from the files of its results tree."""

from __future__ import annotations

import json
from pathlib import Path

import pandas as pd

from .advice import ADVICE_COLUMNS, StudyAdvice, material_advice
from .verdicts import VERDICT_COLUMNS, in_combination, verdict_frame


def _json(path) -> dict:
    return json.loads(Path(path).read_text(encoding="utf-8")) if path and Path(path).is_file() else {}


def study_story(specs: dict, files: dict) -> tuple[pd.DataFrame, pd.DataFrame]:
    """``(verdicts, advice)`` of every material.

    ``specs``: material -> :class:`~demid.spec.MaterialSpec`.  ``files``: ``identifiability``, ``plausible``,
    ``ranking`` (the cross-material CSV tables), and per material (dicts material -> path) ``tables``
    (validated parquet), ``criticism`` and ``uncertainty`` (JSON summaries); optional ``next_wave_value``
    (JSON, materials with ``next_runs``); optional per material ``combinations`` (JSON: what each set
    identifies in combination, and which observable would break a ridge); optional per simulated material
    ``wave_summaries`` (JSON: its waves and the last wave's decision, :func:`demid.waves.wave_summary`).
    """
    from ..data import implausible_targets
    from ..io import read_parquet

    ident = pd.read_csv(files["identifiability"])
    plausible = pd.read_csv(files["plausible"])
    ranking = pd.read_csv(files["ranking"])
    value = _json(files.get("next_wave_value"))
    verdicts, advice = [], []
    for m, spec in specs.items():
        uncertainty = _json(files["uncertainty"][m])
        uninformative = uncertainty.get("uninformative") or {}
        table = read_parquet(files["tables"][m])
        implausible = implausible_targets(table, spec.targets)
        frame = verdict_frame(spec, ident[ident["material"] == m], plausible[plausible["material"] == m], uninformative,
                              implausible)
        combinations = _json((files.get("combinations") or {}).get(m))
        frame = in_combination(frame, spec, combinations)
        verdicts.append(frame)
        advice += material_advice(spec, frame, ranking=ranking[ranking["material"] == m],
                                  criticism=_json(files["criticism"][m]),
                                  implausible=implausible, uninformative=uninformative,
                                  wave_value=value.get(m), ridge_advice=combinations.get("advice") or [],
                                  wave_decision=_json((files.get("wave_summaries") or {}).get(m)).get("decision"))
    verdict_table = pd.concat(verdicts, ignore_index=True) if verdicts else pd.DataFrame(columns=VERDICT_COLUMNS)
    advice_table = StudyAdvice(advice).to_frame() if advice else pd.DataFrame(columns=ADVICE_COLUMNS)
    return verdict_table, advice_table
