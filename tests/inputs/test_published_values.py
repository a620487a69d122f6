"""The published-values file (config key ``published``) is checked at validation: a slip in it is one line
naming the file and the key, never a traceback in the last job or an empty row of the paper comparison."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from demid.config import load_config
from demid.errors import InputError

ROOT = Path(__file__).resolve().parents[2]

# (substitution in data/published.yaml, words the error must contain)
SLIPS = [
    (r"rmse: 10\.311", "rmse: abc", ["table2.paste.D.rmse", "'abc' is not a number"]),
    (r"r2: 0\.989", "r2: 98.9", ["table2.poraver.aor.r2", "98.9 % is 0.989"]),
    (r"r2: 0\.632", "r2: -0.632", ["table2.paste.S.r2", "between 0 and 1"]),
    (r"rmse: 1\.234", "rmse: -1.234", ["table2.mortar.d5.rmse", "cannot be negative"]),
    (r"    d10: ", "    d01: ", ["table2.mortar.d01", "'d01' is not a response of mortar", "d10"]),
    (r"^  mortar: \{d5", "  mortr: {d5", ["targets.mortr", "'mortr' is not a material", "'mortar'"]),
    (r"d15_only:      \{feas", "d15_onyl:      {feas", ["table3.mortar.d15_onyl", "'d15_only'"]),
    (r"feasible_fraction_pct: 0\.702", "feasible_fraction_pct: 170.2", ["table3.poraver.aor_only", "0 and 100"]),
    (r"width: \{e: 0\.8485", "width: {E: 0.8485", ["table3.poraver.aor_only.width.E", "not a factor of poraver"]),
    (r"gamma: \[\"6\.02\", \"6\.40\"\]", "gamma: [\"6.40\", \"6.02\"]",
     ["intervals.mortar.full_sequence.gamma", "lower end above its upper end"]),
    (r"quantity: width, factor: e,", "quantity: width,", ["contractions (item 2)", "needs factor"]),
    (r"value: -99\.7", "value: -199.7", ["contractions (item 4).value", "below -100"]),
    (r"quantity: fraction, value: -87\.3", "quantity: fractoin, value: -87.3", ["contractions (item 1).quantity"]),
    (r"max_error: 0\.02", "max_error: 2", ["pareto.paste.max_error", "2 % is 0.02"]),
    (r"mu_s: \[0\.052, 0\.063\]", "mu_s: [0.052]", ["pareto.paste.intervals.mu_s", "[lower, upper]"]),
    (r"mu_s: \[0\.052, 0\.063\]", "mu_s: 0.052", ["pareto.paste.intervals.mu_s", "should be a list"]),
    (r"^pareto:\n  paste:", "pareto:\n  mortar:", ["pareto.mortar", "computes no Pareto front for mortar"]),
    (r"aor:   \{r2: 0\.989", "aor:   {r2: 0,989", ["table2.poraver.aor", "unknown key '989'", "decimal comma"]),
    (r"unresolved: \[mu_s, mu_r\]", "unresolved: [mu_s, mu_rr]", ["unresolved", "'mu_rr'", "'mu_r'"]),
    (r"^search_domain:", "search_domian:", ["unknown key 'search_domian'", "'search_domain'"]),
    (r"mu_s: \[0\.051821, 0\.388179\]", "mu_s: [0.051821, 0.051821]",
     ["search_domain.paste.mu_s", "lower end at its upper end; a search range needs lower < upper"]),
    (r"^tolerances:\n  poraver: \{aor_only: 0\.01", "tolerances:\n  poraver: {aor_only: 5",
     ["tolerances.poraver.aor_only", "5 % is 0.05"]),
]


@pytest.fixture()
def study(tmp_path):
    shutil.copytree(ROOT / "data", tmp_path / "data")
    shutil.copy(ROOT / "config.yaml", tmp_path / "config.yaml")
    return tmp_path


def test_the_shipped_file_passes(study):
    load_config(study / "config.yaml", base_dir=study)


@pytest.mark.parametrize(("pattern", "replacement", "words"), SLIPS, ids=[s[1] for s in SLIPS])
def test_a_slip_in_the_published_file_names_its_key(study, pattern, replacement, words):
    path = study / "data" / "published.yaml"
    text = path.read_text(encoding="utf-8")
    slipped, n = re.subn(pattern, replacement, text, count=1, flags=re.M)
    assert n == 1, f"premise: {pattern!r} occurs in data/published.yaml"
    path.write_text(slipped, encoding="utf-8")
    with pytest.raises(InputError) as info:
        load_config(study / "config.yaml", base_dir=study)
    message = str(info.value)
    assert "\n" not in message
    assert "config key published: data/published.yaml" in message
    for word in words:
        assert word in message


def test_the_cli_says_it_in_one_line(study):
    path = study / "data" / "published.yaml"
    path.write_text(path.read_text(encoding="utf-8").replace("rmse: 10.311", "rmse: abc"), encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "demid", "validate", "--config", str(study / "config.yaml")],
                          capture_output=True, text=True, cwd=study)
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("demid: error:") and "table2.paste.D.rmse" in lines[0]
    assert "Traceback" not in done.stderr


def test_another_studys_material_is_left_out_and_not_compared(study):
    """A published file shared by several studies (or a config for one material) is fine: the materials the
    config does not study are neither checked nor compared, unless the name is a likely typo."""
    import yaml

    from demid.config import load_yaml
    from demid.published_values import for_materials

    config = yaml.safe_load((study / "config.yaml").read_text(encoding="utf-8"))
    config["materials"] = {"mortar": config["materials"]["mortar"]}
    config["smoke_material"] = "mortar"
    (study / "one.yaml").write_text(yaml.safe_dump(config), encoding="utf-8")
    load_config(study / "one.yaml", base_dir=study)
    published = for_materials(load_yaml(study / "data" / "published.yaml"), ["mortar"])
    assert set(published["table2"]) == {"mortar"} and set(published["table3"]) == {"mortar"}
    assert published["contractions"] and {c["material"] for c in published["contractions"]} == {"mortar"}
    assert published["provenance"] and not published["pareto"]


def test_a_folder_given_as_the_published_file_is_named_a_folder(study):
    config = (study / "config.yaml").read_text(encoding="utf-8")
    (study / "config.yaml").write_text(re.sub(r"(?m)^published: .*$", "published: data", config), encoding="utf-8")
    with pytest.raises(InputError, match=r"config key published: 'data' is a folder .*name the YAML file"):
        load_config(study / "config.yaml", base_dir=study)
