"""Model criticism: show what a model gets wrong, name the cause, extend the model, measure the gain.

Level 1 (:func:`criticize`) confronts the quadratic surrogate with the simulation
runs of one response.  A fixed catalogue of causes is tested, each with a
concrete one-parameter extension:

``missing_term``        one extra third-order term (pure cubic ``a^3``, mixed ``a^2:b``,
                        ``a:b:c``); added-variable F-test.  Terms that the design cannot
                        tell apart (their columns coincide once the quadratic is fitted,
                        e.g. ``b^3`` and ``a^2:b`` in a CCD) form one alias set, tested once;
                        :func:`separating_runs` proposes the extra runs that would split it.
``response_transform``  Box-Cox profile likelihood ratio of lambda against lambda = 1;
                        extension: the quadratic on the transformed scale, back-transformed.
``outlier``             largest externally studentised residual, Bonferroni over runs;
                        extension: refit without that run (a mean shift for it).
``drift``               a linear term in run order (``run`` column); added-variable F-test.
``step``                a shift between two consecutive groups of runs in run order (a change-point, at
                        least two runs each side; the same run-order gate as drift): largest
                        added-variable F over the change-points; extension: a step term, ``detail``
                        the first run after the shift.  Between a drift and a step the better fit
                        is named, the step paying log C for its change-point.
``heteroscedasticity``  likelihood ratio of a log-linear variance, var = s^2 exp(g v), with
                        v each factor and the fitted values; extension: maximum-likelihood WLS.
``factor_level``        a run whose response fits another value of one factor (a unit or decimal
                        slip in the simulation input, x 10^+-1..3, within twice the design's reach):
                        largest drop of the residual sum of squares when the run is moved, null by a
                        parametric bootstrap sharing the family's draws; named over an outlier when
                        its Bayes factor against a shift of the run is at least 1; extension: the
                        run at the value that fits (no added parameter).
``lack_of_fit``         (a misfit test, no cause) F of lack of fit against pure error of replicated runs.

Honest causes (:mod:`.verdict`).  Misfit that no cause answers (only lack of fit fired, or only a slip
too weak to name), or misfit left after the named extensions (the family run again on the extended
model, at 1 %): the cause is ``unexplained``, with the tests that fired.  Every
response gets a verdict: ``adequate`` (with the size of defect the tests find with 80 % power),
``defect``, ``unexplained``, ``ambiguous`` or ``does_not_predict`` (Q^2 < 0).

Ambiguous causes (:mod:`.discrimination`).  When the cause named first (or the candidate not singled out
for a rival) does not lead every catalogue cause of another kind by 6 in AICc (an evidence ratio of 20:1;
a drift and a step, and steps at different change-points, are different kinds), none is named: the
verdict is ``ambiguous`` with ``candidates`` and up to four ``discriminating_runs`` (where their
predictions, made later in run order, differ most relative to their prediction error).  A named cause
carries ``discriminating_runs`` that would confirm it against its nearest rivals (a next wave makes those
inside its box, after the deciding runs: ``runs_for_next_wave``; with ``run_candidates``, the next box's
grid, every run is chosen there); an outlier and a slipped
factor value of the same run list each other as ``aliases`` (no further run tells them apart).

Blocks (:mod:`demid.blocks`).  With a ``block`` column every model carries effect-coded block terms
(predictions at the mean block effect) and pure error is taken within blocks.

Family-wise error.  The catalogue is one family.  Every statistic except
Box-Cox's is a function of the error vector alone, whose distribution (normal
errors, the current model true) is known exactly for the design, so the joint
null is simulated and the Westfall-Young step-down min-P procedure gives
family-adjusted p-values: exact, aware of the tests' correlation (a factor and
the fitted values overlap as variance covariates), never less powerful than
Holm.  Box-Cox's null depends on the unknown mean, so its p-value comes from a
parametric bootstrap of the fitted model (conditional on positive responses) and
it joins the family as an independent uniform, which is conservative when it
correlates positively with the others.  A clean table yields a finding with
probability at most ``family_alpha``.  Where replicated runs give pure error, the
classical lack-of-fit test holds ``LOF_SHARE`` (65 %) of the level and the specific tests
share the rest (weighted min-P), so that the family detects misfit as often as the
lack-of-fit test alone.

Naming.  A cause is named only when it is singled out: its test is more significant
(nominal p) than lack of fit and every test of another kind, or its p-value is below
``OVERWHELMING_P``; otherwise the misfit is ``unexplained`` and the message names the
candidate and its rival.  The rejected cause with the smallest nominal p-value is named, except
that one wild run may read as an outlier or as scatter growing towards its
corner of the design: between those two (and between variance covariates) the
better-fitting extension (higher likelihood) is named.  Its extension is added and
the rest of the catalogue is tested again on the extended model, at most
``max_findings`` rounds; a later finding must also lower the leave-one-out
error, and nothing is tested after a weighted fit (its weights are estimates).

Gain, on the original response scale: leave-one-out RMSE from the exact PRESS
residuals (a transformed fit's leave-one-out prediction is back-transformed;
Box-Cox lambda and variance weights are held at their full-data estimates), and
AICc from the Gaussian likelihood of all n original observations (Jacobian for
transforms, the variance parameter for weights, one mean-shift parameter per
excluded run).  When a run is excluded, leave-one-out errors of the model before
and after are compared on the remaining runs only.

Level 2 (:func:`calibration_check`) confronts the calibrated simulation with the
experiment: the best point in the domain, the errors there and at the reference
point, the bottleneck observable, and bias (discrepancy) extensions with their
cost in parameters and what the measurements can and cannot identify.

Modules: ``models`` (the public core: :class:`~.models.Data`, :class:`~.models.ModelForm`,
:class:`~.models.Model`, the extended surrogate), ``aliasing``, ``catalogue`` (the causes and their
family-wise test, one :class:`~.catalogue.Round` per model), ``slips`` (slipped factor values),
``extensions`` (each cause's extension), ``naming`` (which cause is named, and the runs that would decide),
``level1``, ``level2`` with ``searches`` (its best point, shared bias and bottleneck), ``messages``
(findings in words), ``verdict`` (what the evidence supports) and ``material`` (the per-material step);
the figure is :mod:`demid.plots.criticism`.

Verified against statsmodels (``compare_f_test``, ``outlier_test``, OLS/WLS
log-likelihoods, influence PRESS residuals, ``eval_measures.aicc``) and scipy
(``special.boxcox``, ``optimize``) in ``tests/criticism/test_criticism.py``; power and
false-alarm rates against oracle tests in ``benchmarks/criticism_power.py``.
"""

from ..lazy import lazy_exports

# Names are imported from their submodule on first use (PEP 562): a module that needs one light part
# (demid.story reads .reach) does not pay for the figure's matplotlib and scipy.stats, nor for statsmodels.
_WHERE = {
    "residual_figure": "..plots.criticism",
    "AliasSet": ".aliasing", "separating_runs": ".aliasing",
    "CAUSES": ".catalogue", "Hypothesis": ".catalogue", "Round": ".catalogue",
    "CriticismResult": ".level1", "Finding": ".level1", "criticize": ".level1",
    "Level2Result": ".level2", "calibration_check": ".level2",
    "MaterialCriticism": ".material", "criticize_material": ".material", "reference_point_position": ".material",
    "TRANSFORM_NAMES": ".models", "Data": ".models", "ExtendedSurrogate": ".models", "Model": ".models",
    "ModelForm": ".models", "infer_axial_distance": ".models",
}

__getattr__, __all__ = lazy_exports(__name__, _WHERE)
