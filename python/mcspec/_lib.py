"""The shared library, its prototypes, its statuses as exceptions, and the
opaque, 64-byte aligned buffers that hold its objects.

The library is found, in this order (the first that loads wins):
  1. the file named by the environment variable MCSPEC_LIBRARY;
  2. libmcspec.so* next to this package (a copy installed with it);
  3. the lib directory of the prefix the package is installed under
     (PREFIX/lib/libmcspec.so.0 for PREFIX/lib/python3/dist-packages/mcspec);
  4. the source tree's build/libmcspec.so (the package run from python/);
  5. the system loader (ctypes.CDLL("libmcspec.so.0"), LD_LIBRARY_PATH, ldconfig).
mcspec.library_path says which file was loaded and library_source how it
was found.
"""
import ctypes
import os

import numpy as np

_here = os.path.dirname(os.path.abspath(__file__))


def _candidates():
    env = os.environ.get("MCSPEC_LIBRARY")
    if env:
        yield env, "MCSPEC_LIBRARY"
    for name in ("libmcspec.so", "libmcspec.so.0"):
        yield os.path.join(_here, name), "next to the package"
    # PREFIX/lib/python3/dist-packages/mcspec or PREFIX/lib/python3.X/site-packages/mcspec
    lib = os.path.dirname(os.path.dirname(os.path.dirname(_here)))
    for name in ("libmcspec.so.0", "libmcspec.so"):
        yield os.path.join(lib, name), "the installation prefix's lib"
    yield os.path.join(os.path.dirname(os.path.dirname(_here)), "build", "libmcspec.so"), \
        "the source tree's build"
    yield "libmcspec.so.0", "the system loader"


def _resolved(handle, fallback):
    """The file the loader mapped for handle (from /proc/self/maps)."""
    try:
        with open("/proc/self/maps") as maps:
            for line in maps:
                path = line.split()[-1]
                if "libmcspec.so" in os.path.basename(path) and os.path.exists(path):
                    return os.path.realpath(path)
    except OSError:
        pass
    return fallback


def _load():
    errors = []
    for path, source in _candidates():
        if os.sep in path and not os.path.exists(path):
            continue
        try:
            handle = ctypes.CDLL(path)
        except OSError as e:
            errors.append("%s (%s): %s" % (path, source, e))
            continue
        return handle, _resolved(handle, path), source
    raise ImportError("mcspec: cannot load libmcspec.so: set MCSPEC_LIBRARY to its path, or "
                      "install it (make install) into the prefix of this package; tried: "
                      + "; ".join(errors or ["nothing found"]))


lib, library_path, library_source = _load()

_P = ctypes.c_void_p
_Z = ctypes.c_size_t
_D = ctypes.c_double
_I = ctypes.c_int
_U = ctypes.c_uint
_U32 = ctypes.c_uint32
_U64 = ctypes.c_uint64
_L = ctypes.c_long
_S = ctypes.c_char_p

