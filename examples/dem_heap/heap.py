"""Angle of repose of a lifted-cylinder heap, simulated with Kratos Multiphysics' DEM application.

Spheres (diameter 5 mm ± 15 %, 2,500 kg m^-3, E = 1 MPa) fill a cylinder standing on a rough base,
settle under gravity; the cylinder is lifted and the spheres spread into a heap. The angle of
repose is the slope of the heap's free surface, fitted to the top particles of the final packing.

    python examples/dem_heap/heap.py --mu 0.5 --mur 0.1 --seed 1 --out run/responses.json

writes ``{"angle_of_repose": ..., ...}`` (degrees) to ``--out``. The contact law is Hertz with
viscous damping and Coulomb friction (sliding friction ``--mu``) and the constant-torque rolling
friction model (coefficient ``--mur``, 0 = no rolling resistance). ``--seed`` draws the radii and
the initial positions; one thread, so the same seed repeats the run exactly.
"""
import argparse
import json
import math
import os
import sys
import tempfile
import time
from pathlib import Path

# One OpenMP thread: the contact sums are then done in one fixed order, so a run repeats exactly.
# It must be set before Kratos is imported.
os.environ["OMP_NUM_THREADS"] = "1"

import numpy as np

DIAMETER = 5.0e-3            # mean particle diameter [m]
SPREAD = 0.15                # radii uniform in ±15 % of the mean
DENSITY = 2500.0             # [kg m^-3]
YOUNG = 1.0e6                # [Pa]
POISSON = 0.2
COLUMN_ASPECT = 2.0          # settled column height / cylinder radius: tall enough for a full cone
LIFT_SPEED = 0.15            # [m s^-1]
BASE_HALF_WIDTH = 0.15       # [m]; spheres rolling beyond the base leave the box and are removed
BASE_FRICTION = 1.0          # rough base: sliding and rolling friction of the spheres on it
BASE_ROLLING_FRICTION = 0.5
CYLINDER_FRICTION = 0.1
SETTLE_TIME = 0.30           # [s] before the lift
REST_SPEED = 0.01            # [m s^-1]: the heap is at rest when 98 % of the spheres move slower

SPREAD_TIME = 1.0            # [s] at most after the cylinder's foot has passed the column's top
SEARCH_EVERY = 10
SEARCH_TOLERANCE = 1.0e-3    # [m]: 10 steps at up to 0.4 m/s relative speed
TIME_STEP_FRACTION = 0.4     # of the Rayleigh time step of the smallest sphere


def rayleigh_time_step(radius):
    shear_modulus = YOUNG / (2.0 * (1.0 + POISSON))
    return math.pi * radius * math.sqrt(DENSITY / shear_modulus) / (0.1631 * POISSON + 0.8766)


def cylinder_radius(count):
    """Radius [m] for which ``count`` spheres settle (solid fraction ~0.6) to COLUMN_ASPECT radii."""
    solid = count * math.pi / 6.0 * DIAMETER ** 3 * (1.0 + SPREAD ** 2)
    return (solid / (0.6 * math.pi * COLUMN_ASPECT)) ** (1.0 / 3.0)


