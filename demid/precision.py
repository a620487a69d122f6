"""The precision a printed table carries: the place of each value's last printed digit, and the residual size
below which a fit is exact to that precision (the round-off floor).

A bottom module (it imports nothing from demid) so that reading, design checks, the typo screen and the fit
share one rule.
"""

from __future__ import annotations

import numpy as np


#: ``DataFrame.attrs`` key of a table read from text: per factor column, the place of the finest digit its cells
#: print (trailing zeros kept, which a float loses: 0.900000 is printed to 1e-6, not to 0.1).
PRINTED_PLACE = "printed_place"


def printed_place(cells) -> float:
    """The place of the finest digit any of ``cells`` (strings as printed) shows: 1e-6 for 0.900000, 1 for 83,
    1e-4 for 1.5e-3, 100 for 1.2E+3; 0 when no cell is a number."""
    from decimal import Decimal, InvalidOperation

    exponents = []
    for cell in cells:
        try:
            exponent = Decimal(str(cell).strip().replace("\u2212", "-")).as_tuple().exponent
        except InvalidOperation:
            continue
        if isinstance(exponent, int):
            exponents.append(exponent)
    return float(10.0 ** min(exponents)) if exponents else 0.0


def printed_quantum(y) -> np.ndarray:
    """Per value, the place of its last printed digit (1e-4 for 10.1235; 0 throughout when some value carries
    more than 12 significant digits): the rounding a printed table adds to it is at most half of that.

    A float keeps no trailing zeros (79.9 may have been printed 79.9000, 1200 may be exact to the millimetre),
    so a value is taken to the column's finest place — or, where the column is printed to significant digits
    (-1228 beside 29.18), to the most digits the values show.
    """
    y = np.asarray(y, dtype=float)
    out = np.zeros(y.shape)
    valid = np.isfinite(y) & (y != 0)
    if not valid.any():
        return out
    values = y[valid]
    exponents, own = _own_places(values)
    if np.any(own == 0):
        return out  # a value carries every digit: the column was not rounded for print
    decimals = -np.round(np.log10(own))
    shown = exponents + decimals + 1  # significant digits each value shows
    # Printed to fixed decimals, most values show the most decimals; printed to significant digits, most show
    # the most digits (a lost trailing zero shortens a few either way).  A tie reads decimals: the finer places.
    by_digits = np.sum(shown == shown.max()) > np.sum(decimals == decimals.max())
    # never coarser than units when reading decimals: 1200, 1300 may be exact to the millimetre
    out[valid] = 10.0 ** (exponents - shown.max() + 1) if by_digits else 10.0 ** -max(decimals.max(), 0)
    return out