# name: (restype, argtypes). Every pointer is passed as an address (int).
_PROTOS = {
    "mcs_version": (_S, []),
    "mcs_status_str": (_S, [_I]),
    "mcs_abi_sizeof": (_I, [_I, _P, _P]),
    "mcs_rng_seed": (_I, [_P, _U64, _U64]),
    "mcs_importance_init": (_I, [_P, _Z, _P]),
    "mcs_pattern_kind_str": (_S, [_I]),
    "mcs_pattern_init": (_I, [_P, _I, _Z, _Z, _P]),
    "mcs_pattern_draw": (_I, [_P, _P, _Z, _P, _P, _P]),
    "mcs_pattern_bin_points": (_I, [_Z, _Z, _P, _P, _P, _P]),
    "mcs_pattern2d_kind_str": (_S, [_I]),
    "mcs_pattern2d_init": (_I, [_P, _I, _Z, _Z, _Z]),
    "mcs_pattern2d_draw": (_I, [_P, _P, _Z, _P]),
    "mcs_sampler_kind_str": (_S, [_I]),
    "mcs_sampler_has_dim": (_I, [_I, _Z]),
    "mcs_sampler_init": (_I, [_P, _I, _Z, _Z]),
    "mcs_sampler_draw": (_I, [_P, _P, _Z, _P]),
    "mcs_sampler_base_points": (_I, [_P, _Z, _P]),
    "mcs_dft_init": (_I, [_P, _Z]),
    "mcs_pointset_size": (_I, [_Z, _U, _P]),
    "mcs_pointset_init": (_I, [_P, _Z, _U, _P, _Z]),
    "mcs_pointset_copy": (_I, [_P, _P, _Z, _P]),
    "mcs_pointset_set_wrap": (_I, [_P, _I]),
    "mcs_pointset_add_sets": (_I, [_P, _Z, _Z, _P]),
    "mcs_pointset_add_sets_f": (_I, [_P, _Z, _Z, _P]),
    "mcs_pointset_merge": (_I, [_P, _P]),
    "mcs_pointset_count": (_I, [_P, _P]),
    "mcs_pointset_read_all": (_I, [_P, _Z, _P, _P]),
    "mcs_pointset_exact_power": (_I, [_I, _Z, _L, _P]),
    "mcs_pointset2d_size": (_I, [_Z, _U, _P]),
    "mcs_pointset2d_init": (_I, [_P, _Z, _U, _P, _Z]),
    "mcs_pointset2d_copy": (_I, [_P, _P, _Z, _P]),
    "mcs_pointset2d_set_wrap": (_I, [_P, _I]),
    "mcs_pointset2d_add_sets": (_I, [_P, _Z, _Z, _P]),
    "mcs_pointset2d_add_sets_f": (_I, [_P, _Z, _Z, _P]),
    "mcs_pointset2d_merge": (_I, [_P, _P]),
    "mcs_pointset2d_count": (_I, [_P, _P]),
    "mcs_pointset2d_read_all": (_I, [_P, _Z, _P, _P]),
    "mcs_pointset2d_radial_all": (_I, [_P, _Z, _P, _P, _P]),
    "mcs_pointset2d_exact_power": (_I, [_P, _L, _L, _P]),
    "mcs_pointset2d_exact_radial": (_I, [_P, _Z, _P]),
    "mcs_discrepancy_measure_str": (_S, [_I]),
    "mcs_discrepancy_l2": (_I, [_Z, _Z, _P, _P]),
    "mcs_discrepancy_l2_f": (_I, [_Z, _Z, _P, _P]),
    "mcs_discrepancy_l2_exact_random": (_I, [_I, _Z, _Z, _P]),
    "mcs_discrepancy_l2_exact_jittered": (_I, [_I, _Z, _Z, _P]),
    "mcs_discrepancy_l2_exact_jittered2d": (_I, [_I, _Z, _Z, _P]),
    "mcs_discrepancy_star_work_size": (_I, [_Z, _P]),
    "mcs_discrepancy_star": (_I, [_Z, _P, _P, _Z, _P]),
    "mcs_discrepancy_star_f": (_I, [_Z, _P, _P, _Z, _P]),
    "mcs_spacing_statistic_str": (_S, [_I]),
    "mcs_spacing_work_size": (_I, [_Z, _Z, _P]),
    "mcs_spacing_distances": (_I, [_Z, _Z, _P, _P, _Z, _P]),
    "mcs_spacing_distances_f": (_I, [_Z, _Z, _P, _P, _Z, _P]),
    "mcs_spacing_packing_distance": (_I, [_Z, _Z, _P]),
    "mcs_spacing_exact_random": (_I, [_I, _Z, _Z, _P]),
    "mcs_spectrum_init": (_I, [_P, _Z]),
    "mcs_spectrum_set_batch": (_I, [_P, _U64]),
    "mcs_spectrum_add_bins": (_I, [_P, _Z, _P, _P]),
    "mcs_spectrum_add_dense": (_I, [_P, _Z, _P]),
    "mcs_spectrum_add_points": (_I, [_P, _Z, _P, _P]),
    "mcs_spectrum_add_points_f": (_I, [_P, _Z, _P, _P]),
    "mcs_spectrum_merge": (_I, [_P, _P]),
    "mcs_spectrum_count": (_I, [_P, _P]),
    "mcs_spectrum_units": (_I, [_P, _P]),
    "mcs_spectrum_read_all": (_I, [_P, _Z, _P, _P, _P, _P, _P]),
    "mcs_moment_init": (_I, [_P, _Z]),
    "mcs_moment_add_bins": (_I, [_P, _Z, _P, _P]),
    "mcs_moment_add_dense": (_I, [_P, _Z, _P]),
    "mcs_moment_merge": (_I, [_P, _P]),
    "mcs_moment_count": (_I, [_P, _P]),
    "mcs_moment_cross_matrix": (_I, [_P, _Z, _P, _P]),
    "mcs_moment_covariance_matrix": (_I, [_P, _Z, _P, _P]),
    "mcs_moment_estimator_mean": (_I, [_P, _Z, _Z, _P, _P]),
    "mcs_moment_variance": (_I, [_P, _Z, _Z, _P, _P]),
    "mcs_autocorr_init": (_I, [_P, _Z]),
    "mcs_autocorr_add_bins": (_I, [_P, _Z, _P, _P]),
    "mcs_autocorr_merge": (_I, [_P, _P]),
    "mcs_autocorr_count": (_I, [_P, _P]),
    "mcs_autocorr_mean": (_I, [_P, _P, _Z, _P, _P]),
    "mcs_autocorr_power": (_I, [_P, _P, _Z, _P]),
    "mcs_theory_init": (_I, [_P, _P]),
    "mcs_theory_cross_matrix": (_I, [_P, _Z, _P, _P]),
    "mcs_theory_covariance_matrix": (_I, [_P, _Z, _P, _P]),
    "mcs_theory_estimator_mean": (_I, [_P, _Z, _Z, _P, _P]),
    "mcs_theory_variance": (_I, [_P, _Z, _Z, _P, _P]),
    "mcs_theory_spectrum_init": (_I, [_P, _P]),
    "mcs_theory_spectrum_read_all": (_I, [_P, _Z, _P, _P, _P, _P]),
    "mcs_theory_spectrum_variance": (_I, [_P, _Z, _Z, _P, _P]),
    "mcs_io_peek": (_I, [_Z, _P, _P]),
    "mcs_io_kind_str": (_S, [_U32]),
    "mcs_io_load_size": (_I, [_Z, _P, _U, _P]),
    "mcs_io_save_spectrum": (_I, [_P, _Z, _P, _P]),
    "mcs_io_save_moment": (_I, [_P, _Z, _P, _P]),
    "mcs_io_save_autocorr": (_I, [_P, _Z, _P, _P]),
    "mcs_io_save_pointset": (_I, [_P, _Z, _P, _P]),
    "mcs_io_save_pointset2d": (_I, [_P, _Z, _P, _P]),
    "mcs_io_load_spectrum": (_I, [_P, _Z, _P]),
    "mcs_io_load_moment": (_I, [_P, _Z, _P]),
    "mcs_io_load_autocorr": (_I, [_P, _Z, _P]),
    "mcs_io_load_pointset": (_I, [_P, _U, _P, _Z, _Z, _P]),
    "mcs_io_load_pointset2d": (_I, [_P, _U, _P, _Z, _Z, _P]),
    "mcs_io_save_pcf": (_I, [_P, _Z, _P, _P]),
    "mcs_io_load_pcf": (_I, [_P, _P, _Z, _Z, _P]),
    # the modules wrapped by issue 27's second round
    "mcs_rng_double": (_I, [_P, _P]),
    "mcs_sampler_init_padded": (_I, [_P, _I, _Z, _Z]),
    "mcs_sampler_init_lattice": (_I, [_P, _Z, _Z, _U32]),
    "mcs_sampler_lattice_generator": (_U32, [_Z, _Z]),
    "mcs_bluenoise_kind_str": (_S, [_I]),
    "mcs_bluenoise_has_dim": (_I, [_I, _Z]),
    "mcs_bluenoise_work_size": (_I, [_I, _Z, _Z, _P]),
    "mcs_bluenoise_draw": (_I, [_I, _Z, _Z, _P, _P, _P, _Z, _P]),
    "mcs_welford_init": (_I, [_P]),
    "mcs_welford_add": (_I, [_P, _D]),
    "mcs_welford_mean": (_I, [_P, _P]),
    "mcs_welford_stderr": (_I, [_P, _P]),
    "mcs_pcf_size": (_I, [_Z, _P]),
    "mcs_pcf_init": (_I, [_P, _Z, _I, _Z, _D, _D, _P, _Z]),
    "mcs_pcf_work_size": (_I, [_P, _Z, _P]),
    "mcs_pcf_add": (_I, [_P, _Z, _P, _P, _Z]),
    "mcs_pcf_merge": (_I, [_P, _P]),
    "mcs_pcf_count": (_I, [_P, _P]),
    "mcs_pcf_radius_at": (_I, [_P, _Z, _P]),
    "mcs_pcf_mean": (_I, [_P, _Z, _P]),
    "mcs_pcf_stderr": (_I, [_P, _Z, _P]),
    "mcs_pcf_read_all": (_I, [_P, _Z, _P, _P, _P]),
    "mcs_pcf_power": (_I, [_P, _D, _P]),
    "mcs_pcf_exact": (_I, [_P, _P, _Z, _P]),
    "mcs_radial_effective_nyquist": (_I, [_Z, _Z, _Z, _P, _D, _P]),
    "mcs_radial_oscillations": (_I, [_Z, _Z, _Z, _P, _D, _P]),
    "mcs_integrand_family_str": (_S, [_I]),
    "mcs_integrand_is_periodic": (_I, [_I]),
    "mcs_integrand_has_dim": (_I, [_I, _Z]),
    "mcs_integrand_draw": (_I, [_P, _I, _Z, _P]),
    "mcs_integrand_predict": (_I, [_P, _Z, _P, _Z, _P, _P]),
    "mcs_integrand_predict_1d": (_I, [_P, _Z, _P, _Z, _P, _P]),
    "mcs_integrate_init": (_I, [_P, _I, _Z]),
    "mcs_integrate_add": (_I, [_P, _Z, _P, _Z, _P, _I, _Z, _Z]),
    "mcs_integrate_mse": (_I, [_P, _P]),
    "mcs_integrate_mse_stderr": (_I, [_P, _P]),
    "mcs_integrate_exact": (_I, [_P, _P]),
    "mcs_pointset_add": (_I, [_P, _Z, _P]),
    "mcs_pointset2d_add": (_I, [_P, _Z, _P]),
    "mcs_pointset_power": (_I, [_P, _L, _P]),
    "mcs_pointset2d_radial": (_I, [_P, _Z, _P]),
    "mcs_projections_size": (_I, [_Z, _Z, _Z, _P]),
    "mcs_projections_init": (_I, [_P, _Z, _Z, _Z, _Z, _Z, _P, _Z]),
    "mcs_projections_add": (_I, [_P, _Z, _P]),
    "mcs_projections_pair_stats": (_I, [_P, _Z, _Z, _P]),
    "mcs_projections_flagged": (_I, [_P, _P]),
    # the measure accumulators and their records (accumulators.py)
    "mcs_discrepancy_init": (_I, [_P, _Z]),
    "mcs_discrepancy_add": (_I, [_P, _Z, _P, _P, _Z]),
    "mcs_discrepancy_add_f": (_I, [_P, _Z, _P, _P, _Z]),
    "mcs_discrepancy_merge": (_I, [_P, _P]),
    "mcs_discrepancy_count": (_I, [_P, _I, _P]),
    "mcs_discrepancy_mean": (_I, [_P, _I, _P]),
    "mcs_discrepancy_stderr": (_I, [_P, _I, _P]),
    "mcs_discrepancy_exact_random": (_I, [_P, _I, _P]),
    "mcs_spacing_init": (_I, [_P, _Z]),
    "mcs_spacing_add": (_I, [_P, _Z, _P, _P, _Z]),
    "mcs_spacing_add_f": (_I, [_P, _Z, _P, _P, _Z]),
    "mcs_spacing_merge": (_I, [_P, _P]),
    "mcs_spacing_count": (_I, [_P, _P]),
    "mcs_spacing_mean": (_I, [_P, _I, _P]),
    "mcs_spacing_stderr": (_I, [_P, _I, _P]),
    "mcs_integrate_merge": (_I, [_P, _P]),
    "mcs_integrate_count": (_I, [_P, _P]),
    "mcs_io_save_integrate": (_I, [_P, _Z, _P, _P]),
    "mcs_io_save_discrepancy": (_I, [_P, _Z, _P, _P]),
    "mcs_io_save_spacing": (_I, [_P, _Z, _P, _P]),
    "mcs_io_load_integrate": (_I, [_P, _Z, _P]),
    "mcs_io_load_discrepancy": (_I, [_P, _Z, _P]),
    "mcs_io_load_spacing": (_I, [_P, _Z, _P]),
}


