import os
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


@pytest.fixture(scope="session")
def cli():
    """Runs the mcspec command ($MCSPEC or build/bin/mcspec) and returns the
    rows of its --csv output as lists of strings, header first."""
    exe = os.environ.get("MCSPEC", os.path.join(ROOT, "build", "bin", "mcspec"))
    if not os.access(exe, os.X_OK):
        pytest.skip("no mcspec command at %s (make cli)" % exe)

    def run(*args, stdin=None):
        out = subprocess.run([exe] + [str(a) for a in args] + ["--csv"], input=stdin,
                             capture_output=True, check=True, text=True).stdout
        return [line.split(",") for line in out.strip().splitlines()]
    return run


def f17(x):
    """x as the command prints it (%.17g), so equal doubles give equal text."""
    return "%.17g" % x


def points_text(sets):
    """sets (T, K, d) as the command's point file: one point per line at
    %.17g (exact for doubles), '#' between sets."""
    lines = []
    for s in sets:
        for p in s:
            lines.append(" ".join(f17(v) for v in p))
        lines.append("#")
    return "\n".join(lines) + "\n"
