"""Exact admissible sets of polynomial surrogates against answers computed independently.

Every expected value here comes from closed-form geometry (annuli, balls, shells, strips,
parallelograms, point-to-segment distances), from scipy's adaptive quadrature of analytic
chord lengths, or from a separate line-by-line computation with ``numpy.roots`` and direct
evaluation of the responses — never from the code under test.
"""

from pathlib import Path

import numpy as np
import pytest
from scipy import integrate

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.sampling.exact import Polynomial, exact_set, exact_set_for_surrogates, polynomial_from_surrogate
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate

ROOT = Path(__file__).resolve().parents[2]

# Accuracy the pipeline needs: fractions 0.1 %, widths 0.05 %, reference distance 1 %.
FRACTION_RTOL = 1e-3
WIDTH_RTOL = 5e-4
DISTANCE_RTOL = 1e-2


def quadratic(c0=0.0, a=0.0, b=0.0, ab=0.0, aa=0.0, bb=0.0) -> Polynomial:
    """c0 + a x + b y + ab x y + aa x^2 + bb y^2."""
    return Polynomial([[0, 0], [1, 0], [0, 1], [1, 1], [2, 0], [0, 2]], [c0, a, b, ab, aa, bb])


def squares(dim, center=None) -> Polynomial:
    """sum_i (x_i - center_i)^2."""
    center = np.zeros(dim) if center is None else np.asarray(center, float)
    exps = [[0] * dim]
    coef = [float(np.sum(center ** 2))]
    for i in range(dim):
        e1, e2 = [0] * dim, [0] * dim
        e1[i], e2[i] = 1, 2
        exps += [e1, e2]
        coef += [-2 * center[i], 1.0]
    return Polynomial(exps, coef)


# --------------------------------------------------------------------------- independent references
def strip_area_below(alpha, beta, c):
    """Area of {alpha a + beta b <= c} in the unit square (alpha, beta > 0): piecewise-linear integrand, exact."""
    knots = np.clip([0.0, 1.0, c / alpha, (c - beta) / alpha], 0.0, 1.0)
    knots = np.unique(knots)
    height = lambda a: np.clip((c - alpha * a) / beta, 0.0, 1.0)  # noqa: E731
    return float(sum((k1 - k0) * (height(k0) + height(k1)) / 2 for k0, k1 in zip(knots[:-1], knots[1:])))


def segment_distance(p, a, b):
    p, a, b = map(np.asarray, (p, a, b))
    t = np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0)
    return float(np.linalg.norm(p - (a + t * (b - a))))


def roots_line_intervals(responses, targets, eps, fixed, axis):
    """Admissible intervals in [0, 1] along lines of the unit square, with ``numpy.roots``.

    ``responses`` are vectorised functions of unit coordinates (a, b) of degree <= 2; along a
    line each is the quadratic through its values at t = 0, 1/2, 1.  ``fixed`` holds the other
    coordinate of each line; returns one list of (lower, upper) per line.
    """
    fixed = np.atleast_1d(np.asarray(fixed, float))

    def on_lines(f, t, rows=slice(None)):
        t = np.broadcast_to(np.asarray(t, float), fixed[rows].shape)
        return f(t, fixed[rows]) if axis == 0 else f(fixed[rows], t)

    values = [np.stack([on_lines(f, t) for t in (0.0, 0.5, 1.0)]) for f in responses]
    out = []
    for line in range(len(fixed)):
        cuts = [0.0, 1.0]
        for (v0, v1, v2), target in zip((v[:, line] for v in values), targets):
            coef = np.array([2 * v0 - 4 * v1 + 2 * v2, 4 * v1 - 3 * v0 - v2, v0])  # descending powers
            for level in (target * (1 - eps), target * (1 + eps)):
                shifted = coef - [0, 0, level]
                roots = np.roots(np.trim_zeros(shifted, "f")) if np.any(shifted[:-1]) else []
                cuts += [r.real for r in roots if abs(r.imag) < 1e-12 and 0 < r.real < 1]
        cuts = np.sort(cuts)
        mids = (cuts[1:] + cuts[:-1]) / 2
        rows = np.full(len(mids), line)
        ok = np.ones(len(mids), bool)
        for f, target in zip(responses, targets):
            ok &= np.abs(on_lines(f, mids, rows) - target) <= eps * abs(target)
        out.append([(lo, hi) for lo, hi, good in zip(cuts[:-1], cuts[1:], ok) if good and hi > lo])
    return out


