"""The measure accumulators Discrepancy, Spacing and IntegrationError
(discrepancy.h, spacing.h, integrate.h) and their records (kinds 9 to 11):
the numbers of `mcspec discrepancy`, `stats` and `integrate --family F` bit
for bit, records of the commands' --save that load with those numbers,
records from Python that `mcspec show` reads, merge as one add over both,
and refused input that changes nothing."""
import math
import os
import subprocess

import numpy as np
import pytest

import mcspec
from conftest import ROOT, f17, points_text


def csv17(x):
    """x as the command's CSV prints it: %.17g, an empty field for NaN."""
    return "" if math.isnan(x) else f17(x)


def _file(tmp_path, pts, name="pts.txt"):
    path = tmp_path / name
    path.write_text(points_text(pts))
    return path


def _show(path):
    exe = os.environ.get("MCSPEC", os.path.join(ROOT, "build", "bin", "mcspec"))
    out = subprocess.run([exe, "show", str(path), "--csv"], capture_output=True, check=True,
                         text=True).stdout
    return [line.split(",") for line in out.strip().splitlines()]


def _disc_rows(acc):
    mean, se, ex, root = acc.mean, acc.stderr, acc.exact_random, acc.root
    return [[m, csv17(mean[m]), csv17(se[m]), csv17(ex.get(m, math.nan)), csv17(root[m])]
            for m in mean]


def _spacing_rows(acc):
    mean, se = acc.mean, acc.stderr
    return [[s, csv17(mean[s]), csv17(se[s])] for s in mcspec.measures.SPACING]


# ---- bit for bit with the commands --------------------------------------------

@pytest.mark.parametrize("dim,kind,k", [(2, "jittered", 60), (3, "random", 40), (1, "random", 30)])
def test_a_discrepancy_gives_the_command_numbers_and_its_record_loads_with_them(
        cli, tmp_path, dim, kind, k):
    pts = mcspec.sample(kind, dim, k, sets=5, seed=2)
    src = _file(tmp_path, pts)
    rec = tmp_path / "d.rec"
    rows = [r[:5] for r in cli("discrepancy", "--dim", dim, "--save", rec, src)[1:]]
    acc = mcspec.Discrepancy(dim).add(pts)
    assert _disc_rows(acc) == rows
    loaded = mcspec.load_file(str(rec))
    assert isinstance(loaded, mcspec.Discrepancy)
    assert (loaded.dim, loaded.count, loaded.k_range) == (dim, 5, (k, k))
    assert _disc_rows(loaded) == rows
    mine = tmp_path / "py.rec"
    mcspec.save_file(acc, str(mine))
    assert [r[:5] for r in _show(mine)[1:]] == rows


def test_a_float32_batch_adds_as_its_widened_doubles():
    pts = mcspec.sample("random", 2, 50, sets=4, seed=5).astype(np.float32)
    a = mcspec.Discrepancy(2).add(pts)
    b = mcspec.Discrepancy(2).add(pts.astype(np.float64))
    assert mcspec.save(a) == mcspec.save(b)
    assert mcspec.save(mcspec.Spacing(2).add(pts)) == \
        mcspec.save(mcspec.Spacing(2).add(pts.astype(np.float64)))


@pytest.mark.parametrize("dim,k", [(2, 200), (3, 60), (1, 25)])
def test_a_spacing_gives_the_distance_rows_of_mcspec_stats(cli, tmp_path, dim, k):
    pts = mcspec.sample("random", dim, k, sets=6, seed=4)
    src = _file(tmp_path, pts)
    rec = tmp_path / "s.rec"
    rows = [r[:3] for r in cli("stats", "--dim", dim, "--save", rec, src)[1:3]]
    acc = mcspec.Spacing(dim).add(pts)
    assert _spacing_rows(acc) == rows
    loaded = mcspec.load_file(str(rec))
    assert isinstance(loaded, mcspec.Spacing) and loaded.count == 6
    assert _spacing_rows(loaded) == rows
    mine = tmp_path / "py.rec"
    mcspec.save_file(acc, str(mine))
    assert [r[:3] for r in _show(mine)[1:]] == rows


def test_a_spacing_of_random_sets_reads_the_command_exact_column(cli, tmp_path):
    rec = tmp_path / "s.rec"
    rows = cli("stats", "random", "--dim", 2, "--k", 64, "--sets", 8, "--save", rec)
    acc = mcspec.Spacing(2).add(mcspec.sample("random", 2, 64, sets=8, seed=1))
    assert csv17(acc.exact_random["avg_min_distance"]) == rows[2][3]
    assert math.isnan(acc.exact_random["min_distance"]) and rows[1][3] == ""
    assert _spacing_rows(mcspec.load_file(str(rec))) == [r[:3] for r in rows[1:3]]


@pytest.mark.parametrize("kind,family,dim,k", [("random", "gaussian", 2, 64),
                                               ("jittered", "disk", 2, 60),
                                               ("random", "heaviside", 1, 32)])
