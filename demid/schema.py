"""The configuration's schema: loading YAML, validating against the JSON schema shipped in the package,
filling its defaults, and the hints for common slips.  The bottom of the input layer: it imports no other
module of demid but ``errors``; the cross-checks that call the rest of the package live in demid.config."""

from __future__ import annotations

import copy
import functools
import re
from pathlib import Path

import numpy as np
import yaml

from .errors import InputError
from .numbers import LARGEST, unusable_number

# Shipped with the package (package data), so a non-editable install validates configs too.
SCHEMA_PATH = Path(__file__).resolve().parent / "schemas" / "config.schema.yaml"


def load_schema(path: Path | str = SCHEMA_PATH) -> dict:
    """The schema at ``path`` (a copy: the caller may change it)."""
    return copy.deepcopy(parsed_schema(str(Path(path).resolve())))


@functools.lru_cache(maxsize=None)
def parsed_schema(path: str) -> dict:
    """The schema file at ``path`` as parsed YAML (cached: read once per process)."""
    # Parsed once per process: every MaterialSpec built from a bare entry reads the schema's defaults (the
    # report builds 33), and the YAML parse costs several times the copy.
    # libyaml's safe loader when built (same YAML rules, ~10x faster): every parse of the workflow reads this
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    with open(path, encoding="utf-8") as fh:
        return yaml.load(fh, Loader=loader)  # noqa: S506 (a safe loader)


def material_property(key: str) -> dict:
    """The schema of a ``materials`` entry key (its enum, default, description)."""
    return copy.deepcopy(load_schema()["definitions"]["material"]["properties"][key])


def material_with_defaults(material: dict) -> dict:
    """A copy of one ``materials`` entry with the schema's defaults filled in where keys are absent (an entry
    of a validated config already has them; a bare entry built by a library caller or a test gets them here,
    so that the schema stays the only source of defaults)."""
    return _with_defaults(material, "definitions", "material")


def definition_with_defaults(name: str, block: dict | None) -> dict:
    """A copy of an optional block of the schema's definition ``name`` (absent: an empty block) with that
    definition's defaults filled in, so that an optional block's settings default from the schema only."""
    return _with_defaults(block or {}, "definitions", name)


def design_with_defaults(design: dict) -> dict:
    """A copy of a ``design`` block (from the config, ``--design`` or the table's inferred geometry) with the
    schema's defaults (``alpha``, ``center_runs``) filled in where absent; keys the schema does not know (an
    inferred design's ``inferred`` flag) are kept."""
    return _with_defaults(design, "definitions", "material", "properties", "design")


def _with_defaults(block: dict, *path: str) -> dict:
    """A copy of ``block`` with the defaults of the schema node at ``path`` filled in where absent."""
    schema = load_schema()
    node = schema
    for key in path:
        node = node[key]
    block = copy.deepcopy(block)
    _fill_defaults(block, node, schema)
    return block


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


# PyYAML (YAML 1.1) reads 1e-6 -- no decimal point, no signed exponent -- as a string.
_BARE_EXPONENT = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)[eE][-+]?\d+\s*$")


def _as_number(text: str, expected) -> float | int | None:
    types = set(np.atleast_1d(expected))
    value = float(text)
    if "number" in types:
        return value
    return int(value) if "integer" in types and value.is_integer() else None


def _numbers_written_as_strings(config: dict, validator) -> dict:
    """A copy where strings such as '1e-6' are read as the numbers the schema expects there."""
    config = copy.deepcopy(config)
    while True:
        fixable = [(e, _as_number(e.instance, e.validator_value)) for e in validator.iter_errors(config)
                   if e.validator == "type" and isinstance(e.instance, str) and _BARE_EXPONENT.match(e.instance)
                   and e.absolute_path]
        fixable = [(e, v) for e, v in fixable if v is not None]
        if not fixable:
            return config
        err, value = fixable[0]
        node = config
        for part in list(err.absolute_path)[:-1]:
            node = node[part]
        node[err.absolute_path[-1]] = value


def _hint(err) -> str:
    """What a likely slip meant: a tolerance written in percent (5 for 0.05)."""
    key = str(err.absolute_path[-1]) if err.absolute_path else ""
    path = list(err.absolute_path)
    in_tolerances = (key in ("tolerance", "sigma_rel", "max_error")
                     or (len(path) > 1 and path[-2] == "sweep_tolerances"))
    if in_tolerances and err.validator in ("maximum", "exclusiveMaximum") and isinstance(err.instance, (int, float)):
        what = {"sigma_rel": "relative measurement errors", "max_error": "relative errors"}.get(key, "tolerances")
        return f"; {what} are fractions: {err.instance:g} % is {err.instance / 100:g}"
    return ""


def decimal_comma_hint(err) -> str:
    """A number written with a decimal comma inside {...} (target: 26,4) leaves a number as a key of its own."""
    if err.validator != "additionalProperties" or not isinstance(err.instance, dict):
        return ""
    extra = [k for k in err.instance if k not in err.schema.get("properties", {})]
    if extra and all(isinstance(k, (int, float)) or re.fullmatch(r"\d+", str(k)) for k in extra):
        return "; a number written with a decimal comma? write decimals with a point (26.4, not 26,4)"
    return ""


