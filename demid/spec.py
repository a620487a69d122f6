"""MaterialSpec: one material of a validated config, read once.

Like SALib's ``ProblemSpec``, the spec is built once from the validated configuration and
every per-material step receives it; nothing else reads a material's raw config entry.
Every value that used to be derived in several places (log-scale factors, targets, the
CCD's axial distance, the reference tolerance, label fallbacks, the evaluation size) is
derived here, once.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from functools import cached_property

#: Tolerance used for default sigmas, the ranking and level 2 when a material has no scenario.
FALLBACK_TOLERANCE = 0.02


def join_observables(observables) -> str:
    """An observable set's name in tables and legends: ``d5+d10+d15``."""
    return "+".join(observables)


def _axis_label(label: str, unit: str) -> str:
    return f"{label} [{unit}]" if unit and unit != "-" else label


def _limits(block: dict | None) -> tuple[float | None, float | None]:
    """A factor's physical ``limits`` entry as (lower, upper), None where a side has none."""
    block = block or {}
    return tuple(float(block[side]) if block.get(side) is not None else None for side in ("lower", "upper"))


def limits_problem(lower: float, upper: float, limits: dict | None) -> str | None:
    """Why a factor's physical ``limits`` do not contain its search range [lower, upper] (the key and the
    values), or None."""
    from .sampling.domain import LIMIT_SLACK

    limits = limits or {}
    slack = LIMIT_SLACK * abs(upper - lower)
    if limits.get("lower") is not None and limits["lower"] > lower + slack:
        return (f"limits.lower: {limits['lower']:.10g} is above the search range's lower bound {lower:.10g} (the "
                "range must lie within the physical limits)")
    if limits.get("upper") is not None and limits["upper"] < upper - slack:
        return (f"limits.upper: {limits['upper']:.10g} is below the search range's upper bound {upper:.10g} (the "
                "range must lie within the physical limits)")
    return None


def label_entries(name: str, material: dict):
    """``(config key, text)`` of every label and unit of a validated ``materials`` entry (the schema filled
    the absent ones): what the label check parses."""
    yield f"materials.{name}.label", material["label"]
    for group in ("factors", "responses"):
        for key, item in material[group].items():
            for field in ("label", "unit"):
                yield f"materials.{name}.{group}.{key}.{field}", item[field]
    for key, scenario in material["scenarios"].items():
        yield f"materials.{name}.scenarios.{key}.label", scenario["label"]


@dataclass(frozen=True)
class Factor:
    name: str
    lower: float
    upper: float
    log: bool
    label: str
    unit: str
    limits: tuple[float | None, float | None] = (None, None)  # physical limits (actual units), None: none

    @property
    def axis_label(self) -> str:
        """``label [unit]`` (the label alone for dimensionless factors)."""
        return _axis_label(self.label, self.unit)


@dataclass(frozen=True)
class Response:
    name: str
    target: float | None
    label: str
    unit: str
    sigma: float | None
    sigma_rel: float | None
    tolerance: float | None = None  # own relative tolerance (overrides the scenario's)
    tolerance_abs: float | None = None  # own tolerance in the response's unit
    discrepancy: float | None = None  # model-discrepancy sd (response units) in the plausible set

    @property
    def axis_label(self) -> str:
        return _axis_label(self.label, self.unit)

    @property
    def sigma_config(self) -> dict:
        """The measurement-noise keys as configured (``sigma`` / ``sigma_rel``, absent when unset)."""
        return {k: v for k, v in (("sigma", self.sigma), ("sigma_rel", self.sigma_rel)) if v is not None}


@dataclass(frozen=True)
class Scenario:
    name: str
    observables: tuple[str, ...]
    tolerance: float
    label: str


@dataclass(frozen=True)
class Pareto:
    error_of: str
    minimise: str
    max_error: float


@dataclass(frozen=True)
class NextRuns:
    """The ``next_runs`` request: how many runs, the scenario to refocus on ("" = default), the margin."""

    count: int
    scenario: str
    margin: float


