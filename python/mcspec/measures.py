"""Discrepancies (discrepancy.h) and spacing statistics (spacing.h) of
point sets, per set, as arrays."""
import ctypes

import numpy as np

from . import _lib
from ._lib import Buffer, Error, check, fn
from ._points import sets_array, where_bad

L2_MEASURES = ("l2_star", "l2_centered", "l2_wraparound", "l2_symmetric", "l2_generalized",
               "l2_unanchored")
SPACING = ("min_distance", "avg_min_distance")


def _call(st, arr, what):
    if st == _lib.ERR_POINT_RANGE:
        raise Error(st, where_bad(arr))
    check(st, what)


def discrepancy(sets, star=False):
    """The six squared L2 discrepancies of each set as a dict of arrays [T]
    (mcs_discrepancy_l2, names as `mcspec discrepancy --csv`), and with
    star=True (2D, K <= 4096) the exact star discrepancy D* (not squared)
    under "star". One library call per set."""
    parts, d = sets_array(sets)
    rows, stars = [], []
    d2 = np.empty(6)
    for arr in parts:
        f32 = arr.dtype == np.float32
        for t in range(arr.shape[0]):
            k = arr.shape[1]
            _call((fn.discrepancy_l2_f if f32 else fn.discrepancy_l2)(k, d, arr[t].ctypes.data,
                                                                     d2.ctypes.data),
                  arr, "mcs_discrepancy_l2")
            rows.append(d2.copy())
            if star:
                size = ctypes.c_size_t()
                check(fn.discrepancy_star_work_size(k, ctypes.addressof(size)), "star_work_size")
                work = Buffer(size.value)
                v = ctypes.c_double()
                _call((fn.discrepancy_star_f if f32 else fn.discrepancy_star)(
                    k, arr[t].ctypes.data, work.addr, work.size, ctypes.addressof(v)),
                    arr, "mcs_discrepancy_star")
                stars.append(v.value)
    m = np.array(rows)
    out = {name: m[:, i].copy() for i, name in enumerate(L2_MEASURES)}
    if star:
        out["star"] = np.array(stars)
    return out


def discrepancy_exact_random(measure, k, dim):
    """E[D^2] of an L2 measure for k independent uniform points in dim."""
    v = ctypes.c_double()
    check(fn.discrepancy_l2_exact_random(L2_MEASURES.index(measure), int(k), int(dim),
                                         ctypes.addressof(v)), "l2_exact_random")
    return v.value


def discrepancy_exact_jittered(measure, strata, dim=None):
    """E[D^2] of an L2 measure over a jittered grid, one uniform point per
    cell: strata an int n with dim (n^dim cells; dim 1, n = K: the 1D
    stratified pattern), or a pair (nx, ny) for a 2D grid of nx columns by ny
    rows (mcs_discrepancy_l2_exact_jittered, _jittered2d)."""
    v = ctypes.c_double()
    m = L2_MEASURES.index(measure)
    if isinstance(strata, (tuple, list)):
        if dim not in (None, 2) or len(strata) != 2:
            raise ValueError("strata (nx, ny) is a 2D grid")
        check(fn.discrepancy_l2_exact_jittered2d(m, int(strata[0]), int(strata[1]),
                                                 ctypes.addressof(v)), "l2_exact_jittered2d")
    else:
        if dim is None:
            raise ValueError("give dim with an int strata")
        check(fn.discrepancy_l2_exact_jittered(m, int(strata), int(dim), ctypes.addressof(v)),
              "l2_exact_jittered")
    return v.value


def spacing_exact_random(statistic, dim, k):
    """The exact expectation of a spacing statistic (over d_max, as spacing()
    gives it) for k independent uniform points in dim dimensions
    (mcs_spacing_exact_random): avg_min_distance in 1D, 2D and, from k = 52,
    104, 212, 450, 1007, 2370, in 3D to 8D; min_distance in 1D; Error
    MCS_ERR_DOMAIN elsewhere."""
    v = ctypes.c_double()
    check(fn.spacing_exact_random(SPACING.index(statistic), int(dim), int(k),
                                  ctypes.addressof(v)), "mcs_spacing_exact_random")
    return v.value


def spacing(sets):
    """The minimum and average minimum toroidal distances of each set as a
    dict of arrays [T] (mcs_spacing_distances). One library call per set."""
    parts, d = sets_array(sets)
    res = []
    two = np.empty(2)
    for arr in parts:
        k = arr.shape[1]
        size = ctypes.c_size_t()
        check(fn.spacing_work_size(d, k, ctypes.addressof(size)), "mcs_spacing_work_size")
        work = Buffer(max(size.value, 1))
        f = fn.spacing_distances_f if arr.dtype == np.float32 else fn.spacing_distances
        for t in range(arr.shape[0]):
            _call(f(k, d, arr[t].ctypes.data, work.addr, size.value, two.ctypes.data), arr,
                  "mcs_spacing_distances")
            res.append(two.copy())
    m = np.array(res)
    return {SPACING[0]: m[:, 0].copy(), SPACING[1]: m[:, 1].copy()}
