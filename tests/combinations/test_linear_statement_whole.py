"""The combination sentence of a thin set (linear_statement): the equation normal·x = normal·centre ± width/2 in coded
units rewritten in search units (x_i = (s_i - centre_i) / unit_i), its coefficients of unit length with the largest
positive, and the sentence written with the coefficient of the factor that loads most (coded) equal to 1, the others
to three significant digits (those below half a unit of the third decimal left out), log-scale factors as log10,
and the constant with its half-width to the digits the half-width supports; all written out here, for two to four
factors of either sign and scale."""

from __future__ import annotations

import numpy as np
import pytest

from demid.combinations import linear_statement
from demid.design import Coding
from demid.precision import pm_text


def _case(seed: int, k: int):
    rng = np.random.default_rng(seed)
    normal = rng.normal(size=k)
    normal /= np.linalg.norm(normal)
    unit = rng.uniform(0.05, 20.0, k)
    mid = rng.uniform(-5.0, 50.0, k)
    lead = int(np.argmax(np.abs(normal)))
    if k >= 3:  # a factor that barely loads: its search-unit coefficient 0.002 of the lead's, then 0.0002
        small = (lead + 1) % k
        normal[small] = 0.002 * normal[lead] / unit[lead] * unit[small] * (1 if seed % 2 else 0.1)
    centre = rng.uniform(-1, 1, k)
    width = rng.uniform(0.01, 0.5)
    log = [bool(i % 2) for i in range(k)]
    labels = [f"f{i}" for i in range(k)]
    return normal, centre, width, Coding(tuple(labels), tuple(mid), tuple(unit)), labels, log


def _expected_sentence(a_shown, c_shown, w_shown, lead, labels, log):
    order = [lead] + [i for i in range(len(a_shown)) if i != lead]
    text = ""
    for i in order:
        coef = a_shown[i]
        if abs(coef) < 0.0005:
            continue
        name = f"log10 {labels[i]}" if log[i] else labels[i]
        term = name if abs(abs(coef) - 1) < 1e-12 else f"{abs(coef):.3g}·{name}"
        if not text:
            text = ("−" if coef < 0 else "") + term
        else:
            text += f" {'−' if coef < 0 else '+'} {term}"
    return f"{text} = {pm_text(c_shown, w_shown)}"


@pytest.mark.parametrize("seed,k", [(1, 2), (2, 3), (3, 3), (4, 4), (5, 4), (6, 2)])
def test_the_combination_equation_and_its_sentence(seed, k):
    normal, centre, width, coding, labels, log = _case(seed, k)
    a, c, w, text = linear_statement(normal, centre, width, coding, labels, log)
    unit, mid = np.asarray(coding.unit), np.asarray(coding.center)
    # normal·(s - mid)/unit = normal·centre  <=>  sum (normal/unit) s = normal·centre + sum normal mid/unit
    raw_a, raw_c = normal / unit, normal @ centre + np.sum(normal * mid / unit)
    scale = np.linalg.norm(raw_a) * np.sign(raw_a[np.argmax(np.abs(raw_a))])
    np.testing.assert_allclose(a, raw_a / scale, rtol=1e-12, atol=1e-15)
    assert np.linalg.norm(a) == pytest.approx(1.0) and a[np.argmax(np.abs(a))] > 0
    assert c == pytest.approx(raw_c / scale, rel=1e-12, abs=1e-12)
    assert w == pytest.approx(width / 2 / abs(scale), rel=1e-12)
    lead = int(np.argmax(np.abs(normal)))
    shown = raw_a / raw_a[lead]
    assert text == _expected_sentence(shown, raw_c / raw_a[lead], abs(width / 2 / raw_a[lead]), lead, labels, log)