def roots_fraction(responses, targets, eps, n, axis=0):
    """Midpoint rule over n lines along ``axis`` of the exact (numpy.roots) line lengths."""
    lines = roots_line_intervals(responses, targets, eps, (np.arange(n) + 0.5) / n, axis)
    return float(np.mean([sum(hi - lo for lo, hi in line) for line in lines]))


def roots_span(responses, targets, eps, coord, n=101):
    """Min and max of unit coordinate ``coord``: lines across it on a grid, refined three times around each end."""
    axis = 1 - coord

    def feasible(values):
        return np.array([bool(line) for line in roots_line_intervals(responses, targets, eps, values, axis)])

    def transition(inside, outside, m=101):
        for _ in range(3):  # grid search between a feasible and an infeasible line, three times
            grid = np.linspace(outside, inside, m)
            ok = feasible(grid)
            k = int(np.argmax(ok))
            outside, inside = grid[max(k - 1, 0)], grid[k]
        return inside, abs(inside - outside)

    grid = np.linspace(0.0, 1.0, n)
    ok = np.flatnonzero(feasible(grid))
    lo, hi = ok[0], ok[-1]
    lower, e1 = transition(grid[lo], grid[lo - 1]) if lo > 0 else (0.0, 0.0)
    upper, e2 = transition(grid[hi], grid[hi + 1]) if hi < n - 1 else (1.0, 0.0)
    return lower, upper, max(e1, e2)


# --------------------------------------------------------------------------- two factors, closed form
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_annulus_fraction_and_spans(sign):
    # y = a^2 + b^2 on [-1, 1]^2, target 0.5 at 20 %: 0.4 <= r^2 <= 0.6 (the same set for -y and -0.5)
    poly = squares(2)
    es = exact_set([Polynomial(poly.exponents, sign * poly.coefficients)], [sign * 0.5], 0.2, [-1, -1], [1, 1])
    assert es.fraction == pytest.approx(np.pi * (0.6 - 0.4) / 4, rel=1e-9)
    assert 0 <= es.fraction_error < 1e-7
    np.testing.assert_allclose(es.spans[["lower", "upper"]].to_numpy(),
                               [[-np.sqrt(0.6), np.sqrt(0.6)]] * 2, rtol=1e-10)


def test_annulus_clipped_by_the_box():
    # off-centre annulus, cut by the edge a = 1; reference: scipy.quad of analytic chord lengths
    ca, cb, r1, r2 = 0.7, 0.2, np.sqrt(0.4), np.sqrt(0.6)

    def chord(a):
        def inside(r):
            h2 = r * r - (a - ca) ** 2
            if h2 <= 0:
                return 0.0
            h = np.sqrt(h2)
            return max(0.0, min(1.0, cb + h) - max(-1.0, cb - h))
        return inside(r2) - inside(r1)

    area, _ = integrate.quad(chord, -1, 1, points=[ca - r2, ca - r1, ca + r1, ca + r2], epsabs=1e-13,
                             epsrel=1e-12, limit=200)
    es = exact_set([squares(2, [ca, cb])], [0.5], 0.2, [-1, -1], [1, 1])
    assert es.fraction == pytest.approx(area / 4, rel=1e-7)
    np.testing.assert_allclose(es.model_spans, [[ca - r2, 1.0], [cb - r2, cb + r2]], rtol=1e-10, atol=1e-12)


def test_thin_band_across_the_box():
    # |a + 2b - 1.5| <= 1.5 eps: a strip 1e-3 of the range wide, at 63 degrees to the axes
    eps = 1e-3 * np.sqrt(5) / 3
    c_lo, c_hi = 1.5 * (1 - eps), 1.5 * (1 + eps)
    es = exact_set([quadratic(a=1, b=2)], [1.5], eps, [0, 0], [1, 1])
    exact = strip_area_below(1, 2, c_hi) - strip_area_below(1, 2, c_lo)
    assert es.fraction == pytest.approx(exact, rel=1e-7)
    np.testing.assert_allclose(es.model_spans, [[0, 1], [(c_lo - 1) / 2, c_hi / 2]], rtol=1e-9)


