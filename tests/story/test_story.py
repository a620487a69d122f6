"""One plausible set for every verdict, per-observable tolerance, implausible targets, advice computed
once, the stopping signal and the recommended point — each planted and checked against an independent computation."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.admissibility import evaluate_scenarios
from demid.sampling.domain import Domain
from demid.scenario import JudgedScenario
from demid.spec import MaterialSpec
from demid.story import StudyAdvice, material_advice, verdict_frame
from demid.surrogate import fit_response
from demid.uncertainty import analyse_material
from demid.uncertainty.recommended import digits_for, recommended_point, uninformative_observables
from demid.wave_value import expected_contraction

from ..helpers import make_ccd_table
from ..uncertainty.test_uncertainty import linear, quadratic

SQUARE = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))


def _spec(responses: dict, scenarios: dict, **extra) -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": responses, "scenarios": scenarios, **extra}
    return MaterialSpec.from_material("m", material, grid_points=201)


def _named(surrogate, name):
    from dataclasses import replace

    return replace(surrogate, response=name)


def _verdicts(spec, surrogates, z=2.0):
    frame, _ = evaluate_scenarios(surrogates, spec, 201)
    frame.insert(0, "material", "m")
    unc = analyse_material(surrogates, spec, z=z, tolerances=[0.01, 0.05],
                           sizes={"plausible": 101, "sweep": 21, "posterior": 41})
    return verdict_frame(spec, frame, unc.plausible, unc.uninformative), unc


# --------------------------------------------------------------------------- item 1: the plausible set
def test_identified_strictly_but_not_plausibly_is_said():
    """y = a with se 0.05 everywhere: strict |a - 0.5| <= 0.005 (1 % of the range, identified); plausible
    |a - 0.5| <= 2 sqrt(0.05² + 0.0025²) = 0.1001 (20 %, bounded)."""
    spec = _spec({"y": {"target": 0.5}}, {"s": {"observables": ["y"], "tolerance": 0.01}})
    sur = {"y": _named(linear(0.0, [1.0, 0.0], variance_intercept=0.05 ** 2), "y")}
    verdicts, _ = _verdicts(spec, sur)
    row = verdicts.set_index("factor").loc["a"]
    assert row["strict_lower"] == pytest.approx(0.495, abs=1e-6) and row["strict_upper"] == pytest.approx(0.505, abs=1e-6)
    half = 2 * np.sqrt(0.05 ** 2 + 0.0025 ** 2)
    assert row["plausible_lower"] == pytest.approx(0.5 - half, abs=2e-3)
    assert row["plausible_upper"] == pytest.approx(0.5 + half, abs=2e-3)
    assert row["verdict"] == "bounded"
    assert "identified if surrogate and measurements were exact (strict interval [0.495, 0.505]" in row["reason"]
    # an exact surrogate: the tolerance is the band, plausible = strict, identified on both
    exact = {"y": _named(linear(0.0, [1.0, 0.0]), "y")}
    verdicts, _ = _verdicts(spec, exact)
    row = verdicts.set_index("factor").loc["a"]
    assert row["verdict"] == "identified" and "strict" not in row["reason"]
    assert row["plausible_lower"] == pytest.approx(0.495, abs=1e-3)


# --------------------------------------------------------------------------- item 2: per-observable tolerance
@pytest.mark.parametrize("own", [{"tolerance_abs": 0.03}, {"tolerance": 0.12}])
def test_per_observable_tolerance_matches_an_independent_grid(own):
    """y1 = a (target 0.5, scenario tolerance 2 %), y2 = b² (target 0.25, own band): the strict and the plausible
    fractions equal a brute-force count on a fine grid."""
    spec = _spec({"y1": {"target": 0.5}, "y2": {"target": 0.25, **own}},
                 {"both": {"observables": ["y1", "y2"], "tolerance": 0.02}})
    se2 = 0.004
    sur = {"y1": _named(linear(0.0, [1.0, 0.0]), "y1"),
           "y2": _named(quadratic([0, 0, 0, 0, 0, 1.0], covariance=np.diag([se2 ** 2, 0, 0, 0, 0, 0])), "y2")}
    band2 = own.get("tolerance_abs", own.get("tolerance", 0) * 0.25)
    frame, _ = evaluate_scenarios(sur, spec, 201)
    n = 4000  # cell centres: an unbiased count
    centres = (np.arange(n) + 0.5) / n
    a, b = np.meshgrid(centres, centres, indexing="ij")
    strict = (np.abs(a - 0.5) <= 0.01) & (np.abs(b ** 2 - 0.25) <= band2)
    assert frame["feasible_fraction_pct"].iloc[0] == pytest.approx(100 * strict.mean(), rel=5e-3)
    unc = analyse_material(sur, spec, z=2.0, tolerances=[0.01, 0.05], sizes={"plausible": 201, "sweep": 21,
                                                                             "posterior": 41})
    # plausible: no sigma, so each band is its tolerance widened by the surrogate's se: z sqrt(se² + (band/z)²)
    plausible = (np.abs(a - 0.5) <= 0.01) & (np.abs(b ** 2 - 0.25) <= 2 * np.sqrt(se2 ** 2 + (band2 / 2) ** 2))
    assert unc.plausible["robust_fraction_pct"].iloc[0] == pytest.approx(100 * plausible.mean(), rel=1e-2)
    ranking = unc.ranking.set_index("observables")
    alone = np.abs(b ** 2 - 0.25) <= band2
    assert ranking.loc["y2", "feasible_fraction_pct"] == pytest.approx(100 * alone.mean(), rel=5e-3)


def test_an_uninformative_observable_is_named_with_its_reason():
    """rho = 1505 + 60 (a - 0.5), ±2 % = ±30.1: its band covers its whole simulated range (1475-1535)."""
    spec = _spec({"y": {"target": 0.5}, "rho": {"target": 1505.0}},
                 {"y_only": {"observables": ["y"], "tolerance": 0.02},
                  "rho_only": {"observables": ["rho"], "tolerance": 0.02},
                  "both": {"observables": ["y", "rho"], "tolerance": 0.02}})
    sur = {"y": _named(linear(0.0, [0.0, 1.0]), "y"), "rho": _named(linear(1475.0, [60.0, 0.0]), "rho")}
    verdicts, unc = _verdicts(spec, sur)
    assert list(unc.uninformative) == ["rho"] and "covers (almost) its whole simulated range" in unc.uninformative["rho"]
    assert set(verdicts.loc[verdicts["scenario"] == "rho_only", "verdict"]) == {"uninformative observable"}
    assert "uninformative observable" not in set(verdicts.loc[verdicts["scenario"] == "both", "verdict"])
    # silent where the band is narrow: ±0.5 % of 1505 = ±7.5, a quarter of the range
    narrow = _spec({"rho": {"target": 1505.0, "tolerance": 0.005}}, {"r": {"observables": ["rho"], "tolerance": 0.02}})
    _, unc = _verdicts(narrow, {"rho": sur["rho"]})
    assert unc.uninformative == {}
    # the advice does not propose measuring it
    ranking = pd.DataFrame({"observables": ["y", "rho", "y+rho"], "n_observables": [1, 1, 2],
                            "information_gain_bits": [4.6, 0.0, 4.61], "feasible_fraction_pct": [4.0, 100.0, 4.0],
                            "best_subset": ["(none)", "(none)", "y"],
                            "gain_vs_best_subset_bits": [4.6, 0.0, 0.01], "targets_reachable": [True, True, True]})
    assert uninformative_observables(ranking) == {"rho": uninformative_observables(ranking)["rho"]}
    one = _spec({"y": {"target": 0.5}, "rho": {"target": 1505.0}}, {"y_only": {"observables": ["y"], "tolerance": 0.02}})
    advice = material_advice(one, verdicts.iloc[0:0], ranking=ranking,
                             uninformative=uninformative_observables(ranking))
    assert not any(i.kind == "add_observable" and i.observable == "rho" for i in advice)


# --------------------------------------------------------------------------- item 3: implausible targets
def test_a_target_off_by_a_power_of_ten_gets_check_target_and_no_widening():
    spec = _spec({"rho": {"target": 1.505}, "y": {"target": 0.5}},
                 {"both": {"observables": ["rho", "y"], "tolerance": 0.02}})
    from demid.data import implausible_targets

    table = pd.DataFrame({"rho": [1474.0, 1500.0, 1534.0], "y": [0.1, 0.5, 0.9]})
    implausible = implausible_targets(table, spec.targets)
    level2 = {"feasible": False, "tolerance": 0.02, "bottleneck": "rho", "observables": ["rho", "y"],
              "best_point_at_bound": {"a": "lower", "b": "upper"}, "unmoved": []}
    verdicts = pd.DataFrame({"material": "m", "scenario": "both", "factor": ["a", "b"], "verdict": "no admissible point"})
    advice = material_advice(spec, verdicts, criticism={"level2": level2}, implausible=implausible)
    kinds = [i.kind for i in advice]
    assert "widen" not in kinds
    (check,) = [i for i in advice if i.kind == "check_target"]
    assert "config key materials.m.responses.rho.target" in check.text
    assert "×1000 → 1505 lies inside the simulated range (1474 to 1534)" in check.text
    # the same best point on a bound with a plausible target: widening is advised there
    advice = material_advice(spec.__class__.from_material("m", {**spec.material_config(), "responses": {
        "rho": {"target": 1600.0}, "y": {"target": 0.5}}}), verdicts, criticism={"level2": level2}, implausible={})
    assert [(i.factor, i.bound) for i in advice if i.kind == "widen"] == [("a", "lower"), ("b", "upper")]


def test_no_widening_of_an_unresolved_factor():
    spec = _spec({"y": {"target": 0.5}}, {"s": {"observables": ["y"], "tolerance": 0.02}})
    verdicts = pd.DataFrame({"material": "m", "scenario": "s", "factor": ["a", "b"],
                             "verdict": ["unresolved", "cut by the search range (lower bound)"]})
    widen = [i for i in material_advice(spec, verdicts) if i.kind == "widen"]
    assert [(i.factor, i.bound) for i in widen] == [("b", "lower")]


# --------------------------------------------------------------------------- item 5: stopping signal
def _fitted(noise, seed=1):
    def responses(x):
        a, b = x[:, 0], x[:, 1]
        return {"y": 10 + 4 * a + 3 * b + 2 * a * b - 3 * a ** 2}

    table = make_ccd_table(responses, [0.0, 0.0], [1.0, 1.0], noise=noise, seed=seed).rename(
        columns={"x1": "a", "x2": "b"})
    return {"y": fit_response(table, ["a", "b"], "y", alpha=1.41421).surrogate()}


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_wave_that_cannot_narrow_the_set_says_stop_and_one_that_can_does_not(seed):
    sur = _fitted(noise=0.3, seed=seed)
    new_runs = np.random.default_rng(seed).uniform(0, 1, size=(12, 2))
    target = 12.5
    # the measurement band (σ = 1) dwarfs the surrogate's se: new runs cannot narrow it
    loose = _spec({"y": {"target": target, "sigma": 1.0}}, {"s": {"observables": ["y"], "tolerance": 0.01}})
    value = expected_contraction(JudgedScenario(loose, loose.scenarios[0], sur, 2.0), new_runs)
    assert value["stop"] and value["expected_contraction"] < 0.10
    # a tight measurement (σ = 0.01): the surrogate's se decides the band, and 12 runs shrink it
    tight = _spec({"y": {"target": target, "sigma": 0.01}}, {"s": {"observables": ["y"], "tolerance": 0.01}})
    value = expected_contraction(JudgedScenario(tight, tight.scenarios[0], sur, 2.0), new_runs)
    assert not value["stop"] and value["expected_contraction"] > 0.2
    # the advice follows the value
    advice = material_advice(loose, pd.DataFrame(columns=["scenario", "factor", "verdict"]),
                             wave_value=expected_contraction(JudgedScenario(loose, loose.scenarios[0], sur, 2.0), new_runs))
    assert [i.kind for i in advice if i.kind in ("stop", "next_runs")] == ["stop"]


# --------------------------------------------------------------------------- item 6: recommended point
def test_recommended_point_is_the_most_robust_plausible_point():
    """y1 = a (0.5 ± 0.02·0.5), y2 = b (0.3 ± 0.02·0.3), exact: the largest margin is at (0.5, 0.3)."""
    spec = _spec({"y1": {"target": 0.5}, "y2": {"target": 0.3}},
                 {"s": {"observables": ["y1", "y2"], "tolerance": 0.02}})
    sur = {"y1": _named(linear(0.0, [1.0, 0.0]), "y1"), "y2": _named(linear(0.0, [0.0, 1.0]), "y2")}
    rec = recommended_point(JudgedScenario(spec, spec.scenarios[0], sur, 2.0), n=401)
    assert rec["plausible"] and rec["implausibility"] < 0.3
    assert rec["point"]["a"] == pytest.approx(0.5, abs=0.0026) and rec["point"]["b"] == pytest.approx(0.3, abs=0.0026)
    far = _spec({"y1": {"target": 5.0}, "y2": {"target": 0.3}}, {"s": {"observables": ["y1", "y2"], "tolerance": 0.02}})
    assert not recommended_point(JudgedScenario(far, far.scenarios[0], sur, 2.0), n=101)["plausible"]
    assert digits_for(8.76) == 1 and digits_for(0.0091) == 4 and digits_for(0.5) == 2


# --------------------------------------------------------------------------- item 4: advice read from one table
def test_advice_round_trips_through_its_table():
    spec = _spec({"y": {"target": 0.5}}, {"s": {"observables": ["y"], "tolerance": 0.02}})
    verdicts = pd.DataFrame({"material": "m", "scenario": "s", "factor": ["a", "b"],
                             "verdict": ["bounded", "cut by the search range (upper bound)"]})
    advice = StudyAdvice(material_advice(spec, verdicts))
    again = StudyAdvice.from_frame(advice.to_frame())
    assert again.items == advice.items and again.texts("m", ("widen",)) == advice.texts("m", ("widen",))


# --------------------------------------------------------------------------- the pipeline: one advice, every section
def _report_texts(root, config_path):
    import yaml

    from demid.report.sections import ReportSections

    cfg = yaml.safe_load(config_path.read_text(encoding="utf-8"))
    sections = ReportSections(str(root / "results"), {"materials": cfg["materials"], "published": None})
    return cfg, sections


def _plain(html: str) -> str:
    """Rendered report HTML as plain lines: a heading as '### text', a list item as '- text', tags dropped."""
    import html as entities
    import re

    def flat(fragment: str) -> str:  # tags dropped, entities kept until the end (&lt; is text, not a tag)
        return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", "", fragment)).strip()

    def heading(m) -> str:
        return "\n### " + entities.unescape(flat(m.group(1))).rstrip("¶ ") + "\n"

    text = re.sub(r"<h3[^>]*>(.*?)</h3>", heading, html, flags=re.S)
    text = re.sub(r"<li[^>]*>(.*?)</li>", lambda m: "\n- " + flat(m.group(1)) + "\n", text, flags=re.S)
    return entities.unescape(re.sub(r"<[^>]+>", "", text))


def _markdown(parts) -> str:
    """The report's text parts (sanitised HTML) as plain lines."""
    return _plain("\n".join(getattr(p, "data", "") or "" for p in parts))


