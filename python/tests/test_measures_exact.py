"""The exact columns of mcspec discrepancy KIND and mcspec stats KIND from
Python: mcspec.discrepancy_exact_jittered and mcspec.spacing_exact_random
give the command's exact columns bit for bit, and the means of the per-set
values over sets drawn by mcspec.sample lie within 5 standard errors."""
import math

import numpy as np
import pytest

import mcspec
from conftest import f17


def _mean_se(v):
    return v.mean(), v.std(ddof=1) / math.sqrt(len(v))


def test_jittered_exact_is_the_command_s_column(cli):
    rows = cli("discrepancy", "jittered", "--dim", 2, "--k", 32, "--sets", 2)
    head = rows[0]
    for row in rows[1:]:
        name = row[head.index("measure")]
        if name == "star":
            assert row[head.index("exact")] == ""
            continue
        # 32 points: the pattern's most nearly square grid is 8 x 4
        assert row[head.index("exact")] == f17(mcspec.discrepancy_exact_jittered(name, (8, 4)))


def test_jittered_and_stratified_means_are_within_5_stderr():
    pts = mcspec.sample("jittered", 2, 64, sets=2000, seed=3)
    d = mcspec.discrepancy(pts)
    for name, v in d.items():
        mean, se = _mean_se(v)
        want = mcspec.discrepancy_exact_jittered(name, 8, 2)
        assert want == mcspec.discrepancy_exact_jittered(name, (8, 8))
        assert abs(mean - want) < 5 * se, (name, mean, want, se)
        assert se < 0.03 * want
    d = mcspec.discrepancy(mcspec.sample("stratified", 1, 16, sets=2000, seed=4))
    for name, v in d.items():
        mean, se = _mean_se(v)
        want = mcspec.discrepancy_exact_jittered(name, 16, 1)
        assert abs(mean - want) < 5 * se, (name, mean, want, se)
    # the L2 star in 1D: 1/(6 K^2)
    assert mcspec.discrepancy_exact_jittered("l2_star", 16, 1) == pytest.approx(1 / (6 * 256), 1e-14)


def test_spacing_exact_is_the_command_s_column_and_the_mean():
    pts = mcspec.sample("random", 2, 32, sets=2000, seed=5)
    s = mcspec.spacing(pts)
    mean, se = _mean_se(s["avg_min_distance"])
    want = mcspec.spacing_exact_random("avg_min_distance", 2, 32)
    assert abs(mean - want) < 5 * se, (mean, want, se)
    assert mcspec.spacing_exact_random("min_distance", 1, 10) == pytest.approx(0.1, 1e-15)
    assert mcspec.spacing_exact_random("avg_min_distance", 1, 10) == 0.5
    with pytest.raises(mcspec.Error) as e:
        mcspec.spacing_exact_random("min_distance", 2, 32)
    assert e.value.name == "MCS_ERR_DOMAIN"
    with pytest.raises(mcspec.Error) as e:
        mcspec.discrepancy_exact_jittered("l2_star", 0, 2)
    assert e.value.name == "MCS_ERR_K_RANGE"


def test_stats_kind_exact_column(cli):
    rows = cli("stats", "random", "--dim", 2, "--k", 32, "--sets", 2)
    head = rows[0]
    got = {r[0]: r[head.index("exact")] for r in rows[1:]}
    assert got["avg_min_distance"] == f17(mcspec.spacing_exact_random("avg_min_distance", 2, 32))
    assert got["min_distance"] == ""
    assert np.isfinite(float(got["avg_min_distance"]))
