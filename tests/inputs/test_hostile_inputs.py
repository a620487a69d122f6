"""Inputs from a hostile or careless collaborator: labels holding markup and script, a results folder
holding a shell command and a space, templated configs, ``--out`` onto the data, and an edit of a table
while its job ran.  Nothing from a config runs, no user file is replaced, no edit goes unseen."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest
import yaml

from ..helpers import run_demid
from ..workflow_helpers import REPO, planned_jobs, run_snakemake, written_results

MARK = "PWNED"
SCRIPT = f"<script>document.title='{MARK}'</script>"
IMAGE = f"<img src=x onerror=\"document.title='{MARK}'\">"
MD_LINK = f"[see](javascript:document.title='{MARK}')"
HTML_LINK = f"<a href=\"javascript:document.title='{MARK}'\">y</a>"
SVG = f"<svg onload=\"document.title='{MARK}'\"></svg>"
SHELL_DIR = f"out dir $(touch {MARK}_FILE)"


# --------------------------------------------------------------------------- the sanitiser itself
class _Collect(HTMLParser):
    """Every start tag with its attributes, and the text inside <script> elements."""

    def __init__(self):
        super().__init__()
        self.tags: list[tuple[str, dict]] = []
        self.scripts: list[str] = []
        self._in_script = False

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        self._in_script = tag == "script"

    def handle_endtag(self, tag):
        self._in_script = False

    def handle_data(self, data):
        if self._in_script:
            self.scripts.append(data)


def _live_payloads(html: str) -> list[str]:
    """What of the payloads would run in ``html``: a script holding the mark, an event handler or
    ``javascript:`` address anywhere, an ``svg`` or an image that is not inline PNG data."""
    found = _Collect()
    found.feed(html)
    live = [f"script: {s[:60]}" for s in found.scripts if MARK in s]
    for tag, attrs in found.tags:
        for name, value in attrs.items():
            value = value or ""
            if name.startswith("on") and MARK in value:
                live.append(f"{tag} {name}={value[:60]}")
            if name in ("href", "src", "action", "formaction") and value.strip().lower().startswith("javascript:"):
                live.append(f"{tag} {name}={value[:60]}")
        if tag == "img" and not (attrs.get("src") or "").startswith("data:image/png;base64,"):
            live.append(f"img src={attrs.get('src')}")
        if tag == "svg" and any(n.startswith("on") for n in attrs):
            live.append("svg with a handler")
    return live


@pytest.mark.parametrize("payload", [SCRIPT, IMAGE, MD_LINK, HTML_LINK, SVG,
                                     "<IMG SRC=\"javascript:alert('PWNED')\">", "<iframe src=javascript:PWNED>",
                                     "<a href=\" JaVaScRiPt:PWNED\">x</a>", "<<script>PWNED</script>",
                                     "`code` <script>PWNED</script> `", "<style>body{background:url(PWNED)}</style>"])
def test_report_text_holding_markup_is_shown_not_run(payload):
    from demid.report.safe_html import markdown_html

    html = markdown_html(f"## Material {payload}\n\nThe factor {payload} in unit {payload}.\n\n| a | b |\n|---|---|\n"
                         f"| {payload} | 1 |")
    assert _live_payloads(html) == []
    assert "<script" not in html.lower() and "<iframe" not in html.lower() and "<style" not in html.lower()
    # shown as text (a link keeps its words, without the address)
    assert MARK in html or payload.startswith(("[", "<a "))


def test_the_collector_sees_live_payloads():
    """The check above can fail: unsanitised Markdown keeps every payload live."""
    from nbconvert.filters.markdown_mistune import markdown2html_mistune

    raw = markdown2html_mistune(f"{SCRIPT} {IMAGE} {MD_LINK}")
    assert len(_live_payloads(raw)) >= 3


def test_links_only_to_http_addresses_and_figures_only_as_png():
    from demid.report.safe_html import markdown_html, sanitize

    html = markdown_html("[a](https://example.org/x) [b](http://example.org) [c](file:///etc/passwd) "
                         "[d](data:text/html,x) [e](vbscript:x) [f](ftp://x)")
    found = _Collect()
    found.feed(html)
    hrefs = [attrs.get("href") for tag, attrs in found.tags if tag == "a"]
    assert [h for h in hrefs if h] == ["https://example.org/x", "http://example.org"]
    figure = sanitize('<figure><img src="data:image/png;base64,iVBORw0KGgo=" alt="x" onerror="PWNED">'
                      '<img src="data:text/html;base64,PHNjcmlwdD4="></figure>', figure=True)
    assert figure.count('src="data:image/png;base64,iVBORw0KGgo="') == 1 and "onerror" not in figure
    assert "data:text/html" not in figure.replace("&lt;", "<").split("<img", 2)[-1].split(">")[0] or \
        'src="data:text/html' not in figure


# --------------------------------------------------------------------------- a whole study of hostile labels
def _write_study(root: Path) -> dict:
    from ..helpers import write_small_ccd_table

    write_small_ccd_table(root)
    config = {
        "results_dir": SHELL_DIR, "grid_points": 101,
        "materials": {"m": {
            "data": "data/m.csv", "label": f"Mortar {SCRIPT}", "paper_figure": "fig6",
            "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
            "factors": {"a": {"lower": 0.1, "upper": 0.9, "label": f"friction {IMAGE}", "unit": MD_LINK},
                        "b": {"lower": 1.0, "upper": 11.0, "label": f"energy {HTML_LINK}", "unit": SVG}},
            "responses": {"y1": {"target": 115, "label": f"angle {SCRIPT}", "unit": IMAGE},
                          "y2": {"target": 95, "label": f"flow {MD_LINK}", "unit": HTML_LINK}},
            "scenarios": {"y1_only": {"observables": ["y1"], "tolerance": 0.02, "label": f"one {IMAGE}"},
                          "both": {"observables": ["y1", "y2"], "tolerance": 0.02, "label": f"both --> {SCRIPT}"}},
        }},
    }
    (root / "study.yaml").write_text(yaml.safe_dump(config, allow_unicode=True), encoding="utf-8")
    return config


@pytest.fixture(scope="module")
def hostile_study(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("hostile")
    _write_study(root)
    result = run_snakemake(root, root / "study.yaml", timeout=900)
    assert result.returncode == 0, result.stderr[-3000:]
    return root


@pytest.mark.workflow
def test_a_results_folder_holding_a_command_and_a_space_runs_nothing(hostile_study):
    results = hostile_study / SHELL_DIR
    assert (results / "figures" / "fig6_m.png").read_bytes() == (results / "figures" / "sets_m.png").read_bytes()
    assert (results / "figures" / "fig6_m.svg").is_file()
    assert not list(hostile_study.rglob(f"{MARK}_FILE")) and not (REPO / f"{MARK}_FILE").exists()


@pytest.mark.workflow
def test_report_of_hostile_labels_runs_nothing(hostile_study):
    html = (hostile_study / SHELL_DIR / "report" / "report.html").read_text(encoding="utf-8")
    assert _live_payloads(html) == []
    assert html.count(MARK) >= 10  # the labels are there, as text
    svgs = sorted((hostile_study / SHELL_DIR / "figures").glob("*.svg"))
    assert svgs
    for svg in svgs:  # labels reach SVG only as paths and escaped comments (`-->` in a label cannot end one)
        text = svg.read_text(encoding="utf-8")
        assert "<script" not in text and _live_payloads(text) == [], svg.name


@pytest.mark.workflow
def test_report_of_hostile_labels_in_chromium(hostile_study, tmp_path):
    from ..report.test_report_browser import _browser, _chromium

    browser = _browser()
    if browser is None:
        pytest.skip("no Chromium on this machine (install it with: apt-get install -y chromium)")
    report = hostile_study / SHELL_DIR / "report" / "report.html"
    dom = _chromium(browser, tmp_path, "--dump-dom", report.as_uri())
    assert "<title>" in dom.stdout, dom.stderr[-2000:]
    title = dom.stdout.split("<title>", 1)[1].split("</title>", 1)[0]
    assert MARK not in title
    # the same page with one live payload added does change the title: the check can fail
    live = tmp_path / "live.html"
    live.write_text(report.read_text(encoding="utf-8").replace("</body>", SCRIPT + "</body>"), encoding="utf-8")
    dom = _chromium(browser, tmp_path, "--dump-dom", live.as_uri())
    assert MARK in dom.stdout.split("<title>", 1)[1].split("</title>", 1)[0]


@pytest.mark.workflow
def test_a_table_edited_while_its_job_ran_is_rerun(hostile_study):
    """The edit leaves the table older than the outputs (as an edit during the job does): the next dry run
    plans the material's job again, because the rule carries the table's content digest."""
    data = hostile_study / "data" / "m.csv"
    before = os.stat(data)
    unchanged = run_snakemake(hostile_study, hostile_study / "study.yaml", "-n")
    assert "analyse_material" not in planned_jobs(unchanged.stdout), unchanged.stdout[-2000:]
    text = data.read_text(encoding="utf-8").splitlines()
    header, first = text[0].split(","), text[1].split(",")
    column = header.index("y1")
    first[column] = f"{float(first[column]) + 0.5:.3f}"
    data.write_text("\n".join([text[0], ",".join(first), *text[2:]]) + "\n", encoding="utf-8")
    os.utime(data, ns=(before.st_atime_ns, before.st_mtime_ns))  # as old as before the run
    edited = run_snakemake(hostile_study, hostile_study / "study.yaml", "-n")
    assert planned_jobs(edited.stdout).get("analyse_material") == 1, edited.stdout[-2000:]


# --------------------------------------------------------------------------- configs that would run code
YTE_CONFIG = f"""__use_yte__: true
results_dir: ?__import__("pathlib").Path("{MARK}_YTE").touch() or "results"
materials: {{}}
"""


def _snakemake(workdir: Path, *args: str) -> subprocess.CompletedProcess:
    cmd = [sys.executable, "-m", "snakemake", "-n", "-c1", "-s", str(REPO / "Snakefile"), "--directory",
           str(workdir), *args]
    env = dict(os.environ, PYTHONWARNINGS="ignore")
    return subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, timeout=300, env=env)


@pytest.mark.parametrize("how", ["configfile", "study folder"])
def test_a_templated_config_is_refused_before_it_runs(tmp_path, how):
    (tmp_path / "config.yaml").write_text(YTE_CONFIG.replace(MARK, str(tmp_path / MARK)), encoding="utf-8")
    args = ["--configfile", str(tmp_path / "config.yaml")] if how == "configfile" else []
    result = _snakemake(tmp_path, *args)
    assert result.returncode != 0
    assert not (tmp_path / f"{MARK}_YTE").exists(), "the template's expression ran"
    lines = [ln for ln in result.stderr.splitlines() if ln.startswith("demid: error:")]
    assert len(lines) == 1 and "__use_yte__" in lines[0] and "config.yaml" in lines[0], result.stderr[-2000:]


def test_validate_names_a_template_without_running_it(tmp_path):
    (tmp_path / "config.yaml").write_text(YTE_CONFIG.replace(MARK, str(tmp_path / MARK)), encoding="utf-8")
    line = _one_error_line(_demid(tmp_path, "validate", "--config", "config.yaml"))
    assert "__use_yte__" in line and not (tmp_path / f"{MARK}_YTE").exists()


def test_an_unknown_top_level_key_is_named_before_loading(tmp_path):
    (tmp_path / "config.yaml").write_text("results_dri: out\nmaterials: {}\n", encoding="utf-8")
    result = _snakemake(tmp_path, "--configfile", str(tmp_path / "config.yaml"))
    assert result.returncode != 0
    assert "demid: error:" in result.stderr and "results_dri" in result.stderr and "results_dir" in result.stderr


def test_a_config_not_in_utf8_is_one_line(tmp_path):
    (tmp_path / "config.yaml").write_bytes("results_dir: caf\u00e9\nmaterials: {}\n".encode("latin-1"))
    result = _snakemake(tmp_path, "--configfile", str(tmp_path / "config.yaml"))
    assert result.returncode != 0
    assert "Traceback" not in result.stderr
    assert any(ln.startswith("demid: error:") and "UTF-8" in ln for ln in result.stderr.splitlines())


def test_command_line_configfiles_are_found():
    from demid.config_text import configfiles_on_command_line

    argv = ["-n", "--configfile", "a.yaml", "b.yaml", "-c1", "--configfiles=c.yaml", "target", "--configfile", "d"]
    assert configfiles_on_command_line(argv) == ["a.yaml", "b.yaml", "c.yaml", "d"]


def test_no_rule_runs_a_shell():
    for rules in [REPO / "Snakefile", *sorted((REPO / "workflow" / "rules").glob("*.smk"))]:
        code = [ln.split("#", 1)[0] for ln in rules.read_text(encoding="utf-8").splitlines()]
        assert not any(re.match(r"\s*shell\s*:", ln) or "shell(" in ln for ln in code), rules.name


# --------------------------------------------------------------------------- --out
def _demid(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    return run_demid(*args, cwd=cwd)


@pytest.fixture
def table(tmp_path) -> Path:
    from ..helpers import make_ccd_table

    frame = make_ccd_table(lambda x: {"y": 3 + x[:, 0] + 2 * x[:, 1] + x[:, 0] ** 2}, [0, 0], [1, 1], noise=0.05,
                           seed=1, decimals=4)
    path = tmp_path / "data.csv"
    frame.to_csv(path, index=False)
    return path


COMMANDS = {
    "fit": ["fit", "--factors", "x1,x2", "--responses", "y"],
    "criticize": ["criticize", "--factors", "x1,x2", "--response", "y"],
    "check-transcription": ["check-transcription", "--factors", "x1,x2", "--response", "y",
                            "--published", "r2=0.99"],
}


@pytest.mark.parametrize("command", list(COMMANDS))
def test_out_onto_the_input_is_refused(table, command):
    before = table.read_bytes()
    result = _demid(table.parent, *COMMANDS[command], "--data", str(table), "--out", str(table), "--force")
    assert result.returncode == 2 and "input" in result.stderr and "Traceback" not in result.stderr
    assert table.read_bytes() == before
    link = table.parent / "link.csv"
    link.symlink_to(table)
    result = _demid(table.parent, *COMMANDS[command], "--data", str(link), "--out", "data.csv")
    assert result.returncode == 2 and table.read_bytes() == before


@pytest.mark.parametrize("command", list(COMMANDS))
def test_out_onto_a_foreign_file_needs_force_and_own_output_is_replaced(table, command):
    other = table.parent / "notes.json"
    other.write_text('{"mine": 1}\n', encoding="utf-8")
    result = _demid(table.parent, *COMMANDS[command], "--data", str(table), "--out", str(other))
    assert result.returncode == 2 and "--force" in result.stderr, result.stderr
    assert other.read_text(encoding="utf-8") == '{"mine": 1}\n'
    out = table.parent / "out.json"
    first = _demid(table.parent, *COMMANDS[command], "--data", str(table), "--out", str(out))
    assert first.returncode == 0, first.stderr
    again = _demid(table.parent, *COMMANDS[command], "--data", str(table), "--out", str(out))
    assert again.returncode == 0, again.stderr  # its own output: replaced without --force
    forced = _demid(table.parent, *COMMANDS[command], "--data", str(table), "--out", str(other), "--force")
    assert forced.returncode == 0 and "mine" not in other.read_text(encoding="utf-8")


@pytest.mark.parametrize("target", ["/dev/null", "folder", "fifo"])
def test_out_onto_a_device_folder_or_pipe_is_refused(table, target):
    if target == "folder":
        (table.parent / "folder").mkdir()
    elif target == "fifo":
        os.mkfifo(table.parent / "fifo")
    for command in COMMANDS:
        result = _demid(table.parent, *COMMANDS[command], "--data", str(table), "--out", target, "--force")
        assert result.returncode == 2 and "Traceback" not in result.stderr, result.stderr
    result = _demid(table.parent, "design", "--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1",
                    "--out", target, "--force")
    assert result.returncode == 2, result.stderr
    if target == "/dev/null":
        assert Path("/dev/null").is_char_device()
    else:
        assert not (table.parent / target).is_file()


def test_design_out_onto_a_filled_in_sheet_is_refused(tmp_path):
    args = ["design", "--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1", "--response", "y",
            "--out", "sheet.csv", "--config-out", "frag.yaml"]
    assert _demid(tmp_path, *args).returncode == 0
    assert _demid(tmp_path, *args).returncode == 0  # the unfilled sheet and fragment it wrote: replaced
    sheet = tmp_path / "sheet.csv"
    lines = sheet.read_text(encoding="utf-8").splitlines()
    filled = [lines[0]] + [f"{ln}{100 + i * 1.37:.2f}" for i, ln in enumerate(lines[1:])]
    sheet.write_text("\n".join(filled) + "\n", encoding="utf-8")
    result = _demid(tmp_path, *args)
    assert result.returncode == 2 and "sheet.csv" in result.stderr and "--force" in result.stderr
    assert sheet.read_text(encoding="utf-8") == "\n".join(filled) + "\n"
    frag = tmp_path / "frag.yaml"
    frag.write_text(frag.read_text(encoding="utf-8").replace("y: {}", "y: {target: 3}"), encoding="utf-8")
    result = _demid(tmp_path, *[a if a != "sheet.csv" else "sheet2.csv" for a in args])
    assert result.returncode == 2 and "frag.yaml" in result.stderr


def test_no_stray_files_after_a_refusal(tmp_path):
    shutil.copy(REPO / "config.yaml", tmp_path / "config.yaml")
    result = _demid(tmp_path, "design", "--type", "ccd", "--factor", "a=0:1", "--factor", "b=0:1",
                    "--out", "config.yaml")
    assert result.returncode == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["config.yaml"]


# --------------------------------------------------------------------------- numbers, sizes and formats
def _plain_study(root: Path, **material) -> Path:
    """A valid two-factor study (data/m.csv, study.yaml) with ``material`` keys replaced; returns the config."""
    from ..helpers import make_ccd_table

    frame = make_ccd_table(lambda x: {"y1": 100 + 20 * x[:, 0] - 2 * x[:, 1] + 10 * x[:, 0] ** 2,
                                      "y2": 80 + 5 * x[:, 0] + 3 * x[:, 1]}, [0.1, 1.0], [0.9, 11.0], noise=0.3,
                           seed=3, decimals=3)
    (root / "data").mkdir(exist_ok=True)
    frame.rename(columns={"x1": "a", "x2": "b"}).to_csv(root / "data" / "m.csv", index=False)
    config = {"materials": {"m": {
        "data": "data/m.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {"a": {"lower": 0.1, "upper": 0.9}, "b": {"lower": 1.0, "upper": 11.0}},
        "responses": {"y1": {"target": 115}, "y2": {"target": 95}},
        "scenarios": {"both": {"observables": ["y1", "y2"], "tolerance": 0.02}}, **material}}}
    path = root / "study.yaml"
    path.write_text(yaml.safe_dump(config), encoding="utf-8")
    return path


def _set_response(root: Path, run_index: int, column: str, value: str) -> None:
    path = root / "data" / "m.csv"
    lines = path.read_text(encoding="utf-8").splitlines()
    header = lines[0].split(",")
    cells = lines[run_index].split(",")
    cells[header.index(column)] = value
    lines[run_index] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def _one_error_line(result: subprocess.CompletedProcess) -> str:
    assert result.returncode != 0, result.stdout[-1000:]
    assert "Traceback" not in result.stderr, result.stderr[-3000:]
    lines = [ln for ln in result.stderr.splitlines() if ln.startswith("demid: error:")]
    assert len(lines) == 1, result.stderr[-3000:]
    assert len(lines[0]) <= 520, len(lines[0])
    return lines[0]


@pytest.mark.parametrize("cell", ["5e-324", "1e5000", "-1e5000", "1e308", "-1e308", "1e-400", "1e31"])
def test_an_unusable_number_in_a_table_is_one_line(tmp_path, cell):
    config = _plain_study(tmp_path)
    _set_response(tmp_path, 3, "y1", cell)
    line = _one_error_line(_demid(tmp_path, "validate", "--config", str(config)))
    assert "m.csv" in line and "column 'y1'" in line and cell in line and "run " in line, line
    result = _demid(tmp_path, "criticize", "--data", "data/m.csv", "--factors", "a,b", "--response", "y1",
                    "--out", "c.json")
    assert "y1" in _one_error_line(result) and not (tmp_path / "c.json").exists()


@pytest.mark.workflow  # runs Snakemake
def test_an_unusable_number_stops_the_workflow_in_the_material_job(tmp_path):
    """A table's cells are checked once, in the material's job (start-up reads its header only): the run
    stops there with one line naming the cell, and leaves no results behind."""
    config = _plain_study(tmp_path)
    _set_response(tmp_path, 2, "y2", "1e308")
    cmd = [sys.executable, "-m", "snakemake", "-c1", "-s", str(REPO / "Snakefile"), "--directory", str(tmp_path),
           "--configfile", str(config)]
    result = subprocess.run(cmd, cwd=tmp_path, capture_output=True, text=True, timeout=300,
                            env=dict(os.environ, PYTHONWARNINGS="ignore"))
    line = _one_error_line(result)
    assert "column 'y2'" in line and "1e308" in line and "run 2" in line
    results = tmp_path / "results"  # nothing but the mark naming the study whose results it holds (and logs)
    assert (results / ".demid_study").is_file() and not written_results(results)


@pytest.mark.parametrize("key, value", [
    ("factors", {"a": {"lower": -1e308, "upper": 1e308}, "b": {"lower": 1.0, "upper": 11.0}}),
    ("responses", {"y1": {"target": 1e308}, "y2": {"target": 95}}),
    ("responses", {"y1": {"target": 5e-324}, "y2": {"target": 95}}),
    ("reference_point", {"a": 0.5, "b": 1e300}),
    ("next_runs", {"count": 10**9}),
    ("next_runs", {"count": 10**50}),
])
def test_an_unusable_number_in_a_config_names_the_key(tmp_path, key, value):
    config = _plain_study(tmp_path, **{key: value})
    line = _one_error_line(_demid(tmp_path, "validate", "--config", str(config)))
    assert f"materials.m.{key}" in line, line


@pytest.mark.parametrize("levels", [6, 9])
def test_a_billion_laughs_label_gives_a_short_line_at_once(tmp_path, levels):
    """Nine aliases a level: six levels expand to half a million values, nine (a 1 KB file) to 387
    million; either is refused from the composed document, before any value is built."""
    import time

    config = _plain_study(tmp_path)
    text = config.read_text(encoding="utf-8")
    laughs = ("lol0: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n"
              + "".join(f"lol{i}: &{chr(97 + i)} [" + ", ".join([f"*{chr(96 + i)}"] * 9) + "]\n"
                        for i in range(1, levels)))
    config.write_text(laughs + text.replace("materials:\n  m:\n", f"materials:\n  m:\n    label: *{chr(96 + levels)}\n",
                                            1), encoding="utf-8")
    assert len(config.read_bytes()) < 1500
    started = time.monotonic()
    try:
        result = subprocess.run([sys.executable, "-m", "demid", "validate", "--config", str(config)],
                                capture_output=True, text=True, cwd=tmp_path, timeout=30,
                                env=dict(os.environ, PYTHONWARNINGS="ignore"))
    except subprocess.TimeoutExpired:
        pytest.fail("no answer within 30 s")
    line = _one_error_line(result)
    assert "aliases (*name) expand the document to" in line and "write the values out" in line, line
    assert time.monotonic() - started < 30


def test_a_million_character_cell_is_one_line(tmp_path):
    config = _plain_study(tmp_path)
    _set_response(tmp_path, 4, "y1", "9" * 1_000_000)
    line = _one_error_line(_demid(tmp_path, "validate", "--config", str(config)))
    assert "m.csv" in line
    _set_response(tmp_path, 4, "y1", "1" + "0" * 100_000)
    line = _one_error_line(_demid(tmp_path, "validate", "--config", str(config)))
    assert "column 'y1'" in line and "characters left out" in line


@pytest.mark.workflow  # runs Snakemake
def test_valid_csv_with_a_quoted_line_break_and_yaml_merge_keys_are_accepted(tmp_path):
    config = _plain_study(tmp_path)
    data = tmp_path / "data" / "m.csv"
    lines = data.read_text(encoding="utf-8").splitlines()
    lines[0] += ",note"
    lines[1:] = [ln + (',"first line\nsecond, with a comma"' if i == 2 else ",plain") for i, ln in enumerate(lines[1:])]
    data.write_text("\n".join(lines) + "\n", encoding="utf-8")
    config.write_text(
        "materials:\n"
        "  m:\n    data: data/m.csv\n    design: {type: ccd, alpha: 1.41421, center_runs: 5}\n"
        "    factors: &factors\n      a: {lower: 0.1, upper: 0.9}\n      b: {lower: 1.0, upper: 11.0}\n"
        "    responses: {y1: {target: 115}, y2: {target: 95}}\n"
        "    scenarios: {both: {observables: [y1, y2], tolerance: 0.02}}\n"
        "  n:\n    data: data/m.csv\n    design: {type: ccd, alpha: 1.41421, center_runs: 5}\n"
        "    factors:\n      <<: *factors\n      b: {lower: 1.0, upper: 11.0, unit: mm}\n"
        "    responses: {y1: {target: 115}, y2: {target: 95}}\n"
        "    scenarios: {both: {observables: [y1, y2], tolerance: 0.02}}\n", encoding="utf-8")
    result = _demid(tmp_path, "validate", "--config", str(config))
    assert result.returncode == 0, result.stderr
    assert "2 table(s) valid" in result.stdout
    assert _snakemake(tmp_path, "--configfile", str(config)).returncode == 0


@pytest.mark.workflow  # runs Snakemake
def test_a_results_dir_naming_a_file_is_one_line(tmp_path):
    config = _plain_study(tmp_path)
    (tmp_path / "taken").write_text("mine\n", encoding="utf-8")
    for results_dir in ["taken", "taken/results"]:
        text = yaml.safe_load(config.read_text(encoding="utf-8"))
        config.write_text(yaml.safe_dump({**text, "results_dir": results_dir}), encoding="utf-8")
        line = _one_error_line(_snakemake(tmp_path, "--configfile", str(config)))
        assert "results_dir" in line and "'taken'" in line, line
    assert (tmp_path / "taken").read_text(encoding="utf-8") == "mine\n"


@pytest.mark.workflow
def test_a_second_run_in_the_same_folder_names_the_lock(tmp_path):
    import time

    config = _plain_study(tmp_path)
    cmd = [sys.executable, "-m", "snakemake", "-c1", "--configfile", str(config), "--directory", str(tmp_path)]
    env = dict(os.environ, PYTHONWARNINGS="ignore")
    first = subprocess.Popen(cmd, cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
    locks = tmp_path / ".snakemake" / "locks"
    try:
        deadline = time.monotonic() + 120
        while not (locks.is_dir() and any(locks.iterdir())) and time.monotonic() < deadline:
            time.sleep(0.2)
        assert first.poll() is None and any(locks.iterdir()), "the first run ended before the second started"
        second = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True, env=env, timeout=300)
        line = _one_error_line(second)
        assert "another run" in line and ".snakemake/locks" in line and "--unlock" in line, line
    finally:
        _, err = first.communicate(timeout=900)
    assert first.returncode == 0, err[-2000:]  # the first run was not disturbed
    assert (tmp_path / "results" / "report" / "report.html").is_file()
    # a stale lock (a killed run) is named too; --unlock clears it
    locks.mkdir(parents=True, exist_ok=True)
    (locks / "0.output.lock").write_text("x", encoding="utf-8")
    assert "--unlock" in _one_error_line(run_snakemake(tmp_path, config))
    assert run_snakemake(tmp_path, config, "--unlock").returncode == 0
    assert run_snakemake(tmp_path, config).returncode == 0


@pytest.mark.workflow  # runs Snakemake
@pytest.mark.parametrize("how", ["absolute", "relative", "symlink"])
def test_a_table_outside_the_study_is_never_echoed(tmp_path, how):
    study = tmp_path / "study"
    study.mkdir()
    config = _plain_study(study)
    secret = tmp_path / "secret.txt"
    secret.write_text("SECRET-FIRST-LINE:hunter2\nsecond:SECRET-SECOND\n", encoding="utf-8")
    data = {"absolute": str(secret), "relative": "../secret.txt", "symlink": "data/link.csv"}[how]
    if how == "symlink":
        (study / "data" / "link.csv").symlink_to(secret)
    text = yaml.safe_load(config.read_text(encoding="utf-8"))
    text["materials"]["m"]["data"] = data
    config.write_text(yaml.safe_dump(text), encoding="utf-8")
    for result in (_demid(study, "validate", "--config", str(config)), _snakemake(study, "--configfile", str(config))):
        line = _one_error_line(result)
        assert "outside the study folder" in line and "its content is not shown" in line, line
        assert "SECRET" not in result.stderr + result.stdout and "hunter2" not in result.stderr + result.stdout


def test_a_table_in_utf16_without_a_byte_order_mark_is_named_as_such(tmp_path):
    config = _plain_study(tmp_path)
    data = tmp_path / "data" / "m.csv"
    data.write_bytes(data.read_text(encoding="utf-8").encode("utf-16-le"))
    line = _one_error_line(_demid(tmp_path, "validate", "--config", str(config)))
    assert "UTF-16 without a byte-order mark" in line and "save the table as UTF-8" in line, line
    assert "misspel" not in line


def test_a_line_separator_inside_a_cell_does_not_split_its_row(tmp_path):
    config = _plain_study(tmp_path)
    data = tmp_path / "data" / "m.csv"
    lines = data.read_text(encoding="utf-8").splitlines()
    lines[0] += ",note"
    lines[1:] = [ln + (",first\u2028second\u0085third\x0cfourth" if i == 2 else ",plain") for i, ln in enumerate(lines[1:])]
    data.write_text("\n".join(lines) + "\n", encoding="utf-8")
    result = _demid(tmp_path, "validate", "--config", str(config))
    assert result.returncode == 0, result.stderr
    assert "1 table(s) valid" in result.stdout


@pytest.mark.workflow  # runs Snakemake
@pytest.mark.parametrize("change, key, named", [
    (lambda mats: mats.update(m_transcription=dict(mats["m"])), "config key materials.m:",
     "'m_transcription' and 'm' both give results/validated/m_transcription.parquet"),
    (lambda mats: mats["m"].update(paper_figure="surface"), "config key materials.m.paper_figure:",
     "gives results/figures/surface_m.png"),
    (lambda mats: mats.update(sets_m=dict(mats["m"], paper_figure="sets")), "config key materials.sets_m.paper_figure:",
     "gives results/figures/sets_sets_m.png"),
])
def test_names_that_make_two_rules_write_one_file_name_the_config_key(tmp_path, change, key, named):
    config = _plain_study(tmp_path)
    text = yaml.safe_load(config.read_text(encoding="utf-8"))
    change(text["materials"])
    config.write_text(yaml.safe_dump(text), encoding="utf-8")
    line = _one_error_line(_snakemake(tmp_path, "--configfile", str(config)))
    assert key in line and named in line, line


@pytest.mark.workflow  # runs Snakemake
def test_two_studies_sharing_one_results_dir_the_second_is_refused(tmp_path):
    from demid.out_path import STUDY_MARKER, claim_results_dir, results_owner_problem

    shared = tmp_path / "shared results"
    first, second = tmp_path / "first", tmp_path / "second"
    for study in (first, second):
        study.mkdir()
        config = _plain_study(study)
        text = yaml.safe_load(config.read_text(encoding="utf-8"))
        config.write_text(yaml.safe_dump({**text, "results_dir": str(shared)}), encoding="utf-8")
    assert claim_results_dir(shared, first) == "" and claim_results_dir(shared, first) == ""  # its own, again
    assert (shared / STUDY_MARKER).read_text(encoding="utf-8") == f"{first.resolve()}\n"
    assert f"holds the results of the study in {first.resolve()}" in claim_results_dir(shared, second)
    for args in (("-n",), ()):  # a dry run, and a run (the default helper runs dry)
        cmd = [sys.executable, "-m", "snakemake", *args, "-c1", "-s", str(REPO / "Snakefile"), "--directory",
               str(second), "--configfile", str(second / "study.yaml")]
        result = subprocess.run(cmd, cwd=second, capture_output=True, text=True, timeout=300,
                                env=dict(os.environ, PYTHONWARNINGS="ignore"))
        line = _one_error_line(result)
        assert "config key results_dir" in line and str(first.resolve()) in line, line
    assert not [p for p in shared.rglob("*") if p.name != STUDY_MARKER]
    assert _snakemake(first, "--configfile", str(first / "study.yaml")).returncode == 0
    shutil.rmtree(first)  # a study gone leaves its claim: the other may take the folder over
    assert results_owner_problem(shared, second) == "" and claim_results_dir(shared, second) == ""
    assert (shared / STUDY_MARKER).read_text(encoding="utf-8") == f"{second.resolve()}\n"
    # a study folder copied with its results inside: the copy's results are its own, the original's claim aside
    inside = tmp_path / "own" / "results"
    assert claim_results_dir(inside, tmp_path / "own") == ""
    shutil.copytree(tmp_path / "own", tmp_path / "own copy")
    assert claim_results_dir(tmp_path / "own copy" / "results", tmp_path / "own copy") == ""
    assert (tmp_path / "own copy" / "results" / STUDY_MARKER).read_text(encoding="utf-8") == \
        f"{(tmp_path / 'own copy').resolve()}\n"
