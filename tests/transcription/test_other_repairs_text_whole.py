"""The clause a typo stop adds for other repairs that fit the other runs as well (demid.transcription.typos), against
the wording written out here for 0-5 other repairs of every kind: none adds nothing; one 'fits', two are joined by
'and', more name the first two and count the rest ('and N more'); each value in its shortest positional form with
its slip in words, and the prediction from the other runs to four significant digits."""

from __future__ import annotations

import numpy as np
import pytest

from demid.transcription.typos import SLIP_WORDS, _other_repairs_text

VALUES = [100.91154, 109.1154, 1.0e-5, 2500.0, -0.25]
KINDS = ["digit_dropped", "decimal_shift", "transposition", "sign_lost", "digit_added"]


@pytest.mark.parametrize("count", [0, 1, 2, 3, 4, 5])
@pytest.mark.parametrize("predicted", [100.12345, -0.0123456, 98765.4])
def test_the_other_repairs_clause_names_two_and_counts_the_rest(count, predicted):
    others = [{"value": v, "kind": k} for v, k in zip(VALUES[:count], KINDS[:count])]
    got = _other_repairs_text({"other_repairs": others, "predicted_from_other_runs": predicted})
    if not count:
        assert got == ""
        return
    named = [f"{np.format_float_positional(o['value'], trim='-')} ({SLIP_WORDS[o['kind']]})" for o in others[:2]]
    shown = ", ".join(named) + f" and {count - 2} more" if count > 2 else " and ".join(named)
    verb = "fits" if count == 1 else "fit"
    assert got == (f" after checking it against the source: {shown} {verb} the other runs as well "
                   f"(predicted {predicted:.4g})")


def test_a_flag_without_the_key_has_no_clause():
    assert _other_repairs_text({"predicted_from_other_runs": 1.0}) == ""
