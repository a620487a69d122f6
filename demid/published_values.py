"""The published-values file (config key ``published``): its layout and names, checked before any job.

The layout is ``schemas/published.schema.yaml``; the names (materials, responses, scenarios, factors) are
the config's, and each number must be a possible value of its kind.  A slip here would otherwise surface
as a traceback in the last job or as an empty row of the paper comparison.
"""

from __future__ import annotations

import difflib
import math
from pathlib import Path

from .errors import InputError

SCHEMA_PATH = Path(__file__).resolve().parent / "schemas" / "published.schema.yaml"

def out_of_range(raw, value: float, low: float, high: float, name: str, percent: bool = True) -> str:
    """Why a published number cannot be what was printed ("" when it can): outside [low, high], with the
    fraction as hint when it reads as a percentage (an R² of 98.9).  Shared with the transcription check's
    statistics (transcription.printed.impossible_published)."""
    if low <= value <= high:
        return ""
    if math.isinf(high):
        bounds = "it cannot be negative" if low == 0 else f"it cannot be below {low:g}"
    else:
        bounds = f"it lies between {low:g} and {high:g}"
    hint = f"; written in percent? {value:g} % is {value / 100:g}" if percent and 1 < value <= 100 else ""
    return f"{raw} is not a possible {name} ({bounds}){hint}"


def _closest(name: str, known) -> str:
    """'; did you mean X?' when one known name is clearly closest, else the known names."""
    known = [str(k) for k in known]
    scores = sorted(((difflib.SequenceMatcher(None, str(name), k).ratio(), k) for k in known), reverse=True)
    if scores and scores[0][0] >= 0.6 and (len(scores) == 1 or scores[1][0] < scores[0][0]):
        return f"; did you mean '{scores[0][1]}'?"
    return f" (known: {', '.join(known) or 'none'})"


def _names(mat: dict, key: str):
    """The config material's responses, scenarios or factors; None for another study's material."""
    return (mat.get(key) or {}) if mat else None


def _key(path: list) -> str:
    """Key path as written in YAML; list items counted from 1 (contractions (item 2).factor)."""
    text = ""
    for part in path:
        text += f" (item {part + 1})" if isinstance(part, int) else (f".{part}" if text else str(part))
    return text


class _Checker:
    def __init__(self, materials: dict, where: str):
        self.materials = materials
        self.where = where

    def fail(self, path: list, message: str) -> None:
        key = _key(path)
        raise InputError(f"{self.where}, key {key}: {message}" if key else f"{self.where}: {message}")

    def name(self, path: list, value, known, what: str) -> None:
        if known is None:  # another study's material: not checked
            return
        if value not in known:
            self.fail(path, f"'{value}' is not a {what}{_closest(value, list(known))}")

    def material(self, path: list, name) -> dict:
        """The config's material, or {} for another study's material (its entries are not compared)."""
        if name not in self.materials and difflib.get_close_matches(str(name), list(self.materials), 1, 0.8):
            self.name(path, name, self.materials, "material of the config")  # a likely typo
        return self.materials.get(name, {})

    def number(self, path: list, raw, low: float = -math.inf, high: float = math.inf, what: str = "value",
               percent: bool = False) -> float:
        value = float(raw)
        why = out_of_range(raw, value, low, high, what, percent)
        if why:
            self.fail(path, why)
        return value

    def interval(self, path: list, pair, strict: bool = False) -> None:
        low, high = (float(v) for v in pair)
        if low > high or (strict and low == high):
            self.fail(path, f"[{pair[0]}, {pair[1]}] has its lower end {'above' if low > high else 'at'} its upper "
                            f"end{'; a search range needs lower < upper' if strict else ''}")


def _schema_error(content: dict, where: str) -> None:
    import jsonschema

    from .schema import load_schema

    schema = load_schema(SCHEMA_PATH)
    errors = sorted(jsonschema.Draft7Validator(schema).iter_errors(content),
                    key=lambda e: (len(e.absolute_path), list(map(str, e.absolute_path))))
    if not errors:
        return
    err = errors[0]
    path = list(err.absolute_path)
    if err.validator == "anyOf" and err.schema == schema["definitions"]["number"]:
        message = f"{err.instance!r} is not a number"
    elif err.validator == "additionalProperties" and isinstance(err.instance, dict):
        allowed = list(err.schema.get("properties", {}))
        extra = [k for k in err.instance if k not in allowed]
        from .schema import decimal_comma_hint

        message = f"unknown key '{extra[0]}'{_closest(extra[0], allowed)}{decimal_comma_hint(err)}"
    elif err.validator == "type":
        words = {"array": "a list", "object": "a mapping (name: value)", "string": "text"}
        message = f"{err.instance!r} should be {words.get(err.validator_value, err.validator_value)}"
        if err.validator_value == "array" and err.schema.get("maxItems") == 2:
            message += ", [lower, upper]"
    elif err.validator in ("minItems", "maxItems"):
        message = f"{err.instance!r} must be two numbers, [lower, upper]"
    else:
        message = err.message
    _Checker({}, where).fail(path, message)


