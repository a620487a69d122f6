"""What a run the criticism proposes is for: the purposes its runs carry into the next wave's table.

Kept apart from both so that the next wave (which loads neither scipy nor statsmodels) and the criticism read
one spelling."""

#: Runs that would decide between causes the criticism cannot tell apart (an ambiguous verdict).
DECIDE = "decide between causes"

#: Runs that would confirm or correct a cause the criticism named.
CONFIRM = "confirm the named cause"
