"""Discrepancies (discrepancy.h) and spacing statistics (spacing.h) of
point sets, per set, as arrays."""
import ctypes

import numpy as np

from ._lib import Buffer, check, fn
from ._points import call_points, each_set, sets_array

L2_MEASURES = ("l2_star", "l2_centered", "l2_wraparound", "l2_symmetric", "l2_generalized",
               "l2_unanchored")
SPACING = ("min_distance", "avg_min_distance")


class Work:
    """The scratch of the per-set calls (star discrepancy, spacing): one
    Buffer, replaced by a larger one when a set needs more, and held here
    while a call uses it (so no address of a temporary reaches the library)."""

    def __init__(self):
        self.buf = Buffer(1)

    def at_least(self, need):
        if need > self.buf.size:
            self.buf = Buffer(need)
        return self.buf


def star_work(work, k, what="mcs_discrepancy_star_work_size"):
    """work's Buffer grown to mcs_discrepancy_star_work_size(k)."""
    need = ctypes.c_size_t()
    check(fn.discrepancy_star_work_size(k, ctypes.addressof(need)), what)
    return work.at_least(need.value)


def spacing_work(work, dim, k, what=None):
    """work's Buffer grown to mcs_spacing_work_size(dim, k) (at least 1 byte)."""
    need = ctypes.c_size_t()
    check(fn.spacing_work_size(dim, k, ctypes.addressof(need)),
          what or "mcs_spacing_work_size(K = %d)" % k)
    return work.at_least(need.value)


def discrepancy(sets, star=False):
    """The six squared L2 discrepancies of each set as a dict of arrays [T]
    (mcs_discrepancy_l2, names as `mcspec discrepancy --csv`), and with
    star=True (2D, K <= 4096) the exact star discrepancy D* (not squared)
    under "star". One library call per set."""
    parts, d = sets_array(sets)
    rows, stars = [], []
    d2 = np.empty(6)
    work = Work()
    for k, one, f32, part in each_set(parts):
        call_points((fn.discrepancy_l2_f if f32 else fn.discrepancy_l2)(k, d, one.ctypes.data,
                                                                       d2.ctypes.data),
                    part, "mcs_discrepancy_l2")
        rows.append(d2.copy())
        if star:
            buf = star_work(work, k, "star_work_size")
            v = ctypes.c_double()
            call_points((fn.discrepancy_star_f if f32 else fn.discrepancy_star)(
                k, one.ctypes.data, buf.addr, buf.size, ctypes.addressof(v)),
                part, "mcs_discrepancy_star")
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
    work = Work()
    for k, one, f32, part in each_set(parts):
        buf = spacing_work(work, d, k, "mcs_spacing_work_size")
        f = fn.spacing_distances_f if f32 else fn.spacing_distances
        call_points(f(k, d, one.ctypes.data, buf.addr, buf.size, two.ctypes.data), part,
                    "mcs_spacing_distances")
        res.append(two.copy())
    m = np.array(res)
    return {SPACING[0]: m[:, 0].copy(), SPACING[1]: m[:, 1].copy()}