def _shown(text: str, labels) -> str:
    """An advice text as the report shows it: labels typeset, Markdown rendered, read as plain text."""
    from demid.report.safe_html import markdown_html
    from demid.report.sections import typeset_labels

    return _plain(markdown_html(typeset_labels(text, labels))).strip()


@pytest.mark.workflow
def test_demo_advice_rows_are_the_summary_and_level2_text_and_table3_is_unchanged(demo_run):
    from demid.report.sections import typeset_labels

    cfg, sections = _report_texts(demo_run, demo_run / "config.yaml")
    advice = pd.read_csv(demo_run / "results" / "tables" / "advice.csv").fillna("")
    verdicts = pd.read_csv(demo_run / "results" / "tables" / "verdicts.csv")
    assert list(verdicts.columns) == ["material", "scenario", "factor", "strict_lower", "strict_upper",
                                      "plausible_lower", "plausible_upper", "verdict", "reason"]
    assert len(advice) and set(advice["kind"]) <= {"widen", "add_observable", "check_target", "next_runs", "stop",
                                                   "recalibrate", "measurement_order"}
    summary = _markdown(sections.summary())
    for m in cfg["materials"]:
        level2 = _markdown(sections.criticism(m))
        walk = advice[(advice["material"] == m) & (advice["kind"] == "measurement_order")]["text"]
        ranking_section = _markdown(sections.uncertainty(m))  # the ranking in words, below the ranking
        assert len(walk) and all(_shown(t, sections._plain_labels) in ranking_section for t in walk), m
        rows = advice[(advice["material"] == m) & (advice["kind"] != "measurement_order")]
        labels = sections._plain_labels
        bullets = [line[2:] for line in summary.split(f"### ")[[s.split("\n")[0] for s in summary.split("### ")].index(
            sections._label(m))].splitlines() if line.startswith("- ")]
        next_steps = bullets[-len(rows):] if len(rows) else []
        assert next_steps == [_shown(t, labels) for t in rows["text"]], m
        for text in rows[rows["kind"].isin(["widen", "check_target", "recalibrate"])]["text"]:
            assert _shown(text, labels) in level2
        assert "Widen" not in level2.replace(" ".join(_shown(t, labels) for t in rows[rows["kind"] == "widen"]
                                                      ["text"]), "")
    # the summary's verdicts are the table's: mortar γ identified strictly, bounded plausibly
    mortar = verdicts[(verdicts["material"] == "mortar") & (verdicts["scenario"] == "full_sequence")].set_index("factor")
    assert mortar.loc["gamma", "verdict"] != "identified"
    assert "identified if surrogate and measurements were exact" in mortar.loc["gamma", "reason"]
    ident = pd.read_csv(demo_run / "results" / "tables" / "identifiability.csv").set_index(["material", "scenario",
                                                                                           "factor"])
    for _, row in verdicts.iterrows():  # the strict columns are Table 3's numbers
        key = (row["material"], row["scenario"], row["factor"])
        assert row["strict_lower"] == pytest.approx(ident.loc[key, "lower"], rel=1e-5)
        assert row["strict_upper"] == pytest.approx(ident.loc[key, "upper"], rel=1e-5)


