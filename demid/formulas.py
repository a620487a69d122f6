"""Small formulas that several parts of demid use, written once so that they cannot drift apart.

A bottom module: it imports nothing from demid (the replicate rule lives with the design, in
:func:`demid.design.replicate_groups`).
"""

from __future__ import annotations

import numpy as np


def relative_error(value, target):
    """(y - y*) / |y*|: how far a (predicted) response lies from its target, as a fraction of the target.
    Arrays broadcast (targets[:, None] against a block of predictions)."""
    return (value - target) / np.abs(target)


def f_tail(f, dfn, dfd):
    """Upper tail P(F > f) of the F distribution with (dfn, dfd) degrees of freedom, as ``scipy.stats.f.sf``
    gives it (its survival function is ``scipy.special.fdtrc``; imported here on first use, without the second
    ``scipy.stats`` costs at start-up).  NaN where a degree of freedom is not positive or f is not finite; 1 for
    f <= 0.  A scalar for scalar arguments."""
    from scipy.special import fdtrc

    f, dfn, dfd = np.broadcast_arrays(np.asarray(f, dtype=float), np.asarray(dfn, dtype=float),
                                      np.asarray(dfd, dtype=float))
    out = np.full(f.shape, np.nan)
    ok = (dfn > 0) & (dfd > 0) & np.isfinite(f)
    with np.errstate(invalid="ignore"):
        out[ok] = fdtrc(dfn[ok], dfd[ok], np.maximum(f[ok], 0.0))
    return out[()] if out.ndim == 0 else out
