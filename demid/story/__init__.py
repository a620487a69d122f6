"""One study, one story: the verdicts and the advice every section of the report reads.

:mod:`~demid.story.verdicts` judges each factor on the plausible interval (the strict one beside it);
:mod:`~demid.story.advice` holds every piece of advice, computed once, the one source the report reads
(:mod:`~demid.story.measurements`: the observable ranking in words; :mod:`~demid.story.recommended`: where
the recommended point stands); :func:`study_story` builds both
for the materials of a results tree (``tables/verdicts.csv``, ``tables/advice.csv``).
"""

from .advice import (ADVICE_COLUMNS, LEVEL2_KINDS, NEXT_WAVE_KINDS, RANKING_KINDS, AdviceItem, StudyAdvice,
                     material_advice)
from .build import study_story
from .verdicts import VERDICT_COLUMNS, verdict_display, verdict_frame

__all__ = ["ADVICE_COLUMNS", "LEVEL2_KINDS", "NEXT_WAVE_KINDS", "RANKING_KINDS", "VERDICT_COLUMNS", "AdviceItem",
           "StudyAdvice", "material_advice", "study_story", "verdict_display", "verdict_frame"]
