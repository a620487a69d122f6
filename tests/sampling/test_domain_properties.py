"""Which ends of a factor's range are its physical limits (sides_at_limit), over generated ranges of any scale and
sign and limits placed at the bound, a little or far inside the range (the range reaches past the limit) or
outside it: against the rule written out (a limit at most a millionth of the range outside, a rounded bound, counts
as reached)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling.domain import LIMIT_SLACK, sides_at_limit

# where the limit lies from the bound, in units of the range: positive outside the range, negative inside it
offsets = st.sampled_from([None, 0.0, 0.3 * LIMIT_SLACK, -0.3 * LIMIT_SLACK, -3 * LIMIT_SLACK, 3 * LIMIT_SLACK, -0.2,
                           0.2])


@given(lower=st.floats(-1e4, 1e4), width=st.floats(1e-3, 1e4), lower_offset=offsets, upper_offset=offsets)
@settings(max_examples=80, deadline=None, derandomize=True)
def test_an_end_is_at_its_limit_when_it_reaches_the_limit_or_falls_short_by_a_millionth_of_the_range(
        lower, width, lower_offset, upper_offset):
    upper = lower + width
    limits = (None if lower_offset is None else lower - lower_offset * width,
              None if upper_offset is None else upper + upper_offset * width)
    expected = [side for side, offset in (("lower", lower_offset), ("upper", upper_offset))
                if offset is not None and offset <= LIMIT_SLACK]
    assert sides_at_limit((lower, upper), limits) == expected
