"""sample() for every kind, discrepancy() and spacing() against the command."""
import numpy as np
import pytest

import mcspec
from conftest import f17, points_text


@pytest.mark.parametrize("dim", [1, 2])
def test_every_kind_draws_sets_in_the_unit_cube(dim):
    for kind in mcspec.kinds(dim):
        k = 16
        pts = mcspec.sample(kind, dim, k, sets=3, seed=9)
        assert pts.shape == (3, k, dim) and pts.dtype == np.float64
        assert (pts >= 0).all() and (pts < 1).all()
        again = mcspec.sample(kind, dim, k, sets=3, seed=9)
        assert np.array_equal(pts, again)


def test_unknown_kinds_and_bad_k_raise_with_the_status_name():
    with pytest.raises(mcspec.Error) as e:
        mcspec.sample("nope", 2, 4)
    assert e.value.name == "MCS_ERR_KIND"
    with pytest.raises(mcspec.Error) as e:
        mcspec.sample("halton", 1, 4)
    assert e.value.name == "MCS_ERR_KIND"
    with pytest.raises(mcspec.Error) as e:
        mcspec.sample("jittered", 2, 0)
    assert e.value.name == "MCS_ERR_K_RANGE"


def test_discrepancies_and_spacing_are_the_command_s_means(cli, tmp_path):
    pts = mcspec.sample("random", 2, 40, sets=5, seed=4)
    f = tmp_path / "p.txt"
    f.write_text(points_text(pts))
    d = mcspec.discrepancy(pts, star=True)
    rows = cli("discrepancy", f)
    head = rows[0]
    for row in rows[1:]:
        name = row[head.index("measure")]
        vals = d[name] if name in d else None
        if vals is None:
            continue
        # the command's mean over the sets, formed as mcs_discrepancy does (Welford)
        acc = 0.0
        for i, v in enumerate(vals if name != "star" else vals ** 2):
            acc += (v - acc) / (i + 1)
        assert f17(acc) == row[head.index("value")], name
    s = mcspec.spacing(pts)
    spectral = mcspec.spectral_stats(pts)
    rows = cli("stats", f)
    head = rows[0]
    names = []
    for row in rows[1:]:
        name = row[head.index("statistic")]
        names.append(name)
        if name in spectral:  # effective Nyquist and oscillations, per set and of the mean
            want = spectral[name]
            assert [row[head.index("value")], row[head.index("stderr")]] == \
                [("" if np.isnan(v) else f17(v)) for v in want], name
            continue
        acc = 0.0
        for i, v in enumerate(s[name]):
            acc += (v - acc) / (i + 1)
        assert f17(acc) == row[head.index("value")], name
    assert set(names) == set(s) | set(spectral)