class _Functions:
    """The prototyped functions, as attributes without the mcs_ prefix."""


fn = _Functions()
for _name, (_res, _args) in _PROTOS.items():
    _f = getattr(lib, _name)
    _f.restype = _res
    _f.argtypes = _args
    setattr(fn, _name[4:], _f)

version = fn.version().decode()


def status_name(status):
    return fn.status_str(int(status)).decode()


class Error(ValueError):
    """A call refused (an mcs_status other than MCS_OK), or input refused
    before the library was called. .status is the mcs_status number (the one
    the library would give for that input), .name its name ("MCS_ERR_...").
    Nothing was changed by the call that raised it."""

    def __init__(self, status, message):
        self.status = int(status)
        self.name = status_name(self.status)
        super().__init__("%s: %s" % (self.name, message))


# Status numbers used for Python-side checks (status.h).
ERR_NULL, ERR_N_RANGE, ERR_K_RANGE, ERR_NOT_FINITE = -1, -2, -3, -4
ERR_POINT_RANGE, ERR_KIND, ERR_MISMATCH, ERR_EMPTY = -8, -9, -10, -12
ERR_DOMAIN, ERR_FREQ_RANGE, ERR_FORMAT = -13, -14, -21


def check(status, what):
    """Raises Error unless status is MCS_OK; what names the call."""
    if status != 0:
        raise Error(status, "%s refused the call" % what)