def check_published_values(content: dict, materials: dict, where: str) -> None:
    """Raise :class:`InputError` (naming ``where`` and the key) at the first slip in a published-values file.

    ``materials`` is the validated config's ``materials`` mapping.  A material the config does not study
    (a file shared by several studies, a config for one material) is left out, unless its name is a
    likely typo of one the config studies."""
    _schema_error(content, where)
    c = _Checker(materials, where)
    for m, by_name in (content.get("targets") or {}).items():
        mat = c.material(["targets", m], m)
        for r in by_name:
            c.name(["targets", m, r], r, _names(mat, "responses"), f"response of {m}")
    for m, by_scenario in (content.get("tolerances") or {}).items():
        mat = c.material(["tolerances", m], m)
        for s, eps in by_scenario.items():
            c.name(["tolerances", m, s], s, _names(mat, "scenarios"), f"scenario of {m}")
            c.number(["tolerances", m, s], eps, 0, 1, "relative tolerance", percent=True)
    for m, by_response in (content.get("table2") or {}).items():
        mat = c.material(["table2", m], m)
        for r, stats in by_response.items():
            c.name(["table2", m, r], r, _names(mat, "responses"), f"response of {m}")
            if "r2" in stats:
                c.number(["table2", m, r, "r2"], stats["r2"], 0, 1, "R²", percent=True)
            if "rmse" in stats:
                c.number(["table2", m, r, "rmse"], stats["rmse"], 0, what="RMSE")
    for m, by_scenario in (content.get("table3") or {}).items():
        mat = c.material(["table3", m], m)
        for s, entry in by_scenario.items():
            _check_set(c, ["table3", m, s], mat, m, s, entry)
    for i, item in enumerate(content.get("contractions") or []):
        path = ["contractions", i]
        mat = c.material(path + ["material"], item["material"])
        for end in ("from", "to"):
            c.name(path + [end], item[end], _names(mat, "scenarios"), f"scenario of {item['material']}")
        if item["quantity"] == "width":
            if "factor" not in item:
                c.fail(path, "a width contraction needs factor: (whose width)")
            c.name(path + ["factor"], item["factor"], _names(mat, "factors"), f"factor of {item['material']}")
        c.number(path + ["value"], item["value"], -100, math.inf, "contraction in %")
    for m, by_scenario in (content.get("intervals") or {}).items():
        mat = c.material(["intervals", m], m)
        for s, by_factor in by_scenario.items():
            c.name(["intervals", m, s], s, _names(mat, "scenarios"), f"scenario of {m}")
            _check_intervals(c, ["intervals", m, s], mat, m, by_factor)
    for m, by_factor in (content.get("search_domain") or {}).items():
        _check_intervals(c, ["search_domain", m], c.material(["search_domain", m], m), m, by_factor, strict=True)
    for m, by_scenario in (content.get("scenario_sets") or {}).items():
        mat = c.material(["scenario_sets", m], m)
        domain = (content.get("search_domain") or {}).get(m, {})
        for s, entry in by_scenario.items():
            _check_set(c, ["scenario_sets", m, s], mat, m, s, entry)
            for f in entry.get("unresolved") or []:
                c.name(["scenario_sets", m, s, "unresolved"], f, _names(mat, "factors"), f"factor of {m}")
                if f not in domain:
                    c.fail(["scenario_sets", m, s, "unresolved"], f"'{f}' unresolved over its search range needs "
                                                                   f"search_domain.{m}.{f}: [lower, upper]")
    for m, entry in (content.get("pareto") or {}).items():
        mat = c.material(["pareto", m], m)
        if mat and not mat.get("pareto"):
            c.fail(["pareto", m], f"the config computes no Pareto front for {m} (materials.{m}.pareto is not set), "
                                  "so these intervals would have nothing to be compared with")
        c.number(["pareto", m, "max_error"], entry["max_error"], 0, 1, "relative error", percent=True)
        _check_intervals(c, ["pareto", m, "intervals"], mat, m, entry["intervals"])
    for m, point in (content.get("reference_points") or {}).items():
        mat = c.material(["reference_points", m], m)
        for f in point:
            c.name(["reference_points", m, f], f, _names(mat, "factors"), f"factor of {m}")


def _check_set(c: _Checker, path: list, mat: dict, m: str, s: str, entry: dict) -> None:
    c.name(path, s, _names(mat, "scenarios"), f"scenario of {m}")
    if "feasible_fraction_pct" in entry:
        c.number(path + ["feasible_fraction_pct"], entry["feasible_fraction_pct"], 0, 100, "feasible fraction in %")
    for group in ("width", "upper", "lower"):
        for f, value in (entry.get(group) or {}).items():
            c.name(path + [group, f], f, _names(mat, "factors"), f"factor of {m}")
            if group == "width":
                c.number(path + [group, f], value, 0, what="width")


def _check_intervals(c: _Checker, path: list, mat: dict, m: str, by_factor: dict, strict: bool = False) -> None:
    for f, pair in by_factor.items():
        c.name(path + [f], f, _names(mat, "factors"), f"factor of {m}")
        c.interval(path + [f], pair, strict)


def for_materials(content: dict, materials) -> dict:
    """The published numbers of the studied ``materials`` only (what the paper comparison holds against the
    reproduction): the per-material sections and the contractions filtered, the rest kept."""
    keep = set(materials)
    out = {}
    for key, value in content.items():
        if key == "contractions":
            out[key] = [item for item in value or [] if item.get("material") in keep]
        elif key in ("source", "provenance"):
            out[key] = value
        else:
            out[key] = {m: entry for m, entry in (value or {}).items() if m in keep}
    return out
