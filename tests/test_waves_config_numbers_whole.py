"""A simulated material's whole-number settings written with a point (``waves.max: 3.0``, ``simulation.seed: 4.0``),
which the schema accepts as integers: the wave budget is quoted as the count it is ("max 3", "3 waves", never
"3.0"), and the seed generates the first wave as the integer does."""

from __future__ import annotations

import pytest

from demid.config import validate_schema
from demid.errors import InputError
from demid.spec import MaterialSpec
from demid.waves import WaveEvidence, check_simulated, stop_decision, waves_max


def _material(**extra) -> dict:
    mat = {"design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
           "simulation": {"command": "sim {a} {b} {run_dir}"},
           "factors": {"a": {"lower": 0.1, "upper": 0.9}, "b": {"lower": 1.0, "upper": 11.0}},
           "responses": {"y": {"target": 115}},
           "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02}}}
    mat.update(extra)
    return mat


def _config(mat: dict) -> dict:
    return validate_schema({"materials": {"m": mat}})


def test_a_wave_budget_written_with_a_point_is_named_as_a_count_when_next_runs_are_missing():
    with pytest.raises(InputError) as err:
        check_simulated(_config(_material(waves={"max": 3.0})))
    assert "materials.m.waves: max 3 needs next_runs" in str(err.value)
    assert "3.0" not in str(err.value)


def test_a_wave_budget_written_with_a_point_is_spent_as_that_many_waves():
    config = _config(_material(waves={"max": 3.0, "next_runs": {"count": 9}}))
    check_simulated(config)
    spec = MaterialSpec.from_material("m", config["materials"]["m"])
    evidence = WaveEvidence(wave=3, max_waves=waves_max(spec), plausible_pct=2.0, previous_pct=8.0,
                            surrogates={"y": {"q2": 0.95, "lof_p": 0.5, "loo_band": 0.5}}, model_limit=False,
                            proposed=9, criticism_runs=0)
    decision = stop_decision(None, evidence)
    assert decision["stop"] is True
    assert decision["reason"].startswith("the budget of 3 waves is spent while ")


def test_a_seed_written_with_a_point_passes_the_check_as_the_integer_does():
    for seed in (4, 4.0):
        config = _config(_material(simulation={"command": "sim {a} {b} {run_dir}", "seed": seed}))
        assert config["materials"]["m"]["simulation"]["seed"] == 4
        check_simulated(config)  # the first wave is generated from it without an error
