"""Numpy-only helpers for the built-in charts: smooth random fields, bilinear resampling and a
windowed distance transform (scipy is not a runtime dependency)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt


def gaussian(a: npt.NDArray[np.floating], sigma: float) -> npt.NDArray[np.float64]:
    """Gaussian smoothing (sigma in cells) by FFT, with reflected edges so the field does not wrap."""
    pad = int(np.ceil(3 * sigma))
    p = np.pad(a, pad, mode="reflect") if pad else a
    ky = np.fft.fftfreq(p.shape[0])[:, None]
    kx = np.fft.rfftfreq(p.shape[1])[None, :]
    g = np.exp(-2.0 * (np.pi * sigma) ** 2 * (ky**2 + kx**2))
    s: npt.NDArray[np.float64] = np.fft.irfft2(np.fft.rfft2(p) * g, s=p.shape)
    return s[pad : pad + a.shape[0], pad : pad + a.shape[1]] if pad else s


def smooth_noise(
    rng: np.random.Generator, shape: int | tuple[int, ...], sigma: float
) -> npt.NDArray[np.float64]:
    """A smooth random field with values in (0, 1), roughly uniformly spread (correlation length
    ~ sigma cells)."""
    s = gaussian(rng.standard_normal(shape), sigma)
    s = (s - s.mean()) / s.std()
    p: npt.NDArray[np.float64] = 1.0 / (1.0 + np.exp(-1.7 * s))  # logistic ~ the normal CDF
    return p


def _axis(n: int, m: int) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.floating], npt.NDArray[np.int64]]:
    """Index and fraction of n pixel centres in a coarse axis of m cells covering the same span."""
    x = np.clip((np.arange(n) + 0.5) * m / n - 0.5, 0, m - 1)
    i0 = np.minimum(x.astype(np.int64), max(m - 2, 0))
    return i0, x - i0, np.minimum(i0 + 1, m - 1)


def resample(a: npt.NDArray[np.floating], rows: int, cols: int) -> npt.NDArray[np.float32]:
    """Bilinear interpolation of a coarse field onto rows x cols pixel centres of the same extent
    (float32: the fields are smooth and the charts large)."""
    r0, fr, r1 = _axis(rows, a.shape[0])
    c0, fc, c1 = _axis(cols, a.shape[1])
    a = np.asarray(a, dtype=np.float32)
    fc, fr = fc.astype(np.float32), fr.astype(np.float32)[:, None]
    b = a[:, c0] * (1 - fc) + a[:, c1] * fc  # along the columns on the coarse rows first
    out = b[r0]
    out *= 1 - fr
    out += b[r1] * fr
    return out


def distance_km(
    target: npt.NDArray[np.bool_], dy_km: float, dx_km: npt.NDArray[np.float64], max_km: float
) -> npt.NDArray[np.float64]:
    """Distance (km) from each cell to the nearest True cell of `target`, capped at max_km.

    Separable squared-distance transform (as in Felzenszwalb & Huttenlocher) with the minimum taken
    over a window of +-max_km; dx_km is the cell width of each row (it shrinks with latitude)."""
    cap = max_km**2
    f = np.where(target, 0.0, cap)
    g = f.copy()
    for k in range(1, int(np.ceil(max_km / dx_km.min())) + 1):  # along each row
        if k >= f.shape[1]:
            break
        step: npt.NDArray[np.float64] | float = ((k * dx_km) ** 2)[:, None]
        np.minimum(g[:, k:], f[:, :-k] + step, out=g[:, k:])
        np.minimum(g[:, :-k], f[:, k:] + step, out=g[:, :-k])
    h = g.copy()
    for k in range(1, int(np.ceil(max_km / dy_km)) + 1):  # along each column
        if k >= g.shape[0]:
            break
        step = (k * dy_km) ** 2
        np.minimum(h[k:], g[:-k] + step, out=h[k:])
        np.minimum(h[:-k], g[k:] + step, out=h[:-k])
    return np.sqrt(np.minimum(h, cap))
