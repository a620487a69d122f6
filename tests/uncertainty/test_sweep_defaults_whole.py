"""What a caller of the sweep and of the strict-and-plausible table gets without naming every setting: above
three factors the documented Sobol sample (2^14 points for the sweep, 2^16 for the table, scramble seed 0, the
sweep's spans read off the sample, not polished), and the table's scenario observables given as any iterable of
names, a one-shot iterator included (the table reads them twice: for the strict and for the plausible set)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from demid.sampling import Domain
from demid.uncertainty.plausible import plausible_identifiability_frame
from demid.uncertainty.sweep import tolerance_sweep

from .test_uncertainty import linear

FACTORS = ("a", "b", "c", "d")


def _four_factors():
    domain = Domain(FACTORS, (0.0, -1.0, 2.0, 1.0), (1.0, 1.0, 5.0, 3.0))
    y = linear(1.0, [2.0, 0.5, 0.1, -0.3], 0.01, FACTORS)
    y.response = "y"
    z = linear(-3.0, [0.0, -1.0, 0.4, 0.0], 0.02, FACTORS)
    z.response = "z"
    return domain, {"y": y, "z": z}, {"y": 2.0, "z": -3.2}


def test_the_sweep_without_settings_is_two_to_the_fourteen_sobol_points_seed_0_unpolished():
    domain, surrogates, targets = _four_factors()
    scenarios = {"both": (("y", "z"), 0.1)}
    default = tolerance_sweep(surrogates, domain, scenarios, targets, [0.2], 21)
    named = tolerance_sweep(surrogates, domain, scenarios, targets, [0.2], 21, sobol_points=2 ** 14, seed=0,
                            polish=False, with_error=True)
    pd.testing.assert_frame_equal(default, named)
    # the settings matter: another count, seed or polishing gives other numbers
    for other in (dict(sobol_points=2 ** 13), dict(sobol_points=2 ** 15), dict(seed=1), dict(polish=True)):
        changed = tolerance_sweep(surrogates, domain, scenarios, targets, [0.2], 21, **other)
        assert not changed[["feasible_fraction_pct", "lower", "upper", "fraction_error_pct"]].equals(
            default[["feasible_fraction_pct", "lower", "upper", "fraction_error_pct"]]), other


def test_the_table_without_settings_is_two_to_the_sixteen_sobol_points_seed_0():
    domain, surrogates, targets = _four_factors()
    scenarios = {"both": (("y", "z"), 0.1)}
    default = plausible_identifiability_frame(surrogates, domain, scenarios, targets, 21, polish=False)
    named = plausible_identifiability_frame(surrogates, domain, scenarios, targets, 21, polish=False,
                                            sobol_points=2 ** 16, seed=0)
    pd.testing.assert_frame_equal(default, named)
    for other in (dict(sobol_points=2 ** 15), dict(seed=1)):
        changed = plausible_identifiability_frame(surrogates, domain, scenarios, targets, 21, polish=False, **other)
        assert not np.allclose(changed["robust_fraction_pct"], default["robust_fraction_pct"]), other


def test_a_scenarios_observables_may_be_a_one_shot_iterator():
    """The strict and the plausible set of a scenario given as iter([...]) are those of the same names as a
    tuple, and the table names them: an iterator read once would leave the plausible set without observables."""
    domain = Domain(("a", "b"), (1.0, -2.0), (3.0, 2.0))
    y = linear(1.0, [2.0, 0.5], 0.01)
    y.response = "y"
    z = linear(-3.0, [0.0, -1.0], 0.02)
    z.response = "z"
    surrogates, targets = {"y": y, "z": z}, {"y": 5.0, "z": -3.2}
    as_tuple = plausible_identifiability_frame(surrogates, domain, {"s": (("y", "z"), 0.1)}, targets, 21,
                                               polish=False)
    as_iterator = plausible_identifiability_frame(surrogates, domain, {"s": (iter(["y", "z"]), 0.1)}, targets, 21,
                                                  polish=False)
    pd.testing.assert_frame_equal(as_iterator, as_tuple)
    assert set(as_tuple["observables"]) == {"y+z"}
    # both observables bind: the plausible set is narrower than either observable's alone
    alone = plausible_identifiability_frame(surrogates, domain, {"s": (("y",), 0.1)}, targets, 21, polish=False)
    assert as_tuple["robust_fraction_pct"].iloc[0] < alone["robust_fraction_pct"].iloc[0]


def test_a_whole_number_z_and_tolerance_are_written_as_floats():
    """robust_z: 2 and a tolerance of 1 in the config are numbers the schema reads as ints: the table's columns
    stay float columns (written 2.0 and 1.0 like every other study's), the z's sets those of z = 2.0."""
    domain = Domain(("a", "b"), (1.0, -2.0), (3.0, 2.0))
    y = linear(1.0, [2.0, 0.5], 0.01)
    y.response = "y"
    as_ints = plausible_identifiability_frame({"y": y}, domain, {"s": (("y",), 1)}, {"y": 5.0}, 21, z=2,
                                              polish=False)
    as_floats = plausible_identifiability_frame({"y": y}, domain, {"s": (("y",), 1.0)}, {"y": 5.0}, 21, z=2.0,
                                                polish=False)
    assert as_ints["z"].dtype == np.float64 and as_ints["tolerance"].dtype == np.float64
    pd.testing.assert_frame_equal(as_ints, as_floats)
    assert as_ints.to_csv(index=False) == as_floats.to_csv(index=False)
