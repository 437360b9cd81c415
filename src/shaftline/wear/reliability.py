"""Weibull distribution of wear by maximum likelihood, with confidence bounds.

    F(x) = 1 - exp(-(x / lambda)^beta)       (seed 000 Eq. 5.1)

The fit is scipy's maximum-likelihood estimate with the location fixed at zero. Its
covariance is the inverse observed information of (ln lambda, ln beta) (central
differences of the log-likelihood); bounds on F(x) come from the normal approximation of
u = beta (ln x - ln lambda) by the delta method, as in the usual reliability practice
(Meeker & Escobar 1998, Sect. 8.4), and parameter intervals from the log-parameters.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import stats

from shaftline.errors import InputError


@dataclass(frozen=True, eq=False)
class WeibullFit:
    """Maximum-likelihood Weibull fit.

    Attributes
    ----------
    shape : float
        beta.
    scale : float
        lambda, in the unit of the samples.
    covariance : ndarray (2, 2)
        Of (ln lambda, ln beta).
    samples : ndarray
    confidence : float
        Two-sided level of the bounds, e.g. 0.95.
    """

    shape: float
    scale: float
    covariance: np.ndarray
    samples: np.ndarray
    confidence: float = 0.95

    @property
    def _z(self) -> float:
        return float(stats.norm.ppf(0.5 + 0.5 * self.confidence))

    def interval(self, name: str) -> tuple[float, float]:
        """Confidence interval of ``"shape"`` or ``"scale"``."""
        index, value = (1, self.shape) if name == "shape" else (0, self.scale)
        spread = self._z * np.sqrt(self.covariance[index, index])
        return float(value * np.exp(-spread)), float(value * np.exp(spread))

    def cdf(self, x: float | np.ndarray) -> np.ndarray:
        return 1.0 - np.exp(-((np.asarray(x, dtype=float) / self.scale) ** self.shape))

    def cdf_bounds(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper confidence bounds of F(x)."""
        x = np.asarray(x, dtype=float)
        u = self.shape * (np.log(x) - np.log(self.scale))
        gradient = np.stack([-self.shape * np.ones_like(u), u])  # d u / d(ln lambda, ln beta)
        variance = np.einsum("i...,ij,j...->...", gradient, self.covariance, gradient)
        spread = self._z * np.sqrt(variance)
        to_f = lambda v: 1.0 - np.exp(-np.exp(v))  # noqa: E731
        return to_f(u - spread), to_f(u + spread)

    def exceedance(self, x: float) -> tuple[float, float, float]:
        """P(X > x) with its confidence bounds (lower, estimate, upper)."""
        low, high = self.cdf_bounds(np.array(x))
        return float(1.0 - high), float(1.0 - self.cdf(x)), float(1.0 - low)


def _log_likelihood(log_parameters: np.ndarray, x: np.ndarray) -> float:
    scale, shape = np.exp(log_parameters)
    z = x / scale
    return float(np.sum(np.log(shape / scale) + (shape - 1) * np.log(z) - z**shape))


def fit_weibull(samples: np.ndarray, confidence: float = 0.95) -> WeibullFit:
    """Fit a two-parameter Weibull distribution to positive samples (at least 3)."""
    x = np.asarray(samples, dtype=float)
    if x.ndim != 1 or x.size < 3:
        raise InputError("samples", x.size, "samples", "at least 3 for a Weibull fit")
    if not np.all(np.isfinite(x)):
        raise InputError("samples", "NaN", "", "finite values")
    if np.any(x <= 0):
        raise InputError("samples", float(x[x <= 0][0]), "", "positive values (wear depths or rates)")
    if np.ptp(x) == 0:
        raise InputError("samples", float(x[0]), "", "samples that are not all equal")
    if not 0.5 < confidence < 1.0:
        raise InputError("confidence", confidence, "", "in (0.5, 1)")
    shape, _, scale = stats.weibull_min.fit(x, floc=0)
    theta = np.array([np.log(scale), np.log(shape)])
    step = 1e-4
    hessian = np.empty((2, 2))
    for i in range(2):
        for j in range(2):
            e_i, e_j = np.eye(2)[i] * step, np.eye(2)[j] * step
            hessian[i, j] = (
                _log_likelihood(theta + e_i + e_j, x)
                - _log_likelihood(theta + e_i - e_j, x)
                - _log_likelihood(theta - e_i + e_j, x)
                + _log_likelihood(theta - e_i - e_j, x)
            ) / (4 * step**2)
    covariance = np.linalg.inv(-hessian)
    return WeibullFit(float(shape), float(scale), covariance, x, confidence)


def read_samples(path) -> np.ndarray:
    """Samples from a CSV with one numeric column (a header line is allowed)."""
    from pathlib import Path

    path = Path(path)
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except UnicodeDecodeError:
        raise InputError("data file", str(path), "", "a CSV text file in UTF-8") from None
    except OSError:
        raise InputError("data file", str(path), "", "an existing CSV file") from None
    values = []
    for number, line in enumerate(lines, start=1):
        text = line.split(",")[0].strip()
        if not text:
            continue
        try:
            value = float(text)
        except ValueError:
            if number == 1:
                continue  # header
            raise InputError(f"{path.name}: row {number}", text, "", "a number") from None
        if not np.isfinite(value):
            raise InputError(f"{path.name}: row {number}", text, "", "a finite number")
        values.append(value)
    return np.array(values)
