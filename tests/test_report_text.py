"""Configured labels appear typeset in the report's text, never as raw underscores or carets."""

from demid.report.sections import typeset_labels

LABELS = sorted(["μ_r,Po", "e_Po", "d_10", "d_1", "J m^-2", "plain"], key=len, reverse=True)


def test_labels_get_sub_and_superscripts():
    out = typeset_labels("μ_r,Po ∈ [0.1, 0.2]; γ in J m^-2; d_10 and d_1", LABELS)
    assert out == ("μ<sub>r,Po</sub> ∈ [0.1, 0.2]; γ in J m<sup>-2</sup>; d<sub>10</sub> and d<sub>1</sub>")


def test_code_spans_words_and_unlabelled_text_are_untouched():
    text = "`d_10` stays; xd_1 and d_1x are other words; plain stays plain"
    assert typeset_labels(text, LABELS) == text
