"""Publication figures: admissible sets, response surfaces, Pareto trade-off.

Sets are drawn cell by cell from the evaluation grid.  When the grid is finer
than the figure, cells are max-pooled into pixels so a narrow band or ridge
stays visible instead of being averaged away.
"""

from __future__ import annotations

from itertools import combinations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from .admissibility import AdmissibleSet, Domain  # noqa: E402
from .spec import MaterialSpec  # noqa: E402

plt.rcParams.update({
    "figure.dpi": 150, "font.size": 9, "axes.titlesize": 10, "axes.labelsize": 9,
    "legend.fontsize": 8, "svg.hashsalt": "demid", "axes.spines.top": False, "axes.spines.right": False,
})

SCENARIO_COLORS = ["#9ecae1", "#08519c", "#fdae6b", "#a63603", "#74c476", "#006d2c"]
MAX_PIXELS = 500


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


def _extent(domain: Domain, i: int, j: int):
    lo, hi = domain.search_bounds()
    return [lo[i], hi[i], lo[j], hi[j]]


def _axis_scale(ax, domain: Domain, i: int, j: int):
    # imshow works in search units; label log factors with actual values.
    for k, setter in ((i, ax.xaxis), (j, ax.yaxis)):
        if domain.log[k]:
            setter.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{10 ** v:.3g}"))


def sets_figure(spec: MaterialSpec, sets: dict[str, AdmissibleSet], n: int) -> plt.Figure:
    """Overlay of every scenario's admissible set (pairwise projections for d > 2)."""
    domain, reference_point, title = spec.domain, spec.reference_point, spec.label
    scenario_labels = {sc.name: sc.label for sc in spec.scenarios}
    d = domain.dim
    pairs = list(combinations(range(d), 2)) if d > 1 else [(0, 0)]
    ncol = min(3, len(pairs))
    nrow = int(np.ceil(len(pairs) / ncol))
    fig, grid_axes = plt.subplots(nrow, ncol, figsize=(4.4 * ncol + 0.6, 4.0 * nrow), squeeze=False)
    axes = grid_axes.reshape(1, -1)
    for ax in axes[0][len(pairs):]:
        ax.set_visible(False)
    handles = []
    for s_idx, (name, result) in enumerate(sets.items()):
        color = SCENARIO_COLORS[s_idx % len(SCENARIO_COLORS)]
        label = scenario_labels.get(name) or name
        obs = "+".join(result.observables)
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
            ax.imshow(img.astype(float), origin="lower", extent=_extent(domain, i, j), aspect="auto",
                      cmap=cmap, vmin=0, vmax=1, interpolation="nearest")
    names = list(domain.factors)
    for ax, (i, j) in zip(axes[0], pairs):
        ax.set_xlabel(spec.factor(names[i]).axis_label)
        ax.set_ylabel(spec.factor(names[j]).axis_label)
        lo, hi = domain.search_bounds()
        ax.set_xlim(lo[i], hi[i])
        ax.set_ylim(lo[j], hi[j])
        _axis_scale(ax, domain, i, j)
        if reference_point:
            ref = domain.to_search(np.array([[reference_point[f] for f in names]]))[0]
            ax.plot(ref[i], ref[j], marker="*", ms=11, color="#d62728", mec="k", mew=0.6, ls="none")
    if reference_point:
        handles.append(plt.Line2D([], [], marker="*", ms=10, color="#d62728", mec="k", ls="none",
                                  label="reference point"))
    fig.legend(handles=handles, loc="lower center", ncol=1, frameon=False, bbox_to_anchor=(0.5, 0.0))
    if title:
        fig.suptitle(title)
    fig.tight_layout(rect=(0, (0.035 + 0.045 * len(handles)) / nrow, 1, 1))
    return fig


