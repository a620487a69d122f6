"""demid: which experiments identify the DEM micro-parameters, and what the simulation gets wrong.

The per-material steps, in pipeline order, each taking a :class:`MaterialSpec`:
``validate_material`` → ``check_material`` → ``fit_material`` → ``evaluate_scenarios`` /
``pareto_analysis`` / ``analyse_material`` / ``criticize_material``.  Names load on first use
(PEP 562), so ``import demid`` stays cheap for every pipeline job.
"""

from .lazy import lazy_exports

__version__ = "0.1.0"

_WHERE = {
    "MaterialSpec": ".spec", "load_config": ".config", "InputError": ".errors", "validate_material": ".data",
    "check_material": ".transcription", "fit_material": ".surrogate", "evaluate_scenarios": ".admissibility",
    "pareto_analysis": ".pareto", "analyse_material": ".uncertainty", "criticize_material": ".criticism",
}

__getattr__, __all__ = lazy_exports(__name__, _WHERE)
