"""The HTML report's parts in reading order: one method per section, each laid out by the module of its section.

The sections only render what the results tree holds; the verdicts and the advice they show are
:mod:`demid.story`'s.  Where each section is written:

- :mod:`.study`: the header, surrogate fidelity, the admissible sets, extending the model, the published numbers;
- :mod:`.summary`: the answer per material (recommended point, verdicts, criticism in a line, next step);
- :mod:`.material`: a material's table check, its sets and surfaces drawn, its Pareto trade-off;
- :mod:`.model_criticism`: what the model gets wrong (levels 1 and 2);
- :mod:`.plausible`: strict against plausible sets, the tolerance sweep, the observable ranking;
- :mod:`.loop`: the simulated waves and what to simulate next;
- :mod:`.surfaces`: the response-surface models and residual diagnostics;
- :mod:`.glossary`: the terms.

:class:`~demid.report.context.ReportContext` reads the results tree for all of them.
"""

from __future__ import annotations

from . import glossary, loop, material, model_criticism, plausible, study, summary, surfaces
from .context import ReportContext
from .markdown import markdown_table, typeset_labels
from .plausible import ranking_display

__all__ = ["ReportSections", "markdown_table", "ranking_display", "typeset_labels"]


class ReportSections(ReportContext):
    """Builds the report's displayable parts from the results folder; optional parts are skipped."""

    def all(self) -> list:
        parts = self.header()
        parts += self.summary()
        parts += self.surrogate_fit()
        parts += self.identifiability()
        for m in self.materials:
            parts += self.material(m)
        parts += self.model_extensions()
        parts += self.glossary()
        parts += self.paper_comparison()
        return parts

    def material(self, m: str) -> list:
        """One material's sections, from its table check to its residual diagnostics."""
        parts = [self.md(f"## {self.label(m)}")]
        parts += material.table_check(self, m)
        parts += material.figures(self, m)
        parts += material.pareto(self, m)
        parts += self.waves(m)
        parts += self.criticism(m)
        parts += self.uncertainty(m)
        parts += self.next_wave(m)
        parts += self.response_surfaces(m)
        parts += surfaces.diagnostics(self, m)
        return parts

    # the study's sections
    def header(self) -> list:
        return study.header(self)

    def summary(self) -> list:
        return summary.summary(self)

    def surrogate_fit(self) -> list:
        return study.surrogate_fit(self)

    def identifiability(self) -> list:
        return study.identifiability(self)

    def model_extensions(self) -> list:
        return study.model_extensions(self)

    def glossary(self) -> list:
        return glossary.glossary(self)

    def paper_comparison(self) -> list:
        return study.paper_comparison(self)

    # a material's sections
    def waves(self, m: str) -> list:
        return loop.waves(self, m)

    def criticism(self, m: str) -> list:
        return model_criticism.criticism(self, m)

    def uncertainty(self, m: str) -> list:
        return plausible.uncertainty(self, m)

    def next_wave(self, m: str) -> list:
        return loop.next_wave(self, m)

    def response_surfaces(self, m: str) -> list:
        return surfaces.response_surfaces(self, m)
