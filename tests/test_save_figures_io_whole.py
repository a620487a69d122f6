"""How save_figures shares the figures out (demid.io): by area, largest first, each to the process with less drawn
area so far, the forked one on a tie (this process also writes the tables); every figure once.  Where the
platform cannot fork, this process draws them all after the tables.  The drawing is replaced by a note of the
process that drew it, so the share is read back from the files; sizes of 1-7 figures, equal and unequal."""

from __future__ import annotations

import os

import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

import demid.io


class _Sized:
    def __init__(self, width, height):
        self.size = (width, height)

    def get_size_inches(self):
        return self.size


def _noting_pid(fig, path):
    path.write_text(str(os.getpid()), encoding="utf-8")


def _shares(sizes):
    """(this process's, the forked one's) figure indices by the documented rule, written out."""
    order = sorted(range(len(sizes)), key=lambda i: -(sizes[i][0] * sizes[i][1]))
    ours, theirs, area_ours, area_theirs = [], [], 0.0, 0.0
    for i in order:
        if area_theirs <= area_ours:
            theirs.append(i)
            area_theirs += sizes[i][0] * sizes[i][1]
        else:
            ours.append(i)
            area_ours += sizes[i][0] * sizes[i][1]
    return sorted(ours), sorted(theirs)


SIZES = st.lists(st.tuples(st.sampled_from([1.0, 2.0, 3.0, 6.5]), st.sampled_from([1.0, 1.5, 4.0])),
                 min_size=2, max_size=7)


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the share needs a platform that can fork")
@given(sizes=SIZES)
@settings(max_examples=8, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_figures_are_shared_out_by_area_between_two_processes(tmp_path_factory, sizes):
    folder = tmp_path_factory.mktemp("figures")
    paths = [folder / f"f{i}.png" for i in range(len(sizes))]
    tables = []
    original = demid.io.save_figure
    demid.io.save_figure = _noting_pid
    try:
        demid.io.save_figures({p: _Sized(*s) for p, s in zip(paths, sizes)}, also=lambda: tables.append(os.getpid()))
    finally:
        demid.io.save_figure = original
    assert tables == [os.getpid()]
    drawn_by = [p.read_text(encoding="utf-8") for p in paths]
    ours, theirs = _shares(sizes)
    assert [i for i, pid in enumerate(drawn_by) if pid == str(os.getpid())] == ours
    assert len({drawn_by[i] for i in theirs}) == 1 and str(os.getpid()) not in {drawn_by[i] for i in theirs}


@pytest.mark.parametrize("n", [1, 3])
def test_without_fork_this_process_writes_the_tables_then_every_figure(tmp_path, monkeypatch, n):
    monkeypatch.delattr(os, "fork", raising=False)
    events = []
    monkeypatch.setattr(demid.io, "save_figure", lambda fig, path: events.append(("figure", path.name, os.getpid())))
    paths = [tmp_path / f"f{i}.png" for i in range(n)]
    demid.io.save_figures({p: _Sized(1.0 + i, 1.0) for i, p in enumerate(paths)},
                          also=lambda: events.append(("tables", "", os.getpid())))
    assert events == [("tables", "", os.getpid())] + [("figure", p.name, os.getpid()) for p in paths]
