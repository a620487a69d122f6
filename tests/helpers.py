"""Builders of small synthetic design tables and surrogates for tests."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pandas as pd

from demid.design import ccd_points


def make_ccd_table(coef_fn, lower, upper, alpha=1.41421, center_runs=5, noise=0.0, seed=0, decimals=None):
    """A CCD over the box [lower, upper] (axial points on the bounds) with responses from ``coef_fn``.

    ``coef_fn(actual_points) -> dict[name, values]``.  Runs are shuffled (run order != standard order).
    """
    rng = np.random.default_rng(seed)
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    coded = ccd_points(len(lower), alpha, center_runs)
    center, unit = (lower + upper) / 2, (upper - lower) / (2 * alpha)
    actual = coded * unit + center
    responses = coef_fn(actual)
    order = rng.permutation(len(coded))
    data = {"run": np.arange(1, len(coded) + 1)}
    for i in range(len(lower)):
        data[f"x{i + 1}"] = actual[order, i]
    for name, values in responses.items():
        values = np.asarray(values, float) + noise * rng.standard_normal(len(coded))
        data[name] = values[order] if decimals is None else np.round(values[order], decimals)
    return pd.DataFrame(data)


def write_small_ccd_table(root) -> None:
    """``root/data/m.csv``: a two-factor CCD (a in 0.1-0.9, b in 1-11) with two smooth responses y1, y2,
    0.3 noise, three decimals: the table of the small self-made studies the report tests run."""
    def responses(x):
        a, b = x[:, 0], x[:, 1]
        return {"y1": 100 + 20 * a - 2 * b + 10 * a**2 + 0.5 * a * b, "y2": 80 + 5 * a + 3 * b - 0.1 * b**2}

    table = make_ccd_table(responses, [0.1, 1.0], [0.9, 11.0], noise=0.3, seed=3, decimals=3)
    (root / "data").mkdir()
    table.rename(columns={"x1": "a", "x2": "b"}).to_csv(root / "data" / "m.csv", index=False)


def run_demid(*args, cwd=None, env=None) -> subprocess.CompletedProcess:
    """``python -m demid ARGS`` run inside this test process, as a finished process would report it.

    A fresh interpreter per call costs about two CPU seconds of imports, most of the fast suite's time
    in the command-line tests; the command itself is what they test. The return code is main()'s (an
    argparse refusal's 2 included), stdout and stderr are captured, and an exception that would escape
    main() is printed as the interpreter would (a traceback, code 1), so a test that refuses
    tracebacks still sees one. Warnings are shown, not raised, as in the interpreter."""
    import contextlib
    import io
    import os
    import traceback
    import warnings

    from demid.cli import main

    out, err = io.StringIO(), io.StringIO()
    saved_env, saved_cwd = dict(os.environ), os.getcwd()
    try:
        if env is not None:
            os.environ.clear()
            os.environ.update(env)
        if cwd is not None:
            os.chdir(cwd)
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), warnings.catch_warnings():
            warnings.simplefilter("default")
            try:
                code = main([str(a) for a in args])
            except SystemExit as stop:
                code = stop.code if isinstance(stop.code, int) else (0 if stop.code is None else 1)
                if not isinstance(stop.code, (int, type(None))):
                    print(stop.code, file=sys.stderr)
            except Exception:  # noqa: BLE001 - reported exactly as the interpreter reports it
                traceback.print_exc()
                code = 1
    finally:
        os.chdir(saved_cwd)
        if env is not None:
            os.environ.clear()
            os.environ.update(saved_env)
    return subprocess.CompletedProcess(["demid", *map(str, args)], int(code or 0), out.getvalue(), err.getvalue())


def one_response_study(responses, lower, upper, target: float, count: int, margin: float, z: float = 2.0):
    """A face-centred CCD (3 centre runs) over factors a and b of ``responses`` (a function of the points giving
    {"y": values}), the material spec judging y against ``target`` at 5 % with ``next_runs`` of ``count`` and
    ``margin``, its quadratic surrogates and the plausible frame: what plan_next_wave takes."""
    from demid.spec import MaterialSpec
    from demid.surrogate import fit_material
    from demid.uncertainty import plausible_identifiability_frame

    table = make_ccd_table(responses, lower, upper, alpha=1.0, center_runs=3).rename(columns={"x1": "a", "x2": "b"})
    table["status"] = "ok"
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 3},
        "factors": {"a": {"lower": float(lower[0]), "upper": float(upper[0])},
                    "b": {"lower": float(lower[1]), "upper": float(upper[1])}},
        "responses": {"y": {"target": target}},
        "scenarios": {"y": {"observables": ["y"], "tolerance": 0.05}},
        "next_runs": {"count": count, "scenario": "", "margin": margin}})
    surrogates = {f.response: f.surrogate() for f in fit_material(table, spec)}
    plausible = plausible_identifiability_frame(surrogates, spec.domain, {"y": (("y",), 0.05)}, {"y": target}, 101,
                                                z=z)
    return table, spec, surrogates, plausible


class Linear:
    """A plane surrogate, y = c + x @ a in actual units (the grid and set estimators' exact test fields)."""

    def __init__(self, c, a):
        self.c, self.a = float(c), np.asarray(a, dtype=float)

    def predict(self, x):
        return self.c + np.atleast_2d(np.asarray(x, dtype=float)) @ self.a