def test_an_integration_error_of_drawn_sets_gives_the_command_row(cli, tmp_path, kind, family,
                                                                  dim, k):
    rec = tmp_path / "i.rec"
    row = cli("integrate", kind, "--dim", dim, "--k", k, "--sets", 7, "--family", family,
              "--save", rec)[1]
    acc = mcspec.IntegrationError(family, dim, exact=kind).add(
        mcspec.sample(kind, dim, k, sets=7, seed=1, stream=1))
    mine = [family, str(k), csv17(acc.mse), csv17(acc.mse_stderr), csv17(acc.exact)]
    assert mine == row[:5]
    loaded = mcspec.load_file(str(rec))
    assert isinstance(loaded, mcspec.IntegrationError)
    assert (loaded.family, loaded.dim, loaded.count, loaded.k_range) == (family, dim, 7, (k, k))
    assert [csv17(v) for v in (loaded.mse, loaded.mse_stderr, loaded.exact)] == row[2:5]
    path = tmp_path / "py.rec"
    mcspec.save_file(acc, str(path))
    assert _show(path)[1][:5] == row[:5]


def test_an_integration_error_of_a_point_file_gives_the_command_row(cli, tmp_path):
    pts = mcspec.sample("halton", 2, 50, sets=5, seed=3)
    src = _file(tmp_path, pts)
    rec = tmp_path / "i.rec"
    row = cli("integrate", "--family", "blinn_phong", "--integrands", 5, "--seed", 9,
              "--save", rec, src)[1]
    acc = mcspec.IntegrationError("blinn_phong", 2, integrands=5, seed=9).add(pts)
    assert [csv17(v) for v in (acc.mse, acc.mse_stderr, acc.exact)] == row[2:5]
    assert row[4] == ""
    assert mcspec.save(mcspec.load_file(str(rec)))[:32] == mcspec.save(acc)[:32]


# ---- merge ---------------------------------------------------------------------

def _close(a, b):
    for key in a:
        if math.isnan(a[key]):
            assert math.isnan(b[key])
        else:
            assert a[key] == pytest.approx(b[key], rel=1e-13, abs=1e-300)


def test_a_merge_is_one_add_over_both():
    a_pts = mcspec.sample("random", 2, 40, sets=5, seed=11)
    b_pts = [mcspec.sample("random", 2, 70, sets=1, seed=12)[0] for _ in range(3)]
    both = list(a_pts) + b_pts
    for cls in (mcspec.Discrepancy, mcspec.Spacing):
        a, b, one = cls(2).add(a_pts), cls(2).add(b_pts), cls(2).add(both)
        merged = mcspec.merge(mcspec.save(a), b)
        assert (merged.count, merged.k_range) == (8, (40, 70))
        assert mcspec.save(merged) == mcspec.save(a.copy().merge(b))
        _close(merged.mean, one.mean)
        _close(merged.stderr, one.stderr)
    # the integrand stream goes on over a reset: the same integrands per set
    ie = mcspec.IntegrationError("gaussian", 2, exact="random")
    a = ie.add(a_pts).copy()
    b = ie.reset().add(b_pts)
    one = mcspec.IntegrationError("gaussian", 2, exact="random").add(both)
    merged = mcspec.merge(a, mcspec.save(b))
    assert merged.count == 8 and merged.count == one.count
    for attr in ("mse", "mse_stderr", "exact"):
        assert getattr(merged, attr) == pytest.approx(getattr(one, attr), rel=1e-13)
    assert a.count == 5  # merge() made a new object


def test_adds_in_two_calls_are_bit_equal_to_one():
    pts = mcspec.sample("jittered", 2, 36, sets=6, seed=7)
    for make in (lambda: mcspec.Discrepancy(2), lambda: mcspec.Spacing(2),
                 lambda: mcspec.IntegrationError("cosine", 2, integrands=3)):
        assert mcspec.save(make().add(pts[:2]).add(pts[2:])) == mcspec.save(make().add(pts))


# ---- refused input changes nothing ------------------------------------------------

def _status(excinfo):
    return excinfo.value.name


@pytest.mark.parametrize("make", [lambda: mcspec.Discrepancy(2), lambda: mcspec.Spacing(2),
                                  lambda: mcspec.IntegrationError("gaussian", 2,
                                                                  exact="random")])
