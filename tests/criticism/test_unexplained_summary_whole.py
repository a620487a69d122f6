"""The summary of a response whose misfit no catalogue cause explains (criticism.level1.criticize): it is the
unexplained evidence's own message, naming the tests that fired and their family-wise p-values (parsed back against
the evidence), not the summary of a named cause."""

from __future__ import annotations

import re

from demid.criticism import criticize
from tests.generators import FACTORS, off_catalogue_table


def test_an_unexplained_misfits_summary_is_its_evidence_message():
    table, _ = off_catalogue_table(0, 2, "batch", size=6.0)
    result = criticize(table, FACTORS[2], "y", n_null=199)
    assert result.verdict == "unexplained" and result.unexplained and result.run_order.drift_tested
    assert result.summary == result.unexplained["message"]
    assert result.summary.startswith("y: the runs show misfit that no catalogued cause accounts for.")
    quoted = [float(p) for p in re.findall(r"family-wise p = ([0-9.e+-]+)\)", result.summary)]
    fired = [e["p_family"] for e in result.unexplained["tests"] + result.unexplained["remaining"]]
    assert quoted and quoted == [float(f"{p:.3g}") for p in fired]
