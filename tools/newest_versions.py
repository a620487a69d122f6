"""Install the newest versions requirements.in allows into a fresh virtual environment and run the tests.

    python tools/newest_versions.py                 # the whole suite
    python tools/newest_versions.py -- -k surrogate # arguments after -- go to pytest

Prints which packages are newer than the pins in requirements.txt, then pytest's result, so a
breakage is seen before the pins are moved (``python tools/pin_requirements.py``).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

from pin_requirements import LOOSE, PINNED, ROOT, fresh_install, frozen_versions


def versions(lines: list[str]) -> dict[str, str]:
    pairs = (line.split("==", 1) for line in lines if "==" in line and not line.startswith("#"))
    return {name.lower(): version for name, version in pairs}


def main(argv: list[str]) -> int:
    pytest_args = argv[argv.index("--") + 1 :] if "--" in argv else []
    pinned = versions(PINNED.read_text().splitlines())
    with tempfile.TemporaryDirectory(prefix="demid-newest-") as tmp:
        python = fresh_install(LOOSE, Path(tmp))
        newest = versions(frozen_versions(python))
        changed = sorted(name for name in newest if pinned.get(name) != newest[name])
        print(f"{len(changed)} of {len(newest)} packages differ from requirements.txt:")
        for name in changed:
            print(f"  {name}: {pinned.get(name, '(not pinned)')} -> {newest[name]}")
        result = subprocess.run([python, "-m", "pytest", "-q", *pytest_args], cwd=ROOT)
    print(f"pytest with the newest versions exited {result.returncode}")
    return result.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
