"""Every figure of the pipeline, one module per kind.

``sets`` (admissible sets), ``surface`` (response surfaces), ``pareto`` (trade-off),
``uncertainty`` (sweep and posteriors), ``criticism`` (residuals); ``style`` holds the
backend, rcParams and colours of the first three.  Submodules are imported on first use
(PEP 562), so importing one kind of figure does not apply another kind's style.
"""

from ..lazy import lazy_exports

_WHERE = {
    "sets_figure": ".sets", "surface_figure": ".surface", "surface_figure_from_surrogates": ".surface",
    "pareto_figure": ".pareto", "tolerance_sweep_figure": ".uncertainty", "posterior_figure": ".uncertainty",
    "residual_figure": ".criticism", "combinations_figure": ".combinations",
}

__getattr__, __all__ = lazy_exports(__name__, _WHERE)
