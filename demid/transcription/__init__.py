"""Transcription check: hold a hand-typed table against the statistics its source published.

A source usually publishes more than its design table: R², RMSE or the residual
standard deviation, an ANOVA with lack of fit and pure error, sometimes the
fitted equation.  :func:`check_transcription` refits the full quadratic model
(in coded units, exactly as :func:`demid.surrogate.fit_response` does) and asks
whether every refit statistic *rounds to the printed value*.  When some do not,
it searches every single-cell slip a typist makes -- a digit substituted, two
adjacent digits transposed, the decimal point shifted, a sign lost, a digit
dropped or doubled -- in every response cell and every factor cell, and ranks
the repairs by how many published statistics they restore.

Statistics (all as defined in :mod:`demid.surrogate`): ``r2``, ``adj_r2``,
``rmse`` = sqrt(SSE/n), ``resid_std`` = sqrt(SSE/(n-p)), ``q2`` = 1 - PRESS/SST,
``lof_f``, ``lof_p`` (lack of fit against pure error from replicated points;
NaN without replicates), ``ss_model``, ``ss_residual``, ``ss_lof``,
``ss_pure_error``, ``ss_total`` and the model ``coefficients`` in coded or
actual units.

Agreement rule.  A value printed with ``d`` decimals stands for the interval
``[v - h, v + h]`` with ``h = 0.5 * 10**-d``; the refit agrees when it lies in
that closed interval (widened by one part in a million of ``h`` for
floating-point noise).  Both ends are included, so a source that rounds half
up, half down or half to even is accepted alike.  A printed bound such as
``"< 0.0001"`` agrees when the refit satisfies it.  A statistic also agrees
when the source evidently computed it from sums of squares it printed rounded,
and those sums agree with the refit: F, its p and R² from any values of the sums
within their rounding (Montgomery's F = 1.78 from SS 0.28 and 0.21), adjusted
R², residual SD and RMSE from the printed sums themselves (over the sums'
rounding their range is wider than their own printed precision).

Ranking of repairs.  By the number of published statistics the repaired table
reproduces (``restores``, more first); then by how the repair fits the way the
column is printed (a repair of a cell that stands out -- more decimals than the
rest of its column, or a factor value off every design level -- first; a repair
that needs more decimals than the column shows last); then by the summed
distance of the repaired statistics from the printed values, each in units of
its rounding half-width ``h`` (closer first); then by the kind of slip (sign
lost, decimal shift, transposition, doubled, dropped, substituted digit: the
order of :data:`KINDS`); then by table row and column order.  All repairs that
restore every statistic are reported (at most ``max_suspects``); when none
does, the verdict says so plainly and the best partial repairs (restoring more
statistics than the table as found) are listed as leads.

Candidates.  Each cell's printed string (``printed``, or reconstructed from the
number with the column's largest number of decimals) is edited by every slip
of every kind; a repair that gives the same number under several kinds is kept
under the first kind in :data:`KINDS`.  A factor repair must land on a level of
the declared design: a level another cell of the column prints exactly as
printed there, a level no other cell shows (an axial point) within the
column's printing precision.  The declared coding is the one that puts the most
cells on the design's nominal levels, so a mistyped extreme does not move the
levels; pass ``coding`` to fix it instead.  Repaired tables are coded with
``Coding.from_levels`` as :func:`~demid.surrogate.fit_response` would code them.

Modules: ``printed`` (printed values and published blocks), ``engine`` (the batched
refits), ``typos`` (single-cell slips and the validator's typo flag) and ``check``
(the check of a response, a table and a configured material).

Speed.  A response cell enters the fit linearly, so every response hypothesis
is one column of a matrix ``Y`` and all are evaluated at once from the
pseudo-inverse, the hat matrix and the replicate-group projection of the
table's design.  A factor cell changes the design; the repairs that land on a
design level are refitted together in one batched SVD.  A 20-run, 3-factor
table (about 2,000 response and 140 factor hypotheses) takes a few hundredths
of a second.
"""

from ..lazy import lazy_exports

# Names are imported from their submodule on first use (PEP 562): the workflow's start-up reads only
# ``printed`` (whether a published value is possible), not the check and its refitting engine.
_WHERE = {
    "Suspect": ".check", "TranscriptionResult": ".check", "check_material": ".check", "check_table": ".check",
    "check_transcription": ".check", "transcription_frame": ".check",
    "STATISTICS": ".printed", "PrintedValue": ".printed", "parse_printed": ".printed",
    "KINDS": ".typos", "likely_typos": ".typos", "refuse_likely_typos": ".typos", "single_cell_slips": ".typos",
}

__getattr__, __all__ = lazy_exports(__name__, _WHERE)
