"""Configured labels appear typeset in the report's text, never as raw underscores or carets."""

from demid.report.sections import typeset_labels

LABELS = sorted(["μ_r,Po", "e_Po", "d_10", "d_1", "J m^-2", "plain"], key=len, reverse=True)


def test_labels_get_sub_and_superscripts():
    out = typeset_labels("μ_r,Po ∈ [0.1, 0.2]; γ in J m^-2; d_10 and d_1", LABELS)
    assert out == ("μ<sub>r,Po</sub> ∈ [0.1, 0.2]; γ in J m<sup>-2</sup>; d<sub>10</sub> and d<sub>1</sub>")


def test_code_spans_words_and_unlabelled_text_are_untouched():
    text = "`d_10` stays; xd_1 and d_1x are other words; plain stays plain"
    assert typeset_labels(text, LABELS) == text


def _mortar_spec():
    from pathlib import Path

    import yaml

    from demid.config import validate_schema
    from demid.spec import MaterialSpec

    repo = Path(__file__).resolve().parents[2]
    config = validate_schema(yaml.safe_load((repo / "config.yaml").read_text(encoding="utf-8")))
    return MaterialSpec.from_config("mortar", config)


def _ranking_of_the_full_set(spec):
    import pandas as pd

    used = max((sc.observables for sc in spec.scenarios), key=len)
    return pd.DataFrame({"observables": ["+".join(used)], "n_observables": [len(used)], "best_subset": [""],
                         "information_gain_bits": [1.0], "gain_vs_best_subset_bits": [1.0], "feasible_fraction_pct": [0.0],
                         "targets_reachable": [True]})


def test_next_step_settles_a_discrepancy_before_asking_for_a_narrower_set():
    """Where no point meets every target, "a narrower set needs a new kind of measurement" means nothing:
    the next step names the observable that limits the best match, by its label."""
    import pandas as pd

    from demid.story import material_advice

    spec = _mortar_spec()
    verdicts = pd.DataFrame(columns=["scenario", "factor", "verdict"])
    level2 = {"feasible": False, "tolerance": 0.02, "bottleneck": "d10", "best_point_at_bound": {}}
    steps = [i.text for i in material_advice(spec, verdicts, ranking=_ranking_of_the_full_set(spec),
                                             criticism={"level2": level2})]
    assert not any("narrower set" in s for s in steps)
    label = spec.response_labels["d10"]
    assert any(s.startswith("No parameter set meets every target within 2 %") and label in s for s in steps), steps
    feasible = [i.text for i in material_advice(spec, verdicts, ranking=_ranking_of_the_full_set(spec),
                                                criticism={"level2": {**level2, "feasible": True}})]
    assert any("narrower set" in s for s in feasible)