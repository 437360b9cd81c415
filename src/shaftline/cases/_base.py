"""The strict pydantic base of every case-file section: unknown keys are errors."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict

Quantity = float | int | str


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
