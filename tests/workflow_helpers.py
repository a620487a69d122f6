"""Running the Snakemake workflow from tests, the way a user does."""

from __future__ import annotations

import hashlib
import json
import os
import struct
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def run_snakemake(workdir: Path, configfile: Path, *args: str, timeout: int = 300) -> subprocess.CompletedProcess:
    cmd = [sys.executable, "-m", "snakemake", "-c2", "--configfile", str(configfile), "--directory", str(workdir),
           *args]
    env = dict(os.environ, PYTHONWARNINGS="ignore")
    return subprocess.run(cmd, cwd=REPO, capture_output=True, text=True, timeout=timeout, env=env)


def written_results(results: Path) -> list[Path]:
    """The files a run wrote under its results folder, leaving out the jobs' logs and benchmarks (which a
    stopped job writes too: its one line is in its log) and the mark naming the study the folder belongs to."""
    results = Path(results)
    if not results.exists():
        return []
    return sorted(p for p in results.rglob("*") if p.is_file()
                  and p.relative_to(results).parts[0] not in ("logs", "benchmarks", ".demid_study"))


def sha256(path: Path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def tree_hashes(root: Path, suffixes=(".csv", ".parquet", ".json", ".png", ".svg", ".html", ".ipynb")) -> dict[str, str]:
    return {str(p.relative_to(root)): sha256(p) for p in sorted(root.rglob("*")) if p.suffix in suffixes}


def planned_jobs(stdout: str) -> dict[str, int]:
    """Parse the 'Job stats' table of a dry run into {rule: count}."""
    counts: dict[str, int] = {}
    lines = stdout.splitlines()
    try:
        start = next(i for i, ln in enumerate(lines) if ln.strip().startswith("job") and "count" in ln)
    except StopIteration:
        return counts
    for ln in lines[start + 2:]:
        parts = ln.split()
        if len(parts) != 2 or not parts[1].isdigit():
            break
        if parts[0] != "total":
            counts[parts[0]] = int(parts[1])
    return counts


def _keys_sorted(obj) -> bool:
    if isinstance(obj, dict):
        return list(obj) == sorted(obj) and all(_keys_sorted(v) for v in obj.values())
    if isinstance(obj, list):
        return all(_keys_sorted(v) for v in obj)
    return True


def _png_metadata(path: Path) -> list[tuple[str, bytes]]:
    """(chunk type, body) of every chunk that is not image data."""
    data = Path(path).read_bytes()
    pos, out = 8, []
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind not in (b"IHDR", b"IDAT", b"IEND", b"PLTE", b"pHYs", b"tRNS"):
            out.append((kind.decode("ascii"), data[pos + 8:pos + 8 + length]))
        pos += 12 + length
    return out


def writer_contract_violations(root: Path) -> list[str]:
    """Outputs that break the writers' contracts: JSON keys unsorted, PNG software/time metadata,
    parquet key-value metadata beyond Arrow's schema (pandas block, timestamps)."""
    import pyarrow.parquet as pq

    bad = []
    for path in sorted(Path(root).rglob("*")):
        if path.suffix == ".json":
            if not _keys_sorted(json.loads(path.read_text(encoding="utf-8"))):
                bad.append(f"{path}: keys not sorted")
        elif path.suffix == ".png":
            for kind, body in _png_metadata(path):
                if kind == "tIME" or b"Software" in body or b"Date" in body or b"Creation" in body:
                    bad.append(f"{path}: {kind} chunk {body[:40]!r}")
        elif path.suffix == ".parquet":
            meta = pq.ParquetFile(path).metadata.metadata or {}
            if set(meta) - {b"ARROW:schema"} or pq.read_schema(path).metadata:
                bad.append(f"{path}: key-value metadata {sorted(meta)}")
    return bad
