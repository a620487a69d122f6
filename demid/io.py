"""Deterministic, atomic writers: byte-identical outputs on rerun, no partial files on failure."""

from __future__ import annotations

import errno
import json
import math
import os
import tempfile
from contextlib import contextmanager
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq

FLOAT_FORMAT = "%.10g"
#: Significant digits of every number in a CSV table: what a reader compares, without float noise.
CSV_SIGNIFICANT_DIGITS = 6
#: Figure resolution of the PNG files (a journal's line-art minimum); every figure also gets an SVG.
FIGURE_DPI = 300


@contextmanager
def atomic_path(path: Path | str, suffix: str = ""):
    """Yield a temporary path next to ``path``; rename onto it only if the block succeeds."""
    path = Path(path)
    if path.is_dir():  # else the rename fails naming the temporary file, not the user's path
        raise IsADirectoryError(errno.EISDIR, "is a folder; name the file to write", str(path))
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=suffix or path.suffix, dir=path.parent)
    os.close(fd)
    try:
        yield Path(tmp)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp creates 0600; give the usual file mode
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def _write_parquet_to(frame: pd.DataFrame, where) -> None:
    table = pa.Table.from_pandas(frame.reset_index(drop=True), preserve_index=False)
    table = table.replace_schema_metadata(None)
    # Byte-stream-split floats compress better and read ~2x faster than dictionary pages
    # for the large grid tables; no statistics keeps the bytes independent of writer details.
    floats = [f.name for f in table.schema if pa.types.is_floating(f.type)]
    pq.write_table(table, where, compression="zstd", use_dictionary=[f.name for f in table.schema
                                                                    if f.name not in floats],
                   use_byte_stream_split=floats or False, write_statistics=False)


def write_parquet(frame: pd.DataFrame, path: Path | str) -> None:
    """Parquet without pandas' index metadata or creation timestamps."""
    with atomic_path(path) as tmp:
        _write_parquet_to(frame, tmp)


def read_parquet(path: Path | str) -> pd.DataFrame:
    return pq.read_table(path).to_pandas()


