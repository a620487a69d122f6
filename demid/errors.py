"""User-facing input errors: one line naming the file (or config key), row and column."""

from __future__ import annotations

import sys
from typing import NoReturn


#: Longest error line: room for about 300 characters of detail beside a file's path.  A cell or label quoted
#: in a message (a million characters, a YAML alias expanded a billion times) is cut, and the line says how
#: much was left out.
MAX_MESSAGE = 500
_HEAD, _TAIL = 360, 100


def capped(message: str, limit: int = MAX_MESSAGE) -> str:
    """``message`` on one line of about ``limit`` characters at most: its start and end, and a count of
    what was left out between them."""
    if len(message) <= limit:
        return message
    head, tail = message[:_HEAD], message[-_TAIL:]
    left_out = len(message) - len(head) - len(tail)
    return f"{' '.join(head.split())} […{left_out} characters left out…] {' '.join(tail.split())}"


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
        super().__init__(capped(self._compose()))

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