def test_thin_band_nearly_parallel_to_the_lines():
    # |b + 0.02 a - 0.5| <= 0.5 eps: a band 1e-3 thick across b, almost parallel to a
    eps = 1e-3
    es = exact_set([quadratic(a=0.02, b=1)], [0.5], eps, [0, 0], [1, 1])
    assert es.fraction == pytest.approx(eps, rel=1e-7)
    np.testing.assert_allclose(es.model_spans, [[0, 1], [0.5 * (1 - eps) - 0.02, 0.5 * (1 + eps)]], rtol=1e-9)


WEDGE = dict(polys=[quadratic(a=1, b=1), quadratic(a=1, b=1.1)], targets=[1.0, 1.05], eps=0.02)
# the two bands a + b in [0.98, 1.02] and a + 1.1 b in [1.029, 1.071] cross in a thin parallelogram
WEDGE_VERTICES = np.array([[0.49, 0.49], [0.93, 0.09], [0.51, 0.51], [0.07, 0.91]])


def test_wedge_tips():
    es = exact_set(WEDGE["polys"], WEDGE["targets"], WEDGE["eps"], [0, 0], [1, 1])
    assert es.fraction == pytest.approx(0.04 * 0.042 / 0.1, rel=1e-8)
    np.testing.assert_allclose(es.model_spans, [[0.07, 0.93], [0.09, 0.91]], rtol=1e-9)


@pytest.mark.parametrize("ref", [[0.97, 0.05], [0.95, 0.12], [0.3, 0.3], [0.02, 0.99]])
def test_wedge_reference_distance(ref):
    es = exact_set(WEDGE["polys"], WEDGE["targets"], WEDGE["eps"], [0, 0], [1, 1], reference=ref)
    edges = zip(WEDGE_VERTICES, np.roll(WEDGE_VERTICES, -1, axis=0))
    exact = min(segment_distance(ref, a, b) for a, b in edges)
    assert es.reference_distance == pytest.approx(exact, rel=1e-6)
    assert np.linalg.norm(es.nearest_point - ref) == pytest.approx(exact, rel=1e-6)
    for poly, target in zip(WEDGE["polys"], WEDGE["targets"]):
        assert abs(poly(es.nearest_point)[0] - target) <= WEDGE["eps"] * target * (1 + 1e-9)


def test_disk_distance_on_a_scaled_box():
    # y = a^2 + b^2 <= 0.5 (target 0.25 at 100 %) on [-1, 1] x [-2, 2]: distance in fractions of each range
    es = exact_set([squares(2)], [0.25], 1.0, [-1, -2], [1, 2], reference=[0.9, -1.6])
    # in unit coordinates the disk is an ellipse; the nearest point solves the Lagrange condition exactly:
    # minimise ((x - 0.9)/2)^2 + ((y + 1.6)/4)^2 on x^2 + y^2 = 0.5, parametrised by angle
    theta = np.linspace(0, 2 * np.pi, 2_000_001)
    x, y = np.sqrt(0.5) * np.cos(theta), np.sqrt(0.5) * np.sin(theta)
    d = np.hypot((x - 0.9) / 2, (y + 1.6) / 4)
    assert es.reference_distance == pytest.approx(d.min(), rel=1e-8)
    np.testing.assert_allclose(es.nearest_point, [x[np.argmin(d)], y[np.argmin(d)]], atol=1e-5)


def test_reference_inside_and_empty_set():
    es = exact_set([squares(2)], [0.5], 0.2, [-1, -1], [1, 1], reference=[0.0, 0.7])
    assert es.reference_distance == 0.0
    np.testing.assert_allclose(es.nearest_point, [0.0, 0.7])
    empty = exact_set([squares(2)], [5.0], 0.1, [-1, -1], [1, 1], reference=[0.0, 0.0])
    assert empty.fraction == 0.0 and empty.fraction_error == 0.0
    assert empty.spans[["lower", "upper", "width"]].isna().all().all()
    assert empty.reference_distance == np.inf


