"""One material's uncertainty analysis end to end on surrogates whose answers are known, over generated studies:
observables each linear in its own factor (targets and slopes of either sign), scenarios of different sizes in
either order.  The recommended point is the widest scenario's grid node of least implausibility, written out
here (max_k |s_k (x_k - c_k)| / (ε|t_k|), no surrogate error, σ the tolerance band read at z); a set with a target out of reach gets no information gain."""

from __future__ import annotations

import numpy as np
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.spec import MaterialSpec
from demid.uncertainty.material import analyse_material

from .test_uncertainty import linear

_SIZES = {"plausible": 21, "sweep": 11, "posterior": 21}


def _study(seed: int, widest_first: bool, unreachable: bool):
    rng = np.random.default_rng(seed)
    lo = rng.uniform(-2.0, 2.0, 2)
    hi = lo + rng.uniform(0.5, 3.0, 2)
    targets, surrogates, centres, slopes = {}, {}, {}, {}
    for k, name in enumerate(("y0", "y1")):
        target = rng.choice([-1.0, 1.0]) * rng.uniform(1.0, 20.0)
        slope = rng.choice([-1.0, 1.0]) * abs(target) / (hi[k] - lo[k])
        centre = lo[k] + (hi[k] - lo[k]) * rng.uniform(0.2, 0.8)
        coef = np.zeros(2)
        coef[k] = slope
        if unreachable and k == 1:  # y1's whole range lies on one side of its target, more than 5 % off
            centre = hi[k] + 0.3 * (hi[k] - lo[k])
        surrogates[name] = linear(target - slope * centre, coef)
        surrogates[name].response = name
        targets[name], centres[name], slopes[name] = target, centre, slope
    scenarios = {"one": {"observables": ["y0"], "tolerance": 0.05},
                 "both": {"observables": ["y0", "y1"], "tolerance": 0.05}}
    if widest_first:
        scenarios = dict(reversed(list(scenarios.items())))
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": float(lo[0]), "upper": float(hi[0])},
                    "b": {"lower": float(lo[1]), "upper": float(hi[1])}},
        "responses": {o: {"target": float(t)} for o, t in targets.items()}, "scenarios": scenarios})
    return spec, surrogates, targets, centres, slopes, (lo, hi)


@given(seed=st.integers(0, 10_000), widest_first=st.booleans(), unreachable=st.booleans())
@settings(max_examples=6, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_the_recommended_point_is_the_widest_scenarios_least_implausible_node(seed, widest_first, unreachable):
    spec, surrogates, targets, centres, slopes, (lo, hi) = _study(seed, widest_first, unreachable)
    result = analyse_material(surrogates, spec, tolerances=[0.1], sizes=_SIZES)
    axes = [np.linspace(lo[k], hi[k], _SIZES["plausible"]) for k in range(2)]
    nodes = np.array([(a, b) for a in axes[0] for b in axes[1]])
    implausibility = np.max([np.abs(slopes[o] * (nodes[:, k] - centres[o])) / (0.05 * abs(targets[o]))
                             for k, o in enumerate(("y0", "y1"))], axis=0)
    best = int(np.argmin(implausibility))
    recommended = result.recommended
    assert recommended["scenario"] == "both" and result.summary["recommended"] == recommended
    assert np.isclose(recommended["implausibility"], implausibility[best], rtol=1e-9)
    assert np.allclose([recommended["point"]["a"], recommended["point"]["b"]], nodes[best], rtol=1e-12, atol=1e-12)
    assert recommended["plausible"] == bool(implausibility[best] <= 1.0) == (not unreachable)
    # a set with a target out of reach: no information gain in the ranking or the gain table
    gains = result.information_gain.groupby("observables")["information_gain_bits"].first()
    assert result.unreachable == (("y1", "y0+y1") if unreachable else ())
    for observables, gain in gains.items():
        assert np.isnan(gain) == (unreachable and "y1" in observables.split("+")), (observables, gain)
