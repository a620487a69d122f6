"""A level-1 finding's other reading of its run (criticism.level1), read whole over planted defects: a missing term,
an outlier and a slipped factor value of 2-3 factor CCDs.  The sentence that names a run's
other reading appears exactly when that reading is among the finding's aliases -- an outlier whose run a slip also
fits says so, a slip that also reads as an outlier quotes its Bayes factor (parsed back against the finding's), and
a missing term's finding carries neither sentence."""

from __future__ import annotations

import re

import pytest

from demid.criticism import criticize
from tests.generators import FACTORS, ccd_table, off_catalogue_table

_SLIP_TOO = "A slipped factor value of the same run fits it too"
_OUTLIER_TOO = re.compile(r"The same evidence reads as an outlier of run (\S+) \(the Bayes factor of the slip, "
                          r"(\d+\.\d)\, is no decisive preference\)")

# each names one cause: a term (2 and 3 factors), an outlier a slip also fits, an outlier alone, a slip
_CASES = [("term", 2, 0, 6.0), ("outlier", 2, 3, 8.0), ("outlier", 3, 4, 9.0), ("slip", 3, 6, None),
          ("term", 3, 7, 7.0)]


@pytest.mark.parametrize("kind,k,seed,size", _CASES)
def test_a_findings_other_reading_sentence_matches_its_aliases(kind, k, seed, size):
    if kind == "slip":
        table, _ = off_catalogue_table(seed, k, "slip", slip=0.2)
    else:
        table, _ = ccd_table(seed, k, kind, size)
    findings = criticize(table, FACTORS[k], "y", n_null=199).findings
    assert findings
    for f in findings:
        other = [a for a in f.aliases if a in ("outlier", "factor_level")]
        assert (_SLIP_TOO in f.message) == (f.cause == "outlier" and "factor_level" in other)
        quoted = _OUTLIER_TOO.search(f.message)
        assert (quoted is not None) == (f.cause == "factor_level" and "outlier" in other)
        if quoted:
            assert quoted.group(1) == str(f.detail)
            assert float(quoted.group(2)) == round(f.info["bayes_factor"], 1)
        if f.cause not in ("outlier", "factor_level"):
            assert other == [] and _SLIP_TOO not in f.message and quoted is None