@pytest.mark.workflow
def test_a_study_with_a_unit_slip_and_a_next_wave_gets_one_consistent_story(study_dir):
    """y2's target in another unit (×1000 off): validate names the key and the repair, no widening anywhere;
    σ of y1 larger than the surrogate's se: the next wave is expected to buy little, the advice says stop."""
    import subprocess
    import sys

    import yaml

    from ..workflow_helpers import run_snakemake

    cfg_path = study_dir / "study.yaml"
    cfg = yaml.safe_load(cfg_path.read_text(encoding="utf-8"))
    cfg["materials"]["m"]["responses"]["y2"]["target"] = 0.095
    cfg["materials"]["m"]["responses"]["y1"]["sigma"] = 3.0
    cfg["materials"]["m"]["next_runs"] = {"count": 6, "scenario": "y1_only", "margin": 0.1}
    cfg_path.write_text(yaml.safe_dump(cfg, sort_keys=False), encoding="utf-8")
    check = subprocess.run([sys.executable, "-m", "demid", "validate", "--config", "study.yaml"], cwd=study_dir,
                           capture_output=True, text=True)
    assert check.returncode == 0, check.stderr
    assert "config key materials.m.responses.y2.target" in check.stderr and "×1000 → 95 lies inside" in check.stderr
    proc = run_snakemake(study_dir, cfg_path, "results/report/report.html", timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    advice = pd.read_csv(study_dir / "results" / "tables" / "advice.csv").fillna("")
    # no widening for the slipped target: only where y1's own plausible set ends at a bound
    assert all("plausible set of *y1_only*" in t and "best point" not in t
               for t in advice.loc[advice["kind"] == "widen", "text"]), advice.to_string()
    (check_row,) = advice[advice["kind"] == "check_target"].itertuples()
    assert check_row.observable == "y2" and "×1000 → 95 lies inside the simulated range" in check_row.text
    assert list(advice.loc[advice["kind"].isin(["stop", "next_runs"]), "kind"]) == ["stop"]
    verdicts = pd.read_csv(study_dir / "results" / "tables" / "verdicts.csv")
    both = verdicts[verdicts["scenario"] == "both"]
    assert (both["verdict"] == "no admissible point").all()
    assert both["reason"].str.contains("the target of y2 lies far outside every simulated value").all()
    _, sections = _report_texts(study_dir, cfg_path)
    stop = advice.loc[advice["kind"] == "stop", "text"].iloc[0]
    stop = _shown(stop, sections._plain_labels)
    assert stop in _markdown(sections.next_wave("m")) and stop in _markdown(sections.summary())
    assert (study_dir / "results" / "tables" / "next_runs.csv").is_file()


def test_own_tolerance_keys_are_validated_with_the_key_named():
    from pathlib import Path

    import yaml

    from demid.config import check_semantics, validate_schema
    from demid.errors import InputError

    raw = yaml.safe_load((Path(__file__).resolve().parents[2] / "config.yaml").read_text(encoding="utf-8"))
    raw["materials"]["mortar"]["responses"]["d5"].update(tolerance=0.01, tolerance_abs=2.0)
    with pytest.raises(InputError, match=r"config key materials\.mortar\.responses\.d5: both tolerance and "
                                         r"tolerance_abs"):
        check_semantics(validate_schema(raw))
    raw["materials"]["mortar"]["responses"]["d5"].pop("tolerance")
    spec = MaterialSpec.from_config("mortar", validate_schema(raw))
    assert spec.response("d5").tolerance_abs == 2.0 and spec.response("d10").tolerance is None


def test_the_ranking_shows_an_uninformative_observables_gain_as_about_zero():
    from demid.report.sections import ranking_display

    ranking = pd.DataFrame({"rank": [1, 2], "observables": ["y", "rho"], "information_gain_bits": [3.2, 0.18],
                            "feasible_fraction_pct": [4.0, 100.0]})
    shown = ranking_display(ranking, {"rho": "its band covers its whole simulated range"})
    assert list(shown["information gain [bit]"]) == [3.2, "~0 (0.18; uninformative)"]
    assert list(ranking_display(ranking)["information gain [bit]"]) == [3.2, 0.18]
