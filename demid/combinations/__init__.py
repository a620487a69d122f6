"""What the data identify: parameter combinations of a set (principal axes, a band's curve) and,
per material, of every scenario's strict and plausible set, with the advice that would break a
ridge.  ``axes`` holds the geometry of any set of coded points; ``material`` the per-material step."""

from .axes import (FREE_MIN_WIDTH, IDENTIFIED_MAX_WIDTH, PrincipalAxes, band_curve, curve_bend, linear_statement,
                   principal_axes)
from .material import (MaterialCombinations, SetCombination, admitted_points, break_ridge_advice,
                       material_combinations, plausible_sets, set_combinations)

__all__ = ["FREE_MIN_WIDTH", "IDENTIFIED_MAX_WIDTH", "MaterialCombinations", "PrincipalAxes", "SetCombination",
           "admitted_points", "band_curve", "break_ridge_advice", "curve_bend", "linear_statement",
           "material_combinations", "plausible_sets", "principal_axes", "set_combinations"]
