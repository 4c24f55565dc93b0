"""sample() for every kind in any dimension, pcf(), spectral_stats(),
integration_error() and projections() against the command's output, bit
for bit, and their refusals."""
import subprocess

import numpy as np
import pytest

import mcspec
from conftest import f17, points_text


def c17(x):
    """x as the command's CSV prints it: %.17g, or empty for NaN."""
    return "" if np.isnan(x) else f17(x)


@pytest.fixture(scope="module")
def raw(cli):
    """The command's plain standard output (mcspec sample has no --csv)."""
    import os
    from conftest import ROOT
    exe = os.environ.get("MCSPEC", os.path.join(ROOT, "build", "bin", "mcspec"))

    def run(*args):
        return subprocess.run([exe] + [str(a) for a in args], capture_output=True, check=True,
                              text=True).stdout
    return run


@pytest.mark.parametrize("dim,k", [(1, 12), (2, 12), (3, 7), (5, 9)])
def test_every_kind_of_mcspec_sample_draws_the_command_s_sets_bit_for_bit(raw, dim, k):
    names = mcspec.kinds(dim)
    assert "random" in names and "sobol-owen" in names and "lattice" in names
    if dim <= 3:
        assert "poisson-disk" in names and "dart-throwing" in names
    if dim == 2:
        assert {"lloyd", "pmj02", "pmj02bn", "padded", "halton-owen"} <= set(names)
    for kind in names:
        pts = mcspec.sample(kind, dim, k, sets=2, seed=7)
        assert pts.shape == (2, k, dim)
        text = "#\n".join("".join(" ".join(f17(v) for v in p) + "\n" for p in s) for s in pts)
        assert text == raw("sample", kind, "--dim", dim, "--k", k, "--sets", 2, "--seed", 7), kind


def test_a_kind_outside_its_dimensions_is_refused_by_name():
    for kind, dim in (("lloyd", 3), ("padded", 1), ("poisson-disk", 4), ("sobol-owen", 65)):
        with pytest.raises(mcspec.Error) as e:
            mcspec.sample(kind, dim, 8)
        assert e.value.name == "MCS_ERR_KIND"


def test_pcf_of_a_point_file_is_the_command_s_columns(cli, tmp_path):
    pts = mcspec.sample("random", 2, 100, sets=4, seed=3)
    f = tmp_path / "p.txt"
    f.write_text(points_text(pts))
    for rdf, extra in ((False, []), (True, ["--rdf"])):
        got = mcspec.pcf(pts, rdf=rdf, exact="random", bins=20)
        rows = cli("pcf", f, "--bins", 20, "--exact", "random", *extra)
        assert rows[0] == ["r", "pcf", "pcf_stderr", "exact"]
        assert len(rows) == 21
        for b, row in enumerate(rows[1:]):
            assert row == [c17(got.r[b]), c17(got.mean[b]), c17(got.stderr[b]),
                           c17(got.exact[b])], (rdf, b)
    assert np.isnan(mcspec.pcf(pts, bins=20).exact).all()


def test_pcf_of_a_pattern_has_the_command_s_exact_column(cli):
    pts = mcspec.sample("jittered", 2, 64, sets=5, seed=2)
    got = mcspec.pcf(pts, exact="jittered", radius=2, bins=16)
    rows = cli("pcf", "jittered", "--k", 64, "--sets", 5, "--seed", 2, "--radius", 2, "--bins", 16)
    for b, row in enumerate(rows[1:]):
        assert row == [c17(got.r[b]), c17(got.mean[b]), c17(got.stderr[b]), c17(got.exact[b])]
    assert not np.isnan(got.exact).any()


