"""The grid halved both ways under a model's grid, and the maps between the two.

Every model with an active set predicts the cavitated set of a cold start from the same film
on coarser grids (docs/theory.md Sect. 4.1): the coarse solution, or its swept prediction,
brought back onto the finer grid places the cavitation boundary to within a cell or two.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, TypeVar

import numpy as np

from shaftline.film.cavitation.base import NodeGrid

__all__ = ["CoarseGrid", "coarse_nodes"]

_Model = TypeVar("_Model")


def coarse_nodes(fine: NodeGrid, shape: tuple[int, int]) -> NodeGrid:
    """The coarse grid of ``shape`` (from :func:`~shaftline.film.geometry.coarse_shape`) under
    ``fine``: its fixed nodes are the fine ones on the coarse rows and columns, and both edges."""
    nz, _ = fine.shape
    nz_c, nt_c = shape
    rows = np.rint(np.linspace(0.0, 1.0, nz_c) * (nz - 1)).astype(int)
    fixed_c = fine.fixed[rows][:, ::2].copy()
    value_c = fine.fixed_pressure[rows][:, ::2].copy()
    fixed_c[[0, -1]] = True
    return NodeGrid.of((nz_c, nt_c), 2.0 * fine.d_theta, fine.d_z * (nz - 1) / (nz_c - 1), fixed_c, value_c)


@dataclass(frozen=True, eq=False)
class CoarseGrid(Generic[_Model]):
    """A grid halved in both directions under a model's grid, the coarse model, and the maps.

    Coarse columns are every other fine column; coarse rows lie evenly from edge to edge, so
    a fine field is restricted by linear interpolation in z, and a coarse field is brought
    back to the fine grid bilinearly.

    Attributes
    ----------
    model : CavitationModel
        The model of the same kind on the coarse grid (:func:`coarse_nodes`).
    z_index, z_weight : ndarray (nz_c,)
        Fine row below each coarse row, and the weight of the row above it.
    row_lo, row_hi, row_w : ndarray (nz,)
        Coarse rows around each fine row, and the weight of the upper one.
    col_lo, col_hi : ndarray (nt,)
        Coarse columns around each fine column (the same one for even fine columns).
    """

    model: _Model
    z_index: np.ndarray
    z_weight: np.ndarray
    row_lo: np.ndarray
    row_hi: np.ndarray
    row_w: np.ndarray
    col_lo: np.ndarray
    col_hi: np.ndarray

    @classmethod
    def under(cls, fine: NodeGrid, shape: tuple[int, int], make: Callable[[NodeGrid], _Model]) -> CoarseGrid[_Model]:
        """The coarse grid of ``shape`` under ``fine`` with the model ``make(coarse nodes)``."""
        nz, nt = fine.shape
        nz_c, nt_c = shape
        position = np.linspace(0.0, 1.0, nz_c) * (nz - 1)
        z_index = np.minimum(np.floor(position).astype(int), nz - 2)
        fine_in_coarse = np.linspace(0.0, 1.0, nz) * (nz_c - 1)
        row_lo = np.minimum(np.floor(fine_in_coarse).astype(int), nz_c - 2)
        return cls(
            model=make(coarse_nodes(fine, shape)),
            z_index=z_index,
            z_weight=position - z_index,
            row_lo=row_lo,
            row_hi=row_lo + 1,
            row_w=fine_in_coarse - row_lo,
            col_lo=(np.arange(nt) // 2) % nt_c,
            col_hi=((np.arange(nt) + 1) // 2) % nt_c,
        )

    def restrict(self, field: np.ndarray) -> np.ndarray:
        """A fine field (nz, nt) on the coarse grid: linear in z, every other column."""
        w = self.z_weight[:, None]
        return (field[self.z_index] * (1.0 - w) + field[self.z_index + 1] * w)[:, ::2]

    def prolong(self, field: np.ndarray) -> np.ndarray:
        """A coarse field on the fine grid, bilinearly."""
        row_w = self.row_w[:, None]
        col_w = 0.5 * (np.arange(self.col_lo.size) % 2)[None, :]
        lo = field[self.row_lo] * (1.0 - row_w) + field[self.row_hi] * row_w
        return lo[:, self.col_lo] * (1.0 - col_w) + lo[:, self.col_hi] * col_w