def test_cubic_band():
    # b (1 + 0.3 a) + a^3 - 0.4 a^2 in [0.45, 0.55]: a cubic along lines in a; chord lengths in b are explicit
    poly = Polynomial([[0, 1], [3, 0], [1, 1], [2, 0]], [1.0, 1.0, 0.3, -0.4])
    es = exact_set([poly], [0.5], 0.1, [0, 0], [1, 1])

    def chord(a):
        k, base = 1 + 0.3 * a, a ** 3 - 0.4 * a ** 2
        return max(0.0, min(1.0, (0.55 - base) / k) - max(0.0, (0.45 - base) / k))

    area, _ = integrate.quad(chord, 0, 1, epsabs=1e-14, epsrel=1e-13, limit=200)
    assert es.fraction == pytest.approx(area, rel=1e-8)
    # the band leaves the box through b = 0 where a^3 - 0.4 a^2 = 0.55
    a_end = max(r.real for r in np.roots([1, -0.4, 0, -0.55]) if abs(r.imag) < 1e-12)
    np.testing.assert_allclose(es.model_spans, [[0, a_end], [0, 0.55]], rtol=1e-9, atol=1e-12)


def test_one_factor():
    # y = a^2 on [-1, 1], target 0.5 at 20 %: |a| in [sqrt(0.4), sqrt(0.6)]
    es = exact_set([Polynomial([[2]], [1.0])], [0.5], 0.2, [-1], [1], reference=[0.1])
    assert es.fraction == pytest.approx(np.sqrt(0.6) - np.sqrt(0.4), rel=1e-12)
    np.testing.assert_allclose(es.model_spans, [[-np.sqrt(0.6), np.sqrt(0.6)]], rtol=1e-12)
    assert es.reference_distance == pytest.approx((np.sqrt(0.4) - 0.1) / 2, rel=1e-12)


# --------------------------------------------------------------------------- two factors, against numpy.roots
def _u_ridge():
    # a thin U-shaped ridge (like Poraver's angle of repose: b-width 0.01) and a product band
    # (like its shape factor) that cuts one arm off in a wedge-like end
    ridge = lambda a, b: 10 + 40 * (b - 0.35 - 0.8 * (a - 0.55) ** 2)  # noqa: E731
    product = lambda a, b: 10 + a * b  # noqa: E731
    polys = [quadratic(c0=10 + 40 * (-0.35 - 0.8 * 0.55 ** 2), a=40 * 0.8 * 1.1, b=40, aa=-40 * 0.8),
             quadratic(c0=10, ab=1)]
    return polys, [ridge, product], [10.0, 10.3]


def test_u_ridge_against_numpy_roots():
    polys, funcs, targets = _u_ridge()
    eps = 0.02
    es = exact_set(polys, targets, eps, [0, 0], [1, 1])
    # midpoint rule of exact line lengths across the ridge, at two resolutions to bound its own error
    coarse = roots_fraction(funcs, targets, eps, 1000, axis=1)
    fine = roots_fraction(funcs, targets, eps, 2000, axis=1)
    assert abs(fine - coarse) < 1e-4 * fine  # the reference is good to well under 0.1 %
    assert es.fraction == pytest.approx(fine, rel=FRACTION_RTOL / 3)
    assert es.fraction_error < 1e-6 * es.fraction
    for coord in (0, 1):
        lower, upper, resolution = roots_span(funcs, targets, eps, coord)
        assert resolution < 1e-5
        width = upper - lower
        assert es.model_spans[coord, 0] == pytest.approx(lower, abs=WIDTH_RTOL * width / 4)
        assert es.model_spans[coord, 1] == pytest.approx(upper, abs=WIDTH_RTOL * width / 4)


# --------------------------------------------------------------------------- three factors
def test_ball_fraction_spans_distance():
    r = np.sqrt(0.4)
    ref = np.array([0.9, 0.8, -0.7])
    es = exact_set([squares(3)], [0.2], 1.0, [-1] * 3, [1] * 3, reference=ref)
    assert es.fraction == pytest.approx(4 / 3 * np.pi * r ** 3 / 8, rel=FRACTION_RTOL / 10)
    np.testing.assert_allclose(es.model_spans, [[-r, r]] * 3, rtol=WIDTH_RTOL / 10)
    assert es.reference_distance == pytest.approx((np.linalg.norm(ref) - r) / 2, rel=DISTANCE_RTOL / 100)
    np.testing.assert_allclose(es.nearest_point, ref / np.linalg.norm(ref) * r, atol=1e-5)


