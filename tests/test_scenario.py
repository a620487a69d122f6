"""The judged scenario: one home for a scenario's rescaled surrogates, bands, plausible fields, sets and
membership test, and no consumer that builds them on its own.

Known answers: y = a on [0, 1]^2 with a constant standard error of the mean s, target y*, own band a_k.
The plausible half-width in the response's units is then H = z sqrt(s^2 + (a_k / z)^2) (no σ configured:
the band is the measurement band), so x is plausible exactly when |a - y*| <= H, and strict when
|a - y*| <= a_k -- written out here with numpy, no demid set code.
"""

from __future__ import annotations

import ast
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from demid.sampling.evaluate import evaluate_set
from demid.scenario import MEMBERSHIP_SLACK, JudgedScenario, judged_scenarios
from demid.spec import MaterialSpec

from .inputs.test_import_layers import import_edges, package_modules
from .uncertainty.test_uncertainty import linear

PACKAGE = Path(__file__).resolve().parents[1] / "demid"

#: The calls that build a scenario's judged surrogates, bands or plausible fields.
BUILDERS = ("plausibility_fields", "scenario_surrogates", "scenario_bands", "scenario_grid")

#: Where those calls may stand: the judged scenario itself, and the set evaluators it hands its surrogates and
#: bands to (they build fields from what they are given, never from a spec).
ALLOWED = {
    "scenario.py",
    "sampling/residuals.py",  # the plausible field's own module (the grid estimator's fields)
    "uncertainty/plausible.py",  # the plausible grid set of the plausible table, given the judged surrogates and bands
}


def builder_calls(root: Path = PACKAGE) -> list[str]:
    """``file:line name`` of every call of a builder outside :data:`ALLOWED`."""
    found = []
    for path in sorted(root.rglob("*.py")):
        relative = path.relative_to(root).as_posix()
        if relative in ALLOWED:
            continue
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Call):
                func = node.func
                name = func.id if isinstance(func, ast.Name) else getattr(func, "attr", None)
                if name in BUILDERS:
                    found.append(f"{relative}:{node.lineno} {name}")
    return found


def test_the_scan_finds_a_consumer_that_builds_its_own_fields(tmp_path):
    pkg = tmp_path / "demid"
    (pkg / "uncertainty").mkdir(parents=True)
    (pkg / "scenario.py").write_text("def f(s):\n    return plausibility_fields(s)\n")
    (pkg / "next_wave.py").write_text("from .tolerance import scenario_surrogates as s\nimport demid.tolerance as t\n"
                                      "def g(x):\n    return t.scenario_surrogates(x)\n")
    (pkg / "uncertainty" / "recommended.py").write_text("def h(x):\n    return x.contains(x)\n")
    assert builder_calls(pkg) == ["next_wave.py:4 scenario_surrogates"]


def test_no_consumer_builds_its_own_plausible_fields():
    found = builder_calls()
    assert not found, ("judged surrogates, bands or plausible fields built outside demid/scenario.py (take a "
                       "JudgedScenario instead): " + "; ".join(found))


def test_tolerance_imports_nothing_of_the_package():
    assert import_edges(package_modules())["demid.tolerance"] == set()


# --------------------------------------------------------------------------- known answers
TARGET, OWN, SE, Z = 0.5, 0.05, 0.02, 2.0


def _judged(z: float = Z, own: float | None = OWN) -> JudgedScenario:
    response = {"target": TARGET} if own is None else {"target": TARGET, "tolerance_abs": own}
    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"}, "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": response}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.01}}})
    surrogate = replace(linear(0.0, [1.0, 0.0], variance_intercept=SE ** 2), response="y")
    return judged_scenarios(spec, {"y": surrogate}, z)["s"]


def test_membership_and_implausibility_in_the_responses_own_units():
    judged = _judged()
    a = np.linspace(0.0, 1.0, 2001)
    points = np.column_stack([a, np.full_like(a, 0.3)])
    half = Z * np.sqrt(SE ** 2 + (OWN / Z) ** 2)
    np.testing.assert_allclose(judged.implausibility(points), np.abs(a - TARGET) / half, rtol=1e-12)
    edge = np.abs(np.abs(a - TARGET) - half) > 1e-9  # away from the band's edge, where round-off decides
    assert np.array_equal(judged.contains(points)[edge], (np.abs(a - TARGET) <= half)[edge])
    strict_edge = np.abs(np.abs(a - TARGET) - OWN) > 1e-9
    assert np.array_equal(judged.contains(points, plausible=False)[strict_edge],
                          (np.abs(a - TARGET) <= OWN)[strict_edge])
    # with z = 0 the plausible set is the strict one
    assert np.array_equal(_judged(z=0.0).contains(points), judged.contains(points, plausible=False))
    # a point on the band's edge stays in the set
    on_edge = np.array([[TARGET + half * (1 + MEMBERSHIP_SLACK / 10), 0.3]])
    assert judged.contains(on_edge)[0]


def test_sets_of_the_judged_scenario_are_those_of_the_own_band():
    judged = _judged()
    strict = judged.strict_set(201)
    assert strict.fraction == pytest.approx(2 * OWN, abs=1e-9)  # the strip |a - y*| <= a_k, all of b
    plausible = judged.plausible_set(201)
    half = Z * np.sqrt(SE ** 2 + (OWN / Z) ** 2)
    assert plausible.fraction == pytest.approx(2 * half, abs=2e-3)
    # the same evaluator on the judged surrogates: one set, whichever way it is asked for
    direct = evaluate_set(judged.surrogates, judged.spec.domain, ("y",), judged.targets, judged.tolerance, 201)
    assert direct.fraction == strict.fraction
    # built once: the second ask returns the same objects
    assert judged.fields is judged.fields and judged.surrogates is judged.surrogates


def test_likelihood_width_is_the_plausible_sets_measurement_band():
    judged, plain = _judged(), _judged(own=None)
    c = 0.01 * TARGET / OWN  # the rescaling of the own band onto the scenario's
    assert judged.likelihood_sd["y"] == pytest.approx(c * OWN / Z)
    assert judged.likelihood_sd["y"] == pytest.approx(judged.fields["y"].measurement_sd)
    assert plain.likelihood_sd["y"] == pytest.approx(0.01 * TARGET / Z)
    assert judged.sigma_basis["y"] == f"default sigma = {OWN / Z:g} (own tolerance ±{OWN:g}/{Z:g})"
    assert plain.sigma_basis["y"] == "default sigma_rel = 0.005 (tolerance/2)"
