"""A cheap deterministic simulator for the workflow tests: two smooth responses of factors a and b
with 0.3 % noise drawn from --seed, written as JSON to --out.

``--fail MODE:R`` (repeatable) makes run R fail: ``exit`` (status 3), ``hang`` (sleeps past any test's
timeout), ``garbage`` (writes text that is not JSON), ``nan`` (a non-finite response), ``missing``
(writes nothing), ``flaky`` (exits with status 4 the first time only), ``daemon`` (starts a process in a
session of its own, writes its pid to daemon.pid beside --out, then hangs), ``bigint`` (y1 a JSON integer
of 401 digits), ``huge`` (y1 = 1e300), ``params`` (writes its own params.json beside --out), ``intrude``
(writes a run.json with y1 = 1e6 into run 1's folder, beside its own).  Every argument it receives is also appended, one per line, to --argv-log when given.
"""

import argparse
import json
import random
import subprocess
import sys
import time
from pathlib import Path

parser = argparse.ArgumentParser()
parser.add_argument("--a", type=float, required=True)
parser.add_argument("--b", type=float, required=True)
parser.add_argument("--seed", type=int, required=True)
parser.add_argument("--run", type=int, default=0)
parser.add_argument("--out", required=True)
parser.add_argument("--fail", action="append", default=[])
parser.add_argument("--argv-log", default="")
parser.add_argument("extra", nargs="*")
args = parser.parse_args()
if args.argv_log:
    with open(args.argv_log, "a", encoding="utf-8") as log:
        log.write("\n".join(sys.argv[1:]) + "\n")

failures = {int(run): mode for mode, _, run in (f.partition(":") for f in args.fail)}
mode = failures.get(args.run, "")
if mode:
    if mode == "exit":
        print("simulated divergence", file=sys.stderr)
        sys.exit(3)
    if mode == "daemon":
        daemon = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"], start_new_session=True,
                                  stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        (Path(args.out).parent / "daemon.pid").write_text(str(daemon.pid), encoding="utf-8")
    if mode in ("hang", "daemon"):
        time.sleep(60)
    if mode == "bigint":
        Path(args.out).write_text('{"y1": ' + "9" * 401 + ', "y2": 1.5}', encoding="utf-8")
        sys.exit(0)
    if mode == "params":
        Path(args.out).with_name("params.json").write_text('{"factors": {"a": 0.7}}', encoding="utf-8")
    if mode == "intrude":
        Path(args.out).parent.with_name("run1").joinpath("run.json").write_text(
            '{"reason": "", "responses": {"y1": 1e6, "y2": 1.0}, "status": "ok"}', encoding="utf-8")
    if mode == "garbage":
        with open(args.out, "w", encoding="utf-8") as out:
            out.write("Segmentation fault (core dumped)\n")
        sys.exit(0)
    if mode == "missing":
        sys.exit(0)
    marker = Path(args.out).parent / "flaky-attempted"
    if mode == "flaky" and not marker.exists():
        marker.write_text("", encoding="utf-8")
        sys.exit(4)

noise = random.Random(args.seed)
a, b = args.a, args.b
y1 = 100 + 20 * a - 2 * b + 10 * a ** 2 + 0.5 * a * b + 3 * a ** 3
y2 = 80 + 5 * a + 3 * b - 0.1 * b ** 2 + 0.02 * b ** 3
values = {"y1": y1 * (1 + 0.003 * noise.gauss(0, 1)), "y2": y2 * (1 + 0.003 * noise.gauss(0, 1))}
if mode == "nan":
    values["y2"] = float("nan")
if mode == "huge":
    values["y1"] = 1e300
with open(args.out, "w", encoding="utf-8") as out:
    json.dump(values, out)
