"""Every visual link's points at rest (world frame) laid out in depth-first order, so that the links one joint moves
are one slice and the links it leaves still are the rest: a joint's moved points and its static box cost no walk over
the asset (a per-joint question asked of every joint stays linear in the asset's size)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.types import FloatArray


@dataclass(frozen=True)
class RestPoints:
    points: FloatArray
    """(p, 3) world points at rest, link after link in depth-first order."""
    span: dict[str, tuple[int, int]]
    """Link -> (first, end) point index of its subtree in ``points``."""
    order: dict[str, tuple[int, int]]
    """Link -> (first, end) index of its subtree among the links in depth-first order."""
    low_before: FloatArray
    """(n + 1, 3): row k is the lowest corner of links [0, k) in depth-first order (+inf when none)."""
    high_before: FloatArray
    low_after: FloatArray
    """(n + 1, 3): row k is the lowest corner of links [k, n) (+inf when none)."""
    high_after: FloatArray

    @classmethod
    def of(cls, asset: ArticulatedAsset, world: dict[str, FloatArray]) -> RestPoints:
        """``world``: link -> (k, 3) rest points in the world frame (links without geometry absent or empty)."""
        links, order, _ = asset.depth_first
        counts = np.array([world[n].shape[0] if n in world else 0 for n in links], dtype=np.int64)
        offsets = np.concatenate([[0], np.cumsum(counts)])
        span = {n: (int(offsets[a]), int(offsets[b])) for n, (a, b) in order.items()}
        chunks = [world[n] for n in links if n in world and world[n].shape[0]]
        points = np.concatenate(chunks) if chunks else np.zeros((0, 3))
        low = np.array([world[n].min(axis=0) if counts[k] else np.full(3, np.inf) for k, n in enumerate(links)]).reshape(-1, 3)
        high = np.array([world[n].max(axis=0) if counts[k] else np.full(3, -np.inf) for k, n in enumerate(links)]).reshape(-1, 3)
        inf = np.full((1, 3), np.inf)
        return cls(points=points, span=span, order=order,
                   low_before=np.minimum.accumulate(np.concatenate([inf, low])), high_before=np.maximum.accumulate(np.concatenate([-inf, high])),
                   low_after=np.minimum.accumulate(np.concatenate([low, inf])[::-1])[::-1],
                   high_after=np.maximum.accumulate(np.concatenate([high, -inf])[::-1])[::-1])

    def below(self, link: str) -> FloatArray:
        """The rest points of ``link`` and every link under it."""
        first, end = self.span[link]
        return self.points[first:end]

    def box_without(self, link: str) -> tuple[FloatArray, FloatArray] | None:
        """(low, high) of every link outside ``link``'s subtree; None when nothing outside has geometry."""
        first, end = self.order[link]
        low = np.minimum(self.low_before[first], self.low_after[end])
        high = np.maximum(self.high_before[first], self.high_after[end])
        return (low, high) if np.all(np.isfinite(low)) else None

    def box(self) -> tuple[FloatArray, FloatArray]:
        """(low, high) of the whole object at rest."""
        return self.low_after[0], self.high_after[0]


def posed(points: dict[str, FloatArray], poses: dict[str, FloatArray], links: tuple[str, ...] | list[str], frame: int = 0) -> FloatArray:
    """The local ``points`` of ``links`` placed by ``poses`` (link -> (f, 4, 4)) at ``frame``, stacked."""
    chunks = [points[n] @ poses[n][frame, :3, :3].T + poses[n][frame, :3, 3] for n in links if n in points]
    return np.concatenate(chunks) if chunks else np.zeros((0, 3))