def test_a_refused_pcf_raises_before_adding_anything():
    pts = mcspec.sample("random", 2, 16, sets=2, seed=1)
    with pytest.raises(mcspec.Error) as e:  # the radius reaches past half the torus at K = 16
        mcspec.pcf(pts, radius=3)
    assert e.value.name == "MCS_ERR_K_RANGE"
    bad = mcspec.sample("random", 2, 100, sets=2, seed=1)
    bad[1, 5, 0] = np.nan
    before = bad.copy()
    with pytest.raises(mcspec.Error) as e:
        mcspec.pcf(bad)
    assert e.value.name == "MCS_ERR_POINT_RANGE" and "(1, 5, 0)" in str(e.value)
    assert np.array_equal(bad, before, equal_nan=True)
    with pytest.raises(mcspec.Error) as e:
        mcspec.pcf(bad[:1], bins=0)
    assert e.value.name == "MCS_ERR_N_RANGE"
    with pytest.raises(mcspec.Error) as e:
        mcspec.pcf(mcspec.sample("random", 3, 100, seed=1))
    assert e.value.name == "MCS_ERR_DOMAIN"


@pytest.mark.parametrize("dim,k", [(2, 64), (1, 32)])
def test_spectral_statistics_are_the_stats_rows(cli, tmp_path, dim, k):
    pts = mcspec.sample("jittered" if dim == 2 else "stratified", dim, k, sets=6, seed=5)
    f = tmp_path / "p.txt"
    f.write_text(points_text(pts))
    got = mcspec.spectral_stats(pts)
    rows = cli("stats", f)
    head = rows[0]
    seen = 0
    for row in rows[1:]:
        name = row[head.index("statistic")]
        if name in got:
            seen += 1
            assert [row[head.index("value")], row[head.index("stderr")]] == \
                [c17(got[name].mean), c17(got[name].stderr)], name
    assert seen == 4


def test_the_metric_functions_refuse_bad_arrays():
    with pytest.raises(mcspec.Error) as e:
        mcspec.effective_nyquist([0.0, np.nan, 1.0], 16)
    assert e.value.name == "MCS_ERR_NOT_FINITE"
    with pytest.raises(mcspec.Error) as e:
        mcspec.oscillations([1.0], 16)
    assert e.value.name == "MCS_ERR_DOMAIN"


@pytest.mark.parametrize("dim,exact", [(2, "random"), (2, "jittered"), (1, None)])
def test_integration_error_is_the_command_s_rows_for_point_files(cli, tmp_path, dim, exact):
    kind = {(2, "random"): "random", (2, "jittered"): "jittered", (1, None): "stratified"}
    pts = mcspec.sample(kind[(dim, exact)], dim, 16, sets=6, seed=11)
    more = mcspec.sample(kind[(dim, exact)], dim, 9, sets=3, seed=12)
    f, g = tmp_path / "a.txt", tmp_path / "b.txt"
    f.write_text(points_text(pts))
    g.write_text(points_text(more))
    got = mcspec.integration_error([s for s in pts] + [s for s in more], integrands=4, seed=3,
                                   exact=exact)
    rows = cli("integrate", f, g, "--integrands", 4, "--seed", 3,
               *(["--exact", exact] if exact else []))
    head = rows[0]
    assert head[:6] == ["family", "k", "mse", "mse_stderr", "exact", "predicted"]
    n = 0
    for row in rows[1:]:
        fam, k = row[0], int(row[1])
        cols = got[fam]
        i = list(cols["k"]).index(k)
        for c in head[2:]:
            assert row[head.index(c)] == c17(cols[c][i]), (fam, k, c)
        n += 1
    assert n == 2 * (7 if dim == 2 else 6)  # blinn_phong is 2D only
    assert not np.isnan(got["cosine"]["predicted"]).any()


def test_a_refused_integration_error_raises():
    pts = mcspec.sample("random", 2, 16, sets=2, seed=1)
    with pytest.raises(mcspec.Error) as e:
        mcspec.integration_error(pts, family="nope")
    assert e.value.name == "MCS_ERR_KIND"
    pts[0, 0, 1] = 1.0
    with pytest.raises(mcspec.Error) as e:
        mcspec.integration_error(pts)
    assert e.value.name == "MCS_ERR_POINT_RANGE"


