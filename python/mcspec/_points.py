"""Point arrays in: numpy conventions, checked before the library sees them."""
import numpy as np

from ._lib import Error, ERR_K_RANGE, ERR_NULL, ERR_POINT_RANGE, ERR_MISMATCH, check


def _as_points(a, what):
    """a as a C-contiguous float64 or float32 array (float32 is kept, and
    read by the library's _f calls, which widen each coordinate exactly;
    other dtypes are refused, not converted). A non-contiguous array is
    copied (the only copy made)."""
    if a is None:
        raise Error(ERR_NULL, "%s is None" % what)
    arr = np.asarray(a)
    if arr.dtype not in (np.float64, np.float32):
        if arr.dtype.kind in "iub" or arr.dtype.kind == "f" and arr.dtype.itemsize < 4:
            raise Error(ERR_POINT_RANGE, "%s has dtype %s: give float64 or float32 points in "
                        "[0, 1) (convert with .astype(numpy.float64))" % (what, arr.dtype))
        raise Error(ERR_POINT_RANGE, "%s has dtype %s: give float64 or float32 points in [0, 1)"
                    % (what, arr.dtype))
    return np.ascontiguousarray(arr)


def sets_array(sets, dim=None):
    """sets as a list of (T_i, K_i, d) arrays ready for the library (one
    array when every set has the same K), and d. sets: an array (T, K, d) or
    (K, d) (one set), (T, K) for 1D, or a list of (K, d) arrays."""
    if isinstance(sets, (list, tuple)):
        if len(sets) == 0:
            raise Error(ERR_K_RANGE, "no sets given")
        parts = [_as_points(s, "set %d" % i) for i, s in enumerate(sets)]
        parts = [p.reshape(p.shape[0], 1) if p.ndim == 1 and (dim == 1) else p for p in parts]
        for i, p in enumerate(parts):
            if p.ndim != 2:
                raise Error(ERR_MISMATCH, "set %d has shape %s: each set is (K, d)" % (i, p.shape))
        shapes = {p.shape for p in parts}
        dtypes = {p.dtype for p in parts}
        if len(shapes) == 1 and len(dtypes) == 1:
            parts = [np.ascontiguousarray(np.stack(parts))]
        else:
            parts = [p[np.newaxis] for p in parts]
    else:
        arr = _as_points(sets, "sets")
        if arr.ndim == 2 and dim == 1:
            arr = arr[:, :, np.newaxis]
        elif arr.ndim == 2:
            arr = arr[np.newaxis]
        elif arr.ndim == 1 and dim in (None, 1):
            arr = arr[np.newaxis, :, np.newaxis]
        if arr.ndim != 3:
            raise Error(ERR_MISMATCH, "sets has shape %s: give (T, K, d), (K, d) or a list of "
                        "(K, d) arrays" % (arr.shape,))
        parts = [arr]
    d = parts[0].shape[2]
    for p in parts:
        if p.shape[2] != d or (dim is not None and d != dim):
            raise Error(ERR_MISMATCH, "points of %d coordinates where %s are wanted"
                        % (p.shape[2], dim if dim is not None else d))
        if p.shape[1] == 0 or p.shape[0] == 0:
            raise Error(ERR_K_RANGE, "an empty set (K = 0)")
    return parts, d


def where_bad(arr, wrap=False):
    """The message for a point outside [0, 1) (or NaN) in arr, to go with
    the library's MCS_ERR_POINT_RANGE; computed only after a refusal."""
    top = 1.0 if wrap else np.nextafter(1.0, 0.0)
    a = np.asarray(arr, dtype=np.float64)
    bad = ~((a >= 0.0) & (a <= top))
    if not bad.any():
        return "a point is outside [0, 1)"
    idx = np.unravel_index(int(np.argmax(bad)), a.shape)
    return "point %s = %r is outside [0, 1) (or NaN)" % (tuple(int(i) for i in idx), float(a[idx]))


def call_points(st, arr, what):
    """Raises for a library status st of a call that read the points arr:
    for MCS_ERR_POINT_RANGE the message names the bad point, else check()'s."""
    if st == ERR_POINT_RANGE:
        raise Error(st, where_bad(arr))
    check(st, what)


def each_set(parts):
    """(k, set array, float32?, its part) of every set of sets_array's parts,
    in order (views, no copy); the part is for call_points' message, which
    then names the point by its index in the part (set, point, coordinate)."""
    for arr in parts:
        for t in range(arr.shape[0]):
            yield arr.shape[1], arr[t], arr.dtype == np.float32, arr
