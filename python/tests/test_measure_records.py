"""Records of the pair correlation (kind 8, docs/format.md) from Python: a
PairCorrelation saves and loads as bytes and files, a loaded one reads out
and merges like the saved one, a record of `mcspec pcf --save` loads with
the command's numbers, and damaged records are refused."""
import numpy as np
import pytest

import mcspec
from conftest import f17, points_text


def _acc(seed, rdf=True):
    pts = mcspec.sample("jittered", 2, 64, sets=8, seed=seed)
    return mcspec.PairCorrelation(dim=2, radius=2.0, bins=10, sigma=0.2, rdf=rdf).add(pts)


def test_a_pair_correlation_round_trips_and_merges_like_the_saved_one(tmp_path):
    for rdf in (True, False):
        a, b = _acc(1, rdf), _acc(2, rdf)
        data = mcspec.save(a)
        back = mcspec.load(data)
        assert isinstance(back, mcspec.PairCorrelation)
        assert (back.dim, back.bins, back.rdf, back.radius, back.sigma if not rdf else 0.0) == \
            (2, 10, rdf, 2.0, 0.2 if not rdf else 0.0)
        assert mcspec.save(back) == data
        np.testing.assert_array_equal(back.mean, a.mean)
        np.testing.assert_array_equal(back.stderr, a.stderr)
        merged = mcspec.merge(data, b)
        assert merged.count == 16
        assert mcspec.save(merged) == mcspec.save(a.merge(b))
        path = tmp_path / "p.rec"
        mcspec.save_file(back, str(path))
        assert mcspec.save(mcspec.load_file(str(path))) == data


def test_a_record_of_the_command_loads_with_its_numbers(cli, tmp_path):
    pts = mcspec.sample("random", 2, 100, sets=6, seed=3)
    src = tmp_path / "pts.txt"
    src.write_text(points_text(pts))
    rows = cli("pcf", "--rdf", "--bins", 6, "--radius", 2, "--save", tmp_path / "c.rec", src)
    acc = mcspec.load_file(str(tmp_path / "c.rec"))
    assert [f17(v) for v in acc.mean] == [row[1] for row in rows[1:]]
    assert [f17(v) for v in acc.stderr] == [row[2] for row in rows[1:]]


def test_damaged_and_foreign_records_are_refused():
    data = bytearray(mcspec.save(_acc(4)))
    data[40] ^= 1  # a shape word: the checksum no longer matches
    with pytest.raises(mcspec.Error):
        mcspec.load(bytes(data))
    with pytest.raises(mcspec.Error):
        mcspec.load(bytes(data[:50]))