def test_projections_are_the_command_s_rows(cli, tmp_path):
    pts = mcspec.sample("halton-owen", 4, 64, sets=5, seed=4)
    f = tmp_path / "p.txt"
    f.write_text(points_text(pts))
    got = mcspec.projections(pts, freq=6)
    rows = cli("projections", f, "--freq", 6)
    head = rows[0]
    assert tuple(head) == mcspec.analysis.PROJECTION_COLUMNS
    assert len(rows) == 1 + 6
    for p, row in enumerate(rows[1:]):
        for c in head:
            v = got[c][p]
            want = str(v) if c in ("dim_i", "dim_j", "flagged") else c17(v)
            assert row[head.index(c)] == want, (p, c)


def test_the_kind_form_of_projections_is_sample_then_projections(cli):
    got = mcspec.projections(mcspec.sample("padded", 3, 32, sets=4, seed=2))
    rows = cli("projections", "padded", "--dim", 3, "--k", 32, "--sets", 4, "--seed", 2)
    head = rows[0]
    assert [row[head.index("radial_low")] for row in rows[1:]] == [c17(v) for v in
                                                                   got["radial_low"]]


def test_a_refused_projection_raises():
    with pytest.raises(mcspec.Error) as e:
        mcspec.projections(mcspec.sample("random", 2, 8), freq=0)
    assert e.value.name == "MCS_ERR_FREQ_RANGE"
    with pytest.raises(mcspec.Error) as e:
        mcspec.projections(mcspec.sample("random", 1, 8))
    assert e.value.name == "MCS_ERR_DOMAIN"


def test_a_saturated_poisson_set_raises_empty_as_the_command_exits_2(raw):
    with pytest.raises(subprocess.CalledProcessError) as c:
        raw("sample", "dart-throwing", "--dim", 3, "--k", 4, "--sets", 50)
    assert c.value.returncode == 2
    with pytest.raises(mcspec.Error) as e:
        mcspec.sample("dart-throwing", 3, 4, sets=50)
    assert e.value.name == "MCS_ERR_EMPTY" and "fewer points" in str(e.value)


def test_pcf_exact_random_is_the_random_pattern_s_column(cli):
    pts = mcspec.sample("random", 2, 100, sets=3, seed=6)
    got = mcspec.pcf(pts, exact="random", bins=10)
    rows = cli("pcf", "random", "--k", 100, "--sets", 3, "--seed", 6, "--bins", 10)
    assert [row[1:] for row in rows[1:]] == [[c17(got.mean[b]), c17(got.stderr[b]),
                                              c17(got.exact[b])] for b in range(10)]


def test_the_sampler_and_blue_noise_options_reproduce_the_defaults_and_refuse_bad_values():
    k, d = 32, 4
    assert np.array_equal(mcspec.sample("padded", d, k, sets=2, seed=3, pad="sobol-owen"),
                          mcspec.sample("padded", d, k, sets=2, seed=3))
    assert not np.array_equal(mcspec.sample("padded", d, k, sets=2, seed=3, pad="halton"),
                              mcspec.sample("padded", d, k, sets=2, seed=3))
    g = mcspec.lattice_generator(k, d)
    assert 1 <= g < k
    assert np.array_equal(mcspec.sample("lattice", d, k, sets=2, seed=3, generator=g),
                          mcspec.sample("lattice", d, k, sets=2, seed=3))
    assert np.array_equal(mcspec.base_points("lattice", d, k, generator=g),
                          mcspec.base_points("lattice", d, k))
    assert np.array_equal(mcspec.sample("dart-throwing", 2, 16, seed=2, params={"radius": 0.75}),
                          mcspec.sample("dart-throwing", 2, 16, seed=2))
    for kw, name in ((dict(kind="padded", pad="lattice"), "MCS_ERR_KIND"),
                     (dict(kind="lattice", generator=0), "MCS_ERR_MISMATCH"),
                     (dict(kind="lattice", generator=k), "MCS_ERR_MISMATCH"),
                     (dict(kind="halton-owen", generator=3), "MCS_ERR_KIND"),
                     (dict(kind="poisson-disk", params={"radius": 2.0}), "MCS_ERR_DOMAIN"),
                     (dict(kind="poisson-disk", params={"radius": np.nan}), "MCS_ERR_NOT_FINITE"),
                     (dict(kind="lloyd", params={"candidates": 3}), "MCS_ERR_DOMAIN"),
                     (dict(kind="pmj02", params={"bogus": 1}), "MCS_ERR_DOMAIN")):
        kind = kw.pop("kind")
        with pytest.raises(mcspec.Error) as e:
            mcspec.sample(kind, 2, 16, **kw)
        assert e.value.name == name, (kind, kw)


