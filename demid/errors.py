"""User-facing input errors: one line naming the file (or config key), row and column."""

from __future__ import annotations

import sys
from typing import NoReturn


class InputError(Exception):
    """A problem with user input (table or config) that the user must fix.

    The message is a single line that names where the problem is: the file or
    config key, and where applicable the run (row) and column.  The CLI and the
    Snakemake scripts print ``str(err)`` and exit non-zero without a traceback.
    """

    def __init__(self, message: str, *, source: str | None = None, run=None, column: str | None = None):
        self.source = source
        self.run = run
        self.column = column
        self.detail = message
        super().__init__(self._compose())

    def _compose(self) -> str:
        where = []
        if self.source is not None:
            where.append(str(self.source))
        if isinstance(self.run, (list, tuple)):
            where.append("runs " + ", ".join(map(str, self.run[:-1])) + f" and {self.run[-1]}")
        elif self.run is not None:
            where.append(f"run {self.run}")
        if self.column is not None:
            where.append(f"column '{self.column}'")
        prefix = ", ".join(where)
        return f"{prefix}: {self.detail}" if prefix else self.detail


def stop_job(err: InputError) -> NoReturn:
    """End a Snakemake job on bad input: the one line, in the job's log and on the terminal the workflow
    runs in (the scripts send stderr to the log), exit status 1 and no traceback."""
    line = f"demid: error: {err}"
    print(line, file=sys.stderr, flush=True)
    if sys.stderr is not sys.__stderr__ and sys.__stderr__ is not None:
        print(line, file=sys.__stderr__, flush=True)
    raise SystemExit(1)