def test_shell_fraction_and_spans():
    r1, r2 = np.sqrt(0.4), np.sqrt(0.6)
    es = exact_set([squares(3, [0.1, 0.0, -0.1])], [0.5], 0.2, [-1] * 3, [1] * 3)
    assert es.fraction == pytest.approx(4 / 3 * np.pi * (r2 ** 3 - r1 ** 3) / 8, rel=FRACTION_RTOL / 10)
    assert es.fraction_error < FRACTION_RTOL * es.fraction
    np.testing.assert_allclose(es.model_spans, [[0.1 - r2, 0.1 + r2], [-r2, r2], [-0.1 - r2, -0.1 + r2]],
                               rtol=WIDTH_RTOL / 10)


def test_thin_slab_3d():
    # |c + 0.3 a - 0.5| <= 0.5 eps on [0, 1]^3: a slab 1e-3 thick in c, tilted in a
    eps = 1e-3
    poly = Polynomial([[0, 0, 1], [1, 0, 0]], [1.0, 0.3])
    es = exact_set([poly], [0.5], eps, [0] * 3, [1] * 3)
    assert es.fraction == pytest.approx(eps, rel=FRACTION_RTOL / 10)
    np.testing.assert_allclose(es.model_spans, [[0, 1], [0, 1], [0.5 * (1 - eps) - 0.3, 0.5 * (1 + eps)]],
                               rtol=WIDTH_RTOL / 10)


def test_shell_cut_by_a_slab_3d():
    # shell r^2 in [0.225, 0.275] (target 0.25 at 10 %) cut by the slab |a - 0.45| <= 0.045:
    # volume = int over the slab of the exact annulus areas; nearest point to (0, 0.3, 0) on the slab face
    slab = Polynomial([[1, 0, 0]], [1.0])
    ref = np.array([0.0, 0.3, 0.0])
    es = exact_set([squares(3), slab], [0.25, 0.45], 0.1, [-1] * 3, [1] * 3, reference=ref)
    lo, hi = 0.405, 0.495
    r1, r2 = np.sqrt(0.225), np.sqrt(0.275)
    area = lambda a, r: np.pi * max(r * r - a * a, 0.0)  # noqa: E731
    volume, _ = integrate.quad(lambda a: area(a, r2) - area(a, r1), lo, hi, points=[r1], epsabs=1e-14)
    assert es.fraction == pytest.approx(volume / 8, rel=FRACTION_RTOL / 10)
    assert es.model_spans[0] == pytest.approx([lo, hi], rel=1e-9)
    reach = np.sqrt(r2 * r2 - lo * lo)  # the widest circle of the set lies on the face a = lo
    np.testing.assert_allclose(es.model_spans[1:], [[-reach, reach], [-reach, reach]], rtol=WIDTH_RTOL / 10)
    assert es.reference_distance == pytest.approx(lo / 2, rel=DISTANCE_RTOL / 100)
    np.testing.assert_allclose(es.nearest_point, [lo, 0.3, 0.0], atol=1e-6)


# positions midway between the nodes of a 65-slice scan (k / 64) and off the nodes of a 41^3 grid
MID_NODES = np.array([19.5, 25.5, 38.5, 45.5]) / 64


def test_needle_3d():
    # two thin slabs cross in a needle along a, 1.3e-3 x 2.4e-3 of the range in cross-section
    eps = 2e-3
    b0, c0 = MID_NODES[1], MID_NODES[2]
    slab_b = Polynomial([[0, 1, 0]], [1.0])  # |b - b0| <= b0 eps
    slab_c = Polynomial([[0, 0, 1], [1, 0, 0]], [1.0, 1e-3])  # |c + 0.001 a - c0| <= c0 eps
    es = exact_set([slab_b, slab_c], [b0, c0], eps, [0] * 3, [1] * 3)
    assert es.fraction == pytest.approx((2 * b0 * eps) * (2 * c0 * eps), rel=FRACTION_RTOL / 10)
    np.testing.assert_allclose(es.model_spans, [[0, 1], [b0 * (1 - eps), b0 * (1 + eps)],
                                                [c0 * (1 - eps) - 1e-3, c0 * (1 + eps)]], rtol=1e-9)


