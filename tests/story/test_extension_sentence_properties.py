"""The model-extension sentence over generated rows: each number it quotes reads back as the row's number,
the verb says which way the best error moved (equal errors included), the set's verb which way its share of
Ω moved, and a share read off a weak surrogate (Q² below the waves' stop level, on either side) carries its
Q² and the caveat, which appears exactly when one side is weak."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.story.extensions import extension_sentence
from demid.waves import STOP_Q2

_ERRORS = st.sampled_from([0.0, 0.004, 0.05, 0.237, 0.5, 1.5])
_SHARES = st.sampled_from([0.0, 0.3, 2.5, 12.5, 47.0, 100.0])
# a Q² as the report's rows carry it: a number either side of the stop level, missing (None) or "" (NaN filled)
_Q2 = st.sampled_from([None, "", 0.95, STOP_Q2, 0.49, 0.1, -0.3])


def _weak(q2) -> bool:
    return isinstance(q2, float) and q2 < STOP_Q2


def _percent(text: str) -> float:
    """A quoted error back as a fraction ("0 %" and "12.3 %")."""
    return float(text.replace("−", "-").rstrip(" %")) / 100


def _share(text: str, q2) -> None:
    """One quoted share of Ω, its Q² beside it when weak."""
    if _weak(q2):
        assert text.endswith(f" (surrogate Q² = {q2:.2f} < {STOP_Q2:g})"), text
        text = text[:text.index(" (surrogate")]
    else:
        assert "surrogate Q²" not in text
    return text


@given(before=_ERRORS, after=_ERRORS, share_before=_SHARES, share_after=_SHARES, q2_before=_Q2, q2_after=_Q2,
       added=st.integers(0, 3), sign=st.sampled_from([1.0, -1.0]))
@settings(max_examples=80, deadline=None, derandomize=True)
def test_an_extension_sentence_quotes_the_rows_numbers_and_the_directions_they_moved(
        before, after, share_before, share_after, q2_before, q2_after, added, sign):
    factors = ["mu_r", "e", "k"][:added]
    row = {"material": "ext", "extends": "base", "added_factors": "+".join(factors),
           # a stored best error is a size: its sign says nothing (the sentence reads its size)
           "best_error_before": sign * before, "best_error_after": after,
           "feasible_fraction_before_pct": share_before, "feasible_fraction_after_pct": share_after,
           "surrogate_q2_before": q2_before, "surrogate_q2_after": q2_after}
    text = extension_sentence(row, {"base": "No rolling"}, {"mu_r": "μ_r"}, "AoR")
    head = f"Adding {', '.join(['μ_r', 'e', 'k'][:added])} to" if added else "Extending"
    match = re.fullmatch(
        re.escape(head) + r" the model of No rolling \(ext\): the best point's largest error (falls|does not fall|"
        r"rises) from (\S+ %) to (\S+ %); the admissible set of \*AoR\* (grows|does not grow) from (.+?) to "
        r"(.+?)\.( A set read off a surrogate whose leave-one-out Q² is below .*)?", text)
    assert match, text
    verb, quoted_before, quoted_after, grow, first, second, caveat = match.groups()
    assert verb == ("falls" if after < before else "does not fall" if after == before else "rises")
    assert abs(_percent(quoted_before) - before) <= 0.0005 * before + 1e-12
    assert abs(_percent(quoted_after) - after) <= 0.0005 * after + 1e-12
    assert grow == ("grows" if share_after > share_before else "does not grow")
    for quoted, share, q2 in ((first, share_before, q2_before), (second, share_after, q2_after)):
        quoted = _share(quoted, q2)
        if share <= 0:
            assert quoted == "empty"
        else:
            assert quoted.endswith(" % of Ω") and float(quoted[:-len(" % of Ω")]) == float(f"{share:.3g}")
    assert (caveat is not None) == (_weak(q2_before) or _weak(q2_after))
    if caveat:
        assert f"below {STOP_Q2:g}" in caveat


def test_a_sets_q2_is_its_weakest_surrogates_and_unknown_when_one_is_missing():
    """The Q² a share is read off: the lowest of the scenario's observables' surrogates, NaN when one of them
    has no row in the fit table (a set is only as predictive as its weakest surrogate, and one not judged is
    not judged well)."""
    import numpy as np
    import pandas as pd

    from demid.story.extensions import _lowest_q2

    fit = pd.DataFrame({"material": ["m", "m", "m", "other"], "response": ["a", "b", "c", "d"],
                        "q2": [0.9, 0.4, 0.7, -1.0]})
    assert _lowest_q2(fit, "m", ["a", "b"]) == 0.4
    assert _lowest_q2(fit, "m", ["a", "c"]) == 0.7
    assert np.isnan(_lowest_q2(fit, "m", ["a", "d"]))      # d is another material's
    assert np.isnan(_lowest_q2(fit, "m", ["e"]))
    assert np.isnan(_lowest_q2(None, "m", ["a"]))


def test_a_best_error_is_level_twos_and_unknown_without_it():
    """The best error read off a material's criticism: level 2's best_max_error as a float, NaN when the material
    has no criticism, no level 2 or no best error (never a number made up)."""
    import numpy as np

    from demid.story.extensions import _best_error

    assert _best_error({"level2": {"best_max_error": 0.237}}) == 0.237
    assert _best_error({"level2": {"best_max_error": 1}}) == 1.0 and isinstance(
        _best_error({"level2": {"best_max_error": 1}}), float)
    for criticism in (None, {}, {"level2": None}, {"level2": {}}, {"level2": {"best_max_error": None}}):
        assert np.isnan(_best_error(criticism))
