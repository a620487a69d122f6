"""A refocused wave that must separate aliased terms: a response of one factor alone puts the plausible set on a
strip across the other factor, so the band's runs all share one level of the first and cannot tell its cubic from
its linear term.  The wave's count is its whole budget (the criticism's runs, the design and the separating runs
together), every kind of run the reason counts is the runs it proposes, and the separating runs make the alias
set's members separately estimable given the earlier runs inside the box and the rest of the wave."""

from __future__ import annotations

import json
import re
from functools import lru_cache

import numpy as np
import pandas as pd
import pytest

from demid.design import model_matrix, quadratic_terms
from demid.next_wave import PURPOSE_DECIDE, PURPOSE_DESIGN, PURPOSE_DESIGN_BOX, PURPOSE_SUPPORT, plan_next_wave
from demid.spec import MaterialSpec
from demid.wave_runs import aliased_findings
from demid.surrogate import Surrogate
from demid.uncertainty import plausible_identifiability_frame
from tests.helpers import make_ccd_table


def _strip_study(count: int):
    """y = 10 + 4 a (b has no effect) on a face-centred CCD, its surrogate that plane with a small standard error;
    target 12 at 0.3 %: the plausible set is a thin strip a ~ 0.5 across b."""
    table = make_ccd_table(lambda x: {"y": 10 + 4 * x[:, 0]}, [0, 0], [1, 1], alpha=1.0, center_runs=3)
    table = table.rename(columns={"x1": "a", "x2": "b"})
    table["status"] = "ok"
    spec = MaterialSpec.from_material("m", {
        "data": "planted.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 3},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": 12.0}}, "scenarios": {"y": {"observables": ["y"], "tolerance": 0.003}},
        "next_runs": {"count": count, "scenario": "", "margin": 0.1}})
    surrogates, plausible = _surrogates_and_plausible(spec.domain)
    return table, spec, surrogates, plausible


@lru_cache(maxsize=1)
def _surrogates_and_plausible(domain):
    surrogates = {"y": Surrogate("y", ["a", "b"], quadratic_terms(2), np.array([10.0, 4.0, 0.0, 0.0, 0.0, 0.0]),
                                 np.eye(6) * 1e-8, 1e-6, 10)}
    plausible = plausible_identifiability_frame(surrogates, domain, {"y": (("y",), 0.003)}, {"y": 12.0}, 201,
                                                z=2.0)
    return surrogates, plausible


def _rank(coded: np.ndarray, members) -> int:
    """Rank of the members' columns once the quadratic's are regressed out."""
    base = model_matrix(coded, quadratic_terms(2))
    cols = model_matrix(coded, list(members))
    resid = cols - base @ np.linalg.lstsq(base, cols, rcond=None)[0]
    s = np.linalg.svd(resid, compute_uv=False)
    return int(np.sum(s > 1e-8 * max(s.max(), 1e-300)))


@pytest.mark.parametrize("count, aliases, deciding", [(6, "a^3;a^4", 0), (6, "a^3;b^3", 0), (9, "a^3;a^4", 2),
                                                      (6, "a^3;a:b^2", 1)])
def test_a_wave_with_separating_runs_keeps_its_count_and_counts_each_kind(count, aliases, deciding):
    table, spec, surrogates, plausible = _strip_study(count)
    box0 = plan_next_wave("m", table, surrogates, spec, plausible, None, z=2.0).domain.set_index("factor")
    lo, hi = box0.loc[["a", "b"], "lower"].to_numpy(), box0.loc[["a", "b"], "upper"].to_numpy()
    middle = {f: float((lo[i] + hi[i]) / 2) for i, f in enumerate(("a", "b"))}
    rows = [{"response": "y", "cause": "missing_term", "aliases": aliases, "detail": "", "discriminating_runs": "[]"},
            {"response": "y", "cause": "ambiguous", "detail": "", "aliases": "",
             "discriminating_runs": json.dumps([{**middle, "purpose": PURPOSE_DECIDE}] * deciding)}]
    wave = plan_next_wave("m", table, surrogates, spec, plausible, pd.DataFrame(rows), z=2.0)

    purposes = wave.runs["purpose"].tolist()
    # the count is the wave's budget, everything included
    assert len(wave.runs) == count and purposes[:deciding] == [PURPOSE_DECIDE] * deciding
    counted = {"support": purposes.count(PURPOSE_SUPPORT), "band": purposes.count(PURPOSE_DESIGN),
               "box": purposes.count(PURPOSE_DESIGN_BOX),
               "separate": sum(p.startswith("separate aliased terms") for p in purposes)}
    assert sum(counted.values()) == count - deciding
    assert counted["separate"] >= 1 and counted["band"] >= 1  # premise: both kinds in one wave
    # every run inside the refocused box
    x = wave.runs[["a", "b"]].to_numpy(dtype=float)
    assert np.all((x >= lo - 1e-12) & (x <= hi + 1e-12))

    design = re.search(r"; (\d+) new runs from a D-optimal quadratic design given the (\d+) earlier run\(s\) inside "
                       r"the box: (\d+) over the whole box \(its edges and corners\)", wave.reason)
    assert int(design[1]) == count - deciding and int(design[3]) == counted["support"]
    band = re.search(r", (\d+) on the band near the plausible set", wave.reason)
    assert (int(band[1]) if band else 0) == counted["band"]
    off = re.search(r", (\d+) off the band", wave.reason)
    assert (int(off[1]) if off else 0) == counted["box"]
    separate = re.search(r", (\d+) to separate aliased terms the criticism found", wave.reason)
    assert int(separate[1]) == counted["separate"]

    # the separating runs do what they say: without them the members stay aliased, with them they are not
    earlier = table[["a", "b"]].to_numpy(dtype=float)
    inside = earlier[np.all((earlier >= lo - 1e-12) & (earlier <= hi + 1e-12), axis=1)]
    center, half = (lo + hi) / 2, (hi - lo) / 2
    is_sep = np.array([p.startswith("separate aliased terms") for p in purposes])
    new = x[deciding:]  # the design and separating runs (the criticism's are not part of the separation)
    members = aliased_findings(pd.DataFrame(rows), ["a", "b"])[0][0]
    before = np.vstack([inside, new[~is_sep[deciding:]]])
    assert _rank((before - center) / half, members) < len(members)
    assert _rank((np.vstack([inside, new]) - center) / half, members) == len(members)
