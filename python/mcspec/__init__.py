"""mcspec from Python: numpy arrays in and out of libmcspec.so (ctypes; no
compiled extension). See docs/python.md.

    import mcspec
    pts = mcspec.sample("jittered", 2, 256, sets=64, seed=1)   # (64, 256, 2)
    mean, stderr = mcspec.periodogram(pts, 32, radial=True)    # per radius 0..32
"""
from ._lib import Error, library_path, library_source, version as __version__
from ._lib import status_name
from .pointsets import PointSet, Estimate, periodogram, anisotropy, wave_vectors
from .sampling import sample, kinds, base_points, exact_power, lattice_generator
from .measures import (discrepancy, discrepancy_exact_random, discrepancy_exact_jittered, spacing,
                       spacing_exact_random)
from .binned import Importance, Pattern, Spectrum, Moment, Autocorr, Theory, TheorySpectrum
from .accumulators import Discrepancy, Spacing, IntegrationError
from .records import save, load, save_file, load_file, merge
from .analysis import (Pcf, PairCorrelation, pcf, effective_nyquist, oscillations, spectral_stats,
                       integration_error, integration_error_of, projections)

__all__ = [
    "Error", "library_path", "library_source", "__version__", "status_name",
    "PointSet", "Estimate", "periodogram", "anisotropy", "wave_vectors",
    "sample", "kinds", "base_points", "exact_power", "lattice_generator",
    "discrepancy", "discrepancy_exact_random", "discrepancy_exact_jittered", "spacing",
    "spacing_exact_random",
    "Importance", "Pattern", "Spectrum", "Moment", "Autocorr", "Theory", "TheorySpectrum",
    "Discrepancy", "Spacing", "IntegrationError",
    "save", "load", "save_file", "load_file", "merge",
    "Pcf", "PairCorrelation", "pcf", "effective_nyquist", "oscillations", "spectral_stats",
    "integration_error", "integration_error_of",
    "projections",
]
