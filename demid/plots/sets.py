"""Admissible-set figures (paper Figs. 3 and 5).

Sets are drawn cell by cell from the evaluation grid.  When the grid is finer
than the figure, cells are max-pooled into pixels so a narrow band or ridge
stays visible instead of being averaged away.
"""

from __future__ import annotations

from itertools import combinations
from typing import TYPE_CHECKING

import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch, Rectangle

from .labels import axis_label, tex_label
from .layout import panel_grid
from .style import MAX_PIXELS, plt, SCENARIO_COLORS, _axis_scale, _extent, styled

ZOOM_PIXELS = 600  # nodes per side of the zoom panel's own grid (the panel is ~4 in wide at 300 dpi)

if TYPE_CHECKING:
    from ..sampling import AdmissibleSet
    from ..spec import MaterialSpec


def _pool(mask: np.ndarray, max_pixels: int = MAX_PIXELS) -> np.ndarray:
    """Max-pool a boolean 2-D mask so that no side exceeds ``max_pixels``."""
    out = mask
    for axis in (0, 1):
        n = out.shape[axis]
        if n > max_pixels:
            block = int(np.ceil(n / max_pixels))
            pad = (-n) % block
            widths = [(0, 0), (0, 0)]
            widths[axis] = (0, pad)
            padded = np.pad(out, widths, constant_values=False)
            shape = list(padded.shape)
            shape[axis] = shape[axis] // block
            shape.insert(axis + 1, block)
            out = padded.reshape(shape).any(axis=axis + 1)
    return out


def _cell_mask(result: AdmissibleSet, n: int, d: int) -> np.ndarray:
    if result.cell_fraction is not None:
        return np.asarray(result.cell_fraction) > 0
    return result.mask.reshape((n,) * d)


def _zoom_box(domain, sets: dict, n: int, thin: float = 0.35, keep=None):
    """Search-unit box around every admissible cell (padded), when the sets fill less than ``thin``
    of the range along an axis; None when they are wide enough to read or empty."""
    lo, hi = domain.search_bounds()
    masks = []
    for result in sets.values():
        if result.points is not None:
            return None
        cells = _cell_mask(result, n, 2)
        if cells.any():
            masks.append(cells)
    if not masks:
        return None

    def bbox(mask):
        out = []
        for axis in (0, 1):
            idx = np.flatnonzero(mask.any(axis=1 - axis))
            out.append(tuple(lo[axis] + (hi[axis] - lo[axis]) * np.array([idx[0], idx[-1] + 1]) / n))
        return out

    def is_thin(box):
        return min((b - a) / (hi[k] - lo[k]) for k, (a, b) in enumerate(box)) < thin

    # All sets if together they are thin, else the smallest set (it is drawn last, on top).
    box = bbox(np.logical_or.reduce(masks))
    if not is_thin(box):
        box = bbox(min(masks, key=lambda m: m.sum()))
        if not is_thin(box):
            return None
    if keep is not None:  # the reference point stays in view
        box = [(min(a, keep[k]), max(b, keep[k])) for k, (a, b) in enumerate(box)]
    out = []
    for k, (a, b) in enumerate(box):
        pad = max(0.15 * (b - a), 0.01 * (hi[k] - lo[k]))
        out.append((max(lo[k], a - pad), min(hi[k], b + pad)))
    return out


def _zoom_mask(judged, box, pixels: int = ZOOM_PIXELS) -> np.ndarray:
    """The judged scenario's strict set (:meth:`~demid.scenario.JudgedScenario.contains`) on a fine grid over
    the zoom box (rows = y), so the zoomed panel is drawn at the figure's resolution rather than the
    evaluation grid's."""
    (x0, x1), (y0, y1) = box
    xs, ys = np.linspace(x0, x1, pixels), np.linspace(y0, y1, pixels)
    gx, gy = np.meshgrid(xs, ys)
    points = judged.spec.domain.to_actual(np.column_stack([gx.ravel(), gy.ravel()]))
    return judged.contains(points, plausible=False).reshape(pixels, pixels)


