"""The adaptive quadrature's integrals and error estimates do not depend on the units of the integration variable:
integrating f over pieces of [a, a + L] and L f(a + L v) over the same pieces mapped onto [0, 1] give the same
integrals and the same QUADPACK error estimates (the estimate compares the integrand with its mean over each piece,
a mean per unit of the variable).  Over integrands with kinks, bends, square-root ends and steep growth, ranges from
a twentieth to ten units long, one to three pieces per owner and two owners at once; and every integral lies within
its estimate of the closed form."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.quadrature import integrate

#: (integrand, antiderivative): kink, square-root end, a jump in the slope's derivative, steep growth
#: (a jump in the integrand itself is bisected down to pieces of an absolute length, 1e-13, which units change)
CASES = {
    "kink": (lambda s: np.abs(s - 0.3), lambda s: 0.5 * np.sign(s - 0.3) * (s - 0.3) ** 2),
    "root": (lambda s: np.sqrt(np.abs(s - 0.37)), lambda s: np.sign(s - 0.37) * 2 / 3 * np.abs(s - 0.37) ** 1.5),
    "bend": (lambda s: np.maximum(s - 0.013, 0.0) ** 2, lambda s: np.maximum(s - 0.013, 0.0) ** 3 / 3),
    "steep": (lambda s: np.exp(3 * s), lambda s: np.exp(3 * s) / 3),
}


@pytest.mark.parametrize("a, length", [(0.0, 0.05), (-0.2, 0.8), (0.1, 3.0), (-5.0, 10.0)])
@pytest.mark.parametrize("rtol", [1e-3, 1e-7])
def test_integrals_and_their_error_estimates_do_not_depend_on_units(a, length, rtol):
    rng = np.random.default_rng(int(100 * length))
    names = ["kink", "root", "bend", "steep"]
    pairs = [(names[i], names[(i + 1) % 4]) for i in range(4)]
    for first, second in pairs:
        funcs = [CASES[first][0], CASES[second][0]]
        # pieces: owner 0 one to three pieces of [a, a + L], owner 1 the whole range
        cuts = np.sort(rng.uniform(0, 1, rng.integers(0, 3)))
        edges = np.r_[0.0, cuts, 1.0]
        owners = np.r_[np.zeros(len(edges) - 1, dtype=int), 1]
        lo_v, hi_v = np.r_[edges[:-1], 0.0], np.r_[edges[1:], 1.0]

        def in_units(owner, s):
            return np.where(owner == 0, funcs[0](s), funcs[1](s))[:, None]

        def on_unit(owner, v):
            return length * in_units(owner, a + length * v)

        total, error = integrate(in_units, owners, a + length * lo_v, a + length * hi_v, 2, rtol)
        total_v, error_v = integrate(on_unit, owners, lo_v, hi_v, 2, rtol)
        np.testing.assert_allclose(total_v, total, rtol=1e-9, atol=1e-15)
        np.testing.assert_allclose(error_v, error, rtol=1e-6, atol=1e-18)
        for k, name in enumerate((first, second)):
            anti = CASES[name][1]
            exact = anti(a + length) - anti(a)
            assert abs(total[k, 0] - exact) <= error[k] + 1e-13 * max(abs(exact), 1.0)
            assert abs(total[k, 0] - exact) <= max(rtol * abs(exact), 1e-14)
