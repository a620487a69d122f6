"""Jobs import only what they use: the story, model-extension and report jobs read results and never fit,
criticise or draw, so importing their modules must not load statsmodels, scipy.stats or matplotlib (each a
large share of a short job's time).  Checked in a fresh interpreter: ``sys.modules`` after the import."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("statsmodels", "scipy.stats", "scipy.special", "matplotlib")


def _loaded_after(statement: str) -> list[str]:
    code = (f"import json, sys\n{statement}\n"
            f"print(json.dumps(sorted(m for m in sys.modules if m.split('.')[0] in ('statsmodels', 'scipy', "
            f"'matplotlib'))))")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True,
                         env={"PYTHONPATH": str(ROOT), "PATH": ""})
    return json.loads(out.stdout.splitlines()[-1])


@pytest.mark.parametrize("statement", [
    "import demid.story",
    "from demid.story.extensions import model_extensions",
    "from demid.criticism.reach import Reach, saturation_advice",
])
def test_reading_jobs_load_no_fitting_or_drawing_library(statement):
    loaded = _loaded_after(statement)
    heavy = [m for m in loaded if any(m == h or m.startswith(h + ".") for h in HEAVY)]
    assert heavy == [], f"{statement} loads {heavy[:5]}"


def test_criticism_names_still_resolve():
    """The package imports its parts on first use: every name it exports is there, and is the submodule's."""
    import demid.criticism as criticism
    from demid.criticism.level1 import criticize
    from demid.plots.criticism import residual_figure

    assert criticism.criticize is criticize
    assert criticism.residual_figure is residual_figure
    for name in criticism.__all__:
        assert getattr(criticism, name) is not None
    with pytest.raises(AttributeError):
        criticism.no_such_name  # noqa: B018


def test_the_heavy_import_is_seen():
    """The check can fail: the material step does load them."""
    loaded = _loaded_after("import demid.criticism.level1")
    assert "statsmodels" in loaded or "scipy.stats" in loaded


def test_schema_parsed_once_and_each_caller_gets_its_own_copy():
    from demid.schema import parsed_schema, load_schema

    first = load_schema()
    first["properties"].clear()  # a caller changing its copy
    second = load_schema()
    assert second["properties"], "a caller's change reached the next caller"
    assert second == parsed_schema.__wrapped__(str(Path(ROOT, "demid", "schemas", "config.schema.yaml")))
    before = parsed_schema.cache_info().hits
    load_schema()
    assert parsed_schema.cache_info().hits == before + 1
