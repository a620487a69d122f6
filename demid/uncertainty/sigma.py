"""Measurement sigma of a target: configured ``sigma`` / ``sigma_rel``, or a default.

``sigma`` (absolute) or ``sigma_rel`` (times |y*|) from the response's config.
Plausible sets take the tolerance as the measurement band when neither is configured
(:mod:`demid.tolerance`, :func:`~demid.tolerance.scenario_bands`).  Posteriors need a likelihood width; when neither is configured the default is
``sigma_rel = tolerance / 2``, i.e. the scenario tolerance is read as a two-sigma
(about 95 %) band; outputs say which basis was used (``sigma_basis``).
"""


# =========================================================================== measurement sigma
def measurement_sigma(response_cfg: dict | None, target: float, default_rel: float | None = None) -> float:
    """Absolute measurement standard deviation of one target.

    ``sigma`` wins over ``sigma_rel`` (times |target|); without either,
    ``default_rel * |target|`` when a default is given, else 0.
    """
    cfg = response_cfg or {}
    if cfg.get("sigma") is not None:
        return float(cfg["sigma"])
    if cfg.get("sigma_rel") is not None:
        return float(cfg["sigma_rel"]) * abs(float(target))
    if default_rel is not None:
        return float(default_rel) * abs(float(target))
    return 0.0


def sigma_basis(response_cfg: dict | None, default_rel: float | None = None, z: float = 2.0) -> str:
    """Where :func:`measurement_sigma` took its value from, in words for tables."""
    cfg = response_cfg or {}
    if cfg.get("sigma") is not None:
        return f"config sigma = {float(cfg['sigma']):g}"
    if cfg.get("sigma_rel") is not None:
        return f"config sigma_rel = {float(cfg['sigma_rel']):g}"
    if default_rel is not None:
        return f"default sigma_rel = {float(default_rel):g} (tolerance/{z:g})"
    return "none (surrogate uncertainty only)"


def measurement_sigmas(responses_cfg: dict, observables, targets: dict[str, float],
                       tolerance: float | None = None, z: float = 2.0) -> tuple[dict[str, float], dict[str, str]]:
    """Sigma and its basis for each observable; ``tolerance`` enables the default sigma_rel = tolerance / z
    (the tolerance read as a z-sigma measurement band, as in the plausible set)."""
    default_rel = None if tolerance is None else float(tolerance) / float(z)
    sigma = {o: measurement_sigma(responses_cfg.get(o), targets[o], default_rel) for o in observables}
    basis = {o: sigma_basis(responses_cfg.get(o), default_rel, z) for o in observables}
    return sigma, basis
