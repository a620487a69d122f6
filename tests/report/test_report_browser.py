"""The HTML report as a reader sees it: rendered in headless Chromium, every image loaded, nothing
wider than the window, and a screenshot kept next to the report (results/report/).

The report checked is ``$DEMID_REPORT_HTML`` when set (e.g. the demo's results/report/report.html),
otherwise that of a small self-made study run here; the test also checks that study's tables
(6 significant digits, every column in columns.csv) and that every PNG has its SVG.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pandas as pd
import pytest

from ..workflow_helpers import run_snakemake

pytestmark = pytest.mark.workflow  # a whole Snakemake run, then a browser

BROWSERS = ("chromium", "chromium-browser", "google-chrome")
WIDTH = 1280
PROBE = """<script>
window.addEventListener('load', () => {
  const imgs = Array.from(document.images);
  const broken = imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.alt || i.src.slice(0, 40));
  const doc = document.documentElement;
  const wide = Array.from(document.querySelectorAll('body *')).filter(e => e.getBoundingClientRect().right > doc.clientWidth + 1)
                    .slice(0, 5).map(e => e.tagName + ':' + (e.textContent || '').slice(0, 40));
  const out = document.createElement('pre');
  out.id = 'demid-probe';
  out.textContent = JSON.stringify({images: imgs.length, broken: broken, scrollWidth: doc.scrollWidth,
                                    clientWidth: doc.clientWidth, wide: wide,
                                    headings: Array.from(document.querySelectorAll('h2')).map(h => h.textContent)});
  document.body.appendChild(out);
});
</script>"""


def _browser() -> str | None:
    return next((shutil.which(b) for b in BROWSERS if shutil.which(b)), None)


def _chromium(browser: str, tmp: Path, *args: str) -> subprocess.CompletedProcess:
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={tmp / 'profile'}", f"--window-size={WIDTH},2000", "--virtual-time-budget=20000"]
    return subprocess.run([browser, *flags, *args], capture_output=True, text=True, timeout=180)


@pytest.fixture(scope="module")
def report_html(tmp_path_factory) -> Path:
    given = os.environ.get("DEMID_REPORT_HTML")
    if given:
        return Path(given).resolve()
    root = tmp_path_factory.mktemp("study")
    _write_study(root)
    result = run_snakemake(root, root / "study.yaml", timeout=600)
    assert result.returncode == 0, result.stderr[-3000:]
    return root / "results" / "report" / "report.html"


def _write_study(root: Path) -> None:
    from ..helpers import write_small_ccd_table

    write_small_ccd_table(root)
    (root / "study.yaml").write_text(
        "grid_points: 101\nmaterials:\n  m:\n    data: data/m.csv\n"
        "    design: {type: ccd, alpha: 1.41421, center_runs: 5}\n"
        "    factors:\n      a: {lower: 0.1, upper: 0.9}\n      b: {lower: 1.0, upper: 11.0, unit: 'J m^-2'}\n"
        "    responses:\n      y1: {target: 115, unit: mm}\n      y2: {target: 95}\n"
        "    scenarios:\n      y1_only: {observables: [y1], tolerance: 0.02}\n"
        "      both: {observables: [y1, y2], tolerance: 0.02}\n", encoding="utf-8")


def test_report_renders_in_chromium(report_html, tmp_path):
    browser = _browser()
    if browser is None:
        pytest.skip("no Chromium on this machine (install it with: apt-get install -y chromium); "
                    "the report was not checked in a browser")
    page = tmp_path / "probe.html"
    page.write_text(report_html.read_text(encoding="utf-8").replace("</body>", PROBE + "</body>"), encoding="utf-8")
    dom = _chromium(browser, tmp_path, "--dump-dom", page.as_uri())
    found = re.search(r'<pre id="demid-probe">(.*?)</pre>', dom.stdout, re.S)
    assert found, f"the page did not finish loading: {dom.stderr[-2000:]}"
    probe = json.loads(found.group(1).replace("&quot;", '"').replace("&amp;", "&").replace("&lt;", "<")
                       .replace("&gt;", ">"))
    assert probe["images"] > 0
    assert probe["broken"] == [], probe["broken"]
    assert probe["scrollWidth"] <= probe["clientWidth"], probe["wide"]
    assert probe["headings"][0].rstrip("¶ ") == "Summary"
    shot = report_html.parent / "report_screenshot.png"
    _chromium(browser, tmp_path, f"--screenshot={shot}", report_html.as_uri())
    assert shot.is_file() and shot.stat().st_size > 10_000


def test_self_made_study_outputs_read_well(report_html):
    if os.environ.get("DEMID_REPORT_HTML"):
        pytest.skip("checks the self-made study only")
    results = report_html.parent.parent
    html = report_html.read_text(encoding="utf-8")
    assert "Table 2" not in html and "Table 3" not in html  # no published: generic headings
    pngs = sorted((results / "figures").glob("*.png"))
    assert pngs and all(p.with_suffix(".svg").is_file() for p in pngs)
    columns = pd.read_csv(results / "tables" / "columns.csv")
    known = set(zip(columns["table"], columns["column"]))
    for csv in sorted((results / "tables").glob("*.csv")):
        frame = pd.read_csv(csv, dtype=str, keep_default_na=False)
        missing = [c for c in frame.columns if (csv.name, c) not in known]
        assert not missing, f"{csv.name}: {missing} not in columns.csv"
        for column in frame.columns:
            for value in frame[column]:
                if re.fullmatch(r"-?[0-9.]+(e[-+]?[0-9]+)?", value):
                    digits = value.lstrip("-").split("e")[0].replace(".", "").strip("0")
                    assert len(digits) <= 6, f"{csv.name} {column}: {value}"
    criticism = pd.read_csv(results / "tables" / "criticism.csv")
    assert set(criticism["response"]) == {"y1", "y2"}
