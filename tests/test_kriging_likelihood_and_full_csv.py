"""The kriging fit's restricted likelihood and process variance against the textbook formulas written out
with numpy (Matérn 5/2, a full quadratic trend, the projection K⁻¹ - K⁻¹F(F'K⁻¹F)⁻¹F'K⁻¹), over 1-3
factors, run counts, lengths and nuggets; and a full-precision CSV read back as the frame written."""
from itertools import combinations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st

from demid.io import write_full_csv
from demid.kriging import JITTER, GaussianSystem

_FAST = settings(max_examples=15, derandomize=True, deadline=None)


def _textbook_nll(u, z, lengths, nugget):
    n, k = u.shape
    columns = [np.ones(n), *u.T, *(u[:, i] * u[:, j] for i, j in combinations(range(k), 2)), *(u.T ** 2)]
    f = np.column_stack(columns)
    p = f.shape[1]
    scaled = (u[:, None, :] - u[None, :, :]) / lengths
    r = np.sqrt((scaled ** 2).sum(axis=2))
    kmat = (1 + np.sqrt(5) * r + 5 * r ** 2 / 3) * np.exp(-np.sqrt(5) * r) + (nugget + JITTER) * np.eye(n)
    kinv = np.linalg.inv(kmat)
    info = f.T @ kinv @ f
    projection = kinv - kinv @ f @ np.linalg.solve(info, f.T @ kinv)
    sigma2 = z @ projection @ z / (n - p)
    nll = 0.5 * ((n - p) * np.log(sigma2) + np.linalg.slogdet(kmat)[1] + np.linalg.slogdet(info)[1])
    return nll, sigma2


@_FAST
@given(k=st.integers(1, 3), extra=st.integers(2, 8), seed=st.integers(0, 10_000),
       length=st.floats(0.15, 1.5), nugget=st.floats(1e-4, 0.5), scale=st.sampled_from([1e-3, 1.0, 1e3]))
def test_restricted_likelihood_and_variance_match_the_textbook_formulas(k, extra, seed, length, nugget, scale):
    rng = np.random.default_rng(seed)
    n = (k + 1) * (k + 2) // 2 + extra
    u = rng.random((n, k))
    z = scale * (np.sin(3 * u).sum(axis=1) + 0.3 * rng.standard_normal(n))
    lengths = length * np.linspace(1.0, 2.0, k)
    system = GaussianSystem(u, z, lengths, nugget)
    nll, sigma2 = _textbook_nll(u, z, lengths, nugget)
    assert system.sigma2 == pytest.approx(sigma2, rel=1e-6)
    assert system.restricted_nll() == pytest.approx(nll, rel=1e-6, abs=1e-6)


def test_a_full_precision_csv_reads_back_as_the_frame_written(tmp_path):
    frame = pd.DataFrame({"a": [0.1 + 0.2, 1 / 3, -2.5e-12], "b": [1e17 + 8, 7.0, np.pi], "name": ["x", "y", "z"]})
    path = tmp_path / "runs.csv"
    write_full_csv(frame, path)
    back = pd.read_csv(path)
    assert list(back.columns) == list(frame.columns)
    pd.testing.assert_frame_equal(back, frame, check_exact=True)
    assert path.read_text().splitlines()[0] == "a,b,name"


def test_copy_files_writes_atomic_byte_copies_and_the_log_into_an_existing_folder(tmp_path):
    from demid.io import copy_files

    source = tmp_path / "a b.csv"
    source.write_bytes(b"x,y\n1,2\n")
    (tmp_path / "out").mkdir()
    destination, log = tmp_path / "out" / "copy.csv", tmp_path / "out" / "copied.txt"
    copy_files({source: destination}, log)
    assert destination.read_bytes() == source.read_bytes()
    assert log.read_text(encoding="utf-8") == f"{source} -> {destination}\n"