def surface_figure(domain: Domain, spec: MaterialSpec, grid: pd.DataFrame, n: int,
                   table: pd.DataFrame | None = None, title: str = "") -> plt.Figure:
    """Contour panel per response over the first two factors (others at their mid-range)."""
    names = list(domain.factors)
    d = domain.dim
    responses = [r for r in spec.response_names if r in grid.columns]
    ncol = min(3, len(responses))
    nrow = int(np.ceil(len(responses) / ncol))
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.6 * nrow), squeeze=False)
    lo, hi = domain.search_bounds()
    step = max(1, (n - 1) // 200)
    for ax, r in zip(axes.ravel(), responses):
        values = grid[r].to_numpy().reshape((n,) * d)
        if d > 2:
            values = values[(slice(None), slice(None)) + (n // 2,) * (d - 2)]
        if d == 1:
            ax.plot(np.linspace(lo[0], hi[0], n), values, color="k")
            continue
        z = values[::step, ::step].T
        xs = np.linspace(lo[0], hi[0], n)[::step]
        ys = np.linspace(lo[1], hi[1], n)[::step]
        cs = ax.contourf(xs, ys, z, levels=14, cmap="viridis")
        fig.colorbar(cs, ax=ax, label=spec.response(r).axis_label)
        target = spec.response(r).target
        if target is not None and z.min() < target < z.max():
            ax.contour(xs, ys, z, levels=[target], colors="w", linewidths=1.4, linestyles="--")
        if table is not None:
            pts = domain.to_search(table[names].to_numpy())
            ax.plot(pts[:, 0], pts[:, 1], "o", ms=3.5, mfc="w", mec="k", mew=0.6, ls="none")
        ax.set_xlabel(spec.factor(names[0]).axis_label)
        ax.set_ylabel(spec.factor(names[1]).axis_label)
        ax.set_title(spec.response(r).label)
        _axis_scale(ax, domain, 0, 1)
    for ax in axes.ravel()[len(responses):]:
        ax.set_visible(False)
    sub = "" if d <= 2 else f" (other factors at mid-range: {', '.join(names[2:])})"
    if title or sub:
        fig.suptitle(f"{title}{sub}")
    fig.tight_layout()
    return fig


def pareto_figure(grid: pd.DataFrame, front: pd.DataFrame, spec: MaterialSpec, cloud_points: int = 60_000) -> plt.Figure:
    """Objective cloud (a seeded random subsample of the grid) and the Pareto front, with a zoom on
    the low-error end where the front's intervals are read."""
    error_of, minimise, max_error = spec.pareto.error_of, spec.pareto.minimise, spec.pareto.max_error
    target, title = spec.targets[error_of], spec.label
    error = 100 * np.abs(grid[error_of].to_numpy() - target) / abs(target)
    objective = grid[minimise].to_numpy()
    rng = np.random.default_rng(0)  # a random subsample avoids the moire of a strided one
    pick = np.sort(rng.choice(len(error), size=min(cloud_points, len(error)), replace=False))
    fig, axes = plt.subplots(1, 2, figsize=(9.6, 4.0))
    front_err = 100 * front["error"].to_numpy()
    front_obj = front["objective"].to_numpy()
    for ax, zoom in zip(axes, (False, True)):
        ax.plot(error[pick], objective[pick], ".", ms=1.2, color="#bdbdbd", alpha=0.6, rasterized=True,
                label="grid points (random subsample)")
        ax.plot(front_err, front_obj, "-", color="#08519c", lw=1.8, label="Pareto front")
        ax.axvline(100 * max_error, color="#a63603", ls="--", lw=1, label=f"error = {100 * max_error:g} %")
        ax.set_xlabel(f"relative error of {spec.response(error_of).label} [%]")
        ax.set_ylabel(spec.response(minimise).axis_label)
        if zoom:
            xmax = 3 * 100 * max_error
            near = front_obj[front_err <= xmax]
            lo, hi = (near.min(), near.max()) if len(near) else (front_obj.min(), front_obj.max())
            pad = 0.5 * (hi - lo) + 1e-9 * max(abs(hi), 1.0)
            ax.set_xlim(0, xmax)
            ax.set_ylim(lo - pad, hi + 4 * pad)
            ax.set_title(f"zoom: error ≤ {xmax:g} %")
        else:
            ax.legend(frameon=False, loc="upper right")
            ax.set_title("objective cloud")
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    return fig


def surface_figure_from_surrogates(surrogates: dict, spec: MaterialSpec, table: pd.DataFrame | None,
                                   n: int = 201) -> plt.Figure:
    """Surface panels on an n x n slice through the first two factors (others at mid-range)."""
    from .admissibility import predict_grid

    domain, title = spec.domain, spec.label
    d = domain.dim
    if d > 2:
        # A 2-D slice: the remaining factors at the centre of their (search-unit) range.
        lo, hi = domain.search_bounds()
        mid = domain.to_actual(((lo + hi) / 2)[None, :])[0]
        names = list(domain.factors)
        slice_domain = Domain(tuple(names[:2]), tuple(domain.lower[:2]), tuple(domain.upper[:2]), domain.log[:2])
        pts = slice_domain.grid(n)
        full = np.column_stack([pts] + [np.full(len(pts), mid[k]) for k in range(2, d)])
        grid = pd.DataFrame(full, columns=names)
        for name, sur in surrogates.items():
            grid[name] = sur.predict(full)
        values = {r: grid[r].to_numpy() for r in surrogates}
        grid2 = pd.DataFrame(pts, columns=names[:2]).assign(**values)
        held = ", ".join(
            f"{spec.factor(f).label} = {mid[k + 2]:.3g}"
            + (f" {spec.factor(f).unit}" if spec.factor(f).unit != "-" else "")
            for k, f in enumerate(names[2:]))
        return surface_figure(slice_domain, spec, grid2, n, table,
                              f"{title} — slice at {held}")
    grid = predict_grid(surrogates, domain, n)
    return surface_figure(domain, spec, grid, n, table, title)