def validate_schema(config: dict, source: str = "config") -> dict:
    """Validate against the schema, fill defaults, return a new dict.  Raises InputError."""
    import jsonschema  # only validation needs it, not the per-material jobs

    schema = load_schema()
    validator = jsonschema.Draft7Validator(schema)
    config = _numbers_written_as_strings(config, validator)
    errors = sorted(validator.iter_errors(config), key=lambda e: (len(e.absolute_path), list(map(str, e.absolute_path))))
    if errors:
        err = errors[0]
        more = f" (and {len(errors) - 1} more problem(s))" if len(errors) > 1 else ""
        raise InputError(f"config key {_key_path(err.absolute_path)}: {err.message}{_hint(err)}"
                         f"{decimal_comma_hint(err)}{more}", source=source)
    _refuse_non_finite(config, [], source)
    config = copy.deepcopy(config)
    _fill_defaults(config, schema, schema)
    return config


def _refuse_non_finite(node, path: list, source: str) -> None:
    """YAML's .nan and .inf pass the schema's number type but mean nothing as a bound, target, tolerance or
    setting: one line naming the key."""
    if isinstance(node, dict):
        for key, value in node.items():
            _refuse_non_finite(value, [*path, key], source)
    elif isinstance(node, list):
        for i, value in enumerate(node):
            _refuse_non_finite(value, [*path, i], source)
    elif isinstance(node, float) and not np.isfinite(node):
        raise InputError(f"config key {_key_path(path)}: {node} is not a usable number; give a finite value",
                         source=source)
    elif isinstance(node, float) and unusable_number(node):
        raise InputError(f"config key {_key_path(path)}: {unusable_number(node)}", source=source)
    elif isinstance(node, int) and not isinstance(node, bool) and abs(node) > LARGEST:
        shown = f"{node}" if len(str(node)) < 40 else f"a number of {len(str(abs(node)))} digits"
        raise InputError(f"config key {_key_path(path)}: found {shown}, outside the magnitudes demid computes "
                         "with (at most 1e30)", source=source)


class _UniqueKeyLoader(yaml.SafeLoader):
    """SafeLoader that refuses a key given twice in one mapping (YAML keeps the last one silently)."""


def _construct_unique_mapping(loader, node, deep=False):
    seen = {}
    for key_node, _ in node.value:
        if key_node.tag == "tag:yaml.org,2002:merge":
            continue  # `<<: *anchor` merges a mapping; a key given beside it overrides the merged one
        key = loader.construct_object(key_node, deep=deep)
        if isinstance(key, (str, int, float, bool)) and key in seen:
            raise InputError(f"line {key_node.start_mark.line + 1}: key '{key}' is given twice in one mapping (first "
                             f"at line {seen[key]}); YAML would silently keep only the last, so remove one")
        seen[key] = key_node.start_mark.line + 1
    return loader.construct_mapping(node, deep=deep)


_UniqueKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_unique_mapping)


#: Values aliases (``*name``) may add to a YAML document beyond those written in it: anchors and merge
#: keys for repeated factors add a few hundred; nine levels of nine aliases (a 1 KB file) add 387 million.
MAX_ALIAS_EXPANSION = 100_000


def _refuse_alias_expansion(root) -> None:
    """InputError when the document's aliases, expanded, add more than MAX_ALIAS_EXPANSION values:
    counted on the composed nodes (each counted once, however often it is referred to), before anything
    is built from them."""
    expanded: dict[int, int] = {}

    def size(node) -> int:
        known = expanded.get(id(node))
        if known is not None:
            return known
        total = 1
        if isinstance(node, yaml.SequenceNode):
            total += sum(size(child) for child in node.value)
        elif isinstance(node, yaml.MappingNode):
            total += sum(size(key) + size(value) for key, value in node.value)
        expanded[id(node)] = total
        return total

    total = size(root)
    if total - len(expanded) <= MAX_ALIAS_EXPANSION:
        return
    node = root  # the line named: the innermost value that alone expands beyond the limit
    while isinstance(node, (yaml.SequenceNode, yaml.MappingNode)):
        children = node.value if isinstance(node, yaml.SequenceNode) else [v for _, v in node.value]
        biggest = max(children, key=size, default=None)
        if biggest is None or size(biggest) <= MAX_ALIAS_EXPANSION:
            break
        node = biggest
    raise InputError(f"line {node.start_mark.line + 1}: aliases (*name) expand the document to {total:,} values, "
                     f"more than {MAX_ALIAS_EXPANSION:,} beyond those written; write the values out")


def load_yaml(path: Path | str):
    """A YAML file as Python objects; unreadable text, invalid YAML and repeated keys raise InputError."""
    path = Path(path)
    try:
        with open(path, encoding="utf-8-sig") as fh:
            loader = _UniqueKeyLoader(fh)
            try:
                node = loader.get_single_node()
                if node is None:
                    return None
                _refuse_alias_expansion(node)
                return loader.construct_document(node)
            finally:
                loader.dispose()
    except UnicodeDecodeError as exc:
        raise InputError(f"not UTF-8 text (byte {exc.start}); save it as UTF-8", source=str(path)) from None
    except InputError as err:
        raise InputError(str(err), source=str(path)) from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark is not None else ""
        raise InputError(f"not valid YAML{where}: {getattr(exc, 'problem', exc)}", source=str(path)) from None