def _own_places(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per non-zero finite value, the power of ten of its leading digit and the place of its own last
    non-zero digit (0 where it carries more than 12 significant digits)."""
    exponents = np.floor(np.log10(np.abs(values)))
    own = np.zeros(values.shape)
    open_ = np.ones(values.shape, dtype=bool)  # values whose last digit is not found yet
    for digits in range(1, 13):  # all values at once, a digit at a time (a table of 10,000 runs: 120,000 steps)
        with np.errstate(over="ignore", invalid="ignore"):  # digits past a value's own overflow near 1e-300
            scaled = values * _powers_of_ten(digits - 1 - exponents)
            found = open_ & (np.abs(scaled - np.round(scaled)) <= 1e-12 * np.maximum(1.0, np.abs(scaled)))
        own[found] = _powers_of_ten(exponents[found] - digits + 1)  # what reading the digits leaves
        open_ &= ~found
    return exponents, own


def _powers_of_ten(exponents: np.ndarray) -> np.ndarray:
    """10 ** each of ``exponents`` (whole numbers), each power taken once as a scalar: numpy's power over an
    array may differ from the scalar one in the last bit (1e-05 against 9.999999999999999e-06)."""
    distinct, index = np.unique(exponents, return_inverse=True)
    return np.array([10.0 ** e for e in distinct], dtype=float)[index.reshape(np.shape(exponents))]


#: A factor value shows at least this many significant digits before its print is read as a rounding.
ROUNDED_FACTOR_DIGITS = 4


def factor_print_quantum(x) -> np.ndarray:
    """Per factor value, the rounding its print may hide: the column's last printed place for a value that
    reaches that place in a column printed to at least :data:`ROUNDED_FACTOR_DIGITS` significant digits
    (0.075736, a level derived from alpha), 0 for a value a person set (2, 14, 0.5 beside 0.075736): the
    simulation ran at that very value."""
    x = np.asarray(x, dtype=float)
    quantum = printed_quantum(x)
    out = np.zeros(x.shape)
    valid = np.isfinite(x) & (x != 0) & (quantum > 0)
    if not valid.any():
        return out
    exponents, own = _own_places(x[valid])
    shown = exponents - np.log10(quantum[valid]) + 1  # significant digits at the column's place
    rounded = (np.abs(own / quantum[valid] - 1) < 1e-6) & (shown.max() >= ROUNDED_FACTOR_DIGITS)
    out[valid] = np.where(rounded, quantum[valid], 0.0)
    return out


def factor_round_off_sd(gradient: np.ndarray, x_actual: np.ndarray, unit, log_scale) -> np.ndarray:
    """Per run, the standard deviation of the response error that printing the factors adds: a factor value
    rounded to its column's last printed place q is off by up to q/2 (variance q^2/12), and the response moves
    by the fitted gradient times that.  ``gradient`` (n, k) is in coded units per coded unit, ``unit`` the coded
    unit of each factor in model units; ``log_scale[j]`` marks factors fitted in log10 (a rounding of q at x is
    q / (x ln 10) in log10 units).  Only values whose print looks rounded count (:func:`factor_print_quantum`)."""
    x_actual = np.asarray(x_actual, dtype=float)
    variance = np.zeros(len(x_actual))
    for j in range(x_actual.shape[1]):
        quantum = factor_print_quantum(x_actual[:, j])
        if log_scale[j]:
            quantum = quantum / (np.abs(x_actual[:, j]) * np.log(10.0))
        variance += (gradient[:, j] * quantum / abs(unit[j])) ** 2 / 12.0
    return np.sqrt(variance)


# Residuals smaller than this share of the response's magnitude are floating-point round-off
# (an exact polynomial, a deterministic simulator's identical replicates), not scatter to test.
ROUND_OFF = 1e-9


def round_off_floor(y, factor_sd=None) -> float:
    """Residual size below which a fit of ``y`` is exact to working precision — or to the precision the table
    was printed to: that of ``y`` and, given ``factor_sd`` (per run, see :meth:`demid.surrogate.SurrogateFit.factor_round_off`),
    that of the factors, carried through the fitted gradient."""
    y = np.asarray(y, dtype=float)
    if not y.size:
        return 0.0
    # Rounding to a place q adds errors of root mean square q / sqrt(12); a fit's residuals keep about half
    # of that. 1.5 times the full variance is exceeded by rounding alone about once in 250 tables of 13 runs,
    # while a miss of 0.4 of the last digit still counts as a miss.
    variance = printed_quantum(y) ** 2 / 12
    if factor_sd is not None:
        variance = variance + np.asarray(factor_sd, dtype=float) ** 2
    printed = float(np.sqrt(1.5 * np.mean(variance)))
    return max(ROUND_OFF * float(np.max(np.abs(y))), printed)


def round_off_only(residuals, y, factor_sd=None) -> bool:
    """True when the residuals are round-off: their root mean square is below :func:`round_off_floor`."""
    residuals = np.asarray(residuals, dtype=float)
    return bool(residuals.size) and float(np.sqrt(np.mean(residuals ** 2))) <= round_off_floor(y, factor_sd)


# --------------------------------------------------------------------------- the digits a printed number carries
# The report's one rule for printing a number: to the digits its uncertainty supports — the place of the second
# significant digit of its standard error (or of the tolerance, for a quantity a person set) — never more than
# MAX_DIGITS significant digits; an effect that rounds to zero at that place is written as indistinguishable
# from zero; a relative difference past FAR_RATIO is written as such, not as a percentage of five digits; a
# number read off a surrogate that does not predict left-out runs (Q² < 0) gets UNPREDICTIVE_DIGITS, and the
# sentence that quotes it says why.

#: Significant digits of an uncertainty (standard error, half-width, tolerance) as printed.
UNCERTAINTY_DIGITS = 2
#: Significant digits a value is never printed beyond (a fit's estimate, a predicted value).
MAX_DIGITS = 4
#: A relative difference beyond this many times the reference is written "more than 10×".
FAR_RATIO = 10.0
#: A proposed run's coordinate is written to this share of its factor's range: finer than a simulation's input
#: resolves, coarser than six digits of a float.
COORDINATE_RESOLUTION = 1e-3
#: The smallest p-value printed as a number; below it "< 0.0001".
SMALLEST_P = 1e-4
#: How an effect indistinguishable from zero is written.
ZERO = "≈ 0"
#: Significant digits of a number read off a surrogate that does not predict left-out runs (Q² < 0): its
#: leave-one-out error exceeds the spread of the runs themselves, so no more than the order of magnitude holds.
UNPREDICTIVE_DIGITS = 1


def place_of(uncertainty: float, digits: int = UNCERTAINTY_DIGITS) -> float:
    """The power of ten of ``uncertainty``'s ``digits``-th significant digit once rounded to them: 0.001 for
    0.093, 1 for 12, 0.01 for 0.0998 (which rounds to 0.10)."""
    rounded = float(f"{abs(uncertainty):.{digits}g}")
    return float(10.0 ** (np.floor(np.log10(rounded)) - digits + 1))


def _minus(text: str) -> str:
    """A leading minus as the typographic one (an exponent's stays ASCII)."""
    return "−" + text[1:] if text.startswith("-") else text


def at_place(value: float, place: float) -> str:
    """``value`` rounded to ``place`` (a power of ten), written with exactly the decimals that place shows."""
    decimals = max(0, int(-np.floor(np.log10(place) + 1e-9)))
    rounded = round(value / place) * place
    return _minus(f"{rounded:.{decimals}f}") if rounded != 0 else "0"


def uncertainty_text(uncertainty: float) -> str:
    """A standard error, half-width or tolerance to :data:`UNCERTAINTY_DIGITS` significant digits."""
    if not np.isfinite(uncertainty):
        return "–"
    if uncertainty == 0:
        return "0"
    if abs(uncertainty) >= 10 ** (UNCERTAINTY_DIGITS + 2) or abs(uncertainty) < 1e-4:
        return _minus(f"{uncertainty:.{UNCERTAINTY_DIGITS}g}")
    return at_place(uncertainty, place_of(uncertainty))


def value_text(value: float, uncertainty: float | None = None, max_digits: int = MAX_DIGITS) -> str:
    """``value`` to the digits ``uncertainty`` supports (at most ``max_digits`` significant); :data:`ZERO`
    where it rounds to zero at that place (the data cannot tell it from zero), exactly half the place included:
    it rounds to even, to zero."""
    if value is None or not np.isfinite(value):
        return "–"
    own = place_of(value, max_digits) if value != 0 else 0.0
    if uncertainty is None or not np.isfinite(uncertainty) or uncertainty <= 0:
        return _minus(f"{value:.{max_digits}g}") if value != 0 else "0"
    place = max(place_of(uncertainty), own)
    if abs(value) <= place / 2:
        return ZERO
    if abs(value) >= 10 ** (max_digits + 2) or abs(value) < 1e-4:
        digits = max(1, int(np.floor(np.log10(abs(value))) - np.log10(place) + 1))
        return _minus(f"{value:.{digits}g}")
    return at_place(value, place)


def rough_text(value: float) -> str:
    """A number read off a surrogate that does not predict, to :data:`UNPREDICTIVE_DIGITS` significant digit
    (12.34 → 10, 0.0345 → 0.03, 1234 → 1000)."""
    if value is None or not np.isfinite(value):
        return "–"
    if value == 0:
        return "0"
    if abs(value) >= 10 ** (MAX_DIGITS + 2) or abs(value) < 1e-4:
        return _minus(f"{value:.{UNPREDICTIVE_DIGITS}g}")
    return at_place(value, place_of(value, UNPREDICTIVE_DIGITS))


def pm_text(value: float, uncertainty: float) -> str:
    """``value ± uncertainty``, each to the digits the uncertainty supports."""
    shown = value_text(value, uncertainty)
    return f"{'0' if shown == ZERO else shown} ± {uncertainty_text(uncertainty)}"


def p_text(p: float) -> str:
    """A p-value to two significant digits, below :data:`SMALLEST_P` as "< 0.0001"."""
    if p is None or not np.isfinite(p):
        return "–"
    return f"< {SMALLEST_P:g}" if p < SMALLEST_P else f"{p:.2g}"


def counted(n: int, noun: str) -> str:
    """"1 wave", "3 waves": a count with its noun in the number it takes (regular plurals only)."""
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def q2_text(q2: float) -> str:
    """A Q² (or R²) to two decimals, with as many more as it takes not to print a value below 1 as "1.00"
    (0.9966 → "0.997": a perfect prediction is a claim the runs do not make); "undefined" when not finite."""
    if q2 is None or not np.isfinite(q2):
        return "undefined"
    for places in range(2, 7):
        text = f"{q2:.{places}f}"
        if q2 >= 1 or float(text) < 1:
            return text
    return "> 0.999999"


def percent_text(fraction: float, digits: int = 3) -> str:
    """A relative difference (a fraction) as a percentage to ``digits`` significant digits; "0 %" for none,
    "< 0.01 %" for a trace, "more than 10×" past :data:`FAR_RATIO` (a percentage of five digits says nothing
    a reader can use)."""
    if fraction is None or not np.isfinite(fraction):
        return "–"
    size = abs(fraction)
    if size > FAR_RATIO:
        return f"more than {FAR_RATIO:g}×"
    if size == 0:
        return "0 %"
    if size < 1e-4:
        return "< 0.01 %"
    text = f"{100 * fraction:.{digits}g}"
    if "e" in text:  # rounded up to 10**digits % (999.5 % and up): "1000 %", not "1e+03 %"
        text = f"{100 * fraction:.0f}"
    return _minus(f"{text} %")


def coordinate_text(value: float, lower: float, upper: float) -> str:
    """A proposed run's factor value to :data:`COORDINATE_RESOLUTION` of its range (what a simulation input
    resolves): 0.0757 for 0.075736 in [0.0757, 0.924]."""
    if not np.isfinite(value):
        return "–"
    span = abs(upper - lower) or abs(value) or 1.0
    return at_place(value, float(10.0 ** np.floor(np.log10(COORDINATE_RESOLUTION * span))))


#: Significant digits of a share of Omega in a "before → after" pair, and the most it takes to tell them apart.
SHARE_DIGITS, SHARE_DIGITS_MAX = 3, 6


def shares_apart(before: float, after: float) -> tuple[str, str]:
    """Two shares to :data:`SHARE_DIGITS` significant digits, or to as many more (up to :data:`SHARE_DIGITS_MAX`)
    as make them read apart where they differ: "1.606 % → 1.613 %", not "1.61 % → 1.61 %" beside a +0.4 %
    change (the loop's stop line and the advice print a wave's shares this way)."""
    for digits in range(SHARE_DIGITS, SHARE_DIGITS_MAX + 1):
        texts = f"{before:.{digits}g}", f"{after:.{digits}g}"
        if texts[0] != texts[1] or before == after:
            break
    return texts


def shares_change_text(before: float, after: float) -> str:
    """"before % → after %", the two shares read apart (:func:`shares_apart`)."""
    return " % → ".join(shares_apart(before, after)) + " %"
