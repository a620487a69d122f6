"""The refocused wave's reason, every count it quotes against the runs it proposes and counts made here: the design
runs, the earlier runs inside the box (counted from the table and the box), the runs over the whole box (a quarter
of the design runs), on the band, off it with the band's grid points (counted on the box's 41 x 41 grid at twice
robust_z), and to separate aliased terms; for counts 7-12, margins, targets of either sign, with and without an
alias set and the criticism's runs."""

from __future__ import annotations

import json
import re

import numpy as np
import pandas as pd
import pytest

from demid.next_wave import (PURPOSE_DECIDE, PURPOSE_DESIGN, PURPOSE_DESIGN_BOX, PURPOSE_SUPPORT, plan_next_wave)
from demid.spec import MaterialSpec
from tests.test_boundary_runs import _linear, _study


@pytest.mark.parametrize("sign, count, margin, aliased, deciding", [
    (1.0, 9, 0.1, False, 0), (-1.0, 12, 0.3, True, 0), (1.0, 10, 0.05, True, 2), (-1.0, 7, 0.2, False, 1)])
def test_every_count_the_refocused_waves_reason_quotes_is_the_runs_it_proposes(sign, count, margin, aliased,
                                                                              deciding):
    from demid.scenario import JudgedScenario

    table, spec, surrogates, plausible = _study(lambda x: sign * _linear(x), target=sign * 13.0, margin=margin)
    spec = MaterialSpec.from_material("m", {**spec.material_config(),
                                            "next_runs": {"count": count, "scenario": "", "margin": margin}})
    wave0 = plan_next_wave("m", table, surrogates, spec, plausible, None, z=2.0)
    box = wave0.domain.set_index("factor").loc[["a", "b"]]
    lo, hi = box["lower"].to_numpy(), box["upper"].to_numpy()
    # the box: the plausible spans widened by the margin of the unit range on each side, clipped to it
    spans = plausible[plausible["scenario"] == spec.scenarios[0].name].set_index("factor").loc[["a", "b"]]
    assert lo == pytest.approx(np.maximum(0.0, spans["robust_lower"].to_numpy() - margin), abs=1e-12)
    assert hi == pytest.approx(np.minimum(1.0, spans["robust_upper"].to_numpy() + margin), abs=1e-12)
    middle = {f: float((lo[i] + hi[i]) / 2) for i, f in enumerate(("a", "b"))}
    rows = [{"response": "y", "cause": "ambiguous", "detail": "", "aliases": "",
             "discriminating_runs": json.dumps([{**middle, "purpose": PURPOSE_DECIDE}] * deciding)}]
    if aliased:
        rows.append({"response": "y", "cause": "missing_term", "aliases": "a^3;a:b^2", "detail": "",
                     "discriminating_runs": "[]"})
    wave = plan_next_wave("m", table, surrogates, spec, plausible, pd.DataFrame(rows), z=2.0)
    purposes = wave.runs["purpose"].tolist()
    assert len(purposes) == count and purposes[:deciding] == [PURPOSE_DECIDE] * deciding
    counted = {"support": purposes.count(PURPOSE_SUPPORT), "band": purposes.count(PURPOSE_DESIGN),
               "box": purposes.count(PURPOSE_DESIGN_BOX),
               "separate": sum(p.startswith("separate aliased terms") for p in purposes)}
    earlier = table[["a", "b"]].to_numpy(dtype=float)
    tol = 1e-12 * (hi - lo)
    inside = int(np.all((earlier >= lo - tol) & (earlier <= hi + tol), axis=1).sum())
    design = re.search(r"; (\d+) new runs from a D-optimal quadratic design given the (\d+) earlier run\(s\) inside "
                       r"the box: (\d+) over the whole box \(its edges and corners\)", wave.reason)
    assert (int(design[1]), int(design[2]), int(design[3])) == (count - deciding, inside, counted["support"])
    band = re.search(r", (\d+) on the band near the plausible set", wave.reason)
    assert (int(band[1]) if band else 0) == counted["band"]
    off = re.search(r", (\d+) off the band where its (\d+) grid point\(s\) cannot determine", wave.reason)
    assert (int(off[1]) if off else 0) == counted["box"]
    separate = re.search(r", (\d+) to separate aliased terms the criticism found", wave.reason)
    assert (int(separate[1]) if separate else 0) == counted["separate"]
    assert counted["separate"] <= int(aliased)
    axes = [np.linspace(a, b, 41) for a, b in zip(lo, hi)]
    grid = np.array(np.meshgrid(*axes, indexing="ij")).reshape(2, -1).T
    band_points = int(JudgedScenario(spec, spec.scenarios[0], surrogates, 4.0).contains(grid).sum())
    if off:
        assert int(off[2]) == band_points
    if band_points and not off:
        # a quarter of the design runs (without the separating ones) support the whole box
        assert counted["support"] == int(round((count - deciding - counted["separate"]) / 4))
    assert sum(counted.values()) == count - deciding
    # the wave's value is judged on as many runs as it makes, all aimed at the plausible set; none without a z
    assert wave.value["count"] == count and wave.value["scenario"] == spec.scenarios[0].name
    assert plan_next_wave("m", table, surrogates, spec, plausible, pd.DataFrame(rows), z=0.0).value is None