def sizeof(abi_type):
    size = ctypes.c_size_t(0)
    check(fn.abi_sizeof(abi_type, ctypes.addressof(size), None), "mcs_abi_sizeof")
    return size.value


# mcs_abi_type (abi.h)
ABI = dict(rng=0, importance=1, pattern=2, pattern2d=3, sampler=4, welford=5, dft=6, spectrum=7,
           moment=8, autocorr=9, pointset=10, pointset2d=11, spectrum2d=12, theory=13,
           theory_spectrum=14, discrepancy=15, spacing=16, provenance=17, pcf=18,
           integrand=19, integrate=20, projections=21, projections_pair=22,
           bluenoise_params=23)
_SIZES = {}


def struct_size(name):
    if name not in _SIZES:
        _SIZES[name] = sizeof(ABI[name])
    return _SIZES[name]


_SCRIBBLE = os.environ.get("MCSPEC_SCRIBBLE") == "1"


class Buffer:
    """bytes of zeroed memory aligned to 64 bytes (numpy uint8), .addr its address."""
    __slots__ = ("array", "raw", "addr", "size")

    def __init__(self, size):
        self.raw = np.zeros(size + 64, dtype=np.uint8)
        off = (-self.raw.ctypes.data) % 64
        self.array = self.raw[off:off + size]
        self.addr = self.array.ctypes.data
        self.size = size

    def bytes(self):
        return self.array.tobytes()

    def __del__(self):
        # MCSPEC_SCRIBBLE=1 (python/tests/run.sh sets it) fills memory that
        # is freed, so a call handed the address of a temporary object that
        # Python has already freed sees a corrupted object and is refused
        # every time, instead of passing while the freed memory is intact.
        if _SCRIBBLE:
            try:
                self.raw.fill(0xA5)
            except Exception:  # interpreter shutdown
                pass


def struct(name):
    """An opaque object of the library's struct `name` (abi.h)."""
    return Buffer(struct_size(name))


def out(shape, dtype=np.float64):
    return np.empty(shape, dtype=dtype)


def addr(a):
    return None if a is None else a.ctypes.data


def cstr(p):
    return p.decode() if p is not None else "unknown"
