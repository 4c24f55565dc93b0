"""Every point-set wrapper against the command's own numbers, bit for bit
(its --csv prints %.17g, which round-trips a double)."""
import numpy as np
import pytest

import mcspec
from conftest import f17, points_text


def test_version_is_the_library_s_and_says_which_file_was_loaded():
    assert mcspec.__version__.count(".") == 2
    assert "libmcspec.so" in mcspec.library_path


def test_2d_periodogram_of_sampled_sets_is_the_pattern_command_bit_for_bit(cli):
    pts = mcspec.sample("jittered", 2, 64, sets=20, seed=7)
    mean, se = mcspec.periodogram(pts, 5)
    rows = cli("pattern", "jittered", "--dim", "2", "--k", 64, "--freq", 5, "--trials", 20,
               "--seed", 7)
    assert rows[0][:4] == ["kx", "ky", "power", "power_stderr"]
    for kx, ky, p, s, *_ in rows[1:]:
        assert f17(mean[int(ky) + 5, int(kx) + 5]) == p
        assert f17(se[int(ky) + 5, int(kx) + 5]) == s


def test_radial_power_and_anisotropy_are_the_command_s_for_a_sampler(cli):
    pts = mcspec.sample("sobol-owen", 2, 128, sets=10, seed=3)
    mean, se = mcspec.periodogram(pts, 6, radial=True)
    aniso = mcspec.anisotropy(pts, 6)
    rows = cli("pattern", "sobol-owen", "--dim", "2", "--k", 128, "--freq", 6, "--trials", 10,
               "--seed", 3, "--radial")
    for r, p, s, a, *_ in rows[1:]:
        r = int(r)
        assert (f17(mean[r]), f17(se[r])) == (p, s)
        assert (a == "" and np.isnan(aniso[r])) or f17(aniso[r]) == a


# `mcspec spectrum FILE` may form its statistics by merging one-set objects
# (Chan's update, as mcspec-mpi must) where periodogram() adds the sets in
# turn (Welford, as mcs_pointset2d_add and `mcspec pattern --dim 2`): the two
# agree to rounding, not always in the last bit of a standard error.
SPECTRUM_RTOL = 1e-14


def test_spectrum_of_a_point_file_matches_in_1d_2d_and_float32(cli, tmp_path):
    rng = np.random.default_rng(5)
    for d in (1, 2):
        sets = rng.random((6, 33, d))
        f = tmp_path / ("p%d.txt" % d)
        f.write_text(points_text(sets))
        rows = cli("spectrum", "--freq", 9, "--dim", d, f)
        mean, se = mcspec.periodogram(sets, 9)
        for row in rows[1:]:
            idx = (int(row[0]),) if d == 1 else (int(row[1]) + 9, int(row[0]) + 9)
            np.testing.assert_allclose([mean[idx], se[idx]], [float(row[d]), float(row[d + 1])],
                                       rtol=SPECTRUM_RTOL, atol=0)
    s32 = rng.random((4, 20, 2)).astype(np.float32)
    wide = mcspec.periodogram(s32.astype(np.float64), 4)
    narrow = mcspec.periodogram(s32, 4)
    assert np.array_equal(wide.mean, narrow.mean) and np.array_equal(wide.stderr, narrow.stderr)


def test_a_list_of_sets_of_different_k_is_one_accumulation(cli, tmp_path):
    rng = np.random.default_rng(1)
    sets = [rng.random((k, 2)) for k in (10, 17, 17, 3)]
    f = tmp_path / "p.txt"
    f.write_text(points_text(sets))
    rows = cli("spectrum", "--freq", 3, "--dim", 2, f)
    mean, se = mcspec.periodogram(sets, 3)
    for row in rows[1:]:
        np.testing.assert_allclose(mean[int(row[1]) + 3, int(row[0]) + 3], float(row[2]),
                                   rtol=SPECTRUM_RTOL, atol=0)


def test_pointset_merge_of_halves_is_one_pass_and_copies_are_independent():
    pts = mcspec.sample("random", 2, 50, sets=8, seed=2)
    a = mcspec.PointSet(4).add(pts[:4])
    b = mcspec.PointSet(4).add(pts[4:])
    whole = mcspec.PointSet(4).add(pts)
    c = a.copy()
    a.merge(b)
    assert a.count == 8 and c.count == 4
    np.testing.assert_allclose(a.power, whole.power, rtol=1e-13)


def test_exact_power_of_jittered_is_the_library_s_closed_form():
    power, radial = mcspec.exact_power("jittered", 16, 3)
    assert power[3, 3] == 16.0
    fx, fy = mcspec.wave_vectors(3)
    s = lambda f: np.sinc(f / 4.0) ** 2
    np.testing.assert_allclose(power[(fx != 0) | (fy != 0)],
                               (1 - s(fx) * s(fy))[(fx != 0) | (fy != 0)], rtol=1e-12)


def test_the_package_version_in_pyproject_is_the_library_s():
    import os
    import re
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    text = open(os.path.join(here, "pyproject.toml")).read()
    assert re.search(r'^version = "([^"]+)"', text, re.M).group(1) == mcspec.__version__