@dataclass(frozen=True, eq=False)
class MaterialSpec:
    """A material as every step sees it: factors, responses, design, scenarios and derived values."""

    name: str
    label: str
    data: str
    design_type: str
    alpha: float
    center_runs: int
    factors: tuple[Factor, ...]
    responses: tuple[Response, ...]
    scenarios: tuple[Scenario, ...]
    reference_point: dict | None
    pareto: Pareto | None
    grid_points: int | None
    paper_figure: str | None
    _published: dict
    _material: dict
    next_runs: NextRuns | None = None

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_material(cls, name: str, material: dict, grid_points: int | None = None) -> "MaterialSpec":
        """The spec of one ``materials`` entry (with its ``design``, ``factors`` and ``responses``, which the schema
        requires); keys the schema gives defaults may be absent: they are filled from the schema, the only source
        of defaults.  The pipeline and the command line build specs with :meth:`from_config`."""
        from .schema import material_with_defaults

        material = material_with_defaults(material)
        design = material["design"]
        factors = tuple(
            Factor(f, float(c["lower"]), float(c["upper"]), c["scale"] == "log", c["label"] or f, c["unit"],
                   _limits(c.get("limits")))
            for f, c in material["factors"].items())
        responses = tuple(
            Response(r, float(c["target"]) if c.get("target") is not None else None, c["label"] or r,
                     c["unit"], c.get("sigma"), c.get("sigma_rel"), c.get("tolerance"),
                     c.get("tolerance_abs"), c.get("discrepancy"))
            for r, c in material["responses"].items())
        scenarios = tuple(
            Scenario(s, tuple(c["observables"]), float(c["tolerance"]), c["label"] or s)
            for s, c in material["scenarios"].items())
        par = material.get("pareto")
        pareto = Pareto(par["error_of"], par["minimise"], float(par["max_error"])) if par else None
        nr = material.get("next_runs")
        next_runs = NextRuns(int(nr["count"]), nr["scenario"], float(nr["margin"])) if nr else None
        published = {r: c["published"] for r, c in material["responses"].items() if c.get("published")}
        return cls(
            name=name, label=material["label"] or name, data=material.get("data", ""),
            design_type=design["type"], alpha=float(design["alpha"]),
            center_runs=int(design["center_runs"]), factors=factors, responses=responses,
            scenarios=scenarios, reference_point=material.get("reference_point") or None, pareto=pareto,
            grid_points=grid_points, paper_figure=material.get("paper_figure"),
            _published=copy.deepcopy(published), _material=copy.deepcopy(material), next_runs=next_runs)

    @classmethod
    def from_config(cls, name: str, config: dict) -> "MaterialSpec":
        """The spec of material ``name`` of a validated config (with the config's evaluation size)."""
        material = config["materials"][name]
        return cls.from_material(name, material, grid_points=evaluation_size(config, material))

    # ------------------------------------------------------------------ derived values
    def limits_problem(self) -> str | None:
        """The first factor whose physical limits do not contain its search range, as its config key and why
        (None: every factor's do)."""
        for f in self.factors:
            problem = limits_problem(f.lower, f.upper, dict(zip(("lower", "upper"), f.limits)))
            if problem:
                return f"config key materials.{self.name}.factors.{f.name}.{problem}"
        return None

    @cached_property
    def factor_names(self) -> list[str]:
        return [f.name for f in self.factors]

    @cached_property
    def log_factors(self) -> tuple[str, ...]:
        return tuple(f.name for f in self.factors if f.log)

    @property
    def dim(self) -> int:
        return len(self.factors)

    @cached_property
    def domain(self):
        from .sampling.domain import Domain

        return Domain(tuple(self.factor_names), tuple(f.lower for f in self.factors),
                      tuple(f.upper for f in self.factors), tuple(f.log for f in self.factors),
                      tuple(f.limits for f in self.factors))

    @property
    def axial_alpha(self) -> float:
        """The axial distance of a CCD; 1 for every other design type."""
        return self.alpha if self.design_type == "ccd" else 1.0

    @cached_property
    def design(self) -> dict:
        """The design block as the table validator reads it (type, alpha, center_runs; the schema's defaults
        filled in)."""
        return copy.deepcopy(self._material.get("design") or {})

    @cached_property
    def response_names(self) -> list[str]:
        return [r.name for r in self.responses]

    def response(self, name: str) -> Response:
        return next(r for r in self.responses if r.name == name)

    def factor(self, name: str) -> Factor:
        return next(f for f in self.factors if f.name == name)

    @cached_property
    def targets(self) -> dict[str, float]:
        """Measured targets of the responses that have one, in config order."""
        return {r.name: r.target for r in self.responses if r.target is not None}

    @cached_property
    def factor_labels(self) -> dict[str, str]:
        return {f.name: f.label for f in self.factors}

    @cached_property
    def response_labels(self) -> dict[str, str]:
        return {r.name: r.label for r in self.responses}

    @cached_property
    def sigma_config(self) -> dict[str, dict]:
        """Per response, its configured ``sigma`` / ``sigma_rel`` (what measurement_sigma reads)."""
        return {r.name: r.sigma_config for r in self.responses}

    @cached_property
    def published(self) -> dict[str, dict]:
        """Per response with a ``published`` block, that block (the transcription check's input)."""
        return copy.deepcopy(self._published)

    @property
    def reference_tolerance(self) -> float:
        """Tolerance of the scenario with the most observables (ties: the smallest); the fallback without."""
        if not self.scenarios:
            return FALLBACK_TOLERANCE
        return min(self.scenarios, key=lambda sc: (-len(sc.observables), sc.tolerance)).tolerance

    @property
    def run_order(self) -> str:
        """Declared order of the ``run`` column: ``performed`` (drift is tested where the order can be
        believed) or ``unknown`` (never tested)."""
        return self._material["run_order"]

    @property
    def status_column(self) -> str:
        """The table column that marks failed runs (``status_column``)."""
        return self._material["status_column"]

    @property
    def simulated(self) -> bool:
        """Whether demid simulates this material's runs (a ``simulation:`` block instead of ``data:``)."""
        return bool(self._material.get("simulation"))

    @property
    def extends(self) -> str | None:
        """The material whose model this one extends (``extends:``), None when it extends none."""
        return self._material.get("extends") or None

    @cached_property
    def waves(self) -> dict:
        """The ``waves`` block of a simulated material, with the schema's defaults (``max``, ``stop_early``)."""
        from .schema import definition_with_defaults

        return definition_with_defaults("waves", self._material.get("waves"))

    @cached_property
    def confirmed_values(self) -> tuple[tuple[int, str], ...]:
        """(run, response column) cells confirmed correct although they look like a typo, in config order."""
        items = self._material.get("confirmed_values") or []
        return tuple(dict.fromkeys((int(c["run"]), c["column"]) for c in items))

    def label_entries(self):
        """``(config key, text)`` of every label and unit of this material, as configured."""
        return label_entries(self.name, self._material)

    def material_config(self) -> dict:
        """A copy of the ``materials`` entry with the schema's defaults (a wave's entry is derived from it)."""
        return copy.deepcopy(self._material)

    def __repr__(self) -> str:  # stable and short
        return f"MaterialSpec({self.name!r}, {self._material!r}, grid_points={self.grid_points!r})"

    @property
    def digest(self) -> str:
        """A fingerprint of everything the spec says (sha256 of its repr).  Snakemake reruns a job whose
        params changed but records only plain values, not a spec object: rules pass this beside the spec so
        that an edited target, bound or scenario reruns the material."""
        import hashlib

        return hashlib.sha256(repr(self).encode("utf-8")).hexdigest()


def evaluation_size(config: dict, material: dict) -> int:
    """Grid points per axis (Sobol points above 3 factors) of a material's set evaluation."""
    from .sampling.domain import uses_grid

    if material.get("grid_points"):
        return int(material["grid_points"])
    d = len(material["factors"])
    if d <= 2:
        return int(config["grid_points"])
    return int(config["grid_points_3d"] if uses_grid(d) else config["sobol_points"])

