"""Axis text for a paper: config labels and units as matplotlib mathtext, and one palette.

A config label such as ``μ_r,Po`` becomes ``$\\mu_{\\mathrm{r,Po}}$`` (subscript after the first
underscore), a unit such as ``J m^-2`` becomes ``J m$^{-2}$``; a plain key without a label
(``mu_r``, ``gamma``) reads as its Greek letter with a subscript.  No import side effects.
"""

from __future__ import annotations

import re

#: Okabe & Ito (2008): distinguishable with every common colour-vision deficiency and in grey print.
PALETTE = ["#0072B2", "#E69F00", "#009E73", "#CC79A7", "#56B4E9", "#D55E00", "#F0E442", "#000000"]

_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "eta": "η", "theta": "θ",
    "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ", "rho": "ρ", "sigma": "σ", "tau": "τ",
    "phi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ",
    "Phi": "Φ", "Omega": "Ω",
}
_TEX = {v: "\\" + k for k, v in _GREEK.items()}
_SPECIAL = re.compile(r"([#$%&{}])")


def _math(text: str) -> str:
    """Mathtext of a plain fragment: Greek letters as commands, multi-letter words upright."""
    text = _SPECIAL.sub(r"\\\1", text)
    if text in _GREEK:
        return "\\" + text
    if len(text) == 1 and text in _TEX:
        return _TEX[text]
    out = "".join(_TEX.get(ch, ch) + (" " if ch in _TEX else "") for ch in text).strip()
    plain = text.replace(" ", "")
    if len(plain) > 1 and not any(ch in _TEX for ch in text):
        return "\\mathrm{" + out.replace(" ", "\\ ") + "}"
    return out


def tex_label(label: str) -> str:
    """``μ_r,Po`` -> ``$\\mu_{\\mathrm{r,Po}}$``; labels that are prose (spaces, no underscore) stay text."""
    if not label or "$" in label or ("_" not in label and " " in label.strip()):
        return label
    base, _, sub = label.partition("_")
    if not base:
        return label
    body = _math(base)
    if sub:
        sub = sub.replace("_", ",")
        # Subscripts name things (M for mortar, r for rolling): upright, Greek letters as symbols.
        inner = _math(sub) if sub in _GREEK or sub in _TEX else "\\mathrm{" + "".join(
            _TEX.get(ch, ch) for ch in _SPECIAL.sub(r"\\\1", sub)) + "}"
        body += "_{" + inner + "}"
    return f"${body}$"


def tex_unit(unit: str) -> str:
    """``J m^-2`` -> ``J m$^{-2}$``; a dimensionless unit (``-`` or empty) -> ``–``."""
    if not unit or unit.strip() == "-":
        return "–"
    return re.sub(r"\^\{?(-?[0-9.]+)\}?", r"$^{\1}$", unit)


def axis_label(item) -> str:
    """``label [unit]`` in mathtext for a spec Factor or Response (every axis carries a unit)."""
    return f"{tex_label(item.label)} [{tex_unit(item.unit)}]"
