"""Cross-material tables and the HTML report.

``tables`` (the CSVs under tables/), ``sections`` (the report's text, read by the
notebook; one module per section, see its docstring) and ``render`` (papermill execution and HTML).  Names are imported from their
submodule on first use (PEP 562): the report job's own process only executes and renders the
notebook (the kernel builds the sections), so it does not import pandas and the sections for nothing.
"""

from ..lazy import lazy_exports

_WHERE = {
    "execute_report": ".render", "render_html": ".render",
    "ReportSections": ".sections", "markdown_table": ".markdown",
    "IDENTIFIABILITY_COLUMNS": ".tables", "SURROGATE_FIT_COLUMNS": ".tables", "TRANSCRIPTION_COLUMNS": ".tables",
    "identifiability_table": ".tables", "pareto_intervals": ".tables", "stack_material_tables": ".tables",
    "summary_tables": ".tables", "surrogate_fit_table": ".tables",
}

__getattr__, __all__ = lazy_exports(__name__, _WHERE)