def test_tiny_ball_3d():
    # a ball of radius 0.005 (half a percent of the range) that no scanned slice or grid node meets
    center = MID_NODES[[0, 2, 3]]
    r = np.sqrt(2.5e-5)
    es = exact_set([squares(3, center)], [1e-5], 1.5, [0] * 3, [1] * 3, reference=[0.5, 0.5, 0.5])
    assert es.fraction == pytest.approx(4 / 3 * np.pi * r ** 3, rel=FRACTION_RTOL / 10)
    np.testing.assert_allclose(es.model_spans, np.column_stack([center - r, center + r]), rtol=1e-8)
    gap = np.linalg.norm(center - 0.5)
    assert es.reference_distance == pytest.approx(gap - r, rel=DISTANCE_RTOL / 100)


# --------------------------------------------------------------------------- log-scale factors and the adapter
def test_surrogate_adapter_with_a_log_factor():
    # y = (log10 x)^2 + w^2 over x in [0.1, 10], w in [-1, 1]: the annulus in model coordinates
    coef = np.array([0, 0, 0, 0, 1.0, 1.0])
    sur = Surrogate("y", ["x", "w"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7, log_factors=("x",))
    poly = polynomial_from_surrogate(sur)
    z = np.array([[0.3, -0.2], [-0.7, 0.9]])
    np.testing.assert_allclose(poly(z), sur.predict(np.column_stack([10 ** z[:, 0], z[:, 1]])))
    domain = Domain(("x", "w"), (0.1, -1.0), (10.0, 1.0), (True, False))
    es = exact_set_for_surrogates({"y": sur}, ["y"], {"y": 0.5}, 0.2, domain, reference={"x": 1.0, "w": 0.0})
    assert es.fraction == pytest.approx(np.pi * 0.2 / 4, rel=1e-9)
    r2 = np.sqrt(0.6)
    np.testing.assert_allclose(es.spans[["lower", "upper"]].to_numpy(), [[10 ** -r2, 10 ** r2], [-r2, r2]],
                               rtol=1e-9)
    assert es.reference_distance == pytest.approx(np.sqrt(0.4) / 2, rel=1e-8)
    frame = es.to_frame()
    assert list(frame["factor"]) == ["x", "w"]
    assert {"lower", "upper", "width", "feasible_fraction", "fraction_error", "reference_distance",
            "nearest_point"} <= set(frame.columns)


def test_bad_arguments():
    with pytest.raises(ValueError):
        exact_set([squares(2)], [0.0], 0.1, [-1, -1], [1, 1])
    with pytest.raises(ValueError):
        exact_set([squares(2)], [1.0], 0.1, [-1, -1, -1, -1], [1, 1, 1, 1])
    with pytest.raises(ValueError):
        exact_set([squares(3)], [1.0], 0.1, [-1, -1], [1, 1])
    with pytest.raises(ValueError):
        exact_set([squares(2)], [1.0], 0.1, [-1, -1], [1, 1], reference=[0.0])
    for lower in ([1, -1], [-1, 1], [2, -1]):  # one factor's range empty or reversed
        with pytest.raises(ValueError, match="lower < upper"):
            exact_set([squares(2)], [1.0], 0.1, lower, [1, 1])


# --------------------------------------------------------------------------- the demonstration study
@pytest.fixture(scope="module")
def demo():
    from demid.config import load_config
    from demid.data import validate_material
    from demid.surrogate import fit_material

    config = load_config(ROOT / "config.yaml", base_dir=ROOT)

    def material(name):
        cfg = config["materials"][name]
        spec = MaterialSpec.from_config(name, config)
        table = validate_material(spec, base_dir=ROOT).table
        surrogates = {f.response: f.surrogate() for f in fit_material(table, spec)}
        return cfg, surrogates, spec.targets, spec.domain

    return material


def test_demo_mortar_full_sequence(demo):
    cfg, surrogates, targets, domain = demo("mortar")
    scen = cfg["scenarios"]["full_sequence"]
    es = exact_set_for_surrogates(surrogates, scen["observables"], targets, scen["tolerance"], domain,
                                  reference=cfg["reference_point"])
    lo = np.array([cfg["factors"][f]["lower"] for f in ("mu_r", "gamma")])
    hi = np.array([cfg["factors"][f]["upper"] for f in ("mu_r", "gamma")])
    obs = scen["observables"]
    funcs = [lambda a, b, o=o: surrogates[o].predict(np.column_stack([lo[0] + a * (hi[0] - lo[0]),
                                                                      lo[1] + b * (hi[1] - lo[1])]))
             for o in obs]
    tgt = [targets[o] for o in obs]
    g_lo, g_hi, resolution = roots_span(funcs, tgt, scen["tolerance"], 1)
    width = (g_hi - g_lo) * (hi[1] - lo[1])
    assert es.spans["width"].iloc[1] == pytest.approx(width, rel=WIDTH_RTOL / 5)
    assert round(es.spans["width"].iloc[1], 5) == 0.37856  # exact
    # distance: lines along mu_r through the whole gamma span, nearest admissible point on each
    ref = (np.array([cfg["reference_point"]["mu_r"], cfg["reference_point"]["gamma"]]) - lo) / (hi - lo)
    best = np.inf
    gammas = np.linspace(g_lo, g_hi, 1001)
    for b, line in zip(gammas, roots_line_intervals(funcs, tgt, scen["tolerance"], gammas, 0)):
        for a0, a1 in line:
            best = min(best, np.hypot(np.clip(ref[0], a0, a1) - ref[0], b - ref[1]))
    assert es.reference_distance == pytest.approx(best, rel=DISTANCE_RTOL / 10)
    assert round(100 * es.reference_distance, 2) == 3.94  # exact
    np.testing.assert_allclose(es.nearest_point, [0.1666, 6.3998], atol=1e-4)


def test_demo_paste_diameter_only(demo):
    cfg, surrogates, targets, domain = demo("paste")
    scen = cfg["scenarios"]["diameter_only"]
    es = exact_set_for_surrogates(surrogates, scen["observables"], targets, scen["tolerance"], domain)
    # reference: lines along mu_s on a 300 x 300 midpoint grid of (mu_r, gamma), line intervals from the
    # quadratic formula (vectorised, written here), at two resolutions to bound the midpoint rule's error
    names = list(cfg["factors"])
    lo = np.array([cfg["factors"][f]["lower"] for f in names])
    hi = np.array([cfg["factors"][f]["upper"] for f in names])
    sur, target, eps = surrogates["D"], targets["D"], scen["tolerance"]

    def fraction(n):
        s = (np.arange(n) + 0.5) / n
        b, c = [x.ravel() for x in np.meshgrid(s, s, indexing="ij")]
        t3 = np.array([0.0, 0.5, 1.0])
        pts = lambda t: np.column_stack([lo[0] + t * (hi[0] - lo[0]), lo[1] + b * (hi[1] - lo[1]),  # noqa: E731
                                         lo[2] + c * (hi[2] - lo[2])])
        v = np.stack([sur.predict(pts(np.full(len(b), t))) for t in t3])
        # quadratic through the three values: p(t) = v0 + (4 v1 - 3 v0 - v2) t + (2 v0 - 4 v1 + 2 v2) t^2
        q0, q1, q2 = v[0], 4 * v[1] - 3 * v[0] - v[2], 2 * v[0] - 4 * v[1] + 2 * v[2]
        cuts = [np.zeros(len(b)), np.ones(len(b))]
        for level in (target * (1 - eps), target * (1 + eps)):
            disc = q1 ** 2 - 4 * q2 * (q0 - level)
            sq = np.sqrt(np.where(disc >= 0, disc, np.nan))
            for r in ((-q1 + sq) / (2 * q2), (-q1 - sq) / (2 * q2)):
                cuts.append(np.where((r > 0) & (r < 1), r, 1.0))
        cuts = np.sort(np.column_stack(cuts), axis=1)
        mids = (cuts[:, 1:] + cuts[:, :-1]) / 2
        ok = np.stack([np.abs(sur.predict(pts(mids[:, j])) - target) <= eps * target for j in range(mids.shape[1])],
                      axis=1)
        return float(np.mean(np.sum(np.diff(cuts, axis=1) * ok, axis=1)))

    coarse, fine = fraction(150), fraction(300)
    assert abs(fine - coarse) < 3e-4 * fine  # second-order rule: the finer one is within ~1e-4
    assert es.fraction == pytest.approx(fine, rel=FRACTION_RTOL / 2)
