"""Configuration: JSON-schema validation with defaults, then the checks a schema cannot express."""

from __future__ import annotations

import copy
from pathlib import Path

import yaml

from .errors import InputError

# Shipped with the package (package data), so a non-editable install validates configs too.
SCHEMA_PATH = Path(__file__).resolve().parent / "schemas" / "config.schema.yaml"


def load_schema(path: Path | str = SCHEMA_PATH) -> dict:
    with open(path, encoding="utf-8") as fh:
        return yaml.safe_load(fh)


def _key_path(parts) -> str:
    return ".".join(str(p) for p in parts) or "(top level)"


def _resolve(schema: dict, root: dict) -> dict:
    ref = schema.get("$ref")
    if ref:
        node = root
        for part in ref.lstrip("#/").split("/"):
            node = node[part]
        return node
    return schema


def _fill_defaults(instance, schema: dict, root: dict):
    schema = _resolve(schema, root)
    if isinstance(instance, dict):
        for key, sub in schema.get("properties", {}).items():
            sub_r = _resolve(sub, root)
            if key not in instance and "default" in sub_r:
                instance[key] = copy.deepcopy(sub_r["default"])
            if key in instance:
                _fill_defaults(instance[key], sub_r, root)
        extra = schema.get("additionalProperties")
        if isinstance(extra, dict):
            for key, value in instance.items():
                if key not in schema.get("properties", {}):
                    _fill_defaults(value, extra, root)


def validate_schema(config: dict, source: str = "config") -> dict:
    """Validate against the schema, fill defaults, return a new dict.  Raises InputError."""
    import jsonschema  # only validation needs it, not the per-material jobs

    schema = load_schema()
    validator = jsonschema.Draft7Validator(schema)
    errors = sorted(validator.iter_errors(config), key=lambda e: (len(e.absolute_path), list(map(str, e.absolute_path))))
    if errors:
        err = errors[0]
        more = f" (and {len(errors) - 1} more problem(s))" if len(errors) > 1 else ""
        raise InputError(f"config key {_key_path(err.absolute_path)}: {err.message}{more}", source=source)
    config = copy.deepcopy(config)
    _fill_defaults(config, schema, schema)
    return config


def check_semantics(config: dict, source: str = "config", base_dir: Path | str = ".") -> None:
    """Cross-references the schema cannot check: names, targets, bounds, files."""
    base_dir = Path(base_dir)
    materials = config["materials"]
    smoke = config.get("smoke_material") or ""
    if smoke and smoke not in materials:
        raise InputError(f"config key smoke_material: unknown material '{smoke}' (known: {', '.join(materials)})",
                         source=source)
    for mname, mat in materials.items():
        key = f"materials.{mname}"
        factors = mat["factors"]
        responses = mat["responses"]
        path = base_dir / mat["data"]
        if not path.is_file():
            raise InputError(f"config key {key}.data: data file '{mat['data']}' does not exist", source=source)
        for fname, fac in factors.items():
            if not fac["lower"] < fac["upper"]:
                raise InputError(f"config key {key}.factors.{fname}: lower ({fac['lower']}) must be below "
                                 f"upper ({fac['upper']})", source=source)
            if fac.get("scale") == "log" and fac["lower"] <= 0:
                raise InputError(f"config key {key}.factors.{fname}: a log-scale factor needs lower > 0", source=source)
        clash = set(factors) & set(responses)
        if clash or "run" in factors or "run" in responses:
            raise InputError(f"config key {key}: names used both as factor and response/run: "
                             f"{', '.join(sorted(clash | ({'run'} & (set(factors) | set(responses)))))}", source=source)
        for rname, resp in responses.items():
            if "target" in resp and resp["target"] == 0:
                raise InputError(f"config key {key}.responses.{rname}.target: a relative tolerance needs a "
                                 f"non-zero target", source=source)
        for sname, scen in (mat.get("scenarios") or {}).items():
            for obs in scen["observables"]:
                skey = f"{key}.scenarios.{sname}.observables"
                if obs not in responses:
                    raise InputError(f"config key {skey}: unknown observable '{obs}' (responses: "
                                     f"{', '.join(responses)})", source=source)
                if "target" not in responses[obs]:
                    raise InputError(f"config key {skey}: observable '{obs}' has no target "
                                     f"(set {key}.responses.{obs}.target)", source=source)
        ref = mat.get("reference_point")
        if ref:
            for fname, value in ref.items():
                if fname not in factors:
                    raise InputError(f"config key {key}.reference_point: unknown factor '{fname}'", source=source)
            missing = [f for f in factors if f not in ref]
            if missing:
                raise InputError(f"config key {key}.reference_point: missing factor(s) {', '.join(missing)}",
                                 source=source)
        par = mat.get("pareto")
        if par:
            for role in ("error_of", "minimise"):
                if par[role] not in responses:
                    raise InputError(f"config key {key}.pareto.{role}: unknown response '{par[role]}'", source=source)
            if "target" not in responses[par["error_of"]]:
                raise InputError(f"config key {key}.pareto.error_of: response '{par['error_of']}' has no target",
                                 source=source)
        design = mat["design"]
        if design["type"] == "ccd" and design.get("alpha", 1.0) < 1.0:
            raise InputError(f"config key {key}.design.alpha: a CCD needs alpha >= 1", source=source)


def load_config(path: Path | str, base_dir: Path | str | None = None) -> dict:
    """Read, validate and complete a config file; raises InputError with the key path."""
    path = Path(path)
    if not path.is_file():
        raise InputError("config file does not exist", source=str(path))
    try:
        with open(path, encoding="utf-8-sig") as fh:
            raw = yaml.safe_load(fh)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark is not None else ""
        raise InputError(f"not valid YAML{where}: {getattr(exc, 'problem', exc)}", source=str(path)) from None
    if not isinstance(raw, dict):
        raise InputError("expected a mapping with a 'materials' key", source=str(path))
    config = validate_schema(raw, source=str(path))
    check_semantics(config, source=str(path), base_dir=base_dir if base_dir is not None else Path.cwd())
    return config


def grid_size(config: dict, material: str) -> int:
    """Grid points per axis (Sobol points above 3 factors) of a material (see demid.spec)."""
    from .spec import evaluation_size

    return evaluation_size(config, config["materials"][material])