def initial_packing(count, seed):
    """Radii and centres of ``count`` spheres on a loose jittered lattice inside the cylinder."""
    rng = np.random.default_rng(seed)
    radii = 0.5 * DIAMETER * rng.uniform(1.0 - SPREAD, 1.0 + SPREAD, count)
    r_max = 0.5 * DIAMETER * (1.0 + SPREAD)
    spacing = 2.05 * r_max
    reach = cylinder_radius(count) - 1.05 * r_max
    ticks = np.arange(-reach, reach + 1e-12, spacing)
    layer = np.array([(x, y) for x in ticks for y in ticks if math.hypot(x, y) <= reach])
    layers = -(-count // len(layer))
    centres = np.concatenate([
        np.column_stack([layer, np.full(len(layer), r_max * 1.05 + k * spacing)])
        for k in range(layers)])[:count]
    jitter = rng.uniform(-0.1, 0.1, (count, 3)) * (spacing - 2.0 * r_max)
    return radii, centres + jitter


def spheres_mdpa(radii, centres):
    lines = ["Begin ModelPartData", "End ModelPartData", "Begin Properties 1", "End Properties",
             "Begin Nodes"]
    lines += [f"{i} {x:.9e} {y:.9e} {z:.9e}" for i, (x, y, z) in enumerate(centres, 1)]
    lines += ["End Nodes", "Begin Elements SphericParticle3D"]
    lines += [f"{i} 1 {i}" for i in range(1, len(radii) + 1)]
    lines += ["End Elements", "Begin NodalData RADIUS"]
    lines += [f"{i} 0 {r:.9e}" for i, r in enumerate(radii, 1)]
    lines += ["End NodalData", "Begin SubModelPart grains", "  Begin SubModelPartNodes"]
    lines += [f"  {i}" for i in range(1, len(radii) + 1)]
    lines += ["  End SubModelPartNodes", "  Begin SubModelPartElements"]
    lines += [f"  {i}" for i in range(1, len(radii) + 1)]
    lines += ["  End SubModelPartElements", "End SubModelPart", ""]
    return "\n".join(lines)


def walls_mdpa(radius, cylinder_height, facets=32, rings=8):
    """The base (one square) and the cylinder (``facets`` × ``rings`` quadrilaterals)."""
    nodes, quads = [], {"base": [], "cylinder": []}
    h = BASE_HALF_WIDTH
    nodes += [(-h, -h, 0.0), (h, -h, 0.0), (h, h, 0.0), (-h, h, 0.0)]
    quads["base"].append((1, 2, 3, 4))
    first = len(nodes) + 1
    for ring in range(rings + 1):
        z = cylinder_height * ring / rings
        for k in range(facets):
            angle = 2.0 * math.pi * k / facets
            nodes.append((radius * math.cos(angle), radius * math.sin(angle), z))
    for ring in range(rings):
        for k in range(facets):
            a = first + ring * facets + k
            b = first + ring * facets + (k + 1) % facets
            quads["cylinder"].append((a, b, b + facets, a + facets))
    lines = ["Begin ModelPartData", "End ModelPartData", "Begin Properties 0", "End Properties",
             "Begin Nodes"]
    lines += [f"{i} {x:.9e} {y:.9e} {z:.9e}" for i, (x, y, z) in enumerate(nodes, 1)]
    lines += ["End Nodes", "Begin Conditions RigidFace3D4N"]
    ids = {}
    cid = 0
    for name in ("base", "cylinder"):
        ids[name] = []
        for quad in quads[name]:
            cid += 1
            ids[name].append(cid)
            lines.append(f"{cid} 0 " + " ".join(map(str, quad)))
    lines.append("End Conditions")
    for name in ("base", "cylinder"):
        node_ids = sorted({n for quad in quads[name] for n in quad})
        lines += [f"Begin SubModelPart {name}", "  Begin SubModelPartData"]
        if name == "cylinder":   # rigid-body motion: lifted at LIFT_SPEED from SETTLE_TIME on
            lines += ["  RIGID_BODY_MOTION 1", "  FIXED_MESH_OPTION 0",
                      f"  LINEAR_VELOCITY [3] (0.0,0.0,{LIFT_SPEED})", "  VELOCITY_PERIOD 0.0",
                      "  ANGULAR_VELOCITY [3] (0.0,0.0,0.0)", "  ROTATION_CENTER [3] (0.0,0.0,0.0)",
                      "  ANGULAR_VELOCITY_PERIOD 0.0", f"  VELOCITY_START_TIME {SETTLE_TIME}",
                      "  VELOCITY_STOP_TIME 1000.0", "  ANGULAR_VELOCITY_START_TIME 0.0",
                      "  ANGULAR_VELOCITY_STOP_TIME 1000.0"]
        lines += [f"  IDENTIFIER {name}", "  End SubModelPartData", "  Begin SubModelPartNodes"]
        lines += [f"  {n}" for n in node_ids]
        lines += ["  End SubModelPartNodes", "  Begin SubModelPartConditions"]
        lines += [f"  {c}" for c in ids[name]]
        lines += ["  End SubModelPartConditions", "End SubModelPart"]
    return "\n".join(lines) + "\n"


def contact(mu, mur, restitution):
    # Kratos 10.4 reads a sphere-wall pair's rolling friction from ROLLING_FRICTION of that pair.
    return {
        "COEFFICIENT_OF_RESTITUTION": restitution,
        "STATIC_FRICTION": mu,
        "DYNAMIC_FRICTION": mu,
        "FRICTION_DECAY": 500.0,
        "ROLLING_FRICTION": mur,
        "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Hertz_viscous_Coulomb",
        "DEM_ROLLING_FRICTION_MODEL_NAME": "DEMRollingFrictionModelConstantTorque",
    }


def materials(mu, mur, restitution):
    elastic = {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": POISSON}
    return {
        "materials": [
            {"material_name": "grains", "material_id": 1,
             "Variables": {"PARTICLE_DENSITY": DENSITY, **elastic}},
            {"material_name": "base", "material_id": 2, "Variables": dict(elastic)},
            {"material_name": "cylinder", "material_id": 3, "Variables": dict(elastic)},
        ],
        "material_relations": [
            {"material_names_list": ["grains", "grains"], "material_ids_list": [1, 1],
             "Variables": contact(mu, mur, restitution)},
            {"material_names_list": ["grains", "base"], "material_ids_list": [1, 2],
             "Variables": contact(BASE_FRICTION, BASE_ROLLING_FRICTION, restitution)},
            {"material_names_list": ["grains", "cylinder"], "material_ids_list": [1, 3],
             "Variables": contact(CYLINDER_FRICTION, 0.0, restitution)},
        ],
        "material_assignation_table": [
            ["SpheresPart.grains", "grains"],
            ["RigidFacePart.base", "base"],
            ["RigidFacePart.cylinder", "cylinder"],
        ],
    }


def project_parameters(time_step, final_time):
    h = BASE_HALF_WIDTH
    return {
        "Dimension": 3,
        "BoundingBoxOption": True,
        "BoundingBoxMaxX": h, "BoundingBoxMaxY": h, "BoundingBoxMaxZ": 1.0,
        "BoundingBoxMinX": -h, "BoundingBoxMinY": -h, "BoundingBoxMinZ": -0.01,
        "dem_inlet_option": False,
        "GravityX": 0.0, "GravityY": 0.0, "GravityZ": -9.81,
        "RotationOption": True,
        "RollingFrictionOption": True,
        "do_print_results_option": False,
        "solver_settings": {
            "strategy": "sphere_strategy",
            "RemoveBallsInitiallyTouchingWalls": False,
            "material_import_settings": {"materials_filename": "MaterialsDEM.json"},
        },
        "ElementType": "SphericPartDEMElement3D",
        "TranslationalIntegrationScheme": "Symplectic_Euler",
        "RotationalIntegrationScheme": "Direct_Integration",
        "MaxTimeStep": time_step,
        "FinalTime": final_time,
        # Contacts are searched every SEARCH_EVERY steps within SEARCH_TOLERANCE of a sphere's
        # surface: a contact that starts between two searches is then already in the list.
        "NeighbourSearchFrequency": SEARCH_EVERY,
        "DeltaOption": "Absolute",
        "SearchTolerance": SEARCH_TOLERANCE,
        "search_tolerance_against_walls": SEARCH_TOLERANCE,
        "GraphExportFreq": 1.0,
        "VelTrapGraphExportFreq": 1.0,
        "OutputTimeStep": 1.0,
        "problem_name": "heap",
    }


def heap_angle(radii, centres):
    """Angle of repose [deg] fitted to the heap's free surface.

    The surface profile h(r) is the highest sphere top in rings half a mean diameter wide around
    the heap's axis (the median of the spheres' horizontal positions). The flank is the range of r
    from the last ring above 80 % of the heap's height to the first ring below 20 % of it or below
    1.25 diameters (the rounded summit, the toe and the single layer of loose spheres on the base
    left out); the angle is that of the
    least-squares line through the profile on the flank. The flank is chosen in r, not in h:
    choosing points by their height would cut the scatter and flatten the fitted slope.
    """
    axis = np.median(centres[:, :2], axis=0)
    distance = np.hypot(*(centres[:, :2] - axis).T)
    top = centres[:, 2] + radii
    ring = np.floor(distance / (0.5 * DIAMETER)).astype(int)
    profile = np.zeros(ring.max() + 1)
    np.maximum.at(profile, ring, top)
    height = profile.max()
    start = np.flatnonzero(profile > 0.8 * height).max()
    toe = max(0.2 * height, 1.25 * DIAMETER)   # a single layer of spheres on the base is no flank
    below = np.flatnonzero((profile < toe) & (np.arange(len(profile)) > start))
    stop = below.min() if len(below) else len(profile)
    rings = np.arange(start, stop)
    if len(rings) < 3:
        return float("nan"), height, len(rings)
    slope, _ = np.polyfit((rings + 0.5) * 0.5 * DIAMETER, profile[rings], 1)
    return math.degrees(math.atan(-slope)), height, len(rings)


def simulate(mu, mur, seed, particles, restitution):
    """Run one heap; returns the final radii and centres, the simulated time and the step count."""
    import KratosMultiphysics as Kratos
    from KratosMultiphysics.DEMApplication.DEM_analysis_stage import DEMAnalysisStage

    Kratos.Logger.GetDefaultOutput().SetSeverity(Kratos.Logger.Severity.WARNING)
    Kratos.ParallelUtilities.SetNumThreads(1)
    radii, centres = initial_packing(particles, seed)
    time_step = TIME_STEP_FRACTION * rayleigh_time_step(radii.min())
    column_top = centres[:, 2].max() + radii.max()
    cleared = SETTLE_TIME + column_top / LIFT_SPEED   # the cylinder's foot is above the column
    with tempfile.TemporaryDirectory(prefix="dem_heap_") as workdir:
        folder = Path(workdir)
        (folder / "heapDEM.mdpa").write_text(spheres_mdpa(radii, centres))
        (folder / "heapDEM_FEM_boundary.mdpa").write_text(walls_mdpa(cylinder_radius(particles), 1.1 * column_top))
        (folder / "MaterialsDEM.json").write_text(json.dumps(materials(mu, mur, restitution)))
        parameters = Kratos.Parameters(json.dumps(project_parameters(time_step, cleared + SPREAD_TIME)))

        class HeapStage(DEMAnalysisStage):
            def GetMainPath(self):
                return str(folder)

            steps = 0

            def KeepAdvancingSolutionLoop(self):
                self.steps += 1
                if self.time >= self.end_time:
                    return False
                # At rest once the cylinder's foot is above the column and no sphere moves;
                # looked at every 200 steps (a Python loop over the spheres is not free).
                if self.time < cleared or self.steps % 200:
                    return True
                speeds = [node.GetSolutionStepValue(Kratos.VELOCITY).norm_2()
                          for node in self.spheres_model_part.Nodes]
                return np.quantile(speeds, 0.98) >= REST_SPEED

        cwd = os.getcwd()
        os.chdir(folder)   # Kratos writes its graph files into the working directory
        try:
            stage = HeapStage(Kratos.Model(), parameters)
            stage.Initialize()
            stage.RunSolutionLoop()
            steps = stage.steps - 1
            nodes = list(stage.spheres_model_part.Nodes)
            final_radii = np.array([n.GetSolutionStepValue(Kratos.RADIUS) for n in nodes])
            final_centres = np.array([[n.X, n.Y, n.Z] for n in nodes])
            simulated = stage.time
            stage.Finalize()
        finally:
            os.chdir(cwd)
    return final_radii, final_centres, simulated, steps, time_step


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mu", type=float, required=True, help="sliding friction coefficient")
    parser.add_argument("--mur", type=float, default=0.0, help="rolling friction coefficient")
    parser.add_argument("--seed", type=int, required=True, help="packing seed (radii, positions)")
    parser.add_argument("--out", type=Path, required=True, help="responses JSON to write")
    parser.add_argument("--particles", type=int, default=800, help="number of spheres")
    parser.add_argument("--positions", type=Path, help="also write the final radii and centres (.npz)")
    parser.add_argument("--restitution", type=float, default=0.5, help="coefficient of restitution")
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    if not (args.mu > 0 and args.mur >= 0 and 0 < args.restitution < 1 and args.particles >= 50):
        sys.exit("heap.py: error: need --mu > 0, --mur >= 0, 0 < --restitution < 1, --particles >= 50")
    cpu = time.process_time()
    radii, centres, simulated, steps, time_step = simulate(
        args.mu, args.mur, args.seed, args.particles, args.restitution)
    angle, height, cells = heap_angle(radii, centres)
    if args.positions:
        np.savez(args.positions, radii=radii, centres=centres)
    responses = {
        "angle_of_repose": round(angle, 6),
        "heap_height_mm": round(1e3 * height, 6),
        "particles_left": int(len(radii)),
        "flank_rings": cells,
        "simulated_time_s": round(simulated, 6),
        "steps": steps,
        "time_step_s": time_step,
        "cpu_s": round(time.process_time() - cpu, 2),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    partial = args.out.with_name(args.out.name + ".part")
    partial.write_text(json.dumps(responses, indent=1) + "\n")
    partial.replace(args.out)   # the responses file appears whole or not at all
    print(json.dumps(responses))


if __name__ == "__main__":
    main()
