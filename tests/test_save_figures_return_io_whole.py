"""save_figures (demid.io) returns to its caller: the process that called it goes on after the call (it writes the
tables, then the rest of its job) while the forked process only draws its share and ends.  The call is made in a
process of the test's own, so that a wrong process ending early is seen as the missing return, not as the end of
the test run; the drawing is replaced by a note of the process that drew it."""

from __future__ import annotations

import os

import pytest

import demid.io
from tests.test_save_figures_io_whole import _noting_pid, _Sized


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the share needs a platform that can fork")
@pytest.mark.parametrize("count", [2, 5])
def test_save_figures_returns_in_the_calling_process_after_every_png_is_drawn(tmp_path, count):
    paths = [tmp_path / f"f{i}.png" for i in range(count)]
    tables, returned = tmp_path / "tables.txt", tmp_path / "returned.txt"
    caller = os.fork()
    if caller == 0:  # the caller: save_figures, then a note that the call returned, and out
        code = 1
        try:
            demid.io.save_figure = _noting_pid  # in this process only
            demid.io.save_figures({p: _Sized(1.0 + i, 1.0) for i, p in enumerate(paths)},
                                  also=lambda: tables.write_text(str(os.getpid()), encoding="utf-8"))
            returned.write_text(str(os.getpid()), encoding="utf-8")
            code = 0
        finally:
            os._exit(code)
    _, status = os.waitpid(caller, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    assert returned.read_text(encoding="utf-8") == str(caller)
    assert tables.read_text(encoding="utf-8") == str(caller)
    drawn_by = {p.read_text(encoding="utf-8") for p in paths}
    assert str(caller) in drawn_by and len(drawn_by) == 2  # the caller's share and the forked process's
