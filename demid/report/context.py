"""What every section of the report reads with: the results folder, the config, each material's spec (built
once), tables and JSON files of the results tree, and text and figures as sanitised HTML.

:class:`ReportContext` only reads and renders; the sections (:mod:`.summary`, :mod:`.study`, :mod:`.material`,
:mod:`.model_criticism`, :mod:`.plausible`, :mod:`.loop`, :mod:`.surfaces`, :mod:`.glossary`) are functions of
it, composed by :class:`~demid.report.sections.ReportSections`.
"""

from __future__ import annotations

from functools import cached_property
from pathlib import Path

import pandas as pd

from ..io import FIGURE_DPI
from .markdown import typeset_labels


class ReportContext:
    """The results folder and config of one report, read once; optional parts are skipped by the sections."""

    def __init__(self, results_dir: str, config: dict):
        self.root = Path(results_dir)
        self.config = config
        self.materials = list(config.get("materials", {}))

    def md(self, text: str):
        """Report text (Markdown, labels typeset) as sanitised HTML: whatever a config puts in it is shown,
        never run."""
        from IPython.display import HTML

        from .safe_html import markdown_html

        return HTML(self._unique_anchors(markdown_html(typeset_labels(text, self.plain_labels))))

    def _unique_anchors(self, html: str) -> str:
        """Heading anchors made unique over the whole report: the second "What the model gets wrong" becomes
        ``…-2`` (its link with it), so an in-page link never lands on the first material's heading."""
        import re

        used = self.__dict__.setdefault("_anchors", {})

        def renamed(match: re.Match) -> str:
            anchor = match.group(2)
            used[anchor] = used.get(anchor, 0) + 1
            if used[anchor] == 1:
                return match.group(0)
            new = f"{anchor}-{used[anchor]}"
            return match.group(0).replace(f'id="{anchor}"', f'id="{new}"').replace(f'href="#{anchor}"', f'href="#{new}"')

        return re.sub(r'<(h[1-6]) id="([^"]+)">.*?</\1>', renamed, html, flags=re.S)

    @cached_property
    def plain_labels(self) -> list[str]:
        """Every configured factor/response label and unit, longest first (so d_10 wins over d_1)."""
        found = set()
        for material in self.config.get("materials", {}).values():
            for group in ("factors", "responses"):
                for item in (material.get(group) or {}).values():
                    found.update(t for t in (item.get("label"), item.get("unit")) if t)
        return sorted(found, key=len, reverse=True)

    def image(self, path: Path, alt: str = ""):
        """The PNG inline at the page's full width, with alt text and a link to its SVG twin."""
        import base64
        import html

        from IPython.display import HTML

        from .safe_html import sanitize

        if not path.is_file():
            return self.md(f"_(missing figure {path.name})_")
        raw = path.read_bytes()
        data = base64.b64encode(raw).decode("ascii")
        # Print size at 96 CSS px per inch (the PNG's width in pixels over its dpi), narrowed to the page:
        # every figure's text then appears at about the same size.
        css_px = round(int.from_bytes(raw[16:20], "big") / FIGURE_DPI * 96)
        alt = html.escape(alt or path.stem.replace("_", " "), quote=True)
        return HTML(sanitize(f'<figure style="margin:0"><img src="data:image/png;base64,{data}" alt="{alt}" '
                    f'style="width:{css_px}px;max-width:100%;height:auto"><figcaption style="font-size:small">'
                    f'{alt} — vector version: <code>figures/{path.stem}.svg</code></figcaption></figure>', figure=True))

    def speak(self, text: str, m: str) -> str:
        """``text`` with the material's factor, response and scenario keys written as their labels (a key
        inside a config path or a file name stays)."""
        import re

        from ..story.words import labelled

        spec = self.specs()[m]
        text = labelled(text, spec)
        names = {sc.name: sc.label for sc in spec.scenarios if sc.label and sc.label != sc.name}
        if not names or not text:
            return text
        keys = "|".join(re.escape(k) for k in sorted(names, key=len, reverse=True))
        return re.sub(r"(?<![\w./`'])'?(" + keys + r")'?(?![\w`]|\.\w)", lambda k: names[k.group(1)], text)

    def paper(self, what: str) -> str:
        """`` (paper Table 2)`` where published numbers are declared, else nothing: headings stay generic."""
        return f" (paper {what})" if self.config.get("published") else ""

    def csv(self, name: str) -> pd.DataFrame | None:
        """``tables/{name}``, or None where the study wrote no such table."""
        path = self.root / "tables" / name
        return pd.read_csv(path) if path.is_file() else None

    def label(self, material: str) -> str:
        """The material's configured label."""
        return self.specs()[material].label

    def specs(self) -> dict:
        """Each material's spec, built once for the report."""
        if getattr(self, "_spec_cache", None) is None:
            from ..spec import MaterialSpec

            self._spec_cache = {m: MaterialSpec.from_material(m, entry)
                                for m, entry in self.config["materials"].items()}
        return self._spec_cache

    @staticmethod
    def json(path: Path) -> dict:
        """A JSON file of the results tree, or an empty dict where there is none."""
        import json

        return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}