def test_pair_correlation_accumulators_merge_to_the_one_of_all_sets():
    pts = mcspec.sample("n-rooks", 2, 100, sets=6, seed=8)
    whole = mcspec.PairCorrelation(2, bins=12, rdf=True).add(pts)
    a = mcspec.PairCorrelation(2, bins=12, rdf=True).add(pts[:3])
    b = mcspec.PairCorrelation(2, bins=12, rdf=True).add([s for s in pts[3:]])
    a.merge(b)
    assert a.count == whole.count == 6
    assert np.allclose(a.mean, whole.mean, rtol=1e-14, atol=1e-14)
    assert np.allclose(a.stderr, whole.stderr, rtol=1e-12)
    assert np.array_equal(a.r, whole.r)
    before = (a.count, a.mean.tobytes(), a._mem.bytes(), a._acc.bytes())
    bad = pts.copy()
    bad[4, 0, 1] = -0.5
    with pytest.raises(mcspec.Error) as e:
        a.add(bad)
    assert e.value.name == "MCS_ERR_POINT_RANGE"
    with pytest.raises(mcspec.Error) as e:
        a.merge(mcspec.PairCorrelation(2, bins=13, rdf=True))
    assert e.value.name == "MCS_ERR_MISMATCH"
    small = [pts[0], pts[1][:10]]  # the second set is too small for the radius: neither is added
    with pytest.raises(mcspec.Error) as e:
        a.add(small)
    assert e.value.name == "MCS_ERR_K_RANGE"
    assert before == (a.count, a.mean.tobytes(), a._mem.bytes(), a._acc.bytes())
    assert np.isnan(a.exact("multi-jittered", 100)).all()
    assert not np.isnan(a.exact("n-rooks", 100)).any()


@pytest.mark.parametrize("kind,dim", [("jittered", 2), ("halton", 2), ("stratified", 1)])
def test_integration_error_of_a_kind_is_the_command_s_kind_form(cli, kind, dim):
    got = mcspec.integration_error_of(kind, [9, 16, 25], dim=dim, sets=4, integrands=3, seed=2)
    rows = cli("integrate", kind, "--k", 9, "--k", 16, "--k", 25, "--dim", dim, "--sets", 4,
               "--integrands", 3,
               "--seed", 2)
    head = rows[0]
    assert len(rows) == 1 + 3 * (7 if dim == 2 else 6)  # blinn_phong is 2D only
    for row in rows[1:]:
        cols = got[row[0]]
        i = list(cols["k"]).index(int(row[1]))
        for c in head[2:]:
            assert row[head.index(c)] == c17(cols[c][i]), (kind, row[0], row[1], c)
    if kind != "halton":
        assert not np.isnan(got["gaussian"]["exact"]).any()
    with pytest.raises(mcspec.Error) as e:
        mcspec.integration_error_of(kind, [9, 0], dim=dim)
    assert e.value.name == "MCS_ERR_K_RANGE"
