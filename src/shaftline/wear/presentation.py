"""How a Weibull fit of wear rates is written: its JSON and its one line of text, shared by the
service-wear report and the ``wear weibull`` verb."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from shaftline.wear.reliability import WeibullFit


def weibull_json(fit: WeibullFit) -> dict[str, Any]:
    return {
        "shape": fit.shape,
        "scale": fit.scale,
        "shape_interval": fit.interval("shape"),
        "scale_interval": fit.interval("scale"),
        "confidence": fit.confidence,
    }


def weibull_text(fit: WeibullFit, scale: float = 1.0, unit: str = "") -> str:
    low, high = fit.interval("shape")
    scale_low, scale_high = fit.interval("scale")
    return (
        f"Weibull fit of {fit.samples.size} samples: shape {fit.shape:.4g} ({low:.4g}-{high:.4g}), scale "
        f"{fit.scale * scale:.4g} ({scale_low * scale:.4g}-{scale_high * scale:.4g}){' ' + unit if unit else ''}; "
        f"{fit.confidence:.0%} intervals."
    )
