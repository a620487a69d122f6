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
    for i, v in enumerate(values):
        for digits in range(1, 13):
            scaled = v * 10.0 ** (digits - 1 - exponents[i])
            if abs(scaled - round(scaled)) <= 1e-12 * max(1.0, abs(scaled)):  # what reading the digits leaves
                own[i] = 10.0 ** (exponents[i] - digits + 1)
                break
    return exponents, own


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
