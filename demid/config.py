"""Configuration: JSON-schema validation with defaults, then the checks a schema cannot express."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .design import unreadable_alpha
from .errors import InputError
# The schema half (load, defaults, hints) is demid.schema; load_yaml and validate_schema are still imported from here.
from .schema import load_yaml, validate_schema

#: Table columns with a meaning of their own: the run number and the run's status.
RESERVED_COLUMNS = ("run", "status", "block")


def reserved_column_problem(names) -> str:
    """Why one of ``names`` cannot be a factor or response ("" when none is reserved)."""
    reserved = [n for n in names if n in RESERVED_COLUMNS]
    return (f"'{reserved[0]}' names a column demid reads itself (run: the run number, status: ok or failed, block: the block a run was made in), not "
            "a factor or response" if reserved else "")

# Evaluation points per material held in memory at once (2**24: about 4096**2 or 256**3).
MAX_GRID_NODES = 2 ** 24


def _check_results_dir(config: dict, source: str) -> None:
    results = str(config.get("results_dir", "results")).strip()
    if not results or Path(results).resolve() == Path(Path(results).resolve().anchor):
        raise InputError(f"config key results_dir: '{config.get('results_dir')}' would write the results into "
                         "the file-system root; name a folder, e.g. results", source=source)
    if "{" in results or "}" in results:  # Snakemake would read the braces of every output path as wildcards
        raise InputError(f"config key results_dir: '{results}' holds a brace; name a folder without {{ or }}",
                         source=source)
    existing = next((p for p in [Path(results), *Path(results).parents] if p.exists() and not p.is_dir()), None)
    if existing is not None:
        raise InputError(f"config key results_dir: '{existing}' is an existing file, not a folder; name a folder "
                         "for the results", source=source)


def _check_grid_sizes(config: dict, source: str) -> None:
    for mname, mat in config["materials"].items():
        d = len(mat["factors"])
        size = grid_size(config, mname)
        nodes = size ** d if d <= 3 else size
        if nodes > MAX_GRID_NODES:
            key = (f"materials.{mname}.grid_points" if mat.get("grid_points")
                   else "grid_points" if d <= 2 else "grid_points_3d" if d == 3 else "sobol_points")
            most = int(round(MAX_GRID_NODES ** (1 / d))) if d <= 3 else MAX_GRID_NODES
            raise InputError(f"config key {key}: {size} gives {nodes:,} evaluation points for material '{mname}' "
                             f"({d} factors), more than the {MAX_GRID_NODES:,} held in memory; use at most "
                             f"{most}", source=source)


def _check_labels(config: dict, source: str) -> None:
    """Labels drawn as matplotlib mathtext ($...$, or `_`/`^` typeset by demid): a typo would only fail in a late job."""
    from .spec import label_entries

    for mname, mat in config["materials"].items():
        check_labels(label_entries(mname, mat), source)


def check_labels(entries, source: str | None = None) -> None:
    """One material's labels (``(config key, text)`` pairs: :meth:`MaterialSpec.label_entries`), parsed as
    matplotlib draws them (the workflow checks them in the material's job: matplotlib's parser costs more than
    every other start-up check together)."""
    from .plots.labels import tex_label, tex_unit

    # Checked as drawn: demid typesets `_` and `^` itself, so a label without `$` can become mathtext too.
    drawn = [(key, text, tex_unit(text) if key.endswith(".unit") else tex_label(text))
             for key, text in entries]
    math = [(key, text, shown) for key, text, shown in drawn if shown.count("$") - shown.count(r"\$") >= 2]
    if not math:
        return
    from matplotlib import cbook
    from matplotlib.mathtext import MathTextParser

    parser = MathTextParser("path")
    for key, text, shown in math:
        if not cbook.is_math_text(shown):
            continue
        try:
            parser.parse(shown)
        except ValueError as exc:
            reason = " ".join(str(exc).split())
            if len(reason) > 90:  # pyparsing lists every construct it expected
                reason = reason[:87] + "..."
            raise InputError(f"config key {key}: '{text}' is not valid matplotlib mathtext ({reason}); fix it "
                             r"(`^` and `_` need something after them; write \$ for a literal dollar sign)",
                             source=source) from None


#: Where relative paths in a config point: said whenever a file is not found there.
_RELATIVE_TO = ("paths in the config are relative to the folder the pipeline runs in (snakemake --directory), or "
                "to the config's own folder for python -m demid validate")


def _check_published_file(published: str, base_dir: Path, source: str, materials: dict) -> None:
    """The published-values file must exist and hold the published numbers of this study's materials,
    responses, scenarios and factors (demid.published_values), before any job is scheduled."""
    if not published:
        return
    path = base_dir / published
    if path.is_dir():
        raise InputError(f"config key published: '{published}' is a folder ({path.resolve()}); name the YAML file "
                         "of published numbers in it", source=source)
    if not path.is_file():
        raise InputError(f"config key published: file '{published}' does not exist (looked for {path.resolve()}; "
                         f"{_RELATIVE_TO})", source=source)
    try:
        content = load_yaml(path)
    except InputError as err:
        raise InputError(f"config key published: {err}", source=source) from None
    if not isinstance(content, dict):
        raise InputError(f"config key published: '{published}' must hold a mapping (material -> published "
                         "numbers)", source=source)
    from .published_values import check_published_values

    check_published_values(content, materials, f"config key published: {published}")


def check_semantics(config: dict, source: str = "config", base_dir: Path | str = ".", labels: bool = True) -> None:
    """Cross-references the schema cannot check: names, targets, bounds, files (and, with ``labels``, that every
    label parses as mathtext; see :func:`check_labels`)."""
    base_dir = Path(base_dir)
    _check_results_dir(config, source)
    _check_grid_sizes(config, source)
    if labels:
        _check_labels(config, source)
    materials = config["materials"]
    smoke = config.get("smoke_material") or ""
    if smoke and smoke not in materials:
        raise InputError(f"config key smoke_material: unknown material '{smoke}' (known: {', '.join(materials)})",
                         source=source)
    for mname, mat in materials.items():
        key = f"materials.{mname}"
        _check_declared(key, mat, source)
        _check_table_and_bounds(key, mat, base_dir, source)
        _check_names(key, mat["factors"], mat["responses"], source)
        _check_cross_references(key, mat, source)
        _check_design(key, mat["design"], source)
        _check_published_ranges(key, mat["responses"], source)
        _check_scenario_labels(key, mat.get("scenarios") or {}, source)
        _check_extends(key, mname, mat.get("extends") or "", config["materials"], source)
    # After the materials: the published numbers are checked against their names.
    _check_published_file(config.get("published") or "", base_dir, source, config["materials"])


def _check_declared(key: str, mat: dict, source: str) -> None:
    """At least two factors, a target, a scenario, and not both sigma and sigma_rel nor both tolerance and
    tolerance_abs on one response."""
    factors, responses = mat["factors"], mat["responses"]
    if len(factors) < 2:
        raise InputError(f"config key {key}.factors: only one factor ('{next(iter(factors))}'); demid needs at "
                         "least two (admissible sets, posteriors and surfaces are drawn over factor pairs)",
                         source=source)
    if not any("target" in resp for resp in responses.values()):
        raise InputError(f"config key {key}.responses: no response has a target; give at least one measured "
                         f"value (e.g. {key}.responses.{next(iter(responses))}.target), or there is nothing "
                         "to calibrate against", source=source)
    both = next((r for r, resp in responses.items() if "sigma" in resp and "sigma_rel" in resp), None)
    if both:
        raise InputError(f"config key {key}.responses.{both}: both sigma ({responses[both]['sigma']:g}) and "
                         f"sigma_rel ({responses[both]['sigma_rel']:g}) are given; keep the one the measurement "
                         "reports", source=source)
    both = next((r for r, resp in responses.items() if "tolerance" in resp and "tolerance_abs" in resp), None)
    if both:
        raise InputError(f"config key {key}.responses.{both}: both tolerance and tolerance_abs are given; keep "
                         "one", source=source)
    if not mat.get("scenarios"):
        targeted = [r for r, resp in responses.items() if "target" in resp]
        raise InputError(f"config key {key}.scenarios: no scenario; admissible sets need at least one, e.g. "
                         f"scenarios: {{all: {{observables: [{', '.join(targeted)}], tolerance: 0.05}}}}",
                         source=source)


def _check_table_and_bounds(key: str, mat: dict, base_dir: Path, source: str) -> None:
    """The table exists (or the simulation's command is checked), and every factor's bounds are ordered."""
    factors = mat["factors"]
    path = None if _table_or_simulation(key, mat, source) else base_dir / mat["data"]
    if path is not None and not path.is_file():
        raise InputError(f"config key {key}.data: data file '{mat['data']}' does not exist (looked for "
                         f"{path.resolve()}; {_RELATIVE_TO})", source=source)
    for fname, fac in factors.items():
        if not fac["lower"] < fac["upper"]:
            raise InputError(f"config key {key}.factors.{fname}: lower ({fac['lower']}) must be below "
                             f"upper ({fac['upper']})", source=source)
        if fac.get("scale") == "log" and fac["lower"] <= 0:
            raise InputError(f"config key {key}.factors.{fname}: a log-scale factor needs lower > 0", source=source)
        if fac.get("scale") == "log" and not np.log10(float(fac["lower"])) < np.log10(float(fac["upper"])):
            # searched in log10: bounds that share it to the last bit give a range of no width
            raise InputError(f"config key {key}.factors.{fname}: lower ({fac['lower']}) and upper ({fac['upper']}) "
                             f"have the same log10 to machine precision; a log-scale range needs them apart",
                             source=source)
        if path is None:  # a table's material: checked with its table, after the bounds' slips (data.py)
            _check_limits(f"{key}.factors.{fname}", fac, source)


def _check_names(key: str, factors: dict, responses: dict, source: str) -> None:
    """No name is both factor and response nor a reserved column; no target is 0 (relative tolerances)."""
    clash = set(factors) & set(responses)
    if clash:
        raise InputError(f"config key {key}: names used both as factor and response: "
                         f"{', '.join(sorted(clash))}", source=source)
    reserved = reserved_column_problem(sorted(set(factors) | set(responses)))
    if reserved:
        raise InputError(f"config key {key}: {reserved}; rename that column in the table and the config",
                         source=source)
    for rname, resp in responses.items():
        if "target" in resp and resp["target"] == 0:
            raise InputError(f"config key {key}.responses.{rname}.target: a relative tolerance needs a "
                             f"non-zero target", source=source)


def _check_cross_references(key: str, mat: dict, source: str) -> None:
    """Scenarios, the reference point and the Pareto front name the material's own responses and factors."""
    factors, responses = mat["factors"], mat["responses"]
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
        if par["error_of"] == par["minimise"]:
            raise InputError(f"config key {key}.pareto: error_of and minimise are both '{par['minimise']}'; "
                             "a trade-off needs two different responses", source=source)
        if "target" not in responses[par["error_of"]]:
            raise InputError(f"config key {key}.pareto.error_of: response '{par['error_of']}' has no target",
                             source=source)


def _check_design(key: str, design: dict, source: str) -> None:
    """A CCD's alpha is at least 1 and written so that its levels can be read back."""
    if design["type"] == "ccd" and design["alpha"] < 1.0:
        raise InputError(f"config key {key}.design.alpha: a CCD needs alpha >= 1", source=source)
    unreadable = unreadable_alpha(design["alpha"]) if design["type"] == "ccd" else None
    if unreadable:
        raise InputError(f"config key {key}.design.alpha: {design['alpha']:g} {unreadable}", source=source)


def _table_or_simulation(key: str, mat: dict, source: str) -> bool:
    """A material has a finished table (``data``) or a command demid runs (``simulation``): True for the
    latter, whose command is checked here."""
    if "data" in mat and "simulation" in mat:
        raise InputError(f"config key {key}: both data and simulation are given; keep data for a finished table "
                         "or simulation for demid to run the simulations", source=source)
    if "simulation" not in mat:
        if "data" not in mat:
            raise InputError(f"config key {key}: no data; give data (a CSV table of the runs) or simulation "
                             "(a command demid runs per run)", source=source)
        return False
    from .simulation import check_command

    try:
        check_command(mat["simulation"]["command"], mat["factors"], f"{key}.simulation.command")
    except InputError as err:
        raise InputError(err.detail, source=source) from None
    return True


def _check_published_ranges(key: str, responses: dict, source: str) -> None:
    """A published R² of 1.5 cannot be what the source printed: a slip (often a percentage) stops here."""
    for rname, resp in responses.items():
        if not resp.get("published"):
            continue
        from .transcription.printed import impossible_published  # pandas: only where a study gives statistics

        for stat, raw in resp["published"].items():
            where = f"config key {key}.responses.{rname}.published.{stat}"
            why = impossible_published(stat, raw, where=f"{source}: {where}")
            if why:
                raise InputError(f"{where}: {why}", source=source)


def _check_extends(key: str, name: str, other: str, materials: dict, source: str) -> None:
    """``extends`` names another material of the config: the model it extends."""
    if other and (other == name or other not in materials):
        raise InputError(f"config key {key}.extends: '{other}' is not another material of this config "
                         f"(materials: {', '.join(m for m in materials if m != name)})", source=source)


def _check_scenario_labels(key: str, scenarios: dict, source: str) -> None:
    """Two scenarios with the same label could not be told apart in the tables, figures and report."""
    seen: dict[str, str] = {}
    for sname, scen in scenarios.items():
        label = (scen.get("label") or "").strip()
        if label and label in seen:
            raise InputError(f"config key {key}.scenarios.{sname}.label: '{label}' is also the label of scenario "
                             f"'{seen[label]}'; give each scenario its own label", source=source)
        seen.setdefault(label, sname)


def load_config(path: Path | str, base_dir: Path | str | None = None) -> dict:
    """Read, validate and complete a config file; raises InputError with the key path."""
    path = Path(path)
    if not path.is_file():
        raise InputError("config file does not exist", source=str(path))
    raw = load_yaml(path)
    if not isinstance(raw, dict):
        raise InputError("expected a mapping with a 'materials' key", source=str(path))
    config = validate_schema(raw, source=str(path))
    check_semantics(config, source=str(path), base_dir=base_dir if base_dir is not None else Path.cwd())
    return config


def grid_size(config: dict, material: str) -> int:
    """Grid points per axis (Sobol points above 3 factors) of a material (see demid.spec)."""
    from .spec import evaluation_size

    return evaluation_size(config, config["materials"][material])


def _check_limits(key: str, factor: dict, source: str) -> None:
    """A factor's physical ``limits`` must contain its search range."""
    from .spec import limits_problem

    problem = limits_problem(factor["lower"], factor["upper"], factor.get("limits"))
    if problem:
        raise InputError(f"config key {key}.{problem}", source=source)
