"""The one-shot measure functions and the accumulator objects give the same
numbers bit for bit: discrepancy() and spacing() per set against an object
that holds that set alone (the mean of one value is the value), the star as
the square the object keeps, and integration_error() of one K against an
IntegrationError fed the same sets (the same integrand stream)."""
import numpy as np
import pytest

import mcspec

CASES = [("random", 2, 64, np.float64), ("jittered", 2, 100, np.float32),
         ("random", 1, 33, np.float64), ("sobol-owen", 3, 50, np.float32)]


def same(a, b):
    return np.asarray(a, dtype=np.float64).tobytes() == np.asarray(b, dtype=np.float64).tobytes()


@pytest.mark.parametrize("kind,dim,k,dtype", CASES)
def test_discrepancy_of_each_set_is_the_mean_of_an_object_holding_that_set(kind, dim, k, dtype):
    pts = mcspec.sample(kind, dim, k, sets=4, seed=7).astype(dtype)
    one = mcspec.discrepancy(pts, star=dim == 2)
    for name in mcspec.measures.L2_MEASURES + (("star",) if dim == 2 else ()):
        col = []
        for s in pts:
            mean = mcspec.Discrepancy(dim, star=True).add([s]).mean[name]
            col.append(mean)
        want = one[name] * one[name] if name == "star" else one[name]
        assert same(col, want), name


@pytest.mark.parametrize("kind,dim,k,dtype", CASES)
def test_spacing_of_each_set_is_the_mean_of_an_object_holding_that_set(kind, dim, k, dtype):
    pts = mcspec.sample(kind, dim, k, sets=4, seed=8).astype(dtype)
    one = mcspec.spacing(pts)
    for name in mcspec.measures.SPACING:
        col = [mcspec.Spacing(dim).add([s]).mean[name] for s in pts]
        assert same(col, one[name]), name


@pytest.mark.parametrize("kind,dim,k,exact", [("random", 2, 64, "random"),
                                              ("jittered", 2, 36, "jittered"),
                                              ("stratified", 1, 20, "jittered"),
                                              ("sobol-owen", 2, 32, None)])
def test_integration_error_of_one_k_is_the_objects_of_its_families(kind, dim, k, exact):
    pts = mcspec.sample(kind, dim, k, sets=5, seed=3, stream=1)
    one = mcspec.integration_error(pts, integrands=4, seed=9, exact=exact)
    assert one
    for family, cols in one.items():
        acc = mcspec.IntegrationError(family, dim, integrands=4, seed=9, exact=exact).add(pts)
        assert same(cols["mse"], [acc.mse]) and same(cols["mse_stderr"], [acc.mse_stderr])
        assert same(cols["exact"], [acc.exact]) and cols["sets"][0] == acc.count == 5


def test_integration_error_of_mixed_k_keeps_one_stream_per_family():
    sets = [mcspec.sample("random", 2, k, sets=1, seed=k)[0] for k in (16, 40, 16, 40)]
    one = mcspec.integration_error(sets, integrands=3, seed=2, family="cosine")["cosine"]
    acc = mcspec.IntegrationError("cosine", 2, integrands=3, seed=2)
    by_k = {16: acc.copy(), 40: acc.copy()}
    for s in sets:  # the sets in order, each on the one stream the family has
        target = by_k[s.shape[0]]
        target._rng = acc._rng
        target.add([s])
    assert same(one["mse"], [by_k[16].mse, by_k[40].mse])
    assert same(one["mse_stderr"], [by_k[16].mse_stderr, by_k[40].mse_stderr])
