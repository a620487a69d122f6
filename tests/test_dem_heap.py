"""The Kratos DEM heap of examples/dem_heap: the angle fit against cones of known slope, and one
small simulation (skipped when Kratos is not installed) that writes a finite, plausible angle and
repeats exactly with the same seed."""

from __future__ import annotations

import importlib.util
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

HEAP = Path(__file__).resolve().parents[1] / "examples" / "dem_heap" / "heap.py"


def _heap_module():
    spec = importlib.util.spec_from_file_location("dem_heap", HEAP)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _cone_of_spheres(angle_deg, base_radius, seed):
    """Spheres filling a cone of the given slope (columns on a square grid), plus loose spheres on
    the base beyond the toe (what a real heap leaves)."""
    heap = _heap_module()
    rng = np.random.default_rng(seed)
    d = heap.DIAMETER
    tan = math.tan(math.radians(angle_deg))
    centres = []
    for x in np.arange(-base_radius, base_radius, 0.9 * d):
        for y in np.arange(-base_radius, base_radius, 0.9 * d):
            surface = (base_radius - math.hypot(x, y)) * tan
            # Columns start at random heights, as in a random packing: no terraces of layers.
            for z in np.arange(0.5 * d + rng.uniform(0, 0.9 * d), surface - 0.5 * d, 0.9 * d):
                centres.append((x, y, z))
    for _ in range(40):   # a loose single layer beyond the toe
        r, phi = rng.uniform(base_radius, 1.4 * base_radius), rng.uniform(0, 2 * math.pi)
        centres.append((r * math.cos(phi), r * math.sin(phi), 0.5 * d))
    centres = np.array(centres) + rng.normal(0, 0.05 * d, (len(centres), 3))
    radii = np.full(len(centres), 0.5 * d)
    return radii, centres


@pytest.mark.parametrize("angle", [18.0, 26.0, 34.0])
def test_angle_fit_recovers_the_slope_of_a_cone(angle):
    heap = _heap_module()
    radii, centres = _cone_of_spheres(angle, base_radius=0.06, seed=int(angle))
    fitted, height, rings = heap.heap_angle(radii, centres)
    # The profile is the highest sphere top in each ring, just below the cone's surface at every
    # distance: the slope is kept (±2° for the discreteness of a heap a few spheres high).
    assert rings >= 5
    assert fitted == pytest.approx(angle, abs=2.0)


def _run_heap(tmp_path, name):
    out = tmp_path / name / "responses.json"
    subprocess.run([sys.executable, str(HEAP), "--mu", "0.5", "--mur", "0.2", "--seed", "3",
                    "--particles", "200", "--out", str(out)],
                   check=True, capture_output=True, timeout=900)
    return json.loads(out.read_text())


def test_small_kratos_heap_is_plausible_and_repeats_exactly(tmp_path):
    pytest.importorskip("KratosMultiphysics.DEMApplication",
                        reason="Kratos DEM not installed (pip install -r requirements-dem.txt)")
    first = _run_heap(tmp_path, "a")
    second = _run_heap(tmp_path, "b")
    angle = first["angle_of_repose"]
    assert math.isfinite(angle) and 10.0 < angle < 50.0, first
    assert first["particles_left"] >= 190   # the heap stays on the base
    first.pop("cpu_s"), second.pop("cpu_s")
    assert first == second   # same seed, one thread: the same run to the last digit
