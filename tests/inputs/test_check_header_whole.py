"""A table's header against the columns it must name (demid.data.check_header), each refusal's whole line against
the rule written out here: a repeated column first (named, with the missing columns it may stand for: one or
several), then each missing column in the order run, factors, responses with its hint (the same name in another
case, a close spelling among the columns nobody needs, else the columns found), then a reserved column (status,
block) written in another case.  Headers generated from 1-3 factors and 1-3 responses."""

from __future__ import annotations

import difflib

import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.data import check_header
from demid.errors import InputError


def _expected(header, factors, responses):
    needed = ["run", *factors, *responses]
    missing = [c for c in needed if c not in header]
    repeated = sorted({h for h in header if header.count(h) > 1})
    if repeated:
        named = " or ".join(f"'{m}'" for m in missing)
        hint = f"; {named} {'is' if len(missing) == 1 else 'are'} missing: is one of them {named}?" if missing else ""
        return f"column appears more than once in the header{hint}", repeated[0]
    if missing:
        col = missing[0]
        same = [h for h in header if h.casefold() == col.casefold()]
        spare = [h for h in header if h not in needed]
        close = difflib.get_close_matches(col, spare, n=1, cutoff=0.6)
        hint = (f"; found '{same[0]}', which differs only in upper/lower case" if same else
                f"; found '{close[0]}' — misspelled?" if close else f"; columns found: {', '.join(header)}")
        return f"missing column (expected columns: {', '.join(needed)}){hint}", col
    for reserved in ("status", "block"):
        same = [h for h in header if h != reserved and h.casefold() == reserved.casefold() and h not in needed]
        if same and reserved not in header:
            return (f"differs only in upper/lower case from the reserved column '{reserved}': rename it to "
                    f"'{reserved}'"), same[0]
    return None


EDITS = st.sampled_from(["drop", "upper", "typo", "repeat", "status", "block", "reserved", "extra", "none"])


@given(n_factors=st.integers(1, 3), n_responses=st.integers(1, 3), edits=st.lists(st.tuples(EDITS, st.integers(0, 6)),
                                                                                   max_size=3))
@settings(max_examples=80, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_each_header_is_accepted_or_refused_with_its_one_line(n_factors, n_responses, edits):
    factors = ["mu_s", "mu_r", "k_roll"][:n_factors]  # two close spellings
    responses = ["angle", "angle2", "mass"][:n_responses]
    header = ["run", *factors, *responses]
    for edit, index in edits:
        i = index % len(header)
        if edit == "drop" and len(header) > 1:
            del header[i]
        elif edit == "upper":
            header[i] = header[i].upper()
        elif edit == "typo":
            header[i] = header[i][:-1] + "x"
        elif edit == "repeat":
            header.append(header[i])
        elif edit in ("status", "block"):
            header.append(edit.capitalize())
        elif edit == "reserved":  # the reserved columns under their own names
            header += ["status", "block"]
        elif edit == "extra":
            header.append("notes")
    want = _expected(header, factors, responses)
    if want is None:
        check_header(header, factors, responses, "t.csv")
        return
    with pytest.raises(InputError) as info:
        check_header(header, factors, responses, "t.csv")
    assert (info.value.detail, info.value.column) == want
    assert info.value.source == "t.csv"


@pytest.mark.parametrize("header, factors, message", [
    (["run", "a", "a", "y"], ["a"], "column appears more than once in the header"),
    (["run", "a", "b", "b"], ["a", "b"], "column appears more than once in the header; 'y' is missing: is one of "
                                         "them 'y'?"),
    (["run", "a", "a", "a"], ["a", "b"], "column appears more than once in the header; 'b' or 'y' are missing: is "
                                         "one of them 'b' or 'y'?"),
])
def test_a_repeated_column_names_the_missing_ones_it_may_stand_for(header, factors, message):
    with pytest.raises(InputError) as info:
        check_header(header, factors, ["y"], "t.csv")
    assert info.value.detail == message and info.value.column == header[2]


@pytest.mark.parametrize("extra, refused", [(["Status"], "Status"), (["Status", "status"], None),
                                            (["BLOCK", "block"], None), (["Block"], "Block")])
def test_a_reserved_column_in_another_case_is_refused_only_without_the_column_itself(extra, refused):
    header = ["run", "a", "y", *extra]
    if refused is None:
        check_header(header, ["a"], ["y"], "t.csv")
        return
    with pytest.raises(InputError) as info:
        check_header(header, ["a"], ["y"], "t.csv")
    reserved = refused.lower()
    assert info.value.detail == (f"differs only in upper/lower case from the reserved column '{reserved}': rename it "
                                 f"to '{reserved}'") and info.value.column == refused