def test_refused_sets_raise_and_change_nothing(make):
    acc = make().add(mcspec.sample("random", 2, 30, sets=2, seed=1))
    before = mcspec.save(acc)
    good = mcspec.sample("random", 2, 30, sets=3, seed=2)
    nan, high, neg = good.copy(), good.copy(), good.copy()
    nan[2, 5, 1] = np.nan        # the last set: the first two were taken, then rolled back
    high[1, 0, 0] = 1.0
    neg[2, 29, 0] = -1e-300
    bad = [(nan, "MCS_ERR_POINT_RANGE"), (high, "MCS_ERR_POINT_RANGE"),
           (neg, "MCS_ERR_POINT_RANGE"),
           ((good * 1000).astype(np.int64), "MCS_ERR_POINT_RANGE"),
           (good[:, :, :1].copy(), "MCS_ERR_MISMATCH"),
           (mcspec.sample("random", 3, 30, sets=2, seed=2), "MCS_ERR_MISMATCH"),
           (np.zeros((2, 0, 2)), "MCS_ERR_K_RANGE"), ([], "MCS_ERR_K_RANGE"),
           (np.zeros((2, 2, 2, 2)), "MCS_ERR_MISMATCH")]
    for sets, name in bad:
        with pytest.raises(mcspec.Error) as e:
            acc.add(sets)
        assert _status(e) == name, sets
        assert mcspec.save(acc) == before
    # and the next add is the one a fresh object would make (the integrand
    # stream of IntegrationError did not move either)
    assert mcspec.save(acc.add(good)) == mcspec.save(make().add(
        mcspec.sample("random", 2, 30, sets=2, seed=1)).add(good))


def test_a_spacing_refuses_a_set_of_one_point_and_changes_nothing():
    acc = mcspec.Spacing(2).add(mcspec.sample("random", 2, 10, sets=2, seed=1))
    before = mcspec.save(acc)
    with pytest.raises(mcspec.Error) as e:
        acc.add([mcspec.sample("random", 2, 10, sets=1, seed=2)[0], np.full((1, 2), 0.5)])
    assert _status(e) == "MCS_ERR_K_RANGE" and mcspec.save(acc) == before


def test_mismatched_merges_raise_and_change_nothing():
    pts2 = mcspec.sample("random", 2, 20, sets=3, seed=1)
    pts3 = mcspec.sample("random", 3, 20, sets=3, seed=1)
    pairs = [(mcspec.Discrepancy(2).add(pts2), mcspec.Discrepancy(3).add(pts3)),
             (mcspec.Spacing(2).add(pts2), mcspec.Spacing(3).add(pts3)),
             (mcspec.Discrepancy(2).add(pts2), mcspec.Spacing(2).add(pts2)),
             (mcspec.IntegrationError("gaussian", 2).add(pts2),
              mcspec.IntegrationError("disk", 2).add(pts2)),
             (mcspec.IntegrationError("gaussian", 2).add(pts2),
              mcspec.IntegrationError("gaussian", 1).add(pts2[:, :, :1].copy())),
             (mcspec.Spacing(2).add(pts2), mcspec.PairCorrelation(2, 1.0, 4).add(pts2))]
    for a, b in pairs:
        before, other = mcspec.save(a), mcspec.save(b)
        with pytest.raises(mcspec.Error) as e:
            a.merge(b)
        assert _status(e) == "MCS_ERR_MISMATCH"
        assert mcspec.save(a) == before and mcspec.save(b) == other
        with pytest.raises(mcspec.Error):
            mcspec.merge(before, other)


def test_bad_settings_and_damaged_records_are_refused():
    for call, name in ((lambda: mcspec.Discrepancy(0), "MCS_ERR_DOMAIN"),
                       (lambda: mcspec.Discrepancy(65), "MCS_ERR_DOMAIN"),
                       (lambda: mcspec.Spacing(9), "MCS_ERR_DOMAIN"),
                       (lambda: mcspec.IntegrationError("gaussian", 3), "MCS_ERR_DOMAIN"),
                       (lambda: mcspec.IntegrationError("nope", 2), "MCS_ERR_KIND"),
                       (lambda: mcspec.IntegrationError("disk", 2, integrands=0),
                        "MCS_ERR_K_RANGE"),
                       (lambda: mcspec.IntegrationError("disk", 2, exact="grid"),
                        "MCS_ERR_KIND")):
        with pytest.raises(mcspec.Error) as e:
            call()
        assert _status(e) == name
    for acc in (mcspec.Discrepancy(2), mcspec.Spacing(4), mcspec.IntegrationError("disk", 2)):
        data = bytearray(mcspec.save(acc.add(mcspec.sample("random", acc.dim, 16, sets=2))))
        assert mcspec.save(mcspec.load(bytes(data))) == bytes(data)
        data[33] ^= 1
        with pytest.raises(mcspec.Error) as e:
            mcspec.load(bytes(data))
        assert _status(e) == "MCS_ERR_CHECKSUM"


def test_empty_accumulators_read_nan():
    d, s, i = mcspec.Discrepancy(2), mcspec.Spacing(2), mcspec.IntegrationError("disk", 2)
    assert d.count == s.count == i.count == 0
    assert all(math.isnan(v) for v in list(d.mean.values()) + list(s.stderr.values()))
    assert math.isnan(i.mse) and math.isnan(i.exact)
    one = mcspec.Spacing(2).add(mcspec.sample("random", 2, 16, sets=1))
    assert not math.isnan(one.mean["min_distance"]) and math.isnan(one.stderr["min_distance"])
