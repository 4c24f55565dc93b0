"""Small matplotlib helpers for the figures the command draws: a binned
power spectrum beside theory, the 2D periodogram image, and the radial
power profile. matplotlib is imported only when one is called."""
import numpy as np


def _axes(ax):
    """ax, or the axes of a new figure (matplotlib.figure.Figure: no pyplot,
    no display needed; fig.savefig writes it)."""
    if ax is not None:
        return ax
    from matplotlib.figure import Figure
    return Figure(figsize=(7, 4)).add_subplot()


def spectrum(acc, theory=None, ax=None, log=False):
    """<|S_k|^2> of a Spectrum for k >= 1 with its standard-error band,
    beside the exact power of a TheorySpectrum (as `mcspec pattern --plot`)."""
    ax = _axes(ax)
    r = acc.read_all()
    k = np.arange(len(r["power"]))[1:]
    p, s = r["power"][1:], r["power_stderr"][1:]
    ax.fill_between(k, p - s, p + s, alpha=0.3, label="measured +- 1 stderr")
    ax.plot(k, p, label="measured <|S_k|^2>")
    if theory is not None:
        ax.plot(k, theory.power[1:], "k--", label="exact")
    ax.set_xlabel("frequency k")
    ax.set_ylabel("power")
    if log:
        ax.set_yscale("log")
    ax.legend()
    return ax


def periodogram2d(power, ax=None, log=True):
    """The image of a 2D mean periodogram [fy + F, fx + F]."""
    ax = _axes(ax)
    f = (power.shape[0] - 1) // 2
    img = np.log10(np.maximum(power, 1e-12)) if log else power
    im = ax.imshow(img, origin="lower", extent=(-f - 0.5, f + 0.5, -f - 0.5, f + 0.5),
                   cmap="gray")
    ax.figure.colorbar(im, ax=ax, label="log10 <P(k)>" if log else "<P(k)>")
    ax.set_xlabel("kx")
    ax.set_ylabel("ky")
    return ax


def radial(mean, stderr=None, exact=None, ax=None, label="measured"):
    """The radial power per annulus r = 0..F (r = 0 left out), with its
    standard-error band and an exact profile if given."""
    ax = _axes(ax)
    r = np.arange(len(mean))[1:]
    ax.plot(r, mean[1:], label=label)
    if stderr is not None:
        ax.fill_between(r, mean[1:] - stderr[1:], mean[1:] + stderr[1:], alpha=0.3)
    if exact is not None:
        ax.plot(r, np.asarray(exact)[1:], "k--", label="exact")
    ax.axhline(1.0, color="gray", lw=0.5)
    ax.set_xlabel("radius |k|")
    ax.set_ylabel("radial power")
    ax.legend()
    return ax
