"""What the proposed replicates are for (criticism.verdict.replicate_message), whole, over 1-5 replicates of 1-3 runs
(labels repeated, in any order): the count a confirming message quotes is the number of replicates, each run is
named once in the order first proposed, and the misfit message says who makes them (a simulated table's next wave
simulates them, a table's next wave makes them)."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from demid import run_purposes
from demid.criticism.verdict import replicate_message


@settings(max_examples=40, deadline=None, derandomize=True)
@given(labels=st.lists(st.sampled_from(["3", "12", "7b", "40"]), min_size=1, max_size=5),
       purpose=st.sampled_from([run_purposes.CONFIRM, run_purposes.DECIDE]), simulated=st.booleans())
def test_the_replicates_count_and_runs_are_quoted(labels, purpose, simulated):
    runs = [{"a": 0.5, "b": 2.0, "purpose": purpose, "replicate_of": label} for label in labels]
    text = replicate_message(runs, simulated)
    first_seen = list(dict.fromkeys(labels))
    named = ", ".join(f"run {label}" for label in first_seen)
    if purpose == run_purposes.CONFIRM:
        count, which = re.fullmatch(r" (\d+) replicate\(s\) of (.+?) are proposed for the next wave: .*", text).groups()
        assert int(count) == len(runs) and which == named
        assert "seed-to-seed scatter" in text and "that run failed" in text
        return
    which, made = re.fullmatch(r" Replicates of the runs that misfit most \((.+?)\) are proposed so that the scatter "
                               r"there is measured and the next analysis can name the cause; (.+)\.", text).groups()
    assert which == named
    assert made == ("the next wave (waves.next_runs) simulates them" if simulated else
                    "a next wave (next_runs) makes them")
