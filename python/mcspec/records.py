"""Records (io.h, docs/format.md): save and load as bytes or files, merge."""
import ctypes

import numpy as np

from . import _lib
from ._lib import Buffer, Error, check, fn, struct

_KINDS = {1: "spectrum", 2: "moment", 3: "autocorr", 5: "pointset", 6: "pointset2d", 8: "pcf",
          9: "integrate", 10: "discrepancy", 11: "spacing"}


def _kind_of(obj):
    from .binned import Spectrum, Moment, Autocorr
    from .pointsets import PointSet
    from .analysis import PairCorrelation
    if isinstance(obj, PointSet):
        return obj._p, obj._hdr
    if isinstance(obj, PairCorrelation):
        return "pcf", obj._acc
    from .accumulators import RECORD_CLASSES
    for name, cls in RECORD_CLASSES.items():
        if isinstance(obj, cls):
            return name, obj._acc
    for cls, name in ((Spectrum, "spectrum"), (Moment, "moment"), (Autocorr, "autocorr")):
        if isinstance(obj, cls):
            return name, obj._obj
    raise Error(_lib.ERR_KIND, "no record kind for %r" % (type(obj).__name__,))


def save(obj):
    """The record of obj as bytes (mcs_io_save_*)."""
    name, o = _kind_of(obj)
    f = getattr(fn, "io_save_" + name)
    size = ctypes.c_size_t()
    check(f(o.addr, 0, None, ctypes.addressof(size)), "mcs_io_save_" + name)
    buf = Buffer(size.value)
    check(f(o.addr, buf.size, buf.addr, ctypes.addressof(size)), "mcs_io_save_" + name)
    return buf.array[:size.value].tobytes()


def _first_size(buf):
    """The first member of a loaded object, a size_t (N, or F for a point
    set) by the public headers: C puts a struct's first member at offset 0,
    the one place of a layout this package reads."""
    return ctypes.cast(buf.addr, ctypes.POINTER(ctypes.c_size_t))[0]


def _load_pcf(raw):
    """A PairCorrelation from a pcf record (kind 8), or None for another
    kind. Its settings are the record's shape words (docs/format.md: dim,
    estimator, B, radius and sigma as binary64 bits, from byte 32), read once
    the library has loaded the record, so they are checked."""
    from .analysis import PairCorrelation
    size = ctypes.c_size_t()
    st = fn.io_load_size(raw.size, raw.ctypes.data, 0, ctypes.addressof(size))
    if st != 0:
        check(st, "mcs_io_load_size")
    acc, mem = struct("pcf"), Buffer(max(size.value, 1))
    st = fn.io_load_pcf(acc.addr, mem.addr, mem.size, raw.size, raw.ctypes.data)
    if st == _lib.ERR_KIND:
        return None
    check(st, "mcs_io_load_pcf")
    words = raw[32:72].view("<u8")
    obj = PairCorrelation.__new__(PairCorrelation)
    obj._acc, obj._mem, obj._work = acc, mem, Buffer(1)
    obj.dim, obj.rdf, obj.bins = int(words[0]), int(words[1]) == 0, int(words[2])
    obj.radius, obj.sigma = (float(v) for v in words[3:5].view("<f8"))
    return obj


def load(data):
    """The object saved in data (bytes): a Spectrum, Moment, Autocorr,
    PointSet, PairCorrelation, IntegrationError, Discrepancy or Spacing
    (mcs_io_load_*); MCS_ERR_* on a damaged or foreign record."""
    from .binned import Spectrum, Moment, Autocorr
    from .pointsets import PointSet
    from .accumulators import load_record
    raw = np.frombuffer(bytes(data), dtype=np.uint8)
    pcf = _load_pcf(raw)
    if pcf is not None:
        return pcf
    acc = load_record(raw)
    if acc is not None:
        return acc
    # The kind by the loaders themselves: each refuses another kind with
    # MCS_ERR_KIND before it writes anything.
    for name in ("spectrum", "moment", "autocorr", "pointset", "pointset2d"):
        if name.startswith("pointset"):
            size = ctypes.c_size_t()
            st = fn.io_load_size(raw.size, raw.ctypes.data, 0, ctypes.addressof(size))
            if st != 0:
                check(st, "mcs_io_load_size")
            hdr, mem = struct(name), Buffer(max(size.value, 1))
            st = getattr(fn, "io_load_" + name)(hdr.addr, 0, mem.addr, mem.size, raw.size,
                                                raw.ctypes.data)
            if st == 0:
                return PointSet(_first_size(hdr), 1 if name == "pointset" else 2, _header=hdr,
                                _mem=mem)
        else:
            cls = {"spectrum": Spectrum, "moment": Moment, "autocorr": Autocorr}[name]
            obj = cls.__new__(cls)
            obj._obj = struct(name)
            st = getattr(fn, "io_load_" + name)(obj._obj.addr, raw.size, raw.ctypes.data)
            if st == 0:
                obj.n = _first_size(obj._obj)
                return obj
        if st != _lib.ERR_KIND:
            check(st, "mcs_io_load_" + name)
    raise Error(_lib.ERR_KIND, "a record of a kind this package does not wrap (welford, "
                "spectrum2d)")


def save_file(obj, path):
    """Writes obj's record to path (a temporary file beside it, then renamed)."""
    import os
    data = save(obj)
    tmp = "%s.part%d" % (path, os.getpid())
    with open(tmp, "wb") as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def load_file(path):
    with open(path, "rb") as f:
        return load(f.read())


def merge(*objs):
    """A new object: the union of objs (records as bytes, or objects)."""
    if not objs:
        raise Error(_lib.ERR_EMPTY, "nothing to merge")
    items = [load(o) if isinstance(o, (bytes, bytearray)) else o for o in objs]
    out = items[0].copy() if hasattr(items[0], "copy") else load(save(items[0]))
    for o in items[1:]:
        out.merge(o)
    return out
