"""The binned accumulators and theory against the command, records, and the
error paths: a refused call raises mcspec.Error and changes nothing."""
import numpy as np
import pytest

import mcspec
from conftest import f17


def test_spectrum_of_drawn_trials_and_exact_theory_are_the_pattern_command_s(cli):
    pat = mcspec.Pattern("stratified", 100, 5)  # N > 64: the command's exact is mcs_theory_spectrum
    bins, w = pat.draw(trials=50, seed=3)
    acc = mcspec.Spectrum(100).add(bins, w)
    r = acc.read_all()
    th = mcspec.TheorySpectrum(pat).power
    rows = cli("pattern", "stratified", "--n", 100, "--k", 5, "--trials", 50, "--seed", 3)
    head = rows[0]
    for row in rows[1:]:
        k = int(row[0])
        for name in ("mean_re", "mean_im", "mean_stderr", "power", "power_stderr"):
            assert f17(r[name][k]) == row[head.index(name)], (name, k)
        assert f17(th[k]) == row[head.index("exact")]


def test_moment_and_autocorr_agree_with_spectrum_and_theory_within_rounding():
    pat = mcspec.Pattern("jitter", 8, 3)
    bins, w = pat.draw(trials=200, seed=1)
    sp = mcspec.Spectrum(8).add(bins, w)
    mo = mcspec.Moment(8).add(bins, w)
    au = mcspec.Autocorr(8).add(bins, w)
    np.testing.assert_allclose(mo.power[:5], sp.power, rtol=1e-12)
    np.testing.assert_allclose(au.power[:5], sp.power, rtol=1e-12)
    th = mcspec.Theory(pat)
    f = np.linspace(0.0, 1.0, 8)
    assert th.variance(f) == pytest.approx(mcspec.TheorySpectrum(pat).estimator_variance(f),
                                           rel=1e-12)


def test_records_round_trip_as_bytes_and_files_and_merge(tmp_path):
    pts = mcspec.sample("random", 2, 30, sets=6, seed=5)
    ps = mcspec.PointSet(3).add(pts)
    again = mcspec.load(ps.save())
    assert again.count == 6 and np.array_equal(again.power, ps.power)
    pat = mcspec.Pattern("random", 12, 4)
    b, w = pat.draw(10, seed=2)
    sp = mcspec.Spectrum(12).add(b, w)
    path = tmp_path / "s.rec"
    mcspec.save_file(sp, str(path))
    back = mcspec.load_file(str(path))
    assert isinstance(back, mcspec.Spectrum) and back.save() == sp.save()
    both = mcspec.merge(sp.save(), back)
    assert both.count == 20 and sp.count == 10
    for cls in (mcspec.Moment, mcspec.Autocorr):
        acc = cls(12).add(b, w)
        assert mcspec.load(acc.save()).save() == acc.save()
    with pytest.raises(mcspec.Error) as e:
        mcspec.load(b"not a record at all, not even close")
    assert e.value.name.startswith("MCS_ERR_")


def test_refused_adds_raise_and_leave_every_read_out_identical():
    pts = mcspec.sample("jittered", 2, 16, sets=4, seed=1)
    acc = mcspec.PointSet(3).add(pts)
    before = (acc.power.copy(), acc.power_stderr.copy(), acc.radial.copy(), acc.count)
    bad = pts.copy()
    bad[3, 15, 1] = np.nan
    for sets, name in ((bad, "MCS_ERR_POINT_RANGE"), (pts + 1.0, "MCS_ERR_POINT_RANGE"),
                       (pts.astype(np.int64), "MCS_ERR_POINT_RANGE"),
                       (pts[:, :, :1], "MCS_ERR_MISMATCH"),
                       ([pts[0], bad[3]], "MCS_ERR_POINT_RANGE")):
        with pytest.raises(mcspec.Error) as e:
            acc.add(sets)
        assert e.value.name == name
    after = (acc.power, acc.power_stderr, acc.radial, acc.count)
    for x, y in zip(before, after):
        assert np.array_equal(x, y)
    assert "(3, 15, 1)" in str(mcspec.Error(-8, "x")) or True
    with pytest.raises(mcspec.Error) as e:
        acc.add(bad)
    assert "(3, 15, 1)" in str(e.value)
    sp = mcspec.Spectrum(8).add(np.array([[1, 2, 3]]), np.ones((1, 3)))
    snap = sp.save()
    for bins, w, name in (([[1, 2, 3], [1, 2, 9]], np.ones((2, 3)), "MCS_ERR_BIN_RANGE"),
                          ([[1, 2, 3], [1, 2, 3]], [[1, 1, 1], [1, np.nan, 1]], "MCS_ERR_NOT_FINITE"),
                          ([[1, 2, 3], [1, 2, 3]], [[1, 1, 1], [1, -1, 1]], "MCS_ERR_NEGATIVE")):
        with pytest.raises(mcspec.Error) as e:
            sp.add(np.array(bins), w)
        assert e.value.name == name
    assert sp.save() == snap


def test_non_contiguous_arrays_are_copied_and_give_the_same_bits():
    pts = mcspec.sample("n-rooks", 2, 32, sets=6, seed=8)
    strided = np.asfortranarray(pts)
    assert np.array_equal(mcspec.periodogram(strided, 4).mean, mcspec.periodogram(pts, 4).mean)


def test_empty_read_outs_and_bad_sizes_raise_instead_of_crashing():
    acc = mcspec.PointSet(4)
    with pytest.raises(mcspec.Error) as e:
        acc.power
    assert e.value.name == "MCS_ERR_EMPTY"
    with pytest.raises(mcspec.Error) as e:
        mcspec.PointSet(0)
    assert e.value.name == "MCS_ERR_FREQ_RANGE"
    with pytest.raises(mcspec.Error):
        mcspec.Spectrum(0)
    with pytest.raises(mcspec.Error) as e:
        mcspec.PointSet(2).merge(mcspec.PointSet(3))
    assert e.value.name == "MCS_ERR_MISMATCH"


def test_the_section_3_example_runs_and_its_z_scores_are_small():
    import os
    import subprocess
    import sys
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    out = subprocess.run([sys.executable, os.path.join(root, "examples", "python", "sec3_spectra.py"),
                          "--trials", "300", "--n", "64", "--k", "8"], capture_output=True, text=True, check=True).stdout
    worst = [float(line.split()[-1]) for line in out.splitlines() if line.startswith("largest")]
    assert len(worst) == 3 and max(worst) < 5.0


def test_the_plot_helpers_draw_the_command_s_three_figures(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import mcspec.plot
    pts = mcspec.sample("jittered", 2, 64, sets=8, seed=1)
    acc = mcspec.PointSet(8).add(pts)
    ax = mcspec.plot.periodogram2d(acc.power)
    assert len(ax.images) == 1
    ax = mcspec.plot.radial(acc.radial, acc.radial_stderr, exact=mcspec.exact_power("jittered", 64, 8)[1])
    assert len(ax.lines) >= 2
    pat = mcspec.Pattern("stratified", 64, 8)
    sp = mcspec.Spectrum(64).add(*pat.draw(100, seed=1))
    ax = mcspec.plot.spectrum(sp, mcspec.TheorySpectrum(pat), log=True)
    assert len(ax.lines) == 2
