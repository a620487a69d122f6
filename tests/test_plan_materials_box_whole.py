"""The next wave planned by hand (plan_materials, what the next-wave step writes): each material's next domain is
its refocus scenario's plausible spans widened by the margin times the range on each side and clipped to the search
range, written out here from the plausible table, and every proposed run lies in that box; two materials of
different responses, targets and margins, one table for both."""

from __future__ import annotations

import numpy as np
import pytest

from demid.next_wave import plan_materials
from demid.surrogate import fit_material, surrogates_to_frame
from tests.helpers import one_response_study

STUDIES = {  # material -> (responses, lower, upper, target, count, margin)
    "m": (lambda x: {"y": 10 + 4 * x[:, 0] - 3 * x[:, 1] + x[:, 0] * x[:, 1]}, [0.0, 0.0], [1.0, 1.0], 11.0, 6, 0.1),
    "n": (lambda x: {"y": 50 + 0.2 * x[:, 0] ** 2 + 2 * x[:, 1]}, [-5.0, 1.0], [5.0, 9.0], 60.0, 8, 0.05),
}


@pytest.fixture(scope="module")
def planned():
    specs, frames = {}, {"tables": {}, "fits": {}, "plausible": {}, "findings": {}}
    for name, (responses, lower, upper, target, count, margin) in STUDIES.items():
        table, spec, _, plausible = one_response_study(responses, lower, upper, target, count, margin)
        specs[name] = spec
        frames["tables"][name] = table
        frames["fits"][name] = surrogates_to_frame(fit_material(table, spec))
        frames["plausible"][name] = plausible
        frames["findings"][name] = None
    return specs, frames, plan_materials(specs, frames, z=2.0)


def test_each_next_domain_is_the_plausible_spans_widened_by_the_margin_and_clipped(planned):
    specs, frames, (domain, runs, reasons) = planned
    assert list(domain["material"].unique()) == list(STUDIES) and set(reasons) == set(STUDIES)
    for name, (_, lower, upper, _, count, margin) in STUDIES.items():
        rows = frames["plausible"][name].set_index("factor").loc[["a", "b"]]
        lo, hi = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
        pad = margin * (hi - lo)
        expected_lo = np.maximum(lo, rows["robust_lower"].to_numpy() - pad)
        expected_hi = np.minimum(hi, rows["robust_upper"].to_numpy() + pad)
        assert ((expected_lo > lo) | (expected_hi < hi)).any()  # a box smaller than the search range
        box = domain[domain["material"] == name]
        assert box["factor"].tolist() == ["a", "b"]
        np.testing.assert_allclose(box["lower"].to_numpy(), expected_lo, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(box["upper"].to_numpy(), expected_hi, rtol=1e-12, atol=1e-12)
        proposed = runs[runs["material"] == name][["a", "b"]].to_numpy(dtype=float)
        assert 0 < len(proposed) <= count
        span = expected_hi - expected_lo
        assert np.all(proposed >= expected_lo - 1e-9 * span) and np.all(proposed <= expected_hi + 1e-9 * span)
