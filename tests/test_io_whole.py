"""The file writers' whole behaviour against what the test computes apart: an atomic write leaves the new bytes with
the usual file mode (0666 under the umask) and no temporary file, and a failed one leaves the old file untouched;
a folder is refused by name; copies are byte copies logged one line each; a file's digest is sha256 of its bytes
(files above the 1 MiB read block included; "" for no file); a frame as stored equals the frame written and read
back; the SVG beside a PNG."""

from __future__ import annotations

import hashlib
import os

import numpy as np
import pandas as pd
import pytest

from demid.io import as_stored, atomic_path, content_digest, copy_files, read_parquet, svg_path, write_parquet


def test_an_atomic_write_lands_whole_with_the_usual_mode_and_leaves_nothing_else(tmp_path):
    target = tmp_path / "sub" / "out.txt"
    with atomic_path(target) as tmp:
        assert tmp.parent == target.parent and tmp != target and tmp.suffix == ".txt"
        tmp.write_text("new", encoding="utf-8")
        assert not target.exists()
    assert target.read_text(encoding="utf-8") == "new"
    umask = os.umask(0)
    os.umask(umask)
    assert target.stat().st_mode & 0o777 == 0o666 & ~umask
    assert sorted(p.name for p in target.parent.iterdir()) == ["out.txt"]
    with pytest.raises(RuntimeError):
        with atomic_path(target) as tmp:
            tmp.write_text("half", encoding="utf-8")
            raise RuntimeError("stop")
    assert target.read_text(encoding="utf-8") == "new"
    assert sorted(p.name for p in target.parent.iterdir()) == ["out.txt"]
    with atomic_path(target, suffix=".part") as tmp:
        assert tmp.suffix == ".part"
        tmp.write_text("again", encoding="utf-8")
    assert target.read_text(encoding="utf-8") == "again"


def test_a_folder_is_refused_by_its_own_name(tmp_path):
    with pytest.raises(IsADirectoryError) as err:
        with atomic_path(tmp_path):
            pass
    assert err.value.filename == str(tmp_path)


def test_copies_are_byte_copies_logged_one_line_each(tmp_path):
    sources = []
    for i, payload in enumerate([b"", b"\x00\xff bytes", os.urandom(3000)]):
        path = tmp_path / f"s{i}.bin"
        path.write_bytes(payload)
        sources.append(path)
    pairs = {s: tmp_path / "out" / "deeper" / f"d {i}.bin" for i, s in enumerate(sources)}
    log = tmp_path / "logs" / "copy.log"
    copy_files(pairs, log)
    for source, destination in pairs.items():
        assert destination.read_bytes() == source.read_bytes()
    assert log.read_text(encoding="utf-8") == "".join(f"{s} -> {d}\n" for s, d in pairs.items())


@pytest.mark.parametrize("size", [0, 1, (1 << 20) - 1, 1 << 20, (1 << 20) + 7, 3 * (1 << 20) + 5])
def test_a_digest_is_sha256_of_every_byte(tmp_path, size):
    path = tmp_path / "f.bin"
    payload = np.random.default_rng(size).integers(0, 256, size, dtype=np.uint8).tobytes()
    path.write_bytes(payload)
    assert content_digest(path) == hashlib.sha256(payload).hexdigest()
    assert content_digest(tmp_path / "missing.bin") == "" and content_digest(tmp_path) == ""


def test_a_frame_as_stored_is_the_frame_written_and_read_back(tmp_path):
    frame = pd.DataFrame({"a": [1.5, np.nan, -2.25e-300], "n": [1, 2, 3], "s": ["x", "ÿ", ""],
                          "b": [True, False, True]}, index=[5, 6, 7])
    write_parquet(frame, tmp_path / "t.parquet")
    back = read_parquet(tmp_path / "t.parquet")
    pd.testing.assert_frame_equal(as_stored(frame), back)
    pd.testing.assert_frame_equal(back, frame.reset_index(drop=True))


def test_the_vector_copy_of_a_figure_sits_beside_it():
    assert str(svg_path("out/fig.png")) == "out/fig.svg"
