"""glTF animation channels sampled by time (vectorised over query times).

Interpolation follows the glTF 2.0 specification: LINEAR (lerp; slerp for rotations),
STEP (value of the last key at or before t) and CUBICSPLINE (Hermite with the stored
in/out tangents; rotations renormalised). Before the first key the first value holds,
after the last key the last value holds.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from app.engine.errors import MetricError
from app.engine.export.gltf_container import AccessorReader
from app.engine.export.rotations import slerp
from app.engine.types import FloatArray

PATH_WIDTHS = {"translation": 3, "rotation": 4, "scale": 3}
INTERPOLATIONS = frozenset({"LINEAR", "STEP", "CUBICSPLINE"})


@dataclass(frozen=True, eq=False)
class Channel:
    """One animated node property.

    Attributes
    ----------
    node : target node index
    path : ``translation`` | ``rotation`` | ``scale``
    times : (k,) float, seconds, non-decreasing
    values : (k, c) float key values (c = 3 or 4)
    in_tangents, out_tangents : (k, c) float, CUBICSPLINE only
    """

    node: int
    path: str
    interpolation: str
    times: FloatArray
    values: FloatArray
    in_tangents: FloatArray | None = None
    out_tangents: FloatArray | None = None

    def sample(self, query: FloatArray) -> FloatArray:
        """(m, c) values at times ``query`` (m,)."""
        times = self.times
        count = times.shape[0]
        if count == 1:
            return np.repeat(self.values[:1], query.shape[0], axis=0)
        left = np.clip(np.searchsorted(times, query, side="right") - 1, 0, count - 2)
        span = times[left + 1] - times[left]
        safe_span = np.where(span > 0, span, 1.0)
        s = np.clip((query - times[left]) / safe_span, 0.0, 1.0)
        s = np.where(span > 0, s, 1.0)
        if self.interpolation == "STEP":
            index = np.clip(np.searchsorted(times, query, side="right") - 1, 0, count - 1)
            return self.values[index]
        a, b = self.values[left], self.values[left + 1]
        if self.interpolation == "CUBICSPLINE" and self.in_tangents is not None and self.out_tangents is not None:
            out = _hermite(a, b, self.out_tangents[left] * span[:, None], self.in_tangents[left + 1] * span[:, None], s)
            out = np.where((query <= times[0])[:, None], self.values[0], out)
            out = np.where((query >= times[-1])[:, None], self.values[-1], out)
            if self.path == "rotation":
                out = out / np.linalg.norm(out, axis=1, keepdims=True)
            return out
        if self.path == "rotation":
            return slerp(a, b, s)
        return a + (b - a) * s[:, None]


def _hermite(p0: FloatArray, p1: FloatArray, m0: FloatArray, m1: FloatArray, s: FloatArray) -> FloatArray:
    s = s[:, None]
    s2, s3 = s * s, s * s * s
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1


def read_channels(animation: dict[str, Any], accessors: AccessorReader, node_count: int, where: str) -> list[Channel]:
    """Channels of one animation that target node TRS (``weights`` and pointer targets are ignored).

    Raises
    ------
    MetricError
        Missing samplers/accessors, bad interpolation, key counts that do not
        match, decreasing or non-finite times, non-finite values.
    """
    samplers = animation.get("samplers", [])
    channels = animation.get("channels", [])
    if not isinstance(samplers, list) or not isinstance(channels, list):
        raise MetricError(f"{where}: channels and samplers must be lists")
    out = []
    for number, channel in enumerate(channels):
        target = channel.get("target") if isinstance(channel, dict) else None
        if not isinstance(target, dict):
            raise MetricError(f"{where}: channel {number} has no target")
        path, node = target.get("path"), target.get("node")
        if path not in PATH_WIDTHS or node is None:
            continue
        if not isinstance(node, int) or not 0 <= node < node_count:
            raise MetricError(f"{where}: channel {number} targets missing node {node}")
        sampler_index = channel.get("sampler")
        if not isinstance(sampler_index, int) or not 0 <= sampler_index < len(samplers):
            raise MetricError(f"{where}: channel {number} refers to missing sampler {sampler_index}")
        out.append(_channel(samplers[sampler_index], accessors, node, path, f"{where} channel {number}"))
    return out


def _channel(sampler: Any, accessors: AccessorReader, node: int, path: str, where: str) -> Channel:
    if not isinstance(sampler, dict):
        raise MetricError(f"{where}: sampler is not an object")
    interpolation = sampler.get("interpolation", "LINEAR")
    if interpolation not in INTERPOLATIONS:
        raise MetricError(f"{where}: unknown interpolation '{interpolation}'")
    times = np.asarray(accessors.read(sampler.get("input"), what=f"{where} input"), dtype=np.float64)
    values = np.asarray(accessors.read(sampler.get("output"), what=f"{where} output"), dtype=np.float64)
    width = PATH_WIDTHS[path]
    if times.ndim != 2 or times.shape[1] != 1 or times.shape[0] == 0:
        raise MetricError(f"{where}: input must be a non-empty SCALAR accessor")
    times = times[:, 0]
    if not np.all(np.isfinite(times)) or np.any(np.diff(times) < 0):
        raise MetricError(f"{where}: key times must be finite and non-decreasing")
    if values.shape[1] != width or not np.all(np.isfinite(values)):
        raise MetricError(f"{where}: {path} output must be finite VEC{width}")
    keys = times.shape[0]
    per_key = 3 if interpolation == "CUBICSPLINE" else 1
    if values.shape[0] != keys * per_key:
        raise MetricError(f"{where}: {values.shape[0]} output values for {keys} keys ({interpolation})")
    if path == "rotation" and np.any(np.linalg.norm(values, axis=1) < 1e-12) and per_key == 1:
        raise MetricError(f"{where}: a rotation key is a zero quaternion")
    if per_key == 3:
        triples = values.reshape(keys, 3, width)
        return Channel(
            node, path, interpolation, times, triples[:, 1], in_tangents=triples[:, 0], out_tangents=triples[:, 2]
        )
    if path == "rotation":
        values = values / np.linalg.norm(values, axis=1, keepdims=True)
    return Channel(node, path, interpolation, times, values)