@styled
def sets_figure(spec: MaterialSpec, sets: dict[str, AdmissibleSet], n: int, judged: dict | None = None
                ) -> plt.Figure:
    """Overlay of every scenario's admissible set (pairwise projections for d > 2).  With ``judged`` (name ->
    :class:`~demid.scenario.JudgedScenario`), a thin 2-factor set's zoom panel is redrawn from its surrogates
    on a fine grid over the zoomed box, not from the evaluation grid's enlarged cells."""
    domain, reference_point, title = spec.domain, spec.reference_point, spec.label
    scenario_labels = {sc.name: sc.label for sc in spec.scenarios}
    d = domain.dim
    pairs = list(combinations(range(d), 2)) if d > 1 else [(0, 0)]
    keep = (domain.to_search(np.array([[reference_point[f] for f in domain.factors]]))[0]
            if reference_point else None)
    zoom = _zoom_box(domain, sets, n, keep=keep) if d == 2 else None
    if zoom is not None:  # a thin set: the same pair again, zoomed on the sets
        pairs = pairs + pairs
    nrow, ncol, (width, height) = panel_grid(len(pairs), 3.5, 3.1)
    legend_in = 0.2 + 0.17 * (len(sets) + bool(reference_point))  # one legend line per scenario
    fig, grid_axes = plt.subplots(nrow, ncol, figsize=(width, height + legend_in), squeeze=False)
    axes = grid_axes.reshape(1, -1)
    for ax in axes[0][len(pairs):]:
        ax.set_visible(False)
    handles = []
    for s_idx, (name, result) in enumerate(sets.items()):
        color = SCENARIO_COLORS[s_idx % len(SCENARIO_COLORS)]
        label = scenario_labels.get(name) or name
        obs = " + ".join(tex_label(spec.response_labels.get(o, o)) for o in result.observables)
        frac = 100 * result.fraction
        handles.append(Patch(color=color, label=f"{label} ({obs}, ε={result.tolerance:g}): {frac:.3g} %"))
        if result.points is not None:  # Sobol evaluation (more than 3 factors): admissible points
            pts = domain.to_search(result.points[result.mask])
            for ax, (i, j) in zip(axes[0], pairs):
                ax.plot(pts[:, i], pts[:, j], ".", ms=1.5, color=color, rasterized=True)
            continue
        cells = _cell_mask(result, n, d)
        for ax, (i, j) in zip(axes[0], pairs):
            other = tuple(k for k in range(d) if k not in (i, j))
            proj = cells.any(axis=other) if other else cells
            img = _pool(proj.T)  # rows = y (factor j)
            if not img.any():
                continue
            cmap = ListedColormap([(0, 0, 0, 0), color])
            for k, ax_k in enumerate([ax] if zoom is None else [axes[0][0], axes[0][1]]):
                extent = _extent(domain, i, j)
                if k == 1 and judged is not None and name in judged:
                    img = _zoom_mask(judged[name], zoom)
                    extent = (*zoom[0], *zoom[1])
                ax_k.imshow(img.astype(float), origin="lower", extent=extent, aspect="auto",
                            cmap=cmap, vmin=0, vmax=1, interpolation="nearest")
            if zoom is not None:
                break  # the pair is drawn in both panels above
    _decorate_panels(axes[0], pairs, spec, zoom)
    if reference_point:
        handles.append(plt.Line2D([], [], marker="*", ms=10, color="#D55E00", mec="k", ls="none",
                                  label="reference point"))
    fig.legend(handles=handles, loc="lower center", ncol=1, frameon=False, bbox_to_anchor=(0.5, 0.0))
    if title:
        fig.suptitle(title)
    # laid out when drawn (demid.io.save_figure), once, at the resolution it is saved at
    fig.set_layout_engine("tight", rect=(0, legend_in / (height + legend_in), 1, 1))
    return fig


def _decorate_panels(panels, pairs: list[tuple[int, int]], spec: MaterialSpec, zoom) -> None:
    """Each panel's axis labels, limits and scales, the reference point, a projection's title, and the zoom
    panel's box (``zoom``: its ranges, None without one)."""
    d = spec.domain.dim
    domain, names = spec.domain, list(spec.domain.factors)
    for ax, (i, j) in zip(panels, pairs):
        ax.set_xlabel(axis_label(spec.factor(names[i])))
        ax.set_ylabel(axis_label(spec.factor(names[j])))
        lo, hi = domain.search_bounds()
        ax.set_xlim(lo[i], hi[i])
        ax.set_ylim(lo[j], hi[j])
        _axis_scale(ax, domain, i, j)
        if spec.reference_point:
            ref = domain.to_search(np.array([[spec.reference_point[f] for f in names]]))[0]
            ax.plot(ref[i], ref[j], marker="*", ms=11, color="#D55E00", mec="k", mew=0.6, ls="none")
    if d > 2:  # each panel shows the set's shadow on one pair of factors
        for ax, (i, j) in zip(panels, pairs):
            rest = ", ".join(tex_label(spec.factor(names[k]).label) for k in range(d) if k not in (i, j))
            ax.set_title(f"projection: any {rest}", fontsize=9)
    if zoom is not None:
        (x0, x1), (y0, y1) = zoom
        panels[1].set_xlim(x0, x1)
        panels[1].set_ylim(y0, y1)
        panels[1].set_title("zoom on the admissible sets", fontsize=9)
        panels[0].set_title("whole search range", fontsize=9)
        panels[0].add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, ec="0.3", lw=0.8, ls=":"))
