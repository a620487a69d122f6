"""One material's notes (``uncertainty/{material}.json``) sentence by sentence, over studies of two
observables each linear in its own factor (targets and slopes of either sign, scenarios in either order, a target
out of reach or not, one or both observables flat enough to be uninformative): which observables are called
uninformative (a single-observable share written out here, 2 ε |t| / |s| of the factor's range, clipped), every
number their reason quotes parsed back, the out-of-reach sets named, the sizes quoted, every note a sentence."""

from __future__ import annotations

import re

import numpy as np
import pytest

from demid.uncertainty.material import analyse_material

from .test_material_whole import _SIZES, _study
from .test_uncertainty import linear

TOLERANCE = 0.05  # both scenarios' tolerance, so the reference one too


def _flatten(surrogates, targets, centres, slopes, name, k, lo, hi):
    """Make ``name`` so flat that its band covers its factor's whole range: |slope| * range = 0.02 |target|."""
    slope = np.sign(slopes[name]) * 0.02 * abs(targets[name]) / (hi[k] - lo[k])
    centre = (lo[k] + hi[k]) / 2
    coef = np.zeros(2)
    coef[k] = slope
    surrogates[name] = linear(targets[name] - slope * centre, coef)
    surrogates[name].response = name
    slopes[name], centres[name] = slope, centre


def _share(target, slope, centre, lo, hi) -> float:
    """The strict fraction of one observable linear in one factor: its band's overlap with the range."""
    half = TOLERANCE * abs(target) / abs(slope)
    return max(0.0, min(hi, centre + half) - max(lo, centre - half)) / (hi - lo)


@pytest.mark.parametrize("seed, widest_first, unreachable, flat", [
    (5, True, True, ("y0",)), (17, False, False, ("y1",)), (29, True, False, ("y0", "y1"))])
def test_the_notes_name_the_uninformative_and_out_of_reach_sets_with_their_numbers(seed, widest_first, unreachable,
                                                                                    flat):
    spec, surrogates, targets, centres, slopes, (lo, hi) = _study(seed, widest_first, unreachable)
    for k, name in enumerate(("y0", "y1")):
        if name in flat:
            _flatten(surrogates, targets, centres, slopes, name, k, lo, hi)
    result = analyse_material(surrogates, spec, tolerances=[0.1], sizes=_SIZES)
    notes = result.notes
    assert notes == result.summary["notes"] and all(n.endswith(".") for n in notes), notes

    share = {o: _share(targets[o], slopes[o], centres[o], lo[k], hi[k]) for k, o in enumerate(("y0", "y1"))}
    expected = [o for o in ("y0", "y1") if share[o] >= 0.99]
    assert sorted(result.uninformative) == expected == sorted(flat)
    gains = result.ranking.set_index("observables")["information_gain_bits"]
    for o, why in result.uninformative.items():
        quoted = re.search(r"alone it leaves ([\d.e+-]+) % of the search range admissible", why)
        assert float(quoted.group(1)) == pytest.approx(100 * share[o], rel=5e-3)
        bits = re.search(r" \(([\d.]+) bit: the likelihood only tilts across the range\)$", why)
        assert float(bits.group(1)) == pytest.approx(gains[o], abs=0.005 + 1e-12)
    uninformative = [n for n in notes if n.startswith("Uninformative observables: ")]
    if expected:
        assert uninformative == ["Uninformative observables: "
                                 + "; ".join(f"{o}: {why}" for o, why in result.uninformative.items()) + "."]
    else:
        assert uninformative == []

    out_of_reach = [n for n in notes if "targets out of reach" in n]
    if unreachable:
        assert result.unreachable == ("y1", "y0+y1")
        assert len(out_of_reach) == 1 and out_of_reach[0].startswith("Sets with targets out of reach (y1, y0+y1): no "
                                                                     "point of the search range meets their targets")
        assert out_of_reach[0].endswith("no information gain is given and they rank last.")
    else:
        assert out_of_reach == [] and result.unreachable == ()

    assert notes[0].startswith("Plausible sets: z = 2; y0: ") and "; y1: " in notes[0]
    assert notes[1].startswith(f"Posteriors and ranking at tolerance {TOLERANCE:g}: y0: ") and "; y1: " in notes[1]
    assert notes[2] == (f"Plausible sets on {_SIZES['plausible']} grid points per axis, sweeps on {_SIZES['sweep']}, "
                        f"posteriors on {_SIZES['posterior']} grid points per axis.")
    # linear surrogates in two factors: every strict set is exact, and the notes say so once
    assert sum(n.startswith("Strict sets (identifiability table") for n in notes) == 1
    assert len(notes) == 4 + bool(unreachable) + bool(expected)