def as_stored(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame`` exactly as :func:`read_parquet` returns it after :func:`write_parquet` (a round trip
    in memory): a step that writes an intermediate and uses it itself sees what a later step reads."""
    sink = pa.BufferOutputStream()
    _write_parquet_to(frame, sink)
    return pq.read_table(pa.BufferReader(sink.getvalue())).to_pandas()


def round_significant(frame: pd.DataFrame, digits: int = CSV_SIGNIFICANT_DIGITS) -> pd.DataFrame:
    """A copy with every float column rounded to ``digits`` significant digits (ints, text kept)."""
    out = frame.copy()
    for column in out.columns:
        if pd.api.types.is_float_dtype(out[column]):
            out[column] = [float(f"{v:.{digits}g}") if math.isfinite(v) else v for v in out[column].to_numpy(float)]
    return out


def write_csv(frame: pd.DataFrame, path: Path | str) -> None:
    """CSV rounded to 6 significant digits by one function, so every table reads and reruns alike."""
    with atomic_path(path) as tmp:
        round_significant(frame).to_csv(tmp, index=False, float_format=f"%.{CSV_SIGNIFICANT_DIGITS}g",
                                        lineterminator="\n")


def write_full_csv(frame: pd.DataFrame, path: Path | str) -> None:
    """CSV with every number at full precision (shortest exact form): a table the pipeline reads back as
    data, such as a simulated material's runs, where rounding would change the values analysed."""
    with atomic_path(path) as tmp:
        frame.to_csv(tmp, index=False, lineterminator="\n")


def json_ready(obj, float_format: str | None = FLOAT_FORMAT):
    """``obj`` in plain JSON values, at any depth: numpy scalars and arrays as Python ones, keys as strings, NaN
    or infinity as None (null), every other float through ``float_format`` (None: kept to the last bit)."""
    if isinstance(obj, dict):
        return {str(k): json_ready(v, float_format) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [json_ready(v, float_format) for v in obj]
    if isinstance(obj, np.ndarray):
        return [json_ready(v, float_format) for v in obj.tolist()]
    if isinstance(obj, (np.bool_,)):
        return bool(obj)
    if isinstance(obj, (np.integer,)):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        value = float(obj)
        if not math.isfinite(value):
            return None
        return value if float_format is None else float(float_format % value)
    return obj


def to_json_text(obj) -> str:
    """Sorted keys, NaN as null, floats rounded to 10 significant digits."""
    return json.dumps(json_ready(obj), sort_keys=True, indent=2, ensure_ascii=False) + "\n"


def write_json(obj, path: Path | str) -> None:
    with atomic_path(path) as tmp:
        Path(tmp).write_text(to_json_text(obj), encoding="utf-8")


def svg_path(path: Path | str) -> Path:
    """The vector copy of a PNG figure: same name, ``.svg``."""
    return Path(path).with_suffix(".svg")


def save_figure(fig, path: Path | str, dpi: int = FIGURE_DPI) -> None:
    """PNG (``dpi``) and SVG next to it, both without dates or software metadata, so reruns are
    byte-identical (the SVG's element ids come from a fixed hash salt)."""
    import matplotlib
    import matplotlib.image
    import matplotlib.pyplot as plt
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    # drawn under the rcParams it was built with (demid.plots.style.styled), if any
    with matplotlib.rc_context(getattr(fig, "figure_style", None)):
        # One Agg draw lays the figure out and renders it; savefig would draw it twice (a hidden draw
        # for the layout first), and the layout, which measures every label, is most of the cost.
        canvas, figure_dpi = FigureCanvasAgg(fig), fig.dpi
        fig.dpi = dpi
        canvas.draw()
        with atomic_path(path) as tmp:
            matplotlib.image.imsave(tmp, canvas.buffer_rgba(), format="png", origin="upper", dpi=dpi,
                                    metadata={"Software": None})
        fig.dpi = figure_dpi
        # The SVG keeps the PNG's layout instead of solving it again.
        fig.set_layout_engine(None)
        with matplotlib.rc_context({"svg.hashsalt": "demid"}), atomic_path(svg_path(path)) as tmp:
            fig.savefig(tmp, metadata={"Date": None, "Creator": None}, format="svg")
    plt.close(fig)


def copy_files(pairs: dict, log: Path | str) -> None:
    """Byte copies, source -> destination, each written atomically; what was copied goes to ``log``.
    Paths are arguments, never a shell command line, so any character in a folder name is safe."""
    import shutil

    lines = []
    for source, destination in pairs.items():
        with atomic_path(destination) as tmp:
            shutil.copyfile(source, tmp)
        lines.append(f"{source} -> {destination}\n")
    Path(log).parent.mkdir(parents=True, exist_ok=True)
    Path(log).write_text("".join(lines), encoding="utf-8")


def save_figures(figures: dict, also=None) -> None:
    """Every figure of ``figures`` ({path: figure}) as :func:`save_figure` writes it, in two processes where
    the platform can fork (each then holds the figures already): a material's figures are independent of
    each other and drawing them is about half of its job, so a core the other jobs leave free (while the
    run's last job ends, or any job on a larger machine) draws half of them.  ``also`` (no arguments) runs
    in this process meanwhile, e.g. the tables' writing.  Every figure is drawn by the same code in one
    process, so the bytes are those of a single process."""
    import sys
    import traceback

    items = list(figures.items())
    if len(items) < 2 or not hasattr(os, "fork"):
        if also is not None:
            also()
        for path, fig in items:
            save_figure(fig, path)
        return
    # shared out by area, largest first to the side with less so far (a figure's cost grows with its size);
    # this process, which also writes the tables, takes the smaller share when they are equal
    ours, theirs, area = [], [], [0.0, 0.0]
    for path, fig in sorted(items, key=lambda item: -float(np.prod(item[1].get_size_inches()))):
        side = 1 if area[1] <= area[0] else 0
        (theirs if side else ours).append((path, fig))
        area[side] += float(np.prod(fig.get_size_inches()))
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:  # the child: its share, then out without running the parent's exit handlers
        status = 1
        try:
            for path, fig in theirs:
                save_figure(fig, path)
            status = 0
        except BaseException:  # noqa: BLE001 - reported, and the parent fails the job
            traceback.print_exc()
        finally:
            sys.stderr.flush()
            os._exit(status)
    try:
        if also is not None:
            also()
        for path, fig in ours:
            save_figure(fig, path)
    finally:
        _, status = os.waitpid(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(f"writing {', '.join(str(p) for p, _ in theirs)} failed (the error is above)")


def content_digest(path: Path | str) -> str:
    """sha256 of a file's bytes ("" when there is no such file).  Rules carry it as a parameter, so that
    an input edited at any time, even while its job runs, is seen by the next run (an edit during the
    job leaves the file older than the outputs, which a comparison of times misses)."""
    import hashlib

    path = Path(path)
    if not path.is_file():
        return ""
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()
