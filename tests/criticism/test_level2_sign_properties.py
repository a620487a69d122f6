"""A response's sign convention changes nothing level 2 reports: negating a response and its target (a force
measured downwards, a settlement counted negative) leaves the tolerances, the best point and its largest error,
and the message's per cents as they were."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.material import criticize_material
from demid.spec import MaterialSpec
from demid.surrogate import fit_response
from demid.tolerance import band_scale, observable_band, relative_tolerances

from ..helpers import make_ccd_table
from .test_level2_own_tolerance import EPS, TARGETS, _responses


def _study(own: dict, negated: tuple[str, ...]):
    table = make_ccd_table(_responses, [0.0, 0.0], [1.0, 1.0], noise=1e-4, seed=5).rename(
        columns={"x1": "a", "x2": "b"})
    for r in negated:  # the same measurements, counted the other way
        table[r] = -table[r]
    targets = {r: (-t if r in negated else t) for r, t in TARGETS.items()}
    material = {"data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": {r: {"target": t, **(own if r == "y2" else {})} for r, t in targets.items()},
                "scenarios": {"all": {"observables": list(TARGETS), "tolerance": EPS}},
                "reference_point": {"a": 0.5, "b": 0.45}}
    spec = MaterialSpec.from_material("m", material, grid_points=101)
    surrogates = {r: fit_response(table, ["a", "b"], r).surrogate() for r in TARGETS}
    return criticize_material(table, surrogates, spec).summary["level2"]


def _percents(message: str) -> list[float]:
    """The sizes of the per cents the message quotes, up to the shared bias (a relative bias common to all
    targets moves a negative target the other way: that fit depends on the signs, rightly)."""
    return [float(v) for v in re.findall(r"(\d+(?:\.\d+)?) %", message.split("A shared relative bias")[0])]


@pytest.mark.parametrize("own", [{"tolerance": 0.002}, {"tolerance_abs": 0.0028}])
def test_negating_a_response_and_its_target_leaves_level_2_as_it_was(own):
    plain = _study(own, ())
    flipped = _study(own, ("y2",))
    assert not plain["feasible"] and not flipped["feasible"]
    assert flipped["tolerances"] == pytest.approx(plain["tolerances"], rel=1e-12)
    assert min(flipped["tolerances"].values()) > 0
    assert flipped["best_max_error"] == pytest.approx(plain["best_max_error"], rel=1e-6)
    assert flipped["best_point"]["a"] == pytest.approx(plain["best_point"]["a"], abs=1e-4)
    assert flipped["best_point"]["b"] == pytest.approx(plain["best_point"]["b"], abs=1e-4)
    assert _percents(flipped["message"]) == pytest.approx(_percents(plain["message"]), rel=1e-9)
    for level2 in (plain, flipped):
        _check_quoted_numbers(level2)


def _check_quoted_numbers(level2: dict) -> None:
    """The numbers of the message, parsed back: the worst miss and its multiple of its own tolerance, the best point,
    the bias the bottleneck needs and the errors at the reference point, against the summary's values."""
    message = level2["message"]
    miss = re.search(r"the closest point \(a=([\d.]+), b=([\d.]+)\) still misses (\w+) by ([\d.]+) % \(([\d.]+) times "
                     r"its tolerance of ([\d.]+) %", message)
    assert miss, message
    a, b, name, by, times, own = miss.groups()
    assert float(a) == pytest.approx(level2["best_point"]["a"], abs=5e-5)
    assert float(b) == pytest.approx(level2["best_point"]["b"], abs=5e-5)
    error, tolerance = abs(level2["best_errors"][name]), level2["tolerances"][name]
    assert float(by) == pytest.approx(100 * error, rel=5e-3)
    assert float(own) == pytest.approx(100 * tolerance, rel=5e-3)
    assert float(times) == pytest.approx(error / tolerance, abs=0.05 + 1e-9)
    assert error / tolerance == pytest.approx(level2["best_max_error"] / level2["tolerance"], rel=1e-6)
    bottleneck = level2["bottleneck"]
    bias = re.search(rf"the simulation would then read {bottleneck} ([\d.]+) % (low|high)", message)
    assert bias, message
    assert float(bias.group(1)) == pytest.approx(100 * abs(level2["implied_bias"][bottleneck]), abs=0.005 + 1e-9)
    at_reference = re.search(r"At the reference point the errors are (.*?): ", message).group(1)
    for item in at_reference.split(", "):
        observable, value, _ = item.split(" ")  # "y1 +1.35 %"
        assert float(value.replace("−", "-")) == pytest.approx(
            100 * level2["reference_errors"][observable], abs=0.005 + 1e-9)


@given(target=st.floats(1e-3, 1e6) | st.floats(-1e6, -1e-3), scenario=st.floats(0.001, 0.3),
       own=st.sampled_from(["none", "relative", "absolute"]), own_value=st.floats(0.001, 0.5))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_an_observables_band_does_not_depend_on_its_targets_sign(target, scenario, own, own_value):
    class Response:
        tolerance = own_value if own == "relative" else None
        tolerance_abs = own_value * abs(target) if own == "absolute" else None

    band = observable_band(Response, target, scenario)
    assert band > 0 and band == observable_band(Response, -target, scenario)
    expected = scenario if own == "none" else own_value
    assert band == pytest.approx(expected * abs(target), rel=1e-12)
    assert band_scale(Response, target, scenario) == pytest.approx(scenario / expected, rel=1e-12)

    class Spec:
        targets = {"y": target}

        @staticmethod
        def response(name):
            return Response

    assert relative_tolerances(Spec, ["y"], scenario)["y"] == pytest.approx(expected, rel=1e-12)
