"""Cross-material tables and the HTML report.

``tables`` (the CSVs under tables/), ``sections`` (the report's text, read by the
notebook) and ``render`` (papermill execution and HTML).
"""

from .render import execute_report, render_html
from .sections import ReportSections, markdown_table
from .tables import (IDENTIFIABILITY_COLUMNS, SURROGATE_FIT_COLUMNS, TRANSCRIPTION_COLUMNS, identifiability_table,
                     pareto_intervals, stack_material_tables, summary_tables, surrogate_fit_table)

__all__ = ["IDENTIFIABILITY_COLUMNS", "SURROGATE_FIT_COLUMNS", "TRANSCRIPTION_COLUMNS", "ReportSections",
           "execute_report", "identifiability_table", "markdown_table", "pareto_intervals", "render_html",
           "stack_material_tables", "summary_tables", "surrogate_fit_table"]
