"""A compressed run folder (covsim run --compress): trajectory.csv.gz is what pandas and numpy
read directly, the same table as the uncompressed run's trajectory.csv, and load_run reads
either."""
import gzip

import numpy as np
import pytest

import covsim


@pytest.fixture
def runs(scenarios, cli, tmp_path):
    cli("run", scenarios / "u_shape.json", "--out", tmp_path / "plain")
    cli("run", scenarios / "u_shape.json", "--out", tmp_path / "packed", "--compress")
    return tmp_path / "plain", tmp_path / "packed"


def test_pandas_and_numpy_read_the_gz_as_the_csv(runs):
    pandas = pytest.importorskip("pandas")
    plain, packed = runs
    assert not (packed / "trajectory.csv").exists()
    with gzip.open(packed / "trajectory.csv.gz", "rb") as f:
        assert f.read() == (plain / "trajectory.csv").read_bytes()
    csv = pandas.read_csv(plain / "trajectory.csv")
    gz = pandas.read_csv(packed / "trajectory.csv.gz")  # compression inferred from the name
    assert list(gz.columns) == ["t", "robot", "x", "y", "vx", "vy", "tx", "ty", "rx", "ry"]
    assert len(gz) > 1000
    pandas.testing.assert_frame_equal(gz, csv, check_exact=True)
    table = np.loadtxt(packed / "trajectory.csv.gz", delimiter=",", skiprows=1)
    assert np.array_equal(table, np.loadtxt(plain / "trajectory.csv", delimiter=",", skiprows=1))
    # pandas' default parser may miss the last bit; its round-trip one reads the exact doubles.
    exact = pandas.read_csv(packed / "trajectory.csv.gz", float_precision="round_trip")
    assert np.array_equal(table, exact.to_numpy(dtype=float))


def test_load_run_reads_a_compressed_folder(runs):
    plain, packed = runs
    a, b = covsim.load_run(plain), covsim.load_run(packed)
    assert a.trajectory.keys() == b.trajectory.keys()
    for name in a.trajectory:
        assert np.array_equal(a.trajectory[name], b.trajectory[name]), name
    assert b.trajectory["robot"].dtype == np.int64
    assert np.array_equal(b.path(2), a.path(2))
    # Both files in one folder: which one is the run's is unknown.
    (packed / "trajectory.csv").write_bytes((plain / "trajectory.csv").read_bytes())
    with pytest.raises(ValueError, match="both trajectory.csv and trajectory.csv.gz"):
        covsim.load_run(packed)
